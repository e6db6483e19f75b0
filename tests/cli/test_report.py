"""HTML reports: self-contained, complete, and rendered by a real browser."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest
from typer.testing import CliRunner

from runout.cli import app

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
runner = CliRunner()


@pytest.fixture(scope="module")
def report_608(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("r608")
    result = runner.invoke(
        app, ["run", str(EXAMPLES / "seed002_608.toml"), "--out", str(out), "--report"]
    )
    assert result.exit_code == 0, result.stderr
    return out / "report.html"


def test_report_is_self_contained(report_608: Path) -> None:
    page = report_608.read_text(encoding="utf-8")
    # Figures are embedded; nothing is fetched from elsewhere.
    assert page.count("data:image/png;base64,") >= 5
    assert not re.search(r"""(src|href)=['"](https?:|file:|/)""", page)


def test_report_holds_inputs_results_and_attribution(report_608: Path) -> None:
    page = report_608.read_text(encoding="utf-8")
    for heading in (
        "Runout",
        "Bearing (inputs)",
        "Derived geometry",
        "Characteristic frequencies",
        "Attribution",
        "Spectral lines",
        "Anderon band values",
        "Figures",
        "Case file",
    ):
        assert f">{heading}" in page, heading
    assert "runout 0.1.0" in page
    assert "3.9688" in page  # the ball diameter, in mm
    assert "I_{7-1}" in page or "nZ(1+γ)/2 - 1" in page


def test_report_command_rebuilds_from_the_directory(report_608: Path) -> None:
    report_608.unlink()
    result = runner.invoke(app, ["report", str(report_608.parent)])
    assert result.exit_code == 0, result.stderr
    assert report_608.exists()


def test_report_of_a_directory_without_results_is_a_clear_error(tmp_path: Path) -> None:
    result = runner.invoke(app, ["report", str(tmp_path)])
    assert result.exit_code == 2
    assert "holds no result.json" in " ".join(result.stderr.split())


def _chromium() -> str | None:
    return shutil.which("chromium") or shutil.which("chromium-browser")


def test_report_renders_in_headless_chromium(report_608: Path, tmp_path: Path) -> None:
    browser = _chromium()
    if browser is None:
        if os.environ.get("CI"):
            pytest.fail("CI must install Debian's chromium (see .ci/run)")
        pytest.skip("headless Chromium is not installed here; CI installs it and runs this")
    shot = tmp_path / "page.png"
    subprocess.run(
        [
            browser,
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            f"--user-data-dir={tmp_path / 'profile'}",
            "--window-size=1200,1600",
            f"--screenshot={shot}",
            report_608.as_uri(),
        ],
        check=True,
        capture_output=True,
        timeout=120,
    )
    data = shot.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    assert len(data) > 20_000  # a rendered page with tables and figures, not a blank one


def test_report_of_a_study_directory(tmp_path: Path) -> None:
    case = (EXAMPLES / "seed001_kim_table9.toml").read_text(encoding="utf-8")
    small = tmp_path / "lot.toml"
    small.write_text(case.replace("samples = 1000", "samples = 8"), encoding="utf-8")
    out = tmp_path / "lot"
    result = runner.invoke(app, ["study", str(small), "--out", str(out)])
    assert result.exit_code == 0, result.stderr
    result = runner.invoke(app, ["report", str(out)])
    assert result.exit_code == 0, result.stderr
    page = (out / "report.html").read_text(encoding="utf-8")
    assert "Study statistics" in page
    assert "8 samples" in page
    assert "ball size error: f_c" in page
