"""Calibrate the standing tuck somersaults by simulation and write the table the somersault
behaviour reads (sim_core/tuned/tables/somersaults_<character>.json) - the role of the "about three hours
of tuning" Wooten describes in §8.4 (leap settings until the height and spin allow a landing,
then the timing of the opening), done by a search.

For each character, direction (backward, forward) and strength (human torque limits,
unlimited as the thesis ran) a search (the search service, sim_core.tuning: CMA-ES by default, or
annealing) over the take-off settings (crouch height,
torso pitch, COM offset, lean along the thrust, lift-off hip angle, arm swing, thrust damping,
the tuck's stiffness, damping and move time) and the landing settings (landing lean, opening time, knee bend, foot delta and lead, spin
placement) minimises, with every quantity read off the simulated somersault,

    score = |rotation - 2 pi| + 50 max(0, drift - 0.9 %)             if it ends balanced
          = |rotation - 2 pi| + 50 max(0, drift - 0.9 %) + 0.5 |flight rotation - 5.9| + 1
            + 2 (1 - min(time on the feet after touchdown, 1.5 s) / 1.5 s)
            + 20 max(0, foot slide after landing - 5 cm) / m
            + 100 max(0, skid of the feet's middle after touchdown - 5 cm) / m       otherwise

(rotation: the pelvis's turn from the standing start to the end of the run; flight rotation: from
lift-off to touchdown; drift: of the whole-body angular momentum in flight, which must stay within
1 % - fast moves in the 1 ms step let it drift; a run that falls later after touching down scores
better than one that falls at once, one whose feet skid less on landing better than one that
skids more). The flight's physics step (`flight_step_division`) is not searched: it stays as
the search starts (the table's row, 1 in rows made before it; `--start '{"flight_step_division": 8}'`
for a fast tuck). A run counts as found only with the drift below 0.9 %. A somersault that ended balanced is kept with its measurements; where none did,
the best run is recorded under "not_found" and the behaviour refuses that somersault with it.
The search goes on until it has found a few somersaults (ROBUST_CANDIDATES) and keeps the one
whose eight neighbours (lift-off hip angle and landing lean +-0.02 rad) land most often.

    python -m sim_core calibrate somersault --character man --direction backward --strength unlimited
    python -m sim_core calibrate somersault --character woman --direction forward --iterations 20
    python -m sim_core calibrate somersault --character man --direction backward --strength unlimited \
        --budget 4 --no-refine --tables /tmp/t                      # a quick look

``--budget`` is the number of simulated somersaults each search may run (default ``--iterations``
x ``--population``); choosing the most robust of those found runs up to 32 more (``--no-refine``
keeps the best by score). ``--workers`` (or ``--processes``) runs them in that many processes (the
same result as 1).
"""
from __future__ import annotations

import argparse
import functools
import json
import math
import time
from pathlib import Path

ROOT = Path.cwd()                   # docs are written under the folder it runs in (the checkout)

from ...control.leap import LANDING_SKID_LIMIT, LANDING_SLIDE_LIMIT
from .behaviour import DIRECTIONS, LANDING_SETTINGS, OLD_ROW, SETTINGS, load_table
from ...control.tumble import snap_damping
from ...control.tuned import keep_search, kept_message, names_option, searched_and_fixed
from ...simulate import RunRequest, run
from ...tuning import Space, SerialExecutor, StopAfterFound, executor_for, minimize

DURATION = 5.0
SLIDE_WEIGHT = 20.0         # per m a foot moves after landing beyond the stepping limit (a run on its feet that steps)
SKID_WEIGHT = 100.0         # per m the middle of the feet skids after touchdown beyond the skid limit: the
                            # woman's backward tuck searches (2 x 288 runs) ended "skidded" 0.75 cm over it
                            # with nothing in the score pulling them back
DRIFT_GOAL = 0.009          # angular momentum drift in flight the search aims below (the test's limit is 1 %)
SPACE = {  # name: (low, high) per direction
    "crouch_height": {"backward": (0.42, 0.9), "forward": (0.5, 0.9)},  # the crouch is a squat: it may go below half the standing pelvis height
    "crouch_pitch": {"backward": (-0.3, 1.5), "forward": (0.0, 1.5)},
    "com_offset": {"backward": (-0.2, 0.05), "forward": (-0.05, 0.2)},
    "thrust_lean": {"backward": (-0.1, 0.1), "forward": (-0.1, 0.1)},
    "liftoff_hip": {"backward": (0.0, 2.0), "forward": (-2.0, 0.5)},
    "arm_swing": {"backward": (1.5, 3.2), "forward": (-1.0, 3.2)},
    "thrust_damping": {"backward": (0.2, 1.0), "forward": (0.2, 1.0)},
    "tuck_stiffness": {"backward": (1.0, 4.0), "forward": (1.0, 4.0)},
    "tuck_time": {"backward": (0.05, 0.3), "forward": (0.05, 0.3)},
    "tuck_damping": {"backward": (0.5, 6.0), "forward": (0.5, 6.0)},
    "landing_lean": {"backward": (-0.3, 1.0), "forward": (-0.3, 0.8)},
    "open_time": {"backward": (0.03, 0.4), "forward": (0.03, 0.4)},
    "open_blend": {"backward": (0.12, 0.3), "forward": (0.12, 0.3)},    # shorter: the drift passes 1 %
    "landing_knee_flexion": {"backward": (0.3, 1.4), "forward": (0.3, 1.4)},
    "foot_delta": {"backward": (-0.3, 0.3), "forward": (-0.3, 0.3)},
    "landing_foot_lead_time": {"backward": (0.0, 0.5), "forward": (0.0, 0.5)},
    "spin_placement": {"backward": (0.0, 0.5), "forward": (0.0, 0.5)},
}
START = {   # where the search starts when the table has nothing: found by hand-run searches
    "backward": {"crouch_height": 0.548, "crouch_pitch": 0.966, "com_offset": -0.073, "thrust_lean": -0.037,
                 "liftoff_hip": 1.56, "arm_swing": 3.142, "thrust_damping": 0.474, "tuck_stiffness": 3.0, "tuck_time": 0.15, "landing_lean": 0.458,
                 "open_time": 0.05, "open_blend": 0.1, "landing_knee_flexion": 0.373, "foot_delta": -0.142, "landing_foot_lead_time": 0.18,
                 "spin_placement": 0.292},
    "forward": {"crouch_height": 0.5, "crouch_pitch": 1.0, "com_offset": 0.02, "thrust_lean": 0.0,
                "liftoff_hip": -0.5, "arm_swing": 1.0, "thrust_damping": 0.3, "tuck_stiffness": 3.0, "tuck_time": 0.15, "landing_lean": 0.3,
                "open_time": 0.1, "open_blend": 0.1, "landing_knee_flexion": 0.8, "foot_delta": 0.0, "landing_foot_lead_time": 0.2,
                "spin_placement": 0.2},
}
KEEP = ("rotation", "somersaults", "flight_rotation", "first_flight_time", "com_rise", "com_travel",
        "liftoff_angular_momentum", "angular_momentum_drift", "peak_thrust_grf_body_weights", "final_com_speed",
        "fall_time", "first_touchdown_time", "foot_slide_after_landing", "landing_skid")


def evaluate(character: str, direction: str, strength: str, settings: dict) -> tuple[float, dict]:
    params = dict(settings, low_level=1, direction=DIRECTIONS.index(direction))
    trajectory = run(RunRequest("somersault", character, params=params, duration=DURATION, strength=strength))
    m = {k: trajectory.meta["metrics"].get(k) for k in KEEP}
    m["outcome"] = trajectory.meta["outcome"]
    if m["first_touchdown_time"] is None:
        return 10.0, m
    score = abs(m["rotation"] - 2 * math.pi) + 50.0 * max(0.0, (m["angular_momentum_drift"] or 0.0) - DRIFT_GOAL)
    if m["outcome"] != "success":
        up = m["fall_time"] - m["first_touchdown_time"] if m["fall_time"] is not None else 1.5
        score += 0.5 * abs(m["flight_rotation"] - 5.9) + 1.0 + 2.0 * (1.0 - min(max(up, 0.0), 1.5) / 1.5)
        score += SLIDE_WEIGHT * max(0.0, (m["foot_slide_after_landing"] or 0.0) - LANDING_SLIDE_LIMIT)
        score += SKID_WEIGHT * max(0.0, (m["landing_skid"] or 0.0) - LANDING_SKID_LIMIT)
    return score, m


def evaluate_settings(job: tuple) -> tuple[float, dict]:
    """evaluate() for one (character, direction, strength, settings) job of a process pool."""
    return evaluate(*job)


def somersault_trial(character: str, direction: str, strength: str, fixed: dict, settings: dict) -> tuple[float, dict]:
    """evaluate() of the searched ``settings`` with the ``fixed`` ones, for the search's executor."""
    return evaluate(character, direction, strength, dict(fixed, **settings))


def search(character: str, direction: str, strength: str, budget: int, population: int, seed: int,
           start: dict, verbose: bool = False, executor=None, only: list | None = None, method: str = "cma",
           refine_best: bool = True) -> tuple[float, dict, dict]:
    """A search (sim_core.tuning) from ``start``, stopped once ROBUST_CANDIDATES somersaults are
    found; then the most robust of them (most_robust)."""
    executor = executor or SerialExecutor()
    names, fixed = searched_and_fixed(SETTINGS, SPACE, only, start)
    space = Space({n: SPACE[n][direction] for n in names}, decimals=4)
    first = {n: min(max(start[n], SPACE[n][direction][0]), SPACE[n][direction][1]) for n in names}
    found_ones = StopAfterFound(lambda e: found(e.extra), ROBUST_CANDIDATES, print_evaluation if verbose else None)

    def progress(done, total, best):
        m = best.extra
        print(f"  {character} {direction} ({strength}) {done}/{total} somersaults: best score "
              f"{best.score:.3f} ({m['outcome']}, rotation {m['rotation']:.2f} rad, flight {m['flight_rotation'] or 0:.2f} rad, "
              f"take-off H {m['liftoff_angular_momentum'] or 0:.1f} kg m^2/s)", flush=True)

    result = minimize(functools.partial(somersault_trial, character, direction, strength, fixed), space, method,
                      budget, seed, start=first, sigma=0.12, population=population, progress=progress, stop=found_ones,
                      executor=executor)
    return found_ones.choose(result, fixed, (lambda found: most_robust(character, direction, strength, found, executor)) if refine_best else None)


ROBUST_CANDIDATES = 4        # somersaults found before choosing among them
ROBUST_STEP = 0.02           # rad: the neighbours' change of the lift-off hip angle and the landing lean


def most_robust(character: str, direction: str, strength: str, successes: list, executor) -> tuple[float, dict, dict]:
    """Of the somersaults found (the best few by score), the one whose eight neighbours (lift-off hip
    angle and landing lean +-0.02 rad, the settings the outcome is most sensitive to) succeed most
    often, then by score: a table entry that still lands when the state at take-off differs a little."""
    ranked = []
    for score, settings, m in sorted(successes, key=lambda s: s[0])[:ROBUST_CANDIDATES]:
        jobs = [(character, direction, strength, dict(settings, liftoff_hip=settings["liftoff_hip"] + dh,
                                                      landing_lean=settings["landing_lean"] + dl))
                for dh in (-ROBUST_STEP, 0.0, ROBUST_STEP) for dl in (-ROBUST_STEP, 0.0, ROBUST_STEP) if dh or dl]
        neighbours = sum(found(m) for _, m in executor.map(evaluate_settings, jobs))
        print(f"    candidate score {score:.3f}: {neighbours}/8 neighbours succeed", flush=True)
        ranked.append((-neighbours, score, settings, dict(m, neighbours_succeeding=neighbours)))
    _, score, settings, m = min(ranked, key=lambda r: (r[0], r[1]))
    return score, settings, m


def print_evaluation(evaluation) -> None:
    """--verbose: every run of the search, with its settings."""
    print(f"    {evaluation.score:.3f} {evaluation.extra['outcome']} {json.dumps(evaluation.settings)}", flush=True)


def found(m: dict) -> bool:
    """Balanced at the end, with the flight's angular momentum drift inside DRIFT_GOAL (a margin
    below the 1 % the tests ask for)."""
    return m["outcome"] == "success" and (m["angular_momentum_drift"] or 0.0) < DRIFT_GOAL


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--character", choices=("man", "woman"), action="append")
    parser.add_argument("--direction", choices=DIRECTIONS, action="append")
    parser.add_argument("--strength", choices=("human", "unlimited"), action="append")
    parser.add_argument("--iterations", type=int, default=12, help="batches of a search (budget: this x --population)")
    parser.add_argument("--population", type=int, default=24, help="somersaults per batch of a search")
    parser.add_argument("--budget", type=int, help="simulated somersaults each search may run "
                        "(default --iterations x --population)")
    parser.add_argument("--method", choices=("cma", "anneal"), default="cma")
    parser.add_argument("--refine", action=argparse.BooleanOptionalAction, default=True,
                        help="choose the most robust of the somersaults found (up to 32 more runs)")
    parser.add_argument("--tables", type=Path, default=None,
                        help="directory the tables are written to (default: the shipped tables, sim_core/tuned/tables); the searches start "
                             "from the shipped tables")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--fresh", action="store_true",
                        help="start from START, not from the table's entry (its calibrated row, else its best searched run)")
    parser.add_argument("--verbose", action="store_true", help="print every improvement with its settings")
    parser.add_argument("--start", help="JSON settings to start from, over the table's (or START's)")
    names_option(parser, SPACE, LANDING_SETTINGS)
    parser.add_argument("--workers", "--processes", dest="workers", type=int, default=None,
                        help="simulate the somersaults in this many processes (default: one per CPU; the same "
                             "result as 1)")
    args = parser.parse_args(argv)
    budget = args.budget if args.budget is not None else args.iterations * args.population
    with executor_for(args.workers) as executor:
        calibrate(args, budget, executor)


def calibrate(args, budget: int, executor) -> None:
    for character in args.character or ("man", "woman"):
        for direction in args.direction or DIRECTIONS:
            for strength in args.strength or ("human", "unlimited"):
                started = time.time()
                table = load_table(character)
                old = [e for e in table["somersaults"] if (e["direction"], e["strength"]) == (direction, strength)]
                searched = [e for e in table.get("not_found", []) if (e["direction"], e["strength"]) == (direction, strength)]
                previous = old or searched                   # the calibrated row, else the best searched so far
                start = {**OLD_ROW, **START[direction], **(previous[0]["settings"] if previous and not args.fresh else {})}
                if args.start:
                    start = dict(start, **json.loads(args.start))
                if not start["tuck_damping"]:                # the old rule's damping, as a searched value
                    start["tuck_damping"] = snap_damping(start["tuck_stiffness"])
                score, settings, m = search(character, direction, strength, budget, args.population,
                                            args.seed, start, args.verbose, executor, args.names, args.method,
                                            args.refine)
                keep_search(
                    "somersaults", character, "somersaults", table, {"direction": direction, "strength": strength},
                    found(m), {"settings": settings, "score": round(score, 4), "measured": m},
                    f"{m['outcome']}, angular momentum drift in flight {100 * (m['angular_momentum_drift'] or 0):.2f} %, "
                    f"rotation {m['rotation']:.2f} rad, flight rotation {m['flight_rotation'] or 0:.2f} rad, take-off "
                    f"angular momentum {m['liftoff_angular_momentum'] or 0:.1f} kg m^2/s",
                    {"script": "python -m sim_core calibrate somersault", "duration": DURATION}, args.tables)
                kept = kept_message(found(m), m["outcome"] == "success", DRIFT_GOAL, bool(old))
                print(f"{character} {direction} ({strength}): {m['outcome']}, drift {100 * (m['angular_momentum_drift'] or 0):.2f} % "
                      f"after {time.time() - started:.0f} s - {kept}")


if __name__ == "__main__":
    main()
