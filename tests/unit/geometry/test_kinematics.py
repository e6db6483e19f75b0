"""Kinematic identities that must hold for any geometry."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from runout import BallBearing, Operation
from runout.geometry.kinematics import (
    ball_pass_inner_frequency,
    ball_pass_outer_frequency,
    ball_spin_frequency,
    bearing_frequencies,
    cage_frequency,
)

ratios = st.floats(0.05, 0.45)
angles = st.floats(0.0, math.radians(40))
speeds = st.floats(-500.0, 500.0).filter(lambda v: abs(v) > 1e-3)


@given(ratios, angles, speeds, st.integers(3, 40))
def test_ball_pass_frequencies_add_up_to_z_times_relative_speed(r, a, f, z) -> None:
    # BPFI + BPFO = Z |f_i - f_o| for one ring stationary.
    args = (f, 0.0, r, 1.0, a)
    total = ball_pass_inner_frequency(z, *args) + ball_pass_outer_frequency(z, *args)
    assert total == pytest.approx(z * abs(f), rel=1e-12)


@given(ratios, angles, speeds, speeds)
def test_cage_is_linear_in_ring_speeds(r, a, fi, fo) -> None:
    both = cage_frequency(fi, fo, r, 1.0, a)
    parts = cage_frequency(fi, 0.0, r, 1.0, a) + cage_frequency(0.0, fo, r, 1.0, a)
    assert both == pytest.approx(parts, rel=1e-9, abs=1e-9)


@given(ratios, angles, speeds)
def test_rolling_without_slip_at_both_contacts(r, a, f) -> None:
    # Seed 002 eq. 2-3: surface speeds of ball and raceway agree at both contacts.
    d, dm = r, 1.0
    fc = cage_frequency(f, 0.0, d, dm, a)
    fb = ball_spin_frequency(f, 0.0, d, dm, a)
    rb, rc = d / 2, dm / 2
    assert rb * fb == pytest.approx(abs((rc + rb * math.cos(a)) * fc), rel=1e-9)
    assert rb * fb == pytest.approx(abs((rc - rb * math.cos(a)) * (f - fc)), rel=1e-9)


def test_outer_ring_rotation_swaps_the_roles_of_the_raceways() -> None:
    b = BallBearing(8, 1e-3, 7e-3, contact_angle=math.radians(15))
    inner = bearing_frequencies(b, Operation("inner", speed=90.0))
    outer = bearing_frequencies(b, Operation("outer", speed=90.0))
    g = 1e-3 * math.cos(math.radians(15)) / 7e-3
    assert outer.cage == pytest.approx(45.0 * (1 + g))
    assert inner.cage == pytest.approx(45.0 * (1 - g))
    assert outer.ball_spin == pytest.approx(inner.ball_spin)
    # Tada (seed 000): with the outer ring rotating, f_i = Z f_c and f_o = Z (f_r - f_c).
    assert outer.ball_pass_inner == pytest.approx(8 * outer.cage)
    assert outer.ball_pass_outer == pytest.approx(8 * (90.0 - outer.cage))


def test_vectorised_over_arrays() -> None:
    alpha = np.radians([0.0, 10.0, 20.0])
    fc = cage_frequency(1.0, 0.0, 0.2, 1.0, alpha)
    assert fc.shape == (3,)
    assert np.all(np.diff(fc) > 0)  # larger contact angle, smaller γ, faster cage


def test_orders_at_zero_speed_raise() -> None:
    b = BallBearing(8, 1e-3, 7e-3)
    f = bearing_frequencies(b, Operation("inner", speed=0.0))
    with pytest.raises(ZeroDivisionError):
        f.orders()
