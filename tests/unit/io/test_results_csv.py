"""write_columns writes the bytes csv.writer wrote with f"{v:.12g}" per value."""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from runout.io import result_files
from runout.io.result_files import write_columns


def _reference(path: Path, header: list[str], columns: list[np.ndarray]) -> None:
    """The former row-by-row writer of history.csv."""
    with path.open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(header)
        for row in zip(*columns, strict=True):
            w.writerow([f"{v:.12g}" for v in row])


floats = st.floats(allow_nan=False, allow_infinity=False, width=64)


@settings(max_examples=60, deadline=None)
@given(data=arrays(np.float64, st.tuples(st.just(4), st.integers(0, 300)), elements=floats))
def test_same_bytes_as_csv_writer(tmp_path_factory, data: np.ndarray) -> None:
    d = tmp_path_factory.mktemp("csv")
    header = ["time_s", "x_m", "y_m", "z_m"]
    cols = list(data)
    _reference(d / "a.csv", header, cols)
    write_columns(d / "b.csv", header, cols)
    assert (d / "a.csv").read_bytes() == (d / "b.csv").read_bytes()


def test_chunks_and_special_values(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setattr(result_files, "_CSV_CHUNK", 7)  # several chunks, a partial last one
    rng = np.random.default_rng(1)
    cols = [np.arange(50) * 1e-5, rng.normal(size=50) * 1e-8, np.zeros(50), -np.zeros(50)]
    cols[1][3] = np.inf
    cols[1][4] = np.nan
    cols[2][5] = 1e300
    cols[2][6] = 5e-324
    _reference(tmp_path / "a.csv", ["t", "x", "y", "z"], cols)
    write_columns(tmp_path / "b.csv", ["t", "x", "y", "z"], cols)
    assert (tmp_path / "a.csv").read_bytes() == (tmp_path / "b.csv").read_bytes()


any_floats = st.floats(width=64)  # NaN, inf and -0.0 included


@settings(max_examples=60, deadline=None)
@given(
    data=arrays(np.float64, st.tuples(st.integers(0, 40), st.integers(1, 5)), elements=any_floats)
)
def test_python_formatting_gives_the_compiled_bytes(data: np.ndarray) -> None:
    """The two formatters of ``write_columns`` (Python for a short record written before numba
    is loaded, compiled otherwise) write the same bytes."""
    from runout.base._csvfmt import format_rows

    assert result_files._format_rows_python(data) == format_rows(data)


def test_a_short_record_without_numba_is_formatted_by_python(tmp_path: Path, monkeypatch) -> None:
    import sys

    calls = []
    python = result_files._format_rows_python
    monkeypatch.setattr(
        result_files, "_format_rows_python", lambda b: calls.append(b.shape) or python(b)
    )
    monkeypatch.delitem(sys.modules, "numba", raising=False)
    cols = [np.arange(10) * 1e-3, np.full(10, -2.5e-9)]
    write_columns(tmp_path / "a.csv", ["time_s", "x_m"], cols)
    _reference(tmp_path / "b.csv", ["time_s", "x_m"], cols)
    assert calls == [(10, 2)]
    assert (tmp_path / "a.csv").read_bytes() == (tmp_path / "b.csv").read_bytes()
