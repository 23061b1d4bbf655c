"""Leaping (Wooten ch. 4) and landing (ch. 6) basis behaviours, and the leap composite skill.

Leap thrust: from a crouch, the hips, knees and ankles extend proximal to distal along Hermite
curves (vertical leap: full extension in 0.10, 0.15, 0.22 s; broad jump 0.15, 0.20, 0.45 s), the
ankle servo stiffened (x4.45 vertical, x3.6 broad), the arms swing forward and up; the lift-off
hip angle tilts the ground reaction force past the COM to set the somersault rate (§4.3).

Landing: in flight the hips place the feet relative to the COM by a PD servo on the feet
(eq. 6.1) towards the point where the COM's horizontal speed will have died out when it is over
them (the capture point x + v sqrt(h/g)) plus the calibrated foot servo delta (Table 6.1's role,
per horizontal speed and vertical touchdown speed);
knees flexed, feet parallel to the ground - or, when the touchdown will be fast (a drop or a high
leap), pitched toe-down so the forefoot lands first and the ankles take the first impact, as
people land. After touchdown the knees go soft (position gain down, damping up) and absorb; when
their speed has fallen to 20 % of the touchdown speed the gains come back and the balance
behaviour takes over, from the crouch with the landed legs' hip-to-ankle distance. The landing
uses at most the human torque limits whatever the model's strength (an unlimited servo would land
rigidly, not better). A landing is balanced only if the feet stay where they touched down (see
leap_assess).
"""
from __future__ import annotations

import math
from types import SimpleNamespace
from typing import Callable

import numpy as np

from ..analysis import feet_above_surface, standard_metrics
from ..ballistics import GRAVITY
from ..errors import ParameterError
from .balance import Balance, LegGeometry, inside_a_skill, standing_hip_height
from .crouch import CrouchTable
from .behaviour import Behaviour, ControlContext
from .measure import SupportGeometry, roll_of
from .servo import hermite_scalar
from ..schema import Parameter, Schema
from ..tuned import TableType, load, register as register_table
from ..tuned.constants import constant, constant_rows, own_constants, read_constants, with_constants

# the leap's thrust and landing's hand-set constants: data, leap_any.json's "constants", shared by
# every skill that composes them (docs/tables.md)
LEAP_CONSTANTS = Schema(
    constant("vertical_timing", "s", 0.0, 1.0, "vertical leap: time to full extension of the hip, knee, ankle [W98 §4.1]"),
    constant("broad_timing", "s", 0.0, 1.0, "broad jump: time to full extension of the hip, knee, ankle [W98 §4.2]"),
    constant("ankle_gain_vertical", "1", 1.0, 10.0, "ankle servo gain factor of a vertical leap's thrust"),
    constant("ankle_gain_broad", "1", 1.0, 10.0, "ankle servo gain factor of a broad jump's thrust"),
    constant("sideways_heading_kp", "1", 0.0, 20.0,
             "rad/rad: a sideways lean's hips hold the pelvis's heading on the feet's (its hip abduction in the "
             "crouch turned the pelvis 25 deg before lift-off)"),
    constant("broad_trigger", "1", 0.0, 2.0, "share of the crouch's COM offset that triggers a broad jump's thrust"),
    constant("thrust_damping_default", "1", 0.1, 1.0,
             "share of the stiffened servos' damping kept in the thrust when the row names none (damping brakes "
             "fast extension: high leaps use less, calibrated per row with the lift-off hip angle and COM offset "
             "that cancel the spin it brings)"),
    constant("thrust_gain", "1", 1.0, 10.0, "hip and knee servos stiffened for the thrust [W98 §4.3]"),
    constant("ankle_push_start", "1", 0.0, 0.95, "share of the ankle's extension time after which the ankles push to the lift-off plantarflexion"),
    constant("liftoff_ankle", "rad", 0.0, 1.5, "ankle plantarflexion at the end of the thrust"),
    constant("soft_knee_kp", "1", 0.0, 1.0,
             "knee kp factor while absorbing (the thesis: kp 0; with human torque limits a little spring keeps the "
             "squat shallower)"),
    constant("soft_knee_kv", "1", 0.0, 10.0, "knee damping factor while absorbing"),
    constant("com_kp", "rad/m", 0.0, 20.0, "the balance's COM servo gain (eq. 7.1), used while absorbing"),
    constant("com_kv", "rad s/m", 0.0, 20.0, "the balance's COM servo damping (eq. 7.1), used while absorbing"),
    constant("absorb_time", "s", 0.0, 2.0, "hand over to balance at the latest this long after touchdown"),
    constant("knee_restore", "1", 0.0, 1.0, "knees stiffen again at this share of their touchdown speed [W98 §6.1]"),
    constant("toe_point_per_speed", "s", 0.0, 2.0, "rad of toe-down foot pitch before touchdown per m/s of expected touchdown speed"),
    constant("toe_point_from", "m/s", 0.0, 10.0,
             "touchdown speed above which the forefoot lands first and the ankles give, like a person landing from a height"),
    constant("toe_point_max", "rad", 0.0, 1.5, "the toe-down pitch is at most this (0 = feet parallel to the ground)"),
    constant("fast_landing_speed", "m/s", 0.0, 5.0, "horizontal COM speeds over which the flight knee eases to the fast one"),
    constant("fast_backward_landing_speed", "m/s", 0.0, 5.0,
             "the same, moving backward (a backward landing takes less speed with bent knees: the woman falls at "
             "-1.0 m/s with the slow knee)"),
    constant("toe_fade_speed", "m/s", 0.0, 5.0, "horizontal COM speeds over which the toe-down pitch fades out"),
    constant("settle_time", "s", 0.0, 1.0,
             "after the last touchdown the feet have settled by this time (the heels coming down after a toe-first landing)"),
    constant("arm_swing_default", "rad", 0.0, 3.2, "the arms' forward swing in a thrust whose caller names none"),
    constant("crouch_move_start", "s", 0.0, 2.0, "a leap's crouch starts moving this long after the leap begins"),
    constant("crouch_settle_time", "s", 0.0, 1.0, "a vertical leap's crouch posture must have been reached this long before the thrust"),
    constant("thrust_elbow", "rad", 0.0, 1.5, "elbow flexion the arms swing with in the thrust (mirrored for the left)"),
    constant("balance_handover_time", "s", 0.05, 5.0, "the balance after a landing moves from the landed height to its posture in this time"),
    constant("commanded_touchdown_height", "1", 0.3, 1.5,
             "commanded take-off (commanded_thrust.py): the COM's height above the feet at touchdown, as a share of "
             "the standing hip height"),
    constant("commanded_liftoff_height", "1", 0.5, 1.5,
             "commanded take-off: the COM's height above the feet at lift-off, as a share of the standing hip height"),
    constant("commanded_lean_wait", "s", 0.2, 2.0,
             "commanded take-off: after the crouch the COM moves ahead to commanded_lean_offset over this time; the "
             "thrust starts when the lean will give the flight's horizontal speed"),
    constant("commanded_lean_offset", "m", 0.0, 0.25, "commanded take-off: the furthest lean (COM ahead of the feet)"),
    constant("commanded_lean_push", "1", 0.0, 10.0,
             "commanded take-off: horizontal speed the push adds per m/s of vertical speed still to come per unit "
             "of the lean's slope (1: along the line from the feet to the COM)"),
    constant("commanded_servo_time", "s", 0.005, 1.0,
             "commanded take-off: the legs' correction asks the velocity and spin error back within this time"),
    constant("commanded_correction_limit", "rad", 0.0, 2.0, "commanded take-off: each leg joint corrected by at most this"),
    constant("commanded_start_share", "1", 0.0, 1.0,
             "commanded take-off: the even push's reference at its start, as the square root of this share of the wanted"),
    constant("commanded_spin", "kg m²/s", -30.0, 30.0,
             "commanded take-off: the angular momentum about the lateral axis at lift-off (-: backward, the trunk "
             "kept upright while the legs swing ahead for the landing)"),
    constant("commanded_spin_gain", "rad/(kg m²/s)", 0.0, 0.5,
             "commanded take-off: hip extension per kg m²/s of spin forward of the commanded"),
    constant("commanded_timing_scale", "1", 0.5, 2.0,
             "commanded take-off: its thrust's extension times (broad_timing, vertical_timing) times this - a body "
             "weaker for its size than the one the take-off was designed on extends more slowly, so that its "
             "joints' torques stay inside their limits (torque ~ 1/time^2; docs/jump_to_target.md)"),
    constant("landing_torque_limit", "1", 0.1, 10.0,
             "landing joints use at most this share of the human torque limits, whatever the model's strength "
             "(stiffer legs land harder, not better)"),
)
CONSTANTS = read_constants("leap", LEAP_CONSTANTS)



def leap_constants(character: str) -> SimpleNamespace:
    """The thrust's and the landing's constants for ``character``: leap_any's (tuned on the man and
    used as they are by the woman), or the character's own where its leap table holds a "constants"
    section (a body ``adapt`` scaled by Fig. 6: times by L^1/2, lengths by L, ...; docs/bodies.md)."""
    return own_constants("leap", character, CONSTANTS)


AIRBORNE_HEIGHT = 0.01          # m: every foot site this high above the ground = flight
TOUCHDOWN_HEIGHT = 0.004        # m: a foot site this low = contact
UP = np.array([0.0, 0.0, 1.0])
LANDING_SLIDE_LIMIT = 0.05      # m: a foot further than this from where it settled, at any time after the touchdown, has stepped
LANDING_SKID_LIMIT = 0.05       # m: the middle of the feet moving further than this between the first
                                # touchdown and settling is a skid (feet dragged or bounced), not a landing


def _sides(servos, *names):
    return [[servos.index[f"{n}_{s}_{a}"] for n, a in (name.split(":") for name in names)] for s in "rl"]


class Airborne:
    """Foot contact state from the foot sites."""

    def __init__(self, model, prefix: str = ""):
        self.support = SupportGeometry(model, prefix=prefix)

    def feet_heights(self, data) -> np.ndarray:
        return self.support.heights(data)

    def in_flight(self, data) -> bool:
        return bool(self.feet_heights(data).min() > AIRBORNE_HEIGHT)

    def touching(self, data) -> bool:
        return bool(self.feet_heights(data).min() < TOUCHDOWN_HEIGHT)


class LeapThrust(Behaviour):
    """Basis behaviour: explosive proximal-to-distal extension from the current crouch.

    Each joint runs along the path of balanced crouch poses (COM over the feet, see crouch.py)
    from the crouch height up to standing, the hip in ``timing[0]`` s, the knee in ``timing[1]``,
    the ankle in ``timing[2]`` (Wooten §4.1's order and times), then the ankles plantarflex to
    push off. Following balanced poses keeps the ground force near the COM, so the body leaves
    the ground without spinning; ``liftoff_hip`` flexes (-) or extends (+) the hips at the end
    to send the force past the COM and set the somersault rate (§4.3); ``liftoff_roll`` likewise
    abducts them sideways (a sideways jump: + swings the feet to the left, pushing the body right),
    which sets the roll rate; ``spin_hold`` turns the hips against the body's angular momentum about
    the vertical while the feet are down, as the crouch's Balance ``spin_kp`` does (a sideways jump);
    ``liftoff_turn`` rotates both hips alike by lift-off, which turns the body about the vertical
    against the planted feet (+ to the right, clockwise from above: a hop that turns, turn.py)."""

    def __init__(self, params, ctx: ControlContext, crouch_height: float, timing=None,
                 ankle_gain=None, liftoff_hip=0.0, arm_swing=None, stand_height=None,
                 thrust_damping=None, thrust_lean=0.0, liftoff_roll=0.0, spin_hold=0.0, liftoff_turn=0.0):
        super().__init__(params, ctx)
        self.constants = leap_constants(ctx.character.name)
        c = self.constants
        self.timing = c.vertical_timing if timing is None else timing
        self.ankle_gain = c.ankle_gain_vertical if ankle_gain is None else ankle_gain
        self.liftoff_hip = liftoff_hip
        self.arm_swing = c.arm_swing_default if arm_swing is None else arm_swing
        self.airborne = Airborne(ctx.model, ctx.actor.prefix)
        self.crouch_height = crouch_height
        self.stand_height = stand_height
        self.thrust_damping = c.thrust_damping_default if thrust_damping is None else thrust_damping
        self.thrust_lean = thrust_lean
        self.liftoff_roll = liftoff_roll
        self.spin_hold = spin_hold
        self.liftoff_turn = liftoff_turn

    def start(self, t: float) -> None:
        s = self.ctx.servos
        s.offset[:] = 0.0
        self.t0 = t
        heights = np.linspace(self.crouch_height, self.stand_height, 8)   # definition: the path's 8 solved heights
        self.path = CrouchTable(self.ctx.model, self.ctx.character, heights, self.stand_height, com_offset=self.thrust_lean,
                                actor=self.ctx.actor)
        self.idx = {name: s.indices([f"{name}_r_y", f"{name}_l_y"]) for name in ("hip", "knee", "ankle")}
        self.hip_rotation = s.indices(["hip_r_z", "hip_l_z"])
        self.pelvis = self.ctx.actor.body_id("PELVIS")
        t_hip, t_knee, t_ankle = self.timing
        for side, sign in (("r", 1.0), ("l", -1.0)):
            s.move_to(s.indices([f"hip_{side}_x", f"hip_{side}_z", f"ankle_{side}_x"]),
                      np.array([self.liftoff_roll, self.liftoff_turn, 0.0]), t_hip, t)
            s.move_to(s.indices([f"shoulder_{side}_z"]), sign * self.arm_swing, t_knee, t)
            s.move_to(s.indices([f"elbow_{side}_z"]), sign * self.constants.thrust_elbow, t_knee, t)
        spine = [n for n in s.names if n.startswith("spine") and n.endswith("_y")]
        s.move_to(s.indices(spine), 0.0, t_hip, t)
        ankles = self.idx["ankle"]
        s.set_gains(ankles, s.default_kp[ankles] * self.ankle_gain,
                    s.default_kv[ankles] * self.ankle_gain * self.thrust_damping)
        legs = np.concatenate([self.idx["hip"], self.idx["knee"]])
        s.set_gains(legs, s.default_kp[legs] * self.constants.thrust_gain, s.default_kv[legs] * self.constants.thrust_gain * self.thrust_damping)
        self.event(t, "thrust")

    def _height(self, t: float, duration: float) -> float:
        """Ease-in (zero start slope, fastest at the end): the joints are still extending hard
        when they reach full extension, which is what throws the body up."""
        x = min(max((t - self.t0) / duration, 0.0), 1.0)
        return self.crouch_height + (self.stand_height - self.crouch_height) * x * x

    def update(self, t: float) -> None:
        s = self.ctx.servos
        t_hip, t_knee, t_ankle = self.timing
        hip = self.path.at(self._height(t, t_hip))[1] + self.liftoff_hip * hermite_scalar((t - self.t0) / t_hip)
        knee = self.path.at(self._height(t, t_knee))[0]
        ankle = self.path.at(self._height(t, t_ankle))[2]
        share = self.constants.ankle_push_start
        push = hermite_scalar((t - self.t0 - share * t_ankle) / ((1.0 - share) * t_ankle))
        ankle = ankle + (self.constants.liftoff_ankle - ankle) * push
        for name, value in (("hip", hip), ("knee", knee), ("ankle", ankle)):
            for i in self.idx[name]:
                s.start[i] = s.goal[i] = value
        if self.spin_hold:
            s.offset[self.hip_rotation] = self.spin_hold * float(self.ctx.data.subtree_angmom[self.pelvis][2])
        s.t0[self.idx["hip"]] = t
        s._moving = True

    def lifted_off(self) -> bool:
        return self.airborne.in_flight(self.ctx.data)


class Landing(Behaviour):
    """Basis behaviour: land from flight and absorb, ready for balance (Wooten ch. 6)."""

    schema = Schema(
        Parameter("knee_flexion", "rad", 0.9, 0.0, 1.5, "knee bend held in flight, ready to absorb"),
        Parameter("tuck_knee_flexion", "rad", 0.0, 0.0, 2.4,
                  "knee bend held in flight from lift-off for tuck_time (the feet drawn up over a box's front "
                  "edge), then knee_flexion"),
        Parameter("tuck_time", "s", 0.0, 0.0, 1.5, "how long after lift-off the tuck is held (0 = no tuck)"),
        Parameter("fast_knee_flexion", "rad", 0.65, 0.0, 1.5,
                  "knee bend held in flight when the COM moves 1.5 m/s or faster horizontally (eased in "
                  "from 1.0 m/s; backward: 1.0 m/s, from 0.5): straighter legs land a fast COM (the leap's "
                  "own landing keeps knee_flexion)"),
        Parameter("foot_delta", "m", 0.0, -0.3, 0.3,
                  "foot servo delta: extra forward placement of the feet, added to the calibrated one "
                  "for the horizontal speed (the landing table, Table 6.1's role)"),
        Parameter("foot_lead_time", "s", 0.2, 0.0, 0.6,
                  "feet land this many seconds of horizontal COM travel ahead of the COM "
                  "(0.3 s ~ the capture point of a standing human)"),
        Parameter("foot_kp", "rad/m", 8.0, 0.0, 20.0, "hip offset per metre of foot placement error (eq. 6.1)"),
        Parameter("foot_kv", "rad s/m", 0.5, 0.0, 5.0, "hip offset per m/s of foot speed relative to the COM (eq. 6.1)"),
        Parameter("place_sideways", "bool", 0.0, 0.0, 1.0,
                  "1 = the hips also place the leading foot sideways by the COM's sideways speed, the "
                  "trailing one beneath its hip (a sideways jump); 0 = legs straight down sideways"),
        Parameter("swing_arms", "bool", 0.0, 0.0, 1.0,
                  "1 = swing the arms to arm_flexion in flight; 0 = hold them as the take-off left them"),
        Parameter("arm_flexion", "rad", 0.6, -1.0, 3.0,
                  "forward raise of the arms they swing to in flight (from a high take-off swing, down "
                  "and back to below 0 pitches the trunk back, so the feet can reach forward)"),
        Parameter("arm_time", "s", 0.3, 0.1, 1.0, "duration of that arm swing"),
        Parameter("arm_pitch_gain", "1", 0.0, 0.0, 10.0,
                  "with swing_arms: in flight the arms swing to arm_flexion less this many rad per rad the pelvis is "
                  "pitched forward of arm_pitch (and its pitch rate x arm_time), within -1..3 rad: swung down and back "
                  "as the landing's leg swing pitches the trunk forward, the arms turn it back (0 = arm_flexion alone)"),
        Parameter("arm_pitch", "rad", 0.6, -0.5, 1.5, "the pelvis pitch the arms' feedback (arm_pitch_gain) holds"),
        Parameter("spin_placement", "s/m", 0.0, 0.0, 0.5,
                  "landing a somersault: the feet land this factor x (somersault angular momentum / mass) "
                  "behind the COM for a backward spin, ahead for a forward one, so the ground force at "
                  "touchdown turns the spin back (0 = no spin term)"),
        Parameter("right_time", "s", 0.0, 0.0, 1.0,
                  "after touchdown the hips bring the trunk from its touchdown pitch to the balanced crouch's "
                  "over this time, along an ease (a long flight lands with the trunk pitched forward: righted "
                  "at once, the hips' push threw the man's 1.64 m jump back into the air, spinning backward); "
                  "0 = at once"),
        Parameter("untwist", "bool", 0.0, 0.0, 1.0,
                  "1 = the hips' rotation goes back to 0 in flight, turning the legs under a pelvis that a "
                  "turning take-off (liftoff_turn) left rotated against them; 0 = held as the take-off left it"),
        Parameter("toe_first_at_speed", "bool", 0.0, 0.0, 1.0,
                  "1 = a fast touchdown lands on the forefoot at any horizontal speed (the toe-down pitch is not "
                  "faded out by the COM's horizontal speed): down from a box, a 0.75 m drop landed flat at 1.5 m/s "
                  "forward sank the soles 3.7 cm into the ground and the shanks touched it; 0 = faded (flat feet "
                  "at speed)"),
        Parameter("delta_from_drop", "bool", 0.0, 0.0, 1.0,
                  "1 = the landing table's delta is read for the touchdown speed over the surface the feet are "
                  "above, through the flight (down from a box: the ground below once the feet have passed its edge); "
                  "0 = read once at lift-off (over the box stood on: a flat landing's delta)"),
        Parameter("blend_time", "s", 0.0, 0.0, 0.3,
                  "the joint targets blend from where the landing started to the landing's own over this "
                  "time (opening from a tuck: a gentler move keeps the flight's angular momentum constant "
                  "in the 1 ms step); 0 = at once"),
    )

    def __init__(self, params, ctx: ControlContext):
        super().__init__(params, ctx)
        self.constants = leap_constants(ctx.character.name)
        m, s = ctx.model, ctx.servos
        body = ctx.actor.body_id
        self.airborne = Airborne(m, ctx.actor.prefix)
        self.pelvis = body("PELVIS")
        self.feet = [body("FOOTR"), body("FOOTL")]
        self.hips = [body("ULEGR"), body("ULEGL")]
        self.leg = LegGeometry(ctx.character, "R")
        self.ankle_height = self.leg.ankle_height
        balance = Balance(Balance.schema.defaults(), ctx)
        self.ankle_front, self.ankle_back = balance.ankle_limit_front, balance.ankle_limit_back
        sites = [c["pos"] for c in ctx.character.body("FOOTR")["contacts"] + ctx.character.body("TOER")["contacts"]]
        self.sole_centre = 0.5 * (max(q[0] for q in sites) + min(q[0] for q in sites)) - ctx.character.joint_position("FOOTR")[0]
        self.idx = [{k: s.index[f"{j}_{side}_{a}"] for k, (j, a) in
                     {"hip_y": ("hip", "y"), "hip_x": ("hip", "x"), "knee": ("knee", "y"),
                      "ankle_y": ("ankle", "y"), "ankle_x": ("ankle", "x")}.items()} for side in "rl"]
        self.knees = s.indices(["knee_r_y", "knee_l_y"])
        self.hip_rotation = s.indices(["hip_r_z", "hip_l_z"])
        self.stage = "flight"
        self.calibrated_delta = None
        self.table_delta = foot_delta_lookup(ctx.character.name)
        self.last_fx = [None, None]
        self.last_fy = [None, None]
        self.hip_x_range = [tuple(m.jnt_range[ctx.actor.joint_id(f"hip_{side}_x")]) for side in "rl"]
        self.touchdown_knee_speed = None
        self.com_height = float(ctx.data.subtree_com[self.pelvis][2])
        self.mass = float(m.body_subtreemass[self.pelvis])
        self.finished_at = None
        self.torque_cap = None
        forcerange = m.actuator_forcerange[s.actuators, 1]
        limits = np.array([ctx.character.dofs[ctx.character.dof_index[n]].torque_limit for n in s.names])
        legs = s.indices([f"{j}_{side}_{a}" for j, a in (("hip", "y"), ("knee", "y"), ("ankle", "y"))
                          for side in "rl"])
        if (~m.actuator_forcelimited[s.actuators].astype(bool)[legs]).any() or (forcerange[legs] > limits[legs] * self.constants.landing_torque_limit).any():
            self.torque_cap = (legs, None, None, limits[legs] * self.constants.landing_torque_limit)   # (model's own gains)

    def start(self, t: float) -> None:
        s = self.ctx.servos
        s.offset[:] = 0.0
        s.hold(s.smoothed_target(t), t)
        stand = standing_hip_height(self.ctx.character)
        self.crouch = CrouchTable(self.ctx.model, self.ctx.character, np.linspace(0.5 * stand, stand, 6), stand,  # definition: 6 solved heights
                                  actor=self.ctx.actor)
        s.set_gains(np.arange(len(s.names)), s.default_kp, s.default_kv)     # undo the thrust gains
        # the arms swing in flight (their targets are set every tick: update() holds all targets)
        self.shoulders = s.indices(["shoulder_r_z", "shoulder_l_z"])
        self.arm_from = s.smoothed_target(t)[self.shoulders].copy()
        self.arm_to = np.array([1.0, -1.0]) * self.params["arm_flexion"]
        arm = Landing.schema.by_name["arm_flexion"]
        self.arm_range = (arm.minimum, arm.maximum)        # the feedback's flexion stays in the parameter's range
        self.arm_held, self.last_pitch = None, None
        self.started_at = t
        self.blend_from = s.smoothed_target(t).copy()
        self.event(t, "flight")

    @property
    def finished(self) -> bool:
        return self.finished_at is not None

    def _flight_knee(self, vx: float) -> float:
        """Knee bend held in flight: ``knee_flexion``, easing to ``fast_knee_flexion`` as the
        horizontal speed rises over CONSTANTS.fast_landing_speed (CONSTANTS.fast_backward_landing_speed moving backward;
        straighter legs reach further ahead of a fast COM and take the horizontal speed with the
        whole leg)."""
        p = self.params
        low, high = self.constants.fast_landing_speed if vx >= 0 else self.constants.fast_backward_landing_speed
        share = hermite_scalar((abs(vx) - low) / (high - low))
        return p["knee_flexion"] + (p["fast_knee_flexion"] - p["knee_flexion"]) * share

    def foot_wanted(self, vx: float, spin_offset: float) -> float:
        """Where the sole's centre is placed ahead of the COM in flight (eq. 6.1's goal): the foot lead
        time's worth of the horizontal speed, the calibrated and requested deltas and the spin term."""
        p = self.params
        return vx * p["foot_lead_time"] + self.calibrated_delta + p["foot_delta"] + spin_offset

    def _sideways_hip(self, k: int, d, com, vel, c: float, sn: float) -> float:
        """Hip abduction target for foot ``k``: eq. 6.1's servo across the body. The leading foot
        goes beside the COM where its sideways speed will be used up (the foot lead time's worth
        of it, beyond its hip's width); the trailing foot stays beneath its hip, so that the COM
        comes to rest between the feet (with both feet ahead it stopped beyond the trailing one
        and fell back). Positive hip_x swings a foot to the left."""
        p = self.params
        lateral = lambda point: -sn * (point[0] - com[0]) + c * (point[1] - com[1])
        hip, foot, pelvis = d.xpos[self.hips[k]], d.xpos[self.feet[k]], d.xpos[self.pelvis]
        vy = -sn * vel[0] + c * vel[1]
        width = lateral(hip) - lateral(pelvis)
        wanted = width + (vy * p["foot_lead_time"] if width * vy > 0 else 0.0)
        fy = lateral(foot)
        rate = 0.0 if self.last_fy[k] is None else (fy - self.last_fy[k]) / self.ctx.control_dt
        self.last_fy[k] = fy
        length = max(float(np.linalg.norm(hip - foot)), 0.3)   # definition: a guard, no leg is shorter
        reach = math.asin(max(-1.0, min(1.0, (wanted - lateral(hip)) / length)))
        roll = roll_of(d.xmat[self.pelvis], UP)       # a rolled pelvis swings the legs sideways with it
        target = reach - roll + p["foot_kp"] * (wanted - fy) - p["foot_kv"] * rate
        low, high = self.hip_x_range[k]
        return min(max(target, low), high)

    def update(self, t: float) -> None:
        d, s = self.ctx.data, self.ctx.servos
        p = self.params
        m = d.xmat[self.pelvis].tolist()
        yaw = math.atan2(m[3], m[0])
        c, sn = math.cos(yaw), math.sin(yaw)
        com = d.subtree_com[self.pelvis]
        vel = d.subtree_linvel[self.pelvis]
        vx = c * vel[0] + sn * vel[1]
        angles, velocities = s.angles(), s.velocities()
        targets = s.smoothed_target(t)
        pelvis_pitch = math.atan2(-m[6], m[8])
        crouch_pitch = 0.0
        if self.stage != "flight":
            # while the knees give, the hips pitch the trunk as a balanced crouch of this height would
            hips = 0.5 * (d.xpos[self.hips[0]] + d.xpos[self.hips[1]])
            feet = 0.5 * (d.xpos[self.feet[0]] + d.xpos[self.feet[1]])
            crouch_pitch = float(self.crouch.at(float(hips[2] - feet[2]) + self.ankle_height)[3])
        ankle_command = 0.0
        if self.stage != "flight":
            points = self.airborne.support.supporting_points(d)
            px = c * points[:, 0] + sn * points[:, 1]
            com_x = c * com[0] + sn * com[1]
            ankle_command = self.constants.com_kp * (com_x - 0.5 * (px.min() + px.max())) + self.constants.com_kv * vx
        toe_point = 0.0
        if self.stage == "flight":
            # a fast touchdown lands on the forefoot so the ankles absorb the first impact
            feet_height = max(float(self.airborne.feet_heights(d).min()), 0.0)
            touchdown_speed = math.sqrt(vel[2] * vel[2] + 2.0 * GRAVITY * feet_height)
            toe_point = min(max(self.constants.toe_point_per_speed * (touchdown_speed - self.constants.toe_point_from), 0.0), self.constants.toe_point_max)
            # moving forward or back fast, the feet land flat: the whole sole has to stop the COM's
            # horizontal speed (the forefoot alone would let the ankles give way)
            if not p.get("toe_first_at_speed", 0.0):
                toe_point *= min(max((self.constants.toe_fade_speed[1] - abs(vx)) / (self.constants.toe_fade_speed[1] - self.constants.toe_fade_speed[0]), 0.0), 1.0)
        if self.stage == "flight" and self.airborne.touching(d):
            self.stage = "absorb"
            self.ctx.step_division = 1      # a flight run at a finer physics step lands at the model's
            self.touchdown_knee_speed = max(abs(float(velocities[self.knees].mean())), 1e-3)  # definition: a guard
            self.knees_touched_at = angles[self.knees].copy()
            s.set_gains(self.knees, s.default_kp[self.knees] * self.constants.soft_knee_kp, s.default_kv[self.knees] * self.constants.soft_knee_kv)
            self.touchdown_at = t
            self.touchdown_pitch = pelvis_pitch
            self.event(t, "touchdown")
        elif self.stage == "absorb" and abs(float(velocities[self.knees].mean())) < self.constants.knee_restore * self.touchdown_knee_speed:
            self.stage = "settle"
            self.knees_stopped_at = angles[self.knees].copy()
            s.set_gains(self.knees, s.default_kp[self.knees], s.default_kv[self.knees])
            self.event(t, "knees_restored")
        if self.finished_at is None and (self.stage == "settle" or (
                self.stage == "absorb" and t - self.touchdown_at > self.constants.absorb_time)):
            self.finished_at = t
        knee = self._flight_knee(vx) if self.stage == "flight" else None
        if knee is not None and t - self.started_at < p.get("tuck_time", 0.0):
            knee = max(knee, p["tuck_knee_flexion"])    # the tuck: the thigh servo keeps the foot's place, so the feet rise
        spin_offset = 0.0
        if self.stage == "flight" and p["spin_placement"]:
            # against the somersault angular momentum (about the body's lateral axis), per unit mass
            h = d.subtree_angmom[self.pelvis]
            spin_offset = p["spin_placement"] * (-sn * float(h[0]) + c * float(h[1])) / self.mass
        if self.stage == "flight" and (self.calibrated_delta is None or p.get("delta_from_drop", 0.0)):
            # the landing table's delta for this flight's horizontal and touchdown speeds (delta_from_drop: read again
            # each step, for the surface the feet are now above)
            self.calibrated_delta = self.table_delta(vx, touchdown_speed) if p.get("landing_table", 1.0) else 0.0
        for k in (0, 1):
            j = self.idx[k]
            f = d.xmat[self.feet[k]].tolist()
            foot_pitch = math.atan2(-f[6], f[8])
            foot_roll = math.atan2(f[7], f[8])
            targets[j["ankle_y"]] = angles[j["ankle_y"]] - foot_pitch      # feet parallel to the ground
            if self.stage == "flight":
                targets[j["ankle_y"]] += toe_point
            targets[j["ankle_x"]] = angles[j["ankle_x"]] - foot_roll
            if self.stage != "flight":
                # on the ground the ankles already servo the COM over the feet (eq. 7.1), within
                # what the feet can take, while the knees absorb
                targets[j["ankle_y"]] += min(max(ankle_command, -self.ankle_back), self.ankle_front)
            if self.stage == "flight":
                # eq. 6.1: a PD servo on the foot's place relative to the COM, aiming where the COM's
                # horizontal speed will be used up (capture point) plus the foot servo delta; the
                # thigh is aimed in the world frame, so a pitching pelvis does not swing the feet
                foot = d.xpos[self.feet[k]]            # the ankle; the sole's centre is ahead of it
                fx = c * (foot[0] - com[0]) + sn * (foot[1] - com[1]) + self.sole_centre
                fx_rate = 0.0 if self.last_fx[k] is None else (fx - self.last_fx[k]) / self.ctx.control_dt
                self.last_fx[k] = fx
                wanted = self.foot_wanted(vx, spin_offset)
                hip = d.xpos[self.hips[k]]
                hip_from_com = c * (hip[0] - com[0]) + sn * (hip[1] - com[1])
                thigh_pitch = self.leg.thigh_pitch_for(wanted - self.sole_centre - hip_from_com, knee)
                correction = -p["foot_kp"] * (wanted - fx) + p["foot_kv"] * fx_rate     # eq. 6.1
                targets[j["knee"]] = knee
                targets[j["hip_y"]] = thigh_pitch - pelvis_pitch + correction
                targets[j["hip_x"]] = self._sideways_hip(k, d, com, vel, c, sn) if p["place_sideways"] else 0.0
            else:
                # hips keep the pelvis upright while the knees give (from the touchdown pitch over
                # right_time, if set); the knees are pure dampers while absorbing, then hold where they stopped
                wanted_pitch = crouch_pitch
                if p["right_time"]:
                    share = hermite_scalar((t - self.touchdown_at) / p["right_time"])
                    wanted_pitch = self.touchdown_pitch + (crouch_pitch - self.touchdown_pitch) * share
                targets[j["hip_y"]] = angles[j["hip_y"]] + (pelvis_pitch - wanted_pitch)
                if self.stage == "absorb":
                    targets[j["knee"]] = self.knees_touched_at[k]
                else:
                    targets[j["knee"]] = self.knees_stopped_at[k]
        if p["untwist"]:
            targets[self.hip_rotation] = 0.0
        if p["blend_time"] and t - self.started_at < p["blend_time"]:
            share = hermite_scalar((t - self.started_at) / p["blend_time"])
            targets = self.blend_from + (targets - self.blend_from) * share
        if self.torque_cap is not None:
            # the servo's torque kp (target - q) - kv dq kept within the human limits by the target
            legs, _, _, cap = self.torque_cap
            kp = self.ctx.model.actuator_gainprm[s.actuators][legs, 0]
            kv = -self.ctx.model.actuator_biasprm[s.actuators][legs, 2]
            q, dq = angles[legs], velocities[legs]
            torque = np.clip(kp * (targets[legs] + s.offset[legs] - q) - kv * dq, -cap, cap)
            targets[legs] = q + (torque + kv * dq) / kp - s.offset[legs]
        if p["swing_arms"]:
            swing = hermite_scalar((t - self.started_at) / p["arm_time"])
            arm_to = self.arm_to
            if p["arm_pitch_gain"] and self.stage == "flight":
                pitch_rate = 0.0 if self.last_pitch is None else (pelvis_pitch - self.last_pitch) / self.ctx.control_dt
                ahead = pelvis_pitch + pitch_rate * p["arm_time"] - p["arm_pitch"]
                flexion = min(max(p["arm_flexion"] - p["arm_pitch_gain"] * ahead, self.arm_range[0]), self.arm_range[1])
                arm_to = np.array([1.0, -1.0]) * flexion
                self.arm_held = arm_to
            elif self.arm_held is not None:
                arm_to = self.arm_held          # on the ground the arms stay where the flight's feedback left them
            targets[self.shoulders] = self.arm_from + (arm_to - self.arm_from) * swing
        self.last_pitch = pelvis_pitch
        s.hold(targets, t)



def balance_after_landing(ctx: ControlContext, landing: Landing) -> Balance:
    """Balance that starts from the crouch ``landing`` (the landing that just ended) landed in and
    stands up. The crouch is the one of the landing's crouch table whose hip-to-ankle distance is
    the landed legs' (the balance's knees servo that distance): with the feet landed ahead of the
    hips, the vertical height would name a shorter leg, and the knees would snap up to it and pull
    the feet off the ground."""
    d, body = ctx.data, ctx.actor.body_id
    hips = 0.5 * (d.xpos[body("ULEGR")] + d.xpos[body("ULEGL")])
    feet = 0.5 * (d.xpos[body("FOOTR")] + d.xpos[body("FOOTL")])
    leg_length = float(np.linalg.norm(hips - feet))
    height = float(np.interp(leg_length, landing.crouch.table[:, 4], landing.crouch.heights))
    return Balance(inside_a_skill(move_start=0.0, move_time=landing.constants.balance_handover_time, return_to_stand=0), ctx,
                   from_height=height)


def leap_assess(trajectory, squat_floor: float | None = None, start: float = 0.0) -> tuple[str, dict]:
    """Outcome of a skill with a flight phase: no fall, the feet stay where they touched down
    (``landing_skid``: the middle of the feet moves at most LANDING_SKID_LIMIT until they settle),
    ends still and standing; measured COM rise and travel, flight time, peak vertical ground
    reaction force (body weights). ``squat_floor``: the pelvis height the crouch before the take-off
    may go down to (a deliberate squat; see standard_metrics); None = half its standing height.
    ``start``: the leap's own crouch began then (s; a run that turned first by hops, turn.jump_start):
    the flights before it are not the leap's."""
    a = trajectory.arrays
    flying = feet_above_surface(trajectory).min(axis=1) > AIRBORNE_HEIGHT
    if start:
        flying &= a["time"] >= start
    first = int(np.argmax(flying))                      # the take-off frame (0 when it never flies)
    metrics = standard_metrics(trajectory, squat=(first, squat_floor) if squat_floor is not None else None)
    t = a["time"]
    com = a["com"]
    metrics["com_rise"] = float(com[:, 2].max() - com[0, 2])
    metrics["com_travel"] = float(com[-1, 0] - com[0, 0])
    metrics["com_travel_y"] = float(com[-1, 1] - com[0, 1])
    if flying.any():
        last = len(flying) - 1 - int(np.argmax(flying[::-1]))
        metrics["liftoff_time"] = float(t[first])
        metrics["touchdown_time"] = float(t[min(last + 1, len(t) - 1)])
        metrics["flight_time"] = metrics["touchdown_time"] - metrics["liftoff_time"]
        weight = GRAVITY * trajectory.meta["total_mass"]
        metrics["peak_thrust_grf_body_weights"] = float(a["grf"][:first + 1, 2].max() / weight)
        metrics["peak_landing_grf_body_weights"] = float(a["grf"][last:, 2].max() / weight) if last < len(t) else 0.0
        metrics["liftoff_angular_momentum"] = float(a["angmom"][first, 1])
        metrics["liftoff_horizontal_speed"] = float(a["com_vel"][first, 0])
        after = a["support_points"][last + 1:, :, :2]
        settle = min(int(CONSTANTS.settle_time * trajectory.meta["control_rate"]), len(after) - 1)
        # a recovery step (the landing's landing_recovery_step): the feet are judged until it began, the step
        # is reported (its time), not a slide
        steps = [float(e[0]) for e in trajectory.meta.get("phase_events", ()) if e[1] == RECOVERY_STEP_EVENT]
        metrics["recovery_step"] = bool(steps)
        if steps:
            metrics["recovery_step_time"] = steps[0]
            before = max(int(np.searchsorted(t, steps[0])) - (last + 1), 1)
            after = after[:before]
            settle = min(settle, len(after) - 1)
        metrics["foot_slide_after_landing"] = float(
            np.linalg.norm(after - after[settle], axis=2).max()) if len(after) else 0.0
        # a jump travels: the standard "stepped" (a foot away from where it stood at the start)
        # would always hold; after a flight it is the landing's (a foot sliding from where it settled)
        metrics["stepped"] = bool(metrics["foot_slide_after_landing"] > LANDING_SLIDE_LIMIT)
        # the middle of the feet from the first touchdown until they have settled: feet that skate
        # or bounce back under the body have not landed where they touched down
        down = ~flying[first:]
        first_touchdown = first + int(np.argmax(down)) if down.any() else len(t) - 1
        middle = a["support_points"][first_touchdown:last + 2 + settle, :, :2].mean(axis=1)
        metrics["landing_skid"] = float(np.linalg.norm(middle - middle[0], axis=1).max())
    else:
        metrics["flight_time"] = 0.0
        metrics["foot_slide_after_landing"] = 0.0
        metrics["landing_skid"] = 0.0
    if metrics["fell"]:
        return "fell", metrics
    if metrics["flight_time"] == 0.0 and trajectory.meta["behaviour"] != "land":
        return "no_flight", metrics
    if metrics["foot_slide_after_landing"] > LANDING_SLIDE_LIMIT:
        return "stepped", metrics
    if metrics["landing_skid"] > LANDING_SKID_LIMIT:
        return "skidded", metrics
    if metrics["final_com_speed"] >= 0.1:          # criterion: TARGETS.md "still", COM below 0.1 m/s
        return "not_still", metrics
    return "success", metrics


LANDING_SETTINGS = Schema(
    Parameter("foot_delta", "m", 0.0, -0.3, 0.3,
              "foot servo delta the landing adds to its capture-point placement (Table 6.1's role)"))
# the landing plan's hand-set constants (sim_core/planning/land.py reads them): landing_any.json's "constants"
LANDING_CONSTANTS = Schema(
    constant("plan_step_share", "1", 0.05, 1.0,
             "share of calibrate land's delta step (the man's 2 cm x L) the landing's plan steps foot_delta by "
             "either side of the table's placement (balanced windows at 2-3 m/s can be 1 cm wide around a "
             "placement that falls)"),
)


def _landing_rows(body: dict):
    for row in body.get("foot_delta", []):
        for speed, delta in zip(row["speed"], row["delta"]):
            yield f"foot_delta drop {row['drop']:g} m, speed {speed:g} m/s", {"foot_delta": delta}
    fast = body.get("fast_touchdown")
    if fast:
        yield "fast_touchdown", {"foot_delta": fast["delta"]}
    yield from constant_rows(body)


def foot_delta_row(table: dict, horizontal_speed: float, touchdown_speed: float) -> float:
    """Interpolated over the horizontal speed in each drop's row, then over the vertical touchdown
    speed between the drops, plus the extra for a fast touchdown (a high drop or leap), which
    ramps in from ``speed`` over ``ramp`` m/s of expected vertical touchdown speed."""
    rows = [row for row in table["foot_delta"] if row["speed"]]
    if not rows:
        return 0.0
    by_drop = [float(np.interp(horizontal_speed, row["speed"], row["delta"])) for row in rows]
    delta = float(np.interp(touchdown_speed, [row["touchdown_speed"] for row in rows], by_drop))
    fast = table.get("fast_touchdown")
    if fast:
        delta += fast["delta"] * min(max((touchdown_speed - fast["speed"]) / fast["ramp"], 0.0), 1.0)
    return delta


def landing_speeds(table: dict) -> tuple[float, float]:
    """The horizontal speeds a landing table offers: its rows' common span (every drop's row serves
    them), within the table's ``offered_speeds`` if it names them (``adapt`` writes the span its
    check measured, so a body is offered no speed its rows reach unchecked)."""
    rows = [row for row in table["foot_delta"] if row["speed"]]
    if not rows:
        raise ParameterError("the landing table serves no horizontal speed: no landing of its calibration ended "
                             "balanced (python -m sim_core calibrate land)")
    low, high = max(min(row["speed"]) for row in rows), min(max(row["speed"]) for row in rows)
    offered = table.get("offered_speeds")
    return (low, high) if offered is None else (max(low, offered[0]), min(high, offered[1]))


def landing_drops(table: dict, speed: float) -> tuple[float, float]:
    """The drops (m; a start's drop is its vertical touchdown speed's v^2 / 2g) a landing table offers at
    the horizontal ``speed``: those its ``drop_limits`` measured at that speed (``python -m sim_core
    calibrate land --drop-limits``; between two measured speeds the narrower of the two); a table
    without them (a body ``adapt`` made) offers its rows' lowest to highest drop, what its check ran
    (measured on the man: a drop of 0 at 0.5 m/s falls)."""
    limits = table.get("drop_limits")
    if limits is None:
        drops = [row["drop"] for row in table["foot_delta"] if row["speed"]]
        return min(drops), max(drops)
    speeds = limits["speeds"]
    i = int(np.searchsorted(speeds, speed))
    near = [i] if i < len(speeds) and speeds[i] == speed else [j for j in (i - 1, i) if 0 <= j < len(speeds)]
    return max(limits["low"][i] for i in near), min(limits["high"][i] for i in near)


def landing_side_speed(table: dict, drop: float) -> float:
    """The sideways COM speed (m/s, either way) a landing table offers from ``drop`` (m): its
    ``drop_limits``' measured one (the least landed from its highest row's drop at every forward
    speed tried) up to that drop; from higher, and on a table without them, 0 (straight ahead only:
    measured, the man from 1.26 m with 0.25 m/s sideways fell)."""
    limits = table.get("drop_limits")
    top = max(row["drop"] for row in table["foot_delta"] if row["speed"])
    return 0.0 if limits is None or drop > top else limits["side"]


LANDING_TABLE = register_table(TableType("landing", with_constants(LANDING_SETTINGS, LANDING_CONSTANTS), _landing_rows,
                                         (foot_delta_row,)))


def foot_delta_lookup(character: str) -> Callable[[float, float], float]:
    """The foot servo delta of python -m sim_core calibrate land's table (0 where there is none) for a
    horizontal speed and an expected vertical touchdown speed (foot_delta_row), the table read once: for
    lookups made every control step (the commanded thrust's lift-off velocity, the landing in flight)."""
    table = load("landing", character)
    if table is None:
        return lambda horizontal_speed, touchdown_speed: 0.0
    return lambda horizontal_speed, touchdown_speed: foot_delta_row(table, horizontal_speed, touchdown_speed)


# ------------------------------------------------------------------------------- leap mapping
def rise_tolerance(height: float) -> float:
    """TARGETS.md's tolerance of a vertical leap's COM rise: +-10 %, or +-3 cm below 0.3 m."""
    return 0.03 if height < 0.3 else 0.1 * height     # criterion: TARGETS.md's leap tolerance


UNCOVERED_STEP = 0.005          # m: commanded heights checked for a calibrated row within the tolerance


def height_grid(rises, step: float) -> list[float]:
    """Commanded heights ``step`` apart from 0.1 m (TARGETS.md's lowest leap) to the highest
    calibrated rise, or 1 m."""
    if not len(rises):
        return []
    return [float(h) for h in np.round(np.arange(0.1, min(max(rises), 1.0) + 1e-9, step), 3)]  # criterion: TARGETS.md


def uncovered_gaps(rises) -> list[tuple[float, float]]:
    """The commanded heights (height_grid, UNCOVERED_STEP apart) that no calibrated row's measured
    rise is within the tolerance of - the leap interpolates those, and may miss or fall - as
    intervals (first, last); python -m sim_core calibrate leap --fill tries more crouches in them."""
    gaps = []
    for h in height_grid(rises, UNCOVERED_STEP):
        if min(abs(r - h) for r in rises) <= rise_tolerance(h):
            continue
        if gaps and h - gaps[-1][1] < 1.5 * UNCOVERED_STEP:    # definition: the next grid height
            gaps[-1] = (gaps[-1][0], h)
        else:
            gaps.append((h, h))
    return gaps


def commandable_heights(rises) -> tuple[float, float]:
    """The commanded heights a vertical leap table serves: those whose TARGETS.md tolerance
    (rise_tolerance) reaches a calibrated rise - below the lowest and above the highest, the end
    leap runs while it is within the tolerance of the command."""
    bottom, top = min(rises), max(rises)
    low = bottom - 0.03 if bottom - 0.03 < 0.3 else bottom / 1.1            # criterion: rise_tolerance's inverse
    high = top + 0.03 if top + 0.03 < 0.3 else max(top / 0.9, 0.3)         # criterion: rise_tolerance's inverse
    return low, high


def run_strength(ctx: ControlContext) -> str:
    """The strength a calibration is kept under: "human" for the human torque limits (or a factor
    of them), "unlimited" when the leg servos have no torque limit."""
    knee = ctx.servos.index["knee_r_y"]
    return "human" if ctx.model.actuator_forcelimited[ctx.servos.actuators][knee] else "unlimited"


def vertical_key(ctx: ControlContext) -> str:
    """The vertical-leap table for this run's strength: "vertical" or "vertical_unlimited"."""
    return vertical_table(run_strength(ctx))


def vertical_table(strength: str) -> str:
    """The vertical-leap table of a strength ("human" or "unlimited", run_strength's names)."""
    return "vertical" if strength == "human" else "vertical_unlimited"


# the commanded take-off's flight and the landing arms' pitch feedback: the leap's parameters (its schema,
# skills/leap) that a planned jump's settings also name (a commanded plan, planning/commanded.py)
FLIGHT_TARGET_X = Parameter("flight_target_x", "m", 1.0, -2.5, 2.5,
                            "commanded take-off (low_level, commanded_takeoff=1): the feet land this far forward of the "
                            "middle of the feet at the start")
FLIGHT_TARGET_Y = Parameter("flight_target_y", "m", 0.0, -2.5, 2.5,
                            "commanded take-off: the feet land this far to the left (+) of the middle of the feet at the start")
TURN_ANGLE = Parameter("turn_angle", "rad", 0.0, -1.2, 1.2,
                       "before the leap one hop turns the body about the vertical by about this much (counter-clockwise "
                       "from above: + to the left; control/turn.py), then the leap runs forward in the new heading and a "
                       "commanded take-off (commanded_takeoff) aims at its flight target from the start's feet (0 = no turn)")
LANDING_ARM_PITCH_GAIN = Parameter(
    "landing_arm_pitch_gain", "1", 0.0, 0.0, 10.0,
    "landing: with landing_swing_arms, the arms swing this many rad further down and back per rad the "
    "pelvis is (about to be) pitched forward of landing_arm_pitch (0 = to landing_arm_flexion alone)")
LANDING_ARM_PITCH = Parameter("landing_arm_pitch", "rad", 0.6, -0.5, 1.5, "landing: the pelvis pitch the arms' feedback holds")
LANDING_RECOVERY_STEP = Parameter(
    "landing_recovery_step", "1", 0.0, 0.0, 1.0,
    "landing: above 0.5, once the feet are down the capture point is watched: when it comes within "
    "landing_step_margin of the support's edge (or past it) a foot steps to where it goes and the stance the feet "
    "end in is held, standing up (control/recovery_step.py StepAndHold; a 'recovery_step' event); 0 = the balance")
LANDING_STEP_MARGIN = Parameter("landing_step_margin", "m", 0.03, -0.2, 0.3,
                                "landing: with landing_recovery_step, a step once the capture point is this close to the "
                                "support's edge")
LANDING_TUCK_KNEE_FLEXION = Parameter(
    "landing_tuck_knee_flexion", "rad", 0.0, 0.0, 2.4,
    "landing: the knee bend held in flight from lift-off for landing_tuck_share of flight_air_time (the feet drawn up "
    "over a box's front edge), then the landing's")
LANDING_TOE_FIRST_AT_SPEED = Parameter(
    "landing_toe_first_at_speed", "bool", 0.0, 0.0, 1.0,
    "landing: 1 = a fast touchdown lands on the forefoot at any horizontal speed (the landing's toe_first_at_speed: "
    "a high drop landed flat sinks the soles until the shanks touch the ground); 0 = flat feet at speed")
LANDING_DELTA_FROM_DROP = Parameter(
    "landing_delta_from_drop", "bool", 0.0, 0.0, 1.0,
    "landing: 1 = the landing table's delta is read for the touchdown speed on the surface landed on (the landing's "
    "delta_from_drop; down from a box, the drop to the ground below), and the commanded take-off aims with it; 0 = "
    "for the lift-off's vertical speed (a flat landing's)")
LANDING_TUCK_SHARE = Parameter("landing_tuck_share", "1", 0.0, 0.0, 1.0,
                               "landing: the share of flight_air_time the tuck is held from lift-off (0 = no tuck)")
LEAN_PUSH = Parameter("lean_push", "1", 0.0, 0.0, 10.0,
                      "commanded take-off: the push's forward speed per unit of lean as the commanded_lean_push "
                      "constant, for a row measured with its own (a commanded table's long row); 0 = the character's constant")
RECOVERY_STEP_EVENT = "recovery_step"     # the phase event of a landing's recovery step (leap_assess reads it)

# the leap's low-level settings: the columns of a vertical-leap table, a broad jump's and a planned
# jump's settings (sim_core.planning.jump searches them); a default is what a row that does
# not name the setting runs with
LEAP_SETTINGS = Schema(
    Parameter("crouch_height", "m", 0.65, 0.2, 0.95, "pelvis height of the crouch (a child's is lower: 0.2 m floor)"),
    Parameter("crouch_pitch", "rad", 0.0, 0.0, 1.8, "torso pitch in the crouch"),
    Parameter("com_offset", "m", 0.0, -0.05, 0.25, "COM ahead (+) of the middle of the feet in the crouch"),
    Parameter("com_offset_y", "m", 0.0, -0.2, 0.2, "COM to the left (+) of the middle of the feet in the crouch"),
    Parameter("liftoff_hip", "rad", 0.0, -1.0, 1.0, "hip flexion (-) or extension (+) at lift-off"),
    Parameter("liftoff_roll", "rad", 0.0, -0.5, 0.5, "hip abduction at lift-off (a sideways jump's roll)"),
    Parameter("vertical_thrust", "1", 0.0, 0.0, 1.0, "share of the vertical leap's thrust timing in a broad jump's"),
    Parameter("arm_swing", "rad", 1.0, 0.0, 3.2, "arm swing forward and up in the thrust"),
    Parameter("thrust_damping", "1", CONSTANTS.thrust_damping_default, 0.1, 1.0, "share of the stiffened servos' damping kept in the thrust"),
    Parameter("foot_delta", "m", 0.0, -0.3, 0.3, "landing: foot servo delta"),
    Parameter("landing_swing_arms", "1", 0.0, 0.0, 1.0, "landing: above 0.5 the arms swing to landing_arm_flexion in flight"),
    Parameter("landing_arm_flexion", "rad", 0.6, -1.0, 3.0, "landing: shoulder flexion"),
    Parameter("landing_foot_lead_time", "s", 0.2, 0.0, 0.6, "landing: the feet land this long of COM travel ahead"),
    Parameter("landing_right_time", "s", 0.0, 0.0, 1.0, "landing: the trunk righted over this time after touchdown (0 = at once)"),
    Parameter("crouch_arms", "rad", 0.0, -0.8, 0.0, "shoulder flexion in the crouch (back: -)"),
    Parameter("thrust_lean", "m", 0.0, -0.2, 0.1, "COM ahead (+) of the feet along the thrust's extension"),
    Parameter("spin_hold", "rad/(kg m²/s)", 0.0, 0.0, 0.5, "the hips turn against the spin about the vertical"),
    Parameter("turn_first", "1", 0.0, -1.5, 1.5,
              "above 0.5 the leap first turns a quarter to the right by hops (turn.py; 1: the measured turn, "
              "each hop's hip rotation scaled by it), below -0.5 to the left"),
    Parameter("commanded_takeoff", "1", 0.0, 0.0, 1.0,
              "above 0.5 the thrust servoes the COM velocity to the commanded flight's lift-off velocity and "
              "ends on reaching it (control/commanded_thrust.py)"),
    FLIGHT_TARGET_X, FLIGHT_TARGET_Y, TURN_ANGLE, LANDING_ARM_PITCH_GAIN, LANDING_ARM_PITCH, LANDING_RECOVERY_STEP, LANDING_STEP_MARGIN,
    LEAN_PUSH, LANDING_TUCK_KNEE_FLEXION, LANDING_TUCK_SHARE, LANDING_TOE_FIRST_AT_SPEED,
    LANDING_DELTA_FROM_DROP,
)
LEAP_MEASURED = ("com_rise", "com_travel", "peak_thrust_grf_body_weights")   # columns a calibration measured


def _leap_rows(body: dict):
    for key in ("vertical", "vertical_unlimited"):
        columns = body.get(key, {})
        settings = [n for n in columns if n not in LEAP_MEASURED]
        for k in range(len(columns.get("com_rise", []))):
            yield f"{key} row {k}", {n: columns[n][k] for n in settings}
    for k, row in enumerate(body.get("broad", {}).get("settings", [])):
        yield f"broad row {k}", row
    yield from constant_rows(body)


def vertical_row(columns: dict, height: float) -> dict:
    """The calibrated vertical leap nearest the commanded height when its measured rise is within
    the tolerance (rise_tolerance), else interpolated over the measured rise between the rows
    around it (a column a table lacks at its schema default). The rise is not smooth between rows
    whose thrust differs (a damped and an undamped extension, another crouch): an interpolated
    leap between them can miss or fall where both rows land, so a measured row is preferred."""
    rises = columns["com_rise"]
    nearest = min(rises, key=lambda rise: abs(rise - height))
    h = nearest if abs(nearest - height) <= rise_tolerance(height) else height
    default = LEAP_SETTINGS.defaults()
    column = lambda name: float(np.interp(h, rises, columns.get(name, [default[name]] * len(rises))))
    return {"crouch_height": column("crouch_height"), "crouch_pitch": column("crouch_pitch"),
            "com_offset": column("com_offset"), "arm_swing": column("arm_swing"),
            "thrust_damping": column("thrust_damping"), "foot_delta": column("foot_delta"), "liftoff_hip": column("liftoff_hip")}


BROAD_FLAGS = ("low_level", "distance", "vertical_thrust", "landing_swing_arms", "landing_place_sideways")
# a broad row's parameters (and plan settings) that are switches, not quantities (distance > 0: the
# broad jump's thrust, 0: the vertical leap's), taken whole from the nearer row when blending two


def broad_tolerance(distance: float) -> float:
    """TARGETS.md's tolerance of a broad jump's COM travel: +-10 %."""
    return 0.1 * distance          # criterion: TARGETS.md's broad jump tolerance


def broad_rows(broad: dict) -> tuple[np.ndarray, list[dict]]:
    """The calibrated broad jumps (their leap parameters) in order of measured COM travel, each
    travelling further than the one before (calibrate leap stores them so; a row that does not is
    dropped, so the travel is an increasing function of the row and can be interpolated)."""
    travels, rows = [], []
    for k in sorted(range(len(broad["com_travel"])), key=lambda k: broad["com_travel"][k]):
        if not travels or broad["com_travel"][k] > travels[-1]:
            travels.append(float(broad["com_travel"][k]))
            rows.append(broad["params"][k])
    return np.asarray(travels), rows


def broad_distances(travels) -> tuple[float, float]:
    """The commanded distances a broad-jump table serves: its calibrated travels, and beyond the
    shortest and longest while that end row's travel is within TARGETS.md's 10 % of the command."""
    return min(travels) / 1.1, max(travels) / 0.9      # criterion: broad_tolerance, inverted


def broad_gaps(travels) -> list[tuple[float, float]]:
    """The commanded distances between the shortest and the longest calibrated travel (UNCOVERED_STEP
    apart) that no calibrated row's measured travel is within the tolerance of (broad_tolerance) -
    the broad jump interpolates those, and may miss or fall - as intervals (first, last);
    python -m sim_core calibrate leap --fill --only broad adds rows in them."""
    gaps = []
    if not len(travels):
        return gaps
    for d in np.round(np.arange(min(travels), max(travels) + 1e-9, UNCOVERED_STEP), 3):
        if min(abs(t - d) for t in travels) <= broad_tolerance(d):
            continue
        if gaps and d - gaps[-1][1] < 1.5 * UNCOVERED_STEP:    # definition: the next grid distance
            gaps[-1] = (gaps[-1][0], float(d))
        else:
            gaps.append((float(d), float(d)))
    return gaps


def broad_position(travels: np.ndarray, distance: float) -> tuple[int, float]:
    """Where ``distance`` falls among the measured travels: the row k below it and the share w of
    the way to row k + 1 (0 at or before the first row; the last row with w = 0 at or past it)."""
    if distance <= travels[0]:
        return 0, 0.0
    if distance >= travels[-1]:
        return len(travels) - 1, 0.0
    k = int(np.searchsorted(travels, distance, side="right")) - 1
    return k, float((distance - travels[k]) / (travels[k + 1] - travels[k]))


def blend_rows(a: dict, b: dict, w: float) -> dict:
    """Row ``a`` moved the share ``w`` of the way to row ``b``: each quantity linearly, each switch
    (BROAD_FLAGS) from the nearer row; w = 0 is ``a`` itself, value for value."""
    if w == 0.0:
        return dict(a)
    near = a if w < 0.5 else b          # definition: the nearer row
    names = list(a) + [n for n in b if n not in a]
    return {n: a[n] + w * (b[n] - a[n]) if n in a and n in b and n not in BROAD_FLAGS
            else near.get(n, a.get(n, b.get(n))) for n in names}


def broad_row(broad: dict, distance: float) -> dict:
    """The leap parameters of a broad jump to ``distance``: the calibrated broad jump whose measured
    COM travel is nearest, exactly, when that is within the tolerance (broad_tolerance), else those
    of the two rows whose travels bracket it interpolated linearly in the travel (broad_position,
    blend_rows; beyond the ends the end row). A row is a knife edge - a millimetre more crouch can
    turn its balanced landing into a fall, and a blend of two rows falls more often than not - so
    a measured row is preferred and calibrate leap --fill --only broad adds rows where none is near."""
    travels, rows = broad_rows(broad)
    nearest = int(np.argmin(np.abs(travels - distance)))
    if abs(travels[nearest] - distance) <= broad_tolerance(distance):
        return dict(rows[nearest])
    k, w = broad_position(travels, distance)
    return blend_rows(rows[k], rows[min(k + 1, len(rows) - 1)], w)


LEAP_TABLE = register_table(TableType("leap", with_constants(LEAP_SETTINGS, LEAP_CONSTANTS), _leap_rows,
                                      (vertical_row, broad_row)))


def load_mapping(character: str) -> dict:
    """The character's leap table, else the design table every character starts from (leap_any)."""
    return load("leap", character) or load("leap", "any")


# the settings a low-level leap (low_level=1) runs with, by the names the leap table and the jump plans use
LOW_LEVEL_SETTINGS = Schema(
    Parameter("crouch_height", "m", 0.65, 0.2, 0.95, "pelvis height of the crouch (low_level only)"),
    Parameter("crouch_pitch", "rad", 1.0, 0.0, 1.8, "torso pitch in the crouch (low_level only)"),
    Parameter("com_offset", "m", 0.0, -0.05, 0.25, "COM forward of the feet in the crouch (low_level only)"),
    Parameter("com_offset_y", "m", 0.0, -0.2, 0.2,
              "COM to the left of the feet in the crouch: a sideways jump (low_level only)"),
    Parameter("liftoff_roll", "rad", 0.0, -0.5, 0.5,
              "hip abduction at lift-off for a sideways jump (+ swings the feet to the left, pushing the "
              "body to the right): sets the roll rate, as the lift-off hip angle sets the somersault "
              "rate (low_level only)"),
    Parameter("thrust_lean", "m", 0.0, -0.2, 0.1,
              "COM forward of the feet along the thrust's path of balanced poses: - pushes the body back "
              "(a sideways jump of the woman otherwise leaves moving forward; low_level only)"),
    Parameter("spin_hold", "rad/(kg m²/s)", 0.0, 0.0, 0.5,
              "the hips turn against the body's angular momentum about the vertical in the crouch and the "
              "thrust, this much hip rotation per kg m²/s (0 = not held): a sideways jump's push at the "
              "forefeet, ahead of the COM, twists the body (low_level only)"),
    Parameter("turn_first", "1", 0.0, -1.5, 1.5,
              "above 0.5 the leap first turns a quarter to the right (clockwise from above) by hops that turn, "
              "below -0.5 to the left (1: the measured quarter turn, more or less turns each hop more or less), "
              "then leaps forward in its new heading: a sideways jump made a forward one (0 = no turn; low_level only)"),
    TURN_ANGLE,
    Parameter("commanded_takeoff", "bool", 0.0, 0.0, 1.0,
              "1 = the thrust servoes the COM velocity to the lift-off velocity of the flight to flight_target_x/y/z "
              "in flight_air_time and ends on reaching it (control/commanded_thrust.py; low_level only)"),
    Parameter("arm_swing", "rad", 1.0, 0.0, 3.2, "forward arm swing during the thrust (low_level only)"),
    Parameter("crouch_arms", "rad", 0.0, -0.8, 0.0,
              "arms swung back (-) in the crouch, to swing forward in the thrust; keeps the hands off "
              "the ground in a deep crouch (low_level only)"),
    Parameter("thrust_damping", "1", 1.0, 0.1, 1.0,
              "share of the stiffened leg servos' damping kept in the thrust; less extends faster "
              "(low_level only)"),
)

