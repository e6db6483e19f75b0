"""`[[defect]]` spalls in the dynamic model and the acceleration signal they make, through the CLI.

The CWRU 6205 drive-end bearing at 1797 rpm (examples/cwru_6205_outer_spall.toml, and the same
case with the spall on the inner raceway or on ball 1): `runout run --json` has an envelope
block whose largest peak is the part's defect frequency, within 1 % of the data center's
published order times the shaft speed (the model's contact angle under the 500 N axial load
moves the orders by under 0.5 %), labelled with the part; the inner raceway's BPFI carries
sidebands at +- the shaft speed, the ball's BDF sidebands at +- the cage speed (FTF);
`runout run --out DIR` writes DIR/signal.csv, which `runout diagnose --record --envelope` reads
and names the defective part from; the healthy bearing's signal is not called defective; a
random slip spreads the defect line, and a ball spall under slip is still named the ball (its
cage-rate lines are its modulation); a speed fluctuation moves the tachometer column and
spreads the line, and the diagnosis order-tracks it sharp again; the step resolves a narrow
spall. Bad entries exit 2 with one line naming the file and the key.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

ROOT = Path(__file__).resolve().parents[2]
OUTER = ROOT / "examples" / "cwru_6205_outer_spall.toml"
runner = CliRunner()
#: The data center's defect orders (per shaft revolution) of the 6205 drive end.
PUBLISHED = {"outer": 3.5848, "inner": 5.4152, "ball": 2.0 * 2.3567}
LABEL = {"outer": "BPFO", "inner": "BPFI", "ball": "BDF"}
SHAFT_HZ = 1797.0 / 60.0
FTF_ORDER = 0.39828

_OUTER_DEFECT = re.compile(r'\[\[defect\]\]\npart = "outer"\n(.*\n){2}angle = [^\n]*\n')
_ENTRIES = {
    "outer": None,
    "inner": '[[defect]]\npart = "inner"\nwidth = "1 mm"\ndepth = "50 um"\nangle = "-90 deg"\n',
    "ball": '[[defect]]\npart = "ball"\nwidth = "1 mm"\ndepth = "50 um"\nelement = 1\n',
    "healthy": "",
}


def _case(tmp: Path, kind: str, entry: str | None = None) -> Path:
    text = OUTER.read_text(encoding="utf-8")
    if entry is None:
        entry = _ENTRIES[kind]
    if entry is not None:
        text, n = _OUTER_DEFECT.subn(entry, text)
        assert n == 1
    path = tmp / f"{kind}.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _run(*args: str) -> tuple[int, str]:
    result = runner.invoke(app, list(args))
    return result.exit_code, result.output


@pytest.fixture(scope="module")
def runs(tmp_path_factory) -> dict[str, tuple[Path, Path, dict]]:
    """kind -> (case file, --out directory, result.json) of each spall and the healthy bearing."""
    base = tmp_path_factory.mktemp("defects")
    out = {}
    for kind in ("outer", "inner", "ball", "healthy"):
        case = _case(base, kind)
        directory = base / f"out_{kind}"
        code, text = _run("run", str(case), "--out", str(directory))
        assert code == 0, text
        out[kind] = (case, directory, json.loads((directory / "result.json").read_text()))
    return out


@pytest.mark.parametrize("part", ["outer", "inner", "ball"])
def test_largest_envelope_peak_is_the_defect_frequency(runs, part: str) -> None:
    doc = runs[part][2]
    envelope = doc["envelope"]
    lo, hi = envelope["band_hz"]
    assert 0.0 <= lo < hi <= 6000.0
    first = envelope["peaks"][0]
    expected = PUBLISHED[part] * SHAFT_HZ
    assert abs(first["frequency_hz"] - expected) <= 0.01 * expected, envelope["peaks"][:3]
    assert first["label"] == LABEL[part]
    assert first["part"] == part
    assert (first["harmonic"], first["sideband"]) == (1, 0)
    assert all(p["amplitude"] <= first["amplitude"] for p in envelope["peaks"])


def test_inner_race_sidebands_at_the_shaft_speed(runs) -> None:
    peaks = runs["inner"][2]["envelope"]["peaks"]
    bpfi = peaks[0]["frequency_hz"]
    for side in (-1, 1):
        near = [p for p in peaks if p["label"] == f"BPFI{'+' if side > 0 else '-'}fr"]
        assert near, [p["label"] for p in peaks]
        # the sideband is one shaft speed from BPFI, to the spectrum's resolution
        res = runs["inner"][2]["envelope"]["resolution_hz"]
        assert abs(near[0]["frequency_hz"] - (bpfi + side * SHAFT_HZ)) <= 2.0 * res


def test_ball_defect_is_modulated_by_the_cage(runs) -> None:
    envelope = runs["ball"][2]["envelope"]
    peaks = envelope["peaks"]
    bdf = peaks[0]["frequency_hz"]
    cage = FTF_ORDER * SHAFT_HZ
    res = envelope["resolution_hz"]
    labels = {p["label"]: p["frequency_hz"] for p in peaks}
    assert "FTF" in labels, list(labels)
    assert abs(labels["FTF"] - cage) <= 0.01 * cage + res
    sides = [p for p in peaks if p["label"] in ("BDF-FTF", "BDF+FTF")]
    assert sides, list(labels)
    for p in sides:
        assert abs(abs(p["frequency_hz"] - bdf) - cage) <= 2.0 * res


@pytest.mark.parametrize("part", ["outer", "inner", "ball"])
def test_diagnose_names_the_defective_part_from_signal_csv(runs, part: str) -> None:
    case, directory, _ = runs[part]
    signal = directory / "signal.csv"
    assert signal.read_text().splitlines()[0] == "time_s,a_m_per_s2,rev"
    code, text = _run("diagnose", str(case), "--record", str(signal), "--envelope", "--json")
    assert code == 0, text
    doc = json.loads(text)
    first = doc["defects"][0]
    assert (first["part"], first["assessment"]) == (part, "likely"), doc["verdict"]


def test_healthy_bearing_signal_is_not_called_defective(runs) -> None:
    # its ball passage (Z f_c, the BPFO of a stationary outer ring) varies the stiffness, but
    # without impacts: not impulsive, not called defective
    case, directory, _doc = runs["healthy"]
    code, text = _run(
        "diagnose", str(case), "--record", str(directory / "signal.csv"), "--envelope", "--json"
    )
    assert code == 0, text
    report = json.loads(text)
    assert all(d["assessment"] != "likely" for d in report["defects"]), report["verdict"]


def test_notes_and_summary_state_the_sensor_model(runs, tmp_path: Path) -> None:
    notes = runs["outer"][2]["notes"]
    sensor = [n for n in notes if n.startswith("acceleration signal:")]
    assert sensor and "3000 Hz" in sensor[0] and "H(s)" in sensor[0]
    assert any(n.startswith("defect[1]: 1 mm x 50 um on the outer raceway") for n in notes)
    code, text = _run("run", str(runs["outer"][0]))
    assert code == 0, text
    assert "acceleration signal" in " ".join(text.split())


@pytest.mark.parametrize(
    ("entry", "key"),
    [
        ('[[defect]]\npart = "outer"\nwidth = "20 mm"\ndepth = "50 um"\n', "defect[1].width"),
        ('[[defect]]\npart = "outer"\nwidth = "1 mm"\ndepth = "4 mm"\n', "defect[1].depth"),
        ('[[defect]]\npart = "ball"\nwidth = "1 mm"\ndepth = "5 um"\nelement = 10\n',
         "defect[1].element"),
        ('[[defect]]\npart = "ball"\nwidth = "1 mm"\ndepth = "5 um"\n', "defect[1].element"),
        ('[[defect]]\npart = "inner"\nwidth = "0 mm"\ndepth = "5 um"\n', "defect[1].width"),
        ('[[defect]]\npart = "inner"\nwidth = "1 mm"\ndepth = "5 um"\nelement = 2\n',
         "defect[1].element"),
    ],
)  # fmt: skip
def test_bad_defect_exits_2_naming_the_key(tmp_path: Path, entry: str, key: str) -> None:
    case = _case(tmp_path, "bad", entry)
    code, text = _run("run", str(case), "--json")
    assert code == 2, text
    lines = text.strip().splitlines()
    assert len(lines) == 1, text
    assert str(case) in " ".join(text.split()) or case.name in text
    assert key in text


@pytest.mark.parametrize("model", ["linear", "quasi_static_3d", "equilibrium"])
def test_other_models_refuse_a_defect(tmp_path: Path, model: str) -> None:
    # without the position preload (which these models refuse first)
    text = re.sub(r"(axial_load|preload) = [^\n]*\n", "", OUTER.read_text(encoding="utf-8"))
    for signal in (True, False):
        if not signal:
            text = text.replace('signal = "acceleration"\n', "").split("[sensor]")[0]
        case = tmp_path / f"{signal}.toml"
        case.write_text(text, encoding="utf-8")
        code, out = _run("run", str(case), "--model", model, "--json")
        assert code == 2, out
        assert len(out.strip().splitlines()) == 1
        key = "defect[1]" if not signal or "defect[1]" in out else "analysis.signal"
        assert str(case.name) in out and key in out and '"dynamic"' in out, out


def test_sensor_needs_the_acceleration_signal(tmp_path: Path) -> None:
    text = OUTER.read_text(encoding="utf-8").replace('signal = "acceleration"\n', "")
    case = tmp_path / "case.toml"
    case.write_text(text, encoding="utf-8")
    code, out = _run("run", str(case), "--json")
    assert code == 2, out
    assert "case.toml: sensor:" in out and 'signal = "acceleration"' in out, out


@pytest.mark.parametrize(
    ("duration", "key"), [('"2 h"', "sensor.duration"), ('"0.005 s"', "sensor.duration")]
)
def test_signal_length_is_bounded(tmp_path: Path, duration: str, key: str) -> None:
    # too long for the budget (refused before the signal is integrated), too short for the
    # envelope analysis
    text = OUTER.read_text(encoding="utf-8").replace('duration = "2 s"', f"duration = {duration}")
    case = tmp_path / "case.toml"
    case.write_text(text, encoding="utf-8")
    code, out = _run("run", str(case), "--json")
    assert code == 2, out
    assert len(out.strip().splitlines()) == 1
    assert "case.toml" in out and key in out, out


def _narrow(tmp_path: Path, dynamics: str = "") -> dict:
    """A 20 um wide spall (entry 6 us at 1797 rpm), displacement only, 2 revolutions."""
    text = OUTER.read_text(encoding="utf-8").replace('width = "1 mm"', 'width = "0.02 mm"')
    text = text.replace('signal = "acceleration"\n', "").split("[sensor]")[0]
    text = re.sub(r"revolutions = \d+\nsamples = \d+", "revolutions = 2\nsamples = 256", text)
    text = text.replace("[dynamics]\n", f"[dynamics]\n{dynamics}")
    case = tmp_path / "narrow.toml"
    case.write_text(text, encoding="utf-8")
    code, out = _run("run", str(case), "--json")
    assert code == 0, out
    return json.loads(out)


def test_step_resolves_a_narrow_spall(tmp_path: Path) -> None:
    doc = _narrow(tmp_path)
    note = next(n for n in doc["notes"] if n.startswith("Newmark step at most"))
    entry_us = float(re.search(r"spall \(([0-9.]+) us\)", note).group(1))
    # 10 steps over the entry at least (the step also divides the output interval)
    assert doc["time_step_s"] * 1e6 <= entry_us / 10.0 * (1 + 1e-9)


def test_a_coarser_given_step_is_said(tmp_path: Path) -> None:
    doc = _narrow(tmp_path, 'time_step = "4 us"\n')
    assert any("the impacts are under-resolved" in n for n in doc["notes"]), doc["notes"]


def _concentration(directory: Path, doc: dict) -> float:
    """Share of the squared-envelope spectrum's energy within 2 % of BPFO that lies in the
    three bins around its largest peak (near 1 for an exact line, less as slip spreads it)."""
    import numpy as np

    from runout.analysis.envelope import squared_envelope_spectrum

    data = np.loadtxt(directory / "signal.csv", delimiter=",", skiprows=1)
    fs = 1.0 / (data[1, 0] - data[0, 0])
    ses = squared_envelope_spectrum(data[:, 1], fs, tuple(doc["envelope"]["band_hz"]))
    bpfo = PUBLISHED["outer"] * SHAFT_HZ
    near = np.abs(ses.frequency - bpfo) <= 0.02 * bpfo
    energy = ses.amplitude**2
    i = int(np.argmax(np.where(near, energy, 0.0)))
    return float(energy[i - 1 : i + 2].sum() / energy[near].sum())


def test_slip_spreads_the_defect_line_and_the_diagnosis_still_finds_it(
    runs, tmp_path: Path
) -> None:
    text = OUTER.read_text(encoding="utf-8").replace("seed = 1\n", "seed = 1\nslip = 0.015\n")
    case = tmp_path / "slip.toml"
    case.write_text(text, encoding="utf-8")
    directory = tmp_path / "out"
    code, out = _run("run", str(case), "--out", str(directory))
    assert code == 0, out
    doc = json.loads((directory / "result.json").read_text())
    assert any("random slip 0.015" in n for n in doc["notes"])
    first = doc["envelope"]["peaks"][0]
    bpfo = PUBLISHED["outer"] * SHAFT_HZ
    assert first["label"] == "BPFO" and abs(first["frequency_hz"] - bpfo) <= 0.02 * bpfo
    exact = _concentration(runs["outer"][1], runs["outer"][2])
    spread = _concentration(directory, doc)
    # exact: 0.997; 1.5 % slip over 2 s: 0.90 (the phase wanders by a random walk)
    assert exact > 0.98 and spread < 0.95 * exact, (spread, exact)
    code, text = _run(
        "diagnose", str(case), "--record", str(directory / "signal.csv"), "--envelope", "--json"
    )
    assert code == 0, text
    assert json.loads(text)["defects"][0]["part"] == "outer"


def test_slip_with_waviness_is_refused(tmp_path: Path) -> None:
    text = OUTER.read_text(encoding="utf-8").replace("seed = 1\n", "seed = 1\nslip = 0.01\n")
    text += '\n[[waviness]]\npart = "outer"\norder = 8\namplitude = "0.1 um"\n'
    case = tmp_path / "case.toml"
    case.write_text(text, encoding="utf-8")
    code, out = _run("run", str(case), "--json")
    assert code == 2, out
    assert "case.toml" in out and "sensor.slip" in out


def test_a_given_band_is_the_envelope_band(tmp_path: Path) -> None:
    """``[sensor] band`` replaces the kurtogram's choice: the JSON says so, and the outer
    spall's line is still the largest in it."""
    text = OUTER.read_text(encoding="utf-8").replace(
        'duration = "2 s"', 'duration = "2 s"\nband = ["2 kHz", "3.5 kHz"]'
    )
    case = tmp_path / "band.toml"
    case.write_text(text, encoding="utf-8")
    code, out = _run("run", str(case), "--json")
    assert code == 0, out
    envelope = json.loads(out)["envelope"]
    assert envelope["band_hz"] == pytest.approx([2000.0, 3500.0], rel=1e-12)  # unit conversion
    assert envelope["band_source"] == "given"
    assert envelope["peaks"][0]["label"] == "BPFO"
    assert math.isfinite(envelope["spectral_kurtosis"])
    assert any("given by [sensor] band" in n for n in json.loads(out)["notes"])


@pytest.mark.parametrize(
    ("key", "value"),
    [
        *(
            ("band", band)
            for band in (
                '["4 kHz", "2 kHz"]', '["2 kHz", "7 kHz"]', '["-1 kHz", "2 kHz"]', '["2 kHz"]',
                '"2 kHz"',
            )
        ),
        ("speed_fluctuation", "0.2"),
        ("speed_fluctuation", "-0.01"),
    ],
)  # fmt: skip
def test_a_sensor_value_out_of_range_exits_2_naming_the_key(
    tmp_path: Path, key: str, value: str
) -> None:
    text = OUTER.read_text(encoding="utf-8").replace(
        'duration = "2 s"', f'duration = "2 s"\n{key} = {value}'
    )
    case = tmp_path / "case.toml"
    case.write_text(text, encoding="utf-8")
    code, out = _run("run", str(case), "--json")
    assert code == 2, out
    assert len(out.strip().splitlines()) == 1, out
    assert "case.toml" in out and f"sensor.{key}" in out, out


def test_ball_spall_under_slip_is_named_the_ball(tmp_path: Path) -> None:
    # slip spreads BDF (141 Hz) ten times as wide as FTF (12 Hz): the cage-rate lines stay
    # sharp; they are the ball's modulation, the ball is named first and the cage not likely
    text = _case(tmp_path, "ball").read_text(encoding="utf-8")
    case = tmp_path / "ball_slip.toml"
    case.write_text(text.replace("seed = 1\n", "seed = 1\nslip = 0.015\n"), encoding="utf-8")
    directory = tmp_path / "out"
    code, out = _run("run", str(case), "--out", str(directory))
    assert code == 0, out
    code, text = _run(
        "diagnose", str(case), "--record", str(directory / "signal.csv"), "--envelope", "--json"
    )
    assert code == 0, text
    doc = json.loads(text)
    first = doc["defects"][0]
    assert first["part"] == "ball", doc["verdict"]
    assert first["evidence"]["modulation_found"] >= 1
    cage = next(d for d in doc["defects"] if d["part"] == "cage")
    assert cage["assessment"] != "likely", doc["verdict"]
    assert "rolling element defect" in doc["verdict"].split(" or ")[0], doc["verdict"]


def _fluctuating(tmp: Path, fluctuation: float) -> tuple[Path, Path, dict]:
    text = OUTER.read_text(encoding="utf-8").replace(
        "seed = 1\n", f"seed = 1\nspeed_fluctuation = {fluctuation}\n"
    )
    case = tmp / "fluctuating.toml"
    case.write_text(text, encoding="utf-8")
    directory = tmp / "out"
    code, out = _run("run", str(case), "--out", str(directory))
    assert code == 0, out
    return case, directory, json.loads((directory / "result.json").read_text())


def test_speed_fluctuation_moves_the_tachometer_and_spreads_the_line(runs, tmp_path: Path) -> None:
    import numpy as np

    case, directory, doc = _fluctuating(tmp_path, 0.01)
    assert doc["signal"]["sensor"]["speed_fluctuation"] == 0.01
    assert any("fluctuates by 0.01 rms" in n for n in doc["notes"])
    data = np.loadtxt(directory / "signal.csv", delimiter=",", skiprows=1)
    time, rev = data[:, 0], data[:, 2]
    rate = np.diff(rev) / np.diff(time) / SHAFT_HZ  # relative instantaneous speed
    # the rms of the relative deviation is the fluctuation (over the fine steps; the csv's
    # 12 kHz samples of a < 3 Hz variation read it within round-off of the 9-digit column)
    assert float(np.sqrt(np.mean((rate - 1.0) ** 2))) == pytest.approx(0.01, rel=0.05)
    # the mean speed is the case's (to the last sample's step)
    assert rev[-1] / time[-1] == pytest.approx(SHAFT_HZ, rel=1e-4)
    exact = _concentration(runs["outer"][1], runs["outer"][2])
    spread = _concentration(directory, doc)
    assert spread < 0.9 * exact, (spread, exact)
    # with the tachometer the record is order tracked: the line is sharp again
    code, text = _run(
        "diagnose", str(case), "--record", str(directory / "signal.csv"), "--envelope", "--json"
    )
    assert code == 0, text
    tracked = json.loads(text)
    assert any(n.startswith("order tracking:") for n in tracked["notes"])
    first = tracked["defects"][0]
    assert (first["part"], first["assessment"]) == ("outer", "likely"), tracked["verdict"]
    bpfo = next(h for h in first["evidence"]["harmonics"] if h["harmonic"] == 1)
    assert abs(bpfo["frequency_hz"] / bpfo["expected_hz"] - 1.0) < 0.002
    # without it, 1 % still names the outer race (the line spreads within the slip tolerance)
    bare = tmp_path / "no_tach.csv"
    rows = (directory / "signal.csv").read_text().splitlines()
    bare.write_text("\n".join(r.rsplit(",", 1)[0] for r in rows) + "\n", encoding="utf-8")
    code, text = _run("diagnose", str(case), "--record", str(bare), "--envelope", "--json")
    assert code == 0, text
    assert json.loads(text)["defects"][0]["part"] == "outer"


def test_the_runs_envelope_is_order_tracked_under_a_speed_fluctuation(tmp_path: Path) -> None:
    # the run knows its shaft angle exactly: its envelope block reads the lines at their
    # orders times the mean speed, as diagnose does with a tachometer (at 3 % rms the lines
    # in hertz spread over several bins and the largest peak is no longer BPFO)
    _, _, doc = _fluctuating(tmp_path, 0.03)
    envelope = doc["envelope"]
    assert envelope["order_tracked"] is True
    first = envelope["peaks"][0]
    assert first["label"] == "BPFO", envelope["peaks"][:3]
    assert abs(first["frequency_hz"] / (PUBLISHED["outer"] * SHAFT_HZ) - 1.0) < 0.01
    labels = [p["label"] for p in envelope["peaks"][:4]]
    assert "2xBPFO" in labels, labels
    assert any(n.startswith("envelope band") and "order-tracked" in n for n in doc["notes"])


def test_a_constant_speed_envelope_is_not_order_tracked(runs) -> None:
    assert runs["outer"][2]["envelope"]["order_tracked"] is False


@pytest.mark.parametrize("part", ["outer", "inner", "ball"])
def test_a_noiseless_signal_is_enveloped_above_the_frequencies_it_reads(
    tmp_path: Path, part: str
) -> None:
    """Without sensor noise the low-frequency part of the signal holds the impacts' force
    directly (as impulsive as they are): the kurtogram must not choose a band that contains the
    frequencies the envelope spectrum reads (its envelope would mix them, and its largest
    peak was a leakage line at a few hertz; the diagnosis found no defect in any of the three
    records). The band lies above them, and the largest peak is still the part's defect
    frequency, labelled; the diagnosis of the record names the part first, with evidence
    (the outer race's only as "possible": without noise the kurtogram takes the band of the
    rotor's contact modes, 0.75-1.5 kHz, where its second harmonic stays below the threshold),
    and no other part likely, in a verdict that reads as English."""
    case = _case(tmp_path, part)
    text = case.read_text(encoding="utf-8")
    text, n = re.subn(r"(?m)^noise = .*$", "noise = 0.0", text)
    assert n == 1
    case.write_text(text, encoding="utf-8")
    directory = tmp_path / "out"
    code, out = _run("run", str(case), "--out", str(directory))
    assert code == 0, out
    envelope = json.loads((directory / "result.json").read_text())["envelope"]
    expected = PUBLISHED[part] * SHAFT_HZ
    lo, _hi = envelope["band_hz"]
    bpfi = PUBLISHED["inner"] * SHAFT_HZ  # the highest defect frequency of the bearing
    assert lo >= 3.0 * bpfi, envelope["band_hz"]
    first = envelope["peaks"][0]
    assert abs(first["frequency_hz"] - expected) <= 0.01 * expected, envelope["peaks"][:3]
    assert first["label"] == LABEL[part]
    code, out = _run(
        "diagnose", str(case), "--record", str(directory / "signal.csv"), "--envelope", "--json"
    )
    assert code == 0, out
    doc = json.loads(out)
    assert doc["envelope"]["band_hz"][0] >= 3.0 * bpfi, doc["envelope"]["band_hz"]
    first = doc["defects"][0]
    assert first["part"] == part, doc["verdict"]
    assert first["assessment"] in ("likely", "possible"), doc["verdict"]
    # a noiseless ball spall's cage-rate comb reaches BPFI's windows (BDF + 2 FTF is 2.5 % from
    # BPFI): lines the ball's family explains are no independent evidence of an inner defect
    others = [(c["part"], c["assessment"]) for c in doc["defects"][1:]]
    assert all(a != "likely" for _, a in others), doc["verdict"]
    assert re.search(r"\ba [aeiou]", doc["verdict"]) is None, doc["verdict"]
