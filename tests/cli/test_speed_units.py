"""Speeds written as engineers write them: ``"5400 rev/min"`` was refused ('rev' unknown)."""

from __future__ import annotations

import json
from pathlib import Path

from typer.testing import CliRunner

from runout.cli.commands import app

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "seed000_tada_fig7.toml"


def test_rev_per_min_runs_like_rpm(tmp_path: Path) -> None:
    text = EXAMPLE.read_text()
    assert 'speed = "5400 rpm"' in text
    case = tmp_path / "revmin.toml"
    case.write_text(text.replace('speed = "5400 rpm"', 'speed = "5400 rev/min"'))
    runner = CliRunner()
    ours = runner.invoke(app, ["frequencies", str(case), "--json"])
    reference = runner.invoke(app, ["frequencies", str(EXAMPLE), "--json"])
    assert ours.exit_code == 0, ours.stderr
    assert (
        json.loads(ours.stdout)["frequencies_hz"] == json.loads(reference.stdout)["frequencies_hz"]
    )
