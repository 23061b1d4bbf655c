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


@pytest.mark.parametrize("label, params, duration", [
    ("circle r = 40 m", dict(course=3, turn_radius=40.0, turn_after=15.0), 24.0),
    ("90-degree turn r = 30 m", dict(course=1, turn_angle=math.pi / 2, turn_radius=30.0, turn_after=25.0), 32.0),
])
def test_a_gentle_curve_is_followed(label, params, duration):
    """What steering does work at 3.5 m/s: a circle of 40 m radius (curvature 0.025 1/m) and a
    90-degree turn of 30 m radius, run in and out of, without a fall and on the path."""
    traj = run_running(duration, speed=3.5, **params)
    m = traj.meta["metrics"]
    assert not_fallen(traj), f"{label}: fell at {m['fall_time']} s"
    print(f"{label}: lateral deviation mean {m['path_deviation_mean']:.3f} m, max {m['path_deviation_max']:.3f} m")
    assert m["path_deviation_mean"] < PATH_DEVIATION_GOAL
    heading = math.atan2(*traj.arrays["com_vel"][-1, 1::-1])
    expected = params.get("turn_angle", None)
    if expected is not None:                      # left the curve running in the new direction
        assert abs(heading - expected) < 0.3


def gaits_at_3_5_with(tables: dict, duration: float) -> dict:
    """label -> gait metrics of a run at 3.5 m/s with that speed table in place of the stored one."""
    return {label: run_running(duration, speed=3.5, table=table.to_table()).meta["metrics"]["gait"]
            for label, table in tables.items()}


def test_a_stiffer_thrust_lengthens_the_flight():
    """The table's thrust_gain (the knee's and ankle's position gain in the toe state): the stored
    3.5 m/s row's (about 2x the default) against the same row with the default gain - longer flights,
    a smaller share of the step on the ground."""
    stored = SpeedTable.load("man")
    assert stored.at("thrust_gain", 3.5) > 1.5
    gaits = gaits_at_3_5_with({"stored": stored, "default gain": stored.with_row(3.5, {"thrust_gain": 1.0})}, 20.0)
    print({k: (round(g["flight_time"], 3), round(g["stance_fraction"], 1)) for k, g in gaits.items()})
    assert gaits["stored"]["flight_time"] > gaits["default gain"]["flight_time"] + 0.015
    assert gaits["stored"]["stance_fraction"] < gaits["default gain"]["stance_fraction"] - 5.0


def test_a_toe_push_lengthens_the_flight():
    """The table's toe_push (the toe joint's plantarflexion target in the thrust; Hodgins et al.:
    thrust from the ankle and the metatarsal joint): the 3.5 m/s row with the toes pushing 0.6 rad
    against the same row with them held flat - longer flights, fewer steps per second."""
    stored = SpeedTable.load("man")
    gaits = gaits_at_3_5_with({label: stored.with_row(3.5, {"toe_push": push})
                               for label, push in (("flat", 0.0), ("toe push", 0.6))}, STEADY_RUN)
    print({k: (round(g["flight_time"], 3), round(g["step_frequency"], 2)) for k, g in gaits.items()})
    assert gaits["toe push"]["flight_time"] > gaits["flat"]["flight_time"] + 0.006
    assert gaits["toe push"]["step_frequency"] < gaits["flat"]["step_frequency"] - 0.1


def test_a_tuned_row_replaces_only_its_speed():
    """The tuner scores a candidate row inside the stored table (what it scores is what it writes)."""
    table = SpeedTable([2.5, 4.0], {"thrust_time": [0.2, 0.4], "idle_knee": [1.0, 2.0]})
    new = table.with_row(4.5, {"thrust_time": 0.5})
    assert new.speeds == [2.5, 4.0, 4.5]
    assert new.at("thrust_time", 4.5) == 0.5 and new.at("thrust_time", 4.0) == 0.4
    assert new.at("idle_knee", 4.5) == 2.0                        # not searched: the table's value
    assert table.with_row(4.0, {"idle_knee": 1.5}).values["idle_knee"] == [1.0, 1.5]
    # another row's stored value is kept bit for bit (interpolated at its knot, 0.1075 would come out
    # as 0.10750000000000001)
    odd = SpeedTable([4.5, 5.0], {"ground_speed_matching": [0.028467268324521088, 0.1075]})
    assert odd.with_row(4.5, {}).values["ground_speed_matching"][1] == 0.1075


def _tune_running():
    return importlib.import_module("sim_core.skills.running.calibrate")


def test_evaluation_function_adds_the_fig_12_gait_at_the_fast_end():
    """python -m sim_core calibrate running's evaluation (docs/running.md): the gait term against Fig. 12
    (step frequency, step length, stance fraction) counts from 4.5 m/s up, not at the slower
    speeds; a speed error or a Fig. 12 error beyond its band costs more."""
    tune = _tune_running()
    run_ = {"t_up": 20.0, "duration": 20.0, "mean_speed": 4.5, "head_acc_g": 0.0, "attitude_variation": 0.0,
            "gait_errors": [0.05, 0.05, 0.02]}
    assert tune.evaluation([dict(run_, speed=4.5)]) == pytest.approx(tune.W_GAIT * 0.04)
    assert tune.evaluation([dict(run_, speed=3.5, mean_speed=3.5)]) == pytest.approx(0.0)
    fell = dict(run_, speed=4.5, t_up=10.0, mean_speed=4.05, gait_errors=[0.15, 0.1, 0.05])
    assert tune.evaluation([fell]) == pytest.approx(
        tune.W_FALL * 0.5 + tune.W_SPEED * 0.1 + tune.W_BAND * (0.1 - tune.BAND) + tune.W_GAIT * 0.1
        + tune.W_GAIT_BAND * (0.15 - tune.GAIT_BAND + 0.1 - tune.GAIT_BAND))


def test_evaluation_function_scores_the_courses_on_falls_and_path_deviation():
    """--courses: a turn or a figure eight adds its lost running time and its mean lateral
    deviation (at most 1 m), averaged with the straight runs."""
    tune = _tune_running()
    straight = {"speed": 3.5, "t_up": 30.0, "duration": 30.0, "mean_speed": 3.5, "head_acc_g": 0.0,
                "attitude_variation": 0.0, "gait_errors": [0.4, 0.4, 0.4]}
    turn = {"speed": 3.5, "t_up": 12.0, "duration": 24.0, "course": True, "deviation": 0.2}
    eight = {"speed": 3.5, "t_up": 40.0, "duration": 40.0, "course": True, "deviation": 3.0}
    assert tune.evaluation([straight, turn, eight]) == pytest.approx(
        (tune.W_FALL * 0.5 + tune.W_PATH * 0.2 + tune.W_PATH * 1.0) / 3)
    assert [c["course"] for c, _ in tune.STEERING_COURSES] == [1, 2]      # the steering test's courses


def test_a_search_writes_its_rows_into_the_table_as_stored_when_it_ends():
    """Two searches of different speeds may run at once: the one that ends last keeps the other's row."""
    tune = _tune_running()
    stored_now = SpeedTable([3.5, 5.0], {"thrust_gain": [1.0, 1.7], "idle_knee": [1.5, 1.6]})   # 5.0 written meanwhile
    merged = tune.with_found_rows(stored_now, ["thrust_gain", "idle_knee"], {3.5: [2.5, 1.4]})
    assert merged.values == {"thrust_gain": [2.5, 1.7], "idle_knee": [1.4, 1.6]}


class RecordingPool:
    """Stands in for the tuner's process pool: records the runs it is asked for and answers each
    with a run at its commanded speed, without a fall, off the human figures by ``gait_errors``."""

    def __init__(self, gait_errors):
        self.jobs = []
        self.gait_errors = list(gait_errors)

    def map(self, function, jobs):
        self.jobs.extend(jobs)
        return [{"speed": job[1], "t_up": 30.0, "duration": 30.0, "mean_speed": job[1], "head_acc_g": 0.0,
                 "attitude_variation": 0.0, "gait_errors": list(self.gait_errors)} for job in jobs]


def test_faster_scores_the_candidate_row_on_the_tables_faster_speeds_too():
    """--faster: a row searched at 4.83 m/s is also run at 5.0 m/s with the same candidate table
    (the runner accelerating to 5.0 m/s passes through it); without it, only at its own speed."""
    tune = _tune_running()

    table = SpeedTable([4.5, 5.0], {"thrust_gain": [1.0, 1.7]})
    for faster, speeds in ((True, [4.83, 4.83, 5.0, 5.0]), (False, [4.83, 4.83])):
        pool = RecordingPool([0.0, 0.0, 0.0])
        tune.Evaluator(pool, table, ["thrust_gain"], 4.83, 30.0, "man", "human", faster=faster)([1.3])
        assert [job[1] for job in pool.jobs] == speeds
        assert all(job[0]["speeds"] == [4.5, 4.83, 5.0] for job in pool.jobs)    # the candidate table
    # what a search without --faster names as unchecked when it writes rows at 3.5 and 4.83 m/s
    assert tune.faster_speeds([2.5, 3.5, 4.0, 4.83, 5.0], [4.83, 3.5]) == [4.0, 4.83, 5.0]


def test_joint_search_scores_rows_at_several_speeds_together():
    """--joint: one vector holds the rows of every --speeds (4.83 and 5.0 m/s here); each evaluation
    runs every one of those speeds in the table with all its rows replaced; --gait-at makes the
    Fig. 12 term count only at the speeds named."""
    tune = _tune_running()

    table = SpeedTable([4.5, 5.0], {"thrust_gain": [1.0, 1.7], "idle_knee": [1.0, 1.0]})
    pool = RecordingPool([0.1, 0.1, 0.1])
    evaluate = tune.Evaluator(pool, table, ["thrust_gain"], [4.83, 5.0], 30.0, "man", "human", faster=True,
                              gait_speeds=[4.83])
    score = evaluate([1.3, 1.9])
    assert [job[1] for job in pool.jobs] == [4.83, 4.83, 5.0, 5.0]        # 5.0 is a row, not a faster speed
    candidate = pool.jobs[0][0]
    assert candidate["speeds"] == [4.5, 4.83, 5.0] and candidate["parameters"]["thrust_gain"] == [1.0, 1.3, 1.9]
    # the gait term (0.1 off each quantity) in the two 4.83 m/s runs only, averaged over four
    assert score == pytest.approx(2 * (tune.W_GAIT * 0.1 + tune.W_GAIT_BAND * 3 * 0.02) / 4)
    assert evaluate.row_values([1.3, 1.9]) == {4.83: [1.3], 5.0: [1.9]}
    run_ = {"speed": 5.0, "t_up": 30.0, "duration": 30.0, "mean_speed": 5.0, "head_acc_g": 0.0,
            "attitude_variation": 0.0, "gait_errors": [0.1, 0.1, 0.1]}
    assert tune.evaluation([run_], gait_speeds=[4.83]) == 0.0 and tune.evaluation([run_]) > 0.0
    # --start: one row for every searched speed, or a row per speed
    assert tune.start_rows({"thrust_gain": 1.2}, [4.83, 5.0]) == {4.83: {"thrust_gain": 1.2}, 5.0: {"thrust_gain": 1.2}}
    assert tune.start_rows({"4.83": {"thrust_gain": 1.2}}, [4.83, 5.0]) == {4.83: {"thrust_gain": 1.2}, 5.0: {}}
    with pytest.raises(SystemExit):
        tune.start_rows({"4.7": {"thrust_gain": 1.2}}, [4.83, 5.0])


def test_human_figures_are_the_papers():
    assert HUMAN_FIG12["man"] == {"speed": 4.83, "step_frequency": 2.92, "step_length": 1.66, "stance_fraction": 57.9}


def test_a_running_constant_is_a_setting_a_run_may_set_by_name():
    """The constants of the running laws are data (running_any) and settings: a tuner passes a
    candidate by name (python -m sim_core calibrate running --steering), no module is patched. The stored value
    given explicitly runs bit for bit as the default; another changes the run."""
    stored = Running.settings_schema.by_name["start_speed"].default
    default, same, other = (run_running(1.2, **extra).arrays["qpos"]
                            for extra in ({}, {"start_speed": stored}, {"start_speed": 0.3}))
    assert np.array_equal(default, same) and not np.array_equal(default, other)


# --------------------------------------------------------------------------- the woman (docs/running.md, "The woman")
def woman_speeds() -> tuple[float, float]:
    """The speeds the woman's running table covers: what she is offered."""
    speeds = SpeedTable.load("woman").speeds
    return speeds[0], speeds[-1]


def test_the_woman_is_refused_outside_her_tables_speeds():
    low, high = woman_speeds()
    knob = Running.schema.by_name["speed"]           # below or above the schema's range: its own message
    outside = [v for v in (low - 0.1, high + 0.1) if knob.minimum <= v <= knob.maximum]
    assert outside
    for speed in outside:
        with pytest.raises(ParameterError) as err:
            run(RunRequest("running", "woman", params={"speed": speed}, duration=0.05))
        message = str(err.value)
        assert "\n" not in message and f"speed={speed:g}" in message and f"[{low:g}, {high:g}]" in message, message


def test_the_womans_constants_are_the_mans_mass_scaled_and_the_man_keeps_his():
    """Her table's constants of the laws are running_any's (the man's) scaled by Fig. 6 (mass), but
    for the lean's hip damping (kept: she chatters without it) and the lean into a turn (0: she runs
    turns upright); the man runs with running_any's but for the lean's hip damping (1.0 in his table since
    issue 28's start-lean grid, docs/running.md). Her table was written before mass scaling
    scaled the per-state gain shares (unit ``share``: docs/bodies.md), so her shares are the man's,
    which her rows were searched with."""
    from sim_core.skills.running.calibrate import scaled_table
    stored = SpeedTable.load("woman")
    scaled = scaled_table("man", "woman", stored.speeds, {"start_hip_damping": 1.0, "turn_lean": 0.0})
    shares = {n for n in stored.constants if Running.settings_schema.by_name[n].unit == "share"}
    assert shares and all(stored.constants[n] == Running.settings_schema.by_name[n].default for n in shares)
    assert ({n: v for n, v in stored.constants.items() if n not in shares}
            == pytest.approx({n: v for n, v in scaled.constants.items() if n not in shares}, rel=1e-9))
    assert stored.constants["start_hip_damping"] == 1.0 and stored.constants["pitch_kd"] < 0.5 * 149.0
    assert SpeedTable.load("man").constants == {"start_hip_damping": 1.0}
    assert Running.settings_schema.by_name["start_hip_damping"].default == 0.0


@pytest.mark.slow
def test_the_woman_runs_a_random_speed_of_her_range():
    """From a stand, 30 s at a speed drawn inside her offered range: no fall, speed within 5 %."""
    low, high = woman_speeds()
    speed = float(np.random.default_rng(28).uniform(low, high))
    traj = run(RunRequest("running", "woman", params={"speed": speed}, duration=STEADY_RUN))
    m = traj.meta["metrics"]
    print(f"the woman at {speed:.3f} m/s: {traj.meta['outcome']}, mean speed over the last 10 s "
          f"{m['gait']['mean_speed']:.3f} m/s")
    assert not_fallen(traj), f"fell at {m['fall_time']:.1f} s"
    assert abs(m["gait"]["mean_speed"] - speed) <= SPEED_TOLERANCE * speed


@pytest.mark.slow
@pytest.mark.parametrize("character", ["child", "imaginary_runner"])
def test_a_scaled_character_runs_100_s_at_a_speed_of_its_table(character):
    """The child (Fig. 3, 1.08 m, 26 kg: the man's row mass-scaled, then searched; 2.5-2.8 and 3.0 m/s) and
    the imaginary runner (1.61 m, 46.5 kg: reached through bodies between the woman and it; 3.0 m/s;
    docs/running.md): 100 s from a stand at a speed drawn in the table's range, no fall, speed within
    5 %; a speed beyond the range is refused."""
    low, high = SpeedTable.load(character).offered()[0]      # the child's 2.8-3.0 m/s is refused (docs/running.md)
    speed = float(np.random.default_rng(28).uniform(low, high))
    traj = run(RunRequest("running", character, params={"speed": speed}, duration=100.0))
    m = traj.meta["metrics"]
    print(f"the {character} at {speed:.3f} m/s: mean speed over the last 10 s {m['gait']['mean_speed']:.3f} m/s")
    assert not_fallen(traj), f"fell at {m['fall_time']:.1f} s"
    assert abs(m["gait"]["mean_speed"] - speed) <= SPEED_TOLERANCE * speed
    with pytest.raises(ParameterError, match=rf"\[{low:g}, {high:g}\]"):
        run(RunRequest("running", character, params={"speed": SpeedTable.load(character).speeds[-1] + 0.2}, duration=0.05))


@pytest.mark.slow
def test_the_child_runs_20_s_at_a_random_speed_of_her_offered_range():
    """Through the CLI's parameter path (``behaviour_params``) the child fell 4.8-5.9 s from a stand at single
    speeds of 2.82-2.94 m/s (2.825, 2.8325, 2.8375, 2.84, 2.891, 2.9325); 2.8-3.0 m/s is refused since (docs/running.md,
    the child's arrival at her speed): a speed drawn in what she is offered, its top (2.8) and 3.0 run 20 s."""
    from sim_core.request import behaviour_params
    low, high = SpeedTable.load("child").offered()[0]
    drawn = round(float(np.random.default_rng(1406).uniform(low, high)), 3)
    for speed in (drawn, high, 3.0):
        traj = run(RunRequest("running", "child", params=behaviour_params("running", "child", {"speed": speed}),
                              duration=20.0))
        assert not_fallen(traj), f"{speed} m/s: fell at {traj.meta['metrics']['fall_time']:.2f} s"


@pytest.mark.parametrize("speed, allowed", [(2.45, "[2.5, 5]"), (2.825, "[2.5, 2.8] or [3, 3]"),
                                            (2.95, "[2.5, 2.8] or [3, 3]"), (3.05, "[2.5, 2.8] or [3, 3]")])
def test_a_child_speed_outside_what_she_is_offered_is_refused_in_one_line(speed, allowed):
    """The child is offered 2.5-2.8 and 3.0 m/s (2.8-3.0 refused: single speeds fell there, docs/running.md); any
    other speed is refused before anything runs, naming what is allowed (below 2.5 m/s the schema's own range,
    whose floor is hers)."""
    from sim_core.request import behaviour_params
    with pytest.raises(ParameterError) as error:
        run(RunRequest("running", "child", params=behaviour_params("running", "child", {"speed": speed}), duration=0.05))
    text = str(error.value)
    assert "\n" not in text and f"speed={speed:g}" in text and allowed in text, text


@pytest.mark.parametrize("character, values, words", [
    ("woman", {"course": "turn", "turn_radius": 15.0}, ["radius of 14.9", f"at most {steering_limits('woman')[1]:g} m/s^2", "(the woman)"]),
    ("woman", {"facing": 1.0, "turn_radius": 10.0}, ["radius of 9.98 m", "radius >= 22.5 m", "(the woman)"]),
    ("woman", {"course": "circle", "speed": 3.5, "turn_radius": 50.0}, ["by the woman at speed <= 3.35 m/s", "asked: 3.5 m/s"]),
    ("child", {"course": "circle", "speed": 2.5, "turn_radius": 5.0}, ["at most 0.9 m/s^2", "(the child)"]),
    ("imaginary_runner", {"course": "turn"}, ["straight ahead"]),
])
def test_a_turn_beyond_the_runners_limit_is_refused_in_one_line(character, values, words):
    """The woman and the child turn up to their measured lateral accelerations; the imaginary runner
    runs straight ahead only: anything else is refused before anything runs."""
    with pytest.raises(ParameterError) as error:
        run(RunRequest("running", character, params={"speed": 3.0, **values}, duration=0.05))
    text = str(error.value)
    assert "\n" not in text and all(word in text for word in words), text


@pytest.mark.parametrize("character, kind, params, duration",
                         [("woman", *draw) for draw in steering_draws(28, 2, "woman")]
                         + [("child", *draw) for draw in steering_draws(28, 1, "child")])
def test_a_scaled_runner_runs_a_random_curve_inside_its_limit(character, kind, params, duration):
    """Curves drawn inside the woman's and the child's offered regions (a fixed seed; runs cut to 25 s:
    the lead-in, where the woman used to fall at 4.1 s, and the curve's entry): no fall, on the path
    (docs/running.md, the woman, the child)."""
    traj = run(RunRequest("running", character, params=params, duration=min(duration, 25.0)))
    m = traj.meta["metrics"]
    assert not_fallen(traj), f"{kind} {params}: fell at {m['fall_time']:.1f} s"
    assert m["path_deviation_mean"] < PATH_DEVIATION_GOAL, (kind, params, m["path_deviation_mean"])


def test_the_fig12_table_has_a_row_per_runner_of_the_figure():
    """report running --fig12: man, woman and child, each at its table's speed nearest Fig. 12's
    (short runs here; the report's are 30 s)."""
    from sim_core.skills.running.report import fig12_markdown
    rows = fig12_markdown(duration=4.0).splitlines()[2:]
    assert [r.split(" | ")[0] for r in rows] == ["| man", "| woman", "| child"]
    from sim_core.gait import HUMAN_FIG12
    nearest = [min(SpeedTable.load(c).speeds, key=lambda v: abs(v - HUMAN_FIG12[c]["speed"])) for c in ("man", "woman", "child")]
    assert [r.split(" | ")[2] for r in rows] == [f"{v:g}" for v in nearest]


@pytest.mark.parametrize("table", ["foo", 1, {"speeds": 3.5}])
def test_a_table_parameter_that_is_not_a_table_is_refused_in_one_line(table):
    """``table`` is a tuner's parameter; given by hand as something else (``--set table=foo``) it is
    refused naming what it must be, not a traceback."""
    with pytest.raises(ParameterError, match="is not a running table"):
        Running.schema.validate({"table": table})


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
