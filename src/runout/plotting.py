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

__all__ = ["plot_lines", "plot_orbit", "plot_result", "plot_time_history", "pyplot"]


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
    """Stem plot of the labelled lines (p-p, nm) against order; the largest are annotated."""
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 3.5))
    colours = {"x": "C0", "y": "C1", "z": "C2"}
    for direction in ("x", "y", "z"):
        lines = result.lines(direction)
        if not lines:
            continue
        orders = np.array([c.order for c in lines])
        pp = np.array([c.pp_m for c in lines]) * 1e9
        ax.vlines(orders, 0, pp, colors=colours[direction], lw=1.2, label=direction)
    for c in result.lines(top=top):
        ax.annotate(
            c.label, (c.order, c.pp_m * 1e9), fontsize=7, rotation=30, ha="left", va="bottom"
        )
    ax.set_xlabel("order [waves per revolution of the rotating ring]")
    ax.set_ylabel("peak-to-peak [nm]")
    ax.legend(loc="upper right")
    ax.grid(alpha=0.3)
    ax.set_title("spectral lines")
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
