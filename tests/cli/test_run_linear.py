"""`runout run` on the seed 002 example (linear model): JSON contract, table, files."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from runout.case.model import load_case
from runout.cli.commands import app
from runout.models import linear as lin

CASE = Path(__file__).resolve().parents[2] / "examples" / "seed002_608.toml"
runner = CliRunner()


def test_run_json_contract() -> None:
    result = runner.invoke(app, ["run", str(CASE), "--json"])
    assert result.exit_code == 0, result.stderr
    p = json.loads(result.stdout)
    assert p["model"] == "linear"
    assert set(p["anderon"]) == set("URLMHEA")
    assert p["anderon"]["R"] == pytest.approx(59.61, rel=1e-3)
    assert set(p["runout"]) == {"radial_pp_m", "axial_pp_m", "rro_pp_m", "nrro_pp_m"}
    assert p["runout"]["axial_pp_m"] is None  # the linear model has no axial freedom
    # eccentricity 2.5 um x cos 10 deg dominates the RRO: p-p 2 x 2.462 um plus the slant
    assert p["runout"]["rro_pp_m"] == pytest.approx(2 * 2.5e-6 * 0.98481, rel=0.05)
    assert 0 < p["runout"]["nrro_pp_m"] < p["runout"]["radial_pp_m"]
    first = p["components"][0]
    assert set(first) == {
        "direction",
        "frequency_hz",
        "order",
        "pp_m",
        "label",
        "phase_rad",
        "repeatable",
        "sources",
    }
    assert first["order"] == pytest.approx(1.0) and "eccentricity" in first["label"]
    assert len(first["label"]) <= 80
    top = first["sources"][0]
    assert top["part"] == "inner" and top["lobes"] == 1 and top["share"] > 0.5
    assert {c["direction"] for c in p["components"]} == {"x", "y"}
    assert any(r["formula"].startswith("Z(1+γ)/2") for r in p["attribution"])
    assert p["frequencies_hz"]["rotation"] == pytest.approx(30.0)


def test_run_table_and_files(tmp_path: Path) -> None:
    result = runner.invoke(app, ["run", str(CASE), "--out", str(tmp_path)])
    assert result.exit_code == 0, result.stderr
    out = " ".join(result.stdout.split())
    assert "Frequency attribution" in out and "Anderon" in out
    for name in ("density_waveform.png", "anderon_spectrum.png", "anderon_bands.png"):
        assert (tmp_path / name).stat().st_size > 10_000


def test_rro_plus_nrro_is_the_waveform() -> None:
    res = lin.run(load_case(CASE))
    lines = res.spectral_lines
    assert lines is not None
    _, xr, _ = lin.synthesize(lines.select(lines.repeatable), 6, 24576)
    _, xn, _ = lin.synthesize(lines.select(~lines.repeatable), 6, 24576)
    assert abs((xr + xn) - res.x).max() < 1e-12 * abs(res.x).max()
    assert res.runout.nrro_pp_m == pytest.approx(float(xn.max() - xn.min()), rel=1e-9)
    comparison = res.anderon_comparison()
    assert comparison["R"]["relative_difference"] == pytest.approx(0.0, abs=1e-3)
    assert comparison["U"]["dft"] > 0
