"""Hypothesis: invariants of the ISO/TS 16281 reference rating life (runout.geometry.life).

With the contact angles fixed, the life depends on the ball loads only through the equivalent
loads, which are power means (homogeneous of degree 1): scaling every ball load by s divides
L10r by s^3 exactly, scaling C by s multiplies it by s^3, and raising one ball's load can only
shorten it. Through the equilibrium model, a larger radial load shortens the life.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.geometry.bearing import BallBearing, Material, Operation
from runout.geometry.life import reference_rating_life
from runout.models.equilibrium import rating_life, solve_equilibrium

loads = st.lists(st.floats(0.0, 5e4), min_size=7, max_size=7).filter(lambda q: max(q) > 1.0)
ring = st.sampled_from(["inner", "outer"])


def _life(q_i: list[float], q_o: list[float], rotating: str, rating: float = 23400.0) -> float:
    life = reference_rating_life(
        elements=7,
        element_diameter=11.5e-3,
        pitch_diameter=43.5e-3,
        inner_conformity=0.52,
        outer_conformity=0.53,
        nominal_contact_angle=0.2,
        dynamic_load_rating=rating,
        inner_loads=q_i,
        outer_loads=q_o,
        rotating_ring=rotating,  # type: ignore[arg-type]
    ).l10r_mrev
    assert life is not None
    return life


@settings(max_examples=60, deadline=None)
@given(loads, loads, ring, st.floats(1e-3, 1e3))
def test_life_scales_as_the_inverse_cube_of_the_loads(
    q_i: list[float], q_o: list[float], rotating: str, s: float
) -> None:
    base = _life(q_i, q_o, rotating)
    scaled = _life([s * q for q in q_i], [s * q for q in q_o], rotating)
    assert scaled == pytest.approx(base / s**3, rel=1e-11)
    assert _life(q_i, q_o, rotating, 23400.0 * s) == pytest.approx(base * s**3, rel=1e-11)


@settings(max_examples=60, deadline=None)
@given(loads, ring, st.integers(0, 6), st.floats(1.0, 1e4))
def test_more_load_on_one_ball_shortens_the_life(
    q: list[float], rotating: str, ball: int, extra: float
) -> None:
    more = list(q)
    more[ball] += extra
    assert _life(more, more, rotating) < _life(q, q, rotating)


@pytest.mark.parametrize("clearance", [0.0, 10e-6])
def test_life_falls_with_the_radial_load(clearance: float) -> None:
    b = BallBearing(
        7,
        11.5e-3,
        43.5e-3,
        0.52,
        0.53,
        clearance,
        material=Material(210e9, 0.3, 7850.0),
        dynamic_load_rating=23400.0,
    )
    lives = []
    for radial in (200.0, 500.0, 1000.0, 2000.0):
        op = Operation("inner", 0.0, axial_load=300.0, radial_load=radial)
        life, _ = rating_life(b, op, solve_equilibrium(b, op))
        assert life is not None and life.l10r_mrev is not None
        lives.append(life.l10r_mrev)
    assert all(b < a for a, b in itertools.pairwise(lives))
    assert all(math.isfinite(v) for v in lives) and np.all(np.array(lives) > 0.0)
