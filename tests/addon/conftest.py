"""Fixtures for the add-on tests on Blender as a Python module (PyPI ``bpy``)."""
import pytest


@pytest.fixture(scope="session")
def addon():
    """The add-on, registered once in this process's bpy (skips where bpy is not installed)."""
    bpy = pytest.importorskip("bpy")
    import blender_addon
    if "sim_athletics" not in bpy.types.Scene.bl_rna.properties:
        blender_addon.register()
    return blender_addon


@pytest.fixture
def empty_scene(addon):
    """A fresh, empty file (the add-on stays registered)."""
    import bpy
    bpy.ops.wm.read_homefile(use_empty=True)
    return bpy.context


def man_in_an_empty_scene(fps: int):
    """A fresh, empty file at ``fps`` frames per second with the man added by the add-on's operator;
    returns (the context, his armature)."""
    import bpy
    bpy.ops.wm.read_homefile(use_empty=True)
    context = bpy.context
    context.scene.render.fps, context.scene.render.fps_base = fps, 1.0
    assert bpy.ops.sim_athletics.add_character(character="man") == {"FINISHED"}
    return context, context.view_layer.objects.active
