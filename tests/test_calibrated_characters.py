"""A skill runs only for a character it is calibrated for (its own table); every other character
is refused before anything is simulated, with one line naming who is calibrated - another body's
settings make it fall (the woman on the man's running table fell 0.9 s into the run)."""
import pytest

from sim_core.character.spec import available_characters
from sim_core.errors import ParameterError
from sim_core.simulate import RunRequest, run
from sim_core.tuned import characters_of, exists

TABLE_OF = {"running": "running", "leap": "leap", "land": "landing", "dive": "dives", "jump_to_target": "leap",
            "somersault": "somersaults", "handspring": "handspring"}


@pytest.mark.parametrize("skill", sorted(TABLE_OF))
def test_a_skill_is_refused_for_every_character_it_is_not_calibrated_for(skill):
    table = TABLE_OF[skill]
    refused = [c for c in available_characters() if not exists(table, c)]
    assert refused, "every character has a table: nothing to refuse"
    for character in refused:
        with pytest.raises(ParameterError) as error:
            run(RunRequest(skill, character, duration=0.05))
        message = str(error.value)
        assert "\n" not in message and character in message
        assert "not calibrated" in message or "no calibrated" in message, message
        for calibrated in characters_of(table):
            assert calibrated in message or table in ("somersaults", "handspring"), message


def test_the_characters_a_table_is_for_are_its_own_files():
    assert characters_of("running") == ["child", "imaginary_runner", "man", "woman"]
    assert characters_of("leap") == ["child", "imaginary_runner", "man", "woman"]


def test_the_landings_calibration_trials_run_for_a_character_with_no_table():
    """`calibrate land` places the feet of its trials by their delta alone (landing_table=0), so a
    body with no landing table yet can be calibrated (before, the calibration deleted the table and
    its own trials were then refused), and it no longer deletes a stored table to do so."""
    import inspect

    from sim_core.skills.land import calibrate
    from sim_core.simulate import StartState
    character = next(c for c in available_characters() if not exists("landing", c))
    trajectory = run(RunRequest("land", character, params={"landing_table": 0.0, "foot_delta": 0.0},
                                start=StartState(height=0.2), duration=0.5))
    assert trajectory.meta["duration"] == pytest.approx(0.5)
    assert "tuned.delete" not in inspect.getsource(calibrate.calibrate)


def test_a_landing_starting_faster_than_its_table_serves_is_refused_in_one_line():
    """The child's landing table serves the horizontal speeds its every drop row landed (from the
    Fig. 6-scaled sweep); a faster start is refused before anything is simulated."""
    from sim_core.control.leap import landing_speeds
    from sim_core.simulate import StartState
    from sim_core.tuned import load
    low, high = landing_speeds(load("landing", "child"))
    with pytest.raises(ParameterError) as error:
        run(RunRequest("land", "child", start=StartState(height=0.2, velocity=(high + 0.5, 0.0, 0.0)), duration=0.05))
    message = str(error.value)
    assert "\n" not in message and f"[{low:+.2f}, {high:+.2f}] m/s" in message


@pytest.mark.parametrize("skill, character", [("leap", "child"), ("running", "child"), ("running", "imaginary_runner")])
def test_a_body_not_offered_a_skills_default_runs_at_its_own(skill, character):
    """The schema's default (a 0.3 m leap, running at 3.5 m/s) is outside what the child and the
    imaginary runner are offered: a request that does not set it takes the body's own default
    (Behaviour.character_defaults), which its check accepts; a value the user sets is kept."""
    from sim_core.request import behaviour_params
    from sim_core.skills import behaviour_class
    knob = {"leap": "height", "running": "speed"}[skill]
    schema_default = behaviour_class(skill).schema.by_name[knob].default
    params = behaviour_params(skill, character)
    assert params[knob] != schema_default
    assert behaviour_params(skill, "man")[knob] == schema_default
    run(RunRequest(skill, character, params=params, duration=0.05))          # not refused
    assert behaviour_params(skill, character, [f"{knob}={schema_default}"])[knob] == schema_default
    with pytest.raises(ParameterError):
        run(RunRequest(skill, character, params={knob: schema_default}, duration=0.05))


def test_a_jump_to_a_target_is_refused_for_a_body_whose_jumps_are_not_measured():
    """The child leaps (its leap table) but has no measured jumps to a target (no jump_model
    table): a jump is refused in one line naming who is measured, not searched (the search started
    from broad-jump rows the child does not have, and crashed)."""
    character = next(c for c in characters_of("leap") if not exists("jump_model", c))
    with pytest.raises(ParameterError) as error:
        run(RunRequest("jump_to_target", character, params={"target_x": 0.5}, duration=0.05))
    message = str(error.value)
    assert "\n" not in message and character in message
    assert all(c in message for c in characters_of("jump_model"))


def test_a_scenes_actor_takes_its_bodys_own_defaults():
    """A scene's child who runs without a speed runs at hers, as a one-character request does."""
    from sim_core.request import behaviour_params
    from sim_core.scene import scene_from_dict
    scene = scene_from_dict({"duration": 1, "actors": [{"name": "c", "character": "child", "behaviour": "running"}]})
    assert scene.actors[0].params["speed"] == behaviour_params("running", "child")["speed"] != 3.5
