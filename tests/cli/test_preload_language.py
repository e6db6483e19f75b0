"""One preload language: ``[operation] preload = "spring" | "position"`` in every model.

A 6204 with 10 um of diametral play (radial_clearance), 200 N radial and 20 N axial: the
spring (constant-force) preload lets the shaft move axially, so the loaded balls run down to
their groove bottoms and the shaft drops by about the play and the Hertz approach; a position
preload holds the rings at the axial offset the axial load sets alone, and the shaft drops far
less. Each model either gives the solution of the kind it is asked for, or refuses naming the
key and the models that honour it; none gives a number of the other kind.

The reference solutions below are static force balances of the inner ring on the Z balls with
the exact curvature-centre geometry (Harris, *Rolling Bearing Analysis*: curvature centres
A = (f_i + f_o - 1) D apart, Q = K_n δ^1.5), tilt held, averaged over the cage positions of one
ball pitch; they share only K_n and the preloaded angle with the product. The equilibrium
model's inner ring is free to tilt by default, a different problem; with ``[analysis] ring_tilt
= "held"`` it solves the reference's, at its one instant (the reference at its balls' azimuths).
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import fsolve
from typer.testing import CliRunner

from runout.case.model import parse_case
from runout.cli.commands import app

runner = CliRunner()
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

Z = 8
D = 7.938e-3
DM = 33.5e-3
F_I = F_O = 0.52
PLAY = 10e-6  # radial_clearance = the diametral play P_d
RADIAL = 200.0
AXIAL = 20.0


def _case(
    tmp_path: Path, model: str, *, operation: str = "", dynamics: str = "", analysis: str = ""
) -> Path:
    text = f"""title = "6204, 10 um play, 200 N radial, 20 N axial"
[bearing]
type = "ball"
elements = {Z}
element_diameter = "7.938 mm"
pitch_diameter = "33.5 mm"
inner_conformity = {F_I}
outer_conformity = {F_O}
radial_clearance = "10 um"
[operation]
speed = "1800 rpm"
radial_load = "{RADIAL} N"
axial_load = "{AXIAL} N"
{operation}
[analysis]
model = "{model}"
revolutions = 1
samples = 256
{analysis}
"""
    if model == "dynamic":
        text += f'[dynamics]\nmass = "0.5 kg"\ndamping = "3000 N*s/m"\n{dynamics}'
    path = tmp_path / f"{model}.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _json(path: Path, *extra: str) -> dict[str, Any]:
    result = runner.invoke(app, ["run", str(path), "--json", *extra])
    assert result.exit_code == 0, result.stderr + result.stdout
    out: dict[str, Any] = json.loads(result.stdout)
    return out


def _refused(path: Path, *extra: str) -> str:
    result = runner.invoke(app, ["run", str(path), *extra])
    assert result.exit_code == 2, result.stdout
    assert "Traceback" not in result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, lines
    assert str(path) in lines[0]
    return lines[0]


def _reference(kn: float, alpha_p: float, *, held: bool, cages: np.ndarray | None = None) -> float:
    """Mean y [m] of the static shaft, spring (``held=False``) or position preload.

    Averaged over the cage positions ``cages`` [rad] (ball 1's azimuth), by default eight
    across one ball pitch.
    """
    a = (F_I + F_O - 1.0) * D
    cos0 = 1.0 - PLAY / (2.0 * a)  # Harris: P_d = 2A(1 - cos α⁰)
    zp = a * cos0 * math.tan(alpha_p)  # the rings' axial offset under the axial load alone
    ys = []
    if cages is None:
        cages = np.linspace(0.0, 2.0 * math.pi / Z, 8, endpoint=False)
    for cage in cages:
        theta = cage + 2.0 * math.pi * np.arange(Z) / Z

        def residual(q_um: np.ndarray, theta: np.ndarray = theta) -> np.ndarray:
            q = 1e-6 * q_um  # solved in micrometres: fsolve's steps are relative
            x, y, z = q if not held else (*q, 0.0)
            g = -0.5 * PLAY + x * np.cos(theta) + y * np.sin(theta)
            s = np.hypot(a + g, zp + z)
            load = kn * np.clip(s - a, 0.0, None) ** 1.5
            f = np.array(
                [
                    -np.sum(load * (a + g) * np.cos(theta) / s),
                    -np.sum(load * (a + g) * np.sin(theta) / s) - RADIAL,
                    -np.sum(load * (zp + z) / s) + AXIAL,
                ]
            )
            return f[:2] / RADIAL if held else f / RADIAL

        start = np.array([0.0, -1.0] if held else [0.0, -10.0, 0.0])
        q_um, _, ok, msg = fsolve(residual, start, xtol=1e-12, full_output=True)
        assert ok == 1, msg
        ys.append(1e-6 * q_um[1])
    return float(np.mean(ys))


def _dynamic_reference(out: dict[str, Any], *, held: bool) -> float:
    kn = out["contact_stiffness_n_per_m1_5"]
    return _reference(kn, math.radians(out["preload_contact_angle_deg"]), held=held)


# the spring preload --------------------------------------------------------------------------
@pytest.mark.parametrize("operation", ["", 'preload = "spring"'])
def test_dynamic_spring_preload_gives_the_exact_spring_solution(
    tmp_path: Path, operation: str
) -> None:
    out = _json(_case(tmp_path, "dynamic", operation=operation))
    exact = _dynamic_reference(out, held=False)
    assert exact < -9e-6  # the loaded balls reach their groove bottoms: about the play
    assert out["mean_displacement_m"][1] == pytest.approx(exact, rel=0.01)
    assert out["preload"] == "spring"
    assert len(out["mean_displacement_m"]) == 3  # z is a degree of freedom


def _equilibrium_reference(tmp_path: Path, out: dict[str, Any]) -> float:
    """The spring solution at the equilibrium model's one instant (its balls' azimuths)."""
    kn = _json(_case(tmp_path, "dynamic"))["contact_stiffness_n_per_m1_5"]
    azimuth = np.radians([row["azimuth_deg"] for row in out["balls"]])
    assert azimuth == pytest.approx(azimuth[0] + 2.0 * math.pi * np.arange(Z) / Z, abs=1e-12)
    return _reference(kn, 0.0, held=False, cages=azimuth[:1])


def test_equilibrium_with_the_tilt_held_gives_the_exact_spring_solution(tmp_path: Path) -> None:
    # the reference holds the tilt, as quasi_static_3d and dynamic do: so must equilibrium
    out = _json(_case(tmp_path, "equilibrium", analysis='ring_tilt = "held"'))
    exact = _equilibrium_reference(tmp_path, out)
    assert out["mean_displacement_m"][1] == pytest.approx(exact, rel=0.01)
    # and the cage-averaged solution of the other models, the ball under the load or not
    averaged = _dynamic_reference(_json(_case(tmp_path, "dynamic")), held=False)
    assert out["mean_displacement_m"][1] == pytest.approx(averaged, rel=0.01)
    assert out["ring_tilt"] == "held" and out["held_dofs"] == ["tilt_x", "tilt_y"]
    assert out["ring_displacement"]["tilt_x_rad"] == 0.0
    assert out["ring_displacement"]["tilt_y_rad"] == 0.0
    # the balls' moment is now a reaction: the radial load's offset from the ball plane
    # about x (the load along -y), none about y
    mx, my = out["reaction_moment_n_m"]
    assert abs(mx) > 1e-3 * RADIAL * DM / 2 and abs(my) < 1e-9 * abs(mx)
    assert len(out["stiffness_matrix"]["matrix"]) == 5
    assert any("ring_tilt" in n and "reaction" in n for n in out["notes"])


def test_equilibrium_with_the_tilt_free_answers_another_problem(tmp_path: Path) -> None:
    out = _json(_case(tmp_path, "equilibrium"))
    held = _json(_case(tmp_path, "equilibrium", analysis='ring_tilt = "held"'))
    exact = _equilibrium_reference(tmp_path, out)
    # the ring tilts into the load: it drops by more than the tilt-held answer
    assert out["mean_displacement_m"][1] < exact * 1.05
    assert abs(out["mean_displacement_m"][1] - held["mean_displacement_m"][1]) > 0.05 * abs(exact)
    assert out["ring_tilt"] == "free" and out["held_dofs"] == []
    assert out["reaction_moment_n_m"] == [0.0, 0.0]
    notes = [n for n in out["notes"] if "free to tilt" in n]
    assert len(notes) == 1 and 'ring_tilt = "held"' in notes[0]


def test_equilibrium_reaction_moment_applied_holds_the_free_ring_untilted(
    tmp_path: Path,
) -> None:
    # the reaction moment is the moment load that holds a free ring at zero tilt: applied as
    # moment_load, the free ring stays where the held one is
    held = _json(_case(tmp_path, "equilibrium", analysis='ring_tilt = "held"'))
    mx, my = held["reaction_moment_n_m"]
    moment = f"moment_load = {math.hypot(mx, my)!r}\nmoment_load_direction = {math.atan2(my, mx)!r}"
    free = _json(_case(tmp_path, "equilibrium", operation=moment))
    tilt = free["ring_displacement"]
    scale = abs(held["mean_displacement_m"][1]) / (DM / 2)  # a tilt of this size would matter
    assert abs(tilt["tilt_x_rad"]) < 1e-6 * scale and abs(tilt["tilt_y_rad"]) < 1e-6 * scale
    assert free["mean_displacement_m"] == pytest.approx(held["mean_displacement_m"], abs=1e-12)


def test_equilibrium_refuses_a_moment_on_a_ring_held_against_tilt(tmp_path: Path) -> None:
    path = _case(
        tmp_path,
        "equilibrium",
        operation="moment_load = 0.1",
        analysis='ring_tilt = "held"',
    )
    line = _refused(path)
    assert "analysis.ring_tilt" in line and "moment_load" in line


@pytest.mark.parametrize("model", ["quasi_static_3d", "dynamic"])
@pytest.mark.parametrize("tilt", ["held", "free"])
def test_ring_tilt_is_refused_outside_the_equilibrium_model(
    tmp_path: Path, model: str, tilt: str
) -> None:
    line = _refused(_case(tmp_path, model, analysis=f'ring_tilt = "{tilt}"'))
    assert "analysis.ring_tilt" in line and '"equilibrium"' in line


def test_equilibrium_summary_names_the_reaction_moment(tmp_path: Path) -> None:
    path = _case(tmp_path, "equilibrium", analysis='ring_tilt = "held"')
    result = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "out")])
    assert result.exit_code == 0, result.stderr
    assert "reaction moment" in result.stdout and "tilt held" in result.stdout


def test_dynamic_default_says_the_preload_is_a_spring(tmp_path: Path) -> None:
    out = _json(_case(tmp_path, "dynamic"))
    notes = [n for n in out["notes"] if n.startswith("operation.preload")]
    assert len(notes) == 1 and '"position"' in notes[0] and "default" in notes[0]
    # a case that names its kind gets no such note
    named = _json(_case(tmp_path, "dynamic", operation='preload = "spring"'))
    assert not [n for n in named["notes"] if n.startswith("operation.preload")]


# the position preload ------------------------------------------------------------------------
def test_dynamic_position_preload_holds_the_rings_at_their_preloaded_offset(
    tmp_path: Path,
) -> None:
    out = _json(_case(tmp_path, "dynamic", operation='preload = "position"'))
    held = _dynamic_reference(out, held=True)
    assert out["preload"] == "position"
    assert out["mean_displacement_m"][1] == pytest.approx(held, rel=0.01)
    spring = _dynamic_reference(out, held=False)
    assert abs(held - spring) > 0.5 * abs(spring)  # the two kinds are far apart here


@pytest.mark.parametrize("model", ["quasi_static_3d", "equilibrium"])
def test_position_preload_is_refused_where_the_axial_load_is_a_force(
    tmp_path: Path, model: str
) -> None:
    path = _case(tmp_path, model, operation='preload = "position"')
    line = _refused(path)
    assert "operation.preload" in line and '"dynamic"' in line


def test_position_preload_is_noted_where_the_lines_do_not_depend_on_it(tmp_path: Path) -> None:
    out = _json(_case(tmp_path, "linear", operation='preload = "position"'))
    assert any(n.startswith("operation.preload: not applied by the linear") for n in out["notes"])


# old case files: [dynamics] axial_dof ----------------------------------------------------------
def test_axial_dof_keeps_the_result_of_an_old_case_file_and_says_what_to_write(
    tmp_path: Path,
) -> None:
    old = _json(_case(tmp_path, "dynamic", dynamics="axial_dof = false\n"))
    new = _json(_case(tmp_path, "dynamic", operation='preload = "position"'))
    assert old["preload"] == "position"
    assert old["mean_displacement_m"][1] == pytest.approx(new["mean_displacement_m"][1], rel=1e-9)
    notes = [n for n in old["notes"] if n.startswith("dynamics.axial_dof")]
    assert len(notes) == 1 and 'preload = "position"' in notes[0]
    spring = _json(_case(tmp_path, "dynamic", dynamics="axial_dof = true\n"))
    assert spring["preload"] == "spring"
    assert any('preload = "spring"' in n for n in spring["notes"])


@pytest.mark.parametrize(("preload", "axial_dof"), [("spring", "false"), ("position", "true")])
def test_axial_dof_contradicting_the_preload_is_refused(
    tmp_path: Path, preload: str, axial_dof: str
) -> None:
    path = _case(
        tmp_path,
        "dynamic",
        operation=f'preload = "{preload}"',
        dynamics=f"axial_dof = {axial_dof}\n",
    )
    line = _refused(path)
    assert "dynamics.axial_dof" in line and "operation.preload" in line


@settings(max_examples=30, deadline=None)
@given(
    preload=st.sampled_from([None, "spring", "position"]),
    axial_dof=st.sampled_from([None, True, False]),
    model=st.sampled_from(["dynamic", "quasi_static_3d"]),
)
def test_one_kind_whatever_keys_name_it(
    preload: str | None, axial_dof: bool | None, model: str
) -> None:
    # the kind a case runs with: the preload key, else (dynamic only) the old axial_dof,
    # else spring; two keys that disagree are refused, never resolved one way
    operation: dict[str, Any] = {"speed": 30.0, "axial_load": 20.0}
    dynamics: dict[str, Any] = {"mass": 0.5}
    if preload is not None:
        operation["preload"] = preload
    if axial_dof is not None:
        dynamics["axial_dof"] = axial_dof
    data = {
        "bearing": {
            "type": "ball",
            "elements": Z,
            "element_diameter": D,
            "pitch_diameter": DM,
            "inner_conformity": F_I,
            "outer_conformity": F_O,
            "radial_clearance": PLAY,
        },
        "operation": operation,
        "analysis": {"model": model},
        "dynamics": dynamics,
    }
    from_dof = None if axial_dof is None else ("spring" if axial_dof else "position")
    if preload is not None and from_dof is not None and preload != from_dof:
        with pytest.raises(Exception, match="axial_dof"):
            parse_case(data, "case.toml")
        return
    case = parse_case(data, "case.toml")
    expected = preload or (from_dof if model == "dynamic" else None) or "spring"
    assert case.operation.preload == expected


# the planar and fixed-angle models ---------------------------------------------------------------
def test_two_d_refuses_a_radial_load_that_unloads_balls(tmp_path: Path) -> None:
    line = _refused(_case(tmp_path, "quasi_static_2d"))
    assert "operation.radial_load" in line and '"dynamic"' in line


def test_check_refuses_what_run_refuses_for_the_loads_alone(tmp_path: Path) -> None:
    """`check` refuses the 2-D model's radial load as `run` does: the loads alone unload balls
    of the perfect bearing (before, `check` accepted the case and only `run` refused)."""
    result = runner.invoke(app, ["check", str(_case(tmp_path, "quasi_static_2d"))])
    assert result.exit_code == 2, result.stdout
    line = result.stderr.strip()
    assert len(line.splitlines()) == 1 and "operation.radial_load" in line


def test_two_d_refuses_balls_the_waviness_unloads_as_a_state_not_an_input(tmp_path: Path) -> None:
    """Every ball of the perfect bearing carries load; a large waviness unloads some at some
    instants: the model cannot follow that state (a lost contact at an instant, exit 2), but
    the loads are valid input (`check` accepts them)."""
    path = _case(tmp_path, "quasi_static_2d")
    text = path.read_text(encoding="utf-8").replace(f'"{RADIAL} N"', '"2 N"')
    path.write_text(text + '[[waviness]]\npart = "inner"\norder = 10\namplitude = "5 um"\n')
    assert runner.invoke(app, ["check", str(path)]).exit_code == 0
    line = _refused(path)
    rest = line.split(f"{path}: ", 1)[1]
    assert not rest.startswith("operation."), line
    assert "with the imperfections unloads" in line and "at instant" in line


def test_two_d_runs_a_radial_load_that_keeps_every_ball_loaded(tmp_path: Path) -> None:
    path = _case(tmp_path, "quasi_static_2d")
    light = path.read_text(encoding="utf-8").replace(f'"{RADIAL} N"', '"2 N"')
    path.write_text(light, encoding="utf-8")
    out = _json(path)
    assert out["mean_displacement_m"][1] < 0.0
    assert not any("lost contact" in n for n in out["notes"])


def test_three_d_says_why_it_cannot_hold_the_radial_load(tmp_path: Path) -> None:
    line = _refused(_case(tmp_path, "quasi_static_3d"))
    # at a fixed contact angle α the balls carry at most F_a / tan α radially
    assert "operation.radial_load" in line and '"dynamic"' in line
    assert "tan" in line


def test_three_d_agrees_with_the_dynamic_spring_where_every_ball_stays_loaded(
    tmp_path: Path,
) -> None:
    # 20 N radial against 200 N axial: every ball loaded, the contact angles barely move
    def light(model: str) -> Path:
        path = _case(tmp_path, model)
        text = path.read_text(encoding="utf-8")
        text = text.replace(f'"{RADIAL} N"', '"20 N"').replace(f'"{AXIAL} N"', '"200 N"')
        path.write_text(text, encoding="utf-8")
        return path

    three = _json(light("quasi_static_3d"))["mean_displacement_m"][1]
    dynamic = _json(light("dynamic"))["mean_displacement_m"][1]
    assert three == pytest.approx(dynamic, rel=0.02)


# the spindle's own keys ------------------------------------------------------------------------
def test_spindle_preload_kind_contradicting_its_table_is_refused() -> None:
    case = EXAMPLES / "spindle_hdd.toml"  # a 20 N spring preload in [spindle]
    result = runner.invoke(app, ["run", str(case), "--set", 'operation.preload="position"'])
    assert result.exit_code == 2, result.stdout
    line = result.stderr.strip()
    assert "operation.preload" in line and "preload_displacement" in line


# the readable summary --------------------------------------------------------------------------
@pytest.mark.parametrize("kind", ["spring", "position"])
def test_summary_shows_the_preload_kind(tmp_path: Path, kind: str) -> None:
    path = _case(tmp_path, "dynamic", operation=f'preload = "{kind}"')
    result = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "out")])
    assert result.exit_code == 0, result.stderr
    assert f"{kind} preload" in result.stdout


def test_axial_limit_follows_the_preload_kind_in_the_dynamic_model(tmp_path: Path) -> None:
    # a spring preload moves the rotor axially: an axial-runout limit is judged; a position
    # preload holds it, and the limit is refused rather than judged on a held z
    limit = 'limit = "1 um"\nlimit_on = "axial_pp"\n'
    path = _case(tmp_path, "dynamic", operation='preload = "spring"')
    path.write_text(
        path.read_text(encoding="utf-8").replace("[analysis]\n", f"[analysis]\n{limit}")
    )
    verdict = _json(path)["verdict"]
    assert verdict["quantity"] == "axial_pp" and verdict["value_m"] > 0.0
    held = path.read_text(encoding="utf-8").replace('"spring"', '"position"')
    path.write_text(held, encoding="utf-8")
    line = _refused(path)
    assert "analysis.limit_on" in line
