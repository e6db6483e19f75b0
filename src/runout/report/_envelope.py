"""The files of ``runout diagnose --envelope --out DIR``: the JSON, the envelope spectrum and
the report page."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

from runout.report._html import STYLE, card, esc, figure, fmt_number, meta_line, table

__all__ = ["ENVELOPE_FIGURE", "write_envelope"]

#: The figure's file name.
ENVELOPE_FIGURE = "envelope_spectrum.png"
_COLOURS = {"outer": "#d62728", "inner": "#1f77b4", "ball": "#2ca02c", "cage": "#9467bd"}


def _figure(diagnosis: Any, path: Path) -> None:
    """Squared-envelope spectrum, its local median, and each part's defect harmonics."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    spectrum = diagnosis.spectrum
    f, a = spectrum.frequency, spectrum.amplitude
    top_hz = 1.15 * max(3.0 * d.frequency_hz for d in diagnosis.defects)
    keep = (f > 0) & (f <= top_hz)
    fig, ax = plt.subplots(figsize=(7.5, 3.4), constrained_layout=True)
    ax.plot(f[keep], a[keep], lw=0.7, color="0.3", label="squared envelope spectrum")
    ax.plot(f[keep], diagnosis.floor[keep], lw=0.8, color="0.6", ls="--", label="local median")
    for d in diagnosis.defects:
        for h in (1, 2, 3):
            if h * d.frequency_hz <= top_hz:
                ax.axvline(
                    h * d.frequency_hz,
                    color=_COLOURS.get(d.part, "k"),
                    lw=0.9 if h == 1 else 0.6,
                    ls="-" if h == 1 else ":",
                    alpha=0.8,
                    label=f"{d.part} ({d.assessment})" if h == 1 else None,
                )
    lo, hi = diagnosis.band_hz
    ax.set_title(
        f"{diagnosis.verdict}; band {lo:.0f}-{hi:.0f} Hz ({diagnosis.band_source})", fontsize=9
    )
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel("amplitude [(m/s²)²]")
    ax.set_xlim(0.0, top_hz)
    ax.legend(fontsize=7, ncol=2)
    fig.savefig(path, dpi=110)
    plt.close(fig)


_CAPTION = (
    "Squared-envelope spectrum of the record in the band shown, its local median (the level "
    "each peak's SNR is taken against) and the first three harmonics of each part's defect "
    "frequency at the record's speed."
)


def _evidence(found: list[int], searched: int) -> str:
    return (", ".join(str(h) for h in found) or "none") + f" of {searched}"


def _modulation(evidence: dict[str, Any]) -> str:
    """The ball's cage-rate lines counted as its modulation (``-`` for another part)."""
    searched = len(evidence.get("modulation", ()))
    return f"{evidence.get('modulation_found', 0)} of {searched}" if searched else "-"


def _page(diagnosis: Any, figure_path: Path, directory: Path) -> str:
    """report.html of an envelope diagnosis: verdict, the parts ranked, the peaks, the figure."""
    doc = diagnosis.to_json()
    lo, hi = diagnosis.band_hz
    cards = "".join(
        [
            card("verdict", diagnosis.verdict),
            card("band", f"{lo:.0f}-{hi:.0f} Hz", diagnosis.band_source),
            card("spectral kurtosis", fmt_number(diagnosis.kurtosis, 3), "0 for Gaussian noise"),
            card("speed", f"{diagnosis.speed_hz * 60:.6g} rpm", diagnosis.speed_source),
            card("slip tolerance", f"{100 * diagnosis.slip_tolerance:.3g} %"),
        ]
    )
    ranked = [
        [
            esc(d["part"]),
            esc(d["assessment"]),
            esc(fmt_number(d["score"], 4)),
            esc(fmt_number(d["frequency_hz"], 6)),
            esc(fmt_number(d["order"], 6)),
            esc(_evidence(d["evidence"]["harmonics_found"], d["evidence"]["harmonics_searched"])),
            esc(str(d["evidence"]["sidebands_found"])),
            esc(_modulation(d["evidence"])),
        ]
        for d in doc["defects"]
    ]
    peaks = [
        [
            esc(fmt_number(p["frequency_hz"], 6)),
            esc(fmt_number(p["amplitude"], 4)),
            esc(fmt_number(p["snr"], 3)),
            esc(p["label"] or "-"),
        ]
        for p in doc["envelope"]["peaks"]
    ]
    parts = [
        "<!doctype html><html><head><meta charset='utf-8'>",
        f"<title>Envelope diagnosis: {esc(diagnosis.record)}</title><style>{STYLE}</style>",
        f"</head><body><h1>Envelope diagnosis: {esc(Path(diagnosis.record).name)}</h1>",
        meta_line("squared envelope spectrum, defect frequencies", directory),
        f"<p class='muted'>Record {esc(diagnosis.record)}: "
        f"{fmt_number(diagnosis.duration_s, 4)} s at {fmt_number(diagnosis.sample_rate_hz, 6)} "
        "Hz (acceleration).</p>",
        f"<div class='cards'>{cards}</div>",
        "<h2>Defect evidence, most likely first</h2>",
        table(
            [
                "part",
                "assessment",
                "score [dB]",
                "defect frequency [Hz]",
                "order",
                "harmonics found",
                "sidebands found",
                "cage modulation found",
            ],
            ranked,
            numeric=(2, 3, 4, 6),
        ),
        re.sub(
            r"<figcaption>.*?</figcaption>",
            f"<figcaption>{esc(_CAPTION)}</figcaption>",
            figure(figure_path, directory),
        ),
        "<h2>Largest envelope-spectrum peaks</h2>",
        table(["frequency [Hz]", "amplitude [(m/s²)²]", "SNR", "label"], peaks, numeric=(0, 1, 2))
        if peaks
        else "<p>No peak stands above the local median.</p>",
        "<h2>Notes</h2><ul>",
        *[f"<li>{esc(t)}</li>" for t in diagnosis.notes],
        "</ul></body></html>",
    ]
    return "\n".join(parts)


def write_envelope(diagnosis: Any, directory: Path) -> list[Path]:
    """Write diagnosis.json, the envelope-spectrum figure and report.html into ``directory``.

    Parameters
    ----------
    diagnosis : runout.diagnose.envelope.EnvelopeDiagnosis
        The result.
    directory : Path
        Where (created).

    Returns
    -------
    list of Path
        The files written.
    """
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / "diagnosis.json"
    path.write_text(json.dumps(diagnosis.to_json(), indent=2, allow_nan=False) + "\n")
    drawn = directory / ENVELOPE_FIGURE
    _figure(diagnosis, drawn)
    page = directory / "report.html"
    page.write_text(_page(diagnosis, drawn, directory), encoding="utf-8")
    return [path, drawn, page]
