"""Section 2 and Appendix A.1-A.12: the pressure solution of the Cauchy SIE (2.7) and its integrals.

Reads top to bottom like the paper: the principal-value integrals I1, I2 (A.5), (A.6); the
split of the pressure into bounded and unbounded parts (2.11)-(2.12); the six definite integrals
(A.7)-(A.12) that turn the definitions (2.13) of B and P into (2.15a), (2.15b); and the form
(5.4) of the pressure in the original angle.  ``S = sqrt(a^2 - x^2)`` throughout.
"""
import mpmath as mp
import sympy as sp

from . import checks
from .kernel import Kernel
from .report import MATCHES
from .symbols import (E, R, a, beta, c0, c1, C, phi, s, x)

S = sp.sqrt(a**2 - x**2)
_Ssym, _Esym = sp.symbols("S E", positive=True)


def _points():
    """(a, x) pairs inside the contact used by the numerical checks."""
    return [(av, av * f) for av in checks.sample_a() for f in (mp.mpf("-0.9"), mp.mpf("0.3"), mp.mpf("0.77"))]


# --- (A.5), (A.6): the principal-value integrals of (2.10) ---------------------------------
I1 = sp.pi * (E - 1 - S / 2 * sp.log((E + S) / (E - S)))          # (A.5)
I2 = (sp.pi * x**2 - sp.pi * (E - 1)) / (1 + x**2)                 # (A.6)


def _check_principal_values(report):
    """I1, I2 are Cauchy principal values: compare with a PV quadrature of (A.1) and (A.6)."""
    i1 = checks.mp_function(I1, (a, x))
    i2 = checks.mp_function(I2, (a, x))
    with mp.workdps(checks.DPS):
        pairs1, pairs2 = [], []
        for av, xv in _points():
            w = lambda t: mp.sqrt(av**2 - t**2)
            pairs1.append((checks.pv_quad(lambda t: w(t) * mp.atan(t), xv, -av, av), i1(av, xv)))
            pairs2.append((checks.pv_quad(lambda t: t * w(t) / (1 + t**2), xv, -av, av), i2(av, xv)))
        report.result("I1, the principal value (A.1) = (A.5)", sp.Eq(sp.Symbol("I_1"), I1), MATCHES,
                      "sympy cannot evaluate the principal value (A.1) in closed form")
        report.check("PV quadrature of (A.1) vs (A.5)", checks.assert_close("(A.5)", pairs1), len(pairs1))
        report.result("I2, the principal value (A.6)", sp.Eq(sp.Symbol("I_2"), I2), MATCHES,
                      "elementary; checked rather than re-derived")
        report.check("PV quadrature of (A.6) vs its closed form", checks.assert_close("(A.6)", pairs2), len(pairs2))


# --- (2.10) -> (2.11), (2.12): bounded and unbounded parts ----------------------------------
k = 4 / (R * beta)
r0 = k * (E - 1) * (c0 - c1 / E) + C / sp.pi                       # coefficient in (2.12)
p_unbounded = r0 / S                                               # first term of (2.12)
p_bounded = k * c1 * S / ((1 + x**2) * E) - k * c0 * sp.atanh(S / E)
p_210 = 4 / (sp.pi * R * beta) / S * (c0 * I1 - c1 * I2) + C / (sp.pi * S)   # (2.10)


def _algebraic(expr):
    """Write S and E as symbols with S^2 = a^2 - x^2, E^2 = 1 + a^2 (both positive)."""
    expr = expr.subs({sp.atanh(S / E): sp.log((E + S) / (E - S)) / 2})
    expr = expr.subs({S: _Ssym, E: _Esym})
    return sp.expand_log(expr, force=True)


def _prove_pressure_split(report):
    """(2.11) is an identity and (2.10) with (A.5), (A.6) equals (2.12)."""
    lhs = 1 / (S * (1 + x**2))
    rhs = 1 / (S * (1 + a**2)) + S / ((1 + x**2) * (1 + a**2))
    report.result("The identity (2.11)", sp.Eq(lhs, rhs), MATCHES, "algebra")
    _require_zero("(2.11)", sp.simplify(lhs - rhs))
    report.proof("simplify(lhs - rhs) == 0")

    diff = _algebraic(p_210 - (p_unbounded + p_bounded))
    diff = diff.subs(x**2, _Esym**2 - 1 - _Ssym**2)
    diff = sp.cancel(sp.expand(diff.subs(a**2, _Esym**2 - 1)))
    report.result("The pressure (2.12): bounded plus unbounded part",
                  sp.Eq(sp.Symbol("p"), p_unbounded + p_bounded), MATCHES,
                  "(2.10) with (A.5), (A.6) substituted")
    _require_zero("(2.12)", diff)
    report.proof("(2.10) - (2.12) cancels to 0 with S^2 = a^2 - x^2, E^2 = 1 + a^2")


def _require_zero(what, expr):
    if expr != 0:
        raise AssertionError(f"derive proof failed: {what} leaves {expr}")


# --- (A.7)-(A.12): the definite integrals that give (2.15a), (2.15b) ----------------------
LOG = sp.log((E + S) / (E - S))
W_B = 1 / (1 + x**2)                    # weight of B/2 in (2.13)
W_P = (1 - x**2) / (1 + x**2)**2        # weight of P/(2R) in (2.13)
TABLE = [  # (equation, integrand over -a < x < a, value)
    ("(A.7)", LOG * W_B, sp.pi * sp.log(1 + a**2)),
    ("(A.8)", LOG * W_P, sp.pi * a**2 / (1 + a**2)),
    ("(A.9)", W_B / S, sp.pi / E),
    ("(A.10)", S / (1 + x**2)**2, sp.pi * a**2 / (2 * E)),
    ("(A.11)", W_P / S, sp.pi / E**3),
    ("(A.12)", S * (1 - x**2) / (1 + x**2)**3, sp.pi * a**2 * (2 + a**2) / (4 * E**3)),
]


def _check_table(report):
    with mp.workdps(checks.DPS):
        for label, integrand, value in TABLE:
            f = checks.mp_function(integrand.subs(S, _Ssym), (a, x, _Ssym))
            v = checks.mp_function(value, (a,))
            pairs = [(_quad_chord(f, av), v(av)) for av in checks.sample_a()]
            report.result(f"The integral {label}", sp.Eq(sp.Integral(integrand, (x, -a, a)), value),
                          MATCHES, "stated without proof in the paper")
            report.check(f"tanh-sinh quadrature of {label}", checks.assert_close(label, pairs), len(pairs))


def _quad_chord(f, av):
    """int_{-a}^{a} f(a, x, S) dx with x = a sin(u): the sqrt(a^2 - x^2) end behaviour becomes smooth.

    Breakpoints at x = 0, +-1 where 1/(1 + x^2) turns for large a.
    """
    g = lambda u: f(av, av * mp.sin(u), av * mp.cos(u)) * av * mp.cos(u)
    turn = mp.asin(1 / av) if av > 1 else mp.pi / 4
    return mp.quad(g, [-mp.pi / 2, -turn, 0, turn, mp.pi / 2])


def integrate_pressure(weight):
    """int_{-a}^{a} p(x) weight dx for weight in (W_B, W_P), term by term from the table."""
    value = {sp.simplify(i): v for _, i, v in TABLE}
    terms = [(r0, 1 / S), (k * c1 / E, S / (1 + x**2)), (-k * c0 / 2, LOG)]
    total = 0
    for coeff, shape in terms:
        total += coeff * value[sp.simplify(shape * weight)]
    return total


# --- (5.4): the pressure in the original angle ----------------------------------------------
def pressure_in_angle():
    """N(phi) of (5.4) with s = sqrt(cos^2(phi/2) - cos^2(eps/2)) written stably.

    cos^2(u) - cos^2(v) = sin(v - u) sin(v + u), and cos(eps/2) = 1/E, so with
    eps/2 = atan(a) nothing cancels at the contact edge; atanh(s/cos(phi/2)) equals the
    logarithm of (5.4) (see (A.7) remark) and keeps its accuracy for tiny contacts.
    """
    half_eps = sp.atan(a)
    cp = sp.cos(phi / 2)
    s_ = sp.sqrt(sp.sin(half_eps - phi / 2) * sp.sin(half_eps + phi / 2))
    unbounded = r0 * cp / (E * s_)
    bounded = k * c1 * cp * s_ - k * c0 * sp.atanh(s_ / cp)
    return bounded, unbounded


def _check_angle_form(report):
    """(5.4) is (2.12) after x = tan(phi/2): compare at many points."""
    nb, nu = pressure_in_angle()
    coeffs = {c0: sp.Rational(-3, 7), c1: sp.Rational(2, 11), C: sp.Rational(5, 13), R: sp.Rational(3, 2),
              beta: sp.Rational(7, 5)}
    f54 = checks.mp_function((nb + nu).subs(coeffs), (a, phi))
    f212 = checks.mp_function((p_bounded + p_unbounded).subs(coeffs), (a, x))
    with mp.workdps(checks.DPS):
        pairs = [(f54(av, 2 * mp.atan(xv)), f212(av, xv)) for av, xv in _points()]
    report.result("The pressure in the original angle (5.4)", sp.Eq(sp.Symbol("N"), nb + nu), MATCHES,
                  "s written as sqrt(sin(eps/2 - phi/2) sin(eps/2 + phi/2)); log as atanh")
    report.check("(5.4) vs (2.12) at x = tan(phi/2)", checks.assert_close("(5.4)", pairs), len(pairs))


def derive(report):
    """Prove and check everything above; the pressure kernel itself is emitted by derive.load."""
    report.section("Pressure solution (section 2, Appendix A.1-A.12)")
    _check_principal_values(report)
    _prove_pressure_split(report)
    _check_table(report)
    _check_angle_form(report)
    return []
