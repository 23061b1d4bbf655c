"""The bake's NumPy pipeline, without Blender: rest frames, resampling, basis solving, and the
round trip trajectory -> channels -> forward kinematics (as Blender evaluates it) -> bodies."""
import math

import numpy as np
import pytest

from blender_addon.core import axes, bake_math as bm
from blender_addon.core.rig_frames import rest_frames
from sim_core.character.spec import load_character
from sim_core.simulate import RunRequest, run

RNG = np.random.default_rng(7)


def random_quats(n):
    q = RNG.normal(size=(n, 4))
    return q / np.linalg.norm(q, axis=1, keepdims=True)


@pytest.fixture(scope="module")
def knee_bend():
    """1.5 s of balance moving into a knee bend (enough motion in every joint of the legs)."""
    return run(RunRequest("balance", "man", params=dict(pelvis_height=0.52, move_start=0.1, move_time=1.2),
                          duration=1.5))


def test_axes_sim_forward_is_blender_minus_y_and_a_proper_rotation():
    assert np.allclose(axes.SIM_TO_BLENDER @ [1, 0, 0], [0, -1, 0])   # faces -Y
    assert np.allclose(axes.SIM_TO_BLENDER @ [0, 1, 0], [1, 0, 0])    # left is +X
    assert np.allclose(axes.SIM_TO_BLENDER @ [0, 0, 1], [0, 0, 1])
    for m in (axes.SIM_TO_BLENDER, axes.SIM_TO_GLTF):
        assert np.isclose(np.linalg.det(m), 1.0) and np.allclose(m @ m.T, np.eye(3))
    # glTF: +Y up, the front faces +Z (the format's convention)
    assert np.allclose(axes.SIM_TO_GLTF @ [0, 0, 1], [0, 1, 0])
    assert np.allclose(axes.SIM_TO_GLTF @ [1, 0, 0], [0, 0, 1])


def test_quaternion_matrix_round_trip():
    q = random_quats(500)
    back = bm.matrix_to_quat(bm.quat_to_matrix(q))
    assert np.max(bm.quat_angle(q, back)) < 1e-7
    assert np.all(back[:, 0] >= 0)


def test_slerp_is_the_constant_speed_shortest_arc():
    q0, q1 = random_quats(200), random_quats(200)
    total = bm.quat_angle(q0, q1)
    for u in (0.0, 0.25, 0.5, 1.0):
        q = bm.slerp(q0, q1, np.full(200, u))
        assert np.allclose(bm.quat_angle(q0, q), u * total, atol=1e-7)
    assert np.allclose(bm.quat_angle(bm.slerp(q0, -q1, np.full(200, 0.5)), q0), 0.5 * total, atol=1e-7)


def test_make_continuous_removes_sign_flips():
    q = np.repeat(random_quats(1)[None], 10, axis=0)
    q[3::2] *= -1
    fixed = bm.make_continuous(q)
    assert np.all(np.sum(fixed[1:] * fixed[:-1], axis=-1) > 0)
    assert np.allclose(np.abs(fixed), np.abs(q))


@pytest.mark.parametrize("duration,fps,count", [(3.0, 25, 76), (3.0, 24, 73), (10.0, 60, 601), (0.99, 30, 30)])
def test_frame_times_cover_the_run_inclusive(duration, fps, count):
    frames, times = bm.frame_times(duration, fps, start_frame=10)
    assert len(frames) == count and frames[0] == 10 and times[0] == 0.0
    assert np.allclose(np.diff(frames), 1.0) and times[-1] <= duration + 1e-9


def test_resample_is_exact_on_samples_and_halfway_between():
    t = np.arange(5) * 0.005
    pos = RNG.normal(size=(5, 3, 3))
    quat = random_quats(15).reshape(5, 3, 4)
    p, q = bm.resample(t, pos, quat, t)
    assert np.allclose(p, pos) and np.max(bm.quat_angle(q, quat)) < 1e-7
    p, q = bm.resample(t, pos, quat, t[:-1] + 0.0025)
    assert np.allclose(p, 0.5 * (pos[:-1] + pos[1:]))
    assert np.allclose(bm.quat_angle(quat[:-1], q), 0.5 * bm.quat_angle(quat[:-1], quat[1:]), atol=1e-7)


def test_rest_frames_put_heads_on_joints_and_the_root_at_the_pelvis_com():
    spec = load_character("man")
    frames = rest_frames(spec.bodies)
    assert frames.names == spec.body_names
    sim_heads = axes.blender_to_sim_points(frames.heads)
    assert np.allclose(sim_heads[0], spec.bodies[0]["com"])
    for i, body in enumerate(spec.bodies[1:], start=1):
        assert np.allclose(sim_heads[i], body["joint"]["pos"])
    m = frames.matrices()
    assert np.allclose(m[:, :3, :3] @ np.swapaxes(m[:, :3, :3], 1, 2), np.eye(3), atol=1e-12)
    assert np.allclose(np.linalg.det(m[:, :3, :3]), 1.0)
    lengths = np.linalg.norm(frames.tails - frames.heads, axis=1)
    assert lengths.min() > 0.02
    # the shin bone points down and the foot bone forward (-Y in Blender)
    assert m[frames.names.index("LLEGR"), 2, 1] < -0.9
    assert m[frames.names.index("TOER"), 1, 1] < -0.9


def random_chain() -> tuple[list[int], int, np.ndarray]:
    """A small chain's parents, its bone count and random rest frames."""
    parents = [-1, 0, 1, 1, 0]
    n = len(parents)
    rest = np.tile(np.eye(4), (n, 1, 1))
    rest[:, :3, :3] = bm.quat_to_matrix(random_quats(n))
    rest[:, :3, 3] = RNG.normal(size=(n, 3))
    return parents, n, rest


def test_basis_solves_blenders_pose_evaluation():
    """Random rest frames and random poses of a small chain: pose -> basis -> pose again."""
    parents, n, rest = random_chain()
    ch = bm.BoneChannels(np.arange(6.0), [str(i) for i in range(n)], RNG.normal(size=(6, 3)),
                         random_quats(6 * n).reshape(6, n, 4), 0.0)
    pose = bm.pose_from_channels(ch, rest, parents)
    back = bm.channels(ch.frames, bm.basis_from_pose(pose, rest, parents), ch.names, parents)
    assert np.allclose(back.root_location, ch.root_location)
    assert np.max(bm.quat_angle(back.rotations, ch.rotations)) < 1e-7
    assert back.joint_slip < 1e-12


def test_scaled_bones_solve_blenders_pose_evaluation():
    """A morph's bones carry a uniform scale and a location each: pose -> basis -> pose again."""
    parents, n, rest = random_chain()
    ch = bm.BoneChannels(np.arange(6.0), [str(i) for i in range(n)], RNG.normal(size=(6, 3)),
                         random_quats(6 * n).reshape(6, n, 4), 0.0, RNG.normal(size=(6, n, 3)),
                         RNG.uniform(0.7, 1.0, size=(6, n)))
    ch.locations[:, 0] = ch.root_location
    pose = bm.pose_from_channels(ch, rest, parents)
    back = bm.channels(ch.frames, bm.basis_from_pose(pose, rest, parents, scaled=True), ch.names, parents, scaled=True)
    assert np.allclose(back.root_location, ch.root_location) and np.allclose(back.locations, ch.locations)
    assert np.allclose(back.scales, ch.scales)
    assert np.max(bm.quat_angle(back.rotations, ch.rotations)) < 1e-7


def test_morph_scales_follow_the_logged_fraction():
    """f holds from each logged tick on; a bone's scale is the cube root of its mass ratio."""
    meta = {"edit_fields": ["actuator_gainprm", "morph"], "steps_per_tick": 5, "timestep": 0.001}
    arrays = {"edit_field": np.array([0, 1, 1]), "edit_tick": np.array([0, 2, 4]), "edit_value": np.array([9.0, 0.5, 1.0])}
    f = bm.morph_fraction_at(arrays, meta, np.array([0.0, 0.009, 0.010, 0.015, 0.020, 1.0]))
    assert f.tolist() == [0.0, 0.0, 0.5, 0.5, 1.0, 1.0]
    assert bm.morph_fraction_at(arrays, {"edit_fields": ["actuator_gainprm"]}, np.zeros(1)) is None
    scale = bm.morph_scales(np.array([0.0, 1.0]), np.array([8.0, 2.0]), np.array([1.0, 2.0]))
    assert np.allclose(scale, [[1.0, 1.0], [0.5, 1.0]])


def test_trajectory_round_trip_through_channels(knee_bend):
    """Channels at the 200 Hz samples reproduce every body's pose (what the bake must show)."""
    spec = load_character("man")
    frames = rest_frames(spec.bodies)
    rest = frames.matrices()
    order = [knee_bend.body_index(n) for n in frames.names]     # bones in spec order, bodies in MuJoCo's
    rate = 1.0 / float(np.median(np.diff(knee_bend.arrays["time"])))     # one frame per sample
    ch = bm.bake_channels(knee_bend.arrays, rest, frames.names, frames.parents, fps=rate, start_frame=1)
    n = len(ch.frames)
    assert n == len(knee_bend.arrays["time"])
    # hinge joints: children need no translation channel (the sub-micron slip is the model's
    # offsets as rounded in its MJCF text against the spec's joint positions)
    assert ch.joint_slip < 1e-5
    pose = bm.pose_from_channels(ch, rest, frames.parents)
    pos, rot = bm.body_pose_from_bone(pose, rest)
    truth_pos = knee_bend.arrays["body_pos"][:n, order]
    truth_rot = bm.quat_to_matrix(knee_bend.arrays["body_quat"][:n, order])
    assert np.max(np.linalg.norm(pos - truth_pos, axis=-1)) < 1e-5
    assert np.max(bm.quat_angle(bm.matrix_to_quat(rot), bm.matrix_to_quat(truth_rot))) < 1e-9
    # the knee really bent (this is not a still pose)
    knee = frames.names.index("LLEGR")
    assert np.max(bm.quat_angle(ch.rotations[:, knee], ch.rotations[:1, knee])) > math.radians(30)


def test_resampled_channels_match_the_trajectory_between_samples(knee_bend):
    """At 24 fps the frames fall between samples: bodies then match the interpolated trajectory
    (slerp keeps each bone's head within a fraction of a millimetre of the joint chain)."""
    spec = load_character("man")
    frames = rest_frames(spec.bodies)
    rest = frames.matrices()
    ch = bm.bake_channels(knee_bend.arrays, rest, frames.names, frames.parents, fps=24.0)
    _, at = bm.frame_times(float(knee_bend.arrays["time"][-1]), 24.0)
    order = [knee_bend.body_index(n) for n in frames.names]
    truth_pos, truth_quat = bm.resample(knee_bend.arrays["time"], knee_bend.arrays["body_pos"][:, order],
                                        knee_bend.arrays["body_quat"][:, order], at)
    pos, rot = bm.body_pose_from_bone(bm.pose_from_channels(ch, rest, frames.parents), rest)
    assert np.max(bm.quat_angle(bm.matrix_to_quat(rot), truth_quat)) < 1e-9
    assert np.max(np.linalg.norm(pos[:, 0] - truth_pos[:, 0], axis=-1)) < 1e-12    # root: exact
    assert np.max(np.linalg.norm(pos - truth_pos, axis=-1)) < 1e-3


def test_bake_rejects_bones_without_bodies(knee_bend):
    rest = np.tile(np.eye(4), (2, 1, 1))
    with pytest.raises(ValueError, match="NOSUCH"):
        bm.bake_channels(knee_bend.arrays, rest, ["PELVIS", "NOSUCH"], [-1, 0], fps=24)
