"""Running a case: dispatch to the model (run_model), the model-level input checks, and the
[analysis] outputs added to a result (bands, verdict). Imports the layers below.
"""

from runout.runner.run import run_model

__all__ = ["run_model"]
