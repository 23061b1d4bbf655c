"""Write a trajectory onto a rig as a new Action, F-curves filled in bulk.

The arrays come from :mod:`bake_math` (no bpy); this module only reads the rest matrices and
writes keys with ``keyframe_points.add`` + ``foreach_set`` (one call per curve, not one
``keyframe_insert`` per key). The user's previous action is stashed in the NLA; if anything fails
while the action is being filled, the half-made action is removed and nothing is assigned.
"""
from __future__ import annotations

import json

import bpy
import mujoco
import numpy as np

from . import compat
from .core import prop_motion
from .core.bake_math import BoneChannels, bake_channels
from .core.simcore import sim
from .rig import RESULT_KEY, RigError, bone_parents, rest_matrices

ACTION_KEY = "sim_athletics"
MAX_NAME = 60


def action_name(behaviour: str, params: dict, schema) -> str:
    """``balance pelvis_height=0.52 move_start=0.3``: the behaviour and the parameters that differ
    from their defaults (a choice by its option's name, a path as ``path``; the full set is
    stored on the action). Blender makes it unique."""
    defaults = schema.defaults()

    def shown(k, v) -> str:
        knob = schema.by_name.get(k)
        if knob is not None and knob.kind == "points":
            return k
        return f"{k}={knob.option(v)}" if knob is not None and knob.kind == "choice" else f"{k}={v:g}"
    changed = [shown(k, v) for k, v in params.items() if defaults.get(k) != v]
    name = " ".join([behaviour] + changed) if changed else f"{behaviour} defaults"
    return name if len(name) <= MAX_NAME else name[: MAX_NAME - 1] + "~"


def channels_for(obj: bpy.types.Object, trajectory, fps: float, start_frame: int,
                 duration: float | None = None) -> BoneChannels:
    props = set(moving_prop_bodies(trajectory))           # baked as their own objects
    names = [str(n) for n in trajectory.arrays["body_names"] if str(n) not in props]
    bones = obj.data.bones
    for n in names:
        parent = bones[n].parent
        if parent is not None and parent.name not in names:
            raise RigError(f"bone {n!r} has parent {parent.name!r}, which is not a simulated body")
    return bake_channels(trajectory.arrays, rest_matrices(obj, names), names, bone_parents(obj, names),
                         fps=fps, start_frame=start_frame, duration=duration, morph=morph_masses(trajectory, names))


def morph_masses(trajectory, names: list[str]):
    """(meta, start masses, end masses) per named body of a morphing run (its model's and the
    morph's end arrays), or None for a run whose body stays as it is."""
    end = trajectory.arrays.get(sim("edit_log").MORPH_END + "body_mass")
    if end is None:
        return None
    model = mujoco.MjModel.from_xml_string(trajectory.meta["model_xml"])
    ids = [model.body(n).id for n in names]
    return trajectory.meta, model.body_mass[ids].copy(), np.asarray(end)[ids]


def fill_fcurves(fcurves: list, frames: np.ndarray, values: list[np.ndarray]) -> None:
    """One linear key per frame on each (empty) F-curve, in bulk: one ``keyframe_points.add`` and
    ``foreach_set`` per curve (a ``keyframe_insert`` loop is 36-58x slower, docs/blender.md)."""
    n = len(frames)
    co = np.empty(2 * n, dtype=np.float32)
    co[0::2] = frames
    linear = np.full(n, compat.LINEAR, dtype=np.int32)
    for fc, v in zip(fcurves, values):
        co[1::2] = v
        points = fc.keyframe_points
        points.add(n)
        points.foreach_set("co", co)
        points.foreach_set("interpolation", linear)
        fc.update()


def write_action(obj: bpy.types.Object, ch: BoneChannels, name: str, meta: dict) -> bpy.types.Action:
    """Create the action, fill every F-curve in bulk, then stash the old action and assign."""
    curves = list(ch.fcurve_values())
    action, fcurves, slot = compat.new_action(obj, name, [(path, i, bone) for path, i, bone, _ in curves])
    try:
        fill_fcurves(fcurves, ch.frames, [values for _, _, _, values in curves])
        action[ACTION_KEY] = json.dumps(meta)
        action.use_fake_user = False
        for pb in obj.pose.bones:
            if pb.name in ch.names:
                pb.rotation_mode = "QUATERNION"
        compat.assign_action(obj, action, slot)
    except BaseException:
        bpy.data.actions.remove(action)
        raise
    obj[RESULT_KEY] = json.dumps(dict(meta, action=action.name))
    return action


def bake_trajectory(obj: bpy.types.Object, trajectory, fps: float, start_frame: int = 1,
                    duration: float | None = None) -> bpy.types.Action:
    """Trajectory -> a new action on ``obj`` named after the behaviour and its parameters."""
    meta = trajectory.meta
    schema = sim("skills").behaviour_class(meta["behaviour"]).schema
    ch = channels_for(obj, trajectory, fps, start_frame, duration)
    info = {
        "character": meta.get("character"), "behaviour": meta["behaviour"], "params": meta.get("params", {}),
        "outcome": meta.get("outcome"), "metrics": meta.get("metrics", {}), "strength": meta.get("strength", "human"),
        "fps": fps, "start_frame": start_frame, "frames": len(ch.frames),
        "frame_end": float(ch.frames[-1]), "duration": float(ch.frames[-1] - ch.frames[0]) / fps,
    }
    return write_action(obj, ch, action_name(meta["behaviour"], meta.get("params", {}), schema), info)


def scene_fps(scene) -> float:
    return scene.render.fps / scene.render.fps_base


PROP_OBJECT = "SimAthletics {}"         # a moving prop body's object, e.g. "SimAthletics bicycle_frame"


def moving_prop_bodies(trajectory) -> list[str]:
    """The bodies of the run's moving props that bake as objects: the bicycle's five, if it rode."""
    if not trajectory.meta.get("world", {}).get("bicycle"):
        return []
    n = sim("world.bicycle").NAMES
    return [n[k] for k in ("frame", "fork", "front", "rear", "crank")]


def bake_moving_props(context, armature: bpy.types.Object, trajectory, fps: float, start_frame: int = 1) -> list:
    """Each moving prop body as its own object (a simple mesh from its geoms), parented to the
    armature object (so it moves with the rider's placement) and keyed on every frame from the
    trajectory's recorded body poses (``core.prop_motion``). An existing object of that name is reused (the user
    may have restyled it) and gets the new action. A springboard's deck (a scenery object) is
    keyed with its deflection. Returns the objects."""
    names = moving_prop_bodies(trajectory)
    if not names:
        return bake_springboard(armature, trajectory, fps, start_frame)
    model = mujoco.MjModel.from_xml_string(trajectory.meta["model_xml"])
    keys = prop_motion.prop_keys(trajectory.arrays, names, fps, start_frame)
    objects = []
    for b, name in enumerate(keys.names):
        label = PROP_OBJECT.format(name)
        obj = bpy.data.objects.get(label)
        if obj is None:
            verts, faces = prop_motion.body_mesh(model, model.body(name).id)
            mesh = bpy.data.meshes.new(label)
            mesh.from_pydata([tuple(v) for v in verts], [], faces)
            mesh.update()
            obj = bpy.data.objects.new(label, mesh)
            context.scene.collection.objects.link(obj)
        obj.parent = armature
        obj.matrix_parent_inverse.identity()
        obj.rotation_mode = "QUATERNION"
        channels = [("location", i, name) for i in range(3)] + [("rotation_quaternion", i, name) for i in range(4)]
        action, fcurves, slot = compat.new_action(obj, f"{label} {trajectory.meta.get('behaviour', '')}".strip(),
                                                  channels)
        try:
            fill_fcurves(fcurves, keys.frames, [keys.location[:, b, i] for i in range(3)]
                         + [keys.rotation[:, b, i] for i in range(4)])
            compat.assign_action(obj, action, slot)
        except BaseException:
            bpy.data.actions.remove(action)
            raise
        objects.append(obj)
    return objects


SPRINGBOARD_JOINT = "prop:springboard/deflection"        # sim_core.world.apparatus


def bake_springboard(armature: bpy.types.Object, trajectory, fps: float, start_frame: int = 1) -> list:
    """The springboard's scenery object (``scenery``, drawn at rest) keyed on every frame with
    the deck's deflection as its ``delta_location`` (on top of wherever the user put it), the
    slide turned as the armature is. Returns [the object], or [] for a run without a board."""
    from .scenery import APPARATUS_NAMES
    obj = bpy.data.objects.get(APPARATUS_NAMES["springboard"])
    if obj is None or not trajectory.meta.get("world", {}).get("springboard"):
        return []
    model = mujoco.MjModel.from_xml_string(trajectory.meta["model_xml"])
    keys = prop_motion.slide_keys(trajectory.arrays, model, SPRINGBOARD_JOINT, fps, start_frame)
    offset = keys.offset @ np.array(armature.matrix_world.to_3x3()).T
    channels = [("delta_location", i, "springboard") for i in range(3)]
    action, fcurves, slot = compat.new_action(obj, f"{obj.name} {trajectory.meta.get('behaviour', '')}".strip(),
                                              channels)
    try:
        fill_fcurves(fcurves, keys.frames, [offset[:, i] for i in range(3)])
        compat.assign_action(obj, action, slot)
    except BaseException:
        bpy.data.actions.remove(action)
        raise
    return [obj]
