"""Numerical verification helpers for the derive step (mpmath at 50 digits, 30 must agree).

These compare a closed form with a quadrature or a sum that uses no closed form.
"""
import mpmath as mp
import sympy as sp

DPS = 50          # working precision of every check
DIGITS = 30       # digits that must agree


def max_rel_err(pairs):
    """Largest |x - y| / max(|x|, |y|, tiny) over (x, y) pairs of mpmath numbers."""
    worst = mp.mpf(0)
    for x, y in pairs:
        scale = max(abs(x), abs(y), mp.mpf(10) ** (-DPS))
        worst = max(worst, abs(x - y) / scale)
    return worst


def assert_close(what, pairs, tol=mp.mpf(10) ** (-DIGITS)):
    """Raise if the check fails: make derive must stop rather than emit an unproved result."""
    err = max_rel_err(pairs)
    if err > tol:
        raise AssertionError(f"derive check failed: {what}: max relative error {mp.nstr(err, 3)}")
    return err


def mp_function(expr, args):
    """An mpmath-callable for a sympy expression (evaluated at the current mp.dps)."""
    return sp.lambdify(args, expr, modules="mpmath")


def pv_quad(f, x, lo, hi, breaks=(-1, 0, 1)):
    """Cauchy principal value of int_lo^hi f(s)/(x - s) ds for lo < x < hi.

    Subtracting f(x) leaves a regular integrand; PV int_lo^hi ds/(x - s) = log((x - lo)/(hi - x)).
    ``breaks`` split the interval where f varies on the unit scale (atan, 1/(1+s^2)).
    """
    fx = f(x)
    nodes = sorted({lo, x, hi} | {mp.mpf(b) for b in breaks if lo < b < hi})
    regular = mp.quad(lambda s: (f(s) - fx) / (x - s), nodes)
    return regular + fx * mp.log((x - lo) / (hi - x))


def sample_a():
    """Contact parameters for checks: tiny, sub-critical, near 1 and large."""
    return [mp.mpf(v) for v in ("1e-4", "0.01", "0.1", "0.3", "0.7", "1", "1.5", "3", "10", "100")]
