"""Reproduce the published numbers of the seed papers and write VALIDATION.md.

A :class:`Check` pairs one published number (typed here: it is the paper's) with a function
that computes ours, from an example case file in ``examples/`` where the row reproduces a table
or a figure, otherwise from the library API. The comparison, the tolerance and the verdict rule
are part of the check; so is the reason for a gap, in our own words. Nothing in the generated
document is typed by hand: every "ours" column, every difference and every verdict is computed.

``runout reproduce`` runs every check and writes VALIDATION.md; ``runout reproduce --check``
compares a fresh document with the file on disk (numbers within :data:`CHECK_RTOL` or one unit
of their last printed digit).
"""

from __future__ import annotations

import functools
import math
import re
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
UM = 1e-6
NM = 1e-9
CHECK_RTOL = 1e-6

Value = float | tuple[float, float, float]
"""Ours: a number, or (central value, low, high) of a spread."""

AGREE, SPREAD, NOT = "agree", "spread", "not"
VERDICT_TEXT = {
    AGREE: "✅ agrees",
    SPREAD: "⚠ within the documented spread",
    NOT: "❌ not reproduced",
}


# ---------------------------------------------------------------------------------------------
# checks and their rendering
# ---------------------------------------------------------------------------------------------
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
    spread : callable, optional
        (low, high) of the documented spread: outside ``tol`` but inside it is "within the
        documented spread". With ``ours`` returning (value, low, high) the spread is that one.
    reason : str
        Why a gap exists (our words); "—" when there is none.
    case : str, optional
        The example file the value is computed from.
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
    check: Check
    value: float
    low: float | None
    high: float | None
    verdict: str

    def cells(self) -> list[str]:
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
            diff = f"{100.0 * (self.value / pub - 1.0):+.3g} %"
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


def _bind(fn: Callable[..., Any], *args: Any) -> Callable[[], Value]:
    """``fn`` with its arguments bound (a loop variable captured by value)."""
    return functools.partial(fn, *args)


def _num(x: float, digits: int = 5) -> str:
    """A fixed number of significant figures (five unless the check says otherwise)."""
    if x == 0:
        return "0"
    return f"{x:.{digits}g}"


def _quantum(c: Check) -> float:
    """Below this an error measure (``max``) or a difference (``abs``) is rounding noise that
    would differ between machines: it is printed as a bound or as 0."""
    if c.rule == "max":
        return 1e-3 * c.tol
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
    """A sub-section: a heading, prose, a table of checks, prose after it."""

    title: str
    intro: str
    checks: Callable[[], list[Check]]
    outro: str | Callable[[], str] = ""
    """Prose after the table; a callable when it quotes computed numbers."""


@dataclass(frozen=True)
class Section:
    key: str
    title: str
    intro: str
    groups: list[Group] = field(default_factory=list)


HEADER = ["Source", "Quantity", "Published", "Ours", "Difference", "Verdict", "Why a gap exists"]


def _table(rows: Sequence[Row]) -> str:
    lines = ["| " + " | ".join(HEADER) + " |", "|" + "---|" * len(HEADER)]
    for r in rows:
        lines.append("| " + " | ".join(x.replace("|", "\\|") for x in r.cells()) + " |")
    return "\n".join(lines)


def render_section(section: Section) -> tuple[str, list[Row]]:
    """Markdown of one section and its evaluated rows."""
    parts = [f"### {section.title}", section.intro.strip()]
    rows: list[Row] = []
    for g in section.groups:
        if g.title:
            parts.append(f"#### {g.title}")
        if g.intro.strip():
            parts.append(g.intro.strip())
        group_rows = [c.evaluate() for c in g.checks()]
        rows += group_rows
        parts.append(_table(group_rows))
        outro = g.outro() if callable(g.outro) else g.outro
        if outro.strip():
            parts.append(outro.strip())
    return "\n\n".join(p for p in parts if p) + "\n", rows


HEAD = """\
# Validation

Each published number the code is checked against, our value, the difference, the verdict and
why any gap exists. This file is generated by `runout reproduce` (registry:
`src/runout/reproduce.py`); nothing in it is typed by hand except the papers' numbers and our
explanations. Where a row reproduces a table or a figure, "ours" is computed from the example
case file named in the last section. The same numbers are pinned by the tests in
`tests/reference/`, and `tests/unit/test_validation_doc.py` fails when this file is stale.

Verdicts: ✅ agrees within the tolerance the source supports (shown in brackets); ⚠ outside it
but inside the documented spread (random phases, sampling); ❌ not reproduced (the reason
column says why). Numbers are printed with five significant figures.

Sources: seed 000 S. Tada, "Three-dimensional analysis of non-repeatable runout (NRRO) in ball
bearings", Koyo Engineering Journal (2002); seed 001 Y.-C. Kim, S.-K. Choi, K.-C. Yoon,
"Vibration analysis of ball bearings with ball geometric imperfections"; seed 002 "Anderon
vibration", an instrument maker's calculation model; seed 003 R.K. Purohit, K. Purohit,
"Dynamic analysis of ball bearings with effect of preload and number of balls" (2006); seed 004
Y. Yu et al., "Prediction method for the radial runout of inner ring in cylindrical roller
bearings", Mathematical Problems in Engineering (2017); Harris, *Rolling Bearing Analysis*; the
CWRU bearing data centre's 6205 table. Speeds are in
BENCHMARKS.md.
"""


@dataclass(frozen=True)
class Document:
    text: str
    rows: list[Row]

    def counts(self) -> dict[str, int]:
        return {v: sum(r.verdict == v for r in self.rows) for v in (AGREE, SPREAD, NOT)}

    def summary(self) -> str:
        c = self.counts()
        return (
            f"{len(self.rows)} checks: {c[AGREE]} agree, {c[SPREAD]} within spread, "
            f"{c[NOT]} not reproduced"
        )


def section_keys() -> list[str]:
    return [s.key for s in SECTIONS]


def build(
    only: Iterable[str] | None = None,
    progress: Callable[[str, int, int], None] | None = None,
) -> Document:
    """Run the checks (all sections, or those in ``only``) and render the document."""
    keys = section_keys()
    wanted = list(keys if only is None else only)
    unknown = [k for k in wanted if k not in keys]
    if unknown:
        from runout.errors import RunoutError

        raise RunoutError(f"unknown section(s) {', '.join(unknown)}; choose from {', '.join(keys)}")
    sections = [s for s in SECTIONS if s.key in wanted]
    parts = [HEAD]
    rows: list[Row] = []
    for i, s in enumerate(sections):
        if progress is not None:
            progress(s.title, i, len(sections))
        text, section_rows = render_section(s)
        parts.append(text)
        rows += section_rows
    if only is None:
        parts.append(example_index())
    return Document("\n".join(parts), rows)


# ---------------------------------------------------------------------------------------------
# comparing documents (--check)
# ---------------------------------------------------------------------------------------------
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
    """``### title`` → its block (up to the next ``### `` heading)."""
    out: dict[str, str] = {}
    title = ""
    for line in text.splitlines(keepends=True):
        if line.startswith("### "):
            title = line[4:].strip()
        out[title] = out.get(title, "") + line
    return out


def compare(fresh: str, existing: str, rtol: float = CHECK_RTOL) -> list[str]:
    """Differences between two documents, numbers compared within ``rtol`` or one unit of
    their last printed digit (so a last-digit change on another CPU is not a difference)."""
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
# example case files
# ---------------------------------------------------------------------------------------------
def _load(name: str) -> Any:
    from runout.case import load_case

    return load_case(EXAMPLES / name)


def _variant(name: str, mutate: Callable[[dict[str, Any]], None]) -> Any:
    """The example ``name`` with its data changed by ``mutate`` (a loop done in code)."""
    from runout.case import parse_case

    case = _load(name)
    data = case.spec.model_dump(exclude_none=True)
    mutate(data)
    return parse_case(data, str(EXAMPLES / name), EXAMPLES)


EXAMPLE_USES: dict[str, str] = {}


def _uses(name: str, what: str) -> str:
    EXAMPLE_USES.setdefault(name, what)
    return name


def example_index() -> str:
    lines = [
        "### Example case files used above",
        "",
        "| file | reproduces |",
        "|---|---|",
    ]
    for name in sorted(EXAMPLE_USES):
        lines.append(f"| `examples/{name}` | {EXAMPLE_USES[name]} |")
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------------------------
# kinematics
# ---------------------------------------------------------------------------------------------
INCH = 25.4e-3


@functools.cache
def _cwru() -> dict[str, float]:
    from runout import BallBearing, Operation
    from runout.kinematics import bearing_frequencies

    bearing = BallBearing(9, 0.3126 * INCH, 1.537 * INCH, contact_angle=0.0)
    return dict(bearing_frequencies(bearing, Operation("inner", speed=1.0)).orders())


@functools.cache
def _orders_608() -> dict[str, float]:
    from runout import Operation
    from runout.kinematics import bearing_frequencies

    case = _load("seed002_608.toml")
    return dict(bearing_frequencies(case.bearing, Operation("inner", speed=1.0)).orders())


def _kim_freq(which: str) -> float:
    from runout.kinematics import bearing_frequencies

    case = _load("seed001_kim_spindle.toml")
    f = bearing_frequencies(case.bearing, case.operation, math.radians(18.73))
    return float(f.cage if which == "cage" else f.ball_spin)


def _seed003_bpf_error() -> float:
    from runout import Operation
    from runout.kinematics import bearing_frequencies

    case = _load("seed003_purohit.toml")
    b = case.bearing
    f = bearing_frequencies(b, Operation("inner", speed=case.operation.speed), 0.0)
    expected = 0.5 * b.elements * case.operation.speed * (1 - b.element_diameter / b.pitch_diameter)
    return abs(float(f.ball_pass_outer) / expected - 1.0)


def _seed004_cage_error() -> float:
    from runout import Operation
    from runout.kinematics import bearing_frequencies

    b = _load("seed004_nu209.toml").bearing
    f = bearing_frequencies(b, Operation("inner", speed=1.0))
    d_i, d_e = b.inner_raceway_diameter, b.outer_raceway_diameter
    expected = 0.5 * (1 - 2 * b.element_diameter / (d_i + d_e))
    return abs(float(f.cage) / expected - 1.0)


def _kinematics() -> list[Check]:
    cw = "CWRU 6205-2RS JEM (9 balls, 0.3126 in, 1.537 in, 0°)"
    s002 = _uses("seed002_608.toml", "seed 002 Tab. 1, eq. 43–47, eq. 48–59, Fig. 12")
    s001 = _uses("seed001_kim_spindle.toml", "seed 001 Table 1 bearing, §5.1 frequencies")
    o = _orders_608
    return [
        Check(cw, "BPFI [orders]", 5.4152, lambda: _cwru()["ball_pass_inner"], "abs", 5e-5),
        Check("″", "BPFO", 3.5848, lambda: _cwru()["ball_pass_outer"], "abs", 5e-5),
        Check(
            "″",
            "FTF (cage)",
            0.39828,
            lambda: _cwru()["cage"],
            "rel",
            1e-4,
            reason="the table's last digit: 0.5 (1 − 0.3126/1.537) = 0.398308; checked at "
            "1e-4 relative",
        ),
        Check(
            "″",
            "ball spin",
            2.357,
            lambda: _cwru()["ball_spin"],
            "abs",
            5e-4,
            reason="printed to 4 figures",
        ),
        Check(
            "Seed 002 eq. 48 (608)",
            "I₇₋₁ (k = Z − 1 = 6)",
            3.41198,
            lambda: o()["ball_pass_inner"] - 1,
            "abs",
            1e-5,
            case=s002,
            digits=6,
        ),
        Check(
            "Seed 002 eq. 50",
            "inner flaw rate",
            4.41198,
            lambda: o()["ball_pass_inner"],
            "abs",
            1e-5,
            case=s002,
            digits=6,
        ),
        Check(
            "Seed 002 eq. 51",
            "O_7",
            2.58802,
            lambda: o()["ball_pass_outer"],
            "abs",
            1e-5,
            case=s002,
            digits=6,
        ),
        Check(
            "Seed 002 eq. 52",
            "O_14",
            5.17603,
            lambda: 2 * o()["ball_pass_outer"],
            "abs",
            1e-5,
            case=s002,
            digits=6,
        ),
        Check(
            "Seed 002 eq. 55",
            "B_A0 (cage)",
            0.369716,
            lambda: o()["cage"],
            "abs",
            1e-6,
            case=s002,
            digits=6,
        ),
        Check(
            "Seed 002 eq. 56",
            "B_B1",
            3.15316,
            lambda: 2 * o()["ball_spin"] - o()["cage"],
            "abs",
            1e-5,
            case=s002,
            digits=6,
        ),
        Check(
            "Seed 002 eq. 57",
            "B_A1",
            3.89259,
            lambda: 2 * o()["ball_spin"] + o()["cage"],
            "abs",
            1e-5,
            case=s002,
            digits=6,
        ),
        Check(
            "Seed 002 eq. 59",
            "2 ω_b/ω",
            3.52287,
            lambda: 2 * o()["ball_spin"],
            "abs",
            1e-5,
            case=s002,
            digits=6,
        ),
        Check(
            "Seed 001 §5.1 (Table 1, 7200 rpm, α = 18.73°)",
            "f_c [Hz]",
            50.0,
            lambda: _kim_freq("cage"),
            "abs",
            0.5,
            reason="the paper rounds to 50 Hz",
            case=s001,
        ),
        Check(
            "″",
            "f_b [Hz]",
            335.0,
            lambda: _kim_freq("spin"),
            "abs",
            0.5,
            reason="the paper rounds to 335 Hz",
            case=s001,
        ),
        Check(
            "Seed 003 eq. 2.20 (theory)",
            "BPF vs (Z/2) f_i (1 − D/d_m), relative error",
            None,
            _seed003_bpf_error,
            "max",
            1e-12,
            expected="0",
            case=_uses("seed003_purohit.toml", "seed 003 Table 2 rotor, Figs. 3–4 (dynamic)"),
        ),
        Check(
            "Seed 004 eq. 3 (theory)",
            "cage ratio vs ½ (1 − 2D_w/(d_i + d_e)), relative error",
            None,
            _seed004_cage_error,
            "max",
            1e-12,
            expected="0",
            case=_uses("seed004_nu209.toml", "seed 004 Table 1 NU209, Fig. 9"),
        ),
    ]


# ---------------------------------------------------------------------------------------------
# Hertz contact and axial loading
# ---------------------------------------------------------------------------------------------
MM = 1e-3


def _harris_steel() -> Any:
    from runout import Material

    return Material(207.5e9, 0.3)


def _harris_209_curvature(race: str, which: int) -> float:
    from runout.contact import ball_race_curvature

    values = ball_race_curvature(12.7 * MM, 65 * MM, 0.52, 0.0, race)  # type: ignore[arg-type]
    return float(values[which]) * (MM if which == 0 else 1.0)


def _harris_209_approach_um(race: str) -> float:
    from runout import BallBearing
    from runout.contact import ball_race_contacts

    b = BallBearing(
        9, 12.7 * MM, 65 * MM, 0.52, 0.52, radial_clearance=0.0, material=_harris_steel()
    )
    contacts = ball_race_contacts(b)
    contact = contacts.inner if race == "inner" else contacts.outer
    return float(contact.approach(1000.0)) * 1e6


def _delta_star_rows(worst_row: bool) -> float:
    from runout.contact import HARRIS_DELTA_STAR_TABLE, dimensionless_factors

    errors = []
    for f, ds in HARRIS_DELTA_STAR_TABLE[:-1]:
        if (f == 0.83595) != worst_row:
            continue
        errors.append(abs(float(dimensionless_factors(f)[2]) / ds - 1.0))
    return max(errors)


def _delta_star_083595() -> float:
    from runout.contact import dimensionless_factors

    return float(dimensionless_factors(0.83595)[2])


def _interpolated_stiffness_error() -> float:
    from runout.contact import hertz_point_stiffness, stiffness_from_delta_star_table

    f = np.linspace(0.0, 0.9998527, 4001)
    exact = hertz_point_stiffness(1e3, f, 2.28e11)
    table = stiffness_from_delta_star_table(1e3, f, 2.28e11)
    return float(np.max(np.abs(table / exact - 1.0)))


def _steel_constant() -> float:
    return float((3.0 / _harris_steel().effective_modulus) ** (2 / 3) / 2)


def _inverse_constant() -> float:
    from runout.contact import hertz_point_stiffness

    return float(hertz_point_stiffness(1.0, 0.0, _harris_steel().effective_modulus))


def _purohit_k_n_mm() -> float:
    from runout.models import dynamic as dy

    st = dy.setup(_load("seed003_purohit.toml"))
    return 1.5 * float(st.stiffness) / 1000.0**1.5


def _hamrock_brewe(i: int) -> float:
    from runout.contact import curvature_difference_from_ratio, ellipticity, hamrock_brewe

    r = np.logspace(0.0, 2.0, 201)
    exact = ellipticity(curvature_difference_from_ratio(r))
    fit = hamrock_brewe(r)
    err = np.abs(fit[i] / exact[i] - 1.0)
    return float(np.max(err[r <= 40.0]) if i == 0 else np.max(err))


def _eq9_error() -> float:
    from runout import Material
    from runout.contact import PointContact, ball_flat_contact_radius

    steel = Material()
    rb = 1e-3
    contact = PointContact.from_radii(rb, rb, np.inf, np.inf, steel.effective_modulus)
    worst = 0.0
    for q in (0.01, 1.0, 11.039, 100.0):
        a, b = contact.semi_axes(q)
        ref = float(ball_flat_contact_radius(q, rb, steel))
        worst = max(worst, abs(float(a) / ref - 1.0), abs(float(b) / float(a) - 1.0))
    return worst


def _ball_flat_um(which: str) -> float:
    from runout import Material
    from runout.contact import PointContact, ball_flat_cap_displacement

    steel = Material()
    if which == "cap":
        return float(ball_flat_cap_displacement(11.039, 1e-3, steel)) * 1e6
    contact = PointContact.from_radii(1e-3, 1e-3, np.inf, np.inf, steel.effective_modulus)
    return float(contact.approach(11.039)) * 1e6


def _palmgren() -> float:
    from runout.contact import line_contact_load

    return float(line_contact_load(0.004 * MM, 15.0 * MM))


def _point_contact() -> list[Check]:
    h = "Harris, 209 bearing (D 12.7 mm, d_m 65 mm, f = 0.52, α = 0)"
    return [
        Check(
            h,
            "Σρ_i [1/mm]",
            0.2018,
            lambda: _harris_209_curvature("inner", 0),
            "abs",
            0.5e-4,
            reason="rounding",
        ),
        Check(
            "″",
            "F(ρ)_i",
            0.9400,
            lambda: _harris_209_curvature("inner", 1),
            "abs",
            0.5e-4,
            reason="rounding",
        ),
        Check("″", "Σρ_o [1/mm]", 0.1378, lambda: _harris_209_curvature("outer", 0), "abs", 0.5e-4),
        Check(
            "″",
            "F(ρ)_o",
            0.9121,
            lambda: _harris_209_curvature("outer", 1),
            "abs",
            0.5e-4,
            reason="rounding",
        ),
        Check(
            "″",
            "δ_i at Q = 1000 N [µm]",
            9.86,
            lambda: _harris_209_approach_um("inner"),
            "abs",
            0.005,
            reason="the published value uses the δ* table; within its last digit",
        ),
        Check(
            "″",
            "δ_o at Q = 1000 N [µm]",
            9.50,
            lambda: _harris_209_approach_um("outer"),
            "abs",
            0.005,
            reason="″",
        ),
        Check(
            "Seed 003 Table 1 (Harris's δ*)",
            "largest relative gap of the exact δ* over the 21 rows with F < 1 other than "
            "F = 0.83595",
            None,
            lambda: _delta_star_rows(False),
            "max",
            5e-4,
            expected="the table",
            reason='the row F = 0.995112 lost its "0." in extraction and is restored as 0.3176',
        ),
        Check(
            "Seed 003 Table 1, row F = 0.83595",
            "δ*",
            0.7602,
            _delta_star_083595,
            "rel",
            1.5e-3,
            reason="the exact value is 0.7592: a typo or rounding in the source",
        ),
        Check(
            "Seed 003 Table 1, interpolated in (ln(1−F), ln δ*)",
            "largest relative gap of K vs exact K over 0 ≤ F ≤ 0.99985",
            None,
            _interpolated_stiffness_error,
            "max",
            0.01,
            expected="< 1 %",
            reason="sparse rows near F ≈ 0.2; linear interpolation in F would be 6 % off near "
            "F → 1",
        ),
        Check(
            "Seed 003 eq. 2.10",
            "steel constant c in δ = c δ* Q^(2/3) Σρ^(1/3), ours (3/E′)^(2/3)/2",
            2.787e-8,
            _steel_constant,
            "rel",
            2e-4,
            reason="SI form of Harris's 2.79e-4 (mm); the exponent is not garbled",
        ),
        Check(
            "Seed 003 eq. 2.11–2.13",
            "constant c′ of Q = c′ Σρ^(−1/2) δ*^(−3/2) δ^(3/2) [N/m^1.5]",
            3.587e7,
            _inverse_constant,
            "rel",
            1e-3,
            reason="3.587e7 is 1/2.787e-8: the 3/2 power was not applied, and eq. 2.11 also has "
            "Σρ^(+1/2). We use the consistent inverse",
        ),
        Check(
            "Seed 003 eq. 2.15",
            "K in K √δ [N/mm^1.5], ours 1.5 K_n with the Table 2 geometry",
            7.055e5,
            _purohit_k_n_mm,
            "rel",
            0.03,
            reason="Table 2 is inconsistent (outer race radius 46 mm against a 27 mm pitch "
            "radius, f_o = 0.579); the printed constant is the one of a single contact (next "
            "row)",
        ),
        Check(
            "Seed 003 eq. 2.15, as the paper computed it",
            "K in K √δ [N/mm^1.5] read as 2^1.5 K_n: one contact's constant, the series "
            "combination of the inner and outer contacts skipped",
            7.055e5,
            lambda: 2.0**1.5 / 1.5 * _purohit_k_n_mm(),
            "rel",
            0.02,
            reason="+1.0 %: two equal contacts in series have K_n = K / 2^1.5, so the paper "
            "quotes K of one contact; the rest is Table 2's inconsistent radii (we use the ball "
            "and pitch sizes)",
        ),
        Check(
            "Hamrock & Brewe fits",
            "largest relative error of κ for 1 ≤ R_y/R_x ≤ 40",
            None,
            lambda: _hamrock_brewe(0),
            "max",
            0.035,
            expected="a few %",
            reason="curve fit; it drifts to 6.3 % at R_y/R_x = 100",
        ),
        Check(
            "″",
            "largest relative error of 𝒦, 1 ≤ R_y/R_x ≤ 100",
            None,
            lambda: _hamrock_brewe(1),
            "max",
            0.03,
            expected="a few %",
            reason="worst at the circular end",
        ),
        Check(
            "″",
            "largest relative error of ℰ, 1 ≤ R_y/R_x ≤ 100",
            None,
            lambda: _hamrock_brewe(2),
            "max",
            0.02,
            expected="a few %",
            reason="worst at the circular end",
        ),
        Check(
            "Seed 002 eq. 9 (ball on flat)",
            "contact radius vs the exact solver with radii (r_b, r_b, ∞, ∞), relative",
            None,
            _eq9_error,
            "max",
            1e-13,
            expected="identical",
            reason="eq. 9 is Hertz's circle for equal materials",
        ),
        Check(
            "Seed 002 eq. 11",
            "mean ball load, 20 N, Z = 7, α = 15° [N]",
            11.039,
            lambda: 20.0 / (7 * math.sin(math.radians(15.0))),
            "abs",
            5e-4,
        ),
        Check(
            "Seed 002 Fig. 6 / §2.2",
            "displacement of a 2 mm steel ball on a flat at 11.039 N, eq. 10 [µm]",
            19.0,
            lambda: _ball_flat_um("cap"),
            "rel",
            0.05,
            reason="eq. 10 is a rigid spherical-cap reading of the Hertz radius (half the Hertz "
            "approach); 19 µm from eq. 10 needs E ≈ 2 GPa, about 100× too small: most likely a "
            "unit slip in the figure",
        ),
        Check(
            "″",
            "same, Hertz approach [µm]",
            19.0,
            lambda: _ball_flat_um("hertz"),
            "rel",
            0.05,
            reason="″",
        ),
    ]


def _line_contact() -> list[Check]:
    published = 8.06e4 * 0.004 ** (10 / 9) * 15.0 ** (8 / 9)
    return [
        Check(
            "Harris (Palmgren), Q = 8.06e4 δ^(10/9) l^(8/9) (N, mm)",
            "Q at l = 15 mm, δ = 4 µm [N]",
            published,
            _palmgren,
            "rel",
            2e-3,
            reason="8.06e4 is the rounded inverse of δ = 3.84e-5 Q^0.9 / l^0.8",
        )
    ]


KIM_TABLE2 = {
    7: (19.80, 2.116, 2.113),
    8: (19.38, 1.977, 1.974),
    9: (19.03, 1.863, 1.860),
    10: (18.73, 1.766, 1.763),
    11: (18.47, 1.683, 1.680),
    12: (18.24, 1.610, 1.607),
}


def _kim_bearing(z: int) -> Any:
    def mutate(data: dict[str, Any]) -> None:
        data["bearing"]["elements"] = z
        data["elements"] = {"diameter_errors": [0.0] * z}

    return _variant("seed001_kim_spindle.toml", mutate).bearing


@functools.cache
def kim_fitted_preload() -> float:
    """The axial load [N] that gives Table 2's 18.73° at Z = 10 (static solution)."""
    from runout.loading import axial_load_for_contact_angle

    return float(axial_load_for_contact_angle(_kim_bearing(10), math.radians(18.73)))


@functools.cache
def _kim_axial(z: int) -> Any:
    from runout.loading import axial_loading

    return axial_loading(_kim_bearing(z), kim_fitted_preload())


def _kim_table2() -> list[Check]:
    s001 = _uses("seed001_kim_spindle.toml", "seed 001 Table 1 bearing, §5.1 frequencies")
    out = []
    for z, (alpha, d_i, d_o) in KIM_TABLE2.items():
        fitted = z == 10
        out += [
            Check(
                f"Seed 001 Table 2, Z = {z}",
                "α [°]",
                alpha,
                _bind(lambda z: math.degrees(_kim_axial(z).contact_angle), z),
                "abs",
                0.05,
                reason="the preload is fitted here" if fitted else "—",
                case=s001,
            ),
            Check(
                "″",
                "δ_i [µm]",
                d_i,
                _bind(lambda z: _kim_axial(z).inner_approach * 1e6, z),
                "rel",
                0.03,
                reason="the table's two halves imply different internal geometries (below)",
                case=s001,
            ),
            Check(
                "″",
                "δ_o [µm]",
                d_o,
                _bind(lambda z: _kim_axial(z).outer_approach * 1e6, z),
                "rel",
                0.03,
                reason="″",
                case=s001,
            ),
        ]
    return out


KIM_TABLE2_INTRO = """\
Bearing (`examples/seed001_kim_spindle.toml`, the number of balls changed in code):
D = 1.5875 mm, d_m = 9.1 mm, f_i = 0.529, f_o = 0.535, P_d = 5 µm, steel E = 208 GPa, ν = 0.3.
The paper does not print the axial preload. We fit it on Z = 10 (α = 18.73°) and predict the
other columns with K_n evaluated at the loaded angle."""

KIM_TABLE2_OUTRO = """\
Why the deflections differ while the angles agree to a few thousandths of a degree:

* At a given contact angle the rigid-ring geometry fixes δ_i + δ_o = A (cos α⁰ / cos α − 1)
  whatever the load and the modulus: about 3.04 µm at 18.73°, against 3.529 µm in the table.
  The gap is therefore not in the Hertz law.
* Speed effects at 7200 rpm cannot explain it: the centrifugal force of a ball at the cage
  speed is a few mN, well under 0.1 % of Q; the gyroscopic moment is of the same order. Both
  would also make δ_o > δ_i, whereas the table has δ_i > δ_o (Hertz alone gives δ_o > δ_i for
  this geometry). The equilibrium section below checks the speed effect directly.
* The table's δ_i + δ_o follow the same geometric law if A and α⁰ are those of a smaller
  clearance (P_d ≈ 4.3 µm), but with that clearance the predicted angles drift by up to 0.1°.
  The two halves of Table 2 thus imply different internal geometries (perhaps a
  mounted-clearance or ring-deformation step in the authors' Jones–Harris program that the
  paper does not describe)."""


# ---------------------------------------------------------------------------------------------
# spectra and band values (seed 002 closed forms)
# ---------------------------------------------------------------------------------------------
FIG12 = {"U": 0.46, "R": 60.52, "L": 2.16, "M": 1.46, "H": 1.45, "E": 1.72, "A": 20.52}
FIG13 = {"L": 1.87, "M": 0.75, "H": 0.78}
FIG15 = {"L": 0.57, "M": 0.47, "H": 0.46}
FIG17 = {"L": 1.04, "M": 1.17, "H": 1.13}


@dataclass(frozen=True)
class _Geometry608:
    d_b: float
    d_c: float
    z: int
    cos_a: float


@functools.cache
def _g608() -> _Geometry608:
    b = _load("seed002_608.toml").bearing
    return _Geometry608(b.element_diameter, b.pitch_diameter, b.elements, math.cos(b.contact_angle))


def _waviness(k: int) -> float:
    """Eq. 45–47: 0.1 µm / k^1.5."""
    return 0.1 * UM / k**1.5


def _inner_lines() -> tuple[np.ndarray, np.ndarray]:
    """Eq. 35: eccentricity (order 1), slant (2), waviness nZ±1 at I_{nZ±1}; times cos α."""
    g = _g608()
    f_inner = (1 + g.d_b * g.cos_a / g.d_c) / 2
    orders, amps = [1.0, 2.0], [2.5 * UM, 0.05 * UM]
    for n in range(1, 120):
        for s in (-1, 1):
            k = n * g.z + s
            if 2 <= k < 800:
                orders.append(n * g.z * f_inner + s)
                amps.append(_waviness(k))
    return np.array(orders), np.array(amps) * g.cos_a


def _outer_pairs() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Eq. 37: orders O_nZ and the two waviness amplitudes (nZ−1, nZ+1) behind each line."""
    g = _g608()
    f_cage = (1 - g.d_b * g.cos_a / g.d_c) / 2
    orders, w1, w2 = [], [], []
    for n in range(1, 200):
        a = [_waviness(k) if 2 <= k < 1360 else 0.0 for k in (n * g.z - 1, n * g.z + 1)]
        if a[0] or a[1]:
            orders.append(n * g.z * f_cage)
            w1.append(a[0])
            w2.append(a[1])
    return np.array(orders), np.array(w1) * g.cos_a, np.array(w2) * g.cos_a


def _outer_lines() -> tuple[np.ndarray, np.ndarray]:
    """Expected power of each outer line (random phases)."""
    o, w1, w2 = _outer_pairs()
    return o, np.hypot(w1, w2)


def _ball_lines() -> tuple[np.ndarray, np.ndarray]:
    """Eq. 39, waviness on ball z = 0 only: harmonic 2n gives B_An and B_Bn of (2/Z) W each."""
    g = _g608()
    f_cage = (1 - g.d_b * g.cos_a / g.d_c) / 2
    f_spin = (g.d_c**2 - g.d_b**2 * g.cos_a**2) / (2 * g.d_b * g.d_c)
    orders, amps = [], []
    for n in range(1, 144):
        if 2 * n < 287:
            w = 2.0 / g.z * _waviness(2 * n)
            orders += [2 * n * f_spin + f_cage, 2 * n * f_spin - f_cage]
            amps += [w, w]
    return np.array(orders), np.array(amps) * g.cos_a


def _bands(lines: tuple[np.ndarray, np.ndarray], band: str, printed_edges: bool = False) -> float:
    from runout.spectrum import ANDERON_BANDS, ANDERON_BANDS_PRINTED, anderon_bands_from_lines

    bands = ANDERON_BANDS_PRINTED if printed_edges else ANDERON_BANDS
    return float(anderon_bands_from_lines(*lines, bands)[band])


def _all_lines() -> tuple[np.ndarray, np.ndarray]:
    parts = [_inner_lines(), _outer_lines(), _ball_lines()]
    return np.concatenate([o for o, _ in parts]), np.concatenate([a for _, a in parts])


def _eccentricity(cos_alpha: bool) -> tuple[np.ndarray, np.ndarray]:
    return np.array([1.0]), np.array([2.5 * UM * (_g608().cos_a if cos_alpha else 1.0)])


def _a_band_from_printed() -> float:
    from runout.spectrum import ANDERON_BANDS

    octaves = {b.name: b.octaves for b in ANDERON_BANDS.bands}
    ms = sum(FIG12[b] ** 2 * octaves[b] for b in ("U", "R", "E"))
    return math.sqrt(ms / octaves["A"])


@functools.cache
def _outer_l_draws() -> tuple[float, float, float]:
    """5 %, 95 % of band L over 2000 random phase draws, and the share ≥ the published."""
    from runout.spectrum import ANDERON_BANDS, anderon_bands_from_lines

    o, w1, w2 = _outer_pairs()
    rng = np.random.default_rng(7)
    values = np.empty(2000)
    for i in range(values.size):
        phase = rng.uniform(0.0, 2 * np.pi, o.size)
        amp = np.abs(w1 + w2 * np.exp(1j * phase))
        values[i] = anderon_bands_from_lines(o, amp, ANDERON_BANDS)["L"]
    lo, hi = np.percentile(values, [5, 95])
    return float(lo), float(hi), float(np.mean(values >= FIG15["L"]))


def _spectrum() -> list[Check]:
    f12, f13, f15, f17 = (
        "Seed 002 Fig. 12",
        "Seed 002 Fig. 13, inner ring only",
        "Seed 002 Fig. 15, outer ring only",
        "Seed 002 Fig. 17, ball only",
    )
    out = [
        Check(
            f12,
            "R band (2/3–5/3 wave) of W_i1 cos α = 2.5 µm × cos 10° at order 1",
            FIG12["R"],
            lambda: _bands(_eccentricity(True), "R"),
            "rel",
            0.02,
            reason="the figure matches the same line without cos α (next row); band edges and "
            "leakage do not explain the gap (order 1 is on a bin of the six-revolution DFT)",
        ),
        Check(
            "″",
            "R band of the line without cos α",
            FIG12["R"],
            lambda: _bands(_eccentricity(False), "R"),
            "rel",
            0.02,
            reason="so Fig. 12 did not apply the cos α of eq. 41 to this line",
        ),
        Check(
            "″",
            "A band (1/6–360 wave) recombined from the printed U, R, E values (disjoint bands)",
            FIG12["A"],
            _a_band_from_printed,
            "abs",
            0.01,
            reason="consistent: the R-band rms behind the figure is 2.5 µm/√2, without cos α",
        ),
        Check(
            "″",
            "R band with the edges as printed (0.67–1.67)",
            FIG12["R"],
            lambda: _bands(_eccentricity(True), "R", printed_edges=True),
            "rel",
            0.02,
            reason="the edge choice moves R by only 0.16 %; we keep the exact fractions "
            "(multiples of the 1/6-wave bin of a six-revolution DFT)",
        ),
    ]
    for band, value in FIG13.items():
        out.append(
            Check(
                f13 if band == "L" else "″",
                f"band {band}",
                value,
                _bind(lambda band: _bands(_inner_lines(), band), band),
                "rel",
                0.02,
                reason="two-decimal printing (up to 0.7 %) and the leakage of neighbouring "
                "off-bin lines in the paper's six-revolution DFT (about 1.5 % on L for one draw)",
            )
        )
    for band, value in FIG17.items():
        out.append(
            Check(
                f17 if band == "L" else "″",
                f"band {band}",
                value,
                _bind(lambda band: _bands(_ball_lines(), band), band),
                "rel",
                0.025,
                reason="same reasons; we read W_b0k (eq. 47) as waviness on ball 0 only (on "
                "all seven balls the values would be about 2.7 × larger)",
            )
        )
    for band, value in FIG15.items():
        if band == "L":
            out.append(
                Check(
                    f15,
                    "band L, expected power [5–95 % of 2000 random phase draws]",
                    value,
                    lambda: (_bands(_outer_lines(), "L"), *_outer_l_draws()[:2]),
                    "rel",
                    0.05,
                    spread_from_ours=True,
                    reason="each outer line adds two waviness orders with random phases; we use "
                    "the expected power, the paper one draw. L holds only three lines, so its "
                    "draw cannot be reproduced",
                )
            )
            out.append(
                Check(
                    "″",
                    "share of random draws with L ≥ the published 0.57",
                    None,
                    lambda: _outer_l_draws()[2],
                    "min",
                    0.01,
                    expected="> 1 %",
                    reason="the published value is an ordinary draw",
                )
            )
        else:
            out.append(
                Check(
                    "″",
                    f"band {band}, expected power",
                    value,
                    _bind(lambda band: _bands(_outer_lines(), band), band),
                    "rel",
                    0.05,
                    reason="many lines per band: the random phases average out",
                )
            )
    for band in "LMHEA":
        out.append(
            Check(
                f"{f12}, total" if band == "L" else "″",
                f"band {band}",
                FIG12[band],
                _bind(lambda band: _bands(_all_lines(), band), band),
                "rel",
                0.03,
                reason="the total is the rss of the parts, as Tab. 2 states"
                + ("; A inherits the cos α gap of R" if band == "A" else ""),
            )
        )
    out.append(
        Check(
            f"{f12}, U band (1/6–2/3 wave)",
            "band U of eq. 43–47 (no line below 2/3 wave)",
            FIG12["U"],
            lambda: _bands(_all_lines(), "U"),
            "rel",
            0.03,
            reason="the ball line B_A0 = 0.37 wave would need a ball-size difference W_b00, "
            "which the paper does not give; the value probably comes from such a term or from "
            "the leakage of the paper's DFT",
        )
    )
    return out


SPECTRUM_INTRO = """\
Anderon values of the 608 example of seed 002 (Tab. 1: D = 3.9688 mm, d_c = 15 mm, Z = 7,
α = 10°; deviations eq. 43–47; geometry from `examples/seed002_608.toml`). The lines are
built from the closed forms of seed 002 (eq. 35 inner, eq. 37 outer, eq. 39 ball, amplitudes
times cos α as eq. 41 says) and turned into band values by `anderon_bands_from_lines` (eq. 42
and eq. 1, 1 µin = 25.4 nm, band edges 1/6, 2/3, 5/3, 10, 60, 360, 500 waves). Tests:
`tests/reference/test_anderon_units.py`."""


# ---------------------------------------------------------------------------------------------
# linear model, seed 002 (the paper's six-revolution DFT route, over random phase draws)
# ---------------------------------------------------------------------------------------------
LINEAR_DRAWS = 200
SEED002_FILES = {
    "i": ("seed002_608_fig13_inner.toml", "seed 002 Fig. 13 (inner ring only)"),
    "o": ("seed002_608_fig15_outer.toml", "seed 002 Fig. 15 (outer ring only)"),
    "b": ("seed002_608_fig17_ball.toml", "seed 002 Fig. 17 (ball only)"),
    "iob": ("seed002_608.toml", "seed 002 Tab. 1, eq. 43–47, eq. 48–59, Fig. 12"),
}
BANDS = "URLMHEA"
DFT_REVOLUTIONS, DFT_SAMPLES_PER_REV = 6, 1024


def _seed002_bands(case: Any) -> tuple[dict[str, float], dict[str, float]]:
    """(exact-line values, six-revolution rectangular DFT values) of x [Anderon]."""
    from runout.models import linear as lin
    from runout.spectrum import ANDERON_BANDS, anderon_bands_from_lines, anderon_bands_from_waveform

    b, op = case.bearing, case.operation
    rates = lin.rates(b, op, b.contact_angle)
    terms = lin.closed_form_terms(case.imperfections, rates, b.contact_angle)
    lines = lin.spectral_lines(terms, op.speed, b.elements, op.rotating_ring == "inner")
    keep = lines.order > 0
    exact = anderon_bands_from_lines(lines.order[keep], lines.x_amplitude[keep]).as_dict()
    n = DFT_REVOLUTIONS * DFT_SAMPLES_PER_REV
    _, v, _ = lin.synthesize(lines.derivative(), DFT_REVOLUTIONS, n)
    dft = anderon_bands_from_waveform(v, DFT_SAMPLES_PER_REV, ANDERON_BANDS, density=True)
    return exact, dft.as_dict()


def _reseed(draw: int) -> Callable[[dict[str, Any]], None]:
    def mutate(data: dict[str, Any]) -> None:
        for k, spec in enumerate(data.get("waviness_spectrum", [])):
            spec["seed"] = 1000 * (k + 1) + draw

    return mutate


@functools.cache
def seed002_spread(parts: str, draws: int = LINEAR_DRAWS) -> tuple[np.ndarray, np.ndarray]:
    """(exact, DFT) band values, shape (draws, 7) in the order URLMHEA."""
    name = SEED002_FILES[parts][0]
    exact = np.empty((draws, len(BANDS)))
    dft = np.empty((draws, len(BANDS)))
    for s in range(draws):
        e, d = _seed002_bands(_variant(name, _reseed(s)))
        exact[s] = [e[k] for k in BANDS]
        dft[s] = [d[k] for k in BANDS]
    return exact, dft


def _stat(parts: str, band: str, which: int) -> tuple[float, float, float]:
    values = seed002_spread(parts)[which][:, BANDS.index(band)]
    lo, med, hi = np.percentile(values, [1, 50, 99])
    return float(med), float(lo), float(hi)


def _linear_rows() -> list[Check]:
    out: list[Check] = []
    table = [
        (
            "i",
            "Fig. 13 inner only",
            FIG13,
            0.03,
            "inner-only lines do not depend on the phases; the DFT does, through leakage",
        ),
        (
            "b",
            "Fig. 17 ball only",
            FIG17,
            0.03,
            "cos α: without it the ball column would be 3 % high",
        ),
        ("o", "Fig. 15 outer only", FIG15, 0.03, "random phases: the paper's value is one draw"),
        ("iob", "Fig. 12 all sources", {k: FIG12[k] for k in "LMHERAU"}, 0.03, "random phases"),
    ]
    for parts, title, values, tol, why in table:
        name = _uses(*SEED002_FILES[parts])
        for j, (band, value) in enumerate(values.items()):
            reason = why
            if parts == "iob" and band in "RA":
                reason = "the cos α of eq. 41: without it R would match to 0.1 % (spectrum section)"
            if parts == "iob" and band == "U":
                reason = (
                    "U holds only the B_A0 line (ball size error), whose size the paper does not "
                    "give (W_b00 = 0.1 µm is our guess; 0.117 µm would match)"
                )
            for which, label in ((0, "exact lines"), (1, "6-rev DFT")):
                out.append(
                    Check(
                        f"Seed 002 {title}" if j == 0 and which == 0 else "″",
                        f"band {band}, {label}, median [1–99 %] of {LINEAR_DRAWS} phase draws",
                        value,
                        _bind(
                            lambda parts, band, which: _stat(parts, band, which), parts, band, which
                        ),
                        "rel",
                        tol,
                        spread_from_ours=True,
                        reason=reason,
                        case=name,
                    )
                )
    return out


LINEAR_INTRO = """\
Tests: `tests/reference/test_seed002_anderon.py`, `tests/unit/test_linear.py`,
`tests/property/test_linear_properties.py`. Case `examples/seed002_608.toml` and its
one-part variants: Z = 7, D = 3.9688 mm, d_m = 15 mm, α = 10°, eq. 43–47 (W_i1 2.5 µm, W_s
0.05 µm, 0.1 µm/k^1.5 on inner 2–799, outer 2–1359, ball z = 0 2–286), plus W_b00 = 0.1 µm on
ball z = 0 (our reading, see docs/models/linear.md). Values in Anderon (x direction). "6-rev
DFT" is the paper's route: six revolutions of dx/dθ, 1024 samples per revolution, rectangular
window. Every value is the median over random phase draws (the seeds of the case file
replaced), with the 1 %–99 % range; a published value outside the tolerance but inside that
range is "within the documented spread". Inner-only and ball-only exact lines do not depend on
the phases (one harmonic per line)."""

LINEAR_OUTRO = """\
Why gaps exist: R, A and the inner column sit 1.3–1.6 % low and the ball column 1.4–2.5 %
high. Without the cos α of eq. 41 the inner column and R would match to 0.1 % while the ball
column would be 3 % high, so the paper seems to have applied cos α to the balls but not to the
inner ring; we keep eq. 41 as written."""


def _cross_case(ring: str, model: str) -> Any:
    from runout.case import parse_case

    wav = [
        {"part": "inner", "order": 9, "amplitude": 1e-9, "phase": math.radians(20)},
        {"part": "outer", "order": 7, "amplitude": 1e-9, "phase": math.radians(50)},
        {"part": "ball", "order": 2, "amplitude": 1e-9, "element": 3},
    ]
    case = _load("seed000_tada_table2.toml")
    data = case.spec.model_dump(exclude_none=True)
    data["operation"]["rotating_ring"] = ring
    data["waviness"] = wav
    data["analysis"] = {"model": model, "revolutions": 40, "samples": 8192}
    if model == "linear":
        data["analysis"]["linear_variant"] = "force_balance"
    return parse_case(data, "cross-check")


def _cross_gap(ring: str) -> float:
    from runout.models import linear, quasi_static_3d

    def lines(model: Any, name: str) -> dict[tuple[str, float], float]:
        result = model.run(_cross_case(ring, name))
        return {
            (c.direction, round(c.frequency_hz, 3)): c.pp_m
            for c in result.components
            if c.direction in ("x", "y") and c.pp_m > 1e-11
        }

    lin, qs = lines(linear, "linear"), lines(quasi_static_3d, "quasi_static_3d")
    if len(lin) < 6:
        return math.inf
    return max(abs(qs[k] / v - 1.0) if k in qs else math.inf for k, v in lin.items())


def _cross_rows() -> list[Check]:
    name = _uses("seed000_tada_table2.toml", "seed 000 Table 1 bearing, Table 2 and conclusion 1")
    return [
        Check(
            "linear (force balance) vs quasi_static_3d, 1 nm",
            f"largest relative gap of the radial lines, {ring} ring rotating",
            None,
            _bind(lambda ring: _cross_gap(ring), ring),
            "max",
            2e-3,
            expected="the linearisation error",
            case=name,
        )
        for ring in ("inner", "outer")
    ]


CROSS_INTRO = """\
Tada's standard bearing (`examples/seed000_tada_table2.toml`: Z = 8, D = 1 mm, d_m = 7 mm,
P_d = 10 µm, 20 N) with 1 nm of inner 9-lobe, outer 7-lobe and ball-3 2-lobe waviness; test
`tests/reference/test_cross_linear_vs_quasi_static.py`. Tada's force balance linearised about
the preloaded state is the linear model's `force_balance` variant, so the two models must agree
to the linearisation error."""


# ---------------------------------------------------------------------------------------------
# quasi-static NRRO: seed 000 (Tada, 3-D)
# ---------------------------------------------------------------------------------------------
TADA_PP = 20e-9


def _tada(
    waviness: list[dict[str, Any]],
    *,
    z: int | None = None,
    axial: float | None = None,
    clearance: float | None = None,
    revolutions: float | None = None,
    samples: int | None = None,
    name: str = "seed000_tada_table2.toml",
) -> Any:
    def mutate(data: dict[str, Any]) -> None:
        data["waviness"] = waviness
        if z is not None:
            data["bearing"]["elements"] = z
        if axial is not None:
            data["operation"]["axial_load"] = axial
        if clearance is not None:
            data["bearing"]["radial_clearance"] = clearance
        if revolutions is not None:
            data["analysis"]["revolutions"] = revolutions
        if samples is not None:
            data["analysis"]["samples"] = samples

    return _variant(name, mutate)


def _tada_freqs(case: Any) -> dict[str, float]:
    from runout.kinematics import ball_spin_frequency, cage_frequency
    from runout.models import quasi_static_3d as qs3

    alpha = qs3.setup(case).contact_angle
    b, fr = case.bearing, case.operation.speed
    fc = float(cage_frequency(0.0, fr, b.element_diameter, b.pitch_diameter, alpha))
    fb = float(ball_spin_frequency(0.0, fr, b.element_diameter, b.pitch_diameter, alpha))
    z = b.elements
    return {"f_c": fc, "f_b": fb, "f_r": fr, "f_i": z * fc, "f_o": z * (fr - fc)}


def _line_pp(case: Any, freqs: Sequence[float]) -> np.ndarray:
    """p-p [m] of each frequency in x, y, z: shape (3, len(freqs))."""
    from runout.models import quasi_static_3d as qs3
    from runout.spectrum import extract_lines

    t = qs3.time_grid_of(case)
    disp, _ = qs3.solve(case, t)
    return 2.0 * extract_lines(t, disp, np.asarray(freqs), axis=-1).amplitude


def _tada_table2_row(part: str, lobes: int, n: int, direction: str) -> tuple[float, float]:
    """(main line p-p / waviness p-p, largest other-direction line / main line)."""
    if part == "ball":
        case = _tada([{"part": "ball", "element": 1, "order": lobes, "peak_to_peak": TADA_PP}])
        f = _tada_freqs(case)
        pp = _line_pp(
            case, [lobes * f["f_b"] - f["f_c"], lobes * f["f_b"] + f["f_c"], lobes * f["f_b"]]
        )
        radial = max(pp[0, 0], pp[0, 1])
        axial = pp[2, 2]
        other = max(pp[0, 2], pp[1, 2]) / radial + max(pp[2, 0], pp[2, 1]) / axial
        return min(radial, axial) / TADA_PP, float(other)
    case = _tada([{"part": part, "order": lobes, "peak_to_peak": TADA_PP, "phase": 0.3}])
    f = _tada_freqs(case)
    shift = 0 if (part == "inner" or direction == "z") else (1 if lobes % 8 == 1 else -1)
    freq = n * f["f_i" if part == "inner" else "f_o"] + shift * f["f_r"]
    pp = _line_pp(case, [freq])[:, 0]
    if direction == "xy":
        main = float(np.hypot(pp[0], pp[1]) / math.sqrt(2.0))
        return main / TADA_PP, float(pp[2] / main)
    return float(pp[2] / TADA_PP), float(max(pp[0], pp[1]) / pp[2])


@functools.cache
def _tada_table2_all() -> dict[str, tuple[float, float]]:
    out = {}
    for n in (1, 2):
        for part in ("inner", "outer"):
            for s, d in ((-1, "xy"), (0, "z"), (1, "xy")):
                out[f"{part} {n * 8 + s}"] = _tada_table2_row(part, n * 8 + s, n, d)
        out[f"ball {2 * n}"] = _tada_table2_row("ball", 2 * n, n, "")
    return out


def _tada_conclusion1() -> float:
    from runout.models import quasi_static_3d as qs3

    worst = 0.0
    for axial in (10.0, 20.0, 50.0):
        for z in (6, 8, 12):
            for clearance in (5e-6, 20e-6):
                for part, sign in (("inner", 1), ("outer", -1)):
                    lobes = z + sign
                    wav = [{"part": part, "order": lobes, "peak_to_peak": TADA_PP, "phase": 1.0}]
                    case = _tada(
                        wav, z=z, axial=axial, clearance=clearance, revolutions=16, samples=1024
                    )
                    kin = qs3.setup(case).kinematics
                    f_ring = kin.inner if part == "inner" else kin.outer
                    freq = abs((lobes - sign) * kin.cage - lobes * f_ring)
                    pp = _line_pp(case, [freq])[:, 0]
                    worst = max(worst, abs(pp[0] / TADA_PP - 1), abs(pp[1] / TADA_PP - 1))
    return worst


TADA_CONCLUSION3_AMPLITUDES = (20e-9, 40e-9)


def tada_second_order_lines(z: int, lobes: int, direction: str) -> tuple[int, list[float]]:
    """Seed 000 conclusion 3: the second-order line of one outer waviness at two amplitudes.

    Returns the multiple of Z at which it falls, (2 lobes ± 1 or 2 lobes), and its p-p [m]
    for :data:`TADA_CONCLUSION3_AMPLITUDES` (x for ``direction="xy"``, z for ``"z"``).
    """
    from runout.models import quasi_static_3d as qs3

    lines = []
    multiple = 0
    for a in TADA_CONCLUSION3_AMPLITUDES:
        case = _tada(
            [{"part": "outer", "order": lobes, "peak_to_peak": a}],
            z=z,
            revolutions=32,
            samples=2048,
        )
        kin = qs3.setup(case).kinematics
        lk = 2 * lobes
        m = 0 if direction == "z" else (-1 if (lk - 1) % z == 0 else 1)
        multiple = lk + m
        freq = abs(multiple * kin.cage - lk * kin.outer)
        pp = _line_pp(case, [freq])[:, 0]
        lines.append(float(pp[2] if direction == "z" else pp[0]))
    return multiple, lines


def _tada_conclusion3(z: int, lobes: int, direction: str) -> float:
    """Exponent of the second-order line's growth with the waviness amplitude (2 expected)."""
    _, lines = tada_second_order_lines(z, lobes, direction)
    amps = TADA_CONCLUSION3_AMPLITUDES
    return math.log(lines[1] / lines[0]) / math.log(amps[1] / amps[0])


# (a7, ϑ7 [deg], a9, ϑ9 [deg], printed inclination φ [deg], Tada clockwise)
TADA_FIG6 = [
    (0.25, 0, 0.25, 0, 0),
    (0.25, 0, 0.5, 30, 135),
    (0.25, 0, 0.75, 60, 90),
    (0.25, 0, 1.0, 90, 45),
    (0.5, 30, 0.25, 0, 75),
    (0.5, 30, 0.5, 30, 30),
    (0.5, 30, 0.75, 60, 165),
    (0.5, 30, 1.0, 90, 120),
    (1.0, 90, 0.25, 0, 45),
    (1.0, 90, 0.5, 30, 0),
    (1.0, 90, 0.75, 60, 135),
    (1.0, 90, 1.0, 90, 90),
]


@functools.cache
def _tada_fig6_cell(i: int) -> tuple[float, float, float]:
    """(major-axis error, minor-axis error (relative to the 20 nm unit), inclination [deg])."""
    from runout.models import quasi_static_3d as qs3
    from runout.spectrum import extract_lines

    a7, t7, a9, t9, _ = TADA_FIG6[i]
    wav = [
        {"part": "inner", "order": 7, "peak_to_peak": a7 * TADA_PP, "phase": math.radians(7 * t7)},
        {"part": "inner", "order": 9, "peak_to_peak": a9 * TADA_PP, "phase": math.radians(9 * t9)},
    ]
    case = _tada(wav, name="seed000_tada_fig6.toml")
    t = qs3.time_grid_of(case)
    disp, _ = qs3.solve(case, t)
    fit = extract_lines(t, disp[:2], np.array([_tada_freqs(case)["f_i"]]), axis=-1)
    amp, ph = fit.amplitude[:, 0], fit.phase[:, 0]
    m = np.array([[a * math.cos(p), -a * math.sin(p)] for a, p in zip(amp, ph, strict=True)])
    u, sv, _ = np.linalg.svd(m)
    major = abs(2 * sv[0] / ((a7 + a9) * TADA_PP) - 1)
    minor = abs(2 * sv[1] - abs(a7 - a9) * TADA_PP) / TADA_PP
    incl = (-math.degrees(math.atan2(u[1, 0], u[0, 0]))) % 180.0
    return float(major), float(minor), incl


def _angle_to(printed: float, value: float) -> float:
    """``value`` unwrapped (mod 180°) to the branch nearest ``printed``."""
    return printed + ((value - printed + 90.0) % 180.0 - 90.0)


def _tada_rows() -> list[Check]:
    name = _uses("seed000_tada_table2.toml", "seed 000 Table 1 bearing, Table 2 and conclusion 1")
    fig6 = _uses("seed000_tada_fig6.toml", "seed 000 §3.2 / Fig. 6 ellipses (12 cells)")
    out: list[Check] = []
    labels = {-1: "nZ−1", 0: "nZ", 1: "nZ+1"}
    for n in (1, 2):
        for part in ("inner", "outer"):
            for s in (-1, 0, 1):
                key = f"{part} {n * 8 + s}"
                where = "z" if s == 0 else "x, y"
                out.append(
                    Check(
                        f"Seed 000 Table 2, {part} {labels[s]} (n = {n}, {n * 8 + s} lobes)",
                        f"line in {where} only: other direction / line",
                        None,
                        _bind(lambda key: _tada_table2_all()[key][1], key),
                        "max",
                        1e-3,
                        expected=f"{where} only",
                        case=name,
                    )
                )
        key = f"ball {2 * n}"
        out.append(
            Check(
                f"Seed 000 Table 2, ball 2n (n = {n})",
                "x, y at 2n f_b ± f_c and z at 2n f_b only: other direction / line (sum)",
                None,
                _bind(lambda key: _tada_table2_all()[key][1], key),
                "max",
                2e-3,
                expected="no cross-talk",
                case=name,
            )
        )
    out.append(
        Check(
            "Seed 000 conclusion 1",
            "radial first-order line of nZ±1 waviness / waviness p-p − 1, largest over F_a "
            "10/20/50 N, Z 6/8/12, P_d 5/20 µm, inner and outer",
            None,
            _tada_conclusion1,
            "max",
            1e-6,
            expected="0 (line = waviness p-p)",
            reason="exact: each ball's approach stays at the preload approach, so the Hertz "
            "exponent never acts",
            case=name,
        )
    )
    for z, lobes, d in ((9, 5, "xy"), (9, 4, "xy"), (8, 4, "z")):
        out.append(
            Check(
                "Seed 000 conclusion 3 / Fig. 3",
                f"growth exponent of the second-order line, Z = {z}, outer {lobes} lobes "
                f"({'radial' if d == 'xy' else 'axial'}), 20 → 40 nm",
                2.0,
                _bind(lambda z, lobes, d: _tada_conclusion3(z, lobes, d), z, lobes, d),
                "abs",
                0.01,
                case=name,
            )
        )
    for i, (a7, t7, a9, t9, printed) in enumerate(TADA_FIG6):
        out.append(
            Check(
                f"Seed 000 Fig. 6, a₇ = {a7}, ϑ₇ = {t7}°, a₉ = {a9}, ϑ₉ = {t9}°",
                "major-axis inclination φ [°]",
                float(printed),
                _bind(lambda i, printed: _angle_to(printed, _tada_fig6_cell(i)[2]), i, printed),
                "abs",
                1e-3,
                reason="eq. 8 was lost in extraction; reconstructed as φ = ((Z+1)·ϑ(Z+1) − "
                "(Z−1)·ϑ(Z−1))/2 (mod 180°)"
                if i == 0
                else "—",
                case=fig6,
            )
        )
    out.append(
        Check(
            "Seed 000 §3.2 / Fig. 6, 12 cells",
            "ellipse axes: largest error of major = sum, minor = difference (relative)",
            None,
            lambda: max(max(_tada_fig6_cell(i)[:2]) for i in range(len(TADA_FIG6))),
            "max",
            1e-6,
            expected="0",
            case=fig6,
        )
    )
    return out


TADA_INTRO = """\
Outer ring rotating at 5400 rpm, constant-pressure preload 20 N, d_m = 7 mm, D = 1 mm, Z = 8,
E = 208 GPa, ν = 0.3, P_d = 10 µm. **The paper gives no groove conformities; we use 0.52
(inner) / 0.53 (outer).** Inputs are peak-to-peak as in the paper (20 nm). Tada's eq. 1
(waviness functions) is missing from the extraction; we derive it from the kinematics (module
docstring). Line amplitudes are fitted at the predicted frequencies
(`runout.spectrum.extract_lines`, no leakage). Tests: `tests/reference/test_seed000_tada.py`."""


# ---------------------------------------------------------------------------------------------
# quasi-static NRRO: seed 001 (Kim, 2-D), Tables 4-8
# ---------------------------------------------------------------------------------------------
KIM_TABLE4 = {7: 54.02, 8: 47.75, 9: 42.72, 10: 38.60, 11: 35.18, 12: 32.30}
#: Table 4 at Z = 10, the 2 f_b - f_c and 2 f_b + f_c columns [nm]
KIM_TABLE4_FORM_Z10 = (7.20, 6.77)
#: Tables 5-8 (Z = 10): oversize balls -> (table, f_c, 2 f_b - f_c, 2 f_b + f_c) [nm]
KIM_TABLES5_8 = {
    (1, 2): ("Table 5", 74.38, 13.68, 12.86),
    (1, 3): ("Table 5", 63.34, 11.63, 10.94),
    (1, 4): ("Table 5", 46.12, 8.45, 7.96),
    (1, 5): ("Table 5", 24.41, 4.44, 4.19),
    (1, 2, 3): ("Table 6", 102.84, 18.82, 17.70),
    (1, 3, 5): ("Table 6", 63.87, 11.62, 10.96),
    (1, 4, 7): ("Table 6", 15.69, 2.59, 2.59),
    (1, 5, 9): ("Table 6", 23.50, 4.45, 4.19),
    (1, 2, 3, 4): ("Table 7", 121.20, 22.11, 20.85),
    (1, 3, 5, 7): ("Table 7", 40.08, 7.19, 6.78),
    (1, 2, 3, 4, 5): ("Table 8", 127.72, 23.24, 20.85),
    (1, 2, 4, 5, 8): ("Table 8", 48.80, 8.88, 8.37),
}
KIM_SYMMETRIC = [(1, 6), (1, 4, 6, 9), (1, 2, 6, 7), (1, 3, 5, 7, 9)]
#: f_c value the paper prints for every balanced arrangement [nm]
KIM_FLOOR = 0.99
#: Radius amplitude of the order-2 ball waviness used for the form-error columns [m]: our
#: estimate from Table 4 (Z = 10): 2 f_b ± f_c p-p ≈ 4 a_2 / Z ≈ 7 nm. Only ratios between
#: arrangements are compared, and those do not depend on it.
KIM_FORM_AMPLITUDE = 18e-9
#: Rows whose printed form-error entry repeats a neighbouring number: (balls, column) -> why
KIM_FORM_SLIPS = {
    ((1, 4, 7), 0): "the printed 2.59 repeats the 2 f_b + f_c entry beside it",
    ((1, 2, 3, 4, 5), 1): "the printed 20.85 repeats Table 7's (1,2,3,4) entry",
}


def _kim_case(name: str, z: int, balls: tuple[int, ...], *, size: bool, form: bool) -> Any:
    def mutate(data: dict[str, Any]) -> None:
        data["bearing"]["elements"] = z
        data["elements"] = {
            "diameter_errors": [0.1 * UM if size and k + 1 in balls else 0.0 for k in range(z)]
        }
        data["waviness"] = (
            [
                {"part": "ball", "order": 2, "amplitude": KIM_FORM_AMPLITUDE, "element": k}
                for k in balls
            ]
            if form
            else []
        )
        if form:  # a longer record: the lines sit among small nonlinear products
            data["analysis"].update(revolutions=32, samples=8192)

    return _variant(name, mutate)


@functools.cache
def kim_lines(name: str, z: int, balls: tuple[int, ...], form: bool = False) -> np.ndarray:
    """Phasors [nm p-p] of x at f_c, 2 f_b − f_c, 2 f_b + f_c (2-D model, leakage-free fit).

    ``form=False``: the balls carry the 0.1 µm size error only; ``form=True``: the order-2
    waviness only (y is the same whirl, so x says it all). The phase is that of
    x = Σ A cos(2π f t + φ), t = 0 when ball 1 is at θ = 0 (seed 001 eq. 8).
    """
    from runout.models import quasi_static_2d as qs2
    from runout.spectrum import extract_lines

    case = _kim_case(name, z, balls, size=not form, form=form)
    st = qs2.setup(case)
    kin = st.kinematics
    revs, n = case.analysis.revolutions, case.analysis.samples
    t = np.arange(n) * (revs / case.operation.speed) / n
    disp, _ = qs2.solve(case, t, st)
    freqs = np.array([kin.cage, 2 * kin.spin - kin.cage, 2 * kin.spin + kin.cage])
    fit = extract_lines(t, disp[0], freqs)
    return np.asarray(2e9 * fit.amplitude * np.exp(1j * fit.phase))


def kim_fc_pp_nm(name: str, z: int, balls: tuple[int, ...]) -> float:
    """f_c line p-p [nm] of the 2-D model (x; y is the same circle)."""
    return float(abs(kim_lines(name, z, balls)[0]))


@functools.cache
def kim_cage_hz(name: str, z: int) -> float:
    """f_c [Hz] of the Table 1 bearing with ``z`` balls (eq. 7 at the loaded angle)."""
    from runout.models import quasi_static_2d as qs2

    return float(qs2.setup(_kim_case(name, z, (1,), size=True, form=False)).kinematics.cage)


@dataclass(frozen=True)
class FftReading:
    """How a paper read its lines: a Hann FFT of a record, plus a constant line (its floor).

    ``read(f, line)`` is what the paper's spectrum shows at its bin nearest ``f`` for a true
    line phasor ``line``: :func:`runout.spectrum.peak_bin_gain` × |line + floor|.

    Attributes
    ----------
    duration : float
        Record length T [s].
    floor : complex
        Phasor [nm p-p] of a component at the same frequency present in every run, whatever
        the ball errors (what the paper prints for a balanced set).
    misfit : float
        Largest relative misfit over the rows it was identified from [-].
    rows : int
        Number of published values it was identified from.
    """

    duration: float
    floor: complex
    misfit: float
    rows: int

    def read(self, frequency: float, line: complex) -> float:
        from runout.spectrum import peak_bin_gain

        gain = float(peak_bin_gain(frequency, self.duration))
        return gain * abs(line + self.floor)


def identify_fft_reading(
    frequency: np.ndarray,
    line: np.ndarray,
    published: np.ndarray,
    floor_frequency: float,
    floor_reading: float,
) -> FftReading:
    """Record length and floor phase that best turn exact lines into published readings.

    The floor's size is not fitted: it is what the paper prints where the true lines cancel
    (``floor_reading``, read at ``floor_frequency``), so |floor| = floor_reading / G(T). The
    record length T and the floor's phase minimise Σ (read_i / published_i − 1)²: a grid of
    2 ms from 0.25 s to 4 s × 1° (global), then a joint least-squares refinement. Two
    parameters; use it on many more rows than that. Record lengths one period of the line
    apart (≈ 1/f) fit almost equally: what is identified is where each line falls between
    two bins.
    """
    from scipy.optimize import least_squares

    from runout.spectrum import peak_bin_gain

    def floor_size(T: float, samples: int = 8192) -> np.ndarray:
        return floor_reading / peak_bin_gain(np.asarray(floor_frequency), T, samples=samples)

    grid = np.arange(0.25, 4.0, 0.002)
    phases = np.radians(np.arange(0.0, 360.0, 1.0))
    gain = np.stack([peak_bin_gain(frequency, T, samples=256) for T in grid])  # (nT, m)
    size = np.array([floor_size(T, 256) for T in grid])  # (nT,)
    floor = size[:, None, None] * np.exp(1j * phases)[None, :, None]  # (nT, nφ, 1)
    read = gain[:, None, :] * np.abs(line[None, None, :] + floor)
    cost = ((read / published - 1.0) ** 2).sum(axis=-1)  # (nT, nφ)

    def residual(p: np.ndarray) -> np.ndarray:
        g = peak_bin_gain(frequency, p[0])
        f = floor_size(p[0]) * np.exp(1j * p[1])
        return np.asarray(g * np.abs(line + f) / published - 1.0)

    best = None
    for flat in np.argsort(cost, axis=None)[:5]:
        i, j = np.unravel_index(flat, cost.shape)
        fit = least_squares(residual, [grid[i], phases[j]], x_scale=[1e-3, 1e-2])
        if best is None or fit.cost < best.cost:
            best = fit
    assert best is not None
    T, phase = best.x
    floor_at = complex(floor_size(T) * np.exp(1j * phase))
    return FftReading(float(T), floor_at, float(np.abs(residual(best.x)).max()), line.size)


@functools.cache
def kim_fft_reading() -> FftReading:
    """The reading of seed 001's f_c column, identified from Table 4 and Tables 5–8 (18 rows).

    The floor's size is the 0.99 nm printed for the balanced arrangements (at Z = 10).
    """
    t4, t58 = "seed001_kim_table4.toml", "seed001_kim_tables5_8.toml"
    rows = [(kim_cage_hz(t4, z), kim_lines(t4, z, (1,))[0], v) for z, v in KIM_TABLE4.items()]
    rows += [
        (kim_cage_hz(t58, 10), kim_lines(t58, 10, balls)[0], entry[1])
        for balls, entry in KIM_TABLES5_8.items()
    ]
    f, line, pub = (np.array(c) for c in zip(*rows, strict=True))
    return identify_fft_reading(f, line, pub, kim_cage_hz(t58, 10), KIM_FLOOR)


def kim_read_nm(name: str, z: int, balls: tuple[int, ...]) -> float:
    """Our f_c line as seed 001's spectrum would have shown it [nm p-p]."""
    return kim_fft_reading().read(kim_cage_hz(name, z), kim_lines(name, z, balls)[0])


def kim_form_ratio(balls: tuple[int, ...], column: int) -> float:
    """Our 2 f_b ∓ f_c line of an arrangement over that of ball 1 alone (order-2 waviness)."""
    name = "seed001_kim_tables5_8.toml"
    lines, one = kim_lines(name, 10, balls, True), kim_lines(name, 10, (1,), True)
    return float(abs(lines[1 + column]) / abs(one[1 + column]))


def _kim_rows() -> list[Check]:
    t4 = _uses("seed001_kim_table4.toml", "seed 001 Table 4 (Z = 7…12 in code)")
    t58 = _uses("seed001_kim_tables5_8.toml", "seed 001 Tables 5–8 (arrangements in code)")
    out: list[Check] = []
    exact_gap = "exact line; the paper's FFT reads it low (rows “as read”, text below)"
    for z, value in KIM_TABLE4.items():
        out.append(
            Check(
                f"Seed 001 Table 4, Z = {z}",
                "f_c p-p, one ball +0.1 µm: exact line [nm]",
                value,
                _bind(lambda z: kim_fc_pp_nm(t4, z, (1,)), z),
                "rel",
                0.03,
                reason=exact_gap if z == 7 else "″",
                case=t4,
            )
        )
        out.append(
            Check(
                f"Seed 001 Table 4, Z = {z}",
                "same, as the paper's FFT reads it [nm]",
                value,
                _bind(lambda z: kim_read_nm(t4, z, (1,)), z),
                "rel",
                0.005,
                case=t4,
            )
        )
    for balls, (table, value, *_form) in KIM_TABLES5_8.items():
        where = f"Seed 001 {table}, balls {','.join(map(str, balls))}"
        reason = "—"
        if balls == (1, 5, 9):
            reason = (
                "exact line; the paper's 1 nm floor lowers this arrangement's reading "
                "(rows “as read”)"
            )
        out.append(
            Check(
                where,
                "f_c p-p: exact line [nm]",
                value,
                _bind(lambda balls: kim_fc_pp_nm(t58, 10, balls), balls),
                "rel",
                0.03,
                reason=reason,
                case=t58,
            )
        )
        out.append(
            Check(
                where,
                "same, as the paper's FFT reads it [nm]",
                value,
                _bind(lambda balls: kim_read_nm(t58, 10, balls), balls),
                "rel",
                0.005,
                case=t58,
            )
        )
    out.append(
        Check(
            "Seed 001 Table 6, balls 1,5,9 (linear superposition)",
            "f_c(1,5,9) / f_c(1) over |1 + exp(i·144°) + exp(i·288°)| = 0.618",
            1.0,
            lambda: kim_fc_pp_nm(t58, 10, (1, 5, 9)) / kim_fc_pp_nm(t58, 10, (1,)) / 0.618034,
            "rel",
            0.01,
            reason="our nonlinear model follows superposition",
            case=t58,
        )
    )
    for balls in KIM_SYMMETRIC:
        out.append(
            Check(
                f"Seed 001 Tables 5, 7, 8, balls {','.join(map(str, balls))} (balanced)",
                "f_c p-p: exact line [nm]",
                None,
                _bind(lambda balls: kim_fc_pp_nm(t58, 10, balls), balls),
                "max",
                1e-3,
                expected=f"{KIM_FLOOR} (the floor of the paper's spectrum)",
                reason="a balanced set cancels exactly",
                case=t58,
            )
        )
    one = dict(zip((0, 1), KIM_TABLE4_FORM_Z10, strict=True))
    for balls, (table, _fc, *form) in KIM_TABLES5_8.items():
        for column, label in ((0, "2 f_b − f_c"), (1, "2 f_b + f_c")):
            out.append(
                Check(
                    f"Seed 001 {table}, balls {','.join(map(str, balls))}",
                    f"{label} line / one ball's (Table 4, Z = 10), order-2 ball waviness",
                    form[column] / one[column],
                    _bind(kim_form_ratio, balls, column),
                    "rel",
                    0.01,
                    reason=KIM_FORM_SLIPS.get((balls, column), "—"),
                    case=t58,
                )
            )
    return out


KIM_INTRO = """\
Bearing of Table 1 at 7200 rpm, axial preload 60.68 N (fitted to Table 2's 18.73° at Z = 10);
δ_0 = (δ_i + δ_o)/2 from the axial-load solution. Convention that reproduces the tables: the
0.1 µm size error is on the **diameter** and the tabulated component is **peak-to-peak** (on
the radius, or as a single amplitude, every value is off by a factor 2). Eq. 10 is implemented
as printed (no cos α on the deviations). "Exact line" rows are our leakage-free line; "as the
paper's FFT reads it" rows pass the same line through the paper's reading identified below.
The tables also contain the ball's measured waviness (Fig. 10, not extracted); it does not
feed the f_c line, and the form-error rows compare ratios between arrangements, which do not
depend on its size. Tests: `tests/reference/test_seed001_kim_nrro.py`."""


def kim_outro() -> str:
    """The explanation under the Kim table, with the identified reading computed."""
    r = kim_fft_reading()
    t58 = "seed001_kim_tables5_8.toml"
    gain = r.read(kim_cage_hz(t58, 10), 0j) / abs(r.floor)
    floor_pp, floor_deg = abs(r.floor), math.degrees(math.atan2(r.floor.imag, r.floor.real))
    # one ball's f_c line that each Table 6 row implies under superposition, at the 3 % limits
    s147 = abs(sum(np.exp(2j * np.pi * (k - 1) / 10) for k in (1, 4, 7)))
    s159 = abs(sum(np.exp(2j * np.pi * (k - 1) / 10) for k in (1, 5, 9)))
    need_147 = 0.97 * KIM_TABLES5_8[(1, 4, 7)][1] / s147
    need_159 = 1.03 * KIM_TABLES5_8[(1, 5, 9)][1] / s159
    t4 = "seed001_kim_table4.toml"
    above = [kim_fc_pp_nm(t4, z, (1,)) / v - 1 for z, v in KIM_TABLE4.items()]
    off58 = max(abs(kim_fc_pp_nm(t58, 10, b) / e[1] - 1) for b, e in KIM_TABLES5_8.items())
    sup = abs(kim_fc_pp_nm(t58, 10, (1, 5, 9)) / kim_fc_pp_nm(t58, 10, (1,)) / s159 - 1)
    return f"""\
**How the paper read its f_c column.** Our exact lines are {100 * min(above):.1f} to
{100 * max(above):.1f} % above Table 4 and up to {100 * off58:.1f} % off single rows of
Tables 5–8, and no model that obeys superposition (ours does, to {100 * sup:.1f} %) can meet
them all: within 3 %, Table 6 (1,4,7) needs one ball's line ≥ {need_147:.2f} nm and (1,5,9)
needs it ≤ {need_159:.2f} nm. The printed numbers are readings of an FFT, and two
properties of that reading explain all of them:

* **a component of about 1 nm at f_c present in every run** — it is what the paper prints
  for the balanced sets (0.99 nm), where the balls' own f_c lines cancel exactly. Added to the
  true line it raises or lowers a reading by up to 1 nm depending on the arrangement's phase:
  this is why (1,4,7) reads high and (1,5,9) low;
* **a Hann window on a finite record**: the f_c line falls between two bins and is read low
  by the scalloping loss (`runout.spectrum.peak_bin_gain`). f_c moves with the contact angle
  of each Z (Table 2), so the loss changes with Z: this is the Z-trend of Table 4.

Identification (`runout.reproduce.identify_fft_reading`): the floor's size is taken from the
balanced rows (0.99 nm as read, i.e. {floor_pp:.3f} nm p-p before the window); the record
length and the floor's phase are fitted by least squares to the {r.rows} other published f_c
values of Table 4 and Tables 5–8: T = {r.duration:.4f} s (records one f_c period, ≈ 0.02 s,
longer or shorter fit almost as well: what is pinned is where f_c falls between bins; the
Hann gain at Z = 10 is {gain:.4f}) and a floor phase of {floor_deg:.1f}° (phase of x at t = 0,
ball 1 at θ = 0). Two parameters for {r.rows} numbers: largest misfit {100 * r.misfit:.2f} %.
With this reading our model reproduces every f_c value of Tables 4–8 to better than 0.5 %;
the exact lines (our output) stay the physical values.

The paper does not say what causes its floor; a constant line at the cage frequency
independent of the ball errors is not physical (every balanced set is symmetric), so we do not
model it. The 2 f_b ± f_c columns of Tables 5–8 follow superposition of one ball's lines (our
ratios, order-2 waviness on the same balls) except two entries that repeat a neighbouring
number. Table 4's 2 f_b ± f_c columns (how they change with Z) are not compared: they depend on
the measured ball waviness of Fig. 10, which the paper gives only as a plot, and a Hann record
alone does not reproduce their Z-trend."""


# ---------------------------------------------------------------------------------------------
# equilibrium (Jones-Harris), seed 001 Table 2 at speed
# ---------------------------------------------------------------------------------------------
@functools.cache
def _kim_equilibrium(z: int, speed_factor: float = 1.0) -> tuple[float, float]:
    from runout.bearing import Operation
    from runout.models.equilibrium import solve_equilibrium

    def mutate(data: dict[str, Any]) -> None:
        data["bearing"]["elements"] = z

    case = _variant("seed001_kim_equilibrium.toml", mutate)
    op = case.operation
    sol = solve_equilibrium(
        case.bearing,
        Operation(op.rotating_ring, op.speed * speed_factor, axial_load=op.axial_load),
        race_control=case.analysis.race_control,
    )
    return float(np.degrees(sol.inner_contact_angle[0])), float(
        np.degrees(sol.outer_contact_angle[0])
    )


def _equilibrium_rows() -> list[Check]:
    name = _uses("seed001_kim_equilibrium.toml", "seed 001 §2.1, Table 2 at 7200 rpm (Z in code)")
    out: list[Check] = []
    for z, (alpha, _, _) in KIM_TABLE2.items():
        for i, ring in enumerate(("inner", "outer")):
            out.append(
                Check(
                    f"Seed 001 Table 2, Z = {z}" if i == 0 else "″",
                    f"α_{ring[0]} at 7200 rpm [°]",
                    alpha,
                    _bind(lambda z, i: _kim_equilibrium(z)[i], z, i),
                    "abs",
                    0.05,
                    reason="the preload is fitted here, statically" if z == 10 and i == 0 else "—",
                    case=name,
                )
            )
    out.append(
        Check(
            "Jones–Harris (theory)",
            "α_i − α_o at 2 × speed over α_i − α_o at 7200 rpm (centrifugal force ∝ speed²)",
            4.0,
            lambda: (lambda a, b: (a[0] - a[1]) / (b[0] - b[1]))(
                _kim_equilibrium(10, 2.0), _kim_equilibrium(10)
            ),
            "rel",
            0.01,
            case=name,
        )
    )
    return out


EQUILIBRIUM_INTRO = """\
Case `examples/seed001_kim_equilibrium.toml` (the number of balls changed in code), F_a =
60.68 N. At 7200 rpm the centrifugal force opens the inner angle and closes the outer one by a
few thousandths of a degree, so Table 2 stays matched. Tests:
`tests/reference/test_seed001_kim_equilibrium.py` (also: at speed → 0 the solution equals
`runout.loading.axial_loading`; the stiffness matrix equals central differences of the
re-solved ring forces). The deflections keep the static gap to Table 2 (contact section): speed
cannot explain it."""


# ---------------------------------------------------------------------------------------------
# rigid constraint model, seed 004 (NU209)
# ---------------------------------------------------------------------------------------------
@functools.cache
def _roller(name: str) -> Any:
    from runout.models import roller_constraint as rc

    case = _load(name)
    alpha = rc.rotation_angles(case.analysis.revolutions, case.analysis.samples)
    return rc.solve(rc.geometry_from(case.bearing, case.imperfections, case.operation), alpha)


def _roller_eq17() -> float:
    from runout import RollerBearing
    from runout.imperfections import Imperfections
    from runout.models import roller_constraint as rc

    b = _load("seed004_nu209.toml").bearing
    worst = 0.0
    for clearance in (0.031e-3, 0.041e-3, 0.050e-3):
        d_i = b.outer_raceway_diameter - 2 * b.element_diameter - clearance
        bearing = RollerBearing(b.elements, b.element_diameter, d_i, b.outer_raceway_diameter)
        alpha = rc.rotation_angles(1.0, 1441)
        sol = rc.solve(rc.geometry_from(bearing, Imperfections.perfect(b.elements)), alpha)
        ref = rc.analytic_circular(
            d_i, b.outer_raceway_diameter, b.element_diameter, b.elements, alpha
        )
        worst = max(worst, float(np.max(np.abs(sol.centre[:, 1] - ref[:, 1]) / np.abs(ref[:, 1]))))
    return worst


@functools.cache
def _roller_ellipse(semi_minor: float) -> tuple[float, float]:
    """(ours vs exact, eq. 18–21 vs exact): largest relative distance."""
    from runout import RollerBearing
    from runout.imperfections import Imperfections
    from runout.models import roller_constraint as rc

    b = _load("seed004_nu209.toml").bearing
    z, dw, de = b.elements, b.element_diameter, b.outer_raceway_diameter
    a = 27.4955e-3
    mean, harm = rc.ellipse_harmonics(a, semi_minor)
    bearing = RollerBearing(z, dw, 2 * a, de)
    geo = rc.geometry_from(bearing, Imperfections.perfect(z)).replace(inner_radius=mean, inner=harm)
    alpha = rc.rotation_angles(1.0, 97)
    ours = rc.solve(geo, alpha).centre
    exact = np.array([rc.ellipse_position_exact(a, semi_minor, de, dw, z, x) for x in alpha])
    paper = np.array([rc.ellipse_position_paper(a, semi_minor, de, dw, z, x) for x in alpha])
    scale = np.abs(exact[:, 1])
    return (
        float(np.max(np.linalg.norm(ours - exact, axis=1) / scale)),
        float(np.max(np.linalg.norm(paper - exact, axis=1) / scale)),
    )


def _roller_rows() -> list[Check]:
    figs = {
        "seed004_nu209.toml": ("Fig. 9", "inner raceway 1 µm, 10 lobes", 2.14, "—"),
        "seed004_nu209_fig10.toml": (
            "Fig. 10",
            "outer raceway 1 µm, 12 lobes",
            1.44,
            "the text prints max and min the other way round",
        ),
        "seed004_nu209_fig11.toml": (
            "Fig. 11",
            "every roller 0.5 µm, 8 lobes",
            1.98,
            "the paper's eq. 2 spin (4× the relative spin) gives nearly the same runout, so the "
            "spin reading is not the cause; the paper's Δθ sampling and search step are",
        ),
        "seed004_nu209_fig12.toml": (
            "Fig. 12",
            "rollers 0.5 µm/15, inner 1 µm/8, outer 1 µm/18, 1 µm size errors (phases 0, "
            "diameter errors +)",
            5.186,
            "a roller touches both raceways at the two ends of one diameter, where an odd lobe "
            "count (15) cancels; the paper reads the roller's deviation at the same angle at "
            "both contacts, so that it adds up: read that way (next rows) all three printed "
            "numbers are reproduced",
        ),
    }
    out = [
        Check(
            "Seed 004 §6.1, eq. 17",
            "circular parts, P_d = 0.031 / 0.041 / 0.050 mm: largest relative gap to eq. 17",
            None,
            _roller_eq17,
            "max",
            1e-10,
            expected="the paper's model: ≤ 0.097 %",
            reason="the paper's stepped search limits it; ours is at double-precision rounding",
        )
    ]
    for semi_minor in (27.4905e-3, 27.492e-3, 27.4935e-3):
        out.append(
            Check(
                f"Seed 004 §6.2, ellipse a = 27.4955 mm, b = {semi_minor * 1e3:.5g} mm",
                "largest relative gap to the exact closest distance (parallel curve)",
                None,
                _bind(lambda s: _roller_ellipse(s)[0], semi_minor),
                "max",
                1e-9,
                expected="the paper's model vs eq. 18–21: ≤ 0.15 %",
            )
        )
        out.append(
            Check(
                "″",
                "eq. 18–21 vs the exact closest distance (second-order, between 1e-9 and 1e-3)",
                None,
                _bind(lambda s: _roller_ellipse(s)[1], semi_minor),
                "max",
                1e-3,
                expected="—",
                reason="eq. 18–21 measure the ellipse along the line of centres (polar radius), "
                "which is not the closest distance",
            )
        )
    for name, (fig, what, value, reason) in figs.items():
        use = _uses(name, f"seed 004 Table 1 NU209, {fig}")
        out.append(
            Check(
                f"Seed 004 {fig}",
                f"runout [µm], {what}",
                value,
                _bind(lambda name: float(_roller(name).runout) / UM, name),
                "rel",
                0.03,
                reason=reason,
                case=use,
            )
        )
    use = _uses("seed004_nu209_fig12.toml", "seed 004 Table 1 NU209, Fig. 12")
    for label, index, value, tol in (
        ("runout [µm]", 0, 5.186, 0.03),
        ("largest radial position of the inner ring [µm]", 1, 21.86, 0.02),
        ("smallest radial position of the inner ring [µm]", 2, 16.68, 0.02),
    ):
        out.append(
            Check(
                "Seed 004 Fig. 12, as the paper computed it",
                f"{label}, the roller's deviation read at the outer contact's angle at both "
                'contacts (`roller_contacts = "same_angle"`)',
                value,
                _bind(lambda i: _roller_fig12_paper()[i], index),
                "rel",
                tol,
                reason="the paper's reading of an odd roller lobe count; the physical reading "
                "(row above) lets it cancel across the diameter",
                case=use,
            )
        )
    return out


@functools.lru_cache(maxsize=1)
def _roller_fig12_paper() -> tuple[float, float, float]:
    """Fig. 12 read as seed 004 does: (runout, largest, smallest position along the load) [µm]."""
    from runout.models import roller_constraint as rc

    case = _load("seed004_nu209_fig12.toml")
    geo = rc.geometry_from(case.bearing, case.imperfections, case.operation)
    alpha = rc.rotation_angles(case.analysis.revolutions, case.analysis.samples)
    sol = rc.solve(geo.replace(roller_contacts="same_angle"), alpha)
    r = sol.radial
    return float(sol.runout) / UM, float(r.max()) / UM, float(r.min()) / UM


ROLLER_INTRO = """\
Source: seed 004 (Yu et al. 2017), NU209 of Table 1 (d_i 54.991 mm, d_e 75.032 mm, D_w 10 mm,
Z 14, P_d 41 µm), inner ring turning, measuring load along −y. Tests:
`tests/reference/test_seed004_nu209.py`, `tests/unit/test_roller_constraint.py`. "Ours" is
the exact lowest-potential position (Newton on the exact closest distance, active-set contact
search); 540° are sampled at 0.25° (2,161 positions) as in the paper. Runout is max − min of
the displacement along the load. Roller spin: pure rolling (see the module Notes on eq. 2). The
paper's own check against its analytic cases reached 0.097 % and 0.15 %, so 3 % is the
tolerance for the figures."""


# ---------------------------------------------------------------------------------------------
# dynamic model, seed 003 Figs. 3-4
# ---------------------------------------------------------------------------------------------
DYN_ELEMENTS = (5, 7, 8, 10, 12, 15)
DYN_BPF = {5: 90.0, 7: 120.0, 8: 132.5, 10: 170.0, 12: 200.0, 15: 255.0}


@functools.cache
def dynamic_points() -> dict[tuple[int, float], Any]:
    """Sweep points of examples/seed003_purohit.toml: Z × preload (the runout sweep-dynamic)."""
    from runout.models import dynamic as dy

    case = _load("seed003_purohit.toml")
    points = dy.sweep(case, elements=DYN_ELEMENTS, preloads=(0.0, 10.0))
    points += dy.sweep(case, elements=(5,), preloads=(30.0, 50.0))
    points += dy.sweep(case, elements=(8,), preloads=(50.0, 100.0))
    return {(p.elements, p.preload_n): p for p in points}


def _fn(z: int, p: float) -> float:
    return float(max(dynamic_points()[(z, p)].natural_frequencies_hz))


def _bpv_nm(z: int, p: float) -> float:
    return float(dynamic_points()[(z, p)].ball_passage_pp_m) / NM


def _dynamic_rows() -> list[Check]:
    name = _uses("seed003_purohit.toml", "seed 003 Table 2 rotor, Figs. 3–4 (dynamic)")
    out: list[Check] = []
    for i, (z, value) in enumerate(DYN_BPF.items()):
        out.append(
            Check(
                f"Seed 003 Fig. 3, Z = {z}, 10 N",
                "BPF [Hz]",
                value,
                _bind(lambda z: float(dynamic_points()[(z, 10.0)].ball_passage_hz), z),
                "rel",
                0.05,
                reason="eq. 2.20 with Table 2 gives (Z/2) f_i (1 − D/d_m) (kinematics section); "
                "the published values scale with Z but at about half the kinematic rate: "
                "perhaps f_c computed at half the shaft speed"
                if i == 0
                else "″",
                case=name,
            )
        )
    for z, p, value, reason in (
        (
            5,
            10.0,
            90.0,
            "90 Hz on 0.6 kg needs k ≈ 1.9e5 N/m; the Hertz contacts of this bearing "
            "are over a hundred times stiffer at 10 N preload",
        ),
        (8, 10.0, 135.0, "″"),
        (
            8,
            50.0,
            100.0,
            "the paper's f_n falls with preload here, contrary to its own statement "
            "that preload stiffens",
        ),
    ):
        out.append(
            Check(
                f"Seed 003 Fig. 3/4, Z = {z}, {p:g} N",
                "f_n [Hz] (highest linearised natural frequency)",
                value,
                _bind(lambda z, p: _fn(z, p), z, p),
                "rel",
                0.05,
                reason=reason,
                case=name,
            )
        )
    out += [
        Check(
            "Seed 003 §3.1",
            "BPV falls with more balls: BPV(Z = 5) / BPV(Z = 15), no preload",
            None,
            lambda: _bpv_nm(5, 0.0) / _bpv_nm(15, 0.0),
            "min",
            1.0,
            expected="> 1",
            reason="not monotone in between: Z = 8 has 3 × BPF near f_n (the paper also singles "
            "out 8 balls)",
            case=name,
        ),
        Check(
            "Seed 003 §3.2",
            "BPV falls with preload: BPV(Z = 5, 0 N) / BPV(Z = 5, 10 N)",
            None,
            lambda: _bpv_nm(5, 0.0) / max(_bpv_nm(5, 10.0), 1e-30),
            "min",
            1.0,
            expected="> 1",
            reason="a preload loads every ball and removes the play; the ball-passage stiffness "
            "ripple then falls steeply",
            case=name,
        ),
        Check(
            "Seed 003 Fig. 3",
            "largest BPV at 10 N over Z = 5…15 [nm]",
            None,
            lambda: max(_bpv_nm(z, 10.0) for z in DYN_ELEMENTS),
            "min",
            0.1,
            expected="clearly visible peaks (≥ 0.1 nm; the figure values are not in the text)",
            reason="with a 10 N preload every ball is loaded; large BPV needs a load zone of a "
            "few balls, i.e. play (the 0 N column)",
            case=name,
        ),
        Check(
            "Seed 003 §3",
            "f_n rises with Z: f_n(Z = 15) / f_n(Z = 5) at 10 N",
            None,
            lambda: _fn(15, 10.0) / _fn(5, 10.0),
            "min",
            1.0,
            expected="> 1",
            reason="stiffer bearing",
            case=name,
        ),
        Check(
            "Seed 003 §3.2",
            "f_n rises with preload: f_n(100 N) / f_n(10 N), Z = 8",
            None,
            lambda: _fn(8, 100.0) / _fn(8, 10.0),
            "min",
            1.0,
            expected="> 1",
            reason="stiffer bearing",
            case=name,
        ),
    ]
    return out


DYNAMIC_INTRO = """\
Tests: `tests/unit/test_dynamic.py`, `tests/reference/test_dynamic_checks.py` (independent
checks: contact law vs eq. 2.4–2.5, tangent stiffness vs central differences, Newmark vs a
NumPy reference and DOP853, energy conservation and dissipation, low-speed limit vs the
quasi-static solve), `tests/cli/test_run_dynamic.py`. Rotor of seed 003 Table 2
(`examples/seed003_purohit.toml`): D = 7.96 mm, d_m = 54 mm, r_gi = 4.08 mm, r_go = 4.61 mm,
γ = 0.1 µm read as P_d/2, m = 0.6 kg, c = 200 N s/m, W = 6 N, 5000 rpm; K_n from the exact
Hertz solution. Ours is `runout sweep-dynamic examples/seed003_purohit.toml --elements
5,7,8,10,12,15 --preload 0,10` (plus Z = 5 at 30, 50 N and Z = 8 at 50, 100 N). BPF = Z f_c
(stationary outer ring, eq. 2.20) at the preloaded contact angle; f_n = linearised natural
frequencies at the static equilibrium."""

DYNAMIC_OUTRO = """\
Verdict: the published frequencies cannot come from Table 2 (BPF off by a factor ≈ 2, f_n by
an order of magnitude, and Table 2 itself gives an outer race radius of 46 mm against a 27 mm
pitch radius). The qualitative statements (fewer balls and less preload → more ball-passage
vibration, resonance when a BPF harmonic meets f_n) are reproduced."""


# ---------------------------------------------------------------------------------------------
# studies: seed 001 Table 9 (Monte Carlo)
# ---------------------------------------------------------------------------------------------
KIM_TABLE9 = {0.1e-6: (109.95, 57.94), 0.05e-6: (54.17, 29.55), 0.033e-6: (36.69, 19.18)}
STUDY_SAMPLES: int | None = None
"""Bearings per Monte Carlo (None: the case file's 1000). Tests may lower it."""


@functools.cache
def kim_table9(sigma: float) -> np.ndarray:
    """f_c p-p [nm] of every bearing of the Monte Carlo at ball diameter σ."""
    from runout.case import parse_case
    from runout.study import run_study

    case = _load("seed001_kim_table9.toml")
    data = case.spec.model_dump(exclude_none=True)
    data["study"]["vary"] = {"element_diameter_sigma": sigma}
    if STUDY_SAMPLES is not None:
        data["study"]["samples"] = STUDY_SAMPLES
    res = run_study(parse_case(data, str(EXAMPLES / "seed001_kim_table9.toml")))
    return np.asarray(res.lines["x|ball size error: f_c"][1]) * 1e9


def _rayleigh(sigma: float, z: int = 10) -> tuple[float, float]:
    s = 4.0 / z * sigma * math.sqrt(z / 2.0) * 1e9
    return s * math.sqrt(math.pi / 2.0), s * math.sqrt((4.0 - math.pi) / 2.0)


def _study_rows() -> list[Check]:
    name = _uses("seed001_kim_table9.toml", "seed 001 Table 9 (σ = 0.05, 0.033 µm in code)")
    out: list[Check] = []
    for sigma, (mean, std) in KIM_TABLE9.items():
        out += [
            Check(
                f"Seed 001 Table 9, σ = {sigma * 1e6:g} µm",
                "mean f_c p-p [nm]",
                mean,
                _bind(lambda sigma: float(np.mean(kim_table9(sigma))), sigma),
                "rel",
                0.06,
                reason="sampling: the standard error of a 1000-bearing mean is 1.7 %; plus the "
                "paper's lower single-ball gain (Table 4)",
                case=name,
            ),
            Check(
                "″",
                "σ of f_c p-p [nm]",
                std,
                _bind(lambda sigma: float(np.std(kim_table9(sigma), ddof=1)), sigma),
                "rel",
                0.06,
                reason="sampling (2.2 % standard error)",
                case=name,
            ),
        ]
    r_mean, r_std = _rayleigh(0.1e-6)
    out += [
        Check(
            "Rayleigh law (theory), σ = 0.1 µm",
            "Monte Carlo mean [nm] vs s √(π/2), s = (4/Z) σ √(Z/2)",
            r_mean,
            lambda: float(np.mean(kim_table9(0.1e-6))),
            "rel",
            4.0 * math.sqrt((4 - math.pi) / math.pi) / math.sqrt(1000) + 0.005,
            reason="tolerance: 4 standard errors of the mean plus the 0.5 % nonlinear gain",
            case=name,
        ),
        Check(
            "″",
            "Monte Carlo σ [nm] vs s √((4−π)/2)",
            r_std,
            lambda: float(np.std(kim_table9(0.1e-6), ddof=1)),
            "rel",
            4.0 / math.sqrt(2.0 * 1000) + 0.005,
            reason="tolerance: 4 standard errors of σ plus the 0.5 % gain",
            case=name,
        ),
        Check(
            "Same seed for every σ",
            "mean(σ = 0.05 µm) / mean(σ = 0.1 µm)",
            0.5,
            lambda: float(np.mean(kim_table9(0.05e-6)) / np.mean(kim_table9(0.1e-6))),
            "rel",
            2e-3,
            reason="the same standard normals scaled by σ: linear to the Hertz nonlinearity (the "
            "paper drew new diameters for each σ)",
            case=name,
        ),
    ]
    return out


STUDY_INTRO = """\
Case `examples/seed001_kim_table9.toml`: bearing of Table 1 at 7200 rpm, preload 60.68 N
(fitted to Table 2), 2-D quasi-static model, 8 revolutions × 128 instants, every ball's
**diameter** error normal N(0, σ) (Table 3 is of diameters), 1000 bearings, seed 1; the line is
**peak-to-peak** (the convention that reproduces Tables 4–8). Rayleigh law: f_c p-p has scale
s = (4/Z)·σ·√(Z/2); mean s√(π/2), standard deviation s√((4−π)/2) (derivation in
docs/studies.md). Tests: `tests/reference/test_seed001_kim_table9.py`,
`tests/unit/test_study.py`, `tests/unit/test_arrangement.py`."""


# ---------------------------------------------------------------------------------------------
# the registry
# ---------------------------------------------------------------------------------------------
SECTIONS: list[Section] = [
    Section(
        "kinematics",
        "Kinematics (`runout.kinematics`)",
        "Tests: `tests/reference/test_kinematics_references.py`. Orders = multiples of the "
        "rotating ring's speed.",
        [
            Group(
                "",
                "",
                _kinematics,
                "Seed 004 eq. 2 (roller spin angle) as extracted is four times the pure-rolling "
                "spin; we use the consistent value (see `runout.kinematics`).",
            )
        ],
    ),
    Section(
        "contact",
        "Hertz contact and axial loading (`runout.contact`, `runout.loading`)",
        "Tests: `tests/reference/test_contact_references.py`, "
        '`tests/reference/test_kim_table2.py`. "Ours" is the exact Hertz solution '
        "(ellipticity solved from the complete elliptic integrals) unless the row says "
        "otherwise. Steel is E = 207.5 GPa, ν = 0.3 for Harris's numbers and E = 208 GPa, "
        "ν = 0.3 for seed 001 and seed 002.",
        [
            Group("Point contact", "", _point_contact),
            Group("Line contact", "", _line_contact),
            Group(
                "Ball bearing under a pure axial load — seed 001 (Kim) Table 2",
                KIM_TABLE2_INTRO,
                _kim_table2,
                KIM_TABLE2_OUTRO,
            ),
        ],
    ),
    Section(
        "spectrum",
        "Spectra and band values (`runout.spectrum`)",
        SPECTRUM_INTRO,
        [Group("", "", _spectrum)],
    ),
    Section(
        "linear",
        "Linear model, seed 002 Anderon vibration of a 608 (`runout.models.linear`)",
        LINEAR_INTRO,
        [
            Group("", "", _linear_rows, LINEAR_OUTRO),
            Group(
                "Cross-check: `linear` (force-balance variant) vs `quasi_static_3d` at small "
                "amplitude",
                CROSS_INTRO,
                _cross_rows,
            ),
        ],
    ),
    Section(
        "roller",
        "Rigid constraint model of a cylindrical roller bearing "
        "(`runout.models.roller_constraint`)",
        ROLLER_INTRO,
        [Group("", "", _roller_rows)],
    ),
    Section(
        "dynamic",
        "Dynamic model (`runout.models.dynamic`, seed 003)",
        DYNAMIC_INTRO,
        [Group("Seed 003 Figs. 3–4", "", _dynamic_rows, DYNAMIC_OUTRO)],
    ),
    Section(
        "quasi_static",
        "Quasi-static NRRO models (`runout.models.quasi_static_3d`, "
        "`runout.models.quasi_static_2d`)",
        "Tests: `tests/reference/test_seed000_tada.py`, "
        "`tests/reference/test_seed001_kim_nrro.py`, `tests/unit/test_quasi_static_3d.py`.",
        [
            Group("Seed 000 (Tada), 3-D model, standard model of Table 1", TADA_INTRO, _tada_rows),
            Group("Seed 001 (Kim), 2-D model, Tables 4–8", KIM_INTRO, _kim_rows, kim_outro),
            Group(
                "`equilibrium` (Jones–Harris, seed 001 §2.1) — Table 2 at 7200 rpm",
                EQUILIBRIUM_INTRO,
                _equilibrium_rows,
            ),
        ],
    ),
    Section(
        "studies",
        "Studies (`runout.study`, `runout.arrangement`)",
        "",
        [
            Group(
                "Seed 001 (Kim) Table 9: f_c line of 1000 bearings with random ball diameters",
                STUDY_INTRO,
                _study_rows,
            )
        ],
    ),
]
