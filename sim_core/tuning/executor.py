"""Where evaluations run: one interface in the style of ``concurrent.futures`` (``submit``,
``map``, used as a context manager), with a local process pool as the default, a serial one
for tests and debugging, and a cluster of other machines through Dask distributed.

Dask distributed rather than Ray: its ``Client.submit`` is this interface already (a function and
its arguments, pickled), it is pure Python from PyPI with no object store or daemon of its own to
install, and a scheduler with workers on other machines is two commands (``dask scheduler``,
``dask worker ADDRESS``); Ray's actors and object store are more than a search of independent
simulations needs.

A search's result does not depend on the executor: the search asks for a whole batch, collects
the answers in the order asked, and only then decides the next batch. A function given to the
process pool must be picklable (a module-level function, a ``functools.partial`` of one, or an
object of a module-level class).
"""
from __future__ import annotations

import os
from concurrent.futures import Future, ProcessPoolExecutor

from ..errors import ParameterError

CLUSTER_CONNECT_TIMEOUT = 10.0      # s: how long a scheduler may take to answer before the address is refused


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


class ClusterExecutor:
    """Evaluations on a Dask distributed cluster whose scheduler is at ``address`` (e.g.
    ``tcp://10.0.0.5:8786``; its workers need this project installed). ``submit`` returns a
    ``concurrent.futures.Future`` fed by the cluster's, so a search waits on it as on a local one.
    An evaluation is never run twice by the scheduler's retry (``retries=0``): a worker lost
    mid-evaluation is an error, not a silently repeated simulation."""

    in_process = False

    def __init__(self, address: str, timeout: float = CLUSTER_CONNECT_TIMEOUT):
        try:
            from distributed import Client
        except ImportError as exc:
            raise ParameterError("cluster: Dask distributed is not installed (pip install -e '.[cluster]')") from exc
        try:
            self._client = Client(address, timeout=timeout, set_as_default=False)
        except (OSError, TimeoutError) as exc:
            raise ParameterError(f"cluster={address!r}: no Dask scheduler answered within {timeout:g} s ({exc})") from exc
        self.address = address
        self.workers = len(self._client.scheduler_info()["workers"])

    def submit(self, fn, *args, **kwargs) -> Future:
        local = _ClusterFuture(self._client.submit(fn, *args, pure=False, retries=0, **kwargs))
        local.remote.add_done_callback(local.hand_over)
        return local

    def map(self, fn, *iterables):
        return [f.result() for f in [self.submit(fn, *args) for args in zip(*iterables)]]

    def shutdown(self, wait: bool = True, cancel_futures: bool = False) -> None:
        self._client.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc) -> None:
        self.shutdown()


class _ClusterFuture(Future):
    """A local future that a cluster future's outcome is handed to; cancelling it cancels that."""

    def __init__(self, remote):
        super().__init__()
        self.remote = remote

    def cancel(self) -> bool:
        self.remote.cancel()
        return super().cancel()

    def hand_over(self, remote) -> None:
        if self.cancelled():
            return
        if remote.status == "finished":
            self.set_result(remote.result())
        else:
            self.set_exception(remote.exception() if remote.status == "error" else RuntimeError("cancelled on the cluster"))


def default_workers() -> int:
    return os.cpu_count() or 1


def check_workers(workers: int) -> int:
    if not isinstance(workers, int) or isinstance(workers, bool) or not 1 <= workers <= 256:
        raise ParameterError(f"workers={workers!r}: must be a whole number in [1, 256]")
    return workers


def executor_for(workers: int | None, cluster: str | None = None):
    """The executor of the ``--workers`` and ``--cluster`` options: the Dask cluster at ``cluster``
    if given, else serial for 1 worker, else a local pool (None: one per CPU)."""
    if cluster:
        return ClusterExecutor(cluster)
    if workers is not None and check_workers(workers) == 1:
        return SerialExecutor()
    return LocalPool(workers)
