"""Planning a dive above the loop: the take-off of a dive from a platform height its calibrated
take-off was not measured at, or of a dive with no calibrated row (issue 29: any request in the
offered range, not only the calibrated points).

Each dive's take-off row is calibrated from 10 m (``calibrate dive``), some also from lower platforms
(``calibrate dive --platform 7.5``: rows with ``"platform"``); a dive asked from a platform it has a reached row
of is run as that row with no plan (calibrated_here). From another platform the flight is shorter or longer and
the nearest platform's take-off (dive_row) under- or over-rotates (measured: the man's 205B row from 10 m makes
2.09 of its 2½ somersaults from 7.5 m, 1.66 from 5 m); a custom dive without a row of its own runs the most alike
row's take-off, made for other rotations. The take-off's lift-off hip angle moves its angular momentum
smoothly on the branch a calibrated row is on (the man's 205B row: -0.5 -> 70, 0.7 -> 123 kg m^2/s),
so the plan moves that one setting: the request is run as asked first (its feasibility checks
refuse what the flight cannot hold, before anything else); if it does not enter as a success, the
lift-off hip moves by the rotation missed (``vertical_rotation``) over a slope (``plan_slope`` turns per rad, dives_any.json,
then a secant through the last two dives that entered the water; at most ``plan_step`` rad a trial,
inside the calibration's range for the group), until a dive enters as a success or ``plan_trials``
dives have run. The run is then the request with those take-off settings as set (``low_level``), so its
replay log holds them and replay is exact. If none succeeds, the request is refused naming the
nearest dive. Nothing is stored: a plan costs a few simulated dives of about a second each.
"""
from __future__ import annotations

import dataclasses
from typing import Callable

from ..errors import ParameterError
from ..simulate import RunRequest, run
from ..skills.dive.behaviour import (CONSTANTS, FORWARD_ROTATING, LEAP_SETTINGS, calibrated_here, dive_name,
                                     dive_settings, group_name)
from ..skills.dive.calibrate import SPACE

KNOB = "liftoff_hip"


def plan_dive(request: RunRequest, progress: Callable | None = None,
              cancelled: Callable | None = None) -> tuple[RunRequest, dict | None]:
    """(the request to run, the plan) for a ``dive`` request with ``plan_trials`` >= 1, not ``low_level``
    and not a calibrated dive from a platform it was calibrated from (calibrated_here); else (the
    request, None). The plan: ``found``, ``settings`` (the take-off run),
    ``trials`` and ``tried`` (each trial's lift-off hip, outcome, somersaults and entry angle, in order).
    Raises ParameterError when the request is refused or no trial succeeds."""
    character, _, params, _ = request.validated()
    if params["low_level"] or params["plan_trials"] < 1 or calibrated_here(character.name, params):
        return request, None
    trajectory = run(request)                  # as asked: the behaviour's checks refuse here, before any plan
    settings = dive_settings(character.name, params)
    tried = [_trial(float(settings[KNOB]), trajectory)]
    if tried[0]["outcome"] == "success":     # the calibrated take-off serves this platform too
        return request, {"skill": "dive", "found": True, "settings": None, "trials": 1, "tried": tried}
    low, high = SPACE[KNOB][group_name(params)]
    sign = -1.0 if group_name(params) in FORWARD_ROTATING else 1.0   # more somersault: a forward one by flexing (-)
    wanted = params["somersaults"]
    found = None
    while len(tried) < params["plan_trials"] and found is None:
        if cancelled is not None and cancelled():
            raise ParameterError("the dive's plan was cancelled")
        x = _next(tried, wanted, sign, low, high)
        if x is None:
            break
        asked = {**settings, KNOB: x}
        trial = _trial(x, run(_with_settings(request, asked)))
        tried.append(trial)
        if progress is not None:
            progress(len(tried), int(params["plan_trials"]), trial)
        if trial["outcome"] == "success":
            found = asked
    plan = {"skill": "dive", "found": found is not None, "settings": found, "trials": len(tried), "tried": tried}
    if found is None:
        near = min(tried, key=lambda t: abs(t["somersaults"] - wanted) + t["entry_deg"] / 360.0 + 10.0 * t["hit_platform"])
        raise ParameterError(
            f"{dive_name(params)} from {params['platform_height']:g} m: no take-off found by the plan in {len(tried)} "
            f"simulated dives (the nearest: lift-off hip {near[KNOB]:+.3f} rad, {near['outcome']}, "
            f"{near['somersaults']:.2f} somersaults, {near['entry_deg']:.0f} deg from vertical; allowed: the reached "
            f"dives from 10 m, python -m sim_core report dive --repertoire, those calibrated from this platform, "
            f"or more plan_trials)")
    return _with_settings(request, found), plan


def _with_settings(request: RunRequest, settings: dict) -> RunRequest:
    """The request with the take-off ``settings`` run as set."""
    return dataclasses.replace(request, params={**request.params, "low_level": 1,
                                                **{k: settings[k] for k in LEAP_SETTINGS}})


def _trial(x: float, trajectory) -> dict:
    m = trajectory.meta["metrics"]
    return {KNOB: round(x, 4), "outcome": trajectory.meta["outcome"], "somersaults": float(m.get("somersaults", 0.0)),
            "entry_deg": float(m.get("entry_angle_from_vertical_deg") or 0.0), "hit_platform": bool(m.get("hit_platform")),
            "usable": bool(m.get("entered_water")) and not m.get("hit_platform")}


def _next(tried: list[dict], wanted: float, sign: float, low: float, high: float) -> float | None:
    """The next lift-off hip. With dives on both sides of the wanted somersaults: between the nearest two
    (the secant's point, or the middle where that lies in the outer tenths). Else on from the usable dive
    furthest the way the misses ask (below); None where that is the end of the range, run already. Before any
    dive entered the water: ``plan_step`` toward more rotation."""
    usable = sorted((t for t in tried if t["usable"]), key=lambda t: t[KNOB])
    if not usable:
        return _clip(tried[-1][KNOB] + sign * CONSTANTS.plan_step, low, high)
    vertical = vertical_rotation(usable, wanted)
    miss = {id(t): t["somersaults"] - vertical for t in usable}
    pairs = [(a, b) for a, b in zip(usable, usable[1:]) if miss[id(a)] * miss[id(b)] < 0]
    if pairs:
        a, b = min(pairs, key=lambda ab: abs(miss[id(ab[0])]) + abs(miss[id(ab[1])]))
        share = miss[id(a)] / (miss[id(a)] - miss[id(b)])
        share = share if 0.1 <= share <= 0.9 else 0.5        # definition: the outer tenths bisect
        return _clip(a[KNOB] + share * (b[KNOB] - a[KNOB]), low, high)
    # every usable dive on one side: on from the one furthest the way that turns it less (or more), by what it
    # missed over the slope (the secant to its neighbour where that has the slope's sign and at least a tenth of
    # it, else ``plan_slope``), a whole ``plan_step`` where the secant is flat (the take-off's momentum saturates)
    way = -sign if miss[id(usable[0])] > 0 else sign
    front = usable[0] if way < 0 else usable[-1]
    step = CONSTANTS.plan_step
    if len(usable) >= 2 and abs((usable[1] if way < 0 else usable[-2])[KNOB] - front[KNOB]) > 1e-6:
        near = usable[1] if way < 0 else usable[-2]
        secant = (front["somersaults"] - near["somersaults"]) / (front[KNOB] - near[KNOB])
        if secant * sign >= 0.1 * CONSTANTS.plan_slope:       # definition: a tenth of the slope, the right way
            step = min(step, abs(miss[id(front)] / secant))
    else:
        step = min(step, abs(miss[id(front)]) / CONSTANTS.plan_slope)
    x = _clip(front[KNOB] + way * step, low, high)
    while any(abs(x - t[KNOB]) < 1e-3 for t in tried) and abs(x - front[KNOB]) > 1e-3:   # run already (one that
        x = _clip((x + front[KNOB]) / 2.0, low, high)                                     # did not enter): halfway back
    return None if any(abs(x - t[KNOB]) < 1e-3 for t in tried) else x      # at the range's end: nothing new


def vertical_rotation(usable: list[dict], wanted: float) -> float:
    """The somersaults (as measured from the take-off) of a dive that enters vertically, read off the dives
    run: each entered ``entry_deg`` from vertical, so a vertical one turns that much more or less (the measure
    starts from the take-off's lean, so it is not the dive's name: the man's 205B from 10 m enters 2 deg from
    vertical at 2.43). The one of each dive's two values that the others' agree with best (one dive: the one
    nearer ``wanted``), of the dives that entered within 60 deg of vertical."""
    pairs = [(t["somersaults"] - t["entry_deg"] / 360.0, t["somersaults"] + t["entry_deg"] / 360.0) for t in usable
             if t["entry_deg"] < 60.0]     # definition: further off, an entry's side is a guess; none: ``wanted``
    if not pairs:
        return wanted
    if len(pairs) == 1:
        return min(pairs[0], key=lambda v: abs(v - wanted))
    values = [v for pair in pairs for v in pair]
    return min(values, key=lambda v: sum(min(abs(v - w) for w in pair) for pair in pairs))


def _clip(x: float, low: float, high: float) -> float:
    return round(min(max(x, low), high), 4)


def describe(plan: dict) -> str:
    """One line for the person who asked: what the dive's plan found."""
    if plan["trials"] == 1:
        return "dive plan: the calibrated take-off enters as a success (1 dive)"
    t = plan["tried"][-1]
    return (f"dive plan: lift-off hip {plan['settings'][KNOB]:+.3f} rad ({plan['trials']} dives; the last "
            f"{t['somersaults']:.2f} somersaults, {t['entry_deg']:.0f} deg from vertical)")
