"""`runout diagnose CASE --record FILE --envelope` through the real command line.

Generated acceleration records of the CWRU 6205 drive-end bearing at 1797 rpm, 12 kHz
(:mod:`runout.validation._envelope_checks`: impacts at the defect period with 1 % random slip,
each ringing a 3 kHz resonance, load-zone modulation, Gaussian noise): the defective part is
named first and its fundamental is the largest of its peaks within 1 %; healthy records (noise,
smooth vibration) are not called defective; bad records and options exit 2 with one line.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from runout.case.model import load_case
from runout.cli.commands import app
from runout.validation._envelope_checks import defect_frequencies, defect_record, healthy_record

ROOT = Path(__file__).resolve().parents[2]
CASE = ROOT / "examples" / "cwru_6205_drive_end.toml"
runner = CliRunner()
#: The data center's defect orders (per shaft revolution) of the 6205 drive end.
PUBLISHED = {"outer": 3.5848, "inner": 5.4152, "ball": 2.0 * 2.3567}
LABEL = {"outer": "BPFO", "inner": "BPFI", "ball": "BDF"}


def _write(
    path: Path,
    time: np.ndarray,
    a: np.ndarray,
    header: str = "time_s,a_m_per_s2",
    scale: float = 1.0,
    rev: np.ndarray | None = None,
) -> Path:
    cols = [time, a * scale] + ([] if rev is None else [rev])
    rows = np.column_stack(cols)
    lines = [header] + [",".join(f"{v:.9g}" for v in row) for row in rows]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def case():
    return load_case(CASE)


@pytest.fixture(scope="module")
def records(case, tmp_path_factory) -> dict[str, Path]:
    base = tmp_path_factory.mktemp("env")
    out = {}
    for part in ("outer", "inner", "ball"):
        rec = defect_record(case, part, noise=1.0, seed=3)  # type: ignore[arg-type]
        out[part] = _write(base / f"{part}.csv", rec.time, rec.channels["a"])
    for kind in ("noise", "smooth"):
        rec = healthy_record(case, kind, seed=4)  # type: ignore[arg-type]
        out[kind] = _write(base / f"{kind}.csv", rec.time, rec.channels["a"])
    return out


def _json(*args: str) -> dict:
    result = runner.invoke(app, ["diagnose", str(CASE), *args, "--envelope", "--json"])
    assert result.exit_code == 0, (result.stdout, result.stderr)
    return json.loads(result.stdout)


def _bad(*args: str, case: Path = CASE) -> str:
    result = runner.invoke(app, ["diagnose", str(case), *args])
    assert result.exit_code == 2, (result.exit_code, result.stdout, result.stderr)
    err = result.stderr.strip()
    assert "\n" not in err and "Traceback" not in err, err
    return err


@pytest.mark.parametrize("part", ["outer", "inner", "ball"])
def test_defect_named_first_at_published_frequency(records, part):
    payload = _json("--record", str(records[part]))
    first = payload["defects"][0]
    assert first["part"] == part and first["assessment"] == "likely", payload["defects"]
    assert payload["verdict"].endswith("likely") and payload["verdict"].count("likely") == 1
    assert payload["envelope"]["band_source"] == "kurtogram"
    lo, hi = payload["envelope"]["band_hz"]
    assert lo <= 3000.0 <= hi  # the band holds the resonance the impacts ring
    published_hz = PUBLISHED[part] * 1797.0 / 60.0
    assert first["frequency_hz"] == pytest.approx(published_hz, rel=1e-3)
    # the largest peak labelled with a harmonic of the part is its fundamental, within 1 %
    own = [
        p
        for p in payload["envelope"]["peaks"]
        if p["label"] is not None and p["label"].split("x")[-1] == LABEL[part]
    ]
    assert own, payload["envelope"]["peaks"]
    top = max(own, key=lambda p: p["amplitude"])
    assert top["label"] == LABEL[part]
    assert top["frequency_hz"] == pytest.approx(published_hz, rel=0.01)
    if part != "ball":  # a ball's largest envelope line is its cage modulation (FTF)
        largest = payload["envelope"]["peaks"][0]
        assert largest["label"] == LABEL[part]
    evidence = first["evidence"]
    assert 1 in evidence["harmonics_found"] and len(evidence["harmonics_found"]) >= 2
    if part in ("inner", "ball"):  # the modulation's sidebands: shaft speed, cage
        assert evidence["sidebands_found"] >= 1
        spacing = (
            1797.0 / 60.0
            if part == "inner"
            else defect_frequencies(load_case(CASE), 1797.0)["cage"]
        )
        assert evidence["sideband_spacing_hz"] == pytest.approx(spacing, rel=1e-9)
    else:
        assert evidence["sideband_spacing_hz"] is None
    for p in payload["envelope"]["peaks"]:
        assert set(p) == {"frequency_hz", "amplitude", "snr", "label"}


@pytest.mark.parametrize("kind", ["noise", "smooth"])
def test_healthy_record_not_called_defective(records, kind):
    payload = _json("--record", str(records[kind]))
    assert payload["verdict"] == "no defect evidence"
    assert all(d["assessment"] == "no evidence" for d in payload["defects"])
    assert len(payload["defects"]) == 4


def test_given_band_and_g_unit(case, tmp_path):
    rec = defect_record(case, "outer", seed=5)
    path = _write(tmp_path / "g.csv", rec.time, rec.channels["a"], "t [s],a [g]", scale=1 / 9.80665)
    payload = _json("--record", str(path), "--band", "2000,4000")
    assert payload["envelope"]["band_source"] == "given"
    assert payload["envelope"]["band_hz"] == [2000.0, 4000.0]
    assert payload["defects"][0]["part"] == "outer"
    # g is the standard gravity: the same record in m/s^2 reads the same amplitudes
    path2 = _write(tmp_path / "si.csv", rec.time, rec.channels["a"])
    payload2 = _json("--record", str(path2), "--band", "2000,4000")
    a1 = payload["envelope"]["peaks"][0]["amplitude"]
    assert a1 == pytest.approx(payload2["envelope"]["peaks"][0]["amplitude"], rel=1e-6)


def test_tachometer_speed(case, tmp_path):
    rec = defect_record(case, "inner", rpm=1500.0, seed=6)
    rev = rec.time * 1500.0 / 60.0
    path = _write(
        tmp_path / "tacho.csv", rec.time, rec.channels["a"], "time_s,a_m_per_s2,rev", rev=rev
    )
    payload = _json("--record", str(path))
    assert payload["speed_source"] == "tachometer"
    assert payload["speed_hz"] == pytest.approx(25.0, rel=1e-6)
    assert payload["defects"][0]["part"] == "inner"


def test_table_and_out_directory(records, tmp_path):
    out = tmp_path / "diag"
    result = runner.invoke(
        app,
        ["diagnose", str(CASE), "--record", str(records["outer"]), "--envelope", "--out", str(out)],
    )
    assert result.exit_code == 0, result.stderr
    assert "outer race defect likely" in result.stdout
    assert "Largest envelope-spectrum peaks" in result.stdout
    assert (out / "envelope_spectrum.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    saved = json.loads((out / "diagnosis.json").read_text(encoding="utf-8"))
    assert saved["defects"][0]["part"] == "outer" and saved["method"] == "envelope"
    # the report page: the verdict, every part ranked with its evidence, the figure embedded
    page = (out / "report.html").read_text(encoding="utf-8")
    assert "outer race defect likely" in page
    for d in saved["defects"]:
        assert f"<td>{d['part']}</td>" in page and d["assessment"] in page
    assert "data:image/png;base64," in page
    assert f"{saved['envelope']['band_hz'][0]:.0f}" in page
    assert "report.html" in result.stdout


def test_the_report_shows_the_balls_cage_modulation(records, tmp_path):
    # the ball's FTF lines counted as its modulation (JSON evidence "modulation_found") are
    # evidence a reader of the page needs too: why the cage is not called
    out = tmp_path / "diag"
    result = runner.invoke(
        app,
        ["diagnose", str(CASE), "--record", str(records["ball"]), "--envelope", "--out", str(out)],
    )
    assert result.exit_code == 0, result.stderr
    saved = json.loads((out / "diagnosis.json").read_text(encoding="utf-8"))
    ball = next(d for d in saved["defects"] if d["part"] == "ball")
    found, searched = ball["evidence"]["modulation_found"], len(ball["evidence"]["modulation"])
    assert searched > 0
    page = (out / "report.html").read_text(encoding="utf-8")
    assert "cage modulation found" in page
    assert f"<td>{found} of {searched}</td>" in page


def test_no_acceleration_column(tmp_path):
    path = tmp_path / "x.csv"
    path.write_text("time_s,x_m\n" + "".join(f"{i / 12000},{i % 7}e-6\n" for i in range(200)))
    err = _bad("--record", str(path), "--envelope")
    assert str(path) in err and "no acceleration column" in err


def test_unknown_unit(tmp_path):
    path = tmp_path / "u.csv"
    path.write_text("time_s,a [furlong]\n" + "".join(f"{i / 12000},{i % 7}\n" for i in range(200)))
    err = _bad("--record", str(path), "--envelope")
    assert str(path) in err and "a [furlong]" in err and "acceleration" in err


def test_acceleration_beyond_range(records, tmp_path):
    text = records["noise"].read_text().splitlines()
    text[5] = text[5].split(",")[0] + ",1e9"
    path = tmp_path / "big.csv"
    path.write_text("\n".join(text) + "\n")
    err = _bad("--record", str(path), "--envelope")
    assert str(path) in err and "a_m_per_s2" in err and "row 6" in err


@pytest.mark.parametrize(
    ("band", "words"),
    [("2000", "LO,HI"), ("4000,2000", "LO < HI"), ("nan,3", "LO < HI"), ("1000,9000", "Nyquist")],
)
def test_bad_band(records, band, words):
    err = _bad("--record", str(records["outer"]), "--envelope", "--band", band)
    assert "--band" in err
    if words == "Nyquist":
        assert str(records["outer"]) in err and "half the sample rate" in err
    else:
        assert words in err


def test_band_without_envelope(records):
    err = _bad("--record", str(records["outer"]), "--band", "2000,4000")
    assert "--envelope" in err


def test_line_fit_options_refused(records):
    err = _bad("--record", str(records["outer"]), "--envelope", "--quantity", "velocity")
    assert "--quantity" in err and "--envelope" in err


def test_too_short_and_too_slow(case, tmp_path):
    rec = defect_record(case, "outer", duration=0.3, seed=7)
    path = _write(tmp_path / "short.csv", rec.time, rec.channels["a"])
    err = _bad("--record", str(path), "--envelope")
    assert str(path) in err and "too short" in err and "cage revolutions" in err
    rec = defect_record(case, "outer", sample_rate=2000.0, resonance=600.0, seed=7)
    path = _write(tmp_path / "slow.csv", rec.time, rec.channels["a"])
    err = _bad("--record", str(path), "--envelope")
    assert str(path) in err and "sampled at 2000 Hz" in err


def test_acceleration_column_without_envelope(records):
    err = _bad("--record", str(records["outer"]))
    assert str(records["outer"]) in err and "--envelope" in err


def test_a_varying_tachometer_is_order_tracked_for_the_envelope_only(case, tmp_path):
    # a 3 % speed swing: the envelope diagnosis resamples to the shaft angle and names the
    # inner race; the line fit of a displacement record reads one speed and refuses it
    rec = defect_record(case, "inner", rpm=1500.0, seed=6)
    rev = rec.time * 25.0 + 0.03 * 25.0 / (2 * np.pi * 0.5) * np.sin(2 * np.pi * 0.5 * rec.time)
    # the constant-speed record read at the fluctuating shaft angle: it follows the tachometer
    a = np.interp(rev / 25.0, rec.time, rec.channels["a"])
    path = _write(tmp_path / "tacho.csv", rec.time, a, "time_s,a_m_per_s2,rev", rev=rev)
    payload = _json("--record", str(path))
    assert payload["defects"][0]["part"] == "inner"
    assert any(n.startswith("order tracking:") for n in payload["notes"])
    disp = tmp_path / "disp.csv"
    rows = ["time_s,x_m,y_m,rev"] + [
        f"{t:.9g},{1e-6 * np.cos(2 * np.pi * r):.9g},{1e-6 * np.sin(2 * np.pi * r):.9g},{r:.9g}"
        for t, r in zip(rec.time[::4], rev[::4], strict=True)
    ]
    disp.write_text("\n".join(rows) + "\n", encoding="utf-8")
    err = _bad("--record", str(disp))
    assert "'rev'" in err and "varies by" in err
