"""Bad case files: each is refused with one line naming the file, the key and the problem.

Every case here goes through the real command line (``runout check``), so the exit status and
the absence of a traceback are checked too.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

VALID = """\
title = "valid 608"
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

runner = CliRunner()


def _run(tmp_path: Path, text: str, name: str = "case.toml") -> tuple[int, str]:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    result = runner.invoke(app, ["check", str(path)])
    return result.exit_code, result.stderr


def _replace(line: str, new: str) -> str:
    assert line in VALID, line
    return VALID.replace(line, new)


BAD = {
    "too_few_balls": (
        _replace("elements = 7", "elements = 2"),
        "bearing.elements: must be an integer >= 3, got 2",
    ),
    "fractional_balls": (
        _replace("elements = 7", "elements = 7.5"),
        "bearing.elements: must be an integer >= 3, got 7.5",
    ),
    "diameter_in_kg": (
        _replace('element_diameter = "3.9688 mm"', 'element_diameter = "3 kg"'),
        'bearing.element_diameter: "3 kg" is not a length',
    ),
    "misspelt_key": (
        _replace('element_diameter = "3.9688 mm"', 'element_diamter = "3.9688 mm"'),
        "bearing.element_diamter: unknown key; did you mean 'element_diameter'?",
    ),
    "misspelt_table": (
        VALID.replace("[operation]", "[operations]"),
        "operations: unknown key; did you mean 'operation'?",
    ),
    "misspelt_bearing_table": (
        VALID.split("[operation]")[0].replace("[bearing]", "[bearing_x]"),
        "bearing_x: unknown key; did you mean 'bearing'?",
    ),
    "missing_bearing": (
        'title = "no bearing"\n[operation]\nspeed = "1800 rpm"\n',
        "bearing: required key is missing",
    ),
    "ball_larger_than_pitch": (
        _replace('pitch_diameter = "15 mm"', 'pitch_diameter = "3 mm"'),
        "bearing.element_diameter: 3.9688 mm is not smaller than the pitch diameter 3 mm",
    ),
    "balls_overlap": (
        _replace("elements = 7", "elements = 12"),
        "bearing.elements: 12 balls of 3.9688 mm overlap",
    ),
    "conformity_half": (
        _replace("inner_conformity = 0.52", "inner_conformity = 0.5"),
        "bearing.inner_conformity: must be > 0.5",
    ),
    "negative_clearance": (
        _replace('radial_clearance = "10 um"', 'radial_clearance = "-1 um"'),
        "bearing.radial_clearance: must be >= 0 (no negative clearance)",
    ),
    "clearance_too_large": (
        _replace('radial_clearance = "10 um"', 'radial_clearance = "1 mm"'),
        "bearing.radial_clearance: 1000 um exceeds twice the groove-centre distance",
    ),
    "contact_angle_95": (
        _replace('radial_clearance = "10 um"', 'contact_angle = "95 deg"'),
        "bearing.contact_angle: must lie in [0, 90) deg, got 95 deg",
    ),
    "rotating_cage": (
        _replace('rotating_ring = "inner"', 'rotating_ring = "cage"'),
        "operation.rotating_ring: must be one of 'inner' or 'outer', got 'cage'",
    ),
    "speed_not_a_quantity": (
        _replace('speed = "1800 rpm"', 'speed = "fast"'),
        'operation.speed: "fast" cannot be read as a quantity',
    ),
    "speed_in_newton": (
        _replace('speed = "1800 rpm"', 'speed = "1800 N"'),
        'operation.speed: "1800 N" is not a rotational speed',
    ),
    "negative_axial_load": (
        _replace('axial_load = "20 N"', 'axial_load = "-20 N"'),
        "operation.axial_load: must be >= 0",
    ),
    "two_amplitudes": (
        VALID + '[[waviness]]\npart = "inner"\norder = 8\namplitude = "10 nm"\n'
        'peak_to_peak = "20 nm"\n',
        "waviness[1].amplitude: give exactly one of amplitude or peak_to_peak",
    ),
    "element_on_a_ring": (
        VALID + '[[waviness]]\npart = "inner"\norder = 8\namplitude = "10 nm"\nelement = 2\n',
        'waviness[1].element: only applies to balls or rollers, not part = "inner"',
    ),
    "element_beyond_z": (
        VALID + '[[waviness]]\npart = "ball"\norder = 2\namplitude = "10 nm"\nelement = 8\n',
        "waviness[1].element: must be <= 7 (the number of elements)",
    ),
    "roller_on_ball_bearing": (
        VALID + '[[waviness]]\npart = "roller"\norder = 2\namplitude = "10 nm"\n',
        'waviness[1].part: "roller" does not match bearing.type = "ball"',
    ),
    "negative_order": (
        VALID + '[[waviness]]\npart = "outer"\norder = -3\namplitude = "10 nm"\n',
        "waviness[1].order: must be >= 0, got -3",
    ),
    "reversed_orders": (
        VALID + '[[waviness_spectrum]]\npart = "outer"\norders = [50, 2]\namplitude = "1 nm"\n',
        "waviness_spectrum[1].orders: must be [first, last] with 0 <= first <= last",
    ),
    "wrong_number_of_diameter_errors": (
        VALID + '[elements]\ndiameter_errors = ["0.1 um", 0, 0]\n',
        "elements.diameter_errors: has 3 entries; the bearing has 7 elements",
    ),
    "unknown_model": (
        VALID + '[analysis]\nmodel = "finite_elements"\n',
        "analysis.model: must be one of",
    ),
    "roller_missing_raceway": (
        VALID.split("[bearing]")[0]
        + '[bearing]\ntype = "cylindrical_roller"\nelements = 14\nelement_diameter = "10 mm"\n'
        'outer_raceway_diameter = "75.032 mm"\n',
        "bearing.inner_raceway_diameter: required for a cylindrical roller bearing",
    ),
    "not_toml": (VALID + "this is = = not toml\n", "is not valid TOML"),
    # hostile inputs (tests/hostile/ runs them as subprocesses under limits)
    "power_tower_unit": (
        _replace('axial_load = "20 N"', 'axial_load = "10**10**10 N"'),
        'operation.axial_load: "10**10**10 N" cannot be read as a quantity: write a plain '
        "number and a unit",
    ),
    "infinite_revolutions": (
        VALID + '[analysis]\nmodel = "linear"\nrevolutions = inf\n',
        "analysis.revolutions: must be a finite number, got inf",
    ),
    "negative_speed": (
        _replace('speed = "1800 rpm"', 'speed = "-1800 rpm"'),
        "operation.speed: must be >= 0, got -30.0 Hz: the sense of rotation is not a sign",
    ),
    "huge_conformity": (
        _replace("inner_conformity = 0.52", "inner_conformity = 9.2e18"),
        "bearing.inner_conformity: conformity f = 9.2e+18 is not below 1",
    ),
    "huge_order": (
        VALID + '[[waviness]]\npart = "inner"\norder = 3000000000\namplitude = "1 nm"\n',
        "waviness[1].order: order 3000000000 exceeds the largest supported order 1000000",
    ),
    "ball_of_negative_diameter": (
        VALID + '[elements]\ndiameter_errors = ["-4 mm", 0, 0, 0, 0, 0, 0]\n',
        "elements.diameter_errors[1]: -4 mm on a 3.9688 mm ball leaves a diameter of",
    ),
    "balls_passing_through_each_other": (
        VALID + '[elements]\npitch_errors = ["90 deg", 0, 0, 0, 0, 0, 0]\n',
        "elements.pitch_errors[2]: the pitch errors put ball 2",
    ),
    "negative_damping": (
        VALID + '[dynamics]\nmass = "0.6 kg"\ndamping = -50\n',
        "dynamics.damping: must be >= 0, got -50.0",
    ),
    "check_runs_the_model_setup": (
        _replace('axial_load = "20 N"', 'radial_load = "20 N"')
        + '[analysis]\nmodel = "quasi_static_2d"\n',
        "operation.axial_load: the quasi_static_2d model needs an axial preload > 0 N",
    ),
    "contact_beyond_hertz": (
        _replace('axial_load = "20 N"', 'axial_load = "1e6 N"'),
        "operation.axial_load: the most loaded ball carries about",
    ),
    "too_many_entries": (
        VALID + '[[waviness]]\npart = "inner"\norder = 3\namplitude = "1 nm"\n' * 1001,
        "waviness: has 1001 entries, at most 1000",
    ),
    # a record of one revolution at 1e-308 Hz overflows float64 time (found by the fuzzer)
    "speed_too_small": (
        _replace('speed = "1800 rpm"', "speed = 1e-308"),
        "operation.speed: must be 0 (at rest) or at least 1e-06 Hz, got 1e-308 Hz",
    ),
    "too_many_elements": (
        _replace("elements = 7", "elements = 20000"),
        "bearing.elements: must be at most 10000",
    ),
    # the columns of 10^10 samples do not fit: statistics = "auto" streams them (memory
    # independent of the samples), and the time is what refuses them
    "study_samples_beyond_the_budget": (
        VALID + '[analysis]\nmodel = "linear"\n[study]\nkind = "montecarlo"\n'
        'samples = 10000000000\n[study.vary]\nelement_diameter_sigma = "0.1 um"\n',
        "study.samples: would take about",
    ),
    "study_exact_statistics_beyond_the_memory_budget": (
        VALID + '[analysis]\nmodel = "linear"\n[study]\nkind = "montecarlo"\n'
        'samples = 10000000000\nstatistics = "exact"\n'
        '[study.vary]\nelement_diameter_sigma = "0.1 um"\n',
        "study.statistics: ",
    ),
}


@pytest.mark.parametrize("name", sorted(BAD))
def test_bad_case_is_refused_with_a_clear_message(tmp_path: Path, name: str) -> None:
    text, expected = BAD[name]
    code, stderr = _run(tmp_path, text)
    one_line = " ".join(stderr.split())
    assert code == 2, stderr
    assert "Traceback" not in stderr
    assert f"case.toml: {expected}" in one_line, one_line


def test_missing_file_is_refused(tmp_path: Path) -> None:
    result = runner.invoke(app, ["check", str(tmp_path / "nowhere.toml")])
    assert result.exit_code == 2
    assert "nowhere.toml: no such file" in " ".join(result.stderr.split())


def test_valid_case_passes(tmp_path: Path) -> None:
    code, stderr = _run(tmp_path, VALID)
    assert code == 0, stderr


def test_messages_are_one_line_with_error_prefix(tmp_path: Path) -> None:
    _, stderr = _run(tmp_path, BAD["too_few_balls"][0])
    assert re.match(r"^error: ", stderr)


def test_a_utf8_byte_order_mark_is_read(tmp_path: Path) -> None:
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + VALID.encode("utf-8"))
    result = runner.invoke(app, ["check", str(path)])
    assert result.exit_code == 0, result.stderr


def test_a_newline_in_a_quoted_key_stays_on_one_line(tmp_path: Path) -> None:
    code, stderr = _run(tmp_path, VALID.replace("elements = 7", 'elements = 7\n"a\\nb" = 1'))
    assert code == 2
    assert len(stderr.splitlines()) == 1, stderr
    assert "bearing.a\\nb: unknown key" in stderr


def test_a_hertz_warning_is_one_warning_line(tmp_path: Path) -> None:
    code, stderr = _run(tmp_path, _replace('axial_load = "20 N"', 'axial_load = "6000 N"'))
    assert code == 0, stderr
    (line,) = stderr.splitlines()
    assert line.startswith(f"warning: {tmp_path / 'case.toml'}: operation.axial_load: ")
    assert "ISO 76" in line


def test_an_emoji_code_in_a_value_is_printed_as_text(tmp_path: Path) -> None:
    # rich turned ":x:" in an echoed value into an emoji, so the line no longer said the input
    code, stderr = _run(tmp_path, _replace('speed = "1800 rpm"', 'speed = "1 :x:"'))
    assert code == 2
    assert '"1 :x:"' in stderr


def test_revolutions_beyond_what_the_models_resolve_are_refused(tmp_path: Path) -> None:
    """Found by the case fuzz test: ``revolutions = 2.2250738585e-313`` made a time step below
    the normal floats and ended in an internal error (exit 70), 1e-308 as well, and 1e308 was
    refused by the roller model after ``check`` had passed it. The key now has bounds, and the
    shortest record it allows runs (no synchronous average under two revolutions)."""
    spectrum = '[[waviness_spectrum]]\npart = "inner"\norders = [2, 10]\namplitude = "1 nm"\n'
    for revolutions, bound in (("2.2250738585e-313", ">= 1e-06"), ("1e308", "<= 1000000000.0")):
        text = VALID + f'[analysis]\nmodel = "linear"\nsamples = 64\nrevolutions = {revolutions}\n'
        code, stderr = _run(tmp_path, text + spectrum)
        assert code == 2 and len(stderr.splitlines()) == 1, stderr
        assert f"analysis.revolutions: must be {bound}" in stderr
    path = tmp_path / "case.toml"
    path.write_text(VALID + "[analysis]\nsamples = 64\nrevolutions = 1e-6\n" + spectrum)
    for model in ("linear", "quasi_static_2d"):
        result = runner.invoke(app, ["run", str(path), "--json", "--model", model])
        assert result.exit_code == 0, result.stderr
        assert "NaN" not in result.stdout and "Infinity" not in result.stdout
