"""Benchmarks of the Hertz point-contact solver (runout.geometry.contact).

Reference: what an expert writes with SciPy for the same equation, vectorised: Hertz's
ellipticity equation in κ (Harris, *Rolling Bearing Analysis*, ch. 6) solved for all contacts at
once by ``scipy.optimize.newton`` with its analytic derivative, started from Hamrock & Brewe's
approximation κ ≈ 1.0339 (R_y/R_x)^0.636, then the same stiffness formula.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
from scipy.optimize import newton
from scipy.special import ellipe, ellipk

from _harness import BenchResult, best_time
from runout.geometry.contact import hertz_point_stiffness

N_CONTACTS = 100_000


def _inputs(n: int) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(12345)
    f = rng.uniform(0.0, 0.995, n)
    s = rng.uniform(500.0, 5000.0, n)
    return s, f


def _scipy_newton_stiffness(s: np.ndarray, f: np.ndarray, e_prime: float) -> np.ndarray:
    """Vectorised ``scipy.optimize.newton`` on F(κ) = F(ρ) with dF/dκ, then K of each contact."""

    def residual(k: np.ndarray) -> np.ndarray:
        k2 = k * k
        m = 1.0 - 1.0 / k2
        e = ellipe(m)
        return ((k2 + 1.0) * e - 2.0 * ellipk(m)) / ((k2 - 1.0) * e) - f

    def slope(k: np.ndarray) -> np.ndarray:
        k2 = k * k
        m = 1.0 - 1.0 / k2
        e, kk = ellipe(m), ellipk(m)
        dm = 2.0 / (k2 * k)  # dm/dκ
        de = (e - kk) / (2.0 * m) * dm
        dk = (e - (1.0 - m) * kk) / (2.0 * m * (1.0 - m)) * dm
        num, den = (k2 + 1.0) * e - 2.0 * kk, (k2 - 1.0) * e
        dnum = 2.0 * k * e + (k2 + 1.0) * de - 2.0 * dk
        dden = 2.0 * k * e + (k2 - 1.0) * de
        return (dnum * den - num * dden) / (den * den)

    k0 = 1.0339 * ((1.0 + f) / (1.0 - f)) ** 0.636  # Hamrock & Brewe
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # a contact that does not converge
        kappa = newton(residual, k0, fprime=slope, tol=1e-10, maxiter=50)
    m = 1.0 - 1.0 / kappa**2
    k_int, e_int = ellipk(m), ellipe(m)
    delta_star = 2.0 * k_int / math.pi * (math.pi / (2.0 * kappa**2 * e_int)) ** (1 / 3)
    return 2.0 * math.sqrt(2.0) / 3.0 * e_prime / (np.sqrt(s) * delta_star**1.5)


def bench_point_contact_stiffness_vectorised() -> BenchResult:
    """Stiffness of 10^5 point contacts: ours vs vectorised scipy.optimize.newton."""
    e_prime = 2.28e11
    s, f = _inputs(N_CONTACTS)
    f[f < 1e-6] = 1e-6  # κ = 1 exactly (a circle) is 0/0 in the κ form of the equation
    agree = np.allclose(
        hertz_point_stiffness(s, f, e_prime), _scipy_newton_stiffness(s, f, e_prime), rtol=1e-9
    )
    ours = best_time(lambda: hertz_point_stiffness(s, f, e_prime), repeat=5)
    reference = best_time(lambda: _scipy_newton_stiffness(s, f, e_prime), repeat=5)
    ratio = reference / ours
    return BenchResult(
        name="contact: K for 1e5 point contacts",
        ours_s=ours,
        reference_s=reference,
        reference="vectorised scipy newton",
        target="no slower than vectorised scipy.optimize.newton (>= 1x), same K to 1e-9",
        met=bool(agree and ratio >= 1.0),
    )
