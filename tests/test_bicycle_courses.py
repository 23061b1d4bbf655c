"""The bicycle's courses (sim_core.skills.bicycle.course) and the hill prop (sim_core.world.hill):
geometry and refusals without simulating, then rides read off simulations and compared with
SEEDS-WAVE2.md §8.1 (B2, B3, B6, B8, B9) and issue 30. Speeds are drawn at random (a fixed seed
for CI) inside the range the panel offers."""
import math

import mujoco
import numpy as np
import pytest

from sim_core.errors import ParameterError
from sim_core.simulate import RunRequest, run
from sim_core.skills.bicycle.behaviour import Bicycling, bicycle_constants
from sim_core.skills.bicycle.course import MAX_LEAN, course_for, gate_passes, slalom
from sim_core.skills.bicycle.report import (audit_checks, audit_draw, audit_line, audit_request, audit_seconds, slalom_request,
                                            slalom_seconds)
from sim_core.world import World, add_world
from sim_core.world.hill import CURVE_CHORD, check_hill, hill_height, hill_profile
from sim_core.character.model import new_spec

RANDOM = np.random.default_rng(30)
SLOWEST = Bicycling.settings_schema.by_name["min_speed"].default     # the table's slowest speed offered


def params(**values):
    return Bicycling.schema.validate(values)


def ride(duration, **values):
    return run(RunRequest("bicycle", "man", params=values, duration=duration))


# --- geometry and refusals (no simulation) ---------------------------------------------------------
def test_slalom_gates_alternate_on_the_sine_through_them():
    path, gates = slalom(8, 10.0, 1.0, 10.0)
    assert len(gates) == 8 and np.allclose(gates[:, 1], [1, -1] * 4)
    assert np.allclose(np.diff(gates[:, 0]), 10.0)
    for gx, gy in gates:                                  # the path passes through every gate's centre
        k = np.argmin(np.abs(path[:, 0] - gx))
        assert path[k, 1] == pytest.approx(gy, abs=0.01)
    passes = gate_passes(gates, 1.5, path)
    assert all(p["passed"] for p in passes)
    assert not gate_passes(gates, 1.5, np.column_stack([path[:, 0], np.zeros(len(path))]))[0]["passed"]


def test_slalom_path_leaves_and_rejoins_the_line_without_a_kink():
    """The slalom's path turns by well under a degree from one point to the next, the entry and exit
    included (the sine alone met the line at a kink of atan(pi offset / spacing): the lean it asked
    made the man at 5 m/s, 14 m, 1 m lean 21.6 deg and miss the first gate; docs/bicycle.md)."""
    rng = np.random.default_rng(3032)
    for _ in range(6):
        speed, spacing, offset = slalom_request(rng)
        lead = float(rng.uniform(2.0, 20.0))
        path, gates = slalom(int(rng.integers(1, 9)), spacing, offset, lead)
        heading = np.arctan2(*np.diff(path, axis=0).T[::-1])
        assert np.degrees(np.abs(np.diff(heading))).max() < 2.0, (speed, spacing, offset, lead)
        for gx, gy in gates:
            k = np.argmin(np.abs(path[:, 0] - gx))
            assert path[k, 1] == pytest.approx(gy, abs=0.01)


def test_speed_steps_and_slow_start():
    c = course_for(params(course="speed_steps", speed=3.0, second_speed=5.0, third_speed=4.0, step_time=15.0))
    assert [c.speed_at(t) for t in (0.0, 14.9, 15.0, 29.9, 30.0, 100.0)] == [3, 3, 5, 5, 4, 4]
    c = course_for(params(course="start", speed=4.0, start_speed=1.5))
    assert c.start_speed == 1.5 and c.speed_at(0.0) == 4.0


@pytest.mark.parametrize("values, words", [
    ({"course": "turn", "speed": 5.5, "turn_radius": 5.0}, "lean of"),
    # the audit's seed 8 #17 and #16, seed 7 #29 and #24 (docs/bicycle.md, issue 30's checklist, ninth session)
    ({"course": "turn", "speed": 4.27, "gear": 4.67, "turn_angle": -1.96, "turn_radius": 4.26}, "at most 15 deg"),
    ({"course": "turn", "speed": 7.64, "gear": 3.33, "turn_angle": -0.36, "turn_radius": 66.37},
     "at speed <= 6 m/s (asked: 7.64 m/s)"),
    ({"course": "turn", "speed": 7.66, "gear": 2.5, "turn_angle": 3.02, "turn_radius": 53.01}, "at speed <= 6 m/s"),
    ({"speed": 6.5, "path": [[0, 0], [30, 0], [60, 20]]}, "at speed <= 6 m/s (asked: 6.5 m/s)"),
    # tight turns at the lean limit followed with look-aheads measured to fall or to leave the heading off (tenth session)
    ({"course": "turn", "speed": 3.0, "gear": 3.3, "turn_angle": 3.0, "turn_radius": 3.43, "turn_after": 20.0,
      "lookahead_time": 0.25}, "lookahead_time >= 0.4 s (asked: 0.25 s)"),
    ({"course": "turn", "speed": 6.0, "gear": 2.5, "turn_angle": 3.1, "turn_radius": 13.8, "turn_after": 2.0,
      "lookahead_time": 1.5}, "turn_after >= 1 x lookahead_time x speed = 9.00 m"),
    ({"course": "turn", "speed": 3.0, "gear": 1.2, "turn_angle": -3.0, "turn_radius": 3.43, "turn_after": 9.0,
      "lookahead_time": 3.0}, "<= 1.6 x turn_radius = 5.49 m (asked: 3 s x 3 m/s = 9.00 m)"),
    ({"course": "slalom", "speed": 4.0, "lookahead_time": 3.0}, "turn_after >= 1 x lookahead_time x speed = 12.00 m"),
    ({"course": "slalom", "speed": 8.0, "gate_spacing": 4.0, "gate_offset": 3.0}, "the slalom is ridden at speed"),
    ({"course": "slalom", "speed": 4.0, "gate_spacing": 8.0, "gate_offset": 1.0}, "gate_offset <= 0.65 m"),
    ({"course": "slalom", "speed": 4.0, "gate_spacing": 20.0, "gate_offset": 1.5}, "gate_offset <= 1.00 m"),
    ({"course": "slalom", "speed": 4.0, "gate_width": 1.0}, "gate_width >= 1.5 m"),
    ({"course": "slalom", "speed": 5.5, "gate_spacing": 13.7, "lookahead_time": 0.4}, "lookahead_time >= 0.6 s (asked: 0.4 s)"),
    ({"course": "slalom", "speed": 4.0, "turn_after": 4.0}, "turn_after >= 5 m"),
    ({"course": "start", "speed": 7.05, "gear": 1.75, "start_speed": 4.41}, "ridden in gear >= 2.5 (asked: gear 1.75 at 7.05 m/s)"),
    ({"course": "start", "speed": 7.1, "gear": 2.13, "start_speed": 5.39}, "ridden in gear >= 2.5 (asked: gear 2.13 at 7.1 m/s)"),
    # the audit's seed 9 #29: a foot 3.0 cm off its pedal as the rider slowed (docs/bicycle.md, issue 30's checklist)
    ({"course": "start", "speed": 5.93, "gear": 2.92, "start_speed": 7.56}, "<= 1.15 rev/s (asked: 1.24 rev/s at 7.56 m/s"),
    ({"course": "hill", "hill_grade": 0.5}, "hill_grade=0.5"),
    ({"speed": 3.8, "gear": 4.0, "heading": 1.0}, "cadence v / (2 pi r gear) >= 0.5 rev/s"),
    # the audit's seed 6 #13 (0.40 rev/s): it weaved from the start and fell 33 s in (docs/bicycle.md, issue 30's checklist)
    ({"course": "speed_steps", "speed": 4.15, "gear": 4.94, "step_time": 18.37, "second_speed": 6.37, "third_speed": 4.74},
     "ridden from 0.43 rev/s (asked: 0.40 rev/s at 4.15 m/s in gear 4.94)"),
    ({"speed": 3.2, "gear": 4.94}, "a gear <= 3.55 or a speed >= 4.45 m/s would do"),
    ({"course": "hill", "hill_grade": 0.12}, "ridden up to hill_grade 0.1 "),
    ({"course": "hill", "hill_grade": 0.1, "gear": 2.6}, "is ridden in gear 1.9-2 at speed 4-6 m/s"),
    ({"course": "hill", "hill_grade": 0.1, "gear": 2.0, "speed": 3.0}, "is ridden in gear 1.9-2 at speed 4-6 m/s"),
    ({"course": "hill", "hill_grade": 0.1, "gear": 2.0, "hill_after": 4.0}, "hill_after >= 10 m"),
    ({"course": "hill", "hill_grade": 0.05, "gear": 4.0}, "hill_grade x gear <= 0.16"),
    # the hills within 5 % instantaneously (eleventh session): a sharp 5 % crest dipped the speed 5.0-7.1 %, strokes
    # faster than 1.25 rev/s swung it 5.1-8.7 % (docs/bicycle.md, the hills within 5 % instantaneously)
    ({"course": "hill", "hill_grade": 0.05, "hill_curve": 0.0}, "hill_curve >= 2 m (asked: 0 m)"),
    ({"course": "hill", "hill_grade": 0.05, "speed": 4.0, "gear": 1.0}, "<= 1.25 rev/s (asked: 1.91 rev/s"),
    ({"course": "hill", "hill_grade": 0.05, "speed": 8.0, "gear": 2.5, "hill_curve": 2.0}, "a gear >= 3.05 would do"),
    ({"course": "roundabout"}, "course"),
    ({"path": [[0, 0], [0.01, 0]]}, "degenerate"),
    ({"speed": 4.0, "path": [[0, 0], [10, 0], [10, 10]]}, "radius of 2.48 m (from path, 9.9 m along it)"),
])
def test_bad_courses_are_refused_in_one_line(values, words):
    """Among them a path whose corner (measured at the look-ahead's scale, as pure pursuit cuts it)
    asks more than MAX_LEAN; turns of 3-6 m/s asking up to 4.2 m/s^2 (19 deg of lean) were ridden
    without a fall (docs/bicycle.md)."""
    with pytest.raises(ParameterError) as err:
        course_for(params(**values))
    assert words in str(err.value) and "\n" not in str(err.value)


def test_early_stops_and_coasts_in_any_gear_are_offered():
    """Refused before the stop's stand was mended (thirteenth session, docs/bicycle.md, the stop's stand): the man's seed
    21 offered #14 (a stop braking 1.39 s in, which fell) and the coast outside gears 2.4-2.6 (seed 21's coast in gear
    3.5 fell at its stop); since the crank is levelled with the left pedal forward they stand."""
    assert course_for(params(course="stop", speed=3.03, gear=3.24, coast_after=1.39)).stop
    for gear in (1.0, 2.0, 3.5, 4.56):
        assert course_for(params(course="coast", speed=4.77, gear=gear, coast_after=4.64)).coast_from == 4.64


def test_fast_hills_and_a_flat_hill_are_offered():
    """The audit's seed 7 #24 (a 2 % hill at 6.36 m/s in gear 4.59) and seed 9 #17 (a hill of grade 0 at 6.24 m/s),
    refused by max_hill_speed 5.5 m/s before the rider was held on his saddle: with it every hill up to 5 % at
    6-8 m/s held the climb within 2.1 % per revolution (docs/bicycle.md, the rider held on his saddle)."""
    for values in ({"speed": 6.36, "gear": 4.59, "hill_grade": 0.02}, {"speed": 6.24, "gear": 3.62, "hill_grade": 0.0},
                   {"speed": 8.0, "gear": 3.19, "hill_grade": 0.05}):
        assert course_for(params(course="hill", **values)).hill


def test_a_gentle_turn_is_offered_from_a_short_lead_in():
    """The lead-in rule (min_turn_lead) is for turns asking more than min_turn_lead_lean: the audit's seed 11 #7,
    a 35.9 m turn at 4.28 m/s after 2.3 m with a 2.95 m look-ahead (3 deg of lean), rode (roll 3.8 deg)."""
    c = course_for(params(course="turn", speed=4.28, gear=4.58, turn_angle=1.24, turn_radius=35.91, turn_after=2.3,
                          lookahead_time=0.69))
    assert c.path is not None


def test_a_turn_within_the_lean_limit_is_accepted():
    table = Bicycling.settings_schema.by_name
    speed = float(RANDOM.uniform(SLOWEST, table["max_turn_speed"].default))
    radius = speed ** 2 / (9.81 * math.tan(min(MAX_LEAN, table["max_turn_lean"].default))) * 1.01
    assert course_for(params(course="turn", speed=speed, turn_radius=max(radius, 3.0))).path is not None


def road_heights(hill, xs) -> np.ndarray:
    """The compiled hill's road height at each x: a ray cast straight down onto its boxes from 10 m."""
    spec = new_spec("hill")
    add_world(spec, World(hill=hill), None)
    model = mujoco.MjModel.from_xml_string(spec.to_xml())
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    geomid = np.zeros(1, dtype=np.int32)
    return np.array([10.0 - mujoco.mj_ray(model, data, np.array([x, 0.0, 10.0]), np.array([0.0, 0.0, -1.0]), None, 1,
                                          -1, geomid) for x in xs])


def test_hill_road_is_continuous_and_at_its_grade():
    hill = (10.0, 0.05, 40.0, 10.0, 40.0)
    assert hill_height(hill, [0.0, 10.0, 30.0, 50.0, 55.0, 80.0, 100.0, 120.0]) == pytest.approx(
        [0.0, 0.0, 1.0, 2.0, 2.0, 1.0, 0.0, 0.0])
    # the road surface: a ray cast down onto the boxes meets hill_height everywhere along the hill
    xs = np.linspace(10.5, 99.5, 40)
    assert road_heights(hill, xs) == pytest.approx(hill_height(hill, xs), abs=1e-6)
    with pytest.raises(ParameterError, match="hill grade = 0.3"):
        check_hill((0.0, 0.3, 10.0, 1.0, 10.0))


def test_a_rounded_hill_bends_evenly_through_its_vertical_curves():
    """hill_curve: the four corners rounded by parabolas of that length, laid as short chords; the road
    (a ray cast onto the boxes) is hill_height, and no chord turns by more than CURVE_CHORD / curve of the
    corner's grade change. The course refuses curves longer than its top or climb."""
    hill = (10.0, 0.1, 40.0, 10.0, 40.0, 10.0)
    assert hill_height(hill, [0.0, 5.0, 15.0, 45.0, 50.0, 55.0, 60.0, 105.0]) == pytest.approx(
        [0.0, 0.0, 0.5, 3.5, 3.875, 4.0, 3.875, 0.0])
    xs = np.linspace(0.3, 105.3, 211)              # between the chords' ends
    assert road_heights(hill, xs) == pytest.approx(hill_height(hill, xs), abs=5e-5)   # the XML's digits, boxes 4.5 m deep
    points = np.array([point for _, vertices in hill_profile(hill) for point in vertices])
    keep = np.concatenate([[True], np.diff(points[:, 0]) > 1e-9])
    grades = np.diff(points[keep, 1]) / np.diff(points[keep, 0])
    assert np.abs(np.diff(grades)).max() <= 0.1 * CURVE_CHORD / 10.0 + 1e-9
    with pytest.raises(ParameterError, match="hill curve = 12 m is longer"):
        course_for(params(course="hill", hill_curve=12.0, hill_top=10.0))
    assert course_for(params(course="hill", hill_grade=0.02, hill_curve=0.0)).hill == (10.0, 0.02, 40.0, 10.0, 40.0)  # the sharp hill


# --- rides ---------------------------------------------------------------------------------------
@pytest.mark.slow
def test_a_random_speed_rides_straight_without_a_fall():
    """Any speed offered (the table's min_speed to 8 m/s): 20 s straight, no fall, speed within 5 %, roll < 20 deg."""
    speed = round(float(RANDOM.uniform(SLOWEST, 8.0)), 2)
    m = ride(20.0, speed=speed).meta["metrics"]
    assert not m["fell"], f"speed {speed}: fell at {m['fall_time']}"
    assert m["mean_speed_last_10s"] == pytest.approx(speed, rel=0.05) and m["max_abs_roll_deg"] < 20.0


@pytest.mark.slow
@pytest.mark.parametrize("speed", [3.0, 5.0])
def test_a_30_deg_heading_step_settles_with_margin_at_the_ends_of_the_speeds_offered(speed):
    """The +30 deg step at the slowest and fastest speed a new heading is offered at (max_heading_turn_speed 5 m/s
    since the tenth session: with the rider held on his saddle 5.5 m/s took 2.99 s): counter-steer (the fork first
    turns right), within 5 deg inside TARGETS.md's 3 s (2.73 s measured at 5 m/s)."""
    m = ride(6.0, speed=speed, heading=math.radians(30.0)).meta["metrics"]
    assert not m["fell"] and m["first_fork_motion"] == -1.0
    assert m["heading_within_5deg_from"] is not None and m["heading_within_5deg_from"] <= 2.8


@pytest.mark.slow
def test_speed_steps_3_5_4_are_tracked():
    """B6: mean |v - v_d| over the last 5 s of each step < 10 % of v_d."""
    m = ride(45.0, course="speed_steps", speed=3.0, second_speed=5.0, third_speed=4.0, step_time=15.0).meta["metrics"]
    assert not m["fell"] and len(m["speed_steps"]) == 3
    assert all(s["mean_abs_error"] < 0.10 for s in m["speed_steps"]), m["speed_steps"]


@pytest.mark.slow
def test_hill_5_percent_up_and_down_at_4_m_s_and_a_lower_gear_pedals_faster():
    """TARGETS.md: the commanded speed held within 5 % on the climb and the descent, instantaneously (the
    rider held on his saddle at seat_pitch, the load's feed-forward and eq. 7's integral term; measured 2.8 / 3.2 %
    in gear 2.6, 3.3 / 3.7 % in gear 2.0; with the pelvis free to swing 6.6 / 5.1 % and 4.8 / 4.5 %, docs/bicycle.md,
    the rider held on his saddle; on the default hill_curve 2 m since the eleventh session: 2.8 / 2.5 % in gear 2.6)
    and by the speed's mean over each crank revolution; no fall; cadence v / (2 pi r g)."""
    rides = {gear: ride(28.0, course="hill", hill_grade=0.05, gear=gear).meta["metrics"] for gear in (2.0, 2.6)}
    for gear, m in rides.items():
        assert not m["fell"]
        assert m["hill_climb_worst_revolution_error"] < 0.05 and m["hill_descent_worst_revolution_error"] < 0.05
        assert m["hill_climb_worst_error"] < 0.05 and m["hill_descent_worst_error"] < 0.05
        assert m["hill_climb_cadence_hz"] == pytest.approx(m["hill_climb_cadence_expected_hz"], rel=0.05)
    assert rides[2.0]["hill_climb_cadence_hz"] > rides[2.6]["hill_climb_cadence_hz"]


@pytest.mark.slow
def test_hill_10_percent_up_and_down_at_4_m_s_in_gear_2():
    """Issue 30: a 10 % hill (offered in gears 1.9-2.0 at 4-6 m/s): speed within 15 % on the climb and the
    descent, no fall (13.8 % and 4.7 % measured: the climb's worst is the front wheel leaving the sharp crest; ridden
    by eq. 7 alone, the load's feed-forward and the integral term off beyond max_hill_grade)."""
    m = ride(27.0, course="hill", hill_grade=0.1, gear=2.0, hill_curve=0.0).meta["metrics"]
    assert not m["fell"]
    assert m["hill_climb_worst_error"] < 0.15 and m["hill_descent_worst_error"] < 0.15


@pytest.mark.slow
def test_a_rounded_10_percent_hill_keeps_the_climb_within_12_percent():
    """hill_curve 10 m rounds the crest the front wheel left: the climb's worst error 11.2 % (sharp: 13.8 %),
    the descent's 3.9 % (5.6 %), measured (docs/bicycle.md, rounded hills); the feet on the pedals."""
    m = ride(27.0, course="hill", hill_grade=0.1, gear=2.0, hill_curve=10.0).meta["metrics"]
    assert not m["fell"] and m["max_foot_gap"] < 0.03 and m["max_hand_gap"] < 0.03
    assert m["hill_climb_worst_error"] < 0.12 and m["hill_descent_worst_error"] < 0.05


@pytest.mark.slow
def test_slalom_of_8_gates_and_a_two_sided_pedal():
    """B9: every gate passed, no fall; B2: the pedal pulls the foot at some point (tension)."""
    speed, spacing, offset = slalom_request(RANDOM)        # anywhere in the region the slalom is offered in
    m = ride(slalom_seconds(speed, spacing), course="slalom", speed=speed, gate_spacing=spacing,
             gate_offset=offset).meta["metrics"]
    assert not m["fell"] and m["gates_passed"] == m["gate_count"] == 8, (speed, spacing, offset, m["gate_misses"])
    assert m["pedal_pull_r_max"] > 0.0 and m["pedal_pull_l_max"] > 0.0
    assert m["max_hand_gap"] < 0.03 and m["max_foot_gap"] < 0.03 and m["max_seat_gap"] < 0.001


def test_a_slalom_at_the_edge_of_its_region_passes_its_gates():
    """The hole of issue 30's audit (the man's 5 m/s slalom at 14 m passed 7 of 8 gates): a speed drawn
    over the slalom's offered speeds, the widest offset offered, the gates as close as the sine's
    lateral acceleration allows (the region's corner) - every gate passed, no fall, |roll| < 20 deg."""
    c = bicycle_constants()
    speed = round(float(np.random.default_rng(3033).uniform(c["min_slalom_speed"], c["max_slalom_speed"])), 2)
    offset = c["max_slalom_offset"]
    spacing = math.ceil(math.pi * speed * math.sqrt(offset / c["max_slalom_acceleration"]) * 100) / 100
    m = ride(slalom_seconds(speed, spacing, 3), course="slalom", speed=speed, gate_spacing=spacing, gate_offset=offset,
             gate_count=3).meta["metrics"]
    assert not m["fell"] and m["gates_passed"] == m["gate_count"] == 3, (speed, spacing, m["gate_misses"])
    assert m["max_abs_roll_deg"] < 20.0


@pytest.mark.slow
def test_turn_and_a_start_from_a_slow_roll():
    m = ride(15.0, course="turn").meta["metrics"]
    assert not m["fell"] and m["path_deviation_max"] < 1.5
    start = round(float(RANDOM.uniform(1.5, 3.0)), 2)
    m = ride(12.0, course="start", start_speed=start, speed=4.0).meta["metrics"]
    assert not m["fell"] and m["mean_speed_last_5s"] == pytest.approx(4.0, rel=0.05), start


# --- random requests over the panel (issue 30; python -m sim_core report bicycle --random N --seed S) ---
DRAWS = np.random.default_rng(3030)
AUDIT = [audit_draw(DRAWS) for _ in range(17)]      # seventeen requests drawn from the panel


def test_random_requests_are_refused_in_one_line_or_offered():
    """Each drawn request is either refused before anything runs, in one line naming the limit, or
    offered; both kinds are drawn."""
    refused = 0
    for values in AUDIT:
        try:
            course_for(params(**values))
        except ParameterError as err:
            refused += 1
            assert "\n" not in str(err) and any(ch.isdigit() for ch in str(err)), values
    assert 0 < refused < len(AUDIT)


@pytest.mark.slow
def test_random_requests_are_refused_or_pass():
    """The drawn requests as the audit runs them, the short ones (<= 17 s ridden): refused before
    simulating, or ridden without a fall and passing TARGETS.md's checks (audit_checks)."""
    short = [values for values in AUDIT if audit_seconds(values) <= 17.0]
    assert short
    for values in short:
        result = audit_request(values)
        assert "refused" in result or result["passed"], audit_line(0, result)


def test_offered_draws_are_offered_to_their_rider():
    """``report bicycle --random N --offered``: each draw is inside what the rider is offered (refused draws
    drawn again), among the rider's courses, speeds and gears (no ride)."""
    from sim_core.skills.bicycle.behaviour import rider_courses, riders
    from sim_core.skills.bicycle.report import audit_refusal, offered_draw
    rng = np.random.default_rng(21)
    for rider in riders():
        c = bicycle_constants(rider)
        for _ in range(5):
            draw, refused = offered_draw(rng, rider)
            assert audit_refusal(draw, rider) is None, (rider, draw)
            assert draw["course"] in rider_courses(rider) and c["min_gear"] <= draw["gear"] <= c["max_gear"]
            assert refused >= 0
    assert audit_refusal({"course": "slalom", "speed": 3.5}, "child").startswith("the child rides")
    assert "|heading| <= 0.5 rad" in audit_refusal({"course": "straight", "speed": 2.37, "gear": 2.6, "heading": -1.0}, "child")


def test_the_audit_rides_as_the_rider_asked_and_refuses_what_it_is_not_offered():
    """``report bicycle --random N --character C``: the draw is asked of that rider; a course not in
    the rider's table is refused in one line naming it (the child: the straight, turns and hills only)."""
    from sim_core.skills.bicycle.behaviour import Bicycling
    from sim_core.skills.bicycle.report import AUDIT_PARAMETERS
    defaults = Bicycling.schema.defaults()
    draw = {"course": "slalom", "speed": 3.5, "gear": 2.6, **{n: defaults[n] for n in AUDIT_PARAMETERS["slalom"]}}
    result = audit_request(draw, "child")
    assert "refused" in result and "the child rides" in result["refused"] and "\n" not in result["refused"]


def test_the_audit_judges_the_gates_a_cut_ride_reached():
    """A slalom longer than the audit's ride (AUDIT_MAX_SECONDS) is judged on the gates the ride reaches (each
    with half a spacing after it), not on all: the woman's seed 41 offered #10 (7 gates 33.65 m apart at 3.59 m/s,
    68 s long) passed 6 gates in 60 s and was called a fail."""
    ridden = dict(fell=False, max_abs_roll_deg=1.7, max_hand_gap=0.007, max_foot_gap=0.003, max_seat_gap=0.00025,
                  gate_count=7)
    request = dict(course="slalom", speed=3.59, gear=2.6, gate_count=7, gate_spacing=33.65, gate_offset=0.3, turn_after=7.69)
    gates = {passed: dict((name, ok) for name, ok, _ in audit_checks(request, dict(ridden, gates_passed=passed), 60.0, 0.05))
             ["gates"] for passed in (5, 6)}
    assert gates == {5: False, 6: True}
