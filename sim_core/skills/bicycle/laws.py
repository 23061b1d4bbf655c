"""The bicyclist's control laws as pure functions (Hodgins et al. 1995 eqs. 7-11, with the sign
fix of SEEDS-WAVE2.md §1.3; eq. 11 as printed, which is right in our frame X forward, Y left,
Z up: positive roll is right side down, positive yaw and fork angle are to the left)."""
from __future__ import annotations

import math

from ...ballistics import GRAVITY


def crank_torque(speed: float, desired_speed: float, gain: float, limit: float, feedforward: float = 0.0,
                 integral: float = 0.0, integral_gain: float = 0.0) -> float:
    """Eq. 7 with the sign fix: ``tau = k_v (v_d - v)``, k_v > 0; positive drives forward; held
    within +-``limit`` (the seed gives none: unlimited, a 2.4 m/s error asks 1.2 kN m of the legs).
    ``feedforward`` (N m, load_torque's) is added before the limit, and so is an integral term
    ``integral_gain`` (N m per m) times ``integral`` (m, the accumulated speed error, speed_integral);
    with ``integral_gain`` 0 the seed's eq. 7, bit for bit."""
    torque = gain * (desired_speed - speed) + feedforward + integral_gain * integral   # + 0.0 exactly when off
    return min(max(torque, -limit), limit)


def speed_integral(integral: float, speed: float, desired_speed: float, dt: float, gain: float, limit: float,
                   feedforward: float, integral_gain: float, integral_limit: float = math.inf) -> float:
    """The accumulated speed error (m) of eq. 7's integral term one control step on: ``integral +
    (v_d - v) dt``, with conditional anti-windup: the step is not taken when the unclamped torque
    already lies beyond +-``limit`` in the direction the error would push it (the integral then
    holds; the limit, not the integral, is what the legs give); and the term's torque is kept within
    +-``integral_limit`` (N m): the integral trims what the feed-forward and eq. 7 leave, it does not
    climb."""
    error = desired_speed - speed
    torque = gain * error + feedforward + integral_gain * integral
    if (torque >= limit and error > 0) or (torque <= -limit and error < 0):
        return integral
    bound = integral_limit / integral_gain if integral_gain else math.inf
    return min(max(integral + error * dt, -bound), bound)


def load_torque(mass: float, slope_sine: float, resistance: float, speed: float, wheel_radius: float, gear: float,
                slope_share: float, rolling_share: float) -> float:
    """The crank torque (N m) that holds the bicycle's speed against its load: gravity on ``mass``
    (rider and bicycle, kg) on a road whose grade has sine ``slope_sine`` (uphill positive) times
    ``slope_share``, and the rolling resistance ``resistance`` (N s/m) at ``speed`` times
    ``rolling_share``; the ground force through a wheel of ``wheel_radius`` in ``gear`` (wheel turns
    per crank turn: the crank turns 1/gear as fast, so it needs gear times the wheel's torque):
    gear r (share m g sin + share c v). Negative downhill: the legs brake through the fixed gear."""
    force = slope_share * mass * GRAVITY * slope_sine + rolling_share * resistance * speed
    return gear * wheel_radius * force


def leg_weight(phase: float) -> float:
    """Eq. 8 per leg: ``w = (1 + sin phi)/2`` with phi that leg's crank arm past top dead centre
    in the forward-pedalling direction: 1 at the forward horizontal (mid-downstroke), 0 at the
    rear horizontal; the two legs' weights (phi and phi + pi) sum to 1."""
    return 0.5 * (1.0 + math.sin(phase))


def pedal_forces(torque: float, crank_angle: float, crank_length: float) -> tuple[float, float]:
    """Eqs. 9-10 (right, left): tangential pedal forces (N, positive along forward pedalling) whose
    crank torques sum to ``torque``. ``crank_angle``: the right arm's angle past top dead centre
    (0: right pedal up, Hodgins' theta_crank = 0), the left arm half a turn on. Propulsion goes
    to the leg on the downstroke; braking (torque < 0, fixed gear) to the rising leg, which
    pushes against its pedal (the roles swap, [A] 136)."""
    right = leg_weight(crank_angle)
    left = 1.0 - right
    if torque < 0:
        right, left = left, right
    return right * torque / crank_length, left * torque / crank_length


def ankle_angle(phase: float, mean: float, swing: float, shift: float) -> float:
    """The ankle target (rad, positive = toes down) of a leg whose crank arm is ``phase`` rad past
    top dead centre: least plantarflexed near the top, most near the bottom and into the upstroke
    (``mean - swing cos(phase - shift)``) - the shape of Cavanagh & Sanderson's (1986) ankle
    curve of pursuit riders ([A] 144), whose data the seeds do not give (hand-made; the values
    are bicycle_any.json's)."""
    return mean - swing * math.cos(phase - shift)


def fork_angle(roll: float, roll_rate: float, yaw: float, yaw_rate: float, desired_yaw: float,
               k_roll: float, k_roll_rate: float, k_yaw: float, k_yaw_rate: float, desired_roll: float = 0.0,
               desired_yaw_rate: float = 0.0) -> float:
    """Eq. 11: ``theta_fork = -k_a (a - a_d) - k_ad a' + k_b (b - b_d) + k_bd (b' - b'_d)`` (the seed's
    a_d = 0 and b'_d = 0; ``desired_roll`` is a lean asked for ahead of a curve, lean_ahead;
    ``desired_yaw_rate`` the rate at which the desired heading is turning: without it the yaw-rate
    term holds the heading k_bd b'_d / k_b behind a turning desired heading).
    A right lean steers right (into the fall); a heading left of the desired one first steers
    left, which leans the bicycle right, and the roll term then turns it right: counter-steer."""
    heading_error = math.remainder(yaw - desired_yaw, 2 * math.pi)
    return -k_roll * (roll - desired_roll) - k_roll_rate * roll_rate + k_yaw * heading_error + k_yaw_rate * (yaw_rate - desired_yaw_rate)


def lean_ahead(speed: float, curvature: float, share: float) -> float:
    """The roll (rad, right side down positive) of a steady turn of ``curvature`` (1/m, left
    positive) at ``speed``, tan(lean) = v^2 kappa / g, times ``share``: asked for before the curve
    is reached, the bicycle leans into it instead of waiting for the heading error to turn it."""
    return -share * math.atan(speed * speed * curvature / GRAVITY)
