"""``python -m sim_core adapt`` (sim_core/adapt/command.py, sim_core/adapt/skills.py): the scaled
tables, the nearest source, nothing left behind by a skill that is refused, resume, bad input."""
import json
import shutil

import pytest

from sim_core import tuned
from sim_core.adapt import command
from sim_core.adapt.skills import ADAPTERS, Check, LandingAdapter, LeapAdapter, nearest_source
from sim_core.character.spec import load_character
from sim_core.cli import main
from sim_core.skills import available_behaviours
from sim_core.tuned import store

available_behaviours()          # every skill's module imported: their tables' row types declared


@pytest.fixture
def tables(tmp_path, monkeypatch):
    """The store pointed at a copy of the package's tables."""
    folder = tmp_path / "tables"
    shutil.copytree(store.DIRECTORY, folder)
    monkeypatch.setattr(store, "DIRECTORY", folder)
    return folder


def test_the_nearest_calibrated_character_is_the_nearest_in_size():
    child, man = load_character("child"), load_character("man")
    assert nearest_source(child, ["man", "woman"]) == "woman"
    assert nearest_source(man, ["man", "woman"]) == "woman"          # itself is never its own source
    assert nearest_source(load_character("woman"), ["man", "child"]) == "man"
    assert nearest_source(child, ["nobody_shipped"]) is None


def test_scaling_a_table_onto_its_own_character_changes_nothing():
    woman = load_character("woman")
    landing = tuned.load("landing", "woman")
    scaled, runs = LandingAdapter().scale(woman, woman, landing)
    assert runs == 0
    for row, original in zip(scaled["foot_delta"], landing["foot_delta"]):
        assert row == {k: original[k] for k in ("drop", "touchdown_speed", "speed", "delta")}
    assert scaled["fast_touchdown"] == {k: landing["fast_touchdown"][k] for k in ("speed", "ramp", "delta")}
    leap = tuned.load("leap", "woman")["vertical"]
    rows = LeapAdapter().scaled_rows(woman, woman, {"vertical": leap})
    assert len(rows) == len(leap["com_rise"])
    for k, row in enumerate(rows):
        assert row == pytest.approx({n: leap[n][k] for n in row}, abs=1e-12)


def test_scaling_to_the_child_shortens_lengths_by_L_and_speeds_by_its_root():
    woman, child = load_character("woman"), load_character("child")
    from sim_core.adapt.skills import leg_length_ratio
    L = leg_length_ratio(woman, child)
    scaled, _ = LandingAdapter().scale(woman, child, tuned.load("landing", "woman"))
    original = tuned.load("landing", "woman")["foot_delta"][0]
    assert scaled["foot_delta"][0]["drop"] == pytest.approx(original["drop"] * L, abs=1e-3)
    assert scaled["foot_delta"][0]["speed"][-1] == pytest.approx(original["speed"][-1] * L ** 0.5, abs=1e-3)
    vertical = tuned.load("leap", "woman")["vertical"]
    rows = LeapAdapter().scaled_rows(woman, child, {"vertical": vertical})
    assert rows[0]["crouch_height"] == pytest.approx(vertical["crouch_height"][0] * L)


def test_the_leaps_constants_scale_to_the_child_and_the_man_and_woman_keep_leap_any():
    """Fig. 6 on the thrust's and landing's constants: times by L^1/2, lengths by L, shares as they
    are; a body whose leap table holds no constants section uses leap_any's (the woman's holds her own
    commanded take-off's, the man's values for now: the same numbers; the man's his own commanded take-off's,
    scaled from hers by tools/scale_commanded.py, and nothing else)."""
    from sim_core.adapt.skills import leg_length_ratio
    from sim_core.control.leap import CONSTANTS, leap_constants
    woman, child = load_character("woman"), load_character("child")
    assert vars(leap_constants("woman")) == vars(CONSTANTS)
    assert {n for n, v in vars(leap_constants("man")).items() if v != vars(CONSTANTS)[n]} <= \
        {n for n in vars(CONSTANTS) if n.startswith("commanded_")}
    L = leg_length_ratio(woman, child)
    scaled = LeapAdapter().scaled_constants(woman, child, tuned.load("leap", "woman"))
    assert scaled["vertical_timing"] == pytest.approx([t * L ** 0.5 for t in CONSTANTS.vertical_timing])
    assert scaled["fast_landing_speed"] == pytest.approx([v * L ** 0.5 for v in CONSTANTS.fast_landing_speed])
    assert scaled["thrust_gain"] == CONSTANTS.thrust_gain and scaled["knee_restore"] == CONSTANTS.knee_restore


def test_a_refused_skill_leaves_no_table_behind(tables, tmp_path, monkeypatch):
    """The scaled landing table is written for its check; the check fails and no budget is left for
    a search, so the skill is refused and the child has no landing table afterwards."""
    (tables / "landing_child.json").unlink(missing_ok=True)     # as before the child's landing was adapted
    (tables / "landing_imaginary_runner.json").unlink(missing_ok=True)  # the woman is the nearest source
    monkeypatch.setattr(ADAPTERS["land"], "check", lambda character, rng: Check(False, "measured: fell", 6))
    results = command.adapt("child", ["land"], tmp_path / "out", minutes=0, workers=1, seed=1, redo=None,
                            say=lambda line: None)
    assert [(r.skill, r.status) for r in results] == [("land", "refused")]
    assert "no budget left" in results[0].figures and results[0].route == "scaled from the woman"
    assert not (tables / "landing_child.json").exists()


def test_a_table_that_was_there_is_put_back_byte_for_byte(tables, tmp_path, monkeypatch):
    """tuned.provisional puts the file back; an adaptation stopped during its check (Ctrl-C) leaves
    no scaled table and no state behind."""
    before = (tables / "running_child.json").read_bytes()
    with tuned.provisional("running", "child"):
        (tables / "running_child.json").write_text("{}")
    assert (tables / "running_child.json").read_bytes() == before

    (tables / "landing_child.json").unlink(missing_ok=True)     # as before the child's landing was adapted
    (tables / "landing_imaginary_runner.json").unlink(missing_ok=True)  # the woman is the nearest source

    def stopped(character, rng):
        assert (tables / "landing_child.json").exists()       # the scaled table, written for the check
        raise KeyboardInterrupt
    monkeypatch.setattr(ADAPTERS["land"], "check", stopped)
    with pytest.raises(KeyboardInterrupt):
        command.adapt("child", ["land"], tmp_path / "out", minutes=0, workers=1, seed=1, redo=None,
                      say=lambda line: None)
    assert not (tables / "landing_child.json").exists()
    assert not (tmp_path / "out" / "state.json").exists()


def test_adapt_balance_on_the_child_works_and_a_rerun_resumes(tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["adapt", "--character", "child", "--skills", "balance", "--out", str(out)]) == 0
    state = json.loads((out / "state.json").read_text())
    assert state["character"] == "child" and state["results"][0]["status"] == "works"
    assert "| balance | works |" in (out / "report.md").read_text()
    capsys.readouterr()
    assert main(["adapt", "--character", "child", "--skills", "balance", "--out", str(out)]) == 0
    assert "balance: done before (works); --redo balance runs it again" in capsys.readouterr().out


@pytest.mark.parametrize("argv, message", [
    (["--skills", "bogus"], "--skills bogus: unknown skill; available: all, balance"),
    (["--minutes", "-1"], "--minutes=-1 is out of range; allowed range is [0, 1440]"),
    (["--workers", "0"], "--workers=0 is out of range; allowed range is [1, 64]"),
])
def test_bad_input_is_refused_in_one_line_and_nothing_is_written(tmp_path, capsys, argv, message):
    out = tmp_path / "out"
    assert main(["adapt", "--character", "child", "--out", str(out), *argv]) == 2
    err = capsys.readouterr().err.strip()
    assert message in err and "\n" not in err
    assert not out.exists()


def test_a_state_file_of_another_body_is_refused(tmp_path, capsys):
    out = tmp_path / "out"
    out.mkdir()
    (out / "state.json").write_text(json.dumps({"character": "woman", "results": []}))
    assert main(["adapt", "--character", "child", "--skills", "balance", "--out", str(out)]) == 2
    assert "records an adaptation of 'woman', not 'child'" in capsys.readouterr().err


def test_a_search_whose_table_checks_worse_is_not_kept(tables, tmp_path, monkeypatch):
    """The scaled leap works where its table serves (not the whole range), so the search runs; its
    table checks worse (a fall), so the scaled one is put back and the leap works in part."""
    (tables / "leap_child.json").unlink(missing_ok=True)        # the child has no leap table of its own
    woman = tuned.load("leap", "woman")
    scaled = {"vertical": {n: c[:5] for n, c in woman["vertical"].items()}}
    searched = {"vertical": {n: c[5:] for n, c in woman["vertical"].items()}}
    checks = iter([Check(True, "6/6 where it serves", 6, covers=False), Check(False, "fell", 6)])
    monkeypatch.setattr(ADAPTERS["leap"], "scale", lambda source, target, body: (scaled, 5))
    monkeypatch.setattr(ADAPTERS["leap"], "search", lambda character, workers, minutes, check: (searched, 20))
    monkeypatch.setattr(ADAPTERS["leap"], "check", lambda character, rng: next(checks))
    [result] = command.adapt("child", ["leap"], tmp_path / "out", minutes=5, workers=1, seed=1, redo=None,
                             say=lambda line: None)
    assert (result.status, result.runs) == ("works in part of the range", 5 + 6 + 20 + 6)
    assert "its table checked worse and was not kept: fell" in result.route
    assert tuned.load("leap", "child")["vertical"] == scaled["vertical"]


def test_a_search_that_fails_where_the_scaled_table_failed_is_kept_and_narrowed(tables, tmp_path, monkeypatch):
    """Neither the scaled nor the searched landing table passes; the search's is the body's own
    calibration, so it is kept and cut to the speeds inside the failing draws, then checked again."""
    (tables / "landing_child.json").unlink(missing_ok=True)
    (tables / "landing_imaginary_runner.json").unlink(missing_ok=True)  # the woman is the nearest source
    woman = tuned.load("landing", "woman")
    searched = {k: woman[k] for k in ("foot_delta", "fast_touchdown")}
    checks = iter([Check(False, "2/6", 6, failed=(-0.6, 1.0)), Check(False, "3/6", 6, covers=False, failed=(0.7,)),
                   Check(True, "6/6", 6, covers=False)])
    monkeypatch.setattr(ADAPTERS["land"], "search", lambda character, workers, minutes, check: (searched, 20))
    monkeypatch.setattr(ADAPTERS["land"], "check", lambda character, rng: next(checks))
    [result] = command.adapt("child", ["land"], tmp_path / "out", minutes=5, workers=1, seed=1, redo=None,
                             say=lambda line: None)
    assert (result.status, result.route) == ("works in part of the range", "scaled from the woman and searched")
    rows = tuned.load("landing", "child")["foot_delta"]
    assert all(max(row["speed"]) < 0.7 for row in rows) and any(min(row["speed"]) < 0 for row in rows)


def test_an_own_table_that_fails_its_check_is_reported_and_kept(tables, tmp_path, monkeypatch):
    before = (tables / "running_child.json").read_bytes()
    monkeypatch.setattr(ADAPTERS["running"], "check", lambda character, rng: Check(False, "2.5 m/s: fell at 9.0 s", 1))
    monkeypatch.setattr(ADAPTERS["running"], "search", lambda *args: pytest.fail("an own table is not searched"))
    [result] = command.adapt("child", ["running"], tmp_path / "out", minutes=5, workers=1, seed=1, redo=None,
                             say=lambda line: None)
    assert (result.status, result.route) == ("fails its check (own table kept)", "own table")
    assert "`calibrate running` searches it again" in result.figures
    assert (tables / "running_child.json").read_bytes() == before


def test_the_landing_of_a_body_without_a_leap_table_is_checked_with_the_leaps_scaled_constants(tables, tmp_path,
                                                                                              monkeypatch):
    """The landing is adapted before the leap (the leap lands), but it lands with the leap's constants
    (control.leap.leap_constants): while it is adapted, the body's provisional leap table holds the
    constants scaled to it as the leap's adapter writes them (not leap_any's); removed afterwards."""
    from sim_core.control.leap import CONSTANTS, leap_constants
    (tables / "landing_child.json").unlink(missing_ok=True)     # as before the child was adapted
    (tables / "leap_child.json").unlink(missing_ok=True)
    for skill in ("landing", "leap"):                           # the woman is the nearest source
        (tables / f"{skill}_imaginary_runner.json").unlink(missing_ok=True)
    child, woman = load_character("child"), load_character("woman")
    expected = LeapAdapter().scaled_constants(woman, child, tuned.load("leap", "woman"))
    seen = []

    def check(character, rng):
        seen.append(vars(leap_constants("child")))
        return Check(False, "measured: fell", 6)
    monkeypatch.setattr(ADAPTERS["land"], "check", check)
    results = command.adapt("child", ["land"], tmp_path / "out", minutes=0, workers=1, seed=1, redo=None,
                            say=lambda line: None)
    assert [(r.skill, r.status) for r in results] == [("land", "refused")]
    assert seen and seen[0]["vertical_timing"] == tuple(expected["vertical_timing"]) != CONSTANTS.vertical_timing
    assert seen[0]["fast_landing_speed"] == tuple(expected["fast_landing_speed"])
    assert not (tables / "leap_child.json").exists() and not (tables / "landing_child.json").exists()
