"""`runout diagnose CASE --record FILE` through the real command line: output and bad records.

Every bad record is refused with exit status 2 and one line naming the record file and the row
or column at fault (no traceback).
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from runout.case.model import load_case
from runout.cli.commands import app
from runout.validation._diagnosis_checks import done_when_truth, synthetic_record

ROOT = Path(__file__).resolve().parents[2]
CASE = ROOT / "examples" / "seed002_608.toml"
runner = CliRunner()


def _csv(path: Path, header: str, rows: np.ndarray) -> Path:
    lines = [header] + [",".join(repr(float(v)) for v in row) for row in rows]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def good(tmp_path_factory) -> Path:
    case = load_case(CASE)
    rec, _, _ = synthetic_record(
        case, done_when_truth(7), samples=40_000, sample_rate=4000.0, noise=0.02, seed=1
    )
    rows = np.column_stack([rec.time, rec.channels["x"] * 1e6, rec.channels["y"] * 1e6])
    return _csv(tmp_path_factory.mktemp("rec") / "good.csv", "t [s],x [um],y [um]", rows)


def _invoke(*args: str):
    return runner.invoke(app, ["diagnose", str(CASE), *args])


def test_json_output(good):
    result = _invoke("--record", str(good), "--json")
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert payload["explained_fraction"] > 0.95
    parts = {(e["part"], tuple(e["lobes"])) for e in payload["estimates"]}
    assert ("inner", (6,)) in parts and ("outer", (15,)) in parts
    assert any(abs(u["frequency_hz"] - 50.0) < 0.2 for u in payload["unattributed"])
    inner6 = next(e for e in payload["estimates"] if e["part"] == "inner" and e["lobes"] == [6])
    assert inner6["amplitude_m"] == pytest.approx(0.2e-6, rel=0.1)
    # the case's own waviness tables are ignored, and the output says so
    assert any("ignored" in n for n in payload["notes"])


def test_table_output(good):
    result = _invoke("--record", str(good))
    assert result.exit_code == 0, result.stderr
    assert "Estimated deviations" in result.stdout
    assert "Unattributed lines" in result.stdout
    assert "Not observable" in result.stdout


def test_out_directory_and_estimated_case_runs(good, tmp_path):
    out = tmp_path / "diag"
    result = _invoke("--record", str(good), "--out", str(out))
    assert result.exit_code == 0, result.stderr
    for name in ("report.html", "diagnosis.json", "estimated.toml", "diagnosis_spectrum.png"):
        assert (out / name).is_file(), name
    html = (out / "report.html").read_text(encoding="utf-8")
    assert "Estimated deviations" in html and "data:image/png;base64" in html
    text = re.sub(r"base64,[A-Za-z0-9+/=]+", "", html)  # the figures' bytes are not text
    assert not re.search(r"\bnan\b", text, flags=re.IGNORECASE)
    run = runner.invoke(app, ["run", str(out / "estimated.toml"), "--json"])
    assert run.exit_code == 0, run.stderr
    payload = json.loads(run.stdout)
    assert payload["model"] == "linear"


def test_velocity_quantity(tmp_path):
    case = load_case(CASE)
    rec, x, _y = synthetic_record(
        case, done_when_truth(7), samples=40_000, sample_rate=4000.0, noise=0.0, mains=0.0
    )
    vx = np.gradient(x, rec.step)
    path = _csv(tmp_path / "v.csv", "time_s,x [um/s]", np.column_stack([rec.time, vx * 1e6]))
    result = _invoke("--record", str(path), "--quantity", "velocity", "--json")
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert "noise_rms_m_per_s" in payload
    inner8 = next(e for e in payload["estimates"] if e["part"] == "inner" and e["lobes"] == [8])
    assert inner8["amplitude_m"] == pytest.approx(0.15e-6, rel=0.02)


def test_tachometer_count_replaces_the_speed(tmp_path):
    case = load_case(CASE)
    rec, _, _ = synthetic_record(
        case, done_when_truth(7), samples=40_000, sample_rate=4000.0, noise=0.01, mains=0.0
    )
    rev = np.floor(rec.time * 30.0)  # 1800 rpm
    path = _csv(
        tmp_path / "tach.csv",
        "time_s,x_m,y_m,rev",
        np.column_stack([rec.time, rec.channels["x"], rec.channels["y"], rev]),
    )
    result = _invoke("--record", str(path), "--json")
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert payload["speed_source"] == "tachometer"
    assert payload["rotation_hz"] == pytest.approx(30.0, rel=1e-3)


# ------------------------------------------------------------------ bad records
def _bad(tmp_path: Path, text: str, *extra: str) -> str:
    path = tmp_path / "bad.csv"
    path.write_text(text, encoding="utf-8")
    result = _invoke("--record", str(path), *extra)
    assert result.exit_code == 2, (result.exit_code, result.stdout, result.stderr)
    err = result.stderr.strip()
    assert "\n" not in err and "Traceback" not in err
    assert str(path) in err
    return err


def _rows(n: int = 2000, fs: float = 2000.0) -> list[list[float]]:
    t = np.arange(n) / fs
    return [[ti, 1e-7 * np.sin(2 * np.pi * 123.0 * ti)] for ti in t]


def _text(header: str, rows: list[list[float]]) -> str:
    return header + "\n" + "\n".join(",".join(repr(float(v)) for v in r) for r in rows) + "\n"


def test_bad_non_numeric(tmp_path):
    rows = _rows()
    text = _text("time_s,x_m", rows).splitlines()
    text[10] = text[10].split(",")[0] + ",abc"
    err = _bad(tmp_path, "\n".join(text) + "\n")
    assert "row 11" in err and "'x_m'" in err and "not a number" in err


def test_bad_nan(tmp_path):
    rows = _rows()
    rows[20][1] = float("nan")
    err = _bad(tmp_path, _text("time_s,x_m", rows))
    assert "row 22" in err and "'x_m'" in err and "not a finite number" in err


def test_bad_gap_in_time(tmp_path):
    rows = _rows()
    del rows[100:110]
    err = _bad(tmp_path, _text("time_s,x_m", rows))
    assert "row 102" in err and "gap of 11 time steps" in err


def test_bad_non_uniform_time(tmp_path):
    rows = _rows()
    rows[50][0] += 0.2 / 2000.0
    err = _bad(tmp_path, _text("time_s,x_m", rows))
    assert "not uniformly sampled" in err and "'time_s'" in err


def test_bad_non_monotonic_time(tmp_path):
    rows = _rows()
    rows[30][0], rows[31][0] = rows[31][0], rows[30][0]
    err = _bad(tmp_path, _text("time_s,x_m", rows))
    assert "row 33" in err and "does not increase" in err


def test_bad_too_short(tmp_path):
    err = _bad(tmp_path, _text("time_s,x_m", _rows(n=40)))
    assert "too short: 40 samples" in err


def test_bad_too_few_revolutions(tmp_path):
    err = _bad(tmp_path, _text("time_s,x_m", _rows(n=200, fs=2000.0)))
    assert "too short" in err and "revolutions" in err


def test_bad_missing_time_column(tmp_path):
    err = _bad(tmp_path, _text("when,x_m", _rows()))
    assert "header" in err and "no time column" in err


def test_bad_missing_displacement_column(tmp_path):
    err = _bad(tmp_path, _text("time_s,z_m", _rows()))
    assert "no displacement column" in err


def test_bad_unknown_unit(tmp_path):
    err = _bad(tmp_path, _text("time_s,x [bogon]", _rows()))
    assert "column 'x [bogon]'" in err and "unknown unit" in err


def test_bad_unit_of_the_wrong_kind(tmp_path):
    err = _bad(tmp_path, _text("t [mm],x_m", _rows()))
    assert "column 't [mm]'" in err and "unknown unit" in err


def test_bad_ragged_row(tmp_path):
    text = _text("time_s,x_m", _rows()).splitlines()
    text[5] = text[5].split(",")[0]
    err = _bad(tmp_path, "\n".join(text) + "\n")
    assert "row 6" in err and "fields" in err


def test_bad_velocity_column_without_velocity(tmp_path):
    err = _bad(tmp_path, _text("time_s,x_m_per_s", _rows()))
    assert "--quantity velocity" in err


def test_bad_tachometer_count_decreases(tmp_path):
    rows = [[*r, np.floor(r[0] * 30.0)] for r in _rows(n=4000)]
    rows[3000][2] = 0.0
    err = _bad(tmp_path, _text("time_s,x_m,rev", rows))
    assert "row 3002" in err and "'rev'" in err and "decreases" in err


def test_bad_tachometer_speed_varies(tmp_path):
    t = np.arange(4000) / 2000.0
    rev = np.floor(30.0 * t + 3.0 * t**2)  # speeding up by 20 %
    rows = [[ti, 0.0, ri] for ti, ri in zip(t, rev, strict=True)]
    err = _bad(tmp_path, _text("time_s,x_m,rev", rows))
    assert "speed varies" in err and "'rev'" in err


def test_bad_tachometer_too_few_pulses(tmp_path):
    rows = [[*r, 0.0] for r in _rows(n=4000)]
    rows[100][2] = 1.0
    err = _bad(tmp_path, _text("time_s,x_m,rev", rows))
    assert "at least 3 pulses" in err


def test_bad_missing_file(tmp_path):
    path = tmp_path / "missing.csv"
    result = _invoke("--record", str(path))
    assert result.exit_code == 2
    assert str(path) in result.stderr and "cannot be read" in result.stderr


def test_bad_empty_body(tmp_path):
    err = _bad(tmp_path, "time_s,x_m\n")
    assert "no data rows" in err


def test_record_larger_than_the_memory_budget(tmp_path, monkeypatch):
    case = tmp_path / "plain.toml"
    case.write_text(PLAIN, encoding="utf-8")
    record = tmp_path / "big.csv"
    record.write_text(_text("time_s,x_m", _rows(n=40_000, fs=2000.0)), encoding="utf-8")
    monkeypatch.setenv("RUNOUT_MAX_MEMORY", "1 MiB")  # the case itself needs less
    result = runner.invoke(app, ["diagnose", str(case), "--record", str(record)])
    assert result.exit_code == 2
    err = result.stderr.strip()
    assert err.startswith(f"error: {record}: ") and "\n" not in err
    assert "would need about" in err and "RUNOUT_MAX_MEMORY" in err


PLAIN = """\
title = "608 without imperfections"
[bearing]
type = "ball"
elements = 7
element_diameter = "3.9688 mm"
pitch_diameter = "15 mm"
inner_conformity = 0.52
outer_conformity = 0.53
contact_angle = "10 deg"
[operation]
rotating_ring = "inner"
speed = "1800 rpm"
axial_load = "20 N"
[analysis]
model = "linear"
samples = 256
"""


def test_bad_not_text(tmp_path):
    path = tmp_path / "bad.csv"
    path.write_bytes(b"time_s,x_m\n0.0,\xff\xfe\n")
    result = _invoke("--record", str(path))
    assert result.exit_code == 2
    assert str(path) in result.stderr and "not UTF-8" in result.stderr
