"""dynamic model (seed 003) against independent methods.

* solve_ivp (DOP853, tight tolerances) on a short window, and the O(h²) convergence of
  Newmark-β towards it;
* energy conservation with c = 0 (balls at rest, constant load) and the energy dissipated by c;
* the low-speed limit: the response collapses onto the quasi-static solution of the same
  contact model (mean deflection and ball-passage p-p);
* the transient: the record after the detected transient matches a run started elsewhere;
* the trends seed 003 §3.1-3.2 states (more balls / more preload: less ball-passage
  vibration, higher natural frequency).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from cases import WAVY, dynamic_case
from runout.analysis.spectrum import extract_lines
from runout.models import dynamic as dy
from runout.models._quasi_static import Kinematics

make_case = dynamic_case


def _kernel_run(s: dy.DynamicSetup, state: np.ndarray, h: float, t_end: float) -> np.ndarray:
    n = round(t_end / h)
    out = np.zeros((n, 3))
    status, _, _, _ = dy.newmark_kernel(
        n, 1, 0.0, state, s.params(h), s.theta0, s.harmonics, s.ndof, dy.MAX_ITER, out
    )
    assert status == dy.OK
    return out


def test_newmark_against_dop853_and_second_order() -> None:
    case = make_case(waviness=WAVY, dynamics={"unbalance": 1e-6})
    s = dy.setup(case)
    q0 = dy.static_equilibrium(s, np.array([0.0]))[0]
    y0 = np.concatenate([q0[:2] + np.array([5e-8, 2e-8]), np.zeros(2)])
    t_end = 4e-3  # ≈ 3 periods of the highest natural frequency, 1.1 ball passages
    sol = solve_ivp(
        dy.rhs_first_order(s),
        (0.0, t_end),
        y0,
        method="DOP853",
        rtol=1e-12,
        atol=1e-20,
        dense_output=True,
    )
    assert sol.success
    errors = []
    for h in (4e-6, 2e-6, 1e-6):
        state = np.zeros(9)
        state[:2] = y0[:2]
        f0, _ = dy.contact_forces(s, np.array([0.0]), state[None, :3])
        state[6:8] = (dy.external_force(s, np.array([0.0]))[0, :2] - f0[0, :2]) / s.mass
        out = _kernel_run(s, state, h, t_end)
        t = h * np.arange(1, out.shape[0] + 1)
        ref = sol.sol(t)[:2].T
        errors.append(np.max(np.abs(out[:, :2] - ref)))
    motion = np.ptp(sol.sol(np.linspace(0, t_end, 400))[:2], axis=1).max()
    fn = dy.linearised_natural_frequencies(s, q0).max()
    # at 1 us (≈ 700 steps per natural period) the error is below 1e-3 of the motion
    assert 1.0 / (1e-6 * fn) > 500
    assert errors[-1] < 1e-3 * motion
    # second order: halving h divides the error by about 4
    assert 3.0 < errors[0] / errors[1] < 5.0
    assert 3.0 < errors[1] / errors[2] < 5.0


def _still(s: dy.DynamicSetup) -> dy.DynamicSetup:
    return s.replace(
        kinematics=Kinematics(0.0, 0.0, 0.0, 0.0, "inner", s.n_elements), unbalance_force=0.0
    )


@pytest.mark.parametrize("axial_dof", [False, True])
def test_energy_conserved_without_damping(axial_dof: bool) -> None:
    s = _still(dy.setup(make_case(axial=20.0, dynamics={"damping": 0.0, "axial_dof": axial_dof})))
    q0 = dy.static_equilibrium(s, np.array([0.0]))[0]
    fn = dy.linearised_natural_frequencies(s, q0).max()
    start = q0 + np.array([3e-7, -2e-7, 1e-7 if axial_dof else 0.0])
    drift = []
    for steps_per_period in (100, 200):
        h = 1.0 / (steps_per_period * fn)
        state = np.zeros(9)
        state[:3] = start
        f0, _ = dy.contact_forces(s, np.array([0.0]), start[None])
        state[6:9] = (s.force - f0[0]) / s.mass
        if not axial_dof:
            state[8] = 0.0
        e0 = dy.energy(s, np.zeros(1), start[None], np.zeros((1, 3)))[0]
        e_min = dy.energy(s, np.zeros(1), q0[None], np.zeros((1, 3)))[0]
        _kernel_run(s, state, h, 30.0 / fn)
        e1 = dy.energy(s, np.zeros(1), state[None, :3], state[None, 3:6])[0]
        drift.append(abs(e1 - e0) / (e0 - e_min))
    assert drift[1] < 1e-4
    assert drift[1] < drift[0]


def test_damping_dissipates_exactly_c_v_squared() -> None:
    s = _still(dy.setup(make_case(axial=20.0, dynamics={"damping": 50.0})))
    q0 = dy.static_equilibrium(s, np.array([0.0]))[0]
    fn = dy.linearised_natural_frequencies(s, q0).max()
    h = 1.0 / (400 * fn)
    start = q0 + np.array([3e-7, -2e-7, 0.0])
    state = np.zeros(9)
    state[:3] = start
    f0, _ = dy.contact_forces(s, np.array([0.0]), start[None])
    state[6:8] = (s.force[:2] - f0[0, :2]) / s.mass
    e0 = dy.energy(s, np.zeros(1), start[None], np.zeros((1, 3)))[0]
    # step one at a time to integrate c v² with the trapezoidal rule of the scheme
    dissipated = 0.0
    v_prev = state[3:6].copy()
    out = np.zeros((1, 3))
    for _ in range(round(10.0 / (fn * h))):
        dy.newmark_kernel(1, 1, 0.0, state, s.params(h), s.theta0, s.harmonics, 2, 50, out)
        dissipated += s.damping * h * 0.5 * (v_prev @ v_prev + state[3:6] @ state[3:6])
        v_prev = state[3:6].copy()
    e1 = dy.energy(s, np.zeros(1), state[None, :3], state[None, 3:6])[0]
    assert dissipated > 0.2 * (e0 - dy.energy(s, np.zeros(1), q0[None], np.zeros((1, 3)))[0])
    assert e0 - e1 == pytest.approx(dissipated, rel=1e-3)


def test_low_speed_collapses_onto_quasi_static() -> None:
    # 60 rpm: ball passage 3.4 Hz, natural frequencies 550-830 Hz
    case = make_case(speed=1.0, waviness=WAVY[:1], revolutions=2, samples=512)
    s = dy.setup(case)
    integ = dy.integrate(s, 1.0, 2, 256)
    qs = dy.static_equilibrium(s, integ.time)  # t = 0 after the transient: one time origin
    u = np.array([0.0, -1.0])
    dyn_r = u @ integ.displacement[:2]
    qs_r = qs[:, :2] @ u
    fbp = dy.ball_passage_frequency(s)
    assert dyn_r.mean() == pytest.approx(qs_r.mean(), rel=1e-4)
    assert np.ptp(dyn_r) == pytest.approx(np.ptp(qs_r), rel=1e-2)
    amp_dyn = extract_lines(integ.time, dyn_r, [fbp]).amplitude[0]
    amp_qs = extract_lines(integ.time, qs_r, [fbp]).amplitude[0]
    assert amp_dyn > 1e-10  # a real ball-passage line (clearance: few balls loaded)
    assert amp_dyn == pytest.approx(amp_qs, rel=1e-2)
    # and at 5000 rpm the dynamics matter: the same comparison fails
    fast = dy.setup(make_case(waviness=WAVY[:1]))
    integ_f = dy.integrate(fast, 5000 / 60, 4, 256)
    qs_f = dy.static_equilibrium(fast, integ_f.time)[:, :2] @ u
    assert abs(np.ptp(u @ integ_f.displacement[:2]) / np.ptp(qs_f) - 1.0) > 0.05


def test_transient_removed() -> None:
    # the record after the detected transient equals the steady state reached from a very
    # different start (integrated for a long time)
    case = make_case(axial=5.0, waviness=WAVY[:2])
    s = dy.setup(case)
    speed = 5000 / 60
    integ = dy.integrate(s, speed, 2, 256)
    assert integ.settled == "decayed"
    h = integ.time_step
    stride = round(1.0 / (speed * 256) / h)
    t0 = -integ.transient  # the record starts at t = 0, after the transient
    q0 = dy.static_equilibrium(s, np.array([t0]))[0]
    state = np.zeros(9)
    state[:3] = q0 + np.array([2e-7, 1e-7, 0.0])
    t_total = integ.transient + 2.0 / speed
    n = round(t_total / h)
    out = np.zeros((n // stride, 3))
    status, _, _, _ = dy.newmark_kernel(
        n, stride, t0, state, s.params(h), s.theta0, s.harmonics, s.ndof, dy.MAX_ITER, out
    )
    assert status == dy.OK
    # the decay of the perturbation is the linear e^{-ct/2m}: by the end of the transient
    # found for the small start (at least one block) the large one has shrunk enough.
    # Reported sample k is at t = k dt_out (time origin at the start of the record); kernel
    # row i at t0 + (i + 1) dt_out
    first = round(integ.transient * speed * 256)
    assert integ.time[0] == 0.0
    late = out[first - 1 : first - 1 + integ.displacement.shape[1], :2].T
    pp = np.ptp(integ.displacement[:2], axis=1).max()
    start_error = 2.2e-7 * math.exp(-s.damping / (2 * s.mass) * integ.transient)
    assert np.max(np.abs(late - integ.displacement[:2])) < max(2e-3 * pp, 2 * start_error)


def test_seed003_trends_balls_and_preload() -> None:
    # seed 003 §3.1-3.2: more balls and more preload lower the ball-passage vibration and
    # raise the natural frequency (our consistent numbers; see validation_dynamic.md)
    def bp(elements: int, preload: float) -> tuple[float, float]:
        case = make_case(elements=elements, axial=preload, revolutions=3, samples=768)
        s = dy.setup(case)
        integ = dy.integrate(s, case.operation.speed, 3, 256)
        r = -integ.displacement[1]
        amp = extract_lines(integ.time, r, [dy.ball_passage_frequency(s)]).amplitude[0]
        return float(amp), float(integ.natural_frequencies.max())

    a5, f5 = bp(5, 1.0)
    a9, f9 = bp(9, 1.0)
    a9p, f9p = bp(9, 10.0)
    assert a5 > 100 * a9 > 0
    assert a9 > 10 * a9p
    assert f5 < f9 < f9p
