"""Compare a fresh numeric output with one stored in the repository (a "golden" file).

The stored outputs (``tests/data/examples_json``) were written on one machine. Numba compiles
the kernels for the host CPU (FMA contraction, vector width), and NumPy, SciPy and the BLAS move
from version to version, so the last digits of a float differ between machines; a refactor must
still not move a result unnoticed. :func:`differences` compares two documents by this policy:

Exact
    Keys and their order, strings, booleans, integers, ``None``, list lengths, JSON types.
    Strings are inputs or words: a title that quotes "0.1 um" quotes the case file.
Floats
    ``|new − old| ≤ max(RTOL · max(|new|, |old|), RTOL · scale)`` with :data:`RTOL` = 1e-9.
    Round-off is ~1e-16 relative; the solvers stop at 1e-11 to 1e-13 of their own scale, so a
    result that moves by 1e-9 of itself has really moved. The absolute floor is RTOL times the
    document's *scale* of the quantity's family (its largest stored magnitude): round-off in a
    computed quantity is relative to the problem, not to the quantity (a 1e-20 m axial p-p in a
    record of 10 nm is noise, and a 0.0 may come out as 1e-21). Families:

    * displacements (every ``*_m`` motion, position and contact approach): the floor is
      RTOL times the largest p-p or contact approach, and at least the solver's resolution
      where the document states one (``solver_resolution_m``: smaller figures are noise).
      The solvers stop at 1e-11 (quasi-static, spindle) or 1e-12 (dynamic) of the approach
      and the models drop lines below 1e-9 of it as noise (``floor`` of
      :func:`runout.analysis.decompose.fit_lines`); positions (a mean axial offset under preload) do
      not set the floor: it would hide a 1e-6 change of a runout 1000 times smaller;
    * tilts (``*_rad`` other than phases): the largest tilt;
    * kinematic frequencies (``frequencies_hz``, the lines', the attribution table's): the
      largest characteristic frequency. A line is a combination ``|a f_r + b f_c + c f_b|``
      with integer a, b, c, so its round-off is ~``(|a| + |b| + |c|)`` ulp of that scale: a
      line near 0 Hz from large multiples carries it, and 1e-9 covers multiples up to 1e6;
      orders: that floor divided by the rotation frequency;
    * the stiffness matrix: entry (i, j) by ``sqrt(|K_ii K_jj|)``, the bound of an entry of a
      positive matrix (its rows and columns mix N/m, N/rad and N m/rad: the largest entry
      would hide a moment stiffness under the round-off of a force stiffness);
    * ``*_n_per_m`` stiffnesses, Anderon bands: the largest of their group;
    * any other key: the largest magnitude stored under that key (e.g. every ball's load).
Phases and shares of a line
    A line's complex amplitude carries the displacement floor δ, so its phase moves by up to
    ``2δ / pp`` and its sources' shares by that fraction of themselves: the tolerance is
    ``RTOL·π + 2δ/pp`` (phases compared modulo 2π) and ``(RTOL + 2δ/pp) · max(1, |share|)``.
    Near the floor a line's phase is anything, and the tolerance says so.
Explained fraction
    ``1 − Σres²/Σsig²`` of a record moves by about ``δ/rms``; rms ≥ pp/8 is taken, so the
    tolerance is ``RTOL + 8δ/pp`` with pp the largest p-p of the record: the fraction of a
    motion at the floor (a steady response) is round-off divided by round-off.
Order of lines and sources
    Lines are listed largest first and a line's sources by share; two lines of (nearly) equal
    p-p (the x and y lines of one source, every order of a symmetric spectrum) or two sources of
    equal share may swap between machines. So lines are matched by direction and frequency,
    sources by part, element, lobes and term, and the order must only agree where the values
    differ beyond their tolerance. A line's label is its top source's: where two sources tie,
    the label may name either, and it must be the one its own first source gives.
Numbers printed in text
    Notes, labels and formulas quote computed values with a few digits (``"1.28262 Hz"``,
    ``"1/T = 0.01111 Hz"``): the text around them is exact, a decimal number may move by one
    unit of its last printed digit (a value at a rounding boundary), integers are exact (counts,
    lobes, multiples; or floats printed far from a rounding boundary, e.g. "72 revolutions" of
    exactly 72: should one move, the failure names it).

What is not absorbed: a line within round-off of a model's cut-off (the solvers' floor, 1e-7
of the largest line, the residual search's 1e-3) could appear or vanish; ``test_golden.py``
checks that no stored line sits within 1e-6 of one.
"""

from __future__ import annotations

import bisect
import itertools
import math
import re
from collections.abc import Sequence
from typing import Any

__all__ = ["RTOL", "Scales", "assert_same", "differences", "family", "same_quoted", "scales"]

#: Relative tolerance of a float, and of the absolute floor to its family's scale.
RTOL = 1e-9

DISPLACEMENT = "displacement [m]"
TILT = "tilt [rad]"
FREQUENCIES = "kinematic frequencies [Hz]"
ORDERS = "orders [-]"
#: Frequencies that are kinematic combinations (besides ``frequencies_hz``).
KINEMATIC = [["components", "frequency_hz"], ["attribution", "frequency_hz"], ["ball_passage_hz"]]
STIFFNESS = "stiffness [N/m]"
ANDERON = "Anderon bands"
#: ``*_m`` keys that are geometry (inputs and positions along a shaft), not motions.
GEOMETRY = {
    "radial_clearance_m",
    "position_m",
    "pressure_centre_m",
    "nose_position_m",
    # a catalogue bearing's boundary dimensions and a tolerance class's bore: inputs, not motion
    "bore_diameter_m",
    "outside_diameter_m",
    "width_m",
    "bore_m",
}
#: Strings that quote computed values (compared number by number).
QUOTING = {"notes", "label", "formula"}

Path = tuple[str | int, ...]
Scales = dict[str, float]

_NUMBER = re.compile(r"\d+(?:\.\d+)?(?:[eE][-+]?\d+)?")


def _text(path: Path) -> str:
    """``$.a.b[0]``; a line's name (``"3: x 405.016 Hz"``) in brackets like an index."""
    return "$" + "".join(f".{k}" if _is_key(k) else f"[{k}]" for k in path)


def _is_key(k: str | int) -> bool:
    return isinstance(k, str) and not k[:1].isdigit() and not k.startswith("new ")


def _keys(path: Path) -> list[str]:
    """The keys of ``path`` (list positions dropped)."""
    return [k for k in path if isinstance(k, str) and _is_key(k)]


def family(path: Path) -> str:
    """The family of the float at ``path`` (keys and list positions): its scale's name.

    Parameters
    ----------
    path : tuple of str or int
        Keys and list indices from the document's root.

    Returns
    -------
    str
        One of the named families, or the path's keys joined (a family of its own).
    """
    keys = _keys(path)
    leaf = keys[-1] if keys else ""
    if leaf == "static_position":  # x, y, z [m], then tilt x, y [rad]
        index = path[-1]
        return DISPLACEMENT if isinstance(index, int) and index < 3 else TILT
    if keys[:1] == ["tilt_pp_rad"] or (leaf.endswith("_rad") and leaf != "phase_rad"):
        return TILT
    if leaf.endswith("_n_per_m"):
        return STIFFNESS
    if leaf.endswith("_m") and not leaf.endswith("_n_m") and leaf not in GEOMETRY:
        return DISPLACEMENT
    if keys[:1] == ["frequencies_hz"] or keys in KINEMATIC:
        return FREQUENCIES
    if keys in (["components", "order"], ["attribution", "order"]):
        return ORDERS
    if keys[:1] == ["anderon"]:
        return ANDERON
    return ".".join(keys)


def _sets_displacement_scale(path: Path) -> bool:
    """Whether the displacement at ``path`` is a motion (p-p) or a contact approach."""
    leaf = (_keys(path) or [""])[-1]
    return leaf == "pp_m" or leaf.endswith(("_pp_m", "approach_m")) or leaf == "radial_runout_m"


def scales(doc: Any) -> Scales:
    """The largest magnitude of each family of floats in ``doc``.

    Parameters
    ----------
    doc : object
        A JSON document (dicts, lists, scalars).

    Returns
    -------
    dict
        Family name → largest ``|value|`` (0.0 where every value is zero); displacements:
        the largest p-p or contact approach.
    """
    out: Scales = {}

    def walk(x: Any, path: Path) -> None:
        if isinstance(x, dict):
            for k, v in x.items():
                walk(v, (*path, k))
        elif isinstance(x, list):
            for i, v in enumerate(x):
                walk(v, (*path, i))
        elif isinstance(x, float):
            name = family(path)
            if name == DISPLACEMENT and not _sets_displacement_scale(path):
                return
            if name == FREQUENCIES and _keys(path)[:1] != ["frequencies_hz"]:
                return
            out[name] = max(out.get(name, 0.0), abs(x))

    walk(doc, ())
    return out


def _wrap(angle: float) -> float:
    """``angle`` in [-π, π)."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def _digit_unit(token: str) -> float:
    """One unit of the last digit a number was printed with (``"1.25e-3"`` → 1e-5)."""
    mantissa, _, exponent = token.lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 10.0 ** ((int(exponent) if exponent else 0) - decimals)


def same_quoted(new: str, old: str) -> bool:
    """Whether two texts differ only in decimal numbers that moved by a last printed digit.

    Two printings, in one format, of values within RTOL of each other differ by at most one
    unit of the last digit of that format, plus RTOL; the shown last digit of either is no
    finer than the format's (``%g`` drops trailing zeros), so one unit of the finer shown digit
    bounds it. The text around the numbers, and every integer, is exact.

    Parameters
    ----------
    new, old : str
        The two texts.

    Returns
    -------
    bool
    """
    if new == old:
        return True
    if _NUMBER.split(new) != _NUMBER.split(old):
        return False
    for a, b in zip(_NUMBER.findall(new), _NUMBER.findall(old), strict=True):
        if a == b:
            continue
        decimal = ("." in a or "e" in a.lower()) and ("." in b or "e" in b.lower())
        if not decimal:
            return False
        x, y = float(a), float(b)
        allowed = min(_digit_unit(a), _digit_unit(b)) + RTOL * max(abs(x), abs(y))
        if abs(x - y) > allowed * (1.0 + 1e-12):
            return False
    return True


class _Comparison:
    """One comparison: the stored document's scales and the problems found."""

    def __init__(self, old: Any) -> None:
        self.scale = scales(old)
        resolution = old.get("solver_resolution_m") if isinstance(old, dict) else None
        self.floor_m = max(
            RTOL * self.scale.get(DISPLACEMENT, 0.0),
            resolution if isinstance(resolution, float) else 0.0,
        )
        self.problems: list[str] = []
        self.record_pp = 0.0
        self.rotation = 0.0
        if isinstance(old, dict):
            runout = old.get("runout", {})
            lines = [c.get("pp_m", 0.0) for c in old.get("components", [])]
            values = [runout.get("radial_pp_m", 0.0), runout.get("axial_pp_m", 0.0), *lines]
            self.record_pp = max((abs(v) for v in values if isinstance(v, float)), default=0.0)
            rotation = old.get("frequencies_hz", {}).get("rotation")
            self.rotation = abs(rotation) if isinstance(rotation, float) else 0.0

    def fail(self, path: Path, old: Any, new: Any, tol: float | None = None) -> None:
        extra = "" if tol is None else f" (tolerance {tol:.3g})"
        self.problems.append(f"{_text(path)}: {old!r} became {new!r}{extra}")

    def floor_of(self, path: Path) -> float:
        name = family(path)
        if name == DISPLACEMENT:
            return self.floor_m
        if name == ORDERS:  # the kinematic frequencies' floor, in orders of the rotation
            return RTOL * self.scale.get(FREQUENCIES, 0.0) / self.rotation if self.rotation else 0.0
        return RTOL * self.scale.get(name, 0.0)

    # -- values -----------------------------------------------------------------------------
    def value(self, new: Any, old: Any, path: Path) -> None:
        if type(new) is not type(old):
            self.fail(path, old, new)
            self.problems[-1] += f" ({type(old).__name__} became {type(new).__name__})"
        elif isinstance(old, dict):
            self.mapping(new, old, path)
        elif isinstance(old, list):
            keys = _keys(path)
            if keys == ["components"]:
                self.components(new, old, path)
            elif keys == ["stiffness_matrix", "matrix"]:
                self.matrix(new, old, path)
            else:
                self.sequence(new, old, path)
        elif isinstance(old, float):
            self.number(new, old, path)
        elif isinstance(old, str) and set(_keys(path)[-1:]) & QUOTING:
            if not same_quoted(new, old):
                self.fail(path, old, new)
        elif new != old:
            self.fail(path, old, new)

    def mapping(self, new: dict[str, Any], old: dict[str, Any], path: Path) -> None:
        if list(new) != list(old):
            self.fail(path, f"keys {list(old)}", f"keys {list(new)}")
            return
        for key in old:
            self.value(new[key], old[key], (*path, key))

    def sequence(self, new: list[Any], old: list[Any], path: Path) -> None:
        if len(new) != len(old):
            self.fail(path, f"length {len(old)}", f"length {len(new)}")
            return
        for i, (a, b) in enumerate(zip(new, old, strict=True)):
            self.value(a, b, (*path, i))

    def close(self, new: float, old: float, floor: float) -> tuple[bool, float]:
        tol = max(RTOL * max(abs(new), abs(old)), floor)
        return abs(new - old) <= tol, tol

    def number(self, new: float, old: float, path: Path) -> None:
        if _keys(path) == ["explained_fraction"]:
            spread = 8.0 * self.floor_m / self.record_pp if self.record_pp > 0 else math.inf
            tol = RTOL + spread
            ok = abs(new - old) <= tol
        else:
            ok, tol = self.close(new, old, self.floor_of(path))
        if not ok:
            self.fail(path, old, new, tol)

    def matrix(self, new: list[Any], old: list[Any], path: Path) -> None:
        if len(new) != len(old) or any(len(a) != len(b) for a, b in zip(new, old, strict=False)):
            self.fail(path, f"shape of {old!r}", f"shape of {new!r}")
            return
        diagonal = [abs(row[i]) if i < len(row) else 0.0 for i, row in enumerate(old)]
        largest = max((abs(v) for row in old for v in row), default=0.0)
        for i, (a_row, b_row) in enumerate(zip(new, old, strict=True)):
            for j, (a, b) in enumerate(zip(a_row, b_row, strict=True)):
                if type(a) is not float or type(b) is not float:
                    self.value(a, b, (*path, i, j))
                    continue
                bound = math.sqrt(diagonal[i] * diagonal[j]) if j < len(diagonal) else largest
                ok, tol = self.close(a, b, RTOL * (bound or largest))
                if not ok:
                    self.fail((*path, i, j), b, a, tol)

    # -- lines ------------------------------------------------------------------------------
    def line_spread(self, pp: float) -> float:
        """Relative uncertainty of a line's complex amplitude: 2δ / pp."""
        return 2.0 * self.floor_m / pp if pp > 0 else math.inf

    def components(self, new: list[Any], old: list[Any], path: Path) -> None:
        if not all(isinstance(c, dict) for c in (*new, *old)):
            self.sequence(new, old, path)
            return
        pairs = _match_lines(new, old, self.floor_of((*path, 0, "frequency_hz")))
        matched_new = {j for _, j in pairs}
        for i in sorted(set(range(len(old))) - {i for i, _ in pairs}):
            self.fail((*path, _line_name(i, old[i])), "a line", "no line")
        for j in sorted(set(range(len(new))) - matched_new):
            self.fail((*path, f"new {_line_name(j, new[j])}"), "no line", "a line")
        for i, j in pairs:
            self.line(new[j], old[i], (*path, _line_name(i, old[i])))
        self.ranked(new, old, pairs, path, "pp_m", self.pp_tol)

    def pp_tol(self, old_item: dict[str, Any]) -> float:
        pp = old_item.get("pp_m")
        return max(RTOL * abs(pp), self.floor_m) if isinstance(pp, float) else 0.0

    def ranked(
        self,
        new: Sequence[dict[str, Any]],
        old: Sequence[dict[str, Any]],
        pairs: list[tuple[int, int]],
        path: Path,
        key: str,
        tol_of: Any,
    ) -> None:
        """The new order (largest ``|key|`` first) agrees with the stored one wherever the
        stored values differ beyond their tolerances (ties may swap)."""
        old_of = {j: i for i, j in pairs}
        order = [old_of[j] for j in range(len(new)) if j in old_of]
        for a, b in itertools.pairwise(order):
            va, vb = old[a].get(key), old[b].get(key)
            if not (isinstance(va, float) and isinstance(vb, float)):
                continue
            if abs(va) < abs(vb) - tol_of(old[a]) - tol_of(old[b]):
                self.fail(path, f"item {a} before item {b}", f"item {b} before item {a}")
                self.problems[-1] += f" (order by {key}: {va!r} < {vb!r})"

    def line(self, new: dict[str, Any], old: dict[str, Any], path: Path) -> None:
        if list(new) != list(old):
            self.fail(path, f"keys {list(old)}", f"keys {list(new)}")
            return
        pp = old.get("pp_m")
        spread = self.line_spread(abs(pp)) if isinstance(pp, float) else math.inf
        for key in old:
            a, b, where = new[key], old[key], (*path, key)
            if key == "phase_rad" and isinstance(a, float) and isinstance(b, float):
                tol = RTOL * math.pi + spread
                if abs(_wrap(a - b)) > tol:
                    self.fail(where, b, a, tol)
            elif key == "sources" and isinstance(a, list) and isinstance(b, list):
                self.sources(a, b, where, spread)
            elif key == "label" and isinstance(a, str) and isinstance(b, str):
                if not same_quoted(a, b) and not _label_from_tied_sources(new, old):
                    self.fail(where, b, a)
            else:
                self.value(a, b, where)

    def sources(self, new: list[Any], old: list[Any], path: Path, spread: float) -> None:
        if not all(isinstance(s, dict) for s in (*new, *old)):
            self.sequence(new, old, path)
            return
        pairs = _match_by(new, old, _source_key)
        for i in sorted(set(range(len(old))) - {i for i, _ in pairs}):
            self.fail((*path, i), _source_key(old[i]), "no source")
        for j in sorted(set(range(len(new))) - {j for _, j in pairs}):
            self.fail((*path, f"new {j}"), "no source", _source_key(new[j]))

        def share_tol(item: dict[str, Any]) -> float:
            share = item.get("share")
            size = abs(share) if isinstance(share, float) else 0.0
            return (RTOL + spread) * max(1.0, size)

        for i, j in pairs:
            a, b, where = new[j], old[i], (*path, i)
            if list(a) != list(b):
                self.fail(where, f"keys {list(b)}", f"keys {list(a)}")
                continue
            for key in b:
                if key == "share" and isinstance(a[key], float) and isinstance(b[key], float):
                    tol = share_tol(b)
                    if abs(a[key] - b[key]) > tol:
                        self.fail((*where, key), b[key], a[key], tol)
                else:
                    self.value(a[key], b[key], (*where, key))
        self.ranked(new, old, pairs, path, "share", share_tol)


def _line_name(index: int, line: dict[str, Any]) -> str:
    f = line.get("frequency_hz")
    at = f"{f:.6g} Hz" if isinstance(f, float) else "?"
    return f"{index}: {line.get('direction')} {at}"


def _match_lines(
    new: list[dict[str, Any]], old: list[dict[str, Any]], floor_hz: float
) -> list[tuple[int, int]]:
    """(old index, new index) of the same line: same direction, frequency within tolerance
    (the same label first where several are; fitted lines are at least 0.3/T apart), then
    the remaining lines by direction and label."""
    pairs: list[tuple[int, int]] = []
    free = set(range(len(new)))
    by_direction: dict[Any, tuple[list[float], list[int]]] = {}
    ranked = sorted(
        (c.get("direction"), c["frequency_hz"], j)
        for j, c in enumerate(new)
        if isinstance(c.get("frequency_hz"), float)
    )
    for direction, f, j in ranked:
        freqs, index = by_direction.setdefault(direction, ([], []))
        freqs.append(f)
        index.append(j)
    for i, c in enumerate(old):
        f = c.get("frequency_hz")
        if not isinstance(f, float) or c.get("direction") not in by_direction:
            continue
        tol = max(RTOL * abs(f), floor_hz)
        freqs, index = by_direction[c.get("direction")]
        lo, hi = bisect.bisect_left(freqs, f - tol), bisect.bisect_right(freqs, f + tol)
        near = [index[k] for k in range(lo, hi) if index[k] in free]
        if not near:
            continue
        best = min(near, key=lambda j: (new[j].get("label") != c.get("label"), j))
        free.discard(best)
        pairs.append((i, best))
    # a line whose frequency moved is still the line of its label: compared field by field,
    # the message names the frequency
    for i in sorted(set(range(len(old))) - {i for i, _ in pairs}):
        c = old[i]
        same = [
            j
            for j in sorted(free)
            if new[j].get("direction") == c.get("direction")
            and new[j].get("label") == c.get("label")
        ]
        if same:
            f = c.get("frequency_hz")
            best = min(same, key=lambda j: abs(new[j].get("frequency_hz", 0.0) - f))
            free.discard(best)
            pairs.append((i, best))
    return sorted(pairs)


def _source_key(source: dict[str, Any]) -> tuple[Any, ...]:
    return tuple(source.get(k) for k in ("part", "element", "lobes", "term"))


def _match_by(new: list[Any], old: list[Any], key: Any) -> list[tuple[int, int]]:
    """(old index, new index) of items of equal ``key`` (in their order where keys repeat)."""
    waiting: dict[Any, list[int]] = {}
    for j, item in enumerate(new):
        waiting.setdefault(key(item), []).append(j)
    pairs = []
    for i, item in enumerate(old):
        queue = waiting.get(key(item))
        if queue:
            pairs.append((i, queue.pop(0)))
    return pairs


def _label_from_tied_sources(new: dict[str, Any], old: dict[str, Any]) -> bool:
    """Whether two labels differ only because tied sources swapped: each is the short label
    of its own sources (the sources and their order are compared on their own)."""
    from runout.analysis.lines import Source, short_label

    def label_of(line: dict[str, Any]) -> str | None:
        try:
            return short_label([Source(**s) for s in line.get("sources", [])])
        except TypeError:
            return None

    same_sources = sorted(map(_source_key, new.get("sources", []))) == sorted(
        map(_source_key, old.get("sources", []))
    )
    return same_sources and label_of(new) == new.get("label") and label_of(old) == old.get("label")


def differences(new: Any, old: Any) -> list[str]:
    """Where ``new`` differs from the stored ``old`` beyond the policy of this module.

    Parameters
    ----------
    new : object
        The fresh JSON document (``json.loads`` of the output).
    old : object
        The stored one (its scales set the absolute floors).

    Returns
    -------
    list of str
        One line per difference: JSON path, stored value, new value, tolerance. Empty when the
        documents agree.
    """
    comparison = _Comparison(old)
    comparison.value(new, old, ())
    return comparison.problems


def assert_same(new: Any, old: Any, name: str = "") -> None:
    """Fail (AssertionError) listing the first differences of :func:`differences`.

    Parameters
    ----------
    new, old : object
        Fresh and stored JSON documents.
    name : str
        What was compared, for the message.
    """
    problems = differences(new, old)
    if problems:
        shown = "\n  ".join(problems[:12])
        more = f"\n  ... and {len(problems) - 12} more" if len(problems) > 12 else ""
        where = f"{name}: " if name else ""
        raise AssertionError(
            f"{where}{len(problems)} difference(s) from the stored output:\n  {shown}{more}"
        )
