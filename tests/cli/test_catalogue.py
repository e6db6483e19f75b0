"""[bearing] designation, `runout catalogue` and user catalogues through the command line.

The Case Western Reserve University data set's bearings by designation give the data center's
published defect orders; a standard designation shows d, D, B and the provenance of every
value; a key given beside a designation replaces the catalogue's value with a note; an unknown
designation or a bad user catalogue is refused in one line.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest
from typer.testing import CliRunner

from runout.catalogue import CATALOGUE_ENV
from runout.cli.commands import app

ROOT = Path(__file__).resolve().parents[2]
runner = CliRunner()


@pytest.fixture(autouse=True)
def _no_user_catalogue(monkeypatch: pytest.MonkeyPatch) -> None:
    # --catalogue passes the file on through the environment: restore it after each test
    monkeypatch.setenv(CATALOGUE_ENV, "")


def _case(tmp_path: Path, bearing: str, rest: str = "", name: str = "case.toml") -> Path:
    path = tmp_path / name
    path.write_text(
        f'[bearing]\n{bearing}\n[operation]\nspeed = "1797 rpm"\nradial_load = "100 N"\n{rest}',
        encoding="utf-8",
    )
    return path


def _invoke(*args: str) -> tuple[int, str, str]:
    result = runner.invoke(app, list(args))
    return result.exit_code, result.stdout, result.stderr


# the data center's orders of shaft speed (inner ring turning, contact angle 0)
CWRU = {
    "6205-2RS JEM SKF": {"bpfi": 5.4152, "bpfo": 3.5848, "ftf": 0.39828, "ball": 4.7135},
    "6203-2RS JEM SKF": {"bpfi": 4.9469, "bpfo": 3.0530, "ftf": 0.3817, "ball": 3.9874},
}


@pytest.mark.parametrize("designation", sorted(CWRU))
def test_cwru_bearings_by_designation_give_the_published_orders(
    tmp_path: Path, designation: str
) -> None:
    path = _case(tmp_path, f'designation = "{designation}"')
    code, out, err = _invoke("frequencies", str(path), "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["contact_angle_deg"] == 0.0
    orders = doc["orders"]
    published = CWRU[designation]
    # the data center rounds to 4-5 digits: 0.1 % holds them all (FTF 0.3817 is 0.01 % off)
    assert orders["ball_pass_inner"] == pytest.approx(published["bpfi"], rel=1e-3)
    assert orders["ball_pass_outer"] == pytest.approx(published["bpfo"], rel=1e-3)
    assert orders["cage"] == pytest.approx(published["ftf"], rel=1e-3)
    # the data center's "ball" frequency is twice runout's ball spin (a flaw meets both races)
    assert 2.0 * orders["ball_spin"] == pytest.approx(published["ball"], rel=1e-3)


def test_cwru_example_runs_with_its_source_and_the_bpfo_line() -> None:
    code, out, err = _invoke("run", str(ROOT / "examples" / "cwru_6205_drive_end.toml"), "--json")
    assert code == 0, err
    doc = json.loads(out)
    source = doc["bearing_source"]
    assert source["designation"] == "6205-2RS JEM SKF"
    assert source["values"]["elements"] == 9
    assert source["values"]["element_diameter"] == pytest.approx(0.3126 * 0.0254, rel=1e-12)
    assert source["values"]["pitch_diameter"] == pytest.approx(1.537 * 0.0254, rel=1e-12)
    assert "Case Western Reserve University" in source["provenance"]["elements"]
    assert source["provenance"]["inner_conformity"].startswith("estimate (rule typical_conformity")
    rotation = doc["frequencies_hz"]["rotation"]
    top = doc["components"][0]
    assert top["frequency_hz"] / rotation == pytest.approx(3.5848, rel=1e-3)  # BPFO


def test_check_shows_boundary_dimensions_and_provenance(tmp_path: Path) -> None:
    path = _case(tmp_path, 'designation = "6204"', '[analysis]\nmodel = "linear"\n')
    code, out, err = _invoke("check", str(path))
    assert code == 0, err
    assert "Bearing 6204 from the catalogue" in out
    for row in ("bore d", "outside diameter D", "width B"):
        assert row in out
    assert "d, D, B: ISO 15 boundary dimensions" in out
    assert "estimate (rule ball_section: D_w = 0.3 (D - d))" in out
    assert "estimate (rule conrad_fill" in out
    code, out, err = _invoke("check", str(path), "--json")
    assert code == 0, err
    source = json.loads(out)["bearing_source"]
    assert (source["bore_diameter_m"], source["outside_diameter_m"], source["width_m"]) == (
        pytest.approx(0.020),
        pytest.approx(0.047),
        pytest.approx(0.014),
    )
    assert source["provenance"]["dimensions"] == "ISO 15 boundary dimensions"
    assert set(source["provenance"]) == {"dimensions", *source["values"]}


def test_explicit_keys_replace_catalogue_values_with_a_note(tmp_path: Path) -> None:
    path = _case(
        tmp_path,
        'designation = "6204"\nelement_diameter = "7.938 mm"\nelements = 8\n'
        'inner_groove_radius = "4.2 mm"',
        '[analysis]\nmodel = "linear"\n',
    )
    code, out, err = _invoke("run", str(path), "--json")
    assert code == 0, err
    doc = json.loads(out)
    notes = doc["notes"]
    assert any(
        n.startswith(
            "bearing.element_diameter: 7.938 mm given in the case replaces the catalogue's 8.1 mm"
        )
        for n in notes
    ), notes
    # elements = 8 is the catalogue's own value: nothing replaced, nothing said
    assert not any(n.startswith("bearing.elements") for n in notes)
    assert any(
        n.startswith(
            "bearing.inner_groove_radius: given in the case, so the catalogue's inner_conformity"
        )
        for n in notes
    )
    source = doc["bearing_source"]
    assert source["given_in_case"] == {"element_diameter": pytest.approx(7.938e-3)}
    assert source["provenance"]["element_diameter"].startswith("case file")
    assert source["provenance"]["inner_conformity"].startswith("not applied")
    code, out, err = _invoke("run", str(path))
    assert code == 0, err
    assert "7.938 mm given in the case replaces" in out  # the readable notes
    assert "7.938 (catalogue 8.1)" in out


def test_suffixes_are_named_in_notes(tmp_path: Path) -> None:
    path = _case(tmp_path, 'designation = "6204-2RS C3"', '[analysis]\nmodel = "linear"\n')
    code, out, err = _invoke("check", str(path), "--json")
    assert code == 0, err
    source = json.loads(out)["bearing_source"]
    assert (source["designation"], source["requested"], source["suffix"]) == (
        "6204",
        "6204-2RS C3",
        "2RS C3",
    )
    notes = " ".join(source["notes"])
    assert "suffix 2RS: seals or shields" in notes
    assert "suffix C3: radial clearance class not applied" in notes


def test_unknown_designation_is_refused_with_close_matches(tmp_path: Path) -> None:
    path = _case(tmp_path, 'designation = "6250"')
    code, _, err = _invoke("check", str(path))
    assert code == 2
    line = err.strip()
    assert "\n" not in line
    assert line.startswith(f"error: {path}: bearing.designation: '6250' is not in the catalogue")
    assert "close: 625, " in line


def test_a_type_the_catalogue_contradicts_is_refused(tmp_path: Path) -> None:
    path = _case(tmp_path, 'designation = "NU209"\ntype = "ball"')
    code, _, err = _invoke("check", str(path))
    assert code == 2
    assert "bearing.type: NU209 is a cylindrical_roller bearing in the catalogue" in err


def test_roller_and_angular_contact_designations(tmp_path: Path) -> None:
    path = _case(tmp_path, 'designation = "NU209"', '[analysis]\nmodel = "roller_constraint"\n')
    code, out, err = _invoke("check", str(path), "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["bearing_source"]["values"] == {
        "elements": 14,
        "element_diameter": pytest.approx(0.010),
        "inner_raceway_diameter": pytest.approx(0.054991),
        "outer_raceway_diameter": pytest.approx(0.075032),
    }
    assert "Yu et al." in doc["bearing_source"]["provenance"]["elements"]
    path = _case(tmp_path, 'designation = "7205B"', name="ac.toml")
    code, out, err = _invoke("check", str(path), "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["bearing_source"]["values"]["nominal_contact_angle"] == pytest.approx(
        0.6981317007977318
    )


def test_spindle_bearings_by_designation(tmp_path: Path) -> None:
    text = (ROOT / "examples" / "spindle_machine_tool.toml").read_text(encoding="utf-8")
    keys = (
        'type = "ball"\nelements = 20\nelement_diameter = "11.1125 mm"\npitch_diameter = "90 mm"\n'
        'inner_conformity = 0.52\nouter_conformity = 0.53\nnominal_contact_angle = "25 deg"\n'
    )
    assert text.count(keys) == 2
    path = tmp_path / "spindle.toml"
    path.write_text(text.replace(keys, 'designation = "7014AC"\n'), encoding="utf-8")
    code, out, err = _invoke("check", str(path), "--json")
    assert code == 0, err
    sources = json.loads(out)["bearing_sources"]
    assert [s["name"] for s in sources] == ["A", "B"]
    assert all(s["designation"] == "7014AC" for s in sources)
    path.write_text(text.replace(keys, 'designation = "7014XX"\n', 1), encoding="utf-8")
    code, _, err = _invoke("check", str(path))
    assert code == 2
    assert f"{path}: bearings[1].designation: '7014XX' is not in the catalogue" in err


def test_catalogue_lists_and_shows(tmp_path: Path) -> None:
    code, out, err = _invoke("catalogue", "620?", "--json")
    assert code == 0, err
    names = [e["designation"] for e in json.loads(out)["entries"]]
    assert names == [f"620{k}" for k in range(10)]
    code, out, err = _invoke("catalogue", "62*", "--json")
    names = [e["designation"] for e in json.loads(out)["entries"]]
    assert {"625", "6220", "6205-2RS JEM SKF"} <= set(names) and "6305" not in names
    code, out, err = _invoke("catalogue", "NU2")
    assert code == 0, err
    assert "NU209" in out and "NU320" not in out and "designations" in out
    code, out, err = _invoke("catalogue", "6205-2RS JEM SKF")  # one match: the whole entry
    assert code == 0, err
    assert "Where the values of 6205-2RS JEM SKF come from" in out
    code, _, err = _invoke("catalogue", "6250X")
    assert code == 2
    assert err.count("\n") == 1 and "close:" in err


USER = """\
# a user's catalogue: a bearing runout does not ship, and a 6204 measured on a drawing
designation,kind,d_mm,D_mm,B_mm,elements,element_diameter_mm,pitch_diameter_mm,source
X-17,deep_groove,17,40,12,,,,
6204,deep_groove,20,47,14,8,7.938,33.5,drawing 4711 rev. B
"""


def test_user_catalogue_extends_and_replaces(tmp_path: Path) -> None:
    user = tmp_path / "mine.csv"
    user.write_text(USER, encoding="utf-8")
    path = _case(tmp_path, 'designation = "6204"', '[analysis]\nmodel = "linear"\n')
    code, out, err = _invoke("check", str(path), "--json", "--catalogue", str(user))
    assert code == 0, err
    source = json.loads(out)["bearing_source"]
    assert source["values"]["element_diameter"] == pytest.approx(7.938e-3)
    assert source["provenance"]["element_diameter"] == "drawing 4711 rev. B"
    assert source["catalogue"] == str(user)
    assert any(
        f"catalogue row 6204 of {user} replaces the row of runout" in n for n in source["notes"]
    )
    os.environ[CATALOGUE_ENV] = ""  # a new command in this process: --catalogue set it
    new = _case(tmp_path, 'designation = "X-17"', name="x.toml")
    code, _, err = _invoke("check", str(new))
    assert code == 2 and "'X-17' is not in the catalogue" in err  # not without the file
    os.environ[CATALOGUE_ENV] = str(user)  # the environment variable (restored by the fixture)
    code, out, err = _invoke("check", str(new), "--json")
    assert code == 0, err
    assert json.loads(out)["bearing_source"]["values"]["elements"] == 8
    code, out, err = _invoke("catalogue", "X-*")
    assert code == 0 and "X-17" in out


@pytest.mark.parametrize(
    ("row", "where", "what"),
    [
        (
            "6204,deep_groove,20,47,14,8,abc,33.5,x",
            "row 3, column element_diameter_mm",
            "must be a number",
        ),
        ("6204,deep_groove,20,47,14,8,7.9,33.5,", "row 3, column source", "need their source"),
        ("6204,ball,20,47,14,,,,", "row 3, column kind", "must be one of deep_groove"),
        ("6204,deep_groove,20,47,14,8,30,33.5,x", "row 3", "does not fit the section"),
        ("6204,deep_groove,20,47,14,40,7.9,33.5,x", "row 3", "do not fit round the pitch circle"),
        ("6204,deep_groove,47,20,14,,,,", "row 3, column D_mm", "must exceed the bore"),
        ("6204,deep_groove,20,47", "row 3", "has 4 cells, the header 9"),
    ],
)
def test_bad_user_catalogue_is_refused_in_one_line(
    tmp_path: Path, row: str, where: str, what: str
) -> None:
    user = tmp_path / "bad.csv"
    user.write_text(USER.splitlines()[1] + "\n\n" + row + "\n", encoding="utf-8")
    path = _case(tmp_path, 'designation = "6204"')
    for args in (["--catalogue", str(user)], []):
        if not args:
            os.environ[CATALOGUE_ENV] = str(user)
        code, _, err = _invoke("check", str(path), *args)
        assert code == 2
        assert err.count("\n") == 1, err
        assert f"{user}: {where}: " in err and what in err, err


def test_user_catalogue_link_out_of_its_directory_is_refused(tmp_path: Path) -> None:
    outside = tmp_path / "elsewhere"
    outside.mkdir()
    (outside / "real.csv").write_text(USER, encoding="utf-8")
    inside = tmp_path / "here"
    inside.mkdir()
    (inside / "link.csv").symlink_to(outside / "real.csv")
    code, _, err = _invoke("catalogue", "--catalogue", str(inside / "link.csv"))
    assert code == 2
    assert err.count("\n") == 1 and str(inside / "link.csv") in err


def test_report_shows_where_the_bearing_came_from(tmp_path: Path) -> None:
    out = tmp_path / "out"
    case = str(ROOT / "examples" / "cwru_6205_drive_end.toml")
    code, _, err = _invoke("run", case, "--out", str(out), "--report")
    assert code == 0, err
    page = (out / "report.html").read_text(encoding="utf-8")
    assert "Bearing 6205-2RS JEM SKF from the catalogue" in page
    assert "Where the values of 6205-2RS JEM SKF come from" in page
    assert "Case Western Reserve University" in page
    stored = json.loads((out / "result.json").read_text(encoding="utf-8"))
    assert stored["bearing_source"]["designation"] == "6205-2RS JEM SKF"


def test_study_says_which_catalogue_values_the_case_replaces(tmp_path: Path) -> None:
    path = _case(
        tmp_path,
        'designation = "7205C"\nelement_diameter = "7.9375 mm"',
        '[analysis]\nmodel = "quasi_static_2d"\nrevolutions = 4\nsamples = 512\n'
        '[study]\nkind = "montecarlo"\nsamples = 4\nseed = 1\n'
        '[study.vary]\nelement_diameter_sigma = "0.1 um"\n',
    )
    path.write_text(path.read_text().replace('radial_load = "100 N"', 'axial_load = "50 N"'))
    code, out, err = _invoke("study", str(path), "--json")
    assert code == 0, err
    document = json.loads(out)
    assert document["samples"] == 4
    # the study JSON says where the bearing comes from, as the run JSON does
    source = document["bearing_source"]
    assert source["designation"] == "7205C"
    assert source["bore_diameter_m"] == pytest.approx(0.025, rel=1e-12)
    assert source["given_in_case"] == {"element_diameter": pytest.approx(7.9375e-3, rel=1e-12)}
    assert "estimate" in source["provenance"]["pitch_diameter"]
    code, out, err = _invoke("study", str(path))
    assert code == 0, err
    assert "bearing 7205C from the runout catalogue (dimensions: ISO 15" in out
    assert (
        "note: bearing.element_diameter: 7.9375 mm given in the case replaces the catalogue's "
        "8.1 mm (7205C)" in err
    )


def test_a_tolerance_class_takes_the_designations_bore(tmp_path: Path) -> None:
    """``limit = "P4"`` is tabulated by bore: a designation gives it (ISO 15 d), with a note;
    a ``limit_bore`` the case gives stays, without one."""
    analysis = '[analysis]\nmodel = "linear"\nlimit = "P4"\n'
    waviness = '[[waviness]]\npart = "inner"\norder = 7\namplitude = "0.2 um"\n'
    path = _case(tmp_path, 'designation = "6204"', analysis + waviness)
    code, out, err = _invoke("run", str(path), "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["verdict"]["class"] == "P4" and doc["verdict"]["bore_m"] == pytest.approx(0.020)
    assert doc["verdict"]["limit_m"] == pytest.approx(3e-6)  # 18 mm < d <= 30 mm
    assert any(n.startswith("analysis.limit_bore: the bore of 6204") for n in doc["notes"])
    path = _case(
        tmp_path, 'designation = "6204"', analysis + 'limit_bore = "10 mm"\n' + waviness, "b.toml"
    )
    code, out, err = _invoke("run", str(path), "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["verdict"]["bore_m"] == pytest.approx(0.010)
    assert doc["verdict"]["limit_m"] == pytest.approx(2.5e-6)
    assert not any("limit_bore" in n for n in doc.get("notes", []))


# --------------------------------------------------------------------------------------------
# the catalogue's dynamic load rating C: the maker's where cited, else ISO 281's, with provenance
# --------------------------------------------------------------------------------------------
LIFE = '[analysis]\nmodel = "equilibrium"\n'
URB = "URB Group (Anadolu Rulman), Rolling Bearings General Catalogue, v.14_2017"


def _run(tmp_path: Path, bearing: str, name: str = "case.toml") -> dict:
    path = _case(tmp_path, bearing, LIFE, name=name)
    code, out, err = _invoke("run", str(path), "--json")
    assert code == 0, err
    return json.loads(out)


def _typed(values: dict, rating: str) -> str:
    """The [bearing] keys of a catalogue entry's values, typed into the case (SI)."""
    keys = ("elements", "element_diameter", "pitch_diameter", "inner_conformity")
    typed = [f"{k} = {values[k]!r}" for k in keys]
    typed += [f"outer_conformity = {values['outer_conformity']!r}", 'type = "ball"']
    return "\n".join([*typed, f"dynamic_load_rating = {rating}"])


def test_a_makers_c_gives_the_life_a_typed_c_gives(tmp_path: Path) -> None:
    doc = _run(tmp_path, 'designation = "6214"')
    source = doc["bearing_source"]
    assert source["values"]["dynamic_load_rating"] == pytest.approx(62.2e3, rel=1e-12)
    assert source["provenance"]["dynamic_load_rating"].startswith(URB)
    assert doc["life"]["dynamic_load_rating_n"] == pytest.approx(62.2e3, rel=1e-12)
    assert not any("estimate" in n and "dynamic_load_rating" in n for n in doc["notes"])
    # the same bearing typed key by key with the same C: the same life (same arithmetic)
    typed = _run(tmp_path, _typed(source["values"], '"62.2 kN"'), name="typed.toml")
    assert doc["life"]["l10r_mrev"] == pytest.approx(typed["life"]["l10r_mrev"], rel=1e-12)
    # 100 N radial at zero clearance: the TS life is of the order of ISO 281's (C/P)^3
    assert 0.5 < doc["life"]["l10r_mrev"] / (62.2e3 / 100.0) ** 3 < 2.0
    code, out, _ = _invoke("catalogue", "6214")
    assert code == 0 and "62.2" in out and "URB Group" in out


def test_iso_281_c_of_published_geometry_is_the_standards_formula(tmp_path: Path) -> None:
    # 608 (seed 002): Z = 7, D_w = 3.9688 mm, D_pw = 15 mm, alpha = 0: f_c between Table 2's
    # 58.2 (0.26) and 57.7 (0.27) at D_w / D_pw = 0.264587
    f_c = 58.2 + (3.9688 / 15.0 - 0.26) / 0.01 * (57.7 - 58.2)
    expected = 1.3 * f_c * 7 ** (2 / 3) * 3.9688**1.8  # [N], lengths in mm
    doc = _run(tmp_path, 'designation = "608"')
    source = doc["bearing_source"]
    assert source["values"]["dynamic_load_rating"] == pytest.approx(expected, rel=1e-12)
    assert source["provenance"]["dynamic_load_rating"].startswith(
        "computed by ISO 281:2007 from published internal geometry (Anderon"
    )
    assert doc["life"]["dynamic_load_rating_n"] == pytest.approx(expected, rel=1e-12)
    assert not any("is an estimate" in n for n in doc["notes"])


def test_iso_281_c_of_estimated_geometry_is_said_to_be_an_estimate(tmp_path: Path) -> None:
    doc = _run(tmp_path, 'designation = "6205"')
    origin = doc["bearing_source"]["provenance"]["dynamic_load_rating"]
    assert origin.startswith("estimate (computed by ISO 281:2007 from estimated internal")
    rating = doc["bearing_source"]["values"]["dynamic_load_rating"]
    assert doc["life"]["dynamic_load_rating_n"] == pytest.approx(rating, rel=1e-12)
    note = f"bearing.dynamic_load_rating: {rating / 1e3:.6g} kN of 6205 is an estimate"
    assert any(note in n for n in doc["notes"]), doc["notes"]
    path = _case(tmp_path, 'designation = "6205"', LIFE)
    code, out, err = _invoke("run", str(path))
    assert code == 0, err
    assert "is an estimate, computed by ISO 281:2007" in " ".join(out.split())


def test_a_case_c_replaces_the_catalogues_with_a_note(tmp_path: Path) -> None:
    doc = _run(tmp_path, 'designation = "6214"\ndynamic_load_rating = "63.7 kN"')
    assert doc["life"]["dynamic_load_rating_n"] == pytest.approx(63.7e3, rel=1e-12)
    source = doc["bearing_source"]
    assert source["given_in_case"]["dynamic_load_rating"] == pytest.approx(63.7e3)
    assert source["provenance"]["dynamic_load_rating"].startswith("case file")
    assert (
        "bearing.dynamic_load_rating: 63.7 kN given in the case replaces the catalogue's "
        "62.2 kN (6214)" in doc["notes"]
    )
    # a case C over an ISO 281 estimate: no estimate note, the replacement note instead
    doc = _run(tmp_path, 'designation = "6205"\ndynamic_load_rating = "14.8 kN"', "b.toml")
    assert not any("is an estimate" in n for n in doc["notes"])
    assert any("14.8 kN given in the case replaces the catalogue's" in n for n in doc["notes"])


def test_computed_c_with_the_cases_own_geometry_is_noted(tmp_path: Path) -> None:
    doc = _run(tmp_path, 'designation = "6205"\nelement_diameter = "7.94 mm"')
    assert any(
        "computed by ISO 281:2007 from the catalogue's element_diameter, not from the case's" in n
        for n in doc["notes"]
    ), doc["notes"]


def test_spindle_bearings_by_designation_have_a_life(tmp_path: Path) -> None:
    text = (ROOT / "examples" / "spindle_machine_tool.toml").read_text(encoding="utf-8")
    keys = (
        'type = "ball"\nelements = 20\nelement_diameter = "11.1125 mm"\npitch_diameter = "90 mm"\n'
        'inner_conformity = 0.52\nouter_conformity = 0.53\nnominal_contact_angle = "25 deg"\n'
    )
    path = tmp_path / "spindle.toml"
    path.write_text(text.replace(keys, 'designation = "7014AC"\n'), encoding="utf-8")
    code, out, err = _invoke("run", str(path), "--json")
    assert code == 0, err
    doc = json.loads(out)
    for bearing, source in zip(doc["bearings"], doc["bearing_sources"], strict=True):
        rating = source["values"]["dynamic_load_rating"]
        assert bearing["life"]["dynamic_load_rating_n"] == pytest.approx(rating, rel=1e-12)
    assert any("bearings[1].dynamic_load_rating:" in n and "estimate" in n for n in doc["notes"])


def test_a_roller_row_has_no_c(tmp_path: Path) -> None:
    code, out, err = _invoke("catalogue", "NU209", "--json")
    assert code == 0, err
    entry = json.loads(out)["entries"][0]
    assert "dynamic_load_rating" not in entry["values"]


RATED = """\
designation,kind,d_mm,D_mm,B_mm,elements,element_diameter_mm,pitch_diameter_mm,source,dynamic_load_rating_kN,dynamic_load_rating_source
"""


def test_user_catalogue_c_column(tmp_path: Path) -> None:
    user = tmp_path / "mine.csv"
    user.write_text(RATED + "Y-1,deep_groove,25,52,15,,,,,15.1,maker list 2024 p. 7\n", "utf-8")
    path = _case(tmp_path, 'designation = "Y-1"', LIFE)
    code, out, err = _invoke("run", str(path), "--json", "--catalogue", str(user))
    assert code == 0, err
    doc = json.loads(out)
    assert doc["life"]["dynamic_load_rating_n"] == pytest.approx(15.1e3, rel=1e-12)
    assert doc["bearing_source"]["provenance"]["dynamic_load_rating"] == "maker list 2024 p. 7"


@pytest.mark.parametrize(
    ("row", "column", "what"),
    [
        ("Y-1,deep_groove,25,52,15,,,,,abc,x", "dynamic_load_rating_kN", "must be a number"),
        ("Y-1,deep_groove,25,52,15,,,,,-14,x", "dynamic_load_rating_kN", "finite number > 0"),
        ("Y-1,deep_groove,25,52,15,,,,,0,x", "dynamic_load_rating_kN", "finite number > 0"),
        ("Y-1,deep_groove,25,52,15,,,,,inf,x", "dynamic_load_rating_kN", "finite number > 0"),
        ("Y-1,deep_groove,25,52,15,,,,,NaN,x", "dynamic_load_rating_kN", "finite number > 0"),
        ("Y-1,deep_groove,25,52,15,,,,,1e400,x", "dynamic_load_rating_kN", "finite number > 0"),
        ("Y-1,deep_groove,25,52,15,,,,,2e6,x", "dynamic_load_rating_kN", "at most 1e+06 kN"),
        ("Y-1,deep_groove,25,52,15,,,,,14,", "dynamic_load_rating_source", "needs its source"),
        (
            "Y-1,cylindrical_roller,25,52,15,,,,,14,x",
            "dynamic_load_rating_kN",
            "only applies to ball bearings",
        ),
    ],
)
def test_a_bad_c_cell_is_refused_in_one_line(
    tmp_path: Path, row: str, column: str, what: str
) -> None:
    user = tmp_path / "bad.csv"
    user.write_text(RATED + row + "\n", encoding="utf-8")
    path = _case(tmp_path, 'designation = "6204"')
    code, _, err = _invoke("check", str(path), "--catalogue", str(user))
    assert code == 2
    assert err.count("\n") == 1, err
    assert f"{user}: row 2, column {column}: " in err and what in err, err


def test_a_model_without_life_is_silent_about_the_catalogues_c(tmp_path: Path) -> None:
    # the catalogue's C is not the case's input: the linear model need not say it leaves it
    # out; a C the case gives is noted as before
    for bearing, noted in (
        ('designation = "6214"', False),
        ('designation = "6214"\ndynamic_load_rating = "63.7 kN"', True),
    ):
        path = _case(tmp_path, bearing, '[analysis]\nmodel = "linear"\n')
        code, out, err = _invoke("run", str(path), "--json")
        assert code == 0, err
        notes = json.loads(out)["notes"]
        assert any("dynamic_load_rating: not applied" in n for n in notes) is noted, notes
