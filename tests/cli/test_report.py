"""HTML reports: self-contained, complete, and rendered by a real browser."""

from __future__ import annotations

import base64
import csv
import io
import os
import re
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "docs_hooks"))
import screenshots

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
        "Largest lines",
        "Inputs as the model used them",
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
    assert "3.9688 mm" in page  # the ball diameter, as given
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


def test_report_renders_in_headless_chromium(report_608: Path, tmp_path: Path) -> None:
    if screenshots.chromium() is None:
        if os.environ.get("CI"):
            pytest.fail("CI must install Debian's chromium (see .ci/run)")
        pytest.skip("headless Chromium is not installed here; CI installs it and runs this")
    data = screenshots.screenshot(report_608, tmp_path / "page.png").read_bytes()
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
    assert "Statistics over the lot" in page
    assert "Monte Carlo over 8 samples" in page
    assert "ball size error: f_c" in page


# --------------------------------------------------------------------------------------------
# the page an engineer reads (issue 17)
# --------------------------------------------------------------------------------------------
DATA = Path(__file__).resolve().parents[1] / "data"
# A number printed in exponent notation ("5e-10", "1e+04").
EXPONENT = re.compile(r"\d[eE][-+]?\d")


def _visible_text(page: str) -> str:
    """The page's text without embedded images, the style sheet and the case file."""
    page = re.sub(r"src='data:[^']*'", "", page)
    page = re.sub(r"<style>.*?</style>", "", page, flags=re.S)
    page = re.sub(r"<pre>.*?</pre>", "", page, flags=re.S)
    return re.sub(r"<[^>]+>", " ", page)


def _run_report(case: Path, out: Path) -> str:
    result = runner.invoke(app, ["run", str(case), "--out", str(out), "--report"])
    assert result.exit_code == 0, result.stderr
    return (out / "report.html").read_text(encoding="utf-8")


def _first_screen(page: str) -> str:
    return page[: page.index(">Inputs as the model used them")]


def test_first_screen_has_what_was_run_headline_and_largest_lines(report_608: Path) -> None:
    page = report_608.read_text(encoding="utf-8")
    first = _first_screen(page)
    # what was run: model, bearing, speed
    assert "<b>linear</b>" in first
    assert "ball bearing, 7 balls of 3.9688 mm" in first
    assert "inner ring at 1800 rpm" in first
    # headline at the input's scale: 5.04 um radial p-p in um, no exponent noise
    assert ">radial p-p<" in first and ">5.039 um<" in first
    assert ">RRO p-p<" in first and ">NRRO p-p<" in first
    # the linear model is planar: no axial runout, said as n/a, never 0 (issue 29)
    assert re.search(r">axial p-p</div><div class='v'>n/a<", first)
    # the three largest lines, each with its top source
    table = first[first.index(">Largest lines") :]
    assert table.count("<tr>") == 4  # header + 3 lines
    assert "inner 1 lobes: eccentricity" in table
    assert not EXPONENT.search(_visible_text(first))


def test_lines_are_rows_with_sources_on_demand(report_608: Path) -> None:
    page = report_608.read_text(encoding="utf-8")
    lines = page[page.index(">Spectral lines") : page.index(">Anderon band values")]
    assert "40 largest of" in lines
    assert lines.count("<details><summary>") == 40
    assert "<th>formula</th>" in lines  # the sources table inside each row


def test_inputs_show_only_what_the_model_used(tmp_path: Path) -> None:
    # The linear model holds the contact angle at bearing.contact_angle: a clearance given
    # beside it is not used (the run says so), so the report must not show it as an input.
    text = (EXAMPLES / "seed002_608.toml").read_text(encoding="utf-8")
    assert "radial_clearance" not in text
    case = tmp_path / "608.toml"
    case.write_text(
        text.replace("[bearing]\n", '[bearing]\nradial_clearance = "12 um"\n', 1), "utf-8"
    )
    page = _run_report(case, tmp_path / "out")
    inputs = page[page.index(">Inputs as the model used them") : page.index(">Spectral lines")]
    assert "radial clearance P_d" not in inputs
    assert "12 um" not in inputs
    assert "Given but not used by this model" in inputs
    assert "bearing.radial_clearance" in inputs
    assert "held fixed (bearing.contact_angle)" in inputs


def test_roller_report_names_kia_and_leaves_out_the_unused_load(tmp_path: Path) -> None:
    page = _run_report(EXAMPLES / "seed004_nu209.toml", tmp_path / "nu209")
    first = _first_screen(page)
    assert "= Kia (ISO 492)" in first
    assert "cylindrical roller bearing, 14 rollers of 10 mm" in first
    assert "load radial" not in first  # the rigid model does not use the load's size
    inputs = page[page.index(">Inputs as the model used them") : page.index(">Spectral lines")]
    assert ">radial load<" not in inputs
    assert "operation.radial_load" in inputs  # listed as given but not used
    assert "from the raceway diameters" in inputs  # the clearance the model used


def test_dynamic_report_states_the_play_it_used_and_the_resolution(tmp_path: Path) -> None:
    page = _run_report(EXAMPLES / "seed003_purohit.toml", tmp_path / "purohit")
    first = _first_screen(page)
    # radial p-p of about 6e-20 m is below the solver's resolution: 0, with the resolution
    assert ">0 nm<" in first
    assert "below the solver&#x27;s resolution" in first
    assert not EXPONENT.search(_visible_text(first))
    inputs = page[page.index(">Inputs as the model used them") : page.index(">Figures")]
    assert "radial play P_d/2 = 100 nm" in inputs  # P_d = 0.2 um as given
    assert "rotor mass" in inputs
    # derived quantities in readable units: no exponent notation anywhere in the section
    assert not EXPONENT.search(_visible_text(inputs))
    assert "N/m^1.5" in inputs and "× 10" in inputs


def test_verdict_card_pass_and_fail(tmp_path: Path) -> None:
    text = (DATA / "report_6204.toml").read_text(encoding="utf-8")
    assert 'limit = "0.5 um"' in text
    page = _run_report(DATA / "report_6204.toml", tmp_path / "pass")
    assert "card pass" in _first_screen(page) and ">PASS<" in page
    failing = tmp_path / "fail.toml"
    failing.write_text(text.replace('limit = "0.5 um"', 'limit = "0.1 um"'), "utf-8")
    page = _run_report(failing, tmp_path / "fail")
    first = _first_screen(page)
    assert "card fail" in first and ">FAIL<" in first
    assert "&gt; limit 100 nm" in first  # the value against the limit, at one scale
    # ISO 15242 bands, with their edges in plain numbers (10000 Hz, not 1e+04)
    assert "ISO 15242 H (rms)" in first
    assert "1800–10000 Hz" in first


def test_animation_is_embedded_animated_and_bounded(tmp_path: Path) -> None:
    from PIL import Image

    page = _run_report(DATA / "report_6204.toml", tmp_path / "r6204")
    found = re.findall(r"src='data:image/gif;base64,([A-Za-z0-9+/=]+)'", page)
    assert len(found) == 1
    data = base64.b64decode(found[0])
    assert len(data) < 2_000_000
    with Image.open(io.BytesIO(data)) as gif:
        assert gif.n_frames > 1
        assert gif.size[0] >= 400  # not a thumbnail
        width, frames = gif.size[0], gif.n_frames
    # shown at up to twice its pixel size, not left as a small still
    assert f"style='width: {min(2 * width, 900)}px'" in page
    assert f" {frames} frames." in page  # the caption says what the GIF holds


def test_study_statistics_table_one_row_per_output(tmp_path: Path) -> None:
    import numpy as np

    case = (EXAMPLES / "seed001_kim_table9.toml").read_text(encoding="utf-8")
    small = tmp_path / "lot.toml"
    small.write_text(case.replace("samples = 1000", "samples = 30"), encoding="utf-8")
    out = tmp_path / "lot"
    assert runner.invoke(app, ["study", str(small), "--out", str(out)]).exit_code == 0
    assert runner.invoke(app, ["report", str(out)]).exit_code == 0
    page = (out / "report.html").read_text(encoding="utf-8")
    stats = page[page.index(">Statistics over the lot") : page.index(">Figures")]
    header = re.search(r"<tr>(<th.*?)</tr>", stats)
    assert header is not None
    names = re.findall(r"<th[^>]*>([^<]*)</th>", header.group(1))
    assert names == ["output (p-p)", "mean", "std", "p50", "p95", "p99", "max", "unit"]
    rows = re.findall(r"<tr><td>([^<]*)</td>(.*?)</tr>", stats)
    assert [r[0] for r in rows[:4]] == ["radial p-p", "RRO p-p", "NRRO p-p", "axial p-p"]
    # p99 is computed from samples.csv: check it against numpy
    with (out / "samples.csv").open(encoding="utf-8") as handle:
        radial = [float(r["radial_pp_m"]) for r in csv.DictReader(handle)]
    cells = re.findall(r"<td class=num>([^<]*)</td>", rows[0][1])
    unit = re.findall(r"<td>([^<]*)</td>", rows[0][1])[-1]
    assert unit == "nm"
    assert float(cells[4]) == pytest.approx(np.percentile(radial, 99) * 1e9, rel=1e-3)
    assert "histograms" in page and "Distribution over the lot" in page


def test_sweep_report_shows_points_and_sweep_figures(tmp_path: Path) -> None:
    text = (EXAMPLES / "seed001_kim_table9.toml").read_text(encoding="utf-8")
    text = text[: text.index("[study]")]
    text += (
        '[[waviness]]\npart = "inner"\norder = 11\namplitude = "0.1 um"\n\n'
        '[study]\nkind = "sweep"\n[study.vary]\n'
        '"operation.axial_load" = { start = "20 N", stop = "80 N", num = 3 }\n'
    )
    case = tmp_path / "sweep.toml"
    case.write_text(text, encoding="utf-8")
    out = tmp_path / "sweep"
    result = runner.invoke(app, ["study", str(case), "--out", str(out)])
    assert result.exit_code == 0, result.stderr
    assert runner.invoke(app, ["report", str(out)]).exit_code == 0
    page = (out / "report.html").read_text(encoding="utf-8")
    assert "sweep of 3 points" in page
    points = page[page.index(">Sweep points") : page.index(">Figures")]
    assert points.count("<tr>") == 4
    assert "Runout and the largest lines against operation.axial" in page


def test_unknown_figure_names_get_a_caption(report_608: Path, tmp_path: Path) -> None:
    import shutil as _shutil

    directory = tmp_path / "copy"
    _shutil.copytree(report_608.parent, directory)
    _shutil.copy(directory / "lines.png", directory / "new_panel_xy.png")
    assert runner.invoke(app, ["report", str(directory)]).exit_code == 0
    page = (directory / "report.html").read_text(encoding="utf-8")
    assert "<figcaption>New panel xy.</figcaption>" in page


def test_equilibrium_report_headlines_the_position_not_a_zero_runout(tmp_path: Path) -> None:
    page = _run_report(EXAMPLES / "seed001_kim_equilibrium.toml", tmp_path / "eq")
    first = _first_screen(page)
    assert ">radial p-p<" not in first  # no runout history: no zero runout shown as a result
    assert ">axial displacement<" in first and ">11.2 um<" in first
    assert ">inner contact angle<" in first and ">18.73 deg<" in first
    assert ">axial stiffness<" in first
