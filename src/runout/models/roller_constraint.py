r"""Rigid geometric-constraint model of a cylindrical roller bearing (seed 004, Yu et al. 2017).

A runout measurement turns one ring slowly under a light measuring load; nothing deforms. At
each rotation angle the loaded ring sinks until the rollers stop it, and its centre is the
runout. This module computes that lowest position exactly.

Geometry (seed 004 §4, Fig. 1)
------------------------------
The fixed global frame has its origin at the centre of the fixed ring. Every part is a closed
curve, star-shaped about its centre, whose radius in the fixed frame is

.. math::

    \rho(\theta) = R_0 + \sum_m C_m \cos\bigl(m(\theta - \chi) + \varphi_m\bigr)

(eq. 1, 4-7) with :math:`R_0` the nominal radius plus half the diameter error (eq. 4) and
:math:`\chi` the angle the part has turned through: :math:`\chi = \alpha` for the inner ring
turned by α (eq. 5), 0 for the fixed outer ring (eq. 6) and :math:`\chi = -\gamma_1` for a roller
that has spun clockwise by γ₁ (eq. 7). Roller j orbits at :math:`\beta_j = 2\pi (j-1)/Z +
\gamma_2` (plus its pitch error), :math:`\gamma_2 = \tfrac12\alpha(1 - 2D_w/(d_i+d_e))` (eq. 3).

Contact (seed 004 eq. 8-16, done exactly)
-----------------------------------------
The paper samples the angle Δθ between a raceway point and the roller centre and takes the
smallest distance measured along lines through the roller centre. Here each part is a convex
body with support function :math:`h(\psi) = \max_\theta \rho(\theta)\cos(\theta - \psi)`, and

* roller B (centre :math:`d` relative to the inner ring's centre) against the inner raceway A:
  :math:`g = \max_\psi [\,n(\psi)\cdot d - h_A(\psi) - h_B(\psi + \pi)\,]`, the signed Euclidean
  distance between the two profiles (negative = interference depth);
* roller B inside the outer raceway E: :math:`G = \min_\psi [\,h_E(\psi) - h_B(\psi) -
  n(\psi)\cdot d\,]`, the signed distance from the roller to the raceway.

Both are solved by Newton's method in ψ (and in the profile angle for each support value), so
the contact point may lie off the line of centres, as it does on a wavy profile. The gradient
of the gap with respect to the centres is the contact normal n(ψ*) (envelope theorem).

Stable position (seed 004 §5, done as an optimisation)
------------------------------------------------------
1. Each roller settles radially onto the fixed ring (§5.1): on the outer raceway when the inner
   ring turns (the paper's case), on the inner raceway when the outer ring turns (Kea).
2. The loaded ring's centre c maximises :math:`u\cdot c` (minimum potential of the measuring
   load along the unit vector u) subject to no interference, :math:`C_j(c) \ge 0` for every
   roller. Because every :math:`C_j` bounds a convex body, the admissible pocket is bounded by
   arcs that bulge into it, so a linear potential is extremal at a vertex where two rollers
   touch; the stable vertex is the one whose contact normals straddle the load (KKT
   multipliers :math:`\lambda \ge 0` in :math:`u + \sum \lambda_j \nabla C_j = 0`). An active
   set walk from the two rollers either side of the load reaches it in one or two Newton
   solves; an exhaustive search over pairs is the fall-back. When the *outer* ring is loaded
   (Kea) the admissible set is an intersection of convex sets and the ring hangs like a hoop:
   it may rest on one roller alone, where the contact normal is along the load; that point is
   explicit and is tried whenever the walk leaves a roller. The paper's stable-contact
   criteria (§5.3: no interference; a contact on each side of the load line; the bisector of
   the outermost contacts closest to the load line) are what this optimum satisfies, and the
   tests use them as an oracle.

Notes
-----
* Seed 004 eq. 2 as extracted gives the roller spin as
  :math:`((d_i+d_e)^2 - 4D_w^2)/((d_i+d_e)D_w)\,\alpha`, four times the spin relative to the
  cage (see :mod:`runout.kinematics`). Because the roller frame of eq. 7 is parallel to the
  global frame (it translates, it does not turn with the cage), the angle needed there is the
  absolute spin. Pure rolling on both raceways gives
  :math:`\omega = [\Omega_o (d_m + D_w) - \Omega_i (d_m - D_w)]/(2 D_w)` per unit ring
  rotation (:math:`d_m = (d_i + d_e)/2`), i.e. :math:`\gamma_1 = (d_m - D_w)\alpha/(2D_w) =
  (d_m/D_w)\gamma_2` clockwise for the turning inner ring; that is what we use.
* Roller phases. The product reads element waviness in the **cage** frame (ψ = 0 along the
  outward radius through the element's centre, at its outer contact, at t = 0), as the linear
  and quasi-static models do; eq. 7's roller frame is parallel to the global frame at α = 0
  (the **fixed** frame). Both are fixed to the roller and differ by its position β_j at t = 0,
  so :func:`geometry_from` turns each roller's phases by −kβ_j (:func:`elements_to_fixed_frame`)
  and the kernel works in eq. 7's frame; the contact point then runs over the roller at the
  spin relative to the cage, (γ₂ + γ₁)/α = f_b/f_r, in both readings. "Every roller, 8 lobes,
  phase 0" thus shows the lobe's peak at every roller's outer contact at α = 0 (the paper's
  Fig. 11 reading, all rollers alike in the fixed frame, is
  ``Imperfections.element_phases_from_fixed_frame()``, case key ``[elements] phase_frame =
  "fixed"``: 2.003 µm over 540°; the cage reading, every roller alike relative to the cage,
  gives 2.551 µm).
* Seed 004 eq. 15 and 16 write the roundness terms with sin where eq. 5, 7, 10 and 11 use cos;
  taken literally the profile would change between two steps of the method. We use cos
  everywhere (eq. 5-7).
* The paper's quadrant rules for θ_B and θ_D (Fig. 2-3) are the direction from the roller
  centre to the raceway point; the support-function form above needs no case distinction.
* The paper's step searches (radial step for the rollers, x-y grid for the ring) are replaced
  by Newton solves; their tolerances no longer limit the accuracy (about 1e-15 m here).
* Ball bearings use the same rigid model in the radial plane: contact angle 0, balls as circles
  of their diameter on the groove-bottom diameters ``d_m ∓ (D + P_d/2)``; groove conformity,
  axial play and slant are ignored. This is a simplification for light-load radial runout.
* The profiles must be convex (every harmonic with :math:`C_m m^2` well below the radius);
  otherwise the rigid contact is not unique and a :class:`~runout.errors.GeometryError` says so.
"""

from __future__ import annotations

import csv
import dataclasses
import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

import numba
import numpy as np
from numpy.typing import NDArray

from runout.bearing import BallBearing, Bearing, Operation, RollerBearing
from runout.decompose import Candidate, Kinematic, fit_lines, split_runout
from runout.errors import ConvergenceError, GeometryError, NumericalError
from runout.imperfections import Harmonics, Imperfections, single_harmonic
from runout.kinematics import bearing_frequencies
from runout.models._roller_kernels import (
    _FAR_CONTACT,
    _NO_STABLE,
    _NO_STRADDLE,
    _NO_VERTEX,
    _SETTLE_FAIL,
    TOL_FEASIBLE,  # noqa: F401 - part of this module's documented constants
    TOL_MULTIPLIER,  # noqa: F401
    Bodies,
    _gap,
    _solve_all,
    _support,
)
from runout.results import Component, Runout, RunResult, Source

if TYPE_CHECKING:
    from runout.case import Case

__all__ = [
    "ConstraintGeometry",
    "OrderSweep",
    "Solution",
    "absolute_spin_ratio",
    "analytic_circular",
    "cage_ratio",
    "elements_to_fixed_frame",
    "ellipse_harmonics",
    "ellipse_position_exact",
    "ellipse_position_paper",
    "geometry_from",
    "inside_gap",
    "order_sweep",
    "pair_gap",
    "rotation_angles",
    "run",
    "solve",
    "solve_many",
    "support_function",
]

FloatArray = NDArray[np.float64]

#: Rollers closer than this to the loaded ring are reported as touching [m].
TOL_TOUCH = 1e-11
TWO_PI = 2.0 * math.pi

_STATUS_TEXT = {
    _NO_STRADDLE: "no roller on one side of the load line (too few rollers near the load zone)",
    _NO_VERTEX: "the two-contact Newton solve did not converge",
    _NO_STABLE: (
        "no stable position: every two-roller contact either interferes with another roller "
        "or does not straddle the load (rollers jam: is there radial clearance?)"
    ),
    _SETTLE_FAIL: "a roller could not be settled onto the fixed raceway (Newton did not converge)",
    _FAR_CONTACT: (
        "a roller more than 90 deg from the load zone touches the loaded ring: the clearance is "
        "too small for the part errors (the rigid measuring model does not apply)"
    ),
}


# ============================================================================================
# geometry
# ============================================================================================
@dataclass(frozen=True, eq=False)
class ConstraintGeometry:
    """Everything the rigid model needs, in SI.

    Attributes
    ----------
    n_elements : int
        Number of rollers (or balls) Z.
    element_diameter : float
        Nominal roller diameter D_w [m] (kinematics).
    pitch_diameter : float
        d_m = (d_i + d_e)/2 [m] (kinematics, eq. 3).
    inner_radius, outer_radius : float
        Raceway radii d_i/2, d_e/2 [m] (size errors of the raceways are order-0 harmonics).
    element_radii : ndarray, shape (Z,)
        D_w/2 + ΔD_j/2 for every roller [m] (eq. 4).
    inner, outer : Harmonics
        Raceway roundness in the ring frames (eq. 5-6) [m].
    elements : tuple of Harmonics
        Roller roundness in the **fixed** roller frames of eq. 7 (ψ = 0 along +x of the
        bearing at α = 0; the kernel's frame) [m]. :func:`geometry_from` converts the
        product's cage-frame input; :attr:`cage_frame_elements` is the inverse view.
    pitch_errors : ndarray, shape (Z,)
        Angular position errors of the rollers [rad].
    rotating_ring : {"inner", "outer"}
        The ring that turns and carries the measuring load.
    load_angle : float
        Direction of the measuring load from +x [rad] (default -π/2, downwards).
    spin_ratio : float or None
        Override of the roller rotation per unit ring rotation (counter-clockwise, fixed
        frame) [-]; None (default) uses pure rolling, :func:`absolute_spin_ratio`. Only for
        studying the paper's eq. 2 as printed (``-((d_i+d_e)^2 - 4D_w^2)/((d_i+d_e)D_w)``).
    roller_contacts : {"both_ends", "same_angle"}
        How a roller's profile meets the raceways: ``"both_ends"`` (default, physical) at the
        two ends of a diameter, so that odd lobe counts cancel across it; ``"same_angle"``
        reads the deviation at the outer contact's angle at the inner contact too, as seed 004
        computed Fig. 12 (VALIDATION.md). For reproducing the paper only.
    """

    n_elements: int
    element_diameter: float
    pitch_diameter: float
    inner_radius: float
    outer_radius: float
    element_radii: FloatArray
    inner: Harmonics
    outer: Harmonics
    elements: tuple[Harmonics, ...]
    pitch_errors: FloatArray
    rotating_ring: Literal["inner", "outer"] = "inner"
    load_angle: float = -0.5 * math.pi
    spin_ratio: float | None = None
    roller_contacts: Literal["both_ends", "same_angle"] = "both_ends"

    @property
    def radial_clearance(self) -> float:
        """Nominal diametral play d_e - d_i - 2 D_w with the mean roller [m]."""
        return 2.0 * (
            self.outer_radius - self.inner_radius - 2.0 * float(np.mean(self.element_radii))
        )

    @property
    def load_direction(self) -> FloatArray:
        """Unit vector u of the measuring load."""
        return np.array([math.cos(self.load_angle), math.sin(self.load_angle)])

    @property
    def element_positions(self) -> FloatArray:
        """Roller centres at α = 0, β_j = 2πj/Z + pitch error (j 0-based) [rad], shape (Z,)."""
        z = self.n_elements
        return np.asarray(2.0 * np.pi * np.arange(z) / z + self.pitch_errors, dtype=np.float64)

    @property
    def cage_frame_elements(self) -> tuple[Harmonics, ...]:
        """:attr:`elements` in the cage frames (ψ = 0 along roller j's outward radius at α = 0).

        ``elements[j].shifted(β_j)``; see :func:`elements_to_fixed_frame`.
        """
        return tuple(
            h.shifted(float(b)) for h, b in zip(self.elements, self.element_positions, strict=True)
        )

    def replace(self, **changes: Any) -> ConstraintGeometry:
        """Copy with some attributes replaced."""
        kw = {f: getattr(self, f) for f in self.__dataclass_fields__}
        kw.update(changes)
        return ConstraintGeometry(**kw)


def elements_to_fixed_frame(
    elements: Sequence[Harmonics], positions: Sequence[float] | FloatArray
) -> tuple[Harmonics, ...]:
    r"""Element waviness from the cage frames to the fixed frames of seed 004 eq. 7.

    The product reads element waviness :math:`r(\psi) = \sum a_k\cos(k\psi + \varphi_k)` in
    the **cage** frame: ψ counter-clockwise from the outward radius through the element's
    centre at t = 0, i.e. from its contact with the outer raceway (seed 001 eq. 13, seed 002
    eq. 25-26; the linear and quasi-static models). Seed 004 (Yu et al. 2017) eq. 7 writes the
    roller profile in a frame parallel to the bearing's, ψ from +x, turned by the roller's
    absolute spin χ = −γ₁. Both frames are fixed to the roller and turn with it; at t = 0 they
    differ by the roller's position β_j, so :math:`\psi_f = \psi_c + \beta_j` and
    :math:`\varphi^f_k = \varphi^c_k - k\beta_j` (``shifted(-β_j)``) at every later angle
    too, whatever the spin. Inverse of
    :meth:`runout.imperfections.Imperfections.element_phases_from_fixed_frame`.

    Parameters
    ----------
    elements : sequence of Harmonics
        Radius deviation of each element in its cage frame [m].
    positions : array_like, shape (Z,)
        β_j = 2πj/Z + pitch error of element j (0-based) at t = 0 [rad].

    Returns
    -------
    tuple of Harmonics
        The same profiles in the fixed frames [m].
    """
    return tuple(h.shifted(-float(b)) for h, b in zip(elements, positions, strict=True))


def geometry_from(
    bearing: Bearing, imperfections: Imperfections, operation: Operation | None = None
) -> ConstraintGeometry:
    """Build the model geometry from a bearing, its imperfections and the operation.

    Parameters
    ----------
    bearing : RollerBearing or BallBearing
        A ball bearing is taken in its radial plane (contact angle 0, balls as circles of their
        diameter, raceways at the groove bottoms); see the module Notes.
    imperfections : Imperfections
        ``inner``/``outer`` roundness (order 0 = radius error, i.e. Δd/2 of eq. 4),
        ``elements`` roundness in the cage frame (converted to the fixed frame of eq. 7 by
        :func:`elements_to_fixed_frame`), ``diameter_errors`` (ΔD_j of eq. 4) and
        ``pitch_errors``. Slant is not part of this planar model. Seed 004's own fixed-frame
        phases: pass ``imperfections.element_phases_from_fixed_frame()`` (case key
        ``[elements] phase_frame = "fixed"``).
    operation : Operation, optional
        Rotating ring and the measuring-load direction (``radial_load_direction``).

    Raises
    ------
    GeometryError
        Wrong number of elements, or a profile that is not convex.
    """
    op = operation if operation is not None else Operation()
    z = bearing.elements
    if imperfections.n_elements != z:
        raise GeometryError(
            "imperfections.elements",
            f"{imperfections.n_elements} element profiles for a bearing of {z} elements",
        )
    if isinstance(bearing, RollerBearing):
        d_i, d_e = bearing.inner_raceway_diameter, bearing.outer_raceway_diameter
    elif isinstance(bearing, BallBearing):
        d_i, d_e = bearing.inner_raceway_diameter, bearing.outer_raceway_diameter
    else:  # pragma: no cover - Bearing is a closed union
        raise GeometryError("bearing", f"unsupported bearing {type(bearing).__name__}")
    dw = bearing.element_diameter
    radii = 0.5 * dw + 0.5 * np.asarray(imperfections.diameter_errors, dtype=np.float64)
    pitch = np.asarray(imperfections.pitch_errors, dtype=np.float64)
    positions = 2.0 * np.pi * np.arange(z) / z + pitch
    geo = ConstraintGeometry(
        n_elements=z,
        element_diameter=dw,
        pitch_diameter=0.5 * (d_i + d_e),
        inner_radius=0.5 * d_i,
        outer_radius=0.5 * d_e,
        element_radii=radii,
        inner=imperfections.inner,
        outer=imperfections.outer,
        elements=elements_to_fixed_frame(imperfections.elements, positions),
        pitch_errors=pitch,
        rotating_ring=op.rotating_ring,
        load_angle=op.radial_load_direction,
    )
    _check_convex(geo)
    return geo


def _convexity_margin(radius: float, h: Harmonics) -> float:
    """min over θ of (ρ² + 2ρ'² - ρρ'') / ρ² (1 for a circle, <= 0 when not convex)."""
    if h.is_empty:
        return 1.0
    n = max(256, 16 * h.max_order)
    theta = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    if h.orders.size * n > 1_000_000:  # many harmonics: the kernel-backed evaluation
        r = radius + h.evaluate(theta)
        d1 = h.derivative().evaluate(theta)
        d2 = h.derivative().derivative().evaluate(theta)
    else:  # one cosine and sine table for ρ, ρ', ρ'' (no derived Harmonics objects)
        k = h.orders.astype(np.float64)[:, None]
        a = h.amplitudes[:, None]
        arg = k * theta[None, :] + h.phases[:, None]
        ac = a * np.cos(arg)
        r = radius + ac.sum(axis=0)
        d1 = -(a * k * np.sin(arg)).sum(axis=0)
        d2 = -(k * k * ac).sum(axis=0)
    return float(np.min((r * r + 2 * d1 * d1 - r * d2) / (r * r)))


def _check_convex(geo: ConstraintGeometry) -> None:
    parts: list[tuple[str, float, Harmonics]] = [
        ("inner raceway", geo.inner_radius, geo.inner),
        ("outer raceway", geo.outer_radius, geo.outer),
    ]
    parts += [
        (f"roller {j + 1}", float(geo.element_radii[j]), h) for j, h in enumerate(geo.elements)
    ]
    for name, radius, h in parts:
        if radius <= 0:
            raise GeometryError(name, f"radius {radius:.6g} m is not positive")
        if _convexity_margin(radius, h) < 0.05:
            raise GeometryError(
                name,
                "profile is not convex (some harmonic has amplitude x order^2 comparable to the "
                "radius); the rigid contact model needs convex parts",
            )


def cage_ratio(geo: ConstraintGeometry) -> float:
    """Cage angle per unit rotation of the turning ring, γ₂/α [-] (seed 004 eq. 3).

    ``(1 - D_w/d_m)/2`` for the inner ring turning, ``(1 + D_w/d_m)/2`` for the outer.
    """
    g = geo.element_diameter / geo.pitch_diameter
    return 0.5 * (1.0 - g) if geo.rotating_ring == "inner" else 0.5 * (1.0 + g)


def absolute_spin_ratio(geo: ConstraintGeometry) -> float:
    """Roller rotation in the fixed frame per unit ring rotation, counter-clockwise [-].

    .. math:: \\omega = \\frac{\\Omega_o (d_m + D_w) - \\Omega_i (d_m - D_w)}{2 D_w}

    Pure rolling on both raceways; for the inner ring turning this is
    ``-(d_m - D_w)/(2 D_w)`` = -γ₁/α (clockwise). See the module Notes on seed 004 eq. 2.
    """
    if geo.spin_ratio is not None:
        return geo.spin_ratio
    dm, dw = geo.pitch_diameter, geo.element_diameter
    if geo.rotating_ring == "inner":
        return -(dm - dw) / (2.0 * dw)
    return (dm + dw) / (2.0 * dw)


def rotation_angles(revolutions: float, samples: int) -> FloatArray:
    """Rotation angles of the turning ring: ``samples`` points from 0 to 2π·revolutions inclusive.

    540° in 2161 samples gives the paper's 0.25° steps (seed 004 §7).
    """
    if samples < 2 or not (revolutions > 0):
        raise GeometryError("analysis", "need revolutions > 0 and at least 2 samples")
    return np.linspace(0.0, 2.0 * math.pi * revolutions, samples)


# ============================================================================================
# Python API
# ============================================================================================
def _pack(geo: ConstraintGeometry) -> Bodies:
    """The bodies of ``geo`` packed for the kernels (:data:`_roller_kernels.Bodies`)."""
    bodies = [geo.inner, geo.outer, *geo.elements]
    radii = [geo.inner_radius, geo.outer_radius, *geo.element_radii]
    if geo.roller_contacts == "same_angle":
        # seed 004's reading: the inner contact sees the roller's deviation at the outer
        # contact's angle; bodies 2 + Z + j are roller j with its odd lobes turned by π
        # (the kernels take the inner contact from there when there are 2 + 2Z bodies)
        bodies += [_odd_turned(h) for h in geo.elements]
        radii += list(geo.element_radii)
    return _bodies(radii, bodies)


def _bodies(radii: Sequence[float], bodies: Sequence[Harmonics]) -> Bodies:
    """Base radii and harmonics packed as :data:`_roller_kernels.Bodies`."""
    r0 = np.array(radii, dtype=np.float64)
    sizes = np.array([len(h) for h in bodies], dtype=np.int64)
    off = np.zeros(len(bodies) + 1, dtype=np.int64)
    np.cumsum(sizes, out=off[1:])
    if off[-1]:
        k = np.concatenate([h.orders for h in bodies]).astype(np.float64)
        a = np.concatenate([h.amplitudes for h in bodies]).astype(np.float64)
        p = np.concatenate([h.phases for h in bodies]).astype(np.float64)
    else:
        k = a = p = np.zeros(1)
    return r0, np.ascontiguousarray(k), np.ascontiguousarray(a), np.ascontiguousarray(p), off


def _odd_turned(h: Harmonics) -> Harmonics:
    """The profile read half a turn away at its odd lobes: cos(m(θ+π)+φ) with φ + π for odd m."""
    odd = (h.orders % 2) == 1
    return Harmonics(h.orders, h.amplitudes, h.phases + np.where(odd, np.pi, 0.0))


def _turns(geo: ConstraintGeometry) -> tuple[float, float]:
    return (1.0, 0.0) if geo.rotating_ring == "inner" else (0.0, 1.0)


@dataclass(frozen=True, eq=False)
class Solution:
    """Stable positions of the loaded ring over a set of rotation angles.

    Attributes
    ----------
    geometry : ConstraintGeometry
        The model input.
    alpha : ndarray, shape (n,)
        Rotation angles of the turning ring [rad].
    centre : ndarray, shape (n, 2)
        Centre of the loaded (turning) ring relative to the fixed ring's centre [m].
    pair : ndarray of int, shape (n, 2)
        The two rollers (0-based) whose contacts hold the ring.
    multipliers : ndarray, shape (n, 2)
        Their KKT multipliers (contact forces per unit measuring load) [-].
    gaps : ndarray, shape (n, Z)
        Gap between every roller and the loaded ring at the stable position [m].
    roller_centres : ndarray, shape (n, Z, 2)
        Roller centres after settling on the fixed ring [m].
    """

    geometry: ConstraintGeometry
    alpha: FloatArray
    centre: FloatArray
    pair: NDArray[np.int64]
    multipliers: FloatArray
    gaps: FloatArray
    roller_centres: FloatArray

    @property
    def radial(self) -> FloatArray:
        """Displacement along the load direction u [m]."""
        return np.asarray(self.centre @ self.geometry.load_direction)

    @property
    def horizontal(self) -> FloatArray:
        """Displacement perpendicular to the load, along u rotated +90° [m]."""
        u = self.geometry.load_direction
        return np.asarray(self.centre @ np.array([-u[1], u[0]]))

    @property
    def touching(self) -> NDArray[np.bool_]:
        """Rollers within :data:`TOL_TOUCH` of the loaded ring, shape (n, Z)."""
        return np.asarray(self.gaps <= TOL_TOUCH)

    @property
    def runout(self) -> float:
        """max - min of :attr:`radial` [m]."""
        return float(np.ptp(self.radial))


def solve(geo: ConstraintGeometry, alpha: Sequence[float] | FloatArray) -> Solution:
    """Stable position of the loaded ring at each rotation angle.

    Parameters
    ----------
    geo : ConstraintGeometry
        Bearing, imperfections, turning ring and load direction.
    alpha : array_like, shape (n,)
        Rotation angles of the turning ring [rad], in the order they are visited (each solve
        starts from the previous position).

    Returns
    -------
    Solution

    Raises
    ------
    NumericalError
        No admissible stable position (e.g. rollers jam without clearance); the message names
        the rotation angle and the cause.
    ConvergenceError
        A Newton solve did not converge.
    """
    return _solve_one(geo, _angles(alpha))


def solve_many(
    geometries: Sequence[ConstraintGeometry], alpha: Sequence[float] | FloatArray
) -> list[Solution]:
    """:func:`solve` for several geometries over the same angles, on parallel threads.

    The compiled solver releases the GIL, so the independent solves run on up to
    :func:`numba.get_num_threads` threads; each solution is the one :func:`solve` gives
    (bit for bit, whatever the number of threads).

    Parameters
    ----------
    geometries : sequence of ConstraintGeometry
    alpha : array_like, shape (n,)
        Rotation angles of the turning ring [rad], shared by every solve.

    Returns
    -------
    list of Solution
        In the order of ``geometries``.

    Raises
    ------
    NumericalError, ConvergenceError
        As :func:`solve`, for the first geometry that fails.
    """
    al = _angles(alpha)
    geos = list(geometries)
    threads = min(len(geos), max(1, numba.get_num_threads()))
    if threads <= 1:
        return [_solve_one(g, al) for g in geos]
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(max_workers=threads) as pool:
        return list(pool.map(lambda g: _solve_one(g, al), geos))


def _angles(alpha: Sequence[float] | FloatArray) -> FloatArray:
    al = np.ascontiguousarray(np.asarray(alpha, dtype=np.float64).reshape(-1))
    if not np.all(np.isfinite(al)):
        raise GeometryError("alpha", "rotation angles must be finite")
    return al


def _solve_one(geo: ConstraintGeometry, al: FloatArray) -> Solution:
    """:func:`solve` on checked angles."""
    z = geo.n_elements
    bodies = _pack(geo)
    beta0 = geo.element_positions
    u = geo.load_direction
    c0 = 0.5 * max(geo.radial_clearance, 0.0) * u
    inner_turns, outer_turns = _turns(geo)
    n = al.size
    out_c = np.zeros((n, 2))
    out_pair = np.zeros((n, 2), dtype=np.int64)
    out_lam = np.zeros((n, 2))
    out_gap = np.zeros((n, z))
    out_rc = np.zeros((n, z, 2))
    out_status = np.zeros(n, dtype=np.int64)
    _solve_all(
        al,
        0 if geo.rotating_ring == "inner" else 1,
        bodies,
        np.ascontiguousarray(beta0),
        cage_ratio(geo),
        absolute_spin_ratio(geo),
        inner_turns,
        outer_turns,
        float(u[0]),
        float(u[1]),
        float(c0[0]),
        float(c0[1]),
        out_c,
        out_pair,
        out_lam,
        out_gap,
        out_rc,
        out_status,
    )
    bad = np.flatnonzero(out_status)
    if bad.size:
        i = int(bad[0])
        code = int(out_status[i])
        cls = ConvergenceError if code in (_NO_VERTEX, _SETTLE_FAIL) else NumericalError
        raise cls(
            f"roller_constraint: {_STATUS_TEXT.get(code, 'unknown failure')} at rotation angle "
            f"{math.degrees(al[i]):.6g} deg",
            instant=i,
            time=float(al[i]),
        )
    return Solution(geo, al, out_c, out_pair, out_lam, out_gap, out_rc)


# --------------------------------------------------------------------------------------------
# thin wrappers of the kernels (tests, verification)
# --------------------------------------------------------------------------------------------
def support_function(
    radius: float, harmonics: Harmonics, psi: float, turned: float = 0.0
) -> tuple[float, float, float]:
    """Support function of the profile ``radius + harmonics(θ - turned)`` in direction ψ.

    Returns
    -------
    h, dh_dpsi, radius_of_curvature : float
        :math:`h(\\psi) = \\max_\\theta \\rho(\\theta)\\cos(\\theta-\\psi)` [m], its derivative
        [m/rad] and the radius of curvature of the profile at the support point [m].
    """
    return _support(0, _bodies([radius], [harmonics]), float(turned), float(psi))


def _pair(
    ra: float, ha: Harmonics, rb: float, hb: Harmonics, turned_a: float, turned_b: float,
    centre_b: Sequence[float], inside: bool,
) -> tuple[float, float]:  # fmt: skip
    bodies = _bodies([ra, rb], [ha, hb])
    dx, dy = float(centre_b[0]), float(centre_b[1])
    g, psi, _ = _gap(0, float(turned_a), 1, float(turned_b), dx, dy, bodies, inside)
    return g, psi


def _cold(n: int) -> FloatArray:
    """Support points of ``n`` bodies to start from: δ = 0 (see ``_roller_kernels._support``)."""
    warm = np.zeros((n, 3))
    warm[:, 1] = 1.0
    return warm


def pair_gap(
    radius_a: float,
    harmonics_a: Harmonics,
    radius_b: float,
    harmonics_b: Harmonics,
    centre_b: Sequence[float],
    turned_a: float = 0.0,
    turned_b: float = 0.0,
) -> tuple[float, float]:
    """Signed closest distance between two separate convex profiles (eq. 13-16, exact).

    Body A is centred at the origin, body B at ``centre_b``; each profile is
    ``radius + harmonics(θ - turned)``. Returns the gap [m] (negative: interference depth)
    and the direction ψ of the contact normal from A towards B [rad].
    """
    return _pair(radius_a, harmonics_a, radius_b, harmonics_b, turned_a, turned_b, centre_b, False)


def inside_gap(
    radius_e: float,
    harmonics_e: Harmonics,
    radius_b: float,
    harmonics_b: Harmonics,
    centre_b: Sequence[float],
    turned_e: float = 0.0,
    turned_b: float = 0.0,
) -> tuple[float, float]:
    """Signed distance from profile B (centre ``centre_b``) to the enclosing profile E (eq. 8-11).

    Returns the gap [m] (negative: B sticks out of E) and the normal direction ψ [rad].
    """
    return _pair(radius_e, harmonics_e, radius_b, harmonics_b, turned_e, turned_b, centre_b, True)


# --------------------------------------------------------------------------------------------
# verification cases of seed 004 §6
# --------------------------------------------------------------------------------------------
def _straddling_pair(beta: FloatArray, w: FloatArray) -> tuple[int, int]:
    phi = np.arctan2(
        w[0] * np.sin(beta) - w[1] * np.cos(beta), w[0] * np.cos(beta) + w[1] * np.sin(beta)
    )
    left = np.flatnonzero(phi <= 0)
    right = np.flatnonzero(phi > 0)
    return int(left[np.argmax(phi[left])]), int(right[np.argmin(phi[right])])


def analytic_circular(
    inner_diameter: float,
    outer_diameter: float,
    roller_diameter: float,
    n_elements: int,
    alpha: FloatArray,
) -> FloatArray:
    """Inner-ring centre for perfect circular parts, seed 004 eq. 17, in closed form [m].

    The two rollers either side of the bottom sit at radius (d_e - D_w)/2; the ring centre is
    the intersection, on the bearing's side, of the two circles of radius (d_i + D_w)/2 about
    them (the paper solves eq. 17 by Newton-Raphson; the intersection is explicit).

    Returns
    -------
    ndarray, shape (n, 2)
    """
    al = np.asarray(alpha, dtype=np.float64).reshape(-1)
    dm = 0.5 * (inner_diameter + outer_diameter)
    gam2 = 0.5 * al * (1.0 - roller_diameter / dm)
    s = 0.5 * (outer_diameter - roller_diameter)
    rho = 0.5 * (inner_diameter + roller_diameter)
    out = np.empty((al.size, 2))
    w = np.array([0.0, -1.0])
    base = 2.0 * np.pi * np.arange(n_elements) / n_elements
    for i, g in enumerate(gam2):
        beta = base + g
        ja, jb = _straddling_pair(beta, w)
        pa = s * np.array([math.cos(beta[ja]), math.sin(beta[ja])])
        pb = s * np.array([math.cos(beta[jb]), math.sin(beta[jb])])
        mid = 0.5 * (pa + pb)
        half = 0.5 * float(np.linalg.norm(pb - pa))
        t = (pb - pa) / (2.0 * half)
        normal = np.array([-t[1], t[0]])
        if normal @ mid > 0:  # towards the bearing centre
            normal = -normal
        out[i] = mid + math.sqrt(rho * rho - half * half) * normal
    return out


def ellipse_harmonics(semi_major: float, semi_minor: float, n: int = 64) -> tuple[float, Harmonics]:
    """Mean radius and Fourier harmonics of the ellipse of seed 004 eq. 20-21 in its ring frame.

    The paper's polar radius :math:`ab/\\sqrt{(a\\cos\\theta)^2 + (b\\sin\\theta)^2}` has the
    major axis along the ring's y axis. Its coefficients fall by about ((a-b)/(a+b)) per
    order, so ``n`` samples give it to rounding error.
    """
    a, b = semi_major, semi_minor
    theta = 2.0 * np.pi * np.arange(n) / n
    r = a * b / np.sqrt((a * np.cos(theta)) ** 2 + (b * np.sin(theta)) ** 2)
    c = np.fft.rfft(r) / n
    mean = float(c[0].real)
    orders = np.arange(1, n // 2)
    coef = 2.0 * c[1 : n // 2]
    keep = np.abs(coef) > 1e-24
    return mean, Harmonics.from_complex(orders[keep], coef[keep])


def _roller_pair_positions(
    inner_diameter: float,
    outer_diameter: float,
    roller_diameter: float,
    n_elements: int,
    alpha: float,
) -> tuple[FloatArray, FloatArray]:
    dm = 0.5 * (inner_diameter + outer_diameter)
    beta = 2.0 * np.pi * np.arange(n_elements) / n_elements + 0.5 * alpha * (
        1.0 - roller_diameter / dm
    )
    ja, jb = _straddling_pair(beta, np.array([0.0, -1.0]))
    s = 0.5 * (outer_diameter - roller_diameter)
    pa = s * np.array([math.cos(beta[ja]), math.sin(beta[ja])])
    pb = s * np.array([math.cos(beta[jb]), math.sin(beta[jb])])
    return pa, pb


def _newton2(fun: Any, x0: FloatArray, what: str) -> FloatArray:
    x = np.array(x0, dtype=np.float64)
    for _ in range(60):
        f, jac = fun(x)
        dx = np.linalg.solve(jac, -f)
        x = x + dx
        if np.linalg.norm(dx) <= 1e-16:
            return x
    if np.linalg.norm(dx) <= 1e-14:
        return x
    raise ConvergenceError(f"{what}: Newton-Raphson did not converge")


def ellipse_position_paper(
    semi_major: float,
    semi_minor: float,
    outer_diameter: float,
    roller_diameter: float,
    n_elements: int,
    alpha: float,
    inner_diameter: float | None = None,
) -> FloatArray:
    """Ring centre from seed 004 eq. 18-21: radius of the ellipse along the line of centres.

    ``inner_diameter`` only sets the cage ratio of eq. 3 (default 2 × semi-major).
    """
    a, b = semi_major, semi_minor
    d_i = 2.0 * a if inner_diameter is None else inner_diameter
    pa, pb = _roller_pair_positions(d_i, outer_diameter, roller_diameter, n_elements, alpha)
    rr = 0.5 * roller_diameter

    def polar(t: float) -> tuple[float, float]:
        x = t - alpha
        q = (a * math.cos(x)) ** 2 + (b * math.sin(x)) ** 2
        r = a * b / math.sqrt(q)
        dq = (b * b - a * a) * math.sin(2 * x)
        return r, -0.5 * r * dq / q

    def fun(c: FloatArray) -> tuple[FloatArray, FloatArray]:
        f = np.empty(2)
        jac = np.empty((2, 2))
        for i, pj in enumerate((pa, pb)):
            d = pj - c
            dist = float(np.linalg.norm(d))
            theta = math.atan2(-d[1], -d[0]) + math.pi  # direction from ring centre to roller
            r, dr = polar(theta)
            f[i] = dist - r - rr
            # d dist/dc = -d/|d|; d theta/dc = (d_y, -d_x)/|d|^2 ... chain rule
            dtheta = np.array([d[1], -d[0]]) / dist**2
            jac[i] = -d / dist - dr * dtheta
        return f, jac

    c0 = np.array([0.0, -0.5 * (outer_diameter - 2 * a - 2 * roller_diameter) / 2.0])
    return _newton2(fun, c0, "ellipse eq. 18-21")


def ellipse_position_exact(
    semi_major: float,
    semi_minor: float,
    outer_diameter: float,
    roller_diameter: float,
    n_elements: int,
    alpha: float,
    inner_diameter: float | None = None,
) -> FloatArray:
    """Ring centre for the elliptic inner raceway with the exact closest distance.

    Each roller centre lies at distance D_w/2 from the ellipse (on its parallel curve); the
    closest ellipse point is found on the parametric ellipse (b cos t, a sin t), turned by α,
    by Newton's method on (q(t) - P)·q'(t) = 0, independently of the support-function code.
    """
    a, b = semi_major, semi_minor
    d_i = 2.0 * a if inner_diameter is None else inner_diameter
    pa, pb = _roller_pair_positions(d_i, outer_diameter, roller_diameter, n_elements, alpha)
    rr = 0.5 * roller_diameter
    ca, sa = math.cos(alpha), math.sin(alpha)
    rot = np.array([[ca, -sa], [sa, ca]])

    def closest(c: FloatArray, pj: FloatArray) -> tuple[float, FloatArray]:
        loc = rot.T @ (pj - c)  # roller centre in the ring frame
        t = math.atan2(loc[1] / a, loc[0] / b)
        for _ in range(60):
            q = np.array([b * math.cos(t), a * math.sin(t)])
            q1 = np.array([-b * math.sin(t), a * math.cos(t)])
            q2 = -q
            f = (q - loc) @ q1
            fp = q1 @ q1 + (q - loc) @ q2
            dt = f / fp
            t -= dt
            if abs(dt) < 1e-16:
                break
        q = np.array([b * math.cos(t), a * math.sin(t)])
        v = loc - q
        dist = float(np.linalg.norm(v))
        return dist, rot @ (v / dist)

    def fun(c: FloatArray) -> tuple[FloatArray, FloatArray]:
        f = np.empty(2)
        jac = np.empty((2, 2))
        for i, pj in enumerate((pa, pb)):
            dist, nrm = closest(c, pj)
            f[i] = dist - rr
            jac[i] = -nrm
        return f, jac

    c0 = np.array([0.0, -0.5 * (outer_diameter - 2 * a - 2 * roller_diameter) / 2.0])
    return _newton2(fun, c0, "exact ellipse contact")


# ============================================================================================
# order sweep (runout against the harmonic order of one part)
# ============================================================================================
@dataclass(frozen=True, eq=False)
class OrderSweep:
    """Runout against the harmonic order of one part's roundness error.

    Attributes
    ----------
    orders : ndarray of int, shape (m,)
        Harmonic orders swept.
    parts : tuple of str
        Parts ("inner", "outer", "roller"); "roller" puts the harmonic on every roller.
    amplitude : float
        Zero-to-peak amplitude used for every run [m].
    runout : ndarray, shape (len(parts), m)
        Radial runout p-p along the load [m], perfect-bearing runout included.
    baseline : float
        Runout of the same bearing with perfect parts (roller passage alone) [m].
    n_elements : int
        Z, to read the table against multiples of the roller number.
    """

    orders: NDArray[np.int64]
    parts: tuple[str, ...]
    amplitude: float
    runout: FloatArray
    baseline: float
    n_elements: int

    def rows(self) -> list[dict[str, float | int]]:
        """One row per order: ``order``, ``order_over_z`` and ``<part>_pp_m`` for each part."""
        out: list[dict[str, float | int]] = []
        for i, kk in enumerate(self.orders):
            row: dict[str, float | int] = {
                "order": int(kk),
                "order_over_z": float(kk) / self.n_elements,
            }
            for j, part in enumerate(self.parts):
                row[f"{part}_pp_m"] = float(self.runout[j, i])
            out.append(row)
        return out

    def write_csv(self, path: Path) -> Path:
        """Write the table (header states the amplitude and the baseline)."""
        with path.open("w", newline="") as fh:
            fh.write(
                f"# radial runout p-p [m] with one harmonic of {self.amplitude:.6g} m "
                f"(zero-to-peak) on one part; perfect bearing: {self.baseline:.6g} m; "
                f"Z = {self.n_elements}\n"
            )
            w = csv.writer(fh)
            w.writerow(["order", "order_over_z", *(f"{p}_pp_m" for p in self.parts)])
            for row in self.rows():
                w.writerow([f"{v:.10g}" if isinstance(v, float) else v for v in row.values()])
        return path


def order_sweep(
    geo: ConstraintGeometry,
    alpha: FloatArray,
    orders: Sequence[int] | None = None,
    amplitude: float = 1e-6,
    parts: Sequence[str] = ("inner", "outer", "roller"),
) -> OrderSweep:
    """Runout for a single harmonic of each order on each part in turn (others perfect).

    Parameters
    ----------
    geo : ConstraintGeometry
        The bearing; its own imperfections are discarded (the sweep starts from perfect parts,
        keeping the roller size and pitch errors out as well).
    alpha : ndarray
        Rotation angles [rad].
    orders : sequence of int, optional
        Default 2 … 3Z.
    amplitude : float
        Zero-to-peak amplitude of the harmonic [m].
    parts : sequence of {"inner", "outer", "roller"}
        A "roller" harmonic is the same on every roller in its cage frame (phase 0 at its outer
        contact at α = 0), like a ``[[waviness]] part = "roller"`` entry of a case.
    """
    z = geo.n_elements
    ks = np.arange(2, 3 * z + 1) if orders is None else np.asarray(orders, dtype=np.int64)
    perfect = geo.replace(
        inner=Harmonics.empty(),
        outer=Harmonics.empty(),
        elements=(Harmonics.empty(),) * z,
        element_radii=np.full(z, 0.5 * geo.element_diameter),
        pitch_errors=np.zeros(z),
    )
    geos = [perfect]
    for part in parts:
        for kk in ks:
            h = single_harmonic(int(kk), amplitude)
            if part == "inner":
                g = perfect.replace(inner=h)
            elif part == "outer":
                g = perfect.replace(outer=h)
            elif part in ("roller", "element", "ball"):
                g = perfect.replace(
                    elements=elements_to_fixed_frame((h,) * z, perfect.element_positions)
                )
            else:
                raise GeometryError("order_sweep.parts", f"unknown part {part!r}")
            geos.append(g)
    runouts = np.array([sol.runout for sol in solve_many(geos, alpha)])
    table = runouts[1:].reshape(len(parts), ks.size)
    return OrderSweep(ks, tuple(parts), amplitude, table, float(runouts[0]), z)


# ============================================================================================
# the model entry point
# ============================================================================================
def _candidate_lines(geo: ConstraintGeometry) -> list[Candidate]:
    """The lines the rigid model produces, with their sources, in orders (f_r = 1 Hz).

    * Roller passage through the load zone, m Z f_c.
    * A harmonic of k lobes on the **turning** ring is read where the load holds the ring, a
      direction fixed in space: k f_r, with the roller-passage sidebands k f_r ± m Z f_c (the
      lowest stable position switches between roller pairs Z f_c times a turn); and k |f_r -
      f_c|, the rate at which its lobes pass the rollers.
    * A harmonic of the fixed ring: k |f_c| (lobes passing the rollers) and the sidebands.
    * Roller harmonics: k f_b (spin relative to the cage) and the sidebands.
    * Rollers that differ relative to the cage (size, pitch, profile): m f_c.
    """
    z = geo.n_elements
    c = cage_ratio(geo)
    inner_turns, outer_turns = _turns(geo)
    spin_rel = abs(absolute_spin_ratio(geo) - c)
    passage = z * abs(c)
    out: list[Candidate] = []

    def add(order: float, src: Source, optional: bool = False) -> None:
        if order > 1e-9:
            out.append(Candidate(order, "radial", src, optional=optional))

    for m in (1, 2, 3):
        add(m * passage, Source("load", None, None, f"roller passage {m}x", f"{m} Z f_c"))
    rings = [("inner", geo.inner, inner_turns), ("outer", geo.outer, outer_turns)]
    for name, h, turns in rings:
        sym = "f_i" if name == "inner" else "f_o"
        for kk in h.orders:
            kk = int(kk)
            if kk == 0:
                continue
            rel = kk * abs(turns - c)
            add(rel, Source(name, None, kk, f"k |{sym} - f_c|", f"{kk} |{sym} - f_c|"))
            for sign, word in ((1, "+"), (-1, "-")):
                term = f"k |{sym} - f_c| {word} Z f_c"
                add(abs(rel + sign * passage), Source(name, None, kk, term, term), True)
            if turns != 0.0:
                add(kk * abs(turns), Source(name, None, kk, f"k {sym}", f"{kk} {sym}"))
                for m in (1, 2):
                    for sign, word in ((1, "+"), (-1, "-")):
                        term = f"k {sym} {word} {m} Z f_c"
                        freq = abs(kk * abs(turns) + sign * m * passage)
                        add(freq, Source(name, None, kk, term, term), m > 1)
    roller_orders: set[int] = set()
    for h in geo.elements:
        roller_orders.update(int(kk) for kk in h.orders if kk > 0)
    for kk in sorted(roller_orders):
        add(kk * spin_rel, Source("roller", None, kk, "k f_b", f"{kk} f_b"))
        for sign, word in ((1, "+"), (-1, "-")):
            term = f"k f_b {word} Z f_c"
            add(abs(kk * spin_rel + sign * passage), Source("roller", None, kk, term, term), True)
    # rollers that differ relative to the cage (identical fixed-frame profiles do, unless
    # their orders are multiples of Z)
    uneven = (
        np.ptp(geo.element_radii) > 0
        or np.any(geo.pitch_errors)
        or not _same_profiles(geo.cage_frame_elements)
    )
    if uneven:
        for m in (1, 2, 3):
            src = Source("cage", None, None, f"{m}x: uneven rollers", f"{m} f_c")
            add(m * abs(c), src, m > 1)
    return out


def _same_profiles(elements: Sequence[Harmonics]) -> bool:
    """All profiles equal up to phase round-off (1e-9 rad after a frame change)."""
    first = elements[0]
    for h in elements[1:]:
        if not (
            np.array_equal(h.orders, first.orders)
            and np.allclose(h.amplitudes, first.amplitudes, rtol=1e-12, atol=0.0)
        ):
            return False
        dphi = np.angle(np.exp(1j * (h.phases - first.phases)))
        if np.any(np.abs(dphi) > 1e-9):
            return False
    return True


def _components(
    sol: Solution, rotation_hz: float, notes: list[str]
) -> tuple[tuple[Component, ...], FloatArray | None, float]:
    """Lines of the ring centre (:func:`runout.decompose.fit_lines`), the residual and the
    explained fraction of the variance."""
    geo = sol.geometry
    rev = sol.alpha / (2.0 * math.pi)
    span = float(rev[-1] - rev[0])
    if span <= 0 or rev.size < 8:
        return (), None, 0.0
    time = rev / rotation_hz
    candidates = [
        replace(c, frequency_hz=c.frequency_hz * rotation_hz) for c in _candidate_lines(geo)
    ]
    c = cage_ratio(geo)
    wavy = any(np.any(h.orders > 0) for h in geo.elements)
    turning = geo.inner if geo.rotating_ring == "inner" else geo.outer
    synchronous = bool(np.any((turning.orders > 0) & (turning.amplitudes > 0.0)))
    kin = Kinematic(
        rotation_hz, c * rotation_hz, abs(absolute_spin_ratio(geo) - c) * rotation_hz,
        geo.n_elements, bool(wavy), synchronous,
    )  # fmt: skip
    signal = np.vstack([sol.centre[:, 0], sol.centre[:, 1], np.zeros(rev.size)])
    fit = fit_lines(time, signal, candidates, rotation_hz, directions=("x", "y"), kinematic=kin)
    notes.extend(fit.notes)
    residual = fit.residual if synchronous else None  # nothing turns with the ring: no RRO
    return fit.components, residual, fit.explained_fraction


def run(case: Case) -> RunResult:
    """Run the rigid constraint model on a case (``[analysis] model = "roller_constraint"``).

    The turning ring is the loaded one; its centre relative to the fixed ring is reported at
    ``analysis.samples`` rotation angles from 0 to ``analysis.revolutions`` turns (both ends
    included). ``runout.radial_pp_m`` is max - min along the measuring-load direction
    (``operation.radial_load_direction``, default -y); ``horizontal_pp_m`` across it.
    """
    notes: list[str] = []
    geo = geometry_from(case.bearing, case.imperfections, case.operation)
    # runout's frame: the load key is the load on the shaft, the displacement the shaft's
    # centre relative to the outer ring's. A turning outer ring is the loaded one here: the same
    # relative push is the outer ring loaded the opposite way, and its centre relative to the
    # inner ring is minus the reported displacement.
    shaft = 1.0
    if geo.rotating_ring == "outer":
        shaft = -1.0
        geo = dataclasses.replace(geo, load_angle=geo.load_angle + math.pi)
        notes.append(
            "outer ring turning and loaded: the measuring load acts on it opposite to "
            "radial_load_direction (the key gives the load on the shaft); the displacement is "
            "the shaft relative to the outer ring, as in every model"
        )
    if isinstance(case.bearing, BallBearing):
        notes.append(
            "ball bearing taken in its radial plane: contact angle 0, balls as circles of their "
            "diameter on the groove-bottom diameters; conformity, axial play and slant ignored"
        )
    if case.imperfections.slant is not None:
        notes.append("slant is not part of the planar constraint model and was ignored")
    if case.operation.radial_load == 0.0:
        notes.append(
            "no radial load given: a light measuring load along radial_load_direction is assumed "
            "(the rigid model does not depend on its size)"
        )
    alpha = rotation_angles(case.analysis.revolutions, case.analysis.samples)
    sol = solve(geo, alpha)
    speed = abs(case.operation.speed)
    if speed == 0.0:
        notes.append("speed is 0: time is given in revolutions (1 rev/s assumed)")
    f_rot = speed if speed > 0 else 1.0
    time = alpha / (2.0 * math.pi * f_rot)
    disp = np.vstack([shaft * sol.centre[:, 0], shaft * sol.centre[:, 1], np.zeros(alpha.size)])
    comps, residual, explained = _components(sol, f_rot, notes)
    if shaft < 0.0:
        comps = tuple(
            dataclasses.replace(c, phase_rad=float(math.remainder(c.phase_rad + math.pi, TWO_PI)))
            for c in comps
        )
        residual = None if residual is None else -residual
    u_shaft = shaft * geo.load_direction
    split = split_runout(time, disp, u_shaft, comps, f_rot, residual)
    notes.extend(split.notes)
    pairs, counts = np.unique(np.sort(sol.pair, axis=1), axis=0, return_counts=True)
    touching = sol.touching.sum(axis=1)
    extras: dict[str, Any] = {
        "horizontal_pp_m": float(np.ptp(sol.horizontal)),
        "explained_fraction": explained,
        "contacts": {
            "rollers_touched": sorted({int(j) + 1 for j in np.flatnonzero(sol.touching.any(0))}),
            "pairs": [[int(a) + 1, int(b) + 1] for a, b in pairs],
            "pair_counts": [int(c) for c in counts],
            "max_touching": int(touching.max()),
            "fraction_three_or_more": float(np.mean(touching >= 3)),
        },
        "rotating_ring": geo.rotating_ring,
        "radial_clearance_m": geo.radial_clearance,
        # what ISO 492 calls this radial runout of the assembled bearing's turning ring
        "iso492": {
            "quantity": "Kia" if geo.rotating_ring == "inner" else "Kea",
            "radial_runout_m": sol.runout,
        },
    }
    if speed == 0.0:
        freqs = bearing_frequencies(
            case.bearing, Operation(case.operation.rotating_ring, speed=1.0)
        )
    else:
        freqs = bearing_frequencies(case.bearing, case.operation)
    u = u_shaft  # the load on the shaft

    def writer(directory: Path) -> list[Path]:
        return write_extras(sol, directory, case.analysis.revolutions)

    return RunResult(
        model="roller_constraint",
        title=case.title,
        frequencies=freqs,
        contact_angle=0.0,
        time=time,
        displacement=disp,
        components=comps,
        runout=Runout(
            radial_pp_m=sol.runout,
            axial_pp_m=0.0,
            rro_pp_m=split.runout.rro_pp_m,
            nrro_pp_m=split.runout.nrro_pp_m,
        ),
        measuring_direction=u,
        extras=extras,
        notes=tuple(notes),
        writers=(writer,),
    )


def write_extras(sol: Solution, directory: Path, revolutions: float) -> list[Path]:
    """Write ``contacts.csv``, ``order_sweep.csv`` and the model's plots into ``directory``.

    The order sweep uses one revolution of the turning ring at the run's angular step (at most
    720 angles) and 1 µm on each part, orders 2 … 3Z.
    """
    from runout import plotting

    directory.mkdir(parents=True, exist_ok=True)
    written: list[Path] = []
    path = directory / "contacts.csv"
    z = sol.geometry.n_elements
    with path.open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(
            ["angle_deg", "radial_m", "horizontal_m", "roller_a", "roller_b", "lambda_a",
             "lambda_b", *(f"gap_{j + 1}_m" for j in range(z))]
        )  # fmt: skip
        for i in range(sol.alpha.size):
            w.writerow(
                [
                    f"{math.degrees(sol.alpha[i]):.6g}",
                    f"{sol.radial[i]:.12g}",
                    f"{sol.horizontal[i]:.12g}",
                    int(sol.pair[i, 0]) + 1,
                    int(sol.pair[i, 1]) + 1,
                    f"{sol.multipliers[i, 0]:.6g}",
                    f"{sol.multipliers[i, 1]:.6g}",
                    *(f"{g:.6g}" for g in sol.gaps[i]),
                ]
            )
    written.append(path)
    step = float(np.median(np.diff(sol.alpha))) if sol.alpha.size > 1 else math.radians(0.25)
    n1 = int(min(720, max(64, round(2.0 * math.pi / step)))) + 1
    sweep = order_sweep(sol.geometry, rotation_angles(1.0, n1))
    written.append(sweep.write_csv(directory / "order_sweep.csv"))
    angle_deg = np.degrees(sol.alpha)
    written.append(
        plotting.save_figure(
            plotting.plot_constraint_displacement(angle_deg, sol.radial, sol.horizontal),
            directory / "displacement.png",
        )
    )
    written.append(
        plotting.save_figure(
            plotting.plot_contact_pattern(angle_deg, sol.touching, sol.pair),
            directory / "contact_pattern.png",
        )
    )
    written.append(
        plotting.save_figure(
            plotting.plot_order_sweep(
                sweep.orders, sweep.runout, sweep.parts, sweep.baseline, sweep.n_elements
            ),
            directory / "order_sweep.png",
        )
    )
    return written
