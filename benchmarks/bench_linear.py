"""Benchmark of the linear model (seed 002): the 608 with all harmonics of eq. 43-47.

Ours: closed-form lines (:func:`runout.models.linear.closed_form_terms`,
:func:`~runout.models.linear.spectral_lines`) and their compiled synthesis on 2**16 angles
(x and y). Reference: a straightforward per-ball loop of eq. 28 in NumPy, evaluating each
part's Fourier series at each ball's contact angles.
"""

from __future__ import annotations

import math

import numpy as np

from _harness import BenchResult, best_time
from runout.geometry.bearing import BallBearing, Operation
from runout.geometry.imperfections import (
    BearingImperfections,
    Harmonics,
    Slant,
    single_harmonic,
    spectral_law,
)
from runout.models import linear as lin

N_SAMPLES = 2**16
REVOLUTIONS = 6
ALPHA = math.radians(10.0)
UM = 1e-6


def _case() -> tuple[BearingImperfections, lin.Rates]:
    rng = np.random.default_rng(7)
    inner = single_harmonic(1, 2.5 * UM) + spectral_law((2, 799), 0.1 * UM, -1.5, rng=rng)
    outer = spectral_law((2, 1359), 0.1 * UM, -1.5, rng=rng)
    ball = spectral_law((2, 286), 0.1 * UM, -1.5, rng=rng)
    imp = BearingImperfections(
        inner=inner, outer=outer, elements=[ball] + [Harmonics.empty()] * 6, slant=Slant(0.05 * UM)
    )
    bearing = BallBearing(
        elements=7,
        element_diameter=3.9688e-3,
        pitch_diameter=15e-3,
        inner_conformity=0.52,
        outer_conformity=0.53,
        contact_angle=ALPHA,
    )
    return imp, lin.rates(bearing, Operation("inner", 30.0), ALPHA)


def _ours(imp: BearingImperfections, r: lin.Rates) -> tuple[np.ndarray, np.ndarray]:
    lines = lin.spectral_lines(lin.closed_form_terms(imp, r, ALPHA), r.rotation_hz, 7, True)
    _, x, y = lin.synthesize(lines, REVOLUTIONS, N_SAMPLES)
    return x, y


def _series(h: Harmonics, angle: np.ndarray, chunk: int = 64) -> np.ndarray:
    out = np.zeros(angle.size)
    k, a, p = h.orders.astype(float), h.amplitudes, h.phases
    for s in range(0, k.size, chunk):
        out += (
            a[s : s + chunk, None]
            * np.cos(np.outer(k[s : s + chunk], angle) + p[s : s + chunk, None])
        ).sum(0)
    return out


def _naive(imp: BearingImperfections, r: lin.Rates) -> tuple[np.ndarray, np.ndarray]:
    """Eq. 28 ball by ball: x = (2 cos α / Z) Σ_z w_z cos θ_z, w_z from each part's series."""
    theta = 2 * math.pi * REVOLUTIONS * np.arange(N_SAMPLES) / N_SAMPLES
    z = imp.n_elements
    c = math.cos(ALPHA)
    x = np.zeros(N_SAMPLES)
    y = np.zeros(N_SAMPLES)
    for j in range(z):
        tz = r.cage * theta + 2 * math.pi * j / z
        w = _series(imp.inner, tz - theta) - _series(imp.outer, tz)
        w += _series(imp.element_diameter_deviation(j), r.spin * theta)
        x += 2 * c / z * w * np.cos(tz)
        y += 2 * c / z * w * np.sin(tz)
    assert imp.slant is not None
    s = c * imp.slant.amplitude * np.cos(2 * theta - imp.slant.phase)
    # eq. 28 gives the outer ring relative to the inner; runout reports the shaft: turn the sign
    return lin.SHAFT_FRAME * (x + s), lin.SHAFT_FRAME * (y - s)


def bench_linear_608_all_harmonics_65536_samples() -> BenchResult:
    imp, r = _case()
    xo, yo = _ours(imp, r)
    xn, yn = _naive(imp, r)
    scale = float(np.abs(xn).max())
    if not (np.abs(xo - xn).max() < 1e-9 * scale and np.abs(yo - yn).max() < 1e-9 * scale):
        raise AssertionError("closed form and naive eq. 28 disagree")
    ours = best_time(lambda: _ours(imp, r), repeat=5)
    ref = best_time(lambda: _naive(imp, r), repeat=1)
    return BenchResult(
        name="linear 608, ~2400 harmonics x 65536 samples",
        ours_s=ours,
        reference_s=ref,
        reference="per-ball NumPy loop of eq. 28",
        target="< 0.2 s and >= 20x faster",
        met=ours < 0.2 and ref / ours >= 20.0,
    )
