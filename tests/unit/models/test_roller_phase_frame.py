"""Element phase frames: the cage frame (product default) and the fixed frame of seed 004.

Rolling-element waviness is r(ψ) = a cos(kψ + φ) in a frame that turns with the element. The
product's frame is the **cage** frame: ψ = 0 along the outward radius through the element's
centre (its outer contact) at t = 0, as the linear and quasi-static models read it (seed 001
eq. 13, seed 002 eq. 25-26). Seed 004 (Yu et al. 2017) eq. 7 uses the **fixed** frame: ψ = 0
along +x of the bearing for every roller. ``[elements] phase_frame = "fixed"`` converts with
:meth:`BearingImperfections.element_phases_from_fixed_frame`; ``roller_constraint`` reads the cage
frame and converts back to the fixed frame its kernel uses.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Literal

import numpy as np
import pytest

from runout import BallBearing, Operation, RollerBearing
from runout.case.model import load_case
from runout.geometry.imperfections import BearingImperfections, Harmonics, single_harmonic
from runout.geometry.kinematics import bearing_frequencies
from runout.models import roller_constraint as rc

Ring = Literal["inner", "outer"]
UM = 1e-6
Z = 14
NU209 = RollerBearing(Z, 10e-3, 54.991e-3, 75.032e-3)
BALL = BallBearing(9, 3.969e-3, 22.5e-3, 0.52, 0.53, 15e-6)
ALPHA = rc.rotation_angles(1.0, 181)
ALPHA_540 = rc.rotation_angles(1.5, 2161)
EXAMPLES = Path(__file__).resolve().parents[3] / "examples"
REL = 1e-11  # fixed-frame input vs the old model (measured: at most 1.8e-12)

# Recorded from roller_constraint before it read the cage frame (its kernel's fixed frame),
# on _random_imperfections(7, 14, 1.5 µm) / (11, 9, 0.5 µm) over ALPHA: runout [m] and the
# centre [m] at samples 0, 45, 90, 135, 180 (x, y).
OLD_ROLLER = {
    "inner": (
        6.771338346677468e-06,
        [
            -2.4845205232759554e-06, -1.784163126301727e-05, -1.621118797169936e-07,
            -1.8832424154029003e-05, -6.817145997632417e-07, -2.0734034521776895e-05,
            5.31404026107256e-06, -2.0268774346731928e-05, 3.2083784177991587e-07,
            -2.0735179931466337e-05,
        ],
    ),
    "outer": (
        7.252832285047065e-06,
        [
            2.5894816064744455e-06, -1.9734052174305774e-05, -2.3812875949257173e-06,
            -1.8461968719010317e-05, 2.0154089303339442e-06, -1.8979624441368194e-05,
            2.243003125668843e-06, -1.9407718119957483e-05, 5.907568914518882e-07,
            -1.9184723492615808e-05,
        ],
    ),
}  # fmt: skip
OLD_BALL = 1.6145868543602733e-06
OLD_FIG11 = 2.003083150967185e-06  # seed 004 Fig. 11 (1.98 µm published), VALIDATION.md


def _random_imperfections(seed: int, z: int, amp: float) -> BearingImperfections:
    """Waviness on every part (odd and even element orders), size and pitch errors."""
    rng = np.random.default_rng(seed)
    imp = BearingImperfections.perfect(z)
    for part in ("inner", "outer"):
        k = rng.integers(2, 30, 3)
        imp = imp.add(part, Harmonics(k, rng.uniform(0, amp, 3), rng.uniform(0, 6.3, 3)))
    elems = [
        Harmonics(rng.integers(1, 20, 3), rng.uniform(0, amp / 2, 3), rng.uniform(0, 6.3, 3))
        for _ in range(z)
    ]
    return imp.with_elements(elems).with_element_errors(
        diameter_errors=rng.uniform(-amp, amp, z), pitch_errors=rng.uniform(-2e-3, 2e-3, z)
    )


def _beta(imp: BearingImperfections) -> np.ndarray:
    """Element centres at t = 0 [rad]: 2πj/Z + pitch error (j 0-based)."""
    z = imp.n_elements
    return 2 * np.pi * np.arange(z) / z + imp.pitch_errors


# --------------------------------------------------------------------------------------------
# BearingImperfections.element_phases_from_fixed_frame
# --------------------------------------------------------------------------------------------
def test_fixed_to_cage_frame_turns_each_element_by_its_position() -> None:
    imp = _random_imperfections(7, Z, 1.5 * UM)
    cage = imp.element_phases_from_fixed_frame()
    psi = np.linspace(0.0, 2 * np.pi, 97)
    for j, b in enumerate(_beta(imp)):
        # the material point at ψ_c in the cage frame is at ψ_c + β_j in the fixed frame
        fixed_values = imp.elements[j].evaluate(psi + b)
        np.testing.assert_allclose(cage.elements[j].evaluate(psi), fixed_values, rtol=0, atol=1e-18)
        np.testing.assert_array_equal(cage.elements[j].orders, imp.elements[j].orders)
        np.testing.assert_array_equal(cage.elements[j].amplitudes, imp.elements[j].amplitudes)
    assert cage.inner == imp.inner and cage.outer == imp.outer and cage.slant is imp.slant
    np.testing.assert_array_equal(cage.diameter_errors, imp.diameter_errors)
    np.testing.assert_array_equal(cage.pitch_errors, imp.pitch_errors)


def test_fixed_frame_peak_along_x_sits_at_minus_beta_in_the_cage_frame() -> None:
    # sign check: a fixed-frame lobe pointing along +x of the bearing is seen from the element's
    # outward radius (at β_j) at ψ_c = -β_j; phase φ_c = φ_f + k β_j
    k, a = 8, 0.5 * UM
    imp = BearingImperfections.perfect(Z).add("roller", single_harmonic(k, a))
    cage = imp.element_phases_from_fixed_frame()
    for j, b in enumerate(_beta(imp)):
        assert cage.elements[j].evaluate(np.array([-b]))[0] == pytest.approx(a, rel=1e-12)
        assert cage.elements[j].phases[0] == pytest.approx((k * b) % (2 * np.pi), abs=1e-12)


def test_size_errors_and_perfect_elements_have_no_phase_to_change() -> None:
    imp = BearingImperfections.perfect(5).add("ball", Harmonics([0], [1 * UM]), element=2)
    imp = imp.with_pitch_errors([0.01, -0.02, 0.0, 0.03, 0.0])
    cage = imp.element_phases_from_fixed_frame()
    assert cage.elements == imp.elements


# --------------------------------------------------------------------------------------------
# roller_constraint reads the cage frame
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize("ring", ["inner", "outer"])
def test_fixed_frame_input_gives_the_old_roller_constraint(ring: Ring) -> None:
    imp = _random_imperfections(7, Z, 1.5 * UM)
    op = Operation(ring)
    new = rc.solve(rc.geometry_from(NU209, imp.element_phases_from_fixed_frame(), op), ALPHA)
    # the kernel input of the old model: the user's harmonics taken as fixed-frame ones
    old_geo = rc.geometry_from(NU209, imp, op).replace(elements=imp.elements)
    old = rc.solve(old_geo, ALPHA)
    # the phases go through φ + kβ_j - kβ_j (wrapped to [0, 2π)): round-off of ~1e-15 rad,
    # which the Newton solves carry to ~2e-12 of the centre (4e-17 m; the solver's floor)
    scale = float(np.abs(old.centre).max())
    assert np.max(np.abs(new.centre - old.centre)) <= REL * scale
    np.testing.assert_array_equal(new.pair, old.pair)
    # and the numbers recorded from the old implementation
    runout, centres = OLD_ROLLER[ring]
    assert new.runout == pytest.approx(runout, rel=REL)
    recorded = np.asarray(centres).reshape(5, 2)
    assert np.max(np.abs(new.centre[[0, 45, 90, 135, 180]] - recorded)) <= REL * scale


def test_fixed_frame_input_gives_the_old_model_for_a_ball_bearing() -> None:
    imp = _random_imperfections(11, 9, 0.5 * UM)
    new = rc.solve(rc.geometry_from(BALL, imp.element_phases_from_fixed_frame()), ALPHA)
    assert new.runout == pytest.approx(OLD_BALL, rel=REL)


def test_seed004_fig11_in_the_fixed_frame_keeps_its_value() -> None:
    imp = BearingImperfections.perfect(Z).add("roller", single_harmonic(8, 0.5 * UM))
    fixed = rc.solve(rc.geometry_from(NU209, imp.element_phases_from_fixed_frame()), ALPHA_540)
    assert fixed.runout == pytest.approx(OLD_FIG11, rel=REL)


def test_case_key_phase_frame_fixed_keeps_the_seed004_example(tmp_path: Path) -> None:
    text = (EXAMPLES / "seed004_nu209_fig11.toml").read_text(encoding="utf-8")
    if "phase_frame" not in text:
        text += '\n[elements]\nphase_frame = "fixed"\n'
    path = tmp_path / "fig11_fixed.toml"
    path.write_text(text, encoding="utf-8")
    case = load_case(path)
    sol = rc.solve(rc.geometry_from(case.bearing, case.imperfections, case.operation), ALPHA_540)
    assert sol.runout == pytest.approx(OLD_FIG11, rel=REL)


@pytest.mark.parametrize("ring", ["inner", "outer"])
def test_cage_frame_every_roller_shows_the_same_deviation_at_its_outer_contact(ring: Ring) -> None:
    # "every roller, 8 lobes, phase 0": in the cage frame each roller presents the lobe's peak
    # at its outer contact at t = 0, and the contact point then runs over the roller at the
    # spin relative to the cage, +f_b per ring turn for the inner ring turning (the
    # quasi-static models' Kinematics.contact_rate, seed 002 eq. 6), -f_b for the outer
    k, a = 8, 0.5 * UM
    imp = BearingImperfections.perfect(Z).add("roller", single_harmonic(k, a))
    geo = rc.geometry_from(NU209, imp, Operation(ring))
    cage, spin = rc.cage_ratio(geo), rc.absolute_spin_ratio(geo)
    f = bearing_frequencies(NU209, Operation(ring, 1.0))
    rate = f.ball_spin if ring == "inner" else -f.ball_spin
    assert cage - spin == pytest.approx(rate, rel=1e-12)
    beta = _beta(imp)
    for alpha in (0.0, 0.3, 2.0, 7.1):
        # radius of roller j along its outward radius (the kernel turns it by spin·α)
        outward = beta + cage * alpha
        radius = [
            geo.elements[j].evaluate(np.array([outward[j] - spin * alpha]))[0] for j in range(Z)
        ]
        np.testing.assert_allclose(radius, a * math.cos(k * rate * alpha), rtol=0, atol=1e-18)


def test_cage_frame_rollers_settle_alike_and_the_fixed_frame_ones_do_not() -> None:
    k, a = 8, 0.5 * UM
    cage_imp = BearingImperfections.perfect(Z).add("roller", single_harmonic(k, a))
    geo = rc.geometry_from(NU209, cage_imp)
    sol = rc.solve(geo, np.zeros(1))
    # rollers in the load zone (below the centre) settle onto the outer raceway at t = 0 on
    # their outer contact: the lobe's peak, radius D_w/2 + a, for every one of them
    low = sol.roller_centres[0, :, 1] < -0.02
    dist = np.linalg.norm(sol.roller_centres[0, low], axis=1)
    np.testing.assert_allclose(dist, geo.outer_radius - 5e-3 - a, rtol=0, atol=1e-15)
    fixed = rc.solve(rc.geometry_from(NU209, cage_imp.element_phases_from_fixed_frame()), [0.0])
    spread = np.ptp(np.linalg.norm(fixed.roller_centres[0, low], axis=1))
    assert spread > 0.5 * a  # a cos(8 β_j) differs from roller to roller


def test_geometry_holds_the_kernel_fixed_frame_and_its_cage_view() -> None:
    imp = _random_imperfections(3, Z, 1 * UM)
    geo = rc.geometry_from(NU209, imp)
    psi = np.linspace(0.0, 2 * np.pi, 61)
    for j, b in enumerate(_beta(imp)):
        np.testing.assert_allclose(
            geo.elements[j].evaluate(psi + b), imp.elements[j].evaluate(psi), rtol=0, atol=1e-18
        )
        np.testing.assert_allclose(
            geo.cage_frame_elements[j].evaluate(psi),
            imp.elements[j].evaluate(psi),
            rtol=0,
            atol=1e-18,
        )


def test_order_sweep_puts_the_roller_harmonic_in_every_roller_cage_frame() -> None:
    alpha = rc.rotation_angles(0.5, 181)
    geo = rc.geometry_from(NU209, BearingImperfections.perfect(Z))
    sweep = rc.order_sweep(geo, alpha, orders=[8, 15], parts=("roller",))
    for i, k in enumerate((8, 15)):
        imp = BearingImperfections.perfect(Z).add("roller", single_harmonic(k, 1 * UM))
        direct = rc.solve(rc.geometry_from(NU209, imp), alpha).runout
        assert sweep.runout[0, i] == pytest.approx(direct, rel=1e-12)
        fixed = rc.solve(rc.geometry_from(NU209, imp.element_phases_from_fixed_frame()), alpha)
        assert abs(sweep.runout[0, i] / fixed.runout - 1.0) > 1e-3


def test_cage_lines_are_offered_only_for_rollers_that_differ_in_the_cage_frame() -> None:
    same = BearingImperfections.perfect(Z).add("roller", single_harmonic(8, 0.5 * UM))
    labels = [c.source.label() for c in rc._candidate_lines(rc.geometry_from(NU209, same))]
    assert not any(label.startswith("cage") for label in labels)
    # identical in the fixed frame = different relative to the cage: uneven rollers
    turned = same.element_phases_from_fixed_frame()
    labels = [c.source.label() for c in rc._candidate_lines(rc.geometry_from(NU209, turned))]
    assert any(label.startswith("cage") for label in labels)
    # the same judged on the kernel's geometry: identical fixed-frame profiles are uneven
    geo = rc.geometry_from(NU209, BearingImperfections.perfect(Z))
    fixed_same = geo.replace(elements=(single_harmonic(8, 0.5 * UM),) * Z)
    assert any(c.source.part == "cage" for c in rc._candidate_lines(fixed_same))
