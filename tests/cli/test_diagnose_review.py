"""`runout diagnose` used as a hostile user would: records as instruments and spreadsheets write
them, and records the linear model cannot explain. Each test is a finding of the review."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from runout.case.model import load_case
from runout.cli.commands import app
from runout.validation._diagnosis_checks import Truth, done_when_truth, synthetic_record

ROOT = Path(__file__).resolve().parents[2]
CASE = ROOT / "examples" / "seed002_608.toml"
runner = CliRunner()


def _csv(path: Path, header: str, rows: np.ndarray, *, encoding: str = "utf-8") -> Path:
    lines = [header] + [",".join(repr(float(v)) for v in row) for row in rows]
    path.write_text("\n".join(lines) + "\n", encoding=encoding)
    return path


def _invoke(*args: str, case: Path = CASE):
    return runner.invoke(app, ["diagnose", str(case), *args])


@pytest.fixture(scope="module")
def record():
    case = load_case(CASE)
    rec, _, _ = synthetic_record(
        case, done_when_truth(7), samples=40_000, sample_rate=4000.0, noise=0.01, mains=0.0
    )
    return rec


def _rows(rec, *extra: np.ndarray) -> np.ndarray:
    return np.column_stack([rec.time, rec.channels["x"], rec.channels["y"], *extra])


def test_a_spreadsheet_bom_is_read(record, tmp_path):
    # "CSV UTF-8" from a spreadsheet starts with a byte-order mark
    path = _csv(tmp_path / "bom.csv", "time_s,x_m,y_m", _rows(record), encoding="utf-8-sig")
    result = _invoke("--record", str(path), "--json")
    assert result.exit_code == 0, result.stderr
    inner6 = next(
        e
        for e in json.loads(result.stdout)["estimates"]
        if e["part"] == "inner" and e["lobes"] == [6]
    )
    assert inner6["amplitude_m"] == pytest.approx(0.20e-6, rel=0.01)


def test_a_semicolon_separated_record_is_named_as_such(record, tmp_path):
    path = tmp_path / "semi.csv"
    rows = _rows(record)[:200]
    path.write_text(
        "time_s;x_m;y_m\n" + "\n".join(";".join(repr(float(v)) for v in r) for r in rows) + "\n",
        encoding="utf-8",
    )
    result = _invoke("--record", str(path))
    assert result.exit_code == 2
    err = result.stderr.strip()
    assert str(path) in err and "\n" not in err
    assert "semicolon" in err.replace(str(path), "")


@pytest.mark.parametrize("scale", [1e300, 1e6])
def test_values_of_the_wrong_unit_are_refused(record, tmp_path, scale):
    # 1e300: the sums overflowed (internal error); 1e6: micrometres written in an x_m column
    rows = _rows(record)
    rows[:, 1:] *= scale
    path = _csv(tmp_path / "big.csv", "time_s,x_m,y_m", rows)
    result = _invoke("--record", str(path))
    assert result.exit_code == 2, (result.exit_code, result.stderr)
    err = result.stderr.strip()
    assert str(path) in err and "\n" not in err and "Traceback" not in err
    assert "column 'x_m'" in err and "row " in err and "unit" in err


def test_a_dead_channel_is_refused(record, tmp_path):
    # a disconnected probe: y stays at 0; read as a measurement it halves both whirls
    rows = _rows(record)
    rows[:, 2] = 0.0
    path = _csv(tmp_path / "dead.csv", "time_s,x_m,y_m", rows)
    result = _invoke("--record", str(path))
    assert result.exit_code == 2, (result.exit_code, result.stdout)
    err = result.stderr.strip()
    assert "column 'y_m'" in err and "constant" in err and "\n" not in err


def test_lines_below_the_records_resolution_are_not_estimates(tmp_path):
    # a noise-free model record: an offset of 0.1 um with lines 1e-14 of it (rounding of
    # the model's sums), which the residual's rms alone would call detected
    case = load_case(CASE)
    rec, _, _ = synthetic_record(
        case, done_when_truth(7), samples=40_000, sample_rate=4000.0, noise=0.0, mains=0.0
    )
    rows = _rows(rec)
    rows[:, 1] = 1e-7 + rows[:, 1] * 1e-14
    rows[:, 2] = 2e-7 + rows[:, 2] * 1e-14
    path = _csv(tmp_path / "flat.csv", "time_s,x_m,y_m", rows)
    result = _invoke("--record", str(path), "--json")
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert payload["estimates"] == [] and payload["unattributed"] == []
    assert any("resolution" in n for n in payload["notes"])


def test_a_two_level_tachometer_is_a_pulse_train(record, tmp_path):
    # TTL pulses (0 / 5 V), not 0 / 1
    pulse = 5.0 * (((record.time * 30.0) % 1.0) < 0.1)
    path = _csv(tmp_path / "ttl.csv", "time_s,x_m,y_m,rev", _rows(record, pulse))
    result = _invoke("--record", str(path), "--json")
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert payload["speed_source"] == "tachometer"
    assert payload["rotation_hz"] == pytest.approx(30.0, rel=1e-3)


def test_a_fractional_revolution_count_gives_the_exact_speed(record, tmp_path):
    # an encoder's count with its fraction: the crossings are interpolated, not rounded to
    # the next sample (one sample over the record shifts a 200 Hz line by degrees)
    rev = record.time * 30.0 + 0.37
    path = _csv(tmp_path / "enc.csv", "time_s,x_m,y_m,rev", _rows(record, rev))
    result = _invoke("--record", str(path), "--json")
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert payload["rotation_hz"] == pytest.approx(30.0, rel=1e-9)


@pytest.mark.parametrize("offset", [0.37, 0.81])
def test_an_integer_count_speed_is_fitted_over_every_revolution(record, tmp_path, offset):
    # each revolution's start is known to one sample (1/4000 s): the first and last alone
    # put up to one sample over the 9.9 s between them (8e-6 and 1.7e-5 here); the
    # least-squares rate over all 300 revolutions averages the sampling down
    rev = np.floor(record.time * 30.0 + offset)
    path = _csv(tmp_path / "count.csv", "time_s,x_m,y_m,rev", _rows(record, rev))
    result = _invoke("--record", str(path), "--json")
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert payload["rotation_hz"] == pytest.approx(30.0, rel=4e-6)


RADIAL = """\
title = "608 under a radial load alone"
[bearing]
type = "ball"
elements = 7
element_diameter = "3.9688 mm"
pitch_diameter = "15 mm"
inner_conformity = 0.52
outer_conformity = 0.53
radial_clearance = "5 um"
[operation]
rotating_ring = "inner"
speed = "1800 rpm"
radial_load = "50 N"
[analysis]
model = "linear"
"""


def test_a_radial_load_without_preload_is_flagged(record, tmp_path):
    # the linear model has every element in contact; under a radial load alone the element
    # passage through the load zone gives the stationary ring's nZ +/- 1 lines
    case = tmp_path / "radial.toml"
    case.write_text(RADIAL, encoding="utf-8")
    path = _csv(tmp_path / "r.csv", "time_s,x_m,y_m", _rows(record))
    result = _invoke("--record", str(path), "--json", case=case)
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert any("load zone" in n for n in payload["notes"])
    outer = [e for e in payload["estimates"] if e["part"] == "outer"]
    assert outer and all("load zone" in e["note"] for e in outer)
    inner = [e for e in payload["estimates"] if e["part"] == "inner"]
    assert inner and not any("load zone" in e["note"] for e in inner)


def test_the_preloaded_case_is_not_flagged(record, tmp_path):
    path = _csv(tmp_path / "p.csv", "time_s,x_m,y_m", _rows(record))
    result = _invoke("--record", str(path), "--json")
    payload = json.loads(result.stdout)
    assert not any("load zone" in n for n in payload["notes"])


def test_a_phase_just_below_zero_prints_as_zero(tmp_path):
    case = load_case(CASE)
    truth = Truth({("inner", 6, None): (0.2e-6, -1e-5), ("inner", 8, None): (0.1e-6, 1.0)})
    rec, _, _ = synthetic_record(
        case, truth, samples=40_000, sample_rate=4000.0, noise=0.0, mains=0.0
    )
    path = _csv(tmp_path / "p.csv", "time_s,x_m,y_m", _rows(rec))
    result = _invoke("--record", str(path))
    assert result.exit_code == 0, result.stderr
    row = next(line for line in result.stdout.splitlines() if "│ inner" in line and " 6 │" in line)
    assert "360.0" not in row and " 0.0 " in row
    out = tmp_path / "diag"
    result = _invoke("--record", str(path), "--out", str(out))
    assert result.exit_code == 0, result.stderr
    html = (out / "report.html").read_text(encoding="utf-8")
    row = next(r for r in html.split("<tr>") if ">inner<" in r and ">6<" in r)
    assert ">360<" not in row and ">0<" in row, row


def test_a_line_fitted_at_its_neighbours_frequency_keeps_its_phase(tmp_path):
    # Tada's bearing, outer ring turning: the stationary inner ring's 9 lobes (405.016 Hz)
    # and the turning outer ring's 9 lobes (404.984 Hz) are one line over 0.8 s; the fit at
    # 404.984 Hz gave the inner 9 lobes the phase of mid-record, pi df T = 0.082 rad late
    case = ROOT / "examples" / "seed000_tada_fig7.toml"
    truth = Truth(
        {
            ("inner", 9, None): (10e-9, 0.5),
            ("outer", 9, None): (10e-9, 1.5),
            ("outer", 7, None): (10e-9, 2.5),
        }
    )
    rec, _, _ = synthetic_record(
        load_case(case), truth, samples=4096, sample_rate=5120.0, noise=0.001, mains=0.0
    )
    path = _csv(tmp_path / "tada.csv", "time_s,x_m,y_m", _rows(rec))
    result = _invoke("--record", str(path), "--json", case=case)
    assert result.exit_code == 0, result.stderr
    inner9 = next(e for e in json.loads(result.stdout)["estimates"] if e["part"] == "inner")
    assert inner9["lobes"] == [9] and "fitted as one line" in inner9["note"]
    assert inner9["amplitude_m"] == pytest.approx(10e-9, rel=0.01)
    assert inner9["phase_rad"] == pytest.approx(0.5, abs=0.01)


@pytest.mark.parametrize(
    ("bad", "expected"),
    [("nan", "not a finite number"), ("abc", "not a number"), (None, "fields")],
)
def test_rows_are_the_files_line_numbers_after_a_blank_line(tmp_path, bad, expected):
    # the reader skips a blank line; the row an error names must still be the file's line
    t = np.arange(4000) / 2000.0
    x = 1e-7 * np.sin(2 * np.pi * 123.0 * t)
    lines = ["time_s,x_m"] + [f"{float(a)!r},{float(b)!r}" for a, b in zip(t, x, strict=True)]
    lines.insert(100, "")  # line 101 of the file
    lines[300] = lines[300].split(",")[0] + ("" if bad is None else f",{bad}")  # line 301
    path = tmp_path / "blank.csv"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    result = _invoke("--record", str(path))
    assert result.exit_code == 2
    err = result.stderr.strip()
    assert "row 301" in err and expected in err, err


def test_a_tachometer_gives_the_speed_a_case_leaves_out(record, tmp_path):
    case = tmp_path / "nospeed.toml"
    case.write_text(
        CASE.read_text(encoding="utf-8").replace('speed = "1800 rpm"', 'speed = "0 rpm"'),
        encoding="utf-8",
    )
    rev = np.floor(record.time * 30.0)
    path = _csv(tmp_path / "tach.csv", "time_s,x_m,y_m,rev", _rows(record, rev))
    result = _invoke("--record", str(path), "--json", case=case)
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert payload["speed_source"] == "tachometer"
    assert payload["rotation_hz"] == pytest.approx(30.0, rel=1e-5)
    # the estimated case runs forward at the tachometer's speed
    out = tmp_path / "diag"
    assert _invoke("--record", str(path), "--out", str(out), case=case).exit_code == 0
    run = runner.invoke(app, ["run", str(out / "estimated.toml"), "--json"])
    assert run.exit_code == 0, run.stderr
    # without a tachometer either, the message says what to give
    plain = _csv(tmp_path / "plain.csv", "time_s,x_m,y_m", _rows(record))
    result = _invoke("--record", str(plain), case=case)
    assert result.exit_code == 2
    assert "operation.speed" in result.stderr and "tachometer" in result.stderr


def test_epoch_time_stamps_are_named_as_the_cause(tmp_path):
    # Unix time: a double keeps 2.4e-7 s of 1.7e9 s, a tenth of the 2.5e-6 s step
    t = np.arange(4000) / 400_000.0
    rows = np.column_stack([t + 1.7e9, 1e-7 * np.sin(2 * np.pi * 1230.0 * t)])
    path = _csv(tmp_path / "epoch.csv", "time_s,x_m", rows)
    result = _invoke("--record", str(path))
    assert result.exit_code == 2
    err = result.stderr.strip()
    assert "'time_s'" in err and "from the start of the record" in err and "\n" not in err


def test_a_record_rounded_to_nothing_explains_nothing(record, tmp_path):
    # values of 1e-306 m: their variance underflows to 0, which read 1 - 0/0 as "all explained"
    rows = _rows(record)
    rows[:, 1:] *= 1e-300
    path = _csv(tmp_path / "tiny.csv", "time_s,x_m,y_m", rows)
    result = _invoke("--record", str(path), "--json")
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert payload["estimates"] == [] and payload["explained_fraction"] == 0.0


def test_an_aliased_line_is_named(tmp_path):
    # sampled at 500 Hz without a low-pass filter: the inner 15-lobe line (294.72 Hz) folds
    # to 205.28 Hz, where it read as an unattributed "2 f_r + ..." combination
    case = load_case(CASE)
    rec, _, _ = synthetic_record(
        case, done_when_truth(7), samples=5000, sample_rate=500.0, noise=0.01, mains=0.0
    )
    path = _csv(tmp_path / "alias.csv", "time_s,x_m,y_m", _rows(rec))
    result = _invoke("--record", str(path), "--json")
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    line = next(u for u in payload["unattributed"] if abs(u["frequency_hz"] - 205.28) < 0.1)
    assert "alias" in line["kinematic_match"] and "inner 15 lobes" in line["kinematic_match"]


def test_a_line_beyond_the_lobes_searched_is_named(tmp_path):
    # --max-lobes 10: the outer 13 | 15-lobe line (155.28 Hz) is not searched, but it is one
    case = load_case(CASE)
    rec, _, _ = synthetic_record(
        case, done_when_truth(7), samples=20000, sample_rate=2000.0, noise=0.01, mains=0.0
    )
    path = _csv(tmp_path / "r.csv", "time_s,x_m,y_m", _rows(rec))
    result = _invoke("--record", str(path), "--json", "--max-lobes", "10")
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    line = next(u for u in payload["unattributed"] if abs(u["frequency_hz"] - 155.28) < 0.1)
    assert "outer 15 lobes" in line["kinematic_match"]
    assert "above the lobes searched" in line["kinematic_match"]


def test_quoted_fields_are_read(record, tmp_path):
    # exports that quote every field, header and numbers alike
    rows = _rows(record)
    path = tmp_path / "quoted.csv"
    path.write_text(
        '"time_s","x_m","y_m"\n'
        + "\n".join(",".join(f'"{float(v)!r}"' for v in r) for r in rows)
        + "\n",
        encoding="utf-8",
    )
    result = _invoke("--record", str(path), "--json")
    assert result.exit_code == 0, result.stderr
    assert json.loads(result.stdout)["explained_fraction"] > 0.95


def test_a_band_without_any_bearing_line_is_refused(record, tmp_path):
    # milliseconds in a time_s column: the band ends at 2 Hz, the ring turns at 30 Hz; this
    # gave "none detected" and a list of unattributed lines at a thousandth of their frequency
    rows = _rows(record)
    rows[:, 0] *= 1000.0
    path = _csv(tmp_path / "ms.csv", "time_s,x_m,y_m", rows)
    result = _invoke("--record", str(path))
    assert result.exit_code == 2, result.stdout
    err = result.stderr.strip()
    assert "column 'time_s'" in err and "Nyquist" in err and "unit" in err and "\n" not in err


def test_a_mirrored_y_axis_is_not_dropped_silently(record, tmp_path):
    # y measured the other way round reverses every whirl: the lines' power went into no
    # observation and vanished (explained 0.3, no unattributed line); it must show
    rows = _rows(record)
    rows[:, 2] *= -1.0
    path = _csv(tmp_path / "mirror.csv", "time_s,x_m,y_m", rows)
    result = _invoke("--record", str(path), "--json")
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert any("y axis" in n for n in payload["notes"])
    whirls = [u for u in payload["unattributed"] if u["channel"] == "xy"]
    # the inner 6-lobe line (102.36 Hz, backward in the model) now whirls forward
    line = next(u for u in whirls if abs(u["frequency_hz"] - 102.36) < 0.01)
    assert "forward whirl" in line["kinematic_match"] and "inner 6 lobes" in line["kinematic_match"]
    assert line["pp_m"] == pytest.approx(2 * 0.2e-6 * math.cos(math.radians(10.0)), rel=0.02)


def test_the_right_whirls_leave_no_whirl_unattributed(record, tmp_path):
    path = _csv(tmp_path / "ok.csv", "time_s,x_m,y_m", _rows(record))
    payload = json.loads(_invoke("--record", str(path), "--json").stdout)
    assert not [u for u in payload["unattributed"] if u["channel"] == "xy"]
    assert not any("y axis" in n for n in payload["notes"])


def test_a_spindle_case_is_refused(record, tmp_path):
    # a spindle case read as its first bearing gave "none detected" for any record
    path = _csv(tmp_path / "r.csv", "time_s,x_m,y_m", _rows(record))
    result = _invoke("--record", str(path), case=ROOT / "examples" / "spindle_hdd.toml")
    assert result.exit_code == 2
    err = result.stderr.strip()
    assert "spindle_hdd.toml" in err and "one [bearing]" in err and "\n" not in err
