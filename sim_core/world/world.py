"""World: what a run asks of its surroundings (ground height, slope, props). Pure data plus the
gravity of the slope; the geoms are made by sim_core.world.props."""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..ballistics import GRAVITY
from .bicycle import Bicycle

APPARATUS_FIELDS = ("springboard", "vault_table", "landing_mat")   # recorded only when asked for
SLOPE_RAMP_PER_DEGREE = 0.15   # s per degree: the ground tilts at ~6.7 deg/s


@dataclass
class World:
    """The world a character is put in. ``slope`` tilts the ground (radians) about the axis
    named by ``slope_axis``: 'x+' means the ground rises towards +X. As in Wooten §7.3 the
    ground starts level and tilts to the slope along a Hermite curve over ``slope_ramp``
    seconds from ``slope_start``. The tilt is implemented by turning gravity, which is exactly
    equivalent for a flat plane; each change is a logged model edit.

    ``platform`` > 0 makes a diving platform: the character stands on a platform whose top is
    the z = 0 plane (so every standing controller works unchanged) and whose edge is just behind
    the heels (the -X side, where a diver standing backwards has the water) or, with
    ``platform_edge='ahead'``, just ahead of the toes (facing the water); the water surface
    is ``platform`` metres below. Water is not simulated: the dive ends at entry (Wooten §8.2.1
    lets entering the water end the run)."""
    slope: float = 0.0
    slope_axis: str = "x+"
    extra_mass: dict[str, float] = field(default_factory=dict)   # body -> added kg (backpack)
    slope_start: float = 0.5
    slope_ramp: float | None = None            # s; default SLOPE_RAMP_PER_DEGREE per degree
    platform: float = 0.0                      # m: height of a diving platform above the water (0 = none)
    platform_edge: str = "behind"              # 'behind' the heels (water at -X) or 'ahead' of the toes (+X)
    boxes: tuple = ()                          # ((x, y, height, length, width), ...) m: boxes standing on the
                                               # ground, centred at (x, y), their tops at z = height, to jump
                                               # onto, from or over (geoms "box0", "box1", ...)
    floor: float = 0.0                         # m: height of the ground plane. Below 0, the character starts
                                               # on a box (a box of World.boxes with its top at z = 0, so every
                                               # standing controller works unchanged) and can jump down
    bicycle: Bicycle | None = None             # the bicycle prop (sim_core.world.bicycle), None: no bicycle
    springboard: tuple = ()                    # (x, y[, stiffness N/m]) m: a springboard's centre (geom "springboard"), () = none
    vault_table: tuple = ()                    # (x, y, height, length, width) m: a vaulting table or horse
    landing_mat: tuple = ()                    # (x, y, length, width, thickness) m: a mat softer than the floor
                                               # (sim_core.world.apparatus: figures, checks and builders)
    hill: tuple = ()                           # (start x, grade, climb, top, descent) m: a hill across +X
                                               # (sim_core.world.hill), () = none

    @property
    def ramp_time(self) -> float:
        if self.slope_ramp is not None:
            return self.slope_ramp
        return max(1.0, SLOPE_RAMP_PER_DEGREE * math.degrees(self.slope))

    def gravity(self, t: float = 0.0) -> np.ndarray:
        s = min(max((t - self.slope_start) / self.ramp_time, 0.0), 1.0) if self.slope else 0.0
        return gravity_for_slope(self.slope * s * s * (3.0 - 2.0 * s), self.slope_axis)

    def tilting(self, t: float) -> bool:
        return bool(self.slope) and t <= self.slope_start + self.ramp_time + 0.02

    def to_dict(self) -> dict:
        """The world as recorded in a trajectory's meta."""
        return {"slope": self.slope, "slope_axis": self.slope_axis, "extra_mass": self.extra_mass,
                "platform": self.platform, "platform_edge": self.platform_edge,
                "boxes": [list(b) for b in self.boxes], "floor": self.floor,
                **({"bicycle": self.bicycle.to_dict()} if self.bicycle else {}),
                **{name: list(getattr(self, name)) for name in APPARATUS_FIELDS if getattr(self, name)},
                **({"hill": list(self.hill)} if self.hill else {})}


def gravity_for_slope(slope: float, axis: str) -> np.ndarray:
    g = GRAVITY
    # ground rising towards +X by angle a == gravity tilted to pull towards -X in the ground frame
    direction = {"x+": np.array([-1.0, 0, 0]), "x-": np.array([1.0, 0, 0]),
                 "y+": np.array([0, -1.0, 0]), "y-": np.array([0, 1.0, 0])}[axis]
    return g * (math.sin(slope) * direction - math.cos(slope) * np.array([0, 0, 1.0]))
