"""Schema validation, the CLI's answers to bad input, servo smoothing and the replay log."""
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from sim_core.skills import available_behaviours, behaviour_class
from sim_core.control.servo import hermite_blend
from sim_core.errors import ParameterError
from sim_core.perturbation import Push
from sim_core.simulate import RunRequest, largest_difference, replay, run
from sim_core.trajectory import Trajectory

ROOT = Path(__file__).resolve().parents[1]


def cli(*args, cwd=ROOT):
    return subprocess.run([sys.executable, "-m", "sim_core", *args], cwd=cwd, capture_output=True, text=True)


def test_every_parameter_is_documented():
    for name in available_behaviours():
        for p in behaviour_class(name).schema.parameters:
            assert p.help and p.unit
            if p.kind == "choice":
                assert len(p.options) >= 2 and p.default_option in p.options
            elif p.kind != "points":
                assert p.minimum < p.maximum
                assert p.minimum <= p.default <= p.maximum or p.default == p.special


@pytest.mark.parametrize("value, message", [
    ("nan", "pelvis_height=nan is not finite; allowed range for pelvis_height is [0.2, 1.2] m"),
    ("abc", "pelvis_height='abc' is not a number; allowed range"),
    ("5", "pelvis_height=5 m is out of range; allowed range for pelvis_height is [0.2, 1.2] m"),
])
def test_schema_errors_name_value_and_range(value, message):
    schema = behaviour_class("balance").schema
    with pytest.raises(ParameterError) as err:
        schema.parse_assignments([f"pelvis_height={value}"])
    assert message in str(err.value)


def test_a_count_must_be_a_whole_number():
    schema = behaviour_class("somersault").schema
    assert schema.validate({"flight_step_division": 8})["flight_step_division"] == 8.0
    with pytest.raises(ParameterError, match=r"flight_step_division=2.5 must be a whole number; allowed range .* \[1, 8\] count"):
        schema.parse_assignments(["flight_step_division=2.5"])


def test_unknown_parameter():
    with pytest.raises(ParameterError, match="unknown parameter 'height'"):
        behaviour_class("balance").schema.validate({"height": 1})


@pytest.mark.parametrize("args, message", [
    (["simulate", "balanc"], "unknown behaviour 'balanc'; available: balance"),
    (["simulate", "balance", "--character", "robot"], "unknown character 'robot'; available: child, imaginary_cyclist, imaginary_runner, man, woman"),
    (["simulate", "balance", "--set", "torso_pitch=3"], "torso_pitch=3 rad is out of range; allowed range"),
    (["simulate", "balance", "--set", "pelvis_height=nan"], "pelvis_height=nan is not finite"),
    (["simulate", "balance", "--set", "com_kp=high"], "com_kp='high' is not a number"),
    (["simulate", "balance", "--duration", "-1"], "duration=-1 s is out of range"),
    (["simulate", "balance", "--push", "100@sideways"], "--push '100@sideways' must look like"),
    (["simulate", "balance", "--set", "pelvis_height=0.31"], "pelvis_height=0.31 m is out of reach for man"),
])
def test_cli_bad_input_one_line_nonzero_no_file(tmp_path, args, message):
    out = tmp_path / "run.npz"
    result = cli(*args, "--out", str(out))
    assert result.returncode == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and message in lines[0], result.stderr
    assert not out.exists() and list(tmp_path.iterdir()) == []


def test_cli_malformed_rig_file(tmp_path):
    rig = tmp_path / "bad.json"
    rig.write_text('{"format": "sim_athletics.character", "version": 1, "bodies": [{"name": "A"}]}')
    result = cli("simulate", "balance", "--character", str(rig), "--out", str(tmp_path / "x.npz"))
    assert result.returncode == 2 and "has no 'mass'" in result.stderr
    assert not (tmp_path / "x.npz").exists()


def test_cli_list_describe():
    listing = cli("list")
    assert listing.returncode == 0 and "balance" in listing.stdout and "woman" in listing.stdout
    schema = json.loads(cli("describe", "balance").stdout)
    names = [p["name"] for p in schema["parameters"]]
    assert {"pelvis_height", "torso_pitch", "com_offset_x", "com_offset_y"} <= set(names)


def test_hermite_has_zero_end_slopes():
    s = np.linspace(0, 1, 1001)
    h = hermite_blend(s)
    slope = np.gradient(h, s)
    assert h[0] == 0 and h[-1] == 1 and abs(slope[0]) < 1e-2 and abs(slope[-1]) < 1e-2
    assert np.all(np.diff(h) >= 0)


def test_servo_targets_never_step():
    """Control targets change by small increments per 10 ms tick during a knee bend."""
    traj = run(RunRequest("balance", "man", params=dict(pelvis_height=0.6, move_time=1.0), duration=3.0))
    knee = traj.meta["dof_names"].index("knee_r_y")
    steps = np.abs(np.diff(traj.arrays["control"][:, knee]))
    assert steps.max() < 0.06                   # < 3.5 degrees per tick


def test_replay_of_a_pushed_run_is_bit_identical(tmp_path):
    push = Push(force=80.0, direction_deg=180.0, start=1.0, duration=0.25)
    traj = run(RunRequest("balance", "man", params=dict(pelvis_height=0.7), pushes=[push], duration=5.0))
    path = traj.save(tmp_path / "pushed.npz")
    loaded = Trajectory.load(path)
    assert largest_difference(loaded, replay(loaded)) == 0.0
    result = cli("replay", str(path))
    assert result.returncode == 0
    assert json.loads(result.stdout.strip().splitlines()[-1])["largest_difference"] == 0.0


def test_trajectory_file_contents(tmp_path):
    traj = run(RunRequest("balance", "woman", duration=0.5))
    path = traj.save(tmp_path / "t.npz")
    with np.load(path, allow_pickle=False) as f:
        n = len(f["time"])
        assert f["qpos"].shape == (n, 54) and f["qvel"].shape == (n, 53)
        assert f["body_pos"].shape == (n, 22, 3) and f["body_quat"].shape == (n, 22, 4)
        assert f["com"].shape == (n, 3) and len(f["body_names"]) == 22
        assert f["control"].shape[1] == 47 and f["initial_state"].ndim == 1
        meta = json.loads(str(f["meta"]))
    for key in ("model_xml", "character", "behaviour", "params", "outcome", "metrics"):
        assert key in meta
    assert meta["model_xml"].startswith("<mujoco")
    np.testing.assert_allclose(np.linalg.norm(traj.arrays["body_quat"], axis=2), 1.0, atol=1e-9)


def test_only_external_force_is_the_logged_push():
    """The edit log holds xfrc_applied entries only for the push, on the sternum, and nothing
    else ever writes a force: no run without a push has any applied force."""
    quiet = run(RunRequest("balance", "man", duration=1.0))
    xfrc = quiet.meta["edit_fields"].index("push_force")
    assert not np.any(quiet.arrays["edit_field"] == xfrc)
    assert not np.any(quiet.arrays["push_force"])
    pushed = run(RunRequest("balance", "man", pushes=[Push(50.0, 90.0, 0.5, 0.25)], duration=1.5))
    a = pushed.arrays
    rows = a["edit_field"] == xfrc
    sternum_row = [str(n) for n in a["body_names"]].index("STERNUM") + 1      # +1: the world body
    assert set((a["edit_index"][rows] // 6).tolist()) == {sternum_row}
    on = np.nonzero(np.linalg.norm(a["push_force"], axis=1))[0]
    assert math.isclose(len(on) / pushed.meta["control_rate"], 0.25, abs_tol=1e-9)
    np.testing.assert_allclose(a["push_force"][on[0]], [0.0, 50.0, 0.0], atol=1e-9)


def test_source_never_writes_forces_outside_the_push_module():
    offenders = []
    for path in (ROOT / "sim_core").rglob("*.py"):
        text = path.read_text()
        if path.name in ("perturbation.py", "edit_log.py", "simulate.py", "analysis.py"):
            continue
        if "xfrc_applied" in text or "qfrc_applied" in text:
            offenders.append(path.name)
    assert offenders == []


def test_gain_changes_and_hermite_moves_replay_bit_for_bit():
    """A behaviour that changes servo gains per state and moves targets along Hermite curves:
    every gain change is in the edit log, and the replay reproduces the run exactly."""
    from sim_core.control.balance import Balance
    from sim_core.control.behaviour import REGISTRY

    class SoftKnees(Balance):
        name = "_test_soft_knees"

        def update(self, t):
            super().update(t)
            servos = self.ctx.servos
            knees = servos.indices(["knee_r_y", "knee_l_y"])
            if abs(t - 1.0) < 1e-9:
                servos.set_gains(knees, servos.default_kp[knees] * 0.5, servos.default_kv[knees] * 0.5)
            if abs(t - 2.0) < 1e-9:
                servos.set_gains(knees, servos.default_kp[knees], servos.default_kv[knees])

    REGISTRY[SoftKnees.name] = SoftKnees
    try:
        traj = run(RunRequest(SoftKnees.name, "man", duration=3.0))
    finally:
        del REGISTRY[SoftKnees.name]
    field = traj.meta["edit_fields"].index("actuator_gainprm")
    ticks = traj.arrays["edit_tick"][traj.arrays["edit_field"] == field]
    assert sorted(set(ticks.tolist())) == [100, 200]            # 10 ms ticks: t = 1 s and 2 s
    assert largest_difference(traj, replay(traj)) == 0.0


def test_servo_bank_hermite_move():
    from sim_core.character.model import compile_model, set_standing_pose
    from sim_core.character.spec import load_character
    from sim_core.control.servo import ServoBank
    from sim_core.edit_log import EditLog
    import mujoco
    spec = load_character("man")
    model, _ = compile_model(spec)
    data = mujoco.MjData(model)
    set_standing_pose(model, data, spec)
    bank = ServoBank(model, data, spec, EditLog())
    knee = bank.indices(["knee_r_y"])
    bank.move_to(knee, 1.0, duration=0.5, t=0.0)
    values = [bank.smoothed_target(t)[knee][0] for t in np.linspace(0, 0.6, 61)]
    assert values[0] == pytest.approx(0.0) and values[50] == pytest.approx(1.0) and values[-1] == 1.0
    assert values[25] == pytest.approx(0.5)


def test_a_diverging_simulation_is_reported_not_reset(monkeypatch):
    """MuJoCo silently resets a diverging state (a teleport); the run must stop with an error.
    The divergence is made on purpose: the thrust's servo gains get negative damping."""
    from sim_core.control.servo import ServoBank
    from sim_core.simulate import UnstableSimulation
    original = ServoBank.set_gains
    monkeypatch.setattr(ServoBank, "set_gains", lambda self, idx, kp, kv: original(self, idx, kp, -50.0 * kv))
    with pytest.raises(UnstableSimulation, match="numerically unstable at t=1.1"):
        run(RunRequest("leap", "man", params=dict(low_level=1, crouch_height=0.58, crouch_pitch=0.0), duration=2.5))
