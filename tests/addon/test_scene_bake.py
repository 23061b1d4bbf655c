"""A scene bakes each actor onto its own armature in one .blend (batch.py --scene), placed where
the scene put it; a bad scene file writes nothing."""
import json

import numpy as np
import pytest

bpy = pytest.importorskip("bpy")

from blender_addon import batch  # noqa: E402
from blender_addon.core.axes import SIM_TO_BLENDER  # noqa: E402
from sim_core.simulate import run_scene  # noqa: E402
from sim_core.scene import scene_from_dict  # noqa: E402

SCENE = {"duration": 1.5, "actors": [
    {"name": "left", "character": "man", "behaviour": "running", "params": {"speed": 3}, "position": [0, 0.75]},
    {"name": "right", "character": "woman", "behaviour": "balance", "position": [0.5, -0.75], "heading": 30}]}


def test_a_scene_bakes_two_armatures_into_one_blend(addon, tmp_path):
    scene_file = tmp_path / "two.json"
    scene_file.write_text(json.dumps(SCENE))
    out = tmp_path / "two.blend"
    assert batch.run(["--scene", str(scene_file), "--fps", "25", "--out", str(out)]) == 0
    assert out.exists()
    bpy.ops.wm.open_mainfile(filepath=str(out))
    arms = {o.name: o for o in bpy.data.objects if o.type == "ARMATURE"}
    assert set(arms) == {"left", "right"}
    assert {o.name for o in bpy.data.objects if o.type == "MESH"} == {"left_skin", "right_skin"}
    trajectory = run_scene(scene_from_dict(SCENE))        # the same run (deterministic)
    scene = bpy.context.scene
    assert scene.frame_end == 38                         # 1.5 s at 25 fps from frame 1
    for name, arm in arms.items():
        assert arm.animation_data.action is not None
        view = trajectory.actor(name)
        pelvis = view.body_index("PELVIS")
        for frame in (1, 20, scene.frame_end):
            k = int(np.argmin(np.abs(view.time - (frame - 1) / 25)))      # the sample at this frame's time
            assert view.time[k] == pytest.approx((frame - 1) / 25)
            scene.frame_set(frame)
            head = np.array(arm.matrix_world @ arm.pose.bones["PELVIS"].head)
            sim = SIM_TO_BLENDER @ view.body_pos[k, pelvis]
            assert np.linalg.norm(head - sim) < 0.01, (name, frame, head, sim)
    left = trajectory.actor("left")
    assert left.body_pos[-1, 0, 0] - left.body_pos[0, 0, 0] > 1.0       # the runner ran off


def test_a_bad_scene_file_bakes_nothing(addon, tmp_path, capsys):
    bad = dict(SCENE, actors=[dict(SCENE["actors"][0]), dict(SCENE["actors"][1], position=[0.2, 0.6])])
    scene_file = tmp_path / "bad.json"
    scene_file.write_text(json.dumps(bad))
    out = tmp_path / "bad.blend"
    assert batch.run(["--scene", str(scene_file), "--out", str(out)]) == 2
    assert not out.exists()
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "actors 'left' and 'right' start" in err[0]


def test_a_cyclist_scene_bakes_the_bicycle_with_its_rider(addon, tmp_path):
    """A rider on the bicycle beside a runner: both armatures and the bicycle's five bodies as
    objects, parented to the rider's armature."""
    scene_file = tmp_path / "cyclist.json"
    scene_file.write_text(json.dumps({"duration": 0.5, "actors": [
        {"name": "cyclist", "character": "man", "behaviour": "bicycle", "params": {"speed": 4}},
        {"name": "runner", "character": "man", "behaviour": "running", "params": {"speed": 3.5}, "position": [0, 1.5]}]}))
    out = tmp_path / "cyclist.blend"
    assert batch.run(["--scene", str(scene_file), "--fps", "25", "--out", str(out)]) == 0
    bpy.ops.wm.open_mainfile(filepath=str(out))
    assert {o.name for o in bpy.data.objects if o.type == "ARMATURE"} == {"cyclist", "runner"}
    for part in ("frame", "fork", "front_wheel", "rear_wheel", "crank"):
        obj = bpy.data.objects[f"SimAthletics bicycle_{part}"]
        assert obj.parent.name == "cyclist" and obj.animation_data.action is not None
