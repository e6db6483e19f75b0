"""Signal-processing helpers of :mod:`runout.analysis.spectrum`: orders, p-p conversions,
input checks and the FFT windows.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt
from numpy.typing import ArrayLike

FloatArray = npt.NDArray[np.float64]


#: One microinch in metres (the length unit of the Anderon, seed 002 eq. 1) [m].
MICROINCH = 25.4e-9

#: Relative tolerance on band edges: a line or bin sitting exactly on an edge shared by two
#: adjacent bands belongs to the upper one, whatever the rounding of the edge.
_EDGE_RTOL = 1e-9


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
# windows
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
