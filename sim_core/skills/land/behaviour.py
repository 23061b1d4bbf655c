"""The landing skill (Wooten ch. 6): land from a fall (a start height / velocity), absorb and
stand up balanced."""
from __future__ import annotations

import math

from ...control.behaviour import register
from ...control.leap import Landing, balance_after_landing, landing_speeds, leap_assess
from ...control.measure import yaw_of
from ...control.sequencer import Sequence, Step
from ...errors import ParameterError
from ...schema import Parameter, Schema
from ...tuned import load, require_calibrated


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
        """A run on the character's landing table starts at a horizontal speed its rows serve."""
        if not self.params["landing_table"]:
            return
        name = self.ctx.character.name
        require_calibrated("landing", name, self.name)
        low, high = landing_speeds(load("landing", name))
        model, d, pelvis = self.ctx.model, self.ctx.data, self.ctx.actor.body_id("PELVIS")
        yaw = yaw_of(d.xmat[pelvis])
        free = model.jnt_dofadr[model.body_jntadr[pelvis]]         # the root's free joint: world linear velocity first
        speed = math.cos(yaw) * float(d.qvel[free]) + math.sin(yaw) * float(d.qvel[free + 1])
        if not low <= speed <= high:
            raise ParameterError(f"start velocity {speed:+.2f} m/s (forward) is out of the {name}'s landing range: "
                                 f"its landing table serves [{low:+.2f}, {high:+.2f}] m/s (python -m sim_core "
                                 f"calibrate land)")

    def steps(self) -> list[Step]:
        return [Step("land", lambda t: Landing(self.params, self.ctx), lambda b, t: b.finished),
                Step("balance", lambda t: balance_after_landing(self.ctx, self.previous))]

    @classmethod
    def assess(cls, trajectory):
        return leap_assess(trajectory)
