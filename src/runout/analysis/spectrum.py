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

import math
import warnings
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
from numpy.typing import ArrayLike

from runout.analysis._bands import (
    ANDERON_BANDS,
    ANDERON_BANDS_PRINTED,
    ISO15242_BANDS,
    Band,
    BandSet,
    BandValues,
    anderon_bands_from_lines,
    anderon_bands_from_waveform,
    iso15242_band_set,
    iso15242_bands_from_lines,
    iso15242_bands_from_waveform,
)
from runout.analysis._line_kernels import (
    _gram_numpy,
    _gram_uniform,
    _project_numpy,
    _project_uniform_kernel,
    _synthesize_numpy,
)
from runout.analysis._line_kernels import (
    # runout.analysis.decompose's synthesis
    _synthesize_uniform_kernel as _synthesize_uniform_kernel,
)
from runout.analysis._signal import (
    MICROINCH,
    _as_signal,
    _as_time,
    _check_positive,
    _check_samples_per_rev,
    _uniform_step,
    orders,
    to_peak_to_peak,
    to_zero_to_peak,
)
from runout.analysis._signal import _window as _window
from runout.base._threads import one_blas_thread as _one_blas_thread

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


class LineResolutionWarning(UserWarning):
    """Two requested line frequencies (or one and DC) are closer than 1 / record length.

    The least-squares fit still returns the exact answer for a noise-free signal made of those
    lines only, but the separation of the close lines is sensitive to noise and to any
    component not in the model.
    """


# --------------------------------------------------------------------------------------------
# Amplitude spectrum
# --------------------------------------------------------------------------------------------
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
        """Bin frequencies as orders of ``rotation_hz`` [-] (waves per revolution).

        Parameters
        ----------
        rotation_hz : float
            Rotation frequency of the rotating ring [Hz] (> 0).

        Returns
        -------
        ndarray
            Orders [-], same shape as :attr:`frequencies`.
        """
        return orders(self.frequencies, rotation_hz)

    def channel(self, index: int | tuple[int, ...]) -> Spectrum:
        """The spectrum of one channel of a multi-channel (N-D) spectrum.

        Parameters
        ----------
        index : int or tuple of int
            Index of the channel along the leading axes of :attr:`amplitude`.

        Returns
        -------
        Spectrum
            Same frequencies [Hz], window and sampling; the channel's amplitude [signal unit].
        """
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

    Notes
    -----
    The p-p reading (twice the single-sided value of the Hann-windowed record) is the convention
    of seed 000: Tada, "Three-dimensional analysis of non-repeatable runout (NRRO) in ball
    bearings", Koyo Engineering Journal (2002), §2.2.
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
        """Line frequencies as orders of ``rotation_hz`` [-].

        Parameters
        ----------
        rotation_hz : float
            Rotation frequency of the rotating ring [Hz] (> 0).

        Returns
        -------
        ndarray
            Orders [-], same shape as :attr:`frequencies`.
        """
        return orders(self.frequencies, rotation_hz)

    def evaluate(self, time: ArrayLike) -> FloatArray:
        """The fitted model at ``time`` [s]; shape ``amplitude.shape[:-1] + (len(time),)``.

        Parameters
        ----------
        time : array_like, shape (n,)
            Instants [s], on the time axis of :func:`extract_lines`.

        Returns
        -------
        ndarray
            c + Σ_j A_j cos(2π f_j t + φ_j) at each instant [signal unit], shape
            ``amplitude.shape[:-1] + (n,)``.
        """
        t = np.asarray(time, dtype=float)
        ph = 2.0 * np.pi * np.multiply.outer(t, self.frequencies)  # (n, m)
        terms = self.amplitude[..., None, :] * np.cos(ph + self.phase[..., None, :])
        return np.asarray(terms.sum(axis=-1) + self.constant[..., None])


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
    :math:`M^T M` is computed in closed form from Dirichlet sums and :math:`M^T x` by matrix
    products of blocks of 256 samples with one table of phasors (BLAS), so the cost is
    O(n m + m^3) and memory O(n + m^2); non-uniform samples use a chunked O(n m^2) NumPy path.

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
