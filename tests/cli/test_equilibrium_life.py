"""`runout run` with [bearing] dynamic_load_rating: the equilibrium model's JSON life.

The reference values are in tests/reference/test_iso_ts_16281_life.py; here: what the life is
made of is what the JSON's per-ball table gives, which ring turns, at speed, the nominal angle
of the rating, the refusals, and the notes when there is no life.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from typer.testing import CliRunner

from cases import run_case_text, run_json
from runout.cli.commands import app

runner = CliRunner()

CASE = """\
title = "life"
[bearing]
type = "ball"
elements = 7
element_diameter = "11.5 mm"
pitch_diameter = "43.5 mm"
inner_conformity = 0.52
outer_conformity = 0.53
{clearance}
{rating}
[material]
youngs_modulus = "210 GPa"
poisson_ratio = 0.3
[operation]
rotating_ring = "{ring}"
speed = "{speed}"
axial_load = "500 N"
radial_load = "1000 N"
[analysis]
model = "{model}"
"""


def _invoke(tmp_path: Path, *args: str, **keys: str) -> object:
    values = {
        "clearance": 'radial_clearance = "10 um"',
        "rating": 'dynamic_load_rating = "23.4 kN"',
        "ring": "inner",
        "speed": "0 rpm",
        "model": "equilibrium",
    } | keys
    return run_case_text(tmp_path / "life.toml", CASE.format(**values), *args)


def _run(tmp_path: Path, **keys: str) -> dict:
    return run_json(_invoke(tmp_path, "--json", **keys))


def _mean(loads: list[float], power: float) -> float:
    return (sum(q**power for q in loads) / len(loads)) ** (1.0 / power)


@pytest.mark.parametrize("ring", ["inner", "outer"])
def test_equivalent_loads_are_the_power_means_of_the_ball_table(tmp_path: Path, ring: str) -> None:
    out = _run(tmp_path, ring=ring)
    life = out["life"]
    q_i = [b["inner_load_n"] for b in out["balls"]]
    q_o = [b["outer_load_n"] for b in out["balls"]]
    # the ring turning relative to the load: cubic mean; the other: 10/3-power mean
    p_i, p_o = (3.0, 10.0 / 3.0) if ring == "inner" else (10.0 / 3.0, 3.0)
    assert life["equivalent_inner_load_n"] == pytest.approx(_mean(q_i, p_i), rel=1e-12)
    assert life["equivalent_outer_load_n"] == pytest.approx(_mean(q_o, p_o), rel=1e-12)
    assert life["l10r_inner_mrev"] == pytest.approx(
        (life["inner_contact_rating_n"] / life["equivalent_inner_load_n"]) ** 3, rel=1e-12
    )
    assert life["rotating_ring"] == ring
    assert life["dynamic_load_rating_n"] == 23400.0
    assert life["l10r_hours"] is None  # at rest
    assert life["method"].startswith("ISO/TS 16281:2008")
    assert any(n.startswith("life: ISO/TS 16281 basic reference rating life") for n in out["notes"])


def test_at_speed_hours_and_a_note(tmp_path: Path) -> None:
    out = _run(tmp_path, speed="3000 rpm")
    life = out["life"]
    assert life["l10r_hours"] == pytest.approx(life["l10r_mrev"] * 1e6 / (3000 * 60), rel=1e-12)
    assert any("centrifugal force" in n and n.startswith("life:") for n in out["notes"])


def test_nominal_contact_angle_is_the_rating_angle(tmp_path: Path) -> None:
    deep = _run(tmp_path)["life"]
    # the play's free angle (7.56 deg) is not used for the rating; a catalogue angle is
    assert deep["nominal_contact_angle_deg"] == 0.0
    angular = _run(tmp_path, clearance='nominal_contact_angle = "15 deg"')
    assert angular["life"]["nominal_contact_angle_deg"] == pytest.approx(15.0, rel=1e-12)


def test_nominal_angle_of_a_thrust_bearing_gives_no_life(tmp_path: Path) -> None:
    out = _run(tmp_path, clearance='nominal_contact_angle = "50 deg"')
    assert "life" not in out
    assert any(
        n.startswith("bearing.dynamic_load_rating: no life") and "45 deg" in n for n in out["notes"]
    )


def test_no_rating_no_life_and_a_note(tmp_path: Path) -> None:
    out = _run(tmp_path, rating="")
    assert "life" not in out
    assert any(n.startswith("no life: give [bearing] dynamic_load_rating") for n in out["notes"])


def test_other_models_say_they_do_not_apply_it(tmp_path: Path) -> None:
    out = _run(tmp_path, model="quasi_static_3d", speed="1800 rpm")
    assert "life" not in out
    assert any(
        n.startswith("bearing.dynamic_load_rating: not applied by the quasi_static_3d model")
        for n in out["notes"]
    )


@pytest.mark.parametrize("value", ['"0 N"', '"-5 kN"', '"2e9 N"', '"23.4 mm"', "nan"])
def test_bad_ratings_are_refused_naming_file_and_key(tmp_path: Path, value: str) -> None:
    result = _invoke(tmp_path, "--json", rating=f"dynamic_load_rating = {value}")
    assert result.exit_code == 2  # type: ignore[attr-defined]
    stderr = result.stderr  # type: ignore[attr-defined]
    assert "life.toml" in stderr and "bearing.dynamic_load_rating" in stderr
    assert "Traceback" not in stderr
    assert len(stderr.strip().splitlines()) == 1


def test_readable_summary_shows_the_life(tmp_path: Path) -> None:
    life = _run(tmp_path)["life"]
    result = _invoke(tmp_path)
    assert result.exit_code == 0, result.stderr  # type: ignore[attr-defined]
    text = result.stdout  # type: ignore[attr-defined]
    assert "Reference rating life (ISO/TS 16281)" in text
    assert f"{life['l10r_mrev']:.6g}" in text
    assert math.isfinite(life["l10r_mrev"])


def test_python_api_carries_the_rating(tmp_path: Path) -> None:
    import runout
    from runout.case.model import Case

    bearing = runout.BallBearing(
        7,
        11.5e-3,
        43.5e-3,
        0.52,
        0.53,
        10e-6,
        material=runout.Material(210e9, 0.3),
        dynamic_load_rating=23400.0,
    )
    op = runout.Operation("inner", 0.0, axial_load=500.0, radial_load=1000.0)
    life = runout.run("equilibrium", bearing=bearing, operation=op).to_json()["life"]
    assert life["l10r_mrev"] == pytest.approx(_run(tmp_path)["life"]["l10r_mrev"], rel=1e-12)
    # the case it builds writes the key back (runout run of the saved case gives the same)
    text = Case.from_inputs(bearing, op, analysis={"model": "equilibrium"}).to_toml()
    assert "dynamic_load_rating = 23400.0" in text


def test_report_shows_the_life(tmp_path: Path) -> None:
    life = _run(tmp_path)["life"]
    out = tmp_path / "out"
    assert _invoke(tmp_path, "--out", str(out)).exit_code == 0  # type: ignore[attr-defined]
    result = runner.invoke(app, ["report", str(out)])
    assert result.exit_code == 0, result.stderr
    page = (out / "report.html").read_text(encoding="utf-8")
    assert "reference rating life L10r" in page
    assert f"{life['l10r_mrev']:.4g} million rev" in page
    assert "Reference rating life (ISO/TS 16281)" in page
