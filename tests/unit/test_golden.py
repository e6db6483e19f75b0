"""tests/golden.py: the comparison of stored outputs holds on another machine, and sees a change.

Another machine (another CPU for numba, other library versions) is simulated on every stored
``runout run --json`` output: every float moved by a few ulp and by 1e-13 of its family's scale,
displacements by the model's whole resolution (its solvers' stopping tolerance times the largest
displacement, positions included), a line as a complex amplitude (so that its phase and shares
move as a small line's do), the lines and sources re-sorted and the labels rewritten as the code
would from such values, numbers quoted in text moved by a unit of their last digit. The
comparison must accept all of it, and it must refuse a real change: a number moved by 1e-6 of
itself, a label, a key, a line, the order of lines.
"""

from __future__ import annotations

import copy
import gzip
import json
import math
import re
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import golden
from runout.analysis.decompose import FLOOR, RESIDUAL_REL
from runout.analysis.lines import Source, short_label
from runout.analysis.results import _relative_resolution

ROOT = Path(__file__).resolve().parents[2]
STORED = sorted((ROOT / "tests" / "data" / "examples_json").glob("*.json.gz"))
IDS = [p.name.removesuffix(".json.gz") for p in STORED]
EPS = 2.0**-52
#: Round-off of another machine, as a fraction of a family's scale (the tolerance is 1e-9).
ROUNDOFF = 1e-13
_DECIMAL = re.compile(r"\d+\.\d+")


def _load(path: Path) -> dict[str, Any]:
    return json.loads(gzip.decompress(path.read_bytes()))


@pytest.fixture(scope="module", params=STORED, ids=IDS)
def stored(request: pytest.FixtureRequest) -> dict[str, Any]:
    return _load(request.param)


# -- another machine -------------------------------------------------------------------------
def _last_digit_moved(text: str, rng: np.random.Generator) -> str:
    """Every decimal number of ``text`` moved by one unit of its last digit, or not."""

    def move(m: re.Match[str]) -> str:
        token = m.group(0)
        decimals = len(token.partition(".")[2])
        step = int(rng.integers(-1, 2)) * 10.0**-decimals
        value = float(token) + step
        return f"{value:.{decimals}f}" if value >= 0 else token

    return _DECIMAL.sub(move, text)


def another_machine(doc: dict[str, Any], seed: int) -> dict[str, Any]:
    """``doc`` as another machine could print it (see the module docstring)."""
    rng = np.random.default_rng(seed)
    scale = golden.scales(doc)
    floor_m = _resolution(doc)

    def ulps(x: float) -> float:
        return x * (1.0 + int(rng.integers(-4, 5)) * EPS)

    def walk(x: Any, path: golden.Path) -> Any:
        if isinstance(x, dict):
            return {k: walk(v, (*path, k)) for k, v in x.items()}
        if isinstance(x, list):
            return [walk(v, (*path, i)) for i, v in enumerate(x)]
        if isinstance(x, float):
            size = scale.get(golden.family(path), 0.0)
            if golden.family(path) == golden.DISPLACEMENT:
                size = floor_m / ROUNDOFF
            if golden._keys(path) == ["stiffness_matrix", "matrix"]:
                i, j = path[-2], path[-1]
                assert isinstance(i, int) and isinstance(j, int)
                size = math.sqrt(
                    abs(doc["stiffness_matrix"]["matrix"][i][i])
                    * abs(doc["stiffness_matrix"]["matrix"][j][j])
                )
            if golden._keys(path) == ["explained_fraction"]:
                size = 8.0 * floor_m / ROUNDOFF / max(_record_pp(doc), 1e-300)
            moved = ulps(x) + float(rng.uniform(-1.0, 1.0)) * ROUNDOFF * size
            if golden._keys(path) == ["explained_fraction"]:  # least squares: in [0, 1]
                return min(max(moved, 0.0), 1.0)
            return moved
        if isinstance(x, str) and path and path[-1] in golden.QUOTING:
            return _last_digit_moved(x, rng)
        if isinstance(x, str) and len(path) > 1 and path[-2] == "notes":
            return _last_digit_moved(x, rng)
        return x

    out = walk({k: v for k, v in doc.items() if k != "components"}, ())
    lines = []
    for line in doc.get("components", []):
        new = walk(line, ("components", 0))
        # the line's complex amplitude carries the round-off of the displacements
        c = 0.5 * line["pp_m"] * complex(math.cos(line["phase_rad"]), math.sin(line["phase_rad"]))
        c += floor_m * complex(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0))
        new["pp_m"] = ulps(2.0 * abs(c))
        new["phase_rad"] = ulps(math.atan2(c.imag, c.real))
        spread = floor_m / max(abs(c), 1e-300)
        for s in new["sources"]:
            s["share"] = ulps(s["share"]) + float(rng.uniform(-1.0, 1.0)) * spread
        # the code ranks sources by share and names a line by its first one
        new["sources"].sort(key=lambda s: -abs(s["share"]))
        if not new["label"].startswith("unattributed"):  # its formula's number moved alone
            new["label"] = short_label([Source(**s) for s in new["sources"]])
        lines.append(new)
    if "components" in doc:
        lines.sort(key=lambda c: -c["pp_m"])  # and lists lines largest first
        out = {k: (lines if k == "components" else v) for k, v in {**doc, **out}.items()}
    return out


def _resolution(doc: dict[str, Any]) -> float:
    """What the model's solved positions may differ by [m]: its relative resolution (the
    solvers' stopping tolerance, at least 1e-13) times the largest displacement the document
    states, positions and approaches included
    (:meth:`runout.analysis.results.RunResult.resolution_m`)."""
    sizes: list[float] = []

    def walk(x: Any, path: golden.Path) -> None:
        if isinstance(x, dict):
            for k, v in x.items():
                walk(v, (*path, k))
        elif isinstance(x, list):
            for i, v in enumerate(x):
                walk(v, (*path, i))
        elif isinstance(x, float) and golden.family(path) == golden.DISPLACEMENT:
            sizes.append(abs(x))

    walk(doc, ())
    return max(_relative_resolution(doc["model"]), ROUNDOFF) * max(sizes, default=0.0)


def test_the_floor_covers_the_solvers_resolution(stored: dict[str, Any]) -> None:
    # the displacement floor (1e-9 of the largest p-p or approach, or the stated resolution)
    # is above what the solvers resolve, positions included: another machine's positions
    # differ by less than it
    floor = max(
        golden.RTOL * golden.scales(stored).get(golden.DISPLACEMENT, 0.0),
        stored.get("solver_resolution_m", 0.0),
    )
    assert floor >= _resolution(stored)


def _record_pp(doc: dict[str, Any]) -> float:
    runout = doc["runout"]
    values = [runout["radial_pp_m"], runout["axial_pp_m"], *(c["pp_m"] for c in doc["components"])]
    return max(v for v in values if v is not None)  # null: a quantity the model does not have


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_another_machine_passes(stored: dict[str, Any], seed: int) -> None:
    moved = another_machine(stored, seed)
    assert moved != stored  # the simulation moved something
    assert golden.differences(moved, stored) == []
    assert golden.differences(stored, moved) == []  # either one may be the stored one


def test_the_simulation_reorders_lines_and_rewrites_labels() -> None:
    # the test above must exercise what it claims: swapped ranks and relabelled lines
    swapped = relabelled = 0
    for path in STORED:
        doc = _load(path)
        for seed in (0, 1, 2):
            moved = another_machine(doc, seed)
            key = [(c["direction"], c["frequency_hz"]) for c in doc["components"]]
            new_key = [(c["direction"], round(c["frequency_hz"], 6)) for c in moved["components"]]
            swapped += [(d, round(f, 6)) for d, f in key] != new_key
            relabelled += sum(
                a["label"] != b["label"]
                for a, b in zip(
                    sorted(moved["components"], key=lambda c: (c["direction"], c["order"])),
                    sorted(doc["components"], key=lambda c: (c["direction"], c["order"])),
                    strict=True,
                )
            )
    assert swapped >= 10 and relabelled >= 3, (swapped, relabelled)


def test_equal_lines_and_sources_swapped_pass() -> None:
    swapped = 0
    for path in STORED:
        stored = _load(path)
        doc = copy.deepcopy(stored)
        lines = doc["components"]
        for i in range(0, len(lines) - 1, 2):
            a, b = lines[i], lines[i + 1]
            if abs(a["pp_m"] - b["pp_m"]) <= golden.RTOL * a["pp_m"]:
                lines[i], lines[i + 1] = b, a
                swapped += 1
        for line in lines:
            sources = line["sources"]
            if len(sources) > 1 and abs(sources[0]["share"]) == abs(sources[1]["share"]):
                sources[0], sources[1] = sources[1], sources[0]
                line["label"] = short_label([Source(**s) for s in sources])
                swapped += 1
        assert golden.differences(doc, stored) == [], path.name
    assert swapped > 100  # lines and sources were swapped indeed


# -- a real change ---------------------------------------------------------------------------
def _floor(doc: dict[str, Any], path: golden.Path, scale: golden.Scales) -> float:
    """The comparison's absolute floor at ``path`` (tests/golden.py's policy)."""
    name = golden.family(path)
    floor = golden.RTOL * scale.get(name, 0.0)
    if name == golden.DISPLACEMENT:
        floor = max(floor, doc.get("solver_resolution_m", 0.0))
    if name == golden.ORDERS:
        floor = golden.RTOL * scale[golden.FREQUENCIES] / doc["frequencies_hz"]["rotation"]
    return floor


def _resolved_floats(doc: dict[str, Any]) -> list[tuple[golden.Path, float]]:
    """Floats whose tolerance is 2/3 of 1e-6 of themselves or less: above 1.5e6 floors (the
    phases of lines above 3e6 floors, shares of at least 0.5 of lines above 1e7 floors)."""
    scale = golden.scales(doc)
    floor_m = _floor(doc, ("runout", "radial_pp_m"), scale)
    out: list[tuple[golden.Path, float]] = []

    def walk(x: Any, path: golden.Path) -> None:
        if isinstance(x, dict):
            pp = x.get("pp_m", math.inf) if path[:1] == ("components",) else math.inf
            for k, v in x.items():
                if not (
                    (k == "phase_rad" and pp < 3e6 * floor_m)
                    or (k == "sources" and pp < 1e7 * floor_m)
                ):
                    walk(v, (*path, k))
        elif isinstance(x, list):
            for i, v in enumerate(x):
                walk(v, (*path, i))
        elif isinstance(x, float):
            keys = golden._keys(path)
            if keys[:2] == ["stiffness_matrix", "matrix"]:
                resolved = path[-1] == path[-2]  # the diagonal
            elif keys == ["explained_fraction"]:
                resolved = x >= 0.1 and _record_pp(doc) >= 1e8 * floor_m
            elif keys[-1:] == ["share"]:
                resolved = abs(x) >= 0.5
            else:
                resolved = keys[-1:] == ["phase_rad"] or abs(x) >= 1.5e6 * _floor(doc, path, scale)
            if resolved:
                out.append((path, x))

    walk(doc, ())
    return [(p, v) for p, v in out if v != 0.0 or p[-1] == "phase_rad"]


def _set(doc: Any, path: golden.Path, value: Any) -> Any:
    out = copy.deepcopy(doc)
    where = out
    for k in path[:-1]:
        where = where[k]
    where[path[-1]] = value
    return out


def test_a_number_moved_by_1e_6_of_itself_fails(stored: dict[str, Any]) -> None:
    floats = _resolved_floats(stored)
    assert floats
    rng = np.random.default_rng(7)
    picks = rng.choice(len(floats), size=min(40, len(floats)), replace=False)
    for k in sorted(picks):
        path, x = floats[k]
        moved = x + (1e-6 if path[-1] == "phase_rad" else 1e-6 * x)
        problems = golden.differences(_set(stored, path, moved), stored)
        assert problems, golden._text(path)
        # the message names the path (a line by its index, direction and frequency)
        named = golden._text(path) if path[0] != "components" else f".{path[-1]}: "
        assert named in problems[0], problems


def test_headline_numbers_are_resolved(stored: dict[str, Any]) -> None:
    # the largest runout figure, every characteristic frequency and the largest line are among
    # the numbers a 1e-6 change of which fails (above): the floors do not swallow them
    resolved = {golden._text(p) for p, _ in _resolved_floats(stored)}
    # null: a quantity the model does not have (axial runout of a radial model)
    # (the equilibrium model has none: a position, not a runout)
    runout = {k: v for k, v in stored["runout"].items() if v is not None}
    if runout:
        largest = max(runout, key=lambda k: runout[k])
        if runout[largest] > 10.0 * stored.get("solver_resolution_m", 0.0):
            assert f"$.runout.{largest}" in resolved
    for key in stored["frequencies_hz"]:
        assert f"$.frequencies_hz.{key}" in resolved
    if stored["components"]:
        assert "$.components[0].pp_m" in resolved
        assert "$.components[0].frequency_hz" in resolved
        assert "$.components[0].phase_rad" in resolved


def _first(doc: dict[str, Any]) -> dict[str, Any]:
    line: dict[str, Any] = doc["components"][0]
    return line


def _one_line_doc() -> dict[str, Any]:
    return next(d for d in map(_load, STORED) if len(d["components"]) > 3)


@pytest.mark.parametrize(
    ("what", "change"),
    [
        ("a label", lambda d: _set(d, ("components", 0, "label"), "outer 7 lobes: nZ-1, n=1")),
        ("a key renamed", lambda d: {("pp" if k == "runout" else k): v for k, v in d.items()}),
        ("a key dropped", lambda d: {k: v for k, v in d.items() if k != "notes"}),
        ("keys reordered", lambda d: dict(reversed(list(d.items())))),
        ("a line dropped", lambda d: {**d, "components": d["components"][1:]}),
        ("a line added", lambda d: {**d, "components": [*d["components"], d["components"][0]]}),
        ("a direction", lambda d: _set(d, ("components", 0, "direction"), "w")),
        (
            "a boolean",
            lambda d: _set(d, ("components", 0, "repeatable"), not _first(d)["repeatable"]),
        ),
        ("a source", lambda d: _set(d, ("components", 0, "sources"), [])),
        ("a title", lambda d: {**d, "title": d["title"] + "!"}),
        ("a note", lambda d: {**d, "notes": ["x", *d["notes"][1:]]}),
        ("a note dropped", lambda d: {**d, "notes": d["notes"][1:]}),
        ("a float for an int", lambda d: {**d, "n_elements": float(d.get("n_elements", 1))}),
        ("the order of lines", lambda d: {**d, "components": d["components"][::-1]}),
        ("a phase by pi", lambda d: _set(d, ("components", 0, "phase_rad"), 0.5)),
    ],
)
def test_a_real_change_fails(what: str, change: Any) -> None:
    doc = _one_line_doc()
    doc = {**doc, "n_elements": doc.get("n_elements", 8)}
    doc["components"][0]["phase_rad"] = 0.5 + math.pi
    assert golden.differences(change(doc), doc), what


def test_a_quoted_number_moves_only_by_its_last_digit() -> None:
    note = "1 line(s) below 1/T = 0.01111 Hz (less than one period in the record)"
    assert golden.same_quoted(note.replace("0.01111", "0.01112"), note)
    assert not golden.same_quoted(note.replace("0.01111", "0.01113"), note)
    assert not golden.same_quoted(note.replace("1 line", "2 line"), note)  # integers exact
    assert not golden.same_quoted(note.replace("period", "periods"), note)
    assert golden.same_quoted("at 1.3 Hz", "at 1.29999 Hz")  # %g drops a trailing 0
    assert golden.same_quoted("at 1.3 Hz", "at 1.29 Hz")  # 1.295 printed with 3 digits
    assert not golden.same_quoted("at 1.3 Hz", "at 1.28 Hz")
    assert not golden.same_quoted("inner 8 lobes: nZ", "inner 7 lobes: nZ")


def test_the_message_names_path_values_and_tolerance() -> None:
    doc = _load(STORED[IDS.index("seed000_tada_fig6")])
    moved = _set(doc, ("frequencies_hz", "cage"), doc["frequencies_hz"]["cage"] * (1 + 1e-6))
    (problem,) = golden.differences(moved, doc)
    assert problem.startswith("$.frequencies_hz.cage: 50.62703553337092 became 50.627")
    assert "(tolerance 4.05e-07)" in problem  # 1e-9 of the largest frequency, 405 Hz
    line = _set(doc, ("components", 0, "pp_m"), 2e-8)
    (problem,) = golden.differences(line, doc)
    assert problem.startswith("$.components[0: x 405.016 Hz].pp_m: 9.99")
    with pytest.raises(AssertionError, match=r"fig6: 1 difference\(s\)"):
        golden.assert_same(line, doc, "fig6")


def test_no_stored_line_sits_at_a_cut_off(stored: dict[str, Any]) -> None:
    # list lengths are exact: a line within round-off of a cut-off (the decomposition's
    # FLOOR and residual thresholds, the linear model's 1e-12, the solvers' 1e-9 of the
    # approach, the dynamic model's resolution) could come or go on another machine
    lines = [c["pp_m"] for c in stored["components"]]
    if not lines:
        return
    top = max(lines)
    approaches = [stored.get(k) for k in ("initial_approach_m", "preload_approach_m")]
    approaches += [b["preload_approach_m"] for b in stored.get("bearings", [])]
    cuts = [FLOOR * top, RESIDUAL_REL * top, 2 * RESIDUAL_REL * top, 1e-12 * top]
    cuts += [1e-9 * a for a in approaches if isinstance(a, float)]
    cuts += [stored["solver_resolution_m"]] if "solver_resolution_m" in stored else []
    nearest = min(abs(pp / cut - 1.0) for pp in lines for cut in cuts)
    assert nearest > 1e-6
