r"""Batched kernels of the studies: many bearings of the 2-D quasi-static model at once.

A Monte Carlo over ball sizes changes only the constant part of each ball's approach; the ball
angles, hence :math:`\cos\theta_k` and :math:`\sin\theta_k`, are the same for every bearing of
the batch. :func:`solve_batch` therefore evaluates the trigonometry once and runs the Newton
iteration of seed 001 eq. 16-18 (the one of :func:`runout.models.quasi_static_2d.solve_kernel`:
closed-form 2×2 solve, Armijo backtracking on the convex potential for large steps, warm start
from the previous instant) for every bearing, in parallel over bearings. Each bearing starts
from the centre at its first instant, so its result does not depend on the batch it is in.
One pass over the balls (:func:`_contacts`) gives the force, the stiffness and the energy of
the line search at a point, and the accepted trial point of the search is where the next
Newton iteration starts: three passes per instant instead of six, with the same numbers to
the bit. The kernels release the GIL, so threads of one process (a Dask worker, a thread
pool) run them side by side.

:func:`solve_batch_reference` is the NumPy version used in the tests.
"""

from __future__ import annotations

import math

import numba
import numpy as np
from numpy.typing import NDArray

from runout.base._kernel import kernel
from runout.models.quasi_static_2d import FLOOR

__all__ = ["project_rows", "solve_batch", "solve_batch_reference"]

#: Relative step tolerance of the Newton iteration (same as the per-bearing model).
RTOL = 1e-11
#: A full Newton step below QUAD·δ_0 ends the iteration: quadratic convergence leaves an error
#: of order QUAD²·δ_0 = 1e-12·δ_0 < RTOL·δ_0, one force evaluation earlier.
QUAD = 1e-6


@kernel(nogil=True)
def _contacts(ci, cth, sth, k, q0, q1):  # pragma: no cover - compiled
    """Force, stiffness, total load and Hertz energy of the balls at shaft centre (q0, q1).

    One pass over the balls for what the Newton iteration needs at a point: the force and
    stiffness of eq. 16-17 and the energy its line search descends (the terms and their order
    are those of :func:`runout.models.quasi_static_2d.hertz_potential` with no external force,
    so the values are the same bits). The line search's trial point is where the next
    iteration starts when the full step is taken, so one evaluation serves both.
    """
    f0 = 0.0
    f1 = 0.0
    h00 = 0.0
    h01 = 0.0
    h11 = 0.0
    load_sum = 0.0
    e = -(0.0 * q0 + 0.0 * q1)
    for j in range(ci.size):
        d = 2.0 * ci[j] + q0 * cth[j] + q1 * sth[j]
        if d > 0.0:
            sd = math.sqrt(d)
            p = k * d * sd
            load_sum += p
            kk = 1.5 * k * sd
            f0 += p * cth[j]
            f1 += p * sth[j]
            h00 += kk * cth[j] * cth[j]
            h01 += kk * cth[j] * sth[j]
            h11 += kk * sth[j] * sth[j]
            e += k / 2.5 * d * d * sd
    return f0, f1, h00, h01, h11, load_sum, e


@kernel(nogil=True)
def _solve_one(c_base, offset, cth, sth, k, d_ref, max_iter, q_out, unloaded):  # pragma: no cover
    n, z = c_base.shape
    tol = RTOL * d_ref
    quad = QUAD * d_ref
    reg = 1e-9 * 1.5 * k * math.sqrt(2.0 * d_ref)
    ci = np.empty(z)
    q0 = 0.0
    q1 = 0.0
    for i in range(n):
        for j in range(z):
            ci[j] = c_base[i, j] + offset[j]
        cth_i = cth[i]
        sth_i = sth[i]
        converged = False
        # the evaluation at (q0, q1) is already known (the accepted trial point of the search)
        known = False
        f0 = f1 = h00 = h01 = h11 = load_sum = e0 = 0.0
        for _ in range(max_iter):
            if not known:
                f0, f1, h00, h01, h11, load_sum, e0 = _contacts(ci, cth_i, sth_i, k, q0, q1)
            known = False
            if max(abs(f0), abs(f1)) <= FLOOR * load_sum:  # round-off floor (2-D model)
                converged = True
                break
            h00 += reg
            h11 += reg
            det = h00 * h11 - h01 * h01
            if not det > 0.0:
                return 2, i
            s0 = -(h11 * f0 - h01 * f1) / det
            s1 = -(h00 * f1 - h01 * f0) / det
            slope = f0 * s0 + f1 * s1
            step = 1.0
            big = max(abs(s0), abs(s1)) > 1e-4 * d_ref
            if big:
                for _ls in range(40):
                    t0 = q0 + step * s0
                    t1 = q1 + step * s1
                    g0, g1, k00, k01, k11, g_sum, e1 = _contacts(ci, cth_i, sth_i, k, t0, t1)
                    if e1 <= e0 + 1e-4 * step * slope or step * max(abs(s0), abs(s1)) < tol:
                        # q0 + step * s0 below is t0 exactly: keep this evaluation
                        known = True
                        f0, f1, h00, h01, h11, load_sum, e0 = g0, g1, k00, k01, k11, g_sum, e1
                        break
                    step *= 0.5
            q0 += step * s0
            q1 += step * s1
            # A full Newton step of size e leaves an error of order e^2 / d_ref (the Hertz
            # stiffness varies on the scale d_ref): below QUAD * d_ref it is under tol.
            if step * max(abs(s0), abs(s1)) <= (tol if step < 1.0 else quad):
                converged = True
                break
        # balls without load and the collinear test (loaded_balls_collinear), in one pass
        count = 0
        g00 = 0.0
        g01 = 0.0
        g11 = 0.0
        for j in range(z):
            d = 2.0 * ci[j] + q0 * cth_i[j] + q1 * sth_i[j]
            if d > 0.0:
                sd = math.sqrt(d)
                g00 += sd * cth_i[j] * cth_i[j]
                g01 += sd * cth_i[j] * sth_i[j]
                g11 += sd * sth_i[j] * sth_i[j]
            elif d <= 0.0:
                count += 1
        if z - count < 2:
            return 1, i
        tr = g00 + g11
        if g00 * g11 - g01 * g01 <= 1e-12 * tr * tr:
            return 2, i
        if not converged:
            return 3, i
        q_out[i, 0] = q0
        q_out[i, 1] = q1
        unloaded[i] = count
    return 0, -1


@kernel(nogil=True, parallel=True)
def _solve_batch_parallel(
    c_base, offsets, cth, sth, k, d_ref, max_iter, q, unloaded, status, instant
):  # pragma: no cover
    for m in numba.prange(offsets.shape[0]):
        s, i = _solve_one(c_base, offsets[m], cth, sth, k, d_ref, max_iter, q[m], unloaded[m])
        status[m] = s
        instant[m] = i


@kernel(nogil=True)
def _solve_batch_serial(
    c_base, offsets, cth, sth, k, d_ref, max_iter, q, unloaded, status, instant
):  # pragma: no cover
    for m in range(offsets.shape[0]):
        s, i = _solve_one(c_base, offsets[m], cth, sth, k, d_ref, max_iter, q[m], unloaded[m])
        status[m] = s
        instant[m] = i


def solve_batch(
    c_base: NDArray[np.float64],
    offsets: NDArray[np.float64],
    theta: NDArray[np.float64],
    stiffness: float,
    d_ref: float,
    max_iter: int = 60,
    parallel: bool = True,
) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64], NDArray[np.int64]]:
    r"""Shaft centre of B bearings that differ only by a constant per ball (seed 001 eq. 16-18).

    Ball k of bearing m is compressed by :math:`2\delta_k = 2(c_{ik} + o_{mk}) + x\cos\theta_{ik}
    + y\sin\theta_{ik}` (eq. 10 written for the total approach) and carries
    :math:`P = K_n (2\delta_k)^{3/2}` (eq. 14); the shaft sits where the loads balance (eq.
    16-17).

    Parameters
    ----------
    c_base : ndarray, shape (n, Z)
        Approach δ_k at x = y = 0 shared by all bearings [m] (preload and common deviations).
    offsets : ndarray, shape (B, Z)
        Per-bearing constant added to δ_k [m]; half the ball's diameter error.
    theta : ndarray, shape (n, Z)
        Ball angles [rad], shared.
    stiffness : float
        K_n [N/m^1.5].
    d_ref : float
        Reference approach δ_0 [m] (tolerance RTOL·d_ref).
    max_iter : int
        Newton iterations per instant.
    parallel : bool
        Threads over bearings (Numba ``prange``). Use False inside worker threads or
        processes: Numba's default threading layer must not be entered from two threads.

    Returns
    -------
    q : ndarray, shape (B, n, 2)
        Shaft centre [m].
    unloaded : ndarray, shape (B, n)
        Balls without load.
    status : ndarray, shape (B,)
        0 ok, 1 too few loaded balls, 2 singular, 3 not converged.
    instant : ndarray, shape (B,)
        Instant of the failure (-1 when ok).
    """
    c = np.ascontiguousarray(c_base, dtype=np.float64)
    o = np.ascontiguousarray(offsets, dtype=np.float64)
    th = np.asarray(theta, dtype=np.float64)
    cth = np.ascontiguousarray(np.cos(th))
    sth = np.ascontiguousarray(np.sin(th))
    solve = _solve_batch_parallel if parallel else _solve_batch_serial
    # the outputs are allocated here: compiled, their allocation would only cost compilation
    b, n = o.shape[0], c.shape[0]
    q = np.zeros((b, n, 2))
    unloaded = np.zeros((b, n), dtype=np.int64)
    status = np.zeros(b, dtype=np.int64)
    instant = np.full(b, -1, dtype=np.int64)
    solve(
        c, o, cth, sth, float(stiffness), float(d_ref), int(max_iter), q, unloaded, status, instant
    )
    return q, unloaded, status, instant


def solve_batch_reference(
    c_base: NDArray[np.float64],
    offsets: NDArray[np.float64],
    theta: NDArray[np.float64],
    stiffness: float,
    d_ref: float,
    max_iter: int = 60,
) -> NDArray[np.float64]:
    """Vectorised NumPy Newton solve of the same equations (reference for tests).

    Plain Newton with step halving on the force norm, every bearing and instant at once.

    Returns
    -------
    ndarray, shape (B, n, 2)
        Shaft centre [m].
    """
    c = c_base[None, :, :] + offsets[:, None, :]  # (B, n, Z)
    nvec = np.stack([np.cos(theta), np.sin(theta)], axis=-1)  # (n, Z, 2)
    q = np.zeros((*c.shape[:2], 2))

    def force(qq: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        d = np.maximum(2.0 * c + np.einsum("nzk,bnk->bnz", nvec, qq), 0.0)
        return stiffness * np.einsum("bnz,nzk->bnk", d**1.5, nvec), d

    tol = RTOL * d_ref
    for _ in range(max_iter):
        f, d = force(q)
        h = 1.5 * stiffness * np.einsum("bnz,nzk,nzl->bnkl", np.sqrt(d), nvec, nvec)
        s = -np.linalg.solve(h, f[..., None])[..., 0]
        step = np.ones(q.shape[:2])
        norm0 = np.linalg.norm(f, axis=-1)
        for _ls in range(30):
            f1, _ = force(q + step[..., None] * s)
            worse = np.linalg.norm(f1, axis=-1) > norm0 * (1.0 + 1e-12)
            if not worse.any():
                break
            step[worse] *= 0.5
        q = q + step[..., None] * s
        if np.max(np.abs(step[..., None] * s)) <= tol:
            return q
    raise ArithmeticError("reference Newton iteration did not converge")


@kernel(nogil=True)
def _project_rows(x, p):  # pragma: no cover - compiled
    r, n = x.shape
    k = p.shape[0]
    out = np.zeros((r, k))
    for i in range(r):
        for j in range(k):
            acc = 0.0
            for m in range(n):
                acc += p[j, m] * x[i, m]
            out[i, j] = acc
    return out


def project_rows(x: NDArray[np.float64], p: NDArray[np.float64]) -> NDArray[np.float64]:
    """``x @ p.T`` row by row in a fixed order (results independent of the batch size).

    A BLAS product may sum in an order that depends on the matrix shape; a study's numbers
    must not depend on how its samples are chunked.

    Parameters
    ----------
    x : ndarray, shape (R, n)
        Records.
    p : ndarray, shape (K, n)
        Projector.

    Returns
    -------
    ndarray, shape (R, K)
    """
    return _project_rows(
        np.ascontiguousarray(x, dtype=np.float64), np.ascontiguousarray(p, dtype=np.float64)
    )
