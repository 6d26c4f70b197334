"""Pieces of the collocation kernels (jkrcyl.numerics.arc_angles) against mpmath (40 digits)."""
import math

import mpmath as mp
import numpy as np

from jkrcyl.numerics import arc_angles as ak


def test_ell_half_series_and_log_branch():
    """_ell(t) = 2 log|sin(y)/y|, y = t/2: the Bernoulli series below SERIES_Y, the log above it."""
    ys = np.concatenate([np.geomspace(1e-9, 3.1, 300), -np.geomspace(1e-6, 3.1, 50),
                         [ak.SERIES_Y * (1 - 1e-15), ak.SERIES_Y]])
    with mp.workdps(40):
        for y in ys:
            ref = 2 * mp.log(abs(mp.sin(mp.mpf(y)) / mp.mpf(y)))
            got = ak.ell_half(y, math.sin(y))
            # series side: within 1e-17 of the truth; log side: the rounding of sin(y)/y and of the log
            tol = 1e-17 + 4e-16 * abs(float(ref)) if abs(y) < ak.SERIES_Y else 1e-15 * max(1.0, abs(float(ref)))
            assert abs(got - float(ref)) <= tol, (y, got, ref)


def test_log_sinc_coefficients_are_the_series():
    """LOGSINC against mpmath's Taylor coefficients of log(sin(y)/y) in y^2."""
    with mp.workdps(40):
        c = mp.taylor(lambda y: mp.log(mp.sin(y) / y) if y != 0 else mp.mpf(0), 0, 2 * len(ak.LOGSINC))
        for k, v in enumerate(ak.LOGSINC):
            assert abs(v - float(c[2 * k + 2])) <= 1e-16 * abs(v)
