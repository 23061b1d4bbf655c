"""The characters of Hodgins & Pollard 1997, Fig. 3, built from our man by per-segment scaling.

Fig. 3 gives, per character, the masses of five segments (legs and arms each), four lengths and
three joint-referenced moments of inertia, as ABSOLUTE values. Its man (~75 kg, 1.79 m) is not
ours (97.84 kg, 1.81 m), so its ratios do not carry over: each character is fitted to the
absolute values (SEEDS-WAVE2.md §5.3, trap 4). What the figure leaves open, we choose and say so:

  * how a leg's mass is shared between thigh and shank and how its length is shared between
    them: free, fitted, because the leg's inertia about the hip (Fig. 3) depends on it (the
    imaginary runner's 1.58 kg m^2 for a 6.84 kg, 0.72 m leg needs heavy shanks). The feet keep
    the man's share of the leg's mass: their footprint, which follows their mass at Dempster's
    density, is the support a standing character balances on;
  * how the torso's mass is shared between the lower (CHEST3, CHEST2) and upper trunk (CHEST1,
    STERNUM, shoulder girdle), and the trunk's width and height: fitted to the height and to the
    inertias about the ankle and the hip;
  * the height of the feet (the ankle's above the ground): Fig. 3's height, leg length and body/hip
    inertia pin where the hip and the head are, and for the imaginary runner they agree only with
    a higher ankle (its 5.98 kg head alone, 0.75 m above a hip at leg length over a man-like ankle,
    would take 3.4 of the 3.6 kg m^2 its body/hip leaves after the swing leg);
  * no trunk slice thinner front-to-back than a third of the man's same slice per stature
    (TRUNK_DEPTH_FLOOR, applied only where the fit's optimum breaks it: the imaginary runner);
  * the arm's parts keep the man's mass shares; head and hands are geometric copies of the man's
    at their new mass (Fig. 3 gives no head or hand length).

The fit is a bounded least-squares problem (SciPy's trust-region reflective) on the relative errors (sim_core.character.dimensions measures
each row the same way for every character), with a weak pull of the free shares towards the
man's. Segment masses are met exactly by construction. Servo gains and torque limits follow by
mass scaling (sim_core.adapt.servos), with L the leg-length ratio to the man.
"""
from __future__ import annotations

import math

import numpy as np
from scipy.optimize import least_squares

from ..adapt.servos import mass_scaled_servos, scaled_time_scale
from .dimensions import SEGMENTS, fig3_measures, leg_length_ratio
from .reshape import BodyScale, reshaped
from .spec import CharacterSpec
from ..errors import UnknownNameError

# Hodgins & Pollard 1997, Fig. 3 ([B] 71-91), absolute values (SEEDS-WAVE2.md §5.3). kg, m, kg m^2.
FIG3 = {
    "woman": {"head mass": 4.22, "torso mass": 17.62, "pelvis mass": 11.08, "leg mass": 8.32, "arm mass": 2.51,
              "height": 1.63, "leg length": 0.68, "arm length": 0.50, "hip spacing": 0.15,
              "leg / hip": 1.17, "body / ankle": 45.40, "body / hip": 6.50},
    "child": {"head mass": 5.63, "torso mass": 8.47, "pelvis mass": 3.71, "leg mass": 2.98, "arm mass": 1.20,
              "height": 1.08, "leg length": 0.39, "arm length": 0.29, "hip spacing": 0.13,
              "leg / hip": 0.13, "body / ankle": 10.10, "body / hip": 2.26},
    "imaginary_runner": {"head mass": 5.98, "torso mass": 12.55, "pelvis mass": 9.51, "leg mass": 6.84,
                         "arm mass": 2.38, "height": 1.64, "leg length": 0.72, "arm length": 0.55,
                         "hip spacing": 0.17, "leg / hip": 1.58, "body / ankle": 36.55, "body / hip": 5.16},
    "imaginary_cyclist": {"head mass": 7.19, "torso mass": 28.95, "pelvis mass": 7.89, "leg mass": 5.03,
                          "arm mass": 2.70, "height": 1.74, "leg length": 0.70, "arm length": 0.54,
                          "hip spacing": 0.22, "leg / hip": 0.48, "body / ankle": 74.80, "body / hip": 17.67},
}
# The figure's own factors from its man, in parentheses there: lengths as the ratio, masses as
# (m'/m)^1/3, inertias as (I'/I)^1/5, in the row order of FIG3.
FIG3_FACTORS = {
    "woman": (0.90, 0.87, 0.94, 0.92, 0.87, 0.91, 0.91, 1.01, 0.77, 0.89, 0.90, 0.90),
    "child": (0.99, 0.68, 0.65, 0.65, 0.68, 0.60, 0.52, 0.59, 0.67, 0.58, 0.67, 0.73),
    "imaginary_runner": (1.01, 0.78, 0.89, 0.86, 0.85, 0.92, 0.96, 1.12, 0.84, 0.95, 0.86, 0.86),
    "imaginary_cyclist": (1.07, 1.03, 0.84, 0.78, 0.89, 0.97, 0.93, 1.11, 1.10, 0.84, 0.99, 1.10),
}
PRESETS = ("child", "imaginary_runner", "imaginary_cyclist")     # the characters built from the man
# Acceptance bands of issue 28 (relative error against Fig. 3).
TOLERANCE = {"mass": 0.05, "length": 0.03, "inertia": 0.10}
KIND = {**{f"{segment} mass": "mass" for segment in SEGMENTS},
        **{k: "length" for k in ("height", "leg length", "arm length", "hip spacing")},
        **{k: "inertia" for k in ("leg / hip", "body / ankle", "body / hip")}}

LEG_PARTS = (("ULEG",), ("LLEG",), ("FOOT", "TOE"))
ARM_PARTS = ("UARM", "LARM", "HAND")
LOWER_TRUNK, UPPER_TRUNK = ("CHEST3", "CHEST2"), ("CHEST1", "STERNUM", "CHESTR", "CHESTL")
# Fit weights: rows are held to a fifth of their band (a margin for the physics' own rounding);
# the free shares are pulled towards the man's by this weight per unit of log-ratio.
FIT_BAND_SHARE = 0.2
SHARE_PULL = 0.05
# How far (in log-ratio) each parameter may go from its start: the thigh/shank length split and the
# trunk's width by ~40 %, the ankle's height by a factor 2, the mass shares' odds by e^2.5; unbounded,
# the fit meets the rows with caricatures (a torso seven times as wide and a centimetre deep).
FIT_BOUNDS = np.array([2.0, 0.35, 2.5, 2.0, 2.0, 0.35, 2.5, 2.0, 0.7])
# Depth floor of the trunk's slices: no slice (CHEST3, CHEST2, CHEST1, STERNUM, the shoulder girdle)
# may be thinner front-to-back than this fraction of the man's same slice times the stature ratio.
# Anthropometry: adult chest depth per stature spans well under a factor 2 (roughly 0.12-0.17 of
# stature between the 5th and 95th percentiles of army surveys), and our man (97.8 kg, 1.81 m,
# BMI 30) is at the deep end, so the leanest plausible adult trunk is ~0.6 of his per stature. A
# third is far below that: the floor rules out sheets (unbounded, the imaginary runner's upper trunk
# came out 3 cm deep and its sternum 6 mm, which no skin at Dempster's density can hold), it does not
# shape a body. A slice's depth is its mass over its height and width, so the floor bounds the share
# of the torso's mass the upper trunk takes (both ways: the lower trunk has the same floor). The fit
# applies it only when its unbounded optimum breaks it (fit_fig3): the child's (0.65 of the man's per
# stature) and the cyclist's (lower trunk 0.34) optima keep clear of it, so they are as they were.
TRUNK_DEPTH_FLOOR = 1.0 / 3.0
# Finite-difference step of the fit (absolute, in log-ratio): the model is measured through its MJCF
# text, whose numbers carry ~6 significant digits, so a smaller step sees rounding, not slope.
FIT_STEP = 1e-3
FIT_EVALUATIONS = 300
PARAMETERS = ("leg axial", "thigh/shank", "thigh mass", "arm axial", "trunk height",
              "trunk width", "upper trunk mass", "pelvis width", "foot height")


def fig3_scales(base: CharacterSpec, target: dict, p: np.ndarray, depth_floor: float | None = None
                ) -> dict[str, BodyScale]:
    """Per-body scales for target masses ``target`` and the fit's parameters ``p`` (PARAMETERS, logs).
    With ``depth_floor``, the upper trunk's share of the torso's mass is clamped so that every trunk
    slice is at least that fraction of the man's depth times the stature ratio (TRUNK_DEPTH_FLOOR)."""
    mass = lambda names: sum(base.body(n)["mass"] for n in names)           # noqa: E731
    side_names = lambda prefixes, side: [p_ + side for p_ in prefixes]       # noqa: E731
    scales: dict[str, BodyScale] = {}
    (leg_axial, thigh_shank, thigh_logit, arm_axial, trunk_height, trunk_width, upper_logit,
     pelvis_width, foot_height) = p
    for side in "RL":
        parts = [side_names(part, side) for part in LEG_PARTS]
        man_share = np.array([mass(part) for part in parts]) / mass(sum(parts, []))
        shift = np.exp([thigh_logit, 0.0])              # the feet keep the man's share (their footprint
        thigh_shank_share = man_share[:2] * shift / (man_share[:2] * shift).sum() * man_share[:2].sum()
        share = np.array([*thigh_shank_share, man_share[2]])   # is the support: see the module doc)
        ratios = target["leg mass"] * share / [mass(part) for part in parts]
        scales["ULEG" + side] = BodyScale.stretched(2, math.exp(leg_axial + thigh_shank / 2), ratios[0])
        scales["LLEG" + side] = BodyScale.stretched(2, math.exp(leg_axial - thigh_shank / 2), ratios[1])
        for name in parts[2]:                   # the ankle's height as fitted, the footprint by the mass
            scales[name] = BodyScale.stretched(2, math.exp(leg_axial + foot_height), ratios[2])
        arm_ratio = target["arm mass"] / mass(side_names(ARM_PARTS, side))
        scales["UARM" + side] = BodyScale.stretched(1, math.exp(arm_axial), arm_ratio)
        scales["LARM" + side] = BodyScale.stretched(1, math.exp(arm_axial), arm_ratio)
        scales["HAND" + side] = BodyScale.uniform(arm_ratio)
    scales["HEAD"] = BodyScale.uniform(target["head mass"] / mass(["HEAD"]))
    v, w, h = math.exp(trunk_height), math.exp(trunk_width), math.exp(pelvis_width)
    pelvis_ratio = target["pelvis mass"] / mass(["PELVIS"])
    scales["PELVIS"] = BodyScale((pelvis_ratio / (v * h), h, v), pelvis_ratio)
    man_upper = mass(UPPER_TRUNK) / mass(LOWER_TRUNK + UPPER_TRUNK)
    upper = man_upper * math.exp(upper_logit) / (man_upper * math.exp(upper_logit) + 1 - man_upper)
    if depth_floor is not None:     # a group's depth factor is its mass ratio / (v w)
        least_ratio = depth_floor * target["height"] / float(base.data["height"]) * v * w
        least = {names: least_ratio * mass(names) / target["torso mass"] for names in (LOWER_TRUNK, UPPER_TRUNK)}
        upper = min(max(upper, least[UPPER_TRUNK]), 1.0 - least[LOWER_TRUNK])
    for names, share in ((LOWER_TRUNK, 1 - upper), (UPPER_TRUNK, upper)):
        ratio = target["torso mass"] * share / mass(names)
        for name in names:
            scales[name] = BodyScale((ratio / (v * w), w, v), ratio)
    return scales


def trunk_depth(base: CharacterSpec, target: dict, p: np.ndarray, depth_floor: float | None = None) -> float:
    """The thinnest trunk slice's depth, as a fraction of the man's same slice times the stature ratio."""
    scales = fig3_scales(base, target, p, depth_floor)
    stature = target["height"] / float(base.data["height"])
    return min(scales[name].axes[0] for name in LOWER_TRUNK + UPPER_TRUNK) / stature


def fit_fig3(base: CharacterSpec, target: dict) -> tuple[dict, np.ndarray, float | None]:
    """Least-squares fit of the free shares and lengths to ``target``'s lengths and inertias, fitted
    again with the trunk's depth floor when the unbounded optimum breaks it.
    Returns (reshaped spec data, parameters, the depth floor applied or None)."""
    data, p = _fit_fig3(base, target, None)
    if trunk_depth(base, target, p) >= TRUNK_DEPTH_FLOOR:
        return data, p, None
    # the floor binds: fitted again with it, and with the trunk no narrower than it was (a narrower
    # trunk lowers the floor's share, and the fit would meet the floor by narrowing the trunk into a
    # deep, narrow drum instead of giving the upper trunk its mass)
    data, p = _fit_fig3(base, target, TRUNK_DEPTH_FLOOR, least_width=p[5])
    return data, p, TRUNK_DEPTH_FLOOR


def _fit_fig3(base: CharacterSpec, target: dict, depth_floor: float | None, least_width: float | None = None
              ) -> tuple[dict, np.ndarray]:
    man = fig3_measures(base)
    rows = [k for k in target if KIND[k] != "mass"]

    def build(p):
        return reshaped(base.data, fig3_scales(base, target, p, depth_floor))

    def residuals(p):
        measured = fig3_measures(CharacterSpec(build(p)))
        errors = [(measured[k] / target[k] - 1) / (TOLERANCE[KIND[k]] * FIT_BAND_SHARE) for k in rows]
        pulls = SHARE_PULL * np.array([p[1], p[2], p[6], p[5] - start[5], p[8]])
        return np.concatenate([errors, pulls])

    length = lambda k: math.log(target[k] / man[k])                          # noqa: E731
    torso_ratio = target["torso mass"] / man["torso mass"]
    start = np.array([length("leg length"), 0.0, 0.0, length("arm length"), length("height"),
                      0.5 * (math.log(torso_ratio) - length("height")), 0.0, length("hip spacing"), 0.0])
    upper_bounds = start + FIT_BOUNDS
    lower_bounds = start - FIT_BOUNDS
    if least_width is not None:     # SciPy needs lower < upper strictly
        lower_bounds[5] = min(max(lower_bounds[5], least_width), upper_bounds[5] - FIT_STEP)

    def jacobian(p):
        """Forward differences of absolute step FIT_STEP (backward at an upper bound): SciPy's
        own steps are relative to the parameter, and those that start at 0 would be ~1e-8."""
        base_residuals = residuals(p)
        columns = []
        for i in range(len(p)):
            step = FIT_STEP if p[i] + FIT_STEP <= upper_bounds[i] else -FIT_STEP
            moved = p.copy()
            moved[i] += step
            columns.append((residuals(moved) - base_residuals) / step)
        return np.array(columns).T

    fit = least_squares(residuals, np.clip(start, lower_bounds, upper_bounds), jac=jacobian,
                        bounds=(lower_bounds, upper_bounds), method="trf", max_nfev=FIT_EVALUATIONS)
    return build(fit.x), fit.x


def build_fig3_character(name: str, base: CharacterSpec) -> dict:
    """Spec data of the Fig. 3 character ``name`` (one of PRESETS) made from ``base`` (the man)."""
    if name not in PRESETS:
        raise UnknownNameError(f"unknown Fig. 3 character {name!r}; choose from {', '.join(PRESETS)}")
    data, p, depth_floor = fit_fig3(base, FIG3[name])
    leg_ratio = leg_length_ratio(base, CharacterSpec(data))
    data = mass_scaled_servos(data, base, leg_ratio)
    data["name"] = name
    data["source"] = (f"Hodgins & Pollard 1997, Fig. 3 ({name}): per-segment scaling of {base.name} fitted to the "
                      "figure's absolute masses, lengths and inertias (sim_core.character.fig3)")
    data["strength"] = {"scaled_from": base.name, "note": "kp, kv and torque limits mass-scaled (Fig. 6) by "
                        "the inertia each DOF moves, L = leg-length ratio (sim_core.adapt.servos)"}
    data["made"] = {"preset": name, "from": base.name, "fit": dict(zip(PARAMETERS, map(float, p)))}
    if depth_floor is not None:
        data["made"]["trunk depth floor"] = depth_floor
    data["time_scale"] = scaled_time_scale(base, leg_ratio)     # Fig. 6: physics step and control period x L^1/2
    return data
