"""Calibrate the back handspring by simulation and write the table the handspring behaviour reads
(sim_core/tuned/tables/handspring_<character>.json) - the role of the tuning Wooten describes in §8.3 ("the
aspect of this maneuver that required the most tuning was generating sufficient backwards angular
velocity to land in a handstand position"), done by a search.

For a character and strength, a search (the search service, sim_core.tuning: CMA-ES by default,
or annealing) over the settings of every step (the sit,
the thrust and arm swing, the arched flight, the hands' stiffness, the push's delay, moves and
damping, the snap-down and the landing; the flights' physics step, `flight_step_division`, is not
searched: it stays as started, 1 in rows made before it, `--start '{"flight_step_division": 8}'`) minimises, with every quantity read off the simulated handspring
(sim_core.skills.handspring.behaviour.handspring_assess):

    score = (2 pi - min(rotation before any fall, 2 pi))        how far it turned before it fell
          + 3 [no hand contact] + 2 [no second flight] + 1.5 [feet still down when the hands land]
          + 4 max(0, COM rise - 0.3 m)                          a handspring is low, not a high jump
          + 0.5 max(0, |touchdown vx| - 1 m/s) + 0.3 max(0, |touchdown vz| - 2 m/s)
          + 0.5 |rotation - 2 pi|                               the whole skill turns once
          + 50 max(0, angular momentum drift in a flight - 0.9 %)
          + (1 + 2 (1 - min(time on the feet after touchdown before a fall, 1.5 s) / 1.5 s))   unless it succeeds
          + 0.5 [rebound: the feet leave the ground again after the landing] + 4 min(landing skid, 0.5 m)
          + 10 (m the pelvis went below the deepest crouch, 0.30 m, in the sit: a fall)

A handspring that succeeds is kept with its measurements (and with how many of its eight
neighbours - push delay and landing lean +-0.01 - succeed too); where none did, the best run is
recorded under "not_found" and the behaviour refuses that handspring with it. The search starts
from the table's entry (or from --start) and writes the table only when it found one.

    python -m sim_core calibrate handspring --character man --strength unlimited --workers 2
    python -m sim_core calibrate handspring --budget 4 --no-refine --tables /tmp/t     # a quick look

``--budget`` is the number of simulated handsprings the search may run (default ``--iterations`` x
``--population``); choosing the most robust of the handsprings found runs up to 32 more
(``--no-refine`` keeps the best by score). ``--workers`` (or ``--processes``) runs them in that
many processes (the same result as 1).
"""
from __future__ import annotations

import argparse
import functools
import json
import math
import time
from pathlib import Path

ROOT = Path.cwd()                   # docs are written under the folder it runs in (the checkout)

from .behaviour import HAND_SETTINGS, OLD_ROW, SETTINGS, Handspring, load_table
from ...control.tuned import keep_search, kept_message, names_option, searched_and_fixed
from ...simulate import RunRequest, run
from ...tuning import Space, StopAfterFound, executor_for, minimize

DURATION = 5.0
DRIFT_GOAL = 0.009           # angular momentum drift in flight the search aims below (the tests' limit is 1 %)
MAX_RISE = 0.3               # m of COM rise above standing before the score objects
SPACE = {                    # name: (low, high) of the search (inside the schema's ranges)
    "crouch_height": (0.55, 0.75), "crouch_pitch": (0.2, 1.1), "com_offset": (-0.25, -0.1), "sit_extra": (0.0, 0.25),
    "thrust_lean": (-0.4, -0.1), "liftoff_hip": (0.0, 0.5), "arm_swing": (2.0, 3.1), "arm_gain": (2.0, 10.0),
    "arm_time": (0.06, 0.2), "thrust_damping": (0.2, 1.0), "arch_arm": (1.6, 3.0), "arch_hip": (0.0, 0.5),
    "neck": (-0.8, 0.0), "hand_gain": (1.0, 15.0), "push_delay": (0.0, 0.15), "push_shoulder": (1.5, 3.1),
    "push_hip": (-1.5, 0.3), "snap_knee": (0.0, 1.0), "ready_height": (0.0, 0.7), "push_move": (0.05, 0.25), "push_gain": (1.0, 8.0), "push_damping": (0.5, 8.0), "landing_lean": (0.0, 1.5),
    "open_height": (0.5, 1.0), "landing_knee_flexion": (0.3, 0.9), "foot_delta": (-0.3, 0.1), "landing_foot_lead_time": (0.0, 0.4),
    "spin_placement": (0.0, 0.5),
}
KEEP = ("rotation", "rotation_before_fall", "rotation_at_hands", "com_rise", "com_travel", "liftoff_angular_momentum",
        "liftoff_velocity", "first_flight_time", "hand_contact_time", "second_flight_time", "touchdown_velocity",
        "angular_momentum_drift", "landing_skid", "rebounds", "fall_time", "touchdown_time", "final_com_speed",
        "feet_down_at_hands", "sit_shortfall", "time_on_feet")
NEIGHBOUR_STEP = {"push_delay": 0.01, "landing_lean": 0.01}


def evaluate(job) -> tuple[float, dict]:
    character, strength, settings = job
    params = dict(settings, low_level=1)
    trajectory = run(RunRequest("handspring", character, params=params, duration=DURATION, strength=strength))
    m = {k: trajectory.meta["metrics"].get(k) for k in KEEP}
    m["outcome"] = trajectory.meta["outcome"]
    return score(m), m


def score(m: dict) -> float:
    s = 2 * math.pi - min(m["rotation_before_fall"], 2 * math.pi)
    s += 3.0 * (m["rotation_at_hands"] is None) + 2.0 * (m["second_flight_time"] is None)
    s += 1.5 * bool(m["feet_down_at_hands"])
    s += 4.0 * max(0.0, m["com_rise"] - MAX_RISE)
    if m["touchdown_velocity"] is not None:
        vx, _, vz = m["touchdown_velocity"]
        s += 0.5 * max(0.0, abs(vx) - 1.0) + 0.3 * max(0.0, abs(vz) - 2.0)
    s += 0.5 * abs(m["rotation"] - 2 * math.pi)
    s += 50.0 * max(0.0, (m["angular_momentum_drift"] or 0.0) - DRIFT_GOAL)
    if m["outcome"] != "success":
        s += 1.0 + 2.0 * (1.0 - min(m["time_on_feet"] or 0.0, 1.5) / 1.5)
    s += 0.5 * bool(m["rebounds"]) + 10.0 * m["sit_shortfall"] + 4.0 * min(m["landing_skid"] or 0.0, 0.5)
    return s


def print_evaluation(evaluation) -> None:
    """--verbose: every run of the search, with its settings."""
    print(f"    {evaluation.score:.3f} {evaluation.extra['outcome']} {json.dumps(evaluation.settings)}", flush=True)


def found(m: dict) -> bool:
    return m["outcome"] == "success" and (m["angular_momentum_drift"] or 0.0) < DRIFT_GOAL


def handspring_trial(character: str, strength: str, fixed: dict, settings: dict) -> tuple[float, dict]:
    """evaluate() of the searched ``settings`` with the ``fixed`` ones, for the search's executor."""
    return evaluate((character, strength, dict(fixed, **settings)))


def search(character: str, strength: str, budget: int, population: int, seed: int, start: dict,
           executor, verbose: bool = False, spread: float = 0.15, only: list | None = None,
           method: str = "cma", refine_best: bool = True) -> tuple[float, dict, dict]:
    """A search (sim_core.tuning) from ``start``, stopped once ROBUST_CANDIDATES handsprings are
    found; then the most robust of them (most_robust)."""
    names, fixed = searched_and_fixed(SETTINGS, SPACE, only, start)
    space = Space({n: SPACE[n] for n in names}, decimals=4)
    first = {n: min(max(start[n], SPACE[n][0]), SPACE[n][1]) for n in names}
    found_ones = StopAfterFound(lambda e: found(e.extra), ROBUST_CANDIDATES, print_evaluation if verbose else None)

    def progress(done, total, best):
        m = best.extra
        print(f"  {character} ({strength}) {done}/{total} handsprings: best score {best.score:.3f} "
              f"({m['outcome']}, rotation {m['rotation']:.2f} rad, before a fall {m['rotation_before_fall']:.2f}, "
              f"rise {m['com_rise']:.2f} m); {len(found_ones.found)} found", flush=True)

    result = minimize(functools.partial(handspring_trial, character, strength, fixed), space, method, budget, seed,
                      start=first, sigma=spread, population=population, progress=progress, stop=found_ones,
                      executor=executor)
    return found_ones.choose(result, fixed, (lambda found: most_robust(executor, character, strength, found)) if refine_best else None)


ROBUST_CANDIDATES = 4        # handsprings found before choosing among them


def most_robust(executor, character, strength, successes) -> tuple[float, dict, dict]:
    """Of the handsprings found (the best four by score), the one whose eight neighbours (push
    delay and landing lean a step either way) succeed most often, then by score."""
    ranked = []
    for s, settings, m in sorted(successes, key=lambda r: r[0])[:ROBUST_CANDIDATES]:
        jobs = []
        for a in (-1, 0, 1):
            for b in (-1, 0, 1):
                if a or b:
                    near = dict(settings)
                    near["push_delay"] = max(0.0, near["push_delay"] + a * NEIGHBOUR_STEP["push_delay"])
                    near["landing_lean"] = near["landing_lean"] + b * NEIGHBOUR_STEP["landing_lean"]
                    jobs.append((character, strength, near))
        neighbours = sum(found(r[1]) for r in executor.map(evaluate, jobs))
        print(f"    candidate score {s:.3f}: {neighbours}/8 neighbours succeed", flush=True)
        ranked.append((-neighbours, s, settings, dict(m, neighbours_succeeding=neighbours)))
    _, s, settings, m = min(ranked, key=lambda r: (r[0], r[1]))
    return s, settings, m


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--character", choices=("man", "woman"), default="man")
    parser.add_argument("--strength", choices=("human", "unlimited"), default="unlimited")
    parser.add_argument("--iterations", type=int, default=30, help="batches of the search (budget: this x --population)")
    parser.add_argument("--population", type=int, default=40, help="handsprings per batch of the search")
    parser.add_argument("--budget", type=int, help="simulated handsprings the search may run "
                        "(default --iterations x --population)")
    parser.add_argument("--method", choices=("cma", "anneal"), default="cma")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--workers", "--processes", dest="workers", type=int, default=None,
                        help="processes running the handsprings (default: one per CPU; the same result as 1)")
    parser.add_argument("--spread", type=float, default=0.15,
                        help="the search's first step, as a share of each setting's search range")
    parser.add_argument("--refine", action=argparse.BooleanOptionalAction, default=True,
                        help="choose the most robust of the handsprings found (up to 32 more runs)")
    parser.add_argument("--tables", type=Path, default=None,
                        help="directory the table is written to (default: the shipped tables, sim_core/tuned/tables); the search starts from "
                             "the shipped table")
    parser.add_argument("--verbose", action="store_true", help="print every improvement with its settings")
    parser.add_argument("--start", help="JSON settings to start from, over the table's (or the schema's defaults)")
    names_option(parser, SPACE, HAND_SETTINGS)
    args = parser.parse_args(argv)
    started = time.time()
    table = load_table(args.character)
    old = [e for e in table["handsprings"] if e["strength"] == args.strength]
    defaults = {k: v for k, v in Handspring.schema.defaults().items() if k in SETTINGS}
    start = {**defaults, **OLD_ROW, **(old[0]["settings"] if old else {}), **json.loads(args.start or "{}")}
    start["push_damping"] = start["push_damping"] or start["push_gain"]     # the old rule, as a searched value
    budget = args.budget if args.budget is not None else args.iterations * args.population
    with executor_for(args.workers) as executor:
        s, settings, m = search(args.character, args.strength, budget, args.population, args.seed, start,
                                executor, args.verbose, args.spread, args.names, args.method, args.refine)
    keep_search("handspring", args.character, "handsprings", table, {"strength": args.strength}, found(m),
                {"settings": settings, "score": round(s, 4), "measured": m},
                f"{m['outcome']}, rotation {m['rotation']:.2f} rad ({m['rotation_before_fall']:.2f} before falling), "
                f"angular momentum drift in flight {100 * (m['angular_momentum_drift'] or 0):.2f} %",
                {"script": "python -m sim_core calibrate handspring", "duration": DURATION}, args.tables)
    kept = kept_message(found(m), m["outcome"] == "success", DRIFT_GOAL, bool(old))
    print(f"{args.character} ({args.strength}): {m['outcome']}, drift {100 * (m['angular_momentum_drift'] or 0):.2f} % "
          f"after {time.time() - started:.0f} s - {kept}")


if __name__ == "__main__":
    main()
