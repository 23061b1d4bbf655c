"""A bicycle course's hill in a bake (issue 30): its climb, top and descent appear as scenery
objects, turned as in the simulation, their road surfaces where the simulation had them."""
import pytest

bpy = pytest.importorskip("bpy")

from sim_core.simulate import RunRequest, run  # noqa: E402
from sim_core.world import World  # noqa: E402
from sim_core.world.hill import hill_height  # noqa: E402

HILL = (3.0, 0.1, 6.0, 2.0, 6.0)


def bake_on(context, hill):
    """A short balance on ``hill`` baked onto the man; returns the highest world z of a named object."""
    from blender_addon import api
    assert bpy.ops.sim_athletics.add_character(character="man") == {"FINISHED"}
    arm = context.view_layer.objects.active
    trajectory = run(RunRequest("balance", "man", duration=0.2, world=World(hill=hill)))
    assert api.bake_result(context, arm, trajectory, start_frame=1) is not None
    return lambda name: max((bpy.data.objects[name].matrix_world @ v.co).z for v in bpy.data.objects[name].data.vertices)


def test_a_bake_in_a_world_with_a_hill_shows_its_road(empty_scene):
    from blender_addon import scenery
    top = bake_on(empty_scene, HILL)
    assert top(scenery.HILL_NAMES["hill_top"]) == pytest.approx(float(hill_height(HILL, 10.0)), abs=1e-6)
    assert top(scenery.HILL_NAMES["hill_up"]) == pytest.approx(float(hill_height(HILL, 9.0)), abs=1e-6)
    assert top(scenery.HILL_NAMES["hill_down"]) == pytest.approx(float(hill_height(HILL, 11.0)), abs=1e-6)


ROUNDED = (3.0, 0.1, 6.0, 6.0, 6.0, 4.0)     # the corners rounded by 4 m vertical curves (the top straight 11-13 m)


def test_a_rounded_hill_bakes_its_curves_where_the_simulation_had_them(empty_scene):
    from blender_addon import scenery
    from sim_core.world.hill import hill_profile
    top = bake_on(empty_scene, ROUNDED)
    crest = dict(hill_profile(ROUNDED))["curve_1"]
    for k, ((x0, z0), (x1, z1)) in enumerate(zip(crest[:-1], crest[1:])):
        assert top(scenery.HILL_CURVE_NAME.format(1, k)) == pytest.approx(max(z0, z1), abs=1e-6)
    assert top(scenery.HILL_NAMES["hill_top"]) == pytest.approx(float(hill_height(ROUNDED, 12.0)), abs=1e-6)
