"""Where evaluations run: one interface in the style of ``concurrent.futures`` (``submit``,
``map``, used as a context manager), with a local process pool as the default and a serial one
for tests and debugging.

A search's result does not depend on the executor: the search asks for a whole batch, collects
the answers in the order asked, and only then decides the next batch. A function given to the
process pool must be picklable (a module-level function, a ``functools.partial`` of one, or an
object of a module-level class).
"""
from __future__ import annotations

import os
from concurrent.futures import Future, ProcessPoolExecutor

from ..errors import ParameterError


class SerialExecutor:
    """Runs each evaluation at once, in this process (``submit`` returns a finished future).
    In-process evaluations can see a ``cancelled`` callable, so a cancel can land inside one."""

    in_process = True

    def submit(self, fn, *args, **kwargs) -> Future:
        future: Future = Future()
        try:
            future.set_result(fn(*args, **kwargs))
        except BaseException as exc:  # noqa: BLE001 - handed to the caller through the future
            if isinstance(exc, (KeyboardInterrupt, SystemExit)):
                raise
            future.set_exception(exc)
        return future

    def map(self, fn, *iterables):
        return [self.submit(fn, *args).result() for args in zip(*iterables)]

    def shutdown(self, wait: bool = True, cancel_futures: bool = False) -> None:
        pass

    def __enter__(self):
        return self

    def __exit__(self, *exc) -> None:
        self.shutdown()


class LocalPool:
    """A pool of ``workers`` processes on this machine (default: one per CPU)."""

    in_process = False

    def __init__(self, workers: int | None = None):
        self.workers = default_workers() if workers is None else check_workers(workers)
        self._pool = ProcessPoolExecutor(max_workers=self.workers)

    def submit(self, fn, *args, **kwargs) -> Future:
        return self._pool.submit(fn, *args, **kwargs)

    def map(self, fn, *iterables):
        return list(self._pool.map(fn, *iterables))

    def shutdown(self, wait: bool = True, cancel_futures: bool = False) -> None:
        self._pool.shutdown(wait=wait, cancel_futures=cancel_futures)

    def __enter__(self):
        return self

    def __exit__(self, *exc) -> None:
        # on an error or a cancel, do not wait for evaluations nobody will read
        self.shutdown(wait=exc[0] is None, cancel_futures=exc[0] is not None)


def default_workers() -> int:
    return os.cpu_count() or 1


def check_workers(workers: int) -> int:
    if not isinstance(workers, int) or isinstance(workers, bool) or not 1 <= workers <= 256:
        raise ParameterError(f"workers={workers!r}: must be a whole number in [1, 256]")
    return workers


def executor_for(workers: int | None):
    """The executor of a ``--workers`` option: serial for 1, else a local pool (None: one per CPU)."""
    if workers is not None and check_workers(workers) == 1:
        return SerialExecutor()
    return LocalPool(workers)
