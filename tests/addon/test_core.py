"""The add-on's bpy-free core without Blender: the vendored wheels go after the interpreter's
own packages, panel values reach the schema as the CLI's would, a curve's points become a path
in the rig's frame, and a jump plan is cancelled within a second with nothing written."""
import sys
import time

import numpy as np
import pytest

from blender_addon.core import values, vendor
from blender_addon.core.jobs import PlanningJob, cancelled_error, stored_jump_plan
from blender_addon.core.simcore import SIM_CORE
from sim_core.skills import behaviour_class

UNPLANNED = {"target_x": 1.17, "target_y": 0.3, "plan_trials": 40}     # a jump no table has a plan near


def test_vendored_wheels_are_appended_after_the_interpreters_own(tmp_path, monkeypatch):
    monkeypatch.setattr(sys, "path", list(sys.path))
    first = list(sys.path)
    assert vendor.add_vendored(tmp_path) and sys.path == first + [str(tmp_path)]
    assert not vendor.add_vendored(tmp_path) and not vendor.add_vendored(tmp_path / "missing")
    import numpy
    assert not numpy.__file__.startswith(str(tmp_path))


def test_the_checkout_add_on_uses_the_repositorys_sim_core():
    assert SIM_CORE == "sim_core"


def test_panel_values_reach_the_schema_as_the_cli_gives_them():
    schema = behaviour_class("dive").schema
    assert values.knob_value(schema.by_name["group"], "reverse") == "reverse"
    assert schema.validate({"group": "reverse"})["group"] == 3.0
    assert values.knob_value(schema.by_name["low_level"], True) == 1.0
    assert values.as_typed(np.float32(0.2)) == 0.2


def test_a_curve_becomes_a_path_in_the_rigs_frame():
    rig = np.eye(4)
    rig[:3, 3] = (2.0, 1.0, 0.0)                     # the rig stands at (2, 1) in the Blender scene
    world = np.array([[2.0, 1.0, 0.0], [2.0, -4.0, 0.0], [7.0, -4.0, 0.0]])
    # the character faces -Y in Blender, +X in the simulation; Blender +X is the sim's left (+Y)
    assert values.path_in_rig_frame(world, rig) == [[0.0, 0.0], [5.0, 0.0], [5.0, 5.0]]


@pytest.fixture
def plan_store(tmp_path, monkeypatch):
    """The user plan store in a temporary folder (the planning room keeps plans there), and the
    shipped plan tables as they are now."""
    from sim_core.character.spec import RIGS_DIR
    monkeypatch.setenv("SIM_ATHLETICS_PLANS", str(tmp_path / "plans"))
    tables = {p: p.read_bytes() for p in (RIGS_DIR / "tuned").glob("jump_targets_*.json")}
    yield tmp_path / "plans"
    assert {p: p.read_bytes() for p in (RIGS_DIR / "tuned").glob("jump_targets_*.json")} == tables


def test_a_cancelled_plan_ends_within_a_second_and_writes_nothing(plan_store):
    params = behaviour_class("jump_to_target").schema.validate(UNPLANNED)
    assert stored_jump_plan("man", params, "human") is None
    job = PlanningJob("man", params, "human").start()
    time.sleep(1.5)                                   # well into the planning
    assert not job.done()
    job.cancel()
    start = time.monotonic()
    assert job.wait(timeout=10)
    print(f"\nplanning cancelled after {job.finished_at - start:.3f} s")
    assert job.finished_at - start < 1.0
    assert isinstance(job.error, cancelled_error()) and job.result is None
    with pytest.raises(RuntimeError, match="never stored"):
        job.store()
    assert stored_jump_plan("man", params, "human") is None
    assert not plan_store.exists() or not any(plan_store.iterdir())


def test_a_baked_landing_runs_its_planned_foot_placement():
    """Simulate & Bake's job plans a landing as ``simulate land`` does: the woman from 0.515 m at
    +2.11 m/s falls on her table's placement and lands balanced on the plan's."""
    from blender_addon.core.jobs import SimulationJob, plan_note
    from sim_core.simulate import RunRequest, StartState
    job = SimulationJob(RunRequest("land", "woman", start=StartState(height=0.515, velocity=(2.11, 0.0, 0.0)))).start()
    assert job.wait(120) and job.error is None
    assert job.plan["found"] and job.plan["trials"] > 1 and job.trajectory.meta["outcome"] == "success"
    assert job.trajectory.meta["params"]["foot_delta"] == job.plan["foot_delta"]
    assert "ends balanced" in plan_note(job.plan)
