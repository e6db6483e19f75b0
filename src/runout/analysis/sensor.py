r"""The accelerometer on the housing: a force through the housing's modes, sampled, with noise.

The bearing's force on the outer ring, F(t) along the measuring direction, excites modes of the
housing, each a mass-spring-damper of modal mass :math:`M_k`, natural frequency
:math:`f_k = \omega_k/2\pi` and damping ratio :math:`\zeta_k`, whose accelerations add at the
sensor (modal superposition):

.. math::
    H(s) = \frac{A(s)}{F(s)} = \sum_k \frac{s^2}{M_k\,(s^2 + 2\zeta_k\omega_k s + \omega_k^2)}

(each term the acceleration response of a single-degree-of-freedom system to force: 0 at DC,
the static load gives no acceleration; :math:`1/M_k` far above its resonance). :math:`M_k` is
the mode's mass over the product of its shape at the bearing and at the sensor, negative where
they have opposite signs. Each term is evaluated exactly for a force linear between the
integration's instants (first-order hold, :func:`scipy.signal.cont2discrete`), the sum is
low-pass filtered and sampled at the sensor's rate (:func:`scipy.signal.resample_poly`, a
polyphase anti-aliasing filter, as a data acquisition system's), and Gaussian noise of a given
fraction of the signal's rms is added.

One mode is the transmission of P. D. McFadden and J. D. Smith, "Model for the vibration
produced by a single point defect in a rolling element bearing", Journal of Sound and Vibration
96(1), 1984 (each impact rings the structure's resonance, an exponentially decaying sinusoid),
here driven by the force history of the dynamic model instead of assumed impulses.

Contents
--------
* :class:`AccelerationSignal` -- the sampled signal, its sensor and its envelope block.
* :class:`HousingMode` -- one mode of the housing.
* :func:`housing_acceleration` -- H(s) applied to a force history.
* :func:`sample` -- anti-aliasing and sampling at the sensor's rate.
* :func:`envelope_block` -- squared-envelope spectrum in the kurtogram's band, labelled peaks.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import asdict, dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from runout.analysis.envelope import (
    MIN_BAND_SAMPLES,
    at_uniform_angle,
    complex_envelope,
    fast_kurtogram,
    spectral_kurtosis,
    squared_envelope_spectrum,
)

__all__ = [
    "ENVELOPE_HARMONICS",
    "ENVELOPE_PEAKS",
    "LABEL_TOLERANCE",
    "AccelerationSignal",
    "HousingMode",
    "envelope_block",
    "housing_acceleration",
    "min_samples",
    "sample",
]

FloatArray = NDArray[np.float64]

#: Harmonics of each defect frequency the envelope band must hold (and the peaks are read to).
ENVELOPE_HARMONICS = 3
#: Largest envelope-spectrum peaks listed.
ENVELOPE_PEAKS = 10
#: Relative tolerance of a peak's label (slip of the rolling elements, 2 %).
LABEL_TOLERANCE = 0.02
_NAMES = {"outer": "BPFO", "inner": "BPFI", "ball": "BDF", "cage": "FTF"}


@dataclass(frozen=True)
class HousingMode:
    """One mode of the housing (``[sensor]`` or a ``[[sensor.modes]]`` entry).

    Attributes
    ----------
    resonance_hz : float
        Natural frequency [Hz].
    damping_ratio : float
        [-], 0 < ζ < 1.
    modal_mass_kg : float
        Modal mass as the bearing's force and the sensor see it [kg] (negative where the mode's
        shape has opposite signs at the two; never 0).
    """

    resonance_hz: float
    damping_ratio: float
    modal_mass_kg: float

    def to_json(self) -> dict[str, float]:
        """``resonance_hz``, ``damping_ratio``, ``modal_mass_kg``.

        Returns
        -------
        dict
            The mode, in the units its keys say.
        """
        return asdict(self)


@dataclass(frozen=True, eq=False)
class AccelerationSignal:
    """A sampled housing acceleration (``[analysis] signal = "acceleration"``).

    Attributes
    ----------
    time : ndarray
        Instants [s] from the start of the record (t = 0 of the run).
    acceleration : ndarray
        Housing acceleration along the measuring direction [m/s^2], noise included.
    rev : ndarray
        Revolutions of the rotating ring since t = 0 (the tachometer) [-].
    sample_rate_hz : float
        [Hz].
    modes : tuple of HousingMode
        The housing's modes (one unless ``[[sensor.modes]]`` gives several).
    noise : float
        Rms of the noise over the signal's rms [-].
    seed : int
        Of the noise, the slip and the speed fluctuation.
    slip : float
        Random slip of the rolling elements (``[sensor] slip``) [-].
    speed_fluctuation : float
        Rms of the shaft speed's relative fluctuation (``[sensor] speed_fluctuation``) [-].
    envelope : dict
        :func:`envelope_block`.
    summary : dict or None
        The JSON ``signal`` of a result read back (:meth:`from_json`: no samples); None for
        a computed signal.
    """

    time: FloatArray
    acceleration: FloatArray
    rev: FloatArray
    sample_rate_hz: float
    modes: tuple[HousingMode, ...]
    noise: float
    seed: int
    slip: float = 0.0
    speed_fluctuation: float = 0.0
    envelope: dict[str, Any] = field(default_factory=dict)
    summary: dict[str, Any] | None = None

    @classmethod
    def from_json(cls, signal: dict[str, Any], envelope: dict[str, Any]) -> AccelerationSignal:
        """A signal read back from a run's JSON ``signal`` and ``envelope`` (no samples).

        Parameters
        ----------
        signal : dict
            The JSON ``signal`` (:meth:`to_json`).
        envelope : dict
            The JSON ``envelope`` (:func:`envelope_block`).

        Returns
        -------
        AccelerationSignal
            Without samples; :meth:`to_json` gives ``signal`` back as it was.
        """
        sensor = signal.get("sensor", {})
        # a result written before the modes list carries its one mode's keys alone
        listed = sensor.get("modes") or [sensor]
        modes = tuple(
            HousingMode(
                float(m.get("resonance_hz", math.nan)),
                float(m.get("damping_ratio", math.nan)),
                float(m.get("modal_mass_kg", math.nan)),
            )
            for m in listed
        )
        empty = np.zeros(0)
        return cls(
            time=empty,
            acceleration=empty,
            rev=empty,
            sample_rate_hz=float(signal["sample_rate_hz"]),
            modes=modes,
            noise=float(sensor.get("noise", math.nan)),
            seed=int(sensor.get("seed", 0)),
            slip=float(sensor.get("slip", 0.0)),
            speed_fluctuation=float(sensor.get("speed_fluctuation", 0.0)),
            envelope=envelope,
            summary=signal,
        )

    def to_json(self) -> dict[str, Any]:
        """``signal`` (the sensor and the record's size) of the run's JSON.

        Returns
        -------
        dict
            ``quantity``, ``sample_rate_hz``, ``samples``, ``duration_s``, ``rms_m_per_s2``
            and ``sensor``: ``modes`` (each ``resonance_hz``, ``damping_ratio``,
            ``modal_mass_kg``), and with one mode its three keys beside them as well;
            ``noise``, ``seed``, ``slip``, ``speed_fluctuation``.
        """
        if self.summary is not None:
            return self.summary
        sensor: dict[str, Any] = {}
        if len(self.modes) == 1:
            sensor.update(self.modes[0].to_json())
        sensor["modes"] = [m.to_json() for m in self.modes]
        sensor.update(
            {
                "noise": self.noise,
                "seed": self.seed,
                "slip": self.slip,
                "speed_fluctuation": self.speed_fluctuation,
            }
        )
        return {
            "quantity": "acceleration",
            "sample_rate_hz": self.sample_rate_hz,
            "samples": int(self.time.size),
            "duration_s": float(self.time.size / self.sample_rate_hz),
            "rms_m_per_s2": float(np.sqrt(np.mean(self.acceleration**2))),
            "sensor": sensor,
        }


def housing_acceleration(
    force: FloatArray,
    step: float,
    resonance: float | Sequence[float],
    damping_ratio: float | Sequence[float],
    modal_mass: float | Sequence[float],
) -> FloatArray:
    r"""Acceleration of the housing's modes driven by a force history [m/s^2].

    Parameters
    ----------
    force : ndarray
        Force on the housing along the measuring direction at instants ``step`` apart [N].
    step : float
        Their spacing [s].
    resonance : float or sequence of float
        Natural frequency :math:`f_k` of each mode [Hz].
    damping_ratio : float or sequence of float
        :math:`\zeta_k` [-], 0 < ζ < 1, one for every mode or one each.
    modal_mass : float or sequence of float
        :math:`M_k` [kg] (nonzero), one for every mode or one each.

    Returns
    -------
    ndarray
        :math:`\ddot x`, the sum of the modes' accelerations, at the same instants [m/s^2],
        from the modes at rest in their static position under the first force (no start-up
        transient from a static load).

    Notes
    -----
    :math:`H(s) = \sum_k s^2 / (M_k(s^2 + 2\zeta_k\omega_k s + \omega_k^2))` (modal
    superposition), each term's state-space form discretised exactly for a force linear between
    instants (first-order hold); one term is the single-resonance transmission of McFadden and
    Smith, "Model for the vibration produced by a single point defect in a rolling element
    bearing", J. Sound Vib. 96(1), 1984.
    """
    from scipy import signal as ss

    fn, zeta, mass = np.broadcast_arrays(
        np.atleast_1d(np.asarray(resonance, dtype=np.float64)),
        np.atleast_1d(np.asarray(damping_ratio, dtype=np.float64)),
        np.atleast_1d(np.asarray(modal_mass, dtype=np.float64)),
    )
    f = np.asarray(force, dtype=np.float64)
    # the static part gives no acceleration (H(0) = 0): start from rest under it
    f = f - f[0]
    out: FloatArray = np.zeros(f.size)
    for fk, zk, mk in zip(fn.tolist(), zeta.tolist(), mass.tolist(), strict=True):
        wn = 2.0 * math.pi * fk
        a = np.array([[0.0, 1.0], [-wn * wn, -2.0 * zk * wn]])
        b = np.array([[0.0], [1.0 / mk]])
        c = np.array([[-wn * wn, -2.0 * zk * wn]])
        d = np.array([[1.0 / mk]])
        ad, bd, cd, dd, _ = ss.cont2discrete((a, b, c, d), step, method="foh")
        num, den = ss.ss2tf(ad, bd, cd, dd)
        num = np.asarray(num, dtype=np.float64).ravel()
        out += np.asarray(ss.lfilter(num, den, f), dtype=np.float64)
    return out


def sample(fine: FloatArray, factor: int) -> FloatArray:
    """Every ``factor``-th value of ``fine`` after a polyphase anti-aliasing low-pass.

    Parameters
    ----------
    fine : ndarray
        A signal at ``factor`` times the sensor's rate.
    factor : int
        >= 1.

    Returns
    -------
    ndarray
        At the sensor's rate, the value at instant i of ``fine[i * factor]`` (zero phase).
    """
    from scipy import signal as ss

    if factor == 1:
        return np.asarray(fine, dtype=np.float64)
    out: FloatArray = np.asarray(ss.resample_poly(fine, 1, factor), dtype=np.float64)
    return out


def _label(
    freq: float, fundamentals: dict[str, float], sidebands: dict[str, float | None], f_r: float
) -> tuple[str | None, str | None, int, int]:
    """Name of the line nearest ``freq``: (label, part, harmonic, sideband)."""
    best: tuple[float, str, str, int, int] | None = None
    for part, fd in fundamentals.items():
        spacing = sidebands.get(part)
        # the cage's own harmonics only up to the third: every line is near some high multiple
        top = ENVELOPE_HARMONICS if part == "cage" else 2 * ENVELOPE_HARMONICS
        for h in range(1, top + 1):
            for side in (0,) if spacing is None else (0, -1, 1, -2, 2):
                expected = h * fd + side * (spacing or 0.0)
                gap = abs(freq - expected)
                if gap > LABEL_TOLERANCE * h * fd:
                    continue
                name = _NAMES[part] if h == 1 else f"{h}x{_NAMES[part]}"
                if side:
                    mod = "FTF" if part == "ball" else "fr"
                    name += ("+" if side > 0 else "-") + (mod if abs(side) == 1 else f"2{mod}")
                key = gap / expected + abs(side)
                if best is None or key < best[0]:
                    best = (key, name, part, h, side)
    if best is not None:
        return best[1], best[2], best[3], best[4]
    h = round(freq / f_r)
    if h >= 1 and abs(freq - h * f_r) <= LABEL_TOLERANCE * h * f_r:
        return ("fr" if h == 1 else f"{h}xfr"), None, h, 0
    return None, None, 0, 0


def envelope_block(
    acceleration: FloatArray,
    sample_rate: float,
    fundamentals: dict[str, float],
    sidebands: dict[str, float | None],
    shaft_hz: float,
    band: tuple[float, float] | None = None,
    angle: FloatArray | None = None,
) -> dict[str, Any]:
    """The run's JSON ``envelope``: band (fast kurtogram or given) and the largest labelled peaks.

    Parameters
    ----------
    acceleration : ndarray
        The signal [m/s^2].
    sample_rate : float
        [Hz].
    fundamentals : dict
        Defect frequency of each part, ``outer``, ``inner``, ``ball`` (2 x ball spin) and
        ``cage`` (FTF: a ball defect's modulation) [Hz].
    sidebands : dict
        Spacing of each part's modulation sidebands [Hz] (None: not modulated).
    shaft_hz : float
        Speed of the rotating ring [Hz] (shaft harmonics are labelled ``fr``, ``2xfr``).
    band : (float, float), optional
        Pass band [Hz] (``[sensor] band``, checked by the case); default the fast kurtogram's.
    angle : ndarray, optional
        The rotating ring's angle at each sample [rev] when its speed varies: the signal is
        order-tracked first (:func:`runout.analysis.envelope.at_uniform_angle`), its lines read
        at their orders times the mean speed, which ``fundamentals`` and ``shaft_hz`` are at.

    Returns
    -------
    dict
        ``band_hz`` [lo, hi], ``band_source`` ("kurtogram" or "given"), ``order_tracked``
        (whether ``angle`` was given), ``spectral_kurtosis`` (of the band's complex envelope),
        ``resolution_hz`` and ``peaks``: largest first, each ``frequency_hz``, ``amplitude``
        [(m/s^2)^2], ``label`` (``"BPFI"``, ``"2xBPFO"``, ``"BPFI+fr"``, ``"BDF-FTF"``,
        ``"FTF"``, ``"3xfr"`` or None: the line the peak is within 2 % of), ``part`` (``outer``,
        ``inner``, ``ball``, ``cage`` or None), ``harmonic`` (0: none) and ``sideband`` (-2 to
        2: the order of the modulation sideband, 0 the harmonic itself).

    Notes
    -----
    J. Antoni, "Fast computation of the kurtogram for the detection of transient faults", MSSP
    21, 2007 (the band); R. B. Randall and J. Antoni, "Rolling element bearing diagnostics — A
    tutorial", MSSP 25, 2011, sec. 5.1 (the squared envelope spectrum).
    """
    if angle is not None:
        time = np.arange(acceleration.size, dtype=np.float64) / sample_rate
        _, acceleration, _ = at_uniform_angle(time, angle, acceleration)
    top = max(f for part, f in fundamentals.items() if part != "cage")
    need = (ENVELOPE_HARMONICS + 1) * top
    width = min(need, 0.25 * sample_rate)
    if band is None:
        # the band lies above the lines it is read at (not around them)
        kurtogram = fast_kurtogram(acceleration, sample_rate, min_bandwidth=width, min_low=width)
        band, source, kurtosis = kurtogram.band_hz, "kurtogram", float(kurtogram.max_kurtosis)
    else:
        source = "given"
        kurtosis = float(spectral_kurtosis(complex_envelope(acceleration, sample_rate, band)))
    spectrum = squared_envelope_spectrum(acceleration, sample_rate, band)
    f, amp = spectrum.frequency, spectrum.amplitude
    reach = (ENVELOPE_HARMONICS + 0.5) * top + shaft_hz
    inner = np.flatnonzero((amp[1:-1] > amp[:-2]) & (amp[1:-1] >= amp[2:]) & (f[1:-1] <= reach))
    keep = inner + 1
    order = keep[np.argsort(amp[keep])[::-1]][:ENVELOPE_PEAKS]
    peaks = []
    for i in order.tolist():
        # parabolic interpolation of the peak between its bins
        y0, y1, y2 = amp[i - 1], amp[i], amp[i + 1]
        den = y0 - 2.0 * y1 + y2
        shift = 0.5 * (y0 - y2) / den if den != 0.0 else 0.0
        freq = float(f[i] + shift * spectrum.resolution_hz)
        label, part, harmonic, side = _label(freq, fundamentals, sidebands, shaft_hz)
        peaks.append(
            {
                "frequency_hz": freq,
                "amplitude": float(amp[i]),
                "label": label,
                "part": part,
                "harmonic": harmonic,
                "sideband": side,
            }
        )
    return {
        "band_hz": [float(band[0]), float(band[1])],
        "band_source": source,
        "order_tracked": angle is not None,
        "spectral_kurtosis": kurtosis,
        "resolution_hz": float(spectrum.resolution_hz),
        "peaks": peaks,
    }


def min_samples() -> int:
    """Fewest samples an envelope block is computed from (the kurtogram's).

    Returns
    -------
    int
        Twice :data:`runout.analysis.envelope.MIN_BAND_SAMPLES`.
    """
    return 2 * MIN_BAND_SAMPLES
