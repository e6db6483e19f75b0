r"""Tolerance allocation: the largest tolerance of one drawn quantity that meets a target yield.

``[study] allocate = "KEY"`` with ``target_yield = Y`` (or ``runout study CASE --allocate KEY
--target-yield Y``) asks: *how large may the tolerance of KEY be for a fraction Y of the lot to
meet the case's* ``[analysis] limit``? The tolerance of a ``[study.vary]`` entry is

* ``element_diameter_sigma`` (a spindle: ``element_diameter_sigma.<bearing>``): the standard
  deviation σ [m] of the balls' diameter errors;
* a ``distribution = "normal"`` entry: its ``std`` (the mean stays);
* a ``distribution = "uniform"`` entry: its ``high`` (``low`` stays; zero tolerance is
  ``high = low``), e.g. a waviness amplitude drawn from 0 to its upper tolerance.

Method
------
Every evaluation is a Monte Carlo study (:func:`runout.study.run.run_study`) of the case with
the tolerance replaced, with the case's seed and sample count: **common random numbers**.
Sample i draws ``mean + t z_i`` (normal) or ``low + (t - low) u_i`` (uniform) with the same
``z_i``, ``u_i`` at every tolerance t, so each bearing's figure moves continuously with t and,
where it grows with t (a larger error, a larger runout), the number of bearings within the limit
can only fall as t grows: the yield is a non-increasing step function of t and a bisection on it
is exact up to its resolution.

1. *Pilot and first guess.* The study at the case's own tolerance t_0 gives each bearing's
   figure F_i. If the figure is proportional to the tolerance (exact for the ``linear`` model,
   whose displacement is linear in every imperfection, seed 002 eq. 33-41, when the drawn
   quantity is the only source of the limited figure; close to it for the nonlinear models
   at small errors), bearing i meets the limit L up to t_i = t_0 L / F_i, and the largest t for
   which m = ⌈Y n⌉ bearings pass is t_0 L / F_(m) (F sorted ascending): the first guess.
2. *Bracket.* From the guess, steps of the resolution ``rtol`` (doubling each time) up while
   the yield meets Y, or down while it does not, until one tested tolerance passes and the next
   fails; down to zero tolerance, where a lot that still misses Y is refused (no tolerance
   meets it).
3. *Bisection* between them until the failing tolerance is within ``rtol`` of the passing one
   (relative to the passing one's width above the lowest tolerance), at most
   :data:`MAX_STUDIES` studies in all.

The allocated tolerance is the largest tested one whose **estimated** yield (bearings within
the limit / bearings whose model ran) is at least Y; the next larger tested one misses Y.

Statistics
----------
With common random numbers and a figure that grows with t, the allocated t is (to the
bisection's resolution) the m-th largest of the bearings' critical tolerances t_i, an order
statistic, so the true yield at it, 1 - F_T(t), is Beta(m, n - m + 1) distributed whatever the
distribution of the t_i: the Clopper-Pearson interval of m passes in n (what
:meth:`runout.study.run.StudyResult.lot_yield` states) covers it with at least its confidence,
despite the search having chosen t from the same samples. Its mean is m / (n + 1): the estimate
criterion gives a lot whose true yield is Y within the interval, not a guarantee of Y; for a
guaranteed yield ask for a larger Y (or more samples, which narrow the interval). A fresh Monte
Carlo (another seed) at the allocated tolerance estimates the same true yield; the tests check
its count against the beta-binomial law this implies (a 95 % interval misses the true yield in
one allocation in twenty).

References
----------
C. J. Clopper, E. S. Pearson, "The use of confidence or fiducial limits illustrated in the case
of the binomial", Biometrika 26 (1934) 404-413. H. A. David, H. N. Nagaraja, *Order
Statistics*, 3rd ed., Wiley 2003, sec. 2.2 (the distribution of F(X_(r)) is Beta(r, n - r + 1)).
"""

from __future__ import annotations

import dataclasses
import itertools
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from runout.base.errors import CaseError
from runout.base.units import to_si
from runout.case._schema import split_shorthand
from runout.case.model import Case, VarySpec
from runout.study._plan import StudyError, plan_quantities
from runout.study._result import StudyResult, _si_unit
from runout.study.run import run_study, study_limit

__all__ = [
    "MAX_STUDIES",
    "RTOL",
    "UP_FACTOR",
    "Allocation",
    "Evaluation",
    "Search",
    "SearchError",
    "Tolerance",
    "allocate",
    "search",
    "tolerance_of",
    "with_tolerance",
]

#: Resolution of the search [-]: the failing tolerance is within this fraction of the passing
#: one's width (above the lowest tolerance).
RTOL = 0.01
#: Studies one allocation runs at most (pilot, bracket and bisection).
MAX_STUDIES = 40
#: How far above the first guess the bracket search goes up (steps of rtol, doubling) with the
#: yield still met before it takes the quantity not to limit the lot [-].
UP_FACTOR = 1e4


class SearchError(StudyError):
    """A search that cannot allocate.

    Parameters
    ----------
    reason : str
        ``"unreachable"`` (the target is missed at zero tolerance), ``"unlimited"`` (met at
        every tolerance tried) or ``"failed"`` (a study whose every sample failed, or the
        studies ran out).
    value : float
        The tolerance where it happened [SI unit of the key].
    message : str
        The text of the error.
    """

    def __init__(self, reason: str, value: float, message: str) -> None:
        super().__init__(message)
        self.reason = reason
        self.value = value


@dataclass(frozen=True)
class Tolerance:
    """The tolerance an allocation searches: which entry of ``[study.vary]`` and how.

    Attributes
    ----------
    key : str
        The ``[study.vary]`` key (``"element_diameter_sigma"``, ``"waviness[1].amplitude"``).
    parameter : {"sigma", "std", "high"}
        What of the entry is the tolerance.
    name : str
        The JSON key of the allocated value, with its SI unit: ``"element_diameter_sigma_m"``,
        ``"waviness[1].amplitude.high_m"``.
    unit : str
        SI unit of the value (``"m"``, ``"N"``, ``"rad"``, ``"-"``).
    lowest : float
        Zero tolerance [SI]: 0 (sigma, std) or the uniform's ``low``.
    given : float
        The case's tolerance [SI]: the pilot study's and the first guess's scale.
    """

    key: str
    parameter: str
    name: str
    unit: str
    lowest: float
    given: float


@dataclass(frozen=True)
class Evaluation:
    """One study of the search.

    Attributes
    ----------
    value : float
        The tolerance studied [SI unit of the key].
    passed : int
        Bearings within the limit.
    samples : int
        Bearings whose model ran.
    """

    value: float
    passed: int
    samples: int

    @property
    def fraction(self) -> float:
        """Estimated yield [-]."""
        return self.passed / self.samples


@dataclass(frozen=True)
class Search:
    """The outcome of :func:`search`.

    Attributes
    ----------
    value : float
        The allocated tolerance: the largest tested one whose yield met the target [SI].
    failing : float or None
        The smallest tested tolerance above it whose yield missed the target [SI]; None when
        the search stopped at :data:`MAX_STUDIES` without one (then ``converged`` is False).
    evaluations : tuple of Evaluation
        Every study, in the order run.
    converged : bool
        Whether ``failing`` is within ``rtol`` of ``value``.
    monotone : bool
        Whether the passes never rose with the tolerance over the evaluations (common random
        numbers make them non-increasing when each bearing's figure grows with it).
    """

    value: float
    failing: float | None
    evaluations: tuple[Evaluation, ...]
    converged: bool
    monotone: bool


def _meets(passed: int, samples: int, target: float) -> bool:
    """Whether ``passed`` of ``samples`` is an estimated yield of at least ``target``."""
    # passed / samples >= target without the round-off of 0.95 * 400 = 379.99...
    return passed >= math.ceil(target * samples - 1e-9)


def search(
    passes: Callable[[float], tuple[int, int]],
    *,
    lowest: float,
    guess: float,
    target: float,
    rtol: float = RTOL,
    max_studies: int = MAX_STUDIES,
    known: tuple[Evaluation, ...] = (),
) -> Search:
    """Largest tolerance whose estimated yield meets ``target``: bracket from a guess, bisect.

    Parameters
    ----------
    passes : callable
        ``passes(t) -> (passed, samples)``: bearings within the limit and bearings whose model
        ran, at tolerance t [SI] (a study with common random numbers).
    lowest : float
        Zero tolerance [SI] (0, or a uniform's ``low``).
    guess : float
        First guess [SI], > ``lowest``.
    target : float
        Target yield, 0 < target < 1.
    rtol : float
        Resolution: stop when (failing - passing) <= rtol (passing - lowest).
    max_studies : int
        Studies run at most (``known`` included).
    known : tuple of Evaluation
        Studies already run (the pilot): they count and bound the bracket.

    Returns
    -------
    Search

    Raises
    ------
    SearchError
        The target is not met even at zero tolerance, or met at every tolerance the bracket
        tried (the quantity does not limit the lot), or a study where every sample failed.
    """
    evaluations = list(known)

    def met(width: float) -> bool:
        value = lowest + width
        previous = next((e for e in evaluations if e.value == value), None)
        if previous is None:
            passed, samples = passes(value)
            if samples == 0:
                raise SearchError("failed", value, "every sample failed")
            previous = Evaluation(value, passed, samples)
            evaluations.append(previous)
        return _meets(previous.passed, previous.samples, target)

    def known_below(width: float) -> float | None:
        ok = [e.value - lowest for e in evaluations if _meets(e.passed, e.samples, target)]
        below = [w for w in ok if w < width]
        return max(below) if below else None

    def known_above(width: float) -> float | None:
        bad = [e.value - lowest for e in evaluations if not _meets(e.passed, e.samples, target)]
        above = [w for w in bad if w > width]
        return min(above) if above else None

    width = guess - lowest
    passing: float | None
    failing: float | None
    step = rtol * width
    if met(width):  # up in steps of rtol, doubling, until the yield misses the target
        passing, failing = width, known_above(width)
        while failing is None and len(evaluations) < max_studies:
            if passing >= UP_FACTOR * width:
                raise SearchError("unlimited", lowest + passing, "the yield still meets the target")
            trial = passing + step
            if met(trial):
                passing = trial
                step *= 2.0
            else:
                failing = trial
    else:  # down in steps of rtol, doubling (at most halving), until one meets the target
        passing, failing = known_below(width), width
        while passing is None and len(evaluations) < max_studies:
            trial = max(failing - step, 0.5 * failing)
            if trial < rtol * width:
                trial = 0.0  # the last step down: zero tolerance
            if met(trial):
                passing = trial
            elif trial == 0.0:
                last = evaluations[-1]
                raise SearchError(
                    "unreachable", lowest, f"{last.passed} of {last.samples} within the limit"
                )
            else:
                failing = trial
                step *= 2.0
        if passing is None:
            raise SearchError(
                "failed", lowest + failing, f"no tolerance met the target in {max_studies} studies"
            )
    while failing is not None and len(evaluations) < max_studies:
        if failing - passing <= rtol * passing:
            break
        middle = 0.5 * (passing + failing)
        if met(middle):
            passing = middle
        else:
            failing = middle
    converged = failing is not None and failing - passing <= rtol * passing
    ordered = sorted(evaluations, key=lambda e: e.value)
    monotone = all(a.fraction >= b.fraction for a, b in itertools.pairwise(ordered))
    return Search(
        value=lowest + passing,
        failing=None if failing is None else lowest + failing,
        evaluations=tuple(evaluations),
        converged=converged,
        monotone=monotone,
    )


def tolerance_of(case: Case) -> Tolerance:
    """The tolerance ``case``'s ``[study] allocate`` names, checked against the case.

    Parameters
    ----------
    case : Case
        A case whose ``[study]`` has ``allocate`` and ``target_yield``.

    Returns
    -------
    Tolerance

    Raises
    ------
    CaseError
        No ``[analysis] limit`` (a yield needs one), or a case tolerance of zero (the search
        starts from the case's value: give a nonzero one), naming the file and key.
    """
    study = case.study
    if study is None or study.allocate is None or study.target_yield is None:
        raise CaseError(case.path, "study.allocate", "the case's [study] allocates nothing")
    if study_limit(case) is None:
        raise CaseError(
            case.path,
            "analysis.limit",
            f"study.allocate needs a spec limit: the yield of {study.allocate} is the fraction "
            'of the lot within it (e.g. limit = "0.25 um", limit_on = "nrro_pp")',
        )
    key = study.allocate
    quantity = next(q for q in plan_quantities(case) if q.key == key)
    entry = study.vary[key]
    unit = _si_unit(quantity)
    if split_shorthand(key) is not None:
        assert not isinstance(entry, VarySpec)
        parameter, lowest, given = "sigma", 0.0, float(to_si(entry, "length"))
        unit = "m"
    else:
        assert isinstance(entry, VarySpec)
        if entry.distribution == "normal":
            parameter, lowest, given = "std", 0.0, float(quantity.spread[0])
        else:
            parameter = "high"
            lowest, given = (float(v) for v in quantity.spread)
    if not given > lowest:
        start = "low" if parameter == "high" else "zero"
        raise CaseError(
            case.path,
            f"study.vary.{key}" + ("" if parameter == "sigma" else f".{parameter}"),
            f"is {start}: the allocation starts from the case's tolerance; give a nonzero one "
            "(a guess of the allowed tolerance)",
        )
    base = key if parameter == "sigma" else f"{key}.{parameter}"
    suffix = "" if unit in ("-", "") else "_" + unit.lower().replace("/", "_per_")
    return Tolerance(key, parameter, base + suffix, unit, lowest, given)


def with_tolerance(case: Case, tolerance: Tolerance, value: float) -> Case:
    """``case`` with its allocated tolerance set to ``value`` [SI] and no allocation.

    Parameters
    ----------
    case : Case
        The allocating case.
    tolerance : Tolerance
        From :func:`tolerance_of`.
    value : float
        The tolerance [SI] (a number in a case file is SI).

    Returns
    -------
    Case
        The Monte Carlo study of one step of the search (same seed and samples).
    """
    study = case.study
    assert study is not None
    entry = study.vary[tolerance.key]
    replaced: VarySpec | float
    if isinstance(entry, VarySpec):
        replaced = entry.model_copy(update={tolerance.parameter: float(value)})
    else:
        replaced = float(value)
    new = study.model_copy(
        update={
            "vary": {**study.vary, tolerance.key: replaced},
            "allocate": None,
            "target_yield": None,
        }
    )
    return dataclasses.replace(case, spec=case.spec.model_copy(update={"study": new}))


@dataclass(frozen=True)
class Allocation:
    """An allocated tolerance with the study at it.

    Attributes
    ----------
    tolerance : Tolerance
    target_yield : float
    search : Search
    result : StudyResult
        The Monte Carlo at the allocated tolerance (its ``lot_yield`` is the stated yield).
    rtol : float
        The search's resolution.
    notes : list of str
        Anything the reader must know (no convergence, a non-monotone yield).
    """

    tolerance: Tolerance
    target_yield: float
    search: Search
    result: StudyResult
    rtol: float
    notes: list[str]

    def to_json(self) -> dict[str, Any]:
        """The ``allocated`` JSON object of ``runout study --allocate`` (docs/studies.md).

        Returns
        -------
        dict
            The allocated value under ``<key>_<unit>``, its yield and interval, the search's
            studies, resolution and notes.
        """
        lot = self.result.lot_yield()
        t = self.tolerance
        return {
            "key": t.key,
            t.name: self.search.value,
            "yield": lot["fraction"],
            "ci": [lot["ci_low"], lot["ci_high"]],
            "confidence": lot["confidence"],
            "method": lot["method"],
            "passed": lot["passed"],
            "samples": lot["samples"],
            "target_yield": self.target_yield,
            "criterion": "estimated yield >= target_yield",
            "quantity": lot["quantity"],
            "limit_m": lot["limit_m"],
            "next_" + t.name: self.search.failing,
            "rtol": self.rtol,
            "converged": self.search.converged,
            "seed": self.result.seed,
            "studies": [
                {t.name: e.value, "passed": e.passed, "samples": e.samples}
                for e in self.search.evaluations
            ],
            "notes": list(self.notes),
        }


def allocate(
    case: Case,
    *,
    rtol: float = RTOL,
    max_studies: int = MAX_STUDIES,
    notify: Callable[[str], None] | None = None,
    **engine: Any,
) -> Allocation:
    """Find the largest tolerance of ``case.study.allocate`` meeting ``target_yield``.

    Parameters
    ----------
    case : Case
        A case with ``[analysis] limit`` and ``[study] allocate``, ``target_yield``.
    rtol : float
        Resolution of the search [-] (see :func:`search`).
    max_studies : int
        Studies run at most.
    notify : callable, optional
        Called once with each distinct note of the studies (as :func:`run_study`'s).
    **engine
        ``executor``, ``workers``, ``chunk_size`` of :func:`run_study`.

    Returns
    -------
    Allocation

    Raises
    ------
    CaseError
        No limit, a zero starting tolerance (:func:`tolerance_of`).
        The target cannot be met at zero tolerance (on ``study.target_yield``), is met
        whatever the tolerance (on ``study.allocate``), or every sample of a study failed.

    Notes
    -----
    Method and statistics: the module docstring (common random numbers, a first guess from
    the figures' proportionality to the tolerance, bracket and bisection; the Clopper-Pearson
    interval of the yield at the allocated value, C. J. Clopper and E. S. Pearson 1934).
    """
    tolerance = tolerance_of(case)
    study = case.study
    assert study is not None and study.target_yield is not None
    target = float(study.target_yield)
    limit = study_limit(case)
    assert limit is not None
    seen: set[str] = set()

    def note(message: str) -> None:
        if message not in seen:
            seen.add(message)
            (notify or (lambda _m: None))(message)

    results: dict[float, StudyResult] = {}

    def evaluate(value: float) -> StudyResult:
        if value not in results:
            results[value] = run_study(
                with_tolerance(case, tolerance, value), notify=note, plots=False, **engine
            )
        return results[value]

    def passes(value: float) -> tuple[int, int]:
        lot = evaluate(value).lot_yield()
        return int(lot["passed"]), int(lot["samples"])

    # the pilot: the case's own tolerance, and the guess from proportional figures
    pilot = evaluate(tolerance.given)
    passed, samples = passes(tolerance.given)
    if samples == 0:
        failed = SearchError("failed", tolerance.given, "every sample failed")
        raise _refusal(case, tolerance, target, failed)
    figures = np.sort(pilot.runout[f"{limit[0]}_m"][np.isfinite(pilot.runout[f"{limit[0]}_m"])])
    m = math.ceil(target * samples - 1e-9)
    width = tolerance.given - tolerance.lowest
    if figures[m - 1] > 0.0:
        guess = tolerance.lowest + width * limit[1] / float(figures[m - 1])
    else:
        guess = tolerance.lowest + 2.0 * width
    try:
        found = search(
            passes,
            lowest=tolerance.lowest,
            guess=guess,
            target=target,
            rtol=rtol,
            max_studies=max_studies,
            known=(Evaluation(tolerance.given, passed, samples),),
        )
    except SearchError as exc:
        raise _refusal(case, tolerance, target, exc) from None
    notes: list[str] = []
    if not found.converged:
        notes.append(
            f"the search stopped after {len(found.evaluations)} studies without reaching its "
            f"resolution ({rtol:g}): the next tolerance tried is "
            + ("none" if found.failing is None else f"{found.failing:.6g} {tolerance.unit}")
        )
    if not found.monotone:
        notes.append(
            "the yield is not monotone in the tolerance over the studies (a bearing's figure "
            "does not grow with it): the allocated value is the largest tested one that met "
            "the target below the first one that missed it"
        )
    return Allocation(tolerance, target, found, evaluate(found.value), rtol, notes)


def _refusal(case: Case, tolerance: Tolerance, target: float, exc: SearchError) -> CaseError:
    """The one-line refusal of a search that cannot allocate, naming the file and key."""
    from runout.base.display import format_length, length_unit

    def shown(value: float) -> str:
        if tolerance.unit == "m":
            return format_length(value, length_unit([value]))
        return f"{value:.6g} {tolerance.unit}".rstrip(" -")

    at = f"{tolerance.key} = {shown(exc.value)}"
    if exc.reason == "unreachable":
        return CaseError(
            case.path,
            "study.target_yield",
            f"{target:g} is not met even at zero tolerance ({at} gives {exc}): another source "
            "of the figure, or the limit itself, decides the lot",
        )
    if exc.reason == "unlimited":
        return CaseError(
            case.path,
            "study.allocate",
            f"the yield still meets {target:g} at {at}: {tolerance.key} does not limit the "
            "lot's figure (is the limit on the figure it changes?)",
        )
    return CaseError(case.path, "study.allocate", f"{exc} at {at}")
