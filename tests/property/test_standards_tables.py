"""The ISO 3290-1 and ISO 492 tables of runout.case.standards: a tighter grade or class never
allows more than a looser one; K_ia never falls as the bore grows; the lookup returns the row
of the bore's range, and the grade's sigma is V_DWL over the divisor."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from runout.case.standards import (
    BALL_GRADES,
    KIA_BORE_EDGES_MM,
    KIA_UM,
    TOLERANCE_CLASSES,
    StandardsError,
    class_limit,
    grade_sigma,
)

GRADES = list(BALL_GRADES.values())  # tightest first
FIELDS = (
    "diameter_variation",
    "spherical_form",
    "roughness",
    "lot_diameter_variation",
    "gauge_interval",
)


@given(st.integers(0, len(GRADES) - 1), st.integers(0, len(GRADES) - 1))
def test_tighter_grade_allows_no_more(i: int, j: int) -> None:
    tight, loose = GRADES[min(i, j)], GRADES[max(i, j)]
    assert int(tight.name[1:]) <= int(loose.name[1:])
    for name in FIELDS:
        assert getattr(tight, name) <= getattr(loose, name)


@given(st.sampled_from(GRADES), st.floats(0.5, 100.0))
def test_sigma_is_the_lot_variation_over_the_divisor(grade: object, divisor: float) -> None:
    sigma = grade_sigma(grade, divisor)  # type: ignore[arg-type]
    assert sigma * divisor == pytest.approx(grade.lot_diameter_variation, rel=1e-12)  # type: ignore[attr-defined]


# bores [mm]; the lookup reads a bore to 1 nm (an edge given in metres is that edge)
bores = st.one_of(
    st.floats(KIA_BORE_EDGES_MM[0] + 1e-5, KIA_BORE_EDGES_MM[-1]),
    st.sampled_from(KIA_BORE_EDGES_MM[1:]),
)


@given(bores, st.integers(0, 4), st.integers(0, 4))
def test_tighter_class_allows_no_more(d_mm: float, i: int, j: int) -> None:
    loose, tight = TOLERANCE_CLASSES[min(i, j)], TOLERANCE_CLASSES[max(i, j)]
    assert class_limit(tight, d_mm * 1e-3).limit <= class_limit(loose, d_mm * 1e-3).limit


@given(bores, bores, st.sampled_from(TOLERANCE_CLASSES))
def test_kia_does_not_fall_with_the_bore(a: float, b: float, name: str) -> None:
    small, large = sorted((a, b))
    assert class_limit(name, small * 1e-3).limit <= class_limit(name, large * 1e-3).limit


@given(bores, st.sampled_from(TOLERANCE_CLASSES))
def test_lookup_is_the_row_of_the_bore(d_mm: float, name: str) -> None:
    found = class_limit(name, d_mm * 1e-3)
    edges = KIA_BORE_EDGES_MM
    d = round(d_mm, 6)
    (row,) = [k for k in range(len(edges) - 1) if edges[k] < d <= edges[k + 1]]
    assert found.limit == KIA_UM[name][row] * 1e-6
    assert f"{edges[row]:g} mm < d <= {edges[row + 1]:g} mm" in found.source


@given(st.one_of(st.floats(0.0, KIA_BORE_EDGES_MM[0]), st.floats(120.000001, 1e4)))
def test_bores_outside_the_table_are_refused(d_mm: float) -> None:
    with pytest.raises(StandardsError, match="outside"):
        class_limit("P4", d_mm * 1e-3)
