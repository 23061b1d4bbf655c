"""Measurements a controller takes from the simulated state (cheap, allocation-light)."""
from __future__ import annotations

import math

import mujoco
import numpy as np


def yaw_of(xmat: np.ndarray) -> float:
    """Heading of a body: angle of its local +X projected on the ground plane."""
    return math.atan2(xmat[3], xmat[0])


def pitch_of(xmat: np.ndarray, up: np.ndarray) -> float:
    """Forward pitch: right-handed rotation about the body's local Y (positive = +X tips down,
    +Z leans forward), for any heading."""
    m = xmat.reshape(3, 3)
    return math.atan2(float(-np.dot(m[:, 0], up)), float(np.dot(m[:, 2], up)))


def roll_of(xmat: np.ndarray, up: np.ndarray) -> float:
    """Sideways roll: right-handed rotation about the body's local X (positive = +Y tips up)."""
    m = xmat.reshape(3, 3)
    return math.atan2(float(np.dot(m[:, 1], up)), float(np.dot(m[:, 2], up)))


class SupportGeometry:
    """Foot contact sites: which touch the ground, and the centre of their extent."""

    def __init__(self, model: mujoco.MjModel, foot_bodies=("FOOTR", "FOOTL", "TOER", "TOEL")):
        self.site_ids = np.array([i for i in range(model.nsite)
                                  if model.site_bodyid[i] in {model.body(b).id for b in foot_bodies}])
        self.contact_height = 0.005

    def points(self, data: mujoco.MjData) -> np.ndarray:
        return data.site_xpos[self.site_ids]

    def touching(self, data: mujoco.MjData) -> np.ndarray:
        return self.points(data)[:, 2] < self.contact_height
