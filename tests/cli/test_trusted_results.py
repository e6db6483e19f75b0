"""Results a user can trust (issue 14): each finding through the real command line.

Every test here failed before the shared decomposition (runout.analysis.decompose): a roller
bearing's
rotating-ring runout read as zero, RRO that moved five-fold with the record length, missing
second-order and load-zone lines, short dynamic records that merged lines without a word, and
labels of thousands of characters.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

runner = CliRunner()
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _run(path: Path) -> dict[str, Any]:
    result = runner.invoke(app, ["run", str(path), "--json"])
    assert result.exit_code == 0, result.stderr + result.stdout
    out: dict[str, Any] = json.loads(result.stdout)
    return out


def _write(tmp_path: Path, text: str, name: str = "case.toml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _lines(out: dict[str, Any], direction: str, order: float, tol: float = 1e-6) -> list[Any]:
    return [
        c
        for c in out["components"]
        if c["direction"] == direction and abs(c["order"] - order) < tol
    ]


# 1 -------------------------------------------------------------------------------------------
NU206 = """
title = "NU206, eccentric inner raceway"
[bearing]
type = "cylindrical_roller"
elements = 13
element_diameter = "8 mm"
inner_raceway_diameter = "37.5 mm"
outer_raceway_diameter = "53.53 mm"
[operation]
rotating_ring = "inner"
speed = "1 rpm"
radial_load = "20 N"
[[waviness]]
part = "inner"
order = 1
amplitude = "1 um"
[analysis]
model = "roller_constraint"
revolutions = 4
samples = 1441
"""


def test_roller_eccentric_turning_ring_is_rro(tmp_path: Path) -> None:
    out = _run(_write(tmp_path, NU206))
    # the eccentricity of the turning inner ring, read in the fixed load zone: 2 um p-p at
    # order 1, all of it repeatable
    (line,) = _lines(out, "y", 1.0)
    assert line["pp_m"] == pytest.approx(2e-6, rel=1e-3)
    assert line["repeatable"] and line["sources"][0]["part"] == "inner"
    assert out["runout"]["rro_pp_m"] == pytest.approx(2e-6, rel=1e-3)
    assert out["runout"]["nrro_pp_m"] < out["runout"]["radial_pp_m"]


def test_roller_fig9_over_16_revolutions_has_the_sideband_and_no_short_record_note(
    tmp_path: Path,
) -> None:
    text = (EXAMPLES / "seed004_nu209.toml").read_text(encoding="utf-8")
    text = text.replace("revolutions = 1.5", "revolutions = 16").replace(
        "samples = 2161", "samples = 8001"
    )
    out = _run(_write(tmp_path, text))
    z = 14
    fc = out["frequencies_hz"]["cage"] / out["frequencies_hz"]["rotation"]
    sideband = _lines(out, "y", abs(10 - z * fc), tol=1e-4)
    assert sideband and sideband[0]["pp_m"] > 1e-6
    assert not any("fewer than 2 whole revolutions" in n for n in out["notes"])


# 2 -------------------------------------------------------------------------------------------
SPECTRUM_6204 = """
title = "6204, outer spectrum, inner 9 lobes, ball size errors"
[bearing]
elements = 8
element_diameter = "7.938 mm"
pitch_diameter = "33.5 mm"
inner_conformity = 0.52
outer_conformity = 0.52
radial_clearance = "10 um"
[operation]
speed = "1800 rpm"
axial_load = "50 N"
[[waviness_spectrum]]
part = "outer"
orders = [2, 30]
amplitude = "50 nm"
exponent = -1
phase = "random"
seed = 3
[[waviness]]
part = "inner"
order = 9
amplitude = "20 nm"
[elements]
diameter_errors = ["0.1 um", 0, "-0.05 um", 0, "0.02 um", 0, 0, 0]
[analysis]
model = "{model}"
revolutions = {revolutions}
samples = {samples}
"""


def test_rro_does_not_depend_on_the_record_length(tmp_path: Path) -> None:
    runs = {}
    for revolutions in (10, 20, 40):
        text = SPECTRUM_6204.format(
            model="quasi_static_3d", revolutions=revolutions, samples=400 * revolutions
        )
        runs[revolutions] = _run(_write(tmp_path, text, f"r{revolutions}.toml"))["runout"]
    for r in runs.values():
        # no source is synchronous with the inner ring but the 9 lobes' second order: RRO ~ 0
        assert r["rro_pp_m"] < 1e-3 * r["radial_pp_m"]
        # p-p(total - RRO) <= p-p(total) + p-p(RRO)
        assert r["nrro_pp_m"] <= r["radial_pp_m"] + r["rro_pp_m"]
    # converged once the record resolves the lines: < 1 % between N and 2N revolutions
    assert runs[40]["nrro_pp_m"] == pytest.approx(runs[20]["nrro_pp_m"], rel=1e-2)
    linear = _run(
        _write(
            tmp_path, SPECTRUM_6204.format(model="linear", revolutions=20, samples=8000), "l.toml"
        )
    )
    assert linear["runout"]["rro_pp_m"] == 0.0


# 3 -------------------------------------------------------------------------------------------
BALLS = """
title = "ball waviness and a size error, radially loaded"
[bearing]
elements = 8
element_diameter = "1 mm"
pitch_diameter = "7 mm"
radial_clearance = "10 um"
[operation]
speed = "5400 rpm"
axial_load = "10 N"
radial_load = "10 N"
[[waviness]]
part = "ball"
element = 1
order = 2
amplitude = "5 nm"
[elements]
diameter_errors = ["50 nm", 0, 0, 0, 0, 0, 0, 0]
[analysis]
model = "quasi_static_3d"
revolutions = 20
samples = 8192
"""


def test_ball_lines_complete_and_no_rro_without_a_synchronous_source(tmp_path: Path) -> None:
    out = _run(_write(tmp_path, BALLS))
    r = out["runout"]
    assert r["rro_pp_m"] == 0.0
    assert r["nrro_pp_m"] <= r["radial_pp_m"] * (1 + 1e-12)
    fc = out["frequencies_hz"]["cage"] / out["frequencies_hz"]["rotation"]
    first = _lines(out, "y", fc)[0]
    # the size error's load-zone harmonic 2 f_c is a predicted line, about 10-30 % of f_c
    (second,) = _lines(out, "y", 2 * fc)
    assert 0.05 < second["pp_m"] / first["pp_m"] < 0.5
    assert second["sources"][0]["part"] == "ball" and "2 f_c" in second["sources"][0]["term"]
    assert out["explained_fraction"] > 0.999


# 4 -------------------------------------------------------------------------------------------
SHORT = """
title = "short record"
[bearing]
elements = 8
element_diameter = "1 mm"
pitch_diameter = "7 mm"
inner_conformity = 0.52
outer_conformity = 0.53
radial_clearance = "10 um"
[operation]
speed = "5400 rpm"
axial_load = "20 N"
[[waviness]]
part = "ball"
element = 1
order = 2
amplitude = "5 nm"
[[waviness]]
part = "ball"
element = 2
order = 2
amplitude = "5 nm"
phase = "40 deg"
{dynamics}
[analysis]
model = "{model}"
revolutions = 4
samples = 2048
"""


def test_short_dynamic_record_keeps_the_ball_lines(tmp_path: Path) -> None:
    dyn = _run(
        _write(
            tmp_path,
            SHORT.format(
                model="dynamic", dynamics='[dynamics]\nmass = "0.002 kg"\ndamping = "5 N*s/m"'
            ),
            "d.toml",
        )
    )
    qs = _run(_write(tmp_path, SHORT.format(model="quasi_static_3d", dynamics=""), "q.toml"))
    f = qs["frequencies_hz"]
    for sign in (1, -1):
        order = abs(2 * f["ball_spin"] + sign * f["cage"]) / f["rotation"]
        (a,) = _lines(dyn, "x", order, tol=1e-6)
        (b,) = _lines(qs, "x", order, tol=1e-6)
        assert a["pp_m"] == pytest.approx(b["pp_m"], rel=1e-2)
        assert abs(math.remainder(a["phase_rad"] - b["phase_rad"], 2 * math.pi)) < 1e-2
        assert "ball passage" not in a["label"]


def test_perfect_loaded_bearing_at_low_speed_has_no_rro(tmp_path: Path) -> None:
    text = """
title = "perfect 6204, 20 N, 60 rpm"
[bearing]
elements = 8
element_diameter = "7.938 mm"
pitch_diameter = "33.5 mm"
inner_conformity = 0.52
outer_conformity = 0.52
radial_clearance = "10 um"
[operation]
speed = "60 rpm"
radial_load = "20 N"
[dynamics]
mass = "0.5 kg"
damping = "200 N*s/m"
[analysis]
model = "dynamic"
revolutions = 4
samples = 2048
"""
    out = _run(_write(tmp_path, text))
    r = out["runout"]
    assert r["rro_pp_m"] < 1e-3 * r["radial_pp_m"]
    assert out["components"][0]["label"].startswith("ball passage")


# 5 -------------------------------------------------------------------------------------------
def test_labels_are_short_and_sources_are_ranked_data(tmp_path: Path) -> None:
    text = """
title = "outer 4 and 8 lobes"
[bearing]
elements = 8
element_diameter = "1 mm"
pitch_diameter = "7 mm"
radial_clearance = "10 um"
[operation]
speed = "5400 rpm"
axial_load = "20 N"
[[waviness_spectrum]]
part = "outer"
orders = [2, 60]
amplitude = "0.3 um"
exponent = -1
phase = "random"
seed = 7
[[waviness]]
part = "outer"
order = 8
amplitude = "100 nm"
[analysis]
model = "quasi_static_3d"
revolutions = 8
samples = 4096
"""
    out = _run(_write(tmp_path, text))
    for c in out["components"]:
        assert len(c["label"]) <= 80
        shares = [s["share"] for s in c["sources"]]
        assert sum(shares) == pytest.approx(1.0, abs=1e-9)
        assert abs(shares[0]) == max(abs(v) for v in shares)
        assert set(c["sources"][0]) == {
            "part",
            "element",
            "lobes",
            "term",
            "formula",
            "share",
            "share_basis",
        }
    # the largest axial line (Z f_c) is mostly the 8 lobes' first order, not a higher order
    axial = next(c for c in out["components"] if c["direction"] == "z")
    top = axial["sources"][0]
    assert top["lobes"] == 8 and top["term"].startswith("nZ, n=1")
    assert axial["label"].startswith("outer 8 lobes")
