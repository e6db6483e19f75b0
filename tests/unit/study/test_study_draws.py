"""The Monte Carlo draws of sampling version 2 (issue 31): one counter-based stream per study,
a block of samples in one call, sample i's numbers fixed by (seed, i) alone."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.study._plan import Quantity, draw_block, draw_width, sample_uniforms
from runout.study._workers import worker_threads


@settings(max_examples=40, deadline=None)
@given(
    seed=st.integers(0, 2**63),
    total=st.integers(1, 60),
    cut=st.integers(0, 60),
    width=st.sampled_from([4, 8, 12, 20]),
)
def test_a_block_is_the_rows_of_the_whole_stream(
    seed: int, total: int, cut: int, width: int
) -> None:
    """Samples drawn in two chunks are the samples drawn in one, word for word."""
    cut = min(cut, total)
    whole = sample_uniforms(seed, 0, total, width)
    parts = np.concatenate(
        [sample_uniforms(seed, 0, cut, width), sample_uniforms(seed, cut, total, width)]
    )
    assert whole.tobytes() == parts.tobytes()
    assert whole.shape == (total, width)
    assert np.all((whole > 0.0) & (whole < 1.0))


def test_seeds_and_samples_give_different_words() -> None:
    a, b = sample_uniforms(1, 0, 2, 4), sample_uniforms(2, 0, 2, 4)
    assert not np.any(a == b) and not np.any(a[0] == a[1])


def test_width_is_whole_blocks_and_refused_otherwise() -> None:
    q = Quantity("element_diameter_sigma", ("elements", None, "diameter_errors"), 10, "normal")
    assert draw_width([q]) == 12 and draw_width([]) == 4
    with pytest.raises(ValueError, match="multiple of 4"):
        sample_uniforms(1, 0, 1, 10)


def test_drawn_distributions_have_their_moments() -> None:
    """2x10^5 values per distribution: mean and spread within 5 standard errors of the
    distribution's own (a test that a wrong transform fails by hundreds of errors)."""
    n = 200_000
    normal = Quantity("a", ("operation", None, "axial_load"), 1, "normal", np.array([3.0]), (2.0,))
    uniform = Quantity("b", ("operation", None, "radial_load"), 1, "uniform", spread=(1.0, 5.0))
    pool = Quantity("c", ("bearing", None, "radial_clearance"), 1, "sample", values=(1.0, 2.0, 4.0))
    drawn = draw_block([normal, uniform, pool], 11, 0, n)
    a, b, c = drawn["a"], drawn["b"], drawn["c"]
    assert a.shape == b.shape == c.shape == (n,)
    se = 2.0 / math.sqrt(n)
    assert abs(a.mean() - 3.0) < 5 * se and abs(a.std() - 2.0) < 5 * se / math.sqrt(2.0)
    assert abs(b.mean() - 3.0) < 5 * (4.0 / math.sqrt(12.0)) / math.sqrt(n)
    assert b.min() >= 1.0 and b.max() < 5.0
    counts = np.array([np.sum(c == v) for v in (1.0, 2.0, 4.0)]) / n
    assert np.all(np.abs(counts - 1 / 3) < 5 * math.sqrt(2 / 9 / n))
    # the three quantities use different words of the sample: uncorrelated
    assert abs(np.corrcoef(a, b)[0, 1]) < 5 / math.sqrt(n)


def test_a_per_element_draw_is_one_row_per_sample() -> None:
    mean = np.linspace(0.0, 1e-7, 10)
    q = Quantity(
        "element_diameter_sigma", ("elements", None, "diameter_errors"), 10, "normal", mean, (1e-7,)
    )
    block = draw_block([q], 5, 3, 9)["element_diameter_sigma"]
    assert block.shape == (6, 10)
    one = draw_block([q], 5, 4, 5)["element_diameter_sigma"]
    assert one.tobytes() == block[1:2].tobytes()


@pytest.mark.parametrize(
    ("workers", "cores", "threads"), [(1, 2, 2), (2, 2, 1), (3, 2, 1), (4, 16, 4), (16, 16, 1)]
)
def test_worker_threads_never_oversubscribe(workers: int, cores: int, threads: int) -> None:
    import numba

    expected = min(threads, numba.config.NUMBA_NUM_THREADS)
    assert worker_threads(workers, cores) == expected
    assert workers * worker_threads(workers, cores) <= max(cores, workers)
