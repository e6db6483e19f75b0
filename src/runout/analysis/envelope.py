r"""Envelope analysis of an acceleration record: squared-envelope spectrum and fast kurtogram.

Plain vectorised NumPy/SciPy functions on SI arrays returning small frozen dataclasses; the
matching of the spectrum's peaks to a bearing's defect frequencies is
:mod:`runout.diagnose.envelope`.

A localized defect (a spall) makes a train of impacts, each ringing a resonance of the
structure at a few kHz; the impacts' rate (the defect frequency) is not a line of the
acceleration spectrum but of the *envelope* of the band around the resonance. The squared
envelope spectrum (SES) of the band-passed signal shows it, with its harmonics and the
sidebands of the modulation by the load zone (R. B. Randall and J. Antoni, "Rolling element
bearing diagnostics — A tutorial", Mechanical Systems and Signal Processing 25, 2011, sec. 3.2
and 5.1). The band is the one where the signal is most impulsive, measured by the spectral
kurtosis of its complex envelope and searched over the 1/3-binary tree of bands of the fast
kurtogram (J. Antoni, "Fast computation of the kurtogram for the detection of transient
faults", Mechanical Systems and Signal Processing 21, 2007, sec. 3).

Contents
--------
* :func:`complex_envelope` -- complex envelope of one band (ideal FFT band-pass, analytic).
* :func:`squared_envelope_spectrum` -- one-sided amplitude spectrum of the squared envelope.
* :func:`fast_kurtogram` -- spectral kurtosis over the 1/3-binary tree of bands, best band.
* :func:`spectral_kurtosis` -- kurtosis of a complex envelope (0 for Gaussian noise).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import fft as sfft

__all__ = [
    "MIN_BAND_SAMPLES",
    "ORDER_TRACKING_UPSAMPLE",
    "EnvelopeSpectrum",
    "Kurtogram",
    "at_uniform_angle",
    "complex_envelope",
    "fast_kurtogram",
    "kurtogram_levels",
    "spectral_kurtosis",
    "squared_envelope_spectrum",
]

FloatArray = NDArray[np.float64]
ComplexArray = NDArray[np.complex128]

#: Fewest samples of a band's complex envelope the kurtogram estimates a kurtosis from: the
#: deepest level of Antoni's tree is log2(n) - 7 (his reference code), 2^6 samples per band.
MIN_BAND_SAMPLES = 64
#: Upsampling of a record before it is interpolated at the instants of uniform shaft angle.
ORDER_TRACKING_UPSAMPLE = 4


def _signal(signal: ArrayLike, sample_rate: float) -> FloatArray:
    x = np.asarray(signal, dtype=np.float64)
    if x.ndim != 1 or x.size < 2 * MIN_BAND_SAMPLES:
        raise ValueError(f"signal must be 1-D with at least {2 * MIN_BAND_SAMPLES} samples")
    if not np.all(np.isfinite(x)):
        raise ValueError("signal must be finite")
    if not (math.isfinite(sample_rate) and sample_rate > 0.0):
        raise ValueError(f"sample_rate must be a positive number of Hz, got {sample_rate!r}")
    return x - x.mean()


def _band_bins(n: int, sample_rate: float, band: tuple[float, float]) -> tuple[int, int]:
    """First and one-past-last rfft bin of ``band`` [Hz] (bins k with lo <= k fs / n < hi)."""
    lo, hi = band
    nyquist = 0.5 * sample_rate
    if not (math.isfinite(lo) and math.isfinite(hi) and 0.0 <= lo < hi <= nyquist):
        raise ValueError(
            f"band must satisfy 0 <= low < high <= {nyquist:.6g} Hz (Nyquist), got {band!r}"
        )
    k1 = math.ceil(lo * n / sample_rate - 1e-9)
    k2 = min(n // 2 + 1, math.ceil(hi * n / sample_rate - 1e-9))
    if k2 - k1 < 2:
        raise ValueError(f"band {band!r} holds fewer than 2 frequency bins of the record")
    return k1, k2


def complex_envelope(
    signal: ArrayLike, sample_rate: float, band: tuple[float, float], samples: int | None = None
) -> ComplexArray:
    r"""Complex envelope of ``signal`` in ``band``, shifted to zero frequency.

    Parameters
    ----------
    signal : array_like, shape (n,)
        Uniformly sampled record (any unit; its mean is removed).
    sample_rate : float
        Sampling rate [Hz].
    band : (float, float)
        Pass band [Hz], ``0 <= low < high <= sample_rate / 2``.
    samples : int, optional
        Samples of the envelope returned over the record's duration (default: twice the
        band's bins, enough for its square without aliasing).

    Returns
    -------
    ndarray of complex, shape (samples,)
        :math:`c(t_m)`, :math:`t_m = m\,T/M`, :math:`T` the record's duration: the analytic
        signal of the band-passed record times :math:`e^{-2\pi i f_{low} t}`, whose modulus
        is the envelope in the unit of ``signal``.

    Notes
    -----
    The band-pass is an ideal (rectangular, zero-phase) filter on the record's discrete Fourier
    transform, and the analytic signal keeps the positive frequencies doubled (Antoni and
    Randall 2011, sec. 3.2: "the squared envelope ... obtained as the squared magnitude of the
    analytic signal of the band-pass filtered signal"). The record is treated as periodic, as
    the DFT does.
    """
    x = _signal(signal, sample_rate)
    n = x.size
    k1, k2 = _band_bins(n, sample_rate, band)
    spectrum = sfft.rfft(x)[k1:k2]
    m = int(samples) if samples is not None else sfft.next_fast_len(2 * (k2 - k1))
    if m < k2 - k1:
        raise ValueError(f"samples must be at least the band's {k2 - k1} bins, got {m}")
    padded = np.zeros(m, dtype=np.complex128)
    padded[: k2 - k1] = 2.0 * spectrum
    # c_m = (1/n) sum_j 2 X[k1 + j] exp(2 pi i j m / M) = (M / n) ifft_M
    return np.asarray(sfft.ifft(padded) * (m / n), dtype=np.complex128)


@dataclass(frozen=True)
class EnvelopeSpectrum:
    """One-sided amplitude spectrum of a squared envelope.

    Attributes
    ----------
    frequency : ndarray, shape (m,)
        Frequencies [Hz], from 0 in steps of 1 / duration.
    amplitude : ndarray, shape (m,)
        Amplitude of each line of the squared envelope [(signal unit)^2]: a squared envelope
        :math:`e^2(t) = E + A\\cos(2\\pi f t + \\varphi)` reads :math:`A` at :math:`f`; the mean
        :math:`E` (bin 0) is set to 0.
    band_hz : (float, float)
        The pass band the envelope was taken in [Hz].
    resolution_hz : float
        Frequency step [Hz] (1 / the record's duration).
    """

    frequency: FloatArray
    amplitude: FloatArray
    band_hz: tuple[float, float]
    resolution_hz: float


def squared_envelope_spectrum(
    signal: ArrayLike, sample_rate: float, band: tuple[float, float]
) -> EnvelopeSpectrum:
    r"""Squared-envelope spectrum (SES) of ``signal`` band-passed to ``band``.

    Parameters
    ----------
    signal : array_like, shape (n,)
        Uniformly sampled acceleration record [m/s^2] (any unit; its mean is removed).
    sample_rate : float
        Sampling rate [Hz].
    band : (float, float)
        Pass band [Hz] around the resonance the impacts excite.

    Returns
    -------
    EnvelopeSpectrum
        Frequencies from 0 to the band's width (the envelope of a band holds no higher
        frequency), amplitudes in the signal's unit squared.

    Notes
    -----
    Randall and Antoni, "Rolling element bearing diagnostics — A tutorial" (MSSP 25, 2011),
    sec. 3.2, eq. (2)-(3) and Fig. 7: the envelope is the modulus of the analytic signal of the
    band-passed record, and the spectrum of its *square* is used (the squared envelope has the
    defect's cyclic frequencies without the extraneous components the modulus adds). Here the
    amplitude is one-sided: :math:`2|\mathrm{DFT}(e^2 - \overline{e^2})|/M`.
    """
    x = _signal(signal, sample_rate)
    n = x.size
    k1, k2 = _band_bins(n, sample_rate, band)
    c = complex_envelope(x, sample_rate, band)
    m = c.size
    squared = c.real**2 + c.imag**2
    squared -= squared.mean()
    keep = k2 - k1  # frequencies below the band's width
    amplitude = 2.0 * np.abs(sfft.rfft(squared)[:keep]) / m
    amplitude[0] = 0.0
    duration = n / sample_rate
    frequency = np.arange(keep, dtype=np.float64) / duration
    return EnvelopeSpectrum(frequency, amplitude, (float(band[0]), float(band[1])), 1.0 / duration)


def spectral_kurtosis(envelope: ArrayLike) -> FloatArray:
    r"""Kurtosis of complex envelopes, :math:`E|c|^4 / (E|c|^2)^2 - 2` along the last axis.

    Parameters
    ----------
    envelope : array_like of complex, shape (..., m)
        Complex envelopes (one per row).

    Returns
    -------
    ndarray of float, shape (...)
        0 for stationary circular Gaussian noise, positive for impulsive signals, -1 for a
        pure tone.

    Notes
    -----
    Antoni (2007), sec. 2, eq. (3): the spectral kurtosis of a band is the normalised fourth
    moment of its complex envelope less 2 (the value of complex Gaussian noise); the envelope's
    mean is removed first, as in his reference implementation.
    """
    c = np.asarray(envelope, dtype=np.complex128)
    c = c - c.mean(axis=-1, keepdims=True)
    power = c.real**2 + c.imag**2
    second = power.mean(axis=-1)
    fourth = (power**2).mean(axis=-1)
    with np.errstate(invalid="ignore", divide="ignore"):
        k = fourth / second**2 - 2.0
    return np.asarray(np.where(second > 0.0, k, 0.0), dtype=np.float64)


def kurtogram_levels(samples: int) -> list[tuple[float, int]]:
    """The levels of the 1/3-binary tree for a record of ``samples`` samples.

    Parameters
    ----------
    samples : int
        Record length [-].

    Returns
    -------
    list of (float, int)
        (level, number of bands): level k has 2^k bands of width fs / 2^(k+1), level
        k + log2(3) - 1 (k >= 1) has 3 * 2^(k-1) bands of width fs / (3 * 2^k); down to the
        level whose bands still hold :data:`MIN_BAND_SAMPLES` samples (Antoni 2007, sec. 3.2,
        Fig. 4).
    """
    out: list[tuple[float, int]] = []
    k = 0
    while True:
        bands = 2**k
        if samples // 2 // bands < MIN_BAND_SAMPLES:
            break
        out.append((float(k), bands))
        if k >= 1 and samples // 2 // (3 * 2 ** (k - 1)) >= MIN_BAND_SAMPLES:
            out.append((k + math.log2(3.0) - 1.0, 3 * 2 ** (k - 1)))
        k += 1
    out.sort()
    return out


@dataclass(frozen=True)
class Kurtogram:
    """Spectral kurtosis of every band of the 1/3-binary tree, and the best band.

    Attributes
    ----------
    levels : tuple of float
        Level of each row (0, 1, 1.585, 2, 2.585, ...).
    kurtosis : tuple of ndarray
        Per level, the spectral kurtosis of each of its bands, lowest band first (NaN where a
        band is narrower than the ``min_bandwidth`` asked or starts below the ``min_low``
        asked).
    bandwidths : tuple of float
        Band width of each level [Hz].
    band_hz : (float, float)
        The band of largest kurtosis [Hz].
    level : float
        Its level.
    max_kurtosis : float
        Its kurtosis [-].
    """

    levels: tuple[float, ...]
    kurtosis: tuple[FloatArray, ...]
    bandwidths: tuple[float, ...]
    band_hz: tuple[float, float]
    level: float
    max_kurtosis: float


def fast_kurtogram(
    signal: ArrayLike,
    sample_rate: float,
    *,
    min_bandwidth: float = 0.0,
    min_low: float = 0.0,
    max_level: float | None = None,
) -> Kurtogram:
    r"""Spectral kurtosis over the bands of Antoni's fast kurtogram, and the most impulsive band.

    Parameters
    ----------
    signal : array_like, shape (n,)
        Uniformly sampled record (its mean is removed).
    sample_rate : float
        Sampling rate [Hz].
    min_bandwidth : float
        Narrowest band considered [Hz]: an envelope spectrum only reaches the band's width, so
        the band must be wider than the highest frequency it is read at.
    min_low : float
        Lowest lower edge of a band considered [Hz]: a band that holds the frequencies its
        envelope spectrum is read at holds those lines themselves, not as a modulation of a
        resonance, and its envelope mixes them (a noiseless simulated record's low band carries
        the impacts' force directly, as impulsive as the resonance's band). Bands starting
        below it are not chosen (their kurtosis is reported as NaN): with ``min_low`` > 0 not
        the whole record's band (level 0) either, which holds them too.
    max_level : float, optional
        Deepest level (default: every level whose bands hold :data:`MIN_BAND_SAMPLES`).

    Returns
    -------
    Kurtogram

    Raises
    ------
    ValueError
        A signal too short for level 0, or no band at least ``min_bandwidth`` wide starting at
        ``min_low`` or above.

    Notes
    -----
    J. Antoni, "Fast computation of the kurtogram for the detection of transient faults",
    MSSP 21 (2007): the bands are those of his 1/3-binary tree (sec. 3.2, Fig. 4: at level k,
    2^k bands of width fs / 2^(k+1), between levels k and k+1 the 3 * 2^(k-1) bands of width
    fs / (3 * 2^k)), the statistic is the kurtosis of each band's complex envelope less 2
    (eq. 3, his ``kurt2``), negative values read as 0 as in his reference code. His tree
    computes the complex envelopes with short quasi-analytic FIR filters and decimation; here
    each band is cut from the record's DFT with an ideal rectangular filter and brought to zero
    frequency (critically sampled, one DFT and one inverse DFT per level: the same bands and
    statistic, sharper band edges, O(n log n) per level).
    """
    x = _signal(signal, sample_rate)
    n = x.size
    spectrum = sfft.rfft(x)
    half = n // 2  # bins 0 .. n/2 - 1 cover [0, fs/2)
    levels = kurtogram_levels(n)
    if max_level is not None:
        levels = [lv for lv in levels if lv[0] <= max_level + 1e-9]
    if not levels:
        raise ValueError(f"a record of {n} samples is too short for a kurtogram")
    rows: list[FloatArray] = []
    widths: list[float] = []
    best = (-math.inf, 0.0, (0.0, 0.0))
    for level, bands in levels:
        width = 0.5 * sample_rate / bands
        widths.append(width)
        if width < min_bandwidth:
            rows.append(np.full(bands, np.nan))
            continue
        per = half // bands
        block = spectrum[: per * bands].reshape(bands, per)
        k = np.maximum(spectral_kurtosis(sfft.ifft(block, axis=1)), 0.0)
        low_edges = np.arange(bands) * per * sample_rate / n
        k = np.where(low_edges >= min_low, k, np.nan)
        rows.append(k)
        if np.isnan(k).all():
            continue
        i = int(np.nanargmax(k))
        if k[i] > best[0]:
            best = (float(k[i]), level, (float(low_edges[i]), (i + 1) * per * sample_rate / n))
    if best[0] == -math.inf:
        raise ValueError(
            f"no band of the kurtogram is {min_bandwidth:.6g} Hz wide or more and starts at "
            f"{min_low:.6g} Hz or above (the widest is {0.5 * sample_rate:.6g} Hz, from 0 Hz)"
        )
    return Kurtogram(
        tuple(lv for lv, _ in levels), tuple(rows), tuple(widths), best[2], best[1], best[0]
    )


def at_uniform_angle(
    time: ArrayLike, angle: ArrayLike, values: ArrayLike
) -> tuple[FloatArray, FloatArray, float]:
    """A record resampled at equal increments of the shaft angle (computed order tracking).

    Parameters
    ----------
    time : array_like
        Instants of the samples, equally spaced [s].
    angle : array_like
        Shaft angle at each instant [rev], increasing.
    values : array_like
        The samples (any unit).

    Returns
    -------
    time : ndarray
        As many instants over the same span on the time axis of the mean speed f̄ = revolutions
        / span [s]: a line at a fixed order k of the shaft is at k f̄ Hz whatever the speed did.
    values : ndarray
        The record at those angles.
    mean_hz : float
        f̄ [Hz].

    Notes
    -----
    The record, upsampled :data:`ORDER_TRACKING_UPSAMPLE` times by a polyphase filter, is
    interpolated linearly at the instants of uniform angle (the angle itself interpolated
    linearly between samples). K. R. Fyfe and E. D. S. Munck, "Analysis of computed order
    tracking", Mechanical Systems and Signal Processing 11(2), 1997.
    """
    from scipy.signal import resample_poly

    t = np.asarray(time, dtype=np.float64)
    turns = np.asarray(angle, dtype=np.float64)
    count = t.size
    span = float(t[-1] - t[0])
    mean_hz = float(turns[-1] - turns[0]) / span
    uniform = turns[0] + (turns[-1] - turns[0]) * np.arange(count, dtype=np.float64) / (count - 1)
    instants = np.interp(uniform, turns, t)
    up = ORDER_TRACKING_UPSAMPLE
    step = span / (count - 1) / up
    fine = np.asarray(resample_poly(np.asarray(values, dtype=np.float64), up, 1), dtype=np.float64)
    grid = t[0] + step * np.arange(fine.size, dtype=np.float64)
    out: FloatArray = np.asarray(np.interp(instants, grid, fine), dtype=np.float64)
    return t[0] + (uniform - turns[0]) / mean_hz, out, mean_hz
