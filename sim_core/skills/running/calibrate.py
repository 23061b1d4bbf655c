"""Tune the running controller's five high-level parameters (Hodgins & Pollard 1997 §4.3.1) by
search, speed by speed, and write them as data - a table over the running speed - to
sim_core/tuned/tables/running_<character>.json, which the running behaviour reads (a tuned parameter left at
-1 takes the table's value for the current speed).

    python -m sim_core calibrate running --speeds 3.5 --minutes 10     # simulated annealing at 3.5 m/s
    python -m sim_core calibrate running --speeds 2.5 3.5 4.5 5.0 --minutes 40
    python -m sim_core calibrate running --method cma                  # CMA-ES
    python -m sim_core calibrate running --evaluate                    # only score the current table
    python -m sim_core calibrate running --speeds 3.5 --courses --duration 30 --method cma   # ... and on the tight courses
    python -m sim_core calibrate running --joint --speeds 4.83 5.0 --gait-at 4.83 --method cma --duration 30   # two rows at once

The five parameters: ground-speed matching (forward speed), stance pitch (body attitude), and
thrust timing, ankle extension and knee extension (flight duration).

Evaluation function at a speed v_d (lower is better), averaged over two runs from a stand of
``--duration`` seconds (the paper ran 15 s from a running start; ours must first accelerate),
one with the default lean into the start and one with a longer lean (a second set of first steps,
so that a parameter set is not scored on one lucky sequence):

    E = W_FALL  * (1 - t_up / T)                      running time lost to a fall
      + W_SPEED * |v - v_d| / v_d                     speed error, mean over the last 10 s
      + W_BAND  * max(0, |v - v_d| / v_d - BAND)      the same beyond the target's band (TARGETS.md: 5 %)
      + W_HEAD  * mean |a_head| / g                   head acceleration (smoothness), last 5 s
      + W_ATT   * mean |d(roll, pitch, yaw)| per stride   stride-to-stride attitude variation (rad)
      + W_GAIT  * mean over q of |q - q_h| / q_h      gait against the human (v_d >= 4.5 only)
      + W_GAIT_BAND * sum over q of max(0, |q - q_h| / q_h - GAIT_BAND)   the same beyond 8 %

where q runs over the step frequency, the step length and the stance/step fraction over the last
10 s, compared with the man's figures of Hodgins & Pollard 1997 Fig. 12 (2.92 steps/s, 1.66 m,
57.9 %, measured at 4.83 m/s; TARGETS.md's goal is each within 10 %, so an error beyond 8 % costs
ten times more, as the speed's band does). The paper adjusted its
penalties "to convert a stride where the feet of the runner were barely skimming over the ground
to a stride that was more bouncy"; this term is that adjustment, applied at the fast end of the
table (4.5 m/s and above), where Fig. 12's speed lies. A run that falls before it has three steps
in the window gets 1.0 for each quantity. (Before this round the gait term was the mean of the
step frequency's and the stance fraction's errors, without the band term: the stored 4.5 and
5.0 m/s rows were searched with that.)

With ``--courses`` the row is also scored on the tight courses that the steering test runs at
3.5 m/s (a 90-degree turn of radius 10 m, 24 s, and a figure eight of radius-10 m loops, 40 s, both
at the row's speed), each adding

      + W_FALL * (1 - t_up / T) + W_PATH * min(mean lateral deviation, 1 m)

to the sum before the mean: a row that runs straight but falls in a turn scores worse.

With ``--faster`` the candidate table is also run at each of its faster speeds (the same runs
from a stand, with their own terms in the mean): the table is looked up at the ramped speed
command, so a runner accelerating to 5.0 m/s runs through every row below it, and a row searched
at 4.83 m/s alone made the 5.0 m/s run fall at 18.1 s.

With ``--joint`` (CMA-ES only) the rows of all ``--speeds`` are one search: a candidate holds a row
per speed and every evaluation runs every one of those speeds with all of them in the table - for
rows close together, such as 4.83 m/s (Fig. 12's speed) and 5.0 m/s, which the runner accelerating
to 5.0 m/s passes through. ``--gait-at 4.83`` makes the gait term count only in the runs at the
speeds named (Fig. 12's figures are the man's at 4.83 m/s; the 5.0 m/s runs then answer only for
their speed, falls, smoothness and attitude). ``--start`` takes either one row for every searched
speed or ``{"4.83": {name: value}, ...}``.

The searches are the search service's (sim_core.tuning: SciPy's annealing or CMA-ES, in the
columns scaled to [0, 1] by their ranges). Each evaluation runs its scenarios in a pool of
``--workers`` processes (default one per CPU), or on a Dask distributed cluster (``--cluster ADDRESS``,
the scheduler's address; sim_core.tuning.ClusterExecutor). A search runs at most ``--max-evaluations``
evaluations and is time-boxed by ``--minutes``; the best point found is written only if it
scores better than the current defaults, together with both scores, the evaluation's weights
and the search settings (the file is written atomically: never half-written).
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path.cwd()                   # docs are written under the folder it runs in (the checkout)

from .behaviour import SCHEDULED_CONSTANTS, TABLE_NAMES, TUNED_NAMES, Running, SpeedTable
from ... import tuned
from ...character.spec import character_name
from ...tuning import Space, deadline_stop, executor_for, minimize

COLUMNS = TABLE_NAMES + tuple(SCHEDULED_CONSTANTS)     # what a row of the table can hold

W_FALL, W_SPEED, W_HEAD, W_ATT, W_GAIT = 10.0, 4.0, 0.05, 2.0, 2.0
W_PATH = 4.0                    # per metre of mean lateral deviation from a course's path (at most 1 m)
W_BAND, BAND = 40.0, 0.04       # the speed error beyond 4 % (inside the 5 % target) costs ten times more
W_GAIT_BAND, GAIT_BAND = 20.0, 0.08     # a Fig. 12 quantity off by more than 8 % (the goal: 10 %)
SPEED_WINDOW = 10.0             # s: the steady-state speed is the mean over the run's last 10 s
GAIT_FROM = 4.5                 # m/s: the gait term applies at and above this speed
GRAVITY = 9.80665


def scenario(args) -> dict:
    """One run from a stand; the terms of the evaluation function."""
    from ...gait import HUMAN_FIG12, compare_with_human, head_acceleration, stride_attitude_variation
    from ...simulate import RunRequest, run
    table, speed, start_lean, duration, character, strength, course = args
    # the candidate table is the run's ``table`` parameter: what is scored is the table that would be written
    traj = run(RunRequest("running", character, params=dict(course or {}, speed=speed, start_lean=start_lean, table=table),
                          duration=duration, strength=strength))
    m = traj.meta["metrics"]
    a = traj.arrays
    t_up = m["fall_time"] if m["fell"] else duration
    if course:
        deviation = m.get("path_deviation_mean")
        return {"speed": speed, "t_up": t_up, "duration": duration, "course": True,
                "deviation": 1.0 if deviation is None else float(deviation)}
    end = t_up
    window = (a["time"] >= max(0.0, end - SPEED_WINDOW)) & (a["time"] <= end)
    v = float(np.mean(np.linalg.norm(a["com_vel"][window, :2], axis=1)))
    head = float(np.mean(head_acceleration(traj)[window])) / GRAVITY
    att = stride_attitude_variation(traj, t_from=max(0.0, end - 5.0)) if not m["fell"] else float("nan")
    if not math.isfinite(att):
        att = 0.5
    compared = compare_with_human(m["gait"], character if character in HUMAN_FIG12 else "man")
    gait = [1.0 if c["relative_error"] is None else abs(c["relative_error"]) for c in compared.values()]
    return {"speed": speed, "t_up": t_up, "duration": duration, "mean_speed": v, "head_acc_g": head,
            "attitude_variation": att, "gait_errors": gait}


def evaluation(terms: list[dict], gait_speeds=None) -> float:
    """The mean over the runs of the terms in the module's docstring; the gait term counts at the
    speeds from GAIT_FROM up, or with ``gait_speeds`` (``--gait-at``) at those speeds only."""
    total = 0.0
    for s in terms:
        total += W_FALL * (1.0 - s["t_up"] / s["duration"])
        if s.get("course"):
            total += W_PATH * min(s["deviation"], 1.0)
            continue
        error = abs(s["mean_speed"] - s["speed"]) / s["speed"]
        total += (W_SPEED * error + W_BAND * max(0.0, error - BAND)
                  + W_HEAD * s["head_acc_g"] + W_ATT * s["attitude_variation"])
        if gait_counts(s["speed"], gait_speeds):
            total += (W_GAIT * float(np.mean(s["gait_errors"]))
                      + W_GAIT_BAND * sum(max(0.0, e - GAIT_BAND) for e in s["gait_errors"]))
    return total / len(terms)


def gait_counts(speed: float, gait_speeds=None) -> bool:
    if gait_speeds is None:
        return speed >= GAIT_FROM - 1e-9
    return any(abs(speed - v) < 1e-9 for v in gait_speeds)


def describe(s: dict) -> str:
    if s.get("course"):
        return f"t_up={s['t_up']:.1f} dev={s['deviation']:.2f}"
    return f"t_up={s['t_up']:.1f} v={s['mean_speed']:.2f} gait=" + "/".join(f"{e:.2f}" for e in s["gait_errors"])


class Evaluator:
    """Scores a candidate row of the table at one speed - or, with a list of speeds (``--joint``),
    candidate rows at all of them at once, ``x`` holding their values one row after the other: the
    runs use the stored table with those rows replaced (the runner accelerates through the lower
    rows), i.e. exactly what would be written."""

    def __init__(self, pool, table, names, speed, duration, character, strength, leans=(0.35, 0.5),
                 courses=False, log=None, faster=False, gait_speeds=None):
        self.pool, self.table, self.names, self.duration = pool, table, names, duration
        self.rows = tuple(float(v) for v in speed) if isinstance(speed, (list, tuple)) else (float(speed),)
        self.speed = self.rows[0]
        self.leans = tuple(leans)
        # with ``faster``, also the runs at the table's faster speeds: a runner accelerating to them
        # is looked up at its ramped command, so it passes through this row on the way
        self.faster = tuple(v for v in faster_speeds(table.speeds, list(self.rows)) if v not in self.rows) \
            if faster else ()
        self.courses = STEERING_COURSES if courses else ()
        self.gait_speeds = gait_speeds
        self.log = log          # a file that gets one JSON line per evaluation (the search can be read back)
        self.character, self.strength = character, strength
        self.history: list[tuple[list[float], float]] = []

    def row_values(self, x) -> dict[float, list[float]]:
        n = len(self.names)
        return {speed: [float(v) for v in x[k * n:(k + 1) * n]] for k, speed in enumerate(self.rows)}

    def __call__(self, x) -> float:
        candidate = with_found_rows(self.table, self.names, self.row_values(x))
        table = candidate.to_table()
        jobs = [(table, v_, lean, self.duration, self.character, self.strength, None)
                for v_ in self.rows + self.faster for lean in self.leans]
        jobs += [(table, v, self.leans[0], duration, self.character, self.strength, course)
                 for v in self.rows for course, duration in self.courses]
        terms = self.pool.map(scenario, jobs)
        score = evaluation(terms, self.gait_speeds)
        self.history.append((list(map(float, x)), score))
        print(f"  {len(self.history):4d} {score:8.4f} " + " ".join(describe(s) for s in terms), flush=True)
        if self.log:
            rows = {f"{v:g}": dict(zip(self.names, r)) for v, r in self.row_values(x).items()}
            record = {"row": rows[f"{self.speed:g}"]} if len(self.rows) == 1 else {"rows": rows}
            with open(self.log, "a") as f:
                f.write(json.dumps({**record, "score": score, "runs": terms}) + "\n")
        return score


def bounds(names=TUNED_NAMES) -> list[tuple[float, float]]:
    return [SCHEDULED_CONSTANTS[n] if n in SCHEDULED_CONSTANTS
            else (Running.schema.by_name[n].minimum, Running.schema.by_name[n].maximum) for n in names]


def search(evaluate, x0, deadline, max_evaluations, seed, method, sigma=0.1):
    """The search service over the candidate's columns (every row's, one after the other): scipy's
    dual_annealing (the paper used simulated annealing; no local search, initial temperature 2000)
    or CMA-ES (``sigma``: the initial step, as a share of each range), from ``x0``, at most
    ``max_evaluations`` evaluations and stopped at the ``deadline`` (time.monotonic())."""
    columns = [f"{speed:g} {name}" for speed in evaluate.rows for name in evaluate.names]
    space = Space(dict(zip(columns, bounds(evaluate.names) * len(evaluate.rows))))
    result = minimize(lambda settings: evaluate([settings[c] for c in columns]), space, method, max_evaluations,
                      seed, start=dict(zip(columns, map(float, x0))), sigma=sigma,
                      stop=deadline_stop(deadline - time.monotonic()),
                      options={"initial_temp": 2000.0} if method == "anneal" else None)
    return {"x": [result.best.settings[c] for c in columns], "f": result.best.score}


def start_rows(start: dict, speeds: list[float]) -> dict[float, dict]:
    """``--start``: {name: value} for every searched row, or {speed: {name: value}} per row."""
    keyed = {}
    for key, value in start.items():
        if isinstance(value, dict):
            try:
                keyed[float(key)] = value
            except ValueError:
                raise SystemExit(f"--start: {key!r} is neither a speed with its row nor a parameter") from None
    if not keyed:
        return {v: dict(start) for v in speeds}
    if len(keyed) != len(start):
        raise SystemExit("--start: give either {name: value} or {speed: {name: value}}, not both")
    unknown = sorted(set(keyed) - set(speeds))
    if unknown:
        raise SystemExit(f"--start rows for {', '.join(f'{v:g}' for v in unknown)} m/s, which --speeds does not search")
    return {v: dict(keyed.get(v, {})) for v in speeds}


def with_found_rows(table: SpeedTable, names: list[str], found: dict[float, list[float]]) -> SpeedTable:
    """``table`` with the rows ``found`` (speed -> values of ``names``) in place: a candidate's rows, or
    a search's when it ends - then into the stored table read again, since a search of other speeds
    may have written it meanwhile."""
    for speed, x in found.items():
        table = table.with_row(speed, dict(zip(names, map(float, x))))
    return table


def faster_speeds(speeds: list[float], rows: list[float]) -> list[float]:
    """The table's speeds above the slowest of ``rows``: their runs accelerate through those rows."""
    return [v for v in speeds if any(v > row + 1e-9 for row in rows)]


# ------------------------------------------------------------------ steering constants
# The steering laws' constants (tuned settings of the running, stored in the running_any table's
# constants, and the lean and look-ahead parameters) only act when the heading goal turns, so they
# are searched on paths, not per speed:
#
#     E_steer = mean over the courses of  W_FALL  * (1 - t_up / T)
#                                       + W_SPEED * |v - v_d| / v_d        (mean speed, whole run after 5 s)
#                                       + W_PATH  * min(mean lateral deviation, 1 m)
#
# on a 90-degree turn of radius 10 m (24 s) and a figure eight of loops of radius 10 m (40 s),
# both at 3.5 m/s from a stand. Each candidate runs with the values as its parameters (one name per
# knob: the settings' names); a best point better than the start is written to the running_any
# table's constants (lean and look-ahead are the animator's parameters: printed, set per run).
STEERING_CONSTANTS = {            # name: (low, high)
    "turn_accel": (0.1, 3.0), "heading_gain": (0.5, 4.0), "turn_place_gain": (0.0, 2.0),
    "lateral_gain": (0.0, 0.4), "yaw_error_limit": (0.05, 0.4), "turn_rate_per_speed": (0.1, 0.6),
    "lean": (0.0, 1.5), "lookahead": (1.0, 6.0)}
STEERING_COURSES = (
    ({"course": 1, "turn_angle": math.pi / 2, "turn_radius": 10.0, "turn_after": 25.0}, 24.0),
    ({"course": 2, "turn_radius": 10.0, "turn_after": 25.0}, 40.0),
)


def steering_scenario(args) -> dict:
    from ...simulate import RunRequest, run
    values, course, duration, speed = args
    traj = run(RunRequest("running", "man", params=dict(course, speed=speed, **values), duration=duration))
    m = traj.meta["metrics"]
    a = traj.arrays
    t_up = m["fall_time"] if m["fell"] else duration
    sel = (a["time"] >= 5.0) & (a["time"] <= t_up)
    v = float(np.mean(np.linalg.norm(a["com_vel"][sel, :2], axis=1))) if sel.any() else 0.0
    dev = m.get("path_deviation_mean")
    return {"t_up": t_up, "duration": duration, "mean_speed": v, "deviation": 1.0 if dev is None else float(dev)}


def steering_search(args) -> int:
    names = list(STEERING_CONSTANTS)
    lo = np.array([STEERING_CONSTANTS[n][0] for n in names])
    hi = np.array([STEERING_CONSTANTS[n][1] for n in names])
    x0 = np.array([Running.schema.by_name[n].default for n in names], dtype=float)
    speed = 3.5
    history = []
    with executor_for(args.workers, args.cluster) as pool:
        def evaluate(x) -> float:
            values = dict(zip(names, map(float, x)))
            terms = pool.map(steering_scenario, [(values, c, d, speed) for c, d in STEERING_COURSES])
            score = float(np.mean([W_FALL * (1 - s["t_up"] / s["duration"]) + W_SPEED * abs(s["mean_speed"] - speed) / speed
                                   + W_PATH * min(s["deviation"], 1.0) for s in terms]))
            history.append((values, score))
            print(f"  {len(history):4d} {score:8.4f} " + " ".join(f"t_up={s['t_up']:.1f} v={s['mean_speed']:.2f} dev={s['deviation']:.2f}"
                                                                for s in terms) + " " + json.dumps({k: round(v, 4) for k, v in values.items()}), flush=True)
            return score
        result = minimize(lambda values: evaluate([values[n] for n in names]), Space(STEERING_CONSTANTS), "cma",
                          args.max_evaluations, args.seed, start=dict(zip(names, x0.clip(lo, hi))), sigma=0.2,
                          stop=deadline_stop(60.0 * args.minutes))
        baseline = result.evaluations[0].score
    best = min(history, key=lambda h: h[1])
    print(f"steering: {len(history)} evaluations, baseline {baseline:.4f}, best {best[1]:.4f}")
    if best[1] < baseline:
        stored = tuned.load("running", "any")
        constants = {**stored["constants"], **{n: v for n, v in best[0].items() if n in stored["constants"]}}
        path = tuned.save("running", "any", {**stored, "constants": constants}, strengths=["human"])
        print(f"wrote the steering constants to {path}; lean and lookahead (parameters, set per run): "
              + json.dumps({n: v for n, v in best[0].items() if n not in stored["constants"]}))
    return 0


def scaled_table(source: str, character: str, speeds: list[float], constants: dict) -> SpeedTable:
    """``source``'s running table and the constants of the laws (running_any's are the man's),
    mass-scaled to ``character`` by Fig. 6 (sim_core.adapt.settings; the speeds as velocities, L^1/2);
    the rows taken at ``speeds`` (interpolated, held at the ends); a value scaled out of its setting's
    range is held at the range's end; ``constants`` replaces some constants as they are."""
    from ...adapt.settings import MASS, CharacterPair, scale_columns, scale_settings
    from ...character.spec import load_character
    from .behaviour import CONSTANT_NAMES, RUNNING_SETTINGS, RUNNING_TABLE

    def held(name, value):
        knob = RUNNING_SETTINGS.by_name[name]
        return min(max(value, knob.minimum), knob.maximum)
    pair = CharacterPair(load_character(source), load_character(character))
    table = SpeedTable.load(pair.old_spec.name)
    columns = {n: v for n, v in table.values.items() if n in RUNNING_TABLE.settings.by_name}
    scaled_speeds, scaled = scale_columns(table.speeds, columns, RUNNING_TABLE.settings, pair, MASS)
    scaled_table = SpeedTable(scaled_speeds, {n: [held(n, x) for x in col] for n, col in scaled.items()})
    design = {n: RUNNING_SETTINGS.defaults()[n] for n in CONSTANT_NAMES}
    scaled_constants = {n: held(n, v) for n, v in
                        scale_settings({**design, **table.constants}, RUNNING_SETTINGS, pair, MASS).items()}
    unknown = sorted(set(constants) - set(CONSTANT_NAMES))
    if unknown:
        raise SystemExit(f"--constants: {', '.join(unknown)} are not constants of the running laws")
    speeds = sorted(float(v) for v in speeds)
    return SpeedTable(speeds, {n: [scaled_table.at(n, v) for v in speeds] for n in scaled_table.values},
                      {**scaled_constants, **{n: float(v) for n, v in constants.items()}})


def write_scaled_table(args, argv) -> int:
    """``--scale-from``: the character's first table, written through the store."""
    if args.character == args.scale_from:
        raise SystemExit("--scale-from names the --character itself")
    table = scaled_table(args.scale_from, args.character, args.speeds, args.constants)
    path = tuned.save("running", character_name(args.character), {
        **table.to_table(),
        "note": f"the {args.scale_from}'s rows and the constants of the running laws mass-scaled by Fig. 6 "
                "(sim_core.adapt.settings), the constants of --constants as given; rows then searched by "
                "calibrate running (evaluation.per_speed)",
        "command": "python -m sim_core calibrate running " + " ".join(argv if argv is not None else sys.argv[1:]),
    }, strengths=["human"], directory=args.tables)
    print(f"wrote {path}")
    return 0


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--character", default="man")
    ap.add_argument("--strength", default="human")
    ap.add_argument("--speeds", type=float, nargs="+", default=[3.5])
    ap.add_argument("--duration", type=float, default=20.0)
    ap.add_argument("--minutes", type=float, default=20.0, help="time budget for all speeds together")
    ap.add_argument("--max-evaluations", type=int, default=300, help="per speed")
    ap.add_argument("--method", choices=("anneal", "cma"), default="anneal")
    ap.add_argument("--workers", type=int, default=None, help="processes running an evaluation's runs (default: one "
                    "per CPU)")
    ap.add_argument("--cluster", metavar="ADDRESS",
                    help="run the evaluations' runs on the Dask distributed cluster whose scheduler is at ADDRESS "
                         "(e.g. tcp://10.0.0.5:8786; its workers need this project installed) instead of --workers")
    ap.add_argument("--names", nargs="+", default=list(TUNED_NAMES), choices=list(COLUMNS),
                    help="parameters searched (default the five of Hodgins & Pollard; the table has three more, "
                         "and the scheduled constants of the stance and swing laws)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--sigma", type=float, default=0.1,
                    help="CMA-ES: initial step as a share of each column's range (smaller: a search nearer its start; "
                         "with 0.1 most candidates of a 15-column row fell)")
    ap.add_argument("--leans", type=float, nargs="+", default=[0.35, 0.5],
                    help="start leans (s) of the runs that each evaluation averages (more runs: a sturdier row)")
    ap.add_argument("--evaluate", action="store_true", help="only score the current table")
    ap.add_argument("--courses", action="store_true",
                    help="also score each row on the 90-degree turn and the figure eight of radius 10 m at its speed")
    ap.add_argument("--faster", action="store_true",
                    help="also score each candidate row on the table's faster speeds (same runs): the runner "
                         "accelerating to a faster speed passes through the row, which can make it fall there")
    ap.add_argument("--start", type=json.loads, default={},
                    help="JSON {name: value}: start the search there instead of at the table's row")
    ap.add_argument("--joint", action="store_true",
                    help="search the rows of all --speeds together (one CMA-ES vector, every evaluation runs every "
                         "speed): two rows near each other, e.g. 4.83 and 5.0 m/s, where a runner accelerating to "
                         "the faster passes through the slower")
    ap.add_argument("--gait-at", type=float, nargs="+", default=None, metavar="SPEED",
                    help="the Fig. 12 gait term counts only in the runs at these speeds (default: every run from "
                         f"{GAIT_FROM:g} m/s up)")
    ap.add_argument("--tables", type=Path, default=None,
                    help="directory the table is written to (default: the shipped tables, sim_core/tuned/tables); the search starts from the "
                         "shipped table")
    ap.add_argument("--log", help="append each evaluation (row, score, runs) as a JSON line to this file")
    ap.add_argument("--steering", action="store_true",
                    help="search the steering constants on a 90-degree turn and a figure eight (CMA-ES; prints them)")
    ap.add_argument("--scale-from", metavar="CHARACTER",
                    help="write the --character's first table (at --speeds) and stop: CHARACTER's rows and the constants "
                         "of the running laws, mass-scaled to the --character by Fig. 6 (sim_core.adapt); --constants "
                         "sets some constants instead")
    ap.add_argument("--constants", type=json.loads, default={},
                    help="with --scale-from: JSON {name: value}, constants of the laws written as they are")
    args = ap.parse_args(argv)
    if args.scale_from:
        return write_scaled_table(args, argv)
    if not 0.0 < args.sigma <= 0.5:
        ap.error(f"--sigma {args.sigma:g} must be in (0, 0.5] (a share of each column's range)")
    if args.steering:
        return steering_search(args)
    if args.joint and args.method != "cma":
        ap.error("--joint searches with CMA-ES: add --method cma")
    starts = start_rows(args.start, args.speeds)
    unknown = sorted({n for row in starts.values() for n in row} - set(args.names))
    if unknown:
        ap.error(f"--start names {', '.join(unknown)}, which --names does not search ({', '.join(args.names)})")
    strength = args.strength if args.strength in ("human", "unlimited") else float(args.strength)
    name = character_name(args.character)          # a spec file's tables are stored under its name
    table = SpeedTable.load(name)
    started = time.monotonic()
    per_speed = {}          # this search's rows' records, merged into the file's when it is written
    new_values = {}
    with executor_for(args.workers, args.cluster) as pool:
        groups = [tuple(args.speeds)] if args.joint else [(v,) for v in args.speeds]
        for k, rows in enumerate(groups):
            speed = rows[0] if len(rows) == 1 else list(rows)
            x0 = [float(starts[v][n]) if n in starts[v] else table.at(n, v) for v in rows for n in args.names]
            evaluate = Evaluator(pool, table, args.names, speed, args.duration, args.character, strength, args.leans,
                                 courses=args.courses, log=args.log, faster=args.faster, gait_speeds=args.gait_at)
            label = " + ".join(f"{v:g}" for v in rows)
            if args.evaluate:
                print(f"{label} m/s: evaluation {evaluate(x0):.4f} at {evaluate.row_values(x0)}")
                continue
            remaining = started + 60.0 * args.minutes - time.monotonic()
            deadline = time.monotonic() + remaining / (len(groups) - k)
            stored_row = [table.at(n, v) for v in rows for n in args.names]
            # what a better row must beat is the stored one, also when the search starts elsewhere
            baseline = evaluate(stored_row) if x0 != stored_row else None
            best = search(evaluate, x0, deadline, args.max_evaluations, args.seed, args.method, args.sigma)
            baseline = evaluate.history[0][1] if baseline is None else baseline
            print(f"{label} m/s: {len(evaluate.history)} evaluations, baseline {baseline:.4f}, best {best['f']:.4f}",
                  flush=True)
            found = evaluate.row_values(best["x"])
            print(json.dumps({f"{v:g}": dict(zip(args.names, r)) for v, r in found.items()}, indent=1), flush=True)
            if best["f"] < baseline:
                table = with_found_rows(table, args.names, found)     # the next speed starts from it
                for v, r in found.items():
                    new_values[v] = r
                    per_speed[str(v)] = {"score": best["f"], "baseline_score": baseline,
                                         "evaluations": len(evaluate.history), "searched": list(args.names),
                                         "method": args.method, "duration_s": args.duration,
                                         **({"sigma": args.sigma} if args.method == "cma" else {}),
                                         "leans": list(args.leans), "courses": args.courses,
                                         "faster_speeds_scored": list(evaluate.faster),
                                         **({"searched_with": list(rows)} if len(rows) > 1 else {}),
                                         **({"gait_at": list(args.gait_at)} if args.gait_at else {})}
    if args.evaluate or not new_values:
        if not args.evaluate:
            print("no improvement on the current table; nothing written")
        return 0
    # the rows found go into the table as it is now: another search (of other speeds) may have written it
    # since this one started
    table = with_found_rows(SpeedTable.load(name), args.names, new_values)
    stored = tuned.load("running", name, args.tables) or tuned.load("running", name) or {}
    per_speed = {**stored.get("evaluation", {}).get("per_speed", {}), **per_speed}
    speeds = table.speeds
    # as stored, unrounded (the runs are chaotic in them); not table.at() at the knots, which can change
    # a value in the last bit
    values = {n: list(table.values[n]) for n in COLUMNS}
    elapsed = time.monotonic() - started
    path = tuned.save("running", name, {
        "speeds": speeds, **table.limits_entry(), "parameters": values,
        **({"constants": table.constants} if table.constants else {}),
        **({"note": stored["note"]} if "note" in stored else {}),
        "evaluation": {"weights": {"fall": W_FALL, "speed": W_SPEED, "speed_beyond_band": W_BAND,
                                   "speed_band": BAND, "head_acceleration": W_HEAD,
                                   "attitude_variation": W_ATT, "gait_fig12": W_GAIT,
                                   "gait_fig12_beyond_band": W_GAIT_BAND, "gait_band": GAIT_BAND, "path": W_PATH},
                       "speed_window_s": SPEED_WINDOW,
                       "gait_term_from_m_s": GAIT_FROM,
                       "runs": f"{len(args.leans)} per speed from a stand (lean " + ", ".join(f"{x:g}" for x in args.leans) + " s)",
                       "duration_s": args.duration, "strength": args.strength, "per_speed": per_speed},
        "search": {"method": args.method, "minutes": round(elapsed / 60, 2), "seed": args.seed},
        "command": "python -m sim_core calibrate running " + " ".join(argv if argv is not None else sys.argv[1:]),
    }, strengths=["unlimited" if args.strength == "unlimited" else "human"],   # a factor scales the human limits
        directory=args.tables)
    print(f"wrote {path}")
    unchecked = [] if args.faster else faster_speeds(speeds, new_values)
    if unchecked:
        print("note: the runs at " + ", ".join(f"{v:g}" for v in unchecked) + " m/s pass through the new row(s) as "
              "they accelerate and were not scored with them (--faster does); check them with --evaluate --speeds "
              + " ".join(f"{v:g}" for v in unchecked))
    return 0


if __name__ == "__main__":
    sys.exit(main())
