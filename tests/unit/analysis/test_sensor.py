"""The accelerometer model (runout.analysis.sensor): the transfer function it states, sampling.

:func:`housing_acceleration` driven by a sinusoidal force settles to the amplitude and phase of
:math:`H(j\\omega) = -\\omega^2 / (M(\\omega_n^2 - \\omega^2 + 2j\\zeta\\omega_n\\omega))`
(property test over frequencies, resonances, damping ratios and masses), and several modes the
sum of theirs (modal superposition); a constant force gives no acceleration; :func:`sample`
keeps a tone below the new Nyquist frequency and removes one above it; the envelope block finds
the band of a train of impacts and labels its rate.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.analysis.sensor import envelope_block, housing_acceleration, sample


@settings(max_examples=40, deadline=None)
@given(
    ratio=st.floats(0.2, 3.0),
    resonance=st.floats(500.0, 5000.0),
    zeta=st.floats(0.02, 0.3),
    mass=st.floats(0.1, 10.0),
)
def test_sinusoidal_force_gives_the_stated_transfer_function(
    ratio: float, resonance: float, zeta: float, mass: float
) -> None:
    f = ratio * resonance
    step = 1.0 / (200.0 * max(f, resonance))
    # long enough for the free response (decay time 1/(zeta wn)) to fall below 1e-9
    settle = 21.0 / (zeta * 2.0 * math.pi * resonance)
    n_periods = 20
    t = np.arange(0.0, settle + n_periods / f, step)
    acc = housing_acceleration(np.sin(2.0 * math.pi * f * t), step, resonance, zeta, mass)
    w, wn = 2.0 * math.pi * f, 2.0 * math.pi * resonance
    h = -(w**2) / (mass * (wn**2 - w**2 + 2j * zeta * wn * w))
    tail = t >= settle
    expected = np.imag(h * np.exp(1j * w * t[tail]))
    # first-order hold is exact for a piecewise-linear force: the sine's curvature between
    # steps, (w h)^2 / 12 of its amplitude, is the only error
    assert np.max(np.abs(acc[tail] - expected)) <= 1e-3 * abs(h)


@settings(max_examples=30, deadline=None)
@given(
    ratio=st.floats(0.2, 3.0),
    resonances=st.lists(st.floats(500.0, 5000.0), min_size=2, max_size=4),
    zeta=st.floats(0.05, 0.3),
    masses=st.lists(
        st.one_of(st.floats(0.1, 10.0), st.floats(-10.0, -0.1)), min_size=4, max_size=4
    ),
)
def test_several_modes_give_the_sum_of_their_transfer_functions(
    ratio: float, resonances: list[float], zeta: float, masses: list[float]
) -> None:
    # modal superposition: H = sum of the modes' H_k, a negative modal mass a mode whose shape
    # has opposite signs at the bearing and at the sensor
    masses = masses[: len(resonances)]
    f = ratio * min(resonances)
    step = 1.0 / (200.0 * max(f, *resonances))
    settle = 21.0 / (zeta * 2.0 * math.pi * min(resonances))
    t = np.arange(0.0, settle + 20 / f, step)
    acc = housing_acceleration(np.sin(2.0 * math.pi * f * t), step, resonances, zeta, masses)
    w = 2.0 * math.pi * f
    parts = [
        -(w**2) / (m * ((2 * math.pi * fk) ** 2 - w**2 + 2j * zeta * 2 * math.pi * fk * w))
        for fk, m in zip(resonances, masses, strict=True)
    ]
    h = sum(parts)
    tail = t >= settle
    expected = np.imag(h * np.exp(1j * w * t[tail]))
    # each mode's hold error is (w h)^2 / 12 of its own response: bounded by the sum of those
    assert np.max(np.abs(acc[tail] - expected)) <= 1e-3 * sum(abs(p) for p in parts)


def test_constant_force_gives_no_acceleration() -> None:
    acc = housing_acceleration(np.full(5000, 1234.5), 1e-5, 3000.0, 0.05, 1.0)
    assert np.max(np.abs(acc)) == 0.0


def test_sampling_keeps_a_low_tone_and_removes_a_high_one() -> None:
    fine_rate, factor = 240_000.0, 20  # sampled at 12 kHz: Nyquist 6 kHz
    t = np.arange(48_000) / fine_rate
    low = sample(np.sin(2 * math.pi * 2000.0 * t), factor)
    high = sample(np.sin(2 * math.pi * 9000.0 * t), factor)
    ts = np.arange(low.size) * factor / fine_rate
    core = slice(50, -50)  # away from the filter's edges
    assert np.max(np.abs(low[core] - np.sin(2 * math.pi * 2000.0 * ts[core]))) < 0.01
    assert np.max(np.abs(high[core])) < 0.01  # it would alias to 3 kHz without the filter


def test_envelope_block_labels_the_rate_of_an_impact_train() -> None:
    fs, f_defect, f_r = 12_000.0, 107.0, 30.0
    t = np.arange(24_000) / fs
    rng = np.random.default_rng(0)
    # impacts at f_defect, each ringing 3 kHz (damping ratio 0.05): an impulsive signal
    tau = (t * f_defect) % 1.0 / f_defect
    wn = 2 * math.pi * 3000.0
    a = np.exp(-0.05 * wn * tau) * np.sin(wn * tau)
    a += 0.1 * rng.standard_normal(t.size)
    block = envelope_block(
        a,
        fs,
        {"outer": f_defect, "inner": 162.0, "ball": 141.0, "cage": 12.0},
        {"outer": None, "inner": f_r, "ball": 12.0, "cage": None},
        f_r,
    )
    lo, hi = block["band_hz"]
    assert lo <= 3000.0 <= hi
    first = block["peaks"][0]
    assert abs(first["frequency_hz"] - f_defect) < 0.5
    assert (first["label"], first["part"], first["harmonic"]) == ("BPFO", "outer", 1)
