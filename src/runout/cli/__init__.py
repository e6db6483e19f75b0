"""The ``runout`` command-line tool: one module per command family (:mod:`runout.cli.commands` the
commands, :mod:`runout.cli.diagnose` the diagnosis, :mod:`runout.cli.catalogue` the bearing
catalogue, :mod:`runout.cli.warm` the kernel warm-up), shared helpers in
:mod:`runout.cli.common`.

``runout`` (the console script) is :func:`main`; ``python -m runout.cli`` runs it too.
"""

from runout.cli.commands import app, main

__all__ = ["app", "main"]
