"""Adapting controllers to new bodies (issue 28 part 1, SEEDS-WAVE2.md §5.2, §8.5 S3/S5): every
controller parameter has units Fig. 6 can scale; a settings row scaled geometrically and by mass;
the seed's Fig. 5/8 experiment read off the simulation."""
import json
import math

import pytest

from sim_core.skills.running.behaviour import SpeedTable

from sim_core.adapt.experiment import CONTROLLERS, controller_for, experiment, ordering_holds
from sim_core.adapt.moved_bodies import gain_factors
from sim_core.adapt.scaling import ScaleFactors, Units, factor
from sim_core.adapt.settings import GEOMETRIC, MASS, CharacterPair, GainTarget, gain_target, scale_settings
from sim_core.character.make import between
from sim_core.character.spec import load_character
from sim_core.errors import ParameterError
from sim_core.skills import available_behaviours, behaviour_class
from sim_core.tuned import DIRECTORY
from sim_core.tuned.store import table_type



def _untagged(schema, where: str) -> list[str]:
    bad = []
    for knob in schema.parameters:
        if getattr(knob, "kind", None) == "choice":          # option names, not a quantity
            continue
        try:
            Units.parse(knob.unit)
        except (ParameterError, AttributeError, TypeError) as exc:
            bad.append(f"{where}.{knob.name} ({getattr(knob, 'unit', None)!r}: {exc})")
    return bad


def test_every_parameter_of_every_behaviour_has_units_fig6_understands():
    bad = []
    for name in available_behaviours():
        cls = behaviour_class(name)
        bad += _untagged(cls.schema, f"{name}.schema")
        bad += _untagged(cls.settings_schema, f"{name}.settings_schema")
    assert bad == [], "untagged parameters: " + "; ".join(bad)


def test_every_stored_table_setting_has_units_fig6_understands():
    available_behaviours()                       # the skills register their table row types
    bad = []
    for path in sorted(DIRECTORY.glob("*.json")):
        body = json.loads(path.read_text())
        row_type = table_type(body["skill"])
        names = sorted({n for _, row in row_type.rows(body) for n in row})
        for n in names:
            if n not in row_type.settings.by_name:
                bad.append(f"{path.name}: {n} (not in the {body['skill']} settings schema)")
        bad += [f"{path.name}: {b}" for b in _untagged(row_type.settings, body["skill"])]
    assert bad == [], "untagged table settings: " + "; ".join(bad)


@pytest.fixture(scope="module")
def man():
    return load_character("man")


@pytest.fixture(scope="module")
def running_schema():
    return behaviour_class("running").schema


@pytest.fixture(scope="module")
def woman():
    return load_character("woman")


def test_geometric_scaling_of_a_settings_row_at_half_size(man, running_schema):
    pair = CharacterPair(man, man, length=0.5)
    row = {"speed": 3.5, "start_lean": 0.35, "lookahead": 2.5, "thrust_time": 0.3, "stance_pitch": 0.1,
           "pitch_kp": 1486.0, "pitch_kd": 149.0, "turn_accel": 1.0, "idle_knee_per_speed": 0.4,
           "ground_speed_matching": -1.0, "course": "straight"}
    out = scale_settings(row, running_schema, pair, GEOMETRIC)
    expected = {"speed": 3.5 * 0.7071, "start_lean": 0.35 * 0.7071, "lookahead": 1.25, "thrust_time": 0.3,
                "stance_pitch": 0.1, "pitch_kp": 1486.0 * 0.0625, "pitch_kd": 149.0 * 0.04419,
                "turn_accel": 2.0, "idle_knee_per_speed": 0.4 * 1.414}
    for name, value in expected.items():
        assert out[name] == pytest.approx(value, rel=2e-4), name
    assert out["ground_speed_matching"] == -1.0          # the "as tuned" flag is kept, not scaled
    assert out["course"] == "straight"


def test_scaling_onto_the_same_character_changes_nothing_bit_for_bit(man, running_schema):
    pair = CharacterPair(man, man)
    row = {n: v for n, v in running_schema.defaults().items() if isinstance(v, float)}
    for mode in (GEOMETRIC, MASS):
        assert scale_settings(row, running_schema, pair, mode) == row


def test_gains_name_the_servo_they_drive(man):
    dofs = [d.name for d in man.dofs]
    assert gain_target("pitch_kp", dofs) == GainTarget("hip_r_y", "rule")
    assert gain_target("roll_kd", dofs) == GainTarget("hip_r_x", "rule")
    assert gain_target("yaw_kp", dofs) == GainTarget("hip_r_z", "rule")
    assert gain_target("twist_damping", dofs) == GainTarget("hip_r_z", "rule")
    assert gain_target("flight_hip_gain", dofs) == GainTarget("hip_r_y", "outboard")
    assert gain_target("stance_knee_gain", dofs) == GainTarget("knee_r_y", "rule")
    assert gain_target("spin_kp", dofs) == GainTarget(None)


def test_mass_scaling_of_a_stance_hip_gain_uses_the_body_about_the_hip(man, woman, running_schema):
    pair = CharacterPair(man, woman)
    out = scale_settings({"pitch_kp": 1486.0, "pitch_kd": 149.0, "speed": 3.5}, running_schema, pair, MASS)
    f = gain_factors(pair.old, pair.new, "hip_r_y", pair.length, "rule")
    assert out["pitch_kp"] == pytest.approx(1486.0 * f.inertia / pair.length)          # k' = k I'/I L^-1
    assert out["pitch_kd"] == pytest.approx(149.0 * f.inertia / math.sqrt(pair.length))  # k_v' = k_v I'/I L^-1/2
    assert out["speed"] == pytest.approx(3.5 * math.sqrt(pair.length))
    assert 0.3 < f.inertia < 0.8 and 0.85 < pair.length < 0.9        # the woman's body/hip and legs


def test_an_unknown_gain_takes_the_whole_body_ratio(man, woman):
    pair = CharacterPair(man, woman)
    schema = behaviour_class("balance").schema
    out = scale_settings({"spin_kp": 0.2}, schema, pair, MASS)
    f = pair.factors("spin_kp", MASS)
    assert f.mass == pytest.approx(woman.total_mass / man.total_mass)
    assert out["spin_kp"] == pytest.approx(0.2 * factor(Units.parse("rad/(kg m²/s)"), f))
    assert out["spin_kp"] == pytest.approx(0.2 * math.sqrt(pair.length) / f.inertia)


def test_bad_settings_and_modes_are_refused(man, running_schema):
    pair = CharacterPair(man, man)
    with pytest.raises(ParameterError, match="setting 'pitch_kq' is not in the schema"):
        scale_settings({"pitch_kq": 1.0}, running_schema, pair, MASS)
    with pytest.raises(ParameterError, match="scaling mode 'cubic' must be one of geometric, mass"):
        scale_settings({"pitch_kp": 1.0}, running_schema, pair, "cubic")
    with pytest.raises(ParameterError, match="scale factor length=-1.0 must be a finite number > 0"):
        CharacterPair(man, man, length=-1)


def test_the_scaled_running_table_is_passed_as_the_run_s_table(man, woman):
    body = between(man, woman, 0.7)
    character, params, clamped = controller_for("running", man, body, "mass")
    speeds = params["table"]["speeds"]
    assert speeds[0] == pytest.approx(2.5 * math.sqrt(CharacterPair(man, character).length), rel=1e-3)
    assert params["speed"] < 3.5 and character.dofs[0].kp != man.dofs[0].kp
    unscaled, params0, _ = controller_for("running", man, body, "unscaled")
    # the man's own table, as it is, and the experiment's request (the swing yields while accelerating)
    assert params0 == {"swing_yields": 1.0, "table": SpeedTable.load("man").to_table()}
    assert [d.kp for d in unscaled.dofs] == [d.kp for d in man.dofs]
    # Fig. 6's time step and control period: x L^1/2 in the scaled columns, the man's unscaled
    assert character.time_scale == pytest.approx(math.sqrt(CharacterPair(man, character).length), rel=1e-12)
    assert controller_for("running", man, body, "geometric")[0].time_scale == character.time_scale
    assert unscaled.time_scale == 1.0


def test_running_at_50_percent_keeps_the_seeds_ordering():
    """S5 at 50 %: the man's unscaled controller falls (6.77 s since his start keeps the hip's damping and
    the swing yields to the stance hip, docs/bodies.md); scaled ones run longer, mass-scaled longest (8 s cap:
    three short runs)."""
    trials = experiment("running", fractions=(0.5,), cap=8.0)
    times = {t.controller: t.time_before_falling for t in trials}
    print("\n50 % man -> woman, running:", times)
    assert [t.controller for t in trials] == list(CONTROLLERS)
    assert times["unscaled"] < 7.0 and ordering_holds(trials) == {0.5: True}


def test_at_70_percent_the_swing_yields_and_the_mass_scaled_body_runs_through_its_acceleration():
    """The experiment's controller has the swing yield to the stance hip while accelerating (swing_yields 1;
    docs/bodies.md, 2026-12-06): the 70 % body's mass-scaled run from a stand, which collapsed at 3.29 s with
    its stance hip at the torque limit, runs on (8 s here, 100 s measured); without it, it falls as before.
    A run with it replays bit for bit."""
    from sim_core.adapt.experiment import time_before_falling
    from sim_core.simulate import RunRequest, largest_difference, replay, run
    man = load_character("man")
    character, params, _ = controller_for("running", man, between(man, load_character("woman"), 0.7), "mass")
    assert params["swing_yields"] == 1.0
    seconds, fell = time_before_falling("running", character, params, 8.0)
    assert not fell, f"fell at {seconds:.2f} s"
    seconds, fell = time_before_falling("running", character, {**params, "swing_yields": 0.0}, 8.0)
    assert fell and seconds < 4.0, f"without the yield: {seconds:.2f} s"
    trajectory = run(RunRequest("running", character, params=params, duration=3.0))
    assert largest_difference(trajectory, replay(trajectory)) == 0.0


def test_bad_experiment_input_is_refused():
    with pytest.raises(ParameterError, match="skill 'dive' has no scaling experiment; available: balance, running"):
        experiment("dive")
    with pytest.raises(ParameterError, match="--cap=0.1 s is out of range; allowed range is \\[0.5, 600\\] s"):
        experiment("balance", cap=0.1)


def test_the_scaling_report_rewrites_its_block_and_plots(tmp_path):
    from sim_core.adapt.experiment import BEGIN, END, write_report
    out = tmp_path / "bodies.md"
    out.write_text(f"# title\n\n{BEGIN}\nold\n{END}\n\nafter\n")
    block = write_report(out, skills=("balance",), cap=1.0, fractions=(0.0, 0.7))
    text = out.read_text()
    assert text.startswith("# title") and text.endswith("after\n") and "old" not in text and block in text
    assert "| 70 % | 1.00 (no fall) | 1.00 (no fall) | 1.00 (no fall) | yes | - |" in text
    assert (tmp_path / "bodies_scaling.png").stat().st_size > 10_000
