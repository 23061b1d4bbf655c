"""Benchmark: simulated seconds per wall second with the controller in the loop, against raw
``mj_step`` on the same model in the same run (ratios, never timed assertions).

The raw baseline steps the same compiled model from the same initial state with the control
vectors the controlled run produced, so both meet the same contacts; it does no control and no
recording. Both time the stepping loop only (building the model and analysing the run are
outside it). Each figure is the best of ``repeats`` runs, interleaved.

``scene_bench`` does the same for a scene of several runners side by side in one model: the
scene loop (every actor's behaviour, servos and recording) against raw ``mj_step`` of the same
many-actor model.

``search_bench`` measures a search's throughput: the running search's evaluation runs (runs from
a stand, sim_core.skills.running.calibrate.scenario) handed to a pool of 1 and of 2 local worker
processes in the same run, interleaved, as evaluations per minute and their ratio.
"""
from __future__ import annotations

import time

import mujoco

from .scene import scene_from_dict
from .simulate import RunRequest, run, run_scene

SCENE_SPACING = 1.2          # m between the runners of the benchmark scene (side by side)


def raw_stepping_rate(trajectory, repeats: int) -> float:
    meta = trajectory.meta
    model = mujoco.MjModel.from_xml_string(meta["model_xml"])
    data = mujoco.MjData(model)
    control = trajectory.arrays["control"]
    steps = meta["steps_per_tick"]
    divisions = trajectory.arrays["step_division"]
    if (divisions != 1).any():
        raise ValueError("the raw baseline steps at the model's step: bench a run without divided steps")
    best = float("inf")
    for _ in range(repeats):
        mujoco.mj_setState(model, data, trajectory.arrays["initial_state"], meta["state_spec"])
        start = time.perf_counter()
        for row in control:
            data.ctrl[:] = row
            mujoco.mj_step(model, data, nstep=steps)
        best = min(best, time.perf_counter() - start)
    return len(control) * steps * model.opt.timestep / best


def controlled_rate(request: RunRequest, repeats: int):
    """Simulated seconds per wall second of the simulation loop (behaviour, servos, recording and
    physics; model building before and analysis after the loop are not in it)."""
    best, trajectory = float("inf"), None
    for _ in range(repeats):
        trajectory = run(request)
        best = min(best, trajectory.meta["wall_seconds_in_loop"])
    return trajectory.meta["duration"] / best, trajectory


def bench(behaviour: str = "balance", character: str = "man", duration: float = 10.0,
          params: dict | None = None, repeats: int = 5) -> dict:
    """Interleaves controlled and raw runs so that a busy machine slows both alike."""
    request = RunRequest(behaviour, character, params=params or {}, duration=duration)
    loop_rate = raw_rate = 0.0
    for _ in range(repeats):
        rate, trajectory = controlled_rate(request, 1)
        loop_rate = max(loop_rate, rate)
        raw_rate = max(raw_rate, raw_stepping_rate(trajectory, 1))
    return {"behaviour": behaviour, "character": character, "simulated_s": duration,
            "controller_in_loop_sim_s_per_wall_s": loop_rate, "raw_mj_step_sim_s_per_wall_s": raw_rate,
            "ratio": loop_rate / raw_rate}


def runners_scene(count: int, duration: float, speed: float = 3.0) -> dict:
    """A scene file's dict: ``count`` men running side by side along +X."""
    return {"duration": duration, "actors": [
        {"name": f"runner{k}", "character": "man", "behaviour": "running", "params": {"speed": speed},
         "position": [0.0, SCENE_SPACING * (k - (count - 1) / 2)], "heading": 0.0} for k in range(count)]}


def scene_bench(count: int = 4, duration: float = 5.0, repeats: int = 3) -> dict:
    """Scene loop against raw mj_step of the same ``count``-actor model (interleaved, best of
    ``repeats``); also each runner's outcome, so a benchmark of falling runners shows."""
    scene = scene_from_dict(runners_scene(count, duration))
    loop_rate = raw_rate = 0.0
    for _ in range(repeats):
        trajectory = run_scene(scene)
        loop_rate = max(loop_rate, trajectory.meta["duration"] / trajectory.meta["wall_seconds_in_loop"])
        raw_rate = max(raw_rate, raw_stepping_rate(trajectory, 1))
    return {"scene": f"{count} runners", "simulated_s": duration,
            "outcomes": {a["name"]: a["outcome"] for a in trajectory.meta["actors"]},
            "scene_loop_sim_s_per_wall_s": loop_rate, "raw_mj_step_sim_s_per_wall_s": raw_rate,
            "ratio": loop_rate / raw_rate}


def search_bench(runs: int = 4, duration: float = 4.0, workers=(1, 2), repeats: int = 2) -> dict:
    """Evaluations per minute of the running search (an evaluation: its two runs from a stand, one
    per start lean, ``duration`` s each, of the man's stored table at 3.5 m/s) through a local pool
    of each size in ``workers``; ``runs`` runs a batch; best of ``repeats`` batches, interleaved.
    The pools are started (and their workers' imports warmed) before the clock."""
    from .skills.running.behaviour import SpeedTable
    from .skills.running.calibrate import scenario
    from .tuning import LocalPool
    table = SpeedTable.load("man").to_table()
    leans = (0.35, 0.5)
    jobs = [(table, 3.5, leans[k % 2], duration, "man", "human", None) for k in range(runs)]
    pools = {n: LocalPool(n) for n in workers}
    best = {n: float("inf") for n in workers}
    try:
        for pool in pools.values():
            pool.map(scenario, [(table, 3.5, leans[0], 0.1, "man", "human", None)] * pool.workers)
        for _ in range(repeats):
            for n, pool in pools.items():
                start = time.perf_counter()
                pool.map(scenario, jobs)
                best[n] = min(best[n], time.perf_counter() - start)
    finally:
        for pool in pools.values():
            pool.shutdown()
    per_minute = {n: 60.0 * runs / len(leans) / best[n] for n in workers}
    return {"evaluation": f"{len(leans)} runs of {duration:g} s", "evaluations_per_minute": per_minute,
            "speedup": per_minute[workers[-1]] / per_minute[workers[0]]}
