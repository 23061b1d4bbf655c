"""Landing report (Wooten §6.2): highest drop landed balanced, and landings with horizontal COM
speed, for the man and the woman. Prints a table (paste into the README / docs):

    python -m sim_core report land

``--random N --seed S --character man woman child``: N random drops per character anywhere in
what its landing table offers (horizontal speeds in its rows' common span, then drops in what it
lands at that speed, landing_drops, and sideways speeds within what it lands, landing_side_speed,
uniform, drawn from the seed), each planned and run as ``python -m sim_core
simulate land`` does it (sim_core.planning.land, in this process): each drop's outcome, the plan's
trials and foot_delta, and the wall seconds to a result; then passed / drawn and the median and
worst seconds.
"""
from __future__ import annotations

import argparse
import math
import sys
import time
from multiprocessing import Pool
from pathlib import Path

import numpy as np

ROOT = Path.cwd()                   # docs are written under the folder it runs in (the checkout)

from ... import tuned
from ...control.leap import landing_drops, landing_side_speed, landing_speeds
from ...simulate import RunRequest, StartState, run

DROPS = [round(0.1 * k, 1) for k in range(1, 13)]
SPEEDS = [-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 3.0]
SPEED_DROP = 0.2        # m: the standing COM (~1.05 m man) raised to about the thesis's 1.25 m


def landed(args) -> bool:
    character, height, speed = args
    traj = run(RunRequest("land", character, start=StartState(height=height, velocity=(speed, 0.0, 0.0)),
                          duration=3.0))
    return traj.meta["outcome"] == "success"


def offered(character: str) -> tuple[tuple[float, float], tuple[float, float]]:
    """(drops, horizontal speeds) a character's landing table offers: the lowest to the highest drop
    it lands at any of its speeds (landing_drops), and the speeds every row serves."""
    table = tuned.load("landing", character)
    speeds = landing_speeds(table)
    measured = table.get("drop_limits", {}).get("speeds", [])
    spans = [landing_drops(table, v) for v in [*speeds, *(v for v in measured if speeds[0] <= v <= speeds[1])]]
    return (min(low for low, _ in spans), max(high for _, high in spans)), speeds


def _rounded_inside(values, low: float, high: float, digits: int) -> list[float]:
    """``values`` rounded to ``digits`` decimals, held inside [low, high] at those decimals (a draw
    next to an end of the range must not round out of it: the child's -0.6765 m/s is not -0.68)."""
    scale = 10 ** digits
    inner = (math.ceil(round(low * scale, 6)) / scale, math.floor(round(high * scale, 6)) / scale)
    return [min(max(round(float(v), digits), inner[0]), inner[1]) for v in values]


def random_drops(character: str, count: int, seed: int) -> list[tuple[float, float, float]]:
    """``count`` (drop m, speed m/s, sideways speed m/s): the forward speed drawn uniformly in what the
    table offers (rounded to cm/s inside it), the drop uniformly in what it offers at that speed
    (landing_drops; mm), the sideways speed uniformly within what it offers from that drop
    (landing_side_speed; cm/s)."""
    table = tuned.load("landing", character)
    v0, v1 = landing_speeds(table)
    rng = np.random.default_rng(seed)
    speeds = _rounded_inside(rng.uniform(v0, v1, count), v0, v1, 2)
    fractions, side_fractions = rng.uniform(0.0, 1.0, count), rng.uniform(-1.0, 1.0, count)
    draws = []
    for f, v, s in zip(fractions, speeds, side_fractions):
        low, high = landing_drops(table, v)
        drop = _rounded_inside([low + f * (high - low)], low, high, 3)[0]
        side = landing_side_speed(table, drop)
        draws.append((drop, v, _rounded_inside([s * side], -side, side, 2)[0] + 0.0))    # + 0.0: no -0.0
    return draws


def planned_landing(character: str, drop: float, speed: float, side: float = 0.0, duration: float = 3.0) -> dict:
    """One drop as ``simulate land`` runs it: planned, then run; what it did and its wall seconds."""
    from ...planning.land import plan_landing
    started = time.monotonic()
    request, plan = plan_landing(RunRequest("land", character, start=StartState(height=drop, velocity=(speed, side, 0.0)),
                                            duration=duration))
    trajectory = run(request)
    return {"drop": drop, "speed": speed, "side": side, "outcome": trajectory.meta["outcome"], "plan": plan,
            "seconds": time.monotonic() - started}


def random_report(characters: list[str], count: int, seed: int) -> int:
    for character in characters:
        (h0, h1), (v0, v1) = offered(character)
        print(f"{character}: {count} random drops {h0:g}-{h1:g} m at {v0:+g}..{v1:+g} m/s (seed {seed})", flush=True)
        results = []
        for drop, speed, side in random_drops(character, count, seed):
            r = planned_landing(character, drop, speed, side)
            results.append(r)
            p = r["plan"]
            print(f"  {drop:.3f} m at {speed:+.2f} m/s, {side:+.2f} m/s sideways: {r['outcome']}, plan {p['trials']} trial(s), "
                  f"foot_delta {p['foot_delta']:+.4f} m{'' if p['found'] else ' (none found)'}, {r['seconds']:.1f} s",
                  flush=True)
        seconds = [r["seconds"] for r in results]
        passed = sum(r["outcome"] == "success" for r in results)
        print(f"{character}: {passed}/{count} balanced; plans of 1 trial {sum(r['plan']['trials'] == 1 for r in results)}, "
              f"most trials {max(r['plan']['trials'] for r in results)}; seconds to a result median "
              f"{float(np.median(seconds)):.1f}, worst {max(seconds):.1f}", flush=True)
    return 0


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--random", type=int, default=0, help="random drops per character (0: the fixed report)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--character", nargs="+", default=["man", "woman", "child"])
    args = parser.parse_args(argv)
    if args.random:
        return random_report(args.character, args.random, args.seed)
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
