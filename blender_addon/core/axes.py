"""The one place where the simulation frame meets Blender's (and glTF's) axes.

Simulation (thesis) frame: X forward, Y left, Z up. Blender convention: a character faces -Y
with Z up, so its left is +X. The armature's local space is the simulation frame turned by
-90 degrees about Z: sim (x, y, z) -> Blender (y, -x, z). The armature *object* then places the
character in the scene, like any Blender object.

glTF's convention (+Y up, front facing +Z, right-handed) is fixed by the format, and Blender's
importer maps glTF (x, y, z) -> Blender (x, -z, y); ``BLENDER_TO_GLTF`` is its inverse, so a rig
written as ``BLENDER_TO_GLTF @ SIM_TO_BLENDER @ p`` imports exactly where the bake expects it.

No bpy here: these are plain NumPy matrices used by build.py, the bake math and the tests.
"""
from __future__ import annotations

import numpy as np

# Columns are the images of the sim axes: +X (forward) -> -Y, +Y (left) -> +X, +Z -> +Z.
SIM_TO_BLENDER = np.array([[0.0, 1.0, 0.0],
                           [-1.0, 0.0, 0.0],
                           [0.0, 0.0, 1.0]])
BLENDER_TO_SIM = SIM_TO_BLENDER.T

# Blender's glTF importer: glTF (x, y, z) -> Blender (x, -z, y); this is the inverse.
GLTF_TO_BLENDER = np.array([[1.0, 0.0, 0.0],
                            [0.0, 0.0, -1.0],
                            [0.0, 1.0, 0.0]])
BLENDER_TO_GLTF = GLTF_TO_BLENDER.T
SIM_TO_GLTF = BLENDER_TO_GLTF @ SIM_TO_BLENDER


def sim_to_blender_points(points: np.ndarray) -> np.ndarray:
    """Positions (..., 3) in the sim frame -> the armature's local space."""
    return np.asarray(points, dtype=float) @ SIM_TO_BLENDER.T


def blender_to_sim_points(points: np.ndarray) -> np.ndarray:
    """Positions (..., 3) in the armature's local space -> the sim frame."""
    return np.asarray(points, dtype=float) @ BLENDER_TO_SIM.T


def sim_to_blender_rotations(rotations: np.ndarray) -> np.ndarray:
    """Rotation matrices (..., 3, 3) acting in the sim frame -> the same rotations in Blender's."""
    return SIM_TO_BLENDER @ np.asarray(rotations, dtype=float) @ BLENDER_TO_SIM


def blender_to_sim_rotations(rotations: np.ndarray) -> np.ndarray:
    return BLENDER_TO_SIM @ np.asarray(rotations, dtype=float) @ SIM_TO_BLENDER
