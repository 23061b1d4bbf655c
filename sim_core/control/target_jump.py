"""Jump to a target the animator places (Ooi 2015): a landing point, an air time, a wind-up time.

*Path estimation* (Ooi §3.4.1): the COM leaves the ground at the take-off point and must come
down at the touchdown point ``air_time`` later, so the take-off velocity is
``v = d / T + (0, 0, g T / 2)``. A request whose take-off speed is beyond what the character's
legs have ever given it (its strongest calibrated vertical leap) is refused before anything is
simulated, with the numbers.

*Planning by simulation*: Ooi moved the pelvis kinematically; here the leap's own controllers
do all the work (balance crouch, proximal-to-distal thrust, landing, balance - the leap of
leap.py, with the broad jump's or the vertical leap's thrust), so the wind-up pose, the lean
(forward or sideways), arm swing, lift-off hip angle and the landing's foot delta, foot lead and
arm swing in flight that land the feet on the target are found by searching over whole
simulated jumps (the cross-entropy method, seeded from the request, so the same request always
gives the same plan; it starts from the stored plan found nearest the target, or a prior; a
pattern search then walks the best balanced trial to the target).
Each trial is judged by what the simulation did: the middle of the feet at touchdown, the time
the feet were off the ground, and whether the jump ended balanced. The final run repeats the
best trial's settings - the same simulation - so its outcome is the plan's. Plans for the
usual targets are kept as data (rigs/tuned/jump_targets_<character>.json, written by
scripts/plan_jumps.py); any other request is planned when it is run (``plan_trials`` trials,
about half a second each). A raised target gets a box under it; a target below the start
(``target_z`` < 0) puts the character on a box with the ground that far below, and
``obstacle_height`` a box to clear on the way (Ooi's box -> over a second box -> ground; see
``scene_for``).
"""
from __future__ import annotations

import dataclasses
import json
import math
import sys
from pathlib import Path

import numpy as np

from sim_core.analysis import feet_above_surface, surface_under_points
from sim_core.ballistics import GRAVITY
from sim_core.control.behaviour import register
from sim_core.control.leap import (AIRBORNE_HEIGHT, TUNED_DIR, Leap, leap_assess, load_mapping, run_strength,
                                  vertical_key)
from sim_core.control.tuned import write_table
from sim_core.errors import ParameterError
from sim_core.schema import Parameter, Schema

# where the COM is, relative to the middle of the feet, at take-off and at touchdown of a broad
# jump (measured on the man's calibrated 1.0 m jump; used only for the path estimate)
TAKEOFF_COM = (0.30, 1.00)          # m ahead of the feet, m above them
TOUCHDOWN_COM = (-0.25, 0.90)       # m ahead of the feet (behind: the feet land in front), m above
WINDUP_OVERHEAD = 0.45              # s of the wind-up that are not the crouch: standing still, thrust
LANDING_TOLERANCE = 0.05            # m: landing point within this of the target
AIR_TIME_TOLERANCE = 0.05           # s
PLAN_MARGIN = 0.6                   # the search aims inside this share of the tolerances

# the leap's low-level settings the planner searches, with their ranges
KNOBS = {
    "crouch_height": (0.48, 0.80), "crouch_pitch": (0.0, 0.5), "com_offset": (0.0, 0.20),
    "liftoff_hip": (-0.2, 1.0), "vertical_thrust": (0.0, 1.0), "arm_swing": (0.5, 3.0), "damping": (0.3, 1.0),
    "foot_delta": (-0.15, 0.15), "swing_arms": (0.0, 1.0), "arm_flexion": (-1.0, 1.0),
    "foot_lead_time": (0.15, 0.35), "crouch_arms": (-0.8, 0.0),
}
KNOB_DEFAULTS = {"crouch_arms": 0.0, "liftoff_roll": 0.0,    # a knob a prior or a stored plan does not name
                 "thrust_lean": 0.0, "com_offset_y": 0.0,     # (arms hanging in the crouch, no lift-off roll,
                 "spin_hold": 0.0}                            # the thrust along poses balanced over the feet,
                                                              # no sideways lean, no hold on the twist); the
                                                              # leap's parameters by the same names
SIDEWAYS_KNOBS = {"com_offset_y": (-0.2, 0.2), "liftoff_roll": (-0.5, 0.5),   # searched only for a target off to
                  "com_offset": (-0.05, 0.20),     # the side; the lean ahead may go back a little (the woman's
                                                   # sideways jumps drifted 0.14-0.2 m forward)
                  "thrust_lean": (-0.15, 0.05),    # and the thrust may push back: her best 1.0 m jump left at
                                                   # 0.28 m/s forward whatever the crouch's offset; a thrust
                                                   # along poses with the COM 0.15 m behind the feet, 0.11 m/s
                  "spin_hold": (0.0, 0.3)}         # the hips may turn against the twist that the push at the
                                                   # forefeet gives (the woman's 1.3 m right left at -5.3 kg m²/s)
SIDEWAYS_PRIOR = {"crouch_height": 0.6, "crouch_pitch": 0.0, "com_offset": 0.0, "liftoff_hip": 0.6,
                  "arm_swing": 1.0, "damping": 0.3, "vertical_thrust": 1.0, "foot_lead_time": 0.3}
SIDEWAYS_LIFTOFF_ROLL = 0.3         # rad: where a sideways search starts, feet abducted away from the target at
                                    # lift-off (with none, the man's 1.0 m jump left rolling at 4 kg m^2/s and
                                    # rolled to 59 deg by touchdown; 0.4 rad: -3)
BOX_PRIOR = {"crouch_height": 0.55, "crouch_pitch": 0.0, "com_offset": 0.12, "liftoff_hip": 0.8,
             "arm_swing": 1.0, "damping": 0.3, "vertical_thrust": 1.0, "crouch_arms": -0.6}
                                    # where a box jump's search starts: the deep vertical leap of the
                                    # calibrated table (low thrust damping, the hips extending at lift-off
                                    # to cancel its spin), leaning forward, the arms back so that the
                                    # hands stay off the ground in the deep crouch
BROAD_PRIOR = {"crouch_height": 0.655, "crouch_pitch": 0.0, "com_offset": 0.1, "liftoff_hip": 0.3,
               "arm_swing": 1.0, "damping": 1.0, "vertical_thrust": 0.0}   # a ground target's, with no broad jump
LANDING_PRIOR = {"foot_delta": 0.0, "swing_arms": 0.0, "arm_flexion": 0.6, "foot_lead_time": 0.2}


GROUND_AIR_TIME = 0.45              # s: the air time the report asks of a jump to a target on the
                                    # ground, and the broad jump's planned jumps (a standing broad jump's)
SIDEWAYS_AIR_TIME = 0.6             # s: the report's sideways jumps. The legs push sideways only along their
                                    # lean (at most ~0.6 m/s sideways per m/s up, measured on the man): asked
                                    # in 0.45 s, 150-1,050 trials per target: those that reached it flew 0.59-0.82 s
BOX_DISTANCE, BOX_AIR_TIME = 0.8, 0.6   # m, s: the report's jumps onto a box: its middle this far ahead
                                    # (its near edge 0.5 m ahead, clear of the knees in a deep crouch)
REFINE_SHARE = 0.4                  # share of a search's trials kept for refining the best balanced trial


def search_prior(character: str, target) -> dict:
    """Where the search starts without a stored plan nearby: on the ground, the calibrated broad
    jump nearest the distance (leap.py's mapping, itself planned), or BROAD_PRIOR; onto a box, a
    deep vertical leap leaning forward with the hips extending at lift-off; with the landing's
    defaults."""
    mapping = load_mapping(character)
    if abs(target[1]) > 1e-9:
        prior = {**LANDING_PRIOR, **SIDEWAYS_PRIOR, "com_offset_y": math.copysign(0.17, target[1]),
                 "liftoff_roll": math.copysign(SIDEWAYS_LIFTOFF_ROLL, -target[1])}
    elif target[2] > 0:
        prior = dict(BOX_PRIOR, **LANDING_PRIOR)
    else:
        broad = mapping["broad"]
        distance = float(np.hypot(target[0], target[1]))
        if broad.get("settings"):
            k = int(np.argmin(np.abs(np.asarray(broad["com_travel"]) - distance)))
            prior = dict(broad["settings"][k])
        else:
            prior = dict(BROAD_PRIOR, **LANDING_PRIOR)
    knobs = knobs_for(target)
    prior = {**KNOB_DEFAULTS, **prior}
    return {n: min(max(float(prior[n]), knobs[n][0]), knobs[n][1]) for n in knobs}


def knobs_for(target) -> dict:
    """The settings searched for this target (sideways ones only for a target off to the side)."""
    return {**KNOBS, **SIDEWAYS_KNOBS} if abs(float(target[1])) > 1e-9 else dict(KNOBS)


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


def takeoff_capacity(character: str, key: str) -> float:
    """The fastest take-off (m/s) the character's calibrated vertical leaps reach."""
    rises = load_mapping(character).get(key, {}).get("com_rise", [])
    return math.sqrt(2.0 * GRAVITY * max(rises)) if rises else 0.0


BOX_LENGTH, BOX_WIDTH = 0.6, 1.0    # m: a box under a raised target, centred on it
START_BOX_LENGTH = 0.6              # m: the box a jump down starts on, its front edge just ahead of the toes
START_BOX_EDGE = 0.02               # m ahead of the toes
OBSTACLE_LENGTH = 0.3               # m: a box to jump over, centred between the start and the target


def obstacle_of(target) -> float:
    """The height of the box to jump over (m above the surface landed on) of a target (x, y, z[,
    obstacle height])."""
    return float(target[3]) if len(target) > 3 else 0.0


def scene_for(character, target, world=None):
    """The world of a jump to ``target`` (x, y, z[, obstacle height]) m: the requested one, plus a
    box under a raised target (z > 0); for a target below the start (z < 0) the ground at z and a
    box the character starts on (its top at 0, its front edge just ahead of the toes); and a box
    to jump over, standing on the surface landed on halfway between the toes and the target."""
    from sim_core.world import World
    from sim_core.character.spec import load_character
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
    feet at touchdown and whether the jump fell before it left the ground."""
    a = trajectory.arrays
    feet = a["support_points"]
    flying = feet_above_surface(trajectory).min(axis=1) > AIRBORNE_HEIGHT
    outcome, metrics = leap_assess(trajectory)
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
        result["windup_time"] = float(metrics["liftoff_time"])
        result["air_time"] = float(a["time"][touchdown] - a["time"][first])
        middle = feet[touchdown].mean(axis=0)
        com, velocity = a["com"][touchdown], a["com_vel"][touchdown]
        capture = com[:2] + velocity[:2] * math.sqrt(max(com[2] - middle[2], 0.1) / GRAVITY)
        result["capture_error"] = float(np.linalg.norm(capture - middle[:2]))
    return result


CAPTURE_SCALE = 0.1                 # m of capture-point error that cost a fallen trial as much as a tolerance
UNBALANCED_PRICE = 20.0             # cost of a trial that does not end balanced (and again if it fell
                                    # before lift-off, e.g. hands down in the crouch)


def trial_cost(measured: dict, target, air_time: float) -> float:
    """Tolerances used: landing error and air-time error in units of their tolerances, plus a
    fixed price for not ending balanced; a trial that did not end balanced also pays for its
    capture point's distance from the feet at touchdown (so that, before any trial balances,
    the search moves towards landings with the COM over the feet, not only towards the target)."""
    landing = np.asarray(measured["landing"], dtype=float)
    if not np.isfinite(landing).all():
        return 1e3
    error = float(np.linalg.norm(landing - np.asarray(target[:2], dtype=float)))
    error += abs(measured.get("landing_height", 0.0) - float(target[2]))      # landed on the wrong surface
    cost = error / LANDING_TOLERANCE + abs(measured["air_time"] - air_time) / AIR_TIME_TOLERANCE
    if measured["outcome"] == "success":
        return cost
    capture = measured.get("capture_error", 0.0)
    cost += UNBALANCED_PRICE + (capture / CAPTURE_SCALE if math.isfinite(capture) else UNBALANCED_PRICE)
    return cost + (UNBALANCED_PRICE if measured.get("fell_before_liftoff") else 0.0)


def within_tolerance(measured: dict, target, air_time: float, margin: float = 1.0) -> bool:
    landing = np.asarray(measured["landing"], dtype=float)
    return (measured["outcome"] == "success" and np.isfinite(landing).all()
            and float(np.linalg.norm(landing - np.asarray(target[:2], dtype=float))) <= LANDING_TOLERANCE * margin
            and abs(measured["air_time"] - air_time) <= AIR_TIME_TOLERANCE * margin
            and abs(measured.get("landing_height", 0.0) - float(target[2])) < 0.01)


def leap_params(settings: dict, target, windup_time: float) -> dict:
    """The leap's low-level parameters for these settings (the planner's trials run the leap; a
    vertical-leap thrust when ``vertical_thrust``, else the broad jump's)."""
    vertical = settings["vertical_thrust"] > 0.5
    return {"low_level": 1, "distance": 0.0 if vertical else max(float(target[0]), 0.05),
            "crouch_height": settings["crouch_height"], "crouch_pitch": settings["crouch_pitch"],
            "com_offset": settings["com_offset"], **optional_knobs(settings),
            "liftoff_hip_angle": settings["liftoff_hip"],
            "arm_swing": settings["arm_swing"], "thrust_damping": settings["damping"],
            "foot_delta": settings["foot_delta"], "crouch_time": crouch_time(windup_time),
            **{"landing_" + k: v for k, v in landing_settings(settings).items()}}


def optional_knobs(settings: dict) -> dict:
    """The knobs that a plan may not name (KNOB_DEFAULTS), with their defaults where it does not."""
    return {name: settings.get(name, default) for name, default in KNOB_DEFAULTS.items()}


def landing_settings(settings: dict) -> dict:
    """The landing's settings among the planner's (the leap passes them to its landing)."""
    return {"swing_arms": float(settings["swing_arms"] > 0.5), "arm_flexion": settings["arm_flexion"],
            "foot_lead_time": settings["foot_lead_time"],
            "place_sideways": float(abs(settings.get("com_offset_y", 0.0)) > 0.0)}


def crouch_time(windup_time: float) -> float:
    return max(windup_time - WINDUP_OVERHEAD, 0.3)


def plan_jump(character: str, target, air_time: float, windup_time: float, strength="human",
              trials: int = 120, population: int = 12, elite: int = 4, progress=None, restart: int = 0,
              start: dict | None = None) -> dict:
    """Search the leap's settings for a jump that lands the middle of the feet on ``target`` in
    ``air_time`` and ends balanced. Two stages share the ``trials``: the cross-entropy method
    over all the settings, starting from the best trial of an earlier search for the same
    request, else the stored plan found nearest the target (continuation: a longer jump starts
    from a shorter one), else the prior; then a pattern search from the best balanced trial
    (REFINE_SHARE of the trials). The landing point is not smooth in the settings - a balanced
    jump's neighbours often fall - so the population finds the balanced region and the pattern
    search walks along it, one setting at a time, to the target. An earlier search's best is kept
    if this one does no better; the trial counts add up. ``restart`` > 0 starts a fresh search
    instead of continuing an earlier one that got stuck: from the stored plan found nearest the
    target (else the prior), with the random stream of that restart number. ``start`` (settings,
    e.g. a trial found by a hand-run scan) overrides where the search starts.
    Returns {"settings", "measured", "trials", "found"}."""

    knobs = knobs_for(target)
    names = list(knobs)
    low = np.array([knobs[n][0] for n in names])
    high = np.array([knobs[n][1] for n in names])
    fallback = search_prior(character, target)
    previous = stored_plan(character, {"target_x": float(target[0]), "target_y": float(target[1]),
                                       "target_z": float(target[2]), "obstacle_height": obstacle_of(target),
                                       "air_time": air_time, "windup_time": windup_time, "strength": strength})
    if restart:
        found = nearest_start_plan(character, target, strength)
        prior = found[1] if found else fallback
    else:
        prior = search_start(character, target, previous, strength) or fallback
    prior = {**prior, **(start or {})}
    mean = np.array([float(prior.get(n, fallback[n])) for n in names])
    std = 0.25 * (high - low)
    rng = np.random.default_rng([_stable_seed(target, air_time, windup_time), restart] if restart
                                else _stable_seed(target, air_time, windup_time))
    tried = []          # (cost, x, settings, measured) of every trial, in order

    def trial(x) -> tuple:
        settings = {n: float(v) for n, v in zip(names, x)}
        measured = measure_settings(character, settings, target, air_time, windup_time, strength)
        tried.append((trial_cost(measured, target, air_time), np.asarray(x, dtype=float), settings, measured))
        if progress:
            progress(len(tried), trials, best()[3])
        return tried[-1]

    def best(balanced=False):
        pool = [t for t in tried if t[3]["outcome"] == "success"] if balanced else tried
        return min(pool or tried, key=lambda item: item[0])

    def done() -> bool:
        return bool(tried) and within_tolerance(best()[3], target, air_time, PLAN_MARGIN)

    population_trials = trials - int(REFINE_SHARE * trials) if trials >= 2 * population else trials
    while len(tried) < population_trials and not done():
        batch = []
        for k in range(min(population, population_trials - len(tried))):
            x = mean if not tried else np.clip(mean + std * rng.standard_normal(len(names)), low, high)
            batch.append(trial(x))
            if done():
                break
        batch.sort(key=lambda item: item[0])
        chosen = np.array([item[1] for item in batch[:elite]])
        mean = 0.5 * mean + 0.5 * chosen.mean(axis=0)
        std = np.maximum(0.5 * std + 0.5 * chosen.std(axis=0), 0.02 * (high - low))
    _pattern_search(trial, best, done, low, high, trials - len(tried))
    cost, _, settings, measured = best()
    if previous and trial_cost(previous["measured"], target, air_time) <= cost:
        settings, measured = previous["settings"], previous["measured"]     # the earlier search did better
    return {"settings": settings, "measured": measured, "trials": len(tried) + (previous or {}).get("trials", 0),
            "found": within_tolerance(measured, target, air_time)}


def measure_settings(character: str, settings: dict, target, air_time: float, windup_time: float,
                     strength="human") -> dict:
    """Run the leap with a plan's ``settings`` toward ``target`` (x, y, z, obstacle height) and read
    the landing off it (landing_measures): one trial of the planner, or a stored plan measured
    again. Judged over the run's whole default duration, as the final run is (a foot still creeping
    after the landing passed at 3.85 s and stepped past 5 cm by 5 s)."""
    from sim_core.simulate import RunRequest, run
    duration = max(windup_time + air_time + 2.0, JumpToTarget.default_duration)
    trajectory = run(RunRequest("leap", character, params=leap_params(settings, target, windup_time),
                                duration=duration, strength=strength, world=scene_for(character, target)))
    return landing_measures(trajectory)


def _pattern_search(trial, best, done, low, high, budget: int) -> None:
    """Compass search from the best balanced trial: each setting in turn one step up, then down;
    a move is kept when it lowers the cost; after a sweep with no move the steps halve (from 5 %
    of each range down to 0.5 %)."""
    if budget <= 0 or done():
        return
    step = 0.05 * (high - low)
    centre = best(balanced=True)
    left = budget
    while left > 0 and not done() and (step >= 0.005 * (high - low)).all():
        moved = False
        for i in range(len(step)):
            for sign in (1.0, -1.0):
                if left <= 0 or done():
                    return
                x = centre[1].copy()
                x[i] = min(max(x[i] + sign * step[i], low[i]), high[i])
                if x[i] == centre[1][i]:
                    continue
                left -= 1
                candidate = trial(x)
                if candidate[0] < centre[0]:
                    centre, moved = candidate, True
                    break
        if not moved:
            step = 0.5 * step


def _stable_seed(target, air_time: float, windup_time: float) -> int:
    """A seed from the request's numbers (Python's hash of floats is stable, but be explicit); an
    obstacle counts only where there is one (so a request without one seeds as it always did)."""
    obstacle = [obstacle_of(target)] if obstacle_of(target) else []
    values = [round(float(v) * 1000) for v in (*target[:3], air_time, windup_time, *obstacle)]
    seed = 17
    for v in values:
        seed = (seed * 1_000_003 + v) % (2 ** 31)
    return seed


def plans_path(character: str) -> Path:
    return TUNED_DIR / f"jump_targets_{character}.json"


def stored_plans(character: str) -> list[dict]:
    """Every plan stored for ``character`` (none if its file does not exist yet)."""
    path = plans_path(character)
    return json.loads(path.read_text())["plans"] if path.exists() else []


def stored_plan(character: str, request: dict) -> dict | None:
    return next((plan for plan in stored_plans(character) if same_request(plan["request"], request)), None)


REQUEST_KEYS = ("target_x", "target_y", "target_z", "obstacle_height", "air_time", "windup_time")


def same_request(a: dict, b: dict) -> bool:
    """(A plan stored before obstacles existed has no obstacle_height: none.)"""
    return (all(abs(a.get(k, 0.0) - b.get(k, 0.0)) < 1e-6 for k in REQUEST_KEYS)
            and a.get("strength", "human") == b.get("strength", "human"))


def store_plan(character: str, request: dict, plan: dict, script: str) -> None:
    """Keep a plan (found or not) in rigs/tuned/jump_targets_<character>.json, replacing the one
    for the same request."""
    stored = [p for p in stored_plans(character) if not same_request(p["request"], request)]
    stored.append({"request": request, **plan})
    stored.sort(key=lambda p: tuple(p["request"].get(k, 0.0) for k in REQUEST_KEYS))
    write_table(plans_path(character), {"character": character, "script": script, "plans": stored})


def _side(y: float) -> int:
    return 0 if abs(y) < 1e-9 else (1 if y > 0 else -1)


def search_start(character: str, target, previous: dict | None, strength="human") -> dict | None:
    """Where a search starts: the settings of the stored plan found nearest ``target``
    (nearest_start_plan), or of an earlier search's best trial for this very request
    (``previous``) if that ended balanced nearer the target (None if neither)."""
    found = nearest_start_plan(character, target, strength)
    if previous is None or previous["measured"]["outcome"] != "success":
        return found[1] if found else (previous or {}).get("settings")
    miss = math.dist(previous["measured"]["landing"], [float(v) for v in target[:2]])
    return found[1] if found and found[0] < miss else previous["settings"]


def nearest_start_plan(character: str, target, strength="human") -> tuple[float, dict] | None:
    """(distance, settings) of the stored plan a search for ``target`` starts from: the one found
    onto the same height and to the same side nearest it; with none, for a jump down the nearest
    forward jump on the ground, for a jump onto a box the nearest found onto another box."""
    found = nearest_found_plan(character, target, strength)
    if found is None and target[2] < 0:
        found = nearest_found_plan(character, (target[0], target[1], 0.0), strength)
    if found is None and target[2] > 0:
        found = nearest_found_plan(character, target, strength, raised=True)
    return found


def nearest_found_plan(character: str, target, strength="human", raised=False) -> tuple[float, dict] | None:
    """(distance, settings) of the stored plan that found a jump onto the same height (``raised``:
    onto any box) and to the same side, nearest ``target`` (None if there is none)."""
    plans = [p for p in stored_plans(character)
             if p["found"] and p["request"].get("strength", "human") == strength
             and (p["request"]["target_z"] > 0 if raised else abs(p["request"]["target_z"] - float(target[2])) < 1e-6)
             and abs(p["request"].get("obstacle_height", 0.0) - obstacle_of(target)) < 1e-6
             and _side(p["request"]["target_y"]) == _side(float(target[1]))]
    if not plans:
        return None
    def distance(p):        # nearest; of two as near, the longer jump (shortening one is easier)
        where = (p["request"]["target_x"], p["request"]["target_y"], p["request"]["target_z"])
        return round(math.dist(where, tuple(float(v) for v in target[:3])), 6), -math.hypot(*where[:2])
    nearest = min(plans, key=distance)
    return distance(nearest)[0], dict(nearest["settings"])


@register
class JumpToTarget(Leap):
    name = "jump_to_target"
    world_frame = True             # turns / aims in the world's X-Z plane from the origin
    summary = ("Jump so that the feet land on a target point, with a given air time and wind-up time "
               "(Ooi 2015), by the leap and landing controllers; the settings are planned by simulation.")
    default_duration = 5.0
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
                  "simulated trial jumps the planner may run for a request that has no stored plan "
                  "(0 = only stored plans)"),
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

    def run_params(self) -> dict:
        return self.params

    def is_broad(self, p: dict) -> bool:
        return self.plan["settings"].get("vertical_thrust", 0.0) <= 0.5

    def check_feasible(self) -> None:
        p = self.params
        name = self.ctx.character.name
        target = np.array([p["target_x"], p["target_y"], p["target_z"], p["obstacle_height"]])
        if p["obstacle_height"] > 0.0:
            gap = p["target_x"] - (toe_tip(self.ctx.character) - start_feet_centre(self.ctx.character)[0])
            if p["target_z"] > 0.0 or gap < OBSTACLE_LENGTH + 0.4:
                raise ParameterError(
                    f"parameter obstacle_height={p['obstacle_height']:g} m: a box to jump over needs a target on "
                    f"the ground or below (target_z <= 0, is {p['target_z']:g}) at least "
                    f"{OBSTACLE_LENGTH + 0.4:.1f} m ahead of the toes (is {gap:.2f} m); allowed range of "
                    f"obstacle_height is [0, 1] m, 0 = none")
        if p["target_x"] < 0.0 or (p["target_x"] == 0.0 and p["target_y"] == 0.0):
            raise ParameterError(f"parameter target_x={p['target_x']:g} m: the jump goes forward or sideways, "
                                 f"not back or on the spot; allowed range is [0, 2.5] m, with target_x or "
                                 f"target_y not 0")
        velocity = path_estimate(target[:3], p["air_time"])
        capacity = takeoff_capacity(name, vertical_key(self.ctx))
        speed = float(np.linalg.norm(velocity))
        if speed > capacity:
            raise ParameterError(
                f"target ({p['target_x']:g}, {p['target_y']:g}, {p['target_z']:g}) m in air_time={p['air_time']:g} s "
                f"needs a take-off at {speed:.2f} m/s (path estimate: {velocity[0]:.2f} forward, "
                f"{velocity[2]:.2f} up); the strongest take-off of {name} is {capacity:.2f} m/s - "
                f"allow a longer or shorter air time, or a nearer target")
        request = self.request()
        plan = stored_plan(name, request)
        if plan is None:
            if p["plan_trials"] < 1:
                raise ParameterError(f"no stored plan for this jump of {name} and plan_trials=0; allowed range "
                                     f"of plan_trials is [1, 600] to plan it now (scripts/plan_jumps.py stores plans)")
            plan = plan_jump(name, tuple(target), p["air_time"], p["windup_time"], request["strength"],
                             trials=int(p["plan_trials"]), progress=_print_progress)
        if not plan["found"]:
            m = plan["measured"]
            raise ParameterError(
                f"no jump of {name} found that lands within {LANDING_TOLERANCE * 100:.0f} cm of "
                f"({p['target_x']:g}, {p['target_y']:g}) m with air_time={p['air_time']:g} s "
                f"(+-{AIR_TIME_TOLERANCE:g} s) and ends balanced, in {plan['trials']} simulated trials; the "
                f"nearest landed at ({m['landing'][0]:.2f}, {m['landing'][1]:.2f}) m{_surface(m, p['target_z'])} "
                f"after {m['air_time']:.2f} s ({m['outcome']})")
        self.plan = plan

    def settings(self, p: dict) -> dict:
        settings = {k: self.plan["settings"][k] for k in ("crouch_height", "crouch_pitch", "com_offset", "arm_swing",
                                                          "damping", "liftoff_hip", "foot_delta")}
        settings.update(optional_knobs(self.plan["settings"]))
        settings["crouch_time"] = crouch_time(self.params["windup_time"])
        settings.update(landing_settings(self.plan["settings"]))
        return settings

    @classmethod
    def assess(cls, trajectory):
        outcome, metrics = leap_assess(trajectory)
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


def _print_progress(done: int, total: int, best: dict) -> None:
    if done % 12 == 0 or done == total:
        print(f"planning the jump: {done}/{total} trials, nearest so far lands at "
              f"({best['landing'][0]:.2f}, {best['landing'][1]:.2f}) m after {best['air_time']:.2f} s "
              f"({best['outcome']})", file=sys.stderr, flush=True)
