"""A bounded search space: named settings, each with a low and a high end.

A search works in normalised coordinates (every setting mapped to [0, 1] by its range), so that
one step size means the same share of every range - a crouch height in metres and a gain in
N m/rad are searched alike.
"""
from __future__ import annotations

import math

import numpy as np

from ..errors import ParameterError


class Space:
    """Named settings with their ranges, in the order given (the order of a search's vectors)."""

    def __init__(self, bounds: dict[str, tuple[float, float]], decimals: int | None = None):
        """``decimals``: settings handed out rounded to this many decimals (a table then stores
        exactly what was run)."""
        self.decimals = decimals
        if not bounds:
            raise ParameterError("a search space needs at least one setting")
        for name, (low, high) in bounds.items():
            if not (math.isfinite(low) and math.isfinite(high) and low < high):
                raise ParameterError(f"setting {name}: range [{low:g}, {high:g}] is empty or not finite; "
                                     f"the low end must be below the high end")
        self.names = list(bounds)
        self.low = np.array([float(bounds[n][0]) for n in self.names])
        self.high = np.array([float(bounds[n][1]) for n in self.names])

    @classmethod
    def from_schema(cls, schema, names, narrower: dict[str, tuple[float, float]] | None = None) -> "Space":
        """The settings ``names`` of a parameter ``schema`` with the schema's ranges, or the ranges
        of ``narrower`` where it names one (a search may keep inside the allowed range)."""
        narrower = narrower or {}
        bounds = {}
        for name in names:
            if name not in schema.by_name:
                raise ParameterError(f"unknown setting {name!r}; known: {', '.join(schema.by_name)}")
            p = schema.by_name[name]
            bounds[name] = narrower.get(name, (p.minimum, p.maximum))
        return cls(bounds)

    def __len__(self) -> int:
        return len(self.names)

    def bounds(self) -> dict[str, tuple[float, float]]:
        return {n: (float(lo), float(hi)) for n, lo, hi in zip(self.names, self.low, self.high)}

    def normalise(self, settings: dict) -> np.ndarray:
        """Settings (natural units; every name of the space) -> a point of [0, 1]^n (clipped)."""
        missing = [n for n in self.names if n not in settings]
        if missing:
            raise ParameterError(f"start settings lack {', '.join(missing)}; the space has {', '.join(self.names)}")
        x = np.array([float(settings[n]) for n in self.names])
        return np.clip((x - self.low) / (self.high - self.low), 0.0, 1.0)

    def settings(self, z) -> dict[str, float]:
        """A point of [0, 1]^n (clipped into it) -> settings in natural units."""
        z = np.clip(np.asarray(z, dtype=float), 0.0, 1.0)
        x = self.low + z * (self.high - self.low)
        if self.decimals is not None:
            x = np.round(x, self.decimals)
        return {n: float(v) for n, v in zip(self.names, x)}

    def middle(self) -> dict[str, float]:
        return self.settings(np.full(len(self), 0.5))
