"""Running (Hodgins et al. 1995; Hodgins & Pollard 1997), measured off the simulation and compared
with TARGETS.md "Running". Every run starts from the standing pose.

Targets the controller does not reach yet are listed in SHORTFALLS (see docs/running.md): for
those, a miss is reported as xfail with the measured figures in the reason, and a hit passes;
every other case must meet its target."""
import math

import mujoco
import numpy as np
import pytest

from sim_core.character.model import compile_model, set_standing_pose
from sim_core.character.spec import load_character
from sim_core.skills.running.behaviour import (Running, SpeedTable,
                                               offered_speeds)
from sim_core.skills.running.leg import RunnerLeg
from sim_core.control.path import PathFollower, path_deviation, turn_path
from sim_core.errors import ParameterError
from sim_core.gait import HUMAN_FIG12, STEADY_RUN, compare_with_human
from sim_core.simulate import RunRequest, largest_difference, replay, run

import importlib

SPEED_TOLERANCE = 0.05          # TARGETS.md: mean speed over the last 10 s within 5 %
FIG12_TOLERANCE = 0.10          # TARGETS.md: each gait figure within 10 % of the human one
PATH_DEVIATION_GOAL = 0.3       # m, mean lateral deviation from the path
# measured shortfalls (docs/running.md, "Limitations"): not reached yet (a fall, or a speed or gait off target)
SHORTFALLS = {"gait 4.83"}


def miss(case, message):
    """Fail, or xfail if the case is a documented shortfall."""
    if case in SHORTFALLS:
        pytest.xfail(f"{case}: {message}")
    pytest.fail(f"{case}: {message}")


def run_running(duration, **params):
    return run(RunRequest("running", "man", params=params, duration=duration))


def not_fallen(traj):
    m = traj.meta["metrics"]
    return traj.meta["outcome"] == "success" and not m["fell"]


# --------------------------------------------------------------------------- fast checks
@pytest.mark.parametrize("params, words", [
    ({"speed": 2.4}, ["speed=2.4", "[2.5, 5]"]),
    ({"speed": 5.1}, ["speed=5.1", "[2.5, 5]"]),
    ({"speed": float("nan")}, ["speed", "not finite"]),
    ({"path": [[0.0, 0.0]]}, ["path", "at least 2"]),
    ({"path": [[0.0, 0.0], [0.0, 0.0], [0.01, 0.0]]}, ["path", "degenerate"]),
    ({"path": "0,0; 1,0"}, ["path", "degenerate"]),
    ({"path": "0,0; a,b"}, ["path"]),
    ({"course": 1.5}, ["course=1.5"]),
])
def test_bad_input_is_refused_before_simulating(params, words):
    with pytest.raises(ParameterError) as err:
        run(RunRequest("running", "man", params=params, duration=1.0))
    for word in words:
        assert word in str(err.value)


def test_leg_inverse_kinematics_puts_the_ankle_where_asked():
    """The closed-form leg IK of the flight controller, checked on the model's own kinematics."""
    ch = load_character("man")
    model, _ = compile_model(ch)
    data = mujoco.MjData(model)
    for side, c in (("R", "r"), ("L", "l")):
        leg = RunnerLeg(ch, side)
        for target in [(0.3, 0.0, -0.8), (0.1, 0.05, -0.85), (-0.2, -0.05, -0.7), (0.35, 0.1, -0.6)]:
            set_standing_pose(model, data, ch)
            hy, hx, knee = leg.hip_knee_for(*target)
            for name, value in ((f"hip_{c}_y", hy), (f"hip_{c}_x", hx), (f"knee_{c}_y", knee)):
                data.qpos[model.joint(name).qposadr[0]] = value
            mujoco.mj_kinematics(model, data)
            ankle = data.xpos[model.body("FOOT" + side).id] - data.xpos[model.body("ULEG" + side).id]
            np.testing.assert_allclose(ankle, target, atol=0.01)


def test_path_follower_heads_along_a_turn():
    path = turn_path(math.pi / 2, 5.0, 3.0)
    follower = PathFollower(path, lookahead=2.0)
    assert follower.heading(0.0, 0.0) == pytest.approx(0.0, abs=1e-9)
    for x, y in ((2.0, 0.0), (4.0, 0.0), (6.5, 0.4), (7.6, 1.5), (8.0, 3.0)):   # walked along the path
        follower.heading(x, y)
    assert follower.heading(8.0, 4.0) == pytest.approx(math.pi / 2, abs=0.05)
    assert path_deviation(path, np.array([[2.0, 0.3], [8.0, 5.0]])) == pytest.approx([0.3, 0.0], abs=1e-6)


def test_replay_of_a_run_is_bit_identical():
    traj = run_running(2.0, speed=3.5)
    assert largest_difference(traj, replay(traj)) == 0.0


# --------------------------------------------------------------------------- behaviour
MAN_SPEEDS = offered_speeds("man")      # the offered rows: 2.5-4.5 m/s (docs/running.md, the 100 s audit, issue 28)


@pytest.mark.parametrize("speed", MAN_SPEEDS)
def test_commanded_speed_is_held(speed):
    """From a stand, 30 s (STEADY_RUN): no fall, and the mean speed over the last 10 s within 5 %."""
    traj = run_running(STEADY_RUN, speed=speed)
    m = traj.meta["metrics"]
    measured = m["gait"]["mean_speed"]
    if not not_fallen(traj):
        miss(f"speed {speed}", f"fell at {m['fall_time']:.1f} s (mean speed before it {measured:.2f} m/s)")
    print(f"commanded {speed} m/s: mean speed over the last 10 s {measured:.3f} m/s")
    if abs(measured - speed) > SPEED_TOLERANCE * speed:
        miss(f"speed {speed}", f"mean speed {measured:.3f} m/s, {100 * (measured - speed) / speed:+.1f} %")


@pytest.mark.slow
@pytest.mark.parametrize("speed", [3.0, MAN_SPEEDS[-1]])
def test_100_s_without_falling(speed):
    traj = run_running(100.0, speed=speed)
    if not not_fallen(traj):
        miss(f"100 s at {speed}", f"fell at {traj.meta['metrics']['fall_time']:.1f} s")


def test_start_from_a_stand_into_3_5_m_s_within_5_s():
    traj = run_running(8.0, speed=3.5)
    m = traj.meta["metrics"]
    assert not_fallen(traj)
    print(f"90 % of 3.5 m/s reached {m['time_to_90pct_speed']} s after the start")
    assert m["time_to_90pct_speed"] is not None and m["time_to_90pct_speed"] <= 5.0


def test_gait_against_fig_12():
    """Fig. 12's man runs at 4.83 m/s, above the man's offered range (refused): the gait at the speed
    of his table nearest it, beside the human figures, as `report running --fig12` shows it."""
    speed = min(MAN_SPEEDS, key=lambda v: abs(v - HUMAN_FIG12["man"]["speed"]))
    traj = run_running(STEADY_RUN, speed=speed)
    comparison = compare_with_human(traj.meta["metrics"]["gait"], "man")      # the 10 s before a fall, if any
    for key, row in comparison.items():
        print(f"{key} at {speed} m/s: simulated {row['simulated']:.3f}, human {row['human']} (Fig. 12, 4.83 m/s), "
              f"error {100 * row['relative_error']:+.1f} %")
    if not not_fallen(traj):
        miss("gait 4.83", f"fell at {traj.meta['metrics']['fall_time']:.1f} s")
    worst = max(abs(row["relative_error"]) for row in comparison.values())
    if speed != HUMAN_FIG12["man"]["speed"]:
        miss("gait 4.83", f"4.83 m/s is not offered (the man's table ends at {speed:g} m/s); at {speed:g} m/s off the "
                          f"human figures by up to {100 * worst:.0f} % (goal 10 %)")
    if worst > FIG12_TOLERANCE:
        miss("gait 4.83", f"off the human figures by up to {100 * worst:.0f} % (goal 10 %)")


@pytest.mark.parametrize("course, params, duration", [
    # loops of radius 20 m: 100 s is a whole eight and a third (each curvature, both crossings)
    pytest.param("figure eight", dict(course=2, turn_radius=20.0, turn_after=25.0), 100.0, marks=pytest.mark.slow),
])
def test_steering_along_a_path(course, params, duration):
    """At 3.5 m/s: a figure eight of radius-20 m loops (0.61 m/s^2, inside the offered region)."""
    traj = run_running(duration, speed=3.5, **params)
    m = traj.meta["metrics"]
    deviation = f"lateral deviation mean {m['path_deviation_mean']:.3f} m, max {m['path_deviation_max']:.3f} m"
    print(f"{course}: {deviation}")
    if not not_fallen(traj):
        miss(course, f"fell at {m['fall_time']:.1f} s; {deviation}")
    if m["path_deviation_mean"] >= PATH_DEVIATION_GOAL:
        miss(course, f"{deviation} (goal: mean < 0.3 m)")
    if params["course"] == 2 and duration > 60.0:     # round both loops (left of the start line, then right)
        y = traj.arrays["com"][:, 1]
        assert y.max() > 1.8 * params["turn_radius"] and y.min() < -1.8 * params["turn_radius"]


def steering_limits(character: str) -> tuple[float, float]:
    """The runner's table's steering limits: (fastest speed, largest lateral acceleration)."""
    steering = SpeedTable.load(character).steering
    return steering["max_speed"], steering["max_lateral_acceleration"]


def steering_draws(seed: int, count: int, character: str = "man") -> list[tuple[str, dict, float]]:
    """Requests drawn inside the region where the runner's steering is offered (its table's limits,
    docs/running.md): a speed from 2.5 m/s to its fastest, a radius from the tightest offered at that speed to 1.6 times it, and by turns a
    turn by a random angle, a figure eight, a circle and a random facing; the run's duration takes
    it through the curve (1.35 loops of an eight or a circle, at most 60 s)."""
    fastest, limit = steering_limits(character)
    rng = np.random.default_rng(seed)
    draws = []
    for k in range(count):
        v = round(float(rng.uniform(2.5, fastest)), 2)
        tightest = v * v / limit
        params = dict(speed=v, turn_radius=round(float(rng.uniform(tightest, 1.6 * tightest)), 1), turn_after=15.0)
        kind = ("turn", "figure_eight", "circle", "facing")[k % 4]
        if kind in ("turn", "facing"):
            angle = round(float(rng.uniform(-math.pi, math.pi)), 2)
            params.update(course="turn", turn_angle=angle) if kind == "turn" else params.update(facing=angle)
            duration = 5.0 + (15.0 + abs(angle) * params["turn_radius"]) / v + 10.0
        else:
            params["course"] = kind
            duration = min(60.0, 5.0 + (15.0 + 1.35 * 2 * math.pi * params["turn_radius"]) / v)
        draws.append((kind, params, duration))
    return draws


@pytest.mark.parametrize("kind, params, duration", steering_draws(2912, 2))
def test_a_random_curve_inside_the_offered_region_is_run(kind, params, duration):
    """Random curves inside the offered region (a fixed seed for CI): no fall, on the path."""
    traj = run(RunRequest("running", "man", params=params, duration=duration))
    m = traj.meta["metrics"]
    assert not_fallen(traj), f"{kind} {params}: fell at {m['fall_time']:.1f} s"
    assert m["path_deviation_mean"] < PATH_DEVIATION_GOAL, (kind, params, m["path_deviation_mean"])


@pytest.mark.parametrize("params, words", [
    (dict(speed=3.5, course="turn", turn_radius=10.0), ["radius of 9.9", "1.2", "0.625 m/s^2", "radius >= 19.6 m"]),
    (dict(speed=3.5, course="figure_eight", turn_radius=10.0), ["radius of 10.00 m", "radius >= 19.6 m"]),
    (dict(speed=3.6, course="circle", turn_radius=50.0), ["speed <= 3.5 m/s", "asked: 3.6 m/s"]),
    (dict(speed=3.6, facing=0.5), ["speed <= 3.5 m/s"]),
    (dict(speed=3.0, path=[[0.0, 0.0], [10.0, 0.0], [10.0, 10.0]]), ["radius of 1.77 m", "radius >= 14.4 m"]),
])
def test_a_curve_outside_the_offered_region_is_refused_in_one_line(params, words):
    """Measured: every curve at 3.75 m/s and faster fell, and tighter curves than 0.625 m/s^2 (the
    90-degree turn and the figure eight of radius 10 m at 3.5 m/s fell or were not reliably run);
    refused before simulating, naming what would do."""
    with pytest.raises(ParameterError) as err:
        run(RunRequest("running", "man", params=params, duration=1.0))
    text = str(err.value)
    assert "\n" not in text and all(word in text for word in words), text


def test_a_straight_path_is_run_at_any_speed_of_the_table():
    """A path with no bend along the runner's heading asks no steering: offered at the table's top speed too."""
    run(RunRequest("running", "man", params=dict(speed=MAN_SPEEDS[-1], path=[[0.0, 0.0], [80.0, 0.0]]), duration=0.05))


@pytest.mark.parametrize("speed", [4.55, 4.83, 5.0])
def test_the_man_is_refused_where_100_s_runs_fell(speed):
    """The 100 s audits (docs/running.md, Limitations): from a stand the man fell at 4.55 m/s and faster;
    his table offers 2.5-4.5 m/s (3.7-4.05 m/s again since the arms take the yaw, issue 28), and a speed
    outside it is refused naming the allowed range."""
    with pytest.raises(ParameterError) as err:
        run(RunRequest("running", "man", params=dict(speed=speed), duration=1.0))
    text = str(err.value)
    assert "[2.5, 4.5] m/s" in text and "the man's running table" in text and "\n" not in text, text


@pytest.mark.parametrize("lean", [Running.schema.by_name["start_lean"].minimum, 0.6,
                                  Running.schema.by_name["start_lean"].maximum])
def test_the_man_starts_with_any_offered_start_lean(lean):
    """With the man's hip undamped in the lean (``start_hip_damping`` 0) the start fell 0.7-1.9 s in for
    start_lean 0.1, 0.2, 0.25, 0.6, 0.8, 0.9 and 1.0 s at every speed (docs/running.md, the start lean); with
    the damping kept (1.0 in his table's constants, as the woman's and the child's) every lean starts."""
    assert SpeedTable.load("man").constants.get("start_hip_damping") == 1.0
    traj = run_running(5.0, speed=3.0, start_lean=lean)
    assert not_fallen(traj), f"start_lean {lean} s: fell at {traj.meta['metrics']['fall_time']:.1f} s"


def test_the_arms_take_the_yaw_inside_the_former_gap():
    """3.9 m/s fell at 12.8 s with every row tried before (docs/running.md, Limitations, the arms take the
    yaw): with the arms turned about the trunk by the pelvis's yaw error (``arm_yaw`` of the man's 3.7 m/s
    row) he runs on, the pelvis's yaw rate lower than with ``arm_yaw`` 0 before that fall."""
    man = SpeedTable.load("man")
    assert man.refused == [] and man.offers(3.9)
    column = man.to_table()["parameters"]["arm_yaw"]
    assert column[man.speeds.index(3.7)] > 0 and column[man.speeds.index(3.5)] == 0 == column[man.speeds.index(4.0)]
    off = man.to_table()
    off["parameters"]["arm_yaw"] = [0.0] * len(off["speeds"])
    rates = []
    for params in (dict(speed=3.9), dict(speed=3.9, table=off)):
        traj = run_running(20.0, **params)
        a = traj.arrays
        window = (a["time"] >= 5.0) & (a["time"] <= 11.0)
        rates.append(float(np.mean(np.abs(a["qvel"][window, 5]))))       # the pelvis's (root's) yaw rate
        if "table" not in params:
            assert not_fallen(traj), f"fell at {traj.meta['metrics']['fall_time']:.1f} s"
    print(f"3.9 m/s, mean |pelvis yaw rate| 5-11 s: arms {rates[0]:.2f}, without {rates[1]:.2f} rad/s")
    assert rates[0] < 0.9 * rates[1], rates


def test_the_refused_speeds_are_data_of_the_runners_table():
    """A runner's refused ranges (the man's was (3.7, 4.05) m/s until issue 28's fifth round) are his table's
    ``refused_speeds`` (docs/running.md), carried by the reader, ``to_table`` (a tuner's candidate) and
    ``with_row`` (the calibration writer's table); a malformed range is refused in one line."""
    man = SpeedTable.from_table(dict(SpeedTable.load("man").to_table(), refused_speeds=[[3.7, 4.05]]))
    assert man.refused == [(3.7, 4.05)] and man.offered() == [(2.5, 3.7), (4.05, 4.5)]
    assert not man.offers(3.8) and man.offers(3.7) and man.offers(4.05)
    again = SpeedTable.from_table(man.with_row(3.85, {}).to_table())
    assert again.refused == man.refused and again.to_table()["refused_speeds"] == [[3.7, 4.05]]
    assert "refused_speeds" not in SpeedTable.load("woman").to_table()       # she has none: every speed of hers runs
    assert "refused_speeds" not in SpeedTable.load("man").to_table()
    for bad in ([[4.0, 3.8]], [[2.0, 3.0]], [3.8], "3.8-3.9"):
        with pytest.raises(ParameterError) as err:
            Running.schema.validate({"table": dict(man.to_table(), refused_speeds=bad)})
        assert "refused_speeds" in str(err.value) and "\n" not in str(err.value)


def test_the_steering_limits_are_data_of_the_runners_table():
    """Where each runner turns (its fastest speed and lateral acceleration, docs/running.md) is its table's
    ``steering``, carried by ``to_table`` and ``with_row``; a runner whose table has none (the imaginary
    runner) and a character without a table of its own runs straight only; a malformed entry is refused in
    one line."""
    assert {n: steering_limits(n) for n in ("man", "woman", "child")} == {
        "man": (3.5, 0.625), "woman": (3.35, 0.4), "child": (2.5, 0.9)}
    assert SpeedTable.load("imaginary_runner").steering is None
    man = SpeedTable.load("man")
    assert SpeedTable.from_table(man.with_row(3.85, {}).to_table()).steering == man.steering
    for bad in ({"max_speed": 3.5}, {"max_speed": -1, "max_lateral_acceleration": 0.5}, [3.5, 0.6]):
        with pytest.raises(ParameterError) as err:
            Running.schema.validate({"table": dict(man.to_table(), steering=bad)})
        assert "steering" in str(err.value) and "\n" not in str(err.value)


def test_the_womans_start_lean_is_refused_beyond_what_was_measured():
    """Her start fell at 3.2 s with start_lean 1.0 s at every speed and ran at 0.1-0.7 s (docs/running.md, the start
    lean): her table's ``start_lean`` max 0.7 s, carried by ``to_table``; a longer lean is refused in one line naming
    the range, before anything runs; the man (no limit in his table) takes the schema's whole range."""
    woman = SpeedTable.load("woman")
    assert woman.start_lean["max"] == 0.7 and SpeedTable.load("man").start_lean is None
    assert SpeedTable.from_table(woman.to_table()).start_lean == woman.start_lean
    with pytest.raises(ParameterError) as err:
        run(RunRequest("running", "woman", params={"speed": 3.0, "start_lean": 0.9}, duration=0.05))
    assert "[0.1, 0.7] s" in str(err.value) and "\n" not in str(err.value)
