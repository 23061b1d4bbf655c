"""New characters from existing specs: a body some fraction of the way between two characters,
and a character scaled to a height and a mass (the Fig. 3 presets are sim_core.character.fig3).
Each returns spec data that CharacterSpec validates and compile_model compiles;
``write_character`` stores it.

    python -m sim_core character make --preset child                  # -> rigs/child.json
    python -m sim_core character make --from man --to woman --fraction 0.7 --out F.json
    python -m sim_core character make --from man --height 1.5 --mass 60 --out F.json
"""
from __future__ import annotations

import copy
import json
import math
import re
from pathlib import Path

from ..adapt.servos import mass_scaled_servos, scaled_time_scale
from .dimensions import leg_length_ratio
from .morph import lerp
from .reshape import BodyScale, reshaped, standing_height
from .spec import RIGS_DIR, CharacterSpec
from ..files import write_atomically
from ..errors import ParameterError

HEIGHT_RANGE = (0.8, 2.2)          # m: issue 28's range for a character made to a height
MASS_RANGE = (10.0, 200.0)         # kg
# The long axis of each body in the reference configuration (T-pose): legs and trunk along Z,
# arms and the shoulder girdle along Y, feet and toes along X. The head (a sphere) and the hands
# (boxes along the forearm) are scaled as geometric copies.
AXIS_OF = {"UARM": 1, "LARM": 1, "CHESTR": 1, "CHESTL": 1, "FOOT": 0, "TOE": 0}
UNIFORM = ("HEAD", "HAND")
HEIGHT_ITERATIONS = 6              # fixed-point steps of the height fit (each cuts the error ~10x)


def long_axis(body: str) -> int:
    for prefix, axis in AXIS_OF.items():
        if body.startswith(prefix):
            return axis
    return 2


def check_fraction(fraction: float) -> None:
    if not (math.isfinite(fraction) and 0.0 <= fraction <= 1.0):
        raise ParameterError(f"--fraction={fraction:g} is out of range; allowed range is [0, 1]")


def between(a: CharacterSpec, b: CharacterSpec, fraction: float, name: str | None = None) -> dict:
    """The character ``fraction`` of the way from ``a`` to ``b``: every number of the bodies
    (masses, COMs, inertias, joint positions, shapes, contacts, servo gains, torque limits)
    interpolated linearly, as the seed's intermediate characters are ([B] 65). Its time scale
    (physics step and control period) is ``a``'s x L^1/2, L its leg length over ``a``'s (Fig. 6)."""
    check_fraction(fraction)
    if a.body_names != b.body_names or [d.name for d in a.dofs] != [d.name for d in b.dofs]:
        raise ParameterError(f"{a.name} and {b.name} have different bodies or joints; only characters "
                             "of the same skeleton can be interpolated")
    out = copy.deepcopy(a.data)
    out["bodies"] = _mix(a.data["bodies"], b.data["bodies"], fraction)
    out["standing_pose"] = _mix(a.data["standing_pose"], b.data["standing_pose"], fraction)
    out["total_mass"] = float(sum(body["mass"] for body in out["bodies"]))
    out["height"] = standing_height(out)
    out["name"] = name or f"{a.name}_{b.name}_{round(100 * fraction)}"
    out["source"] = f"{100 * fraction:g} % of the way from {a.name} to {b.name} (linear interpolation)"
    out["strength"] = {"interpolated": [a.name, b.name], "note": "kp, kv and torque limits interpolated"}
    out["made"] = {"from": a.name, "to": b.name, "fraction": fraction}
    out["time_scale"] = scaled_time_scale(a, leg_length_ratio(a, CharacterSpec(out)))
    return out


def _mix(x, y, t):
    """Numbers interpolated, everything else (names, types) taken from ``x``; same structure."""
    if isinstance(x, bool) or x is None or isinstance(x, str):
        return x
    if isinstance(x, (int, float)):
        return lerp(x, y, t)
    if isinstance(x, list):
        return [_mix(u, v, t) for u, v in zip(x, y, strict=True)]
    if isinstance(x, dict):
        return {k: _mix(x[k], y[k], t) for k in x}
    raise TypeError(f"cannot interpolate {type(x).__name__}")


def scaled_to(base: CharacterSpec, height: float, mass: float, name: str | None = None) -> dict:
    """``base`` scaled to ``height`` (m, top of the head) and ``mass`` (kg): every body's long axis
    by one factor, found so the height comes out right, every mass by mass / base's total (the
    proportions and densities of ``base``); servos mass-scaled and the time scale x L^1/2 (Fig. 6),
    L = the leg-length ratio."""
    if not (math.isfinite(height) and HEIGHT_RANGE[0] <= height <= HEIGHT_RANGE[1]):
        raise ParameterError(f"--height={height:g} m is out of range; allowed range is "
                             f"[{HEIGHT_RANGE[0]:g}, {HEIGHT_RANGE[1]:g}] m")
    if not (math.isfinite(mass) and MASS_RANGE[0] <= mass <= MASS_RANGE[1]):
        raise ParameterError(f"--mass={mass:g} kg is out of range; allowed range is "
                             f"[{MASS_RANGE[0]:g}, {MASS_RANGE[1]:g}] kg")
    mass_ratio = mass / base.total_mass
    axial = height / base.data["height"]
    for _ in range(HEIGHT_ITERATIONS):
        data = reshaped(base.data, {b: BodyScale.uniform(mass_ratio) if b.startswith(UNIFORM)
                                    else BodyScale.stretched(long_axis(b), axial, mass_ratio) for b in base.body_names})
        axial *= height / data["height"]
    leg_ratio = leg_length_ratio(base, CharacterSpec(data))
    data = mass_scaled_servos(data, base, leg_ratio)
    data["name"] = name or f"{base.name}_{round(100 * height)}cm_{round(mass)}kg"
    data["source"] = f"{base.name} scaled to {height:g} m and {mass:g} kg (sim_core.character.make)"
    data["strength"] = {"scaled_from": base.name, "note": "kp, kv and torque limits mass-scaled (Fig. 6)"}
    data["made"] = {"from": base.name, "height": height, "mass": mass}
    data["time_scale"] = scaled_time_scale(base, leg_ratio)
    return data


def write_character(data: dict, out: str | Path | None = None) -> Path:
    """Validate ``data`` (and that it compiles) and write it whole to ``out`` (default
    rigs/<name>.json, where load_character finds it by name; never over a spec build.py made)."""
    from .model import compile_model
    if not re.fullmatch(r"[a-z][a-z0-9_]*", data["name"]):
        raise ParameterError(f"character name {data['name']!r} must be lower-case letters, digits and '_'")
    spec = CharacterSpec(data, str(out or data["name"]))
    compile_model(spec)
    path = Path(out) if out else RIGS_DIR / f"{data['name']}.json"
    if path.suffix != ".json":
        raise ParameterError(f"--out {str(path)!r} must end in .json")
    if not out and path.exists() and "made" not in json.loads(path.read_text()):
        raise ParameterError(f"rigs/{path.name} is not a made character (build.py makes it); "
                             "choose another --name or give --out")
    write_atomically(path, json.dumps(data, indent=1) + "\n")
    return path

