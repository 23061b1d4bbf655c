"""Jumps to any target in the region offered (issue 29): random targets with a fixed seed, drawn
and judged as the random-requests report draws and judges them (planned from the measured jumps,
then run); a target outside the region is refused in one line before anything is simulated."""
from __future__ import annotations

import math
import tempfile
from pathlib import Path

import pytest

from sim_core.ballistics import flat_air_time
from sim_core.errors import ParameterError
from sim_core.random_requests import draw_requests, evaluate, result_line
from sim_core.simulate import RunRequest, run
from sim_core.skills.jump_to_target.region import in_region, offered, region_refusal

SEED = 29           # CI's fixed draw
TARGETS = 3         # random targets per character


@pytest.mark.parametrize("character", ["man", "woman"])
def test_random_targets_in_the_region_land_on_target_balanced(character, tmp_path):
    draws = draw_requests(SEED, [character], TARGETS, 0, 0)
    results = [evaluate(draw, 24, str(tmp_path)) for draw in draws]
    lines = [result_line(r) for r in results]
    assert all(in_region(character, d.values[:2], d.values[2]) for d in draws)
    assert sum(r["passed"] for r in results) >= TARGETS - 1, "\n".join(lines)     # >= 90 % asked; 3 draws
    assert max(r["seconds"] for r in results) <= 60, "\n".join(lines)


@pytest.mark.parametrize("params, words", [
    ({"target_x": 0.4, "target_y": 0.6, "air_time": 0.45}, ["target_y at 0.40 m forward in 0.45 s is offered only in"]),  # beyond 46 deg
    ({"target_x": 1.0, "target_y": 0.0, "air_time": 0.8}, ["air_time at 1.00 m forward is offered only in"]),   # beyond the longest flight
    ({"target_x": 2.2, "target_y": 0.0, "air_time": 0.5}, ["no balanced jump of the man lands within 5 cm of 2.20 m"]),
])
def test_a_target_outside_the_region_is_refused_in_one_line_before_simulating(params, words, monkeypatch):
    import sim_core.simulate as simulate
    monkeypatch.setattr(simulate, "Recorder", None)         # a run that started would fail differently
    with pytest.raises(ParameterError) as refused:
        run(RunRequest("jump_to_target", "man", params={**params, "plan_trials": 24}))
    text = str(refused.value)
    assert "\n" not in text and "outside the region" in text and "nearest balanced one lands at" in text
    for word in words:
        assert word in text
    assert region_refusal("man", (params["target_x"], params["target_y"]), params["air_time"]) == text


@pytest.mark.parametrize("character", ["man", "woman"])
def test_the_second_family_is_measured_and_lands_long_flights(character):
    """The vertical leaps blended with the broad rows (jump_model.high_bases) are in the table, inside
    the leap's ranges, with the landing's own settings, and some land balanced after 0.55 s or more
    at 0.5-1 m (the broad jumps fly 0.37-0.54 s)."""
    from sim_core.control.leap import LEAP_SETTINGS
    from sim_core.planning.jump_model import HIGH_LANDING, high_bases, vertical_flight
    from sim_core.skills.jump_to_target.region import model
    assert vertical_flight(0.51) == pytest.approx(0.645, abs=0.001)
    family = high_bases(character)
    ranges = {p.name: (p.minimum, p.maximum) for p in LEAP_SETTINGS.parameters}
    assert all(ranges[n][0] <= s[n] <= ranges[n][1] for s in family for n in s if n in ranges)
    assert all(s[n] == v for s in family for n, v in HIGH_LANDING.items())
    points = model(character)["points"]
    measured = [p for p in points if p["settings"] in family and "surface" not in p["measured"]]   # on flat ground
    assert len(measured) == len(family)
    assert any(p["measured"]["outcome"] == "success" and p["measured"]["air_time"] >= 0.55
               and 0.5 <= p["measured"]["landing"][0] <= 1.0 for p in measured)


BOX_TARGETS = 3     # random box targets per character (onto or down from a box)


@pytest.mark.parametrize("character", ["man", "woman"])
def test_random_box_targets_in_the_region_land_on_target_balanced(character, tmp_path):
    """Box targets drawn as the report draws them (--boxes: onto a box 0.25-0.75 m high or down from
    one, straight ahead, inside the region offered: the measured jumps' or the commanded take-off's down_region)
    land within the tolerances on the box's height."""
    from sim_core.random_requests import BOX_HEIGHT
    draws = draw_requests(SEED, [character], 0, 0, 0, BOX_TARGETS)
    assert len(draws) == BOX_TARGETS and all(d.skill == "box" for d in draws)
    assert all(BOX_HEIGHT[0] <= abs(d.values[1]) <= BOX_HEIGHT[1] and in_region(character, (d.values[0], 0.0, d.values[1]),
                                                                                d.values[2]) for d in draws)
    results = [evaluate(draw, 24, str(tmp_path)) for draw in draws]
    lines = [result_line(r) for r in results]
    assert sum(r["passed"] for r in results) >= BOX_TARGETS - 1, "\n".join(lines)
    assert max(r["seconds"] for r in results) <= 60, "\n".join(lines)


def test_a_box_target_outside_the_region_is_refused_in_one_line_before_simulating(monkeypatch):
    import sim_core.simulate as simulate
    monkeypatch.setattr(simulate, "Recorder", None)         # a run that started would fail differently
    params = {"target_x": 1.0, "target_y": 0.0, "target_z": -0.9, "air_time": 0.6, "plan_trials": 24}
    with pytest.raises(ParameterError) as refused:
        run(RunRequest("jump_to_target", "man", params=params))
    text = str(refused.value)
    assert "\n" not in text and "outside the region" in text and "no balanced jump down from a 0.9 m box" in text
    assert "measured down from: 0.25," in text
    assert region_refusal("man", (1.0, 0.0, -0.9), 0.6) == text


def test_a_box_nearer_than_any_measured_one_is_refused_naming_it():
    """The box stands centred on the target; a jump measured with its box further ahead met the front
    edge of a nearer one with its feet (the man onto 0.639 m at 0.793 m: landed on the ground and fell),
    so such a request is refused before simulating, naming the nearest box measured."""
    from sim_core.skills.jump_to_target.region import clears
    text = region_refusal("man", (0.793, 0.0, 0.639), 0.681)
    assert text and "\n" not in text and "no balanced jump onto it was measured with its box that near" in text
    assert not offered("man", (0.793, 0.0, 0.639), 0.681)
    assert clears({"box_x": 0.8}, {"box_x": 0.82}, 0.83) and not clears({"box_x": 0.8}, {"box_x": 0.82}, 0.81)


def test_landing_variants_of_fallen_flights_are_measured_and_land_beyond_the_first_region():
    """jump_model.measure_landings: the man's fallen flights in issue 29's span outside the region, again
    with the landing's settings varied (LANDING_VARIANTS: the take-off unchanged); some end balanced,
    among them long flights beyond 1.2 m (his 1.64 m in 0.59 s fell; the feet 2.5 cm nearer: 1.61 m)."""
    from sim_core.planning.jump_model import ARMS_UP, LANDING_VARIANTS
    from sim_core.skills.jump_to_target.region import balanced, model
    assert len(LANDING_VARIANTS) == 4 and ARMS_UP["landing_right_time"] > 0
    flat = [p for p in balanced(model("man")) if not p["measured"].get("surface")]
    assert any(p["settings"].get("landing_right_time") == ARMS_UP["landing_right_time"] for p in flat)
    assert any(p["measured"]["landing"][0] > 1.5 and p["measured"]["air_time"] >= 0.56 for p in flat)


COMMANDED_TARGETS = 3       # random targets in a character's commanded region, outside its measured jumps' region


@pytest.mark.parametrize("character", ["man", "woman"])
def test_random_targets_in_the_commanded_region_are_planned_commanded_and_land_balanced(character, tmp_path):
    """Outside the measured jumps' region, inside the commanded one: planned by planning/commanded.py
    (a plan with the commanded take-off and its aim), then run as a user's request. The man's table is
    the woman's scaled by Fig. 6 (tools/scale_commanded.py)."""
    from sim_core.skills.jump_to_target.region import in_region, mode
    draws = draw_requests(SEED, [character], 0, 0, 0, 0, COMMANDED_TARGETS)
    assert [d.character for d in draws] == [character] * COMMANDED_TARGETS
    assert all(in_region(character, d.values[:2], d.values[2])
               and mode(character, d.values[:2], d.values[2]) == "commanded" for d in draws)
    results, lines, plans, c = all_planned_and_run(character, draws, tmp_path)
    assert len(plans) == COMMANDED_TARGETS
    assert all(p["settings"]["commanded_takeoff"] == 1.0 and "flight_target_x" in p["settings"] for p in plans)
    assert all(p["trials"] <= c.aim_trials + c.landing_trials - 1 + len(c.landing_leads) + c.landing_aims for p in plans)
    assert sum(r["passed"] for r in results) >= COMMANDED_TARGETS - 1, "\n".join(lines)
    assert max(r["seconds"] for r in results) <= 60, "\n".join(lines)


def test_a_target_outside_both_regions_is_refused_naming_both(monkeypatch):
    import sim_core.simulate as simulate
    monkeypatch.setattr(simulate, "Recorder", None)         # a run that started would fail differently
    params = {"target_x": 0.55, "target_y": 0.6, "air_time": 0.45, "plan_trials": 24}    # 47 deg: beyond the turned rows
    with pytest.raises(ParameterError) as refused:
        run(RunRequest("jump_to_target", "woman", params=params))
    text = str(refused.value)
    assert "\n" not in text and "outside the region the woman's measured jumps offer" in text
    # a target on flat ground: the flat and turned regions (the box regions are named for box targets alone)
    assert text.endswith("the commanded take-off is offered on flat ground for target_x 0.5-1.25 m, "
                         "target_y -0.02-0.02 m, air_time 0.4-0.52 s, and turned first for a distance of 0.5-1.25 m "
                         "at a bearing of 0-40 deg to either side, air_time 0.4-0.48 s, and turned a quarter "
                         "first for a distance of 1-1.2 m at a bearing of 87-90 deg to either side, air_time 0.4-0.44 s, "
                         "and turned a quarter first with long air times for a distance of 1-1.6 m at a bearing of "
                         "87-90 deg to either side, air_time 0.55-0.7 s, "
                         "and turned a quarter first with the long row at shorter air times for a distance of 1-1.6 m "
                         "at a bearing of 87-90 deg to either side, air_time 0.44-0.55 s, "
                         "and for long air times (the leap's vertical thrust) on flat ground for target_x 0.5-1.6 m, "
                         "target_y -0.02-0.02 m, air_time 0.52-0.7 s, and turned first with long air times for a "
                         "distance of 0.5-1.6 m at a bearing of 0-40 deg to either side, air_time 0.52-0.7 s, and turned "
                         "first with the long row at shorter air times for a distance of 0.7-1.6 m at a bearing of 0-26 "
                         "deg to either side, air_time 0.42-0.52 s, and turned first with long air times beyond the long "
                         "row (its own smaller lean push) for a distance of 1.6-1.71 m at a bearing of 0-26 deg to either "
                         "side, air_time 0.52-0.62 s")
    onto = region_refusal("woman", (0.7, 0.0, 0.6), 0.5)        # onto a box: the flat region and the onto regions
    assert onto.endswith("the commanded take-off is offered on flat ground for target_x 0.5-1.25 m, target_y -0.02-0.02 m, "
                         "air_time 0.4-0.52 s, and onto a box 0.25-0.5 m high at target_x 0.92-1.6 m where the same "
                         "lift-off on flat ground would land in the long air times' region in 0.52-0.66 s "
                         "(T0 = air_time + 2 height / (g air_time)), and onto a box 0.25-0.5 m high at target_x 0.55-0.85 m "
                         "where the same lift-off on flat ground would land in the long air times' region in 0.52-0.7 s "
                         "(T0 = air_time + 2 height / (g air_time)), and onto a box 0.25-0.55 m high at target_x 0.85-1.6 m "
                         "where the same lift-off on flat ground would land in the long row's target_x 0.5-1.6 m (a higher "
                         "lift-off) in 0.7-0.76 s (T0 = air_time + 2 height / (g air_time)), and onto a box 0.25-0.5 m "
                         "high at target_x 0.65-0.77 m at a forward speed of 0.9-1.3 m/s (target_x / air_time) where the "
                         "same lift-off on flat ground would land in the long row's target_x 0.5-1.6 m (a higher lift-off) "
                         "in 0.7-0.76 s (T0 = air_time + 2 height / (g air_time)), and onto a box 0.25-0.55 m high at "
                         "target_x 0.85-1.6 m where the same lift-off on flat ground would land in the long row's "
                         "target_x 0.5-1.6 m (a higher lift-off) in 0.67-0.7 s (T0 = air_time + 2 height / (g air_time))")
    beyond = region_refusal("woman", (1.2, 0.0, 0.7), 0.45)     # onto a box beyond her take-off: that limit alone
    assert beyond.startswith("target (1.2, 0, 0.7) m in air_time=0.45 s is beyond the woman's take-off")
    down = region_refusal("woman", (1.5, 0.0, -0.7), 0.45)      # down from one: the down regions, no turned one
    assert "down from a box 0.25-0.75 m high" in down and "turned first" not in down and "onto a box" not in down
    assert "the commanded take-off is offered on flat ground for target_x 0.5-1.2 m" in region_refusal("man", (1.3, 0.4), 0.72)


def all_planned_and_run(character: str, draws, store):
    """``character``'s drawn requests planned into ``store`` and run as a user's requests: (the report's results,
    their printed lines, the stored plans, the character's planner constants)."""
    from sim_core.skills.jump_to_target.behaviour import read_plans
    from sim_core.skills.jump_to_target.commanded import planner_constants
    results = [evaluate(d, 24, str(store)) for d in draws]
    return results, [result_line(r) for r in results], read_plans(character, store), planner_constants(character)


def turned_long_judged(character: str, draws, store) -> list[dict]:
    """``draws`` (targets to the side at long air times) planned into ``store`` and run as a user's requests: each plan
    the hop, then the vertical thrust, within the planner's trials, landing within the tolerances and balanced (one
    miss allowed) in at most 60 s each; returns the stored plans."""
    results, lines, plans, c = all_planned_and_run(character, draws, store)
    assert all(p["settings"]["vertical_thrust"] == 1.0 and p["settings"]["turn_angle"] != 0.0 for p in plans)
    assert all(p["trials"] <= c.turn_aim_trials + c.landing_trials - 1 + len(c.landing_leads) + c.landing_aims for p in plans)
    assert sum(r["passed"] for r in results) >= len(draws) - 1, "\n".join(lines)
    assert max(r["seconds"] for r in results) <= 60, "\n".join(lines)
    return plans


def turned_row_planned_and_run(way: str, count: int, store, character: str = "man", stream: int | None = None):
    """``count`` random targets uniform in issue 29's box where ``character``'s turned row ``way`` holds them (the
    report's draw, random_requests.draw_turned, seed SEED, or (SEED, ``stream``)) outside the measured jumps, planned
    and run as a user's requests: the hop, then the vertical thrust, within the planner's trials, landing within the
    tolerances and balanced (one miss allowed) in at most 60 s each; as (the draws, the stored plans)."""
    import numpy as np
    from sim_core.random_requests import Draw, draw_turned
    from sim_core.skills.jump_to_target.commanded import commanded_way
    rng = np.random.default_rng(SEED if stream is None else (SEED, stream))
    draws = [Draw("turned_long", character, draw_turned(rng, character, (way,))) for _ in range(count)]
    assert all(commanded_way(character, d.values[:2], d.values[2]) == way
               and not offered(character, d.values[:2], d.values[2]) for d in draws)
    return draws, turned_long_judged(character, draws, store)


def planned_and_run(draw):
    """A drawn request planned into a temporary plan store and run as a user's request: (the report's result,
    its stored plan)."""
    from sim_core.skills.jump_to_target.behaviour import read_plans
    with tempfile.TemporaryDirectory() as store:
        result = evaluate(draw, 24, store)
        plan, = read_plans(draw.character, Path(store))
    return result, plan


def first_commanded_box_draw(character, way, accept=lambda values: True, count=80):
    """The first of the report's box draws (seed SEED, the first ``count``) that ``accept`` takes, planned commanded and
    flown the commanded table's ``way`` (e.g. "down", "long_onto")."""
    from sim_core.skills.jump_to_target.commanded import commanded_way
    from sim_core.skills.jump_to_target.region import mode
    return next(d for d in draw_requests(SEED, [character], 0, 0, 0, count) if accept(d.values)
                and mode(character, (d.values[0], 0.0, d.values[1]), d.values[2]) == "commanded"
                and commanded_way(character, (d.values[0], 0.0, d.values[1]), d.values[2]) == way)


def assert_run_as_planned(result, plan):
    """The run passed (within the tolerances, balanced) and landed where its plan's trial did."""
    assert result["passed"], result_line(result)
    assert result["measured"]["landing"] == plan["measured"]["landing"]


def test_a_target_down_from_a_box_is_offered_commanded_where_its_flat_equivalent_lies_in_the_region():
    """The table's down_region: the same lift-off on flat ground (flat_equivalent) in the commanded region, the box's
    height and the flat-ground air time T0 in down_region (the woman 0.25-0.75 m, T0 0.4-0.49 s; the man 0.25-0.4 m,
    T0 0.42-0.5 s, and in his high_down_region 0.4-0.75 m with the target at most 1.6 m ahead)."""
    from sim_core.ballistics import flat_air_time
    from sim_core.skills.jump_to_target.commanded import commanded_way, flat_equivalent
    assert flat_equivalent((1.2, 0.0, -0.4), 0.6) == pytest.approx((1.2 * flat_air_time(-0.4, 0.6) / 0.6, 0.6 - 0.8 / (9.80665 * 0.6)))
    assert commanded_way("woman", (1.2, 0.0, -0.4), 0.6) == "down"
    assert commanded_way("woman", (0.5, 0.0, -0.6), 0.66) is None       # its flat-ground landing 0.37 m: too near
    assert commanded_way("woman", (1.0, 0.0, 0.3), 0.6) == "long_high_onto"   # onto a box: T0 0.70 s, the higher lift-off
    assert commanded_way("woman", (1.0, 0.0, 0.3), 0.56) is None        # onto a box: T0 0.67 s, between the long row's
    assert commanded_way("woman", (1.0, 0.0, -0.45), 0.6) == "down"
    assert commanded_way("man", (1.2, 0.0, -0.35), 0.6) == "down"       # T0 0.48 s, flat-ground landing 0.96 m
    assert commanded_way("man", (1.2, 0.0, -0.45), 0.6) == "down"       # from 0.4 m far targets: the landing for a drop
    assert commanded_way("man", (1.0, 0.0, -0.45), 0.6) == "down"       # ... and near ones (high_down_region)
    assert commanded_way("man", (1.65, 0.0, -0.7), 0.645) is None       # beyond its 1.6 m (T0 0.42 s, flat-ground landing 1.08 m)
    assert commanded_way("man", (1.65, 0.0, -0.7), 0.68) == "long_down"  # beyond it at T0 0.47 s, 2.43 m/s: the long row's second box


def test_the_man_down_from_a_higher_box_is_offered_near_and_refused_far_in_one_line():
    """His high_down_region: down from a 0.4-0.75 m box where the flat equivalent lies in his straight row and the
    target is at most 1.6 m ahead (the landing for a drop, down_settings: before it, from 1.28 m his landings fell on the
    target and the region stopped at 1.1 m), with T0 up to 0.48 s (the forefoot touches down earlier: above 0.48 s the
    straight row's deepest crouch flew short); just beyond, refused naming it."""
    from sim_core.skills.jump_to_target.commanded import commanded_way
    assert commanded_way("man", (1.05, 0.0, -0.7), 0.68) == "down"      # T0 0.47 s, flat-ground landing 0.73 m
    assert commanded_way("man", (1.55, 0.0, -0.6), 0.66) == "down"      # T0 0.47 s, flat-ground landing 1.1 m
    assert commanded_way("man", (1.65, 0.0, -0.6), 0.62) is None        # 5 cm beyond the region's 1.6 m (T0 0.42 s, flat 1.12 m)
    assert commanded_way("man", (1.65, 0.0, -0.6), 0.66) == "long_down"  # T0 0.47 s at 2.5 m/s: the long row's second box
    assert commanded_way("man", (1.05, 0.0, -0.76), 0.68) is None       # higher than issue 29's boxes
    assert commanded_way("man", (1.0, 0.0, -0.45), 0.64) is None        # T0 0.497 s: above 0.48 s, flown short
    text = region_refusal("man", (1.65, 0.0, -0.6), 0.62)
    assert text and "\n" not in text
    assert "down from a box 0.4-0.75 m high at target_x 0.5-1.6 m where the same lift-off on flat ground" in text


@pytest.mark.parametrize("character", ["man", "woman"])
def test_a_random_target_down_from_a_box_is_flown_by_the_commanded_take_off_as_its_plan_was(character):
    """Down from a box where the same lift-off on flat ground lands in the character's commanded region (the table's
    down_region): drawn as the report draws box targets, planned commanded (the crouch by the flat-ground air
    time; the woman's landing's recovery step of down_settings, the man's have it off) and run as a user's request -
    the run is the plan's trial (the recovery step read from the plan's settings, not the run's parameters)."""
    from sim_core.skills.jump_to_target.commanded import table
    box = first_commanded_box_draw(character, "down")
    result, plan = planned_and_run(box)
    step = table(character).get("down_settings", {}).get("landing_recovery_step", 0.0)
    assert plan["settings"].get("landing_recovery_step", 0.0) == step and plan["settings"]["commanded_takeoff"] == 1.0
    assert_run_as_planned(result, plan)
    assert result["measured"]["outcome"] == plan["measured"]["outcome"] == "success"


def test_a_random_target_of_the_man_down_from_a_higher_box_lands_balanced():
    """The first of the report's box draws for the man (seed SEED) down from a box above 0.4 m by his commanded take-off
    (high_down_region) beyond 1 m ahead (the region's far part; the first such draw at all is the test above's),
    planned and run as a user's request: within the tolerances and balanced, as its plan was."""
    box = first_commanded_box_draw("man", "down", lambda values: values[1] < -0.4 and values[0] > 1.0)
    assert box.values[0] <= 1.6 and box.values[1] >= -0.75
    result, plan = planned_and_run(box)
    assert plan["settings"]["commanded_takeoff"] == 1.0 and not plan["settings"].get("landing_recovery_step", 0.0)
    assert_run_as_planned(result, plan)


def test_a_target_down_from_a_box_with_a_low_lift_off_is_offered_by_the_shallow_crouch_and_refused_below_it():
    """The table's low_down_regions: down from a box where the lift-off flies below the commanded region's air times on
    flat ground (T0 0.28-0.4 s, the woman's boxes 0.25-0.6 m and, with her landing for a drop, 0.6-0.75 m at a forward speed
    of 1.3-2.5 m/s - slower she fell back onto the box, faster forward; the man's T0 0.3-0.5 s from 0.25-0.4 m boxes up to 1.45 m
    ahead, T0 0.3-0.42 s from 0.4-0.6 m boxes 0.6-1.15 m and from 0.6-0.75 m boxes 0.6-1.0 m ahead), flown with the shallower crouch's pairs; a lower
    lift-off (T0 0.12-0.27 s: 0 of 6 measured) is refused in one line naming the limit."""
    from sim_core.skills.jump_to_target.commanded import commanded_way, flat_equivalent, low_down_body, table
    assert flat_equivalent((1.0, 0.0, -0.5), 0.5)[1] == pytest.approx(0.296, abs=0.001)
    assert commanded_way("woman", (1.0, 0.0, -0.5), 0.5) == "low_down"            # T0 0.30 s
    assert commanded_way("woman", (1.0, 0.0, -0.65), 0.55) == "low_down"          # above 0.6 m at 1.82 m/s: the landing for a drop
    assert commanded_way("woman", (0.6, 0.0, -0.7), 0.55) is None                 # 1.09 m/s: she fell back onto the box
    assert commanded_way("woman", (1.5, 0.0, -0.65), 0.55) is None                # 2.73 m/s: fell forward on the target
    assert commanded_way("man", (1.4, 0.0, -0.35), 0.5) == "low_down"             # T0 0.36 s
    assert commanded_way("man", (1.6, 0.0, -0.35), 0.5) == "far_short_down"       # beyond 1.45 m the aim fell short: at
    assert commanded_way("man", (1.55, 0.0, -0.3), 0.54) is None                  # 3.2 m/s the far short row's, 2.87 m/s none
    assert commanded_way("man", (1.55, 0.0, -0.3), 0.56) == "long_down"           # (T0 0.43 s); at T0 0.45 s the long row's second box
    assert commanded_way("man", (0.9, 0.0, -0.6), 0.55) == "low_down"             # T0 0.33 s from a higher box
    assert commanded_way("man", (0.55, 0.0, -0.6), 0.55) == "low_down"            # near a higher box: the landing for a drop
    assert commanded_way("man", (0.45, 0.0, -0.6), 0.55) is None                  # nearer than 0.5 m: not offered
    assert commanded_way("man", (1.2, 0.0, -0.35), 0.6) == "down"                 # the straight row's as before
    assert low_down_body(table("woman"))["crouch_by_air_time"]["crouch_height"][0] == 0.6
    text = region_refusal("woman", (1.0, 0.0, -0.7), 0.45)                         # T0 0.13 s
    assert text and "\n" not in text and "down from a box 0.25-0.6 m high at target_x 0.5-1.6 m where the lift-off " \
        "would fly 0.28-0.4 s on flat ground" in text and "a lower lift-off than its shallowest crouch's is not flown" in text
    text = region_refusal("woman", (0.6, 0.0, -0.7), 0.55)
    assert text and "\n" not in text and "down from a box 0.6-0.75 m high at a forward speed of 1.3-2.5 m/s " \
        "(target_x / air_time) where the lift-off would fly 0.28-0.4 s on flat ground" in text


@pytest.mark.parametrize("character", ["man", "woman"])
def test_a_random_target_down_from_a_box_with_a_low_lift_off_lands_balanced(character):
    """The first of the report's box draws (seed SEED) in the low_down_regions, planned with the shallow crouch's pairs
    and run as a user's request: within 5 cm and 0.05 s and balanced, as its plan was."""
    from sim_core.skills.jump_to_target.commanded import flat_equivalent, table
    box = first_commanded_box_draw(character, "low_down")
    result, plan = planned_and_run(box)
    low = table(character)["low_down_regions"]
    assert flat_equivalent((box.values[0], 0.0, box.values[1]), box.values[2])[1] <= max(b["flat_air_time"][1] for b in low)
    assert plan["settings"]["commanded_takeoff"] == 1.0
    assert_run_as_planned(result, plan)


def test_the_woman_down_from_a_box_between_her_straight_row_and_her_long_row_is_offered_slowly_by_a_lower_damping():
    """Her third low_down box: T0 0.49-0.52 s (down_region ends at 0.49 s, her crouch pairs' deepest 0.45 m) from 0.25-0.75
    m boxes at a forward speed of 0.7-1.6 m/s, flown by the shallow crouch's deepest crouch with the thrust's damping
    lowered beyond 0.49 s (low_down_crouch_by_air_time's thrust_damping column: a higher lift-off from the same crouch;
    the settings' own damping up to 0.49 s, so the rows before plan as they did); faster the flights fell short or the
    landings fell; beyond, refused in one line naming it. No simulation."""
    from sim_core.skills.jump_to_target.commanded import commanded_settings, commanded_way, table, way_body
    body = way_body(table("woman"), "low_down")
    own = table("woman")["settings"]["thrust_damping"]
    assert commanded_settings(body, 0.35, 1.0, -0.5)["thrust_damping"] == own                  # the boxes before as they were
    assert commanded_settings(body, 0.49, 1.0, -0.5)["thrust_damping"] == own
    settings = commanded_settings(body, 0.52, 1.0, -0.5)
    assert settings["crouch_height"] == 0.45 and settings["thrust_damping"] == pytest.approx(0.65)
    assert "lean_push" not in settings and settings["landing_recovery_step"] == 1.0
    assert commanded_way("woman", (0.8, 0.0, -0.4), 0.6) == "down"                # T0 0.46 s: the straight row's as before
    assert commanded_way("woman", (0.8, 0.0, -0.4), 0.63) == "low_down"           # T0 0.50 s at 1.27 m/s
    assert commanded_way("woman", (0.52, 0.0, -0.308), 0.608) == "low_down"       # T0 0.505 s at 0.86 m/s: the test's draw
    assert commanded_way("woman", (1.2, 0.0, -0.5), 0.66) is None                 # 1.82 m/s: flown short or fell
    assert commanded_way("woman", (0.8, 0.0, -0.3), 0.64) == "low_down"           # T0 0.54 s: the fourth box (the test below)
    text = region_refusal("woman", (1.3, 0.0, -0.45), 0.45)
    assert text and "\n" not in text and "down from a box 0.25-0.75 m high at a forward speed of 0.7-1.6 m/s (target_x / " \
        "air_time) where the lift-off would fly 0.49-0.52 s on flat ground" in text


def test_the_woman_down_from_a_box_at_her_long_rows_air_times_is_offered_slowly_by_a_lower_damping_still():
    """Her fourth low_down box: T0 0.52-0.63 s (issue 29's down targets reach ~0.627 s; her long row down from a box fell
    on landing) from 0.25-0.75 m boxes at 0.6-1.6 m at 0.7-1.6 m/s, flown by the shallow crouch's deepest crouch (0.45 m)
    with the thrust's damping lowered further (0.42 at 0.6 s, 0.32 at 0.64 s: on flat ground 0.4 / 0.3 flew 0.595-0.655 /
    0.645-0.685 s); faster, from ~1.75 m/s, the aims missed or the landings fell, nearer than ~0.55 m she landed long;
    beyond, refused in one line naming it. No simulation."""
    from sim_core.skills.jump_to_target.commanded import commanded_settings, commanded_way, table, way_body
    body = way_body(table("woman"), "low_down")
    for air_time, damping in ((0.56, 0.5), (0.6, 0.42), (0.64, 0.32)):
        settings = commanded_settings(body, air_time, 1.0, -0.3)
        assert settings["crouch_height"] == 0.45 and settings["thrust_damping"] == pytest.approx(damping)
    assert commanded_way("woman", (1.0, 0.0, -0.25), 0.7) == "low_down"           # T0 0.627 s at 1.43 m/s
    assert commanded_way("woman", (0.75, 0.0, -0.26), 0.7) == "low_down"          # T0 0.624 s at 1.07 m/s
    assert commanded_way("woman", (1.15, 0.0, -0.3), 0.7) is None                 # T0 0.613 s at 1.64 m/s: just beyond
    assert commanded_way("woman", (1.2, 0.0, -0.3), 0.67) is None                 # T0 0.579 s at 1.79 m/s: missed or fell
    assert commanded_way("woman", (0.58, 0.0, -0.3), 0.66) is None                # T0 0.57 s at 0.58 m: landed long
    assert commanded_way("woman", (0.52, 0.0, -0.308), 0.608) == "low_down"       # T0 0.505 s: the third box's as before
    text = region_refusal("woman", (1.15, 0.0, -0.3), 0.7)
    assert text and "\n" not in text and "down from a box 0.25-0.75 m high at target_x 0.6-1.6 m at a forward speed of " \
        "0.7-1.6 m/s (target_x / air_time) where the lift-off would fly 0.52-0.63 s on flat ground" in text


@pytest.mark.slow
def test_a_random_target_of_the_woman_down_from_a_box_at_her_long_rows_air_times_lands_balanced():
    """The first of the report's box draws for the woman (seed SEED) in her fourth low_down box (T0 0.52-0.63 s), planned
    by the shallow crouch's deepest crouch with the damping lowered and run as a user's request: within 5 cm and 0.05 s
    and balanced, as its plan was."""
    box = first_commanded_box_draw("woman", "low_down", lambda values: flat_air_time(values[1], values[2]) > 0.52, count=400)
    x, z, air_time = box.values
    assert 0.6 <= x and 0.7 <= x / air_time <= 1.6
    result, plan = planned_and_run(box)
    settings = plan["settings"]     # the last aim's crouch and damping (the plan's air time steps either way)
    assert settings["commanded_takeoff"] == 1.0 and settings["landing_recovery_step"] == 1.0
    assert_run_as_planned(result, plan)


@pytest.mark.slow
def test_a_random_target_of_the_woman_down_from_a_box_between_her_rows_lands_balanced():
    """The first of the report's box draws for the woman (seed SEED) in her third low_down box (T0 0.49-0.52 s), planned
    by the shallow crouch's pairs (the deepest crouch, the damping lowered beyond 0.49 s) and run as a user's request:
    within 5 cm and 0.05 s and balanced, as its plan was."""
    box = first_commanded_box_draw("woman", "low_down", lambda values: 0.49 < flat_air_time(values[1], values[2]) <= 0.52,
                                   count=400)
    x, z, air_time = box.values
    assert 0.7 <= x / air_time <= 1.6
    result, plan = planned_and_run(box)
    settings = plan["settings"]     # the last aim's crouch and damping (the plan's air time steps either way)
    assert settings["commanded_takeoff"] == 1.0 and settings["landing_recovery_step"] == 1.0
    assert_run_as_planned(result, plan)


def test_the_man_near_down_from_a_higher_box_is_offered_by_the_shallow_crouch_and_refused_beyond_in_one_line():
    """His fourth low_down box: down from a 0.4-0.75 m box 0.5-0.7 m ahead where the lift-off flies T0 0.3-0.46 s on flat
    ground (before the landing for a drop, down_settings, the targets nearer than 0.6 m fell on the target; T0 0.47-0.5 s
    flew 0.067-0.075 s short); his other down rows keep their targets; beyond, refused in one line naming it."""
    from sim_core.skills.jump_to_target.commanded import commanded_way
    assert commanded_way("man", (0.55, 0.0, -0.6), 0.55) == "low_down"            # T0 0.33 s from a 0.6 m box
    assert commanded_way("man", (0.57, 0.0, -0.494), 0.584) == "low_down"         # T0 0.41 s: the test's draw below
    assert commanded_way("man", (0.55, 0.0, -0.6), 0.68) is None                  # T0 0.50 s: flown short
    assert commanded_way("man", (0.68, 0.0, -0.7), 0.65) == "low_down"            # T0 0.43 s from a 0.7 m box
    assert commanded_way("man", (0.72, 0.0, -0.7), 0.65) is None                  # beyond 0.7 m there: not measured
    assert commanded_way("man", (0.75, 0.0, -0.6), 0.62) == "down"                # the straight row's as before
    text = region_refusal("man", (0.55, 0.0, -0.6), 0.68)
    assert text and "\n" not in text and "down from a box 0.4-0.75 m high at target_x 0.5-0.7 m where the lift-off " \
        "would fly 0.3-0.46 s on flat ground" in text


@pytest.mark.slow
def test_a_random_target_of_the_man_near_down_from_a_higher_box_lands_balanced():
    """The first of the report's box draws for the man (seed SEED) in his low_down_regions from a 0.4-0.75 m box beyond
    their old bounds (nearer than 0.6 m or T0 above 0.42 s), planned with the shallow crouch's pairs and the landing for
    a drop (down_settings) and run as a user's request: within 5 cm and 0.05 s and balanced, as its plan was."""
    from sim_core.skills.jump_to_target.commanded import flat_equivalent
    beyond = lambda v: v[1] <= -0.4 and v[0] <= 0.7 and (v[0] < 0.6 or flat_equivalent((v[0], 0.0, v[1]), v[2])[1] > 0.42)
    box = first_commanded_box_draw("man", "low_down", beyond, count=400)
    result, plan = planned_and_run(box)
    assert plan["settings"]["commanded_takeoff"] == 1.0 and plan["settings"]["landing_toe_first_at_speed"] == 1.0
    assert_run_as_planned(result, plan)


@pytest.mark.slow
def test_a_random_target_of_the_woman_down_from_a_higher_box_with_a_low_lift_off_lands_balanced():
    """The first of the report's box draws for the woman (seed SEED) in her low_down_regions from a box above 0.6 m (beyond
    the row's old bounds: before her landing for a drop half of them fell), planned with her down_settings and the shallow
    crouch's pairs and run as a user's request: within 5 cm and 0.05 s and balanced, as its plan was."""
    box = first_commanded_box_draw("woman", "low_down", lambda values: values[1] < -0.6, count=400)
    assert 1.3 <= box.values[0] / box.values[2] <= 2.5
    result, plan = planned_and_run(box)
    settings = plan["settings"]
    assert settings["landing_toe_first_at_speed"] == 1.0 and settings["landing_delta_from_drop"] == 1.0
    assert settings["commanded_takeoff"] == 1.0 and settings["landing_recovery_step"] == 1.0
    assert_run_as_planned(result, plan)


def test_the_man_down_from_a_box_by_his_near_long_row_is_offered_near_and_refused_beyond_in_one_line():
    """His near_long_down_region: down from a 0.25-0.6 m box where the same lift-off on flat ground lands in his near
    long row's region (T0 0.5-0.65 s), the target at most 1.3 m ahead; with the landing for a drop (down_settings: the
    forefoot first at any forward speed, the landing table's delta for the drop, no recovery step) - before it the region
    stopped at 0.45 m, 1.2 m and 0.655 s (beyond, the landings fell on the target: the shanks touched the ground);
    beyond 1.3 m the landings stand but the aims miss; just beyond, refused naming it."""
    from sim_core.skills.jump_to_target.commanded import commanded_way
    assert commanded_way("man", (1.1, 0.0, -0.35), 0.65) == "near_long_down"     # T0 0.54 s, flat landing 0.91 m
    assert commanded_way("man", (1.28, 0.0, -0.35), 0.65) == "near_long_down"    # beyond 1.2 m: the landing for a drop
    assert commanded_way("man", (1.4, 0.0, -0.35), 0.65) is None                 # beyond 1.3 m: the aims missed
    assert commanded_way("man", (1.0, 0.0, -0.35), 0.68) == "near_long_down"     # asked above 0.655 s: likewise
    assert commanded_way("man", (1.0, 0.0, -0.55), 0.7) == "near_long_down"      # T0 0.54 s from a 0.55 m box
    assert commanded_way("man", (1.0, 0.0, -0.65), 0.7) is None                  # above 0.6 m: not measured
    text = region_refusal("man", (1.0, 0.0, -0.65), 0.7)
    assert text and "\n" not in text and "down from a box 0.25-0.6 m high at target_x 0.5-1.3 m " \
        "where the same lift-off on flat ground would land in the near long row's region in 0.5-0.65 s" in text


OLD_DOWN_LIMITS = {      # the man's down-from-a-box regions before the landing for a drop (down_settings): beyond them, new
    "down": lambda x, z, t: z < -0.4 and x > 1.1,                          # high_down_region's target_x 1.1 m
    "push_down": lambda x, z, t: x / t > 2.2,                              # target_speed 2.2 m/s
    "near_long_down": lambda x, z, t: x > 1.2 or z < -0.45 or t > 0.655,   # 0.45 m, 1.2 m, 0.655 s
}


@pytest.mark.slow
@pytest.mark.parametrize("way", list(OLD_DOWN_LIMITS))
def test_a_random_target_of_the_man_down_from_a_box_beyond_the_old_limits_lands_balanced(way):
    """The first of the report's box draws for the man (seed SEED) in each of his down-from-a-box rows beyond where that
    row stopped before the landing for a drop (the table's down_settings: the forefoot lands first at any forward speed,
    landing_toe_first_at_speed - landed flat after a ~0.75 m drop the soles sank 3.7 cm and the shanks touched the ground;
    the landing table's delta for the touchdown speed on the ground below, landing_delta_from_drop; no recovery step),
    planned and run as a user's request: within 5 cm and 0.05 s and balanced, as its plan was, with those settings."""
    box = first_commanded_box_draw("man", way, lambda values: OLD_DOWN_LIMITS[way](*values), count=200)
    result, plan = planned_and_run(box)
    settings = plan["settings"]
    assert settings["landing_toe_first_at_speed"] == 1.0 and settings["landing_delta_from_drop"] == 1.0
    assert settings["commanded_takeoff"] == 1.0 and not settings.get("landing_recovery_step", 0.0)
    assert_run_as_planned(result, plan)


@pytest.mark.slow
def test_a_random_target_of_the_man_down_from_a_box_by_his_near_long_row_lands_balanced():
    """The first of the report's box draws for the man (seed SEED) in his near_long_down_region, planned with the near
    long row (the vertical thrust, its lean push 10; the landing for a drop, down_settings, without the row's recovery
    step) and run as a user's request: within 5 cm and 0.05 s and balanced, as its plan was."""
    box = first_commanded_box_draw("man", "near_long_down")
    result, plan = planned_and_run(box)
    assert plan["settings"]["vertical_thrust"] == 1.0 and plan["settings"]["lean_push"] == 10.0
    assert plan["settings"]["commanded_takeoff"] == 1.0
    assert_run_as_planned(result, plan)


def test_a_target_down_from_a_box_with_a_lower_lift_off_is_offered_by_its_forward_speed_and_refused_beyond():
    """The table's push_down_regions: down from a box where the lift-off flies below the shallow crouch's on flat ground
    (the man's T0 0.1-0.3 s from 0.25-0.75 m boxes, his lean push 10; the woman's T0 0.21-0.28 s from 0.25-0.75 m boxes - to 0.4 m and from 2.0 m/s before her landing for a drop,
    from T0 0.25 s and to 2.4 m/s before her lean push 10), bounded by the target's forward speed x / air time (the man's
    1.55-3.6 m/s - to 2.2 m/s before the landing for a drop, down_settings, faster his landings fell; beyond 3.6 m/s his
    aims miss - the woman's 1.6-2.8 m/s; slower the aim overshot); the rows before keep their targets; beyond, refused in
    one line naming it. No simulation."""
    from sim_core.skills.jump_to_target.commanded import commanded_way, push_down_body, table
    assert commanded_way("man", (0.85, 0.0, -0.6), 0.45) == "push_down"          # T0 0.18 s at 1.89 m/s
    assert commanded_way("man", (1.2, 0.0, -0.6), 0.45) == "push_down"            # 2.67 m/s: the landing for a drop
    assert commanded_way("man", (1.7, 0.0, -0.6), 0.45) is None                   # 3.78 m/s: the aims missed
    assert commanded_way("man", (0.6, 0.0, -0.6), 0.45) is None                   # 1.33 m/s: the aim overshot
    assert commanded_way("man", (0.9, 0.0, -0.6), 0.55) == "low_down"             # T0 0.33 s: the shallow crouch's as before
    assert commanded_way("woman", (0.9, 0.0, -0.3), 0.42) == "push_down"          # T0 0.27 s at 2.14 m/s
    assert commanded_way("woman", (0.9, 0.0, -0.4), 0.42) == "push_down"          # T0 0.23 s: her lean push 10 (it toppled without)
    assert commanded_way("woman", (1.05, 0.0, -0.45), 0.47) == "push_down"        # T0 0.27 s above 0.4 m: the landing for a drop
    assert commanded_way("woman", (1.1, 0.0, -0.7), 0.53) == "push_down"          # T0 0.26 s from a 0.7 m box at 2.08 m/s
    assert commanded_way("woman", (1.35, 0.0, -0.7), 0.53) == "push_down"         # 2.55 m/s: it pitched off the box without the push
    assert commanded_way("woman", (1.5, 0.0, -0.7), 0.53) is None                 # 2.83 m/s: beyond ~3 m/s her aims fell short
    assert commanded_way("woman", (1.0, 0.0, -0.7), 0.5) == "push_down"           # T0 0.214 s with the push
    assert commanded_way("woman", (1.0, 0.0, -0.7), 0.48) is None                 # T0 0.18 s from a 0.7 m box: flown short or long
    assert commanded_way("woman", (1.0, 0.0, -0.5), 0.5) == "low_down"            # T0 0.30 s as before
    assert push_down_body(table("man"))["settings"]["lean_push"] == 10.0
    text = region_refusal("man", (1.7, 0.0, -0.6), 0.45)
    assert text and "\n" not in text and "down from a box 0.25-0.75 m high at a forward speed of 1.55-3.6 m/s " \
        "(target_x / air_time) where the lift-off would fly 0.1-0.3 s on flat ground" in text
    assert commanded_way("woman", (0.8, 0.0, -0.4), 0.45) == "push_down"          # T0 0.27 s at 1.78 m/s: slower, new
    assert commanded_way("woman", (0.66, 0.0, -0.4), 0.45) is None                # 1.47 m/s: not measured
    text = region_refusal("woman", (1.5, 0.0, -0.7), 0.53)
    assert text and "\n" not in text and "down from a box 0.25-0.75 m high at a forward speed of 1.6-2.8 m/s " \
        "(target_x / air_time) where the lift-off would fly 0.21-0.28 s on flat ground" in text


def test_the_womans_ways_down_from_a_box_land_for_a_drop_with_her_recovery_step():
    """Her down_settings: the landing for a drop (the forefoot first at any forward speed, the landing table's delta for
    the drop) with her landing's recovery step kept (without it her rows fell: 27 / 36 against 34 / 36 with it), so every
    way down from a box plans with them. No simulation."""
    from sim_core.skills.jump_to_target.commanded import commanded_settings, table, way_body
    body = table("woman")
    assert body["down_settings"] == {"landing_toe_first_at_speed": 1.0, "landing_delta_from_drop": 1.0,
                                     "landing_recovery_step": 1.0}
    for way in ("down", "low_down", "push_down"):
        settings = commanded_settings(way_body(body, way), 0.3, 1.0, -0.5)
        assert settings["landing_toe_first_at_speed"] == settings["landing_delta_from_drop"] == 1.0
        assert settings["landing_recovery_step"] == 1.0
    assert "landing_toe_first_at_speed" not in commanded_settings(body, 0.45, 1.0)      # flat ground as before


@pytest.mark.slow
def test_a_random_target_of_the_woman_down_from_a_higher_box_with_a_lower_lift_off_lands_balanced():
    """The first of the report's box draws for the woman (seed SEED) in her push_down_regions from a box above 0.4 m (beyond
    the row's old bounds: before her landing for a drop the aims there fell short), planned with her down_settings and
    run as a user's request: within 5 cm and 0.05 s and balanced, as its plan was."""
    box = first_commanded_box_draw("woman", "push_down", lambda values: values[1] < -0.4, count=400)
    result, plan = planned_and_run(box)
    settings = plan["settings"]
    assert settings["landing_toe_first_at_speed"] == 1.0 and settings["landing_delta_from_drop"] == 1.0
    assert settings["commanded_takeoff"] == 1.0 and settings["landing_recovery_step"] == 1.0
    assert_run_as_planned(result, plan)


@pytest.mark.slow
@pytest.mark.parametrize("character", ["man", "woman"])
def test_a_random_target_down_from_a_box_with_a_lower_lift_off_lands_balanced(character):
    """The first of the report's box draws (seed SEED) in the push_down_regions (the woman's is small: the first 200
    draws), planned with the row's settings and crouch pairs and run as a user's request: within 5 cm and 0.05 s and
    balanced, as its plan was."""
    from sim_core.skills.jump_to_target.commanded import flat_equivalent, table
    box = first_commanded_box_draw(character, "push_down", count=200)
    x, z, air_time = box.values
    row = table(character)["push_down_regions"][0]         # the lower lift-off's box (the man's second: the test below)
    assert row["flat_air_time"][0] <= flat_equivalent((x, 0.0, z), air_time)[1] <= row["flat_air_time"][1]
    assert row["target_speed"][0] <= x / air_time <= row["target_speed"][1]
    result, plan = planned_and_run(box)
    assert plan["settings"]["commanded_takeoff"] == 1.0
    assert plan["settings"].get("lean_push", 0.0) == table(character)["push_down_settings"].get("lean_push", 0.0)
    assert_run_as_planned(result, plan)


def test_the_woman_down_from_a_box_with_a_lower_lift_off_flies_her_lean_push_from_t0_01_s_to_28_m_s():
    """Her push_down_regions with the man's lean push 10 (push_down_settings; with her own push 3 the take-off toppled off
    the box's edge at T0 0.2-0.23 s and pitched off it from 2.57 m/s): T0 0.21-0.28 s (was 0.25 s) at 1.6-2.8 m/s (was
    2.4 m/s) from 0.25-0.75 m boxes, her crouch pairs there and down_settings as before, and a second box T0 0.1-0.21 s
    from 0.25-0.6 m boxes with a shallower pair (0.68 m: 0.17 s; above 0.6 m the aims flew 0.08-0.09 s short or long);
    beyond, faster than 2.8 m/s or slower than 1.6 m/s refused in one line. No simulation."""
    from sim_core.skills.jump_to_target.commanded import commanded_settings, commanded_way, table, way_body
    body = table("woman")
    assert body["push_down_settings"] == {"lean_push": 10.0}
    settings = commanded_settings(way_body(body, "push_down"), 0.22, 1.0, -0.5)
    assert settings["lean_push"] == 10.0 and settings["landing_recovery_step"] == 1.0
    assert settings["crouch_height"] == pytest.approx(0.65)                        # her 0.65 m pair, held from 0.21 s
    assert commanded_settings(way_body(body, "push_down"), 0.17, 1.0, -0.5)["crouch_height"] == pytest.approx(0.68)
    assert "lean_push" not in commanded_settings(way_body(body, "low_down"), 0.3, 1.0, -0.5)     # the shallow crouch's own
    assert commanded_way("woman", (0.93, 0.0, -0.429), 0.424) == "push_down"       # T0 0.218 s at 2.19 m/s
    assert commanded_way("woman", (1.24, 0.0, -0.507), 0.473) == "push_down"       # T0 0.254 s at 2.62 m/s
    assert commanded_way("woman", (1.3, 0.0, -0.45), 0.45) is None                 # 2.89 m/s: aims at their cap fell short
    assert commanded_way("woman", (0.7, 0.0, -0.6), 0.5) is None                   # 1.4 m/s: the slow aims overshot or fell
    assert commanded_way("woman", (0.9, 0.0, -0.55), 0.44) == "push_down"          # T0 0.18 s: the shallower pair
    assert commanded_way("woman", (0.9, 0.0, -0.58), 0.41) == "push_down"          # T0 0.12 s from a 0.58 m box
    assert commanded_way("woman", (0.9, 0.0, -0.65), 0.44) is None                 # T0 0.14 s from a 0.65 m box: missed
    assert commanded_way("woman", (0.8, 0.0, -0.6), 0.4) is None                   # T0 0.09 s: not measured
    text = region_refusal("woman", (1.3, 0.0, -0.45), 0.45)
    assert text and "\n" not in text and "at a forward speed of 1.6-2.8 m/s (target_x / air_time) where the lift-off " \
        "would fly 0.21-0.28 s on flat ground (the lean push's low lift-off" in text
    assert "down from a box 0.25-0.6 m high at a forward speed of 1.6-2.8 m/s (target_x / air_time) where the lift-off " \
        "would fly 0.1-0.21 s on flat ground" in text


WOMANS_PUSH_BEYOND = {      # her push_down box's draws beyond its bounds before her lean push 10 (T0 0.25-0.28 s, 2.4 m/s)
    "lower": lambda x, z, t: flat_air_time(z, t) < 0.25,
    "faster": lambda x, z, t: x / t > 2.4,
    "lowest": lambda x, z, t: flat_air_time(z, t) < 0.21,      # the second box (the shallower pair)
}


@pytest.mark.slow
@pytest.mark.parametrize("beyond", list(WOMANS_PUSH_BEYOND))
def test_a_random_target_of_the_woman_down_from_a_box_with_her_lean_push_lands_balanced(beyond):
    """The first of the report's box draws for the woman (seed SEED) in her push_down_regions beyond its old bounds (T0
    below 0.25 s, faster than 2.4 m/s, the second box below 0.21 s), planned with the lean push 10 and her down_settings
    and run as a user's request: within 5 cm and 0.05 s and balanced, as its plan was."""
    box = first_commanded_box_draw("woman", "push_down", lambda values: WOMANS_PUSH_BEYOND[beyond](*values), count=400)
    result, plan = planned_and_run(box)
    settings = plan["settings"]
    assert settings["lean_push"] == 10.0 and settings["commanded_takeoff"] == 1.0
    assert settings["landing_toe_first_at_speed"] == 1.0 and settings["landing_recovery_step"] == 1.0
    assert_run_as_planned(result, plan)


def test_the_man_down_from_a_box_far_ahead_is_offered_by_the_push_and_the_far_short_row_by_forward_speed():
    """The man's targets down from a box far ahead: the lean push's second box (push_down_regions: 0.25-0.6 m boxes, T0
    0.3-0.44 s, 2.2-2.6 m/s; faster its landings fell or scattered, from higher boxes too) and his far short row's
    far_short_down_regions (the long row at its shallowest crouches: 0.25-0.75 m boxes, T0 0.35-0.47 s, 2.9-3.6 m/s; slower
    it overshoots, as on flat ground), both bounded by the target's forward speed alone and checked after every other way
    down (the targets offered before keep their ways); beyond, refused in one line naming them. No simulation."""
    from sim_core.skills.jump_to_target.commanded import commanded_settings, commanded_way, table, way_body
    assert commanded_way("man", (1.4, 0.0, -0.55), 0.58) == "push_down"           # T0 0.39 s at 2.41 m/s
    assert commanded_way("man", (1.5, 0.0, -0.55), 0.6) == "push_down"            # T0 0.41 s at 2.5 m/s
    assert commanded_way("man", (1.5, 0.0, -0.5), 0.555) is None                  # 2.70 m/s: on the target and fell
    assert commanded_way("man", (1.45, 0.0, -0.7), 0.62) is None                  # a 0.7 m box at 2.34 m/s: fell
    assert commanded_way("man", (1.45, 0.0, -0.5), 0.6) == "down"                 # T0 0.43 s: the straight row's as before
    assert commanded_way("man", (0.9, 0.0, -0.6), 0.55) == "low_down"             # the shallow crouch's as before
    assert commanded_way("man", (1.75, 0.0, -0.35), 0.56) == "far_short_down"     # T0 0.43 s at 3.12 m/s
    assert commanded_way("man", (1.9, 0.0, -0.7), 0.64) == "far_short_down"       # from a 0.7 m box at 2.97 m/s
    assert commanded_way("man", (1.6, 0.0, -0.35), 0.56) is None                  # 2.86 m/s: the far row overshoots
    assert commanded_way("man", (1.65, 0.0, -0.3), 0.49) == "far_short_down"      # T0 0.36 s: its shallowest crouch held
    assert commanded_way("man", (1.6, 0.0, -0.45), 0.52) is None                  # T0 0.34 s: not measured
    body = way_body(table("man"), "far_short_down")
    assert body["crouch_by_air_time"] == table("man")["far_short_crouch_by_air_time"]
    settings = commanded_settings(body, 0.43, 1.75, -0.35)
    assert settings["lean_push"] == table("man")["long_settings"]["lean_push"] and settings["vertical_thrust"] == 1.0
    assert settings["landing_toe_first_at_speed"] == 1.0 and settings["landing_recovery_step"] == 0.0   # down_settings
    text = region_refusal("man", (1.6, 0.0, -0.35), 0.56)
    assert text and "\n" not in text
    assert "down from a box 0.25-0.6 m high at a forward speed of 2.2-2.6 m/s (target_x / air_time) where the lift-off " \
        "would fly 0.3-0.44 s on flat ground" in text
    assert "down from a box 0.25-0.75 m high at a forward speed of 2.9-3.6 m/s (target_x / air_time) where the lift-off " \
        "would fly 0.35-0.47 s on flat ground (the far short row's lift-off, its own forward speed)" in text


def test_the_man_down_from_a_box_far_ahead_by_his_long_row_is_offered_by_forward_speed_and_refused_beyond():
    """His long_down_regions: down from a 0.25-0.75 m box 1.4-1.9 m ahead where the lift-off flies 0.49-0.6 s on flat
    ground at a forward speed of 2.3-3.3 m/s (target_x / air_time: his long row's speeds on flat ground; slower it
    overshot), and at 0.45-0.49 s at 2.3-2.9 m/s (the second box; faster, or below 0.45 s, it flew long), flown by his far long row (the vertical thrust, its lean push 3 and crouch pairs)
    with the landing for a drop (down_settings); checked after every other way down (the targets offered before keep
    their ways); the woman's long row down from a box is not offered (its landings fell); beyond, refused in one line
    naming it. No simulation."""
    from sim_core.skills.jump_to_target.commanded import commanded_settings, commanded_way, table, way_body
    assert commanded_way("man", (1.6, 0.0, -0.4), 0.63) == "long_down"            # T0 0.50 s at 2.54 m/s
    assert commanded_way("man", (1.6, 0.0, -0.45), 0.62) == "long_down"           # T0 0.47 s at 2.58 m/s: the second box
    assert commanded_way("man", (1.8, 0.0, -0.3), 0.58) is None                   # T0 0.47 s at 3.10 m/s: flown long
    assert commanded_way("man", (1.7, 0.0, -0.6), 0.62) is None                   # T0 0.42 s: flown long
    assert commanded_way("man", (1.5, 0.0, -0.55), 0.68) is None                  # 2.21 m/s: it overshot
    assert commanded_way("man", (1.9, 0.0, -0.3), 0.6) == "long_down"             # T0 0.50 s at 3.17 m/s
    assert commanded_way("man", (1.8, 0.0, -0.6), 0.65) == "long_down"            # T0 0.46 s at 2.77 m/s: the second box
    assert commanded_way("man", (1.45, 0.0, -0.35), 0.72) is None                 # T0 0.62 s: not measured
    assert commanded_way("man", (1.95, 0.0, -0.35), 0.6) is None                  # beyond 1.9 m
    assert commanded_way("man", (1.3, 0.0, -0.35), 0.6) == "down"                 # the straight row's as before
    assert commanded_way("man", (1.75, 0.0, -0.35), 0.56) == "far_short_down"     # T0 0.43 s: the far short row's as before
    assert commanded_way("woman", (1.2, 0.0, -0.35), 0.68) is None                # hers: T0 0.57 s, not offered
    body = way_body(table("man"), "long_down")
    assert body["crouch_by_air_time"] == table("man")["long_crouch_by_air_time"]
    settings = commanded_settings(body, 0.52, 1.6, -0.4)
    assert settings["vertical_thrust"] == 1.0 and settings["lean_push"] == table("man")["long_settings"]["lean_push"]
    assert settings["landing_toe_first_at_speed"] == 1.0 and settings["landing_recovery_step"] == 0.0   # down_settings
    text = region_refusal("man", (1.7, 0.0, -0.6), 0.62)
    assert text and "\n" not in text
    assert "down from a box 0.25-0.75 m high at target_x 1.4-1.9 m at a forward speed of 2.3-3.3 m/s (target_x / air_time) " \
        "where the lift-off would fly 0.49-0.6 s on flat ground (the long row's lift-off, its own forward speed)" in text
    assert "down from a box 0.25-0.75 m high at target_x 1.4-1.9 m at a forward speed of 2.3-2.9 m/s (target_x / air_time) " \
        "where the lift-off would fly 0.45-0.49 s on flat ground (the long row's lift-off, its own forward speed)" in text


FAR_DOWN_ROWS = {       # the man's new boxes down from a box far ahead: the way, and which of its draws are the new box's
    "push_down": ("push_down", lambda x, z, t: flat_air_time(z, t) > 0.3),     # the second box (the first: T0 0.1-0.3 s)
    "far_short_down": ("far_short_down", lambda x, z, t: True),
    "long_down": ("long_down", lambda x, z, t: flat_air_time(z, t) >= 0.49),  # his far long row's (T0 0.49-0.6 s)
    "long_down_second": ("long_down", lambda x, z, t: flat_air_time(z, t) < 0.49),   # its second box (T0 0.45-0.49 s)
}


@pytest.mark.slow
@pytest.mark.parametrize("box_name", list(FAR_DOWN_ROWS))
def test_a_random_target_of_the_man_down_from_a_box_far_ahead_lands_balanced(box_name):
    """The first of the report's box draws for the man (seed SEED) in each new box down from a box far ahead (the lean
    push's second box, the far short row's, the far long row's two), planned with that row and the landing for a drop
    (down_settings) and run as a user's request: within 5 cm and 0.05 s and balanced, as its plan was."""
    way, accept = FAR_DOWN_ROWS[box_name]
    box = first_commanded_box_draw("man", way, lambda values: accept(*values), count=400)
    result, plan = planned_and_run(box)
    settings = plan["settings"]
    assert settings["commanded_takeoff"] == 1.0 and settings["landing_toe_first_at_speed"] == 1.0
    assert settings["lean_push"] == (10.0 if way == "push_down" else 3.0)
    assert_run_as_planned(result, plan)


def test_a_random_target_onto_a_box_is_flown_by_the_long_row_as_its_plan_was():
    """Onto a box where the same lift-off on flat ground lands in her long air times' region (the table's
    long_onto_region: T0 = T + 2 h / (g T)): the first such draw of the report's box targets, planned commanded
    with the long row (the vertical thrust, its crouch pairs, the recovery step) and run as a user's request;
    a nearer box (its front edge not cleared) and a higher flat-ground air time are not offered."""
    from sim_core.skills.jump_to_target.commanded import commanded_way
    assert commanded_way("woman", (1.0, 0.0, 0.35), 0.5) == "long_onto"          # T0 0.64 s at 1.28 m
    assert commanded_way("woman", (0.7, 0.0, 0.35), 0.5) == "tucked_onto"         # the box's edge 0.4 m ahead: not the long row
    assert commanded_way("woman", (1.0, 0.0, 0.6), 0.5) is None                   # T0 0.74 s
    assert commanded_way("woman", (0.95, 0.0, 0.45), 0.43) == "long_onto"        # T0 0.64 s at 1.42 m
    assert commanded_way("woman", (0.95, 0.0, 0.52), 0.43) == "shallow_long_high_onto"   # T0 0.68 s: a 0.5 m crouch's
    assert commanded_way("woman", (0.95, 0.0, 0.56), 0.42) is None                # T0 0.69 s, but higher than measured
    assert commanded_way("woman", (0.9, 0.0, 0.3), 0.45) is None                 # 0.85-0.92 m: the long row's near edge missed
    text = region_refusal("woman", (0.9, 0.0, 0.3), 0.45)
    assert text and "\n" not in text and "onto a box 0.25-0.5 m high at target_x 0.92-1.6 m" in text
    assert commanded_way("man", (1.0, 0.0, 0.35), 0.5) == "near_long_onto"        # his flat equivalent 1.28 m: short of his long row, his near row's
    box = first_commanded_box_draw("woman", "long_onto")
    result, plan = planned_and_run(box)
    assert plan["settings"]["vertical_thrust"] == 1.0 and plan["settings"]["commanded_takeoff"] == 1.0
    assert_run_as_planned(result, plan)


def test_a_random_target_of_the_man_onto_a_box_is_flown_by_his_far_long_row():
    """His long_onto_region: onto a 0.25-0.35 m box (higher: 5 of 7) where the same lift-off on flat ground lands 1.6-1.9 m ahead (the far
    long row's region, flat_target_x: nearer, the row's landings missed) in 0.55-0.65 s, asked in 0.44-0.7 s (shorter: its
    aims missed, target_air_time); the first such draw of the
    report's box targets planned with the long row and run as a user's request; a target just outside refused in one
    line naming the limit."""
    from sim_core.skills.jump_to_target.commanded import commanded_way
    assert commanded_way("man", (1.3, 0.0, 0.34), 0.48) == "long_onto"           # T0 0.62 s, flat landing 1.69 m
    assert commanded_way("man", (1.25, 0.0, 0.255), 0.481) is None               # flat landing 1.53 m: short of 1.6 m
    assert commanded_way("man", (1.2, 0.0, 0.44), 0.42) is None                  # above 0.4 m: 10 of 13 landed
    assert commanded_way("man", (1.37, 0.0, 0.37), 0.5) is None                  # above 0.35 m: 5 of 7
    assert commanded_way("man", (1.29, 0.0, 0.38), 0.42) is None                 # air time below 0.44 s: its aims missed
    text = region_refusal("man", (1.25, 0.0, 0.255), 0.481)
    assert text and "\n" not in text and "onto a box 0.25-0.35 m high at target_x 0.85-1.9 m in air_time 0.44-0.7 s where the same " \
        "lift-off on flat ground would land in the long air times' region at 1.6-1.9 m in 0.55-0.65 s" in text
    box = first_commanded_box_draw("man", "long_onto", count=400)      # the draws moved with the rows onto higher boxes
    result, plan = planned_and_run(box)
    assert plan["settings"]["vertical_thrust"] == 1.0 and plan["settings"]["lean_push"] == 3.0
    assert_run_as_planned(result, plan)


MAN_ONTO_ROWS = ("near_long_onto", "near_deep_long_onto", "deep_long_onto", "mid_deep_long_onto")


def test_the_man_onto_a_box_by_his_near_and_deep_rows_and_beyond_them_refused():
    """His `<row>_onto_region`s for his near, near deep, deep and mid deep long rows (0.25-0.5 m boxes): each a target's
    way by its flat equivalent, with the row's `<row>_onto_settings` over the row (the arms held back in the crouch: in
    the deep crouches the hands touched the box; the near rows also tucked, the thrust's COM behind the feet); a target
    outside refused in one line naming the rows (no simulation)."""
    from sim_core.skills.jump_to_target.commanded import commanded_way, table, way_body
    assert commanded_way("man", (0.85, 0.0, 0.35), 0.5) == "near_long_onto"       # T0 0.64 s, flat landing 1.09 m
    assert commanded_way("man", (0.85, 0.0, 0.4), 0.5) == "near_deep_long_onto"   # T0 0.66 s, flat landing 1.12 m
    assert commanded_way("man", (1.0, 0.0, 0.45), 0.52) == "mid_deep_long_onto"   # T0 0.70 s, flat landing 1.34 m
    assert commanded_way("man", (1.25, 0.0, 0.4), 0.52) == "deep_long_onto"       # T0 0.68 s, flat landing 1.64 m
    assert commanded_way("man", (0.72, 0.0, 0.35), 0.5) == "near_long_high_onto"  # nearer than 0.78 m: the 0.6 m crouch's
    assert commanded_way("man", (0.6, 0.0, 0.35), 0.5) is None                    # nearer than 0.65 m: the thighs on the box
    assert commanded_way("man", (1.0, 0.0, 0.45), 0.46) is None                   # asked in under 0.48 s: flown long
    assert commanded_way("man", (1.0, 0.0, 0.55), 0.52) == "mid_deep_long_high_onto"   # higher, T0 0.74 s: the higher lift-off's
    body = table("man")
    for way in MAN_ONTO_ROWS:
        assert way_body(body, way)["settings"]["crouch_arms"] == -0.8
    assert way_body(body, "near_long_onto")["settings"]["lean_push"] == body["near_long_settings"]["lean_push"]
    text = region_refusal("man", (0.6, 0.0, 0.35), 0.5)
    assert text and "\n" not in text and ("onto a box 0.25-0.5 m high at target_x 0.78-1.3 m where the same lift-off on "
                                           "flat ground would land in the near long row's region in 0.52-0.65 s") in text
    assert "onto a box 0.25-0.5 m high in air_time 0.48-0.7 s where the same lift-off on flat ground would land in the " \
        "deep long row's region in 0.635-0.69 s" in text


@pytest.mark.slow
@pytest.mark.parametrize("way", MAN_ONTO_ROWS)
def test_a_random_target_of_the_man_onto_a_box_by_his_near_and_deep_rows_lands_as_planned(way):
    """The first of the report's box draws (seed SEED) in each of those rows, planned with that row and its onto settings
    and run as a user's request: within the tolerances, balanced, as its plan's trial landed."""
    box = first_commanded_box_draw("man", way, count=400)
    result, plan = planned_and_run(box)
    assert plan["settings"]["commanded_takeoff"] == 1.0 and plan["settings"]["crouch_arms"] == -0.8
    assert_run_as_planned(result, plan)


MAN_HIGH_ONTO_ROWS = ("near_deep_long_high_onto", "mid_deep_long_high_onto", "deep_long_high_onto")


def test_the_man_onto_higher_boxes_by_his_deep_rows_with_a_higher_lift_off_and_beyond_them_refused():
    """His `<row>_high_onto_region`s (issue 29): onto a 0.25-0.75 m box whose lift-off flies T0 0.7-0.84 s on flat ground,
    beyond his rows' deepest crouch (0.7 s), the flat equivalent's landing in the near deep, mid deep or deep row's region;
    flown by that row at its 0.5 m crouch with the thrust's damping lowered by the air time (the crouch pairs'
    ``thrust_damping`` column) and the arms' swing smaller (their hands touched a high box's edge); within the take-off
    alone; a target outside refused in one line naming them (no simulation)."""
    from sim_core.skills.jump_to_target.commanded import commanded_settings, commanded_way, table, way_body
    from sim_core.skills.jump_to_target.region import takeoff_refusal
    assert commanded_way("man", (0.9, 0.0, 0.35), 0.65) == "near_deep_long_high_onto"   # T0 0.76 s, flat landing 1.05 m
    assert commanded_way("man", (1.0, 0.0, 0.55), 0.5) == "mid_deep_long_high_onto"     # T0 0.72 s, flat landing 1.45 m
    assert commanded_way("man", (1.3, 0.0, 0.4), 0.6) == "deep_long_high_onto"          # T0 0.74 s, flat landing 1.6 m
    assert commanded_way("man", (0.85, 0.0, 0.4), 0.5) == "near_deep_long_onto"        # T0 0.66 s: the row as it was
    assert commanded_way("man", (0.85, 0.0, 0.64), 0.5) is None      # flat landing 1.24 m, nearer than 0.95 m: fell or missed
    assert commanded_way("man", (0.88, 0.0, 0.6), 0.41) is None      # flat landing 1.52 m, nearer than 0.95 m: flown long
    assert commanded_way("man", (1.6, 0.0, 0.3), 0.6) is None        # T0 0.70 s, flat landing 1.87 m: beyond the deep row
    assert commanded_way("man", (0.9, 0.0, 0.7), 0.7) is None        # T0 0.90 s: beyond the lowest damping's flight
    body = table("man")
    for way in MAN_HIGH_ONTO_ROWS:
        row = way_body(body, way)
        assert row["settings"]["crouch_arms"] == -0.8 and row["settings"]["arm_swing"] == 1.0
        low, high = (commanded_settings(row, t, 1.0) for t in (0.7, 0.84))
        assert low["crouch_height"] == high["crouch_height"] == 0.5
        assert low["thrust_damping"] == pytest.approx(body["settings"]["thrust_damping"], abs=0.01)   # the row's own
        assert high["thrust_damping"] < low["thrust_damping"] - 0.2
    assert way_body(body, "near_deep_long_onto")["settings"]["thrust_damping"] == body["settings"]["thrust_damping"]
    assert takeoff_refusal("man", (1.4, 0.0, 0.5), 0.5) is not None             # beyond his take-off: not offered
    assert not in_region("man", (1.4, 0.0, 0.5), 0.5)
    text = region_refusal("man", (0.85, 0.0, 0.64), 0.5)
    assert text and "\n" not in text and ("onto a box 0.25-0.75 m high at target_x 0.95-1.45 m where the same lift-off on "
                                           "flat ground would land in the mid deep long row's target_x 1.15-1.45 m (a "
                                           "higher lift-off) in 0.7-0.84 s") in text


@pytest.mark.slow
@pytest.mark.parametrize("character, way", [*(("man", way) for way in MAN_HIGH_ONTO_ROWS), ("man", "near_long_high_onto"),
                                            ("woman", "long_high_onto"), ("woman", "tucked_high_onto"),
                                            ("woman", "shallow_long_high_onto")])
def test_a_random_target_onto_a_higher_box_lands_as_planned(character, way):
    """The first of the report's box draws (seed SEED) in each row onto higher boxes (the man's deep rows, his near row
    onto near boxes at its 0.6 m crouch, the woman's long row at its deepest crouch, her tucked row onto near boxes at a
    0.55 m crouch), planned with that row - its one
    crouch, its settings (the man's smaller arm swing, his near row's arms back), the thrust's damping lowered by T0 - and
    run as a user's request: within the tolerances, balanced, as its plan's trial landed."""
    from sim_core.skills.jump_to_target.commanded import table, way_body
    row = way_body(table(character), way)
    box = first_commanded_box_draw(character, way, count=400)
    result, plan = planned_and_run(box)
    assert plan["settings"]["commanded_takeoff"] == 1.0
    assert {plan["settings"]["crouch_height"]} == set(row["crouch_by_air_time"]["crouch_height"])
    assert all(plan["settings"].get(k) == row["settings"].get(k) for k in ("arm_swing", "crouch_arms"))
    assert plan["settings"]["thrust_damping"] < table_settings_damping(character)
    assert_run_as_planned(result, plan)


def test_the_man_onto_near_boxes_by_his_near_row_at_a_shallower_crouch_and_beyond_it_refused():
    """His `near_long_high_onto_region` (issue 29): onto a 0.25-0.5 m box 0.65-0.78 m ahead (its front edge 0.37-0.5 m
    ahead of the start's feet) whose lift-off flies T0 0.6-0.76 s on flat ground, flown by his near row at a 0.6 m crouch
    (at his rows' 0.5 m the knees and hands met the box's face in the crouch) with the thrust's damping lowered by the
    air time, the arms held back in the crouch and the knees tucked in flight; a target outside refused in one line
    naming it (no simulation)."""
    from sim_core.skills.jump_to_target.commanded import commanded_settings, commanded_way, table, way_body
    assert commanded_way("man", (0.7, 0.0, 0.4), 0.5) == "near_long_high_onto"      # T0 0.66 s, flat landing 0.93 m
    assert in_region("man", (0.7, 0.0, 0.4), 0.5)
    assert commanded_way("man", (0.8, 0.0, 0.4), 0.5) == "near_deep_long_onto"      # from 0.78 m: the rows as they were
    assert commanded_way("man", (0.6, 0.0, 0.35), 0.5) is None       # nearer than 0.65 m: the thighs on the box's face
    assert commanded_way("man", (0.7, 0.0, 0.55), 0.5) is None       # above 0.5 m: fell
    assert commanded_way("man", (0.7, 0.0, 0.3), 0.65) == "near_long_high_onto"     # T0 0.74 s: damping 0.3
    assert commanded_way("man", (0.7, 0.0, 0.3), 0.7) is None        # T0 0.79 s: beyond the 0.6 m crouch's flight
    assert commanded_way("man", (0.75, 0.0, 0.3), 0.42) is None      # T0 0.57 s: below the 0.6 m crouch's flight
    body = table("man")
    row = way_body(body, "near_long_high_onto")
    assert row["settings"]["crouch_arms"] == -0.8 and row["settings"]["landing_tuck_knee_flexion"] == 2.0
    low, high = (commanded_settings(row, t, 0.7) for t in (0.6, 0.76))
    assert low["crouch_height"] == high["crouch_height"] == 0.6
    assert high["thrust_damping"] < low["thrust_damping"] <= body["settings"]["thrust_damping"] + 0.01
    text = region_refusal("man", (0.6, 0.0, 0.35), 0.5)
    assert text and "\n" not in text and ("onto a box 0.25-0.5 m high at target_x 0.65-0.78 m where the same lift-off on "
                                           "flat ground would land in the near long row's target_x 0.5-1.3 m (a higher "
                                           "lift-off) in 0.6-0.76 s") in text


def test_the_woman_onto_higher_boxes_by_her_long_row_with_a_higher_lift_off_and_beyond_it_refused():
    """Her `long_high_onto_region` (issue 29): onto a 0.25-0.55 m box at target_x 0.85-1.6 m whose lift-off flies T0
    0.7-0.76 s on flat ground, beyond her long row's onto region (0.66 s), the flat equivalent's landing in her long
    row's region; flown by the long row at its deepest crouch (0.45 m) with the thrust's damping lowered by the air time
    (the crouch pairs' ``thrust_damping`` column); within her take-off alone; a target outside refused in one line
    naming it (no simulation)."""
    from sim_core.skills.jump_to_target.commanded import commanded_settings, commanded_way, table, way_body
    from sim_core.skills.jump_to_target.region import takeoff_refusal
    assert commanded_way("woman", (1.1, 0.0, 0.4), 0.6) == "long_high_onto"     # T0 0.74 s, flat landing 1.35 m
    assert commanded_way("woman", (1.2, 0.0, 0.25), 0.55) == "long_onto"       # T0 0.64 s: the row as it was
    assert commanded_way("woman", (1.0, 0.0, 0.5), 0.6) is None      # T0 0.77 s: flown short (0.71-0.74 s) or fell
    assert commanded_way("woman", (0.85, 0.0, 0.45), 0.6) == "long_high_onto"   # from 0.85 m (was 0.92 m): measured
    assert commanded_way("woman", (0.84, 0.0, 0.45), 0.6) is None    # nearer than 0.85 m at T0 0.75 s: not measured
    assert commanded_way("woman", (0.95, 0.0, 0.56), 0.53) is None   # a 0.56 m box at T0 0.75 s: above 0.55 m short or fell
    assert commanded_way("woman", (1.1, 0.0, 0.3), 0.6) == "long_high_onto"    # T0 0.70 s: the damping 0.79
    assert commanded_way("woman", (1.0, 0.0, 0.41), 0.53) == "shallow_long_high_onto"   # T0 0.69 s: at 0.45 m flown long
    body = table("woman")
    row = way_body(body, "long_high_onto")
    low, high = (commanded_settings(row, t, 1.0) for t in (0.72, 0.76))
    assert low["crouch_height"] == high["crouch_height"] == 0.45                  # her deepest crouch
    assert high["thrust_damping"] < low["thrust_damping"] < body["settings"]["thrust_damping"]
    assert way_body(body, "long_onto")["settings"]["thrust_damping"] == body["settings"]["thrust_damping"]
    assert takeoff_refusal("woman", (1.4, 0.0, 0.5), 0.55) is not None          # beyond her take-off: not offered
    assert not in_region("woman", (1.4, 0.0, 0.5), 0.55)
    assert commanded_way("woman", (1.0, 0.0, 0.53), 0.53) == "long_high_onto"   # a 0.53 m box at T0 0.73 s
    text = region_refusal("woman", (1.0, 0.0, 0.5), 0.6)
    assert text and "\n" not in text and ("onto a box 0.25-0.55 m high at target_x 0.85-1.6 m where the same lift-off on "
                                           "flat ground would land in the long row's target_x 0.5-1.6 m (a higher "
                                           "lift-off) in 0.7-0.76 s") in text


def test_the_woman_onto_boxes_between_her_long_rows_by_a_shallower_crouch_and_beyond_it_refused():
    """Her `shallow_long_high_onto_region` (issue 29): onto a 0.25-0.55 m box at target_x 0.85-1.6 m whose lift-off flies
    T0 0.67-0.7 s on flat ground, between her long row's onto region (0.66 s) and its higher lift-off (0.7 s), the flat
    equivalent's landing in her long row's region; flown by the long row at a 0.5 m crouch with her damping (at her
    deepest 0.45 m crouch these flew 0.06-0.1 s long whatever the damping); a target outside refused in one line naming
    it (no simulation)."""
    from sim_core.skills.jump_to_target.commanded import commanded_settings, commanded_way, table, way_body
    from sim_core.skills.jump_to_target.region import takeoff_refusal
    assert commanded_way("woman", (1.1, 0.0, 0.35), 0.56) == "shallow_long_high_onto"   # T0 0.68 s, flat landing 1.34 m
    assert in_region("woman", (1.1, 0.0, 0.35), 0.56)
    assert commanded_way("woman", (1.1, 0.0, 0.3), 0.6) == "long_high_onto"    # T0 0.70 s: the deepest crouch as it was
    assert commanded_way("woman", (1.2, 0.0, 0.25), 0.55) == "long_onto"       # T0 0.64 s: the row as it was
    assert commanded_way("woman", (1.3, 0.0, 0.3), 0.56) is None      # T0 0.669 s: below 0.67 s flown long
    assert commanded_way("woman", (0.95, 0.0, 0.56), 0.42) is None    # a 0.56 m box at T0 0.69 s: above 0.55 m
    assert commanded_way("woman", (0.93, 0.0, 0.54), 0.44) == "shallow_long_high_onto"    # a 0.54 m box at T0 0.69 s
    assert commanded_way("woman", (0.88, 0.0, 0.4), 0.52) == "shallow_long_high_onto"     # from 0.85 m, T0 0.68 s
    assert commanded_way("woman", (0.83, 0.0, 0.4), 0.52) == "tucked_onto"   # nearer than 0.85 m: the tucked row's
    body = table("woman")
    row = way_body(body, "shallow_long_high_onto")
    assert row["settings"]["vertical_thrust"] == 1.0 and "crouch_arms" not in row["settings"]   # the long row's
    low, high = (commanded_settings(row, t, 1.0) for t in (0.67, 0.7))
    assert low["crouch_height"] == high["crouch_height"] == 0.5                   # shallower than her deepest 0.45 m
    assert low["thrust_damping"] == high["thrust_damping"] == 0.79
    assert takeoff_refusal("woman", (1.5, 0.0, 0.55), 0.47) is not None          # beyond her take-off: not offered
    assert not in_region("woman", (1.5, 0.0, 0.55), 0.47)
    text = region_refusal("woman", (1.3, 0.0, 0.3), 0.56)
    assert text and "\n" not in text and ("onto a box 0.25-0.55 m high at target_x 0.85-1.6 m where the same lift-off on "
                                           "flat ground would land in the long row's target_x 0.5-1.6 m (a higher "
                                           "lift-off) in 0.67-0.7 s") in text


def test_the_woman_onto_near_boxes_by_her_tucked_row_at_a_shallower_crouch_and_beyond_it_refused():
    """Her `tucked_high_onto_region` (issue 29): onto a 0.25-0.5 m box 0.65-0.77 m ahead at a forward speed of 0.9-1.3
    m/s whose lift-off flies T0 0.7-0.76 s on flat ground, beyond her tucked row's onto region (0.7 s), flown by the
    tucked row (the arms back in the crouch, the knees tucked in flight) at a 0.55 m crouch with the thrust's damping
    lowered by the air time (at her deepest 0.45 m crouch the near boxes' landings fell short); a target outside
    refused in one line naming it (no simulation)."""
    from sim_core.skills.jump_to_target.commanded import commanded_settings, commanded_way, table, way_body
    assert commanded_way("woman", (0.7, 0.0, 0.4), 0.6) == "tucked_high_onto"    # T0 0.74 s, 1.17 m/s
    assert in_region("woman", (0.7, 0.0, 0.4), 0.6)
    assert commanded_way("woman", (0.7, 0.0, 0.4), 0.5) == "tucked_onto"         # T0 0.66 s: the row as it was
    assert commanded_way("woman", (0.8, 0.0, 0.4), 0.62) is None      # 0.8 m at T0 0.75 s: flown ~0.1 s short
    assert commanded_way("woman", (0.85, 0.0, 0.4), 0.62) == "long_high_onto"    # 0.85 m: her long row's (from 0.85 m)
    assert commanded_way("woman", (0.7, 0.0, 0.35), 0.68) is None     # T0 0.79 s: flown short or fell
    assert commanded_way("woman", (0.7, 0.0, 0.55), 0.55) is None     # a 0.55 m box: the head on its edge in the lean
    assert commanded_way("woman", (0.6, 0.0, 0.4), 0.6) is None       # nearer than 0.65 m: landed 6-14 cm off
    assert commanded_way("woman", (0.75, 0.0, 0.45), 0.55) is None    # 1.36 m/s: faster than 1.3 m/s flown short
    body = table("woman")
    row = way_body(body, "tucked_high_onto")
    assert row["settings"]["crouch_arms"] == -0.8 and row["settings"]["landing_tuck_knee_flexion"] == 2.0
    assert row["settings"]["vertical_thrust"] == 1.0                              # the long row's
    low, high = (commanded_settings(row, t, 0.7) for t in (0.7, 0.76))
    assert low["crouch_height"] == high["crouch_height"] == 0.55
    assert high["thrust_damping"] < low["thrust_damping"] < body["settings"]["thrust_damping"]
    text = region_refusal("woman", (0.7, 0.0, 0.55), 0.55)
    assert text and "\n" not in text and ("onto a box 0.25-0.5 m high at target_x 0.65-0.77 m at a forward speed of "
                                           "0.9-1.3 m/s (target_x / air_time) where the same lift-off on flat ground "
                                           "would land in the long row's target_x 0.5-1.6 m (a higher lift-off) in "
                                           "0.7-0.76 s") in text


def table_settings_damping(character):
    from sim_core.skills.jump_to_target.commanded import table
    return table(character)["settings"]["thrust_damping"]


def test_a_random_target_of_the_woman_onto_a_near_box_is_flown_by_the_long_row_tucked():
    """Her tucked_onto_region: onto a 0.25-0.5 m box 0.55-0.85 m ahead (its front edge 0.25-0.55 m ahead of the start's
    feet), flown by the long row with the arms held back in the crouch (the hands touched a near box before lift-off)
    and the knees tucked from lift-off for half the air time (the toes caught the box's front edge on the way up);
    the first such draw of the report's box targets planned so and run as a user's request."""
    from sim_core.skills.jump_to_target.commanded import commanded_way
    assert commanded_way("woman", (0.62, 0.0, 0.34), 0.45) == "tucked_onto"      # T0 0.60 s
    assert commanded_way("woman", (0.5, 0.0, 0.34), 0.45) is None                # nearer than measured
    assert commanded_way("woman", (0.7, 0.0, 0.55), 0.45) is None                # higher than measured
    assert commanded_way("man", (0.7, 0.0, 0.35), 0.5) == "near_long_high_onto"  # his near row at a shallower crouch
    assert commanded_way("man", (0.6, 0.0, 0.35), 0.5) is None                   # his rows fall or miss there
    box = first_commanded_box_draw("woman", "tucked_onto")
    result, plan = planned_and_run(box)
    assert plan["settings"]["vertical_thrust"] == 1.0 and plan["settings"]["crouch_arms"] == -0.8
    assert plan["settings"]["landing_tuck_knee_flexion"] > 1.5 and 0.0 < plan["settings"]["landing_tuck_share"] < 1.0
    assert_run_as_planned(result, plan)


def test_an_onto_box_target_beyond_the_take_off_is_refused_naming_the_lift_off_speeds(monkeypatch):
    """A target onto a box needs a lift-off at h / T + g T / 2 up with x / T forward (the flat equivalent's); one
    beyond every lift-off the character was measured to fly (region.lift_envelope: its measured balanced jumps, its
    commanded rows' regions, its highest vertical leap) is refused before simulating in one line naming the speeds;
    nothing offered is beyond it."""
    import numpy as np
    import sim_core.simulate as simulate
    from sim_core.random_requests import box_target_draw
    from sim_core.skills.jump_to_target.region import lift_envelope, lift_off, takeoff_capacity, takeoff_refusal
    monkeypatch.setattr(simulate, "Recorder", None)         # a run that started would fail differently
    params = {"target_x": 1.0, "target_y": 0.0, "target_z": 0.7, "air_time": 0.6, "plan_trials": 24}
    with pytest.raises(ParameterError) as refused:
        run(RunRequest("jump_to_target", "man", params=params))
    text = str(refused.value)
    assert "\n" not in text and "beyond the man's take-off" in text and "4.11 m/s up with 1.67 m/s forward" in text
    assert "the most the man's measured take-offs reach at that forward speed is" in text
    assert region_refusal("man", (1.0, 0.0, 0.7), 0.6) == text
    assert lift_off((1.0, 0.0, 0.7), 0.6) == pytest.approx((1.0 / 0.6, 0.7 / 0.6 + 9.80665 * 0.3))
    for character in ("man", "woman"):
        envelope = lift_envelope(character)
        assert envelope[0, 0] == 0.0 and envelope[0, 1] == pytest.approx(takeoff_capacity(character, "vertical"))
        rng = np.random.default_rng(SEED)
        for _ in range(400):
            x, z, t = box_target_draw(rng, character)
            if in_region(character, (x, 0.0, z), t):
                assert takeoff_refusal(character, (x, 0.0, z), t) is None, (x, z, t)


TURNED_TARGETS = 3          # random targets in a character's turned commanded region, outside its measured jumps' region


@pytest.mark.parametrize("character", ["man", "woman"])
def test_random_lateral_targets_turn_first_and_land_balanced(character, tmp_path):
    """A target to the side in the turned commanded region: planned by planning/commanded.py's plan_turned
    (one hop turns the body toward it, then the commanded take-off forward), then run as a user's request."""
    from sim_core.skills.jump_to_target.commanded import commanded_way
    draws = draw_requests(SEED, [character], 0, 0, 0, 0, 0, TURNED_TARGETS)
    assert [d.character for d in draws] == [character] * TURNED_TARGETS
    assert all(commanded_way(character, d.values[:2], d.values[2]) == "turned" for d in draws)
    results, lines, plans, c = all_planned_and_run(character, draws, tmp_path)
    assert len(plans) == TURNED_TARGETS and all(p["settings"]["turn_angle"] != 0.0 for p in plans)
    assert all(p["trials"] <= c.turn_aim_trials + c.landing_trials - 1 + len(c.landing_leads) + c.landing_aims for p in plans)
    assert sum(r["passed"] for r in results) >= TURNED_TARGETS - 1, "\n".join(lines)
    assert max(r["seconds"] for r in results) <= 60, "\n".join(lines)


@pytest.mark.parametrize("character", ["man", "woman"])
def test_turn_headings_replay(character):
    """A character's measured turn map (turn_headings, planning/turn_map.py): a stored turn_angle's hop reaches
    its stored heading again (the same simulation), and turn_for_heading picks the stored angle nearest a heading."""
    import random
    from sim_core.planning.turn_map import hop_heading
    from sim_core.skills.jump_to_target.commanded import table, turn_for_heading
    pairs = table(character)["turn_headings"]
    k = random.Random(SEED).randrange(len(pairs["turn_angle"]))           # one seeded row
    heading, lowest, began = hop_heading(character, pairs["turn_angle"][k])
    assert began and abs(heading - pairs["heading"][k]) < 1e-4
    assert turn_for_heading(table(character), pairs["heading"][k] + 1e-6) == pairs["turn_angle"][k]


def test_turn_lines_replay():
    """The woman's turned hop chosen by the line of the jump after it (turn_lines, planning/turn_map.py hop_line): a
    seeded stored row's hop and two jumps are replayed (the same simulation), and turn_for_point picks that hop for a
    point on its line ahead of the feet."""
    import math
    import random
    from sim_core.planning.turn_map import hop_line
    from sim_core.skills.jump_to_target.commanded import table, turn_for_point
    body = table("woman")
    rows = body["turn_lines"]
    k = random.Random(SEED).choice([i for i, stood in enumerate(rows["stood"]) if stood > 0.5])     # one seeded row
    row = hop_line("woman", rows["turn_angle"][k])
    assert all(abs(row[name] - rows[name][k]) < 1e-4 for name in ("heading", "feet_x", "feet_y", "line", "stood"))
    ahead = (rows["feet_x"][k] + math.cos(rows["line"][k]), rows["feet_y"][k] + math.sin(rows["line"][k]))
    assert turn_for_point(body, ahead, lines="turn_lines") == rows["turn_angle"][k]


def test_turn_for_point_moves_each_flown_hops_line():
    """A hop already flown is judged by where its jump landed (line_offset: its line moved by its error), the others by
    their measured lines moved by the mean error (planning/commanded.py steer_by_lines). No simulation."""
    from sim_core.skills.jump_to_target.commanded import line_offset, table, turn_for_point
    body = table("woman")
    target = (1.214, -0.211)        # seed 29's miss: the hop chosen anew swung between -0.455 and -0.11 rad
    first = turn_for_point(body, target, lines="turn_lines")
    assert turn_for_point(body, target, lines="turn_lines", errors={}, error=0.0) == first
    _, off, _ = line_offset(body, first, target)
    moved = turn_for_point(body, target, lines="turn_lines", errors={first: off - 0.13})    # it landed 13 cm right
    assert moved != first
    assert abs(line_offset(body, moved, target)[1]) < 0.13


def test_the_mans_commanded_table_is_the_womans_scaled_by_fig_6():
    """The man's commanded take-off (tools/scale_commanded.py): his table's settings are the woman's scaled by
    Fig. 6 (adapt/settings.scale_settings, mass mode), his leap constants hers by scale_constants, with his
    thrust's extension slowed (commanded_timing_scale > 1: his torque limits are 1.54 x hers where Fig. 6 scales
    a torque by M L = 2.08; docs/jump_to_target.md, seventeenth session) and his lean's trigger measured on him
    (commanded_lean_push above hers: his slowed push adds more speed per lean; eighteenth session). No simulation."""
    from sim_core.adapt.settings import MASS, CharacterPair, scale_constants, scale_settings
    from sim_core.character.spec import load_character
    from sim_core.control.leap import LEAP_CONSTANTS, LEAP_SETTINGS, leap_constants
    from sim_core.skills.jump_to_target.commanded import table
    pair = CharacterPair(load_character("woman"), load_character("man"))
    scaled = scale_settings(table("woman")["settings"], LEAP_SETTINGS, pair, MASS)
    assert table("man")["settings"] == pytest.approx(scaled, abs=1e-6)
    hers = vars(leap_constants("woman"))
    measured = ("commanded_timing_scale", "commanded_lean_push")     # his own (tools/scale_commanded.py --const)
    constants = scale_constants({n: hers[n] for n in LEAP_CONSTANTS.by_name if n.startswith("commanded_")
                                 and n not in measured}, LEAP_CONSTANTS, pair, MASS)
    his = vars(leap_constants("man"))
    assert {n: his[n] for n in constants} == pytest.approx(constants, abs=1e-6)
    assert his["commanded_timing_scale"] > 1.0 == hers["commanded_timing_scale"]
    assert his["commanded_lean_push"] > hers["commanded_lean_push"]


def test_sideways_targets_turn_a_quarter_first_by_the_measured_line_nearest():
    """Straight to the side (issue 29's left and right jumps) in the woman's sideways_region: planned with the
    quarter turn (turn_first) whose measured jump's line (quarter_lines, planning/turn_map.py) passes nearest
    the target; a stored row's turn and jump are replayed (the same simulation); a seeded draw is planned and run as a
    user's request; beyond the region not offered."""
    import math
    import random
    from sim_core.planning.turn_map import quarter_line
    from sim_core.skills.jump_to_target.commanded import commanded_way, table, turn_for_point
    body = table("woman")
    region, rows = body["sideways_region"], body["quarter_lines"]
    middle = (0.5 * sum(region["distance"]), 0.5 * sum(region["air_time"]))
    assert commanded_way("woman", (0.0, middle[0]), middle[1]) == commanded_way("woman", (0.0, -middle[0]), middle[1]) \
        == "sideways"
    assert commanded_way("woman", (0.0, region["distance"][1] + 0.05), middle[1]) is None
    assert commanded_way("woman", (0.0, -middle[0]), region["air_time"][1] + 0.05) == "sideways_long_short"   # its long row
    assert "sideways_region" not in table("man")                            # the man's table has no sideways_region:
    assert commanded_way("man", (0.0, middle[0]), middle[1]) == "sideways_near_short"   # his near short row flies it
    k = random.Random(SEED).choice([i for i, stood in enumerate(rows["stood"]) if stood])     # one seeded row
    row = quarter_line("woman", rows["turn_first"][k])
    assert all(abs(row[name] - rows[name][k]) < 1e-4 for name in ("heading", "feet_x", "feet_y", "line", "stood"))
    ahead = (rows["feet_x"][k] + math.cos(rows["line"][k]), rows["feet_y"][k] + math.sin(rows["line"][k]))
    assert turn_for_point(body, ahead) == rows["turn_first"][k]
    draw = first_sideways_draw("sideways")                                    # planned and run as a user's request
    result, plan = planned_and_run(draw)
    assert plan["settings"]["turn_first"] != 0.0 and plan["settings"]["commanded_takeoff"] == 1.0
    assert result["passed"], result_line(result)


def first_sideways_draw(way, count=40, character="woman", side=0.0):
    """The first of the report's sideways draws of ``character`` (seed SEED, the first ``count``) flown ``way`` (``side``
    +1 / -1: the first to the left / right)."""
    from sim_core.skills.jump_to_target.commanded import commanded_way
    return next(d for d in draw_requests(SEED, [character], 0, 0, 0, sideways=count)
                if commanded_way(character, d.values[:2], d.values[2]) == way and d.values[1] * side >= 0.0)


@pytest.mark.slow
def test_sideways_targets_at_longer_air_times_turn_a_quarter_then_fly_the_long_row():
    """Straight to the side 1.0-1.6 m at 0.55-0.7 s (the woman's sideways_long_region): planned with the quarter turn
    (turn_first) steered by its lines as flown, then the long row (the vertical thrust: way_body "sideways_long" reads
    the table as "turned_long" does); a seeded draw planned and run as a user's request; the man flies his mid long row
    there, not it; the woman beyond its bounds is refused in one line naming the region."""
    from sim_core.skills.jump_to_target.commanded import commanded_way, table, way_body
    body = table("woman")
    region = body["sideways_long_region"]
    assert region["distance"] == [1.0, 1.6] and region["air_time"][1] == 0.7
    assert way_body(body, "sideways_long") == way_body(body, "turned_long")
    assert commanded_way("woman", (0.0, 1.45), 0.6) == commanded_way("woman", (0.0, -1.45), 0.6) == "sideways_long"
    assert commanded_way("woman", (0.0, -1.45), 0.5) == "sideways_long_short"      # below it: the row's shorter air times
    assert commanded_way("woman", (0.0, -1.45), 0.42) is None and commanded_way("woman", (0.0, 1.7), 0.6) is None
    assert commanded_way("man", (0.0, 1.45), 0.6) == "sideways_mid_long"       # the man: his own row, not the long row
    text = region_refusal("woman", (0.0, 1.7), 0.6)
    assert "\n" not in text and "turned a quarter first with long air times for a distance of 1-1.6 m" in text
    draw = first_sideways_draw("sideways_long")
    result, plan = planned_and_run(draw)
    assert plan["settings"]["turn_first"] != 0.0 and plan["settings"]["vertical_thrust"] == 1.0
    assert_run_as_planned(result, plan)


def test_the_mans_sideways_targets_turn_a_quarter_then_fly_one_of_his_long_rows():
    """Straight to the side 1.0-1.2 m at 0.5-0.6 s (the man's sideways_near_long_region): the quarter turn (his own
    quarter_lines), then his near long row (way_body "sideways_near_long": the row "turned_near_long" flies, with
    ``sideways_near_long_settings``, the landing's arms without their pitch feedback, over it); 1.2-1.6 m
    (sideways_mid_long_region): then his mid long row; 1.0-1.5 m at 0.6-0.645 s (sideways_mid_deep_long_region): his mid
    deep long row; 1.5-1.6 m at 0.6-0.68 s (sideways_deep_long_region): his far long row at its deepest crouches (as after
    the hop, deep_long_body turned); beyond their bounds refused in one line naming the region (no simulation)."""
    from sim_core.skills.jump_to_target.commanded import commanded_way, deep_long_body, over, table, way_body
    body = table("man")
    region = body["sideways_near_long_region"]
    assert region["distance"] == [1.0, 1.2] and region["air_time"] == [0.5, 0.6] and len(body["quarter_lines"]["stood"]) > 0
    assert way_body(body, "sideways_near_long") == over(way_body(body, "turned_near_long"), body, "sideways_near_long_settings")
    assert way_body(body, "sideways_near_long")["settings"]["landing_arm_pitch_gain"] == 0.0
    assert commanded_way("man", (0.0, 1.15), 0.55) == commanded_way("man", (0.0, -1.15), 0.55) == "sideways_near_long"
    assert commanded_way("man", (0.0, 1.15), 0.62) == "sideways_mid_deep_long" and commanded_way("man", (0.0, -1.15), 0.45) == "sideways_near_short"
    assert commanded_way("man", (0.0, 1.25), 0.577) == commanded_way("man", (0.0, -1.25), 0.55) == "sideways_mid_long"   # beyond the near row's reach the mid row
    assert body["sideways_mid_long_region"]["distance"] == [1.2, 1.6] and body["sideways_mid_long_region"]["air_time"] == [0.5, 0.6]
    assert way_body(body, "sideways_mid_long") == way_body(body, "turned_mid_long")
    assert commanded_way("man", (0.0, 1.45), 0.55) == commanded_way("man", (0.0, -1.45), 0.55) == "sideways_mid_long"
    assert commanded_way("man", (0.0, 1.45), 0.63) == commanded_way("man", (0.0, -1.45), 0.63) == "sideways_mid_deep_long"
    assert way_body(body, "sideways_mid_deep_long") == over(way_body(body, "turned_mid_deep_long"), body,
                                                            "sideways_mid_deep_long_settings")
    assert commanded_way("man", (0.0, 1.15), 0.63) == commanded_way("man", (0.0, -1.05), 0.61) == "sideways_mid_deep_long"
    assert body["sideways_mid_deep_long_region"]["distance"] == [1.0, 1.5]
    assert body["sideways_mid_deep_long_region"]["air_time"] == [0.6, 0.645]
    deep = body["sideways_deep_long_region"]
    assert deep["distance"] == [1.5, 1.6] and deep["air_time"] == [0.6, 0.68] and "side" not in deep
    assert way_body(body, "sideways_deep_long") == way_body(body, "turned_deep_long") == deep_long_body(body, turned=True)
    assert way_body(body, "sideways_deep_long")["crouch_by_air_time"] == body["deep_long_crouch_by_air_time"]
    assert commanded_way("man", (0.0, 1.55), 0.63) == commanded_way("man", (0.0, -1.55), 0.67) == "sideways_deep_long"
    assert commanded_way("man", (0.0, 1.55), 0.69) is None and commanded_way("man", (0.0, -1.65), 0.55) is None
    assert commanded_way("man", (0.0, 1.15), 0.66) is None and commanded_way("man", (0.0, 1.45), 0.67) is None
    text = region_refusal("man", (0.0, 1.15), 0.69)
    assert "\n" not in text and "turned a quarter first with long air times nearer for a distance of 1-1.2 m" in text
    assert "turned a quarter first with long air times in the middle for a distance of 1.2-1.6 m" in text
    assert "turned a quarter first with the longest air times in the middle for a distance of 1-1.5 m" in text
    assert ("turned a quarter first with the longest air times for a distance of 1.5-1.6 m at a bearing of 87-90 deg to "
            "either side, air_time 0.6-0.68 s") in text


@pytest.mark.slow
@pytest.mark.parametrize("way, push, nearer", (("sideways_near_long", 10.0, 1.6), ("sideways_mid_long", 5.0, 1.3),
                                               ("sideways_mid_deep_long", 4.0, 1.6), ("sideways_mid_deep_long", 4.0, 1.3),
                                               ("sideways_deep_long", 3.0, 1.6)))
def test_a_seeded_sideways_draw_of_the_man_is_flown_by_the_quarter_turn_and_his_long_row(way, push, nearer):
    """The first of the report's sideways draws of the man (seed SEED) in each of his sideways rows nearer than ``nearer`` m
    (the mid long row's from 1.2 m and the mid deep long row's from 1.0 m: 1.3 m) planned and run as a user's request:
    the quarter turn, then the near / mid / mid deep / far long row (the vertical thrust, its lean push), landing within
    the tolerances and balanced where its plan's trial did."""
    from sim_core.skills.jump_to_target.commanded import commanded_way
    draw = next(d for d in draw_requests(SEED, ["man"], 0, 0, 0, sideways=80)
                if commanded_way("man", d.values[:2], d.values[2]) == way and abs(d.values[1]) < nearer)
    result, plan = planned_and_run(draw)
    assert plan["settings"]["turn_first"] != 0.0 and plan["settings"]["vertical_thrust"] == 1.0
    assert plan["settings"]["lean_push"] == push and plan["settings"]["landing_arm_pitch_gain"] == 0.0
    assert_run_as_planned(result, plan)


def test_the_mans_sideways_targets_at_short_air_times_turn_a_quarter_then_fly_his_short_rows():
    """Straight to the side 1.0-1.36 m at 0.4-0.5 s (the man's sideways_near_short_region): the quarter turn, then his
    near long row at its shallowest crouches (way_body "sideways_near_short" reads the table as "turned_near_short" does:
    short_body, the near short row's crouch pairs); 1.36-1.6 m (sideways_far_short_region, where the near short row
    landed 8-13 cm short): then his far long row at its shallowest crouches ("turned_far_short"), either side since it
    steers by its own quarter map (sideways_far_short_lines; by quarter_lines its left draws 21 / 25); beyond
    their bounds refused in one line naming the regions (no simulation)."""
    from sim_core.skills.jump_to_target.commanded import commanded_way, short_body, table, way_body
    body = table("man")
    near, far = body["sideways_near_short_region"], body["sideways_far_short_region"]
    assert near["distance"] == [1.0, 1.36] and near["air_time"] == [0.4, 0.5] and "side" not in near
    assert far["distance"] == [1.36, 1.6] and far["air_time"] == [0.4, 0.5] and "side" not in far
    for row in ("near_short", "far_short"):
        assert way_body(body, f"sideways_{row}") == way_body(body, f"turned_{row}") == short_body(body, row)
        assert way_body(body, f"sideways_{row}")["crouch_by_air_time"] == body[f"{row}_crouch_by_air_time"]
    assert commanded_way("man", (0.0, 1.2), 0.45) == commanded_way("man", (0.0, -1.2), 0.45) == "sideways_near_short"
    assert commanded_way("man", (0.0, 1.0), 0.4) == commanded_way("man", (0.0, -1.35), 0.49) == "sideways_near_short"
    assert commanded_way("man", (0.0, -1.5), 0.45) == commanded_way("man", (0.0, 1.5), 0.45) == "sideways_far_short"
    assert commanded_way("man", (0.0, -1.6), 0.4) == commanded_way("man", (0.0, -1.37), 0.49) == "sideways_far_short"
    assert commanded_way("man", (0.0, 1.2), 0.55) == "sideways_near_long"      # from 0.5 s his long rows as before
    assert commanded_way("man", (0.0, -1.5), 0.55) == "sideways_mid_long"
    assert commanded_way("man", (0.0, 1.65), 0.45) is None and commanded_way("man", (0.0, -1.2), 0.39) is None
    assert commanded_way("man", (0.0, 0.95), 0.45) is None
    text = region_refusal("man", (0.0, 1.65), 0.45)
    assert "\n" not in text and ("turned a quarter first with short air times nearer for a distance of 1-1.36 m at a "
                                 "bearing of 87-90 deg to either side, air_time 0.4-0.5 s") in text
    assert ("turned a quarter first with short air times far ahead for a distance of 1.36-1.6 m at a bearing of 87-90 deg "
            "to either side, air_time 0.4-0.5 s") in text


@pytest.mark.slow
@pytest.mark.parametrize("way, push, side", (("sideways_near_short", 10.0, 0.0), ("sideways_far_short", 3.0, -1.0)))
def test_a_seeded_sideways_draw_of_the_man_at_short_air_times_is_flown_by_the_quarter_turn_and_a_short_row(way, push,
                                                                                                           side):
    """The first of the report's sideways draws of the man (seed SEED) in each of his short sideways rows planned and
    run as a user's request (the far row's first to the right; its first to the left: the test below): the quarter turn,
    then the near / far long row (the vertical thrust, its lean push) at its shallowest crouches, landing within the
    tolerances and balanced where its plan's trial did."""
    draw = first_sideways_draw(way, character="man", side=side)
    result, plan = planned_and_run(draw)
    assert plan["settings"]["turn_first"] != 0.0 and plan["settings"]["vertical_thrust"] == 1.0
    assert plan["settings"]["lean_push"] == push and plan["settings"]["crouch_height"] >= 0.62
    assert_run_as_planned(result, plan)


def a_seeded_row_of_its_own_quarter_map_replayed(character: str, way: str) -> None:
    """One seeded row of the sideways row ``way``'s own quarter map (``<way>_lines``) that stood, measured again by
    turn_map.quarter_line with that row's jump (the same simulation, the same numbers), and its line steering to its
    own turn (turn_for_point over that map)."""
    import random
    from sim_core.planning.turn_map import quarter_line
    from sim_core.skills.jump_to_target.commanded import table, turn_for_point
    body = table(character)
    rows = body[f"{way}_lines"]
    k = random.Random(SEED).choice([i for i, stood in enumerate(rows["stood"]) if stood])     # one seeded row
    row = quarter_line(character, rows["turn_first"][k], way)
    assert all(abs(row[name] - rows[name][k]) < 1e-4 for name in ("heading", "feet_x", "feet_y", "line", "stood"))
    ahead = (rows["feet_x"][k] + math.cos(rows["line"][k]), rows["feet_y"][k] + math.sin(rows["line"][k]))
    assert turn_for_point(body, ahead, lines=f"{way}_lines") == rows["turn_first"][k]


def test_the_long_row_at_shorter_air_times_steers_by_its_own_quarter_map():
    """The woman's sideways_long_short_lines: each quarter turn of quarter_lines measured with the long row's own jump at
    shorter air times after it (planning/turn_map.py quarter_line's ``way``; with the short row's jump some turns stood
    whose long row's landing fell at every placement, docs/jump_to_target.md, "Her right jumps at shorter air times"); the
    row steers by them (quarter_lines_of), every other sideways row by quarter_lines; a seeded stored row replayed (the
    same simulation)."""
    from sim_core.skills.jump_to_target.commanded import quarter_lines_of, table
    body = table("woman")
    rows = body["sideways_long_short_lines"]
    assert rows["turn_first"] == body["quarter_lines"]["turn_first"]
    assert quarter_lines_of(body, "sideways_long_short") == "sideways_long_short_lines"
    assert quarter_lines_of(body, "sideways_long") == quarter_lines_of(body, "sideways") == "quarter_lines"
    assert quarter_lines_of(table("man"), "sideways_near_short") == "quarter_lines"
    for side in (-1.0, 1.0):        # turns to either side stood with the row after them
        assert sum(stood for turn, stood in zip(rows["turn_first"], rows["stood"]) if turn * side > 0.0) >= 20
    a_seeded_row_of_its_own_quarter_map_replayed("woman", "sideways_long_short")


def test_the_mans_far_short_row_steers_by_its_own_quarter_map():
    """The man's sideways_far_short_lines: each quarter turn of his quarter_lines measured with the far short row's own
    jump after it (1.48 m in 0.45 s, SIDE_JUMPS; with the short row's jump other turns stood: of his left turns 18 stood
    with it, 12 with this jump, 4 of them the same, docs/jump_to_target.md, "His left jumps at short air times far
    ahead"); only this row of his steers by them; a seeded stored row replayed (the same simulation)."""
    from sim_core.skills.jump_to_target.commanded import quarter_lines_of, table
    body = table("man")
    rows = body["sideways_far_short_lines"]
    assert rows["turn_first"] == body["quarter_lines"]["turn_first"]
    assert quarter_lines_of(body, "sideways_far_short") == "sideways_far_short_lines"
    assert all(quarter_lines_of(body, f"sideways_{row}") == "quarter_lines"
               for row in ("near_short", "near_long", "mid_long", "mid_deep_long", "deep_long"))
    for side in (-1.0, 1.0):        # turns to either side stood with the row after them
        assert sum(stood for turn, stood in zip(rows["turn_first"], rows["stood"]) if turn * side > 0.0) >= 10
    a_seeded_row_of_its_own_quarter_map_replayed("man", "sideways_far_short")


@pytest.mark.slow
def test_a_left_jump_of_the_man_at_short_air_times_far_ahead_is_flown_by_the_far_short_row():
    """The report's first sideways draw of the man to the left in sideways_far_short_region (1.36-1.6 m, 0.4-0.5 s; to the
    right only until it steered by its own quarter map) planned and run as a user's request: the quarter turn to the
    left, then the far long row at its shallowest crouches; a left target just beyond it (1.65 m) refused."""
    from sim_core.skills.jump_to_target.commanded import commanded_way
    assert commanded_way("man", (0.0, 1.65), 0.45) is None and commanded_way("man", (0.0, 1.5), 0.39) is None
    draw = first_sideways_draw("sideways_far_short", character="man", side=1.0)
    assert draw.values[1] > 0.0
    result, plan = planned_and_run(draw)
    assert plan["settings"]["turn_first"] < 0.0 and plan["settings"]["lean_push"] == 3.0   # + turns right
    assert_run_as_planned(result, plan)


@pytest.mark.slow
@pytest.mark.parametrize("side", (1.0, -1.0))
def test_left_and_right_jumps_at_shorter_air_times_turn_a_quarter_then_fly_the_long_row(side):
    """Straight to the left or right 1.0-1.6 m at 0.44-0.55 s (the woman's sideways_long_short_region, either side): the
    quarter turn steered by the row's own quarter map (sideways_long_short_lines), then the long row at its shorter air
    times (way_body "sideways_long_short" reads the table as "turned_long_short" does); beyond it refused in one line
    naming it; the report's first draw to each side planned and run."""
    from sim_core.skills.jump_to_target.commanded import commanded_way, table, way_body
    body = table("woman")
    region = body["sideways_long_short_region"]
    assert "side" not in region and region["air_time"] == [0.44, 0.55] and region["distance"] == [1.0, 1.6]
    assert way_body(body, "sideways_long_short") == way_body(body, "turned_long_short")
    assert commanded_way("woman", (0.0, 1.3), 0.5) == commanded_way("woman", (0.0, -1.3), 0.5) == "sideways_long_short"
    assert commanded_way("woman", (0.0, side * 1.3), 0.43) is None
    text = region_refusal("woman", (0.0, side * 1.3), 0.43)
    assert "\n" not in text and ("turned a quarter first with the long row at shorter air times for a distance of "
                                 "1-1.6 m at a bearing of 87-90 deg to either side, air_time 0.44-0.55 s") in text
    draw = first_sideways_draw("sideways_long_short", side=side)
    assert draw.values[1] * side > 0.0
    result, plan = planned_and_run(draw)
    assert plan["settings"]["turn_first"] * side < 0.0 and plan["settings"]["vertical_thrust"] == 1.0   # + turns right
    assert_run_as_planned(result, plan)


LONG_TARGETS = 3            # random targets in a character's long air times' region, outside its measured jumps' region


@pytest.mark.parametrize("character", ["man", "woman"])
def test_random_long_air_times_are_flown_by_the_vertical_thrust_and_land_balanced(character, tmp_path):
    """Long air times on flat ground (the table's long_region, beyond the broad thrust's deepest crouch): planned
    commanded with the table's long row (the leap's vertical thrust, its own crouch pairs, the landing's recovery
    step; commanded.long_body), then run as a user's request; beyond the region refused naming it."""
    from sim_core.skills.jump_to_target.commanded import commanded_way, table
    from sim_core.skills.jump_to_target.region import mode
    body = table(character)
    region = body["long_region"]
    x, t = 0.5 * sum(region["target_x"]), 0.5 * sum(region["air_time"])
    assert region["air_time"][0] <= 0.55 and region["air_time"][1] >= 0.65 > body["region"]["air_time"][1]
    assert commanded_way(character, (x, 0.0), t) == "long"
    assert commanded_way(character, (x, 0.0), region["air_time"][1] + 0.08) is None      # beyond the man's deep row too
    assert commanded_way(character, (region["target_x"][1] + 0.05, 0.0), t) is None
    assert commanded_way(character, (x, 0.0, -0.3), t) == {"man": "long_down", "woman": None}[character]
    # down from a box: the man's far long row (his long_down_regions, 2.3-3.3 m/s), hers none (its landings fell)
    refusal = region_refusal(character, (x, 0.0), region["air_time"][1] + 0.1)
    assert "\n" not in refusal and (
        f"and for long air times (the leap's vertical thrust) on flat ground for target_x {region['target_x'][0]:g}-"
        f"{region['target_x'][1]:g} m, target_y {region['target_y'][0]:g}-{region['target_y'][1]:g} m, air_time "
        f"{region['air_time'][0]:g}-{region['air_time'][1]:g} s") in refusal
    draws = draw_requests(SEED, [character], 0, 0, 0, long=LONG_TARGETS)
    assert [d.character for d in draws] == [character] * LONG_TARGETS
    assert all(commanded_way(character, d.values[:2], d.values[2]) in ("long", "near_long", "deep_long", "far_short",
                                                                       "near_short", "near_deep_long",
                                                                       "mid_deep_long")   # the man's other rows too
               and mode(character, d.values[:2], d.values[2]) == "commanded" for d in draws)
    results, lines, plans, c = all_planned_and_run(character, draws, tmp_path)
    assert len(plans) == LONG_TARGETS
    assert all(p["settings"]["vertical_thrust"] == 1.0 and p["settings"]["commanded_takeoff"] == 1.0 for p in plans)
    assert all(p["trials"] <= c.aim_trials + c.landing_trials - 1 + len(c.landing_leads) + c.landing_aims for p in plans)
    assert sum(r["passed"] for r in results) >= LONG_TARGETS - 1, "\n".join(lines)
    assert max(r["seconds"] for r in results) <= 60, "\n".join(lines)


@pytest.mark.slow
def test_the_mans_near_long_air_times_are_flown_by_the_near_long_row_and_land_balanced():
    """The man's long air times nearer than his long row (the table's near_long_region: the long row with its own lean
    push, near_long_settings, and crouch pairs; commanded.near_long_body): drawn as the report draws long targets (the
    union of both rows), the first near one planned commanded with the near row and run as a user's request; beyond
    the region refused in one line naming it."""
    from sim_core.skills.jump_to_target.commanded import commanded_way, table
    body = table("man")
    near = body["near_long_region"]
    assert near["target_x"][1] <= body["long_region"]["target_x"][0]
    assert commanded_way("man", (0.9, 0.0), 0.6) == "near_long"
    assert commanded_way("man", (0.9, 0.0), 0.45) == "straight"                      # his commanded row first
    assert commanded_way("man", (1.7, 0.0), 0.6) == "long"
    assert commanded_way("man", (0.9, 0.0), near["air_time"][1] + 0.08) is None     # beyond the deep row too
    assert commanded_way("man", (0.9, 0.0, 0.28), 0.47) == "near_long_onto"     # onto a box by the near row, arms back, tucked
    refusal = region_refusal("man", (0.9, 0.0), near["air_time"][1] + 0.08)
    assert "\n" not in refusal and (
        f"for long air times nearer (the vertical thrust with its own lean push) for target_x {near['target_x'][0]:g}-"
        f"{near['target_x'][1]:g} m, target_y {near['target_y'][0]:g}-{near['target_y'][1]:g} m, air_time "
        f"{near['air_time'][0]:g}-{near['air_time'][1]:g} s") in refusal
    draws = draw_requests(SEED, ["man"], 0, 0, 0, long=6)
    assert {"long", "near_long"} <= {commanded_way("man", d.values[:2], d.values[2]) for d in draws} \
        <= {"long", "near_long", "deep_long", "far_short", "near_short", "near_deep_long",
            "mid_deep_long"}       # his other rows are in the union too
    draw = next(d for d in draws if commanded_way("man", d.values[:2], d.values[2]) == "near_long")
    result, plan = planned_and_run(draw)
    assert plan["settings"]["lean_push"] == body["near_long_settings"]["lean_push"]
    assert plan["settings"]["vertical_thrust"] == 1.0 and plan["settings"]["commanded_takeoff"] == 1.0
    assert result["passed"], result_line(result)


def test_a_jump_that_fell_at_every_placement_is_tried_with_the_feet_led_later_and_only_then():
    """The landing from the arriving state (planning/commanded.py landed_plan): the nearest jump that landed on the
    target and fell is tried with its feet placed a landing step more and less (landing_trials) and, only where every
    placement fell, with its landing_foot_lead_time moved by each of the table's landing_leads in turn
    (docs/jump_to_target.md, "The woman's turned long row from 0.52 s again"). A stand-in trial, no simulation."""
    from sim_core.planning.commanded import landed_plan
    from sim_core.planning.trials import Trials
    from sim_core.skills.jump_to_target.commanded import planner_constants, table
    c = planner_constants("woman")
    assert c.landing_leads and all(lead < 0.0 for lead in c.landing_leads)
    assert planner_constants("man").landing_leads
    lead = table("woman")["settings"]["landing_foot_lead_time"]
    base = {**table("woman")["settings"], "commanded_takeoff": 1.0, "flight_target_x": 1.0, "crouch_height": 0.6}
    judge = lambda m: (True, m["outcome"] == "success")             # every trial on the target; standing is all

    def planned(stands):
        ran = []

        def trial(settings):
            ran.append(settings)
            return 0.01 * len(ran), {"outcome": "success" if stands(settings) else "fell", "landing": (1.0, 0.0),
                                     "air_time": 0.55}
        trials = Trials(trial, 40)
        trials.run(base)
        return landed_plan("woman", (1.0, 0.0), trials, 40, judge, c), ran

    plan, ran = planned(lambda s: s["landing_foot_lead_time"] == lead + c.landing_leads[-1])
    assert plan["found"] and len(ran) == c.landing_trials + len(c.landing_leads)
    assert all(s["landing_foot_lead_time"] == lead for s in ran[:c.landing_trials])        # the placements first
    assert len({s["foot_delta"] for s in ran[:c.landing_trials]}) == c.landing_trials
    assert [s["landing_foot_lead_time"] - lead for s in ran[c.landing_trials:]] == pytest.approx(list(c.landing_leads))
    assert all(s["foot_delta"] == base["foot_delta"] for s in ran[c.landing_trials:])
    plan, ran = planned(lambda s: s["foot_delta"] != base["foot_delta"])    # a placement stands: no lead is tried
    assert plan["found"] and len(ran) == 2 and ran[-1]["landing_foot_lead_time"] == lead
    plan, ran = planned(lambda s: False)                                    # none stands: the placements and leads
    assert not plan["found"] and len(ran) == c.landing_trials + len(c.landing_leads)


def test_a_jump_that_stood_off_the_target_is_flown_again_aimed_by_its_miss():
    """The landing's last step (planning/commanded.py reaim): where no trial landed balanced on the target, the
    balanced one nearest it is flown again with its flight target moved by its miss, forward and to the side, at most
    landing_aims jumps, and only while the last one stood (docs/jump_to_target.md, "Straight to the side with the long
    row"). A stand-in trial whose landing falls short of its flight target by a fixed miss, no simulation."""
    from sim_core.planning.commanded import landed_plan
    from sim_core.planning.trials import Trials
    from sim_core.skills.jump_to_target.commanded import planner_constants, table
    c = planner_constants("woman")
    assert c.landing_aims >= 1 and planner_constants("man").landing_aims >= 1
    target, short = (0.03, -1.3), (0.02, 0.07)          # the trial lands this much behind its flight target
    base = {**table("woman")["settings"], "commanded_takeoff": 1.0, "flight_target_x": target[0],
            "flight_target_y": target[1], "crouch_height": 0.6}
    judge = lambda m: ((on := math.hypot(m["landing"][0] - target[0], m["landing"][1] - target[1]) <= 0.05),
                       on and m["outcome"] == "success")

    def planned(stands):
        ran = []

        def trial(settings):
            ran.append(settings)
            landing = (settings["flight_target_x"] - short[0], settings["flight_target_y"] + short[1])
            return 0.01 * len(ran), {"outcome": "success" if stands(settings) else "fell", "landing": landing,
                                     "air_time": 0.55}
        trials = Trials(trial, 40)
        trials.run(base)
        return landed_plan("woman", target, trials, 40, judge, c), ran

    plan, ran = planned(lambda s: True)
    assert plan["found"] and len(ran) == 2
    assert (ran[1]["flight_target_x"], ran[1]["flight_target_y"]) == pytest.approx(
        (target[0] + short[0], target[1] - short[1]))
    plan, ran = planned(lambda s: s is ran[0])              # the moved jump fell: no more
    assert not plan["found"] and len(ran) == 2
    plan, ran = planned(lambda s: False)                    # nothing stood: nothing to move
    assert not plan["found"] and len(ran) == 1


def test_an_aim_held_at_its_bound_is_not_flown_again():
    """The trials are deterministic, so an aim the planner holds at its bound (aim_range's end: a target beyond what
    the row reaches) is not flown twice (planning/trials.py seen): the aim's step stops and its trials are left to
    the landing (docs/jump_to_target.md: the man's far down targets ran up to four identical jumps at the 2.5 m cap).
    A stand-in trial that lands at a third of its aim, no simulation."""
    from sim_core.planning.commanded import plan_commanded
    from sim_core.skills.jump_to_target.commanded import planner_constants
    c = planner_constants("man")
    ran = []

    def trial(settings):
        ran.append(settings)
        return 1.0, {"outcome": "success", "landing": (settings["flight_target_x"] / 3.0, 0.0), "air_time": 0.45}
    plan = plan_commanded("man", (1.0, 0.0, 0.0, None), 0.45, trial, 40, lambda m: (False, False))
    assert c.aim_trials > 2 and not plan["found"]
    aims = [s["flight_target_x"] for s in ran]
    assert aims[0] == 1.0 and aims[-1] == c.aim_range[1] and aims.count(c.aim_range[1]) == 1 and len(ran) < c.aim_trials
    assert all(a != b for i, a in enumerate(ran) for b in ran[:i])


TURNED_LONG_TARGETS = 3     # random targets in a character's turned long air times' region, outside its measured jumps'


@pytest.mark.slow
@pytest.mark.parametrize("character", ["woman", "man"])
def test_random_lateral_targets_at_long_air_times_turn_first_and_fly_the_long_row(character, tmp_path):
    """A target to the side at a long air time (the table's turned_long_region, and the man's turned_near_long_region):
    planned by plan_turned with the table read by turned_long_body (the hop toward it, then the long row: the leap's
    vertical thrust; nearer, the near long row), run as a user's request; beyond the region refused naming it."""
    from sim_core.skills.jump_to_target.commanded import commanded_way, table
    region = table(character)["turned_long_region"]
    d, b, t = (0.5 * sum(region[k]) for k in ("distance", "bearing", "air_time"))
    assert commanded_way(character, (d * math.cos(b), -d * math.sin(b)), t) == "turned_long"
    assert commanded_way(character, (d * math.cos(b), d * math.sin(b)), region["air_time"][1] + 0.08) is None
    refusal = region_refusal(character, (d * math.cos(b), d * math.sin(b)), region["air_time"][1] + 0.1)
    assert "\n" not in refusal and (
        f"turned first with long air times for a distance of {region['distance'][0]:g}-{region['distance'][1]:g} m") in refusal
    draws = draw_requests(SEED, [character], 0, 0, 0, turned_long=TURNED_LONG_TARGETS)
    assert [d.skill for d in draws] == ["turned_long"] * TURNED_LONG_TARGETS
    assert all(commanded_way(character, d.values[:2], d.values[2]) in ("turned_long", "turned_long_short", "turned_near_long",
                                                                       "turned_deep_long", "turned_far_short",
                                                                       "turned_near_short", "turned_near_deep_long",
                                                                       "turned_mid_deep_long", "turned_far_long")
               and not offered(character, d.values[:2], d.values[2]) for d in draws)
    plans = turned_long_judged(character, draws, tmp_path)
    assert len(plans) == TURNED_LONG_TARGETS


@pytest.mark.slow
def test_random_lateral_targets_at_short_air_times_far_turn_first_and_fly_the_long_row(tmp_path):
    """The woman's turned_long_short_region (docs/jump_to_target.md, "The woman's long row at short air times"): a
    target to the side 0.7-1.6 m away in 0.42-0.52 s, outside her measured jumps and her turned short row's region, is
    planned by plan_turned with turned_long_body (the hop, then the long row: the leap's vertical thrust, its shallow
    crouches far ahead) and run as a user's request; random draws of the report's kind with a fixed seed, judged by
    TARGETS.md; a target turned wider than the region at those air times is refused naming it."""
    from sim_core.skills.jump_to_target.commanded import table
    region = table("woman")["turned_long_short_region"]
    assert region["air_time"][1] <= table("woman")["turned_long_region"]["air_time"][0]
    d, b = region["distance"][1] - 0.05, region["bearing"][1] + 0.05
    refusal = region_refusal("woman", (d * math.cos(b), d * math.sin(b)), region["air_time"][0] + 0.01)
    assert "\n" not in refusal and "turned first with the long row at shorter air times for a distance of " \
        f"{region['distance'][0]:g}-{region['distance'][1]:g} m" in refusal
    _, plans = turned_row_planned_and_run("turned_long_short", TURNED_LONG_TARGETS, tmp_path, "woman", 36)
    assert len(plans) == TURNED_LONG_TARGETS


@pytest.mark.slow
def test_random_targets_turned_wide_near_at_long_air_times_fly_the_hops_lines_beyond_34_deg(tmp_path):
    """The woman's turned_long_region at 34-40 deg (docs/jump_to_target.md, "Her wide near targets"): a target to the
    side at 0.6-0.7 rad in 0.52-0.7 s (0.5-1.07 m away within issue 29's box), outside her measured jumps, is planned by
    plan_turned with the hop chosen by her turn_lines (measured since to hops of 55 deg: lines that stood to 48 deg)
    and run as a user's request; random draws of the report's kind with a fixed seed, judged by TARGETS.md; beyond
    40 deg refused in one line naming the row."""
    import numpy as np

    from sim_core.random_requests import Draw, draw_turned
    from sim_core.skills.jump_to_target.commanded import commanded_way, table
    body = table("woman")
    assert body["turned_long_region"]["bearing"] == [0.0, 0.7]
    assert max(abs(line) for line, stood in zip(body["turn_lines"]["line"], body["turn_lines"]["stood"])
               if stood > 0.5) > 0.8                # her hops' lines that stood reach beyond the bearing offered
    refusal = region_refusal("woman", (0.6, 0.6), 0.6)        # 45 deg
    assert "\n" not in refusal and "turned first with long air times for a distance of 0.5-1.6 m at a bearing of 0-40 deg" \
        in refusal
    rng = np.random.default_rng((SEED, 40))
    draws = []
    while len(draws) < TURNED_LONG_TARGETS:
        values = draw_turned(rng, "woman", ("turned_long",))
        if abs(math.atan2(values[1], values[0])) > 0.6:           # the bearings offered this session
            draws.append(Draw("turned_long", "woman", values))
    assert all(commanded_way("woman", d.values[:2], d.values[2]) == "turned_long"
               and not offered("woman", d.values[:2], d.values[2]) for d in draws)
    plans = turned_long_judged("woman", draws, tmp_path)
    assert len(plans) == TURNED_LONG_TARGETS


def test_the_womans_far_long_row_flies_her_long_row_with_its_own_smaller_push_beyond_its_distance():
    """The woman's turned_far_long_region (docs/jump_to_target.md, "The woman's far long row"): beyond her turned long
    row's distance (her long row lands at most ~1.5 m at long air times) the hop, then the long row with far_long_settings
    over it (a smaller lean push) and its own crouch pairs (far_long_body); a target beyond its distance or at shorter air
    times refused in one line naming it (no simulation)."""
    from sim_core.control.leap import leap_constants
    from sim_core.skills.jump_to_target.commanded import commanded_way, far_long_body, long_body, table, way_body
    body = table("woman")
    region, long_region = body["turned_far_long_region"], body["turned_long_region"]
    assert region["distance"][0] == long_region["distance"][1]          # it starts where the turned long row ends
    settings = far_long_body(body)["settings"]
    assert settings["lean_push"] == body["far_long_settings"]["lean_push"] < leap_constants("woman").commanded_lean_push
    assert settings["vertical_thrust"] == long_body(body)["settings"]["vertical_thrust"] == 1.0
    assert far_long_body(body)["crouch_by_air_time"] == body["far_long_crouch_by_air_time"]
    assert way_body(body, "turned_far_long") == far_long_body(body)
    assert commanded_way("woman", (1.55, 0.4), 0.6) == "turned_far_long"       # 1.6 m away, beyond the long row's
    assert commanded_way("woman", (1.5, 0.3), 0.6) == "turned_long"            # within the long row's distance
    refusal = region_refusal("woman", (1.6, 0.65), 0.6)                      # 1.73 m away
    assert "\n" not in refusal and "turned first with long air times beyond the long row (its own smaller lean push) " \
        f"for a distance of {region['distance'][0]:g}-{region['distance'][1]:g} m" in refusal
    assert region_refusal("woman", (1.55, 0.4), region["air_time"][0] - 0.03) is not None    # its shorter air times


@pytest.mark.slow
def test_random_far_wide_targets_at_long_air_times_turn_first_and_fly_the_far_long_row(tmp_path):
    """The woman's turned_far_long_region (docs/jump_to_target.md, "The woman's far long row"): a target to the side
    1.6-1.71 m away in 0.52-0.62 s, beyond her turned long row's distance and her measured jumps, is planned by
    plan_turned with far_long_body (the hop, then the long row with its smaller lean push) and run as a user's request;
    random draws of the report's kind with a fixed seed, judged by TARGETS.md."""
    _, plans = turned_row_planned_and_run("turned_far_long", TURNED_LONG_TARGETS, tmp_path, "woman", 51)
    assert len(plans) == TURNED_LONG_TARGETS
    assert all(p["settings"]["lean_push"] == 2.0 for p in plans)


def test_the_mans_turned_long_rows_fly_the_long_row_without_the_arms_feedback_and_the_near_row_as_it_is():
    """The man's turned long rows (docs/jump_to_target.md, "The man's turned long rows"): beyond 1.5 m the hop, then
    the long row with turned_long_settings over it (the landing arms without their pitch feedback: with it his hands
    touched the ground in the deep landings after the hop); at 0.5-1.15 m the hop, then the near long row unchanged
    (from 0.5 m: "The man's holes to the side at 0.5-0.62 s"); between them and beyond both refused in one line naming
    both."""
    from sim_core.skills.jump_to_target.commanded import (commanded_way, long_body, near_long_body, table,
                                                          turned_long_body)
    body = table("man")
    far, near = body["turned_long_region"], body["turned_near_long_region"]
    assert near["distance"][1] < far["distance"][0]
    assert commanded_way("man", (1.6, 0.4), 0.6) == "turned_long"
    assert commanded_way("man", (0.85, 0.3), 0.55) == "turned_near_long"
    assert commanded_way("man", (0.85, 0.3), 0.45) == "turned"                     # his short turned row first
    assert commanded_way("man", (1.2, 0.3), 0.6) is None                           # between the near and mid rows
    assert commanded_way("man", (0.55, 0.25), 0.56) == "turned_near_long"         # 0.6 m: the near row's from 0.5 m
    assert commanded_way("man", (0.85, 0.3), near["air_time"][1] + 0.1) is None     # beyond the deep row too
    settings = turned_long_body(body)["settings"]
    assert settings["landing_arm_pitch_gain"] == body["turned_long_settings"]["landing_arm_pitch_gain"] == 0.0
    assert {**settings, "landing_arm_pitch_gain": 0.0} == {**long_body(body)["settings"], "landing_arm_pitch_gain": 0.0}
    assert near_long_body(body)["settings"]["landing_arm_pitch_gain"] == body["settings"]["landing_arm_pitch_gain"] > 0.0
    woman = table("woman")
    assert "turned_long_settings" not in woman and turned_long_body(woman) == long_body(woman)   # hers as measured
    refusal = region_refusal("man", (1.2, 0.3), 0.6)                            # between the near and mid rows
    assert "\n" not in refusal and (
        f"turned first with long air times for a distance of {far['distance'][0]:g}-{far['distance'][1]:g} m") in refusal
    assert (f"turned first with long air times nearer for a distance of {near['distance'][0]:g}-"
            f"{near['distance'][1]:g} m") in refusal


def test_the_mans_mid_long_row_flies_between_his_near_and_far_rows_with_its_own_push_and_no_arms_feedback():
    """The man's mid long row (docs/jump_to_target.md, "The man's mid long row", "The weakest rows of seed 29's report
    shrunk" and "The turned long rows' short edge offered again"): 1.25-1.5 m at 0.52-0.62 s to the side
    (turned_mid_long_region: the hop first), flown by the long row with the mid row's own lean push (between the far
    row's and the near row's) and crouch pairs, its landing arms without their pitch feedback; below 0.52 s his near
    short row, from 0.62 s the deep rows fly it; straight ahead (not offered: 8-9 / 12) and beyond the deep rows refused
    in one line naming it. No simulation."""
    from sim_core.skills.jump_to_target.commanded import commanded_way, long_body, mid_long_body, near_long_body, table
    body = table("man")
    turned = body["turned_mid_long_region"]
    assert body["turned_near_long_region"]["distance"][1] < turned["distance"][0] <= turned["distance"][1] \
        <= body["turned_long_region"]["distance"][0]
    assert "mid_long_region" not in body and commanded_way("man", (1.35, 0.0), 0.6) is None
    assert commanded_way("man", (1.3, 0.3), 0.6) == "turned_mid_long"
    assert commanded_way("man", (1.6, 0.4), 0.6) == "turned_long"                  # the far row's as before
    assert commanded_way("man", (0.85, 0.3), 0.55) == "turned_near_long"           # the near row's as before
    assert turned["air_time"][0] <= 0.6 <= turned["air_time"][1] <= body["turned_mid_deep_long_region"]["air_time"][0]
    assert commanded_way("man", (1.3, 0.3), 0.53) == "turned_mid_long"              # its shallow crouches again
    assert commanded_way("man", (1.3, 0.3), 0.51) == "turned_near_short"            # below, the near short row's
    assert commanded_way("man", (1.3, 0.3), 0.64) == "turned_mid_deep_long"         # from 0.62 s the mid deep row's
    assert commanded_way("man", (1.3, 0.3), 0.72) is None                           # beyond the deep row too
    settings = mid_long_body(body)["settings"]
    push = body["mid_long_settings"]["lean_push"]
    assert body["long_settings"]["lean_push"] < push < body["near_long_settings"]["lean_push"] == \
        near_long_body(body)["settings"]["lean_push"]
    assert settings["landing_arm_pitch_gain"] == 0.0 and settings["vertical_thrust"] == 1.0
    assert {**settings, "lean_push": 0, "landing_arm_pitch_gain": 0} == \
        {**long_body(body)["settings"], "lean_push": 0, "landing_arm_pitch_gain": 0}
    assert mid_long_body(body)["crouch_by_air_time"] == body["mid_long_crouch_by_air_time"]
    assert "mid_long_region" not in table("woman")
    refusal = region_refusal("man", (1.146, 0.355), 0.53)                # 1.2 m: nearer than the row
    assert "\n" not in refusal and (f"turned first with long air times in the middle for a distance of "
                                     f"{turned['distance'][0]:g}-{turned['distance'][1]:g} m") in refusal


MID_LONG_TARGETS = 3        # random targets in the man's mid long row's regions, outside his measured jumps'


@pytest.mark.slow
def test_random_targets_of_the_mans_mid_long_row_land_balanced(tmp_path):
    """The man's turned mid long row's random targets (the report's --mid-long draws, seed SEED), planned and run as a
    user's requests: the hop, then the vertical thrust with the mid row's push."""
    from sim_core.skills.jump_to_target.commanded import commanded_way, table
    draws = draw_requests(SEED, ["man"], 0, 0, 0, mid_long=MID_LONG_TARGETS)
    assert [d.skill for d in draws] == ["mid_long"] * MID_LONG_TARGETS
    assert all(commanded_way("man", d.values[:2], d.values[2]) == "turned_mid_long"
               and not offered("man", d.values[:2], d.values[2]) for d in draws)
    results, lines, plans, c = all_planned_and_run("man", draws, tmp_path)
    push = table("man")["mid_long_settings"]["lean_push"]
    assert all(p["settings"]["vertical_thrust"] == 1.0 and p["settings"]["lean_push"] == push
               and p["settings"]["turn_angle"] != 0.0 for p in plans)
    assert all(p["trials"] <= c.turn_aim_trials + c.landing_trials - 1 + len(c.landing_leads) + c.landing_aims for p in plans)
    assert sum(r["passed"] for r in results) >= MID_LONG_TARGETS - 1, "\n".join(lines)
    assert max(r["seconds"] for r in results) <= 60, "\n".join(lines)


REOFFERED = {"woman": ("turned_long", 0.52, 0.57), "man": ("turned_mid_long", 0.52, 0.55)}   # the bands offered again
REOFFERED_SKILL = {"turned_long": "turned_long", "turned_mid_long": "mid_long"}                 # the report's draw of each


@pytest.mark.slow
@pytest.mark.parametrize("character", ["woman", "man"])
def test_random_targets_at_the_short_edge_of_the_turned_long_rows_land_balanced(character, tmp_path):
    """The woman's turned long row at 0.52-0.57 s and the man's mid long row at 0.52-0.55 s (docs/jump_to_target.md,
    "The turned long rows' short edge offered again"): random targets there of the report's kind (draw_turned, a fixed
    seed, drawn again until inside the band), planned by plan_turned (the hop, then the row; a jump on the target that
    fell at every foot placement tried with its feet led later, landing_leads) and run as a user's requests."""
    import numpy as np

    from sim_core.random_requests import Draw, draw_turned
    from sim_core.skills.jump_to_target.commanded import commanded_way, table
    way, low, high = REOFFERED[character]
    assert table(character)[f"{way}_region"]["air_time"][0] == low
    rng, draws = np.random.default_rng((SEED, 38)), []
    while len(draws) < TURNED_LONG_TARGETS:
        values = draw_turned(rng, character, (way,))
        if values[2] < high:
            draws.append(Draw(REOFFERED_SKILL[way], character, values))
    assert all(commanded_way(character, d.values[:2], d.values[2]) == way
               and not offered(character, d.values[:2], d.values[2]) for d in draws)
    plans = turned_long_judged(character, draws, tmp_path)
    assert len(plans) == TURNED_LONG_TARGETS


def test_the_weakest_rows_are_refused_where_their_fresh_draws_missed():
    """Seed 29's weakest rows shrunk to where their draws pass (docs/jump_to_target.md, "The weakest rows of seed 29's
    report shrunk"): her far onto-box row to T0 0.66 s (three of four misses at 0.68 s), the man's mid long row to 0.62 s
    (above, the deep rows fly it); the woman's turned long row from 0.52 s and the man's mid long row from 0.52 s again
    (the turned long rows' short edge offered again, with the landing's leads: fresh draws there 90 % and more); each
    refused target in one line naming the row's limits. No simulation."""
    from sim_core.skills.jump_to_target.commanded import commanded_way, table
    woman, man = table("woman"), table("man")
    assert woman["turned_long_short_region"]["air_time"][1] <= woman["turned_long_region"]["air_time"][0] == 0.52
    assert commanded_way("woman", (1.0, 0.3), 0.6) == "turned_long"
    assert commanded_way("woman", (1.0, 0.3), 0.5) == "turned_long_short"
    assert commanded_way("woman", (1.0, 0.3), 0.54) == "turned_long"
    assert commanded_way("woman", (0.6, 0.6), 0.54) is None                      # 45 deg: beyond the row's bearings
    refusal = region_refusal("woman", (0.6, 0.6), 0.54)
    assert "\n" not in refusal and "turned first with long air times for a distance of 0.5-1.6 m at a bearing of 0-40 deg " \
        "to either side, air_time 0.52-0.7 s" in refusal
    assert woman["long_onto_region"]["flat_air_time"] == [0.52, 0.66]
    assert commanded_way("woman", (1.2, 0.0, 0.3), 0.56) is None                 # T0 0.67 s: beyond the row's T0
    assert commanded_way("woman", (1.2, 0.0, 0.3), 0.5) == "long_onto"           # T0 0.62 s
    assert "in 0.52-0.66 s" in region_refusal("woman", (1.2, 0.0, 0.3), 0.56)
    assert man["turned_mid_long_region"]["air_time"] == [0.52, 0.62]
    assert commanded_way("man", (1.4, 0.3), 0.58) == "turned_mid_long"
    assert commanded_way("man", (1.4, 0.3), 0.535) == "turned_mid_long"          # from his short rows' end
    assert commanded_way("man", (1.4, 0.3), 0.51) == "turned_near_short"
    refusal = region_refusal("man", (1.146, 0.355), 0.535)                        # 1.2 m: nearer than the row
    assert "\n" not in refusal and "turned first with long air times in the middle for a distance of 1.25-1.5 m at a " \
        "bearing of 0-34 deg to either side, air_time 0.52-0.62 s" in refusal
    assert commanded_way("man", (1.35, 0.3), 0.635) == "turned_mid_deep_long"


NEAR_HOLE = (0.5, 0.7)       # the man's near row's distances offered after the hop from 0.5 m (m; was from 0.7 m)


def test_the_mans_near_targets_to_the_side_are_flown_by_his_near_long_row():
    """The man's near targets to the side at 0.5-0.62 s (docs/jump_to_target.md, "The man's holes to the side at
    0.5-0.62 s"): 0.5-0.7 m flown by the near long row after the hop (turned_near_long_region from 0.5 m); 1.15-1.25 m,
    between his near and mid rows, still refused (the near row 4 / 6 there, the mid row 16 / 20), in one line naming
    both. No simulation."""
    from sim_core.skills.jump_to_target.commanded import commanded_way, table
    body = table("man")
    near, mid = body["turned_near_long_region"], body["turned_mid_long_region"]
    assert near["distance"] == [NEAR_HOLE[0], 1.15] and mid["distance"] == [1.25, 1.5]
    assert commanded_way("man", (0.55, 0.25), 0.56) == "turned_near_long"         # 0.6 m: was refused
    assert commanded_way("man", (0.5, 0.1), 0.61) == "turned_near_long"
    assert commanded_way("man", (0.55, 0.25), 0.47) == "turned"                   # his short turned row first
    assert commanded_way("man", (0.55, 0.25), 0.65) == "turned_near_deep_long"    # from 0.62 s the near deep row's
    assert commanded_way("man", (0.45, 0.45), 0.56) == "turned_near_long"         # 45 deg: offered to 50 deg since
    assert commanded_way("man", (0.35, 0.45), 0.56) is None                       # 52 deg: beyond the row's bearings
    assert commanded_way("man", (1.146, 0.355), 0.57) is None                     # 1.2 m: between the rows
    for target, air_time in (((0.35, 0.45), 0.56), ((1.146, 0.355), 0.57)):
        refusal = region_refusal("man", target, air_time)
        assert "\n" not in refusal and "turned first with long air times nearer for a distance of 0.5-1.15 m at a " \
            "bearing of 0-50 deg to either side, air_time 0.5-0.62 s" in refusal and "turned first with long air " \
            "times in the middle for a distance of 1.25-1.5 m at a bearing of 0-34 deg to either side, air_time " \
            "0.52-0.62 s" in refusal


@pytest.mark.slow
def test_random_near_targets_of_the_man_to_the_side_land_balanced(tmp_path):
    """Random targets of the report's kind (draw_turned, a fixed seed, drawn again until 0.5-0.7 m away: NEAR_HOLE) in
    the man's near long row after the hop, planned by plan_turned and run as a user's requests, judged by TARGETS.md."""
    import numpy as np

    from sim_core.random_requests import Draw, draw_turned
    from sim_core.skills.jump_to_target.commanded import commanded_way
    rng, draws = np.random.default_rng((SEED, 39)), []
    while len(draws) < TURNED_LONG_TARGETS:
        values = draw_turned(rng, "man", ("turned_near_long",))
        if NEAR_HOLE[0] <= math.hypot(*values[:2]) <= NEAR_HOLE[1]:
            draws.append(Draw("turned_long", "man", values))
    assert all(commanded_way("man", d.values[:2], d.values[2]) == "turned_near_long"
               and not offered("man", d.values[:2], d.values[2]) for d in draws)
    plans = turned_long_judged("man", draws, tmp_path)
    assert len(plans) == TURNED_LONG_TARGETS


def test_the_mans_deep_long_row_flies_his_far_row_at_its_deepest_crouches():
    """The man's longest air times (docs/jump_to_target.md, "The man's deep long row"): where none of his long rows
    reaches (0.62-0.7 s), straight ahead (deep_long_region) and after the hop (turned_deep_long_region), flown by his far
    long row as it is (turned: with turned_long_settings) with the deep row's crouch pairs; his other rows keep their
    regions; beyond 0.7 s refused in one line naming it. No simulation."""
    from sim_core.skills.jump_to_target.commanded import (commanded_way, deep_long_body, long_body, table,
                                                          turned_long_body)
    body = table("man")
    straight, turned = body["deep_long_region"], body["turned_deep_long_region"]
    assert straight["air_time"][1] == turned["air_time"][1] > body["turned_long_region"]["air_time"][1]
    assert commanded_way("man", (1.6, 0.0), 0.68) == "deep_long"
    assert commanded_way("man", (1.55, 0.4), 0.68) == "turned_deep_long"
    assert commanded_way("man", (1.3, 0.3), 0.68) == "turned_mid_deep_long"         # nearer: the far row's aim is rough
                                                                                    # there, the mid deep row's push flies it
    assert commanded_way("man", (1.7, 0.3), 0.6) == "turned_long"                   # the far row's as before
    assert commanded_way("man", (1.3, 0.3), 0.6) == "turned_mid_long"               # the mid row's as before
    assert commanded_way("man", (1.0, 0.0), 0.6) == "near_long"                     # the near row's as before
    assert commanded_way("man", (1.8, 0.3), 0.68) is None                           # farther: aims at the cap
    assert commanded_way("man", (1.0, 0.4), 0.72) is None
    deep = deep_long_body(body)
    assert deep["settings"] == long_body(body)["settings"] and deep["crouch_by_air_time"] == \
        body["deep_long_crouch_by_air_time"]
    assert deep_long_body(body, turned=True)["settings"] == turned_long_body(body)["settings"]
    assert min(deep["crouch_by_air_time"]["crouch_height"]) < min(body["long_crouch_by_air_time"]["crouch_height"])
    assert "deep_long_region" not in table("woman") and "turned_deep_long_region" not in table("woman")
    refusal = region_refusal("man", (1.0, 0.4), 0.72)
    assert "\n" not in refusal and (f"turned first with the longest air times for a distance of "
                                     f"{turned['distance'][0]:g}-{turned['distance'][1]:g} m") in refusal


def test_the_mans_short_air_times_far_ahead_are_flown_by_his_long_rows_at_their_shallowest_crouches():
    """The man's short air times far ahead (docs/jump_to_target.md, "The man's long rows at short air times"): where his
    straight commanded row's forward speed ends (~2.1 m/s), straight ahead (far_short_region, near_short_region) and
    after the hop (turned_far_short_region, turned_near_short_region), flown by his far long row and his near long row
    as they are (after the hop too) with their own shallow crouch pairs; his other rows keep their regions;
    beyond them refused in one line naming them. No simulation."""
    from sim_core.skills.jump_to_target.commanded import (commanded_way, long_body, near_long_body, short_body, table,
                                                          turned_long_body)
    body = table("man")
    assert commanded_way("man", (1.75, 0.0), 0.45) == "far_short"
    assert commanded_way("man", (1.3, 0.0), 0.41) == "near_short"
    assert commanded_way("man", (1.7, 0.4), 0.45) == "turned_far_short"
    assert commanded_way("man", (1.3, -0.4), 0.41) == "turned_near_short"
    assert commanded_way("man", (1.0, 0.3), 0.45) == "turned"                         # his commanded row's as before
    assert commanded_way("man", (1.7, 0.3), 0.6) == "turned_long"                     # the far row's as before
    assert commanded_way("man", (1.8, 0.0), 0.6) == "long"
    assert commanded_way("man", (1.75, 0.0), 0.405) == "far_short"                   # its 0.72 m pair flies 0.38-0.40 s
    assert commanded_way("man", (1.75, 0.3), 0.405) == "turned_far_short"
    assert commanded_way("man", (1.75, 0.0), 0.395) is None                           # below the far row's 0.72 m pair
    far, near = short_body(body, "far_short"), short_body(body, "near_short")
    assert far["settings"] == long_body(body)["settings"] and far["crouch_by_air_time"] == body["far_short_crouch_by_air_time"]
    assert far["settings"] != turned_long_body(body)["settings"]     # after the hop too: the landing arms' feedback kept
    assert near["settings"] == near_long_body(body)["settings"] and \
        near["crouch_by_air_time"] == body["near_short_crouch_by_air_time"]
    for row in (far, near):                      # shallower than every long row's crouches: the short air times
        assert min(row["crouch_by_air_time"]["crouch_height"]) > max(body["long_crouch_by_air_time"]["crouch_height"])
    assert not {"far_short_region", "near_short_region", "turned_far_short_region", "turned_near_short_region"} & \
        set(table("woman"))
    turned = body["turned_far_short_region"]
    refusal = region_refusal("man", (1.75, 0.3), 0.395)
    assert "\n" not in refusal and (f"turned first with short air times far ahead for a distance of "
                                     f"{turned['distance'][0]:g}-{turned['distance'][1]:g} m") in refusal


SHORT_TARGETS = 3           # random targets in each of the man's turned short rows' regions, outside his measured jumps'


@pytest.mark.slow
@pytest.mark.parametrize("way", ["turned_far_short", "turned_near_short"])
def test_random_targets_of_the_mans_short_rows_land_balanced(way, tmp_path):
    """Random targets uniform in issue 29's box where the man's turned short rows hold them (the report's draw,
    random_requests.draw_turned, with a fixed seed), planned and run as a user's requests: the hop, then his far or near
    long row at its shallowest crouches, landing within the tolerances and balanced."""
    draws, plans = turned_row_planned_and_run(way, SHORT_TARGETS, tmp_path)
    assert all(d.values[2] <= 0.52 for d in draws) and all(p["settings"]["crouch_height"] > 0.6 for p in plans)


DEEP_LONG_TARGETS = 3       # random targets in the man's turned deep long row's region, outside his measured jumps'


@pytest.mark.slow
def test_random_targets_of_the_mans_deep_long_row_land_balanced(tmp_path):
    """Random targets uniform in issue 29's box where the man's turned deep long row holds them (the report's draw,
    random_requests.draw_turned, with a fixed seed), planned and run as a user's requests: the hop, then the far long
    row's vertical thrust at its deepest crouches, landing within the tolerances and balanced."""
    _, plans = turned_row_planned_and_run("turned_deep_long", DEEP_LONG_TARGETS, tmp_path)
    assert all(p["settings"]["crouch_height"] < 0.55 for p in plans)


def test_the_mans_near_deep_long_row_flies_his_near_row_at_its_deepest_crouches():
    """The man's longest air times nearer than his deep row (docs/jump_to_target.md, "The man's near deep long row"):
    straight ahead (near_deep_long_region) and after the hop (turned_near_deep_long_region), flown by his near long row
    as it is (its lean push) with the near deep row's crouch pairs, and between it and the deep row the mid deep row (the
    long row with its own lean push at the deepest crouches); his other rows keep their regions; beyond 0.7 s refused in
    one line naming them. No simulation."""
    from sim_core.skills.jump_to_target.commanded import (commanded_way, mid_deep_long_body, near_deep_long_body,
                                                          near_long_body, table)
    body = table("man")
    straight, turned = body["near_deep_long_region"], body["turned_near_deep_long_region"]
    assert straight["air_time"][1] == turned["air_time"][1] == 0.7
    assert turned["distance"][1] < body["turned_deep_long_region"]["distance"][0]
    assert commanded_way("man", (0.7, 0.0), 0.68) == "near_deep_long"
    assert commanded_way("man", (0.8, 0.3), 0.68) == "turned_near_deep_long"
    assert commanded_way("man", (0.8, 0.3), 0.6) == "turned_near_long"              # the near row's as before
    assert commanded_way("man", (0.7, 0.0), 0.6) == "near_long"                     # straight: the near row's as before
    assert commanded_way("man", (1.6, 0.3), 0.68) == "turned_deep_long"             # farther: the deep row's as before
    assert commanded_way("man", (1.3, 0.3), 0.68) == "turned_mid_deep_long"         # between: the mid deep row's
    assert commanded_way("man", (1.3, 0.0), 0.68) == "mid_deep_long"
    assert commanded_way("man", (1.6, 0.3), 0.72) is None
    assert commanded_way("man", (0.8, 0.3), 0.72) is None
    deep = near_deep_long_body(body)
    assert deep["settings"] == near_long_body(body)["settings"] and deep["crouch_by_air_time"] == \
        body["near_deep_long_crouch_by_air_time"]
    assert min(deep["crouch_by_air_time"]["crouch_height"]) < min(body["near_long_crouch_by_air_time"]["crouch_height"])
    assert "near_deep_long_region" not in table("woman") and "turned_near_deep_long_region" not in table("woman")
    mid = body["turned_mid_deep_long_region"]
    assert turned["distance"][1] <= mid["distance"][0] and mid["distance"][1] <= body["turned_deep_long_region"]["distance"][0]
    assert mid_deep_long_body(body)["settings"]["lean_push"] == body["mid_deep_long_settings"]["lean_push"] \
        < near_long_body(body)["settings"]["lean_push"]
    refusal = region_refusal("man", (1.3, 0.3), 0.72)
    assert "\n" not in refusal and (f"turned first with the longest air times nearer for a distance of "
                                     f"{turned['distance'][0]:g}-{turned['distance'][1]:g} m") in refusal and (
        f"turned first with the longest air times in the middle for a distance of {mid['distance'][0]:g}-"
        f"{mid['distance'][1]:g} m") in refusal


NEAR_DEEP_LONG_TARGETS = 3  # random targets in the man's turned near deep long row's region, outside his measured jumps'


@pytest.mark.slow
def test_random_targets_of_the_mans_near_deep_long_row_land_balanced(tmp_path):
    """Random targets uniform in issue 29's box where the man's turned near deep long row holds them (the report's draw,
    random_requests.draw_turned, with a fixed seed), planned and run as a user's requests: the hop, then the near long
    row's vertical thrust at its deepest crouches, landing within the tolerances and balanced."""
    from sim_core.skills.jump_to_target.commanded import table
    _, plans = turned_row_planned_and_run("turned_near_deep_long", NEAR_DEEP_LONG_TARGETS, tmp_path)
    assert all(p["settings"]["lean_push"] == table("man")["near_long_settings"]["lean_push"] for p in plans)


MAN_WIDE_ROWS = {"turned": 0.8, "turned_near_long": 0.88, "turned_near_deep_long": 0.88}   # his near turned rows'
#   bearings' bounds (rad; all were 0.6); issue 29's box reaches atan2(0.6, 0.5) = 0.876 rad


def test_the_mans_near_turned_rows_reach_wide_bearings():
    """The man's near turned rows widened (docs/jump_to_target.md, "His wide near targets"): his turned near long and
    turned near deep long rows offered to 0.88 rad (50 deg), which covers issue 29's box at 0.5 m (0.876 rad), his
    turned row to 0.8 rad (46 deg); a target wider than that is refused in one line naming the row's bearings. No
    simulation."""
    from sim_core.skills.jump_to_target.commanded import commanded_way, table
    body = table("man")
    assert all(body[f"{way}_region"]["bearing"] == [0.0, bound] for way, bound in MAN_WIDE_ROWS.items())
    assert math.atan2(0.6, 0.5) <= MAN_WIDE_ROWS["turned_near_long"]
    assert commanded_way("man", (0.8, 0.6), 0.45) == "turned"                   # 37 deg: refused before
    assert commanded_way("man", (0.55, 0.55), 0.45) == "turned"                 # 45 deg
    assert commanded_way("man", (0.5, 0.6), 0.45) is None                       # 50 deg: beyond the turned row
    assert commanded_way("man", (0.5, 0.55), 0.56) == "turned_near_long"        # 48 deg
    assert commanded_way("man", (0.5, -0.55), 0.66) == "turned_near_deep_long"
    assert commanded_way("man", (0.85, 0.3), 0.55) == "turned_near_long"         # the near row's as before
    for target, air_time, words in (
            ((0.5, 0.6), 0.45, "turned first for a distance of 0.5-1.2 m at a bearing of 0-46 deg"),
            ((0.4, 0.6), 0.56, "turned first with long air times nearer for a distance of 0.5-1.15 m at a bearing of "
                               "0-50 deg"),
            ((0.4, 0.6), 0.66, "turned first with the longest air times nearer for a distance of 0.5-1.15 m at a "
                               "bearing of 0-50 deg")):
        assert commanded_way("man", target, air_time) is None
        refusal = region_refusal("man", target, air_time)
        assert "\n" not in refusal and words in refusal


WIDE_LONG_WAYS = ("turned_near_long", "turned_near_deep_long")


@pytest.mark.slow
def test_random_targets_of_the_man_turned_wide_near_land_balanced(tmp_path):
    """Random targets of the report's kind (draw_turned, a fixed seed) in the man's turned near long and near deep long
    rows beyond their old bearings (0.6-0.88 rad), outside his measured jumps, planned by plan_turned (the hop by his heading map, then the
    row's vertical thrust) and run as a user's requests, judged by TARGETS.md."""
    import numpy as np

    from sim_core.random_requests import Draw, draw_turned
    from sim_core.skills.jump_to_target.commanded import commanded_way
    rng, draws = np.random.default_rng((SEED, 50)), []
    assert all(MAN_WIDE_ROWS[way] == 0.88 for way in WIDE_LONG_WAYS)
    while len(draws) < TURNED_LONG_TARGETS:
        values = draw_turned(rng, "man", WIDE_LONG_WAYS)
        if abs(math.atan2(values[1], values[0])) > 0.6:           # the bearings offered this session
            draws.append(Draw("turned_long", "man", values))
    assert all(commanded_way("man", d.values[:2], d.values[2]) in WIDE_LONG_WAYS
               and not offered("man", d.values[:2], d.values[2]) for d in draws)
    plans = turned_long_judged("man", draws, tmp_path)
    assert len(plans) == TURNED_LONG_TARGETS



WOMAN_WIDE_SHORT = (0.5, 0.7)    # her turned row's (0.4-0.48 s) distance from (m) and bearing to (rad) since "Her wide
# near targets at short air times" (was 0.7 m and 0.45 rad)


def test_the_womans_short_turned_row_reaches_near_and_wide():
    """The woman's turned row at short air times widened (docs/jump_to_target.md, "Her wide near targets at short air
    times"): her turned row (the hop, then the commanded take-off; 0.4-0.48 s) offered from 0.5 m (was 0.7 m) to 0.7 rad
    (40 deg; was 0.45), as her turned long row; the issue's examples are flown so; a target wider than that, or in
    0.48-0.52 s beyond her turned long row at shorter air times (not widened: its fresh draws there missed), is refused in
    one line naming the rows. No simulation."""
    from sim_core.skills.jump_to_target.commanded import commanded_way, table
    body = table("woman")
    assert body["turned_region"]["distance"][0] == WOMAN_WIDE_SHORT[0]
    assert body["turned_region"]["bearing"] == [0.0, WOMAN_WIDE_SHORT[1]]
    assert body["turned_long_short_region"] == {"distance": [0.7, 1.6], "bearing": [0.0, 0.45], "air_time": [0.42, 0.52]}
    for target, air_time in (((0.6, 0.4), 0.45), ((0.7, -0.4), 0.45), ((1.0, 0.6), 0.47), ((0.6, -0.2), 0.45),
                             ((0.9, 0.5), 0.45), ((0.58, -0.3), 0.43)):
        assert commanded_way("woman", target, air_time) == "turned" and in_region("woman", target, air_time)
    for target, air_time, words in (
            ((0.5, 0.6), 0.45, "turned first for a distance of 0.5-1.25 m at a bearing of 0-40 deg to either side, "
                               "air_time 0.4-0.48 s"),
            ((0.9, -0.5), 0.5, "turned first with the long row at shorter air times for a distance of 0.7-1.6 m at a "
                               "bearing of 0-26 deg to either side, air_time 0.42-0.52 s")):
        assert commanded_way("woman", target, air_time) is None and not in_region("woman", target, air_time)
        refusal = region_refusal("woman", target, air_time)
        assert "\n" not in refusal and words in refusal


@pytest.mark.slow
def test_random_targets_of_the_woman_turned_wide_near_at_short_air_times_land_balanced(tmp_path):
    """Random targets of the report's kind (draw_turned, a fixed seed) in the woman's turned row (the hop, then the
    commanded take-off, 0.4-0.48 s) where it was widened - nearer than 0.7 m or beyond 0.45 rad (docs/jump_to_target.md,
    "Her wide near targets at short air times") - outside her measured jumps, planned by plan_turned (the hop by her
    turn_lines) and run as a user's requests, judged by TARGETS.md (one miss allowed, 60 s each)."""
    import numpy as np

    from sim_core.random_requests import Draw, draw_turned
    from sim_core.skills.jump_to_target.commanded import commanded_way
    rng, draws = np.random.default_rng((SEED, 60)), []
    while len(draws) < TURNED_TARGETS:
        values = draw_turned(rng, "woman")
        if math.hypot(*values[:2]) < 0.7 or abs(math.atan2(values[1], values[0])) > 0.45:     # offered this session
            draws.append(Draw("turned", "woman", values))
    assert all(commanded_way("woman", d.values[:2], d.values[2]) == "turned"
               and not offered("woman", d.values[:2], d.values[2]) for d in draws)
    results, lines, plans, c = all_planned_and_run("woman", draws, tmp_path)
    assert len(plans) == TURNED_TARGETS and all(p["settings"]["turn_angle"] != 0.0 for p in plans)
    assert all(p["trials"] <= c.turn_aim_trials + c.landing_trials - 1 + len(c.landing_leads) + c.landing_aims for p in plans)
    assert sum(r["passed"] for r in results) >= TURNED_TARGETS - 1, "\n".join(lines)
    assert max(r["seconds"] for r in results) <= 60, "\n".join(lines)
