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
    ref_s = best_time(lambda: reference(N_REF), repeat=1) * (t.size / N_REF)
    return BenchResult(
        name="quasi_static_3d Tada Fig. 7, 4096 instants",
        ours_s=ours_s,
        reference_s=ref_s,
        reference="scipy.optimize.root per instant (scaled from 256 instants)",
        target="< 5 ms after compilation and >= 300x faster",
        met=ours_s < 5e-3 and ref_s / ours_s >= 300.0,
    )
