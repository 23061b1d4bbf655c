"""Eq. 11's four gains at a speed: from the searched steering schedule (rows of gains at speeds,
found by ``python -m sim_core calibrate bicycle``; linear between rows, the end rows beyond them),
or, where the table has no schedule, from the gains at ``reference_speed`` scheduled by physics:
steering leans the bicycle in proportion to v^2 (roll gains x (v_ref / v)^2) and a lean turns it
at g tan(lean) / v (heading gains x v_ref / v)."""
from __future__ import annotations

import numpy as np

GAINS = ("roll_gain", "roll_rate_gain", "yaw_gain", "yaw_rate_gain")
MIN_SCHEDULED_SPEED = 1.0      # definition: m/s, below it the gains stay the 1 m/s ones


def steering_gains(speed: float, constants: dict, schedule: list[dict] | None) -> tuple[float, float, float, float]:
    """(k_roll, k_roll_rate, k_yaw, k_yaw_rate) of eq. 11 at ``speed``."""
    if schedule:
        speeds = [row["reference_speed"] for row in schedule]
        return tuple(float(np.interp(speed, speeds, [row[g] for row in schedule])) for g in GAINS)
    ratio = constants["reference_speed"] / max(speed, MIN_SCHEDULED_SPEED)
    return (constants["roll_gain"] * ratio ** 2, constants["roll_rate_gain"] * ratio ** 2,
            constants["yaw_gain"] * ratio, constants["yaw_rate_gain"] * ratio)
