"""The trials of one plan that runs jumps one after another (planning/jump.py's plan from the measured
jumps, planning/commanded.py's aimed jumps): each trial's settings run through the planner's ``trial``
(settings -> (cost, measured)), the request's cancel checked before it and its progress reported after
it, and every trial kept in the order run. The trials are deterministic (the same settings fly the same jump, bit for
bit): ``seen(settings)`` says whether a settings dict was run already, so a planner whose next step repeats one (an
aim held at its range's bound) stops that step rather than spend a trial on no new information."""
from __future__ import annotations

from typing import Callable

from ..errors import Cancelled


class Trials:
    """``run(settings)`` runs one trial and returns what it measured; ``tried`` holds (cost, index,
    settings, measured) of each; ``progress(done, bound, best measured so far)`` and ``cancelled()``
    are the request's (None: none)."""

    def __init__(self, trial: Callable, bound: int, progress: Callable | None = None,
                 cancelled: Callable | None = None):
        self.trial, self.bound, self.progress, self.cancelled = trial, bound, progress, cancelled
        self.tried: list[tuple] = []

    def seen(self, settings: dict) -> bool:
        return any(settings == e[2] for e in self.tried)

    def run(self, settings: dict) -> dict:
        if self.cancelled is not None and self.cancelled():
            raise Cancelled("planning cancelled")
        cost, measured = self.trial(settings)
        self.tried.append((cost, len(self.tried), settings, measured))
        if self.progress is not None:
            self.progress(len(self.tried), self.bound, min(self.tried, key=lambda e: (e[0], e[1]))[3])
        return measured
