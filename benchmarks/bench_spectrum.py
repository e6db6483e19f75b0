"""Benchmark of runout.analysis.spectrum: least-squares extraction of many known lines.

Ours: :func:`runout.analysis.spectrum.extract_lines` (closed-form Gram matrix, projections as BLAS
products of 256-sample blocks, Cholesky with one refinement step, BLAS on one thread).
Reference: the straightforward approach, building the dense 65,536 x 401 design matrix and
calling :func:`numpy.linalg.lstsq`, also with its BLAS on one thread: on a shared 2-core
machine a threaded BLAS made it ten times slower when the other core was busy (2.5 s vs
26 s), which measures the machine, not the method.
"""

from __future__ import annotations

import numpy as np
from threadpoolctl import threadpool_limits

from _harness import BenchResult, best_time
from runout.analysis.spectrum import extract_lines

N_SAMPLES = 65_536
N_LINES = 200
SAMPLE_RATE = 1000.0


def _problem() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(2024)
    t = np.arange(N_SAMPLES) / SAMPLE_RATE
    # 200 distinct non-bin frequencies at least 1 Hz apart (record resolution 0.015 Hz)
    f = np.sort(
        rng.choice(np.arange(1, 490), N_LINES, replace=False) + rng.uniform(0, 0.5, N_LINES)
    )
    amp = rng.uniform(0.1, 1.0, N_LINES)
    phi = rng.uniform(-np.pi, np.pi, N_LINES)
    x = 0.1 + (amp * np.cos(2 * np.pi * np.multiply.outer(t, f) + phi)).sum(axis=1)
    x += rng.normal(scale=1e-3, size=N_SAMPLES)
    return t, x, f


def _dense_lstsq(t: np.ndarray, x: np.ndarray, f: np.ndarray) -> np.ndarray:
    ph = 2 * np.pi * np.multiply.outer(t, f)
    design = np.hstack([np.ones((t.size, 1)), np.cos(ph), np.sin(ph)])
    coef = np.linalg.lstsq(design, x, rcond=None)[0]
    return np.hypot(coef[1 : 1 + f.size], coef[1 + f.size :])


def bench_extract_lines_200_lines_65536_samples() -> BenchResult:
    t, x, f = _problem()
    ours_amp = extract_lines(t, x, f).amplitude
    ref_amp = _dense_lstsq(t, x, f)
    if not np.allclose(ours_amp, ref_amp, rtol=0, atol=1e-9):
        raise AssertionError("extract_lines and dense lstsq disagree")
    ours = best_time(lambda: extract_lines(t, x, f), repeat=5)
    with threadpool_limits(limits=1, user_api="blas"):
        ref = best_time(lambda: _dense_lstsq(t, x, f), repeat=1)
    return BenchResult(
        name="extract_lines 200 lines x 65536 samples",
        ours_s=ours,
        reference_s=ref,
        reference="dense numpy.linalg.lstsq",
        target=">= 10x faster",
        met=ref / ours >= 10.0,
    )
