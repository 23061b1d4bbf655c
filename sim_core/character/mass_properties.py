"""Masses and moments of inertia of groups of bodies in the standing pose.

Hodgins & Pollard 1997 compute every inertia once, in the upright standing pose ([B] 210-215):
the three joint-referenced inertias of Fig. 3 and the inertia ratio I'/I each servo gain is
mass-scaled by. Both read them from here, measured on the compiled model (so the numbers are the
ones the physics uses: body frames, inertias and joint axes as MuJoCo holds them).
"""
from __future__ import annotations

import mujoco
import numpy as np

from .model import compile_model, set_standing_pose
from .spec import CharacterSpec


class StandingBody:
    """A character compiled and put in its standing pose (feet on the ground, arms down)."""

    def __init__(self, character: CharacterSpec):
        self.character = character
        self.model, _ = compile_model(character)
        self.data = mujoco.MjData(self.model)
        set_standing_pose(self.model, self.data, character)
        mujoco.mj_forward(self.model, self.data)
        self.names = [self.model.body(i).name for i in range(self.model.nbody)]
        self.grounded = {b["name"] for b in character.bodies if b.get("contacts")}

    def subtree(self, root: str) -> set[str]:
        """``root`` and every body outboard of it."""
        ids = {self.names.index(root)}
        for i in range(1, self.model.nbody):
            parents = []
            j = i
            while j > 0:
                parents.append(j)
                j = self.model.body_parentid[j]
            if ids & set(parents):
                ids.add(i)
        return {self.names[i] for i in ids}

    def all_bodies(self) -> set[str]:
        return set(self.names[1:])

    def mass(self, bodies) -> float:
        return float(sum(self.model.body_mass[i] for i in self._ids(bodies)))

    def _ids(self, bodies) -> list[int]:
        """Model order: sums come out the same bit for bit whatever the order of a set of names."""
        return sorted(self.names.index(b) for b in bodies)

    def joint_anchor(self, dof: str) -> np.ndarray:
        return self.data.xanchor[self.model.joint(dof).id].copy()

    def joint_axis(self, dof: str) -> np.ndarray:
        return self.data.xaxis[self.model.joint(dof).id].copy()

    def inertia_about(self, bodies, point, axis) -> float:
        """Moment of inertia (kg m^2) of ``bodies`` about the line through ``point`` along ``axis``."""
        axis = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
        total = 0.0
        for i in self._ids(bodies):
            rotation = self.data.ximat[i].reshape(3, 3)
            central = rotation @ np.diag(self.model.body_inertia[i]) @ rotation.T
            r = self.data.xipos[i] - np.asarray(point, dtype=float)
            total += axis @ central @ axis + self.model.body_mass[i] * (r @ r - (r @ axis) ** 2)
        return float(total)
