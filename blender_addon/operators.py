"""Operators: Add Character, Simulate & Bake. Usable from the panel and from Python:

    bpy.ops.sim_athletics.add_character(character="man")
    bpy.ops.sim_athletics.simulate_bake(behaviour="balance", params="pelvis_height=0.52", duration=3)

A property left unset when called from Python falls back to the panel's setting
(``scene.sim_athletics``). ``params`` is merged over the panel's values for that behaviour.
Interactively, Simulate & Bake runs the simulation in a worker thread under a modal operator:
progress in the status bar, ESC cancels and nothing is written. From Python or in background
mode it runs to the end in the call (progress on the console).
"""
from __future__ import annotations

import bpy
from bpy.props import EnumProperty, FloatProperty, IntProperty, StringProperty

from . import api, compat, props, rig
from .job import SimulationJob


def _user_errors():
    from sim_core.errors import SimAthleticsError
    return (SimAthleticsError, rig.RigError)


class SIMATHLETICS_OT_add_character(bpy.types.Operator):
    """Import a Sim Athletics character (armature + skin) at the 3D cursor"""
    bl_idname = "sim_athletics.add_character"
    bl_label = "Add Character"
    bl_options = {"REGISTER", "UNDO"}

    character: EnumProperty(name="Character", items=props._character_items)

    def execute(self, context):
        settings = context.scene.sim_athletics
        character = self.character if self.properties.is_property_set("character") else settings.character
        try:
            arm = api.add_character(context, character)
        except _user_errors() as exc:
            self.report({"ERROR"}, str(exc))
            return {"CANCELLED"}
        self.report({"INFO"}, f"Added {arm.name} ({len(arm.data.bones)} bones)")
        return {"FINISHED"}


class SIMATHLETICS_OT_simulate_bake(bpy.types.Operator):
    """Simulate the behaviour on the character and bake it into a new action"""
    bl_idname = "sim_athletics.simulate_bake"
    bl_label = "Simulate & Bake"
    bl_options = {"REGISTER", "UNDO"}

    behaviour: StringProperty(name="Behaviour", description="Behaviour name (unset: the panel's)")
    params: StringProperty(name="Parameters",
                           description="name=value pairs merged over the panel's values, e.g. 'pelvis_height=0.52'")
    duration: FloatProperty(name="Duration", min=0.0, description="Seconds to simulate (unset or 0: the panel's)")
    strength: StringProperty(name="Strength", description="'human' or 'unlimited' torque limits (unset: the panel's)")
    start_frame: IntProperty(name="Start frame", description="Frame of the first key (unset: the panel's)")
    armature: StringProperty(name="Armature", description="Rig to bake onto (unset: the active one)")

    _job: SimulationJob | None = None
    _timer = None

    # -- the request, from the operator's properties or the panel's settings

    def _settings(self, context) -> dict:
        settings = context.scene.sim_athletics
        is_set = self.properties.is_property_set
        behaviour = self.behaviour if is_set("behaviour") and self.behaviour else settings.behaviour
        params = props.panel_params(settings, behaviour) if hasattr(settings, props.group_attr(behaviour)) else {}
        if is_set("params") and self.params.strip():
            params.update(api.parse_params(behaviour, self.params))
            params = api.parse_params(behaviour, params)
        duration = self.duration if is_set("duration") and self.duration > 0 else settings.duration
        return {
            "behaviour": behaviour, "params": params, "target": settings.target_object, "duration": duration if duration > 0 else None,
            "strength": self.strength if is_set("strength") and self.strength else settings.strength,
            "start_frame": self.start_frame if is_set("start_frame") else settings.start_frame,
            "armature": self.armature if is_set("armature") and self.armature else None,
            "fit_scene_range": settings.fit_scene_range,
        }

    def _prepare(self, context):
        """Validate everything before simulating: (rig object, request, settings)."""
        s = self._settings(context)
        obj = rig.find_rig(context, s["armature"])
        if s["target"] is not None and props.takes_target(s["behaviour"]):
            s["params"] = api.parse_params(s["behaviour"], {**s["params"], **api.target_from_object(obj, s["target"])})
        request = api.make_request(str(obj[rig.CHARACTER_KEY]), s["behaviour"], s["params"], s["duration"],
                                   s["strength"])
        return obj, request, s

    def _finish(self, context, obj, trajectory, s):
        action = api.bake_result(context, obj, trajectory, s["start_frame"], s["fit_scene_range"])
        outcome = trajectory.meta.get("outcome")
        self.report({"INFO"} if outcome == "success" else {"WARNING"},
                    f"Baked {action.name!r}: {key_count(action)} frames, outcome {outcome}")
        return {"FINISHED"}

    # -- blocking (Python, background)

    def execute(self, context):
        from sim_core.simulate import run
        wm = context.window_manager
        try:
            obj, request, s = self._prepare(context)
            progress = api.console_progress if bpy.app.background else None
            wm.progress_begin(0, 100)
            try:
                trajectory = run(request, progress=lambda f: (wm.progress_update(100 * f),
                                                              progress and progress(f)))
            finally:
                wm.progress_end()
            return self._finish(context, obj, trajectory, s)
        except _user_errors() as exc:
            self.report({"ERROR"}, str(exc))
            return {"CANCELLED"}

    # -- interactive: worker thread + modal timer, ESC cancels

    def invoke(self, context, event):
        if bpy.app.background or context.window is None:
            return self.execute(context)
        try:
            obj, request, s = self._prepare(context)
        except _user_errors() as exc:
            self.report({"ERROR"}, str(exc))
            return {"CANCELLED"}
        self._rig_name, self._s = obj.name, s
        self._job = SimulationJob(request).start()
        wm = context.window_manager
        wm.progress_begin(0, 100)
        self._timer = wm.event_timer_add(0.1, window=context.window)
        wm.modal_handler_add(self)
        context.workspace.status_text_set("Sim Athletics: simulating… (Esc to cancel)")
        return {"RUNNING_MODAL"}

    def modal(self, context, event):
        job = self._job
        if event.type == "ESC":
            job.cancel()
            job.wait()
            self._cleanup(context)
            self.report({"WARNING"}, "Simulation cancelled; nothing was written")
            return {"CANCELLED"}
        if event.type != "TIMER":
            return {"PASS_THROUGH"}
        context.window_manager.progress_update(100 * job.progress)
        if not job.done():
            return {"PASS_THROUGH"}
        self._cleanup(context)
        if job.error is not None:
            if isinstance(job.error, _user_errors()):
                self.report({"ERROR"}, str(job.error))
                return {"CANCELLED"}
            raise job.error
        obj = bpy.data.objects.get(self._rig_name)
        if obj is None:
            self.report({"ERROR"}, f"the rig {self._rig_name!r} was deleted during the simulation")
            return {"CANCELLED"}
        try:
            return self._finish(context, obj, job.trajectory, self._s)
        except _user_errors() as exc:
            self.report({"ERROR"}, str(exc))
            return {"CANCELLED"}

    def _cleanup(self, context):
        wm = context.window_manager
        if self._timer is not None:
            wm.event_timer_remove(self._timer)
            self._timer = None
        wm.progress_end()
        context.workspace.status_text_set(None)


def key_count(action) -> int:
    curves = compat.action_fcurves(action)
    return len(curves[0].keyframe_points) if curves else 0


classes = (SIMATHLETICS_OT_add_character, SIMATHLETICS_OT_simulate_bake)
