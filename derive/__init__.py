"""Symbolic re-derivation of the paper's closed forms and emission of numba kernels.

Run as ``python -m derive --out generated`` (``make derive``).  Each physics module
(``pressure``, ``load``, ...) builds sympy expressions and records what it proved in a
:class:`derive.report.Report`; :mod:`derive.emit` alone turns expressions into code.
"""
