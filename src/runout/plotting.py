"""Plots: the only module that imports matplotlib (lazily, Agg backend).

Every function takes result data and a directory or an Axes and returns what it drew; no
numerics happen here.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from runout.results import RunResult

__all__ = [
    "animate_bearing",
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
    "plot_study",
    "plot_time_history",
    "pyplot",
    "save_figure",
]


def _top_source(component: Any) -> str:
    """The name of a line's largest source, for a plot label (its part and lobes)."""
    if component.sources:
        return str(component.sources[0].label().split(":")[0])
    return str(component.label.split(":")[0].split(";")[0].strip())


#: Most points one curve of a time history is drawn with: a min/max pair per pixel column of a
#: figure 8 in wide at 120 dpi is 1,920 points; a longer record is decimated to that envelope.
ENVELOPE_COLUMNS = 1000
#: Records of at most this many instants are drawn whole; longer ones are decimated.
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
    return np.unique(np.concatenate([[0], moved, [n - 1]]))


def _decimated(n_drawn: int, n: int, how: str) -> str:
    """Second title line saying that a curve is decimated (empty when every sample is drawn)."""
    return "" if n_drawn >= n else f"\n(decimated to {n_drawn:,} of {n:,} points, {how})"


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
    drawn = 0
    for k, name in enumerate("xyz"):
        series = result.displacement[k]
        if k == 2 and not np.any(series):
            continue
        # a long record: its min/max envelope, every peak kept
        keep = envelope_indices(series) if series.size > DRAW_WHOLE else np.arange(series.size)
        drawn = max(drawn, keep.size)
        ax.plot(result.time[keep], (series[keep] - series.mean()) * 1e9, lw=0.8, label=name)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("displacement about mean [nm]")
    ax.legend(loc="upper right")
    ax.grid(alpha=0.3)
    title = f"{result.title or result.model}: time history"
    note = _decimated(drawn, result.time.size, "min and max of each pixel column")
    ax.set_title(title + note, fontsize=9 if note else None)
    return ax


def plot_orbit(result: RunResult, ax: Any = None, arrows: int = 6) -> Any:
    """Orbit (Lissajous figure) of the ring centre in the x-y plane, in nm.

    The look of seed 000 Figs. 4-7: equal aspect, a marker at the first instant and
    ``arrows`` arrowheads along the path showing the sense of motion.
    """
    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(4.5, 4.5))
    x = (result.x - result.x.mean()) * 1e9
    y = (result.y - result.y.mean()) * 1e9
    # a long record: one point per cell of the screen it crosses
    keep = orbit_indices(x, y) if x.size > DRAW_WHOLE else np.arange(x.size)
    ax.plot(x[keep], y[keep], lw=0.6, color="C0")
    if x.size >= 2:
        ax.plot(x[0], y[0], "o", color="C3", ms=5, label="start", zorder=3)
        n = x.size
        for k in range(1, arrows + 1):
            i = min(n - 2, int(k * n / (arrows + 1)))
            ax.annotate(
                "",
                xy=(x[i + 1], y[i + 1]),
                xytext=(x[i], y[i]),
                arrowprops={"arrowstyle": "-|>", "color": "C3", "lw": 0.8, "mutation_scale": 10},
            )
        ax.legend(loc="upper right", fontsize=7)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x [nm]")
    ax.set_ylabel("y [nm]")
    ax.grid(alpha=0.3)
    note = _decimated(keep.size, x.size, "one per pixel crossed")
    ax.set_title("orbit of the ring centre" + note, fontsize=8 if note else None)
    return ax


def animate_bearing(
    result: RunResult,
    path: Path,
    *,
    n_elements: int | None = None,
    frames: int = 120,
    fps: int = 15,
) -> Path:
    """Write a GIF of the ring centre and the balls (the animation seed 000 §4 describes).

    Left: the bearing seen along its axis, balls at their cage positions, a reference mark
    turning with the rotating ring and the measured ring's centre displaced by its magnified
    displacement; right: the orbit traced so far (nm, equal aspect). Frames are spread evenly
    over the record (at most ``frames``, never more than 120).

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
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(6.4, 3.2), dpi=70)
    ax.set_xlim(-1.45, 1.45)
    ax.set_ylim(-1.45, 1.45)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.add_patch(plt.Circle((0, 0), 1.3, fill=False, lw=1.5, color="0.3"))
    ax.set_title("balls and ring centre (displacement magnified)", fontsize=7)
    # the panel is about 200 pixels wide
    keep = orbit_indices(x, y, cells=200) if n > DRAW_WHOLE else np.arange(n)
    ax2.plot(x[keep], y[keep], lw=0.3, color="0.85")
    ax2.set_aspect("equal", adjustable="datalim")
    ax2.set_xlabel("x [nm]", fontsize=7)
    ax2.set_ylabel("y [nm]", fontsize=7)
    ax2.tick_params(labelsize=6)
    ax2.set_title(f"{result.title or 'orbit'}\n({count} frames of {n:,} instants)", fontsize=7)
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
            width=2,
        )
        ang = 2 * math.pi * fr * t[i]
        (m,) = px(ax, np.array([cx + 0.6 * math.cos(ang)]), np.array([cy + 0.6 * math.sin(ang)]))
        draw.line([c, m], fill=red, width=2)
        th = 2 * np.pi * (fc * t[i] + np.arange(z) / z)
        for b in px(ax, np.cos(th), np.sin(th)):
            draw.ellipse(
                [b[0] - r_ball, b[1] - r_ball, b[0] + r_ball, b[1] + r_ball],
                fill=grey,
                outline=dark,
            )
        trace = trace_px[: i // step + 1] + px(ax2, x[i : i + 1], y[i : i + 1])
        if len(trace) >= 2:
            draw.line(trace, fill=blue, width=1)
        d = trace[-1]
        draw.ellipse([d[0] - 3, d[1] - 3, d[0] + 3, d[1] + 3], fill=red)
        images.append(img)
    images[0].save(path, save_all=True, append_images=images[1:], duration=int(1000 / fps), loop=0)
    return path


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
        short = _top_source(c)
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
    if ax.get_legend_handles_labels()[0]:
        ax.legend(loc="best")
    else:
        ax.text(
            0.5,
            0.5,
            "no lines above the solver's resolution",
            transform=ax.transAxes,
            ha="center",
            va="center",
            color="0.4",
        )
    ax.grid(alpha=0.3)
    ax.set_title("spectral lines (largest labelled; full labels in lines.csv)")
    return ax


def plot_result(result: RunResult, directory: Path) -> list[Path]:
    """Save the standard figures of a result as PNG files in ``directory``."""
    plt = pyplot()
    written: list[Path] = []
    if result.time.size < 2:  # a single instant (equilibrium model): nothing to draw
        return written
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


# --------------------------------------------------------------------------------------------
# dynamic model (seed 003)
# --------------------------------------------------------------------------------------------
def plot_dynamic_spectrum(result: RunResult, ax: Any = None, f_max: float | None = None) -> Any:
    """Hann amplitude spectrum (p-p, nm) of x and y with the largest fitted lines labelled.

    The look of seed 003 Figs. 3-4 (FFT of the steady-state displacement), with our labels:
    ball passage and its harmonics, unbalance, natural frequencies, waviness lines.
    """
    from runout.spectrum import amplitude_spectrum

    plt = pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 4))
    fs = 1.0 / float(result.time[1] - result.time[0])
    spec = amplitude_spectrum(result.displacement[:2], sample_rate=fs)
    fbp = float(result.extras.get("ball_passage_hz", fs / 10))
    top = f_max if f_max is not None else min(0.5 * fs, 8.0 * fbp)
    keep = spec.frequencies <= top
    peak = 0.0
    for k, name in enumerate("xy"):
        ax.plot(spec.frequencies[keep], spec.pp[k, keep] * 1e9, lw=0.8, label=name)
        peak = max(peak, float(spec.pp[k, keep].max()) * 1e9)
    for c in result.lines(top=8):
        if c.direction != "z" and c.frequency_hz <= top:
            peak = max(peak, c.pp_m * 1e9)
    ax.set_ylim(0.0, 1.2 * peak if peak > 0.0 else 1.0)
    for c in result.lines(top=8):
        if c.direction == "z" or c.frequency_hz > top:
            continue
        short = _top_source(c)
        ax.annotate(
            f"{short} ({c.direction})",
            (c.frequency_hz, c.pp_m * 1e9),
            xytext=(3, 3),
            textcoords="offset points",
            fontsize=7,
        )
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel("peak-to-peak [nm]")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper right")
    ax.set_title(f"{result.title or result.model}: spectrum of the rotor displacement")
    return ax


def plot_dynamic_figures(result: RunResult, directory: Path) -> list[Path]:
    """``spectrum.png`` of a dynamic run (the standard figures are written separately)."""
    plt = pyplot()
    ax = plot_dynamic_spectrum(result)
    ax.figure.tight_layout()
    path = directory / "spectrum.png"
    ax.figure.savefig(path, dpi=120)
    plt.close(ax.figure)
    return [path]


def _sweep_panels(points: list[Any], key: str, title: str, path: Path) -> Path:
    plt = pyplot()
    n = len(points)
    cols = 2 if n > 1 else 1
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(5.5 * cols, 2.4 * rows), squeeze=False)
    for ax, pt in zip(axes.flat, points, strict=False):
        f = np.asarray(pt.spectrum_hz)
        pp = np.asarray(pt.spectrum_pp_m) * 1e9
        ax.plot(f, pp, lw=0.8, color="C0")
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
        ax.set_ylabel("p-p [nm]", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.grid(alpha=0.3)
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    for ax in axes[-1]:
        ax.set_xlabel("frequency [Hz]", fontsize=8)
    fig.suptitle(title + "  (dashed: 1-3 x ball passage; dotted: natural frequencies)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


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
    for p in preloads:
        chosen = [pt for pt in points if pt.preload_n == p]
        axes[0].semilogy(
            [pt.elements for pt in chosen],
            [max(pt.ball_passage_pp_m, 1e-18) * 1e9 for pt in chosen],
            "o-",
            label=f"{p:g} N",
        )
    for z in elements:
        chosen = [pt for pt in points if pt.elements == z]
        axes[1].semilogy(
            [pt.preload_n for pt in chosen],
            [max(pt.ball_passage_pp_m, 1e-18) * 1e9 for pt in chosen],
            "o-",
            label=f"Z = {z}",
        )
    axes[0].set_xlabel("number of balls")
    axes[1].set_xlabel("axial preload [N]")
    for ax in axes:
        ax.set_ylabel("ball-passage line p-p [nm]")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
    fig.suptitle(f"{title}: ball-passage vibration", fontsize=10)
    fig.tight_layout()
    path = out / "trend.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    written.append(path)
    return written


def plot_study(result: Any, directory: Path, top: int = 4) -> list[Path]:
    """Figures of a :class:`runout.study.StudyResult` in ``directory``.

    Monte Carlo: ``histograms.png`` (radial runout, NRRO and the ``top`` largest lines in x).
    Sweep: ``sweep_<quantity>.png`` for each scalar swept quantity: every runout figure and the
    ``top`` largest lines against it, one curve per model (other quantities at their points).
    """
    plt = pyplot()
    written: list[Path] = []
    lines = [row for row in result.line_table() if row[0] in ("x", "z")][:top]
    ok = np.isfinite(result.runout["radial_pp_m"])
    if result.kind == "montecarlo":
        panels = [("radial runout", result.runout["radial_pp_m"][ok])]
        panels.append(("NRRO", result.runout["nrro_pp_m"][ok]))
        panels += [(f"{d} {f:.4g} Hz: {label}", pp[ok]) for d, f, label, pp in lines]
        cols = 2
        rows = (len(panels) + 1) // 2
        fig, axes = plt.subplots(rows, cols, figsize=(10, 3.0 * rows), squeeze=False)
        for ax, (name, values) in zip(axes.flat, panels, strict=False):
            nm = values * 1e9
            # a quantity constant over the lot (to round-off) has no spread to bin
            spread = float(np.ptp(nm)) if nm.size else 0.0
            flat = spread <= 1e-9 * max(float(np.max(np.abs(nm), initial=0.0)), 1e-300)
            ax.hist(nm, bins=1 if flat else result.bins, color="tab:blue", alpha=0.8)
            ax.set_title(name[:70], fontsize=8)
            ax.set_xlabel("peak-to-peak [nm]")
            ax.set_ylabel("bearings")
            ax.grid(alpha=0.3)
        for ax in list(axes.flat)[len(panels) :]:
            ax.set_visible(False)
        fig.suptitle(f"{result.title}: {result.samples} samples", fontsize=10)
        fig.tight_layout()
        path = directory / "histograms.png"
        fig.savefig(path, dpi=110)
        plt.close(fig)
        return [path]
    models = sorted(set(result.model))
    for q in result.quantities:
        values = result.values[q.key]
        if q.size > 1 or not all(isinstance(v, int | float) for v in values):
            continue
        x = np.asarray(values, dtype=np.float64)
        series = [(k, result.runout[k]) for k in ("radial_pp_m", "rro_pp_m", "nrro_pp_m")]
        series += [(f"{d} {label}", pp) for d, _f, label, pp in lines]
        fig, axes = plt.subplots(1, 2, figsize=(11, 4))
        for m in models:
            mask = np.array([mm == m for mm in result.model])
            order = np.argsort(x[mask], kind="stable")
            for k, (name, y) in enumerate(series):
                ax = axes[0] if k < 3 else axes[1]
                ax.plot(
                    x[mask][order],
                    y[mask][order] * 1e9,
                    "o-",
                    ms=3,
                    label=f"{m}: {name}"[:60],
                )
        for ax, what in zip(axes, ("runout figures", "largest lines"), strict=True):
            ax.set_xlabel(f"{q.key} [SI]")
            ax.set_ylabel("peak-to-peak [nm]")
            ax.set_title(what, fontsize=9)
            ax.grid(alpha=0.3)
            ax.legend(fontsize=6)
        fig.suptitle(result.title, fontsize=10)
        fig.tight_layout()
        name = "".join(ch if ch.isalnum() or ch in "._-" else "_" for ch in q.key)
        path = directory / f"sweep_{name}.png"
        fig.savefig(path, dpi=110)
        plt.close(fig)
        written.append(path)
    return written
