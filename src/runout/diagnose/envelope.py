r"""Envelope diagnosis of a measured acceleration record: which localized defect, if any.

The record's squared-envelope spectrum (:mod:`runout.analysis.envelope`), in the band the fast
kurtogram finds most impulsive or in a band given, is searched for the defect frequencies of
the case's bearing at the record's speed: the outer race's ball pass frequency (BPFO), the
inner race's (BPFI), the ball defect frequency (BDF, twice the ball spin: a spalled ball
strikes both races each spin) and the cage frequency (FTF), each with its harmonics. A rolling
element slips, so a defect line lies within a relative *slip tolerance* of its kinematic
frequency (1-2 % in service; :data:`SLIP_TOLERANCE`); the n-th harmonic within n times that.

Evidence per candidate part (:class:`Candidate`): the largest envelope-spectrum bin in each
harmonic's window and its *SNR*, its amplitude over the median of the envelope spectrum within
± half the shaft speed (the local floor); a harmonic is *found* at an SNR of
:data:`SNR_FOUND` or more. The sidebands of the modulation are searched too: a defect on the
rotating ring passes through the load zone once a revolution (sidebands at ± the shaft speed
about each harmonic), a ball's defect once a cage revolution (± FTF); a defect on the
stationary ring has none. A peak that also falls within another candidate's harmonic window
or within the slip tolerance of a shaft harmonic is *shared* and counts half.

The score (:func:`score`) is the sum of 10 log10(SNR) [dB] over the harmonics found (weight 1,
a shared one 1/2) and half that over the sidebands found. A part is *likely* when its
fundamental is found and its score reaches :data:`SCORE_LIKELY`; *possible* when any harmonic
is found; otherwise there is no evidence of it. The thresholds were chosen from the false-alarm
rate measured on records of Gaussian noise and of smooth vibration (shaft harmonics and noise):
see the validation page. Randall and Antoni (2011), sec. 5.1-5.2 and Table 1, describe the
signatures used.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

import numpy as np
from numpy.typing import NDArray

from runout.analysis.envelope import ORDER_TRACKING_UPSAMPLE, at_uniform_angle
from runout.diagnose._record import Record, RecordError, read_record

__all__ = [
    "HARMONICS",
    "MIN_DEFECT_PERIODS",
    "NYQUIST_FACTOR",
    "ORDER_TRACKING_UPSAMPLE",
    "PEAKS_SHOWN",
    "SCORE_LIKELY",
    "SLIP_TOLERANCE",
    "SNR_FOUND",
    "Candidate",
    "EnvelopeDiagnosis",
    "Evidence",
    "Peak",
    "diagnose_envelope",
    "order_tracked",
    "score",
]

FloatArray = NDArray[np.float64]
Assessment = Literal["likely", "possible", "no evidence"]

#: Default relative slip tolerance of a defect line [-]: rolling elements slip 1-2 %.
SLIP_TOLERANCE = 0.02
#: Harmonics of each defect frequency searched.
HARMONICS = 3
#: SNR (amplitude over the local median of the envelope spectrum) a harmonic needs to be found.
SNR_FOUND = 4.0
#: Score [dB] a candidate with its fundamental found needs to be called likely.
SCORE_LIKELY = 24.0
#: Largest envelope-spectrum peaks listed in the output.
PEAKS_SHOWN = 10
#: Fewest cage revolutions a record must span (the resolution must split FTF sidebands).
MIN_DEFECT_PERIODS = 8.0
#: The Nyquist frequency must be at least this many times the highest fundamental searched:
#: the impacts ring a resonance well above the defect frequencies, and the band holding it
#: must be wider than the harmonics read.
NYQUIST_FACTOR = 8.0

_NAMES = {"outer": "BPFO", "inner": "BPFI", "ball": "BDF", "cage": "FTF"}
_WORDS = {
    "outer": "outer race defect",
    "inner": "inner race defect",
    "ball": "rolling element defect",
    "cage": "cage defect",
}


@dataclass(frozen=True)
class Peak:
    """A local maximum of the envelope spectrum.

    Attributes
    ----------
    frequency_hz : float
        Frequency [Hz] (parabolic interpolation between bins).
    amplitude : float
        Squared-envelope amplitude [(m/s^2)^2].
    snr : float
        Amplitude over the local median of the envelope spectrum [-].
    label : str or None
        What it matches: ``"BPFO"``, ``"2xBPFI+fr"`` (second harmonic of BPFI, upper sideband
        at the shaft speed), ``"BDF-FTF"``, ``"3xfr"`` (a shaft harmonic); None when nothing.
    """

    frequency_hz: float
    amplitude: float
    snr: float
    label: str | None

    def to_json(self) -> dict[str, Any]:
        """The peak as JSON.

        Returns
        -------
        dict
            ``frequency_hz``, ``amplitude``, ``snr``, ``label``.
        """
        return dataclasses.asdict(self)


@dataclass(frozen=True)
class Evidence:
    """One searched line of a candidate: a harmonic or one of its sidebands.

    Attributes
    ----------
    harmonic : int
        Harmonic number n of the defect frequency (1: the fundamental).
    sideband : int
        0 for the harmonic itself, -1 / +1 for its lower / upper modulation sideband.
    expected_hz : float
        Kinematic frequency [Hz].
    frequency_hz : float
        Frequency of the largest bin in the window [Hz].
    snr : float
        Its amplitude over the local median [-].
    found : bool
        ``snr >= SNR_FOUND``.
    shared : bool
        Also within another candidate's harmonic window or a shaft harmonic's.
    """

    harmonic: int
    sideband: int
    expected_hz: float
    frequency_hz: float
    snr: float
    found: bool
    shared: bool

    def to_json(self) -> dict[str, Any]:
        """The line as JSON.

        Returns
        -------
        dict
            The fields above, by name.
        """
        return dataclasses.asdict(self)


@dataclass(frozen=True)
class Candidate:
    """The evidence of a defect on one part.

    Attributes
    ----------
    part : {"outer", "inner", "ball", "cage"}
    frequency_hz : float
        Its defect frequency at the record's speed [Hz].
    order : float
        The same in orders of the rotating ring [-].
    sideband_hz : float or None
        Spacing of its modulation sidebands [Hz] (None: not modulated).
    lines : tuple of Evidence
        Every harmonic and sideband searched.
    score : float
        :func:`score` [dB] of its lines and its modulation's.
    assessment : {"likely", "possible", "no evidence"}
    modulation : tuple of Evidence
        The ball's cage modulation: the FTF harmonics read as the ball's (its own lines found
        with them), weighted as sidebands; empty otherwise.
    """

    part: str
    frequency_hz: float
    order: float
    sideband_hz: float | None
    lines: tuple[Evidence, ...]
    score: float
    assessment: Assessment
    modulation: tuple[Evidence, ...] = ()

    @property
    def harmonics_found(self) -> list[int]:
        """Harmonic numbers found."""
        return [e.harmonic for e in self.lines if e.sideband == 0 and e.found]

    def to_json(self) -> dict[str, Any]:
        """The candidate as JSON.

        Returns
        -------
        dict
            ``part``, ``frequency_hz``, ``order``, ``score``, ``assessment`` and ``evidence``.
        """
        harmonics = [e for e in self.lines if e.sideband == 0]
        sidebands = [e for e in self.lines if e.sideband != 0]
        return {
            "part": self.part,
            "frequency_hz": self.frequency_hz,
            "order": self.order,
            "score": self.score,
            "assessment": self.assessment,
            "evidence": {
                "harmonics_searched": len(harmonics),
                "harmonics_found": self.harmonics_found,
                "sideband_spacing_hz": self.sideband_hz,
                "sidebands_found": sum(1 for e in sidebands if e.found),
                "harmonics": [e.to_json() for e in harmonics],
                "sidebands": [e.to_json() for e in sidebands],
                "modulation_found": sum(1 for e in self.modulation if e.found),
                "modulation": [e.to_json() for e in self.modulation],
            },
        }


@dataclass(frozen=True, eq=False)
class EnvelopeDiagnosis:
    """Result of :func:`diagnose_envelope`.

    Attributes
    ----------
    record : str
        The record file.
    speed_hz : float
        Speed of the rotating ring used [Hz].
    speed_source : {"case", "tachometer"}
    sample_rate_hz, duration_s : float
        Of the record [Hz], [s].
    band_hz : (float, float)
        Band the envelope was taken in [Hz].
    band_source : {"kurtogram", "given"}
    kurtosis : float
        Spectral kurtosis of that band [-] (0 for Gaussian noise).
    slip_tolerance : float
        Relative tolerance of the defect frequencies used [-].
    peaks : tuple of Peak
        The largest envelope-spectrum peaks, largest first.
    defects : tuple of Candidate
        Every part, most likely first.
    verdict : str
        Plain words: "outer race defect likely", "no defect evidence", ...
    notes : tuple of str
    spectrum : EnvelopeSpectrum
        The squared-envelope spectrum (for the figure).
    floor : ndarray
        Its local median [(m/s^2)^2].
    """

    record: str
    speed_hz: float
    speed_source: str
    sample_rate_hz: float
    duration_s: float
    band_hz: tuple[float, float]
    band_source: str
    kurtosis: float
    slip_tolerance: float
    peaks: tuple[Peak, ...]
    defects: tuple[Candidate, ...]
    verdict: str
    notes: tuple[str, ...] = ()
    spectrum: Any = field(default=None, repr=False)
    floor: Any = field(default=None, repr=False)

    def to_json(self) -> dict[str, Any]:
        """The JSON of ``runout diagnose --envelope --json``.

        Returns
        -------
        dict
            The contract the diagnosis page documents: ``method``, ``envelope``, ``defects``,
            ``verdict``, ``notes`` and the record's speed and sampling.
        """
        return {
            "record": self.record,
            "method": "envelope",
            "speed_hz": self.speed_hz,
            "speed_source": self.speed_source,
            "sample_rate_hz": self.sample_rate_hz,
            "duration_s": self.duration_s,
            "slip_tolerance": self.slip_tolerance,
            "envelope": {
                "band_hz": list(self.band_hz),
                "band_source": self.band_source,
                "spectral_kurtosis": self.kurtosis,
                "resolution_hz": float(self.spectrum.resolution_hz),
                "peaks": [p.to_json() for p in self.peaks],
            },
            "defects": [d.to_json() for d in self.defects],
            "verdict": self.verdict,
            "notes": list(self.notes),
        }


def score(
    lines: tuple[Evidence, ...] | list[Evidence],
    modulation: tuple[Evidence, ...] | list[Evidence] = (),
) -> float:
    """Ranking score of a candidate [dB].

    Parameters
    ----------
    lines : sequence of Evidence
        Its searched harmonics and sidebands.
    modulation : sequence of Evidence, optional
        The ball's cage modulation (:attr:`Candidate.modulation`).

    Returns
    -------
    float
        Sum over the lines found of w * 10 log10(snr): w = 1 for a harmonic, 1/2 for a
        sideband, halved again for a shared line; 0 when nothing is found. The modulation
        lines weigh as sidebands.
    """
    total = 0.0
    for e in lines:
        if not e.found:
            continue
        w = (1.0 if e.sideband == 0 else 0.5) * (0.5 if e.shared else 1.0)
        total += w * 10.0 * math.log10(e.snr)
    for e in modulation:
        if e.found:
            total += 0.5 * (0.5 if e.shared else 1.0) * 10.0 * math.log10(e.snr)
    return total


def _local_floor(amplitude: FloatArray, width_bins: int) -> FloatArray:
    from scipy.ndimage import median_filter

    size = max(11, 2 * (width_bins // 2) + 1)
    floor = median_filter(amplitude, size=size, mode="nearest")
    tiny = float(np.max(amplitude)) * 1e-12 + 1e-300
    return np.asarray(np.maximum(floor, tiny), dtype=np.float64)


def _refine(f: FloatArray, a: FloatArray, i: int) -> float:
    """Peak frequency by a parabola through the bin and its neighbours [Hz]."""
    if 0 < i < a.size - 1:
        left, mid, right = a[i - 1], a[i], a[i + 1]
        den = left - 2.0 * mid + right
        if den < 0.0:
            delta = 0.5 * (left - right) / den
            return float(f[i] + max(-0.5, min(0.5, delta)) * (f[1] - f[0]))
    return float(f[i])


def _speed(case: Any, record: Record) -> tuple[Any, str, list[str]]:
    """The operation at the record's speed (tachometer over case), its source, notes."""
    from runout.base.errors import CaseError

    operation = case.operation
    tacho = record.tachometer_speed()
    if tacho is not None:
        nominal = abs(operation.speed)
        scale = tacho / nominal if nominal > 0.0 else 1.0
        operation = dataclasses.replace(
            operation,
            speed=tacho if nominal == 0.0 else operation.speed * scale,
            other_ring_speed=operation.other_ring_speed * scale,
        )
        given = f"the case gives {nominal * 60:.6g} rpm" if nominal > 0 else "the case gives none"
        return (
            operation,
            "tachometer",
            [f"speed from the tachometer: {tacho * 60:.6g} rpm ({given})"],
        )
    if operation.speed == 0.0:
        raise CaseError(
            str(case.path),
            "operation.speed",
            "the envelope diagnosis needs the speed of the rotating ring: give [operation] "
            "speed, or a tachometer column rev in the record",
        )
    return operation, "case", []


def order_tracked(record: Record) -> tuple[Record, str]:
    """The record resampled at uniform shaft angle from its tachometer (computed order tracking).

    Parameters
    ----------
    record : Record
        With ``revolution_starts`` (at least 3).

    Returns
    -------
    Record
        As many samples over the same span, at equal increments of the shaft angle, on the time
        axis of the mean speed f̄ = revolutions / span (``tachometer_hz`` = f̄): a line at a
        fixed order k of the shaft is at k f̄ Hz whatever the speed did.
    str
        The note saying so, with the speed's largest deviation from f̄ per revolution.

    Notes
    -----
    The shaft angle is the tachometer's revolution count interpolated between the instants each
    revolution starts (monotone cubic, PCHIP; before the first and after the last, at the
    speed of the first and the last revolution); the record, upsampled
    :data:`ORDER_TRACKING_UPSAMPLE` times by a polyphase filter, is interpolated linearly at the
    instants of uniform angle. K. R. Fyfe and E. D. S. Munck, "Analysis of computed order
    tracking", Mechanical Systems and Signal Processing 11(2), 1997; J. Antoni and R. B.
    Randall, "Rolling element bearing diagnostics — A tutorial", MSSP 25, 2011, sec. 2 (speed
    fluctuations smear the defect lines; order tracking before the envelope analysis).
    """
    from scipy.interpolate import PchipInterpolator

    starts = np.asarray(record.revolution_starts, dtype=np.float64)
    turns = np.arange(starts.size, dtype=np.float64)
    t = record.time
    # the shaft angle [rev] at each sample: monotone cubic between revolution starts, the
    # first and the last revolution's speed before and after them
    angle = PchipInterpolator(starts, turns, extrapolate=False)(t)
    before, after = t < starts[0], t > starts[-1]
    angle[before] = (t[before] - starts[0]) / (starts[1] - starts[0])
    angle[after] = turns[-1] + (t[after] - starts[-1]) / (starts[-1] - starts[-2])
    span = float(t[-1] - t[0])
    mean_hz = float(angle[-1] - angle[0]) / span
    uniform_time = t
    channels = {}
    for role, values in record.channels.items():
        uniform_time, channels[role], _ = at_uniform_angle(t, angle, values)
    periods = np.diff(starts)
    spread = float(np.max(np.abs(periods * mean_hz - 1.0)))
    tracked = dataclasses.replace(
        record,
        time=uniform_time,
        channels=channels,
        tachometer_hz=mean_hz,
        revolution_starts=None,
    )
    note = (
        f"order tracking: the record resampled at uniform shaft angle from the tachometer "
        f"({angle[-1] - angle[0]:.4g} revolutions in {span:.4g} s; the speed per revolution "
        f"varies by up to {100 * spread:.3g} % about its mean {mean_hz * 60:.6g} rpm), the "
        "envelope spectrum read in orders times the mean speed"
    )
    return tracked, note


def diagnose_envelope(
    case: Any,
    record: Record | str | Path,
    *,
    band: tuple[float, float] | None = None,
    slip_tolerance: float = SLIP_TOLERANCE,
) -> EnvelopeDiagnosis:
    """Envelope diagnosis of an acceleration record (see the module doc).

    Parameters
    ----------
    case : runout.case.model.Case or path
        Bearing and operation (speed, rotating ring); its imperfections are ignored.
    record : Record or path
        An acceleration record (``quantity="acceleration"``) or its CSV file (a time column
        and one acceleration column ``a_m_per_s2`` or ``a [m/s^2]``, ``a [g]``).
    band : (float, float), optional
        Pass band [Hz]; default the fast kurtogram's most impulsive band at least
        ``(HARMONICS + 1)`` times the highest fundamental wide.
    slip_tolerance : float
        Relative tolerance of the defect frequencies [-], 0 to 0.1 (default 0.02).

    Returns
    -------
    EnvelopeDiagnosis

    Raises
    ------
    RecordError
        An unreadable record, one too short (fewer than :data:`MIN_DEFECT_PERIODS` cage
        revolutions) or sampled too slowly (Nyquist below :data:`NYQUIST_FACTOR` times the
        highest defect frequency), or a band outside the record's frequencies.
    CaseError
        No speed (neither the case's nor a tachometer), a spindle case.
    ValueError
        A slip tolerance outside [0, 0.1].

    Notes
    -----
    Randall and Antoni, "Rolling element bearing diagnostics — A tutorial" (MSSP 25, 2011),
    sec. 5.1 (the squared envelope spectrum of the band chosen by the kurtogram) and Table 1
    (signatures: BPFO unmodulated for a stationary outer race, BPFI with shaft-speed sidebands,
    the ball's 2 x BSF with cage sidebands).
    """
    from runout.analysis.envelope import fast_kurtogram, squared_envelope_spectrum
    from runout.base.errors import CaseError
    from runout.case.limits import case_budget
    from runout.diagnose.fit import _load
    from runout.geometry.kinematics import bearing_frequencies
    from runout.geometry.loading import operating_contact_angle

    if not (math.isfinite(slip_tolerance) and 0.0 <= slip_tolerance <= 0.1):
        raise ValueError(
            f"slip_tolerance must be a fraction in [0, 0.1] (0.02 = 2 %), got {slip_tolerance!r}"
        )
    c = _load(case)
    if getattr(c, "spindle", None) is not None:
        raise CaseError(
            str(c.path),
            "bearings",
            "the envelope diagnosis reads one bearing's defect frequencies: give a case with "
            "one [bearing] (the bearing the record was measured on), not a spindle",
        )
    if not isinstance(record, Record):
        record = read_record(record, "acceleration", limits=case_budget(c))
    if record.quantity != "acceleration" or "a" not in record.channels:
        raise RecordError(record.file, "", "the envelope diagnosis needs an acceleration column")
    notes: list[str] = []
    if record.revolution_starts is not None:
        record, tracked = order_tracked(record)
        notes.append(tracked)
    operation, speed_source, speed_notes = _speed(c, record)
    notes += speed_notes
    alpha, _ = operating_contact_angle(c.bearing, operation)
    freqs = bearing_frequencies(c.bearing, operation, alpha)
    f_r = freqs.rotation
    rotating = operation.rotating_ring
    fundamentals = {
        "outer": freqs.ball_pass_outer,
        "inner": freqs.ball_pass_inner,
        "ball": 2.0 * freqs.ball_spin,
        "cage": freqs.cage,
    }
    # the rotating ring's defect passes the load zone once a revolution of that ring relative
    # to the load (the shaft speed); a ball's once a cage revolution; the stationary ring's never
    sidebands: dict[str, float | None] = {
        "outer": f_r if rotating == "outer" else None,
        "inner": f_r if rotating == "inner" else None,
        "ball": freqs.cage,
        "cage": None,
    }
    fs = 1.0 / record.step
    duration = record.duration
    signal = record.channels["a"]
    top = max(fundamentals.values())
    if duration * freqs.cage < MIN_DEFECT_PERIODS:
        need = MIN_DEFECT_PERIODS / freqs.cage
        raise RecordError(
            record.file,
            "",
            f"too short: {duration:.4g} s holds {duration * freqs.cage:.3g} cage revolutions; "
            f"at least {MIN_DEFECT_PERIODS:g} ({need:.3g} s at {f_r * 60:.6g} rpm) are needed "
            "to resolve the cage-rate sidebands",
        )
    if 0.5 * fs < NYQUIST_FACTOR * top:
        raise RecordError(
            record.file,
            f"column {record.column('time')!r}",
            f"sampled at {fs:.6g} Hz: the Nyquist frequency must be at least "
            f"{NYQUIST_FACTOR:g} x the highest defect frequency ({top:.6g} Hz, BPFI or BPFO at "
            f"{f_r * 60:.6g} rpm), i.e. a sample rate of {2 * NYQUIST_FACTOR * top:.6g} Hz or "
            "more, for the band of the resonance the impacts excite",
        )
    need_width = (HARMONICS + 1) * top
    if band is None:
        # the band lies above the lines it is read at (not around them)
        kurtogram = fast_kurtogram(signal, fs, min_bandwidth=need_width, min_low=need_width)
        band_used = kurtogram.band_hz
        band_source = "kurtogram"
    else:
        lo, hi = float(band[0]), float(band[1])
        if not (math.isfinite(lo) and math.isfinite(hi) and 0.0 <= lo < hi <= 0.5 * fs):
            raise RecordError(
                record.file,
                "",
                f"--band {lo:g},{hi:g} Hz is not within the record's frequencies: give "
                f"0 <= LO < HI <= {0.5 * fs:.6g} Hz (half the sample rate)",
            )
        if hi - lo < need_width:
            notes.append(
                f"the band given is {hi - lo:.6g} Hz wide: the envelope spectrum reaches only "
                f"that frequency, harmonics above it are not searched (a band of "
                f"{need_width:.6g} Hz or more reads {HARMONICS} harmonics of every defect)"
            )
        band_used = (lo, hi)
        band_source = "given"
    from runout.analysis.envelope import complex_envelope, spectral_kurtosis

    spectrum = squared_envelope_spectrum(signal, fs, band_used)
    kurt = float(spectral_kurtosis(complex_envelope(signal, fs, band_used)))
    f, amp = spectrum.frequency, spectrum.amplitude
    df = spectrum.resolution_hz
    floor = _local_floor(amp, round(f_r / df))
    snr = amp / floor
    f_max = float(f[-1])

    def window(center: float) -> tuple[float, float]:
        # the slip moves the n-th harmonic n times as far; 1.5 bins: the peak's own width
        half = slip_tolerance * abs(center) + 1.5 * df
        return center - half, center + half

    # every candidate's harmonic windows, and the shaft harmonics', to mark shared peaks
    harmonic_windows: dict[str, list[tuple[float, float]]] = {}
    for part, fd in fundamentals.items():
        harmonic_windows[part] = [window(h * fd) for h in range(1, HARMONICS + 1)]
    shaft_windows = [
        (h * f_r * (1 - slip_tolerance) - 1.5 * df, h * f_r * (1 + slip_tolerance) + 1.5 * df)
        for h in range(1, int(f_max / f_r) + 2)
    ]

    def shared_with(part: str, freq: float) -> bool:
        if any(lo <= freq <= hi for lo, hi in shaft_windows):
            return True
        return any(
            lo <= freq <= hi
            for other, ws in harmonic_windows.items()
            if other != part
            for lo, hi in ws
        )

    def search(part: str, harmonic: int, side: int, expected: float) -> Evidence | None:
        lo, hi = window(expected)
        i1 = max(1, math.ceil(lo / df))
        i2 = min(f.size - 1, math.floor(hi / df))
        if i1 > i2 or hi > f_max:
            return None
        i = i1 + int(np.argmax(amp[i1 : i2 + 1]))
        freq = _refine(f, amp, i)
        value = float(snr[i])
        return Evidence(
            harmonic, side, expected, freq, value, value >= SNR_FOUND, shared_with(part, freq)
        )

    candidates: list[Candidate] = []
    for part, fd in fundamentals.items():
        lines: list[Evidence] = []
        spacing = sidebands[part]
        for h in range(1, HARMONICS + 1):
            e = search(part, h, 0, h * fd)
            if e is None:
                continue
            lines.append(e)
            if spacing is not None:
                for side in (-1, 1):
                    s = search(part, h, side, h * fd + side * spacing)
                    if s is not None:
                        lines.append(s)
        total = score(lines)
        candidates.append(
            Candidate(
                part, fd, fd / f_r, spacing, tuple(lines), total, _assess(tuple(lines), total)
            )
        )
    candidates = _ball_modulation(candidates)
    candidates = _explained(candidates, df)
    # a ball defect modulated by the cage puts lines at FTF: the cage is not called likely
    # on lines a likely ball defect, or the ball's modulation, explains
    ball = next(cd for cd in candidates if cd.part == "ball")
    if ball.assessment == "likely" or ball.modulation:
        candidates = [
            dataclasses.replace(cd, assessment="possible")
            if cd.part == "cage" and cd.assessment == "likely"
            else cd
            for cd in candidates
        ]
        notes.append(
            "lines at the cage frequency (FTF) are read as the ball defect's cage modulation"
        )
    rank = {"likely": 2, "possible": 1, "no evidence": 0}
    candidates.sort(key=lambda cd: (rank[cd.assessment], cd.score), reverse=True)
    peaks = _peaks(f, amp, snr, fundamentals, sidebands, f_r, slip_tolerance, df)
    verdict = _verdict(candidates)
    if band_source == "kurtogram":
        notes.append(
            f"band {band_used[0]:.6g}-{band_used[1]:.6g} Hz chosen by the fast kurtogram "
            f"(spectral kurtosis {kurt:.3g}; bands narrower than {need_width:.6g} Hz not "
            "considered)"
        )
    if not any(cd.assessment != "no evidence" for cd in candidates) and kurt < 0.5:
        notes.append(
            f"the band's spectral kurtosis is {kurt:.3g}: the record is not impulsive there "
            "(Gaussian noise reads 0)"
        )
    return EnvelopeDiagnosis(
        record=record.file,
        speed_hz=f_r,
        speed_source=speed_source,
        sample_rate_hz=fs,
        duration_s=duration,
        band_hz=(float(band_used[0]), float(band_used[1])),
        band_source=band_source,
        kurtosis=kurt,
        slip_tolerance=slip_tolerance,
        peaks=peaks,
        defects=tuple(candidates),
        verdict=verdict,
        notes=tuple(notes),
        spectrum=spectrum,
        floor=floor,
    )


#: Highest harmonic and sideband of a likely candidate's family that explains another's line.
#: The sidebands are the load zone's modulation of the squared envelope: at a half-circle load
#: zone (ε = 1/2) its Fourier coefficients over the mean are 0.88, 0.60, 0.30, 0.086 for the
#: first four and 0 from the fifth (McFadden and Smith's Stribeck modulation, squared), so a
#: clear record shows four on each side (a noiseless ball spall's cage-rate comb did).
_FAMILY_HARMONICS = 2 * HARMONICS
_FAMILY_SIDEBANDS = 4


def _assess(
    lines: tuple[Evidence, ...], total: float, modulation: tuple[Evidence, ...] = ()
) -> Assessment:
    if any(e.harmonic == 1 and e.sideband == 0 and e.found for e in lines) and (
        total >= SCORE_LIKELY
    ):
        return "likely"
    if any(e.found and e.sideband == 0 for e in lines):
        return "possible"
    # a ball's cage-rate sidebands found with its cage modulation: the ball spin's lines
    # themselves spread by slip
    if any(e.found for e in modulation) and any(e.found for e in lines):
        return "possible"
    return "no evidence"


def _ball_modulation(candidates: list[Candidate]) -> list[Candidate]:
    """Read the FTF lines as the ball defect's cage modulation when the ball has lines of its own.

    A spalled ball is carried through the load zone by the cage: its impacts are modulated at
    the cage frequency, which puts lines at FTF and its harmonics in the envelope spectrum
    beside BDF and its ± FTF sidebands (Randall and Antoni 2011, Table 1). Slip spreads the BDF
    lines (BDF is about 10 times FTF, its smear as many times wider) while the FTF lines stay
    sharp; without this rule the cage would outrank the ball. When any line of the ball (a BDF
    harmonic or a BDF ± FTF sideband) is found, the cage's harmonics become the ball's
    ``modulation`` (weighted as sidebands) and, for the cage, shared lines; the cage is then
    at most possible and ranked after the ball. Nothing in the envelope spectrum tells a cage
    fault from a ball's modulation when both are there: the verdict names the ball.
    """
    ball = next(cd for cd in candidates if cd.part == "ball")
    cage = next(cd for cd in candidates if cd.part == "cage")
    if not any(e.found for e in ball.lines) or not any(e.found for e in cage.lines):
        return candidates
    modulation = tuple(e for e in cage.lines if e.sideband == 0)
    total = score(ball.lines, modulation)
    ball = dataclasses.replace(
        ball,
        modulation=modulation,
        score=total,
        assessment=_assess(ball.lines, total, modulation),
    )
    shared = tuple(dataclasses.replace(e, shared=True) for e in cage.lines)
    cage_total = score(shared)
    cage_assessment: Assessment = (
        "possible" if _assess(shared, cage_total) == "likely" else _assess(shared, cage_total)
    )
    cage = dataclasses.replace(cage, lines=shared, score=cage_total, assessment=cage_assessment)
    return [ball if cd.part == "ball" else cage if cd.part == "cage" else cd for cd in candidates]


def _explained(candidates: list[Candidate], df: float) -> list[Candidate]:
    """Mark as shared the lines of a weaker candidate that a likely one's family explains.

    The family of a likely candidate is its harmonics up to :data:`_FAMILY_HARMONICS` with
    their modulation sidebands up to :data:`_FAMILY_SIDEBANDS` (and the modulation's own
    lines), at the slip its fundamental was found at; a weaker candidate's line within two bins
    and 0.2 % of a family line is that family's, not evidence of a second defect. A weaker
    candidate whose found fundamental is such a line is at most possible, however large its
    other lines (a noiseless ball spall's cage-rate comb, BDF + 2 FTF within BPFI's window,
    scored the inner race likely).
    """
    ordered = sorted(candidates, key=lambda cd: cd.score, reverse=True)
    out: list[Candidate] = []
    families: list[FloatArray] = []
    for cd in ordered:
        lines = cd.lines
        if families:
            family = np.concatenate(families)
            changed = []
            explained = False  # its fundamental is a line of the family
            for e in lines:
                near = np.abs(family - e.frequency_hz) <= 2.0 * df + 0.002 * e.frequency_hz
                hit = bool(near.any())
                changed.append(dataclasses.replace(e, shared=True) if hit else e)
                explained |= hit and e.found and (e.harmonic, e.sideband) == (1, 0)
            lines = tuple(changed)
            total = score(lines, cd.modulation)
            assessment = _assess(lines, total, cd.modulation)
            if explained and assessment == "likely":
                assessment = "possible"
            cd = dataclasses.replace(cd, lines=lines, score=total, assessment=assessment)
        out.append(cd)
        if cd.assessment == "likely":
            fund = next(e for e in lines if e.harmonic == 1 and e.sideband == 0)
            ratio = fund.frequency_hz / cd.frequency_hz
            h = np.arange(0, _FAMILY_HARMONICS + 1, dtype=np.float64)[:, None]
            spacing = cd.sideband_hz or 0.0
            if cd.part == "ball":
                spacing *= ratio  # the cage slips with the balls
            s = np.arange(-_FAMILY_SIDEBANDS, _FAMILY_SIDEBANDS + 1, dtype=np.float64)[None, :]
            lines_hz = (h * cd.frequency_hz * ratio + s * spacing).ravel()
            families.append(lines_hz[lines_hz > 0.5 * df])
    return out


def _verdict(candidates: list[Candidate]) -> str:
    likely = [cd for cd in candidates if cd.assessment == "likely"]
    possible = [cd for cd in candidates if cd.assessment == "possible"]
    if likely:
        words = " and ".join(_WORDS[cd.part] for cd in likely)
        return f"{words} likely"
    if possible:
        words = " or ".join(_WORDS[cd.part] for cd in possible)
        article = "an" if words[0] in "aeiou" else "a"
        return f"weak evidence of {article} {words}: not conclusive"
    return "no defect evidence"


def _label(
    freq: float,
    fundamentals: dict[str, float],
    sidebands: dict[str, float | None],
    f_r: float,
    tol: float,
    df: float,
) -> str | None:
    best: tuple[float, str] | None = None
    for part, fd in fundamentals.items():
        # the cage's harmonics are not labelled past the searched ones: every line of the
        # spectrum is near some high multiple of FTF
        for h in range(1, (HARMONICS if part == "cage" else _FAMILY_HARMONICS) + 1):
            sides = (0,) if sidebands[part] is None else (0, -1, 1, -2, 2)
            for side in sides:
                spacing = sidebands[part] or 0.0
                expected = h * fd + side * spacing
                gap = abs(freq - expected)
                if gap <= tol * h * fd + 1.5 * df:
                    name = _NAMES[part] if h == 1 else f"{h}x{_NAMES[part]}"
                    if side:
                        mod = "FTF" if part == "ball" else "fr"
                        name += ("+" if side > 0 else "-") + (
                            mod if abs(side) == 1 else f"{abs(side)}{mod}"
                        )
                    # the harmonic itself before a sideband at the same distance
                    key = gap / max(expected, 1e-300) + abs(side)
                    if best is None or key < best[0]:
                        best = (key, name)
    if best is not None:
        return best[1]
    h = round(freq / f_r)
    if h >= 1 and abs(freq - h * f_r) <= tol * h * f_r + 1.5 * df:
        return "fr" if h == 1 else f"{h}xfr"
    return None


def _peaks(
    f: FloatArray,
    amp: FloatArray,
    snr: FloatArray,
    fundamentals: dict[str, float],
    sidebands: dict[str, float | None],
    f_r: float,
    tol: float,
    df: float,
) -> tuple[Peak, ...]:
    """The largest local maxima of the envelope spectrum up to the highest line searched."""
    top = (HARMONICS + 0.5) * max(fundamentals.values()) + f_r
    keep = np.flatnonzero((amp[1:-1] > amp[:-2]) & (amp[1:-1] >= amp[2:]) & (f[1:-1] <= top)) + 1
    order = keep[np.argsort(amp[keep])[::-1]][:PEAKS_SHOWN]
    out = []
    for i in order:
        freq = _refine(f, amp, int(i))
        out.append(
            Peak(
                freq,
                float(amp[i]),
                float(snr[i]),
                _label(freq, fundamentals, sidebands, f_r, tol, df),
            )
        )
    return tuple(out)
