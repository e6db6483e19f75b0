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

from spindle_cases import TADA, spindle_case

from runout.models import spindle as sp

A = 10e-9


def _solve(case):  # type: ignore[no-untyped-def]
    st_ = sp.setup(case.spindle, case.operation)
    t = sp.time_grid(case.operation.speed, case.analysis.revolutions, case.analysis.samples)
    q, _ = sp.solve(st_, [b.imperfections for b in case.spindle.bearings], t)
    return st_, t, q


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
    assert np.abs(q[:, 3:5]).max() * span < 1e-9 * A


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
    # linear response: equal and opposite, to the linearisation error a / δ_pl
    assert np.abs(d1 + d2).max() <= 4.0 * a / st_.d_ref * scale + 1e-18
