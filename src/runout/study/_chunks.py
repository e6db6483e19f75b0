"""Evaluation of a study's chunks: per-bearing model runs or the batched 2-D kernel.

Part of :mod:`runout.study.run` (its module docstring describes studies).
"""

from __future__ import annotations

import copy
import dataclasses
import functools
import json
import re
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from runout.analysis.decompose import study_key
from runout.base.errors import ContactLossError, ConvergenceError, NumericalError
from runout.base.units import to_si
from runout.case.model import Case, parse_case
from runout.study._plan import RUNOUT_KEYS, Quantity, _set_at, draw_block
from runout.study._pool import BatchArrays, evaluate_rows, line_projector

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


def _plain(value: Any) -> Any:
    """A drawn value as a case takes it: a float, or a list of floats for a per-element key."""
    if isinstance(value, np.ndarray):
        return [float(x) for x in value] if value.ndim else float(value)
    return float(value) if isinstance(value, np.floating) else value


def _chunk_points(task: ChunkTask) -> tuple[list[str], dict[str, Any]]:
    """Model of every sample or point of ``task`` and the values of its quantities.

    Monte Carlo: the values as arrays drawn for the whole chunk at once (:func:`draw_block`:
    shape (n,) or (n, size) per key), no Python object per sample; sweep: lists of the grid's
    values (SI floats or the literal strings of a text key).
    """
    n = task.stop - task.start
    if task.kind == "montecarlo":
        return [task.models[0]] * n, draw_block(task.quantities, task.seed, task.start, task.stop)
    points = [_point(task, i) for i in range(task.start, task.stop)]
    values = {q.key: [v[q.key] for _, v in points] for q in task.quantities}
    return [m for m, _ in points], values


def _point(task: ChunkTask, i: int) -> tuple[str, dict[str, Any]]:
    """Model and values of sample or point ``i``."""
    if task.kind == "montecarlo":
        drawn = draw_block(task.quantities, task.seed, i, i + 1)
        return task.models[0], {key: _plain(v[0]) for key, v in drawn.items()}
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


def _stiffness_entry(details: object) -> dict[str, Any] | None:
    """What a study keeps of an equilibrium result's stiffness, or None for other models.

    ``radial_stiffness`` (the run JSON's object: kxx, kxy, kyx, kyy [N/m], speed_rpm),
    ``axial_stiffness_n_per_m``, the axial diagonal K_aa of the 5×5 ``stiffness_matrix``, and
    with damping asked the run JSON's ``bearing_damping`` (model, β [s], cxx ... czz [N s/m]).
    """
    from runout.analysis.result_details import EquilibriumDetails

    if not isinstance(details, EquilibriumDetails):
        return None
    entry: dict[str, Any] = {
        "radial_stiffness": {k: float(v) for k, v in details.radial_stiffness.to_json().items()},
        "axial_stiffness_n_per_m": float(details.stiffness_matrix.matrix[0][0]),
    }
    if details.bearing_damping is not None:
        entry["bearing_damping"] = details.bearing_damping.to_json()
    return entry


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
    """Evaluate one chunk: a column-wise dict of values, runout and lines.

    Columns are arrays (``values`` of a Monte Carlo, ``runout`` with NaN for a failed sample,
    every line's ``pp_m``); :func:`chunk_json` turns the chunk into the JSON of its file.
    A sample (or point) whose variant or model raises any :class:`Exception` is recorded in
    ``chunk["errors"]`` (sample index -> ``"Type: message"``) with NaN runout and no lines,
    and the chunk goes on: one bad point must not lose the others. ``KeyboardInterrupt`` and
    ``SystemExit`` are not exceptions of the samples and still stop the study.
    """
    chunk = _empty_chunk(task)
    models, values = _chunk_points(task)
    chunk["model"], chunk["values"] = models, values
    if _batched(task):
        # the batch fills only runout, lines and errors: it shares the drawn values
        batch = {**chunk, "runout": {}, "lines": {}, "errors": {}, "stiffness": {}}
        try:
            _evaluate_batched(task, values, batch)
        except Exception:  # the per-bearing path below records each bearing's own failure
            pass
        else:
            return batch
    from runout.runner import run_model

    runout: dict[str, list[float | None]] = chunk["runout"]
    for row, model in enumerate(models):
        point = {key: _plain(v[row]) for key, v in values.items()}
        try:
            result = run_model(_variant(task, model, point))
            figures = result.runout.to_json()
            # None: a figure the model does not have (a radial model's axial p-p), not 0
            numbers = [None if (v := figures[k]) is None else float(v) for k in RUNOUT_KEYS]
            comps = [
                (c.direction, c.frequency_hz, study_key(c.sources) or c.label, c.pp_m)
                for c in result.components
            ]
            stiffness = _stiffness_entry(result.details)
        except Exception as exc:  # recorded with its sample: the study goes on
            chunk["errors"][str(task.start + row)] = error_text(exc)
            for k in RUNOUT_KEYS:
                runout[k].append(None)
            continue
        for k, v in zip(RUNOUT_KEYS, numbers, strict=True):
            runout[k].append(v)
        _add_lines(chunk, row, comps)
        if stiffness is not None:
            chunk["stiffness"][str(task.start + row)] = stiffness
    # None (a figure the model does not have, a failed sample) is NaN in the arrays
    chunk["runout"] = {k: np.array(v, dtype=np.float64) for k, v in runout.items()}
    for entry in chunk["lines"].values():
        entry["pp_m"] = np.array(entry["pp_m"], dtype=np.float64)
    return chunk


def _listed(column: Any) -> list[Any]:
    """A column as JSON lists: NaN (a failed sample, a figure a model lacks) as None."""
    if not isinstance(column, np.ndarray):
        return list(column)
    out: list[Any] = column.tolist()
    if column.dtype.kind == "f" and column.ndim == 1:
        for i in np.flatnonzero(~np.isfinite(column)).tolist():
            out[i] = None
    return out


def chunk_json(chunk: dict[str, Any]) -> dict[str, Any]:
    """The JSON document of a chunk's file (lists; None for a failed sample's figures).

    Parameters
    ----------
    chunk : dict
        A chunk of :func:`evaluate_chunk` (array columns) or one read back from its file.

    Returns
    -------
    dict
        The same chunk with every column a list, as chunk files hold it.
    """
    return {
        **chunk,
        "values": {k: _listed(v) for k, v in chunk["values"].items()},
        "runout": {k: _listed(v) for k, v in chunk["runout"].items()},
        "lines": {
            key: {**entry, "pp_m": _listed(entry["pp_m"])} for key, entry in chunk["lines"].items()
        },
    }


# ---------------------------------------------------------------- batched 2-D path
def _batched(task: ChunkTask) -> bool:
    """Ball-size Monte Carlo of the unloaded 2-D model: every bearing shares the ball angles.

    The batched kernel solves Kim's eq. 16-17 with no external force; a case with a radial
    load (an extension of the 2-D model) goes through the model's own ``run`` instead.
    """
    from runout.base.units import UnitError

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
    from runout.analysis.decompose import resolved_lines
    from runout.models import quasi_static_2d as qs2
    from runout.models._quasi_static import decomposition_kinematic, predicted_lines, time_grid

    data = copy.deepcopy(task.data)
    data.setdefault("analysis", {})["model"] = "quasi_static_2d"
    case = parse_case(data, task.path, Path(task.base_dir))
    from runout.case.conventions import enforce

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


def _evaluate_batched(task: ChunkTask, values: dict[str, Any], chunk: dict[str, Any]) -> None:
    """Fill ``chunk`` (runout, lines, errors) from the batched kernel, column by column.

    The same numbers as the per-bearing records of :func:`evaluate_chunk` would hold: a failed
    bearing has NaN runout and 0 in every line; a line's entry appears at the first bearing
    that succeeds (none: no lines). No Python work per bearing: the drawn sizes go to the
    kernel as one array, and its rows come back as the chunk's columns.
    """
    b = _batch_base(task)
    n = task.stop - task.start
    # every quantity replaces the same key: the last one (sorted keys) wins, as in _variant
    errors = np.asarray(values[task.quantities[-1].key], dtype=np.float64).reshape(n, b.z)
    rows = evaluate_rows(b, errors, task.parallel)
    ok = rows.status == 0
    t = b.time
    for row in np.flatnonzero(~ok).tolist():
        from runout.models import quasi_static_2d as qs2

        code = int(rows.status[row])
        cause = qs2.CAUSES.get(code, "solver failure")
        at = int(rows.instant[row])
        # the exception the model's own run() raises for this status, so that a failed
        # bearing reads the same on both paths
        kind = {qs2.TOO_FEW_LOADED: ContactLossError, qs2.NOT_CONVERGED: ConvergenceError}
        exc = kind.get(code, NumericalError)(cause, at, float(t[at]))
        chunk["errors"][str(task.start + row)] = error_text(exc)

    def column(figures: NDArray[np.float64]) -> NDArray[np.float64]:
        return np.where(ok, figures, np.nan)

    chunk["runout"] = {
        "radial_pp_m": column(rows.radial),
        "axial_pp_m": np.full(n, np.nan),  # the planar model: no axial freedom
        "rro_pp_m": column(rows.rro),
        "nrro_pp_m": column(rows.nrro),
    }
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
                    "pp_m": np.where(pp > 0.0, pp, 0.0),
                }
            else:
                # two lines of one sample that differ only by element numbers: keep the larger
                old = entry["pp_m"]
                entry["pp_m"] = np.where(pp > old, pp, old)


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
