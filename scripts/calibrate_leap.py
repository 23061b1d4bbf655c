"""Calibrate the vertical leap (the role of Wooten's Table 4.1): run leaps over a range of crouch
heights with the low-level settings, measure the COM rise each one achieves and whether it lands
balanced, and write the mapping commanded rise -> crouch height, torso pitch to
rigs/tuned/leap_<character>.json, which the leap behaviour interpolates. Rerun after any change
to the model or the controllers:

    python scripts/calibrate_leap.py [--character man woman] [--processes 2]
"""
from __future__ import annotations

import argparse
import json
import sys
from multiprocessing import Pool
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import numpy as np                                          # noqa: E402

from sim_core.control.leap import DEFAULT_MAPPING, TUNED_DIR   # noqa: E402
from sim_core.simulate import RunRequest, run               # noqa: E402

CROUCH_FRACTIONS = (0.93, 0.88, 0.83, 0.78, 0.73, 0.68, 0.63, 0.59)   # of the standing hip height
DURATION = 4.5


def trial(args):
    character, crouch_height = args
    params = dict(low_level=1, crouch_height=crouch_height, crouch_pitch=0.0, arm_swing=2.5)
    traj = run(RunRequest("leap", character, params=params, duration=DURATION))
    m = traj.meta["metrics"]
    return {"crouch_height": crouch_height, "com_rise": m["com_rise"], "outcome": traj.meta["outcome"],
            "flight_time": m.get("flight_time", 0.0)}


def calibrate(character: str, processes: int) -> dict:
    from sim_core.character.spec import load_character
    from sim_core.control.balance import LegGeometry
    spec = load_character(character)
    stand = 0.5 * sum(LegGeometry(spec, side).standing_hip_height() for side in "RL")
    heights = [round(f * stand, 3) for f in CROUCH_FRACTIONS]
    with Pool(processes) as pool:
        results = pool.map(trial, [(character, h) for h in heights])
    for r in results:
        print(f"  {character}: crouch {r['crouch_height']:.3f} m -> COM rise {r['com_rise']:.3f} m, {r['outcome']}")
    good = [r for r in results if r["outcome"] == "success"]
    good.sort(key=lambda r: r["com_rise"])
    rows, best = [], -1.0
    for r in good:                                   # keep a monotonic mapping
        if r["com_rise"] > best + 0.01:
            rows.append(r)
            best = r["com_rise"]
    mapping = {"character": character, "script": "scripts/calibrate_leap.py", "trials": results,
               "vertical": {"com_rise": [r["com_rise"] for r in rows],
                            "crouch_height": [r["crouch_height"] for r in rows],
                            "torso_pitch": [0.0 for _ in rows]},
               "broad": DEFAULT_MAPPING["broad"], "broad_calibrated": False}
    return mapping


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--character", nargs="+", default=["man", "woman"])
    parser.add_argument("--processes", type=int, default=2)
    args = parser.parse_args()
    TUNED_DIR.mkdir(parents=True, exist_ok=True)
    for character in args.character:
        mapping = calibrate(character, args.processes)
        path = TUNED_DIR / f"leap_{character}.json"
        path.write_text(json.dumps(mapping, indent=1) + "\n")
        v = mapping["vertical"]
        print(f"wrote {path.relative_to(ROOT)}: COM rise {min(v['com_rise'], default=0):.2f} .. "
              f"{max(v['com_rise'], default=0):.2f} m from {len(v['com_rise'])} balanced landings")
    return 0


if __name__ == "__main__":
    sys.exit(main())
