r"""Geometry of the rigid constraint model (seed 004, Yu et al. 2017): the parts as convex
profiles in the fixed frame, the rollers' frames and the packing for the compiled kernels.

Split out of :mod:`runout.models.roller_constraint` (which documents the model and re-exports
these names): :class:`ConstraintGeometry` and :func:`geometry_from` build the bearing of
seed 004 §4 (eq. 1-7) from a case; the kernels are in :mod:`runout.models._roller_kernels`,
the stable-position solve in :mod:`runout.models._roller_solve`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
from numpy.typing import NDArray

from runout.base.errors import GeometryError
from runout.geometry.bearing import BallBearing, Bearing, Operation, RollerBearing
from runout.geometry.imperfections import BearingImperfections, Harmonics
from runout.models._roller_kernels import Bodies

FloatArray = NDArray[np.float64]
TWO_PI = 2.0 * math.pi


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
    :meth:`runout.geometry.imperfections.BearingImperfections.element_phases_from_fixed_frame`.

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
    bearing: Bearing, imperfections: BearingImperfections, operation: Operation | None = None
) -> ConstraintGeometry:
    """Build the model geometry from a bearing, its imperfections and the operation.

    Parameters
    ----------
    bearing : RollerBearing or BallBearing
        A ball bearing is taken in its radial plane (contact angle 0, balls as circles of their
        diameter, raceways at the groove bottoms); see the module Notes.
    imperfections : BearingImperfections
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


def _check_convex(geo: ConstraintGeometry) -> float:
    """Refuse a part that is not convex (:func:`_convexity_margin` below 0.05); the least
    margin of the parts [-] (1 for round parts)."""
    parts: list[tuple[str, float, Harmonics]] = [
        ("inner raceway", geo.inner_radius, geo.inner),
        ("outer raceway", geo.outer_radius, geo.outer),
    ]
    parts += [
        (f"roller {j + 1}", float(geo.element_radii[j]), h) for j, h in enumerate(geo.elements)
    ]
    least = 1.0
    for name, radius, h in parts:
        if radius <= 0:
            raise GeometryError(name, f"radius {radius:.6g} m is not positive")
        margin = _convexity_margin(radius, h)
        if margin < 0.05:
            raise GeometryError(
                name,
                "profile is not convex (some harmonic has amplitude x order^2 comparable to the "
                "radius); the rigid contact model needs convex parts",
            )
        least = min(least, margin)
    return least


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
