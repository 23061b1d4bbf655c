"""The FINA repertoire (issue 29): ``--set dive=107C`` reads a FINA number into the dive's group,
somersaults, twists and position; a number that is malformed, of a form not built or outside the
repertoire is refused in one line before anything runs; the repertoire's dives from 10 m are
simulated and judged off the simulation, and a dive the calibration did not reach is refused
naming the angular momentum it needs and the one reached."""
from pathlib import Path

import numpy as np
import pytest

from sim_core.errors import ParameterError
from sim_core.simulate import RunRequest, run
from sim_core.skills.dive.behaviour import Dive, GROUPS, ROTATION_TOLERANCE, calibrated_row
from sim_core.skills.dive.fina import REPERTOIRE, parse
from sim_core.control.tumble import position_name
from sim_core import tuned


def dive(number: str) -> dict:
    p = Dive.schema.validate({"dive": number})
    return dict(group=GROUPS[int(p["group"])], somersaults=p["somersaults"], twists=p["twists"],
                position=position_name(p["position"]))


@pytest.mark.parametrize("number, wanted", [
    ("107C", dict(group="forward", somersaults=3.5, twists=0.0, position="tuck")),
    ("109c", dict(group="forward", somersaults=4.5, twists=0.0, position="tuck")),
    ("205B", dict(group="back", somersaults=2.5, twists=0.0, position="pike")),
    ("305C", dict(group="reverse", somersaults=2.5, twists=0.0, position="tuck")),
    ("407C", dict(group="inward", somersaults=3.5, twists=0.0, position="tuck")),
    ("5253B", dict(group="back", somersaults=2.5, twists=1.5, position="pike")),
    ("5231D", dict(group="back", somersaults=1.5, twists=0.5, position="tuck")),     # free: tucked, a half twist
    ("5235D", dict(group="back", somersaults=1.5, twists=2.5, position="layout")),   # free: layout, 2 1/2 twists
    ("5154B", dict(group="forward", somersaults=2.5, twists=2.0, position="pike")),
])
def test_a_fina_number_sets_group_somersaults_twists_and_position(number, wanted):
    assert dive(number) == wanted


def test_every_repertoire_number_is_in_the_schemas_ranges_and_custom_keeps_the_parameters():
    for number in REPERTOIRE:
        assert parse(number).number == number
        Dive.schema.validate({"dive": number})              # in range: no ParameterError
    custom = Dive.schema.validate({"group": "back", "somersaults": 2.5, "position": "pike"})
    assert (custom["group"], custom["somersaults"], custom["position"]) == (1.0, 2.5, 1.0)


def test_the_number_overrides_the_four_parameters_as_the_panel_sends_them():
    """The panel sends every knob; a dive number other than custom decides."""
    p = Dive.schema.validate({"dive": "407C", "group": "back", "somersaults": 1.5, "position": "layout"})
    assert dive("407C") == dict(group=GROUPS[int(p["group"])], somersaults=p["somersaults"], twists=p["twists"],
                                position=position_name(p["position"]))


@pytest.mark.parametrize("number, match", [
    ("108X", "not a FINA dive number: group 1-4"),
    ("12C", "not a FINA dive number"),
    ("5250B", "not a FINA dive number"),
    ("113C", "flying dives"),
    ("626C", "armstand dives"),
    ("105D", "position D .* twisting dives"),
    ("103A", "103A is not in the repertoire.*allowed dives are 103B"),
    ("", "not a FINA dive number"),
])
def test_a_bad_dive_number_is_refused_in_one_line_before_anything_runs(number, match):
    """The schema refuses it (validation comes before a model is built)."""
    with pytest.raises(ParameterError, match=match) as error:
        Dive.schema.validate({"dive": number})
    assert "\n" not in str(error.value)
    with pytest.raises(ParameterError, match=match):
        run(RunRequest("dive", "man", params={"dive": number}))


def test_the_cli_refuses_a_bad_dive_number_in_one_line(tmp_path):
    import os
    import subprocess
    import sys
    out = tmp_path / "never.npz"
    done = subprocess.run([sys.executable, "-m", "sim_core", "simulate", "dive", "--set", "dive=108X", "--out", str(out)],
                          capture_output=True, text=True, env=dict(os.environ, PYTHONPATH=str(Path(__file__).parents[1])))
    assert done.returncode != 0 and not out.exists()
    assert len(done.stderr.strip().splitlines()) == 1 and "not a FINA dive number" in done.stderr


@pytest.mark.parametrize("character, number", [("man", "403B"), ("woman", "405B")])
def test_a_seed_dive_by_its_number_is_the_same_run_as_by_its_parameters(character, number):
    """Wooten's inward dives: by FINA number and by group/somersaults/position, bit for bit."""
    by_number = run(RunRequest("dive", character, params={"dive": number}, duration=4.5))
    p = parse(number)
    by_parameters = run(RunRequest("dive", character, duration=4.5, params=dict(
        group=p.group, somersaults=p.somersaults, position=p.position)))
    assert np.array_equal(by_number.arrays["qpos"], by_parameters.arrays["qpos"])
    assert by_number.meta["outcome"] == "success"


def reached_dives(character: str) -> list[str]:
    table = tuned.load("dives", character)
    return [n for n in REPERTOIRE if (row := calibrated_row(table, Dive.schema.validate({"dive": n})))
            and row["measured"]["outcome"] == "success"]


def not_reached_dives(character: str) -> list[str]:
    table = tuned.load("dives", character)
    return [n for n in REPERTOIRE if (row := calibrated_row(table, Dive.schema.validate({"dive": n})))
            and row["measured"]["outcome"] != "success"]


@pytest.mark.parametrize("character", ["man", "woman"])
def test_a_reached_repertoire_dive_beyond_the_seed_makes_its_rotations(character):
    """The deepest reached dive beyond the seed's 1 1/2 and 2 1/2 (most somersaults), simulated by its
    number: its somersaults and twists within a quarter turn, a vertical head-first entry, the
    platform not touched, the flight's angular momentum constant within 1 %."""
    candidates = [n for n in reached_dives(character) if parse(n).somersaults >= 2.5 and n not in ("405B",)]
    if not candidates:
        pytest.xfail(f"the {character} reaches no repertoire dive beyond the seed's")
    number = max(candidates, key=lambda n: (parse(n).somersaults, parse(n).twists))
    traj = run(RunRequest("dive", character, params={"dive": number}, duration=4.5))
    m, p = traj.meta["metrics"], parse(number)
    print(character, number, {k: m[k] for k in ("somersaults", "twists", "entry_angle_from_vertical_deg",
                                                "takeoff_angular_momentum")})
    assert traj.meta["outcome"] == "success", m
    assert abs(m["somersaults"] - p.somersaults) <= ROTATION_TOLERANCE
    assert abs(m["twists"] - p.twists) <= ROTATION_TOLERANCE
    assert m["entry_angle_from_vertical_deg"] < 20.0 and m["head_first"] and not m["hit_platform"]
    assert m["angular_momentum_drift"] < 0.01


def test_a_dive_not_reached_is_refused_naming_the_momentum_needed_and_reached():
    """A repertoire dive the calibration searched and did not reach is refused before simulating,
    with both figures: the man's forward 4 1/2 pike (109B) needs about 30 % more angular momentum
    than any of his forward take-offs reached."""
    missing = not_reached_dives("man")
    if "109B" not in missing:
        pytest.xfail(f"the man reaches 109B (not reached: {missing})")
    number = "109B"
    with pytest.raises(ParameterError, match=r"is not reached by the man.*needs about ([\d.]+) kg m\^2/s, "
                                             r"the calibration's take-offs reached ([\d.]+)") as error:
        run(RunRequest("dive", "man", params={"dive": number}))
    needed, got = (float(x) for x in __import__("re").search(r"needs about ([\d.]+).*reached ([\d.]+)",
                                                              str(error.value)).groups())
    assert needed > got


def test_the_needed_momentum_is_what_the_reached_dives_took_off_with():
    """The physics estimate (air time from 10 m, the position's and the line's inertia) is within
    20 % of the take-off angular momentum the seed's 1 1/2 and 2 1/2 measured, and no reached
    repertoire dive took off with less than 85 % of it (some took off with more and opened early):
    the refusals' figure is the simulation's."""
    momentum_needed = Dive.momentum_needed_by
    for character, number in (("man", "103B"), ("man", "403B"), ("woman", "405B")):
        params = Dive.schema.validate({"dive": number})
        row = calibrated_row(tuned.load("dives", character), params)
        assert momentum_needed(character, params) == pytest.approx(abs(row["measured"]["takeoff_angular_momentum"]),
                                                                   rel=0.2), (character, number)
    for character in ("man", "woman"):
        for number in reached_dives(character):
            params = Dive.schema.validate({"dive": number})
            measured = abs(calibrated_row(tuned.load("dives", character), params)["measured"]["takeoff_angular_momentum"])
            assert measured >= 0.85 * momentum_needed(character, params), (character, number, measured)


def test_the_calibration_covers_the_seed_dives_first_then_the_whole_repertoire():
    """``calibrate dive`` keeps the table's first four rows (the seed's and the first beyond it) in
    place, so the dives calibrated before stay bit for bit; every repertoire dive follows once."""
    from sim_core.skills.dive.behaviour import CALIBRATED_DIVES, dive_key
    from sim_core.skills.dive.calibrate import calibration_dives
    for character in ("man", "woman"):
        dives = calibration_dives(character)
        assert [{k: d[k] for k in d if k != "number"} for d in dives[:4]] == [dive_key(d) for d in CALIBRATED_DIVES[character]]
        assert sorted(d["number"] for d in dives) == sorted(REPERTOIRE)
        table = tuned.load("dives", character)
        assert [d["number"] for d in table["dives"][:4]] == [d["number"] for d in dives[:4]]


def test_a_second_search_keeps_the_better_row_and_the_larger_momentum():
    from sim_core.skills.dive.calibrate import better
    old = {"score": 3.0, "settings": {"liftoff_hip": 1.0}, "largest_momentum_clear": 90.0}
    new = {"score": 5.0, "settings": {"liftoff_hip": 1.2}, "largest_momentum_clear": 95.0}
    assert better(old, new) == dict(old, largest_momentum_clear=95.0)
    assert better(None, new) == new
    assert better(old, dict(new, score=1.0))["settings"] == {"liftoff_hip": 1.2}


def test_a_row_without_the_closure_settings_runs_as_it_was_calibrated():
    """The position's closure (tuck_time, tuck_stiffness, tuck_damping; ``calibrate dive --closure``) defaults
    to the move every row was calibrated with before it: a row without them runs bit for bit as its search
    measured it (the man's 205B: the same somersaults, entry and take-off momentum)."""
    params = Dive.schema.validate({"dive": "205B"})
    row = calibrated_row(tuned.load("dives", "man"), params)
    assert not {"tuck_time", "tuck_stiffness", "tuck_damping"} & set(row["settings"])
    m = run(RunRequest("dive", "man", params={"dive": "205B"})).meta["metrics"]
    for key in ("somersaults", "entry_angle_from_vertical_deg", "takeoff_angular_momentum"):
        assert m[key] == row["measured"][key], key


def test_a_dive_reached_with_a_faster_closure_enters_as_a_success():
    """The man's inward 3½ tuck (407C) made 3.06 somersaults with the closure every row had (0.25 s, stiffness
    3, damping 6) and the take-off its search found (68 kg m^2/s): refused. Closing in ~0.06 s (searched with
    the take-off) it is reached; by its number it enters as a success."""
    params = Dive.schema.validate({"dive": "407C"})
    row = calibrated_row(tuned.load("dives", "man"), params)
    assert row["settings"]["tuck_time"] < Dive.schema.by_name["tuck_time"].default
    traj = run(RunRequest("dive", "man", params={"dive": "407C"}))
    m = traj.meta["metrics"]
    assert traj.meta["outcome"] == "success", m
    assert abs(m["somersaults"] - 3.5) <= ROTATION_TOLERANCE and m["entry_angle_from_vertical_deg"] < 20.0
    assert not m["hit_platform"] and m["angular_momentum_drift"] < 0.01


def test_a_dive_the_faster_closure_did_not_reach_is_still_refused_in_one_line():
    """The man's inward 3½ pike (407B): two searches with the closure made at most 2.71 somersaults (his inward
    take-offs reach ~74 of the ~98 kg m^2/s it needs): refused before simulating, in one line."""
    if "407B" not in not_reached_dives("man"):
        pytest.xfail("the man reaches 407B")
    with pytest.raises(ParameterError, match=r"is not reached by the man") as error:
        run(RunRequest("dive", "man", params={"dive": "407B"}))
    assert "\n" not in str(error.value)
