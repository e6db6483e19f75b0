r"""Spindle: a rigid shaft on two or more ball bearings, five degrees of freedom.

Extends the three-dimensional quasi-static model of seed 000 (Tada,
:mod:`runout.models.quasi_static_3d`) from one bearing to a shaft: the inner rings are one rigid
body (the shaft), the outer rings sit in a rigid housing, and at every instant the shaft's
displacement :math:`q = (x, y, z, \vartheta_x, \vartheta_y)` (translation at the axial origin,
small rotations about x and y) settles where the Hertz forces of every ball of every bearing
balance the loads. Each bearing keeps seed 000's description of its contacts: its own fixed
contact angle, its own K_n (seed 000 eq. 4), its raceway, ball, size and pitch errors turning
with its own cage (:mod:`runout.models._quasi_static`).

Geometry (derived here; docs/models/spindle.md has the figures)
-----------------------------------------------------------------
Bearing b has its ball-set plane at the axial coordinate :math:`p_b`, pitch radius
:math:`R_b = d_m/2`, contact angle :math:`\alpha_b` and a thrust sign :math:`s_b = \pm 1`: the
direction of the axial load on the shaft it carries (the arrangement: DB, DF, DT). The unit
contact normal of ball j, through the ball centre :math:`r_j = (R_b\cos\theta_j,
R_b\sin\theta_j, p_b)`, is :math:`n_j = (\cos\alpha_b\cos\theta_j, \cos\alpha_b\sin\theta_j,
s_b\sin\alpha_b)`. The shaft moves the point :math:`r_j` by :math:`u_0 + \vartheta\times r_j`,
so the approach of ball j (seed 000 eq. 2 in the shaft's frame, where the shaft moving along
:math:`n_j` compresses the contact) is

.. math::
    \delta_j = c_j + g_j\cdot q, \qquad
    g_j = \big(n_x,\; n_y,\; n_z,\; -p_b n_y + R_b\sin\theta_j\,n_z,\;
              p_b n_x - R_b\cos\theta_j\,n_z\big),

with :math:`c_j = (W_{ij} - W_{oj})\cos\alpha_b + W_{bj} + c_{0b}` as in seed 000 (the
deviations of bearing b) and :math:`c_{0b}` the bearing's preload approach. The moment arms are
those of the line of action through the ball centre: any point of that line gives the same
:math:`n\cdot(\vartheta\times r)`, so the pitch radius and the contact points give one arm.
The contact line of bearing b crosses the axis at its pressure centre
:math:`p_b - s_b R_b\tan\alpha_b`.

Balance: :math:`Q_j = K_b[\delta_j]_+^{3/2}` and :math:`\sum_j Q_j g_j = F`, the generalised
load: :math:`F = (F_x, F_y, F_a, M_x, M_y)` with the radial load acting at the nose,
:math:`M = r_{nose}\times F_r` plus the moment load. It is the stationary point of the convex
potential :math:`\Pi(q) = \sum_j \tfrac{K_j}{2.5}[\delta_j]_+^{5/2} - F\cdot q`, solved by
Newton's method (:mod:`runout.models._spindle_kernels`).

Arrangement and preload
-----------------------
* ``DB`` (back-to-back): the bearings at or before the mean position take thrust along +z
  (:math:`s = +1`), the others along -z; the pressure centres lie outside the span. ``DF``
  (face-to-face): the opposite signs, pressure centres inside. ``DT`` (tandem): all +1.
* Constant-pressure (spring) preload F_p: the outer rings of the -z group slide axially on the
  spring (a sixth coordinate w, their axial slide; their balls see :math:`z - w`) and the
  spring pushes them with F_p: the -z group carries exactly F_p, the +z group F_p plus the
  axial load. In DT the preload is an axial force on the shaft. Each bearing's contact angle
  is its own at the preload it carries (:func:`runout.report.summary.operating_contact_angle`,
  or the fixed ``contact_angle``), shared equally within a group.
* Position (rigid) preload δ_a: the outer rings are fixed; at q = 0 each bearing is pressed
  :math:`\delta_a/2` axially into its contacts, :math:`c_{0b} = (\delta_a/2)\sin\alpha_b`,
  and z settles where the groups balance. The contact angle is the one of the load that
  approach gives (a fixed point of Harris's relation), or the fixed ``contact_angle``.

Reported displacement: the shaft at the nose relative to the housing,
:math:`(x + p_n\vartheta_y,\; y - p_n\vartheta_x,\; z)`, z from the shaft's reference
position of the preload (q = 0), not from one bearing's rings centred.

Stiffness: :math:`K = \sum_j \tfrac32 K_j\delta_j^{1/2} g_j g_j^T` at the solution without
imperfections (t = 0), the spring coordinate condensed out, then expressed at the nose,
:math:`K_n = T^{-T} K T^{-1}` with :math:`q_n = T q`. Each entry of :math:`K_n` holds the other
coordinates: :math:`K_{n,xx}` is the force per displacement of the nose with the tilt held. The
stiffness at the tool, the shaft free to tilt, is :math:`1/C_{ii}` of the compliance
:math:`C = K_n^{-1}` (``tool_point_stiffness_n_per_m``); for an overhung nose it is far lower.

Shares of a line (which source makes it): the response linearised about the static position
without imperfections, :math:`K\,\Delta q(t) = -\sum_j k_j\, g_j(t)\, e_j(t)` with
:math:`k_j = \tfrac32 K_j \delta_j^{1/2}` and :math:`e_j` one source's part of :math:`c_j - c_{0b}`
(one harmonic of one part of one bearing: its inner or outer raceway, or one ball), is
evaluated over the run's record for each source alone and fitted at that source's
first-order lines (:func:`linear_phasors`); each source's phasor at the nose is its predicted
contribution to the line, shared as in :mod:`runout.analysis.decompose`.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from runout.analysis.decompose import JOINT_FIT, Candidate, fit_lines, split_runout
from runout.analysis.result_details import SpindleBearingResult, SpindleDetails, StiffnessMatrix
from runout.analysis.results import RunResult, stated_resolution
from runout.base.errors import ContactLossError, ConvergenceError, GeometryError, NumericalError
from runout.geometry.bearing import BallBearing
from runout.geometry.contact import ball_race_contacts
from runout.geometry.imperfections import BearingImperfections
from runout.geometry.kinematics import ball_spin_frequency, bearing_frequencies, cage_frequency
from runout.geometry.life import MAX_RADIAL_CONTACT_ANGLE, RatingLife
from runout.geometry.loading import operating_contact_angle
from runout.geometry.spindle_layout import SpindleLayout
from runout.models._quasi_static import (
    Kinematics,
    PhasorTable,
    contact_series,
    contact_sources,
    decomposition_kinematic,
    measuring_direction,
    predicted_lines,
    time_grid,
    unloaded_note,
)
from runout.models._spindle_kernels import (
    NOT_CONVERGED,
    OK,
    TOO_FEW_LOADED,
    scratch_for,
    solve_chunk,
)
from runout.models.quasi_static_3d import check_axial_room, preload_approach

if TYPE_CHECKING:
    from runout.case.model import Case
    from runout.geometry.bearing import Operation

__all__ = [
    "BearingSetup",
    "Setup",
    "ball_loads",
    "linear_phasors",
    "nose_record",
    "run",
    "setup",
    "solve",
    "solve_reference",
    "static_stiffness",
    "thrust_signs",
]

MODEL = "spindle"
MAX_ITER = 60
#: Instants whose contact arrays are built at once (bounds the memory of long records).
CHUNK = 4096
CAUSES = {
    TOO_FEW_LOADED: "the loaded balls cannot hold the shaft (too few carry load)",
    2: "singular stiffness matrix: the loaded balls cannot hold the shaft",
    NOT_CONVERGED: "Newton iteration did not converge",
}
DOFS = ("x", "y", "z", "tilt_x", "tilt_y")
#: The end of a solver's refusal: the preload holds the shaft against the loads.
HINT = "raise the preload or lower the loads"


@dataclass(frozen=True)
class BearingSetup:
    """One bearing's constants for the solve.

    Attributes
    ----------
    name : str
        The bearing's name in the case.
    position : float
        p_b [m].
    contact_angle : float
        α_b [rad].
    sign : int
        s_b: +1 carries thrust on the shaft along +z, -1 along -z.
    floating : bool
        Its outer ring slides on the preload spring.
    stiffness : float
        K_n [N/m^1.5].
    approach : float
        c_0b, the preload approach [m].
    axial_load : float
        Preload it carries [N].
    pitch_radius : float
        R_b = d_m / 2 [m].
    kinematics : Kinematics
        Signed ring, cage and spin frequencies [Hz] and the number of balls.
    """

    name: str
    position: float
    contact_angle: float
    sign: int
    floating: bool
    stiffness: float
    approach: float
    axial_load: float
    pitch_radius: float
    kinematics: Kinematics

    @property
    def pressure_centre(self) -> float:
        """Axial coordinate where the contact lines cross the axis [m]."""
        return self.position - self.sign * self.pitch_radius * math.tan(self.contact_angle)


@dataclass(frozen=True)
class Setup:
    """Everything the solve needs.

    Attributes
    ----------
    bearings : tuple of BearingSetup
        Each bearing's constants, in the layout's order.
    force : ndarray, shape (m,)
        Generalised load: F_x, F_y, F_z [N], M_x, M_y [N m], then the spring force [N] when m = 6.
    nose_position : float
        Axial coordinate p_n of the nose [m].
    geo : ndarray, shape (5, N)
        Per ball: cos α, s sin α, p [m], R [m], K_n [N/m^1.5].
    floating : ndarray of bool, shape (N,)
        Per ball: its outer ring slides on the preload spring.
    scale : ndarray, shape (m,)
        Length per unit of each coordinate [m].
    reg : ndarray, shape (m,)
        Newton's regularisation of the Hessian's diagonal.
    d_ref : float
        Smallest preload approach [m].
    preload_key : str
        The case key of the preload (``spindle.preload`` or ``spindle.preload_displacement``):
        a shaft the contacts cannot hold is a preload too small for the loads.
    """

    bearings: tuple[BearingSetup, ...]
    force: NDArray[np.float64]
    nose_position: float
    geo: NDArray[np.float64]
    floating: NDArray[np.bool_]
    scale: NDArray[np.float64]
    reg: NDArray[np.float64]
    d_ref: float
    preload_key: str = "spindle.preload"

    @property
    def n_dof(self) -> int:
        """Coordinates solved: 5, or 6 with a spring-loaded ring."""
        return int(self.force.size)


def thrust_signs(positions: list[float], arrangement: str) -> list[int]:
    """s_b per bearing: DT all +1; DB +1 at or before the mean position, -1 after; DF reversed.

    Parameters
    ----------
    positions : list of float
        Axial positions p_b of the bearings [m].
    arrangement : {"DB", "DF", "DT"}
        Back-to-back, face-to-face or tandem.

    Returns
    -------
    list of int
        s_b = +1 (thrust on the shaft along +z) or -1 (along -z) per bearing [-].

    Raises
    ------
    GeometryError
        DB or DF with every bearing at one position (no pair to oppose).
    """
    if arrangement == "DT":
        return [1] * len(positions)
    mean = sum(positions) / len(positions)
    front = [p <= mean + 1e-12 * max(1.0, abs(mean)) for p in positions]
    if all(front):
        raise GeometryError(
            f"bearings[{len(positions)}].position",
            f"arrangement {arrangement} opposes the bearings before and after the mean "
            "position, but they all sit at one position: give distinct positions",
        )
    sign = 1 if arrangement == "DB" else -1
    return [sign if f else -sign for f in front]


def _angle_at(bearing: Any, operation: Operation, load: float) -> float:
    return operating_contact_angle(bearing, dataclasses.replace(operation, axial_load=load))[0]


def setup(layout: SpindleLayout, operation: Operation) -> Setup:
    """Contact angles, K_n, preload approaches, loads and frequencies (module docstring).

    Parameters
    ----------
    layout : SpindleLayout
        Bearings with their positions [m] and imperfections, arrangement, preload (spring
        force [N] or position preload [m]) and nose position [m].
    operation : Operation
        Ring speeds [Hz], radial [N], axial [N] and moment [N m] loads and their directions
        [rad].

    Returns
    -------
    Setup
        Per-bearing constants, the generalised load [N, N m] and the solver's scales.

    Raises
    ------
    GeometryError
        A key the spindle cannot honour (named as in the case file).

    Notes
    -----
    Each bearing after Tada, "Three-dimensional analysis of non-repeatable runout (NRRO) in
    ball bearings", Koyo Engineering Journal (2002) (seed 000): K_n of eq. 4 and its preload
    approach from the balance of eq. 5 (:func:`runout.models.quasi_static_3d.preload_approach`).
    """
    bs = layout.bearings
    signs = thrust_signs([b.position for b in bs], layout.arrangement)
    spring = layout.preload is not None
    floating = [spring and layout.arrangement != "DT" and s < 0 for s in signs]
    out: list[BearingSetup] = []
    for index, (b, s, fl) in enumerate(zip(bs, signs, floating, strict=True), start=1):
        bearing = b.bearing
        if not isinstance(bearing, BallBearing):
            raise GeometryError(f"bearings[{index}].type", "the spindle model needs ball bearings")
        group = sum(1 for t in signs if t == s)
        if layout.preload is not None:
            load = layout.preload / group
            alpha = _angle_at(bearing, operation, load)
            kn = ball_race_contacts(bearing, alpha).combined_stiffness
            c0 = preload_approach(kn, bearing.elements, alpha, load)
        else:
            assert layout.preload_displacement is not None
            e = 0.5 * layout.preload_displacement
            alpha = bearing.contact_angle or bearing.unloaded_contact_angle
            for _ in range(50):  # the load this approach gives at α, and α at that load
                kn = ball_race_contacts(bearing, alpha).combined_stiffness
                load = kn * bearing.elements * (e * math.sin(alpha)) ** 1.5 * math.sin(alpha)
                new = _angle_at(bearing, operation, load)
                if abs(new - alpha) <= 1e-13:
                    break
                alpha = new
            kn = ball_race_contacts(bearing, alpha).combined_stiffness
            c0 = e * math.sin(alpha)
            load = kn * bearing.elements * c0**1.5 * math.sin(alpha)
        if not alpha > 0.0:
            raise GeometryError(
                f"bearings[{index}].contact_angle", "the spindle model needs a contact angle > 0"
            )
        try:
            check_axial_room(b.imperfections, bearing, alpha, c0)
        except GeometryError as exc:
            key = (
                f"bearings[{index}].contact_angle"
                if exc.key.startswith("bearing")
                else "spindle.preload"
            )
            raise GeometryError(key, exc.message) from None
        d, dm = bearing.element_diameter, bearing.pitch_diameter
        kin = Kinematics(
            inner=operation.inner_speed,
            outer=operation.outer_speed,
            cage=float(cage_frequency(operation.inner_speed, operation.outer_speed, d, dm, alpha)),
            spin=float(
                ball_spin_frequency(operation.inner_speed, operation.outer_speed, d, dm, alpha)
            ),
            rotating_ring=operation.rotating_ring,
            n_elements=bearing.elements,
        )
        out.append(BearingSetup(b.name, b.position, alpha, s, fl, kn, c0, load, 0.5 * dm, kin))
    pn = layout.nose_position
    beta, gamma = operation.radial_load_direction, operation.moment_load_direction
    fx, fy = operation.radial_load * math.cos(beta), operation.radial_load * math.sin(beta)
    fz = operation.axial_load
    if spring and layout.arrangement == "DT":
        fz += float(layout.preload or 0.0)
    force = [
        fx,
        fy,
        fz,
        -pn * fy + operation.moment_load * math.cos(gamma),
        pn * fx + operation.moment_load * math.sin(gamma),
    ]
    if any(floating):
        force.append(float(layout.preload or 0.0))
    geo = np.concatenate(
        [
            np.tile(
                [
                    [math.cos(b.contact_angle)],
                    [b.sign * math.sin(b.contact_angle)],
                    [b.position],
                    [b.pitch_radius],
                    [b.stiffness],
                ],
                (1, b.kinematics.n_elements),
            )
            for b in out
        ],
        axis=1,
    )
    fl_balls = np.concatenate([np.full(b.kinematics.n_elements, b.floating) for b in out])
    lever = max(max(abs(b.position), b.pitch_radius) for b in out)
    m = len(force)
    scale = np.array([1.0, 1.0, 1.0, lever, lever, 1.0][:m])
    d_ref = min(b.approach for b in out)
    st = Setup(
        tuple(out),
        np.array(force),
        pn,
        np.ascontiguousarray(geo),
        fl_balls,
        scale,
        np.zeros(m),
        d_ref,
        "spindle.preload" if layout.preload is not None else "spindle.preload_displacement",
    )
    # the regularisation: 1e-9 of the preloaded stiffness's diagonal, coordinate by coordinate
    hess = _hessian(st, _nominal_c(st), *_nominal_angles(st), np.zeros(m))
    return dataclasses.replace(st, reg=1e-9 * np.maximum(np.diag(hess), 1e-300))


def _nominal_angles(st: Setup) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """cos θ_j, sin θ_j of every ball at t = 0 without pitch errors."""
    counts = [b.kinematics.n_elements for b in st.bearings]
    theta = np.concatenate([2.0 * math.pi * np.arange(z) / z for z in counts])
    return np.cos(theta), np.sin(theta)


def _nominal_c(st: Setup) -> NDArray[np.float64]:
    return np.concatenate([np.full(b.kinematics.n_elements, b.approach) for b in st.bearings])


def normals(st: Setup, cth: NDArray[np.float64], sth: NDArray[np.float64]) -> NDArray[np.float64]:
    """Generalised normals g_j, shape (..., N, m) for cos θ, sin θ of shape (..., N).

    Parameters
    ----------
    st : Setup
        From :func:`setup`.
    cth, sth : ndarray, shape (..., N)
        Cosine and sine of the ball angles θ_j [-].

    Returns
    -------
    ndarray, shape (..., N, m)
        g_j: the contact normal [-] and its moment arms about x and y [m] (module docstring),
        and the spring slide's column [-] when m = 6.
    """
    ca, ssa, p, r = st.geo[0], st.geo[1], st.geo[2], st.geo[3]
    nx, ny = ca * cth, ca * sth
    nz = np.broadcast_to(ssa, nx.shape)
    cols = [nx, ny, nz, -p * ny + r * sth * ssa, p * nx - r * cth * ssa]
    if st.n_dof > 5:
        cols.append(np.where(st.floating, -ssa, 0.0) * np.ones_like(nx))
    return np.stack(cols, axis=-1)


def _hessian(
    st: Setup,
    c: NDArray[np.float64],
    cth: NDArray[np.float64],
    sth: NDArray[np.float64],
    q: NDArray[np.float64],
) -> NDArray[np.float64]:
    g = normals(st, cth, sth)
    d = np.maximum(c + g @ q, 0.0)
    kk = 1.5 * st.geo[4] * np.sqrt(d)
    return np.asarray(np.einsum("j,ja,jb->ab", kk, g, g))


def _raise(status: int, instant: int, time: NDArray[np.float64], key: str) -> None:
    # the preload is what makes the contacts hold the shaft against the loads: name its key
    cause = CAUSES.get(status, "numerical failure")
    t = float(time[instant])
    if status == TOO_FEW_LOADED:
        raise ContactLossError(cause, instant, t, key, HINT)
    if status == NOT_CONVERGED:
        raise ConvergenceError(cause, instant, t, key, HINT)
    raise NumericalError(cause, instant, t, key, HINT)


def contact_arrays(
    st: Setup, imperfections: list[BearingImperfections], t: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Approach at q = 0 and cos θ_j, sin θ_j of every ball at ``t``, shape (n, N) each.

    Parameters
    ----------
    st : Setup
        From :func:`setup`.
    imperfections : list of BearingImperfections
        Each bearing's deviations [m], in the order of ``st.bearings``.
    t : ndarray, shape (n,)
        Instants [s].

    Returns
    -------
    c : ndarray, shape (n, N)
        c_j = (W_ij - W_oj) cos α_b + W_bj + c_0b [m].
    cth, sth : ndarray, shape (n, N)
        Cosine and sine of the ball angles θ_j [-].

    Notes
    -----
    Tada, "Three-dimensional analysis of non-repeatable runout (NRRO) in ball
    bearings", Koyo Engineering Journal (2002) (seed 000), eq. 2, bearing by bearing.
    """
    parts = []
    for b, imp in zip(st.bearings, imperfections, strict=True):
        src = _bearing_sources(imp, b)
        parts.append(contact_series(t, *src.args()))
    c, cth, sth = (
        np.ascontiguousarray(np.concatenate([p[k] for p in parts], axis=1)) for k in range(3)
    )
    return c, cth, sth


def solve(
    st: Setup, imperfections: list[BearingImperfections], time: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Shaft coordinates q at every instant, shape (n, m), and unloaded-ball counts (n,).

    Warm-started Newton solves (:func:`runout.models._spindle_kernels.solve_chunk`) over
    chunks of :data:`CHUNK` instants, the contact arrays of one chunk at a time.

    Parameters
    ----------
    st : Setup
        From :func:`setup`.
    imperfections : list of BearingImperfections
        Each bearing's deviations [m], in the order of ``st.bearings``.
    time : ndarray, shape (n,)
        Instants [s].

    Returns
    -------
    q : ndarray, shape (n, m)
        Shaft coordinates x, y, z [m], θx, θy [rad] (and the spring slide w [m] when m = 6).
    unloaded : ndarray of int, shape (n,)
        Balls without load at each instant.

    Raises
    ------
    ContactLossError, ConvergenceError, NumericalError
        When the shaft cannot be held at some instant (the error names it).
    """
    t = np.ascontiguousarray(time, dtype=np.float64)
    n, m = t.size, st.n_dof
    q = np.empty((n, m))
    unloaded = np.empty(n, dtype=np.int64)
    history = np.zeros((3, m))
    smooth = 0
    scratch = scratch_for(st.geo.shape[1], m)
    for first in range(0, n, CHUNK):
        last = min(n, first + CHUNK)
        c, cth, sth = contact_arrays(st, imperfections, t[first:last])
        status, instant, smooth = solve_chunk(
            c,
            cth,
            sth,
            st.geo,
            st.floating,
            st.force,
            st.reg,
            st.scale,
            history,
            smooth,
            st.d_ref,
            MAX_ITER,
            q[first:last],
            unloaded[first:last],
            scratch,
        )
        if status != OK:
            _raise(int(status), first + int(instant), t, st.preload_key)
    return q, unloaded


def solve_reference(
    st: Setup,
    c: NDArray[np.float64],
    cth: NDArray[np.float64],
    sth: NDArray[np.float64],
    *,
    tol: float,
    max_iter: int = MAX_ITER,
) -> NDArray[np.float64]:
    """Vectorised NumPy Newton solve at all instants at once (reference for tests).

    Same equations as the kernel, independent code: batched :func:`numpy.linalg.solve`,
    steps halved while the residual norm grows, every instant started from q = 0.

    Parameters
    ----------
    st : Setup
        From :func:`setup`.
    c : ndarray, shape (n, N)
        Approach of each ball at q = 0 [m] (:func:`contact_arrays`).
    cth, sth : ndarray, shape (n, N)
        Cosine and sine of the ball angles θ_j [-].
    tol : float
        Newton step tolerance [m] (rotations scaled by the lever of ``st.scale``).
    max_iter : int, optional
        Newton iterations; default :data:`MAX_ITER`.

    Returns
    -------
    ndarray, shape (n, m)
        Shaft coordinates x, y, z [m], θx, θy [rad] (and the spring slide w [m] when m = 6).

    Raises
    ------
    ConvergenceError
        When the Newton iteration does not converge within ``max_iter``.
    """
    g = normals(st, cth, sth)  # (n, N, m)
    k = st.geo[4]
    q = np.zeros((c.shape[0], st.n_dof))

    def residual(qq: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        d = np.maximum(c + np.einsum("nja,na->nj", g, qq), 0.0)
        r = np.einsum("nj,nja->na", k * d**1.5, g) - st.force
        return r, d

    w = 1.0 / st.scale  # residuals compared in forces
    for _ in range(max_iter):
        r, d = residual(q)
        h = np.einsum("nj,nja,njb->nab", 1.5 * k * np.sqrt(d), g, g) + np.diag(st.reg)
        s = -np.linalg.solve(h, r[..., None])[..., 0]
        step = np.ones(q.shape[0])
        norm0 = np.linalg.norm(r * w, axis=1)
        for _ls in range(30):
            r1, _ = residual(q + step[:, None] * s)
            worse = np.linalg.norm(r1 * w, axis=1) > norm0 * (1 + 1e-12)
            if not worse.any():
                break
            step[worse] *= 0.5
        q = q + step[:, None] * s
        if np.max(np.abs(step[:, None] * s) * st.scale) <= tol:
            return q
    raise ConvergenceError(
        "reference Newton iteration did not converge", key=st.preload_key, hint=HINT
    )


def generalised_forces(
    st: Setup,
    c: NDArray[np.float64],
    cth: NDArray[np.float64],
    sth: NDArray[np.float64],
    q: NDArray[np.float64],
) -> NDArray[np.float64]:
    """Σ_j Q_j g_j at one instant (c, cth, sth of shape (N,), q of shape (m,)).

    Parameters
    ----------
    st : Setup
        From :func:`setup`.
    c : ndarray, shape (N,)
        Approach of each ball at q = 0 [m].
    cth, sth : ndarray, shape (N,)
        Cosine and sine of the ball angles θ_j [-].
    q : ndarray, shape (m,)
        Shaft coordinates x, y, z [m], θx, θy [rad] (and the spring slide w [m] when m = 6).

    Returns
    -------
    ndarray, shape (m,)
        Generalised contact force: F_x, F_y, F_z [N], M_x, M_y [N m] (and the spring
        force [N] when m = 6).
    """
    g = normals(st, cth, sth)
    d = np.maximum(c + g @ q, 0.0)
    return np.asarray((st.geo[4] * d**1.5) @ g)


def ball_loads(st: Setup, q: NDArray[np.float64]) -> NDArray[np.float64]:
    """Load of every ball at the shaft's position ``q`` without imperfections (t = 0) [N].

    Parameters
    ----------
    st : Setup
        From :func:`setup`.
    q : ndarray, shape (m,)
        Shaft coordinates x, y, z [m], θx, θy [rad] (and the spring slide w [m] when m = 6).

    Returns
    -------
    ndarray, shape (N,)
        ``Q_j = K_n max(δ_j, 0)^(3/2)`` of every ball, bearing after bearing [N].
    """
    cth, sth = _nominal_angles(st)
    d = np.maximum(_nominal_c(st) + normals(st, cth, sth) @ q, 0.0)
    return np.asarray(st.geo[4] * d**1.5)


def plane_record(q: NDArray[np.float64], position: float) -> NDArray[np.float64]:
    """The shaft's displacement at the axial coordinate ``position`` [m], shape (3, n).

    Parameters
    ----------
    q : ndarray, shape (n, m)
        Shaft coordinates x, y, z [m], θx, θy [rad] at each instant.
    position : float
        Axial coordinate of the plane [m].

    Returns
    -------
    ndarray, shape (3, n)
        (x + p θy, y - p θx, z) [m].
    """
    return np.stack([q[:, 0] + position * q[:, 4], q[:, 1] - position * q[:, 3], q[:, 2]])


def nose_record(st: Setup, q: NDArray[np.float64]) -> NDArray[np.float64]:
    """The shaft's displacement at the nose, (x + p_n θy, y - p_n θx, z), shape (3, n) [m].

    Parameters
    ----------
    st : Setup
        From :func:`setup` (the nose position p_n [m]).
    q : ndarray, shape (n, m)
        Shaft coordinates x, y, z [m], θx, θy [rad] at each instant.

    Returns
    -------
    ndarray, shape (3, n)
        Displacement of the nose relative to the housing [m].
    """
    return plane_record(q, st.nose_position)


def static_stiffness(st: Setup) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The shaft's static position without imperfections (t = 0) and its 5×5 stiffness at the
    nose [N/m, N/rad, N m/m, N m/rad], the spring coordinate condensed out.

    Parameters
    ----------
    st : Setup
        From :func:`setup`.

    Returns
    -------
    q : ndarray, shape (m,)
        Static shaft coordinates x, y, z [m], θx, θy [rad] (and the spring slide w [m]).
    stiffness : ndarray, shape (5, 5)
        Rows and columns x, y, z, θx, θy of the nose.

    Raises
    ------
    ContactLossError, ConvergenceError, NumericalError
        When the shaft cannot be held.
    """
    cth, sth = _nominal_angles(st)
    c = _nominal_c(st)
    m = st.n_dof
    q_out = np.empty((1, m))
    status, _, _ = solve_chunk(
        c[None, :],
        cth[None, :],
        sth[None, :],
        st.geo,
        st.floating,
        st.force,
        st.reg,
        st.scale,
        np.zeros((3, m)),
        0,
        st.d_ref,
        MAX_ITER,
        q_out,
        np.empty(1, dtype=np.int64),
        scratch_for(st.geo.shape[1], m),
    )
    if status != OK:
        _raise(int(status), 0, np.zeros(1), st.preload_key)
    q = q_out[0]
    k = _hessian(st, c, cth, sth, q)
    if m > 5:  # the spring-loaded ring's slide: static condensation
        k = k[:5, :5] - np.outer(k[:5, 5], k[5, :5]) / k[5, 5]
    t = np.eye(5)
    t[0, 4] = st.nose_position
    t[1, 3] = -st.nose_position
    ti = np.linalg.inv(t)
    return q, ti.T @ k @ ti


#: A source's fitted linear line below this fraction of its contact amplitude is round-off of
#: a line the linearised model does not produce there (a higher-order line): no prediction.
PREDICTION_FLOOR = 1e-9


def _bearing_sources(imperfections: BearingImperfections, b: BearingSetup) -> Any:
    """One bearing's contact sources in the spindle: ring deviations along its contact
    angle, elements radially, about its own approach (seed 000 eq. 2, bearing by bearing)."""
    return contact_sources(
        imperfections,
        b.kinematics,
        ring_gain=math.cos(b.contact_angle),
        element_gain=1.0,
        offset=b.approach,
        planar=False,
    )


def _single_sources(
    imperfections: BearingImperfections, b: BearingSetup
) -> list[tuple[str, int | None, int, float, tuple[Any, ...]]]:
    """Each harmonic of one bearing alone: (part, element, lobes, amplitude [m], the
    arguments of :func:`contact_series` with only that harmonic)."""
    src = _bearing_sources(imperfections, b)
    z = b.kinematics.n_elements
    no_ring, no_ball = np.zeros((3, 0)), np.zeros((3, 0))
    out: list[tuple[str, int | None, int, float, tuple[Any, ...]]] = []
    for h in range(src.ring.shape[1]):
        amplitude = abs(float(src.ring[1, h]))
        if amplitude == 0.0:
            continue
        inner = h < src.n_inner
        single = dataclasses.replace(
            src,
            ring=np.ascontiguousarray(src.ring[:, h : h + 1]),
            n_inner=1 if inner else 0,
            ball=no_ball,
            ball_offsets=np.zeros(z + 1, dtype=np.int64),
        )
        part = "inner" if inner else "outer"
        out.append((part, None, int(src.ring[0, h]), amplitude, single.args()))
    for j in range(z):
        for col in range(int(src.ball_offsets[j]), int(src.ball_offsets[j + 1])):
            amplitude = abs(float(src.ball[1, col]))
            if amplitude == 0.0:
                continue
            offsets = np.where(np.arange(z + 1) > j, 1, 0).astype(np.int64)
            single = dataclasses.replace(
                src,
                ring=no_ring,
                n_inner=0,
                ball=np.ascontiguousarray(src.ball[:, col : col + 1]),
                ball_offsets=offsets,
            )
            out.append(("ball", j + 1, int(src.ball[0, col]), amplitude, single.args()))
    return out


def linear_phasors(
    st: Setup,
    imperfections: list[BearingImperfections],
    time: NDArray[np.float64],
    q_static: NDArray[np.float64],
    candidates: list[list[Candidate]],
) -> list[tuple[PhasorTable, dict[tuple[str, int | None, int | None], float]]]:
    r"""Each source's predicted phasors (X, Y, Z) at the nose from the linearised spindle.

    About the static position without imperfections :math:`q_0`, one source's part
    :math:`e_j(t)` of the approaches moves the shaft by

    .. math::
        \Delta q(t) = -K^{-1} \sum_j k_j(t)\, g_j(t)\, e_j(t), \qquad
        k_j = 	frac32 K_j ig[c_{0b} + g_j(t)\cdot q_0ig]_+^{1/2},

    K the stiffness at :math:`q_0` (t = 0, the spring coordinate included), :math:`g_j(t)` at
    the ball's angle at t (module docstring). The nose's record of :math:`\Delta q` over the
    run's instants is fitted, by least squares, at the frequencies of that source's candidate
    lines (those the record resolves, at least 0.3/T apart).

    Parameters
    ----------
    st : Setup
        From :func:`setup`.
    imperfections : list of BearingImperfections
        Each bearing's deviations [m], in the order of ``st.bearings``.
    time : ndarray, shape (n,)
        The run's instants [s] (uniform).
    q_static : ndarray, shape (m,)
        Static shaft coordinates without imperfections (:func:`static_stiffness`).
    candidates : list of list of Candidate
        Each bearing's predicted lines (their frequencies [Hz] by source).

    Returns
    -------
    list of (PhasorTable, dict)
        Per bearing: the phasors [m] by (part, element, lobes) and frequency, and each
        source's contact amplitude [m] (the scale of :data:`PREDICTION_FLOOR`).

    Notes
    -----
    Tada, "Three-dimensional analysis of non-repeatable runout (NRRO) in ball bearings", Koyo
    Engineering Journal (2002) (seed 000), eq. 2-5 linearised, on the rigid shaft of this
    module; the single-bearing counterpart is seed 002's linear model (eq. 33-40,
    :func:`runout.models._quasi_static.linear_phasors`).
    """
    t = np.ascontiguousarray(time, dtype=np.float64)
    n, m = t.size, st.n_dof
    cth0, sth0 = _nominal_angles(st)
    hessian = _hessian(st, _nominal_c(st), cth0, sth0, q_static)
    pn = st.nose_position
    nose = np.zeros((3, m))
    nose[0, 0], nose[0, 4], nose[1, 1], nose[1, 3], nose[2, 2] = 1.0, pn, 1.0, -pn, 1.0
    gain = -np.linalg.solve(hessian.T, nose.T).T  # (3, m): -T K^{-1}
    duration = n * float(t[1] - t[0])
    f_lo, f_hi = 1.0 / duration, 0.5 * n / duration * 0.999
    sep = JOINT_FIT / duration
    out: list[tuple[PhasorTable, dict[tuple[str, int | None, int | None], float]]] = []
    first = 0
    for b, imp, cands in zip(st.bearings, imperfections, candidates, strict=True):
        z = b.kinematics.n_elements
        own = slice(first, first + z)
        first += z
        table = PhasorTable()
        scale: dict[tuple[str, int | None, int | None], float] = {}
        sources = _single_sources(imp, b)
        if not sources:
            out.append((table, scale))
            continue
        sub = dataclasses.replace(st, geo=st.geo[:, own], floating=st.floating[own])
        freqs: list[NDArray[np.float64]] = []
        for part, element, lobes, _, _ in sources:
            fs: list[float] = []
            for f in sorted(
                {
                    c.frequency_hz
                    for c in cands
                    if (c.source.part, c.source.element, c.source.lobes) == (part, element, lobes)
                }
            ):
                if f_lo < f < f_hi and all(abs(f - g) >= sep for g in fs):
                    fs.append(f)
            freqs.append(np.array(fs))
        normal = [np.zeros((2 * f.size + 1, 2 * f.size + 1)) for f in freqs]
        rhs = [np.zeros((2 * f.size + 1, 3)) for f in freqs]
        rates = sources[0][4][0]
        for i0 in range(0, n, CHUNK):
            tc = t[i0 : i0 + CHUNK]
            theta = rates[0] * tc[:, None] + sources[0][4][1] + sources[0][4][2]
            g = normals(sub, np.cos(theta), np.sin(theta))  # (nc, z, m)
            d0 = np.maximum(b.approach + g @ q_static, 0.0)
            w = (1.5 * b.stiffness * np.sqrt(d0))[..., None] * (g @ gain.T)  # (nc, z, 3)
            for i, (_, _, _, _, args) in enumerate(sources):
                if not freqs[i].size:
                    continue
                c, _, _ = contact_series(tc, *args)
                r = np.einsum("nj,nja->na", c - b.approach, w)
                arg = 2.0 * math.pi * np.outer(tc, freqs[i])
                design = np.hstack([np.ones((tc.size, 1)), np.cos(arg), np.sin(arg)])
                normal[i] += design.T @ design
                rhs[i] += design.T @ r
        for i, (part, element, lobes, amplitude, _) in enumerate(sources):
            key = (part, element, lobes)
            scale[key] = max(scale.get(key, 0.0), amplitude)
            k = freqs[i].size
            if not k:
                continue
            coef = np.linalg.lstsq(normal[i], rhs[i], rcond=None)[0]
            for f, a, bb in zip(freqs[i], coef[1 : k + 1], coef[k + 1 :], strict=True):
                ph = a - 1j * bb  # x = a cos ωt + b sin ωt = Re((a - ib) e^{iωt})
                table.add(part, element, lobes, float(f), (ph[0], ph[1], ph[2]))
        out.append((table, scale))
    return out


def _bearing_lines(
    st: Setup,
    imperfections: list[BearingImperfections],
    loaded: bool,
) -> list[list[Candidate]]:
    """Every bearing's predicted lines (seed 000 Tables 2-3), their sources naming it."""
    out: list[list[Candidate]] = []
    for b, imp in zip(st.bearings, imperfections, strict=True):
        candidates = predicted_lines(
            imp, b.kinematics, axial=True, second_order_pairs=True, loaded=loaded
        )
        out.append(
            [
                dataclasses.replace(
                    cand,
                    source=dataclasses.replace(
                        cand.source, term=f"{cand.source.term} ({b.name} bearing)"
                    ),
                )
                for cand in candidates
            ]
        )
    return out


def _with_predictions(
    candidates: list[list[Candidate]],
    tables: list[tuple[PhasorTable, dict[tuple[str, int | None, int | None], float]]],
) -> list[Candidate]:
    """The candidates of every bearing, each carrying its source's linearised phasor at the
    nose where the linearised model produces that line (else None: no prediction)."""
    out: list[Candidate] = []
    for cands, (table, scale) in zip(candidates, tables, strict=True):
        for cand in cands:
            s = cand.source
            key = (s.part, s.element, s.lobes)
            ph = table.get(s.part, s.element, s.lobes or 0, cand.frequency_hz)
            floor = PREDICTION_FLOOR * scale.get(key, 0.0)
            axes = (0, 1) if cand.direction == "radial" else (2,)
            if ph is not None and max(abs(ph[a]) for a in axes) <= floor:
                ph = None
            out.append(dataclasses.replace(cand, predicted=ph))
    return out


def _bearing_lives(
    case: Case, st: Setup, q_static: NDArray[np.float64]
) -> tuple[list[RatingLife | None], list[str]]:
    """Each bearing's ISO/TS 16281 life from its ball loads at the static position, and notes.

    A bearing without ``dynamic_load_rating`` has none (a note names it when another bearing
    has one). Seed 000's contacts have one load per ball, the same on both raceways (no
    centrifugal force), along the bearing's fixed contact angle; the rating's nominal angle is
    the bearing's ``nominal_contact_angle`` when the case gives it, else 0 (as the equilibrium
    model rates it).
    """
    from runout.models.equilibrium import LifeModification, ball_loads_life

    layout = case.spindle
    assert layout is not None
    loads = ball_loads(st, q_static)
    base = LifeModification.of_case(case)
    lives: list[RatingLife | None] = []
    notes: list[str] = []
    missing: list[str] = []
    start = 0
    for i, (b, entry) in enumerate(zip(st.bearings, layout.bearings, strict=True), start=1):
        z = b.kinematics.n_elements
        q_b = loads[start : start + z]
        start += z
        bearing = entry.bearing
        spec = case.spec.bearings[i - 1]
        if not isinstance(bearing, BallBearing) or bearing.dynamic_load_rating is None:
            lives.append(None)
            missing.append(f"bearings[{i}] ({b.name})")
            continue
        nominal = spec.nominal_contact_angle
        if nominal is not None and nominal > MAX_RADIAL_CONTACT_ANGLE:
            lives.append(None)
            notes.append(
                f"bearings[{i}].dynamic_load_rating: no life for {b.name}: the nominal contact "
                f"angle {math.degrees(nominal):.6g} deg exceeds 45 deg (a thrust ball bearing)"
            )
            continue
        mod = dataclasses.replace(base, fatigue_load_limit=spec.fatigue_load_limit)
        life, own = ball_loads_life(
            bearing,
            case.operation,
            q_b,
            q_b,
            0.0 if nominal is None else nominal,
            mod,
            table=f"bearings[{i}]",
        )
        lives.append(life)
        notes += [f"{b.name}: {n}" for n in own]
    if len(missing) < len(st.bearings):
        notes.append(
            "life: each bearing's from its ball loads at the static position without "
            "imperfections (seed 000's contacts: one load per ball on both raceways, no "
            "centrifugal force, the contact angle fixed at its preloaded value)"
        )
        if missing:
            notes.append("no life for " + ", ".join(missing) + ": give its dynamic_load_rating (C)")
    return lives, notes


def run(case: Case) -> RunResult:
    """Run the spindle model on a spindle case (``[spindle]`` + ``[[bearings]]``).

    Parameters
    ----------
    case : Case
        A validated case with ``[analysis] model = "spindle"``, a ``[spindle]`` table and two
        or more ``[[bearings]]``.

    Returns
    -------
    RunResult
        The nose's displacement relative to the housing [m], the fitted lines, the runout
        figures [m] and :class:`~runout.analysis.result_details.SpindleDetails` (per-bearing
        runout, static position, 5×5 stiffness at the nose).

    Raises
    ------
    GeometryError
        No ``[spindle]`` table, or a key the spindle cannot honour.

    Notes
    -----
    Each bearing's contacts after Tada, "Three-dimensional analysis of non-repeatable runout
    (NRRO) in ball bearings", Koyo Engineering Journal (2002) (seed 000), eq. 2-5, extended to
    a rigid shaft with five degrees of freedom (module docstring).
    """
    layout = case.spindle
    if layout is None:
        raise GeometryError(
            "analysis.model",
            'model = "spindle" needs a [spindle] table and two or more [[bearings]]',
        )
    op, an = case.operation, case.analysis
    st = setup(layout, op)
    imps = [b.imperfections for b in layout.bearings]
    t = time_grid(op.speed, an.revolutions, an.samples)
    q, unloaded = solve(st, imps, t)
    q_static, stiffness = static_stiffness(st)
    n_balls = int(st.geo.shape[1])
    loss_note, unloaded_max = unloaded_note(unloaded, n_balls), int(unloaded.max())
    lead = st.bearings[0]
    u = measuring_direction(op)
    loaded = op.radial_load > 0.0
    basis = decomposition_kinematic(lead.kinematics, imps[0])
    floor = 1e-9 * st.d_ref
    # each source's share of a line: its contribution in the linearised spindle (docstring)
    per_bearing = _bearing_lines(st, imps, loaded)
    tables = linear_phasors(st, imps, t, q_static, per_bearing)
    lines = _with_predictions(per_bearing, tables)

    def decompose(disp: NDArray[np.float64]) -> Any:
        fit = fit_lines(t, disp, lines, op.speed, kinematic=basis, floor=floor)
        split = split_runout(
            t,
            disp,
            u,
            fit.components,
            op.speed,
            fit.residual,
            synchronous=basis.synchronous_sources,
        )
        return fit, split

    disp = nose_record(st, q)
    fit, split = decompose(disp)
    lives, life_notes = _bearing_lives(case, st, q_static)
    rows = []
    for b, life in zip(st.bearings, lives, strict=True):
        record = plane_record(q, b.position)
        _, split_b = decompose(record)
        mean = record.mean(axis=1)
        rows.append(
            SpindleBearingResult(
                name=b.name,
                position_m=b.position,
                contact_angle_deg=math.degrees(b.contact_angle),
                thrust="+z" if b.sign > 0 else "-z",
                preload_n=b.axial_load,
                preload_approach_m=b.approach,
                pressure_centre_m=b.pressure_centre,
                runout=split_b.runout,
                mean_displacement_m=(float(mean[0]), float(mean[1]), float(mean[2])),
                life=life,
            )
        )
    preload_note = (
        f"constant-pressure preload {layout.preload:.6g} N (spring on the -z group's outer rings)"
        if layout.preload is not None and layout.arrangement != "DT"
        else f"constant axial preload {layout.preload:.6g} N on the shaft (tandem)"
        if layout.preload is not None
        else f"position preload {layout.preload_displacement * 1e6:.6g} um (outer rings fixed)"
        if layout.preload_displacement is not None
        else ""
    )
    notes = (
        loss_note,
        f"rigid shaft on {len(st.bearings)} bearings ({layout.arrangement}), each with its "
        "contact angle fixed at its preloaded value (seed 000); displacement of the nose at "
        f"z = {st.nose_position * 1e3:.6g} mm; z from the shaft's preload reference position, "
        "not from one bearing's rings axially centred",
        preload_note,
        "frequencies and residual-line attribution use the first bearing "
        f"({lead.name}); every bearing's predicted lines are fitted, their sources name it; "
        "a line's sources share it by their contributions in the linearised spindle "
        "(each bearing's parts alone; second-order sources share what those leave)",
        *life_notes,
        *fit.notes,
        *split.notes,
    )
    details = SpindleDetails(
        arrangement=layout.arrangement,
        nose_position_m=st.nose_position,
        tilt_pp_rad=(float(np.ptp(q[:, 3])), float(np.ptp(q[:, 4]))),
        static_position=tuple(float(v) for v in q_static[:5]),
        bearings=tuple(rows),
        stiffness_matrix=StiffnessMatrix(
            dofs=DOFS,
            units="rows F_x, F_y, F_z [N], M_x, M_y [N m]; columns per m or per rad (at the nose)",
            matrix=tuple(tuple(float(v) for v in row) for row in stiffness),
        ),
        unloaded_balls_max=unloaded_max,
        n_elements=n_balls,
        explained_fraction=fit.explained_fraction,
    )
    return RunResult(
        model=MODEL,
        title=case.title,
        frequencies=bearing_frequencies(case.bearing, op, lead.contact_angle),
        contact_angle=lead.contact_angle,
        time=t,
        displacement=disp,
        components=fit.components,
        runout=split.runout,
        measuring_direction=u,
        solver_resolution_m=stated_resolution(MODEL, disp, floor),
        details=details,
        notes=tuple(n for n in notes if n),
    )
