"""Section 5 and Appendix (A.13)-(A.15): the approach delta in closed form.

Reads like the paper's section 5.  The logarithmic kernel of (5.3) is expanded in the cosine
series (5.5); this turns (5.3) into (5.6)-(5.7), which need three series of integrals, the sums
(A.13)-(A.15).  They are summed here by a route the paper does not take:

  Mehler-Dirichlet   int_0^eps cos(n psi) cos(psi/2)/s dpsi = (pi/2) (P_n + P_{n-1})(cos eps),
  weight             2 n/(n^2 - 1) = int_0^1 (1 + t^2) t^(n-2) dt,
  generating fn      sum_{n>=2} (P_n + P_{n-1}) t^n = (1 + t)/sqrt(1 - 2 X t + t^2) - 1 - (1 + X) t,

so (A.15) is one elementary integral in t; (A.13) and (A.14) follow from (A.15) by differentiating
their integrands with respect to X = cos(eps) (Leibniz; both vanish at eps = 0).  The approach is
then assembled from (5.3), (5.6), (5.7) with the load solution of derive.load, compared with the
printed (5.8), and written in a form that keeps its digits in float64 for 1e-8 <= a <= 1e4.

Notation: X = cos(eps), u = sin(eps/2), L_s = log sin(eps/2) = log(a/E), c = cos(eps/2) = 1/E,
s = sqrt(cos^2(psi/2) - cos^2(eps/2)), w_n = n/(n^2 - 1), t = 1/vartheta (inv_theta),
g = 1/G_I (inv_G_I).  S13, S14, S15 denote the sums on the left of (A.13), (A.14), (A.15).
"""
import mpmath as mp
import sympy as sp
from sympy.codegen.cfunctions import log1p

from . import checks, load
from .kernel import Kernel
from .report import MATCHES, NEW
from .symbols import (B, C, E, P, R, Delta, a, beta, c0, c1, inv_G_I, inv_theta, psi, zeta)

n = sp.Symbol("n", integer=True, positive=True)      # Fourier / Legendre index
m = sp.Symbol("m", integer=True, nonnegative=True)   # m = n - 2 >= 0
t = sp.Symbol("t", positive=True)                    # generating-function variable, 0 < t <= 1
X = sp.Symbol("X", real=True)                        # X = cos(eps)
u = sp.Symbol("u", positive=True)                    # u = sin(eps/2), X = 1 - 2 u^2
Ls = sp.Symbol("L_s", real=True)                     # L_s = log sin(eps/2)
cp = sp.Symbol("c_psi", positive=True)               # cos(psi/2)
g, th = inv_G_I, inv_theta
L_of_X = sp.log((1 - X) / 2) / 2                     # L_s as a function of X

# the paper's closed forms, in X and L_s
S13_printed = sp.pi / 16 * (Ls * (-3 + 2 * X + X**2) - sp.Rational(1, 2) + X**2 / 2)        # (A.13)
S14_printed = sp.pi / 8 * (Ls * (-2 + 2 * X) - sp.Rational(1, 2) + X / 2)                   # (A.14)
S15_printed = -sp.pi / 4 * (1 + X) / 2 * (3 + 4 * Ls)                                       # (A.15)


def _require(what, expr):
    if sp.simplify(expr) != 0:
        raise AssertionError(f"derive proof failed: {what}")


def _theta_quad(f, eps_):
    """int_0^eps f(psi, s) dpsi with sin(psi/2) = sin(eps/2) sin(theta): s = sin(eps/2) cos(theta).

    dpsi = 2 sin(eps/2) cos(theta) dtheta / cos(psi/2): the 1/s end of the integrand becomes smooth
    and s is computed without cancellation near psi = eps.
    """
    uu = mp.sin(eps_ / 2)

    def h(theta):
        psi_ = 2 * mp.asin(uu * mp.sin(theta))
        s_ = uu * mp.cos(theta)
        return f(psi_, s_) * 2 * uu * mp.cos(theta) / mp.cos(psi_ / 2)
    return mp.quad(h, [0, mp.pi / 4, mp.pi / 2])


def _sample_eps():
    return [mp.mpf(v) for v in ("1e-3", "0.05", "0.3", "0.8", "1.2", "1.5707963", "2", "2.6", "3", "3.13")]


# --- (5.5): the cosine series of the logarithmic kernel -------------------------------------------
def kernel_55():
    """Right-hand side of (5.5): 1/2 + cos(psi)/4 + cos(psi) log(2 sin(psi/2)) = -sum_{n>=2} w_n cos(n psi)."""
    return sp.Rational(1, 2) + sp.cos(psi) / 4 + sp.cos(psi) * sp.log(2 * sp.sin(psi / 2))


def fourier_55(report):
    report.result("Fourier series of the kernel (5.5)",
                  sp.Eq(-sp.Sum(n / (n**2 - 1) * sp.cos(n * psi), (n, 2, sp.oo)), kernel_55()), MATCHES,
                  "from -log(2 sin(psi/2)) = sum_{n>=1} cos(n psi)/n times cos(psi)")
    z = sp.Symbol("z")
    log_series = sp.summation(z**n / n, (n, 1, sp.oo))          # Piecewise: -log(1 - z) for |z| <= 1, z != 1
    if log_series.args[0][0] != -sp.log(1 - z):
        raise AssertionError("sympy no longer sums z^n/n to -log(1 - z)")
    modulus = sp.expand_complex((1 - sp.exp(sp.I * psi)) * (1 - sp.exp(-sp.I * psi)))
    _require("|1 - exp(i psi)|^2 = 4 sin^2(psi/2)", modulus - 4 * sp.sin(psi / 2)**2)
    report.proof("sum z^n/n = -log(1 - z) on |z| = 1, z != 1 (sympy summation); with z = exp(i psi), "
                 "|1 - z| = 2 sin(psi/2), so sum cos(n psi)/n = -log(2 sin(psi/2)) on 0 < psi < 2 pi")
    # cos(psi) cos(n psi) = [cos((n+1) psi) + cos((n-1) psi)]/2: the coefficient of cos(k psi) in
    # cos(psi) sum_{n>=1} cos(n psi)/n is [1/(k-1) + 1/(k+1)]/2 for k >= 2, 1/4 for k = 1, 1/2 for k = 0.
    k_ = sp.Symbol("k", integer=True)
    _require("(1/(k-1) + 1/(k+1))/2 = w_k", (1 / (k_ - 1) + 1 / (k_ + 1)) / 2 - k_ / (k_**2 - 1))
    report.proof("coefficient matching: [1/(k-1) + 1/(k+1)]/2 = k/(k^2 - 1) for k >= 2; "
                 "the k = 0 and k = 1 coefficients 1/2 and 1/4 are moved to the right of (5.5)")
    f = checks.mp_function(kernel_55(), (psi,))
    with mp.workdps(checks.DPS):
        pairs = []
        for k in range(0, 11):
            coeff = 2 / mp.pi * mp.quad(lambda p: f(p) * mp.cos(k * p), [0, mp.pi / 2, mp.pi])
            pairs.append((coeff + 1, -mp.mpf(k) / (k**2 - 1) + 1 if k >= 2 else mp.mpf(1)))
    report.check("Fourier cosine coefficients of the right of (5.5) by quadrature, k = 0..10 "
                 "(shifted by 1 so that the zero coefficients compare in relative terms)",
                 checks.assert_close("(5.5)", pairs), len(pairs))


def integral_56(report):
    """(5.6): with (5.5), J = int_0^eps N cos(psi) 4 log(2 sin(psi/2)) dpsi splits into B, P and the series."""
    lhs = 4 * sp.cos(psi) * sp.log(2 * sp.sin(psi / 2))
    _require("(5.6) integrand", lhs - (-2 - sp.cos(psi) + 4 * kernel_55()))
    report.result("The integral J of (5.3) by the series (5.6)",
                  r"J = -\mathbb{B} - \frac{P}{2R} - 4\sum_{n\ge2}\frac{n}{n^2-1}\int_0^\epsilon N\cos n\psi\,d\psi",
                  MATCHES, "int_0^eps N = B/2 and int_0^eps N cos = P/(2R) for the even pressure (2.13)")
    report.proof("4 cos(psi) log(2 sin(psi/2)) = -2 - cos(psi) + 4 (5.5); summing under the integral "
                 "is checked with the approach itself (quadrature of (5.3), below)")


# --- (A.15): Mehler-Dirichlet, then the Legendre generating function --------------------------------
def legendre_terms(report):
    """Each integral of (A.15) is (pi/2)(P_n + P_{n-1})(cos eps)."""
    half = sp.Rational(1, 2)
    product = sp.cos(n * psi) * sp.cos(psi / 2) - (sp.cos((n + half) * psi) + sp.cos((n - half) * psi)) / 2
    _require("product to sum", sp.expand(product.rewrite(sp.exp)))
    eps_ = sp.Symbol("epsilon", positive=True)
    _require("s^2 = (cos psi - cos eps)/2",
             sp.expand_trig(sp.cos(psi / 2)**2 - sp.cos(eps_ / 2)**2 - (sp.cos(psi) - sp.cos(eps_)) / 2))
    report.result("Each integral of (A.15) as Legendre polynomials",
                  r"\int_0^\epsilon\frac{\cos n\psi\cos(\psi/2)}{\mathbf{s}}d\psi = \frac{\pi}{2}"
                  r"\left[P_n(\cos\epsilon) + P_{n-1}(\cos\epsilon)\right]", NEW,
                  "Mehler-Dirichlet: P_n(cos eps) = (2/pi) int_0^eps cos((n+1/2) psi)/sqrt(2(cos psi - cos eps)) dpsi")
    report.proof("cos(n psi) cos(psi/2) = [cos((n+1/2) psi) + cos((n-1/2) psi)]/2 and "
                 "s^2 = (cos psi - cos eps)/2, so 1/s = 2/sqrt(2(cos psi - cos eps))")
    with mp.workdps(checks.DPS):
        pairs = []
        for e in _sample_eps()[::2]:
            for k in range(0, 9):
                q = _theta_quad(lambda p, s_: mp.cos((k + mp.mpf(1) / 2) * p) / (2 * s_), e)
                pairs.append((q, mp.pi / 2 * mp.legendre(k, mp.cos(e))))
    report.check("Mehler-Dirichlet integral by quadrature vs pi/2 P_n(cos eps), n = 0..8",
                 checks.assert_close("Mehler-Dirichlet", pairs), len(pairs))


def generating_integrand():
    """(pi/4) (1 + t^2)/t^2 [sum_{n>=2} (P_n + P_{n-1}) t^n]: integrated over 0 < t < 1 it gives S15."""
    G = 1 / sp.sqrt(1 - 2 * X * t + t**2)
    return sp.pi / 4 * (1 + t**2) / t**2 * ((1 + t) * G - 1 - (1 + X) * t)


def antiderivative():
    """An antiderivative in t of (1 + t^2)/t^2 [(1 + t) G - 1 - (1 + X) t], G = (1 - 2Xt + t^2)^(-1/2).

    (1 + t^2)(1 + t)/t^2 = 1/t^2 + 1/t + 1 + t; the four integrals of these over sqrt(Q) are standard.
    """
    sQ = sp.sqrt(1 - 2 * X * t + t**2)
    i0 = sp.log(t - X + sQ)                    # int dt/sqrt(Q)
    i1 = sQ + X * i0                           # int t dt/sqrt(Q)
    im1 = -sp.log((1 - X * t + sQ) / t)        # int dt/(t sqrt(Q))
    im2 = -sQ / t + X * im1                    # int dt/(t^2 sqrt(Q))
    polynomial = 1 / t - (1 + X) * sp.log(t) - t - (1 + X) * t**2 / 2
    return im2 + im1 + i0 + i1 + polynomial


def sum_a15(report, errors):
    weight = sp.integrate((1 + t**2) * t**m, (t, 0, 1))          # m = n - 2
    _require("2 w_n = int_0^1 (1 + t^2) t^(n-2) dt", weight - 2 * (m + 2) / ((m + 2)**2 - 1))
    gen = sp.series(((1 + t) / sp.sqrt(1 - 2 * X * t + t**2) - 1 - (1 + X) * t), t, 0, 14).removeO()
    for k in range(0, 14):
        target = sp.legendre(k, X) + sp.legendre(k - 1, X) if k >= 2 else 0
        _require(f"generating function, t^{k}", sp.expand(gen.coeff(t, k) - target))
    F = antiderivative()
    _require("antiderivative", sp.diff(F, t) * sp.pi / 4 - generating_integrand())
    F_u = F.subs(X, 1 - 2 * u**2)
    at_0 = sp.limit(F_u, t, 0, "+")
    at_1 = F_u.subs(t, 1)
    value = sp.pi / 4 * (at_1 - at_0)
    closed = S15_printed.subs(Ls, sp.log(u)).subs(X, 1 - 2 * u**2)
    _require("(A.15) from the antiderivative", sp.expand_log(value - closed, force=True))
    report.result("The sum (A.15)", sp.Eq(sp.Symbol("S_{15}"), S15_printed), MATCHES,
                  "S15 = (pi/2) sum w_n (P_n + P_{n-1}) = int_0^1 of the generating integrand (Abel's "
                  "theorem at t = 1: the Legendre series converges for -1 < cos eps < 1)")
    report.proof("2 w_n = int_0^1 (1 + t^2) t^(n-2) dt (sympy integrate)")
    report.proof("(1 + t)(1 - 2Xt + t^2)^(-1/2) - 1 - (1 + X) t = sum_{n>=2} (P_n + P_{n-1}) t^n, "
                 "coefficients t^0..t^13 (sympy series vs legendre)")
    report.proof("d/dt of the elementary antiderivative equals the integrand; its limits at t = 0+ "
                 "and t = 1 give -(pi/8)(1 + cos eps)(3 + 4 L_s) = (A.15)")
    _check_sum(report, "15", errors)


def sums_a13_a14(report, errors):
    """(A.13), (A.14) from (A.15) by differentiating in X = cos(eps) under the integral sign.

    s = sqrt((cos psi - X)/2) gives ds/dX = -1/(4 s); Lambda = log((cos(psi/2) + s)/c), c^2 = (1+X)/2,
    gives dLambda/dX = -cos(psi/2)/(2 (1 + X) s).  Both integrands vanish at psi = eps, so the
    moving limit adds nothing: dS13/dX = -S15/4, dS14/dX = -S15/(2(1 + X)), S13 = S14 = 0 at eps = 0.
    """
    cpsi = sp.Symbol("cos_psi", real=True)
    s_X = sp.sqrt((cpsi - X) / 2)
    _require("ds/dX", sp.diff(s_X, X) + 1 / (4 * s_X))
    c_X = sp.sqrt((1 + X) / 2)
    s_c = sp.sqrt(cp**2 - c_X**2)
    Lam = sp.log((cp + s_c) / c_X)
    _require("dLambda/dX", sp.diff(Lam, X) + cp / (2 * (1 + X) * s_c))
    S15_X = S15_printed.subs(Ls, L_of_X)
    for label, printed, rate in (("(A.13)", S13_printed, -S15_X / 4), ("(A.14)", S14_printed, -S15_X / (2 * (1 + X)))):
        in_X = printed.subs(Ls, L_of_X)
        _require(f"{label} derivative", sp.diff(in_X, X) - rate)
        at_zero = sp.limit(printed.subs(Ls, sp.log(u)).subs(X, 1 - 2 * u**2), u, 0, "+")
        _require(f"{label} at eps = 0", at_zero)
        report.result(f"The sum {label}", sp.Eq(sp.Symbol("S_{" + label[3:5] + "}"), printed), MATCHES,
                      "integrated from (A.15) in X = cos(eps)")
        report.proof("ds/dX = -1/(4s) and d/dX log((cos(psi/2) + s)/cos(eps/2)) = -cos(psi/2)/(2(1+X)s)")
        report.proof(f"d{label}/dX = {'-S15/4' if label == '(A.13)' else '-S15/(2(1+X))'} and {label} = 0 at eps = 0")
        _check_sum(report, label[3:5], errors)


def _summed_kernel(p):
    """sum_{n>=2} w_n cos(n psi) = -(5.5), numerically."""
    return -(mp.mpf(1) / 2 + mp.cos(p) / 4 + mp.cos(p) * mp.log(2 * mp.sin(p / 2)))


def sums_by_quadrature():
    """Each closed form vs its series summed under the integral sign with (5.5): no Legendre, no Abel.

    Returns {"13": (max error, points), ...}; raises if a closed form misses.
    """
    closed = {k: checks.mp_function(v.subs(Ls, L_of_X), (X,))
              for k, v in (("13", S13_printed), ("14", S14_printed), ("15", S15_printed))}
    shapes = {"13": lambda p, s_, c: mp.cos(p / 2) * s_,
              "14": lambda p, s_, c: mp.log((mp.cos(p / 2) + s_) / c),
              "15": lambda p, s_, c: mp.cos(p / 2) / s_}
    with mp.workdps(checks.DPS):
        pairs = {k: [] for k in shapes}
        for e in _sample_eps():
            c = mp.cos(e / 2)
            for k, shape in shapes.items():
                q = _theta_quad(lambda p, s_: _summed_kernel(p) * shape(p, s_, c), e)
                pairs[k].append((q, closed[k](mp.cos(e))))
    return {k: (checks.assert_close(f"(A.{k})", pairs[k]), len(pairs[k])) for k in shapes}


def _check_sum(report, key, errors):
    report.check(f"(A.{key}) vs tanh-sinh quadrature of int_0^eps [sum_n w_n cos(n psi)](...) dpsi, "
                 "the sum taken from (5.5), eps from 1e-3 to 3.13", *errors[key])


# --- (5.3), (5.6), (5.7): the approach --------------------------------------------------------------
def sums_in_a():
    """(A.13)-(A.15) at X = cos(eps) = (1 - a^2)/(1 + a^2); L_s stays a symbol (L_s = log(a/E))."""
    X_a = (1 - a**2) / (1 + a**2)
    return {k: v.subs(X, X_a) for k, v in (("13", S13_printed), ("14", S14_printed), ("15", S15_printed))}


def approach_53():
    """delta of (5.3) with J of (5.6)-(5.7), in terms of B, P, c0, c1, r0 and the sums.

    (kappa_I + 1)/(2 G_I) = beta - beta/(2 vartheta) by the definitions of beta* and vartheta.
    """
    S = sums_in_a()
    r0 = sp.Symbol("r0", real=True)
    k = 4 / (R * beta)
    series = r0 / E * S["15"] + k * c1 * S["13"] - k * c0 * S["14"]          # (5.7), cos(eps/2) = 1/E
    J = -B - P / (2 * R) - 4 * series                                          # (5.6)
    kI_over_2GI = beta * (1 - th / 2)
    delta = -R / (4 * sp.pi) * (kI_over_2GI * B + P * g / R + beta * J)         # (5.3)
    return delta, r0


def printed_58():
    """(5.8) as read here (the extracted text garbles its first term):

    delta = B R (kappa + 1)/(4 pi) * 1/(2G) + P/(4 pi) (beta/2 - 1/G_I)
            - (5/4 c0 + c0 L_s + 19/16 c1 + 17/8 c1 L_s) - c1/16 (5 + 6 L_s) cos(2 eps)
            + (3 + 4 L_s) [4 (c0 + c1) pi - beta R C] cos^3(eps/2)/(4 pi)
            - [6 c1 (1 + L_s) + c0 (7 + 12 L_s)] cos(eps)/4,
    with (kappa + 1)/(2G) = beta/(2 vartheta).
    """
    cos_e = (1 - a**2) / (1 + a**2)
    cos_2e = 2 * cos_e**2 - 1
    return (B * R * beta * th / (8 * sp.pi) + P / (4 * sp.pi) * (beta / 2 - g)
            - (sp.Rational(5, 4) * c0 + c0 * Ls + sp.Rational(19, 16) * c1 + sp.Rational(17, 8) * c1 * Ls)
            - c1 / 16 * (5 + 6 * Ls) * cos_2e
            + (3 + 4 * Ls) * (4 * (c0 + c1) * sp.pi - beta * R * C) / (4 * sp.pi * E**3)
            - (6 * c1 * (1 + Ls) + c0 * (7 + 12 * Ls)) * cos_e / 4)


def approach_in_constants(r0):
    """(5.3) after (5.6), (5.7), (A.13)-(A.15): delta in B, P, c0, c1, r0 (E = sec(eps/2), L_s = log(a/E))."""
    return (R * beta * th * B / (8 * sp.pi) + P / (4 * sp.pi) * (beta / 2 - g)
            - c1 * a**2 * (1 + 2 * (2 + a**2) * Ls) / (2 * E**4)
            + c0 * a**2 * (1 + 4 * Ls) / (2 * E**2)
            - R * beta * r0 * (3 + 4 * Ls) / (4 * E**3))


def compare_58(report):
    delta, r0 = approach_53()
    general = approach_in_constants(r0)
    report.result("The approach from (5.3), (5.6), (5.7) in terms of B, P, c0, c1, r0",
                  sp.Eq(sp.Symbol(r"\delta"), general), NEW,
                  "sums (A.13)-(A.15) at cos(eps) = (1 - a^2)/(1 + a^2), cos(eps/2) = 1/E")
    if not load.is_zero(delta - general):
        raise AssertionError("derive proof failed: delta in B, P, c0, c1, r0")
    report.proof("(5.3) with J of (5.6), (5.7) and the sums minus this form reduces to 0")
    r0_def = 4 / (R * beta) * (E - 1) * (c0 - c1 / E) + C / sp.pi                 # (2.12)
    diff = printed_58() - delta.subs(r0, r0_def)
    if not load.is_zero(diff):
        raise AssertionError("derive proof failed: (5.8)")
    report.result("The approach (5.8)", sp.Eq(sp.Symbol(r"\delta"), printed_58()), MATCHES,
                  "read with first term B R (kappa + 1)/(4 pi) * 1/(2G) (the extraction prints P/(2G) "
                  "there, which is not dimensionally consistent)")
    report.proof("(5.8) minus (5.3) assembled with (5.6), (5.7), (A.13)-(A.15) and r0 of (2.12) "
                 "reduces to 0 modulo E^2 = 1 + a^2")
    return delta, r0


# --- delta(a): the load solution substituted, and a form for float64 ---------------------------------
L_ = log1p(a**2)                        # log(1 + a^2)
Ls_ = -log1p(a**-2) / 2                 # log sin(eps/2) = log(a/E), no cancellation at large a
D_ = 2 - th * (L_ + 2 * a**4)           # vartheta^-1 times the denominator of (4.4)


def d_Delta(Ls_expr=Ls_):
    """d delta/d Delta: [t (L + 2a^4) + a^6/E^2 - 2 (g/beta) a^2 E^2 - 4 a^2 E^2 L_s] / D."""
    E2 = 1 + a**2
    return (th * (L_ + 2 * a**4) + a**6 / E2 - 2 * g / beta * a**2 * E2 - 4 * a**2 * E2 * Ls_expr) / D_


def d_zeta(Ls_expr=Ls_):
    """d delta/d zeta: sqrt(a) [2 E^4 (2 + t(a^2 - L)) (2 beta L_s + g)
                                + beta (4 - 2a^4 - t (a^6 - a^4 L + 8a^4 + 6a^2 + 2L + 2))] / (4 pi E^2 D).

    2 + t(a^2 - L) is the adhesion factor of the load (4.4).
    """
    E2 = 1 + a**2
    bracket = (2 * E2**2 * (2 + th * (a**2 - L_)) * (2 * beta * Ls_expr + g)
               + beta * (4 - 2 * a**4 - th * (a**6 - a**4 * L_ + 8 * a**4 + 6 * a**2 + 2 * L_ + 2)))
    return sp.sqrt(a) * bracket / (4 * sp.pi * E2 * D_)


def approach_of_a(report, delta, r0):
    sol = load.solution()
    full = delta.subs({B: sol["B"], P: sol["P"], c0: sol["c0"], c1: sol["c1"], r0: sol["r0"]})
    closed = Delta * d_Delta(Ls) + zeta * d_zeta(Ls)
    if not load.is_zero(full - closed):
        raise AssertionError("derive proof failed: delta = Delta d_Delta + zeta d_zeta")
    report.result("The approach in closed form, delta = Delta d_Delta + zeta d_zeta",
                  sp.Eq(sp.Symbol(r"\delta"), closed), NEW,
                  "load solution (4.4)-(4.5) and r0 = -E zeta sqrt(a)/(pi R) substituted into (5.3); "
                  "R and kappa_I drop out (kappa_I via beta and vartheta)")
    report.proof("(5.3) with the load solution minus the closed form reduces to 0 modulo E^2 = 1 + a^2 "
                 "(L_s kept as a symbol)")
    ls_gap = (sp.log(a / E) - Ls_).replace(log1p, lambda z: sp.log(1 + z))
    _require("L_s = -log1p(a^-2)/2", sp.expand_log(ls_gap, force=True))
    report.proof("log sin(eps/2) = log(a/E) = -log1p(1/a^2)/2 (no cancellation for large a)")
    return full.subs(Ls, sp.log(a / E))


def hertz_limit(report):
    """w = 0, a -> 0: the first two terms of the series of delta/Delta = d_Delta."""
    exact = d_Delta(sp.log(a / E)).replace(log1p, lambda z: sp.log(1 + z))
    log_a = sp.log(a)
    two_terms = (a**2 * (th / 2 - g / beta - 2 * log_a)
                 + a**4 * (th**2 / 4 + 3 * th / 4 + 1 - g / beta * (1 + th / 2) - (2 + th) * log_a))
    rest = sp.series(exact - two_terms, a, 0, 6).removeO()
    lam = sp.Symbol("lambda")
    lowest = min((mono[0] for mono in sp.Poly(sp.expand(rest.subs(log_a, lam)), a).monoms()), default=6)
    if lowest < 6:
        raise AssertionError("derive proof failed: Hertz-type limit")
    report.result("Adhesionless small-contact (Hertz-type) approach",
                  sp.Eq(sp.Symbol(r"\delta/\Delta"), two_terms + sp.O(a**6 * log_a)), NEW,
                  "series of d_Delta at a = 0; to leading order, with P = 4 pi Delta a^2/beta (7.3c) and "
                  "half-width b = 2aR: delta = P/(4 pi) [(kappa + 1)/(2G) - 1/G_I + 2 beta log(2R/b)]")
    report.proof("sympy series of d_Delta minus the two terms is O(a^6 log a)")
    return two_terms


# --- numerical checks of delta: quadrature of (5.3) with (5.4), and the identity (5.2) --------------
MATERIALS = {   # (beta, inv_theta, inv_G_I) of alpha* = 0 pairs; kappa_I follows from beta, vartheta, G_I
    "identical (G = G_I = 1, kappa = kappa_I = 2)": (mp.mpf(3), mp.mpf(1), mp.mpf(1)),
    "stiff hole (G = 10, kappa = 2; G_I = 1, kappa_I = 1.1)": (mp.mpf("1.2"), mp.mpf("0.25"), mp.mpf(1)),
    "rubbery disk in a rigid cradle (G = inf; G_I = 1, kappa_I = 1)": (mp.mpf(1), mp.mpf(0), mp.mpf(1)),
}


def _state_fn():
    """B, P, c0, c1, r0 of derive.load as one mpmath function of (a, R, Delta, beta, inv_theta, zeta)."""
    sol = load.solution()
    names = ("B", "P", "c0", "c1", "r0")
    f = checks.mp_function([sol[k] for k in names], (a, R, Delta, beta, inv_theta, zeta))
    return lambda *vals: dict(zip(names, f(*vals)))


def _pressure_fn(av, Rv, bv, st):
    """(5.4) with s passed in (s = sin(eps/2) cos(theta) on the quadrature path)."""
    k = 4 / (Rv * bv)
    ce = 1 / mp.sqrt(1 + av**2)
    return lambda p, s_: (st["r0"] * mp.cos(p / 2) * ce / s_ + k * st["c1"] * mp.cos(p / 2) * s_
                          - k * st["c0"] * mp.log((mp.cos(p / 2) + s_) / ce))


def _two_sided(f, eps_, cut=None):
    """int_{-eps}^{eps} f(psi, s) dpsi on the theta path, split where f has a log singularity."""
    uu = mp.sin(eps_ / 2)

    def h(theta):
        psi_ = 2 * mp.asin(uu * mp.sin(theta))
        s_ = uu * mp.cos(theta)
        return f(psi_, s_) * 2 * uu * mp.cos(theta) / mp.cos(psi_ / 2)
    pts = [-mp.pi / 2, 0, mp.pi / 2]
    if cut is not None:
        pts = sorted(set(pts + [mp.asin(mp.sin(cut / 2) / uu)]))
    return mp.quad(h, pts)


def check_delta(report, full):
    """delta closed form vs quadrature of (5.3) with (5.4); (5.2) at phi != 0 gives delta cos(phi) - Delta (1 - cos phi)."""
    f_closed = checks.mp_function(full, (a, R, Delta, beta, inv_theta, zeta, g))
    state = _state_fn()
    pairs, pairs_52 = [], []
    with mp.workdps(checks.DPS):
        Rv, Dv = mp.mpf("1.5"), mp.mpf("0.01")
        for bv, tv, gv in MATERIALS.values():
            kI_over_2GI = bv * (1 - tv / 2)
            for w in (mp.mpf(0), mp.mpf("0.004")):
                zv = mp.sqrt(4 * mp.pi * w * Rv / bv)                          # zeta* = sqrt(2 w R/A)
                for av in (mp.mpf("0.05"), mp.mpf("0.4"), mp.mpf("1.7"), mp.mpf(6)):
                    st = state(av, Rv, Dv, bv, tv, zv)
                    N = _pressure_fn(av, Rv, bv, st)
                    eps_ = 2 * mp.atan(av)
                    J = _two_sided(lambda p, s_: N(p, s_) * mp.cos(p) * 2 * mp.log(2 * mp.sin(abs(p) / 2)), eps_)
                    d53 = -Rv / (4 * mp.pi) * (kI_over_2GI * st["B"] + st["P"] * gv / Rv + bv * J)
                    pairs.append((d53, f_closed(av, Rv, Dv, bv, tv, zv, gv)))
                    if av in (mp.mpf("0.4"), mp.mpf("1.7")):
                        for ph in (eps_ / 3, -eps_ * 3 / 4):
                            kern = lambda p, s_: N(p, s_) * (bv * mp.cos(ph - p) * 2 * mp.log(abs(2 * mp.sin((ph - p) / 2)))
                                                             + mp.cos(ph - p) * gv + kI_over_2GI)
                            rhs = -Rv / (4 * mp.pi) * _two_sided(kern, eps_, cut=ph)
                            pairs_52.append((rhs, d53 * mp.cos(ph) - Dv * (1 - mp.cos(ph))))
    report.result("The approach against quadrature of (5.3) with the pressure (5.4)",
                  sp.Symbol(r"\delta"), MATCHES, "three alpha* = 0 material pairs, w = 0 and w > 0, "
                  "a = 0.05, 0.4, 1.7, 6 (sub- and super-critical)")
    report.check("closed-form delta vs tanh-sinh quadrature of (5.3)", checks.assert_close("(5.3)", pairs), len(pairs))
    report.result("The displacement identity (5.2) inside the contact", sp.Symbol(r"\delta"), MATCHES,
                  "(5.2) at phi = eps/3 and -3 eps/4 must equal delta cos(phi) - Delta (1 - cos(phi)) "
                  "with delta from (5.3): checks the signs and factors of (5.2), (5.3) and that (5.4) "
                  "solves (2.3)")
    report.check("quadrature of (5.2) vs delta cos(phi) - Delta (1 - cos(phi))",
                  checks.assert_close("(5.2)", pairs_52), len(pairs_52))


# --- kernels -------------------------------------------------------------------------------------------
def _kernels():
    dD, dz = d_Delta(), d_zeta()
    delta = Delta * dD + zeta * dz
    approach = Kernel("approach", (("delta", delta), ("delta_over_Delta", dD + zeta / Delta * dz)),
                      "Approach delta (5.3)/(5.8) [m] at contact parameter a = tan(eps/2), and delta/Delta.\n"
                      "Delta [m], beta = beta* [1/Pa], inv_G_I = 1/G_I [1/Pa], inv_theta = 1/vartheta,\n"
                      "zeta = zeta* = sqrt(2wR/A) [N/m^(1/2)].  R and kappa_I enter only through zeta,\n"
                      "beta and vartheta.  Stable in float64 for 1e-8 <= a <= 1e4 (away from a_crit).",
                      forms=("into",))
    parts = Kernel("approach_parts", (("d_Delta", dD), ("d_zeta", dz)),
                   "delta = Delta * d_Delta + zeta * d_zeta: d_Delta [-], d_zeta [m/(N/m^(1/2))].")
    return [approach, parts]


def derive(report):
    report.section("The approach (section 5, Appendix A.13-A.15)")
    fourier_55(report)
    integral_56(report)
    legendre_terms(report)
    errors = sums_by_quadrature()
    sum_a15(report, errors)
    sums_a13_a14(report, errors)
    delta, r0 = compare_58(report)
    full = approach_of_a(report, delta, r0)
    hertz_limit(report)
    check_delta(report, full)
    return _kernels()
