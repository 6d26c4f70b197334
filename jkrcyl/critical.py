"""The critical contact parameter of section 4: the root of 2 vartheta - log(1 + a^2) - 2 a^4 = 0."""
import math

from ._validate import theta as _check_theta


def a_crit(theta):
    """a_crit(vartheta), the infinite-load contact parameter (denominator of (4.4) = 0).

    Newton on u = a^2 for f(u) = 2 vartheta - log1p(u) - 2u^2 (decreasing and concave, so Newton
    from the right of the root converges monotonically); inf for vartheta = inf.
    """
    th = _check_theta(theta)
    if math.isinf(th):
        return math.inf
    u = max(math.sqrt(th), 2 * th)          # f(u) < 0 here: start right of the root
    for _ in range(200):
        f = 2 * th - math.log1p(u) - 2 * u * u
        step = f / (1 / (1 + u) + 4 * u)
        u += step
        if abs(step) <= 1e-16 * u:
            break
    return math.sqrt(u)
