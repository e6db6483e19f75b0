"""Checks a figure an engineer could read must pass (shared by the plot and report tests).

:func:`figure_problems` lists what is wrong with a matplotlib figure: an axis without a
quantity and a unit in brackets, two texts drawn over each other, a curve handed to
matplotlib with too many points, a spectral axis that is not logarithmic.
:func:`png_problems` lists what is wrong with a saved image: blank (no pixel variance).
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import numpy as np

#: Most points one Line2D may carry (decimation keeps ~2,000; this leaves room).
MAX_LINE_POINTS = 4_000
#: Least pixel variance (grey levels 0-255, squared) of a figure that shows something.
MIN_PIXEL_VARIANCE = 50.0
#: A unit in brackets at the end of an axis label, or followed by more words.
_UNIT = re.compile(r"\[[^\[\]]+\]")


def _texts(fig: Any, renderer: Any) -> list[tuple[str, Any]]:
    """(text, window extent) of every non-empty visible text drawn in ``fig``.

    Tick labels are those of the ticks inside the view (matplotlib keeps hidden ones for
    ticks outside it); legend texts and annotations are included.
    """
    from matplotlib.text import Text

    out = []
    ticks: set[int] = set()
    for ax in fig.axes:
        if not ax.get_visible():
            continue
        for axis in (ax.xaxis, ax.yaxis):
            # the labels matplotlib draws: those of the ticks inside the view interval
            drawn = axis.get_major_ticks() + axis.get_minor_ticks()
            lo, hi = sorted(axis.get_view_interval())
            slack = 1e-9 * abs(hi - lo)
            for tick in drawn:
                ticks.add(id(tick.label1))
                ticks.add(id(tick.label2))
                loc = tick.get_loc()
                if loc is None or not lo - slack <= loc <= hi + slack:
                    continue
                for label in (tick.label1, tick.label2):
                    if label.get_visible() and label.get_text():
                        out.append((label.get_text(), label.get_window_extent(renderer)))
    for text in fig.findobj(Text):
        if id(text) in ticks or not text.get_visible() or not text.get_text().strip():
            continue
        if not _shown(text):
            continue
        # the text itself (an annotation's extent would include its leader line)
        out.append((text.get_text(), Text.get_window_extent(text, renderer)))
    return out


def _shown(artist: Any) -> bool:
    """Whether ``artist`` and every parent it hangs from (axes, legend) is visible."""
    axes = getattr(artist, "axes", None)
    return axes is None or axes.get_visible()


def figure_problems(fig: Any, *, log_y: tuple[Any, ...] = ()) -> list[str]:
    """What keeps ``fig`` from being readable; empty when nothing does.

    Parameters
    ----------
    fig : matplotlib Figure
        A figure as runout draws it (laid out: it is drawn once here).
    log_y : tuple of Axes
        Axes whose y axis must be logarithmic (spectra).

    Returns
    -------
    list of str
        One message per problem.
    """
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    problems: list[str] = []
    for i, ax in enumerate(fig.axes):
        if not ax.get_visible():
            continue
        if not ax.axison:  # a panel of text only (a message), no axes drawn
            continue
        for which, label in (("x", ax.get_xlabel()), ("y", ax.get_ylabel())):
            if not label.strip():
                problems.append(f"axes {i} ({ax.get_title()!r}): empty {which} label")
            elif not _UNIT.search(label):
                problems.append(f"axes {i}: {which} label {label!r} has no [unit]")
        for line in ax.get_lines():
            n = len(np.atleast_1d(line.get_xdata()))
            if n > MAX_LINE_POINTS:
                problems.append(f"axes {i}: a curve of {n:,} points (> {MAX_LINE_POINTS:,})")
    for ax in log_y:
        if ax.get_yscale() != "log":
            problems.append(f"axes {ax.get_title()!r}: y axis is {ax.get_yscale()}, not log")
    texts = _texts(fig, renderer)
    for a in range(len(texts)):
        for b in range(a + 1, len(texts)):
            (ta, ba), (tb, bb) = texts[a], texts[b]
            w = min(ba.x1, bb.x1) - max(ba.x0, bb.x0)
            h = min(ba.y1, bb.y1) - max(ba.y0, bb.y0)
            if w > 1.0 and h > 1.0:  # more than a pixel each way: drawn over each other
                problems.append(f"texts overlap: {ta!r} and {tb!r}")
    width, height = fig.canvas.get_width_height()
    for text, box in texts:
        if box.x0 < -1 or box.y0 < -1 or box.x1 > width + 1 or box.y1 > height + 1:
            problems.append(f"text {text!r} is cut by the figure's edge")
    return problems


def png_problems(path: Path, min_variance: float = MIN_PIXEL_VARIANCE) -> list[str]:
    """What is wrong with a saved figure: missing, or blank (pixel variance below a bound)."""
    from PIL import Image

    if not path.is_file() or path.stat().st_size == 0:
        return [f"{path.name}: missing or empty"]
    with Image.open(path) as im:
        grey = np.asarray(im.convert("L"), dtype=np.float64)
    variance = float(grey.var())
    if variance < min_variance:
        return [f"{path.name}: blank (pixel variance {variance:.3g} < {min_variance:g})"]
    return []
