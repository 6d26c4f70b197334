"""Sections 6-8: derivatives along the equilibrium curves, and the energy release rate off them.

* dP/da and d delta/da: sympy derivatives of the closed forms of derive.load and derive.approach.
* G at fixed load: rows (2.15a), (2.15b) of the system are solved for (B, C) with P given (the
  Griffith row (3.6b) dropped), r0 and K* follow from (2.12), (3.4), and G = (pi/4) A K*^2 (3.5);
  dG/da|_P is its sympy derivative, evaluated on the equilibrium P = P(a).
* G at fixed grip: the same with P eliminated in favour of the approach delta of (5.3); and at fixed
  work-conjugate approach delta_work = delta + P/(8 pi G_I) (derive.green), the grip a testing machine
  holds when the load is spread over the pin (issue 10, item 4).  At fixed a, delta_work = delta + c P
  with c = 1/(8 pi G_I) >= 0 is the paper's delta driven through a spring of compliance c: its
  stability lies between the paper's fixed grip (c = 0) and fixed load (c = inf).

Stability (section 8.3): the contact grows when G < w and shrinks when G > w (G is the energy
release rate of the exterior crack, whose advance shrinks the contact), so an equilibrium is
stable at fixed load when dG/da|_P > 0 and at fixed grip when dG/da|_delta > 0.  Along the
equilibrium G = w, so dG/da|_P = -(dG/dP)|_a dP/da, and dK/dP at fixed a is proportional to minus
the denominator of (4.4): stable where dP/da > 0 below a_crit and where dP/da < 0 above it (proved
below; the paper's section 8.3 says otherwise for the super-critical branch, see the errata).

Dimensionless kernels use (a, m, inv_theta, gb): m = M vartheta = zeta* beta/(4 pi Delta) (M_R* of
(7.6) when vartheta = inf), gb = (1/G_I)/beta*; loads as p = P beta/(4 pi Delta) (= vartheta P*,
and = P_R* of (7.6)).  Every derivative of G is divided by w.
"""
import mpmath as mp
import sympy as sp
from sympy.polys.matrices import DomainMatrix

from . import approach, checks, green, load, pressure
from .kernel import Kernel
from .report import NEW
from .symbols import (B, C, Delta, E, P, R, a, beta, c0, c1, inv_G_I, inv_theta, zeta)

m = sp.Symbol("m", nonnegative=True)       # M vartheta = zeta beta/(4 pi Delta)
gb = sp.Symbol("gb", nonnegative=True)     # inv_G_I / beta
delta = sp.Symbol("delta", real=True)      # prescribed approach (fixed grip)
Lsym = sp.Symbol("L_s", real=True)

A_ = beta / (2 * sp.pi)
w_ = zeta**2 * A_ / (2 * R)                # zeta* = sqrt(2 w R/A)


def _rat(expr):
    """Cancel as a rational function of (E, L, ...) with E^2 = 1 + a^2 (derive.load.to_EL)."""
    return load.from_EL(sp.factor(load.to_EL(expr)))


def _without_griffith():
    """(B, C) from (2.15a), (2.15b) with P given; returns (B, C, c0, c1, r0) in (a, P, Delta, R, beta, inv_theta)."""
    cons = load.constants_26(1 / inv_theta)
    eqs = [sp.expand(e.subs(cons)) for e in load.system_equations()[:2]]
    Amat, b = sp.linear_eq_to_matrix(eqs, [B, C])
    aug = DomainMatrix.from_Matrix(Amat.applyfunc(load.to_EL).row_join(b.applyfunc(load.to_EL))).to_field()
    sol = aug[:, :2].lu_solve(aug[:, 2:]).to_Matrix()
    Bs, Cs = (load.from_EL(sp.factor(e)) for e in sol)
    c0s = _rat(cons[c0].subs(B, Bs))
    c1s = cons[c1]
    r0s = _rat(pressure.r0.subs({c0: c0s, c1: c1s, C: Cs}))
    return Bs, Cs, c0s, c1s, r0s


def fixed_load_K():
    """K*(a; P): the stress intensity of the pressure solution with load P and no Griffith condition."""
    *_, r0s = _without_griffith()
    return load.stress_intensity(r0s)


def fixed_grip_K(compliance=0):
    """K*(a; delta): as fixed_load_K with P eliminated through the approach (5.3).

    At fixed a, K* and delta are both linear in (P, Delta): solve delta(P) + compliance P = delta for P
    (compliance = 0: the paper's delta; green.work_shift(1, inv_G_I): the work-conjugate approach).
    """
    Bs, Cs, c0s, c1s, r0s = _without_griffith()
    d53, r0sym = approach.approach_53()
    d_of_P = d53.subs(approach.Ls, Lsym).subs(r0sym, r0s).subs({B: Bs, c0: c0s, c1: c1s, C: Cs})
    uP = _rat(sp.diff(d_of_P, P))
    rest = _rat(d_of_P.subs(P, 0))
    K = load.stress_intensity(r0s)
    kP, kD = sp.diff(K, P), K.subs(P, 0)
    return kP * (delta - rest) / (uP + compliance) + kD


def _equilibrium():
    forms = load.solution()
    dD, dz = approach.d_Delta(), approach.d_zeta()
    return forms["P"], Delta * dD + zeta * dz


def _dimensionless(expr):
    """Substitute zeta = 4 pi Delta m/beta and inv_G_I = gb beta; R, Delta, beta must drop out."""
    out = expr.subs(inv_G_I, gb * beta).subs(zeta, 4 * sp.pi * Delta * m / beta)
    return out


def _drop_scales(report, star):
    """Check at 50 digits that R, Delta, beta do not matter, then set them to 1."""
    scales = (R, Delta, beta)
    names = list(star)
    f = checks.mp_function([star[k] for k in names], (a, m, inv_theta, gb) + scales)
    pairs = []
    with mp.workdps(checks.DPS):
        for av in (mp.mpf("0.03"), mp.mpf("0.5"), mp.mpf("1.2"), mp.mpf(4)):
            for tv in (mp.mpf(0), mp.mpf("0.7")):
                pt = (av, mp.mpf("0.35"), tv, mp.mpf("0.4"))
                ref = f(*pt, 1, 1, 1)
                got = f(*pt, mp.mpf("2.5"), mp.mpf("0.013"), mp.mpf("0.37"))
                pairs += list(zip(ref, got))
    report.result("Dimensionless equilibrium and slopes", sp.Symbol("p(a; m, 1/vartheta, g/beta)"), NEW,
                  "p = P beta*/(4 pi Delta) = vartheta P*, delta/Delta, their a-derivatives and (1/w) dG/da "
                  "with zeta* = 4 pi Delta m/beta*, m = M vartheta, 1/G_I = gb beta*")
    report.check("independent of R, Delta, beta* (values at (1, 1, 1) vs (2.5, 0.013, 0.37))",
                 checks.assert_close("scale independence", pairs), len(pairs))
    return {k: v.subs({R: 1, Delta: 1, beta: 1}) for k, v in star.items()}


def derive(report):
    report.section("Derivatives along the equilibria, stability (sections 6, 8.2, 8.3)")
    P_eq, d_eq = _equilibrium()
    dP = sp.diff(P_eq, a)
    dd = sp.diff(d_eq, a)
    report.result("Slope of the load curve dP/da", sp.Symbol("dP/da"), NEW,
                  "sympy derivative of the stable form of (4.4) (derive.load)")
    report.result("Slope of the approach curve d delta/da", sp.Symbol(r"d\delta/da"), NEW,
                  "sympy derivative of the closed-form approach (derive.approach)")

    K_P = fixed_load_K()
    L_ = sp.log(a / E)
    K_d = fixed_grip_K().subs(Lsym, L_)
    K_w = fixed_grip_K(green.work_shift(1, inv_G_I)).subs(Lsym, L_)
    dw_eq = d_eq + green.work_shift(P_eq, inv_G_I)            # work-conjugate approach on the equilibrium
    G_P = sp.pi / 4 * A_ * K_P**2
    G_d = sp.pi / 4 * A_ * K_d**2
    G_w = sp.pi / 4 * A_ * K_w**2
    dG_P = sp.diff(G_P, a).subs(P, P_eq) / w_
    dG_d = sp.diff(G_d, a).subs(delta, d_eq) / w_
    dG_w = sp.diff(G_w, a).subs(delta, dw_eq) / w_
    dG_dP = sp.diff(G_P, P).subs(P, P_eq) / w_
    report.result("Energy release rate at fixed load", sp.Eq(sp.Symbol("K^*(a; P)"), K_P), NEW,
                  "(2.15a), (2.15b) solved for (B, C) at given P (Griffith row dropped); r0 from (2.12), "
                  "K* from (3.4), G = (pi/4) A K*^2 (3.5); dG/da|_P by sympy differentiation")
    report.result("Energy release rate at fixed grip", sp.Symbol(r"K^*(a; \delta)"), NEW,
                  "as at fixed load, with P eliminated through the approach (5.3) (K* and delta are "
                  "linear in (P, Delta) at fixed a); dG/da|_delta by sympy differentiation")
    report.result("Energy release rate at fixed work-conjugate approach", sp.Symbol(r"K^*(a; \delta_{work})"),
                  NEW, "as at fixed grip, with P eliminated through delta + P/(8 pi G_I) = delta_work "
                  "(derive.green); dG/da|_delta_work by sympy differentiation")
    _check(report, K_P, K_d, K_w, dG_P, dG_d, dG_w, dG_dP, dP, dd)
    dK_dP = _stability_sign(report, K_P)
    dG_dP_proved = 2 * dK_dP / sp.sqrt(4 * w_ / (sp.pi * A_))     # (1/w) dG/dP = 2 (dK/dP)/K, K = K_Griffith
    _check_release_form(report, dG_dP, dG_dP_proved)

    ks = [Kernel("load_slopes", (("dP_da", dP), ("ddelta_da", dd)),
                 "dP/da [N/m] and d delta/da [m] along the equilibrium curve (sympy derivatives of (4.4)\n"
                 "and of the approach (5.8)).  Same arguments as load_state and approach.")]
    p = P_eq * beta / (4 * sp.pi * Delta)
    dn = d_eq / Delta
    dwn = dw_eq / Delta
    star = {"p": p, "dp_da": sp.diff(p, a), "delta_over_Delta": dn, "ddelta_da": sp.diff(dn, a),
            "delta_work_over_Delta": dwn, "ddelta_work_da": sp.diff(dwn, a),
            "dG_dp": dG_dP_proved * 4 * sp.pi * Delta / beta}
    star = {k: _dimensionless(v) for k, v in star.items()}
    # at fixed a the state is affine in m (derive.confined): the fixed-arc compliance of the paper's delta
    star["ddelta_dp"] = sp.diff(star["delta_over_Delta"], m) / sp.diff(star["p"], m)
    rates = {"dG_da_P": dG_P, "dG_da_delta": dG_d, "dG_da_delta_work": dG_w}
    star = _drop_scales(report, star)
    _chain_rule(report, star, {k: _dimensionless(v).subs({R: 1, Delta: 1, beta: 1}) for k, v in rates.items()})
    ks.append(Kernel("equilibrium_star",
                     tuple((k, star[k]) for k in ("p", "dp_da", "delta_over_Delta", "ddelta_da",
                                                  "delta_work_over_Delta", "ddelta_work_da", "dG_dp",
                                                  "ddelta_dp")),
                     "Dimensionless equilibrium at contact parameter a: p = P beta*/(4 pi Delta) (= vartheta P*,\n"
                     "= P_R* of (7.6)), dp/da, delta/Delta, d(delta/Delta)/da, delta_work/Delta and its slope\n"
                     "(work-conjugate approach), and at fixed a: (1/w) dG/dp and d(delta/Delta)/dp.  The release\n"
                     "rates along a follow by the chain rule (jkrcyl.numerics.kernels: dG/da|_X = -(dG/dp)\n"
                     "(dX/da)/(dX/dp)), which the derivation checks against the direct derivatives.\n"
                     "m = M vartheta (= M_R* for vartheta = inf), inv_theta = 1/vartheta, gb = (1/G_I)/beta*.",
                     forms=("into",)))
    return ks


def _check_release_form(report, dG_dP, proved):
    """The proved closed form of (1/w) dG/dP at fixed a equals sympy's derivative on the equilibrium."""
    f = checks.mp_function([dG_dP, proved], (a, R, Delta, beta, inv_theta, zeta, inv_G_I))
    pairs = []
    with mp.workdps(checks.DPS):
        for tv in (mp.mpf(1), mp.mpf("0.3"), mp.mpf(0)):
            for av in (mp.mpf("0.01"), mp.mpf("0.4"), mp.mpf("1.3"), mp.mpf(6)):
                pairs.append(tuple(f(av, mp.mpf("1.5"), mp.mpf("0.01"), mp.mpf("1.4"), tv, mp.mpf("0.02"),
                                     mp.mpf("0.5"))))
    report.result("Release rate per unit load at fixed contact", sp.Eq(sp.Symbol(r"(1/w)\,\partial G/\partial P|_a"),
                  proved), NEW, "2 (dK*/dP)/K* on the equilibrium with the proved dK*/dP (no cancellation)")
    report.check("against sympy's derivative of G(a; P) on the equilibrium", checks.assert_close("dG/dP", pairs),
                 len(pairs))


def _chain_rule(report, star, rates):
    """On the equilibrium dG/da|_X = -(dG/dp)|_a (dX/da)/(dX/dp)|_a for X = p, delta, delta_work (50 digits)."""
    forms = {"dG_da_P": -star["dG_dp"] * star["dp_da"],
             "dG_da_delta": -star["dG_dp"] * star["ddelta_da"] / star["ddelta_dp"],
             "dG_da_delta_work": -star["dG_dp"] * star["ddelta_work_da"] / (star["ddelta_dp"] + gb / 2)}
    names = list(forms)
    f = checks.mp_function([forms[k] for k in names] + [rates[k] for k in names], (a, m, inv_theta, gb))
    pairs = []
    with mp.workdps(checks.DPS):
        for av in (mp.mpf("0.02"), mp.mpf("0.5"), mp.mpf("1.2"), mp.mpf(4)):
            for tv, gv in ((mp.mpf(0), mp.mpf(1)), (mp.mpf("0.7"), mp.mpf("0.4")), (mp.mpf(2), mp.mpf("0.2"))):
                v = f(av, mp.mpf("0.35"), tv, gv)
                pairs += list(zip(v[:3], v[3:]))
    report.result("Release rates along a by the chain rule", sp.Symbol(r"dG/da|_X = -(\partial G/\partial p)"
                  r"(dX/da)/(\partial X/\partial p)"), NEW,
                  "X = p, delta/Delta, delta_work/Delta = delta/Delta + (gb/2) p; G = w on the equilibrium, so "
                  "0 = dG/da|_X + (dG/dX)|_a X'(a); (dX/dp)|_a = d(delta/Delta)/dp (+ gb/2): the fixed-arc "
                  "compliance, affine in m")
    report.check("chain-rule forms against the direct sympy derivatives dG/da|_P, |_delta, |_delta_work",
                 checks.assert_close("chain rule", pairs), len(pairs))


def _stability_sign(report, K_P):
    """dK/dP at fixed a is proportional to -(2 - t (L + 2 a^4)): it changes sign at a_crit."""
    dK_dP = sp.diff(K_P, P)
    D_t = 2 - inv_theta * (sp.log(1 + a**2) + 2 * a**4)
    ratio = dK_dP / D_t
    expected = -sp.sqrt(2) / (2 * sp.sqrt(sp.pi * R * a) * (1 + a**2) * (inv_theta * (a**2 - sp.log(1 + a**2)) + 2))
    if not load.is_zero(ratio - expected):
        raise AssertionError("derive proof failed: dK/dP proportional to -D")
    report.result("Fixed-load stability changes sign at a_crit",
                  sp.Eq(sp.Symbol(r"\partial K^*/\partial P|_a"), expected * sp.Symbol("D_t")), NEW,
                  "D_t = 2 - (L + 2a^4)/vartheta, the denominator of (4.4) over vartheta")
    report.proof("dK*/dP at fixed a = -sqrt(2) D_t/(2 sqrt(pi R a) E^2 (2 + (a^2 - L)/vartheta)); with "
                 "dG/da|_P = -(dG/dP) dP/da on the equilibrium (K* > 0), fixed-load stability (dG/da|_P > 0) "
                 "is dP/da > 0 for a < a_crit and dP/da < 0 for a > a_crit")
    report.erratum("Section 8.3 and Fig. 11b, the super-critical branch",
                   "'There is also a corresponding unstable branch at smaller contact angles' and "
                   "'at M = 0.3, there are stable super-critical contact states'",
                   "above a_crit, equilibria are stable at fixed load where dP*/da < 0: the branch at "
                   "smaller contact angles (a_crit < a < a at the P* minimum) is the stable one and the "
                   "branch beyond the minimum is unstable; at M = 0.3 (vartheta = 1) P* increases "
                   "monotonically on the super-critical branch, so none of its states is stable at fixed load",
                   "dK*/dP proportional to -D_t (proved above); G of (3.4)-(3.5) equals the derivative of "
                   "U - P delta with respect to the contact length, so dG/da|_P > 0 is the energy minimum "
                   "(tests/test_equilibria.py, test_release_rate_is_the_energy_derivative, test_fig11_claims)")
    report.erratum("Section 8.1 and Fig. 10, half-plane vs cylinder adherence",
                   "'the half-plane adhesive solution consistently under predicts the value of the adherence force'",
                   "true wherever the cylinder detaches under load, i.e. while its lowest fixed-load P* minimum "
                   "is sub-critical (M < 0.3915 at vartheta = 1, M < 0.5651 at vartheta = 0.5); above that the "
                   "lowest minimum is super-critical, a fold where the contact grows round into full contact "
                   "(erratum 'Sections 6 and 8.3'), not an adherence force, and beyond M = 0.4459 (vartheta = 1), "
                   "0.6113 (vartheta = 0.5) it lies above the Barquins force: there the curves of Fig. 10 cross",
                   "tests/test_equilibria.py, test_half_plane_adherence_vs_cylinder_fig10 (the crossings: minima "
                   "of P* found with the emitted slope kernels, to full double precision); tests/test_figures.py, "
                   "test_fig10_ends_detachment_where_the_lowest_minimum_turns_super_critical (the detachment "
                   "limits from the printed (4.4) at 30 digits: where the residue of P* at a_crit vanishes, "
                   "vartheta = 0.5, or a lower super-critical minimum is born, vartheta = 1)")
    return expected * D_t


def _check(report, K_P, K_d, K_w, dG_P, dG_d, dG_w, dG_dP, dP, dd):
    """Numbers at 50 digits: K on the equilibrium is the Griffith value, the slopes match mpmath
    differentiation of the closed forms, and dG/da|_P = -dG/dP dP/da on the equilibrium."""
    P_eq, d_eq = _equilibrium()
    syms = (a, R, Delta, beta, inv_theta, zeta, inv_G_I)
    dw_eq = d_eq + green.work_shift(P_eq, inv_G_I)
    f = checks.mp_function([K_P.subs(P, P_eq), K_d.subs(delta, d_eq), K_w.subs(delta, dw_eq), dG_P, dG_d, dG_w,
                            dG_dP, dP, dd, P_eq, d_eq], syms)
    fKP = checks.mp_function(K_P, (a, R, Delta, beta, inv_theta, P))
    fKd = checks.mp_function(K_d, (a, R, Delta, beta, inv_theta, inv_G_I, delta))
    fKw = checks.mp_function(K_w, (a, R, Delta, beta, inv_theta, inv_G_I, delta))
    fP = checks.mp_function(P_eq, syms)
    fd = checks.mp_function(d_eq, syms)
    griffith, slopes, chain = [], [], []
    with mp.workdps(checks.DPS):
        Rv, Dv, bv = mp.mpf("1.5"), mp.mpf("0.01"), mp.mpf("1.4")
        for tv, gv in ((mp.mpf(1), mp.mpf("0.5")), (mp.mpf("0.25"), mp.mpf("0.3")), (mp.mpf(0), mp.mpf(1))):
            for zv in (mp.mpf("0.003"), mp.mpf("0.02")):
                wv = zv**2 * bv / (4 * mp.pi * Rv)
                Keq = mp.sqrt(4 * wv / (mp.pi * bv / (2 * mp.pi)))
                for av in (mp.mpf("0.05"), mp.mpf("0.4"), mp.mpf("1.3"), mp.mpf(3)):
                    vals = f(av, Rv, Dv, bv, tv, zv, gv)
                    KP, Kd, Kw, gP, gd, gw, gdP, dPv, ddv, Pv, dv = vals
                    griffith += [(KP, Keq), (Kd, Keq), (Kw, Keq)]
                    args = (Rv, Dv, bv, tv, zv, gv)
                    slopes.append((dPv, mp.diff(lambda s: fP(s, *args), av)))
                    slopes.append((ddv, mp.diff(lambda s: fd(s, *args), av)))
                    G = lambda K: mp.pi / 4 * bv / (2 * mp.pi) * K**2 / wv
                    slopes.append((gP, mp.diff(lambda s: G(fKP(s, Rv, Dv, bv, tv, Pv)), av)))
                    slopes.append((gd, mp.diff(lambda s: G(fKd(s, Rv, Dv, bv, tv, gv, dv)), av)))
                    dwv = dv + Pv * gv / (8 * mp.pi)          # delta_work = delta + P/(8 pi G_I), typed here
                    slopes.append((gw, mp.diff(lambda s: G(fKw(s, Rv, Dv, bv, tv, gv, dwv)), av)))
                    chain.append((gP, -gdP * dPv))
    report.check("K*(a; P(a)), K*(a; delta(a)) and K*(a; delta_work(a)) equal the Griffith value sqrt(4w/(pi A)) "
                 "on the equilibrium",
                 checks.assert_close("Griffith", griffith), len(griffith))
    report.check("dP/da, d delta/da, dG/da|_P, dG/da|_delta, dG/da|_delta_work vs mpmath numerical "
                 "differentiation of the "
                 "undifferentiated closed forms", checks.assert_close("slopes", slopes), len(slopes))
    report.check("dG/da|_P = -(dG/dP)|_a dP/da on the equilibrium (stability changes where dP/da = 0)",
                 checks.assert_close("chain rule", chain), len(chain))
