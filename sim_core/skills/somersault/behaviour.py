"""Standing somersaults (Wooten §8.4, §8.5), built only by sequencing the basis behaviours:
balance (crouch) -> leap (thrust with the lift-off hip angle and arm swing that set the
somersault rate) -> tumble (tuck) -> land (opens on the measured state, places the feet for the
spin) -> balance.

The thesis: "the leaping controller generates the height and rotation rate required for either
a forward or backward tucked somersault, the landing controller untucks and positions the legs
for landing and then transitions to the balance controller". Here the transition from the tuck
to the landing is a state condition, not a time: the controller predicts, from the measured
angular momentum and the ballistic time left until the feet reach the ground, how far the body
will still turn once opened, and opens when that is what the somersault has left (less the
``landing_lean`` it lands short by, so that the ground force at touchdown turns the rest of the
spin back).

The take-off and landing settings per character, direction and strength come from
``sim_core/tuned/tables/somersaults_<character>.json``, written by ``python -m sim_core calibrate somersault``
(a search over whole simulated somersaults, scored off the simulation; docs/planning.md).
"""
from __future__ import annotations

import math

import numpy as np

from ...ballistics import time_to_fall_to
from ...control.balance import Balance
from ...control.behaviour import register
from ...control.leap import AIRBORNE_HEIGHT, Landing, balance_after_landing, leap_assess, run_strength
from ...control.sequencer import Sequence, Step
from ...control.takeoff import takeoff_steps
from ...control.tumble import FlightRotation, Tumble, position_inertia, rotation_to_come
from ...control.tuned import uncalibrated
from ...analysis import feet_above_surface
from ...schema import Choice, Parameter, Schema
from ...tuned import TableType, keyed, load, register as register_table
from ...tuned.settings import SkillSchema
from ...tuned.constants import constant, constant_rows, read_constants, with_constants

# the somersault's hand-set constants: data, somersaults_any.json's "constants" (docs/tables.md)
SOMERSAULT_CONSTANTS = Schema(
    constant("tuck_move", "s", 0.01, 1.0, "the servo move into the tuck, where a calibrated row names no tuck_time"),
    constant("touchdown_com", "1", 0.0, 2.0, "share of the standing COM height at which the feet reach the ground"),
)
CONSTANTS = read_constants("somersaults", SOMERSAULT_CONSTANTS)

DIRECTIONS = ("backward", "forward")
TUCK = 2                    # the tumble's position code
ROTATION_TOLERANCE = 0.35   # rad: a somersault turns 2 pi within this (TARGETS.md)
SQUAT_LOWEST = Balance.schema.by_name["pelvis_height"].minimum   # m: the crouch before a take-off is a
                            # deliberate squat: the pelvis may go down to the balance's deepest crouch
TAKEOFF_SETTINGS = ("crouch_height", "crouch_pitch", "com_offset", "thrust_lean", "liftoff_hip", "arm_swing",
                    "thrust_damping", "tuck_stiffness", "tuck_time", "tuck_damping")
LANDING_SETTINGS = ("landing_lean", "open_time", "open_blend", "landing_knee_flexion", "foot_delta",
                    "landing_foot_lead_time", "spin_placement")
SETTINGS = TAKEOFF_SETTINGS + LANDING_SETTINGS + ("flight_step_division",)
OLD_ROW = {"tuck_time": CONSTANTS.tuck_move, "tuck_damping": 0.0, "flight_step_division": 1}   # what a calibrated row
                            # made before these settings ran with: every stored row reproduces


FLIGHT_STEP_PARAMETER = Parameter(
    "flight_step_division", "count", 1.0, 1.0, 8.0,
    "the physics step from the take-off to the feet's touchdown (the landing's, which goes back to the model's "
    "step) is the model's divided by this (a whole number; 8 as in the dives: fast moves in flight keep the "
    "angular momentum within 1 %) (low_level only)")


def load_table(character: str) -> dict:
    """The character's somersault table (no rows if there is none)."""
    return load("somersaults", character) or {"somersaults": []}


def somersault_row(table: dict, direction: str, strength: str) -> dict | None:
    """The row of the direction and strength (keyed), or None."""
    return keyed(table["somersaults"], direction=direction, strength=strength)


def calibrated(character: str, direction: str, strength: str) -> dict | None:
    """The calibrated somersault of this character, direction and strength, or None."""
    return somersault_row(load_table(character), direction, strength)


SOMERSAULT_SETTINGS = Schema(
    Parameter("crouch_height", "m", 0.55, 0.42, 0.9, "pelvis height of the crouch (low_level only)"),
    Parameter("crouch_pitch", "rad", 0.8, -0.3, 1.5, "torso pitch in the crouch (low_level only)"),
    Parameter("com_offset", "m", -0.08, -0.2, 0.2,
              "COM ahead (+) of or behind (-) the middle of the feet in the crouch; leaning, the thrust "
              "starts once the COM has moved that far (low_level only)"),
    Parameter("thrust_lean", "m", 0.0, -0.1, 0.1,
              "COM ahead (+) of or behind (-) the middle of the feet along the thrust's extension (low_level only)"),
    Parameter("liftoff_hip", "rad", 1.5, -2.0, 2.0,
              "hip extension (+, backward spin) or flexion (-, forward spin) at lift-off (low_level only)"),
    Parameter("arm_swing", "rad", 3.0, -1.0, 3.2, "arm swing forward and up during the thrust (low_level only)"),
    Parameter("thrust_damping", "1", 0.4, 0.1, 1.0,
              "share of the stiffened leg servos' damping kept in the thrust; less extends faster (low_level only)"),
    Parameter("tuck_stiffness", "1", 3.0, 1.0, 4.0,
              "gain factor of the hip, knee and spine servos for the snap into the tuck (low_level only)"),
    Parameter("tuck_time", "s", CONSTANTS.tuck_move, 0.05, 0.4,
              "duration of the servo move into the tuck; shorter closes it sooner and spins faster earlier "
              "(low_level only)"),
    Parameter("tuck_damping", "1", 0.0, 0.0, 8.0,
              "damping factor of the hip, knee and spine servos in the move into the tuck; 0 = tuck_stiffness "
              "x 2 (overdamped, slow to close); lighter closes the tuck sooner (low_level only)"),
    FLIGHT_STEP_PARAMETER,
    Parameter("landing_lean", "rad", 0.4, -0.5, 1.0,
              "the body opens to land this far short of the full turn (whole-body angle at touchdown; "
              "the landing's ground force turns the rest) (low_level only)"),
    Parameter("open_time", "s", 0.1, 0.03, 0.4, "time to open from the tuck, in the opening prediction (low_level only)"),
    Parameter("open_blend", "s", 0.1, 0.0, 0.3,
              "the joints move from the tuck to the landing's targets over this time (low_level only)"),
    Parameter("landing_knee_flexion", "rad", 0.8, 0.3, 1.4, "knee bend held for touchdown (low_level only)"),
    Parameter("foot_delta", "m", -0.15, -0.3, 0.3, "landing: foot servo delta (low_level only)"),
    Parameter("landing_foot_lead_time", "s", 0.1, 0.0, 0.6,
              "landing: the feet land this many seconds of horizontal COM travel ahead of the COM (low_level only)"),
    Parameter("spin_placement", "s/m", 0.25, 0.0, 0.5,
              "landing: feet placed this factor x (angular momentum / mass) against the spin (low_level only)"),
)
SOMERSAULTS_TABLE = register_table(TableType(
    "somersaults", with_constants(SOMERSAULT_SETTINGS, SOMERSAULT_CONSTANTS),
    lambda body: (*((f"{kind} {e['direction']} {e['strength']}", e["settings"]) for kind in ("somersaults", "not_found")
                    for e in body.get(kind, [])), *constant_rows(body)),
    (somersault_row,)))


@register
class Somersault(Sequence):
    name = "somersault"
    world_frame = True             # turns / aims in the world's X-Z plane from the origin
    summary = "Standing tuck somersault, backward or forward: crouch, leap with spin, tuck, open, land, balance (Wooten §8.4-8.5)."
    default_duration = 5.0
    settings_schema = SOMERSAULT_SETTINGS
    schema = SkillSchema(
        Choice("direction", DIRECTIONS, "forward", "the way the somersault turns: backward or forward"),
        Parameter("low_level", "bool", 0.0, 0.0, 1.0,
                  "1 = use the take-off and landing settings below instead of the calibrated ones"),
        settings=SOMERSAULT_SETTINGS,
    )

    @property
    def direction(self) -> float:
        """+1 for a forward somersault, -1 for a backward one."""
        return 1.0 if int(round(self.params["direction"])) == 1 else -1.0

    @property
    def direction_name(self) -> str:
        return DIRECTIONS[int(round(self.params["direction"]))]

    def settings(self) -> dict:
        p = self.params
        if p["low_level"]:
            return {k: p[k] for k in SETTINGS}
        row = calibrated(self.ctx.character.name, self.direction_name, run_strength(self.ctx))["settings"]
        return dict(OLD_ROW, **row)

    def check_feasible(self) -> None:
        if self.params["low_level"]:
            return
        name, strength = self.ctx.character.name, run_strength(self.ctx)
        if calibrated(name, self.direction_name, strength) is None:
            table = load_table(name)
            best = [e["best"] for e in table.get("not_found", [])
                    if e["direction"] == self.direction_name and e["strength"] == strength]
            raise uncalibrated(name, f"{self.direction_name} somersault", strength,
                               [f"{e['direction']} with {e['strength']} strength" for e in table["somersaults"]],
                               best[0] if best else None, "python -m sim_core calibrate somersault")

    # ------------------------------------------------------------------ the script
    def steps(self) -> list[Step]:
        ctx = self.ctx
        cfg = self.cfg = self.settings()
        self.rotation = FlightRotation(ctx.model, ctx.data, ctx.actor)
        self.open_inertia = position_inertia(ctx.model, ctx.character, "layout", ctx.actor)
        self.touchdown_com = CONSTANTS.touchdown_com * float(ctx.data.subtree_com[ctx.actor.root][2])
        takeoff = cfg

        def tuck(t):
            self.rotation.takeoff(t)
            ctx.step_division = int(cfg["flight_step_division"])
            return Tumble(Tumble.schema.validate(dict(position=TUCK, stiffness=cfg["tuck_stiffness"],
                                                    move_time=cfg["tuck_time"], damping=cfg["tuck_damping"])),
                          ctx, self.rotation)

        def land(t):
            return Landing(Landing.schema.validate(dict(
                knee_flexion=cfg["landing_knee_flexion"], fast_knee_flexion=cfg["landing_knee_flexion"],
                foot_delta=cfg["foot_delta"], foot_lead_time=cfg["landing_foot_lead_time"],
                spin_placement=cfg["spin_placement"], blend_time=cfg["open_blend"])), ctx)

        return takeoff_steps(ctx, takeoff) + [
            Step("tuck", tuck, lambda b, t: self.time_to_open()),
            Step("land", land, lambda b, t: b.finished),
            Step("balance", lambda t: balance_after_landing(ctx, self.previous))]

    def time_to_open(self) -> bool:
        """Open when the rotation the opened body will still make before the feet reach the
        ground (at the layout's rate for the measured angular momentum, plus about half the
        difference over the opening) is what the somersault has left, less the landing lean."""
        d = self.ctx.data
        turned = self.direction * self.rotation.whole_body
        remaining = 2 * math.pi - self.cfg["landing_lean"] - turned
        rate_now = self.direction * self.rotation.rate()
        root = self.ctx.actor.root
        rate_open = self.direction * float(d.subtree_angmom[root][1]) / self.open_inertia
        time_left = time_to_fall_to(float(d.subtree_com[root][2]), float(d.subtree_linvel[root][2]), self.touchdown_com)
        if time_left <= self.cfg["open_time"]:
            return True
        return rotation_to_come(rate_now, rate_open, time_left, self.cfg["open_time"]) >= remaining

    def update(self, t: float) -> None:
        self.rotation.update(t)
        super().update(t)

    @classmethod
    def assess(cls, trajectory):
        return somersault_assess(trajectory)


def pelvis_pitch(trajectory) -> np.ndarray:
    """Unwrapped angle (rad, + forward) of the pelvis's long axis in the X-Z plane, per frame."""
    a = trajectory.arrays
    w, x, y, z = a["body_quat"][:, list(a["body_names"]).index("PELVIS")].T
    return np.unwrap(np.arctan2(2 * (x * z + w * y), 1 - 2 * (x * x + y * y)))


def somersault_assess(trajectory) -> tuple[str, dict]:
    """The leap's outcome (balanced at the end, no fall, no step; the crouch before the take-off
    a squat that may go down to SQUAT_LOWEST) plus the measured rotation:
    the pelvis's turn about the somersault axis over the skill (from the standing start to the
    end of the run; a skill that ends balanced has turned a whole number of times, and this
    counts them: TARGETS.md's "the measured rotation count is right"), and in flight alone
    (lift-off to touchdown: the body leans back at take-off and lands short of upright, so this
    is less than a turn); the whole-body angular momentum's drift in flight; the twist rate at
    take-off (none is asked for)."""
    outcome, metrics = leap_assess(trajectory, squat_floor=SQUAT_LOWEST)
    a, meta = trajectory.arrays, trajectory.meta
    t = a["time"]
    pitch = pelvis_pitch(trajectory)
    flying = feet_above_surface(trajectory).min(axis=1) > AIRBORNE_HEIGHT
    direction = 1.0 if int(round(meta["params"]["direction"])) == 1 else -1.0
    metrics["direction"] = DIRECTIONS[int(direction > 0)]
    metrics["rotation"] = float(direction * (pitch[-1] - pitch[0]))
    metrics["somersaults"] = metrics["rotation"] / (2 * math.pi)
    if flying.any():
        first = int(np.argmax(flying))
        last = first + int(np.argmin(flying[first:])) if not flying[first:].all() else len(t) - 1
        metrics["flight_rotation"] = float(direction * (pitch[last] - pitch[first]))
        momentum = a["angmom"][first:last]
        metrics["angular_momentum_drift"] = float(
            np.abs(momentum - momentum[0]).max() / max(np.linalg.norm(momentum[0]), 1e-9)) if len(momentum) else 0.0
        metrics["first_flight_time"] = float(t[last] - t[first])
        metrics["first_touchdown_time"] = float(t[last])
        metrics["takeoff_twist_rate"] = float(a["qvel"][first, 5])
    if outcome == "success" and abs(metrics["rotation"] - 2 * math.pi) > ROTATION_TOLERANCE:
        outcome = "wrong_rotation"
    return outcome, metrics
