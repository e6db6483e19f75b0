r"""Diagnosis: from a measured runout or vibration record to the part deviations behind it.

:func:`diagnose` turns the linear model (seed 002, "Anderon vibration", eq. 33-40; or its
force-balance variant) around:

1. **Candidate lines.** Every deviation the model maps to a line is an unknown: ring waviness of
   k = nZ ± 1 lobes and the eccentricity (k = 1) of the rotating ring, the even harmonics and
   the size error of each element, the inner-raceway slant; lobes up to a bound set by the
   sampling rate (the line must lie below the Nyquist frequency), the record length and
   :data:`MAX_LINES`.
   Candidates that stay below :data:`SCREEN` times the median level of the record's spectrum
   are below detection and not fitted.
2. **Line fit.** The record is fitted at those exact frequencies by the decomposition layer
   (:func:`runout.analysis.decompose.fit_lines`: joint least squares, no leakage; lines the
   record cannot separate are fitted as one and said so; peaks left in the residual are fitted
   too and, when no candidate explains them, reported as *unattributed*).
3. **Inverse.** The model is linear in the complex deviation coefficients; the gains are read
   from the forward model itself. With x and y, the forward and backward whirl of each line are
   two observations; with one channel, one. A line is *detected* when it stands
   :data:`DETECTION` standard deviations above the residual noise (and above the record's
   numerical resolution, :data:`RESOLUTION`; the noise includes the sensor gain and the
   residual near the line); the deviations are the
   weighted minimum-norm least-squares solution over the detected lines (the smallest
   deviations that give them: the limit of a Tikhonov-regularised fit).
4. **Observability.** What a line cannot tell apart is reported as a group, never split by a
   guess: outer waviness of nZ − 1 and nZ + 1 lobes with one channel (the same frequency; with
   x and y they whirl in opposite senses and separate), the balls of a ball set (two
   combinations per order; when both agree with one ball alone, the note names it), and every
   deviation the model maps to no line is listed in ``not_observable``.

Before the fit, the record's own speed is read from its lines and checked against the case's
(or the tachometer's), and a slow drift is tracked (:mod:`runout.diagnose._speed`): a record
whose lines give a speed beyond 2 % of it is refused; within, the lines are fitted on the
tracked shaft angle.

Each estimate's ``amplitude_m`` is the zero-to-peak radius deviation (the case-file
convention) of one equivalent deviation: the ring harmonic itself, or for a group its first
member alone (ball 1 for a ball set, the nZ − 1 harmonic for an outer pair), which gives the
same line. Its ``uncertainty_m`` is one standard deviation: the residual's noise near the line
(never below its white level) and the sensor gain uncertainty (:data:`GAIN_UNCERTAINTY`) in
quadrature; ``phase_uncertainty_rad`` adds the speed tracking's. A line the residual near it or
the gain explains as well as a deviation is not reported (a note names it). Phases are
referred to the instant t = 0 of the record's time column (θ = 0 there).
"""

from __future__ import annotations

import dataclasses
import math
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from runout.analysis.decompose import JOINT_FIT
from runout.diagnose._model import (
    PART_NAMES,
    Equation,
    Unknown,
    equations,
    solve_min_norm,
    static_unknowns,
    unknown_gains,
)
from runout.diagnose._record import Quantity, Record, RecordError, file_line, read_record

__all__ = [
    "DETECTION",
    "GAIN_UNCERTAINTY",
    "MAX_LINES",
    "Diagnosis",
    "Estimate",
    "Record",
    "RecordError",
    "Unattributed",
    "diagnose",
    "read_record",
]

FloatArray = NDArray[np.float64]
TWO_PI = 2.0 * math.pi

#: A line is detected when its fitted amplitude exceeds this many standard deviations of the
#: noise (a complex Gaussian exceeds 5 sigma with probability exp(-12.5) = 4e-6 per line).
DETECTION = 5.0
#: Probability that pure noise puts an unattributed line anywhere in a record's spectrum.
FALSE_ALARM = 1e-3
#: Candidates below this multiple of the median level of the record's spectrum are not fitted.
SCREEN = 3.0
#: Most candidate frequencies fitted (the fit costs samples x lines).
MAX_LINES = 240
#: Highest lobe count searched on any part.
MAX_LOBES = 2000
#: The record must hold this many samples per fitted line.
SAMPLES_PER_LINE = 8
#: Default relative standard uncertainty of the sensor's calibration (its gain) [-]: 1 %, the
#: sensitivity tolerance a displacement probe's calibration certificate typically states.
GAIN_UNCERTAINTY = 0.01
#: Half-width [bins] of the residual's spectrum around a line that sets its local noise floor.
LOCAL_BINS = 16
#: Numerical resolution of a record relative to its largest value [-]: a model's record
#: (``runout run``'s history.csv, 12 significant digits) rounds there, and its rounding errors
#: are periodic, so they land on kinematic lines that the residual's rms alone would call
#: detected. No line smaller than this (times :data:`DETECTION`) is taken for a deviation.
RESOLUTION = 1e-12


@dataclass(frozen=True)
class Estimate:
    """One observable deviation (or group that cannot be told apart).

    Attributes
    ----------
    part : str
        ``"inner"``, ``"outer"``, ``"ball"`` (``"roller"``), ``"slant"`` (parts joined by ``+``
        when their lines coincide).
    lobes : tuple of int
        Lobe counts that give this line and cannot be told apart.
    element : int or None
        1-based element, or None (a ring, or a ball set).
    amplitude_m : float
        Zero-to-peak radius deviation of one equivalent deviation [m].
    phase_rad : float
        Its phase φ of a cos(kθ + φ) [rad], referred to the record's t = 0.
    uncertainty_m : float
        One standard deviation of ``amplitude_m`` [m].
    frequency_hz : float
        Frequency of its line [Hz].
    whirl : str
        ``"forward"``, ``"backward"`` or ``"both"`` (one channel).
    share : float
        Fraction of the variance the estimates explain that this line carries [-].
    note : str
        What the equivalent deviation stands for.
    phase_uncertainty_rad : float
        One standard deviation of ``phase_rad`` [rad]: the noise, the gain and the speed
        tracking's uncertainty.
    """

    part: str
    lobes: tuple[int, ...]
    element: int | None
    amplitude_m: float
    phase_rad: float
    uncertainty_m: float
    frequency_hz: float
    whirl: str
    share: float
    note: str = ""
    phase_uncertainty_rad: float = 0.0

    def to_json(self) -> dict[str, Any]:
        """JSON-ready dict (units in key names).

        Returns
        -------
        dict of str to Any
            The attributes under their own names (``amplitude_m`` [m], ``phase_rad`` [rad],
            ``uncertainty_m`` [m], ``phase_uncertainty_rad`` [rad], ``frequency_hz`` [Hz]);
            ``lobes`` as a list.
        """
        return {
            "part": self.part,
            "lobes": list(self.lobes),
            "element": self.element,
            "amplitude_m": self.amplitude_m,
            "phase_rad": self.phase_rad,
            "uncertainty_m": self.uncertainty_m,
            "phase_uncertainty_rad": self.phase_uncertainty_rad,
            "frequency_hz": self.frequency_hz,
            "whirl": self.whirl,
            "share": self.share,
            "note": self.note,
        }


@dataclass(frozen=True)
class Unattributed:
    """A line above the noise that no deviation of the model explains.

    Attributes
    ----------
    frequency_hz : float
        Frequency of the line [Hz].
    pp : float
        Peak-to-peak [m], or [m/s] for a velocity record.
    channel : str
        ``"x"`` or ``"y"``; ``"xy"`` for the whirl of a fitted line that the model does not
        give there (``pp`` is then the diameter of its circle).
    order : float
        Frequency in orders of the rotating ring [-].
    kinematic_match : str or None
        First-order deviations outside the fit that give a line there (lobes above the bound
        searched, or an alias of a line above the Nyquist frequency), then the simplest
        kinematic combination at that frequency (a higher-order effect), if any.
    """

    frequency_hz: float
    pp: float
    channel: str
    order: float
    kinematic_match: str | None


@dataclass(frozen=True, eq=False)
class Diagnosis:
    """Result of :func:`diagnose`.

    Attributes
    ----------
    estimates : tuple of Estimate
        Detected deviations, largest share first.
    explained_fraction : float
        1 - variance(record - lines of the estimates) / variance(record), both channels [-].
    unattributed : tuple of Unattributed
    not_observable : tuple of str
        What this measurement cannot see, and why.
    notes : tuple of str
        How the record was read and fitted.
    quantity : str
        ``"displacement"`` or ``"velocity"``.
    rotation_hz : float
        Speed of the rotating ring used [Hz].
    speed_source : str
        ``"case"`` or ``"tachometer"``.
    variant : str
        Linear-model variant inverted.
    noise_rms : dict of str to float
        Rms of the residual per channel [m] or [m/s].
    detection_limit_m : float
        Smallest ring deviation a line of this record would show [m] (median over the lines).
    imperfections : runout.geometry.imperfections.BearingImperfections
        The minimum-norm deviations of the detected lines (what ``--out``'s case file holds).
    case : runout.case.model.Case
        The case the bearing and operation came from.
    record : Record
    lobe_bounds : dict of str to int
        Largest lobe count searched per part.
    spectrum : (ndarray, ndarray, ndarray) or None
        Frequencies [Hz] and Hann amplitude spectra of the record and of the reconstruction,
        first channel [m] or [m/s].
    record_speed_hz : float or None
        Mean speed of the rotating ring the record's lines give [Hz] (None: not tracked).
    speed_drift : float or None
        Change of that speed from the record's first to its last instant, relative to
        ``rotation_hz`` [-].
    gain_uncertainty : float
        Relative standard uncertainty of the sensor's gain included in every
        ``uncertainty_m`` [-].
    """

    estimates: tuple[Estimate, ...]
    explained_fraction: float
    unattributed: tuple[Unattributed, ...]
    not_observable: tuple[str, ...]
    notes: tuple[str, ...]
    quantity: str
    rotation_hz: float
    speed_source: str
    variant: str
    noise_rms: dict[str, float]
    detection_limit_m: float
    imperfections: Any
    case: Any
    record: Record
    lobe_bounds: dict[str, int] = field(default_factory=dict)
    spectrum: tuple[FloatArray, FloatArray, FloatArray] | None = None
    record_speed_hz: float | None = None
    speed_drift: float | None = None
    gain_uncertainty: float = GAIN_UNCERTAINTY

    def to_json(self) -> dict[str, Any]:
        """JSON-ready dict: finite numbers, units in key names.

        Returns
        -------
        dict of str to Any
            Estimates, unattributed lines (``pp_m`` [m] or ``pp_m_per_s`` [m/s]), notes, the
            record's description (``duration_s`` [s], ``sample_rate_hz`` [Hz]), the model,
            ``rotation_hz`` [Hz], ``record_speed_hz`` [Hz] and ``speed_drift`` [-] (the speed
            the record's lines give; null when not tracked), ``gain_uncertainty`` [-], the
            residual noise and ``detection_limit_m`` [m].
        """
        unit = "m" if self.quantity == "displacement" else "m_per_s"
        return {
            "estimates": [e.to_json() for e in self.estimates],
            "explained_fraction": self.explained_fraction,
            "unattributed": [
                {
                    "frequency_hz": u.frequency_hz,
                    f"pp_{unit}": u.pp,
                    "channel": u.channel,
                    "order": u.order,
                    "kinematic_match": u.kinematic_match,
                }
                for u in self.unattributed
            ],
            "not_observable": list(self.not_observable),
            "notes": list(self.notes),
            "record": {
                "file": self.record.file,
                "samples": self.record.samples,
                "duration_s": self.record.duration,
                "sample_rate_hz": 1.0 / self.record.step,
                "channels": sorted(self.record.channels),
                "quantity": self.quantity,
            },
            "model": {"name": "linear", "linear_variant": self.variant},
            "rotation_hz": self.rotation_hz,
            "speed_source": self.speed_source,
            "record_speed_hz": self.record_speed_hz,
            "speed_drift": self.speed_drift,
            "gain_uncertainty": self.gain_uncertainty,
            f"noise_rms_{unit}": dict(self.noise_rms),
            "detection_limit_m": self.detection_limit_m,
            "lobes_searched": dict(self.lobe_bounds),
        }

    def estimated_case_text(self) -> str:
        """Case-file text of the bearing and operation with the estimated deviations.

        The case's own imperfection tables are dropped; ``[analysis]`` runs the linear model
        with the variant inverted. ``runout run`` on it gives the reconstructed lines.

        Returns
        -------
        str
            TOML text of the case (see :func:`estimated_case_text`).
        """
        return estimated_case_text(self.case, self.imperfections, self.variant, self.rotation_hz)


def _element_name(case: Any) -> str:
    from runout.geometry.bearing import RollerBearing

    return "roller" if isinstance(case.bearing, RollerBearing) else "ball"


def _load(case: Any) -> Any:
    if isinstance(case, str | Path):
        from runout.case.model import load_case

        return load_case(case)
    return case


def _lobe_bounds(z: int, r: Any, f_hi: float, rotation_hz: float) -> tuple[int, int]:
    """Largest ring and element lobe counts whose lines lie below ``f_hi`` [Hz]."""
    k_ring = 1
    n = 1
    while n * z - 1 <= MAX_LOBES:
        ok = False
        for k in (n * z - 1, n * z + 1):
            for nu in (r.inner, r.outer):
                f1 = abs((k + 1) * r.cage - k * nu) * rotation_hz
                f2 = abs(k * nu - (k - 1) * r.cage) * rotation_hz
                if min(f1, f2) < f_hi:
                    ok = True
        if not ok:
            break
        k_ring = min(n * z + 1, MAX_LOBES)
        n += 1
    m_ball = 0
    m = 2
    while (
        m <= MAX_LOBES
        and min(abs(r.cage + m * r.spin), abs(r.cage - m * r.spin)) * rotation_hz < f_hi
    ):
        m_ball = m
        m += 2
    return k_ring, m_ball


def diagnose(
    case: Any,
    record: Record | str | Path,
    *,
    quantity: Quantity = "displacement",
    variant: str | None = None,
    max_lobes: int | None = None,
    gain_uncertainty: float = GAIN_UNCERTAINTY,
) -> Diagnosis:
    """Estimate the part deviations that produced a measured record (see the module doc).

    Parameters
    ----------
    case : runout.case.model.Case or path
        Bearing and operation (speed, loads, rotating ring); its imperfections are ignored.
    record : Record or path
        The record (:func:`runout.diagnose.fit.read_record` reads a CSV file).
    quantity : {"displacement", "velocity"}
        What a record file's x/y columns hold (ignored for a :class:`Record`).
    variant : {"radial_spring", "force_balance"}, optional
        Linear-model variant to invert; default the case's ``[analysis] linear_variant``.
    max_lobes : int, optional
        Largest lobe count searched (default: every line below the Nyquist frequency, at most
        :data:`MAX_LINES` lines).
    gain_uncertainty : float
        Relative standard uncertainty of the sensor's gain [-] (default
        :data:`GAIN_UNCERTAINTY`, 1 %): a line of phasor X is uncertain by this times |X| on
        top of the noise, in its amplitude, its phase and its detection.

    Returns
    -------
    Diagnosis

    Raises
    ------
    RecordError
        A record that cannot be read or fitted (named by file, row and column), or whose lines
        show a speed beyond :data:`runout.diagnose._speed.SPEED_RTOL` of the tachometer's.
    CaseError
        The record's lines show a speed beyond that tolerance of the case's
        (``operation.speed``).

    Notes
    -----
    The speed check and the order tracking are those of :mod:`runout.diagnose._speed`; the
    lines are those of the linear model (seed 002, "Anderon vibration", an instrument maker's
    calculation model, eq. 33-40: every line at a fixed order of the rotating ring's speed).
    """
    from runout.analysis.decompose import Candidate, Kinematic, attribute_frequency, fit_lines
    from runout.analysis.lines import Source
    from runout.case.limits import case_budget
    from runout.geometry.loading import operating_contact_angle
    from runout.models.linear import rates, variant_gains

    if not (math.isfinite(gain_uncertainty) and 0.0 <= gain_uncertainty < 1.0):
        raise ValueError(
            f"gain_uncertainty must be a fraction in [0, 1) (0.01 = 1 %), got {gain_uncertainty!r}"
        )
    c = _load(case)
    if getattr(c, "spindle", None) is not None:
        from runout.base.errors import CaseError

        # the record of a spindle mixes its bearings' lines through the shaft: one bearing's
        # linear model is not its inverse
        raise CaseError(
            str(c.path),
            "bearings",
            "the diagnosis inverts one bearing's linear model: give a case with one [bearing] "
            "(the bearing the record was measured on), not a spindle",
        )
    if not isinstance(record, Record):
        record = read_record(record, quantity, limits=case_budget(c))
    notes: list[str] = []
    if _has_imperfections(c):
        notes.append(
            "the case's imperfection tables are ignored: the diagnosis estimates them from "
            "the record"
        )
    var = variant if variant is not None else getattr(c.analysis, "linear_variant", "radial_spring")
    bearing, operation = c.bearing, c.operation
    speed_source = "case"
    tacho = record.tachometer_speed()
    if tacho is not None:
        nominal = abs(operation.speed)
        if nominal > 0.0:
            scale = tacho / nominal
            operation = dataclasses.replace(
                operation,
                speed=operation.speed * scale,
                other_ring_speed=operation.other_ring_speed * scale,
            )
            given = f"the case gives {nominal * 60:.6g} rpm"
        else:  # the case leaves the speed to the record
            operation = dataclasses.replace(operation, speed=tacho)
            given = "the case gives none"
        speed_source = "tachometer"
        notes.append(f"speed from the tachometer: {tacho:.6g} Hz ({tacho * 60:.6g} rpm; {given})")
    elif operation.speed == 0.0:
        from runout.base.errors import CaseError

        raise CaseError(
            str(c.path),
            "operation.speed",
            "the diagnosis needs the speed of the rotating ring: give [operation] speed, or a "
            "tachometer column rev in the record",
        )
    if record.quantity == "displacement":
        _plausible(record, float(bearing.element_diameter))
    alpha, _ = operating_contact_angle(bearing, operation)
    variant_gains(alpha, var)  # refuses an unknown variant with the case key
    r = rates(bearing, operation, alpha)
    f_r = r.rotation_hz
    z = int(bearing.elements)
    n = record.samples
    duration = record.duration
    f_hi = 0.5 / record.step * 0.999
    f_lo = 1.0 / duration
    cage_hz = abs(r.cage - (r.inner if operation.rotating_ring == "inner" else r.outer)) * f_r
    if duration * min(cage_hz, f_r) < 2.0:
        raise RecordError(
            record.file,
            "",
            f"too short: {duration:.4g} s holds {duration * f_r:.3g} revolutions; at least "
            f"{math.ceil(2.0 / min(cage_hz, f_r) * f_r)} revolutions of the rotating ring are "
            "needed to separate the cage-rate lines",
        )
    k_ring, m_ball = _lobe_bounds(z, r, f_hi, f_r)
    if max_lobes is not None:
        if max_lobes < 1:
            raise RecordError(record.file, "", f"max_lobes must be >= 1, got {max_lobes}")
        k_ring, m_ball = min(k_ring, max_lobes), min(m_ball, max_lobes - max_lobes % 2)
    slant = abs(r.inner) > 0.0
    channels = tuple(sorted(record.channels))
    while True:
        terms = unknown_gains(z, r, alpha, var, k_ring, m_ball, slant)
        eqs = equations(terms, channels)
        freqs = sorted({abs(e.omega) * f_r for e in eqs})
        n_lines = sum(1 for f in freqs if f_lo < f < f_hi)
        limit = min(MAX_LINES, n // (2 * SAMPLES_PER_LINE))
        if n_lines <= limit or (k_ring <= z + 1 and m_ball <= 2):
            break
        k_ring = max(z + 1, int(k_ring * 0.8))
        m_ball = max(2, int(m_ball * 0.8) // 2 * 2)
    if n_lines == 0:
        # not even the rotating ring's eccentricity (f_r) is in the band: nothing to fit
        raise RecordError(
            record.file,
            f"column {record.column('time')!r}",
            f"no line of the bearing lies in the record's band ({f_lo:.4g} to "
            f"{f_hi / 0.999:.4g} Hz, the Nyquist frequency; the rotating ring turns at "
            f"{f_r:.6g} Hz): sample faster, or check the time column's unit (a bare time_s is "
            "in seconds; 't [ms]' gives milliseconds)",
        )
    if max_lobes is None:
        notes.append(
            f"lobes searched: rings up to {k_ring}, {_element_name(c)}s up to {m_ball} "
            f"({n_lines} candidate lines below the Nyquist frequency {f_hi / 0.999:.6g} Hz)"
        )
    # one candidate per line frequency; the source's term carries the frequency's index
    fidx = {f: i for i, f in enumerate(freqs)}
    inside = [f for f in freqs if f_lo < f < f_hi]
    spectra = _spectra(record)
    tracking = _check_speed(c, record, spectra, freqs, inside, f_r, speed_source, notes)
    time_axis = record.time
    speed_ratio = 1.0  # mean speed of the record / f_r, where the lines are tracked
    if tracking is not None and tracking.applied:
        time_axis = tracking.warped(record.time)
        speed_ratio = tracking.mean_ratio
    # the record's lines lie at the speed it was taken at: screened there
    present = _screen(spectra, inside, speed_ratio)
    if len(present) < len(inside):
        notes.append(
            f"{len(inside) - len(present)} of {len(inside)} candidate lines stay below "
            f"{SCREEN:g} x the median level of the record's spectrum (below detection) and "
            "are not fitted"
        )
    ename = _element_name(c)
    members: dict[int, list[str]] = {}
    for e in eqs:
        names = members.setdefault(fidx[abs(e.omega) * f_r], [])
        for con in e.contributions:
            u = con.unknown
            text = f"{ename if u.part == 2 else PART_NAMES[u.part]} {u.lobes} lobes"
            if text not in names:
                names.append(text)
    # the term carries the frequency's index (read back from the fitted lines) and its members
    cands = [
        Candidate(
            f,
            "radial",
            Source(
                "diagnosis",
                None,
                None,
                f"#{fidx[f]} " + ", ".join(members[fidx[f]][:3]),
                f"{f / f_r:.6g} f_r",
            ),
        )
        for f in present
    ]
    kin = Kinematic(f_r, r.cage * f_r, abs(r.spin) * f_r, z)
    signal = np.zeros((3, n))
    for ch, channel in record.channels.items():
        signal["xy".index(ch)] = channel
    fit = fit_lines(
        time_axis,
        signal,
        cands,
        f_r,
        directions=channels,
        kinematic=None,
    )
    notes += list(fit.notes)
    noise = {ch: float(np.std(fit.residual["xy".index(ch)])) for ch in channels}
    # phasors of each candidate frequency per channel; merged lines map to all they carry
    phasor: dict[str, dict[int, complex]] = {ch: {} for ch in channels}
    merged: dict[int, int] = {}
    spread: dict[int, float] = {}
    fitted_hz: dict[int, float] = {}
    unattributed: list[Unattributed] = []
    tol = 1.0 / duration
    quad = {ch: noise[ch] * math.sqrt(2.0 / n) for ch in channels}
    floor = RESOLUTION * max(float(np.max(np.abs(v))) for v in record.channels.values())
    if any(q < floor for q in quad.values()):
        unit = "m" if record.quantity == "displacement" else "m/s"
        notes.append(
            f"the residual ({', '.join(f'{noise[ch]:.3g}' for ch in channels)} {unit} rms) is "
            f"below the record's numerical resolution ({RESOLUTION:g} of its largest value, "
            f"{floor:.3g} {unit}): lines are detected above that resolution, not the residual"
        )
        quad = {ch: max(q, floor) for ch, q in quad.items()}
    # a line found anywhere in the residual's spectrum must beat the largest of its n/2 noise
    # bins, not one: the level pure noise exceeds somewhere with probability FALSE_ALARM
    search_level = max(DETECTION, math.sqrt(2.0 * math.log(0.5 * n / FALSE_ALARM)))
    for comp in fit.components:
        idx = [int(s.term[1:].split()[0]) for s in comp.sources if s.term.startswith("#")]
        amp = 0.5 * comp.pp_m
        if not idx:
            if amp > search_level * quad[comp.direction]:
                match = attribute_frequency(comp.frequency_hz, kin, tol)
                formula = None if match is None else match[1].formula
                hint = _first_order_hint(
                    comp.frequency_hz, tol, z, r, f_r, (k_ring, m_ball), 1.0 / record.step, ename
                )
                if hint is not None:
                    formula = hint if formula is None else f"{hint}; {formula}"
                unattributed.append(
                    Unattributed(
                        comp.frequency_hz,
                        comp.pp_m,
                        comp.direction,
                        comp.frequency_hz / f_r,
                        formula,
                    )
                )
            continue
        head = min(idx)
        for i in idx:
            merged[i] = head
        spread[head] = max(abs(freqs[i] - freqs[head]) for i in idx)
        fitted_hz[head] = comp.frequency_hz
        phasor[comp.direction][head] = amp * complex(
            math.cos(comp.phase_rad), math.sin(comp.phase_rad)
        )
    # observations per equation: the equations of lines fitted as one are summed
    groups: dict[tuple[int, int], list[Equation]] = {}
    for e in eqs:
        i = fidx[abs(e.omega) * f_r]
        if i not in merged:
            continue  # outside the record's band, or below the fit's floor: zero
        head = merged[i]
        sign = 1 if e.omega >= 0 else -1
        groups.setdefault((head, sign if len(channels) == 2 else 1), []).append(e)
    values: list[complex] = []
    sigmas: list[float] = []  # noise (local floor) and gain: the uncertainty and detection
    weights: list[float] = []  # the white noise alone: the inverse's weights
    kept: list[Equation] = []
    ends = float(time_axis[0] + time_axis[-1])
    local = {
        ch: _local_floor(fit.residual["xy".index(ch)], record.step, quad[ch]) for ch in channels
    }
    unexplained: list[tuple[Equation, complex, float, float]] = []
    for (head, _), group in groups.items():
        e = group[0]
        eq = Equation(e.omega, [c for m in group for c in m.contributions], spread.get(head, 0.0))
        kept.append(eq)
        scale = 1.0
        if record.quantity == "velocity":
            # displacement = velocity / (i ω), ω at the record's own (tracked) speed
            scale = 1.0 / (TWO_PI * freqs[head] * speed_ratio)
        rot: complex = -1j if record.quantity == "velocity" else 1.0
        own = abs(e.omega) * f_r
        if all(abs(abs(m.omega) * f_r - own) <= 1e-9 * own for m in group):
            # a line fitted at another's frequency (closer than the record resolves) comes out
            # with the phase it has mid-record, pi df (t0 + t1) off its phase at t = 0
            rot *= complex(
                math.cos(math.pi * (own - fitted_hz[head]) * ends),
                -math.sin(math.pi * (own - fitted_hz[head]) * ends),
            )
        f_line = freqs[head]
        if len(channels) == 2:
            xv = phasor["x"].get(head, 0j) * scale * rot
            yv = phasor["y"].get(head, 0j) * scale * rot
            v = 0.5 * (xv + 1j * yv) if e.omega > 0 else (0.5 * (xv - 1j * yv)).conjugate()
            white = 0.5 * math.hypot(quad["x"], quad["y"]) * scale
            s = 0.5 * math.hypot(local["x"](f_line), local["y"](f_line)) * scale
            # independent gain errors g_x, g_y move C = (X + iY)/2 by (g_x X + i g_y Y)/2
            s_gain = 0.5 * gain_uncertainty * math.hypot(abs(xv), abs(yv))
        else:
            ch = channels[0]
            v = phasor[ch].get(head, 0j) * scale * rot
            white = quad[ch] * scale
            s = local[ch](f_line) * scale
            s_gain = gain_uncertainty * abs(v)
        s = math.hypot(s, s_gain)
        values.append(v)
        sigmas.append(max(s, 1e-300))
        weights.append(max(white, 1e-300))
        if DETECTION * white < abs(v) <= DETECTION * s:
            unexplained.append((eq, v, white, s))
    detected = [
        (e, v, s) for e, v, s in zip(kept, values, sigmas, strict=True) if abs(v) > DETECTION * s
    ]
    detected_weights = [
        w for v, s, w in zip(values, sigmas, weights, strict=True) if abs(v) > DETECTION * s
    ]
    if unexplained:
        notes.append(_unexplained_note(unexplained, f_r, ename, gain_uncertainty))
    notes.append(
        "uncertainties (one standard deviation) include the residual's noise near each line, "
        f"a sensor gain uncertainty of {100 * gain_uncertainty:.3g} % "
        + (
            "and the speed tracking's uncertainty (phases)"
            if tracking is not None
            else "(the speed was not tracked: no line stands out of the spectrum)"
        )
    )
    if len(channels) == 2:
        unattributed += _other_whirls(
            groups,
            phasor,
            quad,
            freqs,
            members,
            f_r,
            detected,
            notes,
            lambda f: _first_order_hint(
                f, tol, z, r, f_r, (k_ring, m_ball), 1.0 / record.step, ename
            ),
            gain_uncertainty,
        )
    solution = solve_min_norm(
        [d[0] for d in detected],
        np.array([d[1] for d in detected], dtype=np.complex128),
        np.array(detected_weights),
    )
    estimates, alone = _single_ball(
        _estimates(detected, f_r, record, ename, z, tracking), r, f_r, z, ename
    )
    estimates = _load_zone(c, estimates, notes, ename)
    for u in list(solution):
        if u.part == 2 and u.lobes in alone:
            # both lines of this order agree with one element: the case file puts it there
            j, b = alone[u.lobes]
            solution[u] = b if u.element == j else 0j
    imperfections = _imperfections(solution, z)
    # what the record could have shown: the smallest ring deviation of a detected-size line
    ring_gain = abs(variant_gains(alpha, var)[0])
    base = 0.5 * math.hypot(*quad.values()) if len(channels) == 2 else quad[channels[0]]
    per_line = [base / (TWO_PI * f if record.quantity == "velocity" else 1.0) for f in inside] or [
        base
    ]
    detection_limit = float(DETECTION * np.median(per_line) / ring_gain)
    explained, spectrum = _explained(
        c, operation, alpha, var, imperfections, record, f_r, time_axis, speed_ratio
    )
    not_obs = _not_observable(z, channels, terms, k_ring, m_ball, f_hi, ename, r)
    return Diagnosis(
        estimates=estimates,
        explained_fraction=explained,
        unattributed=_one_per_frequency(unattributed, tol),
        not_observable=tuple(not_obs),
        notes=tuple(notes),
        quantity=record.quantity,
        rotation_hz=f_r,
        speed_source=speed_source,
        variant=var,
        noise_rms=noise,
        detection_limit_m=detection_limit,
        imperfections=imperfections,
        case=c,
        record=record,
        lobe_bounds={"inner": k_ring, "outer": k_ring, ename: m_ball},
        spectrum=spectrum,
        record_speed_hz=None if tracking is None else f_r * tracking.mean_ratio,
        speed_drift=None if tracking is None else tracking.drift,
        gain_uncertainty=gain_uncertainty,
    )


def _other_whirls(
    groups: dict[tuple[int, int], list[Equation]],
    phasor: dict[str, dict[int, complex]],
    quad: dict[str, float],
    freqs: list[float],
    members: dict[int, list[str]],
    f_r: float,
    detected: list[tuple[Equation, complex, float]],
    notes: list[str],
    hint: Callable[[float], str | None],
    gain: float = 0.0,
) -> list[Unattributed]:
    """The whirl of a fitted line that no deviation gives, when it stands above the noise.

    With x and y each line has a forward and a backward whirl; the model gives most lines one
    of them. The other is no observation of any deviation, but it is in the record: it is
    reported (channel ``"xy"``), not dropped. When it carries more than the modelled whirls,
    the likeliest cause is a mirrored axis (or the other ring turning), which reverses every
    whirl: a note says so. A whirl within ``gain`` (the relative sensor gain uncertainty) of the
    line is what a mismatch of the x and y gains gives, g √(|X|² + |Y|²)/2 at most: it must
    stand 5 standard deviations above that too, and a note counts those that do not.
    ``hint(frequency)`` names first-order deviations outside the fit
    that give a line there (lobes above the bound, aliases), or None.
    """
    out: list[Unattributed] = []
    sigma = 0.5 * math.hypot(quad["x"], quad["y"])
    wrong = 0.0
    within_gain = 0
    for head in sorted({h for h, _ in groups}):
        xv, yv = phasor["x"].get(head, 0j), phasor["y"].get(head, 0j)
        for sign, word, other in ((1, "forward", "backward"), (-1, "backward", "forward")):
            if (head, sign) in groups:
                continue
            w = 0.5 * abs(xv + 1j * yv) if sign > 0 else 0.5 * abs(xv - 1j * yv)
            if w <= DETECTION * sigma:
                continue
            if w <= DETECTION * math.hypot(sigma, 0.5 * gain * math.hypot(abs(xv), abs(yv))):
                within_gain += 1  # an x/y gain mismatch gives it
                continue
            wrong += (w / sigma) ** 2
            who = ", ".join(members.get(head, [])[:3])
            text = f"{word} whirl at the line of {who}, which the model gives {other} only"
            more = hint(freqs[head])
            out.append(
                Unattributed(
                    freqs[head],
                    2.0 * w,
                    "xy",
                    freqs[head] / f_r,
                    text if more is None else f"{text}; may be {more}",
                )
            )
    if within_gain:
        notes.append(
            f"{within_gain} whirl(s) at fitted lines that the model does not give stand above "
            f"the noise but within the {100 * gain:g} % gain uncertainty (a mismatch of the x "
            "and y gains puts that share of a line into its other whirl): not reported"
        )
    modelled = sum((abs(v) / s) ** 2 for _, v, s in detected)
    if out and wrong > modelled:
        notes.append(
            "most of the lines' power whirls against the model: check the sense of the y axis "
            "(the conventions page; a mirrored y reverses every whirl, and the lobes then read "
            "nZ -/+ 1 for nZ +/- 1) and which ring turns"
        )
    return out


def _first_order_hint(
    frequency: float,
    tol: float,
    z: int,
    r: Any,
    f_r: float,
    bounds: tuple[int, int],
    sample_rate: float,
    ename: str,
) -> str | None:
    """The first-order deviations an unattributed line may be, though no candidate is there.

    Two ways a deviation of the model gives a line the fit did not look for: its lobes are
    above the bound searched, or its line is above the Nyquist frequency and folds into the
    record's band (a record sampled without a low-pass filter). ``tol`` [Hz] is the match.
    """
    k_ring, m_ball = bounds
    nyquist = 0.5 * sample_rate
    found: list[tuple[int, bool, str, float]] = []  # lobes, above the bound, label, line [Hz]
    n = 1
    while n * z - 1 <= MAX_LOBES:
        for name, nu in (("inner", r.inner), ("outer", r.outer)):
            # k = nZ - 1 gives the first term of the closed form, k = nZ + 1 the second
            for k, f in (
                (n * z - 1, abs(n * z * r.cage - (n * z - 1) * nu) * f_r),
                (n * z + 1, abs((n * z + 1) * nu - n * z * r.cage) * f_r),
            ):
                found.append((k, k > k_ring, f"{name} {k} lobes", f))
        n += 1
    for m in range(2, MAX_LOBES + 1, 2):
        for f in (abs(r.cage + m * r.spin) * f_r, abs(r.cage - m * r.spin) * f_r):
            found.append((m, m > m_ball, f"{ename} {m} lobes", f))
    found.sort(key=lambda item: item[0])  # the simplest first
    beyond = [
        label for _, above, label, f in found if above and f < nyquist and abs(f - frequency) <= tol
    ]
    if beyond:
        return (
            " or ".join(beyond[:3]) + f" (above the lobes searched: {k_ring} on the rings, "
            f"{m_ball} on the {ename}s)"
        )
    # one fold only (lines between the Nyquist and the sampling frequency): folded from
    # higher up, the lines of hundreds of lobes cover the band and any frequency would match
    aliases = [
        (label, f)
        for _, _, label, f in found
        if nyquist < f < sample_rate and abs(sample_rate - f - frequency) <= tol
    ]
    if aliases:
        return (
            "alias of "
            + " or ".join(f"{label} ({f:.6g} Hz)" for label, f in aliases[:3])
            + f", above the Nyquist frequency {nyquist:.6g} Hz (no low-pass filter before "
            "sampling?)"
        )
    return None


def _plausible(record: Record, diameter: float) -> None:
    """Refuse a displacement record whose motion exceeds the rolling element's diameter [m]:
    no bearing moves that much and holds together; the column is in the wrong unit."""
    for ch, values in record.channels.items():
        dev = np.abs(values - values.mean())
        worst = int(np.argmax(dev))
        if float(np.ptp(values)) > diameter:
            raise RecordError(
                record.file,
                f"row {file_line(record.file, worst)}, column {record.column(ch)!r}",
                f"the motion spans {float(np.ptp(values)):.4g} m, more than the "
                f"{diameter:.4g} m element diameter: check the column's unit (a bare {ch}_m "
                f"is in metres; give it in brackets, e.g. '{ch} [um]')",
            )


def _load_zone(
    case: Any, estimates: tuple[Estimate, ...], notes: list[str], ename: str
) -> tuple[Estimate, ...]:
    """Flag the stationary ring's estimates when a radial load leaves a load zone.

    The linear model has every element in contact at one mean load (seed 002 eq. 12-20).
    Under a radial load without an axial preload (always for a cylindrical roller bearing)
    only the elements in the load zone carry it, and their passage through it moves the
    ring at multiples of Z f_c relative to the stationary ring: the frequencies of that ring's
    nZ +/- 1 lobes, which the inversion reads as waviness.
    """
    from runout.geometry.bearing import RollerBearing

    op = case.operation
    roller = isinstance(case.bearing, RollerBearing)
    if not (op.radial_load > 0.0 and (roller or op.axial_load <= 0.0)):
        return estimates
    still = "outer" if op.rotating_ring == "inner" else "inner"
    notes.append(
        f"the case has a radial load{'' if roller else ' without an axial preload'}: the "
        f"{ename}s outside the load zone carry no load, which the linear model does not know "
        f"(it has every {ename} in contact); their passage through the load zone gives lines "
        f"at multiples of Z f_c relative to the {still} ring, read here as {still}-ring "
        "waviness of nZ +/- 1 lobes. Compare with `runout run` of the case's own model"
    )
    text = (
        f"may be the {ename}s' passage through the load zone (n Z f_c), not {still}-ring waviness"
    )
    return tuple(
        dataclasses.replace(e, note=f"{e.note}; {text}" if e.note else text)
        if still in e.part.split("+")
        else e
        for e in estimates
    )


def _spectra(record: Record) -> list[Any]:
    """The Hann amplitude spectrum of each channel (x before y), about its mean."""
    from runout.analysis.spectrum import amplitude_spectrum

    fs = 1.0 / record.step
    return [
        amplitude_spectrum(record.channels[ch] - record.channels[ch].mean(), sample_rate=fs)
        for ch in sorted(record.channels)
    ]


def _screen(spectra: list[Any], freqs: list[float], ratio: float = 1.0) -> list[float]:
    """The candidate frequencies whose neighbourhood (±2 bins) in the record's Hann amplitude
    spectrum rises above :data:`SCREEN` × its median level in some channel.

    For white noise the median bin is 1.4 σ/√n and a line at the detection level
    (:data:`DETECTION` × σ √(2/n) = 7.1 σ/√n) shows at least 6 σ/√n, scalloping included: the
    screen drops only lines the fit would not detect, and spares fitting them jointly (the
    fit's cost grows with the number of lines). ``ratio``: the record's speed over the one
    ``freqs`` [Hz] are at (each is looked for at ``ratio`` times itself)."""
    if not freqs:
        return []
    f = np.asarray(freqs)
    keep = np.zeros(f.size, dtype=bool)
    for spec in spectra:
        amp = spec.amplitude
        level = SCREEN * float(np.median(amp))
        centre = np.rint(ratio * f / spec.resolution).astype(np.int64)
        for shift in range(-2, 3):
            i = np.clip(centre + shift, 0, amp.size - 1)
            keep |= amp[i] > level
    return [float(v) for v in f[keep]]


def _local_floor(residual: FloatArray, step: float, white: float) -> Callable[[float], float]:
    """σ_line at a frequency [Hz] from the residual's spectrum around it (±:data:`LOCAL_BINS`
    bins, the line's own ±1 bins left out: the fit removed it there), never below ``white``.

    For white noise of rms σ, E|R_k|² = n σ², so √(2 mean|R_k|²)/n is σ √(2/n), the standard
    deviation of a fitted line's phasor. Near a line smeared by what the model does not hold
    (a drift not tracked, sidebands) the residual rises, and so does this floor: a line the
    residual around it explains as well is not a detection.
    """
    n = residual.size
    power = np.abs(np.fft.rfft(residual - residual.mean())) ** 2

    def at(frequency: float) -> float:
        k0 = round(frequency * n * step)
        lo, hi = max(1, k0 - LOCAL_BINS), min(power.size, k0 + LOCAL_BINS + 1)
        near = np.concatenate([power[lo : max(lo, k0 - 1)], power[min(hi, k0 + 2) : hi]])
        if near.size == 0:
            return white
        return max(white, math.sqrt(2.0 * float(near.mean())) / n)

    return at


def _unexplained_note(
    dropped: list[tuple[Equation, complex, float, float]], f_r: float, ename: str, gain: float
) -> str:
    """The lines above the white noise that the residual near them (or the gain) explains."""
    items = []
    for e, v, white, s in dropped[:6]:
        names = sorted(
            {
                f"{ename if c.unknown.part == 2 else PART_NAMES[c.unknown.part]} "
                f"{c.unknown.lobes} lobes"
                for c in e.contributions
            }
        )
        items.append(
            f"{' or '.join(names[:2])} at {abs(e.omega) * f_r:.6g} Hz ({abs(v):.3g} m: "
            f"{abs(v) / white:.3g} sigma of the white noise, {abs(v) / s:.3g} sigma with the "
            "residual near it and the gain)"
        )
    more = f" and {len(dropped) - 6} more" if len(dropped) > 6 else ""
    return (
        f"{len(dropped)} line(s) stand above {DETECTION:g} sigma of the residual's white level "
        f"but not above the residual near them and the {100 * gain:g} % gain uncertainty: "
        "not reported as deviations (the residual explains them as well): "
        + "; ".join(items)
        + more
    )


def _ranked(spectra: list[Any], present: list[float], ratio: float = 1.0) -> list[float]:
    """The candidate frequencies [Hz] that stand :data:`runout.diagnose._speed.PEAK_LEVEL`
    times above the median level of the record's spectrum, strongest first (the lines worth
    tracking the speed on); ``ratio`` as for :func:`_screen`."""
    from runout.diagnose._speed import PEAK_FLOOR, PEAK_LEVEL

    if not present:
        return []
    f = np.asarray(present)
    level = np.zeros(f.size)
    strong = np.zeros(f.size, dtype=bool)
    for spec in spectra:
        centre = np.rint(ratio * f / spec.resolution).astype(np.int64)
        here = np.zeros(f.size)
        for shift in (-1, 0, 1):
            i = np.clip(centre + shift, 0, spec.amplitude.size - 1)
            here = np.maximum(here, spec.amplitude[i])
        strong |= here > max(
            PEAK_LEVEL * float(np.median(spec.amplitude)), PEAK_FLOOR * float(spec.amplitude.max())
        )
        level = np.maximum(level, here)
    order = np.argsort(-level, kind="stable")
    return [float(f[i]) for i in order if strong[i]]


def _check_speed(
    case: Any,
    record: Record,
    spectra: list[Any],
    freqs: list[float],
    inside: list[float],
    f_r: float,
    speed_source: str,
    notes: list[str],
) -> Any:
    """Check the speed against the record's lines, then track its drift on them.

    Refuses a record whose lines give a speed beyond :data:`runout.diagnose._speed.SPEED_RTOL`
    of ``f_r`` [Hz] (naming ``operation.speed``, or the tachometer column); says in ``notes``
    when the lines do not show the speed, and when the tracking is applied. Returns the
    :class:`runout.diagnose._speed.Tracking`, or None without a line to track.
    """
    from runout.diagnose._speed import (
        CONVINCING,
        SPEED_RTOL,
        line_speed,
        track_speed,
    )

    chans = [record.channels[ch] for ch in sorted(record.channels)]
    fs = 1.0 / record.step
    n = record.samples
    given = "the tachometer" if speed_source == "tachometer" else "the case"
    rpm = f_r * 60.0
    ls = line_speed([sp.amplitude for sp in spectra], fs, n, np.asarray(freqs) / f_r, f_r)
    ratio = 1.0
    if ls is None:
        notes.append(
            f"the speed is not checked against the record's lines: fewer than two lines stand "
            f"out of its spectrum (one line fits any speed); the speed is {given}'s"
        )
    else:
        if (
            abs(ls.ratio - 1.0) > SPEED_RTOL
            and ls.share_best >= CONVINCING
            and ls.share_assumed < 0.5
        ):
            _refuse_speed(case, record, f_r, ls.ratio * f_r, speed_source, ls)
        adopted = abs(ls.ratio - 1.0) <= SPEED_RTOL and ls.share_best >= CONVINCING
        if ls.share_assumed < 0.5 and not adopted:  # (an adopted speed is tracked, and said)
            notes.append(
                f"only {100 * ls.share_assumed:.0f} % of the power of the record's "
                f"{ls.peaks} strongest lines lies on the bearing's lines at {rpm:.6g} rpm "
                f"({given}'s speed): the rest is no line of the bearing's kinematics at that "
                "speed (check the speed, and the unattributed lines)"
            )
        if abs(ls.ratio - 1.0) <= SPEED_RTOL:
            ratio = ls.ratio
    # a line with a candidate closer than the record resolves beats with it: that slow phase
    # is no drift, so only isolated lines are tracked
    near = 1.5 / record.duration
    every = np.asarray(freqs)
    present = _screen(spectra, inside, ratio)
    isolated = [
        f
        for f in _ranked(spectra, present, ratio)
        if np.count_nonzero(np.abs(every - f) < near) == 1
    ]
    tr = track_speed(record.time, chans, isolated, ratio)
    if tr is None:
        return None
    if abs(tr.mean_ratio - 1.0) > SPEED_RTOL:
        _refuse_speed(case, record, f_r, tr.mean_ratio * f_r, speed_source, ls)
    if tr.applied:
        notes.append(
            f"speed tracked on the record's {tr.lines} strongest lines: mean "
            f"{rpm * tr.mean_ratio:.6g} rpm ({given} gives {rpm:.6g} rpm), changing by "
            f"{100 * tr.drift:+.3g} % from the first instant to the last; the lines are fitted "
            "on the tracked shaft angle (order tracking) and their phase uncertainties include "
            "the tracking's"
        )
    return tr


def _refuse_speed(
    case: Any, record: Record, f_r: float, f_lines: float, speed_source: str, ls: Any
) -> None:
    """Refuse a record whose lines give another speed (one line: the file and the key)."""
    from runout.base.errors import CaseError
    from runout.diagnose._speed import SPEED_RTOL

    rpm, seen = f_r * 60.0, f_lines * 60.0
    why = (
        ""
        if ls is None
        else f" ({100 * ls.share_best:.0f} % of its strongest lines' power lies on the "
        f"bearing's lines at {seen:.5g} rpm, {100 * ls.share_assumed:.0f} % at {rpm:.5g} rpm)"
    )
    if speed_source == "tachometer":
        raise RecordError(
            record.file,
            "column 'rev'",
            f"the record's lines give {seen:.5g} rpm where the tachometer gives {rpm:.5g} rpm, "
            f"beyond {100 * SPEED_RTOL:g} %{why}: check that the tachometer counts revolutions "
            "of the rotating ring (one pulse per revolution)",
        )
    raise CaseError(
        str(case.path),
        "operation.speed",
        f"the record {record.file}'s lines give {seen:.5g} rpm where the case gives "
        f'{rpm:.5g} rpm, beyond {100 * SPEED_RTOL:g} %{why}: give speed = "{seen:.5g} rpm" if '
        "the record was taken at that speed, or a tachometer column rev in the record",
    )


def _one_per_frequency(lines: list[Unattributed], tol: float) -> tuple[Unattributed, ...]:
    """One entry per frequency (within ``tol`` [Hz]): the channel where the line is largest."""
    out: list[Unattributed] = []
    for u in sorted(lines, key=lambda u: -u.pp):
        if all(abs(u.frequency_hz - o.frequency_hz) > tol for o in out):
            out.append(u)
    return tuple(out)


def _has_imperfections(case: Any) -> bool:
    imp = case.imperfections
    return bool(
        imp.inner.orders.size
        or imp.outer.orders.size
        or any(not h.is_empty for h in imp.elements)
        or np.any(imp.diameter_errors)
        or np.any(imp.pitch_errors)
        or imp.slant is not None
    )


def _imperfections(solution: dict[Unknown, complex], z: int) -> Any:
    """BearingImperfections holding the minimum-norm solution."""
    from runout.geometry.imperfections import BearingImperfections, Harmonics, Slant

    rings: dict[int, tuple[list[int], list[complex]]] = {0: ([], []), 1: ([], [])}
    balls: list[tuple[list[int], list[complex]]] = [([], []) for _ in range(z)]
    slant = None
    for u, a in solution.items():
        if u.part in (0, 1):
            rings[u.part][0].append(u.lobes)
            rings[u.part][1].append(a)
        elif u.part == 2:
            balls[u.element][0].append(u.lobes)
            balls[u.element][1].append(a)
        elif u.part == 3 and abs(a) > 0:
            slant = Slant(abs(a), float(np.angle(a)) % TWO_PI)

    def harm(k: list[int], a: list[complex]) -> Harmonics:
        if not k:
            return Harmonics.empty()
        return Harmonics.from_complex(k, a)

    return BearingImperfections(
        inner=harm(*rings[0]),
        outer=harm(*rings[1]),
        elements=[harm(*b) for b in balls],
        slant=slant,
    )


def _single_ball(
    estimates: tuple[Estimate, ...], r: Any, f_r: float, z: int, ename: str
) -> tuple[tuple[Estimate, ...], dict[int, tuple[int, complex]]]:
    """Say which element a ball-set order fits when its two lines agree with one element alone.

    Element z's harmonic B gives the line ν_c + mν_b with the ball-1 equivalent
    P = e^{iβ_z} B and the line ν_c − mν_b with Q = e^{−iβ_z} B: one element alone gives
    |P| = |Q| and P/Q = e^{2iβ_z}, which names it (for an even Z, up to the opposite element).
    """
    out = list(estimates)
    alone: dict[int, tuple[int, complex]] = {}
    sets = [
        i for i, e in enumerate(out) if e.part == ename and e.element is None and len(e.lobes) == 1
    ]
    for m in sorted({out[i].lobes[0] for i in sets if out[i].lobes[0] > 0}):
        f_a = abs(r.cage + m * r.spin) * f_r
        f_b = abs(r.cage - m * r.spin) * f_r
        pair = [i for i in sets if out[i].lobes == (m,)]
        a_line = [i for i in pair if abs(out[i].frequency_hz - f_a) <= 1e-9 * f_a]
        b_line = [i for i in pair if abs(out[i].frequency_hz - f_b) <= 1e-9 * f_b]
        if len(a_line) != 1 or len(b_line) != 1:
            continue
        ea, eb = out[a_line[0]], out[b_line[0]]
        p = ea.amplitude_m * complex(math.cos(ea.phase_rad), math.sin(ea.phase_rad))
        q = eb.amplitude_m * complex(math.cos(eb.phase_rad), math.sin(eb.phase_rad))
        sigma = math.hypot(ea.uncertainty_m, eb.uncertainty_m)
        if abs(abs(p) - abs(q)) > 3.0 * sigma + 0.02 * max(abs(p), abs(q)):
            continue
        half = 0.5 * float(np.angle(p / q))  # β_z modulo π
        step = TWO_PI / z
        j = round(half / step) % z
        err = abs(math.remainder(half - j * step, math.pi))
        k = round((half + math.pi) / step) % z
        if abs(math.remainder(half + math.pi - k * step, math.pi)) < err:
            j, err = k, abs(math.remainder(half + math.pi - k * step, math.pi))
        if err > 3.0 * sigma / max(abs(p), 1e-300) + 0.02:
            continue
        b = 0.5 * (
            p * complex(math.cos(j * step), -math.sin(j * step))
            + q * complex(math.cos(j * step), math.sin(j * step))
        )
        alone[m] = (j, b)
        which = f"{ename} {j + 1}"
        if z % 2 == 0:
            which += (
                f" (or {ename} {(j + z // 2) % z + 1} with the phase + pi: opposite {ename}s "
                "give the same lines)"
            )
        text = (
            f"both lines of {m} lobes are consistent with {which} alone: {abs(b):.4g} m at "
            f"phase {float(np.angle(b)) % TWO_PI:.4g} rad"
        )
        for i in (a_line[0], b_line[0]):
            note = out[i].note
            out[i] = dataclasses.replace(out[i], note=f"{note}; {text}" if note else text)
    return tuple(out), alone


def _equivalent(value: complex, contributions: list[Any]) -> complex:
    """The coefficient of one unknown that alone gives ``value`` (its terms in one equation:
    a slant read by one channel enters twice, once conjugated)."""
    if len(contributions) == 1:
        c = contributions[0]
        a = value / c.gain
        return a.conjugate() if c.conj else a
    m = np.zeros((2, 2))
    for c in contributions:
        qr, qi = c.gain.real, c.gain.imag
        sign = -1.0 if c.conj else 1.0
        if c.unknown.real:
            m[:, 0] += (qr, qi)
        else:
            m[0] += (qr, -qi * sign)
            m[1] += (qi, qr * sign)
    sol, *_ = np.linalg.lstsq(m, np.array([value.real, value.imag]), rcond=1e-12)
    return complex(sol[0], sol[1])


def _estimates(
    detected: list[tuple[Equation, complex, float]],
    f_r: float,
    record: Record,
    ename: str,
    z: int,
    tracking: Any = None,
) -> tuple[Estimate, ...]:
    rows = []
    total = 0.0
    two = len(record.channels) == 2
    for e, v, s in detected:
        contribs = sorted(
            e.contributions, key=lambda c: (c.unknown.part, c.unknown.lobes, c.unknown.element)
        )
        rep = contribs[0]
        a = _equivalent(v, [c for c in contribs if c.unknown == rep.unknown])
        amp = abs(a)
        gain = abs(v) / amp if amp > 0.0 else abs(rep.gain)
        parts = sorted({c.unknown.part for c in contribs})
        part = "+".join(ename if p == 2 else PART_NAMES[p] for p in parts)
        lobes = tuple(sorted({c.unknown.lobes for c in contribs}))
        elements = {c.unknown.element for c in contribs}
        element = None
        notes: list[str] = []
        first = f"{part.split('+')[0]} {rep.unknown.lobes}-lobe"
        if e.spread_hz > 0.0:
            # fitted at one member's frequency: a member at df from it drifts by df T cycles
            x = e.spread_hz * record.duration
            bias = 1.0 - math.sin(math.pi * x) / (math.pi * x)
            s = math.hypot(s, bias * abs(v))
            need = math.ceil(JOINT_FIT / e.spread_hz * f_r)
            notes.append(
                f"fitted as one line with lines {e.spread_hz:.3g} Hz away, closer than the "
                f"record resolves (about {need} revolutions would separate them): the {first} "
                f"deviation alone gives it; the amplitude may be off by {100 * bias:.2g} % "
                "(in the uncertainty)"
            )
        elif len({c.unknown for c in contribs}) > 1 and parts in ([0], [1]):
            notes.append(
                f"{part} {' and '.join(map(str, lobes))} lobes give one line"
                + ("" if two else " and one channel cannot tell their whirls apart")
                + f": the {first} deviation alone gives it"
            )
        elif len(parts) > 1:
            notes.append(f"lines of several parts coincide: the {first} deviation alone gives it")
        if 2 in parts and len(elements) > 1:
            notes.append(
                f"{ename} set: {ename} 1 alone with this deviation gives the line; the record "
                f"sees one combination of the {z} {ename}s per line"
            )
        elif parts == [2]:
            element = next(iter(elements)) + 1
        if parts == [2] and lobes == (0,):
            notes.append("size error: the phase places the oversize element (0: element 1)")
        note = "; ".join(notes)
        power = abs(v) ** 2 * (2.0 if two else 1.0)  # both whirls over two channels
        total += power
        f_line = abs(e.omega) * f_r
        phase_sigma = s / abs(v) if abs(v) > 0.0 else math.pi
        if tracking is not None:
            # the warp's own uncertainty, and the correction itself where it was not applied
            phase_sigma = math.hypot(phase_sigma, tracking.phase_sigma(f_line))
            if not tracking.applied:
                phase_sigma = math.hypot(phase_sigma, tracking.phase_shift(f_line))
        rows.append(
            (
                power,
                part,
                lobes,
                element,
                amp,
                float(np.angle(a)) % TWO_PI,
                s / gain,
                f_line,
                ("forward" if e.omega > 0 else "backward") if two else "both",
                note,
                min(phase_sigma, math.pi),
            )
        )
    out = [
        Estimate(
            part=p,
            lobes=lo,
            element=el,
            amplitude_m=float(amp),
            phase_rad=float(ph),
            uncertainty_m=float(unc),
            frequency_hz=float(f),
            whirl=w,
            share=float(pw / total) if total > 0 else 0.0,
            note=note,
            phase_uncertainty_rad=float(sph),
        )
        for pw, p, lo, el, amp, ph, unc, f, w, note, sph in rows
    ]
    return tuple(sorted(out, key=lambda e: -e.share))


def _explained(
    case: Any,
    operation: Any,
    alpha: float,
    variant: str,
    imperfections: Any,
    record: Record,
    f_r: float,
    time_axis: FloatArray | None = None,
    speed_ratio: float = 1.0,
) -> tuple[float, tuple[FloatArray, FloatArray, FloatArray] | None]:
    """Explained variance of the record by the forward model of the estimated deviations.

    ``time_axis``: the tracked instants τ(t) (the shaft at θ = 2π f_r τ), when the lines were
    fitted on them; ``speed_ratio`` the record's mean speed over f_r (velocity scale).
    """
    from runout.analysis.spectrum import amplitude_spectrum
    from runout.models.linear import (
        SpectralLines,
        closed_form_terms,
        rates,
        spectral_lines,
        synthesize,
    )

    r = rates(case.bearing, operation, alpha)
    terms = closed_form_terms(imperfections, r, alpha, variant)
    lines = spectral_lines(terms, f_r, imperfections.n_elements, True)
    lines = lines.select(lines.order > 0)
    if record.quantity == "velocity":
        lines = lines.derivative()
        factor = TWO_PI * f_r * speed_ratio  # du/dt = 2π f_r du/dθ
    else:
        factor = 1.0
    # the compiled synthesis runs from θ = 0: turn each line to the record's first instant
    shift = np.exp(1j * lines.order * TWO_PI * f_r * float(record.time[0]))
    lines = SpectralLines(
        lines.order, lines.c_plus * shift, lines.c_minus / shift, lines.labels, f_r
    )
    if time_axis is not None and time_axis is not record.time:
        # the shaft angle the lines were fitted on (order tracking)
        x, y = lines.evaluate(TWO_PI * f_r * (time_axis - float(record.time[0])))
    else:
        _, x, y = synthesize(lines, f_r * record.step * record.samples, record.samples)
    num = den = 0.0
    recon: dict[str, FloatArray] = {"x": x * factor, "y": y * factor}
    for ch, values in record.channels.items():
        res = values - recon[ch]
        num += float(np.var(res))
        den += float(np.var(values))
    # a record with no variance (rounded to zero) has nothing explained, not everything
    explained = 1.0 - num / den if den > 0.0 else 0.0
    first = sorted(record.channels)[0]
    fs = 1.0 / record.step
    meas = amplitude_spectrum(
        record.channels[first] - record.channels[first].mean(), sample_rate=fs
    )
    rec = amplitude_spectrum(recon[first] - recon[first].mean(), sample_rate=fs)
    return float(explained), (meas.frequencies, meas.amplitude, rec.amplitude)


def _ranges(values: list[int]) -> str:
    return ", ".join(str(v) for v in values[:8]) + (", ..." if len(values) > 8 else "")


def _not_observable(
    z: int,
    channels: tuple[str, ...],
    terms: Any,
    k_ring: int,
    m_ball: int,
    f_hi: float,
    ename: str,
    rates: Any,
) -> list[str]:
    out = [
        f"ring waviness of k lobes with k != nZ +/- 1 (Z = {z}; e.g. "
        f"{_ranges([k for k in range(2, 3 * z) if (k + 1) % z and (k - 1) % z])}) gives no "
        "first-order radial line (seed 002 eq. 33, 37): it cannot be seen",
        f"odd {ename} harmonics cancel across the {ename}'s diameter (seed 002 eq. 26)",
        f"which {ename} carries a deviation: each even order gives two lines, two combinations "
        f"of the {z} {ename}s; equal deviations on every {ename} cancel (eq. 38-40)",
        "axial waviness (nZ lobes) and the axial motion: the record is radial",
        f"lobes above {k_ring} (rings) and {m_ball} ({ename}s): their lines lie above the "
        f"Nyquist frequency {f_hi / 0.999:.6g} Hz or beyond the lines fitted",
    ]
    static = static_unknowns(terms)
    for u in static:
        name = PART_NAMES[u.part]
        if u.part in (0, 1) and u.lobes == 1:
            out.append(
                f"eccentricity of the stationary {name} ring: a static offset, removed with "
                "the record's mean"
            )
        elif u.part == 3:
            out.append("slant of a stationary inner ring: a static offset")
    if len(channels) == 1:
        for name, nu in (("inner", rates.inner), ("outer", rates.outer)):
            if nu == 0.0:
                out.append(
                    f"{name} (stationary) waviness of nZ - 1 and nZ + 1 lobes: one line with "
                    "one channel (only their combination is observable; a record of both x "
                    "and y separates them by their whirl)"
                )
        out.append("forward and backward whirl: one channel cannot tell them apart")
    return out


def estimated_case_text(case: Any, imperfections: Any, variant: str, rotation_hz: float) -> str:
    """Case-file text: ``case``'s bearing and operation with ``imperfections`` (SI numbers).

    Parameters
    ----------
    case : runout.case.model.Case
        The case whose bearing, material, operation, analysis and dynamics tables are kept
        (its own imperfection and study tables are dropped).
    imperfections : runout.geometry.imperfections.BearingImperfections
        The deviations to write: amplitudes [m], phases [rad].
    variant : str
        Linear-model variant written into ``[analysis]``.
    rotation_hz : float
        Speed of the rotating ring [Hz]; written (in rpm, with the case's sign) when it
        differs from the case's speed.

    Returns
    -------
    str
        TOML text with a comment header, the kept tables, the slant and one ``[[waviness]]``
        table per harmonic (amplitude [m], phase [rad]).
    """
    import tomli_w

    document = case.to_document()
    for key in ("waviness", "waviness_spectrum", "profile", "slant", "elements", "study"):
        document.pop(key, None)
    analysis = dict(document.get("analysis", {}))
    for key in ("limit", "bands", "limit_on"):
        analysis.pop(key, None)
    analysis["model"] = "linear"
    analysis["linear_variant"] = variant
    document["analysis"] = analysis
    operation = dict(document.get("operation", {}))
    speed = case.operation.speed
    # the tachometer's speed (also where the case gave none): the record's lines come back
    if abs(abs(speed) - rotation_hz) > 1e-9 * rotation_hz:
        operation["speed"] = f"{math.copysign(rotation_hz, speed) * 60.0!r} rpm"
        document["operation"] = operation
    waviness: list[dict[str, Any]] = []
    for part, h in (("inner", imperfections.inner), ("outer", imperfections.outer)):
        for k, a, p in zip(h.orders, h.amplitudes, h.phases, strict=True):
            waviness.append(
                {"part": part, "order": int(k), "amplitude": float(a), "phase": float(p)}
            )
    ename = _element_name(case)
    for j, h in enumerate(imperfections.elements):
        for k, a, p in zip(h.orders, h.amplitudes, h.phases, strict=True):
            waviness.append(
                {
                    "part": ename,
                    "order": int(k),
                    "amplitude": float(a),
                    "phase": float(p),
                    "element": j + 1,
                }
            )
    title = f"{case.title or Path(case.path).stem}: deviations estimated by runout diagnose"
    chunks = [tomli_w.dumps({"title": title})]
    order = ["bearing", "material", "operation", "analysis", "dynamics"]
    for name in order:
        if name in document:
            chunks.append(tomli_w.dumps({name: document[name]}))
    if imperfections.slant is not None:
        s = imperfections.slant
        chunks.append(
            tomli_w.dumps(
                {
                    "slant": {
                        "part": "inner",
                        "amplitude": float(s.amplitude),
                        "phase": float(s.phase),
                    }
                }
            )
        )
    chunks.extend("[[waviness]]\n" + tomli_w.dumps(entry) for entry in waviness)
    head = (
        "# Deviations estimated by `runout diagnose` from a measured record: the smallest\n"
        "# deviations that give the detected lines (see docs/models/diagnosis.md).\n"
    )
    return head + "\n".join(chunk.strip("\n") + "\n" for chunk in chunks)


class _CallableModule(type(sys.modules[__name__])):  # type: ignore[misc]
    """``runout.diagnose.fit(...)`` works whether the name resolves to this module (imported as
    ``runout.diagnose.fit``) or to the function (the package's lazy export)."""

    def __call__(self, *args: Any, **kwargs: Any) -> Diagnosis:
        return diagnose(*args, **kwargs)


sys.modules[__name__].__class__ = _CallableModule
