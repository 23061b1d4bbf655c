"""The landing skill (Wooten ch. 6): land from a fall (a start height / velocity), absorb and
stand up balanced."""
from __future__ import annotations

import math

from ...control.behaviour import register
from ...ballistics import GRAVITY
from ...control.leap import (Landing, balance_after_landing, landing_drops, landing_side_speed, landing_speeds,
                             leap_assess)
from ...control.measure import SupportGeometry, yaw_of
from ...control.sequencer import Sequence, Step
from ...errors import ParameterError
from ...schema import Parameter, Schema
from ...tuned import load, require_calibrated

DROP_TOLERANCE = 0.005      # definition: m, a drop drawn at a measured limit, read back off the start state (the feet's sites)
SPEED_TOLERANCE = 1e-6      # definition: m/s, a start with no sideways speed, read back off the rotated root


@register
class Land(Sequence):
    """Composite: land from a fall or a flight, absorb, then balance and stand up."""

    name = "land"
    summary = "Land from a fall (use a start height / velocity), absorb and stand up balanced (Wooten ch. 6)."
    default_duration = 3.0
    schema = Schema(*Landing.schema.parameters,
                    Parameter("landing_table", "bool", 1.0, 0.0, 1.0,
                              "1: the feet are placed by the character's landing table plus foot_delta (a character "
                              "needs its table); 0: by foot_delta alone (python -m sim_core calibrate land's trials)"),
                    Parameter("plan_trials", "count", 25, 0, 61,
                              "simulate (python -m sim_core simulate) plans the landing above the loop: the request as "
                              "asked, and if it does not end balanced foot_delta one step more and less, two steps, ... "
                              "(0.5 cm x the body's leg length / the man's: a quarter of the landing calibration's step, "
                              "landing_any.json), at most this many simulations in all; the first balanced one is run. "
                              "0: no plan"))

    def check_feasible(self) -> None:
        """A run on the character's landing table starts at a horizontal speed its rows serve, from a
        drop (its vertical touchdown speed's v^2 / 2g, from the feet's height and the start's vertical
        speed) it offers at that speed, and no faster sideways than it offers (landing_drops,
        landing_side_speed)."""
        if not self.params["landing_table"]:
            return
        name = self.ctx.character.name
        require_calibrated("landing", name, self.name)
        table = load("landing", name)
        low, high = landing_speeds(table)
        model, d, pelvis = self.ctx.model, self.ctx.data, self.ctx.actor.body_id("PELVIS")
        yaw = yaw_of(d.xmat[pelvis])
        free = model.jnt_dofadr[model.body_jntadr[pelvis]]         # the root's free joint: world linear velocity first
        vx, vy, vz = (float(v) for v in d.qvel[free:free + 3])
        speed = math.cos(yaw) * vx + math.sin(yaw) * vy
        side = -math.sin(yaw) * vx + math.cos(yaw) * vy
        source = "python -m sim_core calibrate land"
        if not low <= speed <= high:
            raise ParameterError(f"start velocity {speed:+.2f} m/s (forward) is out of the {name}'s landing range: "
                                 f"its landing table serves [{low:+.2f}, {high:+.2f}] m/s ({source})")
        feet = max(float(SupportGeometry(model, prefix=self.ctx.actor.prefix).heights(d).min()), 0.0)
        drop = (vz * vz + 2.0 * GRAVITY * feet) / (2.0 * GRAVITY)
        side_limit = landing_side_speed(table, drop - DROP_TOLERANCE)
        if abs(side) > side_limit + SPEED_TOLERANCE:
            raise ParameterError(f"start velocity {side:+.2f} m/s (sideways) is out of the {name}'s landing range: "
                                 f"from a drop of {drop:.2f} m it lands sideways speeds within [{-side_limit:+.2f}, "
                                 f"{side_limit:+.2f}] m/s ({source} --drop-limits)")
        lowest, highest = landing_drops(table, speed)
        if not lowest - DROP_TOLERANCE <= drop <= highest + DROP_TOLERANCE:
            raise ParameterError(f"a drop of {drop:.2f} m (the feet {feet:.2f} m up, {vz:+.2f} m/s vertically) at "
                                 f"{speed:+.2f} m/s is out of the {name}'s landing range: at that speed it lands drops "
                                 f"of [{lowest:.2f}, {highest:.2f}] m ({source} --drop-limits)")

    def steps(self) -> list[Step]:
        return [Step("land", lambda t: Landing(self.params, self.ctx), lambda b, t: b.finished),
                Step("balance", lambda t: balance_after_landing(self.ctx, self.previous))]

    @classmethod
    def assess(cls, trajectory):
        return leap_assess(trajectory)
