r"""The measured balls of a lot: the CSV file an arrangement study (``[study] lot``) reads.

One row per ball, a header naming the columns with their units:

* ``ball`` (optional): the ball's name in the lot (default its row number, from 1);
* ``diameter_error_<unit>``: its diameter minus the nominal ``element_diameter``;
* ``waviness_<k>_amplitude_<unit>`` and ``waviness_<k>_phase_<deg|rad>`` (optional, any number
  of orders k, each amplitude with its phase): the order-k harmonic of its form error, as a
  ``[[waviness]] part = "ball"`` entry gives it: zero-to-peak of the ball's *radius* deviation,
  phase in the ball's frame.

Lengths in ``m``, ``mm``, ``um`` or ``nm``. Blank lines and lines starting with ``#`` are
skipped; columns are separated by commas. The file is read through
:func:`runout.base.reading.read_text` (a regular file inside the case's directory, at most
:data:`MAX_LOT_BYTES`), with at most :data:`MAX_LOT_BALLS` rows and :data:`MAX_LOT_ORDERS`
orders. Every refusal is an :class:`~runout.base.reading.InputFileError` naming the file, the
line and the column.

A ball's diameter deviation along its contact line from an order-k radius harmonic of
amplitude a is 2a for an even k and 0 for an odd one (opposite points of the ball move
together or cancel; seed 002, "Anderon vibration", eq. 26): odd orders are read, reported in
the study's notes, and do not enter the arrangement.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from runout.base.reading import InputFileError, read_text

__all__ = ["MAX_LOT_BALLS", "MAX_LOT_BYTES", "MAX_LOT_ORDERS", "BallLot", "read_lot"]

#: Most balls (rows) a lot file holds: the local search costs Z (n - Z) evaluations a move.
MAX_LOT_BALLS = 5000
#: Largest lot file read [B].
MAX_LOT_BYTES = 4 * 1024 * 1024
#: Most waviness orders of a lot file.
MAX_LOT_ORDERS = 32
#: Metres per unit of a length column.
_LENGTH = {"m": 1.0, "mm": 1e-3, "um": 1e-6, "nm": 1e-9}
#: Radians per unit of a phase column.
_ANGLE = {"deg": math.pi / 180.0, "rad": 1.0}
_DIAMETER = re.compile(r"diameter_error_(m|mm|um|nm)")
_AMPLITUDE = re.compile(r"waviness_([0-9]{1,4})_amplitude_(m|mm|um|nm)")
_PHASE = re.compile(r"waviness_([0-9]{1,4})_phase_(deg|rad)")


@dataclass(frozen=True)
class BallLot:
    """The balls of a lot, SI.

    Attributes
    ----------
    file : str
        The file as the case names it.
    names : tuple of str
        Each ball's name (the ``ball`` column, else its row number from 1).
    diameter_errors : ndarray, shape (n,)
        Diameter error of each ball [m].
    orders : ndarray of int, shape (K,)
        Waviness orders of the file, ascending.
    amplitudes : ndarray, shape (n, K)
        Zero-to-peak radius deviation of each order [m].
    phases : ndarray, shape (n, K)
        Phase of each order in the ball's frame [rad].
    """

    file: str
    names: tuple[str, ...]
    diameter_errors: NDArray[np.float64]
    orders: NDArray[np.int64]
    amplitudes: NDArray[np.float64]
    phases: NDArray[np.float64]

    @property
    def size(self) -> int:
        """Number of balls in the lot."""
        return int(self.diameter_errors.size)

    @property
    def even(self) -> NDArray[np.bool_]:
        """Which orders are even (the ones that move the shaft)."""
        return np.asarray(self.orders % 2 == 0)

    def form(self) -> tuple[NDArray[np.complex128], NDArray[np.int64]]:
        r"""Diameter-deviation harmonics :math:`2 a e^{i\varphi}` of the even orders.

        Returns
        -------
        form : ndarray of complex, shape (n, K_even)
            Along the contact line [m] (seed 002 eq. 26).
        orders : ndarray of int, shape (K_even,)
            Their orders.
        """
        keep = self.even
        form = 2.0 * self.amplitudes[:, keep] * np.exp(1j * self.phases[:, keep])
        return np.asarray(form, dtype=np.complex128), self.orders[keep]


def _columns(header: list[str], file: str) -> tuple[int | None, int, float, dict[int, tuple]]:
    """Column indices of the header: name, diameter, and per order (amplitude, phase)."""
    name_col: int | None = None
    diameter: tuple[int, float] | None = None
    amps: dict[int, tuple[int, float]] = {}
    phases: dict[int, tuple[int, float]] = {}
    seen: set[str] = set()
    for i, raw in enumerate(header):
        col = raw.strip()
        if col in seen:
            raise InputFileError(file, f"line 1, {col}", "the column is given twice")
        seen.add(col)
        if col == "ball":
            name_col = i
        elif (m := _DIAMETER.fullmatch(col)) is not None:
            if diameter is not None:
                raise InputFileError(file, col, "a second diameter_error column; keep one")
            diameter = (i, _LENGTH[m.group(1)])
        elif (m := _AMPLITUDE.fullmatch(col)) is not None:
            order = int(m.group(1))
            if order < 1 or order in amps:
                raise InputFileError(file, col, "needs an order >= 1 given once")
            amps[order] = (i, _LENGTH[m.group(2)])
        elif (m := _PHASE.fullmatch(col)) is not None:
            order = int(m.group(1))
            if order < 1 or order in phases:
                raise InputFileError(file, col, "needs an order >= 1 given once")
            phases[order] = (i, _ANGLE[m.group(2)])
        else:
            raise InputFileError(
                file,
                f"line 1, {col or '(empty)'}",
                "not a column of a lot file: expected ball, diameter_error_<m|mm|um|nm>, "
                "waviness_<k>_amplitude_<m|mm|um|nm>, waviness_<k>_phase_<deg|rad>",
            )
    if diameter is None:
        raise InputFileError(
            file, "diameter_error_um", "missing column (the diameter error of every ball)"
        )
    for order in sorted(set(amps) ^ set(phases)):
        missing = (
            f"waviness_{order}_phase_deg" if order in amps else f"waviness_{order}_amplitude_um"
        )
        raise InputFileError(file, missing, f"missing column (order {order} needs both)")
    if len(amps) > MAX_LOT_ORDERS:
        raise InputFileError(
            file,
            "line 1",
            f"{len(amps)} waviness orders; a lot file holds at most {MAX_LOT_ORDERS}",
        )
    orders = {k: (amps[k][0], amps[k][1], phases[k][0], phases[k][1]) for k in sorted(amps)}
    return name_col, diameter[0], diameter[1], orders


def _number(cell: str, file: str, key: str) -> float:
    try:
        value = float(cell)
    except ValueError:
        # the cell itself is not echoed: a lot file named by mistake may be anything
        raise InputFileError(file, key, "not a number") from None
    if not math.isfinite(value):
        raise InputFileError(file, key, "not a finite number")
    return value


def read_lot(path: Path, roots: list[Path] | None = None, name: str | None = None) -> BallLot:
    """Read a lot file (module docstring).

    Parameters
    ----------
    path : Path
        The CSV file.
    roots : list of Path, optional
        Directories it must lie in once its links are followed (the case's directory).
    name : str, optional
        The file as shown in messages (default ``str(path)``).

    Returns
    -------
    BallLot
        The balls, SI.

    Raises
    ------
    InputFileError
        Naming the file and the line and column: not a regular file inside ``roots``, larger
        than :data:`MAX_LOT_BYTES`, no header or no ball, an unknown or missing column, a
        row of another length, a cell that is not a finite number, a negative amplitude, more
        than :data:`MAX_LOT_BALLS` rows.
    """
    shown = str(path) if name is None else name
    text = read_text(path, MAX_LOT_BYTES, roots, shown)
    header: list[str] | None = None
    columns: tuple[int | None, int, float, dict[int, tuple]] | None = None
    names: list[str] = []
    diameters: list[float] = []
    amps: list[list[float]] = []
    phases: list[list[float]] = []
    for lineno, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        cells = [c.strip() for c in line.split(",")]
        if header is None:
            header = cells
            columns = _columns(cells, shown)
            continue
        assert columns is not None
        if len(cells) != len(header):
            raise InputFileError(
                shown, f"line {lineno}", f"{len(cells)} cells, the header names {len(header)}"
            )
        if len(diameters) == MAX_LOT_BALLS:
            raise InputFileError(
                shown, f"line {lineno}", f"more than {MAX_LOT_BALLS} balls, the most a lot holds"
            )
        name_col, d_col, d_scale, orders = columns
        names.append(cells[name_col] if name_col is not None else str(len(diameters) + 1))
        diameters.append(d_scale * _number(cells[d_col], shown, f"line {lineno}, {header[d_col]}"))
        row_a, row_p = [], []
        for a_col, a_scale, p_col, p_scale in orders.values():
            a = a_scale * _number(cells[a_col], shown, f"line {lineno}, {header[a_col]}")
            if a < 0.0:
                raise InputFileError(
                    shown, f"line {lineno}, {header[a_col]}", "an amplitude must be >= 0"
                )
            row_a.append(a)
            row_p.append(p_scale * _number(cells[p_col], shown, f"line {lineno}, {header[p_col]}"))
        amps.append(row_a)
        phases.append(row_p)
    if columns is None:
        raise InputFileError(shown, "", "no header line (e.g. ball,diameter_error_um)")
    if not diameters:
        raise InputFileError(shown, "", "no ball: the header is followed by no row")
    k = len(columns[3])
    return BallLot(
        file=shown,
        names=tuple(names),
        diameter_errors=np.asarray(diameters, dtype=np.float64),
        orders=np.asarray(list(columns[3]), dtype=np.int64),
        amplitudes=np.asarray(amps, dtype=np.float64).reshape(len(diameters), k),
        phases=np.asarray(phases, dtype=np.float64).reshape(len(diameters), k),
    )
