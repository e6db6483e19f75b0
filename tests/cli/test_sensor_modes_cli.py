"""A housing of several modes (`[[sensor.modes]]`), through the CLI.

The outer-race spall of examples/cwru_6205_outer_spall.toml with its sensor replaced: the
dynamic model's force on the outer ring does not depend on the sensor, so the modes' transfer
functions add (modal superposition) and the signal of two modes is the sum of each mode's
signal (compared in signal.csv, within the 12 significant digits it is written with); one entry
of `[[sensor.modes]]` is the single mode of `resonance`, `damping_ratio` and `modal_mass`; the
JSON lists the modes; with the example's noise a two-mode housing still shows the spall's BPFO
as the largest envelope line; a bad entry exits 2 with one line naming the file and the key.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from runout.case._schema import MAX_SENSOR_MODES
from runout.cli.commands import app

ROOT = Path(__file__).resolve().parents[2]
OUTER = ROOT / "examples" / "cwru_6205_outer_spall.toml"
runner = CliRunner()
BPFO_HZ = 3.5848 * 1797.0 / 60.0  # the data center's order times the shaft speed
MODE_A = {"resonance": '"3 kHz"', "damping_ratio": "0.05", "modal_mass": '"1 kg"'}
# a mode whose shape has opposite signs at the bearing and at the sensor
MODE_B = {"resonance": '"4.5 kHz"', "damping_ratio": "0.03", "modal_mass": '"-2.5 kg"'}


def _mode(mode: dict[str, str]) -> str:
    return "[[sensor.modes]]\n" + "".join(f"{k} = {v}\n" for k, v in mode.items())


def _case(tmp: Path, name: str, sensor: str, duration: str = "0.4 s", noise: str = "0") -> Path:
    """The example with ``sensor`` (the housing's keys or tables) as its sensor."""
    text = OUTER.read_text(encoding="utf-8")
    text = text[: text.index("[sensor]")]
    head = f'[sensor]\nsample_rate = "12 kHz"\nduration = "{duration}"\nnoise = {noise}\nseed = 1\n'
    path = tmp / f"{name}.toml"
    path.write_text(text + head + sensor, encoding="utf-8")
    return path


def _run(*args: str) -> tuple[int, str]:
    result = runner.invoke(app, list(args))
    return result.exit_code, result.output


def _signal(tmp: Path, name: str, sensor: str) -> tuple[np.ndarray, dict]:
    case = _case(tmp, name, sensor)
    out = tmp / f"out_{name}"
    code, text = _run("run", str(case), "--out", str(out))
    assert code == 0, text
    table = np.loadtxt(out / "signal.csv", delimiter=",", skiprows=1, comments="#")
    return table[:, 1], json.loads((out / "result.json").read_text())


@pytest.fixture(scope="module")
def signals(tmp_path_factory) -> dict[str, tuple[np.ndarray, dict]]:
    base = tmp_path_factory.mktemp("modes")
    single = "".join(f"{k} = {v}\n" for k, v in MODE_A.items())
    return {
        "single": _signal(base, "single", single),
        "A": _signal(base, "A", _mode(MODE_A)),
        "B": _signal(base, "B", _mode(MODE_B)),
        "AB": _signal(base, "AB", _mode(MODE_A) + _mode(MODE_B)),
    }


def test_two_modes_are_the_sum_of_each(signals) -> None:
    a, b, ab = signals["A"][0], signals["B"][0], signals["AB"][0]
    assert np.max(np.abs(b)) > 0.1 * np.max(np.abs(a))  # both modes take part
    # signal.csv holds 12 significant digits: each value is within 5e-12 of itself, relative
    bound = 1e-11 * (np.abs(a) + np.abs(b) + np.abs(ab)) + 1e-12 * np.max(np.abs(ab))
    assert np.all(np.abs(ab - (a + b)) <= bound), np.max(np.abs(ab - (a + b)) - bound)


def test_one_listed_mode_is_the_single_mode(signals) -> None:
    single, listed = signals["single"][0], signals["A"][0]
    assert np.all(np.abs(single - listed) <= 1e-11 * np.max(np.abs(single)))
    sensor = signals["single"][1]["signal"]["sensor"]
    mode = {"resonance_hz": 3000.0, "damping_ratio": 0.05, "modal_mass_kg": 1.0}
    assert sensor["modes"] == [mode]
    assert {k: sensor[k] for k in mode} == mode  # the single mode's keys stay beside the list


def test_the_json_lists_the_modes(signals) -> None:
    doc = signals["AB"][1]
    sensor = doc["signal"]["sensor"]
    assert sensor["modes"] == [
        {"resonance_hz": 3000.0, "damping_ratio": 0.05, "modal_mass_kg": 1.0},
        {"resonance_hz": 4500.0, "damping_ratio": 0.03, "modal_mass_kg": -2.5},
    ]
    assert "resonance_hz" not in sensor  # no single mode to name
    note = next(n for n in doc["notes"] if n.startswith("acceleration signal"))
    assert "2 housing modes" in note and "4500 Hz" in note and "-2.5 kg" in note


def test_a_two_mode_housing_shows_the_spall(tmp_path: Path) -> None:
    case = _case(tmp_path, "noisy", _mode(MODE_A) + _mode(MODE_B), duration="2 s", noise="0.5")
    code, text = _run("run", str(case), "--json")
    assert code == 0, text
    first = json.loads(text)["envelope"]["peaks"][0]
    assert first["label"] == "BPFO", first
    assert abs(first["frequency_hz"] / BPFO_HZ - 1.0) < 0.01


_TOO_MANY = "".join(
    _mode({"resonance": f'"{1 + i} kHz"', "damping_ratio": "0.05", "modal_mass": '"1 kg"'})
    for i in range(MAX_SENSOR_MODES + 1)
)


@pytest.mark.parametrize(
    ("sensor", "key"),
    [
        ('resonance = "3 kHz"\n' + _mode(MODE_A), "sensor.resonance"),
        ('modal_mass = "1 kg"\n' + _mode(MODE_A), "sensor.modal_mass"),
        ("damping_ratio = 0.05\n", "sensor.resonance"),
        ('resonance = "3 kHz"\n', "sensor.damping_ratio"),
        ("modes = []\n", "sensor.modes"),
        (_TOO_MANY.replace('"17 kHz"', '"5 kHz"'), "sensor.modes"),
        (_mode(MODE_A).replace('"1 kg"', "0"), "sensor.modes[1].modal_mass"),
        (_mode(MODE_A) + _mode(MODE_B).replace("0.03", "1.5"), "sensor.modes[2].damping_ratio"),
        (_mode(MODE_A) + _mode(MODE_B).replace('"4.5 kHz"', '"7 kHz"'), "sensor.sample_rate"),
        (_mode(MODE_A).replace("damping_ratio = 0.05\n", ""), "sensor.modes[1].damping_ratio"),
    ],
)
def test_a_bad_mode_exits_2_naming_the_key(tmp_path: Path, sensor: str, key: str) -> None:
    case = _case(tmp_path, "case", sensor)
    code, out = _run("run", str(case), "--json")
    assert code == 2, out
    assert len(out.strip().splitlines()) == 1, out
    assert "case.toml" in out and key in out, out
