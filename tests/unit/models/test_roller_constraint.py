"""The rigid constraint model (seed 004): contact gaps, stable positions, kinematics, errors."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout import BallBearing, GeometryError, NumericalError, Operation, RollerBearing
from runout.geometry.imperfections import BearingImperfections, Harmonics, single_harmonic
from runout.geometry.kinematics import ball_spin_frequency, cage_frequency
from runout.models import roller_constraint as rc

NU209 = RollerBearing(14, 10e-3, 54.991e-3, 75.032e-3)
UM = 1e-6


def _profile(radius: float, h: Harmonics, theta: np.ndarray, turned: float) -> np.ndarray:
    return radius + h.evaluate(theta - turned)


def _brute_distance(
    ra: float,
    ha: Harmonics,
    ta: float,
    rb: float,
    hb: Harmonics,
    tb: float,
    d: np.ndarray,
    facing: bool = True,
) -> float:
    """Euclidean distance between the two profile curves by zooming dense grids (NumPy).

    ``facing``: B's near side points back at A (separate bodies); else B is inside A.
    """
    psi = math.atan2(d[1], d[0])
    ca, cb, w = psi, psi + (math.pi if facing else 0.0), 0.05
    best = math.inf
    for _ in range(12):
        t1 = ca + np.linspace(-w, w, 201)
        t2 = cb + np.linspace(-w, w, 201)
        pa = _profile(ra, ha, t1, ta)[:, None] * np.stack([np.cos(t1), np.sin(t1)], -1)
        pb = d + _profile(rb, hb, t2, tb)[:, None] * np.stack([np.cos(t2), np.sin(t2)], -1)
        dist = np.linalg.norm(pa[:, None, :] - pb[None, :, :], axis=-1)
        i, j = np.unravel_index(np.argmin(dist), dist.shape)
        best, ca, cb = float(dist[i, j]), float(t1[i]), float(t2[j])
        w /= 8.0
    return best


harm = st.lists(
    st.tuples(st.integers(2, 20), st.floats(0.0, 2 * UM), st.floats(0.0, 2 * math.pi)),
    max_size=3,
).map(lambda t: Harmonics([x[0] for x in t], [x[1] for x in t], [x[2] for x in t]))


@settings(max_examples=15, deadline=None)
@given(harm, harm, st.floats(-math.pi, math.pi), st.floats(0, 2 * math.pi), st.floats(0, 6))
def test_pair_gap_is_the_euclidean_distance_between_the_profiles(ha, hb, psi, ta, tb) -> None:
    ra, rb = 27.4955e-3, 5e-3
    dist = ra + rb + 1 * UM + float(ha.amplitudes.sum() + hb.amplitudes.sum())
    d = dist * np.array([math.cos(psi), math.sin(psi)])
    g, normal = rc.pair_gap(ra, ha, rb, hb, d, ta, tb)
    ref = _brute_distance(ra, ha, ta, rb, hb, tb, d)
    assert g == pytest.approx(ref, abs=2e-14)
    # the normal is the gradient of the gap with respect to B's centre (envelope theorem)
    eps = 1e-7
    for e in (np.array([1.0, 0.0]), np.array([0.0, 1.0])):
        gp, _ = rc.pair_gap(ra, ha, rb, hb, d + eps * e, ta, tb)
        gm, _ = rc.pair_gap(ra, ha, rb, hb, d - eps * e, ta, tb)
        assert (gp - gm) / (2 * eps) == pytest.approx(
            e @ [math.cos(normal), math.sin(normal)], abs=1e-7
        )


@settings(max_examples=15, deadline=None)
@given(harm, harm, st.floats(-math.pi, math.pi), st.floats(0, 2 * math.pi))
def test_inside_gap_is_the_distance_from_roller_to_outer_raceway(he, hb, psi, tb) -> None:
    re_, rb = 37.516e-3, 5e-3
    s = re_ - rb - 1 * UM - float(he.amplitudes.sum() + hb.amplitudes.sum())
    d = s * np.array([math.cos(psi), math.sin(psi)])
    g, _ = rc.inside_gap(re_, he, rb, hb, d, 0.0, tb)
    ref = _brute_distance(re_, he, 0.0, rb, hb, tb, d, facing=False)
    assert g == pytest.approx(ref, abs=2e-14)


def test_support_function_of_a_wavy_profile_matches_dense_maximum() -> None:
    h = single_harmonic(10, 1 * UM, 0.3) + single_harmonic(3, 2 * UM, 1.0)
    r = 27.4955e-3
    for psi in np.linspace(0, 2 * np.pi, 7):
        theta = psi + np.linspace(-0.01, 0.01, 200_001)
        dense = np.max(_profile(r, h, theta, 0.4) * np.cos(theta - psi))
        value, _, _ = rc.support_function(r, h, psi, turned=0.4)
        assert value == pytest.approx(dense, abs=1e-15)
        # radial-line value differs at second order only
        assert abs(value - _profile(r, h, np.array([psi]), 0.4)[0]) < 1e-8


def test_circular_parts_match_eq17_over_a_revolution() -> None:
    alpha = rc.rotation_angles(1.0, 1441)
    sol = rc.solve(rc.geometry_from(NU209, BearingImperfections.perfect(14)), alpha)
    ref = rc.analytic_circular(54.991e-3, 75.032e-3, 10e-3, 14, alpha)
    err = np.max(np.linalg.norm(sol.centre - ref, axis=1))
    assert err / np.max(np.abs(ref[:, 1])) < 1e-10
    # with a roller exactly at the bottom the ring sits on it alone: y = -P_d / 2
    # the ring never rises above resting on one roller: y <= -P_d / 2
    assert np.max(sol.centre[:, 1]) <= -NU209.radial_clearance / 2 + 1e-15


def _random_imperfections(rng: np.random.Generator, z: int, amp: float) -> BearingImperfections:
    imp = BearingImperfections.perfect(z)
    for part in ("inner", "outer"):
        k = rng.integers(2, 30, 3)
        imp = imp.add(part, Harmonics(k, rng.uniform(0, amp, 3), rng.uniform(0, 6.3, 3)))
    elems = [
        Harmonics(rng.integers(2, 20, 2), rng.uniform(0, amp / 2, 2), rng.uniform(0, 6.3, 2))
        for _ in range(z)
    ]
    return imp.with_elements(elems).with_element_errors(
        diameter_errors=rng.uniform(-amp, amp, z), pitch_errors=rng.uniform(-1e-3, 1e-3, z)
    )


@pytest.mark.parametrize("ring", ["inner", "outer"])
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_solution_is_a_stable_two_contact_vertex(ring: str, seed: int) -> None:
    rng = np.random.default_rng(seed)
    imp = _random_imperfections(rng, 14, 1.5 * UM)
    op = Operation(ring, radial_load_direction=float(rng.uniform(-np.pi, np.pi)))
    geo = rc.geometry_from(NU209, imp, op)
    sol = rc.solve(geo, rc.rotation_angles(1.0, 361))
    rows = np.arange(sol.alpha.size)
    held = sol.gaps[rows[:, None], sol.pair]
    assert np.max(np.abs(held)) < 1e-13  # both holding rollers touch
    assert sol.gaps.min() > -1e-13  # nothing interferes
    assert sol.multipliers.min() > -1e-9  # the load lies in the cone of the contact normals
    single = sol.pair[:, 0] == sol.pair[:, 1]
    if ring == "inner":
        assert not single.any()  # sitting on one roller is never stable (module docstring)
    else:
        # a hanging outer ring may rest on one roller; its contact normal is then vertical
        assert np.all(sol.multipliers[single] == [1.0, 0.0])


@settings(max_examples=8, deadline=None)
@given(st.floats(-math.pi, math.pi), st.integers(0, 2**31))
def test_rotating_every_part_and_the_load_rotates_the_solution(theta0: float, seed: int) -> None:
    rng = np.random.default_rng(seed)
    imp = _random_imperfections(rng, 14, 1 * UM)
    geo = rc.geometry_from(NU209, imp, Operation("inner"))
    turned = geo.replace(
        inner=geo.inner.shifted(-theta0),
        outer=geo.outer.shifted(-theta0),
        elements=tuple(h.shifted(-theta0) for h in geo.elements),
        pitch_errors=geo.pitch_errors + theta0,
        load_angle=geo.load_angle + theta0,
    )
    alpha = rc.rotation_angles(0.25, 91)
    a = rc.solve(geo, alpha).centre
    b = rc.solve(turned, alpha).centre
    rot = np.array([[math.cos(theta0), -math.sin(theta0)], [math.sin(theta0), math.cos(theta0)]])
    assert np.max(np.abs(a @ rot.T - b)) < 1e-14


def _paper_distance(ring_r, ring_h, ring_turn, centres, roller_p, roller_r, roller_h, roller_turn):
    """Seed 004 eq. 13-16 (cos form): sampled shortest distance, vectorised over centres."""
    rel = roller_p[None, :] - centres  # (G, 2) ring centre -> roller centre
    base = np.arctan2(rel[:, 1], rel[:, 0])
    # the paper samples ±asin(D_w/d_i); the minimum lies within 1e-3 rad of the line of
    # centres, so a ±0.01 rad window with the same fine spacing is the same search, cheaper
    dth = np.linspace(-0.01, 0.01, 201)
    th = base[:, None] + dth[None, :]
    rad = ring_r + ring_h.evaluate(th - ring_turn)
    cpt = centres[:, None, :] + rad[..., None] * np.stack([np.cos(th), np.sin(th)], -1)
    v = cpt - roller_p
    dirn = np.arctan2(v[..., 1], v[..., 0])
    d = np.linalg.norm(v, axis=-1) - (roller_r + roller_h.evaluate(dirn - roller_turn))
    return d.min(axis=1)


@pytest.mark.parametrize("angle_deg", [0.0, 7.3, 100.0])
def test_paper_criteria_5_3_pick_our_position(angle_deg: float) -> None:
    # Oracle: the paper's stepped search (§5.2-5.3) on a grid around our answer.
    imp = (
        BearingImperfections.perfect(14)
        .add("inner", single_harmonic(10, 1 * UM))
        .add("roller", single_harmonic(8, 0.5 * UM))
    )
    geo = rc.geometry_from(NU209, imp)
    sol = rc.solve(geo, np.radians([angle_deg]))
    ours = sol.centre[0]
    step = 5e-9
    xs = ours[0] + step * np.arange(-20, 21)
    ys = ours[1] + step * np.arange(-20, 21)
    grid = np.stack(np.meshgrid(xs, ys, indexing="ij"), -1).reshape(-1, 2)
    alpha = math.radians(angle_deg)
    spin = rc.absolute_spin_ratio(geo) * alpha
    gaps = []
    for j in range(14):
        p = sol.roller_centres[0, j]
        if p[1] > -0.02:  # only the rollers in the lower part can touch
            gaps.append(np.full(grid.shape[0], np.inf))
            continue
        gaps.append(
            _paper_distance(geo.inner_radius, geo.inner, alpha, grid, p,
                            geo.element_radii[j], geo.elements[j], spin)
        )  # fmt: skip
    gap = np.array(gaps).T  # (G, Z)
    tol = step
    contact = np.abs(gap) <= tol
    ok = (gap >= -tol).all(axis=1)
    side = np.sign(sol.roller_centres[0, :, 0])  # left/right of the (vertical) load line
    ok &= (contact & (side < 0)).any(axis=1) & (contact & (side > 0)).any(axis=1)
    assert ok.any()
    ang = np.arctan2(sol.roller_centres[0, :, 1], sol.roller_centres[0, :, 0])
    alpha1 = np.full(grid.shape[0], np.inf)
    for i in np.flatnonzero(ok):
        a = ang[contact[i]]
        alpha1[i] = abs(0.5 * (a.min() + a.max()) + math.pi / 2)
    best = np.flatnonzero(alpha1 <= alpha1.min() + 1e-12)
    chosen = best[np.argmin(grid[best, 1])]  # ties: the lowest position
    assert np.linalg.norm(grid[chosen] - ours) < 3 * step


def test_kinematics_agree_with_runout_kinematics() -> None:
    for ring in ("inner", "outer"):
        geo = rc.geometry_from(NU209, BearingImperfections.perfect(14), Operation(ring))
        fi, fo = (1.0, 0.0) if ring == "inner" else (0.0, 1.0)
        cage = cage_frequency(fi, fo, 10e-3, NU209.pitch_diameter)
        spin = ball_spin_frequency(fi, fo, 10e-3, NU209.pitch_diameter)
        assert rc.cage_ratio(geo) == pytest.approx(cage, rel=1e-14)
        assert abs(rc.absolute_spin_ratio(geo) - rc.cage_ratio(geo)) == pytest.approx(spin)


def test_outer_ring_turning_matches_the_circle_construction() -> None:
    geo = rc.geometry_from(NU209, BearingImperfections.perfect(14), Operation("outer"))
    alpha = rc.rotation_angles(0.3, 121)
    sol = rc.solve(geo, alpha)
    s = geo.inner_radius + 5e-3
    rho = geo.outer_radius - 5e-3
    for n, al in enumerate(alpha):
        beta = 2 * np.pi * np.arange(14) / 14 + rc.cage_ratio(geo) * al
        ja, jb = sol.pair[n]
        pa = s * np.array([math.cos(beta[ja]), math.sin(beta[ja])])
        pb = s * np.array([math.cos(beta[jb]), math.sin(beta[jb])])
        assert np.sin(beta[ja]) > 0 and np.sin(beta[jb]) > 0  # the top rollers carry it
        c = sol.centre[n]
        assert np.linalg.norm(c - pa) == pytest.approx(rho, abs=1e-15)
        assert np.linalg.norm(c - pb) == pytest.approx(rho, abs=1e-15)
    assert sol.centre[:, 1].max() < 0  # the outer ring hangs below the inner ring's centre


def test_ball_bearing_is_solved_in_its_radial_plane() -> None:
    ball = BallBearing(9, 7.9375e-3, 39e-3, radial_clearance=12e-6)
    imp = BearingImperfections.perfect(9).add("inner", single_harmonic(5, 0.5 * UM))
    sol = rc.solve(rc.geometry_from(ball, imp), rc.rotation_angles(1, 721))
    assert sol.radial.mean() == pytest.approx(6e-6, rel=0.1)
    assert 0.0 < sol.runout < 3 * UM


def test_jammed_rollers_raise_naming_the_angle() -> None:
    tight = RollerBearing(14, 10e-3, 55.0e-3, 75.0001e-3)  # 0.1 um clearance
    imp = BearingImperfections.perfect(14).with_diameter_errors([2 * UM] + [0.0] * 13)
    with pytest.raises(NumericalError, match="rotation angle"):
        rc.solve(rc.geometry_from(tight, imp), rc.rotation_angles(1, 361))


def test_non_convex_profile_is_rejected() -> None:
    imp = BearingImperfections.perfect(14).add("inner", single_harmonic(200, 1e-3))
    with pytest.raises(GeometryError, match="not convex"):
        rc.geometry_from(NU209, imp)


def test_order_sweep_shows_the_roller_number_relation() -> None:
    geo = rc.geometry_from(NU209, BearingImperfections.perfect(14))
    sweep = rc.order_sweep(geo, rc.rotation_angles(1, 361), orders=[13, 14, 15], parts=["outer"])
    out = sweep.runout[0]
    assert out[1] > out[0] and out[1] > out[2]  # Z lobes on the outer raceway stand out
    assert sweep.baseline == pytest.approx(
        rc.solve(geo, rc.rotation_angles(1, 361)).runout, rel=1e-12
    )
    assert [r["order"] for r in sweep.rows()] == [13, 14, 15]


CASE = """
title = "small NU209"
[bearing]
type = "cylindrical_roller"
elements = 14
element_diameter = "10 mm"
inner_raceway_diameter = "54.991 mm"
outer_raceway_diameter = "75.032 mm"
[operation]
rotating_ring = "{ring}"
speed = "60 rpm"
radial_load = "10 N"
[[waviness]]
part = "inner"
order = 10
amplitude = "1 um"
[analysis]
model = "roller_constraint"
revolutions = 2
samples = 241
"""


@pytest.mark.parametrize("ring", ["inner", "outer"])
def test_run_case_gives_a_complete_result_and_files(tmp_path, ring: str) -> None:
    import json

    from runout.case.model import load_case
    from runout.runner import run_model

    path = tmp_path / "case.toml"
    path.write_text(CASE.format(ring=ring))
    result = run_model(load_case(path))
    assert result.model == "roller_constraint"
    assert result.runout.radial_pp_m == pytest.approx(np.ptp(result.radial()), rel=1e-12)
    assert result.runout.axial_pp_m is None and not result.z.any()
    # RRO: the turning ring's 10 lobes read in the load zone (k f_i, an integer order) when
    # the inner ring turns; with the outer ring turning nothing turns with it: no RRO
    assert result.runout.nrro_pp_m > 0
    if ring == "inner":
        assert result.runout.rro_pp_m > 0
        assert any(c.repeatable and c.sources[0].term == "k f_i" for c in result.components)
    else:
        assert result.runout.rro_pp_m == 0.0
    assert result.details.horizontal_pp_m > 0
    assert result.time[-1] == pytest.approx(2.0)  # 2 revolutions at 1 rev/s
    json.dumps(result.to_json(), allow_nan=False)
    written = {p.name for p in result.write(tmp_path / "out")}
    assert {"contacts.csv", "order_sweep.csv", "contact_pattern.png", "displacement.png"} <= written
    rows = (tmp_path / "out" / "order_sweep.csv").read_text().splitlines()
    assert rows[1].startswith("order,order_over_z,inner_pp_m") and len(rows) == 2 + 41


def test_summary_shows_the_motion_across_the_load() -> None:
    # the inner ring of a roller bearing moves far more across the load than along it: the
    # readable table says so, next to the measuring-direction figure
    from runout import examples
    from runout.base.display import LENGTH_UNITS
    from runout.runner import run_model

    result = run_model(examples.nu209().case())
    rows = {name: (value, unit) for name, value, unit in result.summary_sections()[0][1]}
    across = result.details.horizontal_pp_m
    value, unit = rows["radial p-p across the load"]  # shown at the table's scale (um here)
    assert float(value) == pytest.approx(across * dict(LENGTH_UNITS)[unit], rel=1e-3)
    assert across > result.runout.radial_pp_m
