"""Sim Athletics rigs in a scene: import one (Blender's own glTF importer), and recognise one.

A rig is an armature object with one bone per simulated body and a child skin mesh deformed by
an Armature modifier. The armature object carries ``sim_athletics_character`` (the spec it
belongs to) and ``sim_athletics_rig`` (the rig format version); bone rest frames are set from
:mod:`rig_frames` so they are the same whichever importer version made the bones.
"""
from __future__ import annotations

from pathlib import Path

import bpy
import numpy as np
from mathutils import Vector

from . import compat
from .core.rig_frames import rest_frames
from .core.simcore import sim

CHARACTER_KEY = "sim_athletics_character"
RIG_KEY = "sim_athletics_rig"
RESULT_KEY = "sim_athletics_result"
RIG_VERSION = 1


class RigError(Exception):
    """The object is not a usable Sim Athletics rig (message says why)."""


def rig_path(character: str) -> Path:
    return sim("character.spec").RIGS_DIR / f"{character}.glb"


def add_character(context, character: str, location=None) -> bpy.types.Object:
    """Import ``rigs/<character>.glb`` at ``location`` (default: the 3D cursor); return the
    armature object (active and selected). Raises SimAthleticsError for an unknown character."""
    spec = sim("character.spec").load_character(character)                 # unknown name -> UnknownNameError
    path = rig_path(spec.name)
    if not path.exists():
        raise RigError(f"rig file {path} is missing; run 'python build.py rigs'")
    before = set(bpy.data.objects)
    compat.gltf_import(str(path))
    new = [o for o in bpy.data.objects if o not in before]
    arms = [o for o in new if o.type == "ARMATURE"]
    skins = [o for o in new if o.type == "MESH" and any(m.type == "ARMATURE" for m in o.modifiers)]
    if len(arms) != 1 or len(skins) != 1:
        for o in new:
            bpy.data.objects.remove(o)
        raise RigError(f"{path.name}: expected one armature and one skin, the importer made "
                       f"{len(arms)} and {len(skins)}")
    arm, skin = arms[0], skins[0]
    for o in new:
        if o not in (arm, skin):                       # e.g. bone-shape helpers of old importers
            bpy.data.objects.remove(o)
    arm.name = spec.name
    arm.data.name = spec.name
    skin.name = f"{spec.name}_skin"
    arm[CHARACTER_KEY] = spec.name
    arm[RIG_KEY] = RIG_VERSION
    _set_rest_frames(context, arm, spec.bodies)
    arm.location = Vector(location) if location is not None else context.scene.cursor.location.copy()
    for pb in arm.pose.bones:
        pb.rotation_mode = "QUATERNION"
    for o in context.view_layer.objects:
        o.select_set(False)
    arm.select_set(True)
    context.view_layer.objects.active = arm
    return arm


def _set_rest_frames(context, arm: bpy.types.Object, bodies: list[dict]) -> None:
    """Heads, tails and rolls from the spec (the importer's own guesses differ by version).
    Editing rest bones does not move the skin: its vertices stay where the glTF put them."""
    frames = rest_frames(bodies)
    view_layer = context.view_layer
    previous = view_layer.objects.active
    view_layer.objects.active = arm
    bpy.ops.object.mode_set(mode="EDIT")
    try:
        for i, name in enumerate(frames.names):
            eb = arm.data.edit_bones[name]
            eb.use_connect = False
            eb.head = Vector(frames.heads[i])
            eb.tail = Vector(frames.tails[i])
            eb.align_roll(Vector(frames.z_axes[i]))
    finally:
        bpy.ops.object.mode_set(mode="OBJECT")
        if previous is not None and previous.name in view_layer.objects:
            view_layer.objects.active = previous


def find_rig(context, name: str | None = None) -> bpy.types.Object:
    """The armature to bake onto: the object called ``name``, else the active object, else the
    only Sim Athletics rig in the scene. Raises RigError with a message for the user."""
    if name:
        obj = bpy.data.objects.get(name)
        if obj is None:
            raise RigError(f"no object named {name!r}")
        return check_rig(obj)
    obj = context.view_layer.objects.active
    if obj is not None and obj.type == "MESH" and obj.parent is not None and obj.parent.get(CHARACTER_KEY):
        obj = obj.parent                               # the skin is selected: use its armature
    if obj is not None and (obj.type == "ARMATURE" or obj.get(CHARACTER_KEY)):
        return check_rig(obj)
    rigs = [o for o in context.scene.objects if o.type == "ARMATURE" and o.get(CHARACTER_KEY)]
    if len(rigs) == 1:
        return check_rig(rigs[0])
    if not rigs:
        raise RigError("no Sim Athletics character in the scene; add one first (Add Character)")
    raise RigError(f"{len(rigs)} Sim Athletics characters in the scene; select the one to bake onto")


def check_rig(obj: bpy.types.Object) -> bpy.types.Object:
    """Raise RigError unless ``obj`` is a Sim Athletics armature whose bones match its spec."""
    load_character = sim("character.spec").load_character
    SimAthleticsError = sim("errors").SimAthleticsError
    if obj.type != "ARMATURE":
        raise RigError(f"{obj.name!r} is a {obj.type.lower()}, not a Sim Athletics armature")
    character = obj.get(CHARACTER_KEY)
    if not character:
        raise RigError(f"armature {obj.name!r} is not a Sim Athletics rig "
                       f"(no '{CHARACTER_KEY}' property); add a character with Add Character")
    try:
        spec = load_character(str(character))
    except SimAthleticsError as exc:
        raise RigError(f"armature {obj.name!r}: {exc}") from None
    bones = set(obj.data.bones.keys())
    missing = [b for b in spec.body_names if b not in bones]
    if missing:
        raise RigError(f"armature {obj.name!r} lacks bones for bodies {', '.join(missing[:5])}"
                       f"{' ...' if len(missing) > 5 else ''} of character {character!r}")
    return obj


def rest_matrices(obj: bpy.types.Object, names: list[str]) -> np.ndarray:
    """(B, 4, 4) ``Bone.matrix_local`` (armature space) of the named bones, read in bulk."""
    bones = obj.data.bones
    flat = np.empty(len(bones) * 16, dtype=np.float32)
    bones.foreach_get("matrix_local", flat)
    every = flat.reshape(-1, 4, 4).transpose(0, 2, 1).astype(float)   # stored column-major
    index = {b.name: i for i, b in enumerate(bones)}
    return every[[index[n] for n in names]]


def bone_parents(obj: bpy.types.Object, names: list[str]) -> list[int]:
    index = {n: i for i, n in enumerate(names)}
    return [index[obj.data.bones[n].parent.name] if obj.data.bones[n].parent else -1 for n in names]
