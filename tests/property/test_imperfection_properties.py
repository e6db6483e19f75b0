"""Hypothesis properties of runout.geometry.imperfections and the harmonic-sum kernel."""

from __future__ import annotations

import math
import warnings

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

from runout.geometry._kernels import harmonic_sum, harmonic_sum_reference
from runout.geometry.imperfections import (
    Harmonics,
    ProfileWarning,
    from_profile,
    single_harmonic,
)

TWO_PI = 2.0 * math.pi
SETTINGS = settings(max_examples=60, deadline=None)

amplitude = st.floats(min_value=1e-9, max_value=1e-5)
phase = st.floats(min_value=-10.0, max_value=10.0)


@st.composite
def harmonics(draw, max_order: int = 40, max_terms: int = 8, min_order: int = 0):  # type: ignore[no-untyped-def]
    n = draw(st.integers(min_value=1, max_value=max_terms))
    orders = draw(st.lists(st.integers(min_order, max_order), min_size=n, max_size=n, unique=True))
    amps = draw(st.lists(amplitude, min_size=n, max_size=n))
    phases = draw(st.lists(phase, min_size=n, max_size=n))
    return Harmonics(orders, amps, phases)


def scale(h: Harmonics) -> float:
    return float(h.amplitudes.sum()) if len(h) else 1.0


# ------------------------------------------------------------------------------------------
@SETTINGS
@given(
    theta_max=st.floats(min_value=1.0, max_value=1e4),
    n_theta=st.integers(min_value=1, max_value=700),
    orders=st.lists(st.integers(0, 3000), min_size=1, max_size=60),
    seed=st.integers(0, 2**32 - 1),
)
def test_kernel_equals_reference(
    theta_max: float, n_theta: int, orders: list[int], seed: int
) -> None:
    rng = np.random.default_rng(seed)
    theta = rng.uniform(-theta_max, theta_max, n_theta)
    k = np.asarray(orders, dtype=np.float64)
    a = rng.uniform(-1.0, 1.0, k.size) * 10.0 ** rng.uniform(-3, 0, k.size)
    p = rng.uniform(-TWO_PI, TWO_PI, k.size)
    got = harmonic_sum(theta, k, a, p)
    ref = harmonic_sum_reference(theta, k, a, p)
    assert np.max(np.abs(got - ref)) <= 1e-12 * np.abs(a).sum()


@SETTINGS
@given(h=harmonics(min_order=1), theta0=st.floats(0.0, TWO_PI), extra=st.integers(0, 40))
def test_uniform_profile_round_trip(h: Harmonics, theta0: float, extra: int) -> None:
    n = 2 * h.max_order + 1 + extra
    theta = theta0 + np.arange(n) * (TWO_PI / n)
    got = from_profile(theta, h.evaluate(theta), orders=(1, h.max_order))
    check = np.linspace(0.0, TWO_PI, 97)
    np.testing.assert_allclose(
        got.evaluate(check), h.evaluate(check), rtol=0, atol=1e-11 * scale(h)
    )


@SETTINGS
@given(
    h=harmonics(max_order=20, min_order=1),
    jitter=st.floats(0.0, 0.45),
    mean=st.floats(-1e-5, 1e-5),
    seed=st.integers(0, 2**32 - 1),
)
def test_irregular_profile_round_trip(h: Harmonics, jitter: float, mean: float, seed: int) -> None:
    n = 4 * h.max_order + 8
    rng = np.random.default_rng(seed)
    theta = (np.arange(n) + jitter * rng.uniform(-1.0, 1.0, n)) * (TWO_PI / n) + 0.1
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ProfileWarning)
        got = from_profile(
            theta,
            h.evaluate(theta) + mean,
            orders=(1, h.max_order),
            keep_mean=True,
            method="lstsq",
        )
    check = np.linspace(0.0, TWO_PI, 97)
    np.testing.assert_allclose(
        got.evaluate(check), h.evaluate(check) + mean, rtol=0, atol=1e-9 * (scale(h) + abs(mean))
    )


@SETTINGS
@given(h=harmonics(), theta=hnp.arrays(np.float64, 20, elements=st.floats(-50.0, 50.0)))
def test_diameter_deviation_even_and_opposite_points(h: Harmonics, theta: np.ndarray) -> None:
    d = h.diameter_deviation()
    assert (d.orders % 2 == 0).all()
    np.testing.assert_allclose(
        d.evaluate(theta),
        h.evaluate(theta) + h.evaluate(theta + math.pi),
        rtol=0,
        atol=1e-12 * scale(h),
    )


@SETTINGS
@given(
    a=harmonics(), b=harmonics(), theta=hnp.arrays(np.float64, 15, elements=st.floats(-20.0, 20.0))
)
def test_addition_commutes_and_adds(a: Harmonics, b: Harmonics, theta: np.ndarray) -> None:
    tol = 1e-12 * (scale(a) + scale(b))
    np.testing.assert_allclose((a + b).evaluate(theta), (b + a).evaluate(theta), rtol=0, atol=tol)
    np.testing.assert_allclose(
        (a + b).evaluate(theta), a.evaluate(theta) + b.evaluate(theta), rtol=0, atol=tol
    )
    assert (a + b).orders.tolist() == sorted(set(a.orders.tolist()) | set(b.orders.tolist()))


@SETTINGS
@given(order=st.integers(1, 200), pp=st.floats(1e-10, 1e-4), ph=phase)
def test_peak_to_peak_input_is_halved(order: int, pp: float, ph: float) -> None:
    h = single_harmonic(order, peak_to_peak=pp, phase=ph)
    assert h.amplitudes[0] == 0.5 * pp
    assert math.isclose(h.peak_to_peak(), pp, rel_tol=1e-10)


@SETTINGS
@given(
    orders=st.lists(st.integers(0, 30), min_size=1, max_size=12),
    amps=st.lists(st.floats(-1e-5, 1e-5), min_size=12, max_size=12),
    phases=st.lists(phase, min_size=12, max_size=12),
    theta=hnp.arrays(np.float64, 10, elements=st.floats(-20.0, 20.0)),
)
def test_normalisation_preserves_profile(
    orders: list[int], amps: list[float], phases: list[float], theta: np.ndarray
) -> None:
    n = len(orders)
    h = Harmonics(orders, amps[:n], phases[:n])
    raw = sum(
        (a * np.cos(k * theta + p) for k, a, p in zip(orders, amps, phases, strict=False)),
        np.zeros_like(theta),
    )
    total = sum(abs(a) for a in amps[:n]) or 1.0
    # 1e-12 of the amplitudes; the draw reaches subnormal amplitudes (2e-313), which keep fewer
    # digits and whose 1e-12 underflows to 0: there the floor is the subnormal spacing
    # (math.ulp(0.0) = 5e-324) per term summed, and a few terms per order
    atol = 1e-12 * total + 8 * len(orders) * math.ulp(0.0)
    np.testing.assert_allclose(h.evaluate(theta), raw, rtol=0, atol=atol)
    assert (np.diff(h.orders) > 0).all()
    assert (h.amplitudes > 0).all()
    assert ((h.phases >= 0) & (h.phases < TWO_PI)).all()
    back = Harmonics.from_complex(*h.to_complex())
    np.testing.assert_allclose(back.evaluate(theta), h.evaluate(theta), rtol=0, atol=atol)
