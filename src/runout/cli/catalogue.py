"""The ``runout catalogue`` command and the ``--catalogue FILE`` option of the case commands."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Annotated, Any

import typer
from rich.markup import escape
from rich.table import Table

from runout.cli.common import _guard, _out, _print_json, _print_sections

__all__ = ["CatalogueOpt", "register", "use_catalogue"]

CatalogueOpt = Annotated[
    Path | None,
    typer.Option(
        "--catalogue",
        metavar="FILE",
        help="User bearing catalogue (CSV, the format of docs/designation.md): its rows add to "
        "runout's for [bearing] designation, and replace a row of the same designation "
        "(default: the file RUNOUT_CATALOGUE names).",
        show_default=False,
    ),
]


def use_catalogue(path: Path | None) -> None:
    """Read ``path`` (refusing a bad file in one line) and make it the session's catalogue.

    The choice is passed on as ``RUNOUT_CATALOGUE``, so that a study's worker processes read
    the same rows.
    """
    if path is None:
        return
    from runout.catalogue import CATALOGUE_ENV, load_catalogue

    load_catalogue(path)  # InputFileError: one line naming the file, row and column
    os.environ[CATALOGUE_ENV] = str(path)


def _listing(entries: list[Any]) -> Table:
    table = Table(title="Bearing catalogue", title_justify="left", header_style="bold")
    names = ("designation", "kind", "d [mm]", "D [mm]", "B [mm]", "Z", "D_w [mm]", "C [kN]", "from")
    for name in names:
        table.add_column(
            escape(name), justify="left" if name in ("designation", "kind", "from") else "right"
        )
    for e in entries:
        v = e.values
        estimated = "elements" in e.estimated or "element_diameter" in e.estimated
        table.add_row(
            escape(e.designation),
            e.kind,
            f"{e.bore_diameter * 1e3:.6g}",
            f"{e.outside_diameter * 1e3:.6g}",
            f"{e.width * 1e3:.6g}",
            str(v["elements"]),
            f"{float(v['element_diameter']) * 1e3:.6g}",
            _rating(e),
            "estimate"
            if estimated
            else escape(e.catalogue if e.catalogue != "runout" else "published"),
        )
    return table


def _rating(entry: Any) -> str:
    """C [kN] as the listing shows it: ``~`` before an ISO 281 estimate, ``-`` for none."""
    rating = entry.values.get("dynamic_load_rating")
    if rating is None:
        return "-"
    mark = "~" if "dynamic_load_rating" in entry.estimated else ""
    return f"{mark}{float(rating) / 1e3:.4g}"


def register(app: typer.Typer) -> None:
    """Add ``catalogue`` to ``app`` (the ``runout`` command line)."""

    @app.command("catalogue")
    @_guard
    def catalogue_command(
        pattern: Annotated[
            str,
            typer.Argument(
                help="Glob (62*, 70??C) or part of a designation (NU2); empty: every row.",
                show_default=False,
            ),
        ] = "",
        show: Annotated[
            bool, typer.Option("--show", help="Show every matching entry whole.")
        ] = False,
        as_json: Annotated[
            bool, typer.Option("--json", help="Print one JSON object on stdout.")
        ] = False,
        catalogue: CatalogueOpt = None,
    ) -> None:
        """List the bearing catalogue's designations, or show one entry whole.

        Each row: d, D, B (ISO 15), the number Z and diameter D_w of the elements, the
        dynamic load rating C (the maker's, or ~ ISO 281's estimate), and whether they are
        published (with their citation) or estimated by a rule (docs/designation.md). With
        exactly one match, or --show, every value and its source.

        Example: runout catalogue 620? ; runout catalogue "6205-2RS JEM SKF"
        """
        from runout.catalogue import UnknownDesignationError, active_catalogue
        from runout.report.summary import bearing_source_sections

        use_catalogue(catalogue)
        found = active_catalogue()
        entries = found.search(pattern)
        if not entries and pattern:
            try:  # a designation with a suffix ("6204-2RS C3") is one entry
                entries = [found.lookup(pattern)]
            except UnknownDesignationError as exc:
                from runout.cli.common import _fail

                _fail(f"catalogue: {exc.message}")
        if as_json:
            _print_json(
                {
                    "pattern": pattern,
                    "files": list(found.files),
                    "entries": [e.to_json() for e in entries],
                }
            )
            return
        if len(entries) == 1 or show:
            for e in entries:
                doc = e.to_json()
                _print_sections(bearing_source_sections(doc))
                for note in e.notes:
                    _out.print(f"note: {escape(note)}", highlight=False, soft_wrap=True)
            return
        _out.print(_listing(entries))
        _out.print(f"{len(entries)} of {len(found)} designations", highlight=False)
