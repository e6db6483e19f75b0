r"""Ball arrangement: which Z balls of a measured lot go into a bearing, and in what order.

Linear superposition (seed 001 eq. 10 and 16-17 linearised about the preloaded state, equal
ball stiffnesses): the balance :math:`\sum_j K'(2c_j + x\cos\theta_j + y\sin\theta_j)
(\cos\theta_j, \sin\theta_j) = 0` with :math:`\sum_j n_j n_j^T = (Z/2) I` gives the shaft
centre

.. math::
    \mathbf q(t) = -\frac{2}{Z} \sum_j w_j(t)\,\mathbf n_j(t), \qquad
    \mathbf n_j = (\cos\theta_j, \sin\theta_j),\ \theta_j = 2\pi f_c t + 2\pi j / Z,

where :math:`w_j` is ball j's diameter deviation along its contact line. With position phasors
:math:`p_j = e^{i 2\pi j/Z}`:

* a size error :math:`\Delta_j` gives the **f_c** line, p-p :math:`(4/Z)\,|\sum_j \Delta_j p_j|`
  in x and in y (a circle);
* a diameter-deviation harmonic :math:`A_j = a_j e^{i\varphi_j}` of order k (even; seed 002
  eq. 26) gives the **k f_b + f_c** line, p-p :math:`(2/Z)\,|\sum_j A_j p_j|`, and the
  **k f_b − f_c** line, p-p :math:`(2/Z)\,|\sum_j A_j \bar p_j|`.

One oversize ball of 0.1 µm in Z = 10 gives 4Δ/Z = 40 nm; the nonlinear 2-D model gives
40.20 nm, and seed 001 Table 4 prints 38.60 nm, a Hann-FFT reading of that line (the same line
passed through the paper's reading gives 38.66 nm, VALIDATION.md). The
optimiser minimises the sum of these line p-p values (the Σ column of seed 001 Tables 4-8)
with the closed form, then checks the best candidates with the nonlinear model
(:func:`verify`).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from runout.base.errors import GeometryError

__all__ = [
    "Arrangement",
    "ArrangementLines",
    "line_amplitudes",
    "optimise_arrangement",
    "verify",
]


@dataclass(frozen=True)
class ArrangementLines:
    """Linear p-p [m] of the lines of one arrangement.

    Attributes
    ----------
    fc : float
        f_c line (size errors).
    plus, minus : ndarray, shape (K,)
        k f_b + f_c and k f_b − f_c lines of each form order.
    orders : ndarray, shape (K,)
        Orders k of the diameter-deviation harmonics.
    """

    fc: float
    plus: NDArray[np.float64]
    minus: NDArray[np.float64]
    orders: NDArray[np.int64]

    @property
    def total(self) -> float:
        """Sum of every line's p-p [m] (the objective)."""
        return float(self.fc + self.plus.sum() + self.minus.sum())


def _phasors(z: int) -> NDArray[np.complex128]:
    return np.exp(2j * np.pi * np.arange(z) / z)


def line_amplitudes(
    size_errors: ArrayLike,
    form: ArrayLike | None = None,
    orders: ArrayLike | None = None,
) -> ArrangementLines:
    """Linear p-p of the f_c and k f_b ± f_c lines (module docstring) for balls in order.

    Parameters
    ----------
    size_errors : array_like, shape (Z,)
        Diameter error of the ball at each position [m], position 0 first.
    form : array_like of complex, shape (Z, K), optional
        Diameter-deviation harmonic of each ball, :math:`a e^{i\\varphi}` [m].
    orders : array_like of int, shape (K,), optional
        Orders k of ``form``'s columns (for the labels; default 2, 4, ...).

    Returns
    -------
    ArrangementLines
        The p-p of the f_c line and of the k f_b ± f_c lines of each order [m].
    """
    d = np.asarray(size_errors, dtype=np.float64)
    z = d.size
    p = _phasors(z)
    fc = 4.0 / z * abs(np.dot(d, p))
    if form is None:
        f = np.zeros((z, 0), dtype=np.complex128)
    else:
        f = np.asarray(form, dtype=np.complex128).reshape(z, -1)
    k = np.asarray(orders if orders is not None else 2 * np.arange(1, f.shape[1] + 1), np.int64)
    plus = 2.0 / z * np.abs(p @ f)
    minus = 2.0 / z * np.abs(np.conj(p) @ f)
    return ArrangementLines(float(fc), plus, minus, k)


def _objective(
    d: NDArray[np.float64], f: NDArray[np.complex128], p: NDArray[np.complex128]
) -> NDArray[np.float64]:
    """Objective of many arrangements: d (..., Z), f (..., Z, K) → (...)."""
    z = p.size
    total = 4.0 / z * np.abs(d @ p)
    if f.shape[-1]:
        total = total + 2.0 / z * (
            np.abs(np.einsum("...jk,j->...k", f, p)).sum(-1)
            + np.abs(np.einsum("...jk,j->...k", f, np.conj(p))).sum(-1)
        )
    return total


@dataclass(frozen=True)
class Arrangement:
    """The chosen balls and the gain over random assembly.

    Attributes
    ----------
    balls : tuple of int
        Indices into the lot of the ball at each position (position 0 first).
    objective : float
        Linear sum of line p-p [m] of this arrangement.
    lines : ArrangementLines
        Its lines.
    exact : bool
        True when every selection and order was enumerated.
    random_mean, random_p50, random_p95 : float
        Objective of random assembly (random Z balls of the lot in random order) [m].
    evaluated : int
        Arrangements evaluated.
    verified : dict or None
        Nonlinear check (:func:`verify`) of the chosen arrangement when a case was given.
    """

    balls: tuple[int, ...]
    objective: float
    lines: ArrangementLines
    exact: bool
    random_mean: float
    random_p50: float
    random_p95: float
    evaluated: int
    verified: dict[str, Any] | None = field(default=None, compare=False)

    @property
    def improvement(self) -> float:
        """Mean objective of random assembly / ours (how many times smaller)."""
        return self.random_mean / self.objective if self.objective > 0 else math.inf


def optimise_arrangement(
    size_errors: ArrayLike,
    n_elements: int,
    *,
    form: ArrayLike | None = None,
    orders: ArrayLike | None = None,
    rng: np.random.Generator,
    exact_limit: int = 2_000_000,
    restarts: int = 16,
    random_trials: int = 4000,
    case: Any = None,
    candidates: int = 3,
) -> Arrangement:
    """Pick Z balls from a lot and order them to minimise the NRRO lines.

    Exact (every selection, every order with ball 0 of the selection at position 0: rotations
    are equivalent) when ``C(n, Z)·(Z-1)!`` ≤ ``exact_limit``; otherwise a local search:
    ``restarts`` random starts, each improved by the best of all position swaps and lot
    exchanges until none improves (each move is evaluated with the closed form).

    Parameters
    ----------
    size_errors : array_like, shape (n,)
        Measured diameter error of every ball of the lot [m].
    n_elements : int
        Z, balls per bearing (<= n).
    form : array_like of complex, shape (n, K), optional
        Measured diameter-deviation harmonics of every ball [m] (phase in the ball's frame).
    orders : array_like of int, shape (K,), optional
        Orders of ``form``'s columns (even; default 2, 4, ...).
    rng : numpy.random.Generator
        Random starts and the random-assembly baseline.
    exact_limit, restarts, random_trials : int
        Search budget: the most arrangements enumerated for an exact search, the local
        search's random starts, and the random assemblies of the baseline.
    case : Case, optional
        A 2-D model case (:mod:`runout.models.quasi_static_2d`); when given, the best
        ``candidates`` distinct arrangements are run by the nonlinear model and the one with the
        smallest nonlinear objective is returned (``verified``).
    candidates : int
        How many of the best arrangements of the closed form the nonlinear model checks
        (with ``case`` only).

    Returns
    -------
    Arrangement
        The chosen balls with their lines and the random-assembly baseline.
    """
    d = np.asarray(size_errors, dtype=np.float64)
    n, z = d.size, int(n_elements)
    if not 3 <= z <= n:
        raise GeometryError("n_elements", f"must be between 3 and the lot size {n}, got {z}")
    f = (
        np.zeros((n, 0), dtype=np.complex128)
        if form is None
        else np.asarray(form, dtype=np.complex128).reshape(n, -1)
    )
    k = np.asarray(orders if orders is not None else 2 * np.arange(1, f.shape[1] + 1), np.int64)
    p = _phasors(z)
    count = math.comb(n, z) * math.factorial(z - 1)
    if count <= exact_limit:
        found, evaluated = _exact(d, f, p, z)
        exact = True
    else:
        found, evaluated = _local_search(d, f, p, z, rng, restarts)
        exact = False
    # random assembly baseline
    picks = np.argsort(rng.random((random_trials, n)), axis=1)[:, :z]
    rand = _objective(d[picks], f[picks], p)
    best = found[0][0]
    verified = None
    if case is not None:
        checks = [(balls, verify(case, d[list(balls)], f[list(balls)], k)) for balls, _ in found]
        checks = checks[:candidates]
        best, verified = min(checks, key=lambda c: c[1]["total_pp_m"])
    lines = line_amplitudes(d[list(best)], f[list(best)], k)
    return Arrangement(
        balls=tuple(int(b) for b in best),
        objective=lines.total,
        lines=lines,
        exact=exact,
        random_mean=float(rand.mean()),
        random_p50=float(np.median(rand)),
        random_p95=float(np.percentile(rand, 95.0)),
        evaluated=evaluated,
        verified=verified,
    )


def _exact(
    d: NDArray[np.float64], f: NDArray[np.complex128], p: NDArray[np.complex128], z: int
) -> tuple[list[tuple[tuple[int, ...], float]], int]:
    perms = np.array(list(itertools.permutations(range(1, z))), dtype=np.int64).reshape(-1, z - 1)
    perms = np.concatenate([np.zeros((perms.shape[0], 1), np.int64), perms], axis=1)
    best: list[tuple[tuple[int, ...], float]] = []
    evaluated = 0
    for subset in itertools.combinations(range(d.size), z):
        idx = np.asarray(subset)[perms]  # (P, Z)
        obj = _objective(d[idx], f[idx], p)
        evaluated += obj.size
        order = np.argsort(obj, kind="stable")[:4]
        best += [(tuple(int(b) for b in idx[i]), float(obj[i])) for i in order]
        best.sort(key=lambda item: item[1])
        best = best[:4]
    return best, evaluated


def _local_search(
    d: NDArray[np.float64],
    f: NDArray[np.complex128],
    p: NDArray[np.complex128],
    z: int,
    rng: np.random.Generator,
    restarts: int,
) -> tuple[list[tuple[tuple[int, ...], float]], int]:
    n = d.size
    results: list[tuple[tuple[int, ...], float]] = []
    evaluated = 0
    pairs = np.array([(a, b) for a in range(z) for b in range(a + 1, z)], dtype=np.int64)
    for _ in range(restarts):
        perm = rng.permutation(n)
        cur, rest = perm[:z].copy(), perm[z:].copy()
        value = float(_objective(d[cur], f[cur], p))
        while True:
            # all position swaps
            swaps = np.repeat(cur[None, :], len(pairs), axis=0)
            rows = np.arange(len(pairs))
            swaps[rows, pairs[:, 0]], swaps[rows, pairs[:, 1]] = cur[pairs[:, 1]], cur[pairs[:, 0]]
            cands = [swaps]
            if rest.size:
                # every exchange of a position's ball with a ball of the rest of the lot
                ex = np.repeat(cur[None, :], z * rest.size, axis=0)
                pos = np.repeat(np.arange(z), rest.size)
                ex[np.arange(ex.shape[0]), pos] = np.tile(rest, z)
                cands.append(ex)
            allc = np.concatenate(cands)
            obj = _objective(d[allc], f[allc], p)
            evaluated += obj.size
            i = int(np.argmin(obj))
            if not obj[i] < value * (1.0 - 1e-12):
                break
            new = allc[i]
            if rest.size:
                rest = np.setdiff1d(np.concatenate([rest, cur]), new)
            cur, value = new.copy(), float(obj[i])
        results.append((tuple(int(b) for b in cur), value))
    results.sort(key=lambda item: item[1])
    unique: list[tuple[tuple[int, ...], float]] = []
    for balls, value in results:
        if balls not in [u for u, _ in unique]:
            unique.append((balls, value))
    return unique, evaluated


def verify(
    case: Any,
    size_errors: ArrayLike,
    form: ArrayLike | None = None,
    orders: ArrayLike | None = None,
) -> dict[str, Any]:
    """Run the nonlinear 2-D model (seed 001) on one arrangement and read its lines.

    Parameters
    ----------
    case : Case
        Bearing and operation (its own imperfections are replaced).
    size_errors : array_like, shape (Z,)
        Diameter errors by position [m].
    form : array_like of complex, shape (Z, K), optional
        Diameter-deviation harmonics by position [m]; ball radius harmonic = half of it.
    orders : array_like of int, shape (K,), optional
        Their (even) orders.

    Returns
    -------
    dict
        ``fc_pp_m``, ``plus_pp_m`` and ``minus_pp_m`` (lists over orders), ``total_pp_m``.
    """
    from runout.analysis.spectrum import extract_lines
    from runout.case.model import Case
    from runout.geometry.imperfections import BearingImperfections, Harmonics
    from runout.models import quasi_static_2d as qs2
    from runout.models._quasi_static import time_grid

    d = np.asarray(size_errors, dtype=np.float64)
    z = d.size
    if z != case.bearing.elements:
        raise GeometryError("size_errors", f"needs {case.bearing.elements} values, got {z}")
    f = np.zeros((z, 0), np.complex128) if form is None else np.asarray(form, np.complex128)
    f = f.reshape(z, -1)
    k = np.asarray(orders if orders is not None else 2 * np.arange(1, f.shape[1] + 1), np.int64)
    elements = [
        Harmonics(k, 0.5 * np.abs(f[j]), np.angle(f[j])) if f.shape[1] else Harmonics.empty()
        for j in range(z)
    ]
    imp = BearingImperfections(elements=elements, diameter_errors=d)
    variant = Case(
        path=case.path,
        title=case.title,
        bearing=case.bearing,
        operation=case.operation,
        imperfections=imp,
        analysis=case.analysis,
        spec=case.spec,
    )
    st = qs2.setup(variant)
    an = case.analysis
    t = time_grid(case.operation.speed, an.revolutions, an.samples)
    disp, _ = qs2.solve(variant, t, st)
    fc, fb = abs(st.kinematics.cage), st.kinematics.spin
    freqs = np.concatenate([[fc], k * fb + fc, np.abs(k * fb - fc)])
    amp = extract_lines(t, disp[0], freqs).amplitude
    m = k.size
    out = {
        "fc_pp_m": float(2.0 * amp[0]),
        "plus_pp_m": [float(2.0 * a) for a in amp[1 : 1 + m]],
        "minus_pp_m": [float(2.0 * a) for a in amp[1 + m :]],
    }
    out["total_pp_m"] = float(2.0 * amp.sum())
    return out
