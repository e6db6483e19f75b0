"""Case files: TOML in, validated frozen dataclasses out.

A case file describes one bearing, how it runs, what is wrong with its parts and which analysis
to run (docs/case-file.md, generated from the schema below, and docs/conventions.md). A
number is SI; a string carries its unit and is parsed by :mod:`runout.base.units`.

Every problem is reported as a :class:`runout.base.errors.CaseError` that names the file, the key
path (``bearing.elements``, ``waviness[2].order``; array entries are counted from 1) and what is
wrong. Unknown keys are errors with a did-you-mean hint.
"""

from __future__ import annotations

import numbers
import re
import stat
import tomllib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from pydantic import ValidationError

from runout.base.errors import ArgumentTypeError, CaseError, GeometryError
from runout.case._build import (
    _GEOMETRY_KEYS,
    ProfileData,
    _build_bearing,
    _build_imperfections,
    _CaseKeyError,
    harmonic_counts,
)
from runout.case._schema import (
    MAX_CONFORMITY,
    MODEL_IDS,
    STUDY_SHORTHANDS,
    AnalysisSpec,
    BearingSpec,
    CaseSpec,
    DefectSpec,
    DynamicsSpec,
    ElementsSpec,
    MaterialSpec,
    OperationSpec,
    ProfileSpec,
    SensorModeSpec,
    SensorSpec,
    SlantSpec,
    SpindleBearingSpec,
    SpindleSpec,
    StudySpec,
    VarySpec,
    WavinessSpec,
    WavinessSpectrumSpec,
    analysis_limit,
    first_validation_error,
    is_band_quantity,
    limit_si,
    parse_vary_key,
    study_paths,
    sweep_count,
)
from runout.case._schema import _table_type as _table_type  # runout.api, runout.report.plotting
from runout.case.designation import (
    BearingSource,
    blame,
    expand,
    leave_catalogue_rating_unset,
    sources,
)
from runout.case.estimates import check_limits
from runout.case.limits import MAX_CASE_FILE_BYTES, MAX_TOML_DEPTH, case_budget, format_bytes
from runout.catalogue import Catalogue
from runout.geometry.bearing import BallBearing, Bearing, Material, Operation, RollerBearing
from runout.geometry.imperfections import BearingImperfections
from runout.geometry.spindle_layout import SpindleBearing, SpindleLayout

__all__ = [
    "MAX_CONFORMITY",
    "MODEL_IDS",
    "STUDY_SHORTHANDS",
    "Analysis",
    "AnalysisSpec",
    "BearingSpec",
    "Case",
    "CaseSpec",
    "DefectSpec",
    "DynamicsSpec",
    "ElementsSpec",
    "MaterialSpec",
    "OperationSpec",
    "ProfileSpec",
    "SensorModeSpec",
    "SensorSpec",
    "SlantSpec",
    "SpindleBearingSpec",
    "SpindleSpec",
    "StudySpec",
    "VarySpec",
    "WavinessSpec",
    "WavinessSpectrumSpec",
    "apply_overrides",
    "first_validation_error",
    "harmonic_counts",
    "is_band_quantity",
    "limit_si",
    "load_case",
    "parse_case",
    "parse_override",
    "parse_vary_key",
    "read_case_data",
    "study_paths",
    "sweep_count",
]


#: The "file" named in the errors of a case built in code.
PYTHON_PATH = "<python>"


def _plain(value: Any) -> Any:
    """A case-file value: numpy numbers as Python numbers, sequences as lists."""
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]  # a 0-d array is the number it holds
    if isinstance(value, bool | str) or value is None:
        return value
    if isinstance(value, np.bool_):
        return bool(value)
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Real):
        return float(value)
    if isinstance(value, np.ndarray | list | tuple):
        return [_plain(v) for v in value]
    return value


# --------------------------------------------------------------------------------------------
# from objects to the case-file document
# --------------------------------------------------------------------------------------------
def _changed(obj: Any, names: Sequence[str], defaults: Any) -> dict[str, Any]:
    """The attributes of ``obj`` that differ from those of ``defaults`` (a case leaves them out)."""
    return {
        name: _plain(getattr(obj, name))
        for name in names
        if getattr(obj, name) is not None and getattr(obj, name) != getattr(defaults, name)
    }


def _merge_tables(data: dict[str, Any], tables: Mapping[str, Any]) -> None:
    """Add :meth:`Case.from_inputs`' ``tables`` to the document ``data`` built from its other
    arguments; a key or table that those already give is refused (never one over the other)."""
    for name, table in tables.items():
        if name in ("analysis", "dynamics", "study"):
            raise CaseError(
                PYTHON_PATH,
                f"tables.{name}",
                f"the [{name}] keys are runout.run's keyword options (Case.from_inputs' {name} "
                "argument), not a table of tables",
            )
        if isinstance(table, Mapping):
            plain: Any = {key: _plain(value) for key, value in table.items()}
        elif isinstance(table, list | tuple):
            plain = [
                {key: _plain(value) for key, value in entry.items()}
                if isinstance(entry, Mapping)
                else entry
                for entry in table
            ]
        else:
            plain = table  # refused by the schema with the case file's message
        given = data.get(name)
        if given is None:
            data[name] = plain
            continue
        if not (isinstance(given, dict) and isinstance(plain, dict)):
            raise CaseError(PYTHON_PATH, name, "given by the other arguments and in tables")
        for key, value in plain.items():
            if key in given:
                raise CaseError(PYTHON_PATH, f"{name}.{key}", f"given by the {name} and in tables")
            given[key] = value


def _bearing_tables(bearing: Any) -> dict[str, Any]:
    if isinstance(bearing, BallBearing):
        table: dict[str, Any] = {"type": "ball"}
        names: tuple[str, ...] = (
            "elements",
            "element_diameter",
            "pitch_diameter",
            "inner_conformity",
            "outer_conformity",
            "radial_clearance",
            "contact_angle",
            "dynamic_load_rating",
        )
    elif isinstance(bearing, RollerBearing):
        table = {"type": "cylindrical_roller"}
        names = (
            "elements",
            "element_diameter",
            "inner_raceway_diameter",
            "outer_raceway_diameter",
            "roller_length",
        )
    else:
        raise ArgumentTypeError(
            PYTHON_PATH,
            "bearing",
            f"must be a runout.BallBearing or runout.RollerBearing, got {type(bearing).__name__}",
        )
    for name in names:
        value = getattr(bearing, name)
        if value is not None and not (name == "radial_clearance" and value == 0.0):
            table[name] = _plain(value)
    out: dict[str, Any] = {"bearing": table}
    material = _changed(
        bearing.material, ("youngs_modulus", "poisson_ratio", "density"), Material()
    )
    if material:
        out["material"] = material
    return out


_OPERATION_KEYS = (
    "rotating_ring",
    "speed",
    "other_ring_speed",
    "axial_load",
    "preload",
    "radial_load",
    "radial_load_direction",
    "moment_load",
    "moment_load_direction",
)


# --------------------------------------------------------------------------------------------
# the validated case
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Analysis:
    """What to compute: model id, revolutions of the rotating ring, number of instants.

    Attributes
    ----------
    model : str
        Model id (:data:`MODEL_IDS`).
    revolutions : float
        Revolutions of the rotating ring in the record [-].
    samples : int
        Number of instants [-].
    linear_variant : {"radial_spring", "force_balance"}
        Contact model of the linear model.
    race_control : {"outer", "inner", "none"}
        Raceway that resists the gyroscopic moment (equilibrium model).
    ring_tilt : {"free", "held"}
        The inner ring's tilts free (the balls' moment balances the moment load) or held at
        0 (equilibrium model).
    moment_arm : {"curvature_centres", "pitch_radius"}
        Arm of the balls' axial forces in the moment equations (equilibrium model): Harris's
        ℜ_i or ISO/TS 16281's d_m/2.
    bands : {"anderon", "iso15242"} or None
        Band values formed from the lines, if any.
    limit : float or None
        Spec limit in SI: [m] for a runout p-p, [m/s] for an ISO 15242 band.
    limit_on : str
        Quantity the limit applies to: ``"radial_pp"``, ``"rro_pp"``, ``"nrro_pp"``,
        ``"axial_pp"`` or ``"iso15242.<band>"``.
    limit_class : dict or None
        For an ISO 492 tolerance class limit: ``{"class", "bore_m", "source"}`` (the limit is
        its K_ia for the bore, ISO 492:2014); None for a numeric limit.
    bearing_damping : {"none", "kraemer", "proportional"}
        Damping model of the bearing coefficients (equilibrium model):
        :mod:`runout.geometry.bearing_damping`.
    bearing_damping_coefficient : float or None
        The user's β of ``"proportional"`` [s] (c = β k).
    """

    model: str = "quasi_static_3d"
    revolutions: float = 20.0
    samples: int = 4096
    linear_variant: str = "radial_spring"
    race_control: str = "outer"
    ring_tilt: str = "free"
    moment_arm: str = "curvature_centres"
    bands: str | None = None
    limit: float | None = None
    limit_on: str = "radial_pp"
    limit_class: dict[str, Any] | None = None
    bearing_damping: str = "none"
    bearing_damping_coefficient: float | None = None


@dataclass(frozen=True)
class Case:
    """A validated case: every quantity SI, ready for the models.

    Build one from a case file with :func:`load_case`, or in code with
    :meth:`Case.from_inputs` (or let :func:`runout.run` build and run it); do not call the
    constructor yourself: ``spec``, the validated case-file document, is what the models and
    :meth:`to_toml` read.

    Attributes
    ----------
    path : str
        The case file as given, or ``"<python>"`` for a case built in code.
    title : str
        Shown in outputs.
    bearing : BallBearing or RollerBearing
        Geometry and material, SI ([m], [rad], [Pa]).
    operation : Operation
        Speeds [Hz] and loads [N, N m] on the shaft.
    imperfections : runout.geometry.imperfections.BearingImperfections
        The resolved harmonics of every part (what the models use).
    analysis : Analysis
        What to compute.
    spec : CaseSpec
        The validated case-file document.
    profile_data : mapping
        Measured profiles given as arrays: ``[[profile]] file`` name -> (angles [rad],
        deviations [m]); empty for a case read from a file.
    spindle : SpindleLayout or None
        A spindle case's bearings, positions and preload (``[spindle]``, ``[[bearings]]``);
        ``bearing`` and ``imperfections`` are then its first bearing's. None otherwise.
    bearing_sources : tuple of BearingSource
        One per bearing table that names a ``designation``: its catalogue entry, the keys the
        case replaces and the notes (:mod:`runout.case.designation`); empty otherwise.
    """

    path: str
    title: str
    bearing: Bearing
    operation: Operation
    imperfections: BearingImperfections
    analysis: Analysis
    spec: CaseSpec = field(repr=False)
    profile_data: ProfileData = field(default_factory=dict, repr=False, compare=False)
    spindle: SpindleLayout | None = field(default=None, repr=False)
    bearing_sources: tuple[BearingSource, ...] = field(default=(), repr=False, compare=False)

    def bearing_source(self) -> Any:
        """The JSON ``bearing_source`` of a case whose bearings name a ``designation``.

        Returns
        -------
        dict or list or None
            One object (:meth:`runout.case.designation.BearingSource.to_json`) for a single
            bearing, a list for a spindle (``bearing_sources``); None without a designation.
        """
        if not self.bearing_sources:
            return None
        documents = [source.to_json() for source in self.bearing_sources]
        return documents[0] if self.spindle is None and len(documents) == 1 else documents

    @property
    def dynamics(self) -> DynamicsSpec | None:
        """The ``[dynamics]`` table, if any."""
        return self.spec.dynamics

    @property
    def study(self) -> StudySpec | None:
        """The ``[study]`` table, if any."""
        return self.spec.study

    @classmethod
    def from_inputs(
        cls,
        bearing: Bearing,
        operation: Operation | None = None,
        imperfections: Any = None,
        *,
        title: str = "",
        analysis: Mapping[str, Any] | None = None,
        dynamics: Mapping[str, Any] | None = None,
        study: Mapping[str, Any] | None = None,
        base_dir: str | Path | None = None,
        tables: Mapping[str, Any] | None = None,
    ) -> Case:
        """The case a case file with these tables would give, validated the same way.

        Parameters
        ----------
        bearing : BallBearing or RollerBearing
            Geometry and material (``[bearing]``, ``[material]``).
        operation : Operation, optional
            ``[operation]``; default a bearing at rest without load.
        imperfections : runout.Imperfections, optional
            The builder of ``[[waviness]]``, ``[[waviness_spectrum]]``, ``[[profile]]``,
            ``[slant]`` and ``[elements]`` (:class:`runout.case.builder.Imperfections`);
            default none.
        title : str
            Shown in outputs.
        analysis, dynamics, study : mapping, optional
            The ``[analysis]``, ``[dynamics]`` and ``[study]`` keys, by their case-file names:
            SI numbers or strings with units.
        base_dir : str or Path, optional
            Directory that ``[[profile]]`` files are read from; default the working directory.
        tables : mapping, optional
            Any other table of the case file by its name, as the file gives it (SI numbers or
            strings with units): ``{"lubrication": {...}, "sensor": {...}, "defect": [{...},
            ...]}``; under ``"bearing"`` the ``[bearing]`` keys the bearing object has no
            field for (``fatigue_load_limit``).

        Returns
        -------
        Case
            Validated and checked against the budget as a case file would be.

        Raises
        ------
        CaseError
            Naming ``<python>`` and the case key, with the message a case file would give
            (profile arrays beyond the memory budget's points included).
        ArgumentTypeError
            A ``bearing``, ``operation`` or ``imperfections`` of the wrong type: a
            :class:`CaseError` whose key is the argument, and a :class:`TypeError`.
        """
        if operation is not None and not isinstance(operation, Operation):
            raise ArgumentTypeError(
                PYTHON_PATH,
                "operation",
                f"must be a runout.Operation, got {type(operation).__name__}",
            )
        if imperfections is not None and not hasattr(imperfections, "tables"):
            raise ArgumentTypeError(
                PYTHON_PATH,
                "imperfections",
                "must be a runout.Imperfections builder (e.g. "
                "runout.Imperfections(elements=8).waviness('inner', order=9, amplitude=10e-9)), "
                f"got {type(imperfections).__name__}",
            )
        data: dict[str, Any] = {}
        if title:
            data["title"] = title
        data.update(_bearing_tables(bearing))
        if operation is not None:
            changed = _changed(operation, _OPERATION_KEYS, Operation())
            if changed:
                data["operation"] = changed
        if imperfections is not None:
            if imperfections.elements is not None and imperfections.elements != bearing.elements:
                raise CaseError(
                    PYTHON_PATH,
                    "bearing.elements",
                    f"the imperfections were built for elements={imperfections.elements}, the "
                    f"bearing has {bearing.elements}",
                )
            data.update(imperfections.tables())
        for name, table in (("analysis", analysis), ("dynamics", dynamics), ("study", study)):
            if table is not None:
                data[name] = {key: _plain(value) for key, value in table.items()}
        _merge_tables(data, tables or {})
        base = Path.cwd() if base_dir is None else Path(base_dir)
        profiles = imperfections.profile_data if imperfections is not None else {}
        if study is not None and profiles:
            # every sample of a study re-reads the case's profiles from their files
            first = next(iter(profiles))
            index = [p["file"] for p in data.get("profile", [])].index(first) + 1
            raise CaseError(
                PYTHON_PATH,
                f"profile[{index}].file",
                "a study reads its profiles from files: write this one as CSV (Case.save writes "
                "it) and give .profile(..., file=...)",
            )
        return parse_case(data, PYTHON_PATH, base, profile_data=profiles)

    def to_document(self) -> dict[str, Any]:
        """The case-file document (tables of SI numbers) that gives this case again.

        Returns
        -------
        dict
            The keys that were given (keys never set are left out), without None values.
        """
        return self.spec.model_dump(mode="python", exclude_unset=True, exclude_none=True)

    def to_toml(self) -> str:
        """The case as case-file text (SI numbers), for ``runout run`` or :func:`load_case`.

        Keys given at their defaults are written only when they were given; ``[[profile]]``
        files are named as in the case and read relative to the saved file.

        Returns
        -------
        str
            TOML text, tables in the order of the case-file reference.

        Raises
        ------
        CaseError
            A profile given as arrays has no file to name: use :meth:`save`, which writes it.
        """
        if self.profile_data:
            name = next(iter(self.profile_data))
            raise CaseError(
                self.path,
                _profile_key(self.spec, name),
                "was given as arrays and has no file; Case.save(path) writes the case with "
                "its profiles as CSV files next to it",
            )
        return self._toml()

    def _toml(self, files: dict[str, str] | None = None) -> str:
        import tomli_w

        # tables in the order of the case-file reference, and every entry of an array of
        # tables as its own [[table]] (tomli_w would write short ones inline)
        document = self.to_document()
        for entry in document.get("profile", []):  # profiles saved under other names
            entry["file"] = (files or {}).get(entry.get("file", ""), entry.get("file"))
        chunks = []
        top = {k: v for k, v in document.items() if not isinstance(v, dict | list)}
        if top:
            chunks.append(tomli_w.dumps(top))
        for name in CaseSpec.model_fields:
            value = document.get(name)
            if isinstance(value, dict):
                chunks.append(tomli_w.dumps({name: value}))
            elif isinstance(value, list):
                chunks.extend(f"[[{name}]]\n" + tomli_w.dumps(entry) for entry in value)
        return "\n".join(chunk.strip("\n") + "\n" for chunk in chunks)

    def save(self, path: str | Path) -> Path:
        """Write :meth:`to_toml` to ``path``, and profiles given as arrays as CSV beside it.

        Each profile's CSV is named after the case file (``<stem>.<part>_profile_<k>.csv``), so
        that cases saved into one directory do not share a profile file.

        Parameters
        ----------
        path : str or Path
            The case file to write (its directory must exist).

        Returns
        -------
        Path
            The case file written.
        """
        target = Path(path)
        # named after the case file: two cases saved in one directory keep their own profiles
        files = {name: f"{target.stem}.{name}" for name in self.profile_data}
        for name, (angles, deviations) in self.profile_data.items():
            rows = "".join(
                f"{float(a)!r},{float(d)!r}\n" for a, d in zip(angles, deviations, strict=True)
            )
            (target.parent / files[name]).write_text(
                "# angle, radius deviation (units: the case file's [[profile]] entry)\n" + rows,
                encoding="utf-8",
            )
        target.write_text(self._toml(files), encoding="utf-8")
        return target


def _profile_key(spec: CaseSpec, name: str) -> str:
    for i, p in enumerate(spec.profile, start=1):
        if p.file == name:
            return f"profile[{i}].file"
    return "profile"


def _depth(value: object, limit: int) -> int:
    """Nesting depth of tables and arrays, counted up to ``limit + 1`` (no recursion)."""
    stack: list[tuple[object, int]] = [(value, 0)]
    deepest = 0
    while stack:
        node, depth = stack.pop()
        deepest = max(deepest, depth)
        if deepest > limit:
            return deepest
        if isinstance(node, dict):
            stack.extend((v, depth + 1) for v in node.values())
        elif isinstance(node, list):
            stack.extend((v, depth + 1) for v in node)
    return deepest


def parse_case(
    data: dict[str, Any],
    path: str = "<case>",
    base_dir: Path | None = None,
    *,
    profile_data: ProfileData | None = None,
    catalogue: Catalogue | None = None,
) -> Case:
    """Validate a parsed TOML document and build the domain objects.

    Parameters
    ----------
    data : dict
        The TOML document as a dictionary.
    path : str
        File name used in error messages.
    base_dir : Path or None
        Directory that relative file references (profiles) are resolved against, and the only
        one profiles may come from (with those of RUNOUT_PROFILE_DIRS).
    profile_data : mapping, optional
        Profiles given as arrays: ``[[profile]] file`` name -> (angles, deviations) in the
        units of the entry, used instead of reading that file.
    catalogue : runout.catalogue.Catalogue, optional
        The catalogue a ``designation`` is looked up in; default the shipped one extended by
        the file ``RUNOUT_CATALOGUE`` names (:func:`runout.catalogue.active_catalogue`).

    Returns
    -------
    Case

    Raises
    ------
    CaseError
        Naming ``path``, the key path and the problem; also for a case whose estimated memory
        or time exceeds the budget (:mod:`runout.case.limits`).
    """
    if _depth(data, MAX_TOML_DEPTH) > MAX_TOML_DEPTH:
        raise CaseError(path, "", f"tables and arrays are nested deeper than {MAX_TOML_DEPTH}")
    # [bearing] designation: the keys the table leaves out, from the catalogue
    data, pending = expand(data, path, catalogue)
    try:
        spec = CaseSpec.model_validate(data)
    except ValidationError as exc:
        key, message = blame(pending, *first_validation_error(exc))
        raise CaseError(path, key, message) from None
    leave_catalogue_rating_unset(spec, pending)
    try:
        limits = case_budget(spec)
    except GeometryError as exc:
        raise CaseError(path, exc.key, exc.message) from None
    spindle = None
    if spec.bearings:
        # a spindle: each bearing read as its own single-bearing case (the lead one stands
        # for the case's bearing in summaries; the model reads case.spindle)

        spindle, own_cases = build_layout(spec, path, base_dir, profile_data, catalogue)
        bearing = own_cases[0].bearing
    else:
        try:
            bearing = _build_bearing(spec)
        except GeometryError as exc:
            key, message = blame(pending, _GEOMETRY_KEYS.get(exc.key, exc.key), exc.message)
            raise CaseError(path, key, message) from None
    try:
        operation = Operation(
            rotating_ring=spec.operation.rotating_ring,
            speed=spec.operation.speed,
            other_ring_speed=spec.operation.other_ring_speed,
            axial_load=spec.operation.axial_load,
            preload=spec.preload_kind,
            radial_load=spec.operation.radial_load,
            radial_load_direction=spec.operation.radial_load_direction,
            moment_load=spec.operation.moment_load,
            moment_load_direction=spec.operation.moment_load_direction,
        )
    except GeometryError as exc:
        raise CaseError(path, exc.key, exc.message) from None
    try:
        imperfections = (
            own_cases[0].imperfections
            if spindle is not None
            else _build_imperfections(spec, bearing, base_dir or Path.cwd(), limits, profile_data)
        )
    except _CaseKeyError as exc:
        raise CaseError(path, exc.key, exc.message) from None
    except GeometryError as exc:
        raise CaseError(path, exc.key, exc.message) from None
    except ValueError as exc:
        raise CaseError(path, "", str(exc)) from None
    limit_m, limit_class = (
        (None, None) if spec.analysis.limit is None else analysis_limit(spec.analysis)
    )
    analysis = Analysis(
        model=spec.analysis.model,
        revolutions=spec.analysis.revolutions,
        samples=spec.analysis.samples,
        linear_variant=spec.analysis.linear_variant,
        race_control=spec.analysis.race_control,
        # unset: the model's own (free; the case re-serialised for a study keeps it unset)
        ring_tilt=spec.analysis.ring_tilt or "free",
        moment_arm=spec.analysis.moment_arm or "curvature_centres",
        bands=spec.analysis.bands,
        limit=limit_m,
        limit_on=spec.analysis.limit_on,
        limit_class=limit_class,
        bearing_damping=spec.analysis.bearing_damping or "none",
        bearing_damping_coefficient=spec.analysis.bearing_damping_coefficient,
    )
    case = Case(
        path=path,
        title=spec.title,
        bearing=bearing,
        operation=operation,
        imperfections=imperfections,
        analysis=analysis,
        spec=spec,
        profile_data=dict(profile_data or {}),
        spindle=spindle,
        bearing_sources=sources(spec, pending),
    )
    try:
        check_limits(case)
    except GeometryError as exc:
        raise CaseError(path, exc.key, exc.message) from None
    return case


def load_case(
    path: str | Path,
    *,
    model: str | None = None,
    overrides: Mapping[str, Any] | None = None,
) -> Case:
    """Read and validate a TOML case file.

    Only a regular file of at most :data:`runout.case.limits.MAX_CASE_FILE_BYTES` is read (a FIFO
    or /dev/zero is refused before it is opened for reading); a UTF-8 byte-order mark is
    allowed.

    Parameters
    ----------
    path : str or Path
        The case file.
    model : str, optional
        Model id replacing ``[analysis] model`` (``runout run --model``).
    overrides : mapping, optional
        Case keys by dotted path (``"operation.axial_load"``, ``"waviness[2].order"``,
        ``"title"``) -> value as the file would give it (SI number or string with unit),
        replacing or adding that key before validation (``runout run --set``).

    Returns
    -------
    Case

    Raises
    ------
    CaseError
        If the file cannot be read, is not TOML, or is invalid (with the overrides), naming
        the file and the key.
    """
    name = str(path)
    data = read_case_data(path)
    changes = dict(overrides or {})
    if model is not None:
        if "analysis.model" in changes:  # one would silently replace the other
            raise CaseError(name, "analysis.model", "given both as --model and with --set")
        study = data.get("study")
        if isinstance(study, dict) and "models" in study and "study.models" not in changes:
            # a study's models list decides which models run: --model would be ignored
            raise CaseError(
                name,
                "study.models",
                f"the study runs the models it lists; write --set study.models='[\"{model}\"]' "
                "instead of --model",
            )
        changes["analysis.model"] = model
    if not changes:
        return parse_case(data, name, Path(path).parent)
    try:
        apply_overrides(data, changes, name)
        return parse_case(data, name, Path(path).parent)
    except CaseError as exc:
        given = next((k for k in changes if exc.key == k or exc.key.startswith(f"{k}[")), None)
        if given is None:
            raise
        how = "--model" if given == "analysis.model" and model is not None else "--set"
        raise CaseError(name, exc.key, f"{exc.message} (given by {how})") from None


def read_case_data(path: str | Path) -> dict[str, Any]:
    """The TOML document of a case file, read within the size limit, not yet validated.

    Parameters
    ----------
    path : str or Path
        The case file (a regular file of at most
        :data:`~runout.case.limits.MAX_CASE_FILE_BYTES` [B], UTF-8).

    Returns
    -------
    dict
        The parsed TOML document.

    Raises
    ------
    CaseError
        If the file cannot be read or is not TOML.
    """
    p = Path(path)
    name = str(path)
    try:
        info = p.stat()
    except FileNotFoundError:
        raise CaseError(name, "", "no such file") from None
    except OSError as exc:
        raise CaseError(name, "", f"cannot be read ({exc.strerror or exc})") from None
    if stat.S_ISDIR(info.st_mode):
        raise CaseError(name, "", "is a directory, not a case file")
    if not stat.S_ISREG(info.st_mode):
        raise CaseError(name, "", "is not a regular file (a device or FIFO is not a case file)")
    if info.st_size > MAX_CASE_FILE_BYTES:
        raise CaseError(
            name,
            "",
            f"is {format_bytes(info.st_size)}; a case file is at most "
            f"{format_bytes(MAX_CASE_FILE_BYTES)} (put measured data in [[profile]] files)",
        )
    try:
        with p.open("rb") as handle:
            raw = handle.read(MAX_CASE_FILE_BYTES + 1)
    except OSError as exc:
        raise CaseError(name, "", f"cannot be read ({exc.strerror or exc})") from None
    if len(raw) > MAX_CASE_FILE_BYTES:
        raise CaseError(name, "", f"is larger than {format_bytes(MAX_CASE_FILE_BYTES)}")
    try:
        # utf-8-sig: editors on Windows start files with a byte-order mark
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise CaseError(
            name, "", f"is not UTF-8 text (byte {exc.start + 1} cannot be decoded)"
        ) from None
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise CaseError(name, "", f"is not valid TOML: {exc}") from None
    except RecursionError:
        raise CaseError(
            name, "", f"is not valid TOML: nested deeper than {MAX_TOML_DEPTH} levels"
        ) from None


def parse_override(text: str) -> tuple[str, Any]:
    """``KEY=VALUE`` of ``--set`` as (dotted key, value).

    The value is read as a TOML value (``8192``, ``"30 N"``, ``[1, 2]``, ``true``); a bare
    word that is not one (``30 N`` without quotes, ``outer``) is taken as a string.

    Parameters
    ----------
    text : str
        One ``--set`` argument, ``KEY=VALUE``.

    Returns
    -------
    key : str
        The dotted key, stripped.
    value : object
        The TOML value, or the bare text as a string.

    Raises
    ------
    ValueError
        Without ``=`` or without a key.
    """
    key, sep, value = text.partition("=")
    key = key.strip()
    if not sep or not key:
        raise ValueError(f"expected KEY=VALUE (e.g. operation.axial_load='30 N'), got {text!r}")
    value = value.strip()
    try:
        parsed = tomllib.loads(f"v = {value}")
        if set(parsed) == {"v"}:
            return key, parsed["v"]
    except tomllib.TOMLDecodeError:
        pass
    return key, value


_OVERRIDE_KEY = re.compile(r"([a-z_]+)(?:\[(\d+)\])?(?:\.([a-z_]+))?")


def apply_overrides(data: dict[str, Any], overrides: Mapping[str, Any], path: str) -> None:
    """Set case keys by dotted path in a TOML document, in place, before it is validated.

    ``title``, ``table.key``, ``table[i].key`` (entries counted from 1) or
    ``study.vary.KEY`` (a varied quantity, KEY as the file writes it); a table the document
    lacks is created. A key the case does not have is left to the validation, which
    names it with a did-you-mean hint.

    Parameters
    ----------
    data : dict
        The TOML document of a case, changed in place.
    overrides : mapping
        Dotted key path -> value as the file would give it (SI number or string with unit).
    path : str
        File name used in error messages.

    Raises
    ------
    CaseError
        A path that is not a case key's shape, or an array entry the document does not have.
    """
    for key, value in overrides.items():
        if key.startswith(_VARY_PREFIX):  # a study's varied quantity: its key may hold dots
            _override_vary(data, key, value, path)
            continue
        match = _OVERRIDE_KEY.fullmatch(key)
        if match is None:
            raise CaseError(
                path,
                _one_line(key),
                "not a case key: expected 'title', 'table.key' or 'table[i].key' (e.g. "
                "operation.axial_load or waviness[1].order)",
            )
        table, index, name = match.group(1), match.group(2), match.group(3)
        if name is None:
            if index is not None or (table in CaseSpec.model_fields and table != "title"):
                raise CaseError(path, key, "name a key of the table, e.g. 'operation.speed'")
            data[table] = value
            continue
        if index is None:
            section = data.setdefault(table, {})
            if not isinstance(section, dict):
                raise CaseError(
                    path, table, "is an array of tables: name one, e.g. " + table + "[1]"
                )
            section[name] = value
            continue
        entries = data.get(table, [])
        position = int(index)
        if not isinstance(entries, list) or not 1 <= position <= len(entries):
            count = len(entries) if isinstance(entries, list) else 0
            raise CaseError(
                path,
                f"{table}[{position}]",
                f"the case has {count} [[{table}]] entries (counted from 1)",
            )
        entry = entries[position - 1]
        if not isinstance(entry, dict):  # a malformed file: `waviness = [1, 2]`
            raise CaseError(path, f"{table}[{position}]", "is not a table; fix the file first")
        entry[name] = value


_VARY_PREFIX = "study.vary."


def _override_vary(data: dict[str, Any], key: str, value: Any, path: str) -> None:
    """``study.vary.KEY=VALUE``: set (or add) the varied quantity KEY of ``[study.vary]`` (KEY
    as the file writes it, e.g. ``element_diameter_sigma`` or ``"operation.axial_load"``);
    VALUE replaces the whole entry (a value with unit or an inline table)."""
    name = key[len(_VARY_PREFIX) :].strip()
    if len(name) >= 2 and name[0] == name[-1] and name[0] in "\"'":
        name = name[1:-1]
    if not name:
        raise CaseError(
            path, _one_line(key), "name the varied key, e.g. study.vary.element_diameter_sigma"
        )
    study = data.setdefault("study", {})
    if not isinstance(study, dict):
        raise CaseError(path, "study", "is not a table; fix the file first")
    vary = study.setdefault("vary", {})
    if not isinstance(vary, dict):
        raise CaseError(path, "study.vary", "is not a table; fix the file first")
    vary[name] = value


def _one_line(text: str) -> str:
    return "".join(ch if ch.isprintable() else repr(ch)[1:-1] for ch in text)


# --------------------------------------------------------------------------------------------
# spindle cases: one single-bearing case per bearing (parse_case calls build_layout and back)
# --------------------------------------------------------------------------------------------
_TABLES = ("waviness", "waviness_spectrum", "profile")


def _remap(key: str, name: str, index: int, entries: dict[str, list[int]]) -> str:
    """A key of a bearing's own case as the spindle case's key."""
    if key.startswith("bearing."):
        return f"bearings[{index}]." + key[len("bearing.") :]
    if key.startswith("elements"):
        return f"elements.{name}" + key[len("elements") :]
    match = re.match(r"(waviness_spectrum|waviness|profile)\[(\d+)\](.*)", key)
    if match:
        table, k, rest = match.group(1), int(match.group(2)), match.group(3)
        own = entries[table]
        if 1 <= k <= len(own):
            return f"{table}[{own[k - 1]}]{rest}"
    return key


def bearing_document(document: dict[str, Any], name: str) -> tuple[dict[str, Any], dict[str, Any]]:
    """A bearing's single-bearing case document, and the indices of its entries per table.

    Parameters
    ----------
    document : dict
        The spindle case's document (validated, keys as given).
    name : str
        The bearing's ``name`` in ``[[bearings]]``.

    Returns
    -------
    own : dict
        The bearing's own case document (``quasi_static_3d``, the record's ``[analysis]`` keys).
    entries : dict of str to list of int
        Per imperfection table, the indices (from 1) in the spindle case of the entries that
        went into the bearing's case.
    """
    entry = next(b for b in document["bearings"] if b["name"] == name)
    own: dict[str, Any] = {
        "title": document.get("title", ""),
        "bearing": {k: v for k, v in entry.items() if k not in ("name", "position")},
    }
    for table in ("material", "operation"):
        if table in document:
            own[table] = document[table]
    entries: dict[str, list[int]] = {}
    for table in _TABLES:
        rows = document.get(table, [])
        entries[table] = [i for i, row in enumerate(rows, start=1) if row.get("bearing") == name]
        picked = [{k: v for k, v in row.items() if k != "bearing"} for row in rows]
        chosen = [picked[i - 1] for i in entries[table]]
        if chosen:
            own[table] = chosen
    elements = document.get("elements") or {}
    if name in elements:
        own["elements"] = elements[name]
    analysis = {
        k: v
        for k, v in document.get("analysis", {}).items()
        if k in ("revolutions", "samples", "max_memory", "max_time")
    }
    own["analysis"] = {**analysis, "model": "quasi_static_3d"}
    return own, entries


def build_layout(
    spec: CaseSpec,
    path: str,
    base_dir: Path | None,
    profile_data: ProfileData | None,
    catalogue: Catalogue | None = None,
) -> tuple[SpindleLayout, list[Case]]:
    """The spindle of a validated spindle case, and each bearing's own case.

    Parameters
    ----------
    spec : CaseSpec
        The validated spindle case (``[spindle]``, ``[[bearings]]``).
    path : str
        File name used in error messages.
    base_dir : Path or None
        Directory that relative profile files are resolved against.
    profile_data : mapping or None
        Profiles given as arrays: ``[[profile]] file`` name -> (angles, deviations).
    catalogue : runout.catalogue.Catalogue, optional
        The catalogue the bearings' designations were looked up in.

    Returns
    -------
    layout : SpindleLayout
        The bearings at their axial positions [m], arrangement and preload [N or m].
    cases : list of Case
        Each bearing's own single-bearing case, in the case file's order.

    Raises
    ------
    CaseError
        Naming the spindle case's key (``bearings[2].pitch_diameter``, ``waviness[3].order``).
    """
    document = spec.model_dump(mode="python", exclude_unset=True, exclude_none=True)
    assert spec.spindle is not None  # checked by the schema
    bearings: list[SpindleBearing] = []
    cases: list[Case] = []
    for index, b in enumerate(spec.bearings, start=1):
        own, entries = bearing_document(document, b.name)
        try:
            case = parse_case(own, path, base_dir, profile_data=profile_data, catalogue=catalogue)
        except CaseError as exc:
            raise CaseError(path, _remap(exc.key, b.name, index, entries), exc.message) from None
        bearings.append(SpindleBearing(b.name, b.position, case.bearing, case.imperfections))
        cases.append(case)
    try:
        layout = SpindleLayout(
            bearings=tuple(bearings),
            arrangement=spec.spindle.arrangement,
            preload=spec.spindle.preload,
            preload_displacement=spec.spindle.preload_displacement,
            nose_position=spec.spindle.nose_position,
        )
    except GeometryError as exc:
        raise CaseError(path, exc.key, exc.message) from None
    return layout, cases
