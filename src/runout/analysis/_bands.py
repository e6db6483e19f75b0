"""Band values of :mod:`runout.analysis.spectrum`: Anderon bands (seed 002 eq. 1 and eq. 42) and the
rms velocity in the three ISO 15242-1 bands.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Literal

import numpy as np
import numpy.typing as npt
from numpy.typing import ArrayLike

from runout.analysis._signal import (
    _EDGE_RTOL,
    MICROINCH,
    _as_signal,
    _check_positive,
    _check_samples_per_rev,
    _window,
)

FloatArray = npt.NDArray[np.float64]

# --------------------------------------------------------------------------------------------
# Band values
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Band:
    """A pass band ``[low, high)`` in orders or in hertz (see :attr:`BandSet.basis`)."""

    name: str
    low: float
    high: float

    def __post_init__(self) -> None:
        if not (math.isfinite(self.low) and math.isfinite(self.high) and 0 < self.low < self.high):
            raise ValueError(
                f"band {self.name!r}: need 0 < low < high, got {self.low!r}, {self.high!r}"
            )

    @property
    def octaves(self) -> float:
        """Width in octaves, log2(high / low) [-] (seed 002 eq. 1 denominator squared)."""
        return math.log2(self.high / self.low)

    def contains(self, value: ArrayLike) -> npt.NDArray[np.bool_]:
        """True where ``low <= |value| < high``; a value on a shared edge goes to the upper band."""
        v = np.abs(np.asarray(value, dtype=float))
        return (v >= self.low * (1 - _EDGE_RTOL)) & (v < self.high * (1 - _EDGE_RTOL))


@dataclass(frozen=True)
class BandSet:
    """A named set of bands.

    Attributes
    ----------
    name : str
        Label of the set.
    bands : tuple of Band
        The bands; they may overlap (e.g. Anderon E and A).
    basis : {"order", "hz"}
        Whether band edges are orders [-] or frequencies [Hz].
    """

    name: str
    bands: tuple[Band, ...]
    basis: Literal["order", "hz"] = "order"

    def __post_init__(self) -> None:
        if not self.bands:
            raise ValueError("a band set needs at least one band")
        names = [b.name for b in self.bands]
        if len(set(names)) != len(names):
            raise ValueError(f"band names must be unique, got {names}")
        if self.basis not in ("order", "hz"):
            raise ValueError(f"basis must be 'order' or 'hz', got {self.basis!r}")

    @property
    def names(self) -> tuple[str, ...]:
        """Band names, in order."""
        return tuple(b.name for b in self.bands)

    @classmethod
    def from_edges(
        cls,
        name: str,
        edges: dict[str, tuple[float, float]] | Sequence[tuple[str, float, float]],
        basis: Literal["order", "hz"] = "order",
    ) -> BandSet:
        """Build from ``{"L": (low, high), ...}`` or ``[("L", low, high), ...]``."""
        items = [(k, lo, hi) for k, (lo, hi) in edges.items()] if isinstance(edges, dict) else edges
        return cls(name, tuple(Band(k, float(lo), float(hi)) for k, lo, hi in items), basis)

    def scaled(self, factor: float, name: str | None = None) -> BandSet:
        """The same set with every edge multiplied by ``factor``."""
        _check_positive("factor", factor)
        bands = tuple(Band(b.name, b.low * factor, b.high * factor) for b in self.bands)
        return BandSet(name or self.name, bands, self.basis)


#: Anderon meter bands of seed 002 Fig. 12, in orders (waves per revolution of the inner ring).
#: The header prints 0.17, 0.67, 1.67, 10, 60, 360, 500; we take the rounded values as the
#: exact fractions 1/6, 2/3, 5/3 -- multiples of the 1/6-order bin of the six-revolution DFT
#: seed 002 uses, and the 50/300/1800 Hz edges of the meter at 1800 rpm (L = 50-300 Hz,
#: M = 300-1800 Hz). :data:`ANDERON_BANDS_PRINTED` keeps the printed values.
ANDERON_BANDS = BandSet.from_edges(
    "anderon",
    [
        ("U", 1 / 6, 2 / 3),
        ("R", 2 / 3, 5 / 3),
        ("L", 5 / 3, 10.0),
        ("M", 10.0, 60.0),
        ("H", 60.0, 360.0),
        ("E", 5 / 3, 360.0),
        ("A", 1 / 6, 500.0),
    ],
)

#: The Anderon bands with the edges as printed in seed 002 Fig. 12 (two decimals).
ANDERON_BANDS_PRINTED = BandSet.from_edges(
    "anderon (printed edges)",
    [
        ("U", 0.17, 0.67),
        ("R", 0.67, 1.67),
        ("L", 1.67, 10.0),
        ("M", 10.0, 60.0),
        ("H", 60.0, 360.0),
        ("E", 1.67, 360.0),
        ("A", 0.17, 500.0),
    ],
)


def iso15242_band_set(rotation_hz: float = 30.0) -> BandSet:
    """ISO 15242-1 velocity bands [Hz] for a test speed of ``rotation_hz``.

    The standard's bands are Low 50-300 Hz, Medium 300-1800 Hz, High 1800-10000 Hz at
    1800 rpm (30 Hz). For another speed the edges are scaled in proportion to the speed
    (same orders); pass the default for the nominal bands.
    """
    _check_positive("rotation_hz", rotation_hz)
    nominal = BandSet.from_edges(
        "ISO 15242-1",
        [("Low", 50.0, 300.0), ("Medium", 300.0, 1800.0), ("High", 1800.0, 10000.0)],
        basis="hz",
    )
    if rotation_hz == 30.0:
        return nominal
    return nominal.scaled(rotation_hz / 30.0, name=f"ISO 15242-1 at {rotation_hz * 60:.6g} rpm")


#: ISO 15242-1 bands at the standard 1800 rpm [Hz].
ISO15242_BANDS = iso15242_band_set()


@dataclass(frozen=True, eq=False)
class BandValues:
    """Band values of one or several channels.

    Attributes
    ----------
    bands : BandSet
        The bands evaluated.
    values : ndarray, shape (..., n_bands)
        Band values in :attr:`unit` (Anderon, or rms velocity in um/s).
    rms : ndarray, shape (..., n_bands)
        Band rms of the differentiated quantity: (dx/dθ)_rms [µin/rad] for Anderon bands,
        velocity rms [µm/s] for ISO bands.
    unit : str
        Unit of :attr:`values`.
    """

    bands: BandSet
    values: FloatArray
    rms: FloatArray
    unit: str
    _index: dict[str, int] = field(init=False, repr=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "_index", {n: i for i, n in enumerate(self.bands.names)})

    def __getitem__(self, name: str) -> FloatArray:
        """Value(s) of band ``name``."""
        try:
            return self.values[..., self._index[name]]
        except KeyError:
            raise KeyError(f"no band {name!r}; bands are {list(self.bands.names)}") from None

    def as_dict(self) -> dict[str, float]:
        """``{band name: value}`` for a single channel."""
        if self.values.ndim != 1:
            raise ValueError(
                f"as_dict needs a single channel, values have shape {self.values.shape}"
            )
        return {n: float(v) for n, v in zip(self.bands.names, self.values, strict=True)}


def _band_ms(axis_values: FloatArray, ms: FloatArray, bands: BandSet) -> FloatArray:
    """Sum of the mean squares ``ms[..., k]`` whose ``axis_values[k]`` lies in each band."""
    masks = np.stack([b.contains(axis_values) for b in bands.bands], axis=-1).astype(float)
    return np.asarray(ms @ masks)


def _lines_in(values: ArrayLike, amplitudes: ArrayLike, what: str) -> tuple[FloatArray, ...]:
    v = np.asarray(values, dtype=float)
    amp = np.asarray(amplitudes, dtype=float)
    if v.ndim == 0:
        v = v[None]
    if amp.ndim == 0:
        amp = amp[None]
    if v.ndim != 1 or amp.shape[-1:] != v.shape:
        raise ValueError(
            f"amplitudes (shape {amp.shape}) must end with the {what}' length {v.size}"
        )
    if not (np.all(np.isfinite(v)) and np.all(np.isfinite(amp))):
        raise ValueError(f"{what} and amplitudes must be finite")
    return v, amp


def _check_basis(bands: BandSet, basis: str, func: str) -> None:
    if bands.basis != basis:
        raise ValueError(f"{func} needs bands with basis {basis!r}, got {bands.basis!r}")


def _anderon(ms: FloatArray, bands: BandSet) -> BandValues:
    rms = np.sqrt(ms) / MICROINCH
    octaves = np.array([b.octaves for b in bands.bands])
    return BandValues(bands, rms / np.sqrt(octaves), rms, "anderon")


def anderon_bands_from_lines(
    orders: ArrayLike, amplitudes: ArrayLike, bands: BandSet = ANDERON_BANDS
) -> BandValues:
    r"""Anderon band values of a set of exact displacement lines (no leakage).

    A line :math:`W\cos(n\theta + \varphi)` of the outer-ring displacement (seed 002 eq. 41)
    has displacement density :math:`dx/d\theta = -nW\sin(n\theta + \varphi)` (eq. 42), of rms
    :math:`|n|W/\sqrt2`. The band rms is the root sum of squares of the lines in the band and
    the Anderon value is (eq. 1)

    .. math:: V = \frac{(dx/d\theta)_{rms}}{\sqrt{\log_2(n_H/n_L)}}

    with :math:`x` in microinches (25.4 nm) and :math:`\theta` in radians. Lines at the same
    order are treated as incoherent (add them vectorially first if they are not).

    Parameters
    ----------
    orders : array_like, shape (m,)
        Line orders n (waves per revolution of the rotating inner ring) [-]; sign ignored.
    amplitudes : array_like, shape (..., m)
        Zero-to-peak radial displacement amplitudes W [m], the cos α of eq. 41 included.
    bands : BandSet
        Bands in orders; default :data:`ANDERON_BANDS`.

    Returns
    -------
    BandValues
        ``values`` in Anderon, ``rms`` in µin/rad.
    """
    _check_basis(bands, "order", "anderon_bands_from_lines")
    n, w = _lines_in(orders, amplitudes, "orders")
    ms = 0.5 * (n * w) ** 2
    return _anderon(_band_ms(n, ms, bands), bands)


def _bin_mean_square(
    x: FloatArray, window: str | tuple[object, ...] | ArrayLike | None
) -> FloatArray:
    """Mean square per one-sided DFT bin, power-corrected for the window.

    ``P_k = 2 |X_k|^2 / (n sum w^2)`` (no factor 2 at DC and Nyquist); without a window the
    sum over bins equals the mean square of the record (Parseval).
    """
    n = x.shape[-1]
    w = _window(window, n)
    spec = np.fft.rfft(x * w, axis=-1)
    p = np.abs(spec) ** 2 * (2.0 / (n * np.sum(w**2)))
    p[..., 0] *= 0.5
    if n % 2 == 0:
        p[..., -1] *= 0.5
    return p


def anderon_bands_from_waveform(
    x: ArrayLike,
    samples_per_rev: int,
    bands: BandSet = ANDERON_BANDS,
    *,
    window: str | tuple[object, ...] | ArrayLike | None = None,
    density: bool = False,
    axis: int = -1,
) -> BandValues:
    r"""Anderon band values of a waveform sampled against the inner-ring angle.

    The DFT of the whole record (seed 002 used six revolutions) gives a mean square per bin
    :math:`P_k`; bin :math:`k` sits at order :math:`n_k = k\,s/N` (``s`` samples per
    revolution, ``N`` samples). For a displacement record, differentiating in angle
    multiplies each bin's mean square by :math:`n_k^2` (eq. 42); a record of the displacement
    density :math:`dx/d\theta` itself (``density=True``, what seed 002 transformed for its
    Fig. 12) is used as it is. Band rms and the Anderon value then follow eq. 1 as in
    :func:`anderon_bands_from_lines`.

    Lines at orders that are not multiples of the bin spacing :math:`1/\text{revolutions}`
    leak into neighbouring bins and, near a band edge, into the neighbouring band. For a
    displacement record without window the leakage tail, weighted by :math:`n_k^2`, can swamp
    the high bands; a Hann window (power-corrected, so the band rms of a line well inside a
    band is kept) or a density record avoids that.

    Parameters
    ----------
    x : array_like
        Radial displacement [m] (or its density [m/rad], see ``density``), uniformly sampled
        in inner-ring angle.
    samples_per_rev : int
        Samples per revolution (>= 2).
    bands : BandSet
        Bands in orders; default :data:`ANDERON_BANDS`.
    window : str, array_like or None
        ``None`` (rectangular, as seed 002) or a window name such as ``"hann"``.
    density : bool
        ``x`` is the displacement density dx/dθ [m/rad] rather than the displacement [m].
    axis : int
        Sample axis.

    Returns
    -------
    BandValues
    """
    _check_basis(bands, "order", "anderon_bands_from_waveform")
    spr = _check_samples_per_rev(samples_per_rev)
    xs = _as_signal(x, axis, "x")
    n = xs.shape[-1]
    if n < 2 * spr:
        raise ValueError(f"need at least two revolutions ({2 * spr} samples), got {n}")
    p = _bin_mean_square(xs - xs.mean(axis=-1, keepdims=True), window)
    order_k = np.arange(p.shape[-1]) * (spr / n)
    ms = p if density else p * order_k**2
    return _anderon(_band_ms(order_k, ms, bands), bands)


def _iso(ms: FloatArray, bands: BandSet) -> BandValues:
    rms = np.sqrt(ms) * 1e6
    return BandValues(bands, rms, rms, "um/s")


def iso15242_bands_from_lines(
    frequencies: ArrayLike, amplitudes: ArrayLike, bands: BandSet = ISO15242_BANDS
) -> BandValues:
    r"""Rms radial velocity in ISO 15242-1 style bands from exact displacement lines.

    A displacement line :math:`W\cos(2\pi f t + \varphi)` has velocity amplitude
    :math:`2\pi f W` and rms :math:`2\pi f W/\sqrt2`; a band's rms is the root sum of squares
    of its lines.

    Parameters
    ----------
    frequencies : array_like, shape (m,)
        Line frequencies [Hz].
    amplitudes : array_like, shape (..., m)
        Zero-to-peak displacement amplitudes [m].
    bands : BandSet
        Bands in Hz; default :data:`ISO15242_BANDS` (1800 rpm), see :func:`iso15242_band_set`.

    Returns
    -------
    BandValues
        Rms velocity [µm/s] per band.
    """
    _check_basis(bands, "hz", "iso15242_bands_from_lines")
    f, w = _lines_in(frequencies, amplitudes, "frequencies")
    ms = 0.5 * (2.0 * np.pi * f * w) ** 2
    return _iso(_band_ms(f, ms, bands), bands)


def iso15242_bands_from_waveform(
    x: ArrayLike,
    sample_rate: float,
    bands: BandSet = ISO15242_BANDS,
    *,
    window: str | tuple[object, ...] | ArrayLike | None = None,
    axis: int = -1,
) -> BandValues:
    r"""Rms radial velocity in ISO 15242-1 style bands from a displacement time record.

    Mean square per DFT bin (window power-corrected) times :math:`(2\pi f_k)^2`, summed over
    each band; see :func:`anderon_bands_from_waveform` for the leakage remarks.

    Parameters
    ----------
    x : array_like
        Radial displacement [m], uniformly sampled in time.
    sample_rate : float
        Sampling frequency [Hz].
    bands : BandSet
        Bands in Hz.
    window : str, array_like or None
        ``None`` (rectangular) or a window name.
    axis : int
        Sample axis.

    Returns
    -------
    BandValues
        Rms velocity [µm/s] per band.
    """
    _check_basis(bands, "hz", "iso15242_bands_from_waveform")
    _check_positive("sample_rate", sample_rate)
    xs = _as_signal(x, axis, "x")
    n = xs.shape[-1]
    if n < 4:
        raise ValueError(f"need at least 4 samples, got {n}")
    p = _bin_mean_square(xs - xs.mean(axis=-1, keepdims=True), window)
    f = np.fft.rfftfreq(n, 1.0 / float(sample_rate)).astype(np.float64)
    return _iso(_band_ms(f, p * (2.0 * np.pi * f) ** 2, bands), bands)
