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
  cage (see :mod:`runout.geometry.kinematics`). Because the roller frame of eq. 7 is parallel to the
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
  ``BearingImperfections.element_phases_from_fixed_frame()``, case key ``[elements] phase_frame =
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
  otherwise the rigid contact is not unique and a :class:`~runout.base.errors.GeometryError` says
  so.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from runout.analysis.decompose import Candidate, Kinematic, fit_lines, split_runout
from runout.analysis.lines import Component, Runout, Source
from runout.analysis.result_details import HeldRollers, Iso492, RollerDetails
from runout.analysis.results import RunResult
from runout.geometry.bearing import BallBearing, Operation
from runout.geometry.imperfections import Harmonics
from runout.geometry.kinematics import bearing_frequencies
from runout.models._roller_kernels import (
    TOL_FEASIBLE,  # noqa: F401 - part of this module's documented constants
    TOL_MULTIPLIER,  # noqa: F401
)

# the model's parts, one import path for all (the tests and the docs use these names)
from runout.models._roller_setup import (
    ConstraintGeometry,
    _convexity_margin,  # noqa: F401 - used by the tests through this module
    _pack,  # noqa: F401 - used by the tests through this module
    _turns,
    absolute_spin_ratio,
    cage_ratio,
    elements_to_fixed_frame,
    geometry_from,
    rotation_angles,
)
from runout.models._roller_solve import (
    TOL_TOUCH,  # noqa: F401 - part of this module's documented constants
    OrderSweep,
    Solution,
    analytic_circular,
    ellipse_harmonics,
    ellipse_position_exact,
    ellipse_position_paper,
    inside_gap,
    order_sweep,
    pair_gap,
    solve,
    solve_many,
    support_function,
)

if TYPE_CHECKING:
    from runout.case.model import Case

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
TWO_PI = 2.0 * math.pi


# ============================================================================================
# the lines of the model and its entry point
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
    """Lines of the ring centre (:func:`runout.analysis.decompose.fit_lines`), the residual and the
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

    Parameters
    ----------
    case : Case
        A validated case with ``[analysis] model = "roller_constraint"``.

    Returns
    -------
    RunResult
        Centre of the shaft relative to the outer ring [m] at each rotation angle, the fitted
        lines, the runout figures [m] and :class:`~runout.analysis.result_details.RollerDetails`
        (rollers held, ISO 492 radial runout [m]).

    Notes
    -----
    Yu et al., "Prediction method for the radial runout of inner ring in cylindrical roller
    bearings", Math. Probl. Eng. (2017), §4-5, eq. 1-16 (seed 004), solved exactly as the
    module docstring describes.
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
    split = split_runout(time, disp, u_shaft, comps, f_rot, residual, axial=False)
    notes.extend(split.notes)
    pairs, counts = np.unique(np.sort(sol.pair, axis=1), axis=0, return_counts=True)
    touching = sol.touching.sum(axis=1)
    details = RollerDetails(
        horizontal_pp_m=float(np.ptp(sol.horizontal)),
        explained_fraction=explained,
        contacts=HeldRollers(
            rollers_touched=tuple(
                sorted({int(j) + 1 for j in np.flatnonzero(sol.touching.any(0))})
            ),
            pairs=tuple((int(a) + 1, int(b) + 1) for a, b in pairs),
            pair_counts=tuple(int(c) for c in counts),
            max_touching=int(touching.max()),
            fraction_three_or_more=float(np.mean(touching >= 3)),
        ),
        rotating_ring=geo.rotating_ring,
        radial_clearance_m=geo.radial_clearance,
        # what ISO 492 calls this radial runout of the assembled bearing's turning ring
        iso492=Iso492(
            quantity="Kia" if geo.rotating_ring == "inner" else "Kea",
            radial_runout_m=sol.runout,
        ),
        solution=sol,
    )
    if speed == 0.0:
        freqs = bearing_frequencies(
            case.bearing, Operation(case.operation.rotating_ring, speed=1.0)
        )
    else:
        freqs = bearing_frequencies(case.bearing, case.operation)
    u = u_shaft  # the load on the shaft
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
            axial_pp_m=None,  # a planar model: no axial degree of freedom
            rro_pp_m=split.runout.rro_pp_m,
            nrro_pp_m=split.runout.nrro_pp_m,
        ),
        measuring_direction=u,
        details=details,
        notes=tuple(notes),
    )
