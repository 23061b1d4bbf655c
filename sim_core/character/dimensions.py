"""The measures Hodgins & Pollard 1997 give per character (Fig. 3), taken from a spec.

Fig. 3 has 17 segments: head, torso, pelvis, legs of 4 parts and arms of 3. Our 21 bodies map
onto them with the shoulder girdle (CHESTR, CHESTL: no arm joint of the seed's model moves it) in
the torso. The figure does not define its lengths; we measure, in the reference configuration:
  height       top of the head above the ground;
  leg length   hip joint to ankle joint (the two-link leg of the controllers);
  arm length   shoulder joint to wrist joint;
  hip spacing  between the two hip joints.
Its three moments of inertia are those mass scaling uses ([B] 280), about the pitch (Y) axis in
the standing pose: the leg about its hip; the whole body about the ankle; and the body the stance
hip moves, everything but the stance leg, about that hip. (Measured this way the thesis woman,
53.3 kg, has 44.0 and 6.0 kg m^2 against Fig. 3's 54.6 kg woman's 45.4 and 6.5.)
"""
from __future__ import annotations

import numpy as np

from .mass_properties import StandingBody
from .spec import CharacterSpec

SEGMENTS = {
    "head": ("HEAD",),
    "torso": ("CHEST3", "CHEST2", "CHEST1", "STERNUM", "CHESTR", "CHESTL"),
    "pelvis": ("PELVIS",),
    "leg": ("ULEGR", "LLEGR", "FOOTR", "TOER"),
    "arm": ("UARMR", "LARMR", "HANDR"),
}
PITCH = np.array([0.0, 1.0, 0.0])


def fig3_measures(character: CharacterSpec) -> dict[str, float]:
    """Fig. 3's rows for ``character``: masses in kg ('<segment> mass', legs and arms each, the
    right side), lengths in m, moments of inertia in kg m^2."""
    standing = StandingBody(character)
    joint = character.joint_position
    out = {f"{segment} mass": standing.mass(bodies) for segment, bodies in SEGMENTS.items()}
    out.update({
        "height": float(character.data["height"]),
        "leg length": float(np.linalg.norm(joint("ULEGR") - joint("FOOTR"))),
        "arm length": float(np.linalg.norm(joint("UARMR") - joint("HANDR"))),
        "hip spacing": float(np.linalg.norm(joint("ULEGR") - joint("ULEGL"))),
    })
    hip, ankle = standing.joint_anchor("hip_r_y"), standing.joint_anchor("ankle_r_y")
    leg = standing.subtree("ULEGR")
    everything = standing.all_bodies()
    out.update({
        "leg / hip": standing.inertia_about(leg, hip, PITCH),
        "body / ankle": standing.inertia_about(everything, ankle, PITCH),
        "body / hip": standing.inertia_about(everything - leg, hip, PITCH),
    })
    return out


def leg_length_ratio(old: CharacterSpec, new: CharacterSpec) -> float:
    """L of Fig. 6 for runners ([B] 144): ``new``'s leg length over ``old``'s (hip joint to ankle joint)."""
    return fig3_measures(new)["leg length"] / fig3_measures(old)["leg length"]
