"""Planning a jump with the commanded take-off (issue 29), above the loop: for a request in the
character's commanded region (skills/jump_to_target/commanded.py) outside its measured jumps' region.

The commanded take-off flies what it commands - the feet's landing point forward and the air time -
and nearby targets are nearby commands (docs/jump_to_target.md, "A commanded take-off"), so a plan is
a few simulated jumps, not a search over the leap's settings:

1. the aim: the table's settings with the crouch interpolated at the air time (``crouch_by_air_time``)
   (on a box's top or below one at the flat-ground air time of the same vertical lift-off speed,
   ballistics.flat_air_time) and the commanded landing point (``flight_target_x``) at the target; after
   each jump the commanded
   point is moved by a secant on where it landed (the previous two jumps' landing per commanded metre;
   below ``aim_slope_floor`` the table's ``aim_slope`` instead) and the crouch's air time by a secant on
   the air time flown (the first step as flown), until a jump lands within ``aim_tolerance`` and
   ``aim_time_tolerance`` (or within TARGETS.md's tolerances and balanced), at most ``aim_trials`` jumps, or until
   the next aim is a jump already flown (held at a bound: ``aim_range``'s end, the crouch pairs' end; the trials are
   deterministic, planning/trials.py seen, so its trials go to the landing);
2. the landing from the arriving state: if the nearest jump that landed on the target fell, the same
   jump with its feet placed a landing plan step (planning.land.foot_step) more and less, two, ...
   (planning.land.candidates), at most ``landing_trials`` placements in all; where every placement fell, the same
   jump with its ``landing_foot_lead_time`` moved by each of the table's ``landing_leads`` in turn (the feet led
   later: the woman's turned long row fell on the target at its shallow crouches); the first that ends balanced on the
   target is the plan. Where none did, the balanced trial nearest the target is flown again with its flight target
   moved by its miss, at most ``landing_aims`` jumps (reaim).

A long air time on flat ground, in the table's ``long_region`` beyond its ``region``, or onto or down from a box
where the flat equivalent lies there (``long_onto_region``, ``long_down_region``): the same aim with the table read
by commanded.long_body (the leap's vertical thrust and its own crouch pairs); in its ``near_long_region`` beyond both,
by commanded.near_long_body (the same with the near row's own lean push and crouch pairs). Down from a box with a
lift-off lower than the table's region flies (``low_down_regions``): the same aim with commanded.low_down_body (its
crouch pairs with a shallower crouch's); lower still, within a forward speed (``push_down_regions``): with
commanded.push_down_body (its own settings and crouch pairs).

A target beyond the table's straight region's target_y, in its ``turned_region`` (plan_turned): the
jump turns first (one hop, the leap's ``turn_angle``) and flies the commanded take-off forward; the aim
moves the commanded distance along the target's bearing by a secant on the landing's distance along it,
at most ``turn_aim_trials`` jumps; then the landing as 2. The hop is the measured one whose jump's line
passes nearest the target (the table's ``turn_lines``, turn_for_point) - a hop already flown by its line moved to where
its jump landed, one never flown by its measured line moved by the mean of those errors - kept while its jump lands
within ``aim_tolerance`` to the side, its aim by a secant on its own jumps (steer_by_lines); a table without them
(the man's) takes the measured hop whose heading is nearest the one wanted (``turn_headings``, turn_for_heading: the
heading wanted moved by the landing's bearing missed over the table's ``turn_slope``, from ``turn_gain`` x the bearing). A target straight to the side, in its
``sideways_region``, the same with the quarter turn (the leap's ``turn_first``, two hops) and its lines
(``quarter_lines``; the turn chosen anew after each jump, the target moved against the landings' misses to the side so
far); in its ``sideways_<row>_region``, the quarter turn and then the row ``turned_<row>`` flies (way_body), steered as
the hop's lines are (steer_by_lines over ``quarter_lines``). A target to the side at a long air time, in its ``turned_long_region``: the same hop and
aim with the table read by turned_long_body (the long row flown after the hop, with the table's
``turned_long_settings`` over it); in its ``turned_near_long_region``, the near long row after the hop
(near_long_body); in its ``turned_mid_long_region`` / ``turned_far_long_region``, the mid / far long row after the hop
(mid_long_body / far_long_body); in its
``turned_deep_long_region`` (and straight ahead ``deep_long_region``), the long row at its deepest crouches after the
hop (deep_long_body); in its ``turned_far_short_region`` / ``turned_near_short_region`` (and straight ahead
``far_short_region`` / ``near_short_region``), the long / near long row at its shallowest crouches (short_body).

At most min(budget, aim_trials + landing_trials - 1 + len(landing_leads) + landing_aims) jumps (turned: turn_aim_trials in place of
aim_trials);
the plan is the best trial (found or
not: of those found, else of all, the lowest cost), as plan_from_model's. The seed-free steps make
the same request give the same plan.
"""
from __future__ import annotations

import math
from typing import Callable

from ..ballistics import flat_air_time
from ..character.spec import load_character
from ..control.leap import LEAP_SETTINGS
from ..errors import ParameterError
from ..skills.jump_to_target.commanded import (TURNED_WAYS, commanded_settings, commanded_way, line_offset,
                                               planner_constants, quarter_lines_of, table, turn_for_heading, turn_for_point,
                                               turned_settings, way_body)
from .land import candidates, foot_step
from .trials import Trials


def secant(values: list[float], results: list[float], floor: float, fallback: float) -> float:
    """The slope of ``results`` over ``values`` between the last two (``fallback`` where there is one
    value, equal values, or a slope below ``floor``)."""
    if len(values) < 2 or values[-1] == values[-2]:
        return fallback
    slope = (results[-1] - results[-2]) / (values[-1] - values[-2])
    return slope if slope > floor else fallback


def plan_commanded(character: str, target, air_time: float, trial, budget: int, judge: Callable,
                   progress: Callable | None = None, cancelled: Callable | None = None,
                   body: dict | None = None, constants=None) -> dict:
    """Plan ``character``'s jump to ``target`` (x, y, z, obstacle) in ``air_time`` s with the commanded
    take-off (see the module). ``trial``: settings -> (cost, measured) (planning.jump.JumpTrial);
    ``judge(measured)`` -> (landed on the target, within TARGETS.md's tolerances and balanced);
    ``body``, ``constants``: the character's commanded table and the planner's constants (default: the
    stored ones, planner_constants; tools/commanded_jumps.py tries others). Returns the planner's
    {"settings", "measured", "trials", "found"}."""
    c, body = constants or planner_constants(character), body or table(character)
    way = commanded_way(character, target, air_time)
    if way in TURNED_WAYS:
        return plan_turned(character, target, air_time, trial, budget, judge, progress, cancelled, body, c, way)
    body = way_body(body, way)
    x = float(target[0])
    bound = min(budget, c.aim_trials + c.landing_trials - 1 + len(c.landing_leads) + c.landing_aims)
    trials = Trials(trial, bound, progress, cancelled)
    tried, run_trial = trials.tried, trials.run

    # the crouch is measured on flat ground: onto or down from a box it is the one of the same lift-off speed up
    aims, landed, air_aims, flown = [x], [], [flat_air_time(float(target[2]), float(air_time))], []
    while True:
        settings = commanded_settings(body, air_aims[-1], aims[-1], float(target[2]))
        if trials.seen(settings):   # the aim held at a bound (aim_range, the crouch pairs' end): the same jump again
            break
        measured = run_trial(settings)
        landed.append(measured["landing"][0])
        flown.append(measured["air_time"])
        miss, late = landed[-1] - x, flown[-1] - air_time
        if (judge(measured)[1] or (abs(miss) <= c.aim_tolerance and abs(late) <= c.aim_time_tolerance)
                or len(aims) >= min(c.aim_trials, bound) or not math.isfinite(miss)):
            break
        slope = secant(aims, landed, c.aim_slope_floor, c.aim_slope)
        aims.append(min(max(aims[-1] - miss / slope, c.aim_range[0]), c.aim_range[1]))
        rate = secant(air_aims, flown, c.aim_slope_floor, 1.0)     # definition: the first step as flown
        air_aims.append(air_aims[-1] - late / rate)
    return landed_plan(character, target, trials, bound, judge, c)


def landed_plan(character: str, target, trials: Trials, bound: int, judge: Callable, c) -> dict:
    """The landing from the arriving state (the module's 2) after the aim's ``trials``, and the plan."""
    tried, run_trial = trials.tried, trials.run
    found = any(judge(e[3])[1] for e in tried)
    on_target = [e for e in tried if judge(e[3])[0]]
    if not found and on_target:
        _, _, base, _ = min(on_target, key=lambda e: (e[0], e[1]))
        knob = LEAP_SETTINGS.by_name["foot_delta"]
        deltas = candidates(base["foot_delta"], foot_step(load_character(character)), c.landing_trials,
                            knob.minimum, knob.maximum)[1:]
        for delta in deltas[:max(bound - len(tried), 0)]:
            if judge(run_trial({**base, "foot_delta": delta}))[1]:
                break
        else:   # every placement fell: the same jump with its feet led by landing_leads (later: shorter leads)
            for lead in c.landing_leads[:max(bound - len(tried), 0)]:
                if judge(run_trial({**base, "landing_foot_lead_time": base["landing_foot_lead_time"] + lead}))[1]:
                    break
    reaim(target, trials, bound, judge, c)
    cost, _, settings, measured = min(tried, key=lambda e: (not judge(e[3])[1], e[0], e[1]))   # found first
    return {"settings": settings, "measured": measured, "trials": len(tried), "found": bool(judge(measured)[1])}


def reaim(target, trials: Trials, bound: int, judge: Callable, c) -> None:
    """Where no trial has landed balanced on the target (the landing's placements and leads spent too): the balanced
    trial nearest the target flown again with its flight target moved by its miss, forward and to the side (a placement
    or lead that stood moved the landing with it: the woman's quarter turn's 7-12 cm), at most ``landing_aims`` jumps,
    while the last one stood and the move is new."""
    x, y = float(target[0]), float(target[1])
    tried = trials.tried
    for _ in range(min(c.landing_aims, max(bound - len(tried), 0))):
        stood = [e for e in tried if e[3]["outcome"] == "success" and all(map(math.isfinite, e[3]["landing"]))]
        if any(judge(e[3])[1] for e in tried) or not stood:
            return
        _, _, base, measured = min(stood, key=lambda e: math.hypot(e[3]["landing"][0] - x, e[3]["landing"][1] - y))
        moved = dict(base)
        for key, miss in (("flight_target_x", x - measured["landing"][0]), ("flight_target_y", y - measured["landing"][1])):
            knob = LEAP_SETTINGS.by_name[key]
            value, was = min(max(base.get(key, knob.default) + miss, knob.minimum), knob.maximum), base.get(key, knob.default)
            if value != was:        # a flight target held at its bound leaves the jump as it was (seen: not flown)
                moved[key] = value
        if trials.seen(moved) or trials.run(moved)["outcome"] != "success":
            return


def plan_turned(character: str, target, air_time: float, trial, budget: int, judge: Callable,
                progress: Callable | None, cancelled: Callable | None, body: dict, c, way: str = "turned") -> dict:
    """plan_commanded for a target to the side (the module's turned plan): turn first, then forward
    (``way`` "sideways": the quarter turn, its map ``quarter_lines``; "turned_long" / "turned_long_short": the hop, then
    the long row, commanded.turned_long_body; "turned_near_long" / "turned_mid_long" / "turned_far_long": the hop, then the near /
    mid / far long row, commanded.near_long_body / mid_long_body / far_long_body; "turned_deep_long": the hop, then the long row at its deepest crouches,
    commanded.deep_long_body)."""
    body = way_body(body, way)
    x, y = float(target[0]), float(target[1])
    distance, bearing = math.hypot(x, y), math.atan2(y, x)
    along, side = (math.cos(bearing), math.sin(bearing)), (-math.sin(bearing), math.cos(bearing))
    bound = min(budget, c.turn_aim_trials + c.landing_trials - 1 + len(c.landing_leads) + c.landing_aims)
    trials = Trials(trial, bound, progress, cancelled)
    aims, reached, headings, bearings, air_aims, flown = [distance], [], [c.turn_gain * bearing], [], [float(air_time)], []
    # the aim stays in its range and its flight target in the leap's (a quarter turn's aim is all target_y)
    top = min(c.aim_range[1], LEAP_SETTINGS.by_name["flight_target_y"].maximum / max(abs(math.sin(bearing)), 1e-3))
    lines = quarter_lines_of(body, way) if way.startswith("sideways") else ("turn_lines" if "turn_lines" in body else None)
    if lines == "turn_lines" or way.startswith("sideways_"):    # a long row after the turn: each turn's line as flown
        return steer_by_lines(character, (x, y), air_time, trials, bound, judge, body, c, way, top, lines)
    shift = 0.0         # by the lines: the landings' misses to the side so far (m, along ``side``)
    good = None         # the aim, heading and air time aimed of the nearest trial that flew
    grounded = set()    # the turns whose jump did not fly
    while True:
        # the turn whose measured line passes nearest the target moved by the misses to the side (sideways; turned where
        # the table has the hop's lines), else the hop whose heading is nearest the one wanted
        turn = turn_for_point(body, (x - shift * side[0], y - shift * side[1]), grounded, lines) if lines \
            else turn_for_heading(body, headings[-1], grounded)
        if turn is None:        # every measured line that stood and leads ahead was tried
            if not trials.tried:
                raise ParameterError(f"no measured turn of the {character} leads toward ({x:g}, {y:g}) m")
            break
        settings = turned_settings(body, air_aims[-1], aims[-1], bearing, turn, way)
        if trials.seen(settings):   # the aim held at a bound: the same jump again
            break
        measured = trials.run(settings)
        if measured["fell_before_liftoff"] or not measured["air_time"] > 0.5 * air_time:   # definition: it did not fly
            # a trial that did not fly tells nothing of the aim: the next measured hop nearest the heading (another
            # stance to jump from), halfway back to the nearest trial that flew, not secants on it
            grounded.add(turn)
            if len(trials.tried) >= min(c.turn_aim_trials, bound):
                break
            if good is not None:
                aims[-1], headings[-1], air_aims[-1] = [(a + b) / 2.0 for a, b in zip((aims[-1], headings[-1], air_aims[-1]), good)]
            continue
        lx, ly = measured["landing"]
        error = math.hypot(lx - x, ly - y)
        if good is None or error < good[3]:
            good = (aims[-1], headings[-1], air_aims[-1], error)
        reached.append(lx * along[0] + ly * along[1])
        bearings.append(math.atan2(ly, lx))
        flown.append(measured["air_time"])
        miss, late = reached[-1] - distance, flown[-1] - air_time
        off = lx * side[0] + ly * side[1]
        if (judge(measured)[1] or (math.hypot(miss, off) <= c.aim_tolerance and abs(late) <= c.aim_time_tolerance)
                or len(trials.tried) >= min(c.turn_aim_trials, bound) or not (math.isfinite(miss) and math.isfinite(off))):
            break
        slope = secant(aims, reached, c.aim_slope_floor, c.aim_slope)
        aims.append(min(max(aims[-1] - miss / slope, c.aim_range[0]), top))
        # the heading wanted moves by the landing's bearing missed (over the table's slope); the turn is the measured
        # hop nearest it (turn_for_heading: the hop's heading is not smooth in its angle, a secant on it stepped far off)
        headings.append(headings[-1] - (bearings[-1] - bearing) / c.turn_slope)
        shift += off
        rate = secant(air_aims, flown, c.aim_slope_floor, 1.0)     # definition: the first step as flown
        air_aims.append(air_aims[-1] - late / rate)
    return landed_plan(character, target, trials, bound, judge, c)


def steer_by_lines(character: str, target, air_time: float, trials: Trials, bound: int, judge: Callable, body: dict, c,
                   way: str, top: float, lines: str = "turn_lines") -> dict:
    """plan_turned's aim where the table has the hop's lines (``turn_lines``), with a model of each hop from the jumps
    already flown: each hop's line moved to where its jump landed (line_offset: the long row after a hop does not fly
    the line measured with the short row, and each hop misses its own way, so one shift for all - the hop chosen
    anew after each jump - swung between two hops on either side of the target: the woman's (1.214, -0.211) m) and
    its own distance secant (a hop lands its own distance for the same aim: secants across two hops stepped 0.3-0.6
    m). The next hop: the last one again while its jump landed within ``aim_tolerance`` of the target's side,
    else the hop whose line (its own as flown; one never flown, the measured one moved by the mean of the flown
    hops' errors) passes nearest the target; its aim from its own last jump (a hop never flown: from the last jump)
    by the secant of its last two (else ``aim_slope``). The crouch's air time by the secant on the air time flown."""
    x, y = target
    distance, bearing = math.hypot(x, y), math.atan2(y, x)
    along = (math.cos(bearing), math.sin(bearing))
    flown = []          # (turn, aim, distance reached along the bearing, the landing's error left of the hop's line)
    air_aims, times = [float(air_time)], []
    good = None         # the aim and air time of the nearest trial that flew
    grounded = set()    # the turns whose jump did not fly
    turn, aim = turn_for_point(body, target, grounded, lines), distance
    while True:
        if turn is None:        # every measured line that stood and leads ahead was tried
            if not trials.tried:
                raise ParameterError(f"no measured turn of the {character} leads toward ({x:g}, {y:g}) m")
            break
        settings = turned_settings(body, air_aims[-1], aim, bearing, turn, way)
        if trials.seen(settings):   # the aim held at a bound: the same jump again
            break
        measured = trials.run(settings)
        if measured["fell_before_liftoff"] or not measured["air_time"] > 0.5 * air_time:   # definition: it did not fly
            grounded.add(turn)
            if len(trials.tried) >= min(c.turn_aim_trials, bound):
                break
            turn = turn_for_point(body, target, grounded, lines, *_errors(flown))
            if good is not None:
                aim, air_aims[-1] = (aim + good[0]) / 2.0, (air_aims[-1] + good[1]) / 2.0
            continue
        lx, ly = measured["landing"]
        error = math.hypot(lx - x, ly - y)
        if good is None or error < good[2]:
            good = (aim, air_aims[-1], error)
        reached = lx * along[0] + ly * along[1]
        flown.append((turn, aim, reached, line_offset(body, turn, (lx, ly), lines)[1]))
        times.append(measured["air_time"])
        miss, late = reached - distance, times[-1] - air_time
        side = line_offset(body, turn, target, lines)[1] - flown[-1][3]       # the target left of where the hop flew
        if (judge(measured)[1] or (math.hypot(miss, side) <= c.aim_tolerance and abs(late) <= c.aim_time_tolerance)
                or len(trials.tried) >= min(c.turn_aim_trials, bound) or not (math.isfinite(miss) and math.isfinite(side))):
            break
        if abs(side) > c.aim_tolerance:
            turn = turn_for_point(body, target, grounded, lines, *_errors(flown))
        same = [f for f in flown if f[0] == turn] or flown[-1:]        # the hop's own jumps (never flown: the last)
        slope = secant([f[1] for f in same], [f[2] for f in same], c.aim_slope_floor, c.aim_slope)
        aim = min(max(same[-1][1] - (same[-1][2] - distance) / slope, c.aim_range[0]), top)
        rate = secant(air_aims, times, c.aim_slope_floor, 1.0)     # definition: the first step as flown
        air_aims.append(air_aims[-1] - late / rate)
    return landed_plan(character, target, trials, bound, judge, c)


def _errors(flown: list) -> tuple[dict, float]:
    """Each flown hop's last landing error left of its line, and their mean (for hops never flown)."""
    errors = {turn: e for turn, _, _, e in flown}
    return errors, (sum(errors.values()) / len(errors) if errors else 0.0)
