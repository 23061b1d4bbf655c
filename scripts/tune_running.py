"""Tune the running controller's five high-level parameters (Hodgins & Pollard 1997 §4.3.1) by
search, speed by speed, and write them as data - a table over the running speed - to
rigs/tuned/running_<character>.json, which the running behaviour reads (a tuned parameter left at
-1 takes the table's value for the current speed).

    python3 scripts/tune_running.py --speeds 3.5 --minutes 10     # simulated annealing at 3.5 m/s
    python3 scripts/tune_running.py --speeds 2.5 3.5 4.5 5.0 --minutes 40
    python3 scripts/tune_running.py --method cma                  # CMA-ES, if the 'cma' package is installed
    python3 scripts/tune_running.py --evaluate                    # only score the current table

The five parameters: ground-speed matching (forward speed), stance pitch (body attitude), and
thrust timing, ankle extension and knee extension (flight duration).

Evaluation function at a speed v_d (lower is better), averaged over two runs from a stand of
``--duration`` seconds (the paper ran 15 s from a running start; ours must first accelerate),
one with the default lean into the start and one with a longer lean (a second set of first steps,
so that a parameter set is not scored on one lucky sequence):

    E = W_FALL  * (1 - t_up / T)                      running time lost to a fall
      + W_SPEED * |v - v_d| / v_d                     speed error, mean over the last 5 s
      + W_HEAD  * mean |a_head| / g                   head acceleration (smoothness), last 5 s
      + W_ATT   * mean |d(roll, pitch, yaw)| per stride   stride-to-stride attitude variation (rad)

Each evaluation runs its scenarios in a pool of ``--workers`` processes (2 on the project's
machine). The search is time-boxed by ``--minutes``; the best point found is written only if it
scores better than the current defaults, together with both scores, the evaluation's weights
and the search settings (the file is written atomically: never half-written).
"""
from __future__ import annotations

import argparse
import json
import math
import os
import sys
import tempfile
import time
from multiprocessing import Pool
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from sim_core.control.running import TABLE_NAMES, TUNED_DIR, TUNED_NAMES, Running, SpeedTable  # noqa: E402

W_FALL, W_SPEED, W_HEAD, W_ATT = 10.0, 4.0, 0.05, 2.0
GRAVITY = 9.80665


def scenario(args) -> dict:
    """One run from a stand; the terms of the evaluation function."""
    from sim_core.gait import head_acceleration, stride_attitude_variation
    from sim_core.simulate import RunRequest, run
    params, speed, start_lean, duration, character, strength = args
    traj = run(RunRequest("running", character, params=dict(params, speed=speed, start_lean=start_lean),
                          duration=duration, strength=strength))
    m = traj.meta["metrics"]
    a = traj.arrays
    t_up = m["fall_time"] if m["fell"] else duration
    end = t_up
    window = (a["time"] >= max(0.0, end - 5.0)) & (a["time"] <= end)
    v = float(np.mean(np.linalg.norm(a["com_vel"][window, :2], axis=1)))
    head = float(np.mean(head_acceleration(traj)[window])) / GRAVITY
    att = stride_attitude_variation(traj, t_from=max(0.0, end - 5.0)) if not m["fell"] else float("nan")
    if not math.isfinite(att):
        att = 0.5
    return {"speed": speed, "t_up": t_up, "mean_speed": v, "head_acc_g": head, "attitude_variation": att}


def evaluation(terms: list[dict], duration: float) -> float:
    total = 0.0
    for s in terms:
        total += (W_FALL * (1.0 - s["t_up"] / duration) + W_SPEED * abs(s["mean_speed"] - s["speed"]) / s["speed"]
                  + W_HEAD * s["head_acc_g"] + W_ATT * s["attitude_variation"])
    return total / len(terms)


class Evaluator:
    def __init__(self, pool, speed, duration, character, strength):
        self.pool, self.speed, self.duration = pool, speed, duration
        self.character, self.strength = character, strength
        self.history: list[tuple[list[float], float]] = []

    def __call__(self, x) -> float:
        params = dict(zip(TUNED_NAMES, map(float, x)))
        v = self.speed
        jobs = [(params, v, 0.35, self.duration, self.character, self.strength),
                (params, v, 0.5, self.duration, self.character, self.strength)]
        terms = self.pool.map(scenario, jobs)
        score = evaluation(terms, self.duration)
        self.history.append((list(map(float, x)), score))
        return score


def bounds() -> list[tuple[float, float]]:
    return [(Running.schema.by_name[n].minimum, Running.schema.by_name[n].maximum) for n in TUNED_NAMES]


def anneal(evaluate, x0, deadline, max_evaluations, seed):
    """scipy's dual_annealing (the paper used simulated annealing), stopped at the deadline."""
    from scipy.optimize import dual_annealing
    best = {"x": list(x0), "f": evaluate(x0)}

    def track(x, f, context):
        if f < best["f"]:
            best.update(x=list(map(float, x)), f=float(f))
        return time.monotonic() > deadline

    try:
        dual_annealing(evaluate, bounds(), x0=np.array(x0), maxfun=max_evaluations, seed=seed,
                       callback=track, no_local_search=True, initial_temp=2000.0)
    except StopIteration:
        pass
    return best


def cma_search(evaluate, x0, deadline, max_evaluations, seed):
    import cma  # optional dependency
    lo, hi = np.array(bounds()).T
    scale = hi - lo
    es = cma.CMAEvolutionStrategy(((np.array(x0) - lo) / scale).tolist(), 0.1,
                                  {"bounds": [0, 1], "seed": seed, "maxfevals": max_evaluations, "verbose": -9})
    best = {"x": list(x0), "f": evaluate(x0)}
    while not es.stop() and time.monotonic() < deadline:
        z = es.ask()
        f = [evaluate(lo + np.array(zi) * scale) for zi in z]
        es.tell(z, f)
        k = int(np.argmin(f))
        if f[k] < best["f"]:
            best.update(x=(lo + np.array(z[k]) * scale).tolist(), f=float(f[k]))
    return best


def write_atomically(path: Path, data: dict) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
    with os.fdopen(fd, "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")
    os.replace(tmp, path)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--character", default="man")
    ap.add_argument("--strength", default="human")
    ap.add_argument("--speeds", type=float, nargs="+", default=[3.5])
    ap.add_argument("--duration", type=float, default=20.0)
    ap.add_argument("--minutes", type=float, default=20.0, help="time budget for all speeds together")
    ap.add_argument("--max-evaluations", type=int, default=300, help="per speed")
    ap.add_argument("--method", choices=("anneal", "cma"), default="anneal")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--evaluate", action="store_true", help="only score the current table")
    args = ap.parse_args(argv)
    strength = args.strength if args.strength in ("human", "unlimited") else float(args.strength)
    table = SpeedTable.load(args.character)
    path = TUNED_DIR / f"running_{args.character}.json"
    try:
        stored = json.loads(path.read_text())
    except (FileNotFoundError, json.JSONDecodeError):
        stored = {}
    started = time.monotonic()
    per_speed = dict(stored.get("evaluation", {}).get("per_speed", {}))
    new_values = {}
    with Pool(args.workers) as pool:
        for k, speed in enumerate(args.speeds):
            x0 = [table.at(n, speed) for n in TUNED_NAMES]
            evaluate = Evaluator(pool, speed, args.duration, args.character, strength)
            if args.evaluate:
                print(f"{speed} m/s: evaluation {evaluate(x0):.4f} at {dict(zip(TUNED_NAMES, x0))}")
                continue
            remaining = started + 60.0 * args.minutes - time.monotonic()
            deadline = time.monotonic() + remaining / (len(args.speeds) - k)
            search = anneal if args.method == "anneal" else cma_search
            best = search(evaluate, x0, deadline, args.max_evaluations, args.seed)
            baseline = evaluate.history[0][1]
            print(f"{speed} m/s: {len(evaluate.history)} evaluations, baseline {baseline:.4f}, best {best['f']:.4f}",
                  flush=True)
            print(json.dumps(dict(zip(TUNED_NAMES, best["x"])), indent=1), flush=True)
            if best["f"] < baseline:
                new_values[speed] = best["x"]
                per_speed[str(speed)] = {"score": best["f"], "baseline_score": baseline,
                                         "evaluations": len(evaluate.history)}
    if args.evaluate or not new_values:
        if not args.evaluate:
            print("no improvement on the current table; nothing written")
        return 0
    speeds = sorted(set(table.speeds) | set(new_values))
    values = {}
    for n in TABLE_NAMES:
        column = []
        for v in speeds:
            if v in new_values and n in TUNED_NAMES:
                column.append(round(float(new_values[v][TUNED_NAMES.index(n)]), 4))
            else:
                column.append(round(table.at(n, v), 4))
        values[n] = column
    elapsed = time.monotonic() - started
    write_atomically(path, {
        "behaviour": "running", "character": args.character, "speeds": speeds, "parameters": values,
        "evaluation": {"weights": {"fall": W_FALL, "speed": W_SPEED, "head_acceleration": W_HEAD,
                                   "attitude_variation": W_ATT},
                       "runs": "two per speed from a stand (lean 0.35 s and 0.5 s)",
                       "duration_s": args.duration, "strength": args.strength, "per_speed": per_speed},
        "search": {"method": args.method, "minutes": round(elapsed / 60, 2), "seed": args.seed},
        "command": "python3 scripts/tune_running.py " + " ".join(argv if argv is not None else sys.argv[1:]),
    })
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
