"""The search service (sim_core.tuning): exact budgets, seeds, both methods, cancel, and results
that do not depend on the executor."""
from __future__ import annotations

import time

import pytest

from sim_core.errors import Cancelled, ParameterError
from sim_core.tuning import LocalPool, SerialExecutor, Space, minimize

SPACE = Space({"a": (-2.0, 2.0), "b": (0.0, 10.0), "c": (-1.0, 1.0)})
OPTIMUM = {"a": 0.7, "b": 3.0, "c": -0.4}


def bowl(settings: dict) -> tuple[float, dict]:
    """A smooth bowl with its bottom at OPTIMUM (module level: a process pool pickles it)."""
    score = sum(((settings[n] - OPTIMUM[n]) / (SPACE.high[k] - SPACE.low[k])) ** 2 for k, n in enumerate(SPACE.names))
    return score, {"sum": sum(settings.values())}


def slow_bowl(settings: dict) -> float:
    time.sleep(0.02)
    return bowl(settings)[0]


@pytest.mark.parametrize("method", ["cma", "anneal"])
def test_each_method_minimises_a_bowl_within_its_exact_budget(method):
    start = {"a": -1.5, "b": 9.0, "c": 0.9}
    result = minimize(bowl, SPACE, method=method, budget=300, seed=3, start=start)
    assert len(result.evaluations) == 300 and result.ended == "budget"
    assert result.evaluations[0].settings == pytest.approx(start)        # the start is evaluated first
    assert result.best.score < 0.01 < 0.1 < result.evaluations[0].score     # annealing (no local search) is the slower
    assert result.best.extra == {"sum": pytest.approx(sum(result.best.settings.values()))}
    assert all(SPACE.low[k] <= e.settings[n] <= SPACE.high[k] for e in result.evaluations
               for k, n in enumerate(SPACE.names))


@pytest.mark.parametrize("method", ["cma", "anneal"])
@pytest.mark.parametrize("budget", [1, 2, 7, 13])
def test_the_budget_is_exact(method, budget):
    assert len(minimize(bowl, SPACE, method=method, budget=budget, seed=0, population=4).evaluations) == budget


@pytest.mark.parametrize("method", ["cma", "anneal"])
def test_the_same_seed_gives_the_same_search_and_another_seed_another(method):
    runs = [minimize(bowl, SPACE, method=method, budget=30, seed=s) for s in (5, 5, 6)]
    assert [e.settings for e in runs[0].evaluations] == [e.settings for e in runs[1].evaluations]
    assert [e.settings for e in runs[0].evaluations] != [e.settings for e in runs[2].evaluations]


@pytest.mark.parametrize("method", ["cma", "anneal"])
def test_one_or_two_worker_processes_give_the_same_result(method):
    serial = minimize(bowl, SPACE, method=method, budget=24, seed=2, population=6)
    with LocalPool(2) as pool:
        pooled = minimize(bowl, SPACE, method=method, budget=24, seed=2, population=6, executor=pool)
    assert [(e.settings, e.score, e.extra) for e in serial.evaluations] == \
           [(e.settings, e.score, e.extra) for e in pooled.evaluations]


def test_stop_ends_the_search_after_the_accepted_evaluation_whatever_the_executor():
    def stop(evaluation):
        return evaluation.score < 0.05
    serial = minimize(bowl, SPACE, budget=200, seed=1, population=8, stop=stop)
    with LocalPool(2) as pool:
        pooled = minimize(bowl, SPACE, budget=200, seed=1, population=8, stop=stop, executor=pool)
    assert serial.ended == "stop" and len(serial.evaluations) < 200 and stop(serial.evaluations[-1])
    assert [e.settings for e in serial.evaluations] == [e.settings for e in pooled.evaluations]


def test_progress_is_called_per_batch_with_the_best_so_far():
    calls = []
    minimize(bowl, SPACE, budget=13, seed=0, population=4, progress=lambda done, total, best: calls.append((done, total, best.score)))
    assert [c[0] for c in calls] == [1, 5, 9, 13] and all(c[1] == 13 for c in calls)
    assert all(b[2] <= a[2] for a, b in zip(calls, calls[1:]))


@pytest.mark.parametrize("executor", [SerialExecutor, lambda: LocalPool(2)])
@pytest.mark.parametrize("method", ["cma", "anneal"])
def test_cancel_raises_and_stops_between_evaluations(method, executor):
    done = []

    def counting(settings):
        done.append(1)
        return bowl(settings)

    with executor() as ex:
        if isinstance(ex, LocalPool):
            started = time.monotonic()
            with pytest.raises(Cancelled):
                minimize(slow_bowl, SPACE, method=method, budget=1000, seed=0, executor=ex,
                         cancelled=lambda: time.monotonic() - started > 0.3)
            assert time.monotonic() - started < 1.5
        else:
            with pytest.raises(Cancelled, match="nothing was written"):
                minimize(counting, SPACE, method=method, budget=100, seed=0, executor=ex,
                         cancelled=lambda: len(done) >= 5)
            assert len(done) == 5


def test_bad_requests_are_refused_with_the_allowed_values():
    with pytest.raises(ParameterError, match="allowed: cma, anneal"):
        minimize(bowl, SPACE, method="grid")
    with pytest.raises(ParameterError, match="budget=0"):
        minimize(bowl, SPACE, budget=0)
    with pytest.raises(ParameterError, match="start settings lack b, c"):
        minimize(bowl, SPACE, start={"a": 0.0})
    with pytest.raises(ParameterError, match=r"range \[1, 1\] is empty"):
        Space({"x": (1.0, 1.0)})
    with pytest.raises(ParameterError, match="workers=0"):
        LocalPool(0)


def test_a_space_from_a_schema_uses_its_ranges_or_narrower_ones():
    from sim_core.skills import behaviour_class
    schema = behaviour_class("leap").schema
    space = Space.from_schema(schema, ["crouch_height", "arm_swing"], narrower={"arm_swing": (0.5, 3.0)})
    p = schema.by_name["crouch_height"]
    assert space.bounds() == {"crouch_height": (p.minimum, p.maximum), "arm_swing": (0.5, 3.0)}
    assert space.settings(space.normalise({"crouch_height": p.minimum, "arm_swing": 1.0})) == \
           pytest.approx({"crouch_height": p.minimum, "arm_swing": 1.0})
    with pytest.raises(ParameterError, match="unknown setting 'nope'"):
        Space.from_schema(schema, ["nope"])
