"""Angle helpers of the collocation kernels (jkrcyl.numerics.arcs_kernels): the smooth log factor of the
kernel, log((2 sin(t/2)/t)^2), without a log for small t, and the cos/sin tables of node angles for angle
addition (cos(d - a) = cos d cos a + sin d sin a: one log per matrix entry instead of cos, sin, sin, log)."""
import math

import numpy as np
from numba import njit

# log(sin y / y) = sum_k LOGSINC[k] y^(2 k + 2) (Bernoulli numbers; sympy: series(log(sin(y)/y), y, 0, 26)).
# Used for |y| < SERIES_Y, where the 12 terms leave < 1e-20 (the 13th is 9.1e-15 (1/4)^13).
LOGSINC = np.array([-1 / 6, -1 / 180, -1 / 2835, -1 / 37800, -1 / 467775, -691 / 3831077250, -2 / 127702575,
                    -3617 / 2605132530000, -43867 / 350813659321125, -174611 / 15313294652906250,
                    -155366 / 147926426347074375, -236364091 / 2423034863565078262500])
SERIES_Y = 0.5


@njit(cache=True, inline="always")
def ell_half(y, sin_y):
    """ell(t) = log((2 sin(t/2)/t)^2) = 2 log|sin(y)/y| at y = t/2 (arcs._ell): the series for |y| < SERIES_Y
    (no log), else from sin_y (a sine by angle addition: absolute error ~3e-16, relative <= 7e-16 for
    |sin y| >= sin SERIES_Y)."""
    if abs(y) < SERIES_Y:
        z = y * y
        acc = LOGSINC[11]
        for q in range(10, -1, -1):
            acc = acc * z + LOGSINC[q]
        return 2 * z * acc
    return 2 * math.log(abs(sin_y / y))


@njit(cache=True)
def arc_trig(e, s, out):
    """out[0..3, k] = cos, sin of e s_k and of e s_k / 2: the column angles, for angle addition."""
    for k in range(s.size):
        a = e * s[k]
        out[0, k] = math.cos(a)
        out[1, k] = math.sin(a)
        out[2, k] = math.cos(0.5 * a)
        out[3, k] = math.sin(0.5 * a)
