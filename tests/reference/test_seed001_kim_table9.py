"""Seed 001 (Kim et al.) Table 9: f_c NRRO of 1000 bearings with random ball diameters.

Published (peak-to-peak, nm): σ = 0.1 / 0.05 / 0.033 µm → mean 109.95 / 54.17 / 36.69,
σ 57.94 / 29.55 / 19.18. Theory (docs/studies.md): the f_c p-p is Rayleigh with scale
s = g·(4/Z)·σ·sqrt(Z/2), g the nonlinear gain of one oversize ball over 4Δ/Z.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from runout.case.model import load_case, parse_case
from runout.study.run import run_study
from runout.validation.seed001_kim_table9 import KIM_TABLE9

CASE = Path(__file__).resolve().parents[2] / "examples" / "seed001_kim_table9.toml"
TABLE9 = KIM_TABLE9  # σ [m] → published (mean, σ) of the f_c p-p [nm]


def study_case(sigma: float):  # type: ignore[no-untyped-def]
    case = load_case(CASE)
    data = case.spec.model_dump(exclude_none=True)
    data["study"]["vary"] = {"element_diameter_sigma": sigma}
    return parse_case(data, str(CASE))


@pytest.fixture(scope="module")
def results() -> dict[float, np.ndarray]:
    out = {}
    for sigma in TABLE9:
        res = run_study(study_case(sigma))
        assert res.samples == 1000 and not res.errors
        out[sigma] = res.lines["x|ball size error: f_c"][1]
    return out


@pytest.mark.parametrize("sigma", sorted(TABLE9), ids=lambda s: f"{s * 1e6:g}um")
def test_kim_table9_fc_mean_and_sigma(results: dict[float, np.ndarray], sigma: float) -> None:
    mean, std = TABLE9[sigma]
    fc = results[sigma] * 1e9
    assert np.mean(fc) == pytest.approx(mean, rel=0.06)
    assert np.std(fc, ddof=1) == pytest.approx(std, rel=0.06)


def test_kim_table9_follows_the_rayleigh_law(results: dict[float, np.ndarray]) -> None:
    z, sigma = 10, 0.1e-6
    scale = 4.0 / z * sigma * math.sqrt(z / 2.0)
    fc = results[sigma]
    n = fc.size
    r_mean, r_std = scale * math.sqrt(math.pi / 2.0), scale * math.sqrt((4.0 - math.pi) / 2.0)
    # sampling error of the mean is r_std / sqrt(n); allow 4 of them plus the 0.5 % gain
    assert abs(np.mean(fc) - r_mean) < 4.0 * r_std / math.sqrt(n) + 0.005 * r_mean
    assert np.std(fc, ddof=1) == pytest.approx(r_std, rel=4.0 / math.sqrt(2.0 * n) + 0.005)
    # Rayleigh: P(X <= x) = 1 - exp(-x^2 / 2 s^2); compare the empirical median
    assert np.median(fc) == pytest.approx(scale * math.sqrt(2.0 * math.log(2.0)), rel=0.06)


def test_kim_table9_scales_with_sigma(results: dict[float, np.ndarray]) -> None:
    # same seed → same standard normals: the f_c line is linear in σ to the Hertz nonlinearity
    ratio = np.mean(results[0.05e-6]) / np.mean(results[0.1e-6])
    assert ratio == pytest.approx(0.5, rel=2e-3)
    # bearing by bearing the line is linear except where the balls nearly cancel
    big = results[0.1e-6] > np.median(results[0.1e-6])
    np.testing.assert_allclose(results[0.05e-6][big] / results[0.1e-6][big], 0.5, rtol=0.02)
