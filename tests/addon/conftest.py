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
