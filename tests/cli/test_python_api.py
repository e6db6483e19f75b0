"""runout.run and Case.from_inputs: a case built in code is the case of the same file.

The same bearing, operation and imperfections written in Python and in a case file give
byte-identical JSON; a case saved with Case.to_toml (or Case.save) runs to the same JSON with
the command line.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from typer.testing import CliRunner

import runout
from cases import MODIFIED_LIFE_CASE, MODIFIED_LIFE_KEYS
from runout.base.errors import CaseError
from runout.cli.commands import app
from runout.runner import run_model

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
runner = CliRunner()


def _dumps(payload: Any) -> str:
    return json.dumps(payload)


def _file_json(name: str) -> str:
    return _dumps(run_model(runout.load_case(EXAMPLES / name)).to_json())


def _cli_json(path: Path, *extra: str) -> str:
    result = runner.invoke(app, ["run", str(path), "--json", *extra])
    assert result.exit_code == 0, result.stderr
    return _dumps(json.loads(result.stdout))


def _tada() -> dict[str, Any]:
    imperfections = runout.Imperfections(elements=8)
    for part in ("inner", "outer"):
        for order in (7, 8, 9):
            imperfections = imperfections.waviness(part, order=order, peak_to_peak="20 nm")
    return {
        "bearing": runout.BallBearing(
            elements=8,
            element_diameter=1e-3,
            pitch_diameter=7e-3,
            inner_conformity=0.52,
            outer_conformity=0.53,
            radial_clearance=10 * 1e-6,  # "10 um" as the unit parser reads it
        ),
        "operation": runout.Operation(rotating_ring="outer", speed=5400 / 60, axial_load=20.0),
        "imperfections": imperfections,
        "title": "Tada standard model (seed 000 Table 1), Fig. 7 wavinesses",
    }


def test_quasi_static_3d_in_code_equals_the_case_file() -> None:
    result = runout.run("quasi_static_3d", **_tada(), revolutions=72, samples=4096)
    assert _dumps(result.to_json()) == _file_json("seed000_tada_fig7.toml")


def test_roller_constraint_in_code_equals_the_case_file() -> None:
    result = runout.run(
        "roller_constraint",
        bearing=runout.RollerBearing(
            elements=14,
            element_diameter=10e-3,
            inner_raceway_diameter=54.991e-3,
            outer_raceway_diameter=75.032e-3,
        ),
        operation=runout.Operation(rotating_ring="inner", speed=1 / 60, radial_load=10.0),
        imperfections=runout.Imperfections(elements=14).waviness(
            "inner", order=10, amplitude="1 um"
        ),
        title="NU209 (seed 004 Table 1), inner raceway 1 um at 10 lobes (Fig. 9)",
        revolutions=1.5,
        samples=2161,
    )
    assert _dumps(result.to_json()) == _file_json("seed004_nu209.toml")


def test_dynamic_in_code_equals_the_case_file() -> None:
    # the issue: Case(..., spec=None) crashed the dynamic model; the [dynamics] keys are options
    result = runout.run(
        "dynamic",
        bearing=runout.BallBearing(
            elements=9,
            element_diameter=7.96e-3,
            pitch_diameter=54e-3,
            inner_conformity=4.08e-3 / 7.96e-3,  # the file's groove radii over the diameter
            outer_conformity=4.61e-3 / 7.96e-3,
            radial_clearance=0.2e-6,
        ),
        operation=runout.Operation(
            rotating_ring="inner",
            speed=5000 / 60,
            radial_load=6.0,
            axial_load=10.0,
            preload="position",  # the file's seed 003 rotor, held axially
        ),
        title="Purohit rotor-bearing system (seed 003 Table 2)",
        revolutions=50,
        samples=8192,
        mass="0.6 kg",
        damping=200.0,
    )
    assert _dumps(result.to_json()) == _file_json("seed003_purohit.toml")


@pytest.mark.parametrize(
    "name", ["seed000_tada_fig7.toml", "seed004_nu209.toml", "seed003_purohit.toml"]
)
def test_to_toml_of_a_loaded_case_runs_to_the_same_json(name: str, tmp_path: Path) -> None:
    case = runout.load_case(EXAMPLES / name)
    saved = tmp_path / name
    saved.write_text(case.to_toml(), encoding="utf-8")
    again = runout.load_case(saved)
    assert again.spec == case.spec
    assert _cli_json(saved) == _file_json(name)


def test_a_case_built_in_code_saved_and_run_by_the_cli_gives_the_same_json(
    tmp_path: Path,
) -> None:
    tada = _tada()
    case = runout.Case.from_inputs(
        tada["bearing"],
        tada["operation"],
        tada["imperfections"],
        title=tada["title"],
        analysis={"model": "quasi_static_3d", "revolutions": 72, "samples": 4096},
    )
    assert case.path == "<python>"
    saved = tmp_path / "tada.toml"
    saved.write_text(case.to_toml(), encoding="utf-8")
    assert (
        _cli_json(saved)
        == _dumps(run_model(case).to_json())
        == _file_json("seed000_tada_fig7.toml")
    )


def test_a_profile_given_as_arrays_is_saved_as_csv_and_runs_to_the_same_json(
    tmp_path: Path,
) -> None:
    theta = np.linspace(0.0, 2 * np.pi, 720, endpoint=False)
    deviations = 30e-9 * np.cos(5 * theta + 0.4) + 12e-9 * np.cos(11 * theta)
    tada = _tada()
    imperfections = tada["imperfections"].profile(
        "outer", orders=(2, 20), angles=theta, deviations=deviations
    )
    case = runout.Case.from_inputs(
        tada["bearing"],
        tada["operation"],
        imperfections,
        analysis={"model": "quasi_static_2d", "revolutions": 10, "samples": 1024},
    )
    outer = case.imperfections.outer
    assert 5 in outer.orders and 11 in outer.orders
    with pytest.raises(CaseError, match=r"profile\[1\]\.file.*Case\.save"):
        case.to_toml()
    saved = case.save(tmp_path / "profiled.toml")
    assert (tmp_path / "profiled.outer_profile_1.csv").is_file()  # named after the case
    assert _cli_json(saved) == _dumps(run_model(case).to_json())


def test_from_inputs_is_the_case_of_the_file() -> None:
    tada = _tada()
    case = runout.Case.from_inputs(
        tada["bearing"],
        tada["operation"],
        tada["imperfections"],
        title=tada["title"],
        analysis={"model": "quasi_static_3d", "revolutions": 72, "samples": 4096},
    )
    loaded = runout.load_case(EXAMPLES / "seed000_tada_fig7.toml")
    assert case.spec is not None
    assert case.bearing == loaded.bearing
    assert case.operation == loaded.operation
    assert case.imperfections.summary() == loaded.imperfections.summary()


def test_an_unknown_option_is_named_with_a_hint() -> None:
    with pytest.raises(CaseError, match=r"revolution: unknown option.*did you mean 'revolutions'"):
        runout.run("linear", **_tada(), revolution=3)


def test_a_bad_option_value_gets_the_case_file_message() -> None:
    with pytest.raises(CaseError, match=r"<python>: analysis\.samples: must be >= 16"):
        runout.run("linear", **_tada(), samples=4)
    with pytest.raises(CaseError, match=r"dynamics\.mass: must be > 0"):
        runout.run("dynamic", **_tada(), mass="-1 kg")
    with pytest.raises(CaseError, match=r"analysis\.model: must be one of"):
        runout.run("quasi_static", **_tada())


def test_imperfections_for_another_number_of_elements_are_refused() -> None:
    tada = _tada()
    tada["imperfections"] = runout.Imperfections(elements=9).waviness(
        "inner", order=3, amplitude=1e-8
    )
    with pytest.raises(CaseError, match=r"bearing\.elements: the imperfections were built for"):
        runout.run("linear", **tada)


def test_imperfections_without_elements_take_z_from_the_bearing() -> None:
    tada = _tada()
    tada["imperfections"] = runout.Imperfections().spectrum(
        "ball", orders=(2, 6), amplitude=1e-8, exponent=-1, seed=3
    )
    case = runout.Case.from_inputs(tada["bearing"], tada["operation"], tada["imperfections"])
    assert case.imperfections.n_elements == 8
    assert all(not h.is_empty for h in case.imperfections.elements)


def test_importing_runout_does_not_import_the_models_or_pandas() -> None:
    import subprocess
    import sys

    code = (
        "import sys, runout; "
        "print(any(m in sys.modules for m in ('pandas', 'runout.models', 'runout.case.model', "
        "'runout.api')))"
    )
    env = {**os.environ, "PYTHONWARNINGS": "ignore"}
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True, env=env
    )
    assert out.stdout.strip() == "False"
    assert callable(runout.run) and runout.Case.__name__ == "Case"


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.toml")), ids=lambda p: p.stem)
def test_every_example_survives_to_toml(path: Path, tmp_path: Path) -> None:
    case = runout.load_case(path)
    saved = tmp_path / path.name
    saved.write_text(case.to_toml(), encoding="utf-8")
    again = runout.load_case(saved)
    assert again.spec == case.spec
    # the keys the file gave, and only those: a model reads "given" from them
    assert again.spec.model_dump(exclude_unset=True) == case.spec.model_dump(exclude_unset=True)
    assert again.bearing == case.bearing and again.operation == case.operation
    assert again.imperfections.summary() == case.imperfections.summary()


# the modified life's inputs, a case file's tables that the bearing and operation objects do
# not hold: fatigue_load_limit (a [bearing] key) and [lubrication]
LIFE_CASE = MODIFIED_LIFE_CASE.format(**MODIFIED_LIFE_KEYS)


def _life_inputs() -> dict[str, Any]:
    return {
        "bearing": runout.BallBearing(
            elements=7,
            element_diameter=11.5e-3,
            pitch_diameter=43.5 * 1e-3,  # "43.5 mm" as the unit parser reads it
            inner_conformity=0.52,
            outer_conformity=0.53,
            radial_clearance=10 * 1e-6,
            material=runout.Material(youngs_modulus=210e9, poisson_ratio=0.3),
            dynamic_load_rating=23.4e3,
        ),
        "operation": runout.Operation(
            rotating_ring="inner", speed=50.0, axial_load=500.0, radial_load=1500.0
        ),
        "title": "modified life",
    }


def test_the_modified_life_from_code_equals_the_case_file(tmp_path: Path) -> None:
    path = tmp_path / "life.toml"
    path.write_text(LIFE_CASE, encoding="utf-8")
    tables = {
        "bearing": {"fatigue_load_limit": "0.6 kN"},
        "lubrication": {"viscosity_ratio": 1.5, "contamination_factor": 0.5},
    }
    result = runout.run("equilibrium", **_life_inputs(), tables=tables, reliability=99)
    in_code = result.to_json()
    assert in_code["life"]["lnmr_mrev"] > 0.0  # the modified life is there
    assert _dumps(in_code) == _cli_json(path)


def test_a_spall_and_its_sensor_from_code_are_the_case_files() -> None:
    loaded = runout.load_case(EXAMPLES / "cwru_6205_outer_spall.toml")
    document = loaded.to_document()
    tables = {name: document[name] for name in ("defect", "sensor")}
    case = runout.Case.from_inputs(
        loaded.bearing,
        loaded.operation,
        title=loaded.title,
        analysis=document["analysis"],
        dynamics=document.get("dynamics"),
        tables=tables,
    )
    assert case.spec.defect == loaded.spec.defect
    assert case.spec.sensor == loaded.spec.sensor


@pytest.mark.parametrize(
    ("tables", "message"),
    [
        ({"bearing": {"elements": 9}}, r"bearing\.elements: given by the bearing and in tables"),
        ({"analysis": {"samples": 64}}, r"tables\.analysis: the \[analysis\] keys are"),
        ({"lubricant": {"viscosity_ratio": 1.0}}, r"lubricant"),
        ({"lubrication": {"viscosity_ratio": -1.0}}, r"lubrication\.viscosity_ratio"),
    ],
)
def test_tables_that_clash_or_are_wrong_are_refused_naming_the_key(
    tables: dict[str, Any], message: str
) -> None:
    with pytest.raises(CaseError, match=message):
        runout.run("equilibrium", **_life_inputs(), tables=tables)
