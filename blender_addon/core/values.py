"""Panel values as the CLI would take them (no bpy): numbers as typed, choices as their codes,
a curve's points as a path in the rig's start frame."""
from __future__ import annotations

import numpy as np

from .axes import blender_to_sim_points


def as_typed(value) -> float:
    """A panel value as the number the user typed: Blender stores floats in single precision
    (0.2 comes back as 0.20000000298...), so take the shortest decimal that the float32 rounds
    to. The same request then gives the same run as the CLI, bit for bit."""
    return float(str(np.float32(value)))


def knob_value(knob, value):
    """What the schema takes from the panel for one knob: a choice's option name as it is (the
    schema turns it into its code), a bool as 0/1, a number as typed."""
    if knob.kind == "choice":
        return str(value)
    if knob.kind == "bool":
        return 1.0 if value else 0.0
    return as_typed(value)


def path_in_rig_frame(points_world: np.ndarray, rig_world: np.ndarray) -> list[list[float]]:
    """(N, 3) world points of a curve -> [[x, y], ...] in the simulation frame of the rig whose
    4x4 world matrix is ``rig_world`` (the path a run follows from where the rig stands)."""
    points = np.asarray(points_world, dtype=float).reshape(-1, 3)
    inverse = np.linalg.inv(np.asarray(rig_world, dtype=float))
    local = points @ inverse[:3, :3].T + inverse[:3, 3]
    sim = blender_to_sim_points(local)
    return [[round(float(x), 6), round(float(y), 6)] for x, y in sim[:, :2]]
