"""The Python builder of a case: :class:`Imperfections` (the imperfection tables in code) and
:func:`build_case` (a :class:`runout.case.model.Case` from typed inputs, validated as a case file).

:class:`Imperfections` is a *builder* that reads like the case file's imperfection tables
(``[[waviness]]``, ``[[waviness_spectrum]]``, ``[[profile]]``, ``[slant]``, ``[elements]``):
the same keys, units and meanings. It records the tables; the bearing turns them into
harmonics when the case is built. The resolved harmonics the models use are
:class:`runout.geometry.imperfections.Imperfections` (``case.imperfections``), the physics
class. :func:`runout.run` (:mod:`runout.api`) runs a case built here.
"""

from __future__ import annotations

import difflib
import numbers
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from pydantic import ValidationError

from runout.base.errors import ArgumentTypeError, CaseError
from runout.case import limits
from runout.case.model import (
    PYTHON_PATH,
    AnalysisSpec,
    Case,
    CaseSpec,
    DynamicsSpec,
    _plain,
    _table_type,
    first_validation_error,
)
from runout.geometry.bearing import Operation

if TYPE_CHECKING:
    from numpy.typing import ArrayLike


__all__ = ["PYTHON_PATH", "Imperfections", "build_case", "split_options"]


_PARTS = ("inner", "outer", "ball", "roller")


def _check_entry(table: str, index: int, entry: dict[str, Any]) -> None:
    """Validate one imperfection entry as the case file would, naming ``table[index]``."""
    spec_type = _table_type(CaseSpec.model_fields[table].annotation)
    try:
        spec_type.model_validate(entry)
    except ValidationError as exc:
        key, message = first_validation_error(exc)
        where = (
            f"{table}[{index}]" if table in ("waviness", "waviness_spectrum", "profile") else table
        )
        raise CaseError(PYTHON_PATH, f"{where}.{key}" if key else where, message) from None


@dataclass(frozen=True, init=False, eq=False)
class Imperfections:
    """Imperfections of a bearing's parts, written like the case file's tables.

    Each method returns a new object with one more entry (the object itself never changes),
    so calls chain: ``Imperfections(elements=8).waviness("inner", order=9, amplitude=10e-9)``.
    Values are SI numbers or strings with units (``"20 nm"``, ``"30 deg"``), as in a case
    file, and are checked as the case file's keys are when the entry is added.

    Parameters
    ----------
    elements : int, optional
        Number of rolling elements Z. Optional: the bearing gives Z when the case is built,
        and a Z given here must equal it; element numbers and per-element arrays are checked
        against it as soon as it is known.

    Attributes
    ----------
    elements : int or None
        Number of rolling elements Z, when given.
    entries : tuple of (str, dict)
        The case-file tables added so far, in order: table name and its keys.
    profile_arrays : tuple of (str, ndarray, ndarray)
        Profiles given as arrays: file name in the entries, angles [rad] and radius
        deviations [m] (or in the entry's units).

    Notes
    -----
    Rolling elements are numbered 1..Z, as in the case file. The builder does not compute
    harmonics; :meth:`runout.case.model.Case.from_inputs` (and :func:`run`) resolve it against the
    bearing into :class:`runout.geometry.imperfections.Imperfections`, exactly as a case file's
    tables are resolved.
    """

    elements: int | None
    entries: tuple[tuple[str, dict[str, Any]], ...]
    profile_arrays: tuple[tuple[str, np.ndarray, np.ndarray], ...]

    def __init__(self, elements: int | None = None, **unexpected: Any) -> None:
        if unexpected:
            name = next(iter(unexpected))
            raise ArgumentTypeError(
                PYTHON_PATH,
                name,
                f"Imperfections() takes only elements=Z, not {name}=; add imperfections with "
                ".waviness(part, order=..., amplitude=...), .spectrum(...), .profile(...), "
                ".slant(...), .diameter_errors([...]) and .pitch_errors([...]) (the harmonics "
                "themselves: runout.geometry.imperfections.Imperfections)",
            )
        if isinstance(elements, np.ndarray) and elements.ndim == 0:
            elements = elements[()]  # a 0-d array is the number it holds
        if elements is not None and (
            isinstance(elements, bool | np.bool_)
            or not isinstance(elements, numbers.Integral)
            or elements < 3
        ):
            raise CaseError(
                PYTHON_PATH, "bearing.elements", f"must be an integer >= 3, got {elements!r}"
            )
        object.__setattr__(self, "elements", None if elements is None else int(elements))
        object.__setattr__(self, "entries", ())
        object.__setattr__(self, "profile_arrays", ())

    # --- the tables ---------------------------------------------------------------------------
    def _with(
        self, table: str, entry: dict[str, Any], arrays: tuple[Any, ...] | None = None
    ) -> Imperfections:
        entry = {k: _plain(v) for k, v in entry.items() if v is not None}
        index = sum(t == table for t, _ in self.entries) + 1
        if table in ("slant", "elements"):
            index = 1
        _check_entry(table, index, entry)
        element = entry.get("element")
        if self.elements is not None and element is not None and element > self.elements:
            raise CaseError(
                PYTHON_PATH,
                f"{table}[{index}].element",
                f"must be <= {self.elements} (the number of elements)",
            )
        new = object.__new__(Imperfections)
        object.__setattr__(new, "elements", self.elements)
        if table in ("slant", "elements"):
            kept = tuple((t, e) for t, e in self.entries if t != table)
            if table == "elements":  # the [elements] keys accumulate: one table
                old = next((e for t, e in self.entries if t == table), {})
                entry = {**old, **entry}
                _check_entry(table, 1, entry)
            object.__setattr__(new, "entries", (*kept, (table, entry)))
        else:
            object.__setattr__(new, "entries", (*self.entries, (table, entry)))
        object.__setattr__(
            new,
            "profile_arrays",
            self.profile_arrays if arrays is None else (*self.profile_arrays, arrays),
        )
        return new

    def waviness(
        self,
        part: str,
        order: int,
        *,
        amplitude: float | str | None = None,
        peak_to_peak: float | str | None = None,
        phase: float | str = 0.0,
        element: int | None = None,
    ) -> Imperfections:
        """Add one harmonic ``a cos(kθ + φ)`` of a part's radius (``[[waviness]]``).

        Parameters
        ----------
        part : {"inner", "outer", "ball", "roller"}
            The part whose radius deviates.
        order : int
            Number of lobes k.
        amplitude, peak_to_peak : float or str
            Zero-to-peak radius deviation [m], or its peak-to-peak value [m] (halved); one.
        phase : float or str
            φ [rad].
        element : int, optional
            Ball or roller number 1..Z; default every element.

        Returns
        -------
        Imperfections
            A new builder with the entry added.
        """
        return self._with(
            "waviness",
            {
                "part": part,
                "order": order,
                "amplitude": amplitude,
                "peak_to_peak": peak_to_peak,
                "phase": phase,
                "element": element,
            },
        )

    def spectrum(
        self,
        part: str,
        orders: tuple[int, int],
        *,
        amplitude: float | str | None = None,
        peak_to_peak: float | str | None = None,
        exponent: float = 0.0,
        phase: float | str = "random",
        seed: int | None = None,
        element: int | None = None,
    ) -> Imperfections:
        """Add a waviness spectrum ``amplitude * k**exponent`` over ``orders`` (inclusive).

        The ``[[waviness_spectrum]]`` table.

        Parameters
        ----------
        part : {"inner", "outer", "ball", "roller"}
            The part whose radius deviates.
        orders : (int, int)
            First and last order, inclusive.
        amplitude, peak_to_peak : float or str
            Zero-to-peak (or peak-to-peak) amplitude at k = 1 [m]; one of the two.
        exponent : float
            Spectral slope [-].
        phase : float, str or "random"
            One phase for every order [rad], or ``"random"`` (seeded, reproducible).
        seed : int, optional
            Seed of the random phases (``phase="random"`` only; default 0).
        element : int, optional
            Ball or roller number 1..Z; default every element (each its own random phases).

        Returns
        -------
        Imperfections
            A new builder with the entry added.
        """
        return self._with(
            "waviness_spectrum",
            {
                "part": part,
                "orders": list(orders),
                "amplitude": amplitude,
                "peak_to_peak": peak_to_peak,
                "exponent": exponent,
                "phase": phase,
                "seed": seed,
                "element": element,
            },
        )

    def profile(
        self,
        part: str,
        *,
        orders: tuple[int, int],
        file: str | Path | None = None,
        angles: ArrayLike | None = None,
        deviations: ArrayLike | None = None,
        angle_unit: str | None = None,
        deviation_unit: str | None = None,
        element: int | None = None,
    ) -> Imperfections:
        """Add a measured roundness profile, from a CSV file or from arrays (``[[profile]]``).

        Parameters
        ----------
        part : {"inner", "outer", "ball", "roller"}
            The part measured.
        orders : (int, int)
            Orders kept, first and last inclusive.
        file : str or Path, optional
            CSV of angle and deviation (docs/case-file.md), relative to the working directory
            (or ``base_dir`` of :meth:`runout.case.model.Case.from_inputs`).
        angles, deviations : array_like, optional
            The profile itself, instead of a file: angles [rad] and radius deviations [m]
            (or in ``angle_unit`` and ``deviation_unit``).
        angle_unit : {"deg", "rad"}, optional
            Default "deg" for a file (as the case file), "rad" for arrays.
        deviation_unit : str, optional
            Default "um" for a file (as the case file), "m" for arrays.
        element : int, optional
            Ball or roller number 1..Z.

        Returns
        -------
        Imperfections
            A new builder with the entry added.

        Raises
        ------
        CaseError
            Naming ``profile[i].angles`` or ``profile[i].deviations``: arrays with more points
            than any memory budget of this machine reads (counted before they are copied; the
            case's own budget is checked when the case is built), complex values (never cast
            to real) or values that are not numbers.
        """
        from_arrays = angles is not None or deviations is not None
        if from_arrays == (file is not None):
            raise CaseError(
                PYTHON_PATH,
                f"profile[{sum(t == 'profile' for t, _ in self.entries) + 1}].file",
                "give file=... or angles=... and deviations=..., not both or neither",
            )
        arrays = None
        if from_arrays:
            if angles is None or deviations is None:
                raise CaseError(
                    PYTHON_PATH,
                    f"profile[{sum(t == 'profile' for t, _ in self.entries) + 1}].file",
                    "a profile from arrays needs both angles and deviations",
                )
            index = sum(t == "profile" for t, _ in self.entries) + 1
            # sizes first: 5e7 points were copied, then ran out of memory in the fit
            a = _real_array(angles, f"profile[{index}].angles", _most_profile_points())
            d = _real_array(deviations, f"profile[{index}].deviations", _most_profile_points())
            finite = a[np.isfinite(a)]
            span = float(np.ptp(finite)) if finite.size else 0.0
            if angle_unit is None and span > 2.0 * np.pi * (1.0 + 1e-9):
                # degrees read as radians would wrap the profile 57 times: refuse, say why
                raise CaseError(
                    PYTHON_PATH,
                    f"profile[{sum(t == 'profile' for t, _ in self.entries) + 1}].angle_unit",
                    f"the angles span {span:.4g}, more than a turn in radians (the default for "
                    'arrays): give angle_unit="deg" for angles in degrees',
                )
            a.flags.writeable = False
            d.flags.writeable = False
            number = sum(name is not None for name, *_ in self.profile_arrays) + 1
            name = f"{part}_profile_{number}.csv"
            arrays = (name, a, d)
            file = name
            angle_unit = "rad" if angle_unit is None else angle_unit
            deviation_unit = "m" if deviation_unit is None else deviation_unit
        return self._with(
            "profile",
            {
                "part": part,
                "file": str(file),
                "orders": list(orders),
                "angle_unit": angle_unit,
                "deviation_unit": deviation_unit,
                "element": element,
            },
            arrays,
        )

    def slant(
        self,
        *,
        amplitude: float | str | None = None,
        angle: float | str | None = None,
        phase: float | str = 0.0,
    ) -> Imperfections:
        """Set the inner-raceway slant (``[slant]``): its amplitude [m] or angle [rad].

        Parameters
        ----------
        amplitude : float or str, optional
            Amplitude W_s of the two-per-revolution term [m]; give this or ``angle``.
        angle : float or str, optional
            Slant angle β [rad], instead of ``amplitude``.
        phase : float or str
            Phase φ_s [rad].

        Returns
        -------
        Imperfections
            A new builder whose ``[slant]`` is this one (a slant given before is replaced).

        Notes
        -----
        The slant is the inner-raceway term of seed 002 ("Anderon vibration"), eq. 34.
        """
        return self._with("slant", {"amplitude": amplitude, "angle": angle, "phase": phase})

    def diameter_errors(self, values: Sequence[float | str] | ArrayLike) -> Imperfections:
        """Set each element's diameter deviation [m], Z values (``[elements] diameter_errors``).

        Parameters
        ----------
        values : sequence of float or str, or array_like
            Deviation of each element's diameter [m] (or strings with units), elements 1..Z.

        Returns
        -------
        Imperfections
            A new builder with ``[elements] diameter_errors`` set.
        """
        return self._with("elements", {"diameter_errors": self._per_element(values, "diameter")})

    def pitch_errors(self, values: Sequence[float | str] | ArrayLike) -> Imperfections:
        """Set each element's angular position error [rad], Z values (``[elements]``).

        Parameters
        ----------
        values : sequence of float or str, or array_like
            Angular position error of each element [rad] (or strings with units), elements 1..Z.

        Returns
        -------
        Imperfections
            A new builder with ``[elements] pitch_errors`` set.
        """
        return self._with("elements", {"pitch_errors": self._per_element(values, "pitch")})

    def phase_frame(self, frame: str) -> Imperfections:
        """Frame of element waviness phases, "cage" or "fixed" (``[elements] phase_frame``).

        Parameters
        ----------
        frame : {"cage", "fixed"}
            ``"cage"``: angle 0 along the outward radius through the element's centre at t = 0;
            ``"fixed"``: angle 0 along +x of the bearing for every element.

        Returns
        -------
        Imperfections
            A new builder with ``[elements] phase_frame`` set.
        """
        return self._with("elements", {"phase_frame": frame})

    def _per_element(self, values: Any, what: str) -> list[Any]:
        key = f"elements.{what}_errors"
        # the length first: 10^7 entries were converted one by one for minutes before it
        count = _length(values, key)
        if self.elements is not None and count != self.elements:
            raise CaseError(
                PYTHON_PATH, key, f"has {count} entries; the bearing has {self.elements} elements"
            )
        if count > limits.MAX_ELEMENTS:
            raise CaseError(
                PYTHON_PATH,
                key,
                f"has {count} entries, more than the {limits.MAX_ELEMENTS} elements a bearing "
                "may have",
            )
        if np.iscomplexobj(values) or any(
            isinstance(v, numbers.Complex) and not isinstance(v, numbers.Real) for v in values
        ):
            raise CaseError(
                PYTHON_PATH, key, "must be real numbers, got complex values (never cast to real)"
            )
        listed = _plain(values if isinstance(values, np.ndarray | list | tuple) else list(values))
        return list(listed)

    # --- reading it back ----------------------------------------------------------------------
    def tables(self) -> dict[str, Any]:
        """The case-file tables this builder holds (copies), in the order they were added.

        Returns
        -------
        dict
            Table name -> entry (``slant``, ``elements``) or list of entries (``waviness``,
            ``waviness_spectrum``, ``profile``), keys and values as given (SI or with units).
        """
        out: dict[str, Any] = {}
        for table, entry in self.entries:
            if table in ("slant", "elements"):
                out[table] = dict(entry)
            else:
                out.setdefault(table, []).append(dict(entry))
        return out

    @property
    def profile_data(self) -> dict[str, tuple[np.ndarray, np.ndarray]]:
        """Profiles given as arrays: file name in :meth:`tables` -> (angles, deviations)."""
        return {name: (a, d) for name, a, d in self.profile_arrays}

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Imperfections):
            return NotImplemented
        return (
            self.elements == other.elements
            and self.entries == other.entries
            and len(self.profile_arrays) == len(other.profile_arrays)
            and all(
                n1 == n2 and np.array_equal(a1, a2) and np.array_equal(d1, d2)
                for (n1, a1, d1), (n2, a2, d2) in zip(
                    self.profile_arrays, other.profile_arrays, strict=True
                )
            )
        )

    __hash__ = None  # type: ignore[assignment]  # holds arrays and dicts

    def __repr__(self) -> str:
        tables = ", ".join(
            f"[{t}]" if t in ("slant", "elements") else f"{n} [[{t}]]"
            for t, n in _counts(self.entries).items()
        )
        return f"Imperfections(elements={self.elements}{': ' if tables else ''}{tables})"


def _length(values: Any, key: str) -> int:
    """Number of values of an array or sequence, found without copying it."""
    if isinstance(values, np.ndarray):
        return int(values.size)
    if isinstance(values, str | bytes) or not hasattr(values, "__len__"):
        raise CaseError(
            PYTHON_PATH,
            key,
            f"must be a sequence or an array of numbers, got {type(values).__name__}",
        )
    return len(values)


def _most_profile_points() -> int:
    """Most points of a profile given as arrays that any budget on this machine can read.

    The case's own budget (``max_memory``) is checked when the case is built
    (:func:`runout.case.limits.max_profile_points`); here only what no budget allows, so that
    arrays beyond it are refused before they are copied.
    """
    installed = limits.physical_memory() or float(limits.DEFAULT_MAX_MEMORY)
    machine = limits.Budget(installed, limits.DEFAULT_MAX_TIME, "this machine", "default")
    return limits.max_profile_points(machine)


def _real_array(values: Any, key: str, most: int) -> np.ndarray:
    """``values`` as a flat float64 array: at most ``most`` of them, real, checked first."""
    count = _length(values, key)
    if count > most:
        raise CaseError(
            PYTHON_PATH,
            key,
            f"has {count} points, more than the {most} a profile may have on this machine; "
            "resample the profile",
        )
    array = np.asarray(values)
    if array.size > most:  # nested sequences: len() counted the outer one only
        raise CaseError(
            PYTHON_PATH,
            key,
            f"has {array.size} points, more than the {most} a profile may have on this "
            "machine; resample the profile",
        )
    if array.dtype.kind == "c":
        raise CaseError(
            PYTHON_PATH, key, "must be real numbers, got complex values (never cast to real)"
        )
    try:
        return np.array(array, dtype=np.float64).ravel()
    except (TypeError, ValueError):
        raise CaseError(
            PYTHON_PATH, key, f"must be numbers, got values of type {array.dtype}"
        ) from None


def _counts(entries: tuple[tuple[str, dict[str, Any]], ...]) -> dict[str, int]:
    out: dict[str, int] = {}
    for table, _ in entries:
        out[table] = out.get(table, 0) + 1
    return out


def build_case(
    bearing: Any,
    operation: Operation | None = None,
    imperfections: Imperfections | None = None,
    *,
    title: str = "",
    analysis: Mapping[str, Any] | None = None,
    dynamics: Mapping[str, Any] | None = None,
    study: Mapping[str, Any] | None = None,
    base_dir: str | Path | None = None,
    tables: Mapping[str, Any] | None = None,
) -> Case:
    """The case a case file with these tables gives: :meth:`runout.case.model.Case.from_inputs`.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        Geometry and material (``[bearing]``, ``[material]``).
    operation : Operation, optional
        ``[operation]``; default a bearing at rest without load.
    imperfections : Imperfections, optional
        This builder's tables; default none.
    title : str
        Shown in outputs.
    analysis, dynamics, study : mapping, optional
        The ``[analysis]``, ``[dynamics]`` and ``[study]`` keys by their case-file names.
    base_dir : str or Path, optional
        Directory that ``[[profile]]`` files are read from; default the working directory.
    tables : mapping, optional
        Any other table by its case-file name (``lubrication``, ``sensor``, ``defect``, and
        ``bearing`` keys the bearing object has no field for): as ``Case.from_inputs``.

    Returns
    -------
    Case
        Validated as a case file would be (``<python>`` names the file in errors).
    """
    if imperfections is not None and not isinstance(imperfections, Imperfections):
        raise ArgumentTypeError(
            PYTHON_PATH,
            "imperfections",
            "must be a runout.Imperfections builder (e.g. "
            "runout.Imperfections(elements=8).waviness('inner', order=9, amplitude=10e-9)), "
            f"got {type(imperfections).__name__}",
        )
    return Case.from_inputs(
        bearing,
        operation,
        imperfections,
        title=title,
        analysis=analysis,
        dynamics=dynamics,
        study=study,
        base_dir=base_dir,
        tables=tables,
    )


def split_options(options: Mapping[str, Any]) -> tuple[dict[str, Any], dict[str, Any]]:
    """``run``'s options as its [analysis] and [dynamics] keys; an unknown one is an error.

    Parameters
    ----------
    options : mapping
        Keyword options of :func:`runout.run`, by their case-file key names.

    Returns
    -------
    analysis : dict
        The ``[analysis]`` keys.
    dynamics : dict
        The ``[dynamics]`` keys.

    Raises
    ------
    CaseError
        An option that is neither (with the closest key name, when one is close).
    """
    analysis_keys = [k for k in AnalysisSpec.model_fields if k != "model"]
    dynamics_keys = list(DynamicsSpec.model_fields)
    analysis: dict[str, Any] = {}
    dynamics: dict[str, Any] = {}
    for key, value in options.items():
        if key in analysis_keys:
            analysis[key] = value
        elif key in dynamics_keys:
            dynamics[key] = value
        else:
            hint = difflib.get_close_matches(key, analysis_keys + dynamics_keys, n=1, cutoff=0.6)
            suffix = f"; did you mean '{hint[0]}'?" if hint else ""
            raise CaseError(
                PYTHON_PATH,
                key,
                f"unknown option: not a key of [analysis] ({', '.join(analysis_keys)}) or "
                f"[dynamics] ({', '.join(dynamics_keys)}){suffix}",
            )
    return analysis, dynamics
