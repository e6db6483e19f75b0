"""equilibrium (Jones-Harris): balances, stiffness matrix, loads, options, output."""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.base.errors import GeometryError, NumericalError
from runout.case.model import parse_case
from runout.geometry.bearing import BallBearing, Operation
from runout.geometry.loading import axial_loading
from runout.models import equilibrium as eq
from runout.runner import run_model


def bearing(z: int = 10) -> BallBearing:
    return BallBearing(z, 1.5875e-3, 9.1e-3, 0.529, 0.535, 5e-6)


def _ring_balance(
    b: BallBearing, op: Operation, sol: eq.EquilibriumSolution, race_control: str = "outer"
) -> np.ndarray:
    """Loads recomputed from the per-ball outputs minus the applied (module docstring)."""
    lam_i = 2.0 if race_control == "inner" else 0.0
    psi, ai = sol.azimuth, sol.inner_contact_angle
    md = sol.gyroscopic_moment / b.element_diameter
    qa = sol.inner_load * np.sin(ai) - lam_i * md * np.cos(ai)
    qr = sol.inner_load * np.cos(ai) + lam_i * md * np.sin(ai)
    rad = 0.5 * b.pitch_diameter + (b.inner_conformity - 0.5) * b.element_diameter * math.cos(
        b.free_contact_angle
    )
    # unloaded balls exert nothing on the inner ring (no contact, no friction)
    qa, qr = np.where(sol.loaded, qa, 0.0), np.where(sol.loaded, qr, 0.0)
    qm = qa * rad + np.where(sol.loaded, lam_i * b.inner_conformity * sol.gyroscopic_moment, 0.0)
    got = np.array(
        [
            qa.sum(),
            (qr * np.cos(psi)).sum(),
            (qr * np.sin(psi)).sum(),
            (qm * np.sin(psi)).sum(),
            -(qm * np.cos(psi)).sum(),
        ]
    )
    want = np.array(
        [
            op.axial_load,
            op.radial_load * math.cos(op.radial_load_direction),
            op.radial_load * math.sin(op.radial_load_direction),
            op.moment_load * math.cos(op.moment_load_direction),
            op.moment_load * math.sin(op.moment_load_direction),
        ]
    )
    return got - want


def _ball_balance(
    b: BallBearing, sol: eq.EquilibriumSolution, race_control: str = "outer"
) -> np.ndarray:
    """Seed 001 eq. 3-4 recomputed from the outputs [N], shape (2, Z)."""
    lam_i, lam_o = {"outer": (0.0, 2.0), "inner": (2.0, 0.0), "none": (0.0, 0.0)}[race_control]
    ai, ao = sol.inner_contact_angle, sol.outer_contact_angle
    md = sol.gyroscopic_moment / b.element_diameter
    g1 = (
        sol.inner_load * np.sin(ai)
        - sol.outer_load * np.sin(ao)
        - md * (lam_i * np.cos(ai) - lam_o * np.cos(ao))
    )
    g2 = (
        sol.inner_load * np.cos(ai)
        - sol.outer_load * np.cos(ao)
        + md * (lam_i * np.sin(ai) - lam_o * np.sin(ao))
        + sol.centrifugal_force
    )
    return np.stack([g1, g2])


def _compatibility(b: BallBearing, sol: eq.EquilibriumSolution) -> np.ndarray:
    """Distance between groove centres along the two contact lines vs A_1, A_2 [m]."""
    d = b.element_diameter
    ri = (b.inner_conformity - 0.5) * d + sol.inner_approach
    ro = (b.outer_conformity - 0.5) * d + sol.outer_approach
    a1 = ri * np.sin(sol.inner_contact_angle) + ro * np.sin(sol.outer_contact_angle)
    a2 = ri * np.cos(sol.inner_contact_angle) + ro * np.cos(sol.outer_contact_angle)
    q, psi, a, a0 = sol.displacement, sol.azimuth, b.curvature_distance, b.free_contact_angle
    rad = 0.5 * b.pitch_diameter + (b.inner_conformity - 0.5) * d * math.cos(a0)
    want1 = a * math.sin(a0) + q[0] + rad * (q[3] * np.sin(psi) - q[4] * np.cos(psi))
    want2 = a * math.cos(a0) + q[1] * np.cos(psi) + q[2] * np.sin(psi)
    return np.concatenate([a1 - want1, a2 - want2])


@settings(max_examples=20, deadline=None)
@given(
    axial=st.floats(20.0, 150.0),
    radial=st.floats(0.0, 60.0),
    moment=st.floats(0.0, 0.1),
    direction=st.floats(0.0, 6.28),
    speed=st.floats(0.0, 1500.0),
    rotating=st.sampled_from(["inner", "outer"]),
    control=st.sampled_from(["outer", "inner", "none"]),
)
def test_equilibrium_satisfies_every_equation(
    axial: float,
    radial: float,
    moment: float,
    direction: float,
    speed: float,
    rotating: str,
    control: str,
) -> None:
    b = bearing()
    op = Operation(
        rotating,  # type: ignore[arg-type]
        speed,
        axial_load=axial,
        radial_load=radial,
        radial_load_direction=direction,
        moment_load=moment,
        moment_load_direction=direction + 1.0,
    )
    sol = eq.solve_equilibrium(b, op, race_control=control)
    loaded = sol.loaded
    assert np.all(np.isfinite(sol.displacement)) and np.all(np.isfinite(sol.stiffness))
    assert np.abs(_ring_balance(b, op, sol, control)[:3]).max() <= 1e-8 * axial
    assert np.abs(_ring_balance(b, op, sol, control)[3:]).max() <= 1e-8 * axial * 5e-3
    assert np.abs(_ball_balance(b, sol, control)[:, loaded]).max() <= 1e-8 * axial
    assert np.abs(_compatibility(b, sol).reshape(2, -1)[:, loaded]).max() <= 1e-15


@pytest.mark.parametrize(
    "op",
    [
        Operation("inner", 0.0, axial_load=60.68),
        Operation("inner", 120.0, axial_load=60.68, radial_load=30.0, moment_load=0.05),
        Operation("outer", 500.0, axial_load=40.0, radial_load=50.0, radial_load_direction=0.3),
        Operation("inner", 0.0, moment_load=0.1, moment_load_direction=0.4),
        Operation("inner", 900.0, moment_load=0.1, moment_load_direction=0.4),
    ],
    ids=[
        "axial_static",
        "combined_inner",
        "combined_outer_fast",
        "pure_moment_static",
        "pure_moment_fast",
    ],
)
def test_stiffness_matrix_matches_finite_differences(op: Operation) -> None:
    """Implicit-differentiation stiffness vs central differences of re-solved ring forces."""
    b = bearing()
    sol = eq.solve_equilibrium(b, op)
    ring = eq._Ring(b, op, "outer", speed_on=op.speed != 0.0)
    ring.set_angles(sol.inner_contact_angle, sol.outer_contact_angle)
    k_fd = np.zeros((5, 5))
    for k in range(5):
        h = 1e-10 if k < 3 else 1e-10 / ring.rad_i
        e = np.zeros(5)
        e[k] = h
        k_fd[:, k] = ring.forces(sol.displacement + e)[0] - ring.forces(sol.displacement - e)[0]
        k_fd[:, k] /= 2 * h
    assert np.abs(k_fd - sol.stiffness).max() <= 1e-7 * np.abs(sol.stiffness).max()


def test_axial_stiffness_matches_the_static_load_deflection_curve() -> None:
    b = bearing()
    sol = eq.solve_equilibrium(b, Operation("inner", 0.0, axial_load=60.68))
    df = 1e-3
    da = (
        axial_loading(b, 60.68 + df).axial_displacement
        - axial_loading(b, 60.68 - df).axial_displacement
    )
    assert sol.stiffness[0, 0] == pytest.approx(2 * df / da, rel=1e-7)
    # centred axial load: no coupling to the radial and tilt directions
    off = sol.stiffness.copy()
    np.fill_diagonal(off, 0.0)
    assert np.abs(off[0]).max() <= 1e-9 * sol.stiffness[0, 0]


@pytest.mark.parametrize("rpm", [0.0, 7200.0])
def test_pure_axial_load_reports_exactly_zero_radial_displacement_and_tilt(rpm: float) -> None:
    # the Newton round-off (~1e-21 m) used to be printed as 1e-15 µm
    sol = eq.solve_equilibrium(bearing(), Operation("inner", rpm / 60.0, axial_load=60.68))
    assert sol.displacement[0] > 0.0
    assert np.all(sol.displacement[1:] == 0.0)


def test_radial_load_loads_the_balls_under_it_symmetrically() -> None:
    b = bearing()
    op = Operation("inner", 0.0, axial_load=20.0, radial_load=80.0)  # along -y
    sol = eq.solve_equilibrium(b, op)
    assert sol.displacement[2] < 0.0
    # the ball nearest -y (ψ = 252°, 288°) carries most; mirror pairs about the y axis agree
    j = int(np.argmax(sol.inner_load))
    assert round(math.degrees(sol.azimuth[j])) in (252, 288)
    mirror = (15 - np.arange(10)) % 10  # ψ -> 180° - ψ
    np.testing.assert_allclose(sol.inner_load, sol.inner_load[mirror], rtol=1e-8, atol=1e-9)


def test_heavy_radial_load_unloads_balls_without_nan() -> None:
    # No axial preload: the balls away from the load have a radial gap of several µm, larger
    # than the inner groove's overlap at their outer-contact-only position, so they lift off.
    # (With a preload and a free tilt the gap stays small: the centrifugal force wedges those
    # balls between the outer groove and the inner groove's flank, and they carry load.)
    b = bearing()
    sol = eq.solve_equilibrium(b, Operation("inner", 300.0, radial_load=60.0))
    assert 0 < np.count_nonzero(~sol.loaded) < 10
    assert np.all(sol.inner_load[~sol.loaded] == 0.0)
    assert np.all(np.isfinite(sol.outer_load))
    # an unloaded ball is held by its centrifugal force on the outer race only
    assert sol.outer_load[~sol.loaded] == pytest.approx(sol.centrifugal_force[~sol.loaded])


def test_race_control_options_differ_only_by_the_gyroscopic_friction() -> None:
    b = bearing()
    op = Operation("inner", 1500.0, axial_load=60.68)
    out = eq.solve_equilibrium(b, op, race_control="outer")
    inn = eq.solve_equilibrium(b, op, race_control="inner")
    none = eq.solve_equilibrium(b, op, race_control="none")
    assert out.gyroscopic_moment[0] > 0.0
    for a, c in ((out, none), (inn, none), (out, inn)):
        assert not np.allclose(a.outer_contact_angle, c.outer_contact_angle, rtol=0, atol=1e-9)
    # all three keep the axial balance
    for s in (out, none):
        assert (s.inner_load * np.sin(s.inner_contact_angle)).sum() == pytest.approx(60.68)


def test_ball_speeds_reduce_to_seed001_eq7_and_eq9() -> None:
    alpha, g = 0.33, 1.5875 / 9.1
    c, s = math.cos(alpha), math.sin(alpha)
    wm, wr, sb, _ = eq.ball_speeds(c, s, c, s, g, 2 * math.pi * 120.0, 0.0, "outer")
    assert wm == pytest.approx(2 * math.pi * 120.0 * 0.5 * (1 - g * c), rel=1e-12)
    # outer-raceway control tilts the spin axis to tan β = sin α / (cos α + γ'); the spin is
    # eq. 9 divided by cos(α − β) (eq. 9 itself is the spin about an axis at β = α)
    beta = math.atan2(s, c + g)
    eq9 = 2 * math.pi * 120.0 * (1 - (g * c) ** 2) / (2 * g)
    assert wr == pytest.approx(eq9 / math.cos(alpha - beta), rel=1e-12)
    assert sb == pytest.approx(math.sin(beta), rel=1e-12)


def test_needs_a_load_and_a_known_control() -> None:
    with pytest.raises(GeometryError, match="axial load, a radial load or a moment"):
        eq.solve_equilibrium(bearing(), Operation("inner", 100.0))
    with pytest.raises(GeometryError, match="race_control"):
        eq.solve_equilibrium(bearing(), Operation("inner", 0.0, axial_load=10.0), race_control="x")


def test_radial_load_without_axial_on_zero_clearance_is_held() -> None:
    b = BallBearing(10, 1.5875e-3, 9.1e-3, 0.529, 0.535, 0.0)
    sol = eq.solve_equilibrium(b, Operation("inner", 0.0, radial_load=50.0))
    assert sol.displacement[2] < 0.0
    assert sol.residual <= 1e-6


@pytest.mark.parametrize(
    ("clearance", "rpm", "control"),
    [
        (0.0, 0.0, "outer"),
        (5e-6, 0.0, "outer"),
        (5e-6, 0.0, "inner"),
        (0.0, 7200.0, "outer"),
        (5e-6, 7200.0, "outer"),
        (5e-6, 54000.0, "none"),
        (20e-6, 54000.0, "outer"),
    ],
)
def test_moment_alone_holds_the_ring(clearance: float, rpm: float, control: str) -> None:
    # No axial and no radial force: the balls either side of the moment axis press on
    # opposite flanks of the grooves (contact angles of both signs) and hold the ring.
    b = BallBearing(10, 1.5875e-3, 9.1e-3, 0.529, 0.535, clearance)
    op = Operation("inner", rpm / 60.0, moment_load=0.1)
    sol = eq.solve_equilibrium(b, op, race_control=control)
    q, loaded = sol.displacement, sol.loaded
    scale = op.moment_load / (0.5 * b.pitch_diameter)
    assert np.abs(_ring_balance(b, op, sol, control)[:3]).max() <= 1e-8 * scale
    assert np.abs(_ring_balance(b, op, sol, control)[3:]).max() <= 1e-8 * op.moment_load
    assert np.abs(_ball_balance(b, sol, control)[:, loaded]).max() <= 1e-8 * scale
    assert np.abs(_compatibility(b, sol).reshape(2, -1)[:, loaded]).max() <= 1e-15
    # tilt about the moment vector (+x); centred in the axial play (δ_a from one-flank contact)
    assert q[3] > 0.0 and q[4] == 0.0
    assert q[0] == pytest.approx(-0.5 * b.free_end_play, rel=1e-9, abs=1e-18)
    # 10 balls: mirror symmetric across the moment axis, so no radial displacement either
    assert q[1] == 0.0 and q[2] == 0.0
    a_i = sol.inner_contact_angle[loaded]
    assert a_i.max() > 0.0 > a_i.min()


def test_reversed_moment_mirrors_the_solution() -> None:
    # M -> -M is the axial mirror image: same tilt magnitude, same ball loads, contact angles
    # of opposite sign (the Hertz constants are even in the contact angle)
    b = BallBearing(7, 1.5875e-3, 9.1e-3, 0.529, 0.535, 5e-6)
    fwd = eq.solve_equilibrium(b, Operation("inner", 120.0, moment_load=0.05))
    rev = eq.solve_equilibrium(
        b, Operation("inner", 120.0, moment_load=0.05, moment_load_direction=math.pi)
    )
    assert rev.displacement[3] == pytest.approx(-fwd.displacement[3], rel=1e-9)
    assert rev.displacement[:3] == pytest.approx(fwd.displacement[:3], rel=1e-9, abs=1e-16)
    np.testing.assert_allclose(rev.inner_load, fwd.inner_load, rtol=1e-8, atol=1e-12)
    np.testing.assert_allclose(
        rev.inner_contact_angle, -fwd.inner_contact_angle, rtol=1e-8, atol=1e-12
    )
    mg = float(np.abs(fwd.gyroscopic_moment).max())
    np.testing.assert_allclose(
        rev.gyroscopic_moment, -fwd.gyroscopic_moment, rtol=1e-8, atol=1e-12 * mg
    )


def test_pure_moment_held_by_two_balls_only_is_refused_clearly() -> None:
    # 4 balls, moment about the axis through two of them: only the other two can be loaded,
    # nothing holds the ring along that axis; a quarter-turned moment loads all four
    b = BallBearing(4, 1.5875e-3, 9.1e-3, 0.529, 0.535, 5e-6)
    with pytest.raises(NumericalError, match="fewer than 3 balls carry load"):
        eq.solve_equilibrium(b, Operation("inner", 0.0, moment_load=0.05))
    sol = eq.solve_equilibrium(
        b, Operation("inner", 0.0, moment_load=0.05, moment_load_direction=math.pi / 4)
    )
    assert sol.loaded.all()


def test_pure_moment_start_is_centred_and_carries_the_moment() -> None:
    b = BallBearing(7, 1.5875e-3, 9.1e-3, 0.529, 0.535, 5e-6)
    op = Operation("inner", 0.0, moment_load=0.05, moment_load_direction=1.0)
    ring = eq._Ring(b, op, "outer", speed_on=False)
    side = np.sin(ring.psi - 1.0)
    start = np.where(side < 0.0, -b.free_contact_angle, b.free_contact_angle)
    ring.set_angles(start, start)
    q = eq._moment_start(ring, op)
    assert q[0] == pytest.approx(-0.5 * b.free_end_play)
    assert q[1] == q[2] == 0.0
    assert math.atan2(q[4], q[3]) == pytest.approx(1.0)
    force = ring.forces(q)[0]
    carried = force[3] * math.cos(1.0) + force[4] * math.sin(1.0)
    assert 0.05 <= carried <= 0.05 * 1.01  # bracketed to 0.1 % of the tilt beyond the play


def _case(**extra: Any) -> Any:
    data: dict[str, Any] = {
        "title": "eq",
        "bearing": {
            "elements": 10,
            "element_diameter": "1.5875 mm",
            "pitch_diameter": "9.1 mm",
            "inner_conformity": 0.529,
            "outer_conformity": 0.535,
            "radial_clearance": "5 um",
        },
        "operation": {
            "speed": "7200 rpm",
            "axial_load": "60.68 N",
            "radial_load": "10 N",
            "moment_load": "20 N*mm",
            "moment_load_direction": "90 deg",
        },
        "analysis": {"model": "equilibrium", "race_control": "inner"},
    }
    data.update(extra)
    return parse_case(data)


def test_case_keys_and_json_output(tmp_path: Any) -> None:
    case = _case()
    assert case.operation.moment_load == pytest.approx(0.02)
    assert case.operation.moment_load_direction == pytest.approx(math.pi / 2)
    assert case.analysis.race_control == "inner"
    result = run_model(case)
    out = json.loads(json.dumps(result.to_json(), allow_nan=False))
    assert out["model"] == "equilibrium"
    assert out["components"] == []
    assert len(out["balls"]) == 10
    assert len(out["stiffness_matrix"]["matrix"]) == 5
    assert out["ring_displacement"]["tilt_x_rad"] != 0.0
    titles = [t for t, _ in result.summary_sections()]
    assert any("Balls" in t for t in titles)
    written = {p.name for p in result.write(tmp_path)}
    assert {"balls.csv", "stiffness.csv", "balls.png", "result.json"} <= written


@pytest.mark.parametrize(
    "op",
    [
        Operation(
            "inner",
            895.0,
            axial_load=23.5,
            radial_load=59.0,
            radial_load_direction=3.5625,
            moment_load=0.0859375,
            moment_load_direction=4.5625,
        ),
        Operation(
            "outer",
            764.0,
            axial_load=23.0,
            radial_load=24.0,
            radial_load_direction=3.5625,
            moment_load=0.0859375,
            moment_load_direction=4.5625,
        ),
    ],
    ids=["inner_895hz", "outer_764hz"],
)
def test_high_speed_radial_load_larger_than_preload_converges(op: Operation) -> None:
    # Radial load above the axial preload on a free-to-tilt single bearing at high speed: the
    # ring tilts by ~6 mrad and a lightly loaded ball is wedged by its centrifugal force.
    b = bearing()
    sol = eq.solve_equilibrium(b, op)
    loaded = sol.loaded
    assert abs(sol.displacement[4]) > 5e-3
    assert np.abs(_ring_balance(b, op, sol)[:3]).max() <= 1e-8 * op.axial_load
    assert np.abs(_ring_balance(b, op, sol)[3:]).max() <= 1e-8 * op.axial_load * 5e-3
    assert np.abs(_ball_balance(b, sol)[:, loaded]).max() <= 1e-8 * op.axial_load
    assert np.abs(_compatibility(b, sol).reshape(2, -1)[:, loaded]).max() <= 1e-15


def test_inner_race_control_ball_near_lift_off_converges() -> None:
    # Found by a random scan: under inner-race control one ball sits ~0.1 um from lift-off
    # and Newton from the usual starts stalled; the friction continuation solves it.
    b = bearing()
    op = Operation(
        "inner",
        484.88,
        axial_load=20.18,
        radial_load=49.16,
        radial_load_direction=4.717,
        moment_load=0.0593,
        moment_load_direction=5.717,
    )
    sol = eq.solve_equilibrium(b, op, race_control="inner")
    assert sol.loaded.all()
    assert sol.inner_approach.min() < 2e-7  # the lightly loaded ball
    assert np.abs(_ring_balance(b, op, sol, "inner")[:3]).max() <= 1e-8 * op.axial_load
    assert np.abs(_ring_balance(b, op, sol, "inner")[3:]).max() <= 1e-8 * op.axial_load * 5e-3
    assert np.abs(_ball_balance(b, sol, "inner")).max() <= 1e-8 * op.axial_load
    assert np.abs(_compatibility(b, sol)).max() <= 1e-15


# the ring's tilt held (analysis.ring_tilt = "held") ----------------------------------------
@settings(max_examples=20, deadline=None)
@given(
    axial=st.floats(20.0, 150.0),
    radial=st.floats(0.0, 60.0),
    direction=st.floats(0.0, 6.28),
    speed=st.floats(0.0, 1500.0),
    rotating=st.sampled_from(["inner", "outer"]),
    control=st.sampled_from(["outer", "inner", "none"]),
)
def test_held_tilt_balances_the_forces_and_reports_the_balls_moment_as_the_reaction(
    axial: float, radial: float, direction: float, speed: float, rotating: str, control: str
) -> None:
    b = bearing()
    op = Operation(
        rotating,  # type: ignore[arg-type]
        speed,
        axial_load=axial,
        radial_load=radial,
        radial_load_direction=direction,
    )
    sol = eq.solve_equilibrium(b, op, race_control=control, ring_tilt="held")
    loaded = sol.loaded
    assert sol.displacement[3] == 0.0 and sol.displacement[4] == 0.0
    assert sol.held_dofs == ("tilt_x", "tilt_y")
    balance = _ring_balance(b, op, sol, control)
    assert np.abs(balance[:3]).max() <= 1e-8 * axial
    # the moment equations are not imposed: their imbalance is the restraint's reaction,
    # recomputed here from the per-ball outputs (the moment load is 0)
    rad = 0.5 * b.pitch_diameter
    np.testing.assert_allclose(balance[3:], sol.reaction_moment, rtol=0, atol=1e-9 * axial * rad)
    assert np.abs(_ball_balance(b, sol, control)[:, loaded]).max() <= 1e-8 * axial
    assert np.abs(_compatibility(b, sol).reshape(2, -1)[:, loaded]).max() <= 1e-15
    assert sol.stiffness.shape == (5, 5) and np.all(np.isfinite(sol.stiffness))


def test_held_tilt_under_a_pure_axial_load_is_the_free_solution() -> None:
    # nothing tilts a uniformly loaded ring: holding it changes nothing and reacts nothing
    b = bearing()
    op = Operation("inner", 1200.0, axial_load=60.68)
    free = eq.solve_equilibrium(b, op)
    held = eq.solve_equilibrium(b, op, ring_tilt="held")
    np.testing.assert_allclose(held.displacement, free.displacement, rtol=1e-12, atol=1e-18)
    # entries ~1e-16 of the largest are the derivatives' round-off (STIFFNESS_ROUNDOFF)
    scale = np.abs(free.stiffness).max()
    np.testing.assert_allclose(held.stiffness, free.stiffness, rtol=1e-9, atol=1e-12 * scale)
    assert np.all(held.reaction_moment == 0.0) and free.held_dofs == ()


def test_held_tilt_with_balls_lifted_off_at_speed_converges() -> None:
    # the heavy radial load of test_heavy_radial_load_unloads_balls_without_nan, tilt held
    b = bearing()
    op = Operation("inner", 300.0, radial_load=60.0)
    sol = eq.solve_equilibrium(b, op, ring_tilt="held")
    assert 0 < np.count_nonzero(~sol.loaded) < 10
    assert np.abs(_ring_balance(b, op, sol)[:3]).max() <= 1e-8 * op.radial_load
    assert sol.displacement[3] == 0.0 and sol.displacement[4] == 0.0


def test_held_tilt_refuses_a_moment_and_an_unknown_value() -> None:
    op = Operation("inner", 0.0, axial_load=10.0, moment_load=0.01)
    with pytest.raises(GeometryError, match="moment_load"):
        eq.solve_equilibrium(bearing(), op, ring_tilt="held")
    with pytest.raises(GeometryError, match="ring_tilt"):
        eq.solve_equilibrium(bearing(), Operation("inner", 0.0, axial_load=10.0), ring_tilt="x")
