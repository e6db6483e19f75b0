"""Self-contained HTML report of a run directory (`runout report DIR`, `runout run --report`).

A run directory is what ``runout run CASE --out DIR`` writes: ``result.json`` (the JSON
contract), ``summary.json`` (derived geometry, contacts, frequencies), ``case.toml`` (the
input as given), CSV data and PNG figures. The report puts all of it on one page with the
figures embedded, so the file can be mailed or archived on its own.
"""

from __future__ import annotations

import base64
import datetime as _dt
import html
import json
from pathlib import Path
from typing import Any

from runout import __version__
from runout.errors import RunoutError

__all__ = ["build_combined_report", "build_report"]

# Figure file name -> caption. Unknown PNGs are embedded too, captioned by their name.
CAPTIONS = {
    "history.png": "Time history of the measured ring's centre (about its mean).",
    "orbit.png": "Orbit (Lissajous figure) of the ring centre in the radial plane.",
    "lines.png": "Spectral lines, peak-to-peak, against order; the largest are labelled.",
    "density_waveform.png": "Displacement density dx/dθ over the inner ring's rotation.",
    "anderon_spectrum.png": "Anderon spectrum (displacement density per band) on log axes.",
    "anderon_bands.png": "Anderon band values.",
    "displacement.png": "Inner-ring displacement over the rotation (runout).",
    "contact_pattern.png": "Which rolling elements touch at each rotation angle.",
    "order_sweep.png": "Runout against the harmonic order of each part.",
}

STYLE = """
body { font-family: -apple-system, 'Segoe UI', Helvetica, Arial, sans-serif; margin: 2em auto;
       max-width: 1100px; color: #1b1b1b; line-height: 1.4; padding: 0 1em; }
h1 { font-size: 1.6em; margin-top: 1.6em; border-bottom: 2px solid #2b5c8a; padding-bottom: .3em; }
h2 { font-size: 1.25em; color: #2b5c8a; margin-top: 1.8em; }
table { border-collapse: collapse; margin: .6em 0; font-size: .92em; }
th, td { border: 1px solid #c9d3dd; padding: .25em .6em; text-align: left; vertical-align: top; }
th { background: #eef3f8; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
figure { margin: 1em 0; } figure img { max-width: 100%; border: 1px solid #dde; }
figcaption { font-size: .9em; color: #555; }
pre { background: #f6f8fa; padding: .8em; overflow-x: auto; font-size: .85em; }
.meta { color: #555; font-size: .9em; } .note { background: #fff8e1; padding: .5em .8em; }
"""


def _esc(value: object) -> str:
    return html.escape(str(value))


def _fmt(value: Any) -> str:
    if isinstance(value, bool) or value is None:
        return "—" if value is None else str(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if value == 0.0:
            return "0"
        return f"{value:.6g}"
    return str(value)


def _unit_of(key: str) -> tuple[str, float, str]:
    """Display name, scale and unit for a JSON key with its SI unit as suffix."""
    table = {
        "_pp_m": (1e9, "nm (p-p)"),
        "_m": (1e3, "mm"),
        "_deg": (1.0, "deg"),
        "_hz": (1.0, "Hz"),
        "_n": (1.0, "N"),
        "_pa": (1e-9, "GPa"),
        "_kg_per_m3": (1.0, "kg/m³"),
        "_per_m": (1e-3, "1/mm"),
        "_n_per_m1_5": (1.0, "N/m^1.5"),
    }
    for suffix, (scale, unit) in table.items():
        if key.endswith(suffix):
            return key[: -len(suffix)].replace("_", " "), scale, unit
    return key.replace("_", " "), 1.0, ""


def _kv_table(data: dict[str, Any], small_lengths_in_um: bool = False) -> str:
    rows = []
    for key, value in data.items():
        if isinstance(value, dict | list):
            continue
        name, scale, unit = _unit_of(key)
        if isinstance(value, int | float) and not isinstance(value, bool):
            shown = value * scale
            if small_lengths_in_um and unit == "mm" and 0 < abs(shown) < 0.1:
                shown, unit = value * 1e6, "µm"
            rows.append(
                f"<tr><td>{_esc(name)}</td><td class='num'>{_fmt(shown)}</td>"
                f"<td>{_esc(unit)}</td></tr>"
            )
        else:
            rows.append(f"<tr><td>{_esc(name)}</td><td>{_esc(_fmt(value))}</td><td></td></tr>")
    if not rows:
        return ""
    return (
        "<table><tr><th>quantity</th><th>value</th><th>unit</th></tr>" + "".join(rows) + "</table>"
    )


def _records_table(records: list[dict[str, Any]], columns: list[tuple[str, str]]) -> str:
    head = "".join(f"<th>{_esc(title)}</th>" for _, title in columns)
    body = []
    for rec in records:
        cells = []
        for key, _ in columns:
            value = rec.get(key)
            css = " class='num'" if isinstance(value, int | float) else ""
            cells.append(f"<td{css}>{_esc(_fmt(value))}</td>")
        body.append("<tr>" + "".join(cells) + "</tr>")
    return f"<table><tr>{head}</tr>{''.join(body)}</table>"


_STATS = ("mean", "std", "two_sigma", "p5", "p50", "p95")


def _stat_cell(value: Any, scale: float = 1e9) -> str:
    if isinstance(value, dict):
        parts = [
            f"{k.replace('two_sigma', '2σ')} {_fmt(value[k] * scale)}"
            for k in _STATS
            if isinstance(value.get(k), int | float)
        ]
        return ", ".join(parts)
    if isinstance(value, int | float):
        return _fmt(value * scale)
    return _fmt(value)


def _figure(path: Path) -> str:
    data = base64.b64encode(path.read_bytes()).decode("ascii")
    mime = "image/gif" if path.suffix == ".gif" else "image/png"
    caption = CAPTIONS.get(path.name, path.stem.replace("_", " "))
    return (
        f"<figure><img alt='{_esc(path.stem)}' src='data:{mime};base64,{data}'>"
        f"<figcaption>{_esc(caption)}</figcaption></figure>"
    )


def _read_json(path: Path) -> dict[str, Any]:
    try:
        loaded = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, json.JSONDecodeError) as exc:
        raise RunoutError(f"{path}: cannot be read as JSON ({exc})") from None
    if not isinstance(loaded, dict):
        raise RunoutError(f"{path}: expected a JSON object")
    return loaded


def build_report(directory: Path, output: Path | None = None) -> Path:
    """Write ``report.html`` for a run directory and return its path.

    Parameters
    ----------
    directory : Path
        A directory written by ``runout run CASE --out DIR`` (or ``runout study``).
    output : Path or None
        Where to write the page; default ``directory / "report.html"``.

    Raises
    ------
    RunoutError
        If the directory holds no ``result.json`` or ``study.json``.
    """
    title, body = _report_body(Path(directory))
    target = output or Path(directory) / "report.html"
    target.write_text(_page(title, body), encoding="utf-8")
    return target


def build_combined_report(
    directories: list[Path], output: Path, title: str = "runout report"
) -> Path:
    """One page holding the reports of several run directories, with a table of contents.

    Parameters
    ----------
    directories : list of Path
        Run directories (see :func:`build_report`).
    output : Path
        The HTML file to write.
    title : str
        Page title.
    """
    sections = []
    toc = []
    for k, directory in enumerate(directories, start=1):
        run_title, body = _report_body(Path(directory))
        toc.append(f"<li><a href='#run{k}'>{_esc(run_title)}</a></li>")
        sections.append(
            f"<section id='run{k}'>" + body.replace("<h1>", "<h1 class='run'>") + "</section>"
        )
    body = f"<h1>{_esc(title)}</h1><ol>{''.join(toc)}</ol>" + "".join(sections)
    output.parent.mkdir(parents=True, exist_ok=True)
    output.write_text(_page(title, body), encoding="utf-8")
    return output


def _page(title: str, body: str) -> str:
    return (
        "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>"
        f"<title>{_esc(title)} — runout report</title><style>{STYLE}</style></head><body>\n"
        + body
        + "\n</body></html>\n"
    )


def _report_body(directory: Path) -> tuple[str, str]:
    """Title and HTML body of the report of one run directory."""
    directory = Path(directory)
    if not directory.is_dir():
        raise RunoutError(f"{directory}: no such directory (run `runout run CASE --out DIR` first)")
    result_path = directory / "result.json"
    summary_path = directory / "summary.json"
    # `runout study --out DIR` writes manifest.json and its statistics in summary.json.
    is_study = (directory / "manifest.json").exists()
    if not result_path.exists() and not is_study:
        raise RunoutError(
            f"{directory}: holds no result.json or study manifest "
            "(write one with `runout run CASE --out DIR` or `runout study CASE --out DIR`)"
        )
    result = _read_json(result_path) if result_path.exists() else {}
    study = _read_json(summary_path) if is_study and summary_path.exists() else {}
    summary = _read_json(summary_path) if summary_path.exists() and not is_study else {}
    case_text = (
        (directory / "case.toml").read_text(encoding="utf-8")
        if (directory / "case.toml").exists()
        else ""
    )
    title = result.get("title") or study.get("title") or summary.get("title") or directory.name
    model = result.get("model") or study.get("model") or ""
    parts: list[str] = [
        f"<h1>{_esc(title)}</h1>",
        f"<p class='meta'>Model <b>{_esc(model or 'study')}</b> · runout {_esc(__version__)} · "
        f"generated {_dt.datetime.now(_dt.UTC).strftime('%Y-%m-%d %H:%M UTC')} · "
        f"directory {_esc(directory)}</p>",
        "<p class='meta'>Conventions: input amplitudes are zero-to-peak radius deviations; "
        "every output displacement is peak-to-peak; orders are waves per revolution of the "
        "rotating ring; RRO is the part synchronous with the rotating ring, NRRO the rest.</p>",
    ]
    if result.get("runout"):
        parts += ["<h2>Runout</h2>", _kv_table(result["runout"])]
    if summary.get("bearing"):
        parts += ["<h2>Bearing (inputs)</h2>", _kv_table(summary["bearing"], True)]
        material = summary["bearing"].get("material")
        if isinstance(material, dict):
            parts.append(_kv_table(material))
    if summary.get("derived"):
        parts += ["<h2>Derived geometry</h2>", _kv_table(summary["derived"], True)]
    if summary.get("axial_loading"):
        parts += ["<h3>Axial load</h3>", _kv_table(summary["axial_loading"], True)]
    freqs = result.get("frequencies_hz") or summary.get("frequencies_hz")
    if freqs:
        rotation = freqs.get("rotation") or 0.0
        rows = [
            {"name": k, "hz": v, "order": (v / rotation) if rotation else None}
            for k, v in freqs.items()
        ]
        angle = result.get("contact_angle_deg", summary.get("contact_angle_deg"))
        parts += [
            "<h2>Characteristic frequencies</h2>",
            f"<p>Operating contact angle {_fmt(angle)} deg.</p>" if angle is not None else "",
            _records_table(rows, [("name", "frequency"), ("hz", "Hz"), ("order", "order")]),
        ]
    if result.get("attribution"):
        rows = result["attribution"]
        cols = [
            k
            for k in rows[0]
            if k in ("part", "factor", "lobes", "formula", "order", "frequency_hz")
        ]
        parts += [
            "<h2>Attribution: which factor produces which frequency</h2>",
            _records_table(rows, [(c, c.replace("_", " ")) for c in cols]),
        ]
    if result.get("components"):
        comps = sorted(result["components"], key=lambda c: -c.get("pp_m", 0.0))[:40]
        rows = [{**c, "pp_nm": c.get("pp_m", 0.0) * 1e9} for c in comps]
        parts += [
            "<h2>Spectral lines (largest 40)</h2>",
            _records_table(
                rows,
                [
                    ("direction", "dir."),
                    ("frequency_hz", "Hz"),
                    ("order", "order"),
                    ("pp_nm", "p-p [nm]"),
                    ("label", "source (part, lobes, formula)"),
                ],
            ),
        ]
    if result.get("anderon"):
        parts += ["<h2>Anderon band values [Anderon]</h2>", _kv_table(result["anderon"])]
    for key in ("mean_displacement_m", "natural_frequencies_hz"):
        if key in result:
            name, scale, unit = _unit_of(key)
            values = result[key] if isinstance(result[key], list) else [result[key]]
            shown = ", ".join(_fmt(v * scale) for v in values if isinstance(v, int | float))
            parts.append(f"<p><b>{_esc(name)}</b>: {_esc(shown)} {_esc(unit)}</p>")
    if study:
        parts.append("<h2>Study statistics</h2>")
        if "samples" in study:
            parts.append(f"<p>{_esc(study['samples'])} samples.</p>")
        if isinstance(study.get("runout"), dict):
            rows = [{"quantity": k, "stats": _stat_cell(v)} for k, v in study["runout"].items()]
            parts.append(_records_table(rows, [("quantity", "runout"), ("stats", "nm")]))
        if isinstance(study.get("components"), list):
            rows = [
                {
                    "direction": c.get("direction"),
                    "frequency_hz": c.get("frequency_hz"),
                    "label": c.get("label"),
                    "stats": _stat_cell(c.get("pp_m")),
                }
                for c in study["components"][:30]
            ]
            parts.append(
                _records_table(
                    rows,
                    [
                        ("direction", "dir."),
                        ("frequency_hz", "Hz"),
                        ("label", "source"),
                        ("stats", "p-p statistics [nm]"),
                    ],
                )
            )
    figures = sorted(directory.glob("*.png")) + sorted(directory.glob("*.gif"))
    order = list(CAPTIONS)
    figures.sort(key=lambda p: order.index(p.name) if p.name in order else len(order))
    if figures:
        parts.append("<h2>Figures</h2>")
        parts += [_figure(p) for p in figures]
    notes = result.get("notes") or study.get("notes")
    if notes:
        parts.append("<h2>Notes</h2>")
        parts += [f"<p class='note'>{_esc(n)}</p>" for n in notes]
    if case_text:
        parts += ["<h2>Case file</h2>", f"<pre>{_esc(case_text)}</pre>"]
    return str(title), "\n".join(p for p in parts if p)
