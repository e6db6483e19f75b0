"""Generate the case-file key reference (docs/case-file.md) from the validated schema.

The reference is never typed by hand: ``python -m runout.case.schema_doc > docs/case-file.md``; a
test fails when the committed file differs from what the schema says.
"""

from __future__ import annotations

import sys
from typing import Any

from pydantic import BaseModel
from pydantic.fields import PydanticUndefined

from runout.case.model import (
    AnalysisSpec,
    BearingSpec,
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
    WavinessSpec,
    WavinessSpectrumSpec,
)

__all__ = ["case_file_reference"]

TABLES: list[tuple[str, type[BaseModel]]] = [
    ("[bearing]", BearingSpec),
    ("[spindle]", SpindleSpec),
    ("[[bearings]]", SpindleBearingSpec),
    ("[material]", MaterialSpec),
    ("[operation]", OperationSpec),
    ("[[waviness]]", WavinessSpec),
    ("[[waviness_spectrum]]", WavinessSpectrumSpec),
    ("[[profile]]", ProfileSpec),
    ("[[defect]]", DefectSpec),
    ("[slant]", SlantSpec),
    ("[elements]", ElementsSpec),
    ("[analysis]", AnalysisSpec),
    ("[dynamics]", DynamicsSpec),
    ("[sensor]", SensorSpec),
    ("[[sensor.modes]]", SensorModeSpec),
    ("[study]", StudySpec),
]


def _default(info: Any) -> str:
    if info.is_required():
        return "required"
    if info.default is PydanticUndefined:
        return "(empty)"
    value = info.default
    if isinstance(value, float):
        return f"`{value:.6g}`"
    return f"`{value!r}`" if value is not None else "—"


def case_file_reference() -> str:
    """The Markdown key reference of every case-file table.

    Returns
    -------
    str
        The Markdown of docs/case-file.md: the conventions of values and units, then one table
        per case-file table (key, default, meaning), from the schema's descriptions.
    """
    lines = [
        "# Case-file reference",
        "",
        "Generated from the schema by `python -m runout.case.schema_doc`; do not edit by hand.",
        "",
        "A bare number is SI (m, N, Pa, kg, s, rad; speeds in Hz = rev/s). A string carries its",
        'unit: `"3.9688 mm"`, `"7200 rpm"` (or `"7200 rev/min"`), `"10 deg"`, `"208 GPa"`.',
        "Amplitudes are zero-to-peak radius deviations unless the key says `peak_to_peak`. Array",
        "entries in error messages are counted from 1 (`waviness[2].order`). `title` (string) is",
        "the only top-level key.",
        "",
    ]
    for name, model in TABLES:
        lines += [f"## {name}", "", (model.__doc__ or "").strip(), ""]
        lines += ["| key | default | meaning |", "|---|---|---|"]
        for key, info in model.model_fields.items():
            lines.append(f"| `{key}` | {_default(info)} | {info.description or ''} |")
        lines.append("")
    return "\n".join(lines)


if __name__ == "__main__":
    sys.stdout.write(case_file_reference())
