"""Balance (Wooten ch. 7): stand, bend the knees, pitch the torso, shift the COM.

The COM is servoed over the centre of the support polygon by offsets to the ankle and hip
targets (eqs. 7.1-7.2; hip offsets half the ankle's, opposite sign); the ankles keep the feet
flat (7.3-7.4); the knees set the pelvis height by the law of cosines (7.5) and the hips hold
the pelvis attitude (the role of 7.6). Everything is measured in the character's heading frame
with "up" opposite to gravity, so it also stands on a tilted ground.

A request is a timeline: stand until ``move_start``, move the posture (pelvis height, torso
pitch, COM offset) along a Hermite curve over ``move_time``, hold for ``hold_time``, and, if
``return_to_stand``, move back to standing over ``move_time``.
"""
from __future__ import annotations

import math

import numpy as np

from sim_core.control.behaviour import Behaviour, ControlContext, register
from sim_core.control.measure import SupportGeometry, pitch_of, roll_of, yaw_of
from sim_core.control.servo import hermite_blend
from sim_core.errors import ParameterError
from sim_core.schema import Parameter, Schema

SPINE_Y = ("spine_l3_y", "spine_l1_y", "spine_t7_y", "spine_t4_y")
SPINE_SHARE = 0.25           # share of the torso pitch taken by the spine (the rest by the hips)
STANDING_KNEE_FLEX = 0.10    # rad: knees are never locked straight (law of cosines is singular there)
CROUCH_LEAN = 0.3          # pelvis pitch per radian of knee flexion: lean into a crouch to keep
                           # the COM over the feet when the ankles reach their dorsiflexion limit
HIP_SHARE = 0.5             # hip offset per ankle offset (eqs. 7.1-7.2: half the ankle's)


class LegGeometry:
    """Planar leg lengths and the rest-pose knee flexion of one side (for eq. 7.5)."""

    def __init__(self, character, side: str):
        hip = character.joint_position("ULEG" + side)
        knee = character.joint_position("LLEG" + side)
        ankle = character.joint_position("FOOT" + side)
        thigh, shank = knee - hip, ankle - knee
        self.upper = float(np.linalg.norm(thigh[[0, 2]]))
        self.lower = float(np.linalg.norm(shank[[0, 2]]))
        # geometric flexion already present at zero joint angle (shank leaning back of the thigh)
        self.rest_flex = math.atan2(-shank[0], -shank[2]) - math.atan2(-thigh[0], -thigh[2])
        self.ankle_height = float(ankle[2])
        self.hip_height = float(hip[2])

    def knee_angle_for(self, hip_to_ankle: float) -> float:
        """Eq. 7.5: knee joint angle that puts hip and ankle ``hip_to_ankle`` apart."""
        u, l = self.upper, self.lower
        c = (u * u + l * l - hip_to_ankle * hip_to_ankle) / (2 * u * l)
        flex = math.pi - math.acos(max(-1.0, min(1.0, c)))
        return flex - self.rest_flex

    def standing_hip_height(self) -> float:
        u, l = self.upper, self.lower
        flex = STANDING_KNEE_FLEX + self.rest_flex
        return self.ankle_height + math.sqrt(u * u + l * l + 2 * u * l * math.cos(flex))

    def lowest_hip_height(self, knee_limit: float) -> float:
        u, l = self.upper, self.lower
        flex = knee_limit + self.rest_flex
        return self.ankle_height + math.sqrt(max(u * u + l * l + 2 * u * l * math.cos(flex), 0.0))


@register
class Balance(Behaviour):
    name = "balance"
    summary = "Stand balanced; bend the knees, pitch the torso or shift the COM, and come back (Wooten ch. 7)."
    default_duration = 5.0
    schema = Schema(
        Parameter("pelvis_height", "m", 0.0, 0.30, 1.20,
                  "height of the mid-hip point above the ground to move to; 0 = standing height", special=0.0),
        Parameter("torso_pitch", "rad", 0.0, -0.35, 1.75,
                  "forward pitch of the upper body from vertical (hips take 75 %, the spine 25 %)"),
        Parameter("com_offset_x", "m", 0.0, -0.25, 0.25,
                  "desired COM offset forward of the centre of the support polygon (heading frame)"),
        Parameter("com_offset_y", "m", 0.0, -0.20, 0.20,
                  "desired COM offset to the left of the centre of the support polygon"),
        Parameter("move_start", "s", 0.5, 0.0, 600.0, "time to start moving to the requested posture"),
        Parameter("move_time", "s", 1.5, 0.2, 20.0, "duration of the Hermite move there (and back)"),
        Parameter("hold_time", "s", 1.0, 0.0, 600.0, "time to hold the posture before returning"),
        Parameter("return_to_stand", "bool", 1.0, 0.0, 1.0, "1 = return to standing after the hold"),
        Parameter("arm_abduction", "rad", 0.0, -0.5, 1.5, "extra sideways raise of both arms"),
        Parameter("arm_flexion", "rad", 0.0, -0.8, 2.5,
                  "forward raise of both arms from hanging (they follow the torso pitch)"),
        Parameter("elbow_flexion", "rad", 0.2, 0.0, 2.4, "elbow bend of both arms"),
        Parameter("head_pitch", "rad", 0.0, -0.8, 0.8, "head nod forward (+) or back (-)"),
        Parameter("com_kp", "rad/m", 4.0, 0.0, 20.0, "COM servo stiffness: ankle offset per metre of COM error (eq. 7.1)"),
        Parameter("com_kv", "rad s/m", 0.8, 0.0, 5.0, "COM servo damping: ankle offset per m/s of COM speed (eq. 7.1)"),
        Parameter("height_kp", "rad/m", 10.0, 0.0, 20.0,
                  "pelvis height servo: knee offset per metre of height error (corrects servo sag)"),
    )

    def __init__(self, params, ctx: ControlContext):
        super().__init__(params, ctx)
        ch = ctx.character
        m = ctx.model
        self.legs = {s: LegGeometry(ch, s) for s in "RL"}
        self.support = SupportGeometry(m)
        s = ctx.servos
        self.i = {n: s.index[n] for n in s.names}
        self.pelvis = m.body("PELVIS").id
        self.feet = [m.body("FOOTR").id, m.body("FOOTL").id]
        self.hips = [m.body("ULEGR").id, m.body("ULEGL").id]
        self.spine_idx = s.indices(SPINE_Y)
        self.base = ch.standing_pose.copy()
        self.damping_ratio = s.default_kv / s.default_kp
        self.total_mass = float(m.body_subtreemass[self.pelvis])
        self.stand_height = 0.5 * (self.legs["R"].standing_hip_height() + self.legs["L"].standing_hip_height())
        self.posture_from = None
        self.up = np.array([0.0, 0.0, 1.0])

    # ----------------------------------------------------------------- requests
    def target_posture(self) -> np.ndarray:
        p = self.params
        height = p["pelvis_height"] or self.stand_height
        return np.array([height, p["torso_pitch"], p["com_offset_x"], p["com_offset_y"]])

    def standing_posture(self) -> np.ndarray:
        return np.array([self.stand_height, 0.0, 0.0, 0.0])

    def check_feasible(self) -> None:
        knee_max = self.ctx.character.dofs[self.ctx.character.dof_index["knee_r_y"]].range[1]
        lowest = max(leg.lowest_hip_height(knee_max) for leg in self.legs.values())
        h = self.params["pelvis_height"]
        if h and not lowest <= h <= self.stand_height:
            raise ParameterError(
                f"parameter pelvis_height={h:g} m is out of reach for {self.ctx.character.name}; "
                f"allowed range is [{lowest:.3f}, {self.stand_height:.3f}] m (or 0 for standing)")

    def posture(self, t: float) -> np.ndarray:
        p = self.params
        stand, goal = self.standing_posture(), self.target_posture()
        t1 = p["move_start"]
        t2 = t1 + p["move_time"]
        t3 = t2 + p["hold_time"]
        if t < t1:
            return stand
        if t < t2 or not p["return_to_stand"]:
            return stand + (goal - stand) * float(hermite_blend(np.array((t - t1) / p["move_time"])))
        if t < t3:
            return goal
        return goal + (stand - goal) * float(hermite_blend(np.array((t - t3) / p["move_time"])))

    def start(self, t: float) -> None:
        self.up = -self.ctx.model.opt.gravity / np.linalg.norm(self.ctx.model.opt.gravity)
        self.ctx.servos.hold(self.joint_targets(self.standing_posture()), t)
        self.event(t, "stand")
        p = self.params
        self.event(p["move_start"], "move")
        self.event(p["move_start"] + p["move_time"], "hold")
        if p["return_to_stand"]:
            self.event(p["move_start"] + p["move_time"] + p["hold_time"], "return")

    # ----------------------------------------------------------------- control law
    def joint_targets(self, posture: np.ndarray) -> np.ndarray:
        """Nominal joint targets for a posture (before the balance feedback)."""
        height, torso_pitch = posture[0], posture[1]
        q = self.base.copy()
        i, p = self.i, self.params
        for side in "RL":
            leg = self.legs[side]
            s = side.lower()
            q[i[f"knee_{s}_y"]] = leg.knee_angle_for(height - leg.ankle_height)
        q[self.spine_idx] = torso_pitch * SPINE_SHARE / len(SPINE_Y)
        mirror = {"r": 1.0, "l": -1.0}
        for s, sign in mirror.items():
            q[i[f"shoulder_{s}_x"]] = self.base[i[f"shoulder_{s}_x"]] - sign * p["arm_abduction"]
            q[i[f"shoulder_{s}_z"]] = sign * (p["arm_flexion"] + torso_pitch)   # arms keep hanging
            q[i[f"elbow_{s}_z"]] = sign * p["elbow_flexion"]
        q[i["neck_c2_y"]] = p["head_pitch"]
        return q

    def update(self, t: float) -> None:
        d, m, i = self.ctx.data, self.ctx.model, self.i
        servos = self.ctx.servos
        posture = self.posture(t)
        targets = self.joint_targets(posture)
        up = self.up

        # heading frame of the pelvis
        yaw = yaw_of(d.xmat[self.pelvis])
        c, s = math.cos(yaw), math.sin(yaw)
        com = d.subtree_com[self.pelvis]
        com_vel = d.subtree_linvel[self.pelvis]
        points = self.support.points(d)
        touching = points[:, 2] < self.support.contact_height
        pts = points[touching] if touching.any() else points
        # project COM along gravity onto the ground plane z = 0
        com_ground = com[:2] - com[2] * up[:2] / up[2]
        local_pts_x = c * pts[:, 0] + s * pts[:, 1]
        local_pts_y = -s * pts[:, 0] + c * pts[:, 1]
        centre = np.array([(local_pts_x.min() + local_pts_x.max()) / 2, (local_pts_y.min() + local_pts_y.max()) / 2])
        com_local = np.array([c * com_ground[0] + s * com_ground[1], -s * com_ground[0] + c * com_ground[1]])
        vel_local = np.array([c * com_vel[0] + s * com_vel[1], -s * com_vel[0] + c * com_vel[1]])
        kp, kv = self.params["com_kp"], self.params["com_kv"]
        delta_x = kp * (com_local[0] - centre[0] - posture[2]) + kv * vel_local[0]     # eq. 7.1
        delta_y = kp * (com_local[1] - centre[1] - posture[3]) + kv * vel_local[1]     # eq. 7.2

        offset = servos.offset
        offset[:] = 0.0
        angles = servos.angles()
        velocities = servos.velocities()
        knee_flex = 0.5 * (targets[i["knee_r_y"]] + targets[i["knee_l_y"]]) - STANDING_KNEE_FLEX
        pelvis_pitch_goal = posture[1] * (1.0 - SPINE_SHARE) + CROUCH_LEAN * knee_flex
        pelvis_pitch = pitch_of(d.xmat[self.pelvis], up)
        hip_height = 0.5 * (d.xpos[self.hips[0], 2] + d.xpos[self.hips[1], 2])
        knee_offset = self.params["height_kp"] * (hip_height - posture[0])
        for k, side in enumerate("rl"):
            offset[i[f"knee_{side}_y"]] = knee_offset
            foot = d.xmat[self.feet[k]]
            # ankles keep the feet flat (7.3-7.4) plus the COM servo offset
            ay, ax = i[f"ankle_{side}_y"], i[f"ankle_{side}_x"]
            targets[ay] = angles[ay] - pitch_of(foot, up)
            targets[ax] = angles[ax] - roll_of(foot, up)
            # the servo's damping acts on the ankle rate; shift it onto the foot's own rate so it
            # does not drag the foot along when the shank rotates over it
            foot_rate = d.cvel[self.feet[k], :3]
            frame = foot.reshape(3, 3)
            offset[ay] = delta_x + self.damping_ratio[ay] * (velocities[ay] - float(foot_rate @ frame[:, 1]))
            offset[ax] = -delta_y + self.damping_ratio[ax] * (velocities[ax] - float(foot_rate @ frame[:, 0]))
            # hips hold the pelvis attitude; hip offsets are half the ankle's, opposite sign
            hy, hx = i[f"hip_{side}_y"], i[f"hip_{side}_x"]
            targets[hy] = angles[hy] + (pelvis_pitch - pelvis_pitch_goal)
            offset[hy] = HIP_SHARE * delta_x
            offset[hx] = -HIP_SHARE * delta_y
        servos.hold(targets, t)
