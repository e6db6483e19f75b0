"""Seed 001 (Kim, Choi & Yoon) Tables 4-8: NRRO of oversize balls, 2-D model.

Bearing of Table 1 at 7200 rpm under the 60.68 N preload fitted to Table 2 (18.73 deg at
Z = 10, tests/reference/test_kim_table2.py). Conventions that reproduce the paper (see
VALIDATION.md): the 0.1 µm size error is on the *diameter*, the tabulated "NRRO component" is
*peak-to-peak* (2 × the single amplitude), and it is what a Hann FFT of a finite record shows,
which carries a constant ~1 nm line at f_c (`runout.validation.seed001_kim.kim_fft_reading`).
Our own output is the exact (leakage-free) line.
"""

from __future__ import annotations

import numpy as np
import pytest

from runout.analysis.spectrum import amplitude_spectrum, extract_lines, peak_bin_gain
from runout.case.model import Case, parse_case
from runout.models import quasi_static_2d as qs2
from runout.validation.seed001_kim import (
    KIM_FLOOR,
    KIM_SYMMETRIC,
    KIM_TABLE4,
    KIM_TABLE4_FORM_Z10,
    KIM_TABLES5_8,
    kim_cage_hz,
    kim_fft_reading,
    kim_form_ratio,
    kim_lines,
    kim_read_nm,
)

SPEED = 120.0
REVS, SAMPLES = 8, 1024
TABLE4_FC = KIM_TABLE4
# Tables 5-8 (Z = 10): oversize balls -> f_c p-p [nm], the outlier (1, 5, 9) apart
TABLES5_8_FC = {balls: row[1] for balls, row in KIM_TABLES5_8.items() if balls != (1, 5, 9)}
SYMMETRIC = KIM_SYMMETRIC  # printed KIM_FLOOR = 0.99 nm


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
def test_kim_table4_exact_line_is_the_ball_set_geometry(z: int) -> None:
    # One ball Δd oversize pushes the shaft 2Δd/Z away from it (all balls loaded, equal
    # stiffness): p-p 4Δd/Z, plus a small Hertz (δ^1.5) gain that grows as δ_0 shrinks.
    ours = fc_pp_nm(kim_case(z, (1,)))
    linear = 4 * 0.1e3 / z  # nm
    assert 0.001 < ours / linear - 1.0 < 0.01


@pytest.mark.parametrize("z", sorted(TABLE4_FC))
def test_kim_table4_fc_as_the_paper_read_it(z: int) -> None:
    # The printed column is a Hann-FFT reading with a 1 nm floor (VALIDATION.md): two
    # parameters identified from the 18 f_c values of Tables 4-8 reproduce every one of them.
    read = kim_read_nm("seed001_kim_table4.toml", z, (1,))
    assert read == pytest.approx(TABLE4_FC[z], rel=0.005)


@pytest.mark.parametrize("balls", [*sorted(TABLES5_8_FC), (1, 5, 9)], ids=str)
def test_kim_tables5_8_fc_as_the_paper_read_it(balls: tuple[int, ...]) -> None:
    read = kim_read_nm("seed001_kim_tables5_8.toml", 10, balls)
    assert read == pytest.approx(KIM_TABLES5_8[balls][1], rel=0.005)


def test_kim_reading_identification_is_tight() -> None:
    r = kim_fft_reading()
    assert r.rows == 18
    assert r.misfit < 0.005
    assert 0.25 < r.duration < 4.0
    # the floor's size is the printed 0.99 nm before the window's loss
    gain = float(peak_bin_gain(kim_cage_hz("seed001_kim_tables5_8.toml", 10), r.duration))
    assert gain * abs(r.floor) == pytest.approx(KIM_FLOOR, rel=1e-9)


def test_the_reading_model_is_a_literal_hann_fft_of_our_record() -> None:
    # Run the 2-D model over the identified record, add the floor line, take the Hann
    # amplitude spectrum and read the bin nearest f_c: the same as FftReading.read.
    r = kim_fft_reading()
    for z, balls in ((7, (1,)), (10, (1, 4, 7))):
        case = kim_case(z, balls)
        st = qs2.setup(case)
        fc = st.kinematics.cage
        n = 8192
        t = np.arange(n) * (r.duration / n)
        disp, _ = qs2.solve(case, t, st)
        floor = 0.5e-9 * abs(r.floor) * np.cos(2 * np.pi * fc * t + np.angle(r.floor))
        spec = amplitude_spectrum(disp[0] + floor, time=t, window="hann")
        read = 2e9 * spec.amplitude[round(fc * r.duration)]
        line = kim_lines(
            "seed001_kim_tables5_8.toml" if z == 10 else "seed001_kim_table4.toml", z, balls
        )[0]
        assert read == pytest.approx(r.read(fc, line), rel=2e-3)


@pytest.mark.parametrize("balls", [*sorted(TABLES5_8_FC), (1, 5, 9)], ids=str)
@pytest.mark.parametrize("column", [0, 1], ids=["2fb-fc", "2fb+fc"])
def test_kim_tables5_8_form_error_columns_follow_one_ball(
    balls: tuple[int, ...], column: int
) -> None:
    # The 2 f_b -/+ f_c lines of identical balls (same order-2 waviness and spin phase) add
    # like the f_c lines. Two printed entries repeat a neighbouring number instead.
    table = KIM_TABLES5_8[balls]
    printed = table[2 + column] / KIM_TABLE4_FORM_Z10[column]
    ours = kim_form_ratio(balls, column)
    superposition = abs(sum(np.exp(2j * np.pi * (k - 1) / 10) for k in balls))
    assert ours == pytest.approx(superposition, rel=2e-3)
    if (balls, column) == ((1, 4, 7), 0):
        assert table[2] == table[3]  # 2.59 twice
        assert ours == pytest.approx(printed, rel=0.07)
    elif (balls, column) == ((1, 2, 3, 4, 5), 1):
        assert table[3] == KIM_TABLES5_8[(1, 2, 3, 4)][3]  # 20.85, Table 7's
        assert ours == pytest.approx(printed, rel=0.06)
    else:
        assert ours == pytest.approx(printed, rel=0.01)


def test_radial_projection_option_scales_the_line_by_cos_alpha() -> None:
    case = kim_case(10, (1,))
    st = qs2.setup(case)
    ratio = fc_pp_nm(case, "radial") / fc_pp_nm(case)
    assert ratio == pytest.approx(np.cos(st.contact_angle), rel=2e-3)


@pytest.mark.parametrize("balls", sorted(TABLES5_8_FC), ids=str)
def test_kim_tables5_8_fc_several_oversize_balls(balls: tuple[int, ...]) -> None:
    assert fc_pp_nm(kim_case(10, balls)) == pytest.approx(TABLES5_8_FC[balls], rel=0.03)


def test_kim_table6_balls_1_5_9_outlier() -> None:
    # Linear superposition gives |1 + e^{i 144°} + e^{i 288°}| = 0.618 × one ball. The exact
    # line is 5 % above the printed 23.50 nm: this arrangement's phase is nearly opposite the
    # paper's floor line, which lowers its reading (test_kim_tables5_8_fc_as_the_paper_read_it).
    ours = fc_pp_nm(kim_case(10, (1, 5, 9)))
    one = fc_pp_nm(kim_case(10, (1,)))
    assert ours == pytest.approx(0.618 * one, rel=0.01)
    assert ours == pytest.approx(KIM_TABLES5_8[(1, 5, 9)][1], rel=0.06)  # 23.50


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
