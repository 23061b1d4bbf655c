"""The random-requests report (issue 29): a tiny draw with a fixed seed runs through the CLI's
module and prints one line per request with measured figures; seeds draw different requests."""
import re

import pytest

from sim_core import random_requests
from sim_core.skills.jump_to_target.region import in_region
from sim_core.random_requests import JUMP_AIR_TIME, JUMP_FORWARD, JUMP_LATERAL, broad_range, draw_requests, leap_height_range


def test_different_seeds_draw_different_requests_inside_the_ranges():
    first = draw_requests(1, ["man", "woman"], 3, 2, 2)
    assert first == draw_requests(1, ["man", "woman"], 3, 2, 2)          # the same seed, the same draw
    assert first != draw_requests(2, ["man", "woman"], 3, 2, 2)
    for draw in first:
        if draw.skill == "jump":
            x, y, t = draw.values
            lo, hi = JUMP_FORWARD[draw.character]
            assert lo <= x <= hi and abs(y) <= JUMP_LATERAL and JUMP_AIR_TIME[0] <= t <= JUMP_AIR_TIME[1]
            assert in_region(draw.character, (x, y), t)        # inside the box, in the region offered
        else:
            lo, hi = leap_height_range(draw.character) if draw.skill == "leap" else broad_range(draw.character)
            assert lo <= draw.values[0] <= hi


def test_unknown_character_is_refused_in_one_line():
    with pytest.raises(Exception, match="character 'child'"):
        draw_requests(1, ["child"], 1, 0, 0)


def test_report_prints_measured_lines(tmp_path, capsys):
    out = tmp_path / "random.md"
    assert random_requests.main(["--seed", "5", "--jumps", "1", "--leaps", "2", "--broad", "1",
                                 "--characters", "man", "--budget", "2", "--workers", "1",
                                 "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    lines = [line for line in printed.splitlines() if line.startswith("man ")]
    assert len(lines) == 4
    assert sum("rose " in line for line in lines) == 2 and sum("travelled " in line for line in lines) == 1
    jump = next(line for line in lines if "jump to" in line)
    assert re.search(r"landed at \(-?\d+\.\d{3}, [+-]\d+\.\d{3}\) m, \d+\.\d cm off, air \d\.\d{3} s", jump)
    assert re.search(r"planned [12] trials", jump)        # unplanned: planned into the temporary store first
    assert all(re.search(r"(PASS|MISS) ", line) for line in lines)
    assert "| leap | man | " in printed and "| broad | man | " in printed
    assert "--seed 5" in out.read_text()


def test_bad_budget_is_refused(capsys):
    with pytest.raises(SystemExit):
        random_requests.main(["--seed", "1", "--budget", "0"])
    assert "--budget=0: must be at least 1" in capsys.readouterr().err


def test_the_cli_runs_it_as_report_random(tmp_path):
    import subprocess
    import sys
    from pathlib import Path
    out = tmp_path / "random.md"
    done = subprocess.run([sys.executable, "-m", "sim_core", "report", "random", "--seed", "3", "--jumps", "0",
                           "--leaps", "1", "--broad", "0", "--characters", "woman", "--workers", "1",
                           "--out", str(out)], capture_output=True, text=True,
                          cwd=Path(random_requests.__file__).parents[1], timeout=120)
    assert done.returncode == 0, done.stderr
    assert re.search(r"woman leap \d\.\d{3} m +(PASS|MISS) +rose \d\.\d{3} m", done.stdout)
    assert out.exists()


def test_box_draws_are_in_range_in_the_region_and_leave_the_other_draws_as_they_were():
    from sim_core.random_requests import BOX_HEIGHT, box_region_share
    plain = draw_requests(1, ["man", "woman"], 2, 1, 1)
    drawn = draw_requests(1, ["man", "woman"], 2, 1, 1, 2)
    assert drawn[:len(plain)] == plain                       # their own stream: the other draws unchanged
    boxes = drawn[len(plain):]
    assert [d.character for d in boxes] == ["man", "man", "woman", "woman"] and all(d.skill == "box" for d in boxes)
    assert boxes != draw_requests(2, ["man", "woman"], 2, 1, 1, 2)[len(plain):]
    for d in boxes:
        x, z, t = d.values
        lo, hi = JUMP_FORWARD[d.character]
        assert lo <= x <= hi and BOX_HEIGHT[0] <= abs(z) <= BOX_HEIGHT[1] and JUMP_AIR_TIME[0] <= t <= JUMP_AIR_TIME[1]
        assert in_region(d.character, (x, 0.0, z), t)
        assert "box" in d.describe()
    every, onto, down = box_region_share("man", 1, 2000)
    assert 0.0 < every < 1.0 and 0.0 < onto and 0.0 < down


def test_sideways_draws_are_each_characters_to_either_side_in_its_sideways_regions():
    from sim_core.skills.jump_to_target.commanded import SIDEWAYS_WAYS, commanded_way, table
    plain = draw_requests(1, ["man", "woman"], 2, 1, 1)
    drawn = draw_requests(1, ["man", "woman"], 2, 1, 1, sideways=7)    # (seed 1's first 6 of the woman all to the left)
    assert drawn[:len(plain)] == plain                       # their own stream: the other draws unchanged
    side = drawn[len(plain):]
    assert [d.character for d in side] == ["man"] * 7 + ["woman"] * 7 and all(d.skill == "sideways" for d in side)
    for d in side:
        x, y, t = d.values
        way = commanded_way(d.character, (x, y), t)
        assert way in SIDEWAYS_WAYS and x >= 0.0
        region = table(d.character)[f"{way}_region"]
        assert region["distance"][0] - 1e-3 <= abs(y) <= region["distance"][1] and region["air_time"][0] <= t <= region["air_time"][1]
    for character in ("man", "woman"):      # left and right
        assert {y > 0 for _, y, _ in (d.values for d in side if d.character == character)} == {True, False}


def test_long_draws_are_in_each_long_region_outside_the_measured_jumps():
    from sim_core.skills.jump_to_target.commanded import commanded_way, table
    from sim_core.skills.jump_to_target.region import offered
    plain = draw_requests(1, ["man", "woman"], 2, 1, 1, commanded=2)
    drawn = draw_requests(1, ["man", "woman"], 2, 1, 1, commanded=2, long=3)
    assert drawn[:len(plain)] == plain                       # their own stream: the other draws unchanged
    long = drawn[len(plain):]
    assert [d.character for d in long] == ["man"] * 3 + ["woman"] * 3 and all(d.skill == "long" for d in long)
    for d in long:
        x, y, t = d.values
        way = commanded_way(d.character, (x, y), t)       # the man's long draws: his long, near or deep rows' (the union)
        region = table(d.character)[f"{way}_region"]
        assert way in ("long", "near_long", "deep_long", "far_short", "near_short", "near_deep_long",
                       "mid_deep_long") and not offered(d.character, (x, y), t)
        assert all(region[k][0] <= v <= region[k][1] for k, v in zip(("target_x", "target_y", "air_time"), d.values))
    assert all(commanded_way("woman", d.values[:2], d.values[2]) == "long" for d in long if d.character == "woman")
    assert long != draw_requests(2, ["man", "woman"], 2, 1, 1, commanded=2, long=3)[len(plain):]


def test_turned_long_draws_are_in_each_turned_long_region_outside_the_measured_jumps():
    from sim_core.skills.jump_to_target.commanded import commanded_way
    from sim_core.skills.jump_to_target.region import offered
    plain = draw_requests(1, ["man", "woman"], 2, 1, 1, turned=2, long=2)
    drawn = draw_requests(1, ["man", "woman"], 2, 1, 1, turned=2, long=2, turned_long=3)
    assert drawn[:len(plain)] == plain                       # their own stream: the other draws unchanged
    turned_long = drawn[len(plain):]
    assert [d.character for d in turned_long] == ["man"] * 3 + ["woman"] * 3
    for d in turned_long:
        x, y, t = d.values
        assert d.skill == "turned_long" and commanded_way(d.character, (x, y), t) in ("turned_long", "turned_long_short",
                                                                                      "turned_near_long", "turned_deep_long",
                                                                                      "turned_far_short", "turned_near_short",
                                                                                      "turned_near_deep_long",
                                                                                      "turned_mid_deep_long")
        assert not offered(d.character, (x, y), t)
    assert turned_long != draw_requests(2, ["man", "woman"], 2, 1, 1, turned=2, long=2, turned_long=3)[len(plain):]


def test_mid_long_draws_are_in_the_mid_long_rows_regions_outside_the_measured_jumps():
    from sim_core.skills.jump_to_target.commanded import commanded_way
    from sim_core.skills.jump_to_target.region import offered
    plain = draw_requests(1, ["man", "woman"], 2, 1, 1, turned=2, long=2, turned_long=2)
    drawn = draw_requests(1, ["man", "woman"], 2, 1, 1, turned=2, long=2, turned_long=2, mid_long=3)
    assert drawn[:len(plain)] == plain                       # their own stream: the other draws unchanged
    mid = drawn[len(plain):]
    assert [d.character for d in mid] == ["man"] * 3          # the woman's table has no mid long row
    for d in mid:
        x, y, t = d.values
        assert d.skill == "mid_long" and commanded_way("man", (x, y), t) == "turned_mid_long"
        assert not offered("man", (x, y), t)
    assert mid != draw_requests(2, ["man", "woman"], 2, 1, 1, turned=2, long=2, turned_long=2, mid_long=3)[len(plain):]
