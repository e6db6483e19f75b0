"""Plots: the only module that imports matplotlib (lazily, Agg backend).

Every function takes result data and a directory or an Axes and returns what it drew; no
numerics happen here.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from runout.results import RunResult

__all__ = [
    "plot_anderon_spectrum",
    "plot_band_values",
    "plot_constraint_displacement",
    "plot_contact_pattern",
    "plot_density_waveform",
    "plot_linear_figures",
    "plot_lines",
    "plot_orbit",
    "plot_order_sweep",
    "plot_result",
    "plot_time_history",
    "pyplot",
    "save_figure",
]


def pyplot() -> Any:
    """matplotlib.pyplot with the non-interactive Agg backend."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return plt


def plot_time_history(result: RunResult, ax: Any = None) -> Any:
    """x, y (and z when non-zero) against time, in nm."""
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 3.5))
    for k, name in enumerate("xyz"):
        series = result.displacement[k]
        if k == 2 and not np.any(series):
            continue
        ax.plot(result.time, (series - series.mean()) * 1e9, lw=0.8, label=name)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("displacement about mean [nm]")
    ax.legend(loc="upper right")
    ax.grid(alpha=0.3)
    ax.set_title(f"{result.title or result.model}: time history")
    return ax


def plot_orbit(result: RunResult, ax: Any = None) -> Any:
    """Orbit (Lissajous figure) of the ring centre in the x-y plane, in nm."""
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(4.5, 4.5))
    x = (result.x - result.x.mean()) * 1e9
    y = (result.y - result.y.mean()) * 1e9
    ax.plot(x, y, lw=0.6)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x [nm]")
    ax.set_ylabel("y [nm]")
    ax.grid(alpha=0.3)
    ax.set_title("orbit of the ring centre")
    return ax


def plot_lines(result: RunResult, ax: Any = None, top: int = 8) -> Any:
    """Stem plot of the labelled lines (p-p, nm) against order; the largest are annotated.

    Directions are drawn side by side (a small offset in order) so that x and y lines at the
    same frequency stay visible; labels are shortened to the part and lobe count.
    """
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 4))
    colours = {"x": "C0", "y": "C1", "z": "C2"}
    all_orders = [c.order for c in result.components] or [0.0, 1.0]
    span = max(max(all_orders) - min(all_orders), 1.0)
    offsets = {"x": -0.004 * span, "y": 0.0, "z": 0.004 * span}
    peak = 0.0
    for direction in ("x", "y", "z"):
        lines = result.lines(direction)
        if not lines:
            continue
        orders = np.array([c.order for c in lines]) + offsets[direction]
        pp = np.array([c.pp_m for c in lines]) * 1e9
        peak = max(peak, float(pp.max()))
        ax.vlines(orders, 0, pp, colors=colours[direction], lw=1.4, label=direction)
        ax.plot(orders, pp, "o", color=colours[direction], ms=3)
    seen: set[tuple[float, str]] = set()
    for c in result.lines(top=top):
        short = c.label.split(":")[0].split(";")[0].strip()
        key = (round(c.order, 3), short)
        if key in seen:
            continue
        seen.add(key)
        ax.annotate(
            f"{short} ({c.direction})",
            (c.order + offsets.get(c.direction, 0.0), c.pp_m * 1e9),
            xytext=(3, 3),
            textcoords="offset points",
            fontsize=7,
            annotation_clip=True,
            clip_on=True,
        )
    ax.set_ylim(0, 1.25 * peak if peak > 0 else 1.0)
    ax.margins(x=0.12)
    ax.set_xlabel("order [waves per revolution of the rotating ring]")
    ax.set_ylabel("peak-to-peak [nm]")
    ax.legend(loc="best")
    ax.grid(alpha=0.3)
    ax.set_title("spectral lines (largest labelled; full labels in lines.csv)")
    return ax


def plot_result(result: RunResult, directory: Path) -> list[Path]:
    """Save the standard figures of a result as PNG files in ``directory``."""
    plt = pyplot()
    written = []
    for name, fn in (
        ("history.png", plot_time_history),
        ("orbit.png", plot_orbit),
        ("lines.png", plot_lines),
    ):
        fig = fn(result).figure
        fig.tight_layout()
        path = directory / name
        fig.savefig(path, dpi=120)
        plt.close(fig)
        written.append(path)
    return written


def plot_density_waveform(
    revolutions: np.ndarray, density_um_per_rad: np.ndarray, title: str = "", ax: Any = None
) -> Any:
    """Displacement density dx/dθ [µm/rad] against revolutions of the rotating ring.

    The look of seed 002 Fig. 11 and 14.
    """
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 3.5))
    ax.plot(revolutions, density_um_per_rad, lw=0.5, color="C0")
    ax.set_xlabel("revolutions of the rotating ring")
    ax.set_ylabel("dx/dθ [µm/rad]")
    ax.set_xlim(float(revolutions[0]), float(revolutions[-1]))
    ax.grid(alpha=0.3)
    ax.set_title(f"{title}: displacement density (x)" if title else "displacement density (x)")
    return ax


def plot_anderon_spectrum(
    orders: np.ndarray,
    line_rms_uin_per_rad: np.ndarray,
    bands: dict[str, tuple[float, float]],
    band_values: dict[str, float],
    title: str = "",
    ax: Any = None,
) -> Any:
    """Lines' rms displacement density [µin/rad] on log-log axes, with the band values.

    The look of seed 002 Fig. 12: x in waves per revolution, each line a stem; each band's
    Anderon value drawn as a horizontal bar across the band (E and A, which span the others,
    are left out of the bars and given in the legend).
    """
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4))
    keep = line_rms_uin_per_rad > 0
    o, v = orders[keep], line_rms_uin_per_rad[keep]
    floor = max(float(v.min()) if v.size else 1e-3, 1e-4)
    ax.vlines(o, floor, v, colors="C0", lw=0.6, label="lines: (dx/dθ) rms")
    for name, (lo, hi) in bands.items():
        if name in ("E", "A") or name not in band_values:
            continue
        ax.hlines(band_values[name], lo, hi, colors="C3", lw=2)
        ax.text((lo * hi) ** 0.5, band_values[name] * 1.15, name, ha="center", fontsize=8)
    extra = ", ".join(f"{n} {band_values[n]:.3g}" for n in ("E", "A") if n in band_values)
    ax.plot([], [], color="C3", lw=2, label=f"band values [Anderon] ({extra})")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("waves per revolution")
    ax.set_ylabel("µin/rad (lines), Anderon (bands)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(loc="lower left", fontsize=8)
    ax.set_title(f"{title}: Anderon spectrum" if title else "Anderon spectrum")
    return ax


def plot_band_values(values: dict[str, dict[str, float]], title: str = "", ax: Any = None) -> Any:
    """Grouped bar chart of band values: ``{series name: {band: value}}`` [Anderon]."""
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 3.5))
    series = list(values)
    names = list(values[series[0]]) if series else []
    width = 0.8 / max(1, len(series))
    pos = np.arange(len(names))
    for i, s in enumerate(series):
        heights = [values[s][n] for n in names]
        bars = ax.bar(pos + i * width, heights, width, label=s)
        ax.bar_label(bars, fmt="%.3g", fontsize=7)
    ax.set_xticks(pos + width * (len(series) - 1) / 2, names)
    ax.set_yscale("log")
    ax.set_ylabel("Anderon")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, axis="y")
    ax.set_title(f"{title}: Anderon bands" if title else "Anderon bands")
    return ax


def plot_linear_figures(
    directory: Path,
    *,
    title: str,
    revolutions: np.ndarray,
    density_um_per_rad: np.ndarray,
    orders: np.ndarray,
    line_rms_uin_per_rad: np.ndarray,
    bands: dict[str, tuple[float, float]],
    band_values: dict[str, dict[str, float]],
) -> list[Path]:
    """Save the linear model's waveform, Anderon spectrum and band chart as PNG files."""
    plt = pyplot()
    first = next(iter(band_values.values()))
    figures = (
        ("density_waveform.png", plot_density_waveform(revolutions, density_um_per_rad, title)),
        (
            "anderon_spectrum.png",
            plot_anderon_spectrum(orders, line_rms_uin_per_rad, bands, first, title),
        ),
        ("anderon_bands.png", plot_band_values(band_values, title)),
    )
    written = []
    for name, ax in figures:
        fig = ax.figure
        fig.tight_layout()
        path = directory / name
        fig.savefig(path, dpi=120)
        plt.close(fig)
        written.append(path)
    return written


# ---------------------------------------------------------------- roller_constraint model
def save_figure(ax: Any, path: Path, dpi: int = 120) -> Path:
    """Save the figure of ``ax`` to ``path`` and close it."""
    plt = pyplot()
    fig = ax.figure
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    return path


def plot_constraint_displacement(
    angle_deg: np.ndarray, radial: np.ndarray, horizontal: np.ndarray, ax: Any = None
) -> Any:
    """Ring-centre displacement along and across the load against the rotation angle, in µm."""
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 3.5))
    ax.plot(angle_deg, radial * 1e6, lw=0.9, label="along the load (radial runout)")
    ax.plot(angle_deg, horizontal * 1e6, lw=0.9, label="across the load")
    ax.set_xlabel("rotation angle of the turning ring [deg]")
    ax.set_ylabel("displacement [µm]")
    ptp = float(np.ptp(radial)) * 1e6
    ax.set_title(f"stable position of the loaded ring (radial runout {ptp:.4g} µm p-p)")
    ax.legend(loc="best", fontsize=8)
    ax.grid(alpha=0.3)
    return ax


def plot_contact_pattern(
    angle_deg: np.ndarray, touching: np.ndarray, pair: np.ndarray, ax: Any = None
) -> Any:
    """Which rollers touch the loaded ring at each angle (dots) and which two hold it (line)."""
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 3.5))
    rows, cols = np.nonzero(touching)
    ax.scatter(angle_deg[rows], cols + 1, s=2, c="C0", label="touching")
    ax.scatter(angle_deg, pair[:, 0] + 1, s=0.5, c="C1", label="holding (left)")
    ax.scatter(angle_deg, pair[:, 1] + 1, s=0.5, c="C2", label="holding (right)")
    ax.set_xlabel("rotation angle of the turning ring [deg]")
    ax.set_ylabel("roller number")
    ax.set_yticks(range(1, touching.shape[1] + 1))
    ax.set_title("contact pattern")
    ax.legend(loc="upper right", fontsize=7, markerscale=4)
    ax.grid(alpha=0.3)
    return ax


def plot_order_sweep(
    orders: np.ndarray,
    runout: np.ndarray,
    parts: tuple[str, ...],
    baseline: float,
    n_elements: int,
    ax: Any = None,
) -> Any:
    """Runout against the harmonic order of each part, with multiples of Z marked."""
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 3.5))
    for j, part in enumerate(parts):
        ax.plot(orders, runout[j] * 1e6, marker="o", ms=3, lw=0.8, label=part)
    ax.axhline(baseline * 1e6, color="k", lw=0.6, ls=":", label="perfect parts")
    for m in range(1, int(orders.max()) // n_elements + 1):
        ax.axvline(m * n_elements, color="grey", lw=0.6, ls="--")
    ax.set_xlabel(f"harmonic order (dashed: multiples of Z = {n_elements})")
    ax.set_ylabel("radial runout p-p [µm]")
    ax.set_title("runout against the number of lobes")
    ax.legend(loc="best", fontsize=8)
    ax.grid(alpha=0.3)
    return ax
