"""One language across the models (issue 13): each finding through the real command line.

Every test here failed before its fix: a fixed-phase spectrum was refused, ``contact_angle``
meant three things, a radial load loaded opposite balls in two models, displacements had two
signs, the spin sense under outer-ring rotation differed, and inputs vanished without a word.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

runner = CliRunner()

BEARING = """\
[bearing]
type = "ball"
elements = 8
element_diameter = "1 mm"
pitch_diameter = "7 mm"
inner_conformity = 0.52
outer_conformity = 0.53
"""


def _case(
    tmp_path: Path,
    model: str,
    *,
    bearing: str = 'radial_clearance = "10 um"\n',
    operation: str = 'speed = "5400 rpm"\naxial_load = "20 N"\n',
    extra: str = "",
    revolutions: float = 16,
    samples: int = 4096,
    name: str = "case.toml",
) -> Path:
    text = (
        f'title = "{model}"\n{BEARING}{bearing}[operation]\n{operation}{extra}\n'
        f'[analysis]\nmodel = "{model}"\nrevolutions = {revolutions}\nsamples = {samples}\n'
    )
    if model == "dynamic" and "[dynamics]" not in extra:
        text += '[dynamics]\nmass = "0.1 kg"\ndamping = "50 N*s/m"\n'
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _json(path: Path, command: str = "run") -> dict[str, Any]:
    result = runner.invoke(app, [command, str(path), "--json"])
    assert result.exit_code == 0, result.stderr + result.stdout
    out: dict[str, Any] = json.loads(result.stdout)
    return out


def _refused(path: Path, command: str = "run") -> str:
    result = runner.invoke(app, [command, str(path)])
    assert result.exit_code == 2, result.stdout
    assert "Traceback" not in result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, lines
    return lines[0]


def _line(out: dict[str, Any], direction: str, order: float) -> dict[str, Any]:
    found = [
        c
        for c in out["components"]
        if c["direction"] == direction and abs(c["order"] - order) < 1e-6
    ]
    assert found, f"no {direction} line at order {order}"
    return found[0]


# 1 -------------------------------------------------------------------------------------------
SPECTRUM = """
[[waviness_spectrum]]
part = "outer"
orders = [2, 30]
amplitude = "10 nm"
exponent = -1
phase = "0 deg"
"""


def test_fixed_phase_spectrum_runs(tmp_path: Path) -> None:
    out = _json(_case(tmp_path, "quasi_static_3d", extra=SPECTRUM, revolutions=4, samples=2048))
    assert out["components"], "a fixed-phase spectrum has lines"


def test_seed_with_fixed_phase_is_refused_with_its_index(tmp_path: Path) -> None:
    extra = SPECTRUM + "seed = 3\n"
    line = _refused(_case(tmp_path, "quasi_static_3d", extra=SPECTRUM + extra), "check")
    assert "waviness_spectrum[2].seed" in line
    assert 'only applies to phase = "random"' in line


def test_spectrum_law_error_names_the_entry(tmp_path: Path) -> None:
    extra = SPECTRUM.replace("orders = [2, 30]", "orders = [0, 30]").replace(
        "exponent = -1", "exponent = 1"
    )
    line = _refused(_case(tmp_path, "quasi_static_3d", extra=extra), "check")
    assert "waviness_spectrum[1].orders" in line


# 2 -------------------------------------------------------------------------------------------
def _clearance_of(alpha0_deg: float) -> float:
    a = (0.52 + 0.53 - 1.0) * 1e-3
    return 2.0 * a * (1.0 - math.cos(math.radians(alpha0_deg)))


def test_nominal_contact_angle_sets_the_clearance(tmp_path: Path) -> None:
    nominal = _case(tmp_path, "quasi_static_3d", bearing='nominal_contact_angle = "15 deg"\n')
    out = _json(nominal, "check")
    assert out["model_use"]["radial_clearance_m"] == pytest.approx(_clearance_of(15.0), rel=1e-12)
    # the same bearing given by its clearance runs identically
    given = _case(
        tmp_path,
        "quasi_static_3d",
        bearing=f"radial_clearance = {_clearance_of(15.0)!r}\n",
        name="clearance.toml",
        extra='[[waviness]]\npart = "inner"\norder = 9\namplitude = "5 nm"\n',
    )
    nominal = _case(
        tmp_path,
        "quasi_static_3d",
        bearing='nominal_contact_angle = "15 deg"\n',
        extra='[[waviness]]\npart = "inner"\norder = 9\namplitude = "5 nm"\n',
    )
    a, b = _json(given), _json(nominal)
    assert a["runout"] == b["runout"]
    assert a["contact_angle_deg"] == b["contact_angle_deg"]


def test_nominal_contact_angle_and_a_different_clearance_are_refused(tmp_path: Path) -> None:
    path = _case(
        tmp_path,
        "quasi_static_3d",
        bearing='nominal_contact_angle = "15 deg"\nradial_clearance = "10 um"\n',
    )
    line = _refused(path, "check")
    assert "bearing.radial_clearance" in line and "nominal_contact_angle" in line


@pytest.mark.parametrize("model", ["dynamic", "equilibrium"])
def test_fixed_contact_angle_is_refused_where_the_model_derives_it(
    tmp_path: Path, model: str
) -> None:
    path = _case(tmp_path, model, bearing='radial_clearance = "10 um"\ncontact_angle = "0 deg"\n')
    line = _refused(path)
    assert "bearing.contact_angle" in line
    assert "nominal_contact_angle" in line
    assert '"quasi_static_3d"' in line


def test_dynamic_uses_the_clearance_of_a_nominal_angle(tmp_path: Path) -> None:
    path = _case(
        tmp_path,
        "dynamic",
        bearing='nominal_contact_angle = "15 deg"\n',
        revolutions=4,
        samples=1024,
    )
    out = _json(path, "check")
    assert out["model_use"]["radial_clearance_m"] == pytest.approx(_clearance_of(15.0))
    assert out["bearing"]["radial_clearance_m"] == pytest.approx(_clearance_of(15.0))


# 3 and 4 ---------------------------------------------------------------------------------------
LOAD = 'speed = "5400 rpm"\naxial_load = "20 N"\nradial_load = "5 N"\n'


@pytest.mark.parametrize("model", ["quasi_static_2d", "quasi_static_3d"])
def test_radial_load_moves_the_shaft_along_it_in_every_model(tmp_path: Path, model: str) -> None:
    out = _json(_case(tmp_path, model, operation=LOAD, revolutions=2, samples=256))
    x, y = out["mean_displacement_m"][:2]
    assert y < 0.0 and abs(x) < 1e-3 * abs(y)
    assert out["displacement_of"].startswith("centre of the inner ring (shaft) relative")


def test_two_d_and_three_d_radial_stiffness_differ_by_cos_squared(tmp_path: Path) -> None:
    # small against the preload, so that both are linear (5 N is 0.2 % off)
    light = LOAD.replace('"5 N"', '"0.2 N"')
    two = _json(_case(tmp_path, "quasi_static_2d", operation=light, revolutions=2, samples=256))
    three = _json(_case(tmp_path, "quasi_static_3d", operation=light, revolutions=2, samples=256))
    ratio = three["mean_displacement_m"][1] / two["mean_displacement_m"][1]
    cos2 = math.cos(math.radians(three["contact_angle_deg"])) ** 2
    assert ratio == pytest.approx(1.0 / cos2, rel=2e-4)
    assert any("planar" in note and "cos" in note for note in two["notes"])


@pytest.mark.parametrize("model", ["quasi_static_2d", "quasi_static_3d"])
def test_radial_load_without_preload_names_the_models_with_play(tmp_path: Path, model: str) -> None:
    path = _case(tmp_path, model, operation='speed = "5400 rpm"\nradial_load = "5 N"\n')
    line = _refused(path)
    assert "operation.axial_load" in line and '"equilibrium"' in line and '"dynamic"' in line


@pytest.mark.parametrize("ring", ["inner", "outer"])
def test_displacement_sign_and_phase_agree_between_models(tmp_path: Path, ring: str) -> None:
    # An inner raceway with Z + 1 lobes: the same line, the same phase, in every model.
    extra = '[[waviness]]\npart = "inner"\norder = 9\namplitude = "1 nm"\nphase = "17 deg"\n'
    op = f'rotating_ring = "{ring}"\nspeed = "5400 rpm"\naxial_load = "20 N"\n'
    lines = {}
    for model in ("linear", "quasi_static_2d", "quasi_static_3d"):
        out = _json(_case(tmp_path, model, operation=op, extra=extra, name=f"{model}.toml"))
        top = next(c for c in out["components"] if c["direction"] == "x")
        lines[model] = (round(top["order"], 6), top["phase_rad"])
    orders = {order for order, _ in lines.values()}
    assert len(orders) == 1
    phases = [phase for _, phase in lines.values()]
    assert max(abs(math.remainder(p - phases[0], 2 * math.pi)) for p in phases) < 1e-6


# 5 -------------------------------------------------------------------------------------------
TWO_BALLS = """
[[waviness]]
part = "ball"
element = 1
order = 2
amplitude = "1 nm"
[[waviness]]
part = "ball"
element = 2
order = 2
amplitude = "1 nm"
phase = "57 deg"
"""


@pytest.mark.parametrize("ring", ["inner", "outer"])
def test_spin_sense_puts_the_larger_ball_line_at_the_same_frequency(
    tmp_path: Path, ring: str
) -> None:
    op = f'rotating_ring = "{ring}"\nspeed = "5400 rpm"\naxial_load = "20 N"\n'
    tops = {}
    for model in ("linear", "quasi_static_2d", "quasi_static_3d"):
        out = _json(_case(tmp_path, model, operation=op, extra=TWO_BALLS, name=f"{model}.toml"))
        radial = [c for c in out["components"] if c["direction"] == "x"]
        tops[model] = (round(radial[0]["order"], 6), radial[0]["label"])
    assert len({order for order, _ in tops.values()}) == 1, tops
    # the label's formula names the frequency it sits at: 2 f_b + f_c or |2 f_b - f_c|
    out = _json(_case(tmp_path, "quasi_static_3d", operation=op, extra=TWO_BALLS))
    f = out["frequencies_hz"]
    first_order = [
        c
        for c in out["components"]
        if c["direction"] != "z" and c["sources"][0]["term"] in ("2n f_b + f_c", "2n f_b - f_c")
    ]
    assert first_order
    for c in first_order:
        if c["sources"][0]["term"] == "2n f_b + f_c":
            assert c["frequency_hz"] == pytest.approx(2 * f["ball_spin"] + f["cage"], rel=1e-9)
        else:
            assert c["frequency_hz"] == pytest.approx(abs(2 * f["ball_spin"] - f["cage"]), rel=1e-9)


# 7 -------------------------------------------------------------------------------------------
SLANT = '\n[slant]\namplitude = "0.05 um"\n'


@pytest.mark.parametrize("model", ["quasi_static_2d", "quasi_static_3d", "dynamic"])
def test_slant_is_refused_outside_the_linear_model(tmp_path: Path, model: str) -> None:
    line = _refused(_case(tmp_path, model, extra=SLANT, revolutions=4, samples=1024))
    assert "slant" in line and '"linear"' in line


def test_slant_is_refused_by_the_roller_model(tmp_path: Path) -> None:
    line = _refused(_case(tmp_path, "roller_constraint", extra=SLANT, revolutions=1, samples=64))
    assert "slant" in line and '"linear"' in line


@pytest.mark.parametrize(
    "model", ["linear", "quasi_static_2d", "quasi_static_3d", "dynamic", "roller_constraint"]
)
def test_moment_is_refused_outside_the_equilibrium_model(tmp_path: Path, model: str) -> None:
    op = 'speed = "5400 rpm"\naxial_load = "20 N"\nmoment_load = "0.01 N*m"\n'
    line = _refused(_case(tmp_path, model, operation=op, revolutions=2, samples=256))
    assert "operation.moment_load" in line and '"equilibrium"' in line


def test_equilibrium_says_it_does_not_apply_waviness(tmp_path: Path) -> None:
    extra = '[[waviness]]\npart = "inner"\norder = 9\namplitude = "5 nm"\n[elements]\n'
    extra += "diameter_errors = [" + ", ".join(["0.1e-6"] + ["0"] * 7) + "]\n"
    out = _json(_case(tmp_path, "equilibrium", extra=extra))
    notes = " ".join(out["notes"])
    assert "waviness[1]: not applied by the equilibrium model" in notes
    assert "elements.diameter_errors: not applied by the equilibrium model" in notes
    # and the readable summary says it too
    result = runner.invoke(app, ["run", str(tmp_path / "case.toml")])
    assert "waviness[1]: not applied" in " ".join(result.stdout.split())


def test_ball_waviness_without_element_is_called_coherent(tmp_path: Path) -> None:
    extra = '[[waviness]]\npart = "ball"\norder = 2\namplitude = "5 nm"\n'
    out = _json(_case(tmp_path, "quasi_static_3d", extra=extra, revolutions=4, samples=1024))
    assert any("waviness[1]: no element given" in n and "coherent" in n for n in out["notes"])


def test_check_shows_what_the_model_uses(tmp_path: Path) -> None:
    path = _case(
        tmp_path,
        "quasi_static_3d",
        bearing='radial_clearance = "10 um"\ncontact_angle = "15 deg"\n',
        extra='[[waviness]]\npart = "ball"\norder = 2\namplitude = "5 nm"\n',
    )
    use = _json(path, "check")["model_use"]
    assert use["model"] == "quasi_static_3d"
    assert use["contact_angle_deg"] == pytest.approx(15.0)
    assert use["radial_play_per_ball_m"] == pytest.approx(5e-6)
    assert use["preload_approach_m"] > 0.0
    assert {"key": "bearing.contact_angle", "status": "honoured"} in use["keys"]
    assert any(n.startswith("bearing.radial_clearance: not used") for n in use["notes"])
    text = runner.invoke(app, ["check", str(path)], terminal_width=200).stdout
    assert "As the quasi_static_3d model uses it" in text


def test_check_refuses_what_the_named_model_refuses(tmp_path: Path) -> None:
    op = 'speed = "5400 rpm"\naxial_load = "20 N"\nmoment_load = "0.01 N*m"\n'
    line = _refused(_case(tmp_path, "quasi_static_3d", operation=op), "check")
    assert "operation.moment_load" in line
