"""Files of a run: writing result.json and the CSV files of ``runout run --out DIR`` and reading
them back into a typed result. Imports the layers below (no plotting).
"""
