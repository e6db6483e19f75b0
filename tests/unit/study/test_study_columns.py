"""samples.csv names (runout.io.study_columns) and the digest of a study's case."""

from __future__ import annotations

import hashlib
import json
import re

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from cases import kim_case
from runout.case.model import Case
from runout.io.study_columns import element_column, identifier, line_column
from runout.study import run as st_mod
from runout.study._result import statistics
from runout.study.run import Quantity, StudyResult

IDENTIFIER = re.compile(r"[A-Za-z][A-Za-z0-9_]*")


@given(st.text(max_size=60))
def test_every_text_gives_a_plain_identifier(text: str) -> None:
    assert IDENTIFIER.fullmatch(identifier(text))
    assert "__" not in identifier(text)


def test_names_of_keys_elements_and_lines() -> None:
    assert identifier("operation.axial_load") == "operation_axial_load"
    assert identifier("waviness[1].phase") == "waviness_1_phase"
    assert element_column("diameter_errors", None, 3, 8) == "element_diameter_error_03"
    assert element_column("pitch_errors", "rear", 12, 120) == "element_pitch_error_rear_012"
    assert line_column("x", "inner 9 lobes: nZ+1, n=1") == "x_inner_9_lobes_nZ_plus_1_n_1_pp_m"
    assert line_column("y", "inner 7 lobes: nZ-1, n=1") == "y_inner_7_lobes_nZ_minus_1_n_1_pp_m"
    assert line_column("x", "unattributed 12.5 Hz") == "x_unattributed_12p5_Hz_pp_m"


def test_two_labels_with_one_name_are_numbered_by_key_not_by_size() -> None:
    """Two lines whose labels give one identifier keep distinct columns, numbered in the
    order of their keys: the same names whichever line is larger."""
    q = Quantity("operation.axial_load", ("operation", None, "axial_load"), 1, "sweep")

    def result(first: float, second: float) -> StudyResult:
        return StudyResult(
            kind="sweep",
            title="t",
            seed=1,
            quantities=(q,),
            model=["linear"],
            values={"operation.axial_load": [10.0]},
            runout={k: np.array([1e-8]) for k in st_mod.RUNOUT_KEYS},
            lines={
                "x|a+b": (10.0, np.array([first])),
                "x|a plus b": (20.0, np.array([second])),
            },
            errors={},
        )

    for pair in ((1e-9, 2e-9), (2e-9, 1e-9)):
        names = result(*pair).line_columns()
        assert names == {"x|a plus b": "x_a_plus_b_pp_m", "x|a+b": "x_a_plus_b_pp_m_2"}
        described = result(*pair).column_descriptions()
        assert described["columns"]["x_a_plus_b_pp_m_2"]["label"] == "a+b"
        assert list(described["units"]) == [n for n, _ in result(*pair).columns()]


#: [study] keys added since the digests of earlier versions (allocation, arrangement,
#: statistics): those versions had none of them
ADDED_STUDY_KEYS = {
    "allocate",
    "target_yield",
    "lot",
    "minimise",
    "line",
    "band",
    "random_orders",
    "statistics",
}
#: The chunk size of earlier versions' studies that did not set one (250: its default then).
LEGACY_CHUNK_SIZE = 250


#: Left out of the case document as earlier versions wrote it: the study itself, and tables
#: those versions did not have (an empty [[defect]] list: the case has no spall).
_NEWER_TABLES = {"study", "defect"}


def _old_digest(case: Case) -> str:
    """The digest earlier versions wrote into manifest.json (a case without profiles)."""
    assert case.study is not None
    data = case.spec.model_dump(mode="python", exclude_none=True, exclude=_NEWER_TABLES)
    study = case.study.model_dump(mode="json", exclude=ADDED_STUDY_KEYS)
    study["chunk_size"] = case.study.chunk_size or LEGACY_CHUNK_SIZE  # its default then
    doc = {"case": data, "study": study}
    return hashlib.sha256(json.dumps(doc, sort_keys=True, default=str).encode()).hexdigest()


def test_digest_of_a_case_given_by_clearance_is_unchanged() -> None:
    """Sweep directories of earlier versions resume and load: same case, same digest."""
    case = kim_case(
        study={
            "kind": "sweep",
            "vary": {"operation.axial_load": {"values": ["30 N", "60 N"]}},
        }
    )
    assert st_mod._plan(case, None).digest == _old_digest(case)


def test_digest_of_a_monte_carlo_names_its_sampling() -> None:
    """A Monte Carlo's samples are what its draws make them: sampling version 2 draws other
    bearings than version 1 for the same seed, so its chunks carry another digest (and a
    resume of a version-1 directory is refused by name, tests/cli/test_study_scale.py)."""
    case = kim_case(
        study={"kind": "montecarlo", "samples": 4, "vary": {"element_diameter_sigma": "0.1 um"}}
    )
    data = case.spec.model_dump(mode="python", exclude_none=True, exclude=_NEWER_TABLES)
    study = case.study.model_dump(mode="json", exclude=ADDED_STUDY_KEYS)
    study["chunk_size"] = LEGACY_CHUNK_SIZE  # the default of earlier versions
    doc = {"case": data, "study": study, "sampling": 2}
    digest = hashlib.sha256(json.dumps(doc, sort_keys=True, default=str).encode()).hexdigest()
    assert st_mod._plan(case, None).digest == digest != _old_digest(case)


def test_digest_of_a_case_given_by_its_angle_is_new() -> None:
    """Earlier versions failed every sample of a bearing given by its catalogue angle: a
    resume must recompute their chunks, not take them up."""
    case = kim_case(
        study={"kind": "montecarlo", "samples": 4, "vary": {"element_diameter_sigma": "0.1 um"}}
    )
    data = case.to_document()
    del data["bearing"]["radial_clearance"]
    data["bearing"]["nominal_contact_angle"] = "15 deg"
    from runout.case.model import parse_case

    by_angle = parse_case(data, "angle.toml")
    assert st_mod._plan(by_angle, None).digest != _old_digest(by_angle)


def test_statistics_of_equal_values_beyond_half_a_unit_of_resolution() -> None:
    """All samples equal at a magnitude where numpy's ±0.5 cannot make finite bins (a value a
    tampered chunk can hold, tests/property/test_reading_fuzz.py): a histogram, no error; and
    numpy's own bins wherever it can make them."""
    big = statistics([2.0**48, 2.0**48])
    assert sum(big["histogram"]["counts"]) == 2
    assert big["histogram"]["edges"][0] < 2.0**48 < big["histogram"]["edges"][-1]
    small = statistics([3e-7])
    _, edges = np.histogram(np.array([3e-7]), bins=20)
    assert small["histogram"]["edges"] == [float(e) for e in edges]
