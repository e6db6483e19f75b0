"""Seed 002 (Anderon vibration of a 608): Tab. 2, Fig. 12-17 band values, eq. 48-59 peaks.

The paper read its band values from a DFT of six revolutions of the displacement density
(rectangular window); we compare through the same route
(``runout.validation.seed002_anderon.anderon_band_values``: 6 revolutions × 1024 samples),
with the exact-line values alongside. Deviations: eq. 43-47 (eq. 47 on ball z = 0 only, as
written, plus a size error W_b00 = 0.1 um of that ball, phase 0: our reading of the B_A0 peak
of Fig. 17). The inner-only and ball-only columns do not depend on the random phases (every
line comes from one harmonic of one part); the outer-only and all-sources columns do, so for
them we check where the paper's value falls in the spread of 200 phase draws.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from runout.geometry.attribution import attribution_rows
from runout.geometry.bearing import BallBearing, Operation
from runout.geometry.imperfections import (
    BearingImperfections,
    Harmonics,
    Slant,
    single_harmonic,
    spectral_law,
)
from runout.models import linear as lin
from runout.validation.kinematics import SEED002_ORDERS
from runout.validation.seed002_anderon import (
    FIG12,
    FIG13,
    FIG15,
    FIG17,
    anderon_band_values,
)

UM = 1e-6
ALPHA = math.radians(10.0)
Z = 7
BEARING = BallBearing(
    elements=Z,
    element_diameter=3.9688e-3,
    pitch_diameter=15e-3,
    inner_conformity=0.52,
    outer_conformity=0.53,
    contact_angle=ALPHA,
)
RATES = lin.rates(BEARING, Operation("inner", 30.0), ALPHA)
BANDS = "URLMHEA"


def _imperfections(rng: np.random.Generator, parts: str = "iob") -> BearingImperfections:
    inner = single_harmonic(1, 2.5 * UM) + spectral_law((2, 799), 0.1 * UM, -1.5, rng=rng)
    outer = spectral_law((2, 1359), 0.1 * UM, -1.5, rng=rng)
    ball = spectral_law((2, 286), 0.1 * UM, -1.5, rng=rng) + Harmonics([0], [0.1 * UM])
    return BearingImperfections(
        inner=inner if "i" in parts else None,
        outer=outer if "o" in parts else None,
        elements=[ball if "b" in parts else Harmonics.empty()] + [Harmonics.empty()] * (Z - 1),
        slant=Slant(0.05 * UM) if "i" in parts else None,
    )


def _bands(imp: BearingImperfections) -> tuple[dict[str, float], dict[str, float]]:
    """(exact-line values, six-revolution DFT values) of x."""
    return anderon_band_values(BEARING, Operation("inner", 30.0), imp)


def _spread(parts: str, draws: int = 200) -> np.ndarray:
    out = np.empty((draws, len(BANDS)))
    for s in range(draws):
        _, dft = _bands(_imperfections(np.random.default_rng(1000 + s), parts))
        out[s] = [dft[b] for b in BANDS]
    return out


@pytest.fixture(scope="module")
def spreads() -> dict[str, np.ndarray]:
    return {parts: _spread(parts) for parts in ("i", "o", "b", "iob")}


@pytest.mark.parametrize(
    ("parts", "published"),
    [
        ("i", FIG13),  # Fig. 13 / Tab. 2 inner
        ("b", FIG17),  # Fig. 17 / Tab. 2 ball
    ],
    ids=["tab2_inner_fig13", "tab2_ball_fig17"],
)
def test_seed002_tab2_phase_independent_columns(
    spreads: dict[str, np.ndarray], parts: str, published: dict[str, float]
) -> None:
    exact, _ = _bands(_imperfections(np.random.default_rng(11), parts))
    again, _ = _bands(_imperfections(np.random.default_rng(99), parts))
    for band, value in published.items():
        # exact lines: one value whatever the phases
        assert again[band] == pytest.approx(exact[band], rel=1e-12)
        assert exact[band] == pytest.approx(value, rel=0.03), band
        # six-revolution DFT (the paper's route): leakage makes it phase dependent
        dft = spreads[parts][:, BANDS.index(band)]
        assert float(np.median(dft)) == pytest.approx(value, rel=0.03), band


@pytest.mark.parametrize(("band", "published"), list(FIG15.items()))
def test_seed002_fig15_outer_only_inside_phase_spread(
    spreads: dict[str, np.ndarray], band: str, published: float
) -> None:
    values = spreads["o"][:, BANDS.index(band)]
    lo, hi = np.percentile(values, [1, 99])
    assert lo <= published <= hi, (band, lo, hi)


@pytest.mark.parametrize(("band", "published"), [(b, FIG12[b]) for b in "LMHE"])
def test_seed002_fig12_all_sources_inside_phase_spread(
    spreads: dict[str, np.ndarray], band: str, published: float
) -> None:
    values = spreads["iob"][:, BANDS.index(band)]
    lo, hi = np.percentile(values, [1, 99])
    assert lo <= published <= hi, (band, lo, hi)


@pytest.mark.parametrize(("band", "published"), [(b, FIG12[b]) for b in "RA"])
def test_seed002_fig12_eccentricity_dominated_bands(
    spreads: dict[str, np.ndarray], band: str, published: float
) -> None:
    spread_all = spreads["iob"]
    # R and A hold the 2.5 um eccentricity line: barely phase dependent, so a 3 % check.
    values = spread_all[:, BANDS.index(band)]
    assert np.ptp(values) < 0.002 * published
    assert np.median(values) == pytest.approx(published, rel=0.03)


def test_seed002_fig12_u_band_is_the_b_a0_line(spreads: dict[str, np.ndarray]) -> None:
    spread_all = spreads["iob"]
    # U holds only B_A0 (plus leakage). With W_b00 = 0.1 um it is 14 % below the published
    # 0.46: W_b00 is not given in the paper (see docs/models/linear.md); not a 3 % match.
    exact, _ = _bands(_imperfections(np.random.default_rng(0), "b"))
    line = 2 * math.cos(ALPHA) / Z * 0.2 * UM * RATES.cage  # density amplitude of B_A0
    expect = line / math.sqrt(2) / 25.4e-9 / math.sqrt(2.0)  # rms / sqrt(log2(4))
    assert exact["U"] == pytest.approx(expect, rel=1e-12)
    median = float(np.median(spread_all[:, 0]))
    assert 0.8 * FIG12["U"] < median < FIG12["U"]


@pytest.mark.parametrize(
    ("factor", "lobes", "published"),
    [
        ("waviness", "nZ-1 = 6 (n=1)", SEED002_ORDERS["I_6"]),  # eq. 48
        ("flaw", "-", SEED002_ORDERS["inner_flaw"]),  # eq. 49-50
    ],
)
def test_seed002_inner_peaks(factor: str, lobes: str, published: float) -> None:
    rows = attribution_rows(3.9688e-3, 15e-3, ALPHA, Z, "inner", 30.0)
    row = next(
        r for r in rows if r["part"] == "inner" and r["factor"] == factor and (r["lobes"] == lobes)
    )
    assert row["order"] == pytest.approx(published, abs=1e-5)
    assert row["frequency_hz"] == pytest.approx(30 * published, abs=3e-4)


def test_seed002_outer_and_ball_peaks_eq51_to_59() -> None:
    rows = attribution_rows(3.9688e-3, 15e-3, ALPHA, Z, "inner", 30.0)

    def order(part: str, factor: str, lobes_start: str = "") -> list[float]:
        return [
            r["order"]
            for r in rows
            if r["part"] == part and r["factor"] == factor and r["lobes"].startswith(lobes_start)
        ]

    o = SEED002_ORDERS
    assert order("outer", "waviness", "nZ-1 = 6")[0] == pytest.approx(o["O_7"], abs=1e-5)
    assert order("outer", "waviness", "nZ-1 = 13")[0] == pytest.approx(o["O_14"], abs=1e-5)
    assert order("outer", "flaw")[0] == pytest.approx(o["O_7"], abs=1e-5)  # eq. 53-54
    assert order("ball", "diameter error")[0] == pytest.approx(o["B_A0"], abs=1e-6)  # eq. 55
    b1 = order("ball", "waviness", "2n = 2")
    assert sorted(b1) == pytest.approx([o["B_B1"], o["B_A1"]], abs=1e-5)  # eq. 56-57
    assert order("ball", "flaw")[0] == pytest.approx(o["ball_flaw"], abs=1e-5)  # eq. 58-59


def test_seed002_lines_sit_at_the_attributed_peaks() -> None:
    imp = _imperfections(np.random.default_rng(4))
    lines = lin.spectral_lines(lin.closed_form_terms(imp, RATES, ALPHA), 30.0, Z, True)
    o = SEED002_ORDERS
    for published in (o["I_6"], o["O_7"], o["O_14"], o["B_A0"], o["B_B1"], o["B_A1"], 1.0, 2.0):
        assert np.min(np.abs(lines.order - published)) < 1e-5, published
