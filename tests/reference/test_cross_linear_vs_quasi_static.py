"""Cross-check of two independent models: `linear` (seed 002, force-balance variant) against
`quasi_static_3d` (seed 000) at small amplitude.

With the contact angle fixed and a constant axial preload, Tada's force balance (seed 000
eq. 5) linearised about the preloaded state gives x + i y = (2/Z) Σ (w_ring + w_ball / cos α)
e^{iθ_j}: ring waviness passes 1:1 and ball waviness is amplified by 1/cos α. That is the
linear model's ``force_balance`` variant (docs/models/linear.md). At 1 nm the nonlinear lines
must therefore equal the linear ones to the order of the linearisation error (~1e-3 here).
"""

from __future__ import annotations

import tomllib

import pytest

from runout.case import parse_case
from runout.models import linear, quasi_static_3d

CASE = """
title = "cross-check"
[bearing]
type = "ball"
elements = 8
element_diameter = "1 mm"
pitch_diameter = "7 mm"
inner_conformity = 0.52
outer_conformity = 0.53
radial_clearance = "10 um"
[operation]
rotating_ring = "{ring}"
speed = "5400 rpm"
axial_load = "20 N"
[[waviness]]
part = "inner"
order = 9
amplitude = "1 nm"
phase = "20 deg"
[[waviness]]
part = "outer"
order = 7
amplitude = "1 nm"
phase = "50 deg"
[[waviness]]
part = "ball"
order = 2
amplitude = "1 nm"
element = 3
[analysis]
model = "{model}"
linear_variant = "force_balance"
revolutions = 40
samples = 8192
"""


def _lines(model, ring: str) -> dict[tuple[str, float], float]:  # type: ignore[no-untyped-def]
    text = CASE.format(ring=ring, model=model.__name__.rsplit(".", 1)[1])
    if model is quasi_static_3d:
        text = text.replace('linear_variant = "force_balance"\n', "")
    case = parse_case(tomllib.loads(text), "cross.toml")
    result = model.run(case)
    return {
        (c.direction, round(c.frequency_hz, 3)): c.pp_m
        for c in result.components
        if c.direction in ("x", "y") and c.pp_m > 1e-11
    }


@pytest.mark.parametrize("ring", ["inner", "outer"])
def test_linear_force_balance_equals_quasi_static_3d_at_1nm(ring: str) -> None:
    lin = _lines(linear, ring)
    qs = _lines(quasi_static_3d, ring)
    # The three first-order radial lines (inner nZ+1, outer nZ-1, ball 2n ± f_c) of x and y.
    assert len(lin) >= 6
    for key, pp in lin.items():
        assert key in qs, f"{key} missing from quasi_static_3d lines {sorted(qs)}"
        assert qs[key] == pytest.approx(pp, rel=2e-3), key
