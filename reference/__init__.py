"""Test reference of jkrcyl: the paper's printed formulas typed by hand (paper.py) and the high-precision
models (mpmath quadrature of the defining integrals) that derive/ and tests/ compare with.

Never imported by jkrcyl at run time (tests/test_layer.py checks it).
"""
