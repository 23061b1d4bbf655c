"""The calibrated tables' bookkeeping (sim_core/control/tuned.py): what a calibration run keeps."""
import json

import argparse

import pytest

from sim_core.control.tuned import merge_search, names_option, write_table

KEY = {"direction": "backward", "strength": "human"}
OTHER = {"direction": "forward", "strength": "human", "settings": {"a": 1}}


def test_a_found_row_replaces_the_old_one_and_its_not_found_record():
    rows, missing = merge_search([OTHER, {**KEY, "settings": {"a": 0}}], [{**KEY, "best": "fell"}], KEY, True,
                                 {"settings": {"a": 2}, "score": 0.1}, "unused")
    assert rows == [OTHER, {**KEY, "settings": {"a": 2}, "score": 0.1}] and missing == []


def test_without_a_find_the_old_row_stays_else_the_best_run_is_recorded():
    old = {**KEY, "settings": {"a": 0}}
    assert merge_search([old, OTHER], [], KEY, False, {"settings": {"a": 3}}, "fell") == ([OTHER, old], [])
    rows, missing = merge_search([OTHER], [], KEY, False, {"settings": {"a": 3}}, "fell, rotation 5.5 rad")
    assert rows == [OTHER] and missing == [{**KEY, "settings": {"a": 3}, "best": "fell, rotation 5.5 rad"}]
    rows, missing = merge_search([OTHER], [], KEY, False, {"settings": {"a": 3}, "score": 7.0}, "fell")
    assert missing == [{**KEY, "settings": {"a": 3}, "best": "fell", "score": 7.0}]


def test_a_worse_search_does_not_overwrite_the_recorded_best_miss():
    earlier = {**KEY, "settings": {"a": 1}, "best": "fell, rotation 6.35 rad", "score": 20.0}
    _, missing = merge_search([], [earlier], KEY, False, {"settings": {"a": 9}, "score": 63.0}, "fell, rotation -1.3 rad")
    assert missing == [earlier]
    _, missing = merge_search([], [earlier], KEY, False, {"settings": {"a": 2}, "score": 10.0}, "fell, rotation 6.2 rad")
    assert missing == [{**KEY, "settings": {"a": 2}, "best": "fell, rotation 6.2 rad", "score": 10.0}]


def test_a_table_is_written_whole(tmp_path):
    path = tmp_path / "table.json"
    write_table(path, {"rows": [1, 2]})
    assert json.loads(path.read_text()) == {"rows": [1, 2]} and not list(tmp_path.glob("*.tmp"))


def test_a_calibration_searches_only_the_settings_named_and_refuses_an_unknown_one(capsys):
    """--names of the calibration scripts: the named settings, or a clear refusal naming the
    allowed ones (argparse exits with status 2)."""
    parser = argparse.ArgumentParser()
    names_option(parser, {"open_time": (0.03, 0.4), "foot_delta": (-0.3, 0.3)}, ("open_time",))
    assert parser.parse_args(["--names", "open_time,foot_delta"]).names == ["open_time", "foot_delta"]
    assert parser.parse_args([]).names is None
    with pytest.raises(SystemExit) as refused:
        parser.parse_args(["--names", "open_time,tuck"])
    assert refused.value.code == 2
    assert "tuck: not searched settings; choose from open_time, foot_delta" in capsys.readouterr().err


def test_a_search_varies_the_named_settings_of_its_space_and_keeps_the_others_as_started():
    from sim_core.control.tuned import searched_and_fixed
    settings = ("crouch_height", "open_time", "foot_delta", "flight_step_division")
    space = {"crouch_height": (0.4, 0.9), "open_time": (0.03, 0.4), "foot_delta": (-0.3, 0.3)}
    start = {"crouch_height": 0.7, "open_time": 0.1, "foot_delta": 0.0, "flight_step_division": 8}
    assert searched_and_fixed(settings, space, None, start) == (
        ["crouch_height", "open_time", "foot_delta"], {"flight_step_division": 8})
    assert searched_and_fixed(settings, space, ["foot_delta", "open_time"], start) == (
        ["open_time", "foot_delta"], {"crouch_height": 0.7, "flight_step_division": 8})
