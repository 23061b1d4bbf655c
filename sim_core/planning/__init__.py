"""Planning: whatever runs whole simulations to choose a behaviour's settings sits here, above
sim_core/simulate.py (it calls ``simulate.run`` for its trials); a behaviour never runs a nested
simulation, it only looks up what was planned (a jump) or runs the setting chosen for it (a
landing's foot_delta, planning.land). See docs/planning.md."""
from __future__ import annotations

from .jump import plan_and_store, plan_jump, planned
from .land import plan_landing

PLANNED_BEHAVIOURS = ("jump_to_target",)     # behaviours whose runs need a plan first


PLANNED_REQUESTS = ("land", "dive")   # behaviours whose request is planned by trial runs just before it runs


def planned_request(request, progress=None, cancelled=None, executor=None):
    """(the request a run executes, its plan or None): a ``land`` request with the foot placement its
    plan chose by trial runs (planning.land); a ``dive`` with the take-off its plan chose for the
    platform height (planning.dive); any other request as it is. The one rule the CLI's simulate and
    the add-on's bakes share."""
    if request.behaviour == "land":
        return plan_landing(request, progress=progress, cancelled=cancelled, executor=executor)
    if request.behaviour == "dive":
        from .dive import plan_dive          # only then: it imports the dive's calibration
        return plan_dive(request, progress=progress, cancelled=cancelled)
    return request, None


def describe(plan: dict) -> str:
    """One line about a plan of planned_request's for the person who asked."""
    if plan.get("skill") == "dive":
        from .dive import describe as describe_dive
        return describe_dive(plan)
    from .land import describe as describe_landing
    return describe_landing(plan)


def plan_before_run(request, budget: int, progress=None, cancelled=None, executor=None) -> dict | None:
    """For a run ``request`` (simulate.RunRequest) of a planned behaviour with no stored plan: plan
    it now, above the loop, and store the plan (None if it needs none or has one; a budget of 0
    plans nothing, and the run refuses the request). Returns the new plan."""
    if request.behaviour not in PLANNED_BEHAVIOURS or budget < 1:
        return None
    character, _, params, _ = request.validated()
    if planned(character.name, params, request.strength) is not None:
        return None
    return plan_and_store(character, params, request.strength, budget, progress=progress, cancelled=cancelled,
                          executor=executor)


__all__ = ["PLANNED_BEHAVIOURS", "PLANNED_REQUESTS", "describe", "plan_and_store", "plan_before_run", "plan_jump", "plan_landing", "planned", "planned_request"]
