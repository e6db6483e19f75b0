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
  δ* table (``"delta_star_table"``, :func:`runout.geometry.contact.stiffness_from_delta_star_table`),
  at the preloaded contact angle.
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

import functools
import hashlib
import json
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from runout.analysis.decompose import Candidate, Direction, fit_lines, split_runout
from runout.analysis.result_details import DynamicDetails
from runout.analysis.results import RunResult, Source
from runout.analysis.spectrum import amplitude_spectrum, extract_lines
from runout.base.display import format_resolution
from runout.base.errors import GeometryError
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
    "sweep",
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
        details=details,
        notes=tuple(notes),
    )
    return result


# --------------------------------------------------------------------------------------------
# sweeps (seed 003 Figs. 3-4)
# --------------------------------------------------------------------------------------------
def _variant(case: Any, elements: int | None, preload: float | None) -> Any:
    """The case with another number of balls and/or axial preload."""
    from runout.case.model import parse_case

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
    details = result.details
    if not isinstance(details, DynamicDetails):
        raise TypeError(f"a sweep point needs a dynamic result, got the {result.model} model's")
    fbp = details.ball_passage_hz
    radial_bp = float(extract_lines(result.time, radial, [fbp]).amplitude[0]) * 2.0
    if radial_bp <= details.solver_resolution_m:
        radial_bp = 0.0
    keep = spec.frequencies <= 8.0 * fbp
    return SweepPoint(
        elements=case.bearing.elements,
        preload_n=case.operation.axial_load,
        contact_angle_deg=math.degrees(result.contact_angle),
        ball_passage_hz=fbp,
        natural_frequencies_hz=list(details.natural_frequencies_hz),
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
    sweep (:func:`runout.study.run.output_lock`) and must be new, empty or a sweep's output.

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
    runout.study.run.OutputError
        ``out`` empty, a file, unwritable, not a sweep's output, or locked by another writer.
    runout.study.run.StudyError
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
    from runout.study.run import output_directory, output_lock, refuse_foreign

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

    from runout.base.errors import RunoutError
    from runout.study.run import (
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
    from runout.report import plotting
    from runout.study.run import write_atomic

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
