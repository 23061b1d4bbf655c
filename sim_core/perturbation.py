"""Pushes: named, logged test inputs - the only external force the code ever applies.

A push is a constant force on a body's centre of mass (the sternum's by default, as in Wooten
§7.3) for a given time. It is written into ``xfrc_applied`` through the run's edit log, so the
trajectory records it and a replay re-applies it. Start and end snap to control ticks.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

from .edit_log import EditLog, applied_forces
from .errors import ParameterError

DIRECTIONS = {"forward": 0.0, "forward_left": 45.0, "left": 90.0, "back_left": 135.0,
              "back": 180.0, "back_right": 225.0, "right": 270.0, "forward_right": 315.0}


@dataclass(frozen=True)
class Push:
    force: float                  # N
    direction_deg: float          # heading of the force in the ground plane, 0 = +X, 90 = +Y
    start: float = 1.0            # s
    duration: float = 0.25        # s
    body: str = "STERNUM"
    name: str = "push"

    def vector(self) -> np.ndarray:
        a = math.radians(self.direction_deg)
        return np.array([self.force * math.cos(a), self.force * math.sin(a), 0.0])

    @classmethod
    def parse(cls, text: str) -> "Push":
        """'FORCE@DIRECTION[:START[:DURATION]]', DIRECTION in degrees or a name like 'back'."""
        try:
            force_text, _, rest = text.partition("@")
            parts = rest.split(":")
            direction = DIRECTIONS[parts[0]] if parts[0] in DIRECTIONS else float(parts[0])
            values = dict(force=float(force_text), direction_deg=direction)
            if len(parts) > 1:
                values["start"] = float(parts[1])
            if len(parts) > 2:
                values["duration"] = float(parts[2])
        except (ValueError, IndexError):
            raise ParameterError(f"--push {text!r} must look like FORCE@DIRECTION[:START[:DURATION]], "
                                 f"e.g. 120@back:1.0:0.25 (DIRECTION in degrees or one of {', '.join(DIRECTIONS)})") from None
        push = cls(**values)
        push.check()
        return push

    def check(self) -> None:
        for name, value, lo, hi in (("force", self.force, 0.0, 5000.0), ("start", self.start, 0.0, 1e5),
                                    ("duration", self.duration, 0.001, 60.0)):
            if not (math.isfinite(value) and lo <= value <= hi):
                raise ParameterError(f"push {name}={value} is out of range; allowed range is [{lo:g}, {hi:g}]")

    def to_dict(self) -> dict:
        return asdict(self)


class PushSchedule:
    def __init__(self, pushes, model, data, log: EditLog):
        self.pushes = list(pushes)
        self.data, self.log = data, log
        self.body_ids = [model.body(p.body).id for p in self.pushes]
        self.active = [False] * len(self.pushes)

    def apply(self, t: float, half_tick: float) -> None:
        for k, push in enumerate(self.pushes):
            on = push.start - half_tick <= t < push.start + push.duration - half_tick
            if on != self.active[k]:
                self.active[k] = on
                wrench = np.zeros((1, 6))
                if on:
                    wrench[0, :3] = push.vector()
                row = np.array([self.body_ids[k]])
                for col in range(3):
                    self.log.set_array(applied_forces(self.data), "push_force", row, col, wrench[0, col:col + 1])
