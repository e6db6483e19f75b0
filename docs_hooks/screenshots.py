"""Regenerate the report screenshots under ``docs/img/`` (``python docs_hooks/screenshots.py``).

Builds four reports from the current code, renders the first screen of each in headless
Chromium (1200 x 1600 pixels) and writes:

* ``report_demo.png``: the combined report of ``make demo`` (Tada's HDD bearing, the Anderon
  608, the NU209 and a Monte Carlo lot, here of 200 bearings instead of 1000);
* ``report_6204.png``: a 6204 deep groove ball bearing, quasi_static_3d
  (``tests/data/report_6204.toml``);
* ``report_nu206.png``: an NU206 cylindrical roller bearing, roller_constraint
  (``tests/data/report_nu206.toml``);
* ``report_montecarlo.png``: a Monte Carlo lot of Kim's spindle bearings (200 samples).

The same functions check a page as a reader's browser shows it (``tests/docs/
test_screenshots.py``): :func:`text_overlaps` injects a script into a copy of the page that
intersects the boxes of every pair of text runs, and :func:`embedded_images` decodes each
figure embedded in the page.
"""

from __future__ import annotations

import base64
import io
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
DATA = ROOT / "tests" / "data"
IMG = ROOT / "docs" / "img"
#: Window of the screenshots [px]: the first screen of a report on a laptop.
WINDOW = (1200, 1600)
#: Samples of the Monte Carlo lots (the demo runs 1000; the picture needs no more than this).
MC_SAMPLES = 200
NAMES = ("demo", "6204", "nu206", "montecarlo")
DEMO_TITLE = "runout demo: Tada's HDD bearing, the Anderon 608, the NU209, a Monte Carlo lot"

#: Counts text runs whose boxes intersect (by more than 1 px each way) and are not nested;
#: the result goes into the DOM, where ``--dump-dom`` returns it.
OVERLAP_SCRIPT = """
<script>
// the content of a closed <details> (all but its <summary>) is not shown
function hiddenInDetails(el) {
  for (var e = el; e; e = e.parentElement) {
    var d = e.parentElement;
    if (d && d.tagName === 'DETAILS' && !d.open && e.tagName !== 'SUMMARY') return true;
  }
  return false;
}
window.addEventListener('load', function () {
  var boxes = [];
  var walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  var node;
  while ((node = walker.nextNode())) {
    if (!node.textContent.trim()) continue;
    var el = node.parentElement;
    if (!el || el.tagName === 'SCRIPT' || el.tagName === 'STYLE') continue;
    if (hiddenInDetails(el)) continue;
    if (el.checkVisibility && !el.checkVisibility({visibilityProperty: true})) continue;
    var range = document.createRange();
    range.selectNodeContents(node);
    var rects = range.getClientRects();
    for (var i = 0; i < rects.length; i++) {
      var r = rects[i];
      if (r.width > 0.5 && r.height > 0.5) {
        boxes.push({el: el, node: node, l: r.left, r: r.right, t: r.top + window.scrollY,
                    b: r.bottom + window.scrollY});
      }
    }
  }
  boxes.sort(function (a, b) { return a.t - b.t; });
  var count = 0, found = [];
  for (var i = 0; i < boxes.length; i++) {
    var a = boxes[i];
    for (var j = i + 1; j < boxes.length && boxes[j].t < a.b - 1; j++) {
      var b = boxes[j];
      if (a.node === b.node) continue;
      if (a.el.contains(b.el) || b.el.contains(a.el)) continue;
      var w = Math.min(a.r, b.r) - Math.max(a.l, b.l);
      var h = Math.min(a.b, b.b) - Math.max(a.t, b.t);
      if (w > 1 && h > 1) {
        count++;
        if (found.length < 5) found.push(a.node.textContent.trim().slice(0, 40) + ' | ' +
                                         b.node.textContent.trim().slice(0, 40));
      }
    }
  }
  var longest = 0;
  for (var k = 0; k < boxes.length; k++) {
    if (!boxes[k].el.closest('td')) continue;  // table cells: labels, values
    longest = Math.max(longest, boxes[k].r - boxes[k].l);
  }
  document.body.dataset.height = document.documentElement.scrollHeight;
  document.body.dataset.widest = Math.round(longest);
  document.body.dataset.textboxes = boxes.length;
  document.body.dataset.overlaps = count;
  document.body.dataset.overlapping = JSON.stringify(found);
});
</script>
"""


def chromium() -> str | None:
    """Path of a Chromium executable, or None."""
    return shutil.which("chromium") or shutil.which("chromium-browser")


def _chromium_args(browser: str, profile: Path) -> list[str]:
    return [
        browser,
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--hide-scrollbars",
        f"--user-data-dir={profile}",
        f"--window-size={WINDOW[0]},{WINDOW[1]}",
    ]


def _runout(*args: str) -> None:
    exe = shutil.which("runout", path=str(Path(sys.executable).parent)) or shutil.which("runout")
    if exe is None:
        raise RuntimeError("the runout command is not installed next to this Python")
    done = subprocess.run([exe, *args], capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise RuntimeError(f"runout {' '.join(args)} failed ({done.returncode}): {done.stderr}")


def _small_lot(work: Path) -> Path:
    """Kim's Table 9 lot with :data:`MC_SAMPLES` bearings and a spec limit (so a yield)."""
    text = (EXAMPLES / "seed001_kim_table9.toml").read_text(encoding="utf-8")
    text = text.replace("samples = 1000", f"samples = {MC_SAMPLES}")
    text = text.replace("1000 bearings", f"{MC_SAMPLES} bearings")
    text = text.replace(
        "samples = 1024\n", 'samples = 1024\nlimit = "0.25 um"              # radial p-p\n'
    )
    path = work / "kim_lot.toml"
    path.write_text(text, encoding="utf-8")
    return path


def build_reports(work: Path) -> dict[str, Path]:
    """Run the four cases into ``work`` and return the report page of each (by name)."""
    from runout.report.page import build_combined_report

    work.mkdir(parents=True, exist_ok=True)
    lot = _small_lot(work)
    demo = work / "demo"
    runs = {
        "tada_fig7": "seed000_tada_fig7.toml",
        "anderon_608": "seed002_608.toml",
        "nu209": "seed004_nu209.toml",
    }
    for name, case in runs.items():
        _runout("run", str(EXAMPLES / case), "--out", str(demo / name), "--report")
    _runout("study", str(lot), "--out", str(demo / "montecarlo"))
    pages = {
        "demo": build_combined_report(
            [demo / name for name in (*runs, "montecarlo")],
            demo / "report.html",
            title=DEMO_TITLE,
        )
    }
    for name in ("6204", "nu206"):
        out = work / name
        _runout("run", str(DATA / f"report_{name}.toml"), "--out", str(out), "--report")
        pages[name] = out / "report.html"
    _runout("study", str(lot), "--out", str(work / "montecarlo"))
    _runout("report", str(work / "montecarlo"))
    pages["montecarlo"] = work / "montecarlo" / "report.html"
    return pages


def screenshot(page: Path, png: Path) -> Path:
    """Render the first screen of ``page`` into ``png`` (:data:`WINDOW` pixels)."""
    browser = chromium()
    if browser is None:
        raise RuntimeError("headless Chromium is not installed (Debian: apt-get install chromium)")
    png.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as profile:
        subprocess.run(
            [*_chromium_args(browser, Path(profile)), f"--screenshot={png}", page.as_uri()],
            check=True,
            capture_output=True,
            timeout=120,
        )
    _shrink(png)
    return png


def _shrink(png: Path) -> None:
    """Re-save the screenshot as an optimised 8-bit palette PNG (a commit-friendly size)."""
    from PIL import Image

    with Image.open(png) as image:
        quantized = image.convert("RGB").quantize(colors=256, method=Image.Quantize.MEDIANCUT)
    quantized.save(png, optimize=True)


def text_overlaps(page: Path, work: Path) -> dict[str, Any]:
    """Overlapping text runs of ``page`` as Chromium lays it out at :data:`WINDOW` width.

    Returns
    -------
    dict
        ``overlaps`` (count of intersecting pairs), ``textboxes`` (runs measured),
        ``examples`` (up to five overlapping pairs, as text), ``height`` (of the page [px])
        and ``widest`` (the widest line of text in a table cell [px]).
    """
    import json

    browser = chromium()
    if browser is None:
        raise RuntimeError("headless Chromium is not installed (Debian: apt-get install chromium)")
    html = page.read_text(encoding="utf-8")
    probe = work / f"{page.parent.name}_{page.stem}_probe.html"
    probe.write_text(html.replace("</body>", OVERLAP_SCRIPT + "</body>"), encoding="utf-8")
    with tempfile.TemporaryDirectory() as profile:
        done = subprocess.run(
            [
                *_chromium_args(browser, Path(profile)),
                "--dump-dom",
                "--virtual-time-budget=5000",
                probe.as_uri(),
            ],
            check=True,
            capture_output=True,
            timeout=120,
            text=True,
        )
    body = re.search(r"<body([^>]*)>", done.stdout)
    if body is None:
        raise RuntimeError(f"{page}: Chromium returned no <body>")
    attrs = dict(re.findall(r'data-([a-z]+)="([^"]*)"', body.group(1)))
    if "overlaps" not in attrs:
        raise RuntimeError(f"{page}: the overlap probe did not run")
    examples = json.loads(attrs.get("overlapping", "[]").replace("&quot;", '"'))
    return {
        "overlaps": int(attrs["overlaps"]),
        "textboxes": int(attrs.get("textboxes", "0")),
        "examples": examples,
        "height": int(attrs.get("height", "0")),
        "widest": int(attrs.get("widest", "0")),
    }


def embedded_images(page: Path) -> list[tuple[str, Any]]:
    """Every image embedded in ``page``, decoded: (alt text, PIL image)."""
    from PIL import Image

    html = page.read_text(encoding="utf-8")
    found = []
    for alt, data in re.findall(
        r"<img[^>]*alt='([^']*)'[^>]*src='data:image/(?:png|gif);base64,([A-Za-z0-9+/=]+)'", html
    ):
        image = Image.open(io.BytesIO(base64.b64decode(data)))
        image.load()
        found.append((alt, image))
    return found


def pixel_std(image: Any) -> float:
    """Standard deviation of the grey levels of an image (0 for a blank one)."""
    from PIL import ImageStat

    grey = image.convert("L")
    return float(ImageStat.Stat(grey).stddev[0])


def main(target: Path = IMG) -> list[Path]:
    """Build the four reports in a temporary directory and write their screenshots."""
    written = []
    with tempfile.TemporaryDirectory() as tmp:
        pages = build_reports(Path(tmp))
        for name in NAMES:
            written.append(screenshot(pages[name], target / f"report_{name}.png"))
    for path in written:
        print(f"wrote {path.relative_to(ROOT) if path.is_relative_to(ROOT) else path}")
    return written


if __name__ == "__main__":
    main()
