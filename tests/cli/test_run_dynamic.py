"""`runout run` on the dynamic examples and `runout sweep-dynamic` (seed 003)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
runner = CliRunner()


def test_run_json_contract_clearance_example(tmp_path: Path) -> None:
    case = EXAMPLES / "seed003_purohit_clearance.toml"
    result = runner.invoke(app, ["run", str(case), "--json", "--out", str(tmp_path)])
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert payload["model"] == "dynamic"
    for key in ("frequencies_hz", "contact_angle_deg", "runout", "components"):
        assert key in payload
    mean = payload["mean_displacement_m"]
    assert len(mean) == 2 and mean[1] < -0.1e-6  # load along -y beyond the 0.1 um play
    fn = payload["natural_frequencies_hz"]
    assert len(fn) == 2 and all(f > 0 for f in fn)
    top = payload["components"][0]
    assert top["label"].startswith("ball passage")
    bpf = payload["frequencies_hz"]["ball_pass_outer"]
    assert math.isclose(top["frequency_hz"], bpf, rel_tol=1e-9)
    assert any(c["label"].startswith("unbalance") for c in payload["components"])
    r = payload["runout"]
    assert r["radial_pp_m"] > 0 and r["rro_pp_m"] + r["nrro_pp_m"] > 0
    for name in ("spectrum.png", "spectrum.csv", "orbit.png", "result.json"):
        assert (tmp_path / name).stat().st_size > 0


def test_run_preloaded_example_has_no_visible_ball_passage() -> None:
    # 10 N preload loads every ball: the BPV falls below the solver's resolution
    result = runner.invoke(app, ["run", str(EXAMPLES / "seed003_purohit.toml"), "--json"])
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert payload["contact_angle_deg"] > 3.0
    assert payload["runout"]["radial_pp_m"] < 1e-12
    assert payload["natural_frequencies_hz"][0] > 1000.0


def test_sweep_dynamic_writes_panels_and_resumes(tmp_path: Path) -> None:
    case = EXAMPLES / "seed003_purohit_clearance.toml"
    args = ["sweep-dynamic", str(case), "--elements", "6,9", "--preload", "0,5", "--out"]
    result = runner.invoke(app, [*args, str(tmp_path), "--json"])
    assert result.exit_code == 0, result.stderr
    points = json.loads(result.stdout)["points"]
    assert [(p["elements"], p["preload_n"]) for p in points] == [
        (6, 0.0),
        (6, 5.0),
        (9, 0.0),
        (9, 5.0),
    ]
    for name in ("sweep.csv", "trend.png", "spectra_elements_P0N.png", "spectra_preload_Z9.png"):
        assert (tmp_path / name).stat().st_size > 0
    saved = tmp_path / "points" / "Z6_P0N.json"
    stamp = saved.stat().st_mtime_ns
    again = runner.invoke(app, [*args, str(tmp_path), "--json"])
    assert again.exit_code == 0, again.stderr
    assert saved.stat().st_mtime_ns == stamp  # reused, not recomputed
    assert json.loads(again.stdout)["points"] == points


def test_sweep_dynamic_bad_list() -> None:
    case = EXAMPLES / "seed003_purohit.toml"
    result = runner.invoke(app, ["sweep-dynamic", str(case), "--elements", "5,x"])
    assert result.exit_code == 2
    result = runner.invoke(app, ["sweep-dynamic", str(case), "--elements", "40"])
    assert result.exit_code == 2
    assert "elements" in result.stderr


CASE_6204 = """\
title = "6204-like, {elements} balls, {load} N along -y"

[bearing]
type = "ball"
elements = {elements}
element_diameter = "{diameter}"
pitch_diameter = "33.5 mm"
inner_conformity = 0.52
outer_conformity = 0.52
radial_clearance = "10 um"

[operation]
speed = "3000 rpm"
radial_load = "{load} N"
axial_load = "{axial} N"

[dynamics]
mass = "0.5 kg"
damping = "200 N*s/m"

[analysis]
model = "dynamic"
revolutions = 4
samples = 512
"""


def _finite(value: object) -> bool:
    if isinstance(value, float):
        return math.isfinite(value)
    if isinstance(value, dict):
        return all(_finite(v) for v in value.values())
    if isinstance(value, list):
        return all(_finite(v) for v in value)
    return True


@pytest.mark.parametrize(
    ("elements", "diameter", "load", "axial"),
    [
        # a ball straight under a load along -y (Z divisible by 4): with only that ball loaded
        # (its neighbours stay inside the 5 um radial play) the rotor is free across the load
        (8, "7.938 mm", 20.0, 0.0),
        (4, "7.938 mm", 20.0, 0.0),
        (12, "7.938 mm", 5.0, 0.0),
        (16, "6.35 mm", 1.0, 0.0),
        (8, "7.938 mm", 20.0, 0.01),
        # the same bearings where the neighbours are loaded too (three balls)
        (12, "7.938 mm", 20.0, 0.0),
        (16, "6.35 mm", 20.0, 0.0),
    ],
)
def test_run_starts_with_a_ball_right_under_the_load(
    tmp_path: Path, elements: int, diameter: str, load: float, axial: float
) -> None:
    case = tmp_path / "case.toml"
    case.write_text(
        CASE_6204.format(elements=elements, diameter=diameter, load=f"{load:g}", axial=axial)
    )
    result = runner.invoke(app, ["run", str(case), "--json", "--out", str(tmp_path / "out")])
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert _finite(payload)
    r = payload["runout"]
    assert math.isfinite(r["radial_pp_m"]) and r["radial_pp_m"] >= 0.0
    # shaft in housing: the load along -y moves the inner ring down; without preload by more
    # than the 5 um radial play (a rigid axial preload, however small, takes the play up)
    y = payload["mean_displacement_m"][1]  # [x, y], and z with an axial preload
    assert y < (-5e-6 if axial == 0.0 else 0.0)
    history = np.loadtxt(tmp_path / "out" / "history.csv", delimiter=",", skiprows=1)
    assert history.shape == (4 * 128, 4) and np.all(np.isfinite(history))
    assert history[0, 0] == 0.0  # time origin: the start of the reported record
    revolutions = payload["transient_s"] * 50.0  # 3000 rpm
    assert revolutions >= 1 and revolutions == pytest.approx(round(revolutions), abs=1e-9)
