"""What every model returns: one result object with analysis methods, JSON and files.

A model fills a :class:`RunResult`: the time (or angle) history of the measured ring's centre,
the labelled spectral lines (``components``), the runout figures and model-specific extras. The
JSON it prints is the documented contract (README, docs/conventions.md, docs/decomposition.md);
``write`` puts data and plots in a directory; ``to_dataframe`` and ``to_xarray`` give the lines
and the history to pandas and xarray (the ``data`` extra, imported when called).
Plotting is delegated to :mod:`runout.plotting` (the only module that imports matplotlib).
"""

from __future__ import annotations

import csv
import json
import math
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from runout.kinematics import Frequencies

__all__ = [
    "DISPLACEMENT_OF",
    "LABEL_MAX",
    "Component",
    "RunResult",
    "Runout",
    "Source",
    "apply_analysis",
    "frequencies_json",
    "write_columns",
]

#: Longest short label of a component [characters].
LABEL_MAX = 80

#: The one displacement convention of every model's output (JSON ``displacement_of``).
DISPLACEMENT_OF = (
    "centre of the inner ring (shaft) relative to the centre of the outer ring (housing), "
    "whichever ring turns; x, y radial, z axial along the axial load on the shaft, from the "
    "rings axially centred; t = 0 at the start of the reported record"
)

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
        :meth:`runout.kinematics.Frequencies.to_dict` or ``orders()`` [Hz or -].
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


#: Rows formatted per call of :func:`write_columns` (bounds its temporary memory: a few MB).
_CSV_CHUNK = 65536


def write_columns(path: Path, header: list[str], columns: list[NDArray[np.float64]]) -> Path:
    """Write equal-length float columns as CSV, the bytes :mod:`csv` would write, fast.

    The same text as a ``csv.writer`` writing ``f"{v:.12g}"`` for every value (comma
    separated, CRLF line ends, header first), formatted by compiled kernels
    (:func:`runout._csvfmt.format_rows`, about ten times faster than Python's formatting,
    which it falls back on for the rare values it cannot prove it rounds the same way).
    Rows are formatted in chunks, so the text in memory stays small.

    Parameters
    ----------
    path : Path
        Output file.
    header : list of str
        Column names (plain names: no comma, quote or line break).
    columns : list of ndarray, each shape (n,)
        The columns [SI units].

    Returns
    -------
    Path
    """
    from runout._csvfmt import format_rows

    data = [np.asarray(c, dtype=np.float64).ravel() for c in columns]
    n = data[0].size if data else 0
    if any(c.size != n for c in data):
        raise ValueError(f"columns differ in length: {[c.size for c in data]}")
    with path.open("wb") as fh:
        fh.write((",".join(header) + "\r\n").encode("ascii"))
        for i0 in range(0, n, _CSV_CHUNK):
            fh.write(format_rows(np.column_stack([c[i0 : i0 + _CSV_CHUNK] for c in data])))
    return path


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
    extras : dict
        Model-specific JSON entries (e.g. ``natural_frequencies_hz``).
    notes : tuple of str
        Warnings a user should read (unloaded balls, assumptions).
    writers : tuple of callables
        Model-specific extra outputs: each ``writer(directory) -> list[Path]`` is called by
        :meth:`write` after the standard files (e.g. contact tables, sweeps, extra plots).
    element : {"ball", "roller"}
        Rolling elements of the bearing (set by :func:`apply_analysis`): names the passage
        frequencies (``roller_pass_*`` aliases in the JSON of a roller bearing).
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
    extras: dict[str, Any] = field(default_factory=dict)
    notes: tuple[str, ...] = ()
    writers: tuple[Callable[[Path], list[Path]], ...] = field(default=(), repr=False, compare=False)
    element: str = "ball"

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
                "displacement_of": DISPLACEMENT_OF,
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
                "displacement_of": DISPLACEMENT_OF,
                "measuring_direction": [float(v) for v in self.measuring_direction],
            },
        )

    def plot(self, kind: str = "lines", ax: Any = None, **options: Any) -> Any:
        """Draw one figure of this result (matplotlib, through :mod:`runout.plotting`).

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
        from runout import plotting

        return plotting.plot_run(self, kind, ax=ax, **options)

    # ---------------------------------------------------------------- output
    def to_json(self) -> dict[str, Any]:
        """One JSON object: the documented contract (README, docs/conventions.md)."""
        out: dict[str, Any] = {
            "model": self.model,
            "title": self.title,
            "frequencies_hz": frequencies_json(self.frequencies.to_dict(), self.element),
            "contact_angle_deg": math.degrees(self.contact_angle),
            "runout": self.runout.to_json(),
            "components": [c.to_json() for c in self.lines()],
            "displacement_of": DISPLACEMENT_OF,
            "mean_displacement_m": self.mean_displacement() if self.time.size else None,
        }
        if self.anderon is not None:
            out["anderon"] = dict(self.anderon)
        out.update(self.extras)
        if self.notes:
            out["notes"] = list(self.notes)
        return out

    def summary_sections(self) -> list[tuple[str, Rows]]:
        """Readable tables: runout figures, the largest lines, band values, verdict, notes.

        Lengths are shown in one unit per table, chosen over the figures it shows
        (:func:`runout.display.length_unit`); figures below :meth:`resolution_m` print as 0,
        and a note states the resolution once. A section whose rows carry no value and no
        unit (the notes, the verdict) is a list of sentences.
        """
        from runout.display import length_unit

        r = self.runout
        resolution = self.resolution_m()
        zeroed: list[float] = []  # figures shown as 0 for being below the resolution

        def show(value: float, unit: tuple[str, float]) -> str:
            if resolution is not None and 0.0 < abs(value) < resolution:
                zeroed.append(value)
            return _length_number(value, unit, resolution)

        label = "radial p-p (measuring direction)"
        iso492 = self.extras.get("iso492")  # the roller model: Kia or Kea
        if isinstance(iso492, dict) and "quantity" in iso492:
            label += f" = {iso492['quantity']} (ISO 492)"
        figures: list[tuple[str, list[float]]] = [(label, [r.radial_pp_m])]
        across = self.extras.get("horizontal_pp_m")  # models that move freely across the load
        if across is not None:
            figures.append(("radial p-p across the load", [float(across)]))
        figures += [
            ("axial p-p", [r.axial_pp_m]),
            ("RRO p-p", [r.rro_pp_m]),
            ("NRRO p-p", [r.nrro_pp_m]),
        ]
        # the p-p figures share one unit; the mean position (play, approaches: often far
        # larger) has its own, so that a nm-size runout is not shown as 0.01 um
        unit = length_unit(v for _, values in figures for v in values)
        rows: Rows = [
            (name, ", ".join(show(v, unit) for v in values), unit[0]) for name, values in figures
        ]
        if self.time.size:
            mean = self.mean_displacement()
            mean_unit = length_unit(mean)
            rows.append(
                (
                    "mean shaft position rel. outer ring (" + ", ".join("xyz"[: len(mean)]) + ")",
                    ", ".join(show(v, mean_unit) for v in mean),
                    mean_unit[0],
                )
            )
        sections: list[tuple[str, Rows]] = [
            (
                f"{self.title or self.model}: runout ({self.model} model, contact angle "
                f"{math.degrees(self.contact_angle):.4g} deg)",
                rows,
            )
        ]
        top = self.lines(top=15)
        line_unit = length_unit(c.pp_m for c in top)
        line_rows: Rows = [
            (
                f"{c.direction}  {c.label}",
                f"{show(c.pp_m, line_unit)} {line_unit[0]} at {c.frequency_hz:.5g} Hz",
                f"order {c.order:.5g}",
            )
            for c in top
        ]
        if line_rows:
            sections.append(("Largest lines (peak-to-peak)", line_rows))
        iso = self.extras.get("iso15242")
        if isinstance(iso, dict):
            sections.append(
                (
                    "ISO 15242-1 velocity bands (rms along the measuring direction"
                    + ("" if iso["direction"] == "measuring" else f" {iso['direction']}")
                    + f", {_plain(iso['speed_rpm'], 6)} rpm)",
                    [
                        (
                            f"{name}  {_plain(b['low_hz'], 4)}-{_plain(b['high_hz'], 4)} Hz",
                            _plain(b["rms_um_per_s"], 4),
                            iso["unit"],
                        )
                        for name, b in iso["bands"].items()
                    ],
                )
            )
        if self.anderon is not None:
            sections.append(
                (
                    "Anderon band values",
                    [(band, _plain(value, 4), "Anderon") for band, value in self.anderon.items()],
                )
            )
        verdict = self.extras.get("verdict")
        if isinstance(verdict, dict):
            sections.append(("Spec limit", [(verdict_line(verdict), "", "")]))
        notes = list(self.notes)
        if zeroed and resolution is not None:
            from runout.display import resolution_note

            notes.insert(0, resolution_note(resolution, unit))
        if notes:
            sections.append(("Notes", [(note, "", "") for note in notes]))
        return sections

    def write(self, directory: Path, *, history_revolutions: float = 3.0) -> list[Path]:
        """Write ``result.json``, ``history.csv``, ``lines.csv`` and plots into ``directory``.

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
        directory.mkdir(parents=True, exist_ok=True)
        written: list[Path] = []
        path = directory / "result.json"
        path.write_text(json.dumps(self.to_json(), indent=2, allow_nan=False) + "\n")
        written.append(path)
        # the record's CSV is formatted by compiled code that releases the GIL: written on a
        # second thread while the figures are drawn (a record of 2^20 instants: 0.3 s each)
        history = directory / "history.csv"
        pool = ThreadPoolExecutor(1, thread_name_prefix="runout-csv")
        pending = pool.submit(
            write_columns, history, ["time_s", "x_m", "y_m", "z_m"], [self.time, *self.displacement]
        )
        try:
            written += self._write_rest(directory, history_revolutions)
        finally:
            pool.shutdown(wait=True)
        pending.result()  # its error, if any (disk full), is this call's
        return [written[0], history, *written[1:]]

    def _write_rest(self, directory: Path, history_revolutions: float) -> list[Path]:
        """``lines.csv``, the figures and the model's own files (:meth:`write`)."""
        written: list[Path] = []
        path = directory / "lines.csv"
        with path.open("w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["direction", "frequency_hz", "order", "pp_m", "phase_rad", "label"])
            for c in self.lines():
                w.writerow(
                    [
                        c.direction,
                        f"{c.frequency_hz:.12g}",
                        f"{c.order:.12g}",
                        f"{c.pp_m:.6g}",
                        f"{c.phase_rad:.6g}",
                        c.label,
                    ]
                )
        written.append(path)
        from runout import plotting

        written += plotting.plot_result(self, directory, history_revolutions=history_revolutions)
        for writer in self.writers:
            written += writer(directory)
        return written


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
# readable figures
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
        from runout.models.dynamic import NEWTON_RTOL

        return max(float(NEWTON_RTOL), ROUND_OFF)
    return ROUND_OFF


def _length_number(value: float, unit: tuple[str, float], resolution: float | None) -> str:
    """The number of :func:`runout.display.format_length`, without the unit."""
    from runout.display import format_length

    return format_length(value, unit, resolution_m=resolution).rsplit(" ", 1)[0]


def _plain(value: float, digits: int) -> str:
    from runout.display import format_number

    return format_number(value, digits)


def verdict_line(verdict: dict[str, Any]) -> str:
    """The PASS/FAIL sentence of a ``verdict`` JSON object."""
    from runout.display import format_length, length_unit

    word = "PASS" if verdict["pass"] else "FAIL"
    relation = "within" if verdict["pass"] else "exceeds"
    quantity = verdict["quantity"]
    if "limit_m" in verdict:
        unit = length_unit([verdict["value_m"], verdict["limit_m"]])
        value = format_length(verdict["value_m"], unit)
        limit = format_length(verdict["limit_m"], unit)
    else:
        value = f"{_plain(verdict['value_um_per_s'], 4)} um/s"
        limit = f"{_plain(verdict['limit_um_per_s'], 4)} um/s"
    return f"{word}: {quantity} = {value} {relation} the limit {limit}"


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


def iso15242_json(result: RunResult) -> dict[str, Any]:
    """The ``iso15242`` JSON object: rms velocity per ISO 15242-1 band from the lines.

    Bands L, M, H with the edges of 1800 rpm scaled to the rotating ring's speed
    (:func:`runout.spectrum.iso15242_band_set`), from the radial lines along the measuring
    direction (:func:`measured_lines`).
    """
    from runout.spectrum import iso15242_band_set, iso15242_bands_from_lines

    rotation = float(result.frequencies.rotation)
    bands = iso15242_band_set(rotation)
    freqs, amps = measured_lines(result)
    values = iso15242_bands_from_lines(freqs, amps, bands).as_dict()
    u = result.measuring_direction
    return {
        "unit": "um/s",
        "speed_rpm": rotation * 60.0,
        "direction": _direction_name(u),
        "measuring_direction": [float(u[0]), float(u[1])],
        "bands": {
            b.name[0]: {"low_hz": b.low, "high_hz": b.high, "rms_um_per_s": values[b.name]}
            for b in bands.bands
        },
    }


def anderon_json(result: RunResult) -> dict[str, float]:
    """Anderon band values from the lines along the measuring direction, in orders."""
    from runout.spectrum import anderon_bands_from_lines

    freqs, amps = measured_lines(result)
    orders = freqs / float(result.frequencies.rotation)
    return anderon_bands_from_lines(orders, amps).as_dict()


def verdict_json(result: RunResult, limit: float, quantity: str) -> dict[str, Any]:
    """The ``verdict`` JSON object: ``quantity`` of ``result`` against ``limit``.

    Parameters
    ----------
    limit : float
        [m] for a runout p-p, [m/s] for a band (``iso15242.L`` ...).
    quantity : str
        ``radial_pp``, ``rro_pp``, ``nrro_pp``, ``axial_pp`` or ``iso15242.<band>``.
    """
    if quantity.startswith("iso15242."):
        iso = result.extras["iso15242"]
        value = float(iso["bands"][quantity.split(".", 1)[1]]["rms_um_per_s"])
        limit_um = limit * 1e6
        return {
            "quantity": quantity,
            "limit_um_per_s": limit_um,
            "value_um_per_s": value,
            "pass": bool(value <= limit_um),
        }
    value_m = float(getattr(result.runout, f"{quantity}_m"))
    return {
        "quantity": quantity,
        "limit_m": limit,
        "value_m": value_m,
        "pass": bool(value_m <= limit),
    }


def apply_analysis(result: RunResult, case: Any) -> RunResult:
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
    from runout.bearing import RollerBearing
    from runout.errors import CaseError

    analysis = case.analysis
    bands = getattr(analysis, "bands", None)
    limit = getattr(analysis, "limit", None)
    limit_on = getattr(analysis, "limit_on", "radial_pp")
    element = "roller" if isinstance(case.bearing, RollerBearing) else "ball"
    extras = dict(result.extras)
    anderon = result.anderon
    if (bands is not None or limit is not None) and result.time.size < 2:
        key = "analysis.bands" if bands is not None else "analysis.limit"
        raise CaseError(
            case.path, key, f"the {result.model} model gives no record (one instant): no lines"
        )
    if bands is not None and not result.frequencies.rotation > 0.0:
        raise CaseError(case.path, "analysis.bands", "band edges need a rotating ring (speed > 0)")
    if bands == "iso15242":
        extras["iso15242"] = iso15242_json(result)
    elif bands == "anderon" and result.model != "linear":
        anderon = anderon_json(result)
    if limit is not None:
        probe = replace(result, extras=extras)
        verdict = verdict_json(probe, float(limit), limit_on)
        if verdict["pass"]:
            _refuse_unseen_pass(probe, case.path, limit_on)
        extras["verdict"] = verdict
    return replace(result, extras=extras, anderon=anderon, element=element)


def _refuse_unseen_pass(result: RunResult, path: str, quantity: str) -> None:
    """Refuse a PASS the record cannot support: predicted lines it does not resolve.

    A line above the Nyquist frequency or below 1/T is left out of the fit (the notes say
    which): the figures and bands are then lower bounds, enough to fail a limit but not to
    pass it. A band also needs the record to reach the band's upper edge.
    """
    from runout.decompose import NOT_FITTED, NOT_FITTED_NYQUIST
    from runout.errors import CaseError

    unseen = [n for n in result.notes if NOT_FITTED in n]
    if quantity.startswith("iso15242.") and result.time.size >= 2:
        band = result.extras["iso15242"]["bands"][quantity.split(".", 1)[1]]
        nyquist = 0.5 / float(result.time[1] - result.time[0])
        if band["high_hz"] > nyquist:
            unseen.append(f"the band reaches {band['high_hz']:.6g} Hz, the record {nyquist:.6g} Hz")
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
