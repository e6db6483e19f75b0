"""The example case files the checks compute from, and their variants.

The files ship inside the package (``runout.examples.data``, byte-identical copies of the
repository's ``examples/*.toml``) and are found with :mod:`importlib.resources`, so that
``runout reproduce`` works from an installed wheel as from a source checkout. A check that
reproduces a table or a figure names its file with :func:`uses`; the document lists them under
the names the user knows (``examples/NAME``).
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from runout.case.model import Case
    from runout.geometry.bearing import BallBearing

__all__ = [
    "EXAMPLE_USES",
    "ball_bearing",
    "example_path",
    "examples_dir",
    "fixed_contact_angle",
    "load",
    "uses",
    "variant",
]

EXAMPLE_USES: dict[str, str] = {}
"""Example file name → what it reproduces (filled as the checks are built)."""


@functools.cache
def examples_dir() -> Path:
    """The directory of the shipped example case files.

    Returns
    -------
    Path
        ``runout/examples/data`` of the imported package (a source checkout or an installed
        wheel; both are plain directories).
    """
    root = resources.files("runout.examples.data")
    # an installed wheel and a checkout are both directories on disk; a zipped import is not
    # supported (parse_case resolves relative profile paths against a real directory)
    return Path(str(root))


def example_path(name: str) -> Path:
    """The path of the example case file ``name`` (e.g. ``"seed002_608.toml"``).

    Parameters
    ----------
    name : str
        File name in :func:`examples_dir`.

    Returns
    -------
    Path
        The file.

    Raises
    ------
    runout.base.errors.RunoutError
        No such file.
    """
    path = examples_dir() / name
    if not path.is_file():
        from runout.base.errors import RunoutError

        raise RunoutError(f"no example case file {name!r} in {examples_dir()}")
    return path


def load(name: str) -> Case:
    """The example case file ``name``, parsed and validated.

    Parameters
    ----------
    name : str
        File name in :func:`examples_dir` (e.g. ``"seed002_608.toml"``).

    Returns
    -------
    Case
        The validated case.
    """
    from runout.case.model import load_case

    return load_case(example_path(name))


def variant(name: str, mutate: Callable[[dict[str, Any]], None]) -> Case:
    """The example ``name`` with its data changed by ``mutate`` (a loop done in code).

    Parameters
    ----------
    name : str
        File name in :func:`examples_dir`.
    mutate : callable
        Changes the case's data (the dictionary of its tables, as the file gives them) in
        place.

    Returns
    -------
    Case
        The changed data, validated as a case file (relative paths against
        :func:`examples_dir`).
    """
    from runout.case.model import parse_case

    case = load(name)
    data = case.spec.model_dump(exclude_none=True)
    mutate(data)
    return parse_case(data, str(example_path(name)), examples_dir())


def uses(name: str, what: str) -> str:
    """Register that a check computes from the example ``name`` (reproducing ``what``).

    Parameters
    ----------
    name : str
        File name in :func:`examples_dir`.
    what : str
        What the file reproduces (e.g. a paper's table), for the document's index; the first
        registration of a file is kept.

    Returns
    -------
    str
        ``name``, for :attr:`Check.case`.
    """
    EXAMPLE_USES.setdefault(name, what)
    return name


def ball_bearing(case: Case) -> BallBearing:
    """The ball bearing of ``case`` (a check built for ball bearings refuses a roller one).

    Parameters
    ----------
    case : Case
        A validated case.

    Returns
    -------
    BallBearing
        ``case.bearing``.

    Raises
    ------
    TypeError
        A roller bearing.
    """
    from runout.geometry.bearing import BallBearing

    if not isinstance(case.bearing, BallBearing):
        raise TypeError(f"{case.path}: the check needs a ball bearing")
    return case.bearing


def fixed_contact_angle(bearing: BallBearing) -> float:
    """The bearing's fixed ``contact_angle`` [rad]; a check that needs one refuses a free angle.

    Parameters
    ----------
    bearing : BallBearing
        The bearing.

    Returns
    -------
    float
        Its contact angle [rad].

    Raises
    ------
    ValueError
        A free contact angle (None).
    """
    if bearing.contact_angle is None:
        raise ValueError("the check needs a fixed contact_angle")
    return bearing.contact_angle
