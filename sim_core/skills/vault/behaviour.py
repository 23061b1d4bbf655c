"""The handspring vault (Hodgins et al. 1995, [A] 146-164): the seed's six states, then balance.

1. hurdle     - the run starts in the flight before the board (the seed's initial state: forward
                6.75 m/s, the COM 0.9 m above the board's top, set as the initial qpos/qvel and
                logged in meta["start_state"]["skill"]); the hips block: the legs are held ahead of
                the body, so the board stops the feet ahead of the COM and the horizontal speed
                turns into rotation and rise.
2. board      - the feet on the springboard; the legs are held stiff while the board deflects, and
                at its maximum deflection (the deck's velocity reverses) the knees and ankles extend,
                pushing on the board as it rebounds.
3. first flight - eq. 12: each shoulder is servoed to gamma = lambda + phi, lambda the angle from the
                downward vertical of the line from the shoulder to the desired hand position on the
                horse and phi the body's forward pitch (the seed's gamma = lambda - phi with its
                pitch counted the other way), so the arms point at the hand position whatever the
                body's pitch and the hands are ground-speed matched to the horse; the wrists are
                set so that the palms strike the horse flat.
4. horse      - the hands on the horse: arms straight (stiff elbows), no torque at the shoulders or
                wrists (their servos' gains are zero); the angular and forward velocity carry the
                body over the hands.
5. second flight - a layout (straight body, arms overhead), the feet a little apart, and when the
                body has nearly turned upright the landing's leg placement (control/leap.py Landing);
                with second_pike set, a pike once the COM is over the hands that opens when the
                rotation still to come at the layout's rate covers what is left (as the somersault's
                tuck opens).
6. landing    - on the mat: knees and waist absorb (Landing, MatAbsorb) until the COM is over the
                feet's middle and slow (the seed's switch), the legs straighten (MatRise), then the
                balance controller stands her up; the gesture (arms thrown up and back), the bow
                (the balance pitches the torso forward and back, the COM kept over the feet), and she
                stands until the run ends (docs/vault.md).

Nothing but gravity, the contacts (board, horse, mat) and the joint servos moves her. The settings
per character come from ``sim_core/tuned/tables/vault_<character>.json`` and the shared design values
(apparatus layout, the seed's start) from ``vault_any.json``'s constants, each one a character's own table
holds in its "constants" replaced (the man's: his start, horse, board and run-up, scaled by Fig. 6).
"""
from __future__ import annotations

import dataclasses
import math

import mujoco
import numpy as np

from ...ballistics import GRAVITY, time_to_fall_to
from ...control.behaviour import Behaviour, ControlContext, register
from ...control.servo import hermite_scalar
from ...control.balance import Balance
from ...control.leap import UP, Landing, balance_after_landing, run_strength
from ...control.measure import pitch_of, roll_of
from ...control.recovery_step import RecoveryStep, StaggeredStance, StepAndHold
from ...control.sequencer import Sequence, Step
from ...analysis import FOOT_BODIES
from ..handspring.behaviour import HAND_BODIES, PoseMove
from .assess import LIMP_ON_HORSE
from ...control.tumble import FlightRotation, both_sides, inertia_about_com, rotation_to_come
from ...errors import ParameterError
from ...schema import Choice, Parameter, Schema
from ...tuned import TableType, characters_of, keyed, load, register as register_table
from ...tuned.constants import constant, constant_rows, own_constants, read_constants, with_constants
from ...tuned.settings import SkillSchema, prefixed, ranged as setting, unprefixed
from ...world.apparatus import (BOARD_LENGTH, BOARD_TOP, HORSE_1987_LENGTH, HORSE_1987_WIDTH,
                                PROP_BODY_PREFIX, VAULT_TABLE_HEIGHT_MEN,
                                VAULT_TABLE_HEIGHT_WOMEN, VAULT_TABLE_LENGTH, VAULT_TABLE_WIDTH)

# the vault's hand-set design values: data, vault_any.json's "constants" (docs/tables.md)
VAULT_CONSTANTS = Schema(
    constant("start_com_height", "m", 0.5, 1.5,
             "the seed's start: the COM this high above the board's top at rest ([A] 150: 0.9 m)"),
    constant("board_ahead", "m", 0.2, 3.0, "the board's centre this far ahead of the world's origin"),
    constant("touchdown_on_board", "m", -0.6, 0.6,
             "the start is placed so that the feet touch down this far ahead of the board's centre"),
    constant("horse_gap", "m", 0.0, 3.0, "the horse's near edge this far ahead of the board's front edge"),
    constant("board_stiffness", "N/m", 10000.0, 200000.0,
             "the springboard's spring: the woman's 40 kN/m (world.apparatus BOARD_STIFFNESS); a board's springs are set "
             "for the gymnast's weight (the man's: scaled by Fig. 6; docs/vault.md)"),
    constant("horse_height", "m", 0.8, 1.6,
             "the 1987 horse's height (vaulted sideways): the women's 1.20 m of Takei's data; a character's own "
             "table may hold another (the man's: hers x L by Fig. 6, 1.36 m, 1 cm above the men's horse; docs/vault.md)"),
    constant("mat_gap", "m", 0.0, 3.0, "the landing mat's near edge this far beyond the horse's far edge"),
    constant("mat_size", "m", 0.5, 20.0, "the landing mat's length and width"),
    constant("mat_thickness", "m", 0.05, 0.5, "the landing mat's thickness"),
    constant("handled_speed", "m/s", 0.0, 12.0, "the run-up speeds (board touchdown) the controller handles: [low, high]"),
    constant("plan_trials", "count", 1, 100, "the landing search at one run-up speed (planning.vault, report vault --plan) "
             "simulates the vault at most this often"),
    constant("plan_step", "m", 0.0001, 0.1, "its first step of foot_delta, doubled until the fall turns from forward to "
             "back (or back to forward)"),
    constant("plan_resolution", "m", 0.00001, 0.01, "it bisects that bracket until it is this narrow"),
    constant("servo_move", "s", 0.005, 1.0, "the servo move of a step's posture change where no setting names one"),
    constant("contact_force", "N", 0.0, 200.0, "a contact with an apparatus pushing this hard counts as touching"),
    constant("stand_settle", "s", 0.0, 5.0, "standing this long after the balance has stood her up, before the gesture"),
    constant("gesture", "rad", 0.0, 3.2, "the gesture of success: both arms thrown up and back by this much shoulder flexion"),
    constant("gesture_time", "s", 0.1, 5.0, "the arms' move into the gesture, and back"),
    constant("gesture_hold", "s", 0.0, 5.0, "the gesture is held this long"),
    constant("bow_pitch", "rad", 0.0, 1.5, "the bow: the balance pitches the torso this far forward ([A] 164) ..."),
    constant("bow_time", "s", 0.2, 5.0, "... in this time, and back up in the same time"),
    constant("bow_hold", "s", 0.0, 5.0, "the bow is held this long at its deepest"),
    constant("final_stand", "s", 0.0, 30.0, "after the bow she stands this long, and the run ends"),
)
CONSTANTS = read_constants("vault", VAULT_CONSTANTS)


def vault_constants(character: str | None):
    """The vault's constants for ``character``: vault_any.json's, each one the character's own table
    holds in its "constants" section replaced (the man's: scaled from the woman's by Fig. 6,
    adapt.skills.VaultAdapter); None: the shared ones."""
    return CONSTANTS if character is None else own_constants("vault", character, CONSTANTS)

APPARATUS = ("horse_1987", "table")
DEFLECTION_JOINT = PROP_BODY_PREFIX + "springboard/deflection"

PIECE_FROM_VAULT = ("ankle_max", "min_height")   # the step's and the stance's, from catch_ankle, absorb_min_height

VAULT_SETTINGS = Schema(
    setting("hurdle_vz", "m/s", -2.0, 0.5, "vertical COM velocity at the start (the hurdle flight's descent)"),
    setting("hurdle_lean", "rad", -0.8, 0.5, "the body's forward pitch at the start (- leans back: the hips block)"),
    setting("hurdle_spin", "rad/s", -5.0, 5.0, "the body's forward rotation rate at the start"),
    setting("hurdle_arm", "rad", -1.0, 3.14, "shoulder flexion of both arms at the start"),
    setting("hurdle_swing", "s", 0.0, 1.0,
            "the arms swing from hurdle_arm toward board_arm over this time from the start, through the hurdle "
            "flight, so they are moving forward-up as the feet meet the board (0: held until the board)"),
    setting("block_hip", "rad", -1.5, 0.5, "hip flexion (-) of the block: the legs held ahead of the body"),
    setting("board_knee", "rad", 0.0, 1.2, "knee bend at board touchdown, held while the board deflects"),
    setting("board_gain", "1", 1.0, 10.0, "gain factor of the leg servos on the board"),
    setting("board_arm", "rad", -1.0, 3.14, "the arms swing to this shoulder flexion on the board"),
    setting("board_arm_time", "s", 0.02, 0.5, "the board's arm swing takes this long"),
    setting("push_time", "s", 0.01, 0.3, "at maximum deflection the knees, hips and ankles extend in this time"),
    setting("push_after", "s", -1.0, 0.3,
            "the push starts this long after the board touchdown, while the deck is still going down (-1: at the "
            "deck's maximum deflection, the seed's)"),
    setting("push_ankle", "rad", -0.7, 0.9, "ankle angle the push extends to (- plantarflexion)"),
    setting("push_hip", "rad", -1.5, 0.5, "hip angle the push extends to"),
    setting("board_further", "m", -0.3, 0.5,
            "the board this much further from the horse than vault_any.json's horse_gap (the gymnast places the board; "
            "the horse and the mat move, the board and the start stay)"),
    setting("hand_ahead", "m", -0.5, 1.2, "the desired hand position: this far beyond the horse's near edge"),
    setting("flight_hip", "rad", -2.0, 0.5, "hip flexion (-) held in the first flight"),
    setting("open_pitch", "rad", 0.0, 4.0, "the first flight's pike opens once the body has pitched this far forward"),
    setting("open_time", "s", 0.01, 0.5, "the pike opens in this time"),
    setting("arm_gain", "1", 1.0, 10.0, "gain factor of the shoulder servos in the first flight (eq. 12)"),
    setting("reach_shoulder_x", "rad", 1.0, 1.75,
            "shoulder angle about the arm's forward axis in the first flight: the raised arms parallel, the hands "
            "shoulder-width apart (the standing pose's 1.43 brings them together overhead)"),
    setting("wrist_extension", "rad", -1.2, 1.2, "wrist extension of the palms-down hands (held unless palm_down)"),
    setting("forearm_twist", "rad", -1.4, 1.4,
            "the forearms' twist (elbow_*_y, the same on both sides) in the first flight, turning the palms toward "
            "the horse (0: as standing)"),
    setting("palm_down", "bool", 0.0, 1.0,
            "1 = in the first flight each wrist is servoed every tick to turn its palm straight down, from its "
            "forearm's measured orientation (within the wrist's range); 0 = wrist_extension held"),
    setting("elbow_gain", "1", 1.0, 20.0, "gain factor of the elbow servos on the horse (arms straight)"),
    setting("horse_release", "s", 0.0, 0.1,
            "the horse state ends once no hand has pushed on the horse for this long (0: at the first tick without, "
            "so a bounce of the hands ends it and the second flight's servos act while the arms are still on it)"),
    setting("horse_hip", "rad", -1.0, 0.5, "hip angle on the horse (0: the layout)"),
    setting("horse_gate", "bool", 0.0, 1.0,
            "1 = the shoulder and wrist servos have no gain at every tick in which any of her bodies pushes on the "
            "horse, in every state (TARGETS.md V5 read per tick: a bounce of the hands ends the horse state, and the "
            "second flight's shoulder servos then act whenever the hands are back on the top); their gains come back "
            "when nothing touches it; 0 = limp only in the horse state"),
    setting("open_before", "s", 0.0, 0.3,
            "the first flight's pike also opens (to horse_hip, in open_time) once the hands will reach the horse's top "
            "within this time at their present vertical speed, so the body is open at the hand touchdown; 0 = only at "
            "open_pitch"),
    setting("horse_shoulder_gain", "1", 0.0, 10.0,
            "gain factor of the shoulder flexion servos on the horse (0: limp, the seed's 'no shoulder torque'); "
            "above 0 they servo the arms toward horse_shoulder, blocking (the trunk held open over the hands)"),
    setting("horse_shoulder", "rad", 0.0, 3.14, "... the shoulder flexion they servo to on the horse (3.14: in line with the trunk)"),
    setting("flight_clav", "rad", -0.52, 0.26,
            "shoulder-girdle elevation (+: the shoulders toward the ears, clav_*_x; -: depressed) the clavicles move to "
            "in the first flight, so the horse's push has travel (0: as standing; used only with horse_clav_after >= 0)"),
    setting("horse_clav", "rad", -0.52, 0.26,
            "... the elevation the clavicles push to on the horse: the shrug moves the shoulders away from the hands "
            "along the arms, lengthening the hand-to-trunk chain"),
    setting("horse_clav_after", "s", -1.0, 0.3,
            "the shoulder-girdle push starts this long after the hand touchdown (-1: none, the clavicles held as standing)"),
    setting("horse_clav_time", "s", 0.01, 0.3, "... and takes this long"),
    setting("clav_gain", "1", 1.0, 10.0, "gain factor of the clavicle servos in the first flight and on the horse"),
    setting("layout_arm", "rad", 0.0, 3.14, "shoulder flexion in the second flight's layout"),
    setting("second_pike", "rad", -2.0, 0.0,
            "hip flexion (-) the second flight starts in; it opens to the layout once the rotation the laid-out body "
            "will still make before the touchdown covers what is left (0: a layout throughout)"),
    setting("second_pike_at", "m", -1.0, 0.5,
            "... the pike starts once the COM is this far past the hand goal (0: over it; - before it, for a horse "
            "contact that leaves the COM behind the hands)"),
    setting("second_open_time", "s", 0.02, 0.5, "... the second flight's pike opens in this time"),
    setting("second_knee", "rad", 0.0, 1.5,
            "... the knees bend this far with the pike and stay bent as it opens, so the legs arrive soft at the mat "
            "(0: straight in the second flight)"),
    setting("touchdown_lean", "rad", -1.0, 1.5,
            "... what is left: the whole body turned to this short of upright when the feet reach the mat"),
    setting("touchdown_com", "m", 0.3, 1.5, "the COM's height above the mat when the feet reach it (for the time left)"),
    setting("feet_apart", "rad", 0.0, 0.3,
            "hip abduction of each leg in the second flight, until the landing places the legs (the feet a little apart)"),
    setting("flight_feet_centre", "rad/m", 0.0, 20.0,
            "second flight: from the horse liftoff until the landing places the legs, both hips' abduction servos the "
            "feet's middle under the COM across the pelvis (each hip's target its measured angle plus this gain x the "
            "COM's sideways distance from the feet's middle; feet_apart, the same angle on both hips, carries both "
            "feet to her left); 0 = off, the hips held at feet_apart"),
    setting("landing_lean", "rad", 0.0, 2.0, "the landing's leg placement starts this far short of the upright"),
    setting("open_height", "m", 0.5, 2.0, "... or once the COM is this high above the mat, whichever is first"),
    setting("landing_knee_flexion", "rad", 0.0, 1.5, "knee bend held for the touchdown on the mat"),
    setting("landing_sideways", "bool", 0.0, 1.0,
            "landing: 1 = the hips place the feet sideways about the COM, each its hip's width from it (the leap's "
            "place_sideways: a trunk leaning sideways does not leave the COM over one foot); 0 = the legs straight "
            "down from the pelvis"),
    setting("foot_delta", "m", -0.3, 0.3, "landing: foot servo delta (the landing's placement ahead of the capture point)"),
    setting("landing_foot_lead_time", "s", 0.0, 0.6, "landing: the feet land this many seconds of COM travel ahead"),
    setting("spin_placement", "s/m", 0.0, 0.5, "landing: feet placed this factor x (angular momentum / mass) against the spin"),
    setting("absorb_kp", "1", 0.0, 2.0, "after the touchdown: gain factor of the knee and hip servos (they give)"),
    setting("absorb_kv", "1", 0.0, 10.0, "after the touchdown: damping factor of the knee and hip servos"),
    setting("absorb_knee", "rad", 0.0, 1.5, "the knees' targets this much deeper than at the touchdown"),
    setting("absorb_stick", "bool", 0.0, 1.0,
            "1 = the knees stick the landing: their targets follow the measured knees (the servos only damp) while the "
            "COM still goes down, and hold where they are once it stops (no spring back up); 0 = absorb_knee deeper"),
    setting("absorb_hip_gain", "1", 0.0, 5.0, "after the touchdown: gain factor of the hip servos (the waist)"),
    setting("absorb_trunk", "rad", -0.5, 1.5, "after the touchdown the hips servo the pelvis to lean this far forward"),
    setting("absorb_trunk_kp", "rad/m", -10.0, 10.0,
            "... less this much per metre of the capture point ahead of the feet's middle"),
    setting("capture_spin", "bool", 0.0, 1.0,
            "1 = the absorb's capture point takes the speed from the angular momentum about the feet's middle (the "
            "spin about the COM included: H_f / (m h)); 0 = the COM's forward speed"),
    setting("absorb_min_height", "m", 0.05, 1.0, "the capture point's COM height is at least this (a guard)"),
    setting("settled_spin", "kg m²/s", 0.0, 50.0, "... and its angular momentum about the lateral axis is below this"),
    setting("absorb_com_kp", "rad/m", -20.0, 20.0, "ankle offset per metre of the COM ahead of the feet's middle while absorbing"),
    setting("absorb_com_kv", "rad s/m", -10.0, 10.0, "ankle offset per m/s of the COM's forward speed while absorbing"),
    setting("absorb_side_kp", "rad/m", -20.0, 20.0, "ankle roll per metre of the COM left of the feet's middle while absorbing"),
    setting("absorb_side_kv", "rad s/m", -10.0, 10.0, "ankle roll per m/s of the COM's leftward speed while absorbing"),
    setting("capture_after", "s", 0.0, 3.0, "... or, this long after the touchdown, once the capture point is ..."),
    setting("capture_within", "m", 0.0, 0.3, "... within this of the feet's middle"),
    setting("over_feet", "m", 0.0, 0.3, "the balance takes over once the COM is at most this far behind the feet's middle ..."),
    setting("settled_speed", "m/s", 0.0, 2.0, "... and moves slower than this"),
    setting("absorb_max", "s", 0.05, 3.0, "... or this long after the touchdown"),
    setting("rise_time", "s", 0.1, 5.0, "after the landing the knees straighten in this time before the balance"),
    setting("rise_knee", "rad", 0.0, 1.5, "... to this knee bend"),
    setting("rise_from_target", "bool", 0.0, 1.0,
            "1 = the rise's knees start from the absorb's knee targets (the servo's error that held her in the crouch is "
            "kept through the hand-over); 0 = from the measured knees (the holding torque drops to nothing as the rise "
            "starts)"),
    setting("stand_time", "s", 0.2, 5.0, "the balance stands up from the landed crouch in this time"),
    setting("stand_com_offset", "m", -0.25, 0.25, "... with the COM this far ahead (+) of the feet's middle"),
    setting("landing_blend", "s", 0.0, 0.3, "landing: the joint targets blend in from the layout over this time"),
    setting("catch", "bool", 0.0, 1.0,
            "1 = the landing catches the momentum in the impact (MatCatch): the knees and the waist give as pure "
            "dampers while the COM falls and hold where it stopped (nothing stored to throw the trunk back up), and "
            "the ankles servo the capture point over the feet from the touchdown on, through the rise; 0 = MatAbsorb"),
    setting("catch_kp", "rad/m", 0.0, 20.0, "catch: ankle offset per metre of the capture point ahead of catch_target"),
    setting("catch_target", "m", -0.15, 0.15, "catch: the capture point is servoed this far ahead of the feet's middle"),
    setting("catch_lean_max", "rad", 0.0, 1.5, "catch: the waist gives at most to this forward lean of the pelvis"),
    setting("catch_lean_kp", "rad/m", -10.0, 10.0,
            "catch: once the fall has stopped, the held lean less this much per metre of the capture point ahead of "
            "catch_target (the trunk's place moves the COM)"),
    setting("catch_knee_max", "rad", 0.5, 2.5, "catch: the knees give at most to this flexion, then hold there"),
    setting("catch_ankle", "rad", 0.0, 0.6,
            "catch: the ankles' capture-point offset is limited to this either way (0: to what the balance's feet "
            "take standing, the landing's ankle limits)"),
    setting("place_capture", "bool", 0.0, 1.0,
            "1 = the landing places the feet from the predicted touchdown (MatLanding): so that the capture point "
            "of the angular momentum about the feet at the touchdown is place_target ahead of them; 0 = the leap's "
            "placement (foot_delta, landing_foot_lead_time, spin_placement)"),
    setting("place_target", "m", -0.3, 0.3,
            "... the capture point at the touchdown, H_f / (m sqrt(g h)) ahead of the COM's place, this far ahead "
            "of the feet (H_f the angular momentum about the feet, kept through the impact)"),
    setting("catch_side_hip", "1", 0.0, 2.0,
            "catch: the hips' abduction offset per radian of the ankles' sideways command (the hips shift the pelvis "
            "over the feet, as the balance's eq. 7.2 does; 0: the ankles alone)"),
    setting("catch_rise_time", "s", 0.1, 5.0, "catch: the rise along the crouch table takes this long"),
    setting("catch_within", "m", 0.0, 0.3, "catch: the rise starts once the capture point is this close to catch_target ..."),
    setting("catch_min", "s", 0.0, 2.0, "... and at least this long after the touchdown"),
    setting("rise_capture", "bool", 0.0, 1.0,
            "1 = the rise servos the capture point (MatCaptureRise): it starts once the COM's fall has stopped and the "
            "capture point is within rise_margin of catch_target, and goes up the crouch table no faster than "
            "catch_rise_time, slowed to a stop as the capture point nears rise_margin; the ankles and the hips servo "
            "the capture point meanwhile (the catch's catch_kp, catch_lean_kp); 0 = MatRise's (or the catch's) timed rise"),
    setting("rise_margin", "m", 0.01, 0.3, "rise_capture: the capture point's distance from catch_target where the rise stops"),
    setting("recovery_step", "bool", 0.0, 1.0,
            "1 = when the capture point leaves step_at of catch_target after the touchdown (the catch's or the "
            "absorb's), one foot steps to it (control/recovery_step.py RecoveryStep) and the staggered stance is "
            "held (StaggeredStance) through the gesture and the bow; 0 = no step"),
    setting("step_at", "m", 0.02, 0.5, "step: the capture point this far from catch_target ..."),
    setting("step_after", "s", 0.0, 2.0, "... at least this long after the touchdown (and before the rise) ..."),
    setting("step_before", "s", 0.0, 3.0,
            "... and at most this long after it (later the mat's rebound unloads the stance foot: no step then, the "
            "landing goes on without it)"),
    setting("step_spin", "bool", 0.0, 1.0,
            "step: 1 = the trigger's capture point takes its speed from the angular momentum about the feet (the "
            "trunk's spin counts, as capture_spin; the catch's own servo unchanged); 0 = the catch's"),
    setting("step_vz", "m/s", 0.0, 5.0,
            "... while the COM moves up or down slower than this (not in the impact's fall nor the rebound off the mat)"),
    *prefixed(RecoveryStep.schema, "step_", "step", exclude=PIECE_FROM_VAULT),
    *prefixed(StaggeredStance.schema, "hold_", "staggered stance", exclude=PIECE_FROM_VAULT),
    *prefixed(StepAndHold.schema, "hold_", "further steps"),
)


def load_table(character: str) -> dict:
    """The character's vault table (no rows if there is none)."""
    return load("vault", character) or {"vaults": []}


def vault_row(table: dict, strength: str) -> dict | None:
    """The row of the strength (keyed), or None."""
    return keyed(table["vaults"], strength=strength)


def calibrated(character: str, strength: str) -> dict | None:
    """The vault settings of this character and strength, or None."""
    return vault_row(load_table(character), strength)


VAULT_TABLE = register_table(TableType(
    "vault", with_constants(VAULT_SETTINGS, VAULT_CONSTANTS),
    lambda body: (*((f"vaults {e['strength']}", e["settings"]) for e in body.get("vaults", [])), *constant_rows(body)),
    (vault_row,)))


def apparatus_layout(params: dict, character, further: float = 0.0) -> dict:
    """Where the board, the horse (or table) and the mat stand: (x, y, ...) tuples for World, along
    +X from the start's COM at x = 0, the horse ``further`` (the setting board_further) beyond the
    constant gap. The women's horse of Takei's 1987 data (sideways) or the FIG table at the character's
    height (women's for the woman, men's for the man)."""
    k = vault_constants(None if character is None else character.name)
    board_x = k.board_ahead
    near = board_x + BOARD_LENGTH / 2 + k.horse_gap + further
    if APPARATUS[int(round(params["apparatus"]))] == "horse_1987":
        height, length, width = k.horse_height, HORSE_1987_LENGTH, HORSE_1987_WIDTH
        length, width = width, length                  # sideways: its 0.35 m across the run
    else:
        height = VAULT_TABLE_HEIGHT_MEN if character is not None and character.name == "man" else VAULT_TABLE_HEIGHT_WOMEN
        length, width = VAULT_TABLE_LENGTH, VAULT_TABLE_WIDTH
    far = near + length
    mat_length, mat_width = k.mat_size
    return {"springboard": (board_x, 0.0, k.board_stiffness), "vault_table": (near + length / 2, 0.0, height, length, width),
            "landing_mat": (far + k.mat_gap + mat_length / 2, 0.0, mat_length, mat_width, k.mat_thickness),
            "near_edge": near, "far_edge": far, "height": height}


class ApparatusTouch:
    """Whether some of the actor's bodies push on one named world geom (an apparatus), from
    MuJoCo's contact list and the contacts' normal forces of the last step."""

    def __init__(self, model, geom: str, bodies, prefix: str = ""):
        self.model = model
        self.geom = model.geom(geom).id
        self.bodies = np.array([model.body(prefix + b).id for b in bodies])
        self.force = np.zeros(6)

    def touching(self, data) -> bool:
        n = data.ncon
        if not n:
            return False
        contact = data.contact
        geoms = contact.geom[:n]
        body = self.model.geom_bodyid
        for k in range(n):
            g1, g2 = int(geoms[k, 0]), int(geoms[k, 1])
            other = g2 if g1 == self.geom else g1 if g2 == self.geom else -1
            if other < 0 or body[other] not in self.bodies:
                continue
            mujoco.mj_contactForce(self.model, data, k, self.force)
            if self.force[0] > CONSTANTS.contact_force:
                return True
        return False


class PoseLaw(PoseMove):
    """The handspring's PoseMove (Hermite moves of some joints to named angles, some servos' gains
    scaled, every other target held) with some servos limp (gain zero: no torque) and a ``law``
    called every tick with t, for targets that follow the measured state (eq. 12, the board's push)."""

    def __init__(self, ctx: ControlContext, goals: dict[str, float], move_time: float, gain: float = 1.0,
                 gain_joints: list[str] | None = None, limp: tuple[str, ...] = (), law=None,
                 gains: dict[str, float] | None = None):
        super().__init__(ctx, goals, move_time, gain, gain_joints=[] if gain_joints is None else gain_joints)
        self.limp, self.law, self.gains = limp, law, gains or {}

    def start(self, t: float) -> None:
        super().start(t)
        s = self.ctx.servos
        for name in self.limp:
            i = s.indices([name])
            s.set_gains(i, 0.0, 0.0)
        for name, factor in self.gains.items():          # some servos with their own gain factor
            i = s.indices([name])
            s.set_gains(i, s.default_kp[i] * factor, s.default_kv[i] * factor)

    def update(self, t: float) -> None:
        if self.law is not None:
            self.law(t)


class MatLanding(Landing):
    """The leap's landing with the feet placed from the predicted touchdown (``place_capture``): the
    angular momentum about the feet, H_f = L_y + m (h v_x - dx v_z), is what the contact forces at the
    feet leave through the impact, and the capture point it carries, dx + H_f / (m sqrt(g h)), is where
    the COM will come to rest. With the touchdown's v_z (from the feet's height and the fall) and h =
    ``touchdown_com``, the COM's place dx that puts that point ``place_target`` ahead of the feet is solved
    every tick of the flight (it is linear in dx), and the feet are servoed (eq. 6.1) to -dx ahead of the
    COM. (The servo lags: the feet land ~8 cm short of the goal, so place_target is below the point aimed at.)"""

    def __init__(self, params, ctx: ControlContext, cfg: dict):
        super().__init__(params, ctx)
        self.cfg = cfg

    def foot_wanted(self, vx: float, spin_offset: float) -> float:
        if not self.cfg["place_capture"]:
            return super().foot_wanted(vx, spin_offset)
        d = self.ctx.data
        v = d.subtree_linvel[self.pelvis]
        drop = max(float(self.airborne.feet_heights(d).min()), 0.0)
        vz = -math.sqrt(float(v[2]) ** 2 + 2.0 * GRAVITY * drop)      # at the touchdown
        h = self.cfg["touchdown_com"]                  # the COM above the feet at the touchdown (the flight's aim)
        reach = math.sqrt(GRAVITY * h)
        spin = float(d.subtree_angmom[self.pelvis][1]) / self.mass
        dx = (self.cfg["place_target"] - (spin + h * float(v[0])) / reach) / (1.0 - vz / reach)
        return -dx


class MatAbsorb(Behaviour):
    """The landing on the mat after the touchdown ([A] 162): the knees and the waist (hips) give
    as dampers - their servos softened (``absorb_kp``) and damped (``absorb_kv``), their targets a
    little deeper than where they touched down - while the ankles servo the COM over the middle of
    the feet (eq. 7.1's law, within what the feet can take) and keep the feet flat. It hands over
    to the balance controller once the COM passes over the middle of the feet (the seed's switch)
    and has slowed, or after ``absorb_max``."""

    schema = Schema()

    def __init__(self, ctx: ControlContext, cfg: dict, landing: Landing):
        super().__init__({}, ctx)
        self.cfg, self.landing = cfg, landing
        body = ctx.actor.body_id
        self.pelvis, self.feet = body("PELVIS"), [body("FOOTR"), body("FOOTL")]
        s = ctx.servos
        self.joints = {side: {k: s.index[f"{j}_{side}_{a}"] for k, (j, a) in
                              {"hip": ("hip", "y"), "knee": ("knee", "y"), "ankle": ("ankle", "y"),
                               "ankle_x": ("ankle", "x"), "hip_x": ("hip", "x")}.items()}
                       for side in "rl"}
        self.knees = s.indices(["knee_r_y", "knee_l_y"])
        self.hips = s.indices(["hip_r_y", "hip_l_y"])
        self.ankle_front, self.ankle_back = landing.ankle_front, landing.ankle_back
        self.over_feet = False
        self.stopped = False                    # rise_capture: the COM's fall has stopped
        self.stuck = None                       # absorb_stick: the knees where the fall stopped

    def start(self, t: float) -> None:
        s, c = self.ctx.servos, self.cfg
        s.offset[:] = 0.0
        self.t0 = t
        targets = s.angles().copy()
        for side in "rl":
            targets[self.joints[side]["knee"]] += c["absorb_knee"]
        self.base = targets
        s.hold(targets, t)
        s.set_gains(self.knees, s.default_kp[self.knees] * c["absorb_kp"], s.default_kv[self.knees] * c["absorb_kv"])
        s.set_gains(self.hips, s.default_kp[self.hips] * c["absorb_hip_gain"], s.default_kv[self.hips] * c["absorb_hip_gain"])

    def com_from_feet(self, axis: int = 0) -> tuple[float, float]:
        """The COM's distance ahead of (axis 0; axis 1: left of) the middle of the supporting feet
        (m) and its speed that way (the vault runs along +X)."""
        d = self.ctx.data
        points = self.landing.airborne.support.supporting_points(d)
        com = d.subtree_com[self.pelvis]
        middle = 0.5 * (points[:, axis].min() + points[:, axis].max())
        return float(com[axis] - middle), float(d.subtree_linvel[self.pelvis][axis])

    def capture_point(self, ahead: float, speed: float, spin: bool | None = None) -> tuple[float, float]:
        """The capture point (the COM's place plus its speed times sqrt(h / g)) ahead of the feet's middle,
        and the speed it takes (with capture_spin, or ``spin``, from the angular momentum about the feet's middle);
        ``ahead``, ``speed``: com_from_feet's."""
        d, c = self.ctx.data, self.cfg
        height = float(d.subtree_com[self.pelvis][2]) - float(self.landing.airborne.support.points(d)[:, 2].min())
        height = max(height, c["absorb_min_height"])
        if c["capture_spin"] if spin is None else spin:
            # the angular momentum about the feet's middle (the spin about the COM with the COM's own) as
            # the speed a point mass at the COM's height would carry: the trunk's rotation counts too
            v = d.subtree_linvel[self.pelvis]
            mass = float(self.ctx.model.body_subtreemass[self.pelvis])
            about_feet = float(d.subtree_angmom[self.pelvis][1]) + mass * (height * float(v[0]) - ahead * float(v[2]))
            speed = about_feet / (mass * height)
        return ahead + speed * math.sqrt(height / GRAVITY), speed

    def pelvis_lean(self) -> float:
        """The pelvis's forward pitch."""
        return pitch_of(self.ctx.data.xmat[self.pelvis], UP)

    def update(self, t: float) -> None:
        d, s, c = self.ctx.data, self.ctx.servos, self.cfg
        ahead, speed = self.com_from_feet()
        ankle = min(max(c["absorb_com_kp"] * ahead + c["absorb_com_kv"] * speed, -self.ankle_back), self.ankle_front)
        targets = self.base.copy()
        angles = s.angles()
        # the capture point ahead of the feet's middle leans the trunk back, behind it forward
        capture, speed = self.capture_point(ahead, speed)
        trunk_error = self.pelvis_lean() - (self.trunk_lean(t) - c["absorb_trunk_kp"] * capture)
        self.knee_base(t, targets)
        self.knee_targets = targets[self.knees].copy()
        left, left_speed = self.com_from_feet(1)
        sideways = c["absorb_side_kp"] * left + c["absorb_side_kv"] * left_speed
        self.feet_and_hips(targets, angles, ankle, sideways, trunk_error)
        s.hold(targets, t)
        spin = float(d.subtree_angmom[self.pelvis][1])
        if c["rise_capture"]:
            self.over_feet = self.capture_inside(capture)
            return
        if (ahead >= -self.cfg["over_feet"] and abs(speed) < self.cfg["settled_speed"]
                and abs(spin) < self.cfg["settled_spin"]) or (
                t - self.t0 > self.cfg["capture_after"] and abs(capture) < self.cfg["capture_within"]):
            self.over_feet = True

    def capture_inside(self, capture: float) -> bool:
        """rise_capture's start: the COM's fall has stopped (it has moved up once since the touchdown) and the
        capture point is within rise_margin of catch_target."""
        if float(self.ctx.data.subtree_linvel[self.pelvis][2]) >= 0.0:
            self.stopped = True
        return self.stopped and abs(capture - self.cfg["catch_target"]) < self.cfg["rise_margin"]

    def feet_and_hips(self, targets: np.ndarray, angles: np.ndarray, ankle: float, sideways: float,
                      trunk_error: float, side_hip: float | None = None) -> None:
        """Both legs' targets: each ankle turns its foot flat and offsets it by ``ankle`` (the COM's or the
        capture point's servo); sideways the ankles roll the feet flat and servo the COM between them the
        same way (``sideways``), and given ``side_hip`` the hips' abduction (from the base pose) shifts the pelvis with them; the
        waist gives: the hips servo the trunk by ``trunk_error``, whatever the legs do."""
        d = self.ctx.data
        for k, side in enumerate("rl"):
            f = d.xmat[self.feet[k]]
            joints = self.joints[side]
            targets[joints["ankle"]] = angles[joints["ankle"]] - pitch_of(f, UP) + ankle
            targets[joints["ankle_x"]] = angles[joints["ankle_x"]] - roll_of(f, UP) - sideways
            targets[joints["hip"]] = angles[joints["hip"]] + trunk_error
            if side_hip is not None:
                targets[joints["hip_x"]] = self.base[joints["hip_x"]] + side_hip * sideways

    def trunk_lean(self, t: float) -> float:
        """The pelvis's forward pitch the hips servo (the waist gives this far)."""
        return self.cfg["absorb_trunk"]

    def knee_base(self, t: float, targets: np.ndarray) -> None:
        """The knees' targets: where they touched down, a little deeper (set in start); with
        absorb_stick, the measured knees while the COM goes down (the servos damp the fall and
        store nothing), then held where the fall stopped."""
        if not self.cfg["absorb_stick"]:
            return
        if self.stuck is None:
            if float(self.ctx.data.subtree_linvel[self.pelvis][2]) < 0.0:
                targets[self.knees] = self.ctx.servos.angles()[self.knees]
                return
            self.stuck = self.ctx.servos.angles()[self.knees].copy()
        targets[self.knees] = self.stuck

    @property
    def finished(self) -> bool:
        return self.over_feet


class MatRise(MatAbsorb):
    """After the landing has brought the COM to rest over the feet: the same ankle and trunk servo
    while the knees straighten over ``rise_time`` (Hermite) and the trunk's lean goes to upright;
    then the balance controller takes over near its standing height. (The balance standing up from
    the deep landed crouch itself, with the ankles at their dorsiflexion limit, let the COM drift.)"""

    def __init__(self, ctx: ControlContext, cfg: dict, landing: Landing, absorb: MatAbsorb | None = None):
        super().__init__(ctx, cfg, landing)
        self.absorb = absorb

    def start(self, t: float) -> None:
        super().start(t)
        s = self.ctx.servos
        held = self.cfg["rise_from_target"] and getattr(self.absorb, "knee_targets", None) is not None
        self.knees_from = (self.absorb.knee_targets if held else s.angles()[self.knees]).copy()
        self.lean_from = float(self.pelvis_lean())

    def share(self, t: float) -> float:
        return hermite_scalar((t - self.t0) / self.cfg["rise_time"])

    def trunk_lean(self, t: float) -> float:
        return self.lean_from * (1.0 - self.share(t))

    def knee_base(self, t: float, targets: np.ndarray) -> None:
        targets[self.knees] = self.knees_from + (self.cfg["rise_knee"] - self.knees_from) * self.share(t)

    @property
    def finished(self) -> bool:
        return self.share(self.ctx.data.time) >= 1.0


class MatCatch(MatAbsorb):
    """The landing meant to take the momentum in the impact (``catch``): from the touchdown the knees and
    the waist are pure dampers while the COM falls - their targets follow the measured joints (the knees
    down to ``catch_knee_max``, the waist up to ``catch_lean_max`` of forward lean) - and once the fall has
    stopped they hold where it stopped (she still rebounds off the mat: docs/vault.md). Throughout, the
    ankles servo the capture point (the COM's place plus its speed times sqrt(h / g), the spin about the
    COM counted with ``capture_spin``) to ``catch_target`` ahead of the feet's middle, within
    ``catch_ankle``; a continuous servo, not a switch. The held lean moves by ``catch_lean_kp`` per metre
    of the capture point's error, and sideways the hips' abduction joins the ankles' roll
    (``catch_side_hip``). Once the fall has stopped, ``catch_min`` has passed and the capture point is
    within ``catch_within``, the rise (``MatCatchRise``) stands her up with the same servos."""

    def start(self, t: float) -> None:
        super().start(t)
        self.fallen = False                         # the COM's fall stopped
        self.held_knees = None
        self.held_lean = None
        self.capture = 0.0

    def ankle_limits(self, t: float) -> tuple[float, float]:
        """How far back and forward the ankles' capture-point offset may go (catch_ankle, or the balance's)."""
        c = self.cfg
        return (c["catch_ankle"], c["catch_ankle"]) if c["catch_ankle"] else (self.ankle_back, self.ankle_front)

    def posture(self, t: float, targets: np.ndarray, angles: np.ndarray) -> float:
        """The knees' targets (set in ``targets``) and the pelvis lean the hips servo: the measured ones
        while the COM falls (the waist up to catch_lean_max), held where the fall stopped, the held lean
        moved by the capture point's error (catch_lean_kp)."""
        c, d = self.cfg, self.ctx.data
        lean = self.pelvis_lean()
        if not self.fallen and float(d.subtree_linvel[self.pelvis][2]) >= 0.0 and t - self.t0 > 0.0:
            self.fallen = True
            self.held_knees = np.minimum(angles[self.knees], c["catch_knee_max"])
            self.held_lean = min(lean, c["catch_lean_max"])
        if not self.fallen:
            targets[self.knees] = np.minimum(angles[self.knees], c["catch_knee_max"])
            return min(lean, c["catch_lean_max"])
        targets[self.knees] = self.held_knees
        return self.held_lean - c["catch_lean_kp"] * (self.capture - c["catch_target"])

    def update(self, t: float) -> None:
        self.capture, _ = self.capture_point(*self.com_from_feet())
        self.steer(t)

    def steer(self, t: float) -> None:
        """This tick's targets from the capture point measured (``self.capture``)."""
        s, c = self.ctx.servos, self.cfg
        targets = self.base.copy()
        angles = s.angles()
        back, front = self.ankle_limits(t)
        ankle = min(max(c["catch_kp"] * (self.capture - c["catch_target"]), -back), front)
        trunk_error = self.pelvis_lean() - self.posture(t, targets, angles)
        left, left_speed = self.com_from_feet(1)
        sideways = c["absorb_side_kp"] * left + c["absorb_side_kv"] * left_speed
        self.feet_and_hips(targets, angles, ankle, sideways, trunk_error, c["catch_side_hip"])
        s.hold(targets, t)
        if c["rise_capture"]:
            self.over_feet = self.capture_inside(self.capture)
        elif (self.fallen and t - self.t0 >= c["catch_min"]
                and abs(self.capture - c["catch_target"]) < c["catch_within"]):
            self.over_feet = True


class MatCatchRise(MatCatch):
    """The catch's rise, along the landing's crouch table (balanced crouches, the COM over the feet): over
    ``catch_rise_time`` (Hermite) the knees go to the crouch of a height rising from where the rise began to
    standing, and the hips lean the pelvis as the crouch of the height she is at leans (less catch_lean_kp
    per metre of the capture point ahead of catch_target), while the ankles go on servoing the capture
    point, their limits going over to the balance's; then the balance. (Straightening the knees with the
    lean going to upright, as ``MatRise`` does, carried the COM back behind the heels: docs/vault.md.)"""

    def start(self, t: float) -> None:
        super().start(t)
        self.fallen = True
        self.height_from = self.pelvis_height()

    def share(self, t: float) -> float:
        return hermite_scalar((t - self.t0) / self.cfg["catch_rise_time"])

    def ankle_limits(self, t: float) -> tuple[float, float]:
        """From the catch's to the balance's over the rise, so the feet meet the balance as it holds them."""
        back, front = super().ankle_limits(t)
        share = self.share(t)
        return back + (self.ankle_back - back) * share, front + (self.ankle_front - front) * share

    def pelvis_height(self) -> float:
        """The mid-hip point's height above the feet, with the ankles' own height (the crouch table's measure)."""
        d, landing = self.ctx.data, self.landing
        hips = 0.5 * (d.xpos[landing.hips[0]] + d.xpos[landing.hips[1]])
        feet = 0.5 * (d.xpos[landing.feet[0]] + d.xpos[landing.feet[1]])
        return float(hips[2] - feet[2]) + landing.ankle_height

    def posture(self, t: float, targets: np.ndarray, angles: np.ndarray) -> float:
        table = self.landing.crouch
        top = float(table.heights[-1])
        targets[self.knees] = table.at(self.height_from + (top - self.height_from) * self.share(t))[0]
        lean = float(table.at(self.pelvis_height())[3])
        return lean - self.cfg["catch_lean_kp"] * (self.capture - self.cfg["catch_target"])

    @property
    def finished(self) -> bool:
        return self.share(self.ctx.data.time) >= 1.0


class MatCaptureRise(MatCatchRise):
    """rise_capture: the catch's rise along the crouch table (the knees to the crouch of a rising height, the hips
    leaning the pelvis as that crouch leans, less catch_lean_kp per metre of the capture point's error; the ankles
    servo the capture point to catch_target) with its progress servoed by the capture point: it advances at
    1 / catch_rise_time with the capture point at catch_target, slower as it moves away, and not at all from
    rise_margin on, so the rise never carries the COM out of the feet (a timed rise ran it out: docs/vault.md)."""

    def start(self, t: float) -> None:
        self.progress, self.t_last = 0.0, t
        super().start(t)

    def share(self, t: float) -> float:
        return hermite_scalar(self.progress)

    def update(self, t: float) -> None:
        c = self.cfg
        self.capture, _ = self.capture_point(*self.com_from_feet())
        rate = max(0.0, 1.0 - abs(self.capture - c["catch_target"]) / c["rise_margin"]) / c["catch_rise_time"]
        self.progress = min(1.0, self.progress + rate * (t - self.t_last))
        self.t_last = t
        self.steer(t)

    @property
    def finished(self) -> bool:
        return self.progress >= 1.0


class ArmGesture(Behaviour):
    """The gesture of success ([A] 164): the balance that stands her goes on, and both arms are
    thrown up and back - a Hermite rise of the shoulders' flexion by CONSTANTS.gesture over
    gesture_time, held, and back - on top of the balance's arm targets (a servo offset, which the
    balance leaves alone on the arms); the balance's ankles keep the COM over the feet."""

    schema = Schema()

    def __init__(self, ctx: ControlContext, balance: Behaviour):
        super().__init__({}, ctx)
        self.balance = balance
        self.shoulders = ctx.servos.indices(["shoulder_r_z", "shoulder_l_z"])
        self.sign = np.array([1.0, -1.0])            # the left arm's axis is mirrored

    def start(self, t: float) -> None:
        self.t0 = t

    def lift(self, t: float) -> float:
        up, hold = CONSTANTS.gesture_time, CONSTANTS.gesture_hold
        u = t - self.t0
        share = hermite_scalar(u / up) if u < up + hold else 1.0 - hermite_scalar((u - up - hold) / up)
        return CONSTANTS.gesture * share

    @property
    def finished(self) -> bool:
        return self.ctx.data.time - self.t0 >= 2 * CONSTANTS.gesture_time + CONSTANTS.gesture_hold

    def update(self, t: float) -> None:
        self.balance.update(t)
        self.ctx.servos.offset[self.shoulders] = self.sign * self.lift(t)


@register
class Vault(Sequence):
    name = "vault"
    world_frame = True             # the apparatus stands along +X from the origin
    summary = ("Handspring vault (Hodgins et al. 1995): hurdle, springboard, first flight (eq. 12), hands on the "
               "horse, layout second flight, landing on the mat, balance, the gesture and the bow.")
    default_duration = 14.0            # longer than the whole script: the run ends final_stand after the bow
    settings_schema = VAULT_SETTINGS
    schema = SkillSchema(
        Parameter("runup_speed", "m/s", 6.75, 0.0, 12.0,
                  "horizontal COM speed of the hurdle flight (the seed's start: 6.75 m/s, Takei's mean); the "
                  "controller handles the range of the character's handled_speed (vault_any.json's, or its own table's)"),
        Choice("apparatus", APPARATUS, "horse_1987",
               "what she vaults: the 1987 women's horse of Takei's data (sideways, 1.20 m) or the FIG table"),
        Parameter("low_level", "bool", 0.0, 0.0, 1.0,
                  "1 = run the tuned settings as set (--set block_hip=...) instead of the character's table, "
                  "at any run-up speed (unchecked)"),
        settings=VAULT_SETTINGS,
    )

    @classmethod
    def character_defaults(cls, character: str) -> dict:
        """A body whose handled run-up speeds leave out the schema's (the man's 7.2826-7.284 m/s) vaults,
        unless told, at the middle of its range."""
        low, high = vault_constants(character).handled_speed
        speed = cls.schema.by_name["runup_speed"].default
        return {} if low <= speed <= high else {"runup_speed": round((low + high) / 2, 5)}

    # ------------------------------------------------------------------ the world and the start
    @classmethod
    def scene(cls, params, world, character=None):
        """The requested world with the springboard, the horse (or table) and the landing mat (the vault
        rows are set for human strength: another strength runs only with low_level, its settings as set)."""
        settings = cls.settings_for(params, character.name, "human") if character is not None else params
        layout = apparatus_layout(params, character, settings["board_further"])
        return dataclasses.replace(world, springboard=layout["springboard"], vault_table=layout["vault_table"],
                                   landing_mat=layout["landing_mat"])

    @classmethod
    def settings_for(cls, params: dict, character_name: str, strength: str) -> dict:
        if params["low_level"]:
            return {k: params[k] for k in VAULT_SETTINGS.by_name}
        row = calibrated(character_name, strength)
        return dict(row["settings"]) if row else {k: params[k] for k in VAULT_SETTINGS.by_name}

    @classmethod
    def start_state(cls, params, model, data, character, prefix=""):
        """The seed's hurdle flight: the standing pose with the block (hips flexed, knees bent, arms
        raised), the body pitched by hurdle_lean, the COM start_com_height above the board's top at
        x = 0, every body moving at (runup_speed, 0, hurdle_vz) plus the hurdle's forward spin."""
        strength = "human" if model.actuator_forcelimited[model.actuator(prefix + "knee_r_y").id] else "unlimited"
        c = cls.settings_for(params, character.name, strength)
        k = vault_constants(character.name)
        pose = both_sides({"hip_*_y": c["block_hip"], "knee_*_y": c["board_knee"], "shoulder_*_z": c["hurdle_arm"],
                           "elbow_*_z": 0.0})
        for name, value in pose.items():
            data.qpos[model.joint(prefix + name).qposadr[0]] = value
        root = model.joint(prefix + "root")
        q, v = int(root.qposadr[0]), int(root.dofadr[0])
        lean = c["hurdle_lean"]
        data.qpos[q + 3:q + 7] = [math.cos(lean / 2), 0.0, math.sin(lean / 2), 0.0]
        mujoco.mj_kinematics(model, data)
        mujoco.mj_comPos(model, data)
        com = data.subtree_com[root.bodyid[0]].copy()
        data.qpos[q:q + 3] += np.array([0.0, 0.0, BOARD_TOP + k.start_com_height]) - com
        own = model.body_rootid[model.dof_bodyid] == root.bodyid[0]     # this character's dofs only
        data.qvel[own] = 0.0
        mujoco.mj_kinematics(model, data)
        # the feet touch the board (ballistically, the hurdle's rotation aside) at touchdown_on_board
        # from its centre: the whole body is shifted along +X for that
        feet = data.site_xpos[[i for i in range(model.nsite) if model.body(model.site_bodyid[i]).name in
                                [prefix + b for b in FOOT_BODIES]]]
        lowest = feet[int(np.argmin(feet[:, 2]))]
        fall = lowest[2] - BOARD_TOP
        vz = c["hurdle_vz"]
        fall_time = (vz + math.sqrt(vz * vz + 2 * GRAVITY * max(fall, 0.0))) / GRAVITY
        data.qpos[q] += k.board_ahead + k.touchdown_on_board - (lowest[0] + params["runup_speed"] * fall_time)
        mujoco.mj_kinematics(model, data)
        mujoco.mj_comPos(model, data)
        com = data.subtree_com[root.bodyid[0]].copy()
        # a rigid motion: the COM at (speed, 0, vz), the whole body turning at hurdle_spin about the
        # COM (the free joint's linear velocity is the root body's origin's)
        origin = data.qpos[q:q + 3]
        spin = c["hurdle_spin"]
        data.qvel[v:v + 3] = [params["runup_speed"] + spin * (origin[2] - com[2]), 0.0,
                              c["hurdle_vz"] - spin * (origin[0] - com[0])]
        data.qvel[v + 3:v + 6] = np.array([0.0, spin, 0.0]) @ data.xmat[root.bodyid[0]].reshape(3, 3)
        return {"state": "hurdle", "com": com.tolist(), "com_velocity": [params["runup_speed"], 0.0, c["hurdle_vz"]],
                "pitch": lean, "spin": spin, "com_above_board": k.start_com_height}

    def check_feasible(self) -> None:
        if self.params["low_level"]:
            return                  # the settings as set, at any run-up speed (how handled_speed is measured)
        speed = self.params["runup_speed"]
        low, high = vault_constants(self.ctx.character.name).handled_speed
        if not low <= speed <= high:
            raise ParameterError(f"parameter runup_speed={speed:g} m/s is outside what the vault controller handles; "
                                 f"allowed range is [{low:g}, {high:g}] m/s")
        name, strength = self.ctx.character.name, run_strength(self.ctx)
        if calibrated(name, strength) is None:
            limits = "unlimited strength" if strength == "unlimited" else "human torque limits"
            rows = [f"{e['strength']} strength" for e in load_table(name)["vaults"]]
            raise ParameterError(f"the {name} has no vault settings with {limits} (sim_core/tuned/tables/vault_{name}.json: "
                                 f"{', '.join(rows) or 'none'}); the vault is set for the "
                                 f"{' and the '.join(characters_of('vault'))} with human torque limits")

    # ------------------------------------------------------------------ measurements
    def body_pitch(self) -> float:
        """phi: the trunk's forward pitch from vertical (pelvis to the upper chest), unwrapped."""
        d = self.ctx.data
        axis = d.xpos[self.chest] - d.xpos[self.pelvis]
        raw = math.atan2(float(axis[0]), float(axis[2]))
        self._pitch += (raw - self._last_raw + math.pi) % (2 * math.pi) - math.pi
        self._last_raw = raw
        return self._pitch

    def deck_velocity(self) -> float:
        return float(self.ctx.data.qvel[self.deck_dof])

    # ------------------------------------------------------------------ the script
    def steps(self) -> list[Step]:
        ctx = self.ctx
        m, d, s = ctx.model, ctx.data, ctx.servos
        c = self.cfg = self.settings_for(self.params, ctx.character.name, run_strength(ctx))
        layout = apparatus_layout(self.params, ctx.character, c["board_further"])
        self.hand_goal = np.array([layout["near_edge"] + c["hand_ahead"], 0.0, layout["height"]])
        self.mat_top = vault_constants(ctx.character.name).mat_thickness
        body = ctx.actor.body_id
        self.pelvis, self.chest = body("PELVIS"), body("CHEST1")
        self.shoulders = [body("UARMR"), body("UARML")]
        self.forearms = [body("LARMR"), body("LARML")]
        self.feet = [body("FOOTR"), body("FOOTL")]
        p = ctx.actor.prefix
        hips_x = ["hip_r_x", "hip_l_x"]
        self.hips_x = ctx.servos.indices(hips_x)
        self.hip_x_range = m.jnt_range[[ctx.actor.joint_id(name) for name in hips_x]]
        wrists = [f"wrist_{side}_{axis}" for side in "rl" for axis in "xy"]
        self.wrist_range = m.jnt_range[[ctx.actor.joint_id(name) for name in wrists]]
        self.wrist_servos = ctx.servos.indices(wrists)
        self.shoulder_range = m.jnt_range[[ctx.actor.joint_id("shoulder_r_z"), ctx.actor.joint_id("shoulder_l_z")]]
        self._last_raw = 0.0
        self._pitch = 0.0
        self._pitch = self._last_raw = math.atan2(*(d.xpos[self.chest] - d.xpos[self.pelvis])[[0, 2]])
        self.deck_dof = int(m.jnt_dofadr[m.joint(DEFLECTION_JOINT).id])
        self.on_board = ApparatusTouch(m, "springboard", FOOT_BODIES, p)
        self.on_horse = ApparatusTouch(m, "vault_table", HAND_BODIES, p)
        self.rotation = FlightRotation(m, d, ctx.actor)
        legs = both_sides({"hip_*_y": 1, "knee_*_y": 1, "ankle_*_y": 1})
        arms_z = ["shoulder_r_z", "shoulder_l_z"]
        everyone = [m.body(i).name[len(p):] for i in range(m.nbody) if m.body_rootid[i] == ctx.actor.root]
        self.touching_horse = ApparatusTouch(m, "vault_table", everyone, p)
        self.limp_servos = s.indices(list(LIMP_ON_HORSE))
        self.gated = None                               # horse_gate: the gains taken away while she touches
        self.hands = [body("HANDR"), body("HANDL")]
        self.pushed = self.deck_going_down = self.opened = False
        self.stepping, self.step_direction = False, 0.0
        self.hands_off_since = None

        def board(t):
            self.board_t0 = t
            return PoseLaw(ctx, both_sides({"shoulder_*_z": c["board_arm"]}), c["board_arm_time"], c["board_gain"],
                           list(legs), law=lambda t: self.board_law(t))

        clav = ["clav_r_x", "clav_l_x"]
        girdle = c["horse_clav_after"] >= 0.0            # the shoulder-girdle push on the horse

        def clav_goals(elevation: float) -> dict[str, float]:
            # elevation raises the right shoulder at clav_r_x < 0 and the left at clav_l_x > 0
            return {"clav_r_x": -elevation, "clav_l_x": elevation}

        def first_flight(t):
            s.set_gains(s.indices(list(legs)), s.default_kp[s.indices(list(legs))], s.default_kv[s.indices(list(legs))])
            return PoseLaw(ctx, both_sides({"hip_*_y": c["flight_hip"], "knee_*_y": 0.0, "ankle_*_y": 0.5,
                                            "elbow_*_z": 0.0, "elbow_*_y": c["forearm_twist"],
                                            "wrist_*_x": c["wrist_extension"],
                                            "shoulder_*_x": c["reach_shoulder_x"]})
                           | (clav_goals(c["flight_clav"]) if girdle else {}), CONSTANTS.servo_move,
                           c["arm_gain"], arms_z, law=lambda t: (self.reach_law(t), self.palm_law(t)),
                           gains={j: c["clav_gain"] for j in clav} if girdle else None)

        def horse(t):
            self.horse_t0, self.girdle_pushed = t, not girdle
            law = (lambda t: self.girdle_law(t, clav_goals(c["horse_clav"]))) if girdle else None
            clav_gains = {j: c["clav_gain"] for j in clav} if girdle else {}
            if not c["horse_shoulder_gain"]:
                return PoseLaw(ctx, both_sides({"hip_*_y": c["horse_hip"], "elbow_*_z": 0.0}), CONSTANTS.servo_move,
                               c["elbow_gain"], ["elbow_r_z", "elbow_l_z"], limp=LIMP_ON_HORSE, law=law, gains=clav_gains)
            # blocking: the shoulders' flexion servos act (toward horse_shoulder), the rest of the arm limp
            return PoseLaw(ctx, both_sides({"hip_*_y": c["horse_hip"], "elbow_*_z": 0.0,
                                            "shoulder_*_z": c["horse_shoulder"]}), CONSTANTS.servo_move,
                           c["elbow_gain"], ["elbow_r_z", "elbow_l_z"], limp=tuple(j for j in LIMP_ON_HORSE if j not in arms_z),
                           gains={j: c["horse_shoulder_gain"] for j in arms_z} | clav_gains, law=law)

        def second_flight(t):
            s.set_gains(np.arange(len(s.names)), s.default_kp, s.default_kv)
            self.rotation.takeoff(t)
            self.second_opened = c["second_pike"] == 0.0
            self.second_piked = False
            return PoseLaw(ctx, both_sides({"hip_*_y": 0.0, "knee_*_y": 0.0, "shoulder_*_z": c["layout_arm"],
                                            "hip_*_x": c["feet_apart"], "wrist_*_x": 0.0, "wrist_*_y": 0.0,
                                            "elbow_*_y": 0.0}), CONSTANTS.servo_move,
                           law=lambda t: self.second_flight_law(t))

        def ready_to_land(b, t):
            turned = self.body_pitch()
            com_z = float(d.subtree_com[ctx.actor.root][2])
            return self.second_opened and (turned >= 2 * math.pi - c["landing_lean"] or com_z - self.mat_top < c["open_height"]
                                           ) and float(d.subtree_linvel[ctx.actor.root][2]) < 0

        def land(t):
            return MatLanding(Landing.schema.validate(dict(
                knee_flexion=c["landing_knee_flexion"], fast_knee_flexion=c["landing_knee_flexion"],
                foot_delta=c["foot_delta"], foot_lead_time=c["landing_foot_lead_time"],
                spin_placement=c["spin_placement"], blend_time=c["landing_blend"],
                place_sideways=c["landing_sideways"])), ctx, c)

        def hurdle(t):
            swing = both_sides({"shoulder_*_z": c["board_arm"]}) if c["hurdle_swing"] > 0 else {}
            return PoseLaw(ctx, swing, c["hurdle_swing"] or CONSTANTS.servo_move, c["board_gain"], list(legs))

        return [
            Step("hurdle", hurdle,
                 lambda b, t: self.on_board.touching(d)),
            Step("board", board, lambda b, t: self.pushed and not self.on_board.touching(d)),
            Step("first_flight", first_flight, lambda b, t: self.on_horse.touching(d)),
            Step("horse", horse, lambda b, t: self.off_horse(t)),
            Step("second_flight", second_flight, ready_to_land),
            Step("landing", land, lambda b, t: b.stage != "flight"),
            Step("absorb", lambda t: (MatCatch if c["catch"] else MatAbsorb)(ctx, c, self.previous),
                 lambda b, t: b.finished or t - b.t0 > c["absorb_max"] or self.must_step(b, t)),
            Step("rise", lambda t: self.recovery_step() if self.stepping else
                 MatCaptureRise(ctx, c, self.previous.landing) if c["rise_capture"] else
                 MatCatchRise(ctx, c, self.previous.landing) if c["catch"] else
                 MatRise(ctx, c, self.previous.landing, self.previous),
                 lambda b, t: b.finished),
            Step("balance", lambda t: self.step_and_hold() if self.stepping else self.stand_up(),
                 lambda b, t: (b.risen(t) and t - b.t_stance >= c["hold_rise_time"] + CONSTANTS.stand_settle)
                 if self.stepping
                 else b.posture_reached(t) and t - b.t0 >= c["stand_time"] + CONSTANTS.stand_settle),
            Step("gesture", lambda t: ArmGesture(ctx, self.previous),
                 lambda b, t: b.finished),
            Step("bow", lambda t: self.staggered((CONSTANTS.bow_pitch, CONSTANTS.bow_time, CONSTANTS.bow_hold))
                 if self.stepping else self.bow(), lambda b, t: b.posture_back(t)),
            Step("stand", lambda t: self.staggered() if self.stepping else
                 self.rebalance(move_start=0.0, return_to_stand=0)),
        ]

    def must_step(self, absorb: MatAbsorb, t: float) -> bool:
        """recovery_step: the capture point (the absorb's measure) further than step_at from catch_target,
        from step_after to step_before after the touchdown, the COM's vertical speed under step_vz; the step's
        direction is its sign."""
        c = self.cfg
        if not c["recovery_step"] or not c["step_after"] <= t - absorb.t0 <= c["step_before"]:
            return False
        if abs(float(self.ctx.data.subtree_linvel[self.pelvis][2])) >= c["step_vz"]:
            return False
        capture, _ = absorb.capture_point(*absorb.com_from_feet(), spin=bool(c["step_spin"]) or None)
        error = capture - c["catch_target"]
        if abs(error) <= c["step_at"]:
            return False
        self.stepping, self.step_direction = True, error
        return True

    def recovery_step(self) -> RecoveryStep:
        """The step to the capture point (control/recovery_step.py), with the vault's step settings."""
        return RecoveryStep(self.step_params(), self.ctx, self.step_direction)

    def step_and_hold(self) -> StepAndHold:
        """The staggered stance after the step, with further steps (hold_max_steps) while the capture point
        nears the support's edge (control/recovery_step.py)."""
        return StepAndHold(unprefixed(StepAndHold.schema, "hold_", self.cfg), self.ctx, self.step_params(),
                           self.stance_params())

    def piece_given(self) -> dict:
        """What the step and the staggered stance take from the vault's other settings."""
        return dict(ankle_max=self.cfg["catch_ankle"], min_height=self.cfg["absorb_min_height"])

    def step_params(self) -> dict:
        """RecoveryStep's parameters: the vault's step_ settings."""
        return unprefixed(RecoveryStep.schema, "step_", self.cfg, **self.piece_given())

    def staggered(self, bow: tuple[float, float, float] | None = None) -> StaggeredStance:
        """The stance after the step held (control/recovery_step.py), standing up, and with ``bow`` the bow."""
        return StaggeredStance(self.stance_params(), self.ctx, bow)

    def stance_params(self) -> dict:
        """StaggeredStance's parameters: the vault's hold_ settings."""
        return unprefixed(StaggeredStance.schema, "hold_", self.cfg, **self.piece_given())

    @property
    def run_complete(self) -> bool:
        """The run ends when she has stood ``final_stand`` after the bow."""
        return (getattr(self, "script", None) is not None and self.step_name == "stand"
                and self.ctx.data.time - self.current.t0 >= CONSTANTS.final_stand)

    def stand_up(self) -> Behaviour:
        """The balance from the landed crouch, standing up over ``stand_time`` (rebalance)."""
        self.landing = self.previous.landing                  # the rise's landing
        return self.rebalance(move_time=self.cfg["stand_time"], com_offset_x=self.cfg["stand_com_offset"])

    def bow(self) -> Balance:
        """The bow ([A] 164): the balance that stands her moves the torso bow_pitch forward over
        bow_time, holds it bow_hold, and comes back up; its COM servo keeps the COM over the feet
        (the ankles take the hips back as the trunk goes forward). The gesture's arm offsets are
        back at zero; they are cleared."""
        self.ctx.servos.offset[self.ctx.servos.indices(["shoulder_r_z", "shoulder_l_z"])] = 0.0
        balance = self.rebalance(torso_pitch=CONSTANTS.bow_pitch, move_start=0.0, move_time=CONSTANTS.bow_time,
                                 hold_time=CONSTANTS.bow_hold, return_to_stand=1)
        balance.posture_back = lambda t: t - balance.t0 >= 2 * CONSTANTS.bow_time + CONSTANTS.bow_hold
        return balance

    def rebalance(self, **params) -> Balance:
        """A balance (balance_after_landing: from the height the legs' length names) that starts
        from the trunk's pitch as it is and moves to ``params``' posture: a balance started from an
        upright trunk snapped the leaning one up and threw the COM, and one started from the
        standing pose lost her within a second."""
        balance = balance_after_landing(self.ctx, self.landing)
        balance.from_pitch = pitch_of(self.ctx.data.xmat[self.pelvis], UP)
        balance.params = dict(balance.params, **params)
        return balance

    def off_horse(self, t: float) -> bool:
        """No hand has pushed on the horse for ``horse_release`` (the hands' bounces do not end the state)."""
        if self.on_horse.touching(self.ctx.data):
            self.hands_off_since = None
            return False
        if self.hands_off_since is None:
            self.hands_off_since = t
        return t - self.hands_off_since >= self.cfg["horse_release"]

    def board_law(self, t: float) -> None:
        """At the board's maximum deflection (its deck stops going down) the legs extend; with push_after
        set, that long after the board touchdown instead (while the deck still goes down: the hips' push on
        the loaded legs then deflects the board further, event ``push``)."""
        if self.deck_velocity() < 0.0:
            self.deck_going_down = True
        timed = self.cfg["push_after"] >= 0.0 and t - self.board_t0 >= self.cfg["push_after"]
        if self.pushed or not timed and (self.cfg["push_after"] >= 0.0 or not self.deck_going_down
                                         or self.deck_velocity() < 0.0):
            return
        self.pushed = True
        self.event(t, "push" if timed else "max_deflection")
        c, s = self.cfg, self.ctx.servos
        goals = both_sides({"knee_*_y": 0.0, "hip_*_y": c["push_hip"], "ankle_*_y": c["push_ankle"]})
        s.move_to(s.indices(list(goals)), np.array(list(goals.values())), c["push_time"], t)

    def girdle_law(self, t: float, goals: dict[str, float]) -> None:
        """The shoulder-girdle push on the horse: horse_clav_after after the hand touchdown the
        clavicles elevate to horse_clav in horse_clav_time (event ``girdle``), the shoulders moving away
        from the hands along the straight arms (a shrug; the clavicle servos, within their torque limits)."""
        if self.girdle_pushed or t - self.horse_t0 < self.cfg["horse_clav_after"]:
            return
        self.girdle_pushed = True
        self.event(t, "girdle")
        s = self.ctx.servos
        s.move_to(s.indices(list(goals)), np.array(list(goals.values())), self.cfg["horse_clav_time"], t)

    def reach_law(self, t: float) -> None:
        """Eq. 12: each shoulder at gamma = lambda + phi (the arm along the line to the hand goal)."""
        d, s = self.ctx.data, self.ctx.servos
        phi = self.body_pitch()
        if not self.opened and (phi > self.cfg["open_pitch"] or self.hands_arrive_within(self.cfg["open_before"])):
            # the pike that sped the rotation opens before the hands land: the straight body and
            # the arms in line carry the horse's push through the COM
            self.opened = True
            self.event(t, "open")
            hips = s.indices(["hip_r_y", "hip_l_y"])
            s.move_to(hips, np.array([self.cfg["horse_hip"]] * 2), self.cfg["open_time"], t)
        goals = []
        for k, side in enumerate("rl"):
            # each hand's goal is on the horse straight ahead of its own shoulder (the hands land
            # shoulder-width apart); lambda is in the shoulder's sagittal plane
            to_hand = self.hand_goal - d.xpos[self.shoulders[k]]
            lam = math.atan2(float(to_hand[0]), float(-to_hand[2]))       # from the downward vertical, + forward
            gamma = lam + phi
            goals.append(gamma if side == "r" else -gamma)
        i = s.indices(["shoulder_r_z", "shoulder_l_z"])
        s.start[i] = s.goal[i] = np.clip(goals, self.shoulder_range[:, 0], self.shoulder_range[:, 1])
        s.t0[i] = t

    def hands_arrive_within(self, before: float) -> bool:
        """Whether the lower hand, at its present vertical speed, reaches the horse's top within ``before``
        seconds (0: never asked)."""
        if before <= 0.0:
            return False
        d = self.ctx.data
        k = min(self.hands, key=lambda h: float(d.xpos[h][2]))
        above, vz = float(d.xpos[k][2]) - float(self.hand_goal[2]), float(d.subtree_linvel[k][2])
        return vz < 0.0 and above < -vz * before

    def gate_on_horse(self, t: float) -> None:
        """horse_gate: at every tick in which any of her bodies pushes on the horse the shoulder and wrist
        servos have no gain, whatever the state (a state starting meanwhile sets its gains, which are kept
        to come back); once nothing touches it they get back the gains they had."""
        s, m = self.ctx.servos, self.ctx.model
        i = self.limp_servos
        if self.touching_horse.touching(self.ctx.data):
            kp = m.actuator_gainprm[i + s.first, 0].copy()
            kv = -m.actuator_biasprm[i + s.first, 2].copy()
            if np.any(kp != 0.0) or np.any(kv != 0.0):
                self.gated = (kp, kv)
                s.set_gains(i, 0.0, 0.0)
        elif self.gated is not None:
            s.set_gains(i, *self.gated)
            self.gated = None

    def palm_law(self, t: float) -> None:
        """palm_down: each wrist (x, then y) turned so that its palm faces straight down, solved from
        its forearm's measured orientation F: the hand's frame is F R_x(w_x) R_y(w_y), and its
        normal (the thin axis, up in the palm-down reference pose) is up when R_x R_y e_z = F^T e_z
        = u, i.e. w_y = asin(u_x), w_x = atan2(-u_y, u_z); clipped to the wrist's range."""
        if not self.cfg["palm_down"]:
            return
        d, s = self.ctx.data, self.ctx.servos
        goals = []
        for forearm in self.forearms:
            up = d.xmat[forearm].reshape(3, 3)[2]             # F^T e_z: the world's up in the forearm's frame
            goals += [math.atan2(-float(up[1]), float(up[2])), math.asin(float(np.clip(up[0], -1.0, 1.0)))]
        i = self.wrist_servos
        s.start[i] = s.goal[i] = np.clip(goals, self.wrist_range[:, 0], self.wrist_range[:, 1])
        s.t0[i] = t

    def second_flight_law(self, t: float) -> None:
        """The second flight's rotation, closed on the measured state: the pike (second_pike) turns
        her faster; it opens to the layout once the rotation the laid-out body will still make
        before the feet reach the mat (at the layout's rate for her angular momentum, plus about
        half the difference over the opening) covers what is left to turn to touchdown_lean short
        of upright - as the somersault's tuck opens (skills/somersault). An over-rotating vault
        opens at once."""
        if self.cfg["flight_feet_centre"]:
            self.centre_feet(t)
        if self.second_opened:
            return
        c, d = self.cfg, self.ctx.data
        root = self.ctx.actor.root
        s = self.ctx.servos
        if not self.second_piked:
            # the pike once the COM has passed over the hands' goal on the horse
            if float(d.subtree_com[root][0]) < self.hand_goal[0] + c["second_pike_at"]:
                return
            self.second_piked = True
            self.event(t, "second_pike")
            # the layout it opens to: the straight body with the arms overhead, as she leaves the horse
            self.layout_inertia = float(inertia_about_com(self.ctx.model, d, self.ctx.actor)[1, 1])
            s.move_to(s.indices(["hip_r_y", "hip_l_y"]), np.array([c["second_pike"]] * 2), c["second_open_time"], t)
            if c["second_knee"]:
                s.move_to(s.indices(["knee_r_y", "knee_l_y"]), np.array([c["second_knee"]] * 2), c["second_open_time"], t)
        remaining = 2 * math.pi - c["touchdown_lean"] - self.rotation.whole_body
        rate_open = float(d.subtree_angmom[root][1]) / self.layout_inertia
        time_left = time_to_fall_to(float(d.subtree_com[root][2]), float(d.subtree_linvel[root][2]),
                                    self.mat_top + c["touchdown_com"])
        if time_left > c["second_open_time"] and rotation_to_come(self.rotation.rate(), rate_open, time_left,
                                                                  c["second_open_time"]) < remaining:
            return
        self.second_opened = True
        self.event(t, "second_open")
        s.move_to(s.indices(["hip_r_y", "hip_l_y"]), np.zeros(2), c["second_open_time"], t)

    def centre_feet(self, t: float) -> None:
        """flight_feet_centre: both hips' abduction (positive swings a foot to her left, on either side) moves
        the feet's middle under the COM across the pelvis - each target the measured angle plus the gain x the
        COM's sideways distance from the feet's middle, so the servo's torque is proportional to it."""
        d, s = self.ctx.data, self.ctx.servos
        across = d.xmat[self.pelvis].reshape(3, 3)[:, 1]          # the pelvis's left, in the world
        feet = 0.5 * (d.xpos[self.feet[0]] + d.xpos[self.feet[1]])
        off = float(np.dot(d.subtree_com[self.ctx.actor.root] - feet, across))
        i = self.hips_x
        s.start[i] = s.goal[i] = np.clip(s.angles()[i] + self.cfg["flight_feet_centre"] * off,
                                         self.hip_x_range[:, 0], self.hip_x_range[:, 1])
        s.t0[i] = t

    def update(self, t: float) -> None:
        self.rotation.update(t)
        self.body_pitch()
        super().update(t)
        if self.cfg["horse_gate"]:          # cfg: set by steps(), which start() runs before any update
            self.gate_on_horse(t)

    @classmethod
    def assess(cls, trajectory):
        from .assess import vault_assess
        return vault_assess(trajectory)
