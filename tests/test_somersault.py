"""Standing tuck somersaults (Wooten §8.4, §8.5), measured off the simulation: the rotation count,
the flight's physics and a balanced finish on the feet."""
import math

import pytest

from sim_core.skills.somersault.behaviour import DIRECTIONS, ROTATION_TOLERANCE, calibrated, load_table
from sim_core.errors import ParameterError
from sim_core.simulate import RunRequest, largest_difference, replay, run

CASES = [("man", "backward", "unlimited"), ("man", "backward", "human"),
         ("man", "forward", "human"), ("woman", "forward", "human"),   # the thesis: man backward, woman forward
         ("woman", "backward", "human")]                               # issue 29: both ways for both


def _run(character, direction, strength):
    return run(RunRequest("somersault", character, params={"direction": DIRECTIONS.index(direction)},
                          strength=strength))


def _not_found(character, direction, strength):
    for entry in load_table(character).get("not_found", []):
        if (entry["direction"], entry["strength"]) == (direction, strength):
            return entry["best"]
    return "not calibrated"


@pytest.fixture(scope="module")
def somersaults():
    return {case: _run(*case) for case in CASES if calibrated(*case)}


@pytest.mark.parametrize("case", CASES, ids=["-".join(c) for c in CASES])
def test_somersault_turns_once_and_ends_balanced(somersaults, case):
    """One full turn about the somersault axis (2 pi within 0.35 rad, the pelvis from the standing
    start to the end), most of it in the air, ending balanced on the feet; the whole-body angular
    momentum stays constant within 1 % in flight; no twist at take-off."""
    if case not in somersaults:
        pytest.xfail(f"{' '.join(case)}: no calibrated somersault lands ({_not_found(*case)})")
    traj = somersaults[case]
    m = traj.meta["metrics"]
    print(case, {k: m.get(k) for k in ("rotation", "flight_rotation", "first_flight_time", "com_rise", "com_travel",
                                       "liftoff_angular_momentum", "angular_momentum_drift")})
    assert traj.meta["outcome"] == "success", (traj.meta["outcome"], m)
    assert abs(m["rotation"] - 2 * math.pi) <= ROTATION_TOLERANCE
    assert m["flight_rotation"] > 1.5 * math.pi          # it turns in the air, not on the ground
    assert math.copysign(1.0, m["liftoff_angular_momentum"]) == (1.0 if case[1] == "forward" else -1.0)
    assert m["angular_momentum_drift"] < 0.01
    assert abs(m["takeoff_twist_rate"]) < 0.1


def test_somersault_replays_bit_for_bit(somersaults):
    if not somersaults:
        pytest.xfail("no calibrated somersault")
    traj = next(iter(somersaults.values()))
    assert largest_difference(traj, replay(traj)) == 0.0


def test_an_uncalibrated_somersault_is_refused_before_simulating(monkeypatch):
    """A somersault with no calibrated take-off for the character, direction and strength is
    refused with the reason; nothing is simulated."""
    import sim_core.skills.somersault.behaviour as somersault
    monkeypatch.setattr(somersault, "load_table", lambda character: {"somersaults": [], "not_found": [
        {"direction": "backward", "strength": "human", "best": "fell, rotation 3.37 rad"}]})
    with pytest.raises(ParameterError, match="no calibrated backward somersault.*best searched: fell"):
        run(RunRequest("somersault", "man", params={"direction": 0}))


@pytest.mark.parametrize("bad", [{"direction": 2}, {"direction": float("nan")}, {"liftoff_hip": 3.0}])
def test_bad_somersault_parameters_are_refused(bad):
    with pytest.raises(ParameterError, match=next(iter(bad))):
        run(RunRequest("somersault", "man", params=dict(bad, low_level=1)))


def test_the_crouch_before_the_take_off_is_a_squat_not_a_fall():
    """A deep backward-leaning crouch takes the pelvis below half its standing height before the
    take-off; that is the skill's squat (allowed down to SQUAT_LOWEST), not a fall - the same run
    judged by the standing rule throughout would be a fall."""
    from sim_core.analysis import standard_metrics
    from sim_core.skills.somersault.behaviour import SQUAT_LOWEST
    settings = {"crouch_height": 0.55, "crouch_pitch": 1.3655, "com_offset": -0.1459, "thrust_lean": -0.1,
                "liftoff_hip": 1.6871, "arm_swing": 3.0478, "thrust_damping": 0.8088, "tuck_stiffness": 2.1365}
    traj = run(RunRequest("somersault", "man", params=dict(settings, low_level=1, direction=0), duration=1.6))
    names = traj.body_names
    pelvis = traj.arrays["body_pos"][:, names.index("PELVIS"), 2]
    assert traj.meta["metrics"]["liftoff_time"] < 1.6            # it took off within the run
    before = traj.arrays["time"] < traj.meta["metrics"]["liftoff_time"]
    assert SQUAT_LOWEST < pelvis[before].min() < 0.5 * pelvis[0]
    assert not traj.meta["metrics"]["fell"]
    assert standard_metrics(traj)["fell"]


def test_a_lighter_tuck_damping_closes_the_tuck_sooner_and_the_finer_flight_step_keeps_the_momentum():
    """The human back tuck's searched settings: with the old overdamped snap (tuck_damping 0 =
    stiffness x 2) the hips take longer to fold to the tuck after the lift-off than with the
    searched lighter damping, whose flight at an 8-times finer physics step keeps the whole-body
    angular momentum within 1 % (measured 0.25 %; the same tuck in the model's 1 ms step drifts
    2 %), and the replay log reproduces the finer step bit for bit."""
    import numpy as np
    from sim_core.character.model import compile_model
    from sim_core.world import World
    from sim_core.character.spec import load_character
    settings = {"crouch_height": 0.7008, "crouch_pitch": 1.4023, "com_offset": -0.1381, "thrust_lean": -0.0669,
                "liftoff_hip": 1.9558, "arm_swing": 3.1917, "thrust_damping": 0.9597, "tuck_stiffness": 2.9339,
                "tuck_time": 0.0734, "tuck_damping": 0.8173, "flight_step_division": 8}

    model, _ = compile_model(load_character("man"), World(), "human")
    hip_column = model.joint("hip_r_y").qposadr[0]

    def folded_after_liftoff(traj):
        a, m = traj.arrays, traj.meta["metrics"]
        hip = a["qpos"][:, hip_column]
        after = a["time"] >= m["liftoff_time"]
        folded = after & (hip < -1.8)
        return float(a["time"][np.argmax(folded)] - m["liftoff_time"]) if folded.any() else math.inf

    fast = run(RunRequest("somersault", "man", params=dict(settings, low_level=1, direction=0), duration=1.9))
    slow = run(RunRequest("somersault", "man", params=dict(settings, low_level=1, direction=0, tuck_damping=0.0,
                                                            flight_step_division=1), duration=1.9))
    assert folded_after_liftoff(fast) < folded_after_liftoff(slow) - 0.05
    assert fast.meta["metrics"]["angular_momentum_drift"] < 0.01
    coarse = run(RunRequest("somersault", "man", params=dict(settings, low_level=1, direction=0,
                                                              flight_step_division=1), duration=1.9))
    assert coarse.meta["metrics"]["angular_momentum_drift"] > 0.01     # the same tuck in 1 ms steps drifts
    assert (fast.arrays["step_division"] == 8).any()
    assert largest_difference(fast, replay(fast)) == 0.0
