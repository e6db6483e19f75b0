"""One look for every runout figure: rcParams, colours, font sizes and axis labels.

Only :mod:`runout.report.plotting` imports this module; nothing here imports matplotlib at import
time (the CLI's start-up cost), :func:`styled` imports it when a plotting function runs.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any, TypeVar

import numpy as np

from runout.base.display import format_length
from runout.io.output_dir import write_atomic

__all__ = [
    "ANNOTATION_SIZE",
    "DIRECTION_COLOURS",
    "FIT_COLOUR",
    "HIST_COLOUR",
    "LIMIT_COLOUR",
    "NOTE_COLOUR",
    "RC",
    "axis_label",
    "length_scale",
    "log_labels",
    "plain_power",
    "styled",
]

#: Font sizes [pt]: titles, axis labels, tick labels, legends and line labels.
TITLE_SIZE = 9.0
LABEL_SIZE = 9.0
TICK_SIZE = 8.0
LEGEND_SIZE = 7.5
ANNOTATION_SIZE = 7.0

#: One colour per measuring direction, the same in every figure.
DIRECTION_COLOURS = {"x": "#1f77b4", "y": "#ff7f0e", "z": "#2ca02c"}
#: Histogram bars, fitted laws, spec limits and notes.
HIST_COLOUR = "#4c72b0"
FIT_COLOUR = "#222222"
LIMIT_COLOUR = "#c0392b"
NOTE_COLOUR = "0.35"

#: matplotlib rcParams applied (through :func:`styled`) while a runout figure is built and saved.
RC: dict[str, Any] = {
    "figure.dpi": 100,
    "savefig.dpi": 120,
    "figure.facecolor": "white",
    "savefig.facecolor": "white",
    "font.size": LABEL_SIZE,
    "axes.titlesize": TITLE_SIZE,
    "axes.labelsize": LABEL_SIZE,
    "xtick.labelsize": TICK_SIZE,
    "ytick.labelsize": TICK_SIZE,
    "legend.fontsize": LEGEND_SIZE,
    "legend.framealpha": 0.85,
    "figure.titlesize": 10.0,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "lines.linewidth": 1.0,
    # the layout is runout's (:func:`_fix_layout`), never redone by a user's matplotlibrc
    "figure.autolayout": False,
    "figure.constrained_layout.use": False,
    # a plain minus keeps tick labels ASCII-measurable and readable in every font
    "axes.unicode_minus": False,
}

F = TypeVar("F", bound=Callable[..., Any])


def styled(fn: F) -> F:
    """Run ``fn`` with :data:`RC` in force (matplotlib's own settings are restored after).

    The style is applied per call, not globally, so a program that imports runout and draws
    its own figures keeps its matplotlib defaults.
    """

    @functools.wraps(fn)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        import matplotlib

        matplotlib.use("Agg", force=False)
        rc: Any = RC  # matplotlib types the keys as a Literal union
        with matplotlib.rc_context(rc):
            return fn(*args, **kwargs)

    return wrapper  # type: ignore[return-value]


def axis_label(quantity: str, unit: str) -> str:
    """``"quantity [unit]"``: every axis of a runout figure names its quantity and unit.

    Parameters
    ----------
    quantity : str
        What is plotted, in words (``"peak-to-peak"``).
    unit : str
        Its unit as shown (``"nm"``, ``"rpm"``, ``"-"`` for a pure number).

    Returns
    -------
    str
    """
    return f"{quantity} [{unit}]"


#: Superscript digits and minus sign (all in DejaVu Sans, matplotlib's default font).
_SUPERSCRIPT = str.maketrans(
    "0123456789-", "\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079\u207b"
)
#: A label of matplotlib's log-axis formatter: ``$\mathdefault{...}$``.
_MATH_LABEL = re.compile(r"^\$\\mathdefault\{(.*)\}\$$")
#: A power in such a label: ``^{-3}``.
_POWER = re.compile(r"\^\{(-?\d+)\}")


def plain_power(label: str) -> str:
    """A log axis's tick label as plain text: ``10^{-3}`` in mathtext becomes ``10⁻³``.

    matplotlib writes a log axis's labels as mathtext (``$\\mathdefault{10^{-3}}$``,
    ``$\\mathdefault{2\\times10^{-3}}$``); each figure parses each of them again (its own
    renderer's cache): 7-15 ms of the 0.12-0.19 s a log-axis figure of a run takes. The same
    labels in Unicode superscripts are measured and drawn as plain text. A label of any other
    form is returned unchanged.

    Parameters
    ----------
    label : str
        A tick label.

    Returns
    -------
    str
    """
    match = _MATH_LABEL.match(label)
    if match is None:
        return label
    body = _POWER.sub(lambda m: m.group(1).translate(_SUPERSCRIPT), match.group(1))
    body = body.replace("\\times", "\u00d7")
    return label if any(c in body for c in "\\{}^$_") else body


@functools.cache
def _plain_log_formatter() -> type:
    """matplotlib's log-axis formatter, labels in plain text (:func:`plain_power`)."""
    from matplotlib.ticker import LogFormatterSciNotation

    class PlainLogFormatter(LogFormatterSciNotation):
        def __call__(self, x: float, pos: int | None = None) -> str:
            return plain_power(str(super().__call__(x, pos)))

    return PlainLogFormatter


def log_labels(ax: Any, which: str = "y") -> None:
    """Label a log axis of ``ax`` (``"x"`` or ``"y"``) in plain text (:func:`plain_power`).

    Call after the axis is set to log scale (setting the scale resets its formatters). The
    labels, and which ticks carry one, are matplotlib's: only their text is plain.
    """
    axis = ax.xaxis if which == "x" else ax.yaxis
    if axis.get_scale() != "log":
        return
    formatter = _plain_log_formatter()
    axis.set_major_formatter(formatter())
    axis.set_minor_formatter(formatter(labelOnlyBase=False))


def length_scale(values_m: Iterable[float]) -> tuple[str, float]:
    """Unit and factor showing lengths ``values_m`` [m] at their own scale (nm, um, mm, m).

    :func:`runout.base.display.length_unit` decides; the chosen unit makes the largest finite
    magnitude read between 0.1 and 1000.

    Parameters
    ----------
    values_m : array_like of float
        Lengths [m] (NaN and inf are ignored), read in one vectorised pass.

    Returns
    -------
    (str, float)
        Unit name and the factor from metres to it.
    """
    from runout.base.display import length_unit

    return length_unit(np.asarray(values_m, dtype=np.float64))


# --------------------------------------------------------------------------------------------
# helpers every figure module shares (run figures, study figures)
# --------------------------------------------------------------------------------------------
#: Most points handed to matplotlib for one curve (a pixel column pair of a wide figure).
MAX_CURVE_POINTS = 2_000
#: Most points one curve of a time history is drawn with: a min/max pair per pixel column of a
#: figure 8 in wide at 120 dpi is 1,920 points; a longer record is decimated to that envelope.
ENVELOPE_COLUMNS = 1000


def envelope_indices(values: np.ndarray, columns: int = ENVELOPE_COLUMNS) -> np.ndarray:
    """Indices of the smallest and largest value of each of ``columns`` equal runs of samples.

    Drawing only these points (in time order) gives the same picture as drawing every sample
    at a width of ``columns`` pixel columns: every peak and trough stays visible. A record of
    at most ``2 * columns`` samples is returned whole.

    Parameters
    ----------
    values : ndarray, shape (n,)
        The curve.
    columns : int
        Number of runs (pixel columns).

    Returns
    -------
    ndarray of int
        Sorted unique indices, the first and last sample included (at most ``2 * columns + 2``).
    """
    n = values.size
    if n <= 2 * columns:
        return np.arange(n)
    run = -(-n // columns)  # ceil: every sample in one run
    padded = np.concatenate([values, np.full(run * columns - n, values[-1])])
    blocks = padded.reshape(columns, run)
    base = np.arange(columns) * run
    idx = np.concatenate([base + blocks.argmin(axis=1), base + blocks.argmax(axis=1), [0, n - 1]])
    return np.unique(np.minimum(idx, n - 1))


def pyplot() -> Any:
    """matplotlib.pyplot with the non-interactive Agg backend."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return plt


def _fix_layout(fig: Any) -> None:
    """Lay ``fig`` out now (tight layout) and mark it so :func:`_save` keeps that layout.

    Labels placed by :func:`place_labels` are checked against the layout of the moment; a
    later re-layout would move the axes under them.
    """
    fig.tight_layout()
    # tight_layout leaves a placeholder layout engine behind, for which savefig lays the whole
    # figure out once more (a draw that renders nothing) before drawing it: 10 of the 90 ms
    # of a time history, for a layout that is final; without an engine savefig draws once
    # (RC keeps matplotlib's automatic layouts off, so that None means none)
    fig.set_layout_engine(None)
    fig._runout_fixed_layout = True


def _finish(fig: Any) -> Any:
    """Lay ``fig`` out (tight layout) unless its layout is already fixed; return it."""
    if not getattr(fig, "_runout_fixed_layout", False):
        _fix_layout(fig)
    return fig


def _save(fig: Any, path: Path, dpi: int = 100) -> Path:
    """Save ``fig`` (laid out unless its layout is fixed) to ``path`` and close it.

    100 dpi: a 9 in figure is 900 pixels, the width the report shows it at.
    """
    plt = pyplot()
    _finish(fig)
    try:
        # through a temporary renamed over ``path``: a full disk leaves no truncated figure;
        # zlib level 1: a third of the encoding time for files about 5 % larger
        kind = path.suffix.lstrip(".").lower() or "png"
        extra = {"pil_kwargs": {"compress_level": 1}} if kind == "png" else {}
        write_atomic(path, lambda fh: fig.savefig(fh, format=kind, dpi=dpi, **extra), binary=True)
    finally:
        plt.close(fig)
    return path


def _shorten(text: str, limit: int) -> str:
    """``text`` cut to ``limit`` characters, an ellipsis marking the cut."""
    return text if len(text) <= limit else text[: limit - 3].rstrip() + "..."


def _fmt(value_m: float, unit: str, scale: float) -> str:
    """A length at the unit of the panel it is drawn on (``"0.5 um"``)."""
    return format_length(value_m, (unit, scale))
