"""The vault's landing search at one run-up speed (planning.vault; `report vault --plan`, docs/vault.md
"A landing plan per run-up speed"): it steps foot_delta the way the fall goes until the fall turns to the
other side, then bisects, at most plan_trials vaults, stopping at the first success."""
from types import SimpleNamespace

import numpy as np
import pytest

from sim_core.planning.vault import fall_side, plan_foot_delta
from sim_core.skills.vault.behaviour import CONSTANTS, calibrated
from sim_core.skills.vault.report import run_at


def outcome_of(window: tuple[float, float]):
    """A stand-in for the vault (no physics): below the window she falls forward (the COM 0.3 m past the
    feet's middle), above it back, inside it she stands."""
    def simulate(foot_delta):
        low, high = window
        outcome = "success" if low <= foot_delta <= high else "fell"
        ahead = 0.0 if outcome == "success" else (0.3 if foot_delta < low else -0.3)
        return SimpleNamespace(meta={"outcome": outcome, "metrics": {"fall_time": None if outcome == "success" else 1.0}},
                               arrays={"time": np.array([0.0, 1.0, 2.0]), "com": np.array([[ahead, 0, 0.9]] * 3),
                                       "support_points": np.zeros((3, 4, 3))})
    return simulate


def test_the_search_steps_the_way_the_fall_goes_then_bisects_to_a_window():
    plan = plan_foot_delta(outcome_of((0.1820, 0.1823)), 0.2, -0.3, 0.3)
    assert plan["found"] and 0.1820 <= plan["foot_delta"] <= 0.1823 and plan["trials"] <= CONSTANTS.plan_trials
    assert [t["side"] for t in plan["tried"][:2]] == [-1, -1]          # 0.2 falls back: the feet come back


def test_a_fall_that_turns_with_no_standing_placement_between_is_a_bracket_not_a_plan():
    plan = plan_foot_delta(outcome_of((0.18215, 0.18215 - 1e-9)), 0.2, -0.3, 0.3)
    assert not plan["found"] and plan["foot_delta"] is None
    low, high = plan["bracket"]
    assert low < 0.18215 < high and high - low <= CONSTANTS.plan_resolution


def test_at_the_shipped_speed_her_row_stands_on_the_first_trial():
    """6.75 m/s: her row's foot_delta (0.2 m) is the first trial and stands - the search changes nothing there."""
    row = calibrated("woman", "human")["settings"]
    plan = plan_foot_delta(lambda fd: run_at(6.75, overrides=[f"foot_delta={fd}"]), row["foot_delta"], -0.3, 0.3)
    assert plan["found"] and plan["trials"] == 1 and plan["foot_delta"] == row["foot_delta"]
    assert fall_side(run_at(6.75, overrides=["foot_delta=0.19"])) == 1        # measured: falls forward


@pytest.mark.slow
def test_at_6_71_m_s_the_search_finds_a_standing_placement():
    """Measured (docs/vault.md): at 6.71 m/s the search stands within 16 vaults (~40 s); her row since vault11
    (the capture-point rise) stands there at its own foot_delta, the first trial (~6 s)."""
    plan = plan_foot_delta(lambda fd: run_at(6.71, overrides=[f"foot_delta={fd}"]), 0.2, -0.3, 0.3)
    assert plan["found"], plan["tried"]
