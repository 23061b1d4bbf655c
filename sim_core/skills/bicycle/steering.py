"""Eq. 11's four gains at a speed, from the hand-set gains at ``reference_speed``: steering leans
the bicycle in proportion to v^2, so the roll gains go as (v_ref / v)^2; the heading gains stay
the reference's below the reference speed and go down with the roll gains above it (with them
unscaled the bicycle weaves and falls within a second at 6 and 8 m/s; docs/bicycle.md)."""
from __future__ import annotations

MIN_SCHEDULED_SPEED = 1.0      # definition: m/s, below it the gains stay the 1 m/s ones


def steering_gains(speed: float, constants: dict) -> tuple[float, float, float, float]:
    """(k_roll, k_roll_rate, k_yaw, k_yaw_rate) of eq. 11 at ``speed``."""
    scale = (constants["reference_speed"] / max(speed, MIN_SCHEDULED_SPEED)) ** 2
    heading = min(scale, 1.0)
    return (constants["roll_gain"] * scale, constants["roll_rate_gain"] * scale,
            constants["yaw_gain"] * heading, constants["yaw_rate_gain"] * heading)
