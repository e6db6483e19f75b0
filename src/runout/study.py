r"""Studies at scale: Monte Carlo over drawn case quantities and sweeps over listed ones.

A study takes a validated :class:`runout.case.Case` with a ``[study]`` table and evaluates many
variants of it: *samples* (Monte Carlo bearings) or *points* (sweep values × models). Each
variant is the case with some quantities replaced, validated like a case file and run by the
model named in ``[analysis]`` (or ``[study] models``); from each run we keep the runout figures
and every labelled line (:class:`runout.results.Component`, p-p [m]).

Randomness
----------
Sample ``i`` draws its values from ``numpy.random.default_rng(SeedSequence(seed,
spawn_key=(i,)))``: the i-th child of the root seed. The numbers of a sample therefore depend
only on ``(seed, i)``, never on the chunking, the number of workers or the order in which
chunks finish; runs are reproducible bit for bit.

Execution
---------
Samples are grouped in chunks of ``chunk_size``; a chunk is one task. Tasks run in the calling
process, in a local process pool (``workers``), or on any :class:`concurrent.futures.Executor`
(a Dask ``Client.get_executor()``, see :func:`dask_executor`). A ball-size Monte Carlo of the
2-D model is batched: the parent computes what every bearing shares once
(:class:`runout._study_pool.BatchArrays`) and ships it with every chunk, and a chunk is one
call of the batched Numba kernel :func:`runout._study_kernels.solve_batch` (threads over
bearings in the calling process) plus a vectorised line fit and RRO/NRRO split
(:func:`runout._study_pool.evaluate_rows`). The pool is one for the whole study: its workers
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
Every runout figure and line is summarised by its mean, sample standard deviation (ddof = 1),
2σ, 5/50/95 % percentiles (linear interpolation), min, max and a histogram. A line missing from
a sample's output (below the model's reporting floor) counts as 0 in that sample.
"""

from __future__ import annotations

import contextlib
import copy
import csv
import dataclasses
import functools
import hashlib
import itertools
import json
import logging
import math
import os
import re
import secrets
import sys
import threading
from collections.abc import Callable, Iterable, Iterator, Sequence
from concurrent.futures import (
    FIRST_COMPLETED,
    Executor,
    Future,
    ProcessPoolExecutor,
    ThreadPoolExecutor,
    wait,
)
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, TextIO

import numpy as np
from numpy.typing import NDArray

from runout import limits
from runout._study_pool import (
    BatchArrays,
    die_with_parent,
    evaluate_rows,
    init_worker,
    line_projector,
    spawn_context,
)
from runout.case import (
    STUDY_SHORTHANDS,
    Case,
    CaseSpec,
    StudySpec,
    VarySpec,
    parse_case,
    parse_vary_key,
)
from runout.decompose import study_key
from runout.errors import (
    CaseError,
    ContactLossError,
    ConvergenceError,
    NumericalError,
    RunoutError,
)
from runout.units import to_si

try:
    import fcntl
except ImportError:  # pragma: no cover - Windows: O_EXCL lock files instead of flock
    fcntl = None  # type: ignore[assignment]

__all__ = [
    "RUNOUT_KEYS",
    "OutputError",
    "Quantity",
    "StudyError",
    "StudyResult",
    "dask_executor",
    "die_with_parent",
    "error_text",
    "load_study",
    "output_directory",
    "output_lock",
    "plan_quantities",
    "refuse_foreign",
    "run_study",
    "sample_rng",
    "statistics",
    "write_atomic",
]

#: Runout figures kept per sample, in this order (the keys of :class:`runout.results.Runout`).
RUNOUT_KEYS = ("radial_pp_m", "axial_pp_m", "rro_pp_m", "nrro_pp_m")
FORMAT = "runout-study/1"
_DIAMETER_KEY = "elements.diameter_errors"


class StudyError(RunoutError):
    """A study that cannot run as asked (output directory, resume mismatch, bad quantity)."""


def sample_rng(seed: int, index: int) -> np.random.Generator:
    """Generator of sample ``index``: the ``index``-th child of ``SeedSequence(seed)``.

    Identical to ``SeedSequence(seed).spawn(index + 1)[index]``, without spawning the others.
    """
    return np.random.default_rng(np.random.SeedSequence(seed, spawn_key=(index,)))


# --------------------------------------------------------------------------------------------
# quantities
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Quantity:
    """One varied case quantity, every parameter in SI.

    Attributes
    ----------
    key : str
        The ``[study.vary]`` key (``"operation.axial_load"``, ``"element_diameter_sigma"``).
    path : tuple
        ``(table, index or None, name)`` of the case key it replaces.
    size : int
        1 for a scalar key, Z for a per-element array (every element drawn independently).
    distribution : str
        ``"normal"``, ``"uniform"``, ``"sample"`` (Monte Carlo) or ``"sweep"``.
    mean : ndarray, shape (size,)
        Normal: mean per entry [SI].
    spread : tuple of float
        Normal: (std,); uniform: (low, high) [SI].
    values : tuple
        ``"sample"``: the measured values; ``"sweep"``: the swept values (SI floats or the
        literal strings of a text key).
    """

    key: str
    path: tuple[str, int | None, str]
    size: int
    distribution: str
    mean: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))
    spread: tuple[float, ...] = ()
    values: tuple[Any, ...] = ()

    def draw(self, rng: np.random.Generator) -> NDArray[np.float64]:
        """Draw the ``size`` values of one sample [SI]."""
        if self.distribution == "normal":
            return self.mean + self.spread[0] * rng.standard_normal(self.size)
        if self.distribution == "uniform":
            return rng.uniform(self.spread[0], self.spread[1], self.size)
        if self.distribution == "sample":
            pool = np.asarray(self.values, dtype=np.float64)
            return pool[rng.integers(0, pool.size, self.size)]
        raise StudyError(f"study.vary.{self.key}: a sweep quantity is not drawn")


def _set_at(data: dict[str, Any], path: tuple[str, int | None, str], value: Any) -> None:
    table, index, name = path
    if index is None:
        data.setdefault(table, {})[name] = value
    else:
        data[table][index - 1][name] = value


def _get_at(spec: CaseSpec, path: tuple[str, int | None, str]) -> Any:
    table, index, name = path
    node = getattr(spec, table)
    if index is not None:
        node = node[index - 1]
    return None if node is None else getattr(node, name)


def _convert(
    case: Case, data: dict[str, Any], path: tuple[str, int | None, str], raw: Any, where: str
) -> Any:
    """SI value of ``raw`` placed at ``path``: validated as the case key itself would be."""
    trial = copy.deepcopy(data)
    size = case.bearing.elements if path == ("elements", None, "diameter_errors") else 0
    size = case.bearing.elements if path == ("elements", None, "pitch_errors") else size
    _set_at(trial, path, [raw] * size if size else raw)
    try:
        spec = CaseSpec.model_validate(trial)
    except Exception as exc:  # pydantic ValidationError: report it on the study key
        from pydantic import ValidationError

        from runout.case import first_validation_error

        if isinstance(exc, ValidationError):
            _, message = first_validation_error(exc)
            raise CaseError(case.path, where, message) from None
        raise
    value = _get_at(spec, path)
    return value[0] if size else value


def plan_quantities(case: Case, data: dict[str, Any] | None = None) -> list[Quantity]:
    """Resolve the ``[study.vary]`` table of ``case`` into :class:`Quantity` objects (SI).

    Parameters
    ----------
    case : Case
        A case with a ``[study]`` table.
    data : dict, optional
        The case document (default: rebuilt from the validated case).

    Raises
    ------
    CaseError
        Naming ``study.vary.<key>`` when a value is not valid where it goes.
    """
    study = _study_of(case)
    data = _case_data(case) if data is None else data
    z = case.bearing.elements
    out: list[Quantity] = []
    for key in sorted(study.vary):
        entry = study.vary[key]
        where = f"study.vary.{key}"
        if key in STUDY_SHORTHANDS:
            assert not isinstance(entry, VarySpec)
            sigma = to_si(entry, "length")
            base = np.asarray(case.imperfections.diameter_errors, dtype=np.float64)
            out.append(
                Quantity(key, ("elements", None, "diameter_errors"), z, "normal", base, (sigma,))
            )
            continue
        assert isinstance(entry, VarySpec)
        path = parse_vary_key(key)
        table, index, name = path
        if index is not None and index > len(data.get(table, [])):
            raise CaseError(
                case.path, where, f"the case has {len(data.get(table, []))} [[{table}]] entries"
            )
        size = (
            z
            if (table, name) in (("elements", "diameter_errors"), ("elements", "pitch_errors"))
            else 1
        )

        def conv(
            raw: Any, what: str, path: tuple[str, int | None, str] = path, where: str = where
        ) -> Any:
            return _convert(case, data, path, raw, f"{where}.{what}")

        if entry.distribution is None:  # sweep
            values = _sweep_values(entry, conv, where, case.path)
            out.append(Quantity(key, path, size, "sweep", values=tuple(values)))
            continue
        if entry.distribution == "normal":
            std = _numeric(conv(entry.std, "std"), case.path, f"{where}.std")
            if std < 0.0:
                raise CaseError(case.path, f"{where}.std", "must be >= 0")
            if entry.mean is not None:
                mean = np.full(size, _numeric(conv(entry.mean, "mean"), case.path, where))
            else:
                current = _get_at(case.spec, path)
                if current is None:
                    mean = np.zeros(size)
                elif size > 1:
                    mean = np.asarray(current, dtype=np.float64)
                else:
                    mean = np.full(size, _numeric(current, case.path, where))
            out.append(Quantity(key, path, size, "normal", mean, (std,)))
        elif entry.distribution == "uniform":
            low = _numeric(conv(entry.low, "low"), case.path, f"{where}.low")
            high = _numeric(conv(entry.high, "high"), case.path, f"{where}.high")
            if high < low:
                raise CaseError(case.path, f"{where}.high", "must be >= low")
            out.append(Quantity(key, path, size, "uniform", spread=(low, high)))
        else:
            assert entry.values is not None
            values = [
                _numeric(conv(v, f"values[{i + 1}]"), case.path, f"{where}.values[{i + 1}]")
                for i, v in enumerate(entry.values)
            ]
            out.append(Quantity(key, path, size, "sample", values=tuple(values)))
    return out


def _numeric(value: Any, file: str, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise CaseError(
            file,
            where,
            f'is not a number ({value!r}); draw it from distribution = "sample" or sweep it',
        )
    if isinstance(value, int):
        raise CaseError(
            file, where, 'is an integer key: use distribution = "sample" with integer values'
        )
    return float(value)


def _sweep_values(
    entry: VarySpec, conv: Callable[[Any, str], Any], where: str, file: str
) -> list[Any]:
    if entry.values is not None:
        return [conv(v, f"values[{i + 1}]") for i, v in enumerate(entry.values)]
    start = _range_end(conv(entry.start, "start"), file, f"{where}.start")
    stop = _range_end(conv(entry.stop, "stop"), file, f"{where}.stop")
    integer = isinstance(start, int) and isinstance(stop, int)
    if entry.num is not None:
        grid: list[float | int] = [float(v) for v in np.linspace(start, stop, entry.num)]
        if integer:
            if any(v != round(v) for v in grid):
                raise CaseError(file, f"{where}.num", "an integer key needs integer steps")
            grid = [round(v) for v in grid]
    else:
        step = _range_end(
            to_si(entry.step, "dimensionless")
            if not isinstance(entry.step, str)
            else conv(entry.step, "step"),
            file,
            f"{where}.step",
        )
        if step == 0 or (stop - start) * step < 0:
            raise CaseError(file, f"{where}.step", "must be nonzero and point from start to stop")
        count = math.floor((stop - start) / step + 1e-9) + 1
        grid = [start + step * k for k in range(count)]
        if integer and isinstance(step, int | float) and float(step).is_integer():
            grid = [round(v) for v in grid]
    return [conv(v, f"values[{i + 1}]") for i, v in enumerate(grid)]


def _range_end(value: Any, file: str, where: str) -> float | int:
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise CaseError(file, where, f"a range needs numbers, got {value!r}; use values = [...]")
    return value


def _study_of(case: Case) -> StudySpec:
    if case.study is None:
        raise CaseError(case.path, "study", "the case has no [study] table (see docs/studies.md)")
    return case.study


def _case_data(case: Case) -> dict[str, Any]:
    """The case document in SI numbers, without ``[study]`` (re-validates to the same case)."""
    return case.spec.model_dump(mode="python", exclude_none=True, exclude={"study"})


def _models(case: Case) -> list[str]:
    study = _study_of(case)
    return list(study.models) if study.models else [case.analysis.model]


# --------------------------------------------------------------------------------------------
# labels of lines
# --------------------------------------------------------------------------------------------
_ELEMENT_NO = re.compile(r"\b(ball|roller) \d+ ")


@functools.lru_cache(maxsize=4096)
def line_label(label: str) -> str:
    """Label of a line with element numbers removed and repeated parts merged.

    ``"ball 1 size error: f_c; ball 2 size error: f_c"`` → ``"ball size error: f_c"``: in a
    study every element usually has an error, and the line's identity is its formula.
    """
    parts: list[str] = []
    for part in label.split("; "):
        text = _ELEMENT_NO.sub(r"\1 ", part)
        if text not in parts:
            parts.append(text)
    return "; ".join(parts)


# --------------------------------------------------------------------------------------------
# chunks: evaluation
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ChunkTask:
    """Everything one worker needs to evaluate samples ``start`` ... ``stop - 1`` (picklable)."""

    index: int
    start: int
    stop: int
    data: dict[str, Any]
    path: str
    base_dir: str
    quantities: tuple[Quantity, ...]
    kind: str
    seed: int
    models: tuple[str, ...]
    parallel: bool = False
    #: The arrays of a batched ball-size Monte Carlo (computed once by the parent), or None.
    batch: BatchArrays | None = None


def _point(task: ChunkTask, i: int) -> tuple[str, dict[str, Any]]:
    """Model and values of sample or point ``i``."""
    if task.kind == "montecarlo":
        rng = sample_rng(task.seed, i)
        drawn: dict[str, Any] = {}
        for q in task.quantities:
            v = q.draw(rng)
            drawn[q.key] = [float(x) for x in v] if q.size > 1 else float(v[0])
        return task.models[0], drawn
    shape = [len(task.models), *(len(q.values) for q in task.quantities)]
    idx = np.unravel_index(i, shape)
    values = {q.key: q.values[int(j)] for q, j in zip(task.quantities, idx[1:], strict=True)}
    return task.models[int(idx[0])], values


def _variant(task: ChunkTask, model: str, values: dict[str, Any]) -> Case:
    data = copy.deepcopy(task.data)
    data.setdefault("analysis", {})["model"] = model
    for q in task.quantities:
        _set_at(data, q.path, values[q.key])
    return parse_case(data, task.path, Path(task.base_dir))


def _empty_chunk(task: ChunkTask) -> dict[str, Any]:
    return {
        "chunk": task.index,
        "start": task.start,
        "stop": task.stop,
        "model": [],
        "values": {q.key: [] for q in task.quantities},
        "runout": {k: [] for k in RUNOUT_KEYS},
        "lines": {},
        "errors": {},
        "stiffness": {},
    }


def _stiffness_entry(extras: dict[str, Any]) -> dict[str, Any] | None:
    """What a study keeps of an equilibrium result's stiffness, or None for other models.

    ``radial_stiffness`` (the run JSON's object: kxx, kxy, kyx, kyy [N/m], speed_rpm) and
    ``axial_stiffness_n_per_m``, the axial diagonal K_aa of the 5×5 ``stiffness_matrix``.
    """
    radial = extras.get("radial_stiffness")
    matrix = extras.get("stiffness_matrix")
    if not isinstance(radial, dict) or not isinstance(matrix, dict):
        return None
    return {
        "radial_stiffness": {k: float(v) for k, v in radial.items()},
        "axial_stiffness_n_per_m": float(matrix["matrix"][0][0]),
    }


def _add_lines(
    chunk: dict[str, Any], row: int, comps: Iterable[tuple[str, float, str, float]]
) -> None:
    lines = chunk["lines"]
    for direction, freq, label, pp in comps:
        key = f"{direction}|{line_label(label)}"
        entry = lines.get(key)
        if entry is None:
            entry = {"frequency_hz": float(freq), "pp_m": [0.0] * (chunk["stop"] - chunk["start"])}
            lines[key] = entry
        # two lines of one sample that differ only by element numbers: keep the larger
        entry["pp_m"][row] = max(entry["pp_m"][row], float(pp))


#: Longest error message kept per failed sample (a model can raise with a whole array in it).
ERROR_CHARS = 300
#: Failed samples listed (with their errors) in summary.json and the --json output.
ERRORS_SHOWN = 20


def error_text(exc: BaseException) -> str:
    """``"Type: message"`` of a failed sample, on one line and at most ERROR_CHARS long."""
    text = " ".join(f"{type(exc).__name__}: {exc}".split())
    return text if len(text) <= ERROR_CHARS else text[: ERROR_CHARS - 3] + "..."


def evaluate_chunk(task: ChunkTask) -> dict[str, Any]:
    """Evaluate one chunk: a column-wise dict (JSON-ready) of values, runout and lines.

    A sample (or point) whose variant or model raises any :class:`Exception` is recorded in
    ``chunk["errors"]`` (sample index -> ``"Type: message"``) with ``None`` runout and no lines,
    and the chunk goes on: one bad point must not lose the others. ``KeyboardInterrupt`` and
    ``SystemExit`` are not exceptions of the samples and still stop the study.
    """
    chunk = _empty_chunk(task)
    points = [_point(task, i) for i in range(task.start, task.stop)]
    for model, values in points:
        chunk["model"].append(model)
        for key, v in values.items():
            chunk["values"][key].append(v)
    if _batched(task):
        # the batch fills only runout, lines and errors: it shares the drawn values
        batch = {
            **chunk,
            "runout": {k: [] for k in RUNOUT_KEYS},
            "lines": {},
            "errors": {},
            "stiffness": {},
        }
        try:
            _evaluate_batched(task, points, batch)
        except Exception:  # the per-bearing path below records each bearing's own failure
            pass
        else:
            return batch
    from runout.models import run_model

    for row, (model, values) in enumerate(points):
        try:
            result = run_model(_variant(task, model, values))
            figures = result.runout.to_json()
            runout = [float(figures[k]) for k in RUNOUT_KEYS]
            comps = [
                (c.direction, c.frequency_hz, study_key(c.sources) or c.label, c.pp_m)
                for c in result.components
            ]
            stiffness = _stiffness_entry(result.extras)
        except Exception as exc:  # recorded with its sample: the study goes on
            chunk["errors"][str(task.start + row)] = error_text(exc)
            for k in RUNOUT_KEYS:
                chunk["runout"][k].append(None)
            continue
        for k, v in zip(RUNOUT_KEYS, runout, strict=True):
            chunk["runout"][k].append(v)
        _add_lines(chunk, row, comps)
        if stiffness is not None:
            chunk["stiffness"][str(task.start + row)] = stiffness
    return chunk


# ---------------------------------------------------------------- batched 2-D path
def _batched(task: ChunkTask) -> bool:
    """Ball-size Monte Carlo of the unloaded 2-D model: every bearing shares the ball angles.

    The batched kernel solves Kim's eq. 16-17 with no external force; a case with a radial
    load (an extension of the 2-D model) goes through the model's own ``run`` instead.
    """
    from runout.units import UnitError, to_si

    try:
        loaded = to_si(task.data.get("operation", {}).get("radial_load", 0.0), "force") != 0.0
    except UnitError:
        loaded = True  # let the model's own validation report it
    return (
        task.kind == "montecarlo"
        and task.models == ("quasi_static_2d",)
        and not loaded
        and all(q.path == ("elements", None, "diameter_errors") for q in task.quantities)
    )


def _batch_base(task: ChunkTask) -> BatchArrays:
    """The arrays every bearing of ``task``'s ball-size Monte Carlo shares (cached per process).

    Computed by the parent once per study and shipped with every chunk (:func:`_run`), so that
    workers validate no case and set up no model; a chunk without them computes them here.
    """
    if task.batch is not None:
        return task.batch
    key = json.dumps([task.path, task.base_dir, task.data], sort_keys=True, default=str)
    found = _BASES.get(key)
    if found is not None:
        return found
    from runout.decompose import resolved_lines
    from runout.models import quasi_static_2d as qs2
    from runout.models._quasi_static import decomposition_kinematic, predicted_lines, time_grid

    data = copy.deepcopy(task.data)
    data.setdefault("analysis", {})["model"] = "quasi_static_2d"
    case = parse_case(data, task.path, Path(task.base_dir))
    from runout.conventions import enforce

    enforce(case, "quasi_static_2d")  # the batch shares the model's refusals
    z = case.bearing.elements
    base = Case(
        path=case.path,
        title=case.title,
        bearing=case.bearing,
        operation=case.operation,
        imperfections=case.imperfections.with_diameter_errors(np.zeros(z)),
        analysis=case.analysis,
        spec=case.spec,
    )
    st = qs2.setup(base)
    an, op = case.analysis, case.operation
    t = time_grid(op.speed, an.revolutions, an.samples)
    c, theta = qs2.approaches(base, st, t)
    # lines of a representative bearing (every ball with a size error), resolved as in run()
    probe = case.imperfections.with_diameter_errors(np.full(z, 1e-9))
    candidates = predicted_lines(probe, st.kinematics, axial=False, second_order_pairs=True)
    lines, _ = resolved_lines(candidates, "radial", t, float(op.speed))
    freqs = [f for f, _ in lines]
    labels = [study_key(sources) for _, sources in lines]
    f = np.array(freqs, dtype=np.float64)
    found = BatchArrays(
        time=t,
        c=np.ascontiguousarray(c, dtype=np.float64),
        theta=np.ascontiguousarray(theta, dtype=np.float64),
        frequencies=f,
        labels=tuple(labels),
        projector=line_projector(t, f),
        synchronous=decomposition_kinematic(st.kinematics, base.imperfections).synchronous_sources,
        z=z,
        rotation_hz=float(op.speed),
        stiffness=float(st.stiffness),
        d_ref=float(st.initial_approach),
        max_iter=int(qs2.MAX_ITER),
    )
    if len(_BASES) > 8:
        _BASES.clear()
    _BASES[key] = found
    return found


_BASES: dict[str, BatchArrays] = {}
#: Kept for callers of the former private name.
_line_projector = line_projector


def _evaluate_batched(
    task: ChunkTask, points: list[tuple[str, dict[str, Any]]], chunk: dict[str, Any]
) -> None:
    """Fill ``chunk`` (runout, lines, errors) from the batched kernel, column by column.

    The same JSON as the per-bearing records of :func:`evaluate_chunk` would hold: a failed
    bearing has None runout and 0 in every line; a line's entry appears at the first bearing
    that succeeds (none: no lines).
    """
    b = _batch_base(task)
    # every quantity replaces the same key: the last one (sorted keys) wins, as in _variant
    errors = np.array(
        [values[task.quantities[-1].key] for _, values in points], dtype=np.float64
    ).reshape(len(points), b.z)
    rows = evaluate_rows(b, errors, task.parallel)
    ok = rows.status == 0
    t = b.time
    for row in np.flatnonzero(~ok):
        from runout.models import quasi_static_2d as qs2

        code = int(rows.status[row])
        cause = qs2.CAUSES.get(code, "solver failure")
        at = int(rows.instant[row])
        # the exception the model's own run() raises for this status, so that a failed
        # bearing reads the same on both paths
        kind = {qs2.TOO_FEW_LOADED: ContactLossError, qs2.NOT_CONVERGED: ConvergenceError}
        exc = kind.get(code, NumericalError)(cause, at, float(t[at]))
        chunk["errors"][str(task.start + int(row))] = error_text(exc)

    def column(values: NDArray[np.float64]) -> list[float | None]:
        out: list[float | None] = values.tolist()
        for row in np.flatnonzero(~ok):
            out[row] = None
        return out

    runout = chunk["runout"]
    runout["radial_pp_m"] = column(rows.radial)
    runout["axial_pp_m"] = column(np.zeros(len(points)))
    runout["rro_pp_m"] = column(rows.rro)
    runout["nrro_pp_m"] = column(rows.nrro)
    if not ok.any():
        return
    lines = chunk["lines"]
    for axis, name in enumerate(("x", "y")):
        for j in range(b.frequencies.size):
            key = f"{name}|{line_label(b.labels[j])}"
            pp = np.where(ok, rows.pp[:, axis, j], 0.0)
            entry = lines.get(key)
            if entry is None:
                # NaN (never from hypot of finite coefficients) would read 0, as max(0.0, nan)
                lines[key] = {
                    "frequency_hz": float(b.frequencies[j]),
                    "pp_m": np.where(pp > 0.0, pp, 0.0).tolist(),
                }
            else:
                # two lines of one sample that differ only by element numbers: keep the larger
                old = np.array(entry["pp_m"], dtype=np.float64)
                entry["pp_m"] = np.where(pp > old, pp, old).tolist()


# --------------------------------------------------------------------------------------------
# statistics
# --------------------------------------------------------------------------------------------
def statistics(values: ArrayLikeF, bins: int = 20) -> dict[str, Any]:
    """Mean, std (ddof 1), 2σ, 5/50/95 % percentiles, min, max and histogram of ``values``.

    Non-finite entries (failed samples) are left out.
    """
    v = np.asarray(values, dtype=np.float64)
    v = v[np.isfinite(v)]
    if v.size == 0:
        nan = float("nan")
        return {
            "mean": nan,
            "std": nan,
            "two_sigma": nan,
            "p5": nan,
            "p50": nan,
            "p95": nan,
            "min": nan,
            "max": nan,
            "histogram": {"edges": [], "counts": []},
        }
    std = float(np.std(v, ddof=1)) if v.size > 1 else 0.0
    p5, p50, p95 = (float(x) for x in np.percentile(v, [5.0, 50.0, 95.0]))
    counts, edges = np.histogram(v, bins=bins)
    return {
        "mean": float(np.mean(v)),
        "std": std,
        "two_sigma": 2.0 * std,
        "p5": p5,
        "p50": p50,
        "p95": p95,
        "min": float(v.min()),
        "max": float(v.max()),
        "histogram": {"edges": [float(e) for e in edges], "counts": [int(c) for c in counts]},
    }


ArrayLikeF = Sequence[float] | NDArray[np.float64]
_CONTRACT = ("mean", "std", "p5", "p50", "p95")
#: Stiffness columns of stiffness.csv and :meth:`StudyResult.to_dataframe` [N/m].
_STIFFNESS_COLUMNS = ("kxx_n_per_m", "kxy_n_per_m", "kyx_n_per_m", "kyy_n_per_m", "kzz_n_per_m")
#: Runout columns of :meth:`StudyResult.to_dataframe`, in this order.
_FRAME_RUNOUT = ("radial_pp_m", "rro_pp_m", "nrro_pp_m", "axial_pp_m")
#: Confidence of the interval of a lot's yield [-].
YIELD_CONFIDENCE = 0.95


# --------------------------------------------------------------------------------------------
# result
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class StudyResult:
    """All samples (or points) of a study, column-wise.

    Attributes
    ----------
    kind : {"montecarlo", "sweep"}
    title : str
    seed : int
    quantities : tuple of Quantity
    model : list of str, length N
        Model of each sample.
    values : dict
        Quantity key -> list of N values (lists for per-element keys).
    runout : dict
        RUNOUT_KEYS -> ndarray (N,) [m]; NaN for failed samples.
    lines : dict
        ``"direction|label"`` -> (frequency [Hz], ndarray (N,) of p-p [m]).
    errors : dict
        Sample index -> message, for samples whose model failed.
    bins : int
        Histogram bins.
    limit : (str, float) or None
        ``[analysis] limit_on`` and ``limit`` [m] when the case gives a spec limit: the
        Monte Carlo JSON gets ``yield``, a sweep's points get ``pass``.
    stiffness : dict
        Sample index -> ``{"radial_stiffness": {...}, "axial_stiffness_n_per_m": K_aa}`` for
        every equilibrium sample that ran (the run JSON's ``radial_stiffness`` [N/m, rpm] and
        the axial diagonal of its ``stiffness_matrix`` [N/m]); written as ``stiffness.csv``.
    """

    kind: str
    title: str
    seed: int
    quantities: tuple[Quantity, ...]
    model: list[str]
    values: dict[str, list[Any]]
    runout: dict[str, NDArray[np.float64]]
    lines: dict[str, tuple[float, NDArray[np.float64]]]
    errors: dict[int, str]
    bins: int = 20
    limit: tuple[str, float] | None = None
    stiffness: dict[int, dict[str, Any]] = field(default_factory=dict)

    @property
    def samples(self) -> int:
        """Number of samples (or sweep points × models)."""
        return len(self.model)

    def line_table(self) -> list[tuple[str, float, str, NDArray[np.float64]]]:
        """(direction, frequency [Hz], label, p-p per sample [m]), largest mean first."""
        rows = [
            (key.split("|", 1)[0], f, key.split("|", 1)[1], pp)
            for key, (f, pp) in self.lines.items()
        ]
        ok = np.isfinite(self.runout["radial_pp_m"])
        rows.sort(key=lambda r: (-float(np.mean(r[3][ok])) if ok.any() else 0.0, r[0], r[1]))
        return rows

    def summary(self) -> dict[str, Any]:
        """Full statistics (JSON-ready): runout and lines with histograms (Monte Carlo)."""
        ok = np.isfinite(self.runout["radial_pp_m"])
        runout = {k: statistics(self.runout[k], self.bins) for k in RUNOUT_KEYS}
        comps = [
            {
                "direction": d,
                "frequency_hz": f,
                "label": label,
                "pp_m": statistics(pp[ok], self.bins),
            }
            for d, f, label, pp in self.line_table()
        ]
        return {
            "title": self.title,
            "kind": self.kind,
            "seed": self.seed,
            "models": sorted(set(self.model)),
            "samples": self.samples,
            "failed": len(self.errors),
            "errors": self.error_list(),
            "quantities": [q.key for q in self.quantities],
            "runout": runout,
            "components": comps,
        }

    def error_list(self, limit: int = ERRORS_SHOWN) -> list[dict[str, Any]]:
        """The first ``limit`` failed samples as ``{"sample": i, "error": "Type: message"}``.

        Bounded: a study where every one of 10^5 samples fails must not write 10^5 messages
        into summary.json; ``failed`` gives the count, ``points`` (sweeps) every error.
        """
        return [{"sample": i, "error": self.errors[i]} for i in sorted(self.errors)[:limit]]

    def to_json(self) -> dict[str, Any]:
        """The ``runout study --json`` object (the documented JSON contract, docs/studies.md).

        Monte Carlo: ``samples``, ``failed``, ``errors`` (the first ERRORS_SHOWN failed samples
        with their error), ``runout`` and ``components`` with each p-p as {mean, std, p5, p50,
        p95}. Sweep: the same statistics over the points, plus ``points`` (values, model,
        runout and components of each point).
        """
        full = self.summary()

        def trim(stats: dict[str, Any]) -> dict[str, float | None]:
            return {k: _finite(stats[k]) for k in _CONTRACT}

        out: dict[str, Any] = {
            "title": self.title,
            "kind": self.kind,
            "models": full["models"],
            "seed": self.seed,
            "samples": self.samples,
            "failed": len(self.errors),
            "errors": full["errors"],
            "runout": {k: trim(v) for k, v in full["runout"].items()},
            "components": [
                {
                    **{k: c[k] for k in ("direction", "frequency_hz", "label")},
                    "pp_m": trim(c["pp_m"]),
                }
                for c in full["components"]
            ],
        }
        if self.kind == "sweep":
            out["points"] = self.points()
        elif self.limit is not None:
            out["yield"] = self.lot_yield()
        return out

    def lot_yield(self, confidence: float = YIELD_CONFIDENCE) -> dict[str, Any]:
        """The ``yield`` JSON object: fraction of the lot within the limit, with its interval.

        Over the samples whose model succeeded (failed samples are neither passes nor
        failures). A sample passes when its figure is at most the limit. The interval is the
        exact binomial (Clopper-Pearson) one: ``ci_low`` = B(α/2; k, n-k+1) and ``ci_high`` =
        B(1-α/2; k+1, n-k) with B the beta quantile, α = 1 - ``confidence``; 0 when no sample
        passed and 1 when all did. ``fraction`` and the interval are null with no sample.
        """
        if self.limit is None:
            raise ValueError("the study has no spec limit")
        quantity, limit = self.limit
        values = self.runout[f"{quantity}_m"]
        ok = values[np.isfinite(values)]
        n = int(ok.size)
        k = int(np.sum(ok <= limit))
        low: float | None = None
        high: float | None = None
        if n:
            from scipy.stats import beta

            alpha = 1.0 - confidence
            low = 0.0 if k == 0 else float(beta.ppf(alpha / 2.0, k, n - k + 1))
            high = 1.0 if k == n else float(beta.ppf(1.0 - alpha / 2.0, k + 1, n - k))
        return {
            "quantity": quantity,
            "limit_m": limit,
            "passed": k,
            "samples": n,
            "fraction": k / n if n else None,
            "ci_low": low,
            "ci_high": high,
            "confidence": confidence,
            "method": "Clopper-Pearson",
        }

    def points(self) -> list[dict[str, Any]]:
        """Per-sample records: values, model, runout and non-zero lines."""
        rows = []
        table = self.line_table()
        for i in range(self.samples):
            rows.append(
                {
                    "sample": i,
                    "model": self.model[i],
                    "values": {k: v[i] for k, v in self.values.items()},
                    "runout": {k: _finite(float(self.runout[k][i])) for k in RUNOUT_KEYS},
                    "components": [
                        {"direction": d, "frequency_hz": f, "label": label, "pp_m": float(pp[i])}
                        for d, f, label, pp in table
                        if pp[i] > 0.0
                    ],
                    "error": self.errors.get(i),
                }
            )
            if i in self.stiffness:
                rows[-1]["radial_stiffness"] = dict(self.stiffness[i]["radial_stiffness"])
                rows[-1]["axial_stiffness_n_per_m"] = self.stiffness[i]["axial_stiffness_n_per_m"]
            if self.limit is not None:
                value = float(self.runout[f"{self.limit[0]}_m"][i])
                rows[-1]["pass"] = bool(value <= self.limit[1]) if math.isfinite(value) else None
        return rows

    # ------------------------------------------------------------ data
    def to_dataframe(self) -> Any:
        """One row per sample (Monte Carlo) or point (sweep) as a :class:`pandas.DataFrame`.

        Columns: ``sample`` (index), ``model``, one column per varied quantity named by its
        ``[study.vary]`` key (the case key, e.g. ``operation.speed``; SI values, a list per
        row for a per-element key), the runout figures ``radial_pp_m``, ``rro_pp_m``,
        ``nrro_pp_m``, ``axial_pp_m`` [m] (NaN for a failed sample), one p-p column [m] per
        line (``"<direction> <frequency> Hz <label> pp_m"``, as in ``samples.csv``; 0 where the
        line is below the model's reporting floor), ``pass`` when the case gives a spec limit,
        for a study of the equilibrium model ``kxx_n_per_m``, ``kxy_n_per_m``,
        ``kyx_n_per_m``, ``kyy_n_per_m`` and ``kzz_n_per_m`` [N/m] (as in ``stiffness.csv``;
        NaN for a point of another model or a failed one), and ``error`` (the failure's
        ``"Type: message"``, empty when the sample ran).
        ``df.attrs`` holds ``units``, ``kind``, ``title`` and ``seed``.

        Returns
        -------
        pandas.DataFrame

        Raises
        ------
        ImportError
            pandas is not installed (``pip install "runout[data]"``).
        """
        from runout.results import _optional

        pd = _optional("pandas")
        n = self.samples
        data: dict[str, Any] = {"sample": np.arange(n), "model": list(self.model)}
        units: dict[str, str] = {"sample": "-", "model": "-"}
        for q in self.quantities:
            values = self.values[q.key]
            data[q.key] = [list(v) for v in values] if q.size > 1 else list(values)
            units[q.key] = _si_unit(q)
        for k in _FRAME_RUNOUT:
            data[k] = np.asarray(self.runout[k], dtype=np.float64)
            units[k] = "m"
        for d, f, label, pp in self.line_table():
            name = f"{d} {f:.6g} Hz {label} pp_m"  # unique: lines are keyed by direction|label
            data[name] = np.asarray(pp, dtype=np.float64)
            units[name] = "m"
        if self.limit is not None:
            figure = np.asarray(self.runout[f"{self.limit[0]}_m"], dtype=np.float64)
            data["pass"] = [bool(v <= self.limit[1]) if math.isfinite(v) else None for v in figure]
            units["pass"] = "-"
        if self.stiffness:  # equilibrium points: the columns of stiffness.csv, NaN elsewhere
            table = dict(self.stiffness_columns())
            for name in _STIFFNESS_COLUMNS:
                values = table[name]
                column = np.full(n, np.nan)
                column[sorted(self.stiffness)] = values
                data[name] = column
                units[name] = "N/m"
        data["error"] = [self.errors.get(i, "") for i in range(n)]
        units["error"] = "-"
        df = pd.DataFrame(data)
        df.attrs.update({"units": units, "kind": self.kind, "title": self.title, "seed": self.seed})
        if self.limit is not None:
            df.attrs["limit"] = {"quantity": self.limit[0], "limit_m": self.limit[1]}
        return df

    def plot(self, kind: str | None = None, quantity: str | None = None, top: int = 4) -> Any:
        """One figure of the study (matplotlib, through :mod:`runout.plotting`).

        Parameters
        ----------
        kind : {"histograms", "sweep"}, optional
            ``"histograms"`` (Monte Carlo) or ``"sweep"``; by default the study's own kind.
        quantity : str, optional
            Sweep: the swept key on the horizontal axis (needed when several are swept).
        top : int
            Number of lines drawn.

        Returns
        -------
        matplotlib.figure.Figure
        """
        from runout.plotting import plot_study_kind

        if kind is None:
            kind = "histograms" if self.kind == "montecarlo" else "sweep"
        return plot_study_kind(self, kind, quantity=quantity, top=top)

    # ------------------------------------------------------------ files
    def write(self, directory: Path, plots: bool = True) -> list[Path]:
        """Write ``summary.json``, ``samples.csv`` and plots into ``directory``."""
        directory.mkdir(parents=True, exist_ok=True)
        summary = _nan_to_none(self.summary())  # every sample failed: no statistics, null
        if self.limit is not None and self.kind == "montecarlo":
            summary["yield"] = self.lot_yield()
        written = [_write_text(directory / "summary.json", _dumps(summary, indent=2))]
        written.append(self._write_csv(directory / "samples.csv"))
        if self.stiffness:
            written.append(self._write_stiffness(directory / "stiffness.csv"))
        if plots:
            from runout.plotting import plot_study

            if self.limit is None:
                written += plot_study(self, directory)
            else:
                # the spec limit as a line on the histogram of its quantity
                written += plot_study(
                    self, directory, limit_quantity=f"{self.limit[0]}_m", limit_m=self.limit[1]
                )
        return written

    def columns(self) -> list[tuple[str, NDArray[Any]]]:
        """Flat table: (column name, values per sample)."""
        cols: list[tuple[str, NDArray[Any]]] = [
            ("sample", np.arange(self.samples)),
            ("model", np.array(self.model, dtype=object)),
        ]
        for q in self.quantities:
            vals = self.values[q.key]
            if q.size > 1:
                arr = np.array(vals, dtype=np.float64).reshape(self.samples, q.size)
                cols += [(f"{q.key}[{j + 1}]", arr[:, j]) for j in range(q.size)]
            else:
                cols.append((q.key, np.array(vals, dtype=object)))
        cols += [(k, self.runout[k]) for k in RUNOUT_KEYS]
        for d, f, label, pp in self.line_table():
            cols.append((f"{d} {f:.6g} Hz {label} pp_m", pp))
        return cols

    def stiffness_columns(self) -> list[tuple[str, list[Any]]]:
        """The table of ``stiffness.csv``: one row per equilibrium point that ran.

        Columns: ``sample``, the varied values by case key [SI] (``key[j]`` per element of a
        per-element key), ``speed_rpm`` [rev/min], ``frequency_rad_per_s`` (the speed as the
        rotor's angular frequency [rad/s], what rotordynamics codes index bearing
        coefficients by), ``kxx_n_per_m``, ``kxy_n_per_m``, ``kyx_n_per_m``, ``kyy_n_per_m``
        (the radial block, tilts held) and ``kzz_n_per_m`` (the axial stiffness K_aa) [N/m].
        A point whose model failed has no row (its error is in the points and summary).
        """
        rows = sorted(self.stiffness)
        cols: list[tuple[str, list[Any]]] = [("sample", rows)]
        for q in self.quantities:
            vals = self.values[q.key]
            if q.size > 1:
                cols += [(f"{q.key}[{j + 1}]", [vals[i][j] for i in rows]) for j in range(q.size)]
            else:
                cols.append((q.key, [vals[i] for i in rows]))
        radial = [self.stiffness[i]["radial_stiffness"] for i in rows]
        cols.append(("speed_rpm", [r["speed_rpm"] for r in radial]))
        cols.append(
            ("frequency_rad_per_s", [r["speed_rpm"] * 2.0 * math.pi / 60.0 for r in radial])
        )
        for k in _STIFFNESS_COLUMNS[:4]:
            cols.append((k, [r[k] for r in radial]))
        cols.append(("kzz_n_per_m", [self.stiffness[i]["axial_stiffness_n_per_m"] for i in rows]))
        return cols

    def _write_stiffness(self, path: Path) -> Path:
        cols = self.stiffness_columns()

        def rows(fh: TextIO) -> None:
            writer = csv.writer(fh, lineterminator="\n")
            writer.writerow([name for name, _ in cols])
            writer.writerows(zip(*([_cell(v) for v in col] for _, col in cols), strict=True))

        return write_atomic(path, rows)

    def _write_csv(self, path: Path) -> Path:
        cols = self.columns()

        cells = [_cells(col) for _, col in cols]  # column by column: no per-cell dispatch

        def rows(fh: TextIO) -> None:
            writer = csv.writer(fh, lineterminator="\n")
            writer.writerow([name for name, _ in cols])
            writer.writerows(zip(*cells, strict=True))

        return write_atomic(path, rows)


def _si_unit(q: Quantity) -> str:
    """SI unit of a varied quantity's values (``"-"`` for a count, a ratio or a text)."""
    from runout.plotting import _key_unit_kind  # the case schema's kind of the key
    from runout.units import KINDS

    kind = _key_unit_kind(q.path)
    return (KINDS[kind][1] if kind is not None else "") or "-"


def _cell(value: Any) -> str:
    if isinstance(value, float | np.floating):
        return repr(float(value)) if math.isfinite(value) else ""
    return str(value)


def _cells(column: NDArray[Any]) -> list[str]:
    """:func:`_cell` of every entry of ``column``, the same text."""
    if column.dtype.kind == "f":
        return [repr(v) if math.isfinite(v) else "" for v in column.tolist()]
    if column.dtype.kind in "iu":
        return [str(v) for v in column.tolist()]
    return [_cell(v) for v in column]


def _finite(value: float) -> float | None:
    return float(value) if math.isfinite(value) else None


def _nan_to_none(obj: Any) -> Any:
    """``obj`` with every non-finite float replaced by None (JSON has no NaN)."""
    if isinstance(obj, float):
        return _finite(obj)
    if isinstance(obj, dict):
        return {k: _nan_to_none(v) for k, v in obj.items()}
    if isinstance(obj, list):
        return [_nan_to_none(v) for v in obj]
    return obj


def _dumps(obj: Any, indent: int | None = None) -> str:
    return json.dumps(obj, indent=indent, sort_keys=True, allow_nan=False) + "\n"


def _write_text(path: Path, text: str) -> Path:
    return write_atomic(path, lambda fh: fh.write(text))


# --------------------------------------------------------------------------------------------
# output directories: atomic files, one writer, only runout's own directories
# --------------------------------------------------------------------------------------------
#: The lock file of an output directory (holds the writer's PID; removed when it ends).
LOCK_NAME = ".lock"
#: Temporary files of :func:`write_atomic`: ``.<name>.<12 hex digits>.tmp``.
_TEMP = re.compile(r"^\..+\.[0-9a-f]{12}\.tmp$")
#: What ``runout sweep-dynamic`` writes into its ``--out`` (legacy directories have no marker).
_SWEEP_DYNAMIC = re.compile(r"^(points|sweep\.csv|trend\.png|spectra_.+\.png)$")


class OutputError(StudyError):
    """An output directory that cannot be used: not a directory, unwritable, foreign, locked."""


def write_atomic(path: Path, write: Callable[[TextIO], Any]) -> Path:
    """Write ``path`` through a uniquely named temporary file in the same directory.

    ``os.replace`` within one directory is atomic: a reader, or a study resumed after a kill,
    sees the old file or the new one, never half of one. The temporary name is unique
    (``.<name>.<random>.tmp``, created with O_EXCL), so two writers can never truncate or
    rename each other's temporary file, and a leftover of a killed run is recognised and
    removed by the next run (:func:`_remove_leftovers`). Created with mode 0o666 minus the
    umask, like any file the user writes (``mkstemp`` would make it private).

    Raises
    ------
    OutputError
        Naming ``path`` when the file system refuses (read-only, full, permissions).
    """
    try:
        for _ in range(100):
            tmp = path.with_name(f".{path.name}.{secrets.token_hex(6)}.tmp")
            try:
                fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
            except FileExistsError:
                continue
            break
        else:  # pragma: no cover - 100 collisions of 48 random bits
            raise FileExistsError(f"no free temporary name next to {path}")
        try:
            with os.fdopen(fd, "w", encoding="utf-8", newline="") as fh:
                write(fh)
            os.replace(tmp, path)
        except BaseException:
            tmp.unlink(missing_ok=True)
            raise
    except OSError as exc:
        raise OutputError(f"{path}: cannot write ({exc.strerror or exc})") from None
    return path


def output_directory(out: Path | str, option: str = "--out") -> Path:
    """Check ``out`` can be an output directory and create it (with its parents).

    Parameters
    ----------
    out : path or str
        As the user gave it. An empty string is refused: ``Path("")`` is the current
        directory, and writing a study there by accident would replace its files.
    option : str
        Name of the option in messages.

    Raises
    ------
    OutputError
        One line naming the path: empty, an existing file (``/dev/null`` too), or a directory
        that cannot be created.
    """
    if isinstance(out, str) and not out.strip():
        raise OutputError(f"{option}: empty path; give a directory (use {option} . for this one)")
    path = Path(out)
    if path.exists() and not path.is_dir():
        raise OutputError(f"{option} {path}: exists and is not a directory")
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(
            f"{option} {path}: cannot create the directory ({exc.strerror or exc})"
        ) from None
    return path


def _own_lock_file(path: Path) -> bool:
    """Whether ``path`` looks like a lock file of ours: empty or one PID."""
    try:
        text = path.read_text(encoding="ascii").strip()
    except (OSError, ValueError):
        return False
    return text == "" or text.isdigit()


def _entries(directory: Path) -> list[Path]:
    """What ``directory`` holds besides our lock file and leftover temporary files."""
    return sorted(
        p
        for p in directory.iterdir()
        if not (p.name == LOCK_NAME and _own_lock_file(p)) and not _TEMP.match(p.name)
    )


def refuse_foreign(directory: Path, kind: str, force: bool, option: str = "--out") -> None:
    """Refuse a non-empty ``directory`` that is not a runout output of ``kind``.

    A study replaces its own files (chunks, manifest, summary, CSV, plots) in its output
    directory; pointed by mistake at a directory of the user's (or of another command) it
    would overwrite files that happen to share those names and mix its files with others.

    Parameters
    ----------
    directory : Path
        An existing directory.
    kind : {"study", "sweep-dynamic"}
        A study directory holds a ``manifest.json`` of format FORMAT; a sweep-dynamic
        directory holds only ``points/``, ``sweep.csv``, ``trend.png`` and ``spectra_*.png``.
    force : bool
        Write into the directory anyway (only the files runout writes are replaced).

    Raises
    ------
    OutputError
        Naming the directory and the first entry that is not runout's.
    StudyError
        A study directory whose manifest is corrupted (naming the file).
    """
    if force:
        return
    try:
        entries = _entries(directory)
    except OSError as exc:
        raise OutputError(f"{option} {directory}: cannot list ({exc.strerror or exc})") from None
    if not entries:
        return
    if kind == "study":
        manifest = directory / "manifest.json"
        if manifest.is_file():
            _read_manifest(manifest)  # a corrupted manifest is an error of its own
            return
        foreign: Path | None = entries[0]
    else:
        foreign = next((p for p in entries if not _SWEEP_DYNAMIC.match(p.name)), None)
    if foreign is None:
        return
    raise OutputError(
        f"{option} {directory}: not empty and not a runout {kind} output (it holds "
        f"{foreign.name!r}); choose an empty directory or pass --force to write into it"
    )


def _remove_leftovers(directory: Path) -> None:
    """Delete temporary files left by a killed writer (only names write_atomic makes)."""
    for folder in (directory, directory / "chunks", directory / "points"):
        if folder.is_dir():
            for p in folder.iterdir():
                if _TEMP.match(p.name):
                    p.unlink(missing_ok=True)


def _lock_holder(fd: int) -> str:
    try:
        text = os.pread(fd, 32, 0).decode("ascii", "replace").strip()
    except OSError:
        text = ""
    return text if text.isdigit() else "unknown"


def _pid_alive(pid: int) -> bool:  # pragma: no cover - only without fcntl (Windows)
    if pid <= 0:
        return False
    if sys.platform == "win32":
        import ctypes

        handle = ctypes.windll.kernel32.OpenProcess(0x1000, False, pid)  # type: ignore[attr-defined]
        if not handle:
            return False
        ctypes.windll.kernel32.CloseHandle(handle)  # type: ignore[attr-defined]
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


@contextlib.contextmanager
def output_lock(directory: Path) -> Iterator[Path]:
    """Hold the exclusive writer lock of ``directory`` (``directory/.lock``) while in the block.

    POSIX: ``flock`` on the lock file. The kernel releases it when the holder ends, even by
    SIGKILL, so a lock is never stale; the file holds the holder's PID for the message.
    Without ``fcntl`` (Windows) the file is created with O_EXCL and a lock whose PID is no
    longer running is taken over. The file is removed on the way out; a writer that opened
    it just before must then lock the file now at the path (checked with ``samestat``),
    otherwise two writers could hold locks on two different files.

    Raises
    ------
    OutputError
        ``"<dir>/.lock: another runout study is writing to <dir> (pid N)"``, or naming the
        lock file when it cannot be created (unwritable directory).
    """
    path = directory / LOCK_NAME
    busy = f"{path}: another runout study is writing to {directory} (pid {{}})"
    try:
        fd = _acquire(path, busy)
    except OSError as exc:
        raise OutputError(f"{path}: cannot create the lock file ({exc.strerror or exc})") from None
    try:
        os.ftruncate(fd, 0)
        os.pwrite(fd, f"{os.getpid()}\n".encode(), 0)
        yield path
    finally:
        with contextlib.suppress(OSError):
            path.unlink()
        os.close(fd)


def _acquire(path: Path, busy: str) -> int:
    if fcntl is None:  # pragma: no cover - Windows
        while True:
            try:
                return os.open(path, os.O_RDWR | os.O_CREAT | os.O_EXCL, 0o666)
            except FileExistsError:
                holder = path.read_text(encoding="ascii", errors="replace").strip()
                if holder.isdigit() and _pid_alive(int(holder)):
                    raise OutputError(busy.format(holder)) from None
                path.unlink(missing_ok=True)  # stale: its writer is gone
    while True:
        fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o666)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            holder = _lock_holder(fd)
            os.close(fd)
            raise OutputError(busy.format(holder)) from None
        except BaseException:
            os.close(fd)
            raise
        try:
            if os.path.samestat(os.fstat(fd), os.stat(path)):
                return fd
        except FileNotFoundError:
            pass
        os.close(fd)  # the holder removed that file on its way out: lock the new one


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
        Scheduler address ``tcp://HOST:PORT``; None starts a local cluster.
    **cluster
        Keyword arguments of :class:`distributed.LocalCluster` when ``address`` is None.

    Raises
    ------
    StudyError
        When Dask is not installed (``pip install 'runout[dask]'``) or the scheduler does not
        answer.
    """
    try:
        from distributed import Client, LocalCluster
    except ImportError:  # pragma: no cover - depends on the installation
        raise StudyError("--scheduler needs Dask distributed: pip install 'runout[dask]'") from None
    try:
        if address is None:
            import dask

            cluster.setdefault("dashboard_address", None)
            # Dask's nannies trim malloc at 64 KiB by default (MALLOC_TRIM_THRESHOLD_), which
            # returns every NumPy temporary of a chunk to the system and costs the workers
            # much of their time; a local cluster of ours keeps glibc's usual behaviour.
            trim = {"distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": 2**28}
            with dask.config.set(trim):
                client = Client(LocalCluster(**cluster))
        else:
            client = Client(address, timeout=cluster.get("timeout", 10))
    except (OSError, TimeoutError) as exc:
        raise StudyError(f"cannot reach the Dask scheduler {address}: {exc}") from None
    return client.get_executor()


def _digest(data: dict[str, Any], study: StudySpec, base_dir: str) -> str:
    """SHA-256 of what decides a study's numbers: the case (SI), ``[study]``, profile files.

    A ``[[profile]]`` names a CSV file; its bytes are part of the case, so a remeasured
    profile makes another study (its chunks are recomputed on resume) even when the case file
    itself did not change.
    """
    files: dict[str, str] = {}
    for entry in data.get("profile", []):
        name = str(entry.get("file", ""))
        try:
            files[name] = hashlib.sha256((Path(base_dir) / name).read_bytes()).hexdigest()
        except OSError:
            files[name] = "unreadable"  # parse_case reports it when the study runs
    doc = {"case": data, "study": study.model_dump(mode="json")}
    if files:  # studies without profiles keep the digest of earlier versions
        doc["profile_files"] = files
    text = json.dumps(doc, sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()


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
        }


def _plan(case: Case, chunk_size: int | None, parallel: bool = False) -> _Plan:
    study = _study_of(case)
    data = _case_data(case)
    quantities = tuple(plan_quantities(case, data))
    models = tuple(_models(case))
    if study.kind == "montecarlo":
        total = study.samples
    else:
        total = len(models) * math.prod(len(q.values) for q in quantities)
    size = chunk_size or study.chunk_size
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
    return _Plan(study, quantities, models, total, size, tasks, _digest(data, study, base_dir))


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
        ``force``); default: a warning on the ``runout.study`` logger.

    Returns
    -------
    StudyResult
        Failed samples are in ``errors``; the study never stops on one.

    Raises
    ------
    StudyError
        Bad output directory (:class:`OutputError`: empty path, a file, unwritable, foreign,
        locked by another writer), a corrupted manifest, a resume that does not match the
        case, or a worker process that died.
    """
    in_process = executor is None and workers <= 1
    plan = _plan(
        case, chunk_size, in_process and threading.current_thread() is threading.main_thread()
    )
    from runout.conventions import enforce

    for model in plan.models:  # a key a model refuses ends the study before any work
        enforce(case, model)
    _check_analysis_outputs(case, notify or _log.warning)
    if executor is None and workers > 1 and limits.batched_study(case):
        # the case's estimate assumed this process; worker processes each hold the shared
        # arrays too (and the chunks in flight): check the budget for them before starting
        needed = limits.batched_memory(case, workers) + limits.study_points(case) * (
            limits.STUDY_BYTES_PER_RUN
        )
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
    if out is None:
        return _run(None, case, plan, executor, workers, False, False, progress, plots, notify)
    directory = output_directory(out)
    refuse_foreign(directory, "study", force)
    with output_lock(directory):
        return _run(
            directory, case, plan, executor, workers, resume, force, progress, plots, notify
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
) -> StudyResult:
    """run_study once ``directory`` (if any) is checked and locked."""
    manifest = plan.manifest()
    results: dict[int, dict[str, Any]] = {}
    if directory is not None:
        results = _prepare_directory(directory, manifest, plan, resume, force, notify)
    tasks = plan.tasks
    done_samples = sum(tasks[k].stop - tasks[k].start for k in results)
    if progress is not None:
        progress(done_samples, plan.total)
    pending = [t for t in tasks if t.index not in results]

    def finished(index: int, chunk: dict[str, Any]) -> None:
        nonlocal done_samples
        # the chunk names the case + study that wrote it: a resume accepts only its own
        chunk["digest"] = plan.digest
        results[index] = chunk
        if directory is not None:
            _write_text(_chunk_path(directory, index), _dumps(chunk))
            manifest["done"] = sorted(results)
            _write_text(directory / "manifest.json", _dumps(manifest, indent=2))
        done_samples += tasks[index].stop - tasks[index].start
        if progress is not None:
            progress(done_samples, plan.total)

    _execute(pending, executor, workers, finished)
    result = _assemble(case, plan.study, plan.quantities, [results[k] for k in range(len(tasks))])
    if directory is not None:
        manifest["complete"] = True
        _write_text(directory / "manifest.json", _dumps(manifest, indent=2))
        try:
            result.write(directory, plots=plots)
        except OSError as exc:  # a plot or the directory (summary and CSV name their file)
            raise OutputError(f"{directory}: cannot write ({exc.strerror or exc})") from None
    return result


#: Chunks submitted ahead per worker of the process pool (the others wait in the parent, so
#: that the pool's queue holds a few chunks' arrays, not the whole study's).
AHEAD_PER_WORKER = 2
#: Chunks in flight on an external executor (Dask): enough to keep a cluster busy.
AHEAD_EXTERNAL = 64


def _with_batch(tasks: list[ChunkTask]) -> list[ChunkTask]:
    """``tasks`` carrying the arrays of a batched Monte Carlo, computed here once.

    The workers then receive arrays, not a case to validate and a model to set up. A case
    whose set-up fails is left to the workers, whose per-bearing path records each failure.
    """
    if not tasks or not _batched(tasks[0]):
        return tasks
    try:
        base = _batch_base(tasks[0])
    except Exception:  # recorded bearing by bearing in the chunks (evaluate_chunk)
        return tasks
    return [dataclasses.replace(t, batch=base) for t in tasks]


def _threads(tasks: list[ChunkTask]) -> int:
    """Threads for the chunks of an in-process study: Numba's thread count for a batched
    Monte Carlo of several chunks, else 1."""
    if len(tasks) < 2 or tasks[0].batch is None:
        return 1
    import numba

    limit = int(getattr(numba.config, "NUMBA_NUM_THREADS", 1))  # set from the environment
    return max(1, min(len(tasks), limit))


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
    :func:`runout._study_pool.init_worker`) while this process computes the shared arrays.
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
    pool: Executor = (
        ProcessPoolExecutor(
            max_workers=workers,
            initializer=_init_worker,
            initargs=(os.getpid(),),
            mp_context=_context(),
        )
        if executor is None
        else executor
    )
    ok = False
    try:
        if own:  # start every worker now: their start-up overlaps the set-up below
            for _ in range(workers):
                pool.submit(int)
        ahead = AHEAD_PER_WORKER * workers if own else AHEAD_EXTERNAL
        _drain(pool, iter(_with_batch(tasks)), len(tasks), ahead, finished)
        ok = True
    finally:
        if own:
            # every chunk is in: the idle workers exit on their own (they end with this
            # process in any case); after a failure, cancel and wait for them
            pool.shutdown(wait=not ok, cancel_futures=True)


def _drain(
    pool: Executor,
    queue: Iterator[ChunkTask],
    count: int,
    ahead: int,
    finished: Callable[[int, dict[str, Any]], None],
) -> None:
    """Run the ``count`` tasks of ``queue`` on ``pool``, at most ``ahead`` at a time."""
    running: dict[Future[dict[str, Any]], int] = {}
    for _ in range(count + 1):  # one submission round per finished chunk, at most
        for task in itertools.islice(queue, max(0, ahead - len(running))):
            running[pool.submit(evaluate_chunk, task)] = task.index
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


# ---------------------------------------------------------------- manifest and chunk checks
_RESUME_KEYS = ("format", "digest", "samples", "chunk_size", "chunks")


def _is_int(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _is_number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value)


def _manifest_problem(doc: Any) -> str | None:
    """What makes ``doc`` not a manifest.json of this version, or None."""
    if not isinstance(doc, dict):
        return f"a JSON {type(doc).__name__}, not an object"
    if doc.get("format") != FORMAT:
        return f"format is {doc.get('format')!r}, not {FORMAT!r}"
    if not isinstance(doc.get("digest"), str):
        return "no study digest"
    if doc.get("kind") not in ("montecarlo", "sweep"):
        return f"kind is {doc.get('kind')!r}"
    for key in ("samples", "chunk_size", "chunks"):
        if not _is_int(doc.get(key)) or doc[key] < 1:
            return f"{key} is {doc.get(key)!r}, not a positive integer"
    done = doc.get("done")
    if not isinstance(done, list) or not all(_is_int(k) and 0 <= k < doc["chunks"] for k in done):
        return f"done is not a list of chunk numbers below {doc['chunks']}"
    if len(set(done)) != len(done):
        return "done lists a chunk twice"
    if not isinstance(doc.get("complete"), bool):
        return "complete is not true or false"
    return None


def _read_manifest(path: Path) -> dict[str, Any]:
    """``path`` (a manifest.json) checked field by field.

    Raises
    ------
    StudyError
        Naming the file when it cannot be read or is not a manifest of this version: a
        truncated or hand-edited manifest must not become a traceback, nor a resume that
        trusts whatever it lists.
    """
    try:
        doc = json.loads(path.read_text(encoding="utf-8"))
    except OSError as exc:
        problem = f"cannot read: {exc.strerror or exc}"
    except ValueError as exc:  # JSONDecodeError, UnicodeDecodeError
        problem = f"not valid JSON: {exc}"
    else:
        found = _manifest_problem(doc)
        if found is None:
            return dict(doc)
        problem = found
    raise StudyError(
        f"{path}: corrupted study manifest ({problem}); pass --force to start the study afresh "
        f"in {path.parent}"
    )


def _chunk_problem(chunk: Any, task: ChunkTask, digest: str) -> str | None:
    """What makes ``chunk`` not the result of ``task`` in the study ``digest``, or None.

    The digest comes first: a chunk swapped in from another study (or another version of
    this case) is well formed and would silently replace this study's samples. The rest is
    the structure _assemble and StudyResult rely on, so that a damaged file is recomputed
    instead of raising KeyError / TypeError half-way through the statistics.
    """
    if not isinstance(chunk, dict):
        return f"a JSON {type(chunk).__name__}, not an object"
    if chunk.get("digest") != digest:
        return "written by another study" if "digest" in chunk else "no study digest"
    for key, want in (("chunk", task.index), ("start", task.start), ("stop", task.stop)):
        if not _is_int(chunk.get(key)) or chunk[key] != want:
            return f"{key} is {chunk.get(key)!r}, expected {want}"
    n = task.stop - task.start
    model, values, runout = chunk.get("model"), chunk.get("values"), chunk.get("runout")
    if not isinstance(model, list) or len(model) != n or not all(isinstance(m, str) for m in model):
        return f"model is not a list of {n} names"
    if not isinstance(values, dict) or set(values) != {q.key for q in task.quantities}:
        return "values do not hold the study's quantities"
    for q in task.quantities:
        column = values[q.key]
        if not isinstance(column, list) or len(column) != n:
            return f"values of {q.key} are not a list of {n}"
        for v in column:
            ok = (
                isinstance(v, list) and len(v) == q.size and all(_is_number(x) for x in v)
                if q.size > 1
                else _is_number(v) or isinstance(v, str)
            )
            if not ok:
                return f"a value of {q.key} is {v!r}"
    if not isinstance(runout, dict) or not all(
        isinstance(runout.get(k), list)
        and len(runout[k]) == n
        and all(v is None or _is_number(v) for v in runout[k])
        for k in RUNOUT_KEYS
    ):
        return "runout is not a list of numbers per figure"
    lines = chunk.get("lines")
    if not isinstance(lines, dict):
        return "lines is not an object"
    for key, entry in lines.items():
        if (
            "|" not in key
            or not isinstance(entry, dict)
            or not _is_number(entry.get("frequency_hz"))
            or not isinstance(entry.get("pp_m"), list)
            or len(entry["pp_m"]) != n
            or not all(_is_number(v) for v in entry["pp_m"])
        ):
            return f"line {key!r} is damaged"
    errors = chunk.get("errors")
    if not isinstance(errors, dict) or not all(
        k.isdigit() and task.start <= int(k) < task.stop and isinstance(v, str)
        for k, v in errors.items()
    ):
        return "errors is not an object of sample numbers and messages"
    return _stiffness_problem(chunk, task)


#: The model whose points carry a stiffness (``runout.models.equilibrium.MODEL``; not imported:
#: checking a chunk must not load the model).
_EQUILIBRIUM = "equilibrium"
#: Keys of a point's ``radial_stiffness`` (:func:`runout.models.equilibrium.radial_stiffness`).
_RADIAL_KEYS = ("kxx_n_per_m", "kxy_n_per_m", "kyx_n_per_m", "kyy_n_per_m", "speed_rpm")


def _stiffness_problem(chunk: dict[str, Any], task: ChunkTask) -> str | None:
    """What is wrong with the chunk's ``stiffness`` entries, or None.

    Every equilibrium point that ran must have one: a chunk written before studies kept the
    stiffness (no ``stiffness`` object) is recomputed rather than giving a stiffness.csv with
    points missing.
    """
    stiffness = chunk.get("stiffness", {})
    if not isinstance(stiffness, dict):
        return "stiffness is not an object"
    for k, entry in stiffness.items():
        radial = entry.get("radial_stiffness") if isinstance(entry, dict) else None
        if (
            not k.isdigit()
            or not task.start <= int(k) < task.stop
            or not isinstance(radial, dict)
            or set(radial) != set(_RADIAL_KEYS)
            or not all(_is_number(v) for v in radial.values())
            or not _is_number(entry.get("axial_stiffness_n_per_m"))
        ):
            return f"stiffness of sample {k!r} is damaged"
    for row, model in enumerate(chunk["model"]):
        i = str(task.start + row)
        if model == _EQUILIBRIUM and i not in chunk["errors"] and i not in stiffness:
            return f"sample {i} has no stiffness (written by an earlier version)"
    return None


def _load_chunks(
    directory: Path, indices: Iterable[int], plan: _Plan
) -> tuple[dict[int, dict[str, Any]], list[str]]:
    """The recorded chunks that pass :func:`_chunk_problem`, and ``"name: problem"`` of others."""
    done: dict[int, dict[str, Any]] = {}
    bad: list[str] = []
    for index in indices:
        path = _chunk_path(directory, index)
        try:
            chunk = json.loads(path.read_text(encoding="utf-8"))
        except FileNotFoundError:
            problem: str | None = "missing"
        except OSError as exc:
            problem = f"cannot read: {exc.strerror or exc}"
        except ValueError:
            problem = "not valid JSON"
        else:
            problem = _chunk_problem(chunk, plan.tasks[index], plan.digest)
        if problem is None:
            done[index] = chunk
        else:
            bad.append(f"{path.name}: {problem}")
    return done, bad


#: Files a study writes at the top of its output directory (replaced by a fresh run).
_STUDY_FILES = re.compile(
    r"^(manifest\.json|summary\.json|samples\.csv|stiffness\.csv|histograms\.png|sweep_.+\.png)$"
)


def _prepare_directory(
    directory: Path,
    manifest: dict[str, Any],
    plan: _Plan,
    resume: bool,
    force: bool,
    notify: Callable[[str], None],
) -> dict[int, dict[str, Any]]:
    """Check ``directory`` (locked by us); return the chunks already done (resume).

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
    done: dict[int, dict[str, Any]] = {}
    fresh = not resume or old is None
    if not fresh:
        assert old is not None
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
            done, bad = _load_chunks(directory, old["done"], plan)
            if bad:
                n = len(bad)
                shown = "; ".join(bad[:3]) + ("; ..." if n > 3 else "")
                notify(
                    f"{directory / 'chunks'}: recomputing {n} chunk{'s' if n > 1 else ''} that "
                    f"{'were' if n > 1 else 'was'} unreadable or not written by this study "
                    f"({shown})"
                )
    try:
        if fresh:
            for p in directory.iterdir():
                if p.is_file() and _STUDY_FILES.match(p.name):
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


def _assemble(
    case: Case, study: StudySpec, quantities: tuple[Quantity, ...], chunks: list[dict[str, Any]]
) -> StudyResult:
    total = sum(c["stop"] - c["start"] for c in chunks)
    model: list[str] = []
    values: dict[str, list[Any]] = {q.key: [] for q in quantities}
    runout = {k: np.full(total, np.nan) for k in RUNOUT_KEYS}
    lines: dict[str, tuple[float, NDArray[np.float64]]] = {}
    errors: dict[int, str] = {}
    stiffness: dict[int, dict[str, Any]] = {}
    for c in chunks:
        s, e = c["start"], c["stop"]
        model += c["model"]
        for key in values:
            values[key] += c["values"][key]
        for k in RUNOUT_KEYS:
            runout[k][s:e] = [np.nan if v is None else v for v in c["runout"][k]]
        for key, entry in c["lines"].items():
            if key not in lines:
                lines[key] = (entry["frequency_hz"], np.zeros(total))
            lines[key][1][s:e] = entry["pp_m"]
        errors.update({int(k): v for k, v in c["errors"].items()})
        stiffness.update({int(k): v for k, v in c.get("stiffness", {}).items()})
    return StudyResult(
        kind=study.kind,
        title=case.title,
        seed=study.seed,
        quantities=quantities,
        model=model,
        values=values,
        runout=runout,
        lines=lines,
        errors=errors,
        bins=study.bins,
        limit=study_limit(case),
        stiffness=stiffness,
    )


def study_limit(case: Case) -> tuple[str, float] | None:
    """``(limit_on, limit [m])`` of the case's spec limit on a runout figure, or None."""
    analysis = case.analysis
    limit = getattr(analysis, "limit", None)
    if limit is None:
        return None
    return str(analysis.limit_on), float(limit)


def load_study(directory: Path | str, case: Case) -> StudyResult:
    """Read a finished study from its output directory.

    Raises
    ------
    StudyError
        Naming the file: no or a corrupted manifest, a manifest of another case or study, a
        missing chunk (a partial run) or a chunk that is damaged or not this study's.
    """
    d = Path(directory)
    manifest = _read_manifest(d / "manifest.json")
    plan = _plan(case, manifest["chunk_size"])
    differs = next((k for k in _RESUME_KEYS if manifest[k] != plan.manifest()[k]), None)
    if differs is not None:
        raise StudyError(f"{d / 'manifest.json'}: a run of a different case or study ({differs})")
    chunks, bad = _load_chunks(d, range(len(plan.tasks)), plan)
    if bad:
        raise StudyError(f"{d / 'chunks'}: not a complete study of this case ({bad[0]})")
    return _assemble(case, plan.study, plan.quantities, [chunks[k] for k in range(len(plan.tasks))])
