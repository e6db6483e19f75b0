"""One name per quantity: the glossary table, its page, the case keys and the Python names."""

from __future__ import annotations

import dataclasses
import inspect
import re
import typing
from pathlib import Path
from typing import Any

import pytest

from runout.base import glossary
from runout.case.model import BearingSpec, MaterialSpec, OperationSpec
from runout.geometry.bearing import BallBearing, Material, Operation, RollerBearing

DOC = Path(__file__).resolve().parents[3] / "docs" / "glossary.md"
SPECS = {"bearing": BearingSpec, "operation": OperationSpec, "material": MaterialSpec}
CLASSES = (BallBearing, RollerBearing, Operation, Material)
#: SI unit of each quantity kind of the case schema (runout.base.units), as the glossary writes it.
KIND_UNIT = {
    "length": "m",
    "force": "N",
    "pressure": "Pa",
    "density": "kg/m³",
    "angle": "rad",
    "speed": "Hz",
    "dimensionless": "–",
    "moment": "N m",
}


def test_glossary_page_is_current() -> None:
    # Regenerate with: python -m runout.base.glossary > docs/glossary.md
    assert DOC.read_text(encoding="utf-8") == glossary.glossary_markdown()


def test_every_name_is_defined_once() -> None:
    found = glossary.names()
    assert sum(len(t.names) for t in glossary.TERMS) == len(found)
    assert glossary.term("element_diameter").unit == "m"
    with pytest.raises(KeyError):
        glossary.term("ball_diameter")  # a deprecated name is not a glossary name


def test_a_name_in_two_rows_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    twice = (*glossary.TERMS, glossary.Term(("speed",), "n", "rpm", "another speed"))
    monkeypatch.setattr(glossary, "TERMS", twice)
    with pytest.raises(ValueError, match="'speed' is defined twice"):
        glossary.names()


def _spec_unit(info: Any) -> str:
    """SI unit of a case key: from the quantity kind its validator converts to; a count, a
    text choice or a plain number has none."""
    # an optional key (Length | None) keeps its validator inside the union
    metadata = list(info.metadata)
    for arg in typing.get_args(info.annotation):
        metadata += list(getattr(arg, "__metadata__", ()))
    for meta in metadata:
        kind = getattr(getattr(meta, "func", None), "kind", None)
        if kind is not None:
            return KIND_UNIT[kind]
    return "–"


_PARAM = re.compile(r"^(\w+) : [^\n]*\n((?:    [^\n]*\n?)+)", re.MULTILINE)


def _doc_units(cls: type) -> dict[str, str]:
    """Parameter name -> its unit in the class's numpydoc docstring (``[m]``; none: "–")."""
    units: dict[str, str] = {}
    for name, text in _PARAM.findall(inspect.cleandoc(cls.__doc__ or "")):
        found = re.search(r"\[([^\]]+)\]", text)
        unit = found.group(1) if found else "-"
        units[name] = {"-": "–", "kg/m^3": "kg/m³"}.get(unit, unit)
    return units


def _public_fields(cls: type) -> list[str]:
    return [f.name for f in dataclasses.fields(cls) if not f.name.startswith("_")]


def test_every_case_key_and_python_field_is_in_the_glossary() -> None:
    found = glossary.names()
    keys = {f"[{table}] {k}": k for table, spec in SPECS.items() for k in spec.model_fields}
    fields = {f"{cls.__name__}.{f}": f for cls in CLASSES for f in _public_fields(cls)}
    missing = sorted(where for where, name in {**keys, **fields}.items() if name not in found)
    assert missing == []
    assert all(found[name].key for name in {**keys, **fields}.values())  # shown as code


def test_case_keys_python_names_and_glossary_agree_on_units() -> None:
    found = glossary.names()
    shared = 0
    for table, spec in SPECS.items():
        for key, info in spec.model_fields.items():
            unit = _spec_unit(info)
            assert found[key].unit == unit, f"[{table}] {key}: glossary {found[key].unit}"
            for cls in CLASSES:
                if key in _public_fields(cls):
                    shared += 1
                    doc = _doc_units(cls)[key]
                    assert doc == unit, f"{cls.__name__}.{key} [{doc}] vs [{table}] {key} [{unit}]"
    # the promise covers every constructor argument that is also a case key
    assert shared >= 20
    for cls in CLASSES:  # and a Python-only field (material) has the glossary's unit too
        for name, doc in _doc_units(cls).items():
            assert found[name].unit == doc, f"{cls.__name__}.{name} [{doc}]"


def test_the_unit_check_sees_a_disagreement() -> None:
    class Wrong:
        """Doc.

        Parameters
        ----------
        speed : float
            Speed [rpm].
        elements : int
            Count.
        """

    assert _doc_units(Wrong) == {"speed": "rpm", "elements": "–"}
    assert _doc_units(Operation)["speed"] == "Hz"
    assert _spec_unit(OperationSpec.model_fields["speed"]) == "Hz"
    assert _spec_unit(BearingSpec.model_fields["elements"]) == "–"
    assert _spec_unit(BearingSpec.model_fields["pitch_diameter"]) == "m"  # Length | None
