"""Units at the edge: the only module that imports pint.

Case files give a number (taken as SI) or a string carrying its unit (``"3.9688 mm"``,
``"7200 rpm"``, ``"10 deg"``). :func:`to_si` turns either into an SI float after checking the
dimension. Rotational speeds are stored as rotation frequencies in hertz (revolutions per
second): ``"1800 rpm"`` becomes 30.0, ``"30 Hz"`` stays 30.0 and ``"188.5 rad/s"`` becomes 30.0.

A string is read by a bounded grammar before pint sees it: a plain decimal number, then a
product of unit names with integer powers up to :data:`MAX_UNIT_POWER` (``"7850 kg/m^3"``,
``"200 N*s/m"``), at most :data:`MAX_QUANTITY_CHARS` characters. pint itself evaluates any
arithmetic (``"10**10**10 N"`` would never return), so nothing else reaches it.
"""

from __future__ import annotations

import math
import re
import sys
from functools import lru_cache
from typing import Any

__all__ = ["KINDS", "UnitError", "to_si"]


class UnitError(ValueError):
    """A value that cannot be read as the expected kind of quantity."""


def _import_pint() -> Any:
    """pint, imported without dask.

    pint.compat imports dask whenever it is installed (~0.1 s of every CLI call) to accept
    dask arrays as magnitudes, which runout never gives it. While pint is imported, ``dask``
    is marked absent in ``sys.modules`` (pint then sees no dask); the mark is removed right
    after, so dask imports normally later (the study's Dask executor). Nothing changes when
    dask was imported before.
    """
    hide = "dask" not in sys.modules
    if hide:
        sys.modules["dask"] = None  # type: ignore[assignment]
    try:
        import pint
    finally:
        if hide and sys.modules.get("dask", 0) is None:
            del sys.modules["dask"]
    return pint


@lru_cache(maxsize=1)
def _registry() -> Any:
    pint = _import_pint()
    # pint's on-disk cache of the parsed definitions cuts ~0.25 s from every CLI call; a
    # home without a writable cache directory falls back to parsing them
    try:
        ureg: Any = pint.UnitRegistry(cache_folder=":auto:")
    except OSError:
        ureg = pint.UnitRegistry()
    ureg.define("micron = micrometer")
    ureg.define("rev = revolution")  # "1800 rev/min", as drawings and ISO 15242 write speeds
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
    "velocity": ("[length] / [time]", "m/s", 'a velocity (e.g. "50 um/s")'),
    "kinematic_viscosity": (
        "[length] ** 2 / [time]",
        "m^2/s",
        'a kinematic viscosity (e.g. "20 mm^2/s" or "20 cSt")',
    ),
    "acceleration": ("[length] / [time] ** 2", "m/s^2", 'an acceleration (e.g. "3 m/s^2")'),
    "angle": ("", "rad", "an angle"),
    "speed": ("1 / [time]", "Hz", "a rotational speed"),
    "dimensionless": ("", "", "a plain number"),
    "memory": ("", "byte", "an amount of memory (e.g. '8 GiB')"),
}


#: Longest quantity string read: a number and a short unit expression fit easily; anything
#: longer is not a quantity a person typed.
MAX_QUANTITY_CHARS = 80
#: Largest power of one unit (m^3 of a density is the largest any key needs).
MAX_UNIT_POWER = 4

_NUMBER_FIRST = re.compile(r"^\s*[-+]?(\d|\.\d)")
# The grammar of a quantity string, checked before pint sees it: pint evaluates arbitrary
# arithmetic ("10**10**10 N" never returns; "2**2**2**2**2 mm" overflows), so only a plain
# decimal number followed by a product of unit names with small integer powers is accepted.
_NUMBER = r"[-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?"
_NAME = r"[A-Za-z_µμΩ°%]+"
_FACTOR = rf"{_NAME}(?:\s*(?:\^|\*\*)\s*[-+]?[1-{MAX_UNIT_POWER}])?"
_UNITS = rf"(?:1\s*/\s*)?{_FACTOR}(?:\s*(?:\*|/|·|\s)\s*{_FACTOR}){{0,7}}"
_QUANTITY = re.compile(rf"\s*(?P<number>{_NUMBER})\s*(?P<units>{_UNITS})?\s*")


def _parse(text: str) -> Any:
    """A pint quantity from a string of the bounded grammar (number, then unit names)."""
    shown = text if len(text) <= MAX_QUANTITY_CHARS else text[:MAX_QUANTITY_CHARS] + "..."
    if len(text) > MAX_QUANTITY_CHARS:
        raise UnitError(
            f'"{shown}" is too long for a quantity (at most {MAX_QUANTITY_CHARS} characters)'
        )
    if not _NUMBER_FIRST.match(text):
        raise UnitError(f'"{text}" cannot be read as a quantity (it must start with a number)')
    match = _QUANTITY.fullmatch(text)
    if match is None:
        raise UnitError(
            f'"{text}" cannot be read as a quantity: write a plain number and a unit, e.g. '
            f'"3.9688 mm", "7850 kg/m^3" or "200 N*s/m" (no arithmetic, powers up to '
            f"{MAX_UNIT_POWER})"
        )
    number = match.group("number")
    # an integer stays an integer, as pint's own parser keeps it (exact unit conversions)
    magnitude: float | int = int(number) if re.fullmatch(r"[-+]?\d+", number) else float(number)
    if not math.isfinite(magnitude):
        raise UnitError(f'"{text}" is not a finite number')
    ureg = _registry()
    try:
        units = ureg.parse_units(match.group("units") or "")
        return ureg.Quantity(magnitude, units)
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


def _bytes(q: Any, text: str) -> float:
    """Amount of memory in bytes; pint counts information in bits, a dimensionless unit."""
    if str(q.to_base_units().units) != "bit":
        raise UnitError(f'"{text}" is not an amount of memory (e.g. "8 GiB", "512 MiB")')
    return float(q.to("byte").magnitude)


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
        The value in SI units; rotational speeds in revolutions per second [Hz], amounts of
        memory in bytes [B].

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
        elif kind == "memory":
            result = _bytes(q, value)
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
