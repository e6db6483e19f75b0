r"""Jones–Harris quasi-static equilibrium of a ball bearing at speed (seed 001 §2.1, Harris).

Every ball is held between its two raceways by the contact loads :math:`Q_{ij}, Q_{oj}`, the
centrifugal force :math:`F_{cj}` and the friction that resists its gyroscopic moment
:math:`M_{gj}`; the inner ring (five degrees of freedom: axial :math:`\delta_a`, radial
:math:`\delta_x, \delta_y`, tilts :math:`\theta_x, \theta_y`) is held by the balls against the
external axial load, radial load and moment. The outer ring is the reference (fixed).

Geometry (seed 001 eq. 5-6, Harris's notation). With the distance between the groove
curvature centres :math:`A = (f_i + f_o - 1)D`, the free contact angle :math:`\alpha^0` and the
radius of the locus of inner groove curvature centres
:math:`\Re_i = d_m/2 + (f_i - 0.5)D\cos\alpha^0`, ball j at azimuth :math:`\psi_j` sees the inner
groove centre at (axial, radial), relative to the outer groove centre,

.. math::
    A_{1j} = A\sin\alpha^0 + \delta_a + \Re_i(\theta_x\sin\psi_j - \theta_y\cos\psi_j),\qquad
    A_{2j} = A\cos\alpha^0 + \delta_x\cos\psi_j + \delta_y\sin\psi_j .

The ball centre is at :math:`(X_{1j}, X_{2j})` from the outer groove centre; eq. 5-6 give the
approaches explicitly,

.. math::
    \delta_{oj} = \sqrt{X_{1j}^2 + X_{2j}^2} - (f_o - 0.5)D,\qquad
    \delta_{ij} = \sqrt{(A_{1j} - X_{1j})^2 + (A_{2j} - X_{2j})^2} - (f_i - 0.5)D,

and the contact angles are the directions of those two segments
(:math:`\tan\alpha_{oj} = X_{1j}/X_{2j}`,
:math:`\tan\alpha_{ij} = (A_{1j}-X_{1j})/(A_{2j}-X_{2j})`).

Ball equilibrium (seed 001 eq. 3-4, with Harris's sign in the radial equation, see Notes):

.. math::
    Q_{ij}\sin\alpha_{ij} - Q_{oj}\sin\alpha_{oj}
      - \frac{M_{gj}}{D}(\lambda_{ij}\cos\alpha_{ij} - \lambda_{oj}\cos\alpha_{oj}) = 0,

    Q_{ij}\cos\alpha_{ij} - Q_{oj}\cos\alpha_{oj}
      + \frac{M_{gj}}{D}(\lambda_{ij}\sin\alpha_{ij} - \lambda_{oj}\sin\alpha_{oj})
      + F_{cj} = 0,

with :math:`Q = K\delta^{3/2}` (Hertz; :math:`K_i, K_o` evaluated at each contact's own angle),
:math:`F_c = \tfrac12 m d_m\omega_m^2`, :math:`M_g = J\omega_R\omega_m\sin\beta`
(:math:`m = \rho\pi D^3/6`, :math:`J = mD^2/10`) and the ball orbit and spin speeds
:math:`\omega_m, \omega_R` and spin-axis attitude β of Harris's raceway-control theory at the
current contact angles (:func:`ball_speeds`). Outer-raceway control: λ_o = 2, λ_i = 0; inner:
λ_i = 2, λ_o = 0 (seed 001 text after eq. 4).

Ring equilibrium (seed 001 eq. 1-2), with the inner-race force on ball j split into
:math:`P_{aj} = Q_{ij}\sin\alpha_{ij} - \lambda_{ij}(M_{gj}/D)\cos\alpha_{ij}` (axial) and
:math:`P_{rj} = Q_{ij}\cos\alpha_{ij} + \lambda_{ij}(M_{gj}/D)\sin\alpha_{ij}` (radial), and the
moment arm :math:`P_{mj} = P_{aj}\Re_i + \lambda_{ij} f_i M_{gj}`:

.. math::
    \sum_j P_{aj} = F_a,\quad \sum_j P_{rj}(\cos\psi_j, \sin\psi_j) = (F_x, F_y),\quad
    \sum_j P_{mj}(\sin\psi_j, -\cos\psi_j) = (M_x, M_y).

Tilt held (``[analysis] ring_tilt = "held"``). The ring's two moment equations are replaced by
:math:`\theta_x = \theta_y = 0`: the ring Newton solves the three force equations for
:math:`(\delta_a, \delta_x, \delta_y)` and the balls' moment at the solution,
:math:`\sum_j P_{mj}(\sin\psi_j, -\cos\psi_j)`, is the reaction of the restraint that holds the
ring untilted (the moment load that would hold a free ring there). This is the problem the
three-degree-of-freedom models (``quasi_static_3d``, ``dynamic``) solve; the stiffness matrix is
still the full 5×5 at that solution.

Solution (seed 001 Fig. 2: ring Newton outside, ball Newton inside). For given ring
displacements each ball's two equations are solved for :math:`(X_{1j}, X_{2j})` by a 2×2 Newton
iteration (eq. 5-6 are eliminated exactly, so the four per-ball unknowns of the paper reduce to
two); the ring's five equations are solved by Newton's method whose Jacobian is obtained by
implicit differentiation of the converged ball states
(:math:`dP/du = \partial P/\partial u - \partial P/\partial X\,(\partial g/\partial X)^{-1}
\partial g/\partial u`, partial derivatives by forward-mode differentiation written out
by the chain rule in the kernel, exact to round-off). That Jacobian at the solution *is* the
bearing stiffness matrix. The ball solve and the ring force with its Jacobian are one compiled
kernel
(:mod:`runout.models._equilibrium_kernels`); the ring Newton, which needs a handful of them,
stays here. The speed effects are switched on after the static solution has converged
(Newton–Raphson from the low-speed solution). The Hertz constants depend on the contact angles;
they are linearised about the current angles inside the Newton iterations and re-centred until
the angles stop moving, so their angle dependence is part of the stiffness matrix too. The
Newton starts from Harris's pure-axial load-angle relation with the Hertz constants of the free
contact angle (:func:`_axial_start`); the re-centring takes it to the constants of the loaded
angles.

Notes
-----
* Seed 001 eq. 4 prints :math:`-\frac{M_{gj}}{d}(\lambda_{ij}\sin\alpha_{ij} -
  \lambda_{oj}\sin\alpha_{oj})`; a friction force perpendicular to the contact line has
  components :math:`(\mp\sin, \pm\cos)`, so the sine term must carry the opposite sign of the
  cosine term of eq. 3. We use Harris's ``+``. The paper also prints :math:`d` (its ball
  diameter) in eq. 5-6 where a length :math:`(f - 0.5)D` is meant.
* Seed 001 gives λ_ij = λ_oj = 0 for inner-raceway control; that removes the gyroscopic moment
  altogether. It is available as ``race_control = "none"``; ``"inner"`` is Harris's λ_i = 2.
* At rest, a ball whose inner groove centre is no farther than A from the outer one (a gap)
  carries no load. At speed, a ball carries inner-race load unless it has lifted off: with
  Q_i = 0 the outer contact alone balances F_c and the gyroscopic friction, which puts the
  ball centre at X* (near the outer groove bottom); the ball is unloaded only if the inner
  groove does not overlap it there (δ_i(X*) ≤ 0). This is the limit Q_i → 0 of the loaded
  equations, so the switch is continuous. A ball with a small gap along the line of groove
  centres is therefore still loaded at speed: its centrifugal force wedges it between the
  outer groove and the flank of the inner groove. An unloaded ball is reported on the outer
  groove bottom (Q_o = F_c, α = 0) and exerts nothing on the inner ring.
* The ball speeds follow the rolling (no-slip) kinematics at the current angles; a signed speed
  reverses ω_m and with it the centrifugal force's square is unchanged, while the gyroscopic
  moment changes sign with the relative ring speed (outer ring rotating).
* A pure moment (no axial, no radial force) is held by the balls either side of the moment
  axis pressing on opposite flanks of the grooves: contact angles of both signs. The Hertz
  constants depend on α through cos α only (Harris's curvature sums, γ = D cos α/d_m), so
  they are evaluated at |α|. The Newton start is the tilt about the moment vector that carries
  M with the ring centred in the axial play (:func:`_moment_start`); nothing is added to the
  loads.
* Tilt radius and moment arm are Harris's ℜ_i by default: a ball's contact force acts along
  the line through the groove curvature centres, and the inner one lies at ℜ_i. ISO/TS
  16281:2008 moves the groove centres by ℜ_i θ in its rolling-element displacement (eq. 12 of
  the open implementation github.com/minzhun/ISO16281, its ``R_i``) but writes the moment
  equilibrium with the pitch radius, :math:`M = \tfrac12 D_{pw}\sum_j Q_j\sin\alpha_j
  \cos\psi_j` (its eq. 18); ``[analysis] moment_arm = "pitch_radius"`` takes that arm. A
  given moment then loads the balls by about ℜ_i/(d_m/2) more (1.06 % on the reference
  suite's bearing, 2.4 % in its pure-moment life).

References
----------
Kim, Choi & Yoon (seed 001), §2.1, eq. 1-9 and Fig. 2. T. A. Harris, *Rolling Bearing
Analysis* (Jones's raceway-control theory, quasi-static equilibrium of high-speed ball
bearings). ISO/TS 16281:2008, reference cases of an open implementation
(github.com/minzhun/ISO16281, ``Test_BallBearing.py``); its reference rating life from the
ball loads is :func:`rating_life` (:mod:`runout.geometry.life`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from runout.analysis.lines import Runout
from runout.analysis.result_details import (
    BearingDamping,
    EquilibriumDetails,
    RadialStiffness,
    RingDisplacement,
    StiffnessMatrix,
)
from runout.analysis.results import RunResult
from runout.base.errors import ConvergenceError, GeometryError, NumericalError
from runout.geometry.bearing import BallBearing, Operation
from runout.geometry.bearing_damping import (
    KRAEMER_RANGE_S,
    damping_coefficient,
    proportional_damping,
)
from runout.geometry.contact import ball_race_curvature, combined_stiffness, hertz_point_stiffness
from runout.geometry.kinematics import bearing_frequencies
from runout.geometry.life import (
    MAX_RADIAL_CONTACT_ANGLE,
    RatingLife,
    modified_reference_life,
    rated_viscosity,
    reference_rating_life,
)

if TYPE_CHECKING:
    from runout.case.model import Case

#: ``[analysis] moment_arm``: the arm of the balls' axial forces in the moment equations,
#: Harris's ℜ_i (default) or ISO/TS 16281's pitch radius d_m/2.
MOMENT_ARMS = ("curvature_centres", "pitch_radius")

__all__ = [
    "DOF_NAMES",
    "MOMENT_ARMS",
    "RING_TILTS",
    "EquilibriumResult",
    "EquilibriumSolution",
    "LifeModification",
    "ball_loads_life",
    "ball_speeds",
    "bearing_damping",
    "radial_stiffness",
    "rating_life",
    "run",
    "solve_equilibrium",
]

MODEL = "equilibrium"
TWO_PI = 2.0 * math.pi
#: Order of the ring degrees of freedom in displacements and stiffness matrices.
DOF_NAMES = ("axial", "x", "y", "tilt_x", "tilt_y")
#: Values of ``[analysis] ring_tilt``: the inner ring's tilts solved, or held at 0.
RING_TILTS = ("free", "held")
#: The degrees of freedom (indices into :data:`DOF_NAMES`) the ring Newton solves.
_SOLVED = {"free": np.arange(5), "held": np.arange(3)}
_LAMBDA = {"outer": (0.0, 2.0), "inner": (2.0, 0.0), "none": (0.0, 0.0)}
_RING_ITER = 80
_ANGLE_LOOPS = 12
_H_ALPHA = 1e-6  # step of the central difference of K(α) [rad]


# --------------------------------------------------------------------------------------------
# ball speeds (Harris, raceway control)
# --------------------------------------------------------------------------------------------
def ball_speeds(
    cos_i: Any,
    sin_i: Any,
    cos_o: Any,
    sin_o: Any,
    gamma: float,
    inner: float,
    outer: float,
    control: str,
) -> tuple[Any, Any, Any, Any]:
    r"""Orbit speed, spin speed and spin-axis attitude of a ball (Harris, raceway control).

    With γ' = D/d_m, the relative ring speed ω = ω_i − ω_o and the spin-axis attitude β
    (:math:`\tan\beta = \sin\alpha_o/(\cos\alpha_o + \gamma')` for outer-raceway control,
    :math:`\sin\alpha_i/(\cos\alpha_i - \gamma')` for inner-raceway control),

    .. math::
        \frac{\omega_m - \omega_o}{\omega} =
          \frac{(1-\gamma'\cos\alpha_i)c_o}
               {(1-\gamma'\cos\alpha_i)c_o + (1+\gamma'\cos\alpha_o)c_i},
        \quad
        \frac{\omega_R}{\omega} = \Big[\Big(\frac{c_o}{1+\gamma'\cos\alpha_o}
          + \frac{c_i}{1-\gamma'\cos\alpha_i}\Big)\gamma'\cos\beta\Big]^{-1},

    :math:`c = \cos\alpha + \tan\beta\sin\alpha`. With α_i = α_o = β = α these reduce to the
    cage speed of seed 001 eq. 7 and the spin of eq. 9. Works on complex arrays (used for
    complex-step derivatives).

    Parameters
    ----------
    cos_i, sin_i, cos_o, sin_o : array_like
        Cosine and sine of the inner and outer contact angles.
    gamma : float
        D / d_m [-].
    inner, outer : float
        Ring speeds [rad/s].
    control : {"outer", "inner", "none"}
        Controlling raceway ("none" uses the outer-control attitude).

    Returns
    -------
    omega_m : array
        Orbit (cage) speed of the ball [rad/s].
    omega_r : array
        Spin speed about its own axis, relative to the cage, signed with ω [rad/s].
    sin_beta, cos_beta : array
        Spin-axis attitude.
    """
    if control == "inner":
        tb = sin_i / (cos_i - gamma)
    else:
        tb = sin_o / (cos_o + gamma)
    cb = 1.0 / np.sqrt(1.0 + tb * tb)
    sb = tb * cb
    ci = cos_i + tb * sin_i
    co = cos_o + tb * sin_o
    w = inner - outer
    a = (1.0 - gamma * cos_i) * co
    b = (1.0 + gamma * cos_o) * ci
    omega_m = outer + w * a / (a + b)
    omega_r = w / ((co / (1.0 + gamma * cos_o) + ci / (1.0 - gamma * cos_i)) * gamma * cb)
    return omega_m, omega_r, sb, cb


# --------------------------------------------------------------------------------------------
# per-ball problem
# --------------------------------------------------------------------------------------------
@dataclass
class _Params:
    """Constants of the per-ball equations (scalars, or arrays of shape (Z,))."""

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


# --------------------------------------------------------------------------------------------
# ring problem
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class EquilibriumSolution:
    """Converged Jones–Harris state of the bearing.

    Attributes
    ----------
    displacement : ndarray, shape (5,)
        Inner ring relative to the outer ring: δ_a [m], δ_x [m], δ_y [m], θ_x [rad],
        θ_y [rad] (:data:`DOF_NAMES`).
    stiffness : ndarray, shape (5, 5)
        ∂(F_a, F_x, F_y, M_x, M_y)/∂(δ_a, δ_x, δ_y, θ_x, θ_y) at the solution [N/m, N/rad,
        N m/m, N m/rad].
    azimuth : ndarray, shape (Z,)
        ψ_j [rad].
    inner_contact_angle, outer_contact_angle : ndarray
        α_ij, α_oj [rad].
    inner_load, outer_load : ndarray
        Q_ij, Q_oj [N].
    inner_approach, outer_approach : ndarray
        δ_ij, δ_oj [m].
    centrifugal_force : ndarray
        F_cj [N].
    gyroscopic_moment : ndarray
        M_gj [N m].
    orbit_speed, spin_speed : ndarray
        ω_mj, ω_Rj [rad/s].
    loaded : ndarray of bool
        Balls in contact with the inner race.
    iterations : int
        Ring Newton iterations (all stages).
    residual : float
        Largest residual of the solved ring equations at the solution [N or N m].
    held_dofs : tuple of str
        Degrees of freedom held at 0 instead of solved (:data:`DOF_NAMES`; the tilts when
        ``ring_tilt = "held"``).
    reaction_moment : ndarray, shape (2,)
        (M_x, M_y) [N m] the tilt restraint exerts on the inner ring, in the sense of the
        moment load: the balls' moment at the held solution; zero when the tilt is free.
    """

    displacement: NDArray[np.float64]
    stiffness: NDArray[np.float64]
    azimuth: NDArray[np.float64]
    inner_contact_angle: NDArray[np.float64]
    outer_contact_angle: NDArray[np.float64]
    inner_load: NDArray[np.float64]
    outer_load: NDArray[np.float64]
    inner_approach: NDArray[np.float64]
    outer_approach: NDArray[np.float64]
    centrifugal_force: NDArray[np.float64]
    gyroscopic_moment: NDArray[np.float64]
    orbit_speed: NDArray[np.float64]
    spin_speed: NDArray[np.float64]
    loaded: NDArray[np.bool_]
    iterations: int
    residual: float
    held_dofs: tuple[str, ...] = ()
    reaction_moment: NDArray[np.float64] = field(default_factory=lambda: np.zeros(2))

    def ball_table(self) -> list[dict[str, float]]:
        """One row per ball, SI values with the unit in the key.

        Returns
        -------
        list of dict
            One dict per ball: ``ball`` (number from 1), ``azimuth_deg`` [deg], inner and
            outer contact angles [deg], loads [N] and approaches [m], ``centrifugal_force_n``
            [N], ``gyroscopic_moment_n_m`` [N m], ``orbit_speed_hz`` and ``spin_speed_hz`` [Hz].
        """
        rows = []
        for j in range(self.azimuth.size):
            rows.append(
                {
                    "ball": j + 1,
                    "azimuth_deg": math.degrees(self.azimuth[j]),
                    "inner_contact_angle_deg": math.degrees(self.inner_contact_angle[j]),
                    "outer_contact_angle_deg": math.degrees(self.outer_contact_angle[j]),
                    "inner_load_n": float(self.inner_load[j]),
                    "outer_load_n": float(self.outer_load[j]),
                    "inner_approach_m": float(self.inner_approach[j]),
                    "outer_approach_m": float(self.outer_approach[j]),
                    "centrifugal_force_n": float(self.centrifugal_force[j]),
                    "gyroscopic_moment_n_m": float(self.gyroscopic_moment[j]),
                    "orbit_speed_hz": float(self.orbit_speed[j] / TWO_PI),
                    "spin_speed_hz": float(self.spin_speed[j] / TWO_PI),
                }
            )
        return rows


class _Ring:
    """The 5-DOF ring problem for one bearing and operating point.

    The ball balance and the ring force are evaluated by the compiled kernel
    :func:`runout.models._equilibrium_kernels.ring_forces`; this class holds its inputs (the
    bearing constants, the Hertz constants linearised about the current contact angles) and
    the ball centres of the last evaluation, from which the next one starts.
    """

    def __init__(
        self,
        bearing: BallBearing,
        op: Operation,
        control: str,
        speed_on: bool = True,
        moment_arm: str = "curvature_centres",
    ) -> None:
        self.bearing = bearing
        d = bearing.element_diameter
        self.alpha0 = bearing.free_contact_angle
        self.a = bearing.curvature_distance
        self.ri0 = (bearing.inner_conformity - 0.5) * d
        self.ro0 = (bearing.outer_conformity - 0.5) * d
        self.rad_i = 0.5 * bearing.pitch_diameter + self.ri0 * math.cos(self.alpha0)
        # the arm of the balls' axial forces in the moment equations (module docstring)
        self.arm = self.rad_i if moment_arm == "curvature_centres" else 0.5 * bearing.pitch_diameter
        z = bearing.elements
        self.psi = TWO_PI * np.arange(z) / z
        self.cos_psi, self.sin_psi = np.cos(self.psi), np.sin(self.psi)
        mass = bearing.material.density * math.pi * d**3 / 6.0
        lam_i, lam_o = _LAMBDA[control]
        self.p = _Params(
            ball_diameter=d,
            pitch_diameter=bearing.pitch_diameter,
            ri0=self.ri0,
            ro0=self.ro0,
            f_i=bearing.inner_conformity,
            mass=mass,
            inertia=mass * d * d / 10.0,
            inner=TWO_PI * op.inner_speed,
            outer=TWO_PI * op.outer_speed,
            control=control,
            lam_i=lam_i,
            lam_o=lam_o,
            speed_on=speed_on,
        )
        # imported here, not with the module: `runout check` imports this module for its
        # input checks and should not pay for loading Numba
        from runout.models import _equilibrium_kernels

        self.kernels = _equilibrium_kernels
        self.cst = _equilibrium_kernels.constants(
            d,
            bearing.pitch_diameter,
            self.ri0,
            self.ro0,
            bearing.inner_conformity,
            self.p.mass,
            self.p.inertia,
            self.p.inner,
            self.p.outer,
            control == "inner",
            self.a * math.sin(self.alpha0),
            self.a * math.cos(self.alpha0),
            self.rad_i,
            self.a,
            self.arm,
        )
        self._k_cache: dict[float, tuple[float, float]] = {}
        self.x = np.zeros((z, 2))
        self.have_x = False

    # Hertz constants and their slope in the contact angle --------------------------------
    def _k_many(self, alphas: NDArray[np.float64]) -> tuple[NDArray[np.float64], ...]:
        """K_i, K_o [N/m^1.5] at each angle [rad], through a cache keyed by the rounded angle.

        K depends on α through cos α only (γ = D cos α / d_m): even in α, so a ball pressed on
        the other flank of the grooves (α < 0, e.g. under a moment) has K(|α|). The angles
        missing from the cache are solved in one vectorised call of the Hertz solver (each
        entry is solved independently, so the values equal those of one call per angle); a
        key's value is that of its first angle, as with one call per angle in this order.
        """
        alphas = np.minimum(np.abs(alphas), 0.5 * math.pi - _H_ALPHA)
        if not np.all(np.isfinite(alphas)):
            raise GeometryError("contact_angle", "must lie in [0, 90) deg, got a non-finite one")
        keys = [round(a, 13) for a in alphas.tolist()]
        missing: dict[float, float] = {}
        for key, alpha in zip(keys, alphas.tolist(), strict=True):
            if key not in self._k_cache and key not in missing:
                missing[key] = alpha
        if missing:
            ang = np.fromiter(missing.values(), dtype=np.float64, count=len(missing))
            k_i, k_o = _hertz_constants(self.bearing, ang)
            for n, key in enumerate(missing):
                self._k_cache[key] = (float(k_i[n]), float(k_o[n]))
        k_i = np.array([self._k_cache[key][0] for key in keys])
        k_o = np.array([self._k_cache[key][1] for key in keys])
        return k_i, k_o

    def set_angles(self, alpha_i: NDArray[np.float64], alpha_o: NDArray[np.float64]) -> None:
        r"""Linearise K_i, K_o about these signed angles [rad] (central differences of K).

        Angles are limited to :math:`|\alpha| \le \pi/2 - 2h`; a negative angle (contact on
        the other flank) is linearised about itself, K being even in α (:meth:`_k_many`).
        """
        h = _H_ALPHA
        lim = 0.5 * math.pi - 2 * h
        ai_c = np.clip(np.asarray(alpha_i, dtype=np.float64), -lim, lim)
        ao_c = np.clip(np.asarray(alpha_o, dtype=np.float64), -lim, lim)
        # per ball, in the order K(α_i), K(α_i ± h), K(α_o), K(α_o ± h)
        grid = np.stack([ai_c, ai_c + h, ai_c - h, ao_c, ao_c + h, ao_c - h], axis=1)
        k_i, k_o = self._k_many(grid.ravel())
        k_i, k_o = k_i.reshape(grid.shape), k_o.reshape(grid.shape)
        self.p.ki0 = k_i[:, 0].copy()
        self.p.ki1 = (k_i[:, 1] - k_i[:, 2]) / (2 * h)
        self.p.ai_c = ai_c
        self.p.ko0 = k_o[:, 3].copy()
        self.p.ko1 = (k_o[:, 4] - k_o[:, 5]) / (2 * h)
        self.p.ao_c = ao_c

    # geometry ----------------------------------------------------------------------------
    def groove_centres(self, q: NDArray[np.float64]) -> NDArray[np.float64]:
        """(A_1j, A_2j) for ring displacement q, shape (Z, 2) [m]."""
        a1 = (
            self.a * math.sin(self.alpha0)
            + q[0]
            + self.rad_i * (q[3] * self.sin_psi - q[4] * self.cos_psi)
        )
        a2 = self.a * math.cos(self.alpha0) + q[1] * self.cos_psi + q[2] * self.sin_psi
        return np.stack([a1, a2], axis=1)

    def forces(
        self, q: NDArray[np.float64]
    ) -> tuple[NDArray[np.float64], NDArray[np.float64], dict[str, Any], NDArray[np.bool_]]:
        """Ring force (5,), its Jacobian (5, 5), ball states and loaded mask at q.

        Raises
        ------
        ConvergenceError
            When some ball's equilibrium does not converge.
        """
        z = self.psi.size
        kernels = self.kernels
        force = np.empty(5)
        jac = np.empty((5, 5))
        state = np.empty((kernels.N_STATE, z))
        loaded = np.empty(z, dtype=np.bool_)
        x = self.x.copy()  # kept only if every ball converges
        try:
            status = self._ring_forces(q, x, force, jac, state, loaded)
        except ZeroDivisionError as error:  # e.g. ball speeds so large the balance overflows
            raise ConvergenceError(
                f"ball equilibrium (seed 001 eq. 3-6) did not converge ({error})"
            ) from error
        if status != kernels.OK:
            raise ConvergenceError("ball equilibrium (seed 001 eq. 3-6) did not converge")
        self.x, self.have_x = x, True
        out: dict[str, Any] = dict(zip(kernels.STATE_NAMES, state, strict=True))
        out["loaded"] = loaded
        return force, jac, out, loaded

    def _ring_forces(
        self,
        q: NDArray[np.float64],
        x: NDArray[np.float64],
        force: NDArray[np.float64],
        jac: NDArray[np.float64],
        state: NDArray[np.float64],
        loaded: NDArray[np.bool_],
    ) -> int:
        """One call of the compiled ring-force kernel; returns its status."""
        p = self.p
        return int(
            self.kernels.ring_forces(
                np.ascontiguousarray(q, dtype=np.float64),
                self.cos_psi,
                self.sin_psi,
                x,
                self.have_x,
                p.ki0,
                p.ki1,
                p.ai_c,
                p.ko0,
                p.ko1,
                p.ao_c,
                self.cst,
                p.lam_i,
                p.lam_o,
                p.speed_on,
                force,
                jac,
                state,
                loaded,
            )
        )


def _external(op: Operation) -> NDArray[np.float64]:
    return np.array(
        [
            op.axial_load,
            op.radial_load * math.cos(op.radial_load_direction),
            op.radial_load * math.sin(op.radial_load_direction),
            op.moment_load * math.cos(op.moment_load_direction),
            op.moment_load * math.sin(op.moment_load_direction),
        ]
    )


_Forces = tuple[NDArray[np.float64], NDArray[np.float64], dict[str, Any], NDArray[np.bool_]]


def _newton(
    ring: _Ring,
    q: NDArray[np.float64],
    load: NDArray[np.float64],
    stage: str,
    solved: NDArray[np.int64],
) -> tuple[NDArray[np.float64], int, _Forces]:
    """Damped Newton on the ring equations of the degrees of freedom ``solved``.

    The others keep their value in q (the tilts held at 0) and their equations are not
    imposed (their residual is the restraint's reaction). Returns q, the iteration count and
    :meth:`_Ring.forces` at q. The evaluation that accepts a step (the last of its line
    search) is the next iteration's force and Jacobian, so each iteration costs one
    ring-force evaluation unless the step has to be shortened.
    """
    a = ring.a
    f_scale = max(float(np.abs(load[:3]).max()), float(np.abs(load[3:]).max()) / ring.rad_i, 1e-3)
    m_scale = f_scale * ring.rad_i
    scales = np.array([f_scale, f_scale, f_scale, m_scale, m_scale])[solved]
    lin = np.array([1.0, 1.0, 1.0, ring.rad_i, ring.rad_i])
    step_max = 0.05 * a
    ev = ring.forces(q)
    for it in range(1, _RING_ITER + 1):
        force, jac, _, loaded = ev
        res = (force - load)[solved]
        if np.count_nonzero(loaded) < 3:
            free = "free to tilt and to move axially" if solved.size == 5 else "free axially"
            raise NumericalError(
                f"{stage}: fewer than 3 balls carry load; the ring ({free}) cannot be held "
                f"(loads {load.tolist()}); a bearing with play under a radial load alone runs "
                'in model = "dynamic", or here with an axial load too'
            )
        sub = jac[np.ix_(solved, solved)]
        dq = np.zeros(5)
        try:
            dq[solved] = -np.linalg.solve(sub + 1e-12 * np.diag(np.abs(np.diag(sub)) + 1.0), res)
        except np.linalg.LinAlgError:
            raise NumericalError(f"{stage}: singular bearing stiffness matrix") from None
        big = float(np.abs(dq * lin).max())
        if big > step_max:
            dq *= step_max / big
            big = step_max
        norm0 = float(np.abs(res / scales).max())
        t = 1.0
        for _ in range(30):  # t < 1e-6 stops it after 21 halvings
            trial = q + t * dq
            ev = ring.forces(trial)
            trial_res = float(np.abs((ev[0] - load)[solved] / scales).max())
            if trial_res <= max(norm0, 1e-14) or t < 1e-6:
                break
            t *= 0.5
        q = trial
        if big * t <= 1e-13 * a and norm0 <= 1e-9:
            return q, it, ev
    raise ConvergenceError(f"{stage}: ring equilibrium (seed 001 eq. 1-2) did not converge")


def _hertz_constants(
    bearing: BallBearing, alphas: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """K_i, K_o [N/m^1.5] at contact angles in [0, π/2) [rad], in one call of the Hertz solver.

    The values of :func:`runout.geometry.contact.ball_race_contacts` angle by angle, to the last bit
    or two (every entry of the vectorised solver is solved on its own; vectorised ufuncs may
    round differently from scalar ones).
    """
    n = alphas.size
    ep = bearing.material.effective_modulus
    s = np.empty(2 * n)
    f = np.empty(2 * n)
    d, dm = bearing.element_diameter, bearing.pitch_diameter
    s[:n], f[:n] = ball_race_curvature(d, dm, bearing.inner_conformity, alphas, "inner")
    s[n:], f[n:] = ball_race_curvature(d, dm, bearing.outer_conformity, alphas, "outer")
    k = hertz_point_stiffness(s, f, ep)
    return k[:n], k[n:]


def _check_loads(op: Operation) -> None:
    if op.axial_load == 0.0 and op.radial_load == 0.0 and op.moment_load == 0.0:
        raise GeometryError(
            "operation",
            "the equilibrium model needs an axial load, a radial load or a moment to hold the "
            "inner ring",
        )


def _axial_start(bearing: BallBearing, axial_load: float, kn: float) -> tuple[float, float]:
    r"""Contact angle [rad] and axial displacement [m] under the axial load, K_n frozen.

    Harris's load-angle relation :math:`F_a = Z K_n [A(\cos\alpha^0/\cos\alpha - 1)]^{1.5}
    \sin\alpha` with the series stiffness K_n of the free contact angle, solved by bisection
    on :math:`[\alpha^0, \pi/2)` (the load grows with α there), then
    :math:`\delta_a = (A + \delta_n)\sin\alpha - A\sin\alpha^0`,
    :math:`\delta_n = (F_a/(Z K_n\sin\alpha))^{2/3}`. Only a start: the ring Newton then
    evaluates K at each ball's own angles (:func:`runout.geometry.loading.axial_loading` gives the
    static solution with K at the loaded angle, at some twenty Hertz solutions).
    """
    a = bearing.curvature_distance
    alpha0 = bearing.free_contact_angle
    z = bearing.elements
    c0 = math.cos(alpha0)

    def excess(alpha: float) -> float:
        stretch = max(c0 / math.cos(alpha) - 1.0, 0.0)
        value: float = z * kn * (a * stretch) ** 1.5 * math.sin(alpha) - axial_load
        return value

    lo, hi = alpha0, 0.5 * math.pi - 1e-6
    for _ in range(60):  # to below 1e-15 rad
        mid = 0.5 * (lo + hi)
        if excess(mid) < 0.0:
            lo = mid
        else:
            hi = mid
    alpha = 0.5 * (lo + hi)
    d_n = (axial_load / (z * kn * math.sin(alpha))) ** (2.0 / 3.0)
    return alpha, (a + d_n) * math.sin(alpha) - a * math.sin(alpha0)


def _initial_displacement(bearing: BallBearing, op: Operation) -> tuple[NDArray[np.float64], float]:
    """Newton start of the ring (5,) [m, rad] and the contact angle to start from [rad]."""
    _check_loads(op)
    q = np.zeros(5)
    alpha = bearing.free_contact_angle
    if op.axial_load == 0.0 and op.radial_load == 0.0:
        return q, alpha
    k_i, k_o = _hertz_constants(bearing, np.array([alpha]))
    kn = float(combined_stiffness(k_i[0], k_o[0]))
    if op.axial_load > 0.0:
        alpha, q[0] = _axial_start(bearing, op.axial_load, kn)
    if op.radial_load > 0.0:
        z = bearing.elements
        guess = (2.5 * op.radial_load / (z * kn)) ** (2.0 / 3.0)
        if op.axial_load == 0.0:
            guess += 0.5 * bearing.radial_clearance
        q[1] = guess * math.cos(op.radial_load_direction)
        q[2] = guess * math.sin(op.radial_load_direction)
    return q, alpha


def _pure_moment(op: Operation) -> bool:
    """A moment with neither axial nor radial force."""
    return op.axial_load == 0.0 and op.radial_load == 0.0 and op.moment_load > 0.0


def _moment_start(ring: _Ring, op: Operation) -> NDArray[np.float64]:
    r"""Start of the ring Newton for a pure moment: the tilt that carries M, ring centred.

    Without an axial force the Newton start cannot be the unloaded ring: every ball is then
    at zero approach (zero clearance) or in the play, the Hertz stiffness
    :math:`\tfrac32 K\delta^{1/2}` vanishes and the stiffness matrix is singular. By the
    symmetry of the load (a rotation by π about the moment vector maps the bearing onto
    itself and turns δ_a, measured from the centre of the axial play, into −δ_a), the ring sits
    centred in the axial play, :math:`\delta_a = -A\sin\alpha^0`, and tilts about the moment
    vector. Along that ray the moment carried grows monotonically with the tilt θ: it is 0
    while :math:`\Re_i\theta\,|\sin(\psi_j - \varphi_M)| \le A\sin\alpha^0` for every ball
    (angular play) and then like a power of the excess tilt. θ is bracketed by doubling the
    excess tilt (counting the moment only once at least 3 balls are loaded, so that the start
    holds the ring radially too) and refined by bisection to 0.1 %; the full
    five-degree-of-freedom Newton takes over from there (the radial displacement is free: with
    an odd number of balls it is small but not zero). No load is added to the user's case.

    Parameters
    ----------
    ring : _Ring
        The ring problem, speed effects off.
    op : Operation
        Moment [N m] and its direction :math:`\varphi_M` [rad].

    Returns
    -------
    ndarray, shape (5,)
        Ring displacement (δ_a [m], δ_x [m], δ_y [m], θ_x [rad], θ_y [rad]).
    """
    c, s = math.cos(op.moment_load_direction), math.sin(op.moment_load_direction)
    lever = float(np.abs(ring.sin_psi * c - ring.cos_psi * s).max())
    offset = ring.a * math.sin(ring.alpha0)
    play = offset / (ring.rad_i * lever)

    def carried(theta: float) -> float:
        """Moment about the moment vector at tilt θ; 0 while fewer than 3 balls are loaded."""
        q = np.array([-offset, 0.0, 0.0, theta * c, theta * s])
        force, _, _, loaded = ring.forces(q)
        if np.count_nonzero(loaded) < 3:
            return 0.0
        return float(force[3] * c + force[4] * s)

    # excess tilt beyond the play [rad], from 1e-9 A up to an approach of A at the lever
    lo, hi = 0.0, 1e-9 * ring.a / (ring.rad_i * lever)
    while carried(play + hi) < op.moment_load:
        lo, hi = hi, 2.0 * hi
        if hi * ring.rad_i * lever > ring.a:
            raise NumericalError(
                "static: under a pure moment about this axis fewer than 3 balls carry load "
                f"(moment {op.moment_load:.6g} N m); the ring cannot be held"
            )
    while hi - lo > 1e-3 * hi:
        mid = 0.5 * (lo + hi)
        if carried(play + mid) >= op.moment_load:
            hi = mid
        else:
            lo = mid
    theta = play + hi
    return np.array([-offset, 0.0, 0.0, theta * c, theta * s])


def setup(case: Case) -> None:
    """The input checks of :func:`solve_equilibrium` for a case, without solving anything.

    Parameters
    ----------
    case : Case
        A validated case with ``[analysis] model = "equilibrium"``.

    Raises
    ------
    GeometryError
        Not a ball bearing, an unknown race control or ring tilt, no load to hold the inner
        ring, or a moment load on a ring held against tilt.
    """
    bearing = case.bearing
    op = case.operation
    if not isinstance(bearing, BallBearing):
        raise GeometryError("bearing.type", "the equilibrium model needs a ball bearing")
    control = case.analysis.race_control
    if control not in _LAMBDA:
        raise GeometryError(
            "analysis.race_control", f'must be "outer", "inner" or "none", got {control!r}'
        )
    _check_loads(op)
    _check_ring_tilt(case.analysis.ring_tilt, op)


def _check_ring_tilt(ring_tilt: str, op: Operation) -> None:
    """Refuse an unknown ``ring_tilt``, and a moment load on a ring held against tilt."""
    if ring_tilt not in RING_TILTS:
        raise GeometryError("analysis.ring_tilt", f'must be "free" or "held", got {ring_tilt!r}')
    if ring_tilt == "held" and op.moment_load != 0.0:
        # the restraint would carry any moment: the moment load would change nothing
        raise GeometryError(
            "analysis.ring_tilt",
            f'"held" with operation.moment_load = {op.moment_load:.6g} N m: the restraint '
            "that holds the ring untilted carries any moment, so the moment load would change "
            'nothing; remove moment_load, or write ring_tilt = "free" to have the balls carry it',
        )


def solve_equilibrium(
    bearing: BallBearing,
    op: Operation,
    *,
    race_control: str = "outer",
    ring_tilt: str = "free",
    moment_arm: str = "curvature_centres",
) -> EquilibriumSolution:
    """Jones–Harris equilibrium of ``bearing`` at the loads and speed of ``op``.

    Parameters
    ----------
    bearing : BallBearing
        Geometry and material (density for the ball mass).
    op : Operation
        Ring speeds [Hz], axial load, radial load and its direction, moment and its direction.
    race_control : {"outer", "inner", "none"}
        Raceway whose friction resists the gyroscopic moment (module docstring).
    ring_tilt : {"free", "held"}
        "free": the five ring equations are solved; "held": θ_x = θ_y = 0 and the three force
        equations are solved, the balls' moment being the restraint's reaction.
    moment_arm : {"curvature_centres", "pitch_radius"}
        Arm of the balls' axial forces in the two moment equations: Harris's ℜ_i (the
        locus of inner groove curvature centres), or the pitch radius d_m/2 as ISO/TS
        16281's moment equilibrium takes it. The tilt moves the groove centres by ℜ_i θ
        either way.

    Returns
    -------
    EquilibriumSolution
        The converged ring displacement [m, rad], the 5×5 stiffness matrix, the reaction
        moment [N m] of a held tilt and the per-ball contact angles [rad], loads [N],
        approaches [m] and speeds [rad/s].

    Raises
    ------
    GeometryError
        No load, an unknown race control or ring tilt, or a moment load with the tilt held.
    NumericalError, ConvergenceError
        When the ring cannot be held; the message names the stage (static or at speed).
    """
    if not isinstance(bearing, BallBearing):
        raise GeometryError("bearing.type", "the equilibrium model needs a ball bearing")
    if race_control not in _LAMBDA:
        raise GeometryError(
            "analysis.race_control", f'must be "outer", "inner" or "none", got {race_control!r}'
        )
    _check_ring_tilt(ring_tilt, op)
    if moment_arm not in MOMENT_ARMS:
        raise GeometryError(
            "analysis.moment_arm",
            f'must be "curvature_centres" or "pitch_radius", got {moment_arm!r}',
        )
    solved = _SOLVED[ring_tilt]
    load = _external(op)
    q, alpha = _initial_displacement(bearing, op)
    total = 0
    ring = _Ring(bearing, op, race_control, speed_on=False, moment_arm=moment_arm)
    stages = ["static"]
    if op.inner_speed != 0.0 or op.outer_speed != 0.0:
        stages.append("at speed")
    z = bearing.elements
    if _pure_moment(op):
        # balls on either side of the moment axis press on opposite flanks (α of either sign)
        side = np.sin(ring.psi - op.moment_load_direction)
        start = np.where(side < 0.0, -alpha, alpha)
        ring.set_angles(start, start)
        q = _moment_start(ring, op)
    else:
        ring.set_angles(np.full(z, alpha), np.full(z, alpha))
    for stage in stages:
        ring.p.speed_on = stage == "at speed"
        for _ in range(_ANGLE_LOOPS):
            q, it, (_, _, state, loaded) = _newton(ring, q, load, stage, solved)
            total += it
            ai = np.where(loaded, state["alpha_i"], ring.p.ai_c)
            ao = np.where(loaded, state["alpha_o"], ring.p.ao_c)
            moved = max(
                float(np.abs(ai - ring.p.ai_c).max()), float(np.abs(ao - ring.p.ao_c).max())
            )
            if moved < 1e-11:
                # re-centring K about angles this close changes it by O(moved²) relative,
                # below round-off: keep the linearisation (one Hertz solution less)
                break
            ring.set_angles(ai, ao)
        else:
            raise ConvergenceError(f"{stage}: contact angles did not settle")
    # Components below the Newton step tolerance are round-off (e.g. 1e-21 m of radial
    # displacement under a pure axial load), not displacement: report them as 0.
    lin = np.array([1.0, 1.0, 1.0, ring.rad_i, ring.rad_i])
    q = np.where(np.abs(q * lin) <= 1e-13 * ring.a, 0.0, q)
    force, jac, state, loaded = ring.forces(q)
    unl = ~loaded
    fc: NDArray[np.float64] = state["fc"]
    q_o = np.where(unl, fc, state["q_o"])
    d_o = np.where(unl, (np.abs(fc) / ring.p.ko0) ** (2.0 / 3.0), state["d_o"])
    # the moment equations' residual is what the restraint supplies (moment_load is 0)
    reaction = (force - load)[3:] if ring_tilt == "held" else np.zeros(2)
    # below 1e-12 of the loads' moment scale it is round-off (a load symmetric about that
    # axis), not a moment; as the displacement components above
    tiny = 1e-12 * float(np.abs(load[:3]).max()) * ring.rad_i
    reaction = np.where(np.abs(reaction) <= tiny, 0.0, reaction)
    return EquilibriumSolution(
        displacement=q,
        stiffness=jac,
        azimuth=ring.psi,
        inner_contact_angle=np.where(unl, 0.0, state["alpha_i"]),
        outer_contact_angle=np.where(unl, 0.0, state["alpha_o"]),
        inner_load=np.where(unl, 0.0, state["q_i"]),
        outer_load=q_o,
        inner_approach=np.where(unl, 0.0, state["d_i"]),
        outer_approach=d_o,
        centrifugal_force=np.broadcast_to(state["fc"], (z,)).copy(),
        gyroscopic_moment=np.broadcast_to(state["mg"], (z,)).copy(),
        orbit_speed=np.broadcast_to(state["omega_m"], (z,)).copy(),
        spin_speed=np.broadcast_to(state["omega_r"], (z,)).copy(),
        loaded=loaded,
        iterations=total,
        residual=float(np.abs((force - load)[solved]).max()),
        held_dofs=tuple(DOF_NAMES[i] for i in range(5) if i not in solved),
        reaction_moment=reaction,
    )


# --------------------------------------------------------------------------------------------
# model
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class EquilibriumResult(RunResult):
    """A :class:`RunResult` of the equilibrium model with its solver state.

    Its tables and files come from :attr:`details`
    (:class:`~runout.analysis.result_details.EquilibriumDetails`, also in the JSON); ``solution``
    is the full solution (per-ball speeds, forces, the Newton record) for Python use.

    Attributes
    ----------
    solution : EquilibriumSolution or None
        The converged Jones–Harris state: ring displacement [m, rad], stiffness matrix,
        per-ball contact angles [rad], loads [N], approaches [m] and speeds [rad/s]. The other
        fields are those of :class:`RunResult`.
    """

    solution: EquilibriumSolution | None = None


#: Stiffness entries below this fraction of the radial block's largest are the derivative's
#: round-off (the analytic derivatives are exact to ~1e-16) and are reported as 0.
STIFFNESS_ROUNDOFF = 1e-12


def radial_stiffness(sol: EquilibriumSolution, speed_hz: float) -> RadialStiffness:
    r"""The radial 2×2 block of the bearing stiffness, as rotordynamics codes take it [N/m].

    :math:`k_{xx} = \partial F_x/\partial\delta_x`, :math:`k_{xy} = \partial F_x/\partial
    \delta_y`, :math:`k_{yx}`, :math:`k_{yy}` of the Jones–Harris equilibrium (seed 001 §2.1;
    Kim et al., 2015) at the operating point, the axial displacement and the tilts held at
    their solution: the direct radial stiffness of a linear bearing element (for instance
    ``ross.BearingElement(kxx=..., kxy=..., kyx=..., kyy=...)``). The couplings to the tilts
    and the moment stiffness are in the 5×5 ``stiffness_matrix``. The force is the one the
    rings carry for a displacement of the inner ring relative to the outer ring, so the block
    is the bearing's restoring stiffness (positive diagonal). Entries below
    :data:`STIFFNESS_ROUNDOFF` of the block's largest are round-off and reported as 0.

    Parameters
    ----------
    sol : EquilibriumSolution
        Converged equilibrium (:func:`solve_equilibrium`), stiffness matrix in SI units.
    speed_hz : float
        Speed of the rotating ring [Hz] (reported as ``speed_rpm``).

    Returns
    -------
    RadialStiffness
        ``kxx_n_per_m``, ``kxy_n_per_m``, ``kyx_n_per_m``, ``kyy_n_per_m`` [N/m] and
        ``speed_rpm`` [rev/min].
    """
    block = np.array(sol.stiffness[1:3, 1:3], dtype=float)
    scale = float(np.abs(block).max(initial=0.0))
    block[np.abs(block) < STIFFNESS_ROUNDOFF * scale] = 0.0
    return RadialStiffness(
        kxx_n_per_m=float(block[0, 0]),
        kxy_n_per_m=float(block[0, 1]),
        kyx_n_per_m=float(block[1, 0]),
        kyy_n_per_m=float(block[1, 1]),
        speed_rpm=60.0 * float(speed_hz),
    )


@dataclass(frozen=True)
class LifeModification:
    """The inputs of the modified reference rating life L_nmr = a_1 a_ISO L10r (ISO 281:2007).

    Attributes
    ----------
    reliability : float
        Reliability [%] (``[analysis] reliability``; a row of ISO 281's a_1 table).
    viscosity_ratio : float or None
        κ [-] (``[lubrication] viscosity_ratio``).
    operating_viscosity, rated_viscosity : float or None
        ν and ν_1 [m²/s] (``[lubrication]``); κ = ν/ν_1, ν_1 by default ISO 281's.
    contamination_factor : float or None
        e_C [-] (``[lubrication] contamination_factor``).
    fatigue_load_limit : float or None
        C_u [N] (``[bearing] fatigue_load_limit``).
    """

    reliability: float = 90.0
    viscosity_ratio: float | None = None
    operating_viscosity: float | None = None
    rated_viscosity: float | None = None
    contamination_factor: float | None = None
    fatigue_load_limit: float | None = None

    @classmethod
    def of_case(cls, case: Case) -> LifeModification:
        """The case's ``[analysis] reliability``, ``[lubrication]`` and C_u.

        Parameters
        ----------
        case : Case
            A validated case.

        Returns
        -------
        LifeModification
        """
        spec = case.spec
        lube = spec.lubrication
        return cls(
            reliability=90.0 if spec.analysis.reliability is None else spec.analysis.reliability,
            viscosity_ratio=None if lube is None else lube.viscosity_ratio,
            operating_viscosity=None if lube is None else lube.operating_viscosity,
            rated_viscosity=None if lube is None else lube.rated_viscosity,
            contamination_factor=None if lube is None else lube.contamination_factor,
            fatigue_load_limit=spec.lead_bearing.fatigue_load_limit,
        )


def _modified(
    life: RatingLife, bearing: BallBearing, op: Operation, mod: LifeModification
) -> tuple[RatingLife, list[str]]:
    """``life`` with a_1 and, where its inputs are given, a_ISO and L_nmr; and the notes."""
    kappa = mod.viscosity_ratio
    notes: list[str] = []
    if mod.operating_viscosity is not None:
        relative = op.inner_speed - op.outer_speed
        if mod.rated_viscosity is None and relative == 0.0:
            notes.append(
                "life: no modified life L_nmr: lubrication.operating_viscosity needs the rated "
                "viscosity ν_1, which ISO 281 gives for a turning bearing only; give "
                "lubrication.rated_viscosity or viscosity_ratio"
            )
            return modified_reference_life(life, reliability_percent=mod.reliability)[0], notes
        else:
            nu1 = (
                mod.rated_viscosity
                if mod.rated_viscosity is not None
                else rated_viscosity(relative, bearing.pitch_diameter)
            )
            kappa = mod.operating_viscosity / nu1
            source = (
                "lubrication.rated_viscosity"
                if mod.rated_viscosity is not None
                else f"ISO 281's at {60.0 * abs(relative):.6g} r/min and d_m "
                f"{bearing.pitch_diameter * 1e3:.6g} mm"
            )
            notes.append(
                f"life: viscosity ratio κ = ν/ν_1 = {mod.operating_viscosity * 1e6:.6g} / "
                f"{nu1 * 1e6:.6g} mm²/s = {kappa:.4g} (ν_1 {source})"
            )
    modified, more = modified_reference_life(
        life,
        reliability_percent=mod.reliability,
        viscosity_ratio=kappa,
        contamination_factor=mod.contamination_factor,
        fatigue_load_limit=mod.fatigue_load_limit,
    )
    if modified.a_iso is None and mod.reliability != 90.0 and not more:
        more = [
            f"life: analysis.reliability = {mod.reliability:g} % is not applied: the modified "
            "life L_nmr needs bearing.fatigue_load_limit and [lubrication] "
            "contamination_factor and viscosity_ratio (or operating_viscosity)"
        ]
    return modified, notes + more


def ball_loads_life(
    bearing: BallBearing,
    op: Operation,
    inner_loads: NDArray[np.float64],
    outer_loads: NDArray[np.float64],
    nominal_contact_angle: float,
    modification: LifeModification | None = None,
    *,
    table: str = "[bearing]",
) -> tuple[RatingLife, list[str]]:
    """ISO/TS 16281 reference rating life (and the modified life) from one bearing's ball loads.

    Parameters
    ----------
    bearing : BallBearing
        The bearing, with its ``dynamic_load_rating`` C [N] (not None).
    op : Operation
        The operating point (rotating ring, ring speeds [Hz]).
    inner_loads, outer_loads : ndarray, shape (Z,)
        Each ball's inner and outer contact load [N].
    nominal_contact_angle : float
        Nominal contact angle of the rating [rad], 0 to 45°.
    modification : LifeModification or None
        Reliability and the a_ISO inputs; None: 90 %, no a_ISO.
    table : str
        How the notes name the bearing's table (``[bearing]``, ``bearings[2]``).

    Returns
    -------
    life : RatingLife
        L10r and its parts; a_1, a_ISO and L_nmr where their inputs are given.
    notes : list of str
        What the life assumes.

    Notes
    -----
    ISO/TS 16281:2008 eq. 19-29 and ISO 281:2007's a_1, a_ISO (:mod:`runout.geometry.life`).
    """
    rating = bearing.dynamic_load_rating
    assert rating is not None
    angle = math.degrees(nominal_contact_angle)
    relative = op.inner_speed - op.outer_speed
    life = reference_rating_life(
        elements=bearing.elements,
        element_diameter=bearing.element_diameter,
        pitch_diameter=bearing.pitch_diameter,
        inner_conformity=bearing.inner_conformity,
        outer_conformity=bearing.outer_conformity,
        nominal_contact_angle=nominal_contact_angle,
        dynamic_load_rating=rating,
        inner_loads=inner_loads,
        outer_loads=outer_loads,
        rotating_ring=op.rotating_ring,
        relative_speed=relative,
    )
    free = math.degrees(bearing.free_contact_angle)
    why = (
        f" (the play's free contact angle {free:.4g} deg is not a rating angle: for an "
        f"angular-contact bearing give {table} nominal_contact_angle)"
        if nominal_contact_angle == 0.0 and free > 0.0
        else ""
    )
    notes = [
        f"life: ISO/TS 16281 basic reference rating life L10r, rated at the nominal contact "
        f"angle {angle:.6g} deg{why}; the lives count revolutions of one ring relative to the "
        "other; not included: contact ellipses truncated by the groove shoulders (not checked: "
        "runout has no shoulder heights)"
    ]
    life, modified_notes = _modified(life, bearing, op, modification or LifeModification())
    notes += modified_notes
    return life, notes


def bearing_damping(
    stiffness: RadialStiffness, axial_stiffness: float, model: str, coefficient_s: float | None
) -> tuple[BearingDamping | None, list[str]]:
    r"""Damping of the bearing coefficients, c = β k, and the note that names its model.

    Parameters
    ----------
    stiffness : RadialStiffness
        The reported radial block (:func:`radial_stiffness`) [N/m].
    axial_stiffness : float
        K_aa, the axial diagonal of the 5×5 stiffness [N/m].
    model : {"none", "kraemer", "proportional"}
        ``[analysis] bearing_damping``.
    coefficient_s : float or None
        ``[analysis] bearing_damping_coefficient``, β of ``"proportional"`` [s].

    Returns
    -------
    tuple
        :class:`~runout.analysis.result_details.BearingDamping` (cxx = β kxx, cxy = β kxy, cyx,
        cyy and czz = β K_aa [N s/m]) and its note, or (None, []) for ``"none"``.

    Notes
    -----
    E. Krämer, *Dynamics of Rotors and Foundations*, Springer, 1993: rolling-element bearing
    damping c ≈ (0.25 ... 2.5) × 10⁻⁵ s · k (:mod:`runout.geometry.bearing_damping`).
    """
    if model == "none":
        return None, []
    beta = damping_coefficient(model, coefficient_s)
    k = np.array(
        [
            stiffness.kxx_n_per_m,
            stiffness.kxy_n_per_m,
            stiffness.kyx_n_per_m,
            stiffness.kyy_n_per_m,
            axial_stiffness,
        ]
    )
    c = proportional_damping(k, beta)
    low, high = KRAEMER_RANGE_S
    if model == "kraemer":
        note = (
            f'bearing_damping = "kraemer": damping c = β k with β = {beta:.3g} s for every '
            f"coefficient (bearing_damping: cxx ... czz), the geometric mean of Krämer's range "
            f"{low:.3g} ... {high:.3g} s for rolling bearings (Dynamics of Rotors and Foundations, "
            "1993): an estimate, not a measurement (the range spans a factor 10)"
        )
    else:
        note = (
            f'bearing_damping = "proportional": damping c = β k with the given β = {beta:.6g} s '
            f"for every coefficient (bearing_damping: cxx ... czz); Krämer's range for rolling "
            f"bearings is {low:.3g} ... {high:.3g} s"
        )
    damping = BearingDamping(
        model=model,
        coefficient_s=beta,
        cxx_n_s_per_m=float(c[0]),
        cxy_n_s_per_m=float(c[1]),
        cyx_n_s_per_m=float(c[2]),
        cyy_n_s_per_m=float(c[3]),
        czz_n_s_per_m=float(c[4]),
    )
    return damping, [note]


def rating_life(
    bearing: BallBearing,
    op: Operation,
    sol: EquilibriumSolution,
    nominal_contact_angle: float = 0.0,
    modification: LifeModification | None = None,
) -> tuple[RatingLife | None, list[str]]:
    """ISO/TS 16281 reference rating life of the solved bearing, and the notes that go with it.

    Parameters
    ----------
    bearing : BallBearing
        The bearing; its ``dynamic_load_rating`` C [N] (None: no life).
    op : Operation
        The operating point (rotating ring, ring speeds [Hz]).
    sol : EquilibriumSolution
        The converged equilibrium: the inner ring takes the balls' inner contact loads, the
        outer ring their outer contact loads [N].
    nominal_contact_angle : float
        Nominal contact angle of the rating [rad]: 0 for a deep-groove bearing, the case's
        ``nominal_contact_angle`` for an angular-contact one.
    modification : LifeModification or None
        Reliability and the a_ISO inputs; None: 90 %, no a_ISO.

    Returns
    -------
    life : RatingLife or None
        L10r [10^6 rev] and its parts (:func:`runout.geometry.life.reference_rating_life`),
        with a_1, a_ISO and L_nmr where their inputs are given
        (:func:`runout.geometry.life.modified_reference_life`); None without C, or for a
        nominal angle beyond 45° (a thrust bearing).
    notes : list of str
        What the life assumes, or why there is none.

    Notes
    -----
    ISO/TS 16281:2008 eq. 19-29 (:mod:`runout.geometry.life`) on the Jones–Harris loads.
    """
    rating = bearing.dynamic_load_rating
    if rating is None:
        return None, [
            "no life: give [bearing] dynamic_load_rating (C) for the ISO/TS 16281 reference "
            "rating life L10r"
        ]
    angle = math.degrees(nominal_contact_angle)
    if nominal_contact_angle > MAX_RADIAL_CONTACT_ANGLE:
        return None, [
            f"bearing.dynamic_load_rating: no life: the nominal contact angle {angle:.6g} deg "
            "exceeds 45 deg, a thrust ball bearing in ISO 281, whose ISO/TS 16281 formulas "
            "runout does not implement"
        ]
    life, notes = ball_loads_life(
        bearing,
        op,
        sol.inner_load,
        sol.outer_load,
        nominal_contact_angle,
        modification,
    )
    if op.inner_speed != 0.0 or op.outer_speed != 0.0:
        f_c = float(sol.centrifugal_force.max())
        notes.append(
            "life: at speed each ring's equivalent load is formed from its own contact loads, "
            f"the outer ones carrying the centrifugal force ({f_c:.4g} N per ball): ISO/TS "
            "16281's loads are those of a static distribution, so this extends it"
        )
    if op.inner_speed != 0.0 and op.outer_speed != 0.0:
        notes.append(
            f"life: both rings turn; the equivalent loads take the {op.rotating_ring} ring "
            "(operation.rotating_ring) as the one turning relative to the load, as ISO/TS "
            "16281 rates one turning ring"
        )
    return life, notes


def run(case: Case) -> RunResult:
    """Run the Jones–Harris equilibrium model (seed 001 §2.1) on a case.

    Parameters
    ----------
    case : Case
        A validated case with ``[analysis] model = "equilibrium"`` and a ball bearing.

    Returns
    -------
    RunResult
        An :class:`EquilibriumResult` at one instant: the inner ring's displacement relative to
        the outer ring [m] (axial counted from the rings axially centred), no lines, zero
        runout, and :class:`~runout.analysis.result_details.EquilibriumDetails` (ring
        displacement [m, rad], stiffness matrix, radial stiffness [N/m], per-ball table and,
        with ``[bearing] dynamic_load_rating``, the ISO/TS 16281 life, :func:`rating_life`).

    Raises
    ------
    GeometryError
        Not a ball bearing, an unknown race control or ring tilt, no load, or a moment load
        with the tilt held.

    Notes
    -----
    Kim, Choi & Yoon, "Vibration analysis of ball bearings with ball geometric
    imperfections", §2.1, eq. 1-9 (seed 001), with Jones's raceway-control theory from
    Harris, *Rolling Bearing Analysis*.
    """
    bearing = case.bearing
    op = case.operation
    if not isinstance(bearing, BallBearing):
        raise GeometryError("bearing.type", "the equilibrium model needs a ball bearing")
    control = case.analysis.race_control
    ring_tilt = case.analysis.ring_tilt
    moment_arm = case.analysis.moment_arm
    sol = solve_equilibrium(
        bearing, op, race_control=control, ring_tilt=ring_tilt, moment_arm=moment_arm
    )
    loaded = sol.loaded
    # |α|: under a moment some balls press on the other flank (negative angles)
    mean_alpha = float(
        0.5
        * (
            np.abs(sol.inner_contact_angle[loaded]).mean()
            + np.abs(sol.outer_contact_angle[loaded]).mean()
        )
    )
    q = sol.displacement
    notes = [
        "static equilibrium of the perfect bearing at one instant: no runout history "
        "(components empty, runout figures null: a position, not a runout); displacement = "
        "inner ring relative to the outer ring "
        "(mean_displacement_m from the rings centred; ring_displacement.axial_m from the "
        "contact on one groove flank, as in seed 001)",
    ]
    if abs(q[3]) + abs(q[4]) > 0.0 and op.moment_load == 0.0:
        notes.append(
            f'the inner ring is free to tilt (analysis.ring_tilt = "free", the default) and '
            f"tilts by ({q[3] * 1e3:.4g}, {q[4] * 1e3:.4g}) mrad about x, y: a single bearing "
            "has no moment restraint but its balls, so its radial displacement includes the "
            'tilt coupling; ring_tilt = "held" holds the tilt at 0, as quasi_static_3d and '
            "dynamic do"
        )
    reaction = sol.reaction_moment
    if sol.held_dofs:
        notes.append(
            'analysis.ring_tilt = "held": the inner ring\'s tilts are held at 0 (δ_a, δ_x, δ_y '
            "solved); the balls' moment on it is a reaction of the restraint, reaction_moment_n_m "
            f"= ({reaction[0]:.6g}, {reaction[1]:.6g}) N m about x, y; stiffness_matrix is the "
            "5×5 at this solution, tilt rows and columns included"
        )
    if moment_arm == "pitch_radius":
        notes.append(
            'analysis.moment_arm = "pitch_radius": the balls\' axial forces act on the inner '
            f"ring's moment at the pitch radius d_m/2 = {0.5e3 * bearing.pitch_diameter:.6g} mm, "
            "as ISO/TS 16281's moment equilibrium takes it, not at the radius of the inner "
            "groove curvature centres (Harris, the default); the tilt still moves those "
            "centres, so a given moment loads the balls more"
        )
    if not loaded.all():
        notes.append(
            f"{int((~loaded).sum())} of {loaded.size} balls carry no inner-race load "
            "(pressed onto the outer groove by their centrifugal force only)"
        )
    # the rating's nominal angle: the case's catalogue angle, else 0 (deep groove, ISO 281)
    nominal = case.spec.lead_bearing.nominal_contact_angle
    life, life_notes = rating_life(
        bearing, op, sol, 0.0 if nominal is None else nominal, LifeModification.of_case(case)
    )
    notes += life_notes
    radial = radial_stiffness(sol, op.speed)
    damping, damping_notes = bearing_damping(
        radial,
        float(sol.stiffness[0, 0]),
        case.analysis.bearing_damping,
        case.analysis.bearing_damping_coefficient,
    )
    notes += damping_notes
    details = EquilibriumDetails(
        race_control=control,
        ring_tilt=ring_tilt,
        held_dofs=sol.held_dofs,
        reaction_moment_n_m=(float(reaction[0]), float(reaction[1])),
        ring_displacement=RingDisplacement(
            axial_m=float(q[0]),
            x_m=float(q[1]),
            y_m=float(q[2]),
            tilt_x_rad=float(q[3]),
            tilt_y_rad=float(q[4]),
        ),
        stiffness_matrix=StiffnessMatrix(
            dofs=DOF_NAMES,
            units="rows F_a, F_x, F_y [N], M_x, M_y [N m]; columns per m or per rad",
            matrix=tuple(tuple(float(v) for v in row) for row in sol.stiffness),
        ),
        radial_stiffness=radial,
        inner_contact_angle_deg=tuple(math.degrees(v) for v in sol.inner_contact_angle),
        outer_contact_angle_deg=tuple(math.degrees(v) for v in sol.outer_contact_angle),
        balls=tuple(sol.ball_table()),
        newton_iterations=sol.iterations,
        life=life,
        bearing_damping=damping,
    )
    return EquilibriumResult(
        model=MODEL,
        title=case.title,
        frequencies=bearing_frequencies(bearing, op, mean_alpha),
        contact_angle=mean_alpha,
        time=np.zeros(1),
        # runout's axial reference is the rings axially centred; the solve counts from the
        # contact on one flank, half the free end play A sin α⁰ away
        displacement=np.array(
            [
                [q[1]],
                [q[2]],
                [q[0] + bearing.curvature_distance * math.sin(bearing.free_contact_angle)],
            ]
        ),
        components=(),
        # one instant of the perfect bearing: no record, so no runout figure (null, not 0)
        runout=Runout(None, None, None, None),
        details=details,
        notes=tuple(notes),
        solution=sol,
    )
