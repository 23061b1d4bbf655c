"""Calibrate the landing's foot servo delta against horizontal speed and touchdown speed (the
role of Wooten's Table 6.1, which is for one drop height): for each drop of the grid's drops and each
horizontal speed, land with a range of deltas and keep the middle of the longest run of
neighbouring deltas that end balanced (feet staying where they touched down; see leap_assess),
and write sim_core/tuned/tables/landing_<character>.json, which the landing reads: one row per drop, keyed by
the vertical touchdown speed of that drop, interpolated between them. Then the extra delta for
fast touchdowns (high drops and leaps, vertical touchdown speed above FAST_FROM): the one of
fast deltas that lands the most drops from rest of the high drops (the smallest on a tie). The grid
is the man's (below) for the man, and for another body the man's scaled by Fig. 6: drops and
deltas by L, speeds by L^1/2 (a child's landing windows are a third of the man's 2 cm step wide,
and its drops a third of his). Rerun after a change to the model or the controllers:

    python -m sim_core calibrate land [--character man woman] [--processes 2]

Then (``--drop-limits``, on the stored table) the drops and sideways speeds it lands, which the land
skill offers and refuses beyond (landing_drops, landing_side_speed): at each horizontal speed it
serves, drops up from its highest row and down from its lowest until one falls, each planned and
run as ``simulate land`` runs it:

    python -m sim_core calibrate land --drop-limits [--character man woman child imaginary_runner]
"""
from __future__ import annotations

import argparse
import sys
from multiprocessing import Pool
from pathlib import Path

ROOT = Path.cwd()                   # docs are written under the folder it runs in (the checkout)

from ...ballistics import GRAVITY
from ... import tuned
from ...control.leap import LANDING_TABLE, landing_speeds  # noqa: F401  (declares the landing table's row type)
from ...character.spec import character_name
from ...planning.land import plan_landing
from ...simulate import RunRequest, StartState, run
from .calibrate_grid import grid


def fast_touchdown(character: str, table: dict) -> dict | None:
    """Scan the extra delta for fast touchdowns one value at a time (each trial reads the table);
    None if the sweep's table serves no speed (no landing of it balanced: nothing to add to)."""
    if not any(row["speed"] for row in table["foot_delta"]):
        return None
    landed, name, g = {}, character_name(character), grid(character)
    for extra in g.fast_deltas:
        tuned.save("landing", name, dict(table, fast_touchdown={"speed": g.fast_from, "ramp": g.fast_ramp, "delta": extra}),
                   strengths=["human"])
        landed[extra] = [drop for drop in g.high_drops
                         if run(RunRequest("land", character, start=StartState(height=drop), duration=3.0)).meta["outcome"] == "success"]
        print(f"  {character} fast touchdown extra {extra:+.2f} m: lands drops {landed[extra]}")
    best = max(g.fast_deltas, key=lambda e: (len(landed[e]), -abs(e)))
    return {"speed": g.fast_from, "ramp": g.fast_ramp, "delta": best, "landed": {str(k): v for k, v in landed.items()}}


def trial(args):
    character, drop, speed, delta = args
    traj = run(RunRequest("land", character, params=dict(foot_delta=delta, landing_table=0.0),
                          start=StartState(height=drop, velocity=(speed, 0.0, 0.0)), duration=3.0))
    return drop, speed, delta, traj.meta["outcome"] == "success"


def middle_of_longest_run(ok: list[float], deltas: list[float]) -> float:
    """The delta in the middle of the longest run of neighbouring successful deltas (the most
    margin on both sides)."""
    runs, current = [], []
    for d in deltas:
        if d in ok:
            current.append(d)
        else:
            runs.append(current)
            current = []
    runs.append(current)
    best = max(runs, key=len)
    return best[(len(best) - 1) // 2]      # a delta that was run (of an even run, the lower middle one)


def calibrate(character: str, processes: int) -> dict:
    """The sweep, each trial placing the feet by its delta alone (landing_table=0: calibrated against
    no table, so a character with none yet can be calibrated and a stored one is not touched)."""
    g = grid(character)
    with Pool(processes) as pool:
        results = pool.map(trial, [(character, h, v, d) for h in g.drops for v in g.speeds for d in g.deltas])
    rows, landed = [], {}
    for h in g.drops:
        speeds, deltas = [], []
        landed[str(h)] = {}
        for v in g.speeds:
            ok = [d for drop, s, d, success in results if drop == h and s == v and success]
            landed[str(h)][str(v)] = ok
            print(f"  {character} drop {h:.2f} m at {v:+.2f} m/s: balanced with deltas {ok}")
            if ok:
                speeds.append(v)
                deltas.append(round(middle_of_longest_run(ok, g.deltas), 4))
        rows.append({"drop": h, "touchdown_speed": round((2.0 * GRAVITY * h) ** 0.5, 3),
                     "speed": speeds, "delta": deltas})
    return {"script": "python -m sim_core calibrate land", "foot_delta": rows,
            "landed": landed}


def _lands(character: str, drop: float, speed: float, side: float = 0.0) -> bool:
    """One start landed as ``simulate land`` lands it: planned (planning/land.py), then run."""
    request, _ = plan_landing(RunRequest("land", character, start=StartState(height=drop, velocity=(speed, side, 0.0)),
                                         duration=3.0))
    return run(request).meta["outcome"] == "success"


def _last_landed(character: str, values: list, start) -> float:
    """The last of ``values`` (tried in order, ``start(value)`` -> lands?) before the first that
    does not land; None if the first does not."""
    last = None
    for value in values:
        if not start(value):
            break
        last = value
    return last


def drop_limits(character: str, table: dict) -> dict:
    """The drops and sideways speeds the table lands (landing_drops, landing_side_speed), measured
    with the landing's plan at each of its calibrated forward speeds it serves: up from its
    highest row's drop and down from its lowest by the grid's limit drops until one falls; then
    the sideways speeds (side_limit)."""
    g, name = grid(character), character_name(character)
    low, high = landing_speeds(table)
    speeds = sorted({low, high} | {v for v in g.speeds if low <= v <= high})
    drops = [row["drop"] for row in table["foot_delta"] if row["speed"]]
    limits = {"speeds": speeds, "low": [], "high": []}
    for speed in speeds:
        up = _last_landed(character, g.limit_high_drops, lambda h: _lands(character, h, speed))
        down = _last_landed(character, g.limit_low_drops, lambda h: _lands(character, h, speed))
        limits["high"].append(max(drops) if up is None else up)
        limits["low"].append(min(drops) if down is None else down)
        print(f"  {name} at {speed:+.3f} m/s: lands drops {limits['low'][-1]:.3f}-{limits['high'][-1]:.3f} m", flush=True)
    limits["side"] = side_limit(character, table)
    limits["script"] = "python -m sim_core calibrate land --drop-limits"
    return limits


def side_limit(character: str, table: dict) -> float:
    """The sideways speed (m/s, either way) landed from the table's highest row's drop at its slowest,
    no and fastest forward speed: the grid's side speeds in order until one falls, the least of the
    three (offered up to that drop; a higher drop lands straight only, landing_side_speed)."""
    low, high = landing_speeds(table)
    top = max(row["drop"] for row in table["foot_delta"] if row["speed"])
    sides = []
    for speed in sorted({low, high} | ({0.0} if low <= 0.0 <= high else set())):
        side = _last_landed(character, grid(character).limit_side_speeds, lambda s: _lands(character, top, speed, s))
        sides.append(0.0 if side is None else side)
        print(f"  {character_name(character)} from {top:.3f} m at {speed:+.3f} m/s: lands sideways up to "
              f"{sides[-1]:.3f} m/s", flush=True)
    return min(sides)


def measure_drop_limits(character: str) -> Path:
    """``drop_limits`` measured on the stored table (its trials run with the limits open) and
    written into it; a stopped measurement leaves the table byte for byte."""
    name = character_name(character)
    table = tuned.load("landing", name)
    if table is None:
        raise SystemExit(f"{name} has no landing table: python -m sim_core calibrate land --character {name} first")
    table = {k: v for k, v in table.items() if k != "drop_limits"}        # the body (load drops the header)
    open_limits = {"speeds": [0.0], "low": [0.0], "high": [float("inf")], "side": float("inf")}
    with tuned.provisional("landing", name) as stored:
        tuned.save("landing", name, dict(table, drop_limits=open_limits), strengths=["human"])
        table["drop_limits"] = drop_limits(character, table)
        path = tuned.save("landing", name, table, strengths=["human"])
        stored.keep()
    return path


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--character", nargs="+", default=["man", "woman"])
    parser.add_argument("--processes", type=int, default=2)
    parser.add_argument("--drop-limits", action="store_true",
                        help="only measure the drops and sideways speeds the stored table lands (landing_drops) and "
                             "write them into it")
    args = parser.parse_args(argv)
    if args.drop_limits:
        for character in args.character:
            print(f"wrote {measure_drop_limits(character).relative_to(ROOT)}: drop_limits")
        return 0
    for character in args.character:
        table = calibrate(character, args.processes)
        # the fast-touchdown scan runs its trials with the candidate as the character's table; a
        # stopped scan leaves the table that was there, byte for byte
        with tuned.provisional("landing", character_name(character)) as stored:
            fast = fast_touchdown(character, table)
            if fast is not None:
                table["fast_touchdown"] = fast
            path = tuned.save("landing", character_name(character), table, strengths=["human"])
            stored.keep()
        for row in table["foot_delta"]:
            print(f"wrote {path.relative_to(ROOT)}: drop {row['drop']} m, speeds {row['speed']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
