"""The engineer's quantities through the CLI (issue 17): ISO 15242 bands, a spec limit with its
verdict and a lot's yield, lengths at the input's scale, roller passage names."""

from __future__ import annotations

import csv
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest
from scipy.stats import beta
from typer.testing import CliRunner

from runout.cli.commands import app

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
TADA = EXAMPLES / "seed000_tada_fig6.toml"  # quasi_static_3d, ~10 nm radial p-p
KIM_TABLE9 = EXAMPLES / "seed001_kim_table9.toml"  # quasi_static_2d Monte Carlo
KIM_EQUILIBRIUM = EXAMPLES / "seed001_kim_equilibrium.toml"
NU209 = EXAMPLES / "seed004_nu209.toml"

runner = CliRunner()

# A number printed in exponent notation ("5e-10", "1.6e+04").
EXPONENT = re.compile(r"\d[eE][-+]?\d")


def with_analysis(tmp_path: Path, source: Path, extra: str, name: str = "case.toml") -> Path:
    """``source`` with ``extra`` lines added to its [analysis] table."""
    text = source.read_text(encoding="utf-8")
    assert "[analysis]\n" in text
    path = tmp_path / name
    path.write_text(text.replace("[analysis]\n", "[analysis]\n" + extra + "\n", 1), "utf-8")
    return path


def run_json(case: Path) -> dict:
    result = runner.invoke(app, ["run", str(case), "--json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def refused(args: list[str]) -> str:
    """The error line of a command that must end with exit status 2."""
    result = runner.invoke(app, args)
    assert result.exit_code == 2, result.output
    return result.stderr


# -------------------------------------------------------------------------- ISO 15242 bands
def _band_rms_from_components(data: dict, low: float, high: float, axis: str = "x") -> float:
    """Velocity rms [um/s] of the radial lines along ``axis`` (the measuring direction), from
    the components of the JSON (independent of the implementation's line handling)."""
    ms = 0.0
    for c in data["components"]:
        if c["direction"] == axis and low <= c["frequency_hz"] < high:
            amplitude = c["pp_m"] / 2.0
            ms += 0.5 * (2.0 * math.pi * c["frequency_hz"] * amplitude) ** 2
    return math.sqrt(ms) * 1e6


def test_iso15242_bands_in_run_json(tmp_path: Path) -> None:
    data = run_json(with_analysis(tmp_path, TADA, 'bands = "iso15242"'))
    iso = data["iso15242"]
    assert iso["unit"] == "um/s"
    assert iso["direction"] == "x"
    assert iso["speed_rpm"] == pytest.approx(5400.0)
    assert set(iso["bands"]) == {"L", "M", "H"}
    # 5400 rpm is three times the nominal 1800 rpm: the edges scale with it
    assert iso["bands"]["L"]["low_hz"] == pytest.approx(150.0)
    assert iso["bands"]["M"]["low_hz"] == pytest.approx(900.0)
    assert iso["bands"]["H"]["high_hz"] == pytest.approx(30000.0)
    total = 0.0
    for band in iso["bands"].values():
        expected = _band_rms_from_components(data, band["low_hz"], band["high_hz"])
        assert band["rms_um_per_s"] == pytest.approx(expected, rel=1e-9, abs=1e-12)
        total += band["rms_um_per_s"]
    assert total > 0.0  # the 7- and 9-lobe lines of this case fall in a band


def test_iso15242_bands_follow_the_measuring_direction(tmp_path: Path) -> None:
    # NU209 under a light measuring load along -y: the probe reads y, not x
    data = run_json(with_analysis(tmp_path, NU209, 'bands = "iso15242"'))
    iso = data["iso15242"]
    assert iso["direction"] == "y"
    assert iso["measuring_direction"] == pytest.approx([0.0, -1.0], abs=1e-12)
    assert iso["speed_rpm"] == pytest.approx(1.0)
    assert iso["bands"]["L"]["low_hz"] == pytest.approx(50.0 / 1800.0)
    for band in iso["bands"].values():
        expected = _band_rms_from_components(data, band["low_hz"], band["high_hz"], "y")
        assert band["rms_um_per_s"] == pytest.approx(expected, rel=1e-9, abs=1e-12)
    assert iso["bands"]["L"]["rms_um_per_s"] > 0.0


def test_iso15242_band_edges_double_at_3600_rpm(tmp_path: Path) -> None:
    text = TADA.read_text(encoding="utf-8").replace('speed = "5400 rpm"', 'speed = "3600 rpm"')
    source = tmp_path / "source.toml"
    source.write_text(text, encoding="utf-8")
    iso = run_json(with_analysis(tmp_path, source, 'bands = "iso15242"'))["iso15242"]
    assert iso["speed_rpm"] == pytest.approx(3600.0)
    edges = {name: (b["low_hz"], b["high_hz"]) for name, b in iso["bands"].items()}
    assert edges["L"] == pytest.approx((100.0, 600.0))
    assert edges["M"] == pytest.approx((600.0, 3600.0))
    assert edges["H"] == pytest.approx((3600.0, 20000.0))


def test_no_bands_key_leaves_the_json_as_it_was() -> None:
    data = run_json(TADA)
    assert "iso15242" not in data and "verdict" not in data


def test_readable_summary_shows_the_bands_in_um_per_s(tmp_path: Path) -> None:
    case = with_analysis(tmp_path, TADA, 'bands = "iso15242"')
    result = runner.invoke(app, ["run", str(case)])
    assert result.exit_code == 0, result.output
    assert "ISO 15242" in result.stdout
    assert "um/s" in result.stdout


def test_bands_refused_for_the_equilibrium_model(tmp_path: Path) -> None:
    case = with_analysis(tmp_path, KIM_EQUILIBRIUM, 'bands = "iso15242"')
    err = refused(["run", str(case)])
    assert str(case) in err and "analysis.bands" in err
    assert len(err.strip().splitlines()) == 1


def test_anderon_bands_for_a_model_other_than_linear(tmp_path: Path) -> None:
    data = run_json(with_analysis(tmp_path, TADA, 'bands = "anderon"'))
    assert set(data["anderon"]) == {"U", "R", "L", "M", "H", "E", "A"}
    assert all(v >= 0.0 and math.isfinite(v) for v in data["anderon"].values())


# -------------------------------------------------------------------------- limit and verdict
@pytest.mark.parametrize(("limit", "passes"), [('"20 nm"', True), ('"5 nm"', False)])
def test_verdict_on_the_radial_pp(tmp_path: Path, limit: str, passes: bool) -> None:
    data = run_json(with_analysis(tmp_path, TADA, f"limit = {limit}"))
    verdict = data["verdict"]
    assert verdict["quantity"] == "radial_pp"
    assert verdict["value_m"] == data["runout"]["radial_pp_m"]
    assert verdict["limit_m"] == pytest.approx(float(limit.strip('"').split()[0]) * 1e-9)
    assert verdict["pass"] is passes


def test_verdict_on_a_band(tmp_path: Path) -> None:
    extra = 'bands = "iso15242"\nlimit = "1000 um/s"\nlimit_on = "iso15242.M"'
    data = run_json(with_analysis(tmp_path, TADA, extra))
    verdict = data["verdict"]
    assert verdict["quantity"] == "iso15242.M"
    assert verdict["limit_um_per_s"] == pytest.approx(1000.0)
    assert verdict["value_um_per_s"] == data["iso15242"]["bands"]["M"]["rms_um_per_s"]
    assert verdict["pass"] is (verdict["value_um_per_s"] <= 1000.0)


def test_readable_summary_says_pass_or_fail(tmp_path: Path) -> None:
    case = with_analysis(tmp_path, TADA, 'limit = "5 nm"')
    result = runner.invoke(app, ["run", str(case)])
    assert result.exit_code == 0, result.output
    assert "FAIL" in result.stdout and "5 nm" in result.stdout


@pytest.mark.parametrize(
    "extra",
    [
        'limit = "50 um/s"',  # a velocity for a displacement quantity
        'limit = "0.5 um"\nbands = "iso15242"\nlimit_on = "iso15242.M"',  # length for a band
        'limit = "20 N"',
    ],
)
def test_a_limit_of_the_wrong_dimension_is_refused(tmp_path: Path, extra: str) -> None:
    case = with_analysis(tmp_path, TADA, extra)
    err = refused(["run", str(case)])
    assert "analysis.limit" in err and str(case) in err


def test_a_band_limit_without_bands_is_refused(tmp_path: Path) -> None:
    case = with_analysis(tmp_path, TADA, 'limit = "50 um/s"\nlimit_on = "iso15242.M"')
    err = refused(["run", str(case)])
    assert "analysis.limit_on" in err


def test_limit_on_axial_for_a_planar_model_is_refused(tmp_path: Path) -> None:
    source = EXAMPLES / "seed001_kim_table4.toml"
    case = with_analysis(tmp_path, source, 'limit = "1 um"\nlimit_on = "axial_pp"')
    err = refused(["run", str(case)])
    assert "analysis.limit_on" in err and "quasi_static_2d" in err


def test_limit_on_a_band_for_the_equilibrium_model_is_refused(tmp_path: Path) -> None:
    extra = 'bands = "iso15242"\nlimit = "50 um/s"\nlimit_on = "iso15242.M"'
    err = refused(["run", str(with_analysis(tmp_path, KIM_EQUILIBRIUM, extra))])
    assert "analysis." in err


# -------------------------------------------------------------------------- yield of a lot
def _small_study(tmp_path: Path, limit: str, samples: int = 12) -> Path:
    text = KIM_TABLE9.read_text(encoding="utf-8")
    assert "samples = 1000\n" in text
    text = text.replace("samples = 1000\n", f"samples = {samples}\n")
    text = text.replace("samples = 1024\n", "samples = 256\n").replace(
        "revolutions = 8 ", "revolutions = 2 "
    )
    source = tmp_path / "source.toml"
    source.write_text(text, encoding="utf-8")
    return with_analysis(tmp_path, source, f'limit = "{limit}"', name="study.toml")


def _clopper_pearson(k: int, n: int) -> tuple[float, float]:
    low = 0.0 if k == 0 else float(beta.ppf(0.025, k, n - k + 1))
    high = 1.0 if k == n else float(beta.ppf(0.975, k + 1, n - k))
    return low, high


def test_study_yield_with_clopper_pearson_interval(tmp_path: Path) -> None:
    out = tmp_path / "out"
    # a limit inside the spread of the lot: some bearings pass, some fail
    probe = runner.invoke(app, ["study", str(_small_study(tmp_path, "1 mm")), "--json"])
    assert probe.exit_code == 0, probe.output
    radial = json.loads(probe.stdout)["runout"]["radial_pp_m"]
    limit_nm = radial["p50"] * 1e9
    case = _small_study(tmp_path, f"{limit_nm:.6g} nm")
    result = runner.invoke(app, ["study", str(case), "--json", "--out", str(out)])
    assert result.exit_code == 0, result.output
    summary = json.loads(result.stdout)
    y = summary["yield"]
    with (out / "samples.csv").open(newline="") as fh:
        values = np.array([float(row["radial_pp_m"]) for row in csv.DictReader(fh)])
    passed = int(np.sum(values <= y["limit_m"]))
    assert y["quantity"] == "radial_pp"
    assert y["limit_m"] == pytest.approx(float(f"{limit_nm:.6g}") * 1e-9)
    assert (y["passed"], y["samples"]) == (passed, 12)
    assert 0 < passed < 12
    assert y["fraction"] == pytest.approx(passed / 12)
    low, high = _clopper_pearson(passed, 12)
    assert (y["ci_low"], y["ci_high"]) == (pytest.approx(low), pytest.approx(high))
    assert y["confidence"] == 0.95 and y["method"] == "Clopper-Pearson"
    assert json.loads((out / "summary.json").read_text())["yield"]["passed"] == passed
    readable = runner.invoke(app, ["study", str(case)])
    assert readable.exit_code == 0, readable.output
    assert "yield" in readable.stdout and "Clopper-Pearson" in readable.stdout


def test_study_yield_when_every_bearing_passes(tmp_path: Path) -> None:
    result = runner.invoke(app, ["study", str(_small_study(tmp_path, "1 mm", 8)), "--json"])
    assert result.exit_code == 0, result.output
    y = json.loads(result.stdout)["yield"]
    assert (y["passed"], y["samples"], y["fraction"]) == (8, 8, 1.0)
    assert y["ci_high"] == 1.0
    assert y["ci_low"] == pytest.approx(0.025 ** (1 / 8))


def test_sweep_points_carry_pass(tmp_path: Path) -> None:
    text = TADA.read_text(encoding="utf-8") + (
        '[study]\nkind = "sweep"\n[study.vary]\n'
        '"waviness[1].peak_to_peak" = { values = ["1 nm", "20 nm"] }\n'
    )
    source = tmp_path / "source.toml"
    source.write_text(text, encoding="utf-8")
    case = with_analysis(tmp_path, source, 'limit = "8 nm"', name="sweep.toml")
    result = runner.invoke(app, ["study", str(case), "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert "yield" not in data  # a sweep is not a lot
    verdicts = [(p["runout"]["radial_pp_m"] <= 8e-9, p["pass"]) for p in data["points"]]
    assert [v for v, _ in verdicts] == [p for _, p in verdicts] == [True, False]


def test_study_refuses_a_band_limit(tmp_path: Path) -> None:
    extra = 'bands = "iso15242"\nlimit = "50 um/s"\nlimit_on = "iso15242.M"'
    text = _small_study(tmp_path, "1 mm", 8).read_text(encoding="utf-8")
    case = tmp_path / "band_study.toml"
    case.write_text(text.replace("[analysis]\n", "[analysis]\n" + extra + "\n", 1), "utf-8")
    case.write_text(case.read_text().replace('limit = "1 mm"\n', ""), "utf-8")
    err = refused(["study", str(case)])
    assert "analysis.limit_on" in err and str(case) in err


# -------------------------------------------------------------------------- units at the scale
def test_readable_summary_of_a_nm_case_prints_nm_without_exponents() -> None:
    result = runner.invoke(app, ["run", str(TADA)])
    assert result.exit_code == 0, result.output
    text = result.stdout
    assert " nm" in text
    assert not EXPONENT.search(text), text
    # the axial p-p of this planar-loaded case is round-off: 0, with the resolution stated
    assert "solver's resolution" in text


def test_readable_summary_of_a_um_case_prints_um() -> None:
    result = runner.invoke(app, ["run", str(NU209)])
    assert result.exit_code == 0, result.output
    assert " um" in result.stdout
    assert not EXPONENT.search(result.stdout), result.stdout


def test_notes_print_as_a_list_not_a_table() -> None:
    result = runner.invoke(app, ["run", str(NU209)])
    assert result.exit_code == 0, result.output
    notes = result.stdout.split("Notes", 1)[1]
    assert "- operation.radial_load: not applied" in notes
    assert "quantity" not in notes  # no table header over the notes


def test_study_readable_summary_at_the_input_scale(tmp_path: Path) -> None:
    result = runner.invoke(app, ["study", str(_small_study(tmp_path, "1 mm", 8))])
    assert result.exit_code == 0, result.output
    assert "[nm]" in result.stdout or "[um]" in result.stdout
    assert not EXPONENT.search(result.stdout), result.stdout


# -------------------------------------------------------------------------- passage names
def test_roller_bearing_frequencies_use_roller_names() -> None:
    result = runner.invoke(app, ["frequencies", str(NU209)])
    assert result.exit_code == 0, result.output
    assert "roller pass" in result.stdout and "ball pass" not in result.stdout
    data = json.loads(runner.invoke(app, ["frequencies", str(NU209), "--json"]).stdout)
    freqs = data["frequencies_hz"]
    assert freqs["roller_pass_inner"] == freqs["ball_pass_inner"]
    assert freqs["roller_pass_outer"] == freqs["ball_pass_outer"]
    assert data["orders"]["roller_pass_inner"] == data["orders"]["ball_pass_inner"]


def test_ball_bearing_frequencies_keep_ball_names() -> None:
    result = runner.invoke(app, ["frequencies", str(TADA)])
    assert result.exit_code == 0, result.output
    assert "ball pass" in result.stdout and "roller" not in result.stdout
    data = json.loads(runner.invoke(app, ["frequencies", str(TADA), "--json"]).stdout)
    assert "roller_pass_inner" not in data["frequencies_hz"]


def test_roller_run_uses_roller_names() -> None:
    data = run_json(NU209)
    assert data["frequencies_hz"]["roller_pass_outer"] == data["frequencies_hz"]["ball_pass_outer"]
    readable = runner.invoke(app, ["run", str(NU209)])
    assert "roller passage" in readable.stdout and "ball pass" not in readable.stdout
