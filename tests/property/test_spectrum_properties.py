"""Property tests of runout.analysis.spectrum (hypothesis)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.analysis.spectrum import (
    amplitude_spectrum,
    anderon_bands_from_lines,
    anderon_bands_from_waveform,
    extract_lines,
    peak_bin_gain,
    separate_rro_nrro,
)

TWO_PI = 2.0 * np.pi
SETTINGS = settings(max_examples=40, deadline=None)

amplitudes = st.floats(0.01, 10.0)
phases = st.floats(-np.pi, np.pi)


@st.composite
def bin_tones(draw: st.DrawFn, min_gap: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Distinct bins in 1..N/2-1 (N = 256), at least ``min_gap`` apart, with amplitude/phase."""
    slots = draw(st.lists(st.integers(1, 126 // min_gap), min_size=1, max_size=8, unique=True))
    bins = np.array(slots) * min_gap
    amp = np.array(draw(st.lists(amplitudes, min_size=bins.size, max_size=bins.size)))
    phi = np.array(draw(st.lists(phases, min_size=bins.size, max_size=bins.size)))
    return bins, amp, phi


def synth(t: np.ndarray, f: np.ndarray, amp: np.ndarray, phi: np.ndarray) -> np.ndarray:
    return (amp * np.cos(TWO_PI * np.multiply.outer(t, f) + phi)).sum(axis=-1)


@SETTINGS
@given(tones=bin_tones(min_gap=1), offset=st.floats(-100.0, 100.0))
def test_boxcar_spectrum_recovers_on_bin_tones(tones, offset) -> None:
    bins, amp, phi = tones
    n, fs = 256, 512.0
    t = np.arange(n) / fs
    f = bins * fs / n
    s = amplitude_spectrum(offset + synth(t, f, amp, phi), fs, "boxcar")
    expected = np.zeros(n // 2 + 1)
    expected[bins] = amp
    np.testing.assert_allclose(s.amplitude, expected, atol=1e-9)
    np.testing.assert_allclose(s.pp, 2 * expected, atol=2e-9)


@SETTINGS
@given(tones=bin_tones(min_gap=2))
def test_hann_spectrum_recovers_tones_two_bins_apart(tones) -> None:
    # The Hann main lobe covers k-1..k+1, so tones two bins apart do not interfere.
    bins, amp, phi = tones
    n, fs = 256, 1000.0
    t = np.arange(n) / fs
    s = amplitude_spectrum(synth(t, bins * fs / n, amp, phi), fs, "hann")
    np.testing.assert_allclose(s.amplitude[bins], amp, atol=1e-9)


@st.composite
def off_bin_lines(draw: st.DrawFn) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Frequencies 1.5 Hz-spaced slots plus a random sub-slot offset: gaps >= 1 Hz = 2 / T."""
    slots = np.array(draw(st.lists(st.integers(1, 290), min_size=1, max_size=8, unique=True)))
    frac = np.array(draw(st.lists(st.floats(0.0, 0.5), min_size=slots.size, max_size=slots.size)))
    amp = np.array(draw(st.lists(amplitudes, min_size=slots.size, max_size=slots.size)))
    phi = np.array(draw(st.lists(phases, min_size=slots.size, max_size=slots.size)))
    return 1.5 * slots + frac, amp, phi


@SETTINGS
@given(lines=off_bin_lines(), n=st.integers(2000, 2600), t0=st.floats(-50.0, 50.0))
def test_extract_lines_recovers_off_bin_lines(lines, n, t0) -> None:
    f, amp, phi = lines
    t = t0 + np.arange(n) / 1000.0  # non-integer numbers of periods in general
    fit = extract_lines(t, 0.7 + synth(t, f, amp, phi), f)
    got = fit.amplitude * np.exp(1j * fit.phase)
    np.testing.assert_allclose(np.abs(got - amp * np.exp(1j * phi)), 0.0, atol=1e-8)
    assert abs(fit.constant - 0.7) < 1e-8


@SETTINGS
@given(
    slots=st.lists(st.integers(1, 400 * 6), min_size=1, max_size=10, unique=True),
    data=st.data(),
)
def test_anderon_line_and_waveform_band_rms_agree_on_bin(slots, data) -> None:
    # Parseval: with every line on the 1/6-order grid of a six-revolution record and no
    # window, the waveform band rms equals the line band rms.
    spr, revs = 2048, 6
    ords = np.array(slots) / revs
    size = {"min_size": ords.size, "max_size": ords.size}
    amp = np.array(data.draw(st.lists(st.floats(1e-9, 1e-6), **size)))
    phi = np.array(data.draw(st.lists(phases, **size)))
    theta = TWO_PI * np.arange(spr * revs) / spr
    x = (amp * np.cos(np.multiply.outer(theta, ords) + phi)).sum(axis=-1)
    lines = anderon_bands_from_lines(ords, amp)
    wave = anderon_bands_from_waveform(x, spr)
    np.testing.assert_allclose(wave.rms, lines.rms, rtol=1e-7, atol=1e-6)


@SETTINGS
@given(
    spr=st.integers(2, 64),
    revs=st.integers(2, 12),
    channels=st.integers(1, 3),
    seed=st.integers(0, 2**32 - 1),
)
def test_rro_plus_nrro_is_the_signal(spr, revs, channels, seed) -> None:
    x = np.random.default_rng(seed).normal(size=(channels, spr * revs))
    res = separate_rro_nrro(x, spr)
    np.testing.assert_allclose(res.rro_waveform + res.nrro, x, atol=1e-12)
    # the NRRO has zero synchronous average, the RRO is periodic
    folded = res.nrro.reshape(channels, revs, spr)
    np.testing.assert_allclose(folded.mean(axis=1), 0.0, atol=1e-12)
    again = separate_rro_nrro(res.rro_waveform, spr)
    np.testing.assert_allclose(again.nrro, 0.0, atol=1e-12)


@SETTINGS
@given(
    f=st.floats(1.0, 1e4),
    duration=st.floats(0.01, 10.0),
    window=st.sampled_from(["hann", "boxcar", "hamming", "blackman"]),
)
def test_peak_bin_gain_bounded_and_periodic_in_record_length(f, duration, window) -> None:
    g = float(peak_bin_gain(f, duration, window, samples=512))
    assert 0.0 < g <= 1.0 + 1e-12
    # one more period of the line in the record puts it at the same place between bins
    assert float(peak_bin_gain(f, duration + 1.0 / f, window, samples=512)) == pytest.approx(
        g, rel=1e-6
    )
    # never worse than half a bin off
    assert g >= float(peak_bin_gain(1.5, 1.0, window, samples=512)) - 1e-9
