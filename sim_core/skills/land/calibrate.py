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
"""
from __future__ import annotations

import argparse
import sys
from multiprocessing import Pool
from pathlib import Path

ROOT = Path.cwd()                   # docs are written under the folder it runs in (the checkout)

from ...ballistics import GRAVITY
from ... import tuned
from ...control.leap import LANDING_TABLE  # noqa: F401  (declares the landing table's row type)
from dataclasses import dataclass

from ...character.dimensions import leg_length_ratio
from ...character.spec import CharacterSpec, character_name, load_character
from ...simulate import RunRequest, StartState, run

SPEEDS = [-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0]
DELTA_STEP = 0.02            # m between the deltas tried (the landing's plan steps by a share of it, x L)
DELTAS = [round(-0.3 + DELTA_STEP * k, 2) for k in range(28)]     # -0.30 ... 0.24 m
DROPS = (0.2, 0.4, 0.6)      # m above standing: 0.2 puts the COM at about Wooten's 1.25 m (man) and
                             # lands like a standing broad jump (0.45 s in the air); 0.6 lands like a
                             # 0.6 m leap (forefoot first)


FAST_FROM, FAST_RAMP = 3.9, 0.2     # m/s: the extra delta ramps in over this vertical touchdown speed
FAST_DELTAS = [0.0, 0.02, 0.04, 0.06, 0.08]
HIGH_DROPS = [0.8, 0.9, 1.0, 1.1, 1.15, 1.2, 1.3]


@dataclass(frozen=True)
class Grid:
    """What the calibration tries for one body (the constants above are the man's)."""
    speeds: list
    deltas: list
    drops: tuple
    fast_from: float
    fast_ramp: float
    fast_deltas: list
    high_drops: list
    delta_step: float        # m between neighbouring deltas (a landing's plan steps by a share of it)

    @property
    def trials(self) -> int:
        return len(self.drops) * len(self.speeds) * len(self.deltas) + len(self.fast_deltas) * len(self.high_drops)


def grid(character) -> Grid:
    """The man's grid scaled to ``character`` (a name, a spec file or a CharacterSpec) by Fig. 6
    (lengths x L, speeds x L^1/2; the man's own numbers for the man, L = 1)."""
    spec = character if isinstance(character, CharacterSpec) else load_character(character)
    L = leg_length_ratio(load_character("man"), spec)
    length = lambda values: [round(v * L, 4) for v in values]
    speed = lambda values: [round(v * L ** 0.5, 4) for v in values]
    return Grid(speed(SPEEDS), length(DELTAS), tuple(length(DROPS)), speed([FAST_FROM])[0], speed([FAST_RAMP])[0],
                length(FAST_DELTAS), length(HIGH_DROPS), length([DELTA_STEP])[0])


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


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--character", nargs="+", default=["man", "woman"])
    parser.add_argument("--processes", type=int, default=2)
    args = parser.parse_args(argv)
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
