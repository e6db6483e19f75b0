"""Plots: the only module that imports matplotlib (lazily, Agg backend).

Every function takes result data and a directory or an Axes and returns what it drew; no
numerics happen here beyond decimation (at most :data:`MAX_CURVE_POINTS` points a curve, every
peak kept), label placement and drawing a fitted law over a histogram. Every figure is built
in one style (:mod:`runout.report._plot_style`), every axis names its quantity and unit, lengths are
shown at their own scale (nm, um, mm: :func:`runout.base.display.length_unit`).
"""

from __future__ import annotations

import math
import textwrap
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from runout.report import _plot_style as style
from runout.report._plot_style import (
    MAX_CURVE_POINTS,
    _finish,
    _fix_layout,
    _fmt,
    _save,
    _shorten,
    envelope_indices,
    pyplot,
)

if TYPE_CHECKING:
    from runout.analysis.results import RunResult

__all__ = [
    "LINEAR_FIGURES",
    "STANDARD_FIGURES",
    "animate_bearing",
    "place_labels",
    "plot_anderon_spectrum",
    "plot_ball_loads",
    "plot_band_values",
    "plot_constraint_displacement",
    "plot_contact_pattern",
    "plot_density_waveform",
    "plot_dynamic_figures",
    "plot_dynamic_spectrum",
    "plot_dynamic_sweep",
    "plot_linear_figures",
    "plot_lines",
    "plot_orbit",
    "plot_order_sweep",
    "plot_result",
    "plot_run",
    "plot_study",
    "plot_study_kind",
    "plot_time_history",
    "pyplot",
    "result_figures",
    "save_figure",
    "standard_figure_names",
    "streamed_histograms",
    "study_figures",
    "write_figure",
    "write_figures",
]


def _top_source(component: Any) -> str:
    """The name of a line's largest source, for a plot label (its part and lobes)."""
    if component.sources:
        return str(component.sources[0].label().split(":")[0])
    return str(component.label.split(":")[0].split(";")[0].strip())


#: The animation's orbit panel draws records of at most this many instants whole.
DRAW_WHOLE = 10_000
#: Grid cells across an orbit plot's larger span (its axes are about 400 pixels wide): an
#: orbit is drawn through the instants at which its path enters another cell.
ORBIT_CELLS = 500


def orbit_indices(x: np.ndarray, y: np.ndarray, cells: int = ORBIT_CELLS) -> np.ndarray:
    """Indices that draw an orbit at screen resolution: where the path enters another cell.

    The x-y range is cut into square cells, ``cells`` across the larger span; an instant is
    kept when the path has just moved into another cell (the first and last instants always).
    A straight line between kept instants stays within a cell of the dropped ones, so at a
    cell of a pixel or less the picture is that of every instant, with one point per cell
    crossed instead of one per instant.

    Parameters
    ----------
    x, y : ndarray, shape (n,)
        The path.
    cells : int
        Cells across the larger of the x and y spans.

    Returns
    -------
    ndarray of int
        Sorted indices (all of them when ``n <= 2 * cells``).
    """
    n = x.size
    if n <= 2 * cells:
        return np.arange(n)
    span = max(float(np.ptp(x)), float(np.ptp(y)), 1e-300)
    scale = cells / span
    cx = ((x - x.min()) * scale).astype(np.int64)
    cy = ((y - y.min()) * scale).astype(np.int64)
    moved = np.flatnonzero((cx[1:] != cx[:-1]) | (cy[1:] != cy[:-1])) + 1
    # already sorted and unique (no np.unique: its sort cost more than the rest)
    last = [] if moved.size and moved[-1] == n - 1 else [n - 1]
    return np.concatenate([[0], moved, last]).astype(np.int64)


def _decimated(n_drawn: int, n: int, how: str) -> str:
    """Second title line saying that a curve is decimated (empty when every sample is drawn)."""
    return (
        ""
        if n_drawn >= n or n_drawn == 0
        else f"\n(decimated to {n_drawn:,} of {n:,} points, {how})"
    )


#: Offsets [pt] and alignments tried, in this order, for a line label (first free one wins).
_LABEL_OFFSETS = (
    (3, 3, "left"),
    (-3, 3, "right"),
    (3, 13, "left"),
    (-3, 13, "right"),
    (0, 23, "center"),
    (4, -11, "left"),
    (-4, -11, "right"),
    (0, 33, "center"),
    (3, 43, "left"),
    (-3, 43, "right"),
    (6, -22, "left"),
    (-6, -22, "right"),
)


def _overlap(a: Any, b: Any, tolerance: float = 0.5) -> bool:
    """Whether two display-space boxes overlap by more than ``tolerance`` pixels each way."""
    return (
        min(a.x1, b.x1) - max(a.x0, b.x0) > tolerance
        and min(a.y1, b.y1) - max(a.y0, b.y0) > tolerance
    )


def _inside(outer: Any, inner: Any) -> bool:
    """Whether display-space box ``inner`` lies within ``outer``."""
    return bool(
        inner.x0 >= outer.x0
        and inner.x1 <= outer.x1
        and inner.y0 >= outer.y0
        and inner.y1 <= outer.y1
    )


def place_labels(
    ax: Any, items: list[tuple[float, float, str]], fontsize: float | None = None
) -> int:
    """Label points without overlap: greedy placement in display coordinates.

    Each label, in the order given (most important first), is tried at a few offsets from its
    point (right, left, above, below); the first position whose box lies inside the axes and
    overlaps no text already there (labels placed before, the legend, notes) is kept. A label
    with no free position is dropped. Positions are final for the figure's current layout:
    call this after the layout is fixed (:func:`_fix_layout`).

    A label's text is measured once; its box at each candidate offset is that box moved by
    the offset and the alignment (a text's extent does not depend on where it is drawn), so
    only the kept position becomes an artist. The figure is laid out (legend, ticks) by a
    draw that renders nothing.

    Parameters
    ----------
    ax : matplotlib Axes
        Where the points are (data coordinates).
    items : list of (x, y, text)
        Points and their labels, most important first.
    fontsize : float, optional
        Label font size [pt]; default :data:`runout.report._plot_style.ANNOTATION_SIZE`.

    Returns
    -------
    int
        Number of labels dropped for want of room.
    """
    from matplotlib.text import Text

    fig = ax.figure
    if getattr(fig, "_runout_fixed_layout", False):
        # the tight layout has measured the figure (limits, legend and ticks settled); the
        # limits are read so that any autoscaling still pending is done
        ax.get_xlim()
        ax.get_ylim()
    else:
        fig.draw_without_rendering()  # legend positions ("best") and tick labels are settled
    renderer = fig.canvas.get_renderer()
    frame = ax.get_window_extent(renderer)
    taken = [
        Text.get_window_extent(t, renderer) for t in ax.texts if t.get_visible() and t.get_text()
    ]
    legend = ax.get_legend()
    if legend is not None:
        taken.append(legend.get_window_extent(renderer))
    size = fontsize or style.ANNOTATION_SIZE
    pixels_per_point = fig.dpi / 72.0
    dropped = 0
    for x, y, text in items:
        probe = ax.annotate(
            text, (x, y), xytext=(0, 0), textcoords="offset points", ha="left", va="bottom",
            fontsize=size,
        )  # fmt: skip
        probe.update_positions(renderer)
        at_point = Text.get_window_extent(probe, renderer)  # left-aligned on the point itself
        probe.remove()
        shift = {"left": 0.0, "center": 0.5 * at_point.width, "right": at_point.width}
        for dx, dy, ha in _LABEL_OFFSETS:
            box = at_point.translated(dx * pixels_per_point - shift[ha], dy * pixels_per_point)
            if _inside(frame, box) and not any(_overlap(box, b) for b in taken):
                ax.annotate(
                    text,
                    (x, y),
                    xytext=(dx, dy),
                    textcoords="offset points",
                    ha=ha,
                    va="bottom",
                    fontsize=size,
                    # a label moved away from its point is tied to it by a thin leader
                    arrowprops=(
                        None
                        if abs(dy) <= 3
                        else {"arrowstyle": "-", "lw": 0.5, "color": "0.55", "shrinkA": 0}
                    ),
                )
                taken.append(box)
                break
        else:
            dropped += 1
    return dropped


def _window(result: RunResult, revolutions: float | None) -> tuple[np.ndarray, float, str]:
    """Indices of the last ``revolutions`` revolutions of the rotating ring, and a caption.

    Returns the indices, the number of revolutions the whole record spans (0 when the ring
    speed is not known) and the caption (``"last 3 of 72 revolutions"``; empty when the whole
    record is drawn).
    """
    if revolutions is not None and not (math.isfinite(revolutions) and revolutions > 0):
        raise ValueError(f"history revolutions must be a positive number, got {revolutions!r}")
    t = result.time
    n = t.size
    fr = abs(float(result.frequencies.rotation))
    # the record covers n sample intervals (the last sample starts the last interval)
    span = float(t[-1] - t[0]) * fr * n / (n - 1) if n >= 2 else 0.0
    if revolutions is None or fr == 0.0 or span <= revolutions * (1 + 1e-9):
        return np.arange(n), span, ""
    start = int(np.searchsorted(t, t[-1] - revolutions / fr, side="left"))
    return np.arange(start, n), span, f"last {revolutions:g} of {span:.4g} revolutions"


def _resolution_m(result: RunResult) -> float:
    """The solver's resolution of ``result`` [m] (0 when unknown): smaller motion is noise."""
    from runout.analysis.result_details import DynamicDetails

    details = result.details
    found = [
        details.solver_resolution_m if isinstance(details, DynamicDetails) else 0.0,
        float(result.resolution_m() or 0.0),
    ]
    return max((v for v in found if math.isfinite(v)), default=0.0)


def _floor(peak_m: float, resolution_m: float, what: str) -> tuple[float, str]:
    """Floor of a log amplitude axis [m] and the words saying what it is.

    :data:`FLOOR_FRACTION` of the largest ``what``, or the solver's resolution when that is
    higher (below it a value is numerical noise).
    """
    if resolution_m > FLOOR_FRACTION * peak_m:
        unit = style.length_scale([resolution_m])
        return resolution_m, f"axis floor: the solver's resolution ({_fmt(resolution_m, *unit)})"
    return FLOOR_FRACTION * peak_m, f"axis floor {FLOOR_FRACTION:.0e} of the largest {what}"


def _below_resolution(ax: Any, resolution_m: float, what: str) -> None:
    """Say on ``ax`` that ``what`` is below the solver's resolution (nothing else drawn)."""
    unit = style.length_scale([resolution_m])
    ax.text(
        0.5,
        0.5,
        f"{what} is below the solver's resolution\n({_fmt(resolution_m, *unit)}): nothing to draw",
        transform=ax.transAxes,
        ha="center",
        va="center",
        color=style.NOTE_COLOUR,
        bbox={"facecolor": "white", "edgecolor": "none", "alpha": 0.9},
    )


def _direction_name(direction: np.ndarray) -> str:
    """``"x"``, ``"y"`` or ``"30 deg from x"`` for a unit vector in the x-y plane."""
    ux, uy = (float(v) for v in direction[:2])
    angle = math.degrees(math.atan2(uy, ux)) % 180.0
    if min(angle, 180.0 - angle) < 0.5:
        return "x"
    if abs(angle - 90.0) < 0.5:
        return "y"
    return f"{angle:.0f} deg from x"


@style.styled
def plot_time_history(result: RunResult, ax: Any = None, revolutions: float | None = 3.0) -> Any:
    """x, y (and z when it moves) about their mean over the last few revolutions.

    The x axis counts revolutions of the rotating ring from the start of the record (time in
    seconds when the ring speed is zero); the length unit follows the size of the motion.
    A long window is drawn through its min/max envelope (every peak kept, at most
    :data:`MAX_CURVE_POINTS` points a curve).

    Parameters
    ----------
    result : RunResult
        A time-history result.
    ax : matplotlib Axes, optional
        Where to draw (a new figure by default).
    revolutions : float or None
        Revolutions of the rotating ring shown, the last ones of the record (None: all).

    Returns
    -------
    matplotlib Axes
    """
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 3.5))
    idx, _span, caption = _window(result, revolutions)
    fr = abs(float(result.frequencies.rotation))
    t = result.time[idx]
    xs = t * fr if fr > 0.0 else t
    shown = [(name, result.displacement[k]) for k, name in enumerate("xyz")]
    shown = [(name, s) for name, s in shown if name != "z" or np.any(s)]
    dev = [(name, s[idx] - s.mean()) for name, s in shown]
    unit, scale = style.length_scale(np.concatenate([d for _, d in dev]) if dev else [])
    resolution = _resolution_m(result)
    still = all(float(np.ptp(d)) <= resolution for _, d in dev)
    if still:  # numerical noise about a steady position is not a history to draw
        dev = []
        unit = style.length_scale([resolution])[0]
        _below_resolution(ax, resolution, "the motion about the mean")
    drawn = 0
    for name, d in dev:
        keep = envelope_indices(d, MAX_CURVE_POINTS // 2)
        drawn = max(drawn, keep.size)
        ax.plot(xs[keep], d[keep] * scale, lw=0.8, color=style.DIRECTION_COLOURS[name], label=name)
    if fr > 0.0:
        ax.set_xlabel(style.axis_label("revolutions of the rotating ring", "rev"))
    else:
        ax.set_xlabel(style.axis_label("time", "s"))
    ax.set_xlim(float(xs[0]), float(xs[-1]))
    ax.set_ylabel(style.axis_label("displacement about mean", unit))
    if dev:
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    title = _shorten(f"{result.title or result.model}: time history", 90)
    if caption:
        title += f"\n({caption})"
    note = _decimated(drawn, idx.size, "min and max of each pixel column")
    ax.set_title(title + note, fontsize=8 if note else None)
    return ax


def _orbit_keep(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Indices drawing an orbit at screen resolution with at most :data:`MAX_CURVE_POINTS`."""
    cells = ORBIT_CELLS
    keep = orbit_indices(x, y, cells)
    while keep.size > MAX_CURVE_POINTS and cells > 8:
        # a path that fills its area crosses many cells: coarser cells (still a clean line)
        cells = max(8, int(cells * 0.7 * MAX_CURVE_POINTS / keep.size))
        keep = orbit_indices(x, y, cells)
    if keep.size > MAX_CURVE_POINTS:  # a path back and forth across 8 cells: every k-th instant
        keep = keep[np.linspace(0, keep.size - 1, MAX_CURVE_POINTS).round().astype(int)]
    return keep


@style.styled
def plot_orbit(
    result: RunResult, ax: Any = None, arrows: int = 6, revolutions: float | None = None
) -> Any:
    """Orbit (Lissajous figure) of the ring centre in the x-y plane, with the measuring direction.

    The look of seed 000 Figs. 4-7: equal aspect, a marker at the first instant drawn and
    ``arrows`` arrowheads along the path showing the sense of motion. The measuring direction
    (the radial direction in which runout is read) is drawn through the mean position.

    Parameters
    ----------
    result : RunResult
        A time-history result.
    ax : matplotlib Axes, optional
        Where to draw (a new figure by default).
    arrows : int
        Arrowheads along the path.
    revolutions : float or None
        Only the last ``revolutions`` revolutions of the rotating ring (None: the whole record).

    Returns
    -------
    matplotlib Axes
    """
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(6.4, 4.2))
    idx, span, caption = _window(result, revolutions)
    if not caption and span > 0.0:
        caption = f"whole record: {span:.4g} revolutions"
    x_m = result.x[idx] - result.x.mean()
    y_m = result.y[idx] - result.y.mean()
    unit, scale = style.length_scale(np.concatenate([x_m, y_m]))
    resolution = _resolution_m(result)
    if max(float(np.ptp(x_m)), float(np.ptp(y_m))) <= resolution:
        # numerical noise about a steady position: the orbit is a point
        unit, scale = style.length_scale([resolution])
        x_m = y_m = np.zeros(0)
        _below_resolution(ax, resolution, "the motion")
    x, y = x_m * scale, y_m * scale
    keep = _orbit_keep(x, y) if x.size else np.zeros(0, dtype=int)
    if x.size:
        # a dense orbit in a thinner line, so that its loops stay apart
        lw = 0.7 if keep.size <= 500 else 0.4
        ax.plot(x[keep], y[keep], lw=lw, color=style.DIRECTION_COLOURS["x"], label="ring centre")
    # no motion to draw: axes of about one unit of the resolution's scale
    reach = float(np.max(np.hypot(x, y), initial=0.0)) if x.size else 0.75
    if x.size >= 2:
        ax.plot(x[0], y[0], "o", color="C3", ms=5, label="first instant drawn", zorder=3)
        n = x.size
        for k in range(1, arrows + 1):
            i = min(n - 2, int(k * n / (arrows + 1)))
            ax.annotate(
                "",
                xy=(x[i + 1], y[i + 1]),
                xytext=(x[i], y[i]),
                arrowprops={"arrowstyle": "-|>", "color": "C3", "lw": 0.8, "mutation_scale": 10},
            )
    direction = np.asarray(result.measuring_direction, dtype=np.float64)[:2]
    norm = float(np.hypot(*direction))
    name = _direction_name(direction / norm) if norm > 0 else "x"
    u = direction / norm if norm > 0 else np.array([1.0, 0.0])
    ends = np.array([-1.25, 1.25]) * reach
    ax.plot(
        ends * u[0],
        ends * u[1],
        ls="--",
        lw=0.9,
        color="0.3",
        label=f"measuring direction ({name})",
    )
    lim = 1.35 * reach
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel(style.axis_label("x about mean", unit))
    ax.set_ylabel(style.axis_label("y about mean", unit))
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)
    title = "orbit of the ring centre" + (f"\n({caption})" if caption else "")
    note = _decimated(keep.size, x.size, "one point per cell crossed")
    ax.set_title(title + note, fontsize=8 if note else None)
    return ax


def animate_bearing(
    result: RunResult,
    path: Path,
    *,
    n_elements: int | None = None,
    frames: int = 48,
    fps: int = 8,
) -> Path:
    """Write a GIF of the ring centre and the balls (the animation seed 000 §4 describes).

    Left: the bearing seen along its axis, balls at their cage positions, a reference mark
    turning with the rotating ring and the measured ring's centre displaced by its magnified
    displacement; right: the orbit traced so far (nm, equal aspect). Frames are spread evenly
    over the record (at most ``frames``, never more than 120; by default 48 frames shown for
    six seconds: the GIF of a 900 × 450 pixel figure costs about 2.5 ms a frame to write).

    Notes
    -----
    matplotlib draws the static parts once; the moving parts are drawn on that background
    with Pillow (which matplotlib depends on) and the frames saved as a GIF by Pillow, the
    library matplotlib's PillowWriter wraps. Redrawing the figure per frame through
    PillowWriter costs about 0.15 s a frame; this takes a few milliseconds.

    Parameters
    ----------
    result : RunResult
        A time-history result (``time`` and ``displacement``).
    path : Path
        Output ``.gif`` file.
    n_elements : int or None
        Number of balls drawn; default the quasi-static details' ``n_elements`` (else 8).
    frames, fps : int
        Number of frames (<= 120) and frames per second.

    Returns
    -------
    Path
    """
    from PIL import Image, ImageDraw

    plt = pyplot()
    from runout.analysis.result_details import QuasiStaticDetails

    if n_elements is None:
        details = result.details
        n_elements = details.n_elements if isinstance(details, QuasiStaticDetails) else 8
    z = int(n_elements)
    n = result.time.size
    count = max(2, min(frames, 120, n))
    idx = np.linspace(0, n - 1, count).round().astype(int)
    t = result.time
    x = (result.x - result.x.mean()) * 1e9
    y = (result.y - result.y.mean()) * 1e9
    reach = max(float(np.hypot(x, y).max()), 1e-12)
    magnify = 0.15 / reach  # largest excursion drawn at 15 % of the pitch radius
    fc = result.frequencies.cage
    fr = result.frequencies.rotation
    # 900 x 450 pixels: legible in the report at its own size (a GIF scaled up blurs)
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(9.0, 4.5), dpi=100)
    ax.set_xlim(-1.45, 1.45)
    ax.set_ylim(-1.45, 1.45)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.add_patch(plt.Circle((0, 0), 1.3, fill=False, lw=1.5, color="0.3"))
    ax.set_title("balls and ring centre (displacement magnified)", fontsize=10)
    # the panel is about 350 pixels wide
    keep = orbit_indices(x, y, cells=350) if n > DRAW_WHOLE else np.arange(n)
    ax2.plot(x[keep], y[keep], lw=0.3, color="0.85")
    ax2.set_aspect("equal", adjustable="datalim")
    ax2.set_xlabel("x [nm]", fontsize=9)
    ax2.set_ylabel("y [nm]", fontsize=9)
    ax2.tick_params(labelsize=8)
    heading = textwrap.shorten(result.title or "orbit", width=48, placeholder="...")
    ax2.set_title(f"{heading}\n({count} frames of {n:,} instants)", fontsize=10)
    fig.tight_layout()
    fig.canvas.draw()
    background = np.asarray(fig.canvas.buffer_rgba())[..., :3].copy()
    height = background.shape[0]
    # One palette for every frame: the background's 28 colours and the 4 drawn ones. Frames
    # are drawn in palette mode, so no frame needs quantising (3-4 ms a frame).
    colours = [(31, 119, 180), (214, 39, 40), (150, 150, 150), (90, 90, 90)]
    base = Image.fromarray(background).quantize(colors=28, dither=Image.Dither.NONE)
    palette = (base.getpalette() or [])[: 3 * 28]
    palette += [0] * (3 * 28 - len(palette)) + [v for c in colours for v in c]
    base.putpalette(palette)
    blue, red, grey, dark = range(28, 32)

    def px(a: Any, xs: np.ndarray, ys: np.ndarray) -> list[tuple[float, float]]:
        pts = a.transData.transform(np.column_stack([xs, ys]))
        return [(float(u), float(height - v)) for u, v in pts]

    unit = float(ax.transData.transform((1.0, 0.0))[0] - ax.transData.transform((0.0, 0.0))[0])
    r_ball = unit * min(0.28, 0.9 * math.sin(math.pi / z))
    r_ring = unit * 0.7
    plt.close(fig)
    step = max(1, n // 1500)  # the trace is drawn with at most ~1500 points
    trace_px = px(ax2, x[::step], y[::step])  # transformed once, sliced per frame
    # The trace so far is kept on its own copy of the background and only its new segments
    # drawn per frame: a wide line is drawn segment by segment in one colour, so the pixels
    # are those of the whole polyline drawn again (which cost ~2 ms a frame at 1500 points).
    traced = base.copy()
    traced_draw = ImageDraw.Draw(traced)
    traced_to = 0  # trace_px[: traced_to + 1] is on ``traced``
    images = []
    for i in idx:
        upto = i // step
        if upto > traced_to:
            traced_draw.line(trace_px[traced_to : upto + 1], fill=blue, width=2)
            traced_to = upto
        img = traced.copy()
        draw = ImageDraw.Draw(img)
        cx, cy = x[i] * magnify, y[i] * magnify
        (c,) = px(ax, np.array([cx]), np.array([cy]))
        draw.ellipse(
            [c[0] - r_ring, c[1] - r_ring, c[0] + r_ring, c[1] + r_ring],
            outline=blue,
            width=3,
        )
        ang = 2 * math.pi * fr * t[i]
        (m,) = px(ax, np.array([cx + 0.6 * math.cos(ang)]), np.array([cy + 0.6 * math.sin(ang)]))
        draw.line([c, m], fill=red, width=3)
        th = 2 * np.pi * (fc * t[i] + np.arange(z) / z)
        for b in px(ax, np.cos(th), np.sin(th)):
            draw.ellipse(
                [b[0] - r_ball, b[1] - r_ball, b[0] + r_ball, b[1] + r_ball],
                fill=grey,
                outline=dark,
            )
        # the segment from the last traced point to this instant's
        trace = trace_px[upto : upto + 1] + px(ax2, x[i : i + 1], y[i : i + 1])
        draw.line(trace, fill=blue, width=2)
        d = trace[-1]
        draw.ellipse([d[0] - 4, d[1] - 4, d[0] + 4, d[1] + 4], fill=red)
        images.append(img)
    images[0].save(path, save_all=True, append_images=images[1:], duration=int(1000 / fps), loop=0)
    return path


@style.styled
def plot_ball_loads(
    azimuth_deg: np.ndarray,
    inner_load: np.ndarray,
    outer_load: np.ndarray,
    inner_angle_deg: np.ndarray,
    outer_angle_deg: np.ndarray,
    title: str = "",
) -> Any:
    """Ball loads [N] and contact angles [deg] against the ball's azimuth (equilibrium model).

    Two panels sharing the azimuth axis: the inner and outer contact loads Q_i and Q_o above,
    the inner and outer contact angles α_i and α_o below.

    Parameters
    ----------
    azimuth_deg : ndarray, shape (Z,)
        Azimuth ψ of each ball [deg].
    inner_load, outer_load : ndarray, shape (Z,)
        Contact load of each ball on the inner and the outer raceway [N].
    inner_angle_deg, outer_angle_deg : ndarray, shape (Z,)
        Contact angle of each ball at the inner and the outer raceway [deg].
    title : str
        Case title, put ahead of the figure's own title.

    Returns
    -------
    matplotlib Axes
        The upper (load) panel; its ``figure`` holds both.
    """
    plt = pyplot()
    _, (ax, ax2) = plt.subplots(2, 1, figsize=(7, 5), sharex=True)
    ax.plot(azimuth_deg, inner_load, "o-", ms=3, label="Q_i (inner)")
    ax.plot(azimuth_deg, outer_load, "s--", ms=3, label="Q_o (outer)")
    ax.set_ylabel("ball load [N]")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    ax.set_title(f"{title}: ball loads and contact angles" if title else "ball loads")
    ax2.plot(azimuth_deg, inner_angle_deg, "o-", ms=3, label="α_i")
    ax2.plot(azimuth_deg, outer_angle_deg, "s--", ms=3, label="α_o")
    ax2.set_xlabel("ball azimuth ψ [deg]")
    ax2.set_ylabel("contact angle [deg]")
    ax2.legend(fontsize=8)
    ax2.grid(alpha=0.3)
    return ax


#: A spectrum's log axis starts this far below its largest line (relative to it).
FLOOR_FRACTION = 1e-4


#: A log axis spanning more than this ratio gets minor ticks at 2 and 5 of each decade only.
THIN_MINOR_SPAN = 100.0


def _thin_log_minor(ax: Any, which: str = "y") -> None:
    """Minor ticks of a log axis of ``ax`` at 2 and 5 of each decade, not 2 … 9.

    Only on an axis (``"x"`` or ``"y"``, limits already set) spanning more than
    :data:`THIN_MINOR_SPAN`, where matplotlib labels no minor tick anyway: each tick is
    an object laid out and drawn at every pass (a five-decade axis has about 40 minor ticks,
    a fifth of such a figure's drawing time), and 1-2-5 still reads the values between the
    decades.
    """
    from matplotlib.ticker import LogLocator

    lo, hi = ax.get_xlim() if which == "x" else ax.get_ylim()
    lo, hi = min(lo, hi), max(lo, hi)
    if lo > 0 and hi > THIN_MINOR_SPAN * lo:
        axis = ax.xaxis if which == "x" else ax.yaxis
        axis.set_minor_locator(LogLocator(10.0, subs=(2.0, 5.0)))


def _line_labels(
    components: list[Any],
    top: int,
    x_of: Any,
    where: Any,
    shift: dict[str, float] | None = None,
) -> list[tuple[float, float, str]]:
    """(x, y [m], label) of the ``top`` largest lines, one label per line and frequency.

    The same line seen in several directions (same ``x_of`` and short label) gets one label
    naming them all, placed at the largest (``shift``: the x offset each direction is drawn
    with). Lines whose short labels are alike are told apart by ``where(x)`` (``"at 3.8/rev"``).
    """
    groups: dict[tuple[float, str], list[Any]] = {}
    for c in sorted(components, key=lambda c: -c.pp_m):
        key = (round(float(x_of(c)), 6), _top_source(c))
        groups.setdefault(key, []).append(c)
    chosen = list(groups.items())[:top]
    shorts = [short for (_, short), _ in chosen]
    items = []
    for (_, short), members in chosen:
        dirs = ", ".join(sorted({c.direction for c in members}))
        lead = members[0]
        name = short if shorts.count(short) == 1 else f"{short} {where(float(x_of(lead)))}"
        x = float(x_of(lead)) + (shift or {}).get(lead.direction, 0.0)
        items.append((x, lead.pp_m, f"{name} ({dirs})"))
    return items


@style.styled
def plot_lines(result: RunResult, ax: Any = None, top: int = 6) -> Any:
    """Stems of the lines' peak-to-peak against order on a log axis; the largest labelled.

    The axis starts at a floor :data:`FLOOR_FRACTION` of the largest line (stated in the
    title); lines below it are counted, not drawn. Directions are drawn side by side (a small
    offset in order) so x and y lines at one frequency stay visible. Labels are short (the
    largest source's part and lobes; the full labels are in ``lines.csv``), only for the
    ``top`` largest lines, and placed without overlap (:func:`place_labels`); a label with no
    room is dropped and counted in the title.

    Parameters
    ----------
    result : RunResult
        The result whose ``components`` are drawn.
    ax : matplotlib Axes, optional
        Where to draw (a new figure, laid out before labels are placed, by default).
    top : int
        Number of lines labelled.

    Returns
    -------
    matplotlib Axes
    """
    plt = pyplot()
    own = ax is None
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 4.2))
    resolution = _resolution_m(result)
    comps = [c for c in result.components if c.pp_m > resolution and math.isfinite(c.pp_m)]
    peak_m = max((c.pp_m for c in comps), default=0.0)
    unit, scale = style.length_scale([peak_m])
    floor_m, floor_text = _floor(peak_m, resolution, "line")
    # side-by-side offset of the directions: a fraction of the order range drawn
    shown_orders = [c.order for c in comps if c.pp_m >= floor_m] or [0.0, 1.0]
    span = max(max(shown_orders) - min(shown_orders), 1.0)
    offsets = {"x": -0.004 * span, "y": 0.0, "z": 0.004 * span}
    below = 0
    for direction in ("x", "y", "z"):
        lines = [c for c in comps if c.direction == direction]
        drawn = [c for c in lines if c.pp_m >= floor_m]
        below += len(lines) - len(drawn)
        if not drawn:
            continue
        orders = np.array([c.order for c in drawn]) + offsets[direction]
        pp = np.array([c.pp_m for c in drawn]) * scale
        colour = style.DIRECTION_COLOURS[direction]
        ax.vlines(orders, floor_m * scale, pp, colors=colour, lw=1.2, label=direction)
        ax.plot(orders, pp, "o", color=colour, ms=3)
    ax.set_xlabel(style.axis_label("order", "waves per revolution of the rotating ring"))
    ax.set_ylabel(style.axis_label("peak-to-peak", unit))
    ax.margins(x=0.06)
    ax.set_yscale("log")
    style.log_labels(ax)
    if comps:
        ax.set_ylim(floor_m * scale, peak_m * scale * 6.0)  # headroom for labels above the top
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
        _thin_log_minor(ax)
        if below:
            floor_text += f"; {below:,} smaller lines not drawn"
    else:
        ax.set_ylim(1e-1, 1e3)
        ax.set_xlim(0.0, 10.0)
        floor_text = "no lines above the solver's resolution"
        ax.text(0.5, 0.5, floor_text, transform=ax.transAxes, ha="center", va="center", color="0.4")
    items = _line_labels(comps, top, lambda c: c.order, lambda v: f"at {v:.3g}/rev", offsets)
    head = "spectral lines (full labels in lines.csv)"
    _label_largest(ax, items, scale, head, floor_text, own, "largest")
    return ax


def _label_largest(
    ax: Any,
    items: list[tuple[float, float, str]],
    scale: float,
    head: str,
    tail: str,
    own: bool,
    noun: str,
) -> None:
    """Title a spectrum with how many of its largest lines are labelled, and label them.

    The layout is fixed first on a figure of our own (:func:`_fix_layout`), so that the labels
    placed by :func:`place_labels` stay where they were checked; labels without room are
    dropped and the title says how many.
    """
    count = f"{len(items)} {noun} labelled; " if items else ""
    ax.set_title(f"{head}\n{count}{tail}", fontsize=8)
    if own:
        _fix_layout(ax.figure)
    dropped = place_labels(ax, [(x, y * scale, s) for x, y, s in items])
    if dropped:
        ax.set_title(
            f"{head}\n{len(items) - dropped} {noun} labelled, +{dropped} unlabelled; {tail}",
            fontsize=8,
        )


@style.styled
def result_figures(result: RunResult, *, history_revolutions: float = 3.0) -> dict[str, Any]:
    """The standard figures of a result, laid out, by the file name :func:`write_figures` uses.

    ``history.png`` (the last ``history_revolutions`` revolutions: a time trace of the whole
    record would be a solid band), ``orbit.png`` (the orbit over the whole record, at screen
    resolution, with the measuring direction) and ``lines.png``; none for a result of a
    single instant (the equilibrium model).

    Parameters
    ----------
    result : RunResult
        A time-history result.
    history_revolutions : float
        Revolutions of the rotating ring shown by the history (> 0).

    Returns
    -------
    dict
        File name -> matplotlib Figure (the caller saves or closes them).
    """
    return {
        name: _standard_figure(result, name, history_revolutions)
        for name in standard_figure_names(result, history_revolutions)
    }


#: The file names of the standard figures of a time-history result, in the order written.
STANDARD_FIGURES = ("history.png", "orbit.png", "lines.png")


def standard_figure_names(result: RunResult, history_revolutions: float = 3.0) -> list[str]:
    """The standard figures ``result`` gets (:func:`result_figures`): none for one instant.

    Parameters
    ----------
    result : RunResult
        The result.
    history_revolutions : float
        Revolutions of the rotating ring shown by the history (> 0; checked here).

    Returns
    -------
    list of str
        File names, from :data:`STANDARD_FIGURES`.
    """
    if not (math.isfinite(history_revolutions) and history_revolutions > 0):
        raise ValueError(
            f"history_revolutions must be a positive number, got {history_revolutions!r}"
        )
    if result.time.size < 2:  # a single instant (equilibrium model): nothing to draw
        return []
    return list(STANDARD_FIGURES)


def _standard_figure(result: RunResult, name: str, history_revolutions: float) -> Any:
    """One standard figure, laid out (:func:`result_figures`)."""
    if name == "history.png":
        return _finish(plot_time_history(result, revolutions=history_revolutions).figure)
    if name == "orbit.png":
        return _finish(plot_orbit(result).figure)
    if name == "lines.png":
        return _finish(plot_lines(result).figure)
    raise ValueError(f"no standard figure {name!r}; they are {', '.join(STANDARD_FIGURES)}")


@style.styled
def write_figure(
    result: RunResult, directory: Path, name: str, *, history_revolutions: float = 3.0
) -> Path:
    """Save one standard figure of a result (``name``, of :data:`STANDARD_FIGURES`) as PNG.

    The same file :func:`write_figures` writes under that name; figures drawn one by one can
    be drawn by several processes.

    Parameters
    ----------
    result : RunResult
        A time-history result.
    directory : Path
        Existing output directory.
    name : str
        File name, one of :data:`STANDARD_FIGURES`.
    history_revolutions : float
        Revolutions of the rotating ring shown by the history (> 0).

    Returns
    -------
    Path
        ``directory / name``.
    """
    return _save(_standard_figure(result, name, history_revolutions), directory / name)


@style.styled
def write_figures(
    result: RunResult, directory: Path, *, history_revolutions: float = 3.0
) -> list[Path]:
    """Save the standard figures of a result (:func:`result_figures`) as PNG files.

    Parameters
    ----------
    result : RunResult
        A time-history result (an equilibrium result, one instant, writes nothing).
    directory : Path
        Existing output directory.
    history_revolutions : float
        Revolutions of the rotating ring shown by the history (> 0).

    Returns
    -------
    list of Path
        ``history.png``, ``orbit.png`` and ``lines.png`` in ``directory``.
    """
    figures = result_figures(result, history_revolutions=history_revolutions)
    return [_save(fig, directory / name) for name, fig in figures.items()]


@style.styled
def plot_density_waveform(
    revolutions: np.ndarray, density_um_per_rad: np.ndarray, title: str = "", ax: Any = None
) -> Any:
    """Displacement density dx/dθ [µm/rad] against revolutions of the rotating ring.

    The look of seed 002 Fig. 11 and 14; a long record is drawn through its min/max
    envelope (every peak kept).

    Parameters
    ----------
    revolutions : ndarray, shape (n,)
        Rotation of the rotating ring [rev].
    density_um_per_rad : ndarray, shape (n,)
        Displacement density dx/dθ at each instant [µm/rad].
    title : str
        Case title, put ahead of the figure's own title.
    ax : matplotlib Axes, optional
        Where to draw (a new figure by default).

    Returns
    -------
    matplotlib Axes
    """
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 3.5))
    keep = envelope_indices(density_um_per_rad, MAX_CURVE_POINTS // 2)
    ax.plot(revolutions[keep], density_um_per_rad[keep], lw=0.5, color="C0")
    ax.set_xlabel(style.axis_label("revolutions of the rotating ring", "rev"))
    ax.set_ylabel(style.axis_label("dx/dθ", "µm/rad"))
    ax.set_xlim(float(revolutions[0]), float(revolutions[-1]))
    head = f"{title}: displacement density (x)" if title else "displacement density (x)"
    note = _decimated(keep.size, density_um_per_rad.size, "min and max of each pixel column")
    ax.set_title(_shorten(head, 90) + note, fontsize=8 if note else None)
    return ax


@style.styled
def plot_anderon_spectrum(
    orders: np.ndarray,
    line_rms_uin_per_rad: np.ndarray,
    bands: dict[str, tuple[float, float]],
    band_values: dict[str, float],
    title: str = "",
    ax: Any = None,
) -> Any:
    """Lines' rms displacement density [µin/rad] on log-log axes, with the band values.

    The look of seed 002 Fig. 12: x in waves per revolution, each line a stem from a floor
    :data:`FLOOR_FRACTION` of the largest line (stated in the title); each band's Anderon value
    drawn as a horizontal bar across the band (E and A, which span the others, are left out of
    the bars and given in the legend).

    Parameters
    ----------
    orders : ndarray, shape (m,)
        Order of each line [waves per revolution].
    line_rms_uin_per_rad : ndarray, shape (m,)
        Rms displacement density of each line [µin/rad]; lines of zero are not drawn.
    bands : dict
        Band name -> (low, high) edges [waves per revolution].
    band_values : dict
        Band name -> Anderon value [Anderon]; a band missing from it gets no bar.
    title : str
        Case title, put ahead of the figure's own title.
    ax : matplotlib Axes, optional
        Where to draw (a new figure by default).

    Returns
    -------
    matplotlib Axes
    """
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4))
    keep = line_rms_uin_per_rad > 0
    o, v = orders[keep], line_rms_uin_per_rad[keep]
    top = float(v.max()) if v.size else 1.0
    floor = FLOOR_FRACTION * top
    shown = v >= floor
    ax.vlines(o[shown], floor, v[shown], colors="C0", lw=0.6, label="lines: (dx/dθ) rms")
    bars = [float(band_values[n]) for n in bands if n in band_values and n not in ("E", "A")]
    for name, (lo, hi) in bands.items():
        if name in ("E", "A") or name not in band_values:
            continue
        ax.hlines(band_values[name], lo, hi, colors="C3", lw=2)
        ax.text((lo * hi) ** 0.5, band_values[name] * 1.15, name, ha="center", fontsize=8)
    extra = ", ".join(f"{n} {band_values[n]:.3g}" for n in ("E", "A") if n in band_values)
    ax.plot([], [], color="C3", lw=2, label=f"band values [Anderon] ({extra})")
    ax.set_xscale("log")
    ax.set_yscale("log")
    style.log_labels(ax, "x")
    style.log_labels(ax)
    ax.set_ylim(floor, 3.0 * max([top, *bars]))
    _thin_log_minor(ax, "x")
    _thin_log_minor(ax)
    ax.set_xlabel(style.axis_label("order", "waves per revolution"))
    ax.set_ylabel("lines [µin/rad], bands [Anderon]")
    ax.grid(alpha=0.3, which="both")
    ax.legend(loc="lower left")
    head = f"{title}: Anderon spectrum" if title else "Anderon spectrum"
    hidden = int(np.count_nonzero(~shown))
    floor_text = f"axis floor {FLOOR_FRACTION:.0e} of the largest line"
    if hidden:
        floor_text += f"; {hidden:,} smaller lines not drawn"
    ax.set_title(f"{_shorten(head, 90)}\n{floor_text}", fontsize=8)
    return ax


@style.styled
def plot_band_values(
    values: dict[str, dict[str, float]],
    title: str = "",
    ax: Any = None,
    *,
    unit: str = "Anderon",
    quantity: str = "band value",
    edges: dict[str, tuple[float, float]] | None = None,
    edge_unit: str = "waves per revolution",
) -> Any:
    """Grouped bar chart of band values ``{series name: {band: value}}``, each bar labelled.

    Parameters
    ----------
    values : dict
        Series name -> band name -> value [``unit``].
    title : str
        Figure title (the chart's own name is appended).
    ax : matplotlib Axes, optional
        Where to draw.
    unit : str
        Unit of the values: ``"Anderon"`` (seed 002 bands) or ``"um/s"`` (ISO 15242 rms
        velocity).
    quantity : str
        What a bar is, in words (``"band value"``, ``"rms velocity"``).
    edges : dict, optional
        Band name -> (low, high) [``edge_unit``], written under each band's name.
    edge_unit : str
        Unit of ``edges`` (``"waves per revolution"``, ``"Hz"``).

    Returns
    -------
    matplotlib Axes
    """
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 3.8))
    series = list(values)
    names = list(values[series[0]]) if series else []
    width = 0.8 / max(1, len(series))
    pos = np.arange(len(names))
    heights_all = [float(values[s][n]) for s in series for n in names]
    positive = [h for h in heights_all if h > 0.0]
    # a log axis shows bands decades apart; a zero band would vanish from it
    log = (
        bool(positive) and len(positive) == len(heights_all) and max(positive) > 20 * min(positive)
    )
    for i, s in enumerate(series):
        heights = [values[s][n] for n in names]
        bars = ax.bar(pos + i * width, heights, width, label=s)
        # side by side bars are narrow: their values are written upwards
        ax.bar_label(bars, fmt="%.3g", fontsize=7, padding=2, rotation=90 if len(series) > 1 else 0)
    ticks = [
        f"{n}\n{_num(edges[n][0])}-{_num(edges[n][1])}" if edges and n in edges else n
        for n in names
    ]
    ax.set_xticks(pos + width * (len(series) - 1) / 2, ticks)
    if log:
        ax.set_yscale("log")
        style.log_labels(ax)
        ax.set_ylim(min(positive) / 3.0, max(positive) * 8.0)  # room for the values on top
        _thin_log_minor(ax)
    elif positive:
        ax.set_ylim(0.0, max(positive) * 1.3)
    ax.set_xlabel(style.axis_label("band (edges)" if edges else "band", edge_unit))
    ax.set_ylabel(style.axis_label(quantity, unit))
    if len(series) > 1:
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    ax.grid(alpha=0.3, axis="y")
    ax.grid(False, axis="x")
    what = "Anderon bands" if unit == "Anderon" else f"bands [{unit}]"
    ax.set_title(_shorten(f"{title}: {what}" if title else what, 90))
    return ax


@style.styled
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
    names: Sequence[str] | None = None,
) -> list[Path]:
    """Save the linear model's waveform, Anderon spectrum and band chart as PNG files.

    :func:`plot_density_waveform`, :func:`plot_anderon_spectrum` (with the first series of
    ``band_values``) and :func:`plot_band_values` (every series).

    Parameters
    ----------
    directory : Path
        Existing output directory.
    title : str
        Case title, put ahead of each figure's own title.
    revolutions : ndarray, shape (n,)
        Rotation of the rotating ring [rev].
    density_um_per_rad : ndarray, shape (n,)
        Displacement density dx/dθ at each instant [µm/rad].
    orders : ndarray, shape (m,)
        Order of each line [waves per revolution].
    line_rms_uin_per_rad : ndarray, shape (m,)
        Rms displacement density of each line [µin/rad].
    bands : dict
        Band name -> (low, high) edges [waves per revolution].
    band_values : dict
        Series name -> band name -> Anderon value [Anderon] (at least one series).
    names : sequence of str, optional
        The figures to draw, of :data:`LINEAR_FIGURES` (default all of them).

    Returns
    -------
    list of Path
        ``density_waveform.png``, ``anderon_spectrum.png`` and ``anderon_bands.png`` in
        ``directory`` (those of ``names``, in its order).
    """
    first = next(iter(band_values.values()))
    builders = {
        "density_waveform.png": lambda: plot_density_waveform(
            revolutions, density_um_per_rad, title
        ),
        "anderon_spectrum.png": lambda: plot_anderon_spectrum(
            orders, line_rms_uin_per_rad, bands, first, title
        ),
        "anderon_bands.png": lambda: plot_band_values(band_values, title, edges=bands),
    }
    chosen = LINEAR_FIGURES if names is None else names
    unknown = [n for n in chosen if n not in builders]
    if unknown:
        raise ValueError(f"no linear figure {unknown[0]!r}; they are {', '.join(builders)}")
    return [_save(builders[name]().figure, directory / name) for name in chosen]


#: The file names of the linear model's figures (:func:`plot_linear_figures`), in order.
LINEAR_FIGURES = ("density_waveform.png", "anderon_spectrum.png", "anderon_bands.png")


# ---------------------------------------------------------------- roller_constraint model
@style.styled
def save_figure(ax: Any, path: Path, dpi: int = 120) -> Path:
    """Save the figure of ``ax`` to ``path`` and close it.

    Parameters
    ----------
    ax : matplotlib Axes
        An axes of the figure to save.
    path : Path
        File to write (its suffix gives the format, e.g. ``.png``).
    dpi : int
        Resolution [dots per inch].

    Returns
    -------
    Path
        ``path``.
    """
    return _save(ax.figure, path, dpi=dpi)


@style.styled
def plot_constraint_displacement(
    angle_deg: np.ndarray, radial: np.ndarray, horizontal: np.ndarray, ax: Any = None
) -> Any:
    """Ring-centre displacement along and across the load against the rotation angle, in µm.

    The rigid (``roller_constraint``) model's stable position of the loaded ring; the title
    gives the radial runout (peak-to-peak along the load).

    Parameters
    ----------
    angle_deg : ndarray, shape (n,)
        Rotation angle of the turning ring [deg].
    radial, horizontal : ndarray, shape (n,)
        Displacement of the ring centre along and across the load [m].
    ax : matplotlib Axes, optional
        Where to draw (a new figure by default).

    Returns
    -------
    matplotlib Axes
    """
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


@style.styled
def plot_contact_pattern(
    angle_deg: np.ndarray, touching: np.ndarray, pair: np.ndarray, ax: Any = None
) -> Any:
    """Which rollers touch the loaded ring at each angle (dots) and which two hold it (line).

    Rollers are numbered from 1 on the y axis.

    Parameters
    ----------
    angle_deg : ndarray, shape (n,)
        Rotation angle of the turning ring [deg].
    touching : ndarray of bool, shape (n, Z)
        Whether each roller touches the loaded ring at each angle.
    pair : ndarray of int, shape (n, 2)
        The two rollers (0-based) whose contacts hold the ring at each angle.
    ax : matplotlib Axes, optional
        Where to draw (a new figure by default).

    Returns
    -------
    matplotlib Axes
    """
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 3.5))
    rows, cols = np.nonzero(touching)
    ax.scatter(angle_deg[rows], cols + 1, s=2, c="C0", label="touching")
    ax.scatter(angle_deg, pair[:, 0] + 1, s=0.5, c="C1", label="holding (left)")
    ax.scatter(angle_deg, pair[:, 1] + 1, s=0.5, c="C2", label="holding (right)")
    ax.set_xlabel("rotation angle of the turning ring [deg]")
    ax.set_ylabel(style.axis_label("roller number", "-"))
    ax.set_yticks(range(1, touching.shape[1] + 1))
    ax.set_title("contact pattern")
    ax.legend(loc="upper right", fontsize=7, markerscale=4)
    ax.grid(alpha=0.3)
    return ax


@style.styled
def plot_order_sweep(
    orders: np.ndarray,
    runout: np.ndarray,
    parts: tuple[str, ...],
    baseline: float,
    n_elements: int,
    ax: Any = None,
    solved: np.ndarray | None = None,
) -> Any:
    """Runout against the harmonic order of each part, with multiples of Z marked.

    One curve per part, the perfect bearing's runout as a dotted line and the multiples of Z as
    dashed ones; an order whose harmonic jams the rollers or makes its part non-convex
    (``solved`` false) is a gap in its
    curve, marked by an x on the axis.

    Parameters
    ----------
    orders : ndarray of int, shape (m,)
        Harmonic orders swept [-].
    runout : ndarray, shape (len(parts), m)
        Radial runout p-p along the load, one row per part [m].
    parts : tuple of str
        The parts swept (``"inner"``, ``"outer"``, ``"roller"``), the curves' labels.
    baseline : float
        Runout of the same bearing with perfect parts [m].
    n_elements : int
        Number of rollers Z [-].
    ax : matplotlib Axes, optional
        Where to draw (a new figure by default).
    solved : ndarray of bool, shape (len(parts), m), optional
        Where the bearing has a stable position (default: everywhere).

    Returns
    -------
    matplotlib Axes
    """
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 3.5))
    ok = np.ones(runout.shape, dtype=bool) if solved is None else np.asarray(solved, dtype=bool)
    for j, part in enumerate(parts):
        shown = np.ma.masked_where(~ok[j], runout[j] * 1e6)  # a jammed order: a gap
        (curve,) = ax.plot(orders, shown, marker="o", ms=3, lw=0.8, label=part)
        jammed = orders[~ok[j]]
        if jammed.size:
            ax.plot(
                jammed, np.zeros(jammed.size), "x", color=curve.get_color(), ms=5,
                label=f"{part}: jammed or not convex",
            )  # fmt: skip
    ax.axhline(baseline * 1e6, color="k", lw=0.6, ls=":", label="perfect parts")
    for m in range(1, int(orders.max()) // n_elements + 1):
        ax.axvline(m * n_elements, color="grey", lw=0.6, ls="--")
    ax.set_xlabel(
        style.axis_label(f"harmonic order (dashed: multiples of Z = {n_elements})", "lobes")
    )
    ax.set_ylabel("radial runout p-p [µm]")
    ax.set_title("runout against the number of lobes")
    ax.legend(loc="best", fontsize=8)
    ax.grid(alpha=0.3)
    return ax


# --------------------------------------------------------------------------------------------
# dynamic model (seed 003)
# --------------------------------------------------------------------------------------------
@style.styled
def plot_dynamic_spectrum(result: RunResult, ax: Any = None, f_max: float | None = None) -> Any:
    """Hann amplitude spectrum (p-p) of x and y on a log axis, the largest fitted lines labelled.

    The look of seed 003 Figs. 3-4 (FFT of the steady-state displacement), with our labels:
    ball passage and its harmonics, unbalance, natural frequencies, waviness lines. The axis
    starts :data:`FLOOR_FRACTION` below the largest peak (stated in the title); a long spectrum
    is drawn through its min/max envelope (every peak kept).

    Parameters
    ----------
    result : RunResult
        A time-history result (at least two instants, evenly spaced).
    ax : matplotlib Axes, optional
        Where to draw (a new figure, laid out before labels are placed, by default).
    f_max : float, optional
        Highest frequency drawn [Hz]; by default 8 times the ball-passage frequency (a tenth
        of the sample rate for a result without dynamic details), at most the Nyquist
        frequency.

    Returns
    -------
    matplotlib Axes
    """
    from runout.analysis.spectrum import amplitude_spectrum

    plt = pyplot()
    own = ax is None
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 4.2))
    fs = 1.0 / float(result.time[1] - result.time[0])
    spec = amplitude_spectrum(result.displacement[:2], sample_rate=fs)
    from runout.analysis.result_details import DynamicDetails

    details = result.details
    fbp = details.ball_passage_hz if isinstance(details, DynamicDetails) else fs / 10
    top = f_max if f_max is not None else min(0.5 * fs, 8.0 * fbp)
    keep = spec.frequencies <= top
    lines = [c for c in result.lines() if c.direction != "z" and c.frequency_hz <= top]
    resolution = _resolution_m(result)
    lines = [c for c in lines if c.pp_m > resolution]
    peak_m = max([float(spec.pp[:2, keep].max(initial=0.0)), *(c.pp_m for c in lines)], default=0.0)
    unit, scale = style.length_scale([max(peak_m, resolution)])
    floor_m, floor_text = _floor(peak_m, resolution, "peak")
    floor = floor_m * scale
    drawn = 0
    if peak_m > resolution:
        for k, name in enumerate("xy"):
            f = spec.frequencies[keep]
            pp = spec.pp[k, keep] * scale
            idx = envelope_indices(pp, MAX_CURVE_POINTS // 2)
            drawn = max(drawn, idx.size)
            # values under the floor are drawn at it (a log axis has no zero)
            ax.plot(
                f[idx],
                np.maximum(pp[idx], floor),
                lw=0.8,
                color=style.DIRECTION_COLOURS[name],
                label=name,
            )
        ax.set_yscale("log")
        style.log_labels(ax)
        ax.set_ylim(floor, peak_m * scale * 6.0)
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
        _thin_log_minor(ax)
    else:
        # a spectrum of numerical noise is not a result: say so instead of drawing it
        ax.set_yscale("log")
        style.log_labels(ax)
        ax.set_ylim(floor, floor * 1e4)
        ax.set_xlim(0.0, top)
        _below_resolution(ax, resolution, "the motion")
        floor_text = "the response is steady to within the solver's resolution"
    ax.set_xlabel(style.axis_label("frequency", "Hz"))
    ax.set_ylabel(style.axis_label("peak-to-peak", unit))
    items = _line_labels(lines, 6, lambda c: c.frequency_hz, lambda v: f"at {v:.4g} Hz")
    head = f"{result.title or result.model}: spectrum of the rotor displacement"
    note = _decimated(drawn, int(np.count_nonzero(keep)), "min and max of each pixel column")
    _label_largest(ax, items, scale, _shorten(head, 90), floor_text + note, own, "largest lines")
    return ax


@style.styled
def plot_dynamic_figures(result: RunResult, directory: Path) -> list[Path]:
    """``spectrum.png`` of a dynamic run (the standard figures are written separately).

    Parameters
    ----------
    result : RunResult
        A result of the ``dynamic`` model.
    directory : Path
        Existing output directory.

    Returns
    -------
    list of Path
        ``spectrum.png`` in ``directory``, drawn by :func:`plot_dynamic_spectrum`.
    """
    return [_save(plot_dynamic_spectrum(result).figure, directory / "spectrum.png")]


# -------------------------------------------------------------------------------------------
# result.plot(kind=...): one figure of a result or study, from Python
# -------------------------------------------------------------------------------------------
#: Kinds of :meth:`runout.analysis.results.RunResult.plot`, with what each draws.
RUN_KINDS = {
    "lines": "p-p of the labelled lines against their order",
    "history": "x, y (and z) about their mean against revolutions (or time)",
    "orbit": "the orbit of the ring centre in the x-y plane",
    "spectrum": "the amplitude spectrum of x and y against frequency",
}


@style.styled
def plot_run(result: RunResult, kind: str = "lines", ax: Any = None, **options: Any) -> Any:
    """One figure of a run result, by name (:meth:`runout.analysis.results.RunResult.plot`).

    Parameters
    ----------
    result : RunResult
        The result.
    kind : {"lines", "history", "orbit", "spectrum"}
        Which figure (:data:`RUN_KINDS`): :func:`plot_lines`, :func:`plot_time_history`,
        :func:`plot_orbit` or :func:`plot_dynamic_spectrum`.
    ax : matplotlib Axes, optional
        Where to draw (a new figure by default).
    **options
        Keyword arguments of the drawing function (``top``, ``revolutions``, ``f_max``, ...).

    Returns
    -------
    matplotlib Axes

    Raises
    ------
    ValueError
        An unknown ``kind``, or a result of one instant (the equilibrium model) asked for a
        figure of a record.
    """
    drawers: dict[str, Any] = {
        "lines": plot_lines,
        "history": plot_time_history,
        "orbit": plot_orbit,
        "spectrum": plot_dynamic_spectrum,
    }
    if kind not in drawers:
        raise ValueError(f"kind must be one of {', '.join(map(repr, drawers))}; got {kind!r}")
    if result.time.size < 2:
        raise ValueError(
            f"the {result.model} model gives one instant, not a record: no {kind} figure "
            "(its numbers are in result.to_json())"
        )
    return drawers[kind](result, ax=ax, **options)


def plot_result(result: RunResult, kind: str = "lines", ax: Any = None, **options: Any) -> Any:
    """One figure of a run result, by name: the figure :func:`plot_run` draws into.

    Parameters
    ----------
    result : RunResult
        The result (also one read back: :func:`runout.io.result_files.read_result`).
    kind : {"lines", "history", "orbit", "spectrum"}
        Which figure (:data:`RUN_KINDS`).
    ax : matplotlib Axes, optional
        Where to draw (a new figure by default).
    **options
        Keyword arguments of the drawing function.

    Returns
    -------
    matplotlib Figure
    """
    return plot_run(result, kind, ax=ax, **options).figure


def _num(value: float) -> str:
    """``value`` to 3 significant digits, without an exponent below 10^6 (``1800``, ``0.167``)."""
    return f"{float(f'{value:.3g}'):g}"


# the figures of studies and sweeps live in runout.report._plot_study; their names stay
# importable from here
from runout.report._plot_study import (  # noqa: E402
    _RUNOUT_NAMES,  # noqa: F401 - part of the figures' vocabulary (tests)
    STUDY_KINDS,  # noqa: F401 - the kinds of StudyResult.plot
    _key_unit_kind,  # noqa: F401 - used by runout.study.run
    _sweep_axis,  # noqa: F401 - used by the tests
    plot_dynamic_sweep,
    plot_study,
    plot_study_kind,
    streamed_histograms,
    study_figures,
)
