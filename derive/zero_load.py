"""Section 8.1: the zero-load contact (8.1) and the largest M that has one; section 4: a_crit.

(8.1) is not typed: it is the numerator of the normalised load P* (derive.load.normalised_load)
divided by 2 (1 + a^2) sqrt(a), written in m = M vartheta and inv_theta = 1/vartheta so that the rigid
cradle (vartheta = inf, (7.6)) is inv_theta = 0.  M_max(vartheta) is the maximum over a of the M that
makes a a root, M_0(a) = a^(3/2)/(a^2 + 2 vartheta - log(1 + a^2)); its stationarity condition is the
sympy derivative of log M_0.  a_crit is the root of the denominator of (4.4) in u = a^2 (Newton).
"""
import sympy as sp
from sympy.codegen.cfunctions import log1p

from . import load
from .kernel import Kernel
from .report import MATCHES, NEW
from .symbols import M, a, inv_theta, theta

m = sp.Symbol("m", nonnegative=True)          # M vartheta (M_R* when vartheta = inf)
u = sp.Symbol("u", positive=True)             # a^2


def residual():
    """-(numerator of P*)/(2 (1 + a^2) sqrt(a)) in (a, m, inv_theta): a^(3/2) - m (2 + inv_theta (a^2 - L))."""
    P_star = load.normalised_load()
    num = sp.numer(sp.together(P_star))
    g = sp.expand(-num / (2 * (1 + a**2) * sp.sqrt(a)))
    g = g.subs(M, m / theta).subs(theta, 1 / inv_theta)
    return sp.collect(sp.expand(g), m)


def _stable_residual():
    L_ = log1p(a**2)
    return a**sp.Rational(3, 2) - m * (2 + inv_theta * (a**2 - L_))


def printed_81():
    """(8.1) as printed, times M: a0^(3/2) - M (a0^2 + 2 vartheta - log(1 + a0^2))."""
    return a**sp.Rational(3, 2) - M * (a**2 + 2 * theta - sp.log(1 + a**2))


def max_M_forms():
    """M_0(a) (the M with zero load at a) and a/M_0 dM_0/da times the denominator of M_0 (zero at M_max)."""
    den = a**2 + 2 * theta - log1p(a**2)
    M0 = a**sp.Rational(3, 2) / den
    stationary = sp.simplify(sp.diff(sp.log(M0), a) * a * den)
    return M0, sp.factor_terms(sp.expand(stationary))


def critical_forms():
    """Denominator of (4.4), 2 vartheta - L - 2 a^4, in u = a^2, and its u-derivative (Newton for a_crit)."""
    f = load.D.subs(a, sp.sqrt(u)).replace(sp.log, lambda z: log1p(sp.expand(z - 1)))
    return f, sp.diff(f, u)


def derive(report):
    report.section("Zero-load contact and a_crit (sections 4, 8.1)")
    g = residual()
    report.result("Zero-load contact (8.1)", sp.Eq(_stable_residual(), 0), MATCHES,
                  "numerator of the normalised load P* (derive.load) over 2 (1 + a^2) sqrt(a)")
    diff = sp.simplify((g - _stable_residual()).replace(log1p, lambda z: sp.log(1 + z)))
    if diff != 0:
        raise AssertionError(f"zero-load residual: {diff}")
    printed = printed_81().subs(M, m / theta) - _stable_residual().subs(inv_theta, 1 / theta)
    if sp.simplify(printed.replace(log1p, lambda z: sp.log(1 + z))) != 0:
        raise AssertionError("zero-load residual differs from the printed (8.1)")
    report.proof("equals -(numerator of P*)/(2 (1 + a^2) sqrt(a)) and M times the printed (8.1)")
    rigid = sp.solve(sp.Eq(_stable_residual().subs(inv_theta, 0), 0), a)
    if len(rigid) != 1:
        raise AssertionError(f"rigid-cradle zero-load roots: {rigid}")
    report.result("Zero-load contact of the rigid cradle (7.6)", sp.Eq(a, rigid[0]), MATCHES,
                  "sympy solve of the residual at inv_theta = 0 (P_R* = 0 in (7.6))")
    M0, stationary = max_M_forms()
    report.result("Largest M with a zero-load contact", sp.Eq(sp.Symbol("a M_0'/M_0 D"), stationary), NEW,
                  "M_0(a) = a^(3/2)/(a^2 + 2 vartheta - L) solves the residual for M; its maximum over a "
                  "is where this sympy derivative of log M_0 (times a and the denominator) vanishes")
    f, df = critical_forms()
    return [
        Kernel("zero_load_residual", (("g", _stable_residual()),),
               "(8.1) times M vartheta-free: g = a^(3/2) - m (2 + inv_theta (a^2 - log(1 + a^2))),\n"
               "m = M vartheta (M_R* for vartheta = inf); zero at a zero-load contact a0.", array_args=()),
        Kernel("zero_load_rigid", (("a0", rigid[0]),),
               "The one zero-load contact parameter of the rigid cradle (inv_theta = 0), m = M_R*.",
               array_args=()),
        Kernel("zero_load_max", (("M0", M0), ("stationary", stationary)),
               "M0 = a^(3/2)/(a^2 + 2 vartheta - log(1 + a^2)), the M with zero load at a, and the\n"
               "stationarity condition of M0 (zero at M_max, positive below it).", array_args=()),
        Kernel("critical_equation", (("f", f), ("df_du", df)),
               "Denominator of (4.4) in u = a^2, f = 2 vartheta - log(1 + u) - 2 u^2, and df/du (Newton\n"
               "for a_crit = sqrt(u) at f = 0).", array_args=()),
    ]
