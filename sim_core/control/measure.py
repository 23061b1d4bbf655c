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


def surface_under(points: np.ndarray, boxes, floor: float = 0.0) -> np.ndarray:
    """Height of what is under each point (..., 3 or 2): the top of a box whose footprint holds it,
    else the ground (``floor``). ``boxes``: World.boxes, ((x, y, height, length, width), ...)."""
    points = np.asarray(points)
    under = np.full(points.shape[:-1], float(floor))
    for box in boxes:
        under = np.where(in_footprint(points, box), np.maximum(under, box[2]), under)
    return under


def in_footprint(points: np.ndarray, box) -> np.ndarray:
    """Per point (..., 3 or 2): whether it lies over the footprint of ``box`` (x, y, height, length, width)."""
    x, y, _, length, width = box
    return (np.abs(points[..., 0] - x) <= length / 2) & (np.abs(points[..., 1] - y) <= width / 2)


def floor_of(model: mujoco.MjModel) -> float:
    """World.floor read back off a compiled model (the ground plane's height; a diving platform's
    ground is a box whose top is at 0)."""
    ground = model.geom("ground").id
    return float(model.geom_pos[ground][2]) if model.geom_type[ground] == mujoco.mjtGeom.mjGEOM_PLANE else 0.0


STANDING_APPARATUS = ("vault_table", "landing_mat")   # fixed apparatus a foot stands on, like a box


def boxes_of(model: mujoco.MjModel) -> tuple:
    """World.boxes read back off a compiled model (geoms named box0, box1, ...), then the fixed
    apparatus one stands on (the vaulting table, the landing mat): (x, y, top height, length, width)."""
    boxes = []
    while mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, f"box{len(boxes)}") >= 0:
        boxes.append(_box(model, f"box{len(boxes)}"))
    return tuple(boxes) + tuple(_box(model, name) for name in STANDING_APPARATUS
                                if mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, name) >= 0)


def compliant_boxes(model: mujoco.MjModel) -> tuple:
    """The fixed apparatus one stands on that gives under the feet (the landing mat): those whose
    contact impedance at the surface (solimp's first value, used for their contacts by priority) is
    below the ground's; as boxes_of's (x, y, top height, length, width)."""
    ground = float(model.geom_solimp[model.geom("ground").id][0])
    return tuple(_box(model, name) for name in STANDING_APPARATUS
                 if mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, name) >= 0
                 and float(model.geom_solimp[model.geom(name).id][0]) < ground)


def over_a_box(points: np.ndarray, boxes) -> bool:
    """Whether any of the points (n, 3 or 2) is over the footprint of one of the boxes."""
    points = np.asarray(points)
    return any(bool(in_footprint(points, box).any()) for box in boxes)


def _box(model: mujoco.MjModel, name: str) -> tuple:
    geom = model.geom(name)
    (x, y, z), (hx, hy, hz) = model.geom_pos[geom.id], model.geom_size[geom.id]
    return (float(x), float(y), float(z + hz), float(2 * hx), float(2 * hy))


class SupportGeometry:
    """Foot contact sites grouped by foot (foot + toe). A foot that touches the ground anywhere
    contributes all its sites to the support area, so a heel that lifts under a push does not
    move the centre of support forward (which would make the COM servo give way)."""

    def __init__(self, model: mujoco.MjModel, feet=(("FOOTR", "TOER"), ("FOOTL", "TOEL")), prefix: str = ""):
        """``prefix``: the character's name prefix in a scene's model ("" for a single one)."""
        groups = []
        for bodies in feet:
            ids = {model.body(prefix + b).id for b in bodies}
            groups.append([i for i in range(model.nsite) if model.site_bodyid[i] in ids])
        self.site_ids = np.array([i for g in groups for i in g])
        self.foot_of_site = np.array([k for k, g in enumerate(groups) for _ in g])
        self.right, self.left = self.foot_of_site == 0, self.foot_of_site == 1
        self.contact_height = 0.005          # definition: a site within 5 mm of the ground touches it
        self.boxes = boxes_of(model)
        self.floor = floor_of(model)

    def points(self, data: mujoco.MjData) -> np.ndarray:
        return data.site_xpos[self.site_ids]

    def heights(self, data: mujoco.MjData, points: np.ndarray | None = None) -> np.ndarray:
        """Height of every site (or of ``points``, the sites already read) above what is under
        it (the ground or a box)."""
        points = data.site_xpos[self.site_ids] if points is None else points
        if not self.boxes:
            return points[:, 2] - self.floor
        return points[:, 2] - surface_under(points, self.boxes, self.floor)

    def supporting_points(self, data: mujoco.MjData) -> np.ndarray:
        """All sites of every foot that touches the ground (all sites if none does)."""
        points = data.site_xpos[self.site_ids]
        low = self.heights(data, points) < self.contact_height
        right = bool(low[self.right].any())
        left = bool(low[self.left].any())
        if right == left:                       # both feet down (or both up: use them all)
            return points
        return points[self.right] if right else points[self.left]
