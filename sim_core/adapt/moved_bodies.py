"""Which bodies a joint's gain moves, and their moment of inertia (the I of mass scaling).

The seed's rule of thumb ([B] 280, 204-206): of the two bodies (or chains) on either side of a
joint, the lighter is the one the joint's torque mostly moves, unless it touches the ground; then
it is the other. Inertias are taken once, in the upright standing pose ([B] 210-215), about the
joint's axis. For the servos of a standing character the feet are on the ground, so the leg
joints move the body above them (the stance hip: the body about the hip; the stance ankle: the
body about the ankle) and the trunk, neck and arm joints move what is outboard of them. A
per-state controller gain (swing hip: the leg about the hip) names its side explicitly with
``side`` instead.
"""
from __future__ import annotations

from .scaling import ScaleFactors
from ..character.mass_properties import StandingBody


def moved_bodies(standing: StandingBody, dof: str, side: str = "rule") -> frozenset[str]:
    """The bodies ``dof``'s torque moves: ``side`` 'rule' (the seed's rule above), 'outboard'
    (the chain beyond the joint) or 'inboard' (the rest of the body)."""
    model = standing.model
    body = standing.names[model.jnt_bodyid[model.joint(dof).id]]
    outboard = standing.subtree(body)
    inboard = standing.all_bodies() - outboard
    if side == "outboard":
        return frozenset(outboard)
    if side == "inboard":
        return frozenset(inboard)
    if side != "rule":
        raise ValueError(f"side {side!r} must be 'rule', 'outboard' or 'inboard'")
    lighter, heavier = sorted((outboard, inboard), key=standing.mass)
    return frozenset(heavier if lighter & standing.grounded else lighter)


def moved_inertia(standing: StandingBody, dof: str, bodies=None) -> float:
    """Moment of inertia (kg m^2) of ``bodies`` (default: moved_bodies by the rule) about the axis
    of ``dof`` through its joint, in the standing pose."""
    bodies = moved_bodies(standing, dof) if bodies is None else bodies
    return standing.inertia_about(bodies, standing.joint_anchor(dof), standing.joint_axis(dof))


def gain_factors(old: StandingBody, new: StandingBody, dof: str, length: float, side: str = "rule") -> ScaleFactors:
    """The Fig. 6 factors of a gain of ``dof`` that moves ``side`` (see moved_bodies): the bodies
    are chosen on ``old`` and measured in both, M and I the ratios of their mass and of their
    inertia about the joint's axis; ``length`` is the character's L."""
    bodies = moved_bodies(old, dof, side)
    return ScaleFactors(length=length, mass=new.mass(bodies) / old.mass(bodies),
                        inertia=moved_inertia(new, dof, bodies) / moved_inertia(old, dof, bodies))
