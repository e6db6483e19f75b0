"""What a person reads: readable summaries, figures (the only matplotlib user) and the
self-contained HTML report of a run, a study or a diagnosis.

The report pages (``runout.report.build_report``) are those of :mod:`runout.report.page`,
re-exported here.
"""

from runout.report.page import (
    build_combined_report,
    build_report,
)

__all__ = [
    "build_combined_report",
    "build_report",
]
