"""Anderon band values against seed 002 (608 bearing, Tab. 1, eq. 43-47, Fig. 12-17, Tab. 2).

Seed 002 eq. 1 defines the Anderon as the rms of dx/dθ [µin/rad] in a band divided by the
square root of the band's width in octaves; eq. 41 gives the outer-ring radial displacement
as lines (amplitude times cos α) and eq. 42 its density dx/dθ. Fig. 12 prints the band values
of the 608 example, whose R band (2/3-5/3 wave) holds essentially one line: the inner-ring
eccentricity W_i1 = 2.5 µm at order 1 (eq. 43).

The lines of the other parts are built straight from the closed forms of seed 002 (eq. 33/35
inner, eq. 37 outer, eq. 39 ball; runout.validation.seed002_anderon) so that the band
machinery is checked against the published L/M/H values too; the line models themselves live
in runout.geometry.imperfections.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from runout.analysis.spectrum import (
    ANDERON_BANDS,
    ANDERON_BANDS_PRINTED,
    MICROINCH,
    BandSet,
    anderon_bands_from_lines,
    anderon_bands_from_waveform,
)
from runout.validation.seed002_anderon import (
    FIG12,
    FIG13,
    FIG15,
    FIG17,
    W_I1,
    ball_lines,
    inner_lines,
    outer_lines,
)

# Seed 002 Tab. 1 (608 bearing): the contact angle
ALPHA = math.radians(10.0)
COS_A = math.cos(ALPHA)
# W_I1 (inner-ring eccentricity, eq. 43 [m]); Fig. 12 (total), Fig. 13 (inner only), Fig. 15
# (outer only), Fig. 17 (ball only) [Anderon]; the lines of eq. 35 (inner), eq. 37 (outer,
# the expected power of the two waviness orders behind each line), eq. 39 (waviness on ball
# z = 0 only, our reading of W_b0k in eq. 47), all times cos α, from the validation module.


def test_unit_is_microinch_per_radian_per_root_octave() -> None:
    assert MICROINCH == pytest.approx(25.4e-9, rel=0, abs=0)
    # 1 µin amplitude at order 1, band one octave wide: rms density 1/sqrt(2) µin/rad.
    one_octave = BandSet.from_edges("one", {"B": (0.75, 1.5)})
    v = anderon_bands_from_lines([1.0], [MICROINCH], one_octave)
    assert v["B"] == pytest.approx(1 / math.sqrt(2), rel=1e-12)


def test_r_band_of_the_eccentricity_line_against_fig12() -> None:
    # Our value: one line W_i1 cos α at order 1 (eq. 41/42), exact band edges 2/3-5/3:
    # 2.5 µm * cos 10° / sqrt(2) / 25.4 nm / sqrt(log2(2.5)) = 59.61 Anderon.
    ours = anderon_bands_from_lines([1.0], [W_I1 * COS_A])["R"]
    assert ours == pytest.approx(59.6127, abs=1e-3)
    gap = ours / FIG12["R"] - 1.0
    # Tolerance 2 %: the published 60.52 is 1.50 % higher. Not band-edge choice (printed
    # edges move the value by 0.16 %, test below) and not DFT leakage (order 1 is on the
    # 1/6-order grid of the paper's six-revolution DFT, test below). The figure matches the
    # line *without* the cos α of eq. 41 to 0.02 % (test below), so we read the gap as cos α
    # not being applied to this line in Fig. 12 -- a 1 - cos 10° = 1.5 % effect.
    assert abs(gap) < 0.02
    assert gap == pytest.approx(-0.0150, abs=0.0005)


def test_band_edge_convention_changes_r_by_a_fraction_of_a_percent() -> None:
    exact = anderon_bands_from_lines([1.0], [W_I1 * COS_A], ANDERON_BANDS)["R"]
    printed = anderon_bands_from_lines([1.0], [W_I1 * COS_A], ANDERON_BANDS_PRINTED)["R"]
    assert printed == pytest.approx(59.7102, abs=1e-3)
    assert abs(printed / exact - 1.0) < 0.002  # 0.16 %: sqrt(log2(2.5) / log2(1.67 / 0.67))


@pytest.mark.parametrize("density", [False, True])
@pytest.mark.parametrize("window", [None, "hann"])
def test_six_revolution_dft_of_the_eccentricity_line(density: bool, window: str | None) -> None:
    # Seed 002 transforms six revolutions; order 1 falls on a bin, so the rectangular DFT
    # reproduces the line value exactly. The Hann window spreads the line over orders 5/6,
    # 1, 7/6, all inside R, and the n² weighting of those neighbours raises the value by
    # sqrt(2/3 + (25/36 + 49/36)/6) - 1 = +0.46 % for a displacement record.
    spr = 720
    theta = 2 * np.pi * np.arange(6 * spr) / spr
    w = W_I1 * COS_A
    x = -w * np.sin(theta + 0.4) if density else w * np.cos(theta + 0.4)
    v = anderon_bands_from_waveform(x, spr, window=window, density=density)
    line = anderon_bands_from_lines([1.0], [w])["R"]
    if window is None:
        assert v["R"] == pytest.approx(line, rel=1e-10)
    elif density:
        assert v["R"] == pytest.approx(line, rel=1e-10)
    else:
        assert v["R"] == pytest.approx(line * math.sqrt(2 / 3 + (25 / 36 + 49 / 36) / 6), rel=1e-9)


def test_published_r_band_is_the_uncorrected_eccentricity() -> None:
    # 2.5 µm at order 1 without cos α gives 60.53 vs 60.52 printed (+0.02 %).
    v = anderon_bands_from_lines([1.0], [W_I1])["R"]
    assert v == pytest.approx(FIG12["R"], rel=1e-3)
    # Cross-check with the A band (1/6-500): recombining the printed U, R and E bands
    # (disjoint, together covering 1/6-360) gives the printed A = 20.52, so the rms behind
    # the printed R really is 69.58 µin/rad = 2.5 µm / sqrt(2), not 2.5 µm cos 10° / sqrt(2).
    ms = sum(
        (FIG12[b] ** 2) * ANDERON_BANDS.bands[ANDERON_BANDS.names.index(b)].octaves
        for b in ("U", "R", "E")
    )
    a_band = math.sqrt(ms / ANDERON_BANDS.bands[ANDERON_BANDS.names.index("A")].octaves)
    assert a_band == pytest.approx(FIG12["A"], abs=0.01)
    r_rms = FIG12["R"] * math.sqrt(math.log2(2.5)) * MICROINCH
    assert r_rms == pytest.approx(W_I1 / math.sqrt(2), rel=1e-3)


def test_inner_ring_bands_against_fig13() -> None:
    # Deterministic amplitudes (one waviness order per line). Ours with cos α:
    # L 1.843, M 0.744, H 0.770 (-1.4 %, -0.8 %, -1.3 %). Tolerance 2 %: two-decimal
    # rounding (up to 0.7 % on M) plus the paper's six-revolution DFT, which mixes the
    # leakage of neighbouring off-bin lines (about 1.5 % on L for a random-phase draw).
    v = anderon_bands_from_lines(*inner_lines())
    for band, published in FIG13.items():
        assert v[band] == pytest.approx(published, rel=0.02), band


def test_ball_bands_against_fig17() -> None:
    # Ours: L 1.055, M 1.186, H 1.151 (+1.4 %, +1.4 %, +1.9 %); tolerance 2.5 % for the same
    # reasons as the inner ring. Waviness on all seven balls would give about 2.7 times more.
    v = anderon_bands_from_lines(*ball_lines())
    for band, published in FIG17.items():
        assert v[band] == pytest.approx(published, rel=0.025), band


def test_outer_ring_bands_against_fig15_expected_power() -> None:
    # Each outer line sums two waviness orders with random phases; we use the expected power,
    # the paper one random draw. M and H hold many lines and agree (-1.1 %, -2.2 %; 5 %
    # tolerance); L holds three lines and its draw is not reproducible (ours 0.47 vs 0.57).
    v = anderon_bands_from_lines(*outer_lines())
    for band in ("M", "H"):
        assert v[band] == pytest.approx(FIG15[band], rel=0.05), band
    assert 0.3 < v["L"] < 0.7


def test_tab2_root_sum_square_of_parts() -> None:
    # Band mean squares add over disjoint sets of lines, so the total is the rss of the parts
    # (Tab. 2). Ours for the total: L 2.18, M 1.48, H 1.46 vs Fig. 12 2.16, 1.46, 1.45.
    parts = [inner_lines(), outer_lines(), ball_lines()]
    each = [anderon_bands_from_lines(o, a) for o, a in parts]
    total = anderon_bands_from_lines(
        np.concatenate([o for o, _ in parts]), np.concatenate([a for _, a in parts])
    )
    rss = np.sqrt(sum(e.values**2 for e in each))
    np.testing.assert_allclose(total.values, rss, rtol=1e-12)
    for band in ("L", "M", "H"):
        assert total[band] == pytest.approx(FIG12[band], rel=0.03), band
        published_rss = math.hypot(FIG13[band], FIG15[band], FIG17[band])
        assert published_rss == pytest.approx(FIG12[band], abs=0.06)  # Tab. 2 column
