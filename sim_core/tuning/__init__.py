"""The search service (search.py: CMA-ES and annealing behind one call), the bounded spaces it
searches (space.py) and the executors that run its evaluations (executor.py). See
docs/planning.md."""
from sim_core.tuning.executor import LocalPool, SerialExecutor, executor_for
from sim_core.tuning.search import Evaluation, SearchResult, StopAfterFound, deadline_stop, minimize
from sim_core.tuning.space import Space

__all__ = ["Evaluation", "LocalPool", "SearchResult", "SerialExecutor", "Space", "StopAfterFound", "deadline_stop",
           "executor_for", "minimize"]
