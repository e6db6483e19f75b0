"""McFadden & Smith's load-distribution modulation and demodulated line spectrum.

Closed forms: at ε = 1/2 the modulation is cos^a θ on the half circle, whose Fourier
coefficients over the mean are Γ(1 + a/2)² / (Γ(1 + (a+l)/2) Γ(1 + (a-l)/2)); a uniform load
(ε → ∞) gives no sidebands; a pure decay makes the lower sideband larger than the upper by
|E(f_d - f_s)| / |E(f_d + f_s)|.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.validation import mcfadden_smith as ms


def _half_circle(a: float, order: int) -> float:
    g = math.gamma
    return g(1 + a / 2) ** 2 / (g(1 + (a + order) / 2) * g(1 + (a - order) / 2))


@pytest.mark.parametrize("power", [1.0, 2.0])
def test_coefficients_at_half_circle_load_zone_match_the_closed_form(power: float) -> None:
    a = ms.modulation_coefficients(0.5, 3, power=power)
    for order in range(4):
        # the trapezoidal rule on 2^14 points; the kink at ±90° limits it to ~1e-8
        assert a[order] == pytest.approx(_half_circle(1.5 * power, order), rel=1e-6)


def test_coefficients_at_half_circle_known_values() -> None:
    a = ms.modulation_coefficients(0.5, 2)
    assert a[1] == pytest.approx(0.8225, abs=1e-4)
    assert a[2] == pytest.approx(0.4286, abs=1e-4)


def test_uniform_load_has_no_sidebands() -> None:
    a = ms.modulation_coefficients(math.inf, 2)
    assert a[0] == 1.0
    assert np.max(np.abs(a[1:])) < 1e-12
    lines = ms.predicted_lines(math.inf, 162.0, 30.0, 1885.0)
    assert all(v < 1e-12 for (i, side), v in lines.items() if side != 0)


@settings(max_examples=30, deadline=None)
@given(st.floats(0.2, 20.0), st.floats(0.2, 20.0))
def test_a_wider_load_zone_modulates_less(eps1: float, eps2: float) -> None:
    lo, hi = sorted((eps1, eps2))
    assert ms.modulation_coefficients(hi, 1)[1] <= ms.modulation_coefficients(lo, 1)[1] + 1e-12


def test_decay_makes_the_lower_sideband_larger_by_the_decay_ratio() -> None:
    fd, fs, beta = 162.0, 30.0, 1885.0
    lines = ms.predicted_lines(0.5, fd, fs, beta)
    ratio = math.hypot(beta, 2 * math.pi * (fd + fs)) / math.hypot(beta, 2 * math.pi * (fd - fs))
    assert lines[(1, -1)] / lines[(1, 1)] == pytest.approx(ratio, rel=1e-12)
    assert lines[(1, 0)] == 1.0


def test_load_zone_parameter() -> None:
    assert ms.load_zone_parameter(0.0, 9e-6) == 0.5
    # half the displacement taken by the clearance: the zone shrinks to ε = 1/4
    assert ms.load_zone_parameter(9e-6, 9e-6) == pytest.approx(0.25)


def test_measured_lines_read_a_synthetic_record() -> None:
    """Impulses at f_d, amplitudes q(θ) at ε = 1/2, each ringing 3 kHz with ζ = 0.05: the
    lines read from the record agree with the model's (squared envelope, decay 2ζω_n)."""
    rate, duration, fd, fs, fn, zeta = 12_000.0, 4.0, 162.18, 29.95, 3000.0, 0.05
    t = np.arange(int(rate * duration)) / rate
    x = np.zeros_like(t)
    wn = 2 * math.pi * fn
    for k in range(int(duration * fd)):
        t0 = k / fd
        amp = float(ms.load_distribution(2 * math.pi * fs * t0, 0.5))
        tail = t >= t0
        dt = t[tail] - t0
        x[tail] += amp * np.exp(-zeta * wn * dt) * np.sin(wn * dt)
    meas = ms.measured_lines(x, rate, fd, fs)
    pred = ms.predicted_lines(0.5, fd, fs, 2 * zeta * wn)
    for key in ((1, -1), (1, 1), (1, -2), (1, 2), (2, 0)):
        # sampling of q at the impacts and the band edges: a few per cent
        assert meas[key] == pytest.approx(pred[key], rel=0.05), key


def _chain_record(band: tuple[float, float]) -> tuple[dict, dict]:
    fs = 1797.0 / 60.0
    fd = 5.4152 * fs
    record = ms.model_record(
        0.5, fd, fs, resonance_hz=3000.0, damping_ratio=0.05, sample_rate=12_000.0, duration=2.0
    )
    beta = 2.0 * 0.05 * 2.0 * math.pi * 3000.0
    meas = ms.measured_lines(record, 12_000.0, fd, fs, band=band)
    return meas, ms.predicted_lines(0.5, fd, fs, beta)


def test_the_analytic_spectrum_comes_back_through_the_housing_and_the_envelope() -> None:
    """The model's own impulses through runout's housing mode, sampling and squared envelope
    (the VALIDATION rows): every line within CHAIN_RTOL of the analytic spectrum."""
    rows = ms.chain_checks()
    assert len(rows) == 9
    for row in rows:
        ours = row.ours() if callable(row.ours) else row.ours
        assert ours == pytest.approx(row.published, rel=ms.CHAIN_RTOL), row.quantity


def test_the_chains_gap_is_the_envelope_bands() -> None:
    """The gap of the 2-4 kHz band (2 x BPFI 1.1 % low) closes with a wide band: the chain
    adds nothing of its own beyond the band's truncation of each ring's spectrum."""
    narrow, pred = _chain_record(ms.BAND_HZ)
    wide, _ = _chain_record((500.0, 5900.0))
    for key in pred:
        if key[0] == 0:
            continue
        assert wide[key] == pytest.approx(pred[key], rel=2e-3), key
    assert abs(narrow[(2, 0)] / pred[(2, 0)] - 1.0) > 5e-3  # the band's gap is real
