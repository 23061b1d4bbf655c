"""The jump-to-target model (issue 29): which settings land where, measured.

Calibration data: the leap's settings of every calibrated broad jump (control.leap, the broad rows)
and of every stored ground plan straight ahead, each run as a jump to a target and also with its
forward lean, lift-off hip angle, crouch depth and arm swing nudged (``NUDGES``); and a second
family for the long air times, the vertical leaps blended with the broad rows (``high_bases``,
``measure_high``); and the jumps onto and down from boxes (``measure_boxes``: those settings run at
each of BOX_HEIGHTS, ``measure_box_nudges``: around the balanced ones, each recording the surface it
was measured for); each trial measured as the planner measures one (landing point of the middle of
the feet, air time, balanced or not). They are kept in ``sim_core/tuned/tables/jump_model_<character>.json``
(``python -m sim_core.planning.jump_model --characters man,woman`` measures and writes them).

The model maps a request (x, y, air time) to the measured balanced jumps near it, in units of
TARGETS.md's tolerances (``request_distance``): the nearest is a working answer where it is
within the tolerance, and the planner (planning.jump.plan_from_model) runs it, then blends of it
with the near ones on the other side of the target. The region a character is offered is where a measured balanced jump
lands within ``REACH`` tolerances of the request (``nearest_balanced``); the refusal names the
nearest and the air times and lateral offsets measured near that distance (``region_refusal``).
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

import numpy as np

from ..ballistics import GRAVITY, time_to_fall_to
from ..control.leap import LEAP_SETTINGS, Landing, blend_rows, broad_rows, load_mapping
from ..skills.jump_to_target.behaviour import KNOB_DEFAULTS, JumpToTarget, read_plans
from ..skills.jump_to_target.region import JUMP_MODEL_TABLE, LANDING_TOLERANCE, model  # noqa: F401  (the row type, for save)
from .. import tuned
from .jump import measure_settings

# nudges of a calibrated jump's settings measured around it: (setting, change). A broad row is a
# knife edge (the man's 1.0 m row: com_offset +0.005 m fell, -0.005 m landed 13 cm short and
# balanced; liftoff_hip -0.08 rad landed 5 cm short and balanced, +0.07 fell; a lift-off roll of
# 0.02 rad fell): the nudges walk down from each row towards the shorter, balanced side, and deeper
# or shallower crouches change the air time. A sideways lean lands a short jump to the side,
# balanced (the man's 0.5 m row leaning 0.02 m left: (0.50, +0.03) m, 0.04 m: fell; the woman's
# 0.54 m row leaning 0.04 m: (0.56, +0.10) m), a long one falls (the man's 1.0 m row at 0.005 m).
NUDGES = tuple(((name, change),) for name, change in (
    ("com_offset", -0.0025), ("com_offset", -0.005), ("com_offset", -0.01), ("com_offset", -0.015),
    ("liftoff_hip", -0.05), ("liftoff_hip", -0.1), ("liftoff_hip", -0.15),
    ("crouch_height", -0.01), ("crouch_height", 0.01), ("arm_swing", -0.2), ("arm_swing", 0.2),
    ("com_offset_y", 0.02), ("com_offset_y", -0.02), ("com_offset_y", 0.04), ("com_offset_y", -0.04),
    ("com_offset_y", 0.07), ("com_offset_y", -0.07))) + (
    # a deeper crouch leaning less flies longer and shorter (the woman's 1.0 m row: 0.04 m deeper and
    # 0.03 m less lean landed 0.77 m in 0.525 s, balanced; 0.06 / 0.05 and the hips 0.2 rad more
    # extended at lift-off, 0.63 m in 0.54 s; deeper alone, or a wider arm swing, fell)
    (("crouch_height", -0.04), ("com_offset", -0.03)),
    (("crouch_height", -0.06), ("com_offset", -0.05), ("liftoff_hip", 0.2)))
OUTWARD = (("com_offset_y", 0.02),)    # from a balanced jump that landed LATERAL_EDGE or more to a side:
                                        # 0.02 m more lean that way (the nudges' step)
LONGER = (("crouch_height", -0.02), ("com_offset", -0.015))    # from one that flew LONG_EDGE or longer: a
                                        # deeper crouch leaning less (half the compound nudge's step)
LATERAL_EDGE = 0.025                    # m: a landing this far to a side is at the measured region's edge
LONG_EDGE = 0.5                         # s: a flight this long is at its edge (the broad rows fly 0.36-0.54 s)
EXTEND_ROUNDS = 2                       # steps outward from the edge
FILL_STEPS = (0.25, 0.5, 0.75)      # shares of the way between the jumps around a gap that fill measures
FILL_ROUNDS = 2                     # rounds of fill over the gaps left
# the second family (issue 29's air times): the broad jumps fly 0.37-0.54 s (the man) at every distance;
# a calibrated vertical leap blended with a broad jump (blend_rows) takes off higher and leaning less,
# so it lands at the short and middle distances after a longer flight. Measured on the man (0.51 m
# rise blended with his 1.33 m broad row): a quarter to three quarters of the way lands 0.2-1.05 m in
# 0.61-0.66 s. With the landing settings blended too (the broad row's foot lead and delta, set for
# 2.5 m/s forward and a 2 m/s touchdown) every one fell backward: the feet landed 0.14 m ahead of a
# COM moving 0.6 m/s forward and 3.2 m/s down; with the landing's own settings (HIGH_LANDING, its
# calibrated foot delta for those speeds) 5 of 12 landed. The rest left the ground spinning backward
# (-9 kg m^2/s: the vertical rows extend the hips at lift-off) and touched down with the trunk 23 deg
# back; less lift-off hip extension (HIGH_HIP) landed 10 of 12 of those.
HIGH_AIR_TIMES = (0.55, 0.6, 0.65, 0.7)  # s: the vertical rows whose rise flies nearest each (vertical_flight)
HIGH_PARTNERS = (1.0, 1.3, 1.6, 1.9)     # m: the broad rows travelling nearest each (TARGETS.md's distances)
HIGH_WEIGHTS = (0.25, 0.5, 0.75)         # shares of the way from the vertical row to the broad one
HIGH_HIP = (0.0, -0.1, -0.2)             # rad: lift-off hip extension taken off (less backward spin)
HIGH_ARMS_BACK = {"landing_swing_arms": 1.0, "landing_arm_flexion": -0.8}   # those that fell, again with the arms
                                        # swung down and back in flight (pitches the trunk back; the man's 1.21 m broad
                                        # row swings them to -0.84 rad): his 1.23 m jump in 0.62 s touched down with the
                                        # trunk 42 deg forward, the hips righted it and he fell backward; so, 1.19 m in
                                        # 0.60 s, balanced (lift-off hip +-0.1-0.3 rad, foot lead 0.15 / 0.25 s: fell)
HIGH_SIDEWAYS = ("com_offset_y",)       # then the balanced ones leaning sideways (NUDGES of these), as the bases
HIGH_LANDING = {"foot_delta": 0.0,       # the landing as calibrated (calibrate land): its foot delta table only,
                "landing_foot_lead_time": Landing.schema.by_name["foot_lead_time"].default,   # its lead,
                "landing_swing_arms": 0.0,                                                   # arms held
                "landing_arm_flexion": Landing.schema.by_name["arm_flexion"].default}
# boxes (issue 29: onto boxes 0.25-0.75 m and down from them): the same settings measured onto a box at
# each of BOX_HEIGHTS (a box centred where the jump is predicted to land, region.at_height) or down
# from one; the region serves a box request from those measured within region.HEIGHT_REACH of it
BOX_HEIGHTS = tuple(round(0.25 + 0.05 * k, 2) for k in range(11)) + tuple(round(-0.25 - 0.05 * k, 2) for k in range(11))
BOX_PER_HEIGHT = 9                      # bases measured at each height (the most spread of those predicted in span)
BOX_SPAN_X = (0.45, 1.95)               # m: predicted landings measured (issue 29's 0.5-1.9 m, and a tolerance)
BOX_SPAN_T = (0.35, 0.75)               # s: predicted air times measured (0.4-0.7 s, and a tolerance)
BOX_NUDGES = tuple(((name, change),) for name, change in (    # around a balanced box jump (straight ahead): lean
    ("com_offset", 0.01), ("com_offset", -0.01), ("com_offset", 0.02), ("com_offset", -0.02),   # both ways
    ("liftoff_hip", 0.1), ("liftoff_hip", -0.1), ("crouch_height", -0.02), ("crouch_height", 0.02)))
BOX_HEIGHT_STEP = 0.05                  # m: a balanced box jump is also measured this much higher and lower
BOX_NUDGE_ROUNDS = 1
BOX_MIN_X = 0.45                        # m: a box centred nearer would sit on the toes (its front edge 0.3 m before)
WINDUP_TIME = JumpToTarget.schema.by_name["windup_time"].default   # s: the wind-up the calibration jumps ran with
PLAN_KEYS = ("crouch_height", "crouch_pitch", "com_offset", "liftoff_hip", "arm_swing", "thrust_damping",
             "foot_delta", "vertical_thrust", "landing_swing_arms", "landing_arm_flexion", "landing_foot_lead_time")


def plan_settings(row: dict) -> dict:
    """A broad row's leap parameters as the planner's settings (a row with distance 0 runs the
    vertical leap's thrust)."""
    settings = {k: float(row.get(k, LEAP_SETTINGS.defaults().get(k, 0.0))) for k in PLAN_KEYS}
    settings["vertical_thrust"] = float(row.get("distance", 0.0) <= 0.0 or row.get("vertical_thrust", 0.0) > 0.5)
    settings.update({k: float(row.get(k, v)) for k, v in KNOB_DEFAULTS.items()})
    return settings


def bases(character: str) -> list[dict]:
    """The settings measured around: every calibrated broad row and every stored plan on flat ground
    straight ahead (found or not: its settings land somewhere), without repeats."""
    found = [plan_settings(row) for row in broad_rows(load_mapping(character)["broad"])[1]]
    for plan in read_plans(character):
        r = plan["request"]
        if r["target_z"] == 0 and r["target_y"] == 0 and not r.get("obstacle_height") and \
                r.get("strength", "human") == "human" and abs(r["windup_time"] - WINDUP_TIME) < 1e-6:
            found.append({**plan_settings(plan["settings"]), "vertical_thrust": float(plan["settings"]["vertical_thrust"])})
    unique = []
    for s in found:
        if not any(all(abs(s[k] - u[k]) < 1e-9 for k in s) for u in unique):
            unique.append(s)
    return unique


def vertical_flight(rise: float) -> float:
    """The air time of a jump whose COM rises ``rise`` from take-off (ballistics: up and down again)."""
    return time_to_fall_to(0.0, math.sqrt(2.0 * GRAVITY * max(rise, 0.0)), 0.0)


def high_bases(character: str) -> list[dict]:
    """The second family: each calibrated vertical leap flying nearest one of HIGH_AIR_TIMES
    (vertical_flight of its rise) blended HIGH_WEIGHTS of the way to each broad row travelling
    nearest one of HIGH_PARTNERS, with the landing's own settings (HIGH_LANDING) and the lift-off hip
    extension less by each of HIGH_HIP, without repeats."""
    mapping = load_mapping(character)
    columns = mapping["vertical"]
    rises = columns["com_rise"]
    settings_names = [n for n in columns if n not in ("com_rise", "com_travel", "peak_thrust_grf_body_weights")]
    verticals = sorted({min(range(len(rises)), key=lambda k: abs(vertical_flight(rises[k]) - t)) for t in HIGH_AIR_TIMES})
    travels, rows = broad_rows(mapping["broad"])
    partners = sorted({int(np.argmin(np.abs(travels - d))) for d in HIGH_PARTNERS})
    ranges = {p.name: (p.minimum, p.maximum) for p in LEAP_SETTINGS.parameters}
    out = []
    for k in verticals:
        high = plan_settings({n: columns[n][k] for n in settings_names})
        for j in partners:
            for w in HIGH_WEIGHTS:
                blended = {**blend_rows(high, plan_settings(rows[j]), w), **HIGH_LANDING}
                for dh in HIGH_HIP:
                    s = dict(blended)
                    s["liftoff_hip"] = min(max(s["liftoff_hip"] + dh, ranges["liftoff_hip"][0]), ranges["liftoff_hip"][1])
                    if s not in out:
                        out.append(s)
    return out


def measure_high(character: str, points: list[dict], sink=None) -> list[dict]:
    """Measure the second family (high_bases), those of it that did not land balanced again with the
    arms swung back in flight (HIGH_ARMS_BACK), then each balanced one leaning sideways (the NUDGES of
    HIGH_SIDEWAYS), each where not measured already, and step outward from those at a side (extend,
    OUTWARD only). Returns the new jumps."""
    began, added = time.perf_counter(), []
    family = high_bases(character)

    def run(stage: str, todo: list[dict]) -> None:
        todo = [s for k, s in enumerate(todo) if s not in todo[:k] and not any(p["settings"] == s for p in flat(points + added))]
        for k, settings in enumerate(todo):
            added.append(_logged(measure(character, settings), sink))
            if (k + 1) % 20 == 0 or k + 1 == len(todo):
                print(f"{character}: {stage} {k + 1} / {len(todo)}, {len(balanced_points(added))} balanced, "
                      f"{time.perf_counter() - began:.0f} s", file=sys.stderr, flush=True)

    run("high family", family)
    run("arms back", [{**p["settings"], **HIGH_ARMS_BACK} for p in flat(points + added)
                      if p["settings"] in family and p["measured"]["outcome"] != "success"])
    family += [{**s, **HIGH_ARMS_BACK} for s in family]
    sideways = [s for p in balanced_points(flat(points + added)) if p["settings"] in family
                for s in nudged(p["settings"], HIGH_SIDEWAYS)]
    run("sideways", sideways)
    # and outward from those that landed at a side (extend's OUTWARD steps only: they fly long already)
    added += extend(character, points + added, sink, start=[p for p in flat(points + added) if p["settings"] in sideways],
                    longer=False)
    return added


def nudged(settings: dict, only: tuple = ()) -> list[dict]:
    """The settings and each NUDGE of them, inside the leap's ranges (``only``: just the nudges that
    change every one of these settings, without the settings themselves)."""
    ranges = {p.name: (p.minimum, p.maximum) for p in LEAP_SETTINGS.parameters}
    out = [] if only else [dict(settings)]
    for nudge in NUDGES:
        if only and not set(only) <= {name for name, _ in nudge}:
            continue
        changed = dict(settings)
        for name, change in nudge:
            changed[name] = min(max(settings[name] + change, ranges[name][0]), ranges[name][1])
        out.append(changed)
    return out


def measure(character: str, settings: dict, log=None, height: float = 0.0, box_x: float = 1.0) -> dict:
    """One calibration jump: the settings run as a jump to the point they were planned for (the
    target only names the broad thrust; the landing is measured). ``height`` > 0: onto a box that
    high centred ``box_x`` m ahead (scene_for builds it under the target); < 0: down from a box
    that high; the measured jump then records its ``surface`` (and ``box_x`` onto a box)."""
    measured = measure_settings(character, settings, (box_x if height > 0 else 1.0, 0.0, height, 0.0), 0.45, WINDUP_TIME)
    keep = {k: measured[k] for k in ("landing", "air_time", "outcome")}
    if height:
        keep["surface"] = float(height)
        if height > 0:
            keep["box_x"] = float(box_x)
        if abs(measured.get("landing_height", height) - height) > 0.01:    # landed beside the box: not on it
            keep["outcome"] = "off the surface"
    return {"settings": settings, "measured": keep}


def box_bases(character: str, points: list[dict]) -> list[tuple[dict, dict]]:
    """The settings measured onto and down from boxes, each with a measured jump of them (flat or
    on a box) to predict where it lands at another height (region.at_height): every stored box plan
    (no obstacle to clear), the flat bases (as measured in the table) and the balanced jumps of the
    second family straight ahead (high_bases, with and without HIGH_ARMS_BACK), without repeats."""
    out = []
    for plan in read_plans(character):
        r = plan["request"]
        if r["target_z"] != 0 and r.get("strength", "human") == "human" and abs(r["windup_time"] - WINDUP_TIME) < 1e-6 \
                and plan["measured"]["outcome"] == "success":
            settings = {**plan_settings(plan["settings"]), "vertical_thrust": float(plan["settings"]["vertical_thrust"])}
            out.append((settings, {"landing": plan["measured"]["landing"], "air_time": plan["measured"]["air_time"],
                                   "outcome": "success", "surface": float(r["target_z"])}))
    flat = bases(character)
    family = high_bases(character)
    family += [{**s, **HIGH_ARMS_BACK} for s in family]
    for p in points:
        m = p["measured"]
        if "surface" in m or m["outcome"] != "success" or abs(m["landing"][1]) > LATERAL_EDGE:
            continue
        if p["settings"] in flat or p["settings"] in family:
            out.append((p["settings"], m))
    unique = []
    for s, m in out:
        if not any(s == u for u, _ in unique):
            unique.append((s, m))
    return unique


def box_plan(character: str, points: list[dict], heights=BOX_HEIGHTS, per_height: int = BOX_PER_HEIGHT) -> list[tuple]:
    """What measure_boxes runs: for each height, up to ``per_height`` of box_bases whose landing moved
    there (region.at_height) falls in issue 29's span (BOX_SPAN_X, BOX_SPAN_T), the most spread
    (each next the farthest, in tolerances, from those picked), as (settings, height, predicted x)."""
    from ..skills.jump_to_target.region import at_height, request_distance
    found = box_bases(character, points)
    todo = []
    for h in heights:
        fits = []
        for s, m in found:
            moved = at_height(m, h)
            if moved and BOX_SPAN_X[0] <= moved["landing"][0] <= BOX_SPAN_X[1] \
                    and BOX_SPAN_T[0] <= moved["air_time"] <= BOX_SPAN_T[1]:
                fits.append((s, moved, abs(m.get("surface", 0.0) - h)))
        fits.sort(key=lambda e: e[2])           # those measured nearest this height first
        picked = fits[:1]
        while fits and len(picked) < per_height:
            rest = [f for f in fits if not any(f[0] == q[0] for q in picked)]
            if not rest:
                break
            far = max(rest, key=lambda f: min(request_distance(q[1], (*f[1]["landing"], h), f[1]["air_time"])
                                              for q in picked))
            picked.append(far)
        todo += [(s, h, max(moved["landing"][0], BOX_MIN_X)) for s, moved, _ in picked]
    return todo


def measure_box_nudges(character: str, points: list[dict], sink=None, rounds: int = BOX_NUDGE_ROUNDS) -> list[dict]:
    """Around the balanced jumps onto and down from boxes: each of BOX_NUDGES at the height it was
    measured for, and the jump itself at the heights BOX_HEIGHT_STEP above and below (within
    BOX_HEIGHTS' span), each where not measured already; ``rounds`` times, each round around the
    balanced ones the round before added. Returns the new jumps."""
    ranges = {p.name: (p.minimum, p.maximum) for p in LEAP_SETTINGS.parameters}
    low, high = min(abs(h) for h in BOX_HEIGHTS), max(abs(h) for h in BOX_HEIGHTS)
    began, added = time.perf_counter(), []
    around = [p for p in balanced_points(points) if p["measured"].get("surface")]
    for r in range(rounds):
        todo = []
        for p in around:
            h, x = p["measured"]["surface"], p["measured"]["landing"][0]
            for nudge in BOX_NUDGES:
                changed = dict(p["settings"])
                for name, change in nudge:
                    changed[name] = min(max(changed[name] + change, ranges[name][0]), ranges[name][1])
                todo.append((changed, h, x))
            for dh in (-BOX_HEIGHT_STEP, BOX_HEIGHT_STEP):
                h2 = round(h + dh, 3)
                if low - 1e-9 <= abs(h2) <= high + 1e-9 and h2 * h > 0:
                    todo.append((p["settings"], h2, x))
        new = []
        for k, (settings, h, x) in enumerate(todo):
            if any(q["settings"] == settings and q["measured"].get("surface") == h for q in points + added + new):
                continue
            new.append(_logged(measure(character, settings, height=h, box_x=max(x, BOX_MIN_X)), sink))
            if len(new) % 20 == 0:
                print(f"{character}: box nudges round {r + 1}, {k + 1} / {len(todo)}, {len(balanced_points(new))} "
                      f"balanced, {time.perf_counter() - began:.0f} s", file=sys.stderr, flush=True)
        added += new
        around = balanced_points(new)
        print(f"{character}: box nudges round {r + 1}: {len(new)} jumps, {len(around)} balanced", file=sys.stderr, flush=True)
    return added


LANDING_STEP = 0.5 * LANDING_TOLERANCE     # m: a landing variant's feet placed this much nearer or further (the man's
                                        # 1.64 m jump in 0.59 s fell; with the feet 2.5 cm nearer: 1.61 m, balanced)
ARMS_UP = {"landing_swing_arms": 1.0, "landing_arm_flexion": 2.0,    # in flight the arms swing forward and up and
           "landing_right_time": 0.4}  # after touchdown the trunk is righted over 0.4 s: the long flights touch down
                                        # with the trunk pitched 45-57 deg forward, the hands met the ground (the man's
                                        # 1.75 m in 0.57 s), and righted at once the hips threw him back into the air
LANDING_VARIANTS = ((("foot_delta", -LANDING_STEP),), (("foot_delta", LANDING_STEP),),
                    tuple(ARMS_UP.items()), tuple(ARMS_UP.items()) + (("foot_delta", -LANDING_STEP),))


def landing_candidates(character: str, points: list[dict]) -> list[dict]:
    """The flat-ground jumps whose flight lands inside issue 29's span (random_requests' box) where the
    region offers nothing, that did not end balanced: one per cell of half the tolerances (the first
    measured), the flights a different landing might keep."""
    from ..random_requests import JUMP_AIR_TIME, JUMP_FORWARD, JUMP_LATERAL
    from ..skills.jump_to_target.region import AIR_TIME_TOLERANCE, offered
    low, high = JUMP_FORWARD.get(character, (0.5, 1.9))
    cells = {}
    for p in flat(points):
        m = p["measured"]
        (x, y), t = m["landing"][:2], m["air_time"]
        if m["outcome"] == "success" or not (math.isfinite(x) and math.isfinite(y)) \
                or not (low - LANDING_TOLERANCE <= x <= high + LANDING_TOLERANCE) or abs(y) > JUMP_LATERAL + LANDING_TOLERANCE \
                or not (JUMP_AIR_TIME[0] - AIR_TIME_TOLERANCE <= t <= JUMP_AIR_TIME[1] + AIR_TIME_TOLERANCE) \
                or offered(character, (x, y), t):
            continue
        cells.setdefault((round(2 * x / LANDING_TOLERANCE), round(2 * y / LANDING_TOLERANCE),
                          round(2 * t / AIR_TIME_TOLERANCE)), p)
    return list(cells.values())


def measure_landings(character: str, points: list[dict], sink=None) -> list[dict]:
    """Each of landing_candidates with each of LANDING_VARIANTS (the landing's settings only: the same
    take-off and flight, the feet placed a step nearer or further, the arms swung up in flight and
    the trunk righted slowly), where not measured already. Returns the new jumps."""
    ranges = {p.name: (p.minimum, p.maximum) for p in LEAP_SETTINGS.parameters}
    began, added = time.perf_counter(), []
    todo = landing_candidates(character, points)
    for k, p in enumerate(todo):
        for variant in LANDING_VARIANTS:
            settings = dict(p["settings"])
            for name, value in variant:
                value = settings.get(name, 0.0) + value if name == "foot_delta" else value
                settings[name] = min(max(value, ranges[name][0]), ranges[name][1])
            if any(q["settings"] == settings for q in flat(points + added)):
                continue
            added.append(_logged(measure(character, settings), sink))
        if (k + 1) % 10 == 0 or k + 1 == len(todo):
            print(f"{character}: landings {k + 1} / {len(todo)}, {len(balanced_points(added))} of {len(added)} balanced, "
                  f"{time.perf_counter() - began:.0f} s", file=sys.stderr, flush=True)
    return added


def measure_box_edges(character: str, points: list[dict], sink=None) -> list[dict]:
    """Each balanced jump onto a box again with its box centred LANDING_TOLERANCE short of where it
    landed (not nearer than BOX_MIN_X): the nearest box a request it serves may stand on (the box stands
    centred on the target; region.clears serves a request only with its box no nearer than a measured
    one), where no measurement of those settings at that height had a box as near. Returns the new jumps."""
    began, added = time.perf_counter(), []
    onto = [p for p in balanced_points(points) if p["measured"].get("surface", 0.0) > 0]
    for k, p in enumerate(onto):
        h = p["measured"]["surface"]
        x = round(max(p["measured"]["landing"][0] - LANDING_TOLERANCE, BOX_MIN_X), 3)
        if any(q["settings"] == p["settings"] and q["measured"].get("surface") == h
               and q["measured"].get("box_x", math.inf) <= x + 1e-9 for q in points + added):
            continue
        added.append(_logged(measure(character, p["settings"], height=h, box_x=x), sink))
        if len(added) % 10 == 0 or k + 1 == len(onto):
            print(f"{character}: box edges {k + 1} / {len(onto)}, {len(balanced_points(added))} of {len(added)} "
                  f"balanced, {time.perf_counter() - began:.0f} s", file=sys.stderr, flush=True)
    return added


def measure_boxes(character: str, points: list[dict], sink=None, heights=BOX_HEIGHTS,
                  per_height: int = BOX_PER_HEIGHT) -> list[dict]:
    """Measure jumps onto and down from boxes (box_plan: each base run onto a box centred where it is
    predicted to land, or down from one), each where not measured already. Returns the new jumps."""
    began, added = time.perf_counter(), []
    todo = box_plan(character, points, heights, per_height)
    for k, (settings, h, x) in enumerate(todo):
        if any(p["settings"] == settings and p["measured"].get("surface") == h for p in points + added):
            continue
        added.append(_logged(measure(character, settings, height=h, box_x=x), sink))
        if (k + 1) % 10 == 0 or k + 1 == len(todo):
            print(f"{character}: boxes {k + 1} / {len(todo)}, {len(balanced_points(added))} balanced, "
                  f"{time.perf_counter() - began:.0f} s", file=sys.stderr, flush=True)
    return added


def calibrate(character: str, out: Path | None = None, directory: Path | None = None, only: tuple = ()) -> list[dict]:
    """Measure every base and its nudges (one process; about 1.5 s a jump), step outward from the
    edge (extend), fill the gaps between the balanced landings (fill), measure the second family
    (measure_high, which steps outward from its own sideways landings), the jumps onto and down from
    boxes (measure_boxes, measure_box_nudges), and store the table.
    ``only``: measure just the nudges that change every one of these settings and add them to the
    stored table's jumps."""
    points = list(model(character)["points"]) if only else []
    began = time.perf_counter()
    sink = open(out, "a") if out else None
    for k, base in enumerate(bases(character)):
        for settings in nudged(base, only):
            points.append(_logged(measure(character, settings), sink))
        print(f"{character}: base {k + 1}, {len(points)} jumps, {sum(p['measured']['outcome'] == 'success' for p in points)}"
              f" balanced, {time.perf_counter() - began:.0f} s", file=sys.stderr, flush=True)
    points += extend(character, points, sink)
    points += fill(character, points, sink)
    points += measure_high(character, points, sink)
    points += measure_boxes(character, points, sink)
    points += measure_box_nudges(character, points, sink)
    points += measure_box_edges(character, points, sink)
    points += measure_landings(character, points, sink)
    store(character, points, directory)
    return points


def _logged(point: dict, sink) -> dict:
    if sink:
        sink.write(json.dumps(point) + "\n")
        sink.flush()
    return point


def extend(character: str, points: list[dict], sink=None, rounds: int = EXTEND_ROUNDS, start: list[dict] | None = None,
           longer: bool = True) -> list[dict]:
    """Steps outward from the balanced jumps at the edge of the measured region: OUTWARD (more lean
    to the side it landed) from those LATERAL_EDGE or more to a side, LONGER (unless not ``longer``)
    from those that flew LONG_EDGE or longer; each round from the balanced edge jumps the round before
    added (the first from all, or from the balanced ones of ``start``). Returns the new jumps
    (balanced or not)."""
    ranges = {p.name: (p.minimum, p.maximum) for p in LEAP_SETTINGS.parameters}
    added, edge = [], balanced_points(flat(points if start is None else start))
    for _ in range(rounds):
        new = []
        for p in edge:
            steps = []
            side = p["measured"]["landing"][1]
            if abs(side) >= LATERAL_EDGE:
                steps.append([(n, math.copysign(c, side)) for n, c in OUTWARD])
            if longer and p["measured"]["air_time"] >= LONG_EDGE:
                steps.append(list(LONGER))
            for step in steps:
                settings = dict(p["settings"])
                for n, c in step:
                    settings[n] = min(max(settings[n] + c, ranges[n][0]), ranges[n][1])
                if not any(q["settings"] == settings for q in flat(points + added + new)):
                    new.append(_logged(measure(character, settings), sink))
        added += new
        edge = balanced_points(new)
        print(f"{character}: extended by {len(new)} jumps, {len(edge)} balanced", file=sys.stderr, flush=True)
    return added


def flat(points: list[dict]) -> list[dict]:
    """The jumps measured on flat ground (the boxes' record their surface)."""
    return [p for p in points if not p["measured"].get("surface")]


def same_surface(p: dict, q: dict) -> bool:
    """Measured on the same surface (and onto a box, with the box in the same place)."""
    return all(p["measured"].get(k, 0.0) == q["measured"].get(k, 0.0) for k in ("surface", "box_x"))


def balanced_points(points: list[dict]) -> list[dict]:
    return [p for p in points if p["measured"]["outcome"] == "success"]


def gaps(points: list[dict]) -> list[tuple[dict, dict]]:
    """Neighbouring balanced landings (in forward distance) further apart than the tolerance's
    diameter: the jumps on either side of a stretch no measured jump serves."""
    ranked = sorted((p for p in flat(points) if p["measured"]["outcome"] == "success"),
                    key=lambda p: p["measured"]["landing"][0])
    return [(a, b) for a, b in zip(ranked, ranked[1:])
            if b["measured"]["landing"][0] - a["measured"]["landing"][0] > 2 * LANDING_TOLERANCE]


def fill(character: str, points: list[dict], sink=None, rounds: int = FILL_ROUNDS) -> list[dict]:
    """Blends (control.leap.blend_rows) of the two balanced jumps around each gap (gaps), at
    FILL_STEPS shares of the way, measured unless measured already (a jump is deterministic);
    repeated over the gaps left, ``rounds`` times. Returns the new jumps (balanced or not)."""
    added = []
    for _ in range(rounds):
        todo = gaps(points + added)
        for a, b in todo:
            for w in FILL_STEPS:
                settings = blend_rows(a["settings"], b["settings"], w)
                if not any(p["settings"] == settings for p in flat(points + added)):     # measured already: the same
                    added.append(_logged(measure(character, settings), sink))
        print(f"{character}: filled {len(todo)} gaps, {len(added)} jumps, "
              f"{sum(p['measured']['outcome'] == 'success' for p in added)} balanced", file=sys.stderr, flush=True)
    return added


def store(character: str, points: list[dict], directory: Path | None = None) -> Path:
    """Write the table, each jump once (the first of any with the same settings onto the same surface)."""
    points = [p for k, p in enumerate(points) if not any(q["settings"] == p["settings"] and same_surface(p, q)
                                                         for q in points[:k])]
    return tuned.save("jump_model", character, {"script": "python -m sim_core.planning.jump_model", "points": points},
                      strengths=["human"], directory=directory)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--characters", default="man,woman")
    parser.add_argument("--log", help="also append every measured jump to this JSON-lines file")
    parser.add_argument("--only", default="", help="comma-separated settings: measure only the nudges that change "
                                                   "every one of them and add them to the stored table")
    parser.add_argument("--extend-only", action="store_true",
                        help="only step outward from the stored table's edge (extend), adding to it")
    parser.add_argument("--high-only", action="store_true",
                        help="only measure the second family (vertical leaps blended with broad jumps, "
                             "measure_high), adding to the stored table")
    parser.add_argument("--boxes-only", action="store_true",
                        help="only measure jumps onto and down from boxes (measure_boxes), adding to the stored table")
    parser.add_argument("--heights", default="", help="with --boxes-only: comma-separated surface heights (m; "
                                                      "default BOX_HEIGHTS)")
    parser.add_argument("--box-edges-only", action="store_true",
                        help="only measure the stored table's balanced jumps onto boxes again with the box nearer "
                             "(measure_box_edges)")
    parser.add_argument("--landings-only", action="store_true",
                        help="only measure landing variants of the stored table's fallen flights outside the region "
                             "(measure_landings), adding to it")
    parser.add_argument("--box-nudges-only", action="store_true",
                        help="only measure around the stored table's balanced box jumps (measure_box_nudges)")
    parser.add_argument("--per-height", type=int, default=BOX_PER_HEIGHT, help="with --boxes-only: bases per height")
    parser.add_argument("--fill-only", action="store_true",
                        help="only fill the gaps of the stored table's jumps (fill), adding to it")
    args = parser.parse_args(argv)
    heights = tuple(float(h) for h in args.heights.split(",") if h.strip()) or BOX_HEIGHTS
    # each --*-only flag: the measurement that adds to the stored table's points
    adders = {"extend_only": extend, "high_only": measure_high, "landings_only": measure_landings,
              "box_edges_only": measure_box_edges, "box_nudges_only": measure_box_nudges, "fill_only": fill,
              "boxes_only": lambda c, points, sink: measure_boxes(c, points, sink, heights, args.per_height)}
    adder = next((adders[flag] for flag in adders if getattr(args, flag)), None)
    for character in [c.strip() for c in args.characters.split(",") if c.strip()]:
        if adder is not None:
            points = list(model(character)["points"])
            store(character, points + adder(character, points, open(args.log, "a") if args.log else None))
        else:
            calibrate(character, Path(args.log) if args.log else None,
                      only=tuple(n.strip() for n in args.only.split(",") if n.strip()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
