r"""Studies at scale: Monte Carlo over drawn case quantities and sweeps over listed ones.

A study takes a validated :class:`runout.case.model.Case` with a ``[study]`` table and evaluates
many variants of it: *samples* (Monte Carlo bearings) or *points* (sweep values × models). Each
variant is the case with some quantities replaced, validated like a case file and run by the
model named in ``[analysis]`` (or ``[study] models``); from each run we keep the runout figures
and every labelled line (:class:`runout.analysis.results.Component`, p-p [m]).

Randomness
----------
A study draws from one counter-based Philox stream keyed by ``SeedSequence(seed)``; sample ``i``
takes a fixed run of its words (:func:`runout.study._plan.sample_uniforms`, sampling version
:data:`SAMPLING`), and a chunk draws all its samples in one call. The numbers of a sample
therefore depend only on ``(seed, i)``, never on the chunking, the number of workers or the
order in which chunks finish; runs are reproducible bit for bit. A resume of a Monte Carlo
written by an earlier sampling version is refused (its samples are other bearings).

Execution
---------
Samples are grouped in chunks of ``chunk_size``; a chunk is one task. Tasks run in the calling
process, in a local process pool (``workers``), or on any :class:`concurrent.futures.Executor`
(a Dask ``Client.get_executor()``, see :func:`dask_executor`). A ball-size Monte Carlo of the
2-D model is batched: the parent computes what every bearing shares once
(:class:`runout.study._pool.BatchArrays`) and ships it with every chunk, and a chunk is one
call of the batched Numba kernel :func:`runout.study._kernels.solve_batch` (threads over
bearings in the calling process) plus a vectorised line fit and RRO/NRRO split
(:func:`runout.study._pool.evaluate_rows`). The pool is one for the whole study: its workers
start and load the kernels while the parent plans, and serve every chunk.

With an output directory each finished chunk is written as one JSON file
and recorded in ``manifest.json``; :func:`run_study` with ``resume=True`` skips the chunks
already written, so an interrupted run ends with the same files, byte for byte, as an
uninterrupted one.

Safety
------
An output directory has one writer at a time (:func:`output_lock`), holds only runout's
files unless forced (:func:`refuse_foreign`), and every file in it is replaced atomically
through a uniquely named temporary (:func:`write_atomic`). Every chunk carries the digest of
the case and study that wrote it; a resume recomputes a chunk that is unreadable, damaged or
another study's. A sample whose model raises is recorded with its error (:func:`error_text`)
and the study goes on. Pool workers end with their parent, even a SIGKILLed one
(:func:`die_with_parent`). docs/studies.md, "Safety", lists the behaviour and the messages.

Statistics
----------
Each finished chunk is copied into the result's float64 columns and dropped
(:class:`_Assembly`): memory is the columns (8 bytes per sample and column) and the chunks in
flight. Every runout figure and line is summarised by its mean, sample standard deviation
(ddof = 1), 2σ, 5/50/95 % percentiles (linear interpolation, exact), min, max and a histogram.
A line missing from a sample's output (below the model's reporting floor) counts as 0 in that
sample.

With ``[study] statistics = "streaming"`` (or ``"auto"`` when the columns do not fit the memory
budget: :func:`runout.case.estimates.study_statistics`) each chunk is reduced instead into
streaming statistics (:class:`_Streaming`, :mod:`runout.study._stream`): memory independent of
the number of samples, exact count, min, max, mean and std (the same bits for any chunking),
percentiles and histograms from a quantile sketch of relative accuracy 1e-4.
"""

from __future__ import annotations

import csv
import dataclasses
import hashlib
import itertools
import json
import logging
import math
import os
import re
import threading
import time
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import (
    FIRST_COMPLETED,
    Executor,
    Future,
    ProcessPoolExecutor,
    ThreadPoolExecutor,
    wait,
)
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from runout.base.errors import CaseError
from runout.base.reading import MISSING, InputFileError, read_json
from runout.case import estimates, limits
from runout.case._schema import ARRANGEMENT_KEYS
from runout.case.model import Case, StudySpec
from runout.study._chunks import ERROR_CHARS as ERROR_CHARS
from runout.study._chunks import ERRORS_SHOWN as ERRORS_SHOWN
from runout.study._chunks import (
    ChunkTask,
    _threads,
    _with_batch,
    chunk_json,
    error_text,
    evaluate_chunk,
    line_label,
)
from runout.study._files import (
    _RESUME_KEYS,
    OutputError,
    _chunk_problem,
    _read_manifest,
    output_directory,
    output_lock,
    refuse_foreign,
    write_atomic,
)
from runout.study._files import LOCK_NAME as LOCK_NAME
from runout.study._files import (
    _remove_leftovers as _remove_leftovers,  # runout.models.dynamic's sweep
)
from runout.study._plan import (
    FORMAT,
    RUNOUT_KEYS,
    SAMPLING,
    Quantity,
    StudyError,
    _case_data,
    _digest_data,
    _models,
    _study_of,
    draw_block,
    draw_width,
    plan_quantities,
    sample_rng,
    sample_uniforms,
)
from runout.study._result import (
    COLUMNS_FILE,
    COLUMNS_FORMAT,
    CSV_BLOCK,
    StreamedStudyResult,
    StudyResult,
    _cells,
    _write_text,
    line_column_names,
    statistics,
)
from runout.study._result import YIELD_CONFIDENCE as YIELD_CONFIDENCE
from runout.study._result import (
    _dumps as _dumps,  # runout.models.dynamic's sweep
)
from runout.study._stream import QUANTILE_RELATIVE_ERROR, StreamStatistics
from runout.study._workers import die_with_parent, init_worker, spawn_context, worker_threads

__all__ = [
    "RUNOUT_KEYS",
    "SAMPLING",
    "ChunkTask",
    "OutputError",
    "Quantity",
    "StudyError",
    "StudyResult",
    "dask_executor",
    "die_with_parent",
    "draw_block",
    "draw_width",
    "error_text",
    "evaluate_chunk",
    "line_label",
    "load_study",
    "output_directory",
    "output_lock",
    "plan_quantities",
    "refuse_foreign",
    "refuse_unbuildable",
    "run_study",
    "sample_rng",
    "sample_uniforms",
    "statistics",
    "write_atomic",
]


# --------------------------------------------------------------------------------------------
# running
# --------------------------------------------------------------------------------------------
#: The pool workers' set-up (kept under its former name for callers).
_init_worker = init_worker
#: The start method of pool workers (kept under its former name for callers).
_context = spawn_context


def dask_executor(address: str | None = None, **cluster: Any) -> Executor:
    """A :class:`concurrent.futures.Executor` on Dask distributed.

    Parameters
    ----------
    address : str, optional
        Scheduler address: ``tcp://HOST:PORT``, ``tls://HOST:PORT``, ``HOST:PORT`` or
        ``"local"`` (:func:`runout.study.scheduler.scheduler_address`); None (or ``"local"``)
        starts a local cluster.
    **cluster
        Keyword arguments of :class:`distributed.LocalCluster` for a local cluster.

    Returns
    -------
    concurrent.futures.Executor
        The executor of a Dask client (``Client.get_executor()``), for :func:`run_study`.

    Raises
    ------
    StudyError
        A malformed address (refused before any connection), Dask not installed
        (``pip install 'runout[dask]'``), or a scheduler that does not accept the connection
        within the connect timeout or does not answer within the response timeout
        (:mod:`runout.study.scheduler`: ``RUNOUT_SCHEDULER_CONNECT_TIMEOUT``, 10 s, and
        ``RUNOUT_SCHEDULER_RESPONSE_TIMEOUT``, 30 s). Each names ``--scheduler``.
    """
    from runout.study.scheduler import connect_client, scheduler_address

    remote = None if address is None else scheduler_address(address)
    try:
        import dask
        from distributed import Client, LocalCluster
    except ImportError:  # pragma: no cover - depends on the installation
        raise StudyError("--scheduler needs Dask distributed: pip install 'runout[dask]'") from None
    if remote is not None:
        return connect_client(remote).get_executor()
    try:
        cluster.setdefault("dashboard_address", None)
        # Dask's nannies trim malloc at 64 KiB by default (MALLOC_TRIM_THRESHOLD_), which
        # returns every NumPy temporary of a chunk to the system and costs the workers
        # much of their time; a local cluster of ours keeps glibc's usual behaviour.
        trim = {"distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": 2**28}
        with dask.config.set(trim):
            client = Client(LocalCluster(**cluster))
    except (OSError, TimeoutError) as exc:
        raise StudyError(f"--scheduler: cannot start a local Dask cluster: {exc}") from None
    return client.get_executor()


def _digest(
    data: dict[str, Any], study: StudySpec, base_dir: str, given: dict[str, Any] | None = None
) -> str:
    """SHA-256 of what decides a study's numbers: the case (SI), ``[study]``, profile files.

    A ``[[profile]]`` names a CSV file; its bytes are part of the case, so a remeasured
    profile makes another study (its chunks are recomputed on resume) even when the case file
    itself did not change. ``data`` is the case with its defaults (the document earlier
    versions hashed); ``given``, the keys the case gives, marks a bearing given by its
    catalogue angle: earlier versions built every sample of it with a clearance of 0 as well
    and recorded each as failed, so their chunks must not be taken up by a resume.
    """
    files: dict[str, str] = {}
    for entry in data.get("profile", []):
        name = str(entry.get("file", ""))
        try:
            files[name] = hashlib.sha256((Path(base_dir) / name).read_bytes()).hexdigest()
        except OSError:
            files[name] = "unreadable"  # parse_case reports it when the study runs
    # the allocation keys (unset in every study of earlier versions, and in each study an
    # allocation runs) and the arrangement keys (read by kind = "arrangement" only, which
    # writes no chunks) stay out of the digest: older output directories still resume
    unset = {k for k in ("allocate", "target_yield") if getattr(study, k) is None}
    if study.kind != "arrangement":
        unset |= set(ARRANGEMENT_KEYS)
    # how the samples are reduced changes no sample: chunks of either mode resume each other
    unset.add("statistics")
    doc: dict[str, Any] = {"case": data, "study": study.model_dump(mode="json", exclude=unset)}
    if study.chunk_size is None and "chunk_size" in doc["study"]:
        # a chosen chunk size: earlier versions' default in the digest, so that their output
        # directories still resume (the numbers do not depend on the chunk size)
        doc["study"]["chunk_size"] = estimates.LEGACY_CHUNK_SIZE
    if given is not None and _by_catalogue_angle(given):
        doc["samples_built_from"] = "the keys the case gives"
    if files:  # studies without profiles keep the digest of earlier versions
        doc["profile_files"] = files
    if study.kind == "montecarlo":  # its samples are drawn: the draws' version decides them
        doc["sampling"] = SAMPLING
    text = json.dumps(doc, sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()


def _by_catalogue_angle(given: dict[str, Any]) -> bool:
    """Whether a bearing of the case document ``given`` states its nominal contact angle."""
    tables = [given.get("bearing"), *(given.get("bearings") or [])]
    return any(isinstance(t, dict) and "nominal_contact_angle" in t for t in tables)


def _chunk_path(directory: Path, index: int) -> Path:
    return directory / "chunks" / f"chunk_{index:05d}.json"


@dataclass(frozen=True)
class _Plan:
    """A study cut into chunks: what run_study and load_study both need."""

    study: StudySpec
    quantities: tuple[Quantity, ...]
    models: tuple[str, ...]
    total: int
    size: int
    tasks: list[ChunkTask]
    digest: str

    def manifest(self) -> dict[str, Any]:
        """A fresh manifest.json document of this plan (no chunk done)."""
        return {
            "format": FORMAT,
            "digest": self.digest,
            "kind": self.study.kind,
            "samples": self.total,
            "chunk_size": self.size,
            "chunks": len(self.tasks),
            "done": [],
            "complete": False,
            "sampling": SAMPLING,
        }


def _plan(
    case: Case, chunk_size: int | None, parallel: bool = False, concurrency: int = 1
) -> _Plan:
    """The study's chunks: ``chunk_size``, else ``[study] chunk_size``, else a size chosen from
    the estimated cost of a sample for ``concurrency`` chunks at once
    (:func:`runout.case.estimates.study_chunk_size`)."""
    study = _study_of(case)
    data = _case_data(case)
    quantities = tuple(plan_quantities(case, data))
    models = tuple(_models(case))
    if study.kind == "montecarlo":
        total = study.samples
    else:
        total = len(models) * math.prod(len(q.values) for q in quantities)
    size = chunk_size or study.chunk_size or estimates.study_chunk_size(case, concurrency)
    n_chunks = max(1, math.ceil(total / size))
    base_dir = str(Path(case.path).resolve().parent) if case.path != "<case>" else os.getcwd()
    tasks = [
        ChunkTask(
            index=k,
            start=k * size,
            stop=min(total, (k + 1) * size),
            data=data,
            path=case.path,
            base_dir=base_dir,
            quantities=quantities,
            kind=study.kind,
            seed=study.seed,
            models=models,
            parallel=parallel,
        )
        for k in range(n_chunks)
    ]
    digest = _digest(_digest_data(case), study, base_dir, data)
    return _Plan(study, quantities, models, total, size, tasks, digest)


_log = logging.getLogger(__name__)


def run_study(
    case: Case,
    *,
    executor: Executor | None = None,
    workers: int = 1,
    out: Path | str | None = None,
    resume: bool = False,
    progress: Callable[[int, int], None] | None = None,
    chunk_size: int | None = None,
    plots: bool = True,
    force: bool = False,
    notify: Callable[[str], None] | None = None,
) -> StudyResult:
    """Run the study described by ``case.study``.

    Parameters
    ----------
    case : Case
        A validated case with a ``[study]`` table.
    executor : concurrent.futures.Executor, optional
        Where chunks run (e.g. :func:`dask_executor`); overrides ``workers``.
    workers : int
        Local worker processes when no executor is given (1: in this process, where the
        chunks of a batched Monte Carlo run on Numba's number of threads). The workers end
        with this process, even when it is killed (:func:`die_with_parent`).
    out : path, optional
        Directory for the chunk files, ``manifest.json``, ``summary.json``, ``samples.csv`` and
        plots. It must be empty, new, or the output of a study (see ``force``); it is locked
        for the whole run (:func:`output_lock`).
    resume : bool
        Continue the run recorded in ``out/manifest.json`` (same case and study required).
        Every chunk is checked (readable, complete, written by this study: its ``digest``);
        one that is not is recomputed and said through ``notify``.
    progress : callable, optional
        Called as ``progress(samples_done, samples_total)`` after every chunk.
    chunk_size : int, optional
        Overrides ``[study] chunk_size``.
    plots : bool
        Write plots into ``out``.
    force : bool
        Write into a non-empty directory that is not a study output, start afresh over a
        corrupted manifest or over a different study instead of refusing.
    notify : callable, optional
        Called with a one-line note (chunks recomputed on resume, a manifest replaced under
        ``force``); default: a warning on the ``runout.study.run`` logger.

    Returns
    -------
    StudyResult
        Failed samples are in ``errors``; the study does not stop on one (unless every one
        of its first samples is refused for one input: see Raises).

    Raises
    ------
    StudyError
        Bad output directory (:class:`OutputError`: empty path, a file, unwritable, foreign,
        locked by another writer), a corrupted manifest, a resume that does not match the
        case, or a worker process that died.
    CaseError
        A key a model refuses, or the first samples all refused for one input
        (:func:`refuse_unbuildable`), before any sample runs and any file is written.
    """
    in_process = executor is None and workers <= 1
    if chunk_size is None and case.study is not None and case.study.chunk_size is None:
        chunk_size = _resumed_chunk_size(out, resume)
    plan = _plan(
        case,
        chunk_size,
        in_process and threading.current_thread() is threading.main_thread(),
        _concurrency(case, executor, workers),
    )
    from runout.case.conventions import enforce

    for model in plan.models:  # a key a model refuses ends the study before any work
        enforce(case, model)
    _check_analysis_outputs(case, notify or _log.warning)
    refuse_unbuildable(plan)
    local = workers if executor is None else 1
    streaming = estimates.study_statistics(case, local) == "streaming"
    if executor is None and workers > 1 and estimates.batched_study(case):
        # the case's estimate assumed this process; worker processes each hold the shared
        # arrays too (and the chunks in flight): check the budget for them before starting
        kept = (
            estimates.stream_columns(case) * estimates.SKETCH_BYTES_PER_COLUMN
            if streaming
            else estimates.study_points(case) * estimates.batched_sample_bytes(case)
        )
        needed = estimates.batched_memory(case, workers) + kept
        budget = limits.case_budget(case)
        if needed > budget.memory:
            raise limits.LimitError(
                "study.samples",
                f"{workers} worker processes would need about {limits.format_bytes(needed)} "
                f"of memory (each holds the study's shared arrays); use fewer --workers, "
                f"lower analysis.samples or raise the limit ({limits.format_bytes(budget.memory)})"
                f" with [analysis] max_memory or {limits.ENV_MAX_MEMORY}",
            )
    notify = notify or _log.warning
    mode = _streaming_notes(case, local) if streaming else None
    if out is None:
        return _run(
            None, case, plan, executor, workers, False, False, progress, plots, notify, mode
        )
    directory = output_directory(out)
    refuse_foreign(directory, "study", force)
    with output_lock(directory):
        return _run(
            directory, case, plan, executor, workers, resume, force, progress, plots, notify, mode
        )


#: Chunks evaluated at once on an external executor (Dask), for a chosen chunk size: its
#: workers are not known here; a cluster of other size sets ``--chunk-size``.
EXTERNAL_CONCURRENCY = 16


def _concurrency(case: Case, executor: Executor | None, workers: int) -> int:
    """Chunks evaluated at once: worker processes, the threads of this process (a batched
    Monte Carlo), or :data:`EXTERNAL_CONCURRENCY` on an external executor."""
    if executor is not None:
        return EXTERNAL_CONCURRENCY
    if workers > 1:
        return workers
    return estimates.study_threads() if estimates.batched_study(case) else 1


def _resumed_chunk_size(out: Path | str | None, resume: bool) -> int | None:
    """The chunk size of the run ``--resume`` continues (a chosen size depends on the
    workers and cores, which may differ now), or None: none to continue, or a manifest that
    :func:`_prepare_directory` refuses (or replaces under ``--force``) with its reason."""
    if not resume or out is None:
        return None
    try:
        size = _read_manifest(Path(out) / "manifest.json")["chunk_size"]
    except (StudyError, OSError):
        return None
    return int(size)


def _streaming_notes(case: Case, workers: int) -> tuple[str, ...]:
    """The notes of a streaming study: why it streams and what that changes."""
    study = case.study
    assert study is not None
    if study.statistics == "auto":
        budget = limits.case_budget(case)
        why = (
            f'study.statistics = "auto": the per-sample columns of {study.samples} samples do '
            f"not fit the memory budget ({limits.format_bytes(budget.memory)}), so the "
            "statistics are streamed"
        )
    else:
        why = 'study.statistics = "streaming"'
    return (
        f"{why}: count, mean, std, min, max and the yield are exact; the percentiles are "
        f"within a relative {QUANTILE_RELATIVE_ERROR:g} of the exact ones and each histogram "
        "counts the sketch's buckets (a sample within that of a bin edge may be counted in "
        "the next bin)",
        "per-sample values are not kept in memory: with --out, samples.csv and "
        "samples_columns.json are written from the chunk files afterwards, one chunk at a "
        "time, and histograms.png is drawn from the summary's bins; stiffness.csv is not "
        'written (set study.statistics = "exact" for it)',
    )


#: Monte Carlo samples built before a study runs: when every one of them is refused for the
#: same case key, the study stops with that refusal (docs/studies.md, "Failed samples").
FIRST_SAMPLES = 20


def refuse_unbuildable(plan: _Plan) -> None:
    """Stop a study whose first samples are all refused for the same input, before any runs.

    The first :data:`FIRST_SAMPLES` samples of a Monte Carlo (every point of a sweep) are
    built as their chunks would build them (drawn values placed, the case validated, the
    bearing built, the model's refusals) until one is built. Building is milliseconds; a model
    run is not. When none is built and every one was refused for the same case key, no
    sample can run: the refusal is raised at once, as ``runout check`` gives it, instead of
    recording it under every sample of the lot. Samples refused in a tail of a distribution
    (or points of a sweep that a later value brings back) leave the study running as before.

    Parameters
    ----------
    plan : _Plan
        The study's plan (its first task holds what every sample is drawn and built from).

    Raises
    ------
    CaseError
        The first sample's refusal, naming the case file and key, with how many samples
        share it.
    """
    from runout.case.conventions import enforce
    from runout.study._chunks import _point, _variant

    if not plan.tasks:
        return
    task = plan.tasks[0]  # every task draws and builds sample i the same way
    count = plan.total if plan.study.kind == "sweep" else min(FIRST_SAMPLES, plan.total)
    first: CaseError | None = None
    for i in range(count):
        model, values = _point(task, i)
        try:
            enforce(_variant(task, model, values), model)
        except CaseError as exc:
            if first is not None and (exc.file, exc.key) != (first.file, first.key):
                return  # refused for different reasons: the samples' own errors say which
            first = first or exc
            continue
        except Exception:  # not an input error: the model's run records it per sample
            return
        return  # this sample builds: the study runs
    if first is None:
        return
    word = "samples" if plan.study.kind == "montecarlo" else "points"
    which = f"the first {count} {word}" if count < plan.total else f"all {count} {word}"
    drawn = ", ".join(q.key for q in plan.quantities)
    raise CaseError(
        first.file,
        first.key,
        f"{first.message} (in each of {which}, built from study.vary: {drawn}; "
        "the study stops before running any)",
    )


def _check_analysis_outputs(case: Case, notify: Callable[[str], None]) -> None:
    """Refuse a band limit and say that bands are not computed: a study keeps the runout
    figures and line p-p of each sample, not the phases a band value needs."""
    analysis = case.analysis
    if getattr(analysis, "limit", None) is not None and analysis.limit_on.startswith("iso15242"):
        raise CaseError(
            case.path,
            "analysis.limit_on",
            f'"{analysis.limit_on}": a study\'s yield is over the runout p-p of each sample '
            '("radial_pp", "rro_pp", "nrro_pp", "axial_pp"); band limits apply to runout run',
        )
    if getattr(analysis, "bands", None) is not None:
        notify(
            f"{case.path}: analysis.bands: not applied by runout study (band values are "
            "computed by runout run)"
        )


def _run(
    directory: Path | None,
    case: Case,
    plan: _Plan,
    executor: Executor | None,
    workers: int,
    resume: bool,
    force: bool,
    progress: Callable[[int, int], None] | None,
    plots: bool,
    notify: Callable[[str], None],
    streaming: tuple[str, ...] | None = None,
) -> StudyResult:
    """run_study once ``directory`` (if any) is checked and locked.

    Every chunk is added to the result's columns as it finishes (:class:`_Assembly`) and then
    dropped: the study holds its compact columns and the chunks in flight, never all chunks.
    With ``streaming`` (the notes of a streaming study) each chunk is reduced into streaming
    statistics instead (:class:`_Streaming`): memory independent of the number of samples.
    """
    manifest = plan.manifest()
    assembly: _Assembly | _Streaming = (
        _Assembly(case, plan) if streaming is None else _Streaming(case, plan, streaming)
    )
    done: set[int] = set()
    if directory is not None:
        done = _prepare_directory(directory, manifest, plan, resume, force, notify, assembly.add)
    tasks = plan.tasks
    done_samples = sum(tasks[k].stop - tasks[k].start for k in done)
    if progress is not None:
        progress(done_samples, plan.total)
    pending = [t for t in tasks if t.index not in done]
    written_at = time.monotonic()

    def finished(index: int, chunk: dict[str, Any]) -> None:
        nonlocal done_samples, written_at
        # the chunk names the case + study that wrote it: a resume accepts only its own
        chunk["digest"] = plan.digest
        done.add(index)
        if directory is not None:
            _write_text(_chunk_path(directory, index), _dumps(chunk_json(chunk)))
            # the manifest lists every chunk done: rewritten after each chunk it would cost
            # time quadratic in the number of chunks; a resume also takes the valid chunk
            # files the manifest has not listed yet (_prepare_directory)
            now = time.monotonic()
            if now - written_at >= MANIFEST_INTERVAL_S:
                manifest["done"] = sorted(done)
                _write_text(directory / "manifest.json", _dumps(manifest, indent=2))
                written_at = now
        assembly.add(index, chunk)
        done_samples += tasks[index].stop - tasks[index].start
        if progress is not None:
            progress(done_samples, plan.total)

    _execute(pending, executor, workers, finished)
    result = assembly.result()
    if directory is not None:
        manifest["done"] = sorted(done)
        manifest["complete"] = True
        _write_text(directory / "manifest.json", _dumps(manifest, indent=2))
        try:
            result.write(directory, plots=plots)
            if isinstance(result, StreamedStudyResult):
                _write_streamed_samples(directory, case, plan, result)
        except OSError as exc:  # a plot or the directory (summary and CSV name their file)
            raise OutputError(f"{directory}: cannot write ({exc.strerror or exc})") from None
    return result


def _write_streamed_samples(
    directory: Path, case: Case, plan: _Plan, result: StreamedStudyResult
) -> None:
    """``samples.csv`` and ``samples_columns.json`` of a streaming study, from its chunk files.

    One chunk in memory at a time, in sample order: each is read back (and checked, as a
    resume checks it), turned into the columns an exact study has (:class:`_Assembly` over the
    chunk alone) with the line columns of the whole study (0 where a line is not in the chunk,
    as the exact mode has it), and appended. The files are those the exact mode writes for the
    same study, but for the order of lines whose mean p-p tie to round-off.
    """
    keys = list(result.line_statistics)
    order = [f"{d}|{label}" for d, _, label, _ in result._line_order()]
    names = line_column_names(keys)
    header: list[str] | None = None
    described: dict[str, Any] | None = None

    def rows(fh: Any) -> None:
        nonlocal header, described
        writer = csv.writer(fh, lineterminator="\n")
        for task in plan.tasks:
            path = _chunk_path(directory, task.index)
            chunk = read_json(path, [directory])
            problem = _chunk_problem(chunk, task, plan.digest)
            if problem is not None:  # written by this run a moment ago: someone changed it
                raise OutputError(f"{path}: {problem}; run the study again")
            n = task.stop - task.start
            part = _Assembly(case, dataclasses.replace(plan, total=n))
            part.add(0, {**chunk, "start": 0, "stop": n})
            sub = part.result()
            table = [c for c in sub._column_table() if "direction" not in c[3]]
            table[0] = ("sample", np.arange(task.start, task.stop), "-", {})
            for key in order:
                pp = sub.lines[key][1] if key in sub.lines else np.zeros(n)
                direction, _, label = key.partition("|")
                frequency = result.line_statistics[key][0]
                info = {"direction": direction, "frequency_hz": frequency, "label": label}
                table.append((names[key], pp, "m", info))
            if header is None:
                header = [name for name, _, _, _ in table]
                writer.writerow(header)
                described = {
                    "format": COLUMNS_FORMAT,
                    "units": {name: unit for name, _, unit, _ in table},
                    "columns": {name: info for name, _, _, info in table if info},
                }
            for start in range(0, n, CSV_BLOCK):
                block = slice(start, start + CSV_BLOCK)
                writer.writerows(zip(*(_cells(col[block]) for _, col, _, _ in table), strict=True))

    write_atomic(directory / "samples.csv", rows)
    if described is not None:
        text = json.dumps(described, indent=2, allow_nan=False) + "\n"
        _write_text(directory / COLUMNS_FILE, text)


#: Least time between two rewrites of ``manifest.json`` during a study [s] (and at its end).
MANIFEST_INTERVAL_S = 1.0
#: Chunks submitted ahead per worker of the process pool (the others wait in the parent, so
#: that the pool's queue holds a few chunks' arrays, not the whole study's).
AHEAD_PER_WORKER = 2
#: Chunks in flight on an external executor (Dask): enough to keep a cluster busy.
AHEAD_EXTERNAL = 64


def _execute(
    tasks: list[ChunkTask],
    executor: Executor | None,
    workers: int,
    finished: Callable[[int, dict[str, Any]], None],
) -> None:
    """Evaluate ``tasks`` in this process, in a pool of ``workers`` processes or on
    ``executor``, and hand every chunk to ``finished`` (in this thread) as it ends.

    In this process, the chunks of a batched Monte Carlo run side by side on Numba's number of
    threads, each chunk on one (the kernels release the GIL): one chunk per thread keeps every
    thread busy whatever else the machine runs, where threads inside each chunk's kernel wait
    for the slowest at the end of every chunk. A single chunk uses the kernel's threads.
    One pool serves the whole study: its workers start (and load the kernels,
    :func:`runout.study._pool.init_worker`) while this process computes the shared arrays.
    """
    if not tasks:
        return
    if executor is None and workers <= 1:
        batch = _with_batch(tasks)
        threads = _threads(batch)
        if threads <= 1:
            for task in batch:
                finished(task.index, evaluate_chunk(task))
            return
        serial = [dataclasses.replace(t, parallel=False) for t in batch]
        team = ThreadPoolExecutor(threads, thread_name_prefix="runout-study")
        try:
            _drain(team, iter(serial), len(serial), AHEAD_PER_WORKER * threads, finished)
        finally:  # an interrupt drops the queued chunks and waits for the running ones
            team.shutdown(wait=True, cancel_futures=True)
        return
    own = executor is None
    # each worker's Numba team is its share of the cores; a chunk then uses it (a pool
    # worker evaluates its chunks in its main thread, where the parallel kernel may run)
    threads = worker_threads(workers) if own else 1
    pool: Executor = (
        ProcessPoolExecutor(
            max_workers=workers,
            initializer=_init_worker,
            initargs=(os.getpid(), threads),
            mp_context=_context(),
        )
        if executor is None
        else executor
    )
    tasks = [dataclasses.replace(t, parallel=threads > 1) for t in tasks]
    ok = False
    try:
        if own:  # start every worker now: their start-up overlaps the set-up below
            for _ in range(workers):
                pool.submit(int)
        ahead = AHEAD_PER_WORKER * workers if own else AHEAD_EXTERNAL
        batched = _with_batch(tasks)
        submit = _scattered(pool, batched)
        if submit is not None:  # a Dask cluster: the shared arrays sent to each worker once
            batched = [dataclasses.replace(t, batch=None) for t in batched]
        _drain(pool, iter(batched), len(batched), ahead, finished, submit)
        ok = True
    finally:
        if own:
            # every chunk is in: the idle workers exit on their own (they end with this
            # process in any case); after a failure, cancel and wait for them
            pool.shutdown(wait=not ok, cancel_futures=True)


def _scattered(
    pool: Executor, tasks: list[ChunkTask]
) -> Callable[[ChunkTask], Future[dict[str, Any]]] | None:
    """Submission of chunks whose shared arrays were scattered to every Dask worker once.

    On a Dask executor (``Client.get_executor()``) the :class:`BatchArrays` of a batched
    Monte Carlo go to every worker with ``Client.scatter(broadcast=True)``, and each chunk
    carries only a reference to them; None for any other executor or study (the arrays then
    travel with each chunk, as they must for a process pool, whose workers cannot be named).
    """
    client = getattr(pool, "_client", None)
    if client is None or not tasks or tasks[0].batch is None:
        return None
    try:
        shared = client.scatter(tasks[0].batch, broadcast=True, hash=False)
    except Exception:  # the arrays then travel with each chunk, as they do elsewhere
        return None

    def submit(task: ChunkTask) -> Future[dict[str, Any]]:
        future: Future[dict[str, Any]] = pool.submit(_evaluate_with, task, shared)
        return future

    return submit


def _evaluate_with(task: ChunkTask, batch: Any) -> dict[str, Any]:
    """:func:`evaluate_chunk` of ``task`` with the shared arrays a Dask worker holds."""
    return evaluate_chunk(dataclasses.replace(task, batch=batch))


def _drain(
    pool: Executor,
    queue: Iterator[ChunkTask],
    count: int,
    ahead: int,
    finished: Callable[[int, dict[str, Any]], None],
    submit: Callable[[ChunkTask], Future[dict[str, Any]]] | None = None,
) -> None:
    """Run the ``count`` tasks of ``queue`` on ``pool`` (through ``submit`` when given), at
    most ``ahead`` at a time."""
    running: dict[Future[dict[str, Any]], int] = {}
    for _ in range(count + 1):  # one submission round per finished chunk, at most
        for task in itertools.islice(queue, max(0, ahead - len(running))):
            future = pool.submit(evaluate_chunk, task) if submit is None else submit(task)
            running[future] = task.index
        if not running:
            break
        done, _pending = wait(running, return_when=FIRST_COMPLETED)
        for fut in sorted(done, key=running.__getitem__):
            index = running.pop(fut)
            try:
                chunk = fut.result()
            except Exception as exc:  # a dead worker, an executor's failure
                # evaluate_chunk records every sample's failure itself: what lands here lost
                # the whole chunk (a worker killed, out of memory, a scheduler gone)
                raise StudyError(
                    f"chunk {index}: the worker evaluating it failed ({error_text(exc)}); "
                    "the chunks already written to --out are kept (rerun with --resume)"
                ) from None
            finished(index, chunk)


def _load_chunks(
    directory: Path,
    indices: Iterable[int],
    plan: _Plan,
    sink: Callable[[int, dict[str, Any]], None],
) -> tuple[set[int], list[str]]:
    """Hand every recorded chunk that passes :func:`_chunk_problem` to ``sink``, one at a
    time (none is kept here); return their indices and ``"name: problem"`` of the others."""
    done: set[int] = set()
    bad: list[str] = []
    for index in indices:
        path = _chunk_path(directory, index)
        try:
            # only a regular file of the directory, within the bounds of runout.base.reading
            # (a chunk nested 10^5 deep or linked to /dev/zero is a damaged chunk, recomputed)
            chunk = read_json(path, [directory])
        except InputFileError as exc:
            problem: str | None = "missing" if exc.message == MISSING else exc.message
        else:
            problem = _chunk_problem(chunk, plan.tasks[index], plan.digest)
        if problem is None:
            done.add(index)
            sink(index, chunk)
        else:
            bad.append(f"{path.name}: {problem}")
    return done, bad


def _recorded(directory: Path, manifest: dict[str, Any], plan: _Plan) -> list[int]:
    """The chunks a resume takes: those ``manifest`` lists as done and every other chunk
    file of the plan's names in ``directory/chunks`` (the manifest is rewritten at most once
    a second, :data:`MANIFEST_INTERVAL_S`: the chunks finished since are on disk, each still
    checked by :func:`_load_chunks`)."""
    found = set(manifest["done"])
    chunks_dir = directory / "chunks"
    if chunks_dir.is_dir():
        for path in chunks_dir.glob("chunk_*.json"):
            name = _CHUNK_NAME.fullmatch(path.name)
            index = -1 if name is None else int(name[1])
            if 0 <= index < len(plan.tasks) and path.name == _chunk_path(directory, index).name:
                found.add(index)
    return sorted(found)


_CHUNK_NAME = re.compile(r"chunk_(\d{5,})\.json")


#: Files a study writes at the top of its output directory (replaced by a fresh run).
_STUDY_FILES = re.compile(
    r"^(manifest\.json|summary\.json|samples\.csv|samples_columns\.json|stiffness\.csv"
    r"|histograms\.png|sweep_.+\.png)$"
)


def _prepare_directory(
    directory: Path,
    manifest: dict[str, Any],
    plan: _Plan,
    resume: bool,
    force: bool,
    notify: Callable[[str], None],
    sink: Callable[[int, dict[str, Any]], None],
) -> set[int]:
    """Check ``directory`` (locked by us); hand the chunks already done (resume) to ``sink``
    and return their indices.

    Without ``resume`` (or when ``force`` overrides a corrupted manifest or a different
    study) the chunk files and study outputs of an earlier run are deleted, so that nothing
    of it can mix with this one; other files are left alone.
    """
    _remove_leftovers(directory)
    path = directory / "manifest.json"
    old: dict[str, Any] | None = None
    if path.exists():
        try:
            old = _read_manifest(path)
        except StudyError as exc:
            if not force:
                raise
            notify(f"{exc}".split("; pass --force")[0] + ": --force, started afresh")
    elif resume and not force:
        raise StudyError(
            f"--resume: {path}: no such file (no run to continue); run without --resume"
        )
    done: set[int] = set()
    fresh = not resume or old is None
    if not fresh:
        assert old is not None
        _refuse_earlier_sampling(old, manifest, path, force, notify)
        differs = next((key for key in _RESUME_KEYS if old[key] != manifest[key]), None)
        if differs is not None and not force:
            raise StudyError(
                f"--resume: {directory} holds a run of a different case or study ({differs} "
                "differs); run without --resume to start afresh"
            )
        if differs is not None:
            notify(
                f"{path}: a different case or study ({differs} differs): --force, started afresh"
            )
            fresh = True
        else:
            chunks_dir = directory / "chunks"
            if chunks_dir.is_dir() and not chunks_dir.is_symlink():
                # a link where a chunk of ours belongs: never read through it, and its
                # recomputed chunk could only be written through it or over the user's link
                link = next((p for p in sorted(chunks_dir.iterdir()) if p.is_symlink()), None)
                if link is not None:
                    raise OutputError(
                        f"{link}: a symbolic link; runout does not read or write through "
                        "links (remove it, or run without --resume into another directory)"
                    )
            done, bad = _load_chunks(directory, _recorded(directory, old, plan), plan, sink)
            if bad:
                n = len(bad)
                shown = "; ".join(bad[:3]) + ("; ..." if n > 3 else "")
                notify(
                    f"{directory / 'chunks'}: recomputing {n} chunk{'s' if n > 1 else ''} that "
                    f"{'were' if n > 1 else 'was'} unreadable or not written by this study "
                    f"({shown})"
                )
    try:
        ours = [p for p in directory.iterdir() if _STUDY_FILES.match(p.name) or p.name == "chunks"]
        link = next((p for p in ours if p.is_symlink()), None)
        if link is not None:  # the user's link, never written or deleted through
            raise OutputError(
                f"{link}: a symbolic link; runout does not write through links (remove it or "
                "choose another directory)"
            )
        if fresh:
            for p in ours:
                if p.is_file():
                    p.unlink()
            if (directory / "chunks").is_dir():
                for p in (directory / "chunks").glob("chunk_*.json"):
                    p.unlink()
        manifest["done"] = sorted(done)
        _write_text(path, _dumps(manifest, indent=2))
        (directory / "chunks").mkdir(exist_ok=True)
    except OSError as exc:
        raise OutputError(f"{directory}: cannot write ({exc.strerror or exc})") from None
    return done


class _Assembly:
    """The columns of a study's result, filled chunk by chunk in any order.

    Monte Carlo values, runout figures and line p-p are float64 arrays of the whole study
    (8 bytes per sample and column, no Python object per sample); a chunk is copied into them
    as it arrives and can then be dropped. Lines are ordered as if the chunks had arrived in
    order (by the first chunk, and place in it, where each appears), so that the result does
    not depend on which worker finished first.
    """

    def __init__(self, case: Case, plan: _Plan) -> None:
        self.case, self.plan = case, plan
        total = plan.total
        self.model: list[str] = [""] * total
        self.values: dict[str, Any] = {}
        for q in plan.quantities:
            if plan.study.kind == "montecarlo":
                shape = (total, q.size) if q.size > 1 else (total,)
                self.values[q.key] = np.zeros(shape)
            else:
                self.values[q.key] = [None] * total
        self.runout = {k: np.full(total, np.nan) for k in RUNOUT_KEYS}
        self.lines: dict[str, tuple[float, NDArray[np.float64]]] = {}
        self.first: dict[str, tuple[int, int]] = {}
        self.errors: dict[int, str] = {}
        self.stiffness: dict[int, dict[str, Any]] = {}

    def add(self, index: int, chunk: dict[str, Any]) -> None:
        """Copy ``chunk`` (arrays of :func:`evaluate_chunk` or lists of its file) in."""
        s, e = chunk["start"], chunk["stop"]
        self.model[s:e] = chunk["model"]
        for key, column in self.values.items():
            given = chunk["values"][key]
            if isinstance(column, np.ndarray):
                column[s:e] = np.asarray(given, dtype=np.float64).reshape(column[s:e].shape)
            else:
                column[s:e] = list(given)
        for k in RUNOUT_KEYS:
            # None in a chunk file (a failed sample, a figure the model lacks) is NaN
            self.runout[k][s:e] = np.asarray(chunk["runout"][k], dtype=np.float64)
        for place, (key, entry) in enumerate(chunk["lines"].items()):
            here = (index, place)
            if key not in self.lines or here < self.first[key]:
                # the line's frequency is that of its first chunk, whichever chunk finishes
                # first: the files are the same for any worker count and scheduler
                column = self.lines[key][1] if key in self.lines else np.zeros(self.plan.total)
                self.lines[key] = (entry["frequency_hz"], column)
                self.first[key] = here
            self.lines[key][1][s:e] = entry["pp_m"]
        self.errors.update({int(k): v for k, v in chunk["errors"].items()})
        self.stiffness.update({int(k): v for k, v in chunk.get("stiffness", {}).items()})

    def result(self) -> StudyResult:
        """The :class:`StudyResult` of every chunk added."""
        study = self.plan.study
        lines = {key: self.lines[key] for key in sorted(self.lines, key=self.first.__getitem__)}
        return StudyResult(
            kind=study.kind,
            title=self.case.title,
            seed=study.seed,
            quantities=self.plan.quantities,
            model=self.model,
            values=self.values,
            runout=self.runout,
            lines=lines,
            errors=dict(sorted(self.errors.items())),
            bins=study.bins,
            limit=study_limit(self.case),
            stiffness=dict(sorted(self.stiffness.items())),
            limit_class=getattr(self.case.analysis, "limit_class", None),
            bearing_source=self.case.bearing_source(),
        )


class _Streaming:
    """Streaming statistics of a Monte Carlo, reduced chunk by chunk in any order.

    Every runout figure and line is a :class:`StreamStatistics` (exact count, min, max, sum
    and sum of squares; a quantile sketch): memory does not grow with the number of samples,
    and the result is the same, bit for bit, for any chunking and order of arrival. A line
    counts as 0 in the samples of the chunks where it does not appear (as in :class:`_Assembly`):
    its zeros are added at the end, from the number of samples that ran and those its chunks
    covered. A line's frequency is that of its first chunk in sample order.
    """

    def __init__(self, case: Case, plan: _Plan, notes: tuple[str, ...]) -> None:
        self.case, self.plan, self.notes = case, plan, notes
        self.runout = {k: StreamStatistics() for k in RUNOUT_KEYS}
        self.lines: dict[str, tuple[float, StreamStatistics]] = {}
        self.covered: dict[str, int] = {}
        self.first: dict[str, tuple[int, int]] = {}
        self.ran = 0
        self.models: set[str] = set()
        self.failed = 0
        self.errors: dict[int, str] = {}  # the first ERRORS_SHOWN failed samples only
        self.passed = 0
        self.limit = study_limit(case)

    def add(self, index: int, chunk: dict[str, Any]) -> None:
        """Reduce ``chunk`` (arrays of :func:`evaluate_chunk` or lists of its file)."""
        self.models.update(chunk["model"])
        figures = {k: np.asarray(chunk["runout"][k], dtype=np.float64) for k in RUNOUT_KEYS}
        for k in RUNOUT_KEYS:
            self.runout[k].add(figures[k])
        ok = np.isfinite(figures["radial_pp_m"])
        ran = int(np.count_nonzero(ok))
        self.ran += ran
        if self.limit is not None:
            value = figures[f"{self.limit[0]}_m"]
            self.passed += int(np.count_nonzero(value[np.isfinite(value)] <= self.limit[1]))
        for place, (key, entry) in enumerate(chunk["lines"].items()):
            here = (index, place)
            if key not in self.lines:
                self.lines[key] = (entry["frequency_hz"], StreamStatistics())
                self.covered[key] = 0
                self.first[key] = here
            elif here < self.first[key]:  # the frequency of the line's first chunk
                self.lines[key] = (entry["frequency_hz"], self.lines[key][1])
                self.first[key] = here
            self.lines[key][1].add(np.asarray(entry["pp_m"], dtype=np.float64)[ok])
            self.covered[key] += ran
        errors = {int(k): v for k, v in chunk["errors"].items()}
        self.failed += len(errors)
        self.errors = dict(sorted({**self.errors, **errors}.items())[:ERRORS_SHOWN])

    def result(self) -> StreamedStudyResult:
        """The :class:`StreamedStudyResult` of every chunk added."""
        study = self.plan.study
        for key, (_f, stats) in self.lines.items():
            stats.add_zeros(self.ran - self.covered[key])
            self.covered[key] = self.ran
        lines = {key: self.lines[key] for key in sorted(self.lines, key=self.first.__getitem__)}
        return StreamedStudyResult(
            kind=study.kind,
            title=self.case.title,
            seed=study.seed,
            quantities=self.plan.quantities,
            model=[],
            values={},
            runout={},
            lines={},
            errors=self.errors,
            bins=study.bins,
            limit=self.limit,
            limit_class=getattr(self.case.analysis, "limit_class", None),
            bearing_source=self.case.bearing_source(),
            sample_count=self.plan.total,
            failed_count=self.failed,
            models_run=tuple(sorted(self.models)),
            runout_statistics=self.runout,
            line_statistics=lines,
            passed=self.passed,
            notes=self.notes,
        )


def _refuse_earlier_sampling(
    old: dict[str, Any],
    manifest: dict[str, Any],
    path: Path,
    force: bool,
    notify: Callable[[str], None] | None = None,
) -> None:
    """Refuse to resume (or read) a Monte Carlo drawn by an earlier version's sampling.

    Its samples are other bearings than this version draws for the same seed: mixing its
    chunks with new ones would make a lot that neither version draws. ``force`` starts afresh
    (said through ``notify``).
    """
    earlier = old.get("sampling", 1)
    if old.get("kind") != "montecarlo" or earlier == manifest.get("sampling", SAMPLING):
        return
    message = (
        f"{path}: a Monte Carlo drawn by an earlier version of runout (sampling {earlier}; this "
        f"version draws by sampling {SAMPLING}, which gives other samples for the same seed)"
    )
    if notify is None:
        raise StudyError(f"{message}; run the study again to read it with this version")
    if not force:
        raise StudyError(f"--resume: {message}; run without --resume to start afresh")
    notify(f"{message}: --force, started afresh")


def study_limit(case: Case) -> tuple[str, float] | None:
    """``(limit_on, limit [m])`` of the case's spec limit on a runout figure, or None.

    Parameters
    ----------
    case : Case
        A validated case.

    Returns
    -------
    tuple of (str, float) or None
        ``[analysis] limit_on`` and ``limit`` in SI ([m] for a runout p-p, [m/s] for an
        ISO 15242 band); None when the case sets no limit.
    """
    analysis = case.analysis
    limit = getattr(analysis, "limit", None)
    if limit is None:
        return None
    return str(analysis.limit_on), float(limit)


def load_study(directory: Path | str, case: Case) -> StudyResult:
    """Read a finished study from its output directory.

    Parameters
    ----------
    directory : Path or str
        The study's output directory (``manifest.json`` and ``chunks/``).
    case : Case
        The case that ran the study (its digest must match the manifest's).

    Returns
    -------
    StudyResult
        The study assembled from its chunks, as :func:`run_study` returned it.

    Raises
    ------
    StudyError
        Naming the file: no or a corrupted manifest, a manifest of another case or study, a
        missing chunk (a partial run) or a chunk that is damaged or not this study's.
    """
    d = Path(directory)
    manifest = _read_manifest(d / "manifest.json")
    plan = _plan(case, manifest["chunk_size"])
    _refuse_earlier_sampling(manifest, plan.manifest(), d / "manifest.json", False)
    differs = next((k for k in _RESUME_KEYS if manifest[k] != plan.manifest()[k]), None)
    if differs is not None:
        raise StudyError(f"{d / 'manifest.json'}: a run of a different case or study ({differs})")
    streaming = estimates.study_statistics(case) == "streaming"
    assembly = (
        _Streaming(case, plan, _streaming_notes(case, 1)) if streaming else _Assembly(case, plan)
    )
    _done, bad = _load_chunks(d, range(len(plan.tasks)), plan, assembly.add)
    if bad:
        raise StudyError(f"{d / 'chunks'}: not a complete study of this case ({bad[0]})")
    return assembly.result()
