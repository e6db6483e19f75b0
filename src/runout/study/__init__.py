"""Studies at scale: the plan of drawn or listed quantities, chunks, the worker pool and
batched kernels, the output directory, the study result, ball arrangement, the dynamic sweep.

The public names of studies (``runout.study.run_study``, ...) are those of
:mod:`runout.study.run`, re-exported here.
"""

from runout.study.run import (
    RUNOUT_KEYS,
    ChunkTask,
    OutputError,
    Quantity,
    StudyError,
    StudyResult,
    dask_executor,
    die_with_parent,
    error_text,
    evaluate_chunk,
    line_label,
    load_study,
    output_directory,
    output_lock,
    plan_quantities,
    refuse_foreign,
    run_study,
    sample_rng,
    statistics,
    write_atomic,
)

__all__ = [
    "RUNOUT_KEYS",
    "ChunkTask",
    "OutputError",
    "Quantity",
    "StudyError",
    "StudyResult",
    "dask_executor",
    "die_with_parent",
    "error_text",
    "evaluate_chunk",
    "line_label",
    "load_study",
    "output_directory",
    "output_lock",
    "plan_quantities",
    "refuse_foreign",
    "run_study",
    "sample_rng",
    "statistics",
    "write_atomic",
]
