"""Streaming statistics of a Monte Carlo through the real command line (issue 31).

``[study] statistics = "streaming"`` reduces every chunk as it arrives: the summary is the same,
byte for byte, for any worker count and chunk size; the mean and std are the exact ones (the
exact sum rounded once, as the exact mode's columns give them); the percentiles are within the
sketch's relative accuracy; memory does not grow with the samples. ``"auto"`` streams a lot
whose columns do not fit the budget (said in ``notes``), ``"exact"`` refuses it naming the key.
"""

from __future__ import annotations

import csv
import json
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

from peak_memory import peak_rss
from runout.case.estimates import estimate_run, estimate_study
from runout.case.model import load_case

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "seed001_kim_table9.toml"
ALPHA = 1e-4  # the sketch's relative accuracy, as summary.json states it


def cli(*args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    import os

    exe = [sys.executable, "-m", "runout.cli", *args]
    full = None if env is None else {**os.environ, **env}
    return subprocess.run(exe, capture_output=True, text=True, check=False, timeout=300, env=full)


def lot(
    tmp_path: Path, samples: int, statistics: str, chunk: int | None = 250, instants: int = 256
) -> Path:
    """Seed 001 Table 9 with ``samples`` bearings (8 revolutions: the f_c lines resolved)."""
    text = EXAMPLE.read_text().replace("samples = 1000\n", f"samples = {samples}\n", 1)
    text = text.replace("samples = 1024", f"samples = {instants}", 1)
    if instants < 128:  # the cheapest record: one revolution
        text = text.replace("revolutions = 8 ", "revolutions = 1 ", 1)
    size = "" if chunk is None else f"chunk_size = {chunk}\n"  # None: chosen from the cost
    text = text.replace("[study]\n", f'[study]\nstatistics = "{statistics}"\n{size}', 1)
    path = tmp_path / f"lot_{statistics}_{samples}_{chunk}_{instants}.toml"
    path.write_text(text)
    return path


def test_streaming_summary_is_the_same_for_any_workers_and_chunk_size(tmp_path: Path) -> None:
    runs = {
        "one": (lot(tmp_path, 300, "streaming", chunk=50), []),
        "two": (lot(tmp_path, 300, "streaming", chunk=50), ["--workers", "2"]),
        "chunk": (lot(tmp_path, 300, "streaming", chunk=64), []),
        "chosen": (lot(tmp_path, 300, "streaming", chunk=None), []),
    }
    summaries = {}
    for name, (path, extra) in runs.items():
        out = tmp_path / name
        done = cli("study", str(path), "--out", str(out), *extra)
        assert done.returncode == 0, done.stderr
        summaries[name] = (out / "summary.json").read_text()
        assert (out / "samples.csv").is_file()  # from the chunk files
        # drawn from the summary's bins (the per-sample values are not kept)
        assert (out / "histograms.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert summaries["one"] == summaries["two"] == summaries["chunk"] == summaries["chosen"]
    summary = json.loads(summaries["one"])
    assert summary["statistics"] == "streaming" and summary["quantile_relative_error"] == ALPHA
    assert any("histograms.png is drawn from the summary's bins" in n for n in summary["notes"])
    assert summary["components"], "the f_c lines must be there to be compared"


def test_streaming_moments_are_exact_and_percentiles_within_alpha(tmp_path: Path) -> None:
    stream, exact = tmp_path / "s", tmp_path / "e"
    # "auto" within the budget is the exact mode
    for path, out in (
        (lot(tmp_path, 300, "streaming", 50), stream),
        (lot(tmp_path, 300, "auto", 50), exact),
    ):
        done = cli("study", str(path), "--out", str(out))
        assert done.returncode == 0, done.stderr
    s = json.loads((stream / "summary.json").read_text())
    e = json.loads((exact / "summary.json").read_text())
    assert "statistics" not in e and "notes" not in e  # the exact mode's output is unchanged
    with (exact / "samples.csv").open() as fh:
        rows = list(csv.DictReader(fh))
    radial = [Fraction(row["radial_pp_m"]) for row in rows]  # repr: the float64 exactly
    n = len(radial)
    mean = sum(radial, Fraction(0)) / n
    variance = sum(((x - mean) ** 2 for x in radial), Fraction(0)) / (n - 1)
    assert s["runout"]["radial_pp_m"]["mean"] == float(mean)  # the exact sum, rounded once
    assert s["runout"]["radial_pp_m"]["std"] == float(variance) ** 0.5
    pairs = [(s["runout"][k], e["runout"][k]) for k in s["runout"]]
    assert [c["label"] for c in s["components"]] == [c["label"] for c in e["components"]]
    pairs += [(a["pp_m"], b["pp_m"]) for a, b in zip(s["components"], e["components"], strict=True)]
    for got, want in pairs:
        if want["mean"] is None:
            assert got["mean"] is None
            continue
        # numpy's mean and std (pairwise sums) are within a few ulps of the exact ones
        for key in ("mean", "std"):
            assert abs(got[key] - want[key]) <= 1e-14 * abs(want[key]), (key, got, want)
        for key in ("min", "max"):
            assert got[key] == want[key]
        for key in ("p5", "p50", "p95"):
            assert abs(got[key] - want[key]) <= ALPHA * abs(want["max"]), (key, got, want)
            assert abs(got[key] - want[key]) <= 1.000001 * ALPHA * abs(want[key]), (key, got, want)
        assert sum(got["histogram"]["counts"]) == sum(want["histogram"]["counts"])
        assert got["histogram"]["edges"] == want["histogram"]["edges"]


def test_streaming_writes_the_samples_of_the_exact_mode_from_its_chunks(tmp_path: Path) -> None:
    """With --out a streaming study writes samples.csv and samples_columns.json after the run,
    one chunk file at a time: the exact mode's columns and values (the order of two lines whose
    mean p-p tie to round-off may differ: compared by column name)."""
    tables = {}
    for statistics, chunk in (("streaming", 64), ("exact", 50)):
        out = tmp_path / statistics
        done = cli("study", str(lot(tmp_path, 300, statistics, chunk)), "--out", str(out))
        assert done.returncode == 0, done.stderr
        assert "samples.csv, samples_columns.json" in done.stdout  # the "wrote" line
        with (out / "samples.csv").open() as fh:
            rows = list(csv.reader(fh))
        columns = {name: [row[i] for row in rows[1:]] for i, name in enumerate(rows[0])}
        assert len(columns) == len(rows[0]) and len(rows) == 301
        described = json.loads((out / "samples_columns.json").read_text())
        assert list(described["units"]) == rows[0]
        tables[statistics] = (columns, described["units"], described["columns"])
    assert tables["streaming"] == tables["exact"]


def test_auto_streams_a_lot_whose_columns_exceed_the_budget(tmp_path: Path) -> None:
    # a lot large enough for its columns to outweigh the sketches (~1 MiB a column)
    path = lot(tmp_path, 200_000, "auto", chunk=1000, instants=64)
    case = load_case(path)
    per_run = estimate_run(case, case.analysis.model)
    exact = estimate_study(case, per_run, "exact").memory
    streaming = estimate_study(case, per_run, "streaming").memory
    assert streaming < exact
    limit = {"RUNOUT_MAX_MEMORY": f"{int((exact + streaming) / 2)} B"}
    readable = cli("study", str(path), "--out", str(tmp_path / "o"), env=limit)
    assert readable.returncode == 0, readable.stderr
    assert 'note: study.statistics = "auto"' in readable.stdout
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert summary["statistics"] == "streaming" and summary["samples"] == 200_000
    assert 'study.statistics = "auto"' in summary["notes"][0]
    # "exact" refuses the same lot, naming the key and the remedy
    exact_path = lot(tmp_path, 200_000, "exact", chunk=1000, instants=64)
    for command in ("check", "study"):
        refused = cli(command, str(exact_path), env=limit)
        assert refused.returncode == 2, refused.stderr
        assert "study.statistics" in refused.stderr and '"streaming"' in refused.stderr
        assert str(exact_path) in refused.stderr


def test_streaming_directory_reloads_resumes_and_reports(tmp_path: Path) -> None:
    path = lot(tmp_path, 300, "streaming", chunk=50)
    out = tmp_path / "o"
    assert cli("study", str(path), "--out", str(out)).returncode == 0
    first = (out / "summary.json").read_text()
    # an interrupted run: two chunks lost, resumed
    manifest = json.loads((out / "manifest.json").read_text())
    manifest["done"] = manifest["done"][:-2]
    manifest["complete"] = False
    (out / "manifest.json").write_text(json.dumps(manifest))
    for name in ("chunk_00004.json", "chunk_00005.json"):
        (out / "chunks" / name).unlink()
    assert cli("study", str(path), "--out", str(out), "--resume").returncode == 0
    assert (out / "summary.json").read_text() == first
    done = cli("report", str(out))
    assert done.returncode == 0, done.stderr
    from runout.study.run import StudyError, load_study

    result = load_study(out, load_case(path))
    assert (
        json.loads(first)["runout"]["radial_pp_m"]["mean"]
        == result.summary()["runout"]["radial_pp_m"]["mean"]
    )
    # statistics changes no sample: the exact mode resumes the streaming run's chunks
    exact = cli("study", str(lot(tmp_path, 300, "exact", chunk=50)), "--out", str(out), "--resume")
    assert exact.returncode == 0 and "recomputing" not in exact.stderr, exact.stderr
    assert (out / "samples.csv").is_file()
    try:
        result.to_dataframe()
    except StudyError as exc:
        assert 'statistics = "exact"' in str(exc)
    else:
        raise AssertionError("a streaming result has no per-sample table")


def test_streaming_memory_does_not_grow_with_samples(tmp_path: Path) -> None:
    """2x10^4 and 8x10^4 bearings of the cheapest record: the exact columns grow (the test
    can fail), the streaming statistics do not (chunks in flight and the sketches only)."""
    growth = {}
    for mode in ("exact", "streaming"):
        peaks = []
        for samples in (20_000, 80_000):
            path = lot(tmp_path, samples, mode, chunk=250, instants=64)
            peaks.append(peak_rss([sys.executable, "-m", "runout.cli", "study", str(path)]))
        growth[mode] = peaks[1] - peaks[0]
    assert growth["exact"] > 5 * 2**20, growth  # 60,000 samples x ~ 170 B of columns
    # streaming: nothing per sample; what remains is allocator noise, well under the
    # columns of the 60,000 samples the larger lot adds
    assert growth["streaming"] < growth["exact"] / 4, growth


def test_streamed_histograms_have_the_exact_modes_panels(tmp_path: Path) -> None:
    """The streaming figure draws the exact mode's panels, from bins holding every sample."""
    import matplotlib

    matplotlib.use("Agg")
    from runout.report.plotting import streamed_histograms, study_figures
    from runout.study.run import run_study

    stream = run_study(load_case(lot(tmp_path, 120, "streaming", 40)), plots=False)
    exact = run_study(load_case(lot(tmp_path, 120, "exact", 40)), plots=False)
    summary = stream.summary()
    figure = streamed_histograms(summary, limit_quantity="nrro_pp_m", limit_m=2e-7)
    reference = study_figures(exact, limit_quantity="nrro_pp_m", limit_m=2e-7)["histograms.png"]

    def titles(fig: object) -> list[str]:
        return [ax.get_title() for ax in fig.axes if ax.get_visible()]  # type: ignore[attr-defined]

    assert titles(figure) == titles(reference) and titles(figure)
    for ax in figure.axes:
        if not ax.get_visible():
            continue
        (stairs,) = ax.patches
        # one bin per histogram bin, holding every sample that ran
        heights = stairs.get_data().values
        assert heights.sum() == summary["samples"] - summary["failed"]
    limits = [line for ax in figure.axes for line in ax.get_lines() if "limit" in line.get_label()]
    assert len(limits) == 1
