"""Compiled arithmetic-geometric mean for large arrays (see :mod:`runout.geometry._elliptic`).

Kept apart so that importing :mod:`runout.geometry._elliptic` (and so
:mod:`runout.geometry.contact`) does not import numba: the light commands (``runout
frequencies``, ``check``) evaluate one contact at a time and never come here.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from runout.base._kernel import kernel


@kernel()
def _agm_one(b: float, c_sq: float, max_steps: int, tolerance: float) -> tuple[float, float, bool]:
    """M(1, b) and Σ 2^(n-1) c_n² of one entry: the float loop of
    :func:`runout.geometry._elliptic._agm`."""
    a = 1.0
    total = 0.5 * c_sq
    weight = 1.0
    for _ in range(max_steps):
        a_next = 0.5 * (a + b)
        b = math.sqrt(a * b)
        a = a_next
        c = c_sq / (4.0 * a)
        c_sq = c * c
        total = total + weight * c_sq
        weight *= 2.0
        if not c > tolerance * a:  # NaN counts as converged
            return a, total, True
    return a, total, False


@kernel()
def complete_elliptic_all(
    p: NDArray[np.float64], m: NDArray[np.float64], max_steps: int, tolerance: float, tiny: float
) -> tuple[NDArray[np.float64], NDArray[np.float64], bool]:
    """K(m) and E(m) of every entry, as :func:`runout.geometry._elliptic.complete_elliptic` does
    them.

    Entry by entry the operations of its float path (``_scalar``): M(1, √p) for K and, above
    m = 1/2, M(1, √m) for E by Legendre's relation; p = 0 gives (∞, 1).
    """
    n = p.size
    k = np.empty(n)
    e = np.empty(n)
    converged = True
    half_pi = 0.5 * math.pi
    for i in range(n):
        p_i = p[i]
        m_i = m[i]
        if p_i == 0.0:
            k[i] = math.inf
            e[i] = 1.0
            continue
        mean, total, ok = _agm_one(math.sqrt(max(p_i, tiny)), m_i, max_steps, tolerance)
        converged = converged and ok
        k_i = half_pi / mean
        k[i] = k_i
        if m_i > 0.5:
            mean_c, total_c, ok = _agm_one(math.sqrt(m_i), p_i, max_steps, tolerance)
            converged = converged and ok
            e[i] = mean_c + k_i * total_c
        else:
            e[i] = k_i * (1.0 - total)
    return k, e, converged
