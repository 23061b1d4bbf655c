"""Scenes: several actors in one model, each judged by its own behaviour, replayed bit for bit;
bad scene files refused with one line and nothing written."""
import dataclasses
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from sim_core.character.model import Placement
from sim_core.scene import SceneError, load_scene, merge_prop_requests, scene_from_dict
from sim_core.simulate import RunRequest, largest_difference, replay, run, run_scene
from sim_core.trajectory import Trajectory
from sim_core.world import World

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"


def _cli(*args):
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    return subprocess.run([sys.executable, "-m", "sim_core", *args], capture_output=True, text=True, env=env, cwd=ROOT)


def _yaw(quat) -> float:
    w, x, y, z = quat
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))


def test_two_runners_side_by_side_succeed_and_replay_bit_for_bit(tmp_path):
    scene = load_scene(EXAMPLES / "two_runners.json")
    trajectory = run_scene(scene)
    for actor in trajectory.meta["actors"]:
        assert actor["outcome"] == "success", (actor["name"], actor["outcome"])
        view = trajectory.actor(actor["name"])
        assert view.com[-1, 0] - view.com[0, 0] > 5.0            # ran 4 s along +X
        assert abs(view.com[-1, 1] - view.com[0, 1]) < 0.3       # in its own lane
    left, right = trajectory.actor("left"), trajectory.actor("right")
    assert np.all(left.com[:, 1] - right.com[:, 1] > 1.0)         # side by side all the way
    path = trajectory.save(tmp_path / "two.npz")
    loaded = Trajectory.load(path)
    assert largest_difference(loaded, replay(loaded)) == 0.0
    assert loaded.meta["mujoco_version"]


def test_man_balances_while_woman_leaps():
    trajectory = run_scene(load_scene(EXAMPLES / "balance_and_leap.json"))
    outcomes = {a["name"]: a["outcome"] for a in trajectory.meta["actors"]}
    assert outcomes == {"man": "success", "woman": "success"}
    assert trajectory.meta["control_rate"] == 200.0                # balance's 100 Hz updates every 2nd tick
    assert {a["name"]: a["update_every"] for a in trajectory.meta["actors"]} == {"man": 2, "woman": 1}
    woman = trajectory.actor("woman")
    assert woman.meta["metrics"]["flight_time"] > 0.1               # she left the ground
    assert not woman.ground_contact[len(woman.time) // 2:].all()   # and the contact record shows it
    man = trajectory.actor("man")
    # each actor's contact forces with the ground are its ground reaction (they never touch each
    # other), and the man standing still is carried by them
    ground = trajectory.meta["world_geoms"].index("ground")
    for view in (man, woman):
        assert np.allclose(view.contact_force[1:, :, ground].sum(axis=1), view.grf[1:], atol=1e-6)
    assert man.contact_force[-1, :, ground, 2].sum() == pytest.approx(man.meta["total_mass"] * 9.80665, rel=0.02)
    assert largest_difference(trajectory, replay(trajectory)) == 0.0


def test_actor_view_has_the_shapes_of_a_single_run_and_a_lone_actor_is_that_run():
    """A scene of one actor at the origin is the one-character run bit for bit (only the names
    carry the prefix), and its view has the same arrays and judged outcome."""
    single = run(RunRequest("balance", "man", duration=1.0))
    scene = run_scene(scene_from_dict({"duration": 1.0, "actors": [{"name": "solo", "character": "man",
                                                                      "behaviour": "balance"}]}))
    view = scene.actor("solo")
    for name in ("qpos", "qvel", "body_pos", "body_quat", "com", "com_vel", "angmom", "grf", "ground_contact",
                 "support_points", "push_force", "contact_force", "control"):
        assert view.arrays[name].shape == single.arrays[name].shape, name
        assert np.array_equal(view.arrays[name], single.arrays[name]), name
    assert view.body_names == single.body_names
    assert scene.meta["actors"][0]["metrics"] == single.meta["metrics"]
    with pytest.raises(KeyError, match="no actor 'nobody'"):
        scene.actor("nobody")


def test_single_run_records_contact_forces_with_the_ground():
    trajectory = run(RunRequest("balance", "man", duration=0.5))
    assert trajectory.meta["world_geoms"] == ["ground"]
    total = trajectory.contact_force[1:].sum(axis=(1, 2))
    assert np.allclose(total, trajectory.grf[1:], atol=1e-6)        # the ground is all the body touches
    feet = [trajectory.body_index(n) for n in ("FOOTR", "FOOTL", "TOER", "TOEL")]
    assert np.allclose(trajectory.contact_force[1:, feet].sum(axis=(1, 2)), total)


def test_a_runner_runs_along_its_heading_and_a_balancer_holds_its_heading():
    scene = scene_from_dict({"duration": 3.0, "actors": [
        {"name": "north", "character": "man", "behaviour": "running", "params": {"speed": 3}, "position": [0, 0],
         "heading": 90},
        {"name": "turned", "character": "woman", "behaviour": "balance", "position": [3, -2], "heading": -60}]})
    trajectory = run_scene(scene)
    runner, balancer = trajectory.actor("north"), trajectory.actor("turned")
    assert trajectory.meta["actors"][0]["outcome"] == "success"
    assert runner.com[-1, 1] - runner.com[0, 1] > 3.0              # along +Y ...
    assert abs(runner.com[-1, 0] - runner.com[0, 0]) < 0.3         # ... not +X
    assert trajectory.meta["actors"][1]["outcome"] == "success"
    pelvis = balancer.body_index("PELVIS")
    assert _yaw(balancer.body_quat[-1, pelvis]) == pytest.approx(math.radians(-60), abs=0.05)
    assert balancer.com[-1, :2] == pytest.approx(balancer.com[0, :2], abs=0.05)   # stands where placed


def test_a_runners_path_is_in_its_placed_frame():
    """A path's points are the actor's own (from its start, along its heading)."""
    scene = scene_from_dict({"duration": 4.0, "actors": [
        {"name": "r", "character": "man", "behaviour": "running", "position": [2, 5], "heading": 180,
         "params": {"speed": 3, "path": [[0, 0], [30, 0]]}}]})
    trajectory = run_scene(scene)
    view = trajectory.actor("r")
    assert trajectory.meta["actors"][0]["outcome"] == "success"
    assert view.com[-1, 0] < view.com[0, 0] - 4.0                  # heading 180: along -X
    assert abs(view.com[-1, 1] - 5.0) < 0.3
    assert view.meta["metrics"]["path_deviation_max"] < 0.3


def test_props_asked_for_by_a_behaviour_join_the_world():
    scene = scene_from_dict({"duration": 1.0, "actors": [
        {"name": "jumper", "character": "man", "behaviour": "jump_to_target",
         "params": {"plan_trials": 0, "target_x": 1.0, "target_z": 0.2}},
        {"name": "watcher", "character": "woman", "behaviour": "balance", "position": [0, 2.5]}]})
    assert len(scene.world.boxes) == 1 and scene.world.boxes[0][2] == pytest.approx(0.2)
    with pytest.raises(SceneError, match="'dive' turns and aims in the world's own axes from the origin"):
        scene_from_dict({"actors": [{"name": "d", "character": "man", "behaviour": "dive", "position": [1, 0]}]})
    diver = scene_from_dict({"actors": [{"name": "d", "character": "man", "behaviour": "dive"}]}).actors[0]
    moved = dataclasses.replace(diver, placement=Placement(1.0, 0.0, 0.0))
    with pytest.raises(SceneError, match="asks for props \\(platform\\) .* position \\[0, 0\\]"):
        merge_prop_requests(World(), [moved])
    # two actors asking for different worlds (both at the origin, which the clearance check would
    # refuse first: the merge is checked on its own)
    a = scene_from_dict({"actors": [{"name": "a", "character": "man", "behaviour": "dive",
                                     "params": {"platform_height": 3}}]}).actors[0]
    b = scene_from_dict({"actors": [{"name": "b", "character": "man", "behaviour": "dive",
                                     "params": {"platform_height": 5}}]}).actors[0]
    with pytest.raises(SceneError, match="actors 'a' and 'b' ask for different worlds: platform=3.0 and platform=5.0"):
        merge_prop_requests(scene_from_dict({"actors": [{"name": "x", "character": "man",
                                                          "behaviour": "balance"}]}).world, [a, b])


BAD_SCENES = [
    ({"duration": 2, "actors": [{"name": "a", "character": "man", "behaviour": "balance"}], "colour": 1},
     "unknown scene key 'colour'"),
    ({"world": {"wind": 3}, "actors": [{"name": "a", "character": "man", "behaviour": "balance"}]},
     "unknown world key 'wind'"),
    ({"actors": [{"name": "a", "character": "man", "behaviour": "balance", "speed": 1}]},
     "unknown actor (actors[0]) key 'speed'"),
    ({"actors": [{"name": "a", "character": "robot", "behaviour": "balance"}]},
     "actor 'a': unknown character 'robot'"),
    ({"actors": [{"name": "a", "character": "man", "behaviour": "fly"}]}, "actor 'a': unknown behaviour 'fly'"),
    ({"actors": [{"name": "a", "character": "man", "behaviour": "running", "params": {"speed": 30}}]},
     "actor 'a': parameter speed=30"),
    ({"actors": [{"name": "a", "character": "man", "behaviour": "balance"},
                 {"name": "a", "character": "man", "behaviour": "balance", "position": [3, 0]}]},
     "actor name 'a' is used twice"),
    ({"actors": [{"name": "a", "character": "man", "behaviour": "balance"},
                 {"name": "b", "character": "woman", "behaviour": "balance", "position": [0.4, 0.2]}]},
     "actors 'a' and 'b' start 0.43 m apart"),
    ({"duration": 0, "actors": [{"name": "a", "character": "man", "behaviour": "balance"}]}, "duration=0 s"),
    ({"actors": [{"name": "a", "character": "man", "behaviour": "balance", "heading": "north"}]},
     "heading='north' is not a number"),
    ({"actors": []}, "'actors' must be a non-empty list"),
]


@pytest.mark.parametrize("scene, message", BAD_SCENES, ids=[m for _, m in BAD_SCENES])
def test_bad_scenes_are_refused_with_one_line(scene, message):
    with pytest.raises(SceneError) as refused:
        scene_from_dict(scene)
    assert message in str(refused.value)
    assert "\n" not in str(refused.value)


@pytest.mark.parametrize("scene, message", [BAD_SCENES[0], BAD_SCENES[3], BAD_SCENES[7]],
                         ids=["unknown key", "unknown character", "overlapping starts"])
def test_cli_refuses_a_bad_scene_file_and_writes_nothing(tmp_path, scene, message):
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(scene))
    out = tmp_path / "bad.npz"
    result = _cli("simulate", "--scene", str(path), "--out", str(out))
    assert result.returncode == 2
    assert result.stderr.strip().count("\n") == 0 and message in result.stderr
    assert not out.exists()


def test_cli_simulates_and_replays_a_scene_file(tmp_path):
    out = tmp_path / "runners.npz"
    scene = tmp_path / "runners.toml"
    scene.write_text('duration = 1.0\n[[actors]]\nname = "a"\ncharacter = "man"\nbehaviour = "running"\n'
                     'params = {speed = 3}\nposition = [0, 0]\n[[actors]]\nname = "b"\ncharacter = "woman"\n'
                     'behaviour = "balance"\nposition = [0, 1.5]\nheading = 30\n')
    result = _cli("simulate", "--scene", str(scene), "--out", str(out))
    assert result.returncode == 0, result.stderr
    summary = json.loads(result.stdout.strip().splitlines()[-1])
    assert [(a["name"], a["outcome"]) for a in summary["actors"]] == [("a", "success"), ("b", "success")]
    replayed = _cli("replay", str(out))
    assert json.loads(replayed.stdout)["bit_identical"] is True
    refused = _cli("simulate", "--scene", str(scene), "--set", "speed=3")
    assert refused.returncode == 2 and "--set does not apply to --scene" in refused.stderr


def test_each_actors_servo_bank_writes_only_its_slice_and_names_resolve_through_its_prefix():
    import mujoco

    from sim_core.character.model import place_standing
    from sim_core.control.actor import ActorView
    from sim_core.control.servo import ServoBank
    from sim_core.edit_log import EditLog
    from sim_core.scene import compile_scene

    scene = scene_from_dict({"actors": [{"name": "a", "character": "man", "behaviour": "balance"},
                                        {"name": "b", "character": "woman", "behaviour": "balance",
                                         "position": [0, 2], "heading": 90}]})
    model, _ = compile_scene(scene)
    data = mujoco.MjData(model)
    for actor in scene.actors:
        place_standing(model, data, actor.character, actor.prefix, actor.placement)
    views = [ActorView.of(model, a.prefix, a.placement) for a in scene.actors]
    a, b = views
    assert a.body_id("PELVIS") == a.root and model.body(b.root).name == "b/PELVIS"
    assert a.qpos.stop == b.qpos.start and b.qpos.stop == model.nq
    assert a.actuators.stop == b.actuators.start and b.actuators.stop == model.nu
    assert data.qpos[b.root_qpos + 1] == pytest.approx(2.0 + scene.actors[1].character.bodies[0]["com"][0])
    log = EditLog()
    banks = [ServoBank(model, data, s.character, log, v) for s, v in zip(scene.actors, views)]
    data.ctrl[:] = -7.0
    banks[1].hold(np.full(len(banks[1].names), 0.25), 0.0)
    banks[1].write(0.0)
    assert np.all(data.ctrl[a.actuators] == -7.0) and np.all(data.ctrl[b.actuators] == 0.25)
    assert banks[1].names == banks[0].names                       # unprefixed, in the same order
    knee = banks[1].indices(["knee_r_y"])
    banks[1].set_gains(knee, 123.0, 4.0)
    assert model.actuator_gainprm[model.actuator("b/knee_r_y").id, 0] == 123.0
    assert model.actuator_gainprm[model.actuator("a/knee_r_y").id, 0] != 123.0


def test_rates_that_do_not_share_a_loop_are_refused():
    from sim_core.skills import behaviour_class
    from sim_core.scene import Scene, control_tick

    balance = scene_from_dict({"actors": [{"name": "a", "character": "man", "behaviour": "balance"}]}).actors[0]
    odd = type("OddRate", (behaviour_class("balance"),), {"control_rate": 150.0, "name": "odd"})
    other = dataclasses.replace(balance, name="b", behaviour=odd, placement=Placement(0.0, 3.0, 0.0))
    assert control_tick(Scene(World(), [balance], 1.0)) == (100.0, {"a": 1})
    with pytest.raises(SceneError, match="actor 'a' runs at 100 Hz, which does not divide the scene's 150 Hz loop"):
        control_tick(Scene(World(), [balance, other], 1.0))


def test_an_actor_whose_skill_ends_holds_and_is_judged_up_to_its_end():
    """A dive ends at water entry: alone the run stops there; in a scene the diver holds while the
    coach on the platform balances on, and the diver's view ends where the lone run does."""
    lone = run(RunRequest("dive", "man", duration=3.0))
    scene = run_scene(scene_from_dict({"duration": 3.0, "actors": [
        {"name": "diver", "character": "man", "behaviour": "dive"},
        {"name": "coach", "character": "woman", "behaviour": "balance", "position": [2.5, 0], "heading": 180}]}))
    diver, coach = scene.meta["actors"]
    assert scene.meta["world"]["platform"] == 10.0                 # the dive's platform, for both
    assert diver["completed"] and diver["phase_events"][-1][1] == "complete_holding"
    assert (diver["outcome"], coach["outcome"]) == ("success", "success")
    view = scene.actor("diver")
    assert view.meta["ended_early"] and view.meta["duration"] == lone.meta["duration"]
    assert len(view.time) == len(lone.time) and scene.time[-1] == pytest.approx(3.0)
    # the coach never touches the diver: the diver moves as alone, to the solver's round-off
    assert np.abs(view.qpos - lone.qpos).max() < 1e-5
    assert largest_difference(scene, replay(scene)) == 0.0
