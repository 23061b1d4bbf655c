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
  a request in it beyond ``region``'s target_y is planned so (planning/commanded.py plan_turned);
- ``sideways_region`` (optional, with ``quarter_lines``): the same keys for targets straight to the side, flown
  by the leap's quarter turn first (``turn_first``: two hops, control/turn.py) and then the commanded take-off
  forward (a single hop to 75-90 deg mostly fell after it, docs/jump_to_target.md); ``quarter_lines`` (columns
  ``turn_first``, ``heading``, ``feet_x``, ``feet_y``, ``line``, ``stood``) is each ``turn_first`` of a fine grid
  measured (planning/turn_map.py quarter_line): where the hops left the feet, and the line a commanded jump from
  there flew along (rad), whether it stood (turn_for_point);
- ``turn_lines`` (optional, with ``turned_region``): the same for the hop's ``turn_angle`` (columns ``turn_angle``,
  ``heading``, ``feet_x``, ``feet_y``, ``line``, ``stood``): each hop of ``turn_headings`` turned up to ~40 deg and two
  commanded jumps along its heading after it (planning/turn_map.py hop_line: ``line`` through the middle of their
  landings, ``stood`` the share balanced); where it is, a turned plan flies the hop whose line passes nearest the
  target (turn_for_point), not the one whose heading is nearest its bearing;
- ``down_region`` (optional, with ``down_settings``): a jump straight ahead down from a box ``height`` m high
  ([low, high]) is flown by the same take-off where the flight of its lift-off velocity on flat ground lands in
  ``region`` with an air time in ``flat_air_time`` ([low, high] s) (flat_equivalent: the vertical speed's air
  time on flat ground, ballistics.flat_air_time, and the forward speed over it; the crouch is chosen by that
  air time); ``down_settings`` replace the table's settings for it (the landing's recovery step: the drop
  lands harder).

``jump_commanded_any.json`` holds the planner's constants (the aim's bound and tolerances, the
landing plan's bound); a character's table may hold its own in a "constants" section
(planner_constants). The leap's ``commanded_*`` constants are the character's own in its leap
table's "constants" (control.leap.leap_constants). Only reads the tables: the planning is planning's.
"""
from __future__ import annotations

import math

import numpy as np

from ...ballistics import flat_air_time
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
    if "down_settings" in body:
        yield "down_settings", body["down_settings"]
    for k, height in enumerate(body.get("crouch_by_air_time", {}).get("crouch_height", [])):
        yield f"crouch_by_air_time {k}", {"crouch_height": height}
    for k, angle in enumerate(body.get("turn_headings", {}).get("turn_angle", [])):
        yield f"turn_headings {k}", {"turn_angle": angle}
    for k, scale in enumerate(body.get("quarter_lines", {}).get("turn_first", [])):
        yield f"quarter_lines {k}", {"turn_first": scale}
    for k, angle in enumerate(body.get("turn_lines", {}).get("turn_angle", [])):
        yield f"turn_lines {k}", {"turn_angle": angle}
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


def turn_for_point(body: dict, point, avoid=(), lines: str = "quarter_lines") -> float:
    """The turn of the table's ``lines`` (``quarter_lines``: the quarter turn's ``turn_first``; ``turn_lines``: the
    hop's ``turn_angle``) whose measured jump's line (from the feet the turn left, along ``line``) passes nearest
    ``point`` (x, y m) ahead of them, of those that stood (``stood`` above half) and are not in ``avoid``. As the
    hop's heading, the turn's is not smooth in its setting but the same every run."""
    rows = body[lines]
    best, chosen = math.inf, None
    for turn, fx, fy, line, stood in zip(rows["turn_first" if lines == "quarter_lines" else "turn_angle"], rows["feet_x"],
                                         rows["feet_y"], rows["line"], rows["stood"]):
        dx, dy = float(point[0]) - fx, float(point[1]) - fy
        along, off = dx * math.cos(line) + dy * math.sin(line), -dx * math.sin(line) + dy * math.cos(line)
        if stood > 0.5 and turn not in avoid and along > 0.0 and abs(off) < best:
            best, chosen = abs(off), float(turn)
    return chosen


def commanded_settings(body: dict, air_time: float, aim: float, height: float = 0.0) -> dict:
    """The settings of a commanded jump aimed at ``aim`` m forward with the crouch of ``air_time`` s
    (its flat-ground air time): the table's ``settings`` (down a box, ``height`` < 0, with its
    ``down_settings``) with the commanded take-off on, ``flight_target_x`` the aim and the crouch height
    interpolated in ``crouch_by_air_time`` (held beyond its ends)."""
    pairs = body["crouch_by_air_time"]
    return {**body["settings"], **(body.get("down_settings", {}) if height < 0.0 else {}), "commanded_takeoff": 1.0,
            "flight_target_x": float(aim),
            "crouch_height": float(np.interp(air_time, pairs["air_time"], pairs["crouch_height"]))}


def flat_equivalent(target, air_time: float) -> tuple[float, float]:
    """The flat-ground flight of a jump's lift-off velocity: a target ``target`` (x, y, z) reached in
    ``air_time`` s leaves at x / T forward and at the vertical speed that lands z m higher (ballistics);
    on flat ground that flies flat_air_time and lands x flat_air_time / T ahead. As (x, air time)."""
    flat_time = flat_air_time(float(target[2]), float(air_time))
    return float(target[0]) * flat_time / float(air_time), flat_time


def turned_settings(body: dict, air_time: float, aim: float, bearing: float, turn: float, way: str = "turned") -> dict:
    """commanded_settings for a turned jump: the flight aimed ``aim`` m from the start's feet along
    ``bearing`` (rad, + to the left), after a turn of ``turn_angle`` ``turn`` rad (``way`` "sideways": the
    quarter turn's ``turn_first`` ``turn``)."""
    return {**commanded_settings(body, air_time, aim * math.cos(bearing)),
            "flight_target_y": float(aim * math.sin(bearing)), "turn_first" if way == "sideways" else "turn_angle": float(turn)}


JUMP_COMMANDED_TABLE = register_table(TableType("jump_commanded", with_constants(LEAP_SETTINGS, COMMANDED_CONSTANTS),
                                                _rows, (commanded_settings,)))


def table(character: str) -> dict | None:
    """The character's commanded take-off table (None: not offered for it); read again when the file changes."""
    return load_fresh("jump_commanded", character)


def commanded_way(character: str, target, air_time: float) -> str | None:
    """How the commanded take-off flies the request (x, y[, z], air time): on flat ground "straight"
    inside the table's ``region`` (bounds included), "turned" inside its ``turned_region`` beyond it
    (a turn first, then forward), "sideways" inside its ``sideways_region`` (the quarter turn first); down
    from a box (z < 0) "down" where its ``down_region`` holds the height and the flight's flat equivalent
    lies in ``region``; else None."""
    body = table(character)
    z = float(target[2]) if len(target) > 2 else 0.0
    if body is None or z > 0.0:
        return None
    region = body["region"]
    x, y = float(target[0]), float(target[1])
    if z < 0.0:
        down = body.get("down_region")
        if down is None or not down["height"][0] <= -z <= down["height"][1]:
            return None
        x, air_time = flat_equivalent((x, y, z), air_time)
        if not down["flat_air_time"][0] <= air_time <= down["flat_air_time"][1]:
            return None
    values = {"target_x": x, "target_y": y, "air_time": float(air_time)}
    if all(region[k][0] <= v <= region[k][1] for k, v in values.items()):
        return "straight" if z == 0.0 else "down"
    if z < 0.0:
        return None
    if region["target_y"][0] <= y <= region["target_y"][1]:
        return None
    values = {"distance": math.hypot(x, y), "bearing": abs(math.atan2(y, x)), "air_time": float(air_time)}
    return next((way for way in ("turned", "sideways") if body.get(f"{way}_region") is not None
                 and all(body[f"{way}_region"][k][0] <= v <= body[f"{way}_region"][k][1] for k, v in values.items())), None)


def commanded_offers(character: str, target, air_time: float) -> bool:
    """Whether the request lies in the character's measured commanded region, straight, turned or sideways (commanded_way)."""
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
    down = body.get("down_region")
    if down:
        limit += (f", and down from a box {down['height'][0]:g}-{down['height'][1]:g} m high where the same lift-off "
                  f"on flat ground would land in that region in {down['flat_air_time'][0]:g}-{down['flat_air_time'][1]:g} s "
                  f"(T0 = air_time - 2 height / (g air_time), at target_x T0 / air_time)")
    sideways = body.get("sideways_region")
    if sideways:
        limit += (f", and turned a quarter first for a distance of {sideways['distance'][0]:g}-{sideways['distance'][1]:g} m at "
                  f"a bearing of {math.degrees(sideways['bearing'][0]):.0f}-{math.degrees(sideways['bearing'][1]):.0f} deg to "
                  f"either side, air_time {sideways['air_time'][0]:g}-{sideways['air_time'][1]:g} s")
    return limit
