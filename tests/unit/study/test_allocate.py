"""Tolerance allocation (runout.study.allocate): the search against exact order statistics,
common random numbers through the study engine, the tolerance of each kind of entry, the
schema's refusals and the digest of studies without allocation."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.base.errors import CaseError
from runout.case.model import Case, VarySpec
from runout.study import run as st_mod
from runout.study.allocate import (
    SearchError,
    allocate,
    search,
    tolerance_of,
    with_tolerance,
)
from runout.study.run import run_study


def critical_passes(critical: np.ndarray) -> Any:
    """passes(t) of a lot whose bearing i meets the limit up to t_i = critical[i]."""

    def passes(t: float) -> tuple[int, int]:
        return int(np.sum(critical >= t)), critical.size

    return passes


@settings(max_examples=200, deadline=None)
@given(
    critical=st.lists(st.floats(1e-9, 1e-6), min_size=5, max_size=200),
    target=st.floats(0.05, 0.95),
    guess=st.floats(1e-9, 1e-5),
)
def test_search_finds_the_order_statistic(
    critical: list[float], target: float, guess: float
) -> None:
    # with common random numbers the yield at t is the fraction of critical tolerances >= t;
    # the largest t meeting the target is the m-th largest of them, m = ceil(target n)
    t = np.asarray(critical)
    n = t.size
    m = math.ceil(target * n - 1e-9)
    exact = np.sort(t)[::-1][m - 1]
    found = search(critical_passes(t), lowest=0.0, guess=guess, target=target, rtol=1e-3)
    passes = critical_passes(t)
    assert passes(found.value)[0] >= m  # the allocated value meets the target
    assert found.value <= exact  # and is not above the exact answer
    assert found.converged and found.monotone and found.failing is not None
    assert passes(found.failing)[0] < m  # the next value tried misses it
    assert found.failing - found.value <= 1e-3 * found.value
    assert found.value <= exact < found.failing or math.isclose(found.value, exact)
    assert len(found.evaluations) <= 40


def test_search_refuses_an_unreachable_target_and_a_quantity_that_does_not_limit() -> None:
    def never(t: float) -> tuple[int, int]:  # another source fails half the lot at any t
        return 5, 10

    with pytest.raises(SearchError) as info:
        search(never, lowest=0.0, guess=1e-7, target=0.9)
    assert info.value.reason == "unreachable" and info.value.value == 0.0

    def always(t: float) -> tuple[int, int]:
        return 10, 10

    with pytest.raises(SearchError) as info:
        search(always, lowest=0.0, guess=1e-7, target=0.9)
    assert info.value.reason == "unlimited"


def test_search_stops_at_its_study_budget_and_says_so() -> None:
    t = np.linspace(1e-8, 1e-7, 50)
    found = search(critical_passes(t), lowest=0.0, guess=1e-9, target=0.5, max_studies=4)
    assert len(found.evaluations) == 4 and not found.converged


def mc(
    vary: dict[str, Any], samples: int = 40, seed: int = 3, limit: str | None = None, **study: Any
) -> Case:
    """Kim's bearing (quasi_static_2d, short record) with a Monte Carlo [study]."""
    from runout import examples

    kim = examples.kim(radial_load=0.0, oversize=None)
    analysis: dict[str, Any] = {"model": "quasi_static_2d", "revolutions": 4, "samples": 256}
    if limit is not None:
        analysis["limit"] = limit
    return Case.from_inputs(
        kim.bearing,
        kim.operation,
        analysis=analysis,
        study={"kind": "montecarlo", "samples": samples, "seed": seed, "vary": vary, **study},
    )


def test_common_random_numbers_scale_every_draw() -> None:
    # the same seed at another tolerance draws mean + t z_i with the same z_i: what makes the
    # yield monotone in t and the bisection exact
    a = run_study(mc({"element_diameter_sigma": "0.1 um"}, samples=6))
    b = run_study(mc({"element_diameter_sigma": "0.25 um"}, samples=6))
    za = np.asarray(a.values["element_diameter_sigma"])
    zb = np.asarray(b.values["element_diameter_sigma"])
    np.testing.assert_allclose(zb, 2.5 * za, rtol=1e-12, atol=0.0)
    lo, hi = "0 N", "4 N"
    uni = {"operation.radial_load": {"distribution": "uniform", "low": lo, "high": hi}}
    u4 = np.asarray(run_study(mc(uni, samples=6)).values["operation.radial_load"])
    uni["operation.radial_load"]["high"] = "8 N"
    u8 = np.asarray(run_study(mc(uni, samples=6)).values["operation.radial_load"])
    np.testing.assert_allclose(u8, 2.0 * u4, rtol=1e-12, atol=0.0)


@settings(max_examples=6, deadline=None)
@given(scales=st.lists(st.floats(0.02, 0.5), min_size=2, max_size=3, unique=True))
def test_yield_is_monotone_in_the_tolerance_with_common_random_numbers(
    scales: list[float],
) -> None:
    # Kim's bearing, 2-D quasi-static model: a larger ball tolerance never brings a bearing of
    # the same draws back within the limit
    passed = []
    for s in sorted(scales):
        case = mc({"element_diameter_sigma": f"{s} um"}, samples=30, limit="0.2 um")
        passed.append(run_study(case).lot_yield()["passed"])
    assert passed == sorted(passed, reverse=True)


def test_tolerance_of_each_kind_of_entry() -> None:
    sigma = mc(
        {"element_diameter_sigma": "0.1 um"},
        limit="0.2 um",
        allocate="element_diameter_sigma",
        target_yield=0.9,
    )
    t = tolerance_of(sigma)
    assert (t.parameter, t.name, t.unit, t.lowest) == (
        "sigma",
        "element_diameter_sigma_m",
        "m",
        0.0,
    )
    assert t.given == pytest.approx(1e-7)
    normal = {"operation.axial_load": {"distribution": "normal", "std": "2 N"}}
    t = tolerance_of(mc(normal, limit="0.2 um", allocate="operation.axial_load", target_yield=0.9))
    assert (t.parameter, t.name, t.given) == ("std", "operation.axial_load.std_n", 2.0)
    uniform = {"operation.radial_load": {"distribution": "uniform", "low": "1 N", "high": "3 N"}}
    case = mc(uniform, limit="0.2 um", allocate="operation.radial_load", target_yield=0.9)
    t = tolerance_of(case)
    assert (t.parameter, t.name, t.lowest, t.given) == (
        "high",
        "operation.radial_load.high_n",
        1.0,
        3.0,
    )
    step = with_tolerance(case, t, 5.0)
    assert step.study is not None and step.study.allocate is None
    entry = step.study.vary["operation.radial_load"]
    assert isinstance(entry, VarySpec) and entry.high == 5.0 and entry.low == "1 N"


def test_allocation_in_python_meets_the_target_and_states_the_interval() -> None:
    case = mc(
        {"element_diameter_sigma": "0.1 um"},
        samples=80,
        limit="0.15 um",
        allocate="element_diameter_sigma",
        target_yield=0.75,
    )
    found = allocate(case)
    out = found.to_json()
    assert out["passed"] >= math.ceil(0.75 * 80) and out["samples"] == 80
    assert out["ci"][0] < 0.75 < out["ci"][1]
    assert out["element_diameter_sigma_m"] == found.search.value
    assert found.result.lot_yield()["passed"] == out["passed"]
    assert out["studies"][0]["element_diameter_sigma_m"] == pytest.approx(1e-7)


@pytest.mark.parametrize(
    ("study", "key", "message"),
    [
        ({"target_yield": 0.9}, "study.target_yield", "needs allocate"),
        ({"allocate": "element_diameter_sigma"}, "study.target_yield", "required with allocate"),
        ({"allocate": "x", "target_yield": 0.9}, "study.allocate", "not a [study.vary] key"),
        ({"allocate": "element_diameter_sigma", "target_yield": 1.0}, "study.target_yield", ""),
        ({"allocate": "element_diameter_sigma", "target_yield": 0.0}, "study.target_yield", ""),
    ],
)
def test_schema_refusals(study: dict[str, Any], key: str, message: str) -> None:
    with pytest.raises(CaseError) as info:
        mc({"element_diameter_sigma": "0.1 um"}, **study)
    assert info.value.key == key and message in info.value.message


def test_a_study_without_allocation_keeps_its_digest() -> None:
    # the digest of examples/seed001_kim_table9.toml with the draws of sampling version 2
    # (tests/unit/study/test_study_columns.py), which the unset allocation and arrangement keys
    # leave as it was: its output directories still resume and load. A new value here means
    # they no longer do; change it only for a change of what decides the study's numbers
    from pathlib import Path

    from runout.case.model import load_case

    root = Path(__file__).resolve().parents[3]
    case = load_case(root / "examples" / "seed001_kim_table9.toml")
    digest = st_mod._plan(case, None).digest
    assert digest == "21f1175ef8a56043816b3e33d903f0fdef9db026f9e0d217beccd22a950e9ce6"


def test_a_catalogue_bearing_keeps_its_digest(tmp_path: Path) -> None:
    # a designation's dynamic load rating C came with the catalogue's C column: the digest
    # of a study of a catalogue bearing is the one earlier versions took (pinned from the
    # version before the column), so its output directories still resume; a C the case gives
    # is the case's input and is hashed
    case_text = """title = "6205 lot"
[bearing]
designation = "6205"
radial_clearance = "5 um"
[operation]
rotating_ring = "inner"
speed = "1800 rpm"
axial_load = "100 N"
[analysis]
model = "quasi_static_2d"
revolutions = 8
samples = 1024
[study]
kind = "montecarlo"
samples = 100
seed = 1
[study.vary]
element_diameter_sigma = "0.1 um"
"""
    from runout.case.model import load_case

    path = tmp_path / "lot.toml"
    path.write_text(case_text, encoding="utf-8")
    case = load_case(path)
    assert case.bearing.dynamic_load_rating is not None  # the catalogue's
    digest = st_mod._plan(case, None).digest
    assert digest == "877828686166411167552ab9610d7d0080b8af6a7e7e8b8b9b69b1f4be4a057b"
    given = case_text.replace('radial_clearance = "5 um"', 'radial_clearance = "5 um"\n'
                              'dynamic_load_rating = "14 kN"')  # fmt: skip
    path.write_text(given, encoding="utf-8")
    assert st_mod._plan(load_case(path), None).digest != digest
