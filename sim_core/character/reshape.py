"""A new character from an existing spec by stretching each body and changing its mass.

Each body gets a ``BodyScale``: a length factor per world axis of the reference configuration
(X forward, Y left, Z up; the T-pose, where every segment lies along an axis: legs and trunk
along Z, arms along Y, feet along X) and a mass factor. Density stays the segment's own
(Dempster's), so a body's volume, and the product of its three length factors, follows its mass.
Everything attached to a body follows its own scale: its centre of mass, its shapes, its contact
spheres, and the positions of its children's joints (measured from its own joint). The body's
inertia tensor is that of the same solid stretched by the three factors: with S = ∫ρ r rᵀ the
second moment about the centre of mass (S = tr(I)/2 - I), S' = m'/m · D S D with D = diag(s),
and I' = tr(S') - S'. Afterwards the whole body is moved so that the feet stand on z = 0.

Joint ranges and the standing pose are angles and do not change; the servo gains and torque
limits are mass-scaled afterwards by sim_core.adapt.servos (they need the new inertias).
"""
from __future__ import annotations

import copy
import math
from dataclasses import dataclass

import numpy as np

from .anthropometry import capsule_radius


@dataclass(frozen=True)
class BodyScale:
    axes: tuple[float, float, float]      # length factors along world X, Y, Z
    mass: float                           # m'/m

    @classmethod
    def stretched(cls, axis: int, axial: float, mass: float) -> "BodyScale":
        """Length factor ``axial`` along ``axis`` (0, 1, 2 = X, Y, Z); both other axes take the
        factor that keeps the density: sqrt(mass / axial)."""
        across = math.sqrt(mass / axial)
        axes = [across, across, across]
        axes[axis] = axial
        return cls(tuple(axes), mass)

    @classmethod
    def uniform(cls, mass: float) -> "BodyScale":
        """Every length by the cube root of the mass factor (a geometric copy at the same density)."""
        return cls((mass ** (1 / 3),) * 3, mass)


def reshaped(data: dict, scales: dict[str, BodyScale]) -> dict:
    """A copy of spec ``data`` with every body scaled by ``scales[body]`` (every body must be
    named), standing with its lowest contact on z = 0. Servo fields are copied unchanged."""
    missing = [b["name"] for b in data["bodies"] if b["name"] not in scales]
    if missing:
        raise ValueError(f"no scale for bodies {missing}")
    out = copy.deepcopy(data)
    old_origin, new_origin = {}, {}
    for body in out["bodies"]:
        name, parent = body["name"], body["parent"]
        old = np.array(body["joint"]["pos"]) if parent else np.array(body["com"])
        old_origin[name] = old
        if parent is None:
            new_origin[name] = old.copy()
        else:
            new_origin[name] = new_origin[parent] + np.array(scales[parent].axes) * (old - old_origin[parent])
    for body in out["bodies"]:
        name = body["name"]
        s = np.array(scales[name].axes)
        move = lambda p: (new_origin[name] + s * (np.asarray(p) - old_origin[name])).tolist()   # noqa: E731
        old_mass = body["mass"]
        body["mass"] = old_mass * scales[name].mass
        body["com"] = move(body["com"])
        body["inertia"] = stretched_inertia(np.array(body["inertia"]), s, scales[name].mass).tolist()
        body["shapes"] = [_scaled_shape(shape, move, s, scales[name].mass) for shape in body["shapes"]]
        for contact in body["contacts"]:
            contact["pos"] = move(contact["pos"])
            contact["radius"] = contact["radius"] * s[2]
        if body.get("joint"):
            body["joint"]["pos"] = new_origin[name].tolist()
    _stand_on_ground(out)
    out["total_mass"] = float(sum(b["mass"] for b in out["bodies"]))
    out["height"] = standing_height(out)
    return out


def stretched_inertia(inertia: np.ndarray, axes: np.ndarray, mass: float) -> np.ndarray:
    """Inertia tensor about the COM of the same solid stretched by ``axes`` with mass x ``mass``."""
    second_moment = np.trace(inertia) / 2 * np.eye(3) - inertia
    stretched = mass * np.diag(axes) @ second_moment @ np.diag(axes)
    return np.trace(stretched) * np.eye(3) - stretched


def standing_height(data: dict) -> float:
    """Top of the head above the ground in the reference configuration (as build.py measures it)."""
    head = next(b for b in data["bodies"] if b["name"] == "HEAD")
    return float(max(s["pos"][2] + s["radius"] for s in head["shapes"] if s["type"] == "sphere"))


def _scaled_shape(shape: dict, move, s: np.ndarray, mass: float) -> dict:
    """A shape moved and stretched with its body, its volume x ``mass`` (the body's mass factor)
    so that volume x density stays the segment's mass (the skin is checked against it): a
    capsule's radius is solved for its new length, a sphere's from its volume."""
    shape = dict(shape)
    kind = shape["type"]
    if kind == "capsule":
        r, length = shape["radius"], float(np.linalg.norm(np.subtract(shape["to"], shape["from"])))
        volume = (math.pi * r * r * length + 4 / 3 * math.pi * r ** 3) * mass
        shape["from"], shape["to"] = move(shape["from"]), move(shape["to"])
        shape["radius"] = capsule_radius(volume, float(np.linalg.norm(np.subtract(shape["to"], shape["from"]))))
    elif kind == "sphere":
        shape["pos"] = move(shape["pos"])
        shape["radius"] = shape["radius"] * mass ** (1 / 3)
    elif kind in ("box", "ellipse_slab"):
        along = np.array(shape.get("along", [1.0, 0.0, 0.0]))
        isotropic = np.allclose(s, s[0])
        if not isotropic and not np.allclose(np.abs(along), [1.0, 0.0, 0.0]):
            raise ValueError(f"a {kind} not along X can only be scaled uniformly (axes {s.tolist()})")
        shape["pos"] = move(shape["pos"])
        shape["half"] = (np.array(shape["half"]) * s).tolist()
    else:
        raise ValueError(f"unknown shape type {kind!r}")
    return shape


def _stand_on_ground(data: dict) -> None:
    """Shift every position so that the lowest contact sphere touches z = 0."""
    lowest = min(c["pos"][2] - c["radius"] for b in data["bodies"] for c in b["contacts"])
    shift = np.array([0.0, 0.0, -lowest])
    for body in data["bodies"]:
        body["com"] = (np.array(body["com"]) + shift).tolist()
        if body.get("joint"):
            body["joint"]["pos"] = (np.array(body["joint"]["pos"]) + shift).tolist()
        for contact in body["contacts"]:
            contact["pos"] = (np.array(contact["pos"]) + shift).tolist()
        for shape in body["shapes"]:
            for key in ("pos", "from", "to"):
                if key in shape:
                    shape[key] = (np.array(shape[key]) + shift).tolist()
