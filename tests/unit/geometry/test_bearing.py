"""Bearing geometry: derived quantities and refusal of impossible geometry."""

from __future__ import annotations

import math

import pytest

from runout import BallBearing, GeometryError, Material, Operation, RollerBearing


def test_harris_derived_geometry() -> None:
    b = BallBearing(10, 1.5875e-3, 9.1e-3, 0.529, 0.535, 5e-6)
    assert b.total_curvature == pytest.approx(0.064)
    assert b.curvature_distance == pytest.approx(0.064 * 1.5875e-3)
    assert b.outer_raceway_diameter - b.inner_raceway_diameter - 2 * b.element_diameter == (
        pytest.approx(5e-6)
    )
    assert 0.5 * (b.inner_raceway_diameter + b.outer_raceway_diameter) == pytest.approx(9.1e-3)
    alpha0 = math.acos(1 - 5e-6 / (2 * 0.064 * 1.5875e-3))
    assert b.free_contact_angle == pytest.approx(alpha0)
    assert b.free_end_play == pytest.approx(2 * 0.064 * 1.5875e-3 * math.sin(alpha0))
    assert b.nominal_contact_angle == pytest.approx(alpha0)


def test_fixed_contact_angle_wins() -> None:
    b = BallBearing(7, 3.9688e-3, 15e-3, radial_clearance=10e-6, contact_angle=0.2)
    assert b.unloaded_contact_angle == 0.2


def test_zero_clearance_gives_zero_free_contact_angle() -> None:
    assert BallBearing(8, 1e-3, 7e-3).free_contact_angle == 0.0


def test_roller_bearing_derives_pitch_and_clearance() -> None:
    r = RollerBearing(14, 10e-3, 54.991e-3, 75.032e-3)
    assert r.pitch_diameter == pytest.approx(65.0115e-3)
    assert r.radial_clearance == pytest.approx(0.041e-3)
    assert r.nominal_contact_angle == 0.0


@pytest.mark.parametrize(
    ("kwargs", "key", "words"),
    [
        ({"elements": 2}, "elements", ">= 3"),
        ({"elements": 7.0}, "elements", "integer"),
        ({"element_diameter": -1e-3}, "element_diameter", "positive"),
        ({"element_diameter": 8e-3}, "element_diameter", "not smaller than the pitch"),
        ({"elements": 30}, "elements", "overlap"),
        ({"inner_conformity": 0.5}, "inner_conformity", "> 0.5"),
        ({"outer_conformity": 0.49}, "outer_conformity", "> 0.5"),
        ({"radial_clearance": -1e-6}, "radial_clearance", "negative"),
        ({"radial_clearance": 1e-3}, "radial_clearance", "grooves"),
        ({"contact_angle": math.radians(95)}, "contact_angle", "[0, 90)"),
    ],
)
def test_impossible_ball_bearing_is_refused(kwargs, key, words) -> None:
    base = {"elements": 8, "element_diameter": 1e-3, "pitch_diameter": 7e-3}
    base.update(kwargs)
    with pytest.raises(GeometryError) as info:
        BallBearing(**base)
    assert info.value.key == key
    assert words in info.value.message


def test_overlap_message_says_how_many_fit() -> None:
    with pytest.raises(GeometryError, match="at most 21 fit"):
        BallBearing(22, 1e-3, 7e-3)


def test_roller_bearing_with_negative_clearance_is_refused() -> None:
    with pytest.raises(GeometryError, match="negative clearance"):
        RollerBearing(14, 10.1e-3, 54.991e-3, 75.032e-3)


@pytest.mark.parametrize(
    ("kwargs", "key"),
    [
        ({"youngs_modulus": 0.0}, "material.youngs_modulus"),
        ({"poisson_ratio": 0.5}, "material.poisson_ratio"),
        ({"density": -1.0}, "material.density"),
    ],
)
def test_bad_material_is_refused(kwargs, key) -> None:
    with pytest.raises(GeometryError) as info:
        Material(**kwargs)
    assert info.value.key == key


def test_material_effective_modulus() -> None:
    m = Material(208e9, 0.3)
    assert m.effective_modulus == pytest.approx(208e9 / 0.91)


def test_operation_ring_speeds() -> None:
    op = Operation("outer", speed=90.0, other_ring_speed=-10.0)
    assert op.outer_speed == 90.0
    assert op.inner_speed == -10.0
    with pytest.raises(GeometryError):
        Operation("cage", speed=1.0)  # type: ignore[arg-type]
    with pytest.raises(GeometryError):
        Operation("inner", axial_load=-1.0)


def test_former_names_work_for_one_release_with_a_warning() -> None:
    """runout 0.1's argument and attribute names still work and say what to write."""
    new = BallBearing(elements=8, element_diameter=1e-3, pitch_diameter=7e-3)
    with pytest.warns(DeprecationWarning) as record:
        old = BallBearing(n_elements=8, ball_diameter=1e-3, pitch_diameter=7e-3)
    assert old == new
    said = " ".join(str(w.message) for w in record)
    assert "write elements=" in said and "write element_diameter=" in said
    with pytest.warns(DeprecationWarning, match=r"read \.element_diameter"):
        assert new.ball_diameter == 1e-3
    with pytest.warns(DeprecationWarning, match="write element_diameter="):
        roller = RollerBearing(
            elements=12,
            roller_diameter=9e-3,
            inner_raceway_diameter=40e-3,
            outer_raceway_diameter=58e-3,
        )
    assert roller.element_diameter == 9e-3
    with pytest.warns(DeprecationWarning, match="write radial_load_direction="):
        op = Operation(radial_load_angle=0.25)
    assert op.radial_load_direction == 0.25
    with pytest.warns(DeprecationWarning, match=r"read \.moment_load_direction"):
        assert op.moment_load_angle == 0.0
    with pytest.raises(TypeError, match="both elements= and its old name n_elements="):
        BallBearing(elements=8, n_elements=8, element_diameter=1e-3, pitch_diameter=7e-3)


def test_a_string_with_a_unit_is_refused_with_the_si_unit_to_write() -> None:
    with pytest.raises(GeometryError) as info:
        Operation(speed="1800 rpm")  # type: ignore[arg-type]
    assert info.value.key == "operation.speed"
    assert "[Hz, revolutions per second]" in info.value.message
    with pytest.raises(GeometryError, match=r"\[N\]"):
        Operation(axial_load="20 N")  # type: ignore[arg-type]
