"""Closed-form solves of small symmetric positive definite systems for the Numba kernels."""

from __future__ import annotations

import math

from runout.base._kernel import kernel


@kernel()
def solve_spd3(h00, h01, h02, h11, h12, h22, r0, r1, r2):  # pragma: no cover - compiled
    """Solve the symmetric positive definite 3×3 system H s = r (compiled).

    The adjugate (fast) when H is well conditioned, det H > 1e-8 h00 h11 h22; otherwise a
    Cholesky factorisation, which stays accurate where the adjugate's determinant is lost to
    cancellation, e.g. H = (rank 1) + a small regularisation when a single contact is closed.

    Returns
    -------
    s0, s1, s2 : float
        The solution.
    ok : bool
        False when H is not positive definite (a non-positive Cholesky pivot or NaN).
    """
    a00 = h11 * h22 - h12 * h12
    a01 = h02 * h12 - h01 * h22
    a02 = h01 * h12 - h02 * h11
    det = h00 * a00 + h01 * a01 + h02 * a02
    if det > 1e-8 * h00 * h11 * h22:
        a11 = h00 * h22 - h02 * h02
        a12 = h01 * h02 - h00 * h12
        a22 = h00 * h11 - h01 * h01
        s0 = (a00 * r0 + a01 * r1 + a02 * r2) / det
        s1 = (a01 * r0 + a11 * r1 + a12 * r2) / det
        s2 = (a02 * r0 + a12 * r1 + a22 * r2) / det
        return s0, s1, s2, True
    if not h00 > 0.0:
        return 0.0, 0.0, 0.0, False
    l00 = math.sqrt(h00)
    l10 = h01 / l00
    l20 = h02 / l00
    p11 = h11 - l10 * l10
    if not p11 > 0.0:
        return 0.0, 0.0, 0.0, False
    l11 = math.sqrt(p11)
    l21 = (h12 - l20 * l10) / l11
    p22 = h22 - l20 * l20 - l21 * l21
    if not p22 > 0.0:
        return 0.0, 0.0, 0.0, False
    l22 = math.sqrt(p22)
    y0 = r0 / l00
    y1 = (r1 - l10 * y0) / l11
    y2 = (r2 - l20 * y0 - l21 * y1) / l22
    s2 = y2 / l22
    s1 = (y1 - l21 * s2) / l11
    s0 = (y0 - l10 * s1 - l20 * s2) / l00
    return s0, s1, s2, True
