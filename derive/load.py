"""Sections 3-4: the Griffith condition (3.6b), the linear system (4.3) and its inverse (4.4)-(4.5).

Nothing here is typed from the paper except the printed formulas it is compared with:
(2.15a), (2.15b) come from integrating the pressure (2.12) against the weights of (2.13) with the
verified table (A.7)-(A.12); the Griffith condition from the stress-intensity factor (3.4); the
matrix of (4.3) from ``sympy.linear_eq_to_matrix``.
"""
import mpmath as mp
import sympy as sp
from sympy.codegen.cfunctions import log1p
from sympy.polys.matrices import DomainMatrix

from . import checks, pressure
from .kernel import Kernel
from .report import DIFFERS, MATCHES, NEW
from .symbols import (B, C, Delta, E, L, M, P, R, a, beta, c0, c1, inv_theta, phi, theta, x, zeta)

_E, _L = sp.symbols("E L", positive=True)   # opaque sqrt(1 + a^2) and log(1 + a^2)


# --- (3.2)-(3.6): stress-intensity factor and the Griffith condition --------------------------
def stress_intensity(r0):
    """(3.3)-(3.4): K = -sqrt(4 pi R/(1 + a^2)) lim_{x->a} p(x) sqrt(a - x); only r0/S is singular."""
    end_limit = sp.limit(sp.sqrt(a - x) / pressure.S, x, a, dir="-")   # = 1/sqrt(2a)
    return -sp.sqrt(4 * sp.pi * R / (1 + a**2)) * end_limit * r0


def griffith_equation():
    """(3.6): (pi/4) A K^2 = w with A = beta/(2 pi), w = zeta^2 A/(2R) from zeta* = sqrt(2 w R/A)."""
    A = beta / (2 * sp.pi)
    w = zeta**2 * A / (2 * R)
    K = stress_intensity(pressure.r0)
    return K - sp.sqrt(4 * w / (sp.pi * A))     # K > 0: the tensile root


# --- (2.15a), (2.15b), (3.6b) with c0, c1 of (2.6) ---------------------------------------------
def constants_26(vartheta):
    """(2.6) with R (kappa + 1)/(8 pi G) = R beta/(8 pi vartheta), vartheta = G beta/(1 + kappa)."""
    return {c0: -Delta - R * beta * B / (8 * sp.pi * vartheta), c1: beta * P / (2 * sp.pi)}


def system_equations():
    """(2.15a), (2.15b) and the Griffith condition, each as an expression equal to zero."""
    eq_B = pressure.integrate_pressure(pressure.W_B) - B / 2
    eq_P = pressure.integrate_pressure(pressure.W_P) - P / (2 * R)
    return [eq_B, eq_P, griffith_equation()]


def linear_system(vartheta=theta):
    """The 3x3 system for (B, P, C), rows scaled to the paper's (4.1a)-(4.1c) (C coefficients 1/E, 1/E^3, 1/E)."""
    eqs = [e.subs(constants_26(vartheta)) for e in system_equations()]
    A, b = sp.linear_eq_to_matrix([sp.expand(e) for e in eqs], [B, P, C])
    scale = [1 / E, 1 / E**3, 1 / E]
    for i in range(3):
        factor = scale[i] / A[i, 2]
        A[i, :] = sp.simplify(A[i, :] * factor)
        b[i] = sp.simplify(b[i] * factor)
    return A, b


# --- the paper's printed forms (4.2)-(4.5) ------------------------------------------------------
f1, f2 = 1 - 1 / E - sp.log(E), 1 / E - sp.Rational(1, 2) - 1 / (2 * E**2)          # (4.2a)
g1 = -sp.Rational(1, 2) + 3 / (2 * E**2) - 1 / E**3                                  # (4.2b)
g2 = -sp.Rational(1, 4) + 1 / E**3 - 3 / (4 * E**4)
h1, h2 = 1 - 1 / E, 1 / E - 1 / E**2                                                 # (4.2c)


def printed_43(row2_col2_half=False):
    """(4.3) as printed; ``row2_col2_half`` replaces the printed 1/R in row 2 by 1/(2R)."""
    last = 1 / (2 * R) if row2_col2_half else 1 / R
    A = sp.Matrix([[-(f1 / (2 * theta) + sp.Rational(1, 2)), -2 * f2 / R, 1 / E],
                   [-g1 / (2 * theta), -(2 * g2 / R + last), 1 / E**3],
                   [-h1 / (2 * theta), -2 * h2 / R, 1 / E]])
    b = 4 * sp.pi * Delta / (R * beta) * sp.Matrix([f1, g1, h1]) - sp.Matrix([0, 0, zeta * sp.sqrt(a) / R])
    return A, b


D = 2 * theta - L - 2 * a**4                                                   # denominator of (4.4)
P_44 = 2 * (1 + a**2) * (4 * sp.pi * Delta * theta / beta * a**2 - zeta * sp.sqrt(a) * (a**2 - L + 2 * theta)) / D
B_45a = 4 * theta / (R * beta) * (2 * sp.pi * Delta * (L + 2 * a**4) - zeta * beta * sp.sqrt(a) * (1 + 2 * a**2)) / D
C_45b = (8 * sp.pi * Delta * theta / (R * beta) * ((1 - 2 * a**2) * (E - 1) + 2 * a**4) / D
         - zeta * sp.sqrt(a) / R * (E * (2 - 2 * a**4 + 3 * L - 6 * theta) / D
                                    + 2 * (4 * theta - 1 - 2 * L + 2 * a**2 * (a**2 - L + 2 * theta)) / D))


# --- algebraic comparison: rational functions of (a, E, L) modulo E^2 = 1 + a^2 -------------------
def is_zero(expr):
    """True when expr vanishes identically, treating E = sqrt(1+a^2), L = log(1+a^2) as algebraic over a.

    log1p is rewritten as log; the numerator is reduced modulo E^2 - 1 - a^2 in E.
    """
    expr = expr.replace(log1p, lambda u: sp.log(1 + u))
    expr = expr.subs({E: _E, L: _L}).subs({sp.sqrt(a**2 + 1): _E, sp.log(a**2 + 1): _L})
    expr = sp.expand_log(expr, force=True).subs(sp.log(_E), _L / 2)
    num = sp.numer(sp.together(sp.expand(expr)))
    return sp.expand(sp.rem(sp.expand(num), _E**2 - 1 - a**2, _E)) == 0


_Z = sp.Symbol("Z", nonnegative=True)   # zeta sqrt(a): the only way zeta and odd powers of a enter (4.3)


def to_EL(expr):
    """Rational form in (E, L, Z = zeta sqrt(a)); a enters only through a^2 = E^2 - 1."""
    expr = expr.replace(log1p, lambda u: sp.log(1 + u)).subs(zeta, _Z / sp.sqrt(a))
    expr = expr.subs({E: _E, L: _L}).subs({sp.sqrt(a**2 + 1): _E, sp.log(a**2 + 1): _L})
    expr = sp.cancel(expr.subs(a**2, _E**2 - 1))
    if a in expr.free_symbols:
        raise AssertionError(f"odd power of a left in {expr}")
    return expr


def from_EL(expr):
    return expr.subs({_E: E, _L: L, _Z: zeta * sp.sqrt(a)})


def solve_system(A, b):
    """LU solution of A (B, P, C) = b over the field of rational functions of (E, L, Z, ...): exact and small."""
    augmented = DomainMatrix.from_Matrix(A.applyfunc(to_EL).row_join(b.applyfunc(to_EL))).to_field()
    sol = augmented[:, :3].lu_solve(augmented[:, 3:]).to_Matrix()
    return sol.applyfunc(lambda e: from_EL(sp.factor(e)))


def _require(what, expr):
    if not is_zero(expr):
        raise AssertionError(f"derive proof failed: {what}")


# --- stable forms, in inv_theta (vartheta = infinity is inv_theta = 0) ------------------------------
L_ = log1p(a**2)                  # log(1 + a^2) without cancellation for tiny a
Em1 = a**2 / (E + 1)              # sqrt(1 + a^2) - 1 without cancellation
t = inv_theta
D_t = 2 - t * (L_ + 2 * a**4)     # vartheta^-1 times the denominator of (4.4)


def stable_forms():
    """The outputs as emitted; each is proved equal to the solution of the system below."""
    sa = sp.sqrt(a)
    P_ = 2 * E**2 * (4 * sp.pi * Delta * a**2 / beta - zeta * sa * (2 + t * (a**2 - L_))) / D_t
    B_ = 4 / (R * beta) * (2 * sp.pi * Delta * (L_ + 2 * a**4) - zeta * beta * sa * (1 + 2 * a**2)) / D_t
    C_ = (8 * sp.pi * Delta / (R * beta) * ((1 - 2 * a**2) * Em1 + 2 * a**4) / D_t
          - zeta * sa / R * (E * (t * (2 - 2 * a**4 + 3 * L_) - 6)
                             + 2 * (4 - t * (1 + 2 * L_) + 2 * a**2 * (t * (a**2 - L_) + 2))) / D_t)
    c0_ = (-2 * Delta + t * zeta * beta * sa * (1 + 2 * a**2) / (2 * sp.pi)) / D_t
    c1_ = beta * P_ / (2 * sp.pi)
    r0_ = -E * zeta * sa / (sp.pi * R)
    return {"P": P_, "B": B_, "C": C_, "c0": c0_, "c1": c1_, "r0": r0_}


def solution():
    """Closed-form (B, P, C, c0, c1, r0) in the kernel symbols; used by later derivations."""
    return stable_forms()


def normalised_load():
    """Section 6: P* = P beta/(4 pi Delta vartheta) with M = sqrt(w A R)/(sqrt(2) Delta vartheta).

    zeta* beta/(4 pi Delta vartheta) = M, so P* depends on (a, M, vartheta) only.
    """
    P_ = stable_forms()["P"].subs(inv_theta, 1 / theta)
    zeta_of_M = 4 * sp.pi * Delta * theta * M / beta
    return sp.factor_terms(sp.simplify(P_.subs(zeta, zeta_of_M) * beta / (4 * sp.pi * Delta * theta)))


# --- derivation ----------------------------------------------------------------------------------
def derive(report):
    report.section("Load and contact size (sections 3-4)")
    K = stress_intensity(sp.Symbol("r_0"))
    report.result("Stress-intensity factor (3.4)", sp.Eq(sp.Symbol("K_*"), K), MATCHES,
                  "sympy limit of p(x) sqrt(a - x) at the contact end, (3.3)")
    _require("(3.4) end limit", K + sp.sqrt(4 * sp.pi * R) / E * sp.Symbol("r_0") / sp.sqrt(2 * a))
    report.proof("lim sqrt(a - x)/sqrt(a^2 - x^2) = 1/sqrt(2a)")

    A, b = linear_system()
    _compare_system(report, A, b)
    sol = solve_system(A, b)
    _compare_inverse(report, sol)
    kernels = _stable_kernels(report, sol)
    _critical_contact(report)
    return kernels


def _critical_contact(report):
    """Section 4: the root of 2 vartheta - L - 2 a^4 at vartheta = 1, to 30 digits."""
    denominator = sp.lambdify(a, D.subs(theta, 1), modules="mpmath")
    with mp.workdps(checks.DPS):
        root = mp.findroot(denominator, mp.mpf("0.9"))
        eps_deg = 2 * mp.degrees(mp.atan(root))
    report.result("Critical contact parameter at vartheta = 1 (section 4)",
                  rf"a_{{crit}} = {mp.nstr(root, 12)},\quad \epsilon = {mp.nstr(eps_deg, 8)}^\circ",
                  DIFFERS, "mpmath findroot of the denominator of (4.4)")
    report.erratum("Section 4, a_crit at vartheta = 1",
                   r"$a \approx 0.9135 \Rightarrow \epsilon \approx 84.823^\circ$",
                   rf"$a = {mp.nstr(root, 8)}$, $\epsilon = {mp.nstr(eps_deg, 6)}^\circ$ "
                   "(84.823 is 2 atan of the truncated 0.9135)",
                   "50-digit root of 2 vartheta - log(1 + a^2) - 2 a^4 = 0")


def _compare_system(report, A, b):
    A_print, b_print = printed_43()
    report.result("The linear system (4.3) for (B, P, C)", sp.Eq(sp.MatMul(A, sp.Matrix([B, P, C])), b), DIFFERS,
                  "sympy.linear_eq_to_matrix of (2.15a), (2.15b), (3.6b) with c0, c1 of (2.6)")
    for i in range(3):
        for j in range(3):
            same = is_zero(A[i, j] - A_print[i, j])
            if (i, j) == (1, 1):
                if same:
                    raise AssertionError("(4.3) row 2 column 2 unexpectedly matches the print")
                _require("(4.3) row 2 column 2 with 1/(2R)", A[i, j] - printed_43(True)[0][i, j])
            elif not same:
                raise AssertionError(f"(4.3) entry {i + 1},{j + 1} differs from the print")
        _require(f"(4.3) right-hand side row {i + 1}", b[i] - b_print[i])
    report.proof("8 of 9 matrix entries and the right-hand side equal the print (with (4.2) for f, g, h)")
    report.proof("row 2, column 2 is -(2 g2/R + 1/(2R)), not the printed -(2 g2/R + 1/R)")
    err = _check_system_by_quadrature()
    report.check("with (B, P, C) from the derived system, quadrature of the pressure (2.12) "
                 "reproduces B and P of (2.13); the printed matrix misses P by a relative "
                 f"{mp.nstr(err, 1)} at a = 0.5", mp.mpf(0), 1)
    report.erratum("(4.3), row 2, column 2",
                   r"$-\left(\frac{2g_2}{R} + \frac{1}{R}\right)$",
                   r"$-\left(\frac{2g_2}{R} + \frac{1}{2R}\right)$ (from $-P/(2R)$ on the right of (2.15b))",
                   "sympy.linear_eq_to_matrix of (2.15b); an mpmath quadrature of (2.12) with the "
                   "solution of the printed system does not reproduce P, while (4.4), which the "
                   "paper derives from (4.3), matches the corrected system")


def _numeric_point():
    return {a: sp.Rational(1, 2), R: sp.Rational(3, 2), Delta: sp.Rational(1, 50), beta: sp.Rational(7, 5),
            theta: sp.Rational(6, 5), zeta: sp.Rational(1, 20)}


def _check_system_by_quadrature():
    """Quadrature of the pressure with the solved (B, P, C): the derived system reproduces (2.13).

    Returns the relative miss in P of the printed (4.3); raises if the derived system misses.
    """
    point = _numeric_point()
    misses = []
    for half in (True, False):
        A, b = printed_43(row2_col2_half=half)
        sol = A.subs(point).LUsolve(b.subs(point))
        vals = {B: sol[0], P: sol[1], C: sol[2]}
        vals.update({k_: v.subs(vals).subs(point) for k_, v in constants_26(theta).items()})
        p_x = (pressure.p_bounded + pressure.p_unbounded).subs(pressure.S, pressure._Ssym)
        p_fn = checks.mp_function(p_x.subs(vals).subs(point), (x, pressure._Ssym))
        with mp.workdps(checks.DPS):
            av = mp.mpf(1) / 2
            chord = lambda w: (lambda u: p_fn(av * mp.sin(u), av * mp.cos(u)) * w(av * mp.sin(u)) * av * mp.cos(u))
            B_q = 2 * mp.quad(chord(lambda s_: 1 / (1 + s_**2)), [-mp.pi / 2, 0, mp.pi / 2])
            P_q = 2 * point[R] * mp.quad(chord(lambda s_: (1 - s_**2) / (1 + s_**2)**2), [-mp.pi / 2, 0, mp.pi / 2])
            B_v, P_v = mp.mpf(sp.N(sol[0], 60)), mp.mpf(sp.N(sol[1], 60))
            misses.append(max(abs(B_q - B_v) / abs(B_v), abs(P_q - P_v) / abs(P_v)))
    if misses[0] > mp.mpf(10) ** (-checks.DIGITS):
        raise AssertionError(f"derived system fails the quadrature check: {misses[0]}")
    return misses[1]


def _compare_inverse(report, sol):
    for name, got, printed, eq in (("P", sol[1], P_44, "(4.4)"), ("B", sol[0], B_45a, "(4.5a)"),
                                   ("C", sol[2], C_45b, "(4.5b)")):
        report.result(f"{name} in closed form {eq}", sp.Eq(sp.Symbol(name), printed), MATCHES,
                      "LU solution of the derived system")
        _require(eq, got - printed)
        report.proof(f"solution minus the printed {eq} reduces to 0 modulo E^2 = 1 + a^2")


def _stable_kernels(report, sol):
    forms = stable_forms()
    in_t = {theta: 1 / inv_theta}
    targets = {"P": sol[1], "B": sol[0], "C": sol[2]}
    cvals = {k_: v.subs({B: sol[0], P: sol[1]}) for k_, v in constants_26(theta).items()}
    targets.update({"c0": cvals[c0], "c1": cvals[c1], "r0": pressure.r0.subs(cvals).subs(C, sol[2])})
    report.result("Stable forms for float64 (B, P, C, c0, c1, r0)",
                  r"\\".join(f"{k_} = {sp.latex(v)}" for k_, v in forms.items()), NEW,
                  "written in 1/vartheta, log1p(a^2) and a^2/(sqrt(1+a^2)+1) for sqrt(1+a^2)-1")
    for name, target in targets.items():
        _require(f"stable form of {name}", forms[name] - target.subs(in_t))
    report.proof("each stable form minus the LU solution reduces to 0 (vartheta = 1/inv_theta)")
    report.result("r0 from the Griffith condition", sp.Eq(sp.Symbol("r_0"), forms["r0"]), NEW,
                  "the unbounded coefficient depends on the adhesion only")
    P_star = normalised_load()
    report.result("Normalised load P* of section 6", sp.Eq(sp.Symbol("P^*"), P_star), MATCHES,
                  "P beta/(4 pi Delta vartheta) with zeta* = 4 pi Delta vartheta M/beta")
    _require("P* vs (4.4)", P_star - (P_44 * beta / (4 * sp.pi * Delta * theta)).subs(
        zeta, 4 * sp.pi * Delta * theta * M / beta))
    report.proof("equals (4.4) times beta/(4 pi Delta vartheta)")
    return _kernels(forms, P_star)


def stress_intensity_forms(C_, c0_, c1_):
    """K* of (3.4) with r0 of (2.12) from the constants (C, c0, c1), and G* = (pi/4) A K*^2 (3.5).

    G* is written in the output K (a symbol named like it) so that it never squares an intermediate that
    overflows where K itself is finite (huge a)."""
    K = -sp.sqrt(4 * sp.pi * R) / E / sp.sqrt(2 * a) * (4 / (R * beta) * Em1 * (c0_ - c1_ / E) + C_ / sp.pi)
    return K, sp.pi / 4 * beta / (2 * sp.pi) * sp.Symbol("K", real=True)**2


def _kernels(forms, P_star):
    state = Kernel("load_state", tuple((n, forms[n]) for n in ("P", "B", "C", "c0", "c1", "r0")),
                   "Equilibrium at contact parameter a = tan(eps/2): load P (4.4) [N/m], B = int N dphi (4.5a)\n"
                   "[N/m], C = int p dx (4.5b) [N/m], c0, c1 of (2.6) [m], r0 of (2.12) [N/m^2].\n"
                   "Delta [m], R [m], beta = beta* [1/Pa], inv_theta = 1/vartheta, zeta = sqrt(2wR/A) [N/m^(1/2)].",
                   forms=("into",))
    load = Kernel("normalised_load", (("P_star", P_star),),
                  "P* = P beta*/(4 pi Delta vartheta) of section 6 as a function of a, M and vartheta.")
    bounded, unbounded = pressure.pressure_in_angle()
    subs = {c0: forms["c0"], c1: forms["c1"]}
    N_b = bounded.subs(subs)
    N_u = forms["r0"] * sp.cos(phi / 2) / (E * sp.sqrt(sp.sin(sp.atan(a) - phi / 2) * sp.sin(sp.atan(a) + phi / 2)))
    press = Kernel("pressure", (("N_bounded", N_b), ("N_unbounded", N_u)),
                   "Contact pressure N(phi) of (5.4) [Pa] for |phi| < eps, split into the bounded part and the\n"
                   "unbounded (r0) part; the total is their sum.", array_args=("phi",), forms=("into",))
    K, G_release = stress_intensity_forms(*sp.symbols("C c0 c1", real=True))
    sif = Kernel("stress_intensity", (("K", K), ("G_release", G_release)),
                 "Stress-intensity factor K* (3.4) [Pa m^(1/2)] and energy release rate G* = (pi/4) A K*^2 (3.5)\n"
                 "[J/m^2] from the constants c0, c1 [m] and C [N/m] of a pressure solution.",
                 array_args=("C", "a", "c0", "c1"))
    return [state, load, press, sif]
