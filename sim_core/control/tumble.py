"""Tumbling (Wooten ch. 5): somersaults and twists in flight, from the angular momentum the leap
gave the body.

Once airborne nothing can change the whole-body angular momentum H about the COM; the tumbling
controller changes the body's shape instead. A layout, pike or tuck (predetermined angles of the
hips, knees, spine and arms, ``CONSTANTS.positions``) lowers the moment of inertia about the somersault
axis and so raises the somersault rate; ``tightness`` blends between the layout and the full
position. A twist is started in flight, with no twist at take-off, by an asymmetric arm throw
(Frohlich's torque-free twist, §5.2): one arm goes up over the head and the other down across
the body, the body tilts out of the plane of H, and part of H becomes rotation about the long
axis (the legs swing sideways with the throw and add to the tilt); bringing the arms and legs
back stops it.

``FlightRotation`` measures the somersault angle (the pelvis's long axis turning in the
vertical plane of the somersault) and the twist angle (the pelvis's rotation about its long
axis) that transitions and the assessment read.
"""
from __future__ import annotations

import math

import mujoco
import numpy as np

from ..character.model import place_standing
from .actor import ActorView
from .behaviour import Behaviour, ControlContext
from ..schema import Choice, Parameter, Schema
from ..tuned.constants import constant, read_constants, register_constants

# the tumbling's hand-set constants: data, tumble_any.json's "constants" (docs/tables.md).
# positions: joint angles (rad) of each position; "*" is r or l, arm angles are the right side's (mirrored
# for the left); joints not named keep the standing pose (straight, arms hanging: shoulder x is the arm's
# elevation in the frontal plane, 1.43 hanging, 0 sideways, -1.5 overhead; shoulder z swings it forward in
# the sagittal plane); the entry "line" is straight, arms overhead (a head-first water entry).
# twist_throw: the asymmetric arm throw that starts a twist (§5.2), from the line: the right arm stays up by
# the head, the left comes down to the side in the frontal plane, which tilts the body out of the plane of
# the angular momentum; the legs, together, swing twist_hip_swing to the left with it (an asymmetric hip
# movement, as twisting divers and gymnasts add to the arms' tilt: on the woman's back 1 1/2 with 2 1/2
# twists it took the twists from 2.13 to 2.43, measured); mirrored_throw: the left arm up, the right one
# down, the legs to the right.
TUMBLE_CONSTANTS = Schema(
    constant("positions", "rad", -3.2, 3.2, "joint angles of each position (layout, pike, tuck, line) by joint name"),
    constant("twist_hip_swing", "rad", 0.0, 1.0, "hip abduction (left) / adduction (right) of the twist's throw"),
    constant("twist_throw", "rad", -3.2, 3.2, "shoulder angles of the arm throw that starts a twist"),
    constant("mirrored_throw", "rad", -3.2, 3.2, "shoulder angles of the mirrored throw (a twist the other way)"),
    constant("snap_damping", "1", 0.0, 10.0,
             "a stiffened move is damped this much more again: fast but overdamped (with critical damping the "
             "1 ms step let the flight's angular momentum drift ~1 %)"),
    constant("pointed_toes", "rad", 0.0, 1.5, "ankle plantarflexion in flight"),
    constant("twist_throw_time", "s", 0.01, 2.0, "how long the arm throw that starts a twist takes, unless its caller says"),
    constant("twist_stop_time", "s", 0.01, 2.0, "how long the arms take back to the position when a twist stops, unless its caller says"),
    constant("seed_inertia", "kg m^2", 0.0, 100.0, "moment of inertia of each position per character, Wooten Fig. 5.2"),
)
register_constants("tumble", TUMBLE_CONSTANTS)
CONSTANTS = read_constants("tumble", TUMBLE_CONSTANTS)
TWIST_THROW = {**CONSTANTS.twist_throw, "hip_r_x": CONSTANTS.twist_hip_swing, "hip_l_x": CONSTANTS.twist_hip_swing}
MIRRORED_THROW = {**CONSTANTS.mirrored_throw, "hip_r_x": -CONSTANTS.twist_hip_swing, "hip_l_x": -CONSTANTS.twist_hip_swing}

POSITION_NAMES = ("layout", "pike", "tuck", "line")     # by the schemas' position codes 0-3


def _is_mirrored(name: str) -> bool:
    """Arm dofs whose left angle is the negative of the right's (the rig's mirrored axes)."""
    return name.startswith(("shoulder", "elbow")) and name.endswith(("_x", "_z"))


def both_sides(angles: dict[str, float]) -> dict[str, float]:
    """Joint name -> angle with each "*" name ("hip_*_y") spelled out for both sides, the arm
    axes mirrored."""
    out = {}
    for name, value in angles.items():
        if "*" not in name:
            out[name] = value
            continue
        for side, sign in (("r", 1.0), ("l", -1.0)):
            out[name.replace("*", side)] = value * sign if _is_mirrored(name) else value
    return out


def position_angles(position: str) -> dict[str, float]:
    """Joint name -> angle of a named position, both sides spelled out."""
    return both_sides(CONSTANTS.positions[position])


def position_name(code: float) -> str:
    """The position a schema's code (0 layout, 1 pike, 2 tuck, 3 line) names."""
    return POSITION_NAMES[int(round(code))]


def inertia_about_com(model: mujoco.MjModel, data: mujoco.MjData, actor: ActorView | None = None) -> np.ndarray:
    """Whole-body inertia tensor (world frame, kg m^2) about the COM of the current state, of
    ``actor`` (default: the model's only character)."""
    actor = actor or ActorView.of(model)
    bodies = actor.bodies
    rotation = data.ximat[bodies].reshape(-1, 3, 3)
    own = np.einsum("bij,bj,bkj->ik", rotation, model.body_inertia[bodies], rotation)
    r = data.xipos[bodies] - data.subtree_com[actor.root]
    mass = model.body_mass[bodies]
    parallel = np.eye(3) * float(mass @ np.einsum("bi,bi->b", r, r)) - np.einsum("b,bi,bj->ij", mass, r, r)
    return own + parallel


def _posed(model: mujoco.MjModel, character, position: str, actor: ActorView) -> mujoco.MjData:
    data = mujoco.MjData(model)
    mujoco.mj_resetData(model, data)
    place_standing(model, data, character, actor.prefix, actor.placement)
    for name, value in position_angles(position).items():
        data.qpos[actor.joint_qposadr(name)] = value
    mujoco.mj_kinematics(model, data)
    mujoco.mj_comPos(model, data)
    return data


def position_inertia(model: mujoco.MjModel, character, position: str, actor: ActorView | None = None) -> float:
    """Moment of inertia about the somersault (lateral, Y) axis of a named position, the body
    upright, read off MuJoCo's kinematics of the model."""
    actor = actor or ActorView.of(model)
    return float(inertia_about_com(model, _posed(model, character, position, actor), actor)[1, 1])


def position_radius(model: mujoco.MjModel, character, position: str, actor: ActorView | None = None) -> float:
    """Farthest reach (m) of the feet, hands and head from the COM in a named position: how much
    room the body needs to turn in it."""
    actor = actor or ActorView.of(model)
    data = _posed(model, character, position, actor)
    ends = [actor.body_id(n) for n in ("TOER", "TOEL", "HANDR", "HANDL", "HEAD", "FOOTR", "FOOTL")]
    return float(max(np.linalg.norm(data.xpos[b] - data.subtree_com[actor.root]) for b in ends))


class FlightRotation:
    """Rotation measures of a skill, updated every control tick:

    * ``somersault``: angle (rad, + forward) of the pelvis's long axis in the vertical X-Z plane,
      unwrapped, from upright (a skill's rotation counts from the standing start, not from a
      leaning take-off). Right for a straight body; while the body folds or opens the pelvis
      turns against the legs.
    * ``whole_body``: from take-off (``takeoff``), the whole body's mean somersault angle: the
      principal axis of the body's inertia at take-off, then the integral of H_y / I_yy (the
      rate of the mass-weighted mean frame, which folding and opening do not turn). This is what
      a dive has left to turn, whatever its shape.
    * ``twist``: the pelvis's rotation about its long axis since take-off (rad).
    """

    def __init__(self, model: mujoco.MjModel, data: mujoco.MjData, actor: ActorView | None = None):
        self.model, self.data = model, data
        self.actor = actor = actor or ActorView.of(model)
        self.pelvis = actor.body_id("PELVIS")
        self.spin_dof = actor.root_dof + 5          # definition: the free joint's 6th dof, its local angular velocity about z
        self.flying = False
        self.reset(0.0)

    def _raw(self) -> float:
        m = self.data.xmat[self.pelvis]
        return math.atan2(m[2], m[8])           # long (z) axis: x component, z component

    def reset(self, t: float) -> None:
        self.t = t
        self.last = self._raw()
        self.somersault = self.last
        self.whole_body = self.somersault
        self.twist = 0.0

    def takeoff(self, t: float) -> None:
        """Start the whole-body angle at the body's long principal axis (the branch nearest the
        pelvis's angle) and the twist at zero."""
        self.update(t)
        inertia = inertia_about_com(self.model, self.data, self.actor)
        # long axis = least inertia in the X-Z plane; its angle from vertical towards +X
        axis = 0.5 * math.atan2(-2.0 * inertia[0, 2], inertia[0, 0] - inertia[2, 2])
        self.whole_body = axis + math.pi * round((self.somersault - axis) / math.pi)
        self.twist = 0.0
        self.flying = True

    def update(self, t: float) -> None:
        raw = self._raw()
        self.somersault += (raw - self.last + math.pi) % (2 * math.pi) - math.pi
        self.last = raw
        dt = t - self.t
        self.twist += float(self.data.qvel[self.spin_dof]) * dt      # free joint: local angular velocity
        self._rate = None
        if self.flying:
            self.whole_body += self.rate() * dt
        self.t = t

    def rate(self) -> float:
        """Mean somersault rate of the whole body (rad/s): H_y / I_yy about the COM (of the state
        at the last ``update``)."""
        if getattr(self, "_rate", None) is None:
            self._rate = (float(self.data.subtree_angmom[self.actor.root][1])
                          / float(inertia_about_com(self.model, self.data, self.actor)[1, 1]))
        return self._rate


class Tumble(Behaviour):
    """Basis behaviour: take a position in flight and hold it; optionally throw the arms to
    twist, and bring them back when the twist is done. The sequence decides when to leave."""

    schema = Schema(
        Choice("position", POSITION_NAMES, "pike", "body position: layout, pike, tuck or line (straight, arms overhead)"),
        Parameter("tightness", "1", 1.0, 0.0, 1.0, "share of the position's joint angles (0 = layout, 1 = full)"),
        Parameter("move_time", "s", 0.25, 0.05, 1.0, "time to move into the position"),
        Parameter("stiffness", "1", 1.0, 1.0, 4.0,
                  "gain factor of the hip, knee and spine servos while moving into the position (a snap)"),
        Parameter("damping", "1", 0.0, 0.0, 8.0,
                  "damping factor of those servos in the move; 0 = the stiffness x 2 above 1 (overdamped: "
                  "with the 1 ms step a faster move let the flight's angular momentum drift; a lighter "
                  "damping closes the position sooner, with a finer flight step)"),
    )

    def __init__(self, params, ctx: ControlContext, rotation: FlightRotation | None = None):
        super().__init__(params, ctx)
        self.rotation = rotation or FlightRotation(ctx.model, ctx.data, ctx.actor)
        self.twisting = False

    def _targets(self) -> dict[str, float]:
        """Joint targets: the standing pose moved ``tightness`` of the way to the position's
        angles; toes pointed."""
        character = self.ctx.character
        straight = {d.name: v for d, v in zip(character.dofs, character.standing_pose)}
        position = position_name(self.params["position"])
        k = self.params["tightness"] if position != "line" else 1.0
        targets = {name: value + k * (position_angles(position).get(name, value) - value)
                   for name, value in straight.items()}
        for side in "rl":
            targets[f"ankle_{side}_y"] = CONSTANTS.pointed_toes
        return targets

    def start(self, t: float) -> None:
        s = self.ctx.servos
        s.offset[:] = 0.0
        s.set_gains(np.arange(len(s.names)), s.default_kp, s.default_kv)
        trunk_and_legs = s.indices([n for n in s.names if n.startswith(("hip", "knee", "spine"))])
        k = self.params["stiffness"]
        damping = self.params["damping"] or snap_damping(k)
        s.set_gains(trunk_and_legs, s.default_kp[trunk_and_legs] * k, s.default_kv[trunk_and_legs] * damping)
        targets = self._targets()
        s.move_to(s.indices(list(targets)), np.array(list(targets.values())), self.params["move_time"], t)
        self.event(t, "tumble")

    def throw_twist(self, t: float, duration: float = CONSTANTS.twist_throw_time, mirrored: bool = False) -> None:
        s = self.ctx.servos
        throw = MIRRORED_THROW if mirrored else TWIST_THROW
        s.move_to(s.indices(list(throw)), np.array(list(throw.values())), duration, t)
        self.twisting = True
        self.event(t, "twist_throw")

    def stop_twist(self, t: float, duration: float = CONSTANTS.twist_stop_time) -> None:
        s = self.ctx.servos
        thrown = set(TWIST_THROW) | set(MIRRORED_THROW)
        targets = {n: v for n, v in self._targets().items() if n.startswith(("shoulder", "elbow")) or n in thrown}
        s.move_to(s.indices(list(targets)), np.array(list(targets.values())), duration, t)
        self.twisting = False
        self.event(t, "twist_stop")

    def update(self, t: float) -> None:
        """The position is held by the servos; the rotation is measured by the owner."""


def snap_damping(stiffness: float) -> float:
    """The move's damping factor where none is given: the stiffness, doubled for a snap (> 1)."""
    return stiffness * (CONSTANTS.snap_damping if stiffness > 1.0 else 1.0)


def rotation_to_come(rate_now: float, rate_open: float, time_left: float, open_time: float) -> float:
    """Rotation (rad) the body will still make if it opens now: at the open shape's rate for the
    time left, plus about half the difference of the rates over the opening."""
    return rate_open * time_left + 0.5 * (rate_now - rate_open) * open_time
