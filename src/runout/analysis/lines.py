"""The line types of every result: a spectral line (:class:`Component`), its causes
(:class:`Source`) and the runout figures (:class:`Runout`).

They sit below both the decomposition (:mod:`runout.analysis.decompose`, which fits lines) and
the result (:mod:`runout.analysis.results`, which carries them): one definition for both.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, replace
from typing import Any

__all__ = ["LABEL_MAX", "Component", "Runout", "Source", "short_label"]

#: Longest short label of a component [characters].
LABEL_MAX = 80


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
        """A short readable name, e.g. ``"inner 9 lobes: nZ+1, n=1"``.

        Returns
        -------
        str
            Part (and element, lobe count) with the term; the formula for a combination or
            an unattributed line.
        """
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
        """The JSON contract's source object (its fields, in order).

        Returns
        -------
        dict
            The fields by name (``share`` [-]).
        """
        return asdict(self)


def short_label(sources: tuple[Source, ...] | list[Source]) -> str:
    """The top source's label plus ``+N more``, at most :data:`LABEL_MAX` characters.

    Parameters
    ----------
    sources : tuple or list of Source
        A line's sources, largest share first.

    Returns
    -------
    str
        The label, cut with an ellipsis where too long; ``""`` without sources.
    """
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
        """A fitted line with its ranked sources; the label is the short one.

        Parameters
        ----------
        direction : {"x", "y", "z"}
            Direction of the displacement.
        frequency_hz : float
            Frequency of the line [Hz].
        rotation_hz : float
            Speed of the rotating ring [Hz] (the order and repeatability).
        amplitude : float
            Zero-to-peak amplitude [m].
        phase_rad : float
            Phase of x(t) = amplitude cos(2π f t + φ) [rad].
        sources : list or tuple of Source
            What produces the line, largest share first.

        Returns
        -------
        Component
        """
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
        it, and it is repeatable (RRO) when its order is an integer (to 1e-9).

        Parameters
        ----------
        direction : {"x", "y", "z"}
            Direction of the displacement.
        frequency_hz : float
            Frequency of the line [Hz].
        rotation_hz : float
            Speed of the rotating ring [Hz].
        amplitude : float
            Zero-to-peak amplitude [m].
        phase_rad : float
            Phase of x(t) = amplitude cos(2π f t + φ) [rad].
        label : str
            Which part, lobe count and formula produced it.

        Returns
        -------
        Component
            Without sources.
        """
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
        """The JSON contract's component object.

        Returns
        -------
        dict
            The fields by name (``frequency_hz`` [Hz], ``order`` [-], ``pp_m`` [m],
            ``phase_rad`` [rad]), ``sources`` as a list of source objects.
        """
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
    """Runout figures [m], all peak-to-peak; None for a figure the model does not compute.

    Attributes
    ----------
    radial_pp_m : float or None
        Radial runout along the measuring direction [m]. None for a model without a record
        (``equilibrium``: a static position, no runout).
    axial_pp_m : float or None
        Axial runout [m]. None for a model without an axial degree of freedom (``linear``,
        ``quasi_static_2d``, ``roller_constraint``, ``dynamic`` without ``axial_dof``) or
        without a record: not a zero runout, a quantity the model does not have.
    rro_pp_m : float or None
        Repeatable runout (lines at integer orders of the rotating ring) [m]; None without a
        record.
    nrro_pp_m : float or None
        Non-repeatable runout (the radial record minus its RRO waveform) [m]; None without a
        record.
    """

    radial_pp_m: float | None
    axial_pp_m: float | None
    rro_pp_m: float | None
    nrro_pp_m: float | None

    def to_json(self) -> dict[str, float | None]:
        """The JSON contract's ``runout`` object.

        Returns
        -------
        dict of str to float or None
            The four p-p figures by name [m]; ``null`` for a figure the model does not have.
        """
        return {
            "radial_pp_m": self.radial_pp_m,
            "axial_pp_m": self.axial_pp_m,
            "rro_pp_m": self.rro_pp_m,
            "nrro_pp_m": self.nrro_pp_m,
        }
