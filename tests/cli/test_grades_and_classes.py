"""Ball grades (ISO 3290-1) and tolerance classes (ISO 492) through the CLI.

``[study.vary] ball_grade = "G5"`` draws the balls' diameters with sigma = V_DWL / 6 (the
grade's lot diameter variation as +-3 sigma; ``[elements] grade_sigma_divisor`` overrides
the 6) through the element_diameter_sigma machinery: the same seed gives the same lot to the
last bit. ``[analysis] limit = "P4"`` with ``limit_bore`` is the class's K_ia for the bore,
on rro_pp by default. Refusals are one line naming the file and key.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from runout.case.standards import BALL_GRADES, KIA_UM

ROOT = Path(__file__).resolve().parents[2]
KIM = ROOT / "examples" / "seed001_kim_table9.toml"

# a 608-size bearing (bore 8 mm) whose inner raceway is eccentric by ECC: its inner ring's
# repeatable radial runout is about 2 ECC
RUN_CASE = """
title = "608 with an eccentric inner raceway"
[bearing]
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
[[waviness]]
part = "inner"
order = 1
amplitude = "{ecc}"
phase = "0 deg"
[analysis]
model = "linear"
revolutions = 4
samples = 256
{analysis}
"""


def cli(*args: str) -> subprocess.CompletedProcess[str]:
    exe = [sys.executable, "-m", "runout.cli", *args]
    return subprocess.run(exe, capture_output=True, text=True, check=False, timeout=300)


def ok_json(*args: str) -> dict[str, Any]:
    done = cli(*args, "--json")
    assert done.returncode == 0, done.stderr
    out: dict[str, Any] = json.loads(done.stdout)
    return out


def refused(*args: str) -> str:
    done = cli(*args)
    assert done.returncode == 2, (done.stdout, done.stderr)
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1, done.stderr
    return lines[0]


def kim_case(tmp_path: Path, vary: str, elements: str = "", samples: int = 40) -> Path:
    """The seed 001 lot with its [study.vary] replaced by ``vary`` and an [elements] table."""
    text = KIM.read_text(encoding="utf-8").split("[study.vary]")[0]
    text = text.replace("samples = 1000", f"samples = {samples}")
    if elements:
        text += f"\n[elements]\n{elements}\n"
    text += f"\n[study.vary]\n{vary}\n"
    path = tmp_path / "lot.toml"
    path.write_text(text, encoding="utf-8")
    return path


def run_case(tmp_path: Path, ecc: str, analysis: str = "") -> Path:
    path = tmp_path / "run.toml"
    path.write_text(RUN_CASE.format(ecc=ecc, analysis=analysis), encoding="utf-8")
    return path


def test_g5_study_states_its_sigma_and_draws_as_element_diameter_sigma(tmp_path: Path) -> None:
    graded = ok_json("study", str(kim_case(tmp_path, 'ball_grade = "G5"')))
    (entry,) = graded["ball_grades"]
    # ISO 3290-1:2014 G5: V_DWL = 0.25 um, taken as 6 sigma
    assert entry["grade"] == "G5" and entry["key"] == "ball_grade"
    assert entry["lot_diameter_variation_m"] == pytest.approx(0.25e-6, rel=1e-12)
    assert entry["sigma_divisor"] == 6.0
    assert entry["sigma_m"] == pytest.approx(0.25e-6 / 6.0, rel=1e-12)
    assert "ISO 3290-1:2014" in entry["source"]
    # the same draws as the shorthand with that sigma: the same lot
    plain = ok_json(
        "study", str(kim_case(tmp_path, f"element_diameter_sigma = {entry['sigma_m']!r}"))
    )
    assert "ball_grades" not in plain
    for key, stats in graded["runout"].items():
        for name, value in stats.items():
            other = plain["runout"][key][name]
            if value is None or other is None:  # a figure the 2-D model does not give
                assert value is other
            else:
                assert value == pytest.approx(other, rel=1e-12, abs=1e-18)


def test_grade_sigma_divisor_overrides_the_six(tmp_path: Path) -> None:
    case = kim_case(tmp_path, 'ball_grade = "G10"', "grade_sigma_divisor = 4", samples=4)
    (entry,) = ok_json("study", str(case))["ball_grades"]
    assert entry["sigma_m"] == pytest.approx(0.5e-6 / 4.0, rel=1e-12)
    assert entry["sigma_divisor"] == 4.0


def test_explicit_sigma_wins_over_the_grade_with_a_note(tmp_path: Path) -> None:
    case = kim_case(tmp_path, 'element_diameter_sigma = "0.1 um"', 'grade = "G5"', samples=4)
    out = ok_json("study", str(case))
    (entry,) = out["ball_grades"]
    assert entry["sigma_m"] == pytest.approx(1e-7, rel=1e-12)
    (note,) = out["notes"]
    assert "wins over elements.grade" in note and "0.0416667 um" in note
    text = cli("study", str(case))
    assert text.returncode == 0 and "wins over elements.grade" in text.stdout


def test_ball_grade_contradicting_the_elements_grade_is_refused(tmp_path: Path) -> None:
    case = kim_case(tmp_path, 'ball_grade = "G10"', 'grade = "G5"', samples=4)
    line = refused("study", str(case))
    assert str(case) in line and "study.vary.ball_grade" in line and "G5" in line


def test_run_with_a_grade_draws_nothing_and_says_so(tmp_path: Path) -> None:
    plain = ok_json("run", str(run_case(tmp_path, "1 um")))
    graded_case = run_case(tmp_path, "1 um", '[elements]\ngrade = "G5"')
    graded = ok_json("run", str(graded_case))
    assert graded["runout"] == plain["runout"]
    (note,) = [n for n in graded["notes"] if n.startswith("elements.grade")]
    assert "draws no ball sizes" in note and "applies no form from the grade" in note


@pytest.mark.parametrize(
    ("order", "bound"),
    [
        (2, 0.25e-6 / 4.0),  # even: V_DWs / 4 = 0.0625 um is below t_Dw / 2 = 0.125 um
        (3, 0.25e-6 / 2.0),  # odd: a ball of constant width, t_Dw / 2 alone
    ],
)
def test_grade_form_order_draws_each_balls_form_within_the_grade(
    tmp_path: Path, order: int, bound: float
) -> None:
    case = kim_case(tmp_path, 'ball_grade = "G10"', f"grade_form_order = {order}", samples=12)
    out_dir = tmp_path / "lot"
    done = cli("study", str(case), "--out", str(out_dir))
    assert done.returncode == 0, done.stderr
    summary = json.loads((out_dir / "summary.json").read_text(encoding="utf-8"))
    (entry,) = summary["ball_grades"]
    # ISO 3290-1:2014 G10: V_DWs = t_Dw = 0.25 um
    assert entry["form_order"] == order
    assert entry["form_amplitude_max_m"] == pytest.approx(bound, rel=1e-12)
    assert entry["form_entries"] == [1, 10]
    assert "lobes" in done.stdout and "(0-peak)" in done.stdout
    columns = np.genfromtxt(out_dir / "samples.csv", delimiter=",", names=True)
    amplitudes = np.array([columns[f"waviness_{k}_amplitude"] for k in range(1, 11)])
    phases = np.array([columns[f"waviness_{k}_phase"] for k in range(1, 11)])
    # every ball of every bearing has its own draw, within the grade's bound and a turn
    assert amplitudes.shape == (10, 12)
    assert np.all((amplitudes >= 0.0) & (amplitudes <= bound))
    assert np.all((phases >= 0.0) & (phases < 2.0 * np.pi))
    assert np.unique(amplitudes).size == amplitudes.size
    labels = " ".join(c["label"] for c in summary["components"])
    if order == 2:  # an even ball form changes the ball's diameter: lines at 2 f_b +- f_c
        assert "ball lobes: 2n f_b" in labels
    else:  # an odd one keeps the ball's diameter: no line from it in the 2-D model
        assert "ball lobes" not in labels


def test_grade_form_order_without_a_grade_draw_is_refused(tmp_path: Path) -> None:
    case = kim_case(tmp_path, 'element_diameter_sigma = "0.1 um"', "grade_form_order = 2")
    line = refused("study", str(case))
    assert str(case) in line and "elements.grade_form_order" in line and "ball_grade" in line


@pytest.mark.parametrize(
    ("where", "key", "value", "hint"),
    [
        ("vary", "study.vary.ball_grade", '"G7"', "'G3'"),
        ("elements", "elements.grade", '"G80"', "'G60'"),
    ],
)
def test_unknown_grade_is_refused_with_close_matches(
    tmp_path: Path, where: str, key: str, value: str, hint: str
) -> None:
    if where == "vary":
        case = kim_case(tmp_path, f"ball_grade = {value}", samples=4)
    else:
        case = kim_case(tmp_path, 'element_diameter_sigma = "0.1 um"', f"grade = {value}")
    line = refused("study", str(case))
    assert str(case) in line and key in line and "did you mean" in line and hint in line


def test_ball_grade_is_not_allocated(tmp_path: Path) -> None:
    case = kim_case(tmp_path, 'ball_grade = "G5"', samples=4)
    line = refused(
        "study",
        str(case),
        "--set",
        'analysis.limit="0.2 um"',
        "--allocate",
        "ball_grade",
        "--target-yield",
        "0.9",
    )
    assert "study.allocate" in line and "ball grade" in line


@pytest.mark.parametrize(("ecc", "passed"), [("0.5 um", True), ("2 um", False)])
def test_p4_verdict_is_kia_for_the_bore(tmp_path: Path, ecc: str, passed: bool) -> None:
    case = run_case(tmp_path, ecc, 'limit = "P4"\nlimit_bore = "8 mm"')
    verdict = ok_json("run", str(case))["verdict"]
    # ISO 492:2014 class 4, 2.5 mm < d <= 10 mm: K_ia = 2.5 um, on the repeatable runout
    assert verdict["class"] == "P4" and verdict["quantity"] == "rro_pp"
    assert verdict["limit_m"] == pytest.approx(2.5e-6, rel=1e-12)
    assert verdict["bore_m"] == pytest.approx(8e-3, rel=1e-12)
    assert "ISO 492:2014" in verdict["source"] and "2.5 mm < d <= 10 mm" in verdict["source"]
    assert verdict["pass"] is passed
    assert (verdict["value_m"] <= verdict["limit_m"]) is passed
    text = cli("run", str(case))
    assert text.returncode == 0 and "ISO 492 class P4, bore 8 mm" in text.stdout


def test_class_with_explicit_limit_on_radial_pp(tmp_path: Path) -> None:
    case = run_case(
        tmp_path, "1 um", 'limit = "Normal"\nlimit_on = "radial_pp"\nlimit_bore = "40 mm"'
    )
    verdict = ok_json("run", str(case))["verdict"]
    assert verdict["quantity"] == "radial_pp" and verdict["class"] == "Normal"
    assert verdict["limit_m"] == pytest.approx(15e-6, rel=1e-12)


@pytest.mark.parametrize(
    ("analysis", "key", "words"),
    [
        ('limit = "P4"', "analysis.limit_bore", "required"),
        ('limit = "P3"\nlimit_bore = "8 mm"', "analysis.limit", "did you mean"),
        ('limit = "P0"\nlimit_bore = "8 mm"', "analysis.limit", '"Normal"'),
        ('limit = "P4"\nlimit_bore = "150 mm"', "analysis.limit_bore", "outside"),
        ('limit = "P4"\nlimit_on = "axial_pp"\nlimit_bore = "8 mm"', "analysis.limit_on", "K_ia"),
        ('limit = "1 um"\nlimit_bore = "8 mm"', "analysis.limit_bore", "tolerance class"),
    ],
)
def test_class_refusals(tmp_path: Path, analysis: str, key: str, words: str) -> None:
    case = run_case(tmp_path, "1 um", analysis)
    line = refused("run", str(case))
    assert str(case) in line and key in line and words in line


def test_study_yield_against_a_class(tmp_path: Path) -> None:
    case = kim_case(tmp_path, 'ball_grade = "G5"', samples=20)
    out = ok_json(
        "study", str(case), "--set", 'analysis.limit="P5"', "--set", 'analysis.limit_bore="3 mm"'
    )
    lot = out["yield"]
    assert lot["class"] == "P5" and lot["quantity"] == "rro_pp"
    assert lot["limit_m"] == pytest.approx(4e-6, rel=1e-12)
    assert lot["samples"] == 20


def test_tables_are_the_tabulated_ones() -> None:
    # spot values of ISO 3290-1:2014 and ISO 492:2014 (module docstring of runout.case.standards)
    g10 = BALL_GRADES["G10"]
    assert (g10.diameter_variation, g10.spherical_form) == pytest.approx((0.25e-6, 0.25e-6))
    assert (g10.roughness, g10.lot_diameter_variation) == pytest.approx((0.02e-6, 0.5e-6))
    assert g10.gauge_interval == pytest.approx(1e-6)
    assert KIA_UM["P4"][0] == 2.5 and KIA_UM["Normal"][2] == 13.0


def test_grade_form_bound_by_order() -> None:
    from runout.case.standards import StandardsError, grade_form_amplitude

    for grade in BALL_GRADES.values():
        odd = grade_form_amplitude(grade, 3)
        even = grade_form_amplitude(grade, 2)
        # one multiplication of a tabulated value: equal to round-off on any CPU
        assert odd == pytest.approx(0.5 * grade.spherical_form, rel=1e-15)
        bound = min(0.5 * grade.spherical_form, 0.25 * grade.diameter_variation)
        assert even == pytest.approx(bound, rel=1e-15)
        assert even <= odd
    with pytest.raises(StandardsError):
        grade_form_amplitude(BALL_GRADES["G5"], 1)
