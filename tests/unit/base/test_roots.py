"""runout.base._roots.brentq runs SciPy's Brent iterations exactly: same root to the bit."""

from __future__ import annotations

import math

import pytest
import scipy.optimize
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.base._roots import brentq
from runout.geometry import loading
from runout.geometry.bearing import BallBearing

coef = st.floats(-10.0, 10.0, allow_nan=False)


def _compare(f, a: float, b: float, **kw) -> None:  # type: ignore[no-untyped-def]
    try:
        ref, info = scipy.optimize.brentq(f, a, b, full_output=True, **kw)
    except (ValueError, RuntimeError) as exc:
        with pytest.raises(type(exc)):
            brentq(f, a, b, full_output=True, **kw)
        return
    ours, res = brentq(f, a, b, full_output=True, **kw)  # type: ignore[misc]
    assert ours == ref or (math.isnan(ours) and math.isnan(ref))
    # the same evaluations (SciPy counts an iteration even when f(a) or f(b) is 0 exactly)
    assert (res.function_calls, res.converged) == (info.function_calls, info.converged)


@settings(max_examples=300, deadline=None)
@given(
    c=st.lists(coef, min_size=2, max_size=6),
    a=st.floats(-5.0, 0.0),
    b=st.floats(0.01, 5.0),
    xtol=st.sampled_from([2e-12, 1e-6, 1e-15, 1e-3]),
    rtol=st.sampled_from([8.881784197001252e-16, 8.9e-16, 1e-10]),
)
def test_polynomials_and_transcendentals(c, a, b, xtol, rtol) -> None:  # type: ignore[no-untyped-def]
    def poly(x: float) -> float:
        return sum(ci * x**i for i, ci in enumerate(c))

    def trig(x: float) -> float:
        return c[0] * math.sin(3 * x + c[1]) + 0.1 * x - 0.05

    _compare(poly, a, b, xtol=xtol, rtol=rtol)
    _compare(trig, a, b, xtol=xtol, rtol=rtol)
    _compare(lambda x: math.tanh(x - c[0] / 4) * 1e-6, a, b, xtol=xtol, rtol=rtol, maxiter=7)


@pytest.mark.parametrize("load", [0.5, 20.0, 300.0, 5000.0])
def test_axial_loading_contact_angle_unchanged(load: float) -> None:
    """runout.geometry.loading's load-angle relation gives the same angle with SciPy's brentq."""
    b = BallBearing(
        elements=8,
        element_diameter=1e-3,
        pitch_diameter=7e-3,
        inner_conformity=0.52,
        outer_conformity=0.53,
        radial_clearance=10e-6,
    )
    ours = loading.axial_loading(b, load).contact_angle
    original = loading.brentq if hasattr(loading, "brentq") else None
    assert original is None  # imported lazily inside axial_loading
    import runout.base._roots as roots

    saved = roots.brentq
    roots.brentq = scipy.optimize.brentq  # type: ignore[assignment]
    try:
        ref = loading.axial_loading(b, load).contact_angle
    finally:
        roots.brentq = saved
    assert ours == ref


def test_underflowing_function_values_bisect_like_scipy() -> None:
    """Found by hypothesis: f ~ 1e-117 makes the interpolation's denominator underflow to 0;
    Python raised ZeroDivisionError where SciPy's C divides into inf and bisects."""
    c = [4.754897394447338e-117, 9.020990381927154e-112]

    def poly(x: float) -> float:
        return sum(ci * x**i for i, ci in enumerate(c))

    _compare(poly, -2.5, 2.0, xtol=2e-12, rtol=8.881784197001252e-16)
