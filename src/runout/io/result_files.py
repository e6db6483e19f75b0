"""The files of a run: what ``runout run --out DIR`` writes, and reading them back.

:func:`write_result` writes ``result.json`` (the JSON contract), ``history.csv`` (the record),
``lines.csv`` (the labelled lines), the standard figures (:func:`runout.report.plotting.write_figures`)
and each model's own files, chosen by the type of the result's details
(:mod:`runout.analysis.result_details`): ``bearing.gif`` (quasi-static models), ``balls.csv``,
``stiffness.csv`` and ``balls.png`` (equilibrium), ``spectrum.csv`` and ``spectrum.png``
(dynamic), ``contacts.csv``, ``order_sweep.csv`` and its figures (rigid constraint model) and
the Anderon figures (linear). :func:`read_result` reads ``result.json`` and ``history.csv`` of
such a directory back into a :class:`~runout.analysis.results.RunResult`.
"""

from __future__ import annotations

import csv
import json
import math
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from runout.analysis.result_details import (
    DynamicDetails,
    EquilibriumDetails,
    QuasiStaticDetails,
    RollerDetails,
)
from runout.analysis.results import RunResult
from runout.base.errors import RunoutError

if TYPE_CHECKING:
    from runout.models.roller_constraint import OrderSweep, Solution

__all__ = ["HISTORY_COLUMNS", "model_files", "read_result", "write_columns", "write_result"]

#: Header of ``history.csv``: time [s], x, y, z [m] (:data:`runout.analysis.results.DISPLACEMENT_OF`).
HISTORY_COLUMNS = ["time_s", "x_m", "y_m", "z_m"]

#: Rows formatted per call of :func:`write_columns` (bounds its temporary memory: a few MB).
_CSV_CHUNK = 65536


def write_columns(path: Path, header: list[str], columns: list[NDArray[np.float64]]) -> Path:
    """Write equal-length float columns as CSV, the bytes :mod:`csv` would write, fast.

    The same text as a ``csv.writer`` writing ``f"{v:.12g}"`` for every value (comma
    separated, CRLF line ends, header first), formatted by compiled kernels
    (:func:`runout.base.csvfmt.format_rows`, about ten times faster than Python's formatting,
    which it falls back on for the rare values it cannot prove it rounds the same way).
    Rows are formatted in chunks, so the text in memory stays small.

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
    from runout.base.csvfmt import format_rows

    data = [np.asarray(c, dtype=np.float64).ravel() for c in columns]
    n = data[0].size if data else 0
    if any(c.size != n for c in data):
        raise ValueError(f"columns differ in length: {[c.size for c in data]}")
    with path.open("wb") as fh:
        fh.write((",".join(header) + "\r\n").encode("ascii"))
        for i0 in range(0, n, _CSV_CHUNK):
            fh.write(format_rows(np.column_stack([c[i0 : i0 + _CSV_CHUNK] for c in data])))
    return path


def write_result(
    result: RunResult, directory: Path, *, history_revolutions: float = 3.0
) -> list[Path]:
    """Write ``result.json``, ``history.csv``, ``lines.csv``, the figures and the model's files.

    Parameters
    ----------
    result : RunResult
        The result.
    directory : Path
        Output directory (created).
    history_revolutions : float
        Revolutions of the rotating ring the time-history figure shows (the last ones).

    Returns
    -------
    list of Path
        The files written.
    """
    directory.mkdir(parents=True, exist_ok=True)
    written: list[Path] = []
    path = directory / "result.json"
    path.write_text(json.dumps(result.to_json(), indent=2, allow_nan=False) + "\n")
    written.append(path)
    # the record's CSV is formatted by compiled code that releases the GIL: written on a
    # second thread while the figures are drawn (a record of 2^20 instants: 0.3 s each)
    history = directory / "history.csv"
    pool = ThreadPoolExecutor(1, thread_name_prefix="runout-csv")
    pending = pool.submit(
        write_columns, history, HISTORY_COLUMNS, [result.time, *result.displacement]
    )
    try:
        written += _write_rest(result, directory, history_revolutions)
    finally:
        pool.shutdown(wait=True)
    pending.result()  # its error, if any (disk full), is this call's
    return [written[0], history, *written[1:]]


def _write_rest(result: RunResult, directory: Path, history_revolutions: float) -> list[Path]:
    """``lines.csv``, the figures and the model's own files (:func:`write_result`)."""
    written: list[Path] = []
    path = directory / "lines.csv"
    with path.open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["direction", "frequency_hz", "order", "pp_m", "phase_rad", "label"])
        for c in result.lines():
            w.writerow(
                [
                    c.direction,
                    f"{c.frequency_hz:.12g}",
                    f"{c.order:.12g}",
                    f"{c.pp_m:.6g}",
                    f"{c.phase_rad:.6g}",
                    c.label,
                ]
            )
    written.append(path)
    from runout.report import plotting

    written += plotting.write_figures(result, directory, history_revolutions=history_revolutions)
    written += model_files(result, directory)
    return written


def model_files(result: RunResult, directory: Path) -> list[Path]:
    """Write the model's own files of ``result`` into ``directory`` (existing).

    Chosen by the type of ``result.details``; a result read back from its JSON writes those
    its JSON and record suffice for (the rigid model's contact table needs the run's
    solution, which is not stored).

    Returns
    -------
    list of Path
        The files written.
    """
    from runout.models.linear import LinearResult

    details = result.details
    if isinstance(result, LinearResult):
        return _linear_files(result, directory)
    if isinstance(details, QuasiStaticDetails):
        from runout.report import plotting

        return [
            plotting.animate_bearing(
                result, directory / "bearing.gif", n_elements=details.n_elements
            )
        ]
    if isinstance(details, EquilibriumDetails):
        return _equilibrium_files(result, details, directory)
    if isinstance(details, DynamicDetails):
        return _dynamic_files(result, details, directory)
    if isinstance(details, RollerDetails) and details.solution is not None:
        return _roller_files(details.solution, directory)
    return []


def _linear_files(result: Any, directory: Path) -> list[Path]:
    """The linear model's waveform, spectrum and band plots."""
    from runout.analysis.spectrum import ANDERON_BANDS
    from runout.report import plotting

    if result.spectral_lines is None or not len(result.spectral_lines):
        return []
    theta, v = result.density_waveform()
    orders, rms = result.line_anderon_spectrum()
    return list(
        plotting.plot_linear_figures(
            directory,
            title=result.title or result.model,
            revolutions=theta / (2.0 * math.pi),
            density_um_per_rad=v * 1e6,
            orders=orders,
            line_rms_uin_per_rad=rms,
            bands={b.name: (b.low, b.high) for b in ANDERON_BANDS.bands},
            band_values={
                "exact lines": result.anderon_lines().as_dict(),
                "6-rev DFT": result.anderon_dft().as_dict(),
            },
        )
    )


def _equilibrium_files(
    result: RunResult, details: EquilibriumDetails, directory: Path
) -> list[Path]:
    """``balls.csv``, ``stiffness.csv`` and ``balls.png`` of the equilibrium model."""
    from runout.report import plotting

    table = details.balls

    def column(key: str) -> NDArray[np.float64]:
        return np.array([float(row[key]) for row in table])

    ax = plotting.plot_ball_loads(
        column("azimuth_deg"),
        column("inner_load_n"),
        column("outer_load_n"),
        column("inner_contact_angle_deg"),
        column("outer_contact_angle_deg"),
        result.title,
    )
    png = plotting.save_figure(ax, directory / "balls.png")
    path = directory / "balls.csv"
    with path.open("w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(table[0]))
        w.writeheader()
        for row in table:
            w.writerow({k: f"{v:.12g}" for k, v in row.items()})
    kpath = directory / "stiffness.csv"
    dofs = details.stiffness_matrix.dofs
    with kpath.open("w", newline="") as fh:
        w2 = csv.writer(fh)
        w2.writerow(["", *dofs])
        for name, krow in zip(dofs, details.stiffness_matrix.matrix, strict=True):
            w2.writerow([name, *(f"{v:.12g}" for v in krow)])
    return [path, kpath, png]


def _dynamic_files(result: RunResult, details: DynamicDetails, directory: Path) -> list[Path]:
    """``spectrum.csv`` (p-p of x, y, z per frequency) and ``spectrum.png`` of a dynamic run."""
    from runout.analysis.spectrum import amplitude_spectrum
    from runout.report import plotting

    rate = details.sample_rate_hz
    if rate is None:  # read back: the record's spacing
        rate = 1.0 / float(result.time[1] - result.time[0])
    spectrum_csv = directory / "spectrum.csv"
    spec = amplitude_spectrum(result.displacement, sample_rate=rate)
    rows = np.column_stack([spec.frequencies, 2.0 * spec.amplitude.T])
    header = "frequency_hz,x_pp_m,y_pp_m,z_pp_m"
    np.savetxt(spectrum_csv, rows, delimiter=",", header=header, comments="", fmt="%.10g")
    return [spectrum_csv, *plotting.plot_dynamic_figures(result, directory)]


def _roller_files(sol: Solution, directory: Path) -> list[Path]:
    """``contacts.csv``, ``order_sweep.csv`` and the rigid model's plots.

    The order sweep uses one revolution of the turning ring at the run's angular step (at most
    720 angles) and 1 µm on each part, orders 2 … 3Z.
    """
    from runout.models.roller_constraint import order_sweep, rotation_angles
    from runout.report import plotting

    directory.mkdir(parents=True, exist_ok=True)
    written: list[Path] = []
    path = directory / "contacts.csv"
    z = sol.geometry.n_elements
    with path.open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(
            ["angle_deg", "radial_m", "horizontal_m", "roller_a", "roller_b", "lambda_a",
             "lambda_b", *(f"gap_{j + 1}_m" for j in range(z))]
        )  # fmt: skip
        for i in range(sol.alpha.size):
            w.writerow(
                [
                    f"{math.degrees(sol.alpha[i]):.6g}",
                    f"{sol.radial[i]:.12g}",
                    f"{sol.horizontal[i]:.12g}",
                    int(sol.pair[i, 0]) + 1,
                    int(sol.pair[i, 1]) + 1,
                    f"{sol.multipliers[i, 0]:.6g}",
                    f"{sol.multipliers[i, 1]:.6g}",
                    *(f"{g:.6g}" for g in sol.gaps[i]),
                ]
            )
    written.append(path)
    step = float(np.median(np.diff(sol.alpha))) if sol.alpha.size > 1 else math.radians(0.25)
    n1 = int(min(720, max(64, round(2.0 * math.pi / step)))) + 1
    sweep = order_sweep(sol.geometry, rotation_angles(1.0, n1))
    written.append(_write_order_sweep(sweep, directory / "order_sweep.csv"))
    angle_deg = np.degrees(sol.alpha)
    written.append(
        plotting.save_figure(
            plotting.plot_constraint_displacement(angle_deg, sol.radial, sol.horizontal),
            directory / "displacement.png",
        )
    )
    written.append(
        plotting.save_figure(
            plotting.plot_contact_pattern(angle_deg, sol.touching, sol.pair),
            directory / "contact_pattern.png",
        )
    )
    written.append(
        plotting.save_figure(
            plotting.plot_order_sweep(
                sweep.orders, sweep.runout, sweep.parts, sweep.baseline, sweep.n_elements
            ),
            directory / "order_sweep.png",
        )
    )
    return written


def _write_order_sweep(sweep: OrderSweep, path: Path) -> Path:
    """``order_sweep.csv``: the sweep's table (its header states the amplitude and baseline)."""
    with path.open("w", newline="") as fh:
        fh.write(
            f"# radial runout p-p [m] with one harmonic of {sweep.amplitude:.6g} m "
            f"(zero-to-peak) on one part; perfect bearing: {sweep.baseline:.6g} m; "
            f"Z = {sweep.n_elements}\n"
        )
        w = csv.writer(fh)
        w.writerow(["order", "order_over_z", *(f"{p}_pp_m" for p in sweep.parts)])
        for row in sweep.rows():
            w.writerow([f"{v:.10g}" if isinstance(v, float) else v for v in row.values()])
    return path


# --------------------------------------------------------------------------------------------
# reading a run directory back
# --------------------------------------------------------------------------------------------
def read_result_json(directory: Path) -> dict[str, Any]:
    """The JSON object of ``directory / "result.json"``.

    Raises
    ------
    RunoutError
        The file is missing, unreadable or not a JSON object.
    """
    path = Path(directory) / "result.json"
    try:
        loaded = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, json.JSONDecodeError) as exc:
        raise RunoutError(f"{path}: cannot be read as JSON ({exc})") from None
    if not isinstance(loaded, dict):
        raise RunoutError(f"{path}: expected a JSON object")
    return loaded


def read_history(path: Path) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Time [s] and displacement (3, n) [m] of a ``history.csv``.

    Raises
    ------
    RunoutError
        The file is missing, has another header, or a value that is not a number.
    """
    try:
        with Path(path).open(encoding="ascii", newline="") as fh:
            header = fh.readline().strip().split(",")
            if header != HISTORY_COLUMNS:
                raise RunoutError(
                    f"{path}: expected the columns {', '.join(HISTORY_COLUMNS)}, "
                    f"got {', '.join(header)}"
                )
            data = np.loadtxt(fh, delimiter=",", dtype=np.float64, ndmin=2)
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
