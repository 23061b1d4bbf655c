"""Trajectory -> per-frame bone channels, as NumPy arrays, without bpy.

Like the passes of Blender's glTF importer (``compute_vnodes``), the bake is a pipeline of small
named steps, each testable on its own; the bpy layer (:mod:`bake`) only reads the rest matrices
and writes the resulting arrays in bulk:

  1. ``frame_times``: the scene's frames that fall inside the run, and their times.
  2. ``resample``: the 200 Hz body poses at those times (linear for positions, slerp for
     rotations), because a scene's frame rate rarely divides the control rate.
  3. ``bone_pose_matrices``: each body's world pose -> its bone's pose matrix in armature space.
     A body frame is world-parallel in the reference pose, so its world rotation *is* the
     rotation of the body since the rest pose; the bone keeps its own rest orientation on top.
  4. ``basis_from_pose``: armature-space pose matrices -> Blender's ``matrix_basis`` per bone
     (pose relative to the rest pose and to the parent's pose): what the F-curves hold.
  5. ``channels``: root location + quaternion, one quaternion per other bone, with signs made
     continuous so that interpolation between keys never takes the long way round.

Conventions: quaternions are (w, x, y, z); matrices act on column vectors; arrays of matrices
are (..., 4, 4).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .axes import SIM_TO_BLENDER

# ----------------------------------------------------------------------------- quaternions


def quat_to_matrix(q: np.ndarray) -> np.ndarray:
    q = np.asarray(q, dtype=float)
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = np.moveaxis(q, -1, 0)
    out = np.empty(q.shape[:-1] + (3, 3))
    out[..., 0, 0] = 1 - 2 * (y * y + z * z)
    out[..., 0, 1] = 2 * (x * y - w * z)
    out[..., 0, 2] = 2 * (x * z + w * y)
    out[..., 1, 0] = 2 * (x * y + w * z)
    out[..., 1, 1] = 1 - 2 * (x * x + z * z)
    out[..., 1, 2] = 2 * (y * z - w * x)
    out[..., 2, 0] = 2 * (x * z - w * y)
    out[..., 2, 1] = 2 * (y * z + w * x)
    out[..., 2, 2] = 1 - 2 * (x * x + y * y)
    return out


def matrix_to_quat(m: np.ndarray) -> np.ndarray:
    """Rotation matrices (..., 3, 3) -> unit quaternions (w, x, y, z) with w >= 0 (Shepperd's
    method: the largest of the four candidates is computed from the trace, the others from it,
    so no branch divides by a small number)."""
    m = np.asarray(m, dtype=float)
    shape = m.shape[:-2]
    m = m.reshape(-1, 3, 3)
    t = np.stack([m[:, 0, 0] + m[:, 1, 1] + m[:, 2, 2], m[:, 0, 0], m[:, 1, 1], m[:, 2, 2]], axis=1)
    pick = np.argmax(np.stack([t[:, 0], 2 * t[:, 1] - t[:, 0], 2 * t[:, 2] - t[:, 0], 2 * t[:, 3] - t[:, 0]], 1), 1)
    q = np.empty((len(m), 4))
    for case in range(4):
        s = pick == case
        if not s.any():
            continue
        a = m[s]
        if case == 0:
            r = np.sqrt(1.0 + a[:, 0, 0] + a[:, 1, 1] + a[:, 2, 2]) * 2
            q[s] = np.stack([0.25 * r, (a[:, 2, 1] - a[:, 1, 2]) / r, (a[:, 0, 2] - a[:, 2, 0]) / r,
                             (a[:, 1, 0] - a[:, 0, 1]) / r], 1)
        elif case == 1:
            r = np.sqrt(1.0 + a[:, 0, 0] - a[:, 1, 1] - a[:, 2, 2]) * 2
            q[s] = np.stack([(a[:, 2, 1] - a[:, 1, 2]) / r, 0.25 * r, (a[:, 0, 1] + a[:, 1, 0]) / r,
                             (a[:, 0, 2] + a[:, 2, 0]) / r], 1)
        elif case == 2:
            r = np.sqrt(1.0 + a[:, 1, 1] - a[:, 0, 0] - a[:, 2, 2]) * 2
            q[s] = np.stack([(a[:, 0, 2] - a[:, 2, 0]) / r, (a[:, 0, 1] + a[:, 1, 0]) / r, 0.25 * r,
                             (a[:, 1, 2] + a[:, 2, 1]) / r], 1)
        else:
            r = np.sqrt(1.0 + a[:, 2, 2] - a[:, 0, 0] - a[:, 1, 1]) * 2
            q[s] = np.stack([(a[:, 1, 0] - a[:, 0, 1]) / r, (a[:, 0, 2] + a[:, 2, 0]) / r,
                             (a[:, 1, 2] + a[:, 2, 1]) / r, 0.25 * r], 1)
    q *= np.where(q[:, :1] < 0, -1.0, 1.0)
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    return q.reshape(shape + (4,))


def quat_angle(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Angle (rad) of the rotation taking ``a`` to ``b`` (either sign of either quaternion);
    from the relative quaternion with atan2, accurate for tiny angles (arccos is not)."""
    a, b = np.broadcast_arrays(np.asarray(a, float), np.asarray(b, float))
    w = np.sum(a * b, axis=-1)
    vec = (a[..., :1] * b[..., 1:] - b[..., :1] * a[..., 1:]) - np.cross(a[..., 1:], b[..., 1:])
    return 2.0 * np.arctan2(np.linalg.norm(vec, axis=-1), np.abs(w))


def slerp(q0: np.ndarray, q1: np.ndarray, u: np.ndarray) -> np.ndarray:
    """Spherical interpolation (..., 4) with ``u`` broadcast over the leading axes; shortest arc."""
    q0, q1 = np.asarray(q0, float), np.asarray(q1, float)
    u = np.asarray(u, float)[..., None]
    dot = np.sum(q0 * q1, axis=-1, keepdims=True)
    q1 = np.where(dot < 0, -q1, q1)
    dot = np.abs(dot)
    theta = np.arccos(np.clip(dot, -1.0, 1.0))
    sin = np.sin(theta)
    small = sin < 1e-9
    w0 = np.where(small, 1.0 - u, np.sin((1.0 - u) * theta) / np.where(small, 1.0, sin))
    w1 = np.where(small, u, np.sin(u * theta) / np.where(small, 1.0, sin))
    out = w0 * q0 + w1 * q1
    return out / np.linalg.norm(out, axis=-1, keepdims=True)


def make_continuous(q: np.ndarray) -> np.ndarray:
    """Flip signs along axis 0 so that consecutive quaternions are in the same hemisphere (q and
    -q are the same rotation; F-curves interpolate the components, so a sign jump would spin)."""
    q = np.array(q, dtype=float)
    steps = np.where(np.sum(q[1:] * q[:-1], axis=-1) < 0, -1.0, 1.0)
    q[1:] *= np.cumprod(steps, axis=0)[..., None]
    return q


# ----------------------------------------------------------------------------- pipeline

def frame_times(duration: float, fps: float, start_frame: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """(frames, times): one frame per 1/fps from the run's start through its end (inclusive when
    the end falls on a frame, within a microsecond)."""
    if not (fps > 0 and math.isfinite(fps)):
        raise ValueError(f"frame rate {fps!r} must be a positive number")
    n = int(math.floor(duration * fps + 1e-6)) + 1
    k = np.arange(n)
    return start_frame + k.astype(float), k / fps


def resample(times: np.ndarray, positions: np.ndarray, quats: np.ndarray, at: np.ndarray):
    """Body positions (N, B, 3) and quaternions (N, B, 4) sampled at ``times`` -> at ``at`` (M):
    positions linearly, rotations by slerp between the two neighbouring samples. Times past the
    end are clamped to the last sample."""
    times = np.asarray(times, float)
    at = np.clip(np.asarray(at, float), times[0], times[-1])
    i = np.clip(np.searchsorted(times, at, side="right") - 1, 0, len(times) - 2)
    span = times[i + 1] - times[i]
    u = np.clip((at - times[i]) / np.where(span > 0, span, 1.0), 0.0, 1.0)
    exact = np.isclose(at, times[i], rtol=0, atol=1e-9)
    u = np.where(exact, 0.0, u)
    pos = positions[i] + u[:, None, None] * (positions[i + 1] - positions[i])
    rot = slerp(quats[i], quats[i + 1], np.broadcast_to(u[:, None], quats[i].shape[:-1]))
    return pos, rot


def bone_pose_matrices(body_pos: np.ndarray, body_quat: np.ndarray, rest: np.ndarray,
                       scale: np.ndarray | None = None) -> np.ndarray:
    """World body poses in the sim frame (F, B, 3) / (F, B, 4) -> bone pose matrices (F, B, 4, 4)
    in armature space: rotation = body rotation (conjugated into Blender's axes) applied to the
    bone's rest orientation; head = the body frame's origin; ``scale`` (F, B): each bone's uniform
    scale (a morphing body's segments, ``morph_scales``)."""
    rot = SIM_TO_BLENDER @ quat_to_matrix(body_quat) @ SIM_TO_BLENDER.T
    out = np.zeros(body_pos.shape[:2] + (4, 4))
    out[..., :3, :3] = rot @ rest[None, :, :3, :3]
    if scale is not None:
        out[..., :3, :3] *= scale[..., None, None]
    out[..., :3, 3] = body_pos @ SIM_TO_BLENDER.T
    out[..., 3, 3] = 1.0
    return out


def rigid_inverse(m: np.ndarray) -> np.ndarray:
    out = np.zeros_like(m)
    rt = np.swapaxes(m[..., :3, :3], -1, -2)
    out[..., :3, :3] = rt
    out[..., :3, 3] = -(rt @ m[..., :3, 3:4])[..., 0]
    out[..., 3, 3] = 1.0
    return out


def similarity_inverse(m: np.ndarray) -> np.ndarray:
    """Inverse of rotation x uniform scale + translation matrices (a scaled bone's pose)."""
    out = np.zeros_like(m)
    s2 = np.sum(m[..., :3, 0] ** 2, axis=-1)[..., None, None]
    rt = np.swapaxes(m[..., :3, :3], -1, -2) / s2
    out[..., :3, :3] = rt
    out[..., :3, 3] = -(rt @ m[..., :3, 3:4])[..., 0]
    out[..., 3, 3] = 1.0
    return out


def basis_from_pose(pose: np.ndarray, rest: np.ndarray, parents: list[int], scaled: bool = False) -> np.ndarray:
    """Armature-space pose matrices (F, B, 4, 4) -> ``matrix_basis`` (F, B, 4, 4).

    Blender evaluates ``pose = parent_pose @ (parent_rest^-1 @ rest) @ basis`` (``rest @ basis``
    for the root) for bones that inherit rotation and scale, so ``basis`` is that solved for.
    ``scaled``: the poses carry uniform scales (a morph), so the parents' are inverted as such.
    """
    basis = np.empty_like(pose)
    inv_rest = rigid_inverse(rest)
    inverse = similarity_inverse if scaled else rigid_inverse
    for b, p in enumerate(parents):
        if p < 0:
            basis[:, b] = inv_rest[b] @ pose[:, b]
        else:
            rest_local = inv_rest[p] @ rest[b]
            basis[:, b] = rigid_inverse(rest_local) @ inverse(pose[:, p]) @ pose[:, b]
    return basis


@dataclass
class BoneChannels:
    frames: np.ndarray              # (F,) scene frames
    names: list[str]                # bone names, index 0 is the root
    root_location: np.ndarray       # (F, 3) root bone location (bone-local, Blender's convention)
    rotations: np.ndarray           # (F, B, 4) rotation_quaternion per bone (w, x, y, z)
    joint_slip: float               # largest translation a non-root basis would need (m): ~0
    locations: np.ndarray | None = None   # (F, B, 3) every bone's location: a morphing body's joints move
    scales: np.ndarray | None = None      # (F, B) every bone's uniform scale (its basis's)

    def fcurve_values(self):
        """(data_path, index, bone, values (F,)) for every F-curve to write."""
        root = self.names[0]
        for i in range(3):
            yield f'pose.bones["{root}"].location', i, root, self.root_location[:, i]
        for b, name in enumerate(self.names):
            for i in range(4):
                yield f'pose.bones["{name}"].rotation_quaternion', i, name, self.rotations[:, b, i]
        if self.scales is None:
            return
        for b, name in enumerate(self.names):
            if b > 0:
                for i in range(3):
                    yield f'pose.bones["{name}"].location', i, name, self.locations[:, b, i]
            for i in range(3):
                yield f'pose.bones["{name}"].scale', i, name, self.scales[:, b]


def channels(frames: np.ndarray, basis: np.ndarray, names: list[str], parents: list[int],
             scaled: bool = False) -> BoneChannels:
    roots = [b for b, p in enumerate(parents) if p < 0]
    if roots != [0]:
        raise ValueError("the first bone must be the only root")
    if not scaled:
        rotations = make_continuous(matrix_to_quat(basis[..., :3, :3]))
        slip = float(np.abs(basis[:, 1:, :3, 3]).max()) if len(names) > 1 else 0.0
        return BoneChannels(frames, list(names), basis[:, 0, :3, 3].copy(), rotations, slip)
    scales = np.linalg.norm(basis[..., :3, 0], axis=-1)
    rotations = make_continuous(matrix_to_quat(basis[..., :3, :3] / scales[..., None, None]))
    return BoneChannels(frames, list(names), basis[:, 0, :3, 3].copy(), rotations, 0.0,
                        basis[..., :3, 3].copy(), scales)


def morph_fraction_at(arrays: dict, meta: dict, times: np.ndarray) -> np.ndarray | None:
    """A morphing run's fraction f (sim_core.character.morph) at ``times`` (s from the start),
    from its edit log: f holds from each logged tick on (None: the run does not morph)."""
    fields = meta.get("edit_fields", [])
    if "morph" not in fields:
        return None
    sel = arrays["edit_field"] == fields.index("morph")
    if not sel.any():
        return None
    tick_time = meta["steps_per_tick"] * meta["timestep"]
    ticks, values = arrays["edit_tick"][sel], arrays["edit_value"][sel]
    k = np.searchsorted(ticks * tick_time, np.asarray(times, float) + 1e-9, side="right") - 1
    return np.where(k >= 0, values[np.maximum(k, 0)], 0.0)


def morph_scales(fraction: np.ndarray, start_mass: np.ndarray, end_mass: np.ndarray) -> np.ndarray:
    """(F, B) each bone's uniform scale at the fractions (F,): the cube root of its body's mass
    ratio, so that the skin's volume per segment x its density stays the segment's mass."""
    mass = start_mass[None, :] + fraction[:, None] * (end_mass - start_mass)[None, :]
    return np.cbrt(mass / start_mass[None, :])


def frame_poses(trajectory_arrays: dict, names: list[str], fps: float, start_frame: int = 1,
                duration: float | None = None, missing: str = "bodies not in the trajectory"):
    """(frames, positions (F, B, 3), quats (F, B, 4)): the named bodies' recorded world poses
    resampled at the scene's frames. A name the trajectory lacks is a one-line error that
    starts with ``missing``."""
    body_names = [str(n) for n in trajectory_arrays["body_names"]]
    absent = [n for n in names if n not in body_names]
    if absent:
        raise ValueError(f"{missing}: {', '.join(absent)}")
    order = [body_names.index(n) for n in names]
    times, frames, at = run_frames(trajectory_arrays, fps, start_frame, duration)
    pos, quat = resample(times, trajectory_arrays["body_pos"][:, order], trajectory_arrays["body_quat"][:, order], at)
    return frames, pos, quat


def run_frames(trajectory_arrays: dict, fps: float, start_frame: int = 1, duration: float | None = None):
    """(the run's sample times from 0, the scene's frames, their times): the frames that fall
    inside the run (or its first ``duration`` seconds)."""
    times = np.asarray(trajectory_arrays["time"], float)
    times = times - times[0]
    span = float(times[-1]) if duration is None else min(float(duration), float(times[-1]))
    frames, at = frame_times(span, fps, start_frame)
    return times, frames, at


def bake_channels(trajectory_arrays: dict, rest: np.ndarray, names: list[str], parents: list[int],
                  fps: float, start_frame: int = 1, duration: float | None = None,
                  morph: tuple | None = None) -> BoneChannels:
    """The whole pipeline: trajectory arrays + the armature's rest matrices -> F-curve channels.

    ``names``/``parents``/``rest`` describe the armature's bones; every bone must be a body of
    the trajectory (matched by name, so the order of bones and bodies need not agree).
    ``morph``: (meta, start masses, end masses) of a morphing run (the masses per bone, in
    ``names`` order): each bone is then scaled with its body, and its joint placed where the
    body's is (location channels)."""
    frames, pos, quat = frame_poses(trajectory_arrays, names, fps, start_frame, duration,
                                    missing="bones without a simulated body")
    if morph is None:
        pose = bone_pose_matrices(pos, quat, rest)
        return channels(frames, basis_from_pose(pose, rest, parents), names, parents)
    meta, start_mass, end_mass = morph
    fraction = morph_fraction_at(trajectory_arrays, meta, (frames - frames[0]) / fps)
    scale = morph_scales(fraction, start_mass, end_mass)
    pose = bone_pose_matrices(pos, quat, rest, scale)
    return channels(frames, basis_from_pose(pose, rest, parents, scaled=True), names, parents, scaled=True)


# ----------------------------------------------------------------------------- checks

def pose_from_channels(ch: BoneChannels, rest: np.ndarray, parents: list[int]) -> np.ndarray:
    """Forward kinematics as Blender does it (the inverse of ``basis_from_pose``), for tests."""
    n_frames, n_bones = ch.rotations.shape[:2]
    basis = np.zeros((n_frames, n_bones, 4, 4))
    basis[..., :3, :3] = quat_to_matrix(ch.rotations)
    if ch.scales is not None:
        basis[..., :3, :3] *= ch.scales[..., None, None]
        basis[..., :3, 3] = ch.locations
    basis[:, 0, :3, 3] = ch.root_location
    basis[..., 3, 3] = 1.0
    pose = np.empty_like(basis)
    inv_rest = rigid_inverse(rest)
    for b, p in enumerate(parents):
        if p < 0:
            pose[:, b] = rest[b] @ basis[:, b]
        else:
            pose[:, b] = pose[:, p] @ (inv_rest[p] @ rest[b]) @ basis[:, b]
    return pose


def body_pose_from_bone(pose: np.ndarray, rest: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Bone pose matrices (armature space) -> body positions and rotation matrices in the sim
    frame (what a bake must reproduce)."""
    scale = np.linalg.norm(pose[..., :3, 0], axis=-1)[..., None, None]       # 1 but for a morph
    rot = SIM_TO_BLENDER.T @ (pose[..., :3, :3] / scale @ np.swapaxes(rest[..., :3, :3], -1, -2)) @ SIM_TO_BLENDER
    return pose[..., :3, 3] @ SIM_TO_BLENDER, rot
