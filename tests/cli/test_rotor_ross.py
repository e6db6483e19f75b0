"""A ROSS bearing element built from runout's coefficients holds them on its rotor-speed axis.

ROSS 3 renamed the axes of a bearing's coefficient table: ``speed=`` is the rotor speed (what
ROSS 2 called ``frequency=``) and ``frequency=`` the whirl frequency. This imports whichever
ROSS is installed (``make test`` installs the ``rotor`` extra: ROSS 2.3 on Python 3.11/3.12,
ROSS 3.1 on 3.13), builds a ``BearingElement`` from a sweep's ``stiffness.csv`` (as
docs/interchange.md does) and from :meth:`runout.api.BearingCoefficients.to_ross_kwargs`, and
reads K and C back at two of the sweep's speeds. In ROSS 3 they are read at a whirl frequency
other than the speed: a table put on the whirl axis would give the coefficients of another
row.
"""

from __future__ import annotations

import csv
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from typer.testing import CliRunner

from runout.api import bearing_coefficients
from runout.case.model import load_case
from runout.cli.commands import app

# ROSS is an optional extra (pip install "runout[rotor]"): `make test` installs it, so CI runs
# this; an environment without the extra skips it rather than fail on a missing package
rs = pytest.importorskip(
    "ross", reason="ROSS (the optional rotor extra) is not installed; make test installs it"
)

runner = CliRunner()
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
BASE = (EXAMPLES / "seed001_kim_equilibrium.toml").read_text(encoding="utf-8")
MAJOR = int(rs.__version__.split(".")[0])
#: ROSS interpolates its table (pchip): at a node of the table it gives the node's value to
#: the interpolator's round-off.
RTOL = 1e-12


def _case() -> str:
    text = BASE.replace(
        'axial_load = "60.68 N"',
        'axial_load = "60.68 N"\nradial_load = "150 N"\nradial_load_direction = "30 deg"',
    )
    return text.replace(
        'model = "equilibrium"', 'model = "equilibrium"\nbearing_damping = "kraemer"'
    )


def _read_back(element: Any, w: float) -> tuple[np.ndarray, np.ndarray]:
    """K and C of ``element`` at rotor speed ``w`` [rad/s]."""
    if MAJOR >= 3:
        whirl = 0.37 * w + 11.0  # not the speed: the rotor-speed axis must decide
        return element.K(whirl, speed=w), element.C(whirl, speed=w)
    return element.K(w), element.C(w)


def _expected(t: dict[str, np.ndarray], i: int, kind: str) -> list[list[float]]:
    if kind == "k":
        names, unit = ("kxx", "kxy", "kyx", "kyy", "kzz"), "n_per_m"
    else:
        names, unit = ("cxx", "cxy", "cyx", "cyy", "czz"), "n_s_per_m"
    xx, xy, yx, yy, zz = (float(t[f"{n}_{unit}"][i]) for n in names)
    return [[xx, xy, 0.0], [yx, yy, 0.0], [0.0, 0.0, zz]]


def test_bearing_element_from_stiffness_csv_holds_our_coefficients(tmp_path: Path) -> None:
    study = tmp_path / "sweep.toml"
    study.write_text(
        _case()
        + '\n[study]\nkind = "sweep"\n[study.vary]\n'
        + '"operation.speed" = { values = ["0 rpm", "12000 rpm", "36000 rpm"] }\n',
        encoding="utf-8",
    )
    out = tmp_path / "out"
    assert runner.invoke(app, ["study", str(study), "--out", str(out)]).exit_code == 0
    with (out / "stiffness.csv").open(newline="", encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    t = {name: np.array([float(r[name]) for r in rows]) for name in rows[0] if name[0] in "kcf"}
    assert {r["bearing_damping"] for r in rows} == {"kraemer"}
    speed_axis = "speed" if MAJOR >= 3 else "frequency"
    element = rs.BearingElement(
        n=0,
        **{n: t[f"{n}_n_per_m"] for n in ("kxx", "kxy", "kyx", "kyy", "kzz")},
        **{n: t[f"{n}_n_s_per_m"] for n in ("cxx", "cxy", "cyx", "cyy", "czz")},
        **{speed_axis: t["frequency_rad_per_s"]},
    )
    # the rows differ (the speed unloads the inner contacts), so a wrong axis shows
    assert t["kxx_n_per_m"][1] != t["kxx_n_per_m"][2]
    for i in (1, 2):
        K, C = _read_back(element, float(t["frequency_rad_per_s"][i]))
        np.testing.assert_allclose(K, _expected(t, i, "k"), rtol=RTOL, atol=0.0)
        np.testing.assert_allclose(C, _expected(t, i, "c"), rtol=RTOL, atol=0.0)


def test_to_ross_kwargs_puts_the_speed_on_the_installed_versions_axis(tmp_path: Path) -> None:
    path = tmp_path / "one.toml"
    path.write_text(_case(), encoding="utf-8")
    coefficients = bearing_coefficients(load_case(path), [0.0, 200.0, 600.0])
    element = rs.BearingElement(n=3, **coefficients.to_ross_kwargs(rs.__version__))
    t = {
        name: np.asarray(getattr(coefficients, name))
        for name in coefficients.__dataclass_fields__
        if name[0] in "kc"
    }
    for i in (1, 2):
        K, C = _read_back(element, float(coefficients.frequency_rad_per_s[i]))
        np.testing.assert_allclose(K, _expected(t, i, "k"), rtol=RTOL, atol=0.0)
        np.testing.assert_allclose(C, _expected(t, i, "c"), rtol=RTOL, atol=0.0)
