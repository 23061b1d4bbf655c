"""Searches on a Dask distributed cluster (issue 28: evaluations on an existing distributed engine
when given a cluster address). The test starts a local cluster of two worker processes on this
machine, runs the search service and the running search's evaluation on it, and stops it."""
import os
import subprocess
import sys

import pytest

from sim_core.errors import ParameterError
from sim_core.tuning import ClusterExecutor, SerialExecutor, Space, minimize

distributed = pytest.importorskip("distributed")


@pytest.fixture(scope="module")
def cluster():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as local:
        yield local.scheduler_address


def bowl(settings: dict) -> tuple[float, int]:
    """A cheap objective that also tells which process evaluated it."""
    return (settings["a"] - 0.3) ** 2 + (settings["b"] - 0.7) ** 2, os.getpid()


def test_a_search_on_the_cluster_is_the_search_run_here_spread_over_both_workers(cluster):
    space = Space({"a": (0.0, 1.0), "b": (0.0, 1.0)})
    with ClusterExecutor(cluster) as executor:
        assert executor.workers == 2
        remote = minimize(bowl, space, "cma", 24, 3, executor=executor, population=6)
    here = minimize(bowl, space, "cma", 24, 3, executor=SerialExecutor(), population=6)
    assert [e.score for e in remote.evaluations] == [e.score for e in here.evaluations]
    assert [e.settings for e in remote.evaluations] == [e.settings for e in here.evaluations]
    pids = {e.extra for e in remote.evaluations}
    assert len(pids) == 2 and os.getpid() not in pids, pids


def test_the_running_search_scores_a_table_on_the_cluster_as_here(cluster):
    """`calibrate running --evaluate`: one evaluation (two runs from a stand, one per start lean),
    on the cluster and in this machine's single process, prints the same score."""
    def evaluation(*where):
        out = subprocess.run([sys.executable, "-m", "sim_core", "calibrate", "running", "--evaluate", "--speeds", "3.5",
                              "--duration", "4", *where], capture_output=True, text=True, check=True).stdout
        return [line for line in out.splitlines() if "evaluation" in line]
    remote = evaluation("--cluster", cluster)
    assert remote and remote == evaluation("--workers", "1")


def test_an_address_with_no_scheduler_is_refused_in_one_line():
    with pytest.raises(ParameterError) as err:
        ClusterExecutor("tcp://127.0.0.1:9", timeout=1.0)
    assert "tcp://127.0.0.1:9" in str(err.value) and "\n" not in str(err.value)
