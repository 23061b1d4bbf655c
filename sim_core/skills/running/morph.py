"""The runner's controller while its body turns into another's (Hodgins & Pollard 1997, the
metamorphosis): the control model follows the body's fraction f of the way. The table rows at the
running speed, the constants of the laws and the leg's lengths are the two characters' interpolated;
the five tuned parameters may also ride linear ramps (an offset at f = 1, reached linearly,
kept after the morph), which the seed searched because the plain interpolation fell.
"""
from __future__ import annotations

import copy

import numpy as np

from ...character.morph import lerp
from .leg import RunnerLeg

RAMPED = ("ground_speed_matching", "stance_pitch", "thrust_time", "ankle_extension", "knee_extension")


class MorphTable:
    """A SpeedTable's face (``values``, ``constants``, ``at``) for a body ``fraction`` of the way
    from the start table's character to the end table's: each column at the speed interpolated,
    plus ``fraction`` times the column's ramp offset (held within the column's range, ``bounds``)."""

    def __init__(self, start, end, offsets: dict[str, float], bounds: dict[str, tuple[float, float]]):
        self.start, self.end, self.offsets, self.bounds = start, end, dict(offsets), bounds
        self.values = {n: v for n, v in start.values.items() if n in end.values}
        self.constants = start.constants
        self.speeds = start.speeds
        self.fraction = 0.0

    def at(self, name: str, speed: float) -> float:
        f = self.fraction
        value = lerp(self.start.at(name, speed), self.end.at(name, speed), f)
        if name not in self.offsets:
            return value
        low, high = self.bounds[name]
        return min(high, max(low, value + f * self.offsets[name]))


def morph_ramps(target: str, params: dict) -> dict[str, float]:
    """The ramps' offsets at f = 1: the request's ``morph_ramps`` (a tuner's candidate), else none."""
    return {n: float(v) for n, v in params.get("morph_ramps", {}).items()}


def leg_between(a: RunnerLeg, b: RunnerLeg, f: float) -> RunnerLeg:
    """The leg model with every measure interpolated (the body's own legs follow the same f)."""
    leg = copy.copy(a)
    for name, value in vars(a).items():
        setattr(leg, name, lerp(value, getattr(b, name), f))
    return leg


def morph_speed_metrics(time: np.ndarray, speed: np.ndarray, params: dict, fall_time: float | None) -> dict:
    """The ground speed (of the COM) during the morph and after it, against the commanded speed:
    the mean and its error, and the worst error of a 1 s mean (a stride's three steps) during the
    morph; up to a fall, if there is one."""
    begin, end = params["morph_start"], params["morph_start"] + params["morph_time"]
    stop = fall_time if fall_time is not None else np.inf
    out = {}
    for key, (t0, t1) in (("during_morph", (begin, end)), ("after_morph", (end, stop))):
        sel = (time >= t0) & (time < min(t1, stop))
        mean = float(speed[sel].mean()) if sel.any() else None
        out[f"speed_{key}"] = mean
        out[f"speed_error_{key}"] = None if mean is None else mean / params["speed"] - 1.0
    sel = (time >= begin) & (time < min(end, stop))
    dt = float(time[1] - time[0]) if len(time) > 1 else 1.0
    window = max(1, int(round(1.0 / dt)))           # definition: 1 s
    if sel.sum() >= window:
        means = np.convolve(speed[sel], np.ones(window) / window, mode="valid")
        out["speed_error_worst_1s_during_morph"] = float(np.max(np.abs(means / params["speed"] - 1.0)))
    return out
