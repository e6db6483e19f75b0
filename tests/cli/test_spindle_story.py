"""Issue 29 (items 2 and 3), through the command line: a machine-tool spindle's front pair of
two 7014C bearings back-to-back under a 300 N spring preload, the tool 100 mm out.

* The stiffness a machine-tool designer means is the one at the tool with the shaft free to
  tilt, 1/C_ii of the nose compliance, not the diagonal of the 5×5 stiffness (tilt held).
* Each line's sources are shared by the linearised spindle model, so a line's label is the
  source that makes it (the first-order waviness, not a second-order pair of ring harmonics).
* The report's inputs say the preload, the arrangement and which bearing each imperfection is on.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

ROOT = Path(__file__).resolve().parents[2]
MACHINE_TOOL = (ROOT / "examples" / "spindle_machine_tool.toml").read_text(encoding="utf-8")
# 7014C: the 15 deg nominal contact angle, a 300 N constant-pressure (spring) preload
STORY = MACHINE_TOOL.replace('nominal_contact_angle = "25 deg"', 'nominal_contact_angle = "15 deg"')
STORY = re.sub(r'preload_displacement = "6 um".*', 'preload = "300 N"', STORY)
runner = CliRunner()


def _write(tmp_path: Path, text: str, name: str = "case.toml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _json(path: Path) -> dict:
    result = runner.invoke(app, ["run", str(path), "--json"])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


@pytest.fixture(scope="module")
def story(tmp_path_factory: pytest.TempPathFactory) -> tuple[dict, str, str]:
    """The story's JSON, its readable summary and its HTML report."""
    tmp = tmp_path_factory.mktemp("story")
    case = _write(tmp, STORY)
    out = tmp / "out"
    result = runner.invoke(app, ["run", str(case), "--out", str(out), "--report"])
    assert result.exit_code == 0, result.stderr
    doc = json.loads((out / "result.json").read_text(encoding="utf-8"))
    page = (out / "report.html").read_text(encoding="utf-8")
    return doc, result.stdout, page


def test_story_case_is_the_7014c_pair(story: tuple[dict, str, str]) -> None:
    doc, _, _ = story
    assert [b["preload_n"] for b in doc["bearings"]] == pytest.approx([300.0, 300.0])
    assert doc["arrangement"] == "DB"


# --------------------------------------------------------------------------------------------
# finding 2: the stiffness at the tool
# --------------------------------------------------------------------------------------------
def test_tool_point_stiffness_is_the_inverse_of_the_nose_compliance(
    story: tuple[dict, str, str],
) -> None:
    """1/C_ii of the inverted 5×5 stiffness (the shaft free to tilt), against an independent
    inversion; for this overhung tool it is far below the tilt-held diagonal."""
    doc, _, _ = story
    k = np.array(doc["stiffness_matrix"]["matrix"])
    compliance = np.linalg.inv(k)
    expected = 1.0 / np.diag(compliance)[:3]
    tool = doc["tool_point_stiffness_n_per_m"]
    got = np.array([tool["x"], tool["y"], tool["z"]])
    # a 5x5 inversion of a well-conditioned SPD matrix: round-off, far below 1e-9
    np.testing.assert_allclose(got, expected, rtol=1e-9)
    # the story's figures: K_xx 4.954e8 N/m with the tilt held, 20.75 N/um at the tool
    assert k[0, 0] == pytest.approx(4.954e8, rel=1e-3)
    assert tool["x"] == pytest.approx(20.75e6, rel=1e-3)
    assert k[0, 0] / tool["x"] > 20.0
    # axially the tilt does not couple: the two agree
    assert tool["z"] == pytest.approx(k[2, 2], rel=1e-9)


def test_summary_and_report_name_both_stiffnesses(story: tuple[dict, str, str]) -> None:
    _, text, page = story
    flat = " ".join(text.split())
    assert "tool-point stiffness" in flat
    assert "shaft free to tilt" in flat
    assert "tilt held" in flat
    assert "nose stiffness k_x" not in flat  # the old, misleading name
    assert "20.75" in flat  # N/um at the tool, x
    assert "tool-point stiffness" in page and "shaft free to tilt" in page
    assert "tilt held" in page


# --------------------------------------------------------------------------------------------
# finding 3: shares from the linearised spindle model
# --------------------------------------------------------------------------------------------
def _first_order(source: dict) -> bool:
    return source["part"] in ("inner", "outer", "ball") and "order" not in source["term"]


def test_story_largest_lines_are_labelled_by_first_order_waviness(
    story: tuple[dict, str, str],
) -> None:
    doc, _, _ = story
    largest = doc["components"][:6]
    for comp in largest:
        top = comp["sources"][0]
        assert _first_order(top), (comp["frequency_hz"], comp["direction"], top)
        assert comp["label"].startswith(f"{top['part']} {top['lobes']} lobes")
        shares = [s["share"] for s in comp["sources"]]
        assert len(set(np.round(shares, 6))) > 1, "sources must not share a line uniformly"
        # the first-order sources (one per bearing) carry the line; the pairs a little
        first = sum(s["share"] for s in comp["sources"] if _first_order(s))
        assert first == pytest.approx(1.0, abs=0.1), comp["sources"][:3]


def test_a_single_waviness_on_one_bearing_owns_its_line(tmp_path: Path) -> None:
    """One bearing with a spectrum whose 19-lobe harmonic (Z - 1) dominates: the line it makes
    has the second-order pairs of the spectrum as candidates too, and the linearised model
    gives the 19-lobe waviness of bearing A (nearly) the whole line."""
    text = re.sub(
        r"\[\[waviness_spectrum\]\].*?seed = 2\n",
        '[[waviness]]\nbearing = "A"\npart = "inner"\norder = 19\namplitude = "50 nm"\n'
        '[[waviness]]\nbearing = "A"\npart = "inner"\norder = 7\namplitude = "20 nm"\n'
        '[[waviness]]\nbearing = "A"\npart = "inner"\norder = 12\namplitude = "20 nm"\n',
        STORY,
        flags=re.S,
    )
    assert "seed = 1" not in text and "order = 19" in text
    doc = _json(_write(tmp_path, text))
    comp = doc["components"][0]
    assert comp["frequency_hz"] == pytest.approx(doc["components"][1]["frequency_hz"])
    top = comp["sources"][0]
    assert (top["part"], top["lobes"]) == ("inner", 19)
    assert "(A bearing)" in top["term"]
    assert len(comp["sources"]) > 1  # the 7 + 12 pair shares this line's frequency
    # the pair's amplitude is second order, (20 nm)^2 / (preload approach ~ 1 um): ~1 % of it
    assert top["share"] == pytest.approx(1.0, abs=0.02)
    assert comp["label"].startswith("inner 19 lobes")


# --------------------------------------------------------------------------------------------
# finding 3: the inputs the report shows
# --------------------------------------------------------------------------------------------
def _inputs(page: str) -> str:
    start = page.index("Inputs as the model used them")
    end = page.index("</table>", start)
    return re.sub(r"\s+", " ", re.sub(r"<[^>]+>", " ", page[start:end]))


def test_report_inputs_show_the_preload_and_each_imperfections_bearing(
    story: tuple[dict, str, str],
) -> None:
    _, _, page = story
    inputs = _inputs(page)
    assert "groove bottoms" not in inputs
    assert "no axial load" not in inputs
    assert re.search(r"preload 300 N .*constant-pressure", inputs), inputs
    assert "arrangement DB" in inputs, inputs
    assert "inner (bearing A)" in inputs and "inner (bearing B)" in inputs, inputs


def test_position_preload_is_shown_as_such(tmp_path: Path) -> None:
    out = tmp_path / "out"
    case = _write(tmp_path, MACHINE_TOOL)
    result = runner.invoke(app, ["run", str(case), "--out", str(out), "--report"])
    assert result.exit_code == 0, result.stderr
    inputs = _inputs((out / "report.html").read_text(encoding="utf-8"))
    assert "groove bottoms" not in inputs
    assert re.search(r"preload 6 um .*position", inputs), inputs


def test_single_bearing_without_axial_load_names_the_free_contact_angle(tmp_path: Path) -> None:
    """The same rule for every model: without an axial load the models take the free contact
    angle of the clearance; "groove bottoms" only when that angle is 0."""
    text = (ROOT / "examples" / "seed002_608.toml").read_text(encoding="utf-8")
    text = re.sub(r"axial_load = .*\n", "", text)
    text = re.sub(r'\ncontact_angle = "10 deg".*\n', '\nradial_clearance = "5 um"\n', text)
    assert "radial_clearance" in text
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(_write(tmp_path, text)), "--out", str(out), "--report"])
    assert result.exit_code == 0, result.stderr
    doc = json.loads((out / "result.json").read_text(encoding="utf-8"))
    inputs = _inputs((out / "report.html").read_text(encoding="utf-8"))
    assert doc["contact_angle_deg"] > 1.0  # the 5 um clearance's free contact angle
    assert "groove bottoms" not in inputs
    assert "free contact angle of the clearance" in inputs, inputs
