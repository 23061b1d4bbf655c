"""A moving prop's bodies (the bicycle's frame, fork, wheels and crank) as Blender object
animation, without bpy: each prop body's recorded world pose, resampled to the scene's frames
(as the bones are, ``bake_math``) and turned into the object's location and rotation in the
armature's space by the one axis conversion (``axes.py``). The prop's simple mesh comes from the
body's own geoms in the run's model (capsules and cylinders as prisms, boxes as boxes)."""
from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from .axes import SIM_TO_BLENDER, sim_to_blender_points, sim_to_blender_rotations
from .bake_math import frame_poses, make_continuous, matrix_to_quat, quat_to_matrix, run_frames

PRISM_SIDES = 16        # a capsule or cylinder drawn as a 16-sided prism


@dataclass
class PropKeys:
    frames: np.ndarray          # (F,) scene frames
    names: list[str]            # prop body names
    location: np.ndarray        # (F, B, 3) object location in the armature's space
    rotation: np.ndarray        # (F, B, 4) object rotation_quaternion (w, x, y, z), continuous signs


def prop_keys(trajectory_arrays: dict, names: list[str], fps: float, start_frame: int = 1) -> PropKeys:
    """One key per scene frame for each named prop body, from the trajectory's recorded world
    poses (``body_pos``/``body_quat``, which hold the bicycle's bodies after the rider's):
    sim pose -> armature-space object transform (location S p, rotation S R S^T, so mesh
    vertices written as S v_body land where the body is)."""
    frames, pos, quat = frame_poses(trajectory_arrays, names, fps, start_frame,
                                    missing="prop bodies not in the trajectory")
    rot = sim_to_blender_rotations(quat_to_matrix(quat))
    return PropKeys(frames, list(names), sim_to_blender_points(pos), make_continuous(matrix_to_quat(rot)))


@dataclass
class SlideKeys:
    frames: np.ndarray          # (F,) scene frames
    offset: np.ndarray          # (F, 3) the body's displacement from its rest place, in Blender axes


def slide_keys(trajectory_arrays: dict, model: mujoco.MjModel, joint: str, fps: float,
               start_frame: int = 1) -> SlideKeys:
    """One key per scene frame of a world-fixed prop body's travel along its slide joint
    ``joint`` (the springboard's deck): the joint's recorded qpos, linearly resampled, times the
    joint's axis in the world at the model's rest pose (qpos = 0 is where the scenery draws it).
    The recorder leaves such a body out of ``body_pos``, so its motion is read from ``qpos``."""
    j = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, joint)
    if j < 0 or model.jnt_type[j] != mujoco.mjtJoint.mjJNT_SLIDE:
        raise ValueError(f"{joint!r} is not a slide joint of the run's model")
    qpos = np.asarray(trajectory_arrays["qpos"], float)
    if qpos.shape[1] != model.nq:
        raise ValueError(f"the trajectory's qpos has {qpos.shape[1]} entries; the model has {model.nq}")
    times, frames, at = run_frames(trajectory_arrays, fps, start_frame)
    travel = np.interp(at, times, qpos[:, model.jnt_qposadr[j]])
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    axis = data.xmat[model.jnt_bodyid[j]].reshape(3, 3) @ model.jnt_axis[j]
    return SlideKeys(frames, sim_to_blender_points(travel[:, None] * axis))


def body_mesh(model: mujoco.MjModel, body: int) -> tuple[np.ndarray, list[tuple[int, ...]]]:
    """(vertices (V, 3) in the object's local Blender axes, faces) of the body's geoms."""
    verts, faces = [], []
    for g in range(model.ngeom):
        if model.geom_bodyid[g] != body:
            continue
        kind, size = mujoco.mjtGeom(int(model.geom_type[g])), model.geom_size[g]
        if kind in (mujoco.mjtGeom.mjGEOM_CAPSULE, mujoco.mjtGeom.mjGEOM_CYLINDER):
            a = np.linspace(0, 2 * np.pi, PRISM_SIDES, endpoint=False)
            ring = np.stack([size[0] * np.cos(a), size[0] * np.sin(a), np.zeros_like(a)], axis=1)
            local = np.concatenate([ring - [0, 0, size[1]], ring + [0, 0, size[1]]])
            n = PRISM_SIDES
            f = [tuple(range(n - 1, -1, -1)), tuple(range(n, 2 * n))]
            f += [(i, (i + 1) % n, n + (i + 1) % n, n + i) for i in range(n)]
        elif kind == mujoco.mjtGeom.mjGEOM_BOX:
            local = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]) * size
            f = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
        else:
            continue
        placed = local @ quat_to_matrix(model.geom_quat[g]).T + model.geom_pos[g]
        base = sum(len(v) for v in verts)
        verts.append(placed @ SIM_TO_BLENDER.T)
        faces += [tuple(base + i for i in face) for face in f]
    return (np.concatenate(verts) if verts else np.zeros((0, 3))), faces
