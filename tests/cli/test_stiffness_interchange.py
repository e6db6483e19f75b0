"""The equilibrium model's stiffness for rotordynamics codes (issue 18, interchange).

`runout run --json` of an equilibrium case carries ``radial_stiffness``: the 2×2 radial block
(kxx, kxy, kyx, kyy [N/m]) of the 5×5 ``stiffness_matrix`` at the operating speed, in the form
a linear bearing element takes (ross.BearingElement's kxx, kxy, kyx, kyy).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

runner = CliRunner()
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _run(path: Path) -> dict:
    result = runner.invoke(app, ["run", str(path), "--json"])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def test_radial_block_is_the_matrix_block_with_round_off_as_zero() -> None:
    out = _run(EXAMPLES / "seed001_kim_equilibrium.toml")
    k = np.array(out["stiffness_matrix"]["matrix"])
    block = out["radial_stiffness"]
    assert block["speed_rpm"] == 7200.0
    assert block["kxx_n_per_m"] == k[1, 1] and block["kyy_n_per_m"] == k[2, 2]
    assert block["kxx_n_per_m"] > 1e7  # a spindle bearing: tens of N/um
    # under a pure axial load the radial directions do not couple: the matrix holds only
    # the derivative's round-off there (1e-17 of the diagonal), reported as 0
    assert abs(k[1, 2]) < 1e-12 * k[1, 1]
    assert block["kxy_n_per_m"] == 0.0 and block["kyx_n_per_m"] == 0.0


def test_radial_block_under_a_radial_load_couples_and_stiffens(tmp_path: Path) -> None:
    text = (EXAMPLES / "seed001_kim_equilibrium.toml").read_text(encoding="utf-8")
    assert 'axial_load = "60.68 N"' in text
    loaded = tmp_path / "loaded.toml"
    loaded.write_text(
        text.replace(
            'axial_load = "60.68 N"',
            'axial_load = "60.68 N"\nradial_load = "200 N"\nradial_load_direction = "30 deg"',
        ),
        encoding="utf-8",
    )
    free = _run(EXAMPLES / "seed001_kim_equilibrium.toml")["radial_stiffness"]
    block = _run(loaded)["radial_stiffness"]
    # a load at 30 deg: the stiffness ellipse turns with it, kxy = kyx != 0
    assert abs(block["kxy_n_per_m"]) > 1e-3 * block["kxx_n_per_m"]
    assert block["kxy_n_per_m"] == pytest.approx(block["kyx_n_per_m"], rel=1e-6)
    # Hertz contacts stiffen under load
    assert block["kxx_n_per_m"] + block["kyy_n_per_m"] > free["kxx_n_per_m"] + free["kyy_n_per_m"]
