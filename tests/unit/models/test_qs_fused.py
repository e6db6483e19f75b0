"""Fused quasi-static kernels: phasor evaluation of the deviations vs NumPy, one solve a run,
no per-instant temporaries, the memory and phase limits of the estimate."""

from __future__ import annotations

import math
import tracemalloc
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.api import Imperfections as Builder
from runout.base.errors import CaseError
from runout.case.estimates import estimate_run
from runout.case.limits import BYTES_QUASI_STATIC
from runout.case.model import Case
from runout.examples import tada_bearing
from runout.geometry.bearing import Operation
from runout.geometry.imperfections import BearingImperfections, Harmonics
from runout.models import quasi_static_2d as qs2
from runout.models import quasi_static_3d as qs3
from runout.models._quasi_static import (
    ANCHOR,
    Kinematics,
    contact_deviations,
    contact_series,
    contact_sources,
    time_grid,
)
from runout.runner import run_model

KIN = Kinematics(inner=0.0, outer=90.0, cage=50.6, spin=310.1, rotating_ring="outer", n_elements=7)


def _imperfections(rng: np.random.Generator, z: int, balls: bool = True) -> BearingImperfections:
    def harmonics(count: int, kmax: int) -> Harmonics:
        k = rng.choice(np.arange(0 if balls else 1, kmax + 1), size=count, replace=False)
        return Harmonics(k, rng.uniform(1e-9, 3e-8, count), rng.uniform(0, 2 * math.pi, count))

    elements = [harmonics(int(rng.integers(0, 4)), 12) for _ in range(z)] if balls else []
    return BearingImperfections(
        inner=harmonics(4, 30),
        outer=harmonics(3, 30),
        elements=elements or [Harmonics.empty()] * z,
        diameter_errors=rng.normal(0.0, 1e-8, z) if balls else None,
        pitch_errors=rng.normal(0.0, 1e-3, z),
    )


def numpy_contacts(
    imp: BearingImperfections,
    kin: Kinematics,
    t: np.ndarray,
    *,
    ring_gain: float,
    element_gain: float,
    offset: float,
    planar: bool,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """NumPy reference of :func:`contact_series`: every harmonic by np.cos at every instant.

    Seed 000 eq. 2 (3-D) and seed 001 eq. 10 (planar) at zero displacement, with the ball
    angles θ_j = 2π f_c t + 2π j/Z + ε_j, the ring profiles read at θ_j - 2π f_ring t and the
    element diameters at the contact angle 2π f_b t (seed 002 eq. 26).
    """
    z = kin.n_elements
    w = 2 * math.pi
    theta = w * kin.cage * t[:, None] + w * np.arange(z)[None, :] / z + imp.pitch_errors
    rings = []
    for h, f in ((imp.inner, kin.inner), (imp.outer, kin.outer)):
        psi = theta - w * f * t[:, None]
        total = np.zeros_like(theta)
        for k, a, p in zip(h.orders, h.amplitudes, h.phases, strict=True):
            total += a * np.cos(k * psi + p)
        rings.append(total)
    spin = w * kin.contact_rate * t
    ball = np.zeros_like(theta)
    for j, h in enumerate(imp.element_diameter_deviations()):
        for k, a, p in zip(h.orders, h.amplitudes, h.phases, strict=True):
            ball[:, j] += a * np.cos(k * spin + p)
    if planar:
        c = offset + 0.5 * (rings[0] + element_gain * ball - rings[1])
    else:
        c = (rings[0] - rings[1]) * ring_gain + ball + offset
    return c, np.cos(theta), np.sin(theta)


def _amplitude(imp: BearingImperfections) -> float:
    elements = sum(float(np.sum(h.amplitudes)) for h in imp.element_diameter_deviations())
    return float(np.sum(imp.inner.amplitudes) + np.sum(imp.outer.amplitudes)) + elements


@pytest.mark.parametrize("planar", [False, True])
@pytest.mark.parametrize("uniform", [True, False])
def test_fused_evaluation_matches_numpy(planar: bool, uniform: bool) -> None:
    rng = np.random.default_rng(7)
    imp = _imperfections(rng, KIN.n_elements)
    t = time_grid(90.0, 30.0, 3000)
    if not uniform:  # anchored at every instant: the direct evaluation
        t = np.sort(t * (1.0 + 0.01 * np.sin(np.arange(t.size))))
    gains = {"ring_gain": 0.87, "element_gain": 0.9, "offset": 1.4e-6, "planar": planar}
    src = contact_sources(imp, KIN, **gains)
    c, cth, sth = contact_series(t, *src.args())
    c_ref, cth_ref, sth_ref = numpy_contacts(imp, KIN, t, **gains)
    np.testing.assert_allclose(c, c_ref, rtol=0, atol=1e-12 * _amplitude(imp))
    np.testing.assert_allclose(cth, cth_ref, rtol=0, atol=1e-12)
    np.testing.assert_allclose(sth, sth_ref, rtol=0, atol=1e-12)


def test_fused_evaluation_matches_the_model_deviations() -> None:
    """Same as contact_deviations (the arrays the models used to build), to round-off."""
    rng = np.random.default_rng(3)
    imp = _imperfections(rng, KIN.n_elements)
    t = time_grid(90.0, 72.0, 4 * ANCHOR + 17)
    dev = contact_deviations(imp, KIN, t)
    src = contact_sources(imp, KIN, ring_gain=0.5, element_gain=1.0, offset=0.0, planar=False)
    c, cth, _ = contact_series(t, *src.args())
    expect = (dev.inner - dev.outer) * 0.5 + dev.ball
    np.testing.assert_allclose(c, expect, rtol=0, atol=1e-12 * _amplitude(imp))
    np.testing.assert_allclose(cth, np.cos(dev.theta), rtol=0, atol=1e-12)


def test_empty_parts_cost_nothing() -> None:
    """No element harmonics: nothing packed for the elements (no work per instant)."""
    imp = BearingImperfections(inner=Harmonics([5], [1e-8]), elements=[Harmonics.empty()] * 7)
    src = contact_sources(imp, KIN, ring_gain=1.0, element_gain=1.0, offset=0.0, planar=False)
    assert src.ball.shape == (3, 0) and src.ring.shape == (3, 1) and src.n_inner == 1
    perfect = contact_sources(
        BearingImperfections.perfect(7),
        KIN,
        ring_gain=1.0,
        element_gain=1.0,
        offset=2e-6,
        planar=False,
    )
    c, _, _ = contact_series(time_grid(90.0, 2.0, 64), *perfect.args())
    assert np.all(c == 2e-6)


@settings(max_examples=25, deadline=None)
@given(
    seed=st.integers(0, 2**32 - 1),
    revolutions=st.floats(0.5, 500.0),
    samples=st.integers(16, 3 * ANCHOR),
    planar=st.booleans(),
)
def test_recurrence_stays_within_round_off_of_direct_evaluation(
    seed: int, revolutions: float, samples: int, planar: bool
) -> None:
    """Invariant: rotating the phasors between anchors changes nothing beyond round-off of
    the arguments (k θ ε): the uniform grid (recurrence) against the same instants evaluated
    directly (a grid the kernel sees as non-uniform, by one extra instant out of order)."""
    rng = np.random.default_rng(seed)
    imp = _imperfections(rng, KIN.n_elements)
    t = time_grid(90.0, revolutions, samples)
    src = contact_sources(imp, KIN, ring_gain=0.8, element_gain=1.0, offset=0.0, planar=planar)
    c, cth, _ = contact_series(t, *src.args())
    jumbled = np.empty(2 * t.size)
    jumbled[0::2] = t
    jumbled[1::2] = -1.0  # every other instant off the grid: every instant is anchored
    c_direct, cth_direct, _ = contact_series(jumbled, *src.args())
    angle = 2 * math.pi * revolutions * 40.0  # orders up to 30, spin ~3.4x the rotation
    tol = (1e-13 + 8 * angle * 2.0**-52) * _amplitude(imp)
    np.testing.assert_allclose(c, c_direct[0::2], rtol=0, atol=tol)
    np.testing.assert_allclose(cth, cth_direct[0::2], rtol=0, atol=1e-13 + angle * 2.0**-52)


# --------------------------------------------------------------------------------------------
# the fused solves against the kernels on precomputed arrays
# --------------------------------------------------------------------------------------------
def _tada(samples: int = 512, radial: float = 0.0, **analysis: Any) -> Case:
    waves = (
        Builder(elements=8)
        .waviness("inner", 7, amplitude=1e-8)
        .waviness("outer", 9, amplitude=1e-8, phase=1.0)
        .waviness("ball", 4, amplitude=5e-9, element=3)
        .pitch_errors([0, 1e-3, 0, 0, 0, 0, -2e-3, 0])
    )
    return Case.from_inputs(
        tada_bearing(radial_clearance=10e-6),
        Operation(rotating_ring="outer", speed=90.0, axial_load=20.0, radial_load=radial),
        waves,
        analysis={"model": "quasi_static_3d", "revolutions": 10, "samples": samples, **analysis},
    )


@pytest.mark.parametrize("radial", [0.0, 3.0])
def test_fused_3d_solve_matches_the_array_kernel(radial: float) -> None:
    case = _tada(radial=radial)
    s = qs3.setup(case)
    t = qs3.time_grid_of(case)
    disp, unloaded = qs3.solve(case, t, s)
    c, theta = qs3.approaches(case, s, t)
    ca, sa = math.cos(s.contact_angle), math.sin(s.contact_angle)
    q, unl, status, _ = qs3.solve_kernel(
        c, theta, ca, sa, s.stiffness, s.force, np.zeros(3), s.preload, qs3.MAX_ITER
    )
    assert status == qs3.OK
    np.testing.assert_allclose(-disp, q.T, rtol=0, atol=1e-9 * s.preload)
    np.testing.assert_array_equal(unloaded, unl)
    # and the vectorised NumPy reference
    ref = qs3.solve_reference(c, theta, s.contact_angle, s.stiffness, s.force, tol=1e-14)
    np.testing.assert_allclose(-disp, ref.T, rtol=0, atol=1e-9 * s.preload)


@pytest.mark.parametrize("projection", ["none", "radial"])
def test_fused_2d_solve_matches_the_array_kernel(projection: Any) -> None:
    case = _tada(radial=2.0)
    s = qs2.setup(case)
    t = qs3.time_grid_of(case)
    disp, unloaded = qs2.solve(case, t, s, element_projection=projection)
    c, theta = qs2.approaches(case, s, t, projection)
    q, unl, status, _ = qs2.solve_kernel_loaded(
        c, theta, s.stiffness, s.initial_approach, qs2.MAX_ITER, s.force
    )
    assert status == qs2.OK
    np.testing.assert_allclose(disp[:2], q.T, rtol=0, atol=1e-9 * s.initial_approach)
    assert np.all(disp[2] == 0.0)
    np.testing.assert_array_equal(unloaded, unl)


# --------------------------------------------------------------------------------------------
# issue 16 item 1: a run solves once; memory
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize("model", ["quasi_static_3d", "quasi_static_2d"])
def test_a_run_solves_the_record_once(monkeypatch: pytest.MonkeyPatch, model: str) -> None:
    module = qs3 if model == "quasi_static_3d" else qs2
    calls: list[int] = []
    kernel = module.solve_fused

    def counting(t: np.ndarray, *args: Any) -> Any:
        calls.append(t.size)
        return kernel(t, *args)

    monkeypatch.setattr(module, "solve_fused", counting)
    monkeypatch.setattr(qs3, "solve_kernel", None)  # the array kernels are not used either
    monkeypatch.setattr(qs2, "solve_kernel_loaded", None)
    case = _tada(samples=1000, model=model)
    result = run_model(case)
    assert calls == [1000]
    assert result.time.size == 1000


def test_solve_allocates_no_per_instant_temporaries() -> None:
    """The record (3, n) and the int16 counts only: 26 B an instant, no (n, Z) arrays."""
    case = _tada()
    s = qs3.setup(case)
    n = 1 << 16
    t = time_grid(90.0, 10.0, n)
    qs3.solve(case, t[:64], s)  # compiled
    tracemalloc.start()
    try:
        disp, unloaded = qs3.solve(case, t, s)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert unloaded.dtype == np.int16 and disp.shape == (3, n)
    assert peak <= 26 * n + 65536


def test_estimate_counts_one_solve_and_refuses_lost_phases() -> None:
    case = _tada(samples=1 << 22)
    est = estimate_run(case, "quasi_static_3d")
    # at least the record and the decomposition (measured ~100 B an instant), and 2^22 instants
    # fit the default budget of 2 GiB
    assert (1 << 22) * BYTES_QUASI_STATIC <= est.memory < 2 * 1024**3
    assert "4.194e+06 instants" in est.memory_what
    with pytest.raises(CaseError, match=r"analysis\.revolutions"):  # the estimate's LimitError
        _tada(revolutions=2e7)
