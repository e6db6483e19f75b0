"""Small things that erode trust (issue 29, items 5 and 7), each through the real command line.

Every test here failed before its fix: the linear model named the ball-waviness line at
2 f_b + f_c "2n f_b - f_c" with the outer ring turning, ...
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

runner = CliRunner()

BEARING = """\
[bearing]
type = "ball"
elements = 8
element_diameter = "1 mm"
pitch_diameter = "7 mm"
inner_conformity = 0.52
outer_conformity = 0.53
radial_clearance = "10 um"
"""

BALL_WAVINESS = """
[[waviness]]
part = "ball"
element = 1
order = 2
amplitude = "20 nm"
[[waviness]]
part = "ball"
element = 3
order = 4
amplitude = "5 nm"
phase = "40 deg"
"""


def _case(
    tmp_path: Path,
    model: str,
    *,
    operation: str = 'speed = "5400 rpm"\naxial_load = "20 N"\n',
    extra: str = "",
    revolutions: float = 16,
    samples: int = 4096,
) -> Path:
    text = (
        f'title = "{model}"\n{BEARING}[operation]\n{operation}{extra}\n'
        f'[analysis]\nmodel = "{model}"\nrevolutions = {revolutions}\nsamples = {samples}\n'
    )
    if model == "dynamic":
        text += '[dynamics]\nmass = "0.1 kg"\ndamping = "50 N*s/m"\n'
    path = tmp_path / f"{model}.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _json(path: Path) -> dict[str, Any]:
    result = runner.invoke(app, ["run", str(path), "--json"])
    assert result.exit_code == 0, result.stderr + result.stdout
    out: dict[str, Any] = json.loads(result.stdout)
    return out


# 5 -------------------------------------------------------------------------------------------
BALL_LINE = re.compile(r"^(\d+) f_b ([+-]) f_c$")


@pytest.mark.parametrize("ring", ["inner", "outer"])
def test_every_model_names_a_ball_line_by_the_frequency_it_sits_at(
    tmp_path: Path, ring: str
) -> None:
    op = f'rotating_ring = "{ring}"\nspeed = "5400 rpm"\naxial_load = "20 N"\n'
    named: dict[str, dict[tuple[int | None, int | None, str], tuple[str, str, str]]] = {}
    for model in ("linear", "quasi_static_2d", "quasi_static_3d", "dynamic"):
        out = _json(_case(tmp_path, model, operation=op, extra=BALL_WAVINESS))
        f = out["frequencies_hz"]
        spin, cage = f["ball_spin"], f["cage"]
        lines = named.setdefault(model, {})
        for c in out["components"]:
            top = c["sources"][0]
            if c["direction"] == "z" or top["part"] != "ball" or "order" in top["term"]:
                continue
            match = BALL_LINE.match(top["formula"])
            if match is None:
                continue
            k, sign = int(match[1]), match[2]
            expected = k * spin + cage if sign == "+" else abs(k * spin - cage)
            # the sign in the formula is the frequency's: the line sits where it says
            assert c["frequency_hz"] == pytest.approx(expected, rel=1e-6), (model, c)
            assert top["term"] == f"2n f_b {sign} f_c", (model, top)
            # a nonlinear model may add a second source (ball 1's order-2 line at 4 f_b ± f_c)
            label = re.sub(r" \+\d+ more$", "", c["label"])
            lines[(top["element"], top["lobes"], sign)] = (top["term"], top["formula"], label)
    # the first-order lines of both balls, both signs, in every model, named alike
    assert all(len(lines) == 4 for lines in named.values()), named
    reference = named["quasi_static_3d"]
    for model, lines in named.items():
        assert lines == reference, model


# 7b ------------------------------------------------------------------------------------------
INNER_WAVINESS = '\n[[waviness]]\npart = "inner"\norder = 9\namplitude = "10 nm"\n'


@pytest.mark.parametrize("model", ["linear", "quasi_static_2d", "roller_constraint"])
def test_a_model_without_axial_freedom_says_na_not_zero(tmp_path: Path, model: str) -> None:
    path = _case(tmp_path, model, extra=INNER_WAVINESS, revolutions=2, samples=1024)
    out = _json(path)
    assert "axial_pp_m" in out["runout"] and out["runout"]["axial_pp_m"] is None
    text = runner.invoke(app, ["run", str(path)])
    assert text.exit_code == 0, text.stderr
    row = next(line for line in text.stdout.splitlines() if "axial p-p" in line)
    assert "n/a" in row and not re.search(r"\b0\b", row), row


def test_a_model_with_axial_freedom_gives_its_axial_runout(tmp_path: Path) -> None:
    out = _json(_case(tmp_path, "quasi_static_3d", extra=INNER_WAVINESS, revolutions=2))
    assert isinstance(out["runout"]["axial_pp_m"], float)


def test_the_report_says_na_for_the_axial_runout_of_a_radial_model(tmp_path: Path) -> None:
    path = _case(tmp_path, "linear", extra=INNER_WAVINESS, revolutions=2, samples=1024)
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(path), "--out", str(out), "--report"])
    assert result.exit_code == 0, result.stderr
    page = (out / "report.html").read_text(encoding="utf-8")
    card = re.search(r"axial p-p</[^>]+>\s*<[^>]+>([^<]*)<", page)
    assert card is not None and card[1].strip() == "n/a", card


# 7b, the rest: the typed result, studies, equilibrium ----------------------------------------
@pytest.mark.parametrize("model", ["linear", "quasi_static_2d", "roller_constraint", "dynamic"])
def test_the_typed_result_of_a_radial_model_has_no_axial_runout(tmp_path: Path, model: str) -> None:
    from runout.analysis.results import RunResult

    # the dynamic model is radial with its rings held axially (a position preload; its
    # default, a spring preload, frees z)
    op = 'speed = "5400 rpm"\naxial_load = "20 N"\n'
    op += 'preload = "position"\n' if model == "dynamic" else ""
    path = _case(tmp_path, model, operation=op, extra=INNER_WAVINESS, revolutions=2, samples=1024)
    back = RunResult.from_json(_json(path))  # what `runout run --json` wrote, read back
    assert back.runout.axial_pp_m is None and not back.has_axial_freedom
    assert back.to_json()["runout"]["axial_pp_m"] is None
    from runout.case.model import load_case
    from runout.runner import run_model

    assert run_model(load_case(path)).runout.axial_pp_m is None  # the model's own result


def test_an_old_result_file_with_a_zero_axial_runout_reads_as_none(tmp_path: Path) -> None:
    from runout.io.result_files import read_result

    path = _case(tmp_path, "linear", extra=INNER_WAVINESS, revolutions=2, samples=1024)
    out = tmp_path / "out"
    assert runner.invoke(app, ["run", str(path), "--out", str(out)]).exit_code == 0
    doc = json.loads((out / "result.json").read_text(encoding="utf-8"))
    doc["runout"]["axial_pp_m"] = 0.0  # what the files written before this change hold
    (out / "result.json").write_text(json.dumps(doc), encoding="utf-8")
    assert read_result(out).runout.axial_pp_m is None


def _study_case(tmp_path: Path, model: str) -> Path:
    path = _case(tmp_path, model, extra=INNER_WAVINESS, revolutions=2, samples=1024)
    text = path.read_text(encoding="utf-8")
    text += (
        '[study]\nkind = "montecarlo"\nsamples = 4\nseed = 3\n'
        '[study.vary]\nelement_diameter_sigma = "0.1 um"\n'
    )
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("model", ["linear", "quasi_static_2d"])  # a run each; the batched path
def test_a_study_of_a_radial_model_reports_no_axial_statistics(tmp_path: Path, model: str) -> None:
    out = tmp_path / "study"
    done = runner.invoke(app, ["study", str(_study_case(tmp_path, model)), "--out", str(out)])
    assert done.exit_code == 0, done.stderr + done.stdout
    stats = json.loads((out / "summary.json").read_text(encoding="utf-8"))["runout"]
    assert all(v is None for k, v in stats["axial_pp_m"].items() if k != "histogram")
    assert stats["axial_pp_m"]["histogram"]["counts"] == []
    assert stats["radial_pp_m"]["mean"] > 0.0
    rows = (out / "samples.csv").read_text(encoding="utf-8").splitlines()
    column = rows[0].split(",").index("axial_pp_m")
    assert [row.split(",")[column] for row in rows[1:]] == [""] * 4  # empty: no value, not 0
    row = next(line for line in done.stdout.splitlines() if "axial_pp_m" in line)
    assert "n/a" in row and not re.search(r"\b0\b", row), row
    page = runner.invoke(app, ["report", str(out)])
    assert page.exit_code == 0, page.stderr
    html = (out / "report.html").read_text(encoding="utf-8")
    cells = re.search(r"axial p-p</td>(.*?)</tr>", html, re.S)
    assert cells is None or not re.search(r">\s*0(\.0+)?\s*<", cells[1]), cells


def test_equilibrium_has_no_runout_figures_only_a_position(tmp_path: Path) -> None:
    path = _case(tmp_path, "equilibrium", revolutions=2, samples=1024)
    out = _json(path)
    assert out["runout"] == dict.fromkeys(("radial_pp_m", "axial_pp_m", "rro_pp_m", "nrro_pp_m"))
    assert any("no runout" in note for note in out["notes"])
    text = runner.invoke(app, ["run", str(path)])
    assert text.exit_code == 0, text.stderr
    assert not re.search(r"p-p\s*│\s*0\b", text.stdout), text.stdout
