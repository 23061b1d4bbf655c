"""Balance experiments of Wooten §7.3, run by simulation: push recovery in 8 directions, the
steepest slope held, and standing with a backpack; ``python -m sim_core report balance`` prints
the tables and writes them into docs/."""
from __future__ import annotations

import math

from ...world import World
from ...perturbation import DIRECTIONS, Push
from ...simulate import RunRequest, run

PUSH_START, PUSH_DURATION, RECOVERY = 1.0, 0.25, 3.0
FORCE_STEP = 5.0


def push_recovered(character: str, force: float, direction_deg: float, params=None) -> bool:
    push = Push(force=force, direction_deg=direction_deg, start=PUSH_START, duration=PUSH_DURATION)
    trajectory = run(RunRequest("balance", character, params=params or {}, pushes=[push],
                                duration=PUSH_START + PUSH_DURATION + RECOVERY))
    return trajectory.meta["outcome"] == "success"


def largest_on_grid(holds, step: float, upper: float) -> float:
    """Largest multiple of ``step`` in [0, upper] for which ``holds`` is true, assuming it holds
    up to a threshold and fails above it (bisection on the grid; the thesis stepped linearly)."""
    lo, hi = 0, int(upper / step)          # holds(lo * step) assumed, hi * step assumed to fail
    if holds(hi * step):
        return hi * step
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if holds(mid * step):
            lo = mid
        else:
            hi = mid
    return lo * step


def push_scan(character: str, step: float = FORCE_STEP, upper: float = 400.0) -> dict[str, float]:
    return {name: largest_on_grid(lambda f: push_recovered(character, f, deg), step, upper)
            for name, deg in DIRECTIONS.items()}


def slope_holds(character: str, slope_deg: float, axis: str) -> bool:
    world = World(slope=math.radians(slope_deg), slope_axis=axis)
    trajectory = run(RunRequest("balance", character, world=world,
                                duration=world.slope_start + world.ramp_time + 3.0))
    return trajectory.meta["outcome"] == "success"


def steepest_slopes(character: str, step: float = 0.5, upper: float = 45.0) -> dict[str, float]:
    return {axis: largest_on_grid(lambda s: slope_holds(character, s, axis), step, upper)
            for axis in ("x+", "x-", "y+")}


def backpack_stands(character: str, kg: float, duration: float = 10.0) -> dict:
    world = World(extra_mass={"CHEST1": kg})
    trajectory = run(RunRequest("balance", character, world=world, duration=duration))
    return {"kg": kg, "outcome": trajectory.meta["outcome"],
            "com_inside_support_throughout": trajectory.meta["metrics"]["com_inside_support_throughout"]}


def balance_report(characters=("man", "woman"), quick: bool = False, out=print) -> dict:
    step_force, step_slope = (20.0, 2.0) if quick else (FORCE_STEP, 0.5)
    report = {}
    for character in characters:
        pushes = push_scan(character, step_force)
        slopes = steepest_slopes(character, step_slope)
        packs = [backpack_stands(character, kg) for kg in (2.0, 4.0)]
        report[character] = {"push_N": pushes, "slope_deg": slopes, "backpack": packs}
        out(f"\n{character}: largest sternum push recovered (0.25 s, {step_force:g} N steps)")
        for name, force in pushes.items():
            out(f"  {name:14s} {force:6.0f} N")
        out(f"{character}: steepest slope held ({step_slope:g} deg steps; seed man: +X 33.7, -X 38.6, Y 25.7)")
        for axis, deg in slopes.items():
            out(f"  rising {axis:3s}     {deg:5.1f} deg")
        for pack in packs:
            out(f"{character}: backpack +{pack['kg']:g} kg on CHEST1, same parameters: {pack['outcome']}")
    return report
