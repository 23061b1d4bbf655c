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
    """Foot contact sites grouped by foot (foot + toe). A foot that touches the ground anywhere
    contributes all its sites to the support area, so a heel that lifts under a push does not
    move the centre of support forward (which would make the COM servo give way)."""

    def __init__(self, model: mujoco.MjModel, feet=(("FOOTR", "TOER"), ("FOOTL", "TOEL"))):
        groups = []
        for bodies in feet:
            ids = {model.body(b).id for b in bodies}
            groups.append([i for i in range(model.nsite) if model.site_bodyid[i] in ids])
        self.site_ids = np.array([i for g in groups for i in g])
        self.foot_of_site = np.array([k for k, g in enumerate(groups) for _ in g])
        self.right, self.left = self.foot_of_site == 0, self.foot_of_site == 1
        self.contact_height = 0.005

    def points(self, data: mujoco.MjData) -> np.ndarray:
        return data.site_xpos[self.site_ids]

    def supporting_points(self, data: mujoco.MjData) -> np.ndarray:
        """All sites of every foot that touches the ground (all sites if none does)."""
        points = data.site_xpos[self.site_ids]
        low = points[:, 2] < self.contact_height
        right = bool(low[self.right].any())
        left = bool(low[self.left].any())
        if right == left:                       # both feet down (or both up: use them all)
            return points
        return points[self.right] if right else points[self.left]
