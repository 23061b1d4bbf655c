"""Running (Hodgins et al. 1995, "Running"; Hodgins & Pollard 1997 §3.2).

A per-leg state machine (Fig. 3): the *active* leg is the one on the ground or being placed for
touchdown, the *idle* leg the other; they swap roles at lift-off. The active leg goes

    flight -> loading -> heel -> heel+toe -> toe -> unloading -> (lift-off: swap)

with transitions on contact (heel, ball of the foot) and, for the thrust, on the time since
touchdown reaching a fraction of the expected stance duration (30-50 %).

Control laws, each from the paper:
  * foot placement at touchdown, eqs. 1-2: hip-to-heel distance on the ground
    x_hh = 1/2 (t_s xdot - cos(theta) l_f) + k (xdot - xdot_d), likewise y; the leg length at
    touchdown is fixed, which gives z_hh; leg inverse kinematics gives hip and knee targets;
  * ground-speed matching: during flight the hip swings the leg further forward and brings it
    back just before touchdown, so that the foot meets the ground moving backwards;
  * stance: the knee is a spring (low gain, target = its touchdown angle); the ankle gives the
    thrust (ankle and knee extend in the toe state); the stance hip servos the body's roll,
    pitch (slightly forward) and yaw;
  * the idle leg is shortened and its hip mirrors the active hip (eqs. 3-4);
  * the shoulders swing against the opposite hip (eq. 5), elbows cycling with them;
  * every joint is a PD servo (eq. 6) whose target moves smoothly (the laws are continuous in
    the measured state, and targets that change at a state switch are blended along Hermite
    curves).

Steering: a facing direction, or a path followed by pure pursuit (running_path); the body leans
into the turn (desired roll from the turn rate). The run starts from the standing pose: the
body leans forward over the feet, the left leg pushes off and the state machine takes over
while the commanded speed ramps up.

Tuned values are data: the five parameters of Hodgins & Pollard §4.3.1 and the other scheduled
settings per speed in ``sim_core/tuned/tables/running_<character>.json`` (written by
``python -m sim_core calibrate running``), the constants of the laws in ``running_any.json`` (docs/tables.md).
"""
from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np

from ...ballistics import GRAVITY, time_to_fall_to
from ...errors import ParameterError
from ...character.model import Placement
from ...character.spec import load_character
from ...control.behaviour import Behaviour, ControlContext, register
from .leg import RunnerLeg
from ...character.morph import lerp
from .morph import RAMPED, MorphTable, leg_between, morph_ramps, morph_speed_metrics
from ...control.path import (MAX_POINTS, PathFollower, circle_path, figure_eight_path, tightest_radius, turn_path,
                             validate_path)
from ...control.servo import hermite_scalar
from ...schema import Choice, Parameter, Points, Schema
from ...tuned import TableType, characters_of, load, register as register_table, require_calibrated
from ...tuned.constants import constant
from ...tuned.settings import SkillSchema, with_defaults
from ...tuned.store import check_rows

TUNED_NAMES = ("ground_speed_matching", "stance_pitch", "thrust_time", "ankle_extension", "knee_extension")
TABLE_NAMES = TUNED_NAMES + ("speed_gain", "touchdown_leg", "idle_knee")
# settings of the stance and swing laws that the table also schedules over the speed (the searches of
# python -m sim_core calibrate running set them per row): name: (unit, low, high, help); the range is the search's and a row's
SCHEDULED = {
    "thrust_damping": ("1", 0.3, 1.0, "share of the knee's and ankle's default damping during the thrust"),
    "unloading_after": ("1", 0.25, 0.7, "share of the expected stance after the thrust start when the leg unloads"),
    "place_back": ("m", 0.05, 0.3, "the foot lands this much closer to the hip than eq. 1 says"),
    "swing_fold": ("1", 0.0, 2.0, "knee flexion per radian the swinging thigh lags its touchdown angle"),
    "yaw_first": ("1", 0.0, 1.0, "share of the roll torque given up to keep the hip's rotation axis in range"),
    "yaw_gain": ("1", 0.5, 1.5, "scale of the stance hip's yaw servo gains"),
    "twist_damping": ("N m s/rad", 0.0, 30.0, "the stance hip's rotation damped about its own rate (the foot's pivot)"),
    "yaw_twist": ("rad", 0.0, 0.3, "the stance hip's yaw goal turned this much with the stride's pelvis rotation (its hip forward)"),
    "arm_yaw": ("1", -5.0, 5.0, "the arms turned about the trunk (one forward, one back) per radian of the pelvis's yaw error: they take the yaw off the stance hip"),
    "thrust_gain": ("1", 1.0, 4.0, "the knee's and ankle's position gain in the thrust, as a multiple of the default"),
    "toe_push": ("rad", 0.0, 0.7, "the toe joint's plantarflexion target in the thrust (0 = held flat)"),
}
SCHEDULED_CONSTANTS = {name: (low, high) for name, (_, low, high, _) in SCHEDULED.items()}   # the search's space

# states of the active leg (Hodgins 1995 Fig. 3)
FLIGHT, LOADING, HEEL, HEEL_TOE, TOE, UNLOADING, START = range(7)
COURSES = ("straight", "turn", "figure_eight", "circle")     # built-in paths, by the course codes 0-3 (path_for)
STATE_NAMES = ("flight", "loading", "heel", "heel_toe", "toe", "unloading", "start")

TUNED = -1.0                # the value of a tuned parameter that means "as tuned for the running speed"


MORPH_TARGETS = ("none", "woman")   # criterion: the characters of the man's skeleton with a running table
MORPH_FROM = ("man",)               # criterion: the runners measured morphing (docs/bodies.md, the morph)
MORPH_SPEEDS = (2.5, 3.5)           # criterion: m/s, the speeds measured morphing without a fall (docs/bodies.md, the
                                    # morph: 2.5-3.5 m/s; with the woman's 4.0 m/s row, a morph at 4.0 m/s fell at 9.8 s)

START_LEAN = Parameter("start_lean", "s", 0.35, 0.1, 1.0, "time the standing body leans forward before the first push-off")


def offered_speeds(character: str) -> list[float]:
    """The rows of a runner's table at speeds it is offered (not inside a refused range)."""
    table = SpeedTable.load(character)
    return [v for v in table.speeds if table.offers(v)]


class SpeedTable:
    """Tuned values of some parameters as functions of the running speed (piecewise linear,
    held constant beyond the ends): Hodgins et al. tune the thrust timing "30-50 % depending on
    forward speed"; this is where such schedules live, as data. ``refused``: speed ranges inside the
    table that a run is refused (open intervals (low, high), the table's ``refused_speeds``: where
    100 s runs from a stand fell with every row measured between, docs/running.md), next to the rows
    they qualify; ``steering``: the fastest speed and the largest lateral acceleration (v^2 / r) up to
    which the runner was measured to turn (the table's ``steering``; None: it runs straight ahead only);
    ``start_lean``: the longest lean into the start measured to start it (the table's ``start_lean``
    ``max``; None: the schema's range)."""

    def __init__(self, speeds: list[float], values: dict[str, list[float] | float], constants: dict | None = None,
                 refused=None, steering: dict | None = None, start_lean: dict | None = None):
        self.speeds = [float(v) for v in speeds]
        self.values = {k: ([float(x) for x in v] if isinstance(v, (list, tuple)) else [float(v)] * len(self.speeds))
                       for k, v in values.items()}
        # the character's own values of constants of the laws (running_any's are the man's), e.g. the
        # woman's gains mass-scaled from the man's by Fig. 6 (docs/running.md, "The woman")
        self.constants = {k: float(v) for k, v in (constants or {}).items()}
        self.refused = [(float(low), float(high)) for low, high in _refused_ranges(refused, self.speeds)]
        self.steering = _steering_limits(steering)
        self.start_lean = _start_lean_limit(start_lean)

    @classmethod
    def load(cls, character: str = "man") -> "SpeedTable":
        """The character's running table (the man's if the character has none), its columns
        completed from the design values of running_any (which is the table when neither exists);
        the constants and the steering limits of the character's own table, if it has some."""
        fallback = load("running", "any")
        for name in (character, "man"):
            data = load("running", name)
            if data is not None:
                return cls(data.get("speeds", fallback["speeds"]), {**fallback["parameters"], **data.get("parameters", {})},
                           data.get("constants") if name == character else None, data.get("refused_speeds"),
                           data.get("steering") if name == character else None,
                           data.get("start_lean") if name == character else None)
        return cls(fallback["speeds"], fallback["parameters"])

    @classmethod
    def from_table(cls, table: dict) -> "SpeedTable":
        """A table as ``to_table`` gives it (a run's ``table`` parameter)."""
        return cls(table["speeds"], table["parameters"], table.get("constants"), table.get("refused_speeds"),
                   table.get("steering"), table.get("start_lean"))

    def to_table(self) -> dict:
        """The table's speeds and columns (and its constants, if any) as a running table stores them
        (and a tuner passes a candidate to a run: the ``table`` parameter), with its refused speed ranges
        and steering limits."""
        table = {"speeds": list(self.speeds), **self.limits_entry(),
                 "parameters": {n: list(v) for n, v in self.values.items()}}
        if self.constants:
            table["constants"] = dict(self.constants)
        return table

    def limits_entry(self) -> dict:
        """The table file's ``refused_speeds``, ``steering`` and ``start_lean`` entries (those it has): what
        a writer of the table carries."""
        return {**({"refused_speeds": [[low, high] for low, high in self.refused]} if self.refused else {}),
                **({"steering": dict(self.steering)} if self.steering else {}),
                **({"start_lean": dict(self.start_lean)} if self.start_lean else {})}

    def offered(self) -> list[tuple[float, float]]:
        """The speed ranges a run is offered: the table's, less its refused ranges."""
        ranges = [(self.speeds[0], self.speeds[-1])]
        for low, high in self.refused:
            ranges = [part for a, b in ranges for part in ((a, min(b, low)), (max(a, high), b)) if part[0] <= part[1]]
        return ranges

    def offers(self, speed: float) -> bool:
        return any(low <= speed <= high for low, high in self.offered())

    def with_row(self, speed: float, row: dict[str, float]) -> "SpeedTable":
        """A copy with the values of ``row`` at ``speed`` (a new row if the speed is new; the
        other parameters of a new row interpolated from the table)."""
        speeds = sorted(set(self.speeds) | {float(speed)})

        def value(n: str, v: float) -> float:
            if abs(v - speed) < 1e-9 and n in row:
                return row[n]
            if v in self.speeds:                   # a stored row's value as it is (interpolating at a
                return self.values[n][self.speeds.index(v)]     # knot could change it in the last bit)
            return self.at(n, v)
        return SpeedTable(speeds, {n: [value(n, v) for v in speeds] for n in self.values}, self.constants, self.refused,
                          self.steering, self.start_lean)

    def at(self, name: str, speed: float) -> float:
        """A column's value at the speed: piecewise linear between the rows, held beyond the ends."""
        xs, ys = self.speeds, self.values[name]
        if speed <= xs[0]:
            return ys[0]
        for k in range(1, len(xs)):
            if speed <= xs[k]:
                f = (speed - xs[k - 1]) / (xs[k] - xs[k - 1])
                return ys[k - 1] + f * (ys[k] - ys[k - 1])
        return ys[-1]


def _steering_limits(steering) -> dict | None:
    """A table's ``steering`` checked: ``max_speed`` (m/s) and ``max_lateral_acceleration`` (m/s^2),
    both positive (and a ``note`` saying where they were measured)."""
    if steering is None:
        return None
    ok = isinstance(steering, dict) and all(
        isinstance(steering.get(k), (int, float)) and math.isfinite(steering[k]) and steering[k] > 0
        for k in ("max_speed", "max_lateral_acceleration"))
    if not ok:
        raise ParameterError(f"steering={str(steering)[:60]} must give max_speed (m/s) and max_lateral_acceleration "
                             f"(m/s^2), both > 0")
    return dict(steering)


def _start_lean_limit(start_lean) -> dict | None:
    """A table's ``start_lean`` checked: ``max`` (s) inside the schema's start_lean range (and a ``note``
    saying where it was measured)."""
    if start_lean is None:
        return None
    low, high = START_LEAN.minimum, START_LEAN.maximum
    value = start_lean.get("max") if isinstance(start_lean, dict) else None
    if not (isinstance(value, (int, float)) and low <= value <= high):
        raise ParameterError(f"start_lean={str(start_lean)[:60]} must give max (s) within [{low:g}, {high:g}]")
    return dict(start_lean)


def _refused_ranges(refused, speeds: list[float]) -> list:
    """A table's ``refused_speeds`` checked: a list of [low, high] pairs, low < high, inside the table's speeds."""
    if refused is None:
        return []
    ok = bool(speeds) and isinstance(refused, (list, tuple)) and all(
        isinstance(r, (list, tuple)) and len(r) == 2 and all(isinstance(x, (int, float)) and math.isfinite(x) for x in r)
        and speeds[0] <= r[0] < r[1] <= speeds[-1] for r in refused)
    if not ok:
        raise ParameterError(f"refused_speeds={str(refused)[:60]} must be a list of [low, high] speed ranges (m/s), "
                             f"low < high, inside the table's speeds"
                             + (f" [{speeds[0]:g}, {speeds[-1]:g}]" if speeds else ""))
    return list(refused)


def _tuned_parameter(name, unit, minimum, maximum, help_text) -> Parameter:
    return Parameter(name, unit, TUNED, minimum, maximum, f"{help_text}; -1 = the tuned value for the speed",
                     special=TUNED)


SETTING_RANGES = Schema(
    _tuned_parameter("ground_speed_matching", "m", 0.0, 0.3,
                     "tuned: how much further forward the foot swings during flight before it is brought back to touchdown"),
    _tuned_parameter("stance_pitch", "rad", -0.1, 0.4, "tuned: forward pitch of the pelvis the stance hip holds"),
    _tuned_parameter("thrust_time", "1", 0.2, 0.7,
                     "tuned: share of the expected stance time after which the ankle thrusts (toe state)"),
    _tuned_parameter("ankle_extension", "rad", 0.0, 0.87, "tuned: ankle plantarflexion the stance ankle extends to in thrust"),
    _tuned_parameter("knee_extension", "rad", 0.0, 0.8, "tuned: knee angle the stance knee extends to in thrust"),
    _tuned_parameter("speed_gain", "s", 0.0, 0.3, "k of eqs. 1-2: extra forward placement of the foot per m/s of speed error"),
    _tuned_parameter("touchdown_leg", "m", 0.34, 0.95, "hip-to-heel distance at touchdown (fixes z_hh of eqs. 1-2)"),
    _tuned_parameter("idle_knee", "rad", 0.5, 2.4, "knee flexion of the idle (shortened) leg"),
    *(_tuned_parameter(name, unit, low, high, help_text) for name, (unit, low, high, help_text) in SCHEDULED.items()),
    constant("contact_height", "m", 0.0, 0.05, "a foot contact sphere this close to the ground touches it"),
    constant("flying_start_speed", "m/s", 0.0, 10.0, "a run that starts moving faster than this starts in flight"),
    constant("flying_start_stance", "s", 0.0, 5.0, "expected stance time of its first step"),
    constant("min_flight", "s", 0.0, 0.2, "a touchdown of the new active leg is not taken before this"),
    constant("loading_time", "s", 0.0, 0.1, "contact held this long before the stance laws take over"),
    constant("swap_blend", "s", 0.0, 1.0, "Hermite blend of the new active leg's targets after lift-off"),
    constant("flight_hip_gain", "share", 0.0, 20.0, "share of the default gains of the swinging (flight) hip's servos"),
    constant("idle_hip_gain", "share", 0.0, 20.0, "share of the default gains of the idle hip's servos"),
    constant("idle_knee_gain", "share", 0.0, 10.0, "share of the default gains of the idle knee's servo"),
    constant("stance_hip_share", "1", 0.0, 1.0, "stance hip servos are torque-commanded: low kp so 5 ms holds drift little"),
    constant("stance_knee_gain", "share", 0.0, 10.0, "share of the knee's default kp in stance (the knee is a spring)"),
    constant("heel_ankle_gain", "1", 0.0, 5.0, "heel contact: a soft ankle lets the foot come down flat"),
    constant("pitch_kp", "N m/rad", 0.0, 20000.0, "body pitch servo of the stance hip"),
    constant("pitch_kd", "N m s/rad", 0.0, 2000.0, "body pitch servo of the stance hip"),
    constant("roll_kp", "N m/rad", 0.0, 50000.0, "body roll servo of the stance hip"),
    constant("roll_kd", "N m s/rad", 0.0, 5000.0, "body roll servo of the stance hip"),
    constant("yaw_kp", "N m/rad", 0.0, 20000.0, "body yaw servo of the stance hip"),
    constant("yaw_kd", "N m s/rad", 0.0, 2000.0, "body yaw servo of the stance hip"),
    constant("attitude_onset", "s", 0.0, 0.2, "the attitude torque fades in after touchdown, out in unloading"),
    constant("unload_knee", "rad", 0.0, 3.14, "knee flexion the unloading leg folds to (0 = it does not)"),
    constant("unload_ramp", "s", 0.0, 1.0, "the unloading knee moves to unload_knee over this time"),
    constant("thrust_ramp", "s", 0.0, 0.5, "the thrust targets move in over this time"),
    constant("touchdown_toe_up", "rad", 0.0, 2.0, "foot pitched toe-up at touchdown, heel first"),
    constant("foot_inward", "m", 0.0, 0.05, "the foot lands this far inside the hip, toward the centre line"),
    constant("speed_trim_gain", "s", 0.0, 0.2, "m of placement trim per m/s of speed error, per step"),
    constant("speed_trim_max", "m", 0.0, 2.0, "the placement trim is at most this"),
    constant("place_back_speed", "m/s", 0.0, 50.0, "above which the full place_back applies"),
    constant("drift_filter", "1/s", 0.0, 20.0, "low-pass of the sideways speed (about a stride)"),
    constant("turn_place_gain", "m", 0.0, 10.0, "outward placement per g of centripetal acceleration"),
    constant("lateral_gain", "s", 0.0, 1.0, "extra sideways placement per m/s of sideways speed error"),
    constant("placement_limit", "1", 0.0, 10.0, "the hip-to-heel distance on the ground is at most this share of the leg"),
    constant("hip_yaw_limit", "rad", 0.0, 3.14, "the stance hip's yaw goal is at most this"),
    constant("hip_yaw_headroom", "1", 0.0, 10.0, "share of the rotation axis's torque limit the roll is reduced to keep within"),
    constant("accel_margin", "m/s", 0.0, 5.0, "the speed command is at most this above the current speed"),
    constant("swing_yields", "1", 0.0, 1.0, "while accelerating (the speed command below the request), the idle hip's pitch "
             "torque in a stance is held within this share of what the stance hip's torque limit leaves after the "
             "attitude (0: off; 1: the attitude has priority over the swing)"),
    constant("table_lead", "1", 0.0, 10.0, "the table is looked up this share of the way from the current speed to the ramped command"),
    constant("turn_rate_per_speed", "1/m", 0.0, 5.0, "rad/s of heading change per m/s of speed"),
    constant("heading_gain", "1/s", 0.0, 20.0, "heading rate per radian of heading error"),
    constant("turn_accel", "rad/s^2", 0.0, 10.0, "the heading rate changes at most this fast"),
    constant("yaw_error_limit", "rad", 0.0, 3.14, "yaw error the stance hip acts on (limits the yaw change asked of one stance)"),
    constant("turn_lean", "1", 0.0, 1.0, "share of the lean parameter's lean this body takes (the woman: 0, she runs upright: docs/running.md, the woman)"),
    constant("roll_filter", "1", 0.0, 0.5, "share per control tick by which the turn rate and roll goal follow their targets (low-pass)"),
    constant("start_ankle_lean", "rad", 0.0, 2.0, "ankle dorsiflexion while leaning into the start"),
    constant("start_knee", "rad", 0.0, 2.0, "knee flexion while leaning"),
    constant("start_pitch", "rad", 0.0, 1.0, "pelvis pitch the hips hold while leaning"),
    constant("start_speed", "m/s", 0.0, 10.0, "forward COM speed at which the lean turns into the first push-off"),
    constant("start_timeout", "s", 0.0, 10.0, "after the lean, the push-off starts at the latest this long whatever the speed"),
    constant("start_stance", "s", 0.0, 5.0, "expected duration of the first (push-off) stance"),
    constant("start_hip_damping", "1", 0.0, 1.0, "share of the hip's own damping the lean's pitch servo keeps (0: a pure torque on the pelvis)"),
    constant("swing_fold_max", "rad", 0.0, 3.14, "at most this much extra knee flexion of a lagging swing"),
    constant("gsm_retract", "s", 0.0, 1.0, "the swung-forward foot is brought back over this time before the predicted touchdown"),
    constant("idle_forward_thigh", "rad", -3.14, 0.0, "forward angle (from vertical) the idle thigh reaches by the end of stance"),
    constant("idle_unfold", "1", 0.0, 10.0, "share of the expected stance over which the idle knee unfolds after thrust"),
    constant("idle_unfold_knee", "rad", 0.0, 3.14, "idle knee flexion at the end of the unfolding"),
    constant("idle_ankle", "rad", -2.0, 0.0, "the idle ankle's target"),
    constant("idle_knee_min", "rad", 0.0, 3.14, "idle knee flexion of a slow (starting) runner"),
    constant("idle_knee_per_speed", "s/m", 0.0, 5.0, "rad of idle knee flexion per m/s: the idle knee folds more the faster the run"),
    constant("idle_pitch_gain", "1", 0.0, 50.0, "idle hip extension per radian of trunk pitch error, in flight"),
    constant("idle_pitch_damp", "s", 0.0, 5.0, "idle hip extension per rad/s of trunk pitch rate, in flight"),
    constant("idle_abduction", "rad", 0.0, 2.0, "the idle hip abducts at most this much"),
    constant("idle_adduction", "rad", -1.0, 0.0, "the idle hip adducts at least this much (negative: abduction)"),
    constant("ff_max", "rad/s", 0.0, 200.0, "cap on a target's rate used as feed-forward"),
    constant("arm_abduction", "rad", 0.0, 2.0, "the arms are held this far out from hanging"),
    constant("arm_offset", "rad", 0.0, 1.0, "gamma_0 of eq. 5: the arms swing about this forward angle"),
    constant("elbow_base", "rad", 0.0, 3.14, "running elbow flexion"),
    constant("elbow_swing", "1", 0.0, 5.0, "extra elbow flexion per radian of forward arm swing"),
    constant("initial_stance_time", "s", 0.05, 1.0, "the expected stance duration t_s before a stance has been measured"),
    constant("initial_flight_time", "s", 0.0, 1.0, "the expected flight duration before a flight has been measured"),
    constant("initial_touchdown_knee", "rad", 0.0, 2.0, "the knee angle at touchdown assumed before the first touchdown"),
    constant("stance_time_min", "s", 0.01, 1.0, "the expected stance duration (the last stance's, averaged) is at least this"),
    constant("stance_time_max", "s", 0.05, 2.0, "the expected stance duration is at most this"),
    constant("flight_toe_gain", "share", 0.0, 10.0, "share of the default gains of the active leg's toe servos in flight"),
    constant("idle_ankle_gain", "share", 0.0, 10.0, "share of the default gains of the idle leg's ankle servos (pitch and roll)"),
    constant("idle_toe_gain", "share", 0.0, 10.0, "share of the default gains of the idle leg's toe servos"),
    constant("start_idle_knee_gain", "share", 0.0, 10.0, "share of the default gains of the idle knee's servo at the first push-off"),
    constant("idle_hip_flexion_max", "rad", 0.0, 3.0, "the idle hip's target flexes at most this much"),
    constant("idle_hip_extension_max", "rad", 0.0, 2.0, "the idle hip's target extends at most this much"),
)


def _running_rows(body: dict):
    speeds = body.get("speeds", [])
    _refused_ranges(body.get("refused_speeds"), speeds)      # checked with the rows: on load, save and as a run's table
    _steering_limits(body.get("steering"))
    _start_lean_limit(body.get("start_lean"))
    columns = body.get("parameters", {})
    for k, speed in enumerate(speeds):
        yield f"row {speed:g} m/s", {n: (v[k] if isinstance(v, list) else v) for n, v in columns.items()}
    if "constants" in body:
        yield "constants", body["constants"]


RUNNING_TABLE = register_table(TableType("running", SETTING_RANGES, _running_rows, (SpeedTable.at,)))
RUNNING_SETTINGS = with_defaults(SETTING_RANGES, load("running", "any")["constants"])
CONSTANT_NAMES = tuple(load("running", "any")["constants"])


class RunningSchema(SkillSchema):
    """The schema's parameters, plus ``table``: a running table's speeds and columns to run with
    instead of the stored one (a tuner's candidate, SpeedTable.to_table), checked like a stored
    table's rows; and ``morph_ramps``: the five tuned parameters' offsets at the morph's end (a
    tuner's candidate), each within plus or minus its range's width."""

    def validate(self, values: dict, defaults: dict | None = None) -> dict:
        values = dict(values)
        table = values.pop("table", None)
        ramps = values.pop("morph_ramps", None)
        result = super().validate(values, defaults)
        if table is not None:
            if not (isinstance(table, dict) and isinstance(table.get("speeds"), list)
                    and isinstance(table.get("parameters"), dict)):
                raise ParameterError(f"table={str(table)[:60]!r} is not a running table: an object with 'speeds' (a "
                                     f"list) and 'parameters' (an object of columns), as SpeedTable.to_table gives; it "
                                     f"is a tuner's parameter (scripts pass it, not --set)")
            check_rows("the table parameter", "running", table)
            result["table"] = table
        if ramps is not None:
            result["morph_ramps"] = check_ramps(ramps)
        return result


def check_ramps(ramps: dict) -> dict[str, float]:
    """A morph's ramp offsets: names among the five, finite, within their ranges' widths."""
    if not isinstance(ramps, dict):
        raise ParameterError(f"morph_ramps={str(ramps)[:60]!r} must be an object of parameter offsets, e.g. "
                             f"{{\"{RAMPED[0]}\": 0.01}}; allowed names: {', '.join(RAMPED)}")
    out = {}
    for name, value in ramps.items():
        if name not in RAMPED:
            raise ParameterError(f"morph_ramps: unknown parameter {name!r}; allowed: {', '.join(RAMPED)}")
        setting = SETTING_RANGES.by_name[name]
        width = setting.maximum - setting.minimum
        if not (isinstance(value, (int, float)) and math.isfinite(value) and abs(value) <= width):
            raise ParameterError(f"morph_ramps: {name}={value!r} is out of range; allowed range is "
                                 f"[{-width:g}, {width:g}] {setting.unit}")
        out[name] = float(value)
    return out


@register
class Running(Behaviour):
    name = "running"
    summary = ("Run from a stand at the speeds of the runner's table (the man's: 2.5-3.7 and 4.05-4.5 m/s), facing a direction or "
               "along a path (Hodgins et al. 1995).")
    default_duration = 20.0
    control_rate = 200.0
    settings_schema = RUNNING_SETTINGS
    schema = RunningSchema(
        Parameter("speed", "m/s", 3.5, 2.5, 5.0, "desired running speed on the ground plane; each runner runs at the "
                  "speeds of its table only (the man 2.5-4.5 m/s, the woman 2.5-4, the child 2.5-3; docs/running.md)"),
        Parameter("facing", "rad", 0.0, -math.pi, math.pi,
                  "direction to run in (0 = +X, counter-clockwise) when no path or course is given: the runner starts "
                  "straight ahead and turns to it after turn_after m on turn_radius"),
        Choice("course", COURSES, "straight",
               "built-in path when no path is given: straight along facing, a turn by turn_angle, a figure eight, a circle"),
        Parameter("turn_angle", "rad", math.pi / 2, -math.pi, math.pi, "course 1: angle of the turn (left positive)"),
        Parameter("turn_radius", "m", 20.0, 1.5, 50.0,
                  "course 1-3 and facing: radius of the turn, of each loop of the eight, of the circle (v^2 / r "
                  "at most 0.625 m/s^2 up to 3.5 m/s for the man, 0.4 up to 3.35 m/s for the woman, 0.9 for the child; "
                  "docs/running.md)"),
        Parameter("turn_after", "m", 15.0, 2.0, 200.0, "course 1-3: distance run straight before the turn or the loops"),
        Parameter("lean", "1", 1.0, 0.0, 1.5, "share of the lean into a turn that balances the centripetal force (atan(v^2 / (g r)))"),
        Points("path", "the path to run along, [x, y] points in metres from the start (in Blender: a curve "
               "object); given, it replaces the course", clean=lambda points: validate_path(points).tolist(),
               max_points=MAX_POINTS),
        Parameter("lookahead", "m", 2.5, 0.5, 10.0, "path following: distance along the path of the point the runner heads for"),
        Parameter("arm_swing", "1", 0.8, 0.0, 2.0,
                  "k of eq. 5: shoulder swing per radian of the opposite hip's swing"),
        START_LEAN,
        Choice("morph_to", MORPH_TARGETS, "none",
               "the body turns into this character while it runs (Hodgins & Pollard 1997's metamorphosis: lengths, "
               "masses, inertias and servos interpolated every control tick); straight ahead, at speeds both run"),
        Parameter("morph_start", "s", 5.0, 0.0, 100.0,
                  "the morph starts this long into the run (the man reaches 90 % of 3.5 m/s by 4.7 s)"),
        Parameter("morph_time", "s", 20.0, 1.0, 100.0, "the morph takes this long, linearly"),
        settings=RUNNING_SETTINGS,
    )

    @classmethod
    def morph_target(cls, params: dict) -> str | None:
        target = cls.schema.by_name["morph_to"].option(params.get("morph_to", 0.0))
        return None if target == "none" else target

    @classmethod
    def character_defaults(cls, character: str) -> dict:
        """A runner whose table does not cover the schema's speed (the child's 2.5 m/s, the
        imaginary runner's 3 m/s) runs, unless told, at the nearest speed of its table."""
        if load("running", character) is None:
            return {}
        speeds = SpeedTable.load(character).speeds
        speed = cls.schema.by_name["speed"].default
        return {} if speeds[0] <= speed <= speeds[-1] else {"speed": float(min(max(speed, speeds[0]), speeds[-1]))}

    def morph_fraction(self, t: float) -> float:
        p = self.params
        return min(1.0, max(0.0, (t - p["morph_start"]) / p["morph_time"]))

    def check_feasible(self) -> None:
        """A runner needs its own running table, and runs only at the speeds it covers less its refused
        gaps (the man's: 2.5-3.7 and 4.05-4.5 m/s, where 100 s runs from a stand were measured not to fall); a ``table`` parameter (a tuner's or a scaled candidate, checked
        like a stored one) is its own."""
        if "table" not in self.params:
            name = self.ctx.character.name
            require_calibrated("running", name, self.name)
            table = SpeedTable.load(name)
            speed = self.params["speed"]
            ranges = table.offered()
            if not table.offers(speed):
                allowed = " or ".join(f"[{low:g}, {high:g}]" for low, high in ranges)
                raise ParameterError(f"parameter speed={speed:g} m/s is out of range for the {name}; allowed range for "
                                     f"speed is {allowed} m/s (the speeds of the {name}'s running table"
                                     f"{', less those where 100 s runs fell' if len(ranges) > 1 else ''})")
            if table.start_lean is not None and self.params["start_lean"] > table.start_lean["max"]:
                raise ParameterError(f"parameter start_lean={self.params['start_lean']:g} s is out of range for the {name}; "
                                     f"allowed range for start_lean is [{START_LEAN.minimum:g}, {table.start_lean['max']:g}] s "
                                     f"(longer leans were measured to fall in the start: docs/running.md, the start lean)")
            path = path_for(self.params)
            if path is not None and table.steering is not None:
                check_steering(speed, path, self.params["lookahead"], name, table.steering)
            if path is not None and table.steering is None:
                steered = [n for n in characters_of("running") if SpeedTable.load(n).steering is not None]
                raise ParameterError(f"the {name} runs only straight ahead (course=straight, facing=0, no path): turning "
                                     f"is calibrated for the {' and the '.join(steered)} only (docs/running.md, "
                                     f"where steering is offered)")
        target = self.morph_target(self.params)
        if target is not None:
            self._check_morph(target)

    def _check_morph(self, target: str) -> None:
        """A morph runs alone, straight ahead, at a speed both characters' tables cover."""
        if self.ctx.actor.prefix:
            raise ParameterError("morph_to: a morph runs alone (a one-character run), not as an actor of a scene")
        require_calibrated("running", target, self.name)
        name = self.ctx.character.name
        if name not in MORPH_FROM:
            raise ParameterError(f"morph_to: the {name} cannot morph; the morph is measured from the "
                                 f"{', '.join(MORPH_FROM)} only (docs/bodies.md, the morph)")
        if "table" in self.params:
            ends = (self.table.start.speeds, SpeedTable.load(target).speeds)
        else:
            ends = (SpeedTable.load(name).speeds, SpeedTable.load(target).speeds)
        low, high = max(e[0] for e in ends + (MORPH_SPEEDS,)), min(e[-1] for e in ends + (MORPH_SPEEDS,))
        speed = self.params["speed"]
        if not low <= speed <= high:
            raise ParameterError(f"parameter speed={speed:g} m/s is out of range for a morph from the {name} to the "
                                 f"{target}; allowed range for speed is [{low:g}, {high:g}] m/s (the speeds both "
                                 f"running tables cover where a morph was measured)")
        if path_for(self.params) is not None:
            raise ParameterError(f"a morph into the {target} runs only straight ahead (course=straight, facing=0, "
                                 f"no path): the {target} is not calibrated to turn")

    # --------------------------------------------------------------------- setup
    def __init__(self, params, ctx: ControlContext):
        super().__init__(params, ctx)
        m, s, ch = ctx.model, ctx.servos, ctx.character
        self.pelvis = ctx.actor.body_id("PELVIS")
        self.hip_body = [ctx.actor.body_id("ULEGR"), ctx.actor.body_id("ULEGL")]
        self.legs = [RunnerLeg(ch, "R"), RunnerLeg(ch, "L")]
        site = ctx.actor.site_id
        self.heel_sites = [[site(f"FOOT{c}_heel_a"), site(f"FOOT{c}_heel_b")] for c in "RL"]
        self.ball_sites = [[site(f"FOOT{c}_ball_a"), site(f"FOOT{c}_ball_b"), site(f"TOE{c}_toe_a"),
                            site(f"TOE{c}_toe_b")] for c in "RL"]
        self.foot_sites = np.array([i for k in range(2) for i in self.heel_sites[k] + self.ball_sites[k]])
        ix = s.index
        self.j = [dict(hy=ix[f"hip_{c}_y"], hx=ix[f"hip_{c}_x"], hz=ix[f"hip_{c}_z"], knee=ix[f"knee_{c}_y"],
                       ay=ix[f"ankle_{c}_y"], ax=ix[f"ankle_{c}_x"], mt=ix[f"mt_{c}_y"],
                       sx=ix[f"shoulder_{c}_x"], sy=ix[f"shoulder_{c}_y"], sz=ix[f"shoulder_{c}_z"],
                       ez=ix[f"elbow_{c}_z"]) for c in "rl"]
        self.hip_joint_ids = np.array([ctx.actor.joint_id(f"hip_{c}_{ax}") for c in "rl" for ax in "yxz"])
        self.leg_idx = [s.indices([f"hip_{c}_y", f"hip_{c}_x", f"hip_{c}_z", f"knee_{c}_y", f"ankle_{c}_y",
                                   f"ankle_{c}_x", f"mt_{c}_y"]) for c in "rl"]
        self.neck_y = ix["neck_c2_y"]
        self.spine_y = [ix[n] for n in ("spine_l3_y", "spine_l1_y", "spine_t7_y", "spine_t4_y")]
        self.base = ch.standing_pose.copy()
        self.kp0 = s.default_kp.copy()
        self.kv0 = s.default_kv.copy()
        self.ratio = (s.default_kv / s.default_kp).tolist()
        self.torque_limit = m.actuator_forcerange[s.actuators, 1].tolist()
        self.table = (SpeedTable.from_table(params["table"]) if "table" in params else SpeedTable.load(ch.name))
        self.scheduled = [n for n in self.table.values if params.get(n, TUNED) == TUNED]
        defaults = RUNNING_SETTINGS.defaults()
        # a constant is the request's where it differs from running_any's (the man's) value, else the
        # character's table's, else running_any's
        own = self.table.constants
        self.constants = SimpleNamespace(**{n: own[n] if n in own and params.get(n, defaults[n]) == defaults[n]
                                            else params.get(n, defaults[n]) for n in CONSTANT_NAMES})
        share = self.constants.stance_hip_share      # stance hip servos are torque-commanded: low kp
        self.stance_hip_gains = {key: (share, share) for key in ("hy", "hx", "hz")}
        self.p = dict(params)
        if ctx.morph is not None:
            self._prepare_morph(params, defaults)
        self._schedule(0.0)
        placement = ctx.actor.placement
        self.path = self._path()
        # a scene's actor runs in its placed frame: its facing turned by its heading, its path moved
        self.facing = params["facing"] + placement.heading if placement is not None else params["facing"]
        self.follower = PathFollower(self.path, params["lookahead"]) if self.path is not None else None

    def _path(self):
        return path_for(self.params, self.ctx.actor.placement)

    def _prepare_morph(self, params: dict, defaults: dict) -> None:
        """The two ends of the control model (this character's and the target's): tables, the
        constants of the laws, the legs; the ramps' offsets of the five parameters."""
        target = self.morph_target(params)
        end_table = SpeedTable.load(target)
        own = end_table.constants
        self.morph_constants = (vars(self.constants).copy(),
                                {n: own[n] if n in own and params.get(n, defaults[n]) == defaults[n]
                                 else params.get(n, defaults[n]) for n in CONSTANT_NAMES})
        end = load_character(target)
        self.morph_legs = (self.legs, [RunnerLeg(end, "R"), RunnerLeg(end, "L")])
        bounds = {n: (SETTING_RANGES.by_name[n].minimum, SETTING_RANGES.by_name[n].maximum) for n in RAMPED}
        self.table = MorphTable(self.table, end_table, morph_ramps(target, params), bounds)
        self.morph_seen = 0.0

    def _follow_morph(self) -> None:
        """The control model at the body's fraction of the way (called when it has moved on)."""
        f = self.ctx.morph.fraction
        self.morph_seen = f
        self.table.fraction = f
        start, end = self.morph_constants
        self.constants = SimpleNamespace(**{n: lerp(start[n], end[n], f) for n in CONSTANT_NAMES})
        share = self.constants.stance_hip_share
        self.stance_hip_gains = {key: (share, share) for key in ("hy", "hx", "hz")}
        self.legs = [leg_between(a, b, f) for a, b in zip(*self.morph_legs)]
        m, s = self.ctx.model, self.ctx.servos
        s.default_kp = self.ctx.morph.kp[s.actuators].copy()
        s.default_kv = self.ctx.morph.kv[s.actuators].copy()
        self.kp0, self.kv0 = s.default_kp.copy(), s.default_kv.copy()
        self.kp = m.actuator_gainprm[s.actuators, 0].tolist()       # the live gains, rescaled by the morph
        self.kv = (-m.actuator_biasprm[s.actuators, 2]).tolist()

    def _schedule(self, speed: float) -> None:
        """Effective values of the tuned parameters left at -1: the table at this speed."""
        for name in self.scheduled:
            self.p[name] = self.table.at(name, speed)

    @classmethod
    def assess(cls, trajectory) -> tuple[str, dict]:
        """Success = no fall for the whole run (TARGETS.md "Running"); metrics: the standard ones,
        the gait over the last 10 s (sim_core.gait), the time the run took to reach 90 % of the
        commanded speed from the stand, and for a path the lateral deviation from it."""
        from ...analysis import standard_metrics
        from ...gait import gait_metrics, stride_attitude_variation
        from ...control.path import path_deviation
        metrics = standard_metrics(trajectory)
        for key in ("stepped", "max_foot_slide", "com_outside_support_max", "com_inside_support_throughout",
                    "final_com_speed", "max_hand_below_knee"):
            metrics.pop(key, None)                   # standing-skill metrics, meaningless in a run
        a = trajectory.arrays
        params = trajectory.meta["params"]
        gait = gait_metrics(trajectory, until=metrics["fall_time"])
        metrics["gait"] = gait
        speed = np.linalg.norm(a["com_vel"][:, :2], axis=1)
        upright = a["time"] < (metrics["fall_time"] if metrics["fell"] else np.inf)
        reached = np.nonzero((speed >= 0.9 * params["speed"]) & upright)[0]    # definition: the metric's 90 %
        metrics["time_to_90pct_speed"] = float(a["time"][reached[0]]) if len(reached) else None
        metrics["stride_attitude_variation"] = stride_attitude_variation(trajectory, t_from=max(0.0, a["time"][-1] - 10.0))  # definition: the last 10 s
        placement = trajectory.meta.get("placement")
        path = path_for(params, Placement(**placement) if placement else None)
        if path is not None:
            t0 = _first_time_on_path(a, path)
            sel = a["time"] >= t0
            deviation = path_deviation(path, a["com"][sel, :2])
            metrics["path_deviation_mean"] = float(deviation.mean()) if deviation.size else None
            metrics["path_deviation_max"] = float(deviation.max()) if deviation.size else None
        if cls.morph_target(params) is not None:
            metrics.update(morph_speed_metrics(a["time"], speed, params, metrics["fall_time"]))
        return ("fell" if metrics["fell"] else "success"), metrics

    # --------------------------------------------------------------------- start
    def start(self, t: float) -> None:
        c = self.constants
        s = self.ctx.servos
        self.targets = self.base.tolist()
        self.kp = self.kp0.tolist()          # current gains (the torque-commanded servos need them)
        self.kv = self.kv0.tolist()
        self.active = 1                      # the left leg pushes off first
        self.state = START
        self.t_state = t
        self.t_touchdown = t
        self.t_liftoff = t
        self.t_thrust = t
        self.stance_time = c.initial_stance_time     # expected stance duration t_s (the last stance's)
        self.flight_time = c.initial_flight_time
        self.idle_lo = [0.0, 0.0]            # idle hip (y, x) at the last lift-off
        self.active_lo = [0.0, 0.0]          # active hip (y, x) at the last lift-off
        self.blend_from = None
        self.knee_touchdown = c.initial_touchdown_knee
        self.ankle_touchdown = 0.0
        self.ankle_flat = 0.0
        m_ = self.ctx.data.xmat[self.pelvis]
        self.heading_goal = math.atan2(m_[3], m_[0])     # turns from where the body faces, gradually
        self.roll_goal = 0.0
        self.previous_goal = {}
        self.speed_trim = 0.0
        self.lateral_drift = 0.0
        self.turn_rate = 0.0                 # heading rate, low-passed (for the lean and the outward step)
        self.heading_rate = 0.0              # rad/s: rate of the heading goal (smooth: limited acceleration)
        self.idle_bound = 0.0                # N m: the idle hip's pitch torque allowed in this stance (swing_yields)
        d = self.ctx.data
        vx, vy, _ = d.subtree_linvel[self.pelvis].tolist()
        if math.hypot(vx, vy) > c.flying_start_speed:
            # a running start state (RunRequest.start: the body already moving): the right leg
            # is placed for the first touchdown, as after a lift-off of the left
            q = self.ctx.servos.angles().tolist()
            ja, ji = self.j[0], self.j[1]
            self.active = 0
            self.active_lo = [q[ja["hy"]], q[ja["hx"]]]
            self.idle_lo = [q[ji["hy"]], q[ji["hx"]]]
            self.stance_time = c.flying_start_stance
            self._schedule(math.hypot(vx, vy))
            self.event(t, "flying_start")
            self._enter(t, FLIGHT)
            return
        self.event(t, "start")

    # --------------------------------------------------------------------- helpers
    def _set_gains(self, leg: int, scales: dict) -> None:
        """Gains of one leg's servos by joint key (hy, hx, hz, knee, ay, ax, mt) as shares of the
        default (kp, kv); logged for replay."""
        j = self.j[leg]
        idx, kps, kvs = [], [], []
        for key, (kp_share, kv_share) in scales.items():
            i = j[key]
            kp, kv = float(self.kp0[i] * kp_share), float(self.kv0[i] * kv_share)
            if kp == self.kp[i] and kv == self.kv[i]:
                continue
            idx.append(i)
            kps.append(kp)
            kvs.append(kv)
            self.kp[i], self.kv[i] = kp, kv
        if idx:
            self.ctx.servos.set_gains(np.array(idx), np.array(kps), np.array(kvs))

    def _enter(self, t: float, state: int) -> None:
        c = self.constants
        self.state = state
        self.t_state = t
        a = self.active
        self.event(t, f"{STATE_NAMES[state]}_{'R' if a == 0 else 'L'}")
        if state == FLIGHT:
            g, gi, gk = c.flight_hip_gain, c.idle_hip_gain, c.idle_knee_gain
            toe, ankle, idle_toe = c.flight_toe_gain, c.idle_ankle_gain, c.idle_toe_gain
            self._set_gains(a, {"hy": (g, g), "hx": (g, g), "hz": (g, g), "knee": (1.0, 1.0), "ay": (1.0, 1.0),
                                "ax": (1.0, 1.0), "mt": (toe, toe)})
            self._set_gains(1 - a, {"hy": (gi, gi), "hx": (gi, gi), "hz": (gi, gi), "knee": (gk, gk), "ay": (ankle, ankle),
                                    "ax": (ankle, ankle), "mt": (idle_toe, idle_toe)})
        elif state == LOADING:
            self._set_gains(a, self.stance_hip_gains)
        elif state == HEEL:
            self._set_gains(a, {"knee": (c.stance_knee_gain, c.stance_knee_gain), "ay": (c.heel_ankle_gain, c.heel_ankle_gain)})
        elif state == HEEL_TOE:
            self._set_gains(a, {"knee": (c.stance_knee_gain, c.stance_knee_gain), "ay": (1.0, 1.0)})
        elif state == TOE:
            self.t_thrust = t
            damping = self.p["thrust_damping"]       # the servos' damping would eat the push's power
            gain = self.p["thrust_gain"]            # a stiffer push: more vertical impulse, a longer flight
            self._set_gains(a, {"knee": (gain, damping), "ay": (gain, damping)})

    def _liftoff(self, t: float, q: list, targets: list) -> None:
        """The active leg has left the ground: it becomes the idle leg, the other the active one."""
        a, i = self.active, 1 - self.active
        ja, ji = self.j[a], self.j[i]
        c = self.constants
        self.stance_time = min(c.stance_time_max, max(c.stance_time_min, 0.5 * self.stance_time + 0.5 * (t - self.t_touchdown)))
        self.t_liftoff = t
        self.active_lo = [q[ji["hy"]], q[ji["hx"]]]      # the new active leg's hip now
        self.idle_lo = [q[ja["hy"]], q[ja["hx"]]]        # the new idle leg's hip now
        self.blend_from = [targets[ji[k]] for k in BLENDED]
        self.active = i
        self.previous_goal = {}
        self.event(t, "liftoff")
        self._enter(t, FLIGHT)

    # --------------------------------------------------------------------- control
    def update(self, t: float) -> None:
        if self.ctx.morph is not None and self.ctx.morph.fraction != self.morph_seen:
            self._follow_morph()
        c = self.constants
        d = self.ctx.data
        p = self.p
        servos = self.ctx.servos
        q = servos.angles().tolist()
        qd = servos.velocities().tolist()
        force = d.actuator_force[servos.actuators].tolist()
        m = d.xmat[self.pelvis].tolist()
        wx, wy, wz = d.cvel[self.pelvis, :3].tolist()
        cx, cy, _ = d.subtree_com[self.pelvis].tolist()
        vx, vy, vz = d.subtree_linvel[self.pelvis].tolist()
        z = d.site_xpos[self.foot_sites, 2].tolist()
        heel = [min(z[0], z[1]) < c.contact_height, min(z[6], z[7]) < c.contact_height]
        ball = [min(z[2], z[3], z[4], z[5]) < c.contact_height, min(z[8], z[9], z[10], z[11]) < c.contact_height]
        touch = [heel[0] or ball[0], heel[1] or ball[1]]

        yaw = math.atan2(m[3], m[0])
        pitch = math.atan2(-m[6], m[8])
        roll = math.atan2(m[7], m[8])
        pitch_rate = wx * m[1] + wy * m[4] + wz * m[7]
        roll_rate = wx * m[0] + wy * m[3] + wz * m[6]

        # ---- steering: facing direction (or pure pursuit on the path), lean into the turn
        goal = self.follower.heading(cx, cy) if self.follower is not None else self.facing
        speed_now = math.hypot(vx, vy)
        # the heading goal turns toward the goal at a rate proportional to the error, limited in
        # rate and in acceleration, so the yaw the stance hip asks for changes smoothly (an abrupt
        # change of facing direction makes the runner fall: Hodgins et al. 1995, Discussion)
        max_rate = c.turn_rate_per_speed * max(speed_now, 1.0)
        wanted = c.heading_gain * wrap_angle(goal - self.heading_goal)
        wanted = max(-max_rate, min(max_rate, wanted))
        step = c.turn_accel / self.control_rate
        self.heading_rate += max(-step, min(step, wanted - self.heading_rate))
        self.heading_goal = wrap_angle(self.heading_goal + self.heading_rate / self.control_rate)
        self.turn_rate += c.roll_filter * (self.heading_rate - self.turn_rate)
        roll_target = -c.turn_lean * p["lean"] * math.atan(speed_now * self.turn_rate / GRAVITY)
        self.roll_goal += c.roll_filter * (roll_target - self.roll_goal)
        heading = self.heading_goal
        ch, sh = math.cos(heading), math.sin(heading)
        # the speed command ramps up from the stand: the foot is placed to accelerate at most
        # accel_margin above the current speed
        speed_cmd = min(p["speed"], speed_now + c.accel_margin)
        vxd, vyd = speed_cmd * ch, speed_cmd * sh
        self.lateral_drift += c.drift_filter / self.control_rate * ((-sh * vx + ch * vy) - self.lateral_drift)

        targets = self.targets
        a = self.active
        ja = self.j[a]

        # ---- state transitions of the active leg (Fig. 3)
        state = self.state
        if state == START:
            # the lean ends when the body falls forward fast enough to step into the run
            if vx * ch + vy * sh >= c.start_speed or t - self.t_state >= p["start_lean"] + c.start_timeout:
                ji = self.j[1 - a]
                self.idle_lo = [q[ji["hy"]], q[ji["hx"]]]
                self.active_lo = [q[ja["hy"]], q[ja["hx"]]]
                self.t_touchdown = t
                self.t_liftoff = t
                self.stance_time = c.start_stance
                self.ankle_flat = q[ja["ay"]]
                self.knee_touchdown = q[ja["knee"]]
                self._set_gains(a, self.stance_hip_gains)
                knee, ankle, idle_toe = c.start_idle_knee_gain, c.idle_ankle_gain, c.idle_toe_gain
                self._set_gains(1 - a, {"hy": (1.0, 1.0), "hx": (1.0, 1.0), "hz": (1.0, 1.0), "knee": (knee, knee),
                                        "ay": (ankle, ankle), "ax": (ankle, ankle), "mt": (idle_toe, idle_toe)})
                self._enter(t, HEEL_TOE)
        elif state == FLIGHT:
            if touch[a] and t - self.t_liftoff >= c.min_flight:
                self._schedule(speed_now + c.table_lead * (speed_cmd - speed_now))
                # a slow integral of the speed error trims the placement (steady-state speed)
                trim = self.speed_trim + c.speed_trim_gain * (speed_cmd - speed_now)
                self.speed_trim = max(-c.speed_trim_max, min(c.speed_trim_max, trim))
                self.flight_time = 0.5 * self.flight_time + 0.5 * (t - self.t_liftoff)
                self.t_touchdown = t
                self.knee_touchdown = q[ja["knee"]]
                self.ankle_touchdown = q[ja["ay"]]
                self._enter(t, LOADING)
        elif state == LOADING:
            if not touch[a]:
                self._enter(t, FLIGHT)
            elif t - self.t_state >= c.loading_time:
                self.ankle_flat = q[ja["ay"]]
                self._enter(t, HEEL_TOE if ball[a] else HEEL)
        elif state == HEEL:
            if ball[a]:
                self.ankle_flat = q[ja["ay"]]
                self._enter(t, HEEL_TOE)
            elif t - self.t_touchdown >= p["thrust_time"] * self.stance_time:
                self._enter(t, TOE)
        elif state == HEEL_TOE:
            if t - self.t_touchdown >= p["thrust_time"] * self.stance_time:
                self._enter(t, TOE)
        elif state == TOE:
            if not touch[a]:
                self._liftoff(t, q, targets)
            elif not heel[a] and t - self.t_thrust >= p["unloading_after"] * self.stance_time:
                self._enter(t, UNLOADING)
        elif state == UNLOADING:
            if not touch[a]:
                self._liftoff(t, q, targets)
        state = self.state
        a = self.active
        i = 1 - a
        ja, ji = self.j[a], self.j[i]
        kp, kv = self.kp, self.kv

        # ---- active leg
        if state == START:
            # lean forward over the feet: the ankles tip the straight body forward like an
            # inverted pendulum, the hips hold the pelvis pitch, the knees give a little
            s_ = hermite_scalar((t - self.t_state) / p["start_lean"])
            for jj in self.j:
                targets[jj["ay"]] = -c.start_ankle_lean * s_
                targets[jj["knee"]] = c.start_knee * s_
                # a torque on the pelvis through the hip servo; start_hip_damping keeps that share of
                # the hip's own damping (0: none - with the woman's lighter legs the undamped hip
                # chatters at its torque limit and flings the unloaded leg up, docs/running.md)
                targets[jj["hy"]] = q[jj["hy"]] + (pitch - c.start_pitch * s_) + self.kv[jj["hy"]] / self.kp[jj["hy"]] * (
                    qd[jj["hy"]] * (1.0 - c.start_hip_damping) + pitch_rate)
            hy_goal, hx_goal = targets[ja["hy"]], targets[ja["hx"]]
        elif state == FLIGHT:
            hy_goal, hx_goal = self._place_foot(t, p, a, ja, m, pitch, yaw, heading, ch, sh, vx, vy, vz, vxd, vyd)
        else:
            # stance: the hip servos the body attitude (roll, pitch, yaw) as a torque on the
            # pelvis, net of the idle hip's torque (so the swinging leg does not tip the body)
            e_pitch = pitch - p["stance_pitch"]
            e_roll = roll - self.roll_goal
            yaw_goal = heading
            if p["yaw_twist"] > 0:
                # the pelvis turns with the stride (its stance hip forward: in the right leg's stance to
                # the left, measured): the goal follows that twist instead of the heading, so the servo
                # does not fight it
                yaw_goal = heading + (p["yaw_twist"] if a == 0 else -p["yaw_twist"])
            e_yaw = max(-c.yaw_error_limit, min(c.yaw_error_limit, wrap_angle(yaw - yaw_goal)))
            share = hermite_scalar((t - self.t_touchdown) / c.attitude_onset) if state != UNLOADING else \
                1.0 - hermite_scalar((t - self.t_state) / c.attitude_onset)
            # restoring torque on the pelvis (world frame): roll about its x axis, pitch about
            # its y axis, yaw about the vertical
            t_roll = -(c.roll_kp * e_roll + c.roll_kd * roll_rate)
            t_pitch = -(c.pitch_kp * e_pitch + c.pitch_kd * pitch_rate)
            t_yaw = -p["yaw_gain"] * (c.yaw_kp * e_yaw + c.yaw_kd * (wz - self.heading_rate))     # damped relative to the turn
            bx = t_roll * m[0] + t_pitch * m[1]
            by = t_roll * m[3] + t_pitch * m[4]
            bz = t_roll * m[6] + t_pitch * m[7] + t_yaw
            # hip actuators push the pelvis with -sum(tau_j axis_j): the stance hip supplies
            # the restoring torque and cancels the idle hip's reaction
            axes = d.xaxis[self.hip_joint_ids].tolist()
            sa, ia = axes[:3], axes[3:]
            if a == 1:
                sa, ia = ia, sa
            fi = (force[ji["hy"]], force[ji["hx"]], force[ji["hz"]])
            bx = -bx - (ia[0][0] * fi[0] + ia[1][0] * fi[1] + ia[2][0] * fi[2])
            by = -by - (ia[0][1] * fi[0] + ia[1][1] * fi[1] + ia[2][1] * fi[2])
            bz = -bz - (ia[0][2] * fi[0] + ia[1][2] * fi[1] + ia[2][2] * fi[2])
            taus = _solve3(sa[0], sa[1], sa[2], bx, by, bz)
            if c.swing_yields > 0:
                # the attitude's own share of the stance hip's pitch torque (without the idle hip's
                # reaction): what its torque limit leaves is all the idle hip may use (below)
                attitude = _solve3(sa[0], sa[1], sa[2], -(t_roll * m[0] + t_pitch * m[1]), -(t_roll * m[3] + t_pitch * m[4]),
                                   -(t_roll * m[6] + t_pitch * m[7] + t_yaw))
                self.idle_bound = c.swing_yields * max(0.0, self.torque_limit[ja["hy"]] - abs(share * attitude[0]))
            if p["yaw_first"] > 0:
                taus = self._yaw_first(taus, sa, m, bx, by, bz, share, ja, p["yaw_first"])
            for key, tau in zip(("hy", "hx", "hz"), taus):
                j_ = ja[key]
                tau *= share
                if key == "hz" and p["twist_damping"] > 0:
                    tau -= p["twist_damping"] * qd[j_]
                targets[j_] = q[j_] + (tau + kv[j_] * qd[j_]) / kp[j_]
            targets[ja["mt"]] = 0.0
            if state in (LOADING, HEEL):
                targets[ja["knee"]] = self.knee_touchdown
                targets[ja["ay"]] = self.ankle_touchdown
            elif state == HEEL_TOE:
                targets[ja["knee"]] = self.knee_touchdown
                targets[ja["ay"]] = self.ankle_flat
            else:
                s_ = hermite_scalar((t - self.t_thrust) / c.thrust_ramp)
                targets[ja["knee"]] = self.knee_touchdown + (p["knee_extension"] - self.knee_touchdown) * s_
                targets[ja["ay"]] = self.ankle_flat + (p["ankle_extension"] - self.ankle_flat) * s_
                # thrust from the ankle and the metatarsal joint (Hodgins et al. 1995): the toes
                # pushed down against the ground lengthen the push past the ankle's range
                targets[ja["mt"]] = p["toe_push"] * s_
                if state == UNLOADING and c.unload_knee > 0:
                    # the knee starts to fold so that the toe leaves the ground
                    u_ = hermite_scalar((t - self.t_state) / c.unload_ramp)
                    targets[ja["knee"]] += (c.unload_knee - targets[ja["knee"]]) * u_
            targets[ja["ax"]] = 0.0
            hy_goal, hx_goal = q[ja["hy"]], q[ja["hx"]]

        # ---- idle leg: shortened, hip mirroring the active hip (eqs. 3-4)
        if state != START:
            self._idle_leg(t, p, state, ji, i, hy_goal, hx_goal, pitch, speed_now, pitch_rate)

        # ---- arms (eq. 5): each shoulder swings against the opposite hip; elbows cycle with it
        k_arm = p["arm_swing"]
        # and both turn about the trunk with its yaw error (the right arm forward and the left back for a
        # positive yaw): their reaction on the trunk, not the stance hip, takes part of the yaw
        twist = 0.0 if state == START else p["arm_yaw"] * wrap_angle(yaw - heading)
        for leg in (0, 1):
            jj, opposite = self.j[leg], self.j[1 - leg]
            sign = 1.0 if leg == 0 else -1.0
            swing = -k_arm * q[opposite["hy"]] + c.arm_offset + sign * twist
            targets[jj["sz"]] = sign * swing
            targets[jj["sx"]] = self.base[jj["sx"]] - sign * c.arm_abduction      # arms clear the torso
            targets[jj["ez"]] = sign * (c.elbow_base + c.elbow_swing * swing)
        targets[self.neck_y] = -p["stance_pitch"]

        # ---- eq. 6's desired velocity: the servos are position actuators (tau = kp (ctrl - q) -
        # kv qdot), so a moving target is led by kv/kp times its rate, else a swing lags it
        tracked = [ji["hy"], ji["hx"], ji["knee"]]
        if state == FLIGHT:
            tracked += [ja["hy"], ja["hx"], ja["knee"], ja["ay"]]
        command = list(targets)
        previous = self.previous_goal
        rate = self.control_rate
        for j_ in tracked:
            if j_ in previous:
                v_ = (targets[j_] - previous[j_]) * rate
                v_ = c.ff_max if v_ > c.ff_max else -c.ff_max if v_ < -c.ff_max else v_
                command[j_] += kv[j_] / kp[j_] * v_
        if state == START and c.start_hip_damping > 0 and ji["hy"] in previous:
            # in the lean the idle hip's target is the pitch servo's (it moves with the hip angle),
            # so its lead cancels the hip's damping as well: taken back by the same share
            v_ = (targets[ji["hy"]] - previous[ji["hy"]]) * rate
            v_ = c.ff_max if v_ > c.ff_max else -c.ff_max if v_ < -c.ff_max else v_
            command[ji["hy"]] -= c.start_hip_damping * kv[ji["hy"]] / kp[ji["hy"]] * v_
        if c.swing_yields > 0 and state not in (START, FLIGHT) and speed_cmd < p["speed"]:
            # the swing yields to the attitude: the idle hip's pitch torque (kp (command - q) - kv qdot)
            # is held within what the stance hip has left, so cancelling it cannot saturate the stance hip
            j_ = ji["hy"]
            tau = kp[j_] * (command[j_] - q[j_]) - kv[j_] * qd[j_]
            if abs(tau) > self.idle_bound:
                command[j_] = q[j_] + (math.copysign(self.idle_bound, tau) + kv[j_] * qd[j_]) / kp[j_]
        self.previous_goal = {j_: targets[j_] for j_ in tracked}
        servos.hold(np.array(command), t)

    def _yaw_first(self, taus, sa, m, bx, by, bz, share, ja, given_up):
        """The hip's rotation axis runs along the thigh, so with the thigh swept forward or back it
        carries part of the roll torque too; when that would take it past its torque limit, the
        roll demand is reduced (toward zero, never reversed) so that the yaw is still held."""
        c = self.constants
        limit = self.ctx.model.actuator_forcerange[self.ctx.servos.actuators][ja["hz"], 1] * c.hip_yaw_headroom
        hz = taus[2] * share
        if abs(hz) <= limit or share <= 0.0:
            return taus
        rx, ry, rz = m[0], m[3], m[6]                   # the pelvis's roll axis (world)
        per_roll = _solve3(sa[0], sa[1], sa[2], rx, ry, rz)
        if abs(per_roll[2]) < 1e-6:
            return taus
        alpha = (taus[2] - math.copysign(limit, hz) / share) / per_roll[2]
        roll_demand = bx * rx + by * ry + bz * rz
        alpha = given_up * max(min(0.0, roll_demand), min(max(0.0, roll_demand), alpha))
        return tuple(tau - alpha * r for tau, r in zip(taus, per_roll))

    def _place_foot(self, t, p, a, ja, m, pitch, yaw, heading, ch, sh, vx, vy, vz, vxd, vyd):
        """Flight: hip, knee and ankle targets that put the heel at the touchdown point of
        eqs. 1-2 (plus the ground-speed-matching swing), by leg inverse kinematics."""
        c = self.constants
        targets = self.targets
        leg = self.legs[a]
        hip = self.ctx.data.xpos[self.hip_body[a]].tolist()
        ts = self.stance_time
        lf = leg.foot_length
        # eqs. 1-2; departure: the foot lands place_back closer to the hip than eq. 1 says (our
        # stance is not symmetric about mid-stance: the hip passes over the foot early), less
        # when running slowly, where the stance sweep t_s xdot is short
        back = p["place_back"] * min(1.0, math.hypot(vx, vy) / c.place_back_speed) + self.speed_trim
        x_hh = 0.5 * (ts * vx - ch * lf) + p["speed_gain"] * (vx - vxd) - back * ch          # eq. 1
        y_hh = 0.5 * (ts * vy - sh * lf) + p["speed_gain"] * (vy - vyd) - back * sh          # eq. 2
        # a sideways drift (the sway of each step averaged out over about a stride) is corrected
        # harder than eq. 2's k does
        # in a turn the foot lands outside the curve, so that the ground pushes the body round
        # it (centripetal acceleration v * omega, as a share of g, times a lever in metres)
        outward = c.turn_place_gain * math.hypot(vx, vy) * self.turn_rate / GRAVITY
        lateral = c.lateral_gain * self.lateral_drift - outward
        x_hh -= sh * lateral
        y_hh += ch * lateral
        inward = c.foot_inward if a == 0 else -c.foot_inward                          # right foot lands left of its hip
        x_hh -= sh * inward
        y_hh += ch * inward
        reach = math.hypot(x_hh, y_hh)
        limit = c.placement_limit * p["touchdown_leg"]
        if reach > limit:
            x_hh *= limit / reach
            y_hh *= limit / reach
        z_hh = math.sqrt(max(p["touchdown_leg"] ** 2 - x_hh * x_hh - y_hh * y_hh, 0.01))   # definition: a guard
        # ground speed matching: swung further forward during flight, brought back over the last
        # gsm_retract s before the predicted touchdown (ballistic hip height reaching z_hh)
        to_touchdown = time_to_fall_to(hip[2], vz, z_hh)
        gsm = p["ground_speed_matching"] * hermite_scalar(to_touchdown / c.gsm_retract)
        x_hh += gsm * ch
        y_hh += gsm * sh
        fx, fz = leg.ankle_from_heel(c.touchdown_toe_up)
        ax_w, ay_w, az_w = x_hh + fx * ch, y_hh + fx * sh, -z_hh + fz
        px = m[0] * ax_w + m[3] * ay_w + m[6] * az_w              # world -> pelvis frame
        py = m[1] * ax_w + m[4] * ay_w + m[7] * az_w
        pz = m[2] * ax_w + m[5] * ay_w + m[8] * az_w
        hy_goal, hx_goal, knee_goal = leg.hip_knee_for(px, py, pz)
        hz_goal = max(-c.hip_yaw_limit, min(c.hip_yaw_limit, wrap_angle(heading - yaw)))
        # the foot pitched toe-up so that the heel lands first (foot pitch = pelvis pitch + hip + knee + ankle)
        ankle_goal = -c.touchdown_toe_up - pitch - hy_goal - knee_goal
        if p["swing_fold"] > 0:
            # a thigh still behind its touchdown angle keeps its knee folded (the foot clears the
            # ground until the leg has swung forward), instead of reaching down behind the body
            lag = self.ctx.servos.angles()[ja["hy"]] - hy_goal
            if lag > 0:
                fold = min(c.swing_fold_max, p["swing_fold"] * lag)
                knee_goal += fold
                ankle_goal -= fold
        goals = (hy_goal, hx_goal, hz_goal, knee_goal, ankle_goal)
        blend = hermite_scalar((t - self.t_liftoff) / c.swap_blend) if self.blend_from else 1.0
        for k, key in enumerate(BLENDED):
            start = self.blend_from[k] if self.blend_from else goals[k]
            targets[ja[key]] = start + (goals[k] - start) * blend
        targets[ja["ax"]] = 0.0
        targets[ja["mt"]] = 0.0
        return targets[ja["hy"]], targets[ja["hx"]]

    def _idle_leg(self, t, p, state, ji, i, hy_goal, hx_goal, pitch, speed_now, pitch_rate):
        """Eqs. 3-4: the idle hip mirrors the active hip about their lift-off angles, shortened
        (knee folded, ankle flexed) so the toe clears the ground; it is kept on schedule to be
        forward by the end of stance and unfolds its knee while the active leg thrusts."""
        c = self.constants
        targets = self.targets
        hy_idle = self.idle_lo[0] - (hy_goal - self.active_lo[0])
        hx_idle = self.idle_lo[1] - (hx_goal - self.active_lo[1])
        if state not in (FLIGHT, START):
            s_ = hermite_scalar((t - self.t_touchdown) / max(self.stance_time, 0.05))   # definition: a guard
            schedule = self.idle_lo[0] + (c.idle_forward_thigh - pitch - self.idle_lo[0]) * s_
            hy_idle = min(hy_idle, schedule)
        side = 1.0 if i == 0 else -1.0                  # +x adducts the right hip, abducts the left
        hx_idle = side * max(-c.idle_abduction, min(c.idle_adduction, side * hx_idle))
        if state == FLIGHT:
            # in the air the body's angular momentum is fixed: swinging the idle leg back
            # pitches the trunk back (and forward, forward) - the only pitch control there is
            hy_idle += c.idle_pitch_gain * (pitch - p["stance_pitch"]) + c.idle_pitch_damp * pitch_rate
        targets[ji["hy"]] = max(-c.idle_hip_flexion_max, min(c.idle_hip_extension_max, hy_idle))
        # a slow runner folds the idle leg less (people jog with the foot low)
        idle_knee = min(p["idle_knee"], max(c.idle_knee_min, c.idle_knee_per_speed * speed_now))
        targets[ji["hx"]] = hx_idle
        targets[ji["hz"]] = 0.0
        if state in (TOE, UNLOADING) and c.idle_unfold > 0:
            s_ = hermite_scalar((t - self.t_thrust) / max(c.idle_unfold * self.stance_time, 0.02))   # definition: a guard
            targets[ji["knee"]] = idle_knee + (c.idle_unfold_knee - idle_knee) * s_
        else:
            targets[ji["knee"]] = idle_knee
        targets[ji["ay"]] = c.idle_ankle
        targets[ji["ax"]] = 0.0
        targets[ji["mt"]] = 0.0


def check_steering(speed: float, path: np.ndarray, lookahead: float, name: str, steering: dict) -> None:
    """A run along ``path`` (in the runner's frame: it starts at the origin facing +X) is offered
    where the runner was measured to steer (``steering``, its table's limits): a path with a bend (the
    turn from +X onto the path's first direction included) at most its ``max_speed``, its tightest
    bend (at the look-ahead's scale, as pure pursuit cuts it) asking at most its
    ``max_lateral_acceleration``; else refused, naming what would do."""
    radius, where = tightest_radius(np.vstack([[-lookahead, 0.0], path]), lookahead)
    if not math.isfinite(radius):
        return                                              # a straight line along the runner's heading
    fastest, limit = steering["max_speed"], steering["max_lateral_acceleration"]
    if speed > fastest:
        raise ParameterError(f"a course, a path or a facing other than 0 is run by the {name} at speed <= {fastest:g} m/s "
                             f"(asked: {speed:g} m/s): faster, curves measured fell"
                             + (", even a circle of radius 50 m at 5 m/s" if name == "man" else "")
                             + " (docs/running.md, where steering is offered); run straight or slower")
    if speed * speed / radius > limit * 1.01:    # definition: a polyline measures its arcs up to 0.2 % tight
        widest = speed * speed / limit
        slowest = math.sqrt(limit * radius)
        raise ParameterError(f"the path bends on a radius of {radius:.2f} m ({max(where - lookahead, 0.0):.1f} m along "
                             f"it), which at speed {speed:g} m/s asks {speed * speed / radius:.2f} m/s^2 of lateral "
                             f"acceleration; at most {limit:g} m/s^2 is run (the {name}): a radius >= {widest:.1f} m"
                             + (f" or speed <= {slowest:.2f} m/s" if slowest >= Running.schema.by_name["speed"].minimum else "")
                             + " (docs/running.md, where steering is offered)")


def path_for(p: dict, placement: Placement | None = None):
    """The polyline a run follows: the user's points, a built-in course, a turn to ``facing``
    (straight ahead for turn_after m, then a turn by facing on turn_radius), or None (straight
    ahead); in the world frame of a runner placed at ``placement`` (None: the origin, facing +X)."""
    if "path" in p:
        path = np.asarray(p["path"], dtype=float)
    else:
        course = Running.schema.by_name["course"].option(p["course"])
        if course == "turn":
            path = turn_path(p["turn_angle"], p["turn_after"], p["turn_radius"])
        elif course == "figure_eight":
            path = figure_eight_path(p["turn_radius"], p["turn_after"])
        elif course == "circle":
            path = circle_path(p["turn_radius"], p["turn_after"])
        elif p["facing"] != 0.0:
            path = turn_path(p["facing"], p["turn_after"], p["turn_radius"])
        else:
            return None
    if placement is None:
        return path
    return np.array([placement.point([x, y, 0.0])[:2] for x, y in path])


def _first_time_on_path(a: dict, path: np.ndarray) -> float:
    """The deviation is measured once the runner is running (faster than 2 m/s), not while it
    leans and accelerates out of the stand."""
    speed = np.linalg.norm(a["com_vel"][:, :2], axis=1)
    moving = np.nonzero(speed > 2.0)[0]       # criterion: the deviation's judging starts at 2 m/s
    return float(a["time"][moving[0]]) if len(moving) else float(a["time"][-1])


def _solve3(a1, a2, a3, bx, by, bz):
    """Coefficients (c1, c2, c3) with c1 a1 + c2 a2 + c3 a3 = b for 3-vectors (Cramer's rule);
    the hip's three axes never line up within its joint range."""
    det = (a1[0] * (a2[1] * a3[2] - a2[2] * a3[1]) - a2[0] * (a1[1] * a3[2] - a1[2] * a3[1])
           + a3[0] * (a1[1] * a2[2] - a1[2] * a2[1]))
    if abs(det) < 1e-6:
        return 0.0, 0.0, 0.0
    c1 = (bx * (a2[1] * a3[2] - a2[2] * a3[1]) - a2[0] * (by * a3[2] - bz * a3[1]) + a3[0] * (by * a2[2] - bz * a2[1])) / det
    c2 = (a1[0] * (by * a3[2] - bz * a3[1]) - bx * (a1[1] * a3[2] - a1[2] * a3[1]) + a3[0] * (a1[1] * bz - a1[2] * by)) / det
    c3 = (a1[0] * (a2[1] * bz - a2[2] * by) - a2[0] * (a1[1] * bz - a1[2] * by) + bx * (a1[1] * a2[2] - a1[2] * a2[1])) / det
    return c1, c2, c3


def wrap_angle(angle: float) -> float:
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


BLENDED = ("hy", "hx", "hz", "knee", "ay")   # targets blended from idle to active after lift-off
