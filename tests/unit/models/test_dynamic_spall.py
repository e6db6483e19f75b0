"""Spalls in the dynamic model: the compiled kernels against the NumPy reference, and the drop.

A ball crossing a spall on the outer raceway, on the turning inner raceway or on the ball itself
is integrated by the compiled Newmark kernels (the radial one and the general one with the
exact geometry) and by :func:`newmark_reference`, whose spall drop is an independent NumPy
path (:func:`spall_drops_np`); they agree to the Newton tolerance. The drop of a ball into a
spall (:func:`spall_drop`) is 0 outside it, never above the depth nor the geometric limit
D/2 - sqrt(D^2/4 - w^2/4), and symmetric about the spall's centre (property tests).
"""

from __future__ import annotations

import math
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.case.model import parse_case
from runout.models import _dynamic_kernels as dk
from runout.models import _dynamic_setup as ds
from runout.models import dynamic as dy

EXAMPLE = Path(__file__).resolve().parents[3] / "examples" / "cwru_6205_outer_spall.toml"


def _setup(defect: dict, axial: bool) -> dy.DynamicSetup:
    data = tomllib.loads(EXAMPLE.read_text(encoding="utf-8"))
    data["defect"] = [defect]
    if axial:
        data["operation"]["preload"] = "spring"  # the rotor moves axially: general kernel
    else:
        del data["operation"]["axial_load"]  # in the plane, no offset: the radial kernel
        del data["operation"]["preload"]
    for key in ("sensor",):
        del data[key]
    del data["analysis"]["signal"]
    return dy.setup(parse_case(data, "spall.toml"))


def _entry_time(s: dy.DynamicSetup) -> float:
    """A time 0.1 ms before a ball at the bottom of the load zone (within 40 deg of -y) starts
    to drop into the spall [s]."""
    t = np.arange(0.0, 0.5, 2e-6)
    drops = ds.spall_drops_np(s, t)
    theta, _, _ = ds._deviations_np(s, t)
    below = np.cos(theta - (-0.5 * math.pi)) > math.cos(math.radians(40.0))
    starts = (drops[1:] > 0.0) & (drops[:-1] == 0.0) & below[1:]
    first = int(np.flatnonzero(starts.any(axis=1))[0])
    return float(t[first] - 1e-4)


DEFECTS = {
    "outer": {"part": "outer", "width": 1e-3, "depth": 50e-6, "angle": -1.4},
    "inner": {"part": "inner", "width": 1e-3, "depth": 50e-6, "angle": -1.2},
    "ball": {"part": "ball", "width": 1e-3, "depth": 50e-6, "element": 1},
}


@pytest.mark.parametrize("axial", [False, True], ids=["radial", "general"])
@pytest.mark.parametrize("part", list(DEFECTS))
def test_kernel_matches_reference_through_a_spall(part: str, axial: bool) -> None:
    s = _setup(DEFECTS[part], axial)
    t0 = _entry_time(s)
    q0 = dy.static_equilibrium(s, np.array([t0]))[0]
    state = np.zeros(9)
    state[:3] = q0
    h, n = 4e-6, 260  # 1 ms: the contact point crosses the 1 mm spall (0.6 ms)
    times = t0 + h * np.arange(1, n + 1)
    drops = ds.spall_drops_np(s, times)
    entered = drops.max(axis=1) > 0.0
    assert entered.any() and not entered[0], "the window must hold the entry into the spall"
    ref = dy.newmark_reference(s, h, n, state.copy(), t0)
    out = np.zeros((n, 3))
    status, _, _, _ = dy.newmark_kernel(
        n, 1, t0, state.copy(), s.params(h), s.theta0, s.harmonics, s.ndof, dy.MAX_ITER, out,
        s.spalls,
    )  # fmt: skip
    assert status == dy.OK
    motion = np.ptp(ref, axis=0).max()
    healthy = np.zeros((n, 3))
    dy.newmark_kernel(
        n, 1, t0, state.copy(), s.params(h), s.theta0, s.harmonics, s.ndof, dy.MAX_ITER, healthy
    )
    # the spall moves the rotor (by far more than the tolerance below)
    assert np.max(np.abs(out - healthy)) > 1e-3 * motion
    assert np.max(np.abs(out - ref)) < 1e-8 * motion


@settings(max_examples=200, deadline=None)
@given(
    angle=st.floats(-10.0, 10.0),
    width=st.floats(1e-5, 5e-3),
    depth=st.floats(1e-7, 3e-3),
    radius=st.floats(1e-3, 2e-2),
    arc=st.floats(5e-3, 0.1),
)
def test_spall_drop_bounds_and_symmetry(
    angle: float, width: float, depth: float, radius: float, arc: float
) -> None:
    d = dk.spall_drop(angle, arc, width, depth, radius)
    assert d == dk.spall_drop(-angle, arc, width, depth, radius)
    assert 0.0 <= d <= depth
    half = 0.5 * width
    reach = radius - math.sqrt(max(radius * radius - half * half, 0.0)) if half < radius else radius
    assert d <= reach * (1.0 + 1e-12)
    wrapped = math.remainder(angle, 2.0 * math.pi)
    inside = half - arc * abs(wrapped)  # distance of the contact point from the nearer edge
    if inside <= 0.0:
        assert d == 0.0
    elif inside * inside / (2.0 * radius) > 4.0 * sys.float_info.epsilon * radius:
        # the drop r - sqrt(r^2 - e^2) ~ e^2/2r is resolved only above r's round-off
        assert d > 0.0
    # the centre of the spall: the effective depth min(depth, D/2 - sqrt(D^2/4 - w^2/4))
    assert dk.spall_drop(0.0, arc, width, depth, radius) == pytest.approx(min(depth, reach))


def test_compiled_and_numpy_drops_agree() -> None:
    for part, defect in DEFECTS.items():
        s = _setup(defect, False)
        t = np.linspace(0.0, 0.2, 4001)
        ref = ds.spall_drops_np(s, t)
        dr = np.empty(s.n_elements)
        for i in range(0, t.size, 37):
            dk._spall_drops(t[i], s.spalls, s.theta0, ds.TWO_PI * s.kinematics.cage, 0.0, dr)
            assert np.allclose(dr, ref[i], rtol=0.0, atol=1e-15), part
        assert ref.max() > 0.0, part


@pytest.mark.parametrize("axial", [False, True], ids=["radial", "general"])
@pytest.mark.parametrize("part", ["inner", "ball"])
def test_kernel_matches_reference_with_slip(part: str, axial: bool) -> None:
    # the cage slips by a random angle, linear over each 5 ms: the balls and the spalls follow
    s = _setup(DEFECTS[part], axial)
    rng = np.random.default_rng(4)
    knots = np.concatenate([[-0.01, 0.005], np.cumsum(np.r_[0.0, 0.02 * rng.standard_normal(80)])])
    s = s.replace(slip=knots)
    t0 = _entry_time(s)
    q0 = dy.static_equilibrium(s, np.array([t0]))[0]
    state = np.zeros(9)
    state[:3] = q0
    h, n = 4e-6, 260
    assert np.ptp(ds.slip_angles_np(s, t0 + h * np.arange(n))) > 0.0
    ref = dy.newmark_reference(s, h, n, state.copy(), t0)
    out = np.zeros((n, 3))
    status, _, _, _ = dy.newmark_kernel(
        n, 1, t0, state.copy(), s.params(h), s.theta0, s.harmonics, s.ndof, dy.MAX_ITER, out,
        s.spalls, s.slip,
    )  # fmt: skip
    assert status == dy.OK
    motion = np.ptp(ref, axis=0).max()
    assert motion > 1e-9
    assert np.max(np.abs(out - ref)) < 1e-8 * motion


def test_slip_angle_matches_numpy_interpolation() -> None:
    s = _setup(DEFECTS["outer"], False)
    knots = np.array([-0.02, 0.01, 0.0, 0.3, -0.1, 0.05, 0.2])
    s = s.replace(slip=knots)
    t = np.linspace(-0.05, 0.1, 301)  # beyond both ends too: the end intervals' lines
    ref = ds.slip_angles_np(s, t)
    got = np.array([dk.slip_angle(x, knots) for x in t])
    assert np.allclose(got, ref, rtol=0.0, atol=1e-15)
