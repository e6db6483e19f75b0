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
* Hand kernel (:func:`hand_newmark`): the same problem written here from seed 003 alone, as
  one would write it for this bearing: eq. 2.4-2.5 (no preload, so the contact normals are
  the radial directions), eq. 2.16 with the load W and the unbalance, eq. 2.18 for
  the ball angles, average-acceleration Newmark-β with Newton-Raphson on a closed-form 2x2
  solve (§3), the ball angles and the unbalance phase advanced as rotating phasors. It only
  takes the problem's numbers (mass, damping, K_n, play, rates) from the set-up, and its
  record must agree with ours. Target: ours within 1.3x of its time.
"""

from __future__ import annotations

import math
import time
from pathlib import Path

import numba
import numpy as np
from scipy.integrate import solve_ivp

from _harness import BenchResult, best_time
from runout.case.model import load_case
from runout.models import dynamic as dy

CASE = Path(__file__).resolve().parents[1] / "examples" / "seed003_purohit_clearance.toml"
N_STEPS = 1_000_000
WINDOW = 0.02
HAND_ANCHOR = 1000  # steps between exact recomputations of the hand kernel's phasors


@numba.njit(cache=True)
def hand_newmark(n_steps, stride, h, m, c, kn, gamma, theta0, wc, wx, wy, fu, omega, y0, tol, out):  # type: ignore[no-untyped-def]
    """Seed 003 eq. 2.16 by Newmark-β (β = 1/4, γ = 1/2) + Newton-Raphson, phasor angles.

    ``y0`` = (x, y, vx, vy, ax, ay) at t = 0; the load W = (wx, wy). Records (x, y) every
    ``stride`` steps into ``out``; returns the Newton iterations taken.
    """
    z = theta0.size
    cz = np.cos(theta0)
    sz = np.sin(theta0)
    rc_c, rc_s = math.cos(wc * h), math.sin(wc * h)
    ru_c, ru_s = math.cos(omega * h), math.sin(omega * h)
    x, y, vx, vy, ax, ay = y0[0], y0[1], y0[2], y0[3], y0[4], y0[5]
    a0 = 4.0 / (h * h)
    a1 = 4.0 / h
    diag = m * a0 + 2.0 * c / h
    ec = es = uc = us = 0.0
    cj = np.empty(z)
    sj = np.empty(z)
    iters = 0
    for n in range(n_steps):
        if n % HAND_ANCHOR == 0:
            t = (n + 1) * h
            ec, es = math.cos(wc * t), math.sin(wc * t)
            uc, us = math.cos(omega * t), math.sin(omega * t)
        else:
            ec, es = ec * rc_c - es * rc_s, ec * rc_s + es * rc_c
            uc, us = uc * ru_c - us * ru_s, uc * ru_s + us * ru_c
        for j in range(z):
            cj[j] = cz[j] * ec - sz[j] * es
            sj[j] = sz[j] * ec + cz[j] * es
        px = wx + fu * uc
        py = wy + fu * us
        xn = x + h * vx + 0.5 * h * h * ax
        yn = y + h * vy + 0.5 * h * h * ay
        for _ in range(50):
            iters += 1
            fx = fy = kxx = kxy = kyy = 0.0
            for j in range(z):
                d = xn * cj[j] + yn * sj[j] - gamma
                if d > 0.0:
                    r = math.sqrt(d)
                    f = kn * d * r
                    k = 1.5 * kn * r
                    fx += f * cj[j]
                    fy += f * sj[j]
                    kxx += k * cj[j] * cj[j]
                    kxy += k * cj[j] * sj[j]
                    kyy += k * sj[j] * sj[j]
            anx = a0 * (xn - x) - a1 * vx - ax
            any_ = a0 * (yn - y) - a1 * vy - ay
            rx = m * anx + c * (vx + 0.5 * h * (ax + anx)) + fx - px
            ry = m * any_ + c * (vy + 0.5 * h * (ay + any_)) + fy - py
            jxx = diag + kxx
            jyy = diag + kyy
            det = jxx * jyy - kxy * kxy
            dx = (jyy * rx - kxy * ry) / det
            dy = (jxx * ry - kxy * rx) / det
            xn -= dx
            yn -= dy
            if max(abs(dx), abs(dy)) <= tol:
                break
        anx = a0 * (xn - x) - a1 * vx - ax
        any_ = a0 * (yn - y) - a1 * vy - ay
        vx += 0.5 * h * (ax + anx)
        vy += 0.5 * h * (ay + any_)
        ax, ay = anx, any_
        x, y = xn, yn
        if (n + 1) % stride == 0:
            out[(n + 1) // stride - 1, 0] = x
            out[(n + 1) // stride - 1, 1] = y
    return iters


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
        met=bool(ours_s < 1.0 and reference_s / ours_s >= 20.0),
    )


def bench_dynamic_newmark_vs_hand_kernel() -> BenchResult:
    """10^6 steps: our kernel against the phasor hand kernel of seed 003 (same records)."""
    s, h, state0 = _problem()
    if not (s.ndof == 2 and s.axial_offset == 0.0 and s.harmonics[0].size == 0):
        raise AssertionError("the hand kernel is written for a perfect bearing without preload")
    par = s.params(h)
    out = np.zeros((N_STEPS // 100, 3))
    hand_out = np.zeros((N_STEPS // 100, 2))
    y0 = np.array([state0[0], state0[1], state0[3], state0[4], state0[6], state0[7]])
    args = (
        h, s.mass, s.damping, s.stiffness, -s.radial_gap, s.theta0, par[dy.P_WC],
        s.force[0], s.force[1], s.unbalance_force, s.unbalance_omega, y0, par[dy.P_TOL],
        hand_out,
    )  # fmt: skip

    def ours() -> None:
        status, _, _, _ = dy.newmark_kernel(
            N_STEPS, 100, 0.0, state0.copy(), par, s.theta0, s.harmonics, s.ndof, dy.MAX_ITER,
            out,
        )  # fmt: skip
        if status != dy.OK:
            raise AssertionError(f"kernel status {status}")

    def hand() -> None:
        hand_newmark(N_STEPS, 100, *args)

    # interleaved best-of: both see the same load of the shared machine
    ours_s = hand_s = float("inf")
    for _ in range(3):
        ours_s = min(ours_s, best_time(ours, repeat=2))
        hand_s = min(hand_s, best_time(hand, repeat=2))
    motion = float(np.ptp(out[:, :2], axis=0).max())
    diff = float(np.max(np.abs(out[:, :2] - hand_out))) / motion
    return BenchResult(
        name=f"dynamic 1e6 steps Z=9 vs hand kernel (records agree to {diff:.0e} of p-p)",
        ours_s=ours_s,
        reference_s=hand_s,
        reference="seed 003 phasor hand kernel",
        target="within 1.3x of the hand kernel's time, records agree to 1e-9 of p-p",
        met=bool(ours_s <= 1.3 * hand_s and diff < 1e-9),
    )
