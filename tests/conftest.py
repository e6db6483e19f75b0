"""Test-suite configuration.

Hypothesis explores new random examples on every developer run; under CI it is derandomized so
a landing never depends on the luck of one draw (a failure found locally is pinned by a test).
"""

from __future__ import annotations

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")
