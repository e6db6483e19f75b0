"""Decimated plotting: the envelope keeps every run's extremes, the orbit every cell crossed."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from runout.report.plotting import envelope_indices, orbit_indices

finite = st.floats(-1e6, 1e6, allow_nan=False)


def _envelope_reference(values: np.ndarray, columns: int) -> set[float]:
    """The min and max of each run of ceil(n / columns) samples, by a plain loop."""
    run = -(-values.size // columns)
    out: set[float] = set()
    for i0 in range(0, values.size, run):
        out |= {float(values[i0 : i0 + run].min()), float(values[i0 : i0 + run].max())}
    return out


@settings(max_examples=80, deadline=None)
@given(values=arrays(np.float64, st.integers(1, 600), elements=finite), columns=st.integers(1, 50))
def test_envelope_keeps_each_runs_extremes(values: np.ndarray, columns: int) -> None:
    idx = envelope_indices(values, columns)
    assert np.all(np.diff(idx) > 0) and idx[0] == 0 and idx[-1] == values.size - 1
    assert idx.size <= max(values.size, 2 * columns + 2)
    assert _envelope_reference(values, columns) <= set(values[idx].tolist())


def test_short_records_are_drawn_whole() -> None:
    v = np.sin(np.arange(100.0))
    assert np.array_equal(envelope_indices(v, 50), np.arange(100))
    assert np.array_equal(orbit_indices(v, v, 50), np.arange(100))


@settings(max_examples=60, deadline=None)
@given(
    xy=arrays(np.float64, st.tuples(st.just(2), st.integers(30, 400)), elements=finite),
    cells=st.integers(2, 12),
)
def test_orbit_drops_only_instants_in_the_cell_just_drawn(xy: np.ndarray, cells: int) -> None:
    x, y = xy
    idx = orbit_indices(x, y, cells)
    assert np.all(np.diff(idx) > 0) and idx[0] == 0 and idx[-1] == x.size - 1
    if x.size <= 2 * cells:
        return
    span = max(np.ptp(x), np.ptp(y), 1e-300)
    cell = np.stack(
        [((x - x.min()) * (cells / span)).astype(int), ((y - y.min()) * (cells / span)).astype(int)]
    )
    kept = np.zeros(x.size, bool)
    kept[idx] = True
    for i in range(1, x.size - 1):  # a dropped instant lies in the cell of the one before it
        if not kept[i]:
            assert np.array_equal(cell[:, i], cell[:, i - 1])


def test_orbit_indices_are_sorted_unique_and_end_on_the_last_instant() -> None:
    """Built without np.unique (its sort dominated): the same indices as the set of moves."""
    t = np.linspace(0.0, 200.0, 50_000)
    x, y = np.cos(t) + 0.1 * np.cos(7.3 * t), np.sin(t) + 0.1 * np.sin(5.1 * t)
    for cells in (500, 50, 3):
        keep = orbit_indices(x, y, cells)
        scale = cells / max(np.ptp(x), np.ptp(y))
        cx = ((x - x.min()) * scale).astype(np.int64)
        cy = ((y - y.min()) * scale).astype(np.int64)
        moved = np.flatnonzero((cx[1:] != cx[:-1]) | (cy[1:] != cy[:-1])) + 1
        assert np.array_equal(keep, np.unique(np.concatenate([[0], moved, [x.size - 1]])))
    still = np.zeros(5000)
    still[-1] = 1.0  # the last instant is a move: kept once
    keep = orbit_indices(still, np.zeros(5000), 10)
    assert keep.tolist() == [0, 4999]
