"""``[bearing] designation``: a bearing table completed from the catalogue, with provenance.

:func:`expand` runs on the case-file document before validation: it fills the keys the table
leaves out from the catalogue entry (:mod:`runout.catalogue`) and remembers which keys the case
gave itself. :func:`sources` runs after validation: a key the case gives with a value other than
the catalogue's replaces it, and the source says so in its notes (JSON ``notes``, the readable
summary, ``runout check``).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from runout.base.errors import CaseError
from runout.base.reading import InputFileError
from runout.case.standards import is_class_name
from runout.catalogue import (
    Catalogue,
    CatalogueEntry,
    UnknownDesignationError,
    active_catalogue,
)

__all__ = ["BearingSource", "Pending", "blame", "expand", "leave_catalogue_rating_unset", "sources"]

#: Keys whose values are angles [rad] (shown in degrees).
_ANGLES = ("nominal_contact_angle", "contact_angle")
#: Keys without a unit.
_PLAIN = ("elements", "inner_conformity", "outer_conformity")


def _shown(key: str, value: float) -> str:
    if key == "dynamic_load_rating":
        return f"{value / 1e3:.6g} kN"
    if key in _ANGLES:
        return f"{math.degrees(value):.6g} deg"
    if key in _PLAIN:
        return f"{value:.6g}"
    return f"{value * 1e3:.6g} mm"


@dataclass(frozen=True)
class BearingSource:
    """Where a bearing table's values come from: its catalogue entry and the case's own keys.

    Attributes
    ----------
    key : str
        The table: ``"bearing"`` or ``"bearings[2]"``.
    entry : CatalogueEntry
        The catalogue entry of its designation.
    given : mapping of str to float
        The keys the case gives beside the designation that replace a catalogue value, with
        the case's value (SI).
    notes : tuple of str
        The entry's notes (suffix not applied, row replaced) and one per replaced value.
    name : str or None
        The bearing's name in a spindle's ``[[bearings]]``; None for ``[bearing]``.
    not_applied : mapping of str to str
        Catalogue keys not applied -> the case key given instead (``inner_conformity`` ->
        ``inner_groove_radius``).
    """

    key: str
    entry: CatalogueEntry
    given: Mapping[str, float] = field(default_factory=dict)
    notes: tuple[str, ...] = ()
    name: str | None = None
    not_applied: Mapping[str, str] = field(default_factory=dict)

    def provenance(self) -> dict[str, str]:
        """Per key: the catalogue's provenance, or the case's own value or key instead.

        Returns
        -------
        dict of str to str
            ``"dimensions"`` and each key of the entry's values -> where its value comes from.
        """
        out = dict(self.entry.provenance)
        for key in self.given:
            out[key] = "case file (replaces the catalogue's value)"
        for key, by in self.not_applied.items():
            out[key] = f"not applied (the case gives {by})"
        return out

    def to_json(self) -> dict[str, Any]:
        """The JSON ``bearing_source`` object.

        Returns
        -------
        dict
            The entry's designation, d, D, B [m], values (SI) and provenance, the keys the
            case replaces (``given_in_case``) and the notes (docs/outputs.md).
        """
        doc = self.entry.to_json()
        doc.pop("notes", None)
        doc["provenance"] = self.provenance()
        doc["given_in_case"] = {k: v for k, v in self.given.items()}
        if self.name is not None:
            doc["name"] = self.name
        doc["notes"] = list(self.notes)
        return doc


@dataclass(frozen=True)
class Pending:
    """A table expanded before validation, waiting for the validated values.

    Attributes
    ----------
    key : str
        ``"bearing"`` or ``"bearings[i]"``.
    entry : CatalogueEntry
        The catalogue entry of its designation.
    given : tuple of str
        The catalogue keys the case gives itself.
    dropped : tuple of (str, str)
        Catalogue keys not applied and the case key given instead.
    name : str or None
        The spindle bearing's name.
    bore_for_limit : bool
        ``[analysis] limit_bore`` was set from the entry's bore (a tolerance class limit).
    """

    key: str
    entry: CatalogueEntry
    given: tuple[str, ...]
    dropped: tuple[
        tuple[str, str], ...
    ]  # (catalogue key not applied, the case key that replaced it)
    name: str | None = None
    bore_for_limit: bool = False


def _expand_table(
    table: dict[str, Any], key: str, path: str, catalogue: Catalogue
) -> tuple[dict[str, Any], Pending]:
    designation = table["designation"]
    if not isinstance(designation, str):
        raise CaseError(path, f"{key}.designation", f"must be a string, got {designation!r}")
    try:
        entry = catalogue.lookup(designation)
    except UnknownDesignationError as exc:
        raise CaseError(path, f"{key}.designation", exc.message) from None
    given_type = table.get("type")
    if given_type is not None and given_type != entry.type:
        raise CaseError(
            path,
            f"{key}.type",
            f"{entry.designation} is a {entry.type} bearing in the catalogue; leave type out "
            "or name another designation",
        )
    values = dict(entry.values)
    dropped: list[tuple[str, str]] = []
    for side in ("inner", "outer"):
        if f"{side}_groove_radius" in table and f"{side}_conformity" not in table:
            values.pop(f"{side}_conformity", None)
            dropped.append((f"{side}_conformity", f"{side}_groove_radius"))
    if (
        "radial_clearance" in table
        and "nominal_contact_angle" in values
        and "nominal_contact_angle" not in table
    ):
        values.pop("nominal_contact_angle")
        dropped.append(("nominal_contact_angle", "radial_clearance"))
    merged: dict[str, Any] = {"designation": designation, "type": entry.type}
    merged.update(values)
    merged.update(table)
    given = tuple(k for k in table if k in entry.values)
    return merged, Pending(key, entry, given, tuple(dropped))


def expand(
    data: dict[str, Any], path: str, catalogue: Catalogue | None = None
) -> tuple[dict[str, Any], list[Pending]]:
    """The document with every table that names a designation completed from the catalogue.

    Parameters
    ----------
    data : dict
        The case-file document (not changed).
    path : str
        The case file, for messages.
    catalogue : Catalogue, optional
        Default :func:`runout.catalogue.active_catalogue` (the shipped rows and those of the
        file ``RUNOUT_CATALOGUE`` names), read only when a table names a designation.

    Returns
    -------
    data : dict
        The completed document (``data`` itself when no table names a designation).
    pending : list of Pending
        One per completed table, for :func:`sources`.

    Raises
    ------
    CaseError
        An unknown designation (naming ``bearing.designation`` and the closest ones), a
        ``type`` the catalogue contradicts, or a user catalogue that cannot be read.
    """
    bearing = data.get("bearing")
    bearings = data.get("bearings")
    has = isinstance(bearing, dict) and "designation" in bearing
    listed = isinstance(bearings, list) and any(
        isinstance(b, dict) and "designation" in b for b in bearings
    )
    if not (has or listed):
        return data, []
    if catalogue is None:
        try:
            catalogue = active_catalogue()
        except InputFileError as exc:
            raise CaseError(path, "bearing.designation", f"the user catalogue {exc}") from None
    out = dict(data)
    pending: list[Pending] = []
    if has:
        assert isinstance(bearing, dict)
        out["bearing"], p = _expand_table(bearing, "bearing", path, catalogue)
        analysis = data.get("analysis")
        limit = analysis.get("limit") if isinstance(analysis, dict) else None
        if (
            isinstance(analysis, dict)
            and isinstance(limit, str)
            and is_class_name(limit)
            and "limit_bore" not in analysis
        ):
            # a tolerance class is tabulated by bore: the designation's d (ISO 15)
            out["analysis"] = {**analysis, "limit_bore": p.entry.bore_diameter}
            p = dataclasses.replace(p, bore_for_limit=True)
        pending.append(p)
    if listed:
        assert isinstance(bearings, list)
        tables = []
        for i, b in enumerate(bearings, start=1):
            if isinstance(b, dict) and "designation" in b:
                own = {k: v for k, v in b.items() if k not in ("name", "position")}
                merged, p = _expand_table(own, f"bearings[{i}]", path, catalogue)
                rest = {k: v for k, v in b.items() if k in ("name", "position")}
                tables.append({**rest, **merged})
                name = b.get("name")
                pending.append(
                    Pending(
                        p.key, p.entry, p.given, p.dropped, name if isinstance(name, str) else None
                    )
                )
            else:
                tables.append(b)
        out["bearings"] = tables
    return out, pending


def _close(a: float, b: float) -> bool:
    return math.isclose(a, b, rel_tol=1e-9, abs_tol=0.0)


def sources(spec: Any, pending: list[Pending]) -> tuple[BearingSource, ...]:
    """The sources of the expanded tables, with a note for each catalogue value replaced.

    Parameters
    ----------
    spec : CaseSpec
        The validated case.
    pending : list of Pending
        From :func:`expand`.

    Returns
    -------
    tuple of BearingSource
    """
    out = []
    for p in pending:
        if p.key == "bearing":
            table = spec.bearing
        else:
            table = spec.bearings[int(p.key[len("bearings[") : -1]) - 1]
        notes = [f"{p.key}.designation: {n}" for n in p.entry.notes]
        given: dict[str, float] = {}
        for key in p.given:
            value = float(getattr(table, key))
            catalogue_value = float(p.entry.values[key])
            if not _close(value, catalogue_value):
                given[key] = value
                notes.append(
                    f"{p.key}.{key}: {_shown(key, value)} given in the case replaces the "
                    f"catalogue's {_shown(key, catalogue_value)} ({p.entry.designation})"
                )
        for dropped, by in p.dropped:
            catalogue_value = float(p.entry.values[dropped])
            notes.append(
                f"{p.key}.{by}: given in the case, so the catalogue's {dropped} "
                f"{_shown(dropped, catalogue_value)} ({p.entry.designation}) is not applied"
            )
        notes += _rating_notes(p, given)
        if p.bore_for_limit:
            notes.append(
                f"analysis.limit_bore: the bore of {p.entry.designation} from the catalogue, "
                f"{_shown('bore', p.entry.bore_diameter)}, for the tolerance class limit"
            )
        out.append(BearingSource(p.key, p.entry, given, tuple(notes), p.name, dict(p.dropped)))
    return tuple(out)


def leave_catalogue_rating_unset(spec: Any, pending: list[Pending]) -> None:
    """Mark a ``dynamic_load_rating`` that came from the catalogue as not set by the case.

    The key conventions (:mod:`runout.case.conventions`) note a key the case sets that a
    model does not apply; a catalogue bearing's C is not the case's input, so a model
    without a life (the linear one, ...) need not say it leaves it out. Its value stays.

    Parameters
    ----------
    spec : CaseSpec
        The validated case (changed in place: the tables' sets of given fields).
    pending : list of Pending
        From :func:`expand`.
    """
    for p in pending:
        if "dynamic_load_rating" not in p.entry.values or "dynamic_load_rating" in p.given:
            continue
        if p.key == "bearing":
            table = spec.bearing
        else:
            table = spec.bearings[int(p.key[len("bearings[") : -1]) - 1]
        table.__pydantic_fields_set__.discard("dynamic_load_rating")


def _rating_notes(p: Pending, given: Mapping[str, float]) -> list[str]:
    """Say that the catalogue's C is an ISO 281 estimate, or was computed from geometry the
    case replaces; nothing when the case gives its own C or the row has none."""
    origin = p.entry.provenance.get("dynamic_load_rating", "")
    if "dynamic_load_rating" in given or "computed by ISO 281" not in origin:
        return []
    shown = _shown("dynamic_load_rating", float(p.entry.values["dynamic_load_rating"]))
    notes = []
    if origin.startswith("estimate"):
        notes.append(
            f"{p.key}.dynamic_load_rating: {shown} of {p.entry.designation} is an estimate, "
            "computed by ISO 281:2007 from estimated internal geometry (the catalogue holds "
            "no maker's C for it); give dynamic_load_rating, the maker's C, for a rated life"
        )
    replaced = [k for k in ("elements", "element_diameter", "pitch_diameter") if k in given]
    if replaced:
        notes.append(
            f"{p.key}.dynamic_load_rating: {shown} was computed by ISO 281:2007 from the "
            f"catalogue's {', '.join(replaced)}, not from the case's; give "
            "dynamic_load_rating for the bearing the case describes"
        )
    return notes


def blame(pending: list[Pending], key: str, message: str) -> tuple[str, str]:
    """The key and message of a refusal, naming the catalogue row when the value came from it.

    Parameters
    ----------
    pending : list of Pending
        From :func:`expand`.
    key, message : str
        The refusal as the schema or the geometry gives it (``bearing.elements``, ...).

    Returns
    -------
    (str, str)
        ``key`` and ``message`` as given, or, for a value the case did not give itself,
        ``<table>.designation`` and a message that names the row and its catalogue.
    """
    for p in pending:
        prefix = f"{p.key}."
        if not key.startswith(prefix):
            continue
        name = key[len(prefix) :]
        if name in p.entry.values and name not in p.given:
            return (
                f"{p.key}.designation",
                f"the catalogue row {p.entry.designation} ({p.entry.catalogue}) gives "
                f"{name}: {message}",
            )
    return key, message
