"""Stiffness-proportional bearing damping, c = β k (E. Krämer, Dynamics of Rotors and
Foundations, Springer, 1993)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from runout.geometry.bearing_damping import (
    KRAEMER_COEFFICIENT_S,
    KRAEMER_RANGE_S,
    MAX_DAMPING_COEFFICIENT_S,
    damping_coefficient,
    proportional_damping,
)


def test_kraemer_default_is_inside_his_range_near_its_log_middle() -> None:
    low, high = KRAEMER_RANGE_S
    assert (low, high) == (0.25e-5, 2.5e-5)
    assert low < KRAEMER_COEFFICIENT_S < high
    # the geometric mean, rounded to two digits
    assert KRAEMER_COEFFICIENT_S == pytest.approx(math.sqrt(low * high), rel=0.01)
    assert damping_coefficient("kraemer", None) == KRAEMER_COEFFICIENT_S
    assert damping_coefficient("none", None) == 0.0
    assert damping_coefficient("proportional", 2e-5) == 2e-5


@pytest.mark.parametrize("beta", [None, -1e-9, math.nan, math.inf, 2 * MAX_DAMPING_COEFFICIENT_S])
def test_proportional_needs_a_bounded_coefficient(beta: float | None) -> None:
    with pytest.raises(ValueError, match="proportional damping needs a coefficient"):
        damping_coefficient("proportional", beta)


def test_unknown_model_is_refused() -> None:
    with pytest.raises(ValueError, match="unknown bearing damping model"):
        damping_coefficient("viscous", None)


finite = st.floats(-1e12, 1e12, allow_nan=False)


@given(st.lists(finite, min_size=1, max_size=8), st.floats(0.0, MAX_DAMPING_COEFFICIENT_S))
def test_every_coefficient_is_damped_in_proportion(k: list[float], beta: float) -> None:
    c = proportional_damping(k, beta)
    assert c.shape == (len(k),)
    np.testing.assert_array_equal(c, [beta * v for v in k])  # one product each: no round-off
    assert np.all(c * np.asarray(k) >= 0.0)  # never a sign K does not have
