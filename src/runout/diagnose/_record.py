"""Reading a measured runout or vibration record for :func:`runout.diagnose.fit`.

A record is a CSV file with a header row: a time column (``time_s``, or ``t [ms]``), one or both
of ``x_m`` and ``y_m`` (radial displacement of the measured ring along x and y, see the
conventions page; ``x [um]`` gives the unit in brackets), or for the envelope diagnosis one
acceleration column ``a_m_per_s2`` (``a [m/s^2]``, ``a [g]``: g is the standard gravity
9.80665 m/s^2, as accelerometers are calibrated), and optionally a tachometer column
``rev`` (a revolution count, or one pulse per revolution at two levels). Blank lines are
ignored, before the header as between the rows. Every failure is a
:class:`RecordError` naming the file and the row (the file's line number, the header being
line 1) or the column.
"""

from __future__ import annotations

import io
import math
import os
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from runout.base.errors import RunoutError
from runout.base.reading import InputFileError, open_regular
from runout.case.limits import RECORD_BYTES_PER_FILE_BYTE, Budget, format_bytes, max_record_bytes

__all__ = [
    "ARRAYS",
    "MIN_SAMPLES",
    "RECORD_BYTES_PER_FILE_BYTE",
    "Record",
    "RecordError",
    "file_line",
    "read_record",
    "record_from_arrays",
]

FloatArray = NDArray[np.float64]
Quantity = Literal["displacement", "velocity", "acceleration"]

#: Fewest samples a record may have (a line fit needs several per unknown).
MIN_SAMPLES = 64
#: Relative scatter of the time step accepted as uniform sampling (clock jitter).
STEP_RTOL = 1e-3
#: Largest relative variation of the speed a tachometer may show over the record: the fit
#: assumes a constant speed (lines smear by the variation times their order).
TACHO_SPEED_RTOL = 0.01
#: Largest radial displacement [m] and velocity [m/s] a record may hold: anything larger is
#: a column in the wrong unit (micrometres in an ``x_m`` column), not a bearing's runout; an
#: acceleration of 1e6 m/s^2 (100 000 g) is beyond any accelerometer's range.
MAX_VALUE = {"displacement": 1.0, "velocity": 1.0e3, "acceleration": 1.0e6}
#: Standard gravity [m/s^2] (ISO 80000-3), the unit "g" of an acceleration column.
STANDARD_GRAVITY = 9.80665

_HEADER = re.compile(r"^\s*([A-Za-z][A-Za-z0-9_]*?)\s*(?:\[\s*([^\]]*?)\s*\])?\s*$")
_DISPLACEMENT_SUFFIX = {"_m": "m"}
_VELOCITY_SUFFIX = {"_m_per_s": "m/s", "_mps": "m/s"}


class RecordError(RunoutError, ValueError):
    """A record file that cannot be diagnosed; the message names the file and row or column.

    Parameters
    ----------
    file : str
        The record file as given.
    where : str
        ``"row 12, column x_m"``, ``"column time_s"`` or ``""`` for the whole file.
    message : str
        What is wrong and how to fix it.
    """

    def __init__(self, file: str, where: str, message: str) -> None:
        self.file = file
        self.where = where
        self.message = message
        prefix = f"{file}: {where}: " if where else f"{file}: "
        super().__init__(prefix + message)


@dataclass(frozen=True, eq=False)
class Record:
    """A measured record, SI units, uniform time steps.

    Attributes
    ----------
    file : str
        Where it was read from (``"<arrays>"`` for arrays).
    time : ndarray, shape (n,)
        Instants [s].
    channels : dict of str to ndarray
        ``"x"`` and/or ``"y"``: displacement [m] or velocity [m/s] (see ``quantity``); ``"a"``:
        acceleration [m/s^2].
    quantity : {"displacement", "velocity", "acceleration"}
    tachometer_hz : float or None
        Speed of the rotating ring from the tachometer column [Hz], if any: the least-squares
        rate of the instants each revolution starts.
    columns : dict of str to str
        The header's name of the time column and of each channel (``"x"`` -> ``"x [um]"``),
        for messages.
    revolution_starts : ndarray or None
        Instants each whole revolution of the tachometer starts [s] (None without one): an
        acceleration record keeps them for order tracking, its speed may vary.
    """

    file: str
    time: FloatArray
    channels: dict[str, FloatArray]
    quantity: Quantity
    tachometer_hz: float | None = None
    columns: dict[str, str] = field(default_factory=dict)
    revolution_starts: FloatArray | None = None

    def column(self, channel: str) -> str:
        """The header's name of ``channel`` (``"time"``, ``"x"`` or ``"y"``)."""
        return self.columns.get(channel, channel)

    @property
    def samples(self) -> int:
        """Number of instants."""
        return int(self.time.size)

    @property
    def step(self) -> float:
        """Mean time step [s]."""
        return float((self.time[-1] - self.time[0]) / (self.time.size - 1))

    @property
    def duration(self) -> float:
        """n × step: the span the fit resolves lines over [s]."""
        return self.samples * self.step

    def tachometer_speed(self) -> float | None:
        """Mean speed of the rotating ring from the tachometer [Hz] (None without one)."""
        return self.tachometer_hz


def _unit_scale(file: str, column: str, unit: str, kind: str) -> float:
    from runout.base.units import UnitError, to_si

    if kind == "acceleration" and unit.strip() in ("g", "gn", "g0", "g_n"):
        return STANDARD_GRAVITY  # an accelerometer's g, not the gram
    try:
        return to_si(f"1 {unit}", kind)
    except (UnitError, ValueError):
        word = {
            "length": "a length (m, mm, um, nm, in)",
            "time": "a time (s, ms, us)",
            "acceleration": "an acceleration (m/s^2, mm/s^2, g)",
        }.get(kind, "a velocity (m/s, mm/s, um/s)")
        raise RecordError(
            file,
            f"column {_shown_value(column, 40)}",
            f"unknown unit {_shown_value(unit, 40)}: expected {word}",
        ) from None


def _columns(
    file: str, header: list[str], quantity: Quantity
) -> tuple[dict[str, tuple[int, float]], list[str]]:
    """Column roles (time, x, y, rev) -> (index, SI scale) from the header names."""
    kind = {"displacement": "length", "velocity": "velocity"}.get(quantity, "acceleration")
    roles: dict[str, tuple[int, float]] = {}
    ignored: list[str] = []
    for i, raw in enumerate(header):
        name = raw.strip().strip('"').strip()
        m = _HEADER.match(name)
        if m is None:
            ignored.append(name)
            continue
        base, unit = m.group(1).lower(), m.group(2)
        role = None
        scale = 1.0
        if unit is not None:
            role = {"t": "time", "time": "time", "x": "x", "y": "y", "rev": "rev"}.get(base)
            if quantity == "acceleration" and base in ("a", "acc", "acceleration"):
                role = "a"
            elif quantity == "acceleration" and role in ("x", "y"):
                role = None  # a displacement next to the acceleration: not read
            if role == "time":
                scale = _unit_scale(file, name, unit, "time")
            elif role in ("x", "y", "a"):
                scale = _unit_scale(file, name, unit, kind)
            elif role == "rev" and unit not in ("", "rev", "1", "-"):
                raise RecordError(
                    file,
                    f"column {_shown_value(name, 40)}",
                    f"unknown unit {_shown_value(unit, 40)}: rev counts revolutions",
                )
        elif base in ("time_s", "t_s"):
            role = "time"
        elif base in ("a_m_per_s2", "acceleration_m_per_s2"):
            if quantity != "acceleration":
                raise RecordError(
                    file,
                    f"column {_shown_value(name, 40)}",
                    "is an acceleration: the envelope diagnosis reads it (--envelope)",
                )
            role = "a"
        elif base == "rev":
            role = "rev"
        elif base in ("x_m", "y_m"):
            if quantity == "acceleration":
                ignored.append(name)
                continue
            if quantity == "velocity":
                raise RecordError(
                    file,
                    f"column {_shown_value(name, 40)}",
                    "is a displacement but --quantity velocity was given: name the column "
                    "x_m_per_s (or x [mm/s]), or drop --quantity velocity",
                )
            role = base[0]
        elif base in ("x_m_per_s", "y_m_per_s"):
            if quantity == "acceleration":
                ignored.append(name)
                continue
            if quantity == "displacement":
                raise RecordError(
                    file,
                    f"column {_shown_value(name, 40)}",
                    "is a velocity: pass --quantity velocity (Anderon-meter records)",
                )
            role = base[0]
        if role is None:
            ignored.append(name)
            continue
        if role in roles:
            raise RecordError(file, f"column {_shown_value(name, 40)}", f"a second {role} column")
        roles[role] = (i, scale)
    if "time" not in roles:
        only = header[0] if len(header) == 1 else ""
        for sep, word in ((";", "semicolons"), ("\t", "tabs")):
            if sep in only:
                raise RecordError(
                    file,
                    "header",
                    f"the fields are separated by {word}: a record is comma-separated (save "
                    "it as CSV with commas, and decimal points)",
                )
        raise RecordError(
            file,
            "header",
            "no time column: name one time_s (or t [ms], time [s]); " + _found(header),
        )
    if quantity == "acceleration":
        if "a" not in roles:
            raise RecordError(
                file,
                "header",
                "no acceleration column: name one a_m_per_s2 (or a [m/s^2], a [g]); "
                + _found(header),
            )
        return roles, ignored
    if "x" not in roles and "y" not in roles:
        unit = "x_m, y_m (or x [um])" if quantity == "displacement" else "x_m_per_s (or x [mm/s])"
        raise RecordError(
            file,
            "header",
            f"no displacement column: expected one or both of {unit}; " + _found(header),
        )
    return roles, ignored


#: Most header fields an error message lists, and the longest one it shows [characters].
_SHOWN_FIELDS = 8
_SHOWN_NAME = 32


def _found(header: list[str]) -> str:
    """The header's column names as an error shows them: only fields that read as column
    names (a letter, then letters, digits, ``_``, a unit in brackets), each short, so that a
    file that is no record (a link to any text file) is not echoed into the message."""
    names = [h.strip().strip('"').strip() for h in header]
    shown = [n for n in names if _HEADER.match(n) and len(n) <= _SHOWN_NAME]
    if not shown:
        return "its first line holds no column names"
    more = len(names) - len(shown[:_SHOWN_FIELDS])
    return (
        "found "
        + ", ".join(repr(n) for n in shown[:_SHOWN_FIELDS])
        + (f" and {more} other field(s)" if more else "")
    )


def _shown_value(text: str, limit: int = 24) -> str:
    """Text of the file as an error shows it: escaped (repr), at most ``limit`` characters."""
    return repr(text if len(text) <= limit else text[: limit - 3] + "...")


#: The file name of a record built from arrays (:func:`record_from_arrays`).
ARRAYS = "<arrays>"


def file_line(file: str, index: int) -> int:
    """The line number in ``file`` (the header is line 1) of data row ``index`` (0-based).

    The reader skips blank lines, so a blank line inside the data moves every later row; the
    file is read again to count them (only to name the row of an error). A record built from
    arrays counts its rows from 2, as a file without blank lines would.
    """
    if file == ARRAYS:
        return index + 2
    try:
        with (
            open_regular(Path(file)) as raw,
            io.TextIOWrapper(raw, encoding="utf-8-sig", newline="") as fh,
        ):
            seen = -2  # the first line that is not blank is the header
            for number, line in enumerate(fh, start=1):
                if line.strip():
                    seen += 1
                    if seen == index:
                        return number
    except (OSError, UnicodeDecodeError, RunoutError):
        pass
    return index + 2


def _parse_error(file: str, exc: ValueError, header: list[str]) -> RecordError:
    """numpy's loadtxt message turned into the file's line and the column's name."""
    text = str(exc)
    # numpy cuts a long value at 100 characters, without its closing quote
    m = re.search(r"could not convert string '(.*?)'? to \w+ at row (\d+), column (\d+)", text)
    if m:
        value, row, col = m.group(1), int(m.group(2)), int(m.group(3))
        name = header[col - 1].strip() if 0 < col <= len(header) else str(col)
        return RecordError(
            file,
            f"row {file_line(file, row)}, column {_shown_value(name, 40)}",
            f"{_shown_value(value)} is not a number",
        )
    m = re.search(r"number of columns changed from (\d+) to (\d+) at row (\d+)", text)
    if m:
        return RecordError(
            file,
            f"row {file_line(file, int(m.group(3)) - 1)}",  # loadtxt counts these from 1
            f"has {m.group(2)} fields where the header has {m.group(1)}",
        )
    return RecordError(file, "", f"cannot be read as CSV ({_shown_value(text, 160)[1:-1]})")


def read_record(
    path: str | Path,
    quantity: Quantity = "displacement",
    *,
    limits: Budget | None = None,
) -> Record:
    """Read and check a record CSV file.

    Parameters
    ----------
    path : str or Path
        The CSV file (comma-separated, one header row).
    quantity : {"displacement", "velocity"}
        What the x/y columns hold; bare names are ``x_m`` [m] or ``x_m_per_s`` [m/s].
    limits : Budget, optional
        Memory budget; the file's size is checked against it before anything is read.

    Returns
    -------
    Record

    Raises
    ------
    RecordError
        Missing file or columns, unknown unit, a value that is not a number or not finite,
        time not increasing, not uniform or with a gap, too few samples, a bad tachometer.
    """
    file = str(path)
    p = Path(path)
    if quantity not in ("displacement", "velocity", "acceleration"):
        raise RecordError(
            file,
            "",
            f'quantity must be "displacement", "velocity" or "acceleration", got {quantity!r}',
        )
    try:
        # only a regular file (a FIFO would block, /dev/zero never end), a loop of links named
        raw = open_regular(p, None, file)
    except InputFileError as exc:
        raise RecordError(file, "", exc.message) from None
    import warnings

    header: list[str] = []
    try:
        size = os.fstat(raw.fileno()).st_size
        budget = limits if limits is not None else Budget()
        if size > max_record_bytes(budget):
            need = size * RECORD_BYTES_PER_FILE_BYTE
            raise RecordError(
                file,
                "",
                f"a record of {format_bytes(size)} would need about {format_bytes(need)} of "
                f"memory; shorten or decimate it {budget.raise_hint('memory')}",
            )
        # utf-8-sig: a spreadsheet's "CSV UTF-8" starts with a byte-order mark
        with raw, io.TextIOWrapper(raw, encoding="utf-8-sig", newline="") as fh:
            # blank lines are ignored, before the header as between the rows
            first = fh.readline()
            while first and not first.strip():
                first = fh.readline()
            if not first:
                raise RecordError(
                    file, "", "is empty: no header row (expected e.g. time_s,x_m,y_m)"
                )
            header = first.rstrip("\r\n").split(",")
            roles, _ = _columns(file, header, quantity)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # an empty body: our own error below
                # the open file is parsed from its second line, without a copy of the text
                # quotechar: exports that quote every field ("0.5") are read as numbers
                data = np.loadtxt(
                    fh, delimiter=",", dtype=np.float64, ndmin=2, comments=None, quotechar='"'
                )
    except RecordError:
        raise
    except UnicodeDecodeError as exc:
        raise RecordError(file, "", f"is not UTF-8 text ({exc.reason})") from None
    except ValueError as exc:
        raise _parse_error(file, exc, header) from None
    except OSError as exc:
        raise RecordError(file, "", f"cannot be read as text ({exc})") from None
    finally:
        raw.close()
    if data.size == 0:
        raise RecordError(file, "", "has a header but no data rows")
    if data.shape[1] != len(header):
        raise RecordError(
            file,
            f"row {file_line(file, 0)}",
            f"has {data.shape[1]} fields where the header has {len(header)}",
        )
    cols = {role: np.ascontiguousarray(data[:, i]) * scale for role, (i, scale) in roles.items()}
    del data
    return _checked(file, cols, header, roles, quantity)


def record_from_arrays(
    time: FloatArray,
    x: FloatArray | None = None,
    y: FloatArray | None = None,
    *,
    quantity: Quantity = "displacement",
    rev: FloatArray | None = None,
    a: FloatArray | None = None,
) -> Record:
    """A :class:`Record` from arrays (SI units), checked like a file (rows count from 2).

    ``x`` and ``y`` are displacements [m] or velocities [m/s]; ``a`` an acceleration [m/s^2]
    (``quantity="acceleration"``, read by the envelope diagnosis).
    """
    cols: dict[str, FloatArray] = {"time": np.asarray(time, dtype=np.float64).ravel()}
    names = ["time_s"]
    suffix = {"displacement": "_m", "velocity": "_m_per_s"}.get(quantity, "_m_per_s2")
    for role, arr in (("x", x), ("y", y), ("a", a), ("rev", rev)):
        if arr is not None:
            cols[role] = np.asarray(arr, dtype=np.float64).ravel()
            names.append(role + suffix if role != "rev" else "rev")
    roles = {role: (i, 1.0) for i, role in enumerate(cols)}
    if quantity == "acceleration":
        if "a" not in cols or "x" in cols or "y" in cols:
            raise RecordError(ARRAYS, "", "an acceleration record holds a (and no x or y)")
    elif "a" in cols:
        raise RecordError(ARRAYS, "", 'give a with quantity="acceleration"')
    elif "x" not in cols and "y" not in cols:
        raise RecordError(ARRAYS, "", "give x or y (or both)")
    sizes = {a.size for a in cols.values()}
    if len(sizes) != 1:
        raise RecordError(ARRAYS, "", "time, x, y and rev must have the same length")
    return _checked(ARRAYS, cols, names, roles, quantity)


def _checked(
    file: str,
    cols: dict[str, FloatArray],
    header: list[str],
    roles: dict[str, tuple[int, float]],
    quantity: Quantity,
) -> Record:
    def name(role: str) -> str:
        return header[roles[role][0]].strip()

    for role, values in cols.items():
        bad = np.flatnonzero(~np.isfinite(values))
        if bad.size:
            raise RecordError(
                file,
                f"row {file_line(file, int(bad[0]))}, column {name(role)!r}",
                f"{float(values[bad[0]])!r} is not a finite number ({bad.size} such value(s); fill "
                "or cut the gaps, the fit needs every instant)",
            )
    limit = MAX_VALUE[quantity]
    unit = {"displacement": "m", "velocity": "m/s"}.get(quantity, "m/s^2")
    for role in ("x", "y", "a"):
        column = cols.get(role)
        if column is None or column.size == 0:
            continue
        worst = int(np.argmax(np.abs(column)))
        if abs(column[worst]) > limit and role == "a":
            raise RecordError(
                file,
                f"row {file_line(file, worst)}, column {name(role)!r}",
                f"{float(column[worst]):.6g} m/s^2 is beyond any accelerometer's range: check "
                "the column's unit (a bare a_m_per_s2 is in m/s^2; give it in brackets, e.g. "
                "'a [g]')",
            )
        if abs(column[worst]) > limit:
            raise RecordError(
                file,
                f"row {file_line(file, worst)}, column {name(role)!r}",
                f"{float(column[worst]):.6g} {unit} is no bearing's radial motion: check the "
                f"column's unit (a bare {role}_{'m' if unit == 'm' else 'm_per_s'} is in {unit}; "
                f"give it in brackets, e.g. '{role} [um]')",
            )
    t = cols["time"]
    n = t.size
    if n < MIN_SAMPLES:
        raise RecordError(file, "", f"too short: {n} samples, at least {MIN_SAMPLES} needed")
    dt = np.diff(t)
    back = np.flatnonzero(dt <= 0.0)
    if back.size:
        i = int(back[0])
        raise RecordError(
            file,
            f"row {file_line(file, i + 1)}, column {name('time')!r}",
            f"time does not increase ({float(t[i])!r} then {float(t[i + 1])!r} s)",
        )
    step = float(np.median(dt))  # a gap must not move the reference step
    dev = np.abs(dt - step)
    worst = int(np.argmax(dev))
    if dev[worst] > STEP_RTOL * step:
        ratio = dt[worst] / step
        what = (
            f"a gap of {ratio:.3g} time steps"
            if ratio > 1.5
            else f"a step of {dt[worst]:.6g} s where the mean step is {step:.6g} s"
        )
        last = float(np.max(np.abs(t)))
        if float(np.spacing(last)) > 0.25 * STEP_RTOL * step:
            # a double holds 16 digits: time stamps from an epoch lose the step's precision
            fix = (
                f"time stamps near {last:.4g} s are stored to {float(np.spacing(last)):.2g} s "
                "only: give the time from the start of the record"
            )
        else:
            fix = "resample the record on a uniform grid"
        raise RecordError(
            file,
            f"row {file_line(file, worst + 1)}, column {name('time')!r}",
            f"time is not uniformly sampled: {what}; {fix}",
        )
    rev = cols.get("rev")
    # the envelope diagnosis resamples an acceleration record to the shaft angle: its speed
    # may vary; a line fit assumes it constant
    steady = quantity != "acceleration"
    tacho, starts = (None, None) if rev is None else _tachometer(file, name("rev"), t, rev, steady)
    channels: dict[str, FloatArray] = {role: cols[role] for role in ("x", "y", "a") if role in cols}
    for role, values in channels.items():
        if float(np.ptp(values)) == 0.0:
            raise RecordError(
                file,
                f"column {name(role)!r}",
                f"is constant ({float(values[0])!r} {unit} throughout): a dead channel would be "
                "read as a motion of zero"
                + ("" if role == "a" else "; drop the column to diagnose the other alone"),
            )
    names = {role: name(role) for role in ("time", *channels)}
    return Record(file, t, channels, quantity, tacho, names, None if steady else starts)


def _tachometer(
    file: str, column: str, t: FloatArray, rev: FloatArray, steady: bool = True
) -> tuple[float, FloatArray]:
    """Speed [Hz] and revolution starts [s] from a revolution count or a pulse train.

    A column of two levels (0/1, or a TTL 0/5 V) is a pulse train: a revolution starts at each
    rising edge. Otherwise it is a cumulative count (with or without its fraction, as an
    encoder gives it): revolution L starts where the count reaches L, interpolated between
    the samples. The speed is the least-squares slope of those instants over every revolution,
    not the first and last alone (each instant is only known to a time step). With ``steady``
    a speed varying by more than :data:`TACHO_SPEED_RTOL` is refused.
    """
    values = np.unique(rev)
    if values.size == 2 or (values.size == 1 and values[0] in (0.0, 1.0)):
        high = rev > 0.5 * (values[0] + values[-1])
        rising = np.flatnonzero(high[1:] & ~high[:-1]) + 1
        if rising.size < 3:
            raise RecordError(
                file,
                f"column {_shown_value(column, 40)}",
                f"a pulse tachometer needs at least 3 pulses (2 revolutions), found {rising.size}",
            )
        starts = t[rising]
        if steady:
            _steady(file, column, np.diff(starts), "pulse periods")
        return _rate(starts), starts
    drop = np.flatnonzero(np.diff(rev) < 0.0)
    if drop.size:
        i = int(drop[0])
        raise RecordError(
            file,
            f"row {file_line(file, i + 1)}, column {_shown_value(column, 40)}",
            f"the revolution count decreases ({float(rev[i])!r} then {float(rev[i + 1])!r}); "
            "give a cumulative count or a pulse per revolution",
        )
    # a count sampled less than twice a revolution cannot be interpolated (and would ask
    # for one array entry per revolution: 1e11 rev/s ran out of memory): refuse it before
    turns = float(rev[-1]) - float(rev[0])
    if turns > 0.5 * rev.size:
        raise RecordError(
            file,
            f"column {_shown_value(column, 40)}",
            f"the revolution count advances {turns:.6g} revolutions over {rev.size} samples "
            f"({turns / max(float(t[-1] - t[0]), 1e-300):.6g} rev/s): a tachometer must be "
            "sampled at least twice a revolution; check the column (a count of revolutions, "
            "or one pulse per revolution)",
        )
    # the instants the count reaches each whole revolution after its first value
    levels = math.floor(rev[0]) + 1.0 + np.arange(max(0, math.floor(rev[-1]) - math.floor(rev[0])))
    if levels.size < 3:
        raise RecordError(
            file,
            f"column {_shown_value(column, 40)}",
            f"the revolution count completes {max(levels.size - 1, 0)} revolution(s); at least "
            "2 are needed",
        )
    after = np.searchsorted(rev, levels)  # first sample at or past the level (never 0)
    before = after - 1
    frac = (levels - rev[before]) / (rev[after] - rev[before])
    starts = t[before] + frac * (t[after] - t[before])
    if steady:
        _steady(file, column, np.diff(starts), "revolution times")
    return _rate(starts), starts


def _rate(starts: FloatArray) -> float:
    """Revolutions per second from the instants successive revolutions start [Hz]."""
    k = np.arange(starts.size, dtype=np.float64)
    k -= k.mean()
    period = float(np.dot(k, starts - starts.mean()) / np.dot(k, k))
    return 1.0 / period


def _steady(file: str, column: str, periods: FloatArray, what: str) -> None:
    mean = float(periods.mean())
    spread = float(np.max(np.abs(periods - mean))) / mean
    if spread > TACHO_SPEED_RTOL:
        raise RecordError(
            file,
            f"column {_shown_value(column, 40)}",
            f"the speed varies by {100 * spread:.3g} % over the record ({what}); the diagnosis "
            f"assumes a constant speed (within {100 * TACHO_SPEED_RTOL:g} %): resample the "
            "record to the shaft angle or cut a steady part",
        )
