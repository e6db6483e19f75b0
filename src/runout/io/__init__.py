"""Files of a run: writing result.json and the CSV files of ``runout run --out DIR`` and reading
them back into a typed result; the column names of a study's ``samples.csv``
(:mod:`runout.io.study_columns`). Imports the layers below (no plotting).
"""
