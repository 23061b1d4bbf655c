"""Take-off for rotating skills (the dives): the balance behaviour crouches and leans, the leap
thrust extends the legs and ends with the lift-off hip angle that sets the somersault rate
(Wooten §4.3)."""
from __future__ import annotations

from .balance import Balance, inside_a_skill, standing_hip_height
from .behaviour import ControlContext
from .leap import CONSTANTS as LEAP, LeapThrust
from .sequencer import Step
from ..schema import Schema
from ..tuned.constants import constant, read_constants, register_constants

# the take-off's hand-set constant: data, takeoff_any.json's "constants" (docs/tables.md)
TAKEOFF_CONSTANTS = Schema(
    constant("lean_trigger", "1", 0.0, 2.0, "share of the crouch's COM offset, reached moving, that triggers the thrust"),
    constant("crouch_move_start", "s", 0.0, 2.0, "when the crouch starts moving after the take-off begins"),
    constant("crouch_move_time", "s", 0.05, 3.0, "how long the crouch takes to reach its posture"),
    constant("crouch_settle_time", "s", 0.0, 1.0, "how long before now the crouch posture must have been reached"),
)
register_constants("takeoff", TAKEOFF_CONSTANTS)
CONSTANTS = read_constants("takeoff", TAKEOFF_CONSTANTS)

SETTINGS = ("crouch_height", "crouch_pitch", "com_offset", "liftoff_hip", "arm_swing")


def takeoff_steps(ctx: ControlContext, cfg: dict) -> list[Step]:
    """Crouch (leaning by ``com_offset``), then thrust until the feet leave the ground. Leaning
    (back, ``com_offset`` < 0, or forward, > 0), the thrust starts once the COM, moving, has left
    the middle of the feet by that much (as the broad jump leans forward, §4.2)."""
    stand = standing_hip_height(ctx.character)

    def crouch(t):
        return Balance(inside_a_skill(
            pelvis_height=cfg["crouch_height"], torso_pitch=cfg["crouch_pitch"], com_offset_x=cfg["com_offset"],
            move_start=CONSTANTS.crouch_move_start, move_time=CONSTANTS.crouch_move_time, hold_time=0.0, return_to_stand=0), ctx)

    def crouched(b, t):
        lean = cfg["com_offset"]
        if lean < 0 and b.com_ahead_of_support() < CONSTANTS.lean_trigger * lean:
            return True
        if lean > 0 and b.com_ahead_of_support() > CONSTANTS.lean_trigger * lean:
            return True
        return b.posture_reached(t - CONSTANTS.crouch_settle_time)

    def thrust(t):
        return LeapThrust({}, ctx, cfg["crouch_height"], LEAP.vertical_timing, LEAP.ankle_gain_vertical,
                          cfg["liftoff_hip"], cfg["arm_swing"], stand_height=stand,
                          thrust_damping=cfg.get("thrust_damping", LEAP.thrust_damping_default),
                          thrust_lean=cfg.get("thrust_lean", 0.0))

    return [Step("crouch", crouch, crouched), Step("thrust", thrust, lambda b, t: b.lifted_off())]
