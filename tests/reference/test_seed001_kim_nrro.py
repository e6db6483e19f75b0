"""Seed 001 (Kim, Choi & Yoon) Tables 4-8, f_c column: NRRO of oversize balls, 2-D model.

Bearing of Table 1 at 7200 rpm under the 60.68 N preload fitted to Table 2 (18.73 deg at
Z = 10, tests/reference/test_kim_table2.py). Reading that reproduces the paper (see
VALIDATION.md): the 0.1 µm size error is on the *diameter*, and
the tabulated "NRRO component" is *peak-to-peak* (2 × the single amplitude).
"""

from __future__ import annotations

import numpy as np
import pytest

from runout.case import Case, parse_case
from runout.models import quasi_static_2d as qs2
from runout.spectrum import extract_lines

SPEED = 120.0
REVS, SAMPLES = 8, 1024
TABLE4_FC = {7: 54.02, 8: 47.75, 9: 42.72, 10: 38.60, 11: 35.18, 12: 32.30}
# Tables 5-8 (Z = 10): oversize balls -> f_c p-p [nm]
TABLES5_8_FC = {
    (1, 2): 74.38,
    (1, 3): 63.34,
    (1, 4): 46.12,
    (1, 5): 24.41,
    (1, 2, 3): 102.84,
    (1, 3, 5): 63.87,
    (1, 4, 7): 15.69,
    (1, 2, 3, 4): 121.20,
    (1, 3, 5, 7): 40.08,
    (1, 2, 3, 4, 5): 127.72,
    (1, 2, 4, 5, 8): 48.80,
}
SYMMETRIC = [(1, 6), (1, 4, 6, 9), (1, 2, 6, 7), (1, 3, 5, 7, 9)]  # printed 0.99 nm


def kim_case(z: int, oversize: tuple[int, ...]) -> Case:
    errors = [0.1e-6 if k + 1 in oversize else 0.0 for k in range(z)]
    return parse_case(
        {
            "bearing": {
                "type": "ball",
                "elements": z,
                "element_diameter": 1.5875e-3,
                "pitch_diameter": 9.1e-3,
                "inner_conformity": 0.529,
                "outer_conformity": 0.535,
                "radial_clearance": 5e-6,
            },
            "operation": {"rotating_ring": "inner", "speed": SPEED, "axial_load": 60.68},
            "elements": {"diameter_errors": errors},
            "analysis": {"model": "quasi_static_2d", "revolutions": REVS, "samples": SAMPLES},
        }
    )


def fc_pp_nm(case: Case, projection: qs2.ElementProjection = "none") -> float:
    st = qs2.setup(case)
    t = np.arange(SAMPLES) * (REVS / SPEED) / SAMPLES
    disp, _ = qs2.solve(case, t, st, element_projection=projection)
    fit = extract_lines(t, disp[:2], np.array([st.kinematics.cage]), axis=-1)
    pp = 2e9 * fit.amplitude[:, 0]
    assert pp[0] == pytest.approx(pp[1], rel=1e-6)  # a circle at f_c
    return float(pp[0])


@pytest.mark.parametrize("z", sorted(TABLE4_FC))
def test_kim_table4_fc_one_oversize_ball(z: int) -> None:
    ours = fc_pp_nm(kim_case(z, (1,)))
    # Eq. 10 as printed is 3.8-6.1 % above the table, falling with Z: a systematic gap,
    # explained in the validation notes (the table is not self-consistent with Table 5 to
    # better than ~3 %). We pin the sign and size of that documented gap.
    assert 0.03 < ours / TABLE4_FC[z] - 1.0 < 0.065


@pytest.mark.parametrize("z", sorted(TABLE4_FC))
def test_kim_table4_fc_radial_projection_reading(z: int) -> None:
    # Projecting the size error on the radial plane (× cos α) lands within 1.5 %
    ours = fc_pp_nm(kim_case(z, (1,)), "radial")
    assert ours == pytest.approx(TABLE4_FC[z], rel=0.03)


@pytest.mark.parametrize("balls", sorted(TABLES5_8_FC), ids=str)
def test_kim_tables5_8_fc_several_oversize_balls(balls: tuple[int, ...]) -> None:
    assert fc_pp_nm(kim_case(10, balls)) == pytest.approx(TABLES5_8_FC[balls], rel=0.03)


def test_kim_table6_balls_1_5_9_outlier() -> None:
    # Linear superposition gives |1 + e^{i 144°} + e^{i 288°}| = 0.618 × one ball: the
    # paper's 23.50 nm is 5 % below its own Table 5 trend; we match the trend.
    ours = fc_pp_nm(kim_case(10, (1, 5, 9)))
    one = fc_pp_nm(kim_case(10, (1,)))
    assert ours == pytest.approx(0.618 * one, rel=0.01)
    assert ours == pytest.approx(23.50, rel=0.06)


@pytest.mark.parametrize("balls", SYMMETRIC, ids=str)
def test_kim_symmetric_arrangements_cancel(balls: tuple[int, ...]) -> None:
    # printed 0.99 nm, a floor of the paper's spectrum; the balanced set cancels exactly
    assert fc_pp_nm(kim_case(10, balls)) < 1e-3


def test_kernel_matches_reference() -> None:
    case = kim_case(8, (1, 3))
    st = qs2.setup(case)
    t = np.arange(128) * (REVS / SPEED) / 128
    c, theta = qs2.approaches(case, st, t)
    ref = qs2.solve_reference(c, theta, tol=qs2.RTOL * st.initial_approach)
    disp, unloaded = qs2.solve(case, t, st)
    np.testing.assert_allclose(disp[:2], ref.T, rtol=0, atol=1e-9 * st.initial_approach)
    assert unloaded.max() == 0
