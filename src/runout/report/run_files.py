"""The files of a run: what ``runout run --out DIR`` writes (``result.json``, ``history.csv``,
``lines.csv``, the standard figures and each model's own files and figures).

The tables are written by :mod:`runout.io.result_files` (which also reads them back); this
module adds the figures, so it lives with the plots in the report layer.
"""

from __future__ import annotations

import csv
import json
import math
from concurrent.futures import Future, ThreadPoolExecutor
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from runout.analysis.result_details import (
    DynamicDetails,
    EquilibriumDetails,
    QuasiStaticDetails,
    RollerDetails,
)
from runout.analysis.results import RunResult
from runout.analysis.spectrum import ANDERON_BANDS, amplitude_spectrum
from runout.io.result_files import HISTORY_COLUMNS, write_columns
from runout.models.linear import LinearResult
from runout.report import plotting

if TYPE_CHECKING:
    from runout.models.roller_constraint import OrderSweep, Solution

__all__ = ["model_files", "write_result"]


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
    # second thread while the figures are drawn (a record of 2^20 instants: 0.3 s each); so
    # is the rigid model's order sweep (about a hundred solves, 1.5 s on two cores)
    history = directory / "history.csv"
    pool = ThreadPoolExecutor(2, thread_name_prefix="runout-files")
    pending = pool.submit(
        write_columns, history, HISTORY_COLUMNS, [result.time, *result.displacement]
    )
    solution = _roller_solution(result)
    sweep = None if solution is None else pool.submit(_order_sweep, solution)
    try:
        written += _write_rest(result, directory, history_revolutions, sweep)
    finally:
        pool.shutdown(wait=True)
    pending.result()  # its error, if any (disk full), is this call's
    return [written[0], history, *written[1:]]


def _write_rest(
    result: RunResult,
    directory: Path,
    history_revolutions: float,
    sweep: Future[OrderSweep] | None,
) -> list[Path]:
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
    written += plotting.write_figures(result, directory, history_revolutions=history_revolutions)
    written += _model_files(result, directory, sweep)
    return written


def _roller_solution(result: RunResult) -> Solution | None:
    """The rigid model's solution held by ``result`` (None for another model or read back)."""
    if not isinstance(result.details, RollerDetails):
        return None
    # imported here: the roller kernels (and numba) are for roller results alone
    from runout.models.roller_constraint import Solution

    solution = result.details.solution
    return solution if isinstance(solution, Solution) else None


def model_files(result: RunResult, directory: Path) -> list[Path]:
    """Write the model's own files of ``result`` into ``directory`` (existing).

    Chosen by the type of ``result.details``; a result read back from its JSON writes those
    its JSON and record suffice for (the rigid model's contact table needs the run's
    solution, which is not stored).

    Parameters
    ----------
    result : RunResult
        The result.
    directory : Path
        Existing output directory.

    Returns
    -------
    list of Path
        The files written.
    """
    return _model_files(result, directory, None)


def _model_files(
    result: RunResult, directory: Path, sweep: Future[OrderSweep] | None
) -> list[Path]:
    """:func:`model_files`, with the rigid model's order sweep already under way (or None)."""
    details = result.details
    if isinstance(result, LinearResult):
        return _linear_files(result, directory)
    if isinstance(details, QuasiStaticDetails):
        return [
            plotting.animate_bearing(
                result, directory / "bearing.gif", n_elements=details.n_elements
            )
        ]
    if isinstance(details, EquilibriumDetails):
        return _equilibrium_files(result, details, directory)
    if isinstance(details, DynamicDetails):
        return _dynamic_files(result, details, directory)
    solution = _roller_solution(result)
    if solution is not None:
        return _roller_files(solution, directory, sweep)
    return []


def _linear_files(result: Any, directory: Path) -> list[Path]:
    """The linear model's waveform, spectrum and band plots."""
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
    rate = details.sample_rate_hz
    if rate is None:  # read back: the record's spacing
        rate = 1.0 / float(result.time[1] - result.time[0])
    spectrum_csv = directory / "spectrum.csv"
    spec = amplitude_spectrum(result.displacement, sample_rate=rate)
    rows = np.column_stack([spec.frequencies, 2.0 * spec.amplitude.T])
    header = "frequency_hz,x_pp_m,y_pp_m,z_pp_m"
    np.savetxt(spectrum_csv, rows, delimiter=",", header=header, comments="", fmt="%.10g")
    return [spectrum_csv, *plotting.plot_dynamic_figures(result, directory)]


def _order_sweep(sol: Solution) -> OrderSweep:
    """The order sweep of the rigid model's files (:func:`_roller_files`).

    One revolution of the turning ring at the run's angular step (at most 720 angles) and
    1 µm on each part, orders 2 … 3Z.
    """
    from runout.models.roller_constraint import order_sweep, rotation_angles

    step = float(np.median(np.diff(sol.alpha))) if sol.alpha.size > 1 else math.radians(0.25)
    n1 = int(min(720, max(64, round(2.0 * math.pi / step)))) + 1
    return order_sweep(sol.geometry, rotation_angles(1.0, n1))


def _roller_files(
    sol: Solution, directory: Path, sweep: Future[OrderSweep] | None = None
) -> list[Path]:
    """``contacts.csv``, ``order_sweep.csv`` and the rigid model's plots.

    The order sweep is :func:`_order_sweep`'s, computed here unless ``sweep`` is already
    computing it (on another thread, while the standard figures are drawn).
    """
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
    swept = _order_sweep(sol) if sweep is None else sweep.result()
    written.append(_write_order_sweep(swept, directory / "order_sweep.csv"))
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
                swept.orders,
                swept.runout,
                swept.parts,
                swept.baseline,
                swept.n_elements,
                solved=swept.solved,
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
            f"Z = {sweep.n_elements}; an empty cell: that harmonic jams the rollers (no stable "
            "position)\n"
        )
        w = csv.writer(fh)
        w.writerow(["order", "order_over_z", *(f"{p}_pp_m" for p in sweep.parts)])
        for row in sweep.rows():
            w.writerow([f"{v:.10g}" if isinstance(v, float) else v for v in row.values()])
    return path


# --------------------------------------------------------------------------------------------
# reading a run directory back
# --------------------------------------------------------------------------------------------
