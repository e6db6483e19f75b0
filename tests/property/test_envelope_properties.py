"""Invariants of the envelope analysis (:mod:`runout.analysis.envelope`).

* the squared envelope of an amplitude-modulated tone A (1 + m cos 2 pi f_m t) cos 2 pi f_c t is
  A^2 (1 + m^2/2 + 2 m cos + m^2/2 cos 2 ...): its spectrum peaks at f_m with amplitude 2 m A^2
  and at 2 f_m with m^2 A^2 / 2 (exact on DFT bins, to rounding);
* the spectral kurtosis of band-passed Gaussian white noise is 0 within its sampling scatter,
  of a pure tone -1, and the kurtogram finds the band of a train of ringing impacts;
* the kurtogram's tree has Antoni's bands (2^k per level, 3 * 2^(k-1) between levels).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.analysis.envelope import (
    complex_envelope,
    fast_kurtogram,
    kurtogram_levels,
    spectral_kurtosis,
    squared_envelope_spectrum,
)

FS = 8192.0
N = 8192  # one second: every integer frequency is on a bin


@settings(max_examples=40, deadline=None)
@given(
    fc=st.integers(1000, 3000),
    fm=st.integers(5, 200),
    m=st.floats(0.05, 0.9),
    amp=st.floats(0.1, 100.0),
)
def test_am_tone_envelope_spectrum_peaks_at_modulation(fc, fm, m, amp):
    t = np.arange(N) / FS
    x = amp * (1.0 + m * np.cos(2 * math.pi * fm * t)) * np.cos(2 * math.pi * fc * t)
    ses = squared_envelope_spectrum(x, FS, (fc - 600.0, fc + 600.0))
    i = int(np.argmax(ses.amplitude))
    assert ses.frequency[i] == pytest.approx(fm)
    assert ses.amplitude[i] == pytest.approx(2.0 * m * amp**2, rel=1e-9)
    assert ses.amplitude[2 * fm] == pytest.approx(0.5 * m**2 * amp**2, rel=1e-9)
    others = np.delete(ses.amplitude, [fm, 2 * fm])
    assert others.max() <= 1e-9 * amp**2


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), level=st.integers(1, 4))
def test_white_noise_spectral_kurtosis_is_zero(seed, level):
    x = np.random.default_rng(seed).standard_normal(N * 4)
    width = 0.5 * FS / 2**level
    lo = width * (2**level // 2)
    c = complex_envelope(x, FS, (lo, lo + width))
    # the sampling scatter of the kurtosis of m exponential powers: about sqrt(20 / m)
    assert abs(float(spectral_kurtosis(c))) < 5.0 * math.sqrt(20.0 / c.size)


def test_tone_spectral_kurtosis_is_minus_one():
    t = np.arange(N) / FS
    c = complex_envelope(np.cos(2 * math.pi * 1000.0 * t), FS, (900.0, 1100.0))
    assert float(spectral_kurtosis(c)) == pytest.approx(-1.0, abs=1e-9)


@settings(max_examples=15, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), resonance=st.floats(800.0, 3500.0))
def test_kurtogram_finds_the_ringing_band(seed, resonance):
    rng = np.random.default_rng(seed)
    n = N * 2
    t = np.arange(n) / FS
    x = 0.5 * rng.standard_normal(n)
    tau = np.arange(400) / FS
    ring = np.exp(-0.05 * 2 * math.pi * resonance * tau) * np.sin(2 * math.pi * resonance * tau)
    for start in range(300, n - 400, 700):
        x[start : start + 400] += 3.0 * ring
    k = fast_kurtogram(x, FS, min_bandwidth=200.0)
    lo, hi = k.band_hz
    assert lo - 0.1 * (hi - lo) <= resonance <= hi + 0.1 * (hi - lo)
    assert k.max_kurtosis > 1.0
    del t


@settings(max_examples=15, deadline=None)
@given(
    seed=st.integers(0, 2**32 - 1),
    resonance=st.floats(1500.0, 3500.0),
    min_low=st.floats(0.0, 1400.0),
)
def test_kurtogram_chooses_no_band_below_the_lines_it_is_read_at(seed, resonance, min_low):
    """A band starting below ``min_low`` is not chosen (reported as NaN), whatever its
    kurtosis: here a more impulsive low band (a smooth force pulse with each ring, as a
    noiseless simulated record holds the impacts' force) beside the resonance's ringing, and
    the whole record's band, which holds the pulse too."""
    rng = np.random.default_rng(seed)
    n = N * 2
    x = 0.2 * rng.standard_normal(n)
    tau = np.arange(400) / FS
    ring = np.exp(-0.05 * 2 * math.pi * resonance * tau) * np.sin(2 * math.pi * resonance * tau)
    pulse = 5.0 * np.hanning(16)  # impulsive below about 1 kHz only
    for start in range(300, n - 400, 700):
        x[start : start + 400] += ring
        x[start : start + 16] += pulse
    unrestricted = fast_kurtogram(x, FS, min_bandwidth=200.0)
    assert unrestricted.band_hz[0] < 1.0  # the pulse's low band is the most impulsive
    k = fast_kurtogram(x, FS, min_bandwidth=200.0, min_low=min_low)
    lo, hi = k.band_hz
    assert lo >= min_low - FS / n, k.band_hz  # the tree's edges are whole bins
    if min_low > FS / n:
        assert hi - lo < 0.5 * FS  # not the whole record's band
    for (level, bands), row in zip(kurtogram_levels(n), k.kurtosis, strict=False):
        edges = np.arange(bands) * (0.5 * FS / bands)
        # the tree's bands are whole numbers of bins: their edges to a bin's width
        below = edges < min_low - FS / n
        assert np.isnan(row[below]).all(), (level, row)
    unrestricted = fast_kurtogram(x, FS, min_bandwidth=200.0)
    assert k.max_kurtosis <= unrestricted.max_kurtosis + 1e-12


def test_kurtogram_levels_are_antonis_tree():
    levels = kurtogram_levels(2**14)
    assert levels[:5] == [
        (0.0, 1),
        (1.0, 2),
        (pytest.approx(math.log2(3)), 3),
        (2.0, 4),
        (pytest.approx(1 + math.log2(3)), 6),
    ]
    assert all((2**14) // 2 // bands >= 64 for _, bands in levels)


def test_bad_inputs():
    x = np.zeros(1000)
    with pytest.raises(ValueError, match="band"):
        squared_envelope_spectrum(x, FS, (100.0, 5000.0))
    with pytest.raises(ValueError, match="finite"):
        squared_envelope_spectrum(np.full(1000, np.nan), FS, (100.0, 500.0))
    with pytest.raises(ValueError, match="no band"):
        fast_kurtogram(np.ones(1000), FS, min_bandwidth=1e6)
