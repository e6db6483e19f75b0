"""`runout run CASE --out DIR` copies the profile files the case names (review finding: DIR's
case.toml named `inner.csv` relative to DIR, where it was not, so `runout report DIR` could not
load the case and silently showed no inputs, and `runout run DIR/case.toml` failed)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
from typer.testing import CliRunner

from runout.cli.commands import app

CASE = """\
title = "profile travels with the results"
[bearing]
type = "ball"
elements = 8
element_diameter = "1 mm"
pitch_diameter = "7 mm"
radial_clearance = "10 um"
[operation]
rotating_ring = "outer"
speed = "5400 rpm"
axial_load = "20 N"
[[profile]]
part = "inner"
file = "data/inner.csv"
orders = [2, 12]
[analysis]
model = "quasi_static_3d"
revolutions = 8
samples = 1024
"""


def _case(where: Path) -> Path:
    (where / "data").mkdir(parents=True)
    angle = np.arange(360.0)
    deviation = 0.01 * np.cos(np.radians(9 * angle))  # um
    rows = "\n".join(f"{a:g},{d:.9g}" for a, d in zip(angle, deviation, strict=True))
    (where / "data" / "inner.csv").write_text("angle,deviation\n" + rows + "\n")
    path = where / "case.toml"
    path.write_text(CASE)
    return path


def test_the_out_directory_holds_the_profiles_its_case_names(tmp_path: Path) -> None:
    case = _case(tmp_path / "in")
    out = tmp_path / "results"
    done = CliRunner().invoke(app, ["run", str(case), "--out", str(out), "--report"])
    assert done.exit_code == 0, done.output
    copied = out / "data" / "inner.csv"
    assert copied.read_bytes() == (tmp_path / "in" / "data" / "inner.csv").read_bytes()
    # the directory's own case runs and gives the same results
    again = CliRunner().invoke(app, ["run", str(out / "case.toml"), "--json"])
    assert again.exit_code == 0, again.output
    first = json.loads((out / "result.json").read_text())
    assert json.loads(again.stdout)["runout"] == first["runout"]
    # and the report shows the profile among the inputs
    assert "inner.csv" in (out / "report.html").read_text(encoding="utf-8")


def test_a_report_whose_case_does_not_load_says_so(tmp_path: Path) -> None:
    # the report dropped the inputs without a word when DIR/case.toml no longer loaded
    case = _case(tmp_path / "in")
    out = tmp_path / "results"
    assert CliRunner().invoke(app, ["run", str(case), "--out", str(out)]).exit_code == 0
    (out / "data" / "inner.csv").unlink()  # the directory edited by hand
    done = CliRunner().invoke(app, ["report", str(out)])
    assert done.exit_code == 0, done.output
    page = (out / "report.html").read_text(encoding="utf-8")
    assert "case.toml does not load here" in page
    assert "inputs shown come from the results alone" in page
