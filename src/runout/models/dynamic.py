r"""Dynamic model of a rigid rotor on the Hertz contacts of a ball bearing (seed 003).

Purohit & Purohit (2006) treat the shaft and inner ring as a rigid mass m on Z massless,
compression-only Hertz springs with radial clearance, viscous damping c, a constant radial
load W and an unbalance force at shaft speed (seed 003 eq. 2.1–2.5, 2.16), and integrate the
equations of motion with Newmark-β and Newton–Raphson (§3). This module implements that model
on the product's shared descriptions, extends it with an exact contact geometry for an
axially preloaded bearing (eq. 2.21–2.22), an optional axial degree of freedom and the
waviness of both raceways and of the balls, and analyses the steady state like the
quasi-static models.

Reference: R.K. Purohit, K. Purohit, "Dynamic analysis of ball bearings with effect of
preload and number of balls", 2006 (seed 003).

Contact model
-------------
The moving body is the inner ring with the shaft; the outer ring is fixed (seed 003
assumption 2). Its centre is at :math:`q = (x, y, z)` from the outer ring's, z axial (z is
held at 0 unless ``[dynamics] axial_dof = true``). Ball j sits at
:math:`\theta_j(t) = 2\pi f_c t + 2\pi j/Z + \epsilon_j` (eq. 2.18, pitch error ε_j). In the
plane through the bearing axis and ball j, the groove curvature centres are a distance

.. math:: s_j = \sqrt{(A + g_j)^2 + (z_p + z)^2}

apart, with :math:`A = (f_i + f_o - 1)D` (eq. 2.22), the radial gap
:math:`g_j = -P_d/2 + x\cos\theta_j + y\sin\theta_j + W_{ij} - W_{oj}` and :math:`z_p` the
axial offset of the rings under the preload alone. The contact approach and load are

.. math::
    \delta_j = s_j - A + w_{bj}, \qquad Q_j = K_n[\delta_j]_+^{3/2}

(eq. 2.1), acting along the unit normal :math:`n_j = ((A+g_j)\cos\theta_j,
(A+g_j)\sin\theta_j, z_p + z)/s_j`. :math:`W_{ij}, W_{oj}` are the raceway radius deviations
at the ball (inner: material added positive; outer: radius larger positive) and
:math:`w_{bj}` the ball's diameter deviation along its contact line (seed 002 eq. 26), as in
:mod:`runout.models._quasi_static`. Without preload and waviness (:math:`z_p = z = 0`) this
is exactly :math:`\delta_j = x\cos\theta_j + y\sin\theta_j - P_d/2`, seed 003 eq. 2.3–2.4
with γ = P_d/2.

Equations of motion (eq. 2.16, derived)
---------------------------------------

.. math::
    m\ddot q + c\dot q + \sum_j Q_j n_j = F_r e_\beta + F_a e_z
        + F_u (\cos\Omega t, \sin\Omega t, 0),

with the radial load :math:`F_r` along :math:`e_\beta = (\cos\beta, \sin\beta, 0)`
(``Operation.radial_load_direction``, default −y), :math:`F_u = m_u e\,\Omega^2` the unbalance
force at the inner ring's angular speed Ω and :math:`F_a` the axial preload (axial degree of
freedom only). With only x, y the z row is dropped.

Notes
-----
* Extraction errors in seed 003: eq. 2.16 lost the accelerations and velocities ("m k + c k");
  it puts W in the x equation, i.e. the paper's x axis points along the load, while our load
  is along −y by default, so the paper's x is our −y. The contact constant of eq. 2.11–2.15 is
  wrong in the source (see VALIDATION.md); K_n comes from
  :func:`runout.contact.ball_race_contacts` (``contact_law = "exact"``) or from the paper's
  δ* table (``"delta_star_table"``, :func:`runout.contact.stiffness_from_delta_star_table`),
  at the preloaded contact angle.
* Eq. 2.21 is the zero-clearance case of Harris's load-angle relation; we solve the full
  relation with clearance, :math:`F_a = Z K_n (A\cos\alpha^0/\cos\alpha_p - A)^{3/2}
  \sin\alpha_p`, with K_n of the chosen law at α_p (for the exact law this is
  :func:`runout.loading.axial_loading`). Then :math:`z_p = A\cos\alpha^0\tan\alpha_p`.
* Departures from the paper: the contact normal turns with the motion (exact curvature-centre
  geometry instead of a fixed angle); z is optional; waviness of both raceways and of the
  balls, ball size and pitch errors are included; the cage and spin rates use α_p.
* Clearance and contact angle: the bearing enters through ``radial_clearance`` P_d only (the
  diametral play, :math:`P_d = 2A(1 - \cos\alpha^0)`, Harris); α⁰ follows from it. A case's
  ``nominal_contact_angle`` α⁰ is converted into that P_d by the case builder. A fixed
  operating ``contact_angle`` cannot be honoured (α follows from clearance, preload and the
  motion): :func:`setup` refuses it.
* Newmark-β (average acceleration, β = 1/4, γ = 1/2) with a Newton–Raphson iteration on the
  tangent stiffness per step (:func:`newmark_kernel`, compiled; :func:`newmark_reference` is a
  NumPy version for tests). The default step gives :data:`STEPS_PER_PERIOD` steps per period of
  the highest linearised natural frequency and divides the output interval.
* The transient is detected, not assumed (:func:`integrate`): blocks of whole revolutions
  are integrated until the free vibration near the linearised natural frequencies has decayed
  below :data:`SETTLE_TOL` of the response (or has stopped decaying).
"""

from __future__ import annotations

import functools
import hashlib
import json
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

import numpy as np
from numpy.typing import NDArray

from runout.bearing import BallBearing
from runout.contact import (
    ball_race_contacts,
    ball_race_curvature,
    combined_stiffness,
    stiffness_from_delta_star_table,
)
from runout.decompose import Candidate, Direction, fit_lines, split_runout
from runout.display import format_resolution
from runout.errors import ConvergenceError, GeometryError, NumericalError
from runout.imperfections import pack_harmonics
from runout.kinematics import ball_spin_frequency, bearing_frequencies, cage_frequency
from runout.models._dynamic_kernels import (
    BLOWUP,
    FORCE_RTOL,  # noqa: F401 - re-exported with the kernels (docs, tests)
    N_PAR,
    NEWTON_RTOL,
    NOT_CONVERGED,
    NOT_FINITE,
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
    _contact,  # noqa: F401
    _deviations,  # noqa: F401
    newmark_kernel,
    static_kernel,
)
from runout.models._quasi_static import (
    Kinematics,
    decomposition_kinematic,
    predicted_lines,
)
from runout.results import RunResult, Source
from runout.spectrum import amplitude_spectrum, extract_lines

__all__ = [
    "STEPS_PER_PERIOD",
    "DynamicSetup",
    "Integration",
    "contact_forces",
    "contact_stiffness",
    "energy",
    "integrate",
    "linearised_natural_frequencies",
    "newmark_kernel",
    "newmark_reference",
    "preloaded_contact_angle",
    "rhs_first_order",
    "run",
    "setup",
    "static_equilibrium",
    "static_kernel",
    "static_reference",
    "sweep",
]

MODEL = "dynamic"
TWO_PI = 2.0 * math.pi
ContactLaw = Literal["exact", "delta_star_table"]

#: Default number of Newmark steps per period of the highest linearised natural frequency.
STEPS_PER_PERIOD = 200
#: Transient is over when the free vibration is below this fraction of the response p-p.
SETTLE_TOL = 1e-3
#: Lines below this fraction of the reference approach are solver noise (1000 × tolerance).
NOISE = 1e-9
MAX_ITER = 50
#: Most steps a single run may take (transient + analysis) before giving up.
MAX_STEPS = 50_000_000
#: Longest block of the transient search [revolutions of the rotating ring].
MAX_BLOCK_REVOLUTIONS = 200

_CAUSES = {
    NOT_CONVERGED: "Newton-Raphson iteration of the Newmark step did not converge",
    BLOWUP: "the rotor left the bearing (displacement beyond half the groove-centre distance A)",
    NOT_FINITE: "non-finite displacement (numerical blow-up)",
}


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
        for race, f in (("inner", bearing.inner_conformity), ("outer", bearing.outer_conformity)):
            s, fr = ball_race_curvature(
                bearing.element_diameter,
                bearing.pitch_diameter,
                f,
                alpha,
                race,  # type: ignore[arg-type]
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

    def residual(alpha: float) -> float:
        stretch = max(math.cos(free_contact_angle) / math.cos(alpha) - 1.0, 0.0)
        k = _law_stiffness(bearing, alpha, law)
        return z * k * (a * stretch) ** 1.5 * math.sin(alpha) / preload - 1.0

    hi = 0.5 * math.pi * (1.0 - 1e-6)
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
    harmonics: tuple[NDArray[Any], ...]
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
        ring, or an axial degree of freedom with nothing to hold the rotor.
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
    ndof = 3 if dyn.axial_dof else 2
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
    if ndof == 3 and op.axial_load <= 0.0 and op.radial_load <= 0.0:
        raise GeometryError(
            "dynamics.axial_dof",
            "an axial degree of freedom needs an axial or radial load to hold the rotor",
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
    harmonics = (
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
        contact_law=law,
        reference_approach=ref,
        notes=tuple(notes),
    )


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
    theta = st.theta0[None, :] + TWO_PI * kin.cage * t[:, None]

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
    return 0.5 * st.mass * (v[:, :nd] ** 2).sum(1) + pot - (q[:, :nd] * st.force[:nd]).sum(1)


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
    return q


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
    return np.sqrt(lam / st.mass) / TWO_PI


# --------------------------------------------------------------------------------------------
# integration with transient detection
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Integration:
    """Steady-state record of one dynamic run.

    Attributes
    ----------
    time : ndarray, shape (n,)
        Instants of the analysis window [s], ``k / (speed · samples_per_rev)``: t = 0 is the
        first recorded instant, the end of the transient, and the time of the equations of
        motion (ball angles, unbalance phase), which the transient reached from the static
        start at t = -transient.
    displacement : ndarray, shape (3, n)
        x, y and z − (preloaded position) of the rotor [m].
    samples_per_rev : int
        Output samples per revolution of the rotating ring.
    time_step : float
        Newmark step h [s].
    transient : float
        Length of the transient before t = 0, the first recorded instant [s] (a whole number
        of revolutions of the rotating ring).
    settled : str
        How the transient ended: "decayed", "stationary" (free vibration stopped decaying) or
        "limit" (not settled before the step budget).
    natural_frequencies : ndarray
        Linearised natural frequencies at the static equilibrium [Hz].
    static_position : ndarray, shape (3,)
        Static equilibrium at t = 0 (the geometry of the record's start) [m].
    min_loaded : int
        Fewest loaded balls at any step.
    steps : int
        Newmark steps taken.
    iterations : int
        Newton iterations taken.
    """

    time: NDArray[np.float64]
    displacement: NDArray[np.float64]
    samples_per_rev: int
    time_step: float
    transient: float
    settled: str
    natural_frequencies: NDArray[np.float64]
    static_position: NDArray[np.float64]
    min_loaded: int
    steps: int
    iterations: int
    free_vibration: list[float] = field(default_factory=list)


def _raise(status: int, step: int, t: float) -> None:
    cause = _CAUSES.get(status, f"kernel status {status}")
    if status == NOT_CONVERGED:
        raise ConvergenceError(cause, step, t)
    raise NumericalError(cause, step, t)


def _band_amplitude(
    block: NDArray[np.float64], dt: float, f_lo: float, f_hi: float
) -> tuple[float, float]:
    """Largest Hann-spectrum amplitude of x, y (, z) in [f_lo, f_hi], and the block's p-p."""
    spec = amplitude_spectrum(block, sample_rate=1.0 / dt)
    sel = (spec.frequencies >= f_lo) & (spec.frequencies <= f_hi)
    amp = float(spec.amplitude[:, sel].max()) if sel.any() else 0.0
    return amp, float(np.max(np.ptp(block, axis=1)))


def choose_step(
    st: DynamicSetup, f_natural: float, dt_out: float, time_step: float | None
) -> tuple[float, int]:
    """Newmark step h [s] and output stride (h · stride = dt_out).

    Default: at least :data:`STEPS_PER_PERIOD` steps per period of ``f_natural`` (phase
    error of the average-acceleration scheme ≈ (ωh)²/12 ≈ 8e-5 per period) and a whole
    number of steps per output interval. The stride may be astronomically large (a tiny
    step or speed): :func:`plan_integration` checks the work it implies before anything is
    allocated.
    """
    if time_step is not None:
        if not (time_step > 0.0 and math.isfinite(time_step)):
            raise GeometryError("dynamics.time_step", f"must be > 0, got {time_step!r}")
        target = time_step
    else:
        target = 1.0 / (STEPS_PER_PERIOD * max(f_natural, 1e-12))
    stride = max(1, math.ceil(dt_out / target * (1 - 1e-12)))
    return dt_out / stride, stride


def _largest_divisor_at_most(n: int, bound: int) -> int:
    """Largest divisor of ``n`` (>= 1) not above ``bound`` (>= 1), in O(sqrt n) steps."""
    best = 1
    i = 1
    while i * i <= n:
        if n % i == 0:
            for d in (i, n // i):
                if best < d <= bound:
                    best = d
        i += 1
    return best


@dataclass(frozen=True)
class IntegrationPlan:
    """Step, strides and block sizes of one dynamic run, fixed before any array exists.

    Attributes
    ----------
    time_step : float
        Newmark step h [s].
    stride : int
        Steps per output instant.
    steps_per_rev : int
        Steps per revolution of the rotating ring.
    window_steps : int
        Steps of the analysis window (``revolutions`` revolutions).
    rev_block, block_steps : int
        Revolutions and steps of one block of the transient search.
    det_stride : int
        Steps per recorded instant of a transient block (a divisor of ``block_steps``).
    record : int
        Output instants of the analysis window.
    f_lo, f_hi : float
        Lowest positive and highest linearised natural frequency [Hz].
    transient_steps : int
        Most steps the transient search may take (each is integrated twice).
    """

    time_step: float
    stride: int
    steps_per_rev: int
    window_steps: int
    rev_block: int
    block_steps: int
    det_stride: int
    record: int
    f_lo: float
    f_hi: float
    transient_steps: int


def _cost_per_step(st: DynamicSetup) -> float:
    """Estimated seconds of one Newmark step (contacts x harmonics, Newton iterations)."""
    from runout.limits import COST_DYNAMIC_ELEMENT, COST_DYNAMIC_HARMONIC

    z = st.n_elements
    rings = st.harmonics[0].size + st.harmonics[3].size
    balls = st.harmonics[6].size
    return z * COST_DYNAMIC_ELEMENT + (z * rings + balls) * COST_DYNAMIC_HARMONIC


def plan_integration(
    st: DynamicSetup,
    speed: float,
    revolutions: int,
    samples_per_rev: int,
    natural: NDArray[np.float64],
    *,
    time_step: float | None = None,
    max_steps: int = MAX_STEPS,
    limits: Any = None,
) -> IntegrationPlan:
    """Step, strides and transient allowance of a run, refused when beyond the budget.

    The analysis window and one block of the transient search (integrated twice) are the
    least a run does; their time and memory are estimated from the step count and compared
    with ``limits`` (:func:`runout.limits.budget`) before anything is allocated. The steps
    left in the time budget (at most ``max_steps`` in all) bound the transient search.

    Raises
    ------
    runout.limits.LimitError
        Naming the key that makes the run too large (``dynamics.time_step``,
        ``operation.speed``, ``dynamics.mass`` or ``analysis.revolutions``).
    GeometryError
        No contact stiffness at the static position.
    """
    from runout.limits import LimitError, budget, format_bytes, format_seconds

    limits = budget() if limits is None else limits
    f_hi = float(natural.max()) if natural.size else 0.0
    if not (math.isfinite(f_hi) and f_hi > 0.0):
        raise GeometryError(
            "operation.radial_load",
            "the rotor has no contact stiffness at its static position (no ball is loaded): "
            "give a radial load or an axial preload",
        )
    positive = natural[natural > 0.0]
    f_lo = float(positive.min()) if positive.size else f_hi
    if f_lo * MAX_BLOCK_REVOLUTIONS < speed:
        # a transient block is at most 200 revolutions: a free vibration slower than that
        # cannot be seen decaying, and its record would hold less than one sample
        raise GeometryError(
            "dynamics.mass",
            f"the rotor's lowest natural frequency ({f_lo:.3g} Hz, from the mass "
            f"{st.mass:.4g} kg on the contact stiffness) is below 1/{MAX_BLOCK_REVOLUTIONS} of "
            f"the speed ({speed:.4g} Hz): its free vibration outlasts "
            f"{MAX_BLOCK_REVOLUTIONS} revolutions and no steady state can be found",
        )
    dt_out = 1.0 / (speed * samples_per_rev)
    h, stride = choose_step(st, f_hi, dt_out, time_step)
    steps_per_rev = stride * samples_per_rev
    # a block spans >= 20 natural periods and, with damping, >= ln 2 linear decay times 2m/c
    # (the free vibration halves per block at least), but at most 200 revolutions
    decay = math.log(2.0) * 2.0 * st.mass / st.damping if st.damping > 0.0 else math.inf
    rev_block = max(1, math.ceil(20.0 / max(f_lo, 1e-12) * speed))
    rev_block = min(MAX_BLOCK_REVOLUTIONS, max(rev_block, math.ceil(min(decay, 1e9) * speed)))
    window_steps = revolutions * steps_per_rev
    block_steps = rev_block * steps_per_rev
    det_points = block_steps / max(1.0, math.floor(1.0 / (8.0 * f_hi * h)))
    record = revolutions * samples_per_rev
    least = window_steps + 2 * block_steps
    per_step = _cost_per_step(st)
    seconds = least * per_step
    memory = 8.0 * 3 * (8 * record + 6 * det_points) + 16.0 * record * 64
    duration = revolutions / speed
    what = (
        f"{revolutions} revolutions at {speed:.4g} Hz = {duration:.4g} s of motion, and a "
        f"transient block of {rev_block} revolutions, in steps of {h:.3g} s: "
        f"{least:.3g} Newmark steps"
    )
    # the key to change: the one that makes the steps many
    undamped = math.ceil(min(decay, 1e9) * speed) >= rev_block > 1
    if time_step is not None:
        key = "dynamics.time_step"
    elif duration > 60.0:
        key = "operation.speed"
    elif h < 1e-8:
        key = "dynamics.mass"
        what += f" (natural frequency {f_hi:.3g} Hz)"
    elif 2 * block_steps > window_steps and undamped:
        # little or no damping: the transient blocks last as long as the free vibration does
        key = "dynamics.damping"
    else:
        key = "analysis.revolutions"
    if not memory <= limits.memory:
        raise LimitError(
            key,
            f"the dynamic run would need about {format_bytes(memory)} of memory ({what}); "
            f"change {key} {limits.raise_hint('memory')}",
        )
    if not (seconds <= limits.time and least <= max_steps):
        raise LimitError(
            key,
            f"the dynamic run would take about {format_seconds(seconds)} ({what}); change "
            f"{key} {limits.raise_hint('time')}",
        )
    # the transient search is integrated twice: half of what is left of the budget
    left = min(max_steps, int(limits.time / per_step)) - window_steps
    transient_steps = max(block_steps, left // 2)
    fine = max(1, math.floor(1.0 / (8.0 * f_hi * h)))
    det_stride = _largest_divisor_at_most(block_steps, fine)
    return IntegrationPlan(
        time_step=h,
        stride=stride,
        steps_per_rev=steps_per_rev,
        window_steps=window_steps,
        rev_block=rev_block,
        block_steps=block_steps,
        det_stride=det_stride,
        record=record,
        f_lo=f_lo,
        f_hi=f_hi,
        transient_steps=transient_steps,
    )


class _Stepper:
    """Newmark integration state and counters, advanced block by block by :func:`integrate`."""

    def __init__(self, st: DynamicSetup, par: NDArray[np.float64], h: float) -> None:
        self.st, self.par, self.h = st, par, h
        self.state = np.zeros(9)
        self.t = 0.0
        self.steps = self.iterations = 0
        self.min_loaded = st.n_elements

    def start_static(self, t: float, q: NDArray[np.float64]) -> None:
        """Start at rest at ``q`` at time ``t``, acceleration from the equation of motion."""
        st = self.st
        self.t = t
        self.state = np.zeros(9)
        self.state[:3] = q
        f0, _ = contact_forces(st, np.array([t]), q[None])
        self.state[6 : 6 + st.ndof] = (external_force(st, np.array([t]))[0] - f0[0])[
            : st.ndof
        ] / st.mass

    def advance(self, n_steps: int, stride: int, out: NDArray[np.float64]) -> None:
        """``n_steps`` steps, recording every ``stride``-th state into ``out``."""
        st = self.st
        status, bad, it, ml = newmark_kernel(
            n_steps, stride, self.t, self.state, self.par, st.theta0, st.harmonics, st.ndof,
            MAX_ITER, out,
        )  # fmt: skip
        if status != OK:
            _raise(int(status), self.steps + int(bad), self.t + (int(bad) + 1) * self.h)
        self.t += n_steps * self.h
        self.steps += n_steps
        self.iterations += int(it)
        self.min_loaded = min(self.min_loaded, int(ml))


def integrate(
    st: DynamicSetup,
    speed: float,
    revolutions: int,
    samples_per_rev: int,
    *,
    time_step: float | None = None,
    progress: Callable[[float], None] | None = None,
    max_steps: int = MAX_STEPS,
    limits: Any = None,
) -> Integration:
    """Integrate from the static equilibrium, detect the end of the transient, record.

    Blocks of whole revolutions (at least 20 periods of the lowest natural frequency) are
    integrated one after the other. After each block the largest Hann-spectrum amplitude
    within ±15 % of the natural frequencies (the free vibration) is compared with the block's
    p-p: the transient is over when it is below :data:`SETTLE_TOL` of the p-p ("decayed"), or
    when it has stopped decaying ("stationary": the largest amplitude of the last three blocks
    is above half that of the three before, whereas a block lasts at least ln 2 linear decay
    times 2m/c, so a free vibration would have dropped eightfold; a forced line in the band, a
    resonance or an undamped system keeps it, and the analysis then includes it).
    The transient found this way is then integrated again, from the static equilibrium at
    t = -transient, and ``revolutions`` whole revolutions are recorded from t = 0: the returned
    ``time`` starts at 0 where the bearing's geometry (ball angles θ_j(t), ring angles,
    unbalance phase Ωt) is the one every other model has at its t = 0 (the product's time
    origin), and ``transient`` is the length of the transient before it. The transient is
    integrated twice; it is usually short against the record.

    Parameters
    ----------
    st : DynamicSetup
    speed : float
        Rotating ring speed [Hz] (> 0).
    revolutions : int
        Revolutions in the analysis window (>= 1).
    samples_per_rev : int
        Output samples per revolution.
    time_step : float or None
        Newmark step [s]; default automatic (:func:`choose_step`).
    progress : callable or None
        Called with the fraction done (0..1) after each block.
    max_steps : int
        Step budget of the whole run (transient search twice and the window).
    limits : runout.limits.Budget or None
        Memory and time budget (default :func:`runout.limits.budget`); the plan is refused
        before any array is allocated when it exceeds it, and what is left of the time bounds
        the transient search.

    Raises
    ------
    ConvergenceError, NumericalError
        Naming the step and time of the failure.
    runout.limits.LimitError
        A window or a transient block beyond the budget (:func:`plan_integration`).
    """
    q_static = static_equilibrium(st, np.array([0.0]))[0]
    fn = linearised_natural_frequencies(st, q_static)
    plan = plan_integration(
        st,
        speed,
        revolutions,
        samples_per_rev,
        fn,
        time_step=time_step,
        max_steps=max_steps,
        limits=limits,
    )
    f_lo, f_hi = plan.f_lo, plan.f_hi
    dt_out = 1.0 / (speed * samples_per_rev)
    h, stride, steps_per_rev = plan.time_step, plan.stride, plan.steps_per_rev
    par = st.params(h)
    run = _Stepper(st, par, h)
    run.start_static(0.0, q_static)
    history: list[float] = []
    settled = "limit"
    budget = plan.transient_steps
    block_steps = plan.block_steps
    # the transient blocks are recorded finely enough to see the free vibration
    det_stride = plan.det_stride
    dt_det = det_stride * h
    est_blocks = 4
    while run.steps + block_steps <= max(budget, block_steps):
        out = np.zeros((block_steps // det_stride, 3))
        run.advance(block_steps, det_stride, out)
        amp, pp = _band_amplitude(out[:, : st.ndof].T, dt_det, 0.85 * f_lo, 1.15 * f_hi)
        history.append(amp)
        floor = 1e-9 * st.reference_approach
        if amp <= SETTLE_TOL * max(pp, floor) or amp <= floor:
            settled = "decayed"
            break
        # a transient at least halves per block (block sizing above): when the largest of the
        # last three blocks is still above half the largest of the three before, what is left
        # in the band is part of the steady response (a forced line, a resonance, c = 0)
        if len(history) >= 6 and max(history[-3:]) >= 0.5 * max(history[-6:-3]):
            settled = "stationary"
            break
        est_blocks = max(est_blocks, len(history) + 2)
        if progress is not None:
            progress(0.5 * len(history) / est_blocks)
        if run.steps + block_steps > budget:
            break
    transient = run.t
    # One time origin for every model: the bearing's geometry (ball angles, ring angles,
    # unbalance) at the reported t = 0 is the one every other model has at its t = 0. The
    # search above has measured how long the transient lasts; integrate it again from the
    # static equilibrium at t = -transient, so that the record starts at t = 0 exactly.
    if transient > 0.0:
        run.start_static(-transient, static_equilibrium(st, np.array([-transient]))[0])
        for _ in range(len(history)):
            run.advance(block_steps, det_stride, np.zeros((block_steps // det_stride, 3)))
        run.t = 0.0  # exactly, not the rounded sum of the steps
    n_out = revolutions * samples_per_rev
    # the record starts at t = 0: row 0 is the state there, row k the state k output
    # intervals later; the kernel records after each ``stride`` steps, so it fills rows
    # 1..n_out and the last row (the start of the next revolution) is dropped: the window is
    # [0, revolutions / speed)
    out = np.zeros((n_out + 1, 3))
    out[0] = run.state[:3]
    # record in chunks of whole revolutions so that progress can be shown
    chunk_rev = max(1, revolutions // 10)
    done = 0
    while done < revolutions:
        nrev = min(chunk_rev, revolutions - done)
        view = out[1 + done * samples_per_rev : 1 + (done + nrev) * samples_per_rev]
        run.advance(nrev * steps_per_rev, stride, view)
        done += nrev
        if progress is not None:
            progress(0.5 + 0.5 * done / revolutions)
    out = out[:n_out]
    if not np.all(np.isfinite(out)):
        raise NumericalError("non-finite displacement in the analysis window")
    time = np.arange(n_out, dtype=np.float64) * dt_out  # t = 0 after the transient
    return Integration(
        time=time,
        displacement=np.ascontiguousarray(out.T),
        samples_per_rev=samples_per_rev,
        time_step=h,
        transient=transient,
        settled=settled,
        natural_frequencies=fn,
        static_position=q_static,
        min_loaded=run.min_loaded,
        steps=run.steps,
        iterations=run.iterations,
        free_vibration=history,
    )


# --------------------------------------------------------------------------------------------
# lines and result
# --------------------------------------------------------------------------------------------
def ball_passage_frequency(st: DynamicSetup) -> float:
    """Rate at which balls pass the load zone, fixed in space, Z |f_c| [Hz].

    Seed 003 eq. 2.20 writes it for a stationary outer ring, where it is also the rate at which
    balls pass a point of the outer ring; with the outer ring turning the stiffness still varies
    with the balls' positions relative to the (fixed) load.
    """
    return st.n_elements * abs(st.kinematics.cage)


def candidate_lines(
    st: DynamicSetup, imperfections: Any, natural: NDArray[np.float64], loaded: bool = False
) -> list[Candidate]:
    """The lines to fit, each with its source (optional lines are kept only when present).

    Ball passage Z|f_c| and its harmonics (the compliance of the balls under load, seed
    003 eq. 2.20), the unbalance at f_i and its interactions, the linearised natural
    frequencies, and every line of the imperfections (:func:`predicted_lines`, with the
    linearised model's phasors for the shares).
    """
    kin = st.kinematics
    fbp = ball_passage_frequency(st)
    out: list[Candidate] = []

    def add(freq: float, kinds: tuple[Direction, ...], src: Source, optional: bool) -> None:
        if freq > 0.0:
            out.extend(Candidate(freq, d, src, optional=optional) for d in kinds)

    both: tuple[Direction, ...] = ("radial", "axial")
    for n in range(1, 7):
        # the same source predicted_lines gives a loaded bearing (one line, one source)
        add(n * fbp, both, Source("load", None, None, f"ball passage {n}x", f"{n} Z f_c"), n > 3)
    add(0.5 * fbp, ("radial",), Source("load", None, None, "ball passage 1/2", "Z f_c / 2"), True)
    if st.unbalance_force > 0.0:
        fr = abs(kin.inner)
        add(fr, ("radial",), Source("unbalance", None, None, "f_i", "f_i"), False)
        for n in range(2, 4):
            src = Source("unbalance", None, None, f"{n}x: {n} f_i", f"{n} f_i")
            add(n * fr, ("radial",), src, True)
        for n in range(1, 3):
            for sgn in (1, -1):
                formula = f"{n} Z f_c {'+' if sgn > 0 else '-'} f_i"
                src = Source("unbalance", None, None, "x ball passage", formula)
                add(abs(n * fbp + sgn * fr), ("radial",), src, True)
    for i, f in enumerate(sorted(natural), start=1):
        src = Source("natural", None, None, f"mode {i} (linearised)", f"{f:.5g} Hz")
        add(float(f), both, src, True)
    out += predicted_lines(
        imperfections,
        kin,
        axial=st.ndof == 3,
        loaded=loaded,
        contact_angle=st.contact_angle if st.contact_angle > 0.0 else None,
    )
    return out


def _measuring_direction(op: Any) -> NDArray[np.float64]:
    if op.radial_load > 0.0:
        return np.array([math.cos(op.radial_load_direction), math.sin(op.radial_load_direction)])
    return np.array([1.0, 0.0])


def _analysis_grid(case: Any) -> tuple[int, int, list[str]]:
    an = case.analysis
    notes = []
    revs = max(2, math.floor(an.revolutions + 1e-9))
    if revs != an.revolutions:
        notes.append(f"analysis window rounded to {revs} whole revolutions (RRO/NRRO split)")
    spr = max(16, math.ceil(an.samples / revs))
    if spr * revs != an.samples:
        notes.append(
            f"{spr * revs} instants recorded ({spr} per revolution, whole revolutions; "
            f"analysis.samples = {an.samples})"
        )
    return revs, spr, notes


def run(case: Any, progress: Callable[[float], None] | None = None) -> RunResult:
    """Run the dynamic model (seed 003) on a case.

    Parameters
    ----------
    case : Case
        With ``[analysis] model = "dynamic"`` and a ``[dynamics]`` table.
    progress : callable or None
        Called with the fraction done (0..1).

    Returns
    -------
    RunResult
        Steady-state history of the rotor centre (inner ring relative to the outer ring),
        labelled lines, runout figures; extras ``natural_frequencies_hz`` and the
        integration facts, among them ``transient_s``, the length of the transient [s].
        ``time`` starts at 0 at the first reported instant, where the ball angles and the
        unbalance phase are those of every model's t = 0 (the transient ran from
        t = -``transient_s``); line phases (x = pp/2 cos(2π f t + φ)) are relative to it.
        z is counted from the rings axially centred.
    """
    st = setup(case)
    op = case.operation
    dyn = _dyn(case)
    revs, spr, notes = _analysis_grid(case)
    from runout.limits import case_budget

    integ = integrate(
        st, op.speed, revs, spr, time_step=dyn.time_step, progress=progress,
        limits=case_budget(case),
    )  # fmt: skip
    disp = integ.displacement
    u = _measuring_direction(op)
    lines = candidate_lines(
        st, case.imperfections, integ.natural_frequencies, loaded=op.radial_load > 0.0
    )
    noise = NOISE * st.reference_approach
    directions = ("x", "y", "z") if st.ndof == 3 else ("x", "y")
    basis = decomposition_kinematic(
        st.kinematics, case.imperfections, unbalance=st.unbalance_force > 0.0
    )
    fit = fit_lines(
        integ.time, disp, lines, op.speed, directions=directions, kinematic=basis, floor=noise
    )
    comps = fit.components
    split = split_runout(
        integ.time, disp, u, comps, op.speed, fit.residual, synchronous=basis.synchronous_sources
    )
    notes = list(st.notes) + notes + list(fit.notes) + list(split.notes)
    fn = integ.natural_frequencies
    notes.append(
        f"rotor = inner ring + shaft, displacement relative to the outer ring; transient "
        f"detected over {integ.transient * 1e3:.4g} ms ({integ.settled}; t = 0 is its end, "
        "the start of the record); Newmark step "
        f"{integ.time_step * 1e6:.4g} us = {1.0 / (integ.time_step * fn.max()):.0f} steps per "
        "period of the highest natural frequency"
    )
    if np.any(fn == 0.0):
        notes.append(
            "at the static start of the integration the rotor has no stiffness across the load "
            "(a single loaded ball: linearised natural frequency 0 Hz); of the static positions "
            "along that direction it starts from the symmetric one"
        )
    if integ.settled == "stationary":
        notes.append(
            "the free vibration near the natural frequency did not decay (no or little "
            "damping, or a resonance): it is part of the reported response"
        )
    elif integ.settled == "limit":
        notes.append("no steady state detected within the step budget; the record may be biased")
    if not comps:
        notes.append(
            f"no line above the solver's resolution ({format_resolution(noise)} p-p): the "
            "response is steady to within it"
        )
    if integ.min_loaded < st.n_elements:
        notes.append(
            f"balls lost contact: as few as {integ.min_loaded} of {st.n_elements} loaded "
            "(clearance / load zone)"
        )
    bearing = case.bearing
    mean = disp.mean(axis=1)
    fbp = ball_passage_frequency(st)
    extras: dict[str, Any] = {
        "natural_frequencies_hz": [float(f) for f in sorted(fn)],
        "ball_passage_hz": fbp,
        "time_step_s": integ.time_step,
        "transient_s": integ.transient,
        "transient_end": integ.settled,
        "static_displacement_m": [float(v) for v in integ.static_position[: st.ndof]],
        "contact_law": st.contact_law,
        "contact_stiffness_n_per_m1_5": st.stiffness,
        "preload_contact_angle_deg": math.degrees(st.contact_angle),
        "axial_dof": st.ndof == 3,
        "min_loaded_balls": integ.min_loaded,
        "solver_resolution_m": noise,
        "explained_fraction": fit.explained_fraction,
    }
    if st.ndof == 3:
        extras["mean_axial_displacement_m"] = float(mean[2])  # from the preloaded position
    # The product's axial reference is the rings axially centred: the contacts see the
    # preloaded offset z_p plus the axial degree of freedom (held at 0 without it).
    disp = disp.copy()
    disp[2] += st.axial_offset

    def write_extra(directory: Path) -> list[Path]:
        from runout import plotting

        spectrum_csv = directory / "spectrum.csv"
        spec = amplitude_spectrum(disp, sample_rate=spr * op.speed)
        rows = np.column_stack([spec.frequencies, 2.0 * spec.amplitude.T])
        header = "frequency_hz,x_pp_m,y_pp_m,z_pp_m"
        np.savetxt(spectrum_csv, rows, delimiter=",", header=header, comments="", fmt="%.10g")
        return [spectrum_csv, *plotting.plot_dynamic_figures(result, directory)]

    result = RunResult(
        model=MODEL,
        title=case.title,
        frequencies=bearing_frequencies(bearing, op, st.contact_angle),
        contact_angle=st.contact_angle,
        time=integ.time,
        displacement=disp,
        components=comps,
        runout=split.runout,
        measuring_direction=u,
        extras=extras,
        notes=tuple(notes),
        writers=(write_extra,),
    )
    return result


# --------------------------------------------------------------------------------------------
# sweeps (seed 003 Figs. 3-4)
# --------------------------------------------------------------------------------------------
def _variant(case: Any, elements: int | None, preload: float | None) -> Any:
    """The case with another number of balls and/or axial preload."""
    from runout.case import parse_case

    data = case.spec.model_dump(mode="python", exclude_none=True)
    if elements is not None:
        data["bearing"]["elements"] = int(elements)
    if preload is not None:
        data.setdefault("operation", {})["axial_load"] = float(preload)
    data["analysis"]["model"] = MODEL
    base = Path(case.path).parent if case.path and not case.path.startswith("<") else None
    return parse_case(data, f"{case.path} (elements={elements}, preload={preload} N)", base)


def _case_digest(case: Any) -> str:
    text = json.dumps(case.spec.model_dump(mode="json"), sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


@dataclass(frozen=True)
class SweepPoint:
    """One point of a sweep: inputs and the figures of its steady state."""

    elements: int
    preload_n: float
    contact_angle_deg: float
    ball_passage_hz: float
    natural_frequencies_hz: list[float]
    radial_pp_m: float
    ball_passage_pp_m: float
    mean_displacement_m: list[float]
    spectrum_hz: list[float]
    spectrum_pp_m: list[float]
    lines: list[dict[str, Any]]

    def to_json(self) -> dict[str, Any]:
        """Plain JSON."""
        return dict(self.__dict__)


def _point(case: Any, result: RunResult) -> SweepPoint:
    u = result.measuring_direction
    radial = u[0] * result.displacement[0] + u[1] * result.displacement[1]
    fs = 1.0 / (result.time[1] - result.time[0])
    spec = amplitude_spectrum(radial, sample_rate=fs)
    fbp = float(result.extras["ball_passage_hz"])
    radial_bp = float(extract_lines(result.time, radial, [fbp]).amplitude[0]) * 2.0
    if radial_bp <= float(result.extras["solver_resolution_m"]):
        radial_bp = 0.0
    keep = spec.frequencies <= 8.0 * fbp
    return SweepPoint(
        elements=case.bearing.elements,
        preload_n=case.operation.axial_load,
        contact_angle_deg=math.degrees(result.contact_angle),
        ball_passage_hz=fbp,
        natural_frequencies_hz=list(result.extras["natural_frequencies_hz"]),
        radial_pp_m=result.runout.radial_pp_m,
        ball_passage_pp_m=radial_bp,
        mean_displacement_m=result.mean_displacement()[:2],
        spectrum_hz=[float(f) for f in spec.frequencies[keep]],
        spectrum_pp_m=[float(2.0 * a) for a in spec.amplitude[keep]],
        lines=[c.to_json() for c in result.lines(top=12) if c.direction in ("x", "y")],
    )


def exact_number(value: float) -> str:
    """Shortest text of ``value`` that reads back as exactly ``value``.

    ``f"{value:g}"`` when it round-trips (``10``, ``0.5``: the names of earlier versions stay
    valid), ``repr`` otherwise (``10.0000001``). Two different values therefore never share a
    text: a point name made of 6 significant digits let two close preloads share one result.
    """
    value = float(value) + 0.0  # -0.0 and 0.0 are one preload
    short = f"{value:g}"
    return short if float(short) == value else repr(value)


def point_name(elements: int, preload: float) -> str:
    """Name of a sweep point (and of its file in ``points/``): ``Z<z>_P<preload>N``, exact."""
    return f"Z{int(elements)}_P{exact_number(preload)}N"


_POINT_FIELDS = frozenset(SweepPoint.__dataclass_fields__)


def _saved_point(doc: Any, elements: int, preload: float, digest: str) -> SweepPoint | str:
    """The point stored in ``doc`` if it is this case's point (elements, preload); else why not.

    Checked field by field: a damaged or hand-edited file must be recomputed, not raise
    AttributeError / TypeError here or in the plots, and a file of another point (renamed,
    or named by an older version) must not stand in for this one.
    """
    if not isinstance(doc, dict):
        return f"a JSON {type(doc).__name__}, not an object"
    if doc.get("case_digest") != digest:
        return "written for another case"
    if set(doc) != _POINT_FIELDS | {"case_digest"}:
        return "fields missing or unknown"
    if doc["elements"] != elements or doc["preload_n"] != preload:
        return f"the point Z{doc['elements']!r} P{doc['preload_n']!r} N"

    def number(v: Any) -> bool:
        return isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(v)

    scalars = ("contact_angle_deg", "ball_passage_hz", "radial_pp_m", "ball_passage_pp_m")
    arrays = ("natural_frequencies_hz", "mean_displacement_m", "spectrum_hz", "spectrum_pp_m")
    if not all(number(doc[k]) for k in scalars) or not all(
        isinstance(doc[k], list) and all(number(v) for v in doc[k]) for k in arrays
    ):
        return "a figure is not a number"
    if len(doc["mean_displacement_m"]) != 2 or len(doc["spectrum_hz"]) != len(doc["spectrum_pp_m"]):
        return "arrays of the wrong length"
    if not isinstance(doc["lines"], list) or not all(isinstance(x, dict) for x in doc["lines"]):
        return "lines is not a list of objects"
    return SweepPoint(**{k: v for k, v in doc.items() if k != "case_digest"})


def sweep(
    case: Any,
    elements: Sequence[int] = (),
    preloads: Sequence[float] = (),
    out: Path | str | None = None,
    *,
    progress: Callable[[int, int, str], None] | None = None,
    force: bool = False,
    notify: Callable[[str], None] | None = None,
) -> list[SweepPoint]:
    """Run the dynamic model over numbers of balls × axial preloads (seed 003 Figs. 3–4).

    Every point is the case with ``[bearing] elements`` and ``[operation] axial_load``
    replaced. With ``out``, each finished point is written at once (atomically) to
    ``out/points/<point_name>.json`` (with a digest of the case), and a rerun reuses the
    points already there for the same case: an interrupted sweep loses nothing. A saved point
    that is damaged, of another case or of another point is recomputed, and said through
    ``notify``. The panels (``spectra_elements_P<p>N.png``, ``spectra_preload_Z<z>.png``),
    ``trend.png`` and ``sweep.csv`` are written at the end. ``out`` is locked for the whole
    sweep (:func:`runout.study.output_lock`) and must be new, empty or a sweep's output.

    Parameters
    ----------
    case : Case
    elements : sequence of int
        Numbers of balls; empty = the case's.
    preloads : sequence of float
        Axial preloads [N]; empty = the case's.
    out : Path, str or None
        Output directory (an empty string is refused, not taken as the current directory).
    progress : callable or None
        Called as ``progress(done, total, text)`` after each point.
    force : bool
        Write into a non-empty ``out`` that is not a sweep-dynamic output.
    notify : callable or None
        Called with one-line notes (points recomputed); default: a logged warning.

    Returns
    -------
    list of SweepPoint
        In the order elements-major.

    Raises
    ------
    runout.study.OutputError
        ``out`` empty, a file, unwritable, not a sweep's output, or locked by another writer.
    runout.study.StudyError
        A point failed with an exception that is not a runout error (the points finished
        before it are kept).
    """
    zs = list(elements) or [case.bearing.elements]
    ps = list(preloads) or [case.operation.axial_load]
    for p in ps:
        if not (math.isfinite(p) and p >= 0.0):
            raise GeometryError("preload", f"must be >= 0 N, got {p!r}")
    if out is None:
        return _sweep_points(case, zs, ps, None, progress, notify)
    from runout.study import output_directory, output_lock, refuse_foreign

    directory = output_directory(out)
    refuse_foreign(directory, "sweep-dynamic", force)
    with output_lock(directory):
        return _sweep_points(case, zs, ps, directory, progress, notify)


def _sweep_points(
    case: Any,
    zs: list[int],
    ps: list[float],
    out: Path | None,
    progress: Callable[[int, int, str], None] | None,
    notify: Callable[[str], None] | None,
) -> list[SweepPoint]:
    """The points of :func:`sweep`; ``out`` is checked and locked by the caller."""
    import functools

    from runout.errors import RunoutError
    from runout.study import (
        OutputError,
        StudyError,
        _dumps,
        _remove_leftovers,
        error_text,
        write_atomic,
    )

    digest = _case_digest(case)
    points: list[SweepPoint] = []
    total = len(zs) * len(ps)
    redone: list[str] = []
    if out is not None:
        _remove_leftovers(out)
        try:
            (out / "points").mkdir(exist_ok=True)
        except OSError as exc:
            raise OutputError(f"{out / 'points'}: cannot create ({exc.strerror or exc})") from None
    for z in zs:
        for p in ps:
            p = float(p) + 0.0
            name = point_name(z, p)
            path = out / "points" / f"{name}.json" if out is not None else None
            point = None
            if path is not None and path.exists():
                try:
                    found = _saved_point(json.loads(path.read_text()), z, p, digest)
                except (OSError, ValueError):
                    found = "unreadable"
                if isinstance(found, SweepPoint):
                    point = found
                else:
                    redone.append(f"{path.name}: {found}")
            if point is None:
                variant = _variant(case, z, p)
                try:
                    point = _point(variant, run(variant))
                except RunoutError:
                    raise  # names the case and the point already
                except Exception as exc:
                    raise StudyError(
                        f"{variant.path}: {error_text(exc)} (the points finished before it "
                        "are kept)"
                    ) from None
                if path is not None:
                    text = _dumps({**point.to_json(), "case_digest": digest})
                    write_atomic(path, functools.partial(_write_str, text))
            points.append(point)
            if progress is not None:
                progress(len(points), total, name)
    if redone:
        n = len(redone)
        shown = "; ".join(redone[:3]) + ("; ..." if n > 3 else "")
        message = (
            f"{out / 'points' if out is not None else 'points'}: recomputed {n} point"
            f"{'s' if n > 1 else ''} that could not be reused ({shown})"
        )
        if notify is not None:
            notify(message)
        else:
            import logging

            logging.getLogger(__name__).warning(message)
    if out is not None:
        try:
            _write_sweep(points, zs, ps, out, case.title)
        except OSError as exc:  # a plot: the CSV names its own file
            raise OutputError(f"{out}: cannot write ({exc.strerror or exc})") from None
    return points


def _write_str(text: str, fh: Any) -> None:
    fh.write(text)


def _write_sweep(
    points: list[SweepPoint], zs: list[int], ps: list[float], out: Path, title: str
) -> list[Path]:
    from runout import plotting
    from runout.study import write_atomic

    rows = [
        "elements,preload_n,contact_angle_deg,ball_passage_hz,natural_frequency_1_hz,"
        "natural_frequency_2_hz,radial_pp_m,ball_passage_pp_m,mean_x_m,mean_y_m\n"
    ]
    for pt in points:
        fn = [*pt.natural_frequencies_hz, 0.0, 0.0]
        # the preload exactly: two close preloads are two rows, not one value twice
        rows.append(
            f"{pt.elements},{exact_number(pt.preload_n)},{pt.contact_angle_deg:.6g},"
            f"{pt.ball_passage_hz:.8g},{fn[0]:.8g},{fn[1]:.8g},{pt.radial_pp_m:.6g},"
            f"{pt.ball_passage_pp_m:.6g},{pt.mean_displacement_m[0]:.6g},"
            f"{pt.mean_displacement_m[1]:.6g}\n"
        )
    written = [write_atomic(out / "sweep.csv", lambda fh: fh.writelines(rows))]
    written += plotting.plot_dynamic_sweep(points, zs, ps, out, title)
    return written
