"""Lengths shown at the input's scale in readable text.

JSON and CSV output keep SI floats; only readable text (summaries, the report) goes through
this module. :func:`length_unit` picks one unit for a set of figures shown together (a table
column, a summary) so the largest of them reads between 0.1 and 1000 of that unit: a
nanometre-size runout prints ``312.4 nm``, a micrometre-size one ``3.124 um``.

:func:`format_length` never prints ``nan``, ``inf`` or exponent notation (``5e-10 nm``): a
non-finite value is an error (the caller has a bug, not a figure to show) and the number is
written in fixed-point notation. A model's output below the solver's resolution is numerical
noise, not a result, so a value whose magnitude is below ``resolution_m`` prints as ``0``;
:func:`resolution_note` states that resolution once, for the reader.

Unit names are ASCII (``"um"``, not ``"µm"``) so that text pastes into any terminal or file.
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np

__all__ = [
    "LENGTH_UNITS",
    "format_length",
    "format_number",
    "format_resolution",
    "length_unit",
    "resolution_note",
]

#: The units a length may be shown in, smallest first: (name, multiplier from metres).
LENGTH_UNITS: tuple[tuple[str, float], ...] = (
    ("nm", 1e9),
    ("um", 1e6),
    ("mm", 1e3),
    ("m", 1.0),
)

#: Significant digits used to decide whether a reading would round up to 1000 (switch unit).
_UNIT_CHOICE_DIGITS = 4


def length_unit(values_m: Iterable[float]) -> tuple[str, float]:
    """The unit in which a set of lengths reads best.

    Parameters
    ----------
    values_m : iterable of float or ndarray
        Lengths shown together [m] (an array of any shape is read in one vectorised pass).
        Non-finite values are ignored (they are never printed).

    Returns
    -------
    tuple of (str, float)
        Unit name and multiplier from metres: ``("nm", 1e9)``, ``("um", 1e6)``,
        ``("mm", 1e3)`` or ``("m", 1.0)``. The smallest unit in which the largest finite
        magnitude reads below 1000 (after rounding to four significant digits), hence in
        [0.1, 1000) for any largest magnitude from 1e-10 m to below 1000 m, and in [1, 1000)
        above 1 nm. All zero, all non-finite or empty gives ``("nm", 1e9)``.
    """
    if isinstance(values_m, np.ndarray):  # a record: one vectorised pass, not a Python loop
        magnitudes = np.abs(values_m.astype(np.float64, copy=False).ravel())
        largest = float(magnitudes.max(initial=0.0))
        if not math.isfinite(largest):  # rare: leave out the non-finite values
            finite = magnitudes[np.isfinite(magnitudes)]
            largest = float(finite.max(initial=0.0))
    else:
        largest = 0.0
        for value in values_m:
            magnitude = abs(float(value))
            if math.isfinite(magnitude) and magnitude > largest:
                largest = magnitude
    for name, scale in LENGTH_UNITS:
        # Decide on the reading as printed: 999.97 nm would show as "1000 nm".
        if float(f"{largest * scale:.{_UNIT_CHOICE_DIGITS}g}") < 1000.0:
            return name, scale
    return LENGTH_UNITS[-1]


def _fixed(reading: float, digits: int, max_decimals: int | None) -> str:
    """``reading`` with ``digits`` significant digits in fixed-point notation.

    Trailing zeros after the decimal point are dropped (``300``, ``0.5``). ``max_decimals``
    bounds the decimals written (a reading that rounds to zero there prints ``0``).
    """
    if reading == 0.0:
        return "0"
    exponent = math.floor(math.log10(abs(reading)))
    decimals = digits - 1 - exponent
    if max_decimals is not None:
        decimals = min(decimals, max_decimals)
    rounded = round(reading, decimals)
    text = f"{rounded:.{max(decimals, 0)}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    # round() may give -0.0 for a tiny negative reading; a sign on zero is noise.
    if float(text) == 0.0:
        return "0"
    return text


def format_length(
    value_m: float,
    unit: tuple[str, float] | None = None,
    *,
    resolution_m: float | None = None,
    digits: int = 4,
) -> str:
    """A length as readable text, e.g. ``"312.4 nm"``.

    Parameters
    ----------
    value_m : float
        The length [m].
    unit : tuple of (str, float), optional
        Unit name and multiplier from metres, usually from :func:`length_unit` over all the
        figures shown together. Default: the unit chosen for ``value_m`` alone.
    resolution_m : float, optional
        The solver's resolution [m]: a value whose magnitude is below it prints as ``0``.
        Default: no resolution (every value is shown, at most ``digits + 2`` decimals of the
        unit; a value that rounds to zero there prints ``0``).
    digits : int, default 4
        Significant digits.

    Returns
    -------
    str
        Number in fixed-point notation (never exponent notation), a space and the unit name.

    Raises
    ------
    ValueError
        When ``value_m`` or ``resolution_m`` is NaN or infinite, ``resolution_m`` is negative
        or ``digits`` is below 1.
    """
    value = float(value_m)
    if not math.isfinite(value):
        raise ValueError(f"cannot display a non-finite length ({value!r})")
    if digits < 1:
        raise ValueError(f"digits must be at least 1, got {digits}")
    if resolution_m is not None and not (math.isfinite(resolution_m) and resolution_m >= 0.0):
        raise ValueError(f"resolution_m must be finite and >= 0, got {resolution_m!r}")
    name, scale = unit if unit is not None else length_unit([value])
    if resolution_m is not None and abs(value) < resolution_m:
        return f"0 {name}"
    return f"{_fixed(value * scale, digits, digits + 2)} {name}"


def format_number(value: float, digits: int = 4) -> str:
    """A plain number in fixed-point notation with ``digits`` significant digits.

    For the figures that are not lengths (frequencies, band values): ``"0.0679"``,
    ``"1235000"``, never exponent notation. Readings below 1e-12 print as ``0``.

    Parameters
    ----------
    value : float
        The number, in whatever unit the caller shows it (e.g. [Hz]).
    digits : int, default 4
        Significant digits.

    Returns
    -------
    str
        The number in fixed-point notation, without a unit.

    Raises
    ------
    ValueError
        When ``value`` is NaN or infinite, or ``digits`` is below 1.
    """
    number = float(value)
    if not math.isfinite(number):
        raise ValueError(f"cannot display a non-finite number ({number!r})")
    if digits < 1:
        raise ValueError(f"digits must be at least 1, got {digits}")
    return _fixed(number, digits, 12)


def resolution_note(resolution_m: float, unit: tuple[str, float]) -> str:
    """The sentence that states the solver's resolution once.

    Parameters
    ----------
    resolution_m : float
        The solver's resolution [m], positive and finite.
    unit : tuple of (str, float)
        The unit the figures are shown in; the resolution is written in it unless it would
        read below 1e-6 of it (then in its own unit), and as "under 0.001" of the unit when
        it reads below that.

    Returns
    -------
    str
        E.g. ``"values below the solver's resolution (0.001 nm) print as 0"``.

    Raises
    ------
    ValueError
        When ``resolution_m`` is not positive and finite.
    """
    return (
        f"values below the solver's resolution ({format_resolution(resolution_m, unit)}) print as 0"
    )


def format_resolution(resolution_m: float, unit: tuple[str, float] | None = None) -> str:
    """A resolution as readable text: ``"0.52 nm"``, or ``"under 0.001 nm"`` when tiny.

    Parameters
    ----------
    resolution_m : float
        The resolution [m], positive and finite.
    unit : tuple of (str, float), optional
        The unit of the figures it goes with; default the unit of the resolution alone. A
        resolution that would read below 1e-6 of it is written in its own unit.

    Returns
    -------
    str
        Two significant digits and the unit name, or ``"under 0.001 <unit>"``.

    Raises
    ------
    ValueError
        When ``resolution_m`` is not positive and finite.
    """
    if not (math.isfinite(resolution_m) and resolution_m > 0.0):
        raise ValueError(f"resolution_m must be positive and finite, got {resolution_m!r}")
    name, scale = unit if unit is not None else length_unit([resolution_m])
    if resolution_m * scale < 1e-6:
        name, scale = length_unit([resolution_m])
    reading = resolution_m * scale
    # a resolution far below what any figure shows is stated as a bound, not as 0.00000052 nm
    return f"under 0.001 {name}" if reading < 1e-3 else f"{_fixed(reading, 2, None)} {name}"
