"""Kernels of the rigid constraint model: the parallel solves and the reused gaps."""

from __future__ import annotations

import math

import numpy as np
import pytest

from runout import RollerBearing
from runout.geometry.imperfections import BearingImperfections, Harmonics, single_harmonic
from runout.models import _roller_kernels as rk
from runout.models import roller_constraint as rc

NU209 = RollerBearing(14, 10e-3, 54.991e-3, 75.032e-3)
UM = 1e-6


def _geometry(seed: int) -> rc.ConstraintGeometry:
    rng = np.random.default_rng(seed)
    imp = (
        BearingImperfections.perfect(14)
        .add("inner", single_harmonic(8, 1 * UM, 0.7) + single_harmonic(23, 0.2 * UM, 2.0))
        .add("outer", single_harmonic(18, 1 * UM, 1.1))
    )
    elems = [Harmonics([4, 15], [0.4 * UM, 0.1 * UM], rng.uniform(0, 2 * np.pi, 2))] * 14
    imp = imp.with_elements(elems).with_diameter_errors(rng.uniform(-1, 1, 14) * UM)
    return rc.geometry_from(NU209, imp)


def test_solve_many_is_solve_bit_for_bit() -> None:
    alpha = rc.rotation_angles(0.3, 97)
    geos = [_geometry(s) for s in range(3)]
    for one, many in zip(
        [rc.solve(g, alpha) for g in geos], rc.solve_many(geos, alpha), strict=True
    ):
        assert np.array_equal(one.centre, many.centre)
        assert np.array_equal(one.gaps, many.gaps)
        assert np.array_equal(one.pair, many.pair)


def test_reported_gaps_are_the_gaps_at_the_reported_centre() -> None:
    # gaps known from the search are reused: they must equal a fresh evaluation there
    geo = _geometry(7)
    alpha = rc.rotation_angles(0.2, 41)
    sol = rc.solve(geo, alpha)
    bodies = rc._pack(geo)
    shift = bodies[0].size - 2 - geo.n_elements
    for i in (0, 17, 40):
        cx, cy = sol.centre[i]
        for j in range(geo.n_elements):
            rx, ry = sol.roller_centres[i, j]
            if np.hypot(rx, ry) < 1e-9:
                continue
            spin = rc.absolute_spin_ratio(geo) * alpha[i]
            g, *_ = rk._gap(0, alpha[i], 2 + j + shift, spin, rx - cx, ry - cy, bodies, False)
            near = abs(math.remainder(math.atan2(ry, rx) + math.pi / 2, 2 * math.pi)) < (
                0.5 * math.pi + 2 * math.pi / geo.n_elements
            )
            if near:
                assert sol.gaps[i, j] == g


def test_convexity_margin_matches_the_derivative_harmonics() -> None:
    h = Harmonics([0, 3, 8, 23], [0.2 * UM, 1 * UM, 0.5 * UM, 0.1 * UM], [0.1, 0.7, 2.0, -1.0])
    radius = 27e-3
    theta = np.linspace(0.0, 2.0 * np.pi, max(256, 16 * h.max_order), endpoint=False)
    r = radius + h.evaluate(theta)
    d1 = h.derivative().evaluate(theta)
    d2 = h.derivative().derivative().evaluate(theta)
    expected = np.min((r * r + 2 * d1 * d1 - r * d2) / (r * r))
    assert rc._convexity_margin(radius, h) == pytest.approx(expected, rel=1e-12)
