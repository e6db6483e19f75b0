"""``runout reproduce --check``: two documents compared number by number.

Numbers are equal within :data:`~runout.validation.core.CHECK_RTOL` or one unit of their last
printed digit, so that a last-digit change on another CPU is not a difference.
"""

from __future__ import annotations

import re

from runout.validation.core import CHECK_RTOL

__all__ = ["compare", "split_sections"]

_NUMBER = re.compile(r"[-+−]?\d+(?:\.\d+)?(?:e[-+]?\d+)?")


def _numbers(line: str) -> tuple[str, list[str]]:
    return _NUMBER.sub("#", line), _NUMBER.findall(line)


def _close(a: str, b: str, rtol: float) -> bool:
    x, y = float(a.replace("−", "-")), float(b.replace("−", "-"))
    mantissa = a.split("e")[0]
    exponent = int(a.split("e")[1]) if "e" in a else 0
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    last_digit = 10.0 ** (exponent - decimals)
    return abs(x - y) <= max(rtol * max(abs(x), abs(y)), 1.0001 * last_digit)


def split_sections(text: str) -> dict[str, str]:
    """``### title`` → its block (up to the next ``### `` heading).

    Parameters
    ----------
    text : str
        A Markdown document.

    Returns
    -------
    dict of str to str
        Section title -> its lines, heading included; the text before the first heading is
        under ``""``.
    """
    out: dict[str, str] = {}
    title = ""
    for line in text.splitlines(keepends=True):
        if line.startswith("### "):
            title = line[4:].strip()
        out[title] = out.get(title, "") + line
    return out


def compare(fresh: str, existing: str, rtol: float = CHECK_RTOL) -> list[str]:
    """Differences between two documents, numbers compared within ``rtol`` or one unit of
    their last printed digit (so a last-digit change on another CPU is not a difference).

    Parameters
    ----------
    fresh : str
        The document just built.
    existing : str
        The document on disk.
    rtol : float
        Relative tolerance on a number [-].

    Returns
    -------
    list of str
        One message per differing line (and one when the line counts differ); empty when the
        documents agree.
    """
    a, b = fresh.splitlines(), existing.splitlines()
    problems: list[str] = []
    if len(a) != len(b):
        problems.append(f"{len(a)} lines fresh vs {len(b)} on disk")
    for i, (la, lb) in enumerate(zip(a, b, strict=False), start=1):
        if la == lb:
            continue
        sa, na = _numbers(la)
        sb, nb = _numbers(lb)
        same = len(na) == len(nb) and all(_close(x, y, rtol) for x, y in zip(na, nb, strict=True))
        if sa != sb or not same:
            problems.append(f"line {i}: fresh {la[:160]!r} vs on disk {lb[:160]!r}")
    return problems


# ---------------------------------------------------------------------------------------------
