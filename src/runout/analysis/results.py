"""What every model returns: one result object with its analysis and its JSON, read back too.

A model fills a :class:`RunResult`: the time (or angle) history of the measured ring's centre,
the labelled spectral lines (``components``), the runout figures and the model's typed
details (:mod:`runout.analysis.result_details`). The JSON it prints is the documented contract
(README, docs/conventions.md, docs/decomposition.md) and :meth:`RunResult.from_json` reads it back;
``to_dataframe`` and ``to_xarray`` give the lines and the history to pandas and xarray (the
``data`` extra, imported when called). This module neither draws nor writes files: the readable
tables come from :mod:`runout.report.summary`, the files from :mod:`runout.io.result_files` and the
figures from :mod:`runout.report.plotting`; the methods ``summary_sections``, ``write`` and ``plot``
delegate to them.
"""

from __future__ import annotations

import importlib
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, cast

import numpy as np
from numpy.typing import NDArray

from runout.analysis.lines import LABEL_MAX, Component, Runout, Source
from runout.analysis.result_details import (
    Iso15242,
    ModelDetails,
    Verdict,
    details_from_json,
)
from runout.geometry.kinematics import Frequencies

__all__ = [
    "DISPLACEMENT_OF",
    "LABEL_MAX",
    "SPINDLE_DISPLACEMENT_OF",
    "Component",
    "RunResult",
    "Runout",
    "Source",
    "displacement_of",
    "frequencies_json",
    "lines_dataframe",
    "record_resolution",
    "stated_resolution",
]

#: The one displacement convention of every model's output (JSON ``displacement_of``).
DISPLACEMENT_OF = (
    "centre of the inner ring (shaft) relative to the centre of the outer ring (housing), "
    "whichever ring turns; x, y radial, z axial along the axial load on the shaft, from the "
    "rings axially centred; t = 0 at the start of the reported record"
)
#: The same for the ``spindle`` model: the shaft at the nose (``spindle.nose_position``).
SPINDLE_DISPLACEMENT_OF = (
    "the shaft (inner rings) at the nose position relative to the housing (outer rings), "
    "whichever turns; x, y radial, z axial along the shaft, from the shaft's preload "
    "reference position; t = 0 at the start of the reported record"
)


def displacement_of(model: str) -> str:
    """What a model's displacements are (JSON ``displacement_of``).

    Parameters
    ----------
    model : str
        Model id.

    Returns
    -------
    str
        :data:`SPINDLE_DISPLACEMENT_OF` for ``"spindle"``, else :data:`DISPLACEMENT_OF`.
    """
    return SPINDLE_DISPLACEMENT_OF if model == "spindle" else DISPLACEMENT_OF


Rows = list[tuple[str, str, str]]

#: Passage-frequency keys of the JSON contract, and their aliases for roller bearings (the
#: ``ball_pass_*`` keys stay for every bearing: the contract is not broken).
ROLLER_ALIASES = {
    "ball_pass_inner": "roller_pass_inner",
    "ball_pass_outer": "roller_pass_outer",
}


def frequencies_json(values: dict[str, float], element: str) -> dict[str, float]:
    """``frequencies_hz`` (or ``orders``) of the JSON contract for ``element`` bearings.

    Parameters
    ----------
    values : dict
        :meth:`runout.geometry.kinematics.Frequencies.to_dict` or ``orders()`` [Hz or -].
    element : {"ball", "roller"}
        Rolling elements of the bearing: a roller bearing also gets ``roller_pass_inner`` and
        ``roller_pass_outer``, equal to ``ball_pass_inner`` and ``ball_pass_outer``.

    Returns
    -------
    dict of str to float
        A copy of ``values`` [Hz or -], with the roller aliases for a roller bearing.
    """
    out = dict(values)
    if element == "roller":
        out.update({alias: values[key] for key, alias in ROLLER_ALIASES.items() if key in values})
    return out


@dataclass(frozen=True)
class RunResult:
    """Result of one model run on one case.

    Attributes
    ----------
    model : str
        Model id.
    title : str
        Case title.
    frequencies : Frequencies
        Characteristic frequencies at the operating contact angle.
    contact_angle : float
        Operating contact angle [rad].
    time : ndarray
        Instants [s] (angle-driven models: rotation angle / (2π speed)).
    displacement : ndarray, shape (3, n)
        x, y, z of the inner ring's centre relative to the outer ring's [m]
        (:data:`DISPLACEMENT_OF`; z zero for planar models).
    components : tuple of Component
        Labelled spectral lines, largest first.
    runout : Runout
        Runout figures [m].
    measuring_direction : ndarray, shape (2,)
        Unit vector of the radial measuring direction (radial load direction, else x) [-].
    anderon : dict or None
        Band values U, R, L, M, H, E, A [Anderon] where the model gives them.
    details : ModelDetails or None
        The model's own outputs (:mod:`runout.analysis.result_details`, e.g.
        :class:`~runout.analysis.result_details.DynamicDetails` with
        ``natural_frequencies_hz``); their JSON entries follow the common ones.
    notes : tuple of str
        Warnings a user should read (unloaded balls, assumptions).
    element : {"ball", "roller"}
        Rolling elements of the bearing (set by
        :func:`runout.runner.analysis.apply_analysis`): names the passage frequencies
        (``roller_pass_*`` aliases in the JSON of a roller bearing).
    iso15242 : Iso15242 or None
        ISO 15242-1 band values [um/s] (``[analysis] bands = "iso15242"``,
        :func:`runout.runner.analysis.apply_analysis`).
    verdict : Verdict or None
        The result against ``[analysis] limit`` (:func:`runout.runner.analysis.apply_analysis`).
    record_mean : tuple of float or None
        Mean position of a result read back (:meth:`from_json`) as its JSON states it [m]:
        what :meth:`mean_displacement` returns (the record read back from ``history.csv``
        carries 12 digits, the JSON the full mean). None for a model's result.
    solver_resolution_m : float or None
        The resolution the model states for this record [m] (:meth:`resolution_m`): the
        floor below which its line fit calls a line round-off, at least the solver
        tolerance's bound; None for a model that states none (the bound is then derived
        from the record), and as the JSON states it for a result read back.
    stated_contact_angle_deg : float or None
        Contact angle of a result read back, as its JSON states it [deg] (``to_json`` writes
        it again: not every value in degrees is ``math.degrees`` of a float). None for a
        model's result.
    bearing_source : dict, list of dict, or None
        Where the bearing's values come from when the case names a ``designation``
        (:meth:`runout.case.designation.BearingSource.to_json`): one object for
        ``[bearing]`` (JSON ``bearing_source``), a list for a spindle's ``[[bearings]]`` (JSON
        ``bearing_sources``); None without a designation.
    signal : runout.analysis.sensor.AccelerationSignal or None
        The housing acceleration (``[analysis] signal = "acceleration"``, dynamic model): JSON
        ``signal`` and ``envelope``, ``run --out`` writes ``signal.csv``.
    """

    model: str
    title: str
    frequencies: Frequencies
    contact_angle: float
    time: NDArray[np.float64]
    displacement: NDArray[np.float64]
    components: tuple[Component, ...]
    runout: Runout
    measuring_direction: NDArray[np.float64] = field(default_factory=lambda: np.array([1.0, 0.0]))
    anderon: dict[str, float] | None = None
    details: ModelDetails | None = None
    notes: tuple[str, ...] = ()
    element: str = "ball"
    iso15242: Iso15242 | None = None
    verdict: Verdict | None = None
    record_mean: tuple[float, ...] | None = None
    solver_resolution_m: float | None = None
    stated_contact_angle_deg: float | None = None
    bearing_source: dict[str, Any] | list[dict[str, Any]] | None = None
    signal: Any = field(default=None, repr=False)

    # ---------------------------------------------------------------- analysis
    @property
    def x(self) -> NDArray[np.float64]:
        """x displacement [m]."""
        return self.displacement[0]

    @property
    def y(self) -> NDArray[np.float64]:
        """y displacement [m]."""
        return self.displacement[1]

    @property
    def z(self) -> NDArray[np.float64]:
        """Axial displacement [m]."""
        return self.displacement[2]

    def radial(self) -> NDArray[np.float64]:
        """Displacement along the measuring direction [m].

        Returns
        -------
        ndarray, shape (n,)
            u_x x + u_y y with u the measuring direction [m].
        """
        u = self.measuring_direction
        return u[0] * self.displacement[0] + u[1] * self.displacement[1]

    @property
    def has_axial_freedom(self) -> bool:
        """True when the model has an axial degree of freedom (an axial runout to report).

        ``linear``, ``quasi_static_2d`` and ``roller_constraint`` are radial models, and
        ``dynamic`` is one unless ``[dynamics] axial_dof`` is set: their axial p-p is not zero
        but not a quantity they compute, so ``runout.axial_pp_m`` is None, the JSON gives
        ``null`` and the text ``n/a``.
        """
        if self.model == "dynamic":
            return bool(getattr(self.details, "axial_dof", False))
        return self.model in AXIAL_MODELS

    @property
    def axial_motion(self) -> bool:
        """True when the model moves the rings axially (z is part of the output)."""
        return bool(np.any(self.displacement[2] != 0.0))

    def mean_displacement(self) -> list[float]:
        """Mean position of the inner ring's centre relative to the outer ring's over the
        record: x, y, and z when the model moves the rings axially [m]
        (:data:`DISPLACEMENT_OF`).

        Returns
        -------
        list of float
            x, y (and z) [m]; the JSON's mean for a result read back.
        """
        if self.record_mean is not None:
            return list(self.record_mean)
        mean = [float(np.mean(v)) for v in self.displacement]
        return mean if self.axial_motion else mean[:2]

    def resolution_m(self) -> float | None:
        """The solver's resolution of this record [m]: smaller figures are numerical noise.

        What the model states (:attr:`solver_resolution_m`) when it states one, else the
        bound :func:`record_resolution` derives from the record. Every display (summary,
        report, study tables) and the JSON's ``solver_resolution_m`` use this one number.

        Returns
        -------
        float or None
            [m]; None for a record that is all zero and a model that states nothing.
        """
        if self.solver_resolution_m is not None:
            return self.solver_resolution_m
        return record_resolution(self.model, self.displacement)

    def lines(self, direction: str | None = None, top: int | None = None) -> list[Component]:
        """Components, optionally of one direction, largest first, at most ``top`` of them.

        Parameters
        ----------
        direction : {"x", "y", "z"} or None
            Direction of the lines to keep; None: all of them.
        top : int or None
            Most lines returned; None: all of them.

        Returns
        -------
        list of Component
            By p-p [m], largest first.
        """
        chosen = [c for c in self.components if direction is None or c.direction == direction]
        chosen.sort(key=lambda c: -c.pp_m)
        return chosen[:top] if top is not None else chosen

    # ---------------------------------------------------------------- data
    def to_dataframe(self) -> Any:
        """The spectral lines as a :class:`pandas.DataFrame`, one row per line, largest first.

        Columns: ``direction`` (x, y, z), ``frequency_hz`` [Hz], ``order`` [-],
        ``pp_m`` (peak-to-peak [m]), ``phase_rad`` [rad], ``repeatable`` (True for RRO),
        ``label`` (the line's short label, as in the JSON) and ``top_source`` (the label of
        its largest source, empty for a line with no source). ``df.attrs`` holds ``units``
        (column -> unit), ``model``, ``title`` and ``displacement_of``.

        Returns
        -------
        pandas.DataFrame

        Raises
        ------
        ImportError
            pandas is not installed (``pip install "runout[data]"``).
        """
        pd = _optional("pandas")
        rows = [
            {
                "direction": c.direction,
                "frequency_hz": c.frequency_hz,
                "order": c.order,
                "pp_m": c.pp_m,
                "phase_rad": c.phase_rad,
                "repeatable": c.repeatable,
                "label": c.label,
                "top_source": c.sources[0].label() if c.sources else "",
            }
            for c in self.lines()
        ]
        # the columns exist even without a line: code selecting them must not break
        df = pd.DataFrame(rows, columns=list(LINE_COLUMNS))
        df.attrs.update(
            {
                "units": dict(LINE_COLUMNS),
                "model": self.model,
                "title": self.title,
                "displacement_of": displacement_of(self.model),
            }
        )
        return df

    def to_xarray(self) -> Any:
        """The history as an :class:`xarray.DataArray` of dims ``(direction, time)``.

        Coordinates: ``direction`` = x, y, z and ``time`` [s]; values [m] are the
        displacement of :data:`DISPLACEMENT_OF` (z is zero for planar models). ``attrs``:
        ``units`` (m), ``model``, ``title``, ``displacement_of`` and ``measuring_direction``
        (unit vector, x and y); the time coordinate's ``attrs["units"]`` is s.

        Returns
        -------
        xarray.DataArray

        Raises
        ------
        ImportError
            xarray is not installed (``pip install "runout[data]"``).
        """
        xr = _optional("xarray")
        time = xr.Variable(
            "time",
            np.asarray(self.time, dtype=np.float64),
            attrs={"units": "s", "long_name": "time"},
        )
        return xr.DataArray(
            np.asarray(self.displacement, dtype=np.float64),
            dims=("direction", "time"),
            coords={"direction": ["x", "y", "z"], "time": time},
            name="displacement",
            attrs={
                "units": "m",
                "long_name": "displacement of the inner ring's centre",
                "model": self.model,
                "title": self.title,
                "displacement_of": displacement_of(self.model),
                "measuring_direction": [float(v) for v in self.measuring_direction],
            },
        )

    def plot(self, kind: str = "lines", ax: Any = None, **options: Any) -> Any:
        """Draw one figure of this result (matplotlib, through :mod:`runout.report.plotting`).

        Parameters
        ----------
        kind : {"lines", "history", "orbit", "spectrum"}
            ``"lines"``: p-p [m] of the labelled lines against their order;
            ``"history"``: x, y (and z) about their mean [m] against revolutions of the
            rotating ring (time [s] at zero speed); ``"orbit"``: y against x [m];
            ``"spectrum"``: the amplitude spectrum (p-p [m]) of x and y against frequency [Hz].
        ax : matplotlib.axes.Axes, optional
            Axes to draw into; a new figure when None.
        **options
            Passed to the drawing function (e.g. ``revolutions`` for ``"history"``).

        Returns
        -------
        matplotlib.axes.Axes
        """
        # results are data: the figure is drawn by the report layer above, found at call time
        plotting = importlib.import_module("runout.report.plotting")
        return plotting.plot_run(self, kind, ax=ax, **options)

    # ---------------------------------------------------------------- output
    def to_json(self) -> dict[str, Any]:
        """One JSON object: the documented contract (README, docs/conventions.md).

        Returns
        -------
        dict
            Model, title, frequencies [Hz], contact angle [deg], runout [m], components, the
            displacement convention and mean [m], then the optional ``anderon``, the model's
            details, ``iso15242``, ``verdict`` and ``notes``.
        """
        out: dict[str, Any] = {
            "model": self.model,
            "title": self.title,
            "frequencies_hz": frequencies_json(self.frequencies.to_dict(), self.element),
            "contact_angle_deg": (
                math.degrees(self.contact_angle)
                if self.stated_contact_angle_deg is None
                else self.stated_contact_angle_deg
            ),
            # null for a figure the model does not have (Runout): never 0
            "runout": self.runout.to_json(),
            "components": [c.to_json() for c in self.lines()],
            "displacement_of": displacement_of(self.model),
            "mean_displacement_m": (
                self.mean_displacement() if self.time.size or self.record_mean else None
            ),
        }
        resolution = self.resolution_m()
        if resolution is not None:
            # below it a figure is not a result (the summary and report print it as 0)
            out["solver_resolution_m"] = resolution
        if self.anderon is not None:
            out["anderon"] = dict(self.anderon)
        if self.details is not None:
            out.update(self.details.to_json())
        if self.iso15242 is not None:
            out["iso15242"] = self.iso15242.to_json()
        if self.verdict is not None:
            out["verdict"] = self.verdict.to_json()
        if isinstance(self.bearing_source, dict):
            out["bearing_source"] = self.bearing_source
        elif self.bearing_source is not None:
            out["bearing_sources"] = list(self.bearing_source)
        if self.signal is not None:
            out["signal"] = self.signal.to_json()
            out["envelope"] = self.signal.envelope
        if self.notes:
            out["notes"] = list(self.notes)
        return out

    @classmethod
    def from_json(
        cls,
        doc: dict[str, Any],
        *,
        time: NDArray[np.float64] | None = None,
        displacement: NDArray[np.float64] | None = None,
    ) -> RunResult:
        """Read a result back from its JSON object (:meth:`to_json`, a ``result.json``).

        ``from_json(doc).to_json()`` is ``doc`` again, key for key. The JSON holds no record:
        give ``time`` and ``displacement`` (``history.csv``,
        :func:`runout.io.result_files.read_result`) for the figures and the resolution; the mean
        position is the JSON's either way (:attr:`record_mean`). A linear model's result
        comes back as a :class:`~runout.models.linear.LinearResult` whose lines are rebuilt
        from the components.

        Parameters
        ----------
        doc : dict
            The JSON object.
        time : ndarray, shape (n,), optional
            Instants [s].
        displacement : ndarray, shape (3, n), optional
            x, y, z [m] (:data:`DISPLACEMENT_OF`).

        Returns
        -------
        RunResult

        Raises
        ------
        ValueError
            Only one of ``time`` and ``displacement``, or shapes that differ.
        """
        if (time is None) != (displacement is None):
            raise ValueError("give both time and displacement, or neither")
        if time is None or displacement is None:
            t = np.zeros(0)
            disp = np.zeros((3, 0))
        else:
            t = np.asarray(time, dtype=np.float64)
            disp = np.asarray(displacement, dtype=np.float64)
            if disp.shape != (3, t.size):
                raise ValueError(f"displacement must have shape (3, {t.size}), got {disp.shape}")
        mean = doc.get("mean_displacement_m")
        record_mean = None if mean is None else tuple(float(v) for v in mean)
        model = str(doc["model"])
        freqs = {k: float(v) for k, v in doc["frequencies_hz"].items()}
        element = "roller" if all(a in freqs for a in ROLLER_ALIASES.values()) else "ball"
        for alias in ROLLER_ALIASES.values():
            freqs.pop(alias, None)
        iso = doc.get("iso15242")
        verdict = doc.get("verdict")
        anderon = doc.get("anderon")
        result = cls(
            model=model,
            title=str(doc["title"]),
            frequencies=Frequencies(**freqs),
            contact_angle=_radians_exactly(float(doc["contact_angle_deg"])),
            time=t,
            displacement=disp,
            components=tuple(_component_from_json(c) for c in doc["components"]),
            runout=_runout_from(model, doc),
            measuring_direction=_measuring_direction_from(doc),
            anderon=None if anderon is None else {k: float(v) for k, v in anderon.items()},
            details=details_from_json(model, doc),
            notes=tuple(str(n) for n in doc.get("notes", ())),
            element=element,
            iso15242=None if iso is None else Iso15242.from_json(iso),
            verdict=None if verdict is None else Verdict.from_json(verdict),
            record_mean=record_mean,
            solver_resolution_m=_optional_float(doc.get("solver_resolution_m")),
            stated_contact_angle_deg=float(doc["contact_angle_deg"]),
            bearing_source=doc.get("bearing_source", doc.get("bearing_sources")),
            signal=_signal_from(doc),
        )
        if model == "linear" and cls is RunResult:
            # the linear model's result type lives with the model (a layer above), by name
            linear = importlib.import_module("runout.models.linear")
            return cast(RunResult, linear.linear_result(result))
        return result

    def summary_sections(self) -> list[tuple[str, Rows]]:
        """Readable tables: runout figures, the largest lines, band values, verdict, notes.

        See :func:`runout.report.summary.result_sections`.

        Returns
        -------
        list of (str, list of (str, str, str))
            Each section's title and its rows (quantity, value, unit).
        """
        summary = importlib.import_module("runout.report.summary")  # the layer above, by name
        return cast("list[tuple[str, Rows]]", summary.result_sections(self))

    def write(self, directory: Path, *, history_revolutions: float = 3.0) -> list[Path]:
        """Write ``result.json``, ``history.csv``, ``lines.csv``, plots and the model's files.

        See :func:`runout.report.run_files.write_result`.

        Parameters
        ----------
        directory : Path
            Output directory (created).
        history_revolutions : float
            Revolutions of the rotating ring the time-history figure shows (the last ones).

        Returns
        -------
        list of Path
            The files written.
        """
        # the files are written by the report layer above (figures included), found at call time
        files = importlib.import_module("runout.report.run_files")
        return cast(
            "list[Path]",
            files.write_result(self, directory, history_revolutions=history_revolutions),
        )


def _component_from_json(doc: dict[str, Any]) -> Component:
    """A :class:`Component` from its JSON object."""
    return Component(
        direction=str(doc["direction"]),
        frequency_hz=float(doc["frequency_hz"]),
        order=float(doc["order"]),
        pp_m=float(doc["pp_m"]),
        label=str(doc["label"]),
        phase_rad=float(doc["phase_rad"]),
        repeatable=bool(doc["repeatable"]),
        sources=tuple(Source(**src) for src in doc["sources"]),
    )


def _signal_from(doc: dict[str, Any]) -> Any:
    """The ``signal`` and ``envelope`` of a run's JSON (an acceleration signal), or None."""
    if "signal" not in doc:
        return None
    from runout.analysis.sensor import AccelerationSignal

    return AccelerationSignal.from_json(doc["signal"], doc.get("envelope", {}))


def _radians_exactly(degrees: float) -> float:
    """An angle [rad] whose ``math.degrees`` is ``degrees`` where a float near
    ``math.radians(degrees)`` has it (not every value has one: then ``math.radians``)."""
    angle = math.radians(degrees)
    for direction in (math.inf, -math.inf):
        probe = angle
        for _ in range(4):
            if math.degrees(probe) == degrees:
                return probe
            probe = math.nextafter(probe, direction)
    return angle


def _measuring_direction_from(doc: dict[str, Any]) -> NDArray[np.float64]:
    """The measuring direction of a result's JSON: the ISO 15242 object states it; otherwise
    the mean of the x and y lines cannot, so it is +x unless the model's details say so."""
    iso = doc.get("iso15242")
    if iso is not None:
        u = iso["measuring_direction"]
        return np.array([float(u[0]), float(u[1])])
    return np.array([1.0, 0.0])


def _runout_from(model: str, doc: dict[str, Any]) -> Runout:
    """The ``runout`` object of a result JSON; null stays None (a figure the model lacks).

    Files written before these figures were null hold 0.0 where the model had no figure: an
    equilibrium result's four zeros and a radial model's axial 0.0 read back as None too.
    """
    figures: dict[str, float | None] = {
        k: None if v is None else float(v) for k, v in doc["runout"].items()
    }
    if model == "equilibrium":  # a static position, never a runout record
        figures = dict.fromkeys(figures)
    radial_model = model not in AXIAL_MODELS and not (
        model == "dynamic" and bool(doc.get("axial_dof", False))
    )
    if radial_model:
        figures["axial_pp_m"] = None
    return Runout(**figures)


#: Models with an axial degree of freedom (``dynamic`` has one with ``axial_dof``):
#: :attr:`RunResult.has_axial_freedom`.
AXIAL_MODELS = frozenset({"quasi_static_3d", "spindle", "equilibrium"})

#: Columns of :meth:`RunResult.to_dataframe` and their units.
LINE_COLUMNS: dict[str, str] = {
    "direction": "-",
    "frequency_hz": "Hz",
    "order": "-",
    "pp_m": "m",
    "phase_rad": "rad",
    "repeatable": "-",
    "label": "-",
    "top_source": "-",
}


def lines_dataframe(
    results: Mapping[str, RunResult] | Sequence[RunResult], key: str = "run"
) -> Any:
    """The lines of several results in one :class:`pandas.DataFrame`, units kept.

    ``pandas.concat`` keeps ``attrs`` only where every frame has the same ones, and the
    ``model`` and ``title`` of two runs differ: concatenated, the units were lost. Here the
    rows of each result get a column ``key`` naming the run, and ``attrs`` keeps ``units``
    (column -> unit, ``key`` included) and, under ``runs``, each run's ``model``, ``title`` and
    ``displacement_of``.

    Parameters
    ----------
    results : mapping of str to RunResult, or sequence of RunResult
        The runs, by name; a sequence names each run by its model (which must then differ).
    key : str
        Name of the column that says which run a row comes from.

    Returns
    -------
    pandas.DataFrame
        The columns of :meth:`RunResult.to_dataframe` plus ``key``, one row per line
        (``pp_m`` [m], ``frequency_hz`` [Hz], ``phase_rad`` [rad]).

    Raises
    ------
    ValueError
        Two results of a sequence share a model, ``key`` is a column already, or no result.
    ImportError
        pandas is not installed (``pip install "runout[data]"``).
    """
    pd = _optional("pandas")
    named = dict(results) if isinstance(results, Mapping) else {r.model: r for r in results}
    if not isinstance(results, Mapping) and len(named) != len(results):
        raise ValueError("two results of the same model: pass them as a mapping name -> result")
    if not named:
        raise ValueError("no result to put in the table")
    if key in LINE_COLUMNS:
        raise ValueError(f"key {key!r} is a column of the lines already")
    frames = [r.to_dataframe().assign(**{key: name}) for name, r in named.items()]
    df = pd.concat(frames, ignore_index=True)
    df.attrs = {
        "units": {**LINE_COLUMNS, key: "-"},
        "runs": {
            name: {
                "model": r.model,
                "title": r.title,
                "displacement_of": displacement_of(r.model),
            }
            for name, r in named.items()
        },
    }
    return df


def _optional(module: str) -> Any:
    """Import ``module`` of the ``data`` extra, or say how to install it."""
    import importlib

    try:
        return importlib.import_module(module)
    except ImportError as exc:
        raise ImportError(
            f"{module} is needed for this (tables and labelled arrays of results): "
            'pip install "runout[data]"'
        ) from exc


# -------------------------------------------------------------------------------------------
# resolution
# -------------------------------------------------------------------------------------------
#: Relative round-off floor of a model without an iterative solver (closed forms, exact
#: constraints): about 450 ulp of float64, well above the round-off of a few operations.
ROUND_OFF = 1e-13


#: Newton step tolerance of each iterative model, relative to its reference approach [-]: the
#: models solve to it (they read it from here) and a result states its resolution with it.
SOLVER_RTOL: dict[str, float] = {
    "quasi_static_2d": 1e-11,
    "quasi_static_3d": 1e-11,
    "dynamic": 1e-12,
    "spindle": 1e-11,
}


def _relative_resolution(model: str) -> float:
    """Relative tolerance of ``model``'s solved positions [-] (:func:`record_resolution`)."""
    return max(SOLVER_RTOL.get(model, 0.0), ROUND_OFF)


def _optional_float(value: Any) -> float | None:
    return None if value is None else float(value)


def record_resolution(model: str, displacement: NDArray[np.float64]) -> float | None:
    """The solver tolerance's bound on the error of a record's positions [m].

    Every model solves the position of the inner ring's centre, whose magnitude is at most
    ``scale`` = max |displacement| over the record (approaches, play and offsets included).
    The iterative models stop their Newton iterations at a step of :data:`SOLVER_RTOL` times
    their reference approach, which is below ``scale``, with a gain of order one from an
    approach to the centre's motion: the relative tolerance times ``scale`` bounds the
    error of each instant. The linear and roller models evaluate closed forms or exact
    constraints: their floor is the float64 round-off of positions of size ``scale``,
    bounded generously by :data:`ROUND_OFF` (1e-13, about 450 ulp) times ``scale``.
    Time-integration error (dynamic model) is not included: a modelling accuracy, not a
    resolution.

    Parameters
    ----------
    model : str
        Model id.
    displacement : ndarray, shape (3, n)
        The record [m].

    Returns
    -------
    float or None
        [m]; None for a record that is empty or all zero (nothing to resolve).
    """
    scale = float(np.max(np.abs(displacement))) if displacement.size else 0.0
    if not (scale > 0.0 and math.isfinite(scale)):
        return None
    return _relative_resolution(model) * scale


def stated_resolution(
    model: str, displacement: NDArray[np.float64], line_floor_m: float
) -> float | None:
    """The resolution a model states for its record [m] (:attr:`RunResult.solver_resolution_m`).

    The larger of the floor below which the model's line fit calls a line its solver's
    round-off (``line_floor_m``, e.g. 1e-9 of the reference approach for a solver that stops
    at 1e-11 of it) and the tolerance's bound on the positions (:func:`record_resolution`):
    one number below which no figure is a result, for the lines and the p-p figures alike.

    Parameters
    ----------
    model : str
        Model id.
    displacement : ndarray, shape (3, n)
        The record [m].
    line_floor_m : float
        The line fit's floor [m].

    Returns
    -------
    float or None
        [m]; None when both are 0 (nothing to resolve).
    """
    bound = record_resolution(model, displacement) or 0.0
    resolution = max(float(line_floor_m), bound)
    return resolution if resolution > 0.0 else None
