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
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from runout.base.errors import GeometryError

__all__ = [
    "Arrangement",
    "ArrangementLines",
    "line_amplitudes",
    "line_phasors",
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


def line_phasors(
    d: NDArray[np.float64], f: NDArray[np.complex128], p: NDArray[np.complex128]
) -> NDArray[np.complex128]:
    r"""Whirl phasors of the f_c and k f_b ± f_c lines of many arrangements.

    The shaft centre of the module docstring, :math:`q = x + iy`, is the sum
    :math:`q(t) = \sum_l B_l e^{i \nu_l t}` with

    * :math:`B_0 = -(2/Z) \sum_j \Delta_j p_j`, :math:`\nu_0 = \omega_c` (size errors);
    * :math:`B^+_k = -(1/Z) \sum_j A_j p_j`, :math:`\nu = k\omega_b + \omega_c`;
    * :math:`B^-_k = -(1/Z) \sum_j \bar A_j p_j`, :math:`\nu = -(k\omega_b - \omega_c)`,

    from :math:`w_j(t) = \Delta_j + \mathrm{Re}(A_j e^{ik\omega_b t})`. Each line is a circle:
    its p-p along any direction is :math:`2|B|`.

    Parameters
    ----------
    d : ndarray, shape (..., Z)
        Diameter errors by position [m].
    f : ndarray of complex, shape (..., Z, K)
        Diameter-deviation harmonics by position [m].
    p : ndarray of complex, shape (Z,)
        Position phasors :math:`e^{i 2\pi j / Z}`.

    Returns
    -------
    ndarray of complex, shape (..., 1 + 2K)
        :math:`B_0`, then :math:`B^+` of each order, then :math:`B^-` [m].
    """
    z = p.size
    fc = (-2.0 / z) * (d @ p)
    plus = (-1.0 / z) * np.einsum("...jk,j->...k", f, p)
    minus = (-1.0 / z) * np.einsum("...jk,j->...k", np.conj(f), p)
    return np.concatenate([fc[..., None], plus, minus], axis=-1)


def _sum_of_lines(phasors: NDArray[np.complex128]) -> NDArray[np.float64]:
    """Sum of every line's p-p [m] (the Σ column of seed 001 Tables 4-8)."""
    return np.asarray(2.0 * np.abs(phasors).sum(axis=-1))


def _objective(
    d: NDArray[np.float64],
    f: NDArray[np.complex128],
    p: NDArray[np.complex128],
    objective: Objective | None = None,
) -> NDArray[np.float64]:
    """Objective of many arrangements: d (..., Z), f (..., Z, K) → (...)."""
    phasors = line_phasors(d, f, p)
    return _sum_of_lines(phasors) if objective is None else objective(phasors)


#: An objective of many arrangements from their line phasors (..., 1 + 2K) [m] → (...).
Objective = Callable[[NDArray[np.complex128]], NDArray[np.float64]]


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
    random_objectives : ndarray or None
        The objective of every random assembly of the baseline.
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
    random_objectives: NDArray[np.float64] | None = field(default=None, compare=False, repr=False)

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
    objective: Objective | None = None,
) -> Arrangement:
    """Pick Z balls from a lot and order them to minimise the NRRO lines.

    Exact (every selection, every order with ball 0 of the selection at position 0: rotations
    are equivalent for the line magnitudes) when ``C(n, Z)·(Z-1)!`` ≤ ``exact_limit``;
    otherwise a local search:
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
    objective : callable, optional
        What to minimise, from the arrangements' :func:`line_phasors` (shape (..., 1 + 2K))
        to one value each [any unit]; default the sum of every line's p-p [m]. An objective
        with an attribute ``cost`` (work per arrangement relative to the default) lowers
        ``exact_limit`` by that factor; one with ``rotation_invariant = False`` (a p-p along
        one direction) is enumerated over every order, rotations included.

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
    # a rotation of every ball by one position turns the whole pattern in space: the line
    # magnitudes stay, a p-p along one direction over a finite record does not
    turning = bool(getattr(objective, "rotation_invariant", True))
    count = math.comb(n, z) * math.factorial(z - 1 if turning else z)
    cost = float(getattr(objective, "cost", 1.0))
    if count * cost <= exact_limit:
        found, evaluated = _exact(d, f, p, z, objective, turning)
        exact = True
    else:
        found, evaluated = _local_search(d, f, p, z, rng, restarts, objective)
        exact = False
    # random assembly baseline
    picks = np.argsort(rng.random((random_trials, n)), axis=1)[:, :z]
    rand = _objective(d[picks], f[picks], p, objective)
    lucky = int(np.argmin(rand))
    if not exact and rand[lucky] < found[0][1]:
        # the local search is no proof: a random assembly it lost to is the better answer
        candidate = (tuple(int(b) for b in picks[lucky]), float(rand[lucky]))
        found = sorted([candidate, *found], key=lambda c: c[1])
    best = found[0][0]
    verified = None
    if case is not None:
        checks = [(balls, verify(case, d[list(balls)], f[list(balls)], k)) for balls, _ in found]
        checks = checks[:candidates]
        best, verified = min(checks, key=lambda c: c[1]["total_pp_m"])
    lines = line_amplitudes(d[list(best)], f[list(best)], k)
    chosen = lines.total
    if objective is not None:
        chosen = float(_objective(d[list(best)], f[list(best)], p, objective))
    return Arrangement(
        balls=tuple(int(b) for b in best),
        objective=chosen,
        lines=lines,
        exact=exact,
        random_mean=float(rand.mean()),
        random_p50=float(np.median(rand)),
        random_p95=float(np.percentile(rand, 95.0)),
        evaluated=evaluated,
        verified=verified,
        random_objectives=rand,
    )


def _exact(
    d: NDArray[np.float64],
    f: NDArray[np.complex128],
    p: NDArray[np.complex128],
    z: int,
    objective: Objective | None = None,
    turning: bool = True,
) -> tuple[list[tuple[tuple[int, ...], float]], int]:
    if turning:  # rotations are equivalent: the selection's first ball stays at position 0
        perms = np.array(list(itertools.permutations(range(1, z))), np.int64).reshape(-1, z - 1)
        perms = np.concatenate([np.zeros((perms.shape[0], 1), np.int64), perms], axis=1)
    else:
        perms = np.array(list(itertools.permutations(range(z))), np.int64).reshape(-1, z)
    best: list[tuple[tuple[int, ...], float]] = []
    evaluated = 0
    for subset in itertools.combinations(range(d.size), z):
        idx = np.asarray(subset)[perms]  # (P, Z)
        obj = _objective(d[idx], f[idx], p, objective)
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
    objective: Objective | None = None,
) -> tuple[list[tuple[tuple[int, ...], float]], int]:
    n = d.size
    results: list[tuple[tuple[int, ...], float]] = []
    evaluated = 0
    pairs = np.array([(a, b) for a in range(z) for b in range(a + 1, z)], dtype=np.int64)
    for _ in range(restarts):
        perm = rng.permutation(n)
        cur, rest = perm[:z].copy(), perm[z:].copy()
        value = float(_objective(d[cur], f[cur], p, objective))
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
            obj = _objective(d[allc], f[allc], p, objective)
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
