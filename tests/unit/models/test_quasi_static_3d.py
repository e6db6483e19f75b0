"""quasi_static_3d: compiled kernel vs NumPy reference, equilibrium, lost contacts, errors."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cases import typed_case
from runout import Operation, examples
from runout.base.errors import ContactLossError, GeometryError
from runout.case.model import Case
from runout.models import quasi_static_3d as qs3


def _case(
    waviness: list[dict[str, Any]],
    *,
    axial: float = 20.0,
    radial: float = 0.0,
    rotating: str = "inner",
    samples: int = 256,
) -> Case:
    return typed_case(
        examples.tada_bearing(radial_clearance=10e-6),
        Operation(rotating_ring=rotating, speed=90.0, axial_load=axial, radial_load=radial),
        waviness,
        model="quasi_static_3d",
        revolutions=4,
        samples=samples,
    )


def _residual(case: Case, disp: np.ndarray) -> np.ndarray:
    """Force balance of eq. 5 recomputed independently at each instant [N], shape (n, 3).

    ``disp`` is the shaft relative to the outer ring: a shaft moving towards a ball
    compresses it."""
    s = qs3.setup(case)
    c, theta = qs3.approaches(case, s, qs3.time_grid_of(case))
    ca, sa = math.cos(s.contact_angle), math.sin(s.contact_angle)
    nx, ny = ca * np.cos(theta), ca * np.sin(theta)
    d = c + disp[0][:, None] * nx + disp[1][:, None] * ny + disp[2][:, None] * sa
    q = s.stiffness * np.clip(d, 0.0, None) ** 1.5
    return np.stack([(q * nx).sum(1), (q * ny).sum(1), (q * sa).sum(1)], axis=1) - s.force


wav = st.fixed_dictionaries(
    {
        "part": st.sampled_from(["inner", "outer"]),
        "order": st.integers(1, 30),
        "amplitude": st.floats(0.0, 0.4e-6),
        "phase": st.floats(0.0, 6.28),
    }
)


@settings(max_examples=25, deadline=None)
@given(
    waviness=st.lists(wav, min_size=1, max_size=4),
    radial=st.floats(0.0, 15.0),
    rotating=st.sampled_from(["inner", "outer"]),
)
def test_kernel_matches_numpy_reference(
    waviness: list[dict[str, Any]], radial: float, rotating: str
) -> None:
    case = _case(waviness, radial=radial, rotating=rotating, samples=64)
    s = qs3.setup(case)
    t = qs3.time_grid_of(case)
    try:
        disp, _ = qs3.solve(case, t, s)
    except ContactLossError:
        return  # the ring cannot be held: nothing to compare
    c, theta = qs3.approaches(case, s, t)
    ref = qs3.solve_reference(
        c, theta, s.contact_angle, s.stiffness, s.force, tol=qs3.RTOL * s.preload
    )
    assert np.isfinite(disp).all()
    # the kernel and the reference solve in seed 000's frame (outer ring relative to inner)
    np.testing.assert_allclose(-disp, ref.T, rtol=0, atol=1e-9 * s.preload)
    # and both satisfy the balance to a tiny fraction of the preload
    assert np.abs(_residual(case, disp)).max() <= 1e-7 * s.force[2]


def test_radial_load_unloads_balls_and_is_reported() -> None:
    case = _case([], axial=10.0, radial=12.0, samples=64)
    result = qs3.run(case)
    assert result.details.unloaded_balls_max > 0
    assert "lost contact" in result.notes[0]
    disp = result.displacement - np.array(
        [[0.0], [0.0], [qs3.axial_position(case, qs3.setup(case))]]
    )
    assert np.abs(_residual(case, disp)).max() <= 1e-7 * 12.0
    # the shaft moves along the load (default -y) and the measuring direction follows it
    assert result.measuring_direction == pytest.approx([0.0, -1.0], abs=1e-12)
    assert result.displacement[1].mean() < 0.0


def test_radial_load_acts_on_the_shaft_and_loads_the_balls_below_it() -> None:
    # A load along -y pushes the shaft down: the balls under it (-y side) carry more.
    case = _case([], axial=10.0, radial=5.0, samples=64)
    s = qs3.setup(case)
    t = qs3.time_grid_of(case)
    disp, _ = qs3.solve(case, t, s)
    c, theta = qs3.approaches(case, s, t)
    ca = math.cos(s.contact_angle)
    d = c + (disp[0][:, None] * np.cos(theta) + disp[1][:, None] * np.sin(theta)) * ca
    d += disp[2][:, None] * math.sin(s.contact_angle)
    below = np.sin(theta) < -0.5
    above = np.sin(theta) > 0.5
    assert d[below].mean() > d[above].mean()


def test_perfect_bearing_does_not_move() -> None:
    case = _case([], samples=64)
    result = qs3.run(case)
    st = qs3.setup(case)
    # it sits at the preloaded position: (A + δ_pl) sin α from the rings axially centred
    z0 = qs3.axial_position(case, st)
    assert z0 == pytest.approx((0.05e-3 + st.preload) * math.sin(st.contact_angle), rel=1e-12)
    moved = result.displacement - np.array([[0.0], [0.0], [z0]])
    assert np.abs(moved).max() <= 1e-9 * st.preload
    assert result.details.unloaded_balls_max == 0


def test_ring_that_cannot_be_held_raises_with_instant() -> None:
    case = _case([{"part": "inner", "order": 2, "amplitude": 20e-6}], samples=64)
    with pytest.raises(ContactLossError) as info:
        qs3.run(case)
    assert info.value.instant is not None
    assert "instant" in str(info.value)


def test_radial_load_beyond_fixed_angle_capacity_raises() -> None:
    # with α fixed, Σ Q sin α = F_a caps the radial load below F_a cot α: refused before the
    # solve, naming the load and the model that follows the contact angles
    case = _case([], axial=10.0, radial=40.0, samples=64)
    alpha = qs3.operating_contact_angle(case.bearing, case.operation)[0]
    assert 40.0 > 10.0 / math.tan(alpha)
    with pytest.raises(GeometryError, match=r'tan α.*model = "dynamic"') as info:
        qs3.run(case)
    assert info.value.key == "operation.radial_load"
    # just below the cap the model still solves (the cap is no wider than the model's reach)
    below = 0.5 * 10.0 / math.tan(alpha)
    assert qs3.run(_case([], axial=10.0, radial=below, samples=64)).runout is not None


def test_needs_a_preload() -> None:
    with pytest.raises(GeometryError, match="axial preload"):
        qs3.run(_case([], axial=0.0))


def test_preload_approach_inverts_the_balance() -> None:
    s = qs3.setup(_case([]))
    assert 8 * s.stiffness * s.preload**1.5 * math.sin(s.contact_angle) == pytest.approx(20.0)


def test_json_has_no_nan_and_labels_name_the_rule() -> None:
    case = _case([{"part": "outer", "order": 9, "peak_to_peak": 20e-9}], samples=256)
    out = qs3.run(case).to_json()
    assert out["model"] == "quasi_static_3d"
    top = out["components"][0]
    assert top["label"].startswith("outer 9 lobes: nZ+1, n=1")
    assert top["pp_m"] == pytest.approx(20e-9, rel=1e-6)
    assert all(math.isfinite(v) for v in out["runout"].values())
    # a radial nZ+1 line on the rotating ring is non-repeatable: NRRO carries it
    assert out["runout"]["nrro_pp_m"] > 0.9 * out["runout"]["radial_pp_m"]
