"""The compiled "%.12g" CSV formatter against Python's own formatting (the reference)."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from runout.base._csvfmt import format_rows


def _python(block: np.ndarray) -> bytes:
    rows = block.tolist()
    return "".join(",".join(f"{v:.12g}" for v in row) + "\r\n" for row in rows).encode()


@settings(max_examples=200, deadline=None)
@given(block=arrays(np.float64, st.tuples(st.integers(0, 40), st.integers(1, 5))))
def test_any_float_formats_as_python_does(block: np.ndarray) -> None:
    assert format_rows(block) == _python(block)


def test_boundaries_ties_and_extremes() -> None:
    rng = np.random.default_rng(5)
    special = [0.0, -0.0, np.inf, -np.inf, np.nan, 1e-5, 1e-4, 123456789012.5, 999999999999.5]
    special += [9999999999995.0, 1e12, 1e11, 1e22, 1e23, 5e-324, 1.7976931348623157e308, 0.5]
    special += [2.5, 1234567890125.0, 0.1, 1 / 3, -2 / 3, 99999.99999995, 0.000999999999999]
    p10 = 10.0 ** np.arange(-30, 31)
    blocks = [
        np.array(special)[:, None],
        np.concatenate([p10, np.nextafter(p10, 0), np.nextafter(p10, np.inf), -p10])[:, None],
        rng.normal(size=(5000, 4)) * 10.0 ** rng.integers(-30, 30, size=(5000, 4)),
        np.ldexp(rng.uniform(0.5, 1, (5000, 3)), rng.integers(-1074, 1024, (5000, 3))),
        # 13-digit decimals ending in 5: the digit rule's near-ties
        rng.integers(10**12, 10**13, (5000, 2)) * 5 / 10.0 ** rng.integers(0, 20, (5000, 2)),
        np.arange(20000.0).reshape(-1, 2) * 1.2345e-5,
    ]
    for block in blocks:
        assert format_rows(block) == _python(block)
