r"""Numba kernels shared by the imperfection descriptions and the models.

Every kernel takes C-contiguous float64 arrays and plain scalars, and is compiled with
``cache=True`` and without ``fastmath`` (results are reproducible and IEEE-conforming).

Harmonic sum
------------
:func:`harmonic_sum` evaluates a profile written as a Fourier series (seed 002 eq. 23-25,
seed 001 eq. 11-12, seed 004 eq. 1)

.. math:: r(\theta) = \sum_j a_j \cos(k_j \theta + \varphi_j)

at many angles. The reference it must agree with is :func:`harmonic_sum_reference`, the NumPy
expression ``(a[:, None] * cos(k[:, None] * theta[None, :] + phi[:, None])).sum(0)``.

Why no angle-addition recurrence: the reference first rounds the argument ``k θ + φ`` to a
double. For ``k θ ~ 3e7`` (order 3000 over 1600 revolutions) that rounding alone moves each term
by up to ``|k θ| · 2⁻⁵³ ≈ 3e-9`` of its amplitude; a recurrence (however often re-seeded) is
closer to the exact value but differs from the reference by that much. The kernel therefore
forms exactly the same rounded argument ``fl(fl(k θ) + φ)`` and spends its effort on a fast
cosine of it: Cody–Waite reduction by π/2 with a four-part constant (each product ``q · C_i``
exact for ``|q| < 2²⁶``) and Taylor polynomials of degree 16 (cos) and 15 (sin) on
``|r| ≤ π/4`` (truncation below 1e-16), with a branch-free quadrant selection. The loop over
angles has no calls and no branches, so LLVM vectorises it; it agrees with ``numpy.cos`` to
about one unit in the last place. Arguments beyond ``±1e8`` rad fall back to ``math.cos``.

The work is blocked over angles (blocks of :data:`BLOCK` angles stay in L1 cache while every
harmonic is added), serial: the target machines have few cores and the models already run
many evaluations side by side; use a process pool around the models rather than threads here.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from runout.base._kernel import kernel

__all__ = [
    "BLOCK",
    "fast_cos",
    "harmonic_sum",
    "harmonic_sum_reference",
    "harmonic_sum_rows",
]

#: Angles per cache block in :func:`harmonic_sum`.
BLOCK = 1024

# π/2 split into parts of at most 26 significant bits (the last one full precision), so that
# q * _PIO2_i is exact for |q| < 2**27; together they carry about 130 bits of π/2.
# Generated from π computed with Machin's formula in integer arithmetic; the unit tests
# recompute them.
_PIO2_1 = float.fromhex("0x1.921fb58000000p+0")
_PIO2_2 = float.fromhex("-0x1.dde9740000000p-27")
_PIO2_3 = float.fromhex("0x1.1a62630000000p-54")
_PIO2_4 = float.fromhex("0x1.8a2e03707344ap-81")
_TWO_OVER_PI = float.fromhex("0x1.45f306dc9c883p-1")
#: Largest |argument| handled by the fast reduction (|q| stays below 2**26).
FAST_LIMIT = 1.0e8

# Taylor coefficients: cos r = 1 + Σ_{n=1..8} (-1)^n r^(2n)/(2n)!, sin r = r + r Σ_{n=1..7} ...
_C1, _C2, _C3, _C4, _C5, _C6, _C7, _C8 = ((-1.0) ** n / math.factorial(2 * n) for n in range(1, 9))
_S1, _S2, _S3, _S4, _S5, _S6, _S7 = ((-1.0) ** n / math.factorial(2 * n + 1) for n in range(1, 8))


@kernel(inline="always")
def fast_cos(x: float) -> float:
    """cos(x) for |x| <= :data:`FAST_LIMIT`, branch-free and vectorisable (see module notes)."""
    q = np.floor(x * _TWO_OVER_PI + 0.5)
    r = x - q * _PIO2_1
    r = r - q * _PIO2_2
    r = r - q * _PIO2_3
    r = r - q * _PIO2_4
    z = r * r
    c = 1.0 + z * (
        _C1 + z * (_C2 + z * (_C3 + z * (_C4 + z * (_C5 + z * (_C6 + z * (_C7 + z * _C8))))))
    )
    s = r + r * z * (_S1 + z * (_S2 + z * (_S3 + z * (_S4 + z * (_S5 + z * (_S6 + z * _S7))))))
    half = q * 0.5
    odd = half - np.floor(half) > 0.25  # quadrant 1 or 3: cos x = ∓ sin r
    quarter = (q + 1.0) * 0.25
    negative = quarter - np.floor(quarter) >= 0.5  # quadrant 1 or 2: negative sign
    v = s if odd else c
    return -v if negative else v


@kernel()
def _max_abs(x: NDArray[np.float64]) -> float:
    m = 0.0
    for i in range(x.size):
        v = abs(x[i])
        if not v <= m:  # also propagates NaN
            m = v
    return m


@kernel()
def _accumulate(
    out: NDArray[np.float64],
    theta: NDArray[np.float64],
    orders: NDArray[np.float64],
    amplitudes: NDArray[np.float64],
    phases: NDArray[np.float64],
    start: int,
    stop: int,
) -> None:
    """out[i] += Σ_{j in [start, stop)} a_j cos(k_j θ_i + φ_j) for every i (1-D views)."""
    n = theta.size
    big = _max_abs(orders[start:stop]) * _max_abs(theta) + _max_abs(phases[start:stop])
    if big <= FAST_LIMIT:
        for b0 in range(0, n, BLOCK):
            b1 = min(b0 + BLOCK, n)
            tb = theta[b0:b1]
            ob = out[b0:b1]
            for j in range(start, stop):
                k = orders[j]
                a = amplitudes[j]
                p = phases[j]
                for i in range(tb.size):
                    ob[i] += a * fast_cos(k * tb[i] + p)
    else:
        for b0 in range(0, n, BLOCK):
            b1 = min(b0 + BLOCK, n)
            tb = theta[b0:b1]
            ob = out[b0:b1]
            for j in range(start, stop):
                k = orders[j]
                a = amplitudes[j]
                p = phases[j]
                for i in range(tb.size):
                    ob[i] += a * math.cos(k * tb[i] + p)


@kernel()
def harmonic_sum(
    theta: NDArray[np.float64],
    orders: NDArray[np.float64],
    amplitudes: NDArray[np.float64],
    phases: NDArray[np.float64],
) -> NDArray[np.float64]:
    r"""Σ_j a_j cos(k_j θ + φ_j) at every angle of a 1-D array.

    Parameters
    ----------
    theta : ndarray, shape (N,)
        Angles [rad], float64, contiguous.
    orders : ndarray, shape (K,)
        Orders k_j (waves per turn) as float64.
    amplitudes : ndarray, shape (K,)
        Zero-to-peak amplitudes a_j [m].
    phases : ndarray, shape (K,)
        Phases φ_j [rad].

    Returns
    -------
    ndarray, shape (N,)
        The sum [m]; agrees with :func:`harmonic_sum_reference` to about 1e-16 Σ|a_j|.
    """
    out = np.zeros(theta.size)
    _accumulate(out, theta, orders, amplitudes, phases, 0, orders.size)
    return out


@kernel()
def harmonic_sum_rows(
    theta: NDArray[np.float64],
    orders: NDArray[np.float64],
    amplitudes: NDArray[np.float64],
    phases: NDArray[np.float64],
    offsets: NDArray[np.int64],
) -> NDArray[np.float64]:
    """Row-wise harmonic sums: row z of ``theta`` with harmonics ``offsets[z]:offsets[z+1]``.

    The harmonics of all rows are packed one after the other (ragged layout, see
    :func:`runout.geometry.imperfections.pack_harmonics`); this evaluates, for instance, the
    diameter deviation of every rolling element at its own spin angles in one call.

    Parameters
    ----------
    theta : ndarray, shape (Z, N)
        Angles of each row [rad], float64, C-contiguous.
    orders, amplitudes, phases : ndarray, shape (K,)
        Packed harmonics of all rows (orders as float64).
    offsets : ndarray of int64, shape (Z + 1,)
        Row z uses harmonics ``offsets[z]`` to ``offsets[z + 1] - 1``; ``offsets[0] == 0`` and
        ``offsets[Z] == K``.

    Returns
    -------
    ndarray, shape (Z, N)
    """
    z_rows, n = theta.shape
    out = np.zeros((z_rows, n))
    for z in range(z_rows):
        _accumulate(out[z], theta[z], orders, amplitudes, phases, offsets[z], offsets[z + 1])
    return out


def harmonic_sum_reference(
    theta: NDArray[np.float64],
    orders: NDArray[np.float64],
    amplitudes: NDArray[np.float64],
    phases: NDArray[np.float64],
    chunk_elements: int = 4_000_000,
) -> NDArray[np.float64]:
    """NumPy broadcasting reference of :func:`harmonic_sum`, chunked over angles.

    ``(a[:, None] * cos(k[:, None] * theta[None, :] + phi[:, None])).sum(0)``, evaluated on
    blocks of angles so that no temporary exceeds ``chunk_elements`` values.
    """
    theta = np.asarray(theta, dtype=np.float64)
    k = np.asarray(orders, dtype=np.float64)[:, None]
    a = np.asarray(amplitudes, dtype=np.float64)[:, None]
    p = np.asarray(phases, dtype=np.float64)[:, None]
    out = np.zeros(theta.shape[0])
    step = max(1, chunk_elements // max(1, k.shape[0]))
    for s in range(0, theta.shape[0], step):
        t = theta[None, s : s + step]
        out[s : s + step] = (a * np.cos(k * t + p)).sum(0)
    return out
