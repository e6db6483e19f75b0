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
