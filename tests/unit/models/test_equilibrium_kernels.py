"""The equilibrium kernels against the NumPy implementation they replaced.

:mod:`runout.models._equilibrium_kernels` evaluates the ball balance and the ring force of the
Jones-Harris model (seed 001 eq. 1-6) ball by ball in Numba. The reference below is the
vectorised NumPy implementation the model used before (complex-step derivatives, a 2x2 Newton
per ball, the lift-off fixed point, the restarts and the friction continuation), kept verbatim:
the kernel must reproduce it to round-off, state by state, including the ring Jacobian.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.typing import NDArray

from runout.base.errors import ConvergenceError
from runout.geometry.bearing import BallBearing, Operation
from runout.geometry.contact import ball_race_contacts
from runout.models import _equilibrium_kernels as kern
from runout.models import equilibrium as eq
from runout.models.equilibrium import ball_speeds

_H = 1e-30
_BALL_ITER = 50


# --------------------------------------------------------------------------------------------
# NumPy reference (the model's implementation before the kernel)
# --------------------------------------------------------------------------------------------
@dataclass
class _Params:
    """Constants of the per-ball equations (as ``equilibrium._Params``)."""

    ball_diameter: float
    pitch_diameter: float
    ri0: float  # (f_i - 0.5) D
    ro0: float  # (f_o - 0.5) D
    f_i: float
    mass: float
    inertia: float
    inner: float  # [rad/s]
    outer: float
    control: str
    lam_i: float
    lam_o: float
    # Hertz constants linearised in the contact angle about alpha_c: K = k0 + k1 (α − α_c)
    ki0: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))
    ki1: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))
    ai_c: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))
    ko0: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))
    ko1: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))
    ao_c: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))
    speed_on: bool = True


def _hertz(delta: Any, k: Any) -> Any:
    """K δ^1.5 for δ > 0 (real part), else 0; complex-safe."""
    pos = np.real(delta) > 0.0
    safe = np.where(pos, delta, 1.0)
    return np.where(pos, k * safe * np.sqrt(safe), 0.0)


def _ball_state(x1: Any, x2: Any, a1: Any, a2: Any, p: _Params) -> dict[str, Any]:
    """Everything about each ball at ball-centre (x1, x2) and groove-centre (a1, a2) [m]."""
    ro = np.sqrt(x1 * x1 + x2 * x2)
    e1, e2 = a1 - x1, a2 - x2
    ri = np.sqrt(e1 * e1 + e2 * e2)
    cos_o, sin_o = x2 / ro, x1 / ro
    cos_i, sin_i = e2 / ri, e1 / ri
    alpha_o = np.arctan(x1 / x2)
    alpha_i = np.arctan(e1 / e2)
    d_o = ro - p.ro0
    d_i = ri - p.ri0
    k_i = p.ki0 + p.ki1 * (alpha_i - p.ai_c)
    k_o = p.ko0 + p.ko1 * (alpha_o - p.ao_c)
    q_i = _hertz(d_i, k_i)
    q_o = _hertz(d_o, k_o)
    gamma = p.ball_diameter / p.pitch_diameter
    if p.speed_on:
        wm, wr, sb, _ = ball_speeds(cos_i, sin_i, cos_o, sin_o, gamma, p.inner, p.outer, p.control)
        fc = 0.5 * p.mass * p.pitch_diameter * wm * wm
        mg = p.inertia * wr * wm * sb
    else:
        wm = wr = 0.0 * x1
        fc = mg = 0.0 * x1
    md = mg / p.ball_diameter
    g1 = q_i * sin_i - q_o * sin_o - md * (p.lam_i * cos_i - p.lam_o * cos_o)
    g2 = q_i * cos_i - q_o * cos_o + md * (p.lam_i * sin_i - p.lam_o * sin_o) + fc
    pa = q_i * sin_i - p.lam_i * md * cos_i
    pr = q_i * cos_i + p.lam_i * md * sin_i
    return {
        "g1": g1,
        "g2": g2,
        "pa": pa,
        "pr": pr,
        "mg": mg,
        "fc": fc,
        "q_i": q_i,
        "q_o": q_o,
        "d_i": d_i,
        "d_o": d_o,
        "alpha_i": alpha_i,
        "alpha_o": alpha_o,
        "omega_m": wm,
        "omega_r": wr,
    }


def _residual_and_jacobian(
    x: NDArray[np.float64], a: NDArray[np.float64], p: _Params
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """g (Z, 2) and ∂g/∂X (Z, 2, 2) by complex step."""
    g = np.empty((x.shape[0], 2))
    jac = np.empty((x.shape[0], 2, 2))
    for k in range(2):
        xc = x.astype(complex)
        xc[:, k] += 1j * _H
        s = _ball_state(xc[:, 0], xc[:, 1], a[:, 0], a[:, 1], p)
        jac[:, 0, k] = s["g1"].imag / _H
        jac[:, 1, k] = s["g2"].imag / _H
        if k == 0:
            g[:, 0], g[:, 1] = s["g1"].real, s["g2"].real
    return g, jac


def _lifted_off(
    a: NDArray[np.float64], p: _Params
) -> tuple[NDArray[np.bool_], NDArray[np.float64]]:
    """Balls whose inner contact opens at speed (module Notes), for groove centres ``a``.

    With Q_i = 0 the outer contact alone balances the centrifugal force and the gyroscopic
    friction, which fixes the ball centre X* (a short fixed point: the ball speeds depend on
    the angles). The ball carries inner-race load only if the inner groove then still
    overlaps it, δ_i(X*) > 0; this is the limit Q_i → 0 of the loaded equations, so the
    switch is continuous in the ring forces.
    """
    gamma = p.ball_diameter / p.pitch_diameter
    ao = np.arctan(a[:, 0] / a[:, 1])
    ai = ao.copy()
    d_i = np.zeros(a.shape[0])
    x = np.zeros_like(a)
    for _ in range(_BALL_ITER):
        ci, si, co, so = np.cos(ai), np.sin(ai), np.cos(ao), np.sin(ao)
        wm, wr, sb, _ = ball_speeds(ci, si, co, so, gamma, p.inner, p.outer, p.control)
        fc = 0.5 * p.mass * p.pitch_diameter * wm * wm
        md = p.inertia * wr * wm * sb / p.ball_diameter
        v = md * (p.lam_i * ci - p.lam_o * co)
        w = md * (p.lam_i * si - p.lam_o * so) + fc
        q_o = np.hypot(v, w)
        ao_new = np.arctan2(-v, w)
        k_o = np.maximum(p.ko0 + p.ko1 * (ao_new - p.ao_c), 1e-300)
        r = p.ro0 + (q_o / k_o) ** (2.0 / 3.0)
        x = np.stack([r * np.sin(ao_new), r * np.cos(ao_new)], axis=1)
        e1, e2 = a[:, 0] - x[:, 0], a[:, 1] - x[:, 1]
        ai_new = np.arctan(e1 / e2)
        d_i = np.hypot(e1, e2) - p.ri0
        moved = max(float(np.abs(ao_new - ao).max()), float(np.abs(ai_new - ai).max()))
        ao, ai = ao_new, ai_new
        if moved <= 1e-14:
            break
    return np.asarray(d_i <= 0.0), x


def _approaches(
    x: NDArray[np.float64], a: NDArray[np.float64], p: _Params
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """δ_i, δ_o at ball centres x and groove centres a [m]."""
    d_o = np.hypot(x[:, 0], x[:, 1]) - p.ro0
    d_i = np.hypot(a[:, 0] - x[:, 0], a[:, 1] - x[:, 1]) - p.ri0
    return d_i, d_o


def _ball_newton(
    xs: NDArray[np.float64], aa: NDArray[np.float64], sub: _Params, tol: float
) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """2×2 Newton on eq. 3-4 of loaded balls from ``xs``; returns X and the converged mask."""
    xs = xs.copy()
    done = np.zeros(xs.shape[0], dtype=bool)
    for _ in range(_BALL_ITER):
        g, jac = _residual_and_jacobian(xs, aa, sub)
        det = jac[:, 0, 0] * jac[:, 1, 1] - jac[:, 0, 1] * jac[:, 1, 0]
        ok = np.abs(det) > 0.0
        det = np.where(ok, det, 1.0)
        s0 = -(jac[:, 1, 1] * g[:, 0] - jac[:, 0, 1] * g[:, 1]) / det
        s1 = -(jac[:, 0, 0] * g[:, 1] - jac[:, 1, 0] * g[:, 0]) / det
        step = np.where(ok[:, None], np.stack([s0, s1], axis=1), 0.0)
        # keep both approaches from jumping far past zero in one step
        big = np.abs(step).max(axis=1)
        limit = 0.25 * (sub.ri0 + sub.ro0) * 0.05
        factor = np.minimum(1.0, limit / np.maximum(big, 1e-300))
        d_i, d_o = _approaches(xs, aa, sub)
        for _ in range(60):
            ti, to = _approaches(xs + factor[:, None] * step, aa, sub)
            shrink = (ti < 0.1 * d_i) | (to < 0.1 * d_o)
            if not shrink.any():
                break
            factor = np.where(shrink, 0.5 * factor, factor)
        xs = xs + factor[:, None] * step
        done = ok & (big <= tol)  # the full Newton step, not the shortened one
        if np.all(done):
            break
    return xs, done


def _friction_continuation(
    x0: NDArray[np.float64], aa: NDArray[np.float64], sub: _Params, tol: float
) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """Ball Newton along the gyroscopic friction, λ → s·λ with s from 0 to 1.

    The last resort of :func:`_solve_balls`: near lift-off under inner-race control the
    friction on the inner race stays finite while that contact's stiffness vanishes, and
    Newton from the usual starts can stall. Without friction (s = 0) the balance is the
    well-posed centrifugal one; the solution moves continuously with s, so each step starts
    next to its answer (step halved on failure, down to 1/1024).
    """
    q = _sub(sub, np.arange(x0.shape[0]))
    q.lam_i = q.lam_o = 0.0
    x, done = _ball_newton(x0, aa, q, tol)
    s, ds = 0.0, 0.25
    while done.all() and s < 1.0:
        t = min(1.0, s + ds)
        q.lam_i, q.lam_o = t * sub.lam_i, t * sub.lam_o
        xt, ok = _ball_newton(x, aa, q, tol)
        if ok.all():
            x, s, ds = xt, t, min(2.0 * ds, 0.5)
        elif ds > 1.0 / 1024.0:
            ds *= 0.5
        else:
            return xt, ok
    return x, done


def _solve_balls(
    a: NDArray[np.float64], x0: NDArray[np.float64], p: _Params, scale: float
) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """Newton solve of eq. 3-4 for every loaded ball; returns X (Z, 2) and the loaded mask.

    Unloaded balls (inner groove centre within A of the outer one, or, at speed, lifted off
    the inner race by their centrifugal force: :func:`_lifted_off`) are placed on the outer
    groove bottom (see module Notes). For a loaded ball both contacts stay closed along the
    iteration (a step may shrink an approach by at most 90 %): the Hertz law's vanishing
    stiffness at zero approach would otherwise throw Newton across the contact opening. A
    ball that does not converge from ``x0`` is restarted from its outer-contact-only position
    (where the inner groove overlaps it: the iteration then unloads the inner contact), and
    then by continuation in the gyroscopic friction (:func:`_friction_continuation`).
    """
    x = x0.copy()
    if p.speed_on:
        lifted, x_star = _lifted_off(a, p)
        loaded = ~lifted
        x_star = x_star[loaded]
    else:
        loaded = np.hypot(a[:, 0], a[:, 1]) > p.ri0 + p.ro0
        x_star = x[loaded]
    idx = np.flatnonzero(loaded)
    if idx.size:
        sub = _sub(p, idx)
        xs, aa = x[idx], a[idx]
        # start with both contacts closed (the previous state may have had one open)
        d_i, d_o = _approaches(xs, aa, sub)
        bad = (d_i <= 0.0) | (d_o <= 0.0)
        if bad.any():
            if p.speed_on:  # the inner groove overlaps X*: both contacts closed there
                xs[bad] = x_star[bad]
            else:
                xs[bad] = _start(aa[bad], _sub(sub, np.flatnonzero(bad)))
        tol = 1e-13 * scale
        xs, done = _ball_newton(xs, aa, sub, tol)
        if p.speed_on and not done.all():
            redo = np.flatnonzero(~done)
            xs[redo], done[redo] = _ball_newton(x_star[redo], aa[redo], _sub(sub, redo), tol)
        if p.speed_on and not done.all():
            redo = np.flatnonzero(~done)
            start = _start(aa[redo], _sub(sub, redo))
            xs[redo], done[redo] = _friction_continuation(start, aa[redo], _sub(sub, redo), tol)
        for side in (1.0, -1.0):
            if p.speed_on and not done.all():
                redo = np.flatnonzero(~done)
                start = _closed_start(aa[redo], _sub(sub, redo), side)
                xs[redo], done[redo] = _ball_newton(start, aa[redo], _sub(sub, redo), tol)
        if not done.all():
            raise ConvergenceError("ball equilibrium (seed 001 eq. 3-6) did not converge")
        x[idx] = xs
    # unloaded balls: on the outer groove bottom
    out = np.flatnonzero(~loaded)
    if out.size:
        x[out, 0] = 0.0
        x[out, 1] = p.ro0
    return x, loaded


def _sub(p: _Params, idx: NDArray[np.int64]) -> _Params:
    """The parameters of a subset of balls."""
    q = _Params(**{k: v for k, v in p.__dict__.items()})
    for name in ("ki0", "ki1", "ai_c", "ko0", "ko1", "ao_c"):
        setattr(q, name, getattr(p, name)[idx])
    return q


def _start(a: NDArray[np.float64], p: _Params) -> NDArray[np.float64]:
    """Zero-speed ball centre: on the line between the groove centres, Hertz split."""
    dist = np.hypot(a[:, 0], a[:, 1])
    s = np.maximum(dist - p.ri0 - p.ro0, 0.0)
    ci = p.ki0 ** (-2.0 / 3.0)
    co = p.ko0 ** (-2.0 / 3.0)
    d_o = s * co / (ci + co)
    r = p.ro0 + d_o
    return np.stack([a[:, 0] / dist * r, a[:, 1] / dist * r], axis=1)


def _closed_start(a: NDArray[np.float64], p: _Params, side: float) -> NDArray[np.float64]:
    """Both contacts closed by the centrifugal approach, off the line of groove centres.

    The last start of :func:`_solve_balls`, for a ball with no rest overlap that only the
    gyroscopic friction presses onto the inner race: X on |X| = ℜ_o⁰ + δ, |A − X| = ℜ_i⁰ + δ,
    δ = (F_c/K_o)^(2/3) at the orbit speed of the free contact angle, on side ``side`` of the
    line of groove centres.
    """
    dist = np.hypot(a[:, 0], a[:, 1])
    u1, u2 = a[:, 0] / dist, a[:, 1] / dist
    gamma = p.ball_diameter / p.pitch_diameter
    wm, _, _, _ = ball_speeds(u2, u1, u2, u1, gamma, p.inner, p.outer, p.control)
    fc = 0.5 * p.mass * p.pitch_diameter * wm * wm
    e = np.maximum((fc / np.maximum(p.ko0, 1e-300)) ** (2.0 / 3.0), 1e-9 * p.ball_diameter)
    r_o, r_i = p.ro0 + e, p.ri0 + e
    l_ = (dist * dist + r_o * r_o - r_i * r_i) / (2.0 * dist)
    h = side * np.sqrt(np.maximum(r_o * r_o - l_ * l_, 0.0))
    return np.stack([l_ * u1 + h * u2, l_ * u2 - h * u1], axis=1)


def _local_derivatives(
    x: NDArray[np.float64], a: NDArray[np.float64], p: _Params, loaded: NDArray[np.bool_]
) -> tuple[dict[str, Any], NDArray[np.float64]]:
    """Ball state and the total derivative of (P_a, P_r, M_g) w.r.t. (A_1, A_2): (Z, 3, 2)."""
    z = x.shape[0]
    dg_dx = np.empty((z, 2, 2))
    dg_da = np.empty((z, 2, 2))
    dp_dx = np.empty((z, 3, 2))
    dp_da = np.empty((z, 3, 2))
    state: dict[str, Any] = {}
    for which, dg, dp in (("x", dg_dx, dp_dx), ("a", dg_da, dp_da)):
        for k in range(2):
            xc = x.astype(complex)
            ac = a.astype(complex)
            (xc if which == "x" else ac)[:, k] += 1j * _H
            s = _ball_state(xc[:, 0], xc[:, 1], ac[:, 0], ac[:, 1], p)
            dg[:, 0, k] = np.imag(s["g1"]) / _H
            dg[:, 1, k] = np.imag(s["g2"]) / _H
            dp[:, 0, k] = np.imag(s["pa"]) / _H
            dp[:, 1, k] = np.imag(s["pr"]) / _H
            dp[:, 2, k] = np.imag(s["mg"] + 0.0 * xc[:, 0]) / _H
            if not state:
                state = {key: np.real(v + 0.0 * xc[:, 0]) for key, v in s.items()}
    # unloaded balls exert nothing on the inner ring: they contribute nothing
    free = ~loaded
    dg_dx[free] = np.eye(2)
    dg_da[free] = 0.0
    total = dp_da - np.einsum("zij,zjk->zik", dp_dx, np.linalg.solve(dg_dx, dg_da))
    return state, total


def reference_forces(
    ring: eq._Ring, q: NDArray[np.float64], x0: NDArray[np.float64] | None
) -> tuple[NDArray[np.float64], NDArray[np.float64], dict[str, Any], NDArray[np.bool_], Any]:
    """The ring force, Jacobian, states, loaded mask and ball centres of the NumPy code."""
    p = ring.p
    a = ring.groove_centres(q)
    start = _start(a, p) if x0 is None else x0  # type: ignore[arg-type]
    x, loaded = _solve_balls(a, start, p, ring.a)  # type: ignore[arg-type]
    state, dp = _local_derivatives(x, a, p, loaded)  # type: ignore[arg-type]
    pa, pr = state["pa"], state["pr"]
    pm = pa * ring.rad_i + p.lam_i * p.f_i * state["mg"]
    pa = np.where(loaded, pa, 0.0)
    pr = np.where(loaded, pr, 0.0)
    pm = np.where(loaded, pm, 0.0)
    cp, sp = ring.cos_psi, ring.sin_psi
    force = np.array(
        [pa.sum(), (pr * cp).sum(), (pr * sp).sum(), (pm * sp).sum(), -(pm * cp).sum()]
    )
    dpm = dp[:, 0, :] * ring.rad_i + p.lam_i * p.f_i * dp[:, 2, :]
    local = np.stack([dp[:, 0, :], dp[:, 1, :], dpm], axis=1)
    local[~loaded] = 0.0
    z = cp.size
    c = np.zeros((z, 5, 3))
    c[:, 0, 0] = 1.0
    c[:, 1, 1], c[:, 2, 1] = cp, sp
    c[:, 3, 2], c[:, 4, 2] = sp, -cp
    b = np.zeros((z, 2, 5))
    b[:, 0, 0] = 1.0
    b[:, 0, 3], b[:, 0, 4] = ring.rad_i * sp, -ring.rad_i * cp
    b[:, 1, 1], b[:, 1, 2] = cp, sp
    jac = np.einsum("zij,zjk,zkl->il", c, local, b)
    return force, jac, state, loaded, x


# --------------------------------------------------------------------------------------------
# comparisons
# --------------------------------------------------------------------------------------------
def kim(z: int = 10, clearance: float = 5e-6) -> BallBearing:
    return BallBearing(z, 1.5875e-3, 9.1e-3, 0.529, 0.535, clearance)


#: (bearing, operation, race control): at rest, at speed under each race control, a pure
#: moment (contact angles of both signs), a ball lifted off at speed, a ball near lift-off
#: under inner-race control (friction continuation).
CASES = {
    "axial_static": (kim(), Operation("inner", 0.0, axial_load=60.68), "outer"),
    "kim_7200rpm": (kim(), Operation("inner", 120.0, axial_load=60.68), "outer"),
    "combined_inner_control": (
        kim(),
        Operation("inner", 300.0, axial_load=40.0, radial_load=30.0, moment_load=0.03),
        "inner",
    ),
    "combined_no_friction": (
        kim(12),
        Operation("outer", 500.0, axial_load=40.0, radial_load=50.0, radial_load_direction=0.3),
        "none",
    ),
    "pure_moment_static": (
        kim(),
        Operation("inner", 0.0, moment_load=0.1, moment_load_direction=0.4),
        "outer",
    ),
    "lifted_off": (
        kim(11),
        Operation(
            "outer",
            1246.9122519966918,
            axial_load=7.209074334506057,
            radial_load=49.52926880361335,
            radial_load_direction=1.0331056334573563,
            moment_load=0.03751469964966419,
            moment_load_direction=1.989115685977736,
        ),
        "outer",
    ),
    "near_lift_off_inner_control": (
        kim(),
        Operation(
            "inner",
            484.88,
            axial_load=20.18,
            radial_load=49.16,
            radial_load_direction=4.717,
            moment_load=0.0593,
            moment_load_direction=5.717,
        ),
        "inner",
    ),
}


def _ring_at_solution(name: str) -> tuple[eq._Ring, eq.EquilibriumSolution]:
    b, op, control = CASES[name]
    sol = eq.solve_equilibrium(b, op, race_control=control)
    ring = eq._Ring(b, op, control, speed_on=op.speed != 0.0)
    ring.set_angles(sol.inner_contact_angle, sol.outer_contact_angle)
    return ring, sol


def _assert_forces_agree(ring: eq._Ring, q: NDArray[np.float64], have_x: bool) -> None:
    x0 = ring.x.copy() if have_x else None
    ring.have_x = have_x
    try:
        want = reference_forces(ring, q, x0)
    except ConvergenceError:
        with pytest.raises(ConvergenceError):
            ring.forces(q)
        return
    force, jac, state, loaded = ring.forces(q)
    assert np.array_equal(loaded, want[3])
    np.testing.assert_allclose(ring.x, want[4], rtol=1e-13, atol=1e-13 * ring.a)
    f_scale = np.abs(want[0]).max() + 1e-12
    assert np.abs(force - want[0]).max() <= 1e-11 * f_scale
    # rows of the stiffness matrix carry N/m and N m/rad: compare each to its own size
    row = np.abs(want[1]).max(axis=1, keepdims=True) + 1e-300
    assert (np.abs(jac - want[1]) / row).max() <= 1e-9
    # the ball residuals g1, g2 are round-off of the ball loads: compare them on that scale
    loads = np.abs(np.real(np.stack([want[2]["q_i"], want[2]["q_o"]]))).max()
    for name in kern.STATE_NAMES:
        ref = np.real(np.broadcast_to(want[2][name], loaded.shape))
        scale = loads if name in ("g1", "g2") else np.abs(ref).max()
        assert np.abs(state[name] - ref).max() <= 1e-11 * scale + 1e-300, name


@pytest.mark.parametrize("name", sorted(CASES))
def test_ring_forces_match_numpy_at_the_solution(name: str) -> None:
    ring, sol = _ring_at_solution(name)
    _assert_forces_agree(ring, sol.displacement, have_x=False)
    # and again from the converged ball centres (the ring Newton's warm start)
    _assert_forces_agree(ring, sol.displacement, have_x=True)


@settings(max_examples=40, deadline=None)
@given(
    name=st.sampled_from(sorted(CASES)),
    step=st.lists(st.floats(-1.0, 1.0), min_size=5, max_size=5),
    size=st.floats(1e-3, 0.3),
    warm=st.booleans(),
)
def test_ring_forces_match_numpy_near_the_solution(
    name: str, step: list[float], size: float, warm: bool
) -> None:
    """Property: kernel = NumPy reference for ring displacements around each solution."""
    ring, sol = _ring_at_solution(name)
    q = sol.displacement
    lin = np.array([1.0, 1.0, 1.0, 1.0 / ring.rad_i, 1.0 / ring.rad_i])
    # a step of `size` times the largest displacement component, tilts via the ring radius
    amp = size * float(np.abs(q / lin).max())
    trial = q + amp * np.asarray(step) * lin
    if warm:
        ring.forces(q)
    _assert_forces_agree(ring, trial, have_x=warm)


@pytest.mark.parametrize("name", sorted(CASES))
def test_ball_state_derivatives_equal_complex_step(name: str) -> None:
    """The kernel's forward-mode derivatives of (g1, g2, P_a, P_r, M_g) along X_1, X_2, A_1,
    A_2 equal the reference's complex-step ones, and its values the reference's, per ball."""
    ring, sol = _ring_at_solution(name)
    ring.forces(sol.displacement)  # converged ball centres in ring.x
    a = ring.groove_centres(sol.displacement)
    x = ring.x.copy()
    p = ring.p
    outputs = ("g1", "g2", "pa", "pr", "mg")
    for k in range(4):
        seed = np.zeros(4)
        seed[k] = 1.0
        step = 1j * _H * seed
        ref = _ball_state(  # type: ignore[arg-type]
            x[:, 0] + step[0], x[:, 1] + step[1], a[:, 0] + step[2], a[:, 1] + step[3], p
        )
        loads = np.abs(np.real(np.stack([ref["q_i"], ref["q_o"]]))).max()
        for j in range(x.shape[0]):
            got = kern._ball_state(
                x[j, 0], x[j, 1], a[j, 0], a[j, 1], *seed,
                p.ki0[j], p.ki1[j], p.ai_c[j], p.ko0[j], p.ko1[j], p.ao_c[j],
                ring.cst, p.lam_i, p.lam_o, p.speed_on,
            )  # fmt: skip
            for r, state in enumerate(kern.STATE_NAMES):
                want = np.real(np.broadcast_to(ref[state], x.shape[:1])[j])
                # on the bearing's scale of that quantity (the residuals: of the ball loads);
                # the reference's real parts carry O(step²) terms of the complex products
                scale = loads if state in ("g1", "g2") else np.abs(np.real(ref[state])).max()
                assert abs(got[r] - want) <= 1e-12 * scale + 1e-300, (state, j)
            for r, out in enumerate(outputs):
                want = np.imag(np.broadcast_to(ref[out], x.shape[:1])[j]) / _H
                # derivatives of loads [N] along a displacement [m]: relative to the ball's
                # largest derivative of this direction (round-off of the chain rule)
                size = max(abs(np.imag(ref[o][j]) / _H) for o in outputs[:4]) + 1e-300
                assert abs(got[14 + r] - want) <= 1e-9 * size, (out, j, k)


def _ball_table(ring: eq._Ring) -> NDArray[np.float64]:
    """The kernels' ball table of ``ring`` (rows B_*: Hertz constants, azimuths)."""
    p = ring.p
    return kern.ball_table(p.ki0, p.ki1, p.ai_c, p.ko0, p.ko1, p.ao_c, ring.cos_psi, ring.sin_psi)


@pytest.mark.parametrize("name", ["kim_7200rpm", "lifted_off", "near_lift_off_inner_control"])
def test_lift_off_fixed_point_matches_numpy(name: str) -> None:
    ring, sol = _ring_at_solution(name)
    a = ring.groove_centres(sol.displacement)
    lifted, x_star = _lifted_off(a, ring.p)  # type: ignore[arg-type]
    got_x = np.empty_like(a)
    got_lifted = np.empty(a.shape[0], dtype=np.bool_)
    work = np.empty((3, a.shape[0]))
    args = (ring.cst, ring.p.lam_i, ring.p.lam_o, got_x, got_lifted, work)
    kern._lifted_off(a, _ball_table(ring), *args)
    assert np.array_equal(got_lifted, lifted)
    np.testing.assert_allclose(got_x, x_star, rtol=1e-14, atol=1e-14 * ring.a)
    if name == "lifted_off":
        assert lifted.any()


def test_friction_continuation_matches_numpy() -> None:
    ring, sol = _ring_at_solution("near_lift_off_inner_control")
    p = ring.p
    a = ring.groove_centres(sol.displacement)
    every = np.ones(a.shape[0], dtype=np.bool_)
    start = _start(a, p)  # type: ignore[arg-type]
    tol = 1e-13 * ring.a
    want_x, want_done = _friction_continuation(start, a, p, tol)  # type: ignore[arg-type]
    xs = start.copy()
    done = np.empty(every.size, dtype=np.bool_)
    kern._friction_continuation(
        xs, a, every, _ball_table(ring), ring.cst, p.lam_i, p.lam_o, True, tol, done
    )
    assert np.array_equal(done, want_done)
    # a ball without rest overlap has no loaded state without friction (s = 0): there the
    # continuation cannot start, and _closed_start takes over (test_equilibrium_robust.py)
    overlap = np.hypot(a[:, 0], a[:, 1]) > p.ri0 + p.ro0
    assert done[overlap].all()
    np.testing.assert_allclose(xs, want_x, rtol=1e-13, atol=1e-13 * ring.a)


def test_hertz_constants_equal_the_per_angle_solution() -> None:
    b = kim()
    angles = np.array([0.0, 1e-9, 0.2, 0.3268, 0.9, 1.4, 0.5 * math.pi - 1e-6])
    k_i, k_o = eq._hertz_constants(b, angles)
    for alpha, ki, ko in zip(angles, k_i, k_o, strict=True):
        c = ball_race_contacts(b, float(alpha))
        # vectorised and scalar NumPy ufuncs may round differently in the last bit
        assert ki == pytest.approx(c.inner.stiffness, rel=4e-16)
        assert ko == pytest.approx(c.outer.stiffness, rel=4e-16)


def _rotation(phi: float) -> NDArray[np.float64]:
    """Rotation by phi of (x, y) and of (tilt_x, tilt_y); the axial DOF unchanged."""
    c, s = math.cos(phi), math.sin(phi)
    r = np.eye(5)
    r[1:3, 1:3] = r[3:5, 3:5] = [[c, -s], [s, c]]
    return r


@settings(max_examples=30, deadline=None)
@given(
    z=st.integers(7, 13),
    speed=st.sampled_from([0.0, 120.0, 900.0]),
    control=st.sampled_from(["outer", "inner", "none"]),
    radial=st.floats(0.0, 1.0),
    direction=st.floats(0.0, 6.3),
    tilt=st.floats(-1.0, 1.0),
    shift=st.integers(1, 12),
)
def test_ring_forces_turn_with_the_bearing(
    z: int, speed: float, control: str, radial: float, direction: float, tilt: float, shift: int
) -> None:
    """Invariant: turning the ring displacement by k ball pitches turns force and stiffness."""
    b = kim(z)
    ring = eq._Ring(b, Operation("inner", speed, axial_load=30.0), control, speed_on=speed > 0)
    alpha = np.full(z, 0.3)  # the same Hertz linearisation for every ball
    ring.set_angles(alpha, alpha)
    q = np.array(
        [
            2e-6,
            0.5e-6 * radial * math.cos(direction),
            0.5e-6 * radial * math.sin(direction),
            1e-4 * tilt * math.cos(direction + 1.0),
            1e-4 * tilt * math.sin(direction + 1.0),
        ]
    )
    rot = _rotation(2.0 * math.pi * shift / z)
    ring.have_x = False
    force, jac, _, loaded = ring.forces(q)
    ring.have_x = False
    force_r, jac_r, _, loaded_r = ring.forces(rot @ q)
    assert np.array_equal(np.roll(loaded, shift), loaded_r)
    scale = np.abs(force).max()
    assert np.abs(force_r - rot @ force).max() <= 1e-9 * scale
    want = rot @ jac @ rot.T
    row = np.abs(want).max(axis=1, keepdims=True)
    assert (np.abs(jac_r - want) / row).max() <= 1e-8


# --------------------------------------------------------------------------------------------
# cold starts near lift-off under inner-race control
# --------------------------------------------------------------------------------------------
def _cold_ring(b: BallBearing, op: Operation, sol: eq.EquilibriumSolution, ulps: int) -> eq._Ring:
    """A fresh ring at the solution's angles, Hertz constants moved by ``ulps`` units."""
    ring = eq._Ring(b, op, "inner", speed_on=True)
    ring.set_angles(sol.inner_contact_angle, sol.outer_contact_angle)
    for name in ("ki0", "ki1", "ko0", "ko1"):
        k = getattr(ring.p, name)
        for _ in range(abs(ulps)):
            k = np.nextafter(k, math.copysign(np.inf, ulps))
        setattr(ring.p, name, k)
    return ring


@pytest.mark.parametrize("ulps", [-4, -2, -1, 0, 1, 2, 4])
def test_cold_start_converges_near_lift_off_with_perturbed_constants(ulps: int) -> None:
    """A ball with no rest overlap, pressed onto the inner race by the friction alone.

    At this solution ball 4's groove centres are within ℜ_i⁰ + ℜ_o⁰ of each other by some
    1e-5 D or less: its zero-speed start has an open contact, X* leaves the groove and the
    friction continuation has no loaded state to start from; whether the solve converged
    hung on the last bits of the Hertz constants. The kernel must converge from a cold start
    whatever they are, and agree with the reference.
    """
    b, op, _ = CASES["near_lift_off_inner_control"]
    sol = eq.solve_equilibrium(b, op, race_control="inner")
    ring = _cold_ring(b, op, sol, ulps)
    _assert_forces_agree(ring, sol.displacement, have_x=False)
    ring.have_x = False
    _, _, state, loaded = ring.forces(sol.displacement)
    assert loaded.all() and (state["d_i"] > 0.0).all()


@settings(max_examples=25, deadline=None)
@given(
    speed=st.floats(300.0, 700.0),
    axial=st.floats(5.0, 40.0),
    radial=st.floats(10.0, 70.0),
    radial_angle=st.floats(0.0, 6.3),
    moment=st.floats(0.0, 0.08),
    moment_angle=st.floats(0.0, 6.3),
    ulps=st.integers(-4, 4),
)
def test_cold_start_converges_at_solutions_under_inner_control(
    speed: float,
    axial: float,
    radial: float,
    radial_angle: float,
    moment: float,
    moment_angle: float,
    ulps: int,
) -> None:
    """Property: a fresh ring converges at the solution of operating points near lift-off.

    Combined loads at high speed under inner-race control leave some balls with no rest
    overlap, held on the inner race by the gyroscopic friction (before the closed start, a
    cold start failed at over a third of such points); the Hertz constants are perturbed by
    a few ulp, as another evaluation of the elliptic integrals would.
    """
    b = kim()
    op = Operation(
        "inner",
        speed,
        axial_load=axial,
        radial_load=radial,
        radial_load_direction=radial_angle,
        moment_load=moment,
        moment_load_direction=moment_angle,
    )
    try:
        sol = eq.solve_equilibrium(b, op, race_control="inner")
    except ConvergenceError:
        return  # no equilibrium to start from
    ring = _cold_ring(b, op, sol, ulps)
    ring.have_x = False
    ring.forces(sol.displacement)
    ring = _cold_ring(b, op, sol, ulps)
    _assert_forces_agree(ring, sol.displacement, have_x=False)


#: Operating points (Kim bearing, inner-race control) where the ball solve failed before the
#: closed start: solve_equilibrium raised ConvergenceError, each at a ball with no rest overlap.
STALLED = [
    (
        404.6448536997266,
        15.447190019494316,
        58.85354443565682,
        0.5790704354511105,
        0.04800804207725232,
        4.589931318914306,
    ),
    (
        687.0791930747273,
        6.539569221973897,
        62.961559170562026,
        3.524076281532722,
        0.05709112247670378,
        1.2133483448878262,
    ),
]


@pytest.mark.parametrize("point", STALLED)
def test_solve_converges_where_the_friction_alone_loads_a_ball(point: tuple[float, ...]) -> None:
    speed, axial, radial, radial_angle, moment, moment_angle = point
    b = kim()
    op = Operation(
        "inner",
        speed,
        axial_load=axial,
        radial_load=radial,
        radial_load_direction=radial_angle,
        moment_load=moment,
        moment_load_direction=moment_angle,
    )
    sol = eq.solve_equilibrium(b, op, race_control="inner")
    ring = _cold_ring(b, op, sol, 0)
    a = ring.groove_centres(sol.displacement)
    gap = np.hypot(a[:, 0], a[:, 1]) <= ring.ri0 + ring.ro0
    _, _, state, loaded = ring.forces(sol.displacement)
    assert (loaded & gap).any()  # a ball held on the inner race by the friction alone
    assert (state["d_i"][loaded] > 0.0).all()
    _assert_forces_agree(_cold_ring(b, op, sol, 0), sol.displacement, have_x=False)
