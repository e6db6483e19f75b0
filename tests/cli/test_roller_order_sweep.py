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


def test_a_sweep_harmonic_that_makes_a_part_non_convex_is_an_empty_cell(tmp_path: Path) -> None:
    """1 µm of 22 to 24 lobes on a ball of 0.5 mm radius is not convex (a k^2 near the radius):
    outside the rigid model, which refuses such a part in a run; the sweep leaves it empty
    rather than state a runout its warm and cold Newton starts can disagree on."""
    from runout.geometry.imperfections import single_harmonic
    from runout.models._roller_setup import _convexity_margin

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
    header, *rows = (out / "order_sweep.csv").read_text(encoding="utf-8").splitlines()
    assert "or makes its part non-convex (outside the rigid model)" in header
    table = {int(r["order"]): r for r in csv.DictReader(rows)}
    non_convex = [k for k in table if _convexity_margin(0.5e-3, single_harmonic(k, 1e-6)) < 0.05]
    assert non_convex, "orders near 3Z make the 1 mm balls non-convex"
    for k in non_convex:
        assert table[k]["roller_pp_m"] == "", k
