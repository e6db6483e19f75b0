"""ISO 281:2007 basic dynamic load rating C of catalogue rows against the maker's C.

The catalogue (:mod:`runout.catalogue`) carries the maker's C of six deep-groove rows, read in
the URB Group (Anadolu Rulman) Rolling Bearings General Catalogue v.14_2017, and computes C by
ISO 281:2007 (:func:`runout.geometry.life.basic_dynamic_load_rating`) for every other ball
row from its internal geometry. Here the ISO 281 C of those six rows, from the rows' own
(estimated) internal geometry, against the maker's: the spread an ISO 281 estimate of the
catalogue carries. ``tests/unit/case/test_catalogue_rows.py`` bounds it.
"""

from __future__ import annotations

from runout.catalogue import CatalogueEntry, shipped_catalogue
from runout.geometry.life import basic_dynamic_load_rating
from runout.validation.core import Check, bind

__all__ = ["INTRO", "MAKER_ROWS", "checks", "iso281_rating_kn"]

#: The rows whose C is the maker's (bearings.csv).
MAKER_ROWS = ("6008", "6014", "6214", "6215", "6312", "6313")
#: The bound of the comparison (tests/unit/case/test_catalogue_rows.py, MAKER_C_BOUND).
TOLERANCE = 0.15
_GEOMETRY = (
    "the row's internal geometry is estimated (Z and D_w by the catalogue's rules): C goes "
    "as Z^(2/3) D_w^1.8, one ball of Z moves it 5 to 9 %"
)


def _entry(designation: str) -> CatalogueEntry:
    return shipped_catalogue().lookup(designation)


def iso281_rating_kn(designation: str) -> float:
    """ISO 281:2007's C [kN] of a shipped row from its internal geometry.

    Parameters
    ----------
    designation : str
        A shipped row.

    Returns
    -------
    float
        C [kN].
    """
    values = _entry(designation).values
    return (
        basic_dynamic_load_rating(
            int(values["elements"]),
            float(values["element_diameter"]),
            float(values["pitch_diameter"]),
            float(values.get("nominal_contact_angle", 0.0)),
        )
        / 1e3
    )


def checks() -> list[Check]:
    """The maker's C of each row against ISO 281's from the row's geometry, within 15 %.

    Returns
    -------
    list of Check

    Notes
    -----
    ISO 281:2007 eq. (2), b_m = 1.3, f_c of Table 2; the maker's C from the URB Group
    Rolling Bearings General Catalogue v.14_2017, single row deep groove ball bearings.
    """
    out = []
    for designation in MAKER_ROWS:
        maker = float(_entry(designation).values["dynamic_load_rating"]) / 1e3
        gap = abs(iso281_rating_kn(designation) / maker - 1.0) > 0.05
        out.append(
            Check(
                "URB General Catalogue v.14_2017" if designation == MAKER_ROWS[0] else "″",
                f"C [kN] of {designation}, ISO 281 from the catalogue row's geometry",
                maker,
                bind(iso281_rating_kn, designation),
                "rel",
                TOLERANCE,
                reason=_GEOMETRY if gap else "—",
            )
        )
    return out


INTRO = """\
A catalogue bearing (`[bearing] designation`) carries its basic dynamic load rating C: the
maker's where a maker's catalogue gives it (six deep-groove rows, from the URB Group / Anadolu
Rulman Rolling Bearings General Catalogue v.14_2017), else C computed by ISO 281:2007
(C = b_m f_c (i cos α)^0.7 Z^(2/3) D_w^1.8, b_m = 1.3, f_c of its Table 2) from the row's
internal geometry, estimated for most rows (docs/designation.md). Below, ISO 281's C of the six
rows that have both, from the rows' own estimated geometry, against the maker's: the spread an
estimated C carries. Tests: `tests/unit/case/test_catalogue_rows.py`. Tolerance 15 %."""
