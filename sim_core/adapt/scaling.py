"""The scaling rules of Hodgins & Pollard 1997, Fig. 6, implemented once.

A quantity is described by its units as powers of length, time and mass (``Units``). Gravity and
density are invariant, so under a geometric scaling of every length by L, time scales by L^1/2
(a pendulum's period) and mass by L^3; a quantity with units L^l T^t M^m therefore scales by
L^(l + t/2 + 3m) (Fig. 6, "geom. scaling" column).

Mass scaling (Fig. 6, last column; eqs. 2-4) replaces the geometric mass factor by the actual
ratio of the new to the original character's masses: M = m'/m for a linear quantity (a force, a
spring on the hands), and I = I'/I, the ratio of the moments of inertia of the bodies the
quantity moves, for a rotational one (a torque, a joint servo's stiffness or damping), whose mass
enters as a moment of inertia (M L^2). One formula serves both columns: geometric scaling is mass
scaling with M = L^3 and I = L^5.

    >>> scale(1200.0, TORSIONAL_STIFFNESS, ScaleFactors(length=0.5))      # a hip servo's kp
    75.0

Which bodies a gain moves (and so its I) is decided elsewhere (sim_core.adapt.moved_bodies);
here only the arithmetic lives, so every tagged controller parameter is scaled by the same rule.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

from ..errors import ParameterError


@dataclass(frozen=True)
class Units:
    """Powers of length, time and mass. ``rotational``: the mass enters as a moment of inertia
    (M L^2), so mass scaling uses the inertia ratio I (torques, torsional springs and dampers,
    angular momentum) instead of the mass ratio M."""
    length: float = 0.0
    time: float = 0.0
    mass: float = 0.0
    rotational: bool = False

    def __post_init__(self):
        if self.rotational and self.mass and self.length / self.mass < 2:
            raise ParameterError(f"rotational units need the length power >= 2 x the mass power (M L^2 is an "
                                 f"inertia); got L^{self.length:g} M^{self.mass:g}")

    @classmethod
    def parse(cls, text: str, rotational: bool | None = None) -> "Units":
        """Units from a unit string as the behaviour schemas write them: 'm', 's', 'rad/m',
        'rad s/m', 'kg m²/s', 'N m/rad', 'N m s/rad', 'm/s^2', '1', 'bool', 'count', 'share'.
        'rad', '1', 'bool', 'count' and 'share' (a share of a servo's default gains, which
        adapt.settings scales by the bodies its state moves) are dimensionless; 'N' is kg m s^-2. ``rotational`` None:
        rotational when the mass can be read as a moment of inertia (a length power at least
        twice the mass power, with the same sign), i.e. torques, torsional gains, angular momenta
        and their inverses."""
        powers = {"length": 0.0, "time": 0.0, "mass": 0.0}
        for symbol, power in _unit_powers(text.strip().translate(_SUPERSCRIPTS), 1.0, text):
            for quantity, p in _BASE_UNITS[symbol].items():
                powers[quantity] += power * p
        if rotational is None:
            rotational = bool(powers["mass"]) and powers["length"] / powers["mass"] >= 2
        return cls(rotational=rotational, **powers)


_BASE_UNITS = {"m": {"length": 1}, "s": {"time": 1}, "kg": {"mass": 1},
               "N": {"mass": 1, "length": 1, "time": -2}, "rad": {}, "1": {}, "bool": {}, "count": {},
               "share": {}}
_SUPERSCRIPTS = str.maketrans("²³⁻¹", "23-1")


def _unit_powers(text: str, sign: float, whole: str):
    """(symbol, power) pairs of a unit expression: products of symbols with optional powers,
    '/' dividing by everything after it, parentheses grouping (so 'rad/(kg m^2/s)' works)."""
    depth, cut = 0, None
    for i, ch in enumerate(text):
        depth += ch == "("
        depth -= ch == ")"
        if ch == "/" and depth == 0:
            cut = i
            break
    if cut is not None:
        yield from _unit_powers(text[:cut], sign, whole)
        yield from _unit_powers(text[cut + 1:], -sign, whole)
        return
    text = text.strip()
    if text.startswith("(") and text.endswith(")"):
        yield from _unit_powers(text[1:-1], sign, whole)
        return
    for token in text.split():
        match = re.fullmatch(r"([A-Za-z]+|1)(?:\^?(-?\d+(?:\.\d+)?))?", token)
        if not match or match.group(1) not in _BASE_UNITS:
            raise ParameterError(f"unit {whole!r}: {token!r} is not one of {', '.join(_BASE_UNITS)} "
                                 "(with an optional power)")
        yield match.group(1), sign * (float(match.group(2)) if match.group(2) else 1.0)


@dataclass(frozen=True)
class ScaleFactors:
    """``length``: the geometric factor L (the seed takes the leg-length ratio for runners, the
    wheel-radius ratio for the cyclist). ``mass`` (M = m'/m) and ``inertia`` (I = I'/I) are the
    actual ratios of the bodies a quantity moves; None = geometric (M = L^3, I = L^5)."""
    length: float
    mass: float | None = None
    inertia: float | None = None

    def __post_init__(self):
        for name in ("length", "mass", "inertia"):
            value = getattr(self, name)
            if value is not None and not (math.isfinite(value) and value > 0):
                raise ParameterError(f"scale factor {name}={value!r} must be a finite number > 0")

    @property
    def mass_ratio(self) -> float:
        return self.length ** 3 if self.mass is None else self.mass

    @property
    def inertia_ratio(self) -> float:
        return self.length ** 5 if self.inertia is None else self.inertia


def factor(units: Units, factors: ScaleFactors) -> float:
    """The multiplier Fig. 6 gives a quantity of ``units`` for ``factors``."""
    L = factors.length
    time_part = L ** (units.time / 2)                     # T = L^1/2 under invariant gravity
    if units.rotational:                                  # M L^2 -> I: I^m L^(l - 2m)
        return factors.inertia_ratio ** units.mass * L ** (units.length - 2 * units.mass) * time_part
    return factors.mass_ratio ** units.mass * L ** units.length * time_part


def scale(value: float, units: Units, factors: ScaleFactors) -> float:
    """``value`` (of ``units``) for the new character: the one entry point the controllers' tagged
    parameters go through."""
    return value * factor(units, factors)


# Fig. 6's rows, as named units (the table's quantities; F = M L T^-2).
LENGTH = DISPLACEMENT = Units(length=1)
TIME = Units(time=1)
FORCE = Units(length=1, time=-2, mass=1)
TORQUE = Units(length=2, time=-2, mass=1, rotational=True)
VELOCITY = Units(length=1, time=-1)
ACCELERATION = Units(length=1, time=-2)
ANGLE = Units()
ANGULAR_VELOCITY = Units(time=-1)
ANGULAR_ACCELERATION = Units(time=-2)
MASS = Units(mass=1)
STIFFNESS = Units(time=-2, mass=1)                         # N/m
DAMPING = Units(time=-1, mass=1)                           # N s/m
MOMENT_OF_INERTIA = Units(length=2, mass=1, rotational=True)
TORSIONAL_STIFFNESS = Units(length=2, time=-2, mass=1, rotational=True)   # N m/rad
TORSIONAL_DAMPING = Units(length=2, time=-1, mass=1, rotational=True)     # N m s/rad
