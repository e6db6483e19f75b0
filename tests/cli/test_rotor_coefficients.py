"""Bearing coefficients for rotor codes: stiffness and damping over speed (issue 33).

``[analysis] bearing_damping`` damps every coefficient in proportion, c = β k: Krämer's
estimate ("kraemer", β = 0.79e-5 s; E. Krämer, Dynamics of Rotors and Foundations, 1993) or
the user's β ("proportional"). A sweep's ``stiffness.csv`` then carries the damping model and
cxx ... czz; every row equals ``runout run --json`` at that point. The same table comes from
Python (:func:`runout.api.bearing_coefficients`), and a ROSS bearing element built from it
holds our coefficients with our speed on its rotor-speed axis (``frequency=`` in ROSS 2,
``speed=`` in ROSS 3).
"""

from __future__ import annotations

import csv
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

runner = CliRunner()
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
BASE = (EXAMPLES / "seed001_kim_equilibrium.toml").read_text(encoding="utf-8")
SPEEDS = ("3000 rpm", "12000 rpm", "24000 rpm")
STIFFNESS = ("kxx_n_per_m", "kxy_n_per_m", "kyx_n_per_m", "kyy_n_per_m")
DAMPING = ("cxx_n_s_per_m", "cxy_n_s_per_m", "cyx_n_s_per_m", "cyy_n_s_per_m", "czz_n_s_per_m")
HEADER = [
    "sample",
    "operation.speed",
    "speed_rpm",
    "frequency_rad_per_s",
    *STIFFNESS,
    "kzz_n_per_m",
    "bearing_damping",
    "bearing_damping_coefficient_s",
    *DAMPING,
]
#: c = β k is one multiplication: equal to the product to its round-off.
ROUND_OFF = 4e-16


def _case(damping: str, model: str = "equilibrium") -> str:
    """The Kim example with a radial load at 30 deg (kxy != 0) and the given damping keys."""
    text = BASE.replace(
        'axial_load = "60.68 N"',
        'axial_load = "60.68 N"\nradial_load = "150 N"\nradial_load_direction = "30 deg"',
    )
    assert 'model = "equilibrium"' in text
    return text.replace('model = "equilibrium"', f'model = "{model}"\n{damping}')


def _sweep(damping: str) -> str:
    values = ", ".join(f'"{s}"' for s in SPEEDS)
    vary = f'"operation.speed" = {{ values = [{values}] }}\n'
    return _case(damping) + '\n[study]\nkind = "sweep"\n[study.vary]\n' + vary


def _run_json(path: Path) -> dict:
    result = runner.invoke(app, ["run", str(path), "--json"])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def _rows(path: Path) -> list[dict[str, str]]:
    with path.open(newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


@pytest.mark.parametrize(
    ("keys", "model", "beta"),
    [
        ('bearing_damping = "kraemer"', "kraemer", 0.79e-5),
        (
            'bearing_damping = "proportional"\nbearing_damping_coefficient = "1.5e-5 s"',
            "proportional",
            1.5e-5,
        ),
    ],
)
def test_damped_sweep_rows_equal_separate_runs(
    tmp_path: Path, keys: str, model: str, beta: float
) -> None:
    study = tmp_path / "sweep.toml"
    study.write_text(_sweep(keys), encoding="utf-8")
    out = tmp_path / "out"
    result = runner.invoke(app, ["study", str(study), "--out", str(out), "--json"])
    assert result.exit_code == 0, result.stderr
    points = json.loads(result.stdout)["points"]
    with (out / "stiffness.csv").open(newline="", encoding="utf-8") as fh:
        assert next(csv.reader(fh)) == HEADER
    rows = _rows(out / "stiffness.csv")
    assert len(rows) == len(SPEEDS)
    for i, speed in enumerate(SPEEDS):
        single = tmp_path / f"run_{i}.toml"
        single.write_text(_case(keys).replace('speed = "7200 rpm"', f'speed = "{speed}"'), "utf-8")
        run = _run_json(single)
        k, c, row = run["radial_stiffness"], run["bearing_damping"], rows[i]
        assert float(row["speed_rpm"]) == k["speed_rpm"] == float(speed.split()[0])
        assert float(row["frequency_rad_per_s"]) == k["speed_rpm"] * 2.0 * math.pi / 60.0
        kzz = run["stiffness_matrix"]["matrix"][0][0]
        assert [float(row[n]) for n in STIFFNESS] == [k[n] for n in STIFFNESS]
        assert float(row["kzz_n_per_m"]) == kzz
        # the damping model is named in every row and in the run JSON
        assert row["bearing_damping"] == c["model"] == model
        assert float(row["bearing_damping_coefficient_s"]) == c["coefficient_s"] == beta
        assert [float(row[n]) for n in DAMPING] == [c[n] for n in DAMPING]
        # c = β k for every coefficient, the cross terms too
        for c_name, k_value in zip(DAMPING, [*(k[n] for n in STIFFNESS), kzz], strict=True):
            assert c[c_name] == pytest.approx(beta * k_value, rel=ROUND_OFF, abs=0.0), c_name
        assert abs(c["cxy_n_s_per_m"]) > 0.0  # the load at 30 deg couples x and y
        assert points[i]["bearing_damping"] == c
        assert any(n.startswith(f'bearing_damping = "{model}"') for n in run["notes"])
    # the readable output names the damping model of stiffness.csv
    readable = runner.invoke(app, ["study", str(study), "--out", str(tmp_path / "again")])
    assert readable.exit_code == 0, readable.stderr
    text = " ".join(readable.stdout.split())
    assert f'bearing_damping = "{model}" (β = {beta:.3g} s)' in text


def test_without_damping_the_table_is_stiffness_only_and_says_so(tmp_path: Path) -> None:
    study = tmp_path / "sweep.toml"
    study.write_text(_sweep(""), encoding="utf-8")
    out = tmp_path / "out"
    result = runner.invoke(app, ["study", str(study), "--out", str(out)])
    assert result.exit_code == 0, result.stderr
    assert not any(
        name.startswith(("c", "bearing_damping")) for name in _rows(out / "stiffness.csv")[0]
    )
    assert "stiffness only, no damping columns" in " ".join(result.stdout.split())
    single = tmp_path / "one.toml"
    single.write_text(_case(""), encoding="utf-8")
    assert "bearing_damping" not in _run_json(single)


def test_other_models_say_they_do_not_apply_the_damping(tmp_path: Path) -> None:
    case = tmp_path / "qs.toml"
    case.write_text(
        _case('bearing_damping = "kraemer"\nrevolutions = 2', model="quasi_static_3d"), "utf-8"
    )
    out = _run_json(case)
    assert "bearing_damping" not in out
    assert any(
        n.startswith("analysis.bearing_damping: not applied by the quasi_static_3d model")
        for n in out["notes"]
    )


@pytest.mark.parametrize(
    ("keys", "key"),
    [
        ('bearing_damping = "proportional"', "analysis.bearing_damping"),
        ('bearing_damping = "viscous"', "analysis.bearing_damping"),
        ('bearing_damping_coefficient = "2e-5 s"', "analysis.bearing_damping_coefficient"),
        (
            'bearing_damping = "kraemer"\nbearing_damping_coefficient = "2e-5 s"',
            "analysis.bearing_damping_coefficient",
        ),
        *(
            (
                f'bearing_damping = "proportional"\nbearing_damping_coefficient = {value}',
                "analysis.bearing_damping_coefficient",
            )
            for value in ('"-1e-5 s"', '"2e-3 s"', '"1e400 s"', "nan", "inf", '"2e-5 m"', "true")
        ),
    ],
)
def test_hostile_damping_keys_are_refused_naming_file_and_key(
    tmp_path: Path, keys: str, key: str
) -> None:
    case = tmp_path / "damped.toml"
    case.write_text(_case(keys), encoding="utf-8")
    result = subprocess.run(
        [sys.executable, "-m", "runout.cli", "run", str(case), "--json"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 2, result.stderr
    assert "damped.toml" in result.stderr and key in result.stderr
    assert "Traceback" not in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert result.stdout == ""


def test_study_dataframe_carries_the_damping(tmp_path: Path) -> None:
    import tomllib

    from runout.case.model import parse_case
    from runout.study.run import run_study

    data = tomllib.loads(_sweep('bearing_damping = "kraemer"'))
    study = run_study(parse_case(data, str(tmp_path / "case.toml"), tmp_path))
    df = study.to_dataframe()
    table = dict(study.stiffness_columns())
    for c_name, k_name in zip(DAMPING, [*STIFFNESS, "kzz_n_per_m"], strict=True):
        assert list(df[c_name]) == table[c_name]
        assert df.attrs["units"][c_name] == "N s/m"
        np.testing.assert_allclose(df[c_name], 0.79e-5 * df[k_name], rtol=ROUND_OFF, atol=0.0)


@pytest.mark.parametrize(
    "damping", ['bearing_damping = "kraemer"', "bearing_damping = \"proportional\"\n"
                'bearing_damping_coefficient = "2e-5 s"']
)  # fmt: skip
def test_run_out_writes_the_damping_matrix_beside_the_stiffness(
    damping: str, tmp_path: Path
) -> None:
    """``run --out`` of a damped case writes ``damping.csv``: β times the 5×5 of
    ``stiffness.csv``, its model and β on its first line; an undamped case writes none."""
    case = tmp_path / "case.toml"
    case.write_text(_case(damping), encoding="utf-8")
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(case), "--out", str(out)])
    assert result.exit_code == 0, result.stderr
    assert "damping.csv" in result.stdout
    doc = json.loads((out / "result.json").read_text(encoding="utf-8"))
    beta = doc["bearing_damping"]["coefficient_s"]
    lines = (out / "damping.csv").read_text(encoding="utf-8").splitlines()
    assert lines[0].startswith("#") and doc["bearing_damping"]["model"] in lines[0]
    damped = list(csv.reader(lines[1:]))
    with (out / "stiffness.csv").open(newline="", encoding="utf-8") as fh:
        stiff = list(csv.reader(fh))
    assert damped[0] == stiff[0] and [r[0] for r in damped] == [r[0] for r in stiff]
    c = np.array([[float(v) for v in r[1:]] for r in damped[1:]])
    k = np.array([[float(v) for v in r[1:]] for r in stiff[1:]])
    # both written to 12 significant digits (each within 5e-12 relative): equal to that rounding
    np.testing.assert_allclose(c, beta * k, rtol=1e-11, atol=0.0)

    undamped = tmp_path / "plain.toml"
    undamped.write_text(_case(""), encoding="utf-8")
    plain = tmp_path / "plain"
    result = runner.invoke(app, ["run", str(undamped), "--out", str(plain)])
    assert result.exit_code == 0, result.stderr
    assert (plain / "stiffness.csv").is_file() and not (plain / "damping.csv").exists()
