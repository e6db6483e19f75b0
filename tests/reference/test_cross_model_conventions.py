"""The same case in every model: lines, orders, phases, p-p and mean displacement agree.

Shared cases (issue 13): 1 nm of inner (Z + 1 lobes), outer (Z − 1 lobes) and ball (2 lobes,
two balls with different phases) waviness on Tada's standard bearing (seed 000 Table 1, α ≈ 29°
under 20 N), with either ring rotating; a small radial load with preload; a radial load with
play and no preload. At this amplitude the nonlinear models are linear to ~1e-3, so every line
must agree with ``quasi_static_3d`` to that error, times the documented factor of each model
(docs/models/quasi_static.md, docs/models/linear.md):

========================  ===========  ============  ==========
model                     ring lines   ball lines    radial load
========================  ===========  ============  ==========
linear, force_balance     1            1             —
linear, radial_spring     cos α        cos²α         —
quasi_static_2d           1            cos α         cos²α
dynamic (quasi-static)    1            1             —
========================  ===========  ============  ==========

Phases are those of the shaft relative to the outer ring with t = 0 at the start of the record,
so they agree too.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from cases import TADA_BEARING
from runout.analysis.results import RunResult
from runout.case.model import parse_case
from runout.runner import run_model

WAVINESS = [
    {"part": "inner", "order": 9, "amplitude": 1e-9, "phase": 0.3},
    {"part": "outer", "order": 7, "amplitude": 1e-9, "phase": 0.9},
    {"part": "ball", "order": 2, "amplitude": 1e-9, "element": 1},
    {"part": "ball", "order": 2, "amplitude": 1e-9, "element": 2, "phase": 1.0},
]


def _run(model: str, ring: str, variant: str = "radial_spring", **operation: Any) -> RunResult:
    data: dict[str, Any] = {
        "bearing": dict(TADA_BEARING),
        "operation": {"rotating_ring": ring, "speed": 90.0, "axial_load": 20.0, **operation},
        "waviness": WAVINESS if not operation else [],
        "analysis": {"model": model, "revolutions": 16, "samples": 8192},
    }
    if model == "linear":
        data["analysis"]["linear_variant"] = variant
    if model == "dynamic":
        # a light, stiff rotor: natural frequencies ~20x the lines, so it is quasi-static
        data["dynamics"] = {"mass": 0.001, "damping": 5.0}
    return run_model(parse_case(data, "cross.toml"))


def _lines(result: RunResult) -> dict[tuple[str, float], tuple[float, float, str]]:
    return {
        (c.direction, round(c.order, 6)): (c.pp_m, c.phase_rad, c.label)
        for c in result.components
        if c.direction in ("x", "y") and c.pp_m > 1e-12 and "order 2" not in c.label
    }


FACTORS = {
    # model, variant -> (ring factor, ball factor) as functions of cos α
    ("linear", "force_balance"): (lambda c: 1.0, lambda c: 1.0),
    ("linear", "radial_spring"): (lambda c: c, lambda c: c * c),
    ("quasi_static_2d", ""): (lambda c: 1.0, lambda c: c),
    ("dynamic", ""): (lambda c: 1.0, lambda c: 1.0),
}
#: relative tolerance on p-p: the linearisation error; the dynamic model also keeps its small
#: dynamic amplification and holds the rings axially (quasi_static_3d: constant axial force)
TOLERANCE = {"dynamic": 1e-2}


@pytest.mark.parametrize("ring", ["inner", "outer"])
@pytest.mark.parametrize(("model", "variant"), list(FACTORS))
def test_lines_agree_with_quasi_static_3d_by_the_documented_factor(
    ring: str, model: str, variant: str
) -> None:
    reference = _run("quasi_static_3d", ring)
    cos_a = math.cos(reference.contact_angle)
    ref = _lines(reference)
    other = _lines(_run(model, ring, variant or "radial_spring"))
    ring_factor, ball_factor = FACTORS[(model, variant)]
    first_order = {k: v for k, v in ref.items() if "order" not in v[2] and "eq. 7" not in v[2]}
    assert len(first_order) >= 8, sorted(first_order)
    for key, (pp, phase, label) in first_order.items():
        assert key in other, f"{model} lacks {key} ({label})"
        factor = ball_factor(cos_a) if label.startswith("ball") else ring_factor(cos_a)
        rel = TOLERANCE.get(model, 3e-3)
        assert other[key][0] == pytest.approx(factor * pp, rel=rel), (key, label)
        # same sign and time origin: the same phase
        assert abs(math.remainder(other[key][1] - phase, 2 * math.pi)) < 5e-3, (key, label)


@pytest.mark.parametrize("ring", ["inner", "outer"])
def test_mean_displacement_under_a_small_radial_load(ring: str) -> None:
    # Loads act on the shaft: both move it along the load; 2-D is 1/cos²α stiffer.
    three = _run("quasi_static_3d", ring, radial_load=0.2, radial_load_direction=-1.0)
    two = _run("quasi_static_2d", ring, radial_load=0.2, radial_load_direction=-1.0)
    u = np.array([math.cos(-1.0), math.sin(-1.0)])
    m3 = np.array(three.mean_displacement()[:2])
    m2 = np.array(two.mean_displacement()[:2])
    assert m3 @ u > 0 and m2 @ u > 0
    assert abs(m3[0] * u[1] - m3[1] * u[0]) < 1e-6 * (m3 @ u)
    assert (m2 @ u) / (m3 @ u) == pytest.approx(math.cos(three.contact_angle) ** 2, rel=2e-4)


def test_radial_load_with_play_in_the_models_that_have_it() -> None:
    # A 6204-like bearing, 10 um clearance, no preload, 600 N along -y, slowly turning: the
    # shaft drops by the play P_d/2 plus the Hertz approach of the ball under it. equilibrium
    # (static, 5 DOF) and dynamic (after its transient) agree; the rigid constraint model has
    # the play only.
    def case(model: str) -> Any:
        data: dict[str, Any] = {
            "bearing": {
                "type": "ball",
                "elements": 8,
                "element_diameter": 7.938e-3,
                "pitch_diameter": 33.5e-3,
                "inner_conformity": 0.52,
                "outer_conformity": 0.52,
                "radial_clearance": 10e-6,
            },
            "operation": {"speed": 1.0, "radial_load": 600.0},
            "analysis": {"model": model, "revolutions": 1, "samples": 256},
        }
        if model == "dynamic":
            data["dynamics"] = {"mass": 0.5, "damping": 3000.0}
        return parse_case(data, "play.toml")

    static = run_model(case("equilibrium")).mean_displacement()
    rigid = run_model(case("roller_constraint")).mean_displacement()
    assert static[1] < -5e-6  # beyond the play
    # the rigid shaft drops by the play P_d/2 onto a ball under the load, and by up to
    # (P_d/2) / cos(π/Z) between two balls straddling it
    assert -5e-6 / math.cos(math.pi / 8) < rigid[1] < -5e-6
    dynamic = run_model(case("dynamic")).mean_displacement()
    assert dynamic[1] == pytest.approx(static[1], rel=0.02)
