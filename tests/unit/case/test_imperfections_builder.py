"""runout.Imperfections: the case file's imperfection tables, built in code."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import runout
from runout.base.errors import CaseError
from runout.case.model import parse_case
from runout.geometry.imperfections import BearingImperfections as Resolved
from runout.geometry.imperfections import ImperfectionError, single_harmonic

BEARING = runout.BallBearing(
    elements=8, element_diameter=1e-3, pitch_diameter=7e-3, radial_clearance=10e-6
)
OPERATION = runout.Operation(rotating_ring="outer", speed=90.0, axial_load=20.0)
BEARING_TABLE = {
    "type": "ball",
    "elements": 8,
    "element_diameter": 1e-3,
    "pitch_diameter": 7e-3,
    "radial_clearance": 10e-6,
}


def _from_file_tables(tables: dict[str, object], tmp_path: Path | None = None) -> Resolved:
    data = {"bearing": dict(BEARING_TABLE), **tables}
    return parse_case(data, "case.toml", tmp_path).imperfections


def _resolved(builder: runout.Imperfections, tmp_path: Path | None = None) -> Resolved:
    return runout.Case.from_inputs(BEARING, OPERATION, builder, base_dir=tmp_path).imperfections


def test_the_issue_example_works_as_written() -> None:
    builder = (
        runout.Imperfections(elements=8)
        .waviness("inner", order=9, amplitude=10e-9, phase=0.3)
        .spectrum("outer", orders=(2, 30), amplitude=0.3e-6, exponent=-1, phase="random", seed=7)
        .diameter_errors([1e-7, 0, 0, -1e-7, 0, 0, 2e-7, 0])
        .pitch_errors([0.0] * 7 + [1e-3])
    )
    resolved = _resolved(builder)
    expected = _from_file_tables(
        {
            "waviness": [{"part": "inner", "order": 9, "amplitude": 10e-9, "phase": 0.3}],
            "waviness_spectrum": [
                {
                    "part": "outer",
                    "orders": [2, 30],
                    "amplitude": 0.3e-6,
                    "exponent": -1.0,
                    "phase": "random",
                    "seed": 7,
                }
            ],
            "elements": {
                "diameter_errors": [1e-7, 0.0, 0.0, -1e-7, 0.0, 0.0, 2e-7, 0.0],
                "pitch_errors": [0.0] * 7 + [1e-3],
            },
        }
    )
    assert resolved.summary() == expected.summary()
    assert resolved.inner.amplitudes[0] == 10e-9
    assert len(resolved.outer) == 29


def test_peak_to_peak_is_halved_and_units_are_read() -> None:
    resolved = _resolved(
        runout.Imperfections().waviness("outer", order=4, peak_to_peak="20 nm", phase="90 deg")
    )
    assert resolved.outer.amplitudes[0] == pytest.approx(10e-9, rel=1e-12)
    assert resolved.outer.phases[0] == pytest.approx(math.pi / 2, rel=1e-12)


def test_each_call_returns_a_new_object() -> None:
    base = runout.Imperfections(elements=8)
    one = base.waviness("inner", order=3, amplitude=1e-8)
    two = one.waviness("inner", order=5, amplitude=1e-8)
    assert base.tables() == {}
    assert len(one.tables()["waviness"]) == 1
    assert len(two.tables()["waviness"]) == 2
    with pytest.raises(AttributeError):
        base.elements = 9  # type: ignore[misc]


def test_element_numbers_run_from_1_to_z() -> None:
    builder = runout.Imperfections(elements=8).waviness("ball", order=2, amplitude=1e-8, element=8)
    resolved = _resolved(builder)
    assert resolved.elements[7].amplitudes[0] == 1e-8
    assert all(h.is_empty for h in resolved.elements[:7])
    with pytest.raises(CaseError, match=r"waviness\[1\]\.element: must be <= 8"):
        runout.Imperfections(elements=8).waviness("ball", order=2, amplitude=1e-8, element=9)
    with pytest.raises(CaseError, match=r"waviness\[1\]\.element"):
        runout.Imperfections(elements=8).waviness("ball", order=2, amplitude=1e-8, element=0)


@pytest.mark.parametrize(
    ("call", "key"),
    [
        (lambda b: b.waviness("inner", order=3), r"waviness\[1\]\.amplitude"),
        (lambda b: b.waviness("inner", order=3, amplitude=1e-8, peak_to_peak=2e-8), "amplitude"),
        (lambda b: b.waviness("hub", order=3, amplitude=1e-8), r"waviness\[1\]\.part"),
        (lambda b: b.waviness("inner", order=3, amplitude="3 N"), r"waviness\[1\]\.amplitude"),
        (lambda b: b.spectrum("inner", orders=(5, 2), amplitude=1e-8), r"\.orders"),
        (lambda b: b.spectrum("inner", orders=(2, 5), amplitude=1e-8, phase=0.1, seed=3), "seed"),
        (lambda b: b.diameter_errors([0.0] * 7), r"elements\.diameter_errors: has 7 entries"),
        (lambda b: b.slant(amplitude=1e-8, angle=1e-4), r"slant\.amplitude"),
        (lambda b: b.phase_frame("ring"), r"elements\.phase_frame"),
    ],
)
def test_bad_entries_get_the_case_file_message(call: object, key: str) -> None:
    with pytest.raises(CaseError, match=key):
        call(runout.Imperfections(elements=8))  # type: ignore[operator]


def test_a_second_entry_is_numbered_like_the_file() -> None:
    builder = runout.Imperfections().waviness("inner", order=3, amplitude=1e-8)
    with pytest.raises(CaseError, match=r"waviness\[2\]\.order"):
        builder.waviness("inner", order=-1, amplitude=1e-8)


def test_profile_from_a_file_and_from_arrays_agree(tmp_path: Path) -> None:
    theta = np.linspace(0.0, 360.0, 360, endpoint=False)
    microns = 0.05 * np.cos(np.deg2rad(7 * theta)) + 0.02 * np.sin(np.deg2rad(13 * theta))
    (tmp_path / "ring.csv").write_text(
        "angle_deg,deviation_um\n"
        + "".join(f"{float(a)!r},{float(d)!r}\n" for a, d in zip(theta, microns, strict=True)),
        encoding="utf-8",
    )
    from_file = _resolved(
        runout.Imperfections().profile("inner", file="ring.csv", orders=(2, 20)), tmp_path
    )
    from_arrays = _resolved(
        runout.Imperfections().profile(
            "inner",
            orders=(2, 20),
            angles=theta,
            deviations=microns,
            angle_unit="deg",
            deviation_unit="um",
        )
    )
    assert from_file.inner == from_arrays.inner
    assert from_file.inner.amplitudes.max() == pytest.approx(0.05e-6, rel=1e-9)
    with pytest.raises(CaseError, match=r"profile\[1\]\.file: give file"):
        runout.Imperfections().profile("inner", orders=(2, 20))


def test_slant_and_phase_frame_reach_the_case() -> None:
    builder = (
        runout.Imperfections(elements=8)
        .waviness("ball", order=2, amplitude=1e-8, phase=0.5, element=2)
        .slant(amplitude="0.05 um")
        .pitch_errors([0.0, 1e-3, 0, 0, 0, 0, 0, 0])
        .phase_frame("fixed")
    )
    assert builder.tables()["elements"] == {
        "pitch_errors": [0.0, 1e-3, 0, 0, 0, 0, 0, 0],
        "phase_frame": "fixed",
    }
    resolved = _resolved(builder)
    assert resolved.slant is not None and resolved.slant.amplitude == pytest.approx(0.05e-6)
    beta = 2 * math.pi / 8 + 1e-3  # element 2's centre: the fixed-frame phase moves by 2 beta
    assert resolved.elements[1].phases[0] == pytest.approx((0.5 + 2 * beta) % (2 * math.pi))


def test_keyword_of_the_physics_class_is_refused_with_a_hint() -> None:
    with pytest.raises(TypeError, match=r"elements=Z.*\.waviness"):
        runout.Imperfections(outer=single_harmonic(3, 1e-8, 0.0))  # type: ignore[call-arg]


def test_the_physics_class_takes_z_or_says_to_pass_it() -> None:
    wavy = single_harmonic(3, 1e-8, 0.0)
    resolved = Resolved(elements=8, outer=wavy)
    assert resolved.n_elements == 8 and resolved.outer == wavy
    with pytest.raises(ImperfectionError, match="pass elements=Z"):
        Resolved(outer=wavy)
    with pytest.raises(ImperfectionError, match=">= 1"):
        Resolved(elements=0)


def test_equal_builders_compare_equal() -> None:
    theta = np.linspace(0.0, 2 * np.pi, 64, endpoint=False)
    one = runout.Imperfections(elements=8).profile(
        "inner", orders=(2, 8), angles=theta, deviations=1e-8 * np.cos(3 * theta)
    )
    two = runout.Imperfections(elements=8).profile(
        "inner", orders=(2, 8), angles=theta, deviations=1e-8 * np.cos(3 * theta)
    )
    other = runout.Imperfections(elements=8).profile(
        "inner", orders=(2, 8), angles=theta, deviations=1e-8 * np.cos(4 * theta)
    )
    assert one == two
    assert one != other
    assert one != runout.Imperfections(elements=8)


def test_a_study_refuses_a_profile_given_as_arrays() -> None:
    theta = np.linspace(0.0, 2 * np.pi, 64, endpoint=False)
    builder = runout.Imperfections().profile(
        "inner", orders=(2, 8), angles=theta, deviations=1e-8 * np.cos(3 * theta)
    )
    study = {"kind": "sweep", "vary": {"operation.axial_load": {"values": [10.0, 20.0]}}}
    with pytest.raises(CaseError, match=r"profile\[1\]\.file: a study reads its profiles"):
        runout.Case.from_inputs(BEARING, OPERATION, builder, study=study)
