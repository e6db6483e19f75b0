"""The files of ``runout diagnose --envelope --out DIR``: the JSON and the envelope spectrum."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

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


def write_envelope(diagnosis: Any, directory: Path) -> list[Path]:
    """Write diagnosis.json and the envelope-spectrum figure into ``directory``.

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
    figure = directory / ENVELOPE_FIGURE
    _figure(diagnosis, figure)
    return [path, figure]
