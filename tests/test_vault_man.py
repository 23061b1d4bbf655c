"""The man's handspring vault (issue 31 part 3), measured off the simulation: her table scaled to him by
Fig. 6 (adapt.skills.VaultAdapter: lengths by L, times and speeds by L^1/2, the board's springs for his
weight), his own constants (the start, the horse at his height, the run-up speeds he is offered), one
somersault, feet first, inside the dismount band, no shoulder or wrist torque on the horse (V5), standing
balanced after the bow; replay bit for bit; refusals in one line. One whole vault (~2 s of wall time)
serves the run tests (docs/vault.md "The man's vault")."""
import math

import mujoco
import numpy as np
import pytest

from sim_core import tuned
from sim_core.adapt.skills import VaultAdapter
from sim_core.character.dimensions import leg_length_ratio
from sim_core.character.spec import load_character
from sim_core.errors import ParameterError
from sim_core.simulate import RunRequest, largest_difference, replay, run
from sim_core.skills.vault.assess import BALANCED_TIME, NO_STEP, PEAK_LANDING_LIMIT, ROTATION_TOLERANCE, servos_on_horse
from sim_core.skills.vault.behaviour import CONSTANTS, vault_constants
from sim_core.world.apparatus import BOARD_MASS, PROP_BODY_PREFIX


@pytest.fixture(scope="module")
def his():
    return vault_constants("man")


@pytest.fixture(scope="module")
def vault(his):
    """The whole script at the middle of his offered run-up speeds."""
    return run(RunRequest("vault", "man", params={"runup_speed": float(np.mean(his.handled_speed))}))


def test_the_adapter_scales_her_vault_by_fig_6():
    """No physics: the start, the gap, the horse and the run-up by L and L^1/2; the board's half period
    with him on it is hers x L^1/2; a time setting by L^1/2, a length by L, an angle as it is."""
    woman, man = load_character("woman"), load_character("man")
    L = leg_length_ratio(woman, man)
    body, _ = VaultAdapter().scale(woman, man, tuned.load("vault", "woman"))
    k, row = body["constants"], body["vaults"][0]["settings"]
    hers = tuned.load("vault", "woman")["vaults"][0]["settings"]
    assert k["start_com_height"] == pytest.approx(CONSTANTS.start_com_height * L, abs=1e-4)
    assert k["horse_gap"] == pytest.approx(CONSTANTS.horse_gap * L, abs=1e-4)
    assert k["horse_height"] == pytest.approx(CONSTANTS.horse_height * L, abs=1e-4)
    assert k["handled_speed"][0] == pytest.approx(CONSTANTS.handled_speed[0] * math.sqrt(L), abs=1e-4)
    period = lambda mass, stiffness: math.pi * math.sqrt((mass + BOARD_MASS) / stiffness)
    assert period(man.total_mass, k["board_stiffness"]) == pytest.approx(
        period(woman.total_mass, CONSTANTS.board_stiffness) * math.sqrt(L), rel=1e-4)
    assert row["push_time"] == pytest.approx(hers["push_time"] * math.sqrt(L), abs=1e-5)
    assert row["hand_ahead"] == pytest.approx(hers["hand_ahead"] * L, abs=1e-5)
    assert row["block_hip"] == hers["block_hip"] and row["horse_gate"] == hers["horse_gate"]


def test_he_vaults_with_his_own_apparatus_and_start(vault, his):
    model = mujoco.MjModel.from_xml_string(vault.meta["model_xml"])
    deck = model.joint(PROP_BODY_PREFIX + "springboard/deflection").id
    assert model.jnt_stiffness[deck] == his.board_stiffness
    assert vault.meta["start_state"]["skill"]["com_above_board"] == his.start_com_height
    assert vault.meta["world"]["vault_table"][2] == his.horse_height


def test_one_somersault_feet_first_inside_the_band_and_he_stands(vault):
    m = vault.meta["metrics"]
    assert vault.meta["outcome"] == "success", (vault.meta["outcome"], m.get("fall_time"))
    assert m["feet_first"] and abs(m["rotation"] - 2 * math.pi) <= ROTATION_TOLERANCE
    assert m["peak_landing_body_weights"] <= PEAK_LANDING_LIMIT
    assert m["balanced_time_at_end"] >= BALANCED_TIME and m["bow_feet_moved"] < NO_STEP


def test_only_his_hands_touch_the_horse_and_no_shoulder_or_wrist_servo_acts_there(vault):
    """TARGETS.md V5's torque clause, per frame off the file."""
    m = vault.meta["metrics"]
    assert not m["horse_fault"] and set(m["horse_bodies"]) <= {"HANDR", "HANDL", "LARMR", "LARML"}
    v5 = servos_on_horse(vault)
    assert v5["frames"] > 0 and v5["active_frames"] == 0


def test_his_vault_replays_bit_for_bit(vault):
    assert largest_difference(vault, replay(vault)) == 0.0


def test_a_run_up_speed_outside_his_range_is_refused(his):
    low, high = his.handled_speed
    with pytest.raises(ParameterError, match=rf"runup_speed=6.75 m/s is outside .* allowed range is \[{low:g}, {high:g}\]"):
        run(RunRequest("vault", "man", params={"runup_speed": 6.75}, duration=0.1))


def test_the_child_is_refused_in_one_line():
    with pytest.raises(ParameterError, match=r"^the child has no vault settings with human torque limits"):
        run(RunRequest("vault", "child", params={"runup_speed": CONSTANTS.handled_speed[0]}, duration=0.1))


def test_his_default_request_vaults_at_the_middle_of_his_range(his):
    """The schema's run-up (6.75 m/s, hers) is outside his range: the CLI's and the panel's defaults for him
    (Vault.character_defaults) are the middle of it, so ``simulate vault --character man`` is not refused."""
    from sim_core.request import behaviour_params
    low, high = his.handled_speed
    assert low <= behaviour_params("vault", "man")["runup_speed"] <= high
    assert behaviour_params("vault", "woman")["runup_speed"] == 6.75
