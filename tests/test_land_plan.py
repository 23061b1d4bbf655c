"""The landing's per-request plan above the loop (sim_core/planning/land.py): random drops anywhere in
each character's offered range land balanced (TARGETS.md "Landing": -1.0 ... +3.0 m/s horizontal
COM speed, ending balanced; the child: her table's range), the plan's run replays bit for bit, and a
request nothing within the bound lands says so."""
import json
import pickle

import pytest

from sim_core import tuned
from sim_core.cli import main
from sim_core.control.leap import landing_side_speed
from sim_core.planning.land import LandingTrial, candidates, plan_landing
from sim_core.simulate import RunRequest, StartState
from sim_core.skills.land.calibrate_grid import grid
from sim_core.skills.land.report import offered, planned_landing, random_drops
from sim_core.tuning import Space, SerialExecutor, minimize

TARGET_SPEEDS = (-1.0, 3.0)      # m/s: TARGETS.md "Landing", horizontal speed
SKID_LIMIT = 0.05                # m: TARGETS.md via leap_assess, the feet stay where they touched down


def test_the_plan_tries_the_request_first_then_steps_on_either_side_nearest_first():
    assert candidates(0.0, 0.01, 5, -0.3, 0.3) == [0.0, 0.01, -0.01, 0.02, -0.02]
    assert candidates(0.29, 0.01, 4, -0.3, 0.3) == [0.29, 0.3, 0.28, 0.27]      # inside the schema's range
    assert candidates(0.0, 0.01, 1, -0.3, 0.3) == [0.0]
    assert grid("man").delta_step == 0.02 and grid("child").delta_step == pytest.approx(0.0092)


def test_random_drops_are_drawn_inside_the_offered_range_and_differ_by_seed():
    """Rounded to mm and cm/s, never out of the range (the child's slowest -0.6765 m/s is drawn as -0.67);
    the drop inside what the body lands at the speed drawn, the sideways speed inside what it lands."""
    for character in ("man", "woman", "child", "imaginary_runner"):
        (h0, h1), (v0, v1) = offered(character)
        draws = [random_drops(character, 20, seed) for seed in range(1, 30)]
        table = tuned.load("landing", character)
        assert all(h0 <= h <= h1 and v0 <= v <= v1 and abs(w) <= landing_side_speed(table, h) for d in draws for h, v, w in d)
        assert draws[0] == random_drops(character, 20, 1) != draws[1]


def _score(settings):
    return (0.0 if settings["x"] >= 0.3 else 1.0), settings["x"]


def test_the_search_services_scan_evaluates_the_points_in_order_and_stops_at_the_first_accepted():
    space = Space({"x": (0.0, 1.0)}, decimals=4)
    points = [{"x": v} for v in (0.1, 0.2, 0.35, 0.3, 0.9)]
    for population in (None, 2, 3):
        result = minimize(_score, space, method="scan", budget=10, start={"x": 0.0}, population=population,
                          stop=lambda e: e.score == 0.0, options={"points": points}, executor=SerialExecutor())
        assert [e.settings["x"] for e in result.evaluations] == [0.0, 0.1, 0.2, 0.35] and result.ended == "stop"
    result = minimize(_score, space, method="scan", budget=10, start={"x": 0.0}, options={"points": points[:2]})
    assert result.ended == "scanned" and len(result.evaluations) == 3


def test_a_landing_trial_can_go_to_a_process_pool():
    request = RunRequest("land", "man", start=StartState(height=0.3, velocity=(1.0, 0.0, 0.0)))
    assert pickle.loads(pickle.dumps(LandingTrial(request))).request == request


@pytest.mark.parametrize("character, count", [("man", 2), ("woman", 2), ("child", 2), ("imaginary_runner", 2)])
def test_random_drops_in_the_offered_range_land_balanced(character, count):
    """A few drops drawn at random (seed 11) in what the character's table offers, each planned and
    run as ``simulate land`` does: every one balanced, the feet staying where they touched down.
    (The figures over many draws: docs/bodies.md, ``python -m sim_core report land --random``.)"""
    (h0, h1), (v0, v1) = offered(character)
    if character in ("man", "woman"):
        assert (v0, v1) == TARGET_SPEEDS
    for drop, speed, side in random_drops(character, count, seed=11):
        assert h0 <= drop <= h1 and v0 <= speed <= v1
        result = planned_landing(character, drop, speed, side)
        plan = result["plan"]
        assert result["outcome"] == "success" and plan["found"], (drop, speed, plan["tried"])
        assert plan["tried"][-1]["landing_skid"] <= SKID_LIMIT


def test_a_planned_landing_logs_its_foot_delta_and_replays_bit_for_bit(tmp_path, capsys):
    """The woman from 0.515 m at +2.11 m/s falls on her table's placement and balances a few plan
    steps from it: the run logs the chosen foot_delta and replays exactly."""
    out = tmp_path / "land.npz"
    assert main(["simulate", "land", "--character", "woman", "--start-height", "0.515", "--start-velocity",
                 "2.11,0,0", "--workers", "1", "--out", str(out)]) == 0
    captured = capsys.readouterr()
    summary = json.loads(captured.out.strip().splitlines()[-1])
    assert summary["outcome"] == "success" and summary["plan"]["found"] and summary["plan"]["trials"] > 1
    assert summary["plan"]["tried"][0]["outcome"] != "success"
    assert summary["plan"]["foot_delta"] == summary["plan"]["tried"][-1]["foot_delta"] != 0.0
    from sim_core.trajectory import Trajectory
    assert Trajectory.load(out).meta["params"]["foot_delta"] == summary["plan"]["foot_delta"]
    assert "ends balanced" in captured.err
    assert main(["replay", str(out)]) == 0
    assert json.loads(capsys.readouterr().out.strip().splitlines()[-1])["bit_identical"]


def test_a_plan_that_finds_nothing_within_its_bound_says_so_with_the_measured_figures(capsys):
    request = RunRequest("land", "woman", params={"plan_trials": 1},
                         start=StartState(height=0.515, velocity=(2.11, 0.0, 0.0)))
    ran, plan = plan_landing(request)
    assert ran is request and not plan["found"] and plan["trials"] == 1
    assert plan["tried"][0]["outcome"] != "success" and plan["tried"][0]["landing_skid"] > SKID_LIMIT
    assert main(["simulate", "land", "--character", "woman", "--start-height", "0.515", "--start-velocity",
                 "2.11,0,0", "--set", "plan_trials=1", "--workers", "1"]) == 0
    captured = capsys.readouterr()
    assert "NOT FOUND" in captured.err and "skid" in captured.err
    summary = json.loads(captured.out.strip().splitlines()[-1])
    assert summary["plan"]["found"] is False and summary["outcome"] != "success"


def test_a_child_landing_faster_than_her_table_is_refused_before_a_plan_runs(capsys):
    (_, _), (low, high) = offered("child")
    assert main(["simulate", "land", "--character", "child", "--start-height", "0.2", "--start-velocity",
                 f"{high + 0.3:.2f},0,0", "--workers", "1"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err[-1].startswith("error: ") and "landing range" in err[-1] and not any("landing plan" in e for e in err)


def test_a_landing_table_that_serves_no_speed_is_refused_in_one_line_not_a_crash():
    """A body whose calibration balanced no landing (the imaginary cyclist's sweep) has rows with no
    speed: the land skill refuses it in one line, and the fast-touchdown scan has nothing to add to."""
    from sim_core.control.leap import landing_speeds
    from sim_core.errors import ParameterError
    from sim_core.skills.land.calibrate import fast_touchdown
    empty = {"foot_delta": [{"drop": 0.2, "touchdown_speed": 2.0, "speed": [], "delta": []}]}
    with pytest.raises(ParameterError, match="serves no horizontal speed"):
        landing_speeds(empty)
    assert fast_touchdown("man", empty) is None


def test_the_drops_offered_at_a_speed_are_the_narrower_of_the_two_measured_speeds_around_it():
    from sim_core.control.leap import landing_drops, landing_side_speed
    rows = {"foot_delta": [{"drop": 0.2, "touchdown_speed": 2.0, "speed": [-1.0, 3.0], "delta": [0.0, 0.0]},
                           {"drop": 0.6, "touchdown_speed": 3.4, "speed": [-1.0, 3.0], "delta": [0.0, 0.0]}]}
    assert landing_drops(rows, 1.0) == (0.2, 0.6) and landing_side_speed(rows, 0.3) == 0.0    # unmeasured: the rows
    table = dict(rows, drop_limits={"speeds": [0.0, 1.0, 2.0], "low": [0.0, 0.1, 0.2], "high": [1.5, 1.0, 0.6],
                                    "side": 0.3})
    assert landing_drops(table, 1.0) == (0.1, 1.0)          # a measured speed: its own
    assert landing_drops(table, 1.5) == (0.2, 0.6)          # between two: the narrower
    assert landing_drops(table, 0.2) == (0.1, 1.0) and landing_side_speed(table, 0.6) == 0.3
    assert landing_side_speed(table, 0.61) == 0.0             # above the rows: straight ahead only


@pytest.mark.parametrize("character", ["man", "woman", "child", "imaginary_runner"])
def test_a_drop_or_a_sideways_speed_beyond_what_the_body_lands_is_refused_in_one_line_before_simulating(character):
    """Measured (calibrate land --drop-limits): each body lands drops up to a height that depends on
    its forward speed, and sideways speeds up to a limit; beyond them it falls, so it is refused."""
    from sim_core.control.leap import landing_drops, landing_side_speed
    from sim_core.errors import ParameterError
    from sim_core.simulate import run
    table = tuned.load("landing", character)
    (_, _), (low, high) = offered(character)
    assert "drop_limits" in table
    for speed in (low, high):
        too_high = landing_drops(table, speed)[1] + 0.05
        with pytest.raises(ParameterError, match=r"drop of .* out of the .* landing range: at that speed it lands"):
            run(RunRequest("land", character, start=StartState(height=too_high, velocity=(speed, 0.0, 0.0))))
    top = max(row["drop"] for row in table["foot_delta"] if row["speed"])
    for drop in (top, top + 0.02):
        side = landing_side_speed(table, drop) + 0.05
        with pytest.raises(ParameterError, match=r"sideways\) is out of the .* landing range"):
            run(RunRequest("land", character, start=StartState(height=drop, velocity=(0.0, -side, 0.0))))
