"""High-level control: a sequence runs basis behaviours one after another (Wooten ch. 1, 8).

A step ends when its exit condition, read off the measured state, holds - the exit region of one
behaviour inside the capture region of the next - not at a hand-set time, except where a skill
calls for a timed trigger. The next step's behaviour is built at that moment, so its parameters
may depend on the state (e.g. the landing's crouch height)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from .behaviour import Behaviour


@dataclass
class Step:
    name: str
    make: Callable[[float], Behaviour]                 # t -> the step's behaviour, built at its start
    done: Callable[[Behaviour, float], bool] | None = None   # exit condition; None: the last step


class Sequence(Behaviour):
    """Base class of composite skills: subclasses return their script from ``steps()``."""

    def steps(self) -> list[Step]:
        raise NotImplementedError

    def start(self, t: float) -> None:
        self.script = self.steps()
        self.index = -1
        self.current: Behaviour | None = None
        self._advance(t)

    def _advance(self, t: float) -> None:
        self.index += 1
        step = self.script[self.index]
        self.previous = self.current        # the step that just ended: the next may start from it
        self.current = step.make(t)
        self.current.phase_events = self.phase_events          # one list of events for the run
        self.event(t, step.name)
        self.current.start(t)

    def update(self, t: float) -> None:
        step = self.script[self.index]
        if step.done is not None and step.done(self.current, t):
            self._advance(t)
        self.current.update(t)

    @property
    def step_name(self) -> str:
        return self.script[self.index].name
