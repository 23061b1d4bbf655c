"""Calibrate eq. 11's steering gains at speeds across the bicycle's range by simulation, and write
them as the steering schedule of sim_core/tuned/tables/bicycle_any.json (steering.py reads it).

Hand-set gains at one speed, scheduled by physics (roll gains / v^2, heading gains / v), steer
well near 4 m/s but overshoot a heading change at 3 m/s and lag at 6 m/s (docs/bicycle.md): the
bicycle's roll and yaw dynamics are not a pure power of speed. So at each speed of SPEEDS a search
(the search service, sim_core.tuning: CMA-ES by default, or annealing) over the four gains
minimises, read off a simulated +30 deg heading step of STEP_SECONDS from the rolling start,

    score = mean |heading error| (deg) + 2 max(0, overshoot) (deg) + 0.1 max |roll| (deg)     if it stays up
          = 1000 + 100 (STEP_SECONDS - fall time)                                               if it falls

starting from the physics-scheduled gains at that speed. The searches run with no schedule in
the table (each candidate is the scheduled law at its own reference speed).

    python -m sim_core calibrate bicycle [--budget 40] [--workers 2] [--method cma|anneal]
"""
from __future__ import annotations

import argparse
import functools
import math
import time

import mujoco
import numpy as np

from ... import tuned
from ...simulate import RunRequest, run
from ...tuning import Space, executor_for, minimize
from ...world.bicycle import NAMES, frame_state
from .steering import GAINS, steering_gains

SPEEDS = (1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0)     # m/s: the schedule's rows (the panel offers 1-8)
STEP = math.radians(30.0)                         # the heading step of each evaluation
STEP_SECONDS = 6.0
BOUNDS = {"roll_gain": (0.2, 20.0), "roll_rate_gain": (0.0, 5.0), "yaw_gain": (0.0, 5.0), "yaw_rate_gain": (0.0, 3.0)}
FALL_SCORE, FALL_PER_SECOND = 1000.0, 100.0
OVERSHOOT_WEIGHT, ROLL_WEIGHT = 2.0, 0.1


def heading_step_score(settings: dict, speed: float) -> tuple[float, dict]:
    """The score of eq. 11's gains ``settings`` at ``speed`` (module docstring) and what it was
    made of."""
    params = {"speed": speed, "heading": STEP, "reference_speed": speed, **settings}
    trajectory = run(RunRequest("bicycle", "man", params=params, duration=STEP_SECONDS))
    m = trajectory.meta["metrics"]
    if m["fell"]:
        return FALL_SCORE + FALL_PER_SECOND * (STEP_SECONDS - m["fall_time"]), {"fell": m["fall_time"]}
    yaw = np.degrees(heading(trajectory))
    error = math.degrees(STEP) - yaw
    overshoot = max(0.0, float(-error.min()))
    score = float(np.abs(error).mean()) + OVERSHOOT_WEIGHT * overshoot + ROLL_WEIGHT * m["max_abs_roll_deg"]
    return score, {"mean_error_deg": float(np.abs(error).mean()), "overshoot_deg": overshoot,
                   "max_roll_deg": m["max_abs_roll_deg"], "settled_from": m["heading_within_5deg_from"]}


def heading(trajectory) -> np.ndarray:
    """The bicycle frame's heading (rad, unwrapped) at every recorded frame."""
    a = trajectory.arrays
    model = mujoco.MjModel.from_xml_string(trajectory.meta["model_xml"])
    free = model.joint(NAMES["free"])
    q, d = int(free.qposadr[0]), int(free.dofadr[0])
    return np.unwrap([frame_state(a["qpos"][k, q + 3:q + 7], a["qvel"][k, d:d + 6], 0.0, 0.0)["yaw"]
                      for k in range(len(a["time"]))])


def calibrate(budget: int, workers: int, method: str, seed: int) -> dict:
    body = tuned.load("bicycle", "any")
    body.pop("steering_schedule", None)
    body.pop("steering_search", None)
    tuned.save("bicycle", "any", body, strengths=["human"])           # the searches run without a schedule
    constants = body["constants"]
    space = Space(BOUNDS, decimals=4)
    rows, record = [], []
    with executor_for(workers) as executor:
        for speed in SPEEDS:
            start = dict(zip(GAINS, steering_gains(speed, constants, None)))
            start = {k: min(max(v, BOUNDS[k][0]), BOUNDS[k][1]) for k, v in start.items()}
            began = time.time()
            result = minimize(functools.partial(heading_step_score, speed=speed), space, method=method, budget=budget,
                              seed=seed, start=start, executor=executor)
            best = result.best
            first = result.evaluations[0]
            print(f"  {speed:g} m/s: score {first.score:.2f} -> {best.score:.2f} in {len(result.evaluations)} "
                  f"evaluations, {time.time() - began:.0f} s; {best.extra}", flush=True)
            rows.append({"reference_speed": speed, **{k: round(best.settings[k], 4) for k in GAINS}})
            record.append({"speed": speed, "evaluations": len(result.evaluations), "seconds": round(time.time() - began, 1),
                           "start_score": first.score, "score": best.score, "measured": best.extra})
    body["steering_schedule"] = rows
    body["steering_search"] = {"method": method, "seed": seed, "budget": budget, "step_deg": math.degrees(STEP),
                               "seconds": STEP_SECONDS, "speeds": record}
    tuned.save("bicycle", "any", body, strengths=["human"])
    return body


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m sim_core calibrate bicycle", description=__doc__.split("\n\n")[0])
    parser.add_argument("--budget", type=int, default=40, help="evaluations per speed (default 40)")
    parser.add_argument("--workers", type=int, default=None, help="processes (default: one per CPU)")
    parser.add_argument("--method", default="cma", choices=("cma", "anneal"))
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    calibrate(args.budget, args.workers, args.method, args.seed)
    return 0
