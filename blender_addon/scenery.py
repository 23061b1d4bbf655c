"""The simulated world's fixed objects in the Blender scene, so a baked skill is seen where it
happened: a dive's platform and water surface, the boxes a jump lands on, starts from or clears,
the ground below when a jump starts on a box, a vault's springboard, table and landing mat, and a
bicycle course's hill (its climb, top and descent, and the chords of its vertical curves if rounded). Objects are made once per scene and named
``SimAthletics platform`` / ``SimAthletics water`` / ``SimAthletics ground`` / ``SimAthletics box 0``...;
an existing object of that name is reused, never replaced (the user may have moved or restyled
it)."""
from __future__ import annotations

import bpy
import mujoco
import numpy as np

from .core.axes import SIM_TO_BLENDER

PLATFORM_NAME, WATER_NAME, GROUND_NAME = "SimAthletics platform", "SimAthletics water", "SimAthletics ground"
BOX_NAME = "SimAthletics box {}"
APPARATUS_NAMES = {"springboard": "SimAthletics springboard", "vault_table": "SimAthletics vault table",
                   "landing_mat": "SimAthletics landing mat"}     # geom -> object (sim_core.world.apparatus)
HILL_NAMES = {"hill_up": "SimAthletics hill climb", "hill_top": "SimAthletics hill top",
              "hill_down": "SimAthletics hill descent"}              # geom -> object (sim_core.world.hill)
HILL_CURVE_NAME = "SimAthletics hill curve {} {}"   # a rounded hill's vertical curve's chord (corner, chord)


def add_scenery(context, armature, trajectory) -> list:
    """Add the platform and water, and the boxes, of ``trajectory``'s world (if any), in the
    armature object's frame. Returns the objects made."""
    world = trajectory.meta.get("world", {})
    made = []
    floor = float(world.get("floor", 0.0) or 0.0)
    for k, (x, y, height, length, width) in enumerate(world.get("boxes", [])):
        if BOX_NAME.format(k) not in bpy.data.objects:         # from the ground up to its top
            made.append(_box(context, BOX_NAME.format(k), np.array([x, y, 0.5 * (floor + height)]),
                             np.array([length / 2, width / 2, 0.5 * (height - floor)]), armature))
    if floor and GROUND_NAME not in bpy.data.objects:          # the start is on a box: the ground is below
        made.append(_box(context, GROUND_NAME, np.array([0.0, 0.0, floor - 0.005]),
                         np.array([20.0, 20.0, 0.005]), armature))
    platform = float(world.get("platform", 0.0) or 0.0)
    if platform <= 0 and not any(name in world for name in (*APPARATUS_NAMES, "hill")):
        return made
    model = mujoco.MjModel.from_xml_string(trajectory.meta["model_xml"])
    made += _world_boxes(context, armature, model, {**APPARATUS_NAMES, **HILL_NAMES, **hill_curve_names(model)})
    if platform <= 0:
        return made
    ground = model.geom("ground").id
    if PLATFORM_NAME not in bpy.data.objects:
        made.append(_box(context, PLATFORM_NAME, model.geom_pos[ground], model.geom_size[ground], armature))
    if WATER_NAME not in bpy.data.objects:
        made.append(_box(context, WATER_NAME, np.array([0.0, 0.0, -platform - 0.005]),
                         np.array([20.0, 20.0, 0.005]), armature))
    return made


def hill_curve_names(model: mujoco.MjModel) -> dict:
    """A rounded hill's vertical curves: each chord's box geom ("hill_curve_<corner>_<k>") -> its object
    ("SimAthletics hill curve <corner> <k>"), so the scenery's road bends where the simulation's did."""
    names = (mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_GEOM, g) or "" for g in range(model.ngeom))
    return {name: HILL_CURVE_NAME.format(*name.split("_")[2:4]) for name in names if name.startswith("hill_curve_")}


def _world_boxes(context, armature, model: mujoco.MjModel, names: dict) -> list:
    """The model's box geoms named in ``names`` (geom -> object) as boxes where the model puts
    them at rest, turned as they are (a hill's ramps); the springboard's deck is drawn
    at rest, and ``bake.bake_springboard`` keys its deflection."""
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    made = []
    for geom, name in names.items():
        if mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, geom) < 0 or name in bpy.data.objects:
            continue
        g = model.geom(geom).id
        made.append(_box(context, name, data.geom_xpos[g], model.geom_size[g], armature,
                         data.geom_xmat[g].reshape(3, 3)))
    return made


def _box(context, name: str, centre_sim: np.ndarray, half_size_sim: np.ndarray, armature, axes_sim=None):
    """A box given in the simulation frame (its axes the columns of ``axes_sim``, default the
    world's), placed in the armature's frame."""
    mesh = bpy.data.meshes.new(name)
    corners = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], dtype=float)
    axes = np.eye(3) if axes_sim is None else np.asarray(axes_sim)
    points = (centre_sim + (corners * half_size_sim) @ axes.T) @ SIM_TO_BLENDER.T
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    mesh.from_pydata([tuple(p) for p in points], [], faces)
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    obj.matrix_world = armature.matrix_world.copy()
    context.scene.collection.objects.link(obj)
    return obj
