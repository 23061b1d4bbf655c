"""Jump to a target the animator places (Ooi 2015): a landing point, an air time, a wind-up time.

*Path estimation* (Ooi §3.4.1): the COM leaves the ground at the take-off point and must come
down at the touchdown point ``air_time`` later, so the take-off velocity is
``v = d / T + (0, 0, g T / 2)``. A request whose take-off speed is beyond what the character's
legs have ever given it (its strongest calibrated vertical leap) is refused before anything is
simulated, with the numbers.

*Planned above the loop*: Ooi moved the pelvis kinematically; here the leap's own controllers
do all the work (balance crouch, proximal-to-distal thrust, landing, balance - the leap of
leap.py, with the broad jump's or the vertical leap's thrust), so the wind-up pose, the lean,
arm swing, lift-off hip angle and the landing's settings that land the feet on the target are
found by searching over whole simulated jumps - in sim_core/planning/jump.py, which sits above
sim_core/simulate.py: this behaviour never runs a simulation. It only looks its plan up
(``stored_plan``): in the user's plan store (``plan_store_dir``, written by ``python -m sim_core
plan jump_to_target ...``) over the shipped tables (sim_core/tuned/tables/jump_targets_<character>.json,
written by python -m sim_core calibrate jump_to_target), and refuses a request with no plan with the command that
plans it. A raised target gets a box under it; a target below the start (``target_z`` < 0) puts
the character on a box with the ground that far below, and ``obstacle_height`` a box to clear
on the way (Ooi's box -> over a second box -> ground; see ``scene_for``).
"""
from __future__ import annotations

import contextlib
import dataclasses
import math
import os
import tempfile
from pathlib import Path

import numpy as np

from ...analysis import feet_above_surface, surface_under_points
from ...ballistics import GRAVITY
from ...control.behaviour import register
from ...control.leap import AIRBORNE_HEIGHT, LEAP_SETTINGS, leap_assess, run_strength, vertical_table
from ...control.turn import jump_start, turn_duration
from ..leap.behaviour import Leap
from ...errors import ParameterError
from ...schema import Parameter, Schema
from ...tuned import TableType, characters_of, load, register as register_table, require_calibrated, table_path
from .region import AIR_TIME_TOLERANCE, LANDING_TOLERANCE, mode, model, region_refusal, takeoff_capacity

# where the COM is, relative to the middle of the feet, at take-off and at touchdown of a broad
# jump (measured on the man's calibrated 1.0 m jump; used only for the path estimate)
TAKEOFF_COM = (0.30, 1.00)          # m ahead of the feet, m above them
TOUCHDOWN_COM = (-0.25, 0.90)       # m ahead of the feet (behind: the feet land in front), m above
WINDUP_OVERHEAD = 0.45              # s of the wind-up that are not the crouch: standing still, thrust
MIN_CROUCH_TIME = 0.3               # s: the shortest crouch a plan's wind-up asks of the leap
MIN_BROAD_DISTANCE = 0.05           # m: a plan with the broad jump's thrust asks at least this distance (> 0: broad)

KNOB_DEFAULTS = {"crouch_arms": 0.0, "liftoff_roll": 0.0,    # a knob a prior or a stored plan does not name
                 "thrust_lean": 0.0, "com_offset_y": 0.0,     # (arms hanging in the crouch, no lift-off roll,
                 "spin_hold": 0.0}                            # the thrust along poses balanced over the feet,
                                                              # no sideways lean, no hold on the twist); the
                                                              # leap's parameters by the same names

GROUND_AIR_TIME = 0.45              # s: the air time the report asks of a jump to a target on the
                                    # ground, and the broad jump's planned jumps (a standing broad jump's)
SIDEWAYS_AIR_TIME = 0.6             # s: the report's sideways jumps. The legs push sideways only along their
                                    # lean (at most ~0.6 m/s sideways per m/s up, measured on the man): asked
                                    # in 0.45 s, 150-1,050 trials per target: those that reached it flew 0.59-0.82 s
BOX_DISTANCE, BOX_AIR_TIME = 0.8, 0.6   # m, s: the report's jumps onto a box: its middle this far ahead
                                    # (its near edge 0.5 m ahead, clear of the knees in a deep crouch)


def takeoff_velocity(start: np.ndarray, end: np.ndarray, air_time: float) -> np.ndarray:
    """Ooi §3.4.1: the velocity that carries a point from ``start`` to ``end`` in ``air_time``
    under gravity."""
    v = (np.asarray(end, dtype=float) - np.asarray(start, dtype=float)) / air_time
    v[2] += 0.5 * GRAVITY * air_time
    return v


def path_estimate(target, air_time: float) -> np.ndarray:
    """Take-off velocity of the COM for a landing of the middle of the feet at ``target`` (m,
    relative to the middle of the feet at the start; z = height of the landing surface)."""
    target = np.asarray(target, dtype=float)
    distance = math.hypot(target[0], target[1])
    ahead = target[:2] / distance if distance > 1e-9 else np.array([1.0, 0.0])
    start = np.array([*(TAKEOFF_COM[0] * ahead), TAKEOFF_COM[1]])
    end = np.array([*(target[:2] + TOUCHDOWN_COM[0] * ahead), target[2] + TOUCHDOWN_COM[1]])
    return takeoff_velocity(start, end, air_time)


BOX_LENGTH, BOX_WIDTH = 0.6, 1.0    # m: a box under a raised target, centred on it
START_BOX_LENGTH = 0.6              # m: the box a jump down starts on, its front edge just ahead of the toes
START_BOX_EDGE = 0.02               # m ahead of the toes
OBSTACLE_LENGTH = 0.3               # m: a box to jump over, centred between the start and the target
OBSTACLE_ROOM = OBSTACLE_LENGTH + 0.4   # m: a jump over a box lands at least this far ahead of the toes


def obstacle_of(target) -> float:
    """The height of the box to jump over (m above the surface landed on) of a target (x, y, z[,
    obstacle height])."""
    return float(target[3]) if len(target) > 3 else 0.0     # definition: the 4th entry is optional


def scene_for(character, target, world=None):
    """The world of a jump to ``target`` (x, y, z[, obstacle height]) m: the requested one, plus a
    box under a raised target (z > 0); for a target below the start (z < 0) the ground at z and a
    box the character starts on (its top at 0, its front edge just ahead of the toes); and a box
    to jump over, standing on the surface landed on halfway between the toes and the target."""
    from ...world import World
    from ...character.spec import load_character
    world = world or World()
    obstacle = obstacle_of(target)
    if target[2] == 0 and not obstacle:
        return world
    if isinstance(character, str):
        character = load_character(character)
    centre = start_feet_centre(character)
    toes = toe_tip(character)
    boxes = list(world.boxes)
    if target[2] > 0:
        boxes.append((float(centre[0] + target[0]), float(centre[1] + target[1]), float(target[2]),
                      BOX_LENGTH, BOX_WIDTH))
    elif target[2] < 0:
        world = dataclasses.replace(world, floor=float(target[2]))
        front = toes + START_BOX_EDGE
        boxes.append((front - START_BOX_LENGTH / 2, float(centre[1]), 0.0, START_BOX_LENGTH, BOX_WIDTH))
    if obstacle:
        middle = 0.5 * (toes + centre[0] + target[0])
        boxes.append((float(middle), float(centre[1] + 0.5 * target[1]), float(min(target[2], 0.0) + obstacle),
                      OBSTACLE_LENGTH, BOX_WIDTH))
    return dataclasses.replace(world, boxes=tuple(boxes))


def toe_tip(character) -> float:
    """x of the front of the toes' contact spheres in the standing start pose (simulation frame)."""
    return max(c["pos"][0] + c["radius"] for body in ("TOER", "TOEL") for c in character.body(body)["contacts"])


def start_feet_centre(character) -> np.ndarray:
    """Middle of the feet (x, y) of the standing start pose, in the simulation frame: the point
    that targets are given from."""
    points = [c["pos"] for body in ("FOOTR", "TOER", "FOOTL", "TOEL") for c in character.body(body)["contacts"]]
    return np.mean(np.asarray(points, dtype=float)[:, :2], axis=0)


def target_params(character, point) -> dict:
    """The target parameters for a point (m) in the simulation frame of the character's start,
    e.g. an object placed in a Blender scene."""
    centre = start_feet_centre(character)
    return {"target_x": float(point[0] - centre[0]), "target_y": float(point[1] - centre[1]),
            "target_z": float(point[2])}


def landing_measures(trajectory) -> dict:
    """Read off a jump: the middle of the feet at the start and at touchdown (TARGETS.md's landing
    point; a success also keeps the feet within LANDING_SKID_LIMIT of it until they settle, see
    leap_assess), air time, wind-up time (first move to lift-off), and the outcome; for the
    planner's cost, how far the COM's capture point (COM + v sqrt(h/g)) is from the middle of the
    feet at touchdown and whether the jump fell before it left the ground; with a recovery step after the
    touchdown, when it began (``recovery_step_time``; the landing point stays the touchdown's)."""
    a = trajectory.arrays
    feet = a["support_points"]
    flying = feet_above_surface(trajectory).min(axis=1) > AIRBORNE_HEIGHT
    begun = jump_start(trajectory)          # a jump that turned first (turn.py): its hops are not the jump
    if begun:
        flying &= a["time"] >= begun
    outcome, metrics = leap_assess(trajectory, start=begun)
    start = feet[0, :, :2].mean(axis=0)
    result = {"outcome": outcome, "air_time": 0.0, "landing": [float("nan")] * 2, "landing_height": float("nan"),
              "windup_time": float("nan"), "capture_error": float("nan"),
              "fell_before_liftoff": bool(metrics["fell"] and (not flying.any()
                                                                or metrics["fall_time"] < metrics["liftoff_time"]))}
    if flying.any():
        first = int(np.argmax(flying))
        down = ~flying[first:]
        touchdown = first + int(np.argmax(down)) if down.any() else len(flying) - 1
        result["landing"] = (feet[touchdown, :, :2].mean(axis=0) - start).tolist()
        result["landing_height"] = float(surface_under_points(trajectory, feet[touchdown, :, :2].mean(axis=0)))
        result["windup_time"] = float(metrics["liftoff_time"] - begun)
        result["air_time"] = float(a["time"][touchdown] - a["time"][first])
        middle = feet[touchdown].mean(axis=0)
        com, velocity = a["com"][touchdown], a["com_vel"][touchdown]
        capture = com[:2] + velocity[:2] * math.sqrt(max(com[2] - middle[2], 0.1) / GRAVITY)  # definition: a guard
        result["capture_error"] = float(np.linalg.norm(capture - middle[:2]))
    if metrics.get("recovery_step"):        # the landing's recovery step (landing_recovery_step): when it began
        result["recovery_step_time"] = metrics["recovery_step_time"]
    return result


def leap_params(settings: dict, target, windup_time: float, air_time: float | None = None) -> dict:
    """The leap's low-level parameters for these settings (the planner's trials run the leap; a
    vertical-leap thrust when ``vertical_thrust``, else the broad jump's; with the commanded take-off,
    the flight to ``target`` in ``air_time``)."""
    vertical = settings["vertical_thrust"] > 0.5
    return {"low_level": 1, "distance": 0.0 if vertical else max(float(target[0]), MIN_BROAD_DISTANCE),
            "crouch_height": settings["crouch_height"], "crouch_pitch": settings["crouch_pitch"],
            "com_offset": settings["com_offset"], **optional_knobs(settings), **turn_of(settings),
            "liftoff_hip": settings["liftoff_hip"],
            "arm_swing": settings["arm_swing"], "thrust_damping": settings["thrust_damping"],
            "foot_delta": settings["foot_delta"], "crouch_time": crouch_time(windup_time),
            **landing_settings(settings), **commanded_flight(settings, target, air_time)}


def commanded_flight(settings: dict, target, air_time: float | None) -> dict:
    """A plan with the commanded take-off (``commanded_takeoff``, control/commanded_thrust.py): the
    switch, the row's own ``lean_push`` where it names one (control.leap.LEAN_PUSH), and the flight it
    commands, the request's target and air time (forward, the plan's own ``flight_target_x`` where it
    names one: its aim, planning/commanded.py); none for any other plan (which runs as it always did)."""
    if settings.get("commanded_takeoff", 0.0) <= 0.5 or air_time is None:
        return {}
    return {"commanded_takeoff": 1.0, **({"lean_push": float(settings["lean_push"])} if "lean_push" in settings else {}),
            "flight_target_x": float(settings.get("flight_target_x", target[0])),
            "flight_target_y": float(settings.get("flight_target_y", target[1])),
            "flight_target_z": float(target[2]), "flight_air_time": float(air_time)}


def optional_knobs(settings: dict) -> dict:
    """The knobs that a plan may not name (KNOB_DEFAULTS), with their defaults where it does not."""
    return {name: settings.get(name, default) for name, default in KNOB_DEFAULTS.items()}


def turn_of(settings: dict) -> dict:
    """The turn before the jump (the leap's ``turn_first`` or ``turn_angle``, control/turn.py) of a plan that
    turns first; none for any other (a plan without it runs as it always did)."""
    return {k: settings[k] for k in ("turn_first", "turn_angle") if settings.get(k)}


ARM_FEEDBACK = ("landing_arm_pitch_gain", "landing_arm_pitch")    # the arms' pitch feedback: only plans that name it
RECOVERY_SETTINGS = ("landing_recovery_step", "landing_step_margin")  # the landing's recovery step: likewise
TUCK_SETTINGS = ("landing_tuck_knee_flexion", "landing_tuck_share")     # the flight's tuck: likewise
TOE_SETTINGS = ("landing_toe_first_at_speed", "landing_delta_from_drop")   # the forefoot first at speed, the
                                                                             # delta for the drop: likewise


def landing_settings(settings: dict) -> dict:
    """The landing's settings among the planner's (the leap passes them to its landing)."""
    return {"landing_swing_arms": float(settings["landing_swing_arms"] > 0.5),
            "landing_arm_flexion": settings["landing_arm_flexion"],
            "landing_foot_lead_time": settings["landing_foot_lead_time"],
            "landing_place_sideways": float(abs(settings.get("com_offset_y", 0.0)) > 0.0),
            "landing_right_time": float(settings.get("landing_right_time", 0.0)),
            **{k: float(settings[k]) for k in ARM_FEEDBACK + RECOVERY_SETTINGS + TUCK_SETTINGS + TOE_SETTINGS if k in settings}}


def crouch_time(windup_time: float) -> float:
    return max(windup_time - WINDUP_OVERHEAD, MIN_CROUCH_TIME)


def check_request(character, p: dict, strength: str) -> None:
    """The refusals of a jump that need no simulation (the box to clear, the direction, the
    take-off speed against the character's strongest, and on flat ground or a box (no obstacle) a
    target outside the region offered, region.region_refusal, unless a stored plan found this very
    request), for the behaviour and for the planner before it searches; ``strength``: "human" or
    "unlimited" (leap.run_strength). A target to the side beyond the region is refused too where a
    stored plan to that side turns first (issue 29: refused before simulating, whatever the plan store
    holds)."""
    require_calibrated("leap", character.name, "leap")        # a jump to a target takes off as the leap does
    if model(character.name) is None:
        raise ParameterError(
            f"the jump to a target is not measured for the {character.name}: it is offered where measured jumps "
            f"land (sim_core/tuned/tables/jump_model_<character>.json, measured for: "
            f"{', '.join(characters_of('jump_model')) or 'nobody'}); python -m sim_core.planning.jump_model "
            f"--characters {character.name} measures them")
    target = np.array([p["target_x"], p["target_y"], p["target_z"], p["obstacle_height"]])
    if p["obstacle_height"] > 0.0:
        gap = p["target_x"] - (toe_tip(character) - start_feet_centre(character)[0])
        if p["target_z"] > 0.0 or gap < OBSTACLE_ROOM:
            raise ParameterError(
                f"parameter obstacle_height={p['obstacle_height']:g} m: a box to jump over needs a target on "
                f"the ground or below (target_z <= 0, is {p['target_z']:g}) at least "
                f"{OBSTACLE_ROOM:.1f} m ahead of the toes (is {gap:.2f} m); allowed range of "
                f"obstacle_height is [0, 1] m, 0 = none")
    if p["target_x"] < 0.0 or (p["target_x"] == 0.0 and p["target_y"] == 0.0):
        raise ParameterError(f"parameter target_x={p['target_x']:g} m: the jump goes forward or sideways, "
                             f"not back or on the spot; allowed range is [0, 2.5] m, with target_x or "
                             f"target_y not 0")
    velocity = path_estimate(target[:3], p["air_time"])
    capacity = takeoff_capacity(character.name, vertical_table(strength))
    speed = float(np.linalg.norm(velocity))
    if speed > capacity:
        raise ParameterError(
            f"target ({p['target_x']:g}, {p['target_y']:g}, {p['target_z']:g}) m in air_time={p['air_time']:g} s "
            f"needs a take-off at {speed:.2f} m/s (path estimate: {velocity[0]:.2f} forward, "
            f"{velocity[2]:.2f} up); the strongest take-off of {character.name} is {capacity:.2f} m/s - "
            f"allow a longer or shorter air time, or a nearer target")
    if p["obstacle_height"] == 0.0 and strength == "human":
        plan = stored_plan(character.name, {**{k: float(p[k]) for k in REQUEST_KEYS}, "strength": strength})
        refusal = None if plan and plan["found"] else region_refusal(character.name, target[:3], p["air_time"])
        if refusal:        # on flat ground or a box: only where a measured balanced jump does it (region.py)
            raise ParameterError(refusal)


def plan_command(character: str, p: dict) -> str:
    """The command that plans this request (named in the refusal of an unplanned one)."""
    defaults = JumpToTarget.schema.defaults()
    sets = "".join(f" --set {k}={p[k]:g}" for k in REQUEST_KEYS if p[k] != defaults[k])
    return f"python -m sim_core plan jump_to_target --character {character}{sets}"


def plan_row(table: dict, request: dict) -> dict | None:
    """The plan stored for this very request (keyed: same_request), or None."""
    return next((plan for plan in table["plans"] if same_request(plan["request"], request)), None)


JUMP_TARGETS_TABLE = register_table(TableType(
    "jump_targets", LEAP_SETTINGS,
    lambda body: ((f"plan {k} {p['request']}", p["settings"]) for k, p in enumerate(body["plans"])),
    (plan_row,)))


PLAN_STORE_VARIABLE = "SIM_ATHLETICS_PLANS"     # the user's plan store; default below


def plan_store_dir() -> Path:
    """The user's plan store: the directory in $SIM_ATHLETICS_PLANS, else
    $XDG_CACHE_HOME/sim_athletics/plans (~/.cache/sim_athletics/plans). Its files are tables of
    the one store (sim_core.tuned), like the shipped jump_targets tables they are layered over."""
    if os.environ.get(PLAN_STORE_VARIABLE):
        return Path(os.environ[PLAN_STORE_VARIABLE]).expanduser()
    cache = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(cache) / "sim_athletics" / "plans"


@contextlib.contextmanager
def plan_store_at(directory):
    """The plan store is ``directory`` while the block runs ($SIM_ATHLETICS_PLANS set, restored after;
    worker processes started inside inherit it)."""
    before = os.environ.get(PLAN_STORE_VARIABLE)
    os.environ[PLAN_STORE_VARIABLE] = str(directory)
    try:
        yield
    finally:
        if before is None:
            os.environ.pop(PLAN_STORE_VARIABLE, None)
        else:
            os.environ[PLAN_STORE_VARIABLE] = before


@contextlib.contextmanager
def shipped_plans_only():
    """The user's plan store set aside (an empty temporary one) while the block runs: what a
    calibration plans, remeasures and reports are the shipped tables, the same on every machine."""
    with tempfile.TemporaryDirectory(prefix="sim_athletics_no_plans_") as empty, plan_store_at(empty):
        yield


def user_plans_path(character: str) -> Path:
    return table_path("jump_targets", character, plan_store_dir())


def read_plans(character: str, directory: Path | None = None) -> list[dict]:
    """The plans of the character's jump_targets table in ``directory`` (None: the shipped one);
    none if it does not exist yet."""
    table = load("jump_targets", character, directory)
    return table["plans"] if table is not None else []


def stored_plans(character: str) -> list[dict]:
    """Every plan for ``character``: the user's plan store layered over the shipped table (a
    user's plan for a request replaces the shipped one for it)."""
    user = read_plans(character, plan_store_dir())
    shipped = [p for p in read_plans(character)
               if not any(same_request(p["request"], u["request"]) for u in user)]
    return shipped + user


def stored_plan(character: str, request: dict) -> dict | None:
    """The plan stored for ``request``, or None; a search stored as not found is no plan where the commanded take-off
    offers the request now (region.mode "commanded": planned anew, as an unplanned one; e.g. the woman's sideways
    searches of 0.6 s, offered by her sideways_long_region since)."""
    plan = plan_row({"plans": stored_plans(character)}, request)
    if (plan is not None and not plan["found"] and not request.get("obstacle_height", 0.0)
            and request.get("strength", "human") == "human"
            and mode(character, tuple(request.get(k, 0.0) for k in ("target_x", "target_y", "target_z")),
                     request["air_time"]) == "commanded"):
        return None
    return plan


REQUEST_KEYS = ("target_x", "target_y", "target_z", "obstacle_height", "air_time", "windup_time")


def same_request(a: dict, b: dict) -> bool:
    """(A plan stored before obstacles existed has no obstacle_height: none.)"""
    return (all(abs(a.get(k, 0.0) - b.get(k, 0.0)) < 1e-6 for k in REQUEST_KEYS)
            and a.get("strength", "human") == b.get("strength", "human"))


@register
class JumpToTarget(Leap):
    name = "jump_to_target"
    world_frame = True             # turns / aims in the world's X-Z plane from the origin
    summary = ("Jump so that the feet land on a target point, with a given air time and wind-up time "
               "(Ooi 2015), by the leap and landing controllers; the settings are planned by simulation.")
    default_duration = 5.0
    # its tuned settings are a plan's (the jump_targets table's rows, LEAP_SETTINGS): chosen by planning for
    # the request, not set by hand
    settings_schema = Schema()
    schema = Schema(
        Parameter("target_x", "m", 1.0, -2.5, 2.5, "landing point of the middle of the feet, forward of "
                  "the middle of the feet at the start"),
        Parameter("target_y", "m", 0.0, -2.0, 2.0, "landing point, to the left (+) of the start"),
        Parameter("target_z", "m", 0.0, -1.0, 1.0,
                  "height of the surface landed on above the one the character starts on: > 0 onto a box, "
                  "< 0 down (the character starts on a box this high), 0 = on the ground"),
        Parameter("obstacle_height", "m", 0.0, 0.0, 1.0,
                  "a box this high (above the surface landed on) to jump over, halfway between the toes and "
                  "the target, 0.3 m deep; 0 = none"),
        Parameter("air_time", "s", 0.45, 0.05, 1.5, "time the feet are off the ground"),
        Parameter("windup_time", "s", 1.25, 0.75, 3.0, "time from the first move to lift-off"),
        Parameter("plan_trials", "count", 120, 0, 600,
                  "simulated trial jumps that 'python -m sim_core simulate' may run to plan a request that has "
                  "no stored plan, before the run (0 = only stored plans)"),
    )

    def request(self) -> dict:
        p = self.params
        request = {k: float(p[k]) for k in REQUEST_KEYS}
        request["strength"] = run_strength(self.ctx)
        return request

    @classmethod
    def scene(cls, params, world, character=None):
        return scene_for(character, (params["target_x"], params["target_y"], params["target_z"],
                                     params["obstacle_height"]), world)

    @classmethod
    def character_defaults(cls, character: str) -> dict:
        """The schema's (the leap's height is not a knob here): a target a body is not offered is
        refused naming its region (check_request)."""
        return {}

    @classmethod
    def duration_for(cls, params: dict, character: str, strength) -> float:
        """Longer by the turn's time when the request's stored plan turns first (turn.py)."""
        request = {**{k: float(params[k]) for k in REQUEST_KEYS},
                   "strength": "unlimited" if strength == "unlimited" else "human"}
        plan = stored_plan(character, request)
        return cls.default_duration + (turn_duration(plan["settings"].get("turn_first", 0.0),
                                                     plan["settings"].get("turn_angle", 0.0)) if plan else 0.0)

    def run_params(self) -> dict:
        return self.params

    def is_broad(self, p: dict) -> bool:
        return self.plan["settings"].get("vertical_thrust", 0.0) <= 0.5

    def flight_target(self, p: dict) -> tuple[tuple, float]:
        """The commanded take-off's flight (a plan with ``commanded_takeoff``): the request's, forward the
        plan's aim where it names one (commanded_flight)."""
        s = self.plan["settings"]
        return (s.get("flight_target_x", p["target_x"]), s.get("flight_target_y", p["target_y"]), p["target_z"]), p["air_time"]

    def check_feasible(self) -> None:
        """Refuses what no plan can do, then looks the plan up (planning runs above the loop)."""
        p, name = self.params, self.ctx.character.name
        plan = stored_plan(name, self.request())
        check_request(self.ctx.character, p, run_strength(self.ctx))
        if plan is None:
            raise ParameterError(f"no stored plan for this jump of {name}; plan it first with "
                                 f"'{plan_command(name, p)}' (or run it with 'python -m sim_core "
                                 f"simulate', which plans it first)")
        if not plan["found"]:
            m = plan["measured"]
            raise ParameterError(
                f"no jump of {name} found that lands within {LANDING_TOLERANCE * 100:.0f} cm of "
                f"({p['target_x']:g}, {p['target_y']:g}) m with air_time={p['air_time']:g} s "
                f"(+-{AIR_TIME_TOLERANCE:g} s) and ends balanced, in {plan['trials']} simulated trials; the "
                f"nearest landed at ({m['landing'][0]:.2f}, {m['landing'][1]:.2f}) m{_surface(m, p['target_z'])} "
                f"after {m['air_time']:.2f} s ({m['outcome']}); '{plan_command(name, p)} --budget N' searches on")
        self.plan = plan

    def settings(self, p: dict) -> dict:
        settings = {k: self.plan["settings"][k] for k in ("crouch_height", "crouch_pitch", "com_offset", "arm_swing",
                                                          "thrust_damping", "liftoff_hip", "foot_delta")}
        settings.update(optional_knobs(self.plan["settings"]))
        settings.update(turn_of(self.plan["settings"]))
        if self.plan["settings"].get("commanded_takeoff", 0.0) > 0.5:
            settings["commanded_takeoff"] = 1.0
            settings.update({k: self.plan["settings"][k] for k in ("lean_push",) if k in self.plan["settings"]})
        settings["crouch_time"] = crouch_time(self.params["windup_time"])
        settings.update(landing_settings(self.plan["settings"]))
        return settings

    @classmethod
    def assess(cls, trajectory):
        outcome, metrics = leap_assess(trajectory, start=jump_start(trajectory))
        measured = landing_measures(trajectory)
        p = trajectory.meta["params"]
        metrics["landing_x"], metrics["landing_y"] = measured["landing"]
        metrics["landing_error"] = float(math.hypot(measured["landing"][0] - p["target_x"],
                                                    measured["landing"][1] - p["target_y"]))
        metrics["air_time"] = measured["air_time"]          # the first flight (flight_time: to the last touchdown)
        metrics["air_time_error"] = measured["air_time"] - p["air_time"]
        metrics["windup_time"] = measured["windup_time"]
        return outcome, metrics


def _surface(measured: dict, target_z: float) -> str:
    """' on the box' / ' on the ground' where a raised target makes it matter."""
    if target_z <= 0:
        return ""
    return " on the box" if measured.get("landing_height", 0.0) > 0 else " on the ground"
