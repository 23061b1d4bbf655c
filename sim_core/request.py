"""The run request as a schema: what a run is asked besides the behaviour's own parameters (its
length and strength, the start state, the ground, a backpack, a push), described once so that the
CLI, the Blender panel and batch bakes set it from the same source.

Angles here are in degrees, as the CLI has always taken them (``--slope 5``, ``--push 100@90``):
a panel that stores the number typed then makes exactly the CLI's run, bit for bit (a value the
panel kept in radians would come back through single precision and differ in the last bit).

    values, pushes = request_values(args)            # the CLI's / batch's flags
    request = build_request("balance", "man", params, values, pushes)
"""
from __future__ import annotations

import argparse
import math

from .errors import ParameterError
from .schema import Choice, Group, Parameter, Schema

STRENGTHS = ("human", "unlimited")
SLOPE_AXES = ("x+", "x-", "y+", "y-")

REQUEST_SCHEMA = Schema(
    Group("Run",
          Parameter("duration", "s", 0.0, 0.01, 3600.0, "seconds to simulate; 0 = the behaviour's default",
                    special=0.0),
          Choice("strength", STRENGTHS, "human", "joint torque limits of the run",
                 ("Human-plausible joint torque limits (the rig's, with their sources)",
                  "No joint torque limits, as Wooten's 1998 simulations ran")),
          Parameter("strength_factor", "1", 0.0, 0.1, 10.0,
                    "the rig's human torque limits times this factor; 0 = as strength says", special=0.0)),
    Group("Start",
          Parameter("start_height", "m", 0.0, 0.0, 20.0, "start the standing pose this many metres up (drop tests)"),
          Parameter("start_velocity_x", "m/s", 0.0, -20.0, 20.0, "start moving at this speed along +X (landing tests)"),
          Parameter("start_velocity_y", "m/s", 0.0, -20.0, 20.0, "start moving at this speed along +Y"),
          Parameter("start_velocity_z", "m/s", 0.0, -20.0, 20.0, "start moving at this speed upwards")),
    Group("Ground and load",
          Parameter("slope", "deg", 0.0, -60.0, 60.0, "ground slope in degrees (negative: falls towards slope_axis)"),
          Choice("slope_axis", SLOPE_AXES, "x+", "direction in which the ground rises"),
          Parameter("backpack", "kg", 0.0, 0.0, 40.0, "extra mass on the upper torso (CHEST1)")),
    Group("Push",
          Parameter("push_force", "N", 0.0, 0.0, 5000.0, "a sternum push of this force; 0 = no push"),
          Parameter("push_direction", "deg", 0.0, -360.0, 360.0,
                    "heading of the push in the ground plane in degrees (0 = +X, 90 = +Y: from the left)"),
          Parameter("push_start", "s", 1.0, 0.0, 1e5, "time the push starts"),
          Parameter("push_duration", "s", 0.25, 0.001, 60.0, "how long the push lasts")),
)


def _flipped(axis: str) -> str:
    """The opposite axis: a negative slope rising towards x+ is a positive one rising towards x-."""
    return axis[0] + ("-" if axis[1] == "+" else "+")


def behaviour_params(behaviour: str, character, values=None) -> dict:
    """The behaviour's full, validated parameters for ``character`` (a name, a spec file, a
    CharacterSpec, or None: the schema's defaults alone): ``values`` (a dict, or the CLI's
    "name=value" strings) over the character's defaults (Behaviour.character_defaults: the child
    leaps, unless told, to a height it is offered) over the schema's. The CLI, batch bakes and the
    add-on's script API all take their parameters from here."""
    from .character.spec import CharacterSpec, load_character
    from .skills import behaviour_class
    cls = behaviour_class(behaviour)
    if character is None:
        defaults = {}
    else:
        defaults = cls.character_defaults(character.name if isinstance(character, CharacterSpec)
                                          else load_character(character).name)
    if isinstance(values, (list, tuple)):
        return cls.schema.parse_assignments([str(v) for v in values], defaults)
    return cls.schema.validate(dict(values or {}), defaults)


def build_request(behaviour: str, character, params: dict, values: dict | None = None, pushes=()):
    """A RunRequest from the behaviour's validated ``params`` and the request ``values``
    (validated here by REQUEST_SCHEMA; missing ones take its defaults); ``pushes`` are further
    :class:`Push` es (the CLI's repeatable --push) after the schema's own push, if it has one."""
    from .character.model import World
    from .perturbation import Push
    from .simulate import RunRequest, StartState
    v = REQUEST_SCHEMA.validate(values or {})
    slope = math.radians(v["slope"])
    axis = REQUEST_SCHEMA.by_name["slope_axis"].option(v["slope_axis"])
    world = World(slope=abs(slope), slope_axis=axis if slope >= 0 else _flipped(axis),
                  extra_mass={"CHEST1": v["backpack"]} if v["backpack"] else {})
    strength = v["strength_factor"] or REQUEST_SCHEMA.by_name["strength"].option(v["strength"])
    start = StartState(height=v["start_height"],
                       velocity=(v["start_velocity_x"], v["start_velocity_y"], v["start_velocity_z"]))
    own = [Push(force=v["push_force"], direction_deg=v["push_direction"], start=v["push_start"],
                duration=v["push_duration"])] if v["push_force"] else []
    return RunRequest(behaviour, character, params=params, duration=v["duration"] or None,
                      pushes=own + list(pushes), world=world, strength=strength, start=start)


def add_request_arguments(parser: argparse.ArgumentParser, *, strength_choices: bool = False) -> None:
    """The request's command-line flags (``simulate`` and the Blender batch command)."""
    parser.add_argument("--duration", help="seconds to simulate (default: the behaviour's)")
    parser.add_argument("--push", action="append", metavar="FORCE@DIR[:START[:DURATION]]",
                        help="sternum push, e.g. 120@back:1.0:0.25 (N, direction name or degrees, s, s)")
    parser.add_argument("--slope", default="0", help="ground slope in degrees (default 0)")
    parser.add_argument("--slope-axis", default="x+", choices=list(SLOPE_AXES), help="direction in which the ground rises")
    parser.add_argument("--backpack", default="0", help="extra mass in kg on the upper torso (CHEST1)")
    parser.add_argument("--strength", default="human", choices=list(STRENGTHS) if strength_choices else None,
                        help="'human' torque limits, 'unlimited'" + ("" if strength_choices else ", or a factor"))
    parser.add_argument("--start-height", default="0", help="start the standing pose this many metres up (drop tests)")
    parser.add_argument("--start-velocity", default="0,0,0", help="start moving at VX,VY,VZ m/s (landing tests)")


def request_values(args) -> tuple[dict, list]:
    """The flags of :func:`add_request_arguments` as REQUEST_SCHEMA values (text, validated
    when the request is built) and the list of pushes."""
    from .perturbation import Push
    velocity = args.start_velocity.split(",")
    if len(velocity) != 3:
        raise ParameterError(f"--start-velocity {args.start_velocity!r} must be three numbers VX,VY,VZ in m/s")
    values = {"slope": args.slope, "slope_axis": args.slope_axis, "backpack": args.backpack,
              "start_height": args.start_height, "start_velocity_x": velocity[0],
              "start_velocity_y": velocity[1], "start_velocity_z": velocity[2]}
    if args.duration is not None:
        values["duration"] = args.duration
    if args.strength in STRENGTHS:
        values["strength"] = args.strength
    else:
        values["strength_factor"] = args.strength
    return values, [Push.parse(p) for p in args.push or []]
