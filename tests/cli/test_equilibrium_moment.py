"""`runout run` with a pure moment on the equilibrium model (seed 001 §2.1, Jones-Harris).

A moment with no axial and no radial force is a legitimate load case (one of the reference
cases of the ISO/TS 16281 test suite: Z = 7, D = 11.5 mm, d_m = 43.5 mm, f_i = 0.52,
f_o = 0.53, zero clearance, M = 1 N m). The inner ring is then held by the moment's couple
alone: the balls on one side of the moment axis press on one flank of the grooves, those on
the other side on the other flank.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

runner = CliRunner()

CASE = """\
title = "ISO/TS 16281 suite, pure moment"
[bearing]
type = "ball"
elements = 7
element_diameter = "11.5 mm"
pitch_diameter = "43.5 mm"
inner_conformity = 0.52
outer_conformity = 0.53
radial_clearance = "{clearance}"
[material]
youngs_modulus = "210 GPa"
poisson_ratio = 0.3
[operation]
rotating_ring = "inner"
speed = "{speed}"
moment_load = "1 N*m"
moment_load_direction = "{direction}"
[analysis]
model = "equilibrium"
"""


def _run(tmp_path: Path, **keys: str) -> dict:
    values = {"clearance": "0 um", "speed": "0 rpm", "direction": "0 deg"} | keys
    path = tmp_path / "moment.toml"
    path.write_text(CASE.format(**values), encoding="utf-8")
    result = runner.invoke(app, ["run", str(path), "--json"])
    assert result.exit_code == 0, result.stderr
    out: dict = json.loads(result.stdout)
    return out


def test_pure_moment_tilts_the_inner_ring_about_the_moment_axis(tmp_path: Path) -> None:
    out = _run(tmp_path)
    assert out["model"] == "equilibrium"
    q = out["ring_displacement"]
    # moment along +x: the ring tilts about +x (tilt_x > 0), not about y
    assert q["tilt_x_rad"] > 1e-3
    assert q["tilt_y_rad"] == pytest.approx(0.0, abs=1e-12 * q["tilt_x_rad"])
    # no axial force: centred axially by the symmetry (rotation by π about the moment axis)
    assert abs(q["axial_m"]) <= 1e-12
    # the radial displacement is second order (7 balls: no mirror symmetry across the axis)
    assert math.hypot(q["x_m"], q["y_m"]) < 1e-2 * 21.75e-3 * q["tilt_x_rad"]
    balls = out["balls"]
    # both flanks carry load: positive contact angles on one side, negative on the other
    angles = [b["inner_contact_angle_deg"] for b in balls if b["inner_load_n"] > 0.0]
    assert max(angles) > 1.0 and min(angles) < -1.0
    assert max(angles) == pytest.approx(-min(angles), rel=1e-9)


def test_pure_moment_direction_turns_the_tilt(tmp_path: Path) -> None:
    a = _run(tmp_path)["ring_displacement"]
    b = _run(tmp_path, direction="90 deg")["ring_displacement"]
    # ball 1 sits at ψ = 0, so a quarter turn of the moment is not a symmetry of 7 balls; the
    # tilt magnitude changes only slightly
    assert b["tilt_y_rad"] > 0.0
    assert abs(b["tilt_x_rad"]) < 1e-3 * b["tilt_y_rad"]
    assert b["tilt_y_rad"] == pytest.approx(a["tilt_x_rad"], rel=0.01)


def test_pure_moment_with_clearance_and_speed(tmp_path: Path) -> None:
    # With clearance the ring first takes up the angular play, then is held elastically; at
    # speed the centrifugal force and the gyroscopic moment are switched on from there.
    out = _run(tmp_path, clearance="10 um", speed="3000 rpm")
    q = out["ring_displacement"]
    assert q["tilt_x_rad"] > 0.0
    # axially centred in the play: δ_a is measured from one-flank contact, A sin α⁰ = P_e / 2
    a = 0.05 * 11.5e-3
    half_play = a * math.sin(math.acos(1.0 - 10e-6 / (2 * a)))
    assert q["axial_m"] == pytest.approx(-half_play, rel=1e-9)
    assert all(math.isfinite(b["inner_load_n"]) for b in out["balls"])


def test_no_load_at_all_is_still_refused(tmp_path: Path) -> None:
    path = tmp_path / "none.toml"
    text = CASE.format(clearance="0 um", speed="0 rpm", direction="0 deg")
    path.write_text(text.replace('moment_load = "1 N*m"\n', ""), encoding="utf-8")
    result = runner.invoke(app, ["run", str(path), "--json"])
    assert result.exit_code != 0
    assert "axial load, a radial load or a moment" in result.stderr
    assert "Traceback" not in result.stderr
