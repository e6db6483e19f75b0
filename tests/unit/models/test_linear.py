"""The linear model (seed 002): closed-form lines against the direct sum of eq. 28."""

from __future__ import annotations

import math

import numpy as np
import pytest

from runout.base.errors import GeometryError
from runout.geometry.bearing import BallBearing, Operation
from runout.geometry.imperfections import (
    BearingImperfections,
    Harmonics,
    Slant,
    single_harmonic,
    spectral_law,
)
from runout.models import linear as lin

UM = 1e-6
ALPHA = math.radians(10.0)


def _bearing(z: int = 7) -> BallBearing:
    return BallBearing(
        elements=z,
        element_diameter=3.9688e-3,
        pitch_diameter=15e-3,
        inner_conformity=0.52,
        outer_conformity=0.53,
        contact_angle=ALPHA,
    )


def _rates(ring: str = "inner", z: int = 7, other: float = 0.0) -> lin.Rates:
    return lin.rates(_bearing(z), Operation(ring, 30.0, other_ring_speed=other), ALPHA)


def _lines(
    imp: BearingImperfections, r: lin.Rates, variant: str = "radial_spring"
) -> lin.SpectralLines:
    terms = lin.closed_form_terms(imp, r, ALPHA, variant)
    return lin.spectral_lines(terms, r.rotation_hz, imp.n_elements, True)


def _rich(z: int = 7, seed: int = 3) -> BearingImperfections:
    rng = np.random.default_rng(seed)
    inner = single_harmonic(1, 2.0 * UM, 0.3) + spectral_law((2, 60), 0.1 * UM, -1.5, rng=rng)
    outer = spectral_law((2, 80), 0.1 * UM, -1.5, rng=rng)
    balls = [spectral_law((1, 30), 0.05 * UM, -1.0, rng=rng) for _ in range(z)]
    return BearingImperfections(
        inner=inner,
        outer=outer,
        elements=balls,
        diameter_errors=rng.normal(0, 0.05 * UM, z),
        slant=Slant(0.05 * UM, 0.7),
    )


def _rel(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.abs(a - b).max() / np.abs(b).max())


@pytest.mark.parametrize("ring", ["inner", "outer"])
@pytest.mark.parametrize("variant", ["radial_spring", "force_balance"])
def test_lines_agree_with_direct_sum(ring: str, variant: str) -> None:
    imp = _rich()
    r = _rates(ring)
    lines = _lines(imp, r, variant)
    theta = np.linspace(0.0, 2 * math.pi * 3.3, 2001)
    xd, yd = lin.direct_sum(imp, r, ALPHA, theta, variant)
    xl, yl = lines.evaluate(theta)
    assert _rel(xl, xd) < 1e-9
    assert _rel(yl, yd) < 1e-9


def test_lines_agree_with_direct_sum_when_both_rings_turn() -> None:
    imp = _rich(z=9, seed=5)
    r = _rates("inner", z=9, other=-7.0)
    lines = _lines(imp, r)
    theta = np.linspace(0.0, 2 * math.pi * 2.0, 1501)
    xd, yd = lin.direct_sum(imp, r, ALPHA, theta)
    xl, yl = lines.evaluate(theta)
    assert _rel(xl, xd) < 1e-9 and _rel(yl, yd) < 1e-9


def test_synthesis_kernel_matches_numpy_reference() -> None:
    lines = _lines(_rich(), _rates())
    theta, x, y = lin.synthesize(lines, 2.5, 5000)
    xr, yr = lines.evaluate(theta)
    assert _rel(x, xr) < 1e-11 and _rel(y, yr) < 1e-11


def test_terms_evaluate_equals_lines_evaluate() -> None:
    imp = _rich()
    r = _rates()
    terms = lin.closed_form_terms(imp, r, ALPHA)
    theta = np.linspace(0, 9.0, 700)
    u = terms.evaluate(theta)
    x, y = lin.spectral_lines(terms, r.rotation_hz, 7, True).evaluate(theta)
    assert _rel(x, u.real) < 1e-12 and _rel(y, u.imag) < 1e-12


def test_inner_lines_reproduce_eq33() -> None:
    # One inner harmonic k = nZ - 1 and one k = nZ + 1: x = cos α W cos(I θ - φ) (eq. 33, 41).
    z, gamma = 7, 3.9688 / 15 * math.cos(ALPHA)
    for n, sign in ((1, -1), (2, 1), (3, -1)):
        k = n * z + sign
        imp = BearingImperfections(
            inner=Harmonics([k], [0.2 * UM], [0.4]), elements=[Harmonics.empty()] * z
        )
        lines = _lines(imp, _rates())
        assert len(lines) == 1
        assert lines.order[0] == pytest.approx(n * z * (1 + gamma) / 2 + sign, rel=1e-13)
        assert lines.x_amplitude[0] == pytest.approx(math.cos(ALPHA) * 0.2 * UM, rel=1e-13)
        theta = np.linspace(0, 7, 50)
        x, _ = lines.evaluate(theta)
        expect = math.cos(ALPHA) * 0.2 * UM * np.cos(lines.order[0] * theta - 0.4)
        np.testing.assert_allclose(x, lin.SHAFT_FRAME * expect, rtol=0, atol=1e-12 * UM)
        assert "I_(nZ" in lines.labels[0] and f"{k} lobes" in lines.labels[0]


def test_inner_harmonics_not_nz_pm_1_vanish() -> None:
    for k in (2, 3, 4, 5, 7, 9, 14):
        imp = BearingImperfections(inner=Harmonics([k], [UM]), elements=[Harmonics.empty()] * 7)
        assert len(_lines(imp, _rates())) == 0


def test_outer_lines_reproduce_eq37_both_lobes_share_o_nz() -> None:
    z, gamma = 7, 3.9688 / 15 * math.cos(ALPHA)
    imp = BearingImperfections(
        outer=Harmonics([13, 15], [0.3 * UM, 0.1 * UM], [0.2, 1.1]),
        elements=[Harmonics.empty()] * z,
    )
    lines = _lines(imp, _rates())
    assert len(lines) == 1
    assert lines.order[0] == pytest.approx(2 * z * (1 - gamma) / 2, rel=1e-13)
    # eq. 37 with W_o measured into the material (our radius deviation with a minus sign)
    theta = np.linspace(0, 7, 50)
    o = lines.order[0]
    expect = -math.cos(ALPHA) * UM * (0.3 * np.cos(o * theta + 0.2) + 0.1 * np.cos(o * theta + 1.1))
    x, _ = lines.evaluate(theta)
    np.testing.assert_allclose(x, lin.SHAFT_FRAME * expect, rtol=0, atol=1e-12 * UM)
    # forward/backward whirl: 13 lobes (nZ-1) forward, 15 lobes (nZ+1) backward
    c = math.cos(ALPHA) * UM
    assert lines.forward[0] == pytest.approx(0.3 * c, rel=1e-12)
    assert lines.backward[0] == pytest.approx(0.1 * c, rel=1e-12)
    assert lines.ellipse_major[0] == pytest.approx(0.4 * c, rel=1e-12)
    assert lines.ellipse_minor[0] == pytest.approx(0.2 * c, rel=1e-12)


def test_ball_lines_reproduce_eq39_40() -> None:
    z = 7
    gamma = 3.9688 / 15 * math.cos(ALPHA)
    nb = 15 / (2 * 3.9688) * (1 - gamma**2)
    nc = (1 - gamma) / 2
    ball = Harmonics([0, 4], [0.1 * UM, 0.05 * UM], [0.0, 0.9])
    imp = BearingImperfections(elements=[Harmonics.empty()] * 2 + [ball] + [Harmonics.empty()] * 4)
    lines = _lines(imp, _rates())
    np.testing.assert_allclose(lines.order, [nc, 4 * nb - nc, 4 * nb + nc], rtol=1e-13)
    beta = 2 * math.pi * 2 / z
    theta = np.linspace(0, 5, 60)
    c = math.cos(ALPHA)
    # eq. 39-40 with W_b = radius amplitudes of ball z = 2
    expect = (
        (2 / z)
        * c
        * (
            2 * 0.1 * UM * np.cos(nc * theta + beta)
            + 0.05 * UM * np.cos((4 * nb + nc) * theta + 0.9 + beta)
            + 0.05 * UM * np.cos((4 * nb - nc) * theta + 0.9 - beta)
        )
    )
    x, _ = lines.evaluate(theta)
    np.testing.assert_allclose(x, lin.SHAFT_FRAME * expect, rtol=0, atol=1e-12 * UM)
    assert "B_A0" in lines.labels[0] and "ball 3" in lines.labels[0]


def test_odd_ball_orders_do_nothing_and_equal_sizes_cancel() -> None:
    z = 7
    imp = BearingImperfections(
        elements=[Harmonics([3, 5], [UM, UM])] * z, diameter_errors=np.full(z, 0.3 * UM)
    )
    lines = _lines(imp, _rates())
    assert np.all(lines.x_amplitude < 1e-15 * UM)


def test_slant_x_is_eq35_and_y_is_the_quarter_turn_probe() -> None:
    imp = BearingImperfections(elements=[Harmonics.empty()] * 7, slant=Slant(0.05 * UM, 0.6))
    lines = _lines(imp, _rates())
    theta = np.linspace(0, 6, 40)
    x, y = lines.evaluate(theta)
    expect = math.cos(ALPHA) * 0.05 * UM * np.cos(2 * theta - 0.6)
    np.testing.assert_allclose(x, lin.SHAFT_FRAME * expect, atol=1e-12 * UM)
    np.testing.assert_allclose(y, -lin.SHAFT_FRAME * expect, atol=1e-12 * UM)
    assert lines.repeatable.all()


def test_outer_rotating_frequencies() -> None:
    z = 7
    gamma = 3.9688 / 15 * math.cos(ALPHA)
    imp = BearingImperfections(
        inner=Harmonics([1, 6, 8], [UM, UM, UM]),
        outer=Harmonics([1, 13], [UM, UM]),
        elements=[Harmonics.empty()] * z,
    )
    lines = _lines(imp, _rates("outer"))
    orders = sorted(np.round(lines.order[lines.x_amplitude > 1e-3 * UM], 10))
    expect = sorted(
        np.round(
            [
                0.0,  # stationary inner eccentricity: static offset
                z * (1 + gamma) / 2,  # inner 6 and 8 lobes share n f_i (seed 000 Tab. 2)
                1.0,  # outer eccentricity
                2 * z * (1 - gamma) / 2 - 1,  # outer nZ-1
            ],
            10,
        )
    )
    np.testing.assert_allclose(orders, expect, rtol=1e-12)
    # the stationary inner eccentricity is a static offset (order 0)
    assert lines.order[0] == 0.0 and lines.x_amplitude[0] > 0


def test_force_balance_gains() -> None:
    ring, ball = lin.variant_gains(ALPHA, "force_balance")
    assert ring == 1.0 and ball == pytest.approx(1 / math.cos(ALPHA))
    ring, ball = lin.variant_gains(ALPHA, "radial_spring")
    assert ring == ball == pytest.approx(math.cos(ALPHA))
    with pytest.raises(GeometryError, match="linear_variant"):
        lin.variant_gains(ALPHA, "stiff")


def test_pitch_errors_direct_sum_solves_full_balance() -> None:
    # With unequal spacing the direct sum must satisfy eq. 14-18 without eq. 19-20.
    z = 5
    imp = BearingImperfections(
        inner=Harmonics([1, 4, 6], [UM, 0.2 * UM, 0.1 * UM]),
        elements=[Harmonics.empty()] * z,
        pitch_errors=[0.0, 0.05, -0.03, 0.02, 0.0],
    )
    r = _rates(z=z)
    theta = np.linspace(0, 6, 300)
    x, y = lin.direct_sum(imp, r, ALPHA, theta)
    tz = (
        r.cage * theta[None, :]
        + 2 * math.pi * np.arange(z)[:, None] / z
        + np.array(imp.pitch_errors)[:, None]
    )
    # seed 002's balance is written for the outer ring; the result is the shaft: w_z = -g w
    w = np.stack([imp.inner.evaluate(t - theta) for t in tz]) * math.cos(ALPHA) * lin.SHAFT_FRAME
    # Σ_z (w_z - x cos θ_z - y sin θ_z) (cos θ_z, sin θ_z) = 0
    res_x = ((w - x * np.cos(tz) - y * np.sin(tz)) * np.cos(tz)).sum(0)
    res_y = ((w - x * np.cos(tz) - y * np.sin(tz)) * np.sin(tz)).sum(0)
    assert np.abs(res_x).max() < 1e-12 * UM and np.abs(res_y).max() < 1e-12 * UM
    # the lines are the first-order approximation
    xl, _ = _lines(imp, r).evaluate(theta)
    assert _rel(xl, x) < 0.1


def test_too_few_elements_and_zero_speed_are_errors() -> None:
    with pytest.raises(GeometryError, match="at least 3 elements"):
        lin.closed_form_terms(BearingImperfections.perfect(2), _rates(), ALPHA)
    with pytest.raises(GeometryError, match="speed"):
        lin.rates(_bearing(), Operation("inner", 0.0), ALPHA)


def test_perfect_bearing_gives_no_lines_and_zero_runout() -> None:
    lines = _lines(BearingImperfections.perfect(7), _rates())
    assert len(lines) == 0
    _, x, y = lin.synthesize(lines, 2, 64)
    assert not x.any() and not y.any()
