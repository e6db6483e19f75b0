"""`runout run` of a spindle with [[bearings]] dynamic_load_rating: each bearing's L10r.

The spindle model's contacts (seed 000) carry one load per ball, the same on both raceways,
along the bearing's fixed contact angle. Under the preload alone every ball of a bearing
carries preload / (Z sin α), which the life's equivalent loads must equal; the life is then
ISO/TS 16281 eq. 29 of those loads and the contact ratings. Here also: a radial load shortens
the lives, a bearing without C has none (a note names it), the modified life per bearing, the
summary and the report.
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
title = "spindle life"
[spindle]
arrangement = "DB"
preload_displacement = "6 um"
nose_position = "-100 mm"
[[bearings]]
name = "A"
position = "0 mm"
type = "ball"
elements = 20
element_diameter = "11.1125 mm"
pitch_diameter = "90 mm"
inner_conformity = 0.52
outer_conformity = 0.53
nominal_contact_angle = "25 deg"
{rating_a}
[[bearings]]
name = "B"
position = "20 mm"
type = "ball"
elements = 20
element_diameter = "11.1125 mm"
pitch_diameter = "90 mm"
inner_conformity = 0.52
outer_conformity = 0.53
nominal_contact_angle = "25 deg"
{rating_b}
[operation]
rotating_ring = "inner"
speed = "12000 rpm"
{radial}
{lubrication}
[analysis]
model = "spindle"
revolutions = 2
samples = 256
"""

KEYS = {
    "rating_a": 'dynamic_load_rating = "38 kN"',
    "rating_b": 'dynamic_load_rating = "38 kN"',
    "radial": "",
    "lubrication": "",
}


def _invoke(tmp_path: Path, *args: str, **keys: str) -> object:
    return run_case_text(tmp_path / "spindle.toml", CASE.format(**(KEYS | keys)), *args)


def _run(tmp_path: Path, **keys: str) -> dict:
    return run_json(_invoke(tmp_path, "--json", **keys))


def test_each_bearing_life_is_that_of_its_preload_shared_by_its_balls(tmp_path: Path) -> None:
    out = _run(tmp_path)
    e = 10.0 / 9.0
    for b in out["bearings"]:
        life = b["life"]
        q = b["preload_n"] / (20 * math.sin(math.radians(b["contact_angle_deg"])))
        # one load per ball, on both raceways: both equivalent loads are that load
        assert life["equivalent_inner_load_n"] == pytest.approx(q, rel=1e-9)
        assert life["equivalent_outer_load_n"] == pytest.approx(q, rel=1e-9)
        l_i = (life["inner_contact_rating_n"] / q) ** 3
        l_o = (life["outer_contact_rating_n"] / q) ** 3
        assert life["l10r_mrev"] == pytest.approx((l_i**-e + l_o**-e) ** (-1 / e), rel=1e-9)
        assert life["nominal_contact_angle_deg"] == pytest.approx(25.0)
        assert life["l10r_hours"] == pytest.approx(life["l10r_mrev"] * 1e6 / (200.0 * 3600.0))
    assert any("life: each bearing's from its ball loads" in n for n in out["notes"])


def test_a_radial_load_shortens_both_lives(tmp_path: Path) -> None:
    free = _run(tmp_path)["bearings"]
    loaded = _run(tmp_path, radial='radial_load = "2 kN"')["bearings"]
    for a, b in zip(free, loaded, strict=True):
        assert b["life"]["l10r_mrev"] < a["life"]["l10r_mrev"]


def test_a_bearing_without_rating_has_no_life_and_is_named(tmp_path: Path) -> None:
    out = _run(tmp_path, rating_b="")
    assert "life" in out["bearings"][0]
    assert "life" not in out["bearings"][1]
    assert any("no life for bearings[2] (B)" in n for n in out["notes"])


def test_no_rating_no_life_and_no_life_note(tmp_path: Path) -> None:
    out = _run(tmp_path, rating_a="", rating_b="")
    assert all("life" not in b for b in out["bearings"])
    assert not any("life" in n for n in out["notes"])


def test_modified_life_per_bearing(tmp_path: Path) -> None:
    rating = 'dynamic_load_rating = "38 kN"\nfatigue_load_limit = "1.2 kN"'
    lube = "[lubrication]\nviscosity_ratio = 2\ncontamination_factor = 0.6"
    out = _run(tmp_path, rating_a=rating, rating_b=rating, lubrication=lube)
    for b in out["bearings"]:
        life = b["life"]
        assert life["fatigue_load_limit_n"] == 1200.0
        assert life["lnmr_mrev"] == pytest.approx(life["a_iso"] * life["l10r_mrev"], rel=1e-12)


def test_summary_and_report_show_each_life(tmp_path: Path) -> None:
    lives = [b["life"]["l10r_mrev"] for b in _run(tmp_path)["bearings"]]
    result = _invoke(tmp_path)
    assert result.exit_code == 0, result.stderr  # type: ignore[attr-defined]
    text = result.stdout  # type: ignore[attr-defined]
    for name, life in zip("AB", lives, strict=True):
        assert f"{name}: reference rating life L10r (ISO/TS 16281)" in text
        assert f"{life:.6g}" in text
    out = tmp_path / "out"
    assert _invoke(tmp_path, "--out", str(out)).exit_code == 0  # type: ignore[attr-defined]
    assert runner.invoke(app, ["report", str(out)]).exit_code == 0
    page = (out / "report.html").read_text(encoding="utf-8")
    assert "reference rating life L10r [million rev] (ISO/TS 16281)" in page
    for life in lives:
        assert f"{life:.4g}" in page
