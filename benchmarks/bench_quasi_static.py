"""Benchmark of the quasi-static 3-D model (seed 000): the Fig. 7 case, 4,096 instants.

Ours: the compiled Newton kernel :func:`runout.models.quasi_static_3d.solve_kernel` (closed-form
3x3 solve, warm start), on the precomputed contact approaches. Reference: the same equations
(seed 000 eq. 5) solved instant by instant with :func:`scipy.optimize.root` (hybr, analytic
Jacobian, started from 0), timed on 256 instants and scaled to 4,096 in the same run.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from scipy.optimize import root

from _harness import BenchResult, best_time
from runout.case import load_case
from runout.models import quasi_static_3d as qs3

CASE = Path(__file__).resolve().parents[1] / "examples" / "seed000_tada_fig7.toml"
N_REF = 256


def bench_quasi_static_3d_tada_fig7() -> BenchResult:
    case = load_case(CASE)
    st = qs3.setup(case)
    t = qs3.time_grid_of(case)
    c, theta = qs3.approaches(case, st, t)
    ca, sa = math.cos(st.contact_angle), math.sin(st.contact_angle)
    args = (c, theta, ca, sa, st.stiffness, st.force, np.zeros(3), st.preload, qs3.MAX_ITER)

    def ours() -> np.ndarray:
        return qs3.solve_kernel(*args)[0]

    def reference(n: int) -> np.ndarray:
        out = np.empty((n, 3))
        scale = st.preload
        for i in range(n):
            nv = np.stack(
                [ca * np.cos(theta[i]), ca * np.sin(theta[i]), np.full(c.shape[1], sa)], 1
            )

            def f(u: np.ndarray, i: int = i, nv: np.ndarray = nv) -> np.ndarray:
                d = np.maximum(c[i] - nv @ (u * scale), 0.0)
                return (st.stiffness * d**1.5) @ nv - st.force

            def jac(u: np.ndarray, i: int = i, nv: np.ndarray = nv) -> np.ndarray:
                d = np.maximum(c[i] - nv @ (u * scale), 0.0)
                return -(nv.T * (1.5 * st.stiffness * np.sqrt(d))) @ nv * scale

            # started from 0 each time: hybr's relative tolerance stops at once from a
            # near-zero warm start
            sol = root(f, np.zeros(3), jac=jac, method="hybr", tol=1e-13)
            out[i] = sol.x * scale
        return out

    got = ours()
    ref = reference(N_REF)
    if not np.allclose(got[:N_REF], ref, rtol=0, atol=1e-6 * st.preload):
        raise AssertionError("kernel and scipy.optimize.root disagree")
    ours_s = best_time(ours, repeat=7)
    ref_s = best_time(lambda: reference(N_REF), repeat=3) * (t.size / N_REF)
    return BenchResult(
        name="quasi_static_3d Tada Fig. 7, 4096 instants",
        ours_s=ours_s,
        reference_s=ref_s,
        reference="scipy.optimize.root per instant (scaled from 256 instants)",
        target="< 5 ms after compilation and >= 300x faster",
        met=ours_s < 5e-3 and ref_s / ours_s >= 300.0,
    )


def bench_quasi_static_3d_cost_per_instant() -> BenchResult:
    """Cost linear in the number of instants: time per instant at 2^12 ... 2^20 (Fig. 7 case).

    Ours: the full solve (contact deviations + compiled kernel) at 2^20 instants, per instant.
    Reference: the same at 2^12 instants, per instant. Linear cost means a ratio near 1.
    Prints the time per instant at every size.
    """
    case = load_case(CASE)
    st = qs3.setup(case)
    per: dict[int, float] = {}
    for p in (12, 14, 16, 18, 20):
        n = 2**p
        t = np.arange(n) * (0.8 / n)
        best = best_time(lambda t=t: qs3.solve(case, t, st), repeat=3 if p < 18 else 1)
        per[p] = best / n
        print(f"  quasi_static_3d: 2^{p} instants, {per[p] * 1e6:.3f} us per instant")
    ratio = per[20] / per[12]
    return BenchResult(
        name="quasi_static_3d per instant, 2^20 vs 2^12",
        ours_s=per[20],
        reference_s=per[12],
        reference="same solve at 2^12 instants",
        target="time per instant at 2^20 within 1.5x of 2^12 (linear cost)",
        met=ratio < 1.5,
    )


def bench_cli_run_warm_start() -> BenchResult:
    """Wall time of ``runout run examples/seed000_tada_fig7.toml --json`` on a warm cache.

    Ours: the second of two calls (Numba's on-disk cache and Python's bytecode warm).
    Reference: the first call.
    """
    import subprocess
    import sys
    import time

    exe = Path(sys.executable).with_name("runout")
    times = []
    for _ in range(2):
        t0 = time.perf_counter()
        subprocess.run([str(exe), "run", str(CASE), "--json"], check=True, capture_output=True)
        times.append(time.perf_counter() - t0)
    print(f"  runout run --json: {times[0]:.2f} s, then {times[1]:.2f} s")
    return BenchResult(
        name="runout run seed000_tada_fig7 --json (warm)",
        ours_s=times[1],
        reference_s=times[0],
        reference="first call",
        target="< 2 s on a warm cache",
        met=times[1] < 2.0,
    )
