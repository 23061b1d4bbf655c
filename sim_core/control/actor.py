"""Where one actor lives in a (possibly many-actor) model: its name prefix, root body, body /
qpos / qvel / actuator / site ranges and its placement. Behaviours look their character's parts up
through this view, so the same code drives a character alone (prefix "", root body 1, every
actuator) or as one actor of a scene ("<actor>/")."""
from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from ..character.model import Placement


@dataclass(frozen=True)
class ActorView:
    model: mujoco.MjModel
    prefix: str                 # "" for a single character, "<actor>/" in a scene
    root: int                   # body id of the root (the body of the free joint)
    bodies: slice               # the actor's body ids (contiguous: one subtree of the world)
    qpos: slice                 # its qpos addresses, the free joint's 7 first
    qvel: slice                 # its dof addresses, the free joint's 6 first
    actuators: slice            # its servos
    sites: slice                # its sites
    placement: Placement | None  # where its standing start was put (None: the model's own frame)

    @classmethod
    def of(cls, model: mujoco.MjModel, prefix: str = "", placement: Placement | None = None) -> "ActorView":
        joint = model.joint(prefix + "root").id
        root = int(model.jnt_bodyid[joint])
        body_ids = np.nonzero(model.body_rootid == root)[0]
        joints = np.nonzero(np.isin(model.jnt_bodyid, body_ids))[0]
        actuators = np.nonzero((model.actuator_trntype == mujoco.mjtTrn.mjTRN_JOINT)       # its servos, not a prop's
                               & np.isin(model.actuator_trnid[:, 0], joints))[0]                 # tendon-driven element
        sites = np.nonzero(np.isin(model.site_bodyid, body_ids))[0]
        last = joints[-1]
        return cls(model, prefix, root, _span(body_ids),
                   slice(int(model.jnt_qposadr[joint]), int(model.jnt_qposadr[last]) + _width(model, last, qpos=True)),
                   slice(int(model.jnt_dofadr[joint]), int(model.jnt_dofadr[last]) + _width(model, last, qpos=False)),
                   _span(actuators), _span(sites), placement)

    def body_id(self, name: str) -> int:
        return self.model.body(self.prefix + name).id

    def joint_id(self, name: str) -> int:
        return self.model.joint(self.prefix + name).id

    def joint_qposadr(self, name: str) -> int:
        return int(self.model.jnt_qposadr[self.joint_id(name)])

    def site_id(self, name: str) -> int:
        return self.model.site(self.prefix + name).id

    @property
    def root_qpos(self) -> int:
        """qpos address of the free joint (position x, y, z, then the quaternion)."""
        return self.qpos.start

    @property
    def root_dof(self) -> int:
        """dof address of the free joint (linear velocity, then the local angular velocity)."""
        return self.qvel.start


def _span(ids: np.ndarray) -> slice:
    """The ids as a slice; they must be contiguous (an actor is one subtree, added in one go)."""
    if len(ids) == 0:
        return slice(0, 0)
    if not np.all(np.diff(ids) == 1):
        raise ValueError(f"an actor's ids are not contiguous: {ids.tolist()}")
    return slice(int(ids[0]), int(ids[-1]) + 1)


def _width(model: mujoco.MjModel, joint: int, qpos: bool) -> int:
    kind = model.jnt_type[joint]
    if kind == mujoco.mjtJoint.mjJNT_FREE:
        return 7 if qpos else 6     # definition: a free joint's position and quaternion, its 6 dofs
    if kind == mujoco.mjtJoint.mjJNT_BALL:
        return 4 if qpos else 3     # definition: a ball joint's quaternion, its 3 dofs
    return 1
