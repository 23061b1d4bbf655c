"""Character spec -> MuJoCo bodies, joints and servos in an MjSpec (the world's props are
sim_core.world's; a scene puts several characters, prefixed, into one spec).

Physics choices (ARCHITECTURE.md "Choices"):
  * timestep 1 ms (the man's; a body made by scaling multiplies it by its spec's ``time_scale``,
    Fig. 6's L^1/2: ``character_timestep``) with the ``implicitfast`` integrator: the PD servos are MuJoCo position
    actuators whose damping (kv) is integrated implicitly, so stiff servos stay stable at 1 ms,
    and 1 ms resolves the foot contacts of landings (Wooten used a fixed-step RK4).
  * every SD/FAST degree of freedom is a hinge joint (gimbal = 3 hinges in the file's pin
    order, the first fixed in the parent, exactly SD/FAST's gimbal; a ball joint is 3 hinges
    X, Y, Z so that each axis has its own servo and torque limit).
  * inertials are explicit, exactly the spec's (geoms carry no mass).
  * the only actuators are the joint servos; the root (free joint) has none.

The simulation always runs the model compiled from the MJCF text returned here, so a run can be
replayed from the text stored in its trajectory and reproduce it bit for bit.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np

from .spec import CharacterSpec
from ..world import World, add_attachments, add_world
from ..world.props import CONTACT_GROUP, FOOT_FRICTION

TIMESTEP = 0.001
ARMATURE = 0.01            # kg m^2 on every hinge: numerical regularisation of light distal joints
BODY_FRICTION = 0.8
# thigh against belly: the rigid shapes would stop a pike or tuck well before a human's soft
# tissue does (thighs on the chest); the hip's range of motion limits the flexion instead
SOFT_TISSUE_PAIRS = [(f"ULEG{side}", chest) for side in "RL" for chest in ("CHEST3", "CHEST2", "CHEST1")]


@dataclass(frozen=True)
class Placement:
    """Where a character's standing start is put: its spec's origin moved to (x, y) on the ground
    and turned by ``heading`` (rad, counter-clockwise from +X) about the vertical."""
    x: float = 0.0
    y: float = 0.0
    heading: float = 0.0

    def point(self, local) -> list[float]:
        """A point of the character's own frame (x, y, z) in the world."""
        c, s = math.cos(self.heading), math.sin(self.heading)
        return [self.x + c * local[0] - s * local[1], self.y + s * local[0] + c * local[1], float(local[2])]

    def quat(self) -> list[float]:
        """The heading as a quaternion (w first)."""
        return [math.cos(self.heading / 2), 0.0, 0.0, math.sin(self.heading / 2)]


def _quat_from_x_to(direction) -> list[float]:
    """Quaternion (w first) turning +X onto ``direction``."""
    d = np.asarray(direction, dtype=float)
    d = d / np.linalg.norm(d)
    x = np.array([1.0, 0, 0])
    c = float(np.dot(x, d))
    if c < -0.999999:
        return [0.0, 0.0, 0.0, 1.0]
    axis = np.cross(x, d)
    q = np.array([1.0 + c, *axis])
    return list(q / np.linalg.norm(q))


def character_timestep(character: CharacterSpec) -> float:
    """The physics step of ``character``'s runs: the man's TIMESTEP x its Fig. 6 time scale."""
    return TIMESTEP * character.time_scale


def new_spec(name: str, timestep: float = TIMESTEP) -> mujoco.MjSpec:
    """An empty MjSpec with the physics choices of the module doc (gravity is the world's)."""
    spec = mujoco.MjSpec()
    spec.modelname = name
    spec.option.timestep = timestep
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    spec.option.gravity = World().gravity()
    spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
    spec.compiler.inertiafromgeom = mujoco.mjtInertiaFromGeom.mjINERTIAFROMGEOM_FALSE
    spec.compiler.autolimits = True
    spec.compiler.degree = False          # every angle in the spec is in radians
    return spec


def build_mjspec(character: CharacterSpec, world: World | None = None, strength: str | float = "human",
                 also_excluded: tuple = ()) -> mujoco.MjSpec:
    """One character, unprefixed, standing at the origin facing +X, in ``world``; ``also_excluded``:
    body pairs kept from colliding besides its own (a morph's: the pairs of the body it turns into)."""
    world = world or World()
    spec = new_spec(f"sim_athletics_{character.name}", character_timestep(character))
    add_character(spec, character, world.extra_mass, strength, also_excluded=also_excluded)
    add_world(spec, world, character)      # after the character: a moving prop's body comes last
    add_attachments(spec, world, character)
    return spec


def add_character(spec: mujoco.MjSpec, character: CharacterSpec, extra_mass: dict | None = None,
                  strength: str | float = "human", prefix: str = "", placement: Placement | None = None,
                  also_excluded: tuple = ()) -> None:
    """The character's bodies, joints, geoms, sites, servos and excluded contact pairs, every name
    prefixed by ``prefix`` (a scene's "<actor>/"; "" for a single character), its root at
    ``placement`` (None: the spec's own frame, as a single character stands)."""
    _add_bodies(spec, character, extra_mass or {}, prefix, placement)
    torque_scale = _torque_scale(strength)
    for dof in character.dofs:
        act = spec.add_actuator(name=prefix + dof.name, target=prefix + dof.name, trntype=mujoco.mjtTrn.mjTRN_JOINT)
        act.set_to_position(kp=dof.kp, kv=dof.kv)
        act.ctrllimited = mujoco.mjtLimited.mjLIMITED_FALSE
        if torque_scale is not None:
            act.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
            act.forcerange = [-dof.torque_limit * torque_scale, dof.torque_limit * torque_scale]
        else:
            act.forcelimited = mujoco.mjtLimited.mjLIMITED_FALSE
    for a, b in sorted(set(excluded_pairs(character)) | {tuple(sorted(p)) for p in also_excluded}):
        spec.add_exclude(bodyname1=prefix + a, bodyname2=prefix + b)


def _add_bodies(spec: mujoco.MjSpec, character: CharacterSpec, extra_mass: dict, prefix: str,
                placement: Placement | None) -> None:
    """Bodies, joints, shapes and contact spheres with their sites (see add_character)."""
    frames: dict[str, np.ndarray] = {}
    mj_bodies: dict[str, mujoco.MjsBody] = {}
    for b in character.bodies:
        com = np.array(b["com"])
        if b["parent"] is None:
            origin = com.copy()
            if placement is None:
                body = spec.worldbody.add_body(name=prefix + b["name"], pos=origin.tolist())
            else:
                body = spec.worldbody.add_body(name=prefix + b["name"], pos=placement.point(origin),
                                               quat=placement.quat())
            body.add_freejoint(name=prefix + "root")
        else:
            origin = np.array(b["joint"]["pos"])
            body = mj_bodies[b["parent"]].add_body(name=prefix + b["name"], pos=(origin - frames[b["parent"]]).tolist())
            for d in b["joint"]["dofs"]:
                j = body.add_joint(name=prefix + d["name"], type=mujoco.mjtJoint.mjJNT_HINGE, axis=d["axis"],
                                   range=d["range"], limited=mujoco.mjtLimited.mjLIMITED_TRUE)
                j.armature = ARMATURE
        frames[b["name"]] = origin
        mj_bodies[b["name"]] = body
        mass = b["mass"] + extra_mass.get(b["name"], 0.0)
        body.explicitinertial = True
        body.mass = mass
        body.ipos = (com - origin).tolist()
        inertia = np.array(b["inertia"]) * (mass / b["mass"])
        body.fullinertia = [inertia[0, 0], inertia[1, 1], inertia[2, 2], inertia[0, 1], inertia[0, 2], inertia[1, 2]]
        for k, shape in enumerate(b["shapes"]):
            _add_shape(body, shape, origin, f"{prefix}{b['name']}_shape{k}")
        for c in b.get("contacts", []):
            g = body.add_geom(name=f"{prefix}{b['name']}_{c['site']}", type=mujoco.mjtGeom.mjGEOM_SPHERE,
                              size=[c["radius"], 0, 0], pos=(np.array(c["pos"]) - origin).tolist())
            g.friction = [FOOT_FRICTION, 0.005, 0.0001]
            g.contype = g.conaffinity = CONTACT_GROUP
            g.group = 3
            body.add_site(name=f"{prefix}{b['name']}_{c['site']}", pos=(np.array(c["pos"]) - origin - [0, 0, c["radius"]]).tolist())
    sternum = character.body("STERNUM")
    mj_bodies["STERNUM"].add_site(name=prefix + "push_point", pos=(np.array(sternum["com"]) - frames["STERNUM"]).tolist())


def _torque_scale(strength) -> float | None:
    if strength == "unlimited":
        return None
    if strength == "human":
        return 1.0
    return float(strength)


def _add_shape(body, shape: dict, origin: np.ndarray, name: str) -> None:
    kind = shape["type"]
    if kind == "capsule":
        geom = body.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_CAPSULE, size=[shape["radius"], 0, 0],
                             fromto=[*(np.array(shape["from"]) - origin), *(np.array(shape["to"]) - origin)])
    elif kind == "sphere":
        geom = body.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_SPHERE, size=[shape["radius"], 0, 0],
                             pos=(np.array(shape["pos"]) - origin).tolist())
    elif kind in ("box", "ellipse_slab"):
        quat = _quat_from_x_to(shape.get("along", [1, 0, 0]))
        geom = body.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_BOX, size=shape["half"],
                             pos=(np.array(shape["pos"]) - origin).tolist(), quat=quat)
    else:
        raise ValueError(f"unknown shape type {kind!r}")
    geom.friction = [BODY_FRICTION, 0.005, 0.0001]
    bit = CONTACT_GROUP if shape.get("contact", True) else 0
    geom.contype = geom.conaffinity = bit
    geom.rgba = [0.8, 0.65, 0.55, 1]


def excluded_pairs(character: CharacterSpec) -> list[tuple[str, str]]:
    """Bodies whose shapes already touch in the standing pose (e.g. an upper arm against the
    chest) would push each other apart from the first step; exclude those pairs, keep all others
    colliding so limbs cannot pass through each other. (Parent and child never collide in MuJoCo.)
    Read off the character alone: contacts with the world's geoms do not count."""
    spec = new_spec(f"sim_athletics_{character.name}")
    _add_bodies(spec, character, {}, "", None)
    model = spec.compile()
    data = mujoco.MjData(model)
    set_standing_pose(model, data, character)
    mujoco.mj_forward(model, data)
    pairs = set()
    for c in data.contact[: data.ncon]:
        b1, b2 = model.geom_bodyid[c.geom1], model.geom_bodyid[c.geom2]
        pairs.add(tuple(sorted((model.body(b1).name, model.body(b2).name))))
    pairs |= {tuple(sorted(pair)) for pair in SOFT_TISSUE_PAIRS}
    return sorted(pairs)


def set_standing_pose(model: mujoco.MjModel, data: mujoco.MjData, character: CharacterSpec) -> None:
    """Reference configuration with the spec's standing pose; feet on the ground."""
    mujoco.mj_resetData(model, data)
    place_standing(model, data, character)


def place_standing(model: mujoco.MjModel, data: mujoco.MjData, character: CharacterSpec, prefix: str = "",
                   placement: Placement | None = None) -> None:
    """The character named by ``prefix`` in the spec's standing pose at ``placement`` (None: its
    own frame); the rest of ``data`` is left as it is."""
    pelvis = character.bodies[0]
    root = model.joint(prefix + "root").qposadr[0]
    if placement is None:
        data.qpos[root:root + 3] = pelvis["com"]
        data.qpos[root + 3:root + 7] = [1, 0, 0, 0]
    else:
        data.qpos[root:root + 3] = placement.point(pelvis["com"])
        data.qpos[root + 3:root + 7] = placement.quat()
    for i, dof in enumerate(character.dofs):
        data.qpos[model.joint(prefix + dof.name).qposadr[0]] = character.standing_pose[i]


def compile_model(character: CharacterSpec, world: World | None = None, strength="human",
                  also_excluded: tuple = ()) -> tuple[mujoco.MjModel, str]:
    """Return (model, mjcf_text); the model is compiled from the text (see module doc)."""
    xml = build_mjspec(character, world, strength, also_excluded).to_xml()
    return mujoco.MjModel.from_xml_string(xml), xml
