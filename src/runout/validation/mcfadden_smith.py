r"""McFadden & Smith's envelope spectrum of an inner-race defect against the dynamic model's.

P. D. McFadden and J. D. Smith, "Model for the vibration produced by a single point defect in a
rolling element bearing", Journal of Sound and Vibration 96(1), 69-82 (1984): the
defect on the inner race strikes a ball at the inner-race ball-pass frequency :math:`f_d`
(BPFI); each impulse's amplitude follows the load the defect carries through the load zone as
it turns with the shaft at :math:`f_s`, the Stribeck form

.. math:: q(\theta) = q_0 \left[1 - \frac{1}{2\varepsilon}(1 - \cos\theta)\right]^n ,
   \qquad n = 3/2 \text{ (balls)},

(0 where the bracket is negative); each impulse rings a resonance that decays exponentially.
The demodulated spectrum is then the impulse comb convolved with the line spectrum of the
modulation and multiplied by the spectrum of the decay: lines at :math:`i f_d + l f_s` of
relative amplitude :math:`A_l\,|E(i f_d + l f_s)|`, :math:`A_l` the Fourier coefficients of the
modulation and :math:`E(f) = 1/(\beta + 2\pi i f)` the decay's. Their transmission-path term (the
path from a moving defect to a fixed transducer) is not in this module: runout's housing sees
the total force on the outer ring along the measuring direction.

runout's envelope spectrum is the *squared* envelope's (Randall and Antoni 2011), so the
modulation of its lines is :math:`q^2` and the decay rate of a squared ring is
:math:`\beta = 2\zeta\omega_n`. :func:`predicted_lines` evaluates the model; :func:`measured_lines`
reads the same lines from an acceleration record; :func:`checks` compares them on the CWRU 6205
with an inner-raceway spall under a pure radial load (zero clearance: ε = 1/2 from runout's
static solution, :func:`load_zone_parameter`).

Only the paper's abstract and first page were reachable when this was written: the model here
is the one its abstract names (geometry, speed, load distribution, transfer function,
exponential decay) in the form summarised above, and no number printed in its figures is
reproduced.
"""

from __future__ import annotations

import functools
import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from runout.validation.core import Check, bind

__all__ = [
    "BAND_HZ",
    "CHAIN_INTRO",
    "CHAIN_RTOL",
    "INTRO",
    "SECTION_INTRO",
    "SIDEBAND_RTOL",
    "chain_checks",
    "checks",
    "impact_centroid_deg",
    "load_distribution",
    "load_zone_parameter",
    "measured_lines",
    "model_record",
    "modulation_coefficients",
    "predicted_lines",
]

FloatArray = NDArray[np.float64]

#: The envelope band of the comparison: around the 3 kHz housing mode the impacts ring [Hz].
BAND_HZ = (2000.0, 4000.0)
#: Relative tolerance of a sideband over its carrier: the agreement asked of the model's
#: Stribeck modulation (a judgement; the rows show the measured gaps).
SIDEBAND_RTOL = 0.15
#: Relative tolerance of the model's lines read back through runout's housing and envelope:
#: the envelope band (2-4 kHz) truncates the spectrum of each ring, which lowers 2 x BPFI by
#: 1.1 % and moves the sidebands by up to 0.7 % (measured; 0.1 % with a 0.5-5.9 kHz band, and
#: the same with 8 or 32 times oversampling of the impulses).
CHAIN_RTOL = 0.02
#: The chain's case: CWRU's BPFI ratio, the shaft at 1797 rpm, the examples' housing mode.
_CHAIN = {
    "shaft_hz": 1797.0 / 60.0,
    "bpfi_ratio": 5.4152,
    "resonance_hz": 3000.0,
    "damping_ratio": 0.05,
    "sample_rate": 12_000.0,
    "duration": 2.0,
}
#: Quadrature points over a shaft revolution (the modulation's coefficients to ~1e-9).
_POINTS = 1 << 14

INTRO = """\
Tests: `tests/cli/test_mcfadden_smith_cli.py`, `tests/unit/validation/test_mcfadden_smith.py`.
P. D. McFadden and J. D. Smith, "Model for the vibration produced by a single point defect in a
rolling element bearing", Journal of Sound and Vibration 96(1), 69-82 (1984): impulses
at the inner-race ball-pass frequency BPFI, their amplitudes following the Stribeck load
distribution q = q0 [1 - (1 - cos θ)/(2ε)]^(3/2) as the defect turns with the shaft, each
ringing a resonance that decays exponentially; the demodulated spectrum has BPFI and its
harmonics with sidebands at ± k × the shaft rate, of relative amplitude the Fourier
coefficients of the modulation times the spectrum of the decay. Only the first page of the
paper's text was reachable: the rows compare runout with that model (the Published column
holds the model's values), not with a number printed in the paper's figures. The case is
`examples/cwru_6205_outer_spall.toml` with the spall (1 mm x 50 um) moved to the inner
raceway, the axial load removed (500 N radial only, zero clearance: runout's static solution
gives ε = 1/2, the half-circle load zone), no noise, the band 2-4 kHz around the 3 kHz housing
mode, 2 s at 12 kHz. The model is evaluated for runout's squared envelope: modulation q^2,
decay rate 2ζω_n of the squared ring. The lines are read from the record by a Hann-windowed
Fourier sum at their exact frequencies (no scalloping). The last row locates the largest
impacts: the envelope's peak of each impact against the spall's angle past the radial load's
direction, averaged with the impacts' amplitudes as weights over ±90°; McFadden and Smith's
amplitudes follow q, symmetric about 0. What differs: runout's impulses are the force of a
ball leaving the spall through the rotor on its contacts (not Dirac impulses proportional to
the load), and the housing sees the outer ring's total force along the load direction, with no
separate transmission path.
"""


SECTION_INTRO = """\
P. D. McFadden and J. D. Smith, "Model for the vibration produced by a single point defect in a
rolling element bearing", Journal of Sound and Vibration 96(1), 69-82 (1984), give the
analytic envelope spectrum of an inner-race defect: BPFI and its harmonics, with sidebands at
multiples of the shaft rate whose amplitudes are the Fourier coefficients of the load
distribution times the spectrum of the ring's exponential decay. The first table reproduces
that spectrum with runout's signal chain from the model's own impulses; the second compares
the impulses of runout's dynamic model of a spall with the model's.
"""

CHAIN_INTRO = """\
The model's own impulses, as McFadden and Smith define them (Dirac impulses at BPFI, each of
the amplitude q(θ) of the load the defect carries as it turns with the shaft, ε = 1/2), are
put through runout's signal chain: the housing mode's transfer function of `[sensor]`
(3 kHz, ζ = 0.05, discretised exactly with the impulses 8 times finer than the record),
the sensor's anti-aliased sampling at 12 kHz (2 s), and the squared envelope in the 2-4 kHz
band. The lines read from that record against the model's analytic spectrum (the Published
column): this reproduces the published analytic result with runout's transmission and
envelope analysis, independently of how runout's spall makes its impulses (the section's
second table). The tolerance is the band's: a 2 kHz band truncates each ring's spectrum,
which lowers 2 x BPFI by 1.1 % and moves the sidebands by up to 0.7 %; with a 0.5-5.9 kHz
band every line agrees within 0.2 % (measured, `tests/unit/validation/test_mcfadden_smith.py`).
BPFI is CWRU's 5.4152 x the shaft rate at 1797 rpm.
"""


def model_record(
    epsilon: float,
    defect_hz: float,
    shaft_hz: float,
    *,
    resonance_hz: float,
    damping_ratio: float,
    sample_rate: float,
    duration: float,
    oversample: int = 8,
    n: float = 1.5,
) -> FloatArray:
    r"""McFadden and Smith's impulses through runout's housing mode, sampled as runout samples.

    Parameters
    ----------
    epsilon : float
        Load-zone parameter ε [-].
    defect_hz, shaft_hz : float
        BPFI :math:`f_d` and the shaft rate :math:`f_s` [Hz].
    resonance_hz : float
        The housing mode's natural frequency [Hz].
    damping_ratio : float
        Its ζ [-].
    sample_rate : float
        The record's rate [Hz].
    duration : float
        Its length [s].
    oversample : int
        The impulses are placed on a grid this many times finer than the record (>= 1).
    n : float
        Load-deflection exponent [-].

    Returns
    -------
    ndarray
        The housing's acceleration at ``sample_rate`` [m/s^2 per N s of impulse, unit modal
        mass]: impulses at :math:`t_k = (k + 1/2)/f_d` of area :math:`q(2\pi f_s t_k)/q_0`,
        through :func:`runout.analysis.sensor.housing_acceleration` and
        :func:`runout.analysis.sensor.sample`.

    Notes
    -----
    McFadden and Smith (1984): the defect on the inner race strikes at :math:`f_d`, its
    impulse scaled by the load distribution (:func:`load_distribution`), at the load's
    direction at t = 0. The first impulse is half a period in, so that the record starts at
    rest (the housing model starts at rest under the first force value).
    """
    from runout.analysis.sensor import housing_acceleration, sample

    fine = sample_rate * oversample
    count = round(duration * fine)
    times = (np.arange(int(duration * defect_hz) + 1) + 0.5) / defect_hz
    times = times[times * fine < count - 1]
    force = np.zeros(count)
    # each impulse on its nearest fine instant: a triangle two fine steps wide (the force is
    # linear between instants), of area its amplitude over the step
    np.add.at(
        force,
        np.rint(times * fine).astype(np.int64),
        load_distribution(2.0 * math.pi * shaft_hz * times, epsilon, n) * fine,
    )
    acc = housing_acceleration(force, 1.0 / fine, resonance_hz, damping_ratio, 1.0)
    return sample(acc, oversample)


def load_distribution(theta: ArrayLike, epsilon: float, n: float = 1.5) -> FloatArray:
    r"""Stribeck load distribution relative to its maximum, :math:`q/q_0`.

    Parameters
    ----------
    theta : array_like
        Angle from the direction of the radial load [rad].
    epsilon : float
        Load-zone parameter ε [-] (> 0; 1/2: half the circle loaded, ∞: uniform).
    n : float
        Load-deflection exponent [-]: 3/2 for balls, 10/9 for rollers.

    Returns
    -------
    ndarray
        :math:`[1 - (1 - \cos\theta)/(2\varepsilon)]^n`, 0 where the bracket is negative.

    Notes
    -----
    McFadden and Smith (1984), the load distribution (after Harris, *Rolling Bearing
    Analysis*, the Stribeck form).
    """
    if not epsilon > 0.0:
        raise ValueError(f"epsilon must be > 0, got {epsilon}")
    th = np.asarray(theta, dtype=np.float64)
    if not math.isfinite(epsilon):
        return np.ones_like(th)  # every ball equally loaded
    bracket = 1.0 - (1.0 - np.cos(th)) / (2.0 * epsilon)
    return np.asarray(np.maximum(bracket, 0.0) ** n, dtype=np.float64)


def modulation_coefficients(
    epsilon: float, orders: int = 2, *, n: float = 1.5, power: float = 1.0
) -> FloatArray:
    r"""Fourier coefficients of the modulation :math:`(q/q_0)^p` over a shaft turn, over the mean.

    Parameters
    ----------
    epsilon : float
        Load-zone parameter ε [-].
    orders : int
        Highest order l returned.
    n : float
        Load-deflection exponent [-].
    power : float
        p: 1 for the envelope (McFadden and Smith), 2 for the squared envelope.

    Returns
    -------
    ndarray, shape (orders + 1,)
        :math:`A_l/A_0`, with
        :math:`A_l = \frac{1}{2\pi}\int_{-\pi}^{\pi} (q/q_0)^p\cos(l\theta)\,d\theta`
        (the modulation is even: these are the magnitudes of its two-sided coefficients).

    Notes
    -----
    McFadden and Smith (1984): the Fourier series of the load distribution. Computed
    by the trapezoidal rule on :data:`_POINTS` points (spectral for the smooth part; the kink at
    the edge of the load zone limits it to ~1e-9 relative). At ε = 1/2,
    :math:`A_l/A_0 = \Gamma(1 + a/2)^2 / (\Gamma(1 + (a+l)/2)\,\Gamma(1 + (a-l)/2))` with
    a = n p (the unit tests check it).
    """
    theta = np.linspace(-math.pi, math.pi, _POINTS, endpoint=False)
    m = load_distribution(theta, epsilon, n) ** power
    mean = float(np.mean(m))
    return np.array([float(np.mean(m * np.cos(k * theta))) / mean for k in range(orders + 1)])


def predicted_lines(
    epsilon: float,
    defect_hz: float,
    shaft_hz: float,
    decay_rate: float,
    *,
    harmonics: int = 2,
    orders: int = 2,
    n: float = 1.5,
    power: float = 2.0,
) -> dict[tuple[int, int], float]:
    r"""McFadden and Smith's demodulated line spectrum, relative to the BPFI line.

    Parameters
    ----------
    epsilon : float
        Load-zone parameter ε [-].
    defect_hz, shaft_hz : float
        BPFI :math:`f_d` and the shaft rate :math:`f_s` [Hz].
    decay_rate : float
        β of the envelope's decay :math:`e^{-\beta t}` [1/s] (2ζω_n for a squared ring).
    harmonics, orders : int
        Lines i = 0..harmonics, l = -orders..orders (i = 0: only l > 0).
    n : float
        Load-deflection exponent [-].
    power : float
        Of the modulation (2: squared envelope).

    Returns
    -------
    dict of (int, int) to float
        Amplitude of the line at :math:`i f_d + l f_s` over that of :math:`f_d`:
        :math:`A_{|l|}|E(i f_d + l f_s)| / (A_0 |E(f_d)|)`, with
        :math:`|E(f)| = 1/\sqrt{\beta^2 + (2\pi f)^2}`.

    Notes
    -----
    McFadden and Smith (1984): the spectrum of the impulses (a comb at :math:`f_d`)
    convolved with that of the modulation (lines at :math:`l f_s`), times that of the
    exponential decay. The combs of different i do not overlap for the orders used here when
    :math:`f_d/f_s` is not an integer within :math:`2 \cdot` ``orders`` / ``harmonics``.
    """
    a = modulation_coefficients(epsilon, orders, n=n, power=power)

    def e(f: float) -> float:
        return 1.0 / math.hypot(decay_rate, 2.0 * math.pi * f)

    ref = a[0] * e(defect_hz)
    lines = _lines(defect_hz, shaft_hz, harmonics, orders)
    return {(i, side): float(a[abs(side)] * e(f) / ref) for (i, side), f in lines.items()}


def _lines(
    defect_hz: float, shaft_hz: float, harmonics: int, orders: int
) -> dict[tuple[int, int], float]:
    """Frequency [Hz] of each line i f_d + l f_s (i = 0 ... harmonics, |l| <= orders) above
    zero, the shaft-rate lines of i = 0 counted once (l > 0)."""
    out: dict[tuple[int, int], float] = {}
    for i in range(harmonics + 1):
        for side in range(-orders, orders + 1):
            f = i * defect_hz + side * shaft_hz
            if (i, side) != (0, 0) and not (i == 0 and side < 0) and f > 0.0:
                out[(i, side)] = f
    return out


def measured_lines(
    acceleration: ArrayLike,
    sample_rate: float,
    defect_hz: float,
    shaft_hz: float,
    *,
    band: tuple[float, float] = BAND_HZ,
    harmonics: int = 2,
    orders: int = 2,
) -> dict[tuple[int, int], float]:
    """The same lines in a record's squared envelope spectrum, relative to the BPFI line.

    Parameters
    ----------
    acceleration : array_like
        The record [m/s^2].
    sample_rate : float
        [Hz].
    defect_hz, shaft_hz : float
        [Hz].
    band : (float, float)
        Envelope band [Hz].
    harmonics, orders : int
        As :func:`predicted_lines`.

    Returns
    -------
    dict of (int, int) to float
        Amplitude of the squared envelope at each :math:`i f_d + l f_s` over that at
        :math:`f_d`: Hann-windowed Fourier sums at the exact frequencies, so that a line
        between two bins loses nothing (the run's JSON peaks are bin values).
    """
    from runout.analysis.envelope import complex_envelope

    x = np.asarray(acceleration, dtype=np.float64)
    duration = x.size / sample_rate
    sq = np.abs(complex_envelope(x, sample_rate, band)) ** 2
    sq = sq - sq.mean()
    t = np.arange(sq.size) * duration / sq.size
    w = np.hanning(sq.size)

    def amp(f: float) -> float:
        return float(abs(np.sum(w * sq * np.exp(-2j * math.pi * f * t))))

    ref = amp(defect_hz)
    lines = _lines(defect_hz, shaft_hz, harmonics, orders)
    return {key: amp(f) / ref for key, f in lines.items()}


def impact_centroid_deg(
    acceleration: ArrayLike,
    sample_rate: float,
    defect_hz: float,
    shaft_hz: float,
    *,
    band: tuple[float, float] = BAND_HZ,
) -> float:
    """Angle of the largest impacts past the radial load's direction [deg].

    Parameters
    ----------
    acceleration : array_like
        The record [m/s^2]; the spall at the load's direction at t = 0, turning with the shaft.
    sample_rate, defect_hz, shaft_hz : float
        [Hz].
    band : (float, float)
        Envelope band [Hz].

    Returns
    -------
    float
        The envelope's largest value in each BPFI period (its impact), at the spall's angle
        :math:`2\\pi f_s t` then; the mean of those angles within ±90° weighted by the values.
        0 for amplitudes symmetric about the load's direction (McFadden and Smith's q).
    """
    from runout.analysis.envelope import complex_envelope

    x = np.asarray(acceleration, dtype=np.float64)
    env = np.abs(complex_envelope(x, sample_rate, band))
    t = np.arange(env.size) * (x.size / sample_rate) / env.size
    period = np.floor(t * defect_hz).astype(np.int64)
    angles, values = [], []
    for k in range(1, int(period[-1])):  # whole periods only
        sel = np.flatnonzero(period == k)
        j = sel[int(np.argmax(env[sel]))]
        angles.append(math.remainder(2.0 * math.pi * shaft_hz * t[j], 2.0 * math.pi))
        values.append(env[j])
    th, v = np.array(angles), np.array(values)
    zone = np.abs(th) < 0.5 * math.pi
    return math.degrees(float(np.sum(th[zone] * v[zone]) / np.sum(v[zone])))


def load_zone_parameter(radial_clearance: float, radial_displacement: float) -> float:
    r"""ε of a radially loaded bearing from its clearance and the rings' radial displacement.

    Parameters
    ----------
    radial_clearance : float
        Diametral clearance :math:`P_d` [m].
    radial_displacement : float
        :math:`\delta_r` [m] (> 0).

    Returns
    -------
    float
        :math:`\varepsilon = \frac12 (1 - P_d / (2\delta_r))`.

    Notes
    -----
    Harris, *Rolling Bearing Analysis*: the ball on the line of the load is compressed by
    :math:`\delta_r - P_d/2`, the one at θ by :math:`\delta_r\cos\theta - P_d/2`.
    """
    return 0.5 * (1.0 - radial_clearance / (2.0 * radial_displacement))


def case(**changes: Any) -> Any:
    """The compared case: the CWRU outer-spall example with the spall on the inner raceway.

    Parameters
    ----------
    **changes
        Further ``"table.key"`` values (the tests shorten the record).

    Returns
    -------
    runout.case.model.Case
    """
    from runout.validation.defects import _variant

    keys: dict[str, Any] = {
        "operation.axial_load": "0 N",
        "sensor.noise": 0.0,
        "sensor.band": [f"{BAND_HZ[0]:g} Hz", f"{BAND_HZ[1]:g} Hz"],
    }
    keys.update(changes)
    return _variant("inner", **keys)


@functools.cache
def _compared() -> tuple[dict[tuple[int, int], float], dict[tuple[int, int], float], float, float]:
    """(measured lines, predicted lines, runout's ε, impact centroid [deg]) of :func:`case`."""
    from runout.runner import run_model

    c = case()
    result = run_model(c)
    sig = result.signal
    rate = float(sig.sample_rate_hz)
    fr = result.frequencies
    doc = result.to_json()
    eps = load_zone_parameter(
        float(c.bearing.radial_clearance or 0.0), float(np.hypot(*doc["static_displacement_m"]))
    )
    sensor = doc["signal"]["sensor"]
    beta = 2.0 * sensor["damping_ratio"] * 2.0 * math.pi * sensor["resonance_hz"]
    fd, fs = fr.ball_pass_inner, fr.rotation
    meas = measured_lines(sig.acceleration, rate, fd, fs)
    pred = predicted_lines(eps, fd, fs, beta)
    return meas, pred, eps, impact_centroid_deg(sig.acceleration, rate, fd, fs)


@functools.cache
def _chain() -> tuple[dict[tuple[int, int], float], dict[tuple[int, int], float]]:
    """(lines read from :func:`model_record`, the model's lines) on the chain's case."""
    c = _CHAIN
    fs = c["shaft_hz"]
    fd = c["bpfi_ratio"] * fs
    record = model_record(
        0.5,
        fd,
        fs,
        resonance_hz=c["resonance_hz"],
        damping_ratio=c["damping_ratio"],
        sample_rate=c["sample_rate"],
        duration=c["duration"],
    )
    beta = 2.0 * c["damping_ratio"] * 2.0 * math.pi * c["resonance_hz"]
    return measured_lines(record, c["sample_rate"], fd, fs), predicted_lines(0.5, fd, fs, beta)


def _chain_line(which: str, i: int, side: int, over: int) -> float:
    """The chain's line (i, side) over line (over, 0): read back, or the model's."""
    meas, pred = _chain()
    lines = meas if which == "ours" else pred
    return lines[(i, side)] / lines[(over, 0)]


def chain_checks() -> list[Check]:
    """The rows of the analytic spectrum reproduced through runout's housing and envelope.

    Returns
    -------
    list of Check
        2 x BPFI over BPFI, and the sidebands at ± the shaft rate and ± twice it about BPFI
        and 2 x BPFI over their carrier: read from :func:`model_record` by
        :func:`measured_lines`, against :func:`predicted_lines`.

    Notes
    -----
    P. D. McFadden and J. D. Smith, J. Sound Vib. 96(1), 69-82 (1984).
    """
    src = "McFadden & Smith 1984, their impulses (ε = 1/2) through runout's housing and envelope"
    reason = "band truncation of each ring (see above)"
    first = [
        Check(
            src,
            "2xBPFI / BPFI [-]",
            _chain_line("model", 2, 0, 1),
            bind(_chain_line, "ours", 2, 0, 1),
            "rel",
            CHAIN_RTOL,
            reason=reason,
            digits=4,
        )
    ]
    return first + _sideband_rows(src, _chain_sideband, CHAIN_RTOL, reason, digits=4)


def _chain_sideband(which: str, i: int, side: int) -> float:
    """The chain's sideband (i, side) over its carrier (i, 0)."""
    return _chain_line(which, i, side, i)


def _sideband_rows(
    src: str,
    value: Any,
    rtol: float,
    reason: str,
    *,
    case: str | None = None,
    digits: int = 3,
) -> list[Check]:
    """Rows of the sidebands at ± once and twice the shaft rate about BPFI and 2 x BPFI, over
    their carrier: ``value(which, i, side)``, which "model" (Published) or "ours"."""
    rows = []
    for i in (1, 2):
        carrier = "BPFI" if i == 1 else "2xBPFI"
        for side in (-1, 1, -2, 2):
            label = f"{carrier}{'+' if side > 0 else '-'}{'' if abs(side) == 1 else '2'}fr"
            rows.append(
                Check(
                    src,
                    f"{label} / {carrier} [-]",
                    value("model", i, side),
                    bind(value, "ours", i, side),
                    "rel",
                    rtol,
                    reason=reason,
                    case=case,
                    digits=digits,
                )
            )
    return rows


def _line(which: str, i: int, side: int) -> float:
    """A line over its carrier (the i-th harmonic of BPFI), ours or the model's."""
    meas, pred, _, _ = _compared()
    lines = meas if which == "ours" else pred
    return lines[(i, side)] / lines[(i, 0)]


def _asymmetry(which: str, i: int) -> float:
    return _line(which, i, -1) / _line(which, i, 1)


def _epsilon() -> float:
    return _compared()[2]


def _centroid() -> float:
    return _compared()[3]


def checks() -> list[Check]:
    """The rows of the McFadden & Smith section of VALIDATION.md.

    Returns
    -------
    list of Check
        runout's ε; the sidebands at ± the shaft rate and ± twice it about BPFI and 2 x BPFI,
        relative to their carrier, against the model at runout's ε; the lower-to-upper ratio
        the decay predicts; the angle of the largest impacts.

    Notes
    -----
    P. D. McFadden and J. D. Smith, J. Sound Vib. 96(1), 69-82 (1984).
    """
    from runout.validation.cases import uses

    name = uses("cwru_6205_outer_spall.toml", "an inner-raceway spall against McFadden & Smith")
    src = "McFadden & Smith 1984, CWRU 6205 inner spall, 500 N radial, 1797 rpm"
    rows = [
        Check(
            src,
            "load-zone parameter ε of runout's static solution (zero clearance)",
            0.5,
            _epsilon,
            "abs",
            1e-9,
            reason="—",
            case=name,
        )
    ]
    reason = (
        "runout's impacts (the envelope's peak of each) are weaker than q before the load's "
        "direction (0.46 of the largest at -30°, q: 0.82) and close to q after it (last row): "
        "not the symmetric Stribeck modulation the model assumes"
    )
    rows += _sideband_rows(src, _line, SIDEBAND_RTOL, reason, case=name)
    for i in (1, 2):
        rows.append(
            Check(
                src,
                f"lower / upper first sideband of {'BPFI' if i == 1 else '2xBPFI'} [-]",
                _asymmetry("model", i),
                bind(_asymmetry, "ours", i),
                "rel",
                SIDEBAND_RTOL,
                reason="the model's asymmetry is the exponential decay's alone (2ζω_n); runout's "
                "harmonics fall faster than any exponential decay allows (2xBPFI / BPFI 0.43, "
                "≥ 0.5 for e^(-βt)): its impulses have a duration",
                case=name,
                digits=3,
            )
        )
    rows.append(
        Check(
            src,
            "angle of the largest impacts past the load's direction [deg]",
            0.0,
            _centroid,
            "abs",
            5.0,
            reason="measured, not isolated: the skew depends on where the housing mode "
            "sits against the rotor's contact modes (1.17 and 1.44 kHz, lightly damped), 13.5 deg "
            "at 3 kHz, 0.1 at 4.5 kHz, 8.3 at 6 kHz, -1.7 at 8 kHz, 5.9 at 3 kHz with ten times "
            "the rotor's damping: the rotor ringing after each impact, which the model has not, "
            "is the candidate",
            case=name,
            digits=3,
        )
    )
    return rows
