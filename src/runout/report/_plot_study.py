"""Figures of studies and sweeps: Monte Carlo histograms, sweep curves, the dynamic sweep.

Split out of :mod:`runout.report.plotting`, which re-exports every name (import them from
there: this module takes the shared drawing helpers from it). The rules are
:mod:`runout.report.plotting`'s: one style (:mod:`runout.report._plot_style`), every axis names
its quantity and unit, lengths at their own scale.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from runout.report import _plot_style as style
from runout.report._plot_style import (
    MAX_CURVE_POINTS,
    _finish,
    _fmt,
    _save,
    _shorten,
    envelope_indices,
    pyplot,
)

__all__ = [
    "STUDY_KINDS",
    "plot_dynamic_sweep",
    "plot_study",
    "plot_study_kind",
    "streamed_histograms",
    "study_figures",
]


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
        style.log_labels(ax)
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
    the number of samples times the bin width, on the histogram's own scale. Samples without
    a value (NaN: a figure the sample's model does not give) are not binned; the title says
    how many.
    """
    values_m = np.asarray(values_m, dtype=np.float64)
    finite = np.isfinite(values_m)
    missing = int(values_m.size - np.count_nonzero(finite))
    values_m = values_m[finite]
    if missing:
        title = f"{_shorten(title, 40)} ({missing} without a value)"
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
        mean, std = float(np.mean(v)), float(np.std(v, ddof=1))
        _fitted_law(ax, edges, law, mean, std, float(np.mean(v**2)), v.size, unit)
    if flat and values_m.size:  # one value for every bearing: say which
        title = f"{_shorten(title, 48)}: {_fmt(float(values_m[0]), unit, scale)} in every sample"
    _frame_histogram(ax, title, quantity, unit, scale, limit_m, counts)


def _fitted_law(
    ax: Any,
    edges: np.ndarray,
    law: str,
    mean: float,
    std: float,
    mean_square: float,
    count: int,
    unit: str,
) -> None:
    """The fitted law over a histogram of ``count`` samples with bin ``edges`` (values at the
    axis scale): ``"rayleigh"`` (sigma^2 = mean(x^2) / 2, by maximum likelihood) or
    ``"normal"`` (``mean``, ``std``), drawn as density x count x bin width."""
    width = float(edges[1] - edges[0])
    grid = np.linspace(float(edges[0]), float(edges[-1]), 200)
    if law == "rayleigh":
        s2 = mean_square / 2.0
        pdf = grid / s2 * np.exp(-(grid**2) / (2.0 * s2))
        fit = f"Rayleigh fit, σ = {math.sqrt(s2):.3g} {unit}"
    else:
        pdf = np.exp(-0.5 * ((grid - mean) / std) ** 2) / (std * math.sqrt(2.0 * math.pi))
        fit = f"normal fit, σ = {std:.3g} {unit}"
    ax.plot(grid, pdf * count * width, color=style.FIT_COLOUR, lw=1.1, label=fit)


def _frame_histogram(
    ax: Any,
    title: str,
    quantity: str,
    unit: str,
    scale: float,
    limit_m: float | None,
    counts: np.ndarray,
) -> None:
    """A histogram panel's spec-limit line, limits, title, axis labels and legend."""
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
        # the axial p-p of a planar lot is NaN (not a figure of the model): no panel
        if key in result.runout
        and (key != "axial_pp_m" or np.any(np.nan_to_num(result.runout[key][ok])))
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
    """Figures of a :class:`runout.study.run.StudyResult`, laid out, by file name.

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


def _binned_panel(
    ax: Any,
    title: str,
    quantity: str,
    stats: dict[str, Any],
    count: int,
    law: str,
    limit_m: float | None,
) -> None:
    """One histogram drawn from its bins (a streaming study's, from the quantile sketch).

    ``stats`` is a summary statistics object (``mean``, ``std``, ``histogram`` with ``edges``
    [m] and ``counts``) of ``count`` samples. The fitted law is that of
    :func:`_histogram_panel` from the exact moments: normal (mean, std) or Rayleigh with
    sigma^2 = mean(x^2) / 2 = ((n - 1) std^2 / n + mean^2) / 2.
    """
    edges_m = np.asarray(stats["histogram"]["edges"], dtype=np.float64)
    counts = np.asarray(stats["histogram"]["counts"], dtype=np.float64)
    # the scale of the values (the bins of a lot with one value span +-0.5 m around it)
    unit, scale = style.length_scale(
        [float(stats["min"]), float(stats["max"]), *([limit_m] if limit_m is not None else [])]
    )
    edges = edges_m * scale
    low, high = float(stats["min"]) * scale, float(stats["max"]) * scale
    flat = high - low <= 1e-9 * max(abs(low), abs(high), 1e-300)
    if flat:  # one value for the whole lot, as _histogram_panel draws it
        half = max(0.5 * abs(low), 1.0)
        ax.stairs(
            [float(counts.sum())],
            [low - 0.03 * half, low + 0.03 * half],
            fill=True,
            color=style.HIST_COLOUR,
            alpha=0.8,
        )
        ax.set_xlim(low - half, low + half)
        title = f"{_shorten(title, 48)}: {_fmt(float(stats['min']), unit, scale)} in every sample"
    else:
        ax.stairs(counts, edges, fill=True, color=style.HIST_COLOUR, alpha=0.8)
    mean, std = float(stats["mean"]) * scale, float(stats["std"]) * scale
    if not flat and counts.size > 1 and count >= 2 and std > 0.0:
        mean_square = (count - 1) / count * std**2 + mean**2
        _fitted_law(ax, edges, law, mean, std, mean_square, count, unit)
    _frame_histogram(ax, title, quantity, unit, scale, limit_m, counts)


@style.styled
def streamed_histograms(
    summary: dict[str, Any],
    top: int = 4,
    *,
    limit_quantity: str | None = None,
    limit_m: float | None = None,
) -> Any:
    """``histograms.png`` of a Monte Carlo reduced by streaming statistics.

    The panels of :func:`study_figures` (radial p-p, RRO, NRRO, axial p-p when it moves, the
    ``top`` largest lines in x and z, identical outputs drawn once), each from the bins of its
    summary: edges from the exact minimum and maximum, counts from the quantile sketch's
    buckets (a value within the sketch's relative accuracy of an edge may sit in the next
    bin), the fitted law from the exact moments.

    Parameters
    ----------
    summary : dict
        :meth:`runout.study._result.StreamedStudyResult.summary`.
    top : int
        Number of lines drawn.
    limit_quantity : str, optional
        Runout key whose histogram carries the spec limit ``limit_m`` [m].
    limit_m : float, optional
        The spec limit [m].

    Returns
    -------
    matplotlib.figure.Figure
    """
    plt = pyplot()
    heading = _shorten(summary.get("title") or "study", 110)
    ran = int(summary["samples"]) - int(summary["failed"])
    runout = summary["runout"]
    candidates: list[tuple[str, str, dict[str, Any], str, str | None]] = [
        (name, name, runout[key], "normal", key)
        for key, name in _RUNOUT_NAMES.items()
        if key in runout
        and runout[key]["histogram"]["counts"]
        and (key != "axial_pp_m" or runout[key]["max"] != 0.0)
    ]
    rows = [c for c in summary["components"] if c["direction"] in ("x", "z")][:top]
    names = _unique_names([(c["direction"], c["label"]) for c in rows])
    candidates += [
        (f"{name} ({c['frequency_hz']:.4g} Hz)", "line p-p", c["pp_m"], "rayleigh", None)
        for name, c in zip(names, rows, strict=True)
        if c["pp_m"]["histogram"]["counts"]
    ]
    panels: list[tuple[list[str], str, dict[str, Any], str, str | None]] = []
    for title, quantity, stats, law, key in candidates:
        for i, entry in enumerate(panels):
            if stats == entry[2]:  # the same output (every bin, every moment)
                entry[0].append(title)
                if key is not None and entry[4] is None:
                    panels[i] = (entry[0], entry[1], entry[2], entry[3], key)
                break
        else:
            panels.append(([title], quantity, stats, law, key))
    if limit_quantity is not None and not any(p[4] == limit_quantity for p in panels):
        name = _RUNOUT_NAMES.get(limit_quantity, limit_quantity)
        if runout.get(limit_quantity, {}).get("histogram", {}).get("counts"):
            panels.append(([name], name, runout[limit_quantity], "normal", limit_quantity))
    if not panels:
        fig, ax = plt.subplots(figsize=(6, 2))
        ax.set_axis_off()
        ax.text(
            0.5,
            0.5,
            f"all {summary['samples']} samples failed: nothing to draw\n"
            "(their errors are in summary.json)",
            ha="center",
            va="center",
            transform=ax.transAxes,
        )
        fig.suptitle(heading)
        return _finish(fig)
    cols = 2
    n_rows = (len(panels) + 1) // 2
    fig, axes = plt.subplots(n_rows, cols, figsize=(10, 3.1 * n_rows), squeeze=False)
    for ax, (titles, quantity, stats, law, key) in zip(axes.flat, panels, strict=False):
        if len(titles) > 1:
            title = " = ".join(t.split(" (")[0] for t in titles) + " (the same in every sample)"
            quantity = "p-p"
        else:
            title = titles[0]
        limit = limit_m if key is not None and key == limit_quantity else None
        _binned_panel(ax, title, quantity, stats, ran, law, limit)
    for ax in list(axes.flat)[len(panels) :]:
        ax.set_visible(False)
    failed = int(summary["failed"])
    note = f", {failed} failed, not drawn" if failed else ""
    fig.suptitle(
        f"{heading}: {summary['samples']} samples{note}\n(streaming statistics: bins from a "
        f"quantile sketch of relative accuracy {summary['quantile_relative_error']:g})"
    )
    return _finish(fig)


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
    """Unit kind (:data:`runout.base.units.KINDS`) of the case key at ``path``, read off the schema.

    The case schema marks each quantity field with the kind its converter reads; the mark can
    sit inside an optional type (``Length | None``), so the whole annotation is searched.
    """
    import typing

    from runout.case.model import CaseSpec, _table_type

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
    from runout.base.units import KINDS

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


#: Kinds of :meth:`runout.study.run.StudyResult.plot`.
STUDY_KINDS = {
    "histograms": "Monte Carlo: histograms of the runout outputs and the largest lines",
    "sweep": "sweep: runout outputs and the largest lines against a swept quantity",
}


def plot_study_kind(result: Any, kind: str, quantity: str | None = None, top: int = 4) -> Any:
    """One figure of a study, by name (:meth:`runout.study.run.StudyResult.plot`).

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
