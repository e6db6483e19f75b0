"""Analysis of a runout record: spectra and band values, the line types and the one
decomposition every model uses, and the result objects (RunResult and its typed details).
Imports base and geometry.
"""
