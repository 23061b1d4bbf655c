"""A skill's settings scaled from one character to another by Fig. 6 (Hodgins & Pollard 1997).

A settings row is a dict of named values; the skill's schema gives each its unit string, which
``Units.parse`` reads. Two ways, as the seed's Fig. 5/8 compare them:

- ``geometric``: every value by L^(l + t/2 + 3m) (L only: mass as L^3, inertia as L^5);
- ``mass``: lengths and times as above, and the mass of a gain replaced by the actual ratio of
  the bodies it moves (M = m'/m, or I = I'/I for a rotational gain: a torque, a torsional
  stiffness or damping, an inverse angular momentum).

Which bodies a gain moves is read off its name, the one name it has in the schema, the table and
the code (``gain_target``):

- ``pitch``, ``roll``, ``yaw`` and ``twist`` name the body's attitude held by the stance hip
  (Hodgins 1995: the stance hip servos the trunk's pitch, roll and yaw), so the gain drives the
  hip's DOF about that axis and moves, by the seed's rule, the body above the grounded leg (Fig. 3's
  "body / hip");
- a joint word (``hip``, ``knee``, ``ankle``, ``shoulder``, ...) names that joint's DOF (right
  side, the pitch axis unless an attitude word gives another); ``swing``, ``flight`` and ``idle``
  say the gain moves the limb (outboard), ``stance`` or none the seed's rule;
- any other name with a mass in its units (e.g. ``spin_kp``, rad per kg m^2/s of the whole body's
  angular momentum) is scaled by the **whole-body** ratio: the total mass ratio, and for a
  rotational one the ratio of the body's inertia about its own centre of mass (the mean over the
  three axes, in the standing pose). This is the documented fallback, not a measured choice.

A per-state gain given as a **share** of its servo's default gains (unit ``share``, e.g. the
idle knee's ``idle_knee_gain``) is dimensionless, but the default it multiplies is mass-scaled by
the bodies the seed's rule picks in the standing pose (servos.mass_scaled_servos: the body above a
grounded leg), while the state's gain moves its own state's bodies (``swing``/``flight``/``idle``:
the limb). In mass mode such a share is multiplied by the ratio of the two inertia ratios
(``CharacterPair.share_factor``), so the state's kp and kv come out as Fig. 6's per-state rule
says ([B] 204-206: "the bodies it moves in each state"). Measured on the Fig. 5/8 bodies
(docs/bodies.md): the idle knee's share x 0.90 at 25 %, x 0.70 at 70 % of the way to the woman.

L is the leg-length ratio, the seed's L for runners ([B] 144). A value equal to a setting's
``special`` (e.g. -1 = "as tuned") is a flag, not a quantity, and is kept.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .moved_bodies import gain_factors
from .scaling import ScaleFactors, Units, scale
from ..character.dimensions import leg_length_ratio
from ..character.mass_properties import StandingBody
from ..character.spec import CharacterSpec
from ..errors import ParameterError
from ..schema import Schema

GEOMETRIC, MASS = "geometric", "mass"
MODES = (GEOMETRIC, MASS)
ATTITUDE_AXES = {"pitch": "y", "roll": "x", "yaw": "z", "twist": "z"}   # the stance hip's DOF per attitude
JOINT_WORDS = ("hip", "knee", "ankle", "mt", "spine", "neck", "clav", "shoulder", "elbow", "wrist")
SIDE_WORDS = {"stance": "rule", "swing": "outboard", "flight": "outboard", "idle": "outboard"}
SHARE = "share"                             # the unit of a share of a servo's default gains
NOT_NUMBERS = ("choice", "points")          # knob kinds whose values are not quantities


@dataclass(frozen=True)
class GainTarget:
    """The DOF a gain drives and which side of it it moves (moved_bodies' ``side``); ``dof``
    None = the whole body."""
    dof: str | None
    side: str = "rule"


def gain_target(name: str, dof_names: list[str]) -> GainTarget:
    """What the setting ``name`` drives, read off its words (module docstring)."""
    words = name.split("_")
    axis = next((ATTITUDE_AXES[w] for w in words if w in ATTITUDE_AXES), None)
    joint = next((w for w in words if w in JOINT_WORDS), "hip" if axis else None)
    side = next((SIDE_WORDS[w] for w in words if w in SIDE_WORDS), "rule")
    if joint is None:
        return GainTarget(None)
    wanted = axis or "y"
    matches = [d for d in dof_names if d.startswith(f"{joint}_") and d.endswith(f"_{wanted}")]
    preferred = [d for d in matches if "_r_" in d] or matches
    if not preferred:
        return GainTarget(None)
    return GainTarget(preferred[0], side)


class CharacterPair:
    """The original and the new character in their standing pose, and L (default: the ratio of
    their leg lengths, hip joint to ankle joint)."""

    def __init__(self, old: CharacterSpec, new: CharacterSpec, length: float | None = None):
        self.old, self.new = StandingBody(old), StandingBody(new)
        self.old_spec, self.new_spec = old, new
        self.length = leg_length_ratio(old, new) if length is None else float(length)
        ScaleFactors(self.length)                          # refuses a non-positive L
        self.dof_names = [d.name for d in old.dofs]

    def factors(self, name: str, mode: str) -> ScaleFactors:
        """The Fig. 6 factors of the setting ``name`` for ``mode``."""
        if mode == GEOMETRIC:
            return ScaleFactors(self.length)
        if mode != MASS:
            raise ParameterError(f"scaling mode {mode!r} must be one of {', '.join(MODES)}")
        target = gain_target(name, self.dof_names)
        if target.dof is not None:
            return gain_factors(self.old, self.new, target.dof, self.length, target.side)
        return ScaleFactors(self.length, mass=self.new.mass(self.new.all_bodies()) / self.old.mass(self.old.all_bodies()),
                            inertia=_central_inertia(self.new) / _central_inertia(self.old))


    def share_factor(self, name: str, mode: str) -> float:
        """The factor of the gain share ``name`` (unit ``share``, module docstring): in mass mode,
        I'/I of the bodies its state moves over I'/I of those its servo's default was scaled by;
        1 in geometric mode, and where the two are the same bodies."""
        if mode == GEOMETRIC:
            return 1.0
        target = gain_target(name, self.dof_names)
        if target.dof is None or target.side == "rule":
            return 1.0
        own = gain_factors(self.old, self.new, target.dof, self.length, target.side)
        servo = gain_factors(self.old, self.new, target.dof, self.length)
        return own.inertia / servo.inertia


def _central_inertia(standing: StandingBody) -> float:
    """The whole body's moment of inertia about its centre of mass, mean over the three axes."""
    com = standing.data.subtree_com[0]                  # the world body's subtree: the whole character
    return float(np.mean([standing.inertia_about(standing.all_bodies(), com, axis) for axis in np.eye(3)]))


def setting_units(schema: Schema, name: str) -> Units | None:
    """The units of ``schema``'s setting ``name`` (None for a choice or a list of points)."""
    if name not in schema.by_name:
        raise ParameterError(f"setting {name!r} is not in the schema; known: {', '.join(schema.by_name)}")
    knob = schema.by_name[name]
    if getattr(knob, "kind", None) in NOT_NUMBERS or knob.unit in NOT_NUMBERS:
        return None
    return Units.parse(knob.unit)


def scale_settings(row: dict, schema: Schema, pair: CharacterPair, mode: str) -> dict:
    """``row`` (settings of ``schema``, tuned for ``pair.old``) scaled for ``pair.new``."""
    out = {}
    for name, value in row.items():
        units = setting_units(schema, name)
        special = getattr(schema.by_name[name], "special", None)
        if units is None or isinstance(value, bool) or (special is not None and value == special):
            out[name] = value
        elif schema.by_name[name].unit == SHARE:
            out[name] = float(value) * pair.share_factor(name, mode)
        else:
            out[name] = scale(float(value), units, pair.factors(name, mode))
    return out


def scale_constants(constants: dict, schema: Schema, pair: CharacterPair, mode: str) -> dict:
    """A controller's constants (numbers, lists or maps of numbers, as a ``<table>_any.json`` holds
    them) scaled for ``pair.new``, every number by its constant's units and held inside the
    constant's sanity range."""
    def each(name, value):
        if isinstance(value, (list, tuple)):
            return [each(name, v) for v in value]
        if isinstance(value, dict):
            return {k: each(name, v) for k, v in value.items()}
        knob = schema.by_name[name]
        return min(max(scale_settings({name: value}, schema, pair, mode)[name], knob.minimum), knob.maximum)
    return {name: each(name, value) for name, value in constants.items()}


def scale_columns(speeds: list[float], columns: dict[str, list[float]], schema: Schema, pair: CharacterPair,
                  mode: str) -> tuple[list[float], dict[str, list[float]]]:
    """A table scheduled over the running speed (m/s): the speeds scale as velocities (x L^1/2,
    Fig. 6 "desired forward speed"), each column's values by its own units."""
    velocity = Units.parse("m/s")
    new_speeds = [scale(float(v), velocity, ScaleFactors(pair.length)) for v in speeds]
    rows = [scale_settings({n: col[k] for n, col in columns.items()}, schema, pair, mode) for k in range(len(speeds))]
    return new_speeds, {n: [row[n] for row in rows] for n in columns}
