"""``runout warm`` runs one case of every model (and the study) from the shipped examples."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from runout.cli.warm import WARM_CASES, WarmError, warm
from runout.models import MODEL_MODULES
from runout.validation.cases import examples_dir


def test_every_model_is_warmed() -> None:
    models = set()
    for verb, name, model in WARM_CASES:
        path = examples_dir() / name
        assert path.is_file(), name
        if verb == "run":
            declared = tomllib.loads(path.read_text())["analysis"]["model"]
            assert declared == model, name
            models.add(declared)
    assert models == set(MODEL_MODULES)
    assert any(verb == "study" for verb, _, _ in WARM_CASES)


def test_a_failing_case_names_the_model_and_the_file(tmp_path: Path) -> None:
    # an examples directory without the cases: the first one fails, and says which
    seen: list[tuple[str, str, float | None]] = []
    with pytest.raises(WarmError, match=r"warming the linear kernels failed \(run seed002_608"):
        warm(tmp_path, on_case=lambda *args: seen.append(args))
    assert seen == [("linear", "seed002_608.toml", None)]
