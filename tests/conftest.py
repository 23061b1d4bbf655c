"""Shared fixtures. The checkout's root is on sys.path by pytest's ``pythonpath`` option
(pyproject.toml), so the tests import this checkout's sim_core, blender_addon, tools and build."""
import pytest


@pytest.fixture(autouse=True)
def empty_plan_store(tmp_path_factory, monkeypatch):
    """Every test sees an empty user plan store of its own (not the developer's
    ~/.cache/sim_athletics/plans): only the shipped tables' plans, unless the test plans."""
    monkeypatch.setenv("SIM_ATHLETICS_PLANS", str(tmp_path_factory.mktemp("plans")))
