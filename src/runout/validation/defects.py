"""Localized defects in the dynamic model and the acceleration signal they make.

Rows of VALIDATION.md: the largest peak of the envelope spectrum of the signal the dynamic
model makes for a spall on the outer raceway, the inner raceway or a ball of the CWRU 6205
drive-end bearing at 1797 rpm (``examples/cwru_6205_outer_spall.toml``, ``..._inner_spall``,
``..._ball_spall``) against
the data center's published defect orders; and a round trip generator -> diagnosis
(``runout run`` with ``[analysis] signal = "acceleration"``, then
:func:`runout.diagnose.envelope.diagnose_envelope`) over random spalls, speeds and noise levels,
with its detection and false-alarm rates. These are simulations of spalls, not the CWRU data.
"""

from __future__ import annotations

import functools
import math
from typing import Any

import numpy as np

from runout.validation.cases import example_path, uses
from runout.validation.core import Check, bind

__all__ = ["INTRO", "ROUND_TRIP_DEFECTS", "ROUND_TRIP_HEALTHY", "checks", "round_trip"]

EXAMPLE = "cwru_6205_outer_spall.toml"
#: The example of each part's spall (the same case, the spall moved).
EXAMPLES = {
    "outer": EXAMPLE,
    "inner": "cwru_6205_inner_spall.toml",
    "ball": "cwru_6205_ball_spall.toml",
}
#: The data center's defect orders of the 6205 drive end (per shaft revolution).
PUBLISHED = {"outer": 3.5848, "inner": 5.4152, "ball": 4.7135}
#: Defective runs of the round trip (a third per part), and healthy ones.
ROUND_TRIP_DEFECTS = 30
ROUND_TRIP_HEALTHY = 10

INTRO = f"""\
Tests: `tests/cli/test_run_defects.py`, `tests/unit/models/test_dynamic_spall.py`. A
`[[defect]]` spall in the dynamic model drops the contact approach of a ball over it by the
depth its centre reaches, min(depth, D/2 - sqrt(D^2/4 - e^2)) at e from the nearer edge
(Sawalhi and Randall 2008); `[analysis] signal = "acceleration"` passes the bearing's force on
the outer ring through one housing resonance (3 kHz, damping ratio 0.05), samples it at 12 kHz
and adds Gaussian noise. The first rows read the largest peak of the envelope spectrum of that
signal (band of the fast kurtogram) for a 1 mm x 50 um spall on each part of the CWRU 6205
drive-end bearing at 1797 rpm, 500 N radial and 500 N axial load, 2 s, noise 0.5 x the
signal's rms (`examples/cwru_6205_outer_spall.toml`, and the same case with the spall on the
inner raceway or on ball 1), against the data center's published orders; the model's contact
angle under the axial load moves the orders by under 0.6 %. The round trip runs the model on
{ROUND_TRIP_DEFECTS} random spalls (a third on each part; width 0.5-1.5 mm, depth 20-80 um,
anywhere on the ring or on any ball) and {ROUND_TRIP_HEALTHY} healthy bearings at 1200-3000 rpm
(each kind's speeds spread over the range), noise 0.3-1.5 x the signal's rms, a random slip of
1-2 % (`[sensor] slip`: each impact period jitters by about as much), a random slow speed
fluctuation of 0-1 % rms (`[sensor] speed_fluctuation`), 1.5 s each, and diagnoses each signal
with its tachometer (`rev`, so the diagnosis order-tracks) with `runout diagnose --envelope`:
detection is the generated part ranked first and called likely, a false alarm any part called
likely on a healthy bearing. The CWRU records themselves are not read.
"""


def _variant(part: str, **changes: Any) -> Any:
    """The example with its spall on ``part`` (None: healthy) and other keys changed."""
    import tomllib

    from runout.case.model import parse_case

    data = tomllib.loads(example_path(EXAMPLE).read_text(encoding="utf-8"))
    defect: dict[str, Any] = {"width": "1 mm", "depth": "50 um"}
    if part == "ball":
        defect.update(part="ball", element=1)
    elif part in ("outer", "inner"):
        defect.update(part=part, angle="-90 deg")
    for key, value in changes.items():
        table, name = key.split(".")
        if table == "defect":
            defect[name] = value
        else:
            data[table][name] = value
    data["defect"] = [defect] if part in PUBLISHED else []
    return parse_case(data, f"{EXAMPLE} ({part})")


@functools.cache
def _largest(part: str) -> tuple[float, str]:
    """Order and label of the largest envelope peak of the signal of a spall on ``part``."""
    from runout.runner import run_model
    from runout.validation.cases import load

    result = run_model(load(EXAMPLES[part]))
    peak = result.signal.envelope["peaks"][0]
    return peak["frequency_hz"] / result.frequencies.rotation, str(peak["label"])


def _largest_order(part: str) -> float:
    order, label = _largest(part)
    names = {"outer": "BPFO", "inner": "BPFI", "ball": "BDF"}
    return order if label == names[part] else math.nan  # another line: no agreement


@functools.cache
def round_trip(
    defects: int = ROUND_TRIP_DEFECTS, healthy: int = ROUND_TRIP_HEALTHY, seed: int = 0
) -> tuple[float, float, float]:
    """Run the model on random spalls and healthy bearings and diagnose each signal.

    Parameters
    ----------
    defects, healthy : int
        Runs of each kind.
    seed : int
        Of the draws.

    Returns
    -------
    (float, float, float)
        Share of the defective runs whose part is ranked first and called likely, share with
        another part called likely first, share of the healthy runs with any part called
        likely.
    """
    from runout.diagnose._record import record_from_arrays
    from runout.diagnose.envelope import diagnose_envelope
    from runout.runner import run_model

    rng = np.random.default_rng(seed)
    hits = wrong = alarms = 0
    for i in range(defects + healthy):
        part = ("outer", "inner", "ball")[i % 3] if i < defects else "healthy"
        # the speeds of each kind spread over the range (one in each of its equal slices)
        k, count = (i // 3, -(-defects // 3)) if i < defects else (i - defects, healthy)
        rpm = 1200.0 + 1800.0 * (k + float(rng.uniform())) / count
        changes: dict[str, Any] = {
            "operation.speed": f"{rpm:.6g} rpm",
            "sensor.noise": float(rng.uniform(0.3, 1.5)),
            "sensor.seed": 100 + i,
            "sensor.slip": float(rng.uniform(0.01, 0.02)),
            "sensor.duration": "1.5 s",
            "analysis.revolutions": 4,
            "analysis.samples": 1024,
            "defect.width": f"{rng.uniform(0.5, 1.5):.4g} mm",
            "defect.depth": f"{rng.uniform(20.0, 80.0):.4g} um",
        }
        if part in ("outer", "inner"):
            changes["defect.angle"] = f"{rng.uniform(-180.0, 180.0):.4g} deg"
        elif part == "ball":
            changes["defect.element"] = int(rng.integers(1, 10))
        # the record's tachometer follows it: the diagnosis order-tracks
        changes["sensor.speed_fluctuation"] = float(rng.uniform(0.0, 0.01))
        case = _variant(part, **changes)
        sig = run_model(case).signal
        rec = record_from_arrays(sig.time, a=sig.acceleration, rev=sig.rev, quantity="acceleration")
        first = diagnose_envelope(case, rec).defects[0]
        if part == "healthy":
            alarms += first.assessment == "likely"
        elif first.assessment == "likely":
            hits += first.part == part
            wrong += first.part != part
    return hits / defects, wrong / defects, alarms / healthy


def _rate(i: int) -> float:
    return float(round_trip()[i])


def checks() -> list[Check]:
    """The rows of the defects section of VALIDATION.md.

    Returns
    -------
    list of Check
        Largest envelope peak of each part's spall at 1797 rpm against the CWRU data center's
        orders; detection and false-alarm rates of the round trip.

    Notes
    -----
    CWRU bearing data center, 6205-2RS JEM SKF drive-end bearing: BPFO 3.5848, BPFI 5.4152,
    ball 4.7135 times the shaft speed.
    """
    name = uses(EXAMPLE, "a spall's acceleration signal (dynamic model), envelope round trip")
    cases = {
        "outer": name,
        "inner": uses(EXAMPLES["inner"], "an inner raceway spall's envelope peak (BPFI)"),
        "ball": uses(EXAMPLES["ball"], "a ball spall's envelope peak (2 x BSF)"),
    }
    words = {"outer": "the outer raceway", "inner": "the inner raceway", "ball": "ball 1"}
    labels = {"outer": "BPFO", "inner": "BPFI", "ball": "ball defect (2 x BSF)"}
    rows = [
        Check(
            f"CWRU 6205 drive end, spall on {words[part]}, 1797 rpm",
            f"largest envelope peak, labelled {labels[part]} [orders]",
            order,
            bind(_largest_order, part),
            "rel",
            0.01,
            reason="the contact angle under the 500 N axial load (the published orders are at "
            "0); resolution 0.5 Hz",
            case=cases[part],
        )
        for part, order in PUBLISHED.items()
    ]
    source = (
        f"{ROUND_TRIP_DEFECTS} random spalls + {ROUND_TRIP_HEALTHY} healthy runs, 1200-3000 rpm"
    )
    for i, quantity, rule, tol, expected, why in (
        (
            0,
            "spalls: the part ranked first and likely (detection)",
            "min",
            0.7,
            "≥ 0.7",
            "the misses are the generated part ranked first but only possible: slip and noise "
            "keep its score under 24 dB (a ball's cage-rate lines count as its modulation, not "
            "as a cage defect)",
        ),
        (
            1,
            "spalls: another part called likely first",
            "max",
            0.1,
            "≤ 0.1",
            "a ball defect's cage modulation and an inner race's shaft sidebands overlap other "
            "parts' windows",
        ),
        (
            2,
            "healthy runs: any part called likely (false alarm)",
            "max",
            0.5 / ROUND_TRIP_HEALTHY,
            f"0 of {ROUND_TRIP_HEALTHY}",
            "the ball passage alone makes no impacts",
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
