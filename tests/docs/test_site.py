"""The documentation site builds strictly and reads cleanly (issue 17's docs checks).

Builds the whole site with mkdocs (a few seconds; KaTeX is fetched once into ``out/katex``)
and checks it as a reader would: no raw Sphinx roles, reST tables or TeX outside rendered
mathematics, no link leaving the site, KaTeX present. The converter and the checker are unit
tested on small inputs too, so a checker that found nothing cannot pass silently.
"""

from __future__ import annotations

import pkgutil
import sys
from pathlib import Path

import pytest
import yaml

import runout

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "docs_hooks"))

from build import build  # noqa: E402
from griffe_rst import rst_to_markdown  # noqa: E402
from site_check import check_page, check_theory_source  # noqa: E402

#: Modules that are tools of the project, not API (the CLI, the generators of docs pages).
NOT_API = {"runout.validation.reproduce", "runout.case.schema_doc"}


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, list[str]]:
    site_dir = tmp_path_factory.mktemp("site")
    return site_dir, build(site_dir)


def test_built_site_has_no_raw_markup_and_no_link_outside(site: tuple[Path, list[str]]) -> None:
    site_dir, problems = site
    assert problems == []
    assert (site_dir / "assets" / "katex" / "katex.min.js").is_file()


def test_mathematics_is_marked_for_katex(site: tuple[Path, list[str]]) -> None:
    site_dir, _ = site
    page = (site_dir / "models" / "linear" / "index.html").read_text(encoding="utf-8")
    assert page.count('class="arithmatex"') >= 5
    assert "assets/katex/katex.min.js" in page
    api = (site_dir / "api" / "runout.geometry.imperfections" / "index.html").read_text(
        encoding="utf-8"
    )
    assert 'class="arithmatex"' in api  # a ``.. math::`` docstring block, converted


def test_every_public_module_has_an_api_page_in_the_nav() -> None:
    nav = (ROOT / "mkdocs.yml").read_text(encoding="utf-8")
    config = yaml.load(nav, Loader=yaml.BaseLoader)
    pages = str(config["nav"])
    public = {
        m.name
        for m in pkgutil.walk_packages(runout.__path__, "runout.")
        if not any(part.startswith("_") for part in m.name.split(".")[1:])
        and not m.name.startswith("runout.cli")
        and m.name != "runout.examples.data"
    }
    assert {"runout.geometry.bearing", "runout.models.linear", "runout.case"} <= public
    documented = {
        line.removeprefix("::: ").strip(): page.name
        for page in (ROOT / "docs" / "api").glob("*.md")
        for line in page.read_text(encoding="utf-8").splitlines()
        if line.startswith("::: ")
    }
    for module in sorted(public - NOT_API):
        assert module in documented, f"no API page for {module} (python docs_hooks/api_pages.py)"
        assert f"api/{documented[module]}" in pages, f"{module} missing from the nav"


def test_converter_turns_roles_math_and_tables_into_markdown() -> None:
    text = rst_to_markdown(
        "See :func:`~runout.runner.run_model` and :class:`runout.analysis.results.RunResult`,\n"
        "with :math:`\\alpha` here.\n"
        "\n"
        ".. math:: x = y^{2}\n"
        "\n"
        "====  =====\n"
        "a     b\n"
        "====  =====\n"
        "1     two\n"
        "      more\n"
        "3     four\n"
        "====  =====\n"
    )
    assert "`run_model()`" in text and "`runout.analysis.results.RunResult`" in text
    assert "\\(\\alpha\\)" in text
    assert "$$\nx = y^{2}\n$$" in text
    assert "| a | b |" in text and "| 1 | two more |" in text and "| 3 | four |" in text
    assert ":func:" not in text and "====" not in text


def test_checker_finds_what_it_is_for(tmp_path: Path) -> None:
    page = tmp_path / "p.html"
    page.write_text(
        "<p>see :func:<code>x</code> and e^{iθ} and "
        '<span class="arithmatex">\\(e^{i\\theta}\\)</span></p>'
        "<p>==== ====</p><code>e^{ok}</code>"
        '<a href="../../shared/seeds/x.txt">paper</a><a href="missing.html">m</a>',
        encoding="utf-8",
    )
    found = "\n".join(check_page(tmp_path, page))
    assert "raw Sphinx role" in found
    assert found.count("raw TeX") == 1  # the one outside math and code
    assert "reST table" in found
    assert "link leaves the site" in found and "broken link" in found


#: Every theory page (a model's page, diagnosis included): a new one is checked as it appears.
THEORY_PAGES = sorted(
    p.relative_to(ROOT / "docs").as_posix() for p in (ROOT / "docs").glob("models/*.md")
)


def test_every_model_has_a_checked_theory_page() -> None:
    assert len(THEORY_PAGES) >= 7 and "models/linear.md" in THEORY_PAGES


@pytest.mark.parametrize("page", THEORY_PAGES)
def test_theory_page_has_no_plain_text_mathematics_or_collapsed_list(page: str) -> None:
    text = (ROOT / "docs" / page).read_text(encoding="utf-8")
    assert check_theory_source(text, page) == []


def test_theory_checker_flags_plain_equations_and_collapsed_lists() -> None:
    # the quasi-static page as it was (issue 29): a list glued to its paragraph, equations as text
    old = (
        "With the signed ring speeds f_in, f_out [Hz], ball j at θ_j(t) = 2π f_c t + 2πj/Z:\n"
        "* inner raceway radius deviation met by ball j: W_ij(t) = Σ_k a_ik cos(kθ_j)\n"
        "* outer: W_oj(t) = Σ_k a_ok cos(kθ_j);\n"
        "\n"
        "(eq. 3–4), balance Σ Q_j n_j = F (eq. 5) with δ_pl = x\n"
    )
    found = check_theory_source(old, "old.md")
    assert sum("list without a blank line" in f for f in found) == 1
    assert {int(f.split(":")[1]) for f in found if "plain-text mathematics" in f} == {1, 2, 3, 5}
    new = (
        "With $f_{in}$, ball j at $\\theta_j(t) = 2\\pi f_c t$:\n"
        "\n"
        "* inner: $W_{ij}(t) = \\sum_k a_{ik} \\cos(k\\theta_j)$ (`f_c = x` in code is fine)\n"
        "\n"
        "$$\n"
        "Q = K_n \\delta^{1.5}\n"
        "$$\n"
        "```\n"
        "W_ij(t) = Σ\n"
        "```\n"
    )
    assert check_theory_source(new, "new.md") == []
