"""The "Sim Athletics" tab of the 3D viewport's sidebar, drawn from the schemas through the
generated property groups: nothing here is per-behaviour.

* the main panel: character, behaviour, the behaviour's animator parameters (``schema``; a
  choice is a drop-down, a path a curve object, a group a box under its heading), Simulate &
  Bake, Plan Jump for a jump to a target, and the last result;
* "Run request" (open): the request schema - duration, strength, start height and velocity,
  slope, backpack, a push;
* "Tuned settings" (closed by default): the behaviour's ``settings_schema`` - what a search
  sets - where the behaviour has one.
"""
from __future__ import annotations

import json

import bpy

from . import props, rig

CATEGORY = "Sim Athletics"


def draw_schema(layout, group, schema) -> None:
    """Every knob of ``schema`` from ``group``: loose ones in a column, a Group in a box under
    its heading."""
    for heading, knobs in schema.groups:
        col = layout.column(align=True)
        if heading is not None:
            col = layout.box().column(align=True)
            col.label(text=heading)
        for p in knobs:
            col.prop(group, p.name)


class SIMATHLETICS_PT_panel(bpy.types.Panel):
    bl_label = "Sim Athletics"
    bl_idname = "SIMATHLETICS_PT_panel"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = CATEGORY

    def draw(self, context):
        layout = self.layout
        settings = context.scene.sim_athletics

        box = layout.box()
        row = box.row(align=True)
        row.prop(settings, "character", text="")
        row.operator("sim_athletics.add_character", icon="ARMATURE_DATA")
        target = _target(context)
        if target is None:
            box.label(text="No Sim Athletics character selected", icon="INFO")
        else:
            box.label(text=f"Bake onto: {target.name} ({target[rig.CHARACTER_KEY]})", icon="OUTLINER_OB_ARMATURE")

        layout.prop(settings, "behaviour")
        if settings.behaviour:
            if props.takes_target(settings.behaviour):
                layout.prop(settings, "target_object")
            draw_schema(layout, props.params_group(settings, settings.behaviour),
                        props.behaviour_schema(settings.behaviour))
        col = layout.column(align=True)
        col.prop(settings, "start_frame")
        scene = context.scene
        col.label(text=f"Frame rate: {scene.render.fps / scene.render.fps_base:g} fps (scene)")
        col.prop(settings, "fit_scene_range")
        if settings.behaviour == "jump_to_target":
            layout.operator("sim_athletics.plan_jump", icon="VIEWZOOM")
        layout.operator("sim_athletics.simulate_bake", icon="PLAY")

        if target is not None and target.get(rig.RESULT_KEY):
            _draw_result(layout.box(), json.loads(target[rig.RESULT_KEY]))


class _SubPanel:
    bl_parent_id = SIMATHLETICS_PT_panel.bl_idname
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = CATEGORY


class SIMATHLETICS_PT_request(_SubPanel, bpy.types.Panel):
    """The run request: what a run is asked besides the behaviour's parameters."""
    bl_label = "Run request"
    bl_idname = "SIMATHLETICS_PT_request"

    def draw(self, context):
        draw_schema(self.layout, context.scene.sim_athletics.request, props.request_schema())


class SIMATHLETICS_PT_tuned(_SubPanel, bpy.types.Panel):
    """Tuned settings (what a search sets; the tables hold them): folded away, for experts."""
    bl_label = "Tuned settings"
    bl_idname = "SIMATHLETICS_PT_tuned"
    bl_options = {"DEFAULT_CLOSED"}

    @classmethod
    def poll(cls, context):
        settings = context.scene.sim_athletics
        return bool(settings.behaviour) and props.tuned_group(settings, settings.behaviour) is not None

    def draw(self, context):
        settings = context.scene.sim_athletics
        draw_schema(self.layout, props.tuned_group(settings, settings.behaviour),
                    props.settings_schema(settings.behaviour))


def _target(context):
    """The rig a bake would use, cheaply (a panel redraws often): the active object, or the
    armature of the active skin, if it carries the Sim Athletics property."""
    obj = context.view_layer.objects.active
    if obj is not None and obj.type == "MESH" and obj.parent is not None:
        obj = obj.parent
    return obj if obj is not None and obj.type == "ARMATURE" and obj.get(rig.CHARACTER_KEY) else None


def _draw_result(box, result: dict) -> None:
    ok = result.get("outcome") == "success"
    box.label(text=f"{result.get('action', '')}", icon="ACTION")
    box.label(text=f"Outcome: {result.get('outcome')}", icon="CHECKMARK" if ok else "ERROR")
    col = box.column(align=True)
    for name, value in sorted(result.get("metrics", {}).items()):
        if isinstance(value, float):
            text = f"{value:.3f}"
        else:
            text = str(value)
        col.label(text=f"{name.replace('_', ' ')}: {text}")


classes = (SIMATHLETICS_PT_panel, SIMATHLETICS_PT_request, SIMATHLETICS_PT_tuned)
