"""Prop builders: one small function per prop, each adding named world geoms (or the world's
gravity) to an MjSpec for what ``World`` asks. ``PROP_BUILDERS`` runs them in order; a new prop
(springboard, horse, mat, bicycle) is one more function decorated with ``@prop_builder`` and a
World field that asks for it. The geoms' names are the names the trajectory's contact forces use.
"""
from __future__ import annotations

from typing import Callable

import mujoco

from .bicycle import add_bicycle, attach_rider
from .world import World

FOOT_FRICTION = 1.0        # what a foot meets on the ground, a box or a platform
CONTACT_GROUP = 1          # contype/conaffinity bit for character and world geoms
PLATFORM_HEEL_GAP = 0.02   # m: the platform's edge is this far behind the heels (or ahead of the toes)
PLATFORM_LENGTH, PLATFORM_WIDTH, PLATFORM_THICKNESS = 5.0, 2.0, 0.3     # m (FINA: >= 6 x 2 m)

PropBuilder = Callable[[mujoco.MjSpec, World, object], None]
PROP_BUILDERS: dict[str, PropBuilder] = {}


def prop_builder(name: str):
    """Register a builder ``(spec, world, character) -> None`` under ``name``; builders run in
    the order they are registered (the ground first, so its geom is the world's first)."""
    def register(builder: PropBuilder) -> PropBuilder:
        PROP_BUILDERS[name] = builder
        return builder
    return register


def add_world(spec: mujoco.MjSpec, world: World, character) -> None:
    """Every prop of ``world`` into ``spec``. ``character``: the one a prop is placed against
    (a platform's edge at its heels); the character stands at the origin facing +X."""
    for builder in PROP_BUILDERS.values():
        builder(spec, world, character)


def add_attachments(spec: mujoco.MjSpec, world: World, character, prefix: str = "") -> None:
    """What ties the character named by ``prefix`` (a scene's "<actor>/") to a prop, added once the
    character's bodies exist: a bicycle's rider attachments (body to body), if it rides it. Nothing
    for any other world or character."""
    if world.bicycle is not None and world.bicycle.rider == prefix:
        attach_rider(spec, world.bicycle, character)


def _felt(geom) -> None:
    geom.friction = [FOOT_FRICTION, 0.005, 0.0001]
    geom.contype = geom.conaffinity = CONTACT_GROUP


@prop_builder("slope")
def add_slope(spec: mujoco.MjSpec, world: World, character) -> None:
    """The slope tilts gravity (exactly a tilted plane for a flat ground): the start's gravity
    here, the ramp as logged edits in the loop."""
    spec.option.gravity = world.gravity()


@prop_builder("floor")
def add_floor(spec: mujoco.MjSpec, world: World, character) -> None:
    """The ground plane "ground" at ``world.floor`` (none on a diving platform: the platform is
    the ground)."""
    if world.platform > 0:
        return
    _felt(spec.worldbody.add_geom(name="ground", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[0, 0, 0.05],
                                  pos=[0, 0, world.floor]))


@prop_builder("platform")
def add_platform(spec: mujoco.MjSpec, world: World, character) -> None:
    """A diving platform "ground" (a box, its top at z = 0) with its edge just behind the heels
    or, facing the water, just ahead of the toes."""
    if world.platform <= 0:
        return
    sites = [c["pos"][0] for c in character.body("FOOTR")["contacts"] + character.body("TOER")["contacts"]]
    if world.platform_edge == "ahead":         # facing the water: the edge just ahead of the toes
        centre = max(sites) + PLATFORM_HEEL_GAP - PLATFORM_LENGTH / 2
    else:                                      # backwards: the edge just behind the heels
        centre = min(sites) - PLATFORM_HEEL_GAP + PLATFORM_LENGTH / 2
    _felt(spec.worldbody.add_geom(name="ground", type=mujoco.mjtGeom.mjGEOM_BOX,
                                  size=[PLATFORM_LENGTH / 2, PLATFORM_WIDTH / 2, PLATFORM_THICKNESS / 2],
                                  pos=[centre, 0, -PLATFORM_THICKNESS / 2]))


@prop_builder("water")
def add_water(spec: mujoco.MjSpec, world: World, character) -> None:
    """The water "water" under a platform: seen, not felt (the dive ends at entry)."""
    if world.platform <= 0:
        return
    water = spec.worldbody.add_geom(name="water", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[20, 20, 0.05],
                                    pos=[0, 0, -world.platform], rgba=[0.2, 0.4, 0.8, 0.5])
    water.contype = water.conaffinity = 0


@prop_builder("box")
def add_boxes(spec: mujoco.MjSpec, world: World, character) -> None:
    """Boxes "box0", "box1", ... standing on the ground, their tops at their heights."""
    for k, (x, y, height, length, width) in enumerate(world.boxes):
        half = (height - world.floor) / 2              # from the ground up to its top
        _felt(spec.worldbody.add_geom(name=f"box{k}", type=mujoco.mjtGeom.mjGEOM_BOX,
                                      size=[length / 2, width / 2, half], pos=[x, y, world.floor + half],
                                      rgba=[0.6, 0.5, 0.4, 1]))


@prop_builder("bicycle")
def add_bicycle_prop(spec: mujoco.MjSpec, world: World, character) -> None:
    """The bicycle (sim_core.world.bicycle): an articulated prop with its own free joint, its
    geoms colliding with the ground like the character's."""
    if world.bicycle is not None:
        add_bicycle(spec, world.bicycle, CONTACT_GROUP)
