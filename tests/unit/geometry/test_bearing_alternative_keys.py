"""BallBearing takes the case file's alternative keys, with the case file's meaning.

A ``[bearing]`` table may give groove radii instead of conformities and the nominal (free)
contact angle instead of the clearance; Python names equal case keys, so the constructor takes
them too, and ``bearing.nominal_contact_angle`` reads back what the key means (α⁰), not the
fixed operating angle.
"""

from __future__ import annotations

import math
import tomllib

import pytest

from runout import BallBearing
from runout.base.errors import GeometryError
from runout.case.model import parse_case

D = 1.5875e-3
BASE = {"elements": 10, "element_diameter": D, "pitch_diameter": 9.1e-3}


def _case_bearing(table: str) -> BallBearing:
    text = (
        '[bearing]\ntype = "ball"\nelements = 10\nelement_diameter = "1.5875 mm"\n'
        f'pitch_diameter = "9.1 mm"\n{table}\n[operation]\nspeed = "7200 rpm"\n'
    )
    bearing = parse_case(tomllib.loads(text), "alt.toml").bearing
    assert isinstance(bearing, BallBearing)
    return bearing


def test_groove_radii_give_the_conformities_as_in_a_case_file() -> None:
    bearing = BallBearing(**BASE, inner_groove_radius=0.529 * D, outer_groove_radius=0.535 * D)
    assert bearing.inner_conformity == pytest.approx(0.529, rel=1e-15)
    assert bearing.outer_conformity == pytest.approx(0.535, rel=1e-15)
    case = _case_bearing(
        f'inner_groove_radius = "{0.529 * D * 1e3!r} mm"\n'
        f'outer_groove_radius = "{0.535 * D * 1e3!r} mm"'
    )
    assert case.inner_conformity == pytest.approx(bearing.inner_conformity, rel=1e-12)
    assert case.outer_conformity == pytest.approx(bearing.outer_conformity, rel=1e-12)


def test_nominal_contact_angle_gives_the_clearance_as_in_a_case_file() -> None:
    bearing = BallBearing(
        **BASE, inner_conformity=0.529, outer_conformity=0.535, nominal_contact_angle=0.25
    )
    a = (0.529 + 0.535 - 1.0) * D
    assert bearing.radial_clearance == pytest.approx(2.0 * a * (1.0 - math.cos(0.25)), rel=1e-14)
    assert bearing.nominal_contact_angle == pytest.approx(0.25, rel=1e-12)
    case = _case_bearing(
        'inner_conformity = 0.529\nouter_conformity = 0.535\nnominal_contact_angle = "0.25 rad"'
    )
    assert case.radial_clearance == pytest.approx(bearing.radial_clearance, rel=1e-14)


def test_positional_arguments_and_the_angle_together() -> None:
    bearing = BallBearing(10, D, 9.1e-3, 0.52, 0.53, nominal_contact_angle=0.2)
    assert (bearing.elements, bearing.inner_conformity, bearing.outer_conformity) == (
        10,
        0.52,
        0.53,
    )
    a = (0.52 + 0.53 - 1.0) * D
    assert bearing.radial_clearance == pytest.approx(2.0 * a * (1.0 - math.cos(0.2)), rel=1e-14)


def test_nominal_angle_is_not_the_fixed_operating_angle() -> None:
    """A fixed contact angle (seed 000) is the operating angle; α⁰ stays the clearance's."""
    bearing = BallBearing(**BASE, radial_clearance=5e-6, contact_angle=0.3)
    assert bearing.nominal_contact_angle == pytest.approx(bearing.free_contact_angle)
    assert bearing.nominal_contact_angle != pytest.approx(0.3)
    assert bearing.unloaded_contact_angle == 0.3
    free = BallBearing(**BASE, radial_clearance=5e-6)
    assert free.unloaded_contact_angle == free.free_contact_angle


@pytest.mark.parametrize(
    ("extra", "key", "words"),
    [
        (
            {"inner_conformity": 0.52, "inner_groove_radius": 0.52 * D},
            "inner_groove_radius",
            "not both",
        ),
        (
            {"outer_conformity": 0.53, "outer_groove_radius": 0.53 * D},
            "outer_groove_radius",
            "not both",
        ),
        (
            {"radial_clearance": 20e-6, "nominal_contact_angle": 0.2},
            "radial_clearance",
            "disagrees with nominal_contact_angle",
        ),
        ({"nominal_contact_angle": 2.0}, "nominal_contact_angle", "[0, 90) deg"),
        ({"nominal_contact_angle": "15 deg"}, "nominal_contact_angle", "must be a number"),
        ({"inner_groove_radius": -1e-3}, "inner_groove_radius", "positive"),
    ],
)
def test_contradictions_are_refused_naming_the_key(
    extra: dict[str, object], key: str, words: str
) -> None:
    with pytest.raises(GeometryError) as info:
        BallBearing(**BASE, **extra)  # type: ignore[arg-type]
    assert info.value.key == key
    assert words in str(info.value)


def test_a_clearance_that_agrees_with_the_angle_is_accepted() -> None:
    clearance = 2.0 * 0.05 * D * (1.0 - math.cos(0.2))
    bearing = BallBearing(**BASE, radial_clearance=clearance * 1.0005, nominal_contact_angle=0.2)
    assert bearing.radial_clearance == pytest.approx(clearance, rel=1e-14)
