"""`make demo`: the first job on a fresh clone.

Validates the case file of every seed bearing, prints its derived geometry, Hertz contact
constants and characteristic frequencies through the real command line, one comparison table,
then runs four models: Tada's HDD bearing with the Fig. 7 wavinesses (3-D quasi-static NRRO),
the Anderon 608 (linear model, band values), the NU209 roller bearing (radial runout) and an HDD
spindle on two of Tada's bearings (runout at the hub, tilt), and a
Monte Carlo over 1000 of Kim's spindle bearings with random ball sizes. Plots, data and one
self-contained HTML report (out/demo/report.html) are written to out/demo/.
"""

from __future__ import annotations

import math
import shutil
import subprocess
import sys
from pathlib import Path

from rich.console import Console
from rich.markup import escape
from rich.table import Table

from runout.case.model import load_case
from runout.report.page import build_combined_report
from runout.report.summary import bearing_summary

HERE = Path(__file__).resolve().parent
console = Console(width=max(110, Console().width))


def _runout(*args: str) -> None:
    exe = shutil.which("runout") or str(Path(sys.executable).with_name("runout"))
    console.rule(f"runout {' '.join(args)}")
    subprocess.run([exe, *args], check=True)


def main() -> None:
    cases = sorted(HERE.glob("seed*.toml"))
    first = HERE / "seed000_tada_fig7.toml"
    _runout(
        "check", str(first.relative_to(Path.cwd()) if first.is_relative_to(Path.cwd()) else first)
    )
    _runout("frequencies", str(HERE / "seed002_608.toml"))

    table = Table(
        title="The seed bearings: operating contact angle and characteristic frequencies (orders)",
        header_style="bold",
    )
    for col in ("case", "Z", "D [mm]", "d_m [mm]", "α [deg]", "f_c", "f_b", "BPFI", "BPFO"):
        table.add_column(escape(col), justify="left" if col == "case" else "right")
    for path in cases:
        case = load_case(path)
        summary = bearing_summary(case.bearing, case.operation)
        orders = summary.frequencies.orders()
        b = case.bearing
        table.add_row(
            path.stem,
            str(b.elements),
            f"{b.element_diameter * 1e3:.4g}",
            f"{b.pitch_diameter * 1e3:.5g}",
            f"{math.degrees(summary.contact_angle):.3f}",
            f"{orders['cage']:.5f}",
            f"{orders['ball_spin']:.4f}",
            f"{orders['ball_pass_inner']:.4f}",
            f"{orders['ball_pass_outer']:.4f}",
        )
    console.print(table)
    out = Path("out") / "demo"
    runs = {
        "tada_fig7": "seed000_tada_fig7.toml",
        "anderon_608": "seed002_608.toml",
        "nu209": "seed004_nu209.toml",
        "spindle_hdd": "spindle_hdd.toml",
    }
    for name, case_file in runs.items():
        _runout("run", str(HERE / case_file), "--out", str(out / name), "--report")
    # A small Monte Carlo: 1000 of Kim's spindle bearings with random ball diameters.
    _runout("study", str(HERE / "seed001_kim_table9.toml"), "--out", str(out / "montecarlo"))
    report = build_combined_report(
        [out / name for name in (*runs, "montecarlo")],
        out / "report.html",
        title="runout demo: Tada's HDD bearing, the Anderon 608, the NU209, an HDD spindle, "
        "a Monte Carlo lot",
    )
    console.rule("done")
    console.print(
        f"Report: {report.resolve()}  (one page, figures embedded; each run also has its own "
        f"report.html and data in {out}/<run>/). Orders are per revolution of the rotating ring. "
        "Next: `runout check <case>` on your own bearing (see README, 'Five-minute tour')."
    )


if __name__ == "__main__":
    main()
