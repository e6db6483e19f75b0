"""Case.save writes array profiles under the case file's name (review finding: two cases saved
in one directory both wrote inner_profile_1.csv, so the first silently ran the second's)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
from typer.testing import CliRunner

import runout
from runout.cli.commands import app


def test_two_cases_saved_in_one_directory_keep_their_own_profiles(tmp_path: Path) -> None:
    bearing = runout.BallBearing(
        elements=8, element_diameter=1e-3, pitch_diameter=7e-3, radial_clearance=10e-6
    )
    operation = runout.Operation(rotating_ring="outer", speed=90.0, axial_load=20.0)
    theta = np.linspace(0.0, 2.0 * np.pi, 360, endpoint=False)
    analysis = {"model": "quasi_static_3d", "revolutions": 8, "samples": 1024}
    results = {}
    for name, lobes in (("a", 9), ("b", 4)):
        waves = runout.Imperfections().profile(
            "inner", orders=(2, 12), angles=theta, deviations=1e-8 * np.cos(lobes * theta)
        )
        case = runout.Case.from_inputs(bearing, operation, waves, analysis=analysis)
        case.save(tmp_path / f"{name}.toml")
        results[name] = runout.run(
            "quasi_static_3d",
            bearing=bearing,
            operation=operation,
            imperfections=waves,
            revolutions=8,
            samples=1024,
        )
    assert {"a.inner_profile_1.csv", "b.inner_profile_1.csv"} <= {
        p.name for p in tmp_path.iterdir()
    }
    for name in ("a", "b"):
        done = CliRunner().invoke(app, ["run", str(tmp_path / f"{name}.toml"), "--json"])
        assert done.exit_code == 0, done.stderr
        assert json.loads(done.stdout)["runout"] == results[name].to_json()["runout"]
