r"""Pieces shared by the quasi-static models (seed 000 and seed 001): time grid, contact
deviations, predicted spectral lines and their labels, runout figures.

Conventions (both models)
-------------------------
* Angles counter-clockwise from +x [rad] (Tada measures ball angles clockwise; only the sense
  of the orbits changes, not a frequency or an amplitude).
* Ball j (0-based) sits at :math:`\theta_j = 2\pi f_c t + 2\pi j/Z + \epsilon_j` with the signed
  cage frequency :math:`f_c` and the pitch error :math:`\epsilon_j` (seed 000 §2.1, seed 001
  eq. 8).
* A ring turning at :math:`f_r` [Hz] shows its raceway point :math:`\theta - 2\pi f_r t` (ring
  frame) at the fixed-frame angle θ.
* The contact point of ball j in its own frame is at :math:`\pm 2\pi f_b t` (spin relative to
  the cage, seed 000 §2.1, seed 001 eq. 9; the sign is :attr:`Kinematics.contact_rate`'s); the
  diameter deviation along the contact line is
  :meth:`runout.geometry.imperfections.BearingImperfections.evaluate_element_diameters`
  (seed 002 eq. 26).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from numba.extending import register_jitable
from numpy.typing import NDArray

from runout.analysis.decompose import (
    Candidate,
    Direction,
    Kinematic,
    Phasors,
    fit_lines,
    split_runout,
)
from runout.analysis.result_details import QuasiStaticDetails
from runout.analysis.results import RunResult, Source, stated_resolution
from runout.base._kernel import kernel
from runout.base._threads import halves, in_spans, one_blas_thread
from runout.base.errors import GeometryError
from runout.geometry.attribution import ball_size_line, ball_waviness_line
from runout.geometry.imperfections import BearingImperfections, Harmonics
from runout.geometry.kinematics import bearing_frequencies

__all__ = [
    "ANCHOR",
    "ContactDeviations",
    "ContactSources",
    "Kinematics",
    "PhasorTable",
    "contact_advance",
    "contact_anchor",
    "contact_deviations",
    "contact_series",
    "contact_sources",
    "contact_state",
    "contact_values",
    "decomposition_kinematic",
    "linear_phasors",
    "on_grid",
    "predict",
    "predicted_lines",
    "solve_in_halves",
    "time_grid",
    "time_step",
]

TWO_PI = 2.0 * math.pi
#: Highest nonlinear order j of Tada's Table 3 for which lines are predicted and fitted.
MAX_LINE_ORDER = 3
#: Components below this fraction of the largest one are dropped from the output.
FLOOR = 1e-7


@dataclass(frozen=True)
class Kinematics:
    """Signed frequencies [Hz] the quasi-static models need.

    Attributes
    ----------
    inner, outer : float
        Ring speeds [Hz], signed (rotating ring positive).
    cage : float
        Signed cage frequency f_c [Hz].
    spin : float
        Ball spin relative to the cage f_b [Hz] (>= 0).
    rotating_ring : {"inner", "outer"}
    n_elements : int
        Z.
    """

    inner: float
    outer: float
    cage: float
    spin: float
    rotating_ring: str
    n_elements: int

    @property
    def rotation(self) -> float:
        """Speed of the rotating ring [Hz]."""
        return self.inner if self.rotating_ring == "inner" else self.outer

    @property
    def contact_rate(self) -> float:
        r"""Signed rate of the contact-point angle in each element's own frame [Hz].

        Rolling without slip, an element spins against the inner ring's motion relative to the
        cage (:mod:`runout.geometry.kinematics`): seen from the cage, its contact point then runs
        over its surface at :math:`+f_b` when the inner ring turns faster than the outer (ball
        inside a stationary outer race, spinning against its orbit) and at :math:`-f_b` when the
        outer ring is the faster (ball rolling on a stationary inner race, spinning with its
        orbit).
        Seed 002 eq. 6 is the first case; the linear model uses the same signed rate.
        """
        return self.spin if self.inner >= self.outer else -self.spin


def time_grid(speed: float, revolutions: float, samples: int) -> NDArray[np.float64]:
    """``samples`` equally spaced instants over ``revolutions`` turns of the rotating ring [s]."""
    if not (math.isfinite(speed) and speed > 0.0):
        raise GeometryError("operation.speed", f"must be > 0 for a runout analysis, got {speed!r}")
    if not (revolutions > 0.0 and samples >= 16):
        raise GeometryError("analysis", "needs revolutions > 0 and samples >= 16")
    duration = revolutions / speed
    return np.arange(samples, dtype=np.float64) * (duration / samples)


@dataclass(frozen=True)
class ContactDeviations:
    """Deviations seen at each ball's contacts, arrays of shape (n, Z) [m] or [rad].

    Attributes
    ----------
    theta : ndarray
        Ball angular positions θ_j(t) [rad].
    inner : ndarray
        Inner raceway radius deviation at the ball, positive = material added [m].
    outer : ndarray
        Outer raceway radius deviation at the ball, positive = radius larger (material
        removed) [m].
    ball : ndarray
        Ball diameter deviation along the contact line, size errors included [m].
    """

    theta: NDArray[np.float64]
    inner: NDArray[np.float64]
    outer: NDArray[np.float64]
    ball: NDArray[np.float64]


def contact_deviations(
    imperfections: BearingImperfections, kin: Kinematics, time: NDArray[np.float64]
) -> ContactDeviations:
    """Evaluate the raceway and ball deviations at every ball contact and instant.

    Parameters
    ----------
    imperfections : BearingImperfections
        Waviness, size and pitch errors (Z elements).
    kin : Kinematics
        Signed ring, cage and spin frequencies [Hz].
    time : ndarray, shape (n,)
        Instants [s].

    Returns
    -------
    ContactDeviations
    """
    z = kin.n_elements
    t = np.asarray(time, dtype=np.float64)
    theta = (
        TWO_PI * kin.cage * t[:, None]
        + TWO_PI * np.arange(z)[None, :] / z
        + np.asarray(imperfections.pitch_errors, dtype=np.float64)[None, :]
    )
    w_in = imperfections.inner.evaluate(theta - TWO_PI * kin.inner * t[:, None])
    w_out = imperfections.outer.evaluate(theta - TWO_PI * kin.outer * t[:, None])
    spin_angle = TWO_PI * kin.contact_rate * t
    w_ball = np.ascontiguousarray(imperfections.evaluate_element_diameters(spin_angle).T)
    return ContactDeviations(theta=theta, inner=w_in, outer=w_out, ball=w_ball)


# --------------------------------------------------------------------------------------------
# fused evaluation of the deviations (phasor recurrences), for the compiled solves
# --------------------------------------------------------------------------------------------
#: Most instants between two direct evaluations of the phasors (re-anchoring): each step of a
#: recurrence adds a few ulp, so the drift stays below ~1e-13 of the amplitudes.
ANCHOR = 256
#: Tolerance of the uniform-grid test of :func:`on_grid`, relative to the instant (4 ulp).
GRID_RTOL = 4.0 * 2.0**-52
#: Blocks of :data:`ANCHOR` instants per matrix product of :func:`contact_series`.
_SERIES_BLOCKS = 64
#: Records of at least this many instants are solved as two halves (:func:`solve_in_halves`).
SPLIT_MIN = 1 << 17


def solve_in_halves(
    kernel: Callable[..., tuple[int, int]],
    args: tuple[Any, ...],
    n: int,
    new_state: Callable[[], tuple[NDArray[np.float64], ...]] | None = None,
) -> tuple[int, int]:
    """Run a fused quasi-static kernel over instants ``[0, n)``, long records as two halves.

    The kernels take the instants to solve as their last two arguments ``first, last``
    (preceded by their work arrays, ``new_state()``, a fresh set per half, when given: the
    phasors' :func:`contact_state`), and write the global instants of their output arrays,
    so two halves fill one record. A record of at least :data:`SPLIT_MIN` instants is cut at
    a multiple of :data:`ANCHOR` (the phasors are anchored at the same instants as in one
    pass) and its halves run on two threads (the kernels release the GIL) when the caller is
    the main thread of a machine with two cores or more; elsewhere (a study's worker threads)
    one after the other. The second half starts Newton's method from rest, as the first
    instant does: its first solutions agree with one pass to the solver's tolerance, whatever
    the machine, so a result does not depend on the number of cores.

    Returns
    -------
    status, instant : int
        The kernel's status and failing instant: of the first half that fails, in time order.
    """
    spans = halves(n, SPLIT_MIN, ANCHOR)
    if new_state is not None:
        make = new_state
        work = in_spans(lambda first, last: kernel(*args, make(), first, last), spans)
    else:
        work = in_spans(lambda first, last: kernel(*args, first, last), spans)
    for status, instant in work:
        if status != 0:
            return status, instant
    return 0, -1


@dataclass(frozen=True)
class ContactSources:
    r"""The deviations of :func:`contact_deviations`, packed for the compiled kernels.

    The kernels evaluate, at every instant and ball, the approach at zero displacement (3-D:
    :math:`(W_i - W_o) g_r + W_b + c_0`, seed 000 eq. 2; planar: :math:`c_0 + \tfrac12(W_i +
    g_b W_b - W_o)`, seed 001 eq. 10) and :math:`e^{i\theta_j}`, by rotating the phasor
    :math:`a e^{i(k\psi + \varphi)}` of every harmonic from one instant to the next instead of
    calling cos and sin (:func:`contact_advance`), re-anchored on a direct evaluation every
    :data:`ANCHOR` instants and wherever the time grid is not uniform.

    Attributes
    ----------
    rates : ndarray, shape (4,)
        2π f_c, 2π f_inner, 2π f_outer and 2π times the contact rate [rad/s].
    base : ndarray, shape (Z,)
        Nominal ball angles 2π j / Z [rad].
    pitch : ndarray, shape (Z,)
        Pitch errors ε_j [rad].
    ring : ndarray, shape (3, M)
        Orders, amplitudes [m] and phases [rad] of the inner then the outer raceway.
    n_inner : int
        Harmonics of the inner raceway (the first ``n_inner`` columns of ``ring``).
    ball : ndarray, shape (3, K)
        Packed diameter deviations of the elements (orders, amplitudes [m], phases [rad]).
    ball_offsets : ndarray of int64, shape (Z + 1,)
        Element j owns ``ball[:, ball_offsets[j]:ball_offsets[j + 1]]``.
    gains : ndarray, shape (3,)
        g_r (ring gain), g_b (element gain), c_0 [m].
    planar : bool
        Planar combination (seed 001 eq. 10) instead of the 3-D one (seed 000 eq. 2).
    """

    rates: NDArray[np.float64]
    base: NDArray[np.float64]
    pitch: NDArray[np.float64]
    ring: NDArray[np.float64]
    n_inner: int
    ball: NDArray[np.float64]
    ball_offsets: NDArray[np.int64]
    gains: NDArray[np.float64]
    planar: bool

    def args(self) -> tuple[Any, ...]:
        """The positional arguments of the kernels, in their order."""
        return (
            self.rates,
            self.base,
            self.pitch,
            self.ring,
            self.n_inner,
            self.ball,
            self.ball_offsets,
            self.gains,
            self.planar,
        )


def contact_sources(
    imperfections: BearingImperfections,
    kin: Kinematics,
    *,
    ring_gain: float,
    element_gain: float,
    offset: float,
    planar: bool,
) -> ContactSources:
    """Pack the imperfections for the fused kernels (see :class:`ContactSources`).

    Parameters
    ----------
    imperfections : BearingImperfections
        Waviness, size and pitch errors (Z elements).
    kin : Kinematics
        Signed ring, cage and spin frequencies [Hz].
    ring_gain, element_gain : float
        g_r and g_b of :class:`ContactSources` (3-D: cos α and 1; planar: unused and 1 or
        cos α).
    offset : float
        c_0 [m] (δ_pl, or δ_0 of seed 001).
    planar : bool
        Seed 001's planar combination.
    """
    from runout.geometry.imperfections import pack_harmonics

    z = kin.n_elements
    rates = np.array(
        [TWO_PI * kin.cage, TWO_PI * kin.inner, TWO_PI * kin.outer, TWO_PI * kin.contact_rate]
    )
    ring = pack_harmonics((imperfections.inner, imperfections.outer))[:3]
    k, a, p, offsets = pack_harmonics(imperfections.element_diameter_deviations())
    return ContactSources(
        rates=rates,
        base=TWO_PI * np.arange(z) / z,
        pitch=np.ascontiguousarray(imperfections.pitch_errors, dtype=np.float64),
        ring=np.ascontiguousarray(np.stack(ring)),
        n_inner=len(imperfections.inner),
        ball=np.ascontiguousarray(np.stack([k, a, p])),
        ball_offsets=offsets,
        gains=np.array([ring_gain, element_gain, offset]),
        planar=planar,
    )


def contact_state(
    h: float,
    rates: NDArray[np.float64],
    ring: NDArray[np.float64],
    n_inner: int,
    ball: NDArray[np.float64],
    z: int,
) -> tuple[NDArray[np.float64], ...]:
    """Work arrays of the phasor recurrences of the compiled kernels, rotations per step set.

    Built here, not in the kernels: allocating them and the few cosines of the rotations over
    one time step ``h`` [s] is set-up, which compiled would cost the first run of a model
    compilation time for nothing (the same ``math`` functions, so the same bits).

    Returns
    -------
    tuple of ndarray
        The anchored phasors e^{iθ_j} (2, Z) and a e^{i(kψ_j + φ)} of every ring harmonic and
        ball (M, 2, Z); the element phasors (2, K); the cage's and each ring harmonic's
        rotation since the anchor (2,), (2, M); their rotations per step (2,), (2, M), (2, K);
        per-ball sums (2, Z). Row 0 holds real parts, row 1 imaginary parts.
    """
    m = ring.shape[1]
    kb = ball.shape[1]
    wc, wi, wo, wb = (float(w) for w in rates)
    cage_rot = np.array([math.cos(wc * h), math.sin(wc * h)])
    ring_rot = np.empty((2, m))
    for i, order in enumerate(ring[0].tolist()):
        angle = order * ((wc - (wi if i < n_inner else wo)) * h)
        ring_rot[0, i] = math.cos(angle)
        ring_rot[1, i] = math.sin(angle)
    ball_rot = np.empty((2, kb))
    for i, order in enumerate(ball[0].tolist()):
        angle = order * (wb * h)
        ball_rot[0, i] = math.cos(angle)
        ball_rot[1, i] = math.sin(angle)
    return (
        np.empty((2, z)),
        np.empty((m, 2, z)),
        np.empty((2, kb)),
        np.empty(2),
        np.empty((2, m)),
        cage_rot,
        ring_rot,
        ball_rot,
        np.empty((2, z)),
    )


# register_jitable: compiled into its caller, without Python and C entry points of its own
# (first-run compilation time); a helper that several compiled functions of one run call
# stays njit (compiled once, not once per caller).
@register_jitable(no_cfunc_wrapper=True)
def contact_anchor(
    ti: float,
    rates: NDArray[np.float64],
    base: NDArray[np.float64],
    pitch: NDArray[np.float64],
    ring: NDArray[np.float64],
    n_inner: int,
    ball: NDArray[np.float64],
    state: tuple[NDArray[np.float64], ...],
) -> None:
    """Every phasor evaluated directly at instant ``ti`` [s], from the same rounded arguments
    as :func:`contact_deviations` (compiled)."""
    # one name at a time: unpacking a tuple of arrays compiles to far more code
    cage_q = state[0]
    ring_q = state[1]
    ball_ph = state[2]
    cage_p = state[3]
    ring_p = state[4]
    z = base.size
    wc, wi, wo = rates[0], rates[1], rates[2]
    for j in range(z):
        th = wc * ti + base[j] + pitch[j]
        cage_q[0, j] = math.cos(th)
        cage_q[1, j] = math.sin(th)
        psi_i = th - wi * ti
        psi_o = th - wo * ti
        for m in range(ring.shape[1]):
            arg = ring[0, m] * (psi_i if m < n_inner else psi_o) + ring[2, m]
            ring_q[m, 0, j] = ring[1, m] * math.cos(arg)
            ring_q[m, 1, j] = ring[1, m] * math.sin(arg)
    s = rates[3] * ti
    for m in range(ball.shape[1]):
        arg = ball[0, m] * s + ball[2, m]
        ball_ph[0, m] = ball[1, m] * math.cos(arg)
        ball_ph[1, m] = ball[1, m] * math.sin(arg)
    cage_p[0] = 1.0
    cage_p[1] = 0.0
    for m in range(ring.shape[1]):
        ring_p[0, m] = 1.0
        ring_p[1, m] = 0.0


@kernel(inline="always")
def contact_advance(state: tuple[NDArray[np.float64], ...]) -> None:
    """Advance the rotations since the anchor, and the element phasors, by one step (compiled)."""
    ball_ph = state[2]  # one name at a time (see contact_anchor)
    cage_p = state[3]
    ring_p = state[4]
    cage_rot = state[5]
    ring_rot = state[6]
    ball_rot = state[7]
    re, im = cage_p[0], cage_p[1]
    cage_p[0] = re * cage_rot[0] - im * cage_rot[1]
    cage_p[1] = re * cage_rot[1] + im * cage_rot[0]
    for m in range(ring_p.shape[1]):
        re, im = ring_p[0, m], ring_p[1, m]
        ring_p[0, m] = re * ring_rot[0, m] - im * ring_rot[1, m]
        ring_p[1, m] = re * ring_rot[1, m] + im * ring_rot[0, m]
    for m in range(ball_ph.shape[1]):
        re, im = ball_ph[0, m], ball_ph[1, m]
        ball_ph[0, m] = re * ball_rot[0, m] - im * ball_rot[1, m]
        ball_ph[1, m] = re * ball_rot[1, m] + im * ball_rot[0, m]


@kernel(inline="always")
def contact_values(
    state: tuple[NDArray[np.float64], ...],
    n_inner: int,
    ball_offsets: NDArray[np.int64],
    gains: NDArray[np.float64],
    planar: bool,
    c: NDArray[np.float64],
    cth: NDArray[np.float64],
    sth: NDArray[np.float64],
) -> None:
    """Approach of every ball at zero displacement, cos θ_j and sin θ_j (compiled).

    Each ring term is Re(anchored phasor × rotation since the anchor); sums run in the order
    of :func:`contact_deviations` (harmonics in ascending order), then combine as seed 000
    eq. 2 (3-D) or seed 001 eq. 10 (planar), see :class:`ContactSources`.
    """
    cage_q = state[0]  # one name at a time (see contact_anchor)
    ring_q = state[1]
    ball_ph = state[2]
    cage_p = state[3]
    ring_p = state[4]
    acc = state[8]
    z = c.size
    pr, pi = cage_p[0], cage_p[1]
    for j in range(z):
        cth[j] = cage_q[0, j] * pr - cage_q[1, j] * pi
        sth[j] = cage_q[0, j] * pi + cage_q[1, j] * pr
        acc[0, j] = 0.0
        acc[1, j] = 0.0
    # loops over balls innermost: independent sums, which the compiler vectorises
    wi = acc[0]
    for m in range(n_inner):
        pr, pi = ring_p[0, m], ring_p[1, m]
        qr, qi = ring_q[m, 0], ring_q[m, 1]
        for j in range(z):
            wi[j] += qr[j] * pr - qi[j] * pi
    wo = acc[1]
    for m in range(n_inner, ring_p.shape[1]):
        pr, pi = ring_p[0, m], ring_p[1, m]
        qr, qi = ring_q[m, 0], ring_q[m, 1]
        for j in range(z):
            wo[j] += qr[j] * pr - qi[j] * pi
    for j in range(z):
        wb = 0.0
        for h in range(ball_offsets[j], ball_offsets[j + 1]):
            wb += ball_ph[0, h]
        if planar:
            c[j] = gains[2] + 0.5 * (acc[0, j] + wb * gains[1] - acc[1, j])
        else:
            c[j] = (acc[0, j] - acc[1, j]) * gains[0] + wb + gains[2]


def time_step(t: NDArray[np.float64]) -> float:
    """Step of a uniform grid, (t[-1] - t[0]) / (n - 1) [s] (0 for fewer than 2 instants)."""
    n = t.size
    return float((t[n - 1] - t[0]) / (n - 1)) if n > 1 else 0.0


@register_jitable(no_cfunc_wrapper=True)
def on_grid(i: int, t: NDArray[np.float64], h: float, anchor: int) -> bool:
    """True when the phasors anchored at instant ``anchor`` may be advanced to instant i by
    one step of ``h`` [s]: i follows within :data:`ANCHOR` instants and ``t[i]`` is the
    anchor's time plus a whole number of steps to round-off (compiled).

    Otherwise the caller evaluates the phasors directly (:func:`contact_anchor`): at the
    first instant, every :data:`ANCHOR` instants, and at every instant of a non-uniform grid.
    The test is scalar on purpose: arrays passed per instant would cost reference counting.
    """
    r = i - anchor
    if anchor < 0 or not 0 < r < ANCHOR:
        return False
    close: bool = abs(t[i] - (t[anchor] + r * h)) <= GRID_RTOL * (abs(t[i]) + r * abs(h))
    return close


@register_jitable(no_cfunc_wrapper=True)
def predict(known: int, q: float, p: float, o: float) -> float:
    """Starting point of an instant from the solutions of the instants before it.

    ``known`` is how many of the last three solutions (q the last, then p, then o) lie on a
    smooth stretch of the record: quadratic extrapolation ``3 q - 3 p + o`` with three,
    linear ``2 q - p`` with two, the last solution otherwise. The kernels count as smooth the
    instants at which every ball carries load (a contact lost or regained makes the record
    kink, and the equilibrium of a ring held by few balls may not be unique: there they start
    from the last solution, as without extrapolation, and also where an extrapolated start
    fails). A start this close lets Newton's first step land within the tolerance: one step
    per instant instead of two or three, and no line search; the converged solution is the
    same to well within the tolerance.
    """
    if known >= 3:
        return 3.0 * q - 3.0 * p + o
    if known == 2:
        return 2.0 * q - p
    return q


def _series_blocks(
    t: NDArray[np.float64],
    starts: NDArray[np.int64],
    phasors: Callable[[NDArray[np.float64]], tuple[NDArray[np.float64], ...]],
    rot: NDArray[np.float64],
    rot_cage: NDArray[np.float64],
    offset: float,
    c: NDArray[np.float64],
    cth: NDArray[np.float64],
    sth: NDArray[np.float64],
) -> None:
    """The blocks of :func:`contact_series` on a uniform grid, from their first instants."""
    n, z = c.shape
    for b0 in range(0, starts.size, _SERIES_BLOCKS):
        blocks = starts[b0 : b0 + _SERIES_BLOCKS]
        cq, sq, pr, pi = phasors(t[blocks])
        # Re(p e^{iφ}) = Re p cos φ - Im p sin φ: summed over the harmonics by one product
        vals = rot @ np.concatenate([pr, pi], axis=1)  # (blocks, ANCHOR, z)
        # e^{i(θ + φ)}: cos = cos θ cos φ - sin θ sin φ, sin = sin θ cos φ + cos θ sin φ
        cage = rot_cage @ np.stack([np.hstack([cq, sq]), np.hstack([sq, -cq])], axis=1)
        i0, i1 = blocks[0], min(blocks[-1] + ANCHOR, n)
        np.add(vals.reshape(-1, z)[: i1 - i0], offset, out=c[i0:i1])
        cage = cage.reshape(-1, 2 * z)[: i1 - i0]
        cth[i0:i1] = cage[:, :z]
        sth[i0:i1] = cage[:, z:]


def contact_series(
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
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Approaches at zero displacement and cos θ_j, sin θ_j at every instant.

    What the fused quasi-static kernels evaluate instant by instant, written out in full (the
    spindle model, tests). NumPy and BLAS, not compiled: on a uniform grid the phasors of each
    block of :data:`ANCHOR` instants are evaluated at the block's first instant exactly as
    :func:`contact_anchor` does and turned to the block's other instants by exact rotations,
    every harmonic and ball in one matrix product per block; elsewhere (a grid that is not
    uniform) every instant is evaluated directly. Same values as the kernels' recurrence to
    round-off (the rotations are exact here, not repeated products).

    Returns
    -------
    c, cos_theta, sin_theta : ndarray, shape (n, Z)
        [m], [-], [-].
    """
    t = np.ascontiguousarray(t, dtype=np.float64)
    n, z = t.size, base.size
    m = ring.shape[1]
    wc, wi, wo, wb = (float(w) for w in rates)
    # each harmonic, the rings' then the balls': its weight in c (amplitude times the gain
    # and sign of its part), the balls it acts on (a ring's: all; a ball's: its own) and the
    # rate it turns at relative to the anchor [rad/s]
    if planar:  # seed 001 eq. 10: c_0 + (W_i + g_b W_b - W_o) / 2
        w_inner, w_outer, w_ball = 0.5, -0.5, 0.5 * float(gains[1])
    else:  # seed 000 eq. 2: (W_i - W_o) g_r + W_b + c_0
        w_inner, w_outer, w_ball = float(gains[0]), -float(gains[0]), 1.0
    inner = np.arange(m) < n_inner
    weight = np.concatenate([np.where(inner, w_inner, w_outer) * ring[1], w_ball * ball[1]])
    ring_rate = np.where(inner, wi, wo)
    acts = np.zeros((m + ball.shape[1], z))
    acts[:m] = 1.0
    for j in range(z):
        acts[m + ball_offsets[j] : m + ball_offsets[j + 1], j] = 1.0
    turn = np.concatenate([ring[0] * (wc - ring_rate), ball[0] * wb])  # [rad/s] per harmonic

    def phasors(ta: NDArray[np.float64]) -> tuple[NDArray[np.float64], ...]:
        """cos, sin of θ_j (k, z) and the weighted harmonic phasors (k, H, z) at times ta,
        from the same rounded arguments as :func:`contact_anchor`."""
        th = wc * ta[:, None] + base + pitch
        psi = th[:, None, :] - ring_rate[:, None] * ta[:, None, None]
        arg_ring = ring[0][:, None] * psi + ring[2][:, None]
        arg_ball = (ball[0] * (wb * ta)[:, None] + ball[2])[:, :, None]
        amp_ring, amp_ball = weight[:m, None] * acts[:m], weight[m:, None] * acts[m:]
        re = np.concatenate([amp_ring * np.cos(arg_ring), amp_ball * np.cos(arg_ball)], axis=1)
        im = np.concatenate([amp_ring * np.sin(arg_ring), amp_ball * np.sin(arg_ball)], axis=1)
        return np.cos(th), np.sin(th), re, im

    c = np.empty((n, z))
    cth = np.empty((n, z))
    sth = np.empty((n, z))
    h = time_step(t)
    uniform = n > 1 and h != 0.0
    if uniform:  # the kernels' test (on_grid), every instant against its block's first
        steps = np.arange(n) % ANCHOR
        first = t[np.arange(n) - steps]
        uniform = bool(
            np.all(np.abs(t - (first + steps * h)) <= GRID_RTOL * (np.abs(t) + steps * abs(h)))
        )
    if uniform:
        # rotations over r steps, [cos | -sin], of the harmonics and of the cage
        angle = np.multiply.outer(np.arange(ANCHOR) * h, np.append(turn, wc))
        rot = np.concatenate([np.cos(angle[:, :-1]), -np.sin(angle[:, :-1])], axis=1)
        rot_cage = np.stack([np.cos(angle[:, -1]), -np.sin(angle[:, -1])], axis=1)
        starts = np.arange(0, n, ANCHOR)
        with one_blas_thread():  # small products: BLAS threads only wait for each other
            _series_blocks(t, starts, phasors, rot, rot_cage, float(gains[2]), c, cth, sth)
    else:
        chunk = max(1, (1 << 20) // max(1, (m + ball.shape[1]) * z))
        for i0 in range(0, n, chunk):
            cq, sq, pr, _ = phasors(t[i0 : i0 + chunk])
            c[i0 : i0 + chunk] = pr.sum(axis=1) + gains[2]
            cth[i0 : i0 + chunk] = cq
            sth[i0 : i0 + chunk] = sq
    return c, cth, sth


# --------------------------------------------------------------------------------------------
# predicted lines (Tada Table 2 / 3)
# --------------------------------------------------------------------------------------------
def _src(part: str, element: int | None, lobes: int | None, term: str, formula: str) -> Source:
    return Source(part=part, element=element, lobes=lobes, term=term, formula=formula)


def _ring_lines(
    part: str, lobes: int, kin: Kinematics, axial: bool, phasors: PhasorTable
) -> list[Candidate]:
    """Lines of a single ring harmonic of ``lobes`` waves up to order MAX_LINE_ORDER.

    The l-th power of the harmonic carries l·k lobes; the ball set filters it to the radial
    direction when l·k = nZ ± 1 and to the axial direction when l·k = nZ (seed 000 Tables 2-3,
    eq. 6). The frequency is :math:`|(lk + m) f_c - lk f_{ring}|` with m = -1, 0, +1.
    """
    z = kin.n_elements
    f_ring = kin.inner if part == "inner" else kin.outer
    other = kin.outer if part == "inner" else kin.inner
    sym = "f_i" if part == "inner" else "f_o"
    out: list[Candidate] = []
    for order in range(1, MAX_LINE_ORDER + 1):
        lk = order * lobes
        for m in (-1, 0, 1):
            if m == 0 and not axial:
                continue
            if (lk + m) % z:
                continue
            n = (lk + m) // z
            freq = abs((lk + m) * kin.cage - lk * f_ring)
            if freq <= 0.0:
                continue
            rule = f"nZ{'+1' if m == -1 else '-1' if m == 1 else ''}, n={n}"
            if order > 1:
                rule = f"{order}x{lobes}={rule.split(',')[0]}, n={n}, order {order}"
            if f_ring == 0.0:
                formula = f"n {sym}"
            elif other == 0.0 and m != 0:
                formula = f"n {sym} {'+' if m == -1 else '-'} f_r"
            elif other == 0.0:
                formula = f"n {sym}"
            else:
                formula = f"|(lk{m:+d}) f_c - lk f_ring|, l={order}"
            direction: Direction = "axial" if m == 0 else "radial"
            predicted = phasors.get(part, None, lobes, freq) if order == 1 else None
            out.append(
                Candidate(
                    freq, direction, _src(part, None, lobes, rule, formula), predicted=predicted
                )
            )
    return out


def _element_lines(
    index: int, h: Harmonics, kin: Kinematics, axial: bool, loaded: bool, phasors: PhasorTable
) -> list[Candidate]:
    """Lines of ball ``index``'s diameter deviation (seed 000 Table 2, ball rows).

    Order 2n of the diameter deviation gives 2n f_b ± f_c (radial) and 2n f_b (axial); its
    square has a constant part, which turns with the ball at f_c (the second-order f_c line);
    a size error gives f_c, and under a radial load its harmonics 2 f_c, 3 f_c too (the ball
    passes through the load zone once per cage revolution).
    """
    out: list[Candidate] = []
    fc, fb = abs(kin.cage), kin.spin
    j = index + 1
    if fc <= 0.0:
        return out
    for k, a in zip(h.orders, h.amplitudes, strict=True):
        if a == 0.0:
            continue
        k = int(k)
        if k == 0:
            pred = phasors.get("ball", j, 0, fc)
            src = _src("ball", j, 0, *ball_size_line())
            out.append(Candidate(fc, "radial", src, predicted=pred))
            if loaded:
                for m in (2, 3):
                    src = _src("ball", j, 0, f"{m} f_c, load zone", f"{m} f_c")
                    out.append(Candidate(m * fc, "radial", src, optional=True))
            continue
        out.append(
            Candidate(fc, "radial", _src("ball", j, k, "f_c, order 2", "f_c"), optional=True)
        )
        for order in range(1, MAX_LINE_ORDER + 1):
            kk = order * k
            kind = "" if order == 1 else f", order {order}"
            for sign in (1, -1):
                freq = abs(kk * fb + sign * fc)
                if freq <= 0.0:
                    continue
                # the shared table (runout.geometry.attribution) names it as every model does
                term, formula = ball_waviness_line(k, sign, order)
                pred = phasors.get("ball", j, k, freq) if order == 1 else None
                out.append(
                    Candidate(freq, "radial", _src("ball", j, k, term, formula), predicted=pred)
                )
            if axial:
                pred = phasors.get("ball", j, k, kk * fb) if order == 1 else None
                src = _src("ball", j, k, f"2n f_b{kind}", "2n f_b")
                out.append(Candidate(kk * fb, "axial", src, predicted=pred))
    return out


#: Ring harmonics (largest first, per ring) paired for seed 000 eq. 7 sum/difference lines.
MAX_PAIRED_HARMONICS = 24


def _largest(h: Harmonics, count: int) -> list[int]:
    keep = [(float(a), int(k)) for k, a in zip(h.orders, h.amplitudes, strict=True) if k > 0]
    keep = [ka for ka in keep if ka[0] > 0.0]
    keep.sort(reverse=True)
    return sorted(k for _, k in keep[:count])


def _pair_lines(
    imperfections: BearingImperfections, kin: Kinematics, axial: bool
) -> list[Candidate]:
    r"""Second-order lines of two ring harmonics (seed 000 §2.2.2, eq. 7).

    The product of harmonic :math:`k_1` of part 1 (ring speed :math:`f_1`) and :math:`k_2` of
    part 2 carries :math:`L = k_1 \pm k_2` lobes turning at :math:`k_1 f_1 \pm k_2 f_2`; the
    ball set passes it to the radial direction when :math:`L + m = nZ` with m = ∓1 and to the
    axial direction when m = 0, at :math:`|(L + m) f_c - (k_1 f_1 \pm k_2 f_2)|`. For an inner
    waviness :math:`W_{ni}` and an outer :math:`W_{no}` with the outer ring rotating this is
    Tada's eq. 7, :math:`|W_{no} f_r \mp n f_i|` (f_i = Z f_c). Pairs of two harmonics of the
    same ring follow the same rule.
    """
    z = kin.n_elements
    parts = [
        ("inner", k, kin.inner) for k in _largest(imperfections.inner, MAX_PAIRED_HARMONICS)
    ] + [("outer", k, kin.outer) for k in _largest(imperfections.outer, MAX_PAIRED_HARMONICS)]
    out: list[Candidate] = []
    for a in range(len(parts)):
        for b in range(a + 1, len(parts)):
            (p1, k1, f1), (p2, k2, f2) = parts[a], parts[b]
            for sign in (1, -1):
                lobes = k1 + sign * k2
                turn = k1 * f1 + sign * k2 * f2
                if lobes < 0:
                    lobes, turn = -lobes, -turn
                op = "+" if sign == 1 else "-"
                for m in (-1, 0, 1):
                    if (m == 0 and not axial) or (lobes + m) % z or (lobes == 0 and m != 0):
                        continue
                    n = (lobes + m) // z
                    freq = abs((lobes + m) * kin.cage - turn)
                    if freq <= 0.0:
                        continue
                    rule = f"nZ{'+1' if m == -1 else '-1' if m == 1 else ''}"
                    term = (
                        f"{p1} {k1} {op} {p2} {k2} lobes = {rule}, n={n}, order 2 (seed 000 eq. 7)"
                    )
                    formula = f"|{lobes + m} f_c - ({k1} f_{p1[0]} {op} {k2} f_{p2[0]})|"
                    direction: Direction = "axial" if m == 0 else "radial"
                    out.append(
                        Candidate(freq, direction, _src("rings", None, lobes, term, formula))
                    )
    return out


class PhasorTable:
    """Predicted phasors (X, Y, Z) of first-order lines, by source and frequency.

    Frequencies computed two ways (orders of the linear model, Hz here) agree to round-off:
    a lookup matches within 1e-9 relative.
    """

    def __init__(self) -> None:
        self._rows: dict[tuple[str, int | None, int], list[tuple[float, Phasors]]] = {}

    def add(self, part: str, element: int | None, lobes: int, freq: float, ph: Phasors) -> None:
        """Add a term's phasors to its source's line at ``freq`` [Hz]."""
        rows = self._rows.setdefault((part, element, lobes), [])
        for i, (f, old) in enumerate(rows):
            if abs(f - freq) <= 1e-9 * freq:
                rows[i] = (f, (old[0] + ph[0], old[1] + ph[1], old[2] + ph[2]))
                return
        rows.append((freq, ph))

    def get(self, part: str, element: int | None, lobes: int, freq: float) -> Phasors | None:
        """The phasors of a source's line at ``freq`` [Hz], or None."""
        for f, ph in self._rows.get((part, element, lobes), []):
            if abs(f - freq) <= 1e-9 * freq:
                return ph
        return None


def linear_phasors(
    imperfections: BearingImperfections, kin: Kinematics, contact_angle: float
) -> PhasorTable:
    """Predicted first-order phasors of each ring harmonic and each element deviation.

    From the linearised model (seed 002 eq. 33-40, force-balance gains: seed 000 eq. 5
    linearised), turned into the shaft frame like the models: each term C e^{iΩθ} of
    u = x + i y is a line at |Ω| f_r with x and y phasors (C, -iC) for Ω > 0 and (C̄, iC̄) for
    Ω < 0. Used for the shares of lines several sources produce.
    """
    from runout.models import linear

    rot = abs(kin.rotation)
    table = PhasorTable()
    if rot == 0.0 or kin.n_elements < 3:
        return table
    rates = linear.Rates(
        kin.inner / rot, kin.outer / rot, kin.cage / rot, kin.contact_rate / rot, rot
    )
    terms = linear.closed_form_terms(imperfections, rates, contact_angle, "force_balance")
    names = {0: "inner", 1: "outer", 2: "ball"}
    for om, c, part, lobes, element in zip(
        terms.omega, terms.coefficient, terms.part, terms.lobes, terms.element, strict=True
    ):
        if int(part) not in names or om == 0.0:
            continue
        cc = complex(c)
        x, y = (cc, -1j * cc) if om > 0 else (cc.conjugate(), 1j * cc.conjugate())
        element_no = int(element) + 1 if int(part) == 2 else None
        table.add(names[int(part)], element_no, int(lobes), float(abs(om) * rot), (x, y, 0j))
    _axial_phasors(table, imperfections, kin, contact_angle)
    return table


def _axial_phasors(
    table: PhasorTable, imperfections: BearingImperfections, kin: Kinematics, contact_angle: float
) -> None:
    r"""First-order axial phasors (seed 000 eq. 5 linearised, shaft frame).

    Under a constant preload the axial balance keeps the mean approach: the shaft moves by
    :math:`z = -\sum_j e_j / (Z \sin\alpha)`, with :math:`e_j = (W_{ij} - W_{oj})\cos\alpha +
    W_{bj}` the interference at ball j. A ring harmonic of k = nZ lobes adds up over the balls
    (z = ∓ a cot α at k |f_c - f_ring|); a ball's diameter harmonic of order k passes as
    -d / (Z sin α) at k f_b.
    """
    sa = math.sin(contact_angle)
    if sa <= 1e-9:
        return
    z = kin.n_elements
    ca = math.cos(contact_angle)
    for part, h, f_ring, sign in (
        ("inner", imperfections.inner, kin.inner, -1.0),
        ("outer", imperfections.outer, kin.outer, 1.0),
    ):
        for k, a, phi in zip(h.orders, h.amplitudes, h.phases, strict=True):
            k = int(k)
            w = k * (kin.cage - f_ring)
            if k == 0 or k % z or w == 0.0:
                continue
            c = sign * a * ca / sa * complex(math.cos(phi), math.sin(phi))
            table.add(part, None, k, abs(w), (0j, 0j, c if w > 0 else c.conjugate()))
    rate = kin.contact_rate
    for j, h in enumerate(imperfections.element_diameter_deviations()):
        for k, d, phi in zip(h.orders, h.amplitudes, h.phases, strict=True):
            k = int(k)
            if k == 0 or rate == 0.0:
                continue
            c = -d / (z * sa) * complex(math.cos(phi), math.sin(phi))
            table.add("ball", j + 1, k, abs(k * rate), (0j, 0j, c if rate > 0 else c.conjugate()))


def predicted_lines(
    imperfections: BearingImperfections,
    kin: Kinematics,
    *,
    axial: bool = True,
    second_order_pairs: bool = False,
    loaded: bool = False,
    contact_angle: float | None = None,
) -> list[Candidate]:
    """Every line the imperfections should produce (first to third order), with its source.

    With ``second_order_pairs`` the sum and difference lines of two ring harmonics (seed 000
    eq. 7, :func:`_pair_lines`) are added, for the :data:`MAX_PAIRED_HARMONICS` largest
    harmonics of each ring. ``loaded`` (a radial load) adds the ball-passage lines of the load
    zone, m Z f_c, and the load-zone harmonics of size errors. With ``contact_angle`` the
    first-order lines carry their predicted phasors (:func:`linear_phasors`).
    """
    phasors = (
        linear_phasors(imperfections, kin, contact_angle)
        if contact_angle is not None
        else PhasorTable()
    )
    out: list[Candidate] = []
    for part, h in (("inner", imperfections.inner), ("outer", imperfections.outer)):
        for k in h.orders:
            if int(k) > 0:
                out += _ring_lines(part, int(k), kin, axial, phasors)
    for j in range(kin.n_elements):
        h = imperfections.element_diameter_deviation(j)
        out += _element_lines(j, h, kin, axial, loaded, phasors)
    fc = abs(kin.cage)
    if np.any(np.asarray(imperfections.pitch_errors) != 0.0) and fc > 0.0:
        out.append(Candidate(fc, "radial", _src("pitch", None, None, "f_c", "f_c")))
    if loaded:
        out += _load_zone_lines(imperfections, kin)
    if loaded and fc > 0.0:
        z = kin.n_elements
        for m in (1, 2, 3):
            src = _src("load", None, None, f"ball passage {m}x", f"{m} Z f_c")
            out.append(Candidate(m * z * fc, "radial", src, optional=m > 1))
            if axial:
                out.append(Candidate(m * z * fc, "axial", src, optional=True))
    if second_order_pairs:
        out += _pair_lines(imperfections, kin, axial)
    return out


def _load_zone_lines(imperfections: BearingImperfections, kin: Kinematics) -> list[Candidate]:
    """Lines a radial load adds: the stiffness of the load zone, fixed in space, reads a
    turning ring's k lobes at k f_ring (and its element-passage sidebands |k f_ring ± m Z f_c|),
    and an element's 2n lobes at 2n f_b (all elements swelling together move the shaft along
    the load)."""
    out: list[Candidate] = []
    z, fc = kin.n_elements, abs(kin.cage)
    for part, h, f_ring in (
        ("inner", imperfections.inner, kin.inner),
        ("outer", imperfections.outer, kin.outer),
    ):
        if f_ring == 0.0:
            continue
        sym = "f_i" if part == "inner" else "f_o"
        for k in h.orders:
            k = int(k)
            if k <= 0:
                continue
            base = k * abs(f_ring)
            src = _src(part, None, k, f"k {sym}, load zone", f"{k} {sym}")
            out.append(Candidate(base, "radial", src, optional=True))
            for m in (1, 2):
                for sign, word in ((1, "+"), (-1, "-")):
                    term = f"k {sym} {word} {m} Z f_c, load zone"
                    freq = abs(base + sign * m * z * fc)
                    if freq > 0.0:
                        out.append(Candidate(freq, "radial", _src(part, None, k, term, term), True))
    for j, h in enumerate(imperfections.element_diameter_deviations(), start=1):
        for k in h.orders:
            k = int(k)
            if k > 0 and kin.spin > 0.0:
                src = _src("ball", j, k, "2n f_b, load zone", "2n f_b")
                out.append(Candidate(k * kin.spin, "radial", src, optional=True))
    return out


def decomposition_kinematic(
    kin: Kinematics, imperfections: BearingImperfections, *, unbalance: bool = False
) -> Kinematic:
    """The frequencies residual lines are attributed to (see :class:`Kinematic`)."""
    wavy = any(np.any(h.orders > 0) for h in imperfections.element_diameter_deviations())
    turning = imperfections.inner if kin.rotating_ring == "inner" else imperfections.outer
    slant = imperfections.slant is not None and kin.rotating_ring == "inner"
    synchronous = (
        bool(np.any(turning.amplitudes > 0.0))
        or unbalance
        or slant
        or (kin.inner != 0.0 and kin.outer != 0.0)
    )
    return Kinematic(abs(kin.rotation), kin.cage, kin.spin, kin.n_elements, bool(wavy), synchronous)


def unloaded_note(unloaded: NDArray[np.integer[Any]], n_elements: int) -> str:
    """Readable note on balls that lost contact (count per instant)."""
    worst = int(unloaded.max()) if unloaded.size else 0
    if worst == 0:
        return f"all {n_elements} balls stayed loaded at every instant"
    instants = int(np.count_nonzero(unloaded))
    return (
        f"balls lost contact (no load) at {instants} of {unloaded.size} instants, "
        f"at most {worst} of {n_elements} at once"
    )


SolveFn = Callable[[NDArray[np.float64]], tuple[NDArray[np.float64], NDArray[np.integer[Any]]]]


def measuring_direction(operation: Any) -> NDArray[np.float64]:
    """Unit vector of the radial measuring direction: the radial load's, else +x."""
    if operation.radial_load > 0.0:
        angle = operation.radial_load_direction
        return np.array([math.cos(angle), math.sin(angle)])
    return np.array([1.0, 0.0])


def run_quasi_static(
    case: Any,
    setup: Any,
    solve: Callable[[Any, NDArray[np.float64], Any], tuple[NDArray[np.float64], Any]],
    *,
    model: str,
    planar: bool,
    description: str,
    approach_m: float,
) -> RunResult:
    """The run flow shared by the quasi-static models (seeds 000 and 001).

    Solve on the analysis grid, decompose the record (:mod:`runout.analysis.decompose`: the
    predicted lines, the residual search, RRO/NRRO from the lines), and assemble the result with its
    notes and the model's details (:class:`~runout.analysis.result_details.QuasiStaticDetails`; the
    files layer draws its ``bearing.gif``).

    Parameters
    ----------
    case : Case
        The validated case.
    setup : object
        The model's prepared constants (with ``kinematics``, ``contact_angle``).
    solve : callable
        ``solve(case, time, setup) -> (displacement (3, n) [m], unloaded-ball counts)``.
    model : str
        Model id.
    planar : bool
        True for the 2-D model: no axial lines or direction.
    description : str
        What the displacement is, for the notes.
    approach_m : float
        Reference elastic approach [m]: the initial one under the radial load (2-D), the
        one under the axial preload (3-D).
    """
    an, op = case.analysis, case.operation
    t = time_grid(op.speed, an.revolutions, an.samples)
    disp, unloaded = solve(case, t, setup)
    kin = setup.kinematics
    # the counts are summarised at once: the decomposition's arrays then have their room
    loss_note, unloaded_max = unloaded_note(unloaded, kin.n_elements), int(unloaded.max())
    del unloaded
    u = measuring_direction(op)
    lines = predicted_lines(
        case.imperfections,
        kin,
        axial=not planar,
        second_order_pairs=True,
        loaded=op.radial_load > 0.0,
        contact_angle=setup.contact_angle,
    )
    directions = ("x", "y") if planar else ("x", "y", "z")
    basis = decomposition_kinematic(kin, case.imperfections)
    # the Newton solves stop at RTOL ~ 1e-11 of the elastic approach: lines below 1e-9 of it
    # are the solver's round-off, not runout
    approach = float(getattr(setup, "preload", 0.0) or getattr(setup, "initial_approach", 0.0))
    fit = fit_lines(
        t, disp, lines, op.speed, directions=directions, kinematic=basis, floor=1e-9 * approach
    )
    split = split_runout(
        t,
        disp,
        u,
        fit.components,
        op.speed,
        fit.residual,
        synchronous=basis.synchronous_sources,
        axial=not planar,  # the planar model has no axial degree of freedom
    )
    notes = (
        loss_note,
        description,
        *fit.notes,
        *split.notes,
    )
    result = RunResult(
        model=model,
        title=case.title,
        frequencies=bearing_frequencies(case.bearing, op, setup.contact_angle),
        contact_angle=setup.contact_angle,
        time=t,
        displacement=disp,
        components=fit.components,
        runout=split.runout,
        measuring_direction=u,
        solver_resolution_m=stated_resolution(model, disp, 1e-9 * approach),
        details=QuasiStaticDetails(
            planar=planar,
            approach_m=approach_m,
            unloaded_balls_max=unloaded_max,
            n_elements=kin.n_elements,
            explained_fraction=fit.explained_fraction,
        ),
        notes=notes,
    )
    return result
