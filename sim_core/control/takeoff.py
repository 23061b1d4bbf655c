"""Take-off for rotating skills (the dives): the balance behaviour crouches and leans, the leap
thrust extends the legs and ends with the lift-off hip angle that sets the somersault rate
(Wooten §4.3)."""
from __future__ import annotations

from .balance import Balance, standing_hip_height
from .behaviour import ControlContext
from .leap import ANKLE_GAIN_VERTICAL, THRUST_DAMPING, VERTICAL_TIMING, LeapThrust
from .sequencer import Step

LEAN_TRIGGER = 1.0         # share of a backward COM offset that triggers the thrust
SETTINGS = ("crouch_height", "crouch_pitch", "com_offset", "liftoff_hip", "arm_swing")


def takeoff_steps(ctx: ControlContext, cfg: dict) -> list[Step]:
    """Crouch (leaning by ``com_offset``), then thrust until the feet leave the ground. Leaning
    (back, ``com_offset`` < 0, or forward, > 0), the thrust starts once the COM, moving, has left
    the middle of the feet by that much (as the broad jump leans forward, §4.2)."""
    stand = standing_hip_height(ctx.character)

    def crouch(t):
        return Balance(Balance.schema.validate(dict(
            pelvis_height=cfg["crouch_height"], torso_pitch=cfg["crouch_pitch"], com_offset_x=cfg["com_offset"],
            move_start=0.2, move_time=0.8, hold_time=0.0, return_to_stand=0)), ctx)

    def crouched(b, t):
        lean = cfg["com_offset"]
        if lean < 0 and b.com_ahead_of_support() < LEAN_TRIGGER * lean:
            return True
        if lean > 0 and b.com_ahead_of_support() > LEAN_TRIGGER * lean:
            return True
        return b.posture_reached(t - 0.15)

    def thrust(t):
        return LeapThrust({}, ctx, cfg["crouch_height"], VERTICAL_TIMING, ANKLE_GAIN_VERTICAL,
                          cfg["liftoff_hip"], cfg["arm_swing"], stand_height=stand,
                          damping=cfg.get("damping", THRUST_DAMPING), lean=cfg.get("lean", 0.0))

    return [Step("crouch", crouch, crouched), Step("thrust", thrust, lambda b, t: b.lifted_off())]
