"""The panel in Blender (the ``bpy`` module): choices as drop-downs, the run request in its own
sub-panel (a drop height, a push and a slope give the CLI's request), tuned settings in a closed
sub-panel, a curve as a running path, and Plan Jump's job cancelled within a second with nothing
written."""
import json
import time
import numpy as np
import pytest

bpy = pytest.importorskip("bpy")

from blender_addon import operators, panel, props, rig  # noqa: E402
from sim_core.skills import behaviour_class
from sim_core.schema import Parameter, Schema  # noqa: E402

from .panel_layout import draw  # noqa: E402


def test_choices_are_drop_downs_of_their_option_names(empty_scene):
    settings = empty_scene.scene.sim_athletics
    settings.behaviour = "dive"
    drawn = {entry[1]: entry[2] for entry in draw(panel.SIMATHLETICS_PT_panel, empty_scene) if entry[0] == "prop"}
    assert drawn["group"] == "ENUM" and drawn["position"] == "ENUM"
    group = settings.params_dive.bl_rna.properties["group"]
    assert [i.identifier for i in group.enum_items] == ["inward", "back", "forward", "reverse"]
    settings.params_dive.group = "reverse"
    settings.params_dive.position = "tuck"
    values = behaviour_class("dive").schema.validate(props.panel_params(settings, "dive"))
    assert (values["group"], values["position"]) == (3.0, 2.0)          # the codes the dive reads
    settings.behaviour = "running"
    drawn = {entry[1]: entry[2] for entry in draw(panel.SIMATHLETICS_PT_panel, empty_scene) if entry[0] == "prop"}
    assert drawn["course"] == "ENUM" and drawn["path"] == "POINTER"
    settings.behaviour = "somersault"
    drawn = {entry[1]: entry[2] for entry in draw(panel.SIMATHLETICS_PT_panel, empty_scene) if entry[0] == "prop"}
    assert drawn["direction"] == "ENUM"
    assert ("operator", "sim_athletics.plan_jump") not in draw(panel.SIMATHLETICS_PT_panel, empty_scene)
    settings.behaviour = "jump_to_target"
    assert ("operator", "sim_athletics.plan_jump") in draw(panel.SIMATHLETICS_PT_panel, empty_scene)


def test_the_run_request_sub_panel_sets_what_the_cli_flags_set(empty_scene):
    """A drop height, a push and a slope from the panel give the CLI's request, bit for bit."""
    from sim_core.cli import build_request, parser
    from sim_core.request import REQUEST_SCHEMA
    log = draw(panel.SIMATHLETICS_PT_request, empty_scene)
    assert [e[1] for e in log if e[0] == "prop"] == [p.name for p in REQUEST_SCHEMA.parameters]
    assert [e[1] for e in log if e[0] == "label"] == [h for h, _ in REQUEST_SCHEMA.groups]
    request = empty_scene.scene.sim_athletics.request
    request.start_height, request.slope, request.slope_axis = 0.2, -4.0, "y+"
    request.push_force, request.push_direction, request.push_start, request.push_duration = 120.0, 90.0, 0.6, 0.2
    request.backpack, request.duration = 3.5, 1.3
    bpy.ops.sim_athletics.add_character(character="man")
    arm = empty_scene.view_layer.objects.active
    s = operators.run_settings(empty_scene, behaviour="balance")
    from blender_addon import api
    from_panel = api.make_request("man", "balance", s["params"], s["duration"], s["strength"], s["request"])
    cli = build_request(parser().parse_args(
        ["simulate", "balance", "--start-height", "0.2", "--slope", "-4", "--slope-axis", "y+",
         "--push", "120@90:0.6:0.2", "--backpack", "3.5", "--duration", "1.3"]))
    assert from_panel == cli
    assert bpy.ops.sim_athletics.simulate_bake(behaviour="balance") == {"FINISHED"}
    info = json.loads(arm.animation_data.action["sim_athletics"])
    assert info["duration"] == pytest.approx(1.3, abs=0.05)


def test_tuned_settings_are_a_closed_sub_panel_generated_from_the_settings_schema(addon, monkeypatch):
    assert panel.SIMATHLETICS_PT_tuned.bl_options == {"DEFAULT_CLOSED"}
    assert panel.SIMATHLETICS_PT_tuned.bl_parent_id == panel.SIMATHLETICS_PT_panel.bl_idname
    tuned = Schema(Parameter("crouch_depth", "m", 0.2, 0.0, 0.5, "how deep the tuned crouch goes"),
                   Parameter("arm_gain", "1", 2.0, 1.0, 5.0, "gain factor of the arm servos"))
    monkeypatch.setattr(behaviour_class("balance"), "settings_schema", tuned, raising=False)
    addon.unregister()
    addon.register()                                   # the groups are generated at registration
    try:
        bpy.ops.wm.read_homefile(use_empty=True)
        context = bpy.context
        settings = context.scene.sim_athletics
        settings.behaviour = "balance"
        assert panel.SIMATHLETICS_PT_tuned.poll(context)
        drawn = [e[1] for e in draw(panel.SIMATHLETICS_PT_tuned, context) if e[0] == "prop"]
        assert drawn == ["crouch_depth", "arm_gain"]
        main = [e[1] for e in draw(panel.SIMATHLETICS_PT_panel, context) if e[0] == "prop"]
        assert "crouch_depth" not in main and "pelvis_height" in main          # animator knobs only
        settings.tuned_balance.arm_gain = 3.0
        assert props.panel_settings(settings, "balance") == {"crouch_depth": 0.2, "arm_gain": 3.0}
        assert props.panel_tuned_overrides(settings, "balance") == {"arm_gain": 3.0}   # what a run takes
        settings.behaviour = "land"                                            # no tuned settings
        assert not panel.SIMATHLETICS_PT_tuned.poll(context)
    finally:
        monkeypatch.undo()
        addon.unregister()
        addon.register()


def poly_curve(context, name, points):
    """A poly curve object through ``points`` (world metres), linked into the scene."""
    data = bpy.data.curves.new(name, type="CURVE")
    spline = data.splines.new("POLY")
    spline.points.add(len(points) - 1)
    for point, co in zip(spline.points, points):
        point.co = (*co, 1.0)
    curve = bpy.data.objects.new(name, data)
    context.scene.collection.objects.link(curve)
    context.view_layer.update()
    return curve


def test_a_curve_object_is_the_running_path(empty_scene):
    context = empty_scene
    bpy.ops.sim_athletics.add_character(character="man")
    arm = context.view_layer.objects.active
    arm.location = (1.0, 2.0, 0.0)
    # 10 m ahead (-Y), then 20 m on, bearing 2 m left (a bend the runner is offered: docs/running.md)
    curve = poly_curve(context, "track", [(1.0, 2.0, 0.0), (1.0, -8.0, 0.0), (3.0, -28.0, 0.0)])
    context.scene.sim_athletics.params_running.path = curve
    s = operators.run_settings(context, behaviour="running")
    params = operators.with_scene_inputs(context, arm, s)
    assert np.allclose(params["path"], [[0.0, 0.0], [10.0, 0.0], [30.0, 2.0]], atol=1e-6)
    assert bpy.ops.sim_athletics.simulate_bake(behaviour="running", duration=0.2) == {"FINISHED"}
    assert json.loads(arm[rig.RESULT_KEY])["params"]["path"] == params["path"]


def test_a_curve_object_is_the_bicycle_path(empty_scene):
    """The bicycle's path comes from a curve as the runner's does (the schema's Points kind), in
    the rider's frame; the bake has the rider and the bicycle."""
    context = empty_scene
    bpy.ops.sim_athletics.add_character(character="man")
    arm = context.view_layer.objects.active
    curve = poly_curve(context, "road", [(0.0, 0.0, 0.0), (0.0, -20.0, 0.0), (10.0, -40.0, 0.0)])  # 20 m ahead (-Y), then a bend left a turn of 15 deg of lean allows
    context.scene.sim_athletics.params_bicycle.path = curve
    s = operators.run_settings(context, behaviour="bicycle")
    params = operators.with_scene_inputs(context, arm, s)
    assert np.allclose(params["path"], [[0.0, 0.0], [20.0, 0.0], [40.0, 10.0]], atol=1e-6)
    assert bpy.ops.sim_athletics.simulate_bake(behaviour="bicycle", duration=0.2) == {"FINISHED"}
    assert json.loads(arm[rig.RESULT_KEY])["params"]["path"] == params["path"]
    assert "SimAthletics bicycle_frame" in bpy.data.objects


def test_plan_jump_cancelled_like_esc_ends_within_a_second_and_writes_nothing(empty_scene, tmp_path, monkeypatch):
    """The planning operator's job (what invoke starts), cancelled as its modal Esc does: the
    worker ends within 1 s, no plan is stored (user store or shipped table), no action is made."""
    from blender_addon.core.jobs import cancelled_error, stored_jump_plan
    from sim_core.character.spec import RIGS_DIR
    monkeypatch.setenv("SIM_ATHLETICS_PLANS", str(tmp_path / "plans"))
    tables = {p: p.read_bytes() for p in (RIGS_DIR / "tuned").glob("jump_targets_*.json")}
    context = empty_scene
    bpy.ops.sim_athletics.add_character(character="man")
    settings = context.scene.sim_athletics
    settings.behaviour = "jump_to_target"
    settings.params_jump_to_target.target_x = 1.17                # no plan stored near this jump
    settings.params_jump_to_target.target_y = 0.3
    settings.params_jump_to_target.plan_trials = 40
    actions = set(bpy.data.actions.keys())
    job = operators.planning_job(context)
    assert job is not None and job.params["target_x"] == 1.17
    job.start()
    time.sleep(1.5)
    assert not job.done()
    job.cancel()                                        # what the modal operator does on Esc
    start = time.monotonic()
    assert job.wait(timeout=10)
    print(f"\nPlan Jump cancelled after {job.finished_at - start:.3f} s")
    assert job.finished_at - start < 1.0
    assert isinstance(job.error, cancelled_error())
    assert stored_jump_plan("man", job.params, job.strength) is None
    assert not (tmp_path / "plans").exists() or not any((tmp_path / "plans").iterdir())
    assert {p: p.read_bytes() for p in (RIGS_DIR / "tuned").glob("jump_targets_*.json")} == tables
    assert set(bpy.data.actions.keys()) == actions


def test_plan_jump_refuses_bad_input_and_skips_a_stored_plan(empty_scene):
    bpy.ops.sim_athletics.add_character(character="man")
    settings = empty_scene.scene.sim_athletics
    settings.behaviour = "jump_to_target"
    settings.params_jump_to_target.plan_trials = 0
    settings.params_jump_to_target.target_x = 1.17
    with pytest.raises(RuntimeError, match="plan_trials=0"):
        bpy.ops.sim_athletics.plan_jump()
    settings.params_jump_to_target.target_x = 1.0                 # the default jump has a stored plan
    assert operators.planning_job(empty_scene) is None
    assert bpy.ops.sim_athletics.plan_jump() == {"FINISHED"}
