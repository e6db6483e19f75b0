"""The files of ``runout diagnose --out DIR``: report page, JSON, estimated case, figures."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path
from typing import Any

from runout.report._html import (
    STYLE,
    card,
    common_unit,
    esc,
    figure,
    fmt_number,
    length,
    meta_line,
    table,
)
from runout.report._plot_style import log_labels

__all__ = ["write_diagnosis"]

_CAPTIONS = {
    "diagnosis_spectrum.png": "Amplitude spectrum (Hann) of the record and of the lines the "
    "estimated deviations give through the linear model (first channel).",
    "diagnosis_deviations.png": "Estimated deviations per part (zero-to-peak, one equivalent "
    "deviation per line) with their 1-sigma uncertainty.",
}


def _figures(diagnosis: Any, directory: Path) -> list[Path]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    written: list[Path] = []
    unit = "m" if diagnosis.quantity == "displacement" else "m/s"
    if diagnosis.spectrum is not None:
        f, meas, rec = diagnosis.spectrum
        fig, ax = plt.subplots(figsize=(7.0, 3.2), constrained_layout=True)
        keep = f > 0
        ax.semilogy(f[keep], meas[keep] + 1e-30, lw=0.7, color="0.4", label="record")
        ax.semilogy(f[keep], rec[keep] + 1e-30, lw=0.9, color="#1f77b4", label="reconstructed")
        top = float(max(meas[keep].max(initial=0.0), rec[keep].max(initial=0.0)))
        log_labels(ax)
        if top > 0:
            ax.set_ylim(top * 1e-5, top * 2.0)
        # up to a little beyond the highest line found (the rest is the noise floor)
        found = [e.frequency_hz for e in diagnosis.estimates]
        found += [u.frequency_hz for u in diagnosis.unattributed]
        if found:
            ax.set_xlim(0.0, min(float(f[-1]), 1.3 * max(found)))
        ax.set_xlabel("frequency [Hz]")
        ax.set_ylabel(f"amplitude [{unit}]")
        ax.legend(fontsize=7.5)
        path = directory / "diagnosis_spectrum.png"
        fig.savefig(path, dpi=110)
        plt.close(fig)
        written.append(path)
    est = diagnosis.estimates
    fig, ax = plt.subplots(figsize=(7.0, 3.0), constrained_layout=True)
    if est:
        scale_unit, scale = common_unit(e.amplitude_m for e in est)
        colours = {"inner": "#1f77b4", "outer": "#ff7f0e", "ball": "#2ca02c", "roller": "#2ca02c"}
        labels = [
            f"{e.part} {'/'.join(map(str, e.lobes))}" + (f" #{e.element}" if e.element else "")
            for e in est
        ]
        ax.bar(
            range(len(est)),
            [e.amplitude_m * scale for e in est],
            yerr=[e.uncertainty_m * scale for e in est],
            color=[colours.get(e.part, "0.5") for e in est],
        )
        ax.set_xticks(range(len(est)), labels, rotation=60, ha="right", fontsize=7)
        ax.set_ylabel(f"deviation [{scale_unit}]")
    else:
        ax.text(0.5, 0.5, "no deviation detected", ha="center", va="center")
        ax.set_axis_off()
    path = directory / "diagnosis_deviations.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    written.append(path)
    return written


def _page(diagnosis: Any, figures: list[Path], directory: Path) -> str:
    est = diagnosis.estimates
    unit = common_unit([e.amplitude_m for e in est] or [1e-6])
    cards = "".join(
        [
            card("explained fraction", f"{diagnosis.explained_fraction:.4f}"),
            card("deviations detected", str(len(est))),
            card("unattributed lines", str(len(diagnosis.unattributed))),
            card("detection limit", length(diagnosis.detection_limit_m), "ring deviation"),
            card("speed", f"{diagnosis.rotation_hz * 60:.6g} rpm", diagnosis.speed_source),
        ]
    )
    rows = [
        [
            esc(e.part + (f" {e.element}" if e.element else "")),
            esc(" | ".join(map(str, e.lobes))),
            esc(length(e.amplitude_m, unit)),
            esc(length(e.uncertainty_m, unit)),
            # a phase a hair below 2 pi is 0, not 360
            esc(fmt_number(round(math.degrees(e.phase_rad), 1) % 360.0, 4)),
            esc(fmt_number(math.degrees(e.phase_uncertainty_rad), 2)),
            esc(fmt_number(e.frequency_hz)),
            esc(e.whirl),
            esc(fmt_number(e.share, 3)),
            esc(e.note),
        ]
        for e in est
    ]
    parts = [
        "<!doctype html><html><head><meta charset='utf-8'>",
        f"<title>Diagnosis: {esc(diagnosis.case.title)}</title><style>{STYLE}</style></head>",
        f"<body><h1>Diagnosis: {esc(diagnosis.case.title or diagnosis.record.file)}</h1>",
        meta_line(f"linear ({diagnosis.variant}), inverted", directory),
        f"<p class='muted'>Record {esc(diagnosis.record.file)}: {diagnosis.record.samples} "
        f"samples, {fmt_number(diagnosis.record.duration, 4)} s, channels "
        f"{esc(', '.join(sorted(diagnosis.record.channels)))} ({esc(diagnosis.quantity)}).</p>",
        f"<div class='cards'>{cards}</div>",
        "<h2>Estimated deviations</h2>",
        table(
            [
                "part",
                "lobes",
                "amplitude",
                "± 1σ",
                "phase [deg]",
                "± 1σ [deg]",
                "line [Hz]",
                "whirl",
                "share",
                "note",
            ],
            rows,
            numeric=(2, 3, 4, 5, 6, 8),
        )
        if rows
        else "<p>No deviation stands above the noise.</p>",
    ]
    for path in figures:
        caption = f"<figcaption>{esc(_CAPTIONS[path.name])}</figcaption>"
        parts.append(re.sub(r"<figcaption>.*?</figcaption>", caption, figure(path)))
    if diagnosis.unattributed:
        u_unit = "m" if diagnosis.quantity == "displacement" else "m/s"
        parts.append("<h2>Unattributed lines</h2>")
        parts.append(
            table(
                ["frequency [Hz]", "order", f"p-p [{u_unit}]", "channel", "kinematic match"],
                [
                    [
                        esc(fmt_number(u.frequency_hz)),
                        esc(fmt_number(u.order, 5)),
                        esc(fmt_number(u.pp, 4)),
                        esc(u.channel),
                        esc(u.kinematic_match or "none"),
                    ]
                    for u in diagnosis.unattributed
                ],
                numeric=(0, 1, 2),
            )
        )
    parts.append("<h2>Not observable with this record</h2><ul>")
    parts += [f"<li>{esc(t)}</li>" for t in diagnosis.not_observable]
    parts.append("</ul><h2>Notes</h2><ul>")
    parts += [f"<li>{esc(t)}</li>" for t in diagnosis.notes]
    parts.append(
        "</ul><p class='muted'>estimated.toml holds the smallest deviations that give the "
        "detected lines; <code>runout run estimated.toml</code> runs them forward.</p>"
        "</body></html>"
    )
    return "\n".join(parts)


def write_diagnosis(diagnosis: Any, directory: Path) -> list[Path]:
    """Write diagnosis.json, estimated.toml, the figures and report.html into ``directory``.

    Returns
    -------
    list of Path
        The files written.
    """
    directory.mkdir(parents=True, exist_ok=True)
    written = []
    path = directory / "diagnosis.json"
    path.write_text(json.dumps(diagnosis.to_json(), indent=2, allow_nan=False) + "\n")
    written.append(path)
    path = directory / "estimated.toml"
    path.write_text(diagnosis.estimated_case_text(), encoding="utf-8")
    written.append(path)
    figures = _figures(diagnosis, directory)
    written += figures
    path = directory / "report.html"
    path.write_text(_page(diagnosis, figures, directory), encoding="utf-8")
    written.append(path)
    return written
