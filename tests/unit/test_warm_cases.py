"""The install-time warm-up runs one case of every model (and the study)."""

from __future__ import annotations

import tomllib
from pathlib import Path

from runout._warm import WARM_CASES
from runout.models import MODEL_MODULES

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_every_model_is_warmed() -> None:
    models = set()
    for verb, name in WARM_CASES:
        path = EXAMPLES / name
        assert path.is_file(), name
        if verb == "run":
            models.add(tomllib.loads(path.read_text())["analysis"]["model"])
    assert models == set(MODEL_MODULES)
    assert any(verb == "study" for verb, _ in WARM_CASES)
