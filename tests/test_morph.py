"""The metamorphosis (Hodgins & Pollard 1997; docs/bodies.md, "The morph"): the man's model turned
into the woman's while he runs, measured off the simulation; the morphed model checked against the
compile of ``between``; the run replayed bit for bit from its log."""
import mujoco
import numpy as np
import pytest

from sim_core.character.make import between
from sim_core.character.model import build_mjspec, compile_model
from sim_core.character.morph import Morph, model_arrays, morph_models
from sim_core.character.spec import CharacterSpec, load_character
from sim_core.errors import ParameterError
from sim_core.simulate import RunRequest, largest_difference, replay, run
from sim_core.trajectory import Trajectory

# every array the morph sets, and those MuJoCo derives from them (mj_setConst)
COMPARED = ("body_mass", "body_pos", "body_ipos", "body_inertia", "body_iquat", "site_pos", "geom_size", "geom_pos",
            "geom_quat", "geom_aabb", "geom_rbound", "actuator_gainprm", "actuator_biasprm", "actuator_forcerange",
            "body_subtreemass", "body_invweight0", "dof_invweight0", "dof_M0", "actuator_acc0", "qpos0", "dof_length")
EXACT = 1e-12           # relative to the array's largest entry: the sums' rounding
XML_DIGITS = 1e-5       # relative: a model compiled from MJCF text keeps ~6 significant digits


def largest_relative_difference(a: mujoco.MjModel, b: mujoco.MjModel, names=COMPARED) -> dict[str, float]:
    out = {}
    for name in names:
        x, y = getattr(a, name), getattr(b, name)
        scale = max(1.0, float(np.max(np.abs(y[np.abs(y) < 1e9]))))    # the plane's 1e10 bound aside
        out[name] = float(np.max(np.abs(x - y))) / scale
    return out


@pytest.fixture(scope="module")
def man_woman():
    return load_character("man"), load_character("woman")


@pytest.mark.parametrize("fraction", [0.25, 0.5, 1.0])
def test_the_morphed_model_is_the_compile_of_between(man_woman, fraction):
    """Interpolated in place, the man's model at f is the model of between(man, woman, f), compiled
    (without the MJCF text's rounding): masses, lengths, inertias (principal moments and axes),
    shapes, contact sites, servos and the derived constants, to 1e-12 of each array's largest entry."""
    man, woman = man_woman
    model = build_mjspec(man).compile()
    morph = Morph(model, model_arrays(build_mjspec(woman).compile()))
    morph.apply(fraction)
    reference = build_mjspec(CharacterSpec(between(man, woman, fraction))).compile()
    worst = largest_relative_difference(model, reference)
    assert max(worst.values()) < EXACT, worst


def test_the_run_models_morph_to_the_between_models_within_the_mjcf_rounding(man_woman):
    """The run's models come from MJCF text (replay compiles the same text): at f = 0.5 the morphed
    run model and the compiled text of between(man, woman, 0.5) agree to the text's 6 digits; at
    f = 0 the morph gives back the man's model but for the rounding of the sums."""
    man, woman = man_woman
    model, _, morph = morph_models(man, woman)
    morph.apply(0.0)
    assert max(largest_relative_difference(model, compile_model(man)[0]).values()) < EXACT
    morph.apply(0.5)
    reference, _ = compile_model(CharacterSpec(between(man, woman, 0.5)))
    worst = largest_relative_difference(model, reference)
    assert max(worst.values()) < XML_DIGITS, worst


def test_a_morph_into_a_body_of_another_skeleton_is_refused(man_woman):
    man, _ = man_woman
    other = dict(man.data, bodies=man.data["bodies"][:-1], name="short")
    with pytest.raises(ParameterError, match="same skeleton"):
        morph_models(man, CharacterSpec(other))


@pytest.mark.parametrize("values, message", [
    ({"speed": 3.6}, r"allowed range for speed is \[2.5, 3.5\] m/s"),
    ({"speed": 3.0, "course": "turn"}, "straight ahead"),
])
def test_a_morph_is_refused_outside_what_both_run_in_one_line(values, message):
    with pytest.raises(ParameterError, match=message) as err:
        run(RunRequest("running", "man", params={"morph_to": "woman", **values}, duration=0.05))
    assert "\n" not in str(err.value)


def test_a_morph_from_another_runner_than_the_man_is_refused_in_one_line():
    with pytest.raises(ParameterError, match="measured from the man only") as err:
        run(RunRequest("running", "woman", params={"morph_to": "woman", "speed": 3.0}, duration=0.05))
    assert "\n" not in str(err.value)


def test_a_quick_morph_runs_without_a_fall_and_replays_bit_for_bit(tmp_path):
    """The man at 3 m/s turns into the woman over 6 s (from 4 s on), then runs 2 s as her: no
    fall, and the saved run replays bit for bit (the model is re-morphed from the log)."""
    traj = run(RunRequest("running", "man", params={"speed": 3.0, "morph_to": "woman", "morph_start": 4.0,
                                                    "morph_time": 6.0}, duration=12.0))
    m = traj.meta["metrics"]
    print(f"quick morph: {traj.meta['outcome']}, speed during the morph {m['speed_during_morph']:.3f} m/s, after "
          f"{m['speed_after_morph']:.3f} m/s")
    assert not m["fell"]
    assert abs(m["speed_error_during_morph"]) < 0.1 and abs(m["speed_error_after_morph"]) < 0.1
    morphs = traj.arrays["edit_field"] == traj.meta["edit_fields"].index("morph")
    assert traj.arrays["edit_value"][morphs][-1] == 1.0
    saved = Trajectory.load(traj.save(tmp_path / "morph.npz"))
    assert largest_difference(saved, replay(saved)) == 0.0


def test_the_morph_of_the_seed_runs_without_a_fall():
    """Hodgins & Pollard 1997: 20 s of morph, then 7 s as the woman (after 5 s as the man) at
    3 m/s: no fall, the mean speed within 5 % during the morph and after it."""
    traj = run(RunRequest("running", "man", params={"speed": 3.0, "morph_to": "woman"}, duration=32.0))
    m = traj.meta["metrics"]
    assert not m["fell"]
    assert abs(m["speed_error_during_morph"]) < 0.05 and abs(m["speed_error_after_morph"]) < 0.05


def test_the_ramps_offsets_are_checked_and_ride_on_the_interpolated_rows():
    """``morph_ramps`` (a tuner's candidate): the offset is reached at f = 1 on top of the woman's row
    and held in the setting's range; an unknown name or an offset wider than the range is refused."""
    from sim_core.skills.running.behaviour import SETTING_RANGES, Running, SpeedTable
    from sim_core.skills.running.morph import RAMPED, MorphTable
    bounds = {n: (SETTING_RANGES.by_name[n].minimum, SETTING_RANGES.by_name[n].maximum) for n in RAMPED}
    man, woman = SpeedTable.load("man"), SpeedTable.load("woman")
    table = MorphTable(man, woman, {"stance_pitch": 0.05, "thrust_time": 1.0}, bounds)
    assert table.at("stance_pitch", 3.0) == man.at("stance_pitch", 3.0)
    table.fraction = 1.0
    assert table.at("stance_pitch", 3.0) == pytest.approx(woman.at("stance_pitch", 3.0) + 0.05, abs=1e-12)
    assert table.at("thrust_time", 3.0) == bounds["thrust_time"][1]
    assert table.at("speed_gain", 3.0) == pytest.approx(woman.at("speed_gain", 3.0), abs=1e-12)
    for ramps, message in (({"speed_gain": 0.1}, "unknown parameter 'speed_gain'"),
                           ({"stance_pitch": 0.6}, r"allowed range is \[-0.5, 0.5\] rad"),
                           ("3", "must be an object of parameter offsets")):
        with pytest.raises(ParameterError, match=message):
            Running.schema.validate({"morph_to": "woman", "morph_ramps": ramps})


def test_the_morph_changes_the_body_never_the_state(man_woman):
    """Physical validity: the morph edits the model only; positions, velocities, controls and applied
    forces stay bit for bit what they were (its mj_setConst works on a data of its own)."""
    man, woman = man_woman
    model, _, morph = morph_models(man, woman)
    data = mujoco.MjData(model)
    rng = np.random.default_rng(3)
    data.qpos[7:] = rng.uniform(-0.2, 0.2, model.nq - 7)
    data.qpos[2] = 1.2
    data.qvel[:] = rng.normal(size=model.nv)
    data.ctrl[:] = rng.normal(size=model.nu)
    mujoco.mj_forward(model, data)
    state = {k: np.array(getattr(data, k)) for k in ("qpos", "qvel", "act", "ctrl", "xfrc_applied", "qfrc_applied")}
    morph.apply(0.7)
    assert all(np.array_equal(v, getattr(data, k)) for k, v in state.items())
