"""runout.examples: the seed bearings as typed inputs equal the example case files."""

from __future__ import annotations

import dataclasses
import gzip
import json
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

import golden
import runout
from runout import examples
from runout.base.errors import CaseError
from runout.case.model import Case, load_case

ROOT = Path(__file__).resolve().parents[3]
STORED_JSON = ROOT / "tests" / "data" / "examples_json"

FACTORIES: list[tuple[Callable[[], examples.Example], str]] = [
    (examples.tada, "seed000_tada_fig7"),
    (examples.kim, "seed001_kim_spindle"),
    (examples.anderon_608, "seed002_608"),
    (examples.purohit, "seed003_purohit"),
    (examples.nu209, "seed004_nu209"),
]
IDS = [name for _, name in FACTORIES]


def _assert_same_physics(built: Case, read: Case) -> None:
    assert built.title == read.title
    assert built.bearing == read.bearing
    assert built.operation == read.operation
    assert built.analysis == read.analysis
    assert built.spec.dynamics == read.spec.dynamics
    mine, theirs = built.imperfections, read.imperfections
    assert mine.inner == theirs.inner
    assert mine.outer == theirs.outer
    assert mine.elements == theirs.elements
    assert np.array_equal(mine.diameter_errors, theirs.diameter_errors)
    assert np.array_equal(mine.pitch_errors, theirs.pitch_errors)
    assert mine.slant == theirs.slant
    assert built.spec.elements == read.spec.elements  # phase frame of element waviness


@pytest.mark.parametrize(("factory", "name"), FACTORIES, ids=IDS)
def test_each_example_is_its_case_file(factory: Callable[[], examples.Example], name: str) -> None:
    _assert_same_physics(factory().case(), load_case(ROOT / "examples" / f"{name}.toml"))


def test_the_comparison_sees_a_changed_input() -> None:
    # the equality above must be able to fail: one ulp of clearance is another bearing
    read = load_case(ROOT / "examples" / "seed000_tada_fig7.toml")
    with pytest.raises(AssertionError):
        _assert_same_physics(examples.tada(radial_clearance=10e-6).case(), read)
    with pytest.raises(AssertionError):
        _assert_same_physics(examples.tada(peak_to_peak="21 nm").case(), read)


def test_the_bearing_factories_are_the_examples_bearings() -> None:
    assert examples.tada().bearing == examples.tada_bearing()
    assert examples.kim().bearing == examples.kim_bearing()
    assert examples.anderon_608().bearing == examples.bearing_608()
    assert examples.purohit().bearing == examples.purohit_bearing()
    assert examples.nu209().bearing == examples.nu209_bearing()
    assert isinstance(examples.nu209_bearing(), runout.RollerBearing)
    assert isinstance(examples.bearing_608(), runout.BallBearing)


# The cheap examples (under a second each); the others are compared through the CLI by
# tests/cli/test_examples_json.py, and their inputs above.
@pytest.mark.parametrize(
    ("factory", "name"),
    [
        (examples.kim, "seed001_kim_spindle"),
        (examples.anderon_608, "seed002_608"),
        (examples.nu209, "seed004_nu209"),
    ],
    ids=["seed001_kim_spindle", "seed002_608", "seed004_nu209"],
)
def test_run_prints_what_runout_run_prints(
    factory: Callable[[], examples.Example], name: str
) -> None:
    # the stored file is `runout run examples/<name>.toml --json` (written on one machine: the
    # comparison of tests/golden.py absorbs the last digits another machine moves)
    stored = json.loads(gzip.decompress((STORED_JSON / f"{name}.json.gz").read_bytes()))
    result = factory().run()
    golden.assert_same(json.loads(json.dumps(result.to_json(), allow_nan=False)), stored, name)


def test_keyword_arguments_change_what_they_name() -> None:
    kim12 = examples.kim(elements=12, axial_load=30.0, oversize="0.2 um")
    assert kim12.bearing.elements == 12
    assert kim12.operation.axial_load == 30.0
    case = kim12.case()
    assert case.imperfections.diameter_errors[0] == pytest.approx(0.2e-6)
    assert np.all(case.imperfections.diameter_errors[1:] == 0.0)
    assert case.imperfections.diameter_errors.size == 12
    assert "0.2 um" in kim12.title

    perfect = examples.kim(oversize=None)
    assert perfect.imperfections is None
    assert perfect.case().imperfections.is_perfect
    assert "oversize" not in perfect.title

    tada9 = examples.tada(elements=9).case()
    # Fig. 7's lobes are Z - 1, Z and Z + 1 of the bearing
    assert list(tada9.imperfections.inner.orders) == [8, 9, 10]
    assert list(tada9.imperfections.outer.orders) == [8, 9, 10]

    assert examples.tada_bearing(radial_clearance="4 um").radial_clearance == pytest.approx(4e-6)
    assert examples.purohit_bearing(elements=12).elements == 12
    turned = examples.purohit(radial_load_direction="0 deg").operation
    assert turned.radial_load_direction == 0.0
    assert examples.purohit().operation.radial_load_direction == pytest.approx(-np.pi / 2)
    roller = examples.nu209(amplitude="2 um", order=8).case()
    assert list(roller.imperfections.inner.orders) == [8]
    assert roller.imperfections.inner.amplitudes[0] == pytest.approx(2e-6)


def test_with_analysis_and_replace() -> None:
    base = examples.kim()
    short = base.with_analysis(revolutions=2, samples=256)
    assert short.case().analysis.samples == 256
    assert short.case().analysis.revolutions == 2
    assert base.analysis["samples"] == 4096  # the example itself is unchanged
    assert base.case(model="equilibrium").analysis.model == "equilibrium"
    assert dataclasses.replace(base, imperfections=None).case().imperfections.is_perfect


def test_run_options_override_and_unknown_ones_are_refused() -> None:
    result = examples.nu209().run(revolutions=1.0, samples=360)
    assert result.model == "roller_constraint"
    with pytest.raises(CaseError, match="samples"):
        examples.nu209().run(sampels=360)


def test_examples_are_frozen() -> None:
    example = examples.kim()
    with pytest.raises(dataclasses.FrozenInstanceError):
        example.title = "other"  # type: ignore[misc]
    with pytest.raises(TypeError):
        example.analysis["samples"] = 8  # type: ignore[index]
    with pytest.raises(TypeError):
        examples.purohit().dynamics["mass"] = 1.0  # type: ignore[index]
