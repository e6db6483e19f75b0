"""Self-contained HTML report of a run directory (`runout report DIR`, `runout run --report`).

A run directory is what ``runout run CASE --out DIR`` writes: ``result.json`` (the JSON
contract), ``summary.json`` (derived geometry, contacts, frequencies), ``case.toml`` (the
input as given), CSV data and figures. A study directory (``runout study CASE --out DIR``)
holds ``manifest.json``, ``summary.json`` (statistics) and ``samples.csv``. The report puts
all of it on one page with the figures embedded, so the file can be mailed or archived on its
own.

The page reads top-down: a first screen (what was run, the headline peak-to-peak values,
the verdict against a limit, the three largest lines), the inputs as the model used them
(an input the model ignores is listed as such, never shown as if used), one row per spectral
line with its sources on demand, the figures, the notes, and the case file.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from runout.base.display import resolution_note
from runout.base.errors import RunoutError
from runout.base.reading import read_json, read_text, resolve_inside
from runout.case.limits import MAX_CASE_FILE_BYTES
from runout.io.output_dir import write_atomic
from runout.io.result_files import SUMMARY_SHAPE, read_result_json
from runout.report._html import (
    QUANTITY_NAMES,
    RUNOUT_KEYS,
    STYLE,
    card,
    common_unit,
    details,
    esc,
    figure,
    fmt_number,
    length,
    meta_line,
    num,
    quantity_name,
    table,
)
from runout.report._inputs import inputs_section, speed_words, unused_keys
from runout.report._study import STUDY_SUMMARY_SHAPE, study_first_screen, study_statistics

__all__ = ["build_combined_report", "build_report", "report_html"]

#: Spectral lines listed in the lines table (all of them are in lines.csv).
MAX_LINES = 40
#: Figure files shown first, in this order; any other figure follows, by name.
FIGURE_ORDER = (
    "bearing.gif",
    "history_orbit.png",
    "history.png",
    "orbit.png",
    "lines.png",
    "spectrum.png",
    "iso15242_bands.png",
    "bands.png",
    "density_waveform.png",
    "anderon_spectrum.png",
    "anderon_bands.png",
    "displacement.png",
    "contact_pattern.png",
    "order_sweep.png",
    "balls.png",
    "histograms.png",
)


# --------------------------------------------------------------------------------------------
# public API
# --------------------------------------------------------------------------------------------
def build_report(directory: Path, output: Path | None = None) -> Path:
    """Write ``report.html`` for a run directory and return its path.

    Parameters
    ----------
    directory : Path
        A directory written by ``runout run CASE --out DIR`` (or ``runout study``).
    output : Path or None
        Where to write the page; default ``directory / "report.html"``.

    Returns
    -------
    Path
        The page written.

    Raises
    ------
    RunoutError
        If the directory holds no ``result.json`` or study manifest.
    """
    text = report_html(directory)
    target = output or Path(directory) / "report.html"
    return write_atomic(target, lambda fh: fh.write(text))


def report_html(directory: Path) -> str:
    """The text of ``report.html`` for a run or study directory (nothing written).

    Parameters
    ----------
    directory : Path
        A directory written by ``runout run CASE --out DIR`` (or ``runout study``).

    Returns
    -------
    str
        The self-contained page.

    Raises
    ------
    RunoutError
        If the directory holds no ``result.json`` or study manifest.
    """
    title, body = _report_body(Path(directory))
    return _page(title, body)


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

    Returns
    -------
    Path
        ``output``.
    """
    sections = []
    toc = []
    for k, directory in enumerate(directories, start=1):
        run_title, body = _report_body(Path(directory))
        toc.append(f"<li><a href='#run{k}'>{esc(run_title)}</a></li>")
        sections.append(
            f"<section id='run{k}'>" + body.replace("<h1>", "<h1 class='run'>") + "</section>"
        )
    body = f"<h1>{esc(title)}</h1><ol class='meta'>{''.join(toc)}</ol>" + "".join(sections)
    output.parent.mkdir(parents=True, exist_ok=True)
    text = _page(title, body)
    return write_atomic(output, lambda fh: fh.write(text))


def _page(title: str, body: str) -> str:
    return (
        "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>"
        f"<title>{esc(title)} — runout report</title><style>{STYLE}</style></head><body>\n"
        + body
        + "\n</body></html>\n"
    )


# --------------------------------------------------------------------------------------------
# reading the directory
# --------------------------------------------------------------------------------------------
def _read_json(path: Path, shape: dict[str, Any]) -> dict[str, Any]:
    """A JSON object of the directory (only a regular file inside it, within the bounds of
    :mod:`runout.base.reading`, of ``shape``)."""
    loaded = read_json(path, [path.parent], shape=shape)
    if not isinstance(loaded, dict):
        raise RunoutError(f"{path}: expected a JSON object")
    return loaded


def _bearing_source_section(result: dict[str, Any]) -> list[str]:
    """``[bearing] designation``: the catalogue row, d, D, B and where each value comes from."""
    from runout.report._html import table
    from runout.report.summary import bearing_source_sections

    source = result.get("bearing_source", result.get("bearing_sources"))
    if not isinstance(source, dict | list):
        return []
    parts: list[str] = []
    for title, rows in bearing_source_sections(source):
        parts.append(f"<h2>{esc(title)}</h2>")
        if rows and all(not value and not unit for _, value, unit in rows):
            parts += [f"<p class='note'>{esc(text)}</p>" for text, _, _ in rows]
        else:
            parts.append(table(["quantity", "value", "unit"], rows, numeric=(1,)))
    return parts


def _load_case(directory: Path) -> tuple[Any, str | None]:
    """The validated case of the directory's ``case.toml`` (None when it cannot be loaded)
    and, when it cannot, why.

    The copy may miss files the original referred to (a profile named by an absolute path
    that is gone, a directory edited by hand), so a case that does not load again only costs
    the report its operating inputs, which then come from the JSON alone; the page says so.
    """
    path = directory / "case.toml"
    if not (path.exists() or path.is_symlink()):
        return None, None
    from runout.case.model import load_case

    # the copy must be ours to read: a link out of the directory is refused before TOML
    # reads it (load_case itself follows links, as a case named on the command line may)
    resolve_inside(path, [directory])
    try:
        return load_case(path), None
    except (RunoutError, OSError, ValueError) as exc:
        return (
            None,
            f"{path.name} does not load here ({exc}); the inputs shown come from the results alone",
        )


# --------------------------------------------------------------------------------------------
# the page of one directory
# --------------------------------------------------------------------------------------------
def _report_body(directory: Path) -> tuple[str, str]:
    """Title and HTML body of the report of one run or study directory."""
    directory = Path(directory)
    if not directory.is_dir():
        raise RunoutError(f"{directory}: no such directory (run `runout run CASE --out DIR` first)")
    result_path = directory / "result.json"
    summary_path = directory / "summary.json"
    # `runout study --out DIR` writes manifest.json and its statistics in summary.json.
    is_study = (directory / "manifest.json").exists()
    if not (result_path.exists() or result_path.is_symlink()) and not is_study:
        raise RunoutError(
            f"{directory}: holds no result.json or study manifest "
            "(write one with `runout run CASE --out DIR` or `runout study CASE --out DIR`)"
        )
    # the run's JSON as the files layer reads it back (runout.io.result_files.read_result);
    # the page reads it defensively, so a hand-edited or older result.json still reports
    result = read_result_json(directory) if result_path.exists() or result_path.is_symlink() else {}
    exists = summary_path.exists() or summary_path.is_symlink()
    study = _read_json(summary_path, STUDY_SUMMARY_SHAPE) if is_study and exists else {}
    summary = _read_json(summary_path, SUMMARY_SHAPE) if exists and not is_study else {}
    case_path = directory / "case.toml"
    case_text = (
        read_text(case_path, MAX_CASE_FILE_BYTES, [directory])
        if case_path.exists() or case_path.is_symlink()
        else ""
    )
    case, unloaded = _load_case(directory)
    title = result.get("title") or study.get("title") or summary.get("title") or directory.name
    parts: list[str] = [f"<h1>{esc(title)}</h1>"]
    if study:
        parts += study_first_screen(study, case, directory)
        parts += study_statistics(study, directory)
    else:
        parts += _run_first_screen(result, summary, case, directory)
        parts += inputs_section(result, summary, case)
        parts += _bearing_source_section(result)
        parts += _lines_section(result)
        parts += _other_results(result, summary)
    parts += _figures(directory)
    notes = [*(result.get("notes") or study.get("notes") or []), *([unloaded] if unloaded else [])]
    if notes:
        parts.append("<h2>Notes</h2>")
        parts += [f"<p class='note'>{esc(n)}</p>" for n in notes]
    if study.get("errors"):
        parts.append(
            details(
                f"Failed samples ({len(study['errors'])})",
                "".join(f"<p class='note'>{esc(e)}</p>" for e in study["errors"][:50]),
            )
        )
    if case_text:
        parts += [
            "<h2>Case file</h2>",
            details("case.toml (the input as given)", f"<pre>{esc(case_text)}</pre>"),
        ]
    parts.append(
        "<p class='meta'>Conventions: input amplitudes are zero-to-peak radius deviations; "
        "every output displacement is peak-to-peak; orders are waves per revolution of the "
        "rotating ring; RRO is the part synchronous with the rotating ring, NRRO the rest.</p>"
    )
    return str(title), "\n".join(p for p in parts if p)


def _bearing_words(summary: dict[str, Any], case: Any) -> str:
    """E.g. "ball bearing, 8 balls of 7.938 mm on a 33.5 mm pitch diameter"."""
    bearing = summary.get("bearing") or {}
    kind = bearing.get("type") or (getattr(case.bearing, "kind", None) if case else None)
    z = bearing.get("elements")
    d = num(bearing.get("element_diameter_m"))
    dm = num(bearing.get("pitch_diameter_m"))
    roller = kind == "cylindrical_roller"
    name = "cylindrical roller bearing" if roller else "ball bearing"
    element = "rollers" if roller else "balls"
    if z is None or d is None or dm is None:
        return name
    mm = ("mm", 1e3)
    return (
        f"{name}, {z} {element} of {length(d, mm, digits=6)}, "
        f"pitch diameter {length(dm, mm, digits=6)}"
    )


def _load_words(case: Any, unused: set[str]) -> str:
    if case is None:
        return ""
    op = case.operation
    words = []
    if op.radial_load > 0.0 and "operation.radial_load" not in unused:
        words.append(f"radial {fmt_number(op.radial_load, 4)} N")
    if op.axial_load > 0.0 and "operation.axial_load" not in unused:
        words.append(f"axial {fmt_number(op.axial_load, 4)} N")
    if op.moment_load > 0.0 and "operation.moment_load" not in unused:
        words.append(f"moment {fmt_number(op.moment_load, 4)} N m")
    return ("load " + ", ".join(words)) if words else ""


def _verdict_card(verdict: dict[str, Any], unit: tuple[str, float] | None) -> str:
    quantity = str(verdict.get("quantity", ""))
    passed = bool(verdict.get("pass"))
    if "limit_m" in verdict:
        shown = unit or common_unit([verdict.get("limit_m"), verdict.get("value_m")])
        value = length(num(verdict.get("value_m")), shown)
        limit = length(num(verdict.get("limit_m")), shown)
    else:
        value = f"{fmt_number(num(verdict.get('value_um_per_s')), 4)} um/s"
        limit = f"{fmt_number(num(verdict.get('limit_um_per_s')), 4)} um/s"
    name = quantity_name(quantity)
    sign = "≤" if passed else ">"
    return card(
        f"verdict ({name})",
        "PASS" if passed else "FAIL",
        f"{value} {sign} limit {limit}",
        "pass" if passed else "fail",
    )


def _top_source(component: dict[str, Any]) -> str:
    sources = component.get("sources") or []
    if not sources:
        return str(component.get("label") or "unattributed")
    best = max(sources, key=lambda s: abs(num(s.get("share")) or 0.0))
    part = best.get("part")
    lobes = best.get("lobes")
    term = best.get("term") or best.get("formula") or ""
    if part in ("inner", "outer"):
        head = f"{part} {lobes} lobes" if lobes is not None else str(part)
    elif part in ("ball", "roller"):
        element = best.get("element")
        who = f"{part} {element}" if element is not None else f"every {part}"
        head = f"{who} size error" if lobes == 0 else f"{who} {lobes} lobes"
    else:
        head = ""
    text = f"{head}: {term}" if head and term else head or str(term)
    more = len(sources) - 1
    return text + (f" (+{more} more)" if more > 0 else "")


def _sorted_lines(result: dict[str, Any]) -> list[dict[str, Any]]:
    lines = [c for c in result.get("components") or [] if num(c.get("pp_m")) is not None]
    return sorted(lines, key=lambda c: -float(c["pp_m"]))


def _equilibrium_cards(result: dict[str, Any]) -> list[str]:
    """Headline of a static equilibrium: ring displacement, contact angles, stiffness."""
    cards = []
    found = result.get("ring_displacement")
    ring: dict[str, Any] = found if isinstance(found, dict) else {}
    for key, name in (
        ("axial_m", "axial displacement"),
        ("x_m", "x displacement"),
        ("y_m", "y displacement"),
    ):
        value = num(ring.get(key))
        if value is not None and (value or key == "axial_m"):
            cards.append(card(name, length(value), "inner ring vs outer ring"))
    for key, name in (
        ("inner_contact_angle_deg", "inner contact angle"),
        ("outer_contact_angle_deg", "outer contact angle"),
    ):
        angles = [a for a in (num(v) for v in result.get(key) or []) if a is not None]
        if angles:
            spread = f"{min(angles):.4g}–{max(angles):.4g} deg over the balls"
            cards.append(card(name, f"{sum(angles) / len(angles):.4g} deg", spread))
    stiffness = result.get("stiffness_matrix")
    if isinstance(stiffness, dict) and (stiffness.get("dofs") or [None])[0] == "axial":
        matrix = stiffness.get("matrix")
        k_axial = num(matrix[0][0]) if isinstance(matrix, list) and matrix and matrix[0] else None
        if k_axial:
            cards.append(card("axial stiffness", f"{k_axial * 1e-6:.4g} N/um"))
    life = result.get("life")
    if isinstance(life, dict):
        l10r = num(life.get("l10r_mrev"))
        rating = num(life.get("dynamic_load_rating_n"))
        cards.append(
            card(
                "reference rating life L10r",
                "n/a" if l10r is None else f"{l10r:.4g} million rev",
                f"ISO/TS 16281, C = {fmt_number(rating, 5)} N",
            )
        )
        lnmr = num(life.get("lnmr_mrev"))
        a_iso = num(life.get("a_iso"))
        a1 = num(life.get("a1"))
        if lnmr is not None and a_iso is not None and a1 is not None:
            cards.append(
                card(
                    "modified life L_nmr",
                    f"{lnmr:.4g} million rev",
                    f"a_1 = {fmt_number(a1, 4)}, a_ISO = {fmt_number(a_iso, 4)} (ISO 281)",
                )
            )
    return cards


def _run_first_screen(
    result: dict[str, Any], summary: dict[str, Any], case: Any, directory: Path
) -> list[str]:
    model = str(result.get("model") or "")
    unused = unused_keys(result, case)
    what = [
        _bearing_words(summary, case),
        speed_words(result, case),
        _load_words(case, unused),
    ]
    parts = [
        f"<p class='what'>{esc(' · '.join(w for w in what if w))}</p>",
        meta_line(model, directory),
    ]
    runout = result.get("runout") or {}
    resolution = num(result.get("solver_resolution_m"))
    shown_keys = [
        k
        for k in RUNOUT_KEYS
        if num(runout.get(k)) is not None
        and (k != "axial_pp_m" or num(runout.get(k)) or model == "quasi_static_3d")
    ]
    if model == "equilibrium":
        # a static solution of the perfect bearing: its results are a position, not a runout
        shown_keys = []
    values = [float(runout[k]) for k in shown_keys]
    if resolution is not None:
        values = [v if abs(v) >= resolution else 0.0 for v in values]
    unit = common_unit(values)
    cards = []
    iso492: dict[str, Any] = result["iso492"] if isinstance(result.get("iso492"), dict) else {}
    for key in shown_keys:
        name = QUANTITY_NAMES[key[:-2]]
        sub = ""
        if key == "radial_pp_m" and iso492.get("quantity"):
            sub = f"= {iso492['quantity']} (ISO 492)"
        elif key == "rro_pp_m":
            sub = "repeatable"
        elif key == "nrro_pp_m":
            sub = "non-repeatable"
        cards.append(card(name, length(runout[key], unit, resolution), sub))
    if "axial_pp_m" in runout and runout["axial_pp_m"] is None and model != "equilibrium":
        # null in the JSON: the model has no axial degree of freedom (not a zero runout)
        cards.append(card(QUANTITY_NAMES["axial_pp"], "n/a", "no axial freedom"))
    if isinstance(result.get("verdict"), dict):
        cards.append(_verdict_card(result["verdict"], unit))
    iso = result.get("iso15242")
    if isinstance(iso, dict) and isinstance(iso.get("bands"), dict):
        for band, entry in iso["bands"].items():
            rms = num((entry or {}).get("rms_um_per_s"))
            low, high = num(entry.get("low_hz")), num(entry.get("high_hz"))
            cards.append(
                card(
                    f"ISO 15242 {band} (rms)",
                    f"{fmt_number(rms, 4)} {iso.get('unit', 'um/s')}",
                    f"{fmt_number(low, 4)}–{fmt_number(high, 4)} Hz",
                )
            )
    if model == "equilibrium":
        cards += _equilibrium_cards(result)
    parts.append("<div class='cards'>" + "".join(cards) + "</div>")
    if resolution is not None:
        parts.append(f"<p class='muted'>{esc(resolution_note(resolution, unit))}.</p>")
    lines = _sorted_lines(result)[:3]
    if lines:
        line_unit = common_unit(c["pp_m"] for c in lines)
        rows = [
            [
                esc(c.get("direction", "")),
                esc(fmt_number(num(c.get("frequency_hz")), 6)),
                esc(fmt_number(num(c.get("order")), 5)),
                esc(length(c["pp_m"], line_unit, resolution)),
                esc(_top_source(c)),
            ]
            for c in lines
        ]
        parts += [
            "<h3>Largest lines</h3>",
            table(["dir.", "Hz", "order", "p-p", "top source"], rows, numeric=(1, 2, 3)),
        ]
    elif model == "equilibrium":
        parts.append(
            "<p class='muted'>Static equilibrium of the perfect bearing: no runout lines.</p>"
        )
    return parts


# --------------------------------------------------------------------------------------------
# lines and other results
# --------------------------------------------------------------------------------------------
def _lines_section(result: dict[str, Any]) -> list[str]:
    lines = _sorted_lines(result)
    if not lines:
        return []
    shown = lines[:MAX_LINES]
    resolution = num(result.get("solver_resolution_m"))
    unit = common_unit(c["pp_m"] for c in shown)
    rows = []
    for c in shown:
        sources = c.get("sources") or []
        source_rows = [
            [
                esc(s.get("part", "")),
                esc(fmt_number(s.get("element"))),
                esc(fmt_number(s.get("lobes"))),
                esc(s.get("term", "")),
                esc(s.get("formula", "")),
                esc(fmt_number(num(s.get("share")), 3)),
            ]
            for s in sources
        ]
        label = esc(c.get("label") or _top_source(c))
        if source_rows:
            label = (
                f"<details><summary>{label}</summary>"
                + table(["part", "element", "lobes", "term", "formula", "share"], source_rows)
                + "</details>"
            )
        rows.append(
            [
                esc(c.get("direction", "")),
                esc(fmt_number(num(c.get("frequency_hz")), 6)),
                esc(fmt_number(num(c.get("order")), 5)),
                esc(length(c["pp_m"], unit, resolution).rsplit(" ", 1)[0]),
                "RRO" if c.get("repeatable") else "NRRO",
                label,
            ]
        )
    more = len(lines) - len(shown)
    heading = f"Spectral lines ({len(shown)} largest of {len(lines)})" if more else "Spectral lines"
    parts = [
        f"<h2>{esc(heading)}</h2>",
        table(
            ["dir.", "Hz", "order", f"p-p [{unit[0]}]", "kind", "line (click for its sources)"],
            rows,
            numeric=(1, 2, 3),
        ),
    ]
    if more:
        parts.append(f"<p class='muted'>All {len(lines)} lines are in lines.csv.</p>")
    return parts


def _other_results(result: dict[str, Any], summary: dict[str, Any]) -> list[str]:
    parts: list[str] = []
    if isinstance(result.get("anderon"), dict):
        rows = [
            [esc(k), esc(fmt_number(num(v), 5))]
            for k, v in result["anderon"].items()
            if num(v) is not None
        ]
        parts += ["<h2>Anderon band values</h2>", table(["band", "value [Anderon]"], rows, (1,))]
    if isinstance(result.get("attribution"), list) and result["attribution"]:
        records = result["attribution"]
        cols = [
            k
            for k in records[0]
            if k in ("part", "factor", "lobes", "formula", "order", "frequency_hz")
        ]
        rows = [[esc(fmt_number(r.get(k))) for k in cols] for r in records]
        parts.append(
            details(
                "Attribution: which factor produces which frequency",
                table([c.replace("_", " ") for c in cols], rows),
            )
        )
    natural = result.get("natural_frequencies_hz")
    if isinstance(natural, list) and natural:
        shown = ", ".join(fmt_number(num(v), 5) for v in natural)
        parts.append(f"<p><b>natural frequencies</b>: {esc(shown)} Hz</p>")
    if result.get("model") == "spindle" and isinstance(result.get("bearings"), list):
        parts += _spindle_section(result)
    if isinstance(result.get("balls"), list) and result["balls"]:
        balls = result["balls"]
        keys = [k for k in balls[0] if k != "ball"]
        rows = [
            [esc(b.get("ball", ""))]
            # "_m" is metres, but "_n_m" newton-metres (the gyroscopic moment): not a length
            + [
                esc(
                    length(b[k])
                    if k.endswith("_m") and not k.endswith("_n_m")
                    else fmt_number(num(b[k]), 5)
                )
                for k in keys
            ]
            for b in balls
        ]
        parts.append(
            details(
                "Per-ball equilibrium",
                table(["ball", *(k.replace("_", " ") for k in keys)], rows),
            )
        )
    life = result.get("life")
    if isinstance(life, dict):
        rows = [
            [esc(k.replace("_", " ")), esc(v if isinstance(v, str) else fmt_number(num(v), 6))]
            for k, v in life.items()
        ]
        parts.append(details("Reference rating life (ISO/TS 16281)", table(["", ""], rows)))
    return parts


def _spindle_section(result: dict[str, Any]) -> list[str]:
    """The spindle's bearings (runout at each one's plane), tilt and nose stiffness."""
    rows = []
    for b in result["bearings"]:
        r = b.get("runout") or {}
        rows.append(
            [
                esc(b.get("name", "")),
                esc(length(num(b.get("position_m")))),
                esc(b.get("thrust", "")),
                esc(fmt_number(num(b.get("contact_angle_deg")), 4)),
                esc(fmt_number(num(b.get("preload_n")), 4)),
                esc(length(num(b.get("pressure_centre_m")))),
                esc(length(num(r.get("radial_pp_m")))),
                esc(length(num(r.get("axial_pp_m")))),
            ]
        )
    head = [
        "bearing",
        "position",
        "thrust",
        "contact angle [deg]",
        "preload [N]",
        "pressure centre",
        "radial p-p at its plane",
        "axial p-p",
    ]
    parts = ["<h2>Spindle: the shaft on its bearings</h2>", table(head, rows, (1, 3, 4, 5, 6, 7))]
    lives = []
    for b in result["bearings"]:
        life = b.get("life")
        if isinstance(life, dict):
            l10r, lnmr = num(life.get("l10r_mrev")), num(life.get("lnmr_mrev"))
            lives.append(
                [
                    esc(b.get("name", "")),
                    esc("n/a" if l10r is None else f"{l10r:.4g}"),
                    esc("n/a" if lnmr is None else f"{lnmr:.4g}"),
                    esc(fmt_number(num(life.get("dynamic_load_rating_n")), 5)),
                ]
            )
    if lives:
        parts.append(
            table(
                [
                    "bearing",
                    "reference rating life L10r [million rev] (ISO/TS 16281)",
                    "modified life L_nmr [million rev]",
                    "C [N]",
                ],
                lives,
                (1, 2, 3),
            )
        )
    tilt = result.get("tilt_pp_rad") or {}
    parts.append(
        f"<p><b>tilt p-p</b>: θx {esc(fmt_number(num(tilt.get('x')), 4))} rad, "
        f"θy {esc(fmt_number(num(tilt.get('y')), 4))} rad; runout reported at the nose, "
        f"z = {esc(length(num(result.get('nose_position_m'))))}</p>"
    )
    tool = result.get("tool_point_stiffness_n_per_m") or {}
    if tool:
        values = ", ".join(
            f"k_{axis} {fmt_number((num(tool.get(axis)) or 0.0) * 1e-6, 4)}" for axis in "xyz"
        )
        parts.append(
            f"<p><b>tool-point stiffness</b> (at the nose, shaft free to tilt: 1/C_ii of the "
            f"compliance): {esc(values)} N/um</p>"
        )
    matrix = (result.get("stiffness_matrix") or {}).get("matrix")
    if isinstance(matrix, list) and matrix:
        dofs = ["x", "y", "z", "θx", "θy"]
        rows = [
            [dofs[i], *(esc(fmt_number(num(v), 4)) for v in row)] for i, row in enumerate(matrix)
        ]
        parts.append(
            details(
                "5×5 stiffness matrix of the shaft at the nose, each entry with the other "
                "coordinates held (the x, y diagonal: tilt held) (N/m, N/rad, N m/m, N m/rad)",
                table(["", *dofs], rows, (1, 2, 3, 4, 5)),
            )
        )
    return parts


def _figures(directory: Path) -> list[str]:
    figures = sorted(directory.glob("*.png")) + sorted(directory.glob("*.gif"))
    order = list(FIGURE_ORDER)
    figures.sort(key=lambda p: (order.index(p.name) if p.name in order else len(order), p.name))
    if not figures:
        return []
    return ["<h2>Figures</h2>", *(figure(p, directory) for p in figures)]
