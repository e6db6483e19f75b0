"""Seed 000 (Tada): 3-D quasi-static NRRO model against the paper's tables and conclusions.

Standard model of Table 1: outer ring rotating at 5400 rpm, constant-pressure preload 20 N,
d_m = 7 mm, D = 1 mm, Z = 8, E = 208 GPa, ν = 0.3, P_d = 10 µm. The paper gives no groove
conformities; we use 0.52 / 0.53 (stated in VALIDATION.md).
Inputs are peak-to-peak ("total amplitude") as in the paper.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from runout.analysis.spectrum import extract_lines
from runout.case.model import Case
from runout.models import quasi_static_3d as qs3
from runout.validation.seed000_tada import (
    TADA_CONCLUSION3_AMPLITUDES,
    TADA_FIG6,
    TADA_PP,
    tada_case,
    tada_frequencies,
    tada_line_pp,
    tada_second_order_lines,
)

# the example case of Table 2 (examples/seed000_tada_table2.toml: 72 revolutions, 0.8 s, the
# record of Fig. 7, 4096 instants), its waviness and loads changed per test
PP = TADA_PP


def _run(case: Case) -> np.ndarray:
    disp, _ = qs3.solve(case, qs3.time_grid_of(case))
    assert np.isfinite(disp).all()
    return disp


# --------------------------------------------------------------------------------------------
# Table 2: frequency and direction of every first-order line
# --------------------------------------------------------------------------------------------
def _table2_rows() -> list[tuple[str, str, int, str, int, str, int]]:
    """(id, part, lobes, direction, n, base frequency, ± f_r) per row of Table 2, Z = 8."""
    z = 8
    rows = []
    for n in (1, 2):
        rows += [
            (f"inner_nZ_n{n}", "inner", n * z, "z", n, "f_i", 0),
            (f"inner_nZ_plus_1_n{n}", "inner", n * z + 1, "xy", n, "f_i", 0),
            (f"inner_nZ_minus_1_n{n}", "inner", n * z - 1, "xy", n, "f_i", 0),
            (f"outer_nZ_n{n}", "outer", n * z, "z", n, "f_o", 0),
            (f"outer_nZ_plus_1_n{n}", "outer", n * z + 1, "xy", n, "f_o", 1),
            (f"outer_nZ_minus_1_n{n}", "outer", n * z - 1, "xy", n, "f_o", -1),
        ]
    return rows


@pytest.mark.parametrize(
    ("part", "lobes", "direction", "n", "base", "shift"),
    [r[1:] for r in _table2_rows()],
    ids=[r[0] for r in _table2_rows()],
)
def test_tada_table2_raceway(
    part: str, lobes: int, direction: str, n: int, base: str, shift: int
) -> None:
    case = tada_case([{"part": part, "order": lobes, "peak_to_peak": PP, "phase": 0.3}])
    f = tada_frequencies(case)
    freq = n * f[base] + shift * f["f_r"]
    disp = _run(case)
    pp = tada_line_pp(case, [freq], disp)[:, 0]
    radial = float(np.hypot(pp[0], pp[1]) / math.sqrt(2.0))
    main = radial if direction == "xy" else pp[2]
    assert main > 0.1 * PP
    if direction == "xy":
        assert pp[0] == pytest.approx(pp[1], rel=1e-6)  # a circle (§3.1 case 1)
        assert pp[2] <= 1e-3 * main
        # conclusion 1: equals the waviness p-p
        assert pp[0] == pytest.approx(PP, rel=1e-6)
    else:
        assert max(pp[0], pp[1]) <= 1e-3 * main


@pytest.mark.parametrize("n", [1, 2])
def test_tada_table2_ball_2n(n: int) -> None:
    lobes = 2 * n
    case = tada_case([{"part": "ball", "element": 1, "order": lobes, "peak_to_peak": PP}])
    f = tada_frequencies(case)
    f_minus = lobes * f["f_b"] - f["f_c"]
    f_plus = lobes * f["f_b"] + f["f_c"]
    f_axial = lobes * f["f_b"]
    disp = _run(case)
    pp = tada_line_pp(case, [f_minus, f_plus, f_axial], disp)
    axial_main = pp[2, 2]
    radial_main = max(pp[0, 0], pp[0, 1])
    assert axial_main > 0.05 * PP and radial_main > 0.05 * PP
    assert pp[0, 0] > 0.1 * radial_main and pp[0, 1] > 0.1 * radial_main
    assert max(pp[0, 2], pp[1, 2]) <= 1e-3 * radial_main
    assert max(pp[2, 0], pp[2, 1]) <= 1e-3 * axial_main


# --------------------------------------------------------------------------------------------
# Conclusion 1: radial first-order NRRO of an nZ±1 waviness = its p-p, whatever the bearing
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize("axial", [10.0, 20.0, 50.0])
@pytest.mark.parametrize("z", [6, 8, 12])
@pytest.mark.parametrize("clearance", [5e-6, 20e-6])
@pytest.mark.parametrize(("part", "sign"), [("inner", 1), ("outer", -1)])
def test_tada_conclusion1_first_order_equals_waviness(
    axial: float, z: int, clearance: float, part: str, sign: int
) -> None:
    lobes = z + sign
    case = tada_case(
        [{"part": part, "order": lobes, "peak_to_peak": PP, "phase": 1.0}],
        z=z,
        axial=axial,
        clearance=clearance,
        samples=1024,
        revolutions=16,
    )
    kin = qs3.setup(case).kinematics
    f_ring = kin.inner if part == "inner" else kin.outer
    m = -sign
    freq = abs((lobes + m) * kin.cage - lobes * f_ring)
    pp = tada_line_pp(case, [freq], _run(case))[:, 0]
    assert pp[0] == pytest.approx(PP, rel=1e-6)
    assert pp[1] == pytest.approx(PP, rel=1e-6)


# --------------------------------------------------------------------------------------------
# Conclusion 3 / Fig. 3: second-order elements grow with the square of the waviness
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("z", "lobes", "direction"),
    [(9, 5, "xy"), (9, 4, "xy"), (8, 4, "z")],
    ids=["Z9_outer_(Z+1)/2", "Z9_outer_(Z-1)/2", "Z8_outer_Z/2"],
)
def test_tada_conclusion3_second_order_square_law(z: int, lobes: int, direction: str) -> None:
    # the example case of Table 2 (outer ring turning), Z changed; lines as in VALIDATION.md
    multiple, lines = tada_second_order_lines(z, lobes, direction)
    assert multiple % z == 0
    amps = TADA_CONCLUSION3_AMPLITUDES
    exponent = math.log(lines[1] / lines[0]) / math.log(amps[1] / amps[0])
    assert lines[0] > 1e-13  # present, though small
    assert exponent == pytest.approx(2.0, abs=0.01)


# --------------------------------------------------------------------------------------------
# §3.2 / Fig. 6: Z-1 and Z+1 lobes on the stationary inner ring give an ellipse
# --------------------------------------------------------------------------------------------
# TADA_FIG6: (a7, ϑ7 [deg], a9, ϑ9 [deg], printed inclination φ [deg], Tada clockwise)


def tada_eq8_inclination(theta7_deg: float, theta9_deg: float, z: int = 8) -> float:
    """Our reconstruction of Tada's eq. 8 (lost in extraction), degrees clockwise, mod 180.

    With the waviness written as a(cos k(θ_T − ϑ_k)) in Tada's clockwise angle θ_T, the orbit
    is u = a_{Z+1} e^{-i(Ωt + (Z+1)ϑ_{Z+1})} + a_{Z-1} e^{i(Ωt + (Z-1)ϑ_{Z-1})} (counter-
    clockwise); its major axis lies where both phasors align, which in Tada's sense is
    φ = ((Z+1)ϑ_{Z+1} − (Z−1)ϑ_{Z−1}) / 2.
    """
    return ((z + 1) * theta9_deg - (z - 1) * theta7_deg) / 2.0 % 180.0


def test_tada_fig6_printed_inclinations_match_eq8_reconstruction() -> None:
    for _, t7, _, t9, printed in TADA_FIG6:
        diff = (tada_eq8_inclination(t7, t9) - printed) % 180.0
        assert min(diff, 180.0 - diff) < 1e-9


@pytest.mark.parametrize(("a7", "t7", "a9", "t9", "printed"), TADA_FIG6)
def test_tada_fig6_ellipse(a7: float, t7: float, a9: float, t9: float, printed: float) -> None:
    unit = 20e-9  # Fig. 6 amplitudes are relative; p-p in units of 20 nm
    # Tada's ϑ is an angular offset measured clockwise: r = a cos(k(θ_T − ϑ)) = a cos(kθ + kϑ)
    wav = [
        {"part": "inner", "order": 7, "peak_to_peak": a7 * unit, "phase": math.radians(7 * t7)},
        {"part": "inner", "order": 9, "peak_to_peak": a9 * unit, "phase": math.radians(9 * t9)},
    ]
    case = tada_case(wav, samples=2048, revolutions=8)
    disp = _run(case)
    # the orbit is one line at f_i in x and y: fit both, then the ellipse of the two phasors
    f_i = tada_frequencies(case)["f_i"]
    fit = extract_lines(qs3.time_grid_of(case), disp[:2], np.array([f_i]), axis=-1)
    amp, ph = fit.amplitude[:, 0], fit.phase[:, 0]
    m = np.array(
        [
            [amp[0] * math.cos(ph[0]), -amp[0] * math.sin(ph[0])],
            [amp[1] * math.cos(ph[1]), -amp[1] * math.sin(ph[1])],
        ]
    )
    u, sv, _ = np.linalg.svd(m)
    major, minor = 2 * sv[0], 2 * sv[1]
    assert major == pytest.approx((a7 + a9) * unit, rel=1e-6)
    assert minor == pytest.approx(abs(a7 - a9) * unit, rel=1e-6, abs=1e-6 * unit)
    incl_ccw = math.degrees(math.atan2(u[1, 0], u[0, 0]))
    incl_tada = (-incl_ccw) % 180.0
    diff = (incl_tada - printed) % 180.0
    assert min(diff, 180.0 - diff) < 1e-3


# --------------------------------------------------------------------------------------------
# nonlinear vs linearised at small amplitude (two independent methods)
# --------------------------------------------------------------------------------------------
def _mixed(scale: float) -> Case:
    wav = [
        {"part": "inner", "order": 5, "peak_to_peak": 3 * scale, "phase": 0.2},
        {"part": "outer", "order": 4, "peak_to_peak": 2 * scale, "phase": 1.1},
        {"part": "outer", "order": 11, "peak_to_peak": scale, "phase": 2.0},
        {"part": "ball", "element": 2, "order": 2, "peak_to_peak": scale},
    ]
    elements = {
        "diameter_errors": [scale] + [0.0] * 7,
        "pitch_errors": [0.0, 2 * scale / 3.5e-3] + [0.0] * 6,
    }
    return tada_case(wav, samples=512, revolutions=4, elements=elements)


def test_tada_nonlinear_matches_linearised_at_small_amplitude() -> None:
    gaps = []
    for scale in (1e-10, 2e-10):
        case = _mixed(scale)
        st = qs3.setup(case)
        t = qs3.time_grid_of(case)
        c, theta = qs3.approaches(case, st, t)
        # seed 000's frame (outer ring relative to inner) turned into the shaft's
        lin = -qs3.linearised_displacement(
            c, theta, st.contact_angle, st.stiffness, st.preload, st.force
        ).T
        nl, _ = qs3.solve(case, t, st)
        size = np.ptp(lin, axis=1).max()
        gap = np.abs(nl - lin).max()
        assert gap <= 1e-3 * size
        gaps.append(gap)
    # the gap is the second-order term: doubling the inputs quadruples it
    assert gaps[1] / gaps[0] == pytest.approx(4.0, rel=0.05)
