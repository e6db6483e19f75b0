"""Unit tests of runout.geometry._elliptic: K(m) and E(m) by the AGM against scipy.special."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.special import ellipe, ellipkm1

from runout.geometry._elliptic import complete_elliptic

EPS = np.finfo(np.float64).eps  # 2.2e-16
# Measured against a 60-digit AGM (decimal): K within 4 ulp (relative 6.7e-16, the rounding
# of nine AGM steps for p -> 1e-30; 2 ulp for p >= 1/2), E within 1.5 ulp (3.3e-16). SciPy's
# cephes K and E are themselves off by up to 2 ulp, so the comparisons below allow the sum.
K_RTOL = 3 * EPS  # 6.7e-16
E_RTOL = 2 * EPS  # 4.4e-16


def _rel(x: np.ndarray, ref: np.ndarray) -> float:
    return float(np.max(np.abs(x / ref - 1.0)))


def test_first_kind_matches_scipy_ellipkm1_down_to_p_1e_30() -> None:
    p = np.geomspace(1e-30, 1.0, 4001)
    k, _ = complete_elliptic(p, 1.0 - p)
    assert _rel(k, ellipkm1(p)) <= K_RTOL


def test_second_kind_matches_scipy_ellipe_on_both_branches() -> None:
    # m >= 1/2: p = 1 - m is exact (Sterbenz), so the pair is consistent; down to p = 1.1e-16
    m = np.concatenate([np.geomspace(1e-20, 1.0, 4001), np.linspace(0.4, 0.6, 2001)])
    p = 1.0 - m
    k, e = complete_elliptic(p, m)
    assert _rel(e, ellipe(m)) <= E_RTOL
    small = m <= 0.5
    assert _rel(e[small], ellipe(m[small])) <= E_RTOL
    assert _rel(e[~small], ellipe(m[~small])) <= E_RTOL
    assert _rel(k[m < 1.0], ellipkm1(p[m < 1.0])) <= K_RTOL


def test_second_kind_tends_to_one_for_tiny_complement() -> None:
    # E(1 - p) = 1 + (p/4)(ln(16/p) - 1) + ...: 1 to round-off below p = 1e-19
    p = np.geomspace(1e-300, 1e-19, 50)
    k, e = complete_elliptic(p, 1.0 - p)
    assert np.all(e == 1.0)
    np.testing.assert_allclose(k, np.log(4.0) - 0.5 * np.log(p), rtol=1e-15)


def test_endpoints_and_branch_point() -> None:
    k, e = complete_elliptic(np.array([1.0, 0.0, 0.5]), np.array([0.0, 1.0, 0.5]))
    assert k[0] == e[0] == pytest.approx(math.pi / 2, rel=1e-16)
    assert k[1] == math.inf
    assert e[1] == 1.0
    assert k[2] == pytest.approx(1.8540746773013719, rel=K_RTOL)
    assert e[2] == pytest.approx(1.3506438810476755, rel=E_RTOL)


def test_scalar_and_array_paths_agree() -> None:
    p = np.geomspace(1e-30, 1.0, 101)
    k, e = complete_elliptic(p, 1.0 - p)
    for i in range(p.size):
        k1, e1 = complete_elliptic(p[i : i + 1], 1.0 - p[i : i + 1])
        assert k1.shape == e1.shape == (1,)
        assert k1[0] == k[i] and e1[0] == e[i]
    k0, e0 = complete_elliptic(0.25, 0.75)
    assert k0.shape == e0.shape == ()


def test_nan_propagates() -> None:
    for shape in [(1,), (3,)]:
        k, e = complete_elliptic(np.full(shape, np.nan), np.full(shape, np.nan))
        assert np.all(np.isnan(k)) and np.all(np.isnan(e))


_M = st.floats(0.0, 1.0, exclude_max=True)


@settings(max_examples=200, deadline=None)
@given(_M)
def test_legendre_relation(m: float) -> None:
    # E K' + E' K - K K' = pi/2 (DLMF 19.7.1), K' = K(1 - m), E' = E(1 - m). Near m = 0 or 1
    # two terms of order K K' (55 at m = 1 - 1e-16) cancel down to pi/2, so the round-off
    # of the evaluation is relative to K K', not to pi/2
    p = 1.0 - m
    if p == 0.0 or m == 0.0:
        return
    k, e = complete_elliptic(p, m)
    kc, ec = complete_elliptic(m, p)
    residual = float(e * kc + ec * k - k * kc) - math.pi / 2
    assert abs(residual) <= 1e-15 * max(math.pi / 2, float(k * kc))


@settings(max_examples=200, deadline=None)
@given(_M, _M)
def test_monotone_in_m(m1: float, m2: float) -> None:
    # K increases and E decreases with m, up to round-off: adjacent doubles across the switch
    # of formula at m = 1/2 give E rising by up to 4.9e-16 (3 ulp)
    lo, hi = sorted((m1, m2))
    k, e = complete_elliptic(np.array([1.0 - lo, 1.0 - hi]), np.array([lo, hi]))
    assert k[0] <= k[1] * (1.0 + 4 * EPS)
    assert e[0] >= e[1] * (1.0 - 4 * EPS)


def test_compiled_loop_is_the_numpy_loop_bit_for_bit() -> None:
    """Large arrays take the compiled AGM (runout.geometry._elliptic_kernel): NumPy's bits."""
    from runout.geometry import _elliptic as _elliptic

    rng = np.random.default_rng(5)
    p = np.concatenate(
        [np.geomspace(1e-30, 1.0, 3000), rng.uniform(0.0, 1.0, 3000), [0.0, 1.0, 0.5]]
    )
    m = 1.0 - p
    k_fast, e_fast = _elliptic.complete_elliptic(p, m)
    b0_sq = np.stack((p, m))
    b0 = np.sqrt(np.where(b0_sq == 0.0, _elliptic._TINY, b0_sq))
    mean, total = _elliptic._agm(b0, np.stack((m, p)), np.sqrt, _elliptic._any)
    k_ref = _elliptic._HALF_PI / mean[0]
    e_ref = np.where(m <= 0.5, k_ref * (1.0 - total[0]), mean[1] + k_ref * total[1])
    k_ref = np.where(p == 0.0, np.inf, k_ref)
    e_ref = np.where(p == 0.0, 1.0, e_ref)
    assert p.size >= _elliptic._COMPILED_SIZE
    np.testing.assert_array_equal(k_fast, k_ref)
    np.testing.assert_array_equal(e_fast, e_ref)
