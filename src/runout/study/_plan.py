"""Plan of a study: the varied quantities of ``[study.vary]`` in SI and the seeded draws.

Part of :mod:`runout.study.run` (its module docstring describes studies).
"""

from __future__ import annotations

import copy
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from runout.base.errors import CaseError, RunoutError
from runout.base.units import to_si
from runout.case._schema import split_shorthand
from runout.case.model import Case, CaseSpec, StudySpec, VarySpec, parse_vary_key
from runout.case.standards import ISO_3290_SOURCE

#: Runout figures kept per sample, in this order (the keys of
#: :class:`runout.analysis.results.Runout`).
RUNOUT_KEYS = ("radial_pp_m", "axial_pp_m", "rro_pp_m", "nrro_pp_m")
FORMAT = "runout-study/1"
_DIAMETER_KEY = "elements.diameter_errors"


class StudyError(RunoutError):
    """A study that cannot run as asked (output directory, resume mismatch, bad quantity)."""


#: Version of the Monte Carlo draws (recorded in manifest.json as ``sampling``). 1: one
#: ``SeedSequence`` child per sample (runout before issue 31); 2: one counter-based Philox stream
#: per study, sample ``i`` at a fixed place in it (:func:`sample_uniforms`).
SAMPLING = 2
#: Random 64-bit words of one Philox counter step (the stream advances in blocks of four).
_BLOCK = 4


def sample_rng(seed: int, index: int) -> np.random.Generator:
    """Generator of sample ``index`` in studies of sampling version 1 (before issue 31).

    The ``index``-th child of ``SeedSequence(seed)``; studies now draw through
    :func:`sample_uniforms` (:data:`SAMPLING` 2). Kept for callers of the former stream.
    """
    return np.random.default_rng(np.random.SeedSequence(seed, spawn_key=(index,)))


def draw_width(quantities: Sequence[Quantity]) -> int:
    """Random numbers one Monte Carlo sample takes: the drawn entries, padded to a whole block.

    Parameters
    ----------
    quantities : sequence of Quantity
        The study's varied quantities (sorted by key, as :func:`plan_quantities` gives them).

    Returns
    -------
    int
        A multiple of four (one Philox counter step holds four 64-bit words).
    """
    used = sum(q.size for q in quantities)
    return max(_BLOCK, -(-used // _BLOCK) * _BLOCK)


def sample_uniforms(seed: int, start: int, stop: int, width: int) -> NDArray[np.float64]:
    """Uniform numbers of samples ``start`` ... ``stop - 1``, ``width`` per sample, in (0, 1).

    One counter-based stream per study (Philox-4x64, Salmon et al., "Parallel random numbers:
    as easy as 1, 2, 3", SC 2011), keyed by ``SeedSequence(seed)``; sample ``i`` takes the
    64-bit words ``i * width`` ... ``(i + 1) * width - 1`` of it. The stream is positioned at
    ``start`` by its counter (no draws skipped), so a block of samples is one generator call
    and sample ``i``'s numbers depend only on ``(seed, i)``: not on the chunking, the worker
    count or the order in which chunks run.

    Parameters
    ----------
    seed : int
        ``[study] seed``.
    start, stop : int
        First sample and one past the last.
    width : int
        Words per sample, a multiple of four (:func:`draw_width`).

    Returns
    -------
    ndarray, shape (stop - start, width)
        ``(k + 1/2) / 2**52`` with ``k`` the word's top 52 bits: never 0 or 1, exact in float64.
    """
    if width % _BLOCK:
        raise ValueError(f"width must be a multiple of {_BLOCK}, got {width}")
    key = np.random.SeedSequence(seed).generate_state(2, np.uint64)
    stream = np.random.Philox(key=key, counter=start * (width // _BLOCK))
    n = max(0, stop - start)
    words = stream.random_raw(n * width).reshape(n, width)
    return ((words >> np.uint64(12)).astype(np.float64) + 0.5) * 2.0**-52


def draw_block(
    quantities: Sequence[Quantity], seed: int, start: int, stop: int
) -> dict[str, NDArray[np.float64]]:
    """Values of every drawn quantity for samples ``start`` ... ``stop - 1`` [SI].

    One call of the stream (:func:`sample_uniforms`) for the block; quantity ``q`` takes the
    next ``q.size`` columns in key order and turns them into its distribution
    (:meth:`Quantity.from_uniforms`).

    Returns
    -------
    dict
        Key -> ndarray, shape (n,) for a scalar key or (n, size) for a per-element key.
    """
    u = sample_uniforms(seed, start, stop, draw_width(quantities))
    out: dict[str, NDArray[np.float64]] = {}
    column = 0
    for q in quantities:
        v = q.from_uniforms(u[:, column : column + q.size])
        column += q.size
        out[q.key] = v if q.size > 1 else np.ascontiguousarray(v[:, 0])
    return out


# --------------------------------------------------------------------------------------------
# quantities
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Quantity:
    """One varied case quantity, every parameter in SI.

    Attributes
    ----------
    key : str
        The ``[study.vary]`` key (``"operation.axial_load"``, ``"element_diameter_sigma"``).
    path : tuple
        ``(table, index or None, name)`` of the case key it replaces.
    size : int
        1 for a scalar key, Z for a per-element array (every element drawn independently).
    distribution : str
        ``"normal"``, ``"uniform"``, ``"sample"`` (Monte Carlo) or ``"sweep"``.
    mean : ndarray, shape (size,)
        Normal: mean per entry [SI].
    spread : tuple of float
        Normal: (std,); uniform: (low, high) [SI].
    values : tuple
        ``"sample"``: the measured values; ``"sweep"``: the swept values (SI floats or the
        literal strings of a text key).
    grade : dict or None
        A ball-size draw of a bearing with a ball grade (``ball_grade``, or
        ``element_diameter_sigma`` on a bearing whose ``[elements] grade`` is set): the study
        JSON's ``ball_grades`` entry (:func:`_grade_of`).
    """

    key: str
    path: tuple[str, int | None, str]
    size: int
    distribution: str
    mean: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))
    spread: tuple[float, ...] = ()
    values: tuple[Any, ...] = ()
    grade: dict[str, Any] | None = None

    def from_uniforms(self, u: NDArray[np.float64]) -> NDArray[np.float64]:
        """Values of a block of samples from their uniform numbers [SI].

        Parameters
        ----------
        u : ndarray, shape (n, size)
            Uniform numbers in (0, 1) (:func:`sample_uniforms`), one row per sample.

        Returns
        -------
        ndarray, shape (n, size)
            Normal: ``mean + std * Phi^-1(u)`` (the inverse of the normal distribution
            function, one number per value, so that every sample takes the same count);
            uniform: ``low + (high - low) u``; ``"sample"``: entry ``floor(u * count)`` of the
            measured values.
        """
        if self.distribution == "normal":
            from scipy.special import ndtri

            return self.mean + self.spread[0] * ndtri(u)
        if self.distribution == "uniform":
            return self.spread[0] + (self.spread[1] - self.spread[0]) * u
        if self.distribution == "sample":
            pool = np.asarray(self.values, dtype=np.float64)
            pick = np.minimum((u * pool.size).astype(np.int64), pool.size - 1)
            return pool[pick]
        raise StudyError(f"study.vary.{self.key}: a sweep quantity is not drawn")

    def draw(self, rng: np.random.Generator) -> NDArray[np.float64]:
        """Draw the ``size`` values of one sample from ``rng`` [SI] (sampling version 1;
        studies draw blocks through :func:`draw_block`)."""
        if self.distribution == "normal":
            return self.mean + self.spread[0] * rng.standard_normal(self.size)
        if self.distribution == "uniform":
            return rng.uniform(self.spread[0], self.spread[1], self.size)
        if self.distribution == "sample":
            pool = np.asarray(self.values, dtype=np.float64)
            return pool[rng.integers(0, pool.size, self.size)]
        raise StudyError(f"study.vary.{self.key}: a sweep quantity is not drawn")


def _set_at(data: dict[str, Any], path: tuple[str, int | None, str], value: Any) -> None:
    table, index, name = path
    table, _, bearing = table.partition(".")
    if bearing:  # a spindle bearing's [elements.<name>]
        data.setdefault(table, {}).setdefault(bearing, {})[name] = value
    elif index is None:
        data.setdefault(table, {})[name] = value
    else:
        data[table][index - 1][name] = value


def _get_at(spec: CaseSpec, path: tuple[str, int | None, str]) -> Any:
    table, index, name = path
    table, _, bearing = table.partition(".")
    node = getattr(spec, table)
    if bearing:
        node = node.get(bearing) if isinstance(node, dict) else None
    if index is not None:
        node = node[index - 1]
    return None if node is None else getattr(node, name)


def _element_count(case: Case, path: tuple[str, int | None, str]) -> int:
    """Z of the bearing whose per-element key ``path`` is (``[elements]`` or
    ``[elements.<name>]``), 0 for any other key."""
    table, _, name = path
    if name not in ("diameter_errors", "pitch_errors"):
        return 0
    if table == "elements":
        return case.bearing.elements
    if table.startswith("elements.") and case.spindle is not None:
        for b in case.spindle.bearings:
            if f"elements.{b.name}" == table:
                return b.bearing.elements
    return 0


def _convert(
    case: Case, data: dict[str, Any], path: tuple[str, int | None, str], raw: Any, where: str
) -> Any:
    """SI value of ``raw`` placed at ``path``: validated as the case key itself would be."""
    trial = copy.deepcopy(data)
    size = _element_count(case, path)
    _set_at(trial, path, [raw] * size if size else raw)
    try:
        spec = CaseSpec.model_validate(trial)
    except Exception as exc:  # pydantic ValidationError: report it on the study key
        from pydantic import ValidationError

        from runout.case.model import first_validation_error

        if isinstance(exc, ValidationError):
            _, message = first_validation_error(exc)
            raise CaseError(case.path, where, message) from None
        raise
    value = _get_at(spec, path)
    return value[0] if size else value


def plan_quantities(case: Case, data: dict[str, Any] | None = None) -> list[Quantity]:
    """Resolve the ``[study.vary]`` table of ``case`` into :class:`Quantity` objects (SI).

    Parameters
    ----------
    case : Case
        A case with a ``[study]`` table.
    data : dict, optional
        The case document (default: rebuilt from the validated case).

    Raises
    ------
    CaseError
        Naming ``study.vary.<key>`` when a value is not valid where it goes.
    """
    study = _study_of(case)
    data = _case_data(case) if data is None else data
    out: list[Quantity] = []
    formed: set[str] = set()  # element tables whose balls' form is drawn (grade_form_order)
    for key in sorted(study.vary):
        entry = study.vary[key]
        where = f"study.vary.{key}"
        shorthand = split_shorthand(key)
        if shorthand is not None:
            assert not isinstance(entry, VarySpec)
            imperfections, z = _bearing_of(case, key, where, shorthand[1])
            table = "elements" if shorthand[1] is None else f"elements.{shorthand[1]}"
            grade = _grade_of(case, table, key, entry, where)
            sigma = (
                float(grade["sigma_m"])
                if grade is not None and shorthand[0] == "ball_grade"
                else to_si(entry, "length")
            )
            base = np.asarray(imperfections.diameter_errors, dtype=np.float64)
            out.append(
                Quantity(
                    key, (table, None, "diameter_errors"), z, "normal", base, (sigma,), grade=grade
                )
            )
            if grade is not None:
                form = _form_draws(case, data, table, z, grade)
                if form:
                    formed.add(table)
                out.extend(form)
            continue
        assert isinstance(entry, VarySpec)
        path = parse_vary_key(key)
        _refuse_second_description(case, data, path, where)
        if path[0] == "elements" or path[0].startswith("elements."):
            _bearing_of(case, key, where, path[0].partition(".")[2] or None)
        table, index, _name = path
        if index is not None and index > len(data.get(table, [])):
            raise CaseError(
                case.path, where, f"the case has {len(data.get(table, []))} [[{table}]] entries"
            )
        size = _element_count(case, path) or 1

        def conv(
            raw: Any, what: str, path: tuple[str, int | None, str] = path, where: str = where
        ) -> Any:
            return _convert(case, data, path, raw, f"{where}.{what}")

        if entry.distribution is None:  # sweep
            values = _sweep_values(entry, conv, where, case.path)
            out.append(Quantity(key, path, size, "sweep", values=tuple(values)))
            continue
        if entry.distribution == "normal":
            std = _numeric(conv(entry.std, "std"), case.path, f"{where}.std")
            if std < 0.0:
                raise CaseError(case.path, f"{where}.std", "must be >= 0")
            if entry.mean is not None:
                mean = np.full(size, _numeric(conv(entry.mean, "mean"), case.path, where))
            else:
                current = _get_at(case.spec, path)
                if current is None:
                    mean = np.zeros(size)
                elif size > 1:
                    mean = np.asarray(current, dtype=np.float64)
                else:
                    mean = np.full(size, _numeric(current, case.path, where))
            out.append(Quantity(key, path, size, "normal", mean, (std,)))
        elif entry.distribution == "uniform":
            low = _numeric(conv(entry.low, "low"), case.path, f"{where}.low")
            high = _numeric(conv(entry.high, "high"), case.path, f"{where}.high")
            if high < low:
                raise CaseError(case.path, f"{where}.high", "must be >= low")
            out.append(Quantity(key, path, size, "uniform", spread=(low, high)))
        else:
            assert entry.values is not None
            values = [
                _numeric(conv(v, f"values[{i + 1}]"), case.path, f"{where}.values[{i + 1}]")
                for i, v in enumerate(entry.values)
            ]
            out.append(Quantity(key, path, size, "sample", values=tuple(values)))
    for table, elements in case.spec.element_tables:
        if elements.grade_form_order is not None and table not in formed:
            raise CaseError(
                case.path,
                f"{table}.grade_form_order",
                "draws each ball's form from the balls' grade in a Monte Carlo's ball-size "
                f"draw: give [study.vary] ball_grade (or {table}.grade with "
                "element_diameter_sigma), or remove the key",
            )
    # two keys on one case quantity (element_diameter_sigma and elements.diameter_errors):
    # the later draw would silently replace the other's
    drawn_by: dict[tuple[str, int | None, str], str] = {}
    for q in out:
        if q.path in drawn_by:
            raise CaseError(
                case.path,
                f"study.vary.{q.key}",
                f"varies the same quantity as study.vary.{drawn_by[q.path]}; keep one",
            )
        drawn_by[q.path] = q.key
    return out


def _grade_of(case: Case, table: str, key: str, entry: Any, where: str) -> dict[str, Any] | None:
    """The ``ball_grades`` JSON entry of a ball-size shorthand, None without a grade.

    ``ball_grade = "G5"`` draws with sigma = V_DWL / divisor (ISO 3290-1:2014; divisor the
    bearing's ``grade_sigma_divisor``, default 6). ``element_diameter_sigma`` on a bearing
    whose ``[elements] grade`` is set draws the sigma it gives, which wins over the grade's:
    the entry says so in ``note``.

    Raises
    ------
    CaseError
        ``ball_grade`` naming another grade than the bearing's ``[elements] grade``.
    """
    from runout.case.standards import DEFAULT_GRADE_SIGMA_DIVISOR, ball_grade, grade_sigma

    own = dict(case.spec.element_tables).get(table)
    own_grade = own.grade if own is not None else None
    divisor = (
        own.grade_sigma_divisor
        if own is not None and own.grade_sigma_divisor is not None
        else DEFAULT_GRADE_SIGMA_DIVISOR
    )
    explicit = not key.startswith("ball_grade")
    if explicit and own_grade is None:
        return None
    grade = ball_grade(str(own_grade) if explicit else str(entry))
    if not explicit and own_grade is not None and own_grade != grade.name:
        raise CaseError(
            case.path,
            where,
            f'"{grade.name}" contradicts {table}.grade = "{own_grade}": the balls have one '
            "grade; keep one of the two",
        )
    sigma = grade_sigma(grade, divisor)
    out: dict[str, Any] = {
        "key": key,
        "grade": grade.name,
        "lot_diameter_variation_m": grade.lot_diameter_variation,
        "sigma_divisor": divisor,
        "sigma_m": sigma,
        "source": f"{ISO_3290_SOURCE}; sigma = V_DWL / {divisor:g}",
    }
    if explicit:
        given = to_si(entry, "length")
        out["sigma_m"] = given
        out["note"] = (
            f"{where} = {given * 1e6:.6g} um is drawn: it wins over {table}.grade = "
            f'"{grade.name}", whose sigma would be V_DWL / {divisor:g} = {sigma * 1e6:.6g} um'
        )
    return out


def _form_draws(
    case: Case, data: dict[str, Any], table: str, z: int, grade: dict[str, Any]
) -> list[Quantity]:
    """Each ball's form error drawn from its grade, when ``[elements] grade_form_order`` is set.

    Appends Z ``[[waviness]] part = "ball"`` entries (one per ball, amplitude 0) to the case
    document ``data`` and returns the quantities that draw their amplitudes, uniform from 0 to
    the grade's bound (:func:`runout.case.standards.grade_form_amplitude`), and their phases,
    uniform over a turn. Records the order and the bound in the ``ball_grades`` entry
    ``grade``. None of it without ``grade_form_order``.
    """
    from runout.case.standards import ball_grade, grade_form_amplitude

    own = dict(case.spec.element_tables).get(table)
    order = own.grade_form_order if own is not None else None
    if order is None:
        return []
    bound = grade_form_amplitude(ball_grade(str(grade["grade"])), int(order))
    bearing = table.partition(".")[2]
    entries = data.setdefault("waviness", [])
    first = len(entries) + 1
    quantities: list[Quantity] = []
    for j in range(z):
        entry: dict[str, Any] = {
            "part": "ball",
            "order": int(order),
            "amplitude": 0.0,
            "phase": 0.0,
            "element": j + 1,
        }
        if bearing:
            entry["bearing"] = bearing
        entries.append(entry)
        index = first + j
        for name, high in (("amplitude", bound), ("phase", 2.0 * math.pi)):
            quantities.append(
                Quantity(
                    f"waviness[{index}].{name}",
                    ("waviness", index, name),
                    1,
                    "uniform",
                    spread=(0.0, high),
                )
            )
    grade["form_order"] = int(order)
    grade["form_amplitude_max_m"] = bound
    grade["form_entries"] = [first, first + z - 1]
    grade["source"] = (
        f"{grade['source']}; each ball's form: one harmonic of {order} lobes, amplitude uniform "
        f"from 0 to {'min(t_Dw / 2, V_DWs / 4)' if order % 2 == 0 else 't_Dw / 2'}, phase "
        "uniform"
    )
    return quantities


#: The two keys that each describe a ball bearing's play: either one, never both (the
#: catalogue angle sets P_d = 2A(1 - cos a0)).
_PLAY_KEYS = ("radial_clearance", "nominal_contact_angle")


def _refuse_second_description(
    case: Case, data: dict[str, Any], path: tuple[str, int | None, str], where: str
) -> None:
    """Refuse drawing one of a bearing's play keys when the case gives it by the other.

    Every sample would describe the bearing twice, with a clearance its angle does not set,
    and be refused: one line now instead of a lot of failed samples.
    """
    table, index, name = path
    if name not in _PLAY_KEYS or table not in ("bearing", "bearings"):
        return
    section = data.get(table)
    if index is not None:
        section = (
            section[index - 1] if isinstance(section, list) and index <= len(section) else None
        )
    if not isinstance(section, dict):
        return
    other = _PLAY_KEYS[1 - _PLAY_KEYS.index(name)]
    if other not in section:
        return
    prefix = table if index is None else f"{table}[{index}]"
    raise CaseError(
        case.path,
        where,
        f"the case gives the bearing by {prefix}.{other}, which sets its clearance "
        "(P_d = 2A(1 - cos a0)); a drawn "
        f"{name} would describe it twice: vary {prefix}.{other} instead, or give "
        f"{prefix}.{name} in place of {other} in the case",
    )


def _bearing_of(case: Case, key: str, where: str, name: str | None) -> tuple[Any, int]:
    """Imperfections and Z of the bearing a per-element key draws for: the case's bearing
    (``name`` None) or the spindle's bearing ``name``.

    Raises
    ------
    CaseError
        A spindle key without a bearing (which bearing's balls would it be?), a bearing name
        on a single-bearing case, or a name that is not one of the case's ``[[bearings]]``.
    """
    if case.spindle is None:
        if name is not None:
            plain = key.replace(f".{name}", "", 1)
            raise CaseError(
                case.path,
                where,
                f"names a spindle bearing ('{name}') but the case has one bearing ([bearing]); "
                f"write '{plain}'",
            )
        return case.imperfections, case.bearing.elements
    names = [b.name for b in case.spindle.bearings]
    if name is None:
        # a spindle's element errors are per bearing ([elements.<name>]): a draw without a
        # name would not say which bearing's balls it stands for
        base, _, rest = key.partition(".")
        example = f"{base}.{names[0]}" + (f".{rest}" if rest else "")
        raise CaseError(
            case.path,
            where,
            "a spindle's element errors are per bearing ([elements.<name>]): name the bearing, "
            f"e.g. '{example}' (bearings: {', '.join(names)})",
        )
    for b in case.spindle.bearings:
        if b.name == name:
            return b.imperfections, b.bearing.elements
    raise CaseError(case.path, where, f"'{name}' is not a [[bearings]] name ({', '.join(names)})")


def _numeric(value: Any, file: str, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise CaseError(
            file,
            where,
            f'is not a number ({value!r}); draw it from distribution = "sample" or sweep it',
        )
    if isinstance(value, int):
        raise CaseError(
            file, where, 'is an integer key: use distribution = "sample" with integer values'
        )
    return float(value)


def _sweep_values(
    entry: VarySpec, conv: Callable[[Any, str], Any], where: str, file: str
) -> list[Any]:
    if entry.values is not None:
        return [conv(v, f"values[{i + 1}]") for i, v in enumerate(entry.values)]
    start = _range_end(conv(entry.start, "start"), file, f"{where}.start")
    stop = _range_end(conv(entry.stop, "stop"), file, f"{where}.stop")
    integer = isinstance(start, int) and isinstance(stop, int)
    if entry.num is not None:
        grid: list[float | int] = [float(v) for v in np.linspace(start, stop, entry.num)]
        if integer:
            if any(v != round(v) for v in grid):
                raise CaseError(file, f"{where}.num", "an integer key needs integer steps")
            grid = [round(v) for v in grid]
    else:
        step = _range_end(
            to_si(entry.step, "dimensionless")
            if not isinstance(entry.step, str)
            else conv(entry.step, "step"),
            file,
            f"{where}.step",
        )
        if step == 0 or (stop - start) * step < 0:
            raise CaseError(file, f"{where}.step", "must be nonzero and point from start to stop")
        count = math.floor((stop - start) / step + 1e-9) + 1
        grid = [start + step * k for k in range(count)]
        if integer and isinstance(step, int | float) and float(step).is_integer():
            grid = [round(v) for v in grid]
    return [conv(v, f"values[{i + 1}]") for i, v in enumerate(grid)]


def _range_end(value: Any, file: str, where: str) -> float | int:
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise CaseError(file, where, f"a range needs numbers, got {value!r}; use values = [...]")
    return value


def _study_of(case: Case) -> StudySpec:
    if case.study is None:
        raise CaseError(case.path, "study", "the case has no [study] table (see docs/studies.md)")
    return case.study


def _case_data(case: Case) -> dict[str, Any]:
    """The case document in SI numbers, without ``[study]`` (re-validates to the same case).

    Only the keys the case gives: every sample is built from the description the user wrote.
    A dump with the defaults would give keys the user left out (``radial_clearance = 0``
    beside a ``nominal_contact_angle``, a bearing described twice and refused in every
    sample) and mark them as given to the checks that ask what a case sets.
    """
    return case.spec.model_dump(
        mode="python", exclude_unset=True, exclude_none=True, exclude={"study"}
    )


def _digest_data(case: Case) -> dict[str, Any]:
    """The case document a study's digest is taken of: every key with its default, as earlier
    versions hashed it, so that their output directories still resume and load."""
    spec = case.spec
    # an empty [[defect]] list is left out: the table is newer than those directories
    exclude: dict[str, Any] = {"study": True} | ({} if spec.defect else {"defect": True})
    # so is a catalogue bearing's C (the catalogue's C column is newer; the designation, which
    # decides it, is hashed): a C the case gives is in its fields set and is hashed
    rating = "dynamic_load_rating"
    if spec.bearing is not None and rating not in spec.bearing.model_fields_set:
        exclude["bearing"] = {rating}
    unset = [i for i, b in enumerate(spec.bearings or ()) if rating not in b.model_fields_set]
    if unset:
        exclude["bearings"] = {i: {rating} for i in unset}
    return spec.model_dump(mode="python", exclude_none=True, exclude=exclude)


def _models(case: Case) -> list[str]:
    study = _study_of(case)
    return list(study.models) if study.models else [case.analysis.model]
