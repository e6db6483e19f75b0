r"""One decomposition of a runout record for every model: lines, sources, residual, RRO/NRRO.

A model supplies the physics (the record and the *candidate* lines its imperfections should
produce, each with its source); this module does the spectral bookkeeping the same way for all
of them:

1. **Candidates** (:class:`Candidate`): a frequency, a direction (radial or axial) and a
   :class:`Source` (part, element, lobes, term, formula). Candidates at the same frequency are
   one line with several sources.
2. **Fit** (:func:`fit_lines`): least squares at the exact frequencies
   (:func:`runout.analysis.spectrum.extract_lines`, no leakage). Lines closer than the record
   resolves are fitted jointly down to :data:`JOINT_FIT` / T; closer than that they cannot be told
   apart, and the result's notes say which, and how many revolutions would separate them: no
   line is merged without a word.
3. **Residual search**: peaks left in the residual's Hann spectrum above a threshold are fitted
   too, at the nearest admissible combination frequency :math:`|a f_r + b f_c + c f_b|` of the
   bearing's kinematics (small integers; f_r the rotating ring, f_c the cage, f_b the element
   spin relative to the cage), or, when none lies within the resolution, as *unattributed* at
   the peak's frequency. The explained fraction of the variance is reported.
4. **RRO/NRRO** (:func:`split_runout`): RRO is the waveform of the lines at integer orders of
   the rotating ring, plus the synchronous average of the *residual* only when it stands above
   its own uncertainty; its p-p is read at the record's instants (over one revolution for a
   record shorter than that). NRRO is the p-p over the record
   of the record minus the RRO waveform. No averaging of the whole record: a synchronous average
   keeps about 1/(N·distance to an integer order) of every non-integer line, which made RRO
   depend on the record length.

Shares: when several sources produce one line, ``share`` is each source's fraction of the
fitted complex amplitude C of the line, :math:`\mathrm{Re}(c_i \bar C)/|C|^2`, with c_i the
source's predicted complex amplitude (the linearised model, seed 002 eq. 33-40); sources
without a prediction (higher orders) share what the predictions leave, C - Σ c_i, equally; with
no prediction at all the sources share the line equally. The shares add up to 1, and
``share_basis`` says which way each was obtained.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import Any, Literal

import numpy as np
from numpy.typing import NDArray

from runout.analysis.lines import Component, Runout, Source
from runout.base._threads import halves, in_spans

__all__ = [
    "JOINT_FIT",
    "RESIDUAL_REL",
    "Candidate",
    "Kinematic",
    "LineFit",
    "RunoutSplit",
    "Source",
    "attribute_frequency",
    "exact_shares",
    "fit_lines",
    "resolved_lines",
    "split_runout",
    "study_key",
]

FloatArray = NDArray[np.float64]
Direction = Literal["radial", "axial"]
Phasors = tuple[complex, complex, complex]

#: Lines at least this fraction of 1/T apart are fitted jointly; closer ones are not resolved.
JOINT_FIT = 0.3
#: Residual peaks below this fraction of the largest fitted line are not searched for.
RESIDUAL_REL = 1e-3
#: At most this many lines are added by the residual search (per direction) ...
MAX_RESIDUAL_LINES = 12
#: ... in at most this many rounds of search and refit (a round adds every resolvable peak).
RESIDUAL_ROUNDS = 3
#: Residual peaks closer than this many 1/T to a fitted line (to a line carrying unresolved
#: sources) are taken for its leakage (for the beat of what it carries), not searched for.
LEAKAGE = 1.0
LEAKAGE_MERGED = 3.0
#: Lines below this fraction of the largest one are dropped (the solvers' round-off floor).
FLOOR = 1e-7
#: Integer coefficient bounds of the combination search |a f_r + b f_c + c f_b|.
MAX_COMBINATION = 3
#: The words of the notes saying that predicted lines lie outside what the record resolves
#: (above the Nyquist frequency, or below 1/T): a verdict cannot pass on such a record.
NOT_FITTED = "are not fitted"
NOT_FITTED_NYQUIST = "Nyquist frequency"
#: Records of at least this many instants form their RRO record on two threads.
PARALLEL_MIN = 1 << 16
#: Element-passage harmonics n Z f_c the combination search reaches (rigid contacts switch
#: abruptly from one pair of elements to the next: many harmonics).
MAX_PASSAGE_HARMONIC = 12


@dataclass(frozen=True)
class Candidate:
    """A line a model expects, with its source.

    Attributes
    ----------
    frequency_hz : float
        Frequency [Hz] (> 0).
    direction : {"radial", "axial"}
        Radial candidates are fitted in x and y, axial ones in z.
    source : Source
        What produces it (``share`` is filled in by the fit).
    optional : bool
        Kept only when clearly present (above :data:`RESIDUAL_REL` of the largest line).
    predicted : (complex, complex, complex) or None
        Predicted phasors (X, Y, Z) of this source's line, x(t) = Re(X exp(2πi f t)) [m], from
        the linearised model: the shares of a line with several sources.
    """

    frequency_hz: float
    direction: Direction
    source: Source
    optional: bool = False
    predicted: tuple[complex, complex, complex] | None = None


@dataclass(frozen=True)
class Kinematic:
    """The frequencies combination lines are built from [Hz].

    Attributes
    ----------
    rotation : float
        Speed of the rotating ring f_r.
    cage : float
        Cage frequency f_c (signed like the ring speeds).
    spin : float
        Element spin relative to the cage f_b (>= 0).
    n_elements : int
        Z: multiples of Z f_c (element passage) count as simple combinations.
    element_waviness : bool
        Whether element deviations with lobes exist (else f_b does not enter a combination).
    synchronous_sources : bool
        Whether anything turns with the rotating ring (its raceway deviations, an unbalance,
        the other ring turning too); else f_r does not enter a combination, so that a line the
        residual search finds is never taken for RRO without a cause.
    """

    rotation: float
    cage: float
    spin: float
    n_elements: int
    element_waviness: bool = True
    synchronous_sources: bool = True


@dataclass(frozen=True)
class LineFit:
    """Result of :func:`fit_lines`.

    Attributes
    ----------
    components : tuple of Component
        Largest first, each with its ranked sources.
    residual : ndarray, shape (3, n)
        Record minus the fitted lines and offsets [m] (zeros in directions not fitted).
    explained_fraction : float
        1 - residual variance / record variance over the fitted directions [-] (1 for a
        motionless record).
    notes : tuple of str
        Lines that could not be resolved, residual lines found, and what they were taken for.
    """

    components: tuple[Component, ...]
    residual: FloatArray
    explained_fraction: float
    notes: tuple[str, ...] = ()


@dataclass(frozen=True)
class _Group:
    frequency: float
    direction: Direction
    sources: list[tuple[Source, Phasors | None]] = field(default_factory=list)
    optional: bool = True
    merged: bool = False  # carries lines the record cannot resolve (they beat within 1/T)


def _group(candidates: Sequence[Candidate], direction: Direction) -> list[_Group]:
    """Candidates of one direction at the same frequency (1e-9 relative) become one line."""
    chosen = sorted(
        (c for c in candidates if c.direction == direction), key=lambda c: c.frequency_hz
    )
    groups: list[_Group] = []
    for c in chosen:
        f = c.frequency_hz
        if groups and abs(f - groups[-1].frequency) <= 1e-9 * max(f, 1e-300):
            g = groups[-1]
            if all(s != c.source for s, _ in g.sources):
                g.sources.append((c.source, c.predicted))
            if not c.optional:
                groups[-1] = replace(g, optional=False)
        else:
            groups.append(_Group(f, direction, [(c.source, c.predicted)], c.optional))
    return groups


def resolved_lines(
    candidates: Sequence[Candidate],
    direction: Direction,
    time: FloatArray,
    rotation_hz: float,
) -> tuple[list[tuple[float, list[Source]]], list[str]]:
    """The lines of one direction a record can fit: (frequency [Hz], sources), and notes.

    The grouping and resolution policy of :func:`fit_lines` (same frequency: one line;
    closer than :data:`JOINT_FIT`/T: not resolved, said in the notes; optional lines only where
    resolvable), for callers that fit many records at once (the batched studies).

    Parameters
    ----------
    candidates : sequence of Candidate
        The lines the model predicts, with their sources.
    direction : {"radial", "axial"}
        Which candidates to keep.
    time : ndarray, shape (n,)
        Instants of the record [s], uniform (its step and length set the resolution 1/T and
        the Nyquist frequency).
    rotation_hz : float
        Speed of the rotating ring [Hz] (the revolutions a note asks for).

    Returns
    -------
    lines : list of (float, list of Source)
        Each resolvable line: its frequency [Hz] and the sources it carries, by frequency.
    notes : list of str
        Lines the record cannot fit or separate, and what would resolve them.
    """
    n = time.size
    duration = n * float(time[1] - time[0])
    groups, notes = _resolve(
        _group(candidates, direction),
        duration,
        rotation_hz,
        0.5 / duration,
        0.5 * n / duration * 0.999,
    )
    return [(g.frequency, [s for s, _ in g.sources]) for g in groups], notes


def study_key(sources: Sequence[Source]) -> str:
    """A line's identity across the bearings of a study: its sources' labels, element numbers
    removed, sorted (shares differ from bearing to bearing; the sources do not).

    Parameters
    ----------
    sources : sequence of Source
        The sources of one line.

    Returns
    -------
    str
        Their labels without element numbers, sorted, joined by ``"; "``.
    """
    import re

    labels = {re.sub(r"^(ball|roller) \d+ ", r"\1 ", s.label()) for s in sources}
    return "; ".join(sorted(labels))


def _revolutions_needed(df: float, rotation_hz: float, spacing: float = JOINT_FIT) -> int:
    return math.ceil(spacing / max(df, 1e-300) * rotation_hz)


def _resolve(
    groups: list[_Group],
    duration: float,
    rotation_hz: float,
    f_lo: float,
    f_hi: float,
    spacing: float = JOINT_FIT,
) -> tuple[list[_Group], list[str]]:
    """Keep the groups the record can separate; say what it cannot (required first)."""
    notes: list[str] = []
    groups = [replace(g, sources=list(g.sources)) for g in groups]  # merging must not leak
    inside = [g for g in groups if f_lo < g.frequency < f_hi]
    high = [g for g in groups if g.frequency >= f_hi and not g.optional]
    if high:
        need = math.ceil(2.0 * max(g.frequency for g in high) * duration / 0.999) + 1
        names = "; ".join(_short(g) for g in high[:4])
        notes.append(
            f"{len(high)} line(s) at or above the Nyquist frequency {f_hi / 0.999:.4g} Hz "
            f"{NOT_FITTED} (they alias onto lower frequencies: {names}); at least {need} "
            "samples over this record would resolve them"
        )
    low = [g for g in groups if 0.0 < g.frequency <= f_lo and not g.optional]
    if low:
        names = "; ".join(_short(g) for g in low[:4])
        notes.append(
            f"{len(low)} line(s) below 1/T = {f_lo:.4g} Hz (less than one period in the record) "
            f"{NOT_FITTED} ({names}); a longer record would resolve them"
        )
    ranked = sorted(inside, key=lambda g: (g.optional, -len(g.sources)))
    kept: list[_Group] = []
    sep = spacing / duration
    clashes: list[str] = []
    need = 0
    for g in ranked:
        clash = next((k for k in kept if abs(k.frequency - g.frequency) < sep), None)
        if clash is None:
            kept.append(g)
            continue
        if g.optional:
            continue  # an optional line is only looked for where it can be resolved
        df = abs(clash.frequency - g.frequency)
        need = max(need, _revolutions_needed(df, rotation_hz, spacing))
        clashes.append(
            f"{_short(g)} ({g.frequency:.6g} Hz) with {_short(clash)} ({clash.frequency:.6g} Hz)"
        )
        clash.sources.extend(s for s in g.sources if s not in clash.sources)
        kept[kept.index(clash)] = replace(clash, merged=True)
    if clashes:
        shown = "; ".join(clashes[:4]) + (
            f"; and {len(clashes) - 4} more" if len(clashes) > 4 else ""
        )
        notes.append(
            f"{len(clashes)} line(s) closer than {spacing:g}/T to a line of the record are not "
            f"resolved over {duration * rotation_hz:.4g} revolutions (at least {need} would "
            f"resolve them); each is fitted as one line carrying both sources: {shown}"
        )
    kept.sort(key=lambda g: g.frequency)
    return kept, notes


def _short(g: _Group) -> str:
    return g.sources[0][0].label() + (f" +{len(g.sources) - 1} more" if len(g.sources) > 1 else "")


def _shares(sources: list[tuple[Source, complex | None]], fitted: complex) -> list[Source]:
    """Sources with their share of the fitted line ``fitted`` = A e^{iφ}, ranked by it.

    A source with a predicted phasor p gets Re(p C̄)/|C|²; the sources without one share what
    the predictions leave, C - Σp, equally. The shares add up to 1.
    """
    if len(sources) == 1:
        return [replace(sources[0][0], share=1.0, share_basis="single")]
    norm = abs(fitted) ** 2
    known = [p for _, p in sources if p is not None]
    if not known or norm == 0.0:
        return [replace(s, share=1.0 / len(sources), share_basis="equal") for s, _ in sources]
    unknown = len(sources) - len(known)
    if not unknown:
        # every source predicted: split the line in the proportions the predictions give
        # (the fitted line differs from their sum by the model's nonlinearity and gains)
        fitted = complex(sum(known))
        norm = abs(fitted) ** 2
        if norm == 0.0:
            return [replace(s, share=1.0 / len(sources), share_basis="equal") for s, _ in sources]
    rest = (fitted - sum(known)) / unknown if unknown else 0j
    out = []
    for s, p in sources:
        value = p if p is not None else rest
        basis = "predicted" if p is not None else "remainder"
        out.append(
            replace(s, share=float((value * fitted.conjugate()).real / norm), share_basis=basis)
        )
    return sorted(out, key=lambda s: -abs(s.share))


def exact_shares(sources: list[tuple[Source, complex]], fitted: complex) -> list[Source]:
    """Sources whose phasors are known exactly (and add up to ``fitted``), ranked by share.

    Parameters
    ----------
    sources : list of (Source, complex)
        Each source with its complex amplitude c_i in the line's direction [m].
    fitted : complex
        Complex amplitude C of the line [m].

    Returns
    -------
    list of Source
        The sources with ``share`` and ``share_basis`` filled in, largest share first
        (``"single"`` for a lone source).

    Notes
    -----
    Each source's share is Re(c_i C̄)/|C|² with C = Σ c_i, so the shares add up to 1; the
    phasors are those of the linearised model (seed 002, "Anderon vibration", eq. 33-40), as
    in the module docstring.
    """
    return _shares([(s, p) for s, p in sources], fitted)


def attribute_frequency(
    frequency: float, kin: Kinematic, tolerance: float
) -> tuple[float, Source] | None:
    """The admissible combination |a f_r + b f_c + c f_b| nearest to ``frequency``.

    a runs over -MAX_COMBINATION..MAX_COMBINATION, c over even values up to twice that
    (element deviations act along a diameter, seed 002 eq. 26; none without element waviness),
    b over ±(MAX_PASSAGE_HARMONIC Z + 3) (element-passage harmonics and their sidebands); the
    simplest
    combination (fewest multiples, n Z f_c counting as n) wins among those within
    ``tolerance`` [Hz].

    Parameters
    ----------
    frequency : float
        Frequency of a residual peak [Hz].
    kin : Kinematic
        The frequencies f_r, f_c, f_b [Hz] and what may enter a combination.
    tolerance : float
        Largest distance from ``frequency`` of an admissible combination [Hz].

    Returns
    -------
    (float, Source) or None
        The combination's exact frequency [Hz] and a ``"combination"`` source whose formula
        names it; None when nothing lies within ``tolerance``.

    Notes
    -----
    Element deviations act along a diameter, so the element spin f_b enters with even
    multiples only (seed 002, "Anderon vibration", eq. 26).
    """
    m = MAX_COMBINATION
    z = kin.n_elements
    zb = MAX_PASSAGE_HARMONIC * z + 3
    a = (np.arange(-m, m + 1) if kin.synchronous_sources else np.zeros(1, np.int64))[:, None, None]
    b = np.arange(-zb, zb + 1)[None, :, None]
    spins = np.arange(-2 * m, 2 * m + 1, 2) if kin.element_waviness else np.zeros(1, np.int64)
    c = spins[None, None, :]
    f = np.abs(a * kin.rotation + b * kin.cage + c * kin.spin)
    err = np.abs(f - frequency)
    # b = n Z + r costs |n| + |r|: element-passage harmonics and their sidebands are simple
    n_pass = np.round(b / z)
    cost = np.abs(a) + np.abs(n_pass) + np.abs(b - n_pass * z) + np.abs(c) // 2
    ok = (err <= tolerance) & (f > 0.0)
    if not ok.any():
        return None
    score = np.where(ok, cost + err / max(tolerance, 1e-300), np.inf)
    i, j, k = np.unravel_index(int(np.argmin(score)), score.shape)
    ai, bi, ci = int(a[i, 0, 0]), int(b[0, j, 0]), int(c[0, 0, k])
    if next(v for v in (ai, bi, ci) if v) < 0:  # |-x| = |x|: lead with a positive term
        ai, bi, ci = -ai, -bi, -ci
    n_z = round(bi / z)
    parts = [(ai, "f_r"), (n_z, "Z f_c"), (bi - n_z * z, "f_c"), (ci, "f_b")]
    formula = ""
    for v, name in parts:
        if v:
            sign = "-" if v < 0 else ("+" if formula else "")
            count = "" if abs(v) == 1 else f"{abs(v)} "
            formula += f" {sign} {count}{name}"
    formula = " ".join(formula.split())
    source = Source(
        part="combination",
        element=None,
        lobes=None,
        term="residual search",
        formula=formula if "-" not in formula else f"|{formula}|",
    )
    return float(f[i, j, k]), source


def _residual_peaks(
    time: FloatArray, residual: FloatArray, threshold: float
) -> list[tuple[float, float]]:
    """(frequency [Hz], amplitude) of the largest peaks of a residual's Hann spectrum."""
    from runout.analysis.spectrum import amplitude_spectrum

    n = time.size
    fs = (n - 1) / (time[-1] - time[0])
    spec = amplitude_spectrum(residual, sample_rate=fs)
    amp = spec.amplitude
    floor = 4.0 * float(np.median(amp))
    peaks: list[tuple[float, float]] = []
    # the local maxima above both levels, found vectorised (a Python loop over 2^21 bins
    # took a second); the same tests as one bin at a time
    inner = amp[2:-2]
    found = (inner > threshold) & (inner > floor) & (inner >= amp[1:-3]) & (inner > amp[3:-1])
    for i in (np.flatnonzero(found) + 2).tolist():
        # parabolic interpolation on the log amplitude (Hann main lobe)
        la, lb, lc = (math.log(max(v, 1e-300)) for v in amp[i - 1 : i + 2])
        den = la - 2 * lb + lc
        shift = 0.5 * (la - lc) / den if den != 0.0 else 0.0
        peaks.append(((i + max(-0.5, min(0.5, shift))) * spec.resolution, float(amp[i])))
    peaks.sort(key=lambda p: -p[1])
    return peaks


def fit_lines(
    time: FloatArray,
    displacement: FloatArray,
    candidates: Sequence[Candidate],
    rotation_hz: float,
    *,
    directions: tuple[str, ...] = ("x", "y", "z"),
    kinematic: Kinematic | None = None,
    floor: float = 0.0,
    search_residual: bool = True,
) -> LineFit:
    """Fit the candidate lines, search the residual, attribute every line (see module doc).

    Parameters
    ----------
    time : ndarray, shape (n,)
        Instants [s], uniform.
    displacement : ndarray, shape (3, n)
        x, y, z [m].
    candidates : sequence of Candidate
        The lines the model predicts.
    rotation_hz : float
        Speed of the rotating ring [Hz] (orders and repeatability).
    directions : tuple of str
        Directions to fit ("x", "y", "z").
    kinematic : Kinematic or None
        Frequencies for attributing residual lines; None: residual lines are unattributed.
    floor : float
        Lines below this p-p [m] are the solver's round-off and dropped.
    search_residual : bool
        Run the residual search.

    Returns
    -------
    LineFit
    """
    from runout.analysis.spectrum import LineResolutionWarning, extract_lines

    n = time.size
    duration = n * float(time[1] - time[0])
    f_hi = 0.5 * n / duration * 0.999
    f_lo = 1.0 / duration  # a line needs a whole period in the record to be told apart
    notes: list[str] = []
    comps: list[Component] = []
    residual = np.zeros_like(displacement)
    uniform = _uniform_steps(time)
    explained_num = explained_den = 0.0
    largest = 0.0
    fits: dict[str, tuple[list[_Group], Any]] = {}
    for axis, name in enumerate(("x", "y", "z")):
        if name not in directions:
            continue
        kind: Direction = "axial" if name == "z" else "radial"
        signal = displacement[axis]
        groups, fit, resolution_notes = _fit_resolvable(
            _group(candidates, kind), time, signal, duration, rotation_hz, f_lo, f_hi
        )
        if name != "y":  # x and y share the radial candidates: say it once
            notes += resolution_notes
        added = 0
        for attempt in range(RESIDUAL_ROUNDS + 1):
            stop = False
            if attempt:
                try:
                    fit = _fit(extract_lines, LineResolutionWarning, time, signal, groups)
                except ValueError:  # the residual lines made the fit singular: drop them
                    groups = [g for g in groups if g.sources[0][0].term != "residual search"]
                    fit = _fit(extract_lines, LineResolutionWarning, time, signal, groups)
                    stop = True
            model = (
                _synthesize(fit, time, uniform) if fit is not None else np.full(n, signal.mean())
            )
            res = residual[axis]  # formed in place: one record-sized temporary, the model
            np.subtract(signal, model, out=res)
            del model
            if fit is not None:
                largest = max(largest, float(np.max(fit.amplitude, initial=0.0)))
            room = MAX_RESIDUAL_LINES - added
            if stop or not search_residual or n < 64 or attempt == RESIDUAL_ROUNDS or room <= 0:
                break
            scale = max(largest, math.sqrt(_sum_sq_about_mean(signal) / n))
            threshold = max(RESIDUAL_REL * scale, 0.5 * floor)
            new = _add_residual_lines(time, res, groups, kinematic, threshold, duration, kind, room)
            if not new:
                break
            added += new
        fits[name] = (groups, fit)
        explained_num += _sum_sq_about_mean(res)  # res is residual[axis] already
        explained_den += _sum_sq_about_mean(signal)
    top = 2.0 * largest
    found_residual = 0
    for name, (groups, fit) in fits.items():
        if fit is None:
            continue
        for g, amp, ph in zip(groups, fit.amplitude, fit.phase, strict=True):
            pp = 2.0 * float(amp)
            if pp <= max(FLOOR * top, floor) or (g.optional and pp < 2 * RESIDUAL_REL * top):
                continue
            sources = _shares(_directional(g, name), complex(amp * np.exp(1j * ph)))
            if sources[0].term == "residual search" or sources[0].part == "unattributed":
                found_residual += 1
            comps.append(Component.from_sources(name, g.frequency, rotation_hz, amp, ph, sources))
    if found_residual:
        notes.append(
            f"{found_residual} line(s) found in the residual spectrum beyond the predicted "
            "ones (attributed to the nearest kinematic combination, or unattributed)"
        )
    comps.sort(key=lambda c: -c.pp_m)
    explained = 1.0 - explained_num / explained_den if explained_den > 0.0 else 1.0
    return LineFit(tuple(comps), residual, float(explained), tuple(notes))


def _sum_sq_about_mean(x: FloatArray) -> float:
    """sum((x - mean x)^2) with one temporary array (the same sums as the plain expression)."""
    tmp = x - x.mean()
    np.square(tmp, out=tmp)
    return float(np.sum(tmp))


def _uniform_steps(time: FloatArray) -> bool:
    """``np.allclose(steps, steps[0], rtol=1e-9, atol=0)`` over chunks: no record-sized
    temporaries (three of them at 8 B per instant in the plain expression)."""
    if time.size < 2:
        return True
    step = float(time[1] - time[0])
    limit = 1e-9 * abs(step)
    chunk = 1 << 16
    for i0 in range(0, time.size - 1, chunk):
        steps = np.diff(time[i0 : i0 + chunk + 1])
        if not np.all(np.abs(steps - step) <= limit):
            return False
    return True


def _synthesize(fit: Any, time: FloatArray, uniform: bool | None = None) -> FloatArray:
    """The fitted lines and offset at uniform ``time`` (blocks of phasors, BLAS products).

    ``uniform``: whether ``time`` is uniform (:func:`_uniform_steps`), when the caller knows.
    """
    from runout.analysis.spectrum import _synthesize_uniform_kernel

    if not (_uniform_steps(time) if uniform is None else uniform):
        return np.asarray(fit.evaluate(time))  # non-uniform instants: the NumPy evaluation
    omega = 2.0 * np.pi * np.asarray(fit.frequencies, dtype=np.float64)
    phase = fit.phase + omega * float(time[0])
    a = np.ascontiguousarray((fit.amplitude * np.cos(phase))[None, :])
    b = np.ascontiguousarray((-fit.amplitude * np.sin(phase))[None, :])
    const = np.ascontiguousarray(np.atleast_1d(fit.constant).astype(np.float64))
    dt = float(time[1] - time[0])
    out: NDArray[np.float64] = np.asarray(
        _synthesize_uniform_kernel(const, a, b, dt, omega, time.size)
    )[0]
    return out


def _directional(g: _Group, name: str) -> list[tuple[Source, complex | None]]:
    """Each source with its predicted phasor in direction ``name`` (None: no prediction)."""
    axis = "xyz".index(name)
    return [(s, None if p is None else p[axis]) for s, p in g.sources]


#: Largest condition number of a joint fit (column-scaled): beyond it the lines cannot be told
#: apart in this record and are thinned out (_fit_resolvable).
MAX_CONDITION = 1e3
#: A fitted line larger than this many times the record's p-p means the lines cancel each other
#: (not resolved); such a fit is thinned out like an ill-conditioned one.
OVERFIT = 4.0


def _fit(
    extract: Any, warning: Any, time: FloatArray, signal: FloatArray, groups: list[_Group]
) -> Any:
    import warnings

    if not groups:
        return None
    freqs = np.array([g.frequency for g in groups])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", warning)  # closeness is handled by _resolve
        return extract(time, signal, freqs, max_condition=MAX_CONDITION)


def _fit_resolvable(
    groups: list[_Group],
    time: FloatArray,
    signal: FloatArray,
    duration: float,
    rotation_hz: float,
    f_lo: float,
    f_hi: float,
) -> tuple[list[_Group], Any, list[str]]:
    """Resolve and fit; when the joint fit is ill conditioned or has more unknowns than
    samples, or fits lines larger than the record (OVERFIT), widen the spacing lines must keep
    (0.3, 0.6, 1.2, ... /T) until it is not."""
    from runout.analysis.spectrum import LineResolutionWarning, extract_lines

    spacing = JOINT_FIT
    for _ in range(8):
        kept, notes = _resolve(groups, duration, rotation_hz, f_lo, f_hi, spacing)
        try:
            fit = _fit(extract_lines, LineResolutionWarning, time, signal, kept)
        except ValueError:
            spacing *= 2.0
            continue
        # lines far larger than the record they came from cancel each other: the record does
        # not resolve them (a short record with many candidates), however well conditioned
        if fit is not None and 2.0 * float(np.max(fit.amplitude)) > OVERFIT * np.ptp(signal):
            spacing *= 2.0
            continue
        if spacing > JOINT_FIT:
            notes.append(
                f"the {len(groups)} predicted lines cannot all be fitted jointly over this record "
                f"(too close together, or more unknowns than samples): lines were kept at least "
                f"{spacing:g}/T apart; a longer record resolves more of them"
            )
        return kept, fit, notes
    return [], None, ["the record is too short to fit the predicted lines: none were fitted"]


def _add_residual_lines(
    time: FloatArray,
    residual: FloatArray,
    groups: list[_Group],
    kin: Kinematic | None,
    threshold: float,
    duration: float,
    kind: Direction,
    room: int,
) -> int:
    """Add up to ``room`` resolvable residual peaks as lines, largest first; how many."""
    tolerance = 0.5 / duration
    added = 0
    for f, _amp in _residual_peaks(time, residual, threshold):
        if added >= room:
            break
        found = attribute_frequency(f, kin, tolerance) if kin is not None else None
        if found is not None:
            freq, source = found
        else:
            freq = f
            source = Source(
                part="unattributed",
                element=None,
                lobes=None,
                term="residual search",
                formula=f"{f:.6g} Hz (no kinematic combination within {tolerance:.3g} Hz)",
            )
        # a peak next to a fitted line is its leakage (or the beat of lines merged there, which
        # the record cannot resolve), not a line of its own
        if any(
            abs(g.frequency - f) < (LEAKAGE_MERGED if g.merged else LEAKAGE) / duration
            or abs(g.frequency - freq) < JOINT_FIT / duration
            for g in groups
        ):
            continue
        groups.append(_Group(freq, kind, [(source, None)], optional=False))
        groups.sort(key=lambda g: g.frequency)
        added += 1
    return added


# --------------------------------------------------------------------------------------------
# RRO / NRRO
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class RunoutSplit:
    """Runout figures and how they were obtained.

    Attributes
    ----------
    runout : Runout
        Radial, axial, RRO and NRRO p-p [m].
    residual_rro_pp : float
        p-p of the synchronous average of the residual added to RRO [m] (0 when it is not
        above its uncertainty, or the record has fewer than 2 whole revolutions).
    residual_rro_uncertainty : float
        Its uncertainty (rms over a revolution of the across-revolution standard error) [m].
    notes : tuple of str
        How RRO was formed (the residual's synchronous average when it joined it).
    """

    runout: Runout
    residual_rro_pp: float
    residual_rro_uncertainty: float
    notes: tuple[str, ...]


def split_runout(
    time: FloatArray,
    displacement: FloatArray,
    direction: FloatArray,
    components: Sequence[Component],
    rotation_hz: float,
    residual: FloatArray | None = None,
    *,
    synchronous: bool = True,
    axial: bool = True,
) -> RunoutSplit:
    """Radial, axial, RRO and NRRO p-p from the fitted lines (see module docstring).

    Parameters
    ----------
    time : ndarray, shape (n,)
        Instants [s].
    displacement : ndarray, shape (3, n)
        x, y, z [m].
    direction : ndarray, shape (2,)
        Unit vector of the radial measuring direction [-].
    components : sequence of Component
        The fitted lines.
    rotation_hz : float
        Speed of the rotating ring [Hz].
    residual : ndarray, shape (3, n) or None
        What the lines leave; its synchronous average joins RRO when something turns with the
        rotating ring (``synchronous``) and the average stands above three times its
        uncertainty and above :data:`RESIDUAL_REL` of the motion (not solver round-off).
    synchronous : bool
        Whether anything turns with the rotating ring (:attr:`Kinematic.synchronous_sources`);
        without it RRO is 0 by construction.
    axial : bool
        Whether the model has an axial degree of freedom; without one the axial p-p is None
        (not a quantity of the model), not the p-p of a z held at 0.

    Returns
    -------
    RunoutSplit
        Radial, axial, RRO and NRRO p-p [m], the residual's share of RRO [m] and notes.
    """
    u = np.asarray(direction, dtype=float)
    radial = u[0] * displacement[0] + u[1] * displacement[1]
    radial_pp = float(np.ptp(radial)) if radial.size else 0.0
    axial_pp = (float(np.ptp(displacement[2])) if displacement.shape[1] else 0.0) if axial else None
    rep = [c for c in components if c.repeatable and c.direction in ("x", "y")]
    one_rev = np.linspace(0.0, 1.0 / rotation_hz, 4097)[:-1] if rotation_hz > 0 else np.zeros(1)

    def rro_lines(t: FloatArray) -> FloatArray:
        out = np.zeros_like(t)
        work = np.empty_like(t)  # one record-sized buffer, no temporaries per line

        def fill(first: int, last: int) -> None:  # elementwise: the halves of a long record
            part, ts, buf = out[first:last], t[first:last], work[first:last]  # on two threads
            for c in rep:  # give the same values as one pass
                w = u[0] if c.direction == "x" else u[1]
                np.multiply(ts, 2.0 * math.pi * c.frequency_hz, out=buf)
                buf += c.phase_rad
                np.cos(buf, out=buf)
                buf *= w * 0.5 * c.pp_m
                part += buf

        in_spans(fill, halves(t.size, PARALLEL_MIN))
        return out

    rro_wave_rev = rro_lines(one_rev)
    rro_record = rro_lines(time)
    notes: list[str] = []
    extra_pp = uncertainty = 0.0
    if residual is not None and rotation_hz > 0 and synchronous:
        res = u[0] * residual[0] + u[1] * residual[1]
        n_rev = math.floor((time[-1] - time[0] + (time[1] - time[0])) * rotation_hz + 1e-9)
        # samples per revolution, only where the record holds two (a record of a vanishing
        # number of revolutions has a step of 0 or below the normal floats: no average)
        spr_f = 1.0 / (rotation_hz * (time[1] - time[0])) if n_rev >= 2 else 0.0
        spr = round(spr_f) if math.isfinite(spr_f) else 0
        if n_rev >= 2 and spr > 0 and abs(spr_f - spr) < 1e-6 * spr:
            blocks = res[: n_rev * spr].reshape(n_rev, spr)
            avg = blocks.mean(axis=0)
            se = blocks.std(axis=0, ddof=1) / math.sqrt(n_rev)
            uncertainty = float(np.sqrt(np.mean(se**2)))
            avg = avg - avg.mean()
            level = float(np.sqrt(np.mean(avg**2)))
            if level > 3.0 * uncertainty and level > RESIDUAL_REL * float(np.std(radial)):
                extra_pp = float(np.ptp(avg))
                phase = np.rint((time - time[0]) * rotation_hz * spr).astype(np.int64) % spr
                rro_record = rro_record + avg[phase]
                idx = (np.arange(rro_wave_rev.size) * spr // rro_wave_rev.size) % spr
                rro_wave_rev = rro_wave_rev + avg[idx]
                notes.append(
                    f"RRO includes the synchronous average of what the lines leave "
                    f"({extra_pp:.3g} m p-p, uncertainty {uncertainty:.2g} m rms over "
                    f"{n_rev} revolutions)"
                )
    # over a record of at least one revolution, RRO is read at the record's own instants, like
    # the total (so that RRO <= total + NRRO holds exactly); a shorter record: one revolution
    covers_rev = (time[-1] - time[0] + (time[1] - time[0])) * rotation_hz >= 1.0 - 1e-9
    rro_wave = rro_record if covers_rev else rro_wave_rev
    rro_pp = float(np.ptp(rro_wave)) if rep or extra_pp else 0.0
    nrro_pp = float(np.ptp(radial - rro_record)) if radial.size else 0.0
    return RunoutSplit(
        Runout(radial_pp, axial_pp, rro_pp, nrro_pp), extra_pp, uncertainty, tuple(notes)
    )
