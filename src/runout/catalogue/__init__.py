"""The bearing catalogue: a whole bearing from its designation (``[bearing] designation``).

The shipped table (``bearings.csv`` beside this module) holds one row per designation: the
ISO 15 boundary dimensions (bore d, outside diameter D, width B) of the common series (deep
groove 618, 619, 160, 60, 62, 63 and a few miniature ones; angular contact 719 and 70 with the
contact-angle suffixes C = 15 deg and AC = 25 deg, 72 with C, AC and B = 40 deg; cylindrical
roller NU2 and NU3), and the internal geometry where a publication gives it, with its
citation. A cell left empty is estimated by a named rule (:mod:`runout.catalogue._rules`),
and every value says where it comes from (:attr:`CatalogueEntry.provenance`). A ball bearing
row carries its basic dynamic load rating C: the maker's where a maker's catalogue gives it
(``dynamic_load_rating_kN``, cited in ``dynamic_load_rating_source``), else C computed by
ISO 281:2007 from the row's internal geometry (an ``estimate`` where that geometry is).

A user catalogue in the same format (``runout ... --catalogue FILE`` or the environment
variable ``RUNOUT_CATALOGUE``) adds rows, and replaces a shipped row of the same designation
(the entry then says so in its notes).

Examples
--------
>>> from runout.catalogue import lookup
>>> entry = lookup("6205-2RS JEM SKF")
>>> entry.bearing.elements
9
>>> entry.provenance["elements"][:32]
'Case Western Reserve University '
"""

from __future__ import annotations

import csv
import difflib
import fnmatch
import io
import math
import os
import re
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from decimal import Decimal, InvalidOperation
from functools import cache
from importlib import resources
from pathlib import Path
from typing import Any

from runout.base.errors import RunoutError
from runout.base.reading import InputFileError, read_text
from runout.catalogue._rules import RULES, estimate
from runout.geometry.bearing import BallBearing, Bearing, RollerBearing
from runout.geometry.life import MAX_DYNAMIC_LOAD_RATING, basic_dynamic_load_rating

__all__ = [
    "CATALOGUE_ENV",
    "KINDS",
    "MAX_CATALOGUE_BYTES",
    "MAX_CATALOGUE_ROWS",
    "Catalogue",
    "CatalogueEntry",
    "UnknownDesignationError",
    "active_catalogue",
    "load_catalogue",
    "lookup",
    "search",
    "shipped_catalogue",
]

#: Environment variable naming a user catalogue file (same format as the shipped one).
CATALOGUE_ENV = "RUNOUT_CATALOGUE"
#: Largest user catalogue file read [B].
MAX_CATALOGUE_BYTES = 4 * 1024 * 1024
#: Most rows of one catalogue file.
MAX_CATALOGUE_ROWS = 20_000
#: Kinds of bearing a row may describe, and the case's ``[bearing] type`` of each.
KINDS = {
    "deep_groove": "ball",
    "angular_contact": "ball",
    "cylindrical_roller": "cylindrical_roller",
}
#: What the shipped table's boundary dimensions come from.
ISO15 = "ISO 15 boundary dimensions"

_REQUIRED = ("designation", "kind", "d_mm", "D_mm", "B_mm")
#: Optional columns -> (case key, divisor to SI); lengths in mm, angles in degrees.
_INTERNAL: dict[str, tuple[str, int]] = {
    "elements": ("elements", 1),
    "element_diameter_mm": ("element_diameter", 1000),
    "pitch_diameter_mm": ("pitch_diameter", 1000),
    "inner_raceway_diameter_mm": ("inner_raceway_diameter", 1000),
    "outer_raceway_diameter_mm": ("outer_raceway_diameter", 1000),
    "inner_conformity": ("inner_conformity", 1),
    "outer_conformity": ("outer_conformity", 1),
}
#: The maker's basic dynamic load rating C [kN] and its citation (optional columns).
_RATING = "dynamic_load_rating_kN"
_RATING_SOURCE = "dynamic_load_rating_source"
_COLUMNS = (
    *_REQUIRED,
    "nominal_contact_angle_deg",
    *_INTERNAL,
    "source",
    _RATING,
    _RATING_SOURCE,
)
#: Keys ISO 281's load rating is computed from (:func:`_rating`).
_RATING_GEOMETRY = ("elements", "element_diameter", "pitch_diameter")
_BALL_ONLY = ("pitch_diameter", "inner_conformity", "outer_conformity")
_ROLLER_ONLY = ("inner_raceway_diameter", "outer_raceway_diameter")
#: Suffixes read from a designation after its basic part (separated by a space, - or /).
_SEALS = re.compile(r"^(2RS\d?|RS\d?|2RSH|2RSL|2Z|Z|ZZ|2RZ|RZ|LLU|LLB|DDU|VV)$")
_CLEARANCE = re.compile(r"^C[2-5]$")


class UnknownDesignationError(RunoutError, KeyError):
    """A designation the catalogue does not hold.

    Parameters
    ----------
    designation : str
        The designation asked for.
    close : list of str
        The closest designations the catalogue holds (difflib), best first.
    """

    def __init__(self, designation: str, close: list[str]) -> None:
        self.designation = designation
        self.close = close
        hint = f"; close: {', '.join(close)}" if close else ""
        self.message = (
            f"{designation!r} is not in the catalogue{hint} (runout catalogue lists it; a "
            f"user catalogue adds rows: --catalogue FILE or {CATALOGUE_ENV})"
        )
        super().__init__(self.message)

    def __str__(self) -> str:
        return self.message


@dataclass(frozen=True)
class CatalogueEntry:
    """One bearing of the catalogue: boundary dimensions, internal geometry, provenance.

    Attributes
    ----------
    designation : str
        The row's designation (``"6204"``, ``"7014C"``, ``"6205-2RS JEM SKF"``).
    kind : {"deep_groove", "angular_contact", "cylindrical_roller"}
        The bearing's kind.
    bore_diameter, outside_diameter, width : float
        Boundary dimensions d, D, B [m].
    values : mapping of str to float or int
        The ``[bearing]`` keys the entry sets, by case-file name, SI ([m], [rad], [-],
        ``dynamic_load_rating`` [N]).
    provenance : mapping of str to str
        Per key of ``values`` (and ``"dimensions"`` for d, D, B): the citation of a published
        value, or the statement of the rule that estimated it.
    catalogue : str
        Where the row was read: ``"runout"`` (shipped) or the user catalogue file.
    requested : str
        The designation as asked for (``"6204-2RS C3"``); the row's when listed.
    suffix : str
        What followed the basic designation when no row matched ``requested`` exactly.
    notes : tuple of str
        What the entry does not apply (a suffix) or replaced (a shipped row).
    """

    designation: str
    kind: str
    bore_diameter: float
    outside_diameter: float
    width: float
    values: Mapping[str, float | int]
    provenance: Mapping[str, str]
    catalogue: str = "runout"
    requested: str = ""
    suffix: str = ""
    notes: tuple[str, ...] = field(default=())

    @property
    def type(self) -> str:
        """The case's ``[bearing] type``: ``"ball"`` or ``"cylindrical_roller"``."""
        return KINDS[self.kind]

    @property
    def estimated(self) -> tuple[str, ...]:
        """The keys whose values come from a rule, not a publication."""
        return tuple(k for k, v in self.provenance.items() if v.startswith("estimate"))

    @property
    def bearing(self) -> Bearing:
        """The bearing the models take (:class:`BallBearing` or :class:`RollerBearing`).

        Zero radial clearance unless the row gives a nominal contact angle (which sets it);
        default material.
        """
        if self.type == "ball":
            return BallBearing(**self.values)  # type: ignore[arg-type]
        return RollerBearing(**self.values)  # type: ignore[arg-type]

    def to_json(self) -> dict[str, Any]:
        """The entry as JSON.

        Returns
        -------
        dict
            Designation (and as requested), kind, type, d, D, B [m], the catalogue it was read
            from, values (SI), provenance, and the suffix and notes where there are any.
        """
        out: dict[str, Any] = {
            "designation": self.designation,
            "requested": self.requested or self.designation,
            "kind": self.kind,
            "type": self.type,
            "bore_diameter_m": self.bore_diameter,
            "outside_diameter_m": self.outside_diameter,
            "width_m": self.width,
            "catalogue": self.catalogue,
            "values": dict(self.values),
            "provenance": dict(self.provenance),
        }
        if self.suffix:
            out["suffix"] = self.suffix
        if self.notes:
            out["notes"] = list(self.notes)
        return out


def _normal(designation: str) -> str:
    return " ".join(designation.upper().split())


@dataclass(frozen=True)
class Catalogue:
    """Rows by designation, with where each was read.

    Attributes
    ----------
    entries : mapping of str to CatalogueEntry
        By designation in upper case, single spaces.
    files : tuple of str
        The user catalogue files read, in order.
    """

    entries: Mapping[str, CatalogueEntry]
    files: tuple[str, ...] = ()

    def __iter__(self) -> Iterator[CatalogueEntry]:
        return iter(self.entries.values())

    def __len__(self) -> int:
        return len(self.entries)

    def extended(self, other: Catalogue) -> Catalogue:
        """This catalogue with another's rows added.

        Parameters
        ----------
        other : Catalogue
            Rows to add; one of a designation already here replaces that row, and says so in
            its notes.

        Returns
        -------
        Catalogue
        """
        merged = dict(self.entries)
        for key, entry in other.entries.items():
            if key in merged:
                old = merged[key]
                note = (
                    f"catalogue row {entry.designation} of {entry.catalogue} replaces the row "
                    f"of {old.catalogue}"
                )
                entry = _replace(entry, notes=(*entry.notes, note))
            merged[key] = entry
        return Catalogue(merged, (*self.files, *other.files))

    def lookup(self, designation: str) -> CatalogueEntry:
        """The entry of a designation, a suffix after the basic one noted (see :func:`lookup`).

        Parameters
        ----------
        designation : str
            As the case gives it (case and spaces aside).

        Returns
        -------
        CatalogueEntry

        Raises
        ------
        UnknownDesignationError
            Naming the closest designations.
        """
        requested = " ".join(str(designation).split())
        key = _normal(requested)
        entry = self.entries.get(key)
        if entry is not None:
            return _replace(entry, requested=requested)
        # the longest basic designation the text starts with, followed by a separator
        for cut in sorted((m.start() for m in re.finditer(r"[\s\-/]", key)), reverse=True):
            base = self.entries.get(key[:cut].strip())
            if base is not None:
                suffix = requested[cut:].strip(" -/")
                return _replace(
                    base,
                    requested=requested,
                    suffix=suffix,
                    notes=(*base.notes, *_suffix_notes(base.designation, suffix)),
                )
        close = difflib.get_close_matches(key, list(self.entries), n=5, cutoff=0.6)
        raise UnknownDesignationError(requested, [self.entries[c].designation for c in close])

    def search(self, pattern: str = "") -> list[CatalogueEntry]:
        """Rows whose designation matches a pattern (see :func:`search`).

        Parameters
        ----------
        pattern : str
            A glob or a substring, case aside; empty: every row.

        Returns
        -------
        list of CatalogueEntry
        """
        text = _normal(pattern)
        if not text:
            return list(self.entries.values())
        if any(ch in text for ch in "*?["):
            return [e for k, e in self.entries.items() if fnmatch.fnmatchcase(k, text)]
        return [e for k, e in self.entries.items() if text in k]


def _replace(entry: CatalogueEntry, **changes: Any) -> CatalogueEntry:
    import dataclasses

    return dataclasses.replace(entry, **changes)


def _suffix_notes(designation: str, suffix: str) -> list[str]:
    seals, clearance, other = [], [], []
    for token in re.split(r"[\s\-/]+", suffix.upper()):
        if not token:
            continue
        if _SEALS.match(token):
            seals.append(token)
        elif _CLEARANCE.match(token):
            clearance.append(token)
        else:
            other.append(token)
    notes = []
    if seals:
        notes.append(
            f"suffix {' '.join(seals)}: seals or shields, which do not change the rolling "
            f"geometry; the geometry is that of {designation}"
        )
    if clearance:
        notes.append(
            f"suffix {' '.join(clearance)}: radial clearance class not applied (the catalogue "
            "holds no clearance classes); give radial_clearance for the clearance it means"
        )
    if other:
        notes.append(
            f"suffix {' '.join(other)}: not applied; the geometry is that of {designation} (a "
            "suffix that changes the internal design, such as E or ECP, needs that maker's "
            "values)"
        )
    return notes


# --------------------------------------------------------------------------------------------
# reading a catalogue file
# --------------------------------------------------------------------------------------------
def _cell_number(text: str, name: str, where: str, file: str, divisor: int = 1) -> float:
    """The cell's number over ``divisor`` (mm to m: 1000), rounded once from the decimal."""
    try:
        exact = Decimal(text)
    except InvalidOperation:
        raise InputFileError(file, where, f"{name} must be a number, got {text[:40]!r}") from None
    if not exact.is_finite() or exact <= 0 or len(text) > 40:
        raise InputFileError(file, where, f"{name} must be a finite number > 0, got {text[:40]!r}")
    value = float(exact / divisor)
    if not math.isfinite(value) or value <= 0.0:  # 1e400, 1e-400: beyond a float
        raise InputFileError(file, where, f"{name} is beyond a float, got {text[:40]!r}")
    return value


def _entry(row: dict[str, str], file: str, line: int, catalogue: str) -> CatalogueEntry:
    def where(column: str) -> str:
        return f"row {line}, column {column}"

    designation = " ".join(row["designation"].split())
    if not designation or len(designation) > 64 or not designation.isprintable():
        raise InputFileError(file, where("designation"), "must be 1 to 64 printable characters")
    kind = row["kind"].strip()
    if kind not in KINDS:
        raise InputFileError(
            file, where("kind"), f"must be one of {', '.join(KINDS)}, got {kind[:40]!r}"
        )
    dims = {c: _cell_number(row[c].strip(), c, where(c), file, 1000) for c in _REQUIRED[2:]}
    bore, outside, width = dims["d_mm"], dims["D_mm"], dims["B_mm"]
    if not outside > bore:
        raise InputFileError(file, where("D_mm"), "the outside diameter D must exceed the bore d")
    source = (row.get("source") or "").strip()
    given: dict[str, float] = {}
    for column, (key, divisor) in _INTERNAL.items():
        text = (row.get(column) or "").strip()
        if not text:
            continue
        if key in _BALL_ONLY and kind == "cylindrical_roller":
            raise InputFileError(file, where(column), "only applies to ball bearings")
        if key in _ROLLER_ONLY and kind != "cylindrical_roller":
            raise InputFileError(file, where(column), "only applies to cylindrical_roller")
        value = _cell_number(text, column, where(column), file, divisor)
        if key == "elements" and (value != int(value) or value < 3):
            raise InputFileError(file, where(column), f"must be an integer >= 3, got {text!r}")
        given[key] = value
    if given and not source:
        raise InputFileError(
            file,
            where("source"),
            "internal dimensions need their source (a citation); leave them empty to have "
            "runout estimate them",
        )
    provenance = {"dimensions": ISO15 if catalogue == "runout" else f"user catalogue {catalogue}"}
    values: dict[str, float | int] = {}
    for key, value in given.items():
        values[key] = value
        provenance[key] = source
    for key, (value, rule) in estimate(kind, bore, outside, given).items():
        values[key] = value
        provenance[key] = rule
    if "elements" in values:
        values["elements"] = int(values["elements"])
    angle = (row.get("nominal_contact_angle_deg") or "").strip()
    if angle:
        if kind != "angular_contact":
            raise InputFileError(
                file, where("nominal_contact_angle_deg"), "only applies to angular_contact"
            )
        degrees = _cell_number(
            angle, "nominal_contact_angle_deg", where("nominal_contact_angle_deg"), file
        )
        if degrees >= 90.0:
            raise InputFileError(
                file, where("nominal_contact_angle_deg"), f"must be < 90, got {angle!r}"
            )
        values["nominal_contact_angle"] = math.radians(degrees)
        provenance["nominal_contact_angle"] = (
            "the designation's contact-angle suffix (C 15 deg, AC 25 deg, B 40 deg)"
            if catalogue == "runout"
            else source or f"user catalogue ({catalogue})"
        )
    elif kind == "angular_contact":
        raise InputFileError(
            file, where("nominal_contact_angle_deg"), "an angular_contact row needs its angle"
        )
    _rating(row, kind, values, provenance, file, where)
    entry = CatalogueEntry(
        designation=designation,
        kind=kind,
        bore_diameter=bore,
        outside_diameter=outside,
        width=width,
        values=values,
        provenance=provenance,
        catalogue=catalogue,
    )
    _check_geometry(entry, file, f"row {line}")
    return entry


def _rating(
    row: dict[str, str],
    kind: str,
    values: dict[str, float | int],
    provenance: dict[str, str],
    file: str,
    where: Any,
) -> None:
    """Set ``dynamic_load_rating`` [N] of a ball bearing row: the maker's, else ISO 281's.

    A ``dynamic_load_rating_kN`` cell is the maker's C with its citation
    (``dynamic_load_rating_source``, else ``source``). An empty cell: C computed by
    ISO 281:2007 (:func:`runout.geometry.life.basic_dynamic_load_rating`) from the row's
    internal geometry, its provenance saying whether that geometry is published or estimated
    (an estimate's provenance starts with ``estimate``). A cylindrical roller row has no C
    (runout rates the life of ball bearings only).
    """
    text = (row.get(_RATING) or "").strip()
    cited = (row.get(_RATING_SOURCE) or "").strip() or (row.get("source") or "").strip()
    if kind == "cylindrical_roller":
        if text:
            raise InputFileError(
                file, where(_RATING), "only applies to ball bearings (runout rates their life)"
            )
        return
    if text:
        try:
            exact = Decimal(text)
        except InvalidOperation:
            raise InputFileError(
                file, where(_RATING), f"{_RATING} must be a number, got {text[:40]!r}"
            ) from None
        newtons = float(exact * 1000) if exact.is_finite() and len(text) <= 40 else math.nan
        if not (math.isfinite(newtons) and 0.0 < newtons <= MAX_DYNAMIC_LOAD_RATING):
            raise InputFileError(
                file,
                where(_RATING),
                f"{_RATING} must be a finite number > 0 and at most "
                f"{MAX_DYNAMIC_LOAD_RATING / 1e3:.0e} kN, got {text[:40]!r}",
            )
        if not cited:
            raise InputFileError(
                file,
                where(_RATING_SOURCE),
                "a dynamic load rating needs its source (a citation); leave it empty to have "
                "runout compute it by ISO 281",
            )
        values["dynamic_load_rating"] = newtons
        provenance["dynamic_load_rating"] = cited
        return
    estimated = [k for k in _RATING_GEOMETRY if provenance[k].startswith("estimate")]
    try:
        rating = basic_dynamic_load_rating(
            int(values["elements"]),
            float(values["element_diameter"]),
            float(values["pitch_diameter"]),
            float(values.get("nominal_contact_angle", 0.0)),
        )
    except RunoutError:
        return  # outside ISO 281's f_c table: no C (the run notes there is no life)
    values["dynamic_load_rating"] = rating
    if estimated:
        provenance["dynamic_load_rating"] = (
            "estimate (computed by ISO 281:2007 from estimated internal geometry: "
            f"{', '.join(estimated)} by the catalogue's rules; b_m = 1.3, f_c of Table 2)"
        )
    else:
        provenance["dynamic_load_rating"] = (
            "computed by ISO 281:2007 from published internal geometry "
            f"({provenance['element_diameter']}; b_m = 1.3, f_c of Table 2)"
        )


def _check_geometry(entry: CatalogueEntry, file: str, where: str) -> None:
    """Refuse a row whose elements do not fit between its rings or round its pitch circle."""
    v = entry.values
    d_w = float(v["element_diameter"])
    if entry.type == "ball":
        pitch = float(v["pitch_diameter"])
    else:
        pitch = 0.5 * (float(v["inner_raceway_diameter"]) + float(v["outer_raceway_diameter"]))
    section = 0.5 * (entry.outside_diameter - entry.bore_diameter)
    problem = ""
    if not d_w < section:
        problem = f"element diameter {d_w * 1e3:.4g} mm does not fit the section (D - d)/2"
    elif not entry.bore_diameter < pitch - d_w:
        problem = "the elements on the pitch circle reach past the bore"
    elif not pitch + d_w < entry.outside_diameter:
        problem = "the elements on the pitch circle reach past the outside diameter"
    elif int(v["elements"]) * d_w >= math.pi * pitch:
        problem = (
            f"{v['elements']} elements of {d_w * 1e3:.4g} mm do not fit round the pitch circle"
        )
    if problem:
        raise InputFileError(file, where, f"{entry.designation}: {problem}")


def parse_catalogue(text: str, file: str, catalogue: str) -> Catalogue:
    """Rows of catalogue text (CSV, ``#`` comment lines, a header naming the columns).

    Parameters
    ----------
    text : str
        The file's text.
    file : str
        The file as shown in messages.
    catalogue : str
        What the entries say they were read from (``"runout"`` or the file).

    Returns
    -------
    Catalogue

    Raises
    ------
    InputFileError
        Naming the file, the row (counted in lines of the file) and the column.
    """
    lines = [(n, line) for n, line in enumerate(text.splitlines(), start=1)]
    body = [(n, line) for n, line in lines if line.strip() and not line.lstrip().startswith("#")]
    if not body:
        raise InputFileError(file, "", "holds no header row (" + ", ".join(_REQUIRED) + ", ...)")
    if len(body) - 1 > MAX_CATALOGUE_ROWS:
        raise InputFileError(file, "", f"holds more than {MAX_CATALOGUE_ROWS} rows")
    reader = csv.reader(io.StringIO("\n".join(line for _, line in body)))
    rows = list(reader)
    header = [h.strip() for h in rows[0]]
    header_line = body[0][0]
    for column in header:
        if column not in _COLUMNS:
            close = difflib.get_close_matches(column, _COLUMNS, n=1)
            hint = f" (did you mean {close[0]}?)" if close else ""
            raise InputFileError(
                file, f"row {header_line}, column {column[:40]}", f"unknown column{hint}"
            )
    if len(set(header)) != len(header):
        raise InputFileError(file, f"row {header_line}", "a column is named twice")
    for column in _REQUIRED:
        if column not in header:
            raise InputFileError(file, f"row {header_line}", f"has no column {column}")
    entries: dict[str, CatalogueEntry] = {}
    for (line, _), cells in zip(body[1:], rows[1:], strict=True):
        if len(cells) != len(header):
            raise InputFileError(
                file, f"row {line}", f"has {len(cells)} cells, the header {len(header)}"
            )
        entry = _entry(dict(zip(header, cells, strict=True)), file, line, catalogue)
        key = _normal(entry.designation)
        if key in entries:
            raise InputFileError(
                file, f"row {line}, column designation", f"{entry.designation} is given twice"
            )
        entries[key] = entry
    files = () if catalogue == "runout" else (file,)
    return Catalogue(entries, files)


@cache
def shipped_catalogue() -> Catalogue:
    """The catalogue shipped with runout (``runout/catalogue/bearings.csv``).

    Returns
    -------
    Catalogue
    """
    text = resources.files(__package__).joinpath("bearings.csv").read_text(encoding="utf-8")
    return parse_catalogue(text, "runout/catalogue/bearings.csv", "runout")


def load_catalogue(path: str | Path) -> Catalogue:
    """A user catalogue file, read within :data:`MAX_CATALOGUE_BYTES` and inside its directory.

    Parameters
    ----------
    path : str or Path
        The CSV file (the format of the shipped one: docs/designation.md).

    Returns
    -------
    Catalogue
        Its rows alone (:meth:`Catalogue.extended` adds them to another).

    Raises
    ------
    InputFileError
        The file cannot be read (not a regular file, a link out of its directory, too large,
        not UTF-8), or a row is bad: naming the file, row and column.
    """
    p = Path(path)
    shown = str(path)
    text = read_text(p, MAX_CATALOGUE_BYTES, [p.absolute().parent], shown)
    return parse_catalogue(text, shown, shown)


def active_catalogue(path: str | Path | None = None) -> Catalogue:
    """The shipped catalogue extended by ``path``, else by the file ``RUNOUT_CATALOGUE`` names.

    Parameters
    ----------
    path : str or Path, optional
        A user catalogue file; default the environment variable's (none: the shipped one).

    Returns
    -------
    Catalogue
    """
    chosen = path if path is not None else os.environ.get(CATALOGUE_ENV) or None
    if chosen is None:
        return shipped_catalogue()
    return shipped_catalogue().extended(load_catalogue(chosen))


def lookup(designation: str, catalogue: str | Path | Catalogue | None = None) -> CatalogueEntry:
    """The catalogue entry of a designation, with the provenance of every value.

    A row of exactly that designation (case and spaces aside) wins; otherwise the longest row
    designation the text starts with, followed by a space, ``-`` or ``/``, with the rest as a
    suffix that the entry's notes say is not applied (seals and shields do not change the
    rolling geometry; a clearance class C2..C5 is not applied).

    Parameters
    ----------
    designation : str
        ``"6204"``, ``"7014C"``, ``"NU209"``, ``"6205-2RS JEM SKF"``, ...
    catalogue : str, Path or Catalogue, optional
        A user catalogue file, or a catalogue; default :func:`active_catalogue`.

    Returns
    -------
    CatalogueEntry
        ``.bearing`` is the bearing the models take; ``.provenance`` says where each value
        comes from.

    Raises
    ------
    UnknownDesignationError
        Naming the closest designations.
    """
    found = catalogue if isinstance(catalogue, Catalogue) else active_catalogue(catalogue)
    return found.lookup(designation)


def search(
    pattern: str = "", catalogue: str | Path | Catalogue | None = None
) -> list[CatalogueEntry]:
    """The entries whose designation matches ``pattern``.

    Parameters
    ----------
    pattern : str
        A glob (``"62*"``, ``"70??C"``) or a substring (``"NU2"``), case aside; empty: all.
    catalogue : str, Path or Catalogue, optional
        A user catalogue file, or a catalogue; default :func:`active_catalogue`.

    Returns
    -------
    list of CatalogueEntry
        In the catalogue's order.
    """
    found = catalogue if isinstance(catalogue, Catalogue) else active_catalogue(catalogue)
    return found.search(pattern)


__all__ += ["RULES", "parse_catalogue"]
