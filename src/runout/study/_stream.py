"""Streaming statistics of a study: exact moments and a mergeable quantile sketch.

Part of :mod:`runout.study.run` (its module docstring describes studies). A streaming study
keeps, per runout figure and per line, a :class:`StreamStatistics`: its memory does not grow
with the number of samples, and chunks are added in any order and any split with the same
result, bit for bit:

* count, min and max are exact;
* the sum and the sum of squares are exact (:class:`ExactSum`: integer mantissa pieces summed
  by exponent, combined as Python integers), so the mean and the variance are the exact
  rationals, each rounded once;
* the percentiles and the histogram come from a DDSketch-style sketch (:class:`QuantileSketch`:
  log-spaced buckets of relative accuracy :data:`QUANTILE_RELATIVE_ERROR`, integer counts
  merged by addition).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import numpy as np
from numpy.typing import NDArray

#: Relative accuracy of the sketch's percentiles [-]: every percentile is within this fraction
#: of the exact one (linear interpolation between order statistics, as numpy's default).
QUANTILE_RELATIVE_ERROR = 1e-4
#: Bits of a float64 mantissa per piece: n pieces below 2^18 sum exactly in float64 while
#: n < 2^35, far above any chunk.
_PIECE_BITS = 18
#: Offset of the binary exponents of the pieces (the smallest, a squared subnormal's low
#: part, is above -2400).
_EXPONENT_OFFSET = 2400
_EXPONENTS = 4600


class ExactSum:
    """The exact sum of float64 values, the same for any order and split of the values.

    Every finite value is ``m 2^E`` with an integer mantissa ``|m| < 2^53`` (``np.frexp``);
    ``m`` is cut into three pieces of at most 18 bits, and the pieces of one exponent are summed
    by ``np.bincount`` (exact: below 2^53 for fewer than 2^35 values). The per-exponent sums are
    combined as Python integers, so the total is exact and does not depend on the order or
    chunking of the values. Memory: one Python integer.

    Notes
    -----
    Exact summation by exponent bins follows the idea of the accumulators of
    Demmel and Hida, "Accurate and efficient floating point summation", 2003 (SIAM J. Sci.
    Comput. 25(4)), here with integer bins so that no rounding ever happens.
    """

    __slots__ = ("_total",)

    def __init__(self) -> None:
        # the sum is _total * 2^-(_EXPONENT_OFFSET)
        self._total = 0

    def add(self, values: NDArray[np.float64], shift: NDArray[np.int64] | None = None) -> None:
        """Add ``values * 2**shift`` (finite values; ``shift`` an exact power-of-two scale)."""
        v = np.asarray(values, dtype=np.float64).ravel()
        if v.size == 0:
            return
        fraction, exponent = np.frexp(v)
        mantissa = np.ldexp(fraction, 53).astype(np.int64)  # exact: |m| < 2^53
        base = exponent.astype(np.int64) - 53 + _EXPONENT_OFFSET
        if shift is not None:
            base = base + np.asarray(shift, dtype=np.int64).ravel()
        sign = np.where(mantissa < 0, -1, 1)
        magnitude = np.abs(mantissa)
        mask = (1 << _PIECE_BITS) - 1
        total = 0
        for piece in range(3):
            bits = piece * _PIECE_BITS
            part = ((magnitude >> bits) & mask) * sign
            sums = np.bincount(base, weights=part.astype(np.float64), minlength=_EXPONENTS)
            for e in np.flatnonzero(sums):
                total += int(sums[e]) << int(e + bits)
        self._total += total

    def merge(self, other: ExactSum) -> None:
        """Add the values summed by ``other``."""
        self._total += other._total

    @property
    def value(self) -> Fraction:
        """The exact sum."""
        return Fraction(self._total, 1 << _EXPONENT_OFFSET)


def exact_squares(values: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """``x^2`` of every value as ``(hi + lo) 2^(2e)``, exact: the parts and the power.

    ``x = f 2^e`` with ``0.5 <= |f| < 1`` (``np.frexp``); ``f^2 = hi + lo`` exactly by Dekker's
    two-product with Veltkamp's split (no overflow or underflow at this scale), and the scale
    ``2^(2e)`` is applied in the exponents of :class:`ExactSum`.

    Returns
    -------
    parts : ndarray, shape (2 N,)
        ``hi`` then ``lo`` of every value.
    shift : ndarray of int64, shape (2 N,)
        ``2 e`` of every part.

    Notes
    -----
    T. J. Dekker, "A floating-point technique for extending the available precision", 1971
    (Numer. Math. 18), the algorithms mul12 and split (Veltkamp's splitting constant 2^27 + 1).
    """
    f, e = np.frexp(np.asarray(values, dtype=np.float64).ravel())
    hi = f * f
    c = 134217729.0 * f  # 2^27 + 1
    fh = c - (c - f)
    fl = f - fh
    lo = ((fh * fh - hi) + 2.0 * fh * fl) + fl * fl
    shift = 2 * e.astype(np.int64)
    return np.concatenate([hi, lo]), np.concatenate([shift, shift])


class QuantileSketch:
    """A DDSketch of float64 values: log-spaced buckets with relative accuracy ``alpha``.

    A value ``x > 0`` falls in the bucket ``i = ceil(log_gamma x)`` with ``gamma = (1 + alpha)
    / (1 - alpha)``, i.e. ``gamma^(i-1) < x <= gamma^i``, whose representative ``2 gamma^i /
    (gamma + 1)`` is within ``alpha`` of every value of the bucket; negative values have their
    own buckets (of ``|x|``), zeros a count. Counts are integers merged by addition: the sketch
    is the same for any order and split of the values. Memory: 8 bytes per bucket,
    ``ln(max/min) / ln(gamma)`` buckets per sign (dense between the extremes): ~69,000
    for values over six decades, whatever the number of samples.

    Notes
    -----
    C. Masson, J. E. Rim and H. K. Lee, "DDSketch: a fast and fully-mergeable quantile sketch
    with relative-error guarantees", 2019 (Proc. VLDB Endow. 12(12)), the logarithmic mapping
    of section 2 (without collapsing, which would depend on the order of the values).
    """

    __slots__ = ("_log_gamma", "alpha", "gamma", "negative", "positive", "zeros")

    def __init__(self, alpha: float = QUANTILE_RELATIVE_ERROR) -> None:
        self.alpha = alpha
        self.gamma = (1.0 + alpha) / (1.0 - alpha)
        self._log_gamma = math.log(self.gamma)
        self.positive = _Store()
        self.negative = _Store()
        self.zeros = 0

    def _index(self, magnitude: NDArray[np.float64]) -> NDArray[np.int64]:
        return np.ceil(np.log(magnitude) / self._log_gamma).astype(np.int64)

    def add(self, values: NDArray[np.float64]) -> None:
        """Count the (finite) ``values``."""
        v = np.asarray(values, dtype=np.float64).ravel()
        self.zeros += int(np.count_nonzero(v == 0.0))
        self.positive.add(*np.unique(self._index(v[v > 0.0]), return_counts=True))
        self.negative.add(*np.unique(self._index(-v[v < 0.0]), return_counts=True))

    def merge(self, other: QuantileSketch) -> None:
        """Add the counts of ``other`` (of the same ``alpha``)."""
        self.positive.add(*other.positive.items())
        self.negative.add(*other.negative.items())
        self.zeros += other.zeros

    @property
    def count(self) -> int:
        """Number of values counted."""
        return int(self.positive.counts.sum() + self.negative.counts.sum()) + self.zeros

    def buckets(self) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
        """Representative values (ascending) and counts of every occupied bucket."""
        rep = 2.0 / (self.gamma + 1.0)
        neg_keys, neg_counts = self.negative.items()
        pos_keys, pos_counts = self.positive.items()
        neg = -rep * np.exp(neg_keys[::-1] * self._log_gamma)
        pos = rep * np.exp(pos_keys * self._log_gamma)
        zero = np.zeros(1 if self.zeros else 0)
        values = np.concatenate([neg, zero, pos])
        counts = np.concatenate(
            [neg_counts[::-1], np.full(len(zero), self.zeros, np.int64), pos_counts]
        )
        return values, counts

    def order_statistics(self, ranks: NDArray[np.int64]) -> NDArray[np.float64]:
        """Estimates of the order statistics of 0-based ``ranks`` (each within ``alpha``)."""
        values, counts = self.buckets()
        ends = np.cumsum(counts)
        return values[np.searchsorted(ends, np.asarray(ranks), side="right")]


class _Store:
    """Integer counts of consecutive bucket indices (dense from the lowest to the highest seen).

    Adding a chunk costs its own size (the array grows, by half again, only when an index falls
    outside it); the counts, and so every result, do not depend on the order of the chunks.
    """

    __slots__ = ("counts", "offset")

    def __init__(self) -> None:
        self.offset = 0
        self.counts = np.zeros(0, np.int64)

    def add(self, keys: NDArray[np.int64], counts: NDArray[np.int64]) -> None:
        if keys.size == 0:
            return
        low, high = int(keys.min()), int(keys.max())
        if self.counts.size == 0:
            self.offset, self.counts = low, np.zeros(high - low + 1, np.int64)
        end = self.offset + self.counts.size - 1
        if low < self.offset or high > end:
            margin = self.counts.size // 2
            new_low = min(low, self.offset) - (margin if low < self.offset else 0)
            new_high = max(high, end) + (margin if high > end else 0)
            grown = np.zeros(new_high - new_low + 1, np.int64)
            grown[self.offset - new_low : self.offset - new_low + self.counts.size] = self.counts
            self.offset, self.counts = new_low, grown
        self.counts[keys - self.offset] += counts

    def items(self) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
        """Occupied bucket indices (ascending) and their counts."""
        where = np.flatnonzero(self.counts)
        return where.astype(np.int64) + self.offset, self.counts[where]


@dataclass
class StreamStatistics:
    """Count, exact min/max/sum/sum of squares and a quantile sketch of a column's values.

    Attributes
    ----------
    count : int
        Finite values added.
    minimum, maximum : float
        Exact extremes (inf / -inf with no value).
    total, squares : ExactSum
        Exact sum of the values and of their squares.
    sketch : QuantileSketch
        The percentiles and histogram.
    """

    count: int = 0
    minimum: float = math.inf
    maximum: float = -math.inf
    total: ExactSum = field(default_factory=ExactSum)
    squares: ExactSum = field(default_factory=ExactSum)
    sketch: QuantileSketch = field(default_factory=QuantileSketch)

    def add(self, values: Any) -> None:
        """Add the finite entries of ``values`` (non-finite ones, failed samples, are left out)."""
        v = np.asarray(values, dtype=np.float64).ravel()
        v = v[np.isfinite(v)]
        if v.size == 0:
            return
        self.count += int(v.size)
        self.minimum = min(self.minimum, float(v.min()))
        self.maximum = max(self.maximum, float(v.max()))
        self.total.add(v)
        self.squares.add(*exact_squares(v))
        self.sketch.add(v)

    def add_zeros(self, n: int) -> None:
        """Add ``n`` values of 0 (a line below the model's reporting floor in ``n`` samples)."""
        if n <= 0:
            return
        self.count += n
        self.minimum = min(self.minimum, 0.0)
        self.maximum = max(self.maximum, 0.0)
        self.sketch.zeros += n

    def merge(self, other: StreamStatistics) -> None:
        """Add the values of ``other``."""
        self.count += other.count
        self.minimum = min(self.minimum, other.minimum)
        self.maximum = max(self.maximum, other.maximum)
        self.total.merge(other.total)
        self.squares.merge(other.squares)
        self.sketch.merge(other.sketch)

    def mean(self) -> float:
        """The mean, the exact rational rounded once (NaN with no value)."""
        if self.count == 0:
            return math.nan
        return float(self.total.value / self.count)

    def std(self) -> float:
        """Sample standard deviation (ddof 1): the square root of the exact variance rounded
        once (0 for one value, NaN with none)."""
        if self.count == 0:
            return math.nan
        if self.count == 1:
            return 0.0
        n = self.count
        s1 = self.total.value
        variance = (self.squares.value - s1 * s1 / n) / (n - 1)
        # beyond float64 (values above ~1e154): the root of the variance scaled by 4^-k
        k = max(0, (variance.numerator.bit_length() - variance.denominator.bit_length()) // 2)
        return (
            math.ldexp(math.sqrt(float(variance / (1 << (2 * k)))), k)
            if k > 500
            else (math.sqrt(float(variance)))
        )

    def percentiles(self, qs: tuple[float, ...]) -> list[float]:
        """Percentiles ``qs`` [%]: numpy's linear interpolation between the order statistics,
        each order statistic from the sketch (within ``alpha``; the extreme ones exact)."""
        n = self.count
        positions = [(n - 1) * q / 100.0 for q in qs]
        below = np.array([math.floor(h) for h in positions], dtype=np.int64)
        above = np.minimum(below + 1, n - 1)
        low = self.sketch.order_statistics(below)
        high = self.sketch.order_statistics(above)
        out = []
        for h, k, lo_v, hi_v, k_hi in zip(positions, below, low, high, above, strict=True):
            lo_v = self._clamped(float(lo_v), int(k))
            hi_v = self._clamped(float(hi_v), int(k_hi))
            out.append(lo_v + (h - k) * (hi_v - lo_v))
        return out

    def _clamped(self, value: float, rank: int) -> float:
        if rank == 0:
            return self.minimum
        if rank == self.count - 1:
            return self.maximum
        return min(max(value, self.minimum), self.maximum)

    def histogram(self, bins: int) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
        """Edges from the exact min/max (as ``np.histogram``) and counts of the sketch's
        buckets, each bucket counted in the bin of its representative value (clamped to
        [min, max]): a value within ``alpha`` of an edge may be counted in the next bin."""
        lo, hi = self.minimum, self.maximum
        spread = hi - lo
        scale = max(abs(lo), abs(hi))
        if spread == 0.0:
            half = max(0.5, 1e-10 * scale)
            edges = np.linspace(lo - half, lo + half, bins + 1)
        else:
            equal = spread <= 1e-10 * scale
            edges = np.linspace(lo, hi, (1 if equal else bins) + 1)
        values, counts = self.sketch.buckets()
        values = np.clip(values, lo, hi)
        place = np.clip(np.searchsorted(edges, values, side="right") - 1, 0, len(edges) - 2)
        totals = np.bincount(place, weights=counts.astype(np.float64), minlength=len(edges) - 1)
        return edges, totals.astype(np.int64)

    def summary(self, bins: int) -> dict[str, Any]:
        """The statistics of :func:`runout.study._result.statistics`, from the stream."""
        if self.count == 0:
            nan = float("nan")
            return {
                **dict.fromkeys(
                    ("mean", "std", "two_sigma", "p5", "p50", "p95", "min", "max"), nan
                ),
                "histogram": {"edges": [], "counts": []},
            }
        std = self.std()
        p5, p50, p95 = self.percentiles((5.0, 50.0, 95.0))
        edges, counts = self.histogram(bins)
        return {
            "mean": self.mean(),
            "std": std,
            "two_sigma": 2.0 * std,
            "p5": p5,
            "p50": p50,
            "p95": p95,
            "min": self.minimum,
            "max": self.maximum,
            "histogram": {"edges": [float(e) for e in edges], "counts": [int(c) for c in counts]},
        }
