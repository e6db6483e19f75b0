"""One cell of the key × model matrix (runout.case.conventions) checked against what the model does.

Shared by tests/unit/case/test_conventions_matrix.py (single-bearing models) and
tests/unit/case/test_spindle_conventions.py (the spindle column, on a spindle case).
"""

from __future__ import annotations

import copy
import json
from collections.abc import Callable
from typing import Any

import pytest

from runout.base.errors import CaseError
from runout.case.conventions import KeyConvention, honouring_models
from runout.case.model import parse_case
from runout.runner import run_model

Data = dict[str, Any]


def comparable(out: dict[str, Any]) -> str:
    """A run's JSON without the entries a key may change without changing results."""
    return json.dumps({k: v for k, v in out.items() if k not in ("notes", "title")}, default=str)


def assert_cell(
    convention: KeyConvention, model: str, base: Data, change: Callable[[Data], None]
) -> None:
    """An honoured key changes the result, a refused key ends with a CaseError naming the
    file, the key and the models that honour it, a key not applied leaves a note naming it."""
    changed = copy.deepcopy(base)
    change(changed)
    status = convention.status(model)
    case = parse_case(changed, "matrix.toml")
    paths = convention.present(case.spec)
    assert paths, "the change must set the key"
    if status == "refused":
        with pytest.raises(CaseError) as info:
            run_model(case)
        message = str(info.value)
        assert "matrix.toml" in message
        assert paths[0] in message
        for other in honouring_models(convention):
            assert f'"{other}"' in message
        return
    result = run_model(case)
    if status == "not_applicable":
        assert any(
            note.startswith(f"{paths[0]}: not applied by the {model}") for note in result.notes
        )
        return
    reference = run_model(parse_case(base, "matrix.toml"))
    assert comparable(result.to_json()) != comparable(reference.to_json())
