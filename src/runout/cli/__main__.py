"""``python -m runout.cli``: the ``runout`` command, with the usual interpreter exit (so that a
profiler or debugger wrapping the module gets control back; the console script ``runout``
takes the fast one, :func:`runout.cli.commands.main`)."""

from runout.cli.commands import app

app()
