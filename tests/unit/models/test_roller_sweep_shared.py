"""The order sweep's shared and warm-started work gives the sweep of one solve per geometry.

:func:`runout.models.roller_constraint.order_sweep` settles the rollers once for every
geometry whose harmonic is on the loaded ring (they settle as in the perfect bearing), once
per angle for a roller harmonic (alike rollers on a round fixed ring), starts its Newton
solves warm and computes no gap the search did not need. Each entry must be the runout that
:func:`~runout.models.roller_constraint.solve` gives for that geometry alone.

A harmonic that makes its part non-convex is outside the rigid model (a run refuses such a
part): the sweep leaves it unsolved, and so does the reference here.

Tolerance: the Newton stops (vertex step 1e-10 m, settling step 1e-10 m, normals 1e-9 rad,
all quadratic) leave the centres within ~1e-18 m of the exact stable position, and
rounding of coordinates of ~0.03 m is ~4e-18 m an operation: warm and cold starts agree to
a few 1e-17 m (measured up to 2.3e-17 m on the NU209 example). ``TOL`` = 1e-15 m, 1e-9 of
the 1 µm amplitude, leaves that margin and still catches any roller settled at another
radius (which moves a runout by the order of the amplitude).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from hypothesis import example, given, settings
from hypothesis import strategies as st

from runout.base.errors import NumericalError
from runout.case.model import load_case
from runout.geometry.imperfections import Harmonics, single_harmonic
from runout.models import roller_constraint as rc

TOL = 1e-15  # [m], see the module docstring
EXAMPLE = Path(__file__).resolve().parents[3] / "examples" / "seed004_nu209.toml"


def _nu209() -> rc.ConstraintGeometry:
    case = load_case(EXAMPLE)
    return rc.geometry_from(case.bearing, case.imperfections, case.operation)


def _convexity_margin(geo: rc.ConstraintGeometry) -> float:
    """The smallest convexity margin of the parts (the model refuses one below 0.05)."""
    from runout.models._roller_setup import _convexity_margin as margin

    parts = [(geo.inner_radius, geo.inner), (geo.outer_radius, geo.outer)]
    parts += [(float(r), h) for r, h in zip(geo.element_radii, geo.elements, strict=True)]
    return min(margin(r, h) for r, h in parts)


def _one_by_one(
    geo: rc.ConstraintGeometry,
    alpha: np.ndarray,
    orders: np.ndarray,
    amplitude: float,
    parts: tuple[str, ...],
) -> tuple[float, np.ndarray, np.ndarray]:
    """The sweep as it was computed before: one cold :func:`rc.solve` per geometry."""
    z = geo.n_elements
    perfect = geo.replace(
        inner=Harmonics.empty(),
        outer=Harmonics.empty(),
        elements=(Harmonics.empty(),) * z,
        element_radii=np.full(z, 0.5 * geo.element_diameter),
        pitch_errors=np.zeros(z),
    )
    runout = np.zeros((len(parts), orders.size))
    solved = np.zeros((len(parts), orders.size), dtype=bool)
    for i, part in enumerate(parts):
        for m, k in enumerate(orders):
            h = single_harmonic(int(k), amplitude)
            if part == "inner":
                g = perfect.replace(inner=h)
            elif part == "outer":
                g = perfect.replace(outer=h)
            else:
                g = perfect.replace(
                    elements=rc.elements_to_fixed_frame((h,) * z, perfect.element_positions)
                )
            if _convexity_margin(g) < 0.05:  # outside the rigid model: not solved
                continue
            try:
                runout[i, m] = rc.solve(g, alpha).runout
                solved[i, m] = True
            except NumericalError:
                pass
    return rc.solve(perfect, alpha).runout, runout, solved


def _check(
    geo: rc.ConstraintGeometry,
    alpha: np.ndarray,
    orders: np.ndarray,
    amplitude: float = 1e-6,
    parts: tuple[str, ...] = ("inner", "outer", "roller"),
    knife_edge: float = 0.0,
) -> None:
    """The sweep against one cold solve per geometry; with ``knife_edge`` > 0 an entry whose
    solvability changes when the amplitude moves by that fraction either way is not compared
    (a harmonic exactly at the jamming threshold: which side round-off puts it on is not a
    result)."""
    sweep = rc.order_sweep(geo, alpha, orders, amplitude, parts)
    baseline, runout, solved = _one_by_one(geo, alpha, orders, amplitude, parts)
    posed = np.ones_like(solved)
    if knife_edge > 0.0:
        for f in (1.0 - knife_edge, 1.0 + knife_edge):
            posed &= _one_by_one(geo, alpha, orders, f * amplitude, parts)[2] == solved
    assert np.array_equal(sweep.solved[posed], solved[posed])
    assert abs(sweep.baseline - baseline) <= TOL
    both = posed & solved
    assert np.all(np.abs(sweep.runout - runout)[both] <= TOL), np.max(
        np.abs(sweep.runout - runout)[both]
    )


def test_nu209_sweep_equals_one_solve_per_geometry() -> None:
    # the inner ring turning and loaded; every order 2 ... 3Z on each part
    geo = _nu209()
    _check(geo, rc.rotation_angles(1.0, 181), np.arange(2, 3 * geo.n_elements + 1))


def test_outer_ring_loaded_sweep_equals_one_solve_per_geometry() -> None:
    # the outer ring turning and loaded: the rollers settle on the inner ring, and a
    # harmonic on the outer ring shares the perfect bearing's settled rollers
    geo = _nu209().replace(rotating_ring="outer", load_angle=0.5 * np.pi)
    _check(geo, rc.rotation_angles(1.0, 181), np.arange(2, 3 * geo.n_elements + 1, 3))


def test_same_angle_roller_reading_sweep_equals_one_solve_per_geometry() -> None:
    # seed 004's reading of the roller at its inner contact (separate bodies per roller)
    geo = _nu209().replace(roller_contacts="same_angle")
    for ring in ("inner", "outer"):
        _check(geo.replace(rotating_ring=ring), rc.rotation_angles(1.0, 91), np.arange(2, 12))


def test_tight_clearance_sweep_equals_one_solve_per_geometry() -> None:
    # 9 µm of clearance and 2 µm harmonics: at about a third of the angles the two rollers
    # either side of the load are not the stable pair and the walk tries a third roller,
    # which the sweep's cheap gap bound must not clear while it interferes
    geo = _nu209().replace(outer_radius=0.5 * 75.000e-3)
    for ring in ("inner", "outer"):
        orders = np.arange(2, 3 * geo.n_elements + 1, 4)
        _check(geo.replace(rotating_ring=ring), rc.rotation_angles(1.0, 121), orders, 2e-6)


@settings(max_examples=12, deadline=None)
@given(
    ring=st.sampled_from(["inner", "outer"]),
    contacts=st.sampled_from(["both_ends", "same_angle"]),
    orders=st.lists(st.integers(2, 50), min_size=1, max_size=3, unique=True),
    amplitude=st.floats(0.05e-6, 8e-6),
    clearance=st.floats(5e-6, 60e-6),
    load_angle=st.floats(-np.pi, np.pi),
    spin=st.one_of(st.none(), st.floats(-4.0, 4.0)),
    n=st.integers(2, 60),
)
# a roller of 37 lobes of 4.7 um on 5 mm is not convex: both leave it unsolved (CI found a
# warm and a cold start disagreeing on such a part, whose support has several stationary
# points; the model refuses it in a run)
@example("inner", "both_ends", [37], 4.67403112257499e-06, 4.6226530974125895e-05, 0.0, None, 3)
# a roller of 35 lobes of 3.6 um, close to flat between them (convexity margin 0.12): a random
# run found the sweep's warm walk jammed at one angle (and 7e-10 m off at another load angle)
# where the cold solve did not; below EXACT_MARGIN the sweep walks as the run's solve
@example("outer", "same_angle", [2, 35], 3.6055699134563414e-06, 3.3127898557636e-05, 0.0, 3.0, 50)
@example("outer", "same_angle", [2, 35], 3.6055699134563414e-06, 3.3127898557636e-05, 1.0, 3.0, 52)
# 25 lobes of 7.2 um on a roller (margin 0.10): alike rollers settled once were 1.4e-11 m off
@example("outer", "both_ends", [25, 20], 7.205263720428e-06, 2.332841096543e-05, -0.316, None, 15)
# a roller harmonic of 2.5 um against 10 um of clearance: exactly at the jamming threshold (1e-7
# of the amplitude either way jams every roller order or frees it), where the sweep and the
# solve fell on different sides; such knife-edge entries are left out, the others compared
@example("outer", "same_angle", [17, 12, 32], 2.5e-06, 1e-05, 1.079382125469178, -1.56417, 54)
def test_any_sweep_equals_one_solve_per_geometry(
    ring: str,
    contacts: str,
    orders: list[int],
    amplitude: float,
    clearance: float,
    load_angle: float,
    spin: float | None,
    n: int,
) -> None:
    # amplitudes comparable with the clearance jam some orders: both must say so
    nu209 = _nu209()
    geo = nu209.replace(
        rotating_ring=ring,
        roller_contacts=contacts,
        load_angle=load_angle,
        spin_ratio=spin,
        outer_radius=nu209.inner_radius + nu209.element_diameter + 0.5 * clearance,
    )
    # a harmonic jams the rollers only at amplitudes of a quarter of the clearance (>= 1.25
    # um): 1e-6 of it, >= 1.25e-12 m, moves a tie past the walk's feasibility tolerance of
    # 1e-13 m (random runs find exact ties: 2.5 um harmonics against 10 um of clearance)
    _check(geo, rc.rotation_angles(0.3, n), np.array(orders), amplitude, knife_edge=1e-6)


@settings(max_examples=60, deadline=None)
@given(
    mode=st.sampled_from([0, 1]),
    amplitudes=st.lists(st.floats(0.0, 5e-6), min_size=3, max_size=3),
    orders=st.lists(st.integers(2, 40), min_size=3, max_size=3),
    phases=st.lists(st.floats(0.0, 6.3), min_size=3, max_size=3),
    direction=st.floats(-np.pi, np.pi),
    offset=st.floats(-30e-6, 30e-6),
    centre=st.tuples(st.floats(-20e-6, 20e-6), st.floats(-20e-6, 20e-6)),
    turns=st.tuples(st.floats(-7.0, 7.0), st.floats(-7.0, 7.0), st.floats(-7.0, 7.0)),
)
def test_the_cheap_gap_bound_never_exceeds_the_exact_gap(
    mode: int,
    amplitudes: list[float],
    orders: list[int],
    phases: list[float],
    direction: float,
    offset: float,
    centre: tuple[float, float],
    turns: tuple[float, float, float],
) -> None:
    # _worst skips a roller whose bound is positive (in the run's solve too, where the gaps
    # it skips are computed at the accepted centre): the bound must be a lower bound of the
    # gap the Newton solve gives, overlapping or not, whatever the profiles and their turns
    from runout.models import _roller_kernels as rk
    from runout.models._roller_setup import _bodies

    r_in, r_out, r_roll = 27.4955e-3, 37.516e-3, 5e-3
    profiles = [
        single_harmonic(k, a, p) for k, a, p in zip(orders, amplitudes, phases, strict=True)
    ]
    bodies = _bodies([r_in, r_out, r_roll], profiles)
    dev = rk.deviations(bodies)
    s = (r_out - r_roll if mode == 0 else r_in + r_roll) + offset
    rx = np.array([s * np.cos(direction)])
    ry = np.array([s * np.sin(direction)])
    sh = np.array(turns)
    cx, cy = centre
    bound = rk._gap_bound(mode, 0, cx, cy, rx, ry, bodies[0], dev, False)
    exact, _, _ = rk._constraint(mode, 0, cx, cy, rx, ry, sh, bodies)
    # to rounding: coordinates of 0.04 m round at 7e-18 m (the skip needs only a bound above
    # 0 to put the gap above -TOL_FEASIBLE = -1e-13 m)
    assert bound <= exact + 1e-16
