"""Run every ``benchmarks/bench_*.py``; print, and write out/bench.json and out/bench.md.

Each module defines functions named ``bench_*`` that take no argument and return a
:class:`_harness.BenchResult`. Arguments select benchmarks whose function name contains one of
them. The results of the run go to ``out/bench.json`` (one object per benchmark, times in
seconds) and ``out/bench.md`` (a Markdown table: benchmark, ours, reference, ratio, target,
met) so that BENCHMARKS.md can show the figures of one run. Exit status 1 when a target is
missed.
"""

from __future__ import annotations

import datetime as _dt
import importlib.util
import json
import os
import platform
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
OUT = HERE.parent / "out"
sys.path.insert(0, str(HERE))

from _harness import BenchResult  # noqa: E402


def _load(path: Path):  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location(path.stem, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _value(value: float, unit: str) -> str:
    """A benchmark's figure in its unit (durations scaled to s, ms or µs)."""
    return _time(value) if unit == "s" else f"{value:.3g} {unit}"


def _time(seconds: float) -> str:
    """A duration with a unit that keeps 3-4 significant digits."""
    if seconds >= 1.0:
        return f"{seconds:.3g} s"
    if seconds >= 1e-3:
        return f"{seconds * 1e3:.3g} ms"
    return f"{seconds * 1e6:.3g} µs"


def _cell(text: str) -> str:
    return text.replace("|", "\\|")


def markdown(results: list[BenchResult], machine: str) -> str:
    """The Markdown table of a run (one row per benchmark)."""
    lines = [
        f"Run of {_dt.datetime.now(_dt.UTC):%Y-%m-%d %H:%M} UTC on {machine}. Ratio: the "
        "reference's time over ours (above 1: ours is faster); best of several runs each.",
        "",
        "| benchmark | ours | reference (same run) | ratio | target | met |",
        "|---|---|---|---|---|---|",
    ]
    for r in results:
        lines.append(
            f"| {_cell(r.name)} | {_value(r.ours_s, r.unit)} | {_cell(r.reference)}: "
            f"{_value(r.reference_s, r.unit)} | ×{r.ratio:.3g} | {_cell(r.target)} | "
            f"{'yes' if r.met else '**no**'} |"
        )
    return "\n".join(lines) + "\n"


def write_outputs(results: list[BenchResult], out: Path = OUT) -> tuple[Path, Path]:
    """Write ``bench.json`` and ``bench.md`` of a run into ``out``."""
    out.mkdir(parents=True, exist_ok=True)
    machine = f"{platform.machine()}, {os.cpu_count()} CPUs, Python {platform.python_version()}"
    payload = {
        "machine": machine,
        "selection": sys.argv[1:],
        "load_average": list(os.getloadavg()) if hasattr(os, "getloadavg") else None,
        "benchmarks": [
            {
                "name": r.name,
                "ours_s": r.ours_s,
                "reference": r.reference,
                "reference_s": r.reference_s,
                "ratio": r.ratio,
                "target": r.target,
                "met": r.met,
                "unit": r.unit,
            }
            for r in results
        ],
    }
    json_path = out / "bench.json"
    json_path.write_text(json.dumps(payload, indent=2) + "\n")
    md_path = out / "bench.md"
    md_path.write_text(markdown(results, machine))
    return json_path, md_path


def main() -> int:
    only = sys.argv[1:]
    results: list[BenchResult] = []
    for path in sorted(HERE.glob("bench_*.py")):
        module = _load(path)
        for name in sorted(dir(module)):
            if not name.startswith("bench_") or (only and not any(o in name for o in only)):
                continue
            result = getattr(module, name)()
            results.append(result)
            print(
                f"{result.name:<48} ours {_value(result.ours_s, result.unit):>12}   "
                f"{result.reference:<28} {_value(result.reference_s, result.unit):>12}   "
                f"x{result.ratio:9.1f}   target: {result.target}   "
                f"{'met' if result.met else 'MISSED'}",
                flush=True,
            )
    missed = [r for r in results if not r.met]
    json_path, md_path = write_outputs(results)
    print(f"{len(results)} benchmarks, {len(missed)} missed; written {json_path}, {md_path}")
    return 1 if missed else 0


if __name__ == "__main__":
    raise SystemExit(main())
