"""The files of a run, read back: ``result.json`` and ``history.csv`` of a ``runout run --out``
directory into a typed :class:`~runout.analysis.results.RunResult` (:func:`read_result`), and
the fast CSV column writer the run files use (:func:`write_columns`).

:func:`runout.report.run_files.write_result` writes the directory: ``result.json`` (the JSON
contract), ``history.csv`` (the record), ``lines.csv`` (the labelled lines), the standard
figures and each model's own files and figures. Writing figures belongs to the report layer;
reading needs none, so this module stays below it.
"""

from __future__ import annotations

import io
import sys
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from runout.analysis.results import RunResult
from runout.base.errors import RunoutError
from runout.base.reading import InputFileError, open_regular, read_json

__all__ = [
    "HISTORY_COLUMNS",
    "RESULT_SHAPE",
    "SUMMARY_SHAPE",
    "read_history",
    "read_result",
    "read_result_json",
    "write_columns",
]

#: Header of ``history.csv``: time [s], x, y, z [m]
#: (:data:`runout.analysis.results.DISPLACEMENT_OF`).
HISTORY_COLUMNS = ["time_s", "x_m", "y_m", "z_m"]

_LINE = {
    "direction": "string",
    "frequency_hz": "number",
    "order": "number",
    "pp_m": "number",
    "label": "string",
    "phase_rad": "number",
    "repeatable": "bool",
    "sources": [
        {
            "part": "string",
            "element": "number",
            "lobes": "number",
            "term": "string",
            "formula": "string",
            "share": "number",
        }
    ],
}
_RUNOUT = {k: "number" for k in ("radial_pp_m", "axial_pp_m", "rro_pp_m", "nrro_pp_m")}
_CATALOGUE_KEYS = (
    "elements",
    "element_diameter",
    "pitch_diameter",
    "inner_conformity",
    "outer_conformity",
    "inner_raceway_diameter",
    "outer_raceway_diameter",
    "nominal_contact_angle",
    "dynamic_load_rating",
)
#: ``bearing_source`` ([bearing] designation, :mod:`runout.case.designation`)
_SOURCE: dict[str, Any] = {
    "designation": "string",
    "requested": "string",
    "kind": "string",
    "type": "string",
    "bore_diameter_m": "number",
    "outside_diameter_m": "number",
    "width_m": "number",
    "catalogue": "string",
    "suffix": "string",
    "name": "string",
    "values": {k: "number" for k in _CATALOGUE_KEYS},
    "given_in_case": {k: "number" for k in _CATALOGUE_KEYS},
    "provenance": {k: "string" for k in ("dimensions", *_CATALOGUE_KEYS)},
    "notes": ["string"],
}
#: The shape of ``result.json`` that readers rely on (:func:`runout.base.reading.check_shape`):
#: a value of another type (a string where an object belongs) is refused naming its key, an
#: unknown key is free (the contract is extended, not broken).
RESULT_SHAPE: dict[str, Any] = {
    "model": "string",
    "title": "string",
    "rotating_ring": "string",
    "frequencies_hz": "object",
    "contact_angle_deg": "number",
    "radial_clearance_m": "number",
    "solver_resolution_m": "nonnegative",
    "runout": _RUNOUT,
    "components": [_LINE],
    "notes": ["string"],
    "bearing_source": _SOURCE,
    "bearing_sources": [_SOURCE],
    "displacement_of": "string",
    "mean_displacement_m": ["number"],
    "anderon": {k: "number" for k in "URLMHEA"},
    "attribution": [{k: "scalar" for k in ("part", "factor", "lobes", "formula", "order")}],
    "verdict": {
        "quantity": "string",
        "pass": "bool",
        "limit_m": "number",
        "value_m": "number",
        "limit_um_per_s": "number",
        "value_um_per_s": "number",
    },
    "iso15242": {
        "unit": "string",
        "bands": {
            k: {"rms_um_per_s": "number", "low_hz": "number", "high_hz": "number"}
            for k in ("L", "M", "H")
        },
    },
    "iso492": {"quantity": "string"},
    "natural_frequencies_hz": ["number"],
    "ring_displacement": {"axial_m": "number", "x_m": "number", "y_m": "number"},
    "inner_contact_angle_deg": ["number"],
    "outer_contact_angle_deg": ["number"],
    "stiffness_matrix": {"dofs": ["string"], "matrix": [["number"]]},
    "balls": [{"ball": "scalar"}],
    "bearings": [
        {
            "name": "string",
            "position_m": "number",
            "thrust": "string",
            "contact_angle_deg": "number",
            "preload_n": "number",
            "pressure_centre_m": "number",
            "runout": _RUNOUT,
        }
    ],
    "tilt_pp_rad": {"x": "number", "y": "number"},
    "nose_position_m": "number",
    "tool_point_stiffness_n_per_m": {"x": "number", "y": "number", "z": "number"},
}
#: The shape of a run's ``summary.json`` that the report relies on.
SUMMARY_SHAPE: dict[str, Any] = {
    "title": "string",
    "bearing": {
        "type": "string",
        "elements": "number",
        "element_diameter_m": "length",
        "pitch_diameter_m": "length",
        "radial_clearance_m": "length",
        "inner_conformity": "number",
        "outer_conformity": "number",
    },
    "derived": "object",
    "contact": "object",
    "frequencies_hz": "object",
}

#: Rows formatted per call of :func:`write_columns` (bounds its temporary memory: a few MB).
_CSV_CHUNK = 65536
#: Most values :func:`write_columns` formats in Python when numba is not loaded yet: Python
#: formats about a million values a second, and numba costs about 0.6 s to import and start.
_PYTHON_FORMAT_LIMIT = 1 << 19


def _format_rows_python(block: NDArray[np.float64]) -> bytes:
    """The bytes of :func:`runout.base._csvfmt.format_rows`, formatted by Python.

    Parameters
    ----------
    block : ndarray, shape (rows, columns)
        The values.

    Returns
    -------
    bytes
        ``"".join(",".join("%.12g" % v for v in row) + "\\r\\n" for row in block)``, ASCII.
    """
    row = ",".join(["%.12g"] * block.shape[1]) + "\r\n"
    return "".join([row % values for values in map(tuple, block.tolist())]).encode("ascii")


def write_columns(path: Path, header: list[str], columns: list[NDArray[np.float64]]) -> Path:
    """Write equal-length float columns as CSV, the bytes :mod:`csv` would write, fast.

    The same text as a ``csv.writer`` writing ``f"{v:.12g}"`` for every value (comma
    separated, CRLF line ends, header first), formatted by compiled kernels
    (:func:`runout.base._csvfmt.format_rows`, about ten times faster than Python's formatting,
    which it falls back on for the rare values it cannot prove it rounds the same way); a
    record of at most :data:`_PYTHON_FORMAT_LIMIT` values written before numba is loaded is
    formatted by Python instead. Rows are formatted in chunks, so the text in memory stays
    small.

    Parameters
    ----------
    path : Path
        Output file.
    header : list of str
        Column names (plain names: no comma, quote or line break).
    columns : list of ndarray, each shape (n,)
        The columns [SI units].

    Returns
    -------
    Path
    """
    data = [np.asarray(c, dtype=np.float64).ravel() for c in columns]
    n = data[0].size if data else 0
    if any(c.size != n for c in data):
        raise ValueError(f"columns differ in length: {[c.size for c in data]}")
    if "numba" not in sys.modules and n * len(data) <= _PYTHON_FORMAT_LIMIT:
        # a run that compiled nothing (the linear model): Python formats a short record in
        # less time than numba takes to import and start (~0.6 s), for the same bytes
        format_rows = _format_rows_python
    else:
        from runout.base._csvfmt import format_rows
    with path.open("wb") as fh:
        fh.write((",".join(header) + "\r\n").encode("ascii"))
        for i0 in range(0, n, _CSV_CHUNK):
            fh.write(format_rows(np.column_stack([c[i0 : i0 + _CSV_CHUNK] for c in data])))
    return path


def read_result_json(directory: Path) -> dict[str, Any]:
    """The JSON object of ``directory / "result.json"``.

    Parameters
    ----------
    directory : Path
        A run directory (``runout run --out``).

    Returns
    -------
    dict of str to Any
        The decoded JSON contract (values SI, as written).

    Raises
    ------
    RunoutError
        The file is missing, unreadable, not a regular file inside ``directory``, beyond the
        bounds of :mod:`runout.base.reading`, or not of :data:`RESULT_SHAPE` (naming the key).
    """
    directory = Path(directory)
    path = directory / "result.json"
    loaded = read_json(path, [directory], shape=RESULT_SHAPE)
    if not isinstance(loaded, dict):
        raise RunoutError(f"{path}: expected a JSON object")
    return loaded


def read_history(path: Path) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Time [s] and displacement (3, n) [m] of a ``history.csv``.

    Parameters
    ----------
    path : Path
        The ``history.csv`` file (columns :data:`HISTORY_COLUMNS`).

    Returns
    -------
    time : ndarray, shape (n,)
        Sample times [s].
    displacement : ndarray, shape (3, n)
        Displacement x, y, z [m].

    Raises
    ------
    RunoutError
        The file is missing, has another header, or a value that is not a number.
    """
    path = Path(path)
    try:
        with (
            open_regular(path, [path.parent]) as raw,
            io.TextIOWrapper(raw, encoding="ascii", newline="") as fh,
        ):
            header = fh.readline().strip().split(",")
            if header != HISTORY_COLUMNS:
                raise RunoutError(
                    f"{path}: expected the columns {', '.join(HISTORY_COLUMNS)}, "
                    f"got {', '.join(header)}"
                )
            data = np.loadtxt(fh, delimiter=",", dtype=np.float64, ndmin=2)
    except InputFileError:
        raise
    except (OSError, ValueError, UnicodeDecodeError) as exc:
        raise RunoutError(f"{path}: cannot be read ({exc})") from None
    if data.size == 0:
        data = np.zeros((0, 4))
    return np.ascontiguousarray(data[:, 0]), np.ascontiguousarray(data[:, 1:].T)


def read_result(directory: Path, *, measuring_direction: ArrayLike | None = None) -> RunResult:
    """The result of a ``runout run CASE --out DIR`` directory, without rerunning.

    ``result.json`` gives everything but the record, which ``history.csv`` gives (as written:
    12 significant digits); the measuring direction is ``measuring_direction`` when given,
    else the case's (``case.toml`` in the directory, as
    :func:`runout.models.measuring_direction` sets it for the model), else the one the ISO
    15242 output states. The result plots, summarises and writes like the original (a linear
    result rebuilds its lines from the components; the rigid model's contact table is not
    stored, so its files are not rewritten; the history figure's window may start one
    sample apart where a sample sits on its boundary to round-off).

    Parameters
    ----------
    directory : Path
        A run directory (``runout run --out``, or :meth:`RunResult.write
        <runout.analysis.results.RunResult.write>`, which writes no ``case.toml``).
    measuring_direction : array_like, shape (2,), optional
        Unit vector (x, y) of the radial measuring direction the result was computed along.

    Returns
    -------
    RunResult

    Raises
    ------
    RunoutError
        No readable ``result.json`` or ``history.csv``, or neither the case nor the result
        states the measuring direction of a result with a record.
    """
    import dataclasses

    directory = Path(directory)
    doc = read_result_json(directory)
    history = directory / "history.csv"
    if not history.exists():
        raise RunoutError(f"{history}: missing (the record of the run)")
    time, displacement = read_history(history)
    result = RunResult.from_json(doc, time=time, displacement=displacement)
    direction: NDArray[np.float64] | None
    if measuring_direction is not None:
        direction = np.asarray(measuring_direction, dtype=np.float64)
        if direction.shape != (2,):
            raise ValueError("measuring_direction must be a vector (x, y)")
    else:
        direction = _case_measuring_direction(directory, result.model)
    if direction is None and result.iso15242 is None and time.size >= 2:
        raise RunoutError(
            f"{directory / 'case.toml'}: cannot be read, and the result does not state its "
            "measuring direction (it needs the case's radial load direction: give "
            "measuring_direction=)"
        )
    if direction is not None:
        result = dataclasses.replace(result, measuring_direction=direction)
    return result


def _case_measuring_direction(directory: Path, model: str) -> NDArray[np.float64] | None:
    """The measuring direction of ``model`` on the directory's ``case.toml`` (None when it
    does not load: a profile file it refers to may be missing)."""
    path = directory / "case.toml"
    if not path.exists():
        return None
    from runout.case.model import load_case
    from runout.models import measuring_direction

    try:
        case = load_case(path)
    except (RunoutError, OSError, ValueError):
        return None
    return measuring_direction(case, model)
