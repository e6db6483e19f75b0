"""Benchmarks of studies (runout.study): Monte Carlo of seed 001 Table 9 with the 2-D model.

Ours: :func:`runout.study.run_study` on examples/seed001_kim_table9.toml (1,000 bearings × 1,024
instants, ball diameters normal with σ = 0.1 µm), in-process: the batched Numba kernel
(:func:`runout._study_kernels.solve_batch`) plus a pseudo-inverse line fit. Reference: the naive
loop, one bearing at a time through the 2-D model's public ``run`` (case validation, solve,
line fit, runout split), timed on 20 bearings and scaled. The worker scaling (process pool) of
the 10^5-bearing run is printed.
"""

from __future__ import annotations

import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

from _harness import BenchResult, best_time
from runout.case import load_case, parse_case
from runout.models import quasi_static_2d as qs2
from runout.study import _context as _spawn
from runout.study import _init_worker, run_study, sample_rng

CASE = Path(__file__).resolve().parents[1] / "examples" / "seed001_kim_table9.toml"
N_REF = 20


def _reference_per_bearing(case, n: int) -> float:  # type: ignore[no-untyped-def]
    data = case.spec.model_dump(exclude_none=True, exclude={"study"})
    base = np.asarray(case.imperfections.diameter_errors)
    t0 = time.perf_counter()
    for i in range(n):
        draw = base + 0.1e-6 * sample_rng(1, i).standard_normal(10)
        variant = parse_case({**data, "elements": {"diameter_errors": list(draw)}}, "ref")
        qs2.run(variant)
    return (time.perf_counter() - t0) / n


def _with_samples(case, samples: int):  # type: ignore[no-untyped-def]
    data = case.spec.model_dump(exclude_none=True)
    data["study"]["samples"] = samples
    data["study"]["chunk_size"] = 2500
    return parse_case(data, str(CASE))


def bench_study_montecarlo_1000_bearings() -> BenchResult:
    case = load_case(CASE)
    ours = best_time(lambda: run_study(case), repeat=3)
    per = _reference_per_bearing(case, N_REF)
    return BenchResult(
        name="study: Monte Carlo 1,000 bearings x 1,024",
        ours_s=ours,
        reference_s=per * 1000,
        reference="per-bearing qs2.run loop",
        target="< 1 s on 2 cores",
        met=ours < 1.0,
    )


def bench_study_montecarlo_100k_bearings() -> BenchResult:
    case = _with_samples(load_case(CASE), 100_000)
    run_study(_with_samples(load_case(CASE), 100))  # compile, caches
    t0 = time.perf_counter()
    run_study(case)
    ours = time.perf_counter() - t0
    print(f"  10^5 bearings in-process (2 Numba threads): {ours:.2f} s", flush=True)
    for workers in (1, 2):
        # a process pool of N single-threaded workers (spawned; start-up included)
        pool = ProcessPoolExecutor(workers, mp_context=_spawn(), initializer=_init_worker)
        t0 = time.perf_counter()
        with pool:
            run_study(case, executor=pool)
        print(f"  10^5 bearings, {workers} worker process(es): {time.perf_counter() - t0:.2f} s")
    per = _reference_per_bearing(load_case(CASE), N_REF)
    return BenchResult(
        name="study: Monte Carlo 100,000 bearings x 1,024",
        ours_s=ours,
        reference_s=per * 100_000,
        reference="per-bearing qs2.run loop",
        target="< 60 s on 2 cores",
        met=ours < 60.0,
    )
