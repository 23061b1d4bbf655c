"""The trials of one plan that runs jumps one after another (planning/jump.py's plan from the measured
jumps, planning/commanded.py's aimed jumps): each trial's settings run through the planner's ``trial``
(settings -> (cost, measured)), the request's cancel checked before it and its progress reported after
it, and every trial kept in the order run."""
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

    def run(self, settings: dict) -> dict:
        if self.cancelled is not None and self.cancelled():
            raise Cancelled("planning cancelled")
        cost, measured = self.trial(settings)
        self.tried.append((cost, len(self.tried), settings, measured))
        if self.progress is not None:
            self.progress(len(self.tried), self.bound, min(self.tried, key=lambda e: (e[0], e[1]))[3])
        return measured
