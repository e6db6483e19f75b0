"""Harmonic-sum kernel (runout._kernels.harmonic_sum) against straightforward NumPy.

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
"""

from __future__ import annotations

import numpy as np

from _harness import BenchResult, best_time
from runout._kernels import harmonic_sum, harmonic_sum_reference

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
