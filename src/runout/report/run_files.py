"""The files of a run: what ``runout run --out DIR`` writes (``result.json``, ``history.csv``,
``lines.csv``, the standard figures and each model's own files and figures).

The tables are written by :mod:`runout.io.result_files` (which also reads them back); this
module adds the figures, so it lives with the plots in the report layer.
"""

from __future__ import annotations

import csv
import dataclasses
import json
import math
from collections.abc import Sequence
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import dataclass
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
from runout.report import _plot_style as style
from runout.report import plotting

if TYPE_CHECKING:
    from runout.models.roller_constraint import OrderSweep, Solution
    from runout.report._figure_workers import FigureWorkers

__all__ = ["draw_figure", "model_files", "warm_figures", "write_result"]


def write_result(
    result: RunResult,
    directory: Path,
    *,
    history_revolutions: float = 3.0,
    workers: FigureWorkers | None = None,
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
    workers : FigureWorkers, optional
        Processes that draw the figures while this one writes the tables (``runout run
        --out`` starts them before the model runs); by default the figures are drawn here.
        The files are the same either way.

    Returns
    -------
    list of Path
        The files written.
    """
    figures = [
        *plotting.standard_figure_names(result, history_revolutions),
        *_model_figure_names(result),
    ]
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / "result.json"
    history = directory / "history.csv"
    # the record's CSV is formatted by compiled code that releases the GIL: written on a
    # second thread while the figures are drawn (a record of 2^20 instants: 0.3 s each); so
    # is the rigid model's order sweep (about a hundred solves), started first: the longest
    pool = ThreadPoolExecutor(2, thread_name_prefix="runout-files")
    solution = _roller_solution(result)
    sweep = None if solution is None else pool.submit(_order_sweep, solution)
    pending: list[Future[Path]] = []
    tables: list[Path] = []

    def write_tables() -> list[tuple[str, Any]]:
        """The files of this process, and the figures that need what they computed.

        Run once the drawing processes have their figures: the JSON and the tables are
        written while they draw, not before they start.
        """
        path.write_text(json.dumps(result.to_json(), indent=2, allow_nan=False) + "\n")
        pending.append(
            pool.submit(
                write_columns, history, HISTORY_COLUMNS, [result.time, *result.displacement]
            )
        )
        tables.append(_write_lines(result, directory))
        written, swept = _model_tables(result, directory, sweep)
        tables.extend(written)
        data = None if swept is None else _SweepFigure.of(swept)
        return [(name, data) for name in figures if name in _AFTER_TABLES]

    try:
        linear = _linear_inputs(result) if plotting.LINEAR_FIGURES[0] in figures else None
        extras: dict[str, Any] = {name: history_revolutions for name in plotting.STANDARD_FIGURES}
        extras.update({name: linear for name in plotting.LINEAR_FIGURES})
        if solution is not None:
            extras.update(dict.fromkeys(_ROLLER_FIGURES[:2], _RollerFigure.of(solution)))
        first = [(name, extras.get(name)) for name in _longest_first(figures)]
        if workers is None:
            drawn = {name: draw_figure(result, directory, name, extra) for name, extra in first}
            drawn.update(
                {name: draw_figure(result, directory, name, x) for name, x in write_tables()}
            )
        else:
            # the processes draw from arrays: without the solution, whose types would make
            # each of them import the compiled solver (Numba: 0.2 s of CPU) to unpickle it
            sent = _without_solution(result)
            drawn = workers.draw(draw_figure, sent, directory, first, later=write_tables)
    finally:
        pool.shutdown(wait=True)
    for written in pending:
        written.result()  # its error, if any (disk full), is this call's
    standard = [drawn[n] for n in figures if n in plotting.STANDARD_FIGURES]
    own = [drawn[n] for n in figures if n not in plotting.STANDARD_FIGURES]
    signal = []
    if result.signal is not None and result.signal.time.size:
        # the acceleration record, in the columns `runout diagnose --record --envelope` reads
        sig = result.signal
        signal.append(
            write_columns(
                directory / "signal.csv",
                SIGNAL_COLUMNS,
                [sig.time, sig.acceleration, sig.rev],
            )
        )
    return [path, history, tables[0], *standard, *tables[1:], *own, *signal]


#: Columns of ``signal.csv`` (``[analysis] signal = "acceleration"``): time, housing
#: acceleration, revolutions of the rotating ring (a tachometer).
SIGNAL_COLUMNS = ["time_s", "a_m_per_s2", "rev"]

#: What drawing each figure costs, relative to the time history (CPU of one process drawing
#: the examples' figures, 2026-11-29: a history about 0.09 s, the 608's lines 0.16-0.2 s); a
#: figure not named costs 1. The figures are queued longest first, so that two drawing
#: processes end together rather than one drawing a long figure last (the
#: longest-processing-time rule).
_FIGURE_COST = {
    "bearing.gif": 2.4,
    "lines.png": 1.9,
    "anderon_spectrum.png": 1.9,
    "spectrum.png": 1.6,
    "balls.png": 1.6,
    "order_sweep.png": 1.6,
    "anderon_bands.png": 1.4,
    "contact_pattern.png": 1.2,
    "orbit.png": 1.2,
    "displacement.png": 1.1,
    "history.png": 1.0,
    "density_waveform.png": 0.95,
}


def _longest_first(figures: Sequence[str]) -> list[str]:
    """``figures`` drawn before the tables, longest first (:data:`_FIGURE_COST`)."""
    chosen = [name for name in figures if name not in _AFTER_TABLES]
    return sorted(chosen, key=lambda name: -_FIGURE_COST.get(name, 1.0))


#: Figures drawn from what the tables computed (the rigid model's order sweep).
_AFTER_TABLES = frozenset({"order_sweep.png"})


def _write_lines(result: RunResult, directory: Path) -> Path:
    """``lines.csv``: every line of the result (:func:`write_result`)."""
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
    return path


def draw_figure(result: RunResult, directory: Path, name: str, extra: Any = None) -> Path:
    """Draw one figure of ``result`` (a standard figure or the model's own) into ``directory``.

    Parameters
    ----------
    result : RunResult
        The result.
    directory : Path
        Existing output directory.
    name : str
        File name: one of :data:`runout.report.plotting.STANDARD_FIGURES` or of the model's
        figures.
    extra : object
        The history's revolutions for ``history.png`` (a float; each standard figure takes
        it), the order sweep for ``order_sweep.png``, the inputs of the linear model's
        figures (computed from ``result`` when None), else None.

    Returns
    -------
    Path
        ``directory / name``.
    """
    if name in plotting.STANDARD_FIGURES:
        return plotting.write_figure(result, directory, name, history_revolutions=float(extra))
    details = result.details
    if name in plotting.LINEAR_FIGURES:
        inputs = _linear_inputs(result) if extra is None else extra
        (path,) = plotting.plot_linear_figures(directory, **inputs, names=[name])
        return path
    if name == "bearing.gif" and isinstance(details, QuasiStaticDetails):
        return plotting.animate_bearing(
            result, directory / "bearing.gif", n_elements=details.n_elements
        )
    if name == "balls.png" and isinstance(details, EquilibriumDetails):
        return _balls_figure(result, details, directory)
    if name == "spectrum.png" and isinstance(details, DynamicDetails):
        (path,) = plotting.plot_dynamic_figures(result, directory)
        return path
    if isinstance(details, RollerDetails) and name in _ROLLER_FIGURES:
        solution = _roller_solution(result) if extra is None else None
        if solution is not None and name != "order_sweep.png":
            extra = _RollerFigure.of(solution)
        return _roller_figure(directory, name, extra)
    raise ValueError(f"a {result.model} result has no figure {name!r}")


def warm_figures() -> None:
    """Import and initialise what drawing a figure needs: a drawing process's start.

    matplotlib, Pillow's drawing and its image plugins (loaded at the first save), NumPy's
    FFT (the dynamic model's spectrum), the font and the mathtext parser of log axes (built
    at the first text drawn: 0.1-0.2 s): done once, before the processes that draw are
    forked from the one that does this (:mod:`runout.report._figure_workers`).
    """
    import io

    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    import numpy.fft  # noqa: F401
    from PIL import ImageDraw  # noqa: F401

    with matplotlib.rc_context(style.RC):  # type: ignore[arg-type]
        fig = plt.figure(figsize=(1, 1))
        fig.text(0.5, 0.5, "0.5 µm [-]")
        fig.text(0.5, 0.2, r"$\mathdefault{10^{-1}}$", rotation=90)
        fig.savefig(io.BytesIO(), format="png", pil_kwargs={"compress_level": 1})
        plt.close(fig)


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
    tables, swept = _model_tables(result, directory, sweep)
    sweep_data = None if swept is None else _SweepFigure.of(swept)
    figures = [
        draw_figure(result, directory, name, sweep_data if name in _AFTER_TABLES else None)
        for name in _model_figure_names(result)
    ]
    return [*tables, *figures]


#: The rigid model's figures, in the order written.
_ROLLER_FIGURES = ("displacement.png", "contact_pattern.png", "order_sweep.png")


def _model_figure_names(result: RunResult) -> list[str]:
    """The file names of the model's own figures of ``result`` (:func:`draw_figure`)."""
    details = result.details
    if isinstance(result, LinearResult):
        lines = result.spectral_lines
        return [] if lines is None or not len(lines) else list(plotting.LINEAR_FIGURES)
    if isinstance(details, QuasiStaticDetails):
        return ["bearing.gif"]
    if isinstance(details, EquilibriumDetails):
        return ["balls.png"]
    if isinstance(details, DynamicDetails):
        return ["spectrum.png"]
    return [] if _roller_solution(result) is None else list(_ROLLER_FIGURES)


def _model_tables(
    result: RunResult, directory: Path, sweep: Future[OrderSweep] | None
) -> tuple[list[Path], OrderSweep | None]:
    """The model's own tables of ``result``, and the order sweep (rigid model; else None)."""
    details = result.details
    if isinstance(result, LinearResult) or isinstance(details, QuasiStaticDetails):
        return [], None
    if isinstance(details, EquilibriumDetails):
        return _equilibrium_tables(details, directory), None
    if isinstance(details, DynamicDetails):
        return [_dynamic_table(result, details, directory)], None
    solution = _roller_solution(result)
    if solution is None:
        return [], None
    return _roller_tables(solution, directory, sweep)


def _linear_inputs(result: Any) -> dict[str, Any]:
    """What the linear model's figures draw (:func:`plotting.plot_linear_figures`' inputs).

    Computed by the process that ran the model (which has imported what computing them
    needs) and sent with each linear figure to the process that draws it.
    """
    theta, v = result.density_waveform()
    orders, rms = result.line_anderon_spectrum()
    return {
        "title": result.title or result.model,
        "revolutions": theta / (2.0 * math.pi),
        "density_um_per_rad": v * 1e6,
        "orders": orders,
        "line_rms_uin_per_rad": rms,
        "bands": {b.name: (b.low, b.high) for b in ANDERON_BANDS.bands},
        "band_values": {
            "exact lines": result.anderon_lines().as_dict(),
            "6-rev DFT": result.anderon_dft().as_dict(),
        },
    }


def _balls_figure(result: RunResult, details: EquilibriumDetails, directory: Path) -> Path:
    """``balls.png`` of the equilibrium model: each ball's loads and contact angles."""
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
    return plotting.save_figure(ax, directory / "balls.png")


def _equilibrium_tables(details: EquilibriumDetails, directory: Path) -> list[Path]:
    """``balls.csv``, ``stiffness.csv`` and, with ``[analysis] bearing_damping``, ``damping.csv``
    of the equilibrium model."""
    table = details.balls
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
    damping = details.bearing_damping
    if damping is None:  # [analysis] bearing_damping unset or "none": stiffness only
        return [path, kpath]
    # c = β K over the whole 5×5, as the JSON's cxx ... czz are β times its entries
    cpath = directory / "damping.csv"
    beta = damping.coefficient_s
    with cpath.open("w", newline="") as fh:
        fh.write(
            f"# damping c = beta K [N s/m, N s/rad, N m s/m, N m s/rad]: bearing_damping = "
            f"{damping.model}, beta = {beta:.6g} s\n"
        )
        w3 = csv.writer(fh)
        w3.writerow(["", *dofs])
        for name, krow in zip(dofs, details.stiffness_matrix.matrix, strict=True):
            w3.writerow([name, *(f"{beta * v:.12g}" for v in krow)])
    return [path, kpath, cpath]


def _dynamic_table(result: RunResult, details: DynamicDetails, directory: Path) -> Path:
    """``spectrum.csv`` (p-p of x, y, z per frequency) of a dynamic run."""
    rate = details.sample_rate_hz
    if rate is None:  # read back: the record's spacing
        rate = 1.0 / float(result.time[1] - result.time[0])
    spectrum_csv = directory / "spectrum.csv"
    spec = amplitude_spectrum(result.displacement, sample_rate=rate)
    rows = np.column_stack([spec.frequencies, 2.0 * spec.amplitude.T])
    header = "frequency_hz,x_pp_m,y_pp_m,z_pp_m"
    np.savetxt(spectrum_csv, rows, delimiter=",", header=header, comments="", fmt="%.10g")
    return spectrum_csv


def _order_sweep(sol: Solution) -> OrderSweep:
    """The order sweep of the rigid model's files (:func:`_roller_tables`).

    One revolution of the turning ring at the run's angular step (at most 720 angles) and
    1 µm on each part, orders 2 … 3Z.
    """
    from runout.models.roller_constraint import order_sweep, rotation_angles

    step = float(np.median(np.diff(sol.alpha))) if sol.alpha.size > 1 else math.radians(0.25)
    n1 = int(min(720, max(64, round(2.0 * math.pi / step)))) + 1
    return order_sweep(sol.geometry, rotation_angles(1.0, n1))


def _roller_tables(
    sol: Solution, directory: Path, sweep: Future[OrderSweep] | None = None
) -> tuple[list[Path], OrderSweep]:
    """``contacts.csv`` and ``order_sweep.csv`` of the rigid model, and the sweep.

    The order sweep is :func:`_order_sweep`'s, computed here unless ``sweep`` is already
    computing it (on another thread, while the figures are drawn).
    """
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / "contacts.csv"
    z = sol.geometry.n_elements
    header = ["angle_deg", "radial_m", "horizontal_m", "roller_a", "roller_b", "lambda_a",
              "lambda_b", *(f"gap_{j + 1}_m" for j in range(z))]  # fmt: skip
    table = np.column_stack(
        [
            np.degrees(sol.alpha),
            sol.radial,
            sol.horizontal,
            sol.pair[:, 0] + 1,
            sol.pair[:, 1] + 1,
            sol.multipliers,
            sol.gaps,
        ]
    )
    # "%.6g" % v is f"{v:.6g}": the bytes a csv.writer of those strings writes (CRLF), one
    # %-format per row instead of one f-string per cell
    formats = ["%.6g", "%.12g", "%.12g", "%d", "%d", "%.6g", "%.6g", *["%.6g"] * z]
    with path.open("w", newline="") as fh:
        fh.write(",".join(header) + "\r\n")
        np.savetxt(fh, table, fmt=formats, delimiter=",", newline="\r\n")
    swept = _order_sweep(sol) if sweep is None else sweep.result()
    return [path, _write_order_sweep(swept, directory / "order_sweep.csv")], swept


@dataclass(frozen=True)
class _RollerFigure:
    """What the rigid model's position figures draw, as plain arrays (a figure process needs
    neither the solution's types nor the compiled solver they import)."""

    angle_deg: NDArray[np.float64]
    radial: NDArray[np.float64]
    horizontal: NDArray[np.float64]
    touching: NDArray[np.bool_]
    pair: NDArray[np.int64]

    @classmethod
    def of(cls, sol: Solution) -> _RollerFigure:
        return cls(np.degrees(sol.alpha), sol.radial, sol.horizontal, sol.touching, sol.pair)


@dataclass(frozen=True)
class _SweepFigure:
    """What ``order_sweep.png`` draws: the order sweep's table, as plain arrays."""

    orders: NDArray[np.int64]
    runout: NDArray[np.float64]
    parts: tuple[str, ...]
    baseline: float
    n_elements: int
    solved: NDArray[np.bool_]

    @classmethod
    def of(cls, swept: OrderSweep) -> _SweepFigure:
        return cls(
            swept.orders, swept.runout, swept.parts, swept.baseline, swept.n_elements, swept.solved
        )


def _without_solution(result: RunResult) -> RunResult:
    """``result`` without the rigid model's solution (what the figure processes receive)."""
    details = result.details
    if not isinstance(details, RollerDetails) or details.solution is None:
        return result
    return dataclasses.replace(result, details=dataclasses.replace(details, solution=None))


def _roller_figure(directory: Path, name: str, data: Any) -> Path:
    """One of the rigid model's figures (:data:`_ROLLER_FIGURES`) from its data: the
    positions (:class:`_RollerFigure`), or for ``order_sweep.png`` the sweep
    (:class:`_SweepFigure`)."""
    if name == "order_sweep.png":
        if not isinstance(data, _SweepFigure):
            raise ValueError("order_sweep.png is drawn from the order sweep, none was given")
        ax = plotting.plot_order_sweep(
            data.orders, data.runout, data.parts, data.baseline, data.n_elements,
            solved=data.solved,
        )  # fmt: skip
    elif not isinstance(data, _RollerFigure):
        raise ValueError(f"{name} is drawn from the rigid model's solution, none was given")
    elif name == "displacement.png":
        ax = plotting.plot_constraint_displacement(data.angle_deg, data.radial, data.horizontal)
    else:
        ax = plotting.plot_contact_pattern(data.angle_deg, data.touching, data.pair)
    return plotting.save_figure(ax, directory / name)


def _write_order_sweep(sweep: OrderSweep, path: Path) -> Path:
    """``order_sweep.csv``: the sweep's table (its header states the amplitude and baseline)."""
    with path.open("w", newline="") as fh:
        fh.write(
            f"# radial runout p-p [m] with one harmonic of {sweep.amplitude:.6g} m "
            f"(zero-to-peak) on one part; perfect bearing: {sweep.baseline:.6g} m; "
            f"Z = {sweep.n_elements}; an empty cell: that harmonic jams the rollers (no stable "
            "position) or makes its part non-convex (outside the rigid model)\n"
        )
        w = csv.writer(fh)
        w.writerow(["order", "order_over_z", *(f"{p}_pp_m" for p in sweep.parts)])
        for row in sweep.rows():
            w.writerow([f"{v:.10g}" if isinstance(v, float) else v for v in row.values()])
    return path


# --------------------------------------------------------------------------------------------
# reading a run directory back
# --------------------------------------------------------------------------------------------
