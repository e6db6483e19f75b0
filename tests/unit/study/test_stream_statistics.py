"""Streaming statistics of a study (issue 31): exact moments and a mergeable quantile sketch.

The sums are exact, so the mean and variance are the same bits for any split and order of the
values (checked against ``fractions.Fraction`` and ``math.fsum``); the percentiles are within
the sketch's relative accuracy of numpy's exact ones and identical for any split and order.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from runout.study._stream import (
    QUANTILE_RELATIVE_ERROR,
    ExactSum,
    StreamStatistics,
    exact_squares,
)

finite = st.floats(allow_nan=False, allow_infinity=False, width=64)
#: Values whose squares and sums stay finite (the squares are summed exactly in any case).
moderate = st.floats(min_value=-1e150, max_value=1e150, allow_nan=False, allow_subnormal=True)
samples = arrays(np.float64, st.integers(1, 300), elements=moderate)


def _streamed(parts: list[np.ndarray]) -> StreamStatistics:
    total = StreamStatistics()
    for part in parts:
        one = StreamStatistics()
        one.add(part)
        total.merge(one)
    return total


def _splits(values: np.ndarray, seed: int) -> list[np.ndarray]:
    rng = np.random.default_rng(seed)
    shuffled = values[rng.permutation(values.size)]
    cuts = np.sort(rng.integers(0, values.size + 1, size=rng.integers(0, 6)))
    return np.split(shuffled, cuts)


@given(arrays(np.float64, st.integers(0, 200), elements=finite))
def test_the_sum_is_exact(values: np.ndarray) -> None:
    exact = ExactSum()
    exact.add(values)
    assert exact.value == sum((Fraction(float(v)) for v in values), Fraction(0))
    try:
        fsum = math.fsum(values.tolist())
    except OverflowError:  # a sum beyond float64: only the exact one holds it
        return
    if math.isfinite(fsum):  # the exact sum rounded once is fsum's correctly rounded sum
        assert float(exact.value) == fsum


@given(arrays(np.float64, st.integers(0, 100), elements=finite))
def test_squares_are_exact(values: np.ndarray) -> None:
    parts, shift = exact_squares(values)
    exact = ExactSum()
    exact.add(parts, shift)
    assert exact.value == sum((Fraction(float(v)) ** 2 for v in values), Fraction(0))


@settings(deadline=None)  # values over 10^300: a sketch of millions of buckets
@given(samples, st.integers(0, 2**32 - 1))
def test_any_split_and_order_gives_the_same_bits(values: np.ndarray, seed: int) -> None:
    whole = _streamed([values])
    split = _streamed(_splits(values, seed))
    assert whole.count == split.count == values.size
    for name in ("mean", "std"):
        a, b = getattr(whole, name)(), getattr(split, name)()
        assert a == b or (math.isnan(a) and math.isnan(b))
    assert whole.minimum == split.minimum == values.min()
    assert whole.maximum == split.maximum == values.max()
    assert whole.summary(7) == split.summary(7)


@settings(deadline=None)
@given(samples)
def test_mean_and_variance_are_the_exact_rationals_rounded_once(values: np.ndarray) -> None:
    stats = _streamed([values])
    exact = [Fraction(float(v)) for v in values]
    n = len(exact)
    mean = sum(exact, Fraction(0)) / n
    assert stats.mean() == float(mean)
    if n > 1:
        variance = sum(((x - mean) ** 2 for x in exact), Fraction(0)) / (n - 1)
        assert stats.std() == math.sqrt(float(variance))


@settings(max_examples=60, deadline=None)
@given(
    arrays(
        np.float64,
        st.integers(1, 400),
        elements=st.one_of(
            st.floats(1e-9, 1e-5), st.floats(-1e3, -1e-3), st.just(0.0), st.floats(0.5, 2.0)
        ),
    ),
    st.integers(0, 2**32 - 1),
)
def test_percentiles_are_within_the_relative_accuracy(values: np.ndarray, seed: int) -> None:
    stats = _streamed(_splits(values, seed))
    qs = (5.0, 50.0, 95.0)
    got = stats.percentiles(qs)
    # numpy's linear interpolation between the order statistics k and k + 1: each one the
    # sketch gives within alpha, so their convex combination is within alpha of the same
    # combination of the exact ones (in absolute terms of the larger of the two)
    ordered = np.sort(values)
    n = values.size
    for q, value in zip(qs, got, strict=True):
        h = (n - 1) * q / 100.0
        k = math.floor(h)
        lo, hi = ordered[k], ordered[min(k + 1, n - 1)]
        bound = QUANTILE_RELATIVE_ERROR * (1 + 1e-9) * max(abs(lo), abs(hi))
        assert abs(value - np.percentile(values, q)) <= bound + 1e-300, (q, value)


@settings(deadline=None)
@given(samples, st.integers(1, 30))
def test_histograms_count_every_value_once(values: np.ndarray, bins: int) -> None:
    summary = _streamed([values]).summary(bins)
    counts = summary["histogram"]["counts"]
    assert sum(counts) == values.size
    edges = summary["histogram"]["edges"]
    assert edges[0] <= values.min() and values.max() <= edges[-1]


def test_zeros_added_at_the_end_are_the_zeros_of_the_samples() -> None:
    values = np.array([3e-7, 1e-7, 2e-7])
    late = StreamStatistics()
    late.add(values)
    late.add_zeros(2)
    direct = StreamStatistics()
    direct.add(np.concatenate([values, [0.0, 0.0]]))
    assert late.summary(5) == direct.summary(5)


def test_no_value_gives_no_statistics() -> None:
    summary = StreamStatistics().summary(5)
    assert math.isnan(summary["mean"]) and summary["histogram"] == {"edges": [], "counts": []}
