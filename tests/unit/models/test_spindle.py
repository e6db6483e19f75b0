"""The spindle model: a rigid shaft on two or more bearings (issue 20's checks).

Tada's conclusion 1 on a shaft, small-amplitude superposition, the lever of one bearing's
waviness, DB vs DF tilt stiffness against the pressure-centre spread, reduction to
quasi_static_3d, the stiffness matrix against finite differences, and the compiled kernel
against the NumPy reference.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np
import pytest

from runout.case.model import Case, parse_case
from runout.models import quasi_static_3d as qs3
from runout.models import spindle as sp
from runout.runner import run_model
from spindle_cases import TADA, spindle_case

A = 10e-9  # waviness amplitude [m]


def _wavy(
    bearing: str, *, amplitude: float = A, phase: float = 0.0, order: int = 9
) -> dict[str, Any]:
    return {
        "bearing": bearing,
        "part": "inner",
        "order": order,
        "amplitude": amplitude,
        "phase": phase,
    }


def _solve(case: Case) -> tuple[sp.Setup, np.ndarray, np.ndarray]:
    assert case.spindle is not None
    st = sp.setup(case.spindle, case.operation)
    t = sp.time_grid(case.operation.speed, case.analysis.revolutions, case.analysis.samples)
    q, _ = sp.solve(st, [b.imperfections for b in case.spindle.bearings], t)
    return st, t, q


def _case(waviness: list[dict[str, Any]], **kwargs: Any) -> Case:
    kwargs.setdefault("samples", 1024)
    return spindle_case(waviness, **kwargs)


def _nose_line(case: Case, order: int = 9) -> tuple[complex, complex, sp.Setup]:
    st, t, q = _solve(case)
    nose = sp.nose_record(st, q)
    # least-squares phasor of the Z+1 line |(k - 1) f_c - k f_i| (seed 000 Table 2; the
    # record does not hold whole periods of it)
    kin = st.bearings[0].kinematics
    freq = abs((order - 1) * kin.cage - order * kin.inner)
    basis = np.stack(
        [np.ones_like(t), np.cos(2 * np.pi * freq * t), np.sin(2 * np.pi * freq * t)], 1
    )
    out = []
    for row in nose[:2]:
        coef, *_ = np.linalg.lstsq(basis, row, rcond=None)
        out.append(complex(coef[1], -coef[2]))
    return out[0], out[1], st


# --------------------------------------------------------------------------------------------
# Tada's conclusion 1 on a shaft
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize("arrangement", ["DB", "DF"])
@pytest.mark.parametrize("preload", [{"preload": 20.0}, {"preload_displacement": 2e-6}])
def test_in_phase_z_plus_1_translates_without_tilt(
    arrangement: str, preload: dict[str, Any]
) -> None:
    """Identical in-phase Z+1 inner waviness on both bearings: the shaft translates by the
    waviness amplitude (seed 000 conclusion 1) and does not tilt."""
    case = _case([_wavy("front"), _wavy("rear")], arrangement=arrangement, preload=preload)
    result = run_model(case)
    radial = [c for c in result.components if c.direction == "x"]
    assert radial[0].pp_m == pytest.approx(2 * A, rel=1e-6)
    assert result.runout.radial_pp_m == pytest.approx(2 * A, rel=1e-5)
    tilt = result.details.tilt_pp_rad
    assert max(tilt) < 1e-12 * A / 12e-3
    for row in result.details.bearings:
        assert row.runout.radial_pp_m == pytest.approx(2 * A, rel=1e-5)


def test_superposition_small_amplitude() -> None:
    """front-only + rear-only = both, complex, within the linearisation error a / δ_pl."""
    a = 1e-9
    front = _wavy("front", amplitude=a, phase=0.3)
    rear = _wavy("rear", amplitude=a, phase=-1.1)
    xf, yf, st = _nose_line(_case([front]))
    xr, yr, _ = _nose_line(_case([rear]))
    xb, yb, _ = _nose_line(_case([front, rear]))
    bound = 3.0 * a * a / st.d_ref
    assert abs(xf + xr - xb) <= bound
    assert abs(yf + yr - yb) <= bound
    # and neither bearing alone is negligible: the check can fail
    assert min(abs(xf), abs(xr)) > 100 * bound


def test_lever_of_one_bearing_waviness() -> None:
    """One bearing's Z+1 waviness moves its pressure centre by the amplitude while the
    other's stays put: the nose moves by a |p_n - c_r| / |c_f - c_r| (c: pressure centres),
    below the lever about the rear ball-set plane."""
    x, y, st = _nose_line(_case([_wavy("front")]))
    front, rear = st.bearings
    pn = st.nose_position
    lever_pc = abs(pn - rear.pressure_centre) / abs(front.pressure_centre - rear.pressure_centre)
    lever_plane = abs(pn - rear.position) / abs(front.position - rear.position)
    assert abs(x) == pytest.approx(A * lever_pc, rel=1e-3)
    assert abs(y) == pytest.approx(A * lever_pc, rel=1e-3)
    assert abs(x) < A * lever_plane
    # the rear bearing's waviness: the lever about the front pressure centre
    x, _, _ = _nose_line(_case([_wavy("rear")]))
    lever_r = abs(pn - front.pressure_centre) / abs(front.pressure_centre - rear.pressure_centre)
    assert abs(x) == pytest.approx(A * lever_r, rel=1e-3)


# --------------------------------------------------------------------------------------------
# stiffness
# --------------------------------------------------------------------------------------------
def _stiffness(case: Case) -> tuple[sp.Setup, np.ndarray]:
    assert case.spindle is not None
    st = sp.setup(case.spindle, case.operation)
    return st, sp.static_stiffness(st)[1]


@pytest.mark.parametrize("preload", [{"preload": 20.0}, {"preload_displacement": 2e-6}])
def test_db_tilt_stiffer_than_df_by_the_pressure_centre_spread(preload: dict[str, Any]) -> None:
    """DB spreads the pressure centres outward, DF inward: the tilt stiffness about the nose
    is Σ k_r (c_b - p_n)^2 exactly (each bearing a point spring at its pressure centre: every
    contact line crosses the axis there) and DB's exceeds DF's."""
    out = {}
    for arrangement in ("DB", "DF"):
        st, k = _stiffness(_case([], arrangement=arrangement, preload=preload))
        # each bearing's radial stiffness from its balls (Σ over j of 1.5 K δ^1/2 cos²α cos²θ)
        kr = [
            1.5
            * b.stiffness
            * math.sqrt(b.approach)
            * math.cos(b.contact_angle) ** 2
            * b.kinematics.n_elements
            / 2.0
            for b in st.bearings
        ]
        textbook = sum(
            kb * (b.pressure_centre - st.nose_position) ** 2
            for kb, b in zip(kr, st.bearings, strict=True)
        )
        assert k[3, 3] == pytest.approx(textbook, rel=1e-9)
        assert k[4, 4] == pytest.approx(textbook, rel=1e-9)
        assert k[0, 0] == pytest.approx(sum(kr), rel=1e-9)
        spread = abs(st.bearings[1].pressure_centre - st.bearings[0].pressure_centre)
        out[arrangement] = (k[3, 3], spread)
    assert out["DB"][1] > 12e-3 > out["DF"][1]
    assert out["DB"][0] > out["DF"][0]


@pytest.mark.parametrize("preload", [{"preload": 20.0}, {"preload_displacement": 2e-6}])
def test_stiffness_matrix_matches_finite_differences(preload: dict[str, Any]) -> None:
    """K at the nose against the solved displacements under small load steps at the nose."""
    case = _case([], preload=preload, operation={"radial_load": 3.0, "moment_load": 0.01})
    st, k = _stiffness(case)
    q0, _ = sp.static_stiffness(st)
    pn = st.nose_position
    t = np.eye(5)
    t[0, 4], t[1, 3] = pn, -pn
    compliance = np.linalg.inv(k)
    for col, size in enumerate([0.05, 0.05, 0.05, 5e-4, 5e-4]):
        moves = []
        for sign in (1.0, -1.0):
            df_nose = np.zeros(5)
            df_nose[col] = sign * size
            df = t.T @ df_nose  # the generalised load at the origin of a load at the nose
            force = st.force.copy()
            force[:5] += df
            q, _ = sp.static_stiffness(dataclasses.replace(st, force=force))
            moves.append(t @ (q[:5] - q0[:5]))
        fd = (moves[0] - moves[1]) / (2 * size)
        np.testing.assert_allclose(
            fd, compliance[:, col], rtol=1e-4, atol=1e-6 * np.abs(compliance[:, col]).max()
        )
    assert np.allclose(k, k.T, rtol=1e-9, atol=1e-9 * np.abs(k).max())


def test_forces_jacobian_is_the_stiffness() -> None:
    """Σ Q g differentiated numerically at the static solution equals the Hessian."""
    case = _case([], operation={"radial_load": 3.0})
    st = sp.setup(case.spindle, case.operation)  # type: ignore[arg-type]
    q0, _ = sp.static_stiffness(st)
    cth, sth = sp._nominal_angles(st)
    c = sp._nominal_c(st)
    h = sp._hessian(st, c, cth, sth, q0)
    for a in range(st.n_dof):
        step = np.zeros(st.n_dof)
        step[a] = 1e-9 / st.scale[a]
        fd = (
            sp.generalised_forces(st, c, cth, sth, q0 + step)
            - sp.generalised_forces(st, c, cth, sth, q0 - step)
        ) / (2 * step[a])
        np.testing.assert_allclose(fd, h[:, a], rtol=1e-5, atol=1e-6 * np.abs(h).max())


# --------------------------------------------------------------------------------------------
# reductions and the reference solve
# --------------------------------------------------------------------------------------------
def test_reduces_to_quasi_static_3d_with_a_far_stiff_bearing() -> None:
    """The front bearing with a stiff bearing 100 m behind it: the shaft at the front moves as
    seed 000's inner ring under the same spring preload (the rear carries no radial load and
    the tilt it allows reaches the front's contacts as R tan α / L)."""
    big = dict(TADA, elements=40, element_diameter=4e-3, pitch_diameter=60e-3)
    waviness = [_wavy("front", order=9), _wavy("front", order=16, amplitude=5e-9, phase=0.4)]
    case = _case(
        waviness, positions=(0.0, 100.0), nose=0.0, bearings=[dict(TADA), big], samples=512
    )
    st, t, q = _solve(case)
    spindle_disp = sp.nose_record(st, q)
    single = parse_case(
        {
            "bearing": dict(TADA),
            "operation": {"speed": 90.0, "axial_load": 20.0},
            "waviness": [{k: v for k, v in w.items() if k != "bearing"} for w in waviness],
            "analysis": {"model": "quasi_static_3d", "samples": 512, "revolutions": 8},
        }
    )
    qs_disp, _ = qs3.solve(single, t)
    diff = (spindle_disp - spindle_disp.mean(axis=1, keepdims=True)) - (
        qs_disp - qs_disp.mean(axis=1, keepdims=True)
    )
    assert np.abs(diff).max() < 1e-4 * np.ptp(qs_disp[0])
    assert np.ptp(qs_disp[2]) > 1e-9  # the order-16 = 2Z waviness moves it axially too
    assert np.abs(diff[2]).max() < 1e-6 * np.ptp(qs_disp[2])


@pytest.mark.parametrize("preload", [{"preload": 20.0}, {"preload_displacement": 2e-6}])
def test_kernel_matches_numpy_reference(preload: dict[str, Any]) -> None:
    waviness = [
        _wavy("front", order=9, phase=0.2),
        _wavy("rear", order=7, amplitude=20e-9, phase=1.0),
        {"bearing": "rear", "part": "ball", "order": 2, "amplitude": 15e-9, "element": 3},
        {"bearing": "front", "part": "outer", "order": 8, "amplitude": 8e-9},
    ]
    case = _case(
        waviness,
        preload=preload,
        operation={"radial_load": 4.0, "moment_load": 0.02, "axial_load": 3.0},
        samples=256,
    )
    st, t, q = _solve(case)
    c, cth, sth = sp.contact_arrays(st, [b.imperfections for b in case.spindle.bearings], t)  # type: ignore[union-attr]
    ref = sp.solve_reference(st, c, cth, sth, tol=1e-12 * st.d_ref)
    np.testing.assert_allclose(q[:, :3], ref[:, :3], rtol=0, atol=1e-9 * st.d_ref)
    np.testing.assert_allclose(
        q[:, 3:5] * st.scale[3], ref[:, 3:5] * st.scale[3], rtol=0, atol=1e-9 * st.d_ref
    )
    # and the balance holds at every instant
    for i in range(0, t.size, 37):
        r = sp.generalised_forces(st, c[i], cth[i], sth[i], q[i]) - st.force
        assert np.abs(r[:3]).max() < 1e-9 * 20.0
        assert np.abs(r[3:5]).max() < 1e-9 * 20.0 * st.scale[3]


def test_radial_load_at_the_nose_and_moment_balance() -> None:
    """A radial load at the nose: the static position satisfies the force and moment balance
    with the load's moment p_n × F, and the bearings share the load by the lever."""
    case = _case([], operation={"radial_load": 10.0, "radial_load_direction": 0.0})
    st = sp.setup(case.spindle, case.operation)  # type: ignore[arg-type]
    assert st.force[0] == pytest.approx(10.0)
    assert st.force[4] == pytest.approx(st.nose_position * 10.0)
    q, _ = sp.static_stiffness(st)
    assert q[0] > 0.0  # the shaft moves along the load
    cth, sth = sp._nominal_angles(st)
    balance = sp.generalised_forces(st, sp._nominal_c(st), cth, sth, q)
    np.testing.assert_allclose(balance, st.force, rtol=0, atol=1e-9 * 20.0)
    # the overhung load (nose in front of the front bearing) loads the front more
    loads = sp.ball_loads(st, q)
    assert loads[:8].max() > loads[8:].max()


def test_position_preload_sets_equal_approaches() -> None:
    case = _case([], preload={"preload_displacement": 2e-6})
    st = sp.setup(case.spindle, case.operation)  # type: ignore[arg-type]
    for b in st.bearings:
        assert b.approach == pytest.approx(1e-6 * math.sin(b.contact_angle), rel=1e-12)
        assert b.axial_load == pytest.approx(
            b.stiffness * 8 * b.approach**1.5 * math.sin(b.contact_angle), rel=1e-12
        )
    assert st.n_dof == 5


def test_spring_preload_floats_the_rear_group() -> None:
    case = _case([], operation={"axial_load": 5.0})
    st = sp.setup(case.spindle, case.operation)  # type: ignore[arg-type]
    assert st.n_dof == 6 and st.force[5] == 20.0
    assert [b.floating for b in st.bearings] == [False, True]
    q, _ = sp.static_stiffness(st)
    cth, sth = sp._nominal_angles(st)
    forces = sp.generalised_forces(st, sp._nominal_c(st), cth, sth, q)
    np.testing.assert_allclose(forces, st.force, atol=1e-9 * 20)


@pytest.mark.parametrize(
    ("arrangement", "signs"), [("DB", [1, -1]), ("DF", [-1, 1]), ("DT", [1, 1])]
)
def test_thrust_signs(arrangement: str, signs: list[int]) -> None:
    assert sp.thrust_signs([0.0, 0.012], arrangement) == signs
    assert sp.thrust_signs([0.0, 0.01, 0.02, 0.03], "DB") == [1, 1, -1, -1]


def test_three_bearings_run() -> None:
    case = _case([_wavy("third")], positions=(0.0, 6e-3, 20e-3))
    result = run_model(case)
    assert [b.name for b in result.details.bearings] == ["front", "rear", "third"]
    assert result.runout.radial_pp_m > 0.0


def test_shares_of_a_line_two_bearings_make_follow_their_levers() -> None:
    """The in-phase Z+1 line of both bearings: each bearing's share is its pressure-centre
    lever to the nose (front (p_n - a_r)/(a_f - a_r), rear the rest; they add up to 1)."""
    case = _case([_wavy("front"), _wavy("rear")])
    result = run_model(case)
    st = sp.setup(case.spindle, case.operation)  # type: ignore[arg-type]
    front, rear = st.bearings
    lever = (st.nose_position - rear.pressure_centre) / (
        front.pressure_centre - rear.pressure_centre
    )
    line = next(c for c in result.components if c.direction == "x")
    shares = {s.term.rsplit("(", 1)[1].split()[0]: s for s in line.sources}
    assert shares["front"].share == pytest.approx(lever, rel=1e-3)
    assert shares["rear"].share == pytest.approx(1.0 - lever, rel=1e-2)
    assert shares["front"].share_basis == "predicted"
