"""The commanded take-off (issue 29): a leap whose flight is set by what it commands, so that nearby
targets are nearby commands (an experimental mode: no stored plan selects it yet; measured in
docs/jump_to_target.md, "A commanded take-off").

The leap's thrust (leap.LeapThrust) extends the legs along the path of balanced crouch poses; where
the body goes then depends on every setting of the crouch and the thrust, and not smoothly (a
balanced jump's 5 % nudge lands 0.2-0.7 m away). Here the flight is commanded - the feet land at a
point after an air time - and the take-off is servoed to it:

- the lift-off velocity wanted, from where the COM is now (``liftoff_velocity``): up, what rises
  from here to the touchdown COM height in the air time, ``(z_td - z) / T + g T / 2``; along the
  ground, what carries the COM over the air time and the landing's foot lead to where the landing's
  foot servo will put the feet, ``(target - com - delta) / (T + lead)`` (the landing places the
  feet ``lead`` s of horizontal COM travel ahead of the COM, plus its own and the landing table's
  delta);
- the lean (``thrust_due``): after the crouch the COM moves ahead of the feet (the leap's
  ``lean`` step) and the thrust starts once the horizontal speed the lean has given, plus what the
  push along the lean will add, reaches the wanted (the horizontal speed comes from the lean: the
  hips' push alone turned into spin, not speed);
- the push (``CommandedThrust``): the leap's extension, plus a correction of the legs through each
  stance foot's Jacobian - the ground force and moment that bring the COM velocity and the body's
  spin to an even push's reference (the wanted ones times the square root of the rise done) - and
  the hips extended against a spin forward of the commanded one (a lean leaves the ground pitching
  forward; a landing needs the trunk upright while the legs swing ahead).

After a turn (the leap's ``turn_angle``, turn.py) the flight is aimed from the start's feet, the spin is
the one about the pelvis's side axis at the thrust's start, and the lift-off velocity servoed is the
wanted one along the pelvis's heading (the turn aims the line, the push its length).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import mujoco
import numpy as np

from ..ballistics import GRAVITY
from .leap import LeapThrust


@dataclass(frozen=True)
class FlightCommand:
    """A commanded flight and the take-off's constants (leap_any.json's ``commanded_*``): the middle
    of the feet lands at ``target`` (x, y m from the middle of the feet at the start, world frame; z m
    of the surface landed on above the one stood on) after ``air_time`` s; the landing places the
    feet ``lead`` s of horizontal COM travel ahead of the COM plus ``delta`` m plus the landing
    table's ``calibrated_delta(speed, touchdown speed)``; the COM is ``touchdown_height`` m above the
    feet at touchdown and ``liftoff_height`` m at lift-off."""
    target: tuple
    air_time: float
    lead: float
    delta: float
    touchdown_height: float
    liftoff_height: float
    lean_push: float
    servo_time: float
    correction_limit: float
    start_share: float
    spin: float
    spin_gain: float
    calibrated_delta: Callable[[float, float], float] = lambda speed, touchdown_speed: 0.0


def liftoff_velocity(command: FlightCommand, com: np.ndarray, origin: np.ndarray) -> np.ndarray:
    """The COM velocity that flies the commanded flight from the COM at ``com`` (world), the
    middle of the feet at the start at ``origin`` (world x, y, z)."""
    T = command.air_time
    along = origin[:2] + np.asarray(command.target[:2], dtype=float) - com[:2]
    distance = float(np.hypot(*along))
    ahead = along / distance if distance > 1e-9 else np.array([1.0, 0.0])
    up = (origin[2] + command.target[2] + command.touchdown_height - com[2]) / T + 0.5 * GRAVITY * T
    speed = distance / (T + command.lead)
    for _ in range(3):      # definition: a fixed-point solve (the landing table's delta depends on the speed), converged in 3
        speed = (distance - command.delta - command.calibrated_delta(speed, abs(up))) / (T + command.lead)
    return np.array([speed * ahead[0], speed * ahead[1], up])


def thrust_due(command: FlightCommand, data, pelvis: int, support, origin: np.ndarray) -> bool:
    """Whether the leaning crouch should thrust now: the push adds about ``lean_push`` times the
    lean's slope (COM ahead of the middle of the feet per height above them) per m/s of vertical
    speed still to come, to the horizontal speed the lean has given; thrust once that reaches the
    wanted (the lean only grows)."""
    com, velocity = data.subtree_com[pelvis], data.subtree_linvel[pelvis]
    wanted = liftoff_velocity(command, com, origin)
    horizontal = math.hypot(wanted[0], wanted[1])
    heading = wanted[:2] / horizontal if horizontal > 1e-9 else np.array([1.0, 0.0])
    feet = support.points(data).mean(axis=0)
    lean = float((com[:2] - feet[:2]) @ heading) / max(float(com[2] - feet[2]), 0.1)   # definition: a guard
    coming = float(velocity[:2] @ heading) + command.lean_push * max(wanted[2] - float(velocity[2]), 0.0) * lean
    return coming >= horizontal


class CommandedThrust(LeapThrust):
    """The leap's thrust with the commanded take-off's corrections (see the module)."""

    def __init__(self, params, ctx, crouch_height: float, command: FlightCommand, origin=None, turned=False, **thrust):
        """``origin``: the middle of the feet the flight's target is measured from (None: where they are
        when the thrust starts); ``turned``: the body turned before the jump (turn.py), so the spin servoed
        is about the pelvis's side axis at the thrust's start (else the world's y, the start's side)."""
        super().__init__(params, ctx, crouch_height, **thrust)
        self.command = command
        self.given_origin, self.turned = origin, turned

    def start(self, t: float) -> None:
        super().start(t)
        m, d, s = self.ctx.model, self.ctx.data, self.ctx.servos
        points = self.airborne.support.points(d)
        self.origin = np.array([*points[:, :2].mean(axis=0), float(points[:, 2].min())]) \
            if self.given_origin is None else np.asarray(self.given_origin, dtype=float)
        self.side = None
        if self.turned:
            frame = d.xmat[self.pelvis]
            yaw = math.atan2(float(frame[3]), float(frame[0]))
            self.side = np.array([-math.sin(yaw), math.cos(yaw), 0.0])
        self.mass = float(m.body_subtreemass[self.pelvis])
        self.foot_bodies = [self.ctx.actor.body_id("FOOTR"), self.ctx.actor.body_id("FOOTL")]
        self.leg_servos = [s.indices([f"hip_{side}_y", f"knee_{side}_y", f"ankle_{side}_y"]) for side in "rl"]
        self.jacp = np.zeros((3, m.nv))
        self.jacr = np.zeros((3, m.nv))
        self.low = float(d.subtree_com[self.pelvis][2])
        self.wanted = liftoff_velocity(self.command, d.subtree_com[self.pelvis], self.origin)

    def update(self, t: float) -> None:
        s, d, m, c = self.ctx.servos, self.ctx.data, self.ctx.model, self.command
        super().update(t)                           # the leap's extension along balanced poses, and the arms
        com, velocity = d.subtree_com[self.pelvis], d.subtree_linvel[self.pelvis]
        self.wanted = liftoff_velocity(c, com, self.origin)
        if self.side is not None:       # turned: along the heading only (the turn aims the line, the push its length)
            self.wanted = self.wanted - float(self.wanted @ self.side) * self.side
        top = c.liftoff_height + self.origin[2]
        rise = min(max((float(com[2]) - self.low) / max(top - self.low, 1e-3), 0.0), 1.0)   # definition: a guard
        share = math.sqrt(max(rise, c.start_share))     # an even push's velocity, by the rise done
        spin = float(d.subtree_angmom[self.pelvis][1]) if self.side is None else float(d.subtree_angmom[self.pelvis] @ self.side)
        force = self.mass * (self.wanted * share - velocity) / c.servo_time
        moment = (c.spin * share - spin) / c.servo_time
        points = self.airborne.support.points(d)
        cop = np.array([*points[:, :2].mean(axis=0), float(points[:, 2].min())])
        kp = m.actuator_gainprm[s.actuators, 0]
        for k, servos in enumerate(self.leg_servos):
            mujoco.mj_jac(m, d, self.jacp, self.jacr, cop, self.foot_bodies[k])
            dofs = s.dof_adr[servos]
            about = self.jacr[1, dofs] if self.side is None else self.side @ self.jacr[:, dofs]
            torque = -(self.jacp[:, dofs].T @ force + about * moment) / 2.0   # each foot half
            s.offset[servos] = np.clip(torque / kp[servos], -c.correction_limit, c.correction_limit)
        hips = self.idx["hip"]
        s.offset[hips] += min(max(c.spin_gain * (spin - c.spin), -c.correction_limit), c.correction_limit)
