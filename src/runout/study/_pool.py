r"""Batched ball-size Monte Carlo on arrays: what a chunk needs, and its evaluation.

What a chunk of the batched ball-size Monte Carlo needs is computed once by the parent
(:class:`BatchArrays`: time grid, approaches and angles of the unperturbed bearing, the lines
and their least-squares projector) and shipped with every chunk as plain arrays; a worker then
runs no case validation and no model setup, only :func:`evaluate_rows`: the batched Newton
kernel (:func:`runout.study._kernels.solve_batch`, seed 001 eq. 16-18), the line fit of every
record by one fixed-order product and the RRO/NRRO split, vectorised over the chunk's bearings.

The pool's worker processes are :mod:`runout.study._workers`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

import numpy as np
from numpy.typing import NDArray

from runout.analysis.decompose import RESIDUAL_REL
from runout.case.estimates import BYTES_PER_ROW_INSTANT, PASS_BYTES

__all__ = [
    "BatchArrays",
    "RowResults",
    "evaluate_rows",
    "line_projector",
    "split_rows",
]


@dataclass(frozen=True)
class BatchArrays:
    """What every bearing of a ball-size Monte Carlo shares, as arrays (picklable, small).

    Attributes
    ----------
    time : ndarray, shape (n,)
        Instants [s].
    c : ndarray, shape (n, Z)
        Approach of every ball at the centred shaft, without size errors [m].
    theta : ndarray, shape (n, Z)
        Ball angles [rad].
    frequencies : ndarray, shape (m,)
        Lines fitted in every record [Hz].
    labels : tuple of str, length m
        Study key of each line.
    projector : ndarray, shape (1 + 2m, n)
        Least-squares projector of the line fit (:func:`line_projector`).
    synchronous : bool
        Something turns with the rotating ring (the synchronous average may enter the RRO).
    z : int
        Number of balls.
    rotation_hz : float
        Speed of the rotating ring [Hz].
    stiffness : float
        Hertz constant K_n [N/m^1.5].
    d_ref : float
        Reference approach of the tolerances [m].
    max_iter : int
        Newton iterations per instant.
    """

    time: NDArray[np.float64]
    c: NDArray[np.float64]
    theta: NDArray[np.float64]
    frequencies: NDArray[np.float64]
    labels: tuple[str, ...]
    projector: NDArray[np.float64]
    synchronous: bool
    z: int
    rotation_hz: float
    stiffness: float
    d_ref: float
    max_iter: int


@dataclass(frozen=True)
class RowResults:
    """Figures of B bearings (rows of a chunk), as arrays; rows with ``status != 0`` failed.

    Attributes
    ----------
    radial, rro, nrro : ndarray, shape (B,)
        Radial (x) p-p, RRO p-p and NRRO p-p [m].
    pp : ndarray, shape (B, 2, m)
        p-p of every line in x and y [m].
    status : ndarray of int, shape (B,)
        0 ok, else the code of :func:`runout.study._kernels.solve_batch`.
    instant : ndarray of int, shape (B,)
        Instant of a failure (-1 when ok).
    """

    radial: NDArray[np.float64]
    rro: NDArray[np.float64]
    nrro: NDArray[np.float64]
    pp: NDArray[np.float64]
    status: NDArray[np.int64]
    instant: NDArray[np.int64]


def line_projector(time: NDArray[np.float64], freqs: NDArray[np.float64]) -> NDArray[np.float64]:
    r"""Least-squares projector P, shape (1 + 2m, n): [c, a_j, b_j] = P x.

    The fit of :func:`runout.analysis.spectrum.extract_lines` (constant plus a cos/sin pair per
    line, :math:`x \approx c + \sum_j a_j\cos 2\pi f_j t + b_j \sin 2\pi f_j t`) written as the
    pseudo-inverse of its design matrix, so that many records are fitted by one product.
    """
    w = 2.0 * np.pi * np.outer(time, freqs)
    design = np.concatenate([np.ones((time.size, 1)), np.cos(w), np.sin(w)], axis=1)
    return np.ascontiguousarray(np.linalg.pinv(design))


def split_rows(
    b: BatchArrays, q: NDArray[np.float64], coef: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """RRO and NRRO p-p of the radial (x) records, as :func:`runout.analysis.decompose.split_runout`
    splits them for one bearing, batched.

    RRO: the integer-order lines, plus the synchronous average of what the lines leave when
    something turns with the rotating ring and the average stands above three times its
    uncertainty and above RESIDUAL_REL of the motion (whole revolutions with a whole number of
    samples each); NRRO: the p-p over the record of the record minus the RRO waveform.

    Parameters
    ----------
    b : BatchArrays
    q : ndarray, shape (B, n, 2)
        Shaft centre [m].
    coef : ndarray, shape (B, 1 + 2m)
        Line fit of the x records.
    """
    t = b.time
    x = q[:, :, 0]
    n_b, m = x.shape[0], b.frequencies.size
    speed = b.rotation_hz
    one_rev = np.linspace(0.0, 1.0 / speed, 4097)[:-1]
    covers_rev = t.size * (t[1] - t[0]) * speed >= 1.0 - 1e-9
    # The RRO waveform over the record and over one revolution; None while it is zero (a
    # Monte Carlo of ball sizes has no integer-order line and nothing synchronous: then RRO is
    # 0 and NRRO the p-p of the record, without building the zero waveforms).
    rro_rec: NDArray[np.float64] | None = None
    rro_rev: NDArray[np.float64] | None = None
    if m:
        orders = b.frequencies / speed
        rep = np.abs(orders - np.round(orders)) < 1e-9
        if rep.any():
            a_c, a_s = coef[:, 1 : 1 + m][:, rep], coef[:, 1 + m :][:, rep]
            rro_rev = np.zeros((n_b, one_rev.size))
            rro_rec = np.zeros_like(x)
            for tt, out in ((one_rev, rro_rev), (t, rro_rec)):
                wr = 2.0 * np.pi * np.outer(b.frequencies[rep], tt)
                out += np.einsum("bk,kn->bn", a_c, np.cos(wr), optimize=False)
                out += np.einsum("bk,kn->bn", a_s, np.sin(wr), optimize=False)
    n_rev = math.floor(t.size * (t[1] - t[0]) * speed + 1e-9)
    spr_f = 1.0 / (speed * (t[1] - t[0]))
    spr = round(spr_f)
    if b.synchronous and n_rev >= 2 and abs(spr_f - spr) < 1e-6 * spr:
        w = 2.0 * np.pi * np.outer(b.frequencies, t)  # (m, n)
        basis = np.concatenate([np.ones((1, t.size)), np.cos(w), np.sin(w)])  # (1 + 2m, n)
        residual = x - np.einsum("bk,kn->bn", coef, basis, optimize=False)
        blocks = residual[:, : n_rev * spr].reshape(n_b, n_rev, spr)
        avg = blocks.mean(axis=1)
        se = blocks.std(axis=1, ddof=1) / math.sqrt(n_rev)
        uncertainty = np.sqrt(np.mean(se**2, axis=1))
        avg = avg - avg.mean(axis=1, keepdims=True)
        level = np.sqrt(np.mean(avg**2, axis=1))
        keep = (level > 3.0 * uncertainty) & (level > RESIDUAL_REL * np.std(x, axis=1))
        if keep.any():
            phase = np.rint((t - t[0]) * speed * spr).astype(np.int64) % spr
            idx = (np.arange(one_rev.size) * spr // one_rev.size) % spr
            rec = np.zeros_like(x) if rro_rec is None else rro_rec
            rev = np.zeros((n_b, one_rev.size)) if rro_rev is None else rro_rev
            rro_rec = rec + np.where(keep[:, None], avg[:, phase], 0.0)
            rro_rev = rev + np.where(keep[:, None], avg[:, idx], 0.0)
    if rro_rec is None or rro_rev is None:
        return np.zeros(n_b), np.ptp(x, axis=1)
    rro = np.ptp(rro_rec if covers_rev else rro_rev, axis=1)
    nrro = np.ptp(x - rro_rec, axis=1)
    return rro, nrro


def rows_per_pass(instants: int) -> int:
    """Bearings evaluated at once by :func:`evaluate_rows` for records of ``instants``."""
    return max(1, PASS_BYTES // (BYTES_PER_ROW_INSTANT * max(instants, 1)))


def evaluate_rows(b: BatchArrays, errors: NDArray[np.float64], parallel: bool) -> RowResults:
    """Runout figures and line p-p of B bearings that differ only by their ball sizes.

    Evaluated in passes of at most :func:`rows_per_pass` bearings, so that a chunk holds at
    most :data:`PASS_BYTES` of records whatever its size.

    Parameters
    ----------
    b : BatchArrays
        The shared bearing.
    errors : ndarray, shape (B, Z)
        Ball diameter errors [m] (the approach of a ball grows by half its error).
    parallel : bool
        Numba threads over bearings (only in the main thread of a process that runs nothing
        else compiled at the same time; see :func:`runout.study._kernels.solve_batch`).

    Returns
    -------
    RowResults
        Every row's numbers depend on that row's errors only (fixed summation orders), never on
        the other rows of the chunk.
    """
    step = rows_per_pass(b.time.size)
    if errors.shape[0] <= step:
        return _evaluate_pass(b, errors, parallel)
    passes = [
        _evaluate_pass(b, errors[i : i + step], parallel) for i in range(0, errors.shape[0], step)
    ]
    return RowResults(
        *(np.concatenate([getattr(r, f.name) for r in passes]) for f in fields(RowResults))
    )


def _evaluate_pass(b: BatchArrays, errors: NDArray[np.float64], parallel: bool) -> RowResults:
    """:func:`evaluate_rows` of one pass of rows, all at once."""
    from runout.study._kernels import project_rows, solve_batch

    n_b = errors.shape[0]
    q, _unloaded, status, instant = solve_batch(
        b.c, 0.5 * errors, b.theta, b.stiffness, b.d_ref, b.max_iter, parallel
    )
    m = b.frequencies.size
    records = np.ascontiguousarray(np.transpose(q, (0, 2, 1)).reshape(-1, b.time.size))
    coef = project_rows(records, b.projector).reshape(n_b, 2, 1 + 2 * m)
    pp = 2.0 * np.hypot(coef[:, :, 1 : 1 + m], coef[:, :, 1 + m :])  # (B, 2, m)
    rro, nrro = split_rows(b, q, coef[:, 0, :])
    radial = np.ptp(q[:, :, 0], axis=1)
    return RowResults(radial, rro, nrro, pp, status, instant)
