"""``runout run/check/study --model NAME --set KEY=VALUE``: the case changed before validation."""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
TADA = EXAMPLES / "seed000_tada_fig7.toml"
runner = CliRunner()


def _run(*args: str) -> tuple[int, str, str]:
    result = runner.invoke(app, list(args))
    return result.exit_code, result.stdout, result.stderr


def _edited(tmp_path: Path, old: str, new: str) -> Path:
    text = TADA.read_text(encoding="utf-8")
    assert old in text
    path = tmp_path / "edited.toml"
    path.write_text(text.replace(old, new), encoding="utf-8")
    return path


def test_model_runs_another_model_on_the_same_case(tmp_path: Path) -> None:
    code, out, err = _run("run", str(TADA), "--json", "--model", "quasi_static_2d")
    assert code == 0, err
    edited = _edited(tmp_path, 'model = "quasi_static_3d"', 'model = "quasi_static_2d"')
    code2, out2, err2 = _run("run", str(edited), "--json")
    assert code2 == 0, err2
    assert json.loads(out)["model"] == "quasi_static_2d"
    assert json.loads(out)["components"] == json.loads(out2)["components"]


def test_set_changes_a_key_with_its_unit(tmp_path: Path) -> None:
    code, out, err = _run(
        "run",
        str(TADA),
        "--json",
        "--set",
        'operation.axial_load="30 N"',
        "--set",
        "analysis.samples=2048",
    )
    assert code == 0, err
    edited = _edited(tmp_path, 'axial_load = "20 N"', 'axial_load = "30 N"')
    edited.write_text(
        edited.read_text(encoding="utf-8").replace("samples = 4096", "samples = 2048"),
        encoding="utf-8",
    )
    code2, out2, err2 = _run("run", str(edited), "--json")
    assert code2 == 0, err2
    assert json.loads(out) == json.loads(out2)
    # 30 N is not the file's 20 N: the preload contact angle moved
    code3, out3, _ = _run("run", str(TADA), "--json", "--set", "analysis.samples=2048")
    assert code3 == 0
    assert json.loads(out)["contact_angle_deg"] != json.loads(out3)["contact_angle_deg"]


def test_set_takes_a_bare_quantity_and_an_array_entry() -> None:
    code, out, err = _run(
        "check",
        str(TADA),
        "--json",
        "--set",
        "operation.axial_load=30 N",
        "--set",
        "waviness[2].order=10",
    )
    assert code == 0, err
    code, out_plain, _ = _run("check", str(TADA), "--json")
    assert json.loads(out)["contact_angle_deg"] != json.loads(out_plain)["contact_angle_deg"]


def test_set_adds_a_table_the_file_does_not_have() -> None:
    code, out, err = _run(
        "run",
        str(TADA),
        "--json",
        "--model",
        "linear",
        "--set",
        "analysis.bands=anderon",
        "--set",
        "analysis.samples=1024",
    )
    assert code == 0, err
    assert "anderon" in json.loads(out)


@pytest.mark.parametrize(
    ("args", "key", "problem"),
    [
        (["--set", "operation.axial_lod=3"], "operation.axial_lod", "unknown key"),
        (["--set", "analysis.samples=many"], "analysis.samples", "must be an integer"),
        (["--set", "operation.axial_load=-5 N"], "operation.axial_load", "must be >= 0"),
        (["--set", "operation.speed=30 N"], "operation.speed", ""),
        (["--set", "waviness[9].order=3"], "waviness[9]", "has 6 [[waviness]] entries"),
        (["--set", "analysis"], "", "expected KEY=VALUE"),
        (["--set", "bearing=3"], "bearing", "name a key of the table"),
        (["--set", "nope.key=1"], "nope", "unknown key"),
        (
            ["--set", "analysis.samples=1", "--set", "analysis.samples=2"],
            "analysis.samples",
            "given twice",
        ),
        (["--model", "quasi_static"], "analysis.model", "must be one of"),
        (["--model", "linear", "--set", "analysis.model=linear"], "analysis.model", "both"),
    ],
)
@pytest.mark.parametrize("command", ["run", "check", "study"])
def test_bad_values_exit_2_naming_the_file_and_the_key(
    command: str, args: list[str], key: str, problem: str
) -> None:
    code, out, err = _run(command, str(TADA), *args)
    assert code == 2, (out, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith(f"error: {TADA}: {key}"), lines[0]
    assert problem in lines[0]


def test_run_out_keeps_the_case_as_run(tmp_path: Path) -> None:
    out_dir = tmp_path / "out"
    args = [
        "run",
        str(TADA),
        "--out",
        str(out_dir),
        "--model",
        "linear",
        "--set",
        "analysis.samples=1024",
    ]
    code, _, err = _run(*args)
    assert code == 0, err
    saved = (out_dir / "case.toml").read_text(encoding="utf-8")
    document = tomllib.loads(saved)
    assert document["analysis"]["model"] == "linear"
    assert document["analysis"]["samples"] == 1024
    assert saved.startswith("# ")  # says which file and options it came from
    code, _, err = _run(*args)  # the same run again rewrites the directory in place
    assert code == 0, err
    code, _, err = _run("run", str(TADA), "--out", str(out_dir))  # another case: refused
    assert code == 2
    assert "holds another case" in err


def test_study_takes_set(tmp_path: Path) -> None:
    case = EXAMPLES / "seed001_kim_table9.toml"
    code, out, err = _run("study", str(case), "--json", "--set", "study.samples=3")
    assert code == 0, err
    assert json.loads(out)["samples"] == 3


def test_study_vary_takes_set() -> None:
    """``--set study.vary.KEY=VALUE`` was refused as not a case key: a varied quantity's key
    holds dots, and the whole entry (a quantity or an inline table) is its value."""
    case = str(EXAMPLES / "seed001_kim_table9.toml")
    base = ("study", case, "--json", "--set", "study.samples=12")

    def mean_pp(*extra: str) -> float:
        code, out, err = _run(*base, *extra)
        assert code == 0, err
        return float(json.loads(out)["runout"]["radial_pp_m"]["mean"])

    sigma = 'study.vary.element_diameter_sigma="0.2 um"'
    # the lot's runout nearly doubles with sigma (the file's 0.1 um; Hertz contacts: not exactly)
    assert 1.9 < mean_pp("--set", sigma) / mean_pp() < 2.1
    load = 'study.vary."operation.axial_load"={ distribution = "normal", std = "3 N" }'
    assert mean_pp("--set", load) != mean_pp()  # the axial load now varies too
    code, _, err = _run(*base, "--set", "study.target_yield=1.5")  # was pydantic's wording
    assert code == 2 and "study.target_yield: must be < 1.0, got 1.5" in err
    code, _, err = _run(*base, "--set", "study.vary.=1")
    assert code == 2 and "name the varied key" in err and len(err.strip().splitlines()) == 1
    code, _, err = _run(*base, "--set", 'study.vary.element_diameter_sigm="1 um"')
    assert code == 2 and "element_diameter_sigm" in err and len(err.strip().splitlines()) == 1
