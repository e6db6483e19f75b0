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
  :func:`runout.geometry.contact.ball_race_contacts` (``contact_law = "exact"``) or from the paper's
  δ* table (``"delta_star_table"``,
  :func:`runout.geometry.contact.stiffness_from_delta_star_table`), at the preloaded contact
  angle.
* Eq. 2.21 is the zero-clearance case of Harris's load-angle relation; we solve the full
  relation with clearance, :math:`F_a = Z K_n (A\cos\alpha^0/\cos\alpha_p - A)^{3/2}
  \sin\alpha_p`, with K_n of the chosen law at α_p (for the exact law this is
  :func:`runout.geometry.loading.axial_loading`). Then :math:`z_p = A\cos\alpha^0\tan\alpha_p`.
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

import math
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

from runout.analysis.decompose import Candidate, Direction, fit_lines, split_runout
from runout.analysis.lines import Source
from runout.analysis.result_details import DynamicDetails
from runout.analysis.results import RunResult
from runout.base.display import format_resolution
from runout.geometry.kinematics import bearing_frequencies
from runout.models._dynamic_integration import (  # noqa: F401 - the model's names in one place
    MAX_BLOCK_REVOLUTIONS,
    MAX_STEPS,
    SETTLE_TOL,
    STEPS_PER_PERIOD,
    Integration,
    IntegrationPlan,
    _raise,
    choose_step,
    integrate,
)
from runout.models._dynamic_integration import (
    plan_integration as plan_integration,  # runout.runner.checks plans with it
)
from runout.models._dynamic_kernels import (  # noqa: F401 - re-exported with the kernels
    FORCE_RTOL,
    NEWTON_RTOL,
    NOT_CONVERGED,
    OK,
    P_TOL,
    P_WC,
    _contact,
    _deviations,
    newmark_kernel,
    static_kernel,
)
from runout.models._dynamic_setup import (  # noqa: F401 - the model's names in one place
    MAX_ITER,
    TWO_PI,
    ContactLaw,
    DynamicSetup,
    _deviations_np,
    _dyn,
    _law_stiffness,
    contact_forces,
    contact_stiffness,
    energy,
    external_force,
    linearised_natural_frequencies,
    newmark_reference,
    preloaded_contact_angle,
    rhs_first_order,
    setup,
    static_equilibrium,
    static_reference,
)
from runout.models._dynamic_signal import SPALL_STEPS, acceleration_signal, spall_entry_time
from runout.models._quasi_static import (
    decomposition_kinematic,
    predicted_lines,
)

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
]

MODEL = "dynamic"
#: Lines below this fraction of the reference approach are solver noise (1000 × tolerance).
NOISE = 1e-9


# --------------------------------------------------------------------------------------------
# lines and result
# --------------------------------------------------------------------------------------------
def ball_passage_frequency(st: DynamicSetup) -> float:
    """Rate at which balls pass the load zone, fixed in space, Z |f_c| [Hz].

    Seed 003 eq. 2.20 writes it for a stationary outer ring, where it is also the rate at which
    balls pass a point of the outer ring; with the outer ring turning the stiffness still varies
    with the balls' positions relative to the (fixed) load.

    Parameters
    ----------
    st : DynamicSetup
        The model's setup (:func:`setup`); gives Z and the cage frequency f_c [Hz].

    Returns
    -------
    float
        Ball passage frequency Z |f_c| [Hz].

    Notes
    -----
    Purohit & Purohit, "Dynamic analysis of ball bearings with effect of preload and number
    of balls" (2006), eq. 2.20 (seed 003).
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

    Parameters
    ----------
    st : DynamicSetup
        The model's setup (:func:`setup`): kinematics [Hz], degrees of freedom, unbalance
        force [N] and preloaded contact angle [rad].
    imperfections : BearingImperfections
        The case's imperfections (raceway and ball waviness, size and pitch errors).
    natural : ndarray
        Linearised natural frequencies [Hz].
    loaded : bool, optional
        A radial load is applied: adds the load-zone lines of the imperfections. Default False.

    Returns
    -------
    list of Candidate
        Candidate lines, frequencies [Hz], each with its source.

    Notes
    -----
    Ball passage lines after Purohit & Purohit, "Dynamic analysis of ball bearings with effect
    of preload and number of balls" (2006), eq. 2.20 (seed 003).
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
        labelled lines, runout figures; details
        (:class:`~runout.analysis.result_details.DynamicDetails`) ``natural_frequencies_hz`` and the
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
    from runout.case.limits import case_budget

    time_step = dyn.time_step
    entry = spall_entry_time(st)
    if entry is not None:
        # the step resolves a ball's entry into every spall in SPALL_STEPS steps at least
        finest = entry / SPALL_STEPS
        if time_step is None:
            q0 = static_equilibrium(st, np.array([0.0]))[0]
            auto = 1.0 / (STEPS_PER_PERIOD * linearised_natural_frequencies(st, q0).max())
            if finest < auto:
                time_step = finest
                notes.append(
                    f"Newmark step at most {finest * 1e6:.4g} us: {SPALL_STEPS} steps over a "
                    f"ball's entry into a spall ({entry * 1e6:.4g} us)"
                )
        elif time_step > finest:
            notes.append(
                f"dynamics.time_step {time_step * 1e6:.4g} us resolves a ball's entry into a "
                f"spall ({entry * 1e6:.4g} us) in {entry / time_step:.3g} steps, fewer than "
                f"{SPALL_STEPS}: the impacts are under-resolved"
            )
    limits = case_budget(case)
    integ = integrate(
        st, op.speed, revs, spr, time_step=time_step, progress=progress, limits=limits,
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
        integ.time,
        disp,
        u,
        comps,
        op.speed,
        fit.residual,
        synchronous=basis.synchronous_sources,
        axial=st.ndof == 3,  # the rotor is held axially unless [dynamics] axial_dof
    )
    signal = None
    if case.spec.analysis.signal == "acceleration":
        signal, signal_notes = acceleration_signal(case, st, integ, u, limits)
        notes += signal_notes
    if st.spalls.shape[0]:
        notes.append(_defect_note(case))
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
    details = DynamicDetails(
        natural_frequencies_hz=tuple(float(f) for f in sorted(fn)),
        ball_passage_hz=fbp,
        time_step_s=integ.time_step,
        transient_s=integ.transient,
        transient_end=integ.settled,
        static_displacement_m=tuple(float(v) for v in integ.static_position[: st.ndof]),
        contact_law=st.contact_law,
        contact_stiffness_n_per_m1_5=st.stiffness,
        preload_contact_angle_deg=math.degrees(st.contact_angle),
        axial_dof=st.ndof == 3,
        min_loaded_balls=integ.min_loaded,
        solver_resolution_m=noise,
        explained_fraction=fit.explained_fraction,
        # from the preloaded position
        mean_axial_displacement_m=float(mean[2]) if st.ndof == 3 else None,
        sample_rate_hz=spr * op.speed,
    )
    # The product's axial reference is the rings axially centred: the contacts see the
    # preloaded offset z_p plus the axial degree of freedom (held at 0 without it).
    disp = disp.copy()
    disp[2] += st.axial_offset

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
        solver_resolution_m=noise,  # the floor its line fit uses: 1000 Newton tolerances
        details=details,
        notes=tuple(notes),
        signal=signal,
    )
    return result


def _defect_note(case: Any) -> str:
    """What the run did with the case's ``[[defect]]`` entries (one note)."""
    parts = []
    for i, entry in enumerate(case.spec.defect, start=1):
        where = (
            f"ball {entry.element}"
            if entry.part == "ball"
            else f"{entry.part} raceway at {math.degrees(entry.angle or 0.0):.4g} deg"
        )
        parts.append(
            f"defect[{i}]: {entry.width * 1e3:.4g} mm x {entry.depth * 1e6:.4g} um on the {where}"
        )
    return (
        "; ".join(parts) + ": a ball over a spall drops by the depth its centre reaches, "
        "min(depth, D/2 - sqrt(D^2/4 - e^2)) at e from the nearer edge (Sawalhi and Randall 2008)"
    )
