"""The command-line tool on the example case files."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

EXAMPLES = sorted((Path(__file__).resolve().parents[2] / "examples").glob("*.toml"))
runner = CliRunner()


@pytest.mark.parametrize("case", EXAMPLES, ids=lambda p: p.stem)
def test_check_accepts_every_example(case: Path) -> None:
    result = runner.invoke(app, ["check", str(case)])
    assert result.exit_code == 0, result.stderr
    assert "is valid" in result.stdout


@pytest.mark.parametrize("case", EXAMPLES, ids=lambda p: p.stem)
def test_check_json_is_valid_json(case: Path) -> None:
    result = runner.invoke(app, ["check", str(case), "--json"])
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert payload["bearing"]["elements"] >= 3
    assert "frequencies_hz" in payload


def test_frequencies_json_contract_for_the_608() -> None:
    case = next(p for p in EXAMPLES if p.stem == "seed002_608")
    result = runner.invoke(app, ["frequencies", str(case), "--json"])
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    freqs = payload["frequencies_hz"]
    assert set(freqs) == {"rotation", "cage", "ball_spin", "ball_pass_inner", "ball_pass_outer"}
    assert freqs["rotation"] == pytest.approx(30.0)
    assert freqs["ball_pass_outer"] / 30.0 == pytest.approx(2.58802, abs=1e-5)
    assert payload["contact_angle_deg"] == pytest.approx(10.0)


def test_frequencies_table_lists_orders() -> None:
    case = next(p for p in EXAMPLES if p.stem == "seed002_608")
    result = runner.invoke(app, ["frequencies", str(case)])
    assert result.exit_code == 0
    assert "2.58802" in result.stdout


def test_run_with_a_model_not_available_is_a_clear_error(monkeypatch) -> None:
    # Pretend this build has no models: the refusal must name the model and exit 2.
    monkeypatch.setattr("runout.models.MODEL_MODULES", {})
    case = next(p for p in EXAMPLES if p.stem == "seed003_purohit")
    result = runner.invoke(app, ["run", str(case)])
    assert result.exit_code == 2
    assert "analysis.model: model 'dynamic' is not available" in " ".join(result.stderr.split())


def test_the_installed_console_script_exits_2_without_traceback(tmp_path: Path) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text("[bearing]\nelements = 2\n", encoding="utf-8")
    exe = Path(sys.executable).with_name("runout")
    proc = subprocess.run(
        [str(exe), "check", str(bad)], capture_output=True, text=True, timeout=120
    )
    assert proc.returncode == 2
    assert "Traceback" not in proc.stderr
    assert "bad.toml: bearing.elements: must be an integer >= 3, got 2" in proc.stderr


def test_version() -> None:
    result = runner.invoke(app, ["--version"])
    assert result.exit_code == 0
    assert result.stdout.startswith("runout ")


def test_help_has_examples() -> None:
    for command in ("check", "frequencies", "run"):
        result = runner.invoke(app, [command, "--help"])
        assert result.exit_code == 0
        assert "Example:" in result.stdout


def test_loaded_contact_angle_is_reported_for_a_preloaded_case() -> None:
    case = next(p for p in EXAMPLES if p.stem == "seed000_tada_fig7")
    result = runner.invoke(app, ["frequencies", str(case), "--json"])
    payload = json.loads(result.stdout)
    # Preload raises the contact angle above the free contact angle of the clearance.
    free = math.degrees(math.acos(1 - 10e-6 / (2 * 0.05 * 1e-3)))
    assert payload["contact_angle_deg"] > free
