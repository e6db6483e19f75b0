"""The roller model names its radial runout as ISO 492 does: Kia (inner ring turning), Kea.

Issue 17: the roller model computes the radial runout of the assembled bearing's turning ring,
which drawings and ISO 492 call Kia (inner ring) or Kea (outer ring); the output should say so.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "seed004_nu209.toml"


@pytest.mark.parametrize(("ring", "name"), [("inner", "Kia"), ("outer", "Kea")])
def test_roller_runout_is_named_kia_or_kea(tmp_path: Path, ring: str, name: str) -> None:
    text = EXAMPLE.read_text()
    assert 'rotating_ring = "inner"' in text
    case = tmp_path / "nu209.toml"
    case.write_text(text.replace('rotating_ring = "inner"', f'rotating_ring = "{ring}"'))
    runner = CliRunner()
    result = runner.invoke(app, ["run", str(case), "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["iso492"]["quantity"] == name
    assert data["iso492"]["radial_runout_m"] == data["runout"]["radial_pp_m"]
    readable = runner.invoke(app, ["run", str(case)], env={"COLUMNS": "200"})
    assert f"= {name} (ISO 492)" in readable.stdout
