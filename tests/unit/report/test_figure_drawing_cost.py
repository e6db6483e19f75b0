"""What drawing a run's figures costs: one draw per figure, plain log labels, longest first.

``run --out`` must stay within twice the time of ``run --json`` (BENCHMARKS.md); its figures
are most of the difference. A figure laid out by runout is drawn once when saved (no second
layout pass); a log axis's tick labels are matplotlib's own (which ticks carry a label, the
value each shows) written as plain Unicode (``10⁻³``) instead of mathtext, which every
figure parsed again; the drawing processes take the figures longest first.
"""

from __future__ import annotations

import math
import re
import tomllib
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st
from matplotlib.ticker import LogFormatterSciNotation

from runout.case.model import parse_case
from runout.report import _plot_style as style
from runout.report import plotting, run_files
from runout.runner import run_model

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"
_DIGITS = "⁰¹²³⁴⁵⁶⁷⁸⁹"
#: "10⁻³", "2×10⁻³" (a coefficient times a power of ten), or a plain number ("1", "0.5").
_LABEL = re.compile(r"^(?:(\d+)×)?10(⁻?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)$")


def _value(label: str) -> float:
    """The number a plain log label shows."""
    match = _LABEL.match(label)
    if match is None:
        return float(label)
    coefficient = float(match.group(1) or 1)
    power = match.group(2)
    exponent = int("".join(str(_DIGITS.index(c)) for c in power.lstrip("⁻")))
    return coefficient * 10.0 ** (-exponent if power.startswith("⁻") else exponent)


@given(exponent=st.integers(-300, 300), coefficient=st.integers(1, 9))
def test_plain_labels_show_the_value_of_matplotlibs(exponent: int, coefficient: int) -> None:
    """Every label of matplotlib's log formatter converts to plain text showing its value."""
    formatter = LogFormatterSciNotation(labelOnlyBase=False)
    value = coefficient * 10.0**exponent
    if not math.isfinite(value) or value == 0.0:
        return
    mathtext = formatter(value)
    plain = style.plain_power(mathtext)
    assert "$" not in plain and "\\" not in plain, (mathtext, plain)
    assert _value(plain) == pytest.approx(value, rel=1e-12), (mathtext, plain)


@pytest.mark.parametrize(
    "label",
    ["", "abc", "0.5 µm", r"$\mathdefault{10^{\frac{1}{2}}}$", r"$x_{1}$", "$10^{-3}$"],
)
def test_other_labels_are_left_as_they_are(label: str) -> None:
    """Only the formatter's own forms are rewritten; anything else (a fraction, a subscript,
    mathtext not in ``\\mathdefault``) keeps matplotlib's rendering."""
    assert style.plain_power(label) == label


def test_a_run_figures_log_axes_carry_plain_labels_at_their_ticks() -> None:
    """The 608's line spectrum (log y) and Anderon spectrum (log x and y): every drawn tick
    label is plain text and shows the value of the tick it stands at."""
    doc = tomllib.loads((EXAMPLES / "seed002_608.toml").read_text())
    doc["analysis"]["samples"] = 1024
    result: Any = run_model(parse_case(doc, "seed002_608.toml"))
    inputs = run_files._linear_inputs(result)
    axes = [
        plotting.plot_lines(result),
        plotting.plot_anderon_spectrum(
            inputs["orders"],
            inputs["line_rms_uin_per_rad"],
            inputs["bands"],
            next(iter(inputs["band_values"].values())),
            "608",
        ),
    ]
    checked = 0
    for ax in axes:
        ax.figure.canvas.draw()
        for axis in (ax.xaxis, ax.yaxis):
            if axis.get_scale() != "log":
                continue
            lo, hi = sorted(axis.get_view_interval())
            for tick in axis.get_major_ticks() + axis.get_minor_ticks():
                text = tick.label1.get_text()
                if not (tick.label1.get_visible() and text and lo <= tick.get_loc() <= hi):
                    continue
                assert "$" not in text, text
                assert _value(text) == pytest.approx(tick.get_loc(), rel=1e-9), text
                checked += 1
        plotting.pyplot().close(ax.figure)
    assert checked >= 6  # the decades of three log axes


def test_every_figure_has_a_drawing_cost() -> None:
    """The drawing processes take the figures longest first: a figure missing from the cost
    table would be queued as if it cost as little as a time history."""
    names = {
        *plotting.STANDARD_FIGURES,
        *plotting.LINEAR_FIGURES,
        *run_files._ROLLER_FIGURES,
        "bearing.gif",
        "balls.png",
        "spectrum.png",
    }
    assert names <= set(run_files._FIGURE_COST)
    order = run_files._longest_first(sorted(names))
    costs = [run_files._FIGURE_COST[n] for n in order]
    assert costs == sorted(costs, reverse=True)
    assert "order_sweep.png" not in order  # drawn after the tables that compute it


def test_a_laid_out_figure_is_drawn_once_when_saved(tmp_path: Path) -> None:
    """After runout's tight layout no layout engine is left on the figure: savefig draws it
    once, not a layout pass and then the drawing. A user's matplotlibrc asking for automatic
    layouts does not bring one back (the figure's style turns them off)."""
    import matplotlib

    plt = plotting.pyplot()
    with matplotlib.rc_context({"figure.autolayout": True}), matplotlib.rc_context(style.RC):  # type: ignore[arg-type]
        fig, ax = plt.subplots(figsize=(4, 3))
        ax.plot([1.0, 2.0, 3.0], [1e-3, 1.0, 1e2])
        ax.set_yscale("log")
        style.log_labels(ax)
        ax.set_title("a title")
        style._fix_layout(fig)
        assert fig.get_layout_engine() is None
        position = ax.get_position().bounds
        draws = []
        original = fig.draw

        def counted(renderer: Any) -> None:
            draws.append(renderer)
            original(renderer)

        fig.draw = counted
        style._save(fig, tmp_path / "f.png")
    assert len(draws) == 1
    assert ax.get_position().bounds == position  # the layout checked is the layout saved
    assert (tmp_path / "f.png").stat().st_size > 0
