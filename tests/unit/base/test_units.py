"""Unit parsing at the edge."""

from __future__ import annotations

import math

import pytest

from runout.base.units import UnitError, to_si


@pytest.mark.parametrize(
    ("value", "kind", "expected"),
    [
        ("3.9688 mm", "length", 3.9688e-3),
        ("10 um", "length", 10e-6),
        ("10 µm", "length", 10e-6),
        ("0.1 micron", "length", 1e-7),
        (0.002, "length", 0.002),
        ("20 N", "force", 20.0),
        ("2 kgf", "force", 2 * 9.80665),
        ("208 GPa", "pressure", 208e9),
        ("7850 kg/m^3", "density", 7850.0),
        ("10 deg", "angle", math.radians(10)),
        (0.5, "angle", 0.5),
        ("1800 rpm", "speed", 30.0),
        ("30 Hz", "speed", 30.0),
        ("188.49555921538757 rad/s", "speed", 30.0),
        (120, "speed", 120.0),
        ("200 N*s/m", "damping", 200.0),
        ("0.6 kg", "mass", 0.6),
        ("1 g*mm", "mass_length", 1e-6),
        ("0.52", "dimensionless", 0.52),
    ],
)
def test_to_si(value, kind, expected) -> None:
    assert to_si(value, kind) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(
    ("value", "kind", "words"),
    [
        ("3 kg", "length", "is not a length"),
        ("10 mm", "angle", "is not an angle"),
        ("5 N", "speed", "is not a rotational speed"),
        ("fast", "speed", "cannot be read"),
        (True, "length", "boolean"),
        ([1, 2], "length", "as a number or a string"),
        (float("nan"), "length", "finite"),
        ("1 parsec/kg", "force", "is not a force"),
    ],
)
def test_to_si_rejects(value, kind, words) -> None:
    with pytest.raises(UnitError, match=words):
        to_si(value, kind)


def test_registry_falls_back_when_the_pint_cache_cannot_be_written(monkeypatch) -> None:
    import pint

    from runout.base import units

    real = pint.UnitRegistry

    def no_cache(*args, **kwargs):
        if "cache_folder" in kwargs:
            raise PermissionError("read-only cache directory")
        return real(*args, **kwargs)

    monkeypatch.setattr(pint, "UnitRegistry", no_cache)
    units._registry.cache_clear()
    try:
        assert units.to_si("3 mm", "length") == pytest.approx(3e-3)
        assert units.to_si("2 micron", "length") == pytest.approx(2e-6)
    finally:
        monkeypatch.undo()
        units._registry.cache_clear()


def test_rpm_converts_exactly() -> None:
    # through revolutions, not rad/s and back: no 119.99999999999999 Hz in the output
    assert to_si("7200 rpm", "speed") == 120.0
    assert to_si("90 deg/s", "speed") == pytest.approx(0.25, rel=1e-15)


@pytest.mark.parametrize("text", ["1800 rev/min", "1800 rev / min", "30 rev/s", "1800 rpm"])
def test_revolutions_per_minute_read_as_engineers_write_them(text: str) -> None:
    """``rev/min`` (how drawings and ISO 15242 write speeds) reads like ``rpm``."""
    assert to_si(text, "speed") == 30.0
