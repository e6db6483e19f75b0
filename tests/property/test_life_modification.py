"""Hypothesis: invariants of ISO 281's life modification factors (runout.geometry.life).

a_ISO of a radial ball bearing rises with the viscosity ratio κ (within each of the standard's
three κ ranges, and not at all beyond κ = 4), with the contamination factor e_C and the fatigue
load limit C_u, falls with the load P, and stays within [0.1, 50]. Its constants leave a step
at κ = 0.4, where the two ranges' (2.5671 − c_1 κ^−c_2) differ by 7e-5: pinned below, so that
a change of constants shows. The a_1 table is the Weibull relation behind it,
a_1 = 0.95 (ln(100/R) / ln(100/90))^(2/3) + 0.05, rounded.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.base.errors import GeometryError
from runout.geometry.life import (
    A_ISO_CAP,
    RELIABILITY_FACTORS,
    life_modification_factor,
    reliability_factor,
)

#: The standard's κ ranges: a_ISO is monotone within each.
RANGES = [(0.1, 0.4), (0.4, 1.0), (1.0, 4.0)]
fraction = st.floats(0.0, 1.0)
limit = st.floats(0.0, 1e5)
load = st.floats(1.0, 1e6)


def _kappa_pair(draw: st.DrawFn) -> tuple[float, float]:
    low, high = draw(st.sampled_from(RANGES))
    a = draw(st.floats(low, high, exclude_max=high != 4.0))
    b = draw(st.floats(low, high, exclude_max=high != 4.0))
    return min(a, b), max(a, b)


kappa_pairs = st.composite(_kappa_pair)()


@settings(max_examples=200, deadline=None)
@given(kappa_pairs, fraction, limit, load)
def test_a_iso_rises_with_kappa_within_a_range(
    kappas: tuple[float, float], e_c: float, c_u: float, p: float
) -> None:
    lo, hi = kappas
    assert life_modification_factor(lo, e_c, c_u, p) <= life_modification_factor(hi, e_c, c_u, p)


@settings(max_examples=200, deadline=None)
@given(st.floats(0.1, 10.0), fraction, fraction, limit, load)
def test_a_iso_rises_with_contamination_factor(
    kappa: float, e1: float, e2: float, c_u: float, p: float
) -> None:
    lo, hi = sorted((e1, e2))
    a_lo = life_modification_factor(kappa, lo, c_u, p)
    assert a_lo <= life_modification_factor(kappa, hi, c_u, p)
    assert 0.1 <= a_lo <= A_ISO_CAP


@settings(max_examples=200, deadline=None)
@given(st.floats(0.1, 10.0), fraction, limit, load, load)
def test_a_iso_falls_with_the_load(
    kappa: float, e_c: float, c_u: float, p1: float, p2: float
) -> None:
    lo, hi = sorted((p1, p2))
    assert life_modification_factor(kappa, e_c, c_u, hi) <= life_modification_factor(
        kappa, e_c, c_u, lo
    )


@settings(max_examples=100, deadline=None)
@given(st.floats(4.0, 1e3), fraction, limit, load)
def test_kappa_beyond_4_is_4(kappa: float, e_c: float, c_u: float, p: float) -> None:
    assert life_modification_factor(kappa, e_c, c_u, p) == life_modification_factor(
        4.0, e_c, c_u, p
    )


def test_cap_bounds_and_the_clean_unloaded_limit() -> None:
    # a clean, lightly loaded bearing reaches the cap; nothing exceeds it
    assert life_modification_factor(4.0, 1.0, 1e4, 1e3) == A_ISO_CAP
    assert life_modification_factor(0.1, 0.0, 1e4, 1e3) == pytest.approx(0.1, rel=1e-15)
    # just below the cap the formula itself, continuous into the cap
    below = life_modification_factor(1.0, 1.0, 1.0, 1.0 / 0.2)
    assert 0.1 < below < A_ISO_CAP


def test_the_step_of_the_standards_constants_at_kappa_0_4() -> None:
    left = 2.5671 - 2.2649 * 0.4**-0.054381
    right = 2.5671 - 1.9987 * 0.4**-0.19087
    assert left - right == pytest.approx(7.1e-5, abs=0.2e-5)
    # a_ISO drops across it by a few 1e-4 relative at a mid-range load ratio
    just_below = life_modification_factor(math.nextafter(0.4, 0.0), 0.5, 1e3, 2e3)
    at = life_modification_factor(0.4, 0.5, 1e3, 2e3)
    assert 0.0 < 1.0 - at / just_below < 1e-3


@pytest.mark.parametrize(
    ("args", "key"),
    [
        ((0.09, 0.5, 1e3, 1e3), "lubrication.viscosity_ratio"),
        ((1.0, 1.1, 1e3, 1e3), "lubrication.contamination_factor"),
        ((1.0, 0.5, -1.0, 1e3), "bearing.fatigue_load_limit"),
        ((1.0, 0.5, 1e3, 0.0), "load"),
        ((math.nan, 0.5, 1e3, 1e3), "viscosity_ratio"),
    ],
)
def test_outside_its_domain_a_iso_is_refused(args: tuple[float, ...], key: str) -> None:
    with pytest.raises(GeometryError) as err:
        life_modification_factor(*args)
    assert err.value.key == key


@pytest.mark.parametrize("reliability", list(RELIABILITY_FACTORS))
def test_a1_table_is_the_weibull_relation_rounded(reliability: float) -> None:
    weibull = 0.95 * (math.log(100.0 / reliability) / math.log(100.0 / 90.0)) ** (2.0 / 3.0) + 0.05
    assert reliability_factor(reliability) == pytest.approx(weibull, abs=0.005)


def test_a1_falls_with_reliability_and_refuses_other_rows() -> None:
    factors = [reliability_factor(r) for r in sorted(RELIABILITY_FACTORS)]
    assert factors == sorted(factors, reverse=True)
    assert factors[0] == 1.0
    with pytest.raises(GeometryError):
        reliability_factor(93.0)
