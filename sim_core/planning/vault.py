"""A bounded search for the vault's landing placement at one run-up speed, by simulating whole vaults
(issue 31: could a plan per run-up speed, the way the jumps map a request to settings, give a range?).

The vault's landing stands only in a millimetre-wide window of ``foot_delta`` (docs/vault.md "The
landing's window"), and where that window lies moves with the run-up speed. ``plan_foot_delta``
simulates the vault with a start ``foot_delta``; if it falls, the fall's side says which way to move the
feet (the COM past the feet's middle at the fall: the feet too far back, more foot_delta; the COM
behind it: less). It steps that way (vault_any.json's ``plan_step``, doubled each trial) until the fall
turns to the other side, then bisects that bracket down to ``plan_resolution``, at most
``plan_trials`` simulations, stopping at the first success (the vault's own assessment: one
somersault, feet first, at most 11.6 body weights, standing balanced, the bow without a step).

Measured with it (``python -m sim_core report vault --plan SPEEDS``, docs/vault.md "A landing plan per
run-up speed"): the fall's side flips from forward to back inside 0.1-0.2 mm of foot_delta with no
standing placement between at most speeds, so it is not in the vault's run path: the offered range
(handled_speed) stays the one speed, and this is the measuring tool for when the upstream phases are a
smooth family.
"""
from __future__ import annotations

from typing import Callable

import numpy as np

from ..skills.vault.behaviour import CONSTANTS
from .trials import Trials


def fall_side(trajectory) -> int:
    """0 for a success; else +1 when the COM was ahead of the feet's middle at the fall (or at the end,
    for another failure), -1 when behind it."""
    if trajectory.meta["outcome"] == "success":
        return 0
    a, fell = trajectory.arrays, trajectory.meta["metrics"].get("fall_time")
    k = len(a["time"]) - 1 if fell is None else min(int(np.searchsorted(a["time"], fell)), len(a["time"]) - 1)
    return 1 if a["com"][k, 0] > a["support_points"][k, :, 0].mean() else -1


def plan_foot_delta(simulate: Callable, start: float, low: float, high: float, progress: Callable | None = None,
                    cancelled: Callable | None = None) -> dict:
    """The search above from ``start`` within [low, high]: ``simulate(foot_delta)`` runs one whole vault
    and returns its trajectory. Returns ``found``, ``foot_delta`` (the standing one, else None),
    ``bracket`` (the last (forward, back) pair, or None), ``trials``, ``bound`` and ``tried`` (each
    trial's foot_delta, outcome, fall side and fall time, in order)."""
    def trial(settings):
        trajectory = simulate(settings["foot_delta"])
        side = fall_side(trajectory)
        return (0.0 if side == 0 else 1.0), {"foot_delta": settings["foot_delta"], "outcome": trajectory.meta["outcome"],
                                             "side": side, "fall_time": trajectory.meta["metrics"].get("fall_time")}

    bound = int(CONSTANTS.plan_trials)
    trials = Trials(trial, bound, progress, cancelled)
    first = trials.run({"foot_delta": round(start, 6)})
    found = first if first["side"] == 0 else None
    way, inner, outer, step = first["side"], start, None, CONSTANTS.plan_step
    while found is None and outer is None and len(trials.tried) < bound:
        x = round(float(np.clip(inner + way * step, low, high)), 6)
        if x == inner:
            break
        m = trials.run({"foot_delta": x})
        if m["side"] == 0:
            found = m
        elif m["side"] == way:
            inner, step = x, 2 * step
        else:
            outer = x
    while found is None and outer is not None and abs(outer - inner) > CONSTANTS.plan_resolution \
            and len(trials.tried) < bound:
        x = round((inner + outer) / 2, 6)
        m = trials.run({"foot_delta": x})
        if m["side"] == 0:
            found = m
        elif m["side"] == way:
            inner = x
        else:
            outer = x
    tried = [e[3] for e in trials.tried]
    bracket = None if outer is None or found is not None else tuple(sorted((inner, outer)))
    return {"found": found is not None, "foot_delta": found["foot_delta"] if found else None, "bracket": bracket,
            "trials": len(tried), "bound": bound, "tried": tried}
