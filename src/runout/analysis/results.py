"""What every model returns: one result object with its analysis and its JSON, read back too.

A model fills a :class:`RunResult`: the time (or angle) history of the measured ring's centre,
the labelled spectral lines (``components``), the runout figures and the model's typed
details (:mod:`runout.analysis.result_details`). The JSON it prints is the documented contract (README,
docs/conventions.md, docs/decomposition.md) and :meth:`RunResult.from_json` reads it back;
``to_dataframe`` and ``to_xarray`` give the lines and the history to pandas and xarray (the
``data`` extra, imported when called). This module neither draws nor writes files: the readable
tables come from :mod:`runout.report.summary`, the files from :mod:`runout.io.result_files` and the
figures from :mod:`runout.report.plotting`; the methods ``summary_sections``, ``write`` and ``plot``
delegate to them.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from runout.analysis.result_details import (
    Iso15242,
    Iso15242Band,
    ModelDetails,
    Verdict,
    details_from_json,
)
from runout.geometry.kinematics import Frequencies

if TYPE_CHECKING:
    from runout.case.model import Case

__all__ = [
    "DISPLACEMENT_OF",
    "LABEL_MAX",
    "SPINDLE_DISPLACEMENT_OF",
    "Component",
    "RunResult",
    "Runout",
    "Source",
    "apply_analysis",
    "displacement_of",
    "frequencies_json",
]

#: Longest short label of a component [characters].
LABEL_MAX = 80

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
    """What a model's displacements are (JSON ``displacement_of``)."""
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
    """
    out = dict(values)
    if element == "roller":
        out.update({alias: values[key] for key, alias in ROLLER_ALIASES.items() if key in values})
    return out


@dataclass(frozen=True)
class Source:
    """One cause of a spectral line.

    Attributes
    ----------
    part : str
        ``"inner"``, ``"outer"``, ``"ball"``, ``"roller"``, ``"pitch"``, ``"slant"``,
        ``"load"`` (the load zone: ball passage), ``"unbalance"``, ``"natural"`` (a natural
        frequency of the rotor), ``"combination"`` (a kinematic combination found in the
        residual) or ``"unattributed"``.
    element : int or None
        Ball or roller number (1-based); None for rings, every element or no element.
    lobes : int or None
        Lobe count of the harmonic (0: a size error); None where it does not apply.
    term : str
        The rule that produced the line, e.g. ``"nZ+1, n=1"``, ``"2n, order 2"``.
    formula : str
        Its frequency, e.g. ``"n f_i + f_r"``.
    share : float
        Fraction of the line's complex amplitude from this source [-] (the shares of a line
        add up to 1; a source working against the others has a negative share).
    share_basis : str
        ``"single"`` (the only source), ``"predicted"`` (from the linearised model's complex
        amplitude), ``"remainder"`` (an equal part of what the predicted sources leave of the
        fitted line) or ``"equal"`` (no prediction: the sources share the line equally).
    """

    part: str
    element: int | None
    lobes: int | None
    term: str
    formula: str
    share: float = 1.0
    share_basis: str = "single"

    def label(self) -> str:
        """A short readable name, e.g. ``"inner 9 lobes: nZ+1, n=1"``."""
        if self.part in ("inner", "outer", "ball", "roller"):
            who = self.part if self.element is None else f"{self.part} {self.element}"
            if self.lobes == 0:
                text = f"{who} size error"
            elif self.lobes is not None:
                text = f"{who} {self.lobes} lobes"
            else:
                text = who
            return f"{text}: {self.term}" if self.term else text
        if self.part in ("combination", "unattributed"):
            return f"{self.part} {self.formula}"
        if self.part == "load":
            return self.term
        return f"{self.part}: {self.term}" if self.term else self.part

    def to_json(self) -> dict[str, Any]:
        """The JSON contract's source object (its fields, in order)."""
        return asdict(self)


def short_label(sources: tuple[Source, ...] | list[Source]) -> str:
    """The top source's label plus ``+N more``, at most :data:`LABEL_MAX` characters."""
    if not sources:
        return ""
    more = f" +{len(sources) - 1} more" if len(sources) > 1 else ""
    text = sources[0].label()
    if len(text) + len(more) > LABEL_MAX:
        text = text[: LABEL_MAX - len(more) - 1] + "…"
    return text + more


@dataclass(frozen=True)
class Component:
    """One spectral line of the output.

    Attributes
    ----------
    direction : {"x", "y", "z"}
        Direction of the displacement.
    frequency_hz : float
        Frequency [Hz].
    order : float
        Frequency / speed of the rotating ring [-].
    pp_m : float
        Peak-to-peak amplitude [m].
    label : str
        Which part, lobe count and formula produced it, e.g. ``"inner 8 lobes: nZ(1+γ)/2 + 1"``.
    phase_rad : float
        Phase of x(t) = (pp/2) cos(2π f t + φ) [rad].
    repeatable : bool
        True when the line is synchronous with the rotating ring (an integer order): RRO.
    sources : tuple of Source
        What produces the line, largest share first.
    """

    direction: str
    frequency_hz: float
    order: float
    pp_m: float
    label: str
    phase_rad: float = 0.0
    repeatable: bool = False
    sources: tuple[Source, ...] = ()

    @classmethod
    def from_sources(
        cls,
        direction: str,
        frequency_hz: float,
        rotation_hz: float,
        amplitude: float,
        phase_rad: float,
        sources: list[Source] | tuple[Source, ...],
    ) -> Component:
        """A fitted line with its ranked sources; the label is the short one."""
        c = cls.fitted(
            direction, frequency_hz, rotation_hz, amplitude, phase_rad, short_label(sources)
        )
        return replace(c, sources=tuple(sources))

    @classmethod
    def fitted(
        cls,
        direction: str,
        frequency_hz: float,
        rotation_hz: float,
        amplitude: float,
        phase_rad: float,
        label: str,
    ) -> Component:
        """A line fitted at ``frequency_hz`` with zero-to-peak ``amplitude`` [m]: p-p is twice
        it, and it is repeatable (RRO) when its order is an integer (to 1e-9)."""
        order = frequency_hz / rotation_hz
        return cls(
            direction=direction,
            frequency_hz=float(frequency_hz),
            order=float(order),
            pp_m=float(2.0 * amplitude),
            label=label,
            phase_rad=float(phase_rad),
            repeatable=bool(abs(order - round(order)) < 1e-9),
        )

    def to_json(self) -> dict[str, Any]:
        """The JSON contract's component object."""
        return {
            "direction": self.direction,
            "frequency_hz": self.frequency_hz,
            "order": self.order,
            "pp_m": self.pp_m,
            "label": self.label,
            "phase_rad": self.phase_rad,
            "repeatable": self.repeatable,
            "sources": [src.to_json() for src in self.sources],
        }


@dataclass(frozen=True)
class Runout:
    """Runout figures [m], all peak-to-peak."""

    radial_pp_m: float
    axial_pp_m: float
    rro_pp_m: float
    nrro_pp_m: float

    def to_json(self) -> dict[str, float]:
        """The JSON contract's ``runout`` object."""
        return {
            "radial_pp_m": self.radial_pp_m,
            "axial_pp_m": self.axial_pp_m,
            "rro_pp_m": self.rro_pp_m,
            "nrro_pp_m": self.nrro_pp_m,
        }


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
        Runout figures.
    measuring_direction : ndarray, shape (2,)
        Unit vector of the radial measuring direction (radial load direction, else x).
    anderon : dict or None
        Band values U, R, L, M, H, E, A [Anderon] where the model gives them.
    details : ModelDetails or None
        The model's own outputs (:mod:`runout.analysis.result_details`, e.g.
        :class:`~runout.analysis.result_details.DynamicDetails` with ``natural_frequencies_hz``); their
        JSON entries follow the common ones.
    notes : tuple of str
        Warnings a user should read (unloaded balls, assumptions).
    element : {"ball", "roller"}
        Rolling elements of the bearing (set by :func:`apply_analysis`): names the passage
        frequencies (``roller_pass_*`` aliases in the JSON of a roller bearing).
    iso15242 : Iso15242 or None
        ISO 15242-1 band values (``[analysis] bands = "iso15242"``, :func:`apply_analysis`).
    verdict : Verdict or None
        The result against ``[analysis] limit`` (:func:`apply_analysis`).
    record_mean : tuple of float or None
        Mean position of a result read back (:meth:`from_json`) as its JSON states it [m]:
        what :meth:`mean_displacement` returns (the record read back from ``history.csv``
        carries 12 digits, the JSON the full mean). None for a model's result.
    stated_contact_angle_deg : float or None
        Contact angle of a result read back, as its JSON states it [deg] (``to_json`` writes
        it again: not every value in degrees is ``math.degrees`` of a float). None for a
        model's result.
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
    stated_contact_angle_deg: float | None = None

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
        """Displacement along the measuring direction [m]."""
        u = self.measuring_direction
        return u[0] * self.displacement[0] + u[1] * self.displacement[1]

    @property
    def axial_motion(self) -> bool:
        """True when the model moves the rings axially (z is part of the output)."""
        return bool(np.any(self.displacement[2] != 0.0))

    def mean_displacement(self) -> list[float]:
        """Mean position of the inner ring's centre relative to the outer ring's over the
        record: x, y, and z when the model moves the rings axially [m]
        (:data:`DISPLACEMENT_OF`)."""
        if self.record_mean is not None:
            return list(self.record_mean)
        mean = [float(np.mean(v)) for v in self.displacement]
        return mean if self.axial_motion else mean[:2]

    def resolution_m(self) -> float | None:
        """The solver's resolution of this record [m]: smaller figures are numerical noise.

        How it is chosen: every model solves the position of the inner ring's centre, whose
        magnitude is at most ``scale`` = max |displacement| over the record (approaches,
        play and offsets included). The quasi-static models stop their Newton iterations at a
        step of ``RTOL`` (1e-11) times the reference approach, and the dynamic model at
        ``NEWTON_RTOL`` (1e-12) times it; the reference approach is below ``scale`` and the
        gain from a contact approach to the centre's motion is of order one, so the relative
        tolerance times ``scale`` bounds the error of each instant. The linear and roller
        models evaluate closed forms or exact constraints: their floor is the float64
        round-off of positions of size ``scale``, bounded generously by
        :data:`ROUND_OFF` (1e-13, about 450 ulp) times ``scale``. Time-integration error
        (dynamic model) is not included: it is a modelling accuracy, not a resolution.

        Returns
        -------
        float or None
            [m]; None for a record that is all zero (nothing to resolve).
        """
        scale = float(np.max(np.abs(self.displacement))) if self.displacement.size else 0.0
        if not (scale > 0.0 and math.isfinite(scale)):
            return None
        return _relative_resolution(self.model) * scale

    def lines(self, direction: str | None = None, top: int | None = None) -> list[Component]:
        """Components, optionally of one direction, largest first, at most ``top`` of them."""
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
        from runout.report import plotting

        return plotting.plot_run(self, kind, ax=ax, **options)

    # ---------------------------------------------------------------- output
    def to_json(self) -> dict[str, Any]:
        """One JSON object: the documented contract (README, docs/conventions.md)."""
        out: dict[str, Any] = {
            "model": self.model,
            "title": self.title,
            "frequencies_hz": frequencies_json(self.frequencies.to_dict(), self.element),
            "contact_angle_deg": (
                math.degrees(self.contact_angle)
                if self.stated_contact_angle_deg is None
                else self.stated_contact_angle_deg
            ),
            "runout": self.runout.to_json(),
            "components": [c.to_json() for c in self.lines()],
            "displacement_of": displacement_of(self.model),
            "mean_displacement_m": (
                self.mean_displacement() if self.time.size or self.record_mean else None
            ),
        }
        if self.anderon is not None:
            out["anderon"] = dict(self.anderon)
        if self.details is not None:
            out.update(self.details.to_json())
        if self.iso15242 is not None:
            out["iso15242"] = self.iso15242.to_json()
        if self.verdict is not None:
            out["verdict"] = self.verdict.to_json()
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
            runout=Runout(**{k: float(v) for k, v in doc["runout"].items()}),
            measuring_direction=_measuring_direction_from(doc),
            anderon=None if anderon is None else {k: float(v) for k, v in anderon.items()},
            details=details_from_json(model, doc),
            notes=tuple(str(n) for n in doc.get("notes", ())),
            element=element,
            iso15242=None if iso is None else Iso15242.from_json(iso),
            verdict=None if verdict is None else Verdict.from_json(verdict),
            record_mean=record_mean,
            stated_contact_angle_deg=float(doc["contact_angle_deg"]),
        )
        if model == "linear" and cls is RunResult:
            from runout.models.linear import linear_result

            return linear_result(result)
        return result

    def summary_sections(self) -> list[tuple[str, Rows]]:
        """Readable tables: runout figures, the largest lines, band values, verdict, notes.

        See :func:`runout.report.summary.result_sections`.
        """
        from runout.report.summary import result_sections

        return result_sections(self)

    def write(self, directory: Path, *, history_revolutions: float = 3.0) -> list[Path]:
        """Write ``result.json``, ``history.csv``, ``lines.csv``, plots and the model's files.

        See :func:`runout.io.result_files.write_result`.

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
        from runout.io.result_files import write_result

        return write_result(self, directory, history_revolutions=history_revolutions)


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


def _relative_resolution(model: str) -> float:
    """Relative tolerance of ``model``'s solved positions [-] (:meth:`RunResult.resolution_m`)."""
    if model in ("quasi_static_2d", "quasi_static_3d"):
        import importlib

        rtol = float(importlib.import_module(f"runout.models.{model}").RTOL)
        return max(rtol, ROUND_OFF)
    if model == "dynamic":
        from runout.models._dynamic_kernels import NEWTON_RTOL

        return max(float(NEWTON_RTOL), ROUND_OFF)
    return ROUND_OFF


# -------------------------------------------------------------------------------------------
# the [analysis] outputs computed from a model's result
# -------------------------------------------------------------------------------------------
def measured_lines(result: RunResult) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Radial lines along the measuring direction: frequencies [Hz], 0-p amplitudes [m].

    The x and y lines of one frequency are combined as phasors,
    ``|u_x X + u_y Y|`` with ``X = (pp_x / 2) exp(i φ_x)``: the line a probe along the
    measuring direction ``u`` would see. Axial (z) lines are left out.
    """
    u = result.measuring_direction
    phasors: dict[float, complex] = {}
    for c in result.components:
        if c.direction not in ("x", "y"):
            continue
        weight = float(u[0] if c.direction == "x" else u[1])
        phasor = 0.5 * c.pp_m * complex(math.cos(c.phase_rad), math.sin(c.phase_rad))
        phasors[c.frequency_hz] = phasors.get(c.frequency_hz, 0j) + weight * phasor
    freqs = np.array(list(phasors), dtype=np.float64)
    amps = np.array([abs(p) for p in phasors.values()], dtype=np.float64)
    return freqs, amps


def _direction_name(u: NDArray[np.float64]) -> str:
    """``"x"`` or ``"y"`` for a measuring direction along an axis, else ``"measuring"``."""
    # a direction given as an angle (-90 deg) leaves cos/sin round-off on the other axis
    if abs(u[1]) < 1e-12:
        return "x"
    if abs(u[0]) < 1e-12:
        return "y"
    return "measuring"


def iso15242_of(result: RunResult) -> Iso15242:
    """RMS velocity per ISO 15242-1 band from the lines (JSON ``iso15242``).

    Bands L, M, H with the edges of 1800 rpm scaled to the rotating ring's speed
    (:func:`runout.analysis.spectrum.iso15242_band_set`), from the radial lines along the measuring
    direction (:func:`measured_lines`).
    """
    from runout.analysis.spectrum import iso15242_band_set, iso15242_bands_from_lines

    rotation = float(result.frequencies.rotation)
    bands = iso15242_band_set(rotation)
    freqs, amps = measured_lines(result)
    values = iso15242_bands_from_lines(freqs, amps, bands).as_dict()
    u = result.measuring_direction
    return Iso15242(
        unit="um/s",
        speed_rpm=rotation * 60.0,
        direction=_direction_name(u),
        measuring_direction=(float(u[0]), float(u[1])),
        bands={b.name[0]: Iso15242Band(b.low, b.high, values[b.name]) for b in bands.bands},
    )


def anderon_json(result: RunResult) -> dict[str, float]:
    """Anderon band values from the lines along the measuring direction, in orders."""
    from runout.analysis.spectrum import anderon_bands_from_lines

    freqs, amps = measured_lines(result)
    orders = freqs / float(result.frequencies.rotation)
    return anderon_bands_from_lines(orders, amps).as_dict()


def verdict_of(result: RunResult, limit: float, quantity: str) -> Verdict:
    """``quantity`` of ``result`` against ``limit`` (JSON ``verdict``).

    Parameters
    ----------
    limit : float
        [m] for a runout p-p, [m/s] for a band (``iso15242.L`` ...).
    quantity : str
        ``radial_pp``, ``rro_pp``, ``nrro_pp``, ``axial_pp`` or ``iso15242.<band>``.
    """
    if quantity.startswith("iso15242."):
        if result.iso15242 is None:
            raise ValueError(f"{quantity}: the result has no ISO 15242 band values")
        value = float(result.iso15242.bands[quantity.split(".", 1)[1]].rms_um_per_s)
        limit_um = limit * 1e6
        return Verdict(quantity, limit_um, value, bool(value <= limit_um), "um/s")
    value_m = float(getattr(result.runout, f"{quantity}_m"))
    return Verdict(quantity, limit, value_m, bool(value_m <= limit), "m")


def apply_analysis(result: RunResult, case: Case) -> RunResult:
    """``result`` with what the case's ``[analysis]`` asks beyond the model: bands, verdict.

    ``bands = "iso15242"`` adds the ``iso15242`` JSON, ``bands = "anderon"`` the Anderon
    values from the lines (the linear model keeps its own, from its exact x lines as seed 002
    measured), ``limit`` the ``verdict``; the bearing's element type names the passage
    frequencies. Idempotent: applying it twice gives the same result.

    Raises
    ------
    CaseError
        A model without a record (one instant) given bands or a limit, or a zero speed with
        bands (band edges scale with the speed).
    """
    from runout.base.errors import CaseError
    from runout.geometry.bearing import RollerBearing

    analysis = case.analysis
    bands = getattr(analysis, "bands", None)
    limit = getattr(analysis, "limit", None)
    limit_on = getattr(analysis, "limit_on", "radial_pp")
    element = "roller" if isinstance(case.bearing, RollerBearing) else "ball"
    iso15242 = result.iso15242
    verdict = result.verdict
    anderon = result.anderon
    if (bands is not None or limit is not None) and result.time.size < 2:
        key = "analysis.bands" if bands is not None else "analysis.limit"
        raise CaseError(
            case.path, key, f"the {result.model} model gives no record (one instant): no lines"
        )
    if bands is not None and not result.frequencies.rotation > 0.0:
        raise CaseError(case.path, "analysis.bands", "band edges need a rotating ring (speed > 0)")
    if bands == "iso15242":
        iso15242 = iso15242_of(result)
    elif bands == "anderon" and result.model != "linear":
        anderon = anderon_json(result)
    if limit is not None:
        probe = replace(result, iso15242=iso15242)
        verdict = verdict_of(probe, float(limit), limit_on)
        if verdict.passed:
            _refuse_unseen_pass(probe, case.path, limit_on)
    return replace(result, iso15242=iso15242, verdict=verdict, anderon=anderon, element=element)


def _refuse_unseen_pass(result: RunResult, path: str, quantity: str) -> None:
    """Refuse a PASS the record cannot support: predicted lines it does not resolve.

    A line above the Nyquist frequency or below 1/T is left out of the fit (the notes say
    which): the figures and bands are then lower bounds, enough to fail a limit but not to
    pass it. A band also needs the record to reach the band's upper edge.
    """
    from runout.analysis.decompose import NOT_FITTED, NOT_FITTED_NYQUIST
    from runout.base.errors import CaseError

    unseen = [n for n in result.notes if NOT_FITTED in n]
    if quantity.startswith("iso15242.") and result.time.size >= 2 and result.iso15242 is not None:
        band = result.iso15242.bands[quantity.split(".", 1)[1]]
        nyquist = 0.5 / float(result.time[1] - result.time[0])
        if band.high_hz > nyquist:
            unseen.append(f"the band reaches {band.high_hz:.6g} Hz, the record {nyquist:.6g} Hz")
    if not unseen:
        return
    high = any(NOT_FITTED_NYQUIST in n or "the band reaches" in n for n in unseen)
    key = "analysis.samples" if high else "analysis.revolutions"
    what = "more samples" if high else "more revolutions"
    raise CaseError(
        path,
        key,
        f"the record does not resolve every predicted line ({unseen[0]}), so {quantity} "
        f"within the limit cannot be shown (it could only fail); give {what}",
    )
