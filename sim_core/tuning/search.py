"""One search service: minimise a score over a bounded space of settings by CMA-ES (the ``cma``
package) or by simulated annealing (SciPy's ``dual_annealing``), behind one call.

Every calibration and plan asks this for its settings instead of running a loop of its own, so
that budgets, seeds, progress, cancel and parallel evaluation mean the same everywhere:

* ``budget`` is the exact number of evaluations, the start included (it is evaluated first):
  never more; fewer only when ``stop`` says the search is done or CMA-ES has converged.
* the same ``seed`` gives the same evaluations in the same order, whatever the executor: a
  batch is asked for whole, evaluated (in parallel where the executor can), and read back in
  the order asked; a batch's answers after the one ``stop`` accepted are dropped.
* ``progress(done, budget, best)`` is called after every batch (an annealing step is a batch of
  one); ``cancelled()`` is checked before each evaluation is handed out and while one is
  awaited: it raises ``Cancelled`` and the caller writes nothing.
* the search works in normalised coordinates (Space): ``sigma`` is a share of every range.
* ``method="scan"`` is the bounded list search: the start, then ``options["points"]`` (settings in
  natural units) in the order given, ``population`` at a time, until ``stop`` accepts one (a
  landing's plan: the table's foot placement, then steps on either side, nearest first).
"""
from __future__ import annotations

import math
import time
from concurrent.futures import FIRST_COMPLETED, wait
from dataclasses import dataclass, field
from typing import Any, Callable

import cma          # imported here, not inside a search: importing it takes ~1 s, and a cancel cannot land
import numpy as np  # while an import runs
from scipy.optimize import dual_annealing

from ..errors import Cancelled, ParameterError
from .executor import SerialExecutor
from .space import Space

METHODS = ("cma", "anneal", "scan")
CANCEL_POLL = 0.05          # s between looks at ``cancelled`` while an evaluation runs elsewhere
FAILED_SCORE = 1e12         # what annealing is told of a non-finite score (SciPy needs a number)


@dataclass(frozen=True)
class Evaluation:
    """One evaluation: its place in the search, the settings (natural units), the score and
    whatever else the objective measured (``extra``)."""
    index: int
    settings: dict
    score: float
    extra: Any = None


@dataclass
class SearchResult:
    method: str
    seed: int
    budget: int
    evaluations: list[Evaluation] = field(default_factory=list)
    ended: str = "budget"       # "budget", "stop" (the caller's stop accepted one), "converged" (CMA-ES),
                                # "scanned" (a scan evaluated every point)

    @property
    def best(self) -> Evaluation:
        return min(self.evaluations, key=lambda e: (_comparable(e.score), e.index))

    def best_where(self, accept: Callable[[Evaluation], bool]) -> Evaluation | None:
        """The lowest-scoring evaluation that ``accept`` takes (None if none)."""
        chosen = [e for e in self.evaluations if accept(e)]
        return min(chosen, key=lambda e: (_comparable(e.score), e.index)) if chosen else None


class _Ended(Exception):
    """Inside annealing: the budget is spent or ``stop`` accepted an evaluation."""


def minimize(objective: Callable, space: Space, method: str = "cma", budget: int = 100, seed: int = 0,
             start: dict | None = None, sigma: float = 0.25, population: int | None = None,
             progress: Callable | None = None, cancelled: Callable[[], bool] | None = None,
             stop: Callable[[Evaluation], bool] | None = None, executor=None,
             options: dict | None = None) -> SearchResult:
    """Minimise ``objective(settings) -> score`` or ``-> (score, extra)`` over ``space``.

    ``start``: settings to begin from (default: the middle of every range), evaluated first;
    ``sigma``: CMA-ES's first step as a share of each range; ``population``: CMA-ES's batch size
    (default: cma's, 4 + 3 ln n); ``stop(evaluation)``: True ends the search after that
    evaluation; ``executor``: where evaluations run (default serial, in this process);
    ``options``: passed to ``cma`` (its options) or to ``dual_annealing`` (keyword arguments); a
    scan's ``{"points": [settings, ...]}``, evaluated after the start in that order, ``population``
    (default 1) at a time."""
    if method not in METHODS:
        raise ParameterError(f"search method {method!r} is unknown; allowed: {', '.join(METHODS)}")
    if not isinstance(budget, int) or budget < 1:
        raise ParameterError(f"budget={budget!r}: must be a whole number of evaluations, at least 1")
    if not isinstance(seed, int) or seed < 0:
        raise ParameterError(f"seed={seed!r}: must be a whole number >= 0")
    if not 0.0 < sigma <= 1.0:
        raise ParameterError(f"sigma={sigma:g}: must be in (0, 1] (a share of each setting's range)")
    if population is not None and population < 2:
        raise ParameterError(f"population={population}: must be at least 2")
    run = _Run(objective, space, budget, progress, cancelled, stop, executor or SerialExecutor())
    result = SearchResult(method, seed, budget, run.log)
    z0 = space.normalise(start) if start is not None else np.full(len(space), 0.5)
    if not run.evaluate([z0]):
        result.ended = run.ended
        return result
    if method == "cma":
        result.ended = _cma(run, z0, seed, sigma, population, options or {})
    elif method == "scan":
        result.ended = _scan(run, (options or {}).get("points", []), population or 1)
    else:
        result.ended = _anneal(run, z0, seed, options or {})
    return result


class _Run:
    """The evaluations of one search: hands batches to the executor, logs them in order, and
    watches the budget, ``stop`` and ``cancelled``."""

    def __init__(self, objective, space, budget, progress, cancelled, stop, executor):
        self.objective, self.space, self.budget = objective, space, budget
        self.progress, self.cancelled, self.stop, self.executor = progress, cancelled, stop, executor
        self.log: list[Evaluation] = []
        self.ended = "budget"

    @property
    def left(self) -> int:
        return self.budget - len(self.log)

    def check_cancel(self, pending=()) -> None:
        if self.cancelled is not None and self.cancelled():
            for future in pending:
                future.cancel()
            raise Cancelled("search cancelled; nothing was written")

    def evaluate(self, points) -> bool:
        """Evaluate ``points`` (normalised; at most the budget left) in order; False once the
        search must end (budget spent or ``stop`` accepted one)."""
        points = list(points)[:self.left]
        settings = [self.space.settings(z) for z in points]
        futures = []
        if getattr(self.executor, "in_process", False):
            outcomes = (self._one(s) for s in settings)
        else:
            for s in settings:
                self.check_cancel(futures)
                futures.append(self.executor.submit(self.objective, s))
            outcomes = (self._await(f, futures) for f in futures)
        for s, outcome in zip(settings, outcomes):
            score, extra = outcome if isinstance(outcome, tuple) else (outcome, None)
            self.log.append(Evaluation(len(self.log), s, float(score), extra))
            if self.stop is not None and self.stop(self.log[-1]):
                self.ended = "stop"
                for future in futures:
                    future.cancel()     # a batch's answers after the accepted one are not read
                break
        if self.progress is not None and self.log:
            self.progress(len(self.log), self.budget, min(self.log, key=lambda e: (_comparable(e.score), e.index)))
        return self.ended != "stop" and self.left > 0

    def _one(self, settings):
        self.check_cancel()
        return self.executor.submit(self.objective, settings).result()

    def _await(self, future, futures):
        while not future.done():
            self.check_cancel(futures)
            wait([future], timeout=CANCEL_POLL, return_when=FIRST_COMPLETED)
        return future.result()


def _cma(run: _Run, z0, seed: int, sigma: float, population: int | None, options: dict) -> str:
    opts = {"bounds": [0.0, 1.0], "seed": seed + 1, "verbose": -9, **options}   # (cma takes seed 0 as "random")
    if population is not None:
        opts["popsize"] = population
    es = cma.CMAEvolutionStrategy(list(map(float, z0)), sigma, opts)
    while not es.stop():
        asked = es.ask()
        if not run.evaluate(asked):
            return run.ended
        es.tell(asked, [min(_comparable(e.score), FAILED_SCORE) for e in run.log[-len(asked):]])
    return "converged"


def _scan(run: _Run, points: list[dict], batch: int) -> str:
    """The given points (natural units) in order, ``batch`` at a time."""
    z = [run.space.normalise(p) for p in points]
    for k in range(0, len(z), batch):
        if not run.evaluate(z[k:k + batch]):
            return run.ended
    return "scanned"


def _anneal(run: _Run, z0, seed: int, options: dict) -> str:
    start_score = run.log[0].score
    first = [True]

    def score(z) -> float:
        if first[0] and np.array_equal(np.asarray(z, dtype=float), z0):
            first[0] = False        # SciPy's look at the start: it was the search's first evaluation
            return min(_comparable(start_score), FAILED_SCORE)
        first[0] = False
        if run.left <= 0 or not run.evaluate([z]):
            raise _Ended
        return min(_comparable(run.log[-1].score), FAILED_SCORE)

    kwargs = {"no_local_search": True, "maxiter": 10 * run.budget, "maxfun": 10 * run.budget, **options}
    try:
        dual_annealing(score, [(0.0, 1.0)] * len(run.space), x0=np.asarray(z0, dtype=float),
                       rng=np.random.default_rng(seed), **kwargs)
    except _Ended:
        return run.ended
    return "converged"


def _comparable(score: float) -> float:
    return score if math.isfinite(score) else math.inf


class StopAfterFound:
    """A ``stop`` that keeps the evaluations ``accept`` takes (``found``, in order) and ends the
    search at the ``count``-th (a calibration that chooses the most robust of a few found);
    ``report(evaluation)``, if given, sees every evaluation."""

    def __init__(self, accept: Callable[[Evaluation], bool], count: int, report: Callable | None = None):
        self.accept, self.count, self.report = accept, count, report
        self.found: list[Evaluation] = []

    def __call__(self, evaluation: Evaluation) -> bool:
        if self.report is not None:
            self.report(evaluation)
        if self.accept(evaluation):
            self.found.append(evaluation)
        return len(self.found) >= self.count

    def choose(self, result: SearchResult, fixed: dict, robust: Callable | None = None) -> tuple[float, dict, Any]:
        """(score, settings with the ``fixed`` ones, extra) a calibration keeps: the search's best if
        none was found, else ``robust(found)`` (a list of such tuples, best first) or the best found."""
        if not self.found:
            return result.best.score, dict(fixed, **result.best.settings), result.best.extra
        found = sorted(((e.score, dict(fixed, **e.settings), e.extra) for e in self.found), key=lambda r: r[0])
        return robust(found) if robust is not None else found[0]


def deadline_stop(seconds: float) -> Callable[[Evaluation], bool]:
    """A ``stop`` that ends a search once ``seconds`` of wall time have passed (a time-boxed
    search; its result then depends on the machine's speed)."""
    end = time.monotonic() + seconds
    return lambda evaluation: time.monotonic() > end
