"""`runout run` with the a_ISO inputs: the modified reference rating life L_nmr = a_1 a_ISO L10r.

ISO/TS 16281:2008 with ISO 281:2007's factors: a_1 from the reliability, a_ISO of a radial
ball bearing from κ, e_C, C_u at the dynamic equivalent reference load P_ref. Here: the JSON
keys and how they combine, κ from the operating viscosity, the κ range's edges (κ > 4 taken as
4, κ < 0.1 no L_nmr), missing inputs said, the summary and report, and hostile values refused
in one line naming the file and key. The a_ISO function's properties are in
tests/property/test_life_modification.py.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from typer.testing import CliRunner

from cases import MODIFIED_LIFE_CASE as CASE
from cases import MODIFIED_LIFE_KEYS as FULL
from cases import run_case_text, run_json
from runout.cli.commands import app

runner = CliRunner()


def _invoke(tmp_path: Path, *args: str, **keys: str) -> object:
    return run_case_text(tmp_path / "lnmr.toml", CASE.format(**(FULL | keys)), *args)


def _run(tmp_path: Path, **keys: str) -> dict:
    return run_json(_invoke(tmp_path, "--json", **keys))


def _a_iso(kappa: float, ratio: float) -> float:
    """ISO 281:2007 a_ISO of a radial ball bearing, typed from the standard's three ranges."""
    c1, c2 = (2.2649, 0.054381) if kappa < 0.4 else (1.9987, 0.19087 if kappa < 1 else 0.071739)
    bracket = 1.0 - (2.5671 - c1 / kappa**c2) ** 0.83 * ratio ** (1.0 / 3.0)
    return min(50.0, 0.1 * bracket**-9.3)


def test_lnmr_is_a1_a_iso_l10r_at_the_reference_load(tmp_path: Path) -> None:
    out = _run(tmp_path)
    life = out["life"]
    assert life["reliability_percent"] == 99.0
    assert life["a1"] == 0.25  # ISO 281's table at 99 %
    assert life["viscosity_ratio"] == 1.5
    assert life["contamination_factor"] == 0.5
    assert life["fatigue_load_limit_n"] == 600.0
    # a_ISO is evaluated at P_ref = C L10r^(-1/3), the TS's dynamic equivalent reference load
    p_ref = life["equivalent_reference_load_n"]
    assert p_ref == pytest.approx(23400.0 * life["l10r_mrev"] ** (-1.0 / 3.0), rel=1e-12)
    assert life["a_iso"] == pytest.approx(_a_iso(1.5, 0.5 * 600.0 / p_ref), rel=1e-12)
    assert 0.1 < life["a_iso"] < 50.0
    assert life["lnmr_mrev"] == pytest.approx(0.25 * life["a_iso"] * life["l10r_mrev"], rel=1e-12)
    assert life["lnmr_hours"] == pytest.approx(0.25 * life["a_iso"] * life["l10r_hours"], rel=1e-12)
    assert any("L_nmr = a_1 a_ISO L10r" in n and "a_1 = 0.25" in n for n in out["notes"])


def test_kappa_from_the_operating_viscosity_and_iso_281_rated_viscosity(tmp_path: Path) -> None:
    lube = '[lubrication]\noperating_viscosity = "20 mm^2/s"\ncontamination_factor = 0.5'
    life = _run(tmp_path, lubrication=lube)["life"]
    # ISO 281: ν_1 = 4500 n^-0.5 D_pw^-0.5 [mm²/s] from 1000 r/min (n = 3000, D_pw = 43.5 mm)
    nu1 = 4500.0 * 3000.0**-0.5 * 43.5**-0.5
    assert life["viscosity_ratio"] == pytest.approx(20.0 / nu1, rel=1e-12)
    slow = _run(tmp_path, lubrication=lube, speed="600 rpm")["life"]
    nu1_slow = 45000.0 * 600.0**-0.83 * 43.5**-0.5  # below 1000 r/min
    assert slow["viscosity_ratio"] == pytest.approx(20.0 / nu1_slow, rel=1e-12)
    given = _run(tmp_path, lubrication=lube + '\nrated_viscosity = "40 cSt"')["life"]
    assert given["viscosity_ratio"] == pytest.approx(0.5, rel=1e-12)


def test_kappa_above_4_is_taken_as_4_and_said(tmp_path: Path) -> None:
    lube = "[lubrication]\nviscosity_ratio = 7.5\ncontamination_factor = 0.5"
    out = _run(tmp_path, lubrication=lube)
    four = _run(tmp_path, lubrication=lube.replace("7.5", "4"))["life"]
    assert out["life"]["viscosity_ratio"] == 4.0
    assert out["life"]["a_iso"] == four["a_iso"]
    assert any("κ = 7.5 taken as 4" in n for n in out["notes"])


def test_kappa_below_0_1_gives_no_lnmr_and_a_note(tmp_path: Path) -> None:
    lube = "[lubrication]\nviscosity_ratio = 0.05\ncontamination_factor = 0.5"
    out = _run(tmp_path, lubrication=lube)
    life = out["life"]
    assert life["a_iso"] is None and life["lnmr_mrev"] is None and life["lnmr_hours"] is None
    assert math.isfinite(life["l10r_mrev"])  # the reference life stands
    assert any("no modified life" in n and "below 0.1" in n for n in out["notes"])


def test_a_missing_input_is_named(tmp_path: Path) -> None:
    out = _run(tmp_path, limit="")
    assert out["life"]["lnmr_mrev"] is None
    assert any(
        "no modified life L_nmr: a_ISO needs bearing.fatigue_load_limit" in n for n in out["notes"]
    )


def test_reliability_alone_is_said_not_applied(tmp_path: Path) -> None:
    out = _run(tmp_path, limit="", lubrication="")
    assert out["life"]["lnmr_mrev"] is None
    assert any("analysis.reliability = 99 % is not applied" in n for n in out["notes"])


def test_operating_viscosity_at_rest_needs_the_rated_one(tmp_path: Path) -> None:
    lube = '[lubrication]\noperating_viscosity = "20 cSt"\ncontamination_factor = 0.5'
    out = _run(tmp_path, lubrication=lube, speed="0 rpm")
    assert out["life"]["lnmr_mrev"] is None
    assert any("give lubrication.rated_viscosity" in n for n in out["notes"])
    rated = _run(tmp_path, lubrication=lube + '\nrated_viscosity = "10 cSt"', speed="0 rpm")
    assert rated["life"]["viscosity_ratio"] == pytest.approx(2.0, rel=1e-12)
    assert rated["life"]["lnmr_hours"] is None  # at rest: no hours
    assert rated["life"]["lnmr_mrev"] is not None


def test_summary_and_report_show_the_modified_life(tmp_path: Path) -> None:
    life = _run(tmp_path)["life"]
    result = _invoke(tmp_path)
    assert result.exit_code == 0, result.stderr  # type: ignore[attr-defined]
    text = result.stdout  # type: ignore[attr-defined]
    assert "modified life L_nmr = a_1 a_ISO L10r" in text
    assert f"{life['lnmr_mrev']:.6g}" in text
    out = tmp_path / "out"
    assert _invoke(tmp_path, "--out", str(out)).exit_code == 0  # type: ignore[attr-defined]
    assert runner.invoke(app, ["report", str(out)]).exit_code == 0
    page = (out / "report.html").read_text(encoding="utf-8")
    assert "modified life L_nmr" in page
    assert f"{life['lnmr_mrev']:.4g} million rev" in page


def test_other_models_say_they_do_not_apply_it(tmp_path: Path) -> None:
    out = _run(tmp_path, model="quasi_static_3d")
    assert any(
        n.startswith("bearing.fatigue_load_limit: not applied by the quasi_static_3d model")
        or n.startswith("lubrication: not applied by the quasi_static_3d model")
        for n in out["notes"]
    )


HOSTILE = [
    ("bearing.fatigue_load_limit", {"limit": "fatigue_load_limit = 0"}),
    ("bearing.fatigue_load_limit", {"limit": 'fatigue_load_limit = "5 mm"'}),
    ("bearing.fatigue_load_limit", {"limit": "fatigue_load_limit = -3"}),
    ("bearing.fatigue_load_limit", {"limit": "fatigue_load_limit = inf"}),
    ("lubrication.viscosity_ratio", {"lubrication": "[lubrication]\nviscosity_ratio = 0"}),
    ("lubrication.viscosity_ratio", {"lubrication": "[lubrication]\nviscosity_ratio = 1e9"}),
    ("lubrication.viscosity_ratio", {"lubrication": '[lubrication]\nviscosity_ratio = "x"'}),
    ("lubrication.viscosity_ratio", {"lubrication": "[lubrication]\nviscosity_ratio = nan"}),
    (
        "lubrication.contamination_factor",
        {"lubrication": "[lubrication]\ncontamination_factor = 1.5"},
    ),
    (
        "lubrication.contamination_factor",
        {"lubrication": "[lubrication]\ncontamination_factor = -0.1"},
    ),
    (
        "lubrication.operating_viscosity",
        {"lubrication": '[lubrication]\noperating_viscosity = "20 mm"'},
    ),
    (
        "lubrication.operating_viscosity",
        {"lubrication": "[lubrication]\noperating_viscosity = -2e-5"},
    ),
    (
        "lubrication.operating_viscosity",
        {"lubrication": '[lubrication]\nviscosity_ratio = 1\noperating_viscosity = "20 cSt"'},
    ),
    ("lubrication.rated_viscosity", {"lubrication": '[lubrication]\nrated_viscosity = "20 cSt"'}),
    ("lubrication.viscosity", {"lubrication": "[lubrication]\nviscosity = 1"}),
    ("analysis.reliability", {"reliability": "reliability = 93"}),
    ("analysis.reliability", {"reliability": "reliability = 100"}),
    ("analysis.reliability", {"reliability": 'reliability = "high"'}),
]


@pytest.mark.parametrize(
    ("key", "keys"), HOSTILE, ids=[f"{k}-{i}" for i, (k, _) in enumerate(HOSTILE)]
)
def test_hostile_values_are_refused_in_one_line(
    tmp_path: Path, key: str, keys: dict[str, str]
) -> None:
    result = _invoke(tmp_path, "--json", **keys)
    assert result.exit_code == 2  # type: ignore[attr-defined]
    stderr = result.stderr  # type: ignore[attr-defined]
    assert "lnmr.toml" in stderr and key in stderr, stderr
    assert "Traceback" not in stderr
    assert len(stderr.strip().splitlines()) == 1
