"""Sim Athletics for Blender: physics-simulated athletes baked into actions.

Add a character (an armature with a weighted skin), pick a behaviour and its parameters in the
"Sim Athletics" sidebar tab, Simulate & Bake. See docs/blender.md.
"""
bl_info = {
    "name": "Sim Athletics",
    "author": "Sim Athletics",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "3D Viewport > Sidebar > Sim Athletics",
    "description": "Physics-simulated athletes (MuJoCo) baked into actions on a skinned rig",
    "category": "Animation",
}

from pathlib import Path  # noqa: E402

from .core.vendor import add_vendored  # noqa: E402

add_vendored(Path(__file__).resolve().parent / "vendor")     # the legacy zip's wheels, after Blender's own


def register():
    import bpy
    from . import operators, panel, props
    props.register()
    for cls in operators.classes + panel.classes:
        bpy.utils.register_class(cls)


def unregister():
    import bpy
    from . import operators, panel, props
    for cls in reversed(operators.classes + panel.classes):
        bpy.utils.unregister_class(cls)
    props.unregister()
