"""The equilibrium model converges where the gyroscopic friction alone loads a ball.

Found when the Hertz constants moved by a few ulp: under inner-race control a ball with no
overlap at rest, pressed onto the inner race only by the gyroscopic friction, was reached by
none of the ball solve's starts, and ``runout run`` ended with "ball equilibrium ... did not
converge" (exit 2) at operating points like these (Kim's spindle bearing, seed 001).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

CASE = """
[bearing]
type = "ball"
elements = 10
element_diameter = "1.5875 mm"
pitch_diameter = "9.1 mm"
inner_conformity = 0.529
outer_conformity = 0.535
radial_clearance = "5 um"

[operation]
rotating_ring = "inner"
speed = {speed}
axial_load = {axial}
radial_load = {radial}
radial_load_direction = {radial_angle}
moment_load = {moment}
moment_load_direction = {moment_angle}

[analysis]
model = "equilibrium"
race_control = "inner"
"""

POINTS = [
    (404.6448536997266, 15.447190019494316, 58.85354443565682, 0.5790704354511105,
     0.04800804207725232, 4.589931318914306),
    (687.0791930747273, 6.539569221973897, 62.961559170562026, 3.524076281532722,
     0.05709112247670378, 1.2133483448878262),
]  # fmt: skip


@pytest.mark.parametrize("point", POINTS)
def test_run_converges_with_a_ball_held_by_friction(tmp_path: Path, point: tuple) -> None:  # type: ignore[type-arg]
    speed, axial, radial, radial_angle, moment, moment_angle = point
    path = tmp_path / "kim.toml"
    path.write_text(
        CASE.format(
            speed=speed,
            axial=axial,
            radial=radial,
            radial_angle=radial_angle,
            moment=moment,
            moment_angle=moment_angle,
        )
    )
    result = CliRunner().invoke(app, ["run", str(path), "--json"])
    assert result.exit_code == 0, result.stderr
    data = json.loads(result.stdout)
    assert len(data["balls"]) == 10
    assert all(len(row) == 5 for row in data["stiffness_matrix"]["matrix"])
