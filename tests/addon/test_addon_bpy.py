"""The add-on in Blender (the ``bpy`` module): import, panel properties, bake accuracy, skin
deformation, the user's data kept, and bad input refused with nothing written."""
import json
import math

import numpy as np
import pytest

bpy = pytest.importorskip("bpy")

from blender_addon import compat, props, rig  # noqa: E402
from blender_addon.core import bake_math as bm  # noqa: E402
from blender_addon.core.axes import SIM_TO_BLENDER  # noqa: E402
from sim_core.simulate import RunRequest, run  # noqa: E402

from .conftest import man_in_an_empty_scene  # noqa: E402

from .panel_layout import draw  # noqa: E402

FPS = 24                    # Blender's default: frames fall between the simulation's samples
KNEE_BEND = dict(pelvis_height=0.52, move_start=0.3, move_time=1.2, hold_time=0.5)


def _knee_bend_params() -> str:
    return " ".join(f"{k}={v}" for k, v in KNEE_BEND.items())


@pytest.fixture(scope="module")
def baked(addon):
    """The man, a user action on him, then 3 s of balance with a knee bend baked by the operator."""
    context, arm = man_in_an_empty_scene(FPS)
    arm.pose.bones["HEAD"].rotation_quaternion = (0.9, 0.1, 0.0, 0.0)
    arm.pose.bones["HEAD"].keyframe_insert("rotation_quaternion", frame=1)
    user_action = arm.animation_data.action
    user_action.name = "my walk"
    result = bpy.ops.sim_athletics.simulate_bake(behaviour="balance", params=_knee_bend_params(),
                                                 duration=3.0, start_frame=1)
    assert result == {"FINISHED"}
    trajectory = run(RunRequest("balance", "man", params=KNEE_BEND, duration=3.0))
    return context, arm, arm.animation_data.action, trajectory


def _truth_at(trajectory, frames):
    """Trajectory poses at scene frames (interpolated between samples like the bake)."""
    t = (np.asarray(frames, float) - 1.0) / FPS
    return bm.resample(trajectory.arrays["time"], trajectory.arrays["body_pos"], trajectory.arrays["body_quat"], t)


def test_add_character_imports_armature_skin_and_modifier_facing_minus_y(empty_scene):
    assert bpy.ops.sim_athletics.add_character(character="woman") == {"FINISHED"}
    arm = empty_scene.view_layer.objects.active
    assert arm.type == "ARMATURE" and arm[rig.CHARACTER_KEY] == "woman"
    assert len(arm.data.bones) == 22
    skins = [o for o in empty_scene.scene.objects if o.type == "MESH"]
    assert len(skins) == 1 and skins[0].parent == arm
    mods = [m for m in skins[0].modifiers if m.type == "ARMATURE"]
    assert len(mods) == 1 and mods[0].object == arm
    assert len(skins[0].vertex_groups) == 22
    bones = arm.data.bones
    # facing -Y: the toes are in front (more negative Y) of the ankles; left is +X
    assert bones["TOEL"].head_local.y < bones["FOOTL"].head_local.y - 0.05
    assert bones["ULEGL"].head_local.x > 0 > bones["ULEGR"].head_local.x
    assert bpy.data.objects.get("Icosphere") is None          # no importer helper left behind


def _check_generated(group, schema):
    for p in schema.parameters:
        prop = group.properties[p.name]
        assert p.help[:20].lower() in prop.description.lower()
        if p.kind == "choice":                     # a drop-down of the option names
            assert prop.type == "ENUM" and [i.identifier for i in prop.enum_items] == list(p.options)
            assert prop.default == p.default_option
            continue
        if p.kind == "points":                     # a curve object
            assert prop.type == "POINTER" and prop.fixed_type.identifier == "Object"
            continue
        yield p, prop


def test_panel_properties_are_generated_from_the_schema(addon):
    from sim_core.skills import available_behaviours, behaviour_class
    from sim_core.request import REQUEST_SCHEMA
    settings_type = bpy.types.Scene.bl_rna.properties["sim_athletics"].fixed_type
    list(_check_generated(settings_type.properties["request"].fixed_type, REQUEST_SCHEMA))
    for name in available_behaviours():
        group = settings_type.properties[props.group_attr(name)].fixed_type
        for p, prop in _check_generated(group, behaviour_class(name).schema):
            if p.unit == "bool":
                assert prop.type == "BOOLEAN" and prop.default == bool(p.default)
                continue
            assert prop.type == ("INT" if p.unit == "count" else "FLOAT")
            assert prop.default == pytest.approx(p.default)
            assert props.as_typed(prop.hard_min) <= p.minimum and props.as_typed(prop.hard_max) >= p.maximum
            if p.unit == "rad":
                assert prop.subtype == "ANGLE"
            if p.unit == "m":
                assert prop.subtype == "DISTANCE"


def test_bake_matches_every_body_within_1mm_and_0_1_degree(baked):
    context, arm, action, trajectory = baked
    names = trajectory.body_names
    rest = rig.rest_matrices(arm, names)
    frames = list(range(1, 3 * FPS + 2, 10))
    truth_pos, truth_quat = _truth_at(trajectory, frames)
    worst_mm, worst_deg = 0.0, 0.0
    for k, frame in enumerate(frames):
        context.scene.frame_set(frame)
        pose = np.array([np.array(arm.pose.bones[n].matrix) for n in names])
        heads = np.array([np.array(arm.pose.bones[n].head) for n in names])
        assert np.allclose(heads, pose[:, :3, 3], atol=1e-6)
        pos, rot = bm.body_pose_from_bone(pose, rest)
        worst_mm = max(worst_mm, 1000 * float(np.max(np.linalg.norm(pos - truth_pos[k], axis=1))))
        worst_deg = max(worst_deg, math.degrees(float(np.max(bm.quat_angle(bm.matrix_to_quat(rot), truth_quat[k])))))
    print(f"\nbake vs trajectory over {len(frames)} frames x {len(names)} bones: "
          f"head {worst_mm:.4f} mm, orientation {worst_deg:.5f} deg")
    assert worst_mm < 1.0 and worst_deg < 0.1
    # and it is a knee bend: the pelvis went down by more than 0.3 m
    assert trajectory.meta["metrics"]["min_pelvis_height"] < 0.6


def test_action_is_new_with_a_key_on_every_frame_and_the_user_action_stashed(baked):
    context, arm, action, trajectory = baked
    assert action.name.startswith("balance pelvis_height=0.52")
    curves = compat.action_fcurves(action)
    assert len(curves) == 3 + 4 * 22
    for fc in curves:
        co = np.empty(2 * len(fc.keyframe_points), dtype=np.float32)
        fc.keyframe_points.foreach_get("co", co)
        assert np.array_equal(co[0::2], np.arange(1, 3 * FPS + 2, dtype=np.float32))
    info = json.loads(action["sim_athletics"])
    assert info["outcome"] == trajectory.meta["outcome"]
    assert info["params"] == trajectory.meta["params"]
    assert json.loads(arm[rig.RESULT_KEY])["action"] == action.name
    stash = [t for t in arm.animation_data.nla_tracks if t.name == compat.STASH_TRACK]
    assert [s.action.name for t in stash for s in t.strips] == ["my walk"]
    assert bpy.data.actions["my walk"].users >= 1


def test_a_fully_weighted_shin_vertex_moves_rigidly_with_the_shin(baked):
    context, arm, action, trajectory = baked
    skin = next(o for o in context.scene.objects if o.type == "MESH" and o.parent == arm)
    group = skin.vertex_groups["LLEGR"].index
    rigid = [v.index for v in skin.data.vertices
             if len(v.groups) == 1 and v.groups[0].group == group and v.groups[0].weight > 0.9999]
    assert len(rigid) > 50
    picked = rigid[:: max(1, len(rigid) // 20)]
    rest = np.array([np.array(skin.matrix_world @ skin.data.vertices[i].co) for i in picked])
    to_armature = np.array(arm.matrix_world.inverted())
    rest = rest @ to_armature[:3, :3].T + to_armature[:3, 3]
    body = trajectory.body_index("LLEGR")
    joint = np.array(next(b for b in trajectory_spec(trajectory).bodies if b["name"] == "LLEGR")["joint"]["pos"])
    local = rest @ SIM_TO_BLENDER - joint                  # sim frame, relative to the knee
    worst = 0.0
    for frame in range(1, 3 * FPS + 2, 10):
        context.scene.frame_set(frame)
        depsgraph = context.evaluated_depsgraph_get()
        evaluated = skin.evaluated_get(depsgraph)
        mesh = evaluated.to_mesh()
        co = np.empty(3 * len(mesh.vertices), dtype=np.float32)
        mesh.vertices.foreach_get("co", co)
        evaluated.to_mesh_clear()
        world = co.reshape(-1, 3)[picked] @ np.array(skin.matrix_world)[:3, :3].T + np.array(skin.matrix_world)[:3, 3]
        actual = world @ to_armature[:3, :3].T + to_armature[:3, 3]
        pos, quat = _truth_at(trajectory, [frame])
        expected_sim = local @ bm.quat_to_matrix(quat[0, body]).T + pos[0, body]
        expected = expected_sim @ SIM_TO_BLENDER.T
        worst = max(worst, float(np.max(np.linalg.norm(actual - expected, axis=1))))
    print(f"\nshin vertices vs the simulated shin: {1000 * worst:.4f} mm")
    assert worst < 1e-3


def behaviour_defaults(name):
    from sim_core.skills import behaviour_class
    return behaviour_class(name).schema.defaults()


def trajectory_spec(trajectory):
    from sim_core.character.spec import load_character
    return load_character(trajectory.meta["character"])


def _no_new_actions(before):
    return set(bpy.data.actions.keys()) == before


def test_no_character_in_the_scene_is_refused(empty_scene):
    before = set(bpy.data.actions.keys())
    with pytest.raises(RuntimeError, match="no Sim Athletics character in the scene"):
        bpy.ops.sim_athletics.simulate_bake(behaviour="balance", duration=1.0)
    assert _no_new_actions(before)


def test_an_armature_that_is_not_a_sim_athletics_rig_is_refused_and_kept(empty_scene):
    data = bpy.data.armatures.new("plain")
    obj = bpy.data.objects.new("plain", data)
    empty_scene.scene.collection.objects.link(obj)
    empty_scene.view_layer.objects.active = obj
    obj.keyframe_insert("location", frame=1)
    own = obj.animation_data.action
    before = set(bpy.data.actions.keys())
    with pytest.raises(RuntimeError, match="'plain' is not a Sim Athletics rig"):
        bpy.ops.sim_athletics.simulate_bake(behaviour="balance", duration=1.0)
    assert _no_new_actions(before)
    assert obj.animation_data.action == own and len(obj.animation_data.nla_tracks) == 0


def test_a_parameter_out_of_range_is_refused_naming_the_range(empty_scene):
    bpy.ops.sim_athletics.add_character(character="man")
    arm = empty_scene.view_layer.objects.active
    before = set(bpy.data.actions.keys())
    with pytest.raises(RuntimeError, match=r"pelvis_height=5 m is out of range.*\[0\.2, 1\.2\] m"):
        bpy.ops.sim_athletics.simulate_bake(behaviour="balance", params="pelvis_height=5", duration=1.0)
    # a panel value between the documented special value (0) and the minimum: same refusal
    empty_scene.scene.sim_athletics.params_balance.pelvis_height = 0.1
    with pytest.raises(RuntimeError, match="pelvis_height=0.1 m is out of range"):
        bpy.ops.sim_athletics.simulate_bake(behaviour="balance", duration=1.0)
    with pytest.raises(RuntimeError, match="unknown parameter 'pelvis_hieght'"):
        bpy.ops.sim_athletics.simulate_bake(behaviour="balance", params="pelvis_hieght=0.5")
    with pytest.raises(RuntimeError, match="unknown behaviour 'moonwalk'"):
        bpy.ops.sim_athletics.simulate_bake(behaviour="moonwalk")
    assert _no_new_actions(before)
    assert arm.animation_data is None or arm.animation_data.action is None


def test_cancel_writes_nothing(empty_scene):
    from blender_addon import api
    from blender_addon.core.jobs import SimulationJob
    from sim_core.simulate import Cancelled
    bpy.ops.sim_athletics.add_character(character="man")
    before = set(bpy.data.actions.keys())
    with pytest.raises(Cancelled):
        api.simulate_and_bake(empty_scene, behaviour="balance", duration=2.0, cancelled=lambda: True)
    job = SimulationJob(api.make_request("man", "balance", None, 600.0)).start()
    job.cancel()
    assert job.wait(timeout=60)
    assert isinstance(job.error, Cancelled) and job.trajectory is None
    assert _no_new_actions(before)


def test_second_bake_gets_a_unique_name_and_stashes_the_first(empty_scene):
    bpy.ops.sim_athletics.add_character(character="man")
    arm = empty_scene.view_layer.objects.active
    for _ in range(2):
        assert bpy.ops.sim_athletics.simulate_bake(behaviour="balance", duration=0.2) == {"FINISHED"}
    # the panel's defaults come through exactly (not as their single-precision neighbours)
    assert json.loads(arm[rig.RESULT_KEY])["params"] == behaviour_defaults("balance")
    names = sorted(a.name for a in bpy.data.actions)
    assert names == ["balance defaults", "balance defaults.001"]
    stashed = [s.action.name for t in arm.animation_data.nla_tracks for s in t.strips]
    assert stashed == ["balance defaults"] and arm.animation_data.action.name == "balance defaults.001"


def test_panel_draws_the_schema_and_the_last_result(empty_scene):
    from sim_core.skills import behaviour_class
    from blender_addon import api
    from blender_addon.panel import SIMATHLETICS_PT_panel
    context = empty_scene
    api.add_character(context, "man")
    _, trajectory = api.simulate_and_bake(context, behaviour="balance", duration=0.3)
    context.scene.sim_athletics.behaviour = "balance"
    log = draw(SIMATHLETICS_PT_panel, context)
    drawn = [entry[1] for entry in log if entry[0] == "prop"]
    assert [p.name for p in behaviour_class("balance").schema.parameters] == \
        [n for n in drawn if n not in ("character", "behaviour", "start_frame", "fit_scene_range")]
    labels = [entry[1] for entry in log if entry[0] == "label"]
    assert f"Outcome: {trajectory.meta['outcome']}" in labels
    assert any(text.startswith("min pelvis height:") for text in labels)
    assert ("operator", "sim_athletics.simulate_bake") in log


def test_invoke_in_background_runs_to_the_end(empty_scene):
    bpy.ops.sim_athletics.add_character(character="man")
    assert bpy.ops.sim_athletics.simulate_bake("INVOKE_DEFAULT", behaviour="balance", duration=0.2) == {"FINISHED"}
    assert empty_scene.view_layer.objects.active.animation_data.action is not None


def test_a_dive_is_baked_with_its_platform_and_water(empty_scene):
    """The dive through the operator: the baked pelvis falls the platform's height and ends at the
    water; the platform and water appear once, under fixed names, where the simulation had them."""
    from blender_addon import scenery
    context = empty_scene
    context.scene.render.fps, context.scene.render.fps_base = FPS, 1.0
    assert bpy.ops.sim_athletics.add_character(character="man") == {"FINISHED"}
    arm = context.view_layer.objects.active
    params = "group=inward somersaults=1.5 position=pike"
    assert bpy.ops.sim_athletics.simulate_bake(behaviour="dive", params=params, duration=4.5, start_frame=1) == {"FINISHED"}
    platform, water = bpy.data.objects[scenery.PLATFORM_NAME], bpy.data.objects[scenery.WATER_NAME]
    top = max((platform.matrix_world @ v.co).z for v in platform.data.vertices)
    surface = max((water.matrix_world @ v.co).z for v in water.data.vertices)
    assert top == pytest.approx(0.0, abs=1e-6) and surface == pytest.approx(-10.0, abs=0.01)
    action = arm.animation_data.action
    last = int(action.frame_range[1])
    context.scene.frame_set(1)
    start = (arm.matrix_world @ arm.pose.bones["PELVIS"].head).z
    context.scene.frame_set(last)
    end = (arm.matrix_world @ arm.pose.bones["PELVIS"].head).z
    assert start > 0.8 and end < -8.0
    # a second bake reuses the scenery instead of duplicating it
    assert bpy.ops.sim_athletics.simulate_bake(behaviour="dive", params=params, duration=4.5, start_frame=1) == {"FINISHED"}
    assert len([o for o in bpy.data.objects if o.name.startswith("SimAthletics")]) == 2


def test_a_jump_takes_its_target_from_an_empty(empty_scene):
    """The panel's Target object sets the jump's target, measured from the middle of the feet in
    the rig's frame wherever the rig stands; the baked jump lands on it."""
    from mathutils import Vector
    from sim_core.character.spec import load_character
    from sim_core.skills.jump_to_target.behaviour import start_feet_centre
    context = empty_scene
    assert bpy.ops.sim_athletics.add_character(character="man") == {"FINISHED"}
    arm = context.view_layer.objects.active
    arm.location, arm.rotation_euler = (2.0, 1.0, 0.0), (0.0, 0.0, 0.5)
    context.view_layer.update()
    centre = start_feet_centre(load_character("man"))
    spot = bpy.data.objects.new("landing spot", None)
    context.scene.collection.objects.link(spot)
    spot.location = arm.matrix_world @ Vector(SIM_TO_BLENDER @ np.array([centre[0] + 1.0, centre[1], 0.0]))
    context.view_layer.update()
    context.scene.sim_athletics.target_object = spot
    assert bpy.ops.sim_athletics.simulate_bake(behaviour="jump_to_target", params="plan_trials=0",
                                               duration=3.5) == {"FINISHED"}
    result = json.loads(arm[rig.RESULT_KEY])
    assert result["params"]["target_x"] == pytest.approx(1.0, abs=1e-9)
    assert result["params"]["target_y"] == pytest.approx(0.0, abs=1e-9)
    assert result["outcome"] == "success" and result["metrics"]["landing_error"] <= 0.05


def test_a_jump_down_is_baked_with_its_boxes_and_the_ground_below(empty_scene):
    """The woman's jump from a box over a second box to the ground, through the operator: the
    box she starts on, the box she clears and the ground 0.5 m below appear under fixed names
    where the simulation had them, and the baked pelvis ends about 0.5 m lower than it started."""
    from blender_addon import scenery
    context = empty_scene
    context.scene.render.fps, context.scene.render.fps_base = FPS, 1.0
    assert bpy.ops.sim_athletics.add_character(character="woman") == {"FINISHED"}
    arm = context.view_layer.objects.active
    params = "target_x=1.4 target_z=-0.5 obstacle_height=0.3 air_time=0.6 plan_trials=0"
    assert bpy.ops.sim_athletics.simulate_bake(behaviour="jump_to_target", params=params, duration=3.85,
                                               start_frame=1) == {"FINISHED"}
    assert json.loads(arm[rig.RESULT_KEY])["outcome"] == "success"
    top = lambda name: max((bpy.data.objects[name].matrix_world @ v.co).z for v in bpy.data.objects[name].data.vertices)
    assert top(scenery.BOX_NAME.format(0)) == pytest.approx(0.0, abs=1e-6)        # stood on
    assert top(scenery.BOX_NAME.format(1)) == pytest.approx(-0.2, abs=1e-6)       # cleared
    assert top(scenery.GROUND_NAME) == pytest.approx(-0.5, abs=1e-6)
    action = arm.animation_data.action
    context.scene.frame_set(1)
    start = (arm.matrix_world @ arm.pose.bones["PELVIS"].head).z
    context.scene.frame_set(int(action.frame_range[1]))
    end = (arm.matrix_world @ arm.pose.bones["PELVIS"].head).z
    assert end - start == pytest.approx(-0.5, abs=0.1)


def test_a_somersault_is_baked_with_the_panels_strength(empty_scene):
    """The standing back somersault through the operator, at the strength the panel's Strength
    sets: the baked trunk turns upside down in the air and the rig ends upright; the run's
    strength is the one asked for."""
    from sim_core.skills.somersault.behaviour import calibrated
    context = empty_scene
    context.scene.render.fps, context.scene.render.fps_base = FPS, 1.0
    strength = "human" if calibrated("man", "backward", "human") else "unlimited"
    context.scene.sim_athletics.request.strength = strength
    context.scene.sim_athletics.params_somersault.direction = "backward"      # the drop-down
    assert bpy.ops.sim_athletics.add_character(character="man") == {"FINISHED"}
    arm = context.view_layer.objects.active
    assert bpy.ops.sim_athletics.simulate_bake(behaviour="somersault", start_frame=1) == {"FINISHED"}
    result = json.loads(arm[rig.RESULT_KEY])
    assert result["strength"] == strength and result["outcome"] == "success"
    ups = []
    for frame in range(1, int(arm.animation_data.action.frame_range[1]) + 1):
        context.scene.frame_set(frame)
        pelvis = arm.matrix_world @ arm.pose.bones["PELVIS"].head
        head = arm.matrix_world @ arm.pose.bones["HEAD"].head
        ups.append((head - pelvis).normalized().z)          # the trunk's axis: +1 upright, -1 upside down
    assert min(ups) < -0.9 and ups[-1] > 0.9


def test_a_back_handspring_is_baked_with_its_hands_on_the_floor(empty_scene):
    """The back handspring through the operator: the baked trunk turns upside down, the fingers come
    down to the floor while it is inverted, and the rig ends upright behind where it started
    (backward: against the way the feet point), as far as the simulation's centre of mass
    travelled (the pelvis follows it to within 15 cm; human strength travels about 1.2 m,
    unlimited more than 2 m)."""
    from sim_core.skills.handspring.behaviour import calibrated
    context = empty_scene
    context.scene.render.fps, context.scene.render.fps_base = FPS, 1.0
    strength = "human" if calibrated("man", "human") else "unlimited"
    if not calibrated("man", strength):
        pytest.xfail("no calibrated back handspring")
    context.scene.sim_athletics.request.strength = strength
    assert bpy.ops.sim_athletics.add_character(character="man") == {"FINISHED"}
    arm = context.view_layer.objects.active
    assert bpy.ops.sim_athletics.simulate_bake(behaviour="handspring", start_frame=1) == {"FINISHED"}
    result = json.loads(arm[rig.RESULT_KEY])
    assert result["strength"] == strength and result["outcome"] == "success"
    ups, hands_low_inverted = [], False
    for frame in range(1, int(arm.animation_data.action.frame_range[1]) + 1):
        context.scene.frame_set(frame)
        pelvis = arm.matrix_world @ arm.pose.bones["PELVIS"].head
        head = arm.matrix_world @ arm.pose.bones["HEAD"].head
        fingers = arm.matrix_world @ arm.pose.bones["HANDR"].tail
        ups.append((head - pelvis).normalized().z)
        hands_low_inverted |= ups[-1] < -0.9 and fingers.z < 0.05
        if frame == 1:
            start = pelvis.copy()
            facing = (arm.matrix_world @ arm.pose.bones["TOER"].head - arm.matrix_world @ arm.pose.bones["FOOTR"].head).xy
    assert min(ups) < -0.9 and ups[-1] > 0.9 and hands_low_inverted
    travel = (pelvis - start).xy
    simulated_travel = abs(result["metrics"]["com_travel"])
    assert simulated_travel > 0.8 and abs(travel.length - simulated_travel) < 0.15
    assert travel.normalized().dot(facing.normalized()) < -0.9      # backward


def test_a_landing_is_planned_before_it_is_baked(empty_scene):
    """Simulate & Bake of a landing plans its foot placement first, as ``simulate land`` does
    (sim_core.planning.land): the woman from 0.515 m at +2.11 m/s falls on her table's placement and
    is baked balanced on the plan's, through the operator (the panel's start) and the script API."""
    from blender_addon import api
    context = empty_scene
    assert bpy.ops.sim_athletics.add_character(character="woman") == {"FINISHED"}
    arm = context.view_layer.objects.active
    start = context.scene.sim_athletics.request
    start.start_height, start.start_velocity_x = 0.515, 2.11
    assert bpy.ops.sim_athletics.simulate_bake(behaviour="land", duration=3.0) == {"FINISHED"}
    result = json.loads(arm[rig.RESULT_KEY])
    assert result["outcome"] == "success" and result["params"]["foot_delta"] != 0.0
    _, trajectory = api.simulate_and_bake(context, behaviour="land", request={"start_height": 0.515,
                                                                                "start_velocity_x": 2.11})
    assert trajectory.meta["outcome"] == "success"
    assert trajectory.meta["params"]["foot_delta"] == result["params"]["foot_delta"]


def test_adding_a_body_puts_its_own_defaults_in_the_panel_where_the_schemas_are_not_offered(empty_scene):
    """The child is not offered the leap's 0.3 m or running's 3.5 m/s: adding her sets the panel's
    leap height and running speed to her own defaults (sim_core Behaviour.character_defaults); a
    value the user set stays."""
    from sim_core.request import behaviour_params
    settings = empty_scene.scene.sim_athletics
    props.params_group(settings, "running").speed = 3.0
    assert bpy.ops.sim_athletics.add_character(character="child") == {"FINISHED"}
    assert props.params_group(settings, "leap").height == pytest.approx(behaviour_params("leap", "child")["height"])
    assert props.params_group(settings, "running").speed == pytest.approx(3.0)
