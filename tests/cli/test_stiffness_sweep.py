"""`runout study` of the equilibrium model: stiffness.csv over a sweep (issue 18, interchange).

Each row of ``stiffness.csv`` is the bearing's linear stiffness at one swept point, in the form
a rotordynamics code's linear bearing element takes (kxx, kxy, kyx, kyy at a rotor speed in
rad/s, plus the axial kzz); it must equal what `runout run --json` gives at that point.
"""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

runner = CliRunner()
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
BASE = (EXAMPLES / "seed001_kim_equilibrium.toml").read_text(encoding="utf-8")
SPEEDS = ("3000 rpm", "7200 rpm", "12000 rpm")
HEADER = [
    "sample",
    "operation.speed",
    "speed_rpm",
    "frequency_rad_per_s",
    "kxx_n_per_m",
    "kxy_n_per_m",
    "kyx_n_per_m",
    "kyy_n_per_m",
    "kzz_n_per_m",
]


def _loaded(text: str) -> str:
    """The example with a radial load at 30 deg: the radial directions couple (kxy != 0)."""
    assert 'axial_load = "60.68 N"' in text
    return text.replace(
        'axial_load = "60.68 N"',
        'axial_load = "60.68 N"\nradial_load = "150 N"\nradial_load_direction = "30 deg"',
    )


def _run_json(path: Path) -> dict:
    result = runner.invoke(app, ["run", str(path), "--json"])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def _rows(path: Path) -> list[dict[str, str]]:
    with path.open(newline="", encoding="utf-8") as fh:
        reader = csv.DictReader(fh)
        assert reader.fieldnames == HEADER
        return list(reader)


def test_speed_sweep_rows_equal_separate_runs(tmp_path: Path) -> None:
    base = _loaded(BASE)
    study = tmp_path / "sweep.toml"
    study.write_text(
        base
        + '\n[study]\nkind = "sweep"\n[study.vary]\n'
        + '"operation.speed" = { values = ['
        + ", ".join(f'"{s}"' for s in SPEEDS)
        + "] }\n",
        encoding="utf-8",
    )
    out = tmp_path / "out"
    result = runner.invoke(app, ["study", str(study), "--out", str(out), "--json"])
    assert result.exit_code == 0, result.stderr
    points = json.loads(result.stdout)["points"]
    rows = _rows(out / "stiffness.csv")
    assert len(rows) == len(SPEEDS) == len(points)
    for i, speed in enumerate(SPEEDS):
        single = tmp_path / f"run_{i}.toml"
        single.write_text(base.replace('speed = "7200 rpm"', f'speed = "{speed}"'), "utf-8")
        run = _run_json(single)
        k = run["radial_stiffness"]
        row = rows[i]
        assert int(row["sample"]) == i
        assert float(row["speed_rpm"]) == k["speed_rpm"] == float(speed.split()[0])
        assert float(row["operation.speed"]) == k["speed_rpm"] / 60.0  # the swept key, in Hz
        assert float(row["frequency_rad_per_s"]) == k["speed_rpm"] * 2.0 * math.pi / 60.0
        for name in ("kxx_n_per_m", "kxy_n_per_m", "kyx_n_per_m", "kyy_n_per_m"):
            assert float(row[name]) == k[name], (speed, name)
        assert float(row["kzz_n_per_m"]) == run["stiffness_matrix"]["matrix"][0][0]
        # the JSON point carries the run's radial_stiffness, unchanged
        assert points[i]["radial_stiffness"] == k
        assert points[i]["axial_stiffness_n_per_m"] == run["stiffness_matrix"]["matrix"][0][0]
    # the load at 30 deg couples x and y at every speed: the off-diagonal terms are carried
    assert all(abs(float(r["kxy_n_per_m"])) > 1e-3 * float(r["kxx_n_per_m"]) for r in rows)
    # centrifugal force unloads the inner contacts as the speed rises: the rows differ
    assert len({r["kxx_n_per_m"] for r in rows}) == len(SPEEDS)


def test_other_models_write_no_stiffness(tmp_path: Path) -> None:
    study = tmp_path / "sweep.toml"
    study.write_text(
        BASE.replace('model = "equilibrium"', 'model = "quasi_static_3d"\nrevolutions = 2')
        + '\n[study]\nkind = "sweep"\n[study.vary]\n'
        + '"operation.axial_load" = { values = ["50 N", "70 N"] }\n',
        encoding="utf-8",
    )
    out = tmp_path / "out"
    result = runner.invoke(app, ["study", str(study), "--out", str(out), "--json"])
    assert result.exit_code == 0, result.stderr
    assert (out / "samples.csv").is_file()
    assert not (out / "stiffness.csv").exists()
    assert all("radial_stiffness" not in p for p in json.loads(result.stdout)["points"])


def test_resume_recomputes_a_chunk_without_stiffness(tmp_path: Path) -> None:
    study = tmp_path / "sweep.toml"
    study.write_text(
        BASE
        + '\n[study]\nkind = "sweep"\nchunk_size = 1\n[study.vary]\n'
        + '"operation.axial_load" = { values = ["40 N", "60 N"] }\n',
        encoding="utf-8",
    )
    out = tmp_path / "out"
    assert runner.invoke(app, ["study", str(study), "--out", str(out)]).exit_code == 0
    first = (out / "stiffness.csv").read_bytes()
    # a chunk as an earlier version wrote it: no stiffness object
    chunk_path = out / "chunks" / "chunk_00001.json"
    chunk = json.loads(chunk_path.read_text(encoding="utf-8"))
    del chunk["stiffness"]
    chunk_path.write_text(json.dumps(chunk), encoding="utf-8")
    result = runner.invoke(app, ["study", str(study), "--out", str(out), "--resume"])
    assert result.exit_code == 0, result.stderr
    assert "chunk_00001.json: sample 1 has no stiffness" in result.stderr
    assert (out / "stiffness.csv").read_bytes() == first
    assert len(_rows_any(out / "stiffness.csv")) == 2


def _rows_any(path: Path) -> list[dict[str, str]]:
    with path.open(newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


DOC = Path(__file__).resolve().parents[2] / "docs" / "interchange.md"


def _block(text: str, lang: str, starting: str = "") -> str:
    """The first fenced ``lang`` block of ``text`` whose body starts with ``starting``."""
    for part in text.split(f"```{lang}\n")[1:]:
        body = part.split("```", 1)[0]
        if body.startswith(starting):
            return body
    raise AssertionError(f"docs/interchange.md has no {lang} block starting {starting!r}")


def test_the_interchange_page_shows_what_runout_writes(tmp_path: Path) -> None:
    text = DOC.read_text(encoding="utf-8")
    case = tmp_path / "spindle.toml"
    case.write_text(_block(text, "toml"), encoding="utf-8")
    out = tmp_path / "spindle"
    assert runner.invoke(app, ["study", str(case), "--out", str(out)]).exit_code == 0
    shown = list(csv.DictReader(_block(text, "text", "sample,").splitlines()))
    written = _rows_any(out / "stiffness.csv")
    assert [list(r) for r in shown] == [list(r) for r in written]
    assert len(shown) == len(written) == 4
    # the page shows one machine's digits: equal to the solver's tolerance (1e-11 relative)
    for a, b in zip(shown, written, strict=True):
        assert a.pop("bearing_damping") == b.pop("bearing_damping") == "kraemer"
        for name in a:
            assert float(a[name]) == pytest.approx(float(b[name]), rel=1e-9, abs=0.0), name
    run = _run_json(case)
    doc_json = json.loads(_block(text, "json"))
    for key in ("radial_stiffness", "bearing_damping"):
        assert set(doc_json[key]) == set(run[key])
        for name, value in doc_json[key].items():
            if isinstance(value, str):
                assert value == run[key][name], name
            else:
                assert value == pytest.approx(run[key][name], rel=1e-9, abs=0.0), name
    # the rounded 5x5 table: every entry to the 5 digits it shows
    matrix = np.array(run["stiffness_matrix"]["matrix"])
    rows = [line for line in text.splitlines() if line.startswith(("| F_", "| M_"))]
    assert len(rows) == 5
    for i, line in enumerate(rows):
        cells = [c.strip().strip("*").replace("−", "-") for c in line.strip("|").split("|")][1:]
        for j, cell in enumerate(cells):
            assert float(cell) == pytest.approx(matrix[i, j], rel=6e-5), (i, j)


def test_study_dataframe_carries_the_stiffness(tmp_path: Path) -> None:
    import tomllib

    from runout.case.model import parse_case
    from runout.study.run import run_study

    data = tomllib.loads(
        BASE
        + '\n[study]\nkind = "sweep"\nmodels = ["equilibrium", "linear"]\n[study.vary]\n'
        + '"operation.axial_load" = { values = ["40 N", "60 N"] }\n'
    )
    study = run_study(parse_case(data, str(tmp_path / "case.toml"), tmp_path))
    df = study.to_dataframe()
    assert list(df["model"]) == ["equilibrium", "equilibrium", "linear", "linear"]
    rows = dict(study.stiffness_columns())
    assert rows["sample"] == [0, 1]  # only the equilibrium points have a stiffness
    for name in ("kxx_n_per_m", "kxy_n_per_m", "kyx_n_per_m", "kyy_n_per_m", "kzz_n_per_m"):
        assert list(df[name][:2]) == rows[name]
        assert df[name][2:].isna().all()  # the linear model gives none
        assert df.attrs["units"][name] == "N/m"
    assert rows["kzz_n_per_m"][1] > rows["kzz_n_per_m"][0]  # a larger preload stiffens


def test_the_readable_output_names_the_stiffness_file(tmp_path: Path) -> None:
    study = tmp_path / "sweep.toml"
    study.write_text(
        BASE + '\n[study]\nkind = "sweep"\n[study.vary]\n"operation.speed" = { values = '
        '["3000 rpm", "6000 rpm"] }\n',
        encoding="utf-8",
    )
    result = runner.invoke(app, ["study", str(study), "--out", str(tmp_path / "out")])
    assert result.exit_code == 0, result.stderr
    assert "stiffness.csv" in " ".join(result.stdout.split())
