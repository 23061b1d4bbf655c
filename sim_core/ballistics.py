"""Free flight under gravity: the one gravity constant, and the time a falling body takes to
come down to a height (used to time transitions in flight: a runner's touchdown, a dive's
opening), and the flat-ground air time of a flight between two heights (a jump onto or down from a
box flown with a take-off measured on flat ground)."""
from __future__ import annotations

import math

GRAVITY = 9.80665          # m/s^2, standard gravity (the model's world)


def time_to_fall_to(z: float, vz: float, z_end: float) -> float:
    """Ballistic time (s) until a point at height z moving up at vz comes down to z_end."""
    drop = max(z - z_end, 0.0)
    return (vz + math.sqrt(vz * vz + 2.0 * GRAVITY * drop)) / GRAVITY


def flat_air_time(rise: float, air_time: float) -> float:
    """The air time on flat ground of the vertical lift-off speed that lands ``rise`` m higher (< 0:
    lower) in ``air_time`` s: v_z = rise / T + g T / 2 rises and falls back in 2 v_z / g."""
    return air_time + 2.0 * rise / (GRAVITY * air_time)
