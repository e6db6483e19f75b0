"""The Hann window written in NumPy is scipy.signal's, to the bit (no scipy.signal import)."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.signal

from runout.analysis.spectrum import _window


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5, 7, 8, 64, 1000, 4097, 65536])
@pytest.mark.parametrize("name", ["hann", "hanning", "boxcar", "rect", "none"])
def test_window_identical_to_scipy(n: int, name: str) -> None:
    spec = {"hanning": "hann", "rect": "boxcar", "none": "boxcar"}.get(name, name)
    ref = scipy.signal.get_window(spec, n, fftbins=True)
    ours = _window(name, n)
    assert ours.dtype == np.float64
    assert ours.shape == (n,)
    assert np.array_equal(ours, ref)


def test_other_windows_still_from_scipy() -> None:
    assert np.array_equal(_window("hamming", 16), scipy.signal.get_window("hamming", 16))
    with pytest.raises(ValueError, match="unknown window"):
        _window("no-such-window", 16)
