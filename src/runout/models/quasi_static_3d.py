r"""Three-dimensional quasi-static NRRO model with a fixed contact angle (seed 000, Tada).

The inner ring's geometric centre is fixed; the outer ring's centre :math:`(x, y, z)` settles,
at every instant, where the Hertz forces of the Z balls balance the constant axial preload
:math:`F_a` (and a radial load, if any). The contact angle α stays at its preloaded value
(:func:`runout.report.summary.operating_contact_angle`); the balls move with the cage, spin at
:math:`f_b` relative to it and carry the raceway and ball wavinesses, size and pitch errors
with them (seed 000 §2.1).

Elastic approach of ball j (seed 000 eq. 2 and the bracket of eq. 5):

.. math::
    \delta_j = (W_{ij} - W_{oj})\cos\alpha + W_{bj} + \delta_{pl}
               - (x\cos\theta_j + y\sin\theta_j)\cos\alpha - z\sin\alpha,

with

* :math:`W_{ij}` the inner-raceway radius deviation at ball j, positive when material is added
  (a bump pushes the ball outward: more compression);
* :math:`W_{oj}` the outer-raceway radius deviation, positive when the radius grows (material
  removed: less compression; an inward bump, :math:`W_{oj} < 0`, compresses more);
* :math:`W_{bj}` the diameter deviation of ball j along its contact line (seed 002 eq. 26),
  size error included;
* :math:`\delta_{pl}` the preload approach, :math:`K_n Z \delta_{pl}^{3/2}\sin\alpha = F_a`;
* x, y, z the outer ring's centre relative to the inner ring's; +z opens the contacts.

Load :math:`Q_j = K_n[\delta_j]_+^{3/2}` (eq. 3, K_n of eq. 4 from
:func:`runout.geometry.contact.ball_race_contacts`); a ball with :math:`\delta_j \le 0` carries
none. The balance (eq. 5), with the unit contact normal :math:`n_j = (\cos\alpha\cos\theta_j,
\cos\alpha\sin\theta_j, \sin\alpha)`, is

.. math:: \sum_j Q_j\,n_j = (-F_r\cos\beta,\; -F_r\sin\beta,\; F_a),

where the radial load :math:`F_r` acts on the shaft along β (``Operation.radial_load_direction``),
i.e. pushes the outer ring along -β relative to the inner ring; Tada's eq. 5 is the case
:math:`F_r = 0`.

Notes
-----
* Tada's eq. 1 (the waviness functions :math:`W_{ij}, W_{oj}, W_{bj}`) is missing from the
  extracted text. We derive them from the kinematics (see :mod:`runout.models._quasi_static`):
  :math:`W_{ij} = r_i(\theta_j - 2\pi f_{inner} t)`, :math:`W_{oj} = r_o(\theta_j - 2\pi
  f_{outer} t)`, :math:`W_{bj} = w_{bj}(2\pi f_b t)`, :math:`\theta_j = 2\pi f_c t + 2\pi j/Z +
  \epsilon_j`. Angles run counter-clockwise (Tada: clockwise), which mirrors the orbits only.
* Tada's text says the bracket of eq. 5 is raised to 1.5; a negative bracket is a lost contact
  and gives zero load here (counted and reported).
* The same equations hold for either rotating ring; only the ring speeds change. The kernel
  solves for the outer ring's centre relative to the inner ring's (Tada's frame); the reported
  displacement (:func:`solve`, ``runout run``) is the product's: the shaft (inner-ring) centre
  relative to the outer ring, :math:`-(x, y, z)`, so z grows along the axial load on the shaft;
  z is then counted from the rings axially centred (:func:`axial_position`).
* Solver: per instant, Newton's method on the convex potential
  :math:`\Pi(q) = \sum_j \tfrac{K_n}{2.5}[\delta_j]_+^{5/2} + F\cdot q` with a closed-form 3×3
  solve, Armijo backtracking, started from the previous solutions extrapolated
  (:func:`runout.models._quasi_static.predict`). :func:`solve` runs the fused kernel
  :func:`solve_fused`: the deviations :math:`W_{ij}, W_{oj}, W_{bj}` and the ball angles are
  evaluated inside it, instant by instant, by rotating phasors
  (:class:`runout.models._quasi_static.ContactSources`), so a run allocates its record and
  nothing of size (instants × balls); :func:`solve_kernel` is the same Newton solve on
  precomputed arrays (:func:`approaches`), :func:`solve_reference` a vectorised NumPy version
  for tests.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numba.extending import register_jitable
from numpy.typing import NDArray

from runout.analysis.results import SOLVER_RTOL, RunResult
from runout.base._kernel import kernel
from runout.base._linalg import solve_spd3
from runout.base.errors import ContactLossError, ConvergenceError, GeometryError, NumericalError
from runout.geometry.bearing import BallBearing, Operation
from runout.geometry.contact import ball_race_contacts
from runout.geometry.kinematics import ball_spin_frequency, cage_frequency
from runout.geometry.loading import operating_contact_angle
from runout.models._quasi_static import (
    ANCHOR,
    Kinematics,
    contact_advance,
    contact_anchor,
    contact_deviations,
    contact_sources,
    contact_state,
    contact_values,
    on_grid,
    predict,
    run_quasi_static,
    solve_in_halves,
    time_grid,
    time_step,
)

if TYPE_CHECKING:
    from runout.case.model import Case

__all__ = [
    "Setup",
    "linearised_displacement",
    "preload_approach",
    "run",
    "setup",
    "solve",
    "solve_fused",
    "solve_kernel",
    "solve_reference",
    "time_grid_of",
]

MODEL = "quasi_static_3d"
#: Kernel status codes.
OK, TOO_FEW_LOADED, SINGULAR, NOT_CONVERGED = 0, 1, 2, 3
#: Message per kernel status code (errors name the instant and this cause).
CAUSES = {
    TOO_FEW_LOADED: "fewer than 3 balls carry load: the outer ring cannot be held",
    SINGULAR: "singular stiffness matrix: the loaded balls cannot hold the outer ring",
    NOT_CONVERGED: "Newton iteration did not converge",
}
#: Step tolerance of Newton's method relative to the preload approach δ_pl.
RTOL = SOLVER_RTOL["quasi_static_3d"]
MAX_ITER = 60
#: Residual round-off floor relative to the sum of the load magnitudes (64 ulp).
_FLOOR = 64.0 * 2.0**-52


def preload_approach(
    stiffness: float, n_elements: int, contact_angle: float, axial: float
) -> float:
    r"""Elastic approach under the preload, :math:`K_n Z \delta_{pl}^{3/2}\sin\alpha = F_a` [m].

    Parameters
    ----------
    stiffness : float
        K_n [N/m^1.5] (seed 000 eq. 4).
    n_elements : int
        Z.
    contact_angle : float
        α [rad], > 0.
    axial : float
        F_a [N], > 0.

    Returns
    -------
    float
        δ_pl [m].

    Notes
    -----
    The balance of Tada, "Three-dimensional analysis of non-repeatable runout (NRRO) in ball
    bearings", Koyo Engineering Journal (2002) (seed 000), eq. 5, without deviations and
    radial load, with ``Q = K_n δ^(3/2)`` (eq. 3).
    """
    return float((axial / (stiffness * n_elements * math.sin(contact_angle))) ** (2.0 / 3.0))


# --------------------------------------------------------------------------------------------
# kernel
# --------------------------------------------------------------------------------------------
# register_jitable: compiled into its caller, without Python and C entry points of its own
# (first-run compilation time); a helper that several compiled functions of one run call
# stays njit (compiled once, not once per caller).
@register_jitable(no_cfunc_wrapper=True)
def _potential(
    c: NDArray[np.float64],
    cth: NDArray[np.float64],
    sth: NDArray[np.float64],
    ca: float,
    sa: float,
    k: float,
    f: NDArray[np.float64],
    q0: float,
    q1: float,
    q2: float,
) -> float:
    e: float = f[0] * q0 + f[1] * q1 + f[2] * q2
    for j in range(c.size):
        d = c[j] - (q0 * cth[j] + q1 * sth[j]) * ca - q2 * sa
        if d > 0.0:
            e += k / 2.5 * d * d * math.sqrt(d)
    return e


@register_jitable(no_cfunc_wrapper=True)
def _newton(
    ci: NDArray[np.float64],
    cth: NDArray[np.float64],
    sth: NDArray[np.float64],
    cos_a: float,
    sin_a: float,
    k: float,
    force: NDArray[np.float64],
    q0: float,
    q1: float,
    q2: float,
    d_ref: float,
    max_iter: int,
) -> tuple[float, float, float, int, int]:
    """Newton solve of seed 000 eq. 5 at one instant from (q0, q1, q2) (compiled).

    Returns
    -------
    q0, q1, q2 : float
        Outer-ring centre [m].
    unloaded : int
        Balls without load.
    status : int
        0 ok, 1 too few loaded balls, 2 singular, 3 not converged.
    """
    z = ci.size
    tol = RTOL * d_ref
    converged = False
    for _ in range(max_iter):
        # residual r = sum Q n - F and Hessian H = sum 1.5 K d^0.5 n n^T of the potential
        r0 = -force[0]
        r1 = -force[1]
        r2 = -force[2]
        h00 = h01 = h02 = h11 = h12 = h22 = 0.0
        load_sum = abs(force[0]) + abs(force[1]) + abs(force[2])
        for j in range(z):
            d = ci[j] - (q0 * cth[j] + q1 * sth[j]) * cos_a - q2 * sin_a
            if d > 0.0:
                sd = math.sqrt(d)
                qj = k * d * sd
                load_sum += qj
                kk = 1.5 * k * sd
                nx = cos_a * cth[j]
                ny = cos_a * sth[j]
                r0 += qj * nx
                r1 += qj * ny
                r2 += qj * sin_a
                h00 += kk * nx * nx
                h01 += kk * nx * ny
                h02 += kk * nx * sin_a
                h11 += kk * ny * ny
                h12 += kk * ny * sin_a
                h22 += kk * sin_a * sin_a
        # The residual is at its round-off floor: converged. A nearly unloaded ball makes the
        # stiffness nearly singular, and the steps then never fall below the tolerance.
        if max(abs(r0), abs(r1), abs(r2)) <= _FLOOR * load_sum:
            converged = True
            break
        # a small regularisation keeps intermediate iterates with few loaded balls moving
        # (three loaded balls at distinct angles always hold the ring: checked below)
        reg = 1e-9 * 1.5 * k * math.sqrt(d_ref)
        h00 += reg
        h11 += reg
        h22 += reg
        # closed-form 3x3 solve H s = r (gradient of the potential is -r)
        s0, s1, s2, ok = solve_spd3(h00, h01, h02, h11, h12, h22, r0, r1, r2)
        if not ok:
            return q0, q1, q2, 0, SINGULAR
        # Armijo backtracking on the convex potential
        slope = -(r0 * s0 + r1 * s1 + r2 * s2)
        step = 1.0
        big = max(abs(s0), abs(s1), abs(s2)) > 1e-4 * d_ref
        e0 = _potential(ci, cth, sth, cos_a, sin_a, k, force, q0, q1, q2) if big else 0.0
        for _ls in range(40 if big else 0):
            e1 = _potential(
                ci,
                cth,
                sth,
                cos_a,
                sin_a,
                k,
                force,
                q0 + step * s0,
                q1 + step * s1,
                q2 + step * s2,
            )
            if e1 <= e0 + 1e-4 * step * slope or step * max(abs(s0), abs(s1), abs(s2)) < tol:
                break
            step *= 0.5
        q0 += step * s0
        q1 += step * s1
        q2 += step * s2
        if step * max(abs(s0), abs(s1), abs(s2)) <= tol:
            converged = True
            break
    count = 0
    for j in range(z):
        if ci[j] - (q0 * cth[j] + q1 * sth[j]) * cos_a - q2 * sin_a <= 0.0:
            count += 1
    if z - count < 3:
        return q0, q1, q2, count, TOO_FEW_LOADED
    if not converged:
        return q0, q1, q2, count, NOT_CONVERGED
    return q0, q1, q2, count, OK


@kernel()
def solve_kernel(
    c: NDArray[np.float64],
    theta: NDArray[np.float64],
    cos_a: float,
    sin_a: float,
    k: float,
    force: NDArray[np.float64],
    q_start: NDArray[np.float64],
    d_ref: float,
    max_iter: int,
) -> tuple[NDArray[np.float64], NDArray[np.int64], int, int]:
    """Newton solve of seed 000 eq. 5 at every instant (compiled).

    Parameters
    ----------
    c : ndarray, shape (n, Z)
        Approach of each ball at q = 0, :math:`(W_i - W_o)\\cos\\alpha + W_b + \\delta_{pl}` [m].
    theta : ndarray, shape (n, Z)
        Ball angles [rad].
    cos_a, sin_a : float
        cos α, sin α.
    k : float
        K_n [N/m^1.5].
    force : ndarray, shape (3,)
        Right-hand side of the balance [N].
    q_start : ndarray, shape (3,)
        Starting point of the first instant [m].
    d_ref : float
        Reference approach δ_pl [m]: step tolerance RTOL·d_ref, line search only for steps
        above 1e-4·d_ref (below that Newton is in its quadratic range and the potential is
        too flat to judge a step in floating point).
    max_iter : int
        Newton iterations per instant.

    Returns
    -------
    q : ndarray, shape (n, 3)
        Outer-ring centre [m].
    unloaded : ndarray, shape (n,)
        Balls without load at each instant.
    status : int
        0 ok, 1 too few loaded balls, 2 singular, 3 not converged.
    instant : int
        Instant of the failure (-1 when status is 0).

    Notes
    -----
    Tada, "Three-dimensional analysis of non-repeatable runout (NRRO) in ball
    bearings", Koyo Engineering Journal (2002) (seed 000), eq. 2-5.
    """
    n, z = c.shape
    q = np.zeros((n, 3))
    unloaded = np.zeros(n, dtype=np.int64)
    cth = np.empty(z)
    sth = np.empty(z)
    qa = q_start.copy()  # the last three solutions, for the starting point of the next
    qb = q_start.copy()
    qc = q_start.copy()
    smooth = 0  # last instants with every ball loaded (up to 3)
    for i in range(n):
        for j in range(z):
            cth[j] = math.cos(theta[i, j])
            sth[j] = math.sin(theta[i, j])
        for attempt in range(2):  # from the extrapolation, then from the last solution
            order = smooth if attempt == 0 else 1
            q0, q1, q2, count, status = _newton(
                c[i],
                cth,
                sth,
                cos_a,
                sin_a,
                k,
                force,
                predict(order, qa[0], qb[0], qc[0]),
                predict(order, qa[1], qb[1], qc[1]),
                predict(order, qa[2], qb[2], qc[2]),
                d_ref,
                max_iter,
            )
            if status == OK or order < 2:
                break
        smooth = min(smooth + 1, 3) if count == 0 else 0
        if status != OK:
            return q, unloaded, status, i
        qc[:] = qb
        qb[:] = qa
        qa[0] = q[i, 0] = q0
        qa[1] = q[i, 1] = q1
        qa[2] = q[i, 2] = q2
        unloaded[i] = count
    return q, unloaded, 0, -1


@kernel(nogil=True)
def solve_fused(
    t: NDArray[np.float64],
    rates: NDArray[np.float64],
    base: NDArray[np.float64],
    pitch: NDArray[np.float64],
    ring: NDArray[np.float64],
    n_inner: int,
    ball: NDArray[np.float64],
    ball_offsets: NDArray[np.int64],
    gains: NDArray[np.float64],
    planar: bool,
    cos_a: float,
    sin_a: float,
    k: float,
    force: NDArray[np.float64],
    d_ref: float,
    max_iter: int,
    disp: NDArray[np.float64],
    unloaded: NDArray[np.signedinteger[Any]],
    h: float,
    state: tuple[NDArray[np.float64], ...],
    first: int,
    last: int,
) -> tuple[int, int]:
    """Seed 000 eq. 5 at every instant, the deviations evaluated on the fly (compiled).

    :func:`solve_kernel` fused with :func:`runout.models._quasi_static.contact_series`: at
    each instant the phasor recurrences give the approaches c_j and cos θ_j, sin θ_j (arrays
    of Z values, no (n, Z) temporaries), then Newton's method runs from the previous instant's
    solutions (:func:`runout.models._quasi_static.predict`; the first from q = 0).

    Parameters
    ----------
    t : ndarray, shape (n,)
        Instants [s].
    rates, base, pitch, ring, n_inner, ball, ball_offsets, gains, planar
        :meth:`runout.models._quasi_static.ContactSources.args`.
    cos_a, sin_a, k, force, d_ref, max_iter
        As :func:`solve_kernel`.
    disp : ndarray, shape (3, n)
        Filled with the shaft centre relative to the outer ring, -q [m] (the reported frame).
    unloaded : ndarray of int16 or int64, shape (n,)
        Filled with the balls without load at each instant.
    h : float
        Step of the time grid, :func:`runout.models._quasi_static.time_step` [s].
    state : tuple of ndarray
        Work arrays of the phasors, :func:`runout.models._quasi_static.contact_state`.
    first, last : int
        The instants ``first <= i < last`` are solved (and written at i), Newton's method
        starting from rest at ``first`` (:func:`runout.models._quasi_static.solve_in_halves`).

    Returns
    -------
    status : int
        0 ok, 1 too few loaded balls, 2 singular, 3 not converged.
    instant : int
        Instant of the failure (-1 when status is 0).
    """
    z = base.size
    # allocated here, not passed in: fresh arrays alias nothing, which the loops need to run
    # at full speed
    ci = np.empty(z)
    cth = np.empty(z)
    sth = np.empty(z)
    a0 = a1 = a2 = b0 = b1 = b2 = c0 = c1 = c2 = 0.0  # the last three solutions
    smooth = 0  # last instants with every ball loaded (up to 3)
    anchor = first - ANCHOR  # none yet; a literal -1 would compile on_grid a second time
    for i in range(first, last):
        if on_grid(i, t, h, anchor):
            contact_advance(state)
        else:
            contact_anchor(t[i], rates, base, pitch, ring, n_inner, ball, state)
            anchor = i
        contact_values(state, n_inner, ball_offsets, gains, planar, ci, cth, sth)
        for attempt in range(2):  # from the extrapolation, then from the last solution
            order = smooth if attempt == 0 else 1
            q0, q1, q2, count, status = _newton(
                ci,
                cth,
                sth,
                cos_a,
                sin_a,
                k,
                force,
                predict(order, a0, b0, c0),
                predict(order, a1, b1, c1),
                predict(order, a2, b2, c2),
                d_ref,
                max_iter,
            )
            if status == OK or order < 2:
                break
        smooth = min(smooth + 1, 3) if count == 0 else 0
        if status != OK:
            return status, i
        c0, c1, c2 = b0, b1, b2
        b0, b1, b2 = a0, a1, a2
        a0, a1, a2 = q0, q1, q2
        disp[0, i] = -q0
        disp[1, i] = -q1
        disp[2, i] = -q2
        unloaded[i] = count
    return 0, -1


def _raise(status: int, instant: int, time: NDArray[np.float64]) -> None:
    cause = CAUSES[status]
    t = float(time[instant])
    if status == TOO_FEW_LOADED:
        raise ContactLossError(cause, instant, t)
    if status == NOT_CONVERGED:
        raise ConvergenceError(cause, instant, t)
    raise NumericalError(cause, instant, t)


def solve_reference(
    c: NDArray[np.float64],
    theta: NDArray[np.float64],
    contact_angle: float,
    stiffness: float,
    force: NDArray[np.float64],
    *,
    tol: float,
    max_iter: int = MAX_ITER,
) -> NDArray[np.float64]:
    """Vectorised NumPy Newton solve of eq. 5 at all instants at once (reference for tests).

    Same equations as :func:`solve_kernel`, independent code path: batched
    :func:`numpy.linalg.solve`, damped steps (halved while the residual norm grows), every
    instant started from q = 0.

    Parameters
    ----------
    c : ndarray, shape (n, Z)
        Approach of each ball at q = 0 [m] (:func:`approaches`).
    theta : ndarray, shape (n, Z)
        Ball angles [rad].
    contact_angle : float
        α [rad].
    stiffness : float
        K_n [N/m^1.5].
    force : ndarray, shape (3,)
        Right-hand side of the balance [N].
    tol : float
        Newton step tolerance [m].
    max_iter : int, optional
        Newton iterations; default :data:`MAX_ITER`.

    Returns
    -------
    ndarray, shape (n, 3)
        Outer-ring centre [m].

    Raises
    ------
    ConvergenceError
        When the Newton iteration does not converge within ``max_iter``.

    Notes
    -----
    Tada, "Three-dimensional analysis of non-repeatable runout (NRRO) in ball
    bearings", Koyo Engineering Journal (2002) (seed 000), eq. 2-5.
    """
    ca, sa = math.cos(contact_angle), math.sin(contact_angle)
    nvec = np.stack([ca * np.cos(theta), ca * np.sin(theta), np.full_like(theta, sa)], axis=-1)
    q = np.zeros((c.shape[0], 3))
    reg = 1e-9 * 1.5 * stiffness * math.sqrt(float(np.median(c)))

    def residual(qq: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        d = np.maximum(c - np.einsum("nzk,nk->nz", nvec, qq), 0.0)
        r = np.einsum("nz,nzk->nk", stiffness * d**1.5, nvec) - force
        return r, d

    for _ in range(max_iter):
        r, d = residual(q)
        h = np.einsum("nz,nzk,nzl->nkl", 1.5 * stiffness * np.sqrt(d), nvec, nvec)
        h += reg * np.eye(3)  # as in the kernel: keeps iterates with few loaded balls moving
        s = np.linalg.solve(h, r[..., None])[..., 0]
        step = np.ones(q.shape[0])
        norm0 = np.linalg.norm(r, axis=1)
        for _ls in range(30):
            r1, _ = residual(q + step[:, None] * s)
            worse = np.linalg.norm(r1, axis=1) > norm0
            if not worse.any():
                break
            step[worse] *= 0.5
        q = q + step[:, None] * s
        if np.max(np.abs(step[:, None] * s)) <= tol:
            return q
    raise ConvergenceError("reference Newton iteration did not converge")


def linearised_displacement(
    c: NDArray[np.float64],
    theta: NDArray[np.float64],
    contact_angle: float,
    stiffness: float,
    preload: float,
    force: NDArray[np.float64],
) -> NDArray[np.float64]:
    r"""Small-amplitude solution of eq. 5 with :math:`Q` linearised about :math:`\delta_{pl}`.

    :math:`Q_j \approx K_n\delta_{pl}^{3/2} + \tfrac32 K_n\delta_{pl}^{1/2}(\delta_j -
    \delta_{pl})` (the linear equation of seed 000 §2.2.1, "index deleted"), so that

    .. math:: H q = \sum_j \big(Q_0 + k_l (c_j - \delta_{pl})\big) n_j - F,
              \qquad H = k_l \sum_j n_j n_j^T.

    Parameters
    ----------
    c : ndarray, shape (n, Z)
        Approach of each ball at q = 0 [m] (:func:`approaches`).
    theta : ndarray, shape (n, Z)
        Ball angles [rad].
    contact_angle : float
        α [rad].
    stiffness : float
        K_n [N/m^1.5].
    preload : float
        δ_pl [m], the approach the loads are linearised about.
    force : ndarray, shape (3,)
        Right-hand side of the balance [N].

    Returns
    -------
    ndarray, shape (n, 3)
        Outer-ring centre [m].

    Notes
    -----
    Tada, "Three-dimensional analysis of non-repeatable runout (NRRO) in ball
    bearings", Koyo Engineering Journal (2002) (seed 000), eq. 5 and the linear equation of §2.2.1.
    """
    ca, sa = math.cos(contact_angle), math.sin(contact_angle)
    nvec = np.stack([ca * np.cos(theta), ca * np.sin(theta), np.full_like(theta, sa)], axis=-1)
    kl = 1.5 * stiffness * math.sqrt(preload)
    q0 = stiffness * preload**1.5
    h = kl * np.einsum("nzk,nzl->nkl", nvec, nvec)
    rhs = np.einsum("nz,nzk->nk", q0 + kl * (c - preload), nvec) - force
    return np.linalg.solve(h, rhs[..., None])[..., 0]


# --------------------------------------------------------------------------------------------
# model
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Setup:
    """Everything the solve needs, derived from a case.

    Attributes
    ----------
    contact_angle : float
        α [rad].
    stiffness : float
        K_n [N/m^1.5].
    preload : float
        δ_pl [m].
    force : ndarray, shape (3,)
        Right-hand side of eq. 5 [N].
    kinematics : Kinematics
        Signed ring, cage and spin frequencies [Hz] and the number of balls.
    """

    contact_angle: float
    stiffness: float
    preload: float
    force: NDArray[np.float64]
    kinematics: Kinematics


def contact_line_deviation(imperfections: Any, contact_angle: float) -> float:
    """Largest deviation along a contact line the imperfections can add up to [m].

    Raceway orders >= 2 (order 1 is a rigid translation, not a change of the ball's room)
    projected on the contact line, plus the largest element diameter deviation (its
    waviness and diameter error, seed 002 eq. 26).

    Parameters
    ----------
    imperfections : BearingImperfections
        Raceway and element deviations [m].
    contact_angle : float
        α [rad].

    Returns
    -------
    float
        Sum of the raceway amplitudes of orders >= 2 times cos α plus the largest sum of an
        element's diameter amplitudes [m].
    """
    rings = 0.0
    for h in (imperfections.inner, imperfections.outer):
        rings += float(np.sum(h.amplitudes[h.orders >= 2]))
    element = max(
        (float(np.sum(h.amplitudes)) for h in imperfections.element_diameter_deviations()),
        default=0.0,
    )
    return rings * math.cos(contact_angle) + element


def check_axial_room(
    imperfections: Any, bearing: BallBearing, contact_angle: float, preload: float
) -> None:
    r"""Refuse deviations that would carry the ring beyond its opposite groove flanks.

    Under the preload the inner ring's groove centres sit :math:`(A + \delta_{pl})\sin\alpha`
    axially from the rings centred; the opposite flanks touch at :math:`-A\sin\alpha^0`
    (the free end play is :math:`2A\sin\alpha^0`). So the ring can travel at most
    :math:`(A + \delta_{pl})\sin\alpha + A\sin\alpha^0` against the preload. A deviation w
    along the contact line moves it axially by about :math:`w / \sin\alpha` at a fixed
    contact angle; beyond that travel no such motion exists, and the fixed-angle model's
    axial runout is an artefact (e.g. 381 µm of axial p-p with 2 nm of clearance and a small
    preload, where the end play is 1.3 µm).

    Parameters
    ----------
    imperfections : BearingImperfections
        Raceway and element deviations [m].
    bearing : BallBearing
        Geometry: curvature-centre distance A [m] and free contact angle α⁰ [rad].
    contact_angle : float
        α [rad], > 0.
    preload : float
        δ_pl [m].

    Raises
    ------
    GeometryError
        Naming ``bearing.contact_angle`` (a fixed angle) or ``operation.axial_load``.
    """
    w = contact_line_deviation(imperfections, contact_angle)
    s = math.sin(contact_angle)
    a = bearing.curvature_distance
    end_play = 2.0 * a * math.sin(bearing.free_contact_angle)
    travel = (a + preload) * s + 0.5 * end_play
    if w <= 0.0 or w / s <= travel:
        return
    key = "bearing.contact_angle" if bearing.contact_angle is not None else "operation.axial_load"
    raise GeometryError(
        key,
        f"the deviations along a contact line (up to {w * 1e9:.4g} nm) would move the inner "
        f"ring axially by about {w / s * 1e6:.4g} um at the contact angle "
        f"{math.degrees(contact_angle):.4g} deg, beyond the {travel * 1e6:.4g} um it can "
        f"travel before its opposite groove flanks touch (free end play 2A sin a0 = "
        f"{end_play * 1e6:.4g} um): the fixed contact angle cannot hold; raise the axial "
        'preload (or bearing.radial_clearance), or use model = "dynamic"',
    )


def check_radial_capacity(op: Operation, contact_angle: float) -> None:
    r"""Refuse a radial load the balls cannot carry at a fixed contact angle.

    At a fixed angle α every contact force has the axial share sin α, so the balls' forces sum
    to :math:`\sum Q_j = F_a / \sin\alpha` under the constant axial force :math:`F_a`, and
    their radial resultant is at most :math:`\sum Q_j \cos\alpha = F_a / \tan\alpha` (all
    of them on the load line). A larger radial load has no solution in this model: in the
    bearing the loaded balls roll down towards their groove bottoms (their contact angles
    fall), which the exact contact geometry of the dynamic model follows.

    Parameters
    ----------
    op : Operation
        The loads: ``radial_load`` and ``axial_load`` [N].
    contact_angle : float
        The fixed contact angle α [rad], > 0.

    Raises
    ------
    GeometryError
        Naming ``operation.radial_load``, when :math:`F_r \ge F_a / \tan\alpha`.

    Notes
    -----
    Tada, "Three-dimensional analysis of non-repeatable runout (NRRO) in ball bearings",
    Koyo Engineering Journal (2002) (seed 000): the contact angle is held fixed and the
    x, y, z force balance solved at each instant.
    """
    capacity = op.axial_load / math.tan(contact_angle)
    if op.radial_load < capacity:
        return
    raise GeometryError(
        "operation.radial_load",
        f"{op.radial_load:.6g} N is more than the balls carry radially at the fixed contact "
        f"angle {math.degrees(contact_angle):.4g} deg under the {op.axial_load:.6g} N spring "
        f"preload: F_a / tan α = {capacity:.4g} N; the loaded balls move towards their groove "
        'bottoms, which this model cannot follow: use model = "dynamic" (exact contact '
        'geometry, preload = "spring"), or raise operation.axial_load',
    )


def setup(case: Case) -> Setup:
    """Contact angle, K_n, δ_pl, loads and frequencies of a case (see module docstring).

    Parameters
    ----------
    case : Case
        A validated case with a ball bearing, an axial preload > 0 [N] and a contact angle > 0.

    Returns
    -------
    Setup
        α [rad], K_n [N/m^1.5], δ_pl [m], the loads [N] and the kinematics [Hz].

    Raises
    ------
    GeometryError
        Not a ball bearing, no preload, no contact angle, or deviations larger than the axial
        room (:func:`check_axial_room`).

    Notes
    -----
    K_n of Tada, "Three-dimensional analysis of non-repeatable runout (NRRO) in ball
    bearings", Koyo Engineering Journal (2002) (seed 000), eq. 4; δ_pl from the balance of
    eq. 5 (:func:`preload_approach`).
    """
    bearing = case.bearing
    op = case.operation
    if not isinstance(bearing, BallBearing):
        raise GeometryError("bearing.type", "the quasi_static_3d model needs a ball bearing")
    if op.axial_load <= 0.0:
        raise GeometryError(
            "operation.axial_load",
            "the quasi_static_3d model needs an axial preload > 0 N (seed 000 eq. 5); a bearing "
            'without preload, with its radial play, runs in model = "dynamic" (or "equilibrium" '
            "when at least 3 balls carry the load)",
        )
    alpha, _ = operating_contact_angle(bearing, op)
    if not alpha > 0.0:
        raise GeometryError("contact_angle", "the quasi_static_3d model needs a contact angle > 0")
    check_radial_capacity(op, alpha)
    kn = ball_race_contacts(bearing, alpha).combined_stiffness
    z = bearing.elements
    dpl = preload_approach(kn, z, alpha, op.axial_load)
    check_axial_room(case.imperfections, bearing, alpha, dpl)
    # The radial load acts on the shaft along β; in the paper's frame (outer ring moving
    # relative to the inner ring) that is the outer ring pushed along -β.
    beta = op.radial_load_direction
    force = np.array(
        [op.radial_load * math.cos(beta), op.radial_load * math.sin(beta), op.axial_load]
    )
    d, dm = bearing.element_diameter, bearing.pitch_diameter
    kin = Kinematics(
        inner=op.inner_speed,
        outer=op.outer_speed,
        cage=float(cage_frequency(op.inner_speed, op.outer_speed, d, dm, alpha)),
        spin=float(ball_spin_frequency(op.inner_speed, op.outer_speed, d, dm, alpha)),
        rotating_ring=op.rotating_ring,
        n_elements=z,
    )
    return Setup(alpha, kn, dpl, force, kin)


def approaches(
    case: Case, st: Setup, time: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Approach at q = 0 (eq. 2) and ball angles, shape (n, Z) each.

    Parameters
    ----------
    case : Case
        The case (its imperfections).
    st : Setup
        From :func:`setup`.
    time : ndarray, shape (n,)
        Instants [s].

    Returns
    -------
    c : ndarray, shape (n, Z)
        (W_i - W_o) cos α + W_b + δ_pl [m].
    theta : ndarray, shape (n, Z)
        Ball angles θ_j [rad].

    Notes
    -----
    Tada, "Three-dimensional analysis of non-repeatable runout (NRRO) in ball
    bearings", Koyo Engineering Journal (2002) (seed 000), eq. 2.
    """
    dev = contact_deviations(case.imperfections, st.kinematics, time)
    c = (dev.inner - dev.outer) * math.cos(st.contact_angle) + dev.ball + st.preload
    return np.ascontiguousarray(c), np.ascontiguousarray(dev.theta)


def solve(
    case: Case, time: NDArray[np.float64], st: Setup | None = None
) -> tuple[NDArray[np.float64], NDArray[np.integer[Any]]]:
    """Shaft (inner-ring) centre relative to the outer ring (3, n) [m] and unloaded-ball counts
    (n,) at ``time``: the kernel's outer-ring position (seed 000's frame) with its sign turned.

    Parameters
    ----------
    case : Case
        The case (its imperfections).
    time : ndarray, shape (n,)
        Instants [s].
    st : Setup, optional
        From :func:`setup`; derived from ``case`` when None.

    Returns
    -------
    disp : ndarray, shape (3, n)
        Shaft centre relative to the outer ring (x, y, z) [m], z from the preloaded position.
    unloaded : ndarray of int, shape (n,)
        Balls without load at each instant.

    Raises
    ------
    ContactLossError, ConvergenceError, NumericalError
        When the ring cannot be held at some instant (the error names it).

    Notes
    -----
    Tada, "Three-dimensional analysis of non-repeatable runout (NRRO) in ball
    bearings", Koyo Engineering Journal (2002) (seed 000), eq. 2-5.
    """
    st = setup(case) if st is None else st
    t = np.ascontiguousarray(time, dtype=np.float64)
    src = contact_sources(
        case.imperfections,
        st.kinematics,
        ring_gain=math.cos(st.contact_angle),
        element_gain=1.0,
        offset=st.preload,
        planar=False,
    )
    disp = np.empty((3, t.size))
    # counts of at most Z balls: 2 bytes an instant for any case (Z <= MAX_ELEMENTS < 2**15)
    unloaded: NDArray[np.integer[Any]] = np.empty(
        t.size, dtype=np.int16 if st.kinematics.n_elements < 2**15 else np.int64
    )
    h = time_step(t)
    args = (
        t,
        *src.args(),
        math.cos(st.contact_angle),
        math.sin(st.contact_angle),
        st.stiffness,
        st.force,
        st.preload,
        MAX_ITER,
        disp,
        unloaded,
        h,
    )
    status, instant = solve_in_halves(
        solve_fused,
        args,
        t.size,
        lambda: contact_state(h, src.rates, src.ring, src.n_inner, src.ball, src.base.size),
    )
    if status != OK:
        _raise(int(status), int(instant), t)
    return disp, unloaded


def time_grid_of(case: Case) -> NDArray[np.float64]:
    """The instants [s] of a case's analysis (``revolutions`` turns, ``samples`` instants).

    Parameters
    ----------
    case : Case
        The case (its speed [Hz] and ``[analysis]`` window).

    Returns
    -------
    ndarray
        Instants [s].
    """
    an = case.analysis
    return time_grid(case.operation.speed, an.revolutions, an.samples)


def axial_position(case: Case, st: Setup) -> float:
    r"""Axial position of the shaft at the preload, from the rings axially centred [m].

    The groove curvature centres are :math:`A + \delta_{pl}` apart along the contact line at
    α, so the inner ring sits :math:`(A + \delta_{pl})\sin\alpha` along the axial load (for
    the loaded contact angle of Harris's relation this is the equilibrium model's static
    position; with a fixed angle it is the position that angle implies).

    Parameters
    ----------
    case : Case
        The case (a ball bearing: curvature-centre distance A [m]).
    st : Setup
        From :func:`setup`: α [rad] and δ_pl [m].

    Returns
    -------
    float
        (A + δ_pl) sin α [m].

    Raises
    ------
    GeometryError
        Not a ball bearing.
    """
    bearing = case.bearing
    if not isinstance(bearing, BallBearing):
        raise GeometryError("bearing.type", "the quasi_static_3d model needs a ball bearing")
    a = bearing.curvature_distance
    return float((a + st.preload) * math.sin(st.contact_angle))


def run(case: Case) -> RunResult:
    """Run the quasi-static 3-D model (seed 000) on a case.

    The reported z is measured from the rings axially centred (:func:`axial_position` plus
    the solved motion), as in every model.

    Parameters
    ----------
    case : Case
        A validated case with ``[analysis] model = "quasi_static_3d"``, a ball bearing and an
        axial preload.

    Returns
    -------
    RunResult
        Shaft centre relative to the outer ring [m] over the analysis window, the fitted lines
        and the runout figures [m].

    Notes
    -----
    Tada, "Three-dimensional analysis of non-repeatable runout (NRRO) in ball
    bearings", Koyo Engineering Journal (2002) (seed 000), eq. 2-5.
    """
    st = setup(case)
    offset = axial_position(case, st)

    def solve_reported(
        case: Case, time: NDArray[np.float64], st: Setup | None = None
    ) -> tuple[NDArray[np.float64], NDArray[np.integer[Any]]]:
        disp, unloaded = solve(case, time, st)
        disp[2] += offset
        return disp, unloaded

    return run_quasi_static(
        case,
        st,
        solve_reported,
        model=MODEL,
        planar=False,
        description="contact angle fixed at its preloaded value (seed 000)",
        approach_m=st.preload,
    )
