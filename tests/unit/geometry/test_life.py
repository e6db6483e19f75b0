"""ISO/TS 16281 reference rating life of a ball bearing (runout.geometry.life).

The TS's contact ratings carry Lundberg and Palmgren's 0.407 and 0.389: the ratios of the
radial load to Z times the cubic and the 10/3-power mean ball load of a radially loaded bearing
with half its balls loaded (ε = 0.5). Under that very load distribution the TS's life must
therefore be ISO 281's (C / F_r)^3, a check independent of the MASTA values
(tests/reference/test_iso_ts_16281_life.py); the rest are the TS's definitions and refusals.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from runout.base.errors import GeometryError
from runout.geometry.life import (
    RatingLife,
    contact_load_ratings,
    equivalent_element_loads,
    reference_rating_life,
)

SUITE = {
    "elements": 7,
    "element_diameter": 11.5e-3,
    "pitch_diameter": 43.5e-3,
    "inner_conformity": 0.52,
    "outer_conformity": 0.53,
    "nominal_contact_angle": 0.0,
    "dynamic_load_rating": 23400.0,
}


def _life(inner: np.ndarray, outer: np.ndarray | None = None, **keys: object) -> RatingLife:
    args: dict = SUITE | {"elements": inner.size} | keys
    return reference_rating_life(
        **args, inner_loads=inner, outer_loads=inner if outer is None else outer
    )


def test_half_loaded_bearing_gives_iso_281_life() -> None:
    # ε = 0.5: Q(ψ) = Q_max cos^1.5 ψ over the loaded half, many balls (the integrals of
    # Lundberg-Palmgren); F_r = Σ Q cos ψ, and L10r = (C / F_r)^3 (ISO 281, α = 0)
    z = 4000
    psi = 2 * np.pi * np.arange(z) / z
    q = 100.0 * np.clip(np.cos(psi), 0.0, None) ** 1.5
    radial = float(np.sum(q * np.cos(psi)))
    life = _life(q)
    # 0.407 and 0.389 are printed to 3 digits (J_r/J_1 = 0.4068, J_r/J_2 = 0.3889): 0.2 %
    assert life.l10r_mrev == pytest.approx((23400.0 / radial) ** 3, rel=2e-3)


def test_equal_ball_loads_give_each_ring_its_rating_ratio_cubed() -> None:
    q = np.full(7, 800.0)
    life = _life(q)
    q_ci, q_ce = contact_load_ratings(7, 11.5e-3, 43.5e-3, 0.52, 0.53, 0.0, 23400.0)
    assert life.equivalent_inner_load_n == pytest.approx(800.0, rel=1e-14)
    assert life.equivalent_outer_load_n == pytest.approx(800.0, rel=1e-14)
    assert life.l10r_inner_mrev == pytest.approx((q_ci / 800.0) ** 3, rel=1e-12)
    assert life.l10r_outer_mrev == pytest.approx((q_ce / 800.0) ** 3, rel=1e-12)
    # the outer ring's conforming contact is rated higher than the inner one's
    assert q_ce > q_ci


def test_the_turning_ring_takes_the_cubic_mean() -> None:
    q_i = np.array([900.0, 400.0, 0.0, 0.0, 100.0, 300.0, 700.0])
    q_o = q_i + 5.0
    cubic = lambda q: float(np.mean(q**3)) ** (1 / 3)  # noqa: E731
    tenth = lambda q: float(np.mean(q ** (10 / 3))) ** 0.3  # noqa: E731
    assert equivalent_element_loads(q_i, q_o, "inner") == pytest.approx(
        (cubic(q_i), tenth(q_o)), rel=1e-14
    )
    assert equivalent_element_loads(q_i, q_o, "outer") == pytest.approx(
        (tenth(q_i), cubic(q_o)), rel=1e-14
    )


def test_an_unloaded_raceway_has_no_life_of_its_own() -> None:
    life = _life(np.zeros(7), np.full(7, 10.0))
    assert life.l10r_inner_mrev is None
    assert life.l10r_mrev == pytest.approx(life.l10r_outer_mrev, rel=1e-12)


def test_tiny_loads_stay_finite_or_say_none() -> None:
    # 1e-3 N on a 23.4 kN rating: 1e22 million revolutions, finite
    assert _life(np.full(7, 1e-3)).l10r_mrev == pytest.approx(
        _life(np.full(7, 1.0)).l10r_mrev * 1e9, rel=1e-12
    )
    # beyond the floating-point range: None, never inf or NaN
    far = _life(np.full(7, 1e-200))
    assert far.l10r_mrev is None and far.equivalent_reference_load_n is None
    assert all(
        v is None or (isinstance(v, str) or math.isfinite(v)) for v in far.to_json().values()
    )


def test_hours_at_the_relative_speed() -> None:
    life = _life(np.full(7, 800.0), relative_speed=25.0)  # 1500 rpm
    assert life.l10r_hours == pytest.approx(life.l10r_mrev * 1e6 / (25.0 * 3600.0), rel=1e-14)


def test_json_round_trip() -> None:
    life = _life(np.full(7, 800.0), relative_speed=10.0)
    assert RatingLife.from_json(life.to_json()) == life


@pytest.mark.parametrize(
    ("keys", "key"),
    [
        ({"nominal_contact_angle": math.radians(50.0)}, "bearing.nominal_contact_angle"),
        ({"dynamic_load_rating": 0.0}, "bearing.dynamic_load_rating"),
        ({"dynamic_load_rating": math.inf}, "bearing.dynamic_load_rating"),
    ],
)
def test_refusals_name_the_key(keys: dict, key: str) -> None:
    with pytest.raises(GeometryError) as info:
        _life(np.full(7, 800.0), **keys)
    assert info.value.key == key


def test_negative_or_missing_loads_are_refused() -> None:
    with pytest.raises(GeometryError):
        _life(np.array([1.0, -1.0, 1.0]))
    with pytest.raises(GeometryError):
        _life(np.array([1.0, math.nan, 1.0]))
    with pytest.raises(GeometryError):
        _life(np.zeros(7))


def test_iso_281_rating_branches_meet_at_one_inch_and_refuse_outside_table_2() -> None:
    from runout.base.errors import GeometryError
    from runout.geometry.life import basic_dynamic_load_rating

    # ISO 281's 3.647 D_w^1.4 above 25.4 mm continues D_w^1.8: 3.647 = 25.4^0.4 to 0.06 %
    below = basic_dynamic_load_rating(12, 25.4e-3, 200e-3)
    above = basic_dynamic_load_rating(12, 25.4e-3 * (1 + 1e-12), 200e-3)
    assert above == pytest.approx(below, rel=1e-3)
    # a row of Table 2 exactly: D_w / D_pw = 0.1 -> f_c = 55.5
    assert basic_dynamic_load_rating(10, 10e-3, 100e-3) == pytest.approx(
        1.3 * 55.5 * 10 ** (2 / 3) * 10**1.8, rel=1e-12
    )
    # the contact angle enters as (cos a)^0.7 and through f_c at D_w cos a / D_pw
    angled = basic_dynamic_load_rating(10, 10e-3, 100e-3, math.acos(0.5))
    f_c = 46.7  # Table 2 at 0.05
    assert angled == pytest.approx(1.3 * f_c * 0.5**0.7 * 10 ** (2 / 3) * 10**1.8, rel=1e-12)
    with pytest.raises(GeometryError, match="outside ISO 281's f_c table"):
        basic_dynamic_load_rating(10, 45e-3, 100e-3)
