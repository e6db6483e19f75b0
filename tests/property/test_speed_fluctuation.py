"""`[sensor] speed_fluctuation`: the speed profile's invariants, and order tracking undoing it.

The relative deviation u(t) of the shaft speed has zero mean and the rms given, is the same for
the same seed and stays a forward rotation (1 + u > 0); a record resampled at uniform shaft
angle from a tachometer that follows the fluctuation has its order-k line back at k times the
mean speed, sharp.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.analysis.envelope import at_uniform_angle
from runout.diagnose._record import record_from_arrays
from runout.diagnose.envelope import order_tracked
from runout.models._dynamic_signal import speed_profile


@settings(max_examples=40, deadline=None)
@given(
    fluctuation=st.floats(1e-4, 0.1),
    shaft_hz=st.floats(5.0, 200.0),
    duration=st.floats(0.5, 5.0),
    seed=st.integers(0, 2**31),
)
def test_profile_has_zero_mean_the_rms_given_and_is_seeded(
    fluctuation: float, shaft_hz: float, duration: float, seed: int
) -> None:
    u = speed_profile(fluctuation, shaft_hz, duration, seed, 4096)
    assert abs(float(u.mean())) <= 1e-12
    assert float(np.sqrt(np.mean(u * u))) == pytest.approx(fluctuation, rel=1e-9)
    assert float(np.min(1.0 + u)) > 0.0
    np.testing.assert_array_equal(u, speed_profile(fluctuation, shaft_hz, duration, seed, 4096))


#: The records below: sample rate [Hz], length [s], mean shaft speed [Hz], the line's order.
FS, DURATION, SHAFT_HZ, ORDER = 2000.0, 4.0, 25.0, 3.3


def _fluctuating(fluctuation: float, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """Instants [s] and shaft revolutions at each (trapezoid of the fluctuating speed)."""
    n = int(FS * DURATION)
    u = speed_profile(fluctuation, SHAFT_HZ, DURATION, seed, n)
    rate = SHAFT_HZ * (1.0 + u)
    rev = np.concatenate([[0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1]) / FS)])
    return np.arange(n) / FS, rev


@settings(max_examples=10, deadline=None)
@given(fluctuation=st.floats(0.005, 0.05), seed=st.integers(0, 1000))
def test_order_tracking_puts_an_order_line_back_at_the_mean_speed(
    fluctuation: float, seed: int
) -> None:
    time, rev = _fluctuating(fluctuation, seed)
    n = time.size
    a = np.cos(2.0 * np.pi * ORDER * rev)  # a line at a fixed order of the shaft
    rec = record_from_arrays(time, a=a, rev=rev, quantity="acceleration")
    tracked, note = order_tracked(rec)
    assert note.startswith("order tracking:")
    mean_hz = float(tracked.tachometer_hz)
    assert abs(mean_hz / SHAFT_HZ - 1.0) < 1e-3
    spectrum = np.abs(np.fft.rfft(tracked.channels["a"] * np.hanning(n))) ** 2
    freqs = np.fft.rfftfreq(n, 1.0 / FS)
    peak = float(freqs[int(np.argmax(spectrum))])
    df = FS / n
    assert abs(peak - ORDER * mean_hz) <= 1.5 * df
    # sharp: the line's three bins hold most of the energy within 5 % of it
    near = np.abs(freqs - ORDER * mean_hz) <= 0.05 * ORDER * mean_hz
    i = int(np.argmax(spectrum))
    assert spectrum[i - 1 : i + 2].sum() > 0.9 * spectrum[near].sum()


@settings(max_examples=10, deadline=None)
@given(fluctuation=st.floats(0.005, 0.05), seed=st.integers(0, 1000))
def test_resampling_at_the_exact_angle_gives_the_order_line_at_the_mean_speed(
    fluctuation: float, seed: int
) -> None:
    # what a run does with its own shaft angle (no tachometer pulses to interpolate between)
    time, rev = _fluctuating(fluctuation, seed)
    n = time.size
    uniform_time, a, mean_hz = at_uniform_angle(time, rev, np.cos(2.0 * np.pi * ORDER * rev))
    assert mean_hz == pytest.approx(rev[-1] / time[-1], rel=1e-12)
    # the same span, equal steps
    np.testing.assert_allclose(np.diff(uniform_time), time[-1] / (n - 1), rtol=1e-9)
    # the record at uniform angle is the order line at the mean speed, to the resampling's
    # error: the 4x polyphase filter's passband ripple at f = 82 Hz (scipy's default Kaiser
    # design: 1.6e-3 of the amplitude on a pure 82.5 Hz tone) plus the linear interpolation's
    # (2 pi f / (4 fs))^2 / 8 = 5e-4
    core = slice(50, -50)  # away from the polyphase filter's edges
    expected = np.cos(2.0 * np.pi * ORDER * mean_hz * (uniform_time - uniform_time[0]))
    assert np.max(np.abs(a[core] - expected[core])) < 2.5e-3
