"""Cross-check of two independent models: `linear` (seed 002, force-balance variant) against
`quasi_static_3d` (seed 000) at small amplitude.

With the contact angle fixed and a constant axial preload, Tada's force balance (seed 000
eq. 5) linearised about the preloaded state gives x + i y = (2/Z) Σ (w_ring + w_ball / cos α)
e^{iθ_j}: ring waviness passes 1:1 and ball waviness is amplified by 1/cos α. That is the
linear model's ``force_balance`` variant (docs/models/linear.md). At 1 nm the nonlinear lines
must therefore equal the linear ones to the order of the linearisation error (~1e-3 here).
"""

from __future__ import annotations

import pytest

from runout.validation.cross_model import cross_lines

# Tada's standard bearing (examples/seed000_tada_table2.toml) with 1 nm of inner 9-lobe (20°),
# outer 7-lobe (50°) and ball-3 2-lobe waviness, 40 revolutions × 8192 instants; the linear
# model in its force_balance variant (runout.validation.cross_model.cross_case)


@pytest.mark.parametrize("ring", ["inner", "outer"])
def test_linear_force_balance_equals_quasi_static_3d_at_1nm(ring: str) -> None:
    lin = cross_lines(ring, "linear")
    qs = cross_lines(ring, "quasi_static_3d")
    # The three first-order radial lines (inner nZ+1, outer nZ-1, ball 2n ± f_c) of x and y.
    assert len(lin) >= 6
    for key, pp in lin.items():
        assert key in qs, f"{key} missing from quasi_static_3d lines {sorted(qs)}"
        assert qs[key] == pytest.approx(pp, rel=2e-3), key
