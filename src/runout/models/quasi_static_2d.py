r"""Two-dimensional quasi-static NRRO model of the shaft centre (seed 001, Kim, Choi & Yoon).

The outer raceway's centre is fixed at the origin; the inner raceway's centre (the shaft)
settles at :math:`(x, y)` where the Hertz forces of the Z balls cancel (eq. 16-17, no external
load, no inertia). Ball k (eq. 8, 0-based here) deforms by (eq. 10)

.. math::
    \delta_k = \delta_0 + \tfrac12\{W_{ik} + w_{bk} - W_{ok} + x\cos\theta_k + y\sin\theta_k\},

with :math:`W_{ik}` the inner-raceway radius deviation at the ball (positive = material
added), :math:`W_{ok}` the outer-raceway radius deviation (positive = radius larger),
:math:`w_{bk}` the ball's diameter deviation along its contact line (eq. 13, read as seed 002
eq. 26; size error included) and :math:`\delta_0 = (\delta_i + \delta_o)/2` the mean of the
two Hertz approaches of the static axial-load solution (text after eq. 18;
:func:`runout.geometry.loading.axial_loading` at the operating contact angle). The load is
:math:`P_k = C_k (2\delta_k)^{3/2}` with :math:`C_k = K_n` (eq. 14-15), so a ball whose
bracket turns negative carries none (counted and reported).

Notes
-----
* The ½ of eq. 10 makes δ_k the mean of the inner and outer approaches; we apply eq. 14 to the
  total approach 2δ_k. The balance (eq. 16-17) is homogeneous in C_k, so the shaft position
  does not depend on this choice; it does make the loads physical.
* Eq. 10 is planar: x, y and the deviations enter without the contact angle, exactly as
  printed. The contact angle (:func:`runout.report.summary.operating_contact_angle`) sets the
  kinematics (eq. 7, 9) and δ_0 only. ``element_projection="radial"`` multiplies the ball
  deviations by cos α instead (their projection on the radial plane), an option for studies:
  Tables 4-8 are reproduced with eq. 10 as printed once the paper's FFT reading is applied
  (VALIDATION.md, :func:`runout.analysis.spectrum.peak_bin_gain`).
* Eq. 11-12 write the raceway radii as functions of the ball angle θ_k; for a rotating ring we
  evaluate its profile in the ring's frame, :math:`r(\theta_k - 2\pi f_{ring} t)`.
* The shaft is the measured body: the displacement reported is the inner ring's centre
  relative to the outer ring's (z = 0).
* Extension beyond the paper: an external radial load F (``operation.radial_load`` along
  ``radial_load_direction``) is put on the right-hand side of eq. 16-17,
  :math:`\sum_k P_k(\cos\theta_k, \sin\theta_k) = F`, with the contact angle and δ_0 still
  those of the axial preload (a planar model cannot change them); the measuring direction is
  then the load's. Use ``equilibrium`` for the loaded contact angles.
* Solver: Newton per instant (eq. 18) with a closed-form 2×2 solve, Armijo backtracking on the
  convex potential, started from the previous solutions extrapolated
  (:func:`runout.models._quasi_static.predict`). :func:`solve` runs the fused kernel
  :func:`solve_fused`, which evaluates the deviations of eq. 10-13 instant by instant by
  rotating phasors (no arrays of size instants × balls); :func:`solve_kernel_loaded` is the
  same solve on precomputed arrays (:func:`approaches`), :func:`solve_reference` the
  vectorised NumPy version used in tests.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Literal

import numpy as np
from numba.extending import register_jitable
from numpy.typing import NDArray

from runout.analysis.results import SOLVER_RTOL, RunResult
from runout.base._kernel import kernel
from runout.base.errors import ContactLossError, ConvergenceError, GeometryError, NumericalError
from runout.geometry.bearing import BallBearing, Operation
from runout.geometry.contact import ball_race_contacts
from runout.geometry.kinematics import ball_spin_frequency, cage_frequency
from runout.geometry.loading import axial_loading, operating_contact_angle
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
    time_step,
)

if TYPE_CHECKING:
    from runout.case.model import Case

__all__ = [
    "Setup",
    "approaches",
    "run",
    "setup",
    "solve",
    "solve_fused",
    "solve_kernel",
    "solve_kernel_loaded",
    "solve_reference",
]

MODEL = "quasi_static_2d"
OK, TOO_FEW_LOADED, SINGULAR, NOT_CONVERGED = 0, 1, 2, 3
#: Message per kernel status code (errors name the instant and this cause).
CAUSES = {
    TOO_FEW_LOADED: "fewer than 2 balls carry load: the shaft cannot be held",
    SINGULAR: (
        "singular stiffness matrix: the loaded balls lie on one line (e.g. two opposite "
        "balls) and cannot hold the shaft across it"
    ),
    NOT_CONVERGED: "Newton iteration did not converge",
}
RTOL = SOLVER_RTOL["quasi_static_2d"]
MAX_ITER = 60
#: Residual round-off floor relative to the sum of the load magnitudes (64 ulp).
FLOOR = 64.0 * 2.0**-52
ElementProjection = Literal["none", "radial"]


@kernel()
def hertz_potential(
    c: NDArray[np.float64],
    cth: NDArray[np.float64],
    sth: NDArray[np.float64],
    k: float,
    q0: float,
    q1: float,
    force: NDArray[np.float64],
) -> float:
    """Energy of the Hertz contacts minus the work of ``force`` at shaft centre q (compiled);
    the Newton line search of eq. 16-17 descends it (also used by the Monte Carlo kernel).

    Parameters
    ----------
    c : ndarray, shape (Z,)
        δ_k at x = y = 0 [m] (eq. 10 without the x, y terms).
    cth, sth : ndarray, shape (Z,)
        Cosine and sine of the ball angles θ_k [-].
    k : float
        C_k = K_n [N/m^1.5].
    q0, q1 : float
        Shaft centre x, y [m].
    force : ndarray, shape (2,)
        External radial load on the shaft (F_x, F_y) [N].

    Returns
    -------
    float
        ``Σ_k K_n (2δ_k)^(5/2) / 2.5`` over the loaded balls minus ``F · q`` [J].

    Notes
    -----
    The potential whose gradient is the balance of Kim, Choi & Yoon, "Vibration analysis of
    ball bearings with ball geometric imperfections" (seed 001), eq. 14-17.
    """
    e: float = -(force[0] * q0 + force[1] * q1)
    for j in range(c.size):
        d = 2.0 * c[j] + q0 * cth[j] + q1 * sth[j]
        if d > 0.0:
            e += k / 2.5 * d * d * math.sqrt(d)
    return e


@kernel()
def loaded_balls_collinear(
    c: NDArray[np.float64], cth: NDArray[np.float64], sth: NDArray[np.float64], q0: float, q1: float
) -> bool:
    """True when the loaded balls' directions span one line only (compiled).

    The stiffness of the loaded balls, Σ √d_k n_k n_kᵀ (without regularisation), is
    then singular: e.g. two opposite balls hold the shaft along their line and nothing holds
    it across (its position there is undetermined). Relative threshold 1e-12 on
    det / trace².

    Parameters
    ----------
    c : ndarray, shape (Z,)
        δ_k at x = y = 0 [m].
    cth, sth : ndarray, shape (Z,)
        Cosine and sine of the ball angles θ_k [-].
    q0, q1 : float
        Shaft centre x, y [m].

    Returns
    -------
    bool
        True when the loaded balls cannot hold the shaft across their common line.
    """
    h00 = h01 = h11 = 0.0
    for j in range(c.size):
        d = 2.0 * c[j] + q0 * cth[j] + q1 * sth[j]
        if d > 0.0:
            sd = math.sqrt(d)
            h00 += sd * cth[j] * cth[j]
            h01 += sd * cth[j] * sth[j]
            h11 += sd * sth[j] * sth[j]
    tr = h00 + h11
    return h00 * h11 - h01 * h01 <= 1e-12 * tr * tr


@kernel()
def solve_kernel(
    c: NDArray[np.float64], theta: NDArray[np.float64], k: float, d_ref: float, max_iter: int
) -> tuple[NDArray[np.float64], NDArray[np.int64], int, int]:
    """Newton solve of seed 001 eq. 16-17 at every instant, no external load (compiled).

    :func:`solve_kernel_loaded` with a zero force; same parameters and returns.

    Parameters
    ----------
    c : ndarray, shape (n, Z)
        δ_k at x = y = 0 [m] (eq. 10 without the x, y terms).
    theta : ndarray, shape (n, Z)
        Ball angles [rad].
    k : float
        C_k = K_n [N/m^1.5].
    d_ref : float
        Reference approach δ_0 [m] (step tolerance and line-search threshold).
    max_iter : int
        Newton iterations per instant.

    Returns
    -------
    q : ndarray, shape (n, 2)
        Shaft centre [m].
    unloaded : ndarray, shape (n,)
        Balls without load at each instant.
    status : int
        0 ok, 1 too few loaded balls, 2 singular, 3 not converged.
    instant : int
        Instant of the failure (-1 when status is 0).

    Notes
    -----
    Kim, Choi & Yoon, "Vibration analysis of ball bearings with ball geometric
    imperfections" (seed 001), eq. 16-18.
    """
    return solve_kernel_loaded(c, theta, k, d_ref, max_iter, np.zeros(2))


# register_jitable: compiled into its caller, without Python and C entry points of its own
# (first-run compilation time); a helper that several compiled functions of one run call
# stays njit (compiled once, not once per caller).
@register_jitable(no_cfunc_wrapper=True)
def _newton(
    ci: NDArray[np.float64],
    cth: NDArray[np.float64],
    sth: NDArray[np.float64],
    k: float,
    d_ref: float,
    max_iter: int,
    force: NDArray[np.float64],
    q0: float,
    q1: float,
) -> tuple[float, float, int, int]:
    """Newton solve of seed 001 eq. 16-17 at one instant from (q0, q1) (compiled).

    Returns
    -------
    q0, q1 : float
        Shaft centre [m].
    unloaded : int
        Balls without load.
    status : int
        0 ok, 1 too few loaded balls, 2 singular, 3 not converged.
    """
    z = ci.size
    tol = RTOL * d_ref
    converged = False
    for _ in range(max_iter):
        f0 = -force[0]
        f1 = -force[1]
        h00 = h01 = h11 = 0.0
        load_sum = abs(force[0]) + abs(force[1])
        for j in range(z):
            d = 2.0 * ci[j] + q0 * cth[j] + q1 * sth[j]  # total approach 2 δ_k
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
        # residual at its round-off floor: converged (a nearly unloaded ball makes the
        # stiffness nearly singular and the steps then never fall below the tolerance)
        if max(abs(f0), abs(f1)) <= FLOOR * load_sum:
            converged = True
            break
        reg = 1e-9 * 1.5 * k * math.sqrt(2.0 * d_ref)
        h00 += reg
        h11 += reg
        det = h00 * h11 - h01 * h01
        if not det > 0.0:
            return q0, q1, 0, SINGULAR
        s0 = -(h11 * f0 - h01 * f1) / det
        s1 = -(h00 * f1 - h01 * f0) / det
        slope = f0 * s0 + f1 * s1
        step = 1.0
        big = max(abs(s0), abs(s1)) > 1e-4 * d_ref
        e0 = hertz_potential(ci, cth, sth, k, q0, q1, force) if big else 0.0
        for _ls in range(40 if big else 0):
            e1 = hertz_potential(ci, cth, sth, k, q0 + step * s0, q1 + step * s1, force)
            if e1 <= e0 + 1e-4 * step * slope or step * max(abs(s0), abs(s1)) < tol:
                break
            step *= 0.5
        q0 += step * s0
        q1 += step * s1
        if step * max(abs(s0), abs(s1)) <= tol:
            converged = True
            break
    count = 0
    for j in range(z):
        if 2.0 * ci[j] + q0 * cth[j] + q1 * sth[j] <= 0.0:
            count += 1
    if z - count < 2:
        return q0, q1, count, TOO_FEW_LOADED
    if loaded_balls_collinear(ci, cth, sth, q0, q1):
        return q0, q1, count, SINGULAR
    if not converged:
        return q0, q1, count, NOT_CONVERGED
    return q0, q1, count, OK


@kernel()
def solve_kernel_loaded(
    c: NDArray[np.float64],
    theta: NDArray[np.float64],
    k: float,
    d_ref: float,
    max_iter: int,
    force: NDArray[np.float64],
) -> tuple[NDArray[np.float64], NDArray[np.int64], int, int]:
    r"""Newton solve of seed 001 eq. 16-17 with a radial load at every instant (compiled).

    Solves :math:`\sum_k P_k(\cos\theta_k, \sin\theta_k) = F` (eq. 16-17 with the radial
    load F on the right-hand side; F = 0 is the paper's case). Each instant starts from the
    extrapolated previous solutions (:func:`runout.models._quasi_static.predict`).

    Parameters
    ----------
    c : ndarray, shape (n, Z)
        δ_k at x = y = 0 [m] (eq. 10 without the x, y terms).
    theta : ndarray, shape (n, Z)
        Ball angles [rad].
    k : float
        C_k = K_n [N/m^1.5].
    d_ref : float
        Reference approach δ_0 [m]: step tolerance RTOL·d_ref; line search only for steps
        above 1e-4·d_ref (quadratic range below).
    max_iter : int
        Newton iterations per instant.
    force : ndarray, shape (2,)
        External radial load on the shaft (F_x, F_y) [N].

    Returns
    -------
    q : ndarray, shape (n, 2)
        Shaft centre [m].
    unloaded : ndarray, shape (n,)
        Balls without load at each instant.
    status : int
        0 ok, 1 too few loaded balls, 2 singular, 3 not converged.
    instant : int
        Instant of the failure (-1 when status is 0).
    """
    n, z = c.shape
    q = np.zeros((n, 2))
    unloaded = np.zeros(n, dtype=np.int64)
    cth = np.empty(z)
    sth = np.empty(z)
    a0 = a1 = b0 = b1 = c0 = c1 = 0.0  # the last three solutions
    smooth = 0  # last instants with every ball loaded (up to 3)
    for i in range(n):
        for j in range(z):
            cth[j] = math.cos(theta[i, j])
            sth[j] = math.sin(theta[i, j])
        for attempt in range(2):  # from the extrapolation, then from the last solution
            order = smooth if attempt == 0 else 1
            q0, q1, count, status = _newton(
                c[i],
                cth,
                sth,
                k,
                d_ref,
                max_iter,
                force,
                predict(order, a0, b0, c0),
                predict(order, a1, b1, c1),
            )
            if status == OK or order < 2:
                break
        smooth = min(smooth + 1, 3) if count == 0 else 0
        if status != OK:
            return q, unloaded, status, i
        c0, c1 = b0, b1
        b0, b1 = a0, a1
        a0, a1 = q0, q1
        q[i, 0] = q0
        q[i, 1] = q1
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
    k: float,
    d_ref: float,
    max_iter: int,
    force: NDArray[np.float64],
    disp: NDArray[np.float64],
    unloaded: NDArray[np.signedinteger[Any]],
    h: float,
    state: tuple[NDArray[np.float64], ...],
    first: int,
    last: int,
) -> tuple[int, int]:
    """Seed 001 eq. 16-17 at every instant, the deviations evaluated on the fly (compiled).

    :func:`solve_kernel_loaded` fused with
    :func:`runout.models._quasi_static.contact_series` (no (n, Z) temporaries).

    Parameters
    ----------
    t : ndarray, shape (n,)
        Instants [s].
    rates, base, pitch, ring, n_inner, ball, ball_offsets, gains, planar
        :meth:`runout.models._quasi_static.ContactSources.args` (planar combination).
    k, d_ref, max_iter, force
        As :func:`solve_kernel_loaded`.
    disp : ndarray, shape (3, n)
        Filled with the shaft centre (x, y, 0) [m].
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
    a0 = a1 = b0 = b1 = c0 = c1 = 0.0  # the last three solutions
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
            q0, q1, count, status = _newton(
                ci,
                cth,
                sth,
                k,
                d_ref,
                max_iter,
                force,
                predict(order, a0, b0, c0),
                predict(order, a1, b1, c1),
            )
            if status == OK or order < 2:
                break
        smooth = min(smooth + 1, 3) if count == 0 else 0
        if status != OK:
            return status, i
        c0, c1 = b0, b1
        b0, b1 = a0, a1
        a0, a1 = q0, q1
        disp[0, i] = q0
        disp[1, i] = q1
        disp[2, i] = 0.0
        unloaded[i] = count
    return 0, -1


def solve_reference(
    c: NDArray[np.float64],
    theta: NDArray[np.float64],
    *,
    tol: float,
    max_iter: int = MAX_ITER,
    force: NDArray[np.float64] | None = None,
    stiffness: float = 1.0,
) -> NDArray[np.float64]:
    """Vectorised NumPy Newton solve of eq. 16-18 at all instants (reference for tests).

    ``force`` is the external radial load (F_x, F_y) [N] (default none) and ``stiffness``
    C_k = K_n [N/m^1.5] (only matters with a load: without one the balance is homogeneous).

    Parameters
    ----------
    c : ndarray, shape (n, Z)
        δ_k at x = y = 0 [m] (eq. 10 without the x, y terms).
    theta : ndarray, shape (n, Z)
        Ball angles [rad].
    tol : float
        Newton step tolerance [m].
    max_iter : int, optional
        Newton iterations; default :data:`MAX_ITER`.
    force : ndarray, shape (2,), optional
        External radial load on the shaft (F_x, F_y) [N]; default none.
    stiffness : float, optional
        C_k = K_n [N/m^1.5]; default 1.

    Returns
    -------
    ndarray, shape (n, 2)
        Shaft centre [m].

    Raises
    ------
    ConvergenceError
        When the Newton iteration does not converge within ``max_iter``.

    Notes
    -----
    Kim, Choi & Yoon, "Vibration analysis of ball bearings with ball geometric
    imperfections" (seed 001), eq. 16-18.
    """
    nvec = np.stack([np.cos(theta), np.sin(theta)], axis=-1)
    q = np.zeros((c.shape[0], 2))

    load = np.zeros(2) if force is None else np.asarray(force, dtype=np.float64)

    def residual(qq: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        d = np.maximum(2.0 * c + np.einsum("nzk,nk->nz", nvec, qq), 0.0)
        return np.einsum("nz,nzk->nk", stiffness * d**1.5, nvec) - load, d

    for _ in range(max_iter):
        f, d = residual(q)
        h = np.einsum("nz,nzk,nzl->nkl", 1.5 * stiffness * np.sqrt(d), nvec, nvec)
        s = -np.linalg.solve(h, f[..., None])[..., 0]
        step = np.ones(q.shape[0])
        norm0 = np.linalg.norm(f, axis=1)
        for _ls in range(30):
            f1, _ = residual(q + step[:, None] * s)
            worse = np.linalg.norm(f1, axis=1) > norm0
            if not worse.any():
                break
            step[worse] *= 0.5
        q = q + step[:, None] * s
        if np.max(np.abs(step[:, None] * s)) <= tol:
            return q
    raise ConvergenceError("reference Newton iteration did not converge")


@dataclass(frozen=True)
class Setup:
    """Contact angle α [rad], K_n [N/m^1.5], δ_0 [m] and frequencies of a case.

    Attributes
    ----------
    contact_angle : float
        Operating contact angle α under the axial preload [rad].
    stiffness : float
        Combined ball-race contact constant C_k = K_n [N/m^1.5].
    initial_approach : float
        δ_0 = (δ_i + δ_o)/2 of the static axial-load solution [m].
    kinematics : Kinematics
        Signed ring, cage and spin frequencies [Hz] and the number of balls.
    force : ndarray, shape (2,)
        External radial load on the shaft (F_x, F_y) [N].
    """

    contact_angle: float
    stiffness: float
    initial_approach: float
    kinematics: Kinematics
    force: NDArray[np.float64] = field(default_factory=lambda: np.zeros(2))


def setup(case: Case) -> Setup:
    """Derive α, K_n, δ_0 = (δ_i + δ_o)/2 and the kinematics (see module docstring).

    Parameters
    ----------
    case : Case
        A validated case with a ball bearing and an axial preload > 0 [N].

    Returns
    -------
    Setup
        α [rad], K_n [N/m^1.5], δ_0 [m], the kinematics [Hz] and the radial load [N].

    Raises
    ------
    GeometryError
        Not a ball bearing, no axial preload, or a radial load that unloads balls of the
        perfect bearing (:func:`check_static_load_held`).

    Notes
    -----
    δ_0 as in Kim, Choi & Yoon, "Vibration analysis of ball bearings with ball geometric
    imperfections" (seed 001), text after eq. 18; K_n as C_k of eq. 14-15.
    """
    bearing = case.bearing
    op = case.operation
    if not isinstance(bearing, BallBearing):
        raise GeometryError("bearing.type", "the quasi_static_2d model needs a ball bearing")
    if op.axial_load <= 0.0:
        raise GeometryError(
            "operation.axial_load",
            "the quasi_static_2d model needs an axial preload > 0 N to set the initial "
            "deflection (seed 001, text after eq. 18); a bearing without preload, with its "
            'radial play, runs in model = "dynamic" (or "equilibrium" when at least 3 balls '
            "carry the load)",
        )
    alpha, loading = operating_contact_angle(bearing, op)
    if loading is None or bearing.contact_angle is not None:
        loading = axial_loading(bearing, op.axial_load)
    d0 = 0.5 * (loading.inner_approach + loading.outer_approach)
    kn = ball_race_contacts(bearing, alpha).combined_stiffness
    d, dm = bearing.element_diameter, bearing.pitch_diameter
    kin = Kinematics(
        inner=op.inner_speed,
        outer=op.outer_speed,
        cage=float(cage_frequency(op.inner_speed, op.outer_speed, d, dm, alpha)),
        spin=float(ball_spin_frequency(op.inner_speed, op.outer_speed, d, dm, alpha)),
        rotating_ring=op.rotating_ring,
        n_elements=bearing.elements,
    )
    beta = op.radial_load_direction
    force = np.array([op.radial_load * math.cos(beta), op.radial_load * math.sin(beta)])
    st = Setup(alpha, kn, d0, kin, force)
    check_static_load_held(case, st)
    return st


def approaches(
    case: Case,
    st: Setup,
    time: NDArray[np.float64],
    element_projection: ElementProjection = "none",
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """δ_k at x = y = 0 (eq. 10) and ball angles, shape (n, Z) each.

    Parameters
    ----------
    case : Case
        The case (its imperfections).
    st : Setup
        From :func:`setup`.
    time : ndarray, shape (n,)
        Instants [s].
    element_projection : {"none", "radial"}, optional
        ``"radial"`` multiplies the ball deviations by cos α; default ``"none"`` (eq. 10 as
        printed).

    Returns
    -------
    c : ndarray, shape (n, Z)
        δ_k at x = y = 0 [m].
    theta : ndarray, shape (n, Z)
        Ball angles θ_k [rad].

    Notes
    -----
    Kim, Choi & Yoon, "Vibration analysis of ball bearings with ball geometric
    imperfections" (seed 001), eq. 8 and 10-13.
    """
    dev = contact_deviations(case.imperfections, st.kinematics, time)
    ball = dev.ball * (math.cos(st.contact_angle) if element_projection == "radial" else 1.0)
    c = st.initial_approach + 0.5 * (dev.inner + ball - dev.outer)
    return np.ascontiguousarray(c), np.ascontiguousarray(dev.theta)


def solve(
    case: Case,
    time: NDArray[np.float64],
    st: Setup | None = None,
    *,
    element_projection: ElementProjection = "none",
) -> tuple[NDArray[np.float64], NDArray[np.integer[Any]]]:
    """Shaft centre (3, n) [m] (z = 0) and unloaded-ball counts (n,) at ``time``.

    Parameters
    ----------
    case : Case
        The case (its imperfections).
    time : ndarray, shape (n,)
        Instants [s].
    st : Setup, optional
        From :func:`setup`; derived from ``case`` when None.
    element_projection : {"none", "radial"}, optional
        ``"radial"`` multiplies the ball deviations by cos α; default ``"none"``.

    Returns
    -------
    disp : ndarray, shape (3, n)
        Shaft centre (x, y, 0) relative to the outer ring [m].
    unloaded : ndarray of int, shape (n,)
        Balls without load at each instant.

    Raises
    ------
    ContactLossError, ConvergenceError, NumericalError
        When the shaft cannot be held at some instant (the error names it).

    Notes
    -----
    Kim, Choi & Yoon, "Vibration analysis of ball bearings with ball geometric
    imperfections" (seed 001), eq. 10-18 (with the radial load of the module docstring).
    """
    st = setup(case) if st is None else st
    t = np.ascontiguousarray(time, dtype=np.float64)
    src = contact_sources(
        case.imperfections,
        st.kinematics,
        ring_gain=1.0,
        element_gain=math.cos(st.contact_angle) if element_projection == "radial" else 1.0,
        offset=st.initial_approach,
        planar=True,
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
        st.stiffness,
        st.initial_approach,
        MAX_ITER,
        st.force,
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
        cause, when = CAUSES[int(status)], float(t[int(instant)])
        if status == TOO_FEW_LOADED:
            raise ContactLossError(cause, int(instant), when)
        if status == NOT_CONVERGED:
            raise ConvergenceError(cause, int(instant), when)
        raise NumericalError(cause, int(instant), when)
    return disp, unloaded


#: Positions of the balls across one ball pitch at which :func:`check_static_load_held` solves.
_CAGE_POSITIONS = 8


def _unloading_text(op: Operation, worst: int, n_elements: int, cause: str) -> str:
    """Why the planar model refuses a record where balls lose contact (see below)."""
    return (
        f"{op.radial_load:.6g} N {cause} up to {worst} of {n_elements} balls against the "
        f"{op.axial_load:.6g} N axial load: the planar model keeps the contact angle and "
        "approach of the axial load alone, so it cannot follow the rings moving axially "
        '(preload = "spring") or the contact angles changing (preload = "position"); use '
        'model = "dynamic" (either preload)'
    )


def check_static_load_held(case: Case, st: Setup) -> None:
    """Refuse a radial load that unloads balls of the perfect bearing (an input the planar
    model cannot represent; part of :func:`setup`, so ``runout check`` says it too).

    The perfect bearing's shaft position under the radial load is solved in NumPy
    (:func:`solve_reference`, no compiled kernel: ``check`` stays quick) at
    :data:`_CAGE_POSITIONS` positions of the balls across one ball pitch; when a ball carries
    no load at one of them, the loads alone put the case outside the model
    (:func:`check_radial_load_held` explains why).

    Parameters
    ----------
    case : Case
        The case (its bearing and loads; its imperfections are left out).
    st : Setup
        From :func:`setup`.

    Raises
    ------
    GeometryError
        Naming ``operation.radial_load``.
    """
    op = case.operation
    if op.radial_load <= 0.0:
        return
    n_elements = st.kinematics.n_elements
    pitch = 2.0 * math.pi / n_elements
    shift = np.arange(_CAGE_POSITIONS) / _CAGE_POSITIONS
    theta = pitch * (np.arange(n_elements)[None, :] + shift[:, None])
    c = np.full(theta.shape, st.initial_approach)
    try:
        q = solve_reference(
            c, theta, tol=RTOL * st.initial_approach, force=st.force, stiffness=st.stiffness
        )
    except ConvergenceError:  # no static position at all: the run says so, naming the instant
        return
    approach = 2.0 * c + np.cos(theta) * q[:, :1] + np.sin(theta) * q[:, 1:]
    worst = int((approach <= 0.0).sum(axis=1).max())
    if worst:
        text = _unloading_text(op, worst, n_elements, "unloads")
        raise GeometryError("operation.radial_load", text + ", or raise operation.axial_load")


def check_radial_load_held(
    op: Operation, unloaded: NDArray[np.integer[Any]], n_elements: int
) -> None:
    """Refuse a record under which balls lose contact: the planar model cannot be right.

    The planar model keeps the contact angle and the initial approach δ_0 of the axial load
    alone. While every ball stays loaded, a spring and a position preload move the shaft
    alike to first order (the axial and radial motions of a uniform bearing decouple).
    Once balls unload they part: a spring preload lets the rings slide axially until the
    loaded balls reach their groove bottoms, a position preload holds them and the contact
    angles change ball by ball; the planar model follows neither. The loads alone unloading
    a ball is an input the model cannot represent (:func:`check_static_load_held`, in
    :func:`setup`); here the imperfections unload balls at some instants of the record: the
    model cannot follow that state (a :class:`ContactLossError`, as a lost contact of the
    other quasi-static models).

    Parameters
    ----------
    op : Operation
        The loads [N].
    unloaded : ndarray of int, shape (n,)
        Balls without load at each instant.
    n_elements : int
        Number of balls Z.

    Raises
    ------
    ContactLossError
        When a radial load is set and a ball lost contact at some instant.

    Notes
    -----
    Kim, Choi & Yoon, "Vibration analysis of ball bearings with ball geometric
    imperfections" (seed 001), eq. 10 (planar approach at the preload's contact angle).
    """
    worst = int(unloaded.max()) if unloaded.size else 0
    if op.radial_load <= 0.0 or worst == 0:
        return
    instant = int(np.argmax(unloaded))
    cause = _unloading_text(op, worst, n_elements, "with the imperfections unloads")
    raise ContactLossError(cause, instant)


def planar_note(contact_angle: float) -> str:
    """What the planar model (seed 001 eq. 10-17) costs against the 3-D one, in words.

    Parameters
    ----------
    contact_angle : float
        Operating contact angle α [rad].

    Returns
    -------
    str
        A note for the result: the stiffness ratio 1/cos²α [-] and the ball gain cos α [-].
    """
    c = math.cos(contact_angle)
    return (
        "planar model (seed 001 eq. 10-17): the contacts act radially, so under a radial load "
        f"it is 1/cos²α = {1.0 / c**2:.4g} times stiffer than quasi_static_3d, and ball "
        f"deviations pass at cos α = {c:.4g} of the 3-D gain (ring waviness 1:1); "
        "quasi_static_3d takes the contact angle into the force balance"
    )


def run(case: Case) -> RunResult:
    """Run the quasi-static 2-D model (seed 001) on a case.

    Parameters
    ----------
    case : Case
        A validated case with ``[analysis] model = "quasi_static_2d"``, a ball bearing and an
        axial preload.

    Returns
    -------
    RunResult
        Shaft centre relative to the outer ring [m] over the analysis window, the fitted lines
        and the runout figures [m].

    Notes
    -----
    Kim, Choi & Yoon, "Vibration analysis of ball bearings with ball geometric
    imperfections" (seed 001), eq. 8-18.
    """
    st = setup(case)

    def solve_held(
        case: Case, time: NDArray[np.float64], st: Setup
    ) -> tuple[NDArray[np.float64], NDArray[np.integer[Any]]]:
        disp, unloaded = solve(case, time, st)
        check_radial_load_held(case.operation, unloaded, st.kinematics.n_elements)
        return disp, unloaded

    return run_quasi_static(
        case,
        st,
        solve_held,
        model=MODEL,
        planar=True,
        description=planar_note(st.contact_angle),
        approach_m=st.initial_approach,
    )
