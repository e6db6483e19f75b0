"""Seed 001 (Kim, Choi & Yoon) Table 2: contact angle and deflections against the number of balls.

The spindle bearing of Table 1 (D = 1.5875 mm, d_m = 9.1 mm, f_i = 0.529, f_o = 0.535,
P_d = 5 um, steel) runs at 7200 rpm under an axial preload the paper does not print. We fit
that load once, on the Z = 10 column (18.73 deg), and *predict* the other five angles with the
static pure-axial model of runout.geometry.loading. The deflections are compared too; they are
systematically 12-15 % below the table for a reason that cannot be speed effects (see the
last tests and VALIDATION.md).
"""

from __future__ import annotations

import math

import pytest

from runout import BallBearing
from runout.examples import kim_bearing
from runout.geometry.loading import AxialLoading
from runout.validation.seed001_kim import KIM_TABLE2, kim_axial_loading, kim_fitted_preload

# Z: (alpha [deg], delta_i [um], delta_o [um])
TABLE2 = KIM_TABLE2
FIT_Z = 10


def _bearing(z: int) -> BallBearing:
    # the Table 1 bearing, steel E = 208 GPa, ν = 0.3
    return kim_bearing(elements=z)


def _fitted_axial_load() -> float:
    # fitted on the Z = FIT_Z column: the load whose static solution gives TABLE2[FIT_Z][0]
    return kim_fitted_preload()


def _solve(z: int) -> AxialLoading:
    return kim_axial_loading(z)


def test_kim2002_table2_fitted_axial_load_is_plausible() -> None:
    fa = _fitted_axial_load()
    # about 60.7 N; the solve at Z = 10 returns the angle it was fitted to
    assert 55.0 < fa < 65.0
    assert math.degrees(_solve(FIT_Z).contact_angle) == pytest.approx(18.73, abs=1e-9)


@pytest.mark.parametrize("z", [7, 8, 9, 11, 12], ids=lambda z: f"z{z}")
def test_kim2002_table2_contact_angle(z: int) -> None:
    # predicted, not fitted: within 0.05 deg (observed at most 0.005 deg)
    assert math.degrees(_solve(z).contact_angle) == pytest.approx(TABLE2[z][0], abs=0.05)


@pytest.mark.parametrize("z", sorted(TABLE2), ids=lambda z: f"z{z}")
def test_kim2002_table2_deflections_documented_gap(z: int) -> None:
    # Documented discrepancy: ours are 12.4-15.2 % (inner) and 11.6-14.4 % (outer) below the
    # table. At the table's own angles the rigid-ring geometry fixes δ_i + δ_o independently of
    # the load and the modulus, so the gap belongs to the table, not to the contact law.
    r = _solve(z)
    _, d_i, d_o = TABLE2[z]
    assert r.inner_approach * 1e6 / d_i == pytest.approx(0.865, abs=0.02)
    assert r.outer_approach * 1e6 / d_o == pytest.approx(0.871, abs=0.02)


def test_kim2002_table2_total_deflection_is_geometric_at_printed_angles() -> None:
    # δ_i + δ_o = A (cos α⁰ / cos α - 1) with A = (f_i + f_o - 1) D and α⁰ from P_d = 5 um:
    # 3.04 um at 18.73 deg, whereas the table sums to 3.529 um.
    b = _bearing(FIT_Z)
    alpha = math.radians(TABLE2[FIT_Z][0])
    geometric = b.curvature_distance * (math.cos(b.free_contact_angle) / math.cos(alpha) - 1)
    assert geometric * 1e6 == pytest.approx(3.042, abs=1e-3)
    assert _solve(FIT_Z).total_approach == pytest.approx(geometric, rel=1e-9)


def test_kim2002_table2_speed_effects_too_small_to_explain_gap() -> None:
    # centrifugal force of one ball at the cage speed of 7200 rpm (f_c = 50 Hz, seed 001 §5.1)
    b = _bearing(FIT_Z)
    mass = b.material.density * math.pi / 6 * b.element_diameter**3
    centrifugal = mass * 0.5 * b.pitch_diameter * (2 * math.pi * 50.0) ** 2
    q = _solve(FIT_Z).ball_load
    assert centrifugal == pytest.approx(7.4e-3, rel=0.01)
    assert centrifugal / q < 5e-4  # 0.04 % of the ball load (≈ 18.9 N)
