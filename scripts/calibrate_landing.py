"""Calibrate the landing's foot servo delta against horizontal speed (the role of Wooten's
Table 6.1): for each speed, land from a small drop with a range of deltas, keep the middle of the
deltas that end balanced, and write rigs/tuned/landing_<character>.json, which the landing reads.
Rerun after a change to the model or the controllers:

    python scripts/calibrate_landing.py [--character man woman] [--processes 2]
"""
from __future__ import annotations

import argparse
import json
import sys
from multiprocessing import Pool
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from sim_core.control.leap import TUNED_DIR                      # noqa: E402
from sim_core.simulate import RunRequest, StartState, run          # noqa: E402

SPEEDS = [-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 3.0]
DELTAS = [-0.12, -0.08, -0.04, 0.0, 0.04, 0.08, 0.12, 0.16]
DROP = 0.2                   # m above standing: the COM starts at about Wooten's 1.25 m (man)


def trial(args):
    character, speed, delta = args
    traj = run(RunRequest("land", character, params=dict(foot_delta=delta),
                          start=StartState(height=DROP, velocity=(speed, 0.0, 0.0)), duration=3.0))
    return speed, delta, traj.meta["outcome"] == "success"


def calibrate(character: str, processes: int) -> dict:
    path = TUNED_DIR / f"landing_{character}.json"
    if path.exists():
        path.unlink()                      # calibrate against no table (delta = the trial's own)
    with Pool(processes) as pool:
        results = pool.map(trial, [(character, v, d) for v in SPEEDS for d in DELTAS])
    speeds, deltas, landed = [], [], {}
    for v in SPEEDS:
        ok = [d for s, d, success in results if s == v and success]
        landed[v] = ok
        print(f"  {character} at {v:+.1f} m/s: balanced with deltas {ok}")
        if ok:
            speeds.append(v)
            deltas.append(sorted(ok)[len(ok) // 2])
    return {"character": character, "script": "scripts/calibrate_landing.py", "drop": DROP,
            "foot_delta": {"speed": speeds, "delta": deltas},
            "landed": {str(k): v for k, v in landed.items()}}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--character", nargs="+", default=["man", "woman"])
    parser.add_argument("--processes", type=int, default=2)
    args = parser.parse_args()
    TUNED_DIR.mkdir(parents=True, exist_ok=True)
    for character in args.character:
        table = calibrate(character, args.processes)
        path = TUNED_DIR / f"landing_{character}.json"
        path.write_text(json.dumps(table, indent=1) + "\n")
        print(f"wrote {path.relative_to(ROOT)}: speeds {table['foot_delta']['speed']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
