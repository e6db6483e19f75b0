"""Unit tests of runout.geometry.imperfections and runout.geometry._kernels."""

from __future__ import annotations

import dataclasses
import math
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from runout.base.errors import GeometryError, RunoutError
from runout.geometry._kernels import (
    _PIO2_1,
    _PIO2_2,
    _PIO2_3,
    _PIO2_4,
    _TWO_OVER_PI,
    fast_cos,
    harmonic_sum,
    harmonic_sum_reference,
    harmonic_sum_rows,
)
from runout.geometry.bearing import BallBearing
from runout.geometry.imperfections import (
    BearingImperfections,
    Harmonics,
    ImperfectionError,
    ProfileError,
    ProfileWarning,
    Slant,
    anderon_608_example,
    from_profile,
    pack_harmonics,
    read_profile_csv,
    single_harmonic,
    slant_amplitude,
    slant_angle,
    spectral_law,
)

UM = 1e-6
TWO_PI = 2.0 * math.pi


def direct(h: Harmonics, theta: np.ndarray) -> np.ndarray:
    """Σ a cos(kθ + φ) written out, independent of the code under test."""
    out = np.zeros_like(theta, dtype=float)
    for k, a, p in zip(h.orders, h.amplitudes, h.phases, strict=True):
        out = out + a * np.cos(k * theta + p)
    return out


# ------------------------------------------------------------------------------------------
# Harmonics: normalisation and validation
# ------------------------------------------------------------------------------------------
class TestHarmonicsNormalisation:
    def test_sorted_and_default_phases(self) -> None:
        h = Harmonics([5, 2, 9], [1.0, 2.0, 3.0])
        assert h.orders.tolist() == [2, 5, 9]
        assert h.amplitudes.tolist() == [2.0, 1.0, 3.0]
        assert h.phases.tolist() == [0.0, 0.0, 0.0]
        assert h.orders.dtype == np.int64

    def test_duplicates_merge_by_complex_addition(self) -> None:
        h = Harmonics([3, 3], [1.0, 1.0], [0.0, math.pi / 2])
        assert h.orders.tolist() == [3]
        assert h.amplitudes[0] == pytest.approx(math.sqrt(2.0))
        assert h.phases[0] == pytest.approx(math.pi / 4)

    def test_duplicates_that_cancel_are_dropped(self) -> None:
        h = Harmonics([4, 4, 6], [1.0, 1.0, 2.0], [0.0, math.pi, 0.0])
        # 1 + 1·e^{iπ} leaves a rounding residue of 1.2e-16, far below anything physical
        assert h.amplitudes[h.orders == 6][0] == 2.0
        assert h.amplitudes[h.orders == 4].max(initial=0.0) < 1e-15

    def test_negative_amplitude_flips_phase(self) -> None:
        h = Harmonics([2], [-1.5], [0.25])
        assert h.amplitudes[0] == 1.5
        assert h.phases[0] == pytest.approx(0.25 + math.pi)
        theta = np.linspace(0, 7, 50)
        np.testing.assert_allclose(h.evaluate(theta), -1.5 * np.cos(2 * theta + 0.25), atol=1e-15)

    def test_phases_wrapped(self) -> None:
        h = Harmonics([1, 2, 3], [1.0, 1.0, 1.0], [-0.5, 7.0, -1e-300])
        assert ((h.phases >= 0) & (h.phases < TWO_PI)).all()
        assert h.phases[0] == pytest.approx(TWO_PI - 0.5)
        assert h.phases[1] == pytest.approx(7.0 - TWO_PI)

    def test_zero_amplitudes_dropped(self) -> None:
        h = Harmonics([1, 2], [0.0, 1.0])
        assert h.orders.tolist() == [2]

    def test_order_zero_is_a_signed_size(self) -> None:
        h = Harmonics([0], [2.0], [math.pi / 3])  # value 2 cos 60° = 1
        assert h.amplitudes[0] == pytest.approx(1.0)
        assert h.phases[0] == 0.0
        neg = Harmonics([0], [-3.0])
        assert neg.amplitudes[0] == 3.0
        assert neg.phases[0] == pytest.approx(math.pi)
        assert neg.evaluate(0.3) == pytest.approx(-3.0)
        merged = Harmonics([0, 0], [1.0, -0.25])
        assert merged.evaluate(1.0) == pytest.approx(0.75)

    def test_integral_floats_accepted_as_orders(self) -> None:
        assert Harmonics([2.0, 3.0], [1.0, 1.0]).orders.tolist() == [2, 3]

    def test_immutable(self) -> None:
        h = Harmonics([2], [1.0])
        with pytest.raises(ValueError):
            h.amplitudes[0] = 5.0
        with pytest.raises(dataclasses.FrozenInstanceError):
            h.orders = np.array([3])  # type: ignore[misc]

    def test_equality_and_hash(self) -> None:
        a = Harmonics([2, 3], [1.0, 2.0], [0.1, 0.2])
        b = Harmonics([3, 2], [2.0, 1.0], [0.2, 0.1])
        assert a == b
        assert hash(a) == hash(b)
        assert a != Harmonics([2, 3], [1.0, 2.0001], [0.1, 0.2])
        assert a != "x"

    def test_repr(self) -> None:
        assert "k=2" in repr(Harmonics([2], [1e-6]))
        assert "orders 1..100" in repr(Harmonics(np.arange(1, 101), np.ones(100)))


class TestHarmonicsValidation:
    @pytest.mark.parametrize(
        ("orders", "amplitudes", "phases", "match"),
        [
            ([2], [math.nan], [0.0], "amplitudes: must be finite"),
            ([2], [1.0], [math.inf], "phases: must be finite"),
            ([math.nan], [1.0], [0.0], "orders: must be finite"),
            ([-1], [1.0], [0.0], "orders: must be >= 0"),
            ([2.5], [1.0], [0.0], "orders: must be whole numbers"),
            ([2, 3], [1.0], [0.0], "same length"),
            ([[2, 3]], [[1.0, 1.0]], None, "one-dimensional"),
            (["a"], [1.0], None, "must be numbers"),
        ],
    )
    def test_errors(self, orders, amplitudes, phases, match) -> None:  # type: ignore[no-untyped-def]
        with pytest.raises(ImperfectionError, match=match):
            Harmonics(orders, amplitudes, phases)

    def test_error_types(self) -> None:
        with pytest.raises(ValueError) as info:
            Harmonics([2], [math.nan])
        assert isinstance(info.value, RunoutError)
        assert isinstance(info.value, GeometryError)
        assert info.value.key == "harmonics.amplitudes"  # type: ignore[attr-defined]


# ------------------------------------------------------------------------------------------
# Harmonics: operations
# ------------------------------------------------------------------------------------------
@pytest.fixture
def profile() -> Harmonics:
    return Harmonics([0, 1, 2, 3, 8], [0.2, 1.0, 0.5, 0.3, 0.1], [0.0, 0.4, 1.3, 2.0, 5.9])


class TestHarmonicsOperations:
    def test_evaluate_shapes(self, profile: Harmonics) -> None:
        assert profile.evaluate(0.5).shape == ()
        assert profile.evaluate(np.zeros((3, 4))).shape == (3, 4)
        assert profile(0.5) == profile.evaluate(0.5)
        assert Harmonics.empty().evaluate(np.ones(5)).tolist() == [0.0] * 5

    def test_evaluate_matches_direct_sum(self, profile: Harmonics) -> None:
        theta = np.linspace(-10, 10, 101)
        np.testing.assert_allclose(profile.evaluate(theta), direct(profile, theta), atol=1e-15)

    def test_evaluate_kernel_path(self) -> None:
        h = spectral_law((2, 400), UM, -1.0, seed=4)
        theta = np.linspace(0, 100, 5000).reshape(50, 100)  # 399 x 5000 > threshold
        np.testing.assert_allclose(h.evaluate(theta), direct(h, theta), rtol=0, atol=1e-20)

    def test_add_commutes_and_sums(self, profile: Harmonics) -> None:
        other = Harmonics([2, 5], [0.7, 0.1], [3.0, 1.0])
        theta = np.linspace(0, 6, 40)
        assert profile + other == other + profile
        np.testing.assert_allclose(
            (profile + other).evaluate(theta),
            profile.evaluate(theta) + other.evaluate(theta),
            atol=1e-14,
        )
        assert profile.__add__(3) is NotImplemented

    def test_scaled(self, profile: Harmonics) -> None:
        theta = np.linspace(0, 6, 40)
        np.testing.assert_allclose(
            profile.scaled(-2.5).evaluate(theta), -2.5 * profile.evaluate(theta), atol=1e-14
        )
        assert profile.scaled(0.0).is_empty
        with pytest.raises(ImperfectionError):
            profile.scaled(math.nan)

    def test_shifted_and_mirrored(self, profile: Harmonics) -> None:
        theta = np.linspace(0, 6, 40)
        np.testing.assert_allclose(
            profile.shifted(0.7).evaluate(theta), profile.evaluate(theta + 0.7), atol=1e-14
        )
        np.testing.assert_allclose(
            profile.mirrored().evaluate(theta), profile.evaluate(-theta), atol=1e-14
        )

    def test_band(self, profile: Harmonics) -> None:
        assert profile.band(2, 3).orders.tolist() == [2, 3]
        assert profile.band(3).orders.tolist() == [3, 8]

    def test_derivative(self, profile: Harmonics) -> None:
        theta = np.linspace(0, 6, 40)
        eps = 1e-6
        numeric = (profile.evaluate(theta + eps) - profile.evaluate(theta - eps)) / (2 * eps)
        np.testing.assert_allclose(profile.derivative().evaluate(theta), numeric, atol=1e-8)
        assert 0 not in profile.derivative().orders

    def test_diameter_deviation_seed002_eq26(self, profile: Harmonics) -> None:
        d = profile.diameter_deviation()
        assert d.orders.tolist() == [0, 2, 8]
        np.testing.assert_allclose(d.amplitudes, 2 * profile.amplitudes[[0, 2, 4]])
        theta = np.linspace(0, 6, 40)
        np.testing.assert_allclose(
            d.evaluate(theta),
            profile.evaluate(theta) + profile.evaluate(theta + math.pi),
            atol=1e-14,
        )

    def test_complex_round_trip(self, profile: Harmonics) -> None:
        k, c = profile.to_complex()
        assert Harmonics.from_complex(k, c).evaluate(1.234) == pytest.approx(
            profile.evaluate(1.234)
        )
        np.testing.assert_allclose(c, profile.amplitudes * np.exp(1j * profile.phases))
        with pytest.raises(ImperfectionError):
            Harmonics.from_complex([1], [complex(math.nan, 0)])

    def test_properties(self, profile: Harmonics) -> None:
        assert len(profile) == 5
        assert profile.max_order == 8
        assert not profile.is_empty
        assert Harmonics.empty().is_empty
        assert Harmonics.empty().max_order == 0
        theta = np.arange(4096) * TWO_PI / 4096
        assert profile.rms == pytest.approx(np.sqrt(np.mean(profile.evaluate(theta) ** 2)))

    def test_peak_to_peak_single_harmonic_exact(self) -> None:
        for k in (1, 2, 7, 150):
            h = single_harmonic(k, 0.37 * UM, 0.123)
            assert h.peak_to_peak() == pytest.approx(0.74 * UM, rel=1e-13)

    def test_peak_to_peak_mixture(self, profile: Harmonics) -> None:
        theta = np.linspace(0, TWO_PI, 2_000_001)
        v = profile.evaluate(theta)
        assert profile.peak_to_peak() == pytest.approx(v.max() - v.min(), rel=1e-9)
        assert profile.peak_to_peak() >= v.max() - v.min()

    def test_peak_to_peak_trivial(self) -> None:
        assert Harmonics.empty().peak_to_peak() == 0.0
        assert Harmonics([0], [1.0]).peak_to_peak() == 0.0
        with pytest.raises(ImperfectionError):
            single_harmonic(2, 1.0).peak_to_peak(samples=4)


# ------------------------------------------------------------------------------------------
# Builders
# ------------------------------------------------------------------------------------------
class TestSingleHarmonic:
    def test_amplitude(self) -> None:
        h = single_harmonic(8, 10e-9, 0.5)
        assert (h.orders.tolist(), h.amplitudes.tolist(), h.phases.tolist()) == (
            [8],
            [10e-9],
            [0.5],
        )

    def test_peak_to_peak_halved(self) -> None:
        assert single_harmonic(8, peak_to_peak=20e-9).amplitudes[0] == 10e-9

    def test_order_zero_size_error(self) -> None:
        h = single_harmonic(0, -0.1 * UM)
        assert h.evaluate(2.0) == pytest.approx(-0.1 * UM)

    @pytest.mark.parametrize(
        ("kwargs", "match"),
        [
            ({"order": 2}, "exactly one"),
            ({"order": 2, "amplitude": 1.0, "peak_to_peak": 2.0}, "exactly one"),
            ({"order": 0, "peak_to_peak": 2.0}, "order 0"),
            ({"order": 2, "peak_to_peak": -2.0}, ">= 0"),
            ({"order": 2.5, "amplitude": 1.0}, "whole number"),
            ({"order": True, "amplitude": 1.0}, "whole number"),
            ({"order": 2, "amplitude": math.inf}, "finite"),
            ({"order": 2, "amplitude": 1.0, "phase": math.nan}, "finite"),
            ({"order": -2, "amplitude": 1.0}, ">= 0"),
        ],
    )
    def test_errors(self, kwargs, match) -> None:  # type: ignore[no-untyped-def]
        with pytest.raises(ImperfectionError, match=match):
            single_harmonic(**kwargs)


class TestSpectralLaw:
    def test_law_and_inclusive_range(self) -> None:
        h = spectral_law((2, 10), 0.1 * UM, -1.5, phase=0.3)
        assert h.orders.tolist() == list(range(2, 11))
        np.testing.assert_allclose(h.amplitudes, 0.1 * UM * np.arange(2, 11) ** -1.5)
        assert (h.phases == 0.3).all()

    def test_seed002_eq45_half_open_range(self) -> None:
        # 2 <= k < 800 in the paper is orders=(2, 799) here
        h = spectral_law((2, 799), 0.1 * UM, -1.5, seed=0)
        assert len(h) == 798
        assert h.max_order == 799
        assert h.amplitudes[0] == pytest.approx(0.1 * UM / 2**1.5)

    def test_random_phases_reproducible(self) -> None:
        a = spectral_law((1, 50), UM, -1.0, seed=7)
        b = spectral_law((1, 50), UM, -1.0, seed=7)
        c = spectral_law((1, 50), UM, -1.0, seed=8)
        assert a == b
        assert a != c
        assert ((a.phases >= 0) & (a.phases < TWO_PI)).all()
        np.testing.assert_array_equal(
            a.phases, np.random.default_rng(7).uniform(0.0, TWO_PI, size=50)
        )

    def test_rng_advances(self) -> None:
        rng = np.random.default_rng(3)
        first = spectral_law((1, 20), UM, -1.0, rng=rng)
        second = spectral_law((1, 20), UM, -1.0, rng=rng)
        assert not np.array_equal(first.phases, second.phases)

    @pytest.mark.parametrize(
        ("kwargs", "match"),
        [
            ({"orders": (2, 10), "seed": 1, "rng": np.random.default_rng(1)}, "not both"),
            ({"orders": (2, 10)}, "needs a seed"),
            ({"orders": (2, 10), "phase": 0.0, "seed": 1}, "only makes sense"),
            ({"orders": (2, 10), "phase": "zero"}, "random"),
            ({"orders": (2, 10), "phase": math.nan}, "finite"),
            ({"orders": (0, 10), "seed": 1}, "order 0"),
            ({"orders": (10, 2), "seed": 1}, "k1 <= k2"),
            ({"orders": (2.5, 10), "seed": 1}, "whole numbers"),
            ({"orders": (2, 10, 12), "seed": 1}, "whole numbers"),
            ({"orders": "2-10", "seed": 1}, "whole numbers"),
            ({"orders": (2, 10), "amplitude": -1.0, "seed": 1}, ">= 0"),
            ({"orders": (2, 10), "exponent": math.inf, "seed": 1}, "finite"),
            ({"orders": (2, 10), "rng": 5}, "Generator"),
        ],
    )
    def test_errors(self, kwargs, match) -> None:  # type: ignore[no-untyped-def]
        args = {"amplitude": UM, "exponent": -1.5, **kwargs}
        with pytest.raises(ImperfectionError, match=match):
            spectral_law(**args)


class TestFromProfile:
    truth = Harmonics([2, 3, 7, 15], [1.0, 0.5, 0.2, 0.05], [0.3, 2.0, 4.0, 1.0]).scaled(UM)

    def test_uniform_fft_with_offset(self) -> None:
        n = 128
        theta = 0.37 + np.arange(n) * TWO_PI / n
        got = from_profile(theta, self.truth.evaluate(theta) + 3 * UM, orders=(1, 20))
        np.testing.assert_allclose(
            got.band(2, 20).to_complex()[1][[0, 1, 5, 13]], self.truth.to_complex()[1], atol=1e-20
        )
        assert got.band(1, 1).amplitudes.max(initial=0.0) < 1e-20
        assert 0 not in got.orders  # the mean is dropped by default

    def test_uniform_any_order_and_closing_sample(self) -> None:
        n = 90
        deg = np.arange(n + 1) * 4.0  # 0..360 inclusive
        theta = np.deg2rad(deg)
        dev = self.truth.evaluate(theta)
        perm = np.random.default_rng(0).permutation(n + 1)
        got = from_profile(theta[perm], dev[perm], orders=(2, 15), method="fft")
        k, c = got.to_complex()
        assert k.tolist() == list(range(2, 16))
        np.testing.assert_allclose(c[[0, 1, 5, 13]], self.truth.to_complex()[1], atol=1e-20)
        assert np.abs(np.delete(c, [0, 1, 5, 13])).max() < 1e-20

    def test_default_orders_below_nyquist(self) -> None:
        n = 64
        theta = np.arange(n) * TWO_PI / n
        got = from_profile(theta, self.truth.evaluate(theta))
        assert got.max_order <= 31

    def test_keep_mean(self) -> None:
        n = 64
        theta = np.arange(n) * TWO_PI / n
        got = from_profile(theta, self.truth.evaluate(theta) - 2 * UM, (2, 20), keep_mean=True)
        assert got.evaluate(0.0) == pytest.approx(self.truth.evaluate(0.0) - 2 * UM, abs=1e-20)

    def test_nyquist_error(self) -> None:
        n = 30
        theta = np.arange(n) * TWO_PI / n
        with pytest.raises(ProfileError, match="Nyquist"):
            from_profile(theta, self.truth.evaluate(theta), orders=(1, 15))

    def test_irregular_least_squares(self) -> None:
        rng = np.random.default_rng(5)
        theta = np.sort(np.arange(200) * TWO_PI / 200 + rng.uniform(0, 0.02, 200))
        got = from_profile(theta, self.truth.evaluate(theta) + 1 * UM, orders=(2, 20))
        sub = Harmonics(got.orders, got.amplitudes, got.phases).band(2, 20)
        theta_check = np.linspace(0, TWO_PI, 333)
        np.testing.assert_allclose(
            sub.evaluate(theta_check), self.truth.evaluate(theta_check), atol=1e-18
        )
        assert 0 not in got.orders

    def test_partial_arc_least_squares(self) -> None:
        theta = np.linspace(0.0, 0.8 * TWO_PI, 400)
        got = from_profile(theta, self.truth.evaluate(theta), orders=(2, 15))
        np.testing.assert_allclose(
            got.evaluate(theta), self.truth.evaluate(theta), rtol=0, atol=1e-16
        )

    def test_short_arc_warns(self) -> None:
        theta = np.linspace(0.0, 1.0, 400)
        with pytest.warns(ProfileWarning, match="ill-conditioned"):
            from_profile(theta, self.truth.evaluate(theta), orders=(2, 8))

    def test_tiny_arc_cannot_separate_orders(self) -> None:
        theta = np.linspace(0.0, 0.05, 400)
        with pytest.raises(ProfileError, match=r"cannot separate orders 2\.\.15"):
            from_profile(theta, self.truth.evaluate(theta), orders=(2, 15))

    def test_sparse_irregular_warns(self) -> None:
        theta = np.sort(np.random.default_rng(1).uniform(0, TWO_PI, 60))
        with pytest.warns(ProfileWarning, match="half a wavelength"):
            from_profile(theta, self.truth.evaluate(theta), orders=(2, 25))

    def test_jitter_within_tolerance_uses_fft(self) -> None:
        n = 360
        deg = np.round(np.arange(n) * 1.0 + 1e-5 * np.sin(np.arange(n)), 4)
        theta = np.deg2rad(deg)
        got = from_profile(theta, self.truth.evaluate(theta), orders=(2, 15), method="fft")
        np.testing.assert_allclose(
            got.to_complex()[1][[0, 1, 5, 13]], self.truth.to_complex()[1], atol=1e-6 * UM
        )

    @pytest.mark.parametrize(
        ("theta", "kwargs", "match"),
        [
            (np.linspace(0, 6, 2), {"orders": (1, 1)}, "at least 3"),
            (np.sort(np.random.default_rng(2).uniform(0, 6, 50)), {}, "give orders"),
            (np.arange(16) * TWO_PI / 16, {"orders": (0, 3)}, "keep_mean"),
            (np.arange(16) * TWO_PI / 16, {"orders": (4, 3)}, "k1 <= k2"),
            (np.arange(16) * TWO_PI / 16, {"orders": (1, 2, 3)}, "orders must be"),
            (np.linspace(0, 3, 40), {"orders": (1, 5), "method": "fft"}, "equal steps"),
            (np.linspace(0, 3, 40), {"orders": (1, 25)}, "cannot determine"),
            (np.repeat(np.linspace(0, 6, 5), 10), {"orders": (1, 4)}, "rank"),
            (np.arange(16) * TWO_PI / 16, {"orders": (1, 3), "method": "magic"}, "method"),
            (np.arange(16) * TWO_PI / 16, {"uniform_tolerance": 0.7}, "uniform_tolerance"),
        ],
    )
    @pytest.mark.filterwarnings("ignore::runout.geometry.imperfections.ProfileWarning")
    def test_errors(self, theta, kwargs, match) -> None:  # type: ignore[no-untyped-def]
        with pytest.raises(ProfileError, match=match):
            from_profile(theta, np.cos(3 * theta), **kwargs)

    def test_input_errors(self) -> None:
        with pytest.raises(ProfileError, match="3 angles but 2"):
            from_profile([0.0, 1.0, 2.0], [0.0, 1.0])
        with pytest.raises(ProfileError, match="finite"):
            from_profile([0.0, 1.0, math.nan], [0.0, 1.0, 2.0])
        with pytest.raises(ProfileError, match="numbers"):
            from_profile(["a", "b", "c"], [0.0, 1.0, 2.0])

    def test_too_large_least_squares(self) -> None:
        theta = np.sort(np.random.default_rng(3).uniform(0, TWO_PI, 20_001))
        with pytest.raises(ProfileError, match="too large"):
            from_profile(theta, np.zeros_like(theta), orders=(1, 1000))


class TestReadProfileCsv:
    @staticmethod
    def write(tmp_path: Path, text: str, name: str = "profile.csv") -> Path:
        path = tmp_path / name
        path.write_text(text, encoding="utf-8")
        return path

    def test_header_comments_and_units(self, tmp_path: Path) -> None:
        path = self.write(
            tmp_path, "# roundness of ring 7\nangle_deg,dev_um\n0,0.5\n\n90,-0.25\n180,1.0\n"
        )
        ang, dev = read_profile_csv(path, angle_unit="deg", deviation_scale=1e-6)
        np.testing.assert_allclose(ang, [0.0, math.pi / 2, math.pi])
        np.testing.assert_allclose(dev, [0.5e-6, -0.25e-6, 1.0e-6])

    @pytest.mark.parametrize("sep", [",", ";", "\t", " ", "  "])
    def test_delimiters(self, tmp_path: Path, sep: str) -> None:
        path = self.write(tmp_path, f"0{sep}1\n1{sep}2\n2{sep}3\n")
        ang, dev = read_profile_csv(path, angle_unit="rad")
        assert ang.tolist() == [0.0, 1.0, 2.0]
        assert dev.tolist() == [1.0, 2.0, 3.0]

    def test_columns_and_explicit_delimiter(self, tmp_path: Path) -> None:
        path = self.write(tmp_path, "i|dev|ang\n1|5|0\n2|6|90\n")
        ang, dev = read_profile_csv(path, delimiter="|", columns=(2, 1))
        np.testing.assert_allclose(ang, [0.0, math.pi / 2])
        assert dev.tolist() == [5.0, 6.0]

    def test_bad_row_names_file_and_line(self, tmp_path: Path) -> None:
        path = self.write(tmp_path, "angle,dev\n0,1\n1,oops\n")
        with pytest.raises(ProfileError, match=r"profile\.csv:3: expected numbers") as info:
            read_profile_csv(path)
        assert info.value.line == 3
        assert info.value.file == str(path)
        # a profile may be any file: its contents are never echoed
        assert "oops" not in str(info.value)

    def test_missing_column(self, tmp_path: Path) -> None:
        path = self.write(tmp_path, "0,1\n1\n")
        with pytest.raises(ProfileError, match=":2:"):
            read_profile_csv(path)

    def test_non_finite(self, tmp_path: Path) -> None:
        path = self.write(tmp_path, "0,1\n1,nan\n")
        with pytest.raises(ProfileError, match=":2: non-finite"):
            read_profile_csv(path)

    def test_missing_file_and_empty(self, tmp_path: Path) -> None:
        with pytest.raises(ProfileError, match="cannot read"):
            read_profile_csv(tmp_path / "nope.csv")
        with pytest.raises(ProfileError, match="no data"):
            read_profile_csv(self.write(tmp_path, "# nothing\nangle,dev\n"))

    def test_bad_arguments(self, tmp_path: Path) -> None:
        path = self.write(tmp_path, "0,1\n")
        with pytest.raises(ProfileError, match="angle_unit"):
            read_profile_csv(path, angle_unit="grad")  # type: ignore[arg-type]
        with pytest.raises(ProfileError, match="deviation_scale"):
            read_profile_csv(path, deviation_scale=0.0)

    def test_round_trip_through_from_profile(self, tmp_path: Path) -> None:
        truth = Harmonics([2, 5, 11], [0.4, 0.1, 0.02], [1.0, 2.0, 3.0]).scaled(UM)
        deg = np.arange(720) * 0.5
        dev_um = truth.evaluate(np.deg2rad(deg)) / UM
        text = "angle [deg], deviation [um]\n" + "".join(
            f"{a:.1f}, {d:.12e}\n" for a, d in zip(deg, dev_um, strict=True)
        )
        ang, dev = read_profile_csv(self.write(tmp_path, text), deviation_scale=1e-6)
        got = from_profile(ang, dev, orders=(2, 20))
        np.testing.assert_allclose(
            got.to_complex()[1][[0, 3, 9]], truth.to_complex()[1], rtol=0, atol=1e-9 * UM
        )


# ------------------------------------------------------------------------------------------
# Slant
# ------------------------------------------------------------------------------------------
class TestSlant:
    def test_seed002_eq34(self) -> None:
        beta, r = 0.01, 0.011
        assert slant_amplitude(beta, r) == pytest.approx(
            r * (1 - math.cos(beta)) / (2 * math.cos(beta))
        )
        assert slant_angle(slant_amplitude(beta, r), r) == pytest.approx(beta, rel=1e-12)
        # small-angle form W_s ≈ r β² / 4, without cancellation at tiny angles
        assert slant_amplitude(1e-9, 1.0) == pytest.approx(0.25e-18, rel=1e-9)

    def test_from_angle_and_bearing(self) -> None:
        bearing = BallBearing(7, 3.9688e-3, 15e-3, radial_clearance=10e-6)
        r_o = 0.5 * bearing.outer_raceway_diameter
        s = Slant.from_bearing(bearing, angle=0.004, phase=0.2)
        assert s.amplitude == pytest.approx(slant_amplitude(0.004, r_o))
        assert s.phase == 0.2
        assert Slant.from_angle(0.004, bearing) == Slant.from_angle(0.004, r_o)
        assert Slant.from_bearing(bearing, angle=0.004, radius=11e-3).amplitude == pytest.approx(
            slant_amplitude(0.004, 11e-3)
        )
        assert Slant.from_bearing(bearing, amplitude=0.05 * UM).amplitude == 0.05 * UM
        assert s.angle(r_o) == pytest.approx(0.004)
        with pytest.raises(ImperfectionError, match="exactly one"):
            Slant.from_bearing(bearing)
        with pytest.raises(ImperfectionError, match="exactly one"):
            Slant.from_bearing(bearing, amplitude=1.0, angle=0.1)

    def test_displacement_eq35(self) -> None:
        s = Slant(0.05 * UM, 0.3)
        theta = np.linspace(0, 7, 30)
        np.testing.assert_allclose(s.displacement(theta), 0.05 * UM * np.cos(2 * theta - 0.3))
        assert s.peak_to_peak == 0.1 * UM

    def test_add(self) -> None:
        a, b = Slant(1.0, 0.3), Slant(0.5, 2.0)
        theta = np.linspace(0, 7, 30)
        np.testing.assert_allclose(
            (a + b).displacement(theta), a.displacement(theta) + b.displacement(theta), atol=1e-15
        )
        assert a.__add__(1) is NotImplemented

    @pytest.mark.parametrize(
        ("call", "match"),
        [
            (lambda: Slant(-1.0), ">= 0"),
            (lambda: Slant(math.nan), "finite"),
            (lambda: Slant(1.0, math.inf), "finite"),
            (lambda: slant_amplitude(2.0, 1.0), "90"),
            (lambda: slant_amplitude(0.1, -1.0), "positive length"),
            (lambda: slant_angle(-1.0, 1.0), ">= 0"),
        ],
    )
    def test_errors(self, call, match) -> None:  # type: ignore[no-untyped-def]
        with pytest.raises(ImperfectionError, match=match):
            call()


# ------------------------------------------------------------------------------------------
# BearingImperfections
# ------------------------------------------------------------------------------------------
class TestImperfections:
    def test_perfect(self) -> None:
        imp = BearingImperfections.perfect(7)
        assert imp.n_elements == 7
        assert imp.is_perfect
        assert imp.diameter_errors.tolist() == [0.0] * 7
        assert imp.summary() == []
        for bad in (0, True, 2.5):
            with pytest.raises(ImperfectionError):
                BearingImperfections.perfect(bad)  # type: ignore[arg-type]

    def test_infer_z(self) -> None:
        assert BearingImperfections(diameter_errors=[0.0, 1e-7, 0.0]).n_elements == 3
        assert BearingImperfections(pitch_errors=np.zeros(5)).n_elements == 5
        with pytest.raises(ImperfectionError, match="perfect"):
            BearingImperfections()

    @pytest.mark.parametrize(
        ("kwargs", "match"),
        [
            ({"diameter_errors": [0.0, 1.0]}, r"one value per rolling element \(3\)"),
            ({"pitch_errors": [0.0, 0.0, math.nan]}, "finite"),
            ({"inner": "x"}, "must be Harmonics"),
            ({"elements": (Harmonics.empty(), 3, Harmonics.empty())}, "element 2"),
            ({"slant": 0.1}, "Slant"),
        ],
    )
    def test_validation(self, kwargs, match) -> None:  # type: ignore[no-untyped-def]
        base = {"elements": (Harmonics.empty(),) * 3}
        with pytest.raises(ImperfectionError, match=match):
            BearingImperfections(**{**base, **kwargs})

    def test_frozen(self) -> None:
        imp = BearingImperfections.perfect(3)
        with pytest.raises(dataclasses.FrozenInstanceError):
            imp.slant = None  # type: ignore[misc]
        with pytest.raises(ValueError):
            imp.diameter_errors[0] = 1.0

    def test_add_parts(self) -> None:
        h = single_harmonic(4, 0.1 * UM)
        imp = BearingImperfections.perfect(5)
        assert imp.add("inner", h).inner == h
        assert imp.add("outer", h).outer == h
        assert imp.add("outer", h).add("outer", h).outer == h.scaled(2.0)
        all_balls = imp.add("ball", h)
        assert all(e == h for e in all_balls.elements)
        second = imp.add("roller", h, element=2)
        assert [not e.is_empty for e in second.elements] == [False, True, False, False, False]
        some = imp.add("element", h, element=[1, 5, 5])
        assert [not e.is_empty for e in some.elements] == [True, False, False, False, True]
        assert some.elements[4] == h  # a repeated number adds once
        assert imp.is_perfect and not some.is_perfect

    @pytest.mark.parametrize(
        ("part", "element", "match"),
        [
            ("inner", 1, "only balls or rollers"),
            ("cage", None, "must be"),
            ("ball", 0, "from 1 to 5"),
            ("ball", 6, "from 1 to 5"),
            ("ball", True, "whole numbers"),
            ("ball", [1, 2.0], "whole numbers"),
        ],
    )
    def test_add_errors(self, part, element, match) -> None:  # type: ignore[no-untyped-def]
        with pytest.raises(ImperfectionError, match=match):
            BearingImperfections.perfect(5).add(part, single_harmonic(2, UM), element=element)
        with pytest.raises(ImperfectionError, match="Harmonics"):
            BearingImperfections.perfect(5).add("inner", 3.0)  # type: ignore[arg-type]

    def test_with_methods(self) -> None:
        imp = BearingImperfections.perfect(3)
        h = single_harmonic(3, UM)
        assert imp.with_inner(h).inner == h
        assert imp.with_outer(h).outer == h
        assert imp.with_elements([h, h, h]).elements == (h, h, h)
        with pytest.raises(ImperfectionError, match="one profile per"):
            imp.with_elements([h])
        assert imp.with_diameter_errors([1e-7, 0, 0]).diameter_errors[0] == 1e-7
        assert imp.with_pitch_errors([0, 1e-3, 0]).pitch_errors[1] == 1e-3
        both = imp.with_element_errors(diameter_errors=[1e-7, 0, 0])
        both = both.with_element_errors(pitch_errors=[0, 0, 2e-3])
        assert both.diameter_errors[0] == 1e-7 and both.pitch_errors[2] == 2e-3
        assert imp.with_slant(Slant(1e-8)).slant == Slant(1e-8)
        assert imp.with_slant(Slant(0.0)).is_perfect
        assert imp.with_slant(Slant(1e-8)).with_slant(None).slant is None

    def test_element_diameter_deviation(self) -> None:
        ball = Harmonics([0, 1, 2, 3, 4], [0.01, 0.1, 0.2, 0.3, 0.4], [0, 1, 2, 3, 4]).scaled(UM)
        imp = BearingImperfections.perfect(3).add("ball", ball, element=2)
        imp = imp.with_diameter_errors([0.0, 0.05 * UM, 0.0])
        d = imp.element_diameter_deviation(1)
        assert d.orders.tolist() == [0, 2, 4]
        theta = np.linspace(0, 6, 50)
        expected = ball.evaluate(theta) + ball.evaluate(theta + math.pi) + 0.05 * UM
        np.testing.assert_allclose(d.evaluate(theta), expected, atol=1e-20)
        assert imp.element_diameter_deviation(0).is_empty
        with pytest.raises(IndexError):
            imp.element_diameter_deviation(3)

    def test_evaluate_element_diameters(self) -> None:
        imp = (
            BearingImperfections.perfect(4)
            .add("ball", spectral_law((2, 30), UM, -1.0, seed=1), element=1)
            .add("ball", single_harmonic(2, 0.5 * UM, 1.0), element=3)
            .with_diameter_errors([0.0, 1e-7, 0.0, -2e-7])
        )
        theta = np.random.default_rng(0).uniform(0, 50, (4, 300))
        got = imp.evaluate_element_diameters(theta)
        for j in range(4):
            np.testing.assert_allclose(
                got[j], imp.element_diameter_deviation(j).evaluate(theta[j]), atol=1e-20
            )
        shared = imp.evaluate_element_diameters(theta[0])
        assert shared.shape == (4, 300)
        np.testing.assert_allclose(shared[0], got[0])
        with pytest.raises(ImperfectionError, match="shape"):
            imp.evaluate_element_diameters(np.zeros((3, 5)))

    def test_summary(self) -> None:
        imp = (
            BearingImperfections.perfect(3)
            .add("inner", single_harmonic(8, 10e-9, 0.5))
            .add("ball", single_harmonic(2, 5e-9), element=3)
            .with_element_errors(diameter_errors=[0, -1e-7, 0], pitch_errors=[1e-4, 0, 0])
            .with_slant(Slant(5e-8, 0.1))
        )
        rows = imp.summary()
        assert rows[0] == {
            "part": "inner",
            "element": None,
            "kind": "waviness",
            "order": 8,
            "amplitude": 10e-9,
            "phase": 0.5,
            "unit": "m",
        }
        kinds = [(r["part"], r["element"], r["kind"]) for r in rows]
        assert kinds == [
            ("inner", None, "waviness"),
            ("element", 3, "waviness"),
            ("element", 2, "diameter_error"),
            ("element", 1, "pitch_error"),
            ("slant", None, "slant"),
        ]
        assert rows[2]["amplitude"] == -1e-7
        assert rows[3]["unit"] == "rad"
        assert "Z=3" in repr(imp)

    def test_pack_harmonics(self) -> None:
        parts = [single_harmonic(2, 1.0), Harmonics.empty(), Harmonics([1, 3], [1.0, 2.0])]
        k, a, p, offsets = pack_harmonics(parts)
        assert offsets.tolist() == [0, 1, 1, 3]
        assert k.tolist() == [2.0, 1.0, 3.0]
        assert a.tolist() == [1.0, 1.0, 2.0]
        assert p.tolist() == [0.0, 0.0, 0.0]
        assert k.dtype == np.float64 and offsets.dtype == np.int64
        assert pack_harmonics([])[3].tolist() == [0]


class TestAnderon608Example:
    def test_seed002_eq43_to_47(self) -> None:
        imp = anderon_608_example(seed=1)
        assert imp.n_elements == 7
        assert imp.inner.orders[0] == 1 and imp.inner.amplitudes[0] == 2.5 * UM
        assert imp.inner.phases[0] == 0.0
        assert imp.inner.max_order == 799 and len(imp.inner) == 799
        assert imp.outer.orders[0] == 2 and imp.outer.max_order == 1359
        assert imp.elements[0].orders[0] == 2 and imp.elements[0].max_order == 286
        assert all(e.is_empty for e in imp.elements[1:])
        assert imp.slant == Slant(0.05 * UM, 0.0)
        np.testing.assert_allclose(imp.outer.amplitudes, 0.1 * UM * imp.outer.orders**-1.5)

    def test_reproducible_and_all_balls(self) -> None:
        assert anderon_608_example(seed=2).outer == anderon_608_example(seed=2).outer
        every = anderon_608_example(seed=2, ball_waviness="all")
        assert all(not e.is_empty for e in every.elements)
        assert every.elements[0] != every.elements[1]
        with pytest.raises(ImperfectionError):
            anderon_608_example(seed=2, ball_waviness="some")  # type: ignore[arg-type]
        with pytest.raises(ImperfectionError, match="needs a seed"):
            anderon_608_example()


# ------------------------------------------------------------------------------------------
# Kernels
# ------------------------------------------------------------------------------------------
def _pi_fraction(digits: int = 60) -> Fraction:
    """π from Machin's formula in integer arithmetic."""

    def arctan_inv(x: int, scale: int) -> int:
        total, term, n, sign = 0, scale // x, 1, 1
        while term:
            total += sign * (term // n)
            term //= x * x
            n += 2
            sign = -sign
        return total

    scale = 10 ** (digits + 10)
    return Fraction(4 * (4 * arctan_inv(5, scale) - arctan_inv(239, scale)), scale)


class TestKernels:
    def test_reduction_constants(self) -> None:
        half_pi = _pi_fraction() / 2
        parts = [_PIO2_1, _PIO2_2, _PIO2_3, _PIO2_4]
        residual = half_pi - sum(Fraction(c) for c in parts)
        assert abs(float(residual)) < 1e-38
        for c in parts[:3]:
            mantissa = Fraction(c) / Fraction(2) ** math.frexp(c)[1]
            assert (mantissa * 2**26).denominator == 1  # at most 26 significant bits
        assert _TWO_OVER_PI == float(1 / half_pi)

    def test_fast_cos_matches_numpy(self) -> None:
        rng = np.random.default_rng(0)
        x = np.concatenate(
            [
                rng.uniform(-1e8, 1e8, 20_000),
                rng.uniform(-10, 10, 20_000),
                np.arange(-2000, 2000) * (math.pi / 4),
                np.arange(-2000, 2000) * (math.pi / 2) + 1e-9,
                [0.0, -0.0, 1e-300, math.pi, 1e8],
            ]
        )
        got = harmonic_sum(x, np.ones(1), np.ones(1), np.zeros(1))
        np.testing.assert_allclose(got, np.cos(x), rtol=0, atol=3e-16)
        assert fast_cos(0.5) == pytest.approx(math.cos(0.5), abs=1e-16)

    def test_large_arguments_fall_back(self) -> None:
        theta = np.linspace(0, 1e7, 1001)
        k, a, p = np.array([3000.0, 17.0]), np.array([1.0, 0.5]), np.array([0.1, 2.0])
        np.testing.assert_allclose(
            harmonic_sum(theta, k, a, p), harmonic_sum_reference(theta, k, a, p), atol=1e-15
        )

    def test_non_finite_propagates(self) -> None:
        got = harmonic_sum(np.array([math.nan, 1.0]), np.ones(1), np.ones(1), np.zeros(1))
        assert math.isnan(got[0]) and got[1] == pytest.approx(math.cos(1.0))

    def test_rows(self) -> None:
        theta = np.random.default_rng(1).uniform(0, 100, (3, 2000))
        k = np.array([2.0, 5.0, 1.0, 4.0])
        a = np.array([1.0, 0.5, 0.2, 0.1])
        p = np.array([0.1, 0.2, 0.3, 0.4])
        offsets = np.array([0, 2, 2, 4])
        got = harmonic_sum_rows(theta, k, a, p, offsets)
        np.testing.assert_allclose(got[0], harmonic_sum_reference(theta[0], k[:2], a[:2], p[:2]))
        assert (got[1] == 0.0).all()
        np.testing.assert_allclose(got[2], harmonic_sum_reference(theta[2], k[2:], a[2:], p[2:]))

    def test_reference_chunks(self) -> None:
        theta = np.linspace(0, 10, 1000)
        k, a, p = np.arange(1.0, 51.0), np.ones(50), np.zeros(50)
        np.testing.assert_allclose(
            harmonic_sum_reference(theta, k, a, p, chunk_elements=77),
            harmonic_sum_reference(theta, k, a, p),
            atol=1e-13,
        )
