"""The landing skill (Wooten ch. 6): land from a fall (a start height / velocity), absorb and
stand up balanced."""
from __future__ import annotations

from ...control.behaviour import register
from ...control.leap import Landing, balance_after_landing, leap_assess
from ...control.sequencer import Sequence, Step
from ...schema import Parameter, Schema
from ...tuned import require_calibrated


@register
class Land(Sequence):
    """Composite: land from a fall or a flight, absorb, then balance and stand up."""

    name = "land"
    summary = "Land from a fall (use a start height / velocity), absorb and stand up balanced (Wooten ch. 6)."
    default_duration = 3.0
    schema = Schema(*Landing.schema.parameters,
                    Parameter("landing_table", "bool", 1.0, 0.0, 1.0,
                              "1: the feet are placed by the character's landing table plus foot_delta (a character "
                              "needs its table); 0: by foot_delta alone (python -m sim_core calibrate land's trials)"))

    def check_feasible(self) -> None:
        if self.params["landing_table"]:
            require_calibrated("landing", self.ctx.character.name, self.name)

    def steps(self) -> list[Step]:
        return [Step("land", lambda t: Landing(self.params, self.ctx), lambda b, t: b.finished),
                Step("balance", lambda t: balance_after_landing(self.ctx, self.previous))]

    @classmethod
    def assess(cls, trajectory):
        return leap_assess(trajectory)
