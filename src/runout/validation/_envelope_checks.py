r"""Checks of the envelope diagnosis (:mod:`runout.diagnose.envelope`) on generated records.

A small generator in the style of P. D. McFadden and J. D. Smith, "Model for the vibration
produced by a single point defect in a rolling element bearing", Journal of Sound and Vibration
96(1), 1984: impacts at the defect period, each period scattered by a random slip (1-2 %),
each impact ringing one damped resonance of the housing; the impacts' amplitudes follow the
load the defect sees (a rotating-ring defect passes the load zone once a shaft revolution, a
ball's once a cage revolution; a stationary-ring defect sits in it), plus Gaussian noise. It is
not the Case Western Reserve University data and not a model of the bearing's contacts: it
checks that the diagnosis finds what the generator put in, and measures its detection and
false-alarm rates. The healthy records are Gaussian noise, and smooth vibration (shaft
harmonics, as unbalance and misalignment make) in noise.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
from numpy.typing import NDArray

from runout.diagnose._record import Record, record_from_arrays

__all__ = [
    "CWRU_RPM",
    "CWRU_SAMPLE_RATE",
    "Rates",
    "defect_frequencies",
    "defect_record",
    "healthy_record",
    "round_trip_rates",
]

FloatArray = NDArray[np.float64]
Part = Literal["outer", "inner", "ball"]

#: The CWRU drive-end motor speed at 0 hp [rpm] and the data set's sample rate [Hz].
CWRU_RPM = 1797.0
CWRU_SAMPLE_RATE = 12_000.0


def defect_frequencies(case: Any, rpm: float) -> dict[str, float]:
    """Shaft, cage and defect frequencies of ``case``'s bearing at ``rpm`` [Hz].

    Parameters
    ----------
    case : runout.case.model.Case
        The bearing (its operation's rotating ring is used).
    rpm : float
        Speed of the rotating ring [rpm].

    Returns
    -------
    dict of str to float
        ``shaft``, ``cage``, ``outer`` (BPFO), ``inner`` (BPFI), ``ball`` (2 x ball spin) [Hz].
    """
    import dataclasses

    from runout.geometry.kinematics import bearing_frequencies
    from runout.geometry.loading import operating_contact_angle

    op = case.operation
    scale = rpm / 60.0 / abs(op.speed)
    op = dataclasses.replace(
        op, speed=op.speed * scale, other_ring_speed=op.other_ring_speed * scale
    )
    alpha, _ = operating_contact_angle(case.bearing, op)
    fr = bearing_frequencies(case.bearing, op, alpha)
    return {
        "shaft": fr.rotation,
        "cage": fr.cage,
        "outer": fr.ball_pass_outer,
        "inner": fr.ball_pass_inner,
        "ball": 2.0 * fr.ball_spin,
    }


def _load_zone(angle: FloatArray) -> FloatArray:
    """Relative impact amplitude at ``angle`` [rad] from the load's direction: a half-plane
    load zone with the Stribeck load distribution's 3/2 power, never quite 0 (the preload)."""
    return np.asarray(0.15 + 0.85 * np.maximum(np.cos(angle), 0.0) ** 1.5, dtype=np.float64)


def defect_record(
    case: Any,
    part: Part,
    *,
    rpm: float = CWRU_RPM,
    sample_rate: float = CWRU_SAMPLE_RATE,
    duration: float = 2.0,
    resonance: float = 3000.0,
    damping_ratio: float = 0.05,
    slip: float = 0.01,
    noise: float = 1.0,
    amplitude: float = 10.0,
    seed: int = 0,
) -> Record:
    """An acceleration record of a localized defect on ``part``.

    Parameters
    ----------
    case : runout.case.model.Case
        The bearing (kinematics only).
    part : {"outer", "inner", "ball"}
        The defective part.
    rpm : float
        Shaft speed [rpm].
    sample_rate : float
        [Hz].
    duration : float
        [s].
    resonance : float
        Natural frequency the impacts ring [Hz].
    damping_ratio : float
        Of that resonance [-].
    slip : float
        Standard deviation of each impact period, relative [-].
    noise : float
        Rms of the Gaussian noise over the rms of the impacts' signal [-].
    amplitude : float
        Peak acceleration of an impact at full load [m/s^2].
    seed : int
        Of the random generator.

    Returns
    -------
    Record
        ``quantity="acceleration"``, one channel ``a`` [m/s^2].
    """
    rng = np.random.default_rng(seed)
    freq = defect_frequencies(case, rpm)
    n = round(duration * sample_rate)
    t = np.arange(n) / sample_rate
    period = 1.0 / freq[part]
    count = int(duration / period) + 2
    starts = np.cumsum(period * (1.0 + slip * rng.standard_normal(count)))
    starts = starts - period * rng.uniform(0.0, 1.0) - period
    starts = starts[(starts >= 0.0) & (starts < duration)]
    if part == "inner":  # the defect turns with the shaft through the fixed load zone
        gain = _load_zone(2.0 * math.pi * freq["shaft"] * starts + rng.uniform(0, 2 * math.pi))
    elif part == "ball":  # the ball turns with the cage
        gain = _load_zone(2.0 * math.pi * freq["cage"] * starts + rng.uniform(0, 2 * math.pi))
    else:
        gain = np.ones_like(starts)
    wn = 2.0 * math.pi * resonance
    wd = wn * math.sqrt(1.0 - damping_ratio**2)
    ring = int(8.0 / (damping_ratio * wn) * sample_rate) + 1  # to e^-8 of the first peak
    signal = np.zeros(n + ring)
    first = np.ceil(starts * sample_rate).astype(np.int64)
    offsets = np.arange(ring)
    # each impact's response on the samples after it: a matrix of impacts x ring
    tau = (first[:, None] + offsets[None, :]) / sample_rate - starts[:, None]
    response = gain[:, None] * np.exp(-damping_ratio * wn * tau) * np.sin(wd * tau)
    np.add.at(signal, (first[:, None] + offsets[None, :]).ravel(), response.ravel())
    signal = amplitude * signal[:n]
    rms = float(np.sqrt(np.mean(signal**2)))
    signal = signal + noise * rms * rng.standard_normal(n)
    return record_from_arrays(t, a=signal, quantity="acceleration")


def healthy_record(
    case: Any,
    kind: Literal["noise", "smooth"],
    *,
    rpm: float = CWRU_RPM,
    sample_rate: float = CWRU_SAMPLE_RATE,
    duration: float = 2.0,
    seed: int = 0,
) -> Record:
    """An acceleration record of a healthy bearing.

    Parameters
    ----------
    case : runout.case.model.Case
        Unused but for symmetry with :func:`defect_record` (the speed is ``rpm``).
    kind : {"noise", "smooth"}
        Gaussian white noise of 1 m/s^2 rms; or the first 12 shaft harmonics (1 m/s^2 at
        the shaft speed, falling as 1/k, random phases), a 3 kHz structural tone and that
        noise at half the rms.
    rpm, sample_rate, duration, seed
        As :func:`defect_record`.

    Returns
    -------
    Record
    """
    del case
    rng = np.random.default_rng(seed)
    n = round(duration * sample_rate)
    t = np.arange(n) / sample_rate
    if kind == "noise":
        a = rng.standard_normal(n)
    else:
        f_r = rpm / 60.0
        a = 0.5 * rng.standard_normal(n)
        for k in range(1, 13):
            a += np.cos(2 * math.pi * k * f_r * t + rng.uniform(0, 2 * math.pi)) / k
        a += 0.3 * np.cos(2 * math.pi * 3000.0 * t)
    return record_from_arrays(t, a=a, quantity="acceleration")


@dataclass(frozen=True)
class Rates:
    """Detection and false-alarm rates over generated records.

    Attributes
    ----------
    defective : int
        Defect records diagnosed.
    detected : float
        Share of them whose first-ranked part is the generated one, called likely [-].
    named : float
        Share whose first-ranked part is the generated one (likely or possible) [-].
    wrong : float
        Share called likely with another part first [-].
    healthy : int
        Healthy records diagnosed.
    false_alarm : float
        Share of them with any part called likely [-].
    weak : float
        Share of them with a part called possible [-].
    """

    defective: int
    detected: float
    named: float
    wrong: float
    healthy: int
    false_alarm: float
    weak: float


def round_trip_rates(case: Any, records: int = 60, seed: int = 0) -> Rates:
    """Diagnose random defect and healthy records and count the outcomes.

    Parameters
    ----------
    case : runout.case.model.Case
        The bearing (the CWRU 6205 drive end).
    records : int
        Defect records, and as many healthy ones.
    seed : int
        First seed.

    Returns
    -------
    Rates

    Notes
    -----
    Each defect record draws the part (outer, inner, ball), the speed (1000-3600 rpm), the slip
    (1-2 %), the resonance (2-4.5 kHz), the damping ratio (0.03-0.1) and the noise (0.5 to 3
    times the impacts' rms); 2 s at 12 kHz. Each healthy record is noise or smooth vibration
    (alternately) at a random speed.
    """
    from runout.diagnose.envelope import diagnose_envelope

    rng = np.random.default_rng(seed)
    hits = named = wrong = 0
    for i in range(records):
        part: Part = ("outer", "inner", "ball")[i % 3]
        rpm = float(rng.uniform(1000.0, 3600.0))
        rec = defect_record(
            case,
            part,
            rpm=rpm,
            slip=float(rng.uniform(0.01, 0.02)),
            resonance=float(rng.uniform(2000.0, 4500.0)),
            damping_ratio=float(rng.uniform(0.03, 0.1)),
            noise=float(rng.uniform(0.5, 3.0)),
            seed=seed + 1000 + i,
        )
        d = diagnose_envelope(_at(case, rpm), rec)
        first = d.defects[0]
        if first.part == part and first.assessment == "likely":
            hits += 1
        if first.part == part and first.assessment != "no evidence":
            named += 1
        if first.part != part and first.assessment == "likely":
            wrong += 1
    alarms = weak = 0
    for i in range(records):
        rpm = float(rng.uniform(1000.0, 3600.0))
        kind: Literal["noise", "smooth"] = "noise" if i % 2 == 0 else "smooth"
        rec = healthy_record(case, kind, rpm=rpm, seed=seed + 5000 + i)
        d = diagnose_envelope(_at(case, rpm), rec)
        if any(c.assessment == "likely" for c in d.defects):
            alarms += 1
        if any(c.assessment == "possible" for c in d.defects):
            weak += 1
    return Rates(
        records,
        hits / records,
        named / records,
        wrong / records,
        records,
        alarms / records,
        weak / records,
    )


def _at(case: Any, rpm: float) -> Any:
    """``case`` at ``rpm`` (the diagnosis reads the speed from the case)."""
    import dataclasses

    op = case.operation
    scale = rpm / 60.0 / abs(op.speed)
    op = dataclasses.replace(
        op, speed=op.speed * scale, other_ring_speed=op.other_ring_speed * scale
    )
    return dataclasses.replace(case, operation=op)
