r"""Complete elliptic integrals K(m) and E(m) by the arithmetic-geometric mean, in NumPy.

A few array operations per AGM step replace ``scipy.special.ellipkm1`` and ``ellipe``, whose
import costs about 0.1 s of the start-up of the light commands (``runout frequencies``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]

#: AGM steps allowed. From b₀ = √p with p the smallest subnormal double (b₀ ≈ 2e-162) the
#: AGM of (1, b₀) meets the stopping test after 12 steps, from any p >= 1e-30 after at most
#: 9, and from p >= 1/2 after 4.
_MAX_STEPS = 16

#: Stop once every c_n <= 2⁻²⁷ a_n: then a_n - M <= a_n - b_n = c_n²/(2a_{n+1}) <= 2⁻⁵⁵ a_n
#: (an eighth of an ulp), and the terms of the sum still to come are below 2⁻¹⁰⁰ relative.
_TOLERANCE = 2.0**-27

#: Arrays from this size on use the compiled loop (:mod:`runout.geometry._elliptic_kernel`); smaller
#: ones (the ellipticity's starting table has 406 entries, a model's contacts a few dozen) stay
#: in NumPy or Python floats (:data:`_LOOP_SIZE`), a fraction of a millisecond, so that neither
#: the light commands (``frequencies``, ``check``) nor the first run of a model wait for the
#: loop to compile. Every path gives the same bits.
_COMPILED_SIZE = 4096

#: Arrays below this size (and in [0, 1]) go entry by entry in Python floats (:func:`_scalar`).
_LOOP_SIZE = 64

_TINY = 5e-324
_HALF_PI = 0.5 * math.pi
_T = TypeVar("_T", float, FloatArray)


def complete_elliptic(p: ArrayLike, m: ArrayLike) -> tuple[FloatArray, FloatArray]:
    r"""Complete elliptic integrals of the first and second kind, parameter m, vectorised.

    .. math::

        \mathcal{K}(m) = \int_0^{\pi/2}\frac{d\theta}{\sqrt{1 - m\sin^2\theta}},\qquad
        \mathcal{E}(m) = \int_0^{\pi/2}\sqrt{1 - m\sin^2\theta}\,d\theta

    (SciPy's convention: the modulus is :math:`\sqrt m`). Both :math:`m` and its complement
    :math:`p = 1 - m` are passed, each to full relative precision, so that neither loses
    digits to the subtraction: :math:`\mathcal{K}` uses only :math:`p` (like
    ``scipy.special.ellipkm1(p)``), :math:`\mathcal{E}` uses :math:`m` for :math:`m \le 1/2`
    and :math:`p` above.

    Parameters
    ----------
    p : array_like
        Complementary parameter :math:`p = 1 - m`, in [0, 1] [-]; may be as small as the
        smallest positive double.
    m : array_like
        Parameter :math:`m` in [0, 1] [-], consistent with ``p``.

    Returns
    -------
    K, E : ndarray
        :math:`\mathcal{K}(m)` in [π/2, ∞] and :math:`\mathcal{E}(m)` in [1, π/2] [-], arrays
        of the broadcast shape of ``p`` and ``m`` (``K`` is infinite at ``p = 0``). NaN
        propagates. Outside [0, 1] NumPy warns of an invalid value; p < 0 or m > 1 gives NaN
        (m < 0 gives the analytic continuation, not tested).

    Raises
    ------
    ArithmeticError
        If the AGM has not converged after ``_MAX_STEPS`` steps (cannot happen for arguments
        in [0, 1]; a guard for the bounded loop).

    Notes
    -----
    Gauss's arithmetic-geometric mean, :math:`a_0 = 1`, :math:`b_0 = \sqrt p`,
    :math:`c_0^2 = m`, :math:`a_{n+1} = (a_n + b_n)/2`, :math:`b_{n+1} = \sqrt{a_n b_n}`,
    :math:`c_{n+1} = c_n^2/(4a_{n+1})` (:math:`= (a_n - b_n)/2` without the cancellation)
    converges quadratically to :math:`M(1, \sqrt p)`, and (Abramowitz & Stegun 17.6.1-17.6.4;
    DLMF 19.8.1, 19.8.5, 19.8.6)

    .. math::

        \mathcal{K}(m) = \frac{\pi}{2M(1, \sqrt p)},\qquad
        \mathcal{E}(m) = \mathcal{K}(m)\,\Big(1 - \Sigma(m)\Big),\qquad
        \Sigma(m) = \sum_{n\ge0} 2^{n-1}c_n^2 .

    :math:`1 - \Sigma(m) = \mathcal{E}/\mathcal{K}` is at least 0.728 for :math:`m \le 1/2`
    but tends to 0 as :math:`m \to 1`, so above :math:`m = 1/2` the second kind comes instead
    from Legendre's relation (A&S 17.3.13; DLMF 19.7.1) with the complementary integrals
    :math:`\mathcal{K}(p) = \pi/(2M(1, \sqrt m))` and :math:`\mathcal{K}(p) - \mathcal{E}(p)
    = \mathcal{K}(p)\,\Sigma(p)`:

    .. math::

        \mathcal{E}(m) = \frac{\pi/2 + \mathcal{K}(m)\,[\mathcal{K}(p) - \mathcal{E}(p)]}
        {\mathcal{K}(p)} = M(1, \sqrt m) + \mathcal{K}(m)\,\Sigma(p),

    a sum of two positive terms. Both means run together, as one AGM on a stacked array.
    Against a 60-digit evaluation, K is within 4 ulp (relative 6.7e-16, the round-off of up
    to nine AGM steps) and E within 2 ulp over the whole range.
    """
    p_arr = np.asarray(p, dtype=np.float64)
    m_arr = np.asarray(m, dtype=np.float64)
    if p_arr.shape != m_arr.shape:
        p_arr, m_arr = np.broadcast_arrays(p_arr, m_arr)
    if p_arr.size == 1:
        # one contact at a time (the common call, from a Newton solve): Python floats are
        # some ten times faster than NumPy's per-call overhead on one-element arrays
        k1, e1 = _scalar(float(p_arr.flat[0]), float(m_arr.flat[0]))
        return np.full(p_arr.shape, k1), np.full(p_arr.shape, e1)
    p_few = p_arr.ravel().tolist() if p_arr.size < _LOOP_SIZE else []
    m_few = m_arr.ravel().tolist() if p_few else []
    if p_few and all(
        0.0 <= p_i <= 1.0 and 0.0 <= m_i <= 1.0 for p_i, m_i in zip(p_few, m_few, strict=True)
    ):
        # a few contacts (a model's Hertz constants, angle by angle): Python floats entry by
        # entry, several times faster than NumPy's per-call overhead (bit for bit the same)
        pairs = [_scalar(p_i, m_i) for p_i, m_i in zip(p_few, m_few, strict=True)]
        k_few = np.array([k_i for k_i, _ in pairs]).reshape(p_arr.shape)
        return k_few, np.array([e_i for _, e_i in pairs]).reshape(p_arr.shape)
    if p_arr.size >= _COMPILED_SIZE and np.all((p_arr >= 0.0) & (p_arr <= 1.0)):
        # many contacts at once: the float loop compiled, entry by entry (bit for bit)
        from runout.geometry._elliptic_kernel import complete_elliptic_all

        k_all, e_all, converged = complete_elliptic_all(
            np.ascontiguousarray(p_arr).ravel(),
            np.ascontiguousarray(m_arr).ravel(),
            _MAX_STEPS,
            _TOLERANCE,
            _TINY,
        )
        if not converged:  # pragma: no cover - cannot happen for arguments in [0, 1]
            raise ArithmeticError("the arithmetic-geometric mean did not converge")
        return k_all.reshape(p_arr.shape), e_all.reshape(p_arr.shape)
    # M(1, √p) with c₀² = m gives K(m) and Σ(m) for every entry; M(1, √m) with c₀² = p is
    # needed only above m = 1/2 (Legendre). Each entry stops at its own convergence, so
    # evaluating a subset changes no bit. b₀ = 0 (K(1) = ∞, set below) would never meet the
    # stopping test: start at the least double.
    mean, total = _agm(np.sqrt(np.where(p_arr == 0.0, _TINY, p_arr)), m_arr, np.sqrt, _any)
    k = _HALF_PI / mean
    e = k * (1.0 - total)
    high = m_arr > 0.5
    if high.any():
        mean_c, total_c = _agm(np.sqrt(m_arr[high]), p_arr[high], np.sqrt, _any)
        e[high] = mean_c + k[high] * total_c
    if (p_arr == 0.0).any():
        k = np.where(p_arr == 0.0, np.inf, k)
        e = np.where(p_arr == 0.0, 1.0, e)
    return k, e


def _scalar(p: float, m: float) -> tuple[float, float]:
    """:func:`complete_elliptic` of one pair of Python floats."""
    if not (0.0 <= p <= 1.0 and 0.0 <= m <= 1.0):  # NaN or outside [0, 1]: as arrays do
        k_arr, e_arr = complete_elliptic(np.array([p, p]), np.array([m, m]))
        return float(k_arr[0]), float(e_arr[0])
    if p == 0.0:
        return math.inf, 1.0
    mean, total = _agm_float(math.sqrt(p), m)
    k = _HALF_PI / mean
    if m <= 0.5:
        return k, k * (1.0 - total)
    mean_c, total_c = _agm_float(math.sqrt(m), p)
    return k, mean_c + k * total_c


def _agm_float(b: float, c_sq: float) -> tuple[float, float]:
    """:func:`_agm` of Python floats: the same operations, without NumPy's per-call cost
    (locals only: the models' Hertz constants call it a few hundred times per solve)."""
    a, total, weight = 1.0, 0.5 * c_sq, 1.0
    tolerance = _TOLERANCE
    for _ in range(_MAX_STEPS):
        a_next = 0.5 * (a + b)
        b = math.sqrt(a * b)
        a = a_next
        c = c_sq / (4.0 * a)
        c_sq = c * c
        total = total + weight * c_sq
        weight *= 2.0
        if not c > tolerance * a:  # NaN counts as converged
            return a, total
    raise ArithmeticError("the arithmetic-geometric mean did not converge")  # pragma: no cover


def _any(x: NDArray[np.bool_]) -> bool:
    return bool(x.any())


def _agm(b: _T, c_sq: _T, sqrt: Callable[[_T], _T], any_: Callable[[Any], bool]) -> tuple[_T, _T]:
    """M(1, b) and Σ = Σ 2^(n-1) c_n² with c₀² = ``c_sq``, on floats or arrays alike.

    Every entry stops at its own convergence (arrays keep a converged entry as it is), so an
    entry's value never depends on the other entries of the array: floats, arrays and the
    compiled loop (:func:`runout.geometry._elliptic_kernel.complete_elliptic_all`) agree bit for
    bit.
    """
    if isinstance(b, float):
        return _agm_float(b, c_sq)
    else:
        a_arr = np.ones_like(b)
        total_arr = 0.5 * c_sq
        weight = 1.0
        active = np.ones(np.shape(b), dtype=np.bool_)
        for _ in range(_MAX_STEPS):
            a_next = 0.5 * (a_arr + b)
            b_next = sqrt(a_arr * b)
            c = c_sq / (4.0 * a_next)
            c_sq_next = c * c
            total_next = total_arr + weight * c_sq_next
            a_arr = np.where(active, a_next, a_arr)
            b = np.where(active, b_next, b)
            c_sq = np.where(active, c_sq_next, c_sq)
            total_arr = np.where(active, total_next, total_arr)
            active &= c > _TOLERANCE * a_next  # NaN counts as converged
            weight *= 2.0
            if not any_(active):
                return a_arr, total_arr
    raise ArithmeticError("the arithmetic-geometric mean did not converge")  # pragma: no cover
