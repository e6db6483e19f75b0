"""The record's own speed (runout.diagnose._speed), on multi-tone records of known speed.

Invariants: the speed ratio the peaks give is the ratio the record was made at (to the
spectral resolution), whatever ratio; the tracked warp gives back the drift put in, and a
record without drift is left on its own clock.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.analysis.spectrum import amplitude_spectrum
from runout.diagnose._speed import line_speed, track_speed

#: Orders of a bearing-like line set (the 608 at 1800 rpm: cage, ball and ring lines).
ORDERS = np.array([1.0, 2.588, 3.412, 4.412, 5.176, 6.824, 7.764, 10.353, 12.94])
F_R = 30.0
FS = 2000.0


def _record(
    ratio: float, drift: float, seconds: float, noise: float, seed: int
) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    t = np.arange(round(seconds * FS)) / FS
    span = t.size / FS
    theta = 2 * math.pi * F_R * ratio * (t + drift * (t * t / (2 * span) - 0.5 * t))
    x = np.zeros_like(t)
    for k, o in enumerate(ORDERS[::2]):
        x += (1.0 / (k + 1)) * np.cos(o * theta + 0.7 * k)
    return t, x + noise * rng.standard_normal(t.size)


@settings(max_examples=15, deadline=None)
@given(ratio=st.floats(0.4, 2.5), seed=st.integers(0, 100))
def test_the_peaks_give_the_speed_the_record_was_taken_at(ratio, seed):
    t, x = _record(ratio, 0.0, 4.0, 0.05, seed)
    spec = amplitude_spectrum(x - x.mean(), sample_rate=FS)
    found = line_speed([spec.amplitude], FS, t.size, ORDERS, F_R)
    assert found is not None
    # the peaks are read to 1.5 bins: at the lowest order used, 1.5 / (T f_r) relative
    assert found.ratio == pytest.approx(ratio, rel=1.5 / (4.0 * F_R))
    assert found.share_best >= 0.99
    if abs(ratio - 1.0) > 0.05:
        assert found.share_assumed < 0.5


def test_one_line_cannot_give_a_speed():
    t = np.arange(8000) / FS
    x = np.cos(2 * math.pi * 77.0 * t)
    spec = amplitude_spectrum(x, sample_rate=FS)
    assert line_speed([spec.amplitude], FS, t.size, ORDERS, F_R) is None


@settings(max_examples=10, deadline=None)
@given(drift=st.floats(-0.005, 0.005), seed=st.integers(0, 100))
def test_the_tracked_drift_is_the_drift_put_in(drift, seed):
    t, x = _record(1.0, drift, 1.0, 0.02, seed)
    tr = track_speed(t, [x], list(ORDERS[::2] * F_R))
    assert tr is not None
    # the fit's own standard deviation of the drift (2 σ_b), and the bias of the quadratic
    # model, far below
    sigma = 2.0 * math.sqrt(tr.cov[1, 1])
    assert abs(tr.drift - drift) <= 4.0 * sigma + 1e-6
    assert abs(tr.mean_ratio - 1.0) <= 4.0 * math.sqrt(tr.cov[0, 0] + tr.cov[1, 1]) + 1e-6


def test_a_record_without_drift_keeps_its_clock():
    t, x = _record(1.0, 0.0, 1.0, 0.02, 3)
    tr = track_speed(t, [x], list(ORDERS[::2] * F_R))
    assert tr is not None and not tr.applied
    np.testing.assert_array_equal(tr.warped(t)[[0]], t[[0]])


def test_a_drifting_record_is_tracked():
    t, x = _record(1.0, 0.003, 1.0, 0.02, 3)
    tr = track_speed(t, [x], list(ORDERS[::2] * F_R))
    assert tr is not None and tr.applied
    # on the warped clock the lines are steady: the residual of a fit at fixed frequencies
    # falls to the noise
    tau = tr.warped(t)
    cols = [np.ones_like(t)]
    for o in ORDERS[::2]:
        cols += [np.cos(2 * math.pi * o * F_R * tau), np.sin(2 * math.pi * o * F_R * tau)]
    a = np.column_stack(cols)
    coef, *_ = np.linalg.lstsq(a, x, rcond=None)
    assert np.std(x - a @ coef) < 0.025
