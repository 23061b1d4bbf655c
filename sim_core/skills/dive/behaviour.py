"""10 m platform dives (Wooten §8.2.1), built only by sequencing the basis behaviours:
balance (crouch, leaning) -> leap (thrust with the lift-off hip angle that sets the somersault
rate) -> tumble (pike, tuck or layout; arm throw for twists) -> entry (straight "line", arms
overhead) -> the run ends when the hands or head reach the water.

The diver stands backwards at the edge (heels at the edge, water at -X) for the inward group
(somersaulting forward, towards the platform) and the back group (backward), or faces the water
(toes at the edge) for the forward group (forward) and the reverse group (backward, towards the
platform). Opening for the entry is a state-based
transition: the controller predicts, from the measured angular momentum and the ballistic time
left to the water, how far the body will still turn once straightened, and opens when that is
what remains of the dive's rotation (Wooten opened on timing; ch. 5's summary proposes state).

The leap settings per dive (crouch, lean, lift-off hip angle, arm swing) come from
the dive table (``sim_core/tuned/tables/dives_<character>.json``, else ``dives_any.json``: design values),
written by ``python -m sim_core calibrate dive``.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np

from ...character.model import compile_model
from ...character.spec import load_character
from ...control.behaviour import register
from ...control.leap import CONSTANTS as LEAP
from ...control.sequencer import Sequence, Step
from ...ballistics import GRAVITY, time_to_fall_to
from ...control.takeoff import SETTINGS, takeoff_steps
from ...control.tumble import (POSITION_NAMES, FlightRotation, Tumble, position_inertia, position_name, position_radius,
                                    rotation_to_come)
from ...errors import ParameterError
from ...schema import Choice, Parameter, Schema
from .fina import CUSTOM, REPERTOIRE, DiveNumber, parse
from ...tuned import TableType, load, register as register_table, require_calibrated
from ...tuned.settings import SkillSchema
from ...tuned.constants import constant, constant_rows, read_constants, with_constants

# the dive's hand-set constants: data, dives_any.json's "constants" (docs/tables.md)
DIVE_CONSTANTS = Schema(
    constant("takeoff_clear", "s", 0.0, 1.0, "this long without contact makes a take-off"),
    constant("platform_margin", "m", 0.0, 0.5, "room kept between the turning body and the platform"),
    constant("feet_clearance", "m", 0.0, 1.0, "the position is taken once the feet are this far past the platform's edge"),
    constant("position_move", "s", 0.0, 1.0, "after take-off, before the position is held (in the feasibility estimate)"),
    constant("snap", "1", 1.0, 10.0, "gain factor of the hip, knee and spine servos for the moves into and out of the position"),
    constant("open_move", "s", 0.01, 1.0, "the servo move from the position to the line"),
    constant("open_time", "s", 0.0, 1.0, "time to straighten from the position into the line"),
    constant("twist_stop_lead", "s", 0.0, 1.0, "the arms come back this much of the measured twist rate early"),
    constant("tilt_doubling_twists", "1", 0.0, 5.0, "from this many twists the arms come back at the half twist (see twist_moves)"),
    constant("flight_step_division", "count", 1.0, 64.0,
             "the flight's physics step is the model's divided by this: with the 1 ms step a fast twist (10-12 rad/s) "
             "let the flight's angular momentum drift 4 % (measured: 4.4 / 2.1 / 1.0 % at 1 / 0.5 / 0.25 ms)"),
    constant("hold_move", "s", 0.01, 1.0, "the servo move that keeps the lift-off shape until the body is clear of the platform"),
    constant("entry_reach", "1", 0.0, 3.0, "share of the standing COM height the hands reach below the COM in the line"),
    constant("plan_slope", "1/rad", 0.1, 5.0,
             "a dive's plan (planning/dive.py): somersaults gained per rad of lift-off hip, its first step (measured: "
             "the man's 205B 1.25, the woman's 307C 0.75 on their rows)"),
    constant("plan_step", "rad", 0.05, 1.0, "a dive's plan moves the lift-off hip at most this far per trial"),
    constant("free_tuck_twists", "1", 0.0, 3.0,
             "a dive in the free position (FINA D) somersaults in the tuck and twists in the line at the end up to "
             "this many twists, in the layout throughout above (the twist then needs the whole flight)"),
)
CONSTANTS = read_constants("dives", DIVE_CONSTANTS)

GROUPS = ("inward", "back", "forward", "reverse")
FORWARD_ROTATING = ("inward", "forward")      # the others somersault backward
FACING_THE_WATER = ("forward", "reverse")     # the others stand backwards, heels at the edge
CLOSURE_SETTINGS = ("tuck_time", "tuck_stiffness", "tuck_damping")   # the closure into the position (DIVE_SETTINGS)
LEAP_SETTINGS = SETTINGS + ("thrust_damping", "twist_lead", *CLOSURE_SETTINGS)
ROTATION_TOLERANCE = 0.25   # turns: a dive's somersaults and twists count within a quarter turn of its name

CALIBRATED_DIVES = {   # the dives python -m sim_core calibrate dive calibrates, per character, in its table's order:
                      # Wooten §8.2.1's two 10 m dives of the man and of the woman; then two beyond the seed
    "man": [dict(group=0, somersaults=1.5, twists=0.0, position=1),      # inward 1 1/2 pike
            dict(group=1, somersaults=1.5, twists=0.5, position=2),      # back 1 1/2 with 1/2 twist
            dict(group=2, somersaults=1.5, twists=0.0, position=1),      # forward 1 1/2 pike
            dict(group=3, somersaults=1.5, twists=0.0, position=2)],     # reverse 1 1/2 tuck
    "woman": [dict(group=0, somersaults=2.5, twists=0.0, position=1),    # inward 2 1/2 pike
              dict(group=1, somersaults=1.5, twists=2.5, position=0),    # back 1 1/2 with 2 1/2 twists (free: layout)
              dict(group=2, somersaults=1.5, twists=0.0, position=1),    # forward 1 1/2 pike
              dict(group=3, somersaults=1.5, twists=0.0, position=2)],   # reverse 1 1/2 tuck
}

def group_name(p: dict) -> str:
    return GROUPS[int(round(p["group"]))]


def dive_name(p: dict) -> str:
    twists = f" with {p['twists']:g} twists" if p["twists"] else ""
    return f"{group_name(p)} {p['somersaults']:g} somersault {position_name(p['position'])}{twists}"


def _article(name: str) -> str:
    return ("an " if name[0] in "aeiou" else "a ") + name


def dive_row(table: dict, p: dict) -> dict | None:
    """The dive of the same group most alike (same position, then nearest twists, then nearest
    somersaults, then the row calibrated from the platform nearest the asked one): its settings, or None if the
    table has no dive of the group."""
    group = group_name(p)
    rows = [d for d in table["dives"] if GROUPS[d["group"]] == group]
    if not rows:
        return None
    asked = p.get("platform_height", CALIBRATION_PLATFORM)
    best = min(rows, key=lambda d: (d.get("position", 0) != int(round(p["position"])),
                                    abs(d.get("twists", 0.0) - p["twists"]), abs(d.get("somersaults", 0.0) - p["somersaults"]),
                                    abs(row_platform(d) - asked)))
    return dict(best["settings"])


def row_platform(row: dict) -> float:
    """The platform height (m) a table row was calibrated from: its ``platform``; a row without one is from
    CALIBRATION_PLATFORM (10 m)."""
    return float(row.get("platform", CALIBRATION_PLATFORM))


def calibrated_row(table: dict, p: dict) -> dict | None:
    """The table's row of exactly this dive (group, somersaults, twists, position) calibrated from exactly the
    platform ``p`` asks (``platform_height``; without one, CALIBRATION_PLATFORM), or None."""
    asked = p.get("platform_height", CALIBRATION_PLATFORM)
    return next((d for d in rows_of_dive(table, p) if abs(row_platform(d) - asked) < 1e-9), None)


def nearest_platform_row(table: dict, p: dict) -> dict | None:
    """The table's row of exactly this dive calibrated from the platform nearest the one ``p`` asks (the
    asked one's where there is one; at equal distance the higher platform's), or None."""
    asked = p.get("platform_height", CALIBRATION_PLATFORM)
    rows = rows_of_dive(table, p)
    return min(rows, key=lambda d: (abs(row_platform(d) - asked), -row_platform(d))) if rows else None


def rows_of_dive(table: dict, p: dict) -> list[dict]:
    """The table's rows of exactly this dive (group, somersaults, twists, position), from any platform."""
    key = dive_key(p)
    return [d for d in table["dives"] if all(abs(d.get(k, 0.0) - v) < 1e-9 for k, v in key.items())]


def dive_key(p: dict) -> dict:
    """What names a dive in a table row: group and position codes (whole numbers), somersaults,
    twists."""
    return dict(group=int(round(p["group"])), somersaults=float(p["somersaults"]), twists=float(p["twists"]),
                position=int(round(p["position"])))


def calibrated_here(character: str, p: dict) -> bool:
    """Whether the dive ``p`` has a calibrated row of its own that entered as a success, calibrated from the
    platform it is asked from (calibrated_row: 10 m, or a row's ``platform``)."""
    row = calibrated_row(load("dives", character) or {"dives": []}, p)
    return row is not None and row["measured"].get("outcome") == "success"


def dive_settings(character: str, p: dict) -> dict:
    """Every take-off setting a run of the dive ``p`` uses (without ``low_level``): load_settings over the
    schema's defaults of those a row may lack (the thrust's damping, the twist lead, the position's closure)."""
    defaults = {k: Dive.schema.by_name[k].default for k in ("thrust_damping", "twist_lead", *CLOSURE_SETTINGS)}
    return {**defaults, **load_settings(character, p)}


def load_settings(character: str, p: dict) -> dict:
    """Leap settings for this dive: the character's calibrated dive most alike (dive_row), else
    the group's design row (dives_any)."""
    own = load("dives", character)
    return (own is not None and dive_row(own, p)) or dive_row(load("dives", "any"), p)


DIVE_SETTINGS = Schema(
    Parameter("crouch_height", "m", 0.70, 0.4, 0.95, "pelvis height of the crouch"),
    Parameter("crouch_pitch", "rad", 0.3, 0.0, 1.5, "torso pitch in the crouch"),
    Parameter("com_offset", "m", -0.04, -0.25, 0.25,
              "COM ahead (+) of or behind (-) the middle of the feet: the diver leans and thrusts once the COM has moved that far"),
    Parameter("liftoff_hip", "rad", 0.0, -2.2, 2.0,
              "hip flexion (-, forward somersault) or extension (+, backward) at lift-off"),
    Parameter("arm_swing", "rad", 2.5, -1.0, 3.2, "arm swing during the thrust, forward and up (+) or back (-)"),
    Parameter("thrust_damping", "1", LEAP.thrust_damping_default, 0.1, 1.0,
              "share of the stiffened leg servos' damping kept in the thrust; less extends faster"),
    Parameter("twist_lead", "s", 0.6, 0.0, 2.0,
              "twisting dives: open and throw the arms at the latest this long before the predicted entry "
              "(as soon as clear of the platform when it is longer than the flight)"),
    # the closure into the position once clear of the platform (the defaults: every row calibrated before them)
    Parameter("tuck_time", "s", Tumble.schema.by_name["move_time"].default, 0.05, 1.0,
              "the servo move from the lift-off shape into the pike or tuck; shorter closes it sooner"),
    Parameter("tuck_stiffness", "1", CONSTANTS.snap, 1.0, 4.0,
              "gain factor of the hip, knee and spine servos for the move into the position"),
    Parameter("tuck_damping", "1", 0.0, 0.0, 8.0,
              "damping factor of those servos in that move; 0 = twice the stiffness (overdamped); less closes sooner"),
)

DIVES_TABLE = register_table(TableType(
    "dives", with_constants(DIVE_SETTINGS, DIVE_CONSTANTS),
    lambda body: (*((f"dive {k}", d["settings"]) for k, d in enumerate(body["dives"])), *constant_rows(body)), (dive_row,)))


class DiveSchema(SkillSchema):
    """The dive's schema: a ``dive`` number other than custom sets group, somersaults, twists and
    position (fina.parse; the free position D by CONSTANTS.free_tuck_twists), so that a run's
    parameters, its replay log and its assessment hold the dive as numbers like any other."""

    def validate(self, values: dict, defaults: dict | None = None) -> dict:
        result = super().validate(values, defaults)
        number = self.by_name["dive"].option(result["dive"])
        if number != CUSTOM:
            result.update(dive_parameters(number))
        return result


def dive_parameters(number: str) -> dict:
    """The group, somersaults, twists and position codes of a FINA number."""
    dive = parse(number)
    position = dive.position
    if position == "free":
        position = "tuck" if dive.twists <= CONSTANTS.free_tuck_twists else "layout"
    return dict(group=float(GROUPS.index(dive.group)), somersaults=dive.somersaults, twists=dive.twists,
                position=float(POSITION_NAMES.index(position)))


@register
class Dive(Sequence):
    name = "dive"
    world_frame = True             # turns / aims in the world's X-Z plane from the origin
    summary = "Platform dive: leap backwards off the edge, somersault and twist in flight, enter the water straight (Wooten §8.2.1)."
    default_duration = 4.0
    settings_schema = DIVE_SETTINGS
    schema = DiveSchema(
        DiveNumber("dive", (CUSTOM, *REPERTOIRE), CUSTOM,
                   "a FINA dive number (e.g. 107C: forward 3½ somersaults tuck; 5253B: back 2½ with 1½ twists pike); "
                   "it sets group, somersaults, twists and position; custom: those four as set"),
        Choice("group", GROUPS, "inward", "the dive's group: standing backwards, inward or back; facing the water, "
               "forward or reverse",
               ("Standing backwards, somersault towards the platform", "Standing backwards, somersault away from it",
                "Facing the water, somersault forward", "Facing the water, somersault back towards the platform")),
        Parameter("somersaults", "1", 1.5, 0.5, 4.5, "somersaults before entry (x.5 = head first)"),
        Parameter("twists", "1", 0.0, 0.0, 3.0, "twists (full turns about the long axis), by an arm throw in flight"),
        Choice("position", POSITION_NAMES[:3], "pike", "body position in flight: layout (straight), pike or tuck"),
        Parameter("platform_height", "m", 10.0, 3.0, 10.0, "platform height above the water"),
        Parameter("low_level", "bool", 0.0, 0.0, 1.0, "1 = run the tuned settings as set (--set crouch_height=...) instead of the calibrated ones"),
        Parameter("plan_trials", "count", 12, 0, 40,
                  "a dive its calibrated take-off does not reach from this platform (another height, or a dive with no "
                  "calibrated row) is planned first by this many simulated dives at most (0: the take-off as calibrated)"),
        settings=DIVE_SETTINGS,
    )

    @classmethod
    def scene(cls, params, world, character=None):
        facing = group_name(params) in FACING_THE_WATER
        return dataclasses.replace(world, platform=params["platform_height"], platform_edge="ahead" if facing else "behind")

    # ------------------------------------------------------------------ settings and checks
    @property
    def direction(self) -> float:
        """+1 for a forward somersault, -1 for a backward one."""
        return 1.0 if group_name(self.params) in FORWARD_ROTATING else -1.0

    def settings(self) -> dict:
        p = self.params
        if p["low_level"]:
            return {k: p[k] for k in LEAP_SETTINGS}
        return dive_settings(self.ctx.character.name, p)

    def check_feasible(self) -> None:
        p = self.params
        if not p["low_level"]:
            require_calibrated("dives", self.ctx.character.name, self.name)
        if abs(p["somersaults"] * 2 - round(p["somersaults"] * 2)) > 1e-9:
            raise ParameterError(f"parameter somersaults={p['somersaults']:g} must be a whole or half number")
        if abs(p["twists"] * 2 - round(p["twists"] * 2)) > 1e-9:
            raise ParameterError(f"parameter twists={p['twists']:g} must be a whole or half number")
        limits = self.limits()
        if not p["low_level"]:
            self.refuse_not_reached()
        if limits["angular_momentum"].get(group_name(p), 0.0) <= 0:
            raise ParameterError(
                f"the {self.ctx.character.name} has no calibrated {group_name(p)} take-off that clears "
                f"the platform (python -m sim_core calibrate dive found none)")
        if p["twists"] > limits.get("twists", 0.0) + ROTATION_TOLERANCE:
            raise ParameterError(
                f"{_article(dive_name(p))} cannot be completed by the {self.ctx.character.name}: the arm throw made at most "
                f"{limits.get('twists', 0.0):.2f} twists in a calibrated dive (allowed: that + {ROTATION_TOLERANCE:g})")
        flight = self.flight_time(limits["rise"])
        lead = self.twist_lead_needed()
        if p["twists"] and not p["low_level"] and position_name(p["position"]) != "layout" and lead >= flight:
            raise ParameterError(
                f"{_article(dive_name(p))} cannot be done by the {self.ctx.character.name}: the "
                f"{self.ctx.character.name}'s calibrated twisting {group_name(p)} dive twists from the take-off in the "
                f"layout (twist lead {lead:.2f} s, "
                f"the flight {flight:.2f} s), which leaves no time in the {position_name(p['position'])}; "
                f"use position=0 (layout)")
        capacity = self.rotation_capacity(limits, flight)
        if p["somersaults"] > capacity + ROTATION_TOLERANCE:
            raise ParameterError(
                f"{_article(dive_name(p))} cannot be completed from {p['platform_height']:g} m by the "
                f"{self.ctx.character.name}: the flight allows at most {capacity:.2f} somersaults in this position "
                f"with the largest calibrated take-off angular momentum (allowed: that + {ROTATION_TOLERANCE:g})")

    def twist_lead_needed(self) -> float:
        """How long before the entry the twist of this dive needs the layout: the twist lead of the
        character's calibrated twisting dive of the group nearest in twists (a multi-twist dive
        twists from the take-off in the layout), else the lead this run's settings use."""
        own = load("dives", self.ctx.character.name)
        rows = [d for d in (own or {}).get("dives", []) if d.get("twists") and "twist_lead" in d["settings"]
                and GROUPS[d["group"]] == group_name(self.params)]
        if not rows:
            return self.settings()["twist_lead"]
        return min(rows, key=lambda d: abs(d["twists"] - self.params["twists"]))["settings"]["twist_lead"]

    def refuse_not_reached(self) -> None:
        """A dive the calibration searched and did not reach (the measured outcome of its row from the
        platform nearest the asked one, nearest_platform_row, is not a success) is refused with what it needs and what the take-offs reached."""
        own = load("dives", self.ctx.character.name)
        row = own and nearest_platform_row(own, self.params)
        if not row or row["measured"].get("outcome") == "success":
            return
        m = row["measured"]
        needed = self.momentum_needed(self.flight_time(self.limits()["rise"]))
        why = ("" if row["largest_momentum_clear"] < needed else
               ": the momentum is there, no searched take-off gave the rotations and a vertical entry together")
        raise ParameterError(
            f"{_article(dive_name(self.params))} is not reached by the {self.ctx.character.name} with human strength: "
            f"the best calibrated take-off made {m.get('somersaults') or 0:.2f} somersaults and {m.get('twists') or 0:.2f} "
            f"twists ({m.get('outcome')}, {abs(m.get('takeoff_angular_momentum') or 0):.1f} kg m^2/s at take-off); "
            f"it needs about {needed:.1f} kg m^2/s, the calibration's take-offs reached "
            f"{row['largest_momentum_clear']:.1f}{why} (allowed: the reached dives, python -m sim_core report dive --repertoire)")

    def rotation_capacity(self, limits: dict, flight: float) -> float:
        """Somersaults the flight (``flight`` s from this platform) allows: the largest take-off
        angular momentum the calibration reached for this group without touching the platform,
        spent in the position for the flight time less the take-off and opening, and in the line
        for the rest."""
        momentum = limits["angular_momentum"].get(group_name(self.params), 0.0)
        return momentum * self.rotation_per_momentum(flight) / (2 * math.pi)

    def momentum_needed(self, flight: float) -> float:
        """The take-off angular momentum (kg m^2/s) the dive's somersaults need in a flight of
        ``flight`` s: the inverse of rotation_capacity."""
        return 2 * math.pi * self.params["somersaults"] / self.rotation_per_momentum(flight)

    @classmethod
    def momentum_needed_by(cls, character: str, params: dict) -> float:
        """momentum_needed of a dive (validated ``params``) of a named character, from its
        table's rise, outside a run (the calibration's start, the repertoire report)."""
        spec = load_character(character)
        model, _ = compile_model(spec)
        rise = (load("dives", character) or load("dives", "any"))["limits"]["rise"]
        flight = flight_time(params["platform_height"], rise, entry_reach(spec))
        per_momentum = rotation_per_momentum(flight, position_inertia(model, spec, position_name(params["position"])),
                                             position_inertia(model, spec, "line"))
        return 2 * math.pi * params["somersaults"] / per_momentum

    def rotation_per_momentum(self, flight: float) -> float:
        return rotation_per_momentum(flight, self._position_inertia(), self._line_inertia())

    def limits(self) -> dict:
        return (load("dives", self.ctx.character.name) or load("dives", "any"))["limits"]

    def flight_time(self, rise: float) -> float:
        return flight_time(self.params["platform_height"], rise, self._entry_reach())

    def _entry_reach(self) -> float:
        return entry_reach(self.ctx.character)

    def _position_inertia(self) -> float:
        return position_inertia(self.ctx.model, self.ctx.character, position_name(self.params["position"]),
                                self.ctx.actor)

    def _line_inertia(self) -> float:
        if not hasattr(self, "_line"):
            self._line = position_inertia(self.ctx.model, self.ctx.character, "line", self.ctx.actor)
        return self._line

    # ------------------------------------------------------------------ the script
    def steps(self) -> list[Step]:
        p, ctx = self.params, self.ctx
        cfg = self.cfg = self.settings()
        self.rotation = FlightRotation(ctx.model, ctx.data, ctx.actor)
        self.target = 2 * math.pi * p["somersaults"]
        self.twist_target = 2 * math.pi * p["twists"]
        self.entry_bodies = [ctx.actor.body_id(n) for n in ("HANDR", "HANDL", "HEAD", "FOOTR", "FOOTL")]

        def tumble(t):
            self.rotation.takeoff(t)
            return _Aerial(Tumble.schema.validate(dict(position=p["position"], move_time=cfg["tuck_time"],
                                                       stiffness=cfg["tuck_stiffness"], damping=cfg["tuck_damping"])),
                           ctx, self.rotation, self)

        def entry(t):
            return _Aerial(Tumble.schema.validate(dict(position=3, move_time=CONSTANTS.open_move, stiffness=CONSTANTS.snap)), ctx,  # definition: 3 is the line
                           self.rotation, self)

        return takeoff_steps(ctx, cfg) + [
            Step("tumble", tumble, lambda b, t: self.time_to_open(t)), Step("entry", entry)]

    # ------------------------------------------------------------------ transitions
    def time_to_open(self, t: float) -> bool:
        """Open when the rotation the straight body will still make before the hands reach the
        water (at the line's rate for the measured angular momentum, plus about half the
        difference over the opening) equals what the dive has left."""
        d = self.ctx.data
        remaining = self.target - self.direction * self.rotation.whole_body
        rate_now = self.direction * self.rotation.rate()
        root = self.ctx.actor.root
        rate_line = self.direction * float(d.subtree_angmom[root][1]) / self._line_inertia()
        time_left = time_to_fall_to(float(d.subtree_com[root][2]), float(d.subtree_linvel[root][2]),
                                    -self.params["platform_height"] + self._entry_reach())
        coming = rotation_to_come(rate_now, rate_line, time_left, CONSTANTS.open_time)
        if self.twist_target and time_left <= self.cfg["twist_lead"]:
            return True                  # the twist needs this long in the layout
        if time_left <= CONSTANTS.open_time:
            return True                  # enter straight even if the rotation falls short
        return coming >= remaining

    def start(self, t: float) -> None:
        super().start(t)
        self.rotation.reset(t)

    def update(self, t: float) -> None:
        self.rotation.update(t)
        super().update(t)

    @property
    def run_complete(self) -> bool:
        if self.index < 2:
            return False
        lowest = min(float(self.ctx.data.xpos[b][2]) for b in self.entry_bodies)
        return lowest < -self.params["platform_height"]

    @classmethod
    def assess(cls, trajectory):
        return dive_assess(trajectory)


CALIBRATION_PLATFORM = Dive.schema.by_name["platform_height"].default   # m: 10, FINA's highest, Wooten's dives;
                                                                        # calibrate dive runs its dives from it


def flight_time(platform_height: float, rise: float, reach: float) -> float:
    """Seconds from the take-off to the hands reaching the water: up ``rise`` m, then down the
    platform's height and the rise less the hands' ``reach`` below the COM (ballistics)."""
    drop = platform_height + rise - reach
    return math.sqrt(2 * rise / GRAVITY) + math.sqrt(2 * max(drop, 0.0) / GRAVITY)


def entry_reach(character) -> float:
    """How far (m) the hands reach below the COM in the line: a share of the standing COM height."""
    return CONSTANTS.entry_reach * float(character.bodies[0]["com"][2])


def rotation_per_momentum(flight: float, position_inertia: float, line_inertia: float) -> float:
    """Somersault angle (rad) per unit of take-off angular momentum (kg m^2/s) in a flight of
    ``flight`` s: in the position (``position_inertia``) for the flight less the take-off and
    opening, in the line for the rest."""
    straight = min(flight, CONSTANTS.open_time + CONSTANTS.position_move)
    return (flight - straight) / position_inertia + straight / line_inertia


class _Aerial(Tumble):
    """The tumble step of a dive: straight until the feet are clear of the platform (a pike or
    tuck swings the legs towards it), then its position; the twist throw and stop by the twist
    count measured so far."""

    def __init__(self, params, ctx, rotation, dive: Dive):
        super().__init__(params, ctx, rotation)
        self.dive = dive
        m = ctx.model
        ground = m.geom("ground").id
        # the side of the platform the water is on: -1 (-X, standing backwards) or +1 (facing it)
        self.water_side = 1.0 if group_name(dive.params) in FACING_THE_WATER else -1.0
        self.edge = float(m.geom_pos[ground][0] + self.water_side * m.geom_size[ground][0])
        self.feet = [ctx.actor.body_id(n) for n in ("FOOTR", "FOOTL", "TOER", "TOEL")]
        self.clear = self.params["position"] in (0, 3)       # definition: the layout and line codes
        self.moves = twist_moves(dive.twist_target / (2 * math.pi)) if dive.twist_target else []
        self.moves_made = 0                 # of self.moves
        self.radius = position_radius(m, ctx.character, position_name(self.params["position"]), ctx.actor)

    def start(self, t: float) -> None:
        self.ctx.step_division = CONSTANTS.flight_step_division
        if self.clear:
            super().start(t)
            return
        s = self.ctx.servos                 # keep the lift-off shape until clear
        s.offset[:] = 0.0
        s.set_gains(np.arange(len(s.names)), s.default_kp, s.default_kv)
        s.move_to(np.arange(len(s.names)), s.angles().copy(), CONSTANTS.hold_move, t)

    def _clear_of_platform(self) -> bool:
        """The body can turn in its position without touching the platform: the COM is higher
        above the platform, or farther past its edge, than the position's reach; or the feet are
        already past the edge."""
        d = self.ctx.data
        com = d.subtree_com[self.ctx.actor.root]
        past = self.water_side * (com[0] - self.edge)           # how far the COM is out over the water
        if com[2] - self.radius > CONSTANTS.platform_margin or past - self.radius > CONSTANTS.platform_margin:
            return True
        return min(self.water_side * (float(d.xpos[b][0]) - self.edge) for b in self.feet) > CONSTANTS.feet_clearance

    def update(self, t: float) -> None:
        super().update(t)
        if not self.clear and self._clear_of_platform():
            self.clear = True
            super().start(t)
        dive = self.dive
        if not dive.twist_target or self.params["position"] != 3:    # definition: 3 is the line
            return
        if self.moves_made == len(self.moves):
            return
        rate = abs(float(self.ctx.data.qvel[self.ctx.actor.root_dof + 5]))   # definition: the free joint's spin dof
        turns = (abs(self.rotation.twist) + rate * CONSTANTS.twist_stop_lead) / (2 * math.pi)
        at, move = self.moves[self.moves_made]
        if turns >= at:
            if move == "back":
                self.stop_twist(t)
            else:
                self.throw_twist(t, mirrored=move == "mirrored throw")
            self.moves_made += 1


def twist_moves(twists: float) -> list[tuple[float, str]]:
    """The arm moves of a twist, each made once the twist count (with the measured rate's lead)
    reaches its turn: the throw at once and the arms back at the end; from CONSTANTS.tilt_doubling_twists
    on, also the arms back at the half twist and a second throw half a twist before the end.
    An arm move turns the body about its own front-to-back axis; after half a twist that axis
    points the other way about the angular momentum, so the same move tilts the body the other
    way in the world. Bringing the arms back at the half twist therefore tilts the body further
    instead of undoing the tilt (measured on the woman's back 1 1/2: the tilt rises from ~6 to
    ~15 degrees, the twist rate from ~8 to 10-12 rad/s). The second throw takes one tilt's worth
    away and the arms back at the end the other: half a twist before a whole number of twists
    that is the same throw, before a whole-and-a-half the mirrored one (the other arm down),
    whose arms-back then comes at a half twist (Frohlich 1979; Yeadon 1993)."""
    if twists < CONSTANTS.tilt_doubling_twists:
        return [(0.0, "throw"), (twists, "back")]
    whole = abs(twists - round(twists)) < 1e-6
    return [(0.0, "throw"), (0.5, "back"), (twists - 0.5, "throw" if whole else "mirrored throw"), (twists, "back")]


def takeoff_index(contact: np.ndarray, clear_frames: int) -> int | None:
    """First frame of the first run of at least ``clear_frames`` frames without contact, after
    a contact (a single frame without contact during the push is not a take-off)."""
    touched = np.nonzero(contact)[0]
    if len(touched) == 0:
        return None
    k = int(touched[0])
    while k < len(contact):
        if not contact[k] and not contact[k:k + clear_frames].any():
            return k
        k += 1
    return None


def dive_assess(trajectory) -> tuple[str, dict]:
    """Somersaults and twists measured between take-off and entry, the body's angle from the
    vertical at entry, angular momentum drift in flight, platform clearance."""
    a = trajectory.arrays
    meta = trajectory.meta
    names = list(a["body_names"])
    pelvis, head = names.index("PELVIS"), names.index("HEAD")
    feet = [names.index("FOOTR"), names.index("FOOTL")]
    on_platform = a["ground_contact"].any(axis=1)
    metrics: dict = {}
    start = takeoff_index(on_platform, int(CONSTANTS.takeoff_clear * meta["control_rate"]))
    end = len(a["time"]) - 1
    if start is None or start >= end:
        return "no_flight", metrics
    later = np.nonzero(on_platform[start:])[0]
    metrics["hit_platform"] = bool(len(later))
    t = a["time"]
    quat = a["body_quat"][:, pelvis]
    # pelvis long axis (local z) in the world: third column of the rotation matrix
    w, x, y, z = quat.T
    axis_x = 2 * (x * z + w * y)
    axis_z = 1 - 2 * (x * x + y * y)
    pitch = np.unwrap(np.arctan2(axis_x, axis_z))
    somersault = float(pitch[end] - pitch[0])          # from the upright start
    twist_rate = a["qvel"][:, 5]
    twist = float(np.sum(twist_rate[start:end]) * (t[1] - t[0]))
    body_axis = a["body_pos"][end, head] - 0.5 * (a["body_pos"][end, feet[0]] + a["body_pos"][end, feet[1]])
    p = meta["params"]
    ends_head_first = abs(p["somersaults"] % 1.0 - 0.5) < 1e-6        # x.5 somersaults end head down
    wanted = -1.0 if ends_head_first else 1.0
    entry_angle = math.degrees(math.acos(np.clip(wanted * body_axis[2] / np.linalg.norm(body_axis), -1.0, 1.0)))
    momentum = a["angmom"][start:end + 1]
    drift = float(np.abs(momentum - momentum[0]).max() / max(np.linalg.norm(momentum[0]), 1e-9))
    metrics.update({
        "dive": dive_name(p), "takeoff_time": float(t[start]), "entry_time": float(t[end]),
        "flight_time": float(t[end] - t[start]),
        "somersaults": abs(somersault) / (2 * math.pi), "somersault_direction": "forward" if somersault > 0 else "backward",
        "twists": abs(twist) / (2 * math.pi), "entry_angle_from_vertical_deg": entry_angle,
        "head_first": bool(body_axis[2] < 0), "takeoff_angular_momentum": float(momentum[0, 1]),
        "angular_momentum_drift": drift, "entered_water": bool(meta.get("ended_early", False)),
        "takeoff_twist_rate": float(twist_rate[start]),
    })
    wanted_direction = "forward" if group_name(p) in FORWARD_ROTATING else "backward"
    if not metrics["entered_water"]:
        return "no_entry", metrics
    if metrics["hit_platform"]:
        return "hit_platform", metrics
    if (abs(metrics["somersaults"] - p["somersaults"]) > ROTATION_TOLERANCE
            or abs(metrics["twists"] - p["twists"]) > ROTATION_TOLERANCE
            or metrics["somersault_direction"] != wanted_direction):
        return "wrong_rotation", metrics
    if entry_angle > 20.0:           # criterion: the dive's judging, a vertical entry is within 20 deg
        return "entry_not_vertical", metrics
    return "success", metrics
