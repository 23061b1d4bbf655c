"""A ride's course: where the bicycle is steered (a path, or a fixed heading), what speed is
commanded when, and what the ground holds (a hill).

Courses (the ``course`` parameter; a ``path`` given replaces the course's path):
  * straight: hold ``heading`` at ``speed``;
  * turn: straight for ``turn_after`` m, an arc of ``turn_radius`` turning by ``turn_angle``;
  * slalom: ``gate_count`` gates ``gate_spacing`` m apart, alternately ``gate_offset`` m left and
    right of the start line (the first to the left), ridden along a sine through their centres that
    leaves and rejoins the line tangentially (``slalom``);
  * speed_steps: ``speed`` until ``step_time``, ``second_speed`` until twice it, then ``third_speed``;
  * hill: ``hill_after`` m of flat, a climb of ``hill_length`` m at ``hill_grade``, ``hill_top`` m
    of flat top and a descent like the climb (the hill is a world prop, sim_core.world.hill), ridden
    along its centre line (a straight path); ``hill_curve`` > 0 rounds its four corners with vertical
    curves of that length (0, the default: the sharp hill);
  * start: the rolling start is at ``start_speed``; the rider pedals up to ``speed``;
  * coast: a freewheel bicycle; from ``coast_after`` s the rider stops pedalling and holds the cranks
    level, steering on, until the speed falls to the table's ``coast_min_speed``, then stops as below;
  * stop: a freewheel bicycle with rim brakes; from ``coast_after`` s the rider brakes to a standstill
    (behaviour.py), offered from the speeds at which the stop was measured to work (min/max_stop_speed).

A course that asks the bicycle to turn harder than ``MAX_LEAN`` of lean at its speed is refused
before anything runs, naming the limit; so is a request outside the limits measured by the random
audit of the panel (the table's min_speed, min_gear, min_cadence, min_fast_gear, max_cadence,
max_hill_grade, max_hill_grade_gear, max_hill_speed, max_hill_cadence, max_sharp_hill_grade, min_hill_curve
and the steep_hill_ limits, a slowing start's
max_slowing_cadence, a turn's max_turn_speed and max_turn_lean, a stop's min_stop_after, a new heading's max_heading_change, max_heading_turn_speed,
min_heading_turn_gear and min_heading_turn_cadence, and the slalom's region: min_slalom_speed,
max_slalom_speed, max_slalom_acceleration, max_slalom_offset, min_slalom_gate_width, min_slalom_lead,
min_slalom_lookahead; and the look-ahead of the courses that turn: min_turn_lookahead, min_turn_lead,
min_turn_lead_lean, max_turn_lookahead_radii).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...ballistics import GRAVITY
from ...control.path import tightest_radius, turn_path, validate_path
from ...errors import ParameterError
from ...schema import Choice
from ...world.bicycle import wheel_radius as sized_wheel_radius
from ...world.hill import HILL_WIDTH, check_hill

COURSES = ("straight", "turn", "slalom", "speed_steps", "hill", "start", "coast", "stop")
COURSE = Choice("course", COURSES, "straight",
                "what the ride does (docs/bicycle.md, courses): hold the heading; a turn; a slalom of gates; "
                "speed steps; over a hill; a start from a slow roll; coast on a freewheel; brake to a stop")
FREEWHEEL_COURSES = ("coast", "stop")   # definition: the courses ridden on a freewheel bicycle
MAX_LEAN = math.radians(25.0)      # criterion: the steepest steady lean a course may ask for (v^2 / (g r) = tan)
SLALOM_POINT_SPACING = 0.25        # definition: m between the points of the slalom's sine
RUN_OUT = 60.0                     # definition: m of straight after a course's last feature (longer than a ride goes)


@dataclass(frozen=True)
class Course:
    """What the controller asks for, from the request: ``path`` (N x 2, m from the start, or None
    for a fixed heading), the commanded speed as steps ``speeds`` ((from time s, m/s), ...), the
    start's rolling speed, the gates ((x, y) centres, m), ``hill`` (the World field, () for none),
    the time from which the crank is not driven (``coast_from``, None: never) and whether the rider
    then brakes to a stop (``stop``)."""
    name: str
    path: np.ndarray | None
    speeds: tuple
    start_speed: float
    gates: np.ndarray
    gate_width: float
    hill: tuple
    coast_from: float | None = None
    stop: bool = False

    def speed_at(self, t: float) -> float:
        speed = self.speeds[0][1]
        for start, value in self.speeds:
            if t >= start:
                speed = value
        return speed


def course_for(p: dict) -> Course:
    """The course a request asks for (``p``: the validated parameters), refused if it turns
    harder than MAX_LEAN allows at its fastest commanded speed."""
    name = COURSE.option(p["course"])
    speeds = ((0.0, p["speed"]),)
    path, gates, hill, start_speed = None, np.zeros((0, 2)), (), p["speed"]
    if name == "turn":
        path = turn_path(p["turn_angle"], p["turn_after"], p["turn_radius"], RUN_OUT)
        _check_turn(p["speed"], p["turn_radius"], "turn_radius", p["max_turn_lean"], p["min_turn_radius"],
                    p["max_turn_speed"])
        _check_lookahead(p, math.atan(p["speed"] ** 2 / (GRAVITY * p["turn_radius"])), p["turn_radius"])
    elif name == "slalom":
        _check_slalom(p)
        _check_lookahead(p, math.atan(slalom_acceleration(p["speed"], p["gate_spacing"], p["gate_offset"]) / GRAVITY))
        path, gates = slalom(p["gate_count"], p["gate_spacing"], p["gate_offset"], p["turn_after"])
    elif name == "speed_steps":
        speeds = ((0.0, p["speed"]), (p["step_time"], p["second_speed"]), (2 * p["step_time"], p["third_speed"]))
    elif name == "hill":
        hill = (p["hill_after"], p["hill_grade"], p["hill_length"], p["hill_top"], p["hill_length"])
        if p["hill_curve"] > 0.0:              # its corners rounded by vertical curves (0: the sharp hill)
            hill += (p["hill_curve"],)
            check_hill(hill)
        # ridden along the hill's centre line: held to a heading alone, low gears left it 5-10 deg off
        # and the rider ran off the side of the 8 m wide hill (docs/bicycle.md, hills)
        path = validate_path([[0.0, 0.0], [p["hill_after"] + 2 * p["hill_length"] + p["hill_top"] + RUN_OUT, 0.0]])
        if p["heading"] != 0.0:
            raise ParameterError(f"the hill lies across the start's heading ({HILL_WIDTH:g} m wide): the hill course is "
                                 f"ridden with heading 0 (asked: {p['heading']:g} rad)")
    elif name == "start":
        start_speed = p["start_speed"]
    elif name == "stop":
        _check_stop(p)
        if p["coast_after"] < p["min_stop_after"]:
            raise ParameterError(f"the stop brakes from coast_after >= {p['min_stop_after']:g} s (asked: {p['coast_after']:g} s); "
                                 f"earlier was not measured (docs/bicycle.md, the stop's stand)")
    elif name == "coast":
        _check_coast(p)
    if name == "coast" and not p["min_coast_gear"] <= p["gear"] <= p["max_coast_gear"]:
        raise ParameterError(f"parameter gear={p['gear']:g} is out of range for the coast course; allowed range for gear is "
                             f"[{p['min_coast_gear']:g}, {p['max_coast_gear']:g}] (other gears were not measured: "
                             f"docs/bicycle.md, the stop's stand)")
    if "path" in p:
        path = np.asarray(p["path"], dtype=float)
        lookahead = p["lookahead_time"] * max(speed for _, speed in speeds)
        radius, where = tightest_radius(np.vstack([[-lookahead, 0.0], path]), lookahead)
        if math.isfinite(radius):
            _check_turn(max(speed for _, speed in speeds), radius, f"path, {max(where - lookahead, 0.0):.1f} m along it",
                        p["max_turn_lean"], p["min_turn_radius"], p["max_turn_speed"])
    _check_pedalling(p, [speed for _, speed in speeds], start_speed)
    fastest = max(speed for _, speed in speeds)
    if path is None and p["heading"] != 0.0:
        _check_heading_turn(p, fastest, min(*(speed for _, speed in speeds), start_speed))
    if hill:
        _check_hill(p, [speed for _, speed in speeds])
    coast_from = p["coast_after"] if name in FREEWHEEL_COURSES else None
    return Course(name, path, speeds, start_speed, gates, p["gate_width"], hill, coast_from, name == "stop")


def wheel_radius(p: dict) -> float:
    """The radius (m) of the wheels of the bicycle a request rides (its table's bicycle_size: a child's
    bicycle is smaller)."""
    return sized_wheel_radius(p["bicycle_size"])


def wheel_circumference(p: dict) -> float:
    """The distance (m) a request's bicycle rolls per wheel turn, 2 pi r: the cadence at speed v in gear g
    is v / (2 pi r g) rev/s."""
    return 2 * math.pi * wheel_radius(p)


def _check_lookahead(p: dict, lean: float, radius: float | None = None) -> None:
    """A course that turns off its straight lead-in (the turn course, the slalom) is followed by pure pursuit
    (behaviour.py) with a look-ahead of at least the table's ``min_turn_lookahead`` s; one asking a steady ``lean``
    (rad) above its ``min_turn_lead_lean`` aims no further than its ``min_turn_lead`` look-ahead distances
    (lookahead_time x speed) from the start, so that the aim starts on the straight; and on the turn course no
    further than its ``max_turn_lookahead_radii`` turn radii ahead: where the turns were measured to pass
    (docs/bicycle.md, the rider held on his saddle: the audit's margins, tenth session)."""
    ahead = p["lookahead_time"] * p["speed"]
    if p["lookahead_time"] < p["min_turn_lookahead"]:
        raise ParameterError(f"a course that turns is followed with lookahead_time >= {p['min_turn_lookahead']:g} s "
                             f"(asked: {p['lookahead_time']:g} s); shorter, the heading was measured to be left 6-53 deg off "
                             f"after a tight turn")
    if lean > p["min_turn_lead_lean"] and p["turn_after"] < p["min_turn_lead"] * ahead:
        raise ParameterError(f"a course that turns is ridden with turn_after >= {p['min_turn_lead']:g} x lookahead_time x "
                             f"speed = {p['min_turn_lead'] * ahead:.2f} m of straight before it (asked: {p['turn_after']:g} m); "
                             f"shorter, the pursuit aims around the corner from the start and a turn asking {math.degrees(lean):.1f} deg "
                             f"of lean (more than {math.degrees(p['min_turn_lead_lean']):.0f} deg) was measured to fall: a "
                             f"shorter lookahead_time or a longer turn_after would do")
    if radius is not None and ahead > p["max_turn_lookahead_radii"] * radius:
        raise ParameterError(f"a turn of turn_radius {radius:g} m is followed with lookahead_time x speed <= "
                             f"{p['max_turn_lookahead_radii']:g} x turn_radius = {p['max_turn_lookahead_radii'] * radius:.2f} m "
                             f"(asked: {p['lookahead_time']:g} s x {p['speed']:g} m/s = {ahead:.2f} m); further, the pursuit "
                             f"cut the turn and the rider was measured to fall in it: lookahead_time <= "
                             f"{p['max_turn_lookahead_radii'] * radius / p['speed']:.2f} s would do")


def _check_heading_turn(p: dict, fastest: float, slowest: float) -> None:
    """A commanded heading (no path) is turned to (behaviour._turn_to_heading) at the speeds, gears
    and cadences where the turn was measured to settle within 5 deg without a fall (docs/bicycle.md,
    random requests over the panel; the heading step); the turn course rides turns elsewhere."""
    rolled = wheel_circumference(p)
    if abs(p["heading"]) > p["max_heading_change"]:
        raise ParameterError(f"a new heading is turned to up to |heading| <= {p['max_heading_change']:g} rad (asked: "
                             f"{p['heading']:g} rad); larger, this rider was measured to fall in the turn: the turn course "
                             f"rides a larger turn")
    if fastest > p["max_heading_turn_speed"]:
        raise ParameterError(f"a new heading is turned to at speed <= {p['max_heading_turn_speed']:g} m/s (asked: heading "
                             f"{p['heading']:g} rad at {fastest:g} m/s); faster, the turn was measured to fall: the turn "
                             f"course rides a turn at speed")
    if p["gear"] < p["min_heading_turn_gear"]:
        raise ParameterError(f"a new heading is turned to at gear >= {p['min_heading_turn_gear']:g} (asked: heading "
                             f"{p['heading']:g} rad at gear {p['gear']:g}); in lower gears the heading was measured to stay "
                             f"5-10 deg off or to weave: the turn course rides a turn in any gear offered")
    cadence = slowest / (rolled * p["gear"])
    if cadence < p["min_heading_turn_cadence"]:
        raise ParameterError(f"a new heading is turned to at a cadence v / (2 pi r gear) >= {p['min_heading_turn_cadence']:g} "
                             f"rev/s (asked: heading {p['heading']:g} rad at {slowest:g} m/s in gear {p['gear']:g}, "
                             f"{cadence:.2f} rev/s); slower, the pedal strokes rocked the turning bicycle over: a gear <= "
                             f"{slowest / (rolled * p['min_heading_turn_cadence']):.2f} would do")


def _check_pedalling(p: dict, speeds: list[float], start_speed: float) -> None:
    """The gear is at least the table's ``min_gear``, and at least its ``min_fast_gear`` if any speed a course
    commands (the rolling start's too) reaches its ``fast_speed``; every speed is at least its ``min_speed`` and
    asks a cadence v / (2 pi r gear) of at most its ``max_cadence``; every commanded speed (not the rolling
    start's) asks at least its ``min_cadence`` (issue 30, eighth session): all measured (docs/bicycle.md, random
    requests over the panel; the fast gears: issue 30's checklist, seventh session)."""
    rolled = wheel_circumference(p)       # m per wheel turn; a cadence v / (rolled gear)
    slowest = min(speeds)
    if slowest < p["min_speed"]:
        raise ParameterError(f"the bicycle is ridden at speed >= {p['min_speed']:g} m/s (asked: {slowest:g} m/s): "
                             f"slower rides were measured to fall (docs/bicycle.md, random requests over the panel)")
    if p["gear"] > p["max_gear"]:
        raise ParameterError(f"the bicycle is ridden at gear <= {p['max_gear']:g} (asked: {p['gear']:g}): higher gears were "
                             f"not measured for this rider (docs/bicycle.md, riders other than the man)")
    if p["gear"] < p["min_gear"]:
        raise ParameterError(f"the bicycle is ridden at gear >= {p['min_gear']:g} (asked: {p['gear']:g}): in lower gears the "
                             f"legs were measured to lose more than 5 % of the speed (docs/bicycle.md, random requests over the panel)")
    fastest = max(*speeds, start_speed)
    if fastest > p["max_speed"]:
        raise ParameterError(f"the bicycle is ridden at speed <= {p['max_speed']:g} m/s (asked: {fastest:g} m/s): faster "
                             f"was not measured for this rider (docs/bicycle.md, riders other than the man)")
    if fastest >= p["fast_speed"] and p["gear"] < p["min_fast_gear"]:
        raise ParameterError(f"at speed >= {p['fast_speed']:g} m/s the bicycle is ridden in gear >= {p['min_fast_gear']:g} "
                             f"(asked: gear {p['gear']:g} at {fastest:g} m/s): in lower gears it was measured to weave (roll "
                             f"to 18 deg, the heading 11 deg off; from 5.39 to 7.1 m/s in gear 2.13 to 20.5 deg) and a start to "
                             f"7.05 m/s in gear 1.75 fell; a gear >= {p['min_fast_gear']:g} or a speed < {p['fast_speed']:g} m/s "
                             f"would do")
    slow_cadence = slowest / (rolled * p["gear"])
    if slow_cadence < p["min_cadence"]:
        raise ParameterError(f"the cadence v / (2 pi r gear) is ridden from {p['min_cadence']:g} rev/s (asked: {slow_cadence:.2f} "
                             f"rev/s at {slowest:g} m/s in gear {p['gear']:g}); slower, the pedal strokes were measured to "
                             f"set the bicycle weaving (roll to 19 deg, the heading 71 deg off) or to fall: a gear <= "
                             f"{slowest / (rolled * p['min_cadence']):.2f} or a speed >= "
                             f"{rolled * p['gear'] * p['min_cadence']:.2f} m/s would do")
    cadence = start_speed / (rolled * p["gear"])
    if start_speed > max(speeds) and cadence > p["max_slowing_cadence"]:
        raise ParameterError(f"a start slowing from its rolling start is ridden from a cadence v / (2 pi r gear) <= "
                             f"{p['max_slowing_cadence']:g} rev/s (asked: {cadence:.2f} rev/s at {start_speed:g} m/s in gear "
                             f"{p['gear']:g}); faster, the feet were measured to leave the pedals by 3 cm or more: a gear >= "
                             f"{start_speed / (rolled * p['max_slowing_cadence']):.2f} or a start_speed "
                             f"<= {rolled * p['gear'] * p['max_slowing_cadence']:.2f} m/s would do")
    cadence = fastest / (rolled * p["gear"])
    if cadence > p["max_cadence"]:
        raise ParameterError(f"the cadence v / (2 pi r gear) is ridden up to {p['max_cadence']:g} rev/s (asked: {cadence:.2f} "
                             f"rev/s at {fastest:g} m/s in gear {p['gear']:g}); faster, the legs were measured to lose more "
                             f"than 5 % of the speed: a gear >= "
                             f"{fastest / (rolled * p['max_cadence']):.2f} or a speed <= "
                             f"{rolled * p['gear'] * p['max_cadence']:.2f} m/s would do")


def _check_hill(p: dict, speeds: list[float]) -> None:
    """Hills up to the table's ``max_hill_grade`` with hill_grade x gear (the climb's crank torque goes
    with it: m g grade r gear) up to its ``max_hill_grade_gear``; steeper ones, up to ``steep_hill_grade``,
    only in gears ``steep_hill_min_gear``-``steep_hill_max_gear`` at speeds ``steep_hill_min_speed``-
    ``steep_hill_max_speed`` after at least ``steep_hill_min_lead`` m of flat: where the speed was measured
    to hold within 15 % up and down (docs/bicycle.md, hills). Up to ``max_hill_grade``, at a cadence up to
    ``max_hill_cadence`` and, steeper than ``max_sharp_hill_grade``, with ``hill_curve`` >= ``min_hill_curve``:
    where it held within 5 % instantaneously (docs/bicycle.md, the hills within 5 % instantaneously)."""
    grade, gear = p["hill_grade"], p["gear"]
    if grade > p["steep_hill_grade"]:
        raise ParameterError(f"the hill is ridden up to hill_grade {p['steep_hill_grade']:g} (asked: {grade:g}): steeper "
                             f"hills were measured to fall or to lose more than 15 % of the speed (docs/bicycle.md, hills)")
    if grade > p["max_hill_grade"]:
        low, high = p["steep_hill_min_gear"], p["steep_hill_max_gear"]
        slow, fast = p["steep_hill_min_speed"], p["steep_hill_max_speed"]
        lead = p["steep_hill_min_lead"]
        if not low <= gear <= high or not all(slow <= v <= fast for v in speeds) or p["hill_after"] < lead:
            raise ParameterError(f"a hill steeper than hill_grade {p['max_hill_grade']:g} (asked: {grade:g}) is ridden in gear "
                                 f"{low:g}-{high:g} at speed {slow:g}-{fast:g} m/s after hill_after >= {lead:g} m of flat "
                                 f"(asked: gear {gear:g} at {', '.join(f'{v:g}' for v in speeds)} m/s after {p['hill_after']:g} m); "
                                 f"elsewhere the climb was measured to lose more than 15 % of the speed or to fall, and a climb "
                                 f"begun while the rolling start settles lost 16 % (docs/bicycle.md, hills)")
        return
    if max(speeds) > p["max_hill_speed"]:
        raise ParameterError(f"a hill up to hill_grade {p['max_hill_grade']:g} is ridden at speed <= {p['max_hill_speed']:g} m/s "
                             f"(asked: {max(speeds):g} m/s on hill_grade {grade:g}); faster, the climb was measured to lose "
                             f"more than 5 % of the speed per crank revolution")
    cadence = max(speeds) / (wheel_circumference(p) * gear)
    if cadence > p["max_hill_cadence"]:
        raise ParameterError(f"a hill up to hill_grade {p['max_hill_grade']:g} is ridden at a cadence v / (2 pi r gear) <= "
                             f"{p['max_hill_cadence']:g} rev/s (asked: {cadence:.2f} rev/s at {max(speeds):g} m/s in gear {gear:g}); "
                             f"faster, the speed was measured to swing by more than 5 % within the strokes: a gear >= "
                             f"{max(speeds) / (wheel_circumference(p) * p['max_hill_cadence']):.2f} would do")
    if grade > p["max_sharp_hill_grade"] and p["hill_curve"] < p["min_hill_curve"]:
        raise ParameterError(f"a hill steeper than hill_grade {p['max_sharp_hill_grade']:g} (asked: {grade:g}) is ridden with its "
                             f"corners rounded, hill_curve >= {p['min_hill_curve']:g} m (asked: {p['hill_curve']:g} m); at a sharp "
                             f"crest the speed was measured to dip by more than 5 %")
    most = p["max_hill_grade_gear"]
    if grade * gear > most:
        raise ParameterError(f"the hill is ridden with hill_grade x gear <= {most:g} (asked: {grade:g} x {gear:g} = "
                             f"{grade * gear:.3f}); above it the climb was measured to lose more than 15 % of the speed: "
                             f"at gear {gear:g} a hill_grade <= {most / gear:.3f}, or a gear <= {most / grade:.2f}, would do")


def _check_coast(p: dict) -> None:
    """The coast is offered from the speeds it was measured from (min/max_coast_speed), and it ends in a
    stop from a speed the stop was measured from (coast_min_speed from min_stop_speed)."""
    speed, slowest, low, high = p["speed"], p["coast_min_speed"], p["min_coast_speed"], p["max_coast_speed"]
    if not low <= speed <= high:
        raise ParameterError(f"the coast is ridden from speed {low:g}-{high:g} m/s (asked: {speed:g} m/s); "
                             f"from elsewhere it was not measured (docs/bicycle.md, coasting)")
    if not p["min_stop_speed"] <= slowest < speed:
        raise ParameterError(f"the coast hands over to a stop at coast_min_speed, which must be from "
                             f"{p['min_stop_speed']:g} m/s up to below the speed {speed:g} m/s (asked: {slowest:g} m/s)")


def _check_stop(p: dict) -> None:
    """The stop is offered from the speeds at which it was measured to end standing (min/max_stop_speed,
    docs/bicycle.md)."""
    speed, low, high = p["speed"], p["min_stop_speed"], p["max_stop_speed"]
    if not low <= speed <= high:
        raise ParameterError(f"the stop is ridden from speed {low:g}-{high:g} m/s (asked: {speed:g} m/s); "
                             f"from elsewhere the rider was not measured to stop standing (docs/bicycle.md, the stop)")


def slalom(count: int, spacing: float, offset: float, lead: float) -> tuple[np.ndarray, np.ndarray]:
    """The slalom's path and gate centres: the gates ``spacing`` apart from ``lead`` + half a spacing,
    alternately ``offset`` left (the first) and right; between them a sine of half-period ``spacing``
    and amplitude ``offset`` whose crests are the gates. The path leaves and rejoins the start line
    tangentially: a half-cosine from the line to the first gate (from half a spacing before ``lead``,
    or from the start if that is nearer) and one from the last gate back to the line a spacing on,
    then straight on. (The sine alone met the line at a heading kink of atan(pi offset / spacing),
    whose curvature read 0.5 s ahead asked a 12 deg lean spike at 5 m/s: the man's slalom at 5 m/s,
    14 m, 1 m leaned 21.6 deg and missed the first gate, docs/bicycle.md.)"""
    count = int(count)
    gates = np.array([[lead + spacing * (k + 0.5), offset * (1 if k % 2 == 0 else -1)] for k in range(count)])
    first, last = gates[0, 0], gates[-1, 0]
    enter = max(lead - spacing / 2, 0.0)
    end = last + spacing
    x = np.arange(enter, end, SLALOM_POINT_SPACING)
    points = [[0.0, 0.0]] + [[xi, _slalom_y(xi, enter, first, last, spacing, offset, gates[-1, 1])] for xi in x]
    points += [[end, 0.0], [end + RUN_OUT, 0.0]]
    return validate_path(points), gates


def _slalom_y(x: float, enter: float, first: float, last: float, spacing: float, offset: float, last_y: float) -> float:
    """The slalom path's offset (m, left positive) at ``x``: the entry's half-cosine, the sine, the exit's."""
    if x < first:
        return offset * (1.0 - math.cos(math.pi * (x - enter) / (first - enter))) / 2
    if x > last:
        return last_y * (1.0 + math.cos(math.pi * (x - last) / spacing)) / 2
    return offset * math.cos(math.pi * (x - first) / spacing)


def slalom_acceleration(speed: float, spacing: float, offset: float) -> float:
    """The slalom sine's peak lateral acceleration (m/s^2): v^2 at its tightest radius,
    offset (pi / gate period)^2."""
    return offset * (math.pi * speed / spacing) ** 2


def slalom_widest_offset(speed: float, spacing: float, most: float, widest: float) -> float:
    """The largest gate offset (m) offered at this speed and spacing: at most ``widest`` (the rider's
    table's max_slalom_offset) and a sine asking at most ``most`` (max_slalom_acceleration)."""
    return min(widest, most / slalom_acceleration(speed, spacing, 1.0))


def _check_slalom(p: dict) -> None:
    """The slalom is offered where its gates were measured to be passed, the region in the rider's table
    (bicycle_any.json, the man's; a rider's own table narrows it; docs/bicycle.md, courses and the slalom's
    region): speed min_slalom_speed-max_slalom_speed, turn_after >= min_slalom_lead, gate_width >= min_slalom_gate_width, gate_offset up to
    max_slalom_offset with the sine's peak lateral acceleration offset (pi v / spacing)^2 within
    max_slalom_acceleration. Outside it the request is refused before it runs, naming what would do."""
    speed, spacing, offset, width = p["speed"], p["gate_spacing"], p["gate_offset"], p["gate_width"]
    low, high = p["min_slalom_speed"], p["max_slalom_speed"]
    if not low <= speed <= high:
        raise ParameterError(f"the slalom is ridden at speed {low:g}-{high:g} m/s (asked: {speed:g} m/s); "
                             f"elsewhere the rider misses gates (docs/bicycle.md, courses)")
    if p["turn_after"] < p["min_slalom_lead"]:
        raise ParameterError(f"the slalom is ridden with turn_after >= {p['min_slalom_lead']:g} m of straight before it "
                             f"(asked: {p['turn_after']:g} m): from a shorter lead-in the rider, still settling from the "
                             f"rolling start, missed the first gate or fell")
    if p["lookahead_time"] < p["min_slalom_lookahead"]:
        raise ParameterError(f"the slalom is ridden with lookahead_time >= {p['min_slalom_lookahead']:g} s (asked: "
                             f"{p['lookahead_time']:g} s): with a shorter look-ahead the rider was measured to miss gates")
    if width < p["min_slalom_gate_width"]:
        raise ParameterError(f"the slalom's gates are ridden through with gate_width >= {p['min_slalom_gate_width']:g} m "
                             f"(asked: {width:g} m): the rider crosses a gate up to 0.6 m from its centre")
    most, widest = p["max_slalom_acceleration"], p["max_slalom_offset"]
    allowed = slalom_widest_offset(speed, spacing, most, widest)
    if offset > allowed:
        raise ParameterError(f"the slalom at speed {speed:g} m/s with gate_spacing {spacing:g} m is ridden through its "
                             f"gates with gate_offset <= {allowed:.2f} m (asked: {offset:g} m): offsets up to "
                             f"{widest:g} m whose sine's lateral acceleration stays within "
                             f"{most:g} m/s^2; a wider gate_spacing or a lower speed would do")


def _check_turn(speed: float, radius: float, names: str, most: float, tightest: float, fastest: float) -> None:
    """A turn asking a steady lean (tan = v^2 / (g r)) of more than MAX_LEAN, or than the rider's table's
    ``most`` (max_turn_lean: the woman fell on a tighter turn at 3 m/s, the imaginary cyclist leaned past
    20 deg; docs/bicycle.md, riders other than the man), is refused naming the speed or radius that would do;
    so is one tighter than the table's ``tightest`` radius at any speed (min_turn_radius: the child fell on
    3.0-3.43 m turns at 2-3 m/s whatever the lean), and one faster than its ``fastest`` (max_turn_speed: the man
    fell after turns at 6.5-7.64 m/s; docs/bicycle.md, issue 30's checklist)."""
    if speed > fastest:
        raise ParameterError(f"the course turns (from {names}) at speed <= {fastest:g} m/s (asked: {speed:g} m/s); "
                             f"faster, the rider was measured to fall or to lean past 20 deg after the turn")
    if radius < tightest:
        raise ParameterError(f"the course turns on a radius of {radius:.2f} m (from {names}); this rider's turns "
                             f"are ridden on a radius of at least {tightest:g} m (allowed range of turn_radius "
                             f"for this rider: [{tightest:g}, 100] m)")
    lean, limit = math.atan(speed * speed / (GRAVITY * radius)), min(MAX_LEAN, most)
    if lean > limit:
        slowest = math.sqrt(GRAVITY * radius * math.tan(limit))
        raise ParameterError(f"the course turns on a radius of {radius:.2f} m (from {names}), which at "
                             f"speed {speed:g} m/s needs a lean of {math.degrees(lean):.1f} deg; at most "
                             f"{math.degrees(limit):g} deg is ridden: slow to <= {slowest:.2f} m/s or "
                             f"widen the turn to >= {speed * speed / (GRAVITY * math.tan(limit)):.2f} m")


def gate_passes(gates: np.ndarray, width: float, xy: np.ndarray) -> list[dict]:
    """Per gate: where the ride crossed the gate's line (x = the gate's x, the course runs along
    +X) and whether that was between its poles (``width`` apart); a gate never reached is missed."""
    out = []
    for gx, gy in gates:
        after = np.nonzero(xy[:, 0] >= gx)[0]
        if len(after) == 0 or after[0] == 0:
            out.append({"gate": [float(gx), float(gy)], "passed": False, "miss": None})
            continue
        k = after[0]
        f = (gx - xy[k - 1, 0]) / (xy[k, 0] - xy[k - 1, 0])
        y = xy[k - 1, 1] + f * (xy[k, 1] - xy[k - 1, 1])
        out.append({"gate": [float(gx), float(gy)], "passed": bool(abs(y - gy) <= width / 2),
                    "miss": float(y - gy)})
    return out
