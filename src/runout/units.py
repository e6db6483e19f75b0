"""Units at the edge: the only module that imports pint.

Case files give a number (taken as SI) or a string carrying its unit (``"3.9688 mm"``,
``"7200 rpm"``, ``"10 deg"``). :func:`to_si` turns either into an SI float after checking the
dimension. Rotational speeds are stored as rotation frequencies in hertz (revolutions per
second): ``"1800 rpm"`` becomes 30.0, ``"30 Hz"`` stays 30.0 and ``"188.5 rad/s"`` becomes 30.0.
"""

from __future__ import annotations

import math
import re
from functools import lru_cache
from typing import Any

import pint

__all__ = ["KINDS", "UnitError", "to_si"]


class UnitError(ValueError):
    """A value that cannot be read as the expected kind of quantity."""


@lru_cache(maxsize=1)
def _registry() -> Any:
    # pint's on-disk cache of the parsed definitions cuts ~0.25 s from every CLI call; a
    # home without a writable cache directory falls back to parsing them
    try:
        ureg: Any = pint.UnitRegistry(cache_folder=":auto:")
    except OSError:
        ureg = pint.UnitRegistry()
    ureg.define("micron = micrometer")
    return ureg


# kind -> (pint dimensionality string, SI unit to convert to, human word)
KINDS: dict[str, tuple[str, str, str]] = {
    "length": ("[length]", "m", "a length"),
    "force": ("[force]", "N", "a force"),
    "pressure": ("[pressure]", "Pa", "a pressure or modulus"),
    "density": ("[mass] / [length] ** 3", "kg/m^3", "a density"),
    "mass": ("[mass]", "kg", "a mass"),
    "time": ("[time]", "s", "a time"),
    "damping": (
        "[force] * [time] / [length]",
        "N*s/m",
        "a viscous damping (force x time / length)",
    ),
    "stiffness": ("[force] / [length]", "N/m", "a stiffness (force / length)"),
    "moment": ("[force] * [length]", "N*m", "a moment"),
    "mass_length": ("[mass] * [length]", "kg*m", "an unbalance (mass x length)"),
    "frequency": ("1 / [time]", "Hz", "a frequency"),
    "angle": ("", "rad", "an angle"),
    "speed": ("1 / [time]", "Hz", "a rotational speed"),
    "dimensionless": ("", "", "a plain number"),
}


_NUMBER_FIRST = re.compile(r"^\s*[-+]?(\d|\.\d)")


def _parse(text: str) -> Any:
    ureg = _registry()
    if not _NUMBER_FIRST.match(text):
        raise UnitError(f'"{text}" cannot be read as a quantity (it must start with a number)')
    try:
        return ureg.Quantity(text.strip())
    except Exception as exc:  # pint raises several unrelated types
        raise UnitError(f'"{text}" cannot be read as a quantity ({exc})') from None


def _speed_hz(q: Any, text: str) -> float:
    """Rotational speed in revolutions per second, whatever angle unit the string used."""
    ureg = _registry()
    if not q.check("1 / [time]"):
        raise UnitError(f'"{text}" is not a rotational speed')
    factor, root = ureg.get_root_units(q.units)
    # pint treats the radian as dimensionless: rpm and rad/s have 'radian' in their root units,
    # Hz and 1/s do not. The former are angular rates, the latter revolutions per second.
    if "radian" in str(root):
        # straight to revolutions (not via rad/s and back): "7200 rpm" is exactly 120 Hz
        return float(q.to("revolution / second").magnitude)
    return float(q.magnitude) * float(factor)


def to_si(value: object, kind: str) -> float:
    """Convert a case-file value to an SI float.

    Parameters
    ----------
    value : float, int or str
        A number (already SI: m, N, Pa, kg, s, rad, Hz) or a string with its unit.
    kind : str
        One of :data:`KINDS` (``"length"``, ``"force"``, ``"angle"``, ``"speed"``, ...).

    Returns
    -------
    float
        The value in SI units; rotational speeds in revolutions per second [Hz].

    Raises
    ------
    UnitError
        If the value is not a number or a quantity string of the right dimension.
    """
    if kind not in KINDS:
        raise KeyError(f"unknown quantity kind {kind!r}")
    dim, target, word = KINDS[kind]
    if isinstance(value, bool):
        raise UnitError(f"expected {word}, got a boolean")
    if isinstance(value, int | float):
        result = float(value)
    elif isinstance(value, str):
        q = _parse(value)
        if kind == "speed":
            result = _speed_hz(q, value)
        elif kind in ("angle", "dimensionless"):
            if not q.dimensionless:
                raise UnitError(f'"{value}" is not {word}')
            result = float(q.to(target).magnitude) if target else float(q.to("").magnitude)
        else:
            if not q.check(dim):
                raise UnitError(f'"{value}" is not {word}')
            result = float(q.to(target).magnitude)
    else:
        raise UnitError(f"expected {word} as a number or a string with a unit, got {value!r}")
    if not math.isfinite(result):
        raise UnitError(f"{value!r} is not a finite number")
    return result
