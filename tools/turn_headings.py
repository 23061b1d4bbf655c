"""Measure the turn's hop (control/turn.py, the leap's ``turn_angle``) on a fine grid of angles and write
the heading each reached into the character's commanded table (``turn_headings``, read by
skills/jump_to_target/commanded.py turn_for_heading): every angle runs the hop from the standing start,
then the heading of the pelvis when the leap's own crouch begins is read off the simulation; a hop that
fell (the COM below ``--fall-height`` m before the leap began) is left out. The hop does not depend on the
jump that follows (the same angle reaches the same heading for any target), so one run each is the map:

    tools/turn_headings.py --character woman --from -1.2 --to 1.2 --step 0.005 --write
"""
from __future__ import annotations

import argparse
import math

import numpy as np

from sim_core.planning.turn_map import hop_heading
from sim_core.tuned.store import read, save


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--character", default="woman")
    ap.add_argument("--from", dest="low", type=float, default=-1.2)
    ap.add_argument("--to", dest="high", type=float, default=1.2)
    ap.add_argument("--step", type=float, default=0.005)
    ap.add_argument("--fall-height", type=float, default=0.5, help="m: a hop whose COM went lower fell")
    ap.add_argument("--write", action="store_true", help="store the map in the character's commanded table")
    args = ap.parse_args()
    angles, headings = [], []
    for angle in np.round(np.arange(args.low, args.high + 1e-9, args.step), 4):
        if not angle:
            continue
        heading, lowest, began = hop_heading(args.character, float(angle))
        kept = began and lowest >= args.fall_height
        print(f"turn_angle {angle:+.3f} rad: heading {math.degrees(heading):+7.2f} deg, lowest COM {lowest:.2f} m"
              f"{'' if kept else ' (fell: left out)'}", flush=True)
        if kept:
            angles.append(float(angle))
            headings.append(round(heading, 5))
    if args.write:
        body = read("jump_commanded", args.character)
        body["turn_headings"] = {"turn_angle": angles, "heading": headings}
        path = save("jump_commanded", args.character, body, body["strengths"])    # checked, written whole
        print(f"wrote {len(angles)} hops to {path}")


if __name__ == "__main__":
    main()
