"""The one place for Blender API differences between the versions we support.

* Actions: up to 4.3 an Action owns a flat list of F-curves (``action.fcurves.new``). From 4.4
  Actions are layered: F-curves live in a channelbag of a keyframe strip of a layer, one
  channelbag per *slot*, and an animated ID names the slot it uses
  (``animation_data.action_slot``); 5.0 removed the flat ``action.fcurves``.
* Extensions (4.2+) are installed from a zip with ``blender_manifest.toml`` and bundled wheels;
  3.4 installs a legacy add-on zip (``bl_info``). Only packaging differs (see build.py); the
  add-on's code is the same.
* The glTF importer grew options over the versions (``disable_bone_shape`` in 4.x); we pass only
  the ones the running importer has.
"""
from __future__ import annotations

import bpy

LAYERED_ACTIONS = "layers" in bpy.types.Action.bl_rna.properties and "slots" in bpy.types.Action.bl_rna.properties
STASH_TRACK = "[Action Stash]"          # the name Blender's own "Stash" gives the NLA track
LINEAR = 1                              # index of 'LINEAR' in Keyframe.interpolation's enum


def new_action(obj: bpy.types.Object, name: str, channels: list[tuple[str, int, str]]):
    """Create an Action for ``obj`` with one empty F-curve per (data_path, index, group).
    Returns (action, fcurves, slot-or-None). Nothing is assigned to ``obj`` yet."""
    action = bpy.data.actions.new(name)
    try:
        if LAYERED_ACTIONS:
            slot = action.slots.new(id_type="OBJECT", name=obj.name)
            strip = action.layers.new("Layer").strips.new(type="KEYFRAME")
            bag = strip.channelbag(slot, ensure=True)
            curves = [bag.fcurves.new(path, index=index, group_name=group) for path, index, group in channels]
            return action, curves, slot
        action.id_root = "OBJECT"
        curves = [action.fcurves.new(path, index=index, action_group=group) for path, index, group in channels]
        return action, curves, None
    except Exception:
        bpy.data.actions.remove(action)
        raise


def action_fcurves(action: bpy.types.Action) -> list:
    """Every F-curve of an action, legacy or layered."""
    if LAYERED_ACTIONS:
        return [fc for layer in action.layers for strip in layer.strips
                for bag in getattr(strip, "channelbags", []) for fc in bag.fcurves]
    return list(action.fcurves)


def assign_action(obj: bpy.types.Object, action: bpy.types.Action, slot=None) -> str | None:
    """Make ``action`` the object's active action. A previous action is kept: stashed in a muted
    NLA track, as Blender's own "Stash" does. Returns the stashed action's name, if any."""
    anim = obj.animation_data or obj.animation_data_create()
    previous = anim.action
    stashed = None
    if previous is not None and previous != action:
        track = anim.nla_tracks.new()
        track.name = STASH_TRACK
        start = int(previous.frame_range[0])
        track.strips.new(previous.name, start, previous)
        track.mute = True
        stashed = previous.name
        anim.action = None
    anim.action = action
    if slot is not None and LAYERED_ACTIONS:
        anim.action_slot = slot
    return stashed


def gltf_import(filepath: str) -> None:
    """Blender's glTF importer with the options this version has. The 3.4 importer still uses
    ``numpy.bool``, which numpy 1.24 removed: if the numpy in use lacks it, the alias is lent
    for the duration of the import only."""
    import numpy
    props = bpy.ops.import_scene.gltf.get_rna_type().properties.keys()
    options = {"disable_bone_shape": True} if "disable_bone_shape" in props else {}
    lend_bool = "bool" not in numpy.__dict__
    if lend_bool:
        numpy.bool = bool
    try:
        bpy.ops.import_scene.gltf(filepath=filepath, **options)
    finally:
        if lend_bool:
            del numpy.bool
