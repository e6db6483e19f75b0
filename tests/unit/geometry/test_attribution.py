"""Frequency attribution table (seed 002 Tab. 3, seed 000 Tab. 2)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from runout.geometry.attribution import attribution_rows, attribution_table_rows
from runout.geometry.bearing import BallBearing, Operation
from runout.geometry.imperfections import BearingImperfections, Harmonics
from runout.geometry.kinematics import bearing_frequencies
from runout.models import linear as lin

D, DM, ALPHA, Z = 3.9688e-3, 15e-3, math.radians(10.0), 7


def _bearing() -> BallBearing:
    return BallBearing(
        elements=Z,
        element_diameter=D,
        pitch_diameter=DM,
        inner_conformity=0.52,
        outer_conformity=0.53,
        contact_angle=ALPHA,
    )


@pytest.mark.parametrize("ring", ["inner", "outer"])
def test_flaw_rows_are_the_kinematic_frequencies(ring: str) -> None:
    f = bearing_frequencies(_bearing(), Operation(ring, 25.0), ALPHA)
    rows = attribution_rows(D, DM, ALPHA, Z, ring, 25.0)
    by = {(r["part"], r["factor"]): r for r in rows}
    assert by[("inner", "flaw")]["frequency_hz"] == pytest.approx(f.ball_pass_inner, rel=1e-12)
    assert by[("outer", "flaw")]["frequency_hz"] == pytest.approx(f.ball_pass_outer, rel=1e-12)
    assert by[("ball", "flaw")]["frequency_hz"] == pytest.approx(2 * f.ball_spin, rel=1e-12)
    assert by[("ball", "diameter error")]["frequency_hz"] == pytest.approx(f.cage, rel=1e-12)


@pytest.mark.parametrize("ring", ["inner", "outer"])
def test_every_waviness_row_is_a_line_of_the_model(ring: str) -> None:
    # A single harmonic per row must put a line exactly at the row's order.
    rows = attribution_rows(D, DM, ALPHA, Z, ring, 30.0, n_max=2)
    r = lin.rates(_bearing(), Operation(ring, 30.0), ALPHA)
    for row in rows:
        if row["factor"] != "waviness" or row["part"] == "ball":
            continue
        k = int(row["lobes"].split("=")[1].split()[0])
        h = Harmonics([k], [1e-6])
        imp = BearingImperfections(
            inner=h if row["part"] == "inner" else None,
            outer=h if row["part"] == "outer" else None,
            elements=[Harmonics.empty()] * Z,
        )
        lines = lin.spectral_lines(lin.closed_form_terms(imp, r, ALPHA), 30.0, Z, False)
        assert np.min(np.abs(lines.order - row["order"])) < 1e-12, row
    for n in (1, 2):
        imp = BearingImperfections(elements=[Harmonics([2 * n], [1e-6])] + [Harmonics.empty()] * 6)
        lines = lin.spectral_lines(lin.closed_form_terms(imp, r, ALPHA), 30.0, Z, False)
        want = sorted(row["order"] for row in rows if row["lobes"].startswith(f"2n = {2 * n}"))
        np.testing.assert_allclose(sorted(lines.order), want, rtol=1e-12)


def test_bad_arguments_are_clear_errors() -> None:
    with pytest.raises(ValueError, match="rotating_ring"):
        attribution_rows(D, DM, ALPHA, Z, "cage")
    with pytest.raises(ValueError, match="at least 3"):
        attribution_rows(D, DM, ALPHA, 2)
    with pytest.raises(ValueError, match="ball_diameter"):
        attribution_rows(DM, D, ALPHA, Z)


def test_table_rows_render() -> None:
    rows = attribution_table_rows(attribution_rows(D, DM, ALPHA, Z, "inner", 30.0))
    assert any("eq. 49" in r[0] and "4.41198" in r[1] for r in rows)
