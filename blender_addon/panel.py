"""The "Sim Athletics" tab of the 3D viewport's sidebar. Parameters are drawn from the
behaviour's schema through the generated property group: nothing here is per-behaviour."""
from __future__ import annotations

import json

import bpy

from . import props, rig


class SIMATHLETICS_PT_panel(bpy.types.Panel):
    bl_label = "Sim Athletics"
    bl_idname = "SIMATHLETICS_PT_panel"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Sim Athletics"

    def draw(self, context):
        from sim_core.control.behaviour import behaviour_class
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
            cls = behaviour_class(settings.behaviour)
            group = props.params_group(settings, settings.behaviour)
            if props.takes_target(settings.behaviour):
                layout.prop(settings, "target_object")
            col = layout.column(align=True)
            for p in cls.schema.parameters:
                col.prop(group, p.name)
        col = layout.column(align=True)
        col.prop(settings, "strength")
        col.prop(settings, "duration")
        col.prop(settings, "start_frame")
        scene = context.scene
        col.label(text=f"Frame rate: {scene.render.fps / scene.render.fps_base:g} fps (scene)")
        col.prop(settings, "fit_scene_range")
        layout.operator("sim_athletics.simulate_bake", icon="PLAY")

        if target is not None and target.get(rig.RESULT_KEY):
            _draw_result(layout.box(), json.loads(target[rig.RESULT_KEY]))


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


classes = (SIMATHLETICS_PT_panel,)
