"""Benchmark of the spindle model: 4,096 instants of a two-bearing spindle, 16 balls in total.

The HDD spindle example (``examples/spindle_hdd.toml``: two bearings of Tada's size back to
back, 20 N spring preload, waviness on both). Ours: :func:`runout.models.spindle.solve` (the
contact deviations by phasor recurrences and the warm-started compiled Newton solve of the
shaft's 5 + 1 coordinates at every instant), after compilation.

The reference, written here from the equations of docs/models/spindle.md, not by calling
runout's kernels, is what an expert writes with NumPy alone: the deviations as vectorised
harmonic sums (``np.cos`` of every harmonic at every ball and instant), then Newton's method on
all instants at once (batched ``np.linalg.solve`` of the 6x6 systems, every instant from rest,
step halved where the residual grows) to the same tolerance (step <= 1e-11 of the smallest
preload approach). Both solutions are compared before timing.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from _harness import BenchResult, best_time
from runout.case.model import load_case
from runout.models import spindle as sp

CASE = Path(__file__).resolve().parents[1] / "examples" / "spindle_hdd.toml"
RTOL = 1e-11


def _numpy_contacts(
    st: sp.Setup, imps: list, t: NDArray[np.float64]
) -> tuple[NDArray[np.float64], ...]:
    """Approach at q = 0 and cos, sin of the ball angles, shape (n, N), by direct sums."""
    cs, cos_t, sin_t = [], [], []
    for b, imp in zip(st.bearings, imps, strict=True):
        kin, z = b.kinematics, b.kinematics.n_elements
        theta = (
            2 * math.pi * kin.cage * t[:, None] + 2 * math.pi * np.arange(z) / z + imp.pitch_errors
        )
        wi = np.zeros_like(theta)
        for k, a, p in zip(imp.inner.orders, imp.inner.amplitudes, imp.inner.phases, strict=True):
            wi += a * np.cos(k * (theta - 2 * math.pi * kin.inner * t[:, None]) + p)
        wo = np.zeros_like(theta)
        for k, a, p in zip(imp.outer.orders, imp.outer.amplitudes, imp.outer.phases, strict=True):
            wo += a * np.cos(k * (theta - 2 * math.pi * kin.outer * t[:, None]) + p)
        wb = np.zeros_like(theta)
        spin = 2 * math.pi * kin.contact_rate * t
        for j, h in enumerate(imp.element_diameter_deviations()):
            for k, a, p in zip(h.orders, h.amplitudes, h.phases, strict=True):
                wb[:, j] += a * np.cos(k * spin + p)
        cs.append((wi - wo) * math.cos(b.contact_angle) + wb + b.approach)
        cos_t.append(np.cos(theta))
        sin_t.append(np.sin(theta))
    return np.concatenate(cs, 1), np.concatenate(cos_t, 1), np.concatenate(sin_t, 1)


def numpy_solve(st: sp.Setup, imps: list, t: NDArray[np.float64]) -> NDArray[np.float64]:
    """Newton's method on all instants at once (see module docstring), shape (n, m)."""
    c, cth, sth = _numpy_contacts(st, imps, t)
    ca, ssa, p, r, k = st.geo
    nx, ny = ca * cth, ca * sth
    nz = np.broadcast_to(ssa, nx.shape)
    cols = [nx, ny, nz, -p * ny + r * sth * ssa, p * nx - r * cth * ssa]
    if st.n_dof > 5:
        cols.append(np.broadcast_to(np.where(st.floating, -ssa, 0.0), nx.shape))
    g = np.stack(cols, -1)
    q = np.zeros((t.size, st.n_dof))
    tol = RTOL * st.d_ref

    def residual(qq: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        d = np.maximum(c + np.einsum("nja,na->nj", g, qq), 0.0)
        return np.einsum("nj,nja->na", k * d**1.5, g) - st.force, d

    for _ in range(60):
        res, d = residual(q)
        h = np.einsum("nj,nja,njb->nab", 1.5 * k * np.sqrt(d), g, g)
        s = -np.linalg.solve(h, res[..., None])[..., 0]
        step = np.ones(t.size)
        norm0 = np.linalg.norm(res / st.scale, axis=1)
        for _ls in range(30):
            r1, _ = residual(q + step[:, None] * s)
            worse = np.linalg.norm(r1 / st.scale, axis=1) > norm0 * (1 + 1e-12)
            if not worse.any():
                break
            step[worse] *= 0.5
        q = q + step[:, None] * s
        if np.max(np.abs(step[:, None] * s) * st.scale) <= tol:
            return q
    raise AssertionError("the NumPy reference did not converge")


def bench_spindle_hdd_4096_instants() -> BenchResult:
    case = load_case(CASE)
    assert case.spindle is not None
    st = sp.setup(case.spindle, case.operation)
    imps = [b.imperfections for b in case.spindle.bearings]
    t = sp.time_grid(case.operation.speed, case.analysis.revolutions, 4096)
    q, _ = sp.solve(st, imps, t)
    ref = numpy_solve(st, imps, t)
    err = np.abs((q - ref) * st.scale).max()
    if not err < 1e-9 * st.d_ref:
        raise AssertionError(f"the kernel and the NumPy reference disagree by {err:.3g} m")
    ours = best_time(lambda: sp.solve(st, imps, t), repeat=20)
    reference = best_time(lambda: numpy_solve(st, imps, t), repeat=3)
    return BenchResult(
        name="spindle HDD, 2 bearings x 8 balls, 4096 instants",
        ours_s=ours,
        reference_s=reference,
        reference="NumPy: vectorised deviations + batched Newton (6x6 solves)",
        target="< 10 ms after compilation (issue 20)",
        met=ours < 0.010,
    )
