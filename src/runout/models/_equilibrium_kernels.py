r"""Numba kernels of the Jones–Harris equilibrium: the ball balance and the ring force.

:mod:`runout.models.equilibrium` describes the physics (Kim, Choi & Yoon, seed 001 §2.1,
eq. 1-9; Harris, *Rolling Bearing Analysis*); this module evaluates, for one ring
displacement, what its ring Newton needs: every ball's equilibrium (seed 001 eq. 3-6, a 2×2
Newton per ball, the lift-off test at speed, the restarts), the ring force (eq. 1-2) and its
Jacobian by implicit differentiation of the converged ball states. The steps are those of the
vectorised NumPy implementation it replaced, ball by ball and in the same order (the same
global stopping rules, the same step limits), so that the results agree to round-off; the unit
tests keep that NumPy implementation as the reference.

Derivatives are forward-mode derivatives written out by the chain rule (:func:`_ball_state`
carries each quantity with its derivative along one direction of (X, A)), exact to round-off
like the complex-step derivatives of the NumPy reference; real arithmetic compiles in about
half the time of the complex arithmetic this kernel used before.

Compilation time (a model's first run on an empty cache, some 3 s on the 2-core machine):
one entry point per run (:func:`_balls`, which ends with :func:`_ring_jacobian`); the
restarts (:func:`_restart_balls`) compile only in a run that needs them. The ball Newton,
the ring Jacobian and the lift-off test are inlined into :func:`_balls` at numba's IR level
(``inline="always"``): as functions of their own (``register_jitable``) they cost some
0.13 s of first-run compilation each, measured, for their own typing pass, module and LLVM
optimisation. Small scalar helpers stay ``register_jitable`` (inlining them measured no
better), and :func:`_ball_state`, called six times, stays ``njit`` (compiled once). Tiny
helpers (``max``/``min`` of two floats, the residual and its Jacobian) are written out where
they are used.

The kernels take C-contiguous float64 arrays and plain scalars, are compiled with
``cache=True`` and without ``fastmath``. The constants of the bearing travel in one float64
vector (indices ``C_*`` below); the Hertz constants of each ball (linearised in its contact
angles, :meth:`runout.models.equilibrium._Ring.set_angles`) and its azimuth in one ball
table of shape (8, Z) (rows ``B_*``), which :func:`ring_forces` builds from its arguments.
"""

from __future__ import annotations

import math

import numpy as np
from numba.extending import register_jitable
from numpy.typing import NDArray

from runout.base._kernel import kernel

FloatArray = NDArray[np.float64]
BoolArray = NDArray[np.bool_]


__all__ = [
    "BALL_ITER",
    "N_CONST",
    "N_STATE",
    "STATE_NAMES",
    "ball_table",
    "constants",
    "ring_forces",
]

#: Iterations of the ball Newton and of the lift-off fixed point.
BALL_ITER = 50
_SHRINK = 60  # halvings of a ball Newton step that would open a contact
# continuation in the gyroscopic friction: each pass advances s by >= 1/1024 or halves ds
# (at most 10 times in a row), so this bounds the loop with a wide margin
_CONT_PASSES = 1024 * 12

# indices of the constant vector
C_D, C_DM, C_RI0, C_RO0, C_FI, C_MASS, C_INERTIA, C_INNER, C_OUTER, C_INNER_CONTROL = range(10)
C_A1, C_A2, C_RAD_I, C_SCALE, C_ARM = range(10, 15)
N_CONST = 15

# rows of the ball table (8, Z): the Hertz constants K = k0 + k1 (α − α_c) of the inner and
# outer contacts, and the azimuth. One array rather than eight: each array argument of a
# compiled function costs its own unpacking code (first-run compilation time)
B_KI0, B_KI1, B_AI_C, B_KO0, B_KO1, B_AO_C, B_COS, B_SIN = range(8)
N_BALL_ROWS = 8

#: Rows of the per-ball state returned by :func:`ring_forces`.
STATE_NAMES = (
    "g1",
    "g2",
    "pa",
    "pr",
    "mg",
    "fc",
    "q_i",
    "q_o",
    "d_i",
    "d_o",
    "alpha_i",
    "alpha_o",
    "omega_m",
    "omega_r",
)
N_STATE = len(STATE_NAMES)

#: Status codes of :func:`ring_forces`.
OK, BALLS_DID_NOT_CONVERGE = 0, 1


def constants(
    ball_diameter: float,
    pitch_diameter: float,
    ri0: float,
    ro0: float,
    f_i: float,
    mass: float,
    inertia: float,
    inner: float,
    outer: float,
    inner_control: bool,
    a1_0: float,
    a2_0: float,
    rad_i: float,
    scale: float,
    moment_arm: float,
) -> NDArray[np.float64]:
    """The constant vector of the kernels.

    Parameters
    ----------
    ball_diameter, pitch_diameter : float
        D, d_m [m].
    ri0, ro0 : float
        (f_i − 0.5) D and (f_o − 0.5) D [m].
    f_i : float
        Inner conformity [-].
    mass, inertia : float
        Ball mass [kg] and polar moment of inertia [kg m²].
    inner, outer : float
        Ring speeds [rad/s].
    inner_control : bool
        Spin-axis attitude of inner-raceway control (else outer).
    a1_0, a2_0 : float
        A sin α⁰, A cos α⁰: the groove centres of the centred ring [m].
    rad_i : float
        ℜ_i, radius of the locus of inner groove curvature centres [m].
    scale : float
        Length scale of the ball Newton tolerance (A) [m].
    moment_arm : float
        Arm of a ball's axial force in the ring's moment [m]: ℜ_i (Harris), or d_m/2 as
        ISO/TS 16281's moment equilibrium takes it.

    Returns
    -------
    ndarray, shape (N_CONST,)
    """
    return np.array(
        [
            ball_diameter,
            pitch_diameter,
            ri0,
            ro0,
            f_i,
            mass,
            inertia,
            inner,
            outer,
            1.0 if inner_control else 0.0,
            a1_0,
            a2_0,
            rad_i,
            scale,
            moment_arm,
        ]
    )


# --------------------------------------------------------------------------------------------
# scalar ball functions
# --------------------------------------------------------------------------------------------
# register_jitable: compiled into its caller, without Python and C entry points of its own
# (first-run compilation time); a helper that several compiled functions of one run call
# stays njit (compiled once, not once per caller).
@register_jitable(no_cfunc_wrapper=True)
def _speeds(
    cos_i: float,
    sin_i: float,
    cos_o: float,
    sin_o: float,
    gamma: float,
    inner: float,
    outer: float,
    inner_control: bool,
) -> tuple[float, float, float]:
    """Orbit and spin speed and sin β (Harris, ``equilibrium.ball_speeds``) at the contact
    angles (cos α_i, sin α_i, cos α_o, sin α_o); the spin-axis attitude tan β of inner- or
    outer-raceway control (:func:`_ball_state` writes the same out with its derivatives)."""
    if inner_control:
        tb = sin_i / (cos_i - gamma)
    else:
        tb = sin_o / (cos_o + gamma)
    cb = 1.0 / math.sqrt(1.0 + tb * tb)
    sb = tb * cb
    ci = cos_i + tb * sin_i
    co = cos_o + tb * sin_o
    w = inner - outer
    a = (1.0 - gamma * cos_i) * co
    b = (1.0 + gamma * cos_o) * ci
    omega_m = outer + w * a / (a + b)
    omega_r = w / ((co / (1.0 + gamma * cos_o) + ci / (1.0 - gamma * cos_i)) * gamma * cb)
    return omega_m, omega_r, sb


@kernel()
def _ball_state(
    x1: float,
    x2: float,
    a1: float,
    a2: float,
    tx1: float,
    tx2: float,
    ta1: float,
    ta2: float,
    ki0: float,
    ki1: float,
    ai_c: float,
    ko0: float,
    ko1: float,
    ao_c: float,
    cst: FloatArray,
    lam_i: float,
    lam_o: float,
    speed_on: bool,
) -> tuple[float, ...]:
    r"""Ball j at centre (x1, x2) and inner groove centre (a1, a2) [m], with the derivative of
    its first five state entries along the direction (tx1, tx2, ta1, ta2).

    Seed 001 eq. 3-6 (module docstring of :mod:`runout.models.equilibrium`): the residuals
    g1, g2 [N] of the ball's two equations, the inner-race force components P_a, P_r [N], the
    gyroscopic moment M_g [N m], F_c, Q_i, Q_o [N], δ_i, δ_o [m], α_i, α_o [rad], ω_m, ω_R
    [rad/s], in the order of :data:`STATE_NAMES`; then the directional derivatives of g1, g2,
    P_a, P_r and M_g (forward-mode differentiation: each quantity ``v`` carries its derivative
    ``t_v``, by the chain rule written out). The values are those of the plain evaluation; the
    derivatives are exact to round-off, as the complex-step derivatives of the NumPy reference.
    """
    d = cst[C_D]
    dm = cst[C_DM]
    # outer contact: distance from the outer groove centre, angle
    ro = math.sqrt(x1 * x1 + x2 * x2)
    t_ro = (x1 * tx1 + x2 * tx2) / ro
    e1 = a1 - x1
    e2 = a2 - x2
    t_e1 = ta1 - tx1
    t_e2 = ta2 - tx2
    ri = math.sqrt(e1 * e1 + e2 * e2)
    t_ri = (e1 * t_e1 + e2 * t_e2) / ri
    cos_o = x2 / ro
    sin_o = x1 / ro
    cos_i = e2 / ri
    sin_i = e1 / ri
    t_cos_o = (tx2 - cos_o * t_ro) / ro
    t_sin_o = (tx1 - sin_o * t_ro) / ro
    t_cos_i = (t_e2 - cos_i * t_ri) / ri
    t_sin_i = (t_e1 - sin_i * t_ri) / ri
    u_o = x1 / x2
    u_i = e1 / e2
    alpha_o = math.atan(u_o)
    alpha_i = math.atan(u_i)
    t_alpha_o = (tx1 - u_o * tx2) / x2 / (1.0 + u_o * u_o)
    t_alpha_i = (t_e1 - u_i * t_e2) / e2 / (1.0 + u_i * u_i)
    d_o = ro - cst[C_RO0]
    d_i = ri - cst[C_RI0]
    # Hertz loads K δ^1.5 with K linear in the contact angle
    k_i = ki0 + ki1 * (alpha_i - ai_c)
    k_o = ko0 + ko1 * (alpha_o - ao_c)
    q_i = t_q_i = q_o = t_q_o = 0.0
    if d_i > 0.0:
        root = math.sqrt(d_i)
        q_i = k_i * d_i * root
        t_q_i = ki1 * t_alpha_i * d_i * root + 1.5 * k_i * root * t_ri
    if d_o > 0.0:
        root = math.sqrt(d_o)
        q_o = k_o * d_o * root
        t_q_o = ko1 * t_alpha_o * d_o * root + 1.5 * k_o * root * t_ro
    wm = wr = fc = mg = t_fc = t_mg = 0.0
    if speed_on:
        # orbit and spin speeds (Harris; equilibrium.ball_speeds), spin-axis attitude tan β
        gamma = d / dm
        inner = cst[C_INNER]
        if cst[C_INNER_CONTROL]:
            den = cos_i - gamma
            tb = sin_i / den
            t_tb = (t_sin_i - tb * t_cos_i) / den
        else:
            den = cos_o + gamma
            tb = sin_o / den
            t_tb = (t_sin_o - tb * t_cos_o) / den
        root = math.sqrt(1.0 + tb * tb)
        cb = 1.0 / root
        t_cb = -cb * (tb * t_tb / root) / root
        sb = tb * cb
        t_sb = t_tb * cb + tb * t_cb
        ci = cos_i + tb * sin_i
        co = cos_o + tb * sin_o
        t_ci = t_cos_i + t_tb * sin_i + tb * t_sin_i
        t_co = t_cos_o + t_tb * sin_o + tb * t_sin_o
        outer = cst[C_OUTER]
        w = inner - outer
        fi = 1.0 - gamma * cos_i
        fo = 1.0 + gamma * cos_o
        a = fi * co
        b = fo * ci
        t_a = -gamma * t_cos_i * co + fi * t_co
        t_b = gamma * t_cos_o * ci + fo * t_ci
        ab = a + b
        wm = outer + w * a / ab
        t_wm = w * (t_a * b - a * t_b) / (ab * ab)
        p = co / fo
        r = ci / fi
        t_p = (t_co - p * gamma * t_cos_o) / fo
        t_r = (t_ci + r * gamma * t_cos_i) / fi
        den = (p + r) * gamma * cb
        t_den = gamma * ((t_p + t_r) * cb + (p + r) * t_cb)
        wr = w / den
        t_wr = -wr * t_den / den
        fc = 0.5 * cst[C_MASS] * dm * wm * wm
        t_fc = cst[C_MASS] * dm * wm * t_wm
        inertia = cst[C_INERTIA]
        mg = inertia * wr * wm * sb
        t_mg = inertia * (t_wr * wm * sb + wr * t_wm * sb + wr * wm * t_sb)
    md = mg / d
    t_md = t_mg / d
    lc = lam_i * cos_i - lam_o * cos_o
    ls = lam_i * sin_i - lam_o * sin_o
    t_lc = lam_i * t_cos_i - lam_o * t_cos_o
    t_ls = lam_i * t_sin_i - lam_o * t_sin_o
    g1 = q_i * sin_i - q_o * sin_o - md * lc
    g2 = q_i * cos_i - q_o * cos_o + md * ls + fc
    t_g1 = t_q_i * sin_i + q_i * t_sin_i - t_q_o * sin_o - q_o * t_sin_o - t_md * lc - md * t_lc
    t_g2 = t_q_i * cos_i + q_i * t_cos_i - t_q_o * cos_o - q_o * t_cos_o + t_md * ls + md * t_ls
    t_g2 += t_fc
    pa = q_i * sin_i - lam_i * md * cos_i
    pr = q_i * cos_i + lam_i * md * sin_i
    t_pa = t_q_i * sin_i + q_i * t_sin_i - lam_i * (t_md * cos_i + md * t_cos_i)
    t_pr = t_q_i * cos_i + q_i * t_cos_i + lam_i * (t_md * sin_i + md * t_sin_i)
    return (
        g1,
        g2,
        pa,
        pr,
        mg,
        fc,
        q_i,
        q_o,
        d_i,
        d_o,
        alpha_i,
        alpha_o,
        wm,
        wr,
        t_g1,
        t_g2,
        t_pa,
        t_pr,
        t_mg,
    )


# --------------------------------------------------------------------------------------------
# ball equilibrium
# --------------------------------------------------------------------------------------------
@kernel(inline="always")  # into _balls, _restart_balls and _friction_continuation
def _ball_newton(
    xs: FloatArray,
    aa: FloatArray,
    active: BoolArray,
    balls: FloatArray,
    cst: FloatArray,
    lam_i: float,
    lam_o: float,
    speed_on: bool,
    tol: float,
    done: BoolArray,
) -> None:
    """2×2 Newton on eq. 3-4 of the balls flagged ``active`` (rows of ``xs``, ``aa``), in
    place.

    Every ball takes its Newton step, shortened so that neither approach shrinks by more than
    90 % (the Hertz stiffness vanishes at zero approach) and so that no component exceeds
    0.25 % of the groove radii; all balls iterate until all have converged (a full step at
    most ``tol`` [m]). ``done`` receives the convergence of the active balls (the other
    entries are left as they are). A mask rather than a list of positions: no index array
    to allocate, first-run compile time.
    """
    z = active.size
    ri0 = cst[C_RI0]
    ro0 = cst[C_RO0]
    limit = 0.25 * (ri0 + ro0) * 0.05
    for m in range(z):
        if active[m]:
            done[m] = False
    for _ in range(BALL_ITER):
        all_done = True
        for m in range(z):
            if not active[m]:
                continue
            x1 = xs[m, 0]
            x2 = xs[m, 1]
            a1 = aa[m, 0]
            a2 = aa[m, 1]
            # g and ∂g/∂X: two directional derivatives of the ball state
            k0, k1, kc = balls[B_KI0, m], balls[B_KI1, m], balls[B_AI_C, m]
            o0, o1, oc = balls[B_KO0, m], balls[B_KO1, m], balls[B_AO_C, m]
            s = _ball_state(
                x1, x2, a1, a2, 1.0, 0.0, 0.0, 0.0, k0, k1, kc, o0, o1, oc, cst, lam_i, lam_o,
                speed_on,
            )  # fmt: skip
            g1 = s[0]
            g2 = s[1]
            j00 = s[14]  # literal indices (see _ring_jacobian)
            j10 = s[15]
            s = _ball_state(
                x1, x2, a1, a2, 0.0, 1.0, 0.0, 0.0, k0, k1, kc, o0, o1, oc, cst, lam_i, lam_o,
                speed_on,
            )  # fmt: skip
            j01 = s[14]
            j11 = s[15]
            det = j00 * j11 - j01 * j10
            ok = abs(det) > 0.0
            if not ok:
                det = 1.0
            s0 = -(j11 * g1 - j01 * g2) / det
            s1 = -(j00 * g2 - j10 * g1) / det
            if not ok:
                s0 = 0.0
                s1 = 0.0
            # max/min written out (the builtins compile one function per tuple type): the
            # builtins' semantics, the first argument kept unless the second is larger/smaller
            big = abs(s1) if abs(s1) > abs(s0) else abs(s0)
            factor = limit / (1e-300 if 1e-300 > big else big)
            factor = factor if factor < 1.0 else 1.0
            # the approaches δ_i, δ_o now and after the step (seed 001 eq. 5-6)
            d_i = math.hypot(a1 - x1, a2 - x2) - ri0
            d_o = math.hypot(x1, x2) - ro0
            for _ in range(_SHRINK):
                y1 = x1 + factor * s0
                y2 = x2 + factor * s1
                ti = math.hypot(a1 - y1, a2 - y2) - ri0
                to = math.hypot(y1, y2) - ro0
                if not (ti < 0.1 * d_i or to < 0.1 * d_o):
                    break
                factor = 0.5 * factor
            xs[m, 0] = x1 + factor * s0
            xs[m, 1] = x2 + factor * s1
            done[m] = ok and big <= tol  # the full Newton step, not the shortened one
            if not done[m]:
                all_done = False
        if all_done:
            break


@kernel(inline="always")  # into _balls, its one caller (tests call it too)
def _lifted_off(
    a: FloatArray,
    balls: FloatArray,
    cst: FloatArray,
    lam_i: float,
    lam_o: float,
    x_star: FloatArray,
    lifted: BoolArray,
    work: FloatArray,
) -> None:
    """Balls whose inner contact opens at speed, and their outer-contact-only centres X*.

    With Q_i = 0 the outer contact alone balances F_c and the gyroscopic friction; a short
    fixed point (the ball speeds depend on the angles), run until no angle of any ball moves
    by more than 1e-14 rad. A ball is lifted off when δ_i(X*) <= 0 (module Notes of
    :mod:`runout.models.equilibrium`).
    """
    z = a.shape[0]
    d = cst[C_D]
    dm = cst[C_DM]
    gamma = d / dm
    mass = cst[C_MASS]
    inertia = cst[C_INERTIA]
    ri0 = cst[C_RI0]
    ro0 = cst[C_RO0]
    inner = cst[C_INNER]
    outer = cst[C_OUTER]
    control = cst[C_INNER_CONTROL]
    # rows of the caller's work array (3, Z): an allocation here would compile np.empty
    ao = work[0]
    ai = work[1]
    d_i = work[2]  # set for every ball by each pass of the fixed point (BALL_ITER >= 1)
    for j in range(z):
        angle = math.atan(a[j, 0] / a[j, 1])
        ao[j] = angle
        ai[j] = angle
    # each element read or written once per pass: every source-level access compiles its
    # own indexing code
    for _ in range(BALL_ITER):
        moved = 0.0
        for j in range(z):
            ai_j = ai[j]
            ao_j = ao[j]
            ci = math.cos(ai_j)
            si = math.sin(ai_j)
            co = math.cos(ao_j)
            so = math.sin(ao_j)
            wm, wr, sb = _speeds(ci, si, co, so, gamma, inner, outer, control)
            fc = 0.5 * mass * dm * wm * wm
            md = inertia * wr * wm * sb / d
            v = md * (lam_i * ci - lam_o * co)
            w = md * (lam_i * si - lam_o * so) + fc
            q_o = math.hypot(v, w)
            ao_new = math.atan2(-v, w)
            k_o = balls[B_KO0, j] + balls[B_KO1, j] * (ao_new - balls[B_AO_C, j])
            k_o = 1e-300 if 1e-300 > k_o else k_o  # max(k_o, 1e-300) (see _ball_newton)
            r = ro0 + (q_o / k_o) ** (2.0 / 3.0)
            x1 = r * math.sin(ao_new)
            x2 = r * math.cos(ao_new)
            x_star[j, 0] = x1
            x_star[j, 1] = x2
            e1 = a[j, 0] - x1
            e2 = a[j, 1] - x2
            ai_new = math.atan(e1 / e2)
            d_i[j] = math.hypot(e1, e2) - ri0
            step_o = abs(ao_new - ao_j)
            step_i = abs(ai_new - ai_j)
            moved = step_o if step_o > moved else moved  # max(...) (see _ball_newton)
            moved = step_i if step_i > moved else moved
            ao[j] = ao_new
            ai[j] = ai_new
        if moved <= 1e-14:
            break
    for j in range(z):
        lifted[j] = d_i[j] <= 0.0


@register_jitable(no_cfunc_wrapper=True)
def _start(
    a1: float, a2: float, ki0: float, ko0: float, ri0: float, ro0: float
) -> tuple[float, float]:
    """Zero-speed ball centre: on the line between the groove centres, Hertz split [m]."""
    dist = math.hypot(a1, a2)
    s = dist - ri0 - ro0
    s = 0.0 if 0.0 > s else s  # max(s, 0) (see _ball_newton)
    ci = ki0 ** (-2.0 / 3.0)
    co = ko0 ** (-2.0 / 3.0)
    d_o = s * co / (ci + co)
    r = ro0 + d_o
    return a1 / dist * r, a2 / dist * r


@register_jitable(no_cfunc_wrapper=True)
def _closed_start(
    a1: float, a2: float, ko0: float, cst: FloatArray, side: float
) -> tuple[float, float]:
    """A ball centre with both contacts closed off the line of groove centres [m].

    For a ball with no rest overlap (|A| <= ℜ_i⁰ + ℜ_o⁰, the zero-speed start has an open
    contact) that only the gyroscopic friction presses onto the inner race (inner-race
    control): without friction it would lift off, so neither X* (which may not exist: the
    fixed point can leave the groove) nor the friction continuation (no loaded state at
    λ = 0) reaches it. The ball centre is put where both approaches equal the centrifugal
    one, δ = (F_c/K_o)^(2/3) (F_c at the orbit speed of the free contact angle), on the side
    ``side`` (±1) of the line of groove centres; the Newton step limits keep both contacts
    closed from there.
    """
    ri0 = cst[C_RI0]
    ro0 = cst[C_RO0]
    dist = math.hypot(a1, a2)
    u1 = a1 / dist
    u2 = a2 / dist
    gamma = cst[C_D] / cst[C_DM]
    wm, _, _ = _speeds(u2, u1, u2, u1, gamma, cst[C_INNER], cst[C_OUTER], cst[C_INNER_CONTROL])
    fc = 0.5 * cst[C_MASS] * cst[C_DM] * wm * wm
    e = max((fc / max(ko0, 1e-300)) ** (2.0 / 3.0), 1e-9 * cst[C_D])
    r_o = ro0 + e
    r_i = ri0 + e
    along = (dist * dist + r_o * r_o - r_i * r_i) / (2.0 * dist)
    h = side * math.sqrt(max(r_o * r_o - along * along, 0.0))
    return along * u1 + h * u2, along * u2 - h * u1


# Small loops instead of NumPy array expressions (`.all()`, `~done`, fancy indexing, slice
# assignment): the same work, but several times less compile time.
@register_jitable(no_cfunc_wrapper=True)
def _all(flags: BoolArray, active: BoolArray) -> bool:
    """Every active entry true."""
    for m in range(flags.size):
        if active[m] and not flags[m]:
            return False
    return True


@register_jitable(no_cfunc_wrapper=True)
def _copy_rows(dst: FloatArray, src: FloatArray, active: BoolArray) -> None:
    """dst[m] = src[m] for the active rows of arrays of shape (Z, 2)."""
    for m in range(src.shape[0]):
        if active[m]:
            dst[m, 0] = src[m, 0]
            dst[m, 1] = src[m, 1]


@kernel()
def _friction_continuation(
    xs: FloatArray,
    aa: FloatArray,
    active: BoolArray,
    balls: FloatArray,
    cst: FloatArray,
    lam_i: float,
    lam_o: float,
    speed_on: bool,
    tol: float,
    done: BoolArray,
) -> None:
    """Ball Newton along the gyroscopic friction, λ → s·λ with s from 0 to 1, in place, for
    the balls flagged ``active``.

    The last resort of the ball solve (near lift-off under inner-race control): without
    friction (s = 0) the balance is the centrifugal one; each step starts next to its answer
    (step halved on failure, down to 1/1024).
    """
    z = active.size
    _ball_newton(xs, aa, active, balls, cst, 0.0, 0.0, speed_on, tol, done)
    xt = np.empty((z, 2))
    ok = np.empty(z, dtype=np.bool_)
    s, ds = 0.0, 0.25
    for _ in range(_CONT_PASSES):
        if not (_all(done, active) and s < 1.0):
            return
        t = min(1.0, s + ds)
        _copy_rows(xt, xs, active)
        lam_ti = t * lam_i
        lam_to = t * lam_o
        _ball_newton(xt, aa, active, balls, cst, lam_ti, lam_to, speed_on, tol, ok)
        if _all(ok, active):
            _copy_rows(xs, xt, active)
            s, ds = t, min(2.0 * ds, 0.5)
        elif ds > 1.0 / 1024.0:
            ds *= 0.5
        else:
            _copy_rows(xs, xt, active)
            for m in range(z):
                if active[m]:
                    done[m] = ok[m]
            return


@kernel()
def _balls(
    q: FloatArray,
    x: FloatArray,
    have_x: bool,
    balls: FloatArray,
    cst: FloatArray,
    lam_i: float,
    lam_o: float,
    speed_on: bool,
    a: FloatArray,
    x_star: FloatArray,
    loaded: BoolArray,
    done: BoolArray,
    jac: FloatArray,
    state: FloatArray,
    parts: FloatArray,
    lift_work: FloatArray,
) -> bool:
    """Groove centres ``a`` at ring displacement q and eq. 3-4 for every loaded ball, in place
    in ``x`` (Z, 2) from its current value (or the Hertz split without ``have_x``).

    ``balls`` is the ball table (rows ``B_*``: Hertz constants and azimuths). The lift-off
    test, the ball Newton and the ring Jacobian are inlined here (their one call each in a
    run that needs no restart): compiled on their own they cost first-run compilation time
    for nothing (module Notes). For the same reason each array
    element is read or written once where the code allows (every source-level access compiles
    its own indexing code) and the loops over the balls are merged where their order allows.

    Unloaded balls (a gap at rest, lifted off at speed: ``loaded`` false) go to the outer
    groove bottom. A loaded ball starts with both contacts closed; ``done`` tells which
    converged (true for the unloaded ones), and the restarts of :func:`_restart_balls` take
    the others from their outer-contact-only centres ``x_star`` (at speed). Returns whether
    every ball converged, and then also the ball states and the Jacobian of the ring force
    (:func:`_ring_jacobian`, compiled into this kernel: one entry point, not two).
    """
    z = balls.shape[1]
    ri0 = cst[C_RI0]
    ro0 = cst[C_RO0]
    rad_i = cst[C_RAD_I]
    a1_0 = cst[C_A1]
    a2_0 = cst[C_A2]
    q0 = q[0]
    q1 = q[1]
    q2 = q[2]
    q3 = q[3]
    q4 = q[4]
    for j in range(z):
        cp = balls[B_COS, j]
        sp = balls[B_SIN, j]
        a1 = a1_0 + q0 + rad_i * (q3 * sp - q4 * cp)
        a2 = a2_0 + q1 * cp + q2 * sp
        a[j, 0] = a1
        a[j, 1] = a2
        if not have_x:
            x[j, 0], x[j, 1] = _start(a1, a2, balls[B_KI0, j], balls[B_KO0, j], ri0, ro0)
    if speed_on:
        _lifted_off(a, balls, cst, lam_i, lam_o, x_star, loaded, lift_work)
    for j in range(z):
        a1 = a[j, 0]
        a2 = a[j, 1]
        if speed_on:
            on = not loaded[j]  # _lifted_off wrote "lifted off"
        else:
            on = math.hypot(a1, a2) > ri0 + ro0
        loaded[j] = on
        if on:
            # start with both contacts closed (the previous state may have had one open)
            x1 = x[j, 0]
            x2 = x[j, 1]
            d_i = math.hypot(a1 - x1, a2 - x2) - ri0  # as _approaches
            d_o = math.hypot(x1, x2) - ro0
            if d_i <= 0.0 or d_o <= 0.0:
                if speed_on:  # the inner groove overlaps X*: both contacts closed there
                    x[j, 0] = x_star[j, 0]
                    x[j, 1] = x_star[j, 1]
                else:
                    x[j, 0], x[j, 1] = _start(a1, a2, balls[B_KI0, j], balls[B_KO0, j], ri0, ro0)
    tol = 1e-13 * cst[C_SCALE]
    _ball_newton(x, a, loaded, balls, cst, lam_i, lam_o, speed_on, tol, done)
    all_done = True  # every loaded ball converged (a loop: _all would compile apart)
    for j in range(z):
        if loaded[j]:
            if not done[j]:
                all_done = False
        else:  # on the outer groove bottom
            x[j, 0] = 0.0
            x[j, 1] = ro0
            done[j] = True
    if all_done:
        _ring_jacobian(a, x, balls, cst, lam_i, lam_o, speed_on, jac, state, loaded, parts)
    return all_done


@kernel()
def _restart_balls(
    a: FloatArray,
    x: FloatArray,
    balls: FloatArray,
    cst: FloatArray,
    lam_i: float,
    lam_o: float,
    speed_on: bool,
    x_star: FloatArray,
    done: BoolArray,
    loaded: BoolArray,
    jac: FloatArray,
    state: FloatArray,
    parts: FloatArray,
) -> bool:
    """At speed, the balls :func:`_balls` left unconverged (``done`` false), restarted.

    From the outer-contact-only centre X*, then by continuation in the friction, then from
    both contacts closed off the line of groove centres on either side (:func:`_closed_start`),
    each attempt on the balls still unconverged, in place in ``x`` and ``done``; then, when
    every ball has converged, the ball states and the Jacobian (:func:`_ring_jacobian`).
    Returns whether every ball converged. Compiled only when a run needs it (rarely: near
    lift-off).
    """
    ri0 = cst[C_RI0]
    ro0 = cst[C_RO0]
    tol = 1e-13 * cst[C_SCALE]
    z = done.size
    redo = np.empty(z, dtype=np.bool_)
    dr = np.empty(z, dtype=np.bool_)
    for attempt in range(4):
        k = 0
        for j in range(z):
            redo[j] = not done[j]
            if redo[j]:
                k = k + 1
        if k == 0:
            break
        for j in range(z):
            if not redo[j]:
                continue
            if attempt == 0:
                x[j, 0] = x_star[j, 0]
                x[j, 1] = x_star[j, 1]
            elif attempt == 1:
                ki0 = balls[B_KI0, j]
                x[j, 0], x[j, 1] = _start(a[j, 0], a[j, 1], ki0, balls[B_KO0, j], ri0, ro0)
            else:
                side = 1.0 if attempt == 2 else -1.0
                x[j, 0], x[j, 1] = _closed_start(a[j, 0], a[j, 1], balls[B_KO0, j], cst, side)
        if attempt != 1:
            _ball_newton(x, a, redo, balls, cst, lam_i, lam_o, speed_on, tol, dr)
        else:
            _friction_continuation(x, a, redo, balls, cst, lam_i, lam_o, speed_on, tol, dr)
        for j in range(z):
            if redo[j]:
                done[j] = dr[j]
    ok = True
    for j in range(z):
        if not done[j]:
            ok = False
    if ok:
        _ring_jacobian(a, x, balls, cst, lam_i, lam_o, speed_on, jac, state, loaded, parts)
    return ok


# --------------------------------------------------------------------------------------------
# ring force and stiffness
# --------------------------------------------------------------------------------------------
def ball_table(*rows: FloatArray) -> FloatArray:
    """The kernels' ball table (8, Z): ki0, ki1, ai_c, ko0, ko1, ao_c, cos ψ, sin ψ.

    Parameters
    ----------
    *rows : ndarray, shape (Z,)
        The Hertz constants K = k0 + k1 (α − α_c) of the inner and outer contacts
        [N/m^1.5, N/m^1.5/rad, rad] and the ball azimuths' cosine and sine, in the order of
        the rows ``B_*``.

    Returns
    -------
    ndarray, shape (8, Z)
        C-contiguous float64.
    """
    if len(rows) != N_BALL_ROWS:
        raise ValueError(f"ball_table takes {N_BALL_ROWS} rows, got {len(rows)}")
    return np.ascontiguousarray(np.stack(rows), dtype=np.float64)


def ring_forces(
    q: FloatArray,
    cos_psi: FloatArray,
    sin_psi: FloatArray,
    x: FloatArray,
    have_x: bool,
    ki0: FloatArray,
    ki1: FloatArray,
    ai_c: FloatArray,
    ko0: FloatArray,
    ko1: FloatArray,
    ao_c: FloatArray,
    cst: FloatArray,
    lam_i: float,
    lam_o: float,
    speed_on: bool,
    force: FloatArray,
    jac: FloatArray,
    state: FloatArray,
    loaded: BoolArray,
) -> int:
    r"""Ring force, its Jacobian and every ball's state at ring displacement ``q``.

    Seed 001 eq. 1-6. The groove centres of ball j are

    .. math::
        A_{1j} = A\sin\alpha^0 + \delta_a + \Re_i(\theta_x\sin\psi_j - \theta_y\cos\psi_j),\quad
        A_{2j} = A\cos\alpha^0 + \delta_x\cos\psi_j + \delta_y\sin\psi_j ;

    the balls are solved from their previous centres ``x`` (when ``have_x``; else from the
    Hertz split on the line of groove centres), and the ring force is
    :math:`(\sum P_a, \sum P_r\cos\psi, \sum P_r\sin\psi, \sum P_m\sin\psi,
    -\sum P_m\cos\psi)` with :math:`P_m = P_a\Re_i + \lambda_i f_i M_g`. Its Jacobian is
    :math:`\sum_j C_j\,(dP/dA)_j\,B_j` with :math:`dP/dA = \partial P/\partial A -
    \partial P/\partial X\,(\partial g/\partial X)^{-1}\partial g/\partial A` (implicit
    differentiation of the ball balance, forward-mode partial derivatives).

    Compiled in two kernels: the ball solve (:func:`_balls`) and the restarts of the balls it
    left unconverged (:func:`_restart_balls`, compiled only when a run needs them), each
    ending with the ball states and the Jacobian (:func:`_ring_jacobian`); the five sums of
    the force are NumPy's (its pairwise order keeps the force bit for bit where it cancels,
    e.g. the radial force of a purely axial load).

    Parameters
    ----------
    q : ndarray, shape (5,)
        δ_a, δ_x, δ_y [m], θ_x, θ_y [rad].
    cos_psi, sin_psi : ndarray, shape (Z,)
        Ball azimuths.
    x : ndarray, shape (Z, 2)
        Ball centres from the outer groove centre [m]; updated in place.
    have_x : bool
        Whether ``x`` holds a previous solution to start from.
    ki0, ki1, ai_c, ko0, ko1, ao_c : ndarray, shape (Z,)
        Hertz constants K = k0 + k1 (α − α_c) of the inner and outer contacts
        [N/m^1.5, N/m^1.5/rad, rad].
    cst : ndarray, shape (N_CONST,)
        Bearing constants (:func:`constants`).
    lam_i, lam_o : float
        Raceway-control factors λ_i, λ_o [-].
    speed_on : bool
        Centrifugal and gyroscopic effects on.
    force : ndarray, shape (5,)
        Out: F_a, F_x, F_y [N], M_x, M_y [N m].
    jac : ndarray, shape (5, 5)
        Out: ∂force/∂q.
    state : ndarray, shape (N_STATE, Z)
        Out: the ball states in the order of :data:`STATE_NAMES` (SI units).
    loaded : ndarray of bool, shape (Z,)
        Out: balls in contact with the inner race.

    Returns
    -------
    int
        :data:`OK`, or :data:`BALLS_DID_NOT_CONVERGE`.
    """
    z = cos_psi.size
    balls = ball_table(ki0, ki1, ai_c, ko0, ko1, ao_c, cos_psi, sin_psi)
    a = np.empty((z, 2))
    x_star = np.empty((z, 2))
    done = np.empty(z, dtype=np.bool_)
    parts = np.empty((5, z))
    lift_work = np.empty((3, z))  # the lift-off fixed point's angles and approaches
    ring = (balls, cst, lam_i, lam_o, bool(speed_on))
    out = (jac, state, parts)
    ok = _balls(q, x, bool(have_x), *ring, a, x_star, loaded, done, *out, lift_work)
    if not ok and speed_on:
        ok = _restart_balls(a, x, *ring, x_star, done, loaded, *out)
    if not ok:
        return BALLS_DID_NOT_CONVERGE
    force[:] = parts.sum(axis=1)  # each row in NumPy's pairwise order
    force[4] = -force[4]
    return OK


@kernel(inline="always")  # into _balls and _restart_balls (see _balls)
def _ring_jacobian(
    a: FloatArray,
    x: FloatArray,
    balls: FloatArray,
    cst: FloatArray,
    lam_i: float,
    lam_o: float,
    speed_on: bool,
    jac: FloatArray,
    state: FloatArray,
    loaded: BoolArray,
    parts: FloatArray,
) -> None:
    """Ball states, the Jacobian ``jac`` of the ring force and each ball's part of it in
    ``parts`` (P_a, P_r cos ψ, P_r sin ψ, P_m sin ψ, P_m cos ψ per ball; rows summed by
    :func:`ring_forces`), at converged ball centres ``x`` and groove centres ``a``."""
    z = balls.shape[1]
    rad_i = cst[C_RAD_I]
    # the tilt moves the groove centres by ℜ_i θ (rad_i); the axial forces' moment has its
    # own arm (ℜ_i, or d_m/2 as ISO/TS 16281 writes the moment equilibrium)
    arm = cst[C_ARM]
    lam_fi = lam_i * cst[C_FI]
    for r in range(5):
        for c in range(5):
            jac[r, c] = 0.0
    for j in range(z):
        # derivatives along X_1, X_2, A_1, A_2: ∂(g_1, g_2, P_a, P_r, M_g)/∂(X, A), as scalars
        # (small arrays would compile to several times the code); entries 14-18 of the ball
        # state by literal indices: a computed index compiles to a switch over the 19 entries
        xj0, xj1, aj0, aj1 = x[j, 0], x[j, 1], a[j, 0], a[j, 1]
        k0, k1, kc = balls[B_KI0, j], balls[B_KI1, j], balls[B_AI_C, j]
        o0, o1, oc = balls[B_KO0, j], balls[B_KO1, j], balls[B_AO_C, j]
        s = _ball_state(
            xj0, xj1, aj0, aj1, 1.0, 0.0, 0.0, 0.0, k0, k1, kc, o0, o1, oc, cst, lam_i, lam_o,
            speed_on,
        )  # fmt: skip
        st_pa = s[2]
        st_pr = s[3]
        st_mg = s[4]
        state[0, j] = s[0]
        state[1, j] = s[1]
        state[2, j] = st_pa
        state[3, j] = st_pr
        state[4, j] = st_mg
        state[5, j] = s[5]
        state[6, j] = s[6]
        state[7, j] = s[7]
        state[8, j] = s[8]
        state[9, j] = s[9]
        state[10, j] = s[10]
        state[11, j] = s[11]
        state[12, j] = s[12]
        state[13, j] = s[13]
        gx00 = s[14]
        gx10 = s[15]
        px00 = s[16]
        px10 = s[17]
        px20 = s[18]
        s = _ball_state(
            xj0, xj1, aj0, aj1, 0.0, 1.0, 0.0, 0.0, k0, k1, kc, o0, o1, oc, cst, lam_i, lam_o,
            speed_on,
        )  # fmt: skip
        gx01 = s[14]
        gx11 = s[15]
        px01 = s[16]
        px11 = s[17]
        px21 = s[18]
        s = _ball_state(
            xj0, xj1, aj0, aj1, 0.0, 0.0, 1.0, 0.0, k0, k1, kc, o0, o1, oc, cst, lam_i, lam_o,
            speed_on,
        )  # fmt: skip
        ga00 = s[14]
        ga10 = s[15]
        pa00 = s[16]
        pa10 = s[17]
        pa20 = s[18]
        s = _ball_state(
            xj0, xj1, aj0, aj1, 0.0, 0.0, 0.0, 1.0, k0, k1, kc, o0, o1, oc, cst, lam_i, lam_o,
            speed_on,
        )  # fmt: skip
        ga01 = s[14]
        ga11 = s[15]
        pa01 = s[16]
        pa11 = s[17]
        pa21 = s[18]
        if not loaded[j]:  # an unloaded ball exerts nothing on the inner ring
            for r in range(5):
                parts[r, j] = 0.0
            continue
        cp = balls[B_COS, j]
        sp = balls[B_SIN, j]
        pm = st_pa * arm + lam_fi * st_mg
        parts[0, j] = st_pa
        parts[1, j] = st_pr * cp
        parts[2, j] = st_pr * sp
        parts[3, j] = pm * sp
        parts[4, j] = pm * cp
        # (∂g/∂X)^{-1} ∂g/∂A by Cramer's rule (2×2), columns A_1, A_2
        det = gx00 * gx11 - gx01 * gx10
        s00 = (gx11 * ga00 - gx01 * ga10) / det
        s10 = (gx00 * ga10 - gx10 * ga00) / det
        s01 = (gx11 * ga01 - gx01 * ga11) / det
        s11 = (gx00 * ga11 - gx10 * ga01) / det
        # local: rows (P_a, P_r, P_m), columns (A_1, A_2)
        l00 = pa00 - (px00 * s00 + px01 * s10)
        l01 = pa01 - (px00 * s01 + px01 * s11)
        l10 = pa10 - (px10 * s00 + px11 * s10)
        l11 = pa11 - (px10 * s01 + px11 * s11)
        l20 = pa20 - (px20 * s00 + px21 * s10)
        l21 = pa21 - (px20 * s01 + px21 * s11)
        l20 = l00 * arm + lam_fi * l20
        l21 = l01 * arm + lam_fi * l21
        for col in range(5):
            # column col of B_j: ∂A_1/∂q_col, ∂A_2/∂q_col (scalars: no array compiled)
            if col == 0:
                b0, b1 = 1.0, 0.0
            elif col == 1:
                b0, b1 = 0.0, cp
            elif col == 2:
                b0, b1 = 0.0, sp
            elif col == 3:
                b0, b1 = rad_i * sp, 0.0
            else:
                b0, b1 = -rad_i * cp, 0.0
            la = l00 * b0 + l01 * b1
            lr = l10 * b0 + l11 * b1
            lm = l20 * b0 + l21 * b1
            # C_j: (P_a, P_r, P_m) -> (F_a, F_x, F_y, M_x, M_y)
            jac[0, col] += la
            jac[1, col] += cp * lr
            jac[2, col] += sp * lr
            jac[3, col] += sp * lm
            jac[4, col] += -cp * lm
