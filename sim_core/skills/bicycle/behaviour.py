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

import dataclasses
import math

import mujoco
import numpy as np

from ...control.behaviour import Behaviour, register
from ...control.path import MAX_POINTS, PathFollower, validate_path
from ...schema import Parameter, Points, Schema
from ...tuned import TableType, load, register as register_table
from ...tuned.settings import SkillSchema, with_defaults
from ...errors import ParameterError
from ...world.bicycle import CRANK_LENGTH, DEFAULT_GEAR, NAMES, Bicycle, BicycleView
from .course import COURSE, course_for
from .steering import steering_gains
from .laws import ankle_angle, crank_torque, fork_angle, lean_ahead, pedal_forces
from .mount import IK_ITERATIONS_PER_TICK, SitePairs, match_velocities, solve

RIDERS = ("man",)                   # criterion: the riders measured to ride (docs/bicycle.md: the others fall)
MIN_LOOKAHEAD_SPEED = 1.0           # definition: m/s, the speed below which the look-ahead distance stops shrinking
MOUNT_CRANK_ANGLE = math.pi / 2      # the start's crank: right pedal forward, left back (horizontal)
LEG_JOINTS = {"r": ("hip_r_y", "knee_r_y"), "l": ("hip_l_y", "knee_l_y")}
ANKLE_JOINTS = {"r": "ankle_r_y", "l": "ankle_l_y"}
ARM_JOINTS = {"r": ("shoulder_r_x", "shoulder_r_y", "shoulder_r_z", "elbow_r_y", "elbow_r_z"),
              "l": ("shoulder_l_x", "shoulder_l_y", "shoulder_l_z", "elbow_l_y", "elbow_l_z")}


# the constants of the bicycling laws: their values are data (bicycle_any.json "constants", the
# defaults below are replaced by them); each range is a sanity bound a table row is checked against
BICYCLE_RANGES = Schema(
    Parameter("speed_gain", "N m s/m", 0.0, 0.0, 5000.0, "eq. 7 k_v: crank torque per m/s of speed error"),
    Parameter("max_crank_torque", "N m", 0.0, 0.0, 1000.0, "limit of eq. 7's crank torque, driving or braking (a rider's strength)"),
    Parameter("ik_velocity_filter", "s", 0.0, 0.0, 0.5, "time constant of the low-pass on the limb targets' velocity that leads the servos (0: unfiltered)"),
    Parameter("speed_ramp", "m/s^2", 0.1, 0.1, 10.0, "eq. 7's desired speed moves to a newly commanded one at this rate (a start, a speed step)"),
    Parameter("roll_gain", "1", 0.0, 0.0, 20.0, "eq. 11 k_alpha at reference_speed"),
    Parameter("roll_rate_gain", "s", 0.0, 0.0, 5.0, "eq. 11 k_alpha-dot at reference_speed"),
    Parameter("yaw_gain", "1", 0.0, 0.0, 10.0, "eq. 11 k_beta at reference_speed"),
    Parameter("yaw_rate_gain", "s", 0.0, 0.0, 5.0, "eq. 11 k_beta-dot at reference_speed"),
    Parameter("lean_feedforward", "1", 0.0, 0.0, 1.0, "share of a steady turn's lean (tan = v^2 kappa / g) asked for ahead of a path's curve (0: the seed's eq. 11)"),
    Parameter("curvature_preview", "s", 0.0, 0.0, 3.0, "the path's curvature is read this many seconds of travel ahead"),
    Parameter("reference_speed", "m/s", 0.5, 0.5, 10.0, "speed at which the four steering gains are these (steering.py scales them with speed)"),
    Parameter("max_fork_angle", "rad", 0.0, 0.0, 1.0, "limit of the commanded fork angle"),
    Parameter("ankle_mean", "rad", -0.7, -0.7, 0.87, "ankle curve: mean plantarflexion over a crank turn"),
    Parameter("ankle_swing", "rad", 0.0, 0.0, 0.5, "ankle curve: half its range"),
    Parameter("ankle_phase", "rad", -math.pi, -math.pi, math.pi, "ankle curve: crank angle past top dead centre of the least plantarflexion"),
    Parameter("mount_hip", "rad", -2.18, -2.18, 0.52, "mounting posture: hip flexion (negative)"),
    Parameter("mount_knee", "rad", 0.0, 0.0, 2.62, "mounting posture: knee flexion"),
    Parameter("mount_shoulder_x", "rad", -1.57, -1.57, 1.75, "mounting posture: right shoulder x (left mirrored)"),
    Parameter("mount_shoulder_y", "rad", -1.57, -1.57, 1.57, "mounting posture: shoulder y (arms forward)"),
    Parameter("mount_elbow_z", "rad", 0.0, 0.0, 2.62, "mounting posture: right elbow z (left mirrored)"),
    Parameter("mount_ankle", "rad", -0.7, -0.7, 0.87, "mounting posture: ankle plantarflexion"),
)


def _bicycle_rows(body: dict):
    yield "constants", body["constants"]


def bicycle_constants(character: str = "any") -> dict:
    """The constants of the bicycling laws: bicycle_any.json's for every rider (no per-character
    table yet)."""
    return load("bicycle", "any")["constants"]



BICYCLE_TABLE = register_table(TableType("bicycle", BICYCLE_RANGES, _bicycle_rows, (bicycle_constants,)))
BICYCLE_SETTINGS = with_defaults(BICYCLE_RANGES, bicycle_constants())


def mount_posture(c: dict) -> dict[str, float]:
    """The rider's reference posture for the mounting solve, both sides, from the constants."""
    return {"hip_r_y": c["mount_hip"], "hip_l_y": c["mount_hip"], "knee_r_y": c["mount_knee"],
            "knee_l_y": c["mount_knee"], "shoulder_r_x": c["mount_shoulder_x"], "shoulder_l_x": -c["mount_shoulder_x"],
            "shoulder_r_y": c["mount_shoulder_y"], "shoulder_l_y": c["mount_shoulder_y"],
            "elbow_r_z": c["mount_elbow_z"], "elbow_l_z": -c["mount_elbow_z"],
            "ankle_r_y": c["mount_ankle"], "ankle_l_y": c["mount_ankle"]}


@register
class Bicycling(Behaviour):
    name = "bicycle"
    summary = "Ride the bicycle at a commanded speed and heading (Hodgins et al. 1995)."
    settings_schema = BICYCLE_SETTINGS
    schema = SkillSchema(
        Parameter("speed", "m/s", 4.0, 1.0, 8.0, "commanded forward speed (also the rolling start's)"),
        Parameter("heading", "rad", 0.0, -math.pi, math.pi, "commanded heading, counter-clockwise from the start's"),
        Parameter("gear", "1", DEFAULT_GEAR, 0.5, 5.0, "wheel turns per crank turn (fixed gear)"),
        COURSE,
        Parameter("turn_angle", "rad", math.pi / 2, -math.pi, math.pi, "turn: angle of the turn (left positive)"),
        Parameter("turn_radius", "m", 15.0, 3.0, 100.0, "turn: radius of the turn"),
        Parameter("turn_after", "m", 10.0, 2.0, 200.0, "turn, slalom: distance ridden straight before the turn or the gates"),
        Parameter("gate_count", "count", 8, 1, 30, "slalom: number of gates"),
        Parameter("gate_spacing", "m", 10.0, 4.0, 40.0, "slalom: distance along the course from one gate to the next"),
        Parameter("gate_offset", "m", 1.0, 0.2, 3.0, "slalom: each gate's centre this far left, then right, of the start line"),
        Parameter("gate_width", "m", 1.5, 0.5, 5.0, "slalom: distance between a gate's two poles"),
        Parameter("step_time", "s", 15.0, 2.0, 100.0, "speed_steps: time of each step (speed, then second_speed, then third_speed)"),
        Parameter("second_speed", "m/s", 5.0, 1.0, 8.0, "speed_steps: the speed commanded from step_time"),
        Parameter("third_speed", "m/s", 4.0, 1.0, 8.0, "speed_steps: the speed commanded from twice step_time"),
        Parameter("hill_grade", "1", 0.05, 0.0, 0.12, "hill: rise over run of the climb and the descent (0.05 = 5 %)"),
        Parameter("hill_after", "m", 10.0, 0.0, 200.0, "hill: flat ground before the climb"),
        Parameter("hill_length", "m", 40.0, 5.0, 300.0, "hill: length (along the ground) of the climb and of the descent"),
        Parameter("hill_top", "m", 10.0, 1.0, 100.0, "hill: length of its flat top"),
        Parameter("start_speed", "m/s", 1.5, 1.5, 8.0, "start: the rolling start's speed, from which the rider pedals up to speed"),
        Points("path", "the path to ride along, [x, y] points in metres from the start (in Blender: a curve "
               "object); given, it replaces the course's path", clean=lambda points: validate_path(points).tolist(),
               max_points=MAX_POINTS),
        Parameter("lookahead_time", "s", 0.875, 0.25, 3.0,
                  "path following: the rider heads for the point this many seconds ahead along the path at his speed"),
        settings=BICYCLE_SETTINGS,
    )
    default_duration = 10.0

    @classmethod
    def scene(cls, params, world, character=None):
        """The requested world with the bicycle (at the origin facing +X, its gear, the rider
        attached) and the course's hill, if it has one."""
        return dataclasses.replace(world, bicycle=Bicycle(gear=params["gear"], rider=""), hill=course_for(params).hill)

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
        for name, value in mount_posture(params).items():
            reference[model.joint(name).qposadr[0]] = value
        data.qpos[:] = reference
        dofs = np.arange(int(root.dofadr[0]), model.nv)
        rider_dofs = dofs[model.body_rootid[model.dof_bodyid[dofs]] == model.jnt_bodyid[root.id]]
        every = list(range(len(pairs.names)))
        solve(model, data, pairs, every, rider_dofs, reference, iterations=300)   # definition: IK solver iterations to mount
        gaps = solve(model, data, pairs, every, rider_dofs, data.qpos.copy(), iterations=50, posture_weight=0.0)  # definition: IK iterations
        course = course_for(params)
        bike.rolling_start(data, course.start_speed)
        dof = int(root.dofadr[0])
        data.qvel[dof:dof + 3] = data.qvel[bike.free_dof:bike.free_dof + 3]
        match_velocities(model, data, pairs, rider_dofs)
        return {"mounted": True, "rolling_speed": course.start_speed, "crank_angle": MOUNT_CRANK_ANGLE,
                "attachment_gaps": {n: float(g) for n, g in zip(pairs.names, gaps)}}

    def check_feasible(self):
        """A scene does not mount a rider yet (run_scene calls neither start_state nor the rider's
        attachments): refuse rather than ride a bicycle that is not there. Only the riders measured
        to ride are offered."""
        if mujoco.mj_name2id(self.ctx.model, mujoco.mjtObj.mjOBJ_BODY, NAMES["frame"]) < 0 or self.ctx.actor.prefix:
            raise ParameterError("the bicycle behaviour runs only alone (python -m sim_core simulate bicycle); "
                                 "scenes with a bicycle are not built yet")
        rider = self.ctx.character.name
        if rider not in RIDERS:
            raise ParameterError(f"bicycle is not calibrated for the {rider} (calibrated for: {', '.join(RIDERS)}): "
                                 f"the bicycle is sized and its steering gains set for the man; at 4 m/s the woman "
                                 f"fell 11.0 s into a ride, the imaginary cyclist 5.7 s, the child and the imaginary "
                                 f"runner within 3 s (docs/bicycle.md)")

    def start(self, t):
        """Look the bicycle and the limbs up; the targets start at the mounted pose."""
        ctx = self.ctx
        model, servos = ctx.model, ctx.servos
        self.target = servos.angles().copy()
        self.bike = BicycleView.of(model)
        self.pairs = SitePairs(model, ctx.actor.prefix)
        self.scratch = mujoco.MjData(model)
        self.desired_yaw = self.params["heading"] + self.bike.state(ctx.data)["yaw"]
        self.course = course_for(self.params)
        self.follower = None
        if self.course.path is not None:      # the path is from where the bicycle starts
            start = ctx.data.qpos[self.bike.free_qpos:self.bike.free_qpos + 2]
            self.follower = PathFollower(self.course.path + start, self.params["lookahead_time"] * self.params["speed"])
        self.leg_servos = {side: servos.indices(names) for side, names in LEG_JOINTS.items()}
        self.arm_servos = {side: servos.indices(names) for side, names in ARM_JOINTS.items()}
        self.ankle_servos = {side: servos.indices([name])[0] for side, name in ANKLE_JOINTS.items()}
        self.limb_servos = np.concatenate([*self.leg_servos.values(), *self.arm_servos.values()])
        self.limb_dofs = servos.dof_adr[self.limb_servos]
        self.leg_dofs = {side: servos.dof_adr[i] for side, i in self.leg_servos.items()}
        self.kp = servos.default_kp
        self.lag = servos.default_kv / servos.default_kp          # s: a PD servo's lag behind its target
        self.previous_ik = None
        self.ik_velocity = np.zeros(len(self.limb_servos))
        self.fork_command = 0.0
        self.desired_speed = self.course.start_speed
        self.jac = np.zeros((3, model.nv))

    def update(self, t):
        """Eq. 11 -> fork command -> arm IK; pedal IK and ankle curve -> leg targets; eqs. 7-10
        -> pedal forces -> leg torques (servo offsets)."""
        ctx, servos, bike = self.ctx, self.ctx.servos, self.bike
        model, data = ctx.model, ctx.data
        state = bike.state(data)
        c = self.params
        desired_roll = 0.0
        if self.follower is not None:      # pure pursuit: head for the point lookahead_time ahead
            x, y = data.qpos[bike.free_qpos], data.qpos[bike.free_qpos + 1]
            moving = max(state["speed"], MIN_LOOKAHEAD_SPEED)
            self.follower.lookahead = c["lookahead_time"] * moving
            self.desired_yaw = self.follower.heading(x, y)
            curvature = self.follower.curvature_ahead(x, y, c["curvature_preview"] * moving)
            desired_roll = lean_ahead(state["speed"], curvature, c["lean_feedforward"])
        fork = fork_angle(state["roll"], state["roll_rate"], state["yaw"], state["yaw_rate"], self.desired_yaw,
                          *steering_gains(state["speed"], c), desired_roll)
        self.fork_command = min(max(fork, -c["max_fork_angle"]), c["max_fork_angle"])
        self._pedal(t, state)

    def _limb_goal(self, state, which, servo_rows, ankles=None) -> np.ndarray:
        """Servo targets: the limbs ``servo_rows`` by inverse kinematics of the attachments
        ``which`` (hands on a fork turned to its command, feet on the pedals as they are), led
        by the servo's lag; the ankles on their curve when given; the rest at the mounted pose."""
        ctx, servos, bike = self.ctx, self.ctx.servos, self.bike
        scratch = self.scratch
        scratch.qpos[:] = ctx.data.qpos
        scratch.qpos[bike.steer_qpos] = self.fork_command
        for side, value in (ankles or {}).items():
            scratch.qpos[servos.qpos_adr[self.ankle_servos[side]]] = value
        solve(ctx.model, scratch, self.pairs, which, servos.dof_adr[servo_rows], ctx.data.qpos, IK_ITERATIONS_PER_TICK)
        goal = self.target.copy()
        ik = scratch.qpos[servos.qpos_adr[servo_rows]]
        if self.previous_ik is not None:   # the targets' velocity, low-passed: the IK starts from the measured
            # limbs, so its raw difference carries their jitter, and led by it the servos lost their damping
            # (the shoulders chattered at 17 Hz, 2.8 rad/s rms, and the tyres' contacts took ~130 W)
            blend = ctx.control_dt / (self.params["ik_velocity_filter"] + ctx.control_dt)
            self.ik_velocity += blend * ((ik - self.previous_ik) / ctx.control_dt - self.ik_velocity)
        self.previous_ik = ik.copy()
        goal[servo_rows] = ik + self.lag[servo_rows] * self.ik_velocity
        for side, value in (ankles or {}).items():
            goal[self.ankle_servos[side]] = value
        return goal

    def _pedal(self, t, state) -> None:
        """Feet on the pedals: pedal IK and the ankle curve -> leg targets; eqs. 7-10 -> pedal
        forces -> leg torques (servo offsets)."""
        ctx, servos, bike = self.ctx, self.ctx.servos, self.bike
        model, data = ctx.model, ctx.data
        c = self.params
        curve = (c["ankle_mean"], c["ankle_swing"], c["ankle_phase"])
        ankles = {"r": ankle_angle(state["crank"], *curve), "l": ankle_angle(state["crank"] + math.pi, *curve)}
        goal = self._limb_goal(state, [2, 3, 4, 5], self.limb_servos, ankles)  # definition: the hand and foot attachments
        # eqs. 7-10: pedal forces, through each leg's Jacobian to joint torques (servo offsets)
        step = c["speed_ramp"] * ctx.control_dt
        self.desired_speed += min(max(self.course.speed_at(t) - self.desired_speed, -step), step)
        torque = crank_torque(state["speed"], self.desired_speed, c["speed_gain"], c["max_crank_torque"])
        forces = dict(zip("rl", pedal_forces(torque, state["crank"], CRANK_LENGTH)))
        offset = np.zeros(len(goal))
        axle = data.xpos[bike.crank_body]
        crank_axis = data.xmat[bike.crank_body].reshape(3, 3)[:, 1]
        for k, side in ((4, "r"), (5, "l")):          # definition: the foot attachments
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
