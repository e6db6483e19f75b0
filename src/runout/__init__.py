"""runout: rotational accuracy and vibration of rolling bearings from the geometry of their parts.

The package is organised as plain, vectorised physics functions on SI floats and arrays
(``kinematics``, ``contact``, ``imperfections``, ``spectrum``), frozen dataclasses describing a
bearing and its operation (``bearing``), one module per model under ``runout.models``, and the
edges where units and files appear (``units``, ``case``, ``cli``).

From Python, :func:`run` runs a model on a bearing built in code, :func:`load_case` reads a
case file, and :class:`Imperfections` builds the imperfection tables of a case file
(:mod:`runout.api`, docs/python.md). They are imported on first use, so that ``import runout``
stays light.
"""

from typing import TYPE_CHECKING, Any

from runout.base._numba_cache import ensure_numba_cache

ensure_numba_cache()  # before any kernel is compiled: a read-only install must still run

from runout.base.errors import CaseError, GeometryError, NumericalError, RunoutError  # noqa: E402
from runout.geometry.bearing import BallBearing, Material, Operation, RollerBearing  # noqa: E402

if TYPE_CHECKING:
    from runout.api import Imperfections, run
    from runout.case.model import Case, load_case
    from runout.diagnose.fit import diagnose

__version__ = "0.1.0"

#: Names imported on first use: name -> module.
_LAZY = {
    "Case": "runout.case.model",
    "Imperfections": "runout.api",
    "diagnose": "runout.diagnose.fit",
    "load_case": "runout.case.model",
    "run": "runout.api",
}


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        import importlib

        value = getattr(importlib.import_module(_LAZY[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'runout' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted({*globals(), *_LAZY})


__all__ = [
    "BallBearing",
    "Case",
    "CaseError",
    "GeometryError",
    "Imperfections",
    "Material",
    "NumericalError",
    "Operation",
    "RollerBearing",
    "RunoutError",
    "__version__",
    "diagnose",
    "load_case",
    "run",
]
