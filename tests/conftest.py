import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))


import pytest  # noqa: E402


@pytest.fixture(autouse=True)
def empty_plan_store(tmp_path_factory, monkeypatch):
    """Every test sees an empty user plan store of its own (not the developer's
    ~/.cache/sim_athletics/plans): only the shipped tables' plans, unless the test plans."""
    monkeypatch.setenv("SIM_ATHLETICS_PLANS", str(tmp_path_factory.mktemp("plans")))
