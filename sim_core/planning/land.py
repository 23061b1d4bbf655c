"""Planning a landing above the loop: the foot placement of one ``land`` request, chosen by
simulating it before the run (issue 29: any request in the offered range).

The landing table (control.leap.foot_delta_row) places the feet for the horizontal and touchdown
speeds; between its rows and drops the balanced window (a few centimetres wide: where the feet land
against the COM's speed at touchdown) can lie beside the interpolated value. So before the run, the
request is simulated as asked (the table's placement plus the request's ``foot_delta``); if it does
not end balanced, the same request with ``foot_delta`` one step more and one step less, then two
steps, ... (the step: landing_any.json's ``plan_step_share`` of calibrate land's delta step for
this body, the man's 2 cm x L; at 2-3 m/s the balanced windows are 1-4 cm wide and not always
whole - measured: the woman from 0.515 m at +2.11 m/s balanced at -0.01 and +0.01..+0.03 m but fell
at 0, from 0.27 m at +2.83 m/s only at -0.005 and +0.005 m of -0.16..+0.16 m - so the plan steps
finer than the calibration's grid), nearest the table's first, at most ``plan_trials`` simulations
in all (the skill's parameter). The first balanced one is the plan, and the run is the request with
that ``foot_delta`` (the same simulation as the trial, so it ends as the trial did; its trajectory
logs the chosen value, so replay is exact). If none within the bound ends balanced, the plan says
so with every trial's outcome, and the run is the request as asked.

The trials run through the search service (sim_core.tuning, its ``scan``: the points in order, two
at a time, stopping at the first accepted, so the plan does not depend on the executor). Nothing
is stored: a plan costs a few simulations of about a second.
"""
from __future__ import annotations

import dataclasses
from typing import Callable

from ..control.leap import LANDING_CONSTANTS
from ..simulate import RunRequest, run
from ..skills.land.calibrate_grid import grid
from ..tuned.constants import read_constants
from ..tuning import Space, minimize

CONSTANTS = read_constants("landing", LANDING_CONSTANTS)

TRIAL_FIGURES = ("landing_skid", "foot_slide_after_landing", "final_com_speed")


class LandingTrial:
    """The objective: the request with ``foot_delta`` set, simulated; score 0 if it ends balanced,
    else 1; extra: its outcome and the figures that judge it (picklable: a process pool runs it)."""

    def __init__(self, request: RunRequest):
        self.request = request

    def __call__(self, settings: dict) -> tuple[float, dict]:
        trajectory = run(with_foot_delta(self.request, settings["foot_delta"]))
        metrics = trajectory.meta["metrics"]
        extra = {"outcome": trajectory.meta["outcome"],
                 **{name: float(metrics[name]) for name in TRIAL_FIGURES if name in metrics}}
        return (0.0 if extra["outcome"] == "success" else 1.0), extra


def with_foot_delta(request: RunRequest, foot_delta: float) -> RunRequest:
    return dataclasses.replace(request, params={**request.params, "foot_delta": foot_delta})


def foot_step(character) -> float:
    """The step (m) a plan moves ``character``'s (a spec) feet by: landing_any.json's ``plan_step_share``
    of calibrate land's delta step for the body (the man's 2 cm x L)."""
    return round(CONSTANTS.plan_step_share * grid(character).delta_step, 4)


def candidates(asked: float, step: float, trials: int, low: float, high: float) -> list[float]:
    """``asked``, then asked +- 1, 2, ... steps (more first), inside [low, high], ``trials`` in all."""
    out, k = [asked], 1
    while len(out) < trials and (asked + k * step <= high or asked - k * step >= low):
        out += [round(v, 4) for v in (asked + k * step, asked - k * step) if low <= v <= high]
        k += 1
    return out[:trials]


def plan_landing(request: RunRequest, progress: Callable | None = None, cancelled: Callable | None = None,
                 executor=None) -> tuple[RunRequest, dict | None]:
    """(the request to run, the plan) for a ``land`` request on its landing table with
    ``plan_trials`` >= 1; else (the request, None). The plan: ``found``, ``foot_delta`` (the chosen
    one, or the one asked if none was found), ``offset`` (m from the one asked), ``step``,
    ``trials`` and ``tried`` (every trial's foot_delta, outcome and figures, in order)."""
    character, cls, params, _ = request.validated()
    if request.behaviour != "land" or not params["landing_table"] or params["plan_trials"] < 1:
        return request, None
    knob = cls.schema.by_name["foot_delta"]
    step = foot_step(character)
    asked = float(params["foot_delta"])
    points = candidates(asked, step, int(params["plan_trials"]), knob.minimum, knob.maximum)
    space = Space({"foot_delta": (knob.minimum, knob.maximum)}, decimals=4)
    report = None if progress is None else (lambda done, budget, best: progress(done, budget, best.extra))
    result = minimize(LandingTrial(request), space, method="scan", budget=len(points), start={"foot_delta": asked},
                      population=2, progress=report, cancelled=cancelled, executor=executor,
                      stop=lambda evaluation: evaluation.score == 0.0,
                      options={"points": [{"foot_delta": v} for v in points[1:]]})
    tried = [{"foot_delta": e.settings["foot_delta"], **e.extra} for e in result.evaluations]
    found = result.ended == "stop"
    chosen = tried[-1]["foot_delta"] if found else asked
    plan = {"found": found, "foot_delta": chosen, "offset": round(chosen - asked, 4), "step": step,
            "trials": len(tried), "bound": len(points), "tried": tried}
    return (with_foot_delta(request, chosen) if found else request), plan


def describe(plan: dict) -> str:
    """One line for the person who asked: what the plan found, or that nothing within the bound
    ended balanced, with each trial's outcome."""
    if plan["found"]:
        if plan["trials"] == 1:
            return "landing plan: the table's foot placement ends balanced (1 trial)"
        return (f"landing plan: foot_delta {plan['foot_delta']:+.4f} m ({plan['offset'] * 100:+.2f} cm from the "
                f"table's placement) ends balanced ({plan['trials']} trials, steps of {plan['step'] * 100:.2f} cm)")
    tried = ", ".join(f"{t['foot_delta']:+.4f} m {t['outcome']} (skid {t.get('landing_skid', float('nan')):.3f} m)"
                      for t in plan["tried"])
    return (f"landing plan: NOT FOUND - none of {plan['trials']} foot placements within "
            f"{(plan['bound'] - 1) // 2} steps of {plan['step'] * 100:.2f} cm of the table's ended balanced: {tried}; "
            f"the run is the request as asked")
