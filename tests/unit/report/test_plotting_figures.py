"""Figures an engineer can read: units on every axis, no text over text, decimated curves.

Small real results (the 608 of seed 002 at 1024 instants, Tada's HDD bearing over 72
revolutions, the seed 003 rotor, a 16-bearing Monte Carlo and a 3-point sweep) are drawn
by the functions that write the output files, and every figure is checked with
:func:`plot_checks.figure_problems` and :func:`plot_checks.png_problems`.
"""

from __future__ import annotations

import copy
import math
import tomllib
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from matplotlib.text import Text
from typer.testing import CliRunner

from cases import KIM_BEARING, KIM_OPERATION, dynamic_case
from plot_checks import MAX_LINE_POINTS, figure_problems, png_problems
from runout.base.display import format_length
from runout.case.model import parse_case
from runout.cli.commands import app
from runout.models.linear import ANDERON_BANDS
from runout.report import plotting
from runout.runner import run_model
from runout.study.run import Quantity, run_study

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"

KIM: dict[str, Any] = {
    "title": "Kim spindle bearing",
    "bearing": dict(KIM_BEARING),
    "operation": dict(KIM_OPERATION),
    "analysis": {
        "model": "quasi_static_2d",
        "revolutions": 4,
        "samples": 256,
        "limit": "0.5 um",
    },
}


def _example(name: str, **analysis: Any) -> Any:
    doc = tomllib.loads((EXAMPLES / name).read_text())
    doc["analysis"].update(analysis)
    return run_model(parse_case(doc, name))


@pytest.fixture(scope="module")
def linear_608() -> Any:
    return _example("seed002_608.toml", samples=1024)


@pytest.fixture(scope="module")
def tada() -> Any:
    return _example("seed000_tada_fig7.toml")  # 72 revolutions of 4096 instants


@pytest.fixture(scope="module")
def montecarlo() -> Any:
    data = copy.deepcopy(KIM)
    data["study"] = {
        "kind": "montecarlo",
        "samples": 16,
        "seed": 3,
        "vary": {"element_diameter_sigma": "0.1 um"},
    }
    return run_study(parse_case(data, "kim.toml"))


@pytest.fixture(scope="module")
def sweep() -> Any:
    data = copy.deepcopy(KIM)
    data["study"] = {
        "kind": "sweep",
        "vary": {"operation.axial_load": {"start": "30 N", "stop": "90 N", "num": 3}},
    }
    data["elements"] = {"diameter_errors": ["0.1 um", 0, 0, 0, 0, 0, 0, 0, 0, 0]}
    return run_study(parse_case(data, "kim.toml"))


def _assert_readable(
    figures: dict[str, Any], tmp_path: Path, spectra: tuple[str, ...] = ()
) -> None:
    """Every figure, laid out as the writers save it, passes the checks; so does its PNG."""
    assert figures
    problems = []
    for name, fig in figures.items():
        plotting._finish(fig)
        log_y = (fig.axes[0],) if name in spectra else ()
        problems += [f"{name}: {p}" for p in figure_problems(fig, log_y=log_y)]
        path = tmp_path / name
        fig.savefig(path, dpi=110)
        plotting.pyplot().close(fig)
        problems += png_problems(path)
    assert problems == []


# ---------------------------------------------------------------- the checker can fail
def test_checks_catch_overlap_missing_unit_long_curve_and_blank(tmp_path: Path) -> None:
    plt = plotting.pyplot()
    fig, ax = plt.subplots()
    ax.plot(np.arange(MAX_LINE_POINTS + 1.0))
    ax.set_xlabel("time [s]")
    ax.set_ylabel("displacement")  # no unit
    ax.text(0.5, 0.5, "first label", transform=ax.transAxes)
    ax.text(0.5, 0.5, "second label", transform=ax.transAxes)
    found = figure_problems(fig, log_y=(ax,))
    plt.close(fig)
    assert any("has no [unit]" in p for p in found)
    assert any("texts overlap" in p and "first label" in p for p in found)
    assert any("curve of 4,001 points" in p for p in found)
    assert any("not log" in p for p in found)
    blank = plt.figure()
    blank.savefig(tmp_path / "blank.png")
    plt.close(blank)
    assert png_problems(tmp_path / "blank.png")
    assert png_problems(tmp_path / "missing.png")


def test_label_placement_drops_labels_without_room() -> None:
    plt = plotting.pyplot()
    fig, ax = plt.subplots(figsize=(4, 3))
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    fig.tight_layout()
    items = [(0.5, 0.5, f"label number {k}") for k in range(20)]
    dropped = plotting.place_labels(ax, items)
    placed = len(ax.texts)
    assert placed + dropped == 20 and 0 < placed < 20
    assert figure_problems(fig) == []  # the placed ones overlap nothing
    plt.close(fig)


@settings(max_examples=25, deadline=None)
@given(
    points=st.lists(
        st.tuples(
            st.floats(0.0, 1.0),
            st.floats(0.0, 1.0),
            st.text("abcdefghij ()0123456789:/", min_size=1, max_size=24),
        ),
        min_size=1,
        max_size=12,
    ),
    log=st.booleans(),
    fixed=st.booleans(),
    legend_loc=st.sampled_from(["upper left", "best"]),
)
def test_placed_labels_are_where_they_were_checked(
    points: list[Any], log: bool, fixed: bool, legend_loc: str
) -> None:
    """A label's box at each offset is computed from one measurement (moved by the offset and
    alignment): the drawn labels must lie inside the axes and clear of each other and the
    legend, as the placement checked them. On a figure whose layout runout fixed (the tight
    layout has measured it) the placement does not lay the figure out again; on any other it
    does: both must hold."""
    plt = plotting.pyplot()
    fig, ax = plt.subplots(figsize=(5, 3))
    ax.plot([0.0, 1.0], [1e-3 if log else 0.0, 1.0], label="curve")
    if log:
        ax.set_yscale("log")
        points = [(x, max(y, 1e-3), t) for x, y, t in points]
    ax.set_xlim(0.0, 1.0)
    ax.set_ylim(1e-3 if log else 0.0, 1.0)
    ax.legend(loc=legend_loc)
    if fixed:
        plotting._fix_layout(fig)
    else:
        fig.tight_layout()
    dropped = plotting.place_labels(ax, points)
    labels = [t for t in ax.texts if t.get_text()]
    assert len(labels) + dropped == len(points)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    frame = ax.get_window_extent(renderer)
    boxes = [Text.get_window_extent(t, renderer) for t in labels]
    legend = ax.get_legend().get_window_extent(renderer)
    for k, box in enumerate(boxes):
        assert frame.x0 - 0.01 <= box.x0 and box.x1 <= frame.x1 + 0.01
        assert frame.y0 - 0.01 <= box.y0 and box.y1 <= frame.y1 + 0.01
        for other in [legend, *boxes[:k]]:
            overlap_x = min(box.x1, other.x1) - max(box.x0, other.x0)
            overlap_y = min(box.y1, other.y1) - max(box.y0, other.y0)
            assert not (overlap_x > 0.51 and overlap_y > 0.51), (box, other)
    plt.close(fig)


# ---------------------------------------------------------------- single runs
@pytest.mark.parametrize("which", ["linear_608", "tada"])
def test_run_figures_are_readable(which: str, request: Any, tmp_path: Path) -> None:
    result = request.getfixturevalue(which)
    figures = plotting.result_figures(result)
    assert list(figures) == ["history.png", "orbit.png", "lines.png"]
    _assert_readable(figures, tmp_path, spectra=("lines.png",))


def test_history_shows_the_chosen_last_revolutions(tada: Any) -> None:
    for revolutions in (3.0, 10.0):
        ax = plotting.plot_time_history(tada, revolutions=revolutions)
        xs = np.concatenate([line.get_xdata() for line in ax.get_lines()])
        assert "revolutions of the rotating ring [rev]" == ax.get_xlabel()
        # the record spans 72 revolutions: only its last ones are drawn
        assert xs.max() == pytest.approx(72.0, abs=0.05)
        assert xs.min() == pytest.approx(72.0 - revolutions, abs=0.05)
        assert f"last {revolutions:g} of 72 revolutions" in ax.get_title()
        plotting.pyplot().close(ax.figure)
    with pytest.raises(ValueError, match="positive"):
        plotting.result_figures(tada, history_revolutions=0.0)


def test_orbit_marks_the_measuring_direction(tada: Any) -> None:
    ax = plotting.plot_orbit(tada, revolutions=3.0)
    texts = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "measuring direction (x)" in texts
    direction = next(
        line for line in ax.get_lines() if line.get_label() == "measuring direction (x)"
    )
    assert np.all(np.asarray(direction.get_ydata()) == 0.0)  # along x
    assert ax.get_aspect() == 1.0
    assert ax.get_xlabel().endswith("[nm]") and ax.get_ylabel().endswith("[nm]")
    plotting.pyplot().close(ax.figure)


def test_lines_on_a_log_axis_with_a_floor_and_few_labels(linear_608: Any) -> None:
    ax = plotting.plot_lines(linear_608)
    peak = max(c.pp_m for c in linear_608.components)
    assert ax.get_yscale() == "log"
    assert ax.get_ylabel() == "peak-to-peak [um]"  # 4.9 um eccentricity: micrometres
    assert ax.get_ylim()[0] == pytest.approx(plotting.FLOOR_FRACTION * peak * 1e6)
    assert "axis floor 1e-04 of the largest line" in ax.get_title()
    labels = [t.get_text() for t in ax.texts]
    assert 1 <= len(labels) <= 6 and len(set(labels)) == len(labels)
    # the eccentricity line seen in x and y: one label naming both directions
    assert "inner 1 lobes (x, y)" in labels
    plotting.pyplot().close(ax.figure)


def test_linear_model_figures(linear_608: Any, tmp_path: Path) -> None:
    theta, v = linear_608.density_waveform()
    orders, rms = linear_608.line_anderon_spectrum()
    waveform = plotting.plot_density_waveform(theta / (2 * math.pi), v * 1e6, "608")
    assert max(len(line.get_xdata()) for line in waveform.get_lines()) <= 2 * 1000 + 2
    spectrum = plotting.plot_anderon_spectrum(
        orders, rms, {"L": (4.0, 50.0), "M": (50.0, 300.0)}, {"L": 1.0, "M": 2.0}, "608"
    )
    bars = plotting.plot_band_values(
        {
            "exact lines": linear_608.anderon_lines().as_dict(),
            "DFT": linear_608.anderon_dft().as_dict(),
        },
        "608",
        edges={b.name: (b.low, b.high) for b in ANDERON_BANDS.bands},
    )
    assert bars.get_yscale() == "log"  # 0.4 to 60 Anderon
    figures = {
        "waveform.png": waveform.figure,
        "anderon.png": spectrum.figure,
        "bands.png": bars.figure,
    }
    _assert_readable(figures, tmp_path, spectra=("anderon.png",))


def test_band_bars_name_bands_edges_and_unit(tmp_path: Path) -> None:
    ax = plotting.plot_band_values(
        {"lot": {"L": 12.0, "M": 30.0, "H": 8.0}},
        "608",
        unit="um/s",
        quantity="rms velocity",
        edges={"L": (50.0, 300.0), "M": (300.0, 1800.0), "H": (1800.0, 10000.0)},
        edge_unit="Hz",
    )
    assert ax.get_ylabel() == "rms velocity [um/s]"
    assert ax.get_xlabel() == "band (edges) [Hz]"
    assert [t.get_text() for t in ax.get_xticklabels()] == [
        "L\n50-300",
        "M\n300-1800",
        "H\n1800-10000",
    ]
    _assert_readable({"bands.png": ax.figure}, tmp_path)


def test_dynamic_spectrum_is_logarithmic_and_readable(tmp_path: Path) -> None:
    result = run_model(dynamic_case(revolutions=4, samples=1024))
    ax = plotting.plot_dynamic_spectrum(result)
    assert ax.get_yscale() == "log"
    _assert_readable({"spectrum.png": ax.figure}, tmp_path, spectra=("spectrum.png",))


# ---------------------------------------------------------------- studies
def test_montecarlo_histograms(montecarlo: Any, tmp_path: Path) -> None:
    figures = plotting.study_figures(montecarlo, limit_quantity="radial_pp_m", limit_m=5e-7)
    assert list(figures) == ["histograms.png"]
    fig = figures["histograms.png"]
    axes = [ax for ax in fig.axes if ax.get_visible()]
    titles = [ax.get_title() for ax in axes]
    assert len(set(titles)) == len(titles)
    # the 2-D model has no repeatable part here: radial p-p and NRRO are the same array
    ok = np.isfinite(montecarlo.runout["radial_pp_m"])
    assert np.array_equal(montecarlo.runout["radial_pp_m"][ok], montecarlo.runout["nrro_pp_m"][ok])
    merged = next(ax for ax in axes if "radial p-p = NRRO p-p" in ax.get_title())
    legend = [t.get_text() for t in merged.get_legend().get_texts()]
    assert f"limit {format_length(5e-7, ('nm', 1e9))}" in legend
    limit = [line for line in merged.get_lines() if line.get_label().startswith("limit")]
    assert limit and np.allclose(limit[0].get_xdata(), 500.0)
    # no two panels draw the same bars
    heights = [tuple(p.get_height() for p in ax.patches) for ax in axes]
    edges = [tuple(p.get_x() for p in ax.patches) for ax in axes]
    assert len(set(zip(heights, edges, strict=True))) == len(axes)
    # the largest line: a Rayleigh law by maximum likelihood, sigma^2 = mean(x^2) / 2
    _d, _f, _label, pp = montecarlo.line_table()[0]
    sigma_nm = math.sqrt(float(np.mean((pp[ok] * 1e9) ** 2)) / 2)
    line_ax = next(ax for ax in axes if "Hz)" in ax.get_title())
    fit = [t.get_text() for t in line_ax.get_legend().get_texts()]
    assert fit == [f"Rayleigh fit, σ = {sigma_nm:.3g} nm"]
    _assert_readable(figures, tmp_path)


def test_plot_study_keeps_its_positional_call(montecarlo: Any, tmp_path: Path) -> None:
    written = plotting.plot_study(montecarlo, tmp_path)
    assert written == [tmp_path / "histograms.png"] and png_problems(written[0]) == []
    with pytest.raises(ValueError, match="limit_quantity"):
        plotting.plot_study(montecarlo, tmp_path, limit_quantity="peak_m", limit_m=1e-6)


def test_sweep_axis_names_the_key_and_its_unit(sweep: Any, tmp_path: Path) -> None:
    figures = plotting.study_figures(sweep)
    assert list(figures) == ["sweep_operation.axial_load.png"]
    fig = figures["sweep_operation.axial_load.png"]
    for ax in fig.axes:
        assert ax.get_xlabel() == "axial load [N]"
        labels = [t.get_text() for t in ax.get_legend().get_texts()]
        assert len(set(labels)) == len(labels)  # one curve per distinct output or line
    lines_ax = fig.axes[1]
    wanted = [row for row in sweep.line_table() if row[0] in ("x", "z")][:4]
    assert len(lines_ax.get_lines()) == len(wanted)
    _assert_readable(figures, tmp_path)


@pytest.mark.parametrize(
    ("path", "values", "label"),
    [
        (("operation", None, "speed"), (50.0, 100.0), "speed [rpm]"),
        (
            ("operation", None, "radial_load_direction"),
            (0.0, math.pi),
            "radial load direction [deg]",
        ),
        (("waviness", 2, "amplitude"), (1e-7, 3e-7), "waviness 2: amplitude [nm]"),
        (("bearing", None, "radial_clearance"), (5e-6, 20e-6), "radial clearance [um]"),
        (("bearing", None, "elements"), (8, 12), "elements [-]"),
        (("material", None, "youngs_modulus"), (2e11, 2.1e11), "youngs modulus [Pa]"),
    ],
)
def test_sweep_axis_label(
    path: tuple[str, int | None, str], values: tuple[float, ...], label: str
) -> None:
    q = Quantity("key", path, 1, "sweep", values=values)
    text, scale = plotting._sweep_axis(q, np.asarray(values, dtype=np.float64))
    assert text == label and "[SI]" not in text
    if label.startswith("speed"):
        assert scale == 60.0  # Hz (revolutions per second) to rpm


# ---------------------------------------------------------------- through the CLI
def test_run_writes_readable_figures_through_the_cli(tmp_path: Path) -> None:
    case = EXAMPLES / "seed000_tada_fig7.toml"
    result = CliRunner().invoke(app, ["run", str(case), "--out", str(tmp_path)])
    assert result.exit_code == 0, result.output
    for name in ("history.png", "orbit.png", "lines.png"):
        assert png_problems(tmp_path / name) == []
