"""A verdict passes only on a record that resolves the lines it is about (review finding).

A line above the Nyquist frequency or below 1/T is left out of the fit: runout figures and band
values are then lower bounds, which can fail a limit but not pass it. Before, a 1024-sample
record of a 2430 Hz line gave ISO 15242 band M = 0 and PASS (FAIL with 16384 samples), and a
0.02-revolution record of Tada's bearing passed a 5 nm limit that the full record exceeds 8x.
"""

from __future__ import annotations

import json
from pathlib import Path

from typer.testing import CliRunner

from runout.cli.commands import app

runner = CliRunner()
ROOT = Path(__file__).resolve().parents[2]
BAND_CASE = ROOT / "tests" / "data" / "verdict_band_above_nyquist.toml"
TADA = ROOT / "examples" / "seed000_tada_fig7.toml"


def _said(result: object) -> str:
    return " ".join(result.stderr.split())  # type: ignore[attr-defined]


def test_no_band_pass_above_the_nyquist_frequency() -> None:
    result = runner.invoke(app, ["run", str(BAND_CASE), "--json"])
    assert result.exit_code == 2
    assert "analysis.samples" in _said(result) and "Nyquist" in _said(result)
    # enough samples: the line is fitted and the band fails honestly
    result = runner.invoke(
        app, ["run", str(BAND_CASE), "--set", "analysis.samples=16384", "--json"]
    )
    assert result.exit_code == 0, result.stderr
    verdict = json.loads(result.stdout)["verdict"]
    assert verdict["pass"] is False and verdict["value_um_per_s"] > 50.0


def test_no_runout_pass_from_a_record_shorter_than_its_lines() -> None:
    args = ["run", str(TADA), "--set", "analysis.revolutions=0.02", "--set", "analysis.samples=64"]
    result = runner.invoke(app, [*args, "--set", 'analysis.limit="5 nm"', "--json"])
    assert result.exit_code == 2
    assert "analysis.revolutions" in _said(result)
    # a limit the lower bound already exceeds still fails
    result = runner.invoke(app, [*args, "--set", 'analysis.limit="0.1 nm"', "--json"])
    assert result.exit_code == 0, result.stderr
    assert json.loads(result.stdout)["verdict"]["pass"] is False
