"""Balanced crouch poses: for a pelvis height, the knee angle and pelvis pitch that keep the COM
over the centre of the feet with the feet flat and the ankles inside their dorsiflexion range.

Why: the law of cosines of Wooten eq. 7.5 puts the hips above the ankles, which for a deep
knee bend needs more ankle dorsiflexion than a human has (the woman's short shank needs ~75
degrees at 0.47 m); a person leans the trunk forward instead. This solves that pose on the
model's own kinematics (MuJoCo), like Ooi's sampling of balanced crouch poses (§3.4.2.1), once
per behaviour for a table of heights; controllers interpolate it.
"""
from __future__ import annotations

import math

import mujoco
import numpy as np

from ..character.spec import CharacterSpec
from .actor import ActorView
from ..schema import Schema
from ..tuned.constants import constant, read_constants, register_constants

# the crouch's hand-set constants: data, crouch_any.json's "constants" (docs/tables.md)
CROUCH_CONSTANTS = Schema(
    constant("dorsiflexion_use", "1", 0.0, 1.0, "share of the ankle's dorsiflexion range a crouch may use"),
    constant("arm_reach_per_depth", "rad", 0.0, 10.0,
             "forward arm raise per unit of relative crouch depth: people reach forward to counterbalance a deep squat"),
    constant("arm_reach_max", "rad", 0.0, 3.2, "the forward arm raise of a crouch is at most this"),
)
register_constants("crouch", CROUCH_CONSTANTS)
CONSTANTS = read_constants("crouch", CROUCH_CONSTANTS)



def arm_reach(height: float, standing_height: float) -> float:
    """Forward arm flexion that goes with a crouch to this pelvis height."""
    depth = max(0.0, (standing_height - height) / standing_height)
    return min(CONSTANTS.arm_reach_max, CONSTANTS.arm_reach_per_depth * depth)


class CrouchTable:
    def __init__(self, model: mujoco.MjModel, character: CharacterSpec, heights: np.ndarray,
                 standing_height: float, com_offset: float = 0.0, actor: ActorView | None = None):
        """``actor``: the character's part of the model (default: the model's only character);
        the poses are measured in its foot's frame, wherever it stands."""
        self.model, self.character = model, character
        actor = actor or ActorView.of(model)
        self.com_offset = com_offset
        self.data = mujoco.MjData(model)
        self.base_qpos = np.zeros(model.nq)
        for joint in np.nonzero(model.jnt_type == mujoco.mjtJoint.mjJNT_FREE)[0]:
            self.base_qpos[model.jnt_qposadr[joint] + 3] = 1.0       # every root at the origin, upright
        for i, dof in enumerate(character.dofs):
            self.base_qpos[actor.joint_qposadr(dof.name)] = character.standing_pose[i]
        jnt = actor.joint_qposadr
        self.adr = {n: jnt(n) for n in ("knee_r_y", "knee_l_y", "hip_r_y", "hip_l_y", "ankle_r_y", "ankle_l_y")}
        self.foot = actor.body_id("FOOTR")
        self.pelvis = actor.body_id("PELVIS")
        self.hips = (actor.body_id("ULEGR"), actor.body_id("ULEGL"))
        ankle = character.joint_position("FOOTR")
        self.ankle_height = float(ankle[2])
        sites = [c["pos"] for c in character.body("FOOTR")["contacts"] + character.body("TOER")["contacts"]]
        self.centre_from_ankle = 0.5 * (max(p[0] for p in sites) + min(p[0] for p in sites)) - float(ankle[0])
        lo = character.dofs[character.dof_index["ankle_r_y"]].range[0]
        self.ankle_min = CONSTANTS.dorsiflexion_use * lo
        self.standing_height = standing_height
        self.shoulders = [(jnt(f"shoulder_{side}_z"), sign) for side, sign in (("r", 1.0), ("l", -1.0))]
        self.heights = np.asarray(heights, dtype=float)
        rows = [self.solve(h) for h in self.heights]                 # knee, hip_y, ankle_y, pelvis_pitch
        self.table = np.array([(*row, self.leg_length(*row[:3])) for row in rows])   # + hip-ankle distance

    def measure(self, knee: float, hip: float, ankle: float) -> tuple[float, float, float]:
        """(pelvis height, COM offset from the centre of the feet, pelvis pitch) of a pose."""
        d, a = self.data, self.adr
        d.qpos[:] = self.base_qpos
        for side in "rl":
            d.qpos[a[f"knee_{side}_y"]] = knee
            d.qpos[a[f"hip_{side}_y"]] = hip
            d.qpos[a[f"ankle_{side}_y"]] = ankle
        reach = arm_reach(self._height, self.standing_height)
        for adr, sign in self.shoulders:
            d.qpos[adr] = sign * reach
        mujoco.mj_kinematics(self.model, d)
        mujoco.mj_comPos(self.model, d)
        rot = d.xmat[self.foot].reshape(3, 3)
        origin = d.xpos[self.foot]
        hip_mid = 0.5 * (d.xpos[self.hips[0]] + d.xpos[self.hips[1]])
        height = float((rot.T @ (hip_mid - origin))[2]) + self.ankle_height
        com_x = float((rot.T @ (d.subtree_com[self.pelvis] - origin))[0]) - self.centre_from_ankle
        pelvis = rot.T @ d.xmat[self.pelvis].reshape(3, 3)
        pitch = math.atan2(-pelvis[2, 0], pelvis[2, 2])
        return height, com_x, pitch

    def solve(self, height: float) -> tuple[float, float, float, float]:
        """(knee, hip_y, ankle_y, pelvis_pitch) for this pelvis height, COM over the centre of
        the feet (or ``com_offset`` m ahead of it, behind if negative), the pelvis as upright as the usable ankle dorsiflexion allows. Nested
        bisections: the hip height depends only on ankle and knee, the COM also on the hip."""
        self._height = height
        knee_max = self.character.dofs[self.character.dof_index["knee_r_y"]].range[1]
        hip_lo, hip_hi = self.character.dofs[self.character.dof_index["hip_r_y"]].range

        def knee_for(ankle):
            return _bisect(lambda k: self.measure(k, 0.0, ankle)[0] - height, 0.0, knee_max, decreasing=True)

        def hip_for(knee, ankle):
            # flexing the hip (more negative) moves the COM forward
            return _bisect(lambda h: self.measure(knee, h, ankle)[1] - self.com_offset, hip_lo, hip_hi, decreasing=True)

        def pose(ankle):
            knee = knee_for(ankle)
            if abs(self.measure(knee, 0.0, ankle)[0] - height) > 1e-3:   # definition: the solve's 1 mm tolerance
                return knee, 0.0, ankle, -math.inf      # legs leaning too far to reach this height
            hip = hip_for(knee, ankle)
            return knee, hip, ankle, self.measure(knee, hip, ankle)[2]

        # more dorsiflexion (ankle more negative) lets the trunk stand more upright
        most = pose(self.ankle_min)
        if most[3] > 0.0:                     # even the usable dorsiflexion leaves a forward lean
            return most
        ankle = _bisect(lambda a: pose(a)[3], self.ankle_min, 0.0, decreasing=False)
        result = pose(ankle)
        if not math.isfinite(result[3]):            # the height is out of reach: straightest legs
            knee = knee_for(0.0)
            result = (knee, 0.0, 0.0, self.measure(knee, 0.0, 0.0)[2])
        return result

    def leg_length(self, knee: float, hip: float, ankle: float) -> float:
        """Distance from the mid-hip point to the ankles in a pose: what the knees control,
        whatever the body's lean (a slope, a push)."""
        self.measure(knee, hip, ankle)
        d = self.data
        hip_mid = 0.5 * (d.xpos[self.hips[0]] + d.xpos[self.hips[1]])
        dx, _, dz = hip_mid - d.xpos[self.foot]          # sagittal plane: the pose is symmetric
        return float(math.hypot(dx, dz))

    def at(self, height: float) -> np.ndarray:
        """Interpolated (knee, hip_y, ankle_y, pelvis_pitch, leg_length) for a height in the table."""
        return np.array([np.interp(height, self.heights, self.table[:, k]) for k in range(5)])  # definition: the 5 columns


def _bisect(f, lo: float, hi: float, decreasing: bool, iterations: int = 15) -> float:  # definition: 15 halvings
    """Root of a monotonic f on [lo, hi] (the nearer end if f does not change sign there)."""
    sign = -1.0 if decreasing else 1.0
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        if sign * f(mid) > 0.0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)
