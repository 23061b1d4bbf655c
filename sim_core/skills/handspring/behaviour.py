"""Back handspring (Wooten §8.3), built only by sequencing the basis behaviours: balance (sit back
until the COM falls behind the heels) -> leap (thrust backward with the arms swinging overhead) ->
tumble (an arched layout, the arms reaching for the floor) -> hands (the hands land through the
contact model and the arms are held stiff) -> push (a set time after the hands land, Wooten: "the
hands ... were programmed to push off the ground a set amount of time after contact": the
shoulders block and the hips snap down) -> second flight (the snap held until the turn is nearly
complete) -> land -> balance.

The thesis: "The leaping controller initiates the maneuver by causing the character to jump
backwards into the air with substantial rotation about the somersaulting axis. The tumbling
controller performs a backwards 1/2 somersault in the layout position. The character then lands on
his hands and after a set amount of time pushes off the ground to perform another 1/2 somersault.
The landing controller positions the legs for touchdown and transitions to the balance
controller." Nothing holds the hands: they touch, carry the body and leave by contact forces alone.

The settings per character and strength come from ``sim_core/tuned/tables/handspring_<character>.json``,
written by ``python -m sim_core calibrate handspring`` (a search over whole simulated
handsprings, scored off the simulation; docs/planning.md).
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np

from ...ballistics import GRAVITY
from ...analysis import FOOT_BODIES, feet_above_surface, standard_metrics, surface_under_points, true_runs
from ...control.balance import Balance, inside_a_skill, standing_hip_height
from ...control.behaviour import Behaviour, ControlContext, register
from ...control.leap import (CONSTANTS as LEAP, AIRBORNE_HEIGHT, Airborne,
                                   Landing, LeapThrust, balance_after_landing, run_strength)
from ...control.sequencer import Sequence, Step
from ..somersault.behaviour import FLIGHT_STEP_PARAMETER, ROTATION_TOLERANCE, SQUAT_LOWEST, pelvis_pitch
from ...control.tumble import FlightRotation, both_sides
from ...control.tuned import uncalibrated
from ...schema import Parameter, Schema
from ...tuned import TableError, TableType, keyed, load, register as register_table
from ...tuned.settings import SkillSchema, ranged as setting   # a setting's range: its default is the table's
from ...tuned.constants import constant, constant_rows, read_constants, with_constants

# the handspring's hand-set constants: data, handspring_any.json's "constants" (docs/tables.md)
HANDSPRING_CONSTANTS = Schema(
    constant("sit_timeout", "s", 0.0, 10.0, "the thrust starts at the latest this long into the run, fallen back or not"),
    constant("arch_move", "s", 0.01, 1.0, "the servo move into the arch after lift-off"),
    constant("arch_gain", "1", 1.0, 10.0, "gain factor of the arched joints' servos in the first flight"),
    constant("push_clear", "s", 0.0, 0.5, "after the push starts, this long before a flight counts as the second one"),
    constant("landing_blend", "s", 0.0, 1.0, "the landing's targets blend in from the snap over this time"),
    constant("crouch_move_start", "s", 0.0, 2.0, "the sit's crouch starts moving this long after the run begins"),
    constant("crouch_move_time", "s", 0.05, 3.0, "how long the sit's crouch takes to reach its posture"),
    constant("hands_move", "s", 0.01, 1.0, "the servo move of the arms' stiffening when the hands touch"),
    constant("snap_move", "s", 0.01, 1.0, "the servo move of the snap-down after the push"),
    constant("arch", "rad", -3.2, 3.2, "joint angles of the arch by joint name (the spine at, near, its extension range)"),
    constant("snap_spine", "rad", -3.2, 3.2, "spine angles of the snap-down by joint name"),
)
CONSTANTS = read_constants("handspring", HANDSPRING_CONSTANTS)

HAND_BODIES = ("HANDR", "HANDL")
SKID_LIMIT = 0.05          # m: the middle of the feet moving further after touchdown is a step or skid
ARMS = ["shoulder_r_z", "shoulder_l_z", "shoulder_r_x", "shoulder_l_x", "elbow_r_z", "elbow_l_z",
        "wrist_r_x", "wrist_l_x"]

TAKEOFF_SETTINGS = ("crouch_height", "crouch_pitch", "com_offset", "sit_extra", "thrust_lean", "liftoff_hip",
                    "arm_swing", "arm_gain", "arm_time", "thrust_damping")
HAND_SETTINGS = ("arch_arm", "arch_hip", "neck", "hand_gain", "push_delay", "push_shoulder", "push_hip",
                 "snap_knee", "push_move", "push_gain", "push_damping")
LANDING_SETTINGS = ("landing_lean", "open_height", "ready_height", "landing_knee_flexion", "foot_delta", "landing_foot_lead_time", "spin_placement")
SETTINGS = TAKEOFF_SETTINGS + HAND_SETTINGS + LANDING_SETTINGS + ("flight_step_division",)
OLD_ROW = {"push_damping": 0.0, "flight_step_division": 1}   # what a row calibrated before these settings
                            # ran with: it reproduces


def load_table(character: str) -> dict:
    """The character's handspring table (no rows if there is none)."""
    return load("handspring", character) or {"handsprings": []}


def handspring_row(table: dict, strength: str) -> dict | None:
    """The row of the strength (keyed), or None."""
    return keyed(table["handsprings"], strength=strength)


def calibrated(character: str, strength: str) -> dict | None:
    """The calibrated handspring of this character and strength, or None."""
    return handspring_row(load_table(character), strength)


SETTING_RANGES = Schema(
    setting("crouch_height", "m", 0.5, 0.9, "pelvis height of the sit (low_level only)"),
    setting("crouch_pitch", "rad", -0.3, 1.5, "torso pitch in the sit (low_level only)"),
    setting("com_offset", "m", -0.25, -0.05, "COM behind (-) the middle of the feet in the sit (low_level only)"),
    setting("sit_extra", "m", 0.0, 0.3,
              "the thrust starts once the COM, falling back, is this much further behind (low_level only)"),
    setting("thrust_lean", "m", -0.4, 0.0,
              "COM behind (-) the middle of the feet along the thrust's extension: the push goes back (low_level only)"),
    setting("liftoff_hip", "rad", 0.0, 0.5, "hip extension at lift-off (backward spin) (low_level only)"),
    setting("arm_swing", "rad", 1.5, 3.14, "arm swing forward and up to overhead during the thrust (low_level only)"),
    setting("arm_gain", "1", 1.0, 10.0, "gain factor of the shoulder and elbow servos for the arm swing (low_level only)"),
    setting("arm_time", "s", 0.05, 0.3, "duration of the arm swing (low_level only)"),
    setting("thrust_damping", "1", 0.1, 1.0,
              "share of the stiffened leg servos' damping kept in the thrust (low_level only)"),
    setting("arch_arm", "rad", 1.5, 3.14,
              "shoulder flexion in the first flight: the arms reach for the floor behind the head (low_level only)"),
    setting("arch_hip", "rad", 0.0, 0.52, "hip extension of the arched first flight (low_level only)"),
    setting("neck", "rad", -1.0, 0.5, "head tilt in the first flight, back (-) to see the floor (low_level only)"),
    setting("hand_gain", "1", 1.0, 15.0, "gain factor of the arm servos while the hands take the weight (low_level only)"),
    setting("push_delay", "s", 0.0, 0.3, "the push starts this long after the hands touch (low_level only)"),
    setting("push_shoulder", "rad", 1.0, 3.14, "shoulder angle the push (the block) moves to (low_level only)"),
    setting("push_hip", "rad", -2.0, 0.5, "hip flexion (-) of the snap-down (low_level only)"),
    setting("snap_knee", "rad", 0.0, 1.2, "knee bend of the snap-down (low_level only)"),
    setting("push_move", "s", 0.03, 0.3, "duration of the push's moves (low_level only)"),
    setting("push_gain", "1", 1.0, 10.0, "gain factor of the servos of the push (low_level only)"),
    setting("push_damping", "1", 0.0, 10.0,
              "damping factor of the servos of the push; 0 = push_gain (damped as much as stiffened, so no "
              "faster than the default servo); lighter moves the block and the snap-down sooner (low_level only)"),
    setting("landing_lean", "rad", 0.0, 1.6,
              "the landing starts when the pelvis has turned this much short of one turn (low_level only)"),
    setting("open_height", "m", 0.4, 1.1,
              "... or when the COM has come down to this height, whichever is first (low_level only)"),
    setting("ready_height", "m", 0.0, 0.8,
              "... or when a foot has come down to this height above the ground (low_level only)"),
    setting("landing_knee_flexion", "rad", 0.3, 1.4, "knee bend held for touchdown (low_level only)"),
    setting("foot_delta", "m", -0.3, 0.3, "landing: foot servo delta (low_level only)"),
    setting("landing_foot_lead_time", "s", 0.0, 0.6,
              "landing: the feet land this many seconds of horizontal COM travel ahead of the COM (low_level only)"),
    setting("spin_placement", "s/m", 0.0, 0.5,
              "landing: feet placed this factor x (angular momentum / mass) against the spin (low_level only)"),
    FLIGHT_STEP_PARAMETER,
)
HANDSPRING_TABLE = register_table(TableType(
    "handspring", with_constants(SETTING_RANGES, HANDSPRING_CONSTANTS),
    lambda body: (*((f"{kind} {e['strength']}", e["settings"]) for kind in ("handsprings", "not_found")
                    for e in body.get(kind, [])), *constant_rows(body)),
    (handspring_row,)))
# the settings' defaults are data: the man's calibrated unlimited-strength row, so that low_level=1 with
# nothing set runs that handspring
DEFAULT_ROW = {**OLD_ROW, **(calibrated("man", "unlimited") or {"settings": {}})["settings"]}
if set(DEFAULT_ROW) != set(SETTING_RANGES.by_name):
    raise TableError("handspring_man.json: the handspring settings' defaults are its unlimited row, which names "
                     f"{', '.join(sorted(DEFAULT_ROW)) or 'nothing'}; needed: {', '.join(SETTING_RANGES.by_name)}")
HANDSPRING_SETTINGS = Schema(*(dataclasses.replace(p, default=float(DEFAULT_ROW[p.name]))
                               for p in SETTING_RANGES.parameters))


class HandContact:
    """Whether a hand touches the world (the ground or a box), from MuJoCo's contact list."""

    def __init__(self, model, prefix: str = ""):
        self.model = model
        self.hands = np.array([model.body(prefix + n).id for n in HAND_BODIES])

    def touching(self, data) -> bool:
        if not data.ncon:
            return False
        bodies = self.model.geom_bodyid[data.contact.geom[: data.ncon]]
        world = bodies == 0
        hand = np.isin(bodies, self.hands)
        return bool(((world[:, 0] & hand[:, 1]) | (world[:, 1] & hand[:, 0])).any())


class PoseMove(Behaviour):
    """Basis step of a skill: Hermite moves of some joints to named angles, some servos' gains
    scaled; every other target is held where it is."""

    schema = Schema()

    def __init__(self, ctx: ControlContext, goals: dict[str, float], move_time: float, gain: float = 1.0,
                 gain_joints: list[str] | None = None, damping: float | None = None):
        super().__init__({}, ctx)
        self.goals, self.move_time, self.gain = goals, move_time, gain
        self.damping = gain if damping is None else damping       # a factor on the servos' damping
        self.gain_joints = list(goals) if gain_joints is None else gain_joints

    def start(self, t: float) -> None:
        s = self.ctx.servos
        s.offset[:] = 0.0
        s.hold(s.smoothed_target(t), t)
        s.move_to(s.indices(list(self.goals)), np.array(list(self.goals.values())), self.move_time, t)
        stiff = s.indices(self.gain_joints)
        s.set_gains(stiff, s.default_kp[stiff] * self.gain, s.default_kv[stiff] * self.damping)

    def update(self, t: float) -> None:
        """The servos hold the pose."""


@register
class Handspring(Sequence):
    name = "handspring"
    world_frame = True             # turns / aims in the world's X-Z plane from the origin
    summary = ("Standing back handspring: sit back, leap backward, arch onto the hands, push off, snap down, "
               "land, balance (Wooten §8.3).")
    default_duration = 5.0
    settings_schema = HANDSPRING_SETTINGS
    schema = SkillSchema(
        Parameter("low_level", "bool", 0.0, 0.0, 1.0,
                  "1 = run the tuned settings as set (--set crouch_height=...; their defaults are the man's "
                  "calibrated unlimited-strength row) instead of the calibrated ones"),
        settings=HANDSPRING_SETTINGS,
    )

    def settings(self) -> dict:
        p = self.params
        if p["low_level"]:
            return {k: p[k] for k in SETTINGS}
        return dict(OLD_ROW, **calibrated(self.ctx.character.name, run_strength(self.ctx))["settings"])

    def check_feasible(self) -> None:
        if self.params["low_level"]:
            return
        name, strength = self.ctx.character.name, run_strength(self.ctx)
        if calibrated(name, strength) is None:
            table = load_table(name)
            best = [e["best"] for e in table.get("not_found", []) if e["strength"] == strength]
            raise uncalibrated(name, "back handspring", strength, [f"{e['strength']} strength" for e in table["handsprings"]],
                               best[0] if best else None, "python -m sim_core calibrate handspring")

    # ------------------------------------------------------------------ the script
    def steps(self) -> list[Step]:
        ctx = self.ctx
        c = self.cfg = self.settings()
        self.rotation = FlightRotation(ctx.model, ctx.data, ctx.actor)
        self.hands = HandContact(ctx.model, ctx.actor.prefix)
        self.airborne = Airborne(ctx.model, ctx.actor.prefix)
        stand = standing_hip_height(ctx.character)
        self.t_hands = None

        def sit(t):
            return Balance(inside_a_skill(
                pelvis_height=c["crouch_height"], torso_pitch=c["crouch_pitch"], com_offset_x=c["com_offset"],
                move_start=CONSTANTS.crouch_move_start, move_time=CONSTANTS.crouch_move_time, hold_time=0.0,
                return_to_stand=0), ctx)

        def fallen_back(b, t):
            return b.com_ahead_of_support() < c["com_offset"] - c["sit_extra"] or t > CONSTANTS.sit_timeout

        def thrust(t):
            return ArmSwingThrust({}, ctx, c["crouch_height"], LEAP.vertical_timing, LEAP.ankle_gain_vertical,
                                  c["liftoff_hip"], c["arm_swing"], stand_height=stand, thrust_damping=c["thrust_damping"],
                                  thrust_lean=c["thrust_lean"], arm_gain=c["arm_gain"], arm_time=c["arm_time"])

        arch = both_sides({"shoulder_*_z": c["arch_arm"], "hip_*_y": c["arch_hip"], "neck_c2_y": c["neck"], **CONSTANTS.arch})
        push = both_sides({"shoulder_*_z": c["push_shoulder"], "hip_*_y": c["push_hip"], "knee_*_y": c["snap_knee"],
                            **CONSTANTS.snap_spine})

        def hands(t):
            self.t_hands = t
            return PoseMove(ctx, {}, CONSTANTS.hands_move, c["hand_gain"], gain_joints=ARMS)

        def arch_flight(t):
            ctx.step_division = int(c["flight_step_division"])     # until the landing's touchdown
            return PoseMove(ctx, arch, CONSTANTS.arch_move, CONSTANTS.arch_gain)

        def pushed_off(b, t):
            return (t - self.t_hands > c["push_delay"] + CONSTANTS.push_clear and not self.hands.touching(ctx.data)
                    and self.airborne.in_flight(ctx.data))

        def open_for_landing(b, t):
            turned = -self.rotation.somersault
            return (turned >= 2 * math.pi - c["landing_lean"] or ctx.data.subtree_com[ctx.actor.root][2] < c["open_height"]
                    or self.airborne.feet_heights(ctx.data).min() < c["ready_height"])

        def land(t):
            return Landing(Landing.schema.validate(dict(
                knee_flexion=c["landing_knee_flexion"], fast_knee_flexion=c["landing_knee_flexion"], foot_delta=c["foot_delta"],
                foot_lead_time=c["landing_foot_lead_time"], spin_placement=c["spin_placement"], blend_time=CONSTANTS.landing_blend)), ctx)

        return [
            Step("crouch", sit, fallen_back),
            Step("thrust", thrust, lambda b, t: b.lifted_off()),
            Step("arch", arch_flight, lambda b, t: self.hands.touching(ctx.data)),
            Step("hands", hands, lambda b, t: t - self.t_hands >= c["push_delay"]),
            Step("push", lambda t: PoseMove(ctx, push, c["push_move"], c["push_gain"],
                                            gain_joints=list(push) + ["elbow_r_z", "elbow_l_z"],
                                            damping=c["push_damping"] or None), pushed_off),
            Step("snap", lambda t: PoseMove(ctx, {}, CONSTANTS.snap_move), open_for_landing),
            Step("land", land, lambda b, t: b.finished),
            Step("balance", lambda t: balance_after_landing(ctx, self.previous))]

    def update(self, t: float) -> None:
        self.rotation.update(t)
        super().update(t)

    @classmethod
    def assess(cls, trajectory):
        return handspring_assess(trajectory)


class ArmSwingThrust(LeapThrust):
    """The leap thrust with the arms swung overhead by stiffened shoulder and elbow servos over
    ``arm_time``, so that they are up by lift-off (a slow swing would go on in the air and turn the
    body the other way)."""

    def __init__(self, params, ctx, *args, arm_gain: float, arm_time: float, **kwargs):
        super().__init__(params, ctx, *args, **kwargs)
        self.arm_gain, self.arm_time = arm_gain, arm_time

    def start(self, t: float) -> None:
        super().start(t)
        s = self.ctx.servos
        arms = s.indices(["shoulder_r_z", "shoulder_l_z", "elbow_r_z", "elbow_l_z"])
        s.set_gains(arms, s.default_kp[arms] * self.arm_gain, s.default_kv[arms] * self.arm_gain)
        s.move_to(s.indices(["shoulder_r_z", "shoulder_l_z"]), np.array([self.arm_swing, -self.arm_swing]),
                  self.arm_time, t)


def handspring_assess(trajectory) -> tuple[str, dict]:
    """The handspring's phases read off the contacts - first flight (nothing touches), hands (a hand
    on the ground), second flight, landing - and its outcome: one backward turn of the pelvis
    (2 pi within ROTATION_TOLERANCE, standing start to the end), the hands between two flights, no
    body but the feet and (in their phase) the hands on the ground, the feet staying where they
    land, still and standing at the end. Also the whole-body angular momentum's drift in each
    flight, the take-off state and the rotation reached before a fall (for the calibration)."""
    a = trajectory.arrays
    names = trajectory.body_names
    metrics = standard_metrics(trajectory, allowed_contacts=FOOT_BODIES + HAND_BODIES)
    t = a["time"]
    last = len(t) - 1
    contact = a["ground_contact"]
    hand = contact[:, [names.index(n) for n in HAND_BODIES]].any(axis=1)
    foot = contact[:, [names.index(n) for n in FOOT_BODIES]].any(axis=1)
    feet_up = feet_above_surface(trajectory).min(axis=1) > AIRBORNE_HEIGHT
    pitch = pelvis_pitch(trajectory)
    rotation = pitch[0] - pitch                                   # + backward
    metrics["rotation"] = float(rotation[-1])
    metrics["somersaults"] = metrics["rotation"] / (2 * math.pi)
    metrics["com_rise"] = float(a["com"][:, 2].max() - a["com"][0, 2])
    metrics["com_travel"] = float(a["com"][-1, 0] - a["com"][0, 0])
    flights = true_runs(~hand & ~foot & feet_up)               # (first frame, first frame after)
    first = flights[0] if flights else None
    takeoff = first[0] if first else len(t)
    hands_on = None
    if first:
        after = np.flatnonzero(hand[first[1]:])
        hands_on = first[1] + int(after[0]) if len(after) else None
    second = next((f for f in flights if f[0] > hands_on), None) if hands_on is not None else None
    # a fall: a body but the feet and hands on the ground, the hands on it outside their phase, or
    # the pelvis below half its standing height. The sit before the take-off is a deliberate squat:
    # there the pelvis may go down to the balance behaviour's deepest crouch (SQUAT_LOWEST), and
    # ``sit_shortfall`` is how far it went below (judged apart, so that the calibration sees how far
    # the rest got)
    allowed = np.array([n in FOOT_BODIES + HAND_BODIES for n in names])
    pelvis = a["body_pos"][:, names.index("PELVIS")]
    low = pelvis[:, 2] - surface_under_points(trajectory, pelvis) < 0.5 * pelvis[0, 2]
    low[:takeoff] = False
    out_of_phase = hand.copy()
    out_of_phase[takeoff:second[1] if second else len(t)] = False
    falling = np.flatnonzero((contact & ~allowed).any(axis=1) | low | out_of_phase)
    metrics["sit_shortfall"] = float(max(0.0, SQUAT_LOWEST - pelvis[:takeoff, 2].min())) if takeoff else 0.0
    fall_frame = int(falling[0]) if len(falling) else last
    metrics["rotation_before_fall"] = float(rotation[: fall_frame + 1].max())
    metrics["fell"] = bool(len(falling)) or metrics["sit_shortfall"] > 0.0
    metrics["fall_time"] = (float(t[fall_frame]) if len(falling) else
                            float(t[int(np.argmin(pelvis[:takeoff, 2]))]) if metrics["fell"] else None)
    if first:
        metrics["liftoff_time"] = float(t[first[0]])
        metrics["liftoff_angular_momentum"] = float(a["angmom"][first[0], 1])
        metrics["liftoff_velocity"] = a["com_vel"][first[0]].tolist()
        metrics["first_flight_time"] = float(t[min(first[1], last)] - t[first[0]])
    if hands_on is not None:
        metrics["hands_touchdown_time"] = float(t[hands_on])
        metrics["rotation_at_hands"] = float(rotation[hands_on])
        metrics["feet_down_at_hands"] = bool(foot[hands_on])
    if second:
        touchdown = min(second[1], last)
        metrics["hand_contact_time"] = float(t[second[0]] - t[hands_on])
        metrics["second_flight_time"] = float(t[touchdown] - t[second[0]])
        metrics["touchdown_time"] = float(t[touchdown])
        metrics["touchdown_velocity"] = a["com_vel"][touchdown].tolist()
        middle = a["support_points"][touchdown:, :, :2].mean(axis=1)
        metrics["landing_skid"] = float(np.linalg.norm(middle - middle[0], axis=1).max())
        metrics["rebounds"] = len([f for f in flights if f[0] > touchdown])
        # a travelling skill: the standard "stepped" (a foot away from where it started) would
        # always hold; here it is the landing's (a skid or a rebound after touchdown)
        metrics["stepped"] = bool(metrics["landing_skid"] > SKID_LIMIT or metrics["rebounds"])
        later = falling[falling > touchdown]
        metrics["time_on_feet"] = float(t[later[0] if len(later) else -1] - t[touchdown])
    weight = GRAVITY * float(trajectory.meta["total_mass"])
    for phase, (i, j) in (("thrust", (0, first[0] if first else None)),
                          ("hands", (hands_on, second[0] if second else None)),
                          ("landing", (second[1] if second else None, len(t)))):
        if i is not None and j is not None and j > i:
            metrics[f"peak_{phase}_grf_body_weights"] = float(a["grf"][i:j, 2].max() / weight)
    drifts = []
    for i, j in [f for f in (first, second) if f]:
        h = a["angmom"][i:j]
        drifts.append(float(np.abs(h - h[0]).max() / max(np.linalg.norm(h[0]), 1e-9)))
    metrics["angular_momentum_drift"] = max(drifts) if drifts else 0.0
    metrics["flight_drifts"] = drifts
    if metrics["fell"]:
        return "fell", metrics
    if not first:
        return "no_flight", metrics
    if hands_on is None:
        return "no_hands", metrics
    if second is None:
        return "no_second_flight", metrics
    if metrics["landing_skid"] > SKID_LIMIT or metrics["rebounds"]:
        return "stepped", metrics
    if metrics["final_com_speed"] >= 0.1:      # criterion: TARGETS.md "still", COM below 0.1 m/s
        return "not_still", metrics
    if abs(metrics["rotation"] - 2 * math.pi) > ROTATION_TOLERANCE:
        return "wrong_rotation", metrics
    return "success", metrics
