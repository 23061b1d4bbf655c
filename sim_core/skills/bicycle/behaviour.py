"""Bicycling (Hodgins et al. 1995, "Bicycling"; SEEDS-WAVE2.md §1).

The rider sits on the bicycle prop (sim_core.world.bicycle): the pelvis on the saddle by a
passive pivot about the lateral axis, the hands on the grips and the feet on the pedals by
two-sided soft attachments (equality constraints between rider and bicycle bodies, never to the
world). The run starts mounted and rolling at the commanded speed (a named start state,
``start_state``: the rider posed by inverse kinematics, everything moving at the speed, the
wheels rolling and the crank turning at v/(r g)).

Control, every tick (laws.py for the equations):
  * speed: crank torque by eq. 7 (sign-fixed), split between the legs by crank angle (eqs.
    8-10), each leg's tangential pedal force turned into hip, knee and ankle torques through
    the leg's Jacobian at the foot's site (``mj_jacSite``: tau = J^T f), added to the servos as
    offsets (tau / kp);
  * the legs follow the pedals: inverse kinematics of each foot to where its pedal will be one
    servo lag ahead, with the servo's damping fed the target's velocity (so the PD follows the
    crank instead of braking it);
  * steering: eq. 11 gives the fork angle; inverse kinematics puts the hands on the grips of a
    fork turned to it; the arms' servos steer the bicycle through the hand springs ([A] 142);
  * waist, neck and wrists hold their mounted angles ([A] 144).
"""
from __future__ import annotations

import math

import mujoco
import numpy as np

from ...control.behaviour import Behaviour, register
from ...schema import Parameter, Schema
from ...world.bicycle import CRANK_LENGTH, DEFAULT_GEAR, Bicycle, BicycleView
from .laws import ankle_angle, crank_torque, fork_angle, pedal_forces
from .mount import SitePairs, match_velocities, solve

# the rider's reference posture for the mounting solve (rad): hips and knees bent, arms forward
MOUNT_POSTURE = {"hip_r_y": -1.0, "hip_l_y": -1.0, "knee_r_y": 1.3, "knee_l_y": 1.3,
                 "shoulder_r_x": 0.3, "shoulder_l_x": -0.3, "shoulder_r_y": -1.0, "shoulder_l_y": -1.0,
                 "elbow_r_z": 0.5, "elbow_l_z": -0.5, "ankle_r_y": 0.3, "ankle_l_y": 0.3}
MOUNT_CRANK_ANGLE = math.pi / 2      # the start's crank: right pedal forward, left back (horizontal)
LEG_JOINTS = {"r": ("hip_r_y", "knee_r_y"), "l": ("hip_l_y", "knee_l_y")}
ANKLE_JOINTS = {"r": "ankle_r_y", "l": "ankle_l_y"}
ARM_JOINTS = {"r": ("shoulder_r_x", "shoulder_r_y", "shoulder_r_z", "elbow_r_y", "elbow_r_z"),
              "l": ("shoulder_l_x", "shoulder_l_y", "shoulder_l_z", "elbow_l_y", "elbow_l_z")}
# hand-set gains (not yet calibrated; to become a tuned table): eq. 7 in N m per m/s, eq. 11's at
# REFERENCE_SPEED (the roll terms scale with (v_ref / v)^2, as the steer needed to right a lean does)
RIDE_GAINS = {"speed": 500.0, "roll": 2.0, "roll_rate": 0.4, "yaw": 0.6, "yaw_rate": 0.3}
REFERENCE_SPEED = 4.0
MAX_FORK_ANGLE = 0.5                 # rad: the commanded fork angle's limit
IK_ITERATIONS_PER_TICK = 3


@register
class Bicycling(Behaviour):
    name = "bicycle"
    summary = "Ride the bicycle at a commanded speed and heading (Hodgins et al. 1995)."
    schema = Schema(
        Parameter("speed", "m/s", 4.0, 1.0, 8.0, "commanded forward speed (also the rolling start's)"),
        Parameter("heading", "deg", 0.0, -180.0, 180.0, "commanded heading, counter-clockwise from the start's"),
        Parameter("gear", "1", DEFAULT_GEAR, 0.5, 5.0, "wheel turns per crank turn (fixed gear)"),
    )
    default_duration = 10.0

    @classmethod
    def scene(cls, params, world, character=None):
        import dataclasses
        return dataclasses.replace(world, bicycle=Bicycle(gear=params["gear"], rider=""))

    @classmethod
    def start_state(cls, params, model, data, character):
        """Mounted and rolling: the rider's root and joints solved so that the seat bones sit on
        the saddle and the palms and balls of the feet on the grips and pedals (crank
        horizontal), then the rolling start at the commanded speed."""
        bike = BicycleView.of(model)
        bike.set_crank(data, MOUNT_CRANK_ANGLE)
        mujoco.mj_kinematics(model, data)
        pairs = SitePairs(model)
        root = model.joint("root")
        adr = int(root.qposadr[0])
        seat_mid = data.site_xpos[pairs.rider[:2]].mean(axis=0)
        saddle = data.site_xpos[pairs.bike[:2]].mean(axis=0)
        data.qpos[adr:adr + 3] += saddle - seat_mid
        reference = data.qpos.copy()
        for name, value in MOUNT_POSTURE.items():
            reference[model.joint(name).qposadr[0]] = value
        data.qpos[:] = reference
        dofs = np.arange(int(root.dofadr[0]), model.nv)
        rider_dofs = dofs[model.body_rootid[model.dof_bodyid[dofs]] == model.jnt_bodyid[root.id]]
        every = list(range(len(pairs.names)))
        solve(model, data, pairs, every, rider_dofs, reference, iterations=300)
        gaps = solve(model, data, pairs, every, rider_dofs, data.qpos.copy(), iterations=50, posture_weight=0.0)
        bike.rolling_start(data, params["speed"])
        dof = int(root.dofadr[0])
        data.qvel[dof:dof + 3] = data.qvel[bike.free_dof:bike.free_dof + 3]
        match_velocities(model, data, pairs, rider_dofs)
        return {"mounted": True, "rolling_speed": params["speed"], "crank_angle": MOUNT_CRANK_ANGLE,
                "attachment_gaps": {n: float(g) for n, g in zip(pairs.names, gaps)}}

    def start(self, t):
        """Look the bicycle and the limbs up; the targets start at the mounted pose."""
        ctx = self.ctx
        model, servos = ctx.model, ctx.servos
        self.target = servos.angles().copy()
        self.bike = BicycleView.of(model)
        self.pairs = SitePairs(model, ctx.actor.prefix)
        self.scratch = mujoco.MjData(model)
        self.desired_yaw = math.radians(self.params["heading"]) + self.bike.state(ctx.data)["yaw"]
        self.leg_servos = {side: servos.indices(names) for side, names in LEG_JOINTS.items()}
        self.arm_servos = {side: servos.indices(names) for side, names in ARM_JOINTS.items()}
        self.ankle_servos = {side: servos.indices([name])[0] for side, name in ANKLE_JOINTS.items()}
        self.limb_servos = np.concatenate([*self.leg_servos.values(), *self.arm_servos.values()])
        self.limb_dofs = servos.dof_adr[self.limb_servos]
        self.leg_dofs = {side: servos.dof_adr[i] for side, i in self.leg_servos.items()}
        self.kp = servos.default_kp
        self.lag = servos.default_kv / servos.default_kp          # s: a PD servo's lag behind its target
        self.previous_ik = None
        self.fork_command = 0.0
        self.jac = np.zeros((3, model.nv))

    def update(self, t):
        """Eq. 11 -> fork command -> arm IK; pedal IK and ankle curve -> leg targets; eqs. 7-10
        -> pedal forces -> leg torques (servo offsets)."""
        ctx, servos, bike = self.ctx, self.ctx.servos, self.bike
        model, data = ctx.model, ctx.data
        state = bike.state(data)
        g = RIDE_GAINS
        scale = (REFERENCE_SPEED / max(state["speed"], 1.0)) ** 2
        fork = fork_angle(state["roll"], state["roll_rate"], state["yaw"], state["yaw_rate"], self.desired_yaw,
                          g["roll"] * scale, g["roll_rate"] * scale, g["yaw"], g["yaw_rate"])
        self.fork_command = min(max(fork, -MAX_FORK_ANGLE), MAX_FORK_ANGLE)
        # where the limbs should be: the feet on the pedals as they are, the hands on a fork at its command
        scratch = self.scratch
        scratch.qpos[:] = data.qpos
        scratch.qpos[bike.steer_qpos] = self.fork_command
        ankles = {"r": ankle_angle(state["crank"]), "l": ankle_angle(state["crank"] + math.pi)}
        for side, value in ankles.items():
            scratch.qpos[servos.qpos_adr[self.ankle_servos[side]]] = value
        solve(model, scratch, self.pairs, [2, 3, 4, 5], self.limb_dofs, data.qpos, IK_ITERATIONS_PER_TICK)
        goal = self.target.copy()
        ik = scratch.qpos[servos.qpos_adr[self.limb_servos]]
        velocity = np.zeros_like(ik) if self.previous_ik is None else (ik - self.previous_ik) / ctx.control_dt
        self.previous_ik = ik.copy()
        goal[self.limb_servos] = ik + self.lag[self.limb_servos] * velocity
        for side, value in ankles.items():
            goal[self.ankle_servos[side]] = value
        # eqs. 7-10: pedal forces, through each leg's Jacobian to joint torques (servo offsets)
        torque = crank_torque(state["speed"], self.params["speed"], g["speed"])
        forces = dict(zip("rl", pedal_forces(torque, state["crank"], CRANK_LENGTH)))
        offset = np.zeros(len(goal))
        axle = data.xpos[bike.crank_body]
        crank_axis = data.xmat[bike.crank_body].reshape(3, 3)[:, 1]
        for k, side in ((4, "r"), (5, "l")):
            site = self.pairs.rider[k]
            arm = data.site_xpos[self.pairs.bike[k]] - axle
            tangent = np.cross(crank_axis, arm)
            tangent /= np.linalg.norm(tangent)
            mujoco.mj_jacSite(model, data, self.jac, None, site)
            tau = self.jac[:, self.leg_dofs[side]].T @ (forces[side] * tangent)
            idx = self.leg_servos[side]
            offset[idx] = tau / self.kp[idx]
        servos.offset[:] = offset
        servos.hold(goal, t)

    @classmethod
    def assess(cls, trajectory):
        from .assess import ride_metrics
        metrics = ride_metrics(trajectory)
        return ("success" if not metrics["fell"] else "fell"), metrics
