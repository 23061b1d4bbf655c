"""The commanded take-off's table (issue 29): where a character's jump to a target is flown by the
commanded take-off (control/commanded_thrust.py) and with which settings.

A character with a table ``jump_commanded_<character>.json`` (the woman's; the man's commanded
flights land pitched forward and fall, docs/jump_to_target.md) holds:

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
  refused naming both limits.

``jump_commanded_any.json`` holds the planner's constants (the aim's bound and tolerances, the
landing plan's bound). The leap's ``commanded_*`` constants are the character's own in its leap
table's "constants" (control.leap.leap_constants). Only reads the tables: the planning is planning's.
"""
from __future__ import annotations

import numpy as np

from ...control.leap import LEAP_SETTINGS
from ...schema import Schema
from ...tuned import TableType, load_fresh, register as register_table
from ...tuned.constants import constant, constant_rows, read_constants, with_constants

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
    constant("landing_trials", "count", 1, 30,
             "an aimed jump that lands on the target and falls is tried again with its feet placed a landing plan "
             "step (planning/land.py) more and less, two, ...: this many placements in all, its own the first"),
)
CONSTANTS = read_constants("jump_commanded", COMMANDED_CONSTANTS)


def _rows(body: dict):
    if "settings" in body:
        yield "settings", body["settings"]
    for k, height in enumerate(body.get("crouch_by_air_time", {}).get("crouch_height", [])):
        yield f"crouch_by_air_time {k}", {"crouch_height": height}
    yield from constant_rows(body)


def commanded_settings(body: dict, air_time: float, aim: float) -> dict:
    """The settings of a commanded jump aimed at ``aim`` m forward with the crouch of ``air_time`` s:
    the table's ``settings`` with the commanded take-off on, ``flight_target_x`` the aim and the crouch
    height interpolated in ``crouch_by_air_time`` (held beyond its ends)."""
    pairs = body["crouch_by_air_time"]
    return {**body["settings"], "commanded_takeoff": 1.0, "flight_target_x": float(aim),
            "crouch_height": float(np.interp(air_time, pairs["air_time"], pairs["crouch_height"]))}


JUMP_COMMANDED_TABLE = register_table(TableType("jump_commanded", with_constants(LEAP_SETTINGS, COMMANDED_CONSTANTS),
                                                _rows, (commanded_settings,)))


def table(character: str) -> dict | None:
    """The character's commanded take-off table (None: not offered for it); read again when the file changes."""
    return load_fresh("jump_commanded", character)


def commanded_offers(character: str, target, air_time: float) -> bool:
    """Whether the request (x, y[, z], air time) on flat ground lies in the character's measured
    commanded region (the table's ``region``, bounds included)."""
    body = table(character)
    if body is None or (len(target) > 2 and float(target[2])):
        return False
    region = body["region"]
    values = {"target_x": float(target[0]), "target_y": float(target[1]), "air_time": float(air_time)}
    return all(region[k][0] <= v <= region[k][1] for k, v in values.items())


def commanded_limit(character: str) -> str | None:
    """The commanded region's limits in words (None: the character has none)."""
    body = table(character)
    if body is None:
        return None
    r = body["region"]
    return (f"the commanded take-off is offered on flat ground for target_x {r['target_x'][0]:g}-{r['target_x'][1]:g} m, "
            f"target_y {r['target_y'][0]:g}-{r['target_y'][1]:g} m, air_time {r['air_time'][0]:g}-{r['air_time'][1]:g} s")
