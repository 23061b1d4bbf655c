"""Mass scaling of a spec's joint servos (Fig. 6): each DOF's stiffness kp (N m/rad) by
I'/I L^-1, its damping kv (N m s/rad) by I'/I L^-1/2 and its torque limit (N m) by I'/I L^-1,
with I'/I the ratio of the inertias of the bodies the DOF moves (moved_bodies, the same bodies
in both characters) and L the leg-length ratio (the seed's choice of L for runners, [B] 144).

The spec's ``time_scale`` (its physics step and control period against the man's) is a time, so
both columns scale it by L^1/2 (``scaled_time_scale``): Fig. 6 scales "the integration time step"
([B] 132-138) with the controller."""
from __future__ import annotations

import copy

from .moved_bodies import gain_factors
from .scaling import TIME, TORQUE, TORSIONAL_DAMPING, TORSIONAL_STIFFNESS, ScaleFactors, scale
from ..character.mass_properties import StandingBody
from ..character.spec import CharacterSpec

SERVO_UNITS = {"kp": TORSIONAL_STIFFNESS, "kv": TORSIONAL_DAMPING, "torque_limit": TORQUE}


def scaled_time_scale(old: CharacterSpec, length_ratio: float) -> float:
    """The time scale of a body made from ``old`` with leg-length ratio L: old's x L^1/2 (Fig. 6's time
    row; both of its columns). From the man (time scale 1): L^1/2 against his 1 ms and control rates."""
    return scale(old.time_scale, TIME, ScaleFactors(length_ratio))


def mass_scaled_servos(new_data: dict, old: CharacterSpec, length_ratio: float) -> dict:
    """``new_data`` (a reshaped copy of ``old``) with every DOF's kp, kv and torque limit scaled
    from ``old``'s by Fig. 6's mass-scaling column."""
    old_standing, new_standing = StandingBody(old), StandingBody(CharacterSpec(new_data))
    old_dofs = {d.name: d for d in old.dofs}
    out = copy.deepcopy(new_data)
    for body in out["bodies"]:
        for dof in (body.get("joint") or {}).get("dofs", []):
            factors = gain_factors(old_standing, new_standing, dof["name"], length_ratio)
            for key, units in SERVO_UNITS.items():
                dof[key] = scale(getattr(old_dofs[dof["name"]], key), units, factors)
    return out


CONTROLLERS = ("unscaled", "geometric", "mass")     # the three controllers of the seed's Fig. 5/8


def controller_servos(new_data: dict, old: CharacterSpec, length_ratio: float, controller: str) -> dict:
    """``new_data`` with the servos and the timing of ``old``'s controller carried over as
    ``controller`` says: 'unscaled' (old's kp, kv, torque limits and time scale as they are),
    'geometric' (Fig. 6 with L only) or 'mass' (mass_scaled_servos); the time scale x L^1/2 in both."""
    if controller not in CONTROLLERS:
        raise ValueError(f"controller {controller!r} must be one of {', '.join(CONTROLLERS)}")
    if controller == "mass":
        out = mass_scaled_servos(new_data, old, length_ratio)
    else:
        geometric = ScaleFactors(length_ratio)
        old_dofs = {d.name: d for d in old.dofs}
        out = copy.deepcopy(new_data)
        for body in out["bodies"]:
            for dof in (body.get("joint") or {}).get("dofs", []):
                for key, units in SERVO_UNITS.items():
                    value = getattr(old_dofs[dof["name"]], key)
                    dof[key] = value if controller == "unscaled" else scale(value, units, geometric)
    out["time_scale"] = old.time_scale if controller == "unscaled" else scaled_time_scale(old, length_ratio)
    return out

