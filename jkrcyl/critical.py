"""The critical contact parameter of section 4: the root of 2 vartheta - log(1 + a^2) - 2 a^4 = 0."""
import math

from numba import njit

from ._validate import theta as _check_theta


def a_crit(theta):
    """a_crit(vartheta), the infinite-load contact parameter (denominator of (4.4) = 0); inf for vartheta = inf."""
    return a_crit_kernel(_check_theta(theta))


@njit(cache=True)
def a_crit_kernel(theta):
    """Unchecked a_crit for numba callers (the atlas): Newton on u = a^2 for
    f(u) = 2 vartheta - log1p(u) - 2u^2, decreasing and concave, so Newton from the right of the
    root converges monotonically."""
    if math.isinf(theta):
        return math.inf
    u = max(math.sqrt(theta), 2.0 * theta)          # f(u) < 0 here: start right of the root
    for _ in range(200):
        f = 2.0 * theta - math.log1p(u) - 2.0 * u * u
        step = f / (1.0 / (1.0 + u) + 4.0 * u)
        u += step
        if abs(step) <= 1e-16 * u:
            break
    return math.sqrt(u)
