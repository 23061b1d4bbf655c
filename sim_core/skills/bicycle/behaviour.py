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
  * waist, neck and wrists hold their mounted angles ([A] 144);
  * the rider held on his saddle: the limbs' inverse kinematics is solved with the rider turned about the
    (passive) seat pivot to seat_pitch, so the arms and legs hold the pelvis's pitch and the rider does not
    swing fore and aft with each pedal stroke (which rocked the frame's speed by +-4 %: docs/bicycle.md);
  * coasting (the coast and stop courses, a freewheel bicycle): eq. 7 off, the legs turn the cranks
    back to level, the left pedal forward, and hold them; stopping: eq. 7's braking torque to the rim brakes (joint friction set
    through the edit log), the left foot let go of its pedal below foot_release_speed and put down
    beside the bicycle, its knee propping the lean, and the bars turned straight from where they are
    (docs/bicycle.md, the stop and the stop's stand).
"""
from __future__ import annotations

import dataclasses
import math

import mujoco
import numpy as np

from ...control.behaviour import Behaviour, register
from ...control.path import MAX_POINTS, PathFollower, validate_path
from ...schema import Parameter, Points, Schema
from ...tuned import TableType, characters_of, load, register as register_table
from ...tuned.settings import SkillSchema, with_defaults
from ...character.dimensions import fig3_measures
from ...character.spec import load_character
from ...errors import ParameterError
from ...world.bicycle import (BRAKE_MAX_TORQUE, DEFAULT_GEAR, LIMB_SOLREF, NAMES, Bicycle,
                              BicycleView)
from .assess import STOPPED_SPEED
from .course import COURSE, FREEWHEEL_COURSES, course_for
from .steering import steering_gains
from .laws import ankle_angle, crank_torque, speed_integral, fork_angle, lean_ahead, load_torque, pedal_forces
from .mount import IK_ITERATIONS_PER_TICK, SitePairs, match_velocities, solve

FOOT_IK_ITERATIONS = 5              # definition: damped least-squares steps a tick for the foot going down
FOOT_IK_DAMPING = 1e-3              # definition: lambda^2 of that solve
HIP_Y, KNEE = 0, 3                  # definition: the hip's flexion and the knee's places in the left leg's servos below
SIZED_FOR = "man"                   # definition: the rider the bicycle's saddle and bar are set for (world/bicycle.py)
MIN_LOOKAHEAD_SPEED = 1.0           # definition: m/s, the speed below which the look-ahead distance stops shrinking
MOUNT_CRANK_ANGLE = math.pi / 2      # the start's crank: right pedal forward, left back (horizontal)
COAST_CRANK_ANGLE = -math.pi / 2     # definition: the crank held coasting and stopping: left pedal forward, right back (horizontal)
LEG_JOINTS = {"r": ("hip_r_y", "knee_r_y"), "l": ("hip_l_y", "knee_l_y")}
ANKLE_JOINTS = {"r": "ankle_r_y", "l": "ankle_l_y"}
ARM_JOINTS = {"r": ("shoulder_r_x", "shoulder_r_y", "shoulder_r_z", "elbow_r_y", "elbow_r_z"),
              "l": ("shoulder_l_x", "shoulder_l_y", "shoulder_l_z", "elbow_l_y", "elbow_l_z")}


# the constants of the bicycling laws: their values are data (bicycle_any.json "constants", the
# defaults below are replaced by them); each range is a sanity bound a table row is checked against
BICYCLE_RANGES = Schema(
    Parameter("bicycle_size", "1", 1.0, 0.3, 1.0, "the bicycle the rider rides: its every length (wheels, crank, frame, bar) and mass as a share of the 26-inch bicycle's, its angles kept (world/bicycle.py, Bicycle.size; 1: the 26-inch one, a child's is smaller)"),
    Parameter("arm_gain_scale", "1", 1.0, 0.2, 5.0, "the arms' servo gains (kp and kv) while riding are the rider's times this (the arms steer the bicycle's fork through the hands, a load that does not shrink with the rider; 1: the rider's own)"),
    Parameter("max_speed", "m/s", 0.5, 0.5, 8.0, "the fastest speed a course may command (faster was not measured for the rider; course.py refuses it)"),
    Parameter("max_gear", "1", 0.5, 0.5, 5.0, "the highest gear offered (higher was not measured for the rider; course.py refuses it)"),
    Parameter("min_slalom_speed", "m/s", 0.5, 0.5, 8.0, "the slalom is offered from this speed (course.py; slower, the rider fell or missed gates)"),
    Parameter("max_slalom_speed", "m/s", 0.5, 0.5, 8.0, "the slalom is offered up to this speed (course.py; faster, the rider missed gates)"),
    Parameter("max_slalom_offset", "m", 0.2, 0.2, 3.0, "the slalom is offered with gate offsets up to this (course.py; wider, the rider missed gates)"),
    Parameter("min_slalom_lead", "m", 2.0, 2.0, 200.0, "the slalom is offered with at least this much straight (turn_after) before it (course.py; shorter, the rider missed the first gate or fell)"),
    Parameter("min_slalom_lookahead", "s", 0.25, 0.25, 3.0, "the slalom is offered from this lookahead_time (course.py; shorter, the rider missed gates)"),
    Parameter("min_slalom_gate_width", "m", 0.5, 0.5, 5.0, "the slalom is offered with gates at least this wide (course.py; the rider crosses a gate up to 0.6 m from its centre)"),
    Parameter("max_turn_lean", "rad", 0.0, 0.0, 0.5, "a turn (the turn course, a given path's bends) is offered asking a steady lean (tan = v^2 / (g r)) up to this (and course.py's MAX_LEAN); more, the rider fell or leaned past 20 deg"),
    Parameter("max_turn_speed", "m/s", 8.0, 0.5, 8.0, "a turn (the turn course, a given path's bends) is offered up to this speed (faster, the rider fell or leaned past 20 deg after the turn; course.py refuses it)"),
    Parameter("min_turn_lookahead", "s", 0.25, 0.25, 3.0, "the turn course and the slalom are offered from this lookahead_time (course.py; shorter, the heading was left 6-53 deg off after a tight turn)"),
    Parameter("min_turn_lead", "1", 0.0, 0.0, 10.0, "the turn course and the slalom asking more than min_turn_lead_lean of lean are offered with turn_after at least this many look-ahead distances (lookahead_time x speed) of straight before the turn (course.py; shorter, the pursuit aims around the corner from the start and the rider fell within 1.5 s)"),
    Parameter("min_turn_lead_lean", "rad", 0.0, 0.0, 0.5, "min_turn_lead applies to turns and slaloms asking a steady lean above this (course.py; gentler turns passed from any lead-in)"),
    Parameter("max_turn_lookahead_radii", "1", 0.1, 0.1, 100.0, "the turn course is offered with a look-ahead distance (lookahead_time x speed) of at most this many turn radii (course.py; further, the pursuit cut the turn and the rider fell in it)"),
    Parameter("min_turn_radius", "m", 3.0, 3.0, 100.0, "a turn (the turn course, a given path's bends) is offered on a radius of at least this (course.py), whatever its lean; tighter, the rider fell (3: the schema's tightest turn, no limit beyond it)"),
    Parameter("max_slalom_acceleration", "m/s^2", 0.1, 0.1, 10.0, "the slalom is offered up to this peak lateral acceleration of its sine, offset (pi v / spacing)^2 (course.py; more, the rider fell or missed gates)"),
    Parameter("speed_gain", "N m s/m", 0.0, 0.0, 5000.0, "eq. 7 k_v: crank torque per m/s of speed error"),
    Parameter("max_crank_torque", "N m", 0.0, 0.0, 1000.0, "limit of eq. 7's crank torque, driving or braking (a rider's strength)"),
    Parameter("speed_integral_gain", "N m/m", 0.0, 0.0, 2000.0, "eq. 7's integral term: crank torque per m of accumulated speed error (laws.speed_integral: held while the desired speed ramps to a new command and while the torque is at max_crank_torque, not used coasting or stopping; 0: the seed's eq. 7)"),
    Parameter("speed_integral_limit", "N m", 0.0, 0.0, 1000.0, "the integral term's crank torque is kept within +- this (laws.speed_integral; 1000: unbounded within max_crank_torque)"),
    Parameter("slope_feedforward", "1", 0.0, 0.0, 2.0, "share of the crank torque that holds rider and bicycle on the road's grade under the wheels (gear r m g sin, laws.load_torque; the grade sensed from the wheels' axle line, BicycleView.road_sine; negative downhill: the legs brake) added to eq. 7 (0: the seed's eq. 7)"),
    Parameter("grade_filter", "s", 0.0, 0.0, 5.0, "time constant of the low-pass on the road's grade the load's feed-forward feels (BicycleView.road_sine; 0: as sensed each tick)"),
    Parameter("rolling_feedforward", "1", 0.0, 0.0, 2.0, "share of the crank torque that holds the rolling resistance at the desired speed (gear r c v_d, laws.load_torque) added to eq. 7 (0: the seed's eq. 7)"),
    Parameter("hold_seat_pitch", "1", 0.0, 0.0, 1.0, "1: while riding, the limbs' targets hold the pelvis at its mounted pitch on the saddle (``_seat_pelvis``, as the stop does once the foot is down); 0: the pelvis pitches as the limbs let it (the man's: 56 deg forward at the top of a stroke)"),
    Parameter("seat_pitch_time", "s", 0.0, 0.0, 10.0, "while riding, the limbs' targets hold the pelvis on the saddle at a pitch that moves from the mounted one to seat_pitch with this time constant (``_seat_pelvis``): the rider's swing fore and aft on the saddle over each pedal stroke is held (0: off, the pelvis pitches as the limbs let it; hold_seat_pitch, when 1, holds the mounted pitch instead)"),
    Parameter("seat_pitch", "rad", 0.0, -1.2, 0.0, "the pelvis's pitch on the saddle (about the frame's lateral axis, forward tilt negative) the limbs hold while riding with seat_pitch_time (the man's free pelvis pitched 42-49 deg forward on average, swinging 17-55 deg peak to peak)"),
    Parameter("ik_velocity_filter", "s", 0.0, 0.0, 0.5, "time constant of the low-pass on the limb targets' velocity that leads the servos (0: unfiltered)"),
    Parameter("speed_ramp", "m/s^2", 0.1, 0.1, 10.0, "eq. 7's desired speed moves to a newly commanded one at this rate (a start, a speed step)"),
    Parameter("roll_gain", "1", 0.0, 0.0, 20.0, "eq. 11 k_alpha at reference_speed"),
    Parameter("roll_rate_gain", "s", 0.0, 0.0, 5.0, "eq. 11 k_alpha-dot at reference_speed"),
    Parameter("yaw_gain", "1", 0.0, 0.0, 10.0, "eq. 11 k_beta at reference_speed"),
    Parameter("yaw_rate_gain", "s", 0.0, 0.0, 5.0, "eq. 11 k_beta-dot at reference_speed"),
    Parameter("heading_acceleration", "m/s^2", 0.1, 0.1, 10.0, "a commanded heading (no path) is approached as a turn asking this lateral acceleration: the desired heading turns at this / v rad/s"),
    Parameter("heading_rate_feedforward", "1", 0.0, 0.0, 1.0, "share of the desired heading's turning rate (to a commanded heading) eq. 11's yaw-rate term damps the yaw rate relative to (0: the seed's, relative to 0; without it the heading lags the turn by k_bd/k_b times its rate)"),
    Parameter("heading_rate_filter", "s", 0.0, 0.0, 2.0, "time constant of the low-pass on that turning rate before eq. 11 uses it (0: unfiltered)"),
    Parameter("min_coast_speed", "m/s", 0.5, 0.5, 10.0, "the coast is ridden from this speed (course.py refuses slower: not measured)"),
    Parameter("max_coast_speed", "m/s", 10.0, 0.5, 10.0, "the coast is ridden up to this speed (course.py refuses faster: not measured)"),
    Parameter("min_stop_speed", "m/s", 0.5, 0.5, 10.0, "the stop is ridden from this speed, and a coast hands over to its stop (coast_min_speed) from it (course.py refuses slower)"),
    Parameter("max_stop_speed", "m/s", 10.0, 0.5, 10.0, "the stop is ridden up to this speed (course.py refuses faster: not measured to end standing)"),
    Parameter("min_coast_gear", "1", 0.5, 0.5, 10.0, "the coast is offered from this gear (course.py refuses lower; 1: every gear offered, since the crank is levelled with the left pedal forward 55 coasts in gears 1.01-4.56 stood, docs/bicycle.md, the stop's stand)"),
    Parameter("max_coast_gear", "1", 10.0, 0.5, 10.0, "the coast is offered up to this gear (course.py refuses higher; 5: every gear offered; before the stop's stand was mended its stop fell in 3, 3, 2 and 5 of 9 coasts in gears 2.0, 2.8, 3.0 and 3.5)"),
    Parameter("min_stop_after", "s", 0.5, 0.5, 100.0, "the stop brakes from coast_after >= this (course.py refuses earlier; 0.5, the schema's least: 15 stops braking 0.52-1.98 s in stood, among them 3.03 m/s after 1.39 s, which fell before the stop's stand was mended)"),
    Parameter("max_heading_change", "rad", 3.15, 0.0, 3.15, "the largest commanded heading (a turn from the start's) offered (larger, the child fell 1.7-2.3 s in; course.py refuses it)"),
    Parameter("max_heading_turn_speed", "m/s", 0.5, 0.5, 10.0, "a commanded heading other than the start's (no path) is offered up to this speed (faster, the turn to it fell or leaned past 20 deg; course.py refuses it)"),
    Parameter("min_heading_turn_gear", "1", 0.5, 0.5, 5.0, "a commanded heading other than the start's (no path) is offered from this gear (in lower gears the heading was left 5-10 deg off or the bicycle weaved; course.py refuses it)"),
    Parameter("min_heading_turn_cadence", "1/s", 0.0, 0.0, 5.0, "a commanded heading other than the start's (no path) is offered from this cadence v / (2 pi r gear), in revolutions per second (slower, the turn fell; course.py refuses it)"),
    Parameter("path_rate_feedforward", "1", 0.0, 0.0, 1.0, "along a path, share of the path's turning rate (v times its curvature read curvature_preview ahead) eq. 11's yaw-rate term damps the yaw rate relative to (0: relative to 0, which holds the heading back from the path's bends)"),
    Parameter("lean_feedforward", "1", 0.0, 0.0, 1.0, "share of a steady turn's lean (tan = v^2 kappa / g) asked for ahead of a path's curve (0: the seed's eq. 11)"),
    Parameter("curvature_preview", "s", 0.0, 0.0, 3.0, "the path's curvature is read this many seconds of travel ahead"),
    Parameter("reference_speed", "m/s", 0.5, 0.5, 10.0, "speed at which the four steering gains are these (steering.py scales them with speed)"),
    Parameter("max_fork_angle", "rad", 0.0, 0.0, 1.0, "limit of the commanded fork angle"),
    Parameter("min_speed", "m/s", 0.5, 0.5, 8.0, "the slowest speed a course may command (slower rides were measured to fall; course.py refuses them)"),
    Parameter("max_cadence", "1/s", 0.5, 0.5, 10.0, "the fastest cadence v / (2 pi r gear), in revolutions per second, a course may ask (faster, the legs do not turn the crank at the wheel's pace; course.py refuses it)"),
    Parameter("min_cadence", "1/s", 0.0, 0.0, 5.0, "the slowest cadence v / (2 pi r gear), in revolutions per second, a course may ask at any of its commanded speeds (slower, the rider weaved to 19 deg, the heading wandered 71 deg, and fell; course.py refuses it)"),
    Parameter("max_slowing_cadence", "1/s", 10.0, 0.5, 10.0, "a start from a rolling start faster than its speed is offered from a rolling start at a cadence v / (2 pi r gear), in revolutions per second, up to this (faster, the feet left the pedals by 3 cm or more as the rider slowed; course.py refuses it)"),
    Parameter("min_fast_gear", "1", 0.5, 0.5, 5.0, "the lowest gear offered when a course commands fast_speed or more (lower, the rider weaved and fell; course.py refuses it)"),
    Parameter("fast_speed", "m/s", 8.0, 0.5, 10.0, "from this speed the gear is at least min_fast_gear (course.py)"),
    Parameter("min_gear", "1", 0.5, 0.5, 5.0, "the lowest gear offered (lower, the legs lost more than 5 % of the speed at 1.9-2.4 rev/s; course.py refuses it)"),
    Parameter("max_hill_grade", "1", 0.0, 0.0, 0.2, "the steepest hill_grade offered in any gear (up to max_hill_grade_gear); steeper, up to steep_hill_grade, in the steep_hill_ gears and speeds only (course.py refuses the rest)"),
    Parameter("max_hill_speed", "m/s", 8.0, 0.5, 8.0, "a hill up to max_hill_grade is offered up to this speed (faster, the climb lost more than 5 % of the speed per crank revolution; course.py refuses it)"),
    Parameter("max_hill_cadence", "1/s", 10.0, 0.5, 10.0, "a hill up to max_hill_grade is offered up to this cadence v / (2 pi r gear), in revolutions per second (faster, the speed swung by more than 5 % within the strokes; course.py refuses it)"),
    Parameter("max_sharp_hill_grade", "1", 0.2, 0.0, 0.2, "a hill up to max_hill_grade steeper than this is offered with its corners rounded, hill_curve >= min_hill_curve (at a sharp crest the speed dipped by more than 5 %; course.py refuses it)"),
    Parameter("min_hill_curve", "m", 0.0, 0.0, 100.0, "the shortest vertical curve (hill_curve) of a hill steeper than max_hill_grade's sharp limit, max_sharp_hill_grade"),
    Parameter("max_hill_grade_gear", "1", 0.0, 0.0, 1.0, "the largest hill_grade x gear a hill may ask (the climb's crank torque goes with it; steeper or higher-geared climbs lost more than 15 % of the speed; course.py refuses them)"),
    Parameter("steep_hill_grade", "1", 0.0, 0.0, 0.2, "the steepest hill_grade offered; above max_hill_grade only in the steep_hill_ gears and speeds (course.py refuses the rest)"),
    Parameter("steep_hill_min_gear", "1", 0.5, 0.5, 5.0, "a hill steeper than max_hill_grade is offered from this gear"),
    Parameter("steep_hill_max_gear", "1", 0.5, 0.5, 5.0, "and up to this gear"),
    Parameter("steep_hill_min_speed", "m/s", 0.5, 0.5, 8.0, "and from this speed"),
    Parameter("steep_hill_max_speed", "m/s", 0.5, 0.5, 8.0, "and up to this speed"),
    Parameter("steep_hill_min_lead", "m", 0.0, 0.0, 200.0, "and after at least this much flat (hill_after) before the climb"),
    Parameter("coast_min_speed", "m/s", 0.5, 0.5, 8.0, "coast course: below this speed the rider brakes to a stop (steering needs speed)"),
    Parameter("crank_level_rate", "rad/s", 0.1, 0.1, 20.0, "coasting and stopping: the legs turn the crank back (free on the freewheel) to level with the left pedal forward (COAST_CRANK_ANGLE) at most this fast"),
    Parameter("brake_deceleration", "m/s^2", 0.1, 0.1, 5.0, "stop: eq. 7's desired speed falls to 0 at this rate; its braking torque goes to the rim brakes"),
    Parameter("front_brake_share", "1", 0.0, 0.0, 1.0, "stop: share of the braking torque asked of the front brake"),
    Parameter("stop_lean", "rad", 0.0, 0.0, 0.4, "stop: eq. 11's desired roll towards the foot that goes down (left) while braking"),
    Parameter("foot_release_speed", "m/s", 0.0, 0.0, 3.0, "stop: below this speed the left foot leaves its pedal and the brakes stop the bicycle"),
    Parameter("foot_out", "m", 0.0, 0.0, 0.8, "stop: the left foot is put down this far left of the wheels' contact line"),
    Parameter("foot_ahead", "m", -0.5, -0.5, 0.5, "stop: and this far ahead of the left hip"),
    Parameter("foot_swing_time", "s", 0.05, 0.05, 2.0, "stop: time to move the foot from its pedal to the ground point"),
    Parameter("foot_ankle", "rad", -0.7, -0.7, 0.87, "stop: the left ankle's plantarflexion while the foot goes down (toes first)"),
    Parameter("fork_straighten_rate", "rad/s", 0.0, 0.0, 5.0, "stop: once the foot is down the arms turn the fork straight at this rate"),
    Parameter("stand_roll", "rad", -0.5, -0.5, 0.0, "stop: the roll (left down) the planted leg holds the bicycle at"),
    Parameter("knee_roll_gain", "1", 0.0, 0.0, 20.0, "stop: the planted knee straightens this many rad per rad the bicycle leans beyond stand_roll"),
    Parameter("knee_roll_integral_gain", "1/s", 0.0, 0.0, 20.0, "stop: and this many rad per rad s of roll beyond stand_roll (the lean does not creep)"),
    Parameter("knee_roll_rate_gain", "s", 0.0, 0.0, 5.0, "stop: and this many rad per rad/s of roll rate towards the foot"),
    Parameter("stop_stand", "s", 0.0, 0.0, 60.0, "stop: the run ends this long after the bicycle came to rest with the foot down"),
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
    """The constants of the bicycling laws: bicycle_any.json's (the man's), with the rider's own
    table's (bicycle_<rider>.json, a subset) over them."""
    own = load("bicycle", character) if character != "any" else None
    return {**load("bicycle", "any")["constants"], **(own["constants"] if own else {})}


def riders() -> list[str]:
    """The riders measured to ride: the man (bicycle_any.json is his) and every rider with a table."""
    return sorted({SIZED_FOR, *characters_of("bicycle")})


def rider_courses(character: str) -> tuple[str, ...]:
    """The courses ``character`` is offered: its table's "courses" (every course for the man or a rider with no table)."""
    table = load("bicycle", character) if character != SIZED_FOR else None
    return tuple(table["courses"]) if table is not None else tuple(COURSE.options)


def rider_knobs(character: str) -> dict:
    """The animator parameters whose default the rider's table replaces (its "knobs": the woman's
    look-ahead), checked against the schema; {} for the man or a rider with no table."""
    table = load("bicycle", character) if character != SIZED_FOR else None
    return {n: Bicycling.schema.by_name[n].validate(v) for n, v in (table or {}).get("knobs", {}).items()}


def rider_settings(params: dict, character) -> dict:
    """``params`` with the rider's own constants and knobs (bicycle_<rider>.json) for those the
    request left at the schema's defaults (bicycle_any.json's; a value the user set is kept, as
    running does); the man's unchanged."""
    if character is None or character.name == SIZED_FOR or load("bicycle", character.name) is None:
        return params
    defaults = Bicycling.schema.defaults()
    own = {**bicycle_constants(character.name), **rider_knobs(character.name)}
    return {**params, **{n: v for n, v in own.items() if params.get(n, defaults[n]) == defaults[n]}}


def check_rider(params: dict, character) -> None:
    """Only the riders measured to ride (riders), on the courses measured for them (the rider's
    table's "courses"; its speeds and gears are course.py's checks of its constants); refused in one
    line naming what is offered."""
    name = SIZED_FOR if character is None else character.name
    offered = riders()
    if name not in offered:
        raise ParameterError(f"bicycle is not calibrated for the {name} (calibrated for: {', '.join(offered)}): "
                             f"not measured to ride: a rider rides with a table of its own, bicycle_{name}.json, and a "
                             f"bicycle its size (docs/bicycle.md, riders other than the man)")
    courses = rider_courses(name)
    course = COURSE.option(params["course"])
    if course not in courses:
        raise ParameterError(f"the {name} rides the bicycle's {', '.join(courses)} course(s) only (asked: "
                             f"{course}); the others were not measured for the {name} (docs/bicycle.md)")



BICYCLE_TABLE = register_table(TableType("bicycle", BICYCLE_RANGES, _bicycle_rows, (bicycle_constants,)))
BICYCLE_SETTINGS = with_defaults(BICYCLE_RANGES, bicycle_constants())


def frame_fit(character, size: float = 1.0) -> float:
    """The bicycle's frame size for ``character`` (Bicycle.fit) on a bicycle of ``size`` (Bicycle.size):
    its leg length over the man's, for whom the saddle and the bar were set (Fig. 3's leg length),
    over the bicycle's size; 1 for the man or no character."""
    if character is None or character.name == SIZED_FOR:
        return 1.0
    legs = fig3_measures(character)["leg length"] / fig3_measures(load_character(SIZED_FOR))["leg length"]
    return legs if size == 1.0 else legs / size


def foot_time(character) -> float | None:
    """The feet's attachments' time constant for ``character`` (Bicycle.foot_time): the man's
    (LIMB_SOLREF) times the square root of its leg mass over the man's (Fig. 3's), so that a
    lighter leg's attachment holds the same pedal force with the same stretch (MuJoCo's soft
    constraint is as stiff as the effective mass over its time constant squared); None for the man.
    At the man's 20 ms the imaginary cyclist's 5 kg legs left their pedals by 3.1-5.3 cm at the top
    of the stroke (docs/bicycle.md, riders other than the man)."""
    if character is None or character.name == SIZED_FOR:
        return None
    legs = fig3_measures(character)["leg mass"] / fig3_measures(load_character(SIZED_FOR))["leg mass"]
    return LIMB_SOLREF[0] * math.sqrt(legs)


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
        Parameter("hill_curve", "m", 2.0, 0.0, 100.0, "hill: length of the vertical curves (parabolas) that round its foot and crest corners, at most hill_top and hill_length (0: sharp corners)"),
        Parameter("start_speed", "m/s", 1.5, 1.5, 8.0, "start: the rolling start's speed, from which the rider pedals up to speed"),
        Parameter("coast_after", "s", 2.0, 0.5, 100.0, "coast, stop: time from which the rider stops pedalling (coast) or brakes to a stop (stop)"),
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
        params = rider_settings(params, character)
        check_rider(params, character)
        course = course_for(params)
        bicycle = Bicycle(gear=params["gear"], rider="", freewheel=course.name in FREEWHEEL_COURSES,
                          fit=frame_fit(character, params["bicycle_size"]), foot_time=foot_time(character),
                          size=params["bicycle_size"])
        return dataclasses.replace(world, bicycle=bicycle, hill=course.hill)

    @classmethod
    def start_state(cls, params, model, data, character, prefix=""):
        """Mounted and rolling: the rider's root and joints solved so that the seat bones sit on
        the saddle and the palms and balls of the feet on the grips and pedals (crank
        horizontal), then the rolling start at the commanded speed. ``prefix``: the rider's (a
        scene's actor); nobody else is moved."""
        params = rider_settings(params, character)
        bike = BicycleView.of(model)
        bike.set_crank(data, MOUNT_CRANK_ANGLE)
        mujoco.mj_kinematics(model, data)
        pairs = SitePairs(model, prefix)
        root = model.joint(prefix + "root")
        adr = int(root.qposadr[0])
        seat_mid = data.site_xpos[pairs.rider[:2]].mean(axis=0)
        saddle = data.site_xpos[pairs.bike[:2]].mean(axis=0)
        data.qpos[adr:adr + 3] += saddle - seat_mid
        reference = data.qpos.copy()
        for name, value in mount_posture(params).items():
            reference[model.joint(prefix + name).qposadr[0]] = value
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

    @classmethod
    def character_defaults(cls, character: str) -> dict:
        """The rider's table's knobs (rider_knobs)."""
        return rider_knobs(character)

    def __init__(self, params, ctx):
        super().__init__(rider_settings(params, ctx.character), ctx)

    def check_feasible(self):
        """Only the riders measured to ride are offered (check_rider)."""
        check_rider(self.params, self.ctx.character)

    def start(self, t):
        """Look the bicycle and the limbs up; the targets start at the mounted pose."""
        ctx = self.ctx
        model, servos = ctx.model, ctx.servos
        self.target = servos.angles().copy()
        self.bike = BicycleView.of(model)
        self.pairs = SitePairs(model, ctx.actor.prefix)
        self.scratch = mujoco.MjData(model)
        yaw = self.bike.state(ctx.data)["yaw"]
        self.heading_goal = self.params["heading"] + yaw     # the commanded heading, approached as a turn
        self.desired_yaw = yaw
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
        if self.params["arm_gain_scale"] != 1.0:      # the arms steer the fork: their gains for the bicycle, not the rider
            arms = np.concatenate(list(self.arm_servos.values()))
            self.kp = self.kp.copy()
            self.kp[arms] *= self.params["arm_gain_scale"]
            servos.set_gains(arms, self.kp[arms], servos.default_kv[arms] * self.params["arm_gain_scale"])
        self.previous_ik = None
        self.ik_velocity = np.zeros(len(self.limb_servos))
        self.fork_command = 0.0
        self.desired_yaw_rate = 0.0          # rad/s: the rate the desired heading turns at
        self.yaw_rate_feedforward = 0.0      # rad/s: its low-pass, eq. 11's yaw-rate term is relative to
        self.desired_speed = self.course.start_speed
        self.jac = np.zeros((3, model.nv))
        rider_root = model.jnt_bodyid[model.joint(ctx.actor.prefix + "root").id]
        self.mass = float(model.body_subtreemass[rider_root] + model.body_subtreemass[self.bike.frame])   # kg, rider and bicycle
        self.speed_error_integral = 0.0     # eq. 7's accumulated speed error (m; speed_integral_gain)
        # the hill's speed law: the load's feed-forward and the integral term ride hill courses up to max_hill_grade;
        # elsewhere eq. 7 alone, as measured before: on the steep hills (up to steep_hill_grade, the legs near their
        # limit) either threw the rider on the 10 % climb at 4 m/s in gear 2.0, and on flat ground the integral
        # upset a stop (3.2 m/s, gear 4.51) and a long turn at 7 m/s (docs/bicycle.md, the hill's speed law)
        self.load_law = bool(self.course.hill) and self.params["hill_grade"] <= self.params["max_hill_grade"]
        self.road_sine = self.bike.road_sine(ctx.data)     # the grade the rider feels (low-passed, grade_filter)
        self.crank_command = None            # coasting: the crank angle the legs hold (None: the pedals as they are)
        self.coasting = self.coasted = False
        self.stopping = self.course.stop        # braking to a stop (the stop course; a coast that got too slow)
        self.foot_down = None               # stop: (time the foot left its pedal, where it left it from the left hip)
        self.planted = None                 # stop: the left leg's servo targets once the foot is on the ground
        self.knee_integral = 0.0            # stop: the planted knee's integral term (rad)
        self.rest_since = None              # stop: when the bicycle came to rest with the foot down
        self.foot_site = model.site(ctx.actor.prefix + "rider_foot_l").id
        self.foot_eq = model.equality(ctx.actor.prefix + "attach_foot_l").id
        self.left_hip = model.body(ctx.actor.prefix + "ULEGL").id
        self.pelvis = model.body(ctx.actor.prefix + "PELVIS").id
        self.root_qpos = int(model.joint(ctx.actor.prefix + "root").qposadr[0])
        self.pelvis_pitch = None            # stop: the pelvis's pitch on the saddle held once the foot is down (rad)
        self.seat_pitch_time = 0.0 if self.params["hold_seat_pitch"] else self.params["seat_pitch_time"]
        if self.params["hold_seat_pitch"] or self.seat_pitch_time:  # held from the mount (the child's hip met its flexion
            self.pelvis_pitch = self._pelvis_pitch(ctx.data)        # limit at the top), or moved to seat_pitch
        left_leg = ("hip_l_y", "hip_l_x", "hip_l_z", "knee_l_y")
        self.left_leg_servos = servos.indices(left_leg)
        self.left_leg_dofs = servos.dof_adr[self.left_leg_servos]
        self.left_leg_qpos = servos.qpos_adr[self.left_leg_servos]
        joints = [model.joint(ctx.actor.prefix + n).id for n in left_leg]
        self.left_leg_range = (model.jnt_range[joints, 0], model.jnt_range[joints, 1])
        self.left_foot_geoms = np.nonzero(np.isin(model.geom_bodyid, [model.body(ctx.actor.prefix + b).id
                                                                      for b in ("FOOTL", "TOEL")]))[0]
        self.ground = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "ground")

    def update(self, t):
        """Eq. 11 -> fork command -> arm IK; pedal IK and ankle curve -> leg targets; eqs. 7-10
        -> pedal forces -> leg torques (servo offsets)."""
        ctx, servos, bike = self.ctx, self.ctx.servos, self.bike
        model, data = ctx.model, ctx.data
        state = bike.state(data)
        c = self.params
        desired_roll = -c["stop_lean"] if self.coasting and self.stopping else 0.0
        self.desired_yaw_rate = 0.0
        if self.follower is None and self.desired_yaw != self.heading_goal:
            self._turn_to_heading(state["speed"])
        if self.follower is not None:      # pure pursuit: head for the point lookahead_time ahead
            x, y = data.qpos[bike.free_qpos], data.qpos[bike.free_qpos + 1]
            moving = max(state["speed"], MIN_LOOKAHEAD_SPEED)
            self.follower.lookahead = c["lookahead_time"] * moving
            self.desired_yaw = self.follower.heading(x, y)
            curvature = self.follower.curvature_ahead(x, y, c["curvature_preview"] * moving)
            desired_roll = lean_ahead(state["speed"], curvature, c["lean_feedforward"])
            self.desired_yaw_rate = c["path_rate_feedforward"] * state["speed"] * curvature
        # eq. 11's yaw rate is damped relative to the desired heading's (or the path's) rate, low-passed: a short turn's step
        # of it (0.03 rad at 4.42 m/s: 0.45 rad/s for 66 ms) set off a weave of 20 deg (docs/bicycle.md)
        blend = ctx.control_dt / (c["heading_rate_filter"] + ctx.control_dt)
        self.yaw_rate_feedforward += blend * (self.desired_yaw_rate - self.yaw_rate_feedforward)
        if self.foot_down is not None:    # once the foot leaves its pedal the arms turn the bars straight (eq. 11 at a
            # walking pace swung them to its +-0.5 rad limit: turned 12-24 deg when the foot landed, the stop fell)
            step = c["fork_straighten_rate"] * ctx.control_dt
            self.fork_command -= min(max(self.fork_command, -step), step)
        else:
            fork = fork_angle(state["roll"], state["roll_rate"], state["yaw"], state["yaw_rate"], self.desired_yaw,
                              *steering_gains(state["speed"], c), desired_roll, self.yaw_rate_feedforward)
            self.fork_command = min(max(fork, -c["max_fork_angle"]), c["max_fork_angle"])
        self._pedal(t, state, self._crank_torque(t, state))

    def _turn_to_heading(self, speed: float) -> None:
        """Eq. 11's desired heading turns towards the commanded one at the rate of a turn asking
        heading_acceleration of lateral acceleration (omega = a / v). Stepped at once, a 172 deg
        heading change threw the bicycle over within 1.4 s at 3 m/s; asking the turn's lean ahead as
        well (lean_feedforward, as along a path) left weaves of 14-21 deg that did not die out, or fell,
        at 3.1 and 4.4 m/s (docs/bicycle.md, random requests over the panel)."""
        rate = self.params["heading_acceleration"] / max(speed, MIN_LOOKAHEAD_SPEED)
        error = math.remainder(self.heading_goal - self.desired_yaw, 2 * math.pi)
        step = rate * self.ctx.control_dt
        if abs(error) <= step:
            self.desired_yaw = self.heading_goal
        else:
            self.desired_yaw += math.copysign(step, error)
            self.desired_yaw_rate = self.params["heading_rate_feedforward"] * math.copysign(rate, error)

    def _crank_torque(self, t, state) -> float:
        """Eq. 7 on the desired speed, which follows the course's command at speed_ramp. Coasting
        (the coast and stop courses, from coast_from) the crank is not driven: the legs turn it back to
        level, the left pedal forward, and hold it on the freewheel; on the coast course, below coast_min_speed (too slow to steer),
        the rider brakes to a stop. Stopping, the desired speed falls to 0 at brake_deceleration and
        eq. 7's braking torque goes to the rim brakes (a freewheel cannot brake through the pedals);
        below foot_release_speed the left foot goes down."""
        c, course, dt = self.params, self.course, self.ctx.control_dt
        coast_from = course.coast_from
        if coast_from is not None and t >= coast_from and not self.coasted:   # from now on the crank is not driven
            self.coasting = self.coasted = True
            self.crank_command = state["crank"]
        if self.coasting and not self.stopping and state["speed"] < c["coast_min_speed"]:
            self.stopping, self.desired_speed = True, state["speed"]      # too slow to steer: a stop
            self.event(t, "brake_to_stop")
        if not self.coasting:
            step = c["speed_ramp"] * dt
            self.desired_speed += min(max(course.speed_at(t) - self.desired_speed, -step), step)
            uphill, ki = 0.0, 0.0
            if self.load_law:
                self.road_sine += dt / (c["grade_filter"] + dt) * (self.bike.road_sine(self.ctx.data) - self.road_sine)
                uphill = load_torque(self.mass, self.road_sine, self.bike.rolling_resistance,
                                     self.desired_speed, self.bike.wheel_radius, c["gear"], c["slope_feedforward"],
                                     c["rolling_feedforward"])
                ki = c["speed_integral_gain"]
            if ki and self.desired_speed == course.speed_at(t):     # held while the desired speed ramps
                self.speed_error_integral = speed_integral(self.speed_error_integral, state["speed"], self.desired_speed, dt,
                                                           c["speed_gain"], c["max_crank_torque"], uphill, ki,
                                                           c["speed_integral_limit"])
            return crank_torque(state["speed"], self.desired_speed, c["speed_gain"], c["max_crank_torque"], uphill,
                                self.speed_error_integral, ki)
        # the crank turned back (free on the freewheel) to level with the left pedal forward: with the left pedal
        # back the stop's foot landed with its knee near straight (0.53-0.62 rad against 0.89-0.92), the bicycle
        # leaned onto it to 10.5-11 deg and crept on, or fell; turned forward, in high gears the crank reached the
        # wheel's pace, lagged and fell back to the other level (docs/bicycle.md, the stop's stand)
        level = COAST_CRANK_ANGLE + 2 * math.pi * math.floor((self.crank_command - COAST_CRANK_ANGLE) / (2 * math.pi))
        self.crank_command = max(self.crank_command - c["crank_level_rate"] * dt, level)
        if self.stopping:
            self.desired_speed = max(self.desired_speed - c["brake_deceleration"] * dt, 0.0)
            if self.foot_down is None and state["speed"] < c["foot_release_speed"]:
                self._release_foot(t)
            # the brakes hold the bicycle whichever way it rolls; with the foot down, fully
            self._brake(math.inf if self.planted is not None else
                        -crank_torque(abs(state["speed"]), self.desired_speed, c["speed_gain"], 2 * c["max_crank_torque"]))
            if self.planted is not None and self.rest_since is None and abs(state["speed"]) < STOPPED_SPEED:
                self.rest_since = t
                self.event(t, "at_rest")
        return 0.0

    @property
    def run_complete(self) -> bool:
        """A stop's run ends stop_stand after the bicycle came to rest with the foot down: the skill is
        done (asked to, the rider stands on: twelve stops stood 22 s, docs/bicycle.md, the stop)."""
        return self.rest_since is not None and self.ctx.data.time - self.rest_since >= self.params["stop_stand"]

    def _release_foot(self, t) -> None:
        """The left foot leaves its pedal (its attachment switched off through the edit log, so a
        replay switches it off at the same tick) for a ground point beside the hip (``_ground_point``)."""
        data = self.ctx.data
        active = data.eq_active.copy()
        active[self.foot_eq] = 0
        self.ctx.servos.log.set_flat(data.eq_active, "eq_active", active)
        self.foot_down = (t, data.site_xpos[self.foot_site] - data.xpos[self.left_hip])
        self.fork_command = float(data.qpos[self.bike.steer_qpos])   # the bars straightened from where they are
        self.event(t, "foot_off_pedal")

    def _ground_point(self) -> np.ndarray:
        """Where the left foot goes down, read afresh each tick (the bicycle still rolls while the foot
        swings): on the ground foot_out left of the wheels' contact line and foot_ahead ahead of the
        left hip. Aimed once, where the hip was when the foot let go, the foot landed 0.2 m behind the
        hip at rest: the leg then pushed the bicycle forward against the brakes and the foot back, and
        both crept until the bicycle fell (docs/bicycle.md, the stop)."""
        data, bike = self.ctx.data, self.bike
        frame = data.xmat[bike.frame].reshape(3, 3)
        heading = math.atan2(frame[1, 0], frame[0, 0])
        forward, left = np.array([math.cos(heading), math.sin(heading), 0.0]), np.array([-math.sin(heading), math.cos(heading), 0.0])
        hip = data.xpos[self.left_hip]
        mid = data.xpos[bike.frame].copy()
        mid[:2] += left[:2] * bike.wheel_radius * math.sin(bike.state(data)["roll"])   # the wheels' contact line
        ground = mid + forward * (float(np.dot(hip - mid, forward)) + self.params["foot_ahead"]) + left * self.params["foot_out"]
        ground[2] = 0.0
        return ground

    def _foot_on_ground(self) -> bool:
        data = self.ctx.data
        for con in data.contact[:data.ncon]:
            pair = {con.geom1, con.geom2}
            if self.ground in pair and pair & set(self.left_foot_geoms.tolist()):
                return True
        return False

    def _left_leg_goal(self, t, goal: np.ndarray) -> None:
        """The released left leg: inverse kinematics of the foot's sole to a point moving from where
        it left the pedal out to above the ground point (in half foot_swing_time) and down to it (in
        foot_swing_time), toes a little down (foot_ankle). Once the foot touches the ground the
        hip's targets stay where they are and the knee props the lean: its target straightens with
        the roll beyond stand_roll (proportional, integral and roll-rate terms: the leg pushes the
        bicycle back up as it leans further onto the foot), and the hip's flexion turns the thigh so
        that the knee's change moves the foot up and down, not along the ground (through the leg's
        Jacobian at the foot); the arms and the right leg hold the pelvis at its pitch on the saddle
        (``_seat_pelvis``)."""
        ctx, servos, c = self.ctx, self.ctx.servos, self.params
        if self.planted is None and self._foot_on_ground():
            self.planted = servos.angles()[self.left_leg_servos].copy()
            self.pelvis_pitch = self._pelvis_pitch(ctx.data)     # held from here
            self.event(t, "foot_planted")
        if self.planted is not None:
            goal[self.left_leg_servos] = self.planted
            state = self.bike.state(ctx.data)
            error = state["roll"] - c["stand_roll"]
            self.knee_integral += c["knee_roll_integral_gain"] * error * ctx.control_dt
            knee = max(self.planted[KNEE] + c["knee_roll_gain"] * error + self.knee_integral
                       + c["knee_roll_rate_gain"] * state["roll_rate"], 0.0)
            goal[self.left_leg_servos[KNEE]] = knee
            # the hip turns the thigh so that the knee's change does not move the foot along the ground
            # fore and aft (alone, the straightening knee pushed the planted foot forward and it slid)
            mujoco.mj_jacSite(ctx.model, ctx.data, self.jac, None, self.foot_site)
            frame = ctx.data.xmat[self.bike.frame].reshape(3, 3)[:, 0]
            along = frame @ self.jac[:, self.left_leg_dofs[[HIP_Y, KNEE]]]
            goal[self.left_leg_servos[HIP_Y]] = self.planted[HIP_Y] - along[1] / along[0] * (knee - self.planted[KNEE])
        else:
            start_time, start = self.foot_down           # from where it left the pedal, relative to the hip
            hip = ctx.data.xpos[self.left_hip]
            ground = self._ground_point() - hip
            share = min((t - start_time) / c["foot_swing_time"], 1.0)
            point = hip + start + min(2.0 * share, 1.0) * (ground - start)
            point[2] = hip[2] + start[2] + share * (ground[2] - start[2])
            scratch = self.scratch
            scratch.qpos[:] = ctx.data.qpos
            scratch.qpos[servos.qpos_adr[self.ankle_servos["l"]]] = c["foot_ankle"]
            jac = np.zeros((3, ctx.model.nv))
            for _ in range(FOOT_IK_ITERATIONS):
                mujoco.mj_kinematics(ctx.model, scratch)
                mujoco.mj_comPos(ctx.model, scratch)
                mujoco.mj_jacSite(ctx.model, scratch, jac, None, self.foot_site)
                J = jac[:, self.left_leg_dofs]
                error = point - scratch.site_xpos[self.foot_site]
                step = np.zeros(ctx.model.nv)
                step[self.left_leg_dofs] = np.linalg.solve(J.T @ J + FOOT_IK_DAMPING * np.eye(len(self.left_leg_dofs)), J.T @ error)
                mujoco.mj_integratePos(ctx.model, scratch.qpos, step, 1.0)
                scratch.qpos[self.left_leg_qpos] = np.clip(scratch.qpos[self.left_leg_qpos], *self.left_leg_range)
            goal[self.left_leg_servos] = scratch.qpos[self.left_leg_qpos]
        goal[self.ankle_servos["l"]] = c["foot_ankle"]

    def _brake(self, torque: float) -> None:
        """The rim brakes for a total braking torque (N m at the wheels, front_brake_share of it at
        the front): each wheel hinge's dry friction, at most BRAKE_MAX_TORQUE, set through the edit
        log (a replay brakes alike)."""
        model = self.ctx.model
        friction = model.dof_frictionloss.copy()
        share = self.params["front_brake_share"]
        wanted = max(torque, 0.0)
        friction[self.bike.front_dof] = min(share * wanted, BRAKE_MAX_TORQUE)
        friction[self.bike.rear_dof] = min((1.0 - share) * wanted, BRAKE_MAX_TORQUE)
        self.ctx.servos.log.set_flat(model.dof_frictionloss, "dof_frictionloss", friction)

    def _limb_goal(self, state, which, servo_rows, ankles=None) -> np.ndarray:
        """Servo targets: the limbs ``servo_rows`` by inverse kinematics of the attachments
        ``which`` (hands on a fork turned to its command, feet on the pedals as they are), led
        by the servo's lag; the ankles on their curve when given; the rest at the mounted pose."""
        ctx, servos, bike = self.ctx, self.ctx.servos, self.bike
        scratch = self.scratch
        scratch.qpos[:] = ctx.data.qpos
        scratch.qpos[bike.steer_qpos] = self.fork_command
        if self.crank_command is not None:
            scratch.qpos[bike.crank_qpos] = self.crank_command
        for side, value in (ankles or {}).items():
            scratch.qpos[servos.qpos_adr[self.ankle_servos[side]]] = value
        if self.seat_pitch_time and self.planted is None:    # the pitch held moves from the mount's to seat_pitch
            blend = ctx.control_dt / (self.seat_pitch_time + ctx.control_dt)
            self.pelvis_pitch += blend * (self.params["seat_pitch"] - self.pelvis_pitch)
        if self.planted is not None or self.params["hold_seat_pitch"] or self.seat_pitch_time:
            self._seat_pelvis(scratch)
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

    def _pelvis_pitch(self, data) -> float:
        """The pelvis's pitch on the saddle (rad, about the frame's lateral axis; forward tilt negative)."""
        frame = data.xmat[self.bike.frame].reshape(3, 3)
        forward = data.xmat[self.pelvis].reshape(3, 3)[:, 0]
        return math.atan2(float(forward @ frame[:, 2]), float(forward @ frame[:, 0]))

    def _seat_pelvis(self, scratch) -> None:
        """Turn the rider in ``scratch`` about the seat pivot (the frame's lateral axis through the
        saddle) back to the pelvis pitch he rode with: the limbs' inverse kinematics then gives the
        targets that hold him there. Without it, once a foot has left its pedal the pelvis pitch is held
        by nothing but limbs whose targets follow them, and under a stand's propping leg it tipped
        back 36 deg in 3 s (docs/bicycle.md, the stop)."""
        model = self.ctx.model
        mujoco.mj_kinematics(model, scratch)
        turn = self.pelvis_pitch - self._pelvis_pitch(scratch)
        axis = scratch.xmat[self.bike.frame].reshape(3, 3)[:, 1]
        quat = np.zeros(4)
        mujoco.mju_axisAngle2Quat(quat, axis, -turn)
        rot = np.zeros(9)
        mujoco.mju_quat2Mat(rot, quat)
        pivot = scratch.site_xpos[self.pairs.bike[:2]].mean(axis=0)
        q = self.root_qpos
        scratch.qpos[q:q + 3] = pivot + rot.reshape(3, 3) @ (scratch.qpos[q:q + 3] - pivot)
        turned = np.zeros(4)
        mujoco.mju_mulQuat(turned, quat, scratch.qpos[q + 3:q + 7].copy())
        scratch.qpos[q + 3:q + 7] = turned

    def _pedal(self, t, state, torque: float) -> None:
        """Feet on the pedals: pedal IK and the ankle curve -> leg targets; eqs. 7-10 -> pedal
        forces -> leg torques (servo offsets)."""
        ctx, servos, bike = self.ctx, self.ctx.servos, self.bike
        model, data = ctx.model, ctx.data
        c = self.params
        curve = (c["ankle_mean"], c["ankle_swing"], c["ankle_phase"])
        ankles = {"r": ankle_angle(state["crank"], *curve), "l": ankle_angle(state["crank"] + math.pi, *curve)}
        attached = [2, 3, 4] if self.foot_down is not None else [2, 3, 4, 5]   # definition: the hands' and feet's attachments
        goal = self._limb_goal(state, attached, self.limb_servos, ankles)
        if self.foot_down is not None:
            self._left_leg_goal(t, goal)
        # eqs. 7-10: pedal forces, through each leg's Jacobian to joint torques (servo offsets)
        forces = dict(zip("rl", pedal_forces(torque, state["crank"], bike.crank_length)))
        offset = np.zeros(len(goal))
        axle = data.xpos[bike.crank_body]
        crank_axis = data.xmat[bike.crank_body].reshape(3, 3)[:, 1]
        for k, side in ((4, "r"), (5, "l"))[:1 if self.foot_down is not None else 2]:   # definition: the foot attachments
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
        rider = trajectory.meta.get("character")
        params = rider_settings(trajectory.meta["params"], load_character(rider) if rider else None)   # its limits
        metrics = ride_metrics(trajectory, params)
        return ("success" if not metrics["fell"] else "fell"), metrics
