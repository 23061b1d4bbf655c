"""The vaulting apparatus in a bake (issue 31 part 1): a run in a world with a springboard, a
vaulting table and a landing mat bakes onto the rig, and the three appear as scenery objects, once,
with their tops where the simulation had them."""
import pytest

bpy = pytest.importorskip("bpy")

from sim_core.simulate import RunRequest, run  # noqa: E402
from sim_core.world import World  # noqa: E402
from sim_core.world import apparatus as A  # noqa: E402

WORLD = World(springboard=(2.0, 0.0), vault_table=(4.0, 0.0, A.VAULT_TABLE_HEIGHT_WOMEN, A.VAULT_TABLE_LENGTH,
                                                   A.VAULT_TABLE_WIDTH),
              landing_mat=(7.0, 0.0, 4.0, 2.0, A.LANDING_MAT_THICKNESS))


def test_a_bake_in_the_vaulting_world_shows_the_apparatus(empty_scene):
    from blender_addon import api, scenery
    context = empty_scene
    assert bpy.ops.sim_athletics.add_character(character="woman") == {"FINISHED"}
    arm = context.view_layer.objects.active
    trajectory = run(RunRequest("balance", "woman", duration=0.3, world=WORLD))
    assert "prop:springboard" not in trajectory.body_names        # the deck is the world's, not a bone
    action = api.bake_result(context, arm, trajectory, start_frame=1)
    assert action is not None and arm.animation_data.action == action
    top = lambda name: max((bpy.data.objects[name].matrix_world @ v.co).z for v in bpy.data.objects[name].data.vertices)
    assert top(scenery.APPARATUS_NAMES["springboard"]) == pytest.approx(A.BOARD_TOP, abs=1e-6)
    assert top(scenery.APPARATUS_NAMES["vault_table"]) == pytest.approx(A.VAULT_TABLE_HEIGHT_WOMEN, abs=1e-6)
    assert top(scenery.APPARATUS_NAMES["landing_mat"]) == pytest.approx(A.LANDING_MAT_THICKNESS, abs=1e-6)
    api.bake_result(context, arm, trajectory, start_frame=1)       # a second bake reuses them
    assert len([o for o in bpy.data.objects if o.name.startswith("SimAthletics")]) == 3
