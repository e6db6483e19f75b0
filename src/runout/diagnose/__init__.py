"""Diagnosis: from a measured runout or vibration record to the part deviations behind it
(the record reader, the linear model as observation equations, the fit).

The public names (``runout.diagnose.diagnose``, ...) are those of :mod:`runout.diagnose.fit`,
re-exported here.
"""

from runout.diagnose.fit import (
    DETECTION,
    GAIN_UNCERTAINTY,
    MAX_LINES,
    Diagnosis,
    Estimate,
    Record,
    RecordError,
    Unattributed,
    diagnose,
    read_record,
)

__all__ = [
    "DETECTION",
    "GAIN_UNCERTAINTY",
    "MAX_LINES",
    "Diagnosis",
    "Estimate",
    "Record",
    "RecordError",
    "Unattributed",
    "diagnose",
    "read_record",
]
