"""The region of jump targets a character is offered (issue 29), from its measured jumps.

The measured jumps are the jump_model table (sim_core/tuned/tables/jump_model_<character>.json,
written by ``python -m sim_core.planning.jump_model``): the leap's settings of every calibrated
broad jump and stored straight-ahead plan and of nudges of them, each with where it landed the
middle of the feet, its air time and whether it ended balanced. A request (x, y, air time) is
offered where a measured balanced jump does it within ``REACH`` of TARGETS.md's tolerances
(``request_distance``); anything else is refused before simulating, in one line naming the limit
(``region_refusal``). Only reads the table: the measuring is planning's.
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


def _model_rows(body: dict):
    for k, point in enumerate(body.get("points", [])):
        yield f"point {k}", point["settings"]


def nearest_point_row(body: dict, target, air_time: float) -> dict | None:
    """The measured balanced jump nearest the request in units of the tolerances (request_distance)."""
    points = balanced(body)
    return min(points, key=lambda p: request_distance(p["measured"], target, air_time)) if points else None


JUMP_MODEL_TABLE = register_table(TableType("jump_model", LEAP_SETTINGS, _model_rows, (nearest_point_row,)))


def request_distance(measured: dict, target, air_time: float) -> float:
    """How far a measured jump is from a request, in units of TARGETS.md's tolerances: the larger of
    the landing-point miss / 5 cm and the air-time miss / 0.05 s (<= 1: the jump does the request)."""
    landing = measured["landing"]
    miss = math.hypot(landing[0] - float(target[0]), landing[1] - float(target[1])) / LANDING_TOLERANCE
    return max(miss, abs(measured["air_time"] - air_time) / AIR_TIME_TOLERANCE)


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
    """The ``count`` measured balanced jumps nearest the request, as (request_distance, point)."""
    points = balanced(model(character))
    ranked = sorted(((request_distance(p["measured"], target, air_time), p) for p in points), key=lambda e: e[0])
    return ranked[:count]


def offered(character: str, target, air_time: float) -> bool:
    """Whether a measured balanced jump does the request within REACH tolerances (request_distance)."""
    body = model(character)
    stamp = _LOADED[character][0]
    if stamp is None or stamp != _ARRAYS.get(character, (None,))[0]:
        rows = [(*p["measured"]["landing"], p["measured"]["air_time"]) for p in balanced(body)]
        _ARRAYS[character] = (stamp, np.asarray(rows, dtype=float).reshape(-1, 3))
    points = _ARRAYS[character][1]
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
    points = balanced(model(character))
    if not points:          # not measured (python -m sim_core.planning.jump_model): the planner searches
        return None
    d, nearest = nearest_balanced(character, target, air_time)[0]
    if d <= REACH:
        return None
    x, y = float(target[0]), float(target[1])
    reach, window = REACH * LANDING_TOLERANCE, REACH * AIR_TIME_TOLERANCE
    here = [p["measured"] for p in points if abs(p["measured"]["landing"][0] - x) <= reach]
    timed = [h for h in here if abs(h["air_time"] - air_time) <= window]
    if not here:
        xs = sorted(p["measured"]["landing"][0] for p in points)
        gap = next(((a, b) for a, b in zip(xs, xs[1:]) if a < x < b), None)
        limit = (f"no balanced jump of the {character} lands within {reach * 100:.0f} cm of {x:.2f} m forward"
                 + (f" (measured landings go from {gap[0]:.2f} to {gap[1]:.2f} m)" if gap
                    else f" (measured landings: {xs[0]:.2f}-{xs[-1]:.2f} m)"))
    elif not timed:
        limit = (f"air_time at {x:.2f} m forward is offered only in "
                 f"{intervals([(max(h['air_time'] - window, 0.0), h['air_time'] + window) for h in here])} s")
    else:
        spans = [(h["landing"][1] - math.sqrt(max(reach ** 2 - (h["landing"][0] - x) ** 2, 0.0)),
                  h["landing"][1] + math.sqrt(max(reach ** 2 - (h["landing"][0] - x) ** 2, 0.0))) for h in timed]
        limit = f"target_y at {x:.2f} m forward in {air_time:g} s is offered only in {intervals(spans)} m"
    m = nearest["measured"]
    return (f"target ({x:g}, {y:g}) m in air_time={air_time:g} s is outside the region the {character}'s measured "
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
