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
process (vectorised: ball-size Monte Carlo of the 2-D model goes through the batched Numba
kernel :func:`runout._study_kernels.solve_batch`), in a local process pool (``workers``), or on
any :class:`concurrent.futures.Executor` (a Dask ``Client.get_executor()``, see
:func:`dask_executor`). With an output directory each finished chunk is written as one JSON file
and recorded in ``manifest.json``; :func:`run_study` with ``resume=True`` skips the chunks
already written, so an interrupted run ends with the same files, byte for byte, as an
uninterrupted one.

Statistics
----------
Every runout figure and line is summarised by its mean, sample standard deviation (ddof = 1),
2σ, 5/50/95 % percentiles (linear interpolation), min, max and a histogram. A line missing from
a sample's output (below the model's reporting floor) counts as 0 in that sample.
"""

from __future__ import annotations

import copy
import csv
import functools
import hashlib
import json
import math
import os
import re
import threading
from collections.abc import Callable, Iterable, Sequence
from concurrent.futures import Executor, Future, ProcessPoolExecutor, as_completed
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from runout.case import (
    STUDY_SHORTHANDS,
    Case,
    CaseSpec,
    StudySpec,
    VarySpec,
    parse_case,
    parse_vary_key,
)
from runout.errors import CaseError, RunoutError
from runout.units import to_si

__all__ = [
    "RUNOUT_KEYS",
    "Quantity",
    "StudyError",
    "StudyResult",
    "dask_executor",
    "load_study",
    "plan_quantities",
    "run_study",
    "sample_rng",
    "statistics",
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
    size = case.bearing.n_elements if path == ("elements", None, "diameter_errors") else 0
    size = case.bearing.n_elements if path == ("elements", None, "pitch_errors") else size
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
    z = case.bearing.n_elements
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


def evaluate_chunk(task: ChunkTask) -> dict[str, Any]:
    """Evaluate one chunk: a column-wise dict (JSON-ready) of values, runout and lines."""
    chunk = _empty_chunk(task)
    points = [_point(task, i) for i in range(task.start, task.stop)]
    for model, values in points:
        chunk["model"].append(model)
        for key, v in values.items():
            chunk["values"][key].append(v)
    if _batched(task):
        _evaluate_batched(task, points, chunk)
        return chunk
    from runout.models import run_model

    for row, (model, values) in enumerate(points):
        try:
            result = run_model(_variant(task, model, values))
        except RunoutError as exc:
            chunk["errors"][str(task.start + row)] = str(exc)
            for k in RUNOUT_KEYS:
                chunk["runout"][k].append(None)
            continue
        figures = result.runout.to_json()
        for k in RUNOUT_KEYS:
            chunk["runout"][k].append(float(figures[k]))
        _add_lines(
            chunk, row, ((c.direction, c.frequency_hz, c.label, c.pp_m) for c in result.components)
        )
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


@dataclass(frozen=True)
class _BatchBase:
    """What every bearing of a ball-size Monte Carlo shares (cached per process)."""

    setup: Any
    time: NDArray[np.float64]
    c: NDArray[np.float64]
    theta: NDArray[np.float64]
    sync: tuple[NDArray[np.float64], NDArray[np.float64], int] | None
    frequencies: NDArray[np.float64]
    labels: tuple[str, ...]
    projector: NDArray[np.float64]
    z: int
    rotation_hz: float


_BASES: dict[str, _BatchBase] = {}


def _batch_base(task: ChunkTask) -> _BatchBase:
    key = json.dumps([task.path, task.base_dir, task.data], sort_keys=True, default=str)
    found = _BASES.get(key)
    if found is not None:
        return found
    from runout.models import quasi_static_2d as qs2
    from runout.models._quasi_static import predicted_lines, synchronous_grid, time_grid

    data = copy.deepcopy(task.data)
    data.setdefault("analysis", {})["model"] = "quasi_static_2d"
    case = parse_case(data, task.path, Path(task.base_dir))
    from runout.conventions import enforce

    enforce(case, "quasi_static_2d")  # the batch shares the model's refusals
    z = case.bearing.n_elements
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
    grid = synchronous_grid(op.speed, an.revolutions, an.samples)
    sync: tuple[NDArray[np.float64], NDArray[np.float64], int] | None = None
    if grid is not None:
        ts, spr = grid
        # The same instants up to round-off (time_grid and synchronous_grid compute them
        # differently): reuse the record instead of solving twice.
        if ts.size == t.size and np.allclose(ts, t, rtol=0.0, atol=1e-9 * (t[1] - t[0])):
            sync = (np.empty((0, z)), np.empty((0, z)), spr)
        else:
            cs, ths = qs2.approaches(base, st, ts)
            sync = (cs, ths, spr)
    # lines of a representative bearing (every ball with a size error), merged as in run()
    probe = case.imperfections.with_diameter_errors(np.full(z, 1e-9))
    lines = predicted_lines(probe, st.kinematics, axial=False, second_order_pairs=True)
    duration = t.size * (t[1] - t[0])
    f_max, f_min, tol = 0.5 * t.size / duration * 0.999, 0.5 / duration, 0.05 / duration
    freqs: list[float] = []
    labels: list[list[str]] = []
    for ln in sorted(lines, key=lambda ln: ln.frequency_hz):
        if not (ln.directions == "radial" and f_min < ln.frequency_hz < f_max):
            continue
        if freqs and ln.frequency_hz - freqs[-1] <= tol:
            if ln.label not in labels[-1]:
                labels[-1].append(ln.label)
        else:
            freqs.append(ln.frequency_hz)
            labels.append([ln.label])
    f = np.array(freqs, dtype=np.float64)
    found = _BatchBase(
        setup=st,
        time=t,
        c=c,
        theta=theta,
        sync=sync,
        frequencies=f,
        labels=tuple(line_label("; ".join(lab)) for lab in labels),
        projector=_line_projector(t, f),
        z=z,
        rotation_hz=float(op.speed),
    )
    if len(_BASES) > 8:
        _BASES.clear()
    _BASES[key] = found
    return found


def _line_projector(time: NDArray[np.float64], freqs: NDArray[np.float64]) -> NDArray[np.float64]:
    r"""Least-squares projector P, shape (1 + 2m, n): [c, a_j, b_j] = P x.

    The fit of :func:`runout.spectrum.extract_lines` (constant plus a cos/sin pair per line,
    :math:`x \approx c + \sum_j a_j\cos 2\pi f_j t + b_j \sin 2\pi f_j t`) written as the
    pseudo-inverse of its design matrix, so that many records are fitted by one product.
    """
    w = 2.0 * np.pi * np.outer(time, freqs)
    design = np.concatenate([np.ones((time.size, 1)), np.cos(w), np.sin(w)], axis=1)
    return np.ascontiguousarray(np.linalg.pinv(design))


def _split_batch(
    b: _BatchBase,
    q: NDArray[np.float64],
    coef: NDArray[np.float64],
    errors: NDArray[np.float64],
    status: NDArray[np.int64],
    args: tuple[Any, ...],
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """RRO and NRRO p-p of the radial (x) records, as the 2-D model's run() splits them.

    :func:`runout.models._quasi_static.split_runout`, batched: when the labelled lines explain
    the record (relative rms residual <= LINE_RESIDUAL_MAX), RRO is the p-p over one revolution
    of the integer-order lines and NRRO the p-p over the record of the others; otherwise the
    synchronous average of the record on the synchronous grid (if any) is used.
    """
    from runout._study_kernels import solve_batch
    from runout.models._quasi_static import LINE_RESIDUAL_MAX
    from runout.spectrum import separate_rro_nrro

    t = b.time
    x = q[:, :, 0]
    n_b, m = x.shape[0], b.frequencies.size
    w = 2.0 * np.pi * np.outer(b.frequencies, t)  # (m, n)
    basis = np.concatenate([np.ones((1, t.size)), np.cos(w), np.sin(w)])  # (1 + 2m, n)
    fitted = np.einsum("bk,kn->bn", coef, basis, optimize=False)
    centred = x - x.mean(axis=1, keepdims=True)
    scale = np.sqrt(np.mean(centred**2, axis=1))
    residual = np.sqrt(np.mean((x - fitted) ** 2, axis=1))
    use_lines = (scale == 0.0) | (residual <= LINE_RESIDUAL_MAX * scale)
    rro = np.zeros(n_b)
    nrro = np.zeros(n_b)
    speed = b.rotation_hz
    if m:
        orders = b.frequencies / speed
        rep = np.abs(orders - np.round(orders)) < 1e-9
        a_c, a_s = coef[:, 1 : 1 + m], coef[:, 1 + m :]
        if rep.any():
            spr = max(2048, int(16 * np.abs(orders[rep]).max()))
            wr = 2.0 * np.pi * np.outer(b.frequencies[rep], np.arange(spr) / (spr * speed))
            wave = np.einsum("bk,kn->bn", a_c[:, rep], np.cos(wr), optimize=False)
            wave += np.einsum("bk,kn->bn", a_s[:, rep], np.sin(wr), optimize=False)
            rro = np.ptp(wave, axis=1)
        if (~rep).any():
            wn = w[~rep]
            wave = np.einsum("bk,kn->bn", a_c[:, ~rep], np.cos(wn), optimize=False)
            wave += np.einsum("bk,kn->bn", a_s[:, ~rep], np.sin(wn), optimize=False)
            nrro = np.ptp(wave, axis=1)
    rro = np.where(scale == 0.0, 0.0, rro)
    nrro = np.where(scale == 0.0, 0.0, nrro)
    if use_lines.all() or b.sync is None:
        if b.sync is None:
            rro = np.where(use_lines, rro, 0.0)
            nrro = np.where(use_lines, nrro, 0.0)
        return rro, nrro
    cs, ths, spr_s = b.sync
    if cs.shape[0] == 0:
        xs, sync_status = x, status
    else:
        qs_, _, sync_status, _ = solve_batch(cs, 0.5 * errors, ths, *args)
        xs = qs_[:, :, 0]
    sep = separate_rro_nrro(xs, spr_s, axis=-1)
    avg_rro = np.where(sync_status == 0, sep.rro_pp, np.nan)
    avg_nrro = np.where(sync_status == 0, sep.nrro_pp, np.nan)
    return np.where(use_lines, rro, avg_rro), np.where(use_lines, nrro, avg_nrro)


def _evaluate_batched(
    task: ChunkTask, points: list[tuple[str, dict[str, Any]]], chunk: dict[str, Any]
) -> None:
    from runout._study_kernels import project_rows, solve_batch
    from runout.models import quasi_static_2d as qs2

    b = _batch_base(task)
    st, t = b.setup, b.time
    # every quantity replaces the same key: the last one (sorted keys) wins, as in _variant
    errors = np.array(
        [values[task.quantities[-1].key] for _, values in points], dtype=np.float64
    ).reshape(len(points), b.z)
    args = (st.stiffness, st.initial_approach, qs2.MAX_ITER, task.parallel)
    q, _unl, status, instant = solve_batch(b.c, 0.5 * errors, b.theta, *args)
    m = b.frequencies.size
    records = np.ascontiguousarray(np.transpose(q, (0, 2, 1)).reshape(-1, t.size))
    coef = project_rows(records, b.projector).reshape(len(points), 2, 1 + 2 * m)
    pp = 2.0 * np.hypot(coef[:, :, 1 : 1 + m], coef[:, :, 1 + m :])  # (B, 2, m)
    rro, nrro = _split_batch(b, q, coef[:, 0, :], errors, status, args)
    radial = np.ptp(q[:, :, 0], axis=1)
    for row in range(len(points)):
        if status[row] != 0:
            cause = qs2.CAUSES.get(int(status[row]), "solver failure")
            at = int(instant[row])
            chunk["errors"][str(task.start + row)] = f"{cause} (instant {at}, t = {t[at]:.6g} s)"
            for k in RUNOUT_KEYS:
                chunk["runout"][k].append(None)
            continue
        chunk["runout"]["radial_pp_m"].append(float(radial[row]))
        chunk["runout"]["axial_pp_m"].append(0.0)
        chunk["runout"]["rro_pp_m"].append(float(rro[row]))
        chunk["runout"]["nrro_pp_m"].append(float(nrro[row]))
        _add_lines(
            chunk,
            row,
            (
                (name, float(b.frequencies[j]), b.labels[j], float(pp[row, axis, j]))
                for axis, name in enumerate(("x", "y"))
                for j in range(m)
            ),
        )


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
            "quantities": [q.key for q in self.quantities],
            "runout": runout,
            "components": comps,
        }

    def to_json(self) -> dict[str, Any]:
        """The ``runout study --json`` object (DESIGN.md contract).

        Monte Carlo: ``samples``, ``runout`` and ``components`` with each p-p as {mean, std,
        p5, p50, p95}. Sweep: the same statistics over the points, plus ``points`` (values,
        model, runout and components of each point).
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
        return out

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
        return rows

    # ------------------------------------------------------------ files
    def write(self, directory: Path, plots: bool = True) -> list[Path]:
        """Write ``summary.json``, ``samples.csv`` and plots into ``directory``."""
        directory.mkdir(parents=True, exist_ok=True)
        written = [_write_text(directory / "summary.json", _dumps(self.summary(), indent=2))]
        written.append(self._write_csv(directory / "samples.csv"))
        if plots:
            from runout.plotting import plot_study

            written += plot_study(self, directory)
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

    def _write_csv(self, path: Path) -> Path:
        cols = self.columns()
        tmp = path.with_suffix(".tmp")
        with tmp.open("w", newline="", encoding="utf-8") as fh:
            writer = csv.writer(fh, lineterminator="\n")
            writer.writerow([name for name, _ in cols])
            for i in range(self.samples):
                writer.writerow([_cell(col[i]) for _, col in cols])
        os.replace(tmp, path)
        return path


def _cell(value: Any) -> str:
    if isinstance(value, float | np.floating):
        return repr(float(value)) if math.isfinite(value) else ""
    return str(value)


def _finite(value: float) -> float | None:
    return float(value) if math.isfinite(value) else None


def _dumps(obj: Any, indent: int | None = None) -> str:
    return json.dumps(obj, indent=indent, sort_keys=True, allow_nan=False) + "\n"


def _write_text(path: Path, text: str) -> Path:
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)
    return path


# --------------------------------------------------------------------------------------------
# running
# --------------------------------------------------------------------------------------------
def _init_worker() -> None:  # pragma: no cover - runs in worker processes
    import numba

    numba.set_num_threads(1)


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
            cluster.setdefault("dashboard_address", None)
            client = Client(LocalCluster(**cluster))
        else:
            client = Client(address, timeout=cluster.get("timeout", 10))
    except (OSError, TimeoutError) as exc:
        raise StudyError(f"cannot reach the Dask scheduler {address}: {exc}") from None
    return client.get_executor()


def _digest(data: dict[str, Any], study: StudySpec) -> str:
    doc = {"case": data, "study": study.model_dump(mode="json")}
    text = json.dumps(doc, sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()


def _chunk_path(directory: Path, index: int) -> Path:
    return directory / "chunks" / f"chunk_{index:05d}.json"


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
) -> StudyResult:
    """Run the study described by ``case.study``.

    Parameters
    ----------
    case : Case
        A validated case with a ``[study]`` table.
    executor : concurrent.futures.Executor, optional
        Where chunks run (e.g. :func:`dask_executor`); overrides ``workers``.
    workers : int
        Local worker processes when no executor is given (1: in this process).
    out : path, optional
        Directory for the chunk files, ``manifest.json``, ``summary.json``, ``samples.csv`` and
        plots.
    resume : bool
        Continue the run recorded in ``out/manifest.json`` (same case and study required).
    progress : callable, optional
        Called as ``progress(samples_done, samples_total)`` after every chunk.
    chunk_size : int, optional
        Overrides ``[study] chunk_size``.
    plots : bool
        Write plots into ``out``.

    Returns
    -------
    StudyResult

    Raises
    ------
    StudyError
        Bad output directory or a resume that does not match the case.
    """
    study = _study_of(case)
    data = _case_data(case)
    quantities = tuple(plan_quantities(case, data))
    models = tuple(_models(case))
    from runout.conventions import enforce

    for model in models:  # a key a model refuses ends the study before any work
        enforce(case, model)
    if study.kind == "montecarlo":
        total = study.samples
    else:
        total = len(models) * math.prod(len(q.values) for q in quantities)
    size = chunk_size or study.chunk_size
    n_chunks = max(1, math.ceil(total / size))
    base_dir = str(Path(case.path).resolve().parent) if case.path != "<case>" else os.getcwd()
    in_process = executor is None and workers <= 1
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
            parallel=in_process and threading.current_thread() is threading.main_thread(),
        )
        for k in range(n_chunks)
    ]
    # sweep points are known up front: check them before any work is scheduled
    directory = Path(out) if out is not None else None
    results: dict[int, dict[str, Any]] = {}
    manifest: dict[str, Any] = {
        "format": FORMAT,
        "digest": _digest(data, study),
        "kind": study.kind,
        "samples": total,
        "chunk_size": size,
        "chunks": n_chunks,
        "done": [],
        "complete": False,
    }
    if directory is not None:
        results = _prepare_directory(directory, manifest, resume)
    done_samples = sum(tasks[k].stop - tasks[k].start for k in results)
    if progress is not None:
        progress(done_samples, total)
    pending = [t for t in tasks if t.index not in results]

    def finished(index: int, chunk: dict[str, Any]) -> None:
        nonlocal done_samples
        results[index] = chunk
        if directory is not None:
            _write_text(_chunk_path(directory, index), _dumps(chunk))
            manifest["done"] = sorted(results)
            _write_text(directory / "manifest.json", _dumps(manifest, indent=2))
        done_samples += tasks[index].stop - tasks[index].start
        if progress is not None:
            progress(done_samples, total)

    _execute(pending, executor, workers, finished)
    result = _assemble(case, study, quantities, [results[k] for k in range(n_chunks)])
    if directory is not None:
        manifest["complete"] = True
        _write_text(directory / "manifest.json", _dumps(manifest, indent=2))
        result.write(directory, plots=plots)
    return result


def _execute(
    tasks: list[ChunkTask],
    executor: Executor | None,
    workers: int,
    finished: Callable[[int, dict[str, Any]], None],
) -> None:
    if not tasks:
        return
    if executor is None and workers <= 1:
        for task in tasks:
            finished(task.index, evaluate_chunk(task))
        return
    own = executor is None
    pool: Executor = (
        ProcessPoolExecutor(max_workers=workers, initializer=_init_worker, mp_context=_context())
        if executor is None
        else executor
    )
    try:
        futures: dict[Future[dict[str, Any]], int] = {
            pool.submit(evaluate_chunk, task): task.index for task in tasks
        }
        for fut in as_completed(futures):
            finished(futures[fut], fut.result())
    finally:
        if own:
            pool.shutdown(cancel_futures=True)


def _context() -> Any:
    import multiprocessing

    # Numba's threading layers are not fork-safe once used: start clean interpreters.
    return multiprocessing.get_context("spawn")


def _prepare_directory(
    directory: Path, manifest: dict[str, Any], resume: bool
) -> dict[int, dict[str, Any]]:
    """Create or check ``directory``; return the chunks already done (resume)."""
    if directory.exists() and not directory.is_dir():
        raise StudyError(f"--out {directory}: exists and is not a directory")
    (directory / "chunks").mkdir(parents=True, exist_ok=True)
    old_path = directory / "manifest.json"
    old: dict[str, Any] | None = None
    if old_path.exists():
        try:
            old = json.loads(old_path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            old = None
    done: dict[int, dict[str, Any]] = {}
    if resume:
        if old is None:
            raise StudyError(f"--resume: no readable manifest.json in {directory}")
        for key in ("format", "digest", "samples", "chunk_size", "chunks"):
            if old.get(key) != manifest[key]:
                raise StudyError(
                    f"--resume: {directory} holds a run of a different case or study ({key} "
                    "differs); run without --resume to start afresh"
                )
        for index in old.get("done", []):
            path = _chunk_path(directory, int(index))
            try:
                done[int(index)] = json.loads(path.read_text(encoding="utf-8"))
            except (OSError, ValueError):
                continue  # recomputed
    else:
        for path in (directory / "chunks").glob("chunk_*.json"):
            path.unlink()
    manifest["done"] = sorted(done)
    _write_text(old_path, _dumps(manifest, indent=2))
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
    )


def load_study(directory: Path | str, case: Case) -> StudyResult:
    """Read a finished (or partial: missing chunks raise) study from its output directory."""
    d = Path(directory)
    study = _study_of(case)
    try:
        manifest = json.loads((d / "manifest.json").read_text(encoding="utf-8"))
        chunks = [
            json.loads(_chunk_path(d, k).read_text(encoding="utf-8"))
            for k in range(int(manifest["chunks"]))
        ]
    except (OSError, ValueError, KeyError) as exc:
        raise StudyError(f"{d}: not a complete study directory ({exc})") from None
    return _assemble(case, study, tuple(plan_quantities(case)), chunks)
