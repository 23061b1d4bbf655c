"""Free flight under gravity: the one gravity constant, and the time a falling body takes to
come down to a height (used to time transitions in flight: a runner's touchdown, a dive's
opening)."""
from __future__ import annotations

import math

GRAVITY = 9.80665          # m/s^2, standard gravity (the model's world)


def time_to_fall_to(z: float, vz: float, z_end: float) -> float:
    """Ballistic time (s) until a point at height z moving up at vz comes down to z_end."""
    drop = max(z - z_end, 0.0)
    return (vz + math.sqrt(vz * vz + 2.0 * GRAVITY * drop)) / GRAVITY
