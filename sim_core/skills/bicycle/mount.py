"""The rider's pose on the bicycle: inverse kinematics that puts the rider's attachment sites
(seat bones, palms, balls of the feet) on the bicycle's (saddle, grips, pedals).

Used twice: once for the start state (the whole rider, its root included, is posed on the
bicycle standing still or rolling; a named, logged initial state like StartState), and every
control tick for the arms (the shoulder and elbow angles that put the hands on the grips for the
current fork angle, [A] 142). A damped least-squares solve on MuJoCo's site Jacobians
(``mj_jacSite``) on a scratch copy of the state: the run's own state is never touched by it.
"""
from __future__ import annotations

import mujoco
import numpy as np

from ...world.bicycle import ATTACHMENTS

IK_DAMPING = 1e-3            # damped least squares: lambda^2 added to J J^T's diagonal
IK_POSTURE_WEIGHT = 0.05     # pull of the unconstrained joints back to the reference posture
IK_ITERATIONS = 60
IK_ITERATIONS_PER_TICK = 3   # warm-started from the current pose each control tick
IK_TOLERANCE = 5e-4          # m: stop when every site is this close


class SitePairs:
    """The attachment sites of one rider on one bicycle, as model ids."""

    def __init__(self, model: mujoco.MjModel, prefix: str = ""):
        self.names = [name for name, *_ in ATTACHMENTS]
        self.rider = np.array([model.site(f"{prefix}rider_{n}").id for n in self.names])
        self.bike = np.array([model.site(bike).id for _, _, bike, _ in ATTACHMENTS])

    def gaps(self, data: mujoco.MjData) -> np.ndarray:
        """Distance (m) between each rider site and its bicycle site."""
        return np.linalg.norm(data.site_xpos[self.rider] - data.site_xpos[self.bike], axis=1)


def solve(model: mujoco.MjModel, data: mujoco.MjData, pairs: SitePairs, which: list[int], dofs: np.ndarray,
          reference: np.ndarray, iterations: int = IK_ITERATIONS, posture_weight: float = IK_POSTURE_WEIGHT) -> np.ndarray:
    """Move the dofs ``dofs`` (addresses in qvel) of ``data`` so the attachment pairs ``which``
    meet; ``reference``: the qpos the other directions are pulled towards (by ``posture_weight``;
    0 for an exact final pass). Joint limits are kept.
    Returns the final gaps. ``data`` must be a scratch copy."""
    nv = model.nv
    jac = np.zeros((3, nv))
    jac_bike = np.zeros((3, nv))
    hinge_dofs = [d for d in dofs if model.jnt_type[model.dof_jntid[d]] == mujoco.mjtJoint.mjJNT_HINGE]
    hinge_qpos = np.array([model.jnt_qposadr[model.dof_jntid[d]] for d in hinge_dofs], dtype=int)
    hinge_cols = np.array([list(dofs).index(d) for d in hinge_dofs], dtype=int)
    lo = model.jnt_range[model.dof_jntid[hinge_dofs], 0]
    hi = model.jnt_range[model.dof_jntid[hinge_dofs], 1]
    for _ in range(iterations):
        mujoco.mj_kinematics(model, data)
        mujoco.mj_comPos(model, data)
        rows, errs = [], []
        for k in which:
            mujoco.mj_jacSite(model, data, jac, None, pairs.rider[k])
            mujoco.mj_jacSite(model, data, jac_bike, None, pairs.bike[k])
            rows.append((jac - jac_bike)[:, dofs])
            errs.append(data.site_xpos[pairs.bike[k]] - data.site_xpos[pairs.rider[k]])
        J, e = np.vstack(rows), np.concatenate(errs)
        if np.abs(e).max() < IK_TOLERANCE:
            break
        posture = np.zeros(len(dofs))
        posture[hinge_cols] = reference[hinge_qpos] - data.qpos[hinge_qpos]
        # minimise |J dq - e|^2 + w^2 |dq - posture|^2 + lambda^2 |dq|^2
        w2 = posture_weight ** 2
        A = J.T @ J + (w2 + IK_DAMPING) * np.eye(len(dofs))
        dq = np.linalg.solve(A, J.T @ e + w2 * posture)
        step = np.zeros(nv)
        step[dofs] = dq
        mujoco.mj_integratePos(model, data.qpos, step, 1.0)
        data.qpos[hinge_qpos] = np.clip(data.qpos[hinge_qpos], lo, hi)
    mujoco.mj_kinematics(model, data)
    return pairs.gaps(data)


def match_velocities(model: mujoco.MjModel, data: mujoco.MjData, pairs: SitePairs, dofs: np.ndarray) -> None:
    """Set the velocities of the dofs ``dofs`` so that every rider site moves with its bicycle
    site (the attachments start unstretched in velocity too): one least-squares solve on the
    site Jacobians at the current pose."""
    mujoco.mj_kinematics(model, data)
    mujoco.mj_comPos(model, data)
    jac, jac_bike = np.zeros((3, model.nv)), np.zeros((3, model.nv))
    rows, errs = [], []
    for k in range(len(pairs.names)):
        mujoco.mj_jacSite(model, data, jac, None, pairs.rider[k])
        mujoco.mj_jacSite(model, data, jac_bike, None, pairs.bike[k])
        rows.append(jac[:, dofs])
        errs.append(jac_bike @ data.qvel - jac @ data.qvel)
    J, e = np.vstack(rows), np.concatenate(errs)
    dq = np.linalg.solve(J.T @ J + IK_DAMPING * np.eye(len(dofs)), J.T @ e)
    data.qvel[dofs] += dq
