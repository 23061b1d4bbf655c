"""What the thesis leaves open, added to the SD/FAST data to make a complete character.

Every number here has its source beside it. The SD/FAST files give masses, inertias, centres of
mass, joint positions and axes (Wooten 1998, App. A); this module adds names, anatomical joint
ranges, human-plausible torque limits, servo gains, segment densities (Wooten Table 3.1, from
Dempster & Gaughran 1967) and the shapes used for contact and for the skin.

Sources, cited by key below:
  [W98]   Wooten 1998, thesis (Tables 3.1-3.4, §3.1.1 foot contact, §7.1 ankle limits).
  [AAOS]  American Academy of Orthopaedic Surgeons, "Joint Motion: Method of Measuring and
          Recording" (1965) / Norkin & White, "Measurement of Joint Motion" (2016): average
          active ranges of motion of adults.
  [AND07] Anderson, Madigan & Nussbaum 2007, "Maximum voluntary joint torque as a function of
          joint angle and angular velocity", J. Biomech. 40:3105 (hip, knee, ankle peaks of
          young men, ~150-300 N m).
  [KUL84] Kulig, Andrews & Hay 1984, "Human strength curves", Exerc. Sport Sci. Rev. 12:417
          (trunk, shoulder, elbow, wrist, neck peaks).
  [MILLER93] Miller et al. 1993, Eur. J. Appl. Physiol. 66:254: women's peak joint torques are
          ~50-70 % of men's; we use 0.65 for the woman.
"""
from __future__ import annotations

import math

import numpy as np

from .sdfast import SdBody

# SD/FAST joint name -> our joint name. DOF names are '<joint>_<axis>' (e.g. 'hip_r_y').
JOINT_NAMES = {
    "SPINEL3": "spine_l3", "SPINEL1": "spine_l1", "SPINET7": "spine_t7", "SPINET4": "spine_t4",
    "NECKC2": "neck_c2", "HIPR": "hip_r", "HIPL": "hip_l", "KNEER": "knee_r", "KNEEL": "knee_l",
    "ANKLER": "ankle_r", "ANKLEL": "ankle_l", "MTR": "mt_r", "MTL": "mt_l",
    "CLAVR": "clav_r", "CLAVL": "clav_l", "SHLDR": "shoulder_r", "SHLDL": "shoulder_l",
    "ELBR": "elbow_r", "ELBL": "elbow_l", "WRSTR": "wrist_r", "WRSTL": "wrist_l",
}

# Segment density in kg/m^3 [W98 Table 3.1 after Dempster & Gaughran].
DENSITY = {
    "HEAD": 1171, "STERNUM": 1009, "CHEST1": 1009, "CHEST2": 1009, "CHEST3": 1029,
    "PELVIS": 1029, "ULEG": 1040, "LLEG": 1079, "FOOT": 1066, "TOE": 1066,
    "CHEST": 1009, "UARM": 1068, "LARM": 1102, "HAND": 1070,
}

# Sign conventions (thesis frame X forward, Y left, Z up; right-handed rotations):
#   +y at hip = extension, +y at knee = flexion, +y at ankle = plantarflexion,
#   +y at a spine joint = forward flexion, +x at the right hip = adduction (mirror on the left),
#   +x at the right shoulder = arm down from the T-pose, +z at the right shoulder/elbow = forward.
# Ranges in degrees for the RIGHT side; the left side mirrors x and z. [AAOS] unless noted.
RANGE_DEG = {
    "spine_l3": {"x": (-10, 10), "y": (-8, 15), "z": (-10, 10)},
    "spine_l1": {"x": (-10, 10), "y": (-8, 15), "z": (-10, 10)},
    "spine_t7": {"x": (-8, 8), "y": (-5, 12), "z": (-12, 12)},
    "spine_t4": {"x": (-8, 8), "y": (-5, 12), "z": (-12, 12)},
    "neck_c2": {"x": (-40, 40), "y": (-60, 50), "z": (-70, 70)},
    "hip": {"y": (-125, 30), "x": (-45, 30), "z": (-45, 45)},
    "knee": {"y": (-2, 150)},
    "ankle": {"x": (-20, 30), "y": (-40, 50)},      # dorsiflexion 40 deg: weight-bearing lunge
    "mt": {"y": (-70, 40)},
    "clav": {"x": (-15, 30), "z": (-25, 25)},
    "shoulder": {"x": (-90, 100), "y": (-90, 90), "z": (-60, 180)},
    "elbow": {"y": (-80, 80), "z": (0, 150)},
    "wrist": {"x": (-70, 70), "y": (-30, 30)},
}
# Mirror signs of the left side for each axis (lateral rotations flip, sagittal do not).
LEFT_MIRROR = {"x": -1, "y": 1, "z": -1}

# Peak isometric torque in N m for the man (symmetric limit per DOF) [AND07], [KUL84].
TORQUE_LIMIT_MAN = {
    "spine": {"x": 200, "y": 300, "z": 100},        # trunk extension ~300 N m [KUL84]
    "neck_c2": {"x": 40, "y": 50, "z": 30},
    "hip": {"y": 300, "x": 200, "z": 100},            # hip extension ~250-300 N m [AND07]
    "knee": {"y": 300},                                # knee extension ~250-300 N m [AND07]
    "ankle": {"x": 80, "y": 250},                      # plantarflexion ~200-250 N m [AND07]
    "mt": {"y": 60},
    "clav": {"x": 100, "z": 100},
    "shoulder": {"x": 110, "y": 60, "z": 110},        # shoulder flexion/abduction ~100 N m
    "elbow": {"y": 20, "z": 80},                       # elbow flexion ~70-80 N m [KUL84]
    "wrist": {"x": 20, "y": 15},
}
WOMAN_STRENGTH_RATIO = 0.65                            # [MILLER93]

# Servo proportional gains (N m/rad) for the man; kv = KV_RATIO * kp. Chosen empirically, as
# in [W98 §3.2]: stiff enough to hold the standing pose under gravity with < 2 deg error.
KP_MAN = {
    "spine": 2000, "neck_c2": 150, "hip": 1200, "knee": 1200, "ankle": 800, "mt": 800,
    "clav": 300, "shoulder": 250, "elbow": 80, "wrist": 15,
}
KV_RATIO = 0.08

# Standing pose (radians): arms hang at the sides from the T-pose reference configuration.
STANDING_POSE = {
    "shoulder_r_x": math.radians(82), "shoulder_l_x": -math.radians(82),
    "elbow_r_z": math.radians(12), "elbow_l_z": -math.radians(12),
}


def joint_family(joint: str) -> str:
    """'hip_r' -> 'hip', 'spine_l3' -> 'spine_l3' (families key the tables above)."""
    if joint.startswith("spine") or joint.startswith("neck"):
        return joint
    return joint.rsplit("_", 1)[0]


def dof_range(joint: str, axis: str) -> tuple[float, float]:
    lo, hi = RANGE_DEG[joint_family(joint)][axis]
    if joint.endswith("_l") and LEFT_MIRROR[axis] < 0:
        lo, hi = -hi, -lo
    return math.radians(lo), math.radians(hi)


def dof_torque_limit(joint: str, axis: str, strength_ratio: float) -> float:
    family = "spine" if joint.startswith("spine") else joint_family(joint)
    return TORQUE_LIMIT_MAN[family][axis] * strength_ratio


def dof_gains(joint: str, mass_ratio: float) -> tuple[float, float]:
    family = "spine" if joint.startswith("spine") else joint_family(joint)
    kp = KP_MAN[family] * mass_ratio
    return kp, KV_RATIO * kp


def segment_kind(body: str) -> str:
    for prefix in ("ULEG", "LLEG", "FOOT", "TOE", "UARM", "LARM", "HAND"):
        if body.startswith(prefix):
            return prefix
    if body in ("CHESTR", "CHESTL"):
        return "CHEST"
    return body


def capsule_radius(volume: float, length: float) -> float:
    """Radius of a capsule of the given volume whose axis (cap centres) has the given length."""
    radius = math.sqrt(volume / (math.pi * length))
    for _ in range(50):                 # Newton on pi r^2 L + 4/3 pi r^3 = V
        f = math.pi * radius**2 * length + 4 / 3 * math.pi * radius**3 - volume
        df = 2 * math.pi * radius * length + 4 * math.pi * radius**2
        radius -= f / df
    return radius


def segment_shapes(body: SdBody, joints: dict[str, np.ndarray], children: dict[str, list[str]],
                   scale: float) -> list[dict]:
    """Shapes in world coordinates of the reference configuration, sized so that
    volume x density = mass (the skin of issue 3 and the contact model both use them).

    ``joints`` maps body name -> world position of its inboard joint; ``scale`` is the
    character's height / the man's (1.0 for the man).
    """
    kind = segment_kind(body.name)
    volume = body.mass / DENSITY[kind]
    com = body.original_com
    own = joints.get(body.name)
    kids = children.get(body.name, [])

    def capsule(a, b, vol):
        r = capsule_radius(vol, float(np.linalg.norm(b - a)))
        return {"type": "capsule", "from": list(map(float, a)), "to": list(map(float, b)), "radius": r}

    if kind in ("ULEG", "LLEG", "UARM", "LARM"):
        end = joints[kids[0]]
        return [capsule(own, end, volume)]
    if kind == "CHEST":                       # shoulder girdle: clavicle joint -> shoulder joint
        return [capsule(own, joints[kids[0]], volume)]
    if kind == "HAND":
        # hand: a box from the wrist outward, through the hand's COM, thickness from volume
        direction = com - own
        direction[2] = 0.0
        length = 2.0 * float(np.linalg.norm(direction)) + 0.02
        unit = direction / np.linalg.norm(direction)
        width = 0.09 * scale
        thickness = volume / (length * width)
        centre = own + unit * length / 2
        return [{"type": "box", "pos": list(map(float, centre)),
                 "half": [length / 2, width / 2, thickness / 2], "along": list(map(float, unit))}]
    if kind == "HEAD":
        radius = (3 * volume / (4 * math.pi)) ** (1 / 3)
        return [{"type": "sphere", "pos": list(map(float, com)), "radius": radius}]
    if kind in ("FOOT", "TOE"):
        return []                              # feet: see foot_shapes()
    # torso segments and pelvis: an elliptic slab between the inboard joint and the next spine joint
    if kind == "PELVIS":
        bottom, top = joints["ULEGR"][2] - 0.06 * scale, joints["CHEST3"][2]
    elif kind == "STERNUM":
        bottom, top = own[2], joints["HEAD"][2]
    else:
        spine_child = [k for k in kids if k.startswith("CHEST") or k == "STERNUM"][0]
        bottom, top = own[2], joints[spine_child][2]
    height = top - bottom
    half_width = {"PELVIS": 0.16, "CHEST3": 0.15, "CHEST2": 0.15, "CHEST1": 0.16, "STERNUM": 0.12}[kind] * scale
    half_depth = volume / (math.pi * half_width * height)   # elliptic cylinder of that volume
    centre = np.array([com[0], 0.0, (bottom + top) / 2])
    return [{"type": "ellipse_slab", "pos": list(map(float, centre)),
             "half": [half_depth, half_width, height / 2]}]


def foot_contacts(foot: SdBody, toe: SdBody, ankle: np.ndarray, mt: np.ndarray,
                  scale: float, radius: float = 0.01) -> dict[str, list[dict]]:
    """Contact spheres at the heel and ball corners (FOOT) and the toe tip (TOE) [W98 §3.1.1].

    Heel 5.5 cm behind the ankle, ball at the metatarsal joint, toe tip as far ahead of the
    metatarsal joint as twice the toe's COM offset; corners at +/-3 cm (heel) and +/-4.5 cm
    (ball), scaled with height. All sphere bottoms touch z = 0 in the reference configuration.
    """
    y = foot.original_com[1]
    heel_x = ankle[0] - 0.055 * scale
    ball_x = mt[0]
    toe_x = mt[0] + 2.0 * (toe.original_com[0] - mt[0])
    half_heel, half_ball, half_toe = 0.03 * scale, 0.045 * scale, 0.035 * scale
    points = lambda x, h: [[x, y - h, radius], [x, y + h, radius]]
    return {
        foot.name: [{"type": "sphere", "pos": p, "radius": radius, "site": s}
                    for p, s in zip(points(heel_x, half_heel) + points(ball_x, half_ball),
                                    ["heel_a", "heel_b", "ball_a", "ball_b"])],
        toe.name: [{"type": "sphere", "pos": p, "radius": radius, "site": s}
                   for p, s in zip(points(toe_x, half_toe), ["toe_a", "toe_b"])],
    }


def foot_shapes(foot: SdBody, toe: SdBody, ankle: np.ndarray, mt: np.ndarray,
                scale: float) -> dict[str, list[dict]]:
    """Skin-only boxes for foot and toe (contact is by the spheres of foot_contacts), each of
    volume mass / density: the foot from heel to ball, the toe from ball to tip."""
    result = {}
    heel_x = ankle[0] - 0.055 * scale
    toe_x = mt[0] + 2.0 * (toe.original_com[0] - mt[0])
    for body, x0, x1, width in ((foot, heel_x, mt[0], 0.085 * scale), (toe, mt[0], toe_x, 0.08 * scale)):
        length = x1 - x0
        height = body.mass / DENSITY[segment_kind(body.name)] / (length * width)
        centre = [(x0 + x1) / 2, float(body.original_com[1]), height / 2]
        result[body.name] = [{"type": "box", "pos": centre, "half": [length / 2, width / 2, height / 2],
                              "along": [1.0, 0.0, 0.0], "contact": False}]
    return result
