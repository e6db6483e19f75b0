"""Benchmarks of the Jones–Harris equilibrium model (runout.models.equilibrium).

The reference is what an expert writes for a static load distribution (the ISO/TS 16281
approach of the open implementation github.com/minzhun/ISO16281, ``BallBearing.disp``): three
unknowns (radial displacement, axial displacement, tilt), one Hertz constant for the bearing
(ball-inner and ball-outer contacts in series at the free contact angle), per-ball loads
K δ^1.5 vectorised over the balls, and ``scipy.optimize.root`` with an analytic Jacobian. Of
MINPACK's two methods ``lm`` is the faster here (0.3 ms against 0.6 ms for ``hybr``, 11
against 23 function calls), so the reference uses it. It is timed from the bearing to the
displacements, its Hertz constant included (one exact Hertz solution, ~0.1 ms; our solve
also computes its Hertz constants).

Ours does more: five degrees of freedom, contact angles and Hertz constants per ball and
contact, the 5×5 stiffness matrix, and at speed the centrifugal and gyroscopic ball balance
of every ball. Targets (issue 16): the static solve within 2× of the reference, the solve at
the Kim spindle speed (7200 rpm) within 5× of the same static reference.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from scipy.optimize import root

from _harness import BenchResult, best_time
from runout.geometry.bearing import BallBearing, Operation
from runout.geometry.contact import ball_race_contacts
from runout.models.equilibrium import solve_equilibrium

#: Kim spindle bearing (seed 001 Table 1) and its fitted axial preload (VALIDATION.md).
KIM = BallBearing(10, 1.5875e-3, 9.1e-3, 0.529, 0.535, 5e-6)
PRELOAD = 60.68  # [N]
SPEED = 120.0  # [Hz], 7200 rpm


def reference_static(
    bearing: BallBearing, axial: float, radial: float, moment: float
) -> tuple[np.ndarray, int]:
    """Three-unknown static load distribution, vectorised over balls, analytic Jacobian.

    Unknowns u = (δ_r [m], δ_a [m], θ [rad]) with the radial load along ψ = 0 and the moment
    about the axis that tilts the ball at ψ = 0 axially. Ball j: groove-centre distance
    L_j = |(A sin α⁰ + δ_a + ℜ_i θ cos ψ_j, A cos α⁰ + δ_r cos ψ_j)|, load
    Q_j = K_n [L_j − A]₊^1.5 along that line. Returns u and the number of function calls.
    """
    kn = ball_race_contacts(bearing, bearing.free_contact_angle).combined_stiffness
    z = bearing.elements
    cpsi = np.cos(2.0 * math.pi * np.arange(z) / z)
    a = bearing.curvature_distance
    alpha0 = bearing.free_contact_angle
    rad = 0.5 * bearing.pitch_diameter + (
        bearing.inner_conformity - 0.5
    ) * bearing.element_diameter * math.cos(alpha0)
    s0, c0 = a * math.sin(alpha0), a * math.cos(alpha0)
    load = np.array([radial, axial, moment])
    scale = np.array([1.0, 1.0, 1.0 / rad])  # equations in N

    def fun(u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        s = s0 + u[1] + rad * u[2] * cpsi
        c = c0 + u[0] * cpsi
        length = np.hypot(s, c)
        d = np.maximum(length - a, 0.0)
        sq = np.sqrt(d)
        q = kn * d * sq
        dq = 1.5 * kn * sq
        sn, cs = s / length, c / length
        qs, qc = q * sn, q * cs  # axial and radial components
        # d(qs)/ds, d(qs)/dc = d(qc)/ds, d(qc)/dc
        q_l = q / length
        qs_s = dq * sn * sn + q_l * cs * cs
        qs_c = (dq - q_l) * sn * cs
        qc_c = dq * cs * cs + q_l * sn * sn
        f = np.array([(qc * cpsi).sum(), qs.sum(), rad * (qs * cpsi).sum()]) - load
        jac = np.array(
            [
                [(qc_c * cpsi * cpsi).sum(), (qs_c * cpsi).sum(), rad * (qs_c * cpsi * cpsi).sum()],
                [(qs_c * cpsi).sum(), qs_s.sum(), rad * (qs_s * cpsi).sum()],
                [
                    rad * (qs_c * cpsi * cpsi).sum(),
                    rad * (qs_s * cpsi).sum(),
                    rad * rad * (qs_s * cpsi * cpsi).sum(),
                ],
            ]
        )
        return f * scale, jac * scale[:, None]

    # start: every ball loaded by the axial load alone (the textbook estimate)
    d0 = (max(axial, radial, 1.0) / (z * kn * math.sin(max(alpha0, 0.1)))) ** (2.0 / 3.0)
    u0 = np.array([0.0, d0, 0.0])
    sol = root(fun, u0, jac=True, method="lm", options={"xtol": 1e-13})
    if not sol.success:
        raise RuntimeError(sol.message)
    return sol.x, int(sol.nfev)


def _ratio_result(name: str, ours: Callable[[], object], target: float, what: str) -> BenchResult:
    ours_s = best_time(ours, repeat=15)
    ref_s = best_time(lambda: reference_static(KIM, PRELOAD, 0.0, 0.0), repeat=15)
    return BenchResult(
        name=name,
        ours_s=ours_s,
        reference_s=ref_s,
        reference="3-unknown scipy root, lm (static)",
        target=f"{what} within {target:g}x of the static reference",
        met=bool(ours_s <= target * ref_s),
    )


def _check_agreement() -> None:
    """Ours at rest and the reference agree on the axial displacement (to the K(α) effect)."""
    ref, _ = reference_static(KIM, PRELOAD, 0.0, 0.0)
    sol = solve_equilibrium(KIM, Operation("inner", 0.0, axial_load=PRELOAD))
    # the reference keeps K at the free angle; ours evaluates it at the loaded angle
    if not math.isclose(sol.displacement[0], ref[1], rel_tol=0.02):
        raise AssertionError(f"axial displacement {sol.displacement[0]} vs reference {ref[1]}")


def bench_equilibrium_static() -> BenchResult:
    """Kim bearing at rest under its preload: our 5-DOF solve + stiffness vs the reference."""
    _check_agreement()
    op = Operation("inner", 0.0, axial_load=PRELOAD)
    return _ratio_result(
        "equilibrium: static solve (Kim, preload)",
        lambda: solve_equilibrium(KIM, op),
        2.0,
        "static 5-DOF solve + stiffness",
    )


def bench_equilibrium_at_speed() -> BenchResult:
    """Kim bearing at 7200 rpm (seed 001 Table 2): centrifugal and gyroscopic ball balance."""
    op = Operation("inner", SPEED, axial_load=PRELOAD)
    return _ratio_result(
        "equilibrium: solve at 7200 rpm (Kim)",
        lambda: solve_equilibrium(KIM, op),
        5.0,
        "solve at speed",
    )
