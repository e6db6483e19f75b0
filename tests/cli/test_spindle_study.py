"""Monte Carlo of a spindle's ball sizes, per bearing, through ``runout study``.

``"element_diameter_sigma.<bearing>"`` and ``"elements.<bearing>.diameter_errors"`` draw one
bearing's balls (issue 20: which bearing's ball grade matters more); the single-bearing keys are
refused on a spindle with a message naming the key and what to write.
"""

from __future__ import annotations

import csv
import json
import re
from pathlib import Path

import numpy as np
import pytest
from scipy.special import ndtri
from typer.testing import CliRunner

from runout.cli.commands import app
from runout.study.run import sample_uniforms

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = (ROOT / "examples" / "spindle_hdd_ball_grade.toml").read_text(encoding="utf-8")
SIGMA = 0.06e-6  # [m], the example's
Z = 8  # balls per bearing in the example
runner = CliRunner()


def _case(tmp_path: Path, samples: int = 6, vary: str | None = None, seed: int = 1) -> Path:
    """The example with fewer samples, another seed and optionally another [study.vary]."""
    text = EXAMPLE.replace("samples = 200", f"samples = {samples}")
    text = text.replace("seed = 1\n", f"seed = {seed}\n")
    if vary is not None:
        text = text.split("[study.vary]")[0] + "[study.vary]\n" + vary + "\n"
    path = tmp_path / f"case_{seed}_{abs(hash(vary))}.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _study(path: Path, *args: str) -> dict:
    result = runner.invoke(app, ["study", str(path), "--json", *args])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def _lines(doc: dict) -> dict[tuple[str, str], dict]:
    return {(c["direction"], c["label"]): c["pp_m"] for c in doc["components"]}


def test_front_balls_change_only_the_front_bearing_lines(tmp_path: Path) -> None:
    doc = _study(_case(tmp_path))
    assert doc["models"] == ["spindle"] and doc["samples"] == 6 and doc["failed"] == 0
    base = runner.invoke(app, ["run", str(_case(tmp_path)), "--json"])
    assert base.exit_code == 0, base.stderr
    perfect = {
        c["direction"]: c["pp_m"]
        for c in json.loads(base.stdout)["components"]
        if "7 lobes" in c["label"]
    }
    lines = _lines(doc)
    size = {k: v for k, v in lines.items() if "ball size error" in k[1]}
    assert {k[1] for k in size} == {"ball size error: f_c (front bearing)"}
    assert all(v["std"] > 1e-9 for v in size.values())
    # the rear bearing's 7-lobe line does not move with the front balls
    rear = {k[0]: v for k, v in lines.items() if k[1] == "inner 7 lobes: nZ-1, n=1 (rear bearing)"}
    assert set(rear) == {"x", "y"}
    for direction, stats in rear.items():
        assert stats["mean"] == pytest.approx(perfect[direction], rel=1e-9)
        assert stats["std"] < 1e-9 * stats["mean"]


def test_rear_balls_give_the_rear_line_and_move_the_hub_less(tmp_path: Path) -> None:
    front = _study(_case(tmp_path, samples=20))
    rear = _study(_case(tmp_path, samples=20, vary='"element_diameter_sigma.rear" = "0.06 um"'))
    labels = {k[1] for k in _lines(rear) if "ball size error" in k[1]}
    assert labels == {"ball size error: f_c (rear bearing)"}
    # the same draws (same seed): the hub is 8 mm from the front bearing, 20 mm from the rear
    f_line = _lines(front)[("x", "ball size error: f_c (front bearing)")]["mean"]
    r_line = _lines(rear)[("x", "ball size error: f_c (rear bearing)")]["mean"]
    assert f_line > 2.0 * r_line > 0.0


def test_reproducible_with_its_seed(tmp_path: Path) -> None:
    a = _study(_case(tmp_path, seed=3))
    b = _study(_case(tmp_path, seed=3))
    c = _study(_case(tmp_path, seed=4))
    assert a["runout"] == b["runout"] and a["components"] == b["components"]
    assert a["runout"]["radial_pp_m"] != c["runout"]["radial_pp_m"]


def test_statistics_equal_a_loop_of_runout_run_over_the_same_draws(tmp_path: Path) -> None:
    samples = 4
    case = _case(tmp_path, samples=samples)
    out = tmp_path / "out"
    doc = _study(case, "--out", str(out))
    with (out / "samples.csv").open(encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    radial = []
    for i in range(samples):
        # sample i's draw: its Z words of the study's Philox stream (seed 1), sigma x
        # Phi^-1(u) per front ball
        errors = SIGMA * ndtri(sample_uniforms(1, i, i + 1, Z)[0])
        drawn = [float(rows[i][f"element_diameter_error_front_{j + 1:02d}"]) for j in range(Z)]
        assert drawn == pytest.approx(errors, rel=1e-15, abs=0.0)
        text = case.read_text(encoding="utf-8").split("[study]")[0]
        values = ", ".join(f'"{float(v)!r} m"' for v in errors)
        text += f"\n[elements.front]\ndiameter_errors = [{values}]\n"
        one = tmp_path / f"sample_{i}.toml"
        one.write_text(text, encoding="utf-8")
        result = runner.invoke(app, ["run", str(one), "--json"])
        assert result.exit_code == 0, result.stderr
        run = json.loads(result.stdout)
        radial.append(run["runout"]["radial_pp_m"])
        assert float(rows[i]["radial_pp_m"]) == pytest.approx(radial[-1], rel=1e-12)
    stats = doc["runout"]["radial_pp_m"]
    assert stats["mean"] == pytest.approx(np.mean(radial), rel=1e-12)
    assert stats["std"] == pytest.approx(np.std(radial, ddof=1), rel=1e-12)


def test_the_per_element_key_and_the_table_form_draw_the_same(tmp_path: Path) -> None:
    short = _study(_case(tmp_path))
    keyed = _study(
        _case(
            tmp_path,
            vary='"elements.front.diameter_errors" = { distribution = "normal", std = "0.06 um" }',
        )
    )
    table = _study(_case(tmp_path, vary='element_diameter_sigma = { front = "0.06 um" }'))
    dotted = _study(_case(tmp_path, vary='element_diameter_sigma.front = "0.06 um"'))
    for other in (keyed, table, dotted):
        assert other["runout"] == short["runout"]
        assert other["components"] == short["components"]


@pytest.mark.parametrize(
    ("vary", "says"),
    [
        (
            'element_diameter_sigma = "0.06 um"',
            r"study\.vary\.element_diameter_sigma: .*per bearing.*"
            r"'element_diameter_sigma\.front' \(bearings: front, rear\)",
        ),
        (
            '"elements.diameter_errors" = { distribution = "normal", std = "0.06 um" }',
            r"study\.vary\.elements\.diameter_errors: .*'elements\.front\.diameter_errors'",
        ),
        (
            '"element_diameter_sigma.middle" = "0.06 um"',
            r"study\.vary\.element_diameter_sigma\.middle: 'middle' is not a \[\[bearings\]\] "
            r"name \(front, rear\)",
        ),
        (
            '"element_diameter_sigma.front" = "0.06 um"\n'
            '"elements.front.diameter_errors" = { distribution = "normal", std = "0.06 um" }',
            r"study\.vary\.elements\.front\.diameter_errors: varies the same quantity as "
            r"study\.vary\.element_diameter_sigma\.front; keep one",
        ),
        (
            '"element_diameter_sigma.front" = "0.06 um"\n'
            'element_diameter_sigma = { front = "0.1 um", rear = "0.06 um" }',
            r"study\.vary\.element_diameter_sigma\.front: given twice",
        ),
    ],
)
def test_spindle_refusals_name_the_key(tmp_path: Path, vary: str, says: str) -> None:
    result = runner.invoke(app, ["study", str(_case(tmp_path, vary=vary))])
    assert result.exit_code == 2
    assert re.search(says, " ".join(result.stderr.split())), result.stderr
    assert "Traceback" not in result.stderr


def test_a_bearing_name_on_a_single_bearing_case_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "one.toml"
    text = (ROOT / "examples" / "seed001_kim_table9.toml").read_text(encoding="utf-8")
    vary = '[study.vary]\n"element_diameter_sigma.front" = "0.1 um"\n'
    text = text.split("[study.vary]")[0] + vary
    path.write_text(text, encoding="utf-8")
    result = runner.invoke(app, ["study", str(path)])
    assert result.exit_code == 2
    message = " ".join(result.stderr.split())
    assert "study.vary.element_diameter_sigma.front" in message
    assert "write 'element_diameter_sigma'" in message


def test_per_bearing_pitch_errors_and_two_bearings_at_once(tmp_path: Path) -> None:
    vary = (
        '"elements.rear.pitch_errors" = { distribution = "normal", std = "0.01 deg" }\n'
        'element_diameter_sigma = { front = "0.06 um", rear = "0.06 um" }'
    )
    doc = _study(_case(tmp_path, vary=vary))
    assert doc["failed"] == 0
    sizes = {k[1] for k in _lines(doc) if "ball size error" in k[1]}
    # identical bearings: both bearings' f_c lines (and the rear's pitch line) fall on one
    # frequency, one merged line naming each source
    assert sizes == {
        "ball size error: f_c (front bearing); ball size error: f_c (rear bearing); "
        "pitch: f_c (rear bearing)"
    }
    out = tmp_path / "out"
    _study(_case(tmp_path, vary=vary), "--out", str(out))
    header = (out / "samples.csv").read_text(encoding="utf-8").splitlines()[0].split(",")
    for key in (
        "element_diameter_error_front_08",
        "element_diameter_error_rear_08",
        "element_pitch_error_rear_08",
    ):
        assert key in header


def test_two_keys_on_one_bearings_balls_are_refused(tmp_path: Path) -> None:
    """A single bearing's shorthand and per-element key both set its diameters: the later draw
    would silently replace the other's."""
    path = tmp_path / "one.toml"
    text = (ROOT / "examples" / "seed001_kim_table9.toml").read_text(encoding="utf-8")
    vary = (
        '[study.vary]\nelement_diameter_sigma = "0.1 um"\n'
        '"elements.diameter_errors" = { distribution = "normal", std = "0.1 um" }\n'
    )
    path.write_text(text.split("[study.vary]")[0] + vary, encoding="utf-8")
    result = runner.invoke(app, ["study", str(path)])
    assert result.exit_code == 2
    message = " ".join(result.stderr.split())
    assert (
        "study.vary.elements.diameter_errors: varies the same quantity as "
        "study.vary.element_diameter_sigma; keep one"
    ) in message
