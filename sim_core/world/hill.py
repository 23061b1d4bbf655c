"""A hill as a prop: flat ground, a straight climb at a grade, a flat top and a straight descent,
across the +X direction (for a bicycle course; SEEDS-WAVE2.md B8). Three boxes, "hill_up",
"hill_top" and "hill_down", their top faces the road; the climb starts at ground level and the
descent ends there, so the road is continuous (kinks of atan(grade) at the four corners).

``World.hill`` = (start x, grade, climb length, top length, descent length), lengths in metres
along the ground (horizontal), grade as rise over run (0.05 = 5 %)."""
from __future__ import annotations

import math

import mujoco
import numpy as np

from ..errors import ParameterError
from .props import _felt, prop_builder
from .world import World

HILL_WIDTH = 8.0            # m: across the road (a rider wanders well inside it)
HILL_DEPTH = 0.5            # m: each ramp reaches this far below its road surface (the top, to below the ground)
GRADE_RANGE = (0.0, 0.2)    # criterion: rise over run a hill may have
LENGTH_RANGE = (1.0, 500.0)  # criterion: m, each of the climb, top and descent
START_RANGE = (0.0, 1000.0)  # criterion: m from the origin to the foot of the climb


def check_hill(hill) -> tuple[float, float, float, float, float]:
    """The five numbers of a World.hill, refused with the allowed range when one is outside it."""
    if len(hill) != 5:
        raise ParameterError(f"hill has {len(hill)} value(s); it needs 5: start, grade, climb, top, descent")
    names = ("start", "grade", "climb", "top", "descent")
    ranges = (START_RANGE, GRADE_RANGE, LENGTH_RANGE, LENGTH_RANGE, LENGTH_RANGE)
    for name, value, (low, high) in zip(names, hill, ranges):
        if not low <= value <= high:
            raise ParameterError(f"hill {name} = {value:g} is outside {low:g} to {high:g}")
    return tuple(float(v) for v in hill)


def hill_height(hill, x):
    """The road's height (m) at ``x`` (m along +X): 0 before and after the hill."""
    start, grade, climb, top, descent = hill
    x = np.asarray(x, dtype=float)
    rise = grade * climb
    up = np.clip(x - start, 0.0, climb) * grade
    down = np.clip(x - (start + climb + top), 0.0, descent) * (rise / descent)
    return up - down


def _ramp(spec, name: str, x0: float, z0: float, length: float, slope: float, depth: float = HILL_DEPTH) -> None:
    """A box ``depth`` thick whose top face runs from (x0, z0) for ``length`` m of ground at rise ``slope``."""
    angle = math.atan(slope)
    half = 0.5 * math.hypot(length, slope * length)
    normal = np.array([-math.sin(angle), 0.0, math.cos(angle)])
    middle = np.array([x0 + length / 2, 0.0, z0 + slope * length / 2])
    quat = np.zeros(4)
    mujoco.mju_axisAngle2Quat(quat, np.array([0.0, 1.0, 0.0]), -angle)
    _felt(spec.worldbody.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_BOX, size=[half, HILL_WIDTH / 2, depth / 2],
                                  pos=middle - normal * depth / 2, quat=quat, rgba=[0.45, 0.55, 0.35, 1]))


@prop_builder("hill")
def add_hill(spec: mujoco.MjSpec, world: World, character) -> None:
    """The hill's three road boxes, if the world has a hill."""
    if not world.hill:
        return
    start, grade, climb, top, descent = check_hill(world.hill)
    rise = grade * climb
    _ramp(spec, "hill_up", start, 0.0, climb, grade)
    _ramp(spec, "hill_top", start + climb, rise, top, 0.0, rise + HILL_DEPTH)   # down to the ground
    _ramp(spec, "hill_down", start + climb + top, rise, descent, -rise / descent)
