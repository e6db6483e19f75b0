"""Benchmarks of the Hertz point-contact solver (runout.contact)."""

from __future__ import annotations

import math
import time

import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from _harness import BenchResult, best_time
from runout.contact import hertz_point_stiffness

N_CONTACTS = 100_000
N_NAIVE = 2_000  # the per-contact loop is timed on this subset and scaled to N_CONTACTS


def _inputs(n: int) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(12345)
    f = rng.uniform(0.0, 0.995, n)
    s = rng.uniform(500.0, 5000.0, n)
    return s, f


def _naive_stiffness(s: np.ndarray, f: np.ndarray, e_prime: float) -> np.ndarray:
    """Textbook approach: per contact, solve Hertz's equation for κ with brentq."""
    out = np.empty_like(s)
    for i, (si, fi) in enumerate(zip(s, f, strict=True)):
        if fi == 0.0:
            kappa = 1.0
        else:

            def g(k: float, fi: float = fi) -> float:
                m = 1.0 - 1.0 / (k * k)
                e = ellipe(m)
                return ((k * k + 1.0) * e - 2.0 * ellipk(m)) / ((k * k - 1.0) * e) - fi

            kappa = brentq(g, 1.0 + 1e-9, 1e4, xtol=1e-12)
        m = 1.0 - 1.0 / kappa**2
        k_int, e_int = ellipk(m), ellipe(m)
        delta_star = 2.0 * k_int / math.pi * (math.pi / (2.0 * kappa**2 * e_int)) ** (1 / 3)
        out[i] = 2.0 * math.sqrt(2.0) / 3.0 * e_prime / (math.sqrt(si) * delta_star**1.5)
    return out


def bench_point_contact_stiffness_vectorised() -> BenchResult:
    """Stiffness of 10^5 point contacts: vectorised safeguarded Newton vs per-contact brentq."""
    e_prime = 2.28e11
    s, f = _inputs(N_CONTACTS)
    ours = best_time(lambda: hertz_point_stiffness(s, f, e_prime), repeat=3)

    s_sub, f_sub = s[:N_NAIVE], f[:N_NAIVE]
    t0 = time.perf_counter()
    naive = _naive_stiffness(s_sub, f_sub, e_prime)
    reference = (time.perf_counter() - t0) * (N_CONTACTS / N_NAIVE)

    agree = np.allclose(hertz_point_stiffness(s_sub, f_sub, e_prime), naive, rtol=1e-9)
    ratio = reference / ours
    return BenchResult(
        name="contact: K for 1e5 point contacts",
        ours_s=ours,
        reference_s=reference,
        reference=f"brentq loop ({N_NAIVE} scaled)",
        target=">= 50x faster than per-contact brentq, same K to 1e-9",
        met=bool(agree and ratio >= 50.0),
    )
