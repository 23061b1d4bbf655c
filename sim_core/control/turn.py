"""Turning to face a sideways target before jumping: small vertical hops whose thrust rotates the
hips (LeapThrust's ``liftoff_turn``), each turning the body an eighth of a turn against the planted
feet, the legs turned back under the pelvis in flight (Landing's ``untwist``), a short balance
between them - then the leap itself runs forward in the new heading.

Why (docs/jump_to_target.md): a sideways jump's take-off rolls and twists the body and its landing
does not take the sideways speed of a 1.3-1.6 m jump (a 0.45 m drop at 1.1 m/s sideways or more
fell with every foot lead and knee bend tried), while the forward landing does; a person jumping
far to a side turns to face the way first. Measured on the man: a 0.15 m hop with the hips rotated
0.5 rad by lift-off turned him 52 deg and landed balanced (1.0 rad: 94 deg, fell); two of them turn
him 86-93 deg, the feet 0.2-0.25 m further from a target on the side turned to.

A turn by an angle (the leap's ``turn_angle``, a target to the side made a forward jump along its
bearing): one hop whose hips rotate the angle x ``hop_turn_per_rad``. Measured on the woman: 0.15 / 0.3
/ 0.56 / 0.8 rad asked turned her 12 / 29 / 42 / 53 deg, with a scatter of about +-4 deg from one asked
angle to the next (the feet pivot on the ground as the hips untwist after the touchdown).
"""
from __future__ import annotations

from types import SimpleNamespace

from .balance import Balance, inside_a_skill, standing_hip_height
from .behaviour import ControlContext
from .leap import Landing, LeapThrust, balance_after_landing, leap_constants, load_mapping, vertical_key, vertical_row
from .sequencer import Step
from ..schema import Schema
from ..tuned.constants import constant, own_constants, read_constants, register_constants

# the turn's hand-set constants: data, turn_any.json's "constants" (docs/tables.md)
TURN_CONSTANTS = Schema(
    constant("hops", "count", 1.0, 4.0, "hops to a quarter turn"),
    constant("hop_height", "m", 0.05, 0.5, "COM rise of each hop (the vertical leap table's row for it)"),
    constant("hop_turn", "rad", 0.0, 1.0, "hip rotation of each hop's thrust (both hips alike)"),
    constant("crouch_time", "s", 0.2, 2.0, "each hop's crouch moves to its posture in this time"),
    constant("settle_time", "s", 0.0, 3.0,
             "after a hop's landing the balance stands up (its hand-over time) and then holds this long before the next"),
    constant("hop_turn_per_rad", "rad/rad", 0.0, 2.0,
             "a turn by an angle (the leap's turn_angle): one hop whose hips rotate this much per rad of heading asked"),
    constant("turn_time", "s", 0.0, 10.0,
             "the hops take at most this long, from the start to the leap's own crouch (measured: 5.6 s; a run that turns "
             "first is this much longer)"),
)
register_constants("turn", TURN_CONSTANTS)
CONSTANTS = read_constants("turn", TURN_CONSTANTS)


def turn_constants(character: str):
    """The turn's constants for ``character``: turn_any's (measured on the man), or the character's
    own where a ``turn_<character>.json`` holds them (the woman's hops turn her further: her own hop_turn)."""
    return own_constants("turn", character, CONSTANTS)

STEP_PREFIX = "turn_"        # the hops' steps are named turn_crouch, turn_thrust, turn_land, turn_settle


def turn_steps(ctx: ControlContext, direction: float, sequence, angle: float = 0.0) -> list[Step]:
    """The steps of a quarter turn by hops, to the right for ``direction`` > 0.5, to the left below
    -0.5 (each hop's hip rotation ``direction`` x hop_turn), none else; or, for ``angle`` != 0 (rad,
    counter-clockwise from above: to the left), one hop whose hips rotate ``angle`` x hop_turn_per_rad
    toward it; ``sequence`` is the Sequence running them (its ``previous``, the landing just
    ended, starts each balance)."""
    c, leap = turn_constants(ctx.character.name), leap_constants(ctx.character.name)
    if angle:
        hops, turn = 1, -angle * c.hop_turn_per_rad          # the hips' + rotation turns to the right
    elif abs(direction) <= 0.5:               # definition: the setting is a switch, its sign the side
        return []
    else:
        hops, turn = int(round(c.hops)), direction * c.hop_turn   # +-1: the measured quarter turn
    hop = SimpleNamespace(**vertical_row(load_mapping(ctx.character.name)[vertical_key(ctx)], c.hop_height))
    stand = standing_hip_height(ctx.character)

    def crouch(t):
        return Balance(inside_a_skill(
            pelvis_height=hop.crouch_height, torso_pitch=hop.crouch_pitch, com_offset_x=hop.com_offset,
            move_start=leap.crouch_move_start, move_time=c.crouch_time, hold_time=0.0, return_to_stand=0), ctx)

    def thrust(t):
        return LeapThrust({}, ctx, hop.crouch_height, leap.vertical_timing, leap.ankle_gain_vertical, hop.liftoff_hip,
                          hop.arm_swing, stand_height=stand, thrust_damping=hop.thrust_damping, liftoff_turn=turn)

    def land(t):
        return Landing(Landing.schema.validate(dict(foot_delta=hop.foot_delta, untwist=1.0)), ctx)

    def settle(t):
        return balance_after_landing(ctx, sequence.previous)

    one = [Step(STEP_PREFIX + "crouch", crouch, lambda b, t: b.posture_reached(t - leap.crouch_settle_time)),
           Step(STEP_PREFIX + "thrust", thrust, lambda b, t: b.lifted_off()),
           Step(STEP_PREFIX + "land", land, lambda b, t: b.finished),
           Step(STEP_PREFIX + "settle", settle, lambda b, t: b.posture_reached(t - c.settle_time))]
    return one * hops


def turn_duration(direction: float, angle: float = 0.0) -> float:
    """How much longer a run is that turns first (turn_steps' ``direction`` or ``angle``: one hop of the hops)."""
    if angle:
        return CONSTANTS.turn_time / CONSTANTS.hops
    return CONSTANTS.turn_time if abs(direction) > 0.5 else 0.0


def jump_start(trajectory) -> float:
    """When the leap's own crouch began in a run that turned first (its last hop's balance ended):
    0 for a run without the turn."""
    settles = [when for when, name in trajectory.meta.get("phase_events", []) if name == STEP_PREFIX + "settle"]
    if not settles:
        return 0.0
    return min((when for when, name in trajectory.meta["phase_events"] if name == "crouch" and when > max(settles)),
               default=0.0)
