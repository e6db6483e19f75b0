"""Base layer: errors, units, readable display of lengths, the glossary, safe reading of files
(``reading``), and small utilities
(numba's cache directory, threads, roots, small linear algebra, compiled CSV formatting).
Imports nothing else of runout.
"""
