"""Run every ``benchmarks/bench_*.py`` and print our time, the reference's, and the ratio.

Each module defines functions named ``bench_*`` that take no argument and return a
:class:`_harness.BenchResult`. Exit status 1 when a target is missed.
"""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from _harness import BenchResult  # noqa: E402


def _load(path: Path):  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location(path.stem, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


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
                f"{result.name:<48} ours {result.ours_s * 1e3:10.3f} ms   "
                f"{result.reference:<28} {result.reference_s * 1e3:10.3f} ms   "
                f"x{result.ratio:9.1f}   target: {result.target}   "
                f"{'met' if result.met else 'MISSED'}",
                flush=True,
            )
    missed = [r for r in results if not r.met]
    print(f"{len(results)} benchmarks, {len(missed)} missed")
    return 1 if missed else 0


if __name__ == "__main__":
    raise SystemExit(main())
