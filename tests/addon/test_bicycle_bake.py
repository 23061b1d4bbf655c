"""The bicycle in a bake (issue 30 part 5): the rider bakes onto his armature and the bicycle's
five bodies bake as their own objects (a mesh from their geoms), keyed every frame, the frame
object where the simulated frame body was, the wheels spinning."""
import numpy as np
import pytest

from blender_addon.core import prop_motion
from blender_addon.core.axes import SIM_TO_BLENDER
from blender_addon.core.bake_math import quat_angle, quat_to_matrix

BICYCLE_BODIES = ["bicycle_frame", "bicycle_fork", "bicycle_front_wheel", "bicycle_rear_wheel", "bicycle_crank"]


@pytest.fixture(scope="module")
def ride():
    from sim_core.simulate import RunRequest, run
    return run(RunRequest("bicycle", "man", params={"speed": 4.0}, duration=2.0))


def test_prop_keys_refuse_a_body_the_trajectory_lacks(ride):
    with pytest.raises(ValueError, match="prop bodies not in the trajectory: bicycle_bell"):
        prop_motion.prop_keys(ride.arrays, ["bicycle_bell"], fps=24)


def test_a_wheel_mesh_is_a_prism_of_the_tyre_radius(ride):
    import mujoco
    from sim_core.world.bicycle import WHEEL_RADIUS
    model = mujoco.MjModel.from_xml_string(ride.meta["model_xml"])
    verts, faces = prop_motion.body_mesh(model, model.body("bicycle_rear_wheel").id)
    radius = np.hypot(verts[:, 0], verts[:, 2])      # the axle is sim Y = Blender -X (model_xml keeps ~6 digits)
    assert radius.max() == pytest.approx(WHEEL_RADIUS, abs=1e-4) and len(faces) == 2 * (prop_motion.PRISM_SIDES + 2)


def test_the_bicycle_bakes_as_objects_following_its_bodies(empty_scene, ride):
    bpy = pytest.importorskip("bpy")
    from blender_addon import api, bake
    context = empty_scene
    assert bpy.ops.sim_athletics.add_character(character="man") == {"FINISHED"}
    arm = context.view_layer.objects.active
    action = api.bake_result(context, arm, ride, start_frame=1)
    assert arm.animation_data.action == action                    # the rider, as any skill
    assert "bicycle_frame" not in {fc.data_path.split('"')[1] for fc in bake.compat.action_fcurves(action)}
    objects = {name: bpy.data.objects[bake.PROP_OBJECT.format(name)] for name in BICYCLE_BODIES}
    fps = bake.scene_fps(context.scene)
    names = list(ride.body_names)
    times = ride.time - ride.time[0]
    worst = worst_turn = 0.0
    wheel_angle = []
    for frame in (1, 13, 25, 37, 43):
        context.scene.frame_set(frame)
        k = int(np.argmin(np.abs(times - (frame - 1) / fps)))
        assert abs(times[k] - (frame - 1) / fps) < 1e-9           # these frames fall on recorded samples
        for name in ("bicycle_frame", "bicycle_fork"):
            seen = np.array(objects[name].matrix_world.translation)
            worst = max(worst, float(np.linalg.norm(seen - SIM_TO_BLENDER @ ride.body_pos[k, names.index(name)])))
            rot = SIM_TO_BLENDER @ quat_to_matrix(ride.body_quat[k, names.index(name)]) @ SIM_TO_BLENDER.T
            worst_turn = max(worst_turn, float(np.abs(np.array(objects[name].matrix_world.to_3x3()) - rot).max()))
        wheel_angle.append(np.array(objects["bicycle_rear_wheel"].matrix_world.to_quaternion()))
    print(f"bicycle frame/fork objects vs bodies: worst {worst * 1000:.4f} mm, rotation entries {worst_turn:.1e}")
    assert worst < 0.01 and worst_turn < 1e-4
    turned = quat_angle(np.array(wheel_angle[0]), np.array(wheel_angle[2]))
    print(f"rear wheel's world rotation changed by {np.degrees(float(turned)):.1f} deg between frames 1 and 25")
    assert float(turned) > 0.5                                     # 1 s at 4 m/s: the wheel turned a lot
    api.bake_result(context, arm, ride, start_frame=1)             # a second bake reuses the objects
    assert len([o for o in bpy.data.objects if o.name.startswith("SimAthletics bicycle")]) == 5
