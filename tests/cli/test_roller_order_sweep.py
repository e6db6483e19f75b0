"""The rigid model's order sweep (``order_sweep.csv``) with harmonics that jam the rollers.

``runout run --out`` of a ball bearing under the roller_constraint model printed its complete
result and then exited 2: the order sweep written beside it puts 1 µm of one harmonic on each
part, and a roller harmonic of 23 or 24 lobes jams the 8 balls of 10 µm clearance. The sweep is
an aid to read the run's bearing, whose solution stands: such an order is an empty cell (the
file's header says what it means) and a gap in the plot, and the run succeeds.
"""

from __future__ import annotations

import csv
import subprocess
import sys
from pathlib import Path

CASE = """title = "8 balls of 1 mm, 10 um clearance, rigid model"
[bearing]
type = "ball"
elements = 8
element_diameter = "1 mm"
pitch_diameter = "7 mm"
radial_clearance = "10 um"
[operation]
speed = "5400 rpm"
[[waviness]]
part = "inner"
order = 9
amplitude = "10 nm"
[analysis]
model = "roller_constraint"
revolutions = 2
samples = 1024
"""


def test_a_sweep_order_that_jams_the_rollers_is_an_empty_cell_not_a_failed_run(
    tmp_path: Path,
) -> None:
    case = tmp_path / "case.toml"
    case.write_text(CASE, encoding="utf-8")
    out = tmp_path / "out"
    done = subprocess.run(
        [sys.executable, "-m", "runout.cli", "run", str(case), "--out", str(out)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    text = (out / "order_sweep.csv").read_text(encoding="utf-8")
    header, *rows = text.splitlines()
    assert "an empty cell: that harmonic jams the rollers" in header
    table = list(csv.DictReader(rows))
    jammed = [int(r["order"]) for r in table if r["roller_pp_m"] == ""]
    assert jammed, "the roller harmonics near 3Z jam this bearing"
    # every other entry is a runout, the perfect bearing's at least
    for r in table:
        for part in ("inner", "outer", "roller"):
            if r[f"{part}_pp_m"]:
                assert float(r[f"{part}_pp_m"]) > 0.0
    assert (out / "order_sweep.png").stat().st_size > 0


def _rows(path: Path) -> list[str]:
    return path.read_text(encoding="utf-8").splitlines()


def test_the_sweep_started_before_the_model_is_the_solutions_sweep(tmp_path: Path) -> None:
    """``run --out`` starts the order sweep from the case while the model runs: its table is
    the one computed afterwards from the model's solution (an outer ring turning, whose load
    angle the model turns by π, included)."""
    from concurrent.futures import ThreadPoolExecutor

    from runout.case.model import load_case
    from runout.report import run_files
    from runout.runner import run_model

    for ring in ("inner", "outer"):
        case_file = tmp_path / f"{ring}.toml"
        case_file.write_text(
            CASE.replace('speed = "5400 rpm"', f'speed = "5400 rpm"\nrotating_ring = "{ring}"'),
            encoding="utf-8",
        )
        out = tmp_path / f"out_{ring}"
        done = subprocess.run(
            [sys.executable, "-m", "runout.cli", "run", str(case_file), "--out", str(out)],
            capture_output=True,
            text=True,
            check=False,
        )
        assert done.returncode == 0, done.stderr
        result = run_model(load_case(case_file))
        solution = run_files._roller_solution(result)
        assert solution is not None
        fresh = run_files._write_order_sweep(
            run_files._order_sweep(solution), tmp_path / f"fresh_{ring}.csv"
        )
        assert _rows(out / "order_sweep.csv") == _rows(fresh)
        # the early sweep's key is the solution's: it is the one used
        with ThreadPoolExecutor(1) as pool:
            early = run_files.start_order_sweep(load_case(case_file), pool)
            assert early is not None
            key, _ = early.result()
        assert key == run_files._sweep_key(
            solution.geometry, run_files._sweep_angles(solution.alpha)
        )


def test_an_early_sweep_of_another_bearing_is_not_used(tmp_path: Path) -> None:
    from concurrent.futures import Future

    from runout.case.model import load_case
    from runout.report import run_files
    from runout.runner import run_model

    case_file = tmp_path / "case.toml"
    case_file.write_text(CASE, encoding="utf-8")
    other = tmp_path / "other.toml"
    other.write_text(CASE.replace('radial_clearance = "10 um"', 'radial_clearance = "20 um"'))
    result = run_model(load_case(case_file))
    solution = run_files._roller_solution(result)
    assert solution is not None
    wrong: Future[object] = Future()
    swept = run_files._order_sweep(run_files._roller_solution(run_model(load_case(other))))
    wrong.set_result((("another bearing",), swept))
    written = run_files.write_result(result, tmp_path / "out", early_sweep=wrong)
    assert written
    fresh = run_files._write_order_sweep(run_files._order_sweep(solution), tmp_path / "f.csv")
    assert _rows(tmp_path / "out" / "order_sweep.csv") == _rows(fresh)
