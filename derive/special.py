"""Section 7: the special cases as limits of the general result (nothing typed but the prints they meet).

* adhesionless contact (7.1), (7.2): w = 0, i.e. zeta* = 0 (vartheta = G beta*/(1 + kappa) in (7.1));
* Barquins' half-plane (7.3b)-(7.4): the leading term in a of the Delta part and of the zeta* part of
  (4.4); normalised as in section 6, and its minimum (the half-plane adherence force);
* rubbery cylinder in a rigid cradle (7.5)-(7.7): vartheta -> inf (inv_theta = 0), P_R* of (7.6) as the
  limit of vartheta P* at M = M_R*/vartheta, lift-off (7.7) as sqrt(a) dP_R*/da;
* neat fit (section 7.3): Delta = 0, the load normalised by the adhesion, Q* = P/zeta*.
Each emitted form is compared with the printed formula, typed below (the tests type the same prints again, on
their own, in reference/paper.py: the derivation never imports the tests' reference).
"""
import sympy as sp
from sympy.codegen.cfunctions import log1p

from . import load
from .kernel import Kernel
from .report import MATCHES
from .symbols import Delta, M, R, a, beta, inv_theta, theta, zeta

G = sp.Symbol("G", positive=True)
kappa = sp.Symbol("kappa", positive=True)
M_R = sp.Symbol("M_R", nonnegative=True)
w = sp.Symbol("w", nonnegative=True)



# --- the paper's printed forms (7.1)-(7.7) -------------------------------------------------------------------
def printed_71():
    """(7.1): P|_{w=0} = 8 pi Delta G a^2 (1 + a^2)/(2 G beta* - (L + 2 a^4)(1 + kappa)), L = log(1 + a^2)."""
    L = sp.log(1 + a**2)
    return 8 * sp.pi * Delta * G * a**2 * (1 + a**2) / (2 * G * beta - (L + 2 * a**4) * (1 + kappa))


def printed_72():
    """(7.2): B R/P|_{w=0} = (L + 2 a^4)/(a^2 (1 + a^2))."""
    return (sp.log(1 + a**2) + 2 * a**4) / (a**2 * (1 + a**2))


def printed_74():
    """(7.4): P_h = a_h^2 R_D/(2 A R* R) - sqrt(4 a_h w/A), a_h = 2 a R, 1/R* = 1/R_D - 1/R, R_D = R - Delta."""
    A, R_D = beta / (2 * sp.pi), R - Delta
    a_h = 2 * a * R
    return a_h**2 / (2 * A) * (1 / R_D - 1 / R) * R_D / R - sp.sqrt(4 * a_h * w / A)


def printed_76():
    """(7.6): P_R* = (1 + a^2)(a^2 - 2 M_R* sqrt(a))."""
    return (1 + a**2) * (a**2 - 2 * M_R * sp.sqrt(a))


def printed_77():
    """(7.7): 4 a^(7/2) - 5 M_R* a^2 + 2 a^(3/2) - M_R* (zero at lift-off)."""
    return 4 * a**sp.Rational(7, 2) - 5 * M_R * a**2 + 2 * a**sp.Rational(3, 2) - M_R


def _plain(expr):
    return expr.replace(log1p, lambda z: sp.log(1 + z))


def _require_equal(what, derived, printed):
    if sp.simplify(_plain(derived) - _plain(printed)) != 0:
        raise AssertionError(f"derive check failed: {what} differs from the print")


def adhesionless():
    """(7.1), (7.2): zeta* = 0 in P and B of derive.load, vartheta = G beta*/(1 + kappa)."""
    sol = load.solution()
    P_w0 = sol["P"].subs(zeta, 0)
    BR_over_P = sp.factor(sp.cancel(sol["B"].subs(zeta, 0) * R / sol["P"].subs(zeta, 0)))
    return P_w0, BR_over_P


def half_plane():
    """(7.3c)/(7.4): leading terms in a of the Delta and zeta* parts of (4.4); P_h* and its minimum."""
    P = load.solution()["P"]
    lead_Delta = sp.limit(sp.diff(P, Delta) / a**2, a, 0) * a**2
    lead_zeta = sp.limit(sp.diff(P, zeta) / sp.sqrt(a), a, 0) * sp.sqrt(a)
    P_h = Delta * lead_Delta + zeta * lead_zeta
    # section 6: P* = P beta*/(4 pi Delta vartheta), zeta* = 4 pi Delta vartheta M/beta*
    P_h_star = sp.expand((P_h * beta / (4 * sp.pi * Delta)).subs(zeta, 4 * sp.pi * Delta * M / (inv_theta * beta))
                         * inv_theta)
    P_fin = P_h_star.subs(inv_theta, 1 / theta)
    (a_m,) = sp.solve(sp.diff(P_fin, a), a)
    return P_h, P_h_star, a_m, sp.simplify(P_fin.subs(a, a_m))


def rubbery():
    """(7.5)-(7.7): inv_theta = 0; P_R* = lim vartheta P*(M = M_R*/vartheta); lift-off sqrt(a) dP_R*/da."""
    P = load.solution()["P"]
    P_rigid = P.subs(inv_theta, 0)
    P_star = load.normalised_load()
    P_R_star = sp.factor(sp.limit(theta * P_star.subs(M, M_R / theta), theta, sp.oo))
    lift_off = sp.expand(sp.sqrt(a) * sp.diff(P_R_star, a))
    return P_rigid, P_R_star, lift_off


def neat_fit():
    """Section 7.3: Delta = 0, Q* = P/zeta* (a function of a and vartheta only)."""
    return sp.factor(load.solution()["P"].subs(Delta, 0) / zeta)


def derive(report):
    report.section("Special cases (section 7)")
    P_w0, BR_over_P = adhesionless()
    _require_equal("(7.1)", P_w0.subs(inv_theta, (1 + kappa) / (G * beta)), printed_71())
    _require_equal("(7.2)", BR_over_P, printed_72())
    report.result("Adhesionless contact (7.1), (7.2)", sp.Eq(sp.Symbol("P_{w=0}"), P_w0), MATCHES,
                  "zeta* = 0 in (4.4), (4.5a) with vartheta = G beta*/(1 + kappa)")
    report.proof("equal to the printed (7.1) and (7.2)")

    P_h, P_h_star, a_m, P_m = half_plane()
    A = beta / (2 * sp.pi)
    _require_equal("(7.4)", P_h.subs(zeta, sp.sqrt(2 * w * R / A)), printed_74())
    report.result("Half-plane (Barquins) load (7.3c), (7.4)", sp.Eq(sp.Symbol("P_h"), P_h), MATCHES,
                  "leading terms in a of the Delta part and of the zeta* part of (4.4)")
    report.proof("equal to the printed (7.4) with zeta* = sqrt(2 w R/A), 1/R* = Delta/(R R_D)")
    report.result("Half-plane adherence (minimum of P_h*)", sp.Eq(sp.Symbol("P_h^*"), P_m), MATCHES,
                  f"sympy solve of dP_h*/da = 0: a = {a_m}")

    P_rigid, P_R_star, lift_off = rubbery()
    _require_equal("(7.6)", P_R_star, printed_76())
    _require_equal("(7.7)", lift_off, printed_77())
    report.result("Rubbery cylinder in a rigid cradle (7.5)-(7.7)", sp.Eq(sp.Symbol("P_R^*"), P_R_star), MATCHES,
                  "limit vartheta -> inf of vartheta P* at M = M_R*/vartheta; (7.7) = sqrt(a) dP_R*/da")
    report.proof("equal to the printed (7.6) and (7.7)")

    Q = neat_fit()
    report.result("Neat fit Q* = P/zeta* (section 7.3)", sp.Eq(sp.Symbol("Q^*"), Q), MATCHES,
                  "Delta = 0 in the stable form of (4.4)")
    return [
        Kernel("adhesionless_load", (("P", P_w0),), "(7.1): load without adhesion [N/m]; inv_theta = (1 + kappa)/(G beta*)."),
        Kernel("adhesionless_BR_over_P", (("BR_over_P", BR_over_P),), "(7.2): B R/P without adhesion."),
        Kernel("half_plane_load", (("P_h", P_h),), "(7.3c): Barquins' half-plane load [N/m]."),
        Kernel("half_plane_P_star", (("P_h_star", P_h_star),),
               "P_h* = P_h beta*/(4 pi Delta vartheta) of the half-plane (section 6 normalisation)."),
        Kernel("half_plane_adherence", (("a", a_m), ("P_star", P_m)),
               "Minimum of P_h*: the half-plane fixed-load adherence (contact parameter, P_h*)."),
        Kernel("rubbery_load", (("P", P_rigid),), "(7.5): load of the rubbery cylinder, vartheta = inf [N/m]."),
        Kernel("rubbery_P_star", (("P_R_star", P_R_star),), "(7.6): P_R* = P beta*/(4 pi Delta)."),
        Kernel("lift_off", (("f", lift_off),), "(7.7): sqrt(a) dP_R*/da; zero at lift-off."),
        Kernel("neat_fit_load", (("Q_star", Q),), "Q* = P/zeta* at Delta = 0 (section 7.3)."),
        Kernel("neat_fit_slope", (("dQ_star_da", sp.diff(Q, a)),),
               "dQ*/da at Delta = 0: fixed-load stable where Q* dQ*/da < 0 (jkrcyl.model.stability)."),
    ]
