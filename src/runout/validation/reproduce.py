"""Reproduce the published numbers of the seed papers and write VALIDATION.md.

The registry, the published numbers and the functions that compute ours live in
:mod:`runout.validation` (one module per source); this module keeps the names that
``runout reproduce`` (:func:`runout.cli.commands.reproduce_command`) and older imports use.
``runout reproduce`` runs every check and writes VALIDATION.md; ``runout reproduce --check``
compares a fresh document with the file on disk (numbers within :data:`CHECK_RTOL` or one unit
of their last printed digit).
"""

from __future__ import annotations

from runout import validation as _validation
from runout.validation import *  # noqa: F403  (the registry, the checks, build, compare)
from runout.validation.fft_reading import FftReading, identify_fft_reading

__all__ = [*_validation.__all__, "FftReading", "identify_fft_reading"]
