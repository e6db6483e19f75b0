"""HTML pieces of the report (:mod:`runout.report.page`): style, cards, tables and embedded figures.

Everything here returns HTML text; nothing reads a run directory except :func:`figure`,
which embeds one image file. Lengths are shown through :mod:`runout.base.display` at the scale of
the figures shown together.
"""

from __future__ import annotations

import base64
import datetime as _dt
import html
import io
import math
import re
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

from runout import __version__
from runout.base.display import format_length, length_unit
from runout.base.reading import MAX_FIGURE_BYTES, InputFileError, read_bytes

__all__ = [
    "CAPTIONS",
    "GIF_MAX_BYTES",
    "QUANTITY_NAMES",
    "RUNOUT_KEYS",
    "STYLE",
    "caption_of",
    "card",
    "common_unit",
    "details",
    "esc",
    "figure",
    "fmt_number",
    "length",
    "meta_line",
    "num",
    "quantity_name",
    "table",
]

# Figure file name -> caption. Names not listed get a caption from their pattern or stem.
CAPTIONS = {
    "bearing.gif": "Animation: the rolling elements at their cage positions and the ring centre "
    "(displacement magnified), with the orbit traced so far.",
    "history_orbit.png": "Time history of a few revolutions beside the orbit of the ring centre.",
    "history.png": "Time history of the measured ring's centre (about its mean).",
    "orbit.png": "Orbit of the ring centre in the radial plane; the measuring direction is marked.",
    "lines.png": "Spectral lines, peak-to-peak, against order; the largest are labelled.",
    "spectrum.png": "Amplitude spectrum of the rotor's response.",
    "bands.png": "Velocity band values.",
    "iso15242_bands.png": "ISO 15242 velocity bands L, M, H (rms).",
    "density_waveform.png": "Displacement density dx/dθ over the inner ring's rotation.",
    "anderon_spectrum.png": "Anderon spectrum (displacement density per band) on log axes.",
    "anderon_bands.png": "Anderon band values.",
    "displacement.png": "Inner-ring displacement over the rotation (runout).",
    "contact_pattern.png": "Which rolling elements touch at each rotation angle.",
    "order_sweep.png": "Runout against the harmonic order of each part.",
    "balls.png": "Load and contact angle of each ball at equilibrium.",
    "histograms.png": "Distribution over the lot of each output, with the fitted law.",
    "trend.png": "Peak-to-peak of the ball-passage line against the swept quantity.",
}
# Patterns for figures whose names carry a parameter.
_PATTERNS = (
    (re.compile(r"^sweep_(.+)\.png$"), "Runout and the largest lines against {0}, per model."),
    (re.compile(r"^hist(?:ogram)?_(.+)\.png$"), "Distribution over the lot of {0}."),
    (re.compile(r"^spectra_(.+)\.png$"), "Spectra of the sweep ({0})."),
)

#: An embedded animation larger than this is left out of the page (and the page says so) [B].
GIF_MAX_BYTES = 2_000_000

STYLE = """
* { box-sizing: border-box; }
body { font-family: -apple-system, 'Segoe UI', Helvetica, Arial, sans-serif; margin: 1.2em auto;
       max-width: 1160px; color: #1b1b1b; line-height: 1.35; padding: 0 1em; font-size: 15px; }
h1 { font-size: 1.5em; margin: 1.2em 0 .2em; border-bottom: 2px solid #2b5c8a;
     padding-bottom: .2em; }
h2 { font-size: 1.15em; color: #2b5c8a; margin: 1.4em 0 .4em; }
h3 { font-size: 1em; margin: 1em 0 .3em; }
table { border-collapse: collapse; margin: .4em 0; font-size: .9em; }
th, td { border: 1px solid #c9d3dd; padding: .2em .55em; text-align: left; vertical-align: top; }
th { background: #eef3f8; font-weight: 600; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
figure { margin: .8em 0 1.4em; }
figure img { max-width: 100%; height: auto; border: 1px solid #dde; display: block; }
figcaption { font-size: .88em; color: #444; margin-top: .3em; }
pre { background: #f6f8fa; padding: .8em; overflow-x: auto; font-size: .82em; }
details > summary { cursor: pointer; }
details.block { margin: .5em 0; }
details.block > summary { color: #2b5c8a; font-weight: 600; }
td details > summary { list-style-position: inside; }
.meta { color: #555; font-size: .88em; margin: .2em 0; }
.what { font-size: 1em; margin: .2em 0 .6em; }
.cards { display: grid; grid-template-columns: repeat(auto-fill, minmax(180px, 1fr));
         gap: .6em; margin: .6em 0; }
.card { border: 1px solid #c9d3dd; border-radius: 6px; padding: .45em .7em; background: #fbfcfe; }
.card .k { font-size: .82em; color: #555; }
.card .v { font-size: 1.45em; font-weight: 600; font-variant-numeric: tabular-nums;
           white-space: nowrap; }
.card .s { font-size: .78em; color: #555; }
.card.pass { border-color: #2e7d32; background: #eef8ef; }
.card.pass .v { color: #2e7d32; }
.card.fail { border-color: #c62828; background: #fdeeee; }
.card.fail .v { color: #c62828; }
.note { background: #fff8e1; padding: .35em .7em; margin: .3em 0; font-size: .9em; }
.muted { color: #666; font-size: .88em; }
"""


def esc(value: object) -> str:
    """HTML-escaped text of ``value``."""
    return html.escape(str(value))


def fmt_number(value: Any, digits: int = 6) -> str:
    """A plain number for a table cell (never ``nan``: non-finite values print as a dash)."""
    if value is None or isinstance(value, bool):
        return "—" if value is None else str(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            return "—"
        if value == 0.0:
            return "0"
        text = f"{value:.{digits}g}"
        if "e" in text and 1e-4 <= abs(value) < 1e12:
            # fixed-point notation for what a reader expects as a plain number (10000 Hz)
            decimals = max(0, digits - 1 - math.floor(math.log10(abs(value))))
            text = f"{value:.{decimals}f}"
            if "." in text:
                text = text.rstrip("0").rstrip(".")
        return text
    return str(value)


def length(
    value_m: float | None,
    unit: tuple[str, float] | None = None,
    resolution_m: float | None = None,
    digits: int = 4,
) -> str:
    """A length at the given (or its own) scale; a missing or non-finite value prints a dash."""
    if value_m is None or not isinstance(value_m, int | float) or not math.isfinite(value_m):
        return "—"
    return format_length(float(value_m), unit, resolution_m=resolution_m, digits=digits)


def common_unit(values_m: Iterable[Any]) -> tuple[str, float]:
    """One unit for lengths shown together (non-numbers ignored)."""
    return length_unit(
        float(v) for v in values_m if isinstance(v, int | float) and not isinstance(v, bool)
    )


def card(key: str, value: str, sub: str = "", css: str = "") -> str:
    """One headline card: a short label, a value and an optional one-line remark."""
    extra = f" {css}" if css else ""
    sub_html = f"<div class='s'>{esc(sub)}</div>" if sub else ""
    return (
        f"<div class='card{extra}'><div class='k'>{esc(key)}</div>"
        f"<div class='v'>{esc(value)}</div>{sub_html}</div>"
    )


def table(header: Sequence[str], rows: Iterable[Sequence[str]], numeric: Sequence[int] = ()) -> str:
    """A table of already-escaped cells; ``numeric`` are the right-aligned columns."""
    num = set(numeric)
    head = "".join(
        f"<th{' class=num' if i in num else ''}>{esc(h)}</th>" for i, h in enumerate(header)
    )
    body = "".join(
        "<tr>"
        + "".join(f"<td{' class=num' if i in num else ''}>{c}</td>" for i, c in enumerate(row))
        + "</tr>"
        for row in rows
    )
    return f"<table><tr>{head}</tr>{body}</table>"


def details(summary: str, content: str, css: str = "block") -> str:
    """A collapsed block: ``summary`` (escaped here) opens ``content`` (HTML)."""
    return f"<details class='{css}'><summary>{esc(summary)}</summary>{content}</details>"


def caption_of(name: str) -> str:
    """Caption of a figure file, from :data:`CAPTIONS`, a name pattern, or its stem."""
    if name in CAPTIONS:
        return CAPTIONS[name]
    for pattern, text in _PATTERNS:
        match = pattern.match(name)
        if match:
            return text.format(match.group(1).replace("_", " "))
    return Path(name).stem.replace("_", " ").capitalize() + "."


def _gif_frames(data: bytes) -> tuple[int, int]:
    """Frame count and width [px] of a GIF."""
    from PIL import Image

    with Image.open(io.BytesIO(data)) as image:
        return int(getattr(image, "n_frames", 1)), image.size[0]


#: The first bytes of the figure files a report embeds.
_SIGNATURES = {".png": (b"\x89PNG\r\n\x1a\n",), ".gif": (b"GIF87a", b"GIF89a")}


def figure(path: Path, directory: Path | None = None) -> str:
    """An embedded figure (base64 data URI) with its caption.

    A GIF is embedded as it is (animated) when it has more than one frame and is below
    :data:`GIF_MAX_BYTES`; otherwise the page says why it is not shown. Only a regular file
    inside ``directory`` (default: the figure's own) of at most
    :data:`~runout.base.reading.MAX_FIGURE_BYTES` that starts as a PNG or GIF does is
    embedded: a page that is mailed on its own must never carry another file.

    Raises
    ------
    InputFileError
        A link out of the directory, not a regular file, too large, or not an image.
    """
    directory = path.parent if directory is None else directory
    data = read_bytes(path, MAX_FIGURE_BYTES, [directory])
    if not data.startswith(_SIGNATURES.get(path.suffix.lower(), (b"",))):
        raise InputFileError(str(path), "", f"is not a {path.suffix[1:].upper()} image")
    caption = caption_of(path.name)
    css = ""
    if path.suffix.lower() == ".gif":
        frames, width = _gif_frames(data)
        if len(data) > GIF_MAX_BYTES:
            return (
                f"<p class='note'>{esc(path.name)} ({len(data) / 1e6:.1f} MB, {frames} frames) "
                "is not embedded: above the report's 2 MB bound; open it next to this page.</p>"
            )
        caption += f" {frames} frames."
        # a small animation is shown up to twice its size (at most the page's width)
        css = f" style='width: {min(2 * width, 900)}px'" if frames > 1 else ""
        mime = "image/gif"
    else:
        mime = "image/png"
    encoded = base64.b64encode(data).decode("ascii")
    return (
        f"<figure><img{css} alt='{esc(path.stem)}' src='data:{mime};base64,{encoded}'>"
        f"<figcaption>{esc(caption)}</figcaption></figure>"
    )


#: Reader's names of the runout outputs and limit quantities (JSON key without "_m").
QUANTITY_NAMES = {
    "radial_pp": "radial p-p",
    "rro_pp": "RRO p-p",
    "nrro_pp": "NRRO p-p",
    "axial_pp": "axial p-p",
}
#: The run JSON's runout keys, in the order the report shows them.
RUNOUT_KEYS = ("radial_pp_m", "rro_pp_m", "nrro_pp_m", "axial_pp_m")


def num(value: Any) -> float | None:
    """``value`` as a float when it is a finite number, else None."""
    if isinstance(value, bool) or not isinstance(value, int | float):
        return None
    return float(value) if math.isfinite(value) else None


def quantity_name(quantity: str) -> str:
    """Reader's name of a limit quantity ("radial_pp" -> "radial p-p", "iso15242.M" -> ...)."""
    if quantity.startswith("iso15242."):
        return f"ISO 15242 band {quantity.split('.', 1)[1]}"
    return QUANTITY_NAMES.get(quantity, quantity.replace("_", " "))


def meta_line(model: str, directory: Path) -> str:
    """The grey line under the title: model, runout version, time and directory name."""
    stamp = _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d %H:%M UTC")
    return (
        f"<p class='meta'>Model <b>{esc(model)}</b> · runout {esc(__version__)} · "
        f"generated {stamp} · directory {esc(directory.name)}</p>"
    )
