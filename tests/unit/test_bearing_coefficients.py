"""runout.api.bearing_coefficients: a bearing's coefficients over speed, as rotor codes take
them (the Python form of a sweep's stiffness.csv)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import runout
from runout.api import BearingCoefficients, bearing_coefficients
from runout.case.model import load_case
from runout.runner import run_model

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
BASE = (EXAMPLES / "seed001_kim_equilibrium.toml").read_text(encoding="utf-8")
SPEEDS_HZ = [0.0, 120.0, 400.0]


def _case(tmp_path: Path, damping: str = "", model: str = "equilibrium") -> runout.Case:
    path = tmp_path / "case.toml"
    text = BASE.replace('model = "equilibrium"', f'model = "{model}"\n{damping}')
    path.write_text(text, encoding="utf-8")
    return load_case(path)


def test_each_row_is_the_run_at_that_speed(tmp_path: Path) -> None:
    case = _case(tmp_path, 'bearing_damping = "proportional"\nbearing_damping_coefficient = 2e-5')
    got = bearing_coefficients(case, SPEEDS_HZ)
    assert isinstance(got, BearingCoefficients)
    assert got.damping_model == "proportional" and got.damping_coefficient_s == 2e-5
    np.testing.assert_array_equal(got.speed_hz, SPEEDS_HZ)
    np.testing.assert_allclose(got.speed_rpm, np.multiply(SPEEDS_HZ, 60.0), rtol=1e-15)
    np.testing.assert_allclose(got.frequency_rad_per_s, np.multiply(SPEEDS_HZ, 2 * np.pi), 1e-15)
    for i, speed in enumerate(SPEEDS_HZ):
        text = (tmp_path / "case.toml").read_text(encoding="utf-8")
        (tmp_path / "one.toml").write_text(
            text.replace('speed = "7200 rpm"', f"speed = {speed!r}"), encoding="utf-8"
        )
        details = run_model(load_case(tmp_path / "one.toml")).details
        k = details.radial_stiffness
        assert got.kxx_n_per_m[i] == k.kxx_n_per_m and got.kyy_n_per_m[i] == k.kyy_n_per_m
        assert got.kxy_n_per_m[i] == k.kxy_n_per_m and got.kyx_n_per_m[i] == k.kyx_n_per_m
        assert got.kzz_n_per_m[i] == details.stiffness_matrix.matrix[0][0]
        assert got.cxx_n_s_per_m[i] == details.bearing_damping.cxx_n_s_per_m
        assert got.czz_n_s_per_m[i] == details.bearing_damping.czz_n_s_per_m
    # centrifugal force unloads the inner contacts: the stiffness moves with speed
    assert len(set(got.kxx_n_per_m)) == len(SPEEDS_HZ)


def test_no_damping_gives_zero_damping_named_none(tmp_path: Path) -> None:
    got = bearing_coefficients(_case(tmp_path), [50.0])
    assert got.damping_model == "none" and got.damping_coefficient_s == 0.0
    assert got.cxx_n_s_per_m.tolist() == [0.0] and got.czz_n_s_per_m.tolist() == [0.0]
    assert got.kxx_n_per_m[0] > 0.0


@pytest.mark.parametrize(("version", "axis"), [("2.3.0", "frequency"), ("3.1.0", "speed")])
def test_ross_kwargs_name_the_rotor_speed_axis_of_each_major(
    tmp_path: Path, version: str, axis: str
) -> None:
    got = bearing_coefficients(_case(tmp_path, 'bearing_damping = "kraemer"'), [10.0, 20.0])
    kwargs = got.to_ross_kwargs(version)
    assert set(kwargs) == {
        *("kxx", "kxy", "kyx", "kyy", "kzz", "cxx", "cxy", "cyx", "cyy", "czz"),
        axis,
    }
    np.testing.assert_array_equal(kwargs[axis], got.frequency_rad_per_s)
    np.testing.assert_array_equal(kwargs["cyy"], got.cyy_n_s_per_m)


@pytest.mark.parametrize("version", ["1.5.0", "4.0.0", "dev"])
def test_ross_kwargs_refuse_a_version_whose_axis_is_unknown(tmp_path: Path, version: str) -> None:
    got = bearing_coefficients(_case(tmp_path), [10.0])
    with pytest.raises(ValueError, match="speed axis of ROSS 2"):
        got.to_ross_kwargs(version)


@pytest.mark.parametrize("speeds", [[], [-1.0], [float("nan")], [[1.0, 2.0]]])
def test_bad_speeds_are_refused_naming_the_key(tmp_path: Path, speeds: list) -> None:
    with pytest.raises(runout.CaseError, match=r"operation\.speed"):
        bearing_coefficients(_case(tmp_path), speeds)


def test_another_model_is_refused(tmp_path: Path) -> None:
    with pytest.raises(runout.CaseError, match=r"analysis\.model"):
        bearing_coefficients(_case(tmp_path, model="quasi_static_3d"), [10.0])
