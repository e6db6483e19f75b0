"""Property-based tests of Hertz contact (runout.geometry.contact) and axial loading
(runout.geometry.loading)."""

from __future__ import annotations

import math

from hypothesis import assume, given, settings
from hypothesis import strategies as st

from runout import BallBearing, Material
from runout.geometry.contact import (
    ball_race_contacts,
    ball_race_curvature,
    combined_stiffness,
    ellipticity,
    point_contact,
)
from runout.geometry.loading import axial_loading

FAST = settings(max_examples=60, deadline=None)
SLOW = settings(max_examples=25, deadline=None)

curvature_difference = st.floats(0.0, 1.0 - 1e-12, allow_nan=False)
conformity = st.floats(0.502, 0.58)


@st.composite
def bearings(draw: st.DrawFn) -> BallBearing:
    d = draw(st.floats(1e-3, 30e-3))
    dm = d * draw(st.floats(3.0, 12.0))
    z_max = math.floor(math.pi / math.asin(d / dm) - 1e-9)
    z = draw(st.integers(3, max(3, min(z_max, 40))))
    fi, fo = draw(conformity), draw(conformity)
    a = (fi + fo - 1.0) * d
    clearance = draw(st.sampled_from([0.0, 0.05, 0.5, 1.5])) * a
    e = draw(st.floats(70e9, 400e9))
    return BallBearing(z, d, dm, fi, fo, clearance, material=Material(e, 0.3))


@FAST
@given(curvature_difference, curvature_difference)
def test_ellipticity_at_least_one_and_increasing(f1: float, f2: float) -> None:
    lo, hi = sorted((f1, f2))
    assume(hi - lo > 1e-9)
    k_lo, k_hi = ellipticity([lo, hi]).ellipticity
    assert k_lo >= 1.0
    assert k_hi > k_lo


@FAST
@given(
    st.floats(1.0, 1e5),
    st.floats(0.0, 0.9999),
    st.floats(1e9, 1e12),
    st.one_of(st.just(0.0), st.floats(1e-12, 1e-3)),
)
def test_approach_of_load_of_approach_is_identity(
    curvature_sum: float, f: float, modulus: float, delta: float
) -> None:
    c = point_contact(curvature_sum, f, modulus)
    assert math.isclose(float(c.approach(c.load(delta))), delta, rel_tol=1e-12)


@FAST
@given(st.floats(0.0, math.radians(60)), conformity, conformity, st.floats(2.5, 20.0))
def test_series_stiffness_below_both_contacts(
    alpha: float, fi: float, fo: float, ratio: float
) -> None:
    d, e_prime = 10e-3, 2.28e11
    ks = []
    for race, f in (("inner", fi), ("outer", fo)):
        s, fr = ball_race_curvature(d, ratio * d, f, alpha, race)  # type: ignore[arg-type]
        ks.append(point_contact(float(s), float(fr), e_prime).stiffness)
    kn = float(combined_stiffness(*ks))
    assert kn <= min(ks)
    # the series approach is at most twice the larger single approach
    assert kn >= min(ks) / 2**1.5 * (1 - 1e-12)


@SLOW
@given(bearings(), st.floats(1.0, 1e4), st.floats(1.01, 10.0))
def test_contact_angle_increases_with_axial_load(
    bearing: BallBearing, load: float, factor: float
) -> None:
    scale = bearing.material.youngs_modulus * bearing.element_diameter**2 * 1e-6
    fa = load * scale / 1e4  # keep loads physical for every ball size and modulus
    low = axial_loading(bearing, fa)
    high = axial_loading(bearing, fa * factor)
    assert low.contact_angle >= bearing.free_contact_angle
    assert high.contact_angle > low.contact_angle
    assert high.axial_displacement > low.axial_displacement


@SLOW
@given(bearings())
def test_contact_angle_tends_to_free_angle_as_load_vanishes(bearing: BallBearing) -> None:
    alpha0 = bearing.free_contact_angle
    angles = [axial_loading(bearing, fa).contact_angle - alpha0 for fa in (1e-2, 1e-5, 1e-8)]
    assert all(a >= 0.0 for a in angles)
    assert angles[0] > angles[1] > angles[2]
    assert angles[2] < 1e-2  # rad, at 10 nN


@SLOW
@given(bearings(), st.floats(0.0, math.radians(45)))
def test_ball_race_contacts_accepts_any_valid_bearing(bearing: BallBearing, alpha: float) -> None:
    c = ball_race_contacts(bearing, alpha)
    assert c.inner.ellipticity >= 1.0 and c.outer.ellipticity >= 1.0
    assert 0.0 < c.combined_stiffness <= min(c.inner.stiffness, c.outer.stiffness)
