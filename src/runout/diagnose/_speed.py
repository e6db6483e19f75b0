r"""The record's own speed, for :func:`runout.diagnose.fit`: checked against the case's, and
tracked through a slow drift.

Every line of the linear model (seed 002 eq. 33-40) lies at a fixed multiple (its *order*) of
the rotating ring's speed, so the record's lines carry the speed it was taken at:

* :func:`line_speed` finds the speed ratio that puts the record's strongest spectral peaks on
  the bearing's orders (a coarse check, to a spectral bin: a case at 1234 rpm against a record
  of 1800 rpm is refused, not fitted at the wrong lines);
* :func:`track_speed` follows a slow drift: the shaft angle is taken as
  θ(t) = 2π f_r τ(t) with τ(t) = t + a t' + b t'²/T (t' = t − t₀, T the record's length),
  and (a, b) are fitted with the amplitudes of the strongest lines by variable projection
  (Gauss-Newton on the two nonlinear parameters, the lines' coefficients solved by linear
  least squares at each step). The mean speed is f_r (1 + a + b), the speed changes by
  2b f_r over the record. The lines are then fitted against τ: order tracking without
  resampling (no interpolation error).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "PEAK_FLOOR",
    "PEAK_LEVEL",
    "SPEED_RTOL",
    "LineSpeed",
    "Tracking",
    "line_speed",
    "track_speed",
]

FloatArray = NDArray[np.float64]
TWO_PI = 2.0 * math.pi

#: Largest relative difference between the speed the record's lines give and the speed the
#: diagnosis assumes (the case's, or the tachometer's) that is tracked; beyond it the record
#: is refused. Within it the lines are fitted on the tracked shaft angle.
SPEED_RTOL = 0.02
#: A spectral peak used for the speed stands this many times above the spectrum's median
#: level (white noise's largest bin of 10⁶ stays below 5 times it).
PEAK_LEVEL = 10.0
#: ... and this fraction of the largest peak's amplitude: a noise-free record's median level is
#: its round-off (1e-16 of it), where ripples are no lines.
PEAK_FLOOR = 1e-6
#: Strongest peaks used for the speed check.
MAX_PEAKS = 12
#: Strongest candidate lines the drift is tracked on.
TRACK_LINES = 8
#: Most samples the tracking fits: a longer record is averaged over blocks of q samples (a
#: boxcar, which passes the tracked lines with at least sinc(1/4) = 0.90 of their amplitude,
#: and refers each block to its middle instant).
TRACK_SAMPLES = 1 << 15
#: Speed ratios searched by :func:`line_speed`.
RATIO_RANGE = (0.25, 4.0)
#: Fraction of the peaks' power that must lie on the bearing's lines at a speed before that
#: speed is taken as the record's.
CONVINCING = 0.8
#: A tracked correction is applied when the phase it moves the highest tracked line by
#: exceeds 3 of its standard deviations and this [rad] (below, the lines are fitted on the
#: record's clock and the correction's size joins the phase uncertainty).
NEGLIGIBLE_PHASE = 1e-4


@dataclass(frozen=True)
class LineSpeed:
    """Speed ratio the record's strongest lines give.

    Attributes
    ----------
    ratio : float
        Record speed / assumed speed that puts the most peak power on the bearing's lines [-].
    share_assumed : float
        Fraction of the peaks' power on the bearing's lines at the assumed speed [-].
    share_best : float
        The same at ``ratio`` [-].
    peaks : int
        Peaks used.
    """

    ratio: float
    share_assumed: float
    share_best: float
    peaks: int


@dataclass(frozen=True)
class Tracking:
    """The fitted shaft-angle warp τ(t) = t + a t' + b t'²/T.

    Attributes
    ----------
    a, b : float
        Warp coefficients [-].
    cov : ndarray, shape (2, 2)
        Their covariance [-].
    duration : float
        T [s].
    t0 : float
        First instant [s].
    applied : bool
        Whether the lines are fitted against τ (the correction is significant).
    top_hz : float
        Highest tracked line [Hz].
    lines : int
        Lines tracked.
    """

    a: float
    b: float
    cov: FloatArray
    duration: float
    t0: float
    applied: bool
    top_hz: float
    lines: int

    @property
    def mean_ratio(self) -> float:
        """Mean speed over the record / assumed speed [-]."""
        return 1.0 + self.a + self.b

    @property
    def drift(self) -> float:
        """Change of the speed over the record / assumed speed [-] (end minus start)."""
        return 2.0 * self.b

    def warped(self, time: FloatArray) -> FloatArray:
        """τ(t) [s]: the instant at the assumed speed the shaft reaches θ(t) at."""
        tp = time - self.t0
        return np.asarray(time + self.a * tp + self.b * tp * tp / self.duration)

    def phase_sigma(self, frequency_hz: float) -> float:
        """Standard deviation of a line's phase at t₀ from the warp's uncertainty [rad].

        The fit reads a line's phase where the record's weight is (its middle); an error
        δτ(t) moves the phase at t₀ by the mean of 2π f δτ over the record:
        2π f (δa T/2 + δb T/3).
        """
        g = np.array([0.5 * self.duration, self.duration / 3.0])
        return TWO_PI * frequency_hz * math.sqrt(max(float(g @ self.cov @ g), 0.0))

    def phase_shift(self, frequency_hz: float) -> float:
        """Phase at t₀ the correction moves a line by [rad] (the mean of 2π f (τ − t))."""
        return abs(TWO_PI * frequency_hz * (0.5 * self.a + self.b / 3.0) * self.duration)

    def largest_shift(self, frequency_hz: float) -> float:
        """Largest phase the correction moves a line by anywhere in the record [rad]."""
        us = [1.0]
        if self.b != 0.0 and 0.0 < -self.a / (2.0 * self.b) < 1.0:
            us.append(-self.a / (2.0 * self.b))
        worst = max(abs(self.a * u + self.b * u * u) for u in us)
        return TWO_PI * frequency_hz * worst * self.duration


def _peaks(
    spectra: list[FloatArray], resolution: float, f_lo: float
) -> tuple[FloatArray, FloatArray]:
    """Frequencies [Hz] and powers of the strongest local maxima of the summed power."""
    power = np.sum([a * a for a in spectra], axis=0)
    level = max(float(np.median(power)) * PEAK_LEVEL**2, float(power.max()) * PEAK_FLOOR**2)
    inner = power[1:-1]
    is_peak = (inner > power[:-2]) & (inner >= power[2:]) & (inner > level)
    idx = np.flatnonzero(is_peak) + 1
    idx = idx[idx * resolution > f_lo]
    if idx.size == 0:
        return np.zeros(0), np.zeros(0)
    idx = idx[np.argsort(power[idx])[::-1][:MAX_PEAKS]]
    # the peak's frequency to a fraction of a bin (parabola through the log powers)
    lp = np.log(
        np.maximum(power[np.clip(idx[:, None] + np.arange(-1, 2), 0, power.size - 1)], 1e-300)
    )
    den = lp[:, 0] - 2.0 * lp[:, 1] + lp[:, 2]
    shift = np.where(den < 0.0, 0.5 * (lp[:, 0] - lp[:, 2]) / np.where(den < 0, den, -1.0), 0.0)
    return (idx + np.clip(shift, -0.5, 0.5)) * resolution, power[idx]


def line_speed(
    spectra: list[FloatArray],
    sample_rate: float,
    samples: int,
    orders: FloatArray,
    rotation_hz: float,
) -> LineSpeed | None:
    """Speed ratio that puts the record's strongest peaks on the bearing's orders.

    Parameters
    ----------
    spectra : list of ndarray
        Hann amplitude spectrum of each channel (bins of ``sample_rate / samples``).
    sample_rate : float
        [Hz].
    samples : int
        Record length the spectra are of.
    orders : ndarray
        Orders of the bearing's candidate lines (frequency / speed) [-].
    rotation_hz : float
        The speed assumed [Hz].

    Returns
    -------
    LineSpeed or None
        None when fewer than two peaks stand out (one line fits any speed: some order puts
        it anywhere).

    Notes
    -----
    A peak matches an order o at ratio s when |f − s o f_r| ≤ 1.5 bins. The power matched
    at each ratio is found by sweeping the ratio intervals of every (peak, order) pair; of
    the ratios matching most, the one nearest 1 is returned.
    """
    resolution = sample_rate / samples
    freq, power = _peaks(spectra, resolution, 1.5 * resolution)
    if freq.size < 2:
        return None
    total = float(power.sum())
    o = np.asarray(orders, dtype=np.float64)
    o = o[o > 0.0]
    tol = 1.5 * resolution
    events: list[tuple[float, int, int]] = []  # ratio, +1 open / -1 close, peak
    for j, f in enumerate(freq):
        lo = (f - tol) / (o * rotation_hz)
        hi = (f + tol) / (o * rotation_hz)
        keep = (hi > RATIO_RANGE[0]) & (lo < RATIO_RANGE[1])
        for a, b in zip(lo[keep], hi[keep], strict=True):
            events.append((float(a), 1, j))
            events.append((float(b), -1, j))
    # each peak counts once however many of its orders overlap: a depth per peak
    events.sort(key=lambda e: (e[0], -e[1]))
    depth = np.zeros(freq.size, dtype=np.int64)
    score = 0.0
    best = (-1.0, 1.0, 1.0)  # score, interval start, end
    segments: list[tuple[float, float, float]] = []
    for i, (s, kind, j) in enumerate(events):
        if kind > 0:
            depth[j] += 1
            if depth[j] == 1:
                score += float(power[j])
        else:
            depth[j] -= 1
            if depth[j] == 0:
                score -= float(power[j])
        end = events[i + 1][0] if i + 1 < len(events) else s
        if end > s:
            segments.append((score, s, end))
    assumed = 0.0
    for score_i, s0, s1 in segments:
        if s0 <= 1.0 <= s1:
            assumed = max(assumed, score_i)
    top = max((seg[0] for seg in segments), default=0.0)
    for score_i, s0, s1 in segments:
        if score_i >= top * (1.0 - 1e-12):
            mid = 0.5 * (s0 + s1)
            if best[0] < 0.0 or abs(math.log(mid)) < abs(math.log(0.5 * (best[1] + best[2]))):
                best = (score_i, s0, s1)
    if best[0] <= 0.0:
        return LineSpeed(1.0, assumed / total, 0.0, int(freq.size))
    ratio = 0.5 * (best[1] + best[2])
    if best[1] <= 1.0 <= best[2]:
        ratio = 1.0
    return LineSpeed(ratio, assumed / total, best[0] / total, int(freq.size))


def track_speed(
    time: FloatArray,
    channels: list[FloatArray],
    frequencies: list[float],
    ratio: float = 1.0,
    iterations: int = 30,
) -> Tracking | None:
    """Fit the warp τ(t) on the strongest lines (see the module doc).

    Parameters
    ----------
    time : ndarray
        Instants [s], uniform.
    channels : list of ndarray
        The record's channels [m] or [m/s].
    frequencies : list of float
        Candidate line frequencies at the assumed speed [Hz], strongest first; those closer
        than 1.5/T to a stronger one are skipped (not resolved from it).
    ratio : float
        Starting speed ratio (from :func:`line_speed`).
    iterations : int
        Most Gauss-Newton steps.

    Returns
    -------
    Tracking or None
        None without a line to track.
    """
    n = time.size
    t0 = float(time[0])
    duration = n * float(time[1] - time[0])
    chosen: list[float] = []
    for candidate in frequencies:
        if all(abs(candidate - g) > 1.5 / duration for g in chosen):
            chosen.append(candidate)
        if len(chosen) == TRACK_LINES:
            break
    if not chosen:
        return None
    f = np.asarray(chosen)
    dt = float(time[1] - time[0])
    q = min(math.ceil(n / TRACK_SAMPLES), math.floor(0.25 / (float(f.max()) * dt)))
    if q >= 2:
        n = n // q * q
        time = time[:n].reshape(-1, q).mean(axis=1)
        channels = [c[:n].reshape(-1, q).mean(axis=1) for c in channels]
        n = time.size
    tp = time - t0
    u2 = tp * tp / duration
    data = np.concatenate([c - c.mean() for c in channels])
    scale = float(np.std(data)) or 1.0
    data = data / scale
    m = len(channels)

    def model(p: FloatArray) -> tuple[FloatArray, FloatArray]:
        tau = time + p[0] * tp + p[1] * u2
        arg = TWO_PI * tau[:, None] * f[None, :]
        cos, sin = np.cos(arg), np.sin(arg)
        basis = np.hstack([cos, sin, np.ones((n, 1))])
        # normal equations: the lines are resolved (1.5/T apart), the Gram matrix is benign
        gram = basis.T @ basis
        resid = np.empty_like(data)
        jac = np.empty((data.size, 2))
        for k in range(m):
            y = data[k * n : (k + 1) * n]
            coef = np.linalg.solve(gram, basis.T @ y)
            resid[k * n : (k + 1) * n] = y - basis @ coef
            dfit = sin @ (-coef[: f.size] * TWO_PI * f) + cos @ (
                coef[f.size : 2 * f.size] * TWO_PI * f
            )
            cols = np.column_stack([dfit * tp, dfit * u2])
            # projected on the complement of the lines (variable projection)
            jac[k * n : (k + 1) * n] = cols - basis @ np.linalg.solve(gram, basis.T @ cols)
        return resid, jac

    p = np.array([ratio - 1.0, 0.0])
    resid, jac = model(p)
    cost = float(resid @ resid)
    for _ in range(iterations):
        step, *_ = np.linalg.lstsq(jac, resid, rcond=None)
        if TWO_PI * float(f.max()) * float(np.abs(step).sum()) * duration < 1e-7:
            break  # converged: the step moves no line by more than 1e-7 rad
        moved = False
        for _halving in range(8):
            trial = p + step
            r2, j2 = model(trial)
            c2 = float(r2 @ r2)
            if c2 < cost:
                p, resid, jac, cost = trial, r2, j2, c2
                moved = True
                break
            step = 0.5 * step
        if not moved:
            break
    dof = max(data.size - 2 - m * (2 * f.size + 1), 1)
    sigma2 = cost / dof
    jtj = jac.T @ jac
    try:
        cov = np.asarray(sigma2 * np.linalg.inv(jtj), dtype=np.float64)
    except np.linalg.LinAlgError:
        cov = np.full((2, 2), np.inf)
    tr = Tracking(float(p[0]), float(p[1]), cov, duration, t0, False, float(f.max()), f.size)
    shift = tr.largest_shift(tr.top_hz)
    applied = bool(shift > max(3.0 * tr.phase_sigma(tr.top_hz), NEGLIGIBLE_PHASE))
    return Tracking(tr.a, tr.b, cov, duration, t0, applied, tr.top_hz, f.size)
