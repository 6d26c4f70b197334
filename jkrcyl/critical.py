"""The critical contact parameter of section 4: the root of 2 vartheta - log(1 + a^2) - 2 a^4 = 0."""
from ._validate import theta as _check_theta
from .numerics.kernels import a_crit_nb

a_crit_kernel = a_crit_nb     # unchecked numba form for njit callers (the atlas)


def a_crit(theta):
    """a_crit(vartheta), the infinite-load contact parameter (denominator of (4.4) = 0); inf for vartheta = inf."""
    return a_crit_nb(_check_theta(theta))
