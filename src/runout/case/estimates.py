"""Estimates of what a case asks for: the memory and time of a run or a study of each model,
from the sizes of the case (instants, lines, harmonics, elements, samples), checked against
the budget of :mod:`runout.case.limits` before any work.

The costs per unit (``COST_*``, ``BYTES_*``) are policy and live in :mod:`runout.case.limits`
with the limits; the estimators that read a case live here, above the schema and the build.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from typing import Any

from runout.case._build import harmonic_counts
from runout.case._schema import VarySpec, sweep_count
from runout.case.limits import (
    BYTES_LINE_INSTANT,
    BYTES_QUASI_STATIC,
    COST_DYNAMIC_ELEMENT,
    COST_DYNAMIC_HARMONIC,
    COST_LINE_FIT,
    COST_LINEAR,
    COST_QUASI_STATIC,
    COST_ROLLER,
    COST_RUN,
    MAX_PHASE_ANGLE,
    LimitError,
    ResourceEstimate,
    case_budget,
    check,
    format_seconds,
)

__all__ = [
    "BYTES_PER_ROW_INSTANT",
    "COST_BATCH",
    "LEGACY_CHUNK_SIZE",
    "PASS_BYTES",
    "SKETCH_BYTES_PER_COLUMN",
    "STUDY_BYTES_PER_RUN",
    "Sizes",
    "batched_memory",
    "batched_sample_bytes",
    "batched_study",
    "check_limits",
    "estimate_run",
    "estimate_study",
    "sizes_of",
    "stream_columns",
    "study_chunk_size",
    "study_point_seconds",
    "study_points",
    "study_statistics",
    "study_threads",
]


# --------------------------------------------------------------------------------------------
# estimates of the models
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Sizes:
    """The sizes of a case that set the work of a run.

    Attributes
    ----------
    elements : int
        Number of rolling elements Z [-].
    ring_harmonics : int
        Harmonics of the inner plus the outer raceway.
    element_harmonics : int
        Harmonics of every element's diameter deviation, summed over the elements.
    largest_element : int
        Harmonics of the most detailed element.
    max_order : int
        Highest order of any part.
    samples, revolutions : float
        ``[analysis]`` samples and revolutions [-].
    """

    elements: int
    ring_harmonics: int
    element_harmonics: int
    largest_element: int
    max_order: int
    samples: float
    revolutions: float

    @property
    def contact_harmonics(self) -> float:
        """Harmonic evaluations per instant: Z contacts see both rings, each element its own."""
        return self.elements * (self.ring_harmonics + 1) + self.element_harmonics

    @property
    def lines(self) -> float:
        """Rough number of spectral lines fitted (a few per harmonic, and the Z multiples)."""
        return 4.0 * (self.ring_harmonics + self.element_harmonics) + 32.0


def sizes_of(case: Any) -> Sizes:
    """:class:`Sizes` of a validated case.

    Parameters
    ----------
    case : Case
        A validated case (its resolved imperfections, bearing and ``[analysis]``).

    Returns
    -------
    Sizes
    """
    imp = case.imperfections
    elements = [len(imp.elements[j]) + 1 for j in range(imp.n_elements)]
    orders = [imp.inner.max_order, imp.outer.max_order]
    orders += [h.max_order for h in imp.elements]
    return Sizes(
        elements=int(case.bearing.elements),
        ring_harmonics=len(imp.inner) + len(imp.outer),
        element_harmonics=sum(elements),
        largest_element=max(elements, default=1),
        max_order=max(orders, default=0),
        samples=float(case.analysis.samples),
        revolutions=float(case.analysis.revolutions),
    )


def _sync_instants(s: Sizes) -> float:
    """Instants of the synchronous grid of whole revolutions the quasi-static models solve."""
    whole = math.floor(s.revolutions + 1e-9)
    if whole < 2:
        return 0.0
    return whole * max(16.0, math.ceil(s.samples / whole))


def _instants_key(s: Sizes) -> str:
    """The key that sets the number of instants: revolutions when the synchronous grid rules."""
    return "analysis.revolutions" if _sync_instants(s) > 2.0 * s.samples else "analysis.samples"


def _highest_order_key(spec: Any) -> str:
    """The waviness, spectrum or profile entry with the highest order."""
    best, key = -1, "waviness"
    for table in ("waviness", "waviness_spectrum", "profile"):
        for i, entry in enumerate(getattr(spec, table), start=1):
            order = entry.order if table == "waviness" else entry.orders[1]
            if order > best:
                best = order
                key = f"{table}[{i}].order" if table == "waviness" else f"{table}[{i}].orders"
    return key


def estimate_run(case: Any, model: str) -> ResourceEstimate:
    """Memory and time of one run of ``model`` on ``case`` (before any allocation).

    The dynamic model's step count needs its natural frequencies;
    :func:`runout.models.dynamic.plan_integration` refines this estimate once they are known.

    Parameters
    ----------
    case : Case
        A validated case (a spindle case: every bearing's share).
    model : str
        Model id.

    Returns
    -------
    ResourceEstimate
        Peak memory of the large arrays [B] and computing time [s], with the case keys that
        size them.

    Raises
    ------
    LimitError
        For the quasi-static models, a record whose angles would pass
        :data:`~runout.case.limits.MAX_PHASE_ANGLE` [rad].
    """

    if model == "spindle" and getattr(case, "spindle", None) is not None:
        return _estimate_spindle(case)
    s = sizes_of(case)
    z = s.elements
    n = max(s.samples, _sync_instants(s))
    key = _instants_key(s)
    counts = harmonic_counts(case.spec, z)
    harmonics_key = max(counts, key=lambda c: c[1])[0] if counts else key
    instants = f"{n:.4g} instants"
    if model == "linear":
        memory = n * (8.0 * 16) + n * 16.0 * 4
        if case.imperfections.pitch_errors.any():
            seconds = n * s.contact_harmonics * COST_QUASI_STATIC
        else:
            seconds = n * s.lines * COST_LINEAR
        what = f"{instants} x {s.lines:.4g} lines"
    elif model in ("quasi_static_2d", "quasi_static_3d"):
        # one solve on the analysis grid; the deviations are evaluated inside the kernel
        n, key = s.samples, "analysis.samples"
        # a ball's harmonics turn with its spin, up to d_m / (2 D) times the ring's rotation
        bearing = case.bearing
        spin = max(1.0, bearing.pitch_diameter / (2.0 * bearing.element_diameter))
        angle = 2.0 * math.pi * s.revolutions * max(1, s.max_order) * spin
        if angle > MAX_PHASE_ANGLE:
            raise LimitError(
                "analysis.revolutions",
                f"the angles of the record would reach {angle:.3g} rad (2 pi x revolutions x "
                f"highest order {max(1, s.max_order)} x ball spin ratio {spin:.3g}), beyond "
                f"the {MAX_PHASE_ANGLE:.0e} rad within which double precision keeps their "
                "phase to 1e-7 rad; lower analysis.revolutions",
            )
        # the line fit keeps partial sums per line, direction and block of 256 instants, and
        # blocks of 2048 instants per line; pairs of ring harmonics add lines (seed 000 eq. 7)
        paired = min(s.ring_harmonics, 48)
        fitted = s.lines + 6.0 * paired * (paired - 1) / 2.0 / z
        per_line = BYTES_LINE_INSTANT * fitted * max(n, 256.0)
        memory = n * BYTES_QUASI_STATIC + per_line + 16.0 * min(fitted, 4096.0) * 4096.0
        if per_line > n * BYTES_QUASI_STATIC:
            key = harmonics_key  # the lines, i.e. the harmonics, not the record, are to cut
        seconds = n * s.contact_harmonics * COST_QUASI_STATIC
        seconds += n * s.lines * COST_LINE_FIT
        instants = f"{n:.4g} instants"
        what = f"{instants} x {z} elements x {s.contact_harmonics / z:.4g} harmonics"
    elif model == "roller_constraint":
        n = s.samples
        memory = n * (z * 8.0 * 16 + 3 * 8.0 * 8) + 16.0 * 8.0 * (s.max_order + 16) * 8
        per = s.ring_harmonics + s.largest_element + 2
        seconds = n * z * per * COST_ROLLER
        # the convexity check samples every part at 16 points per wave of its highest order
        grid = max(256.0, 16.0 * s.max_order)
        convexity = (z + 2) * 3 * grid * per * COST_QUASI_STATIC
        seconds += convexity
        what = f"{n:.4g} instants x {z} elements x {per} harmonics"
        key = "analysis.samples"
        if convexity > 0.5 * seconds:
            what = f"convexity of {z + 2} parts on {grid:.4g} angles x {per} harmonics"
            return ResourceEstimate(
                memory, seconds + COST_RUN, key, _highest_order_key(case.spec), what, what
            )
    elif model == "dynamic":
        # without the natural frequencies: at least one Newmark step per output instant
        memory = n * (3 * 8.0 * 8 + 16.0 * min(s.lines, 4096.0))
        seconds = n * (z * COST_DYNAMIC_ELEMENT + s.contact_harmonics * COST_DYNAMIC_HARMONIC)
        what = f"{n:.4g} output instants x {z} elements"
    else:  # equilibrium: one static solution, no record
        memory, seconds, what = 0.0, 0.0, "one equilibrium"
    seconds += COST_RUN
    time_key = key
    if s.ring_harmonics + s.element_harmonics > 64 * z and model != "equilibrium":
        # many harmonics: the orders, not the record, are what to cut
        time_key = harmonics_key
    return ResourceEstimate(memory, seconds, key, time_key, what, what)


def _estimate_spindle(case: Any) -> ResourceEstimate:
    """A spindle run: each bearing's contacts as a quasi_static_3d run of it, the line fit
    repeated at the nose and at every bearing's plane, the contact arrays of one chunk of
    instants and the shaft's record. Measured after compilation: examples/spindle_hdd.toml
    runs in 0.04 s (estimated 0.12 s), examples/spindle_machine_tool.toml (2 x 20 balls,
    2 x 44 harmonics, 4096 instants) in 0.09 s (estimated 0.52 s)."""
    from types import SimpleNamespace

    layout = case.spindle
    parts = [
        estimate_run(
            SimpleNamespace(
                imperfections=b.imperfections,
                bearing=b.bearing,
                analysis=case.analysis,
                spec=case.spec,
                spindle=None,
            ),
            "quasi_static_3d",
        )
        for b in layout.bearings
    ]
    # the nose and every bearing's plane; with several imperfect bearings, also the shaft
    # solved and fitted with each bearing's imperfections alone (the shares of shared lines)
    imperfect = sum(1 for b in layout.bearings if not b.imperfections.is_perfect)
    fits = len(layout.bearings) + 1 + (len(layout.bearings) if imperfect > 1 else 0)
    balls = sum(int(b.bearing.elements) for b in layout.bearings)
    n = float(case.analysis.samples)
    memory = max(p.memory for p in parts) + n * (6 + 3 * fits) * 8.0 + 4096.0 * balls * 24.0
    seconds = sum(p.seconds for p in parts) * fits + COST_RUN
    worst = max(parts, key=lambda p: p.seconds)
    what = (
        f"{len(layout.bearings)} bearings, {balls} balls: {worst.time_what} each, {fits} line fits"
    )
    return ResourceEstimate(memory, seconds, worst.memory_key, worst.time_key, what, what)


def study_points(case: Any) -> int:
    """Number of runs a case's ``[study]`` asks for (samples, or sweep points x models).

    Parameters
    ----------
    case : Case
        A validated case.

    Returns
    -------
    int
        0 without ``[study]``.
    """

    study = case.study
    if study is None:
        return 0
    if study.kind == "montecarlo":
        return int(study.samples)
    models = len(study.models) if study.models else 1
    total = models
    for key, entry in study.vary.items():
        total *= sweep_count(case.spec, key, entry)
    return int(total)


def _study_key(case: Any) -> str:
    """The key that sets the number of runs of a study: samples, or the largest sweep."""

    study = case.study
    if study is None or study.kind == "montecarlo":
        return "study.samples"
    best, key = 0, "study.vary"
    for name, entry in study.vary.items():
        count = sweep_count(case.spec, name, entry)
        if count > best and isinstance(entry, VarySpec):
            field = "values" if entry.values is not None else "num" if entry.num else "step"
            best, key = count, f"study.vary.{name}.{field}"
    return key


#: Bytes a study keeps per run (runout figures, line p-p and varied values; the records are not
#: kept: chunks are summarised as they finish).
STUDY_BYTES_PER_RUN = 2048.0
#: Seconds per instant and element of a batched ball-size Monte Carlo, everything included
#: (draws, kernel, line fit, RRO/NRRO split, records) on one thread: measured 15 ns (2x10^4
#: bearings x 1024 instants x 10 balls in 3.1 s of CPU). Two Numba threads in-process or two
#: worker processes take about half of that in wall time.
COST_BATCH = 1.5e-8


def batched_study(case: Any) -> bool:
    """The ball-size Monte Carlo of the unloaded 2-D model, which runs batched (runout.study.run).

    Parameters
    ----------
    case : Case
        A validated case with a ``[study]``.

    Returns
    -------
    bool
        True for a Monte Carlo of ``quasi_static_2d`` alone, without radial load, that varies
        only the balls' sizes.
    """
    study = case.study
    models = tuple(study.models) if study.models else (case.analysis.model,)
    return bool(
        study.kind == "montecarlo"
        and models == ("quasi_static_2d",)
        and case.operation.radial_load == 0.0
        and all(
            key in ("element_diameter_sigma", "ball_grade", "elements.diameter_errors")
            for key in study.vary
        )
        and not _draws_ball_form(case)
    )


def _draws_ball_form(case: Any) -> bool:
    """Whether a ball-size draw also draws each ball's form (``[elements] grade_form_order``
    on a graded bearing: runout.study._plan), which the batched kernel does not model."""
    elements = case.spec.elements
    if getattr(elements, "grade_form_order", None) is None:  # none, or a spindle's tables
        return False
    vary = case.study.vary
    return "ball_grade" in vary or ("element_diameter_sigma" in vary and elements.grade)


#: Bytes one pass of :func:`runout.study._pool.evaluate_rows` holds per bearing and instant:
#: the records (16), their transposed copy for the line fit (16), the RRO waveform or the
#: residual of the split (8) and a margin (measured ~40 B).
BYTES_PER_ROW_INSTANT = 48
#: Most memory one pass of :func:`runout.study._pool.evaluate_rows` holds [B]: a chunk with
#: more bearings than fit is evaluated in passes of rows (each row's numbers depend on that
#: row only, so the passes change nothing but the memory).
PASS_BYTES = 64 * 2**20


def batched_memory(case: Any, workers: int = 1) -> float:
    """Memory of a batched ball-size Monte Carlo's arrays [B], summaries apart.

    The shared arrays (time, the balls' approaches and angles, the line projector:
    :class:`runout.study._pool.BatchArrays`) exist once in this process, and with worker
    processes once more in every worker and in the pickles of its chunks in flight (two per
    worker); each concurrent evaluation (a Numba thread in this process, or a worker) holds one
    pass of rows (:data:`PASS_BYTES` at most).

    Parameters
    ----------
    case : Case
        A validated case with a ball-size Monte Carlo ``[study]``.
    workers : int
        Worker processes (1: the study runs in this process, one chunk per Numba thread).

    Returns
    -------
    float
        Estimated peak memory of the arrays [B].
    """
    s = sizes_of(case)
    n = float(s.samples)
    shared = n * (8.0 + 16.0 * s.elements + 8.0 * (1.0 + 2.0 * s.lines))
    if workers <= 1:
        copies, concurrent = 1.0, float(max(2, os.cpu_count() or 1))
    else:
        copies, concurrent = 1.0 + 3.0 * workers, float(workers)
    # a chosen chunk size is at most MAX_CHOSEN_CHUNK samples: the bound where none is given
    given = case.study.chunk_size
    chunk = float(min(MAX_CHOSEN_CHUNK if given is None else given, case.study.samples))
    one_pass = min(float(PASS_BYTES), max(1.0, chunk) * n * BYTES_PER_ROW_INSTANT)
    return copies * shared + concurrent * one_pass


def batched_sample_bytes(case: Any) -> float:
    """Bytes a batched ball-size Monte Carlo keeps per sample [B].

    The study's result columns are float64 arrays (:class:`runout.study.run.StudyResult`): the
    Z drawn diameters, the four runout figures, the p-p of every line in x and y
    (:attr:`Sizes.lines`, an upper bound) and the sample's model; nothing per sample besides.

    Parameters
    ----------
    case : Case
        A validated case with a ball-size Monte Carlo ``[study]``.

    Returns
    -------
    float
        Bytes per sample [B].
    """
    s = sizes_of(case)
    return 8.0 * (s.elements + 4.0 + 2.0 * s.lines + 1.0)


def study_threads() -> int:
    """Threads a batched Monte Carlo runs on in this process (Numba's, as the study uses).

    Returns
    -------
    int
        ``NUMBA_NUM_THREADS`` where set to a positive integer (at most the cores), else the
        cores of the machine.
    """
    limit = os.environ.get("NUMBA_NUM_THREADS", "").strip()
    cores = os.cpu_count() or 1
    return max(1, min(cores, int(limit))) if limit.isdigit() and int(limit) > 0 else cores


#: Bytes of the streaming statistics of one column (a runout figure or a line) [B]: the
#: quantile sketch's occupied buckets, 16 bytes each, for values spread over six decades at a
#: relative accuracy of 1e-4 (ln(10^6) / ln((1 + 1e-4) / (1 - 1e-4)) ~ 69,000 buckets).
SKETCH_BYTES_PER_COLUMN = 16.0 * 69_000


def study_statistics(case: Any, workers: int = 1) -> str:
    """How a study reduces its samples: ``"exact"`` or ``"streaming"`` (``[study] statistics``).

    ``"auto"`` is exact when the per-sample columns fit the memory budget (with ``workers``
    worker processes, each holding the shared arrays of a batched Monte Carlo), streaming
    otherwise. A sweep is always exact (its JSON lists every point).

    Parameters
    ----------
    case : Case
        A validated case with a ``[study]``.
    workers : int
        Local worker processes of the study (1: in this process).

    Returns
    -------
    str
        ``"exact"`` or ``"streaming"``.
    """
    study = case.study
    asked = getattr(study, "statistics", "auto")
    if study.kind != "montecarlo" or asked != "auto":
        return "exact" if study.kind != "montecarlo" else str(asked)
    per_run = _per_run(case)
    memory = estimate_study(case, per_run, "exact").memory
    if workers > 1 and batched_study(case):
        memory = batched_memory(case, workers) + study_points(case) * batched_sample_bytes(case)
    return "exact" if memory <= case_budget(case).memory else "streaming"


def _per_run(case: Any) -> ResourceEstimate:
    """The estimate of one run of the study's largest model."""
    models = list(case.study.models) if case.study.models else [case.analysis.model]
    return max((estimate_run(case, m) for m in models), key=lambda e: (e.seconds, e.memory))


def stream_columns(case: Any) -> int:
    """Columns a streaming study summarises: the four runout figures and every line in x and
    y (:attr:`Sizes.lines`, an upper bound).

    Parameters
    ----------
    case : Case
        A validated case with a ``[study]``.

    Returns
    -------
    int
        The number of columns, each one :class:`runout.study._stream.StreamStatistics`.
    """
    return 4 + 2 * int(sizes_of(case).lines)


def estimate_study(
    case: Any, per_run: ResourceEstimate, statistics: str | None = None
) -> ResourceEstimate:
    """Memory and time of a case's whole ``[study]`` from the estimate of one run.

    The records are not kept (each chunk is summarised as it finishes): memory is one run's
    plus :data:`STUDY_BYTES_PER_RUN` per run; a batched ball-size Monte Carlo keeps
    :func:`batched_sample_bytes` per sample, holds its shared arrays and one pass of rows per
    concurrent evaluation (:func:`batched_memory`, in this
    process; :func:`runout.study.run.run_study` checks again for worker processes) and costs
    :data:`COST_BATCH` per instant and ball instead of a whole run.

    Parameters
    ----------
    case : Case
        A validated case with a ``[study]``.
    per_run : ResourceEstimate
        Estimate of one run [B, s] (the largest of the study's models).
    statistics : {"exact", "streaming"}, optional
        The study's reduction (default: :func:`study_statistics`). Streaming keeps no
        per-sample column: the chunks in flight and :data:`SKETCH_BYTES_PER_COLUMN` per
        summarised column instead of the bytes per sample.

    Returns
    -------
    ResourceEstimate
        Memory [B] and time [s] of the whole study; the key that sets the number of runs.
    """
    points = study_points(case)
    key = _study_key(case)
    streaming = (statistics or study_statistics(case)) == "streaming"
    if streaming:  # per sample nothing: the chunks in flight (two per core) and the sketches
        # a chosen chunk size is at most MAX_CHOSEN_CHUNK samples: the bound where none is given
        chunk = case.study.chunk_size or MAX_CHOSEN_CHUNK
        in_flight = 2 * max(1, os.cpu_count() or 1) * min(points, chunk)
        kept_runs = float(in_flight)
        sketches = stream_columns(case) * SKETCH_BYTES_PER_COLUMN
    else:
        kept_runs, sketches = float(points), 0.0
    memory = per_run.memory + kept_runs * STUDY_BYTES_PER_RUN + sketches
    each = per_run.seconds
    seconds_per_thread, on = 1.0, ""
    if batched_study(case):
        # compact result columns instead of a run's record per sample; the chunks run side by
        # side on every thread of this process (measured: wall time = CPU time / threads)
        kept = sketches if streaming else points * batched_sample_bytes(case)
        memory = max(per_run.memory, batched_memory(case)) + kept
        each = case.analysis.samples * case.bearing.elements * COST_BATCH
        seconds_per_thread = 1.0 / study_threads()
        on = f" on {study_threads()} threads" if study_threads() > 1 else ""
    seconds = points * each * seconds_per_thread
    what = f"{points} runs x about {format_seconds(each)} each{on}"
    return ResourceEstimate(memory, seconds, key, key, f"{points} runs", what)


#: Work a chosen chunk aims at [s of CPU]: its fixed costs (a task, a chunk file, an entry in
#: the manifest: milliseconds) stay small beside it, and progress and a resume lose little.
CHUNK_SECONDS = 0.25
#: Chunks per concurrent evaluation a chosen chunk size leaves at least, where the study has
#: enough samples: the last chunks of the workers finish close together.
CHUNKS_PER_WORKER = 4
#: Largest chosen chunk [samples]: a chunk's file and its Python lists stay some megabytes.
MAX_CHOSEN_CHUNK = 2_048
#: Chunk size of earlier versions, where ``[study] chunk_size`` is not given and the size is
#: not chosen (a study's digest keeps it: older output directories still resume).
LEGACY_CHUNK_SIZE = 250


def study_point_seconds(case: Any) -> float:
    """Estimated CPU time of one point of a case's study on one thread [s].

    Parameters
    ----------
    case : Case
        A validated case with a ``[study]``.

    Returns
    -------
    float
        A batched ball-size Monte Carlo: :data:`COST_BATCH` per instant and ball; any other
        study: one run of its costliest model (:func:`estimate_run`).
    """
    if batched_study(case):
        return float(case.analysis.samples * case.bearing.elements * COST_BATCH)
    models = list(case.study.models) if case.study.models else [case.analysis.model]
    return max(estimate_run(case, m).seconds for m in models)


def study_chunk_size(case: Any, concurrency: int) -> int:
    """Samples per chunk of a study whose case and command line do not set it.

    About :data:`CHUNK_SECONDS` of estimated work per chunk (:func:`study_point_seconds`),
    but at least :data:`CHUNKS_PER_WORKER` chunks per concurrent evaluation where the study
    has that many points, and at most :data:`MAX_CHOSEN_CHUNK` samples. The numbers of a
    study do not depend on its chunk size (each sample's draws are its own), only its speed,
    its memory in flight and the granularity of ``--resume``.

    Parameters
    ----------
    case : Case
        A validated case with a ``[study]``.
    concurrency : int
        Chunks evaluated at once (worker processes, or this process's threads).

    Returns
    -------
    int
        The chunk size [samples], at least 1.
    """
    points = max(1, study_points(case))
    per_point = max(study_point_seconds(case), 1e-9)
    size = math.ceil(CHUNK_SECONDS / per_point)
    balanced = math.ceil(points / (CHUNKS_PER_WORKER * max(1, concurrency)))
    return int(max(1, min(size, balanced, MAX_CHOSEN_CHUNK)))


def check_limits(case: Any) -> None:
    """Refuse a case whose run (or study) would exceed the budget, before any work.

    Parameters
    ----------
    case : Case
        A validated case; its budget is :func:`runout.case.limits.case_budget`.

    Raises
    ------
    LimitError
        The estimate of a run, or of the study, beyond the memory or time budget.
    """
    limits = case_budget(case)
    per_run = estimate_run(case, case.analysis.model)
    if case.study is not None:
        per_run = _per_run(case)
        mode = study_statistics(case)
        estimate = estimate_study(case, per_run, mode)
        if getattr(case.study, "statistics", "auto") == "exact" and case.study.kind == "montecarlo":
            try:
                check(estimate, limits)
            except LimitError as exc:
                if not estimate.memory > limits.memory:
                    raise
                # the columns of every sample do not fit: the streaming statistics would
                raise LimitError(
                    "study.statistics",
                    f'"exact" keeps every sample\'s figures: {exc.message}; or set '
                    'statistics = "streaming" (or "auto")',
                ) from None
        else:
            check(estimate, limits)
    check(per_run, limits)
