r"""Compiled kernels of the rigid constraint model (seed 004): support functions, gaps, solve.

Split out of :mod:`runout.models.roller_constraint`, which documents the model (Y. Yu et al.,
"Prediction method for the radial runout of inner ring in cylindrical roller bearings", Math.
Probl. Eng., 2017, seed 004 eq. 1-16 and §5) and calls :func:`_solve_all`.

Bodies are packed (:data:`Bodies`, built by ``roller_constraint._pack``): index 0 inner
raceway, 1 outer raceway, 2 + j roller j. ``r0[b]`` is the base radius and the harmonics of
body b are ``off[b]:off[b+1]``; the profile in the fixed frame is
:math:`\rho(\theta) = r_0 + \sum_m a_m\cos(k_m(\theta - \chi) + \varphi_m)` (eq. 1, 4-7)
with the body's current turn χ.

Work saved per rotation angle (results bit for bit those of the direct method)
--------------------------------------------------------------------------------
* The gaps reported at the stable position are those the last feasibility check
  (:func:`_worst`) computed at that very centre; only the others (the two contact rollers
  and those it cleared by their bound) are computed there, once.
* :func:`_worst` clears a roller by a certified lower bound on its gap (:func:`_gap_bound`,
  the base circles less the largest deviations) before its exact Newton gap: a vertex the
  walk rejects costs no exact gap of a roller that cannot interfere.
* The candidate rollers are ordered by an insertion sort into a preallocated array.
* :func:`_solve_all` releases the GIL, so independent solves (the order sweep of the
  model files) run on parallel threads (``roller_constraint.solve_many``).

Work saved per solve of the order sweep (centres to round-off of the direct method)
-----------------------------------------------------------------------------------
The sweep (``_roller_solve.order_sweep``: 123 solves of 721 angles for the NU209 example)
wants only each solve's runout. Measured single-thread on the NU209 example: 1.87-1.90 s of
CPU before, 0.60 s after (BENCHMARKS.md, "Runs that write quickly").

* Settling shared (``settle``): with the harmonic on the loaded ring, the fixed ring and
  the rollers are the perfect bearing's, and so are the settled radii at every angle
  (``SETTLE_GIVEN``, bit for bit); a roller harmonic is the same on every roller in its
  cage frame and the fixed ring is round, so every roller settles at the same radius at a
  given angle: the first candidate settles, the others take its radius (``SETTLE_ONCE``).
* Warm starts (``warm``): each support's Newton on δ starts from the support point of the
  gap's iteration before; each gap's Newton on ψ from the normal of the Newton iteration
  before (the vertex), the previous settling step's normal moved by dψ/ds (settling), or
  the roller's normal at the angle before (its first settling step). The stops are the
  same steps (1e-9 rad, 1e-10 m), so the solutions agree with the cold ones to round-off
  (2.9e-17 m on the sweep's runouts).
* Roller directions shared (``radii``): cos β, sin β and the angle from the contact side of
  every roller at every angle are the perfect bearing's (same rollers, cage and load).
* No gap the search did not need (``exact`` false): the sweep reads no gaps.
* Rollers settled when needed (a harmonic on the fixed ring, whose rollers settle each on
  their own): a candidate stays at its nominal radius until the walk needs it, as one of a
  vertex's pair or because the gap bound of a roller placed there (settling moves it by at
  most the fixed ring's and its own deviations) cannot clear it; most candidates are cleared
  by that bound and never settle. The walk is the same (a roller the bound clears is never
  the worst), so the centres are those of settling every roller, to round-off; the roller
  centres reported are nominal for the rollers never settled (the sweep reads only centres).
  The outer-ring part of the NU209 sweep: 0.35 s of CPU before, 0.16 s after.

Rotating phasors (the profile's harmonics and the Newton angles δ and ψ advanced by
multiplication instead of sine and cosine) were tried: about 10 % faster here, but they move
the round-off-level figures of VALIDATION.md (the §6.2 ellipse gaps of ~2e-12), so the
direct libm evaluation is kept.
"""

from __future__ import annotations

import math

import numpy as np
from numba.extending import register_jitable
from numpy.typing import NDArray

from runout.base._kernel import kernel

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]
#: Packed bodies: base radii r0, orders k, amplitudes a, phases φ, offsets.
Bodies = tuple[FloatArray, FloatArray, FloatArray, FloatArray, IntArray]

#: A roller counts as interfering below this gap [m] (rounding of the gap is ~1e-17 m).
TOL_FEASIBLE = 1e-13
#: A KKT multiplier below ``-TOL_MULTIPLIER`` means the vertex is not the stable one [-].
TOL_MULTIPLIER = 1e-9

#: How :func:`_solve_all` settles the rollers: each by itself; from ``settled`` (the radii of
#: a bearing with the same fixed ring and rollers); the first candidate by itself and the
#: others at its radius (rollers alike in their cage frames on a round fixed ring: the module
#: docstring).
SETTLE_EACH = 0
SETTLE_GIVEN = 1
SETTLE_ONCE = 2

# status codes of the compiled solver
_OK = 0
_NO_STRADDLE = 1
_NO_VERTEX = 2
_NO_STABLE = 3
_SETTLE_FAIL = 4
_FAR_CONTACT = 5


# register_jitable: compiled into its caller, without Python and C entry points of its own
# (first-run compilation time); a helper that several compiled functions of one run call
# stays njit (compiled once, not once per caller).
@register_jitable(no_cfunc_wrapper=True)
def _profile(
    r0: float, k: FloatArray, a: FloatArray, p: FloatArray, lo: int, hi: int, x: float
) -> tuple[float, float, float]:
    r = r0
    d1 = 0.0
    d2 = 0.0
    for i in range(lo, hi):
        arg = k[i] * x + p[i]
        c = math.cos(arg)
        s = math.sin(arg)
        r += a[i] * c
        d1 -= a[i] * k[i] * s
        d2 -= a[i] * k[i] * k[i] * c
    return r, d1, d2


@register_jitable(no_cfunc_wrapper=True)
def _support(b: int, bt: Bodies, shift: float, psi: float) -> tuple[float, float, float]:
    """Support value h(ψ), its derivative h'(ψ) and the radius of curvature at the support point."""
    h, h1, rc, _ = _support_from(b, bt, shift, psi, 0.0)
    return h, h1, rc


@register_jitable(no_cfunc_wrapper=True)
def _support_from(
    b: int, bt: Bodies, shift: float, psi: float, delta: float
) -> tuple[float, float, float, float]:
    """:func:`_support` with Newton started from the support point at ψ + δ (δ = 0: the
    direction itself); also returns the support point's δ (the start of a nearby ψ)."""
    r0, k, a, p, off = bt
    lo = off[b]
    hi = off[b + 1]
    if hi == lo:
        return r0[b], 0.0, r0[b], delta
    # Newton on the support condition ρ'cos δ - ρ sin δ = 0; quadratic convergence, so once
    # a step is below 1e-9 rad the next would be below ~1e-16 rad and we stop. h is taken at
    # the last evaluated δ (it is stationary there, error O(step² ρ)), h' at the updated δ.
    r = d1 = d2 = 0.0
    h = h1 = 0.0
    for _ in range(40):
        r, d1, d2 = _profile(r0[b], k, a, p, lo, hi, psi + delta - shift)
        cd = math.cos(delta)
        sd = math.sin(delta)
        f = d1 * cd - r * sd
        fp = d2 * cd - 2.0 * d1 * sd - r * cd
        step = f / fp
        h = r * cd
        delta -= step
        if abs(step) < 1e-9:
            break
    h1 = r * math.sin(delta)
    rc = (r * r + d1 * d1) ** 1.5 / (r * r + 2.0 * d1 * d1 - r * d2)
    return h, h1, rc, delta


@register_jitable(no_cfunc_wrapper=True)
def _gap(
    ba: int,
    sa: float,
    bb: int,
    sb: float,
    dx: float,
    dy: float,
    bt: Bodies,
    inside: bool,
) -> tuple[float, float, float]:
    """Signed distance between body A (centre 0) and body B (centre d); normal angle; curvature.

    ``inside=False``: B lies outside A (roller on the inner raceway), the gap is
    d·n − h_A(ψ) − h_B(ψ + π). ``inside=True``: A encloses B (roller in the outer raceway), the
    gap is h_A(ψ) − h_B(ψ) − d·n. Newton on ψ makes the gap stationary (support functions h).
    """
    return _gap_from(ba, sa, bb, sb, dx, dy, bt, inside, math.atan2(dy, dx), False)


@register_jitable(no_cfunc_wrapper=True)
def _gap_from(
    ba: int,
    sa: float,
    bb: int,
    sb: float,
    dx: float,
    dy: float,
    bt: Bodies,
    inside: bool,
    psi: float,
    warm: bool,
) -> tuple[float, float, float]:
    """:func:`_gap` with Newton on ψ started from ``psi``; with ``warm`` each support's Newton
    starts from the support point of the iteration before (δ = 0 otherwise), the same
    stationary points to the same steps, from closer."""
    sign = -1.0 if inside else 1.0  # B's support enters with this sign, the gap with it too
    turn = 0.0 if inside else math.pi
    g = 0.0
    rk = 0.0
    da = db = 0.0
    for _ in range(40):
        ha, h1a, rca, ea = _support_from(ba, bt, sa, psi, da)
        hb, h1b, rcb, eb = _support_from(bb, bt, sb, psi + turn, db)
        if warm:
            da = ea
            db = eb
        c = math.cos(psi)
        s = math.sin(psi)
        nd = c * dx + s * dy
        g = sign * (nd - ha - sign * hb)
        rk = rca + sign * rcb
        f1 = -s * dx + c * dy - h1a - sign * h1b
        f2 = -nd + ha + sign * hb - rca - sign * rcb
        step = f1 / f2
        psi -= step
        if abs(step) < 1e-9:  # quadratic convergence: g is stationary in ψ, error O(step²|d|)
            break
    return g, psi, rk


@register_jitable(no_cfunc_wrapper=True)
def _constraint(
    mode: int,
    j: int,
    cx: float,
    cy: float,
    rx: FloatArray,
    ry: FloatArray,
    sh: FloatArray,
    bt: Bodies,
) -> tuple[float, float, float]:
    """Gap C_j(c) between roller j and the loaded ring centred at c, and its gradient in c.

    The loaded ring is body ``mode`` (0 the inner raceway, 1 the outer). One call of
    :func:`_gap` with run-time arguments for both modes: constant ones would compile a
    specialisation per value.
    """
    g, gx, gy, _ = _constraint_from(mode, j, cx, cy, rx, ry, sh, bt, 0.0, False)
    return g, gx, gy


@register_jitable(no_cfunc_wrapper=True)
def _constraint_from(
    mode: int,
    j: int,
    cx: float,
    cy: float,
    rx: FloatArray,
    ry: FloatArray,
    sh: FloatArray,
    bt: Bodies,
    turn: float,
    warm: bool,
) -> tuple[float, float, float, float]:
    """:func:`_constraint` by :func:`_gap_from` from the normal ``turn`` [rad] off the line
    of centres (0: on it, as :func:`_gap`); also returns the normal's turn found."""
    dx = rx[j] - cx
    dy = ry[j] - cy
    inner_body = 2 + j + (bt[0].size - 2 - rx.size)  # seed 004's reading: see _pack
    roller = inner_body if mode == 0 else 2 + j
    line = math.atan2(dy, dx)
    g, psi, _ = _gap_from(mode, sh[mode], roller, sh[2], dx, dy, bt, mode == 1, line + turn, warm)
    sign = -1.0 if mode == 0 else 1.0
    return g, sign * math.cos(psi), sign * math.sin(psi), psi - line


@register_jitable(no_cfunc_wrapper=True)
def _vertex(
    mode: int,
    ja: int,
    jb: int,
    cx: float,
    cy: float,
    ux: float,
    uy: float,
    rx: FloatArray,
    ry: FloatArray,
    sh: FloatArray,
    bt: Bodies,
    warm: bool,
) -> tuple[float, float, float, float, bool]:
    """Newton solve of C_a(c) = C_b(c) = 0; returns c, the KKT multipliers and success.

    With ``warm`` each gap's Newton starts from the normals of the iteration before, turned
    as the line of centres turned (:func:`_constraint_from`)."""
    lam_a = lam_b = 0.0
    pa = pb = 0.0
    for _ in range(60):
        ca, gax, gay, qa = _constraint_from(mode, ja, cx, cy, rx, ry, sh, bt, pa, warm)
        cb, gbx, gby, qb = _constraint_from(mode, jb, cx, cy, rx, ry, sh, bt, pb, warm)
        if warm:
            pa = qa
            pb = qb
        det = gax * gby - gay * gbx
        if abs(det) < 1e-10:
            return cx, cy, 0.0, 0.0, False
        ddx = (-ca * gby + cb * gay) / det
        ddy = (-gax * cb + gbx * ca) / det
        lam_a = (-ux * gby + uy * gbx) / det
        lam_b = (-gax * uy + gay * ux) / det
        cx += ddx
        cy += ddy
        step = math.hypot(ddx, ddy)
        if step > 1e-2:
            return cx, cy, 0.0, 0.0, False
        if step <= 1e-10:  # quadratic convergence: remaining error ~ step² / radius
            return cx, cy, lam_a, lam_b, True
    return cx, cy, lam_a, lam_b, False


@register_jitable(no_cfunc_wrapper=True)
def _gap_bound(
    mode: int,
    j: int,
    cx: float,
    cy: float,
    rx: FloatArray,
    ry: FloatArray,
    r0: FloatArray,
    dev: FloatArray,
    far: bool,
) -> float:
    """Lower bound on the gap C_j(c) of roller j at its centre (rx, ry)[j] [m].

    ``far``: a roller far from the load zone, placed at its nominal radius. Settling moves
    it by at most dev(fixed ring) + dev(roller) along its radius, so its settled gap is at
    least the circle gap minus twice the deviations involved.

    Otherwise the exact gap at that centre: a support value lies within the body's largest
    deviation of its base radius (r0 - dev <= ρ <= h <= r0 + dev), so the gap, stationary in
    ψ (the largest d·n - h_A - h_B of two separate bodies, the smallest h_A - h_B - d·n of one
    inside the other), is at least the gap of the base circles less the two deviations.
    (One function for both: each compiled function costs first-run compilation time.)
    """
    dist = math.hypot(rx[j] - cx, ry[j] - cy)
    if far:
        if mode == 0:
            gap = dist - r0[0] - r0[2 + j]
        else:
            gap = r0[1] - r0[2 + j] - dist
        slack = dev[0] + dev[1] + 2.0 * dev[2 + j]
    else:
        roller = 2 + j + (r0.size - 2 - rx.size) if mode == 0 else 2 + j  # as _constraint
        if mode == 0:
            gap = dist - r0[0] - r0[roller]
        else:
            gap = r0[1] - r0[roller] - dist
        slack = dev[mode] + dev[roller]
    signed: float = gap - slack
    return signed


@register_jitable(no_cfunc_wrapper=True)
def _worst(
    mode: int,
    skip1: int,
    skip2: int,
    cx: float,
    cy: float,
    rx: FloatArray,
    ry: FloatArray,
    far: NDArray[np.bool_],
    dev: FloatArray,
    sh: FloatArray,
    bt: Bodies,
    wg: FloatArray,
    pending: FloatArray,
    lazy: bool,
) -> tuple[int, float]:
    """The roller that interferes most with the loaded ring at c (-1 if none).

    ``wg[j]`` receives the exact gap of every roller it evaluates, NaN for the others (the
    skipped ones, the far ones cleared by their bound and the settled ones cleared by
    :func:`_gap_bound`: the exact gap of those could not change the answer).

    With ``lazy``, a candidate not settled yet (NaN in ``pending``, the angle's row of the
    settled radii) sits at its nominal radius and is bounded as a far one; the first whose
    bound does not clear it is returned as ``-2 - j``, for the caller to settle it and ask
    again (before any exact gap is computed: the answer is the one with every candidate
    settled).
    """
    if lazy:
        for j in range(rx.size):
            if j == skip1 or j == skip2 or far[j] or not math.isnan(pending[j]):
                continue
            if _gap_bound(mode, j, cx, cy, rx, ry, bt[0], dev, True) <= 0.0:
                return -2 - j, math.nan
    worst = -1
    wgap = -TOL_FEASIBLE
    for j in range(rx.size):
        wg[j] = math.nan
        if j == skip1 or j == skip2:
            continue
        unsettled = lazy and not far[j] and math.isnan(pending[j])
        if unsettled or _gap_bound(mode, j, cx, cy, rx, ry, bt[0], dev, far[j]) > 0.0:
            continue  # cannot interfere; its exact gap, if wanted, is _gaps_at's
        gj, _, _, _ = _constraint_from(mode, j, cx, cy, rx, ry, sh, bt, 0.0, False)
        wg[j] = gj
        if gj < wgap:
            wgap = gj
            worst = j
    return worst, wgap


@register_jitable(no_cfunc_wrapper=True)
def _single(
    ring: int,
    j: int,
    wx: float,
    wy: float,
    rx: FloatArray,
    ry: FloatArray,
    sh: FloatArray,
    bt: Bodies,
) -> tuple[float, float]:
    """Outer ring hanging on roller j alone: the contact normal points along w = -u.

    With ψ_w the angle of w, G = 0 and stationarity in ψ give the roller centre relative to
    the ring as d = (h_E - h_B) w + (h_E' - h_B') t, t ⊥ w, in closed form. ``ring`` is the
    outer raceway's body, 1 (passed, not written here: a constant would compile a
    specialisation of :func:`_support` of its own).
    """
    psi = math.atan2(wy, wx)
    cw = math.cos(psi)
    sw = math.sin(psi)
    he, h1e, _, _ = _support_from(ring, bt, sh[ring], psi, 0.0)
    hb, h1b, _, _ = _support_from(2 + j, bt, sh[2], psi, 0.0)
    tx = -sw
    ty = cw
    dx = (he - hb) * wx + (h1e - h1b) * tx
    dy = (he - hb) * wy + (h1e - h1b) * ty
    return rx[j] - dx, ry[j] - dy


def deviations(bt: Bodies) -> FloatArray:
    """Largest deviation of each body from its base radius, Σ|a| of its harmonics [m] (the
    gap bounds of :func:`_gap_bound`), summed in order."""
    _, _, a, _, off = bt
    amplitudes = np.abs(a).tolist()
    dev = []
    for b in range(off.size - 1):
        total = 0.0
        for v in amplitudes[off[b] : off[b + 1]]:
            total += v
        dev.append(total)
    return np.array(dev)


@register_jitable(no_cfunc_wrapper=True)
def _settle(
    mode: int,
    roller: int,
    s: float,
    ex: float,
    ey: float,
    sh: FloatArray,
    bt: Bodies,
    psi: float,
    warm: bool,
) -> tuple[float, float, bool]:
    """Radius s [m] along (ex, ey) at which body ``roller`` touches the fixed ring (body
    1 - mode) from s, by Newton's method on the gap; and whether it converged. With ``warm``
    each gap's Newton starts from the normal of the gap before (:func:`_gap_from`)."""
    fixed = 1 - mode
    if math.isnan(psi):
        psi = math.atan2(s * ey, s * ex)
    for _ in range(40):
        if not warm:
            psi = math.atan2(s * ey, s * ex)
        g, psi, rk = _gap_from(
            fixed, sh[fixed], roller, sh[2], s * ex, s * ey, bt, mode == 0, psi, warm
        )
        sg = g
        if mode != 0:
            g = -g
        ds = g / (math.cos(psi) * ex + math.sin(psi) * ey)
        s += ds
        if warm:
            # the normal where the gap is stationary moves with s: dψ/ds = -(∂f1/∂s)/f2 of
            # _gap_from's Newton, f2 = -(±g) - rk there; the next Newton starts on it
            sign = -1.0 if mode == 0 else 1.0
            psi += ds * (ey * math.cos(psi) - ex * math.sin(psi)) / (sign * sg + rk)
        if abs(ds) <= 1e-10:  # Newton on a nearly linear gap: next step < 1e-18 m
            return s, psi, True
    return s, psi, False


@register_jitable(no_cfunc_wrapper=True)
def _gaps_at(
    mode: int,
    cx: float,
    cy: float,
    rx: FloatArray,
    ry: FloatArray,
    far: NDArray[np.bool_],
    dev: FloatArray,
    sh: FloatArray,
    bt: Bodies,
    kept: FloatArray,
    out: FloatArray,
    exact: bool,
) -> bool:
    """The gap of every roller at the accepted centre c into ``out``: the bound of a far
    roller, the gap the search computed there (``kept``) or, where it did not, a new one
    (NaN instead when not ``exact``: a caller that wants only the centre).
    False when a far roller's bound is not positive (contact beyond the contact side)."""
    clear = True
    for j in range(rx.size):
        if far[j]:
            gj = _gap_bound(mode, j, cx, cy, rx, ry, bt[0], dev, True)
            if gj <= 0.0:
                clear = False
            out[j] = gj
            continue
        gj = kept[j]
        if exact and math.isnan(gj):  # else known from the accepted search's last _worst
            gj, _, _, _ = _constraint_from(mode, j, cx, cy, rx, ry, sh, bt, 0.0, False)
        out[j] = gj
    return clear


#: :func:`_support` and :func:`_gap` compiled on their own, for callers in Python (the kernels
#: compile them in).
support = kernel()(_support)
gap = kernel()(_gap)


def work_arrays(z: int) -> tuple[NDArray[np.bool_], FloatArray, FloatArray, NDArray[np.int64]]:
    """The work space of :func:`_solve_all` for Z rollers: ``far``, ``sh``, ``fwork``,
    ``iwork``."""
    return np.empty(z, dtype=np.bool_), np.empty(3), np.empty((6, z)), np.empty((2, z), np.int64)


@register_jitable(no_cfunc_wrapper=True)
def _accept(
    n: int,
    mode: int,
    bx: float,
    by: float,
    la: float,
    lb: float,
    first: int,
    second: int,
    rx: FloatArray,
    ry: FloatArray,
    far: NDArray[np.bool_],
    dev: FloatArray,
    sh: FloatArray,
    bt: Bodies,
    kept: FloatArray,
    out_c: FloatArray,
    out_pair: NDArray[np.int64],
    out_lam: FloatArray,
    out_gap: FloatArray,
    out_status: NDArray[np.int64],
    exact: bool,
) -> None:
    """The stable position (bx, by) of angle n, its contact pair and multipliers, and every
    roller's gap there (see :func:`_gaps_at`), into the outputs (a contact beyond the
    candidates: status). For :func:`_solve_pairs`; :func:`_solve_all` has the same lines
    written out (as a function of its own, ~0.1 s more of the run's first compilation)."""
    out_c[n, 0] = bx
    out_c[n, 1] = by
    out_pair[n, 0] = first
    out_pair[n, 1] = second
    out_lam[n, 0] = la
    out_lam[n, 1] = lb
    if not _gaps_at(mode, bx, by, rx, ry, far, dev, sh, bt, kept, out_gap[n], exact):
        out_status[n] = _FAR_CONTACT


@register_jitable(no_cfunc_wrapper=True)
def _settle_late(
    n: int,
    j: int,
    mode: int,
    beta: float,
    r0: FloatArray,
    radii: FloatArray,
    sh: FloatArray,
    bt: Bodies,
    turn: FloatArray,
    settled: FloatArray,
    rx: FloatArray,
    ry: FloatArray,
    out_rc: FloatArray,
    warm: bool,
) -> bool:
    """Settle candidate j at angle n now (a lazy walk's: :func:`_solve_all`), as step 1
    would have: from its nominal radius along its direction, from its last normal; whether
    it converged."""
    ex = radii[n, j, 0]
    ey = radii[n, j, 1]
    s = r0[1] - r0[2 + j] if mode == 0 else r0[0] + r0[2 + j]
    roller = 2 + j if mode == 0 else 2 + j + (r0.size - 2 - rx.size)
    p0 = beta + turn[j] if warm else math.nan
    s, p1, ok = _settle(mode, roller, s, ex, ey, sh, bt, p0, warm)
    turn[j] = p1 - beta
    settled[n, j] = s
    rx[j] = s * ex
    ry[j] = s * ey
    out_rc[n, j, 0] = rx[j]
    out_rc[n, j, 1] = ry[j]
    return ok


@register_jitable(no_cfunc_wrapper=True)
def _worst_settling(
    mode: int,
    skip1: int,
    skip2: int,
    cx: float,
    cy: float,
    rx: FloatArray,
    ry: FloatArray,
    far: NDArray[np.bool_],
    dev: FloatArray,
    sh: FloatArray,
    bt: Bodies,
    wg: FloatArray,
    n: int,
    beta0: FloatArray,
    cage_turn: float,
    radii: FloatArray,
    turn: FloatArray,
    settled: FloatArray,
    out_rc: FloatArray,
    warm: bool,
    lazy: bool,
) -> tuple[int, bool]:
    """:func:`_worst` at angle n, first settling (a lazy walk) each candidate whose bound at
    its nominal radius cannot clear it; and False when one of those fails to settle."""
    worst, _ = _worst(mode, skip1, skip2, cx, cy, rx, ry, far, dev, sh, bt, wg, settled[n], lazy)
    while worst <= -2:
        j = -2 - worst
        if not _settle_late(
            n, j, mode, beta0[j] + cage_turn, bt[0], radii, sh, bt, turn, settled, rx, ry, out_rc,
            warm,
        ):  # fmt: skip
            return -1, False
        worst, _ = _worst(
            mode, skip1, skip2, cx, cy, rx, ry, far, dev, sh, bt, wg, settled[n], lazy
        )
    return worst, True


@kernel(nogil=True)
def _solve_all(
    alphas: FloatArray,
    n_start: int,
    mode: int,
    bt: Bodies,
    beta0: FloatArray,
    cage: float,
    spin: float,
    inner_turns: float,
    outer_turns: float,
    ux: float,
    uy: float,
    c0x: float,
    c0y: float,
    out_c: FloatArray,
    out_pair: NDArray[np.int64],
    out_lam: FloatArray,
    out_gap: FloatArray,
    out_rc: FloatArray,
    out_status: NDArray[np.int64],
    dev: FloatArray,
    far: NDArray[np.bool_],
    sh: FloatArray,
    fwork: FloatArray,
    iwork: NDArray[np.int64],
    settled: FloatArray,
    settle: int,
    radii: FloatArray,
    radii_given: bool,
    warm: bool,
    exact: bool,
) -> tuple[int, float, float]:
    """The rotation angles from ``n_start`` on, in turn (see the module docstring), from the
    inner-ring centre (c0x, c0y) of the angle before.

    ``dev`` holds the largest deviation of each body from its base radius
    (:func:`deviations`); ``far`` (Z,), ``sh`` (3,), ``fwork`` (6, Z) and ``iwork`` (2, Z) are
    work space (:func:`work_arrays`). Both come from the caller: set-up that, compiled, would
    only cost compilation time.

    ``settled`` (n, Z) receives each candidate roller's settled radius [m], or gives it
    (``settle``: ``SETTLE_EACH``, ``SETTLE_GIVEN``, ``SETTLE_ONCE``); ``radii`` (n, Z, 3)
    receives, or with ``radii_given`` gives, each roller's radius direction (cos β, sin β)
    and its angle φ from the contact side [rad] (the same for every bearing with these
    rollers, cage and load direction); ``warm`` starts the
    Newton solves from the solutions nearby; without ``exact`` the gaps the search did not
    compute are NaN (module docstring: the order sweep's savings). A run's solve passes
    ``SETTLE_EACH``, no ``warm`` and ``exact``.

    Returns the number of angles, or the first angle whose active-set walk found no stable
    vertex, and the centre of the last angle solved: the search over every pair of
    candidates (:func:`_solve_pairs`) takes that angle from the work space as this kernel
    leaves it, and the caller resumes here after it. Apart, it compiles only in a run that
    needs it (none of the examples does).
    """
    z = beta0.size
    r0 = bt[0]
    # sh: turns χ of the inner ring, the outer ring and the rollers
    wg = fwork[0]  # gaps of the last _worst call
    kept = fwork[1]  # gaps at the accepted position, NaN where not known
    shift = r0.size - 2 - z  # Z with seed 004's roller reading (inner contacts: see _pack)
    rx = fwork[2]
    ry = fwork[3]
    phi = fwork[4]
    turn = fwork[5]  # normal of each roller's last settled contact less its direction
    for j in range(z):
        turn[j] = math.nan
    cx = c0x
    cy = c0y
    # contact side: rollers around +u (inner ring loaded) or around -u (outer ring loaded)
    wx = ux if mode == 0 else -ux
    wy = uy if mode == 0 else -uy
    cand = iwork[0]
    sc = iwork[1]  # candidates sorted by angle
    lim = 0.5 * math.pi + 2.0 * math.pi / z
    # the order sweep's solves of a harmonic on the fixed ring (rollers settling each on their
    # own, warm, given directions, no gaps wanted): a candidate settles only when the walk
    # needs it, as one of a vertex's pair or when the bound at its nominal radius cannot clear
    # it (_worst); the centres are those of settling every candidate (the same walk: a roller
    # the bound clears is never the worst) to round-off, but its reported position is nominal
    lazy = settle == SETTLE_EACH and radii_given and warm and not exact
    for n in range(n_start, alphas.size):
        alpha = alphas[n]
        # e^{-i shift} of the inner ring, the outer ring and the rollers at this angle
        for j in range(z):
            kept[j] = math.nan
        sh[0] = inner_turns * alpha
        sh[1] = outer_turns * alpha
        sh[2] = spin * alpha
        status = _OK
        # 1. rollers near the contact side settle radially onto the fixed ring (§5.1); the
        #    others only need a safe lower bound on their gap (checked below)
        nc = 0
        for j in range(z):
            beta = beta0[j] + cage * alpha
            if radii_given:
                ex = radii[n, j, 0]
                ey = radii[n, j, 1]
                phi[j] = radii[n, j, 2]
            else:
                ex = math.cos(beta)
                ey = math.sin(beta)
                phi[j] = math.atan2(wx * ey - wy * ex, wx * ex + wy * ey)
                radii[n, j, 0] = ex
                radii[n, j, 1] = ey
                radii[n, j, 2] = phi[j]
            if abs(phi[j]) >= lim:
                far[j] = True
                turn[j] = math.nan
                # nominal circle position, exact settling not needed for a bound
                s = r0[1] - r0[2 + j] if mode == 0 else r0[0] + r0[2 + j]
                rx[j] = s * ex
                ry[j] = s * ey
                out_rc[n, j, 0] = rx[j]
                out_rc[n, j, 1] = ry[j]
                continue
            far[j] = False
            cand[nc] = j
            nc += 1
            if settle == SETTLE_GIVEN:
                s = settled[n, j]
            elif settle == SETTLE_ONCE and nc > 1:
                s = settled[n, cand[0]]
            elif lazy:
                s = r0[1] - r0[2 + j] if mode == 0 else r0[0] + r0[2 + j]
                settled[n, j] = math.nan  # not settled yet
            else:
                if mode == 0:
                    s = r0[1] - r0[2 + j]
                else:
                    s = r0[0] + r0[2 + j]
                roller = 2 + j if mode == 0 else 2 + j + shift
                p0 = beta + turn[j] if warm else math.nan
                s, p1, ok = _settle(mode, roller, s, ex, ey, sh, bt, p0, warm)
                turn[j] = p1 - beta
                if not ok:
                    status = _SETTLE_FAIL
                settled[n, j] = s
            rx[j] = s * ex
            ry[j] = s * ey
            out_rc[n, j, 0] = rx[j]
            out_rc[n, j, 1] = ry[j]
        if status != _OK:
            out_status[n] = status
            continue
        # 2. candidates sorted by angle from the contact side
        for i in range(nc):  # insertion sort (a dozen rollers; no allocation per angle)
            j = cand[i]
            m = i
            while m > 0 and phi[sc[m - 1]] > phi[j]:
                sc[m] = sc[m - 1]
                m -= 1
            sc[m] = j
        ia = -1
        for i in range(nc):
            if phi[sc[i]] <= 0.0:
                ia = i
        ib = ia + 1
        if ia < 0 or ib >= nc:
            out_status[n] = _NO_STRADDLE
            continue
        # 3. active-set walk over two-contact vertices
        found = False
        single = -1
        bx = by = 0.0
        la = lb = 0.0
        for _ in range(4 * z):
            if lazy:
                for jj in (sc[ia], sc[ib]):
                    if math.isnan(settled[n, jj]):
                        b = beta0[jj] + cage * alpha
                        if not _settle_late(
                            n, jj, mode, b, r0, radii, sh, bt, turn, settled, rx, ry, out_rc,
                            warm,
                        ):  # fmt: skip
                            out_status[n] = _SETTLE_FAIL
                if out_status[n] == _SETTLE_FAIL:
                    break
            vx, vy, lam_a, lam_b, conv = _vertex(
                mode,
                sc[ia],
                sc[ib],
                cx,
                cy,
                ux,
                uy,
                rx,
                ry,
                sh,
                bt,
                warm,
            )
            if not conv:
                break
            if lam_a < -TOL_MULTIPLIER or lam_b < -TOL_MULTIPLIER:
                keep = sc[ib] if lam_a < -TOL_MULTIPLIER else sc[ia]
                if mode == 1:
                    # the hoop may hang on the kept roller alone (convex admissible set)
                    qx, qy = _single(mode, keep, wx, wy, rx, ry, sh, bt)
                    wj, ok = _worst_settling(
                        mode, keep, keep, qx, qy, rx, ry, far, dev, sh, bt, wg, n, beta0,
                        cage * alpha, radii, turn, settled, out_rc, warm, lazy,
                    )  # fmt: skip
                    if not ok:
                        out_status[n] = _SETTLE_FAIL
                        break
                    if wj < 0:
                        found = True
                        for jj in range(z):  # a loop: a slice copy compiles NumPy's shape check
                            kept[jj] = wg[jj]
                        bx, by, la, lb = qx, qy, 1.0, 0.0
                        ia = ib = -1
                        single = keep
                        break
                if lam_a < -TOL_MULTIPLIER:
                    ia = ib
                    ib = ib + 1
                    if ib >= nc:
                        break
                else:
                    ib = ia
                    ia = ia - 1
                    if ia < 0:
                        break
                continue
            worst, ok = _worst_settling(
                mode, sc[ia], sc[ib], vx, vy, rx, ry, far, dev, sh, bt, wg, n, beta0,
                cage * alpha, radii, turn, settled, out_rc, warm, lazy,
            )  # fmt: skip
            if not ok:
                out_status[n] = _SETTLE_FAIL
                break
            if worst >= 0 and far[worst]:
                out_status[n] = _FAR_CONTACT
                break
            if worst < 0:
                found = True
                for jj in range(z):
                    kept[jj] = wg[jj]
                bx, by, la, lb = vx, vy, lam_a, lam_b
                break
            pos = -1
            for i in range(nc):
                if sc[i] == worst:
                    pos = i
            if pos < 0:
                break
            if phi[worst] > 0.0:
                ib = pos
            else:
                ia = pos
            if ia > ib:
                ia, ib = ib, ia
            if ia == ib:
                break
        if out_status[n] == _FAR_CONTACT or out_status[n] == _SETTLE_FAIL:
            continue
        if not found:
            if lazy:  # _solve_pairs reads every candidate's position: all settled
                for i in range(nc):
                    j = cand[i]
                    if math.isnan(settled[n, j]):
                        b = beta0[j] + cage * alpha
                        if not _settle_late(
                            n, j, mode, b, r0, radii, sh, bt, turn, settled, rx, ry, out_rc,
                            warm,
                        ):  # fmt: skip
                            out_status[n] = _SETTLE_FAIL
                if out_status[n] == _SETTLE_FAIL:
                    continue
            return n, cx, cy  # 4. every pair of candidates: _solve_pairs
        cx = bx
        cy = by
        # _accept written out: as a function of its own it costs the run ~0.1 s of compilation
        out_c[n, 0] = bx
        out_c[n, 1] = by
        out_pair[n, 0] = sc[ia] if single < 0 else single
        out_pair[n, 1] = sc[ib] if single < 0 else single
        out_lam[n, 0] = la
        out_lam[n, 1] = lb
        if not _gaps_at(mode, bx, by, rx, ry, far, dev, sh, bt, kept, out_gap[n], exact):
            out_status[n] = _FAR_CONTACT
    return alphas.size, cx, cy


@kernel(nogil=True)
def _solve_pairs(
    n: int,
    mode: int,
    bt: Bodies,
    cx: float,
    cy: float,
    ux: float,
    uy: float,
    out_c: FloatArray,
    out_pair: NDArray[np.int64],
    out_lam: FloatArray,
    out_gap: FloatArray,
    out_status: NDArray[np.int64],
    dev: FloatArray,
    far: NDArray[np.bool_],
    sh: FloatArray,
    fwork: FloatArray,
    iwork: NDArray[np.int64],
    warm: bool,
    exact: bool,
) -> tuple[float, float]:
    """Angle n where the active-set walk of :func:`_solve_all` found no stable vertex: the
    lowest admissible KKT vertex over every pair of candidate rollers (and, outer ring
    loaded, every single roller), from the work space :func:`_solve_all` left at that angle
    (settled rollers, candidates sorted by angle, the rings' turns); (cx, cy) is the centre
    of the angle before. No stable position: status ``_NO_STABLE``. Returns the centre the
    next angle starts from (the stable position, or (cx, cy) without one).
    """
    z = far.size
    wg = fwork[0]
    kept = fwork[1]
    rx = fwork[2]
    ry = fwork[3]
    sc = iwork[1]
    wx = ux if mode == 0 else -ux
    wy = uy if mode == 0 else -uy
    nc = 0
    for j in range(z):
        if not far[j]:
            nc += 1
    found = False
    single = -1
    ia = ib = -1
    bx = by = 0.0
    la = lb = 0.0
    best = -1e300
    for i1 in range(nc):
        for i2 in range(i1 + 1, nc):
            vx, vy, lam_a, lam_b, conv = _vertex(
                mode,
                sc[i1],
                sc[i2],
                cx,
                cy,
                ux,
                uy,
                rx,
                ry,
                sh,
                bt,
                warm,
            )
            if not conv or lam_a < -TOL_MULTIPLIER or lam_b < -TOL_MULTIPLIER:
                continue
            wj, _ = _worst(mode, sc[i1], sc[i2], vx, vy, rx, ry, far, dev, sh, bt, wg, wg, False)
            if wj < 0 and ux * vx + uy * vy > best:
                best = ux * vx + uy * vy
                bx, by, la, lb = vx, vy, lam_a, lam_b
                ia, ib = i1, i2
                single = -1
                found = True
    if mode == 1:
        for i1 in range(nc):
            qx, qy = _single(mode, sc[i1], wx, wy, rx, ry, sh, bt)
            wj, _ = _worst(mode, sc[i1], sc[i1], qx, qy, rx, ry, far, dev, sh, bt, wg, wg, False)
            if wj < 0 and ux * qx + uy * qy > best:
                best = ux * qx + uy * qy
                bx, by, la, lb = qx, qy, 1.0, 0.0
                single = sc[i1]
                found = True
    if not found:
        out_status[n] = _NO_STABLE
        return cx, cy
    first = sc[ia] if single < 0 else single
    second = sc[ib] if single < 0 else single
    args = (rx, ry, far, dev, sh, bt, kept, out_c, out_pair, out_lam, out_gap, out_status)
    _accept(n, mode, bx, by, la, lb, first, second, *args, exact)
    return bx, by
