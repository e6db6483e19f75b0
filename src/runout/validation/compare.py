"""``runout reproduce --check``: two documents compared number by number, rows cell by cell.

A document is stale when a number moved beyond what it states, not when its last digit did on
another CPU (numba compiles for the host, libraries move):

* text is exact, and so is a verdict with its tolerance;
* a number is the same within :data:`~runout.validation.core.CHECK_RTOL` or one unit of its
  last printed digit;
* in a table row, "ours" may also read as a bound (``< 1e-11``: an error measure at rounding
  level) on one side and as a number at that bound on the other;
* the "difference" column is computed from ours and the published value, so it may move as
  much as ours may (CHECK_RTOL of ours), in its own unit: a difference of two near-equal
  numbers (``-5.14e-08 %``) has few stable digits, and compared on its own it would be stale
  whenever ours moved in its last digits.
"""

from __future__ import annotations

import re

from runout.validation.core import CHECK_RTOL

__all__ = ["compare", "split_sections"]

_NUMBER = re.compile(r"[-+−]?\d+(?:\.\d+)?(?:e[-+]?\d+)?")
_VERDICT = re.compile(r"^(?:✅ agrees|⚠ within the documented spread|❌ not reproduced) \((.*)\)$")
#: The cells of a row of a check table (:data:`runout.validation.render.HEADER`).
_CELLS = ("source", "quantity", "published", "ours", "difference", "verdict", "why")
_OURS, _DIFFERENCE, _VERDICT_CELL = 3, 4, 5


def _numbers(line: str) -> tuple[str, list[str]]:
    return _NUMBER.sub("#", line), _NUMBER.findall(line)


def _value(token: str) -> float:
    return float(token.replace("−", "-"))


def _last_digit(token: str) -> float:
    """One unit of the last digit ``token`` is printed with (``"2.5e-08"`` → 1e-9)."""
    mantissa, _, exponent = token.partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return 10.0 ** ((int(exponent) if exponent else 0) - decimals)


def _close(a: str, b: str, rtol: float) -> bool:
    """Within ``rtol``, or one unit of the finer last digit of the two (one format prints
    both; ``%g`` drops trailing zeros, so the finer one is the format's)."""
    x, y = _value(a), _value(b)
    digit = min(_last_digit(a), _last_digit(b))
    return abs(x - y) <= max(rtol * max(abs(x), abs(y)), 1.0001 * digit)


def _same_text(a: str, b: str, rtol: float) -> bool:
    """Equal text, numbers within ``rtol`` or one unit of their last printed digit."""
    if a == b:
        return True
    sa, na = _numbers(a)
    sb, nb = _numbers(b)
    return (
        sa == sb
        and len(na) == len(nb)
        and all(_close(x, y, rtol) for x, y in zip(na, nb, strict=True))
    )


def _cells(line: str) -> list[str] | None:
    """The cells of a check-table row (``|`` escaped as ``\\|`` inside a cell), else None."""
    if not (line.startswith("| ") and line.endswith(" |")):
        return None
    cells = [c.strip() for c in re.split(r"(?<!\\)\|", line)[1:-1]]
    if len(cells) != len(_CELLS) or not _VERDICT.match(cells[_VERDICT_CELL]):
        return None
    return cells


def _first_number(text: str) -> float | None:
    found = _NUMBER.search(text)
    return _value(found.group(0)) if found else None


def _same_ours(a: str, b: str, rtol: float) -> bool:
    """Ours: as text, or a bound ``< q`` against a number at that bound."""
    if _same_text(a, b, rtol):
        return True
    for bound, other in ((a, b), (b, a)):
        if bound.startswith("< ") and not other.startswith("< "):
            q, x = _first_number(bound), _first_number(other)
            if q is None or x is None or _numbers(other)[0] != "#":
                return False
            return abs(x) <= q * (1.0 + rtol) + 1.0001 * _last_digit(_NUMBER.findall(other)[0])
    return False


def _same_difference(a: str, b: str, ours: str, published: str, verdict: str, rtol: float) -> bool:
    """The difference column: it moves as ours may, CHECK_RTOL of ours, in its own unit."""
    if _same_text(a, b, rtol):
        return True
    va, vb = _first_number(a), _first_number(b)
    x, p = _first_number(ours), _first_number(published)
    unit = {"%": 100.0, "×": 1.0}
    kind_a = "%" if a.endswith("%") else ("×" if a.startswith("×") else "")
    kind_b = "%" if b.endswith("%") else ("×" if b.startswith("×") else "")
    if va is None or vb is None or x is None or kind_a != kind_b:
        return False
    tokens = _NUMBER.findall(a) + _NUMBER.findall(b)
    digit = 1.0001 * min(_last_digit(t) for t in tokens)
    if kind_a:  # 100 (ours/published − 1) % or ×ours/published: ratios of ours
        if not p:
            return False
        allowed = unit[kind_a] * rtol * abs(x / p)
    else:  # ours − published, printed as 0 below 1e-4 of the tolerance
        rule = _VERDICT.match(verdict)
        tol = _first_number(rule.group(1)) if rule else None
        allowed = max(rtol * abs(x), 1e-4 * tol * (1.0 + rtol) if tol else 0.0)
    return abs(va - vb) <= allowed + digit


def _row_differences(fresh: list[str], disk: list[str], rtol: float) -> list[str]:
    """Names of the cells of two check-table rows that differ."""
    out = []
    for k, (a, b) in enumerate(zip(fresh, disk, strict=True)):
        if k == _VERDICT_CELL:
            same = a == b
        elif k == _OURS:
            same = _same_ours(a, b, rtol)
        elif k == _DIFFERENCE:
            same = _same_difference(a, b, fresh[_OURS], fresh[2], fresh[_VERDICT_CELL], rtol)
        else:
            same = _same_text(a, b, rtol)
        if not same:
            out.append(f"{_CELLS[k]} {a[:80]!r} on disk {b[:80]!r}")
    return out


def split_sections(text: str) -> dict[str, str]:
    """``### title`` → its block (up to the next ``### `` heading).

    Parameters
    ----------
    text : str
        A validation document (Markdown).

    Returns
    -------
    dict of str to str
        Each section's title and its text, heading included (the text before the first
        heading under the title ``""``).
    """
    out: dict[str, str] = {}
    title = ""
    for line in text.splitlines(keepends=True):
        if line.startswith("### "):
            title = line[4:].strip()
        out[title] = out.get(title, "") + line
    return out


#: A sentence of the document's head (:data:`runout.validation.render.HEAD`): a file without it
#: was not written by ``runout reproduce``, which replaces only its own document.
GENERATED_MARK = "generated by `runout reproduce`"
#: The title of the document's last section, the index of the example case files.
EXAMPLES_TITLE = "Example case files used above"


def merge_sections(existing: str, fresh: str) -> str:
    """``existing`` with each section of ``fresh`` in place of the one of the same title.

    Parameters
    ----------
    existing : str
        A validation document on disk.
    fresh : str
        A document of some sections (``runout reproduce --only``).

    Returns
    -------
    str
        The existing document, its head and every other section unchanged; a section of
        ``fresh`` it lacks goes before the index of the example case files (at the end without
        one).
    """
    blocks = split_sections(existing)
    new = {t: b for t, b in split_sections(fresh).items() if t}
    added = [t for t in new if t not in blocks]
    out: list[str] = []
    for title, block in blocks.items():
        if title == EXAMPLES_TITLE:
            out += [new[t] for t in added]
            added = []
        out.append(new.get(title, block) if title else block)
    out += [new[t] for t in added]
    # a block ends with the blank line before the next heading, the last with none
    parts = [b.rstrip("\n") + "\n" for b in out]
    return "\n".join(parts)


def compare(fresh: str, existing: str, rtol: float = CHECK_RTOL) -> list[str]:
    """Differences between two documents (see the module docstring for what is one).

    Parameters
    ----------
    fresh : str
        The document as ``runout reproduce`` builds it now.
    existing : str
        The document on disk.
    rtol : float
        Relative tolerance of a number (:data:`~runout.validation.core.CHECK_RTOL`).

    Returns
    -------
    list of str
        One entry per differing line: its number, and the differing cells of a table row or
        the two lines.
    """
    a, b = fresh.splitlines(), existing.splitlines()
    problems: list[str] = []
    if len(a) != len(b):
        problems.append(f"{len(a)} lines fresh vs {len(b)} on disk")
    for i, (la, lb) in enumerate(zip(a, b, strict=False), start=1):
        if la == lb:
            continue
        ca, cb = _cells(la), _cells(lb)
        if ca is not None and cb is not None:
            cells = _row_differences(ca, cb, rtol)
            if cells:
                problems.append(
                    f"line {i} ({ca[0][:40]} | {ca[1][:60]}): fresh " + "; ".join(cells)
                )
        elif not _same_text(la, lb, rtol):
            problems.append(f"line {i}: fresh {la[:160]!r} vs on disk {lb[:160]!r}")
    return problems
