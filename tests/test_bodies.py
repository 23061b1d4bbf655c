"""New bodies (issue 28): Fig. 6 scaling rules, the Fig. 3 characters, characters between two
specs and by height/mass, the `character` command; outcomes read off the simulation."""
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from sim_core.adapt import scaling
from sim_core.adapt.scaling import ScaleFactors, Units, factor, scale
from sim_core.errors import ParameterError

ROOT = Path(__file__).resolve().parents[1]

# SEEDS-WAVE2.md §8.5 S1: Fig. 6's geometric column at L = 0.5.
GEOMETRIC_AT_HALF = {
    "LENGTH": 0.5, "TIME": 0.7071, "FORCE": 0.125, "TORQUE": 0.0625, "VELOCITY": 0.7071,
    "ACCELERATION": 1.0, "ANGLE": 1.0, "ANGULAR_VELOCITY": 1.414, "ANGULAR_ACCELERATION": 2.0,
    "MASS": 0.125, "STIFFNESS": 0.25, "DAMPING": 0.1768, "MOMENT_OF_INERTIA": 0.03125,
    "TORSIONAL_STIFFNESS": 0.0625, "TORSIONAL_DAMPING": 0.04419,
}


@pytest.mark.parametrize("quantity", sorted(GEOMETRIC_AT_HALF))
def test_fig6_geometric_scaling_at_half_size(quantity):
    got = factor(getattr(scaling, quantity), ScaleFactors(length=0.5))
    assert got == pytest.approx(GEOMETRIC_AT_HALF[quantity], rel=2e-4)


def test_fig6_mass_scaling_uses_the_actual_mass_and_inertia_ratios():
    L, M, I = 0.5, 0.3, 0.2
    f = ScaleFactors(length=L, mass=M, inertia=I)
    k, kv = 1200.0, 96.0
    assert scale(k, scaling.TORSIONAL_STIFFNESS, f) == pytest.approx(k * I / L)            # eq. 4
    assert scale(kv, scaling.TORSIONAL_DAMPING, f) == pytest.approx(kv * I / math.sqrt(L))
    assert scale(300.0, scaling.TORQUE, f) == pytest.approx(300.0 * I / L)
    assert scale(5000.0, scaling.STIFFNESS, f) == pytest.approx(5000.0 * M / L)          # hand springs
    assert scale(50.0, scaling.DAMPING, f) == pytest.approx(50.0 * M / math.sqrt(L))
    assert scale(100.0, scaling.FORCE, f) == pytest.approx(100.0 * M)
    assert scale(2.0, scaling.MOMENT_OF_INERTIA, f) == pytest.approx(2.0 * I)
    for quantity in ("LENGTH", "TIME", "VELOCITY", "ANGULAR_VELOCITY", "ANGLE"):         # '-' in the mass column
        units = getattr(scaling, quantity)
        assert factor(units, f) == factor(units, ScaleFactors(length=L))
    # same lengths, different inertia (eq. 3): the gains scale by I'/I alone
    assert scale(k, scaling.TORSIONAL_STIFFNESS, ScaleFactors(length=1.0, inertia=I)) == pytest.approx(k * I)


def test_geometric_scaling_is_mass_scaling_with_mass_as_length_cubed():
    L = 0.8
    for name in GEOMETRIC_AT_HALF:
        units = getattr(scaling, name)
        assert factor(units, ScaleFactors(L)) == pytest.approx(factor(units, ScaleFactors(L, mass=L ** 3, inertia=L ** 5)))


@pytest.mark.parametrize("text, expected", [
    ("m", Units(length=1)), ("s", Units(time=1)), ("rad", Units()), ("1", Units()), ("bool", Units()),
    ("rad/m", Units(length=-1)), ("rad s/m", Units(length=-1, time=1)), ("m/s^2", Units(length=1, time=-2)),
    ("N m/rad", scaling.TORSIONAL_STIFFNESS), ("N m s/rad", scaling.TORSIONAL_DAMPING),
    ("kg m²", scaling.MOMENT_OF_INERTIA), ("N/m", scaling.STIFFNESS),
    ("rad/(kg m²/s)", Units(length=-2, time=1, mass=-1, rotational=True)),
])
def test_unit_strings_of_the_schemas_parse(text, expected):
    assert Units.parse(text) == expected


def test_bad_units_and_factors_are_refused():
    with pytest.raises(ParameterError, match="furlong"):
        Units.parse("furlong/s")
    with pytest.raises(ParameterError, match="length=-0.5"):
        ScaleFactors(length=-0.5)
    with pytest.raises(ParameterError, match="rotational"):
        Units(length=1, mass=1, rotational=True)
