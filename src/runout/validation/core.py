"""The core of the validation document: a check, its evaluated row, the verdict rules.

A :class:`Check` pairs one published number (typed in the module of its source, next to the
citation) with a function that computes ours. The comparison, the tolerance and the verdict
rule are part of the check; so is the reason for a gap, in our own words. A :class:`Group` is a
table of checks with its prose, a :class:`Section` a heading of groups; :mod:`.render` turns
them into Markdown and :mod:`.compare` compares two documents.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

__all__ = [
    "AGREE",
    "CHECK_RTOL",
    "NM",
    "NOT",
    "ROUNDOFF",
    "SPREAD",
    "UM",
    "VERDICT_TEXT",
    "Check",
    "Document",
    "Group",
    "Row",
    "Section",
    "Value",
    "bind",
]

UM = 1e-6
NM = 1e-9
CHECK_RTOL = 1e-6
#: Relative round-off of the error measures the checks compute: double precision (2.2e-16)
#: through the conditioning of what is checked (the closest distances of seed 004 lose four
#: digits to cancellation and read 1e-12 to 3e-12, and move between machines). A relative
#: error or difference below it is rounding noise: printed as a bound or 0, not as a result.
ROUNDOFF = 1e-11

Value = float | tuple[float, float, float]
"""Ours: a number, or (central value, low, high) of a spread."""

AGREE, SPREAD, NOT = "agree", "spread", "not"
VERDICT_TEXT = {
    AGREE: "✅ agrees",
    SPREAD: "⚠ within the documented spread",
    NOT: "❌ not reproduced",
}


@dataclass(frozen=True)
class Check:
    """One published (or theoretical) value against ours.

    Parameters
    ----------
    source, quantity : str
        Where the number is printed and what it is.
    published : float or None
        The source's number. ``None`` for a check against theory: then ``expected`` describes
        the expectation and ``ours`` returns the measured error or ratio.
    ours : callable
        Computes our value (same unit as ``published``).
    rule : {"rel", "abs", "max", "min"}
        ``rel``/``abs``: ``|ours/published − 1|`` or ``|ours − published|`` within ``tol``.
        ``max``/``min``: ours ≤ ``tol`` or ours ≥ ``tol`` (``published`` may be None).
    tol : float
        The tolerance the source supports (the one of the reference test).
    expected : str
        What a check against theory expects (shown in the "Published" column when
        ``published`` is None).
    reason : str
        Why a gap exists (our words); "—" when there is none.
    case : str, optional
        The example file the value is computed from.
    spread_from_ours : bool
        ``ours`` returns (value, low, high), the documented spread of ours: a published value
        outside ``tol`` but inside (low, high) is "within the documented spread".
    digits : int
        Significant digits shown.
    """

    source: str
    quantity: str
    published: float | None
    ours: Callable[[], Value]
    rule: str = "rel"
    tol: float = 0.03
    expected: str = ""
    reason: str = "—"
    case: str | None = None
    spread_from_ours: bool = False
    digits: int = 5

    def evaluate(self) -> Row:
        """Compute ours and apply the rule: the :class:`Row` of the document.

        Returns
        -------
        Row
            Our value (and its spread when ``ours`` gives one) with the verdict: :data:`AGREE`
            within the rule, :data:`SPREAD` outside it but inside the spread of ours (with
            ``spread_from_ours``), :data:`NOT` otherwise.
        """
        value = self.ours()
        low = high = None
        if isinstance(value, tuple):
            value, low, high = value
        value = float(value)
        pub = self.published
        if self.rule == "rel":
            assert pub is not None
            ok = abs(value / pub - 1.0) <= self.tol
        elif self.rule == "abs":
            assert pub is not None
            ok = abs(value - pub) <= self.tol
        elif self.rule == "max":
            ok = value <= self.tol
        elif self.rule == "min":
            ok = value >= self.tol
        else:  # pragma: no cover - registry error
            raise ValueError(self.rule)
        verdict = AGREE if ok else NOT
        if (
            not ok
            and self.spread_from_ours
            and pub is not None
            and low is not None
            and high is not None
            and low <= pub <= high
        ):
            verdict = SPREAD
        return Row(self, value, low, high, verdict)


@dataclass(frozen=True)
class Row:
    """A check evaluated: our value, its spread (when it has one) and the verdict.

    Attributes
    ----------
    check : Check
        The check this row evaluates.
    value : float
        Ours, in the unit of ``check.published``.
    low, high : float or None
        The documented spread of ours (None without one).
    verdict : {"agree", "spread", "not"}
        :data:`AGREE`, :data:`SPREAD` or :data:`NOT`.
    """

    check: Check
    value: float
    low: float | None
    high: float | None
    verdict: str

    def cells(self) -> list[str]:
        """The table's cells: source, quantity, published, ours, difference, verdict, why.

        Returns
        -------
        list of str
            The seven cells of :data:`runout.validation.render.HEADER`, in its order.
        """
        c = self.check
        pub = c.published
        d = c.digits
        published = _num(pub, d) if pub is not None else (c.expected or "—")
        q = _quantum(c)
        if c.rule == "max" and 0 <= self.value < q:
            ours = f"< {q:.3g}"
        elif c.rule == "abs" and abs(self.value - (pub or 0.0)) < q:
            ours = _num(pub or 0.0, d)
        else:
            ours = _num(self.value, d)
        if self.low is not None and self.high is not None:
            ours += f" [{_num(self.low, d)}–{_num(self.high, d)}]"
        if pub is None:
            diff = "—"
        elif c.rule == "abs":
            delta = self.value - pub
            diff = "0" if abs(delta) < q else f"{delta:+.3g}"
        elif pub != 0 and 0.5 <= abs(self.value / pub) <= 2.0:
            gap = self.value / pub - 1.0
            diff = "0 %" if abs(gap) < ROUNDOFF else f"{100.0 * gap:+.3g} %"
        elif pub != 0 and self.value != 0:
            diff = f"×{self.value / pub:.4g}"
        else:
            diff = "—"
        tolerance = _rule_text(c)
        return [
            c.source,
            c.quantity,
            published,
            ours,
            diff,
            f"{VERDICT_TEXT[self.verdict]} ({tolerance})",
            c.reason,
        ]


def bind(fn: Callable[..., Any], *args: Any) -> Callable[[], Value]:
    """``fn`` with its arguments bound (a loop variable captured by value).

    Parameters
    ----------
    fn : callable
        Computes our value from ``args``.
    *args
        Its positional arguments.

    Returns
    -------
    callable
        ``fn(*args)`` without arguments, for :attr:`Check.ours`.
    """
    return functools.partial(fn, *args)


def _num(x: float, digits: int = 5) -> str:
    """A fixed number of significant figures (five unless the check says otherwise)."""
    if x == 0:
        return "0"
    return f"{x:.{digits}g}"


def _quantum(c: Check) -> float:
    """Below this an error measure (``max``) or a difference (``abs``) is rounding noise that
    would differ between machines: it is printed as a bound or as 0.

    An error measure reads as a bound below 1e-3 of its tolerance, and below :data:`ROUNDOFF`
    (the checks with a tolerance under 1e-8 are relative errors expected at round-off; where
    the tolerance is itself below ROUNDOFF, the bound is the tolerance).
    """
    if c.rule == "max":
        return max(1e-3 * c.tol, min(c.tol, ROUNDOFF))
    if c.rule == "abs":
        return 1e-4 * c.tol
    return 0.0


def _rule_text(c: Check) -> str:
    if c.rule == "rel":
        return f"±{100 * c.tol:.3g} %"
    if c.rule == "abs":
        return f"±{c.tol:.3g}"
    if c.rule == "max":
        return f"≤ {c.tol:.3g}"
    return f"≥ {c.tol:.3g}"


@dataclass(frozen=True)
class Group:
    """A sub-section: a heading, prose, a table of checks, prose after it.

    Attributes
    ----------
    title : str
        The ``####`` heading; empty for none.
    intro : str
        Prose before the table (Markdown).
    checks : callable
        Builds the group's list of :class:`Check` (called when the document is built).
    outro : str or callable
        Prose after the table; a callable when it quotes computed numbers.
    """

    title: str
    intro: str
    checks: Callable[[], list[Check]]
    outro: str | Callable[[], str] = ""
    """Prose after the table; a callable when it quotes computed numbers."""


@dataclass(frozen=True)
class Section:
    """A ``###`` section of the document: ``key`` for ``--only``, a title, prose, groups.

    Attributes
    ----------
    key : str
        Its name for ``runout reproduce --only``.
    title : str
        The ``###`` heading.
    intro : str
        Prose under the heading (Markdown).
    groups : list of Group
        Its tables, in order.
    """

    key: str
    title: str
    intro: str
    groups: list[Group] = field(default_factory=list)


@dataclass(frozen=True)
class Document:
    """The rendered Markdown and every evaluated row.

    Attributes
    ----------
    text : str
        The Markdown document (VALIDATION.md).
    rows : list of Row
        Every evaluated check, in document order.
    """

    text: str
    rows: list[Row]

    def counts(self) -> dict[str, int]:
        """Number of rows per verdict.

        Returns
        -------
        dict of str to int
            :data:`AGREE`, :data:`SPREAD` and :data:`NOT` -> number of rows.
        """
        return {v: sum(r.verdict == v for r in self.rows) for v in (AGREE, SPREAD, NOT)}

    def summary(self) -> str:
        """One line: checks, agreeing, within spread, not reproduced.

        Returns
        -------
        str
            ``N checks: A agree, S within spread, X not reproduced``.
        """
        c = self.counts()
        return (
            f"{len(self.rows)} checks: {c[AGREE]} agree, {c[SPREAD]} within spread, "
            f"{c[NOT]} not reproduced"
        )
