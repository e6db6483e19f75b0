"""The report screenshots of docs/img: regenerated from the current code and checked as a reader
sees the pages (issue 17, "Done when").

``docs_hooks/screenshots.py`` builds four reports (the demo, a 6204 quasi_static_3d run, an
NU206 roller run, a Monte Carlo lot), renders each in headless Chromium and checks it: no two
runs of text overlap on the laid-out page, no embedded figure is empty, the screenshot is not
blank, and the page fetches nothing. The committed screenshots must exist with the size the
script writes. The checks are also run on pages made to fail, so a check that sees nothing
cannot pass silently.
"""

from __future__ import annotations

import os
import re
import sys
from pathlib import Path

import pytest
from PIL import Image

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "docs_hooks"))

import screenshots  # noqa: E402

#: Grey-level standard deviation below which an image counts as empty (a white or one-colour
#: panel is 0; the sparsest real figure of these reports is above 20).
MIN_FIGURE_STD = 8.0
MIN_SCREEN_STD = 15.0


def _require_chromium() -> None:
    if screenshots.chromium() is None:
        if os.environ.get("CI"):
            pytest.fail("CI must install Debian's chromium (see .ci/run)")
        pytest.skip("headless Chromium is not installed here; CI installs it and runs this")


@pytest.fixture(scope="module")
def shots(tmp_path_factory: pytest.TempPathFactory) -> dict[str, tuple[Path, Path]]:
    """name -> (report page, regenerated screenshot)."""
    _require_chromium()
    work = tmp_path_factory.mktemp("shots")
    pages = screenshots.build_reports(work / "runs")
    return {
        name: (pages[name], screenshots.screenshot(pages[name], work / f"report_{name}.png"))
        for name in screenshots.NAMES
    }


@pytest.mark.parametrize("name", screenshots.NAMES)
def test_no_overlapping_text(
    shots: dict[str, tuple[Path, Path]], name: str, tmp_path: Path
) -> None:
    page, _ = shots[name]
    found = screenshots.text_overlaps(page, tmp_path)
    assert found["textboxes"] > 50  # the probe measured the page's text
    assert found["overlaps"] == 0, found["examples"]
    # short labels in the tables (their sources open on demand), not paragraph-long rows: a
    # 6204 page was 7,000 px of such rows; a label as wide as half the page is one
    assert 0 < found["widest"] < 600, found["widest"]
    if name != "demo":  # the demo page holds four reports
        assert found["height"] < 6000, found["height"]


@pytest.mark.parametrize("name", screenshots.NAMES)
def test_no_empty_figure(shots: dict[str, tuple[Path, Path]], name: str) -> None:
    page, _ = shots[name]
    images = screenshots.embedded_images(page)
    assert images
    for alt, image in images:
        assert screenshots.pixel_std(image) > MIN_FIGURE_STD, alt


@pytest.mark.parametrize("name", screenshots.NAMES)
def test_screenshot_is_not_blank_and_matches_the_committed_one(
    shots: dict[str, tuple[Path, Path]], name: str
) -> None:
    _, png = shots[name]
    with Image.open(png) as shot:
        assert shot.size == screenshots.WINDOW
        assert screenshots.pixel_std(shot) > MIN_SCREEN_STD
        size = shot.size
    committed = screenshots.IMG / f"report_{name}.png"
    assert committed.is_file(), f"{committed} is missing: run python docs_hooks/screenshots.py"
    assert committed.stat().st_size < 400_000
    with Image.open(committed) as image:
        assert image.size == size  # fonts and time stamps differ, the layout does not


@pytest.mark.parametrize("name", screenshots.NAMES)
def test_pages_are_self_contained(shots: dict[str, tuple[Path, Path]], name: str) -> None:
    page = shots[name][0].read_text(encoding="utf-8")
    assert not re.search(r"""\bsrc=(?!['"]?data:)""", page)  # every image is embedded
    assert not re.search(r"""\bhref=(?!['"]?#)""", page)  # links stay on the page
    assert "<script" not in page


def test_the_6204_page_animates_and_gives_a_verdict(shots: dict[str, tuple[Path, Path]]) -> None:
    page = shots["6204"][0]
    gifs = [image for alt, image in screenshots.embedded_images(page) if image.format == "GIF"]
    assert len(gifs) == 1 and gifs[0].n_frames > 1
    text = page.read_text(encoding="utf-8")
    assert ">PASS<" in text and "quasi_static_3d" in text


def test_the_montecarlo_page_has_statistics_and_yield(
    shots: dict[str, tuple[Path, Path]],
) -> None:
    text = shots["montecarlo"][0].read_text(encoding="utf-8")
    assert ">Statistics over the lot<" in text
    assert "<th class=num>p99</th>" in text
    assert ">yield (radial p-p ≤ 250 nm)<" in text


# --------------------------------------------------------------------------------------------
# the checks themselves fail on bad pages
# --------------------------------------------------------------------------------------------
def test_overlap_probe_finds_overlapping_text(tmp_path: Path) -> None:
    _require_chromium()
    page = tmp_path / "bad.html"
    page.write_text(
        "<!DOCTYPE html><html><body>"
        + "".join(f"<p>line {k} of ordinary text</p>" for k in range(60))
        + "<div style='position:absolute;top:10px;left:10px'>first label</div>"
        "<div style='position:absolute;top:14px;left:20px'>second label</div>"
        "<details><summary>closed</summary><div style='position:absolute;top:10px;"
        "left:10px'>hidden text is not on the page</div></details>"
        "</body></html>",
        encoding="utf-8",
    )
    found = screenshots.text_overlaps(page, tmp_path)
    # the two labels overlap each other and the first paragraphs; hidden text does not count
    assert found["overlaps"] >= 1
    assert any("first label" in pair for pair in found["examples"])
    assert not any("hidden text" in pair for pair in found["examples"])


def test_blank_figure_is_caught() -> None:
    blank = Image.new("RGB", (400, 300), "white")
    assert screenshots.pixel_std(blank) < MIN_FIGURE_STD
    grey = Image.new("RGB", (400, 300), (120, 130, 140))
    assert screenshots.pixel_std(grey) < MIN_FIGURE_STD
