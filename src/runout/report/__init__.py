"""What a person reads: readable summaries, figures (the only matplotlib user) and the
self-contained HTML report of a run, a study or a diagnosis.

The report pages (``runout.report.build_report``) are those of :mod:`runout.report.page`,
re-exported here.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from runout.report.page import build_combined_report, build_report

__all__ = [
    "build_combined_report",
    "build_report",
]


def __getattr__(name: str) -> Any:
    # imported when first asked for: a process that only draws figures (``run --out``'s) does
    # not import the report pages and the case schema they read (0.1 s at its start)
    if name in __all__:
        from runout.report import page

        return getattr(page, name)
    raise AttributeError(f"module 'runout.report' has no attribute {name!r}")
