"""Hypothesis: corrupt and hostile case files are refused with one line naming the file.

The first tests corrupt one key of a valid case and call :func:`runout.case.model.parse_case`; the
last one fuzzes whole case files through the real command line (``check`` and ``run``).
"""

from __future__ import annotations

import json
import math
import time
import tomllib
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from runout.base.errors import CaseError
from runout.case._schema import BearingSpec
from runout.case.model import CaseSpec, parse_case
from runout.cli.commands import app

BASE = tomllib.loads(
    """
[bearing]
type = "ball"
elements = 7
element_diameter = "3.9688 mm"
pitch_diameter = "15 mm"
inner_conformity = 0.52
outer_conformity = 0.53
radial_clearance = "10 um"
[operation]
rotating_ring = "inner"
speed = "1800 rpm"
axial_load = "20 N"
"""
)

BEARING_KEYS = {field.alias or name for name, field in BearingSpec.model_fields.items()}

LENGTH_KEYS = ["element_diameter", "pitch_diameter", "radial_clearance"]

bad_lengths = st.one_of(
    st.floats(max_value=-1e-9, allow_nan=False, allow_infinity=False),
    st.sampled_from(["3 kg", "12 N", "fast", "10 rpm", "", "mm", "1e400 m"]),
    st.booleans(),
    st.lists(st.integers(), max_size=2),
)


@settings(max_examples=60, deadline=None)
@given(key=st.sampled_from(LENGTH_KEYS), value=bad_lengths)
def test_corrupt_length_is_refused_naming_the_key(key: str, value: object) -> None:
    data = {**BASE, "bearing": {**BASE["bearing"], key: value}}
    try:
        parse_case(data, "fuzz.toml")
    except CaseError as exc:
        assert exc.file == "fuzz.toml"
        assert exc.key.startswith("bearing."), exc
        assert exc.message
    else:
        raise AssertionError(f"bearing.{key} = {value!r} was accepted")


@settings(max_examples=60, deadline=None)
@given(
    elements=st.one_of(st.integers(max_value=2), st.floats(allow_nan=False), st.text(max_size=3))
)
def test_bad_number_of_elements_is_refused(elements: object) -> None:
    data = {**BASE, "bearing": {**BASE["bearing"], "elements": elements}}
    try:
        parse_case(data, "fuzz.toml")
    except CaseError as exc:
        assert exc.key == "bearing.elements", exc
    else:
        raise AssertionError(f"elements = {elements!r} was accepted")


@settings(max_examples=40, deadline=None)
@given(key=st.text(alphabet="abcdefghijklmnopqrstuvwxyz_", min_size=1, max_size=12))
def test_unknown_keys_are_refused(key: str) -> None:
    # Every key the [bearing] table knows, read from the schema so that a new key (such as
    # `designation`) cannot turn this property false.
    if key in BEARING_KEYS:
        return
    data = {**BASE, "bearing": {**BASE["bearing"], key: 1.0}}
    try:
        parse_case(data, "fuzz.toml")
    except CaseError as exc:
        assert exc.key == f"bearing.{key}"
        assert exc.message.startswith("unknown key")
    else:
        raise AssertionError(f"unknown key {key!r} was accepted")


# --------------------------------------------------------------------------------------------
# The case-file fuzzer: random (and hostile) case files through the real command line
# --------------------------------------------------------------------------------------------
# Every example is a whole case file: one of a few real bearings, any model, random loads,
# speeds, waviness, element errors and analysis sizes, with a few keys replaced by hostile
# values (inf, nan, huge or negative numbers, power towers, wrong units, wrong types). Both
# `runout check` and `runout run --json` run in-process. Within the budget (RUNOUT_MAX_TIME
# is lowered so that every run is short) the contract is: exit 0 with finite JSON, or exit 2
# with one line naming the file; never a traceback, never an internal error; and a case that
# `check` calls valid is not refused on input by `run`.
FUZZ_EXAMPLES = 500
#: Time budget of each fuzzed run: keeps 500 examples (check + run) within a few minutes.
FUZZ_ENV = {"RUNOUT_MAX_TIME": "0.5 s", "RUNOUT_MAX_MEMORY": "256 MiB", "COLUMNS": "37"}

BEARINGS = {
    "608": {
        "type": "ball",
        "elements": 7,
        "element_diameter": "3.9688 mm",
        "pitch_diameter": "15 mm",
        "inner_conformity": 0.52,
        "outer_conformity": 0.53,
        "radial_clearance": "10 um",
    },
    "tada": {
        "type": "ball",
        "elements": 8,
        "element_diameter": "1 mm",
        "pitch_diameter": "7 mm",
        "radial_clearance": "10 um",
    },
    "purohit": {
        "type": "ball",
        "elements": 8,
        "element_diameter": "7.96 mm",
        "pitch_diameter": "54 mm",
        "inner_groove_radius": "4.08 mm",
        "outer_groove_radius": "4.61 mm",
        "radial_clearance": "0.2 um",
    },
    "nu209": {
        "type": "cylindrical_roller",
        "elements": 14,
        "element_diameter": "10 mm",
        "inner_raceway_diameter": "54.991 mm",
        "outer_raceway_diameter": "75.032 mm",
        "roller_length": "10 mm",
    },
}
MODELS = [
    "linear",
    "quasi_static_2d",
    "quasi_static_3d",
    "equilibrium",
    "dynamic",
    "roller_constraint",
]
HOSTILE = st.one_of(
    st.sampled_from(
        [
            math.inf,
            -math.inf,
            math.nan,
            0,
            -1,
            1e308,
            -1e308,
            1e-308,
            10**18,
            "10**10**10 N",
            "2**2**2**2**2 mm",
            "1e400 m",
            "nan mm",
            "-3 mm",
            "1 m^5",
            "3 kg",
            "1e-9 rpm",
            "1e30 kg",
            "1e-30 kg",
            "1e-15 s",
            "1e6 N",
            "",
            "x" * 200,
            "3 mm\n",
        ]
    ),
    st.floats(width=64),
    st.integers(min_value=-(2**63), max_value=2**63 - 1),
    st.booleans(),
    st.lists(st.integers(min_value=-3, max_value=10**9), max_size=3),
    st.text(max_size=6),
)
#: (table, key) a corruption may hit; ``None`` as the table is the top level.
TARGETS = [
    ("bearing", "elements"),
    ("bearing", "element_diameter"),
    ("bearing", "pitch_diameter"),
    ("bearing", "radial_clearance"),
    ("bearing", "inner_conformity"),
    ("bearing", "contact_angle"),
    ("material", "youngs_modulus"),
    ("material", "poisson_ratio"),
    ("operation", "speed"),
    ("operation", "axial_load"),
    ("operation", "radial_load"),
    ("operation", "other_ring_speed"),
    ("analysis", "samples"),
    ("analysis", "revolutions"),
    ("analysis", "max_memory"),
    ("dynamics", "mass"),
    ("dynamics", "damping"),
    ("dynamics", "time_step"),
    ("dynamics", "unbalance"),
    ("waviness", "order"),
    ("waviness", "amplitude"),
    ("waviness_spectrum", "orders"),
    ("waviness_spectrum", "exponent"),
    ("elements", "diameter_errors"),
    ("elements", "pitch_errors"),
]


def _toml_value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, str):
        return json.dumps(value)  # a TOML basic string is a JSON string
    if isinstance(value, list):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    raise TypeError(value)


def _toml(doc: dict[str, Any]) -> str:
    lines: list[str] = []
    for table, body in doc.items():
        entries = body if isinstance(body, list) else [body]
        header = f"[[{table}]]" if isinstance(body, list) else f"[{table}]"
        for entry in entries:
            lines.append(header)
            lines += [f"{k} = {_toml_value(v)}" for k, v in entry.items()]
    return "\n".join(lines) + "\n"


@st.composite
def case_files(draw: st.DrawFn) -> dict[str, Any]:
    name = draw(st.sampled_from(sorted(BEARINGS)))
    model = draw(st.sampled_from(MODELS))
    bearing = dict(BEARINGS[name])
    z = bearing["elements"]
    ball = bearing["type"] == "ball"
    doc: dict[str, Any] = {"bearing": bearing}
    doc["operation"] = {
        "rotating_ring": draw(st.sampled_from(["inner", "outer"])),
        "speed": draw(st.sampled_from(["1800 rpm", "30 Hz", 100, "5000 rpm", 0])),
        "axial_load": draw(st.sampled_from(["20 N", 0, "5 N", "200 N"])),
        "radial_load": draw(st.sampled_from([0, "6 N", "50 N"])),
    }
    doc["analysis"] = {
        "model": model,
        "samples": draw(st.sampled_from([64, 128, 256, 512])),
        "revolutions": draw(st.sampled_from([1, 2, 2.5, 4])),
    }
    parts = ["inner", "outer", "ball" if ball else "roller"]
    waves = draw(
        st.lists(
            st.tuples(
                st.sampled_from(parts),
                st.integers(min_value=1, max_value=40),
                st.sampled_from(["1 nm", "20 nm", "0.2 um"]),
            ),
            max_size=3,
        )
    )
    if waves:
        doc["waviness"] = [{"part": p, "order": k, "amplitude": a} for p, k, a in waves]
    if draw(st.booleans()):
        doc["waviness_spectrum"] = [
            {
                "part": draw(st.sampled_from(parts)),
                "orders": [2, draw(st.sampled_from([10, 50, 200]))],
                "amplitude": "1 nm",
                "exponent": -1.5,
            }
        ]
    if draw(st.booleans()):
        doc["elements"] = {
            "diameter_errors": [draw(st.sampled_from([0, "0.1 um", "-0.2 um"])) for _ in range(z)]
        }
    if model == "dynamic":
        doc["dynamics"] = {"mass": "0.6 kg", "damping": "200 N*s/m"}
    for table, key in draw(st.lists(st.sampled_from(TARGETS), max_size=3, unique=True)):
        value = draw(HOSTILE)
        if table in ("waviness", "waviness_spectrum"):
            if table not in doc:
                continue
            doc[table][0][key] = value
        else:
            doc.setdefault(table, {})[key] = value
    return doc


runner = CliRunner()


def _finite_json(value: Any) -> bool:
    if isinstance(value, float):
        return math.isfinite(value)
    if isinstance(value, dict):
        return all(_finite_json(v) for v in value.values())
    if isinstance(value, list):
        return all(_finite_json(v) for v in value)
    return True


#: Tables whose keys describe the run's input (every case table but the title and the study).
_INPUT_TABLES = tuple(k for k in CaseSpec.model_fields if k not in ("title", "study"))


def _one_error_line(stderr: str, name: str) -> str:
    lines = stderr.splitlines()
    assert len(lines) == 1, f"not one line:\n{stderr}"
    assert lines[0].startswith(f"error: {name}: "), lines[0]
    return lines[0]


@pytest.fixture(scope="module")
def fuzz_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("fuzz")


@settings(max_examples=FUZZ_EXAMPLES, deadline=None)
@given(doc=case_files())
def test_fuzzed_case_files_through_the_command_line(fuzz_dir: Path, doc: dict[str, Any]) -> None:
    path = fuzz_dir / "fuzz.toml"
    path.write_text(_toml(doc), encoding="utf-8")
    start = time.perf_counter()
    checked = runner.invoke(app, ["check", str(path)], env=FUZZ_ENV)
    ran = runner.invoke(app, ["run", str(path), "--json"], env=FUZZ_ENV)
    elapsed = time.perf_counter() - start
    for result in (checked, ran):
        assert result.exit_code in (0, 2), (result.exit_code, result.stderr, _toml(doc))
        assert "Traceback" not in result.stderr + result.stdout
        if result.exit_code == 2:
            _one_error_line(result.stderr, str(path))
        else:
            assert all(line.startswith("warning: ") for line in result.stderr.splitlines())
    if ran.exit_code == 0:
        payload = json.loads(ran.stdout)
        assert _finite_json(payload), "non-finite number in the JSON output"
    if checked.exit_code == 0 and ran.exit_code == 2:
        # `check` called it valid: `run` may fail numerically, never on input
        line = _one_error_line(ran.stderr, str(path))
        rest = line[len(f"error: {path}: ") :]
        assert not rest.startswith(_INPUT_TABLES), f"check passed, run refused: {line}"
    assert elapsed < 30.0, f"one example took {elapsed:.1f} s: the budget does not bound it"
