"""Findings of this session's review, each through the real command line (they failed before):
an index into a malformed table, an absurd speed, a closed standard output, and a moment shown
as a length in the equilibrium report."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from typer.testing import CliRunner

from runout.cli.commands import app

runner = CliRunner()
ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
SCRIPT = Path(sys.executable).with_name("runout")


def _said(result: object) -> str:
    return " ".join(result.stderr.split())  # type: ignore[attr-defined]


def test_set_into_a_malformed_table_is_named_not_an_internal_error(tmp_path: Path) -> None:
    case = tmp_path / "bad.toml"
    text = (EXAMPLES / "seed000_tada_fig7.toml").read_text(encoding="utf-8")
    case.write_text(text.split("[[waviness]]")[0] + "waviness = [1, 2]\n", encoding="utf-8")
    result = runner.invoke(app, ["check", str(case), "--set", "waviness[1].order=3"])
    assert result.exit_code == 2, result.stderr
    assert "waviness[1]" in _said(result)


def test_a_speed_beyond_any_bearing_is_refused_not_overflowed() -> None:
    case = str(EXAMPLES / "seed003_purohit.toml")
    result = runner.invoke(app, ["check", case, "--set", "operation.speed=1e300"])
    assert result.exit_code == 2, result.stderr
    assert "operation.speed" in _said(result) and "rpm" in _said(result)


def test_a_closed_standard_output_is_a_write_error_not_a_bug() -> None:
    command = f'"{SCRIPT}" run "{EXAMPLES / "seed002_608.toml"}" --json >&-'
    done = subprocess.run(["bash", "-c", command], capture_output=True, text=True, timeout=300)
    assert done.returncode == 1, done.stderr
    assert "cannot write the output" in done.stderr
    assert "internal error" not in done.stderr


def test_the_equilibrium_report_shows_the_gyroscopic_moment_as_a_moment(tmp_path: Path) -> None:
    out = tmp_path / "kim"
    case = str(EXAMPLES / "seed001_kim_equilibrium.toml")
    result = runner.invoke(app, ["run", case, "--out", str(out), "--report"])
    assert result.exit_code == 0, result.stderr
    page = (out / "report.html").read_text(encoding="utf-8")
    assert "gyroscopic moment" in page
    assert "755.4 nm" not in page  # 7.554e-7 N m read as metres


def test_study_model_cannot_be_silently_ignored_by_the_study_models_list(tmp_path: Path) -> None:
    case = str(EXAMPLES / "seed001_kim_table9.toml")
    text = (EXAMPLES / "seed001_kim_table9.toml").read_text(encoding="utf-8")
    listed = tmp_path / "listed.toml"
    listed.write_text(text.replace("[study]\n", '[study]\nmodels = ["quasi_static_2d"]\n', 1))
    result = runner.invoke(app, ["study", str(listed), "--model", "linear", "--json"])
    assert result.exit_code == 2
    assert "study.models" in _said(result)
    # without a list, --model chooses the model
    result = runner.invoke(
        app, ["study", case, "--model", "linear", "--set", "study.samples=4", "--json"]
    )
    assert result.exit_code == 0, result.stderr
    assert '"linear"' in result.stdout


def test_numpy_integers_are_integers_and_degrees_are_not_radians() -> None:
    import numpy as np
    import pytest

    import runout
    from runout.base.errors import CaseError

    bearing = runout.BallBearing(elements=np.int64(8), element_diameter=1e-3, pitch_diameter=7e-3)
    assert type(bearing.elements) is int and bearing.elements == 8
    theta = np.linspace(0.0, 360.0, 360, endpoint=False)
    with pytest.raises(CaseError, match='angle_unit="deg"'):
        runout.Imperfections().profile(
            "inner", orders=(2, 12), angles=theta, deviations=np.cos(9 * theta)
        )
    ok = runout.Imperfections().profile(
        "inner",
        orders=(2, 12),
        angles=theta,
        deviations=1e-8 * np.cos(np.radians(9 * theta)),
        angle_unit="deg",
    )
    assert ok.entries
