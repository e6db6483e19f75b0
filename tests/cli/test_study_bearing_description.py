"""Studies build every sample from the bearing the user described, through the real CLI.

Issue 29, item 1: a lot of HDD bearings given by their catalogue angle
(``nominal_contact_angle``, no ``radial_clearance``) failed every sample, because each sample
was rebuilt from the resolved case (clearance 0 *and* the angle) instead of the case file's
own keys; the whole lot ran before the study said so. Item 7: ``samples.csv`` column names.
"""

from __future__ import annotations

import csv
import json
import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

#: An HDD spindle bearing (seed 000 Table 1 geometry) given by its catalogue angle.
HDD = """\
title = "HDD lot by catalogue angle"
[bearing]
type = "ball"
elements = 8
element_diameter = "1 mm"
pitch_diameter = "7 mm"
inner_conformity = 0.52
outer_conformity = 0.53
{angle_or_clearance}
[operation]
rotating_ring = "inner"
speed = "5400 rpm"
axial_load = "20 N"
[[waviness]]
part = "inner"
order = 9
peak_to_peak = "20 nm"
[analysis]
model = "{model}"
revolutions = 4
samples = 256
[study]
kind = "montecarlo"
samples = {samples}
seed = 7
chunk_size = {chunk}
[study.vary]
element_diameter_sigma = "0.1 um"
{more}
"""

#: Plain identifiers: what every samples.csv column name must be.
IDENTIFIER = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")


def cli(*args: str, timeout: float = 120) -> subprocess.CompletedProcess[str]:
    exe = [sys.executable, "-m", "runout.cli", *args]
    return subprocess.run(exe, capture_output=True, text=True, check=False, timeout=timeout)


def write(
    tmp_path: Path,
    name: str,
    *,
    angle_or_clearance: str = 'nominal_contact_angle = "15 deg"',
    model: str = "quasi_static_3d",
    samples: int = 20,
    chunk: int = 8,
    more: str = "",
) -> Path:
    path = tmp_path / name
    path.write_text(
        HDD.format(
            angle_or_clearance=angle_or_clearance,
            model=model,
            samples=samples,
            chunk=chunk,
            more=more,
        ),
        encoding="utf-8",
    )
    return path


def clearance_of_angle(degrees: float) -> float:
    """P_d = 2A(1 - cos a0), A = (f_i + f_o - 1) D (Harris) [m], of the HDD bearing."""
    return 2.0 * (0.52 + 0.53 - 1.0) * 1e-3 * (1.0 - math.cos(math.radians(degrees)))


def radial(doc: dict[str, object]) -> list[float]:
    runout = doc["runout"]
    assert isinstance(runout, dict)
    return [runout["radial_pp_m"][k] for k in ("mean", "std", "p5", "p50", "p95")]


@pytest.mark.parametrize("model", ["quasi_static_2d", "quasi_static_3d"])
def test_hdd_lot_by_catalogue_angle_runs_every_sample(tmp_path: Path, model: str) -> None:
    """20 bearings by catalogue angle: every sample runs, the histograms hold the lot, and the
    numbers are those of the same lot given by the clearance the angle sets (and not those of
    another angle): the angle is honoured, not replaced by a clearance of 0."""
    out = tmp_path / "out"
    done = cli(
        "study", str(write(tmp_path, "angle.toml", model=model)), "--json", "--out", str(out)
    )
    assert done.returncode == 0, done.stderr
    doc = json.loads(done.stdout)
    assert (doc["samples"], doc["failed"], doc["errors"]) == (20, 0, [])
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    counts = summary["runout"]["radial_pp_m"]["histogram"]["counts"]
    assert sum(counts) == 20
    f_c = [c for c in summary["components"] if c["label"] == "ball size error: f_c"]
    assert f_c and all(sum(c["pp_m"]["histogram"]["counts"]) == 20 for c in f_c)

    pd = f'radial_clearance = "{clearance_of_angle(15.0)!r} m"'
    same = cli(
        "study", str(write(tmp_path, "pd.toml", model=model, angle_or_clearance=pd)), "--json"
    )
    assert same.returncode == 0, same.stderr
    np.testing.assert_allclose(radial(doc), radial(json.loads(same.stdout)), rtol=1e-9)
    other = 'nominal_contact_angle = "25 deg"'
    steeper = cli(
        "study", str(write(tmp_path, "a25.toml", model=model, angle_or_clearance=other)), "--json"
    )
    assert steeper.returncode == 0, steeper.stderr
    assert radial(json.loads(steeper.stdout))[0] != pytest.approx(radial(doc)[0], rel=1e-6)


def test_catalogue_angle_and_a_varied_clearance_are_refused_before_any_work(
    tmp_path: Path,
) -> None:
    """Drawing the clearance of a bearing given by its angle would describe it twice."""
    vary = '"bearing.radial_clearance" = { distribution = "uniform", low = "2 um", high = "8 um" }'
    out = tmp_path / "out"
    done = cli("study", str(write(tmp_path, "both.toml", more=vary)), "--out", str(out))
    assert done.returncode == 2, done.stderr
    line = done.stderr.strip()
    assert "\n" not in line and "Traceback" not in line
    assert "both.toml" in line and "study.vary.bearing.radial_clearance" in line
    assert "nominal_contact_angle" in line
    assert not list(out.glob("chunks/chunk_*.json"))


def test_spindle_study_of_bearings_by_catalogue_angle(tmp_path: Path) -> None:
    """The spindle example gives its bearings by catalogue angle: a ball-grade study of it."""
    root = Path(__file__).resolve().parents[2]
    text = (root / "examples" / "spindle_machine_tool.toml").read_text(encoding="utf-8")
    assert "nominal_contact_angle" in text and "radial_clearance" not in text
    names = re.findall(r'^name = "([^"]+)"', text, flags=re.M)
    text = text.split("[study]")[0]
    text = re.sub(r"(?m)^revolutions = .*$", "revolutions = 2", text)
    text = re.sub(r"(?m)^samples = .*$", "samples = 256", text)
    text += (
        f'\n[study]\nkind = "montecarlo"\nsamples = 3\nseed = 1\n[study.vary]\n'
        f'"element_diameter_sigma.{names[0]}" = "0.1 um"\n'
    )
    path = tmp_path / "spindle.toml"
    path.write_text(text, encoding="utf-8")
    done = cli("study", str(path), "--json", timeout=300)
    assert done.returncode == 0, done.stderr
    doc = json.loads(done.stdout)
    assert (doc["samples"], doc["failed"]) == (3, 0), doc["errors"]


def test_every_sample_refused_for_one_input_stops_at_once(tmp_path: Path) -> None:
    """Balls larger than the pitch circle in every draw: the study stops with the refusal
    `check` would give (exit 2, one line naming the file and the key) before any chunk runs,
    not after the whole lot of 100 000 samples."""
    vary = '"bearing.element_diameter" = { distribution = "uniform", low = "8 mm", high = "9 mm" }'
    path = write(
        tmp_path, "big.toml", samples=100_000, chunk=250, more=vary, model="quasi_static_2d"
    )
    text = path.read_text().replace('element_diameter_sigma = "0.1 um"\n', "")
    # the lot's estimated time would be refused first: allow it, the lot must never run
    path.write_text(text.replace("samples = 256\n", 'samples = 256\nmax_time = "10 h"\n'))
    out = tmp_path / "out"
    done = cli("study", str(path), "--out", str(out), timeout=60)
    assert done.returncode == 2, done.stderr
    line = done.stderr.strip()
    assert "\n" not in line and "Traceback" not in line
    assert "big.toml" in line and "bearing.element_diameter" in line
    assert "not smaller than the pitch diameter" in line
    assert "first 20 samples" in line
    assert not list(out.glob("chunks/chunk_*.json"))


def test_a_few_failing_samples_still_run_the_lot(tmp_path: Path) -> None:
    """Samples refused only in a tail of the distribution (balls too large now and then) are
    left out as before: the study runs, exit 0, and says how many failed."""
    vary = (
        '"bearing.element_diameter" = { distribution = "sample", values = '
        '["1 mm", "1 mm", "1 mm", "1 mm", "1 mm", "1 mm", "1 mm", "1 mm", "1 mm", "8 mm"] }'
    )
    path = write(tmp_path, "tail.toml", samples=40, more=vary, model="quasi_static_2d")
    path.write_text(path.read_text().replace('element_diameter_sigma = "0.1 um"\n', ""))
    done = cli("study", str(path), "--json")
    assert done.returncode == 0, done.stderr
    doc = json.loads(done.stdout)
    assert 0 < doc["failed"] < 40
    assert "pitch diameter" in doc["errors"][0]["error"]
    assert f"{doc['failed']} of 40 samples failed" in done.stderr


def test_samples_csv_names_are_plain_identifiers_with_units_beside(tmp_path: Path) -> None:
    vary = (
        '"operation.axial_load" = { distribution = "normal", std = "1 N" }\n'
        '"waviness[1].phase" = { distribution = "uniform", low = "0 deg", high = "360 deg" }'
    )
    out = tmp_path / "out"
    path = write(tmp_path, "names.toml", more=vary, samples=6)
    done = cli("study", str(path), "--out", str(out))
    assert done.returncode == 0, done.stderr
    assert "samples_columns.json" in done.stdout
    with (out / "samples.csv").open(encoding="utf-8", newline="") as fh:
        rows = list(csv.reader(fh))
    header = rows[0]
    assert all(IDENTIFIER.match(name) for name in header), header
    assert len(set(header)) == len(header)
    drawn = [f"element_diameter_error_{j:02d}" for j in range(1, 9)]
    assert header[:2] == ["sample", "model"]
    assert header[2:10] == drawn
    assert {"operation_axial_load", "waviness_1_phase", "radial_pp_m"} <= set(header)
    assert len(rows) == 7  # no units row: every row below the header is a sample
    columns = json.loads((out / "samples_columns.json").read_text(encoding="utf-8"))
    assert list(columns["units"]) == header  # every column, in the CSV's order
    assert columns["units"]["element_diameter_error_01"] == "m"
    assert columns["units"]["operation_axial_load"] == "N"
    assert columns["units"]["waviness_1_phase"] == "rad"
    assert columns["units"]["model"] == "-"
    assert columns["columns"]["element_diameter_error_03"] == {
        "key": "element_diameter_sigma",
        "element": 3,
    }
    assert columns["columns"]["waviness_1_phase"] == {"key": "waviness[1].phase"}
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    lines = [n for n in header if n.endswith("_pp_m")]
    described = {
        (c["direction"], c["label"]): name for name, c in columns["columns"].items() if "label" in c
    }
    for comp in summary["components"]:
        name = described[(comp["direction"], comp["label"])]
        assert name in lines and columns["units"][name] == "m"
        assert columns["columns"][name]["frequency_hz"] == comp["frequency_hz"]
    assert described[("x", "ball size error: f_c")] == "x_ball_size_error_f_c_pp_m"
    # the drawn values are the sample's draws: sample 0's words of the study's Philox stream
    # (seed 7), the ball sizes after the other keys' columns in key order, through Phi^-1
    from scipy.special import ndtri

    from runout.case.model import load_case
    from runout.study.run import plan_quantities, sample_uniforms

    quantities = plan_quantities(load_case(path))
    keys = [q.key for q in quantities]
    offset = sum(q.size for q in quantities[: keys.index("element_diameter_sigma")])
    width = -(-sum(q.size for q in quantities) // 4) * 4
    u = sample_uniforms(7, 0, 1, width)[0, offset : offset + 8]
    first = [float(v) for v in rows[1][2:10]]
    assert first == pytest.approx(1e-7 * ndtri(u), rel=1e-15)


def test_report_reads_new_and_old_samples_csv(tmp_path: Path) -> None:
    """`runout report` takes p99 of every line from samples.csv, by the new names and by the
    names earlier versions wrote (a directory without samples_columns.json)."""
    out = tmp_path / "out"
    assert (
        cli("study", str(write(tmp_path, "r.toml", samples=12)), "--out", str(out)).returncode == 0
    )
    assert cli("report", str(out)).returncode == 0
    new_page = (out / "report.html").read_text(encoding="utf-8")
    columns = json.loads((out / "samples_columns.json").read_text(encoding="utf-8"))
    # rewrite the directory as an earlier version wrote it
    old_names = []
    for name in columns["units"]:
        info = columns["columns"].get(name, {})
        if "label" in info:
            hz = f"{info['frequency_hz']:.6g}"
            old_names.append(f"{info['direction']} {hz} Hz {info['label']} pp_m")
        elif "element" in info:
            old_names.append(f"{info['key']}[{info['element']}]")
        else:
            old_names.append(name)
    with (out / "samples.csv").open(encoding="utf-8", newline="") as fh:
        rows = list(csv.reader(fh))
    with (out / "samples.csv").open("w", encoding="utf-8", newline="") as fh:
        csv.writer(fh, lineterminator="\n").writerows([old_names, *rows[1:]])
    (out / "samples_columns.json").unlink()
    (out / "report.html").unlink()
    assert cli("report", str(out)).returncode == 0
    old_page = (out / "report.html").read_text(encoding="utf-8")

    def table(page: str) -> str:
        return page[page.index(">Statistics over the lot") : page.index(">Figures")]

    assert table(new_page) == table(old_page)
    assert "p99 needs" not in table(new_page)
    # a p99 cell for every line row (a number, not a dash)
    rows_html = re.findall(r"<tr><td>([^<]*)</td>(.*?)</tr>", table(new_page))
    assert len(rows_html) > 4
    for _, cells in rows_html:
        p99 = re.findall(r"<td class=num>([^<]*)</td>", cells)[4]
        assert re.match(r"^-?[0-9.]+$", p99), p99


def test_sweep_dynamic_of_a_bearing_by_catalogue_angle(tmp_path: Path) -> None:
    """`sweep-dynamic` rebuilds each point from the case too: the seed 003 rotor with its
    clearance given as the catalogue angle that sets it (4 revolutions of 512 instants)."""
    root = Path(__file__).resolve().parents[2]
    text = (root / "examples" / "seed003_purohit.toml").read_text(encoding="utf-8")
    text = text.replace('radial_clearance = "0.2 um"', 'nominal_contact_angle = "1 deg"')
    text = text.replace("revolutions = 50", "revolutions = 4").replace(
        "samples = 8192", "samples = 512"
    )
    assert "nominal_contact_angle" in text and "radial_clearance" not in text
    path = tmp_path / "dyn.toml"
    path.write_text(text, encoding="utf-8")
    done = cli("sweep-dynamic", str(path), "--preload", "10", "--json", timeout=300)
    assert done.returncode == 0, done.stderr
    (point,) = json.loads(done.stdout)["points"]
    assert point["preload_n"] == 10.0


@pytest.mark.parametrize(
    "text", ["not json at all\n", '{"format": "something else", "units": {}, "columns": {}}\n']
)
def test_an_edited_samples_columns_json_is_refused_not_read_as_an_old_study(
    tmp_path: Path, text: str
) -> None:
    """A samples_columns.json that is not runout's description was taken for an earlier
    version's directory without a word (the old column names then found no line columns)."""
    out = tmp_path / "out"
    assert (
        cli("study", str(write(tmp_path, "r.toml", samples=12)), "--out", str(out)).returncode == 0
    )
    (out / "samples_columns.json").write_text(text, encoding="utf-8")
    done = cli("report", str(out))
    assert done.returncode == 2, done.stdout + done.stderr
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and "samples_columns.json" in lines[0], lines
