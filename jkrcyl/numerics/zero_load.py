"""The zero-load contact (8.1) and the largest M that has one: the one implementation (library and atlas).

(8.1) times M vartheta is the residual g(a) = a^(3/2) - m (2 + (a^2 - log(1 + a^2))/vartheta), m = M vartheta
(derive/zero_load.py): negative at a = 0 and for large a, positive between its two roots exactly when
M < M_max(vartheta) = max_a a^(3/2)/(a^2 + 2 vartheta - log(1 + a^2)).  So the two roots are bracketed by
[0, a_max] and [a_max, a_hi], a_max the a of M_max.  For vartheta = inf (M = M_R*, (7.6)) there is one
root, a0 = (2 M_R*)^(2/3).
"""
import math

from numba import njit

from .._validate import finite_scalar, theta as _check_theta
from . import kernels, roots

_residual_root = roots.brent_solver(kernels.zero_load_residual_nb)
_stationary_root = roots.brent_solver(kernels.zero_load_stationary_nb)


@njit(cache=True)
def zero_load_max_nb(theta):
    """(M_max, a at the maximum) of (8.1) for vartheta >= 1/2; (inf, inf) for vartheta = inf."""
    if math.isinf(theta):
        return math.inf, math.inf
    args = (theta,)
    lo, hi = 1e-6, 1.0
    while kernels.zero_load_stationary_nb(hi, args) > 0.0:
        hi *= 2.0
    a_max = _stationary_root(lo, hi, kernels.zero_load_stationary_nb(lo, args),
                             kernels.zero_load_stationary_nb(hi, args), args)
    return kernels.zero_load_M0_nb(a_max, theta), a_max


@njit(cache=True)
def zero_load_roots_nb(M, theta, M_max, a_max):
    """(n, a_small, a_large): the n in {0, 1, 2} zero-load contact parameters of (8.1) (0.0 where absent);
    M_max, a_max from :func:`zero_load_max_nb`.  M = M_max exactly counts as no root."""
    if not M > 0.0:
        return 0, 0.0, 0.0
    if math.isinf(theta):
        a0 = kernels.zero_load_rigid_nb(M)
        return 1, a0, a0
    if not M < M_max:
        return 0, 0.0, 0.0
    args = (1.0 / theta, M * theta)
    hi = max(10.0, 4.0 / (M * M))                      # g(a) ~ a^1.5 - M a^2 < 0 beyond 1/M^2
    g_lo = kernels.zero_load_residual_nb(0.0, args)
    g_m = kernels.zero_load_residual_nb(a_max, args)
    g_hi = kernels.zero_load_residual_nb(hi, args)
    if not (g_lo < 0.0 < g_m and g_hi < 0.0):
        return 0, 0.0, 0.0
    return 2, _residual_root(0.0, a_max, g_lo, g_m, args), _residual_root(a_max, hi, g_m, g_hi, args)


def zero_load_max_M(theta: float) -> tuple:
    """The largest M with a zero-load contact (8.1): max over a of a^(3/2)/(a^2 + 2 vartheta - log(1 + a^2)).

    (8.1) has two roots for M < M_max and none for M > M_max.

    Parameters
    ----------
    theta : float
        vartheta (section 4) in [1/2, 1e12], or inf (a rigid cradle).

    Returns
    -------
    tuple of float
        (M_max, a at the maximum); (inf, inf) for vartheta = inf.

    Raises
    ------
    ValueError
        Naming theta outside its domain.

    Examples
    --------
    >>> import jkrcyl
    >>> M_max, a = jkrcyl.zero_load_max_M(1.0)
    >>> round(M_max, 6), round(a, 6)
    (0.644632, 2.063832)
    >>> len(jkrcyl.zero_load_contact(0.99 * M_max, 1.0)), len(jkrcyl.zero_load_contact(1.01 * M_max, 1.0))
    (2, 0)
    """
    M_max, a_max = zero_load_max_nb(_check_theta(theta))
    return float(M_max), float(a_max)


def zero_load_contact(M: float, theta: float) -> list:
    """Sorted contact parameters a0 > 0 of the non-trivial zero-load equilibria (8.1); [] if none.

    Exact tangency (M equal to :func:`zero_load_max_M`) counts as no root.

    Parameters
    ----------
    M : float
        The normalised adhesion (section 6), >= 0 (M_R* of (7.6) for vartheta = inf).
    theta : float
        vartheta in [1/2, 1e12], or inf.

    Returns
    -------
    list of float
        The roots a0 = tan(eps0/2), smallest first (two, one for vartheta = inf: (7.6) gives a0 = (2 M_R*)^(2/3),
        or none).

    Raises
    ------
    ValueError
        Naming M or theta outside its domain.

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
    >>> a0 = jkrcyl.zero_load_contact(pin.M, pin.theta)
    >>> round(a0[0], 6), round(float(pin.solve(P=0.0)[0].a), 6)     # the state the forward solve finds at P = 0
    (0.800455, 0.800455)
    >>> abs(jkrcyl.zero_load_contact(0.3, float("inf"))[0] / (2 * 0.3) ** (2 / 3) - 1) < 1e-14      # (7.6)
    True
    """
    M = finite_scalar("M", M, low=0.0)
    th = _check_theta(theta)
    n, a_small, a_large = zero_load_roots_nb(M, th, *zero_load_max_nb(th))
    return [float(a_small), float(a_large)][:n] if n != 1 else [float(a_small)]
