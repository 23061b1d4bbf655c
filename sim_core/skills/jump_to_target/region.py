"""The region of jump targets a character is offered (issue 29), from its measured jumps.

The measured jumps are the jump_model table (sim_core/tuned/tables/jump_model_<character>.json,
written by ``python -m sim_core.planning.jump_model``): the leap's settings of every calibrated
broad jump and stored straight-ahead plan and of nudges of them, each with where it landed the
middle of the feet, its air time and whether it ended balanced, and the height of the surface it
was measured landing on (``surface``: a box top above the start, or the ground below a box it
started on; no entry = flat ground). A request (x, y[, z], air time) is offered where a measured
balanced jump does it within ``REACH`` of TARGETS.md's tolerances (``request_distance``; a box
request by a jump measured for a surface within HEIGHT_REACH of its height, its landing moved there
ballistically, ``at_height``); anything else is refused before simulating, in one line naming the
limit (``region_refusal``). Only reads the table: the measuring is planning's.
"""
from __future__ import annotations

import math

import numpy as np

from ...control.leap import LEAP_SETTINGS
from ...tuned import TableType, load, register as register_table, table_path

LANDING_TOLERANCE = 0.05            # m: TARGETS.md: the landing point within this of the target
AIR_TIME_TOLERANCE = 0.05           # s: TARGETS.md: the air time within this of the one asked
REACH = 1.0             # tolerances: a request is offered where a measured balanced jump is this near
                        # (request_distance): replayed, the same settings land the same (one simulation)
HEIGHT_REACH = 0.025    # m: a box request is served by jumps measured for a surface this near its height
                        # (half the step between the measured heights, jump_model.BOX_HEIGHTS); the man's
                        # 0.5 m box plan run onto 0.4 m landed balanced, onto 0.55 m fell
GRAVITY = 9.81


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
    for a request at a height (target z), of the jump moved to that height (at_height) and the
    height miss / HEIGHT_REACH; infinite for a jump that does not serve that height (serves)."""
    z = height_of(target)
    if not serves(measured, z):
        return math.inf
    moved = at_height(measured, z)
    if moved is None:
        return math.inf
    landing = moved["landing"]
    miss = math.hypot(landing[0] - float(target[0]), landing[1] - float(target[1])) / LANDING_TOLERANCE
    return max(miss, abs(moved["air_time"] - air_time) / AIR_TIME_TOLERANCE,
               abs(surface(measured) - z) / HEIGHT_REACH if z else 0.0)


def balanced(body: dict | None) -> list[dict]:
    return [p for p in (body or {}).get("points", []) if p["measured"]["outcome"] == "success"
            and all(math.isfinite(v) for v in p["measured"]["landing"])]


_LOADED: dict = {}


def model(character: str) -> dict | None:
    """The character's measured jumps (None: not measured); read again when the file changes."""
    path = table_path("jump_model", character)
    stamp = path.stat().st_mtime_ns if path.exists() else None
    if _LOADED.get(character, (None,))[0] != stamp or stamp is None:
        _LOADED[character] = (stamp, load("jump_model", character))
    return _LOADED[character][1]


def nearest_balanced(character: str, target, air_time: float, count: int = 1) -> list[tuple[float, dict]]:
    """The ``count`` measured balanced jumps nearest the request that serve its height, as
    (request_distance, point); a point measured for another surface with its "measured" moved to
    the request's height (at_height) and the measured one as "as_measured"."""
    z = height_of(target)
    ranked = []
    for p in balanced(model(character)):
        d = request_distance(p["measured"], target, air_time)
        if math.isfinite(d):
            moved = at_height(p["measured"], z)
            ranked.append((d, p if moved is p["measured"] else {**p, "measured": moved, "as_measured": p["measured"]}))
    ranked.sort(key=lambda e: e[0])
    return ranked[:count]


def offered(character: str, target, air_time: float) -> bool:
    """Whether a measured balanced jump does the request within REACH tolerances (request_distance)."""
    body = model(character)
    stamp = _LOADED[character][0]
    if stamp is None or stamp != _ARRAYS.get(character, (None,))[0]:
        rows = [(*p["measured"]["landing"], p["measured"]["air_time"], surface(p["measured"])) for p in balanced(body)]
        _ARRAYS[character] = (stamp, np.asarray(rows, dtype=float).reshape(-1, 4))
    points = _ARRAYS[character][1]
    z = height_of(target)
    if z:
        near = (points[:, 3] != 0.0) & (np.abs(points[:, 3] - z) <= HEIGHT_REACH + 1e-9)
        if not near.any():
            return False
        return any(request_distance({"landing": list(r[:2]), "air_time": r[2], "surface": r[3]}, target, air_time) <= REACH
                   for r in points[near])
    points = points[points[:, 3] == 0.0]
    if not len(points):
        return False
    miss = np.hypot(points[:, 0] - float(target[0]), points[:, 1] - float(target[1])) / LANDING_TOLERANCE
    return bool(np.maximum(miss, np.abs(points[:, 2] - air_time) / AIR_TIME_TOLERANCE).min() <= REACH)


_ARRAYS: dict = {}


def region_refusal(character: str, target, air_time: float) -> str | None:
    """None if the request (x, y, air time) is in the region offered, else the one-line refusal
    naming the limit it breaks: the forward distances measured (no balanced jump lands near x), the
    air times offered at x, or the lateral offsets offered at x in that air time; and the nearest
    measured balanced jump."""
    z = height_of(target)
    every = balanced(model(character))
    if not any((surface(p["measured"]) != 0.0) == (z != 0.0) for p in every):
        return None         # not measured (python -m sim_core.planning.jump_model): the planner searches
    x, y = float(target[0]), float(target[1])
    on = "" if not z else (f" onto a {z:g} m box" if z > 0 else f" down from a {-z:g} m box")
    points = [{**p, "measured": at_height(p["measured"], z)} for p in every if serves(p["measured"], z)]
    points = [p for p in points if p["measured"] is not None]
    if not points:
        heights = sorted({round(surface(p["measured"]), 3) for p in every if surface(p["measured"]) * z > 0})
        return (f"target ({x:g}, {y:g}, {z:g}) m is outside the region the {character}'s measured jumps offer: "
                f"no balanced jump{on} was measured for a surface within {HEIGHT_REACH * 100:.1f} cm of {z:g} m "
                f"(measured {'onto' if z > 0 else 'down from'}: {', '.join(f'{abs(h):g}' for h in heights) or 'none'} m)")
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
