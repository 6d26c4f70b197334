"""Cohesive-zone (Maugis-Dugdale) adhesion of the pin in the hole (issue 19): what is closed form.

Normalisation of jkrcyl.numerics.arcs: nu = N R beta*/(4 pi Delta) (N compressive positive), p = int nu cos(phi)
dphi = P beta*/(4 pi Delta), delta/Delta; on the contact arcs (5.2) with the alpha* terms reads

    (delta/Delta) cos(phi) - (1 - cos(phi)) = - int nu(psi) K(phi - psi) dpsi,
    K(t) = cos t log(2 - 2 cos t) + k1 cos t + k0 + ar (pi sign(t) sin t - t sin t)      (|t| < 2 pi),

and the gap outside is h/Delta = (1 - cos phi) - (delta/Delta) cos phi - int nu K dpsi.  The Dugdale law puts
nu = -s0, s0 = sigma0 R beta*/(4 pi Delta), wherever 0 < h <= h0.

Derived here:
1. The antiderivative F of K (F' = K, proved by differentiation on both sides of t = 0), so the displacement of a
   uniform traction on any arc [lo, hi] is elementary: int_lo^hi K(phi - psi) dpsi = F(phi - lo) - F(phi - hi).
   The log part is written 2 sin t log|2 sin(t/2)| (no cancellation in 2 - 2 cos t, 0 at t = 0).
2. The zone's load and width: int cos = sin(hi) - sin(lo), int 1 = hi - lo.
3. The scales: s0 h0/Delta = m^2 (w = sigma0 h0, m^2 = w beta* R/(4 pi Delta^2)); the transition parameter
   lambda = 4 sigma0/(pi^2 E*^2 w/R_eff)^(1/3), E* = 4/beta*, R_eff = R R_D/Delta, is
   lambda = 4 s0 (R_D/R)^(1/3)/m^(2/3) (and back); Baney-Hui's abar and Pbar in the normalised variables.
4. The half-plane limit: with phi = l xi, nu = l n, s0 = l s, delta/Delta = l^2 d, m = l^(3/2) mh the
   equations tend (l -> 0) to the cylinder-on-a-flat problem 2 int n log|xi - eta| = xi^2/2 - D (kernel series
   proved), whose Maugis-Dugdale solution (Hertz plus the arctan density) gives p = eps^2/4 - 2 s0 sqrt(c^2 - eps^2)
   and the opening at the zone end h(c) = (eps^2/2)(M sqrt(M^2-1) - acosh M) + 4 s0 eps (sqrt(M^2-1) acosh M
   - M log M), M = c/eps (mpmath, 30 digits); with the scales of 3 these are Baney and Hui's (1997) equations
   (proved symbolically).

What stays numerical (jkrcyl.numerics.cohesive): the contact density for finite contacts (collocation), the zone
ends (roots of h(c) = h0), and everything that depends on them.
"""
import mpmath as mp
import sympy as sp

from . import checks
from .kernel import Kernel
from .report import NEW

t = sp.Symbol("t", real=True)
tp = sp.Symbol("t", positive=True)
k0, k1, ar = sp.symbols("k0 k1 ar", real=True)
phi_, lo, hi = sp.symbols("phi lo hi", real=True)
m, s0, eps, c = sp.symbols("m s0 eps c", positive=True)
lam, DoR = sp.symbols("lam Delta_over_R", positive=True)
p = sp.Symbol("p", real=True)


def _require(what, expr):
    if sp.simplify(expr) != 0:
        raise AssertionError(f"derive proof failed: {what}")


def kernel(tt):
    """K(t) of the displacement equation (derive/green.py), for 0 < |t| < 2 pi."""
    return (sp.cos(tt) * sp.log(2 - 2 * sp.cos(tt)) + k1 * sp.cos(tt) + k0
            + ar * (sp.pi * sp.sign(tt) * sp.sin(tt) - tt * sp.sin(tt)))


def antiderivative(tt, side=None):
    """F(t) with F' = K: the piecewise form emitted (side=None), or one side's smooth branch (+1, -1)."""
    one_minus_cos = 2 * sp.sin(tt / 2) ** 2
    smooth = -tt - sp.sin(tt) + k1 * sp.sin(tt) + k0 * tt + ar * (-sp.sin(tt) + tt * sp.cos(tt))
    if side is not None:
        return sp.sin(tt) * sp.log(2 - 2 * sp.cos(tt)) + smooth + ar * side * sp.pi * one_minus_cos
    log_part = sp.Piecewise((0, sp.Eq(tt, 0)), (2 * sp.sin(tt) * sp.log(sp.Abs(2 * sp.sin(tt / 2))), True))
    kink = sp.Piecewise((sp.pi * one_minus_cos, tt >= 0), (-sp.pi * one_minus_cos, True))
    return log_part + smooth + ar * kink


# --- 1-2. the displacement and the load of a uniform zone traction -------------------------------------
def zone_integrals(report):
    report.section("Cohesive zone (Maugis-Dugdale; issue 19)")
    for side in (1, -1):
        Fs = antiderivative(t, side)
        Ks = kernel(t).subs(sp.sign(t), side)
        _require(f"F' = K (sign {side})", sp.diff(Fs, t) - Ks)
    # the emitted form equals the smooth branches: log(2 - 2 cos t) = 2 log|2 sin(t/2)|
    _require("2 - 2 cos t = (2 sin(t/2))^2", sp.expand_trig((2 - 2 * sp.cos(2 * t)) - (2 * sp.sin(t)) ** 2))
    report.result("Displacement of a uniform traction on an arc (the Dugdale zone)",
                  r"\int_{lo}^{hi} K(\phi-\psi)\,d\psi = F(\phi - lo) - F(\phi - hi),\quad F(t) = \sin t\log(2-2\cos t)"
                  r" - t - \sin t + k_1\sin t + k_0 t + \frac{\alpha^*}{\beta^*}\big[\pi\,\mathrm{sign}(t)(1-\cos t)"
                  r" - \sin t + t\cos t\big]", NEW,
                  "d/dt[sin t log(2 - 2 cos t)] = cos t log(2 - 2 cos t) + 1 + cos t; the alpha* part integrates "
                  "pi sign(t) sin t - t sin t, continuous at t = 0; valid for |t| < 2 pi (arcs within (-pi, pi])")
    report.proof("F' - K = 0 on t > 0 and on t < 0 (differentiation of each smooth branch, symbolic in k0, k1, "
                 "alpha*/beta*); F is continuous at 0; the emitted log part 2 sin t log|2 sin(t/2)| equals "
                 "sin t log(2 - 2 cos t) (2 - 2 cos t = 4 sin^2(t/2)) and is 0 at t = 0")
    # numerical: the antiderivative against quadrature of the kernel at 30 digits
    Fm = checks.mp_function(antiderivative(t), (t, k0, k1, ar))
    Km = checks.mp_function(kernel(t), (t, k0, k1, ar))
    pairs = []
    with mp.workdps(checks.DPS):
        for (a_, b_), (kk0, kk1, kar) in (((mp.mpf("-0.3"), mp.mpf("1.1")), (mp.mpf("0.5"), mp.mpf("0.4"), 0)),
                                          ((mp.mpf("0.2"), mp.mpf("5.9")), (1, mp.mpf("0.7"), mp.mpf("0.375"))),
                                          ((mp.mpf("-6"), mp.mpf("-0.1")), (mp.mpf("0.2"), 0, mp.mpf("-0.12")))):
            nodes = sorted({a_, b_, mp.mpf(0)} if a_ < 0 < b_ else {a_, b_})
            quad = mp.quad(lambda x: Km(x, kk0, kk1, kar), nodes)
            pairs.append((quad, Fm(b_, kk0, kk1, kar) - Fm(a_, kk0, kk1, kar)))
    report.check("F(b) - F(a) against quadrature of K over (a, b) straddling 0 and reaching |t| ~ 6",
                 checks.assert_close("zone antiderivative", pairs), len(pairs))
    Z = antiderivative(phi_ - lo) - antiderivative(phi_ - hi)
    report.result("Load and width of a zone (the Dugdale traction's share of (2.2))",
                  r"p_{zone} = -s_0\int_{lo}^{hi}\cos\psi\,d\psi = -s_0(\sin hi - \sin lo),\quad "
                  r"B_{zone} = -s_0\,(hi - lo)", NEW, "elementary")
    doc_z = ("Displacement of a unit uniform traction on the arc lo < psi < hi (derive/cohesive.py):\n"
             "int_lo^hi K(phi - psi) dpsi = F(phi - lo) - F(phi - hi), F' = K, -pi <= lo, hi, phi <= pi.\n"
             "K(t) = cos t log(2 - 2 cos t) + k1 cos t + k0 + ar (pi sign(t) sin t - t sin t)\n"
             "(generated/green.py); a Dugdale zone (nu = -s0) adds s0 times this to the gap h/Delta.")
    doc_l = ("Load and width of a unit zone traction on lo < psi < hi: int cos(psi) dpsi and hi - lo\n"
             "(a zone nu = -s0 adds -s0 load to p = P beta*/(4 pi Delta), -s0 width to B = int nu).")
    return [Kernel("zone_displacement", (("Z", Z),), doc_z, array_args=(), extra_args=(k0, k1, ar)),
            Kernel("zone_load", (("load", sp.sin(hi) - sp.sin(lo)), ("width", hi - lo)), doc_l, array_args=())]


# --- 3. scales ----------------------------------------------------------------------------------------
def scales(report):
    """lambda <-> s0 and Baney-Hui's variables, from the physical definitions."""
    w, sig0, R, Delta, bt, a_ = sp.symbols("w sigma0 R Delta beta a", positive=True)
    P_ = sp.Symbol("P", real=True)
    RD = R - Delta
    s0_of = sig0 * R * bt / (4 * sp.pi * Delta)
    m2_of = w * bt * R / (4 * sp.pi * Delta ** 2)
    h0 = w / sig0
    _require("s0 h0/Delta = m^2", s0_of * h0 / Delta - m2_of)
    report.result("The Dugdale scales", r"s_0 = \frac{\sigma_0 R\beta^*}{4\pi\Delta},\quad \frac{h_0}{\Delta} = "
                  r"\frac{m^2}{s_0},\quad m^2 = \frac{w\beta^* R}{4\pi\Delta^2}", NEW,
                  "w = sigma0 h0 (Dugdale); m = M vartheta (M_R* for vartheta = inf), the Griffith edge coefficient "
                  "of JKR is m/pi")
    report.proof("s0 h0/Delta - m^2 = 0 with h0 = w/sigma0")
    E_star, R_eff = 4 / bt, R * RD / Delta
    lam_def = 4 * sig0 / (sp.pi ** 2 * E_star ** 2 * w / R_eff) ** sp.Rational(1, 3)
    sub = {sig0: 4 * sp.pi * Delta * s0 / (R * bt), w: 4 * sp.pi * Delta ** 2 * m ** 2 / (bt * R)}
    lam_norm = 4 * s0 * (1 - DoR) ** sp.Rational(1, 3) / m ** sp.Rational(2, 3)
    got = sp.simplify(sp.powsimp(sp.powdenest(lam_def.subs(sub), force=True), force=True))
    _require("lambda in (m, s0, Delta/R)", sp.simplify((got / lam_norm.subs(DoR, Delta / R)) ** 3 - 1))
    s0_of_lam = sp.solve(sp.Eq(lam, lam_norm), s0)[0]
    _require("s0 of lambda", lam_norm.subs(s0, s0_of_lam) - lam)
    report.result("The transition parameter (Baney-Hui's lambda with R_eff = R R_D/Delta)",
                  r"\lambda = \frac{4\sigma_0}{(\pi^2E^{*2}w/R_{eff})^{1/3}} = \frac{4 s_0}{m^{2/3}}\Big(1 - "
                  r"\frac{\Delta}{R}\Big)^{1/3},\quad s_0 = \frac{\lambda\,m^{2/3}}{4}\Big(1 - \frac{\Delta}{R}"
                  r"\Big)^{-1/3}", NEW, "E* = 4/beta*, R_D = R - Delta; lambda -> inf is JKR (zone -> 0)")
    report.proof("the definition with sigma0, w written through s0, m equals the normalised form (cubes "
                 "compared); the inverse solves it for s0")
    # Baney-Hui: abar = a/[2 (w R_eff^2/(pi E*))^(1/3)], Pbar = P/(pi E* w^2 R_eff)^(1/3), a = R eps
    abar_def = a_ / (2 * (w * R_eff ** 2 / (sp.pi * E_star)) ** sp.Rational(1, 3))
    Pbar_def = P_ / (sp.pi * E_star * w ** 2 * R_eff) ** sp.Rational(1, 3)
    abar_norm = eps / (2 * m ** sp.Rational(2, 3) * (1 - DoR) ** sp.Rational(2, 3))
    Pbar_norm = p / (m ** sp.Rational(4, 3) * (1 - DoR) ** sp.Rational(1, 3))
    sub2 = {a_: R * eps, P_: 4 * sp.pi * Delta * p / bt, w: sub[w]}
    for what, got_, want in (("abar", abar_def, abar_norm), ("Pbar", Pbar_def, Pbar_norm)):
        _require(what, sp.simplify((got_.subs(sub2) / want.subs(DoR, Delta / R)) ** 3 - 1))
    report.result("Baney-Hui's variables in the normalised ones",
                  r"\bar a = \frac{\varepsilon}{2 m^{2/3}(1-\Delta/R)^{2/3}},\quad \bar P = \frac{p}{m^{4/3}"
                  r"(1-\Delta/R)^{1/3}}", NEW, "a = R eps (the half-width on the hole; other choices differ by "
                  "O(eps^2)), P = 4 pi Delta p/beta*")
    report.proof("cubes of the ratios to the definitions simplify to 1")
    doc_l = ("Transition parameter lambda = 4 sigma0/(pi^2 E*^2 w/R_eff)^(1/3) (E* = 4/beta*,\n"
             "R_eff = R R_D/Delta) in the normalised variables: lambda = 4 s0 (1 - Delta/R)^(1/3)/m^(2/3)\n"
             "(derive/cohesive.py).")
    doc_s = ("Zone strength s0 = sigma0 R beta*/(4 pi Delta) of the transition parameter lambda (inverse of\n"
             "transition_parameter): s0 = lambda m^(2/3) (1 - Delta/R)^(-1/3)/4.")
    doc_h = "Range of the Dugdale law h0/Delta = m^2/s0 (w = sigma0 h0)."
    doc_b = ("Baney-Hui's (1997) contact half-width abar and load Pbar from eps (a = R eps) and\n"
             "p = P beta*/(4 pi Delta): abar = eps/(2 m^(2/3) (1 - Delta/R)^(2/3)),\n"
             "Pbar = p/(m^(4/3) (1 - Delta/R)^(1/3)).")
    return [Kernel("transition_parameter", (("lam", lam_norm),), doc_l, array_args=()),
            Kernel("zone_strength", (("s0", s0_of_lam),), doc_s, array_args=()),
            Kernel("zone_range", (("h0_over_Delta", m ** 2 / s0),), doc_h, array_args=()),
            Kernel("baney_hui_variables", (("abar", abar_norm), ("Pbar", Pbar_norm)), doc_b, array_args=())]


# --- 4. the half-plane limit -----------------------------------------------------------------------------
def _half_plane_closed_forms():
    """p and the opening h(c) of the Maugis-Dugdale cylinder on a flat, normalised (kernel 2 log|t|)."""
    M_ = c / eps
    ac = sp.acosh(M_)
    sq = sp.sqrt(M_ ** 2 - 1)
    load = eps ** 2 / 4 - 2 * s0 * sp.sqrt(c ** 2 - eps ** 2)
    hertz = eps ** 2 / 2 * (M_ * sq - ac)
    dugdale = 4 * s0 * eps * (sq * ac - M_ * sp.log(M_))
    return load, hertz, dugdale


def half_plane(report):
    ell, xi, eta = sp.symbols("ell xi eta", positive=True)
    # the kernel at t = ell (xi - eta): 2 log ell + 2 log|xi - eta| + k0 + k1 + O(ell)
    series = sp.series(kernel(tp).subs(sp.sign(tp), 1).subs(tp, ell * xi), ell, 0, 2).removeO()
    _require("kernel series", sp.expand(sp.expand_log(series, force=True)
                                        - (2 * sp.log(ell) + 2 * sp.log(xi) + k0 + k1 + ar * sp.pi * ell * xi)))
    d_ = sp.Symbol("d", real=True)
    rigid = sp.series((ell ** 2 * d_ * sp.cos(ell * xi) - (1 - sp.cos(ell * xi))) / ell ** 2, ell, 0, 2).removeO()
    _require("rigid terms", rigid - (d_ - xi ** 2 / 2))
    report.result("The half-plane limit of the normalised equations",
                  r"\phi = \ell\xi,\ \nu = \ell n,\ s_0 = \ell\hat s,\ \frac{\delta}{\Delta} = \ell^2\hat d,\ "
                  r"m = \ell^{3/2}\hat m:\quad 2\int n(\eta)\log|\xi-\eta|\,d\eta = \frac{\xi^2}{2} - D,\ "
                  r"\frac{h}{\Delta\ell^2} = \frac{\xi^2}{2} - D - 2\int n\log|\xi-\eta|\,d\eta + O(\ell)", NEW,
                  "D = d + (k0 + k1) int n + 2 log(ell) int n: the approach of a half-plane is defined only up to "
                  "such a constant; the range h0/(Delta ell^2) = mh^2/s, lambda, abar, Pbar are invariant")
    report.proof("K(ell t) = 2 log ell + 2 log t + k0 + k1 + (alpha*/beta*) pi ell |t| + O(ell^2 log ell) "
                 "(series); (d ell^2 cos(ell xi) - (1 - cos(ell xi)))/ell^2 = d - xi^2/2 + O(ell^2): the alpha* "
                 "term and the curvature of the hole are O(ell) corrections, the cylinder on a flat is the limit")
    load, hertz, dugdale = _half_plane_closed_forms()
    report.result("Maugis-Dugdale solution of the half-plane limit",
                  r"p = \frac{\varepsilon^2}{4} - 2 s_0\sqrt{c^2-\varepsilon^2},\quad \frac{h(c)}{\Delta} = "
                  r"\frac{\varepsilon^2}{2}\big(M\sqrt{M^2-1} - \cosh^{-1}M\big) + 4 s_0\varepsilon\big("
                  r"\sqrt{M^2-1}\cosh^{-1}M - M\log M\big),\ M = \frac{c}{\varepsilon}", NEW,
                  "density nu = sqrt(eps^2 - phi^2)/(2 pi) - (2 s0/pi) atan(sqrt((c^2 - eps^2)/(eps^2 - phi^2))) on "
                  "the contact (bounded: k = 0, nu -> -s0 at its ends), -s0 on the zones eps < |phi| < c")
    hp = sp.Symbol("phi", positive=True)
    hertz_gap = (hp * sp.sqrt(hp ** 2 - eps ** 2) - eps ** 2 * sp.acosh(hp / eps)) / 2
    _require("Hertz opening antiderivative", sp.diff(hertz_gap, hp) - sp.sqrt(hp ** 2 - eps ** 2))
    report.proof("the Hertz opening (1/2)(phi sqrt(phi^2 - eps^2) - eps^2 acosh(phi/eps)) has the derivative "
                 "sqrt(phi^2 - eps^2), the gap slope outside a Hertz contact")
    report.check("the density solves the contact equation (principal value 2 PV int nu/(phi - psi) = phi at "
                  "phi/eps = 0.3, 0.8), its load is p, and the opening from the log potential "
                  "(c^2 - eps^2)/2 - 2 int nu [log|c - psi| - log|eps - psi|] dpsi is h(c)",
                  checks.assert_close("half-plane Maugis-Dugdale", _half_plane_pairs(load, hertz + dugdale)), 12)
    # Baney and Hui (1997), as printed in issue 19
    Mb = sp.Symbol("M_BH", positive=True)
    abar = eps / (2 * m ** sp.Rational(2, 3))
    lamb = 4 * s0 / m ** sp.Rational(2, 3)
    sq, ac = sp.sqrt(Mb ** 2 - 1), sp.acosh(Mb)
    bh_closure = lamb * abar ** 2 / 2 * (Mb * sq - ac) + lamb ** 2 * abar / 2 * (sq * ac - Mb * sp.log(Mb))
    bh_load = m ** sp.Rational(4, 3) * (abar ** 2 - lamb * abar * sq)
    ours = ((hertz + dugdale) * s0 / m ** 2).subs(c, Mb * eps)
    _require("Baney-Hui closure", sp.expand(bh_closure - ours))
    _require("Baney-Hui load", sp.simplify(bh_load - load.subs(c, Mb * eps)))
    report.result("The half-plane limit is Baney and Hui's (1997) cylinder on a flat",
                  r"\frac{\lambda\bar a^2}{2}\big[m\sqrt{m^2-1} - \ln(m+\sqrt{m^2-1})\big] + \frac{\lambda^2\bar a}"
                  r"{2}\big[\sqrt{m^2-1}\ln(m+\sqrt{m^2-1}) - m\ln m\big] = 1,\quad \bar P = \bar a^2 - "
                  r"\lambda\bar a\sqrt{m^2-1}", NEW,
                  "Baney-Hui's m is c/eps; with abar = eps/(2 m^(2/3)), lambda = 4 s0/m^(2/3), Pbar = p/m^(4/3) "
                  "(Delta/R -> 0) the closure is (s0/m^2) h(c) = 1, i.e. h(c) = h0, and Pbar is p")
    report.proof("Baney-Hui's closure minus (s0/m^2) h(c) and their load times m^(4/3) minus p expand to 0")
    report.result("What is closed form and what is numerical (jkrcyl.numerics.cohesive*)",
                  r"\text{closed: zone displacement and load, scales, contactless states, half-plane limit, "
                  r"dE/dc = 2(s_0 h(c) - m^2); numerical: contact density, zone ends, branch, slopes, pull-off}",
                  NEW,
                  "closed form: the displacement and the load of every Dugdale zone (any arc, any alpha*), the "
                  "states without contact up to the root of h = h0 at a zone end (the approach is linear), "
                  "lambda <-> s0 <-> h0, the half-plane limit (Baney-Hui: its closure and load; its pull-off is a "
                  "1-D minimisation over them, jkrcyl.numerics.cohesive_half_plane), the affine dependence of "
                  "every state on the approach at a fixed contact and zone (k, p, B, h(c)), the energy identity "
                  "of the zone end: with the zone |phi| < c held, the minimum of the elastic plus interface "
                  "energy has dE/dc = 2 (s0 h(c) - m^2) (envelope theorem; the stability rule of "
                  "jkrcyl.model.cohesive is its second derivative, a Schur complement). Numerical: the contact "
                  "density of a finite contact (the Gauss-Chebyshev collocation of jkrcyl.numerics.arcs with the "
                  "zone displacement as a third right-hand side; spectral, at the rate of the Bernstein ellipse "
                  "through the zone end c/eps), the approach from k = 0 (linear), the zone ends from h = h0 "
                  "(scalar roots), the branch as a 1-D family (pseudo-arclength continuation in "
                  "(log eps, log(c - eps)): it turns back in eps and in c), the per-point tangent slopes and "
                  "the stability derivatives (central differences in eps and c at a fixed approach), the "
                  "interface energy int h over the zone (Gauss-Legendre), the pull-off (walk on the traced "
                  "branch; a stand-alone continuation as the second route). Checked in tests/test_cohesive*.py: "
                  "JKR as lambda -> inf (contact width at a fixed load O(lambda^-2), approach, pull-off and the "
                  "cycle's dissipated energy O(lambda^-4)), Baney-Hui at Delta/R -> 0 (states and pull-off to "
                  "1e-4 through the public API), the Dugdale energy stationary along the states (1e-8), the "
                  "stability flags against minima of the held-zone-end energy (random pairs)")
    doc = ("Half-plane limit (cylinder on a flat, Baney-Hui 1997) in the normalised variables: load\n"
           "p = eps^2/4 - 2 s0 sqrt(c^2 - eps^2) and the opening h(c)/Delta at the zone end c of a contact\n"
           "|phi| < eps with the zone eps < |phi| < c (derive/cohesive.py); the state has\n"
           "h(c) = h0 = m^2/s0.")
    return [Kernel("half_plane_state", (("p", load), ("opening", hertz + dugdale)), doc, array_args=())]


def _half_plane_pairs(load, opening):
    """30-digit checks of the half-plane Maugis-Dugdale density (quadrature, no closed form used)."""
    pairs = []
    fl = checks.mp_function(load, (eps, c, s0))
    fo = checks.mp_function(opening, (eps, c, s0))
    with mp.workdps(checks.DPS):
        for ev, cv, sv in ((mp.mpf("0.7"), mp.mpf("1.3"), mp.mpf("0.2")),
                           (mp.mpf("1"), mp.mpf("1.05"), mp.mpf("3")),
                           (mp.mpf("0.2"), mp.mpf("2.5"), mp.mpf("0.01"))):
            A = cv ** 2 - ev ** 2

            def nu(x, ev=ev, sv=sv, A=A, cv=cv):
                if abs(x) < ev:
                    return mp.sqrt(ev ** 2 - x ** 2) / (2 * mp.pi) - 2 * sv / mp.pi * mp.atan(mp.sqrt(A / (ev ** 2 - x ** 2)))
                return -sv if abs(x) < cv else mp.mpf(0)

            nodes = [-cv, -ev, ev, cv]
            for x in (mp.mpf("0.3") * ev, mp.mpf("0.8") * ev):
                pairs.append((2 * checks.pv_quad(nu, x, -cv, cv, breaks=(-ev, ev)) + 1, x + 1))
            pairs.append((mp.quad(nu, nodes) + 1, fl(ev, cv, sv) + 1))
            gap = (cv ** 2 - ev ** 2) / 2 - 2 * mp.quad(
                lambda x: nu(x) * (mp.log(abs(cv - x)) - mp.log(abs(ev - x))), nodes)
            pairs.append((gap, fo(ev, cv, sv)))
    return pairs


def derive(report):
    return zone_integrals(report) + scales(report) + half_plane(report)
