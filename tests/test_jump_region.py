"""Jumps to any target in the region offered (issue 29): random targets with a fixed seed, drawn
and judged as the random-requests report draws and judges them (planned from the measured jumps,
then run); a target outside the region is refused in one line before anything is simulated."""
from __future__ import annotations

import pytest

from sim_core.errors import ParameterError
from sim_core.random_requests import draw_requests, evaluate, result_line
from sim_core.simulate import RunRequest, run
from sim_core.skills.jump_to_target.region import offered, region_refusal

SEED = 29           # CI's fixed draw
TARGETS = 3         # random targets per character


@pytest.mark.parametrize("character", ["man", "woman"])
def test_random_targets_in_the_region_land_on_target_balanced(character, tmp_path):
    draws = draw_requests(SEED, [character], TARGETS, 0, 0)
    results = [evaluate(draw, 24, str(tmp_path)) for draw in draws]
    lines = [result_line(r) for r in results]
    assert all(offered(character, d.values[:2], d.values[2]) for d in draws)
    assert sum(r["passed"] for r in results) >= TARGETS - 1, "\n".join(lines)     # >= 90 % asked; 3 draws
    assert max(r["seconds"] for r in results) <= 60, "\n".join(lines)


@pytest.mark.parametrize("params, words", [
    ({"target_x": 1.0, "target_y": 0.4, "air_time": 0.45}, ["target_y at 1.00 m forward in 0.45 s is offered only in"]),
    ({"target_x": 1.0, "target_y": 0.0, "air_time": 0.535}, ["air_time at 1.00 m forward is offered only in"]),  # between the families
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
