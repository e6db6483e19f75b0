"""dynamic model (seed 003): kernels against NumPy references, contact law, set-up, errors."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from cases import WAVY, dynamic_case
from runout.base.errors import CaseError, ConvergenceError, GeometryError, NumericalError
from runout.case.model import parse_case
from runout.geometry.bearing import BallBearing
from runout.geometry.loading import axial_loading
from runout.models import dynamic as dy
from runout.models._quasi_static import Kinematics

make_case = dynamic_case


# --------------------------------------------------------------------------------------------
# contact law
# --------------------------------------------------------------------------------------------
@settings(max_examples=40, deadline=None)
@given(
    x=st.floats(-2e-6, 2e-6),
    y=st.floats(-2e-6, 2e-6),
    t=st.floats(0.0, 0.05),
    elements=st.integers(5, 15),
)
def test_zero_preload_force_is_seed003_eq_2_5(x: float, y: float, t: float, elements: int) -> None:
    # without preload and waviness the exact geometry reduces to eq. 2.4-2.5 with γ = P_d/2
    case = make_case(elements=elements, clearance=0.2e-6)
    s = dy.setup(case)
    force, d = dy.contact_forces(s, np.array([t]), np.array([[x, y, 0.0]]))
    theta = s.theta0 + 2 * math.pi * s.kinematics.cage * t
    bracket = x * np.cos(theta) + y * np.sin(theta) - 0.1e-6
    q = s.stiffness * np.clip(bracket, 0.0, None) ** 1.5
    expected = np.array([(q * np.cos(theta)).sum(), (q * np.sin(theta)).sum()])
    assert np.allclose(d[0], bracket, rtol=0, atol=1e-18)
    scale = s.stiffness * 2e-6**1.5
    assert np.allclose(force[0, :2], expected, rtol=1e-12, atol=1e-12 * scale)


@settings(max_examples=30, deadline=None)
@given(
    q=st.lists(st.floats(-1.5e-6, 1.5e-6), min_size=3, max_size=3),
    t=st.floats(0.0, 0.02),
    axial=st.sampled_from([0.0, 10.0, 80.0]),
    ndof=st.sampled_from([False, True]),
)
def test_kernel_contact_jacobian_matches_finite_differences(
    q: list[float], t: float, axial: float, ndof: bool
) -> None:
    case = make_case(axial=axial, waviness=WAVY, dynamics={"axial_dof": ndof}, radial=6.0)
    s = dy.setup(case)
    par = s.params(1e-6)
    z = s.n_elements
    cth, sth, gap, wb = (np.empty(z) for _ in range(4))
    dy._deviations(t, par, s.theta0, s.harmonics, cth, sth, gap, wb)
    out = dy._contact(
        *q, cth, sth, gap, wb, s.curvature_distance, s.axial_offset, s.stiffness, s.ndof
    )
    f_ref, approach = dy.contact_forces(s, np.array([t]), np.array([q]))
    scale = s.stiffness * s.reference_approach**1.5 + 1e-3
    assert np.allclose(out[:3][: s.ndof], f_ref[0, : s.ndof], rtol=1e-10, atol=1e-10 * scale)
    kmat = np.array([[out[3], out[4], out[5]], [out[4], out[6], out[7]], [out[5], out[7], out[8]]])[
        : s.ndof, : s.ndof
    ]
    # The central-difference reference (step h = 1e-4 δ_ref) is only accurate when no ball is
    # within 100 h of opening or closing its contact: the Hertz stiffness ~ δ^1/2 bends sharply
    # there (relative error ~ 0.04 (h/δ)^2).
    assume(np.abs(approach).min() > 1e-2 * s.reference_approach)
    k_fd = dy.contact_stiffness(s, t, np.array(q))
    kscale = np.abs(k_fd).max() + 1.0
    assert np.allclose(kmat, k_fd, rtol=1e-5, atol=1e-5 * kscale)


def test_preloaded_contact_angle_matches_axial_loading() -> None:
    case = make_case(axial=30.0)
    b = case.bearing
    alpha, kn = dy.preloaded_contact_angle(b, 30.0, b.free_contact_angle, "exact")
    ref = axial_loading(b, 30.0)
    assert alpha == pytest.approx(ref.contact_angle, abs=1e-12)
    assert kn == pytest.approx(ref.combined_stiffness, rel=1e-12)


def test_preloaded_contact_angle_zero_clearance_is_eq_2_21() -> None:
    # seed 003 eq. 2.21 with the number of balls as its leading factor and B d_b = A
    case = make_case(clearance=0.0, axial=50.0)
    b = case.bearing
    alpha, kn = dy.preloaded_contact_angle(b, 50.0, 0.0, "exact")
    pl = b.elements * kn * (b.curvature_distance * (1 / math.cos(alpha) - 1)) ** 1.5
    assert pl * math.sin(alpha) == pytest.approx(50.0, rel=1e-10)


def test_delta_star_law_close_to_exact() -> None:
    b = make_case().bearing
    exact = dy._law_stiffness(b, 0.1, "exact")
    table = dy._law_stiffness(b, 0.1, "delta_star_table")
    assert table != exact
    assert table == pytest.approx(exact, rel=5e-3)


def test_preload_holds_axial_position() -> None:
    # with the axial DOF and no radial load the preloaded position z_p is the equilibrium
    case = make_case(axial=40.0, radial=0.0, dynamics={"axial_dof": True})
    s = dy.setup(case)
    q = dy.static_equilibrium(s, np.array([0.0]))[0]
    assert np.max(np.abs(q)) < 1e-6 * s.reference_approach
    f, _ = dy.contact_forces(s, np.array([0.0]), np.zeros((1, 3)))
    assert f[0, 2] == pytest.approx(40.0, rel=1e-9)
    fn = dy.linearised_natural_frequencies(s, q)
    assert fn.size == 3 and np.all(fn > 0)


# --------------------------------------------------------------------------------------------
# kernels against NumPy references
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("axial", "ndof", "unbalance"),
    [(0.0, False, 0.0), (20.0, False, 1e-7), (20.0, True, 1e-7)],
)
def test_newmark_kernel_matches_reference(axial: float, ndof: bool, unbalance: float) -> None:
    case = make_case(
        axial=axial, waviness=WAVY, dynamics={"axial_dof": ndof, "unbalance": unbalance}
    )
    s = dy.setup(case)
    q0 = dy.static_equilibrium(s, np.array([0.0]))[0]
    state = np.zeros(9)
    state[:3] = q0 + np.array([3e-8, -2e-8, 1e-8 if ndof else 0.0])
    h, n = 5e-6, 150
    ref = dy.newmark_reference(s, h, n, state.copy())
    out = np.zeros((n, 3))
    work = state.copy()
    status, _, _, _ = dy.newmark_kernel(
        n, 1, 0.0, work, s.params(h), s.theta0, s.harmonics, s.ndof, dy.MAX_ITER, out
    )
    assert status == dy.OK
    motion = np.ptp(ref, axis=0).max()
    assert motion > 1e-9
    assert np.max(np.abs(out - ref)) < 1e-8 * motion


def test_static_kernel_matches_reference() -> None:
    case = make_case(axial=0.0, waviness=WAVY, dynamics={"unbalance": 1e-6})
    s = dy.setup(case)
    t = np.linspace(0.0, 0.02, 60)
    q = dy.static_equilibrium(s, t)
    ref = dy.static_reference(s, t)
    assert np.max(np.abs(q - ref)) < 1e-9 * s.reference_approach
    force, _ = dy.contact_forces(s, t, q)
    assert np.allclose(force[:, :2], dy.external_force(s, t)[:, :2], rtol=0, atol=1e-8)


# --------------------------------------------------------------------------------------------
# set-up and errors
# --------------------------------------------------------------------------------------------
def test_load_direction_and_natural_frequencies() -> None:
    s = dy.setup(make_case())
    q = dy.static_equilibrium(s, np.array([0.0]))[0]
    assert q[1] < -0.1e-6  # load along -y: the rotor drops by more than the radial play
    assert abs(q[0]) < 1e-3 * abs(q[1])
    fn = dy.linearised_natural_frequencies(s, q)
    k = dy.contact_stiffness(s, 0.0, q)
    assert np.allclose(np.sort((2 * np.pi * fn) ** 2 * 0.6), np.sort(np.linalg.eigvalsh(k)))


def test_free_contact_angle_from_the_clearance_only() -> None:
    # a free angle α⁰ = 5° given as its diametral play P_d = 2A(1 - cos α⁰), A = (f_i+f_o-1)D
    a = 4.08e-3 + 4.61e-3 - 7.96e-3
    clearance = 2.0 * a * (1.0 - math.cos(math.radians(5.0)))
    case = make_case(clearance=clearance, axial=20.0)
    s = dy.setup(case)
    assert s.curvature_distance == pytest.approx(a, rel=1e-12)
    assert s.free_contact_angle == pytest.approx(math.radians(5.0), rel=1e-9)
    assert s.radial_gap == -0.5 * clearance  # the user's clearance, unchanged
    assert s.contact_angle > math.radians(5.0)  # the preload opens the angle
    assert not s.notes


def test_fixed_contact_angle_is_refused() -> None:
    # an operating contact angle held fixed is not honoured by the dynamic model: refused,
    # not read as something else
    case = make_case(axial=20.0)
    bearing = case.bearing
    assert isinstance(bearing, BallBearing)
    fixed = dataclasses.replace(
        case, bearing=dataclasses.replace(bearing, contact_angle=math.radians(5.0))
    )
    with pytest.raises(GeometryError, match=r"bearing\.contact_angle"):
        dy.setup(fixed)


def test_missing_dynamics_and_bad_inputs() -> None:
    case = make_case()
    bare = parse_case(
        {
            "bearing": case.spec.bearing.model_dump(exclude_none=True),
            "operation": {"speed": 10.0},
            "analysis": {"model": "dynamic"},
        }
    )
    with pytest.raises(GeometryError, match="dynamics"):
        dy.run(bare)
    with pytest.raises(GeometryError, match="radial load or an axial preload"):
        dy.setup(make_case(radial=0.0, axial=0.0, dynamics={"axial_dof": True}))
    with pytest.raises(GeometryError, match="speed"):
        dy.setup(make_case(speed=0.0))
    with pytest.raises(CaseError, match="contact_law"):
        make_case(dynamics={"contact_law": "table"})


def test_no_convergence_names_step_and_time() -> None:
    s = dy.setup(make_case())
    state = np.zeros(9)
    out = np.zeros((10, 3))
    status, step, _, _ = dy.newmark_kernel(
        10, 1, 0.0, state, s.params(1e-5), s.theta0, s.harmonics, s.ndof, 1, out
    )
    assert status == dy.NOT_CONVERGED and step == 0
    with pytest.raises(ConvergenceError, match=r"at instant 0 \(t = 1e-05\)"):
        dy._raise(int(status), int(step), 1e-5)


def test_blow_up_is_reported() -> None:
    # a load the contacts cannot hold pushes the rotor out of the grooves
    s = dy.setup(make_case()).replace(force=np.array([0.0, -1e9, 0.0]))
    with pytest.raises(NumericalError, match=r"left the bearing|not converge"):
        dy.integrate(s, 80.0, 2, 64, time_step=1e-5)


def test_step_choice() -> None:
    s = dy.setup(make_case())
    h, stride = dy.choose_step(s, 1000.0, 1e-4, None)
    assert h * stride == pytest.approx(1e-4)
    assert h <= 1.0 / (dy.STEPS_PER_PERIOD * 1000.0)
    assert h > 0.9 / (dy.STEPS_PER_PERIOD * 1000.0)
    h2, stride2 = dy.choose_step(s, 1000.0, 1e-4, 3e-5)
    assert stride2 == 4 and h2 == pytest.approx(2.5e-5)


def test_zero_speed_kinematics_for_energy_helpers() -> None:
    s = dy.setup(make_case())
    still = s.replace(kinematics=Kinematics(0.0, 0.0, 0.0, 0.0, "inner", s.n_elements))
    e = dy.energy(still, np.zeros(2), np.zeros((2, 3)), np.zeros((2, 3)))
    assert np.all(e == 0.0)  # no contact is closed at q = 0 (radial play)


# --------------------------------------------------------------------------------------------
# a single loaded ball, time origin, frame
# --------------------------------------------------------------------------------------------
def test_static_equilibrium_on_a_single_ball_under_the_load() -> None:
    # 8 balls, one straight under the load along -y, its neighbours inside the 5 um play: the
    # ball holds the rotor along y only, every x within the play is an equilibrium (singular
    # Hessian). The static solve must still converge, to the symmetric x = 0 and, along y,
    # to seed 003 eq. 2.1 with eq. 2.4: W = K_n (-y - P_d/2)^{3/2}.
    s = dy.setup(make_case(elements=8, clearance=10e-6, radial=6.0))
    assert math.degrees(s.theta0[6]) == pytest.approx(270.0)
    q = dy.static_equilibrium(s, np.array([0.0]))[0]
    expected_y = -(5e-6 + (6.0 / s.stiffness) ** (2.0 / 3.0))
    assert q[1] == pytest.approx(expected_y, rel=1e-12)
    assert abs(q[0]) < 1e-6 * abs(q[1])
    _, approach = dy.contact_forces(s, np.zeros(1), q[None])
    assert int((approach[0] > 0).sum()) == 1  # the neighbours really are unloaded
    fn = dy.linearised_natural_frequencies(s, q)
    k_yy = 1.5 * s.stiffness * math.sqrt(-expected_y - 5e-6)
    assert fn[0] == 0.0  # no stiffness across the load
    assert fn[1] == pytest.approx(math.sqrt(k_yy / s.mass) / (2 * math.pi), rel=1e-6)


def test_record_starts_at_the_end_of_the_transient() -> None:
    # reported t = 0 is the first recorded instant, after a transient integrated from the
    # static equilibrium at t = -transient (the geometry at t = 0 is every model's): sample k
    # is the state at k dt_out of one uninterrupted integration from that start
    case = make_case(waviness=WAVY[:2], dynamics={"unbalance": 1e-7})
    s = dy.setup(case)
    speed, spr = case.operation.speed, 64
    integ = dy.integrate(s, speed, 2, spr)
    assert integ.time[0] == 0.0
    assert integ.time[1] == pytest.approx(1.0 / (speed * spr), rel=1e-12)
    first = round(integ.transient * speed * spr)
    assert first == pytest.approx(integ.transient * speed * spr, abs=1e-6)
    h = integ.time_step
    stride = round(1.0 / (speed * spr) / h)
    t0 = -integ.transient
    q0 = dy.static_equilibrium(s, np.array([t0]))[0]
    state = np.zeros(9)
    state[:3] = q0
    f0, _ = dy.contact_forces(s, np.array([t0]), q0[None])
    state[6:8] = (dy.external_force(s, np.array([t0]))[0, :2] - f0[0, :2]) / s.mass
    n_rec = integ.time.size
    out = np.zeros((first + n_rec, 3))
    status, _, _, _ = dy.newmark_kernel(
        (first + n_rec) * stride, stride, t0, state, s.params(h), s.theta0, s.harmonics, 2,
        dy.MAX_ITER, out,
    )  # fmt: skip
    assert status == dy.OK
    # kernel row i is the state at t0 + (i + 1) dt_out
    same = out[first - 1 : first - 1 + n_rec, :2].T
    pp = np.ptp(integ.displacement[:2], axis=1).max()
    assert pp > 1e-9
    assert np.max(np.abs(same - integ.displacement[:2])) < 1e-6 * pp
    # one sample later is clearly different
    assert np.max(np.abs(out[first : first + n_rec, :2].T - integ.displacement[:2])) > 1e-2 * pp


def test_unbalance_phase_is_relative_to_the_reported_time_origin() -> None:
    # preloaded rotor (every ball loaded, nearly linear): the unbalance F_u (cos Ωt, sin Ωt)
    # of time t gives x = Re{X e^{iΩt}}, X = (K - mΩ² + icΩ)^{-1} F_u (1, -i): the reported
    # time is the time of the equations of motion (t = 0 after the transient), phase arg X
    case = make_case(axial=20.0, dynamics={"unbalance": 1e-7})
    s = dy.setup(case)
    result = dy.run(case)
    transient = result.details.transient_s
    assert transient > 0.0 and result.time[0] == 0.0
    om = s.unbalance_omega
    q0 = np.array([*result.details.static_displacement_m, 0.0])
    dyn_matrix = dy.contact_stiffness(s, 0.0, q0) + (
        -s.mass * om**2 + 1j * s.damping * om
    ) * np.eye(2)
    x_amp = np.linalg.solve(dyn_matrix, s.unbalance_force * np.array([1.0, -1.0j]))
    one_sample = om * result.time[1]  # phase error of a one-sample shift of the origin
    for axis, name in enumerate("xy"):
        (line,) = [
            c for c in result.components if c.direction == name and c.label == "unbalance: f_i"
        ]
        assert line.pp_m == pytest.approx(2 * abs(x_amp[axis]), rel=1e-4)
        expected = np.angle(x_amp[axis])
        error = (line.phase_rad - expected + math.pi) % (2 * math.pi) - math.pi
        assert abs(error) < 1e-2 * one_sample


@pytest.mark.parametrize("direction_deg", [-90.0, 30.0, 180.0])
def test_displacement_is_the_shaft_in_the_housing_along_the_load(direction_deg: float) -> None:
    # product frame: the inner ring's centre relative to the outer ring's, loads act on the
    # shaft along their direction, so the mean displacement points along the radial load
    case = make_case(
        load_direction=math.radians(direction_deg), revolutions=2, samples=256, speed=20.0
    )
    result = dy.run(case)
    mean = np.array(result.mean_displacement()[:2])
    u = np.array([math.cos(math.radians(direction_deg)), math.sin(math.radians(direction_deg))])
    assert mean @ u > 0.1e-6  # beyond the 0.1 um radial play
    assert abs(mean[0] * u[1] - mean[1] * u[0]) < 1e-2 * (mean @ u)
    assert np.allclose(result.measuring_direction, u)
    if direction_deg == -90.0:
        assert mean[1] < -0.1e-6
