"""What every model returns: one result object with analysis methods, JSON and files.

A model fills a :class:`RunResult`: the time (or angle) history of the measured ring's centre,
the labelled spectral lines (``components``), the runout figures and model-specific extras. The
JSON it prints is the documented contract (README, docs/conventions.md, docs/decomposition.md);
``write`` puts data and plots in a directory.
Plotting is delegated to :mod:`runout.plotting` (the only module that imports matplotlib).
"""

from __future__ import annotations

import csv
import json
import math
from collections.abc import Callable
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

    def lines(self, direction: str | None = None, top: int | None = None) -> list[Component]:
        """Components, optionally of one direction, largest first, at most ``top`` of them."""
        chosen = [c for c in self.components if direction is None or c.direction == direction]
        chosen.sort(key=lambda c: -c.pp_m)
        return chosen[:top] if top is not None else chosen

    # ---------------------------------------------------------------- output
    def to_json(self) -> dict[str, Any]:
        """One JSON object: the documented contract (README, docs/conventions.md)."""
        out: dict[str, Any] = {
            "model": self.model,
            "title": self.title,
            "frequencies_hz": self.frequencies.to_dict(),
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
        """Readable tables: runout figures, the largest lines, band values."""
        r = self.runout
        label = "radial p-p (measuring direction)"
        iso492 = self.extras.get("iso492")  # the roller model: Kia or Kea
        if isinstance(iso492, dict) and "quantity" in iso492:
            label += f" = {iso492['quantity']} (ISO 492)"
        figures: Rows = [(label, f"{r.radial_pp_m * 1e9:.4g}", "nm")]
        across = self.extras.get("horizontal_pp_m")  # models that move freely across the load
        if across is not None:
            figures.append(("radial p-p across the load", f"{across * 1e9:.4g}", "nm"))
        figures += [
            ("axial p-p", f"{r.axial_pp_m * 1e9:.4g}", "nm"),
            ("RRO p-p", f"{r.rro_pp_m * 1e9:.4g}", "nm"),
            ("NRRO p-p", f"{r.nrro_pp_m * 1e9:.4g}", "nm"),
        ]
        if self.time.size:
            mean = self.mean_displacement()
            figures.append(
                (
                    "mean shaft position rel. outer ring (" + ", ".join("xyz"[: len(mean)]) + ")",
                    ", ".join(f"{v * 1e9:.4g}" for v in mean),
                    "nm",
                )
            )
        sections: list[tuple[str, Rows]] = [
            (
                f"{self.title or self.model}: runout ({self.model} model, contact angle "
                f"{math.degrees(self.contact_angle):.4g} deg)",
                figures,
            )
        ]
        rows: Rows = []
        for c in self.lines(top=15):
            rows.append(
                (
                    f"{c.direction}  {c.label}",
                    f"{c.pp_m * 1e9:.4g} nm at {c.frequency_hz:.5g} Hz",
                    f"order {c.order:.5g}",
                )
            )
        if rows:
            sections.append(("Largest lines (peak-to-peak)", rows))
        if self.anderon is not None:
            sections.append(
                (
                    "Anderon band values",
                    [(band, f"{value:.4g}", "Anderon") for band, value in self.anderon.items()],
                )
            )
        if self.notes:
            sections.append(("Notes", [(note, "", "") for note in self.notes]))
        return sections

    def write(self, directory: Path) -> list[Path]:
        """Write ``result.json``, ``history.csv``, ``lines.csv`` and plots into ``directory``.

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
        path = directory / "history.csv"
        write_columns(path, ["time_s", "x_m", "y_m", "z_m"], [self.time, *self.displacement])
        written.append(path)
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

        written += plotting.plot_result(self, directory)
        for writer in self.writers:
            written += writer(directory)
        return written
