"""How a paper read its spectral lines: a Hann FFT of a finite record plus a constant floor.

Seed 001 (Kim, Choi, Yoon) prints readings of an FFT, not the lines themselves;
:func:`identify_fft_reading` finds the record length and the floor's phase that turn exact
lines into the published readings (:func:`runout.validation.seed001_kim.kim_fft_reading`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["FftReading", "identify_fft_reading"]


@dataclass(frozen=True)
class FftReading:
    """How a paper read its lines: a Hann FFT of a record, plus a constant line (its floor).

    ``read(f, line)`` is what the paper's spectrum shows at its bin nearest ``f`` for a true
    line phasor ``line``: :func:`runout.analysis.spectrum.peak_bin_gain` × |line + floor|.

    Attributes
    ----------
    duration : float
        Record length T [s].
    floor : complex
        Phasor [nm p-p] of a component at the same frequency present in every run, whatever
        the ball errors (what the paper prints for a balanced set).
    misfit : float
        Largest relative misfit over the rows it was identified from [-].
    rows : int
        Number of published values it was identified from.
    """

    duration: float
    floor: complex
    misfit: float
    rows: int

    def read(self, frequency: float, line: complex) -> float:
        """What the paper's spectrum shows at its bin nearest ``frequency`` for a true line.

        Parameters
        ----------
        frequency : float
            Frequency of the line [Hz].
        line : complex
            The true line's phasor [nm p-p].

        Returns
        -------
        float
            :func:`runout.analysis.spectrum.peak_bin_gain` × |line + floor| [nm p-p].
        """
        from runout.analysis.spectrum import peak_bin_gain

        gain = float(peak_bin_gain(frequency, self.duration))
        return gain * abs(line + self.floor)


def identify_fft_reading(
    frequency: np.ndarray,
    line: np.ndarray,
    published: np.ndarray,
    floor_frequency: float,
    floor_reading: float,
) -> FftReading:
    """Record length and floor phase that best turn exact lines into published readings.

    The floor's size is not fitted: it is what the paper prints where the true lines cancel
    (``floor_reading``, read at ``floor_frequency``), so |floor| = floor_reading / G(T). The
    record length T and the floor's phase minimise Σ (read_i / published_i − 1)²: a grid of
    2 ms from 0.25 s to 4 s × 1° (global), then a joint least-squares refinement. Two
    parameters; use it on many more rows than that. Record lengths one period of the line
    apart (≈ 1/f) fit almost equally: what is identified is where each line falls between
    two bins.

    Parameters
    ----------
    frequency : ndarray, shape (m,)
        Frequency of each line [Hz].
    line : ndarray of complex, shape (m,)
        Exact phasor of each line, in the unit of ``published`` (nm p-p for seed 001).
    published : ndarray, shape (m,)
        The paper's reading of each line.
    floor_frequency : float
        Frequency at which the paper prints its floor [Hz].
    floor_reading : float
        The floor's reading there, in the unit of ``published``.

    Returns
    -------
    FftReading
        The record length, the floor phasor, the largest relative misfit and the number of
        rows.
    """
    from scipy.optimize import least_squares

    from runout.analysis.spectrum import peak_bin_gain

    def floor_size(T: float, samples: int = 8192) -> np.ndarray:
        return floor_reading / peak_bin_gain(np.asarray(floor_frequency), T, samples=samples)

    grid = np.arange(0.25, 4.0, 0.002)
    phases = np.radians(np.arange(0.0, 360.0, 1.0))
    gain = np.stack([peak_bin_gain(frequency, T, samples=256) for T in grid])  # (nT, m)
    size = np.array([floor_size(T, 256) for T in grid])  # (nT,)
    floor = size[:, None, None] * np.exp(1j * phases)[None, :, None]  # (nT, nφ, 1)
    read = gain[:, None, :] * np.abs(line[None, None, :] + floor)
    cost = ((read / published - 1.0) ** 2).sum(axis=-1)  # (nT, nφ)

    def residual(p: np.ndarray) -> np.ndarray:
        g = peak_bin_gain(frequency, p[0])
        f = floor_size(p[0]) * np.exp(1j * p[1])
        return np.asarray(g * np.abs(line + f) / published - 1.0)

    best = None
    for flat in np.argsort(cost, axis=None)[:5]:
        i, j = np.unravel_index(flat, cost.shape)
        fit = least_squares(residual, [grid[i], phases[j]], x_scale=[1e-3, 1e-2])
        if best is None or fit.cost < best.cost:
            best = fit
    assert best is not None
    T, phase = best.x
    floor_at = complex(floor_size(T) * np.exp(1j * phase))
    return FftReading(float(T), floor_at, float(np.abs(residual(best.x)).max()), line.size)
