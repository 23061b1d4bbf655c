"""Schema kinds (choice, points, group) and the request schema: the CLI takes option names (and
the old numbers), errors name the allowed options, the request flags build the same request as
the values of the request schema."""
import json
import math
import subprocess
import sys
from pathlib import Path

import pytest

from sim_core.skills import behaviour_class
from sim_core.errors import ParameterError
from sim_core.request import REQUEST_SCHEMA, build_request
from sim_core.schema import Choice, Group, Parameter, Points, Schema

ROOT = Path(__file__).resolve().parents[1]

CHOICES = [("dive", "group", ("inward", "back", "forward", "reverse")),
           ("dive", "position", ("layout", "pike", "tuck")),
           ("running", "course", ("straight", "turn", "figure_eight", "circle")),
           ("somersault", "direction", ("backward", "forward"))]


@pytest.mark.parametrize("behaviour, name, options", CHOICES)
def test_coded_knobs_are_choices_whose_names_give_the_old_codes(behaviour, name, options):
    schema = behaviour_class(behaviour).schema
    knob = schema.by_name[name]
    assert knob.kind == "choice" and knob.options == options
    for code, option in enumerate(options):
        assert schema.parse_assignments([f"{name}={option}"])[name] == float(code)     # what the behaviour reads
        assert schema.parse_assignments([f"{name}={code}"])[name] == float(code)       # the old numbers still work
        assert schema.validate({name: option.upper()})[name] == float(code)
        assert knob.option(float(code)) == option


@pytest.mark.parametrize("value", ["sideways", "1.5", "7", "-1", "nan"])
def test_a_bad_choice_names_the_allowed_options(value):
    with pytest.raises(ParameterError) as err:
        behaviour_class("dive").schema.parse_assignments([f"group={value}"])
    message = str(err.value)
    assert f"group={value}" in message or f"group='{value}'" in message
    assert "allowed options for group are inward, back, forward, reverse" in message


def test_defaults_are_unchanged_codes():
    assert behaviour_class("dive").schema.defaults()["group"] == 0.0
    assert behaviour_class("dive").schema.defaults()["position"] == 1.0
    assert behaviour_class("somersault").schema.defaults()["direction"] == 1.0
    assert behaviour_class("running").schema.defaults()["course"] == 0.0
    assert "path" not in behaviour_class("running").schema.defaults()


def test_points_are_parsed_cleaned_and_absent_unless_given():
    schema = behaviour_class("running").schema
    assert schema.by_name["path"].kind == "points"
    values = schema.parse_assignments(["path=0,0; 5,0; 5,0; 10,2"])
    assert values["path"] == [[0.0, 0.0], [5.0, 0.0], [10.0, 2.0]]           # the repeated point merged
    assert "path" not in schema.validate({"path": []})
    with pytest.raises(ParameterError, match="parameter path has a point that is not finite"):
        schema.validate({"path": [[0, 0], [float("nan"), 1]]})


def test_groups_head_their_knobs_in_the_panel_and_docs():
    schema = Schema(Parameter("a", "m", 1.0, 0.0, 2.0, "first"),
                    Group("Landing", Choice("b", ("x", "y"), "y", "second"), Points("c", "third")))
    assert [p.name for p in schema.parameters] == ["a", "b", "c"]
    assert schema.groups == [(None, (schema.by_name["a"],)), ("Landing", (schema.by_name["b"], schema.by_name["c"]))]
    assert schema.defaults() == {"a": 1.0, "b": 1.0}
    assert "| **Landing** | | | | |" in schema.markdown()
    assert [row.get("group") for row in schema.to_json_dict()] == [None, "Landing", "Landing"]


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "sim_core", *args], cwd=ROOT, capture_output=True, text=True)


def test_cli_takes_option_names_and_describe_lists_options_and_the_request():
    described = json.loads(_cli("describe", "somersault").stdout)
    direction = next(p for p in described["parameters"] if p["name"] == "direction")
    assert direction["options"] == ["backward", "forward"] and direction["default"] == "forward"
    assert {"start_height", "slope", "push_force", "backpack"} <= {p["name"] for p in described["request"]}
    bad = _cli("simulate", "somersault", "--set", "direction=sideways")
    assert bad.returncode == 2
    assert "allowed options for direction are backward, forward" in bad.stderr


def test_request_schema_builds_what_the_cli_flags_build():
    from types import SimpleNamespace
    from sim_core.request import request_values
    args = SimpleNamespace(duration="2", push=["100@forward:0.5:0.25"], slope="-5", slope_axis="y+",
                           backpack="4", strength="1.5", start_height="0.3", start_velocity="0.5,0,-1")
    values, pushes = request_values(args)
    request = build_request("balance", "man", {}, values, pushes)
    assert request.duration == 2.0 and request.strength == 1.5
    assert request.world.slope == pytest.approx(math.radians(5)) and request.world.slope_axis == "y-"
    assert request.world.extra_mass == {"CHEST1": 4.0}
    assert request.start.height == 0.3 and request.start.velocity == (0.5, 0.0, -1.0)
    assert [p.force for p in request.pushes] == [100.0]
    # the same request from schema values (the panel's way): a drop height, a push, a slope
    panel = build_request("balance", "man", {}, {"start_height": 0.3, "push_force": 100, "push_direction": 0,
                                                 "push_start": 0.5, "push_duration": 0.25, "slope": -5,
                                                 "slope_axis": "y+", "backpack": 4, "duration": 2,
                                                 "strength_factor": 1.5,
                                                 "start_velocity_x": 0.5, "start_velocity_z": -1})
    assert panel == request


def test_request_values_are_checked_with_their_range():
    with pytest.raises(ParameterError, match=r"slope=70 deg is out of range; allowed range for slope is \[-60, 60\] deg"):
        build_request("balance", "man", {}, {"slope": "70"})
    with pytest.raises(ParameterError, match="allowed options for slope_axis are x\\+, x-, y\\+, y-"):
        build_request("balance", "man", {}, {"slope_axis": "z+"})
    assert REQUEST_SCHEMA.validate({})["duration"] == 0.0
