"""Benchmark of the dynamic model (seed 003): Newmark-β + Newton–Raphson kernel.

Problem: the seed 003 Table 2 rotor with Z = 9 balls, radial play 0.1 µm, no preload (only
the balls near the load line are loaded, so Newton needs about two iterations per step),
6 N radial load and a small unbalance, started from its static equilibrium.

* Ours: :func:`runout.models.dynamic.newmark_kernel`, one million steps at the default step
  (200 steps per period of the highest linearised natural frequency), after compilation.
* Reference: :func:`scipy.integrate.solve_ivp` (LSODA) on the first-order form of the same
  equations (:func:`runout.models.dynamic.rhs_first_order`). Both are compared with a
  DOP853 solution at rtol 1e-12 on a 20 ms window; LSODA's rtol is tightened (1e-4, 1e-5, ...)
  until its error is no larger than Newmark's, it is timed on that window and scaled to the
  simulated time of one million Newmark steps (LSODA's cost is linear in the simulated time
  of this steady problem).
"""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

from _harness import BenchResult, best_time
from runout.case import load_case
from runout.models import dynamic as dy

CASE = Path(__file__).resolve().parents[1] / "examples" / "seed003_purohit_clearance.toml"
N_STEPS = 1_000_000
WINDOW = 0.02


def _problem() -> tuple[dy.DynamicSetup, float, np.ndarray]:
    case = dy._variant(load_case(CASE), 9, 0.0)
    s = dy.setup(case)
    q0 = dy.static_equilibrium(s, np.array([0.0]))[0]
    fn = dy.linearised_natural_frequencies(s, q0).max()
    h = 1.0 / (dy.STEPS_PER_PERIOD * fn)
    state = np.zeros(9)
    state[:3] = q0
    f0, _ = dy.contact_forces(s, np.array([0.0]), q0[None])
    state[6:8] = (dy.external_force(s, np.array([0.0]))[0, :2] - f0[0, :2]) / s.mass
    return s, h, state


def bench_dynamic_newmark_million_steps() -> BenchResult:
    s, h, state0 = _problem()
    par = s.params(h)
    out = np.zeros((N_STEPS // 100, 3))

    def ours() -> int:
        state = state0.copy()
        status, _, _, _ = dy.newmark_kernel(
            N_STEPS, 100, 0.0, state, par, s.theta0, s.harmonics, s.ndof, dy.MAX_ITER, out
        )
        if status != dy.OK:
            raise AssertionError(f"kernel status {status}")
        return int(status)

    ours_s = best_time(ours, repeat=3)

    # accuracy on the window: Newmark (default step) and LSODA against a tight DOP853
    y0 = np.concatenate([state0[:2], state0[3:5]])
    rhs = dy.rhs_first_order(s)
    n_win = round(WINDOW / h)
    t_eval = h * np.arange(1, n_win + 1)
    ref = (
        solve_ivp(
            rhs, (0.0, t_eval[-1]), y0, method="DOP853", rtol=1e-12, atol=1e-22, t_eval=t_eval
        )
        .y[:2]
        .T
    )
    win = np.zeros((n_win, 3))
    st = state0.copy()
    dy.newmark_kernel(n_win, 1, 0.0, st, par, s.theta0, s.harmonics, s.ndof, dy.MAX_ITER, win)
    err_newmark = float(np.max(np.abs(win[:, :2] - ref)))
    motion = float(np.ptp(ref, axis=0).max())
    lsoda_s = float("inf")
    chosen = None
    for rtol in (1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10):
        t0 = time.perf_counter()
        sol = solve_ivp(
            rhs,
            (0.0, t_eval[-1]),
            y0,
            method="LSODA",
            rtol=rtol,
            atol=1e-6 * rtol * motion,
            t_eval=t_eval,
        )
        elapsed = time.perf_counter() - t0
        err = float(np.max(np.abs(sol.y[:2].T - ref)))
        if sol.success and err <= err_newmark:
            lsoda_s, chosen = elapsed, rtol
            break
    scale = N_STEPS * h / t_eval[-1]
    reference_s = lsoda_s * scale
    return BenchResult(
        name=f"dynamic Newmark 1e6 steps Z=9 (err {err_newmark / motion:.1e} of p-p)",
        ours_s=ours_s,
        reference_s=reference_s,
        reference=f"solve_ivp LSODA rtol {chosen:g} (20 ms, scaled x{scale:.0f})",
        target="< 1 s after compilation and >= 20x faster at equal accuracy",
        met=ours_s < 1.0 and reference_s / ours_s >= 20.0,
    )
