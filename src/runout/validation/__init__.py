"""Validation against the seed papers: the registry behind ``runout reproduce`` and VALIDATION.md.

One module per source holds that paper's published numbers as named constants next to their
citation, and the functions that compute ours from the example case files
(:mod:`runout.validation.cases`). The core (:mod:`.core`: :class:`Check`, :class:`Group`,
:class:`Section`, the verdict rules), the renderer (:mod:`.render`) and the ``--check``
comparison (:mod:`.compare`) are shared. :data:`SECTIONS` orders the document; :func:`build`
runs it. Nothing in the generated document is typed by hand: every "ours" column, every
difference and every verdict is computed.

The reference tests (``tests/reference/``) import the same constants and helpers, so a
published number is typed once.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

from runout.validation import (
    catalogue_rating,
    contact,
    cross_model,
    defects,
    diagnosis,
    envelope,
    iso_ts_16281,
    kinematics,
    mcfadden_smith,
    seed000_tada,
    seed001_kim,
    seed001_kim_table9,
    seed002_anderon,
    seed003_purohit,
    seed004_yu,
)
from runout.validation.cases import EXAMPLE_USES
from runout.validation.compare import GENERATED_MARK, compare, merge_sections, split_sections
from runout.validation.core import (
    AGREE,
    CHECK_RTOL,
    NOT,
    ROUNDOFF,
    SPREAD,
    Check,
    Document,
    Group,
    Row,
    Section,
)
from runout.validation.render import HEAD, example_index, render_section

__all__ = [
    "AGREE",
    "CHECK_RTOL",
    "EXAMPLE_USES",
    "GENERATED_MARK",
    "NOT",
    "ROUNDOFF",
    "SECTIONS",
    "SPREAD",
    "Check",
    "Document",
    "Group",
    "Row",
    "Section",
    "build",
    "compare",
    "merge_sections",
    "section_keys",
    "split_sections",
]

SECTIONS: list[Section] = [
    Section(
        "kinematics",
        "Kinematics (`runout.geometry.kinematics`)",
        "Tests: `tests/reference/test_kinematics_references.py`. Orders = multiples of the "
        "rotating ring's speed.",
        [
            Group(
                "",
                "",
                kinematics.checks,
                "Seed 004 eq. 2 (roller spin angle) as extracted is four times the pure-rolling "
                "spin; we use the consistent value (see `runout.geometry.kinematics`).",
            )
        ],
    ),
    Section(
        "contact",
        "Hertz contact and axial loading (`runout.geometry.contact`, `runout.geometry.loading`)",
        "Tests: `tests/reference/test_contact_references.py`, "
        '`tests/reference/test_kim_table2.py`. "Ours" is the exact Hertz solution '
        "(ellipticity solved from the complete elliptic integrals) unless the row says "
        "otherwise. Steel is E = 207.5 GPa, ν = 0.3 for Harris's numbers and E = 208 GPa, "
        "ν = 0.3 for seed 001 and seed 002.",
        [
            Group("Point contact", "", contact.point_contact_checks),
            Group("Line contact", "", contact.line_contact_checks),
            Group(
                "Ball bearing under a pure axial load — seed 001 (Kim) Table 2",
                seed001_kim.TABLE2_INTRO,
                seed001_kim.table2_checks,
                seed001_kim.TABLE2_OUTRO,
            ),
        ],
    ),
    Section(
        "spectrum",
        "Spectra and band values (`runout.analysis.spectrum`)",
        seed002_anderon.SPECTRUM_INTRO,
        [Group("", "", seed002_anderon.spectrum_checks)],
    ),
    Section(
        "linear",
        "Linear model, seed 002 Anderon vibration of a 608 (`runout.models.linear`)",
        seed002_anderon.LINEAR_INTRO,
        [
            Group("", "", seed002_anderon.linear_checks, seed002_anderon.LINEAR_OUTRO),
            Group(
                "Cross-check: `linear` (force-balance variant) vs `quasi_static_3d` at small "
                "amplitude",
                cross_model.INTRO,
                cross_model.checks,
            ),
        ],
    ),
    Section(
        "roller",
        "Rigid constraint model of a cylindrical roller bearing "
        "(`runout.models.roller_constraint`)",
        seed004_yu.INTRO,
        [Group("", "", seed004_yu.checks)],
    ),
    Section(
        "dynamic",
        "Dynamic model (`runout.models.dynamic`, seed 003)",
        seed003_purohit.INTRO,
        [Group("Seed 003 Figs. 3–4", "", seed003_purohit.checks, seed003_purohit.OUTRO)],
    ),
    Section(
        "quasi_static",
        "Quasi-static NRRO models (`runout.models.quasi_static_3d`, "
        "`runout.models.quasi_static_2d`)",
        "Tests: `tests/reference/test_seed000_tada.py`, "
        "`tests/reference/test_seed001_kim_nrro.py`, `tests/unit/models/test_quasi_static_3d.py`.",
        [
            Group(
                "Seed 000 (Tada), 3-D model, standard model of Table 1",
                seed000_tada.INTRO,
                seed000_tada.checks,
            ),
            Group(
                "Seed 001 (Kim), 2-D model, Tables 4–8",
                seed001_kim.NRRO_INTRO,
                seed001_kim.nrro_checks,
                seed001_kim.nrro_outro,
            ),
            Group(
                "`equilibrium` (Jones–Harris, seed 001 §2.1) — Table 2 at 7200 rpm",
                seed001_kim.EQUILIBRIUM_INTRO,
                seed001_kim.equilibrium_checks,
            ),
        ],
    ),
    Section(
        "life",
        "Reference rating life, ISO/TS 16281 (`runout.geometry.life`, `equilibrium`)",
        iso_ts_16281.INTRO,
        [
            Group("", "", iso_ts_16281.checks),
            Group(
                "A catalogue bearing's dynamic load rating C (ISO 281:2007, `runout.catalogue`)",
                catalogue_rating.INTRO,
                catalogue_rating.checks,
            ),
        ],
    ),
    Section(
        "diagnosis",
        "Diagnosis from a measured record (`runout.diagnose.fit`)",
        diagnosis.INTRO,
        [Group("", "", diagnosis.checks)],
    ),
    Section(
        "envelope",
        "Envelope diagnosis of an acceleration record (`runout.diagnose.envelope`)",
        envelope.INTRO,
        [Group("", "", envelope.checks)],
    ),
    Section(
        "studies",
        "Studies (`runout.study.run`, `runout.study.arrangement`)",
        "",
        [
            Group(
                "Seed 001 (Kim) Table 9: f_c line of 1000 bearings with random ball diameters",
                seed001_kim_table9.INTRO,
                seed001_kim_table9.checks,
            )
        ],
    ),
    Section(
        "defects",
        "Localized defects and their acceleration signal (`runout.models.dynamic`, "
        "`[analysis] signal`)",
        defects.INTRO,
        [Group("", "", defects.checks)],
    ),
    Section(
        "mcfadden_smith",
        "An inner-race spall's envelope spectrum against McFadden & Smith (1984)",
        mcfadden_smith.SECTION_INTRO,
        [
            Group(
                "The analytic spectrum, reproduced through runout's housing and envelope",
                mcfadden_smith.CHAIN_INTRO,
                mcfadden_smith.chain_checks,
            ),
            Group(
                "runout's inner-raceway spall against the model",
                mcfadden_smith.INTRO,
                mcfadden_smith.checks,
            ),
        ],
    ),
]


def section_keys() -> list[str]:
    """The keys of :data:`SECTIONS`, in document order (``runout reproduce --only``).

    Returns
    -------
    list of str
        ``kinematics``, ``contact``, ... as :data:`SECTIONS` orders them.
    """
    return [s.key for s in SECTIONS]


def build(
    only: Iterable[str] | None = None,
    progress: Callable[[str, int, int], None] | None = None,
) -> Document:
    """Run the checks (all sections, or those in ``only``) and render the document.

    Parameters
    ----------
    only : iterable of str, optional
        Keys of the sections to run (:func:`section_keys`); None runs them all and adds the
        index of the example case files.
    progress : callable, optional
        Called as ``progress(title, index, count)`` before each section.

    Returns
    -------
    Document
        The Markdown of VALIDATION.md (its head, the sections) and every evaluated row.

    Raises
    ------
    runout.base.errors.RunoutError
        A key of ``only`` that names no section.
    """
    keys = section_keys()
    wanted = list(keys if only is None else only)
    unknown = [k for k in wanted if k not in keys]
    if unknown:
        from runout.base.errors import RunoutError

        raise RunoutError(f"unknown section(s) {', '.join(unknown)}; choose from {', '.join(keys)}")
    sections = [s for s in SECTIONS if s.key in wanted]
    parts = [HEAD]
    rows: list[Row] = []
    for i, s in enumerate(sections):
        if progress is not None:
            progress(s.title, i, len(sections))
        text, section_rows = render_section(s)
        parts.append(text)
        rows += section_rows
    if only is None:
        parts.append(example_index())
    return Document("\n".join(parts), rows)
