"""Plots: the only module that imports matplotlib (lazily, Agg backend).

Every function takes result data and a directory or an Axes and returns what it drew; no
numerics happen here beyond decimation (at most :data:`MAX_CURVE_POINTS` points a curve, every
peak kept), label placement and drawing a fitted law over a histogram. Every figure is built
in one style (:mod:`runout._plot_style`), every axis names its quantity and unit, lengths are
shown at their own scale (nm, um, mm: :func:`runout.display.length_unit`).
"""

from __future__ import annotations

import math
import textwrap
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from runout import _plot_style as style

if TYPE_CHECKING:
    from runout.results import RunResult

__all__ = [
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
    "study_figures",
]


def _top_source(component: Any) -> str:
    """The name of a line's largest source, for a plot label (its part and lobes)."""
    if component.sources:
        return str(component.sources[0].label().split(":")[0])
    return str(component.label.split(":")[0].split(";")[0].strip())


#: Most points one curve of a time history is drawn with: a min/max pair per pixel column of a
#: figure 8 in wide at 120 dpi is 1,920 points; a longer record is decimated to that envelope.
ENVELOPE_COLUMNS = 1000
#: The animation's orbit panel draws records of at most this many instants whole.
DRAW_WHOLE = 10_000
#: Grid cells across an orbit plot's larger span (its axes are about 400 pixels wide): an
#: orbit is drawn through the instants at which its path enters another cell.
ORBIT_CELLS = 500


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


#: Most points handed to matplotlib for one curve (a pixel column pair of a wide figure).
MAX_CURVE_POINTS = 2_000
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


def pyplot() -> Any:
    """matplotlib.pyplot with the non-interactive Agg backend."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return plt


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

    Parameters
    ----------
    ax : matplotlib Axes
        Where the points are (data coordinates).
    items : list of (x, y, text)
        Points and their labels, most important first.
    fontsize : float, optional
        Label font size [pt]; default :data:`runout._plot_style.ANNOTATION_SIZE`.

    Returns
    -------
    int
        Number of labels dropped for want of room.
    """
    from matplotlib.text import Text

    fig = ax.figure
    fig.canvas.draw()  # legend positions ("best") and tick labels are settled by a draw
    renderer = fig.canvas.get_renderer()
    frame = ax.get_window_extent(renderer)
    taken = [
        Text.get_window_extent(t, renderer) for t in ax.texts if t.get_visible() and t.get_text()
    ]
    legend = ax.get_legend()
    if legend is not None:
        taken.append(legend.get_window_extent(renderer))
    dropped = 0
    for x, y, text in items:
        for dx, dy, ha in _LABEL_OFFSETS:
            label = ax.annotate(
                text,
                (x, y),
                xytext=(dx, dy),
                textcoords="offset points",
                ha=ha,
                va="bottom",
                fontsize=fontsize or style.ANNOTATION_SIZE,
                # a label moved away from its point is tied to it by a thin leader
                arrowprops=(
                    None
                    if abs(dy) <= 3
                    else {"arrowstyle": "-", "lw": 0.5, "color": "0.55", "shrinkA": 0}
                ),
            )
            label.update_positions(renderer)
            box = Text.get_window_extent(label, renderer)  # the text, not its leader
            if _inside(frame, box) and not any(_overlap(box, b) for b in taken):
                taken.append(box)
                break
            label.remove()
        else:
            dropped += 1
    return dropped


def _fix_layout(fig: Any) -> None:
    """Lay ``fig`` out now (tight layout) and mark it so :func:`_save` keeps that layout.

    Labels placed by :func:`place_labels` are checked against the layout of the moment; a
    later re-layout would move the axes under them.
    """
    fig.tight_layout()
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
    # zlib level 1: a third of the encoding time for files about 5 % larger
    _finish(fig).savefig(path, dpi=dpi, pil_kwargs={"compress_level": 1})
    plt.close(fig)
    return path


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
    found = [
        float(result.extras.get("solver_resolution_m", 0.0) or 0.0),
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
        Number of balls drawn; default ``result.extras["n_elements"]`` (else 8).
    frames, fps : int
        Number of frames (<= 120) and frames per second.

    Returns
    -------
    Path
    """
    from PIL import Image, ImageDraw

    plt = pyplot()
    z = int(n_elements if n_elements is not None else result.extras.get("n_elements", 8))
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
    images = []
    for i in idx:
        img = base.copy()
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
        trace = trace_px[: i // step + 1] + px(ax2, x[i : i + 1], y[i : i + 1])
        if len(trace) >= 2:
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
    """Ball loads [N] and contact angles [deg] against the ball's azimuth (equilibrium model)."""
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
    if comps:
        ax.set_ylim(floor_m * scale, peak_m * scale * 6.0)  # headroom for labels above the top
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
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
    """The standard figures of a result, laid out, by the file name :func:`plot_result` uses.

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
    if not (math.isfinite(history_revolutions) and history_revolutions > 0):
        raise ValueError(
            f"history_revolutions must be a positive number, got {history_revolutions!r}"
        )
    if result.time.size < 2:  # a single instant (equilibrium model): nothing to draw
        return {}
    return {
        "history.png": _finish(plot_time_history(result, revolutions=history_revolutions).figure),
        "orbit.png": _finish(plot_orbit(result).figure),
        "lines.png": _finish(plot_lines(result).figure),
    }


@style.styled
def plot_result(
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
    ax.set_ylim(floor, 3.0 * max([top, *bars]))
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
        ax.set_ylim(min(positive) / 3.0, max(positive) * 8.0)  # room for the values on top
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
) -> list[Path]:
    """Save the linear model's waveform, Anderon spectrum and band chart as PNG files."""
    first = next(iter(band_values.values()))
    figures = (
        ("density_waveform.png", plot_density_waveform(revolutions, density_um_per_rad, title)),
        (
            "anderon_spectrum.png",
            plot_anderon_spectrum(orders, line_rms_uin_per_rad, bands, first, title),
        ),
        ("anderon_bands.png", plot_band_values(band_values, title, edges=bands)),
    )
    return [_save(ax.figure, directory / name) for name, ax in figures]


# ---------------------------------------------------------------- roller_constraint model
@style.styled
def save_figure(ax: Any, path: Path, dpi: int = 120) -> Path:
    """Save the figure of ``ax`` to ``path`` and close it."""
    return _save(ax.figure, path, dpi=dpi)


@style.styled
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


@style.styled
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
    """
    from runout.spectrum import amplitude_spectrum

    plt = pyplot()
    own = ax is None
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 4.2))
    fs = 1.0 / float(result.time[1] - result.time[0])
    spec = amplitude_spectrum(result.displacement[:2], sample_rate=fs)
    fbp = float(result.extras.get("ball_passage_hz", fs / 10))
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
        ax.set_ylim(floor, peak_m * scale * 6.0)
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    else:
        # a spectrum of numerical noise is not a result: say so instead of drawing it
        ax.set_yscale("log")
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
    """``spectrum.png`` of a dynamic run (the standard figures are written separately)."""
    return [_save(plot_dynamic_spectrum(result).figure, directory / "spectrum.png")]


def _sweep_panels(points: list[Any], key: str, title: str, path: Path) -> Path:
    plt = pyplot()
    n = len(points)
    cols = 2 if n > 1 else 1
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(5.5 * cols, 2.6 * rows), squeeze=False)
    peak = max((float(np.max(pt.spectrum_pp_m, initial=0.0)) for pt in points), default=0.0)
    unit, scale = style.length_scale([peak])
    for ax, pt in zip(axes.flat, points, strict=False):
        f = np.asarray(pt.spectrum_hz)
        pp = np.asarray(pt.spectrum_pp_m) * scale
        idx = envelope_indices(pp, MAX_CURVE_POINTS // 2)
        ax.plot(f[idx], pp[idx], lw=0.8, color="C0")
        for m in range(1, 4):
            ax.axvline(m * pt.ball_passage_hz, color="C1", lw=0.6, ls="--")
        for fn in pt.natural_frequencies_hz:
            if fn <= (f.max() if f.size else 0.0):
                ax.axvline(fn, color="C2", lw=0.6, ls=":")
        label = f"Z = {pt.elements}" if key == "elements" else f"preload {pt.preload_n:g} N"
        ax.set_title(
            f"{label}: BPF {pt.ball_passage_hz:.4g} Hz, f_n "
            + "/".join(f"{v:.4g}" for v in pt.natural_frequencies_hz)
            + " Hz",
            fontsize=8,
        )
        ax.set_ylabel(style.axis_label("p-p", unit), fontsize=8)
        ax.set_xlabel(style.axis_label("frequency", "Hz"), fontsize=8)
        ax.tick_params(labelsize=7)
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    fig.suptitle(title + "  (dashed: 1-3 x ball passage; dotted: natural frequencies)", fontsize=9)
    return _save(fig, path, dpi=110)


@style.styled
def plot_dynamic_sweep(
    points: list[Any], elements: list[int], preloads: list[float], out: Path, title: str = ""
) -> list[Path]:
    """Seed 003 Fig. 3/4-style panels of a sweep, and ``trend.png`` of the ball-passage line.

    ``spectra_elements_P<p>N.png``: one panel per number of balls at each preload;
    ``spectra_preload_Z<z>.png``: one panel per preload at each number of balls;
    ``trend.png``: p-p of the ball-passage line along the measuring direction (log scale).
    """
    plt = pyplot()
    written: list[Path] = []
    if len(elements) > 1:
        for p in preloads:
            chosen = [pt for pt in points if pt.preload_n == p]
            written.append(
                _sweep_panels(
                    chosen,
                    "elements",
                    f"{title}: effect of the number of balls (preload {p:g} N)",
                    out / f"spectra_elements_P{p:g}N.png",
                )
            )
    if len(preloads) > 1:
        for z in elements:
            chosen = [pt for pt in points if pt.elements == z]
            written.append(
                _sweep_panels(
                    chosen,
                    "preload",
                    f"{title}: effect of the preload (Z = {z})",
                    out / f"spectra_preload_Z{z}.png",
                )
            )
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8))
    unit, scale = style.length_scale([pt.ball_passage_pp_m for pt in points])
    for p in preloads:
        chosen = [pt for pt in points if pt.preload_n == p]
        axes[0].semilogy(
            [pt.elements for pt in chosen],
            [max(pt.ball_passage_pp_m, 1e-18) * scale for pt in chosen],
            "o-",
            label=f"{p:g} N",
        )
    for z in elements:
        chosen = [pt for pt in points if pt.elements == z]
        axes[1].semilogy(
            [pt.preload_n for pt in chosen],
            [max(pt.ball_passage_pp_m, 1e-18) * scale for pt in chosen],
            "o-",
            label=f"Z = {z}",
        )
    axes[0].set_xlabel(style.axis_label("number of balls", "-"))
    axes[1].set_xlabel(style.axis_label("axial preload", "N"))
    for ax in axes:
        ax.set_ylabel(style.axis_label("ball-passage line p-p", unit))
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
    fig.suptitle(f"{title}: ball-passage vibration", fontsize=10)
    written.append(_save(fig, out / "trend.png", dpi=110))
    return written


# --------------------------------------------------------------------------------------------
# studies
# --------------------------------------------------------------------------------------------
#: Short names of the runout outputs of a study (panel titles, axis labels, legends).
_RUNOUT_NAMES = {
    "radial_pp_m": "radial p-p",
    "rro_pp_m": "RRO p-p",
    "nrro_pp_m": "NRRO p-p",
    "axial_pp_m": "axial p-p",
}


def _num(value: float) -> str:
    """``value`` to 3 significant digits, without an exponent below 10^6 (``1800``, ``0.167``)."""
    return f"{float(f'{value:.3g}'):g}"


def _shorten(text: str, limit: int) -> str:
    """``text`` cut to ``limit`` characters, an ellipsis marking the cut."""
    return text if len(text) <= limit else text[: limit - 3].rstrip() + "..."


def _unique_names(rows: list[tuple[str, str]]) -> list[str]:
    """Short names (``"x: inner 8 lobes"``) of (direction, label) lines, all different.

    The short name is the direction and the first source's part and lobes; where two lines
    would read the same, their labels are given in full (cut at 60 characters), and if that
    still does not tell them apart they are numbered.
    """
    short = [f"{d}: {label.split(';')[0].split(':')[0].strip()}" for d, label in rows]
    out = [
        s if short.count(s) == 1 else _shorten(f"{d}: {label}", 60)
        for s, (d, label) in zip(short, rows, strict=True)
    ]
    counts: dict[str, int] = {}
    for i, name in enumerate(list(out)):
        if out.count(name) > 1:
            counts[name] = counts.get(name, 0) + 1
            out[i] = f"{name} #{counts[name]}"
    return out


def _same(a: np.ndarray, b: np.ndarray) -> bool:
    """Whether two per-sample outputs are the same array (to round-off)."""
    return a.shape == b.shape and bool(np.allclose(a, b, rtol=1e-12, atol=0.0, equal_nan=True))


def _fmt(value_m: float, unit: str, scale: float) -> str:
    """A length at the unit of the panel it is drawn on (``"0.5 um"``)."""
    from runout.display import format_length

    return format_length(value_m, (unit, scale))


def _histogram_panel(
    ax: Any,
    title: str,
    quantity: str,
    values_m: np.ndarray,
    law: str,
    bins: int,
    limit_m: float | None,
) -> None:
    """One Monte Carlo histogram [count per bin], its fitted law and a spec-limit line.

    ``law`` is ``"rayleigh"`` (scale by maximum likelihood, sigma^2 = mean(x^2) / 2) or
    ``"normal"`` (sample mean and standard deviation); the law is drawn as its density times
    the number of samples times the bin width, on the histogram's own scale.
    """
    unit, scale = style.length_scale([*values_m, *([limit_m] if limit_m is not None else [])])
    v = values_m * scale
    spread = float(np.ptp(v)) if v.size else 0.0
    flat = spread <= 1e-9 * max(float(np.max(np.abs(v), initial=0.0)), 1e-300)
    if flat:
        # one value for the whole lot: one narrow bar at it (a histogram has no width to bin)
        v0 = float(v[0]) if v.size else 0.0
        half = max(0.5 * abs(v0), 1.0)
        ax.bar([v0], [v.size], width=0.06 * half, color=style.HIST_COLOUR, alpha=0.8)
        ax.set_xlim(v0 - half, v0 + half)
        counts = np.array([v.size])
    else:
        counts, edges, _ = ax.hist(v, bins=bins, color=style.HIST_COLOUR, alpha=0.8)
    if not flat and v.size >= 2:
        width = float(edges[1] - edges[0])
        grid = np.linspace(float(edges[0]), float(edges[-1]), 200)
        if law == "rayleigh":
            s2 = float(np.mean(v**2)) / 2.0
            pdf = grid / s2 * np.exp(-(grid**2) / (2.0 * s2))
            fit = f"Rayleigh fit, σ = {math.sqrt(s2):.3g} {unit}"
        else:
            mean, std = float(np.mean(v)), float(np.std(v, ddof=1))
            pdf = np.exp(-0.5 * ((grid - mean) / std) ** 2) / (std * math.sqrt(2.0 * math.pi))
            fit = f"normal fit, σ = {std:.3g} {unit}"
        ax.plot(grid, pdf * v.size * width, color=style.FIT_COLOUR, lw=1.1, label=fit)
    if limit_m is not None:
        x = limit_m * scale
        ax.axvline(
            x,
            color=style.LIMIT_COLOUR,
            lw=1.4,
            ls="--",
            label=f"limit {_fmt(limit_m, unit, scale)}",
        )
        lo, hi = ax.get_xlim()
        pad = 0.05 * max(hi - lo, abs(x), 1e-300)
        ax.set_xlim(min(lo, x - pad), max(hi, x + pad))
    # headroom above the tallest bar for the legend (it holds the fit and the limit's text)
    ax.set_ylim(0, max(float(np.max(counts, initial=0.0)), 1.0) * 1.5)
    if flat:  # one value for every bearing: say which
        title = f"{_shorten(title, 48)}: {_fmt(float(values_m[0]), unit, scale)} in every sample"
    ax.set_title(_shorten(title, 70), fontsize=8)
    ax.set_xlabel(style.axis_label(quantity, unit))
    ax.set_ylabel(style.axis_label("bearings", "count per bin"))
    if ax.get_legend_handles_labels()[0]:
        ax.legend(loc="upper right", fontsize=6.5)


def _montecarlo_panels(
    result: Any, top: int, ok: np.ndarray
) -> list[tuple[str, str, np.ndarray, str, str | None]]:
    """(title, axis quantity, values [m], law, runout key) of each histogram, identical merged."""
    panels: list[tuple[list[str], str, np.ndarray, str, str | None]] = []
    candidates: list[tuple[str, str, np.ndarray, str, str | None]] = [
        (name, name, np.asarray(result.runout[key])[ok], "normal", key)
        for key, name in _RUNOUT_NAMES.items()
        if key in result.runout and (key != "axial_pp_m" or np.any(result.runout[key][ok]))
    ]
    rows = [row for row in result.line_table() if row[0] in ("x", "z")][:top]
    names = _unique_names([(d, label) for d, _f, label, _pp in rows])
    candidates += [
        (f"{name} ({f:.4g} Hz)", "line p-p", pp[ok], "rayleigh", None)
        for name, (_d, f, _label, pp) in zip(names, rows, strict=True)
    ]
    for title, quantity, values, law, key in candidates:
        for entry in panels:
            if _same(values, entry[2]):
                entry[0].append(title)
                # the limit belongs to whichever name it was set on
                if key is not None and entry[4] is None:
                    panels[panels.index(entry)] = (entry[0], entry[1], entry[2], entry[3], key)
                break
        else:
            panels.append(([title], quantity, values, law, key))
    out = []
    for titles, quantity, values, law, key in panels:
        if len(titles) > 1:
            title = " = ".join(t.split(" (")[0] for t in titles) + " (the same in every sample)"
            quantity = "p-p"
        else:
            title = titles[0]
        out.append((title, quantity, values, law, key))
    return out


@style.styled
def study_figures(
    result: Any,
    top: int = 4,
    *,
    limit_quantity: str | None = None,
    limit_m: float | None = None,
) -> dict[str, Any]:
    """Figures of a :class:`runout.study.StudyResult`, laid out, by file name.

    Monte Carlo: ``histograms.png``, one panel per output: radial p-p, RRO, NRRO (and axial
    p-p when it moves) and the ``top`` largest lines in x and z. Outputs that are the same
    array in every sample are drawn once, the panel's title naming all of them. The runout
    outputs carry a fitted normal law (mean and sample standard deviation), the lines a
    fitted Rayleigh law (a line's amplitude from random phases; scale by maximum
    likelihood, sigma^2 = mean(x^2)/2). A spec limit is drawn on the histogram of
    ``limit_quantity``.

    Sweep: ``sweep_<key>.png`` for each scalar swept quantity: the runout outputs and the
    ``top`` largest lines (one curve per line, lines being told apart by label and direction)
    against it, one set of curves per model; the axis is named after the key in words with its
    unit (``"axial load [N]"``, ``"speed [rpm]"``).

    Parameters
    ----------
    result : StudyResult
        The study.
    top : int
        Number of lines drawn.
    limit_quantity : str, optional
        Key of ``result.runout`` (``"radial_pp_m"``, ``"rro_pp_m"``, ``"nrro_pp_m"``, ...)
        whose histogram carries the limit.
    limit_m : float, optional
        The spec limit [m] (with ``limit_quantity``).

    Returns
    -------
    dict
        File name -> matplotlib Figure (the caller saves or closes them).
    """
    if (limit_quantity is None) != (limit_m is None):
        raise ValueError("plot_study: give limit_quantity and limit_m together")
    if limit_quantity is not None and limit_quantity not in result.runout:
        raise ValueError(
            f"plot_study: limit_quantity {limit_quantity!r} is not one of {sorted(result.runout)}"
        )
    if limit_m is not None and not (math.isfinite(limit_m) and limit_m > 0):
        raise ValueError(f"plot_study: limit_m must be a positive length, got {limit_m!r}")
    plt = pyplot()
    ok = np.isfinite(result.runout["radial_pp_m"])
    heading = _shorten(result.title or "study", 110)
    if result.kind == "montecarlo" and not ok.any():
        # no sample to draw: say so rather than draw empty axes
        fig, ax = plt.subplots(figsize=(6, 2))
        ax.set_axis_off()
        ax.text(
            0.5,
            0.5,
            f"all {result.samples} samples failed: nothing to draw\n"
            "(their errors are in summary.json)",
            ha="center",
            va="center",
            transform=ax.transAxes,
        )
        fig.suptitle(heading)
        return {"histograms.png": _finish(fig)}
    if result.kind == "montecarlo":
        panels = _montecarlo_panels(result, top, ok)
        if limit_quantity is not None and not any(p[4] == limit_quantity for p in panels):
            # an output not drawn by default (axial p-p of a planar lot): give it its panel
            name = _RUNOUT_NAMES.get(limit_quantity, limit_quantity)
            values = np.asarray(result.runout[limit_quantity])[ok]
            panels.append((name, name, values, "normal", limit_quantity))
        cols = 2
        rows = (len(panels) + 1) // 2
        fig, axes = plt.subplots(rows, cols, figsize=(10, 3.1 * rows), squeeze=False)
        for ax, (title, quantity, values, law, key) in zip(axes.flat, panels, strict=False):
            limit = limit_m if key is not None and key == limit_quantity else None
            _histogram_panel(ax, title, quantity, values, law, result.bins, limit)
        for ax in list(axes.flat)[len(panels) :]:
            ax.set_visible(False)
        failed = int(np.count_nonzero(~ok))
        note = f" ({failed} failed, not drawn)" if failed else ""
        fig.suptitle(f"{heading}: {result.samples} samples{note}")
        return {"histograms.png": _finish(fig)}
    return _sweep_figures(result, top)


@style.styled
def plot_study(
    result: Any,
    directory: Path,
    top: int = 4,
    *,
    limit_quantity: str | None = None,
    limit_m: float | None = None,
) -> list[Path]:
    """Save the figures of a study (:func:`study_figures`) in ``directory``.

    Monte Carlo: ``histograms.png``; sweep: ``sweep_<key>.png`` per scalar swept quantity.
    Parameters as :func:`study_figures`; returns the paths written.
    """
    figures = study_figures(result, top, limit_quantity=limit_quantity, limit_m=limit_m)
    return [_save(fig, directory / name, dpi=110) for name, fig in figures.items()]


def _key_unit_kind(path: tuple[str, int | None, str]) -> str | None:
    """Unit kind (:data:`runout.units.KINDS`) of the case key at ``path``, read off the schema.

    The case schema marks each quantity field with the kind its converter reads; the mark can
    sit inside an optional type (``Length | None``), so the whole annotation is searched.
    """
    import typing

    from runout.case import CaseSpec, _table_type

    table, _index, name = path
    field = CaseSpec.model_fields.get(table)
    model = _table_type(field.annotation) if field is not None else None
    info = getattr(model, "model_fields", {}).get(name)
    if info is None:
        return None

    def search(obj: Any) -> str | None:
        for meta in getattr(obj, "__metadata__", ()) or ():
            kind = getattr(getattr(meta, "func", None), "kind", None)
            if kind is not None:
                return str(kind)
        for arg in typing.get_args(obj):
            found = search(arg)
            if found is not None:
                return found
        return None

    for meta in info.metadata:
        kind = getattr(getattr(meta, "func", None), "kind", None)
        if kind is not None:
            return str(kind)
    return search(info.annotation)


#: How a swept quantity of each unit kind is shown: (unit, factor from SI) - the engineer's
#: units (rpm, deg); lengths choose their unit from the values.
_SHOWN_UNITS = {"speed": ("rpm", 60.0), "angle": ("deg", 180.0 / math.pi)}


def _sweep_axis(q: Any, x_si: np.ndarray) -> tuple[str, float]:
    """Axis label (``"axial load [N]"``) and factor from SI for a swept quantity."""
    from runout.units import KINDS

    table, index, name = q.path
    words = name.replace("_", " ")
    if index is not None:
        words = f"{table.replace('_', ' ')} {index}: {words}"
    kind = _key_unit_kind(q.path)
    if kind == "length":
        unit, scale = style.length_scale(x_si)
    elif kind in _SHOWN_UNITS:
        unit, scale = _SHOWN_UNITS[kind]
    elif kind is not None and KINDS[kind][1]:
        unit, scale = KINDS[kind][1], 1.0
    else:  # a count or a ratio (number of balls, conformity): a pure number
        unit, scale = "-", 1.0
    return style.axis_label(words, unit), scale


def _sweep_figures(result: Any, top: int) -> dict[str, Any]:
    """``sweep_<key>.png`` of each scalar swept quantity (see :func:`study_figures`)."""
    plt = pyplot()
    written: dict[str, Any] = {}
    models = sorted(set(result.model))
    runout = [
        (_RUNOUT_NAMES[k], np.asarray(result.runout[k]))
        for k in ("radial_pp_m", "rro_pp_m", "nrro_pp_m")
    ]
    # identical outputs (RRO = radial of a model without NRRO) are one curve, named for both
    merged: list[tuple[str, np.ndarray]] = []
    for name, y in runout:
        for i, (other, yy) in enumerate(merged):
            if _same(y, yy):
                merged[i] = (f"{other} = {name}", yy)
                break
        else:
            merged.append((name, y))
    rows = [row for row in result.line_table() if row[0] in ("x", "z")][:top]
    names = _unique_names([(d, label) for d, _f, label, _pp in rows])
    lines = [(name, pp) for name, (_d, _f, _l, pp) in zip(names, rows, strict=True)]
    for q in result.quantities:
        values = result.values[q.key]
        if q.size > 1 or not all(isinstance(v, int | float) for v in values):
            continue
        x_si = np.asarray(values, dtype=np.float64)
        xlabel, xscale = _sweep_axis(q, x_si)
        fig, axes = plt.subplots(1, 2, figsize=(12, 4.2))
        for ax, what, series in zip(
            axes, ("runout outputs", "largest lines"), (merged, lines), strict=True
        ):
            unit, scale = style.length_scale(
                np.concatenate([y for _, y in series]) if series else []
            )
            for m_i, m in enumerate(models):
                mask = np.array([mm == m for mm in result.model])
                order = np.argsort(x_si[mask], kind="stable")
                for k, (name, y) in enumerate(series):
                    label = f"{name} ({m})" if len(models) > 1 else name
                    ax.plot(
                        x_si[mask][order] * xscale,
                        y[mask][order] * scale,
                        ("o-", "s--", "^:", "d-.")[m_i % 4],
                        ms=3.5,
                        color=f"C{k % 10}",
                        label=label,
                    )
            ax.set_xlabel(xlabel)
            ax.set_ylabel(style.axis_label("peak-to-peak", unit))
            ax.set_title(what)
            if series:
                handles = len(series) * len(models)
                if handles > 4:  # a crowded legend goes beside the axes, never over the curves
                    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
                else:
                    ax.legend(loc="best")
        fig.suptitle(_shorten(result.title or "sweep", 100))
        name = "".join(ch if ch.isalnum() or ch in "._-" else "_" for ch in q.key)
        written[f"sweep_{name}.png"] = _finish(fig)
    return written


# -------------------------------------------------------------------------------------------
# result.plot(kind=...): one figure of a result or study, from Python
# -------------------------------------------------------------------------------------------
#: Kinds of :meth:`runout.results.RunResult.plot`, with what each draws.
RUN_KINDS = {
    "lines": "p-p of the labelled lines against their order",
    "history": "x, y (and z) about their mean against revolutions (or time)",
    "orbit": "the orbit of the ring centre in the x-y plane",
    "spectrum": "the amplitude spectrum of x and y against frequency",
}
#: Kinds of :meth:`runout.study.StudyResult.plot`.
STUDY_KINDS = {
    "histograms": "Monte Carlo: histograms of the runout outputs and the largest lines",
    "sweep": "sweep: runout outputs and the largest lines against a swept quantity",
}


@style.styled
def plot_run(result: RunResult, kind: str = "lines", ax: Any = None, **options: Any) -> Any:
    """One figure of a run result, by name (:meth:`runout.results.RunResult.plot`).

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


def plot_study_kind(result: Any, kind: str, quantity: str | None = None, top: int = 4) -> Any:
    """One figure of a study, by name (:meth:`runout.study.StudyResult.plot`).

    Parameters
    ----------
    result : StudyResult
        The study.
    kind : {"histograms", "sweep"}
        ``"histograms"`` for a Monte Carlo study, ``"sweep"`` for a sweep (:data:`STUDY_KINDS`).
    quantity : str, optional
        Sweep: the swept key drawn on the horizontal axis (needed when several scalar keys are
        swept).
    top : int
        Number of lines drawn.

    Returns
    -------
    matplotlib Figure

    Raises
    ------
    ValueError
        An unknown kind, a kind of the other study type, or an unknown or ambiguous quantity.
    """
    expected = {"histograms": "montecarlo", "sweep": "sweep"}
    if kind not in expected:
        raise ValueError(f"kind must be one of {', '.join(map(repr, expected))}; got {kind!r}")
    if result.kind != expected[kind]:
        other = next(k for k, v in expected.items() if v == result.kind)
        raise ValueError(f"a {result.kind} study draws kind={other!r}, not {kind!r}")
    figures = study_figures(result, top)
    if kind == "histograms":
        return figures["histograms.png"]
    by_key = {
        "sweep_"
        + "".join(ch if ch.isalnum() or ch in "._-" else "_" for ch in q.key)
        + ".png": q.key
        for q in result.quantities
    }
    drawn = {by_key[name]: fig for name, fig in figures.items() if name in by_key}
    if quantity is None:
        if len(drawn) != 1:
            for fig in drawn.values():
                pyplot().close(fig)
            raise ValueError(
                f"the sweep draws {len(drawn)} figures ({', '.join(drawn) or 'none'}): "
                "name one with quantity="
            )
        return next(iter(drawn.values()))
    if quantity not in drawn:
        for fig in drawn.values():
            pyplot().close(fig)
        raise ValueError(
            f"quantity {quantity!r} is not a drawn swept key; drawn: {', '.join(drawn) or 'none'}"
        )
    for key, fig in drawn.items():
        if key != quantity:
            pyplot().close(fig)
    return drawn[quantity]
