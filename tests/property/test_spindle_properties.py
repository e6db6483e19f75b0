"""Spindle invariants over drawn geometry (hypothesis).

Seed 000's conclusion 1 on a shaft over drawn ball counts, spans, preloads and arrangements:
identical in-phase Z+1 inner waviness on both bearings translates the shaft by the waviness
amplitude and does not tilt it; and the response to a small waviness turns sign with it.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "unit"))

from runout.models import spindle as sp
from runout.models._spindle_kernels import RTOL
from spindle_cases import TADA, spindle_case

A = 10e-9
EPS = float(np.finfo(np.float64).eps)
#: Terms of a generalised force summed in floating point: γ_n of a sum of n terms is n ulp;
#: a bearing pair has at most 2 × 12 balls here (64 is the solver's own residual floor).
SUM_ULPS = 64.0


def _solve(case):  # type: ignore[no-untyped-def]
    st_ = sp.setup(case.spindle, case.operation)
    t = sp.time_grid(case.operation.speed, case.analysis.revolutions, case.analysis.samples)
    q, _ = sp.solve(st_, [b.imperfections for b in case.spindle.bearings], t)
    return st_, t, q


def _resolution(st_):  # type: ignore[no-untyped-def]
    """What the solver resolves of each coordinate (x, y, z [m], θx, θy [rad], ...).

    The Newton iteration stops at a step of RTOL·d_ref at each coordinate's lever, or when the
    residual is at its round-off; a residual computed to SUM_ULPS ulp of the terms of each
    generalised force (ball loads times their normals, and the external load) moves the
    solution by the inverse stiffness times that. On a short DF span the pressure centres
    close in, the tilt stiffness is small and the second term dominates (up to ~1e4 ulp of
    the approach at the lever): round-off, not a tilt.
    """
    q0, _ = sp.static_stiffness(st_)
    cth, sth = sp._nominal_angles(st_)
    h = sp._hessian(st_, sp._nominal_c(st_), cth, sth, q0)
    terms = np.abs(sp.ball_loads(st_, q0)[:, None] * sp.normals(st_, cth, sth)).sum(axis=0)
    terms += np.abs(st_.force)
    return RTOL * st_.d_ref / st_.scale + SUM_ULPS * EPS * (np.abs(np.linalg.inv(h)) @ terms)


@settings(max_examples=12, deadline=None)
@given(
    z=st.integers(6, 12),
    span=st.floats(4e-3, 40e-3),
    preload=st.floats(5.0, 60.0),
    arrangement=st.sampled_from(["DB", "DF"]),
    phase=st.floats(-3.0, 3.0),
)
def test_conclusion_1_on_a_shaft(
    z: int, span: float, preload: float, arrangement: str, phase: float
) -> None:
    waviness = [
        {"bearing": name, "part": "inner", "order": z + 1, "amplitude": A, "phase": phase}
        for name in ("front", "rear")
    ]
    case = spindle_case(
        waviness,
        arrangement=arrangement,
        preload={"preload": preload},
        positions=(0.0, span),
        bearings=[dict(TADA, elements=z), dict(TADA, elements=z)],
        samples=512,
    )
    st_, _, q = _solve(case)
    # the shaft's orbit is a circle of the waviness amplitude (a line of p-p 2a in x and y),
    # up to the second-order terms of the contacts, of the size a^2 / δ_pl (observed up to
    # 2 a^2 / δ_pl for Z = 7; a wrong translation or a tilt would be of the size of a)
    nose = sp.nose_record(st_, q)
    radius = np.hypot(nose[0] - nose[0].mean(), nose[1] - nose[1].mean())
    assert np.abs(radius - A).max() < 4.0 * A * A / st_.d_ref
    # no tilt: the tilts are at the solver's resolution, a tilt of a / span is 1e6 times more
    tilt = _resolution(st_)[3:5]
    assert np.all(np.abs(q[:, 3:5]) <= tilt), (np.abs(q[:, 3:5]).max(axis=0), tilt)
    assert tilt.max() < 1e-4 * A / span


@settings(max_examples=8, deadline=None)
@given(
    order=st.sampled_from([7, 8, 9, 15, 16, 17]),
    phase=st.floats(-3.0, 3.0),
    which=st.sampled_from(["front", "rear"]),
)
def test_small_waviness_response_turns_sign_with_it(order: int, phase: float, which: str) -> None:
    a = 0.5e-9
    wavy = {"bearing": which, "part": "inner", "order": order, "amplitude": a, "phase": phase}
    flipped = dict(wavy, phase=phase + np.pi)
    _, _, q0 = _solve(spindle_case([], samples=256))
    st_, _, q1 = _solve(spindle_case([wavy], samples=256))
    _, _, q2 = _solve(spindle_case([flipped], samples=256))
    d1 = sp.nose_record(st_, q1 - q0)
    d2 = sp.nose_record(st_, q2 - q0)
    scale = max(np.abs(d1).max(), 1e-30)
    # linear response: equal and opposite, to the linearisation error a / δ_pl, and to the
    # resolution of the three solutions at the nose (a translation and a tilt at its lever)
    res = _resolution(st_)
    nose = max(res[0] + abs(st_.nose_position) * res[4], res[1] + abs(st_.nose_position) * res[3])
    assert np.abs(d1 + d2).max() <= 4.0 * a / st_.d_ref * scale + 4.0 * nose
