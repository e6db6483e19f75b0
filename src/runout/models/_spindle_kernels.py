r"""Compiled Newton solve of the spindle's balance (see :mod:`runout.models.spindle`).

Every ball of every bearing is one row of the arrays: its approach at zero displacement
:math:`c_j` and :math:`\cos\theta_j, \sin\theta_j` per instant, and its constant geometry
(:math:`\cos\alpha`, :math:`s\sin\alpha`, axial position p, pitch radius R, K_n, and whether
its outer ring floats on the preload spring). The approach is
:math:`\delta_j = c_j + g_j\cdot q` with the generalised normal :math:`g_j` of
:func:`normal`; the solve minimises the convex potential
:math:`\Pi(q) = \sum_j \tfrac{K_j}{2.5}[\delta_j]_+^{5/2} - F\cdot q` by Newton's method with a
Cholesky solve of the m × m Hessian (m = 5, or 6 with the spring-preloaded ring), Armijo
backtracking and the warm start of :func:`runout.models._quasi_static.predict`.
"""

from __future__ import annotations

import math

import numpy as np
from numba.extending import register_jitable
from numpy.typing import NDArray

from runout.analysis.results import SOLVER_RTOL
from runout.base._kernel import kernel
from runout.models._quasi_static import predict

F64 = NDArray[np.float64]

__all__ = [
    "NOT_CONVERGED",
    "OK",
    "SINGULAR",
    "TOO_FEW_LOADED",
    "cholesky_solve",
    "scratch_for",
    "solve_chunk",
]

OK, TOO_FEW_LOADED, SINGULAR, NOT_CONVERGED = 0, 1, 2, 3
#: Step tolerance relative to the reference approach (as seed 000's kernel).
RTOL = SOLVER_RTOL["spindle"]
#: Residual round-off floor relative to the sum of the load magnitudes (64 ulp).
_FLOOR = 64.0 * 2.0**-52
#: Largest number of generalised coordinates (x, y, z, θx, θy and the spring-loaded ring).
MAX_DOF = 6


# register_jitable: compiled into its caller, without Python and C entry points of its own
# (first-run compilation time); a helper that several compiled functions of one run call
# stays njit (compiled once, not once per caller).
@register_jitable(no_cfunc_wrapper=True)
def normal(
    cth: float,
    sth: float,
    ca: float,
    ssa: float,
    p: float,
    r: float,
    floating: bool,
    g: NDArray[np.float64],
) -> None:
    r"""Generalised normal :math:`g = \partial\delta/\partial q` of one ball (compiled).

    With :math:`u(r) = u_0 + \vartheta\times r` of the ball centre
    :math:`r = (R\cos\theta, R\sin\theta, p)` and the contact normal
    :math:`n = (\cos\alpha\cos\theta, \cos\alpha\sin\theta, s\sin\alpha)`:
    :math:`g = (n_x, n_y, n_z, -n_x\cdot 0 - p\,n_y + R\sin\theta\,n_z,\; p\,n_x - R\cos\theta\,
    n_z)` and, for a ball of the spring-loaded ring, :math:`g_5 = -n_z` (its outer ring's axial
    slide w enters as z - w).
    """
    nx = ca * cth
    ny = ca * sth
    g[0] = nx
    g[1] = ny
    g[2] = ssa
    g[3] = -p * ny + r * sth * ssa
    g[4] = p * nx - r * cth * ssa
    if g.size > 5:
        g[5] = -ssa if floating else 0.0


@register_jitable(no_cfunc_wrapper=True)
def cholesky_solve(h: F64, rhs: F64, out: F64, work: F64) -> bool:
    """Solve the symmetric positive definite system h s = rhs into ``out`` (compiled).

    ``work`` (m × m) receives the Cholesky factor; ``h`` is left unchanged. False when a pivot
    is not positive (h not positive definite, or NaN).
    """
    m = rhs.size
    for i in range(m):
        for j in range(i + 1):
            s = h[i, j]
            for k in range(j):
                s -= work[i, k] * work[j, k]
            if i == j:
                if not s > 0.0:
                    return False
                work[i, i] = math.sqrt(s)
            else:
                work[i, j] = s / work[j, j]
    for i in range(m):
        s = rhs[i]
        for k in range(i):
            s -= work[i, k] * out[k]
        out[i] = s / work[i, i]
    for i in range(m - 1, -1, -1):
        s = out[i]
        for k in range(i + 1, m):
            s -= work[k, i] * out[k]
        out[i] = s / work[i, i]
    return True


@register_jitable(no_cfunc_wrapper=True)
def _potential(c: F64, gn: F64, k: F64, force: F64, q: F64) -> float:
    """Π(q) of the balls with generalised normals ``gn`` (N, m) and stiffnesses ``k``."""
    m = q.size
    e = 0.0
    for a in range(m):
        e -= force[a] * q[a]
    for j in range(c.size):
        d = c[j]
        for a in range(m):
            d += gn[j, a] * q[a]
        if d > 0.0:
            e += k[j] / 2.5 * d * d * math.sqrt(d)
    return e


# inlined into its one caller, solve_chunk: compiled on its own it would also build the Python
# and C entry points of its fourteen array arguments (first-run compilation time)
@kernel(inline="always")
def newton(
    c: NDArray[np.float64],
    cth: NDArray[np.float64],
    sth: NDArray[np.float64],
    geo: NDArray[np.float64],
    floating: NDArray[np.bool_],
    force: NDArray[np.float64],
    reg: NDArray[np.float64],
    scale: NDArray[np.float64],
    q: NDArray[np.float64],
    d_ref: float,
    max_iter: int,
    h: NDArray[np.float64],
    work: NDArray[np.float64],
    vec: NDArray[np.float64],
    gn: NDArray[np.float64],
) -> tuple[int, int]:
    """Newton solve of the spindle balance at one instant, from ``q`` (updated in place).

    Parameters
    ----------
    c, cth, sth : ndarray, shape (N,)
        Approach at q = 0 [m], cos θ_j, sin θ_j of every ball.
    geo : ndarray, shape (5, N)
        cos α, s sin α, p [m], R [m], K_n [N/m^1.5] per ball.
    floating : ndarray of bool, shape (N,)
        Balls of the spring-loaded ring(s).
    force : ndarray, shape (m,)
        Generalised load (F_x, F_y, F_z [N], M_x, M_y [N m], spring force [N]).
    reg : ndarray, shape (m,)
        Regularisation added to the Hessian's diagonal (keeps iterates moving).
    scale : ndarray, shape (m,)
        Length per unit of each coordinate [m] (1 for translations, a lever for tilts).
    q : ndarray, shape (m,)
        Start, overwritten with the solution.
    d_ref : float
        Reference approach [m] (step tolerance RTOL·d_ref).
    max_iter : int
    h, work : ndarray, shape (m, m)
        Work arrays; ``h`` holds the unregularised Hessian of the solution on return.
    vec : ndarray, shape (4, m)
        Work array (no allocation per instant; rows 1 to 3).
    gn : ndarray, shape (N, m)
        Work array: the generalised normals of the balls at this instant.

    Returns
    -------
    unloaded : int
        Balls without load.
    status : int
        0 ok, 1 too few loaded balls, 2 singular, 3 not converged.
    """
    n = c.size
    m = q.size
    # the normals do not depend on q: once per instant, not at every iteration and trial
    for j in range(n):
        normal(cth[j], sth[j], geo[0, j], geo[1, j], geo[2, j], geo[3, j], floating[j], gn[j])
    k = geo[4]
    r = vec[1]
    s = vec[2]
    trial = vec[3]
    tol = RTOL * d_ref
    converged = False
    balanced = False  # residual at its round-off floor: h and loaded are those of q
    loaded = 0
    for _ in range(max_iter):
        for a in range(m):
            r[a] = -force[a]
            for b in range(m):
                h[a, b] = 0.0
        load_sum = 0.0
        for a in range(m):
            load_sum += abs(force[a]) / scale[a]
        loaded = 0
        for j in range(n):  # (indexed, not a row view: a view per ball costs reference counts)
            d = c[j]
            for a in range(m):
                d += gn[j, a] * q[a]
            if d > 0.0:
                sd = math.sqrt(d)
                qj = k[j] * d * sd
                load_sum += qj
                kk = 1.5 * k[j] * sd
                for a in range(m):
                    r[a] += qj * gn[j, a]
                    ga = kk * gn[j, a]
                    for b in range(a + 1):
                        h[a, b] += ga * gn[j, b]
                loaded += 1
        for a in range(m):
            for b in range(a):
                h[b, a] = h[a, b]
        worst = 0.0
        for a in range(m):
            worst = max(worst, abs(r[a]) / scale[a])
        if worst <= _FLOOR * load_sum:
            converged = balanced = True
            break
        for a in range(m):
            h[a, a] += reg[a]
        ok = cholesky_solve(h, r, s, work)
        for a in range(m):
            h[a, a] -= reg[a]
        if not ok:
            return 0, SINGULAR
        # the step is -s: the gradient of the potential is r
        big = False
        slope = 0.0
        step_len = 0.0
        for a in range(m):
            slope -= r[a] * s[a]
            step_len = max(step_len, abs(s[a]) * scale[a])
        big = step_len > 1e-4 * d_ref
        step = 1.0
        if big:
            e0 = _potential(c, gn, k, force, q)
            for _ls in range(40):
                for a in range(m):
                    trial[a] = q[a] - step * s[a]
                e1 = _potential(c, gn, k, force, trial)
                if e1 <= e0 + 1e-4 * step * slope or step * step_len < tol:
                    break
                step *= 0.5
        for a in range(m):
            q[a] -= step * s[a]
        if step * step_len <= tol:
            converged = True
            break
    if not balanced:  # the stiffness and contacts of the last step's q
        loaded = 0
        for a in range(m):
            for b in range(m):
                h[a, b] = 0.0
        for j in range(n):
            d = c[j]
            for a in range(m):
                d += gn[j, a] * q[a]
            if d <= 0.0:
                continue
            loaded += 1
            kk = 1.5 * k[j] * math.sqrt(d)
            for a in range(m):
                for b in range(m):
                    h[a, b] += kk * gn[j, a] * gn[j, b]
    # one call, with run-time arguments: literal ones (a constant True, a counter's first 0)
    # would each compile a specialisation of their own
    return _final(h, work, r, s, n - loaded, converged)


@kernel(inline="always")  # one caller, newton (see there)
def _final(h: F64, work: F64, r: F64, s: F64, unloaded: int, converged: bool) -> tuple[int, int]:
    """Status of a solve whose unregularised stiffness is ``h`` (compiled).

    The loaded balls must hold every coordinate: the stiffness scaled to a unit diagonal
    stays positive definite with 1e-10 taken off its diagonal.
    """
    m = r.size
    for a in range(m):
        for b in range(m):
            work[a, b] = h[a, b] / math.sqrt(max(h[a, a] * h[b, b], 1e-300))
    for a in range(m):
        work[a, a] -= 1e-10
    if not cholesky_solve(work, r, s, work):
        return unloaded, TOO_FEW_LOADED
    if not converged:
        return unloaded, NOT_CONVERGED
    return unloaded, OK


def scratch_for(n_balls: int, m: int) -> tuple[F64, F64, F64, F64]:
    """The work arrays of :func:`solve_chunk` for ``n_balls`` balls and m coordinates."""
    return np.empty((m, m)), np.empty((m, m)), np.empty((4, m)), np.empty((n_balls, m))


@kernel(nogil=True)
def solve_chunk(
    c: NDArray[np.float64],
    cth: NDArray[np.float64],
    sth: NDArray[np.float64],
    geo: NDArray[np.float64],
    floating: NDArray[np.bool_],
    force: NDArray[np.float64],
    reg: NDArray[np.float64],
    scale: NDArray[np.float64],
    history: NDArray[np.float64],
    smooth_in: int,
    d_ref: float,
    max_iter: int,
    q_out: NDArray[np.float64],
    unloaded: NDArray[np.int64],
    scratch: tuple[F64, F64, F64, F64],
) -> tuple[int, int, int]:
    """The balance at every instant of a chunk, warm-started (compiled).

    Parameters
    ----------
    c, cth, sth : ndarray, shape (n, N)
        Per instant and ball, as :func:`newton`.
    geo, floating, force, reg, scale, d_ref, max_iter
        As :func:`newton`.
    history : ndarray, shape (3, m)
        The last three solutions before the chunk (row 0 the last), updated in place.
    smooth_in : int
        How many of them lie on a smooth stretch (:func:`runout.models._quasi_static.predict`).
    q_out : ndarray, shape (n, m)
        Filled with the solutions.
    unloaded : ndarray, shape (n,)
        Filled with the balls without load.
    scratch : tuple of ndarray
        Work arrays of shapes (m, m), (m, m), (4, m) and (N, m) (:func:`scratch_for`): from
        the caller, so that the kernel allocates nothing (nothing to compile for it).

    Returns
    -------
    status, instant, smooth : int
        Status (0 ok), the failing instant of the chunk (-1) and the smooth count to carry.
    """
    n = c.shape[0]
    m = force.size
    h = scratch[0]
    work = scratch[1]
    vec = scratch[2]
    gn = scratch[3]
    q = vec[0]  # newton's own work is rows 1 to 3
    smooth = smooth_in
    for i in range(n):
        status = OK
        count = 0
        for attempt in range(2):  # from the extrapolation, then from the last solution
            order = smooth if attempt == 0 else 1
            for a in range(m):
                q[a] = predict(order, history[0, a], history[1, a], history[2, a])
            count, status = newton(
                c[i],
                cth[i],
                sth[i],
                geo,
                floating,
                force,
                reg,
                scale,
                q,
                d_ref,
                max_iter,
                h,
                work,
                vec,
                gn,
            )
            if status == OK or order < 2:
                break
        if status != OK:
            return status, i, smooth
        smooth = min(smooth + 1, 3) if count == 0 else 0
        for a in range(m):
            history[2, a] = history[1, a]
            history[1, a] = history[0, a]
            history[0, a] = q[a]
            q_out[i, a] = q[a]
        unloaded[i] = count
    return OK, -1, smooth
