"""Planning a jump to a target (Ooi 2015) by simulation, above the simulation loop.

The jump_to_target behaviour (sim_core/skills/jump_to_target/behaviour.py) only runs a plan; this module
finds one: it searches the leap's settings (the wind-up pose, the lean, arm swing, lift-off hip
angle and the landing's foot delta, foot lead and arm swing in flight) over whole simulated
jumps, each trial a ``simulate.run`` of the leap, judged by what the simulation did (the middle of
the feet at touchdown, the time the feet were off the ground, whether the jump ended balanced).
On flat ground without an obstacle a request is planned from the character's measured jumps
(plan_from_model; the jump_model table, python -m sim_core.planning.jump_model): the nearest
measured balanced jump, then blends towards near ones, at most MODEL_TRIALS trials. Elsewhere the
search is the search service's (sim_core.tuning): CMA-ES over every setting from the request's
start (the best trial of an earlier search for the same request, else the stored plan found
nearest the target, else a prior), then CMA-ES again with a short step from the best balanced
trial (REFINE_SHARE of the budget): the landing point is not smooth in the settings - a balanced
jump's neighbours often fall - so the first stage finds the balanced region and the second walks
along it to the target. The seed comes from the request, so the same request always gives the
same plan, with one worker or many. The final run repeats the best trial's settings - the same
simulation - so its outcome is the plan's.

``plan_jump`` takes ``progress`` and ``cancelled`` callables (the Blender operator's status bar
and Esc): a cancel raises ``Cancelled`` within a trial's tick check and nothing is stored.
``plan_and_store`` keeps the plan in the user's plan store (skills.jump_to_target.behaviour.plan_store_dir),
where later runs find it; ``store_plan`` writes the shipped table (python -m sim_core calibrate jump_to_target).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from ..character.spec import load_character
from ..control.leap import LEAP_SETTINGS, blend_rows, load_mapping
from ..control.turn import turn_duration
from ..skills.jump_to_target.behaviour import AIR_TIME_TOLERANCE, KNOB_DEFAULTS, LANDING_TOLERANCE, REQUEST_KEYS, JumpToTarget, check_request, landing_measures, leap_params, obstacle_of, plan_store_dir, read_plans, same_request, scene_for, stored_plan, stored_plans, turn_of
from .. import tuned
from ..errors import ParameterError
from ..simulate import RunRequest, run
from ..tuning import SerialExecutor, Space, minimize
from ..skills.jump_to_target.region import REACH, mode, model, nearest_balanced
from .commanded import plan_commanded
from .land import candidates as foot_candidates, foot_step
from .trials import Trials

PLAN_MARGIN = 0.6                   # the search aims inside this share of the tolerances

# the leap's low-level settings the planner searches, with their ranges
KNOBS = {
    "crouch_height": (0.48, 0.80), "crouch_pitch": (0.0, 0.5), "com_offset": (0.0, 0.20),
    "liftoff_hip": (-0.2, 1.0), "vertical_thrust": (0.0, 1.0), "arm_swing": (0.5, 3.0), "thrust_damping": (0.3, 1.0),
    "foot_delta": (-0.15, 0.15), "landing_swing_arms": (0.0, 1.0), "landing_arm_flexion": (-1.0, 1.0),
    "landing_foot_lead_time": (0.15, 0.35), "crouch_arms": (-0.8, 0.0),
}

SIDEWAYS_KNOBS = {"com_offset_y": (-0.2, 0.2), "liftoff_roll": (-0.5, 0.5),   # searched only for a target off to
                  "com_offset": (-0.05, 0.20),     # the side; the lean ahead may go back a little (the woman's
                                                   # sideways jumps drifted 0.14-0.2 m forward)
                  "thrust_lean": (-0.15, 0.05),    # and the thrust may push back: her best 1.0 m jump left at
                                                   # 0.28 m/s forward whatever the crouch's offset; a thrust
                                                   # along poses with the COM 0.15 m behind the feet, 0.11 m/s
                  "spin_hold": (0.0, 0.3)}         # the hips may turn against the twist that the push at the
                                                   # forefeet gives (the woman's 1.3 m right left at -5.3 kg m²/s)
SIDEWAYS_PRIOR = {"crouch_height": 0.6, "crouch_pitch": 0.0, "com_offset": 0.0, "liftoff_hip": 0.6,
                  "arm_swing": 1.0, "thrust_damping": 0.3, "vertical_thrust": 1.0, "landing_foot_lead_time": 0.3}
SIDEWAYS_LIFTOFF_ROLL = 0.3         # rad: where a sideways search starts, feet abducted away from the target at
                                    # lift-off (with none, the man's 1.0 m jump left rolling at 4 kg m^2/s and
                                    # rolled to 59 deg by touchdown; 0.4 rad: -3)
BOX_PRIOR = {"crouch_height": 0.55, "crouch_pitch": 0.0, "com_offset": 0.12, "liftoff_hip": 0.8,
             "arm_swing": 1.0, "thrust_damping": 0.3, "vertical_thrust": 1.0, "crouch_arms": -0.6}
                                    # where a box jump's search starts: the deep vertical leap of the
                                    # calibrated table (low thrust damping, the hips extending at lift-off
                                    # to cancel its spin), leaning forward, the arms back so that the
                                    # hands stay off the ground in the deep crouch
BROAD_PRIOR = {"crouch_height": 0.655, "crouch_pitch": 0.0, "com_offset": 0.1, "liftoff_hip": 0.3,
               "arm_swing": 1.0, "thrust_damping": 1.0, "vertical_thrust": 0.0}   # a ground target's, with no broad jump
LANDING_PRIOR = {"foot_delta": 0.0, "landing_swing_arms": 0.0, "landing_arm_flexion": 0.6, "landing_foot_lead_time": 0.2}


MODEL_TRIALS = 6                    # at most this many trials a flat-ground request planned from the measured
                                    # jumps runs (about 1.5 s each)
FOOT_TRIALS = 12                    # definition: then at most this many more, the feet of the trial that landed
                                    # on the target and fell placed a step (planning.land.foot_step) more and less
NEIGHBOURS = 8                      # measured balanced jumps its trials start from or blend towards
REFINE_SHARE = 0.4                  # share of a search's trials kept for refining the best balanced trial
POPULATION = 12                     # trials per batch of the first stage (CMA-ES's population)
FIRST_STEP = 0.25                   # the first stage's step, as a share of each setting's range
REFINE_STEP = 0.05                  # the refining stage's step (the pattern search it replaced began at 5 %)
REFINE_POPULATION = 6

def search_prior(character: str, target) -> dict:
    """Where the search starts without a stored plan nearby: on the ground, the calibrated broad
    jump nearest the distance (leap.py's mapping, itself planned), or BROAD_PRIOR; onto a box, a
    deep vertical leap leaning forward with the hips extending at lift-off; with the landing's
    defaults."""
    mapping = load_mapping(character)
    if _side(target[0], target[1]):
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
    return measured["outcome"] == "success" and lands_on(measured, target, air_time, margin)


def lands_on(measured: dict, target, air_time: float, margin: float = 1.0) -> bool:
    """Whether a trial landed on the target in the air time asked, within the tolerances (balanced or not)."""
    landing = np.asarray(measured["landing"], dtype=float)
    return (np.isfinite(landing).all()
            and float(np.linalg.norm(landing - np.asarray(target[:2], dtype=float))) <= LANDING_TOLERANCE * margin
            and abs(measured["air_time"] - air_time) <= AIR_TIME_TOLERANCE * margin
            and abs(measured.get("landing_height", 0.0) - float(target[2])) < 0.01)


def plan_jump(character: str, target, air_time: float, windup_time: float, strength: str = "human",
              budget: int = 120, progress: Callable | None = None, cancelled: Callable[[], bool] | None = None,
              executor=None, restart: int = 0, start: dict | None = None) -> dict:
    """Search the leap's settings for a jump of ``character`` (a name) that lands the middle of the
    feet on ``target`` (x, y, z[, obstacle height]) m in ``air_time`` s after a wind-up of
    ``windup_time`` s and ends balanced, in at most ``budget`` simulated trials.

    Two stages share the budget (see the module's docstring). An earlier search's best (a stored
    plan for this request, found or not) is kept if this one does no better; the trial counts add
    up. ``restart`` > 0 starts a fresh search instead of continuing an earlier one that got stuck:
    from the stored plan found nearest the target (else the prior), with that restart's seed.
    ``start`` (settings, e.g. a trial found by a hand-run scan) overrides where the search starts.
    ``progress(done, budget, best_measured)`` after every batch; ``cancelled()`` -> True raises
    sim_core.errors.Cancelled (in-process trials check it every 50 ticks); ``executor``: where the
    trials run (default: serially in this process; sim_core.tuning.LocalPool for a process pool).
    Returns {"settings", "measured", "trials", "found"}; stores nothing (plan_and_store does)."""
    target = tuple(float(v) for v in target) + ((0.0,) if len(target) == 3 else ())
    if not isinstance(budget, int) or budget < 1:
        raise_budget(budget)
    # a target the commanded take-off serves is planned so, also one to the side a stored plan turning first is near
    commanded = not obstacle_of(target) and strength == "human" and not restart and start is None \
        and mode(character, target, air_time) == "commanded"
    turned = turned_start(character, target, strength) if not restart and start is None and not commanded else None
    if commanded:
        # outside the measured jumps' region, inside the commanded take-off's (skills/jump_to_target/commanded.py)
        trial = JumpTrial(character, target, air_time, windup_time, strength, cancelled)
        return plan_commanded(character, target, air_time, trial, budget,
                              lambda measured: (lands_on(measured, target, air_time),
                                                within_tolerance(measured, target, air_time)),
                              progress, cancelled)
    if not obstacle_of(target) and strength == "human" and not restart and start is None and turned is None \
            and model(character) is not None and (target[2] == 0 or nearest_balanced(character, target, air_time)):
        # on flat ground, or onto / down from a box a measured jump serves: from the measured jumps (jump_model)
        trial = JumpTrial(character, target, air_time, windup_time, strength, cancelled)
        return plan_from_model(character, target, air_time, trial, budget, progress, cancelled)
    space = Space(knobs_for(target))
    fallback = search_prior(character, target)
    previous = stored_plan(character, request_of(target, air_time, windup_time, strength))
    if restart:
        found = nearest_start_plan(character, target, strength)
        prior = found[1] if found else fallback
    else:
        prior = search_start(character, target, previous, strength) or fallback
    if start:      # settings as a plan stores them: a knob they do not name is its default, as when the plan runs
        prior = {**prior, **KNOB_DEFAULTS, **start}
    fixed = turn_of(prior)          # a plan that turns first is searched turning as it did (the turn is not searched),
    if fixed:                       # from the jump it ran: a knob it does not name at its default, not the prior's
        prior = {**KNOB_DEFAULTS, **prior}
    first = {n: min(max(float(prior.get(n, fallback[n])), lo), hi) for n, (lo, hi) in space.bounds().items()}
    seed = _stable_seed(target, air_time, windup_time) + 7919 * restart
    executor = executor or SerialExecutor()
    trial = JumpTrial(character, target, air_time, windup_time, strength,
                      cancelled if getattr(executor, "in_process", False) else None, fixed)

    def good_enough(evaluation) -> bool:
        return within_tolerance(evaluation.extra, target, air_time, PLAN_MARGIN)

    def report(offset: int):
        if progress is None:
            return None
        return lambda done, total, best: progress(offset + done, budget, best.extra)

    broad_budget = budget - int(REFINE_SHARE * budget) if budget >= 2 * POPULATION else budget
    tried = minimize(trial, space, "cma", broad_budget, seed, start=first, sigma=FIRST_STEP,
                     population=POPULATION, progress=report(0), cancelled=cancelled, stop=good_enough,
                     executor=executor).evaluations
    if len(tried) < budget and not good_enough(min(tried, key=lambda e: e.score)):
        centre = _best(tried, balanced=True)
        tried = tried + minimize(trial, space, "cma", budget - len(tried), seed + 1, start=centre.settings,
                                 sigma=REFINE_STEP, population=REFINE_POPULATION, progress=report(len(tried)),
                                 cancelled=cancelled, stop=good_enough, executor=executor).evaluations
    best = _best(tried)
    settings, measured = {**best.settings, **fixed}, best.extra
    if previous and trial_cost(previous["measured"], target, air_time) <= best.score:
        settings, measured = previous["settings"], previous["measured"]     # the earlier search did better
    return {"settings": settings, "measured": measured, "trials": len(tried) + (previous or {}).get("trials", 0),
            "found": within_tolerance(measured, target, air_time)}


def candidates(near: list[tuple[float, dict]], target, air_time: float):
    """The settings a request's trials run, in order: the measured balanced jump nearest the request,
    then that jump blended (control.leap.blend_rows) towards each other near one that landed on the
    other side of the target, by the share of the way that puts the landing on the target if the
    landing is linear in the settings between them (interpolation of the measured data), then the
    other measured jumps within REACH of the request; onto or down from a box those before the
    blends (a jump moved from the height it was measured for lands balanced or not: another is a
    fresh chance)."""
    first = near[0][1]
    yield first["settings"]
    others = [p["settings"] for d, p in near[1:] if d <= REACH]     # other measured jumps doing the request
    if len(target) > 2 and float(target[2]):
        yield from others         # a box: each moved from another height is a fresh chance (a knife edge in height)
    x0, t0 = first["measured"]["landing"][0], first["measured"]["air_time"]
    for _, other in near[1:]:
        x1, t1 = other["measured"]["landing"][0], other["measured"]["air_time"]
        if (x1 - x0) * (float(target[0]) - x0) <= 0 or abs(x1 - x0) < 1e-3:
            continue
        w = min(max((float(target[0]) - x0) / (x1 - x0), 0.0), 1.0)
        yield blend_rows(first["settings"], other["settings"], w)
    if not (len(target) > 2 and float(target[2])):
        yield from others


def plan_from_model(character: str, target, air_time: float, trial, budget: int, progress=None,
                    cancelled=None) -> dict:
    """Plan a jump from the measured jumps: run candidates() one by one (``trial``:
    planning.jump.JumpTrial for the request) until one lands within the tolerances and balanced, at
    most min(budget, MODEL_TRIALS) of them; if none did but one landed on the target and fell, its
    feet placed a step more and less, two steps, ... (``foot_delta``; the landing's balanced window is
    a few centimetres of foot placement wide, as a landing's plan finds: planning.land), at most
    FOOT_TRIALS more. Returns the planner's {"settings", "measured", "trials", "found"} (the best
    trial, found or not)."""
    near = nearest_balanced(character, target, air_time, NEIGHBOURS)
    bound = min(budget, MODEL_TRIALS + FOOT_TRIALS)
    trials = Trials(trial, bound, progress, cancelled)
    tried = trials.tried

    def run_trial(settings) -> bool:
        return within_tolerance(trials.run(settings), target, air_time)

    found = False
    for settings in candidates(near, target, air_time):
        if len(tried) >= min(budget, MODEL_TRIALS):
            break
        if trials.seen(settings):       # the same jump measured at two heights: run once
            continue
        if found := run_trial(settings):
            break
    fell_on_target = [e for e in tried if lands_on(e[3], target, air_time)]
    if not found and fell_on_target:
        _, _, base, _ = min(fell_on_target, key=lambda e: (e[0], e[1]))
        knob = LEAP_SETTINGS.by_name["foot_delta"]
        steps = foot_candidates(base["foot_delta"], foot_step(load_character(character)), FOOT_TRIALS + 1,
                                knob.minimum, knob.maximum)[1:]
        for delta in steps[:max(bound - len(tried), 0)]:
            if run_trial({**base, "foot_delta": delta}):
                break
    cost, _, settings, measured = min(tried, key=lambda e: (e[0], e[1]))
    return {"settings": settings, "measured": measured, "trials": len(tried),
            "found": bool(within_tolerance(measured, target, air_time))}


def _best(tried: list, balanced: bool = False):
    """The lowest-cost trial (``balanced``: of those that ended balanced, if any did); of equal
    costs the earlier."""
    pool = [e for e in tried if e.extra["outcome"] == "success"] if balanced else tried
    return min(pool or tried, key=lambda e: (e.score, e.index))


def raise_budget(budget) -> None:
    raise ParameterError(f"budget={budget!r}: must be a whole number of trials, at least 1 (a trial is one "
                         f"simulated jump, about half a second)")


def request_of(target, air_time: float, windup_time: float, strength: str) -> dict:
    """The stored-plan request of a jump (the keys a plan is found by)."""
    return {"target_x": float(target[0]), "target_y": float(target[1]), "target_z": float(target[2]),
            "obstacle_height": obstacle_of(target), "air_time": float(air_time), "windup_time": float(windup_time),
            "strength": strength}


@dataclass
class JumpTrial:
    """One trial of a plan as the search service's objective: settings -> (cost, measures). An
    object of a module-level class, so a process pool can pickle it; ``cancelled`` stays in this
    process (a worker's trial cannot see it: the service watches it between trials there)."""
    character: str
    target: tuple
    air_time: float
    windup_time: float
    strength: str
    cancelled: Callable[[], bool] | None = None
    fixed: dict = field(default_factory=dict)     # settings every trial runs with, not searched (turn_of)

    def __call__(self, settings: dict) -> tuple[float, dict]:
        measured = measure_settings(self.character, {**settings, **self.fixed}, self.target, self.air_time,
                                    self.windup_time, self.strength, cancelled=self.cancelled)
        return trial_cost(measured, self.target, self.air_time), measured

    def __getstate__(self):
        return {**self.__dict__, "cancelled": None}


def measure_settings(character: str, settings: dict, target, air_time: float, windup_time: float,
                     strength="human", cancelled: Callable[[], bool] | None = None) -> dict:
    """Run the leap with a plan's ``settings`` toward ``target`` (x, y, z, obstacle height) and read
    the landing off it (landing_measures): one trial of the planner, or a stored plan measured
    again. Judged over the run's whole default duration, as the final run is (a foot still creeping
    after the landing passed at 3.85 s and stepped past 5 cm by 5 s)."""
    duration = max(windup_time + air_time + 2.0, JumpToTarget.default_duration) + turn_duration(settings.get("turn_first", 0.0),
                                                                                                  settings.get("turn_angle", 0.0))
    trajectory = run(RunRequest("leap", character, params=leap_params(settings, target, windup_time, air_time),
                                duration=duration, strength=strength, world=scene_for(character, target)),
                     cancelled=cancelled)
    return landing_measures(trajectory)


def strength_name(strength) -> str:
    """A run's strength ("human", "unlimited" or a factor of the human limits) as the plans key it
    (leap.run_strength: a factor keeps the torque limits, so it is "human")."""
    return "unlimited" if strength == "unlimited" else "human"


def plan_and_store(character: str, params: dict, strength="human", budget: int = 120, progress=None,
                   cancelled=None, executor=None) -> dict:
    """Plan the jump_to_target request ``params`` (the behaviour's parameters, validated) of
    ``character`` (a name or a spec), refusing at once what no plan can do, and keep the plan
    (found or not: a request nothing was found for is then refused at once, with the numbers) in
    the user's plan store. Written only when the search ends (a cancel writes nothing), through a
    temporary file."""
    spec = load_character(character) if isinstance(character, str) else character
    p = JumpToTarget.schema.validate(params)
    strength = strength_name(strength)
    target = tuple(p[k] for k in ("target_x", "target_y", "target_z", "obstacle_height"))
    check_request(spec, p, strength)
    plan = plan_jump(spec.name, target, p["air_time"], p["windup_time"], strength, budget, progress=progress,
                     cancelled=cancelled, executor=executor)
    store_user_plan(spec.name, request_of(target, p["air_time"], p["windup_time"], strength), plan)
    return plan


def planned(character: str, params: dict, strength="human") -> dict | None:
    """The stored plan (user store over shipped tables) of a jump_to_target request, or None."""
    p = JumpToTarget.schema.validate(params)
    target = tuple(p[k] for k in ("target_x", "target_y", "target_z", "obstacle_height"))
    return stored_plan(character, request_of(target, p["air_time"], p["windup_time"], strength_name(strength)))


def store_user_plan(character: str, request: dict, plan: dict) -> None:
    """Keep a plan in the user's plan store (one file per character), replacing the one for the
    same request."""
    _store(character, request, plan, "python -m sim_core plan", plan_store_dir())


def _store(character: str, request: dict, plan: dict, script: str, directory: Path | None) -> None:
    """The character's jump_targets table in ``directory`` (None: the shipped one) with ``plan``
    in the place of any plan for the same request, written whole through the table store."""
    kept = [p for p in read_plans(character, directory) if not same_request(p["request"], request)]
    kept.append({"request": request, **plan})
    kept.sort(key=lambda p: tuple(p["request"].get(k, 0.0) for k in REQUEST_KEYS))
    tuned.save("jump_targets", character, {"script": script, "plans": kept},
               strengths=sorted({p["request"].get("strength", "human") for p in kept}), directory=directory)


def _stable_seed(target, air_time: float, windup_time: float) -> int:
    """A seed from the request's numbers (Python's hash of floats is stable, but be explicit); an
    obstacle counts only where there is one (so a request without one seeds as it always did)."""
    obstacle = [obstacle_of(target)] if obstacle_of(target) else []
    values = [round(float(v) * 1000) for v in (*target[:3], air_time, windup_time, *obstacle)]
    seed = 17
    for v in values:
        seed = (seed * 1_000_003 + v) % (2 ** 31)
    return seed


def store_plan(character: str, request: dict, plan: dict, script: str, directory: Path | None = None) -> None:
    """Keep a plan (found or not) in the shipped table, sim_core/tuned/tables/jump_targets_<character>.json
    (or in the table of that name in ``directory``), replacing the one for the same request
    (python -m sim_core calibrate jump_to_target; a user's plans go to store_user_plan)."""
    _store(character, request, plan, script, directory)


def _side(x: float, y: float) -> int:
    """0 for a target more ahead than to the side (a broad jump, leaning sideways a little), else
    1 to the left, -1 to the right: a target at (0.57, +0.008) m started from the pure-sideways 1.0 m
    plan and every trial landed at (0.0, +1.0) m (docs/random_requests.md before issue 29's fix)."""
    return 0 if abs(y) <= abs(x) else (1 if y > 0 else -1)


def search_start(character: str, target, previous: dict | None, strength="human") -> dict | None:
    """Where a search starts: the settings of the stored plan found nearest ``target``
    (nearest_start_plan), or of an earlier search's best trial for this very request
    (``previous``) if that ended balanced nearer the target (None if neither)."""
    found = nearest_start_plan(character, target, strength)
    if previous is None or previous["measured"]["outcome"] != "success":
        return found[1] if found else (previous or {}).get("settings")
    miss = math.dist(previous["measured"]["landing"], [float(v) for v in target[:2]])
    return found[1] if found and found[0] < miss else previous["settings"]


def turned_start(character: str, target, strength="human") -> dict | None:
    """For a target on the ground more to the side than ahead, the settings of the stored plan found
    nearest it to that side if that plan turns first (turn_of): such a target is searched from it,
    turning as it does, not planned from the measured jumps (none of which turns). None otherwise."""
    if float(target[2]) or obstacle_of(target) or _side(float(target[0]), float(target[1])) == 0:
        return None
    found = nearest_found_plan(character, target, strength)
    return found[1] if found and turn_of(found[1]) else None


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
             and _side(p["request"]["target_x"], p["request"]["target_y"]) == _side(float(target[0]), float(target[1]))]
    if not plans:
        return None
    def distance(p):        # nearest; of two as near, the longer jump (shortening one is easier)
        where = (p["request"]["target_x"], p["request"]["target_y"], p["request"]["target_z"])
        return round(math.dist(where, tuple(float(v) for v in target[:3])), 6), -math.hypot(*where[:2])
    nearest = min(plans, key=distance)
    return distance(nearest)[0], dict(nearest["settings"])
