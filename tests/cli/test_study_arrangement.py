"""`runout study` of `[study] kind = "arrangement"`: a lot's balls in the best order (seed 001).

Through the real command line: the JSON contract, the prediction checked by running the model
on a case file written with the chosen balls in the chosen order, the output directory, and
one-line refusals (exit 2, naming the file and the key or the line) of bad lots and cases.
"""

from __future__ import annotations

import json
import math
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "seed001_kim_arrangement.toml"
LOT = ROOT / "examples" / "seed001_kim_lot.csv"


def cli(*args: str) -> subprocess.CompletedProcess[str]:
    exe = [sys.executable, "-m", "runout.cli", *args]
    return subprocess.run(exe, capture_output=True, text=True, check=False, timeout=300)


def case_dir(tmp_path: Path, study: str = "", lot: str | None = None) -> Path:
    """The example case and lot copied into ``tmp_path``, its [study] keys replaced."""
    text = EXAMPLE.read_text(encoding="utf-8")
    if study:
        head = text.split("[study]")[0]
        text = head + "[study]\n" + study
    (tmp_path / "case.toml").write_text(text, encoding="utf-8")
    if lot is None:
        shutil.copyfile(LOT, tmp_path / "seed001_kim_lot.csv")
    else:
        (tmp_path / "seed001_kim_lot.csv").write_text(lot, encoding="utf-8")
    return tmp_path / "case.toml"


STUDY = 'kind = "arrangement"\nlot = "seed001_kim_lot.csv"\nseed = 1\nrandom_orders = 500\n'


def run_json(case: Path) -> dict:
    done = cli("study", str(case), "--json")
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def lot_rows() -> dict[str, list[str]]:
    rows = [r for r in LOT.read_text().splitlines() if r and not r.startswith("#")]
    header = rows[0].split(",")
    return {r.split(",")[0]: r.split(",") for r in rows[1:]} | {"header": header}


def chosen_case(case: Path, balls: list[str]) -> Path:
    """A case file with the lot's ``balls`` at positions 1..Z, written as a user would."""
    rows = lot_rows()
    header = rows["header"]
    body = case.read_text(encoding="utf-8").split("[study]")[0]
    d = [f'"{rows[b][header.index("diameter_error_um")]} um"' for b in balls]
    body += f"[elements]\ndiameter_errors = [{', '.join(d)}]\n"
    for position, b in enumerate(balls, start=1):
        for k in (2, 4):
            a = rows[b][header.index(f"waviness_{k}_amplitude_um")]
            phase = rows[b][header.index(f"waviness_{k}_phase_deg")]
            body += (
                f'[[waviness]]\npart = "ball"\nelement = {position}\norder = {k}\n'
                f'amplitude = "{a} um"\nphase = "{phase} deg"\n'
            )
    out = case.parent / "chosen.toml"
    out.write_text(body, encoding="utf-8")
    return out


def test_example_gives_an_order_better_than_every_random_one(tmp_path: Path) -> None:
    doc = run_json(case_dir(tmp_path, STUDY))
    arr, rand = doc["arrangement"], doc["random"]
    assert doc["kind"] == "arrangement" and doc["model"] == "quasi_static_2d"
    assert doc["lot"] == {
        "file": "seed001_kim_lot.csv",
        "balls": 16,
        "elements": 10,
        "waviness_orders": [2, 4],
    }
    assert len(arr["balls"]) == 10 and len(set(arr["balls"])) == 10
    assert set(arr["balls"]) <= {f"B{i:02d}" for i in range(1, 17)}
    assert [p["ball"] for p in arr["positions"]] == arr["balls"]
    assert [line["line"] for line in arr["lines"]] == ["fc", "2fb+fc", "4fb+fc", "2fb-fc", "4fb-fc"]
    assert math.isclose(arr["predicted"], sum(x["predicted_pp_m"] for x in arr["lines"]))
    assert rand["orders"] == 500
    assert arr["predicted"] <= rand["min"]
    assert rand["fraction_as_good"] == 0.0
    assert rand["p5"] <= rand["p50"] <= rand["p95"]
    assert rand["improvement"] == pytest.approx(rand["mean"] / arr["predicted"])


def test_prediction_agrees_with_the_model_run_on_the_chosen_order(tmp_path: Path) -> None:
    """The chosen order, written as a case file and run by `runout run`, gives the predicted
    lines: the closed form linearises the Hertz contacts about the preloaded state, so the
    lines agree to the second-order terms it leaves out (a few % for 0.1 um errors here)."""
    case = case_dir(tmp_path, STUDY)
    doc = run_json(case)
    done = cli("run", str(chosen_case(case, doc["arrangement"]["balls"])), "--json")
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout)
    x_lines = [c for c in result["components"] if c["direction"] == "x"]
    model_sum = 0.0
    for line in doc["arrangement"]["lines"]:
        hit = min(x_lines, key=lambda c: abs(c["frequency_hz"] - line["frequency_hz"]))
        assert hit["frequency_hz"] == pytest.approx(line["frequency_hz"], rel=1e-9)
        model_sum += hit["pp_m"]
        # the study's own check reads the same model at the same frequencies
        assert hit["pp_m"] == pytest.approx(line["model_pp_m"], rel=1e-3, abs=1e-11)
    assert model_sum == pytest.approx(doc["arrangement"]["predicted"], rel=0.05)
    assert doc["check"]["value"] == pytest.approx(model_sum, rel=1e-3)


def test_nrro_prediction_agrees_with_the_models_nrro(tmp_path: Path) -> None:
    case = case_dir(tmp_path, STUDY + 'minimise = "nrro_pp"\n')
    doc = run_json(case)
    assert doc["minimise"]["quantity"] == "nrro_pp"
    done = cli("run", str(chosen_case(case, doc["arrangement"]["balls"])), "--json")
    assert done.returncode == 0, done.stderr
    nrro = json.loads(done.stdout)["runout"]["nrro_pp_m"]
    assert doc["check"]["value"] == pytest.approx(nrro, rel=1e-9)
    # the p-p of a sum of lines moves with the products the linear law leaves out: 10 %
    assert doc["arrangement"]["predicted"] == pytest.approx(nrro, rel=0.10)
    assert doc["arrangement"]["predicted"] <= doc["random"]["min"]


def test_readable_summary_and_out_directory(tmp_path: Path) -> None:
    case = case_dir(tmp_path, STUDY)
    out = tmp_path / "out"
    done = cli("study", str(case), "--out", str(out))
    assert done.returncode == 0, done.stderr
    assert "order (position 1 first): B" in done.stdout
    assert "random orders: p5" in done.stdout and "predicted" in done.stdout
    doc = json.loads((out / "arrangement.json").read_text())
    rows = (out / "arrangement.csv").read_text().splitlines()
    assert rows[0] == "position,ball,lot_row,diameter_error_um" and len(rows) == 11
    assert [r.split(",")[1] for r in rows[1:]] == doc["arrangement"]["balls"]
    assert len((out / "random_orders.csv").read_text().splitlines()) == 501
    assert (out / "case.toml").read_text() == case.read_text()
    # a directory of the user's is refused before anything is computed
    foreign = tmp_path / "mine"
    foreign.mkdir()
    (foreign / "notes.txt").write_text("mine")
    done = cli("study", str(case), "--out", str(foreign))
    assert done.returncode == 2 and "not a runout output" in done.stderr


LOT_HEAD = "ball,diameter_error_um,waviness_2_amplitude_um,waviness_2_phase_deg\n"


@pytest.mark.parametrize(
    ("study", "lot", "expected"),
    [
        (
            STUDY,
            LOT_HEAD + "".join(f"B{i},0.1,0.01,0\n" for i in range(8)),
            "study.lot: seed001_kim_lot.csv holds 8 balls; the bearing takes elements = 10",
        ),
        (
            STUDY,
            LOT_HEAD + "".join(f"B{i},0.1,0.01,0\n" for i in range(11)) + "B11,abc,0.01,0\n",
            "seed001_kim_lot.csv: line 13, diameter_error_um: not a number",
        ),
        (
            STUDY,
            "ball,waviness_2_amplitude_um,waviness_2_phase_deg\nB1,0.01,0\n",
            "seed001_kim_lot.csv: diameter_error_um: missing column",
        ),
        (
            STUDY,
            "ball,diameter_error_um,waviness_2_amplitude_um\nB1,0.1,0.01\n",
            "seed001_kim_lot.csv: waviness_2_phase_deg: missing column",
        ),
        (
            STUDY,
            "ball,diameter_error_um\n" + "".join(f"B{i},0.1\n" for i in range(5001)),
            "seed001_kim_lot.csv: line 5002: more than 5000 balls",
        ),
        (
            STUDY,
            LOT_HEAD + "B1,0.1,0.01\n",
            "seed001_kim_lot.csv: line 2: 3 cells, the header names 4",
        ),
        (
            STUDY,
            "ball,diameter_error_inch\nB1,0.1\n",
            "seed001_kim_lot.csv: line 1, diameter_error_inch: not a column",
        ),
        (
            STUDY + 'minimise = "band"\nband = "H"\n',
            None,
            'study.band: "H" holds none of the lot\'s lines',
        ),
        (
            STUDY + 'minimise = "line"\nline = "6fb+fc"\n',
            None,
            'study.line: "6fb+fc": the lot gives no such line',
        ),
        (STUDY + 'minimise = "line"\nline = "3fb+fc"\n', None, "study.line"),
        (STUDY + 'minimise = "line"\n', None, "study.line: required"),
        (STUDY + "samples = 10\n", None, "study.samples: does not apply"),
        ('kind = "arrangement"\n', None, "study.lot: required"),
        (
            'kind = "montecarlo"\nlot = "x.csv"\n[study.vary]\nelement_diameter_sigma = "0.1 um"\n',
            None,
            'study.lot: only applies to kind = "arrangement"',
        ),
    ],
)
def test_bad_input_is_refused_in_one_line(
    tmp_path: Path, study: str, lot: str | None, expected: str
) -> None:
    done = cli("study", str(case_dir(tmp_path, study, lot)), "--json")
    assert done.returncode == 2, done.stdout + done.stderr
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), done.stderr
    assert expected in lines[0]
    assert done.stdout == ""


def test_a_case_with_imperfections_of_its_own_or_another_model_is_refused(tmp_path: Path) -> None:
    case = case_dir(tmp_path, STUDY)
    text = case.read_text()
    case.write_text(
        text.replace(
            "[study]",
            '[elements]\ndiameter_errors = ["0.1 um", 0, 0, 0, 0, 0, 0, 0, 0, 0]\n[study]',
        )
    )
    done = cli("study", str(case), "--json")
    assert done.returncode == 2 and "elements.diameter_errors: the lot gives" in done.stderr
    case.write_text(text.replace('model = "quasi_static_2d"', 'model = "linear"'))
    done = cli("study", str(case), "--json")
    assert done.returncode == 2 and "analysis.model:" in done.stderr
    case.write_text(text)
    done = cli("study", str(case), "--json", "--workers", "2")
    assert done.returncode == 2 and "--workers does not apply" in done.stderr
