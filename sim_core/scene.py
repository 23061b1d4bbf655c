"""A scene: a world plus one or more actors (a character with a behaviour, its parameters and a
placement), all in ONE MuJoCo model. This module reads and checks scene files and builds the
scene's MjSpec; sim_core.simulate runs it (``run_scene``).

File (JSON, or TOML with the same keys)::

    {"duration": 6,
     "world": {"slope": 0, "slope_axis": "x+", "floor": 0, "boxes": [[x, y, height, length, width]],
               "springboard": [x, y], "vault_table": [x, y, height, length, width],
               "landing_mat": [x, y, length, width, thickness]},
     "actors": [{"name": "a", "character": "man", "behaviour": "running", "params": {"speed": 3},
                 "position": [0, 0], "heading": 0, "strength": "human"}, ...]}

``heading`` is in DEGREES in the file (counter-clockwise from +X, [-360, 360]); ``Actor.heading``
is in radians. ``world.slope`` is in degrees too (as on the command line). Only ``name``,
``character`` and ``behaviour`` are required of an actor; ``duration`` defaults to the longest
default duration of the actors' behaviours.

Every name of an actor's character in the model is prefixed "<name>/" (its bodies, joints,
servos, sites and geoms); the world's geoms keep their names ("ground", "box0", ...).
A bad file is refused with one line naming the problem (SceneError); nothing is written.
"""
from __future__ import annotations

import dataclasses
import json
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import mujoco
import numpy as np

from .character.model import Placement, add_character, character_timestep, new_spec, place_standing
from .character.spec import CharacterSpec, load_character
from .control.behaviour import Behaviour
from .skills import behaviour_class
from .errors import SimAthleticsError
from .world import World, add_attachments, add_world
from .world.apparatus import APPARATUS_LAYOUT, check_apparatus

TOP_KEYS = ("duration", "world", "actors")
WORLD_KEYS = ("slope", "slope_axis", "floor", "boxes", *APPARATUS_LAYOUT)
ACTOR_KEYS = ("name", "character", "behaviour", "params", "position", "heading", "strength")
NAME_PATTERN = re.compile(r"[A-Za-z0-9_-]{1,32}")
START_CLEARANCE = 0.10        # m: free ground between two actors' standing footprints at the start
MAX_POSITION = 1000.0         # m from the origin
# World fields a behaviour's scene() may set; any change is a prop it asks for
PROP_FIELDS = ("platform", "platform_edge", "boxes", "floor", "slope", "slope_axis", "springboard", "vault_table",
               "landing_mat", "bicycle", "hill")


class SceneError(SimAthleticsError):
    """A scene file or scene is malformed; the message names the bad key or value."""


@dataclass
class Actor:
    name: str
    character: CharacterSpec
    behaviour: type[Behaviour]
    params: dict
    placement: Placement = field(default_factory=Placement)
    strength: str | float = "human"

    @property
    def prefix(self) -> str:
        return f"{self.name}/"


@dataclass
class Scene:
    world: World
    actors: list[Actor]
    duration: float
    prop_character: CharacterSpec | None = None     # the actor's character a prop is placed against

    def actor(self, name: str) -> Actor:
        for a in self.actors:
            if a.name == name:
                return a
        raise SceneError(f"no actor {name!r} in the scene; actors: {', '.join(a.name for a in self.actors)}")


# --------------------------------------------------------------------------------- reading
def load_scene(path: str | Path) -> Scene:
    """Read and check a scene file (.json, or .toml)."""
    path = Path(path)
    try:
        text = path.read_text()
    except OSError as exc:
        raise SceneError(f"cannot read scene file {str(path)!r}: {exc.strerror}") from None
    if path.suffix == ".toml":
        import tomllib
        try:
            data = tomllib.loads(text)
        except tomllib.TOMLDecodeError as exc:
            raise SceneError(f"scene file {str(path)!r} is not valid TOML: {exc}") from None
    else:
        try:
            data = json.loads(text)
        except json.JSONDecodeError as exc:
            raise SceneError(f"scene file {str(path)!r} is not valid JSON: {exc.msg} at line {exc.lineno}") from None
    return scene_from_dict(data)


def scene_from_dict(data) -> Scene:
    if not isinstance(data, dict):
        raise SceneError("a scene must be an object with keys duration, world, actors")
    _known(data, TOP_KEYS, "scene")
    world = _world(data.get("world", {}))
    raw_actors = data.get("actors")
    if not isinstance(raw_actors, list) or not raw_actors:
        raise SceneError("scene key 'actors' must be a non-empty list of actors")
    actors = [_actor(raw, k) for k, raw in enumerate(raw_actors)]
    names = [a.name for a in actors]
    for name in names:
        if names.count(name) > 1:
            raise SceneError(f"actor name {name!r} is used twice; every actor needs its own name")
    check_start_clearance(actors)
    duration = data.get("duration", max(a.behaviour.duration_for(a.params, a.character.name, a.strength) for a in actors))
    if isinstance(duration, bool) or not isinstance(duration, (int, float)) or not (
            math.isfinite(duration) and 0.01 <= duration <= 3600):
        raise SceneError(f"duration={duration!r} s is out of range; allowed range is [0.01, 3600] s")
    world, prop_character = merge_prop_requests(world, actors)
    scene = Scene(world, actors, float(duration), prop_character)
    control_tick(scene)                      # refuse rates that cannot share one loop
    return scene


def _known(data: dict, allowed: tuple, where: str) -> None:
    for key in data:
        if key not in allowed:
            raise SceneError(f"unknown {where} key {key!r}; allowed: {', '.join(allowed)}")


def _number(value, what: str, lo: float, hi: float, unit: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise SceneError(f"{what}={value!r} is not a number; allowed range is [{lo:g}, {hi:g}] {unit}")
    if not math.isfinite(value) or not lo <= value <= hi:
        raise SceneError(f"{what}={value!r} is out of range; allowed range is [{lo:g}, {hi:g}] {unit}")
    return float(value)


def _world(raw) -> World:
    if not isinstance(raw, dict):
        raise SceneError(f"scene key 'world' must be an object, not {raw!r}")
    _known(raw, WORLD_KEYS, "world")
    slope = math.radians(_number(raw.get("slope", 0.0), "world slope", -60, 60, "degrees"))
    axis = raw.get("slope_axis", "x+")
    if axis not in ("x+", "x-", "y+", "y-"):
        raise SceneError(f"world slope_axis={axis!r} is not one of x+, x-, y+, y-")
    if slope < 0:                                   # a negative slope rises the other way
        axis, slope = axis[0] + ("-" if axis[1] == "+" else "+"), -slope
    floor = _number(raw.get("floor", 0.0), "world floor", -5, 0, "m")
    boxes = raw.get("boxes", [])
    if not isinstance(boxes, list):
        raise SceneError(f"world boxes must be a list of [x, y, height, length, width], not {boxes!r}")
    checked = []
    for k, box in enumerate(boxes):
        if not (isinstance(box, list) and len(box) == 5):
            raise SceneError(f"world boxes[{k}]={box!r} must be [x, y, height, length, width] (m)")
        x, y = (_number(v, f"world boxes[{k}] x/y", -MAX_POSITION, MAX_POSITION, "m") for v in box[:2])
        height = _number(box[2], f"world boxes[{k}] height", floor, 5, "m")
        length, width = (_number(v, f"world boxes[{k}] length/width", 0.01, 100, "m") for v in box[3:])
        checked.append((x, y, height, length, width))
    apparatus = {}
    for name in APPARATUS_LAYOUT:
        if name in raw:
            try:
                apparatus[name] = check_apparatus(name, raw[name])
            except SimAthleticsError as exc:
                raise SceneError(f"world {exc}") from None
    return World(slope=slope, slope_axis=axis, floor=floor, boxes=tuple(checked), **apparatus)


def _actor(raw, k: int) -> Actor:
    if not isinstance(raw, dict):
        raise SceneError(f"actors[{k}] must be an object with name, character, behaviour, ...")
    _known(raw, ACTOR_KEYS, f"actor (actors[{k}])")
    for key in ("name", "character", "behaviour"):
        if key not in raw:
            raise SceneError(f"actors[{k}] has no {key!r}")
    name = raw["name"]
    if not isinstance(name, str) or not NAME_PATTERN.fullmatch(name):
        raise SceneError(f"actor name {name!r} must be 1-32 letters, digits, '_' or '-'")
    where = f"actor {name!r}"
    try:
        character = load_character(raw["character"])
        cls = behaviour_class(raw["behaviour"])
        params = raw.get("params", {})
        if not isinstance(params, dict):
            raise SceneError(f"params must be an object of name: value, not {params!r}")
        params = cls.schema.validate(params, cls.character_defaults(character.name))
    except SimAthleticsError as exc:
        raise SceneError(f"{where}: {exc}") from None
    position = raw.get("position", [0.0, 0.0])
    if not (isinstance(position, list) and len(position) == 2):
        raise SceneError(f"{where}: position={position!r} must be [x, y] (m)")
    x, y = (_number(v, f"{where} position", -MAX_POSITION, MAX_POSITION, "m") for v in position)
    heading = math.radians(_number(raw.get("heading", 0.0), f"{where} heading", -360, 360, "degrees"))
    strength = raw.get("strength", "human")
    if not (strength in ("human", "unlimited") or (
            not isinstance(strength, bool) and isinstance(strength, (int, float)) and 0.1 <= strength <= 10)):
        raise SceneError(f"{where}: strength={strength!r} must be 'human', 'unlimited' or a factor in [0.1, 10]")
    if cls.world_frame and (x, y, heading) != (0.0, 0.0, 0.0):
        raise SceneError(f"{where}: behaviour {cls.name!r} turns and aims in the world's own axes from the "
                         f"origin; put it at position [0, 0] with heading 0")
    return Actor(name, character, cls, params, Placement(x, y, heading), strength)


# --------------------------------------------------------------------------------- checks
def footprint(character: CharacterSpec) -> tuple[np.ndarray, float]:
    """(centre (x, y) in the character's own frame, radius m) of a circle holding every geom of
    the standing character seen from above (each geom's bounding sphere)."""
    spec = new_spec(f"footprint_{character.name}")
    add_character(spec, character)
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_resetData(model, data)
    place_standing(model, data, character)
    mujoco.mj_kinematics(model, data)
    centre = np.array(character.bodies[0]["com"][:2], dtype=float)
    reach = np.linalg.norm(data.geom_xpos[:, :2] - centre, axis=1) + model.geom_rbound
    return centre, float(reach.max())


def check_start_clearance(actors: list[Actor]) -> None:
    """Refuse two actors whose standing footprints come closer than START_CLEARANCE."""
    prints = {}
    for a in actors:
        if a.character.name not in prints:
            prints[a.character.name] = footprint(a.character)
    placed = []
    for a in actors:
        centre, radius = prints[a.character.name]
        placed.append((a, np.array(a.placement.point([*centre, 0.0])[:2]), radius))
    for i, (a, ca, ra) in enumerate(placed):
        for b, cb, rb in placed[i + 1:]:
            distance = float(np.linalg.norm(ca - cb))
            need = ra + rb + START_CLEARANCE
            if distance < need:
                raise SceneError(
                    f"actors {a.name!r} and {b.name!r} start {distance:.2f} m apart (footprint centres); "
                    f"their footprints ({ra:.2f} m and {rb:.2f} m radius) need at least {need:.2f} m "
                    f"({START_CLEARANCE:.2f} m clearance)")


def merge_prop_requests(world: World, actors: list[Actor]) -> tuple[World, CharacterSpec | None]:
    """The scene's world with the props every actor's behaviour asks for (``Behaviour.scene``: a
    dive's platform, a jump's boxes). A behaviour places its props in its own frame (the
    character standing at the origin facing +X), so an actor that asks for props must stand
    there; two actors asking for different values of one World field are refused."""
    merged, owner, added_boxes = {}, {}, []
    prop_character = None
    for a in actors:
        asked = a.behaviour.scene(a.params, world, a.character)
        if asked.bicycle is not None and asked.bicycle != world.bicycle:     # the actor rides the bicycle it asks for
            asked = dataclasses.replace(asked, bicycle=dataclasses.replace(asked.bicycle, rider=a.prefix))
        changed = [f for f in PROP_FIELDS if getattr(asked, f) != getattr(world, f)]
        if not changed:
            continue
        if (a.placement.x, a.placement.y, a.placement.heading) != (0.0, 0.0, 0.0):
            raise SceneError(
                f"actor {a.name!r}: behaviour {a.behaviour.name!r} asks for props ({', '.join(changed)}) placed "
                f"in its own frame; put it at position [0, 0] with heading 0")
        prop_character = prop_character or a.character
        for f in changed:
            if f == "boxes":
                added_boxes += [b for b in asked.boxes if b not in world.boxes]
                continue
            value = getattr(asked, f)
            if f in merged and merged[f] != value:
                raise SceneError(f"actors {owner[f]!r} and {a.name!r} ask for different worlds: "
                                 f"{f}={merged[f]!r} and {f}={value!r}")
            merged[f], owner[f] = value, a.name
    if added_boxes:
        merged["boxes"] = tuple(world.boxes) + tuple(added_boxes)
    return dataclasses.replace(world, **merged), prop_character


def scene_timestep(scene: Scene) -> float:
    """The one physics step of the scene's model: its actors' (character_timestep), which must agree
    (a body made by scaling has its own Fig. 6 time scale; it shares a scene only with bodies of
    the same)."""
    steps = {a.name: character_timestep(a.character) for a in scene.actors}
    first = scene.actors[0]
    for a in scene.actors[1:]:
        if steps[a.name] != steps[first.name]:
            raise SceneError(f"actor {a.name!r} ({a.character.name}) has time_scale {a.character.time_scale:g}, actor "
                             f"{first.name!r} ({first.character.name}) {first.character.time_scale:g}; one scene has "
                             f"one physics step, so its actors' time scales must be equal")
    return steps[first.name]


def control_tick(scene: Scene) -> tuple[float, dict[str, int]]:
    """The loop's control rate (Hz) and each actor's update interval in ticks. The scene ticks at
    the fastest actor's rate; every other rate must divide it (200 and 100 Hz share a 200 Hz
    loop, the 100 Hz actor updating every 2nd tick), and a tick must be whole physics steps."""
    timestep = scene_timestep(scene)
    rates = {a.name: float(a.behaviour.rate_for(a.character)) for a in scene.actors}
    fastest = max(rates.values())
    every = {}
    for name, rate in rates.items():
        ratio = fastest / rate
        if abs(ratio - round(ratio)) > 1e-9:
            raise SceneError(f"actor {name!r} runs at {rate:g} Hz, which does not divide the scene's "
                             f"{fastest:g} Hz loop; rates in one scene must divide the fastest")
        every[name] = int(round(ratio))
    steps = 1.0 / (fastest * timestep)
    if abs(steps - round(steps)) > 1e-9:
        raise SceneError(f"the scene's control rate {fastest:g} Hz is not a whole number of {timestep * 1e3:g} ms steps")
    return fastest, every


# --------------------------------------------------------------------------------- the model
def build_scene_spec(scene: Scene) -> mujoco.MjSpec:
    """One MjSpec: every actor's character, prefixed and placed, then the world's props (the world's
    geoms still come first in the model; a moving prop's body comes after the characters')."""
    spec = new_spec("sim_athletics_scene", scene_timestep(scene))
    for a in scene.actors:
        add_character(spec, a.character, {}, a.strength, prefix=a.prefix, placement=a.placement)
    add_world(spec, scene.world, scene.prop_character or scene.actors[0].character)   # a moving prop's body last
    for a in scene.actors:                   # what ties an actor to a prop (a rider to the bicycle)
        add_attachments(spec, scene.world, a.character, a.prefix)
    return spec


def compile_scene(scene: Scene) -> tuple[mujoco.MjModel, str]:
    """(model, mjcf_text); as for one character, the model is compiled from the text."""
    xml = build_scene_spec(scene).to_xml()
    return mujoco.MjModel.from_xml_string(xml), xml
