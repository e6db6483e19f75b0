"""Compiled ``"%.12g"`` formatting of float columns into CSV text, byte for byte Python's.

History files hold millions of values; Python formats ~5 million a second. The kernels here
produce the same bytes as ``"%.12g" % v`` for every value they can prove they round the same
way, and hand the rest (a few in ten thousand, plus non-finite and extreme values) back to
Python:

* 12 significant digits: with ``e = floor(log10 |v|)`` and the exact power ``10**(11 - e)``
  (``|11 - e| <= 22``, so the power is a double), ``s = |v| 10**(11 - e)`` is computed with a
  single rounding, i.e. within ``2**-53 s < 1.2e-4`` of the exact value. Rounded to the
  nearest integer, it gives Python's (correctly rounded) digits unless its fraction lies within
  that error of one half: such values (and ``|11 - e| > 22``, NaN, inf) are formatted by Python.
* the layout of ``%g``: fixed notation when ``-4 <= exponent < 12``, else ``d.ddde±XX``;
  trailing zeros and a bare decimal point removed.

:func:`runout.io.result_files.write_columns` uses it; the tests compare it with Python's formatting.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from runout.base._kernel import kernel

__all__ = ["format_rows"]

_POW10 = np.array([10.0**k for k in range(23)])
#: Half-width of the band around a rounding tie left to Python (> the 1.2e-4 error bound).
_TIE_BAND = 2.5e-4


@kernel()
def _digits(v: float) -> tuple[int, int, bool]:
    """12 correctly rounded significant digits of |v| as an integer, its exponent, proven."""
    a = abs(v)
    if not (a > 0.0 and a < math.inf):
        return 0, 0, False
    e = int(math.floor(math.log10(a)))  # noqa: RUF046  (an int for numba's typing)
    s = 0.0
    found = False
    for _ in range(3):  # log10 may be one off near a power of ten
        k = 11 - e
        if k > 22 or k < -22:
            return 0, 0, False
        s = a * _POW10[k] if k >= 0 else a / _POW10[-k]
        if s >= 1e12:
            e += 1
        elif s < 1e11:
            e -= 1
        else:
            found = True
            break
    if not found:
        return 0, 0, False
    n = math.floor(s)
    f = s - n
    if abs(f - 0.5) <= _TIE_BAND:
        return 0, 0, False
    d = int(n) + (1 if f > 0.5 else 0)
    if d == 1_000_000_000_000:
        d = 100_000_000_000
        e += 1
    return d, e, True


@kernel()
def _significant(d: int) -> int:
    """Digits of the 12-digit ``d`` left once its trailing zeros are dropped (1..12)."""
    nd = 12
    while nd > 1 and d % 10 == 0:
        d //= 10
        nd -= 1
    return nd


@kernel()
def _length(v: float, d: int, e: int) -> int:
    """Length of the ``%.12g`` text of ``v`` (digits ``d``, exponent ``e``) [bytes]."""
    nd = _significant(d)
    n = 1 if v < 0.0 else 0
    if 0 <= e < 12:
        return n + e + 1 + (nd - e if nd > e + 1 else 0)
    if -4 <= e < 0:
        return n + 2 + (-e - 1) + nd
    return n + (nd + 1 if nd > 1 else 1) + 2 + (3 if abs(e) >= 100 else 2)


@kernel()
def _render(
    v: float, d: int, e: int, out: npt.NDArray[np.uint8], pos: int, digits: npt.NDArray[np.uint8]
) -> int:
    """Write ``%.12g`` of ``v`` (digits ``d``, exponent ``e``) at ``out[pos:]``; new end.

    ``digits`` is scratch space of 12 bytes.
    """
    x = d
    for i in range(11, -1, -1):
        digits[i] = 48 + x % 10
        x //= 10
    nd = _significant(d)
    if v < 0.0:
        out[pos] = 45  # '-'
        pos += 1
    if -4 <= e < 12:
        if e >= 0:
            for i in range(e + 1):
                out[pos] = digits[i]
                pos += 1
            if nd > e + 1:
                out[pos] = 46  # '.'
                pos += 1
                for i in range(e + 1, nd):
                    out[pos] = digits[i]
                    pos += 1
        else:
            out[pos] = 48
            out[pos + 1] = 46
            pos += 2
            for _ in range(-e - 1):
                out[pos] = 48
                pos += 1
            for i in range(nd):
                out[pos] = digits[i]
                pos += 1
        return pos
    out[pos] = digits[0]
    pos += 1
    if nd > 1:
        out[pos] = 46
        pos += 1
        for i in range(1, nd):
            out[pos] = digits[i]
            pos += 1
    out[pos] = 101  # 'e'
    out[pos + 1] = 45 if e < 0 else 43
    pos += 2
    ae = abs(e)
    if ae >= 100:
        out[pos] = 48 + ae // 100
        pos += 1
    out[pos] = 48 + (ae // 10) % 10
    out[pos + 1] = 48 + ae % 10
    return pos + 2


@kernel(nogil=True)  # a run writes it while plotting
def _plan(
    block: npt.NDArray[np.float64],
) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.int64], npt.NDArray[np.int64]]:
    """Digits, exponent and text length of each value; length -1 where Python must format."""
    rows, cols = block.shape
    digits = np.empty((rows, cols), np.int64)
    exps = np.empty((rows, cols), np.int64)
    length = np.empty((rows, cols), np.int64)
    for r in range(rows):
        for c in range(cols):
            v = block[r, c]
            if v == 0.0:  # "0" or "-0"
                digits[r, c] = 0
                exps[r, c] = 0
                length[r, c] = 2 if math.copysign(1.0, v) < 0.0 else 1
                continue
            d, e, ok = _digits(v)
            digits[r, c] = d
            exps[r, c] = e
            length[r, c] = _length(v, d, e) if ok else -1
    return digits, exps, length


@kernel(nogil=True)  # a run writes it while plotting
def _write(
    block: npt.NDArray[np.float64],
    digits: npt.NDArray[np.int64],
    exps: npt.NDArray[np.int64],
    length: npt.NDArray[np.int64],
    fallback: npt.NDArray[np.uint8],
    fallback_at: npt.NDArray[np.int64],
    size: int,
) -> npt.NDArray[np.uint8]:
    """The CSV text of ``block``: values joined by ',' and rows ended by '\\r\\n'.

    The values with ``length == -1`` take their text, in row-major order, from
    ``fallback[fallback_at[j]:fallback_at[j + 1]]``.
    """
    rows, cols = block.shape
    out = np.empty(size, np.uint8)
    scratch = np.empty(12, np.uint8)
    pos = 0
    j = 0
    for r in range(rows):
        for c in range(cols):
            if c:
                out[pos] = 44  # ','
                pos += 1
            v = block[r, c]
            if length[r, c] < 0:
                for i in range(fallback_at[j], fallback_at[j + 1]):
                    out[pos] = fallback[i]
                    pos += 1
                j += 1
            elif v == 0.0:
                if math.copysign(1.0, v) < 0.0:
                    out[pos] = 45
                    pos += 1
                out[pos] = 48
                pos += 1
            else:
                pos = _render(v, digits[r, c], exps[r, c], out, pos, scratch)
        out[pos] = 13
        out[pos + 1] = 10
        pos += 2
    return out[:pos]


def format_rows(block: npt.NDArray[np.float64]) -> bytes:
    """CSV text (ASCII) of a 2-D float block, every value as ``"%.12g" % v``, CRLF rows.

    Parameters
    ----------
    block : ndarray, shape (rows, columns)
        The values.

    Returns
    -------
    bytes
        Exactly ``"".join(",".join("%.12g" % v for v in row) + "\\r\\n" for row in block)``
        encoded as ASCII.
    """
    data = np.ascontiguousarray(block, dtype=np.float64)
    if data.ndim != 2:
        raise ValueError(f"block must be 2-D, got shape {data.shape}")
    digits, exps, length = _plan(data)
    slow = length < 0
    texts = [f"{v:.12g}".encode("ascii") for v in data[slow].tolist()]
    fallback = np.frombuffer(b"".join(texts), dtype=np.uint8)
    fallback_at = np.zeros(len(texts) + 1, dtype=np.int64)
    np.cumsum([len(t) for t in texts], out=fallback_at[1:])
    rows, cols = data.shape
    size = int(length[~slow].sum()) + fallback.size + rows * (cols - 1) + 2 * rows
    out = _write(data, digits, exps, length, fallback, fallback_at, size)
    if out.size != size:  # the lengths planned and written disagree: a bug, never seen
        raise RuntimeError(f"CSV formatting wrote {out.size} bytes, planned {size}")
    return out.tobytes()
