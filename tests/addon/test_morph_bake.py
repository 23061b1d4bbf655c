"""A morph baked in Blender (docs/bodies.md, "The morph"): on the man's rig, every bone follows its
body (head and orientation) while the body turns into the woman's, and each bone is scaled by the
cube root of its segment's mass ratio, so the skin shrinks with the body."""
import math

import numpy as np
import pytest

bpy = pytest.importorskip("bpy")

from blender_addon import bake, rig  # noqa: E402
from blender_addon.core import bake_math as bm  # noqa: E402
from sim_core.simulate import RunRequest, run  # noqa: E402

from .conftest import man_in_an_empty_scene  # noqa: E402

FPS = 24


@pytest.fixture(scope="module")
def morph_baked(addon):
    """2 s of running at 3 m/s, the man turning into the woman from 0.5 s to 1.5 s, baked."""
    context, arm = man_in_an_empty_scene(FPS)
    trajectory = run(RunRequest("running", "man", params={"speed": 3.0, "morph_to": "woman", "morph_start": 0.5,
                                                          "morph_time": 1.0}, duration=2.0))
    bake.bake_trajectory(arm, trajectory, FPS)
    skin = next(o for o in context.scene.objects if o.type == "MESH")
    return context, arm, skin, trajectory


def _skin_volume(context, skin) -> float:
    mesh = skin.evaluated_get(context.evaluated_depsgraph_get()).to_mesh()
    try:
        co = np.empty(3 * len(mesh.vertices))
        mesh.vertices.foreach_get("co", co)
        co = co.reshape(-1, 3)
        mesh.calc_loop_triangles()
        tri = np.empty(3 * len(mesh.loop_triangles), dtype=np.int64)
        mesh.loop_triangles.foreach_get("vertices", tri)
        a, b, c = (co[tri.reshape(-1, 3)[:, k]] for k in range(3))
        return abs(float(np.sum(np.einsum("ij,ij->i", a, np.cross(b, c)))) / 6.0)
    finally:
        skin.evaluated_get(context.evaluated_depsgraph_get()).to_mesh_clear()


def test_a_morph_bakes_with_every_bone_on_its_body_and_the_skin_shrinking(morph_baked):
    context, arm, skin, trajectory = morph_baked
    assert not trajectory.meta["metrics"]["fell"]
    names = trajectory.body_names
    rest = rig.rest_matrices(arm, names)
    frames = [1, 13, 25, 37, 49]                          # 0, 0.5, 1.0, 1.5, 2.0 s
    truth_pos, truth_quat = bm.resample(trajectory.arrays["time"], trajectory.arrays["body_pos"],
                                        trajectory.arrays["body_quat"], (np.array(frames) - 1.0) / FPS)
    worst_mm, worst_deg, volumes, before = 0.0, 0.0, [], None
    for k, frame in enumerate(frames):
        context.scene.frame_set(frame)
        if frame == 13:                                  # the morph starts at 0.5 s: no bone scaled yet
            before = [arm.pose.bones[n].matrix.to_scale()[0] for n in names]
        pose = np.array([np.array(arm.pose.bones[n].matrix) for n in names])
        pos, rot = bm.body_pose_from_bone(pose, rest)
        worst_mm = max(worst_mm, 1000 * float(np.max(np.linalg.norm(pos - truth_pos[k], axis=1))))
        worst_deg = max(worst_deg, math.degrees(float(np.max(bm.quat_angle(bm.matrix_to_quat(rot), truth_quat[k])))))
        volumes.append(_skin_volume(context, skin))
    _, start_mass, end_mass = bake.morph_masses(trajectory, names)
    scales = np.array([arm.pose.bones[n].matrix.to_scale()[0] for n in names])     # at the last frame
    mass_ratio = float(end_mass.sum() / start_mass.sum())
    print(f"\nmorph bake: head {worst_mm:.4f} mm, orientation {worst_deg:.5f} deg; skin volume "
          f"{volumes[0] * 1000:.1f} -> {volumes[-1] * 1000:.1f} l (x {volumes[-1] / volumes[0]:.3f}; mass x {mass_ratio:.3f})")
    assert worst_mm < 1.0 and worst_deg < 0.1
    assert np.allclose(scales, np.cbrt(end_mass / start_mass), rtol=1e-4)
    assert before == pytest.approx([1.0] * len(names), abs=1e-4)         # float32 F-curves
    assert volumes[-1] / volumes[0] == pytest.approx(mass_ratio, rel=0.1)      # the skin follows the mass
