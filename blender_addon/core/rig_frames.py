"""Where each bone sits and points in the rest pose, computed from the character spec.

One bone per simulated body, named exactly as the body:
  * head: the body's inboard joint (the origin of its MuJoCo frame); the root bone (PELVIS) has
    no joint, so its head is the pelvis centre of mass, which is where MuJoCo puts the root
    body's frame and what the trajectory records as its position;
  * tail: towards the joint of the body's next child along the chain (the one nearest the
    mid-plane, so the pelvis points up the spine and the sternum to the head); a body with no
    child (head, hands, toes) points through its centre of mass to twice that distance;
  * roll: the bone's Z axis as close as possible to the character's forward direction (up, for
    bones that themselves point forward, like the feet).

All in the armature's local space (see :mod:`axes`). No bpy: the add-on applies these after
Blender's glTF importer has created the bones, the tests check them without Blender.
"""
from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass

import numpy as np

from .axes import SIM_TO_BLENDER, sim_to_blender_points


@dataclass
class RestFrames:
    names: list[str]
    parents: list[int]          # index of the parent bone, -1 for the root
    heads: np.ndarray           # (B, 3) armature space
    tails: np.ndarray           # (B, 3)
    z_axes: np.ndarray          # (B, 3) direction the bone's Z axis is aligned to (roll)

    def matrices(self) -> np.ndarray:
        """(B, 4, 4) rest matrices (Blender's ``Bone.matrix_local``: columns X, Y, Z, head)."""
        y = self.tails - self.heads
        y /= np.linalg.norm(y, axis=1, keepdims=True)
        z = self.z_axes - np.sum(self.z_axes * y, axis=1, keepdims=True) * y
        z /= np.linalg.norm(z, axis=1, keepdims=True)
        x = np.cross(y, z)
        out = np.zeros((len(self.names), 4, 4))
        out[:, :3, 0], out[:, :3, 1], out[:, :3, 2], out[:, :3, 3] = x, y, z, self.heads
        out[:, 3, 3] = 1.0
        return out


def spec_digest(bodies: list[dict]) -> str:
    """Fingerprint of what a rig is made from (bodies: names, tree, masses, joints, shapes), stored
    in the .glb so a stale rig is caught after the spec changes."""
    keys = ("name", "parent", "mass", "density", "com", "shapes", "joint")
    text = json.dumps([{k: b.get(k) for k in keys} for b in bodies], sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def body_origin(body: dict) -> np.ndarray:
    """Origin of the body's simulation frame in the reference pose (sim coordinates)."""
    return np.array(body["joint"]["pos"] if body.get("joint") else body["com"], dtype=float)


def rest_frames(bodies: list[dict]) -> RestFrames:
    names = [b["name"] for b in bodies]
    index = {n: i for i, n in enumerate(names)}
    parents = [index[b["parent"]] if b.get("parent") else -1 for b in bodies]
    origins = np.array([body_origin(b) for b in bodies])
    tails_sim = np.empty_like(origins)
    for i, b in enumerate(bodies):
        kids = [k for k, p in enumerate(parents) if p == i]
        if kids:
            k = min(kids, key=lambda k: abs(origins[k][1]))
            tails_sim[i] = origins[k]
        else:
            tails_sim[i] = origins[i] + 2.0 * (np.array(b["com"]) - origins[i])
        if np.linalg.norm(tails_sim[i] - origins[i]) < 0.02:       # degenerate: point up 5 cm
            tails_sim[i] = origins[i] + np.array([0.0, 0.0, 0.05])
    heads, tails = sim_to_blender_points(origins), sim_to_blender_points(tails_sim)
    forward, up = SIM_TO_BLENDER @ np.array([1.0, 0, 0]), np.array([0.0, 0, 1.0])
    y = (tails - heads) / np.linalg.norm(tails - heads, axis=1, keepdims=True)
    z_axes = np.where((np.abs(y @ forward) > 0.7)[:, None], up, forward)
    return RestFrames(names, parents, heads, tails, z_axes)
