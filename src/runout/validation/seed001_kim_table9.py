"""Seed 001 (Y.-C. Kim, S.-K. Choi, K.-C. Yoon, "Vibration analysis of ball bearings with ball
geometric imperfections") Table 9: the f_c line of 1000 bearings with random ball diameters
(``runout.study.run`` Monte Carlo), and the Rayleigh law it follows.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from runout.validation.cases import example_path, load, uses
from runout.validation.core import Check, bind

__all__ = ["INTRO", "KIM_TABLE9", "STUDY_SAMPLES", "checks", "kim_table9", "rayleigh"]

#: Table 9: ball diameter σ [m] → (mean, standard deviation) of the f_c line p-p [nm].
KIM_TABLE9 = {0.1e-6: (109.95, 57.94), 0.05e-6: (54.17, 29.55), 0.033e-6: (36.69, 19.18)}
STUDY_SAMPLES: int | None = None
"""Bearings per Monte Carlo (None: the case file's 1000). Tests may lower it."""


@functools.cache
def kim_table9(sigma: float) -> np.ndarray:
    """f_c p-p [nm] of every bearing of the Monte Carlo at ball diameter σ.

    Parameters
    ----------
    sigma : float
        Standard deviation σ of the ball diameter errors [m].

    Returns
    -------
    ndarray, shape (samples,)
        The f_c line p-p of each bearing in x [nm] (:data:`STUDY_SAMPLES` bearings, or the
        case file's 1000).

    Notes
    -----
    The study of seed 001 Table 9 (:data:`KIM_TABLE9`).
    """
    from runout.case.model import parse_case
    from runout.study.run import run_study

    case = load("seed001_kim_table9.toml")
    data = case.spec.model_dump(exclude_none=True)
    data["study"]["vary"] = {"element_diameter_sigma": sigma}
    if STUDY_SAMPLES is not None:
        data["study"]["samples"] = STUDY_SAMPLES
    res = run_study(parse_case(data, str(example_path("seed001_kim_table9.toml"))))
    return np.asarray(res.lines["x|ball size error: f_c"][1]) * 1e9


def rayleigh(sigma: float, z: int = 10) -> tuple[float, float]:
    """(mean, standard deviation) [nm] of the f_c line p-p by the Rayleigh law, σ [m].

    The p-p has the scale s = (4/Z) σ √(Z/2): mean s √(π/2), standard deviation
    s √((4 − π)/2).

    Parameters
    ----------
    sigma : float
        Standard deviation σ of the ball diameter errors [m].
    z : int
        Number of balls Z [-].

    Returns
    -------
    tuple of float
        Mean and standard deviation of the f_c line p-p [nm].
    """
    s = 4.0 / z * sigma * math.sqrt(z / 2.0) * 1e9
    return s * math.sqrt(math.pi / 2.0), s * math.sqrt((4.0 - math.pi) / 2.0)


def checks() -> list[Check]:
    """The Monte Carlo table.

    Returns
    -------
    list of Check
        Mean and standard deviation of the f_c line at each σ of Table 9, both against the
        Rayleigh law at σ = 0.1 µm, and the scaling of the mean with σ.

    Notes
    -----
    Seed 001 Table 9 (:data:`KIM_TABLE9`).
    """
    name = uses("seed001_kim_table9.toml", "seed 001 Table 9 (σ = 0.05, 0.033 µm in code)")
    out: list[Check] = []
    for sigma, (mean, std) in KIM_TABLE9.items():
        out += [
            Check(
                f"Seed 001 Table 9, σ = {sigma * 1e6:g} µm",
                "mean f_c p-p [nm]",
                mean,
                bind(lambda sigma: float(np.mean(kim_table9(sigma))), sigma),
                "rel",
                0.06,
                reason="sampling: the standard error of a 1000-bearing mean is 1.7 %; plus the "
                "paper's lower single-ball gain (Table 4)",
                case=name,
            ),
            Check(
                "″",
                "σ of f_c p-p [nm]",
                std,
                bind(lambda sigma: float(np.std(kim_table9(sigma), ddof=1)), sigma),
                "rel",
                0.06,
                reason="sampling (2.2 % standard error)",
                case=name,
            ),
        ]
    r_mean, r_std = rayleigh(0.1e-6)
    out += [
        Check(
            "Rayleigh law (theory), σ = 0.1 µm",
            "Monte Carlo mean [nm] vs s √(π/2), s = (4/Z) σ √(Z/2)",
            r_mean,
            lambda: float(np.mean(kim_table9(0.1e-6))),
            "rel",
            4.0 * math.sqrt((4 - math.pi) / math.pi) / math.sqrt(1000) + 0.005,
            reason="tolerance: 4 standard errors of the mean plus the 0.5 % nonlinear gain",
            case=name,
        ),
        Check(
            "″",
            "Monte Carlo σ [nm] vs s √((4−π)/2)",
            r_std,
            lambda: float(np.std(kim_table9(0.1e-6), ddof=1)),
            "rel",
            4.0 / math.sqrt(2.0 * 1000) + 0.005,
            reason="tolerance: 4 standard errors of σ plus the 0.5 % gain",
            case=name,
        ),
        Check(
            "Same seed for every σ",
            "mean(σ = 0.05 µm) / mean(σ = 0.1 µm)",
            0.5,
            lambda: float(np.mean(kim_table9(0.05e-6)) / np.mean(kim_table9(0.1e-6))),
            "rel",
            2e-3,
            reason="the same standard normals scaled by σ: linear to the Hertz nonlinearity (the "
            "paper drew new diameters for each σ)",
            case=name,
        ),
    ]
    return out


INTRO = """\
Case `examples/seed001_kim_table9.toml`: bearing of Table 1 at 7200 rpm, preload 60.68 N
(fitted to Table 2), 2-D quasi-static model, 8 revolutions × 128 instants, every ball's
**diameter** error normal N(0, σ) (Table 3 is of diameters), 1000 bearings, seed 1; the line is
**peak-to-peak** (the convention that reproduces Tables 4–8). Rayleigh law: f_c p-p has scale
s = (4/Z)·σ·√(Z/2); mean s√(π/2), standard deviation s√((4−π)/2) (derivation in
docs/studies.md). Tests: `tests/reference/test_seed001_kim_table9.py`,
`tests/unit/study/test_study.py`, `tests/unit/study/test_arrangement.py`."""
