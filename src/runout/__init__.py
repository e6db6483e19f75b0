"""runout: rotational accuracy and vibration of rolling bearings from the geometry of their parts.

The package is organised as plain, vectorised physics functions on SI floats and arrays
(``kinematics``, ``contact``, ``imperfections``, ``spectrum``), frozen dataclasses describing a
bearing and its operation (``bearing``), one module per model under ``runout.models``, and the
edges where units and files appear (``units``, ``case``, ``cli``).
"""

from runout._cache import ensure_numba_cache

ensure_numba_cache()  # before any kernel is compiled: a read-only install must still run

from runout.bearing import BallBearing, Material, Operation, RollerBearing  # noqa: E402
from runout.errors import CaseError, GeometryError, NumericalError, RunoutError  # noqa: E402

__version__ = "0.1.0"

__all__ = [
    "BallBearing",
    "CaseError",
    "GeometryError",
    "Material",
    "NumericalError",
    "Operation",
    "RollerBearing",
    "RunoutError",
    "__version__",
]
