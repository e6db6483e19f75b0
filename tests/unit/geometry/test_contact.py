"""Unit tests of runout.geometry.contact (Hertz point and line contact) and
runout.geometry.loading."""

from __future__ import annotations

import math
from typing import Literal

import numpy as np
import pytest
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from runout import BallBearing, GeometryError, Material, RollerBearing
from runout.geometry.contact import (
    PALMGREN_LINE_CONSTANT,
    BallContacts,
    PointContact,
    ball_flat_cap_displacement,
    ball_flat_cap_force,
    ball_flat_contact_radius,
    ball_race_contacts,
    ball_race_curvature,
    combined_stiffness,
    curvature_difference_from_ratio,
    curvature_from_radii,
    delta_star_from_table,
    dimensionless_factors,
    ellipticity,
    hertz_point_stiffness,
    line_contact_approach,
    line_contact_load,
    point_contact,
    radius_ratio,
    roller_race_contacts,
)
from runout.geometry.loading import (
    axial_load_for_contact_angle,
    axial_loading,
    axial_loading_fixed_angle,
)

STEEL = Material(207.5e9, 0.3)


def _bearing(**kw: object) -> BallBearing:
    args: dict[str, object] = {
        "elements": 9,
        "element_diameter": 12.7e-3,
        "pitch_diameter": 65e-3,
        "inner_conformity": 0.52,
        "outer_conformity": 0.52,
        "radial_clearance": 20e-6,
        "material": STEEL,
    }
    args.update(kw)
    return BallBearing(**args)  # type: ignore[arg-type]


def _naive_kappa(f: float) -> float:
    """Hertz's equation in its textbook form, solved with brentq in κ."""

    def g(k: float) -> float:
        m = 1.0 - 1.0 / k**2
        return ((k * k + 1) * ellipe(m) - 2 * ellipk(m)) / ((k * k - 1) * ellipe(m)) - f

    return brentq(g, 1.0 + 1e-7, 1e4, xtol=1e-13, rtol=1e-15)


# --- curvature -------------------------------------------------------------------------------
def test_ball_race_curvature_matches_four_radii_form_inner_and_outer() -> None:
    d, dm, f, alpha = 10e-3, 50e-3, 0.515, math.radians(25.0)
    for race, sign in (("inner", 1.0), ("outer", -1.0)):
        s, fr = ball_race_curvature(d, dm, f, alpha, race)  # type: ignore[arg-type]
        # rolling-plane raceway radius along the contact normal (Harris)
        r_ring = sign * (dm - sign * d * math.cos(alpha)) / (2 * math.cos(alpha))
        s2, f2 = curvature_from_radii(d / 2, d / 2, r_ring, -f * d)
        assert s == pytest.approx(s2, rel=1e-13)
        assert fr == pytest.approx(f2, rel=1e-13)


def test_curvature_from_radii_is_vectorised_and_symmetric_in_labels() -> None:
    s, f = curvature_from_radii([1.0, 2.0], [1.0, 3.0], np.inf, np.inf)
    assert s.shape == (2,)
    s_b, f_b = curvature_from_radii([1.0, 3.0], [1.0, 2.0], np.inf, np.inf)
    np.testing.assert_allclose(f, f_b)
    np.testing.assert_allclose(s, s_b)
    assert f[0] == 0.0


@pytest.mark.parametrize(
    ("radii", "key"),
    [
        ((1.0, 1.0, 0.0, 1.0), "r_ii1"),
        ((1.0, 1.0, np.inf, -0.9), "curvature"),  # groove tighter than the ball
        ((1.0, np.inf, np.inf, np.inf), "curvature"),  # cylinder on flat: line contact
        ((float("nan"), 1.0, 1.0, 1.0), "r_i1"),
    ],
)
def test_curvature_from_radii_rejects_impossible_geometry(radii, key) -> None:
    with pytest.raises(GeometryError) as info:
        curvature_from_radii(*radii)
    assert info.value.key == key


def test_ball_race_curvature_rejects_bad_inputs() -> None:
    with pytest.raises(GeometryError):
        ball_race_curvature(10e-3, 50e-3, 0.5)
    with pytest.raises(GeometryError):
        ball_race_curvature(10e-3, 9e-3, 0.52)
    with pytest.raises(GeometryError):
        ball_race_curvature(10e-3, 50e-3, 0.52, race="middle")  # type: ignore[arg-type]


# --- ellipticity -------------------------------------------------------------------------------
def test_ellipticity_is_one_for_circular_contact() -> None:
    kappa, k, e = ellipticity(0.0)
    assert kappa == 1.0
    assert k == pytest.approx(math.pi / 2, rel=1e-15)
    assert e == pytest.approx(math.pi / 2, rel=1e-15)


@pytest.mark.parametrize("f", [1e-4, 2e-3, 0.05, 0.3, 0.7, 0.9, 0.94, 0.99, 0.9999])
def test_ellipticity_matches_textbook_equation_solved_with_brentq(f: float) -> None:
    assert float(ellipticity(f).ellipticity) == pytest.approx(_naive_kappa(f), rel=1e-11)


def test_ellipticity_vectorised_shape_and_extreme_slender_contacts() -> None:
    f = np.array([[0.0, 0.5], [1 - 1e-12, 1 - 1e-15]])
    kappa, k, e = ellipticity(f)
    assert kappa.shape == f.shape
    assert np.all(np.isfinite(kappa)) and np.all(kappa >= 1.0)
    # residual of the defining equation in the precise form 1 - F = 2 p (K - E) / ((1 - p) E)
    p = kappa[1] ** -2.0
    one_minus_f = 2 * p * (k[1] - e[1]) / ((1 - p) * e[1])
    np.testing.assert_allclose(one_minus_f, 1 - f[1], rtol=1e-9)


@pytest.mark.parametrize("f", [1e-12, 1e-9, 1e-6, 3e-4])
def test_ellipticity_near_circular_follows_series(f: float) -> None:
    # F = 3m/8 + 3m²/16 + O(m³) inverts to m = 8F/3 - 32F²/9 + O(F³), κ² = 1/(1-m)
    m = 8 * f / 3 - 32 * f**2 / 9
    kappa = float(ellipticity(f).ellipticity)
    assert kappa**2 - 1 == pytest.approx(m / (1 - m), rel=10 * f, abs=1e-15)


@pytest.mark.parametrize("f", [-1e-3, 1.0, 1.5, float("nan")])
def test_ellipticity_rejects_out_of_range(f: float) -> None:
    with pytest.raises(GeometryError):
        ellipticity(f)


def test_dimensionless_factors_are_one_for_circle_and_consistent() -> None:
    a, b, d = dimensionless_factors([0.0, 0.8])
    np.testing.assert_allclose([a[0], b[0], d[0]], 1.0, rtol=1e-14)
    kappa = ellipticity(0.8).ellipticity
    assert a[1] / b[1] == pytest.approx(float(kappa), rel=1e-13)


def test_radius_ratio_round_trip() -> None:
    f = np.linspace(0, 0.99, 7)
    np.testing.assert_allclose(curvature_difference_from_ratio(radius_ratio(f)), f, atol=1e-15)


# --- point contact -------------------------------------------------------------------------
def test_point_contact_sphere_on_flat_is_classical_hertz() -> None:
    r, q, ep = 5e-3, 100.0, STEEL.effective_modulus
    c = PointContact.from_radii(r, r, np.inf, np.inf, ep)
    e_star = ep / 2  # 1/E* = (1-ν²)/E + (1-ν²)/E
    a_ref = (3 * q * r / (4 * e_star)) ** (1 / 3)
    a, b = c.semi_axes(q)
    assert a == pytest.approx(a_ref, rel=1e-13)
    assert b == pytest.approx(a_ref, rel=1e-13)
    assert c.approach(q) == pytest.approx(a_ref**2 / r, rel=1e-13)
    assert c.max_pressure(q) == pytest.approx(3 * q / (2 * math.pi * a_ref**2), rel=1e-13)


def test_point_contact_methods_are_consistent() -> None:
    s, f = ball_race_curvature(12.7e-3, 65e-3, 0.52)
    c = point_contact(float(s), float(f), STEEL.effective_modulus)
    q = np.array([0.0, 10.0, 1000.0])
    np.testing.assert_allclose(c.load(c.approach(q)), q, rtol=1e-13)
    assert c.load(-1e-6) == 0.0
    assert c.max_pressure(0.0) == 0.0
    a, b = c.semi_axes(1000.0)
    assert a / b == pytest.approx(c.ellipticity, rel=1e-13)
    assert c.stiffness == pytest.approx(
        float(hertz_point_stiffness(s, f, STEEL.effective_modulus)), rel=1e-15
    )
    with pytest.raises(GeometryError):
        c.approach(-1.0)


def test_point_contact_stiffness_scales_with_modulus() -> None:
    k1 = hertz_point_stiffness(1000.0, 0.9, 2e11)
    k2 = hertz_point_stiffness(1000.0, 0.9, 1e11)
    assert k1 / k2 == pytest.approx(2.0, rel=1e-14)


def test_combined_stiffness_three_published_forms_agree() -> None:
    ki, ko = 3.2e10, 1.7e10
    seed001_eq15 = 1.0 / ((1 / ki) ** (2 / 3) + (1 / ko) ** (2 / 3)) ** 1.5
    seed000_eq4 = ki * ko / (ki ** (2 / 3) + ko ** (2 / 3)) ** 1.5
    n = 1.5
    seed003_eq214 = 1.0 / (1.0 / ki ** (1 / n) + 1.0 / ko ** (1 / n)) ** n
    kn = float(combined_stiffness(ki, ko))
    for value in (seed001_eq15, seed000_eq4, seed003_eq214):
        assert kn == pytest.approx(value, rel=1e-14)
    # two equal contacts in series: approach doubles under the same load
    assert float(combined_stiffness(ki, ki)) == pytest.approx(ki / 2**1.5, rel=1e-14)


def test_ball_race_contacts_default_angle_and_series_law() -> None:
    b = _bearing()
    c = ball_race_contacts(b)
    assert isinstance(c, BallContacts)
    assert c.contact_angle == b.free_contact_angle
    q = 500.0
    assert c.approach(q) == pytest.approx(c.inner.approach(q) + c.outer.approach(q), rel=1e-13)
    assert c.load(c.approach(q)) == pytest.approx(q, rel=1e-13)
    fixed = ball_race_contacts(_bearing(contact_angle=math.radians(15)))
    assert fixed.contact_angle == pytest.approx(math.radians(15))
    with pytest.raises(GeometryError):
        ball_race_contacts(b, math.pi / 2)


def test_table_interpolation_rejects_out_of_range() -> None:
    with pytest.raises(GeometryError):
        delta_star_from_table(0.99999)
    assert delta_star_from_table(0.0) == pytest.approx(1.0)


# --- ball on flat (seed 002 eq. 9-10) ---------------------------------------------------------
def test_ball_flat_cap_force_inverse_and_small_displacement_limit() -> None:
    rb = 1e-3
    q = np.array([0.1, 1.0, 11.039])
    x = ball_flat_cap_displacement(q, rb)
    np.testing.assert_allclose(ball_flat_cap_force(x, rb), q, rtol=1e-12)
    # for small x the cap depth is half the Hertz approach r²/r_b
    r = ball_flat_contact_radius(q, rb)
    np.testing.assert_allclose(x, r**2 / (2 * rb), rtol=1e-3)
    with pytest.raises(GeometryError):
        ball_flat_cap_force(-1e-9, rb)


# --- line contact --------------------------------------------------------------------------------
def test_palmgren_constant_in_si() -> None:
    # 3.84e-5 Q^0.9 / l^0.8 in mm, here Q = 1000 N, l = 10 mm
    mm = 3.84e-5 * 1000.0**0.9 / 10.0**0.8
    assert float(line_contact_approach(1000.0, 10e-3)) == pytest.approx(mm * 1e-3, rel=1e-13)
    assert PALMGREN_LINE_CONSTANT == pytest.approx(1.5287e-10, rel=1e-4)


def test_line_contact_inverse_and_modulus_scaling() -> None:
    d = line_contact_approach([10.0, 2000.0], 12e-3)
    np.testing.assert_allclose(line_contact_load(d, 12e-3), [10.0, 2000.0], rtol=1e-13)
    soft = line_contact_approach(1000.0, 12e-3, effective_modulus=1e11)
    hard = line_contact_approach(1000.0, 12e-3, effective_modulus=2e11)
    assert soft / hard == pytest.approx(2.0**0.9, rel=1e-13)
    # dimensional homogeneity: scaling Q by s² E'-fixed and l by s scales δ by s
    s = 3.0
    assert line_contact_approach(1000.0 * s**2, 12e-3 * s) == pytest.approx(
        s * line_contact_approach(1000.0, 12e-3), rel=1e-13
    )


def test_roller_race_contacts() -> None:
    b = RollerBearing(14, 11e-3, 54.5e-3, 76.5e-3, roller_length=12e-3)
    c = roller_race_contacts(b)
    q = 800.0
    assert c.approach(q) == pytest.approx(2 * float(c.inner.approach(q)), rel=1e-13)
    assert c.load(c.approach(q)) == pytest.approx(q, rel=1e-12)
    assert c.inner.load(c.inner.approach(q)) == pytest.approx(q, rel=1e-12)
    assert c.inner.stiffness * float(c.inner.approach(q)) ** (10 / 9) == pytest.approx(q)
    # Hertz line contact: b = sqrt(8 Q / (π l E' Σρ)), p = 2Q / (π b l)
    w = float(c.inner.semi_width(q))
    s = 2 / 11e-3 + 2 / 54.5e-3
    assert w == pytest.approx(
        math.sqrt(8 * q / (math.pi * 12e-3 * b.material.effective_modulus * s))
    )
    assert c.outer.max_pressure(q) < c.inner.max_pressure(q)
    with pytest.raises(GeometryError):
        roller_race_contacts(RollerBearing(14, 11e-3, 54.5e-3, 76.5e-3))


# --- loading ---------------------------------------------------------------------------------
def test_axial_loading_zero_load_returns_free_angle() -> None:
    b = _bearing()
    r = axial_loading(b, 0.0)
    assert r.contact_angle == b.free_contact_angle
    assert r.ball_load == 0.0 and r.total_approach == 0.0 and r.axial_displacement == 0.0


@pytest.mark.parametrize("load", [-1.0, float("nan"), float("inf")])
def test_axial_loading_rejects_bad_load(load: float) -> None:
    with pytest.raises(GeometryError) as info:
        axial_loading(_bearing(), load)
    assert info.value.key == "axial_load"


@pytest.mark.parametrize("clearance", [0.0, 20e-6])
@pytest.mark.parametrize("stiffness", ["at_angle", "free"])
def test_axial_loading_is_self_consistent(
    clearance: float, stiffness: Literal["at_angle", "free"]
) -> None:
    b = _bearing(radial_clearance=clearance)
    fa = 5000.0
    r = axial_loading(b, fa, stiffness=stiffness)
    a = b.curvature_distance
    alpha0 = b.free_contact_angle
    # force balance and geometry
    assert b.elements * r.ball_load * math.sin(r.contact_angle) == pytest.approx(fa, rel=1e-12)
    geometric = a * (math.cos(alpha0) / math.cos(r.contact_angle) - 1.0)
    assert r.total_approach == pytest.approx(geometric, rel=1e-9)
    assert r.inner_approach + r.outer_approach == pytest.approx(r.total_approach, rel=1e-14)
    assert r.axial_displacement == pytest.approx(
        (a + r.total_approach) * math.sin(r.contact_angle) - a * math.sin(alpha0), rel=1e-12
    )
    # the explicit inverse gives the load back
    inverse = axial_load_for_contact_angle(b, r.contact_angle, stiffness=stiffness)
    assert inverse == pytest.approx(fa, rel=1e-9)
    expected_angle = r.contact_angle if stiffness == "at_angle" else alpha0
    assert r.contacts.contact_angle == pytest.approx(expected_angle)


def test_axial_loading_stiffness_at_angle_differs_from_frozen() -> None:
    b = _bearing(radial_clearance=0.0)
    at = axial_loading(b, 20000.0)
    frozen = axial_loading(b, 20000.0, stiffness="free")
    assert at.contact_angle != frozen.contact_angle
    assert abs(at.contact_angle - frozen.contact_angle) < math.radians(0.5)


def test_axial_loading_fixed_angle() -> None:
    b = _bearing(contact_angle=math.radians(15.0))
    r = axial_loading_fixed_angle(b, 1000.0)
    assert r.contact_angle == pytest.approx(math.radians(15.0))
    assert r.ball_load == pytest.approx(1000.0 / (9 * math.sin(math.radians(15.0))))
    assert r.contacts.load(r.total_approach) == pytest.approx(r.ball_load, rel=1e-12)
    assert axial_loading_fixed_angle(b, 0.0).total_approach == 0.0
    with pytest.raises(GeometryError):
        axial_loading_fixed_angle(_bearing(), 100.0, contact_angle=0.0)


def test_axial_load_for_contact_angle_rejects_angle_below_free_angle() -> None:
    b = _bearing()
    with pytest.raises(GeometryError):
        axial_load_for_contact_angle(b, 0.5 * b.free_contact_angle)
    with pytest.raises(GeometryError):
        axial_loading(b, 1.0, stiffness="bogus")  # type: ignore[arg-type]
