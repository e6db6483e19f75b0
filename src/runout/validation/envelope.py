"""Envelope diagnosis (:mod:`runout.diagnose.envelope`) of generated acceleration records.

The records are those of :mod:`runout.validation._envelope_checks` (a McFadden & Smith-style
generator: impacts at the defect period with random slip, each ringing one damped resonance,
load-zone modulation, Gaussian noise) on the CWRU 6205 drive-end bearing; they are not the
CWRU data set. The rows give the defect frequency the diagnosis finds at 1797 rpm against the
data center's published orders, and the detection and false-alarm rates over random defects,
speeds and noise levels.
"""

from __future__ import annotations

import functools

from runout.validation.cases import load, uses
from runout.validation.core import Check, bind

__all__ = ["INTRO", "RATE_RECORDS", "checks"]

#: Defect records, and as many healthy ones, of the rate rows.
RATE_RECORDS = 300
#: The data center's defect orders of the 6205 drive end (per shaft revolution).
PUBLISHED = {"outer": 3.5848, "inner": 5.4152, "ball": 4.7135}

INTRO = """\
Tests: `tests/cli/test_diagnose_envelope_cli.py`, `tests/property/test_envelope_properties.py`,
`tests/unit/validation/test_envelope_validation.py`. `runout diagnose --envelope` reads the
squared-envelope spectrum of an acceleration record in the band the fast kurtogram chooses. The
records here are generated, not measured: impacts at the defect period of the CWRU 6205
drive-end bearing (outer race, inner race or ball), each period scattered by a random slip of
1-2 % (standard deviation), each impact ringing one damped resonance (2-4.5 kHz, damping ratio
0.03-0.1), the impacts' amplitudes following the load zone (a Stribeck-like cos^1.5 half-plane
zone: the inner-race defect turns through it with the shaft, the ball's with the cage), plus
Gaussian noise of 0.5 to 3 times the impacts' rms; 2 s at 12 kHz, 1000-3600 rpm. The healthy
records are Gaussian noise, and smooth vibration (the first 12 shaft harmonics falling as 1/k,
a 3 kHz tone, noise), alternately. The first rows read the defect frequency the diagnosis finds
on one record of each part at 1797 rpm (slip 1 %, noise equal to the impacts' rms) against the
data center's published orders; the rate rows count, over 300 defect and 300 healthy records,
how often the generated part is ranked first and called likely, how often another part is
called likely first, and how often a healthy record has any part called likely (false alarm)
or possible. The thresholds (a harmonic is found at 4 times the local median of the envelope
spectrum; likely with the fundamental found and a score of 24 dB) were set so that no healthy
record of this kind is called defective: 0 of 300 bounds the false-alarm rate below 1 % (95 %
confidence, rule of three).
"""


@functools.cache
def _found(part: str) -> float:
    """Defect order the diagnosis finds (its fundamental's peak) on a generated record."""
    from runout.diagnose.envelope import diagnose_envelope
    from runout.validation._envelope_checks import defect_record

    case = load("cwru_6205_drive_end.toml")
    d = diagnose_envelope(case, defect_record(case, part, noise=1.0, seed=11))  # type: ignore[arg-type]
    first = d.defects[0]
    if first.part != part:
        return float("nan")
    fund = next(e for e in first.lines if e.harmonic == 1 and e.sideband == 0)
    return fund.frequency_hz / d.speed_hz


@functools.cache
def _rates() -> tuple[float, float, float, float, float, float]:
    from runout.validation._envelope_checks import round_trip_rates

    r = round_trip_rates(load("cwru_6205_drive_end.toml"), records=RATE_RECORDS, seed=0)
    return r.detected, r.named, r.wrong, r.false_alarm, r.weak, 0.0


def _rate(i: int) -> float:
    return _rates()[i]


def checks() -> list[Check]:
    """The envelope-diagnosis rows of VALIDATION.md.

    Returns
    -------
    list of Check
        The defect orders found on generated records at 1797 rpm against the CWRU data
        center's, and the detection and false-alarm rates over random records.

    Notes
    -----
    CWRU bearing data center, 6205-2RS JEM SKF drive-end bearing: BPFO 3.5848, BPFI 5.4152,
    ball 4.7135 times the shaft speed.
    """
    name = uses("cwru_6205_drive_end.toml", "`runout diagnose --envelope` of generated records")
    rows: list[Check] = []
    words = {"outer": "BPFO", "inner": "BPFI", "ball": "ball defect (2 x BSF)"}
    for part, order in PUBLISHED.items():
        rows.append(
            Check(
                "CWRU 6205 drive end, generated record, 1797 rpm",
                f"{words[part]} found by the envelope diagnosis [orders]",
                order,
                bind(_found, part),
                "rel",
                0.01,
                reason="the record's slip (1 % per impact, random) moves the line; the "
                "resolution is 0.5 Hz",
                case=name,
            )
        )
    source = f"{RATE_RECORDS} + {RATE_RECORDS} generated records, 1000-3600 rpm"
    for i, quantity, rule, tol, expected, why in (
        (
            0,
            "defect records: generated part first and likely",
            "min",
            0.8,
            "≥ 0.8",
            "measured on the generator above; the noise reaches 3 x the impacts' rms",
        ),
        (
            1,
            "defect records: generated part first (likely or possible)",
            "min",
            0.9,
            "≥ 0.9",
            "the rest show no harmonic above 4 x the local median",
        ),
        (
            2,
            "defect records: another part called likely first",
            "max",
            0.05,
            "≤ 0.05",
            "a defect's harmonics and sidebands can fall in another part's window within the slip "
            "tolerance",
        ),
        (
            3,
            "healthy records: any part called likely (false alarm)",
            "max",
            0.5 / RATE_RECORDS,  # none of them: a share below one record in RATE_RECORDS
            f"0 of {RATE_RECORDS}",
            "the thresholds were chosen for none",
        ),
        (
            4,
            "healthy records: a part called possible",
            "max",
            0.1,
            "≤ 0.1",
            "a noise peak above 4 x the median in one harmonic window: said as not conclusive",
        ),
    ):
        rows.append(
            Check(
                source,
                quantity,
                None,
                bind(_rate, i),
                rule,
                tol,
                expected=expected,
                reason=why,
                case=name,
                digits=3,
            )
        )
    return rows
