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
- ``sideways_<row>_region`` (optional, with ``quarter_lines``; "sideways_<row>" one of SIDEWAYS_WAYS): the same keys;
  straight to the side beyond ``sideways_region``, flown by the quarter turn and then the row the turned way ``turned_<row>`` flies (way_body: "long" turned_long_body, "near_long" near_long_body, ...), its
  turn and aim steered by the quarter lines as flown (planning/commanded.py steer_by_lines); ``sideways_<row>_settings``
  (optional) replace the row's settings for it (the man's near long row: the landing's arms without their pitch
  feedback, whose deeper landings after the quarter turn fell at every placement, docs/jump_to_target.md);
  a turned region may hold one side only (optional ``side`` [1, 1]: to the left, [-1, -1]: to the right; the target's
  sign of target_y); ``sideways_<row>_lines`` (optional, the columns of ``quarter_lines``): the quarter turns measured
  with that row's own jump after them (planning/turn_map.py quarter_line's ``way``), steering it in place of
  ``quarter_lines`` (quarter_lines_of: after some turns the row's landing falls where the short row's stood);
- ``turn_lines`` (optional, with ``turned_region``): the same for the hop's ``turn_angle`` (columns ``turn_angle``,
  ``heading``, ``feet_x``, ``feet_y``, ``line``, ``stood``): each hop of ``turn_headings`` turned up to ~40 deg (the woman's: ~55 deg) and two
  commanded jumps along its heading after it (planning/turn_map.py hop_line: ``line`` through the middle of their
  landings, ``stood`` the share balanced); where it is, a turned plan flies the hop whose line passes nearest the
  target (turn_for_point), not the one whose heading is nearest its bearing;
- ``long_region`` (optional, with ``long_settings`` and ``long_crouch_by_air_time``): the same keys as ``region``
  for long air times on flat ground, flown with the leap's vertical thrust (``long_settings``: its faster
  extension, ``vertical_thrust`` 1, and the landing's recovery step) instead of the broad jump's - the broad
  thrust's deepest crouch flies ~0.5 s, the vertical one's 0.72 s (docs/jump_to_target.md, "Long air times");
  ``long_crouch_by_air_time`` its crouch pairs (long_body); a request there outside ``region`` is planned so;
- ``turned_long_region`` (optional, with the long row and ``turned_region``): the same keys as ``turned_region`` for
  long air times: the hop first (chosen as the turned plan's, by ``turn_lines``), then the long row (long_body)
  forward along the new heading; a request in it beyond ``region``'s target_y is planned so; ``turned_long_settings``
  (optional) replace the long row's settings for it (turned_long_body: the man's landing arms without their pitch
  feedback, whose hands touched the ground in the deep landings after the hop);
- ``turned_long_short_region`` (optional, with the long row and ``turned_region``): the same keys as ``turned_region`` for
  shorter air times than ``turned_long_region``'s, flown as it (the hop, then turned_long_body): the long row's shallow
  crouches far ahead fly 0.42-0.52 s, where the broad thrust's forward speed ends (docs/jump_to_target.md, "The woman's
  long row at short air times"); a request in it beyond ``region``'s target_y is planned so;
- ``turned_near_long_region`` (optional, with the near long row and ``turned_region``): the same keys for long air
  times nearer, the hop first, then the near long row as it is (near_long_body; the near row's landing kept its arms'
  pitch feedback: without it more fell); a request in it beyond ``region``'s target_y is planned so;
- ``down_region`` (optional, with ``down_settings``): a jump straight ahead down from a box ``height`` m high
  ([low, high]) is flown by the same take-off where the flight of its lift-off velocity on flat ground lands in
  ``region`` with an air time in ``flat_air_time`` ([low, high] s) (flat_equivalent: the vertical speed's air
  time on flat ground, ballistics.flat_air_time, and the forward speed over it; the crouch is chosen by that
  air time); ``down_settings`` replace the table's settings for it and for every other way down from a box
  (commanded_settings: the woman's landing's recovery step, the drop lands harder; the man's landing for a drop, the
  forefoot first at any forward speed and the landing table's delta for the drop, control.leap.Landing's
  ``toe_first_at_speed`` and ``delta_from_drop``).
- ``high_down_region`` (optional, with ``down_region``): the same keys as ``down_region`` and ``target_x`` ([low, high] m,
  the target's own forward distance) for higher boxes, flown as ``down_region``'s: from a higher box a far target's
  landing (faster forward with a harder drop) fell at every foot placement while a nearer one's stood
  (docs/jump_to_target.md, "The man down from higher boxes");
- ``near_long_region`` (optional, with ``long_settings``, ``near_long_settings`` and ``near_long_crouch_by_air_time``):
  a second long row for long air times nearer than ``long_region`` (the same keys), flown with ``long_settings`` and
  ``near_long_settings`` over them (its own lean push, ``lean_push``: the man's long row leaves at ~1.3 m/s forward
  whatever is aimed nearer, a larger push starts the thrust earlier in the lean, docs/jump_to_target.md) and its own
  crouch pairs (near_long_body); a request there outside ``region`` and ``long_region`` is planned so;
- ``turned_mid_long_region`` (optional, with ``long_settings``, ``mid_long_settings``, ``mid_long_crouch_by_air_time`` and
  ``turned_region``): the same keys as ``turned_region``, between the turned near and far long rows: the hop first, then a
  third long row with its own lean push and crouch pairs (mid_long_body: the man's push 5, between the far row's 3 and the
  near row's 10, lands ~1.2-1.5 m); a request in it beyond ``region``'s target_y is planned so (straight ahead the row
  was not offered: docs/jump_to_target.md, "The man's mid long row");
- ``turned_far_long_region`` (optional, with ``long_settings``, ``far_long_settings``, ``far_long_crouch_by_air_time`` and
  ``turned_region``): the same keys as ``turned_region``, beyond the turned long row's distance: the hop first, then a long
  row with its own smaller lean push and crouch pairs (far_long_body: the woman's push 2, her long row's 3 ends at ~1.5 m
  at long air times, the smaller push leaves faster forward and lands ~1.6-1.75 m); a request in it beyond ``region``'s
  target_y is planned so (docs/jump_to_target.md, "The woman's far long row");
- ``low_down_regions`` (optional, with ``low_down_crouch_by_air_time``): boxes with the keys of ``high_down_region``
  (``height``, ``flat_air_time``, ``target_x``) for a jump straight ahead down from a box whose lift-off flies lower
  than ``region``'s air times on flat ground (T0 below them), bounded by the target's own forward distance alone (the
  flat equivalent of a low lift-off lands nearer than any flat target measured): flown as ``down_region``'s (the
  table's settings with its ``down_settings``) with ``low_down_crouch_by_air_time`` as the crouch pairs
  (low_down_body: the table's pairs and a shallower crouch's, whose lift-off flies ~0.3 s on flat ground; a shallower
  one still leaves as fast up, docs/jump_to_target.md "Down from a box with a shallow crouch");
- ``push_down_regions`` (optional, with ``push_down_settings`` and ``push_down_crouch_by_air_time``): boxes with the keys
  of ``low_down_regions`` and ``target_speed`` ([low, high] m/s, the target's forward distance over its air time: the
  lift-off's forward speed) for a jump straight ahead down from a box with a lift-off lower still (T0 below the
  shallowest crouch's), flown as ``low_down_regions``' with ``push_down_settings`` over the table's settings (the man's
  lean push 10: the thrust starts earlier in the lean, the body does not pitch off the box's edge) and
  ``push_down_crouch_by_air_time`` as the crouch pairs (push_down_body); bounded by the forward speed, where the landing
  after the drop stood (docs/jump_to_target.md "Down from a box with a lower lift-off still"); checked after every
  other way down, a box may also ask T0 within the shallow crouch's where that row's aims ran short (the man's targets at
  2.2-2.6 m/s, T0 0.3-0.44 s: docs/jump_to_target.md "The man down from a box far ahead");
- ``<row>_down_regions`` (optional, a straight row of STRAIGHT_WAYS): boxes with the keys of ``push_down_regions``
  (``height``, ``flat_air_time``, ``target_speed``) for a jump straight ahead down from a box flown by that row
  (way "<row>_down", way_body, with its ``<row>_down_settings`` if any, as ``<row>_down_region``'s) where the flat
  equivalent lands nearer than the row's own region (the drop adds the forward distance): bounded by the box's own
  bounds alone, checked after every other way down (the man's far short row, the long row at its shallowest crouches,
  leaves at ~2.9-3.6 m/s forward: docs/jump_to_target.md "The man down from a box far ahead");
- ``deep_long_region``, ``turned_deep_long_region`` (optional, with the long row and ``deep_long_crouch_by_air_time``):
  the same keys as ``long_region`` / ``turned_region`` for the longest air times, flown by the long row as it is (and,
  turned, with ``turned_long_settings``) at its deepest crouches, ``deep_long_crouch_by_air_time`` (deep_long_body): the
  man's far row at a 0.5 m crouch flies 0.65-0.7 s and lands up to ~1.75 m as aimed (nearer than ~1.45 m its landing
  per aimed m is flat and rough), beyond his other rows' deepest crouches (docs/jump_to_target.md, "The man's deep long
  row"); a request there outside the rows above is planned so;
- ``far_short_region``, ``turned_far_short_region`` (optional, with the long row and ``far_short_crouch_by_air_time``) and
  ``near_short_region``, ``turned_near_short_region`` (optional, with the near long row and ``near_short_crouch_by_air_time``):
  the same keys as ``long_region`` / ``turned_region`` for short air times far ahead, flown by the long row or the near
  long row as they are (after the hop too) at their shallowest crouches, each row's own
  ``*_short_crouch_by_air_time`` (short_body): the man's straight row leaves at most ~2.1 m/s forward, his far and near
  long rows at 0.62-0.76 m crouches fly 0.4-0.52 s and land ~1.6-2.2 m and ~1.0-1.6 m (docs/jump_to_target.md, "The man's
  long rows at short air times"); a request there outside the rows above is planned so;
- ``near_deep_long_region``, ``turned_near_deep_long_region`` (optional, with the near long row and
  ``near_deep_long_crouch_by_air_time``): the same keys as ``long_region`` / ``turned_region`` for the longest air times
  nearer, flown by the near long row as it is (its lean push) at its deepest crouches, ``near_deep_long_crouch_by_air_time``
  (near_deep_long_body): the man's near row at a 0.5 m crouch flies 0.65-0.72 s and lands 0.35-0.9 m as aimed, balanced,
  where his far row's landing does not follow its aim (docs/jump_to_target.md, "The man's near deep long row"); a request
  there outside the rows above is planned so;
- ``mid_deep_long_region``, ``turned_mid_deep_long_region`` (optional, with the long row, ``mid_deep_long_settings`` and
  ``mid_deep_long_crouch_by_air_time``): the same keys for the longest air times between the near deep and the deep
  rows, flown by the long row with its own lean push (``mid_deep_long_settings`` over ``long_settings``) at its deepest
  crouches (mid_deep_long_body): the man's push 4 at a 0.5 m crouch lands 1.0-1.45 m in 0.65-0.7 s, all balanced
  (docs/jump_to_target.md, "The man's near deep long row"); a request there outside the rows above is planned so;
- ``long_onto_region``, ``long_down_region`` (optional, with the long row): the same keys as ``down_region`` for a
  jump straight ahead onto a box / down from one flown by the long row (long_body) where the flight's flat
  equivalent lies in ``long_region`` with its air time in ``flat_air_time``; ``target_x`` (optional, [low, high] m)
  bounds the target's own forward distance (onto a box: a nearer box's front edge, 0.3 m before the target, is
  not cleared); ``flat_target_x`` (optional, [low, high] m) bounds the flat equivalent's landing within the row's
  region (the man's far long row onto a box missed where it lands nearer than 1.6 m on flat ground);
  ``target_air_time`` (optional, [low, high] s) bounds the target's own air time (the man's far row onto a box missed
  its aim at the shortest air times, the fastest forward). Onto a box needs
  T0 = T + 2 h / (g T) >= 0.53 s: only the long row flies it; ``<row>_onto_region``, ``<row>_down_region`` (optional)
  the same for any other straight row (``<row>_region``, STRAIGHT_WAYS), flown by that row (way_body); with
  ``<row>_onto_settings`` / ``<row>_down_settings`` (optional) over that row's settings onto / down from a box (the man's deep rows: the arms held back in
  their deepest crouches, whose hands touched the box before the lift-off; docs/jump_to_target.md "The man onto boxes by
  his near and deep long rows");
- ``<row>_high_onto_region`` (optional, the keys of ``long_onto_region``, with ``<row>_high_onto_settings`` and
  ``<row>_high_onto_crouch_by_air_time``): onto a box with a higher lift-off than the straight row ``<row>`` flies on
  flat ground (T0 beyond its region's air times): the flat equivalent's landing in that row's region (target_x,
  target_y), T0 in the box's own ``flat_air_time``, flown by that row with ``<row>_high_onto_settings`` over it and its
  own crouch pairs (way_body: the man's deep rows with the thrust's damping lowered and the arms' swing smaller, whose
  hands touched a high box's edge in the take-off; docs/jump_to_target.md "The man onto higher boxes"); ``<row>`` may
  also be "tucked" (HIGH_ONTO_ROWS: the tucked row, tucked_onto_body, its landings in the long row's region; the woman's
  near boxes at a shallower crouch, docs/jump_to_target.md "The woman onto near boxes"), or "shallow_long" (the long row
  as "long" flies it, a second box over its own pairs: the woman's long row at a 0.5 m crouch below her deepest crouch's
  lift-off, docs/jump_to_target.md "The woman onto boxes between her long row's onto rows"); ``target_speed`` (optional,
  [low, high] m/s) bounds the target's forward speed x / air_time;
- ``tucked_onto_region`` (optional, with the long row and ``tucked_onto_settings``): the keys of ``long_onto_region`` for a
  box nearer than it, flown by the long row with ``tucked_onto_settings`` over its settings (tucked_onto_body: the arms held
  back in the crouch, ``crouch_arms``: leaning on to a box whose front edge is ~0.4 m ahead of the feet, the hands
  touched it before the lift-off and the jump fell back; and the knees tucked in flight, ``landing_tuck_knee_flexion``
  for ``landing_tuck_share`` of the air time: the toes caught the box's front edge on the way up; docs/jump_to_target.md
  "Onto a box: the take-off's limit, and a near box tucked").

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
    constant("landing_leads", "s", -0.2, 0.2,
             "where every placement fell, the same jump with its landing_foot_lead_time moved by each of these in turn "
             "(none: no more), one jump each beyond the placements"),
    constant("landing_aims", "count", 0, 5,
             "where no jump has landed balanced on the target after the placements and leads, the balanced one nearest "
             "it flown again with its flight target moved by its miss (forward and to the side): at most this many "
             "jumps (0: none)"),
)
CONSTANTS = read_constants("jump_commanded", COMMANDED_CONSTANTS)


def planner_constants(character: str):
    """The planner's constants for ``character``: jump_commanded_any's, each one the character's own table's
    "constants" section holds replaced (the man's aim needs more jumps than the woman's)."""
    return own_constants("jump_commanded", character, CONSTANTS)


def _rows(body: dict):
    """The table's rows of leap settings as the schema checks them: every ``*settings`` section (a row's settings over
    the table's own) and each crouch height of every ``*crouch_by_air_time`` pairs, then the turn maps and constants."""
    for key, section in body.items():
        if key.endswith("settings"):
            yield key, section
    for key, pairs in body.items():
        if key.endswith("crouch_by_air_time"):
            for k, height in enumerate(pairs.get("crouch_height", [])):
                yield f"{key} {k}", {"crouch_height": height,
                                     **({"thrust_damping": pairs["thrust_damping"][k]}
                                        if pairs.get("thrust_damping", [None] * (k + 1))[k] is not None else {})}
    for k, angle in enumerate(body.get("turn_headings", {}).get("turn_angle", [])):
        yield f"turn_headings {k}", {"turn_angle": angle}
    for key in (k for k in body if k == "quarter_lines" or (k.startswith("sideways_") and k.endswith("_lines"))):
        for k, scale in enumerate(body[key].get("turn_first", [])):
            yield f"{key} {k}", {"turn_first": scale}
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


def quarter_lines_of(body: dict, way: str) -> str:
    """The table's quarter map a sideways ``way`` steers by: its own ``<way>_lines`` where the table has them, else
    ``quarter_lines`` (the quarter turns measured with the short row's jump after them)."""
    return f"{way}_lines" if f"{way}_lines" in body else "quarter_lines"


def _turn_column(rows: dict) -> str:
    """A map's turn column: ``turn_first`` (a quarter map) or ``turn_angle`` (the hop's ``turn_lines``)."""
    return "turn_first" if "turn_first" in rows else "turn_angle"


def turn_for_point(body: dict, point, avoid=(), lines: str = "quarter_lines", errors: dict | None = None,
                   error: float = 0.0) -> float:
    """The turn of the table's ``lines`` (``quarter_lines``: the quarter turn's ``turn_first``; ``turn_lines``: the
    hop's ``turn_angle``) whose measured jump's line (from the feet the turn left, along ``line``) passes nearest
    ``point`` (x, y m) ahead of them, of those that stood (``stood`` above half) and are not in ``avoid``. As the
    hop's heading, the turn's is not smooth in its setting but the same every run. ``errors``: for turns already
    flown, how far to the left of its line (line_offset) the turn's jump landed; the line of every other turn is taken
    ``error`` to the left of the measured one (none: the lines as measured)."""
    rows = body[lines]
    best, chosen = math.inf, None
    for turn in rows[_turn_column(rows)]:
        along, off, stood = line_offset(body, turn, point, lines)
        miss = off - (errors or {}).get(float(turn), error)
        if stood > 0.5 and turn not in avoid and along > 0.0 and abs(miss) < best:
            best, chosen = abs(miss), float(turn)
    return chosen


def line_offset(body: dict, turn: float, point, lines: str = "turn_lines") -> tuple[float, float, float]:
    """Where ``point`` (x, y m) lies from the measured line of ``turn`` in the table's ``lines`` (turn_for_point):
    (along it from the feet the turn left, to its left, m) and the share of its measured jumps that stood."""
    rows = body[lines]
    k = list(rows[_turn_column(rows)]).index(turn)
    dx, dy = float(point[0]) - rows["feet_x"][k], float(point[1]) - rows["feet_y"][k]
    line = rows["line"][k]
    return (dx * math.cos(line) + dy * math.sin(line), -dx * math.sin(line) + dy * math.cos(line), rows["stood"][k])


def commanded_settings(body: dict, air_time: float, aim: float, height: float = 0.0) -> dict:
    """The settings of a commanded jump aimed at ``aim`` m forward with the crouch of ``air_time`` s
    (its flat-ground air time): the table's ``settings`` (down a box, ``height`` < 0, with its
    ``down_settings``) with the commanded take-off on, ``flight_target_x`` the aim and the crouch height
    interpolated in ``crouch_by_air_time`` (held beyond its ends; and the thrust's damping where the pairs have a
    ``thrust_damping`` column: a higher lift-off from the same crouch; a null in it is the settings' own)."""
    pairs = body["crouch_by_air_time"]
    settings = {**body["settings"], **(body.get("down_settings", {}) if height < 0.0 else {})}
    column = lambda key: [settings[key] if value is None else value for value in pairs[key]]     # noqa: E731
    return {**settings, "commanded_takeoff": 1.0, "flight_target_x": float(aim),
            **{key: float(np.interp(air_time, pairs["air_time"], column(key)))       # the pairs' columns but the air time
               for key in ("crouch_height", "thrust_damping") if key in pairs}}


def over(under: dict, body: dict, settings: str | None = None, pairs: str | None = None) -> dict:
    """A row of the table ``body`` as its plan reads it: the table ``under`` (the row it stands on: the table itself, or
    another row) with ``body``'s ``settings`` section over its settings and ``body``'s ``pairs`` as its crouch pairs
    (commanded_settings); each optional (None, or a section the table lacks: ``under``'s kept)."""
    return {**under, **({"settings": {**under["settings"], **body[settings]}} if settings in body else {}),
            **({"crouch_by_air_time": body[pairs]} if pairs in body else {})}


def long_body(body: dict) -> dict:
    """The table as the long air times' plan reads it (``long_region``): its ``settings`` with ``long_settings``
    over them and ``long_crouch_by_air_time`` as the crouch pairs (commanded_settings)."""
    return over(body, body, "long_settings", "long_crouch_by_air_time")


def near_long_body(body: dict, row: str = "near_long") -> dict:
    """The table as the near long air times' plan reads it (``near_long_region``): long_body with
    ``near_long_settings`` over its settings and ``near_long_crouch_by_air_time`` as the crouch pairs
    (``row`` "mid_long": the mid long row's ``mid_long_settings`` and ``mid_long_crouch_by_air_time``)."""
    return over(long_body(body), body, f"{row}_settings", f"{row}_crouch_by_air_time")


def mid_long_body(body: dict) -> dict:
    """The table as the turned mid long air times' plan reads it (``turned_mid_long_region``): near_long_body of the
    mid row."""
    return near_long_body(body, "mid_long")


def far_long_body(body: dict) -> dict:
    """The table as the turned far long air times' plan reads it (``turned_far_long_region``): near_long_body of the far
    row (``far_long_settings``, ``far_long_crouch_by_air_time``)."""
    return near_long_body(body, "far_long")


def low_down_body(body: dict) -> dict:
    """The table as a low lift-off's plan down from a box reads it (``low_down_regions``): its
    ``low_down_crouch_by_air_time`` as the crouch pairs."""
    return over(body, body, pairs="low_down_crouch_by_air_time")


def push_down_body(body: dict) -> dict:
    """The table as a lower lift-off's plan down from a box reads it (``push_down_regions``): ``push_down_settings`` over
    its settings and ``push_down_crouch_by_air_time`` as the crouch pairs."""
    return over(body, body, "push_down_settings", "push_down_crouch_by_air_time")


def turned_long_body(body: dict) -> dict:
    """The table as the turned long air times' plan reads it (``turned_long_region``): long_body with
    ``turned_long_settings`` (where the table has them) over its settings."""
    return over(long_body(body), body, "turned_long_settings")


def deep_long_body(body: dict, turned: bool = False) -> dict:
    """The table as the deep long air times' plan reads it (``deep_long_region``; ``turned``: ``turned_deep_long_region``):
    long_body (turned: turned_long_body) with ``deep_long_crouch_by_air_time`` as the crouch pairs."""
    return over(turned_long_body(body) if turned else long_body(body), body, pairs="deep_long_crouch_by_air_time")


def tucked_onto_body(body: dict) -> dict:
    """The table as a near box's plan reads it (``tucked_onto_region``): long_body with ``tucked_onto_settings`` over its
    settings."""
    return over(long_body(body), body, "tucked_onto_settings")


def short_body(body: dict, row: str) -> dict:
    """The table as a short air times' plan far ahead reads it, straight or after the hop (``row`` "far_short":
    ``far_short_region`` and ``turned_far_short_region``, long_body - after the hop too: the landing arms' pitch feedback
    kept, without it the man fell on the target at 0.42-0.45 s; "near_short": ``near_short_region`` and
    ``turned_near_short_region``, near_long_body) with the row's ``<row>_crouch_by_air_time`` as the crouch pairs."""
    return over(long_body(body) if row == "far_short" else near_long_body(body), body, pairs=f"{row}_crouch_by_air_time")


def near_deep_long_body(body: dict) -> dict:
    """The table as the near deep long air times' plan reads it (``near_deep_long_region``, and after the hop
    ``turned_near_deep_long_region``): near_long_body with ``near_deep_long_crouch_by_air_time`` as the crouch pairs."""
    return over(near_long_body(body), body, pairs="near_deep_long_crouch_by_air_time")


def mid_deep_long_body(body: dict) -> dict:
    """The table as the mid deep long air times' plan reads it (``mid_deep_long_region``, and after the hop
    ``turned_mid_deep_long_region``): near_long_body of the mid deep row (``mid_deep_long_settings``,
    ``mid_deep_long_crouch_by_air_time``)."""
    return near_long_body(body, "mid_deep_long")


STRAIGHT_WAYS = ("long", "near_long", "deep_long", "far_short", "near_short", "near_deep_long",
                 "mid_deep_long")   # commanded_way's ways beyond ``region``, straight ahead
SIDEWAYS_WAYS = ("sideways", "sideways_long", "sideways_long_short", "sideways_near_long", "sideways_mid_long",
                 "sideways_mid_deep_long", "sideways_deep_long", "sideways_near_short", "sideways_far_short")
# the ways straight to the side: the quarter turn, then the table's own row ("sideways") or the row the turned way
# "turned_<row>" flies (way_body)
HIGH_ONTO_ROWS = {**{row: (row, row) for row in STRAIGHT_WAYS}, "tucked": ("tucked_onto", "long"),
                  "shallow_long": ("long", "long")}
# the rows a ``<row>_high_onto_region`` may fly: the way whose table flies it (way_body) and the row whose flat region its
# flat equivalent lands in ("tucked": tucked_onto_body, the long row flying with the arms back and the tuck;
# "shallow_long": the long row again, a second box of it over its own crouch pairs)
TURNED_WAYS = ("turned", "turned_long", "turned_long_short", "turned_near_long", "turned_mid_long", "turned_far_long",
               "turned_deep_long", "turned_far_short", "turned_near_short", "turned_near_deep_long", "turned_mid_deep_long",
               *SIDEWAYS_WAYS)      # the ways commanded_way names that turn first (planning.commanded.plan_turned)


def way_body(body: dict, way: str) -> dict:
    """The table as the plan of a request that commanded_way (or box_way) sends ``way`` reads it: the row that flies it
    ("<row>_high_onto": that row with its ``<way>_settings`` and ``<way>_crouch_by_air_time``; long_body, near_long_body, mid_long_body, far_long_body, low_down_body, push_down_body, turned_long_body, deep_long_body, short_body,
    near_deep_long_body, mid_deep_long_body; straight ahead a row the table lacks flies as the table's own settings), else
    the table as it is."""
    if way.endswith("_high_onto") and way.removesuffix("_high_onto") in HIGH_ONTO_ROWS:
        # onto a box by a straight row (or the tucked row) with a higher lift-off (box_way): that row, its
        # ``<way>_settings`` and crouch pairs
        flown_by, _ = HIGH_ONTO_ROWS[way.removesuffix("_high_onto")]
        return over(way_body(body, flown_by), body, f"{way}_settings", f"{way}_crouch_by_air_time")
    row = way.rsplit("_", 1)[0]
    if way.endswith(("_down", "_onto")) and row in STRAIGHT_WAYS:
        # onto or down from a box by a straight row (box_way): flown by that row, its ``<way>_settings`` over it if any
        return over(way_body(body, row), body, f"{way}_settings")
    if way == "long" and "long_settings" in body:
        return long_body(body)      # long air times (onto or down from a box too): the vertical thrust's settings and pairs
    if way == "tucked_onto":
        return tucked_onto_body(body)  # onto a near box: the long row, the arms back in the crouch, the flight tucked
    if way == "near_long" and "near_long_settings" in body:
        return near_long_body(body)  # long air times nearer: the same with the near row's own lean push and crouch pairs
    if way == "low_down":
        return low_down_body(body)   # a low lift-off down from a box: the crouch pairs with the shallower crouch's
    if way == "push_down":
        return push_down_body(body)  # a lower one still: its own settings (the lean push) and crouch pairs
    if way == "deep_long" and "deep_long_crouch_by_air_time" in body:
        return deep_long_body(body)  # the longest air times: the long row at its deepest crouches
    if way.startswith("sideways_"):     # the quarter turn, then the turned row's row, its ``<way>_settings`` over it if any
        return over(way_body(body, way.replace("sideways", "turned", 1)), body, f"{way}_settings")
    if way in ("turned_long", "turned_long_short"):
        return turned_long_body(body)
    if way == "turned_near_long":
        return near_long_body(body)
    if way == "turned_mid_long":
        return mid_long_body(body)
    if way == "turned_far_long":
        return far_long_body(body)
    if way == "turned_deep_long":
        return deep_long_body(body, turned=True)
    if way in ("far_short", "near_short", "turned_far_short", "turned_near_short"):
        return short_body(body, way.removeprefix("turned_"))      # the long rows at their shallowest crouches
    if way in ("near_deep_long", "turned_near_deep_long") and "near_deep_long_crouch_by_air_time" in body:
        return near_deep_long_body(body)   # the longest air times nearer: the near row at its deepest crouches
    if way in ("mid_deep_long", "turned_mid_deep_long") and "mid_deep_long_settings" in body:
        return mid_deep_long_body(body)    # between them: the long row with its own push at its deepest crouches
    return body


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
            "flight_target_y": float(aim * math.sin(bearing)), "turn_first" if way.startswith("sideways") else "turn_angle": float(turn)}


JUMP_COMMANDED_TABLE = register_table(TableType("jump_commanded", with_constants(LEAP_SETTINGS, COMMANDED_CONSTANTS),
                                                _rows, (commanded_settings,)))


def table(character: str) -> dict | None:
    """The character's commanded take-off table (None: not offered for it); read again when the file changes."""
    return load_fresh("jump_commanded", character)


def commanded_way(character: str, target, air_time: float) -> str | None:
    """How the commanded take-off flies the request (x, y[, z], air time): on flat ground "straight"
    inside the table's ``region`` (bounds included), "long" inside its ``long_region`` beyond it (the
    vertical thrust, long_body), "near_long" inside its ``near_long_region`` beyond both (near_long_body), "turned"
    inside its ``turned_region`` beyond both (a turn first, then forward), "turned_long" inside its
    ``turned_long_region`` (the turn first, then the long row; "turned_long_short" inside its ``turned_long_short_region``),
    "turned_near_long" inside its ``turned_near_long_region``
    (the turn first, then the near long row), "turned_mid_long" inside its ``turned_mid_long_region`` (the turn
    first, then the mid long row), "turned_far_long" inside its ``turned_far_long_region`` (the turn first, then the far
    long row), "turned_deep_long" inside its ``turned_deep_long_region`` (the turn first, then the
    long row at its deepest crouches), "far_short" / "near_short" inside its ``far_short_region`` / ``near_short_region``
    and "turned_far_short" / "turned_near_short" inside its ``turned_far_short_region`` / ``turned_near_short_region`` (the
    long / near long row at its shallowest crouches, short_body), "near_deep_long" / "turned_near_deep_long" inside its
    ``near_deep_long_region`` / ``turned_near_deep_long_region`` (the near long row at its deepest crouches, straight /
    after the hop), "mid_deep_long" / "turned_mid_deep_long" inside its ``mid_deep_long_region`` /
    ``turned_mid_deep_long_region`` (the long row with the mid deep row's push at its deepest crouches), "sideways" inside
    its ``sideways_region`` (the
    quarter turn first), "sideways_<row>" inside its ``sideways_<row>_region`` (the quarter turn, then the turned row's row); down
    from a box (z < 0) or onto one (z > 0) as box_way says; else None."""
    body = table(character)
    z = float(target[2]) if len(target) > 2 else 0.0
    if body is None:
        return None
    if z != 0.0:
        return box_way(body, target, air_time)
    region = body["region"]
    x, y = float(target[0]), float(target[1])
    values = {"target_x": x, "target_y": y, "air_time": float(air_time)}
    if all(region[k][0] <= v <= region[k][1] for k, v in values.items()):
        return "straight"
    straight = next((way for way in STRAIGHT_WAYS if body.get(f"{way}_region") is not None
                     and all(body[f"{way}_region"][k][0] <= v <= body[f"{way}_region"][k][1] for k, v in values.items())), None)
    if straight is not None or region["target_y"][0] <= y <= region["target_y"][1]:
        return straight
    values = {"distance": math.hypot(x, y), "bearing": abs(math.atan2(y, x)), "air_time": float(air_time),
              "side": math.copysign(1.0, y)}
    return next((way for way in TURNED_WAYS if body.get(f"{way}_region") is not None
                 and all(low <= values[k] <= high for k, (low, high) in body[f"{way}_region"].items())), None)


def box_way(body: dict, target, air_time: float) -> str | None:
    """commanded_way for a target onto a box (z > 0) or down from one (z < 0), straight ahead: its flat equivalent
    (flat_equivalent) in the table's ``region`` with the height and T0 in ``down_region`` or (and the target's own
    forward distance) in ``high_down_region``: "down"; the height, T0 and the target's own forward distance in one of
    its ``low_down_regions``: "low_down" (low_down_body); in one of its straight rows' regions (``long_region``, ...,
    STRAIGHT_WAYS) with them in that row's ``<row>_down_region`` / ``<row>_onto_region``: "<row>_down" / "<row>_onto" (flown
    by that row, way_body; e.g. "long_down" / "long_onto", the long row, long_body), in ``tucked_onto_region``:
    "tucked_onto" (tucked_onto_body); onto a box, the flat equivalent's landing in a straight row's region and T0 in its
    ``<row>_high_onto_region``'s own flat_air_time (the height too): "<row>_high_onto" (way_body); down from a box after all those, the height, T0 and the target's forward speed
    (x / air time) in one of its ``push_down_regions``: "push_down" (push_down_body); after those, the same in one of a
    straight row's ``<row>_down_regions``: "<row>_down" (that row, way_body); else None."""
    z, asked = float(target[2]), float(air_time)
    x, air_time = flat_equivalent(target, air_time)
    values = {"target_x": x, "target_y": float(target[1]), "air_time": air_time}
    rows = (("down", "region", body.get("down_region")), ("down", "region", body.get("high_down_region")),
            *(("low_down", None, box) for box in body.get("low_down_regions", ())),
            *((f"{row}_down", f"{row}_region", body.get(f"{row}_down_region")) for row in STRAIGHT_WAYS),
            *(("push_down", None, box) for box in body.get("push_down_regions", ())),
            *((f"{row}_down", None, box) for row in STRAIGHT_WAYS for box in body.get(f"{row}_down_regions", ()))) \
        if z < 0.0 \
        else (*((f"{row}_onto", f"{row}_region", body.get(f"{row}_onto_region")) for row in STRAIGHT_WAYS),
              ("tucked_onto", "long_region", body.get("tucked_onto_region")),
              *((f"{row}_high_onto", f"{HIGH_ONTO_ROWS[row][1]}_region", body.get(f"{row}_high_onto_region"))
                for row in HIGH_ONTO_ROWS))
    def within(box: dict, key: str, value: float) -> bool:       # an optional bound holds when absent
        low, high = box.get(key, (-math.inf, math.inf))
        return low <= value <= high

    for way, region_key, box in rows:
        region = body.get(region_key) if region_key else {}     # a low lift-off: the box's own bounds alone
        if (region is not None and box is not None and within(box, "height", abs(z))
                and within(box, "target_x", float(target[0])) and within(box, "flat_air_time", air_time)
                and within(box, "flat_target_x", x) and within(box, "target_air_time", float(asked))
                and within(box, "target_speed", float(target[0]) / float(asked))
                and all(within(region, k, v) for k, v in values.items()
                        if not (k == "air_time" and way.endswith("_high_onto")))):   # a higher lift-off: T0 its own
            return way
    return None


def commanded_offers(character: str, target, air_time: float) -> bool:
    """Whether the request lies in the character's measured commanded region, straight, long, turned, sideways,
    onto or down from a box (commanded_way)."""
    return commanded_way(character, target, air_time) is not None


def _span(region: dict, key: str, unit: str) -> str:
    """``key low-high unit`` of a region's [low, high]."""
    return f"{key} {region[key][0]:g}-{region[key][1]:g} {unit}"


def _flat(region: dict) -> str:
    """A flat-ground region (target_x, target_y, air_time) in words."""
    return ", ".join(_span(region, key, unit) for key, unit in (("target_x", "m"), ("target_y", "m"), ("air_time", "s")))


def _side(region: dict) -> str:
    """A turned region's ``side`` (the sign of target_y it holds; none: both) in words."""
    low, high = region.get("side", (-1.0, 1.0))
    return "to either side" if low < 0.0 < high else ("to the left" if low > 0.0 else "to the right")


def _turned(region: dict) -> str:
    """A turned region (distance, bearing, air_time) in words."""
    return (f"for a distance of {region['distance'][0]:g}-{region['distance'][1]:g} m at a bearing of "
            f"{math.degrees(region['bearing'][0]):.0f}-{math.degrees(region['bearing'][1]):.0f} deg "
            f"{_side(region)}, "
            + _span(region, "air_time", "s"))


def _box(region: dict, way: str, landing: str, sign: str) -> str:
    """A box region (height, flat_air_time, optional target_x, target_air_time, target_speed and flat_target_x) in words: the same
    lift-off's flat landing in ``landing``."""
    return (f"{way} a box {region['height'][0]:g}-{region['height'][1]:g} m high"
            + (f" at target_x {region['target_x'][0]:g}-{region['target_x'][1]:g} m" if "target_x" in region else "")
            + (f" in air_time {region['target_air_time'][0]:g}-{region['target_air_time'][1]:g} s"
               if "target_air_time" in region else "")
            + (f" at a forward speed of {region['target_speed'][0]:g}-{region['target_speed'][1]:g} m/s (target_x / air_time)"
               if "target_speed" in region else "")
            + f" where the same lift-off on flat ground would land in {landing}"
            + (f" at {region['flat_target_x'][0]:g}-{region['flat_target_x'][1]:g} m" if "flat_target_x" in region else "")
            + " in "
              f"{region['flat_air_time'][0]:g}-{region['flat_air_time'][1]:g} s (T0 = air_time {sign} 2 height / (g air_time)")


def _low_box(box: dict, why: str) -> str:
    """A low lift-off's box down from it (``low_down_regions``, ``push_down_regions``: height, flat_air_time and an
    optional target_x and target_speed) in words, ``why`` in brackets at the end."""
    return (f"down from a box {box['height'][0]:g}-{box['height'][1]:g} m high"
            + (f" at target_x {box['target_x'][0]:g}-{box['target_x'][1]:g} m" if "target_x" in box else "")
            + (f" at a forward speed of {box['target_speed'][0]:g}-{box['target_speed'][1]:g} m/s (target_x / air_time)"
               if "target_speed" in box else "")
            + f" where the lift-off would fly {box['flat_air_time'][0]:g}-{box['flat_air_time'][1]:g} s on flat ground ({why})")


FLAT_REGION_WORDS = (       # commanded_limit's words for each region on flat ground beyond ``region``, in its order
    ("turned_region", "turned first"),
    ("sideways_region", "turned a quarter first"),
    ("sideways_long_region", "turned a quarter first with long air times"),
    ("sideways_long_short_region", "turned a quarter first with the long row at shorter air times"),
    ("sideways_near_long_region", "turned a quarter first with long air times nearer"),
    ("sideways_mid_long_region", "turned a quarter first with long air times in the middle"),
    ("sideways_mid_deep_long_region", "turned a quarter first with the longest air times in the middle"),
    ("sideways_deep_long_region", "turned a quarter first with the longest air times"),
    ("sideways_near_short_region", "turned a quarter first with short air times nearer"),
    ("sideways_far_short_region", "turned a quarter first with short air times far ahead"),
    ("long_region", "for long air times (the leap's vertical thrust) on flat ground for"),
    ("near_long_region", "for long air times nearer (the vertical thrust with its own lean push) for"),
    ("deep_long_region", "for the longest air times (the vertical thrust's deepest crouches) for"),
    ("far_short_region", "for short air times far ahead (the vertical thrust's shallowest crouches) for"),
    ("near_short_region", "for short air times nearer (the same with its own lean push) for"),
    ("near_deep_long_region", "for the longest air times nearer (the near row's deepest crouches) for"),
    ("mid_deep_long_region", "for the longest air times in the middle (the vertical thrust with its own push, deepest crouches) for"),
    ("turned_long_region", "turned first with long air times"),
    ("turned_long_short_region", "turned first with the long row at shorter air times"),
    ("turned_near_long_region", "turned first with long air times nearer"),
    ("turned_mid_long_region", "turned first with long air times in the middle"),
    ("turned_far_long_region", "turned first with long air times beyond the long row (its own smaller lean push)"),
    ("turned_deep_long_region", "turned first with the longest air times"),
    ("turned_far_short_region", "turned first with short air times far ahead"),
    ("turned_near_short_region", "turned first with short air times nearer"),
    ("turned_near_deep_long_region", "turned first with the longest air times nearer"),
    ("turned_mid_deep_long_region", "turned first with the longest air times in the middle"))


def commanded_limit(character: str, z: float = 0.0) -> str | None:
    """The commanded region's limits in words for a target ``z`` m up (0: on flat ground, turned or not; > 0: onto a
    box; < 0: down from one): the flat region (the box regions are read from it) and the regions of that kind alone
    (None: the character has none)."""
    body = table(character)
    if body is None:
        return None
    kind = "flat" if z == 0.0 else ("onto" if z > 0.0 else "down")
    parts = [("flat", f"the commanded take-off is offered on flat ground for {_flat(body['region'])}")]
    for key in ("down_region", "high_down_region"):
        if body.get(key):
            parts.append(("down", _box(body[key], "down from", "that region", "-") + ", at target_x T0 / air_time)"))
    for key, why in (("low_down_regions", "T0 = air_time - 2 height / (g air_time); a lower lift-off than its shallowest "
                                          "crouch's is not flown"),
                     ("push_down_regions", "the lean push's low lift-off; faster forward its landings fell or its aims missed")):
        parts += [("down", _low_box(box, why)) for box in body.get(key, ())]
    parts += [("down", _low_box(box, f"the {row.replace('_', ' ')} row's lift-off, its own forward speed"))
              for row in STRAIGHT_WAYS for box in body.get(f"{row}_down_regions", ())]
    parts += [("flat", f"{words} {(_flat if key.removesuffix('_region') in STRAIGHT_WAYS else _turned)(body[key])}")
              for key, words in FLAT_REGION_WORDS if body.get(key)]
    boxes = (*((f"{row}_onto_region", "onto", "+", row) for row in STRAIGHT_WAYS), ("tucked_onto_region", "onto", "+", "long"),
             *((f"{row}_high_onto_region", "onto", "+", HIGH_ONTO_ROWS[row][1]) for row in HIGH_ONTO_ROWS),
             *((f"{row}_down_region", "down from", "-", row) for row in STRAIGHT_WAYS))
    for key, way, sign, row in boxes:
        if body.get(key):
            landing = "the long air times' region" if row == "long" else f"the {row.replace('_', ' ')} row's region"
            if key.endswith("_high_onto_region"):     # the row's landings, its own (higher) lift-off's air times
                landing = f"the {row.replace('_', ' ')} row's target_x {_span(body[f'{row}_region'], 'target_x', 'm')[9:]} (a higher lift-off)"
            parts.append(("onto" if sign == "+" else "down", _box(body[key], way, landing, sign) + ")"))
    return ", and ".join(text for k, (of, text) in enumerate(parts) if k == 0 or of == kind)
