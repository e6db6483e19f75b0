"""Property tests of the linear model: closed form = direct sum for any geometry and parts."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.geometry.bearing import BallBearing, Operation
from runout.geometry.imperfections import BearingImperfections, Harmonics, Slant
from runout.models import linear as lin

UM = 1e-6


def _harmonics(draw: st.DrawFn, kmax: int, kmin: int = 1) -> Harmonics:
    n = draw(st.integers(0, 6))
    orders = draw(st.lists(st.integers(kmin, kmax), min_size=n, max_size=n))
    amps = draw(st.lists(st.floats(0.0, 1.0), min_size=n, max_size=n))
    phases = draw(st.lists(st.floats(0.0, 6.3), min_size=n, max_size=n))
    return Harmonics(orders, np.array(amps) * UM, phases)


@st.composite
def cases(draw: st.DrawFn) -> tuple[BallBearing, Operation, float, BearingImperfections, str]:
    z = draw(st.integers(3, 16))
    dm = 20e-3
    d = draw(st.floats(1e-3, 0.9 * dm * math.sin(math.pi / z)))
    alpha = math.radians(draw(st.floats(0.0, 40.0)))
    bearing = BallBearing(
        elements=z,
        element_diameter=d,
        pitch_diameter=dm,
        inner_conformity=0.52,
        outer_conformity=0.53,
        contact_angle=alpha,
    )
    ring = draw(st.sampled_from(["inner", "outer"]))
    other = draw(st.sampled_from([0.0, 0.0, -3.0, 11.0]))
    op = Operation(ring, draw(st.floats(1.0, 200.0)), other_ring_speed=other)
    balls = [_harmonics(draw, 12, 0) for _ in range(z)]
    imp = BearingImperfections(
        inner=_harmonics(draw, 3 * z + 2),
        outer=_harmonics(draw, 3 * z + 2),
        elements=balls,
        diameter_errors=np.array(draw(st.lists(st.floats(-1, 1), min_size=z, max_size=z))) * UM,
        slant=Slant(draw(st.floats(0, 0.1)) * UM, draw(st.floats(0, 6.3))),
    )
    variant = draw(st.sampled_from(list(lin.VARIANTS)))
    return bearing, op, alpha, imp, variant


@settings(max_examples=40, deadline=None)
@given(cases())
def test_closed_form_equals_direct_sum(case: tuple) -> None:
    bearing, op, alpha, imp, variant = case
    r = lin.rates(bearing, op, alpha)
    lines = lin.spectral_lines(
        lin.closed_form_terms(imp, r, alpha, variant), r.rotation_hz, imp.n_elements, False
    )
    theta = np.linspace(0.0, 2 * math.pi * 2.7, 400)
    xd, yd = lin.direct_sum(imp, r, alpha, theta, variant)
    xl, yl = lines.evaluate(theta)
    # round-off is relative to the deviations that are summed, not to the motion: diameter
    # errors can cancel to a motion of round-off size, which is no scale for itself
    size = sum(float(np.abs(h.amplitudes).sum()) for h in (imp.inner, imp.outer, *imp.elements))
    size += float(np.abs(imp.diameter_errors).sum()) + (imp.slant.amplitude if imp.slant else 0.0)
    scale = max(float(np.abs(xd).max()), float(np.abs(yd).max()), size, 1e-30)
    assert np.abs(xl - xd).max() <= 1e-9 * scale
    assert np.abs(yl - yd).max() <= 1e-9 * scale
    assert np.all(np.isfinite(lines.x_amplitude))
    # |X|^2 + |Y|^2 = 2 (|C+|^2 + |C-|^2): x and y share the two whirl circles
    assert np.all(lines.ellipse_major + 1e-30 >= lines.ellipse_minor)
    # line by line to a few ulp of the line; a line cancelled in the element sums is ~1 ulp of
    # the largest line on either side, far below the floor of (1e-9 of the largest line)^2
    squares = 2 * (lines.forward**2 + lines.backward**2)
    assert np.allclose(
        lines.x_amplitude**2 + lines.y_amplitude**2,
        squares,
        rtol=1e-9,
        atol=1e-18 * float(np.max(squares, initial=0.0)),
    )


@settings(max_examples=20, deadline=None)
@given(cases())
def test_scaling_the_deviations_scales_the_lines(case: tuple) -> None:
    bearing, op, alpha, imp, variant = case
    r = lin.rates(bearing, op, alpha)
    twice = BearingImperfections(
        inner=imp.inner.scaled(2.0),
        outer=imp.outer.scaled(2.0),
        elements=[h.scaled(2.0) for h in imp.elements],
        diameter_errors=2 * imp.diameter_errors,
        slant=Slant(2 * imp.slant.amplitude, imp.slant.phase) if imp.slant else None,
    )
    a = lin.closed_form_terms(imp, r, alpha, variant)
    b = lin.closed_form_terms(twice, r, alpha, variant)
    # doubling is exact in binary floating point: the coefficients double to the ulp (a zero
    # stays zero); the floor is 1e-12 of the largest coefficient, not an absolute 1e-40 m
    floor = 1e-12 * float(np.max(np.abs(2 * a.coefficient), initial=0.0))
    np.testing.assert_allclose(b.coefficient, 2 * a.coefficient, rtol=1e-12, atol=floor)
