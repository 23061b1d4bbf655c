"""Calibrate the take-off of each platform dive by simulation and write the table the dive
behaviour reads (sim_core/tuned/tables/dives_<character>.json) - the role of the hand tuning Wooten
describes in §8.2.1 ("about five hours of effort" per dive), done by a search.

For each dive of the character the search (the search service, sim_core.tuning: CMA-ES by
default, or annealing, over the six leap settings: crouch height, torso pitch, backward COM
offset, lift-off hip angle, arm swing, thrust damping; and the twist lead of a twisting dive)
minimises

    score = 10 * hit_platform + 10 * |somersaults - wanted| + 10 * |twists - wanted| + entry
    entry = max(0, entry angle from vertical - 5 deg) / 10 deg   with the somersaults within a quarter turn,
          = 17.5 (the worst entry's)                              else          (no water entry: 100)

with every quantity read off the simulated dive. (Before the repertoire the entry term counted
whatever the rotation: a dive half a turn short but vertical then scored better than one a
quarter turn short and flat, and the searches for the 2 1/2 and 3 1/2 somersault dives stayed at
the 1 1/2 or 2 1/2 they started from; measured on the man's 205B and 107B.) The table also records the largest take-off
angular momentum seen per dive group without touching the platform, which the dive's
feasibility check uses to refuse dives the flight cannot hold.

    python -m sim_core calibrate dive                      # both characters, their dives
    python -m sim_core calibrate dive --character woman --iterations 4 --population 10
    python -m sim_core calibrate dive --character woman --only 0 --start '{"thrust_damping": 0.3}'
    python -m sim_core calibrate dive --character man --only 0 --budget 4 --no-refine --tables /tmp/t   # a quick look
    python -m sim_core calibrate dive --character man --dive 103B --platform 7.5 --budget 48 --no-refine --workers 1

``--platform H`` runs the same search from platform H (default 10 m, FINA's highest, from which every dive
is calibrated): it starts from the dive's row of the nearest platform and, where it reaches the dive, adds a
row recording ``"platform": H`` (a row without ``platform`` is from 10 m); a search from H that does not reach
the dive adds nothing (the dive from H is then planned from the nearest platform's row, sim_core.planning.dive).
The 10 m rows and the table's limits (computed from the 10 m rows only) are left as they are.

``--budget`` is the number of simulated dives the search may run per dive (default
``--iterations`` x ``--population``); the refinement's 25 runs come on top (``--no-refine``
skips it). ``--workers`` runs the dives in that many processes (the same result as 1).
"""
from __future__ import annotations

import argparse
import functools
import json
import time
from pathlib import Path

import numpy as np

ROOT = Path.cwd()                   # docs are written under the folder it runs in (the checkout)

from .behaviour import (CALIBRATED_DIVES, CALIBRATION_PLATFORM, CLOSURE_SETTINGS, FORWARD_ROTATING, GROUPS, ROTATION_TOLERANCE, Dive,
                        calibrated_row, dive_key, dive_parameters, nearest_platform_row, row_platform)
from .fina import REPERTOIRE, parse
from ... import tuned
from ...errors import ParameterError
from ...simulate import RunRequest, run
from ...tuning import Space, executor_for, minimize

SPACE = {  # name: (low, high) per group
    "crouch_height": {g: (0.4, 0.8) for g in GROUPS},
    # a torso pitched further forward in the crouch gives the back take-off far more angular
    # momentum (measured on the man's 205B: pitch 0.4 -> 30-44 kg m^2/s, 1.0 -> 129, clear of the
    # platform): the schema's whole range, so that the 2 1/2 and 3 1/2 somersault dives are in it
    "crouch_pitch": {g: (0.0, 1.5) for g in GROUPS},
    "com_offset": {"inward": (-0.25, -0.05), "back": (-0.25, -0.05), "forward": (0.05, 0.25), "reverse": (0.05, 0.25)},
    # a back or reverse take-off with the hips flexed at lift-off (-) leaves with less angular momentum, smoothly
    # (measured on the man's 205B from its stored row: -0.5 -> 70 kg m^2/s, 0 -> 92, 0.7 -> 123): his 2 1/2 and
    # 3 1/2 back dives need 70-95, which the range's old floor (0.3) left out
    "liftoff_hip": {"inward": (-2.2, -0.6), "back": (-1.0, 2.0), "forward": (-2.2, -0.6), "reverse": (-1.0, 2.0)},
    "arm_swing": {"inward": (-1.0, 3.2), "back": (1.0, 3.2), "forward": (-1.0, 3.2), "reverse": (1.0, 3.2)},
    # less damping extends the legs faster: the woman's inward take-off reached the angular
    # momentum of 2 1/2 somersaults only below ~0.6 (measured: 0.3 -> 29 kg m^2/s, 1.0 -> 22)
    "thrust_damping": {g: (0.15, 1.0) for g in GROUPS},
    "twist_lead": {g: (0.3, 1.9) for g in GROUPS},      # twisting dives only
    # the closure into the position (--closure only): the man's 407C row closing in 0.05 s at stiffness 4, damping 3
    # instead of 0.25 s at 3, 6 made 3.34 somersaults, not 3.06, with the same take-off (68 kg m^2/s)
    "tuck_time": {g: (0.05, 0.25) for g in GROUPS},
    "tuck_stiffness": {g: (2.0, 4.0) for g in GROUPS},
    "tuck_damping": {g: (1.0, 6.0) for g in GROUPS},
}


class NoLimits:
    """Lifts the feasibility limits while calibrating (the check reads the table being made)."""

    def __enter__(self):
        self.saved = Dive.limits
        Dive.limits = lambda self: {"rise": 0.3, "angular_momentum": {g: 999.0 for g in GROUPS}, "twists": 99.0}

    def __exit__(self, *exc):
        Dive.limits = self.saved


def evaluate(character: str, dive: dict, settings: dict) -> tuple[float, dict]:
    params = dict(dive, low_level=1, **settings)
    try:
        trajectory = run(RunRequest("dive", character, params=params, duration=4.5))
    except ParameterError:
        return 100.0, {}
    m = dict(trajectory.meta["metrics"], outcome=trajectory.meta["outcome"])
    if not m.get("entered_water"):
        return 100.0, m
    short = abs(m["somersaults"] - dive["somersaults"])
    entry = (max(0.0, m["entry_angle_from_vertical_deg"] - 5.0) if short <= ROTATION_TOLERANCE else 180.0 - 5.0) / 10.0
    score = 10.0 * m["hit_platform"] + 10.0 * short + 10.0 * abs(m["twists"] - dive["twists"]) + entry
    if m["somersault_direction"] != ("forward" if GROUPS[dive["group"]] in FORWARD_ROTATING else "backward"):
        score += 10.0
    return score, m


def dive_trial(character: str, dive: dict, settings: dict) -> tuple[float, dict]:
    """evaluate() under the calibration's lifted limits, for a search's executor (a worker
    process does not inherit the NoLimits of the parent's with-block)."""
    with NoLimits():
        return evaluate(character, dive, settings)


def search(character: str, dive: dict, budget: int, population: int, seed: int, start: dict | None = None,
           method: str = "cma", executor=None, refine_best: bool = True, closure: bool = False) -> dict:
    """A search (sim_core.tuning) from the middle of the space, or from ``start`` (the table's
    present settings for this dive and ``--start``; a setting it lacks starts from the middle of
    its range) with a narrower spread, stopped at the first dive that lands balanced within 8 deg
    of vertical; then ``refine``. ``closure``: the position's closure (CLOSURE_SETTINGS) is searched too; else
    a row runs the schema's defaults for it, as every row calibrated before it."""
    group = GROUPS[dive["group"]]
    names = [n for n in SPACE if (n != "twist_lead" or dive["twists"]) and (closure or n not in CLOSURE_SETTINGS)]
    space = Space({n: SPACE[n][group] for n in names}, decimals=4)
    start = start or {}
    first = {n: start.get(n, 0.5 * sum(SPACE[n][group])) for n in names}
    spreads = [0.12 if n in start else 0.35 for n in names]       # a share of each range

    def progress(done, total, best):
        m = best.extra or {}
        print(f"  {character} {group} {done}/{total} dives: best score {best.score:.3f} "
              f"({m.get('outcome')}, {m.get('somersaults', 0):.2f} somersaults, {m.get('twists', 0):.2f} twists, "
              f"entry {m.get('entry_angle_from_vertical_deg', 0):.0f} deg)", flush=True)

    def landed(evaluation) -> bool:
        m = evaluation.extra
        return m.get("outcome") == "success" and m.get("entry_angle_from_vertical_deg", 90) < 8.0

    result = minimize(functools.partial(dive_trial, character, dive), space, method, budget, seed, start=first,
                      sigma=1.0 if method == "cma" else 0.25, population=population, progress=progress,
                      stop=landed, executor=executor,
                      options={"CMA_stds": spreads} if method == "cma" else None)
    momentum = max([abs(e.extra["takeoff_angular_momentum"]) for e in result.evaluations
                    if e.extra.get("entered_water") and not e.extra.get("hit_platform")] + [0.0])
    best = (result.best.score, result.best.settings, result.best.extra)
    if refine_best:
        best = refine(character, dive, best, names, space.low, space.high, executor)
    score, settings, m = best
    keep = ("outcome", "somersaults", "twists", "entry_angle_from_vertical_deg", "takeoff_angular_momentum",
            "flight_time", "angular_momentum_drift", "hit_platform")
    return {**{k: v for k, v in dive.items() if k != "platform_height"}, "settings": settings, "score": round(float(score), 4),
            "measured": {k: m.get(k) for k in keep}, "largest_momentum_clear": round(momentum, 2)}


REFINE = {True: ("liftoff_hip", "twist_lead"), False: ("liftoff_hip", "com_offset")}
REFINE_STEPS = 5
REFINE_SPAN = 0.06          # share of each range either side of the best


def refine(character: str, dive: dict, best: tuple, names: list, low, high, executor) -> tuple:
    """A grid over the two settings the dive is most sensitive to (the lift-off hip angle, and
    the twist lead or the lean), around the search's best, +-6 % of their ranges; keeps the cell
    whose own score plus its neighbours' mean is lowest, so that the table holds a setting that
    still works when the state at take-off differs a little."""
    first, second = REFINE[bool(dive["twists"])]
    i, j = names.index(first), names.index(second)
    centre = best[1]
    axes = [np.clip(centre[n] + np.linspace(-REFINE_SPAN, REFINE_SPAN, REFINE_STEPS) * (high[k] - low[k]), low[k], high[k])
            for n, k in ((first, i), (second, j))]
    grid = np.full((REFINE_STEPS, REFINE_STEPS), np.inf)
    cells = [(a, b) for a in range(REFINE_STEPS) for b in range(REFINE_STEPS)]
    jobs = [dict(centre, **{first: round(float(axes[0][a]), 4), second: round(float(axes[1][b]), 4)}) for a, b in cells]
    runs = {}
    for (a, b), settings, (score, m) in zip(cells, jobs, executor.map(functools.partial(dive_trial, character, dive),
                                                                       jobs)):
        grid[a, b] = score
        runs[a, b] = (score, settings, m)
    robust = np.full_like(grid, np.inf)
    for a in range(REFINE_STEPS):
        for b in range(REFINE_STEPS):
            around = grid[max(a - 1, 0):a + 2, max(b - 1, 0):b + 2]
            robust[a, b] = grid[a, b] + np.mean(around)
    if not (grid < 2.0).any():
        print(f"  {character} {GROUPS[dive['group']]} refined over {first} x {second}: no cell scores < 2; "
              f"keeping the search's best ({best[0]:.3f})", flush=True)
        return best if best[0] <= grid.min() else runs[np.unravel_index(np.argmin(grid), grid.shape)]
    a, b = np.unravel_index(np.argmin(robust), robust.shape)
    print(f"  {character} {GROUPS[dive['group']]} refined over {first} x {second}: "
          f"{np.sum(grid < 2.0)} of {grid.size} cells score < 2; chosen score {grid[a, b]:.3f}", flush=True)
    return runs[a, b]


def table_limits(dives: list[dict]) -> dict:
    """What the dive's feasibility check allows: per group the largest take-off angular momentum
    seen without touching the platform; the most twists a calibrated dive made while its
    somersaults were right (within a quarter turn); of the rows from 10 m (the lower platforms' rows
    leave the limits as the 10 m calibration measured them)."""
    dives = [d for d in dives if abs(row_platform(d) - CALIBRATION_PLATFORM) < 1e-9]
    twists = [d["measured"]["twists"] for d in dives
              if d["measured"].get("somersaults") is not None and not d["measured"].get("hit_platform")
              and abs(d["measured"]["somersaults"] - d["somersaults"]) <= 0.25]
    return {"rise": 0.3,
            "angular_momentum": {group: max([d["largest_momentum_clear"] for d in dives
                                             if GROUPS[d["group"]] == group] + [0.0]) for group in GROUPS},
            "twists": round(max(twists + [0.0]), 3)}


def calibration_dives(character: str) -> list[dict]:
    """The dives calibrated for ``character``, in its table's order: CALIBRATED_DIVES (the seed's
    and the first beyond it), then the rest of the FINA repertoire; each with its number."""
    repertoire = {n: dive_key(dive_parameters(n)) for n in REPERTOIRE}
    seed = [dive_key(d) for d in CALIBRATED_DIVES[character]]
    keys = seed + [key for key in repertoire.values() if key not in seed]
    return [dict(number=next(n for n, k in repertoire.items() if k == key), **key) for key in keys]


def better(old: dict | None, new: dict) -> dict:
    """A search's row, or the dive's old row where that scored better (a second search of a dive
    not reached keeps the first's best); the largest momentum either reached clear of the platform."""
    kept = new if old is None or new["score"] <= old.get("score", float("inf")) else old
    return dict(kept, largest_momentum_clear=max(new["largest_momentum_clear"], (old or {}).get("largest_momentum_clear", 0.0)))


def reached(row: dict | None) -> bool:
    """A table row whose search reached its dive (the measured outcome a success)."""
    return row is not None and row.get("measured", {}).get("outcome") == "success"


def nearest_momentum(table: dict | None, character: str, dive: dict) -> dict:
    """Where a dive without its own row starts: the settings of the table's dive of the same group
    whose measured take-off angular momentum is nearest the one this dive needs
    (Dive.momentum_needed_by; the search then has the rotation near, not only the name)."""
    rows = [d for d in (table or {}).get("dives", []) if d["group"] == dive["group"] and d.get("measured")]
    if not rows:
        return {}
    needed = Dive.momentum_needed_by(character, Dive.schema.validate({n: dive[n] for n in dive if n != "number"}))
    return dict(min(rows, key=lambda d: abs(abs(d["measured"]["takeoff_angular_momentum"]) - needed))["settings"])


def chosen(dives: list[dict], only: list | None, numbers: list | None) -> set[int]:
    """Indices of the dives to search: ``--only`` indices and ``--dive`` numbers; all without either."""
    if only is None and numbers is None:
        return set(range(len(dives)))
    wanted = {parse(n).number for n in numbers or []}
    unknown = wanted - {d["number"] for d in dives}
    if unknown:
        raise ParameterError(f"--dive {', '.join(sorted(unknown))}: not in the repertoire; allowed: {', '.join(REPERTOIRE)}")
    return set(only or []) | {k for k, d in enumerate(dives) if d["number"] in wanted}


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--character", choices=sorted(CALIBRATED_DIVES), action="append")
    parser.add_argument("--iterations", type=int, default=5, help="batches of the search (budget: this x --population)")
    parser.add_argument("--population", type=int, default=12, help="dives per batch of the search")
    parser.add_argument("--budget", type=int, help="simulated dives the search may run per dive "
                        "(default --iterations x --population)")
    parser.add_argument("--method", choices=("cma", "anneal"), default="cma")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--workers", type=int, default=None, help="processes running the dives (default: one per "
                        "CPU; the same result as 1)")
    parser.add_argument("--refine", action=argparse.BooleanOptionalAction, default=True,
                        help="the robustness grid after the search (25 dives)")
    parser.add_argument("--tables", type=Path, default=None,
                        help="directory the table is written to (default: the shipped tables, sim_core/tuned/tables; read from there too)")
    parser.add_argument("--limits-only", action="store_true",
                        help="only recompute the table's limits from its rows (after a change of this script's rules)")
    parser.add_argument("--fresh", action="store_true", help="search from the middle of the space, not from the table")
    parser.add_argument("--start", help="JSON settings to start from, over the table's")
    parser.add_argument("--only", type=int, action="append",
                        help="calibrate only the dive with this index in the character's list; keep the others' table rows")
    parser.add_argument("--platform", type=float, default=CALIBRATION_PLATFORM,
                        help="platform height (m) the dives are searched from; a reached dive adds a row with this "
                             "platform (default: 10 m, the table's main rows)")
    parser.add_argument("--closure", action="store_true",
                        help="search the position's closure (tuck_time, tuck_stiffness, tuck_damping) with the take-off")
    parser.add_argument("--dive", action="append",
                        help="calibrate only this FINA dive of the repertoire (e.g. 107C; repeatable); keep the others' rows")
    args = parser.parse_args(argv)
    budget = args.budget if args.budget is not None else args.iterations * args.population
    for character in args.character or sorted(CALIBRATED_DIVES):
        started = time.time()
        stored = tuned.load("dives", character, args.tables) or tuned.load("dives", character)  # where it starts
        old = stored["dives"] if stored is not None else []
        if args.limits_only:
            table = dict(stored, limits=table_limits(old))
            path = tuned.save("dives", character, table, strengths=["human"], directory=args.tables)
            print(f"{character}: limits {table['limits']}")
            continue
        todo = calibration_dives(character)
        searched = chosen(todo, args.only, args.dive)
        here = args.platform
        main = abs(here - CALIBRATION_PLATFORM) < 1e-9
        asked = [dict(d, platform_height=here) for d in todo]
        rows = [calibrated_row(stored, d) if stored is not None else None for d in asked]
        # a search starts from the dive's own row if it reached the dive (from another platform: the row of the
        # nearest platform, where that reached it), else from nearest_momentum's
        near = [nearest_platform_row(stored, d) if stored is not None else None for d in asked]
        starts = [dict({} if args.fresh else row["settings"] if reached(row) else nearest_momentum(stored, character, d),
                       **json.loads(args.start or "{}")) for d, row in zip(todo, near)]
        how = {"budget": budget, "population": args.population, "seed": args.seed, "method": args.method,
               "refine": args.refine, "fresh": args.fresh, "start": args.start,
               **({"closure": True} if args.closure else {})}     # a platform row's own search
        dives = []
        with executor_for(args.workers) as executor:
            for k, dive in enumerate(todo):
                key = {n: v for n, v in dive.items() if n != "number"}
                if k in searched:
                    found = search(character, dict(key, platform_height=here), budget, args.population, args.seed,
                                   starts[k], args.method, executor, args.refine, args.closure)
                    if main:
                        dives.append({"number": dive["number"], **better(rows[k], found)})
                    elif reached(found) or rows[k] is not None:
                        kept = better(rows[k], found)
                        dives.append({"number": dive["number"], **{n: v for n, v in kept.items() if n != "platform"},
                                      "platform": here, **({"search": how} if kept["settings"] == found["settings"] else {})})
                    else:
                        print(f"  {character} {dive['number']} from {here:g} m: not reached, no row added", flush=True)
                elif rows[k] is not None:
                    dives.append({"number": dive["number"], **rows[k]})
        # the rows of the other platforms as they were: the 10 m rows first, in the table's order
        others = [d for d in (stored or {}).get("dives", []) if abs(row_platform(d) - here) > 1e-9]
        dives = others + dives if not main else dives + others
        limits = table_limits(dives)
        path = tuned.save("dives", character, {"script": "python -m sim_core calibrate dive",
                                               "search": ({**vars(args), "tables": str(args.tables), "budget": budget}
                                                          if main or stored is None else stored.get("search")),
                                               "dives": dives, "limits": limits}, strengths=["human"],
                          directory=args.tables)
        print(f"{character}: wrote {path} in {time.time() - started:.0f} s")
        for d in dives:
            print(f"  {d['measured']}")


if __name__ == "__main__":
    main()
