"""Vaulting apparatus as props (issue 31 part 1): a springboard on a linear spring-damper, a vaulting
table (or the 1987 horse) of competition dimensions, and a landing mat softer than the floor.

Each is one ``@prop_builder`` function adding named geoms ("springboard", "vault_table",
"landing_mat"), so the trajectory's contact_force has a column for each. The springboard is the one
prop that moves: its top is a body (named with ``PROP_BODY_PREFIX``, which no actor's name can
carry) on a vertical slide joint whose joint stiffness and damping ARE the spring-damper (a force in
N/m, not a contact softness, so the deflection under a load is the load over the stiffness).
Figures and their sources: docs/vault.md, "Apparatus"."""
from __future__ import annotations

import math

import mujoco
import numpy as np

from ..ballistics import GRAVITY
from ..errors import ParameterError
from .props import _felt, prop_builder
from .world import World

PROP_BODY_PREFIX = "prop:"     # a moving prop's body; ':' is not allowed in an actor's name

# Springboard (FIG Apparatus Norms: 1.20 m x 0.60 m, front ~0.20 m high). The stiffness is chosen so
# that a gymnast's ~5 kN board force deflects it 0.125 m, and so that the half period of the woman
# (53.3 kg) on it, pi*sqrt(m/k) = 0.12 s, falls in Takei's board contact range (0.11-0.15 s).
BOARD_LENGTH, BOARD_WIDTH, BOARD_TOP = 1.20, 0.60, 0.20       # m; BOARD_TOP: the top at rest
BOARD_THICKNESS = 0.05          # m: the deck
BOARD_MASS = 5.0                # kg: the moving deck (a whole board weighs ~20-25 kg, most of it the base)
BOARD_STIFFNESS = 40000.0       # N/m: the board's default (a World may give its own: springboard=(x, y, stiffness))
BOARD_STIFFNESS_RANGE = (10000.0, 200000.0)   # N/m: what is refused outside (a board's springs are set for the
                                              # gymnast's weight: docs/vault.md "Apparatus")
BOARD_DAMPING = 250.0           # N s/m: damping ratio ~0.08 with a 53 kg gymnast (the board rebounds)
BOARD_TRAVEL = 0.14             # m: the deck bottoms out 1 cm above the floor

# Vaulting table (FIG Apparatus Norms, since 2001): 1.20 m long, 0.95 m wide, 1.25 m high (women),
# 1.35 m (men). The 1987 women's horse of Takei's data: sideways, 1.20 m high, 1.60 m long, 0.35 m wide.
VAULT_TABLE_LENGTH, VAULT_TABLE_WIDTH = 1.20, 0.95
VAULT_TABLE_HEIGHT_WOMEN, VAULT_TABLE_HEIGHT_MEN = 1.25, 1.35
HORSE_1987_HEIGHT, HORSE_1987_LENGTH, HORSE_1987_WIDTH = 1.20, 1.60, 0.35
VAULT_HEIGHT_RANGE, VAULT_SIZE_RANGE = (0.8, 1.6), (0.2, 2.0)    # m: what is refused outside

# Landing mat (FIG: 0.20 m thick vault landing mats). Softer than the floor by its own contact
# solref/solimp, used for every contact on it (priority over the character's geoms): a standing
# person sinks ~4 cm, and a vault's landing (4 m/s down) ~11 cm without reaching the floor
# (measured by tests/test_apparatus.py and tests/test_vault.py; figures in docs/vault.md). The
# softness is in the impedance, low at the surface and rising with the depth (as foam stiffens when
# it is compressed), not in a long time constant: MuJoCo's contact is a spring-damper of that time
# constant in acceleration space, and one of 0.16 s let a landing sink v * tau ~ 0.6 m, through the mat.
LANDING_MAT_THICKNESS = 0.20
LANDING_MAT_SOLREF = (0.02, 1.0)                  # time constant (s), critically damped (the floor's)
LANDING_MAT_SOLIMP = (0.3, 0.95, 0.10, 0.5, 2.0)  # impedance 0.3 at the surface -> 0.95 at 10 cm deep
MAT_THICKNESS_RANGE, MAT_SIZE_RANGE = (0.05, 0.5), (0.5, 20.0)
MAX_POSITION = 1000.0


POSITION = (-MAX_POSITION, MAX_POSITION)
# each apparatus field: its values in order, each with its allowed range (m unless APPARATUS_UNITS says)
APPARATUS_LAYOUT = {
    "springboard": {"x": POSITION, "y": POSITION, "stiffness": BOARD_STIFFNESS_RANGE},
    "vault_table": {"x": POSITION, "y": POSITION, "height": VAULT_HEIGHT_RANGE, "length": VAULT_SIZE_RANGE,
                    "width": VAULT_SIZE_RANGE},
    "landing_mat": {"x": POSITION, "y": POSITION, "length": MAT_SIZE_RANGE, "width": MAT_SIZE_RANGE,
                    "thickness": MAT_THICKNESS_RANGE},
}


APPARATUS_UNITS = {"stiffness": "N/m"}
APPARATUS_DEFAULTS = {"springboard": {"stiffness": BOARD_STIFFNESS}}   # trailing values a World may leave out


def check_apparatus(field: str, value) -> tuple:
    """``value`` of the World field ``field`` (see APPARATUS_LAYOUT) as a tuple of floats, the values
    left out filled from APPARATUS_DEFAULTS, or a one-line refusal naming the bad value and its
    allowed range."""
    layout, defaults = APPARATUS_LAYOUT[field], APPARATUS_DEFAULTS.get(field, {})
    if not (isinstance(value, (tuple, list)) and len(layout) - len(defaults) <= len(value) <= len(layout)):
        given = ", ".join(n for n in layout if n not in defaults) + "".join(f"[, {n}]" for n in defaults)
        units = "".join(f" ({n} in {APPARATUS_UNITS.get(n, 'm')})" for n in defaults)
        raise ParameterError(f"{field}={value!r} must be ({given}) in m{units}")
    for (name, (lo, hi)), v in zip(layout.items(), value):
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) or not lo <= v <= hi:
            raise ParameterError(f"{field} {name}={v!r} is out of range; allowed range is [{lo:g}, {hi:g}] "
                                 f"{APPARATUS_UNITS.get(name, 'm')}")
    return tuple(float(v) for v in value) + tuple(defaults[n] for n in list(layout)[len(value):])


@prop_builder("springboard")
def add_springboard(spec: mujoco.MjSpec, world: World, character) -> None:
    """The deck "springboard" on a vertical slide "prop:springboard/deflection": joint stiffness
    the World's (BOARD_STIFFNESS unless it gives one) and damping BOARD_DAMPING, spring reference set
    so the deck rests at qpos = 0 (top at BOARD_TOP) under its own weight; a limit at BOARD_TRAVEL is
    its bottoming out."""
    if not world.springboard:
        return
    x, y, stiffness = check_apparatus("springboard", world.springboard)
    size = np.array([BOARD_LENGTH, BOARD_WIDTH, BOARD_THICKNESS])
    body = spec.worldbody.add_body(name=PROP_BODY_PREFIX + "springboard",
                                   pos=[x, y, world.floor + BOARD_TOP - BOARD_THICKNESS / 2])
    body.mass, body.ipos = BOARD_MASS, [0.0, 0.0, 0.0]
    body.fullinertia = list(BOARD_MASS / 12 * (size @ size - size ** 2)) + [0.0, 0.0, 0.0]   # a solid box's
    body.explicitinertial = True                 # kept in the model's XML (the trajectory's)
    body.add_joint(name=PROP_BODY_PREFIX + "springboard/deflection", type=mujoco.mjtJoint.mjJNT_SLIDE,
                   axis=[0, 0, 1], stiffness=stiffness, damping=BOARD_DAMPING,
                   springref=BOARD_MASS * GRAVITY / stiffness, limited=mujoco.mjtLimited.mjLIMITED_TRUE,
                   range=[-BOARD_TRAVEL, BOARD_TRAVEL])
    deck = body.add_geom(name="springboard", type=mujoco.mjtGeom.mjGEOM_BOX,
                         size=list(size / 2), rgba=[0.85, 0.75, 0.55, 1])
    _felt(deck)


@prop_builder("vault_table")
def add_vault_table(spec: mujoco.MjSpec, world: World, character) -> None:
    """The vaulting table (or horse) "vault_table": a block from the floor up to its top."""
    if not world.vault_table:
        return
    x, y, height, length, width = check_apparatus("vault_table", world.vault_table)
    _felt(spec.worldbody.add_geom(name="vault_table", type=mujoco.mjtGeom.mjGEOM_BOX,
                                  size=[length / 2, width / 2, height / 2], pos=[x, y, world.floor + height / 2],
                                  rgba=[0.55, 0.35, 0.25, 1]))


@prop_builder("landing_mat")
def add_landing_mat(spec: mujoco.MjSpec, world: World, character) -> None:
    """The landing mat "landing_mat" on the floor, its top at ``thickness``, softer than the floor
    (LANDING_MAT_SOLREF/SOLIMP, used for its contacts by priority)."""
    if not world.landing_mat:
        return
    x, y, length, width, thickness = check_apparatus("landing_mat", world.landing_mat)
    mat = spec.worldbody.add_geom(name="landing_mat", type=mujoco.mjtGeom.mjGEOM_BOX,
                                  size=[length / 2, width / 2, thickness / 2],
                                  pos=[x, y, world.floor + thickness / 2], rgba=[0.2, 0.35, 0.7, 1])
    _felt(mat)
    mat.solref, mat.solimp, mat.priority = list(LANDING_MAT_SOLREF), list(LANDING_MAT_SOLIMP), 1


def world_geom_mask(model: mujoco.MjModel) -> np.ndarray:
    """Per geom: is it the world's (on the world body or on a moving prop's body such as the
    springboard's deck)? What a character stands on and what contact_force has columns for."""
    prop = np.array([model.body(b).name.startswith(PROP_BODY_PREFIX) for b in range(model.nbody)])
    prop[0] = True
    return prop[model.geom_bodyid]
