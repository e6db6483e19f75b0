"""Harmonic-sum kernel (runout.geometry._kernels.harmonic_sum) against straightforward NumPy.

Workload: 2,400 harmonics (a 0.1 µm / k^1.5 spectrum, random phases) at 65,536 angles
spanning 1,600 turns (k θ up to ~2.4e7 rad), i.e. 157 million cosine terms. That is the size of
seed 002's outer-ring spectrum (eq. 46, 1,358 orders) plus its inner-ring one (eq. 45) sampled
for a long NRRO record.

References:
* the per-harmonic NumPy loop, ``out += a_k * np.cos(k * θ + φ_k)`` for each k — what one
  writes first (target: ours at least 3× faster);
* the broadcasting NumPy expression of ``harmonic_sum_reference`` (chunked so the temporary
  stays at 4 million values) — also the accuracy reference (target: at least 3× faster).

The kernel is serial (no ``parallel=True``): the benchmark machine has 2 cores and the models
run several evaluations side by side.

Also: the fused evaluation of the quasi-static models
(:func:`runout.models._quasi_static.contact_series`: phasors rotated from instant to instant,
re-anchored every 256) on seed 002's 608 spectra, against the same deviations by NumPy
(``np.cos`` of every harmonic at every ball and instant, one harmonic at a time).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from _harness import BenchResult, best_time
from runout.geometry._kernels import harmonic_sum, harmonic_sum_reference

N_HARMONICS = 2_400
N_ANGLES = 65_536
TARGET = 3.0


def _workload() -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(20240601)
    k = np.arange(2, 2 + N_HARMONICS, dtype=np.float64)
    a = 0.1e-6 * k**-1.5
    p = rng.uniform(0.0, 2.0 * np.pi, N_HARMONICS)
    theta = np.linspace(0.0, 1600 * 2.0 * np.pi, N_ANGLES)
    return theta, k, a, p


def _numpy_loop(theta: np.ndarray, k: np.ndarray, a: np.ndarray, p: np.ndarray) -> np.ndarray:
    out = np.zeros_like(theta)
    for kj, aj, pj in zip(k, a, p, strict=True):
        out += aj * np.cos(kj * theta + pj)
    return out


def _check(ours: np.ndarray, ref: np.ndarray, a: np.ndarray) -> None:
    err = float(np.max(np.abs(ours - ref)) / np.sum(a))
    if err > 1e-12:
        raise AssertionError(f"harmonic_sum differs from the reference by {err:.3g} of Σa")


def bench_harmonic_sum_vs_numpy_loop() -> BenchResult:
    theta, k, a, p = _workload()
    _check(harmonic_sum(theta, k, a, p), _numpy_loop(theta, k, a, p), a)
    ours = best_time(lambda: harmonic_sum(theta, k, a, p), repeat=3)
    ref = best_time(lambda: _numpy_loop(theta, k, a, p), repeat=2)
    return BenchResult(
        name="harmonic_sum 2400 harmonics x 65536 angles",
        ours_s=ours,
        reference_s=ref,
        reference="numpy loop over harmonics",
        target=f">= {TARGET:g}x faster",
        met=ref / ours >= TARGET,
    )


def bench_harmonic_sum_vs_numpy_broadcast() -> BenchResult:
    theta, k, a, p = _workload()
    _check(harmonic_sum(theta, k, a, p), harmonic_sum_reference(theta, k, a, p), a)
    ours = best_time(lambda: harmonic_sum(theta, k, a, p), repeat=3)
    ref = best_time(lambda: harmonic_sum_reference(theta, k, a, p), repeat=2)
    return BenchResult(
        name="harmonic_sum 2400 harmonics x 65536 angles",
        ours_s=ours,
        reference_s=ref,
        reference="numpy broadcast (chunked)",
        target=f">= {TARGET:g}x faster",
        met=ref / ours >= TARGET,
    )


def _numpy_contacts(imp, kin, t, gain):  # type: ignore[no-untyped-def]
    """(W_i - W_o) g + W_b at every instant and ball by NumPy (seed 000 eq. 2 without δ_pl)."""
    z, w = kin.n_elements, 2.0 * math.pi
    theta = w * kin.cage * t[:, None] + w * np.arange(z)[None, :] / z + imp.pitch_errors
    c = np.zeros_like(theta)
    for h, f, sign in ((imp.inner, kin.inner, 1.0), (imp.outer, kin.outer, -1.0)):
        psi = theta - w * f * t[:, None]
        for k, a, p in zip(h.orders, h.amplitudes, h.phases, strict=True):
            c += (sign * gain * a) * np.cos(k * psi + p)
    spin = w * kin.contact_rate * t
    for j, h in enumerate(imp.element_diameter_deviations()):
        for k, a, p in zip(h.orders, h.amplitudes, h.phases, strict=True):
            c[:, j] += a * np.cos(k * spin + p)
    return c


def bench_fused_contacts_vs_numpy() -> BenchResult:
    """Seed 002's 608 (2,157 ring and 144 ball harmonics, 7 balls), 8,192 instants."""
    from runout.case.model import load_case
    from runout.models import quasi_static_3d as qs3
    from runout.models._quasi_static import contact_series, contact_sources, time_grid

    case = load_case(Path(__file__).resolve().parents[1] / "examples" / "seed002_608.toml")
    st = qs3.setup(case)
    imp, kin = case.imperfections, st.kinematics
    t = time_grid(case.operation.speed, case.analysis.revolutions, 8192)
    gain = math.cos(st.contact_angle)
    src = contact_sources(imp, kin, ring_gain=gain, element_gain=1.0, offset=0.0, planar=False)
    ref = _numpy_contacts(imp, kin, t, gain)
    err = float(np.abs(contact_series(t, *src.args())[0] - ref).max())
    if err > 1e-12 * float(np.abs(ref).max()):
        raise AssertionError(f"fused evaluation differs from NumPy by {err:.3g} m")
    ours = best_time(lambda: contact_series(t, *src.args()), repeat=3)
    reference = best_time(lambda: _numpy_contacts(imp, kin, t, gain), repeat=1)
    return BenchResult(
        name="fused contact deviations, 608 spectra, 8192 instants x 7 balls",
        ours_s=ours,
        reference_s=reference,
        reference="numpy cos per harmonic on (n, Z)",
        target=f">= {TARGET:g}x faster",
        met=reference / ours >= TARGET,
    )
