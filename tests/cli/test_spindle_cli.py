"""The spindle through the command line: the examples' JSON, the read-back result, and the
case-file contract of [spindle] + [[bearings]] (each refusal names the file, the key and what
to write)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from runout.analysis.results import RunResult
from runout.cli.commands import app

ROOT = Path(__file__).resolve().parents[2]
HDD = (ROOT / "examples" / "spindle_hdd.toml").read_text(encoding="utf-8")
runner = CliRunner()


def _json(path: Path) -> dict:
    result = runner.invoke(app, ["run", str(path), "--json"])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def test_hdd_example_runs_and_reads_back(tmp_path: Path) -> None:
    doc = _json(ROOT / "examples" / "spindle_hdd.toml")
    assert doc["model"] == "spindle"
    assert [b["name"] for b in doc["bearings"]] == ["front", "rear"]
    assert [b["thrust"] for b in doc["bearings"]] == ["+z", "-z"]
    matrix = doc["stiffness_matrix"]["matrix"]
    assert len(matrix) == 5 and all(len(row) == 5 for row in matrix)
    assert doc["stiffness_matrix"]["dofs"] == ["x", "y", "z", "tilt_x", "tilt_y"]
    # the rear's 7-lobe waviness tilts the shaft; the in-phase 9-lobe pair does not
    assert doc["tilt_pp_rad"]["x"] > 1e-7
    labels = [c["label"] for c in doc["components"]]
    assert any("(rear bearing)" in label for label in labels)
    assert any("(front bearing)" in label for label in labels)
    back = RunResult.from_json(doc)
    assert back.to_json() == doc


def test_machine_tool_example_position_preload() -> None:
    doc = _json(ROOT / "examples" / "spindle_machine_tool.toml")
    a, b = doc["bearings"]
    assert a["preload_n"] == pytest.approx(b["preload_n"], rel=1e-12)
    assert a["pressure_centre_m"] < 0.0 < 0.02 < b["pressure_centre_m"]  # DB: outside the pair
    assert any("position preload 6 um" in n for n in doc["notes"])


BEARINGS = HDD.split("[material]")[0]


def _case(tmp_path: Path, text: str) -> tuple[int, str]:
    path = tmp_path / "case.toml"
    path.write_text(text, encoding="utf-8")
    result = runner.invoke(app, ["check", str(path)])
    return result.exit_code, result.stderr


REFUSALS = [
    (
        "both bearing tables",
        HDD.replace(
            "[material]",
            '[bearing]\nelements = 8\nelement_diameter = "1 mm"\n'
            'pitch_diameter = "7 mm"\n[material]',
        ),
        r"case\.toml: bearing: a case has either one \[bearing\] or a spindle's \[\[bearings\]\]",
    ),
    (
        "no bearing key on a waviness",
        HDD.replace('bearing = "rear"\npart = "inner"\norder = 7', 'part = "inner"\norder = 7'),
        r"waviness\[3\]\.bearing: required with \[\[bearings\]\]: "
        r'write bearing = "<name>" \(one of front, rear\)',
    ),
    (
        "unknown bearing name",
        HDD.replace(
            'bearing = "rear"\npart = "inner"\norder = 7',
            'bearing = "back"\npart = "inner"\norder = 7',
        ),
        r'waviness\[3\]\.bearing: "back" is not a \[\[bearings\]\] name \(front, rear\)',
    ),
    (
        "plain [elements] on a spindle",
        HDD.replace(
            "[analysis]", "[elements]\npitch_errors = [0, 0, 0, 0, 0, 0, 0, 0]\n[analysis]"
        ),
        r"elements: with \[\[bearings\]\], per-bearing tables: write \[elements\.<name>\]",
    ),
    (
        "no [spindle] table",
        re.sub(r"\[spindle\][^\[]*", "", HDD, count=1),
        r"spindle: required with \[\[bearings\]\]",
    ),
    (
        "two preloads",
        HDD.replace('preload = "20 N"', 'preload = "20 N"\npreload_displacement = "2 um"'),
        r"spindle\.preload: give exactly one of preload or preload_displacement",
    ),
    (
        "tandem position preload",
        HDD.replace('preload = "20 N"', 'preload_displacement = "2 um"').replace('"DB"', '"DT"'),
        r"spindle\.preload_displacement: a tandem \(DT\) set has no opposed bearing",
    ),
    (
        "duplicate names",
        HDD.replace('name = "rear"', 'name = "front"'),
        r'bearings\[2\]\.name: "front" is used twice',
    ),
    (
        "another model",
        HDD.replace('model = "spindle"', 'model = "quasi_static_3d"'),
        r'analysis\.model: "quasi_static_3d" runs one bearing; '
        r'a case with \[\[bearings\]\] runs in model = "spindle"',
    ),
    (
        "a bearing's own key",
        HDD.replace(
            'name = "rear"\nposition = "12 mm"\ntype = "ball"\nelements = 8',
            'name = "rear"\nposition = "12 mm"\ntype = "ball"\nelements = 2',
        ),
        r"bearings\[2\]\.elements: must be an integer >= 3",
    ),
    (
        "a bearing's built geometry",
        re.sub(r'(name = "rear"[^\[]*element_diameter = )"1 mm"', r'\1"5 mm"', HDD),
        r"bearings\[2\]\.",
    ),
    (
        "an entry's built check, by its own index",
        HDD.replace(
            'bearing = "rear"\npart = "inner"\norder = 7',
            'bearing = "rear"\npart = "inner"\norder = 0',
        ),
        r"waviness\[3\]\.order: order 0 of a raceway is a size change",
    ),
    (
        "one bearing",
        HDD.split('[[bearings]]\nname = "rear"')[0]
        + '[operation]\nspeed = 90\n[analysis]\nmodel = "spindle"\n',
        r"bearings: has 1 entries: a spindle has 2 to 8 bearings",
    ),
]


@pytest.mark.parametrize(("what", "text", "pattern"), REFUSALS, ids=[r[0] for r in REFUSALS])
def test_spindle_case_refusals(tmp_path: Path, what: str, text: str, pattern: str) -> None:
    code, err = _case(tmp_path, text)
    assert code == 2, err
    assert re.search(pattern, err), err
    assert "Traceback" not in err


def test_nine_bearings_refused_before_building(tmp_path: Path) -> None:
    block = HDD.split("[[bearings]]")[1]
    rows = "".join(
        "[[bearings]]" + block.replace('name = "front"', f'name = "b{i}"') for i in range(9)
    )
    text = HDD.split("[[bearings]]")[0] + rows + '[analysis]\nmodel = "spindle"\n'
    code, err = _case(tmp_path, text)
    assert code == 2
    assert "bearings: has 9 entries: a spindle has 2 to 8 bearings" in err


def test_bearing_key_on_a_single_bearing_case(tmp_path: Path) -> None:
    text = (ROOT / "examples" / "seed000_tada_fig7.toml").read_text(encoding="utf-8")
    text = text.replace(
        '[[waviness]]\npart = "inner"\norder = 7',
        '[[waviness]]\nbearing = "front"\npart = "inner"\norder = 7',
        1,
    )
    code, err = _case(tmp_path, text)
    assert code == 2
    assert "waviness[1].bearing: names a [[bearings]] entry of a spindle case" in err


def test_spindle_model_on_a_single_bearing_case(tmp_path: Path) -> None:
    text = (ROOT / "examples" / "seed000_tada_fig7.toml").read_text(encoding="utf-8")
    text = text.replace('model = "quasi_static_3d"', 'model = "spindle"')
    assert 'model = "spindle"' in text
    code, err = _case(tmp_path, text)
    assert code == 2
    assert 'model = "spindle" needs a [spindle] table and two or more [[bearings]]' in err


def test_per_bearing_elements_table(tmp_path: Path) -> None:
    text = HDD.replace(
        "[analysis]",
        '[elements.rear]\ndiameter_errors = ["0.1 um", 0, 0, 0, 0, 0, 0, 0]\n[analysis]',
    )
    path = tmp_path / "case.toml"
    path.write_text(text, encoding="utf-8")
    doc = _json(path)
    # the rear ball 1's size error is a source of a cage-frequency line
    assert any(
        s["part"] == "ball"
        and s["element"] == 1
        and s["lobes"] == 0
        and s["term"].endswith("(rear bearing)")
        for c in doc["components"]
        for s in c["sources"]
    )


def test_span_sweep_study_runs_the_spindle() -> None:
    """`runout study` runs the spindle over the span and the hub's position: the rear
    bearing's tilt reaches the hub by the lever, so the hub's runout grows with its overhang."""
    result = runner.invoke(
        app, ["study", str(ROOT / "examples" / "spindle_hdd_span_sweep.toml"), "--json"]
    )
    assert result.exit_code == 0, result.stderr
    doc = json.loads(result.stdout)
    assert doc["failed"] == 0
    points = doc["points"]
    assert len(points) == 12
    assert {p["model"] for p in points} == {"spindle"}
    by_span: dict[float, list[tuple[float, float]]] = {}
    for p in points:
        span = p["values"]["bearings[2].position"]
        by_span.setdefault(span, []).append(
            (p["values"]["spindle.nose_position"], p["runout"]["radial_pp_m"])
        )
    for rows in by_span.values():
        rows.sort()  # the most overhanging hub (most negative position) first
        assert rows[0][1] > rows[1][1] > rows[2][1]


def test_study_refuses_a_ball_size_draw_on_a_spindle(tmp_path: Path) -> None:
    text = (ROOT / "examples" / "spindle_hdd_span_sweep.toml").read_text(encoding="utf-8")
    text = text.split("[study]")[0] + (
        '[study]\nkind = "montecarlo"\nsamples = 4\n[study.vary]\n'
        'element_diameter_sigma = "0.1 um"\n'
    )
    path = tmp_path / "case.toml"
    path.write_text(text, encoding="utf-8")
    result = runner.invoke(app, ["study", str(path), "--json"])
    assert result.exit_code == 2
    assert "study.vary.element_diameter_sigma: a spindle's element errors are per bearing" in (
        result.stderr
    )


def test_preload_sweep(tmp_path: Path) -> None:
    text = (ROOT / "examples" / "spindle_hdd_span_sweep.toml").read_text(encoding="utf-8")
    text = text.split("[study]")[0] + (
        '[study]\nkind = "sweep"\n[study.vary]\n"spindle.preload" = { values = ["10 N", "40 N"] }\n'
    )
    path = tmp_path / "case.toml"
    path.write_text(text, encoding="utf-8")
    result = runner.invoke(app, ["study", str(path), "--json"])
    assert result.exit_code == 0, result.stderr
    points = json.loads(result.stdout)["points"]
    assert [p["values"]["spindle.preload"] for p in points] == [10.0, 40.0]
    assert points[0]["runout"] != points[1]["runout"]


def test_hertz_check_of_each_bearing_under_its_preload(tmp_path: Path) -> None:
    text = (ROOT / "examples" / "spindle_machine_tool.toml").read_text(encoding="utf-8")
    text = text.replace('preload_displacement = "6 um"', 'preload_displacement = "400 um"')
    path = tmp_path / "case.toml"
    path.write_text(text, encoding="utf-8")
    notes = _json(path)["notes"]
    for name in ("A", "B"):
        assert any(
            n.startswith(f"spindle.preload_displacement: the most loaded ball of bearing {name}")
            and "ISO 76" in n
            for n in notes
        )


def test_check_shows_each_bearings_imperfections() -> None:
    # the rear bearing's waviness was not shown: check printed the lead bearing's parts only
    done = CliRunner().invoke(app, ["check", str(ROOT / "examples" / "spindle_hdd.toml")])
    assert done.exit_code == 0, done.output
    front = done.stdout.index("Imperfections: front bearing")
    rear = done.stdout.index("Imperfections: rear bearing")
    assert front < rear
    assert re.search(r"inner\W+all\W+7\W", done.stdout[rear:])  # the rear's 7-lobe row
    assert not re.search(r"inner\W+all\W+7\W", done.stdout[front:rear])


def test_the_json_says_what_the_spindle_displacement_is() -> None:
    # displacement_of said "from the rings axially centred", which is one bearing's
    # convention; the spindle reports the shaft at the nose from its preload position
    done = CliRunner().invoke(app, ["run", str(ROOT / "examples" / "spindle_hdd.toml"), "--json"])
    assert done.exit_code == 0, done.output
    meaning = json.loads(done.stdout)["displacement_of"]
    assert "nose" in meaning and "preload" in meaning
    assert "rings axially centred" not in meaning


def test_frequencies_are_those_the_spindle_model_uses_per_bearing() -> None:
    # `runout frequencies` showed the first bearing at its free contact angle (25 deg on the
    # machine-tool spindle) while the model runs it at its preloaded angle (25.28 deg)
    case = str(ROOT / "examples" / "spindle_machine_tool.toml")
    freqs = CliRunner().invoke(app, ["frequencies", case, "--json"])
    run = CliRunner().invoke(app, ["run", case, "--json"])
    assert freqs.exit_code == 0 and run.exit_code == 0, freqs.output + run.output
    shown, ran = json.loads(freqs.stdout), json.loads(run.stdout)
    assert shown["contact_angle_deg"] == ran["contact_angle_deg"]
    assert shown["frequencies_hz"] == ran["frequencies_hz"]
    names = [b["name"] for b in shown["bearings"]]
    assert names == [b["name"] for b in ran["bearings"]]
    for mine, theirs in zip(shown["bearings"], ran["bearings"], strict=True):
        assert mine["contact_angle_deg"] == pytest.approx(theirs["contact_angle_deg"], rel=1e-12)
    text = CliRunner().invoke(app, ["frequencies", case])
    assert all(f"{name} bearing" in text.stdout for name in names)


def test_a_bad_value_in_a_bearings_elements_table_names_that_bearing(tmp_path: Path) -> None:
    # the error said elements.diameter_errors[1], losing the bearing's name
    text = (ROOT / "examples" / "spindle_hdd.toml").read_text(encoding="utf-8")
    text += '\n[elements.rear]\npitch_errors = ["x m", 0, 0, 0, 0, 0, 0, 0]\n'
    case = tmp_path / "bad_elements.toml"
    case.write_text(text, encoding="utf-8")
    done = CliRunner().invoke(app, ["check", str(case)])
    assert done.exit_code == 2
    assert "elements.rear.pitch_errors[1]" in done.stderr
