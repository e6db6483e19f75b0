r"""Spectra, known-line extraction, RRO/NRRO separation and band values (Anderon, ISO 15242-1).

Shared signal processing for every model. Plain vectorised functions on SI arrays returning
small frozen dataclasses.

Conventions
-----------
* Units are SI: time [s], frequency [Hz], displacement [m], angle [rad].
* An *order* is a frequency divided by the rotation frequency of the rotating ring, i.e. the
  number of waves per revolution of that ring (seed 002 calls the unit "wave").
* An *amplitude* is zero-to-peak: a line :math:`A\cos(2\pi f t + \varphi)` has amplitude
  :math:`A`. A *p-p* value is the peak-to-peak value :math:`2A`. Displacement runout is
  reported p-p, as in seed 000 §2.2 (twice the single-sided spectrum value of the Hann-windowed
  record, read as a p-p value), see :attr:`Spectrum.pp` and :attr:`Lines.pp`.
* Phases follow :math:`x(t) = c + \sum_j A_j \cos(2\pi f_j t + \varphi_j)` with ``t`` the time
  exactly as the caller gave it (the phase refers to ``t = 0``, not to the first sample).

Contents
--------
* :func:`amplitude_spectrum` -- windowed one-sided amplitude spectrum, coherent gain corrected.
* :func:`extract_lines` -- leakage-free least-squares fit of lines at known frequencies.
* :func:`peak_bin_gain` -- what a windowed FFT of a finite record reads for an off-bin line
  (scalloping loss), to compare exact lines with published analyser readings.
* :func:`separate_rro_nrro` and :func:`separate_rro_nrro_lines` -- repeatable and
  non-repeatable parts of a waveform or of a list of lines.
* :func:`anderon_bands_from_lines`, :func:`anderon_bands_from_waveform` -- Anderon band values
  (seed 002 eq. 1 and eq. 42).
* :func:`iso15242_bands_from_lines`, :func:`iso15242_bands_from_waveform` -- rms velocity in
  the three ISO 15242-1 bands.
* helpers :func:`orders`, :func:`to_peak_to_peak`, :func:`to_zero_to_peak`.
"""

from __future__ import annotations

import contextlib
import functools
import math
import warnings
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, Literal

import numba
import numpy as np
import numpy.typing as npt
from numpy.typing import ArrayLike

from runout._threads import halves, in_spans

__all__ = [
    "ANDERON_BANDS",
    "ANDERON_BANDS_PRINTED",
    "ISO15242_BANDS",
    "MICROINCH",
    "Band",
    "BandSet",
    "BandValues",
    "LineResolutionWarning",
    "LineRunout",
    "Lines",
    "Peaks",
    "RroNrro",
    "Spectrum",
    "amplitude_spectrum",
    "anderon_bands_from_lines",
    "anderon_bands_from_waveform",
    "extract_lines",
    "iso15242_band_set",
    "iso15242_bands_from_lines",
    "iso15242_bands_from_waveform",
    "orders",
    "peak_bin_gain",
    "separate_rro_nrro",
    "separate_rro_nrro_lines",
    "to_peak_to_peak",
    "to_zero_to_peak",
]

FloatArray = npt.NDArray[np.float64]

#: One microinch in metres (the length unit of the Anderon, seed 002 eq. 1) [m].
MICROINCH = 25.4e-9

#: Relative tolerance on band edges: a line or bin sitting exactly on an edge shared by two
#: adjacent bands belongs to the upper one, whatever the rounding of the edge.
_EDGE_RTOL = 1e-9


class LineResolutionWarning(UserWarning):
    """Two requested line frequencies (or one and DC) are closer than 1 / record length.

    The least-squares fit still returns the exact answer for a noise-free signal made of those
    lines only, but the separation of the close lines is sensitive to noise and to any
    component not in the model.
    """


# --------------------------------------------------------------------------------------------
# Helpers
# --------------------------------------------------------------------------------------------


def orders(frequency: ArrayLike, rotation_hz: float) -> FloatArray:
    """Frequencies expressed as orders of the rotating ring's speed [-].

    Parameters
    ----------
    frequency : array_like
        Frequencies [Hz].
    rotation_hz : float
        Rotation frequency of the rotating ring [Hz] (> 0).

    Returns
    -------
    ndarray
        ``frequency / rotation_hz``: waves per revolution.
    """
    _check_positive("rotation_hz", rotation_hz)
    return np.asarray(frequency, dtype=float) / float(rotation_hz)


def to_peak_to_peak(amplitude: ArrayLike) -> FloatArray:
    """Zero-to-peak amplitude -> peak-to-peak value (times two) [same unit]."""
    return 2.0 * np.asarray(amplitude, dtype=float)


def to_zero_to_peak(pp: ArrayLike) -> FloatArray:
    """Peak-to-peak value -> zero-to-peak amplitude (divided by two) [same unit]."""
    return 0.5 * np.asarray(pp, dtype=float)


def _check_positive(name: str, value: float) -> None:
    if isinstance(value, bool) or not (
        isinstance(value, int | float | np.integer | np.floating)
        and math.isfinite(value)
        and value > 0
    ):
        raise ValueError(f"{name} must be a positive finite number, got {value!r}")


def _as_signal(signal: ArrayLike, axis: int, name: str = "signal") -> FloatArray:
    """Finite float array with the sample axis moved last."""
    x = np.asarray(signal, dtype=float)
    if x.ndim == 0:
        raise ValueError(f"{name} must be an array of samples, got a scalar")
    try:
        x = np.moveaxis(x, axis, -1)
    except np.exceptions.AxisError as exc:
        raise ValueError(f"{name}: axis {axis} out of range for shape {x.shape}") from exc
    if not np.all(np.isfinite(x)):
        bad = int(np.count_nonzero(~np.isfinite(x)))
        raise ValueError(f"{name} holds {bad} non-finite value(s) (NaN or inf)")
    return x


def _check_samples_per_rev(samples_per_rev: int) -> int:
    if isinstance(samples_per_rev, bool) or not isinstance(samples_per_rev, int | np.integer):
        raise ValueError(f"samples_per_rev must be an integer, got {samples_per_rev!r}")
    if samples_per_rev < 2:
        raise ValueError(f"samples_per_rev must be >= 2, got {samples_per_rev}")
    return int(samples_per_rev)


def _uniform_step(time: FloatArray, rtol: float) -> float | None:
    """Sampling step of ``time`` if it is uniform within ``rtol`` of the step, else ``None``."""
    n = time.size
    dt = (time[-1] - time[0]) / (n - 1)
    if not dt > 0:
        return None
    # |time - (t0 + dt i)| in one array (in place): a record of 2^22 instants costs 32 MiB less
    dev = np.arange(n, dtype=np.float64)
    dev *= dt
    dev += time[0]
    dev -= time
    np.abs(dev, out=dev)
    if np.max(dev) <= rtol * dt:
        return float(dt)
    return None


def _as_time(time: ArrayLike, n: int) -> FloatArray:
    t = np.asarray(time, dtype=float)
    if t.ndim != 1:
        raise ValueError(f"time must be a 1-D array, got shape {t.shape}")
    if t.size != n:
        raise ValueError(f"time has {t.size} samples but the signal has {n}")
    if not np.all(np.isfinite(t)):
        raise ValueError("time holds non-finite value(s) (NaN or inf)")
    if n >= 2 and not np.all(t[1:] > t[:-1]):  # diff > 0, without an array of differences
        raise ValueError("time must be strictly increasing")
    return t


# --------------------------------------------------------------------------------------------
# Amplitude spectrum
# --------------------------------------------------------------------------------------------

_WINDOW_ALIASES = {
    "hann": "hann",
    "hanning": "hann",
    "boxcar": "boxcar",
    "rect": "boxcar",
    "rectangular": "boxcar",
    "none": "boxcar",
}


def _hann(n: int) -> FloatArray:
    """Periodic (DFT-even) Hann window of length ``n`` [-].

    The same operations as ``scipy.signal.get_window("hann", n, fftbins=True)`` (a cosine sum
    over ``n + 1`` points, the last dropped), so the values are identical to the bit, without
    importing scipy.signal (about a second of start-up).
    """
    if n <= 1:
        return np.ones(n)
    # SciPy: w = 0; w += 0.5 cos(0 fac); w += 0.5 cos(1 fac), i.e. 0.5 + 0.5 cos(fac) with the
    # same roundings (cos 0 = 1; 0.5 x is exact); computed in place, one array of n + 1
    w = np.linspace(-np.pi, np.pi, n + 1)
    np.cos(w, out=w)
    w *= 0.5
    w += 0.5
    return w[:-1]


def _window(window: str | tuple[object, ...] | ArrayLike | None, n: int) -> FloatArray:
    """Periodic (DFT-even) window of length ``n``; arrays are taken as given."""
    if window is None:
        return np.ones(n)
    if isinstance(window, str):
        spec: str | tuple[object, ...] = _WINDOW_ALIASES.get(window.lower(), window)
    elif isinstance(window, tuple):
        spec = window
    else:
        w = np.asarray(window, dtype=float)
        if w.shape != (n,):
            raise ValueError(f"window array must have shape ({n},), got {w.shape}")
        if not np.all(np.isfinite(w)) or w.sum() <= 0:
            raise ValueError("window array must be finite with a positive sum")
        return w
    if spec == "hann":
        return _hann(n)
    if spec == "boxcar":
        return np.ones(n)
    import scipy.signal  # lazily, other windows only: importing it costs ~1 s at start-up

    try:
        return np.asarray(scipy.signal.get_window(spec, n, fftbins=True), dtype=float)
    except (ValueError, TypeError) as exc:
        raise ValueError(f"unknown window {window!r}: {exc}") from None


@dataclass(frozen=True, eq=False)
class Peaks:
    """Local maxima of a spectrum, largest first.

    Attributes
    ----------
    frequencies : ndarray, shape (k,)
        Bin frequencies [Hz].
    amplitude : ndarray, shape (k,)
        Single-sided zero-to-peak amplitudes [signal unit].
    """

    frequencies: FloatArray
    amplitude: FloatArray

    @property
    def pp(self) -> FloatArray:
        """Peak-to-peak values, ``2 * amplitude`` [signal unit]."""
        return 2.0 * self.amplitude

    def __len__(self) -> int:
        return int(self.frequencies.size)


@dataclass(frozen=True, eq=False)
class Spectrum:
    """One-sided amplitude spectrum with the window's coherent gain corrected.

    A sinusoid of amplitude ``A`` whose frequency falls on a bin reads ``A`` in
    :attr:`amplitude` and ``2A`` in :attr:`pp` (seed 000 §2.2 convention).

    Attributes
    ----------
    frequencies : ndarray, shape (n_f,)
        Bin frequencies [Hz], ``k * sample_rate / n`` for ``k = 0 .. n // 2``.
    amplitude : ndarray, shape (..., n_f)
        Single-sided zero-to-peak amplitude [signal unit]; the frequency axis is last, the
        leading axes are those of the input signal without its sample axis.
    window : str
        Description of the window used.
    n_samples : int
        Record length in samples.
    sample_rate : float
        Sampling frequency [Hz].
    """

    frequencies: FloatArray
    amplitude: FloatArray
    window: str
    n_samples: int
    sample_rate: float

    @property
    def pp(self) -> FloatArray:
        """Peak-to-peak spectrum, ``2 * amplitude`` [signal unit]."""
        return 2.0 * self.amplitude

    @property
    def resolution(self) -> float:
        """Bin spacing ``sample_rate / n_samples`` [Hz]."""
        return self.sample_rate / self.n_samples

    def orders(self, rotation_hz: float) -> FloatArray:
        """Bin frequencies as orders of ``rotation_hz`` [-] (waves per revolution)."""
        return orders(self.frequencies, rotation_hz)

    def channel(self, index: int | tuple[int, ...]) -> Spectrum:
        """The spectrum of one channel of a multi-channel (N-D) spectrum."""
        return Spectrum(
            self.frequencies,
            np.asarray(self.amplitude[index], dtype=float),
            self.window,
            self.n_samples,
            self.sample_rate,
        )

    def at(self, frequency: ArrayLike, *, pp: bool = False) -> FloatArray:
        """Amplitude of the bin nearest to ``frequency``.

        Parameters
        ----------
        frequency : array_like
            Frequency or frequencies [Hz], within the spectrum's range.
        pp : bool
            Return the peak-to-peak value (``2 * amplitude``) instead of the amplitude.

        Returns
        -------
        ndarray
            Shape ``amplitude.shape[:-1] + np.shape(frequency)``.
        """
        f = np.asarray(frequency, dtype=float)
        df = self.resolution
        if not np.all(np.isfinite(f)) or np.any(f < 0) or np.any(f > self.frequencies[-1] + df / 2):
            raise ValueError(
                f"frequency {frequency!r} is outside the spectrum range "
                f"[0, {self.frequencies[-1]:.6g}] Hz"
            )
        idx = np.clip(np.rint(f / df).astype(int), 0, self.frequencies.size - 1)
        out = self.amplitude[..., idx]
        return 2.0 * out if pp else out

    def peaks(self, n: int | None = None, *, threshold: float | None = None) -> Peaks:
        """Local maxima of a single-channel spectrum, largest first.

        Parameters
        ----------
        n : int or None
            Keep at most the ``n`` largest peaks.
        threshold : float or None
            Keep peaks whose single-sided amplitude is at least ``threshold``
            [signal unit].

        Returns
        -------
        Peaks
            The DC bin is never reported.
        """
        if self.amplitude.ndim != 1:
            raise ValueError(
                f"peaks needs a single-channel spectrum, this one has shape "
                f"{self.amplitude.shape}; select one with .channel(i)"
            )
        if n is not None and (isinstance(n, bool) or not isinstance(n, int) or n < 0):
            raise ValueError(f"n must be a non-negative integer, got {n!r}")
        a = self.amplitude
        if a.size < 3:
            return Peaks(np.empty(0), np.empty(0))
        left = np.concatenate(([np.inf], a[:-1]))
        right = np.concatenate((a[1:], [-np.inf]))
        mask = (a > left) & (a >= right)
        mask[0] = False
        if threshold is not None:
            mask &= a >= threshold
        idx = np.flatnonzero(mask)
        idx = idx[np.argsort(-a[idx], kind="stable")]
        if n is not None:
            idx = idx[:n]
        return Peaks(self.frequencies[idx].copy(), a[idx].copy())


def amplitude_spectrum(
    signal: ArrayLike,
    sample_rate: float | None = None,
    window: str | tuple[object, ...] | ArrayLike | None = "hann",
    *,
    time: ArrayLike | None = None,
    axis: int = -1,
    remove_dc: bool = True,
) -> Spectrum:
    r"""One-sided amplitude spectrum, corrected for the window's coherent gain.

    With :math:`X_k = \sum_i w_i x_i e^{-2\pi j k i / n}` the single-sided amplitude is
    :math:`A_k = 2 |X_k| / \sum_i w_i` (no factor 2 at DC and at the Nyquist bin), so a
    sinusoid of amplitude :math:`A` centred on bin :math:`k` reads :math:`A_k = A` and
    :math:`2A` as a p-p value -- the convention of seed 000 §2.2 (Hann window, p-p value
    twice the single-sided spectrum). Windows are periodic (DFT-even); with the Hann window a
    line leaks half its amplitude into each neighbouring bin, so lines on bins two or more
    apart are read exactly.

    Parameters
    ----------
    signal : array_like
        Samples [any unit]; several channels (e.g. x and y directions) along other axes.
    sample_rate : float or None
        Sampling frequency [Hz]. Give either this or ``time``.
    window : str, tuple, array_like or None
        ``"hann"`` (default), ``"boxcar"`` (also ``"none"``, ``None``), any name
        :func:`scipy.signal.get_window` knows, or an array of length ``n``.
    time : array_like or None
        Sample times [s], 1-D; must be uniform (relative jitter below 1e-6 of the step).
    axis : int
        Sample axis of ``signal``.
    remove_dc : bool
        Subtract the mean of each channel first (default). Without it a large offset leaks
        into the first bins through the window.

    Returns
    -------
    Spectrum

    Raises
    ------
    ValueError
        Fewer than 4 samples, non-finite values, non-uniform ``time``, bad sample rate or
        window.
    """
    x = _as_signal(signal, axis)
    n = x.shape[-1]
    if n < 4:
        raise ValueError(f"a spectrum needs at least 4 samples, got {n}")
    if (sample_rate is None) == (time is None):
        raise ValueError("give exactly one of sample_rate and time")
    if time is not None:
        t = _as_time(time, n)
        dt = _uniform_step(t, 1e-6)
        if dt is None:
            jitter = float(np.max(np.abs(np.diff(t) - np.diff(t).mean())))
            raise ValueError(
                f"time is not uniformly sampled (step varies by up to {jitter:.3g} s); "
                "use extract_lines for non-uniform samples or resample first"
            )
        fs = 1.0 / dt
    else:
        assert sample_rate is not None
        _check_positive("sample_rate", sample_rate)
        fs = float(sample_rate)
    w = _window(window, n)
    # one windowed copy of the record (in place), one spectrum, one amplitude array
    xw = x - x.mean(axis=-1, keepdims=True) if remove_dc else x.copy()
    xw *= w
    spec = np.fft.rfft(xw, axis=-1)
    del xw
    amp = np.abs(spec)
    del spec
    amp *= 2.0 / w.sum()
    amp[..., 0] *= 0.5
    if n % 2 == 0:
        amp[..., -1] *= 0.5
    freqs = np.fft.rfftfreq(n, 1.0 / fs).astype(np.float64)
    name = window if isinstance(window, str) else ("boxcar" if window is None else "custom")
    return Spectrum(freqs, amp, str(name), n, fs)


def peak_bin_gain(
    frequency: ArrayLike,
    duration: float,
    window: str | tuple[object, ...] | None = "hann",
    *,
    samples: int = 8192,
) -> FloatArray:
    r"""Fraction of a line's amplitude that a windowed FFT reads at the line's nearest bin.

    A record of length :math:`T` has bins every :math:`1/T`; a line at :math:`f` sits
    :math:`\delta = fT - \operatorname{round}(fT)` bins (:math:`|\delta| \le 1/2`) from its
    nearest bin, where :func:`amplitude_spectrum` reads it as :math:`A\,G(\delta)` with

    .. math:: G(\delta) = \frac{\left|\sum_{n=0}^{N-1} w_n e^{-2\pi i \delta n/N}\right|}
              {\sum_{n=0}^{N-1} w_n}

    (the scalloping loss; for the Hann window :math:`G \to \operatorname{sinc}\delta /
    (1 - \delta^2)` as :math:`N \to \infty`, 1 on a bin and 0.849 half-way). The leakage of
    the line's negative-frequency image is neglected: it is below 1e-3 of the amplitude once
    the line is more than about five bins from DC (Hann window). Use it to compare an exact
    line (:func:`extract_lines`) with a value read off a published FFT spectrum of a record
    whose length is known or has been identified.

    Parameters
    ----------
    frequency : array_like
        Line frequencies [Hz], >= 0.
    duration : float
        Record length :math:`T = N \Delta t` [s], > 0.
    window : str, tuple or None
        As in :func:`amplitude_spectrum` (default ``"hann"``).
    samples : int
        Number of samples :math:`N` of the record (default 8192; the gain converges as
        :math:`1/N^2`, so any realistic record is represented).

    Returns
    -------
    ndarray
        :math:`G` [-], same shape as ``frequency``: in (0, 1] and lowest half a bin off for
        the Hann, Hamming, Blackman and boxcar windows (a flat-top window ripples a few 1e-4
        above 1).
    """
    _check_positive("duration", duration)
    if samples < 4:
        raise ValueError(f"samples must be at least 4, got {samples}")
    f = np.asarray(frequency, dtype=float)
    if not np.all(np.isfinite(f)) or np.any(f < 0):
        raise ValueError("frequency must be finite and >= 0")
    w = _window(window, samples)
    cycles = f * duration
    offset = cycles - np.round(cycles)
    n = np.arange(samples)
    phasor = np.exp(-2j * np.pi * np.multiply.outer(offset, n) / samples)
    return np.asarray(np.abs(phasor @ w) / w.sum(), dtype=np.float64)


# --------------------------------------------------------------------------------------------
# Known-line extraction (least squares)
# --------------------------------------------------------------------------------------------

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
    independent: a long record's halves run on two threads (:mod:`runout._threads`) with the
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


@dataclass(frozen=True, eq=False)
class Lines:
    r"""Lines fitted at known frequencies.

    The model is :math:`x(t) = c + \sum_j A_j \cos(2\pi f_j t + \varphi_j)`, ``t`` as given
    to :func:`extract_lines`.

    Attributes
    ----------
    frequencies : ndarray, shape (m,)
        Line frequencies [Hz], in the order requested.
    amplitude : ndarray, shape (..., m)
        Zero-to-peak amplitudes :math:`A_j` [signal unit].
    phase : ndarray, shape (..., m)
        Phases :math:`\varphi_j` [rad] in (-pi, pi].
    constant : ndarray, shape (...)
        Fitted offset :math:`c` [signal unit] (0 when no constant was fitted).
    residual_rms : ndarray, shape (...)
        Rms of the signal minus the fitted model [signal unit].
    condition_number : float
        Condition number of the column-scaled design matrix [-].
    """

    frequencies: FloatArray
    amplitude: FloatArray
    phase: FloatArray
    constant: FloatArray
    residual_rms: FloatArray
    condition_number: float

    @property
    def pp(self) -> FloatArray:
        """Peak-to-peak value of each line, ``2 * amplitude`` [signal unit]."""
        return 2.0 * self.amplitude

    def orders(self, rotation_hz: float) -> FloatArray:
        """Line frequencies as orders of ``rotation_hz`` [-]."""
        return orders(self.frequencies, rotation_hz)

    def evaluate(self, time: ArrayLike) -> FloatArray:
        """The fitted model at ``time`` [s]; shape ``amplitude.shape[:-1] + (len(time),)``."""
        t = np.asarray(time, dtype=float)
        ph = 2.0 * np.pi * np.multiply.outer(t, self.frequencies)  # (n, m)
        terms = self.amplitude[..., None, :] * np.cos(ph + self.phase[..., None, :])
        return np.asarray(terms.sum(axis=-1) + self.constant[..., None])


@functools.lru_cache(maxsize=1)
def _blas_controller() -> Any:
    """threadpoolctl's controller of the BLAS libraries loaded (NumPy's and SciPy's)."""
    import scipy.linalg  # noqa: F401  (loads SciPy's BLAS, so that the controller sees it)

    try:
        from threadpoolctl import ThreadpoolController
    except ImportError:  # a dependency; without it the BLAS keeps its default threads
        return None
    return ThreadpoolController()


def _one_blas_thread() -> contextlib.AbstractContextManager[Any]:
    """Run the enclosed BLAS/LAPACK calls on one thread.

    The fit's dense algebra is small (a symmetric eigenvalue problem and a Cholesky of
    ``2 m + 1`` unknowns, ~5 ms on one core for 200 lines): a threaded BLAS gains nothing on
    it, and when the cores are busy with other work its threads wait for each other, which
    measured 0.36-2.3 s instead of 65 ms for a 200-line fit on a shared 2-core machine.
    """
    controller = _blas_controller()
    if controller is None:
        return contextlib.nullcontext()
    return controller.limit(limits=1, user_api="blas")


def _fmt_pair(a: float, b: float) -> str:
    """'a Hz and b Hz' with just enough digits to tell them apart."""
    for digits in range(6, 18):
        sa, sb = f"{a:.{digits}g}", f"{b:.{digits}g}"
        if sa != sb:
            break
    return f"{sa} Hz and {sb} Hz"


def _close_pairs(freqs: FloatArray, limit: float) -> list[tuple[float, float]]:
    order = np.sort(freqs)
    gaps = np.diff(order)
    return [(float(order[i]), float(order[i + 1])) for i in np.flatnonzero(gaps < limit)]


def extract_lines(
    time: ArrayLike,
    signal: ArrayLike,
    frequencies: ArrayLike,
    *,
    axis: int = -1,
    constant: bool = True,
    max_condition: float = 1e6,
) -> Lines:
    r"""Least-squares amplitudes and phases of lines at known frequencies (no leakage).

    Fits :math:`x(t) = c + \sum_j [a_j \cos(2\pi f_j t) + b_j \sin(2\pi f_j t)]` and
    returns :math:`A_j = \sqrt{a_j^2 + b_j^2}`, :math:`\varphi_j = \operatorname{atan2}(-b_j,
    a_j)` so that :math:`x = c + \sum_j A_j \cos(2\pi f_j t + \varphi_j)`. Unlike a DFT
    this is exact for non-integer numbers of periods and for lines closer than a bin, as long
    as every line present is in the model.

    Implementation: normal equations :math:`M^T M\,c = M^T x` scaled to unit diagonal, solved
    by Cholesky with one step of iterative refinement on the true residual (which recovers
    the accuracy of a QR solve for the condition numbers accepted here). For uniform samples
    :math:`M^T M` is computed in closed form from Dirichlet sums and :math:`M^T x` by a
    compiled rotating-phasor (Goertzel-like) loop, so the cost is O(n m + m^3) and memory
    O(n + m^2); non-uniform samples use a chunked O(n m^2) NumPy path.

    Parameters
    ----------
    time : array_like, shape (n,)
        Sample times [s], strictly increasing; uniform sampling is detected automatically.
    signal : array_like
        Samples [any unit]; ``signal.shape[axis] == n``; other axes are channels.
    frequencies : array_like, shape (m,)
        Distinct line frequencies [Hz], > 0 and, for uniform samples, below Nyquist.
    axis : int
        Sample axis of ``signal``.
    constant : bool
        Also fit a constant offset (default).
    max_condition : float
        Largest accepted condition number of the column-scaled design matrix (default 1e6;
        two lines a fraction g of 1/T apart give roughly 1/g).

    Returns
    -------
    Lines

    Warns
    -----
    LineResolutionWarning
        When two frequencies (or a frequency and DC) are closer than 1 / record length; the
        message names them.

    Raises
    ------
    ValueError
        Bad shapes or values, fewer samples than unknowns, duplicate frequencies, a frequency
        at or above Nyquist, or a design matrix too ill-conditioned to separate the lines
        (the message names the closest frequencies).
    """
    x = _as_signal(signal, axis)
    n = x.shape[-1]
    t = _as_time(time, n)
    f = np.asarray(frequencies, dtype=float)
    if f.ndim == 0:
        f = f[None]
    if f.ndim != 1 or f.size == 0:
        raise ValueError(f"frequencies must be a non-empty 1-D array, got shape {f.shape}")
    if not np.all(np.isfinite(f)) or np.any(f <= 0):
        raise ValueError(
            "frequencies must be finite and > 0 (the constant term stands for 0 Hz), got "
            f"{f[~(np.isfinite(f) & (f > 0))][:5].tolist()}"
        )
    m = f.size
    p = 2 * m + int(constant)
    if n < p:
        raise ValueError(f"{m} lines need at least {p} samples, got {n}")
    sorted_f = np.sort(f)
    dup = np.flatnonzero(np.diff(sorted_f) == 0)
    if dup.size:
        raise ValueError(f"duplicate line frequency {sorted_f[dup[0]]:.9g} Hz")

    dt = _uniform_step(t, 1e-9)
    record = (t[-1] - t[0]) * n / (n - 1)  # n samples cover n steps
    if dt is not None and sorted_f[-1] >= 0.5 / dt * (1 - 1e-12):
        raise ValueError(
            f"line frequency {sorted_f[-1]:.9g} Hz is at or above the Nyquist frequency "
            f"{0.5 / dt:.9g} Hz of the samples (it would alias onto another line)"
        )
    lead = x.shape[:-1]
    xs = np.ascontiguousarray(x.reshape(-1, n))
    omega = 2.0 * np.pi * f

    if dt is not None:
        gram = _gram_uniform(n, dt, omega, constant)

        def project(r: FloatArray) -> FloatArray:
            c, s = _project_uniform_kernel(r, dt, omega)
            cols = [c, s] if not constant else [r.sum(axis=1)[:, None], c, s]
            return np.hstack(cols)

        def synth(coef: FloatArray) -> FloatArray:
            c0 = coef[:, 0] if constant else np.zeros(coef.shape[0])
            off = int(constant)
            return np.asarray(
                _synthesize_uniform_kernel(
                    np.ascontiguousarray(c0),
                    np.ascontiguousarray(coef[:, off : off + m]),
                    np.ascontiguousarray(coef[:, off + m :]),
                    dt,
                    omega,
                    n,
                )
            )

    else:
        tau = t - t[0]
        gram = _gram_numpy(tau, omega, constant)

        def project(r: FloatArray) -> FloatArray:
            c, s = _project_numpy(r, tau, omega)
            cols = [c, s] if not constant else [r.sum(axis=1)[:, None], c, s]
            return np.hstack(cols)

        def synth(coef: FloatArray) -> FloatArray:
            c0 = coef[:, 0] if constant else np.zeros(coef.shape[0])
            off = int(constant)
            return _synthesize_numpy(c0, coef[:, off : off + m], coef[:, off + m :], tau, omega)

    # Scale the columns to unit norm, check the conditioning, solve.
    d = np.sqrt(np.diag(gram))
    if np.any(d == 0):
        raise ValueError("a design-matrix column is identically zero (line at a sampling null)")
    gn = gram / np.outer(d, d)
    with _one_blas_thread():  # see _one_blas_thread: threads cost far more than they give here
        eig = np.linalg.eigvalsh(gn)
    cond = math.inf if eig[0] <= 0 else float(math.sqrt(eig[-1] / eig[0]))
    if not cond <= max_condition:
        pairs = _close_pairs(f, 1.0 / record) or _close_pairs(f, np.inf)[:1]
        gap = min((b - a for a, b in _close_pairs(f, np.inf)), default=math.inf)
        names = "; ".join(_fmt_pair(a, b) for a, b in pairs[:5])
        raise ValueError(
            f"the lines cannot be separated: design-matrix condition number {cond:.3g} exceeds "
            f"{max_condition:.3g}; closest lines {names} (gap {gap:.3g} Hz, record "
            f"resolution 1/T = {1.0 / record:.3g} Hz). Merge them or use a longer record"
        )
    close = _close_pairs(f, 1.0 / record)
    low = sorted_f[sorted_f < 1.0 / record] if constant else np.empty(0)
    if close or low.size:
        parts = [_fmt_pair(a, b) for a, b in close[:5]]
        parts += [f"{v:.9g} Hz and DC" for v in low[:3]]
        more = "" if len(close) <= 5 else f" (and {len(close) - 5} more pairs)"
        warnings.warn(
            "lines closer than 1/record length = "
            f"{1.0 / record:.6g} Hz: {'; '.join(parts)}{more}; their separation is "
            "sensitive to noise and to unmodelled components",
            LineResolutionWarning,
            stacklevel=2,
        )

    import scipy.linalg  # lazily: CLI start-up

    with _one_blas_thread():
        try:
            cho = scipy.linalg.cho_factor(gn, check_finite=False)
        except np.linalg.LinAlgError as exc:  # only for max_condition set near 1e8 or above
            raise ValueError(f"the lines cannot be separated numerically ({exc})") from None

        def solve(rhs: FloatArray) -> FloatArray:
            return np.asarray(scipy.linalg.cho_solve(cho, (rhs / d).T, check_finite=False)).T / d

        coef = solve(project(xs))
        # the residual is formed in place in the synthesised array: one record-sized array
        resid = synth(coef)
        np.subtract(xs, resid, out=resid)
        coef = coef + solve(project(resid))  # one step of iterative refinement
        del resid
        resid = synth(coef)
        np.subtract(xs, resid, out=resid)
    np.square(resid, out=resid)
    residual_rms = np.sqrt(np.mean(resid, axis=1))

    off = int(constant)
    a = coef[:, off : off + m]
    b = coef[:, off + m :]
    # Refer phases to t = 0: cos(w tau) with tau = t - t0.
    phase = np.arctan2(-b, a) - omega * t[0]
    phase = np.angle(np.exp(1j * phase))
    amp = np.hypot(a, b)
    const = coef[:, 0] if constant else np.zeros(coef.shape[0])
    return Lines(
        frequencies=f.copy(),
        amplitude=amp.reshape(*lead, m),
        phase=phase.reshape(*lead, m),
        constant=const.reshape(lead),
        residual_rms=residual_rms.reshape(lead),
        condition_number=cond,
    )


# --------------------------------------------------------------------------------------------
# RRO / NRRO
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class RroNrro:
    """Repeatable (RRO) and non-repeatable (NRRO) parts of a synchronously sampled waveform.

    Attributes
    ----------
    rro : ndarray, shape (..., samples_per_rev)
        Synchronous average: the mean over revolutions at each angular position (it keeps the
        signal's mean value) [signal unit].
    nrro : ndarray, shape (..., n)
        Signal minus the RRO repeated over every revolution [signal unit].
    n_revolutions : int
        Number of revolutions averaged.
    """

    rro: FloatArray
    nrro: FloatArray
    n_revolutions: int

    @property
    def rro_waveform(self) -> FloatArray:
        """RRO repeated over the whole record, same shape as ``nrro`` [signal unit]."""
        return np.tile(self.rro, (1,) * (self.rro.ndim - 1) + (self.n_revolutions,))

    @property
    def rro_pp(self) -> FloatArray:
        """Max minus min of the RRO over one revolution [signal unit]."""
        return np.ptp(self.rro, axis=-1)

    @property
    def nrro_pp(self) -> FloatArray:
        """Max minus min of the NRRO waveform over the whole record [signal unit]."""
        return np.ptp(self.nrro, axis=-1)

    @property
    def nrro_pp_per_angle(self) -> FloatArray:
        """Largest spread (max - min over revolutions) found at any one angular position.

        This is the width of the band the NRRO occupies when every revolution is overlaid on
        one polar plot, the usual reading of a spindle NRRO test [signal unit].
        """
        spr = self.rro.shape[-1]
        folded = self.nrro.reshape(*self.nrro.shape[:-1], self.n_revolutions, spr)
        return np.max(np.ptp(folded, axis=-2), axis=-1)


def separate_rro_nrro(signal: ArrayLike, samples_per_rev: int, *, axis: int = -1) -> RroNrro:
    r"""Split a synchronously sampled waveform into RRO and NRRO.

    The signal must be sampled at ``samples_per_rev`` equally spaced angular positions of the
    rotating ring over an integer number :math:`N \ge 2` of revolutions. The RRO is the
    synchronous average :math:`r_i = \frac1N \sum_{k=0}^{N-1} x_{i + k\,s}` (``s`` samples per
    revolution), the component that repeats every revolution; the NRRO is everything else,
    :math:`x - r` with :math:`r` repeated. By construction ``rro_waveform + nrro == signal``.

    Lines at integer orders end up in the RRO. Lines at non-integer orders are attenuated in
    the average but not removed entirely for a short record (by a factor of order
    :math:`1/(N \cdot \mathrm{dist}(\text{order}, \mathbb Z))`), so a few revolutions give a
    biased RRO; use :func:`separate_rro_nrro_lines` on fitted lines for an exact split.

    Parameters
    ----------
    signal : array_like
        Samples [any unit], sample axis ``axis``; other axes are channels.
    samples_per_rev : int
        Samples per revolution of the rotating ring (>= 2).
    axis : int
        Sample axis of ``signal``.

    Returns
    -------
    RroNrro
    """
    spr = _check_samples_per_rev(samples_per_rev)
    x = _as_signal(signal, axis)
    n = x.shape[-1]
    if n % spr:
        raise ValueError(
            f"the record ({n} samples) is not an integer number of revolutions of "
            f"{spr} samples ({n / spr:.4g} revolutions)"
        )
    n_rev = n // spr
    if n_rev < 2:
        raise ValueError(f"RRO/NRRO separation needs at least 2 revolutions, got {n_rev}")
    folded = x.reshape(*x.shape[:-1], n_rev, spr)
    rro = folded.mean(axis=-2)
    nrro = (folded - rro[..., None, :]).reshape(x.shape)
    return RroNrro(rro=rro, nrro=nrro, n_revolutions=n_rev)


@dataclass(frozen=True, eq=False)
class LineRunout:
    """Lines classified as repeatable (integer order) or non-repeatable, with p-p bounds.

    Attributes
    ----------
    orders : ndarray, shape (m,)
        Line orders [-].
    is_rro : ndarray of bool, shape (m,)
        True where the order is an integer within the tolerance.
    rro_pp_sum, nrro_pp_sum : ndarray, shape (...)
        Sum of the lines' p-p values: the largest p-p the waveform can reach, when all peaks
        align (an upper bound) [signal unit].
    rro_pp_rss, nrro_pp_rss : ndarray, shape (...)
        Root sum of squares of the lines' p-p values: a typical value for lines of unrelated
        phase (``2 sqrt(2)`` times the rms of the sum) [signal unit].
    """

    orders: FloatArray
    is_rro: npt.NDArray[np.bool_]
    rro_pp_sum: FloatArray
    rro_pp_rss: FloatArray
    nrro_pp_sum: FloatArray
    nrro_pp_rss: FloatArray


def separate_rro_nrro_lines(
    frequencies: ArrayLike,
    amplitudes: ArrayLike,
    rotation_hz: float,
    *,
    tol: float = 1e-6,
) -> LineRunout:
    """Classify lines as RRO (integer order) or NRRO (any other order) and bound their p-p.

    A line whose order ``f / rotation_hz`` lies within ``tol`` of a non-zero integer repeats
    every revolution of the rotating ring and is RRO; every other line is NRRO. The p-p of a
    line is twice its amplitude; the p-p of a sum of lines is at most the sum of their p-p
    (reached when the peaks coincide) and, for unrelated phases, typically near the root sum
    of squares.

    Parameters
    ----------
    frequencies : array_like, shape (m,)
        Line frequencies [Hz] (sign ignored; none may be 0).
    amplitudes : array_like, shape (..., m)
        Zero-to-peak amplitudes [signal unit].
    rotation_hz : float
        Rotation frequency of the rotating ring [Hz].
    tol : float
        Absolute tolerance on the order [-]. A record of ``N`` revolutions cannot tell
        orders closer than about ``1/N`` apart, so keep ``tol`` well below that.

    Returns
    -------
    LineRunout
    """
    f = np.abs(np.asarray(frequencies, dtype=float))
    amp = np.asarray(amplitudes, dtype=float)
    if f.ndim != 1 or amp.shape[-1:] != f.shape:
        raise ValueError(
            f"amplitudes (shape {amp.shape}) must end with the frequencies' length {f.size}"
        )
    if not (np.all(np.isfinite(f)) and np.all(np.isfinite(amp))):
        raise ValueError("frequencies and amplitudes must be finite")
    if np.any(amp < 0):
        raise ValueError("amplitudes must be >= 0 (zero-to-peak)")
    if not (math.isfinite(tol) and 0 <= tol < 0.5):
        raise ValueError(f"tol must lie in [0, 0.5), got {tol!r}")
    o = orders(f, rotation_hz)
    if np.any(o <= tol):
        raise ValueError(
            "a line at 0 Hz (order 0) is an offset, not runout; remove it before classifying"
        )
    is_rro = np.abs(o - np.rint(o)) <= tol
    pp = 2.0 * amp
    zero = np.zeros_like(pp)
    rro = np.where(is_rro, pp, zero)
    nrro = np.where(is_rro, zero, pp)
    return LineRunout(
        orders=o,
        is_rro=is_rro,
        rro_pp_sum=rro.sum(axis=-1),
        rro_pp_rss=np.sqrt((rro**2).sum(axis=-1)),
        nrro_pp_sum=nrro.sum(axis=-1),
        nrro_pp_rss=np.sqrt((nrro**2).sum(axis=-1)),
    )


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
