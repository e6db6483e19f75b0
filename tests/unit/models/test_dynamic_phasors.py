"""Rotating phasors of the dynamic kernel against the direct evaluation (NumPy), radial path."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cases import WAVY, dynamic_case
from runout.models import _dynamic_kernels as dk
from runout.models import dynamic as dy

WAVY_BALLS = [*WAVY, {"part": "ball", "order": 4, "amplitude": 5e-9, "element": 1, "phase": 1.0}]


def _setup(unbalance: float = 1e-7) -> dy.DynamicSetup:
    return dy.setup(dynamic_case(waviness=WAVY_BALLS, dynamics={"unbalance": unbalance}))


def _phasor_state(s: dy.DynamicSetup, h: float, t0: float, steps: int) -> tuple[np.ndarray, ...]:
    """Deviations after anchoring at t0 and rotating ``steps`` times by h (the kernel's path)."""
    par = s.params(h)
    rate, ball, ring, bcoef = dk._phasor_tables(par, s.theta0, s.harmonics)
    ph = np.empty((rate.size, 2))
    dk._phasor_anchor(t0, rate, ph)
    rot = np.column_stack([np.cos(rate * h), np.sin(rate * h)])
    for _ in range(steps):
        dk._phasor_rotate(ph, rot)
    z = s.n_elements
    cth, sth, gap, wb = (np.empty(z) for _ in range(4))
    dk._phasor_deviations(ph, ball, ring, bcoef, s.harmonics[9], par[dk.P_G0], cth, sth, gap, wb)
    return cth, sth, gap, wb, ph[1]


@settings(max_examples=40, deadline=None)
@given(
    t0=st.floats(0.0, 0.5),
    steps=st.integers(0, dk.ANCHOR_STEPS),
    h=st.floats(1e-7, 2e-5),
)
def test_rotated_phasors_match_direct_evaluation(t0: float, steps: int, h: float) -> None:
    s = _setup()
    cth, sth, gap, wb, unb = _phasor_state(s, h, t0, steps)
    t = t0 + steps * h
    theta, gap_ref, wb_ref = dy._deviations_np(s, np.array([t]))
    # phase error ~ (steps + angle/eps) ulp: far below 1e-12 of the amplitudes
    assert np.allclose(cth, np.cos(theta[0]), rtol=0.0, atol=1e-12)
    assert np.allclose(sth, np.sin(theta[0]), rtol=0.0, atol=1e-12)
    amp = 50e-9
    assert np.allclose(gap, gap_ref[0], rtol=0.0, atol=1e-12 * amp)
    assert np.allclose(wb, wb_ref[0], rtol=0.0, atol=1e-12 * amp)
    wu = s.unbalance_omega * t
    assert np.allclose(unb, [np.cos(wu), np.sin(wu)], rtol=0.0, atol=1e-12)


def test_phasor_deviations_match_the_compiled_direct_kernel() -> None:
    s = _setup()
    par = s.params(1e-6)
    z = s.n_elements
    direct = [np.empty(z) for _ in range(4)]
    dy._deviations(0.0123, par, s.theta0, s.harmonics, *direct)
    phasor = _phasor_state(s, 1e-6, 0.0123, 0)[:4]
    for a, b in zip(phasor, direct, strict=True):
        assert np.allclose(a, b, rtol=1e-13, atol=1e-22)


def test_perfect_parts_have_only_the_cage_and_unbalance_phasors() -> None:
    s = dy.setup(dynamic_case())
    rate, _ball, ring, bcoef = dk._phasor_tables(s.params(1e-6), s.theta0, s.harmonics)
    assert rate.size == 2 and ring.shape[1] == 0 and bcoef.shape[0] == 0


@pytest.mark.parametrize("unbalance", [0.0, 1e-7])
def test_radial_newmark_path_matches_the_numpy_reference(unbalance: float) -> None:
    # z_p = 0 and two degrees of freedom: the kernel takes its radial path (seed 003 eq. 2.4)
    s = _setup(unbalance)
    assert s.ndof == 2 and s.axial_offset == 0.0
    q0 = dy.static_equilibrium(s, np.array([0.0]))[0]
    state = np.zeros(9)
    state[:3] = q0 + np.array([3e-8, -2e-8, 0.0])
    # more steps than ANCHOR_STEPS: both the rotation and the re-anchoring are exercised
    h, n = 5e-6, dk.ANCHOR_STEPS + 44
    ref = dy.newmark_reference(s, h, n, state.copy())
    out = np.zeros((n, 3))
    status, _, _, _ = dy.newmark_kernel(
        n, 1, 0.0, state.copy(), s.params(h), s.theta0, s.harmonics, s.ndof, dy.MAX_ITER, out
    )
    assert status == dy.OK
    scale = np.abs(ref).max()
    assert np.allclose(out, ref, rtol=0.0, atol=1e-9 * scale)
