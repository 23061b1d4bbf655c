"""Character spec -> MuJoCo model, built in code with MjSpec, plus the world around it.

Physics choices (ARCHITECTURE.md "Choices"):
  * timestep 1 ms with the ``implicitfast`` integrator: the PD servos are MuJoCo position
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
from dataclasses import dataclass, field

import mujoco
import numpy as np

from sim_core.ballistics import GRAVITY
from sim_core.character.spec import CharacterSpec

TIMESTEP = 0.001
ARMATURE = 0.01            # kg m^2 on every hinge: numerical regularisation of light distal joints
FOOT_FRICTION = 1.0
BODY_FRICTION = 0.8
SLOPE_RAMP_PER_DEGREE = 0.15   # s per degree: the ground tilts at ~6.7 deg/s
PLATFORM_HEEL_GAP = 0.02   # m: the platform's edge is this far behind the heels (or ahead of the toes)
PLATFORM_LENGTH, PLATFORM_WIDTH, PLATFORM_THICKNESS = 5.0, 2.0, 0.3     # m (FINA: >= 6 x 2 m)
# thigh against belly: the rigid shapes would stop a pike or tuck well before a human's soft
# tissue does (thighs on the chest); the hip's range of motion limits the flexion instead
SOFT_TISSUE_PAIRS = [(f"ULEG{side}", chest) for side in "RL" for chest in ("CHEST3", "CHEST2", "CHEST1")]
CONTACT_GROUP = 1          # contype/conaffinity bit for character and world geoms


@dataclass
class World:
    """The world a character is put in. ``slope`` tilts the ground (radians) about the axis
    named by ``slope_axis``: 'x+' means the ground rises towards +X. As in Wooten §7.3 the
    ground starts level and tilts to the slope along a Hermite curve over ``slope_ramp``
    seconds from ``slope_start``. The tilt is implemented by turning gravity, which is exactly
    equivalent for a flat plane; each change is a logged model edit.

    ``platform`` > 0 makes a diving platform: the character stands on a platform whose top is
    the z = 0 plane (so every standing controller works unchanged) and whose edge is just behind
    the heels (the -X side, where a diver standing backwards has the water) or, with
    ``platform_edge='ahead'``, just ahead of the toes (facing the water); the water surface
    is ``platform`` metres below. Water is not simulated: the dive ends at entry (Wooten §8.2.1
    lets entering the water end the run)."""
    slope: float = 0.0
    slope_axis: str = "x+"
    extra_mass: dict[str, float] = field(default_factory=dict)   # body -> added kg (backpack)
    slope_start: float = 0.5
    slope_ramp: float | None = None            # s; default SLOPE_RAMP_PER_DEGREE per degree
    platform: float = 0.0                      # m: height of a diving platform above the water (0 = none)
    platform_edge: str = "behind"              # 'behind' the heels (water at -X) or 'ahead' of the toes (+X)
    boxes: tuple = ()                          # ((x, y, height, length, width), ...) m: boxes standing on the
                                               # ground, centred at (x, y), their tops at z = height, to jump
                                               # onto, from or over (geoms "box0", "box1", ...)
    floor: float = 0.0                         # m: height of the ground plane. Below 0, the character starts
                                               # on a box (a box of World.boxes with its top at z = 0, so every
                                               # standing controller works unchanged) and can jump down

    @property
    def ramp_time(self) -> float:
        if self.slope_ramp is not None:
            return self.slope_ramp
        return max(1.0, SLOPE_RAMP_PER_DEGREE * math.degrees(self.slope))

    def gravity(self, t: float = 0.0) -> np.ndarray:
        s = min(max((t - self.slope_start) / self.ramp_time, 0.0), 1.0) if self.slope else 0.0
        return gravity_for_slope(self.slope * s * s * (3.0 - 2.0 * s), self.slope_axis)

    def tilting(self, t: float) -> bool:
        return bool(self.slope) and t <= self.slope_start + self.ramp_time + 0.02


def gravity_for_slope(slope: float, axis: str) -> np.ndarray:
    g = GRAVITY
    # ground rising towards +X by angle a == gravity tilted to pull towards -X in the ground frame
    direction = {"x+": np.array([-1.0, 0, 0]), "x-": np.array([1.0, 0, 0]),
                 "y+": np.array([0, -1.0, 0]), "y-": np.array([0, 1.0, 0])}[axis]
    return g * (math.sin(slope) * direction - math.cos(slope) * np.array([0, 0, 1.0]))


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


def build_mjspec(character: CharacterSpec, world: World | None = None, strength: str | float = "human") -> mujoco.MjSpec:
    world = world or World()
    spec = mujoco.MjSpec()
    spec.modelname = f"sim_athletics_{character.name}"
    spec.option.timestep = TIMESTEP
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    spec.option.gravity = world.gravity()
    spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
    spec.compiler.inertiafromgeom = mujoco.mjtInertiaFromGeom.mjINERTIAFROMGEOM_FALSE
    spec.compiler.autolimits = True
    spec.compiler.degree = False          # every angle in the spec is in radians

    if world.platform > 0:
        sites = [c["pos"][0] for c in character.body("FOOTR")["contacts"] + character.body("TOER")["contacts"]]
        if world.platform_edge == "ahead":         # facing the water: the edge just ahead of the toes
            centre = max(sites) + PLATFORM_HEEL_GAP - PLATFORM_LENGTH / 2
        else:                                      # backwards: the edge just behind the heels
            centre = min(sites) - PLATFORM_HEEL_GAP + PLATFORM_LENGTH / 2
        ground = spec.worldbody.add_geom(name="ground", type=mujoco.mjtGeom.mjGEOM_BOX,
                                         size=[PLATFORM_LENGTH / 2, PLATFORM_WIDTH / 2, PLATFORM_THICKNESS / 2],
                                         pos=[centre, 0, -PLATFORM_THICKNESS / 2])
        water = spec.worldbody.add_geom(name="water", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[20, 20, 0.05],
                                        pos=[0, 0, -world.platform], rgba=[0.2, 0.4, 0.8, 0.5])
        water.contype = water.conaffinity = 0               # seen, not felt: the dive ends at entry
    else:
        ground = spec.worldbody.add_geom(name="ground", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[0, 0, 0.05],
                                         pos=[0, 0, world.floor])
    ground.friction = [FOOT_FRICTION, 0.005, 0.0001]
    ground.contype = ground.conaffinity = CONTACT_GROUP
    for k, (x, y, height, length, width) in enumerate(world.boxes):
        half = (height - world.floor) / 2              # from the ground up to its top
        box = spec.worldbody.add_geom(name=f"box{k}", type=mujoco.mjtGeom.mjGEOM_BOX,
                                      size=[length / 2, width / 2, half], pos=[x, y, world.floor + half],
                                      rgba=[0.6, 0.5, 0.4, 1])
        box.friction = [FOOT_FRICTION, 0.005, 0.0001]
        box.contype = box.conaffinity = CONTACT_GROUP

    torque_scale = _torque_scale(strength)
    frames: dict[str, np.ndarray] = {}
    mj_bodies: dict[str, mujoco.MjsBody] = {}
    for b in character.bodies:
        com = np.array(b["com"])
        if b["parent"] is None:
            origin = com.copy()
            body = spec.worldbody.add_body(name=b["name"], pos=origin.tolist())
            body.add_freejoint(name="root")
        else:
            origin = np.array(b["joint"]["pos"])
            body = mj_bodies[b["parent"]].add_body(name=b["name"], pos=(origin - frames[b["parent"]]).tolist())
            for d in b["joint"]["dofs"]:
                j = body.add_joint(name=d["name"], type=mujoco.mjtJoint.mjJNT_HINGE, axis=d["axis"],
                                   range=d["range"], limited=mujoco.mjtLimited.mjLIMITED_TRUE)
                j.armature = ARMATURE
        frames[b["name"]] = origin
        mj_bodies[b["name"]] = body
        mass = b["mass"] + world.extra_mass.get(b["name"], 0.0)
        body.explicitinertial = True
        body.mass = mass
        body.ipos = (com - origin).tolist()
        inertia = np.array(b["inertia"]) * (mass / b["mass"])
        body.fullinertia = [inertia[0, 0], inertia[1, 1], inertia[2, 2], inertia[0, 1], inertia[0, 2], inertia[1, 2]]
        for k, shape in enumerate(b["shapes"]):
            _add_shape(body, shape, origin, f"{b['name']}_shape{k}")
        for c in b.get("contacts", []):
            g = body.add_geom(name=f"{b['name']}_{c['site']}", type=mujoco.mjtGeom.mjGEOM_SPHERE,
                              size=[c["radius"], 0, 0], pos=(np.array(c["pos"]) - origin).tolist())
            g.friction = [FOOT_FRICTION, 0.005, 0.0001]
            g.contype = g.conaffinity = CONTACT_GROUP
            g.group = 3
            body.add_site(name=f"{b['name']}_{c['site']}", pos=(np.array(c["pos"]) - origin - [0, 0, c["radius"]]).tolist())
    sternum = character.body("STERNUM")
    mj_bodies["STERNUM"].add_site(name="push_point", pos=(np.array(sternum["com"]) - frames["STERNUM"]).tolist())

    for dof in character.dofs:
        act = spec.add_actuator(name=dof.name, target=dof.name, trntype=mujoco.mjtTrn.mjTRN_JOINT)
        act.set_to_position(kp=dof.kp, kv=dof.kv)
        act.ctrllimited = mujoco.mjtLimited.mjLIMITED_FALSE
        if torque_scale is not None:
            act.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
            act.forcerange = [-dof.torque_limit * torque_scale, dof.torque_limit * torque_scale]
        else:
            act.forcelimited = mujoco.mjtLimited.mjLIMITED_FALSE
    _exclude_touching_pairs(spec, character)
    return spec


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


def _exclude_touching_pairs(spec: mujoco.MjSpec, character: CharacterSpec) -> None:
    """Bodies whose shapes already touch in the standing pose (e.g. an upper arm against the
    chest) would push each other apart from the first step; exclude those pairs, keep all others
    colliding so limbs cannot pass through each other. (Parent and child never collide in MuJoCo.)"""
    model = spec.compile()
    data = mujoco.MjData(model)
    set_standing_pose(model, data, character)
    mujoco.mj_forward(model, data)
    pairs = set()
    for c in data.contact[: data.ncon]:
        if model.geom_bodyid[c.geom1] == 0 or model.geom_bodyid[c.geom2] == 0:     # the world's geoms
            continue
        b1, b2 = model.geom_bodyid[c.geom1], model.geom_bodyid[c.geom2]
        pairs.add(tuple(sorted((model.body(b1).name, model.body(b2).name))))
    pairs |= {tuple(sorted(pair)) for pair in SOFT_TISSUE_PAIRS}
    for a, b in sorted(pairs):
        spec.add_exclude(bodyname1=a, bodyname2=b)


def set_standing_pose(model: mujoco.MjModel, data: mujoco.MjData, character: CharacterSpec) -> None:
    """Reference configuration with the spec's standing pose; feet on the ground."""
    mujoco.mj_resetData(model, data)
    pelvis = character.bodies[0]
    data.qpos[:3] = pelvis["com"]
    data.qpos[3:7] = [1, 0, 0, 0]
    for i, dof in enumerate(character.dofs):
        data.qpos[model.joint(dof.name).qposadr[0]] = character.standing_pose[i]


def compile_model(character: CharacterSpec, world: World | None = None, strength="human") -> tuple[mujoco.MjModel, str]:
    """Return (model, mjcf_text); the model is compiled from the text (see module doc)."""
    xml = build_mjspec(character, world, strength).to_xml()
    return mujoco.MjModel.from_xml_string(xml), xml
