"""The script API: what the operators, the panel and the batch command call.

    from sim_athletics import api            # (blender_addon in a repository checkout)
    arm = api.add_character(bpy.context, "man")
    action, trajectory = api.simulate_and_bake(bpy.context, behaviour="balance",
                                               params={"pelvis_height": 0.52}, duration=3)

Errors a user can cause raise sim_core's ``errors.SimAthleticsError`` (bad parameter, unknown
behaviour or character) or ``rig.RigError`` (no rig, not a rig) with a one-line message, before
anything is written.
"""
from __future__ import annotations

import sys
from typing import Callable

from . import bake, rig, scenery
from .core.jobs import planned_request
from .core.simcore import sim


def parse_params(behaviour: str, params, character: str | None = None) -> dict:
    """A dict, a list of ``"name=value"`` strings, or one text ``"name=value name=value"``
    (commas or spaces), validated by the behaviour's schema: the full parameter dict, with the
    defaults filled in (a choice by its option name or number): ``character``'s where it has its
    own (sim_core.request.behaviour_params), else the schema's."""
    if isinstance(params, str):
        params = [item for item in params.replace(",", " ").split() if item]
    return sim("request").behaviour_params(behaviour, character, params)


def make_request(character: str, behaviour: str, params, duration: float | None = None, strength: str | None = None,
                 request: dict | None = None, pushes=()):
    """A validated RunRequest (raises before anything runs or is written). ``request``: values
    of the request schema (sim_core.request: start height and velocity, slope, backpack, push,
    strength, duration); ``duration`` and ``strength`` override its own."""
    values = dict(request or {})
    if duration is not None:
        values["duration"] = duration
    if strength is not None:
        values.pop("strength_factor", None)
        values["strength"] = strength
    run_request = sim("request").build_request(behaviour, character, parse_params(behaviour, params, character),
                                               values, pushes)
    run_request.validated()
    return run_request


def target_from_object(obj, target) -> dict[str, float]:
    """The jump target parameters (target_x, target_y, target_z) for a scene object (an Empty, a
    box...): its origin, in the rig's start frame, from the middle of the character's feet."""
    import numpy as np
    from .core.axes import BLENDER_TO_SIM
    local = obj.matrix_world.inverted() @ target.matrix_world.translation
    point = BLENDER_TO_SIM @ np.array(local[:3], dtype=float)
    character = sim("character.spec").load_character(str(obj[rig.CHARACTER_KEY]))
    return {k: round(v, 4) for k, v in sim("skills.jump_to_target.behaviour").target_params(character, point).items()}


def path_from_curve(context, obj, curve) -> list[list[float]]:
    """A path knob's points from a curve object: its evaluated points (modifiers and bevel-free
    resolution applied, as the viewport shows it), in the rig ``obj``'s start frame."""
    import numpy as np
    from .core.values import path_in_rig_frame
    evaluated = curve.evaluated_get(context.evaluated_depsgraph_get())
    mesh = evaluated.to_mesh()
    try:
        co = np.empty(3 * len(mesh.vertices), dtype=np.float64)
        mesh.vertices.foreach_get("co", co)
    finally:
        evaluated.to_mesh_clear()
    world = co.reshape(-1, 3) @ np.array(curve.matrix_world)[:3, :3].T + np.array(curve.matrix_world)[:3, 3]
    return path_in_rig_frame(world, np.array(obj.matrix_world))


def add_character(context, character: str = "man", location=None):
    return rig.add_character(context, character, location)


def console_progress(fraction: float) -> None:
    """Progress bar on stderr for background mode (the UI uses window_manager.progress_*)."""
    width = 30
    done = int(round(fraction * width))
    sys.stderr.write(f"\rSim Athletics: simulating [{'#' * done}{'.' * (width - done)}] {100 * fraction:5.1f}%")
    if fraction >= 1.0:
        sys.stderr.write("\n")
    sys.stderr.flush()


def simulate_and_bake(context, *, behaviour: str, params=None, duration: float | None = None,
                      armature: str | None = None, start_frame: int | None = None,
                      fit_scene_range: bool = False, target: str | None = None, strength: str | None = None,
                      request: dict | None = None, pushes=(),
                      progress: Callable[[float], None] | None = None,
                      cancelled: Callable[[], bool] | None = None):
    """Simulate ``behaviour`` on the rig's character and bake it as a new action on the rig.
    Keys land on every frame of the scene's frame rate from ``start_frame`` (default: the scene's
    start). ``target``: name of a scene object whose origin sets a jump's target parameters.
    Returns (action, trajectory). Nothing is written if validation, the run or the bake fails or
    is cancelled. ``strength``: "human" (the rig's torque limits) or "unlimited"; ``request``:
    the request schema's values (a drop height, a push, a slope...), ``pushes`` further pushes."""
    import bpy
    obj = rig.find_rig(context, armature)
    if target:
        if target not in bpy.data.objects:
            raise rig.RigError(f"target object {target!r} is not in this file")
        params = {**parse_params(behaviour, params, str(obj[rig.CHARACTER_KEY])),
                  **target_from_object(obj, bpy.data.objects[target])}
    run_request = make_request(str(obj[rig.CHARACTER_KEY]), behaviour, params, duration, strength, request, pushes)
    run_request, _ = planned_request(run_request, cancelled=cancelled)     # a landing's foot placement, planned
    trajectory = sim("simulate").run(run_request, progress=progress, cancelled=cancelled)
    action = bake_result(context, obj, trajectory, start_frame, fit_scene_range)
    return action, trajectory


def bake_result(context, obj, trajectory, start_frame: int | None = None, fit_scene_range: bool = False):
    scene = context.scene
    fps = bake.scene_fps(scene)
    start = scene.frame_start if start_frame is None else int(start_frame)
    action = bake.bake_trajectory(obj, trajectory, fps=fps, start_frame=start)
    scenery.add_scenery(context, obj, trajectory)
    bake.bake_moving_props(context, obj, trajectory, fps=fps, start_frame=start)
    if fit_scene_range:
        scene.frame_start = start
        scene.frame_end = int(round(action.frame_range[1]))
    return action
