"""runout: rotational accuracy and vibration of rolling bearings from the geometry of their parts.

The package is a stack of stage packages, each importing only those below it (the contract is
checked by ``make test``; docs/architecture.md draws it): ``base`` (errors, units, display,
glossary) -> ``geometry`` (bearing, imperfections, kinematics, Hertz contact, loading) ->
``catalogue`` (bearings by designation) -> ``case`` and ``analysis`` (case files; spectra,
lines and results) -> ``models`` (the physics) -> ``runner``, ``io``, ``diagnose`` -> ``api``,
``examples`` -> ``report`` -> ``study`` -> ``validation`` -> ``cli``.

From Python, :func:`run` runs a model on a bearing built in code, :func:`load_case` reads a
case file, :func:`bearing_coefficients` gives a bearing's stiffness and damping over speed
for a rotor code, and :class:`Imperfections` builds the imperfection tables of a case file
(:mod:`runout.api`, docs/python.md); ``runout.catalogue.lookup("6204")`` gives a catalogue
bearing with the provenance of its values. They are imported on first use, so that ``import runout``
stays light.
"""

import importlib
import importlib.util
import sys
import types
import warnings
from typing import TYPE_CHECKING, Any, cast

from runout.base._numba_cache import ensure_numba_cache

ensure_numba_cache()  # before any kernel is compiled: a read-only install must still run

from runout.base.errors import CaseError, GeometryError, NumericalError, RunoutError  # noqa: E402
from runout.geometry.bearing import BallBearing, Material, Operation, RollerBearing  # noqa: E402

if TYPE_CHECKING:
    from runout.api import BearingCoefficients, Imperfections, bearing_coefficients, run
    from runout.case.model import Case, load_case
    from runout.diagnose.fit import diagnose

__version__ = "0.1.0"

#: Names imported on first use: name -> module.
_LAZY = {
    "BearingCoefficients": "runout.api",
    "Case": "runout.case.model",
    "Imperfections": "runout.api",
    "bearing_coefficients": "runout.api",
    "diagnose": "runout.diagnose.fit",
    "load_case": "runout.case.model",
    "run": "runout.api",
}


#: Subpackages reachable as attributes of ``runout`` (``runout.catalogue.lookup``), imported
#: on first use.
_SUBPACKAGES = ("catalogue",)


def __getattr__(name: str) -> Any:
    if name in _SUBPACKAGES:
        return importlib.import_module(f"runout.{name}")
    if name in _LAZY:
        value = getattr(importlib.import_module(_LAZY[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'runout' has no attribute {name!r}")


#: Module paths of the flat layout (before the stage packages) that keep working for one
#: release, with a DeprecationWarning: old path -> the modules its names now live in.
MOVED_MODULES: dict[str, tuple[str, ...]] = {
    "runout.arrangement": ("runout.study.arrangement",),
    "runout.attribution": ("runout.geometry.attribution",),
    "runout.bearing": ("runout.geometry.bearing",),
    "runout.contact": ("runout.geometry.contact",),
    "runout.conventions": ("runout.case.conventions",),
    "runout.decompose": ("runout.analysis.decompose",),
    "runout.display": ("runout.base.display",),
    "runout.errors": ("runout.base.errors",),
    "runout.glossary": ("runout.base.glossary",),
    "runout.imperfections": ("runout.geometry.imperfections",),
    "runout.input_checks": ("runout.runner.checks",),
    "runout.kinematics": ("runout.geometry.kinematics",),
    "runout.limits": ("runout.case.limits", "runout.case.estimates"),
    "runout.loading": ("runout.geometry.loading",),
    "runout.plotting": ("runout.report.plotting",),
    "runout.reproduce": ("runout.validation.reproduce",),
    "runout.result_details": ("runout.analysis.result_details",),
    "runout.result_files": ("runout.io.result_files", "runout.report.run_files"),
    "runout.results": ("runout.analysis.results", "runout.runner.analysis"),
    "runout.schema_doc": ("runout.case.schema_doc",),
    "runout.spectrum": ("runout.analysis.spectrum",),
    "runout.summary": ("runout.report.summary",),
    "runout.units": ("runout.base.units",),
}


class _MovedModule(types.ModuleType):
    """An old module path: its names are looked up in the modules they moved to."""

    def __getattr__(self, name: str) -> Any:
        for home in MOVED_MODULES[self.__name__]:
            module = importlib.import_module(home)
            if hasattr(module, name):
                return getattr(module, name)
        raise AttributeError(f"module {self.__name__!r} has no attribute {name!r}")


class _MovedFinder:
    """Imports an old module path (:data:`MOVED_MODULES`) as its alias, with a warning."""

    def find_spec(self, fullname: str, path: Any, target: Any = None) -> Any:
        if fullname not in MOVED_MODULES:
            return None
        return importlib.util.spec_from_loader(fullname, cast(Any, self))

    def create_module(self, spec: Any) -> types.ModuleType:
        homes = MOVED_MODULES[spec.name]
        warnings.warn(
            f"{spec.name} is deprecated (runout's modules moved into stage packages); "
            f"import {' or '.join(homes)}",
            DeprecationWarning,
            stacklevel=2,
        )
        return _MovedModule(spec.name)

    def exec_module(self, module: types.ModuleType) -> None:
        """Nothing to run: the alias looks its names up on use."""


if not any(isinstance(f, _MovedFinder) for f in sys.meta_path):
    sys.meta_path.append(_MovedFinder())


def __dir__() -> list[str]:
    return sorted({*globals(), *_LAZY})


__all__ = [
    "BallBearing",
    "BearingCoefficients",
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
    "bearing_coefficients",
    "diagnose",
    "load_case",
    "run",
]
