"""Leaping and landing (Wooten ch. 4, 6): what works today, measured off the simulation and
compared with TARGETS.md. What is not reached yet is an xfail that says what was measured (see
the README and docs/leap_report.md); jumps to a target are in test_target_jump.py."""
import numpy as np
import pytest

from sim_core.control.leap import (blend_rows, broad_distances, broad_gaps, broad_row, broad_rows, commandable_heights,
                                   load_mapping, rise_tolerance, uncovered_gaps)
from sim_core.errors import ParameterError
from sim_core.simulate import RunRequest, StartState, largest_difference, replay, run

import importlib


def first_flight(traj):
    flying = traj.arrays["support_points"][:, :, 2].min(axis=1) > 0.01
    start = int(np.argmax(flying))
    end = start
    while end + 1 < len(flying) and flying[end + 1]:
        end += 1
    return start, end


@pytest.mark.parametrize("name, height", [("man", 0.3), ("man", 0.8), ("man", 1.15), ("woman", 0.92), ("woman", 1.15)])
def test_drop_landing_ends_balanced(name, height):
    """Seed (Wooten §6.2): the man recovers from a 1.15 m drop, the woman from 0.92 m (the man's
    high drops need the calibrated extra foot servo delta for fast touchdowns)."""
    traj = run(RunRequest("land", name, start=StartState(height=height), duration=3.0))
    m = traj.meta["metrics"]
    assert traj.meta["outcome"] == "success", m
    assert m["final_com_speed"] < 0.1 and not m["fell"]
    assert m["final_pelvis_height"] > (0.85 if name == "man" else 0.75)      # stood back up


LANDED_SPEEDS = {"man": (-1.0, 3.0), "woman": (-1.0, 3.0)}      # m/s: measured range, TARGETS.md -1 .. +3


@pytest.mark.parametrize("name", ["man", "woman"])
@pytest.mark.parametrize("speed", [-1.0, -0.5, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0])
def test_landing_with_horizontal_speed_ends_balanced(name, speed):
    """TARGETS.md: landings with horizontal COM speed -1 .. +3 m/s end balanced (0.2 m drop, the
    report's case). Above 1 m/s the legs are held straighter in flight (fast_knee_flexion).
    Balanced includes the feet staying where they touched down (a hop back under the body to
    catch the COM is a skid, not a landing)."""
    traj = run(RunRequest("land", name, start=StartState(height=0.2, velocity=(speed, 0.0, 0.0)), duration=3.0))
    assert traj.meta["outcome"] != "success" or traj.meta["metrics"]["landing_skid"] <= 0.05
    low, high = LANDED_SPEEDS[name]
    if not low <= speed <= high:
        pytest.xfail(f"{name} at {speed:+.1f} m/s: {traj.meta['outcome']} (lands {low:+.1f} .. {high:+.1f} m/s)")
    assert traj.meta["outcome"] == "success", traj.meta["metrics"]


@pytest.mark.parametrize("height", [0.2, 0.4])
def test_leap_goes_straight_up_without_spinning(height):
    """The calibrated thrust leaves the ground nearly straight up: little horizontal speed, and the
    whole-body angular momentum turns the body by less than 0.3 rad over the flight."""
    traj = run(RunRequest("leap", "man", params=dict(height=height), duration=2.5))
    start, end = first_flight(traj)
    a = traj.arrays
    flight = (end - start) / traj.meta["control_rate"]
    assert flight > 0.3
    assert abs(a["com_vel"][start, 0]) < 0.2
    inertia = 15.0          # kg m^2: the man's pitch inertia in a loose flight pose (order of)
    assert abs(a["angmom"][start, 1]) / inertia * flight < 0.3


@pytest.mark.parametrize("hip, sign", [(0.3, -1.0), (-0.3, 1.0)])
def test_liftoff_hip_sets_the_somersault_direction(hip, sign):
    traj = run(RunRequest("leap", "man", params=dict(low_level=1, crouch_height=0.65, crouch_pitch=0.0,
                                                     liftoff_hip=hip), duration=2.0))
    start, _ = first_flight(traj)
    assert sign * traj.arrays["angmom"][start, 1] > 3.0


def test_angular_momentum_is_constant_in_flight():
    """Physics check: only gravity acts in flight, so the angular momentum about the COM stays
    constant (relative drift < 1 %) whatever the limbs do."""
    traj = run(RunRequest("leap", "man", params=dict(low_level=1, crouch_height=0.65, crouch_pitch=0.0,
                                                     liftoff_hip=0.3), duration=2.0))
    start, end = first_flight(traj)
    momentum = traj.arrays["angmom"][start:end + 1]
    drift = np.abs(momentum - momentum[0]).max() / np.linalg.norm(momentum[0])
    assert np.linalg.norm(momentum[0]) > 3.0 and drift < 0.01


def test_leap_replays_bit_for_bit():
    traj = run(RunRequest("leap", "man", params=dict(low_level=1, crouch_height=0.7), duration=2.5))
    assert largest_difference(traj, replay(traj)) == 0.0


def test_a_tucked_commanded_leap_replays_bit_for_bit_and_differs_from_the_untucked():
    """The flight's tuck (landing_tuck_knee_flexion from lift-off for landing_tuck_share of the commanded air time): a
    servo target like any other, so the run replays exactly; and it changes the run (the knees bend in flight)."""
    params = dict(low_level=1, distance=0.0, crouch_height=0.6, commanded_takeoff=1, flight_target_x=0.7,
                  flight_air_time=0.5)
    tucked = run(RunRequest("leap", "woman", params={**params, "landing_tuck_knee_flexion": 2.0,
                                                                  "landing_tuck_share": 0.5}, duration=2.5))
    assert largest_difference(tucked, replay(tucked)) == 0.0
    plain = run(RunRequest("leap", "woman", params=params, duration=2.5))
    assert np.abs(tucked.arrays["qpos"] - plain.arrays["qpos"]).max() > 0.1


@pytest.mark.parametrize("name, height, strength", [
    ("man", 0.1, "human"), ("man", 0.2, "human"), ("man", 0.35, "human"), ("man", 0.4, "human"), ("man", 0.6, "human"),
    ("woman", 0.16, "human"), ("woman", 0.25, "human"), ("woman", 0.33, "human"), ("woman", 0.4, "human"),
    ("woman", 0.44, "human"), ("woman", 0.58, "human"), ("woman", 0.59, "human"), ("woman", 0.6, "human"),
    ("woman", 0.7, "human"), ("man", 0.27, "unlimited"),
    ("man", 0.1, "unlimited"), ("man", 0.33, "unlimited"), ("man", 0.7, "unlimited"), ("man", 0.9, "unlimited"), ("man", 1.0, "unlimited"),
    ("woman", 0.45, "unlimited"), ("woman", 0.58, "unlimited"), ("woman", 0.85, "unlimited"), ("woman", 0.9, "unlimited"),
    ("woman", 1.0, "unlimited")])
def test_commanded_vertical_leap_is_reached_and_lands_balanced(name, height, strength):
    """TARGETS.md: COM rise within +-10 % (+-3 cm below 0.3 m), ending balanced: the composite
    leaps (0.16, 0.33, 0.58 m, woman), the 0.6 m target with human torque limits, 1.0 m with
    unlimited strength (man and woman), the lowest target 0.1 m (the man's lowest calibrated
    leaps rise 0.11-0.12 m, within its 3 cm), and heights that fell when they were interpolated between
    calibrated rows (man 0.4; woman 0.4, 0.44, 0.59, 0.7; unlimited: man 0.27, 0.33, 0.7, woman 0.58, 0.85,
    0.9) and now run rows calibrate_leap.py --fill added."""
    traj = run(RunRequest("leap", name, params=dict(height=height), duration=5.0, strength=strength))
    m = traj.meta["metrics"]
    assert traj.meta["outcome"] == "success", m
    tolerance = rise_tolerance(height)
    assert abs(m["com_rise"] - height) <= tolerance
    # seed simulation: 5.8 x body weight at 0.5 m; goal <= 3.5 x (measured per height in the report)
    if strength == "human":
        assert m["peak_thrust_grf_body_weights"] <= 6.0


def random_adapted_heights(name: str, count: int = 3) -> list[float]:
    """``count`` heights drawn uniformly (seed 28) over what the body's leap is offered (its commandable
    heights, from the schema's lowest)."""
    from sim_core.skills.leap.behaviour import Leap
    low, high = commandable_heights(load_mapping(name)["vertical"]["com_rise"])
    low = max(low, Leap.schema.by_name["height"].minimum)
    return [round(float(h), 3) for h in np.random.default_rng(28).uniform(low, high, count)]


@pytest.mark.parametrize("name, height", [(n, h) for n in ("child", "imaginary_runner") for h in random_adapted_heights(n)])
def test_an_adapted_body_leaps_anywhere_it_is_offered_and_lands_balanced(name, height):
    """Issue 28: the child's and the imaginary runner's leaps at random heights of their offered ranges
    rise within tolerance and stand 5 s (their tables' top rows, which fell 1.5-2 s after landing, were
    taken out: docs/bodies.md)."""
    traj = run(RunRequest("leap", name, params=dict(height=height), duration=5.0))
    m = traj.meta["metrics"]
    assert traj.meta["outcome"] == "success", m
    assert abs(m["com_rise"] - height) <= rise_tolerance(height)


BROAD_DISTANCES = {"man": (0.3, 0.5, 0.75, 1.0, 1.1, 1.3, 1.6, 1.9, 2.1), "woman": (0.3, 0.5, 0.75, 1.0, 1.3, 1.6)}


@pytest.mark.parametrize("name, distance", [(n, d) for n, ds in BROAD_DISTANCES.items() for d in ds])
def test_broad_jump_travels_the_commanded_distance_and_lands_balanced(name, distance):
    """TARGETS.md: broad jumps 0.3 .. 2.1 m (man) and 0.3 .. 1.6 m (woman), composites 1.1 and
    2.1 m (man): COM travel within +-10 %, ending balanced, the feet staying where they land. A
    distance outside the calibrated broad jumps (python -m sim_core calibrate leap plans them) is
    refused before simulating, naming the range: an xfail saying so."""
    try:
        traj = run(RunRequest("leap", name, params=dict(distance=distance), duration=5.0))
    except ParameterError as refused:
        pytest.xfail(str(refused))
    m = traj.meta["metrics"]
    assert traj.meta["outcome"] == "success", m
    assert abs(m["com_travel"] - distance) <= 0.1 * distance
    assert m["landing_skid"] <= 0.05
    assert not m["stepped"]         # the landing's slide, not the jump's travel from the start


def random_broad_distances(name: str, count: int = 4) -> list[float]:
    """``count`` distances drawn uniformly (seed 29) over the character's calibrated broad-jump travels."""
    travels = load_mapping(name)["broad"]["com_travel"]
    return [round(float(d), 3) for d in np.random.default_rng(29).uniform(min(travels), max(travels), count)]


@pytest.mark.parametrize("name, distance", [(n, d) for n in ("man", "woman") for d in random_broad_distances(n)])
def test_a_broad_jump_anywhere_in_the_calibrated_range_travels_within_10_percent_and_lands(name, distance):
    """Issue 29: a broad jump at any distance between the shortest and the longest calibrated one
    (drawn at random, not at the rows) travels within 10 % and lands balanced."""
    traj = run(RunRequest("leap", name, params=dict(distance=distance), duration=5.0))
    m = traj.meta["metrics"]
    assert traj.meta["outcome"] == "success", m
    assert abs(m["com_travel"] - distance) <= 0.1 * distance, m["com_travel"]


@pytest.mark.parametrize("name", ["man", "woman"])
def test_every_broad_distance_in_the_calibrated_range_has_a_row_within_10_percent(name):
    """A blend of two calibrated broad jumps falls more often than not (a row is a knife edge), so
    from the shortest to the longest calibrated travel every distance (5 mm apart) has a measured
    row within 10 % (python -m sim_core calibrate leap --fill --only broad adds them)."""
    assert broad_gaps(load_mapping(name)["broad"]["com_travel"]) == []


def test_the_broad_map_runs_a_row_exactly_at_its_travel_and_blends_between_rows():
    """At a row's measured travel the broad jump runs that row value for value (the stored jumps
    stay bit-identical); in a gap (a table with two rows) the quantities are linear in the travel
    and the switches (the thrust, the landing's arm swing) come from the nearer row."""
    broad = load_mapping("man")["broad"]
    travels, rows = broad_rows(broad)
    for travel, row in zip(travels, rows):
        assert broad_row(broad, travel) == row
    two = {"com_travel": [1.0, 2.0], "params": [dict(crouch_height=0.6, distance=1.0, landing_swing_arms=0.0),
                                                 dict(crouch_height=0.7, distance=0.0, landing_swing_arms=1.0)]}
    assert broad_row(two, 1.3) == pytest.approx(dict(crouch_height=0.63, distance=1.0, landing_swing_arms=0.0))
    assert broad_row(two, 1.6) == pytest.approx(dict(crouch_height=0.66, distance=0.0, landing_swing_arms=1.0))
    assert blend_rows(rows[0], rows[1], 0.0) == rows[0]
    low, high = broad_distances(travels)
    assert low == pytest.approx(min(travels) / 1.1) and high == pytest.approx(max(travels) / 0.9)


@pytest.mark.parametrize("name", ["man", "woman"])
@pytest.mark.parametrize("table", ["vertical", "vertical_unlimited"])
def test_every_commanded_height_runs_a_calibrated_leap_within_its_tolerance(name, table):
    """From 0.1 m up to the highest calibrated leap (or 1 m), every height (5 mm apart) has a
    calibrated row whose measured rise is within its tolerance, so the leap runs that measured row
    and no interpolation between rows (which missed or fell: the woman's 0.44 / 0.59 m, the man's
    0.27 m unlimited) is left; python -m sim_core calibrate leap --fill fills the gaps."""
    assert uncovered_gaps(load_mapping(name)[table]["com_rise"]) == []


def test_a_fill_tries_crouches_between_the_neighbours_whose_rises_straddle_a_gap():
    """calibrate_leap.py --fill: for a gap in the rises, each damping's neighbouring crouches whose
    measured rises lie either side of its middle get two crouches between them (a third and two
    thirds of the way); a family that does not straddle it gets none."""
    calibrate_leap = importlib.import_module("sim_core.skills.leap.calibrate")
    results = [dict(crouch_height=0.60, thrust_damping=1.0, com_rise=0.30), dict(crouch_height=0.57, thrust_damping=1.0, com_rise=0.40),
               dict(crouch_height=0.55, thrust_damping=1.0, com_rise=0.45), dict(crouch_height=0.60, thrust_damping=0.3, com_rise=0.50)]
    assert uncovered_gaps([0.30, 0.45])[-1] == pytest.approx((0.335, 0.405))   # beyond 10 % of both rows
    assert calibrate_leap.gap_crouches(results, [(0.34, 0.36)]) == [(0.59, 1.0), (0.58, 1.0)]


def test_the_stated_range_of_commandable_heights_is_the_one_that_runs():
    """The refusal's range is exact: its ends run (the end leap within tolerance), just beyond
    them is refused."""
    low, high = commandable_heights(load_mapping("man")["vertical"]["com_rise"])
    for height in (low + 1e-3, high - 1e-3):
        run(RunRequest("leap", "man", params=dict(height=height), duration=0.01))
    for height in (low - 1e-3, high + 1e-3):
        with pytest.raises(ParameterError, match="allowed range"):
            run(RunRequest("leap", "man", params=dict(height=height), duration=0.01))


def test_infeasible_and_bad_leaps_are_refused_before_simulating():
    with pytest.raises(ParameterError, match=r"distance=2.45 m is beyond the calibrated broad jumps of man; allowed range "
                                             r"is \[0.28, 2.28\] m \(calibrated broad jumps travel 0.30 ... 2.05 m"):
        run(RunRequest("leap", "man", params=dict(distance=2.45)))
    with pytest.raises(ParameterError, match=r"distance=0.2 m is below the calibrated broad jumps of woman; allowed range "
                                             r"is \[0.30, 1.83\] m"):
        run(RunRequest("leap", "woman", params=dict(distance=0.2)))
    with pytest.raises(ParameterError, match=r"height=1.1 m is infeasible for man with human torque limits; "
                                             r"allowed range is \[0.09, 1.00\] m \(calibrated leaps rise 0.12 ... 0.90 m\)"):
        run(RunRequest("leap", "man", params=dict(height=1.1)))
    with pytest.raises(ParameterError, match="height=1.2 m is infeasible for woman with human torque limits"):
        run(RunRequest("leap", "woman", params=dict(height=1.2)))
    with pytest.raises(ParameterError, match="height=-0.2 m is out of range"):
        run(RunRequest("leap", "man", params=dict(height=-0.2)))
    with pytest.raises(ParameterError, match="start height=-1"):
        run(RunRequest("land", "man", start=StartState(height=-1.0)))
