"""Landing report (Wooten §6.2): highest drop landed balanced, and landings with horizontal COM
speed, for the man and the woman. Prints a table (paste into the README / docs):

    python -m sim_core report land
"""
from __future__ import annotations

import sys
from multiprocessing import Pool
from pathlib import Path

ROOT = Path.cwd()                   # docs are written under the folder it runs in (the checkout)

from ...simulate import RunRequest, StartState, run

DROPS = [round(0.1 * k, 1) for k in range(1, 13)]
SPEEDS = [-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 3.0]
SPEED_DROP = 0.2        # m: the standing COM (~1.05 m man) raised to about the thesis's 1.25 m


def landed(args) -> bool:
    character, height, speed = args
    traj = run(RunRequest("land", character, start=StartState(height=height, velocity=(speed, 0.0, 0.0)),
                          duration=3.0))
    return traj.meta["outcome"] == "success"


def main(argv=None) -> int:
    with Pool(2) as pool:
        for character in ("man", "woman"):
            drops = pool.map(landed, [(character, h, 0.0) for h in DROPS])
            speeds = pool.map(landed, [(character, SPEED_DROP, v) for v in SPEEDS])
            held = [h for h, ok in zip(DROPS, drops) if ok]
            print(f"{character}: drops landed balanced (m): {held}; highest contiguous: "
                  f"{max([h for i, h in enumerate(DROPS) if all(drops[:i + 1])], default=0.0)}")
            print(f"{character}: horizontal speeds landed from {SPEED_DROP} m (m/s): "
                  f"{[v for v, ok in zip(SPEEDS, speeds) if ok]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
