"""The stiffness at the tool (issue 29 item 2): 1/C_ii of the nose compliance, the shaft free to
tilt, checked by hand on a rigid shaft on two radial springs and against the 5×5 diagonal."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.analysis.result_details import tool_point_stiffness


def _two_springs(k1: float, k2: float, p1: float, p2: float, ka: float, pn: float) -> np.ndarray:
    """5×5 stiffness at the nose (x, y, z, θx, θy) of a rigid shaft on two radial springs k1, k2
    at z = p1, p2 and an axial spring ka: built at the origin (a spring at p sees x + p θy and
    y - p θx), moved to the nose as the spindle model does (K_n = T^-T K T^-1)."""
    k = np.zeros((5, 5))
    for kk, p in ((k1, p1), (k2, p2)):
        gx = np.array([1.0, 0.0, 0.0, 0.0, p])  # x + p θy
        gy = np.array([0.0, 1.0, 0.0, -p, 0.0])  # y - p θx
        k += kk * (np.outer(gx, gx) + np.outer(gy, gy))
    k[2, 2] = ka
    t = np.eye(5)
    t[0, 4], t[1, 3] = pn, -pn
    ti = np.linalg.inv(t)
    return np.asarray(ti.T @ k @ ti)


def _by_hand(k1: float, k2: float, p1: float, p2: float, pn: float) -> float:
    """A force F at the nose: the bearings react F a1 and F a2 (a1 = (pn - p2)/(p1 - p2),
    a2 = 1 - a1, moments about each bearing); the nose moves a1 u1 + a2 u2 with u_i = R_i/k_i
    (the shaft is straight): k = 1 / (a1²/k1 + a2²/k2)."""
    a1 = (pn - p2) / (p1 - p2)
    a2 = 1.0 - a1
    return 1.0 / (a1**2 / k1 + a2**2 / k2)


def test_overhung_nose_on_two_equal_springs() -> None:
    # springs 2e8 N/m at 0 and 0.1 m, the tool 0.1 m out: a1 = 2, a2 = -1, k = 2e8 / 5
    k = _two_springs(2e8, 2e8, 0.0, 0.1, 5e7, -0.1)
    kx, ky, kz = tool_point_stiffness(k)
    assert kx == pytest.approx(4e7, rel=1e-12)
    assert ky == pytest.approx(4e7, rel=1e-12)
    assert kz == pytest.approx(5e7, rel=1e-12)  # the axial spring does not couple to tilt
    # the diagonal holds the tilt: both springs push the nose, 4e8 N/m, ten times more
    assert k[0, 0] == pytest.approx(4e8, rel=1e-12)


@settings(max_examples=60, deadline=None)
@given(
    k1=st.floats(1e6, 1e10),
    k2=st.floats(1e6, 1e10),
    p1=st.floats(-0.2, 0.2),
    gap=st.floats(0.005, 0.3),
    pn=st.floats(-0.5, 0.5),
)
def test_two_springs_by_hand(k1: float, k2: float, p1: float, gap: float, pn: float) -> None:
    k = _two_springs(k1, k2, p1, p1 + gap, 1e8, pn)
    kx, ky, _ = tool_point_stiffness(k)
    expected = _by_hand(k1, k2, p1, p1 + gap, pn)
    # a 5×5 solve of a matrix whose condition grows like (lever / gap)² · k1/k2: 1e-6 covers it
    assert kx == pytest.approx(expected, rel=1e-6)
    assert ky == pytest.approx(expected, rel=1e-6)
    # never stiffer than the diagonal with the tilt held
    assert kx <= k[0, 0] * (1 + 1e-9)
