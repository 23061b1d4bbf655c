"""Operators: Add Character, Simulate & Bake, Plan Jump. Usable from the panel and from Python:

    bpy.ops.sim_athletics.add_character(character="man")
    bpy.ops.sim_athletics.simulate_bake(behaviour="balance", params="pelvis_height=0.52", duration=3)
    bpy.ops.sim_athletics.plan_jump()          # the panel's jump_to_target request

A property left unset when called from Python falls back to the panel's setting
(``scene.sim_athletics``). ``params`` is merged over the panel's values for that behaviour; the
run request (start height, slope, push...) is the panel's Run request sub-panel.
Interactively, Simulate & Bake and Plan Jump run their work in a worker thread under a modal
operator (core/jobs.py): progress in the status bar, Esc cancels within a second and nothing is
written. From Python or in background mode they run to the end in the call.
"""
from __future__ import annotations

import bpy
from bpy.props import EnumProperty, FloatProperty, IntProperty, StringProperty

from . import api, compat, props, rig
from .core.jobs import PlanningJob, SimulationJob, plan_note, planned_request, stored_jump_plan
from .core.simcore import sim

JUMP = "jump_to_target"


def _user_errors():
    return (sim("errors").SimAthleticsError, rig.RigError)


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
        changed = props.use_character_defaults(settings, character)
        self.report({"INFO"}, f"Added {arm.name} ({len(arm.data.bones)} bones)"
                    + (f"; the panel now offers its own defaults ({', '.join(changed)})" if changed else ""))
        return {"FINISHED"}


class _ModalJob:
    """The modal half shared by the operators that run a job: a timer polls it, Esc cancels it
    (waiting for the worker so that nothing is left running), the status bar shows progress."""
    _job = None
    _timer = None
    busy_text = "Sim Athletics: working… (Esc to cancel)"

    def invoke(self, context, event):
        if bpy.app.background or context.window is None:
            return self.execute(context)
        try:
            job = self._new_job(context)
        except _user_errors() as exc:
            self.report({"ERROR"}, str(exc))
            return {"CANCELLED"}
        if job is None:
            return self._nothing_to_do()
        return self._start_modal(context, job)

    def _nothing_to_do(self):
        return {"FINISHED"}

    def _start_modal(self, context, job):
        self._job = job.start()
        wm = context.window_manager
        wm.progress_begin(0, 100)
        self._timer = wm.event_timer_add(0.1, window=context.window)
        wm.modal_handler_add(self)
        context.workspace.status_text_set(self.busy_text)
        return {"RUNNING_MODAL"}

    def modal(self, context, event):
        job = self._job
        if event.type == "ESC":
            job.cancel()
            job.wait()
            self._cleanup(context)
            self.report({"WARNING"}, f"{self.bl_label} cancelled; nothing was written")
            return {"CANCELLED"}
        if event.type != "TIMER":
            return {"PASS_THROUGH"}
        context.window_manager.progress_update(100 * job.progress)
        if job.status:
            context.workspace.status_text_set(f"{self.busy_text} {job.status}")
        if not job.done():
            return {"PASS_THROUGH"}
        self._cleanup(context)
        if job.error is not None:
            if isinstance(job.error, _user_errors()):
                self.report({"ERROR"}, str(job.error))
                return {"CANCELLED"}
            raise job.error
        try:
            return self._finish_job(context, job)
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


class SIMATHLETICS_OT_simulate_bake(_ModalJob, bpy.types.Operator):
    """Simulate the behaviour on the character and bake it into a new action"""
    bl_idname = "sim_athletics.simulate_bake"
    bl_label = "Simulate & Bake"
    bl_options = {"REGISTER", "UNDO"}
    busy_text = "Sim Athletics: simulating… (Esc to cancel)"

    behaviour: StringProperty(name="Behaviour", description="Behaviour name (unset: the panel's)")
    params: StringProperty(name="Parameters",
                           description="name=value pairs merged over the panel's values, e.g. 'pelvis_height=0.52'")
    duration: FloatProperty(name="Duration", min=0.0, description="Seconds to simulate (unset or 0: the panel's)")
    strength: StringProperty(name="Strength", description="'human' or 'unlimited' torque limits (unset: the panel's)")
    start_frame: IntProperty(name="Start frame", description="Frame of the first key (unset: the panel's)")
    armature: StringProperty(name="Armature", description="Rig to bake onto (unset: the active one)")

    # -- the request, from the operator's properties or the panel's settings

    def _settings(self, context) -> dict:
        return run_settings(context, **overrides(self))

    def _prepare(self, context):
        """Validate everything before simulating: (rig object, request, settings)."""
        s = self._settings(context)
        obj = rig.find_rig(context, s["armature"])
        params = with_scene_inputs(context, obj, s)
        request = api.make_request(str(obj[rig.CHARACTER_KEY]), s["behaviour"], params, s["duration"],
                                   s["strength"], s["request"])
        return obj, request, s

    def _finish(self, context, obj, trajectory, s, plan=None):
        action = api.bake_result(context, obj, trajectory, s["start_frame"], s["fit_scene_range"])
        outcome = trajectory.meta.get("outcome")
        self.report({"INFO"} if outcome == "success" else {"WARNING"},
                    f"Baked {action.name!r}: {key_count(action)} frames, outcome {outcome}{plan_note(plan)}")
        return {"FINISHED"}

    # -- blocking (Python, background)

    def execute(self, context):
        wm = context.window_manager
        try:
            obj, request, s = self._prepare(context)
            progress = api.console_progress if bpy.app.background else None
            wm.progress_begin(0, 100)
            try:
                request, plan = planned_request(request)         # a landing's foot placement, planned first
                trajectory = sim("simulate").run(request, progress=lambda f: (wm.progress_update(100 * f),
                                                                              progress and progress(f)))
            finally:
                wm.progress_end()
            return self._finish(context, obj, trajectory, s, plan)
        except _user_errors() as exc:
            self.report({"ERROR"}, str(exc))
            return {"CANCELLED"}

    # -- interactive: worker thread + modal timer, ESC cancels (_ModalJob.invoke)

    def _new_job(self, context):
        obj, request, s = self._prepare(context)
        self._rig_name, self._s = obj.name, s
        return SimulationJob(request)

    def _finish_job(self, context, job):
        obj = bpy.data.objects.get(self._rig_name)
        if obj is None:
            self.report({"ERROR"}, f"the rig {self._rig_name!r} was deleted during the simulation")
            return {"CANCELLED"}
        return self._finish(context, obj, job.trajectory, self._s, job.plan)


def overrides(op) -> dict:
    """The operator properties that were set (from Python or the redo panel): they win over the
    panel's settings."""
    def is_set(name: str) -> bool:
        return name in op.properties.bl_rna.properties and op.properties.is_property_set(name)
    found = {name: getattr(op, name) for name in ("behaviour", "params", "strength", "armature") if is_set(name)}
    if is_set("duration") and op.duration > 0:
        found["duration"] = op.duration
    if is_set("start_frame"):
        found["start_frame"] = op.start_frame
    return {k: v for k, v in found.items() if v not in ("", None)}


def run_settings(context, behaviour: str | None = None, params: str = "", duration: float | None = None,
                 strength: str | None = None, start_frame: int | None = None, armature: str | None = None) -> dict:
    """The run's settings: the given overrides (an operator's properties), else the panel's."""
    settings = context.scene.sim_athletics
    behaviour = behaviour or settings.behaviour
    has_group = hasattr(settings, props.group_attr(behaviour))
    values = props.panel_params(settings, behaviour) if has_group else {}
    values.update(props.panel_tuned_overrides(settings, behaviour))
    if params.strip():
        values.update(api.parse_params(behaviour, params))
        values = api.parse_params(behaviour, values)
    return {
        "behaviour": behaviour, "params": values, "target": settings.target_object, "duration": duration,
        "paths": props.panel_paths(settings, behaviour) if has_group else {},
        "strength": strength, "request": props.panel_request(settings),
        "start_frame": settings.start_frame if start_frame is None else start_frame,
        "armature": armature, "fit_scene_range": settings.fit_scene_range,
    }


def with_scene_inputs(context, obj, s: dict) -> dict:
    """The parameters with what scene objects set: a jump's target from the Target object, a
    path from its curve (both in the rig's frame)."""
    params = dict(s["params"])
    if s["target"] is not None and props.takes_target(s["behaviour"]):
        params.update(api.target_from_object(obj, s["target"]))
    for name, curve in s["paths"].items():
        params[name] = api.path_from_curve(context, obj, curve)
    return api.parse_params(s["behaviour"], params)


class SIMATHLETICS_OT_plan_jump(_ModalJob, bpy.types.Operator):
    """Plan the jump to the target (simulated trial jumps) and store the plan for the bake"""
    bl_idname = "sim_athletics.plan_jump"
    bl_label = "Plan Jump"
    bl_options = {"REGISTER"}
    busy_text = "Sim Athletics: planning the jump… (Esc to cancel)"

    params: StringProperty(name="Parameters", description="jump_to_target name=value pairs over the panel's")
    strength: StringProperty(name="Strength", description="'human' or 'unlimited' (unset: the panel's)")
    armature: StringProperty(name="Armature", description="Rig whose character jumps (unset: the active one)")

    def _new_job(self, context):
        """A PlanningJob for the panel's jump (not started), or None if a plan is stored already.
        Validates everything first (raises the user errors)."""
        return planning_job(context, **overrides(self))

    def _nothing_to_do(self):
        self.report({"INFO"}, "this jump is planned already (a stored plan)")
        return {"FINISHED"}

    def execute(self, context):
        try:
            job = self._new_job(context)
            if job is None:
                return self._nothing_to_do()
            job.start().wait()
            if job.error is not None:
                raise job.error
            return self._finish_job(context, job)
        except _user_errors() as exc:
            self.report({"ERROR"}, str(exc))
            return {"CANCELLED"}

    def _finish_job(self, context, job):
        job.store()
        found = job.result.get("found")
        self.report({"INFO"} if found else {"WARNING"},
                    f"Jump plan stored ({job.result.get('trials')} trials): "
                    + ("found; Simulate & Bake uses it" if found else "no jump within the tolerance found"))
        return {"FINISHED"}


def planning_job(context, params: str = "", strength: str | None = None, armature: str | None = None):
    """The planning operator's job, from its properties and the panel: validated, not started;
    None when the jump has a stored plan."""
    s = run_settings(context, behaviour=JUMP, params=params, strength=strength, armature=armature)
    obj = rig.find_rig(context, s["armature"])
    params = with_scene_inputs(context, obj, s)
    request = api.make_request(str(obj[rig.CHARACTER_KEY]), JUMP, params, None, s["strength"], s["request"])
    strength = request.strength
    character = str(obj[rig.CHARACTER_KEY])
    if stored_jump_plan(character, params, strength) is not None:
        return None
    if params["plan_trials"] < 1:
        raise sim("errors").ParameterError("parameter plan_trials=0: give the planner at least 1 trial; "
                                           "allowed range of plan_trials is [1, 600]")
    return PlanningJob(character, params, strength)


def key_count(action) -> int:
    curves = compat.action_fcurves(action)
    return len(curves[0].keyframe_points) if curves else 0


classes = (SIMATHLETICS_OT_add_character, SIMATHLETICS_OT_simulate_bake, SIMATHLETICS_OT_plan_jump)
