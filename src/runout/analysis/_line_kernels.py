"""Kernels of the known-line fit of :func:`runout.analysis.spectrum.extract_lines`: projection and
synthesis on a uniform grid (blocks of :data:`_ANCHOR` samples as BLAS matrix products) with
their NumPy references, and the Gram matrices.

The uniform-grid kernels are NumPy and BLAS, not compiled: a product of the record's blocks
with one table of in-block phasors is as fast as a compiled rotating-phasor loop (faster for
long records) and costs no compilation on the first run of a model.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from runout.base._threads import halves, in_spans, one_blas_thread

FloatArray = npt.NDArray[np.float64]


#: Samples per block: the phasor of sample ``i0 + r`` of a block is the product of the exact
#: phasors of the block's start ``i0`` and of the offset ``r`` (no recurrence, no drift).
_ANCHOR = 256

#: Blocks per matrix product: bounds the temporaries to ``_BLOCKS`` x (2 m + 1) per channel.
_BLOCKS = 64

#: Records of at least this many samples are projected and synthesised on two threads.
_PARALLEL_MIN = 1 << 16


def _offset_table(dt: float, omega: FloatArray) -> FloatArray:
    """``[cos | sin](omega_j r dt)`` for the in-block offsets r < :data:`_ANCHOR`, (A, 2m)."""
    phase = np.multiply.outer(np.arange(_ANCHOR) * dt, omega)
    return np.concatenate([np.cos(phase), np.sin(phase)], axis=1)


def _start_phasors(dt: float, omega: FloatArray, first: int, last: int) -> FloatArray:
    """cos and sin of ``omega_j i0 dt`` at the starts ``i0`` of blocks ``first..last-1``."""
    phase = np.multiply.outer(np.arange(first, last) * _ANCHOR * dt, omega)
    return np.stack([np.cos(phase), np.sin(phase)])


def _project_span(
    x: FloatArray, w: FloatArray, dt: float, omega: FloatArray, first: int, last: int
) -> tuple[FloatArray, FloatArray]:
    """The sums of :func:`_project_uniform_kernel` over blocks ``first <= blk < last``."""
    nc, n = x.shape
    m = omega.shape[0]
    out_c = np.zeros((nc, m))
    out_s = np.zeros((nc, m))
    for b0 in range(first, last, _BLOCKS):
        b1 = min(b0 + _BLOCKS, last)
        i0, i1 = b0 * _ANCHOR, min(b1 * _ANCHOR, n)
        full = (i1 - i0) // _ANCHOR  # whole blocks; a short last block goes on its own
        zc, zs = _start_phasors(dt, omega, b0, b1)
        # in-block sums of x cos(omega r dt) and x sin(omega r dt), (nc, blocks, 2m)
        p = x[:, i0 : i0 + full * _ANCHOR].reshape(nc, full, _ANCHOR) @ w
        if full < b1 - b0:
            tail = x[:, i0 + full * _ANCHOR : i1]
            p = np.concatenate([p, (tail @ w[: tail.shape[1]])[:, None, :]], axis=1)
        # rotated by each block's start: cos(a + b) = cos a cos b - sin a sin b, ...
        pc, ps = p[..., :m], p[..., m:]
        out_c += np.einsum("kbj,bj->kj", pc, zc) - np.einsum("kbj,bj->kj", ps, zs)
        out_s += np.einsum("kbj,bj->kj", pc, zs) + np.einsum("kbj,bj->kj", ps, zc)
    return out_c, out_s


def _project_uniform_kernel(
    x: FloatArray, dt: float, omega: FloatArray
) -> tuple[FloatArray, FloatArray]:
    """C[k, j] = sum_i x[k, i] cos(omega_j i dt), S[k, j] = sum_i x[k, i] sin(omega_j i dt).

    The record is cut in blocks of :data:`_ANCHOR` samples: one matrix product of the blocks
    with the table of in-block phasors gives every block's sums, which the exact phasor of
    the block's start rotates to the record's origin (no recurrence: round-off at the 1e-16
    level). The blocks are independent: a long record's halves run on two threads
    (:mod:`runout.base._threads`, BLAS on one thread each) with the same result to the bit.
    :func:`_project_numpy` is the reference it is tested against.
    """
    n = x.shape[1]
    nb = (n + _ANCHOR - 1) // _ANCHOR
    w = _offset_table(dt, omega)
    with one_blas_thread():
        parts = in_spans(
            lambda first, last: _project_span(x, w, dt, omega, first, last),
            halves(nb, _PARALLEL_MIN // _ANCHOR),
        )
    out_c, out_s = parts[0]
    for part_c, part_s in parts[1:]:
        out_c = out_c + part_c
        out_s = out_s + part_s
    return out_c, out_s


def _synthesize_span(
    const: FloatArray,
    a: FloatArray,
    b: FloatArray,
    wt: FloatArray,
    dt: float,
    omega: FloatArray,
    first: int,
    last: int,
    y: FloatArray,
) -> None:
    """Blocks ``first <= blk < last`` of :func:`_synthesize_uniform_kernel` into ``y``."""
    nc, m = a.shape
    n = y.shape[1]
    for b0 in range(first, last, _BLOCKS):
        b1 = min(b0 + _BLOCKS, last)
        zc, zs = _start_phasors(dt, omega, b0, b1)
        # a cos(s + r) + b sin(s + r) = (a cos s + b sin s) cos r + (b cos s - a sin s) sin r,
        # and the constant times a row of ones: one product per chunk of blocks
        coef = np.empty((nc, b1 - b0, 2 * m + 1))
        coef[..., :m] = a[:, None, :] * zc + b[:, None, :] * zs
        coef[..., m : 2 * m] = b[:, None, :] * zc - a[:, None, :] * zs
        coef[..., 2 * m] = const[:, None]
        i0, i1 = b0 * _ANCHOR, min(b1 * _ANCHOR, n)
        y[:, i0:i1] = (coef @ wt).reshape(nc, -1)[:, : i1 - i0]


def _synthesize_uniform_kernel(
    const: FloatArray, a: FloatArray, b: FloatArray, dt: float, omega: FloatArray, n: int
) -> FloatArray:
    """y[k, i] = const[k] + sum_j a[k, j] cos(omega_j i dt) + b[k, j] sin(omega_j i dt).

    Same blocks as :func:`_project_uniform_kernel`: each block's coefficients are rotated by
    the exact phasor of its start, then one matrix product with the table of in-block phasors
    writes the samples. Blocks are independent: a long record's halves run on two threads
    with the same result to the bit.
    """
    y = np.empty((a.shape[0], n))
    nb = (n + _ANCHOR - 1) // _ANCHOR
    wt = np.concatenate([_offset_table(dt, omega).T, np.ones((1, _ANCHOR))])
    with one_blas_thread():
        in_spans(
            lambda first, last: _synthesize_span(const, a, b, wt, dt, omega, first, last, y),
            halves(nb, _PARALLEL_MIN // _ANCHOR),
        )
    return y


_CHUNK = 2048


def _project_numpy(x: FloatArray, tau: FloatArray, omega: FloatArray) -> tuple[FloatArray, ...]:
    """NumPy reference of :func:`_project_uniform_kernel` for arbitrary sample times."""
    nc = x.shape[0]
    out_c = np.zeros((nc, omega.size))
    out_s = np.zeros((nc, omega.size))
    for i0 in range(0, tau.size, _CHUNK):
        ph = np.outer(tau[i0 : i0 + _CHUNK], omega)
        xs = x[:, i0 : i0 + _CHUNK]
        out_c += xs @ np.cos(ph)
        out_s += xs @ np.sin(ph)
    return out_c, out_s


def _synthesize_numpy(
    const: FloatArray, a: FloatArray, b: FloatArray, tau: FloatArray, omega: FloatArray
) -> FloatArray:
    """NumPy reference of :func:`_synthesize_uniform_kernel` for arbitrary sample times."""
    y = np.empty((a.shape[0], tau.size))
    for i0 in range(0, tau.size, _CHUNK):
        ph = np.outer(tau[i0 : i0 + _CHUNK], omega)
        y[:, i0 : i0 + _CHUNK] = const[:, None] + a @ np.cos(ph).T + b @ np.sin(ph).T
    return y


def _gram_numpy(tau: FloatArray, omega: FloatArray, constant: bool) -> FloatArray:
    """M^T M accumulated over chunks of the design matrix (any sample times)."""
    m = omega.size
    p = 2 * m + int(constant)
    g = np.zeros((p, p))
    for i0 in range(0, tau.size, _CHUNK):
        ph = np.outer(tau[i0 : i0 + _CHUNK], omega)
        cols = [np.cos(ph), np.sin(ph)]
        if constant:
            cols.insert(0, np.ones((ph.shape[0], 1)))
        mc = np.hstack(cols)
        g += mc.T @ mc
    return g


def _dirichlet_sum(phi: FloatArray, n: int) -> npt.NDArray[np.complex128]:
    """sum_{i=0}^{n-1} exp(1j * phi * i), exactly, for any real ``phi``."""
    r = np.remainder(phi + np.pi, 2.0 * np.pi) - np.pi  # same phasors, r in [-pi, pi)
    half = 0.5 * r
    s = np.sin(half)
    small = np.abs(s) < 1e-300
    ratio = np.where(small, float(n), np.sin(n * half) / np.where(small, 1.0, s))
    return np.exp(1j * half * (n - 1)) * ratio


def _gram_uniform(n: int, dt: float, omega: FloatArray, constant: bool) -> FloatArray:
    """M^T M for uniform samples tau_i = i dt in closed form, O(m^2) instead of O(n m^2)."""
    m = omega.size
    s_diff = _dirichlet_sum(np.subtract.outer(omega, omega) * dt, n)
    s_sum = _dirichlet_sum(np.add.outer(omega, omega) * dt, n)
    cc = 0.5 * (s_diff.real + s_sum.real)
    ss = 0.5 * (s_diff.real - s_sum.real)
    cs = 0.5 * (s_sum.imag - s_diff.imag)  # sum cos(w_i t) sin(w_j t)
    off = int(constant)
    p = 2 * m + off
    g = np.empty((p, p))
    g[off : off + m, off : off + m] = cc
    g[off + m :, off + m :] = ss
    g[off : off + m, off + m :] = cs
    g[off + m :, off : off + m] = cs.T
    if constant:
        s1 = _dirichlet_sum(omega * dt, n)
        g[0, 0] = n
        g[0, 1 : 1 + m] = g[1 : 1 + m, 0] = s1.real
        g[0, 1 + m :] = g[1 + m :, 0] = s1.imag
    return g
