"""Ball arrangement (runout.study.arrangement): linear law vs the nonlinear model, optimiser."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout import examples
from runout.study.arrangement import line_amplitudes, optimise_arrangement, verify


@pytest.mark.parametrize("balls", [(1, 2), (1, 4), (1, 2, 3), (1, 3, 5, 7), (1, 2, 4, 5, 8)])
def test_linear_fc_law_matches_nonlinear_model_on_kim_tables(balls: tuple[int, ...]) -> None:
    case = examples.kim().case()
    d = np.zeros(10)
    d[[b - 1 for b in balls]] = 0.1e-6
    linear = line_amplitudes(d).fc
    nonlinear = verify(case, d)["fc_pp_m"]
    assert linear == pytest.approx(nonlinear, rel=0.01)


def test_form_lines_match_nonlinear_model() -> None:
    case = examples.kim().case()
    rng = np.random.default_rng(4)
    form = (10e-9 * rng.random((10, 1))) * np.exp(2j * np.pi * rng.random((10, 1)))
    d = rng.normal(0.0, 0.05e-6, 10)
    lin = line_amplitudes(d, form, [2])
    non = verify(case, d, form, [2])
    assert lin.fc == pytest.approx(non["fc_pp_m"], rel=0.01)
    assert lin.plus[0] == pytest.approx(non["plus_pp_m"][0], rel=0.02)
    assert lin.minus[0] == pytest.approx(non["minus_pp_m"][0], rel=0.02)


@settings(max_examples=30, deadline=None)
@given(
    st.lists(st.floats(-1e-6, 1e-6), min_size=4, max_size=12),
    st.integers(0, 11),
    st.floats(0.1, 10.0),
)
def test_linear_law_rotation_invariant_and_homogeneous(
    errors: list[float], shift: int, factor: float
) -> None:
    d = np.array(errors)
    base = line_amplitudes(d).fc
    assert line_amplitudes(np.roll(d, shift)).fc == pytest.approx(base, rel=1e-9, abs=1e-21)
    assert line_amplitudes(factor * d).fc == pytest.approx(factor * base, rel=1e-9, abs=1e-21)
    assert line_amplitudes(d + 1e-7).fc == pytest.approx(base, rel=1e-6, abs=1e-20)


def test_exact_optimiser_is_the_brute_force_minimum() -> None:
    rng = np.random.default_rng(7)
    lot = rng.normal(0.0, 0.1e-6, 7)
    res = optimise_arrangement(lot, 5, rng=rng)
    assert res.exact
    brute = min(line_amplitudes(lot[list(p)]).fc for p in itertools.permutations(range(7), 5))
    assert res.objective == pytest.approx(brute, rel=1e-12)
    assert res.improvement > 1.0 and res.random_p50 > res.objective


def test_local_search_reaches_the_exact_optimum_on_small_lots() -> None:
    rng = np.random.default_rng(11)
    lot = rng.normal(0.0, 0.1e-6, 9)
    form = 20e-9 * np.exp(2j * np.pi * rng.random((9, 1)))
    exact = optimise_arrangement(lot, 6, form=form, rng=np.random.default_rng(1))
    heur = optimise_arrangement(
        lot, 6, form=form, rng=np.random.default_rng(1), exact_limit=0, restarts=24
    )
    assert exact.exact and not heur.exact
    assert heur.objective <= exact.objective * 1.05


def test_large_lot_improvement_and_nonlinear_check() -> None:
    case = examples.kim().case()
    rng = np.random.default_rng(3)
    lot = rng.normal(0.0, 0.1e-6, 40)
    form = rng.normal(0, 20e-9, (40, 1)) * np.exp(2j * np.pi * rng.random((40, 1)))
    res = optimise_arrangement(lot, 10, form=form, rng=rng, case=case, restarts=8)
    assert not res.exact and len(set(res.balls)) == 10
    assert res.improvement > 10.0
    assert res.verified is not None
    assert res.verified["total_pp_m"] < 0.2 * res.random_mean
