"""Study pages of the report (:mod:`runout.report.page`): Monte Carlo statistics and sweep points.

A study directory (``runout study CASE --out DIR``) holds ``summary.json`` (statistics per
output), ``samples.csv`` (one row per sample or sweep point) and the figures. The statistics
table has one row per output with the mean, standard deviation and percentiles at one unit
per row; p99, which the JSON does not hold, is taken from ``samples.csv``.
"""

from __future__ import annotations

import csv
import io
import math
import os
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from runout.base.reading import InputFileError, open_regular
from runout.io.study_columns import line_columns, read_columns
from runout.report._html import (
    QUANTITY_NAMES,
    RUNOUT_KEYS,
    card,
    common_unit,
    esc,
    fmt_number,
    length,
    meta_line,
    num,
    quantity_name,
    table,
)

__all__ = ["STUDY_SUMMARY_SHAPE", "study_first_screen", "study_statistics"]

_STATS = {k: "number" for k in ("mean", "std", "p5", "p50", "p95", "max", "min")}
#: The shape of a study's ``summary.json`` that the report relies on
#: (:func:`runout.base.reading.check_shape`).
STUDY_SUMMARY_SHAPE: dict[str, Any] = {
    "title": "string",
    "kind": "string",
    "models": ["string"],
    "quantities": ["string"],
    "samples": "number",
    "failed": "number",
    "notes": ["string"],
    "errors": ["string"],
    "runout": {k: _STATS for k in RUNOUT_KEYS},
    "components": [
        {"direction": "string", "frequency_hz": "number", "label": "string", "pp_m": _STATS}
    ],
    "yield": {
        "quantity": "string",
        "fraction": "number",
        "ci_low": "number",
        "ci_high": "number",
        "confidence": "number",
        "limit_m": "number",
        "limit_um_per_s": "number",
        "passed": "number",
        "samples": "number",
    },
}
#: Largest ``samples.csv`` a report reads [B] (a study of 10^5 samples and 50 outputs: ~75 MB).
MAX_SAMPLES_CSV_BYTES = 512 * 1024 * 1024


@contextmanager
def _open_samples(path: Path) -> Iterator[io.TextIOWrapper]:
    """``samples.csv`` as text: only a regular file inside its directory, of a bounded size."""
    with open_regular(path, [path.parent]) as raw:
        size = os.fstat(raw.fileno()).st_size
        if size > MAX_SAMPLES_CSV_BYTES:
            raise InputFileError(
                str(path), "", f"is larger than {MAX_SAMPLES_CSV_BYTES // 2**20} MiB"
            )
        with io.TextIOWrapper(raw, encoding="utf-8", newline="") as handle:
            try:
                yield handle
            except UnicodeDecodeError:
                raise InputFileError(str(path), "", "is not UTF-8 text") from None
            except csv.Error as exc:
                raise InputFileError(str(path), "", f"is not CSV ({exc})") from None


def _samples_columns(directory: Path) -> dict[str, list[float]]:
    """Finite numbers of every column of ``samples.csv`` (empty when there is none)."""
    path = directory / "samples.csv"
    columns: dict[str, list[float]] = {}
    if not (path.exists() or path.is_symlink()):
        return columns
    with _open_samples(path) as handle:
        for record in csv.DictReader(handle):
            for key, text in record.items():
                if key is None:
                    continue
                try:
                    value = float(text)
                except (TypeError, ValueError):
                    continue
                if math.isfinite(value):
                    columns.setdefault(key, []).append(value)
    return columns


def _percentile(values: list[float], q: float) -> float | None:
    """Linear-interpolation percentile (numpy's default) of ``values``; None when empty."""
    if not values:
        return None
    ordered = sorted(values)
    pos = q / 100.0 * (len(ordered) - 1)
    lo = math.floor(pos)
    hi = min(lo + 1, len(ordered) - 1)
    return ordered[lo] + (ordered[hi] - ordered[lo]) * (pos - lo)


def study_first_screen(study: dict[str, Any], case: Any, directory: Path) -> list[str]:
    """HTML of a study's first screen: what was varied, headline statistics and the yield."""
    kind = study.get("kind", "study")
    models = ", ".join(study.get("models") or [])
    varied = ", ".join(study.get("quantities") or [])
    count = study.get("samples")
    what = (
        f"Monte Carlo over {count} samples" if kind == "montecarlo" else f"sweep of {count} points"
    )
    failed = study.get("failed") or 0
    words = [what, f"varied: {varied}" if varied else "", f"{failed} failed" if failed else ""]
    parts = [
        f"<p class='what'>{esc(' · '.join(w for w in words if w))}</p>",
        meta_line(models or "study", directory),
    ]
    stats: dict[str, Any] = study["runout"] if isinstance(study.get("runout"), dict) else {}
    cards = []
    radial = stats.get("radial_pp_m") if isinstance(stats.get("radial_pp_m"), dict) else None
    if radial and kind == "montecarlo":
        unit = common_unit([radial.get("mean"), radial.get("p95"), radial.get("max")])
        cards.append(card("radial p-p, mean", length(num(radial.get("mean")), unit)))
        cards.append(card("radial p-p, p95", length(num(radial.get("p95")), unit)))
        nrro = stats.get("nrro_pp_m")
        if isinstance(nrro, dict):
            cards.append(card("NRRO p-p, p95", length(num(nrro.get("p95")), unit)))
    yld = study.get("yield")
    if isinstance(yld, dict):
        fraction = num(yld.get("fraction"))
        low, high = num(yld.get("ci_low")), num(yld.get("ci_high"))
        if "limit_m" in yld:
            limit = length(num(yld.get("limit_m")))
        else:
            limit = f"{fmt_number(num(yld.get('limit_um_per_s')), 4)} um/s"
        confidence = num(yld.get("confidence"))
        cards.append(
            card(
                f"yield ({quantity_name(str(yld.get('quantity', '')))} ≤ {limit})",
                f"{fraction * 100:.1f} %" if fraction is not None else "—",
                f"{yld.get('passed')} of {yld.get('samples')}; "
                + (
                    f"{confidence * 100:.0f} % CI {low * 100:.1f}–{high * 100:.1f} %"
                    if low is not None and high is not None and confidence is not None
                    else ""
                ),
            )
        )
    if cards:
        parts.append("<div class='cards'>" + "".join(cards) + "</div>")
    return parts


_STAT_COLUMNS = ("mean", "std", "p50", "p95", "p99", "max")


def study_statistics(study: dict[str, Any], directory: Path) -> list[str]:
    """HTML of the statistics table (Monte Carlo) or of the sweep points (sweep)."""
    samples = _samples_columns(directory)
    rows: list[list[str]] = []
    outputs: list[tuple[str, str, dict[str, Any]]] = []
    runout = study.get("runout") or {}
    ordered = [k for k in RUNOUT_KEYS if k in runout] + [k for k in runout if k not in RUNOUT_KEYS]
    for key in ordered:
        stats = runout[key]
        if isinstance(stats, dict):
            name = QUANTITY_NAMES.get(key[:-2], key) if key.endswith("_m") else key
            outputs.append((str(name), str(key), stats))
    # the line columns by samples_columns.json; a study of an earlier version has none and
    # named a line's column by its direction, frequency and label
    named = line_columns(directory)
    for c in (study.get("components") or [])[:12]:
        stats = c.get("pp_m")
        if isinstance(stats, dict):
            hz = fmt_number(num(c.get("frequency_hz")), 6)
            name = f"{c.get('direction', '')} {hz} Hz {c.get('label', '')}"
            if named is not None:
                column = named.get((str(c.get("direction")), str(c.get("label"))), "")
            else:
                column = (
                    f"{c.get('direction')} {_csv_hz(c.get('frequency_hz'))} Hz "
                    f"{c.get('label')} pp_m"
                )
            outputs.append((name, column, stats))
    if study.get("kind") == "montecarlo":
        for name, column, stats in outputs:
            values = dict(stats)
            if "p99" not in values:
                values["p99"] = _percentile(samples.get(column, []), 99.0)
            unit = common_unit(values.get(k) for k in _STAT_COLUMNS)
            rows.append(
                [esc(name)]
                + [esc(length(num(values.get(k)), unit).rsplit(" ", 1)[0]) for k in _STAT_COLUMNS]
                + [esc(unit[0])]
            )
        parts = [
            "<h2>Statistics over the lot</h2>",
            table(["output (p-p)", *_STAT_COLUMNS, "unit"], rows, numeric=(1, 2, 3, 4, 5, 6)),
        ]
        if not samples:
            parts.append("<p class='muted'>p99 needs samples.csv, which this directory lacks.</p>")
        return parts
    # a sweep: one row per point from samples.csv
    return _sweep_table(directory)


def _csv_hz(value: Any) -> str:
    """The frequency as samples.csv writes it in a column name (6 significant digits)."""
    number = num(value)
    return f"{number:.6g}" if number is not None else ""


def _sweep_table(directory: Path) -> list[str]:
    path = directory / "samples.csv"
    if not (path.exists() or path.is_symlink()):
        return []
    with _open_samples(path) as handle:
        records = list(csv.DictReader(handle))
    if not records:
        return []
    keys = [k for k in records[0] if k not in ("sample",)]
    runout = [k for k in RUNOUT_KEYS if k in keys]
    inputs = [k for k in keys if k not in runout and not k.endswith("pp_m")]
    described = read_columns(directory)
    titles = {k: _input_title(k, described) for k in inputs}
    values = [num(_float(r.get(k))) for r in records for k in runout]
    unit = common_unit(values)
    rows = []
    for r in records[:200]:
        cells = [esc(_cell(r.get(k, ""))) for k in inputs]
        cells += [esc(length(_float(r.get(k)), unit).rsplit(" ", 1)[0]) for k in runout]
        rows.append(cells)
    header = [titles[k] for k in inputs] + [f"{QUANTITY_NAMES[k[:-2]]} [{unit[0]}]" for k in runout]
    return [
        "<h2>Sweep points</h2>",
        table(header, rows, numeric=tuple(range(len(inputs), len(header)))),
    ]


def _input_title(column: str, described: dict[str, Any] | None) -> str:
    """Heading of an input column of the sweep table: the case key it varies (with the
    element number of a per-element draw), or the column's name."""
    info = (described or {}).get("columns", {}).get(column)
    if not isinstance(info, dict) or "key" not in info:
        return column
    element = info.get("element")
    return f"{info['key']} {element}" if element is not None else str(info["key"])


def _cell(text: str) -> str:
    """A swept value as a number of 6 significant digits (46.6667, not 46.66666666666667)."""
    value = _float(text)
    return fmt_number(value, 6) if value is not None else text


def _float(text: Any) -> float | None:
    try:
        value = float(text)
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None
