"""The region of jump targets a character is offered (issue 29), from its measured jumps.

The measured jumps are the jump_model table (sim_core/tuned/tables/jump_model_<character>.json,
written by ``python -m sim_core.planning.jump_model``): the leap's settings of every calibrated
broad jump and stored straight-ahead plan and of nudges of them, each with where it landed the
middle of the feet, its air time and whether it ended balanced, and the height of the surface it
was measured landing on (``surface``: a box top above the start, or the ground below a box it
started on; no entry = flat ground). A request (x, y[, z], air time) is offered where a measured
balanced jump does it within ``REACH`` of TARGETS.md's tolerances (``request_distance``; a box
request at a height between two measured ones by a jump that landed balanced at both, its landing
and air time interpolated between the two, ``served``); anything else is refused before
simulating, in one line naming the limit (``region_refusal``). Only reads the table: the measuring
is planning's.

A request onto a box that asks a faster lift-off up than any the character was measured to fly at its forward speed
(``lift_envelope``: its measured balanced jumps, its commanded rows' regions, its highest vertical leap) is refused
naming the two speeds (``takeoff_refusal``, the first limit ``region_refusal`` names for it).

A character with a commanded take-off table (commanded.py: the man's and the woman's) is also offered the box
measured for it on flat ground (``in_region``); ``mode`` says which of the two plans a request
(planning/jump.py: the measured jumps', or planning/commanded.py), and a refusal of a request
outside both names both limits.
"""
from __future__ import annotations

import math

import numpy as np

from ...ballistics import GRAVITY
from ...control.leap import LEAP_SETTINGS, load_mapping
from ...tuned import TableType, load_fresh, register as register_table
from .commanded import STRAIGHT_WAYS, commanded_limit, commanded_offers, flat_equivalent, table

LANDING_TOLERANCE = 0.05            # m: TARGETS.md: the landing point within this of the target
AIR_TIME_TOLERANCE = 0.05           # s: TARGETS.md: the air time within this of the one asked
REACH = 1.0             # tolerances: a request is offered where a measured balanced jump is this near
                        # (request_distance): replayed, the same settings land the same (one simulation)
HEIGHT_REACH = 0.05     # m: a box request is served by a jump that landed balanced at measured heights this
                        # far apart on either side of it (jump_model.BOX_HEIGHTS' step): landing balanced at
                        # one height is a knife edge (the man's 0.5 m box plan onto 0.4 m landed balanced,
                        # onto 0.55 m fell; a jump moved 2.5 cm from the one height it was measured for,
                        # ballistically, landed 31 / 40 random box requests of seed 29)


def _model_rows(body: dict):
    for k, point in enumerate(body.get("points", [])):
        yield f"point {k}", point["settings"]


def nearest_point_row(body: dict, target, air_time: float) -> dict | None:
    """The measured balanced jump nearest the request in units of the tolerances (request_distance)."""
    points = balanced(body)
    return min(points, key=lambda p: request_distance(p["measured"], target, air_time)) if points else None


JUMP_MODEL_TABLE = register_table(TableType("jump_model", LEAP_SETTINGS, _model_rows, (nearest_point_row,)))


def surface(measured: dict) -> float:
    """The height of the surface a jump was measured landing on (0: flat ground, the tables before boxes)."""
    return float(measured.get("surface", 0.0))


def height_of(target) -> float:
    return float(target[2]) if len(target) > 2 else 0.0


def serves(measured: dict, z: float) -> bool:
    """Whether a jump measured for its surface may serve a request landing at height ``z``: flat
    ground only by flat-ground jumps, a box by jumps measured within HEIGHT_REACH of it."""
    h = surface(measured)
    return h == z if (h == 0.0 or z == 0.0) else abs(h - z) <= HEIGHT_REACH + 1e-9


def at_height(measured: dict, z: float) -> dict:
    """The measured jump with its landing moved to a surface at height ``z`` (ballistics: the same
    take-off velocity, from the landing point, air time and surface measured, lands where the path
    crosses z on the way down); unchanged on its own surface; None if the path does not reach z."""
    h = surface(measured)
    if abs(h - z) < 1e-9:
        return measured
    t, (x, y) = measured["air_time"], measured["landing"][:2]
    up = (h + 0.5 * GRAVITY * t * t) / t
    disc = up * up - 2.0 * GRAVITY * z
    if disc < 0.0 or t <= 0.0:
        return None
    t2 = (up + math.sqrt(disc)) / GRAVITY
    return {**measured, "landing": [x * t2 / t, y * t2 / t], "air_time": t2, "surface": z}


def request_distance(measured: dict, target, air_time: float) -> float:
    """How far a measured jump is from a request, in units of TARGETS.md's tolerances: the larger of
    the landing-point miss / 5 cm and the air-time miss / 0.05 s (<= 1: the jump does the request);
    infinite for a jump on another surface than the request's (a box request's jumps: served)."""
    if abs(surface(measured) - height_of(target)) > 1e-9:
        return math.inf
    landing = measured["landing"]
    miss = math.hypot(landing[0] - float(target[0]), landing[1] - float(target[1])) / LANDING_TOLERANCE
    return max(miss, abs(measured["air_time"] - air_time) / AIR_TIME_TOLERANCE)


def _key(settings: dict) -> tuple:
    return tuple(sorted(settings.items()))


def brackets(character: str) -> list[tuple[dict, dict, dict]]:
    """The measured box jumps as (point, lower, upper): the same settings landing balanced at two
    neighbouring measured heights HEIGHT_REACH apart (lower and upper measured), or at one (lower is
    upper); ``point`` the lower one's jump."""
    body = model(character)
    if body is None or _BRACKETS.get(character, (None,))[0] is not body:     # the brackets of the table as read now
        by_settings = {}
        for p in balanced(body):
            if surface(p["measured"]):
                by_settings.setdefault(_key(p["settings"]), {}).setdefault(surface(p["measured"]), []).append(p)
        out = []
        for heights in by_settings.values():
            # at each height the one measured with the nearest box (box_edge: it serves the most requests)
            same = sorted((min(at, key=box_centre) for at in heights.values()), key=lambda p: surface(p["measured"]))
            for k, p in enumerate(same):
                out.append((p, p["measured"], p["measured"]))
                if k + 1 < len(same) and abs(surface(same[k + 1]["measured"]) - surface(p["measured"])) <= HEIGHT_REACH + 1e-6:
                    out.append((p, p["measured"], same[k + 1]["measured"]))
        _BRACKETS[character] = (body, out)
    return _BRACKETS[character][1]


_BRACKETS: dict = {}


def box_centre(point: dict) -> float:
    """Where the box a jump onto a box was measured on stood (its middle, m ahead of the start's feet;
    -inf for a jump on flat ground or down from a box: no box ahead)."""
    return float(point["measured"].get("box_x", -math.inf))


def clears(low: dict, high: dict, x: float) -> bool:
    """Whether a jump measured onto boxes (low, high: its measurements at the two heights) serves a
    request whose box stands centred on x: the box no nearer than either measured one. A nearer box
    edge meets the feet on the way up (the man's jump onto 0.6 m measured with the box at 0.86 m
    landed balanced with it at 0.82 and 0.90 m, and hit its front at 0.79 m and fell)."""
    return x >= max(low.get("box_x", -math.inf), high.get("box_x", -math.inf)) - 1e-9


def served(character: str, z: float, x: float | None = None) -> list[dict]:
    """The character's measured jumps that serve a box request at height ``z`` (and, onto a box, with
    the box centred ``x`` m ahead: clears): each that landed balanced at measured heights on both
    sides of z (brackets; or at z itself), with "measured" its landing and air time interpolated to z
    (linear in the height) and "as_measured" the lower one."""
    out = []
    for p, low, high in brackets(character):
        h0, h1 = surface(low), surface(high)
        if not (h0 - 1e-9 <= z <= h1 + 1e-9) or (h0 == h1 and abs(z - h0) > 1e-9):
            continue
        if x is not None and not clears(low, high, x):
            continue
        w = 0.0 if h1 == h0 else (z - h0) / (h1 - h0)
        moved = {**low, "surface": z, "air_time": low["air_time"] + w * (high["air_time"] - low["air_time"]),
                 "landing": [a + w * (b - a) for a, b in zip(low["landing"], high["landing"])]}
        out.append({**p, "measured": moved, "as_measured": low})
    return out


def balanced(body: dict | None) -> list[dict]:
    return [p for p in (body or {}).get("points", []) if p["measured"]["outcome"] == "success"
            and all(math.isfinite(v) for v in p["measured"]["landing"])]


def model(character: str) -> dict | None:
    """The character's measured jumps (None: not measured); read again when the file changes."""
    return load_fresh("jump_model", character)


def nearest_balanced(character: str, target, air_time: float, count: int = 1) -> list[tuple[float, dict]]:
    """The ``count`` measured balanced jumps nearest the request that serve its height, as
    (request_distance, point); a point measured for another surface with its "measured" moved to
    the request's height (at_height) and the measured one as "as_measured"."""
    z = height_of(target)
    points = served(character, z, float(target[0])) if z else balanced(model(character))
    ranked = sorted(((request_distance(p["measured"], target, air_time), p) for p in points), key=lambda e: e[0])
    return [e for e in ranked if math.isfinite(e[0])][:count]


def offered(character: str, target, air_time: float) -> bool:
    """Whether a measured balanced jump does the request within REACH tolerances (request_distance)."""
    body = model(character)
    if body is None or _ARRAYS.get(character, (None,))[0] is not body:     # the arrays of the table as read now
        rows = [(*p["measured"]["landing"], p["measured"]["air_time"], surface(p["measured"])) for p in balanced(body)]
        _ARRAYS[character] = (body, np.asarray(rows, dtype=float).reshape(-1, 4))
    points = _ARRAYS[character][1]
    z = height_of(target)
    if z:
        return any(request_distance(p["measured"], target, air_time) <= REACH for p in served(character, z, float(target[0])))
    points = points[points[:, 3] == 0.0]
    if not len(points):
        return False
    miss = np.hypot(points[:, 0] - float(target[0]), points[:, 1] - float(target[1])) / LANDING_TOLERANCE
    return bool(np.maximum(miss, np.abs(points[:, 2] - air_time) / AIR_TIME_TOLERANCE).min() <= REACH)


_ARRAYS: dict = {}


def in_region(character: str, target, air_time: float) -> bool:
    """Whether the request is offered: in the measured jumps' region (offered) or in the commanded
    take-off's (commanded_in_region)."""
    return offered(character, target, air_time) or commanded_in_region(character, target, air_time)


def commanded_in_region(character: str, target, air_time: float) -> bool:
    """Whether the commanded take-off offers the request (commanded.commanded_offers) within the character's take-off
    (takeoff_refusal: a row onto higher boxes, ``<row>_high_onto_region``, reaches T0 beyond the lift-offs measured at
    the faster forward speeds)."""
    return commanded_offers(character, target, air_time) and takeoff_refusal(character, target, air_time) is None


def mode(character: str, target, air_time: float) -> str | None:
    """How a request on flat ground or a box is planned: "measured" (from the measured jumps: in their
    region, or where they were not measured), "commanded" (the commanded take-off: outside their region,
    in its own), or None (refused: region_refusal says why)."""
    if model(character) is None or offered(character, target, air_time):
        return "measured"
    return "commanded" if commanded_in_region(character, target, air_time) else None


def takeoff_capacity(character: str, key: str) -> float:
    """The fastest take-off (m/s) the character's calibrated vertical leaps reach."""
    rises = load_mapping(character).get(key, {}).get("com_rise", [])
    return math.sqrt(2.0 * GRAVITY * max(rises)) if rises else 0.0


def lift_off(target, air_time: float) -> tuple[float, float]:
    """The lift-off velocity (m/s along the ground, up) of a flight to ``target`` (x, y[, z]) in ``air_time`` s as the
    commanded take-off flies it: its flat equivalent's (commanded.flat_equivalent: the vertical speed that flies T0 on
    flat ground, g T0 / 2, and the target's distance over the air time)."""
    distance = math.hypot(float(target[0]), float(target[1]))
    _, flat_time = flat_equivalent((distance, 0.0, height_of(target)), air_time)
    return distance / float(air_time), 0.5 * GRAVITY * flat_time


def lift_envelope(character: str) -> np.ndarray:
    """The most vertical lift-off speed the character was measured to fly at each speed along the ground: rows
    (along, up) m/s of the upper hull of the lift-offs (lift_off) of its measured balanced jumps (the jump_model table:
    flat ground, onto and down from boxes), of the far corners of its commanded table's flat straight regions (each
    measured to land there: ``region``, ``long_region``, ...), and of the leap's highest vertical leap
    (takeoff_capacity, nothing along the ground); between two measured lift-offs the hull's straight line."""
    body, commanded = model(character), table(character)
    cached = _ENVELOPES.get(character)
    if cached is not None and cached[0] is body and cached[1] is commanded:     # the tables as read now
        return cached[2]
    points = [lift_off((*p["measured"]["landing"], surface(p["measured"])), p["measured"]["air_time"])
              for p in balanced(body) if p["measured"]["air_time"] > 0.0]
    for key in ("region", *(f"{way}_region" for way in STRAIGHT_WAYS)):     # the flat straight rows' regions
        region = (commanded or {}).get(key)
        if region:
            points += [lift_off((x, 0.0), t) for x in region["target_x"] for t in region["air_time"]]
    points.append((0.0, takeoff_capacity(character, "vertical")))
    hull = []
    for p in sorted(points):        # the upper hull, left to right (monotone chain)
        while len(hull) >= 2 and ((hull[-1][0] - hull[-2][0]) * (p[1] - hull[-2][1])
                                  - (hull[-1][1] - hull[-2][1]) * (p[0] - hull[-2][0])) >= 0.0:
            hull.pop()
        hull.append(p)
    envelope = np.asarray([h for h in hull if h[0] >= 0.0] or hull, dtype=float)
    _ENVELOPES[character] = (body, commanded, envelope)
    return envelope


_ENVELOPES: dict = {}


def takeoff_refusal(character: str, target, air_time: float) -> str | None:
    """None unless the request is onto a box (z > 0) and needs a faster lift-off up than any the character was
    measured to fly at its speed along the ground (lift_envelope); then the one-line refusal naming the speeds."""
    z = height_of(target)
    if z <= 0.0:
        return None
    along, up = lift_off(target, air_time)
    envelope = lift_envelope(character)
    where = (f"target ({float(target[0]):g}, {float(target[1]):g}, {z:g}) m in air_time={air_time:g} s is beyond the "
             f"{character}'s take-off: onto a {z:g} m box it needs a lift-off at {up:.2f} m/s up with {along:.2f} m/s "
             f"forward (the flight of T0 = air_time + 2 height / (g air_time) = {2.0 * up / GRAVITY:.2f} s on flat ground)")
    if along > envelope[-1, 0]:
        return f"{where}; none of the {character}'s measured take-offs goes faster than {envelope[-1, 0]:.2f} m/s forward"
    most = float(np.interp(along, envelope[:, 0], envelope[:, 1]))
    if up <= most:
        return None
    return (f"{where}; the most the {character}'s measured take-offs reach at that forward speed is {most:.2f} m/s up "
            f"({envelope[0, 1]:.2f} m/s straight up, the leap's highest) - a lower box or a shorter air time")


def region_refusal(character: str, target, air_time: float) -> str | None:
    """None if the request (x, y, air time) is in the region offered (in_region), else the one-line
    refusal naming the limit it breaks: the forward distances measured (no balanced jump lands near
    x), the air times offered at x, or the lateral offsets offered at x in that air time; and the
    nearest measured balanced jump; and the commanded take-off's limits where the character has them."""
    refusal = measured_refusal(character, target, air_time)
    if refusal is None or commanded_in_region(character, target, air_time):
        return None
    beyond = takeoff_refusal(character, target, air_time)
    if beyond is not None:      # onto a box beyond the body's take-off: that limit alone
        return beyond
    limit = commanded_limit(character, height_of(target))
    return refusal if limit is None else f"{refusal}; {limit}"


def measured_refusal(character: str, target, air_time: float) -> str | None:
    """region_refusal's for the measured jumps' region alone."""
    z = height_of(target)
    every = balanced(model(character))
    if not any((surface(p["measured"]) != 0.0) == (z != 0.0) for p in every):
        return None         # not measured (python -m sim_core.planning.jump_model): the planner searches
    x, y = float(target[0]), float(target[1])
    on = "" if not z else (f" onto a {z:g} m box" if z > 0 else f" down from a {-z:g} m box")
    points = served(character, z) if z else [p for p in every if not surface(p["measured"])]
    if not points:
        heights = sorted({round(abs(surface(p["measured"])), 3) for p in every if surface(p["measured"]) * z > 0})
        return (f"target ({x:g}, {y:g}, {z:g}) m is outside the region the {character}'s measured jumps offer: "
                f"no balanced jump{on} was measured at the heights around it (a box is offered where a jump "
                f"landed balanced at the measured heights on both sides, {HEIGHT_REACH * 100:.0f} cm apart; "
                f"measured {'onto' if z > 0 else 'down from'}: {', '.join(f'{h:g}' for h in heights) or 'none'} m)")
    if z > 0 and not served(character, z, x):
        nearest_box = min(box_centre(p) for p in points)
        return (f"target ({x:g}, {y:g}, {z:g}) m is outside the region the {character}'s measured jumps offer: "
                f"the {z:g} m box stands centred on the target, {x:.2f} m ahead, and no balanced jump onto it was "
                f"measured with its box that near (its front edge meets the feet on the way up; the nearest "
                f"measured at that height is centred {nearest_box:.2f} m ahead)")
    points = served(character, z, x) if z > 0 else points
    d, nearest = nearest_balanced(character, target, air_time)[0]
    if d <= REACH:
        return None
    reach, window = REACH * LANDING_TOLERANCE, REACH * AIR_TIME_TOLERANCE
    here = [p["measured"] for p in points if abs(p["measured"]["landing"][0] - x) <= reach]
    timed = [h for h in here if abs(h["air_time"] - air_time) <= window]
    if not here:
        xs = sorted(p["measured"]["landing"][0] for p in points)
        gap = next(((a, b) for a, b in zip(xs, xs[1:]) if a < x < b), None)
        limit = (f"no balanced jump{on} of the {character} lands within {reach * 100:.0f} cm of {x:.2f} m forward"
                 + (f" (measured landings go from {gap[0]:.2f} to {gap[1]:.2f} m)" if gap
                    else f" (measured landings: {xs[0]:.2f}-{xs[-1]:.2f} m)"))
    elif not timed:
        limit = (f"air_time at {x:.2f} m forward{on} is offered only in "
                 f"{intervals([(max(h['air_time'] - window, 0.0), h['air_time'] + window) for h in here])} s")
    else:
        spans = [(h["landing"][1] - math.sqrt(max(reach ** 2 - (h["landing"][0] - x) ** 2, 0.0)),
                  h["landing"][1] + math.sqrt(max(reach ** 2 - (h["landing"][0] - x) ** 2, 0.0))) for h in timed]
        limit = f"target_y at {x:.2f} m forward in {air_time:g} s is offered only in {intervals(spans)} m"
    m = nearest["measured"]
    where = f"({x:g}, {y:g})" if not z else f"({x:g}, {y:g}, {z:g})"
    return (f"target {where} m in air_time={air_time:g} s is outside the region the {character}'s measured "
            f"jumps offer: {limit}; the nearest balanced one lands at ({m['landing'][0]:.2f}, "
            f"{m['landing'][1]:+.2f}) m in {m['air_time']:.2f} s")


def intervals(spans) -> str:
    """Overlapping (low, high) spans merged, as 'a-b, c-d'."""
    merged = []
    for lo, hi in sorted(spans):
        if merged and lo <= merged[-1][1]:
            merged[-1] = (merged[-1][0], max(merged[-1][1], hi))
        else:
            merged.append((lo, hi))
    return ", ".join(f"{lo:.2f}-{hi:.2f}" for lo, hi in merged)
