"""A hill as a prop: flat ground, a straight climb at a grade, a flat top and a straight descent,
across the +X direction (for a bicycle course; SEEDS-WAVE2.md B8). Three boxes, "hill_up",
"hill_top" and "hill_down", their top faces the road; the climb starts at ground level and the
descent ends there, so the road is continuous (kinks of atan(grade) at the four corners).

``World.hill`` = (start x, grade, climb length, top length, descent length[, curve length]), lengths
in metres along the ground (horizontal), grade as rise over run (0.05 = 5 %). A curve length > 0
rounds the four corners as roads are built: a vertical curve (a parabola, the grade changing
evenly along it) of that length centred on each corner, laid as boxes "hill_curve_<corner>_<k>"
(chords at most CURVE_CHORD long, their ends on the parabola); the straight parts keep their
names, shortened. 0 (or five numbers) is the sharp hill."""
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
CURVE_RANGE = (0.0, 100.0)   # criterion: m, a vertical curve's length (0: the sharp corner); at most each straight's
CURVE_CHORD = 0.5            # definition: m, the longest chord of a vertical curve (its corners 1/40 of a 5 % change at 10 m)


def check_hill(hill) -> tuple:
    """The numbers of a World.hill (five, or six with the vertical curves' length), refused with the
    allowed range when one is outside it."""
    if len(hill) not in (5, 6):
        raise ParameterError(f"hill has {len(hill)} value(s); it needs 5 or 6: start, grade, climb, top, descent[, curve]")
    names = ("start", "grade", "climb", "top", "descent", "curve")
    ranges = (START_RANGE, GRADE_RANGE, LENGTH_RANGE, LENGTH_RANGE, LENGTH_RANGE, CURVE_RANGE)
    for name, value, (low, high) in zip(names, hill, ranges):
        if not low <= value <= high:
            raise ParameterError(f"hill {name} = {value:g} is outside {low:g} to {high:g}")
    if len(hill) == 6 and hill[5] > min(hill[2:5]):
        raise ParameterError(f"hill curve = {hill[5]:g} m is longer than the shortest of the climb, top and descent "
                             f"({min(hill[2:5]):g} m): the vertical curves would overlap")
    return tuple(float(v) for v in hill)


def _curve(hill) -> float:
    return float(hill[5]) if len(hill) == 6 else 0.0


def hill_profile(hill) -> list:
    """The road as pieces (name, ((x, z) of each vertex, ...)): the climb, top and descent straights and,
    with a curve length, the four vertical curves' chords ("curve_<corner>", corners 0-3 from the foot
    of the climb), in order along +X."""
    start, grade, climb, top, descent = hill[:5]
    rise, length = grade * climb, _curve(hill)
    corners = [(start, 0.0), (start + climb, rise), (start + climb + top, rise), (start + climb + top + descent, 0.0)]
    grades = [0.0, grade, 0.0, -rise / descent, 0.0]
    if length <= 0.0:
        return [("up", corners[0:2]), ("top", corners[1:3]), ("down", corners[2:4])]
    count = max(2, math.ceil(length / CURVE_CHORD))
    curves = []
    for k, ((x, z), before, after) in enumerate(zip(corners, grades[:-1], grades[1:])):
        u = np.linspace(0.0, length, count + 1)          # along the curve from its beginning
        curves.append((f"curve_{k}", list(zip(x - length / 2 + u, z + before * (u - length / 2) + (after - before) * u ** 2 / (2 * length)))))
    pieces = []
    for k, name in enumerate(("up", "top", "down")):
        pieces.append(curves[k])
        pieces.append((name, [curves[k][1][-1], curves[k + 1][1][0]]))
    pieces.append(curves[3])
    return pieces


def hill_height(hill, x):
    """The road's height (m) at ``x`` (m along +X): 0 before and after the hill."""
    start, grade, climb, top, descent = hill[:5]
    x = np.asarray(x, dtype=float)
    if _curve(hill) > 0.0:
        points = [point for _, vertices in hill_profile(hill) for point in vertices]
        xs, zs = zip(*points)
        return np.interp(x, xs, zs)
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
    """The hill's road boxes, if the world has a hill: three for the sharp hill; with vertical curves
    the straights (a straight the curves use up is left out) and each curve's chords. The top and
    the curves' boxes reach below the ground."""
    if not world.hill:
        return
    hill = check_hill(world.hill)
    start, grade, climb, top, descent = hill[:5]
    rise = grade * climb
    if _curve(hill) <= 0.0:
        _ramp(spec, "hill_up", start, 0.0, climb, grade)
        _ramp(spec, "hill_top", start + climb, rise, top, 0.0, rise + HILL_DEPTH)   # down to the ground
        _ramp(spec, "hill_down", start + climb + top, rise, descent, -rise / descent)
        return
    for name, vertices in hill_profile(hill):
        for k, ((x0, z0), (x1, z1)) in enumerate(zip(vertices[:-1], vertices[1:])):
            if x1 - x0 <= 0.0:
                continue
            depth = HILL_DEPTH if name in ("up", "down") else max(z0, z1) + HILL_DEPTH
            _ramp(spec, f"hill_{name}" if name in ("up", "top", "down") else f"hill_{name}_{k}",
                  x0, z0, x1 - x0, (z1 - z0) / (x1 - x0), depth)
