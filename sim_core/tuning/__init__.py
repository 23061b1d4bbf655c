"""The search service (search.py: CMA-ES and annealing behind one call), the bounded spaces it
searches (space.py) and the executors that run its evaluations (executor.py). See
docs/planning.md."""
from .executor import ClusterExecutor, LocalPool, SerialExecutor, executor_for
from .search import Evaluation, SearchResult, StopAfterFound, deadline_stop, minimize
from .space import Space

__all__ = ["ClusterExecutor", "Evaluation", "LocalPool", "SearchResult", "SerialExecutor", "Space", "StopAfterFound", "deadline_stop",
           "executor_for", "minimize"]
