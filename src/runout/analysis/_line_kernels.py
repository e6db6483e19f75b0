"""Kernels of the known-line fit of :func:`runout.analysis.spectrum.extract_lines`: projection and
synthesis on a uniform grid (Numba, rotating phasors re-anchored every :data:`_ANCHOR` samples)
with their NumPy references, and the Gram matrices.
"""

from __future__ import annotations

import numba
import numpy as np
import numpy.typing as npt

from runout.base._threads import halves, in_spans

FloatArray = npt.NDArray[np.float64]


#: Samples between exact re-evaluations of the rotating phasor in the kernels.
_ANCHOR = 256


#: Records of at least this many samples are projected and synthesised on two threads.
_PARALLEL_MIN = 1 << 16


@numba.njit(cache=True, nogil=True)
def _project_blocks(x, dt, omega, first, last, part_c, part_s):
    """Blocks ``first <= blk < last`` of :func:`_project_uniform_kernel`: each block's own
    sums into ``part_c[blk]``, ``part_s[blk]`` (compiled; releases the GIL)."""
    nc, n = x.shape
    m = omega.shape[0]
    rc = np.cos(omega * dt)
    rs = np.sin(omega * dt)
    for blk in range(first, last):
        i0 = blk * _ANCHOR
        i1 = min(i0 + _ANCHOR, n)
        zc = np.cos(omega * (dt * i0))
        zs = np.sin(omega * (dt * i0))
        acc_c = part_c[blk]
        acc_s = part_s[blk]
        for i in range(i0, i1):
            for k in range(nc):
                xi = x[k, i]
                ac = acc_c[k]
                as_ = acc_s[k]
                for j in range(m):
                    ac[j] += xi * zc[j]
                    as_[j] += xi * zs[j]
            for j in range(m):
                tc = zc[j] * rc[j] - zs[j] * rs[j]
                zs[j] = zc[j] * rs[j] + zs[j] * rc[j]
                zc[j] = tc


@numba.njit(cache=True)
def _sum_blocks(part_c, part_s):
    """The blocks' sums added in block order (compiled)."""
    out_c = np.zeros(part_c.shape[1:])
    out_s = np.zeros(part_s.shape[1:])
    for blk in range(part_c.shape[0]):
        out_c += part_c[blk]
        out_s += part_s[blk]
    return out_c, out_s


def _project_uniform_kernel(
    x: FloatArray, dt: float, omega: FloatArray
) -> tuple[FloatArray, FloatArray]:
    """C[k, j] = sum_i x[k, i] cos(omega_j i dt), S[k, j] = sum_i x[k, i] sin(omega_j i dt).

    Goertzel-like: one rotating phasor per line, advanced sample by sample (the inner loop
    over lines vectorises). Each block of ``_ANCHOR`` samples restarts the phasors from an
    exact cos/sin so that rounding drift stays at the 1e-14 level, and keeps its own partial
    sums (pairwise-like summation), added in block order at the end. The blocks are
    independent: a long record's halves run on two threads (:mod:`runout.base._threads`) with the
    same result to the bit. :func:`_project_numpy` is the reference it is tested against.
    """
    nc, n = x.shape
    nb = (n + _ANCHOR - 1) // _ANCHOR
    part_c = np.zeros((nb, nc, omega.shape[0]))
    part_s = np.zeros((nb, nc, omega.shape[0]))
    in_spans(
        lambda first, last: _project_blocks(x, dt, omega, first, last, part_c, part_s),
        halves(nb, _PARALLEL_MIN // _ANCHOR),
    )
    out_c, out_s = _sum_blocks(part_c, part_s)
    return out_c, out_s


@numba.njit(cache=True, nogil=True, fastmath={"reassoc"})
def _synthesize_blocks(const, a, b, dt, omega, first, last, y):
    """Blocks ``first <= blk < last`` of :func:`_synthesize_uniform_kernel` into ``y``
    (compiled; releases the GIL)."""
    nc, m = a.shape
    n = y.shape[1]
    rc = np.cos(omega * dt)
    rs = np.sin(omega * dt)
    for blk in range(first, last):
        i0 = blk * _ANCHOR
        i1 = min(i0 + _ANCHOR, n)
        zc = np.cos(omega * (dt * i0))
        zs = np.sin(omega * (dt * i0))
        for i in range(i0, i1):
            for k in range(nc):
                ak = a[k]
                bk = b[k]
                acc = 0.0
                for j in range(m):
                    acc += ak[j] * zc[j] + bk[j] * zs[j]
                y[k, i] = const[k] + acc
            for j in range(m):
                tc = zc[j] * rc[j] - zs[j] * rs[j]
                zs[j] = zc[j] * rs[j] + zs[j] * rc[j]
                zc[j] = tc


def _synthesize_uniform_kernel(
    const: FloatArray, a: FloatArray, b: FloatArray, dt: float, omega: FloatArray, n: int
) -> FloatArray:
    """y[k, i] = const[k] + sum_j a[k, j] cos(omega_j i dt) + b[k, j] sin(omega_j i dt).

    Same rotating phasors as :func:`_project_uniform_kernel`; the sum over lines may be
    reassociated (vectorised), which changes only the last bits. Blocks are independent: a
    long record's halves run on two threads with the same result to the bit.
    """
    y = np.empty((a.shape[0], n))
    nb = (n + _ANCHOR - 1) // _ANCHOR
    in_spans(
        lambda first, last: _synthesize_blocks(const, a, b, dt, omega, first, last, y),
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
