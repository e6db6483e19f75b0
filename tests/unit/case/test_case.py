"""Case files build the right domain objects (imperfections, speeds, loads)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from runout.base.errors import CaseError
from runout.case.model import load_case, parse_case

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"

BASE = {
    "bearing": {
        "elements": 7,
        "element_diameter": "3.9688 mm",
        "pitch_diameter": "15 mm",
        "radial_clearance": "10 um",
    },
    "operation": {"speed": "1800 rpm", "axial_load": "20 N"},
}


def _with(**tables):  # type: ignore[no-untyped-def]
    return parse_case({**BASE, **tables}, "t.toml", Path.cwd())


def test_units_reach_si() -> None:
    case = _with()
    assert case.bearing.element_diameter == pytest.approx(3.9688e-3)
    assert case.bearing.radial_clearance == pytest.approx(10e-6)
    assert case.operation.speed == pytest.approx(30.0)
    assert case.operation.radial_load_direction == pytest.approx(-math.pi / 2)
    assert case.imperfections.is_perfect


def test_peak_to_peak_is_halved_and_phase_in_degrees() -> None:
    case = _with(
        waviness=[{"part": "inner", "order": 8, "peak_to_peak": "20 nm", "phase": "90 deg"}]
    )
    h = case.imperfections.inner
    assert list(h.orders) == [8]
    assert h.amplitudes[0] == pytest.approx(10e-9)
    assert h.phases[0] == pytest.approx(math.pi / 2)


def test_ball_waviness_on_one_element_only() -> None:
    case = _with(waviness=[{"part": "ball", "order": 2, "amplitude": "5 nm", "element": 3}])
    elements = case.imperfections.elements
    assert [len(e) for e in elements] == [0, 0, 1, 0, 0, 0, 0]


def test_spectrum_on_every_ball_gets_independent_seeded_phases() -> None:
    spec = {"part": "ball", "orders": [2, 10], "amplitude": "0.1 um", "exponent": -1.5, "seed": 4}
    a = _with(waviness_spectrum=[spec]).imperfections.elements
    b = _with(waviness_spectrum=[spec]).imperfections.elements
    assert all(np.array_equal(x.phases, y.phases) for x, y in zip(a, b, strict=True))
    assert not np.array_equal(a[0].phases, a[1].phases)
    assert a[0].amplitudes[0] == pytest.approx(0.1e-6 * 2**-1.5)


def test_slant_from_angle_and_element_errors() -> None:
    case = _with(
        slant={"angle": "10 arcsec", "phase": "0 deg"},
        elements={"diameter_errors": ["0.1 um", 0, 0, 0, 0, 0, 0], "pitch_errors": [0] * 7},
    )
    assert case.imperfections.slant is not None
    assert case.imperfections.slant.amplitude > 0
    assert case.imperfections.diameter_errors[0] == pytest.approx(0.1e-6)


def test_measured_profile_is_read_relative_to_the_case_file(tmp_path: Path) -> None:
    angles = np.arange(0, 360, 0.5)
    deviation = 0.2 * np.cos(np.radians(angles) * 5 + 0.3)  # um
    (tmp_path / "outer.csv").write_text(
        "angle_deg,deviation_um\n"
        + "\n".join(f"{a},{d}" for a, d in zip(angles, deviation, strict=True))
    )
    (tmp_path / "case.toml").write_text(
        """
[bearing]
elements = 7
element_diameter = "3.9688 mm"
pitch_diameter = "15 mm"
[[profile]]
part = "outer"
file = "outer.csv"
angle_unit = "deg"
deviation_unit = "um"
orders = [2, 50]
"""
    )
    case = load_case(tmp_path / "case.toml")
    h = case.imperfections.outer
    k = int(np.argmax(h.amplitudes))
    assert h.orders[k] == 5
    assert h.amplitudes[k] == pytest.approx(0.2e-6, rel=1e-9)
    assert h.phases[k] == pytest.approx(0.3, abs=1e-9)


def test_missing_profile_file_names_the_key(tmp_path: Path) -> None:
    with pytest.raises(CaseError) as info:
        _with(profile=[{"part": "inner", "file": str(tmp_path / "nope.csv"), "orders": [1, 9]}])
    assert info.value.key == "profile[1].file"


def test_both_rings_turning() -> None:
    case = _with(
        operation={"rotating_ring": "outer", "speed": "600 rpm", "other_ring_speed": "-5 Hz"}
    )
    assert case.operation.outer_speed == pytest.approx(10.0)
    assert case.operation.inner_speed == pytest.approx(-5.0)


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.toml")), ids=lambda p: p.stem)
def test_examples_load(path: Path) -> None:
    case = load_case(path)
    assert case.bearing.elements >= 3
