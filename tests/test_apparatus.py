"""Vaulting apparatus (issue 31 part 1), measured off the simulation: the springboard's deflection
and oscillation under a rigid test mass against its spring-damper's, the man standing on the board
and on the landing mat (sinks ~4 cm) against the floor (~0), the vaulting table's top at its height,
a scene asking for all three builds with a contact-force column each, bad dimensions refused."""
import math

import mujoco
import numpy as np
import pytest

from sim_core.ballistics import GRAVITY
from sim_core.character.model import new_spec
from sim_core.errors import ParameterError
from sim_core.scene import SceneError, build_scene_spec, scene_from_dict
from sim_core.simulate import RunRequest, StartState, largest_difference, replay, run
from sim_core.world import World, add_world
from sim_core.world import apparatus as A
from sim_core.world.props import CONTACT_GROUP

TEST_MASS = 50.0                       # kg: the rigid block dropped on the board
BLOCK = np.array([0.30, 0.30, 0.20])   # m: its size
MAT = (0.0, 0.0, 3.0, 2.0, A.LANDING_MAT_THICKNESS)


def _with_block(world: World, bottom: float) -> tuple[mujoco.MjModel, mujoco.MjData]:
    """``world`` and a free rigid block at rest, its bottom ``bottom`` m above the floor at (0, 0)."""
    spec = new_spec("apparatus_test")
    add_world(spec, world, None)
    body = spec.worldbody.add_body(name="block", pos=[0, 0, bottom + BLOCK[2] / 2], mass=TEST_MASS,
                                   inertia=TEST_MASS / 12 * (BLOCK @ BLOCK - BLOCK ** 2))
    body.add_freejoint(name="block")
    geom = body.add_geom(type=mujoco.mjtGeom.mjGEOM_BOX, size=list(BLOCK / 2))
    geom.contype = geom.conaffinity = CONTACT_GROUP
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    return model, data


def _settle(model, data, seconds: float, what) -> np.ndarray:
    out = []
    for _ in range(int(round(seconds / model.opt.timestep))):
        mujoco.mj_step(model, data)
        out.append(what(data))
    return np.array(out)


def test_springboard_deflects_as_its_spring_and_oscillates_at_its_period():
    model, data = _with_block(World(springboard=(0.0, 0.0)), A.BOARD_TOP + 0.0005)
    deck = model.joint(A.PROP_BODY_PREFIX + "springboard/deflection").qposadr[0]
    q = _settle(model, data, 3.0, lambda d: d.qpos[deck])
    # static deflection: the block's weight over the stiffness (the deck's own weight is balanced at q = 0)
    static = -q[-500:].mean()
    assert static == pytest.approx(TEST_MASS * GRAVITY / A.BOARD_STIFFNESS, rel=0.01), static
    # damped period of the block on the deck vs the spring-damper's
    moving = TEST_MASS + A.BOARD_MASS
    omega = math.sqrt(A.BOARD_STIFFNESS / moving)
    zeta = A.BOARD_DAMPING / (2 * math.sqrt(A.BOARD_STIFFNESS * moving))
    expected = 2 * math.pi / (omega * math.sqrt(1 - zeta ** 2))
    swing = q[:1500] + static
    ups = np.nonzero((swing[:-1] < 0) & (swing[1:] >= 0))[0] * model.opt.timestep
    period = float(np.mean(np.diff(ups[:4])))
    assert period == pytest.approx(expected, rel=0.03), (period, expected)


def test_the_man_standing_on_the_springboard_deflects_it_by_his_weight():
    trajectory = run(RunRequest("balance", "man", duration=1.0, world=World(springboard=(0.0, 0.0)),
                                start=StartState(height=A.BOARD_TOP)))
    meta, arrays = trajectory.meta, trajectory.arrays
    column = meta["world_geoms"].index("springboard")
    force = arrays["contact_force"][-20:, :, column, 2].sum(axis=1).mean()       # on the man's bodies
    deck = arrays["qpos"][-20:, -1].mean()           # the deck's slide: the last joint (props come last)
    assert force > 900, force                        # he stands on the deck (the man weighs ~960 N)
    assert -deck == pytest.approx(force / A.BOARD_STIFFNESS, rel=0.05), (deck, force)
    assert "prop:springboard" not in trajectory.body_names        # the deck is the world's
    assert largest_difference(trajectory, replay(trajectory)) == 0.0


def _foot_sink(world: World, start: float) -> float:
    trajectory = run(RunRequest("balance", "man", duration=1.0, world=world, start=StartState(height=start)))
    feet = trajectory.arrays["support_points"][-1, :, 2]
    return start - float(feet.mean())


def test_the_man_sinks_about_4_cm_into_the_landing_mat_and_not_into_the_floor():
    floor = _foot_sink(World(), 0.0)
    mat = _foot_sink(World(landing_mat=MAT), A.LANDING_MAT_THICKNESS)
    assert abs(floor) < 0.002, floor
    assert 0.03 < mat < 0.05, mat


def test_the_vaulting_table_top_is_at_its_height():
    height = A.VAULT_TABLE_HEIGHT_WOMEN
    world = World(vault_table=(0.0, 0.0, height, A.VAULT_TABLE_LENGTH, A.VAULT_TABLE_WIDTH))
    model, data = _with_block(world, height + 0.01)
    block = model.body("block").id
    z = _settle(model, data, 1.0, lambda d: d.xpos[block][2])
    rests_at = z[-1] - BLOCK[2] / 2
    assert rests_at == pytest.approx(height, abs=0.002), rests_at


def test_a_springboard_given_its_stiffness_is_built_with_it():
    name = A.PROP_BODY_PREFIX + "springboard/deflection"
    for world, stiffness in ((World(springboard=(0.0, 0.0, 65000.0)), 65000.0),
                             (World(springboard=(0.0, 0.0)), A.BOARD_STIFFNESS)):
        model, data = _with_block(world, 1.0)
        assert model.jnt_stiffness[model.joint(name).id] == stiffness


def test_a_scene_asking_for_the_apparatus_builds_with_a_contact_column_each():
    scene = scene_from_dict({"duration": 1, "world": {
        "springboard": [2.0, 0.0], "vault_table": [4.0, 0.0, 1.25, 1.2, 0.95], "landing_mat": [7.0, 0.0, 4.0, 2.0, 0.2]},
        "actors": [{"name": "a", "character": "woman", "behaviour": "balance"}]})
    model = build_scene_spec(scene).compile()
    for name in ("springboard", "vault_table", "landing_mat"):
        assert model.geom(name).id >= 0
    assert scene.world.to_dict()["vault_table"] == [4.0, 0.0, 1.25, 1.2, 0.95]
    assert "springboard" not in World().to_dict()          # worlds without apparatus record as before


@pytest.mark.parametrize("world, message", [
    (World(vault_table=(4.0, 0.0, 3.0, 1.2, 0.95)), "vault_table height=3.0 is out of range; allowed range is [0.8, 1.6] m"),
    (World(landing_mat=(0.0, 0.0, 3.0, 2.0, 0.01)), "landing_mat thickness=0.01 is out of range"),
    (World(springboard=(1.0,)), "springboard=(1.0,) must be (x, y[, stiffness]) in m (stiffness in N/m)"),
    (World(springboard=(1.0, 0.0, 5.0)), "springboard stiffness=5.0 is out of range; allowed range is [10000, 200000] N/m"),
])
def test_bad_apparatus_dimensions_are_refused_in_one_line(world, message):
    with pytest.raises(ParameterError) as error:
        add_world(new_spec("bad"), world, None)
    assert message in str(error.value) and "\n" not in str(error.value)


def test_a_scene_with_a_bad_vault_table_is_refused_in_one_line():
    with pytest.raises(SceneError, match=r"world vault_table length=-1 is out of range; allowed range is \[0.2, 2\] m"):
        scene_from_dict({"world": {"vault_table": [4, 0, 1.25, -1, 0.95]},
                         "actors": [{"name": "a", "character": "woman", "behaviour": "balance"}]})
