"""Column names of a study's ``samples.csv`` and the ``samples_columns.json`` beside it.

Every column of ``samples.csv`` is named by a plain identifier (ASCII letters, digits and
underscores, starting with a letter), so that pandas, R, SQL and spreadsheets take the table
as it is: a varied case key with its dots and brackets written as underscores
(``operation_axial_load``, ``waviness_1_phase``), one column per element of a per-element
draw (``element_diameter_error_01``, ``element_pitch_error_front_03`` for a spindle's bearing
``front``), a line named by its direction and stable label
(``x_ball_size_error_f_c_pp_m``). Units are not in the names: ``samples_columns.json`` gives
the SI unit of every column and what each varied or line column is (its case key and element,
or the line's direction, frequency and full label).

Studies written by earlier versions named the columns by the ``[study.vary]`` key
(``element_diameter_sigma[3]``) and the line's direction, frequency and label
(``x 39.3827 Hz ball size error: f_c pp_m``), with no ``samples_columns.json``: the readers
here take both.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from runout.base.reading import InputFileError, read_json

__all__ = [
    "COLUMNS_FILE",
    "FORMAT",
    "element_column",
    "identifier",
    "line_column",
    "line_columns",
    "old_line_column",
    "read_columns",
]

#: The file beside ``samples.csv`` that gives each column's unit and meaning.
COLUMNS_FILE = "samples_columns.json"
#: Its ``format``.
FORMAT = "runout-samples-columns/1"

# symbols of the line labels' formulas, spelt out so that distinct formulas keep distinct names
_WORDS = (
    ("±", " plus minus "),
    ("+", " plus "),
    ("−", " minus "),
    ("-", " minus "),
    ("/", " over "),
    ("γ", "gamma"),
    ("α", "alpha"),
    ("β", "beta"),
    ("θ", "theta"),
    ("ω", "omega"),
    ("π", "pi"),
)
_DECIMAL_POINT = re.compile(r"(?<=\d)\.(?=\d)")
_OTHER = re.compile(r"[^A-Za-z0-9]+")


def identifier(text: str) -> str:
    """``text`` as a plain identifier: ASCII letters, digits and single underscores.

    Parameters
    ----------
    text : str
        A case key (``"waviness[1].phase"``) or a line label (``"inner 9 lobes: nZ+1, n=1"``).

    Returns
    -------
    str
        ``"waviness_1_phase"``, ``"inner_9_lobes_nZ_plus_1_n_1"``: signs spelt out (``+`` as
        ``plus``, ``-`` as ``minus``, ``/`` as ``over``), Greek letters by name, a decimal
        point as ``p``, every other run of characters as one underscore. Starts with ``c_``
        when it would start with a digit or be empty.
    """
    for symbol, word in _WORDS:
        text = text.replace(symbol, word)
    text = _DECIMAL_POINT.sub("p", text)
    name = _OTHER.sub("_", text).strip("_")
    return name if name[:1].isalpha() else f"c_{name}".rstrip("_")


def element_column(name: str, bearing: str | None, element: int, elements: int) -> str:
    """Column of element ``element`` of a per-element draw.

    Parameters
    ----------
    name : {"diameter_errors", "pitch_errors"}
        The ``[elements]`` key drawn (``element_diameter_sigma`` draws ``diameter_errors``).
    bearing : str or None
        The spindle bearing whose elements they are; None for a single bearing.
    element : int
        Element number, from 1.
    elements : int
        Number of elements Z (sets the zero padding: at least two digits).

    Returns
    -------
    str
        ``element_diameter_error_01``, ``element_pitch_error_rear_12``.
    """
    width = max(2, len(str(elements)))
    stem = "element_" + name.removesuffix("s")
    if bearing is not None:
        stem += f"_{identifier(bearing)}"
    return f"{stem}_{element:0{width}d}"


def line_column(direction: str, label: str) -> str:
    """Column of the p-p [m] of a study's line: ``<direction>_<label>_pp_m``.

    Parameters
    ----------
    direction : str
        ``"x"``, ``"y"`` or ``"z"``.
    label : str
        The line's label in the study (element numbers removed), e.g.
        ``"ball size error: f_c"``.

    Returns
    -------
    str
        ``"x_ball_size_error_f_c_pp_m"``. A study whose two labels give one name numbers the
        later ones (``..._pp_m_2``); ``samples_columns.json`` names each column's line.
    """
    return f"{identifier(direction)}_{identifier(label)}_pp_m"


def old_line_column(direction: str, frequency_hz: float, label: str) -> str:
    """The column name earlier versions gave a line: ``"<dir> <frequency> Hz <label> pp_m"``.

    Parameters
    ----------
    direction : str
        ``"x"``, ``"y"`` or ``"z"``.
    frequency_hz : float
        The line's frequency [Hz].
    label : str
        The line's label.

    Returns
    -------
    str
        The name (spaces, colons and a float included: read old files only).
    """
    return f"{direction} {frequency_hz:.6g} Hz {label} pp_m"


def read_columns(directory: Path) -> dict[str, Any] | None:
    """``samples_columns.json`` of a study directory, or None (an earlier version's study,
    or a file that is not one of ours).

    Parameters
    ----------
    directory : Path
        The study's output directory.

    Returns
    -------
    dict or None
        ``{"format", "units": {column: unit}, "columns": {column: {...}}}``; None when the
        directory has no such file (an earlier version's study).

    Raises
    ------
    InputFileError
        The file is a link out of the directory, not a regular file, beyond the bounds of
        :mod:`runout.base.reading`, not JSON, or not runout's description (an edited
        directory, not an earlier version's).
    """
    path = Path(directory) / COLUMNS_FILE
    if not (path.exists() or path.is_symlink()):
        return None
    doc = read_json(path, [Path(directory)])
    ok = (
        isinstance(doc, dict)
        and doc.get("format") == FORMAT
        and isinstance(doc.get("units"), dict)
        and isinstance(doc.get("columns"), dict)
    )
    if not ok:
        # not ours, or edited: reading samples.csv by the names of an earlier version instead
        # would silently lose its line columns
        raise InputFileError(
            str(path),
            "",
            f'is not a "{FORMAT}" description of samples.csv (an edited or foreign file; '
            "remove it to read the study as an earlier version's)",
        )
    return doc


def line_columns(directory: Path) -> dict[tuple[str, str], str] | None:
    """The line columns of a study's ``samples.csv`` by (direction, label), from its
    ``samples_columns.json``.

    Parameters
    ----------
    directory : Path
        The study's output directory.

    Returns
    -------
    dict or None
        ``{(direction, label): column}``; None for a study without ``samples_columns.json``
        (earlier versions: the column is :func:`old_line_column`).
    """
    doc = read_columns(directory)
    if doc is None:
        return None
    out: dict[tuple[str, str], str] = {}
    for name, info in doc["columns"].items():
        if isinstance(info, dict) and "label" in info and "direction" in info:
            out[(str(info["direction"]), str(info["label"]))] = name
    return out
