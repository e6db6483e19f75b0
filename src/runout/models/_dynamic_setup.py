r"""Set-up and physics of the dynamic model (seed 003): contact law, preloaded contact angle,
the rotor's description, contact forces and stiffness, references and the static start.

Part of :mod:`runout.models.dynamic` (which documents the model and re-exports these names).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Literal

import numpy as np
from numpy.typing import NDArray

from runout.base.errors import ConvergenceError, GeometryError
from runout.geometry.bearing import BallBearing
from runout.geometry.contact import (
    RaceName,
    ball_race_contacts,
    ball_race_curvature,
    combined_stiffness,
    stiffness_from_delta_star_table,
)
from runout.geometry.imperfections import pack_harmonics
from runout.geometry.kinematics import ball_spin_frequency, cage_frequency
from runout.models._dynamic_kernels import (
    FORCE_RTOL,  # noqa: F401 - re-exported with the kernels (docs, tests)
    N_PAR,
    N_SP,
    NEWTON_RTOL,
    OK,
    P_A,
    P_C,
    P_FU,
    P_FX,
    P_FY,
    P_FZ,
    P_G0,
    P_H,
    P_K,
    P_M,
    P_TOL,
    P_WB,
    P_WC,
    P_WI,
    P_WO,
    P_WU,
    P_ZP,
    S_ANGLE,
    S_ARC,
    S_BALL,
    S_DEPTH,
    S_ELEMENT,
    S_RADIUS,
    S_RATE,
    S_WIDTH,
    Harmonics,
    _contact,  # noqa: F401
    _deviations,  # noqa: F401
    static_kernel,
)
from runout.models._quasi_static import (
    Kinematics,
)

TWO_PI = 2.0 * math.pi
ContactLaw = Literal["exact", "delta_star_table"]
#: Most Newton–Raphson iterations of one Newmark step (and of the NumPy reference's).
MAX_ITER = 50
#: Widest spall, as a fraction of the circumference of the surface it is on: a localized
#: defect, not a missing stretch of raceway.
MAX_SPALL_FRACTION = 0.1


# --------------------------------------------------------------------------------------------
# set-up
# --------------------------------------------------------------------------------------------
def _law_stiffness(bearing: BallBearing, alpha: float, law: str) -> float:
    """K_n [N/m^1.5] at contact angle α by the exact Hertz solution or the δ* table."""
    if law == "exact":
        return float(ball_race_contacts(bearing, alpha).combined_stiffness)
    if law == "delta_star_table":
        ep = bearing.material.effective_modulus
        ks = []
        races: tuple[tuple[RaceName, float], ...] = (
            ("inner", bearing.inner_conformity),
            ("outer", bearing.outer_conformity),
        )
        for race, f in races:
            s, fr = ball_race_curvature(
                bearing.element_diameter, bearing.pitch_diameter, f, alpha, race
            )
            ks.append(float(stiffness_from_delta_star_table(s, fr, ep)))
        return float(combined_stiffness(ks[0], ks[1]))
    raise GeometryError("dynamics.contact_law", f'must be "exact" or "delta_star_table": {law!r}')


def preloaded_contact_angle(
    bearing: BallBearing, preload: float, free_contact_angle: float, law: str = "exact"
) -> tuple[float, float]:
    r"""Contact angle α_p [rad] and K_n [N/m^1.5] of a bearing under an axial preload.

    Solves (seed 003 eq. 2.21–2.22 with clearance, see module Notes)

    .. math:: P_l = Z K_n(\alpha_p)\,\big(A\cos\alpha^0/\cos\alpha_p - A\big)^{3/2}\sin\alpha_p

    by Brent's method on :math:`[\alpha^0, 90°)`, with K_n of ``law`` at α_p.

    Parameters
    ----------
    bearing : BallBearing
    preload : float
        Axial preload P_l [N] (>= 0); 0 returns α⁰.
    free_contact_angle : float
        α⁰ = arccos(1 − P_d/2A) [rad] (Harris's free contact angle of the clearance).
    law : {"exact", "delta_star_table"}
    """
    return _preloaded_contact_angle(bearing, float(preload), float(free_contact_angle), law)


@functools.lru_cache(maxsize=64)
def _preloaded_contact_angle(
    bearing: BallBearing, preload: float, free_contact_angle: float, law: str
) -> tuple[float, float]:
    """:func:`preloaded_contact_angle`, remembered: a run sets the same bearing up twice (the
    case check and the model), and each solve takes some 40 Hertz solutions."""
    a = bearing.curvature_distance
    z = bearing.elements
    if preload <= 0.0:
        return free_contact_angle, _law_stiffness(bearing, free_contact_angle, law)

    def carried(alpha: float) -> float:
        stretch = max(math.cos(free_contact_angle) / math.cos(alpha) - 1.0, 0.0)
        k = _law_stiffness(bearing, alpha, law)
        force: float = z * k * (a * stretch) ** 1.5 * math.sin(alpha)
        return force

    def residual(alpha: float) -> float:
        return carried(alpha) / preload - 1.0

    hi = 0.5 * math.pi * (1.0 - 1e-6)
    if not carried(hi) >= preload:  # no angle short of 90 degrees carries the preload
        raise GeometryError(
            "operation.axial_load",
            f"the preload {preload:.4g} N is more than the {carried(hi):.4g} N the balls carry "
            "at a contact angle of 90 deg (the Hertz contacts would be crushed long before)",
        )
    from scipy.optimize import brentq  # lazily: ~0.1 s of CLI start-up

    alpha = float(brentq(residual, free_contact_angle, hi, xtol=1e-15, rtol=8.9e-16))
    return alpha, _law_stiffness(bearing, alpha, law)


@dataclass(frozen=True)
class DynamicSetup:
    """Everything the integration needs, derived from a case (SI).

    Attributes
    ----------
    mass, damping : float
        m [kg], c [N s/m].
    ndof : int
        2 (x, y) or 3 (x, y, z).
    curvature_distance : float
        A [m].
    radial_gap : float
        g_0 = −P_d/2 [m], minus the radial play (seed 003's γ) of ``radial_clearance`` P_d.
    axial_offset : float
        z_p [m].
    stiffness : float
        K_n [N/m^1.5].
    contact_angle : float
        α_p [rad] (kinematics).
    free_contact_angle : float
        α⁰ = arccos(1 − P_d/2A) [rad] (Harris's free contact angle of the clearance).
    force : ndarray, shape (3,)
        Constant external force on the rotor [N].
    unbalance_force : float
        F_u = m_u e Ω² [N].
    unbalance_omega : float
        Ω [rad/s].
    theta0 : ndarray, shape (Z,)
        Ball angles at t = 0 [rad].
    kinematics : Kinematics
        Signed ring, cage and spin frequencies [Hz].
    harmonics : tuple of ndarray
        Packed waviness (inner k, a, φ; outer k, a, φ; ball k, a, φ, offsets).
    spalls : ndarray, shape (n, N_SP)
        The ``[[defect]]`` entries, one row each (columns ``S_*`` of
        :mod:`runout.models._dynamic_kernels`); empty without defects.
    slip : ndarray
        The cage's slip angle at knots, ``[t0, T, φ_0, φ_1, ...]``
        (:func:`runout.models._dynamic_kernels.slip_angle`); empty: the exact kinematics.
    contact_law : str
    reference_approach : float
        Approach scale for tolerances [m].
    notes : tuple of str
    """

    mass: float
    damping: float
    ndof: int
    curvature_distance: float
    radial_gap: float
    axial_offset: float
    stiffness: float
    contact_angle: float
    free_contact_angle: float
    force: NDArray[np.float64]
    unbalance_force: float
    unbalance_omega: float
    theta0: NDArray[np.float64]
    kinematics: Kinematics
    harmonics: Harmonics
    spalls: NDArray[np.float64] = field(default_factory=lambda: np.zeros((0, N_SP)))
    slip: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))
    contact_law: str = "exact"
    reference_approach: float = 1e-6
    notes: tuple[str, ...] = ()

    @property
    def n_elements(self) -> int:
        """Z."""
        return int(self.theta0.size)

    def params(self, h: float) -> NDArray[np.float64]:
        """Scalar parameter vector of the kernels for step ``h`` [s]."""
        p = np.zeros(N_PAR)
        kin = self.kinematics
        p[P_H] = h
        p[P_M] = self.mass
        p[P_C] = self.damping
        p[P_A] = self.curvature_distance
        p[P_G0] = self.radial_gap
        p[P_ZP] = self.axial_offset
        p[P_K] = self.stiffness
        p[P_WC] = TWO_PI * kin.cage
        p[P_WI] = TWO_PI * kin.inner
        p[P_WO] = TWO_PI * kin.outer
        p[P_WB] = TWO_PI * kin.contact_rate  # signed: see Kinematics.contact_rate
        p[P_FU] = self.unbalance_force
        p[P_WU] = self.unbalance_omega
        p[P_FX], p[P_FY], p[P_FZ] = self.force
        p[P_TOL] = NEWTON_RTOL * self.reference_approach
        return p

    def replace(self, **changes: Any) -> DynamicSetup:
        """A copy with some fields changed (tests and benchmarks)."""
        from dataclasses import replace

        return replace(self, **changes)


def _dyn(case: Any) -> Any:
    spec = case.dynamics
    if spec is None:
        raise GeometryError("dynamics", 'model = "dynamic" needs a [dynamics] table with the mass')
    return spec


def _preload_notes(case: Any, op: Any) -> list[str]:
    """What the run says about its preload kind: the older key it read, or its default.

    An older case file's ``[dynamics] axial_dof`` keeps its result and is named with what to
    write instead; a case with an axial load that names neither kind is told that its rotor
    is free axially (the dynamic model held it by default before ``preload`` existed).
    """
    spec = getattr(case, "spec", None)
    if spec is None:
        return []
    dof = spec.dynamics.axial_dof if spec.dynamics is not None else None
    kind = op.preload
    if dof is not None:
        return [
            f"dynamics.axial_dof = {str(dof).lower()} is read as [operation] preload = "
            f'"{kind}"; write that instead (axial_dof is kept for older case files)'
        ]
    if "preload" not in spec.operation.model_fields_set and op.axial_load > 0.0:
        return [
            'operation.preload = "spring" (the default): the rotor moves axially under the '
            'constant axial load; write preload = "position" to hold it at the rings\' '
            "preloaded axial offset (the dynamic model's default before the preload key)"
        ]
    return []


def setup(case: Any) -> DynamicSetup:
    """Derive the rotor, contact and kinematic constants of a case (see module docstring).

    The radial play is P_d/2 of ``bearing.radial_clearance`` (seed 003 eq. 2.3–2.4, γ);
    with an axial preload the contact angle α_p solves eq. 2.21–2.22 with clearance
    (:func:`preloaded_contact_angle`). No input is altered.

    Parameters
    ----------
    case : Case
        A ball bearing case with a ``[dynamics]`` table and a speed > 0.

    Returns
    -------
    DynamicSetup

    Raises
    ------
    GeometryError
        No ``[dynamics]`` table, not a ball bearing, speed <= 0, a fixed
        ``bearing.contact_angle`` (not honoured by this model), an unbalance on a still inner
        ring, or no load to hold the rotor.
    """
    bearing = case.bearing
    op = case.operation
    dyn = _dyn(case)
    if not isinstance(bearing, BallBearing):
        raise GeometryError("bearing.type", "the dynamic model needs a ball bearing (seed 003)")
    if not (math.isfinite(op.speed) and op.speed > 0.0):
        raise GeometryError("operation.speed", f"must be > 0 for the dynamic model: {op.speed!r}")
    if bearing.contact_angle is not None:
        # a fixed operating angle cannot be honoured: the contact angle of this model follows
        # from the clearance, the preload and the motion (a case's nominal_contact_angle has
        # already become radial_clearance = 2A(1 - cos α⁰))
        raise GeometryError(
            "bearing.contact_angle",
            "the dynamic model does not hold a fixed (operating) contact angle: its contact "
            "angle follows from radial_clearance and the axial load; give the free angle as "
            "nominal_contact_angle (or radial_clearance) instead",
        )
    notes: list[str] = []
    a = bearing.curvature_distance
    alpha0 = bearing.free_contact_angle  # cos α⁰ = 1 - P_d / 2A (Harris)
    law = dyn.contact_law
    # spring: the axial force is constant and z is a degree of freedom; position: z is held
    # at z_p, the rings' axial offset under the axial load alone (eq. 2.21-2.22)
    ndof = 3 if op.preload == "spring" else 2
    notes.extend(_preload_notes(case, op))
    alpha_p, kn = preloaded_contact_angle(bearing, op.axial_load, alpha0, law)
    zp = a * math.cos(alpha0) * math.tan(alpha_p) if op.axial_load > 0.0 else 0.0
    if op.axial_load > 0.0:
        kin_alpha = alpha_p
    else:
        kin_alpha = 0.0  # rings axially centred: the balls touch at the groove bottoms
        alpha_p = 0.0
    g0 = -0.5 * bearing.radial_clearance  # radial play γ = P_d/2 of seed 003 eq. 2.3-2.4
    beta = op.radial_load_direction
    force = np.array(
        [
            op.radial_load * math.cos(beta),
            op.radial_load * math.sin(beta),
            op.axial_load if ndof == 3 else 0.0,
        ]
    )
    omega_u = TWO_PI * op.inner_speed
    fu = dyn.unbalance * omega_u**2
    if dyn.unbalance > 0.0 and op.inner_speed == 0.0:
        raise GeometryError(
            "dynamics.unbalance",
            "the rotor of the dynamic model is the inner ring; it does not turn, so an "
            "unbalance cannot act (seed 003 assumption 2)",
        )
    if op.axial_load <= 0.0 and op.radial_load <= 0.0:
        # no static position: the rotor floats in its play (or touches with zero stiffness)
        # and the step, the transient and the natural frequencies have no scale
        raise GeometryError(
            "operation.radial_load",
            "the dynamic model needs a radial load or an axial preload to hold the rotor "
            "(with neither, it has no static position and no contact stiffness); an "
            "unbalance alone does not hold it",
        )
    z = bearing.elements
    d, dm = bearing.element_diameter, bearing.pitch_diameter
    kin = Kinematics(
        inner=op.inner_speed,
        outer=op.outer_speed,
        cage=float(cage_frequency(op.inner_speed, op.outer_speed, d, dm, kin_alpha)),
        spin=float(ball_spin_frequency(op.inner_speed, op.outer_speed, d, dm, kin_alpha)),
        rotating_ring=op.rotating_ring,
        n_elements=z,
    )
    imp = case.imperfections
    theta0 = TWO_PI * np.arange(z) / z + np.asarray(imp.pitch_errors, dtype=np.float64)
    kb, ab, pb, off = pack_harmonics(imp.element_diameter_deviations())
    harmonics: Harmonics = (
        imp.inner.orders.astype(np.float64),
        imp.inner.amplitudes.copy(),
        imp.inner.phases.copy(),
        imp.outer.orders.astype(np.float64),
        imp.outer.amplitudes.copy(),
        imp.outer.phases.copy(),
        kb,
        ab,
        pb,
        off,
    )
    spalls = spall_table(case, kin, d, dm)
    if imp.slant is not None and imp.slant.amplitude > 0.0:
        notes.append("raceway slant is not part of the dynamic model and was ignored")
    # approach scale: the preload approach, else the Hertz approach of a ball carrying the load
    load = max(op.radial_load, op.axial_load, fu, 1e-3)
    ref = (load / (kn * max(1, z // 4))) ** (2.0 / 3.0)
    return DynamicSetup(
        mass=dyn.mass,
        damping=dyn.damping,
        ndof=ndof,
        curvature_distance=a,
        radial_gap=g0,
        axial_offset=zp,
        stiffness=kn,
        contact_angle=alpha_p,
        free_contact_angle=alpha0,
        force=force,
        unbalance_force=fu,
        unbalance_omega=omega_u,
        theta0=theta0,
        kinematics=kin,
        harmonics=harmonics,
        spalls=spalls,
        contact_law=law,
        reference_approach=ref,
        notes=tuple(notes),
    )


def spall_table(
    case: Any, kin: Kinematics, element_diameter: float, pitch_diameter: float
) -> NDArray[np.float64]:
    """The kernels' table of the case's ``[[defect]]`` entries, each checked against the bearing.

    Parameters
    ----------
    case : Case
        Its ``spec.defect`` entries (SI).
    kin : Kinematics
        Ring, cage and spin frequencies [Hz].
    element_diameter, pitch_diameter : float
        D and d_m [m].

    Returns
    -------
    ndarray, shape (n, N_SP)
        One row per defect (columns ``S_*``).

    Raises
    ------
    GeometryError
        A spall wider than :data:`MAX_SPALL_FRACTION` of its surface's circumference, deeper
        than the ball radius, or on a ball the bearing does not have (the key named).
    """
    entries = list(getattr(case.spec, "defect", ()) or ())
    out = np.zeros((len(entries), N_SP))
    r = 0.5 * element_diameter
    z = int(case.bearing.elements)
    for i, entry in enumerate(entries):
        key = f"defect[{i + 1}]"
        if entry.part == "ball":
            arc, rate, angle = r, TWO_PI * kin.contact_rate, 0.0
            surface = "the ball"
        else:
            # raceway radii at the groove bottom (contact angle 0)
            sign = 1.0 if entry.part == "outer" else -1.0
            arc = 0.5 * (pitch_diameter + sign * element_diameter)
            rate = TWO_PI * (kin.outer if entry.part == "outer" else kin.inner)
            angle = float(entry.angle or 0.0)
            surface = f"the {entry.part} raceway"
        widest = MAX_SPALL_FRACTION * TWO_PI * arc
        if entry.width >= widest:
            raise GeometryError(
                f"{key}.width",
                f"{entry.width * 1e3:.6g} mm is not a localized defect: it must be below "
                f"{MAX_SPALL_FRACTION:g} of the circumference of {surface} "
                f"({widest * 1e3:.6g} mm)",
            )
        if entry.depth >= r:
            raise GeometryError(
                f"{key}.depth",
                f"{entry.depth * 1e3:.6g} mm must be below the ball radius ({r * 1e3:.6g} mm)",
            )
        element = 0
        if entry.part == "ball":
            if entry.element > z:
                raise GeometryError(
                    f"{key}.element",
                    f"ball {entry.element} does not exist: the bearing has {z} (1 to {z})",
                )
            element = entry.element - 1
        out[i, S_BALL] = 1.0 if entry.part == "ball" else 0.0
        out[i, S_RATE] = rate
        out[i, S_ANGLE] = angle
        out[i, S_ARC] = arc
        out[i, S_WIDTH] = entry.width
        out[i, S_DEPTH] = entry.depth
        out[i, S_RADIUS] = r
        out[i, S_ELEMENT] = element
    return out


def slip_angles_np(st: DynamicSetup, t: NDArray[np.float64]) -> NDArray[np.float64]:
    """The cage's slip angle at instants t [rad] (0 without slip), by :func:`numpy.interp`."""
    t = np.atleast_1d(np.asarray(t, dtype=np.float64))
    if st.slip.size < 4:
        return np.zeros_like(t)
    knots = st.slip[0] + st.slip[1] * np.arange(st.slip.size - 2)
    values = st.slip[2:]
    inside = np.interp(t, knots, values)
    # beyond the knots: the first or last interval's line, as the kernels extend it
    lo = values[0] + (values[1] - values[0]) * (t - knots[0]) / st.slip[1]
    hi = values[-2] + (values[-1] - values[-2]) * (t - knots[-2]) / st.slip[1]
    out: NDArray[np.float64] = np.where(t < knots[0], lo, np.where(t > knots[-1], hi, inside))
    return out


def spall_drops_np(st: DynamicSetup, t: NDArray[np.float64]) -> NDArray[np.float64]:
    """Drop of every ball into the spalls [m], shape (n, Z): the kernels' sum, vectorised.

    An independent NumPy path for the tests of the compiled one
    (:func:`runout.models._dynamic_kernels.spall_drop`).
    """
    t = np.atleast_1d(np.asarray(t, dtype=np.float64))
    out = np.zeros((t.size, st.n_elements))
    wc = TWO_PI * st.kinematics.cage
    phi = slip_angles_np(st, t)

    def drop(angle: NDArray[np.float64], row: NDArray[np.float64]) -> NDArray[np.float64]:
        wrapped = np.angle(np.exp(1j * angle))
        e = 0.5 * row[S_WIDTH] - row[S_ARC] * np.abs(wrapped)
        rad = row[S_RADIUS]
        sunk = rad - np.sqrt(np.clip(rad * rad - e * e, 0.0, None))
        return np.where(e > 0.0, np.minimum(sunk, row[S_DEPTH]), 0.0)

    for row in st.spalls:
        if row[S_BALL] == 0.0:
            ang = st.theta0[None, :] + ((wc - row[S_RATE]) * t + phi)[:, None] - row[S_ANGLE]
            out += drop(ang, row)
        else:
            ang = row[S_RATE] * (t + (phi / wc if wc != 0.0 else 0.0)) + row[S_ANGLE]
            out[:, int(row[S_ELEMENT])] += np.maximum(drop(ang, row), drop(ang - np.pi, row))
    return out


# --------------------------------------------------------------------------------------------
# NumPy references (tests) and helpers
# --------------------------------------------------------------------------------------------
def _deviations_np(
    st: DynamicSetup, t: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Ball angles, radial gap at q = 0 and ball deviations, shape (n, Z) each (vectorised)."""
    ik, ia, ip, ok, oa, op, bk, ba, bp, boff = st.harmonics
    kin = st.kinematics
    t = np.atleast_1d(np.asarray(t, dtype=np.float64))
    theta = st.theta0[None, :] + (TWO_PI * kin.cage * t + slip_angles_np(st, t))[:, None]

    def hsum(k: NDArray[Any], a: NDArray[Any], p: NDArray[Any], x: NDArray[Any]) -> Any:
        if k.size == 0:
            return np.zeros_like(x)
        return np.sum(a * np.cos(k * x[..., None] + p), axis=-1)

    gap = (
        st.radial_gap
        + hsum(ik, ia, ip, theta - TWO_PI * kin.inner * t[:, None])
        - hsum(ok, oa, op, theta - TWO_PI * kin.outer * t[:, None])
    )
    spin = TWO_PI * kin.contact_rate * t
    wb = np.zeros_like(theta)
    for j in range(st.n_elements):
        lo, hi = int(boff[j]), int(boff[j + 1])
        if hi > lo:
            wb[:, j] = hsum(bk[lo:hi], ba[lo:hi], bp[lo:hi], spin)
    if st.spalls.shape[0]:
        wb = wb - spall_drops_np(st, t)  # a spall takes material off the contact
    return theta, gap, wb


def contact_forces(
    st: DynamicSetup, t: NDArray[np.float64], q: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    r"""Vectorised :math:`\sum_j Q_j n_j` [N] and approaches δ_j [m] at instants t, q (n, 3).

    Returns
    -------
    force : ndarray, shape (n, 3)
    approach : ndarray, shape (n, Z)
    """
    theta, gap, wb = _deviations_np(st, t)
    q = np.atleast_2d(q)
    c, s = np.cos(theta), np.sin(theta)
    g = gap + q[:, :1] * c + q[:, 1:2] * s
    sa = st.axial_offset + (q[:, 2:3] if st.ndof == 3 else 0.0) + np.zeros_like(g)
    a = st.curvature_distance
    sr = a + g
    dist = np.hypot(sr, sa)
    d = (g * (a + sr) + sa * sa) / (dist + a) + wb
    load = st.stiffness * np.clip(d, 0.0, None) ** 1.5
    n = np.stack([sr * c / dist, sr * s / dist, sa / dist], axis=-1)
    force = np.einsum("nz,nzk->nk", load, n)
    if st.ndof == 2:
        force[:, 2] = 0.0
    return force, d


def contact_stiffness(
    st: DynamicSetup, t: float, q: NDArray[np.float64], *, step: float | None = None
) -> NDArray[np.float64]:
    """Tangent stiffness K_t = ∂(Σ Q n)/∂q [N/m] at one instant, by central differences."""
    q = np.asarray(q, dtype=np.float64)
    ndof = st.ndof
    h = step if step is not None else 1e-4 * st.reference_approach
    out = np.zeros((ndof, ndof))
    for i in range(ndof):
        dq = np.zeros(3)
        dq[i] = h
        fp, _ = contact_forces(st, np.array([t]), (q + dq)[None])
        fm, _ = contact_forces(st, np.array([t]), (q - dq)[None])
        out[:, i] = (fp[0, :ndof] - fm[0, :ndof]) / (2.0 * h)
    return out


def external_force(st: DynamicSetup, t: NDArray[np.float64]) -> NDArray[np.float64]:
    """Load + unbalance on the rotor [N], shape (n, 3)."""
    t = np.atleast_1d(np.asarray(t, dtype=np.float64))
    f = np.tile(st.force, (t.size, 1))
    f[:, 0] += st.unbalance_force * np.cos(st.unbalance_omega * t)
    f[:, 1] += st.unbalance_force * np.sin(st.unbalance_omega * t)
    return f


def energy(
    st: DynamicSetup, t: NDArray[np.float64], q: NDArray[np.float64], v: NDArray[np.float64]
) -> NDArray[np.float64]:
    r"""Mechanical energy :math:`\tfrac12 m|v|^2 + \sum_j \tfrac{K_n}{2.5}[\delta_j]_+^{5/2}
    - F\cdot q` [J] (constant load; conserved when c = 0, speed 0 and no unbalance)."""
    _, d = contact_forces(st, t, q)
    pot = (st.stiffness / 2.5 * np.clip(d, 0.0, None) ** 2.5).sum(axis=1)
    nd = st.ndof
    energy: NDArray[np.float64] = (
        0.5 * st.mass * (v[:, :nd] ** 2).sum(1) + pot - (q[:, :nd] * st.force[:nd]).sum(1)
    )
    return energy


def rhs_first_order(st: DynamicSetup) -> Callable[[float, NDArray[np.float64]], Any]:
    """Right-hand side of the first-order form y = (q, v) for :func:`scipy.integrate.solve_ivp`."""
    nd = st.ndof

    def rhs(t: float, y: NDArray[np.float64]) -> NDArray[np.float64]:
        q = np.zeros(3)
        q[:nd] = y[:nd]
        v = y[nd:]
        f, _ = contact_forces(st, np.array([t]), q[None])
        e = external_force(st, np.array([t]))
        acc = (e[0, :nd] - f[0, :nd] - st.damping * v) / st.mass
        return np.concatenate([v, acc])

    return rhs


def newmark_reference(
    st: DynamicSetup,
    h: float,
    n_steps: int,
    state: NDArray[np.float64],
    t_start: float = 0.0,
    max_iter: int = MAX_ITER,
) -> NDArray[np.float64]:
    """The Newmark scheme of :func:`newmark_kernel` in NumPy (vectorised over balls).

    Independent code path for tests: Jacobian by central differences of
    :func:`contact_forces`, matrix solve by :func:`numpy.linalg.solve`.

    Returns
    -------
    ndarray, shape (n_steps, 3)
        q after each step [m].
    """
    nd = st.ndof
    q = state[:nd].copy()
    v = state[3 : 3 + nd].copy()
    a = state[6 : 6 + nd].copy()
    out = np.zeros((n_steps, 3))
    tol = NEWTON_RTOL * st.reference_approach
    eye = np.eye(nd)
    for n in range(n_steps):
        t1 = t_start + (n + 1) * h
        e = external_force(st, np.array([t1]))[0, :nd]
        p = q + h * v + 0.5 * h * h * a
        for _ in range(max_iter):
            pq = np.zeros(3)
            pq[:nd] = p
            f, _ = contact_forces(st, np.array([t1]), pq[None])
            na = 4.0 / h**2 * (p - q) - 4.0 / h * v - a
            nv = v + 0.5 * h * (a + na)
            r = st.mass * na + st.damping * nv + f[0, :nd] - e
            jac = (4.0 * st.mass / h**2 + 2.0 * st.damping / h) * eye + contact_stiffness(
                st, t1, pq
            )
            s = np.linalg.solve(jac, r)
            p = p - s
            if np.max(np.abs(s)) <= tol:
                break
        else:
            raise ConvergenceError("reference Newton did not converge", n, t1)
        na = 4.0 / h**2 * (p - q) - 4.0 / h * v - a
        v = v + 0.5 * h * (a + na)
        a, q = na, p
        out[n, :nd] = q
    return out


def static_reference(
    st: DynamicSetup, times: NDArray[np.float64], max_iter: int = 200
) -> NDArray[np.float64]:
    """Quasi-static solution at all instants at once (NumPy, damped Newton from q = 0).

    Returns
    -------
    ndarray, shape (n, 3)
    """
    nd = st.ndof
    times = np.asarray(times, dtype=np.float64)
    n = times.size
    q = np.zeros((n, 3))
    e = external_force(st, times)
    tol = NEWTON_RTOL * st.reference_approach
    hstep = 1e-4 * st.reference_approach

    def resid(qq: NDArray[np.float64]) -> NDArray[np.float64]:
        return contact_forces(st, times, qq)[0][:, :nd] - e[:, :nd]

    for _ in range(max_iter):
        r = resid(q)
        jac = np.zeros((n, nd, nd))
        for i in range(nd):
            dq = np.zeros(3)
            dq[i] = hstep
            jac[:, :, i] = (resid(q + dq) - resid(q - dq)) / (2 * hstep)
        jac += 1e-9 * st.stiffness * math.sqrt(st.reference_approach) * np.eye(nd)
        s = np.linalg.solve(jac, r[..., None])[..., 0]
        lam = np.ones(n)
        norm0 = np.linalg.norm(r, axis=1)
        for _ls in range(40):
            trial = q.copy()
            trial[:, :nd] -= lam[:, None] * s
            worse = np.linalg.norm(resid(trial), axis=1) > norm0 * (1 - 1e-4 * lam)
            worse &= lam * np.max(np.abs(s), axis=1) > tol
            if not worse.any():
                break
            lam[worse] *= 0.5
        q[:, :nd] -= lam[:, None] * s
        if np.max(lam * np.max(np.abs(s), axis=1)) <= tol:
            return q
    raise ConvergenceError("reference static Newton did not converge")


def static_equilibrium(
    st: DynamicSetup, times: NDArray[np.float64], q_start: NDArray[np.float64] | None = None
) -> NDArray[np.float64]:
    """Quasi-static rotor position (n, 3) [m] of the same contact model at ``times``.

    Raises
    ------
    ConvergenceError
        Naming the instant.
    """
    times = np.ascontiguousarray(np.atleast_1d(times), dtype=np.float64)
    start = np.zeros(3) if q_start is None else np.asarray(q_start, dtype=np.float64)
    q, status, instant = static_kernel(
        times, start, st.params(1.0), st.theta0, st.harmonics, st.ndof, 200
    )
    if status != OK:
        raise ConvergenceError(
            "quasi-static Newton iteration did not converge", int(instant), float(times[instant])
        )
    positions: NDArray[np.float64] = q
    return positions


def linearised_natural_frequencies(
    st: DynamicSetup, q: NDArray[np.float64], t: float = 0.0
) -> NDArray[np.float64]:
    """Undamped natural frequencies sqrt(eig(K_t)/m)/2π [Hz] at rotor position q, time t.

    A direction without stiffness gives 0 Hz: eigenvalues below 1e-9 of the largest (the
    central differences of :func:`contact_stiffness` resolve about 1e-12 of it) are set to 0.
    This happens when a single ball carries the load: it holds the rotor along its own line
    only (seed 003 eq. 2.4: δ_j depends on q through x cos θ_j + y sin θ_j).

    Parameters
    ----------
    st : DynamicSetup
    q : ndarray, shape (3,)
        Rotor centre [m].
    t : float
        Time [s] (ball positions).

    Returns
    -------
    ndarray, shape (ndof,)
        Ascending [Hz].
    """
    k = contact_stiffness(st, t, q)
    lam = np.linalg.eigvalsh(0.5 * (k + k.T))
    lam[lam < 1e-9 * max(float(lam.max()), 0.0)] = 0.0
    frequencies: NDArray[np.float64] = np.sqrt(lam / st.mass) / TWO_PI
    return frequencies
