r"""Compiled kernels of the dynamic model (seed 003): deviations, contacts, Newmark, statics.

Split out of :mod:`runout.models.dynamic` (which documents the model and re-exports these
names). Reference: R.K. Purohit, K. Purohit, "Dynamic analysis of ball bearings with effect of
preload and number of balls", 2006 (seed 003), eq. 2.1-2.5, 2.16 and §3 (Newmark-β with
Newton-Raphson).

Rotating phasors
----------------
Every angle of the model grows linearly in time: ball j at :math:`\theta_j(t) = \theta_{0j} +
\omega_c t` (eq. 2.18), the raceway harmonics at :math:`k(\theta_j - \omega_{i,o} t)`, the ball
harmonics at :math:`k\omega_b t`, the unbalance at :math:`\Omega t`. The Newmark kernel
therefore advances :math:`e^{i r t}` of each rate r by one multiplication with
:math:`e^{i r h}` per step instead of calling sin and cos: a raceway harmonic at ball j is
:math:`\operatorname{Re}(a e^{i(\varphi + k\theta_{0j})} e^{ik(\omega_c - \omega)t})`. Each
multiplication adds about one ulp of phase and modulus, so every :data:`ANCHOR_STEPS` steps
the phasors are recomputed from the exact angle: the deviations stay within ~1e-13 of the
direct evaluation (:func:`_deviations`, kept for the quasi-static kernel and the tests).
"""

from __future__ import annotations

import math

import numpy as np
from numba.extending import register_jitable
from numpy.typing import NDArray

from runout.analysis.results import SOLVER_RTOL
from runout.base._kernel import kernel
from runout.base._linalg import solve_spd3

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]
#: Packed harmonics of the inner ring, outer ring and balls: orders, amplitudes [m], phases
#: [rad] of each (:func:`runout.geometry.imperfections.pack_harmonics`) and the balls' offsets.
Harmonics = tuple[
    FloatArray, FloatArray, FloatArray, FloatArray, FloatArray, FloatArray,
    FloatArray, FloatArray, FloatArray, IntArray,
]  # fmt: skip

#: The rotating phasors of the Newmark kernels (:func:`newmark_kernel`): rates [rad/s],
#: rotations per step (cos, sin), ball, ring and ball-harmonic coefficients, ball offsets.
Phasors = tuple[FloatArray, FloatArray, FloatArray, FloatArray, FloatArray, IntArray]

#: Newton step tolerance relative to the reference approach.
NEWTON_RTOL = SOLVER_RTOL["dynamic"]
#: A quasi-static force balance holding to this fraction of (Σ ball loads + |load|) has
#: converged (the round-off floor of the sum over balls is ~Z × 1e-16 of it).
FORCE_RTOL = 1e-13
#: Steps between two recomputations of the rotating phasors from the exact angles (their
#: round-off grows by ~1e-16 per step in between).
ANCHOR_STEPS = 256
TWO_PI_K = 2.0 * math.pi

# kernel status codes
OK, NOT_CONVERGED, BLOWUP, NOT_FINITE = 0, 1, 2, 3

# indices of the scalar parameter vector of the kernels
P_H, P_M, P_C, P_A, P_G0, P_ZP, P_K = 0, 1, 2, 3, 4, 5, 6
P_WC, P_WI, P_WO, P_WB = 7, 8, 9, 10
P_FU, P_WU, P_FX, P_FY, P_FZ, P_TOL = 11, 12, 13, 14, 15, 16
N_PAR = 17

# columns of the spall table of the kernels (:attr:`DynamicSetup.spalls`, one row a defect)
#: 0 a raceway spall, 1 a ball spall.
S_BALL = 0
#: Raceway: angular speed of its ring [rad/s]; ball: signed contact rate of the ball [rad/s].
S_RATE = 1
#: Raceway: angle of the spall's centre on its ring [rad]; ball: 0 (facing the outer raceway).
S_ANGLE = 2
#: Radius of the spalled surface [m] (arc length per radian of the angle above).
S_ARC = 3
#: Width along the rolling direction [m], depth [m], radius of the ball that drops in [m].
S_WIDTH, S_DEPTH, S_RADIUS = 4, 5, 6
#: Ball spalls: the ball's index (0-based).
S_ELEMENT = 7
N_SP = 8


@register_jitable(no_cfunc_wrapper=True)
def spall_drop(angle: float, arc: float, width: float, depth: float, radius: float) -> float:
    r"""How far a ball's centre drops into a spall at ``angle`` from its centre [m].

    A ball of radius r over a spall of width w, its centre a distance x = arc·|angle| from the
    spall's centre, rests on the nearer edge, e = w/2 - x away (horizontally): it drops
    :math:`r - \sqrt{r^2 - e^2}` (0 at the edge, growing as :math:`e^2/2r`: a smooth entry),
    at most the depth; outside the spall (e <= 0) it does not drop. Over the centre of a
    spall deeper than it can reach this is the effective depth
    :math:`\min(d, D/2 - \sqrt{D^2/4 - w^2/4})`.

    Parameters
    ----------
    angle : float
        Angle of the contact point from the spall's centre [rad] (any turn: wrapped here).
    arc : float
        Radius of the spalled surface [m].
    width, depth : float
        Of the spall [m].
    radius : float
        Of the ball [m].

    Returns
    -------
    float
        Drop of the ball's centre [m] (>= 0).

    Notes
    -----
    The path of a ball's centre over a spall of N. Sawalhi and R. B. Randall, "Simulating gear
    and bearing interactions in the presence of faults: Part I. The combined gear bearing
    dynamic model and the simulation of localised bearing faults", Mechanical Systems and
    Signal Processing 22 (2008) 1924-1951, sec. 2.3 and Fig. 5 (the ball cannot reach the
    bottom of a spall narrower than itself; the depth seen follows the edge's geometry).
    """
    a = angle - TWO_PI_K * math.floor(angle / TWO_PI_K + 0.5)
    e = 0.5 * width - arc * abs(a)
    if e <= 0.0:
        return 0.0
    d = radius if e >= radius else radius - math.sqrt(radius * radius - e * e)
    return d if d < depth else depth


@register_jitable(no_cfunc_wrapper=True)
def slip_angle(t: float, slip: FloatArray) -> float:
    """Angle the cage has slipped by at time t [rad] (0 without slip).

    ``slip`` is ``[t0, T, φ_0, φ_1, ...]``: the slip angle at the knots t0 + kT, linear in
    between (the cage's speed constant over each interval); empty: no slip.
    """
    n = slip.size - 2
    if n < 2:
        return 0.0
    u: float = (t - slip[0]) / slip[1]
    k = math.floor(u)
    if k < 0:
        k = 0
    elif k > n - 2:
        k = n - 2
    f = u - k
    a: float = slip[2 + k]
    b: float = slip[3 + k]
    return a + (b - a) * f


@register_jitable(no_cfunc_wrapper=True)
def _slip_balls(phi: float, cth: FloatArray, sth: FloatArray) -> None:
    """Turn every ball's (cos, sin) by the slip angle ``phi`` [rad]."""
    c = math.cos(phi)
    s = math.sin(phi)
    for j in range(cth.size):
        cj = cth[j]
        sj = sth[j]
        cth[j] = cj * c - sj * s
        sth[j] = cj * s + sj * c


@register_jitable(no_cfunc_wrapper=True)
def _spall_drops(
    t: float, sp: FloatArray, theta0: FloatArray, wc: float, phi: float, dr: FloatArray
) -> None:
    """Drop of every ball into the spalls at time t [m] (:func:`spall_drop`), into ``dr``.

    ``phi`` is the cage's slip angle [rad] (:func:`slip_angle`): the balls' angles and, in
    proportion, their spin lag by it.
    """
    for j in range(dr.size):
        dr[j] = 0.0
    for i in range(sp.shape[0]):
        arc, w, dp, r = sp[i, S_ARC], sp[i, S_WIDTH], sp[i, S_DEPTH], sp[i, S_RADIUS]
        if sp[i, S_BALL] == 0.0:
            # raceway: the contact point's angle on the ring, from the spall's centre
            for j in range(dr.size):
                ang = theta0[j] + (wc - sp[i, S_RATE]) * t + phi - sp[i, S_ANGLE]
                dr[j] += spall_drop(ang, arc, w, dp, r)
        else:
            # ball: its spall meets the outer raceway at spin angle 0, the inner at pi
            j = int(sp[i, S_ELEMENT])
            ang = sp[i, S_RATE] * (t + (phi / wc if wc != 0.0 else 0.0)) + sp[i, S_ANGLE]
            dr[j] += max(spall_drop(ang, arc, w, dp, r), spall_drop(ang - math.pi, arc, w, dp, r))


@kernel()
def _hsum(k: FloatArray, a: FloatArray, p: FloatArray, lo: int, hi: int, angle: float) -> float:
    s = 0.0
    for i in range(lo, hi):
        s += a[i] * math.cos(k[i] * angle + p[i])
    return s


@kernel()
def _deviations(
    t: float,
    par: FloatArray,
    theta0: FloatArray,
    hk: Harmonics,
    cth: FloatArray,
    sth: FloatArray,
    gap: FloatArray,
    wb: FloatArray,
) -> None:
    """Ball angles (cos, sin), radial gap at q = 0 and ball deviation at time t."""
    z = theta0.size
    wc = par[P_WC]
    wi = par[P_WI]
    wo = par[P_WO]
    spin = par[P_WB] * t
    ik, ia, ip, ok, oa, op, bk, ba, bp, boff = hk
    for j in range(z):
        th = theta0[j] + wc * t
        cth[j] = math.cos(th)
        sth[j] = math.sin(th)
        g = par[P_G0]
        if ik.size:
            g += _hsum(ik, ia, ip, 0, ik.size, th - wi * t)
        if ok.size:
            g -= _hsum(ok, oa, op, 0, ok.size, th - wo * t)
        gap[j] = g
        wb[j] = _hsum(bk, ba, bp, boff[j], boff[j + 1], spin) if bk.size else 0.0


def _phasor_tables(
    par: FloatArray, theta0: FloatArray, hk: Harmonics
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """Rates and coefficients of the rotating phasors of :func:`_phasor_deviations`.

    Set-up of the Newmark kernels, in Python (``math``, the same bits as compiled): compiled,
    it would only make the first run of the model wait for its compilation.

    Phasor 0 is the cage :math:`e^{i\\omega_c t}`, 1 the unbalance :math:`e^{i\\Omega t}`,
    then one per raceway harmonic (inner, then outer; rate :math:`k(\\omega_c - \\omega)`)
    and one per ball harmonic (rate :math:`k\\omega_b`).

    Returns
    -------
    rate : ndarray, shape (2 + n_ring + n_ball,)
        Angular rate of each phasor [rad/s].
    ball : ndarray, shape (Z, 2)
        :math:`e^{i\\theta_{0j}}` (cos, sin).
    ring : ndarray, shape (Z, n_ring, 2)
        :math:`\\pm a e^{i(\\varphi + k\\theta_{0j})}` [m], + inner, − outer (gap sign).
    bcoef : ndarray, shape (n_ball, 2)
        :math:`a e^{i\\varphi}` of each ball harmonic [m].
    """
    ik, ia, ip, ok, oa, op, bk, ba, bp, _boff = hk
    z = theta0.size
    ni = ik.size
    nr = ni + ok.size
    nb = bk.size
    wc = par[P_WC]
    rate = np.empty(2 + nr + nb)
    rate[0] = wc
    rate[1] = par[P_WU]
    ball = np.empty((z, 2))
    ring = np.empty((z, nr, 2))
    for j in range(z):
        ball[j, 0] = math.cos(theta0[j])
        ball[j, 1] = math.sin(theta0[j])
    for m in range(nr):
        if m < ni:
            kk, aa, pp, sign, w = ik[m], ia[m], ip[m], 1.0, par[P_WI]
        else:
            i = m - ni
            kk, aa, pp, sign, w = ok[i], oa[i], op[i], -1.0, par[P_WO]
        rate[2 + m] = kk * (wc - w)
        for j in range(z):
            arg = kk * theta0[j] + pp
            ring[j, m, 0] = sign * aa * math.cos(arg)
            ring[j, m, 1] = sign * aa * math.sin(arg)
    bcoef = np.empty((nb, 2))
    for i in range(nb):
        rate[2 + nr + i] = bk[i] * par[P_WB]
        bcoef[i, 0] = ba[i] * math.cos(bp[i])
        bcoef[i, 1] = ba[i] * math.sin(bp[i])
    return rate, ball, ring, bcoef


@kernel()
def _phasor_anchor(t: float, rate: FloatArray, ph: FloatArray) -> None:
    """Set every phasor to its exact value :math:`e^{i r t}` at time t [s]."""
    for m in range(rate.size):
        ph[m, 0] = math.cos(rate[m] * t)
        ph[m, 1] = math.sin(rate[m] * t)


@kernel()
def _phasor_rotate(ph: FloatArray, rot: FloatArray) -> None:
    """Advance every phasor by one step: multiply by its :math:`e^{i r h}`."""
    for m in range(ph.shape[0]):
        pr = ph[m, 0]
        pi = ph[m, 1]
        ph[m, 0] = pr * rot[m, 0] - pi * rot[m, 1]
        ph[m, 1] = pr * rot[m, 1] + pi * rot[m, 0]


# register_jitable: compiled into its caller, without Python and C entry points of its own
# (first-run compilation time); a helper that several compiled functions of one run call
# stays njit (compiled once, not once per caller).
@register_jitable(no_cfunc_wrapper=True)
def _phasor_balls(ph: FloatArray, ball: FloatArray, cth: FloatArray, sth: FloatArray) -> None:
    """cos and sin of the ball angles θ_j from the cage phasor (perfect parts: nothing else)."""
    er = ph[0, 0]
    ei = ph[0, 1]
    for j in range(ball.shape[0]):
        cth[j] = ball[j, 0] * er - ball[j, 1] * ei
        sth[j] = ball[j, 0] * ei + ball[j, 1] * er


@kernel()
def _phasor_deviations(
    ph: FloatArray,
    ball: FloatArray,
    ring: FloatArray,
    bcoef: FloatArray,
    boff: IntArray,
    g0: float,
    cth: FloatArray,
    sth: FloatArray,
    gap: FloatArray,
    wb: FloatArray,
) -> None:
    """What :func:`_deviations` gives, from the phasors of :func:`_phasor_tables` (no trig)."""
    er = ph[0, 0]
    ei = ph[0, 1]
    nr = ring.shape[1]
    for j in range(ball.shape[0]):
        cth[j] = ball[j, 0] * er - ball[j, 1] * ei
        sth[j] = ball[j, 0] * ei + ball[j, 1] * er
        g = g0
        for m in range(nr):
            g += ring[j, m, 0] * ph[2 + m, 0] - ring[j, m, 1] * ph[2 + m, 1]
        gap[j] = g
        w = 0.0
        for i in range(boff[j], boff[j + 1]):
            w += bcoef[i, 0] * ph[2 + nr + i, 0] - bcoef[i, 1] * ph[2 + nr + i, 1]
        wb[j] = w


@kernel()
def _contact(
    q0: float,
    q1: float,
    q2: float,
    cth: FloatArray,
    sth: FloatArray,
    gap: FloatArray,
    wb: FloatArray,
    a: float,
    zp: float,
    k: float,
    ndof: int,
) -> tuple[float, float, float, float, float, float, float, float, float, int]:
    """Sum of Q_j n_j (force of the contacts resisting q) and its Jacobian (symmetric)."""
    f0 = f1 = f2 = 0.0
    k00 = k01 = k02 = k11 = k12 = k22 = 0.0
    loaded = 0
    sa = zp + (q2 if ndof == 3 else 0.0)
    for j in range(cth.size):
        g = gap[j] + q0 * cth[j] + q1 * sth[j]
        sr = a + g
        s = math.sqrt(sr * sr + sa * sa)
        d = (g * (a + sr) + sa * sa) / (s + a) + wb[j]
        if d <= 0.0:
            continue
        loaded += 1
        sd = math.sqrt(d)
        q = k * d * sd
        dq = 1.5 * k * sd
        nx = sr * cth[j] / s
        ny = sr * sth[j] / s
        nz = sa / s
        f0 += q * nx
        f1 += q * ny
        f2 += q * nz
        geo = q / s
        kk = dq - geo
        k00 += kk * nx * nx + geo * cth[j] * cth[j]
        k01 += kk * nx * ny + geo * cth[j] * sth[j]
        k11 += kk * ny * ny + geo * sth[j] * sth[j]
        k02 += kk * nx * nz
        k12 += kk * ny * nz
        k22 += kk * nz * nz + geo
    return f0, f1, f2, k00, k01, k02, k11, k12, k22, loaded


@register_jitable(no_cfunc_wrapper=True)
def _solve3(
    j00: float,
    j01: float,
    j02: float,
    j11: float,
    j12: float,
    j22: float,
    r0: float,
    r1: float,
    r2: float,
    ndof: int,
) -> tuple[float, float, float]:
    """Solve the symmetric 2x2 (ndof 2) or 3x3 system J s = r in closed form."""
    if ndof == 2:
        det = j00 * j11 - j01 * j01
        return (j11 * r0 - j01 * r1) / det, (j00 * r1 - j01 * r0) / det, 0.0
    s0, s1, s2, _ok = solve_spd3(j00, j01, j02, j11, j12, j22, r0, r1, r2)
    return s0, s1, s2


@kernel()
def _newmark_radial(
    n_steps: int,
    stride: int,
    t_start: float,
    state: FloatArray,
    par: FloatArray,
    phasors: Phasors,
    sp: FloatArray,
    theta0: FloatArray,
    slip: FloatArray,
    max_iter: int,
    out: FloatArray,
) -> tuple[int, int, int, int]:
    """:func:`newmark_kernel` in the plane without axial offset (two degrees of freedom, z_p = 0).

    There the exact geometry of :func:`_contact` reduces to seed 003 eq. 2.3-2.5: s_j = A +
    g_j, so δ_j = g_j + w_bj and n_j = (cos θ_j, sin θ_j) (the geometric stiffness cancels).
    The same scheme and tests, with that contact written into the loop (no z row, no 3x3
    solve) and, for perfect parts, without re-evaluating the constant gap.
    """
    h = par[P_H]
    m = par[P_M]
    c = par[P_C]
    k = par[P_K]
    tol = par[P_TOL]
    c0 = 4.0 / (h * h)
    c1 = 4.0 / h
    hh = 0.5 * h
    jd = m * c0 + 2.0 * c / h
    rate, rot, ball, ring, bcoef, boff = phasors
    z = ball.shape[0]
    # allocated here (fresh arrays: the compiler knows they alias nothing, the loop below
    # runs a third faster than on arrays passed in) and filled by loops: np.full and np.zeros
    # would each compile an implementation of their own
    cth = np.empty(z)
    sth = np.empty(z)
    gap = np.empty(z)
    wb = np.empty(z)
    gw = np.empty(z)  # radial gap + ball deviation at q = 0: constant for perfect parts
    gx = np.empty(z)  # the same less the drops into the spalls
    dr = np.empty(z)
    for j in range(z):
        gap[j] = gw[j] = gx[j] = par[P_G0]
        wb[j] = dr[j] = 0.0
    spalled = sp.shape[0] > 0
    slipping = slip.size > 3
    wc = par[P_WC]
    ph = np.empty((rate.size, 2))
    g0 = par[P_G0]
    wavy = rate.size > 2
    q0, q1 = state[0], state[1]
    v0, v1 = state[3], state[4]
    a0, a1 = state[6], state[7]
    fx, fy = par[P_FX], par[P_FY]
    fu = par[P_FU]
    iters = 0
    min_loaded = z
    rec = 0
    limit = 0.5 * par[P_A]
    for n in range(n_steps):
        if n % ANCHOR_STEPS == 0:
            _phasor_anchor(t_start + (n + 1) * h, rate, ph)
        else:
            _phasor_rotate(ph, rot)
        if wavy:
            _phasor_deviations(ph, ball, ring, bcoef, boff, g0, cth, sth, gap, wb)
            for j in range(z):
                gw[j] = gap[j] + wb[j]
        else:
            _phasor_balls(ph, ball, cth, sth)
        phi = 0.0
        if slipping:
            phi = slip_angle(t_start + (n + 1) * h, slip)
            _slip_balls(phi, cth, sth)
        if spalled:
            _spall_drops(t_start + (n + 1) * h, sp, theta0, wc, phi, dr)
            for j in range(z):
                gx[j] = gw[j] - dr[j]
        else:
            for j in range(z):
                gx[j] = gw[j]
        e0 = fx + fu * ph[1, 0]
        e1 = fy + fu * ph[1, 1]
        p0 = q0 + h * v0 + 0.5 * h * h * a0
        p1 = q1 + h * v1 + 0.5 * h * h * a1
        converged = False
        loaded = z
        for _ in range(max_iter):
            iters += 1
            f0 = f1 = 0.0
            k00 = k01 = k11 = 0.0
            loaded = 0
            for j in range(z):
                cj = cth[j]
                sj = sth[j]
                d = gx[j] + p0 * cj + p1 * sj
                if d > 0.0:
                    loaded += 1
                    sd = math.sqrt(d)
                    q = k * d * sd
                    dq = 1.5 * k * sd
                    f0 += q * cj
                    f1 += q * sj
                    k00 += dq * cj * cj
                    k01 += dq * cj * sj
                    k11 += dq * sj * sj
            na0 = c0 * (p0 - q0) - c1 * v0 - a0
            na1 = c0 * (p1 - q1) - c1 * v1 - a1
            r0 = m * na0 + c * (v0 + hh * (a0 + na0)) + f0 - e0
            r1 = m * na1 + c * (v1 + hh * (a1 + na1)) + f1 - e1
            j00 = jd + k00
            j11 = jd + k11
            det = j00 * j11 - k01 * k01
            s0 = (j11 * r0 - k01 * r1) / det
            s1 = (j00 * r1 - k01 * r0) / det
            p0 -= s0
            p1 -= s1
            if max(abs(s0), abs(s1)) <= tol:
                converged = True
                break
        if not (math.isfinite(p0) and math.isfinite(p1)):
            state[0], state[1], state[2] = q0, q1, 0.0
            return NOT_FINITE, n, iters, min_loaded
        if not converged:
            state[0], state[1], state[2] = q0, q1, 0.0
            return NOT_CONVERGED, n, iters, min_loaded
        if math.sqrt(p0 * p0 + p1 * p1) > limit:
            return BLOWUP, n, iters, min_loaded
        na0 = c0 * (p0 - q0) - c1 * v0 - a0
        na1 = c0 * (p1 - q1) - c1 * v1 - a1
        v0 += hh * (a0 + na0)
        v1 += hh * (a1 + na1)
        a0, a1 = na0, na1
        q0, q1 = p0, p1
        if loaded < min_loaded:
            min_loaded = loaded
        if (n + 1) % stride == 0 and rec < out.shape[0]:
            out[rec, 0] = q0
            out[rec, 1] = q1
            out[rec, 2] = 0.0
            rec += 1
    state[0], state[1], state[2] = q0, q1, 0.0
    state[3], state[4], state[5] = v0, v1, 0.0
    state[6], state[7], state[8] = a0, a1, 0.0
    return OK, -1, iters, min_loaded


def newmark_kernel(
    n_steps: int,
    stride: int,
    t_start: float,
    state: FloatArray,
    par: FloatArray,
    theta0: FloatArray,
    hk: Harmonics,
    ndof: int,
    max_iter: int,
    out: FloatArray,
    spalls: FloatArray | None = None,
    slip: FloatArray | None = None,
) -> tuple[int, int, int, int]:
    """Integrate seed 003 eq. 2.16 (module form) over ``n_steps`` Newmark steps (compiled).

    Average-acceleration Newmark-β (β = 1/4, γ = 1/2): with step h,

    .. math::
        a_{n+1} = \\tfrac{4}{h^2}(q_{n+1} - q_n) - \\tfrac4h v_n - a_n, \\quad
        v_{n+1} = v_n + \\tfrac h2 (a_n + a_{n+1}),

    and :math:`R(q_{n+1}) = m a_{n+1} + c v_{n+1} + \\sum_j Q_j n_j - F(t_{n+1}) = 0` solved
    by Newton–Raphson with the Jacobian :math:`(4m/h^2 + 2c/h) I + K_t` (closed-form solve).
    The ball angles, waviness and unbalance come from rotating phasors (module docstring),
    recomputed from the exact angles every :data:`ANCHOR_STEPS` steps.
    A Python dispatcher onto two compiled kernels, :func:`_newmark_radial` (two degrees of
    freedom without axial offset) and :func:`_newmark_general`, so that a run compiles only
    the one it uses.

    Parameters
    ----------
    n_steps : int
        Steps to take.
    stride : int
        Record q every ``stride`` steps (the first record is the state after ``stride`` steps).
    t_start : float
        Time of ``state`` [s].
    state : ndarray, shape (9,)
        q, v, a (3 each) [m, m/s, m/s²]; updated in place.
    par : ndarray
        Scalars (:meth:`DynamicSetup.params`).
    theta0 : ndarray, shape (Z,)
        Ball angles at t = 0 [rad].
    hk : tuple of ndarray
        Packed waviness (:attr:`DynamicSetup.harmonics`).
    ndof : int
        2 or 3.
    max_iter : int
        Newton iterations per step.
    out : ndarray, shape (n_steps // stride, 3)
        Recorded q [m].
    spalls : ndarray, shape (n, N_SP), optional
        Localized defects (:attr:`DynamicSetup.spalls`): each ball's approach drops by
        :func:`spall_drop` while its contact point is over one. Default none.
    slip : ndarray, optional
        The cage's slip angle at knots (:func:`slip_angle`): every ball's angle, and its spin
        in proportion, lag by it. Only for parts without waviness (their phasors do not
        slip). Default none.

    Returns
    -------
    status : int
        0 ok, 1 not converged, 2 rotor left the bearing, 3 not finite.
    step : int
        Failing step (-1 if ok).
    iterations : int
        Newton iterations taken in total.
    min_loaded : int
        Fewest loaded balls at any step.
    """
    # the phasors' tables and rotations per step, set up here (not compiled: see _phasor_tables)
    rate, ball, ring, bcoef = _phasor_tables(par, theta0, hk)
    h = float(par[P_H])
    rot = np.array([[math.cos(r * h), math.sin(r * h)] for r in rate.tolist()]).reshape(-1, 2)
    phasors = (rate, rot, ball, ring, bcoef, hk[9])
    sp = np.zeros((0, N_SP)) if spalls is None else np.ascontiguousarray(spalls, np.float64)
    th0 = np.ascontiguousarray(theta0, np.float64)
    sl = np.zeros(0) if slip is None else np.ascontiguousarray(slip, np.float64)
    if sl.size > 3 and rate.size > 2:
        raise ValueError("slip is modelled for parts without waviness (rotating phasors)")
    if ndof == 2 and par[P_ZP] == 0.0:
        # in the plane without axial offset the exact geometry is seed 003 eq. 2.3-2.5
        return _newmark_radial(
            n_steps, stride, t_start, state, par, phasors, sp, th0, sl, max_iter, out
        )
    return _newmark_general(
        n_steps, stride, t_start, state, par, phasors, sp, th0, sl, ndof, max_iter, out
    )


@kernel()
def _newmark_general(
    n_steps: int,
    stride: int,
    t_start: float,
    state: FloatArray,
    par: FloatArray,
    phasors: Phasors,
    sp: FloatArray,
    theta0: FloatArray,
    slip: FloatArray,
    ndof: int,
    max_iter: int,
    out: FloatArray,
) -> tuple[int, int, int, int]:
    """:func:`newmark_kernel` with the exact contact geometry (:func:`_contact`), any z_p."""
    h = par[P_H]
    m = par[P_M]
    c = par[P_C]
    a = par[P_A]
    zp = par[P_ZP]
    k = par[P_K]
    tol = par[P_TOL]
    c0 = 4.0 / (h * h)
    c1 = 4.0 / h
    jd = m * c0 + 2.0 * c / h
    rate, rot, ball, ring, bcoef, boff = phasors
    z = ball.shape[0]
    cth = np.empty(z)  # allocated here, filled by loops: see _newmark_radial
    sth = np.empty(z)
    gap = np.empty(z)  # constant for perfect parts
    wb = np.empty(z)
    wx = np.empty(z)  # ball deviation less the drops into the spalls
    dr = np.empty(z)
    for j in range(z):
        gap[j] = par[P_G0]
        wb[j] = wx[j] = dr[j] = 0.0
    spalled = sp.shape[0] > 0
    slipping = slip.size > 3
    wc = par[P_WC]
    ph = np.empty((rate.size, 2))
    g0 = par[P_G0]
    wavy = rate.size > 2
    q0, q1, q2 = state[0], state[1], state[2]
    v0, v1, v2 = state[3], state[4], state[5]
    a0, a1, a2 = state[6], state[7], state[8]
    if ndof == 2:
        q2 = v2 = a2 = 0.0
    fx, fy, fz = par[P_FX], par[P_FY], par[P_FZ]
    fu = par[P_FU]
    iters = 0
    min_loaded = z
    rec = 0
    limit = 0.5 * a
    for n in range(n_steps):
        if n % ANCHOR_STEPS == 0:
            _phasor_anchor(t_start + (n + 1) * h, rate, ph)
        else:
            _phasor_rotate(ph, rot)
        if wavy:
            _phasor_deviations(ph, ball, ring, bcoef, boff, g0, cth, sth, gap, wb)
        else:
            _phasor_balls(ph, ball, cth, sth)
        phi = 0.0
        if slipping:
            phi = slip_angle(t_start + (n + 1) * h, slip)
            _slip_balls(phi, cth, sth)
        if spalled:
            _spall_drops(t_start + (n + 1) * h, sp, theta0, wc, phi, dr)
        for j in range(z):
            wx[j] = wb[j] - dr[j]
        e0 = fx + fu * ph[1, 0]
        e1 = fy + fu * ph[1, 1]
        e2 = fz
        # predictor
        p0 = q0 + h * v0 + 0.5 * h * h * a0
        p1 = q1 + h * v1 + 0.5 * h * h * a1
        p2 = q2 + h * v2 + 0.5 * h * h * a2 if ndof == 3 else 0.0
        converged = False
        loaded = z
        for _ in range(max_iter):
            iters += 1
            f0, f1, f2, k00, k01, k02, k11, k12, k22, loaded = _contact(
                p0, p1, p2, cth, sth, gap, wx, a, zp, k, ndof
            )
            na0 = c0 * (p0 - q0) - c1 * v0 - a0
            na1 = c0 * (p1 - q1) - c1 * v1 - a1
            na2 = c0 * (p2 - q2) - c1 * v2 - a2
            nv0 = v0 + 0.5 * h * (a0 + na0)
            nv1 = v1 + 0.5 * h * (a1 + na1)
            nv2 = v2 + 0.5 * h * (a2 + na2)
            r0 = m * na0 + c * nv0 + f0 - e0
            r1 = m * na1 + c * nv1 + f1 - e1
            r2 = m * na2 + c * nv2 + f2 - e2
            s0, s1, s2 = _solve3(jd + k00, k01, k02, jd + k11, k12, jd + k22, r0, r1, r2, ndof)
            p0 -= s0
            p1 -= s1
            p2 -= s2
            if max(abs(s0), abs(s1), abs(s2)) <= tol:
                converged = True
                break
        if not (math.isfinite(p0) and math.isfinite(p1) and math.isfinite(p2)):
            state[0], state[1], state[2] = q0, q1, q2
            return NOT_FINITE, n, iters, min_loaded
        if not converged:
            state[0], state[1], state[2] = q0, q1, q2
            return NOT_CONVERGED, n, iters, min_loaded
        if math.sqrt(p0 * p0 + p1 * p1 + p2 * p2) > limit:
            return BLOWUP, n, iters, min_loaded
        na0 = c0 * (p0 - q0) - c1 * v0 - a0
        na1 = c0 * (p1 - q1) - c1 * v1 - a1
        na2 = c0 * (p2 - q2) - c1 * v2 - a2 if ndof == 3 else 0.0
        v0 += 0.5 * h * (a0 + na0)
        v1 += 0.5 * h * (a1 + na1)
        v2 += 0.5 * h * (a2 + na2)
        a0, a1, a2 = na0, na1, na2
        q0, q1, q2 = p0, p1, p2
        if loaded < min_loaded:
            min_loaded = loaded
        if (n + 1) % stride == 0 and rec < out.shape[0]:
            out[rec, 0] = q0
            out[rec, 1] = q1
            out[rec, 2] = q2
            rec += 1
    state[0], state[1], state[2] = q0, q1, q2
    state[3], state[4], state[5] = v0, v1, v2
    state[6], state[7], state[8] = a0, a1, a2
    return OK, -1, iters, min_loaded


def _in_order(terms: FloatArray, start: float = 0.0) -> FloatArray:
    """``start`` plus the terms along the first axis, added one by one in order as the
    compiled loops add them (NumPy's ``sum`` adds pairwise: other round-off)."""
    if terms.shape[0] == 0:
        return np.full(terms.shape[1:], start)
    steps = terms.copy()
    steps[0] += start
    return np.asarray(np.cumsum(steps, axis=0)[-1])


def _contact_terms(
    q0: float,
    q1: float,
    q2: float,
    dev: tuple[FloatArray, FloatArray, FloatArray, FloatArray],
    a: float,
    zp: float,
    ndof: int,
) -> tuple[FloatArray, FloatArray, FloatArray, float]:
    """Approaches δ_j [m], radial and total distances sr_j, s_j [m] of every ball's groove
    centres, and the axial one s_a [m] (the geometry of :func:`_contact`, over all balls)."""
    cth, sth, gap, wb = dev
    sa = zp + (q2 if ndof == 3 else 0.0)
    g = gap + q0 * cth + q1 * sth
    sr = a + g
    s = np.sqrt(sr * sr + sa * sa)
    d = (g * (a + sr) + sa * sa) / (s + a) + wb
    return d, sr, s, sa


def _static_deviations(
    t: float, par: FloatArray, theta0: FloatArray, hk: Harmonics
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """:func:`_deviations` in NumPy: cos θ_j, sin θ_j, gap and ball deviation at time t."""
    ik, ia, ip, ok, oa, op, bk, ba, bp, boff = hk
    th = theta0 + par[P_WC] * t
    gap = np.full(theta0.size, par[P_G0])
    if ik.size:
        angle = th - par[P_WI] * t
        gap = gap + _in_order(ia[:, None] * np.cos(ik[:, None] * angle + ip[:, None]))
    if ok.size:
        angle = th - par[P_WO] * t
        gap = gap - _in_order(oa[:, None] * np.cos(ok[:, None] * angle + op[:, None]))
    terms = ba * np.cos(bk * (par[P_WB] * t) + bp)
    wb = np.array([_in_order(terms[boff[j] : boff[j + 1]]) for j in range(theta0.size)])
    return np.cos(th), np.sin(th), gap, wb


def static_kernel(
    times: FloatArray,
    q_start: FloatArray,
    par: FloatArray,
    theta0: FloatArray,
    hk: Harmonics,
    ndof: int,
    max_iter: int,
) -> tuple[FloatArray, int, int]:
    """Quasi-static solution of the same contact model at each instant.

    NumPy over the balls, not compiled: a run solves an instant or two (the start of the
    integration), where compiling the solve would make the first run of the model wait some
    2 s. The steps and tests of the compiled Newmark kernel's contact (:func:`_contact`).
    Newton's method on the convex potential :math:`\\Pi(q) = \\sum_j \\tfrac{K_n}{2.5}
    [\\delta_j]_+^{5/2} - F(t)\\cdot q` (inertia and damping dropped), Armijo backtracking and
    a warm start from the previous instant.

    An instant has converged when the Newton correction is below the tolerance, or when the
    force balance itself holds to round-off, :math:`\\max_i |\\sum_j Q_j n_{ji} - F_i| \\le`
    :data:`FORCE_RTOL` :math:`(\\sum_j Q_j + |F|)`. The second test is needed when the
    equilibrium is not unique: a single loaded ball (a ball straight under the load, its
    neighbours inside the play, e.g. Z divisible by 4 and the load along −y) holds the rotor
    only along its own line, so every position across it within the play is an equilibrium
    (the Hessian of Π is singular there). The round-off force across (~1e-16 of the load)
    then drives regularised Newton corrections that never fall below the position tolerance,
    although the forces balance. The iterate then stays close to where it came from (from
    q = 0: within picometres of the symmetric equilibrium across the load).

    Returns
    -------
    q : ndarray, shape (n, 3)
        Rotor centre [m].
    status : int
        0 ok, 1 not converged.
    instant : int
        Failing instant (-1 if ok).
    """
    a, zp, k, tol = float(par[P_A]), float(par[P_ZP]), float(par[P_K]), float(par[P_TOL])
    fx, fy, fz = float(par[P_FX]), float(par[P_FY]), float(par[P_FZ])
    fu, wu = float(par[P_FU]), float(par[P_WU])
    n = times.size
    q = np.zeros((n, 3))
    p0, p1, p2 = float(q_start[0]), float(q_start[1]), float(q_start[2])
    if ndof == 2:
        p2 = 0.0
    # tiny regularisation: keeps Newton moving while few balls are loaded
    reg = 1e-9 * k * math.sqrt(tol / NEWTON_RTOL)

    def potential(
        q0: float, q1: float, q2: float, dev: tuple[FloatArray, ...], e: tuple[float, ...]
    ) -> float:
        d = _contact_terms(q0, q1, q2, dev, a, zp, ndof)[0]  # type: ignore[arg-type]
        d = d[d > 0.0]
        en = -(e[0] * q0 + e[1] * q1 + (e[2] * q2 if ndof == 3 else 0.0))
        return float(_in_order(k / 2.5 * d * d * np.sqrt(d), en))

    for i, t in enumerate(times.tolist()):
        dev = _static_deviations(t, par, theta0, hk)
        cth, sth = dev[0], dev[1]
        e = (fx + fu * math.cos(wu * t), fy + fu * math.sin(wu * t), fz)
        converged = False
        scale = math.sqrt(e[0] * e[0] + e[1] * e[1] + (e[2] * e[2] if ndof == 3 else 0.0))
        for _ in range(max_iter):
            # the sums of _contact over the loaded balls
            d, sr, s, sa = _contact_terms(p0, p1, p2, dev, a, zp, ndof)
            on = d > 0.0
            d, sr, s, c_on, s_on = d[on], sr[on], s[on], cth[on], sth[on]
            sd = np.sqrt(d)
            load = k * d * sd
            nx, ny, nz = sr * c_on / s, sr * s_on / s, sa / s
            geo = load / s
            kk = 1.5 * k * sd - geo
            r0 = float(_in_order(load * nx)) - e[0]
            r1 = float(_in_order(load * ny)) - e[1]
            r2 = float(_in_order(load * nz)) - e[2]
            k00 = float(_in_order(kk * nx * nx + geo * c_on * c_on))
            k01 = float(_in_order(kk * nx * ny + geo * c_on * s_on))
            k11 = float(_in_order(kk * ny * ny + geo * s_on * s_on))
            k02 = float(_in_order(kk * nx * nz))
            k12 = float(_in_order(kk * ny * nz))
            k22 = float(_in_order(kk * nz * nz + geo))
            worst = max(abs(r0), abs(r1), abs(r2) if ndof == 3 else 0.0)
            if worst <= FORCE_RTOL * (float(_in_order(load)) + scale):
                converged = True  # forces balance to round-off (see the docstring)
                break
            if ndof == 2:  # _solve3's operations, in Python (nothing to compile)
                det = (k00 + reg) * (k11 + reg) - k01 * k01
                s0 = ((k11 + reg) * r0 - k01 * r1) / det
                s1 = ((k00 + reg) * r1 - k01 * r0) / det
                s2 = 0.0
            else:  # the compiled solve's Python source
                s0, s1, s2, _ok = solve_spd3.py_func(  # type: ignore[no-untyped-call]
                    k00 + reg, k01, k02, k11 + reg, k12, k22 + reg, r0, r1, r2
                )
            big = max(abs(s0), abs(s1), abs(s2))
            step = 1.0
            if big > 1e-3 * tol / NEWTON_RTOL:
                en0 = potential(p0, p1, p2, dev, e)
                slope = -(r0 * s0 + r1 * s1 + r2 * s2)
                for _ls in range(60):
                    en1 = potential(p0 - step * s0, p1 - step * s1, p2 - step * s2, dev, e)
                    if en1 <= en0 + 1e-4 * step * slope:
                        break
                    step *= 0.5
            p0 -= step * s0
            p1 -= step * s1
            p2 -= step * s2
            if step * big <= tol:
                converged = True
                break
        if not converged:
            return q, 1, i
        q[i, 0] = p0
        q[i, 1] = p1
        q[i, 2] = p2
    return q, 0, -1
