"""The commanded take-off's table (issue 29): where a character's jump to a target is flown by the
commanded take-off (control/commanded_thrust.py) and with which settings.

A character with a table ``jump_commanded_<character>.json`` (the woman's; the man's, hers scaled by
Fig. 6 with his thrust slowed for his strength, tools/scale_commanded.py and docs/jump_to_target.md) holds:

- ``settings``: the leap's settings a commanded plan starts from (the crouch's pitch and lean, the
  thrust's, the landing's with the arms' pitch feedback) - its crouch height is replaced by
  ``crouch_by_air_time``;
- ``crouch_by_air_time``: measured pairs (columns ``air_time``, ``crouch_height``) of the crouch that
  flies an air time with this take-off (the crouch sets the vertical speed); a plan's crouch is
  interpolated in them at the air time it aims for;
- ``region``: the box (``target_x``, ``target_y``, ``air_time``, each [low, high]) where random requests
  planned this way were measured to land within TARGETS.md's tolerances and balanced (``measured``
  says how, with the command); a request on flat ground there and outside the measured jumps' region
  (region.py) is planned with the commanded take-off (planning/commanded.py), anything outside both is
  refused naming both limits;
- ``turn_headings`` (with ``turned_region``): the heading (rad) the turn's hop reached for each ``turn_angle``
  of a fine grid (turn_for_heading);
- ``turned_region`` (optional): where a target to the side of the start's line is flown by turning
  first (one hop, the leap's ``turn_angle``, control/turn.py) and then the commanded take-off forward
  along the new heading (``distance`` from the start's feet m, ``bearing`` |atan2(y, x)| rad, ``air_time``
  s, each [low, high]; the commanded flight itself lands on its heading's line, it does not steer sideways);
  a request in it beyond ``region``'s target_y is planned so (planning/commanded.py plan_turned).

``jump_commanded_any.json`` holds the planner's constants (the aim's bound and tolerances, the
landing plan's bound); a character's table may hold its own in a "constants" section
(planner_constants). The leap's ``commanded_*`` constants are the character's own in its leap
table's "constants" (control.leap.leap_constants). Only reads the tables: the planning is planning's.
"""
from __future__ import annotations

import math

import numpy as np

from ...control.leap import LEAP_SETTINGS
from ...schema import Schema
from ...tuned import TableType, load_fresh, register as register_table
from ...tuned.constants import constant, constant_rows, own_constants, read_constants, with_constants

COMMANDED_CONSTANTS = Schema(
    constant("aim_trials", "count", 1, 20,
             "a commanded plan runs at most this many aimed jumps (the commanded landing point and the crouch's air "
             "time moved by a secant after each)"),
    constant("aim_tolerance", "m", 0.0, 0.1, "the aim stops once a jump lands this near the target ..."),
    constant("aim_time_tolerance", "s", 0.0, 0.1, "... and flies this near the air time asked"),
    constant("aim_slope_floor", "1", 0.0, 1.0,
             "a secant slope (landing per commanded m, air time per aimed s) below this is not trusted"),
    constant("aim_slope", "1", 0.05, 2.0, "the landing per commanded m assumed where the secant is not trusted"),
    constant("aim_range", "m", 0.0, 2.5, "the commanded landing point stays in this range (low, high)"),
    constant("turn_aim_trials", "count", 1, 20,
             "a turned commanded plan runs at most this many aimed jumps (after each the aimed distance moved by a "
             "secant on the landing's distance, the heading wanted by the landing's bearing missed: turn_slope)"),
    constant("turn_gain", "1", 0.0, 2.0, "a turned plan's first heading wanted per rad of the target's bearing"),
    constant("turn_slope", "1", 0.05, 2.0,
             "a turned plan moves the heading it wants by the landing's bearing missed over this"),
    constant("landing_trials", "count", 1, 30,
             "an aimed jump that lands on the target and falls is tried again with its feet placed a landing plan "
             "step (planning/land.py) more and less, two, ...: this many placements in all, its own the first"),
)
CONSTANTS = read_constants("jump_commanded", COMMANDED_CONSTANTS)


def planner_constants(character: str):
    """The planner's constants for ``character``: jump_commanded_any's, each one the character's own table's
    "constants" section holds replaced (the man's aim needs more jumps than the woman's)."""
    return own_constants("jump_commanded", character, CONSTANTS)


def _rows(body: dict):
    if "settings" in body:
        yield "settings", body["settings"]
    for k, height in enumerate(body.get("crouch_by_air_time", {}).get("crouch_height", [])):
        yield f"crouch_by_air_time {k}", {"crouch_height": height}
    for k, angle in enumerate(body.get("turn_headings", {}).get("turn_angle", [])):
        yield f"turn_headings {k}", {"turn_angle": angle}
    yield from constant_rows(body)


def turn_for_heading(body: dict, heading: float, avoid=()) -> float:
    """The ``turn_angle`` whose measured hop turned the character nearest ``heading`` (rad, + to the left):
    the table's ``turn_headings`` (columns ``turn_angle``, ``heading``), the heading each turn_angle's hop
    reached at the leap's crouch, measured from the standing start on a fine grid; hops that fell are not
    in it, nor those in ``avoid``. The hop's heading is not smooth in its angle (docs/jump_to_target.md) but
    the same angle turns the same way every run (the start is the same state): the measured map is
    inverted, not fitted."""
    pairs = body["turn_headings"]
    k = int(np.argmin([abs(h - heading) if a not in avoid else math.inf
                       for a, h in zip(pairs["turn_angle"], pairs["heading"])]))
    return float(pairs["turn_angle"][k])


def commanded_settings(body: dict, air_time: float, aim: float) -> dict:
    """The settings of a commanded jump aimed at ``aim`` m forward with the crouch of ``air_time`` s:
    the table's ``settings`` with the commanded take-off on, ``flight_target_x`` the aim and the crouch
    height interpolated in ``crouch_by_air_time`` (held beyond its ends)."""
    pairs = body["crouch_by_air_time"]
    return {**body["settings"], "commanded_takeoff": 1.0, "flight_target_x": float(aim),
            "crouch_height": float(np.interp(air_time, pairs["air_time"], pairs["crouch_height"]))}


def turned_settings(body: dict, air_time: float, aim: float, bearing: float, turn: float) -> dict:
    """commanded_settings for a turned jump: the flight aimed ``aim`` m from the start's feet along
    ``bearing`` (rad, + to the left), after a turn of ``turn_angle`` ``turn`` rad."""
    return {**commanded_settings(body, air_time, aim * math.cos(bearing)),
            "flight_target_y": float(aim * math.sin(bearing)), "turn_angle": float(turn)}


JUMP_COMMANDED_TABLE = register_table(TableType("jump_commanded", with_constants(LEAP_SETTINGS, COMMANDED_CONSTANTS),
                                                _rows, (commanded_settings,)))


def table(character: str) -> dict | None:
    """The character's commanded take-off table (None: not offered for it); read again when the file changes."""
    return load_fresh("jump_commanded", character)


def commanded_way(character: str, target, air_time: float) -> str | None:
    """How the commanded take-off flies the request (x, y[, z], air time) on flat ground: "straight"
    inside the table's ``region`` (bounds included), "turned" inside its ``turned_region`` beyond it
    (a turn first, then forward), None outside both."""
    body = table(character)
    if body is None or (len(target) > 2 and float(target[2])):
        return None
    region = body["region"]
    x, y = float(target[0]), float(target[1])
    values = {"target_x": x, "target_y": y, "air_time": float(air_time)}
    if all(region[k][0] <= v <= region[k][1] for k, v in values.items()):
        return "straight"
    turned = body.get("turned_region")
    if turned is None or region["target_y"][0] <= y <= region["target_y"][1]:
        return None
    values = {"distance": math.hypot(x, y), "bearing": abs(math.atan2(y, x)), "air_time": float(air_time)}
    return "turned" if all(turned[k][0] <= v <= turned[k][1] for k, v in values.items()) else None


def commanded_offers(character: str, target, air_time: float) -> bool:
    """Whether the request lies in the character's measured commanded region, straight or turned (commanded_way)."""
    return commanded_way(character, target, air_time) is not None


def commanded_limit(character: str) -> str | None:
    """The commanded region's limits in words (None: the character has none)."""
    body = table(character)
    if body is None:
        return None
    r, turned = body["region"], body.get("turned_region")
    limit = (f"the commanded take-off is offered on flat ground for target_x {r['target_x'][0]:g}-{r['target_x'][1]:g} m, "
             f"target_y {r['target_y'][0]:g}-{r['target_y'][1]:g} m, air_time {r['air_time'][0]:g}-{r['air_time'][1]:g} s")
    if turned:
        limit += (f", and turned first for a distance of {turned['distance'][0]:g}-{turned['distance'][1]:g} m at a "
                  f"bearing of {math.degrees(turned['bearing'][0]):.0f}-{math.degrees(turned['bearing'][1]):.0f} deg "
                  f"to either side, air_time {turned['air_time'][0]:g}-{turned['air_time'][1]:g} s")
    return limit
