"""Confined regime (sections 6, 8.2, 8.3; issue 12): what slow pulling does at the fold and at h(pi) = 0.

The two-patch states that follow h(pi) = 0 have no closed form (jkrcyl.twopatch solves them); what the
closed forms (4.4) and (5.10) do decide is checked here, at 30 digits, and feeds two errata:

1. At fixed contact a the load is affine in the adhesion, p = p0(a) + m p1(a) (p = vartheta P*,
   m = M vartheta), and G/w = (m'/m)^2 along the family p(a; m'), so dG/dP at fixed a has the sign of
   p1(a): negative below a_crit, positive above.  At a fold (a P* minimum, where the equilibrium turns
   unstable under load) a further pull therefore raises G on the sub-critical branch -- the contact
   shrinks, the pin detaches (and, in the hole, lands on the top) -- but lowers G on the super-critical
   branch: the contact grows, closes the gap at phi = pi and zips round into full contact.
2. Slow pulling from the stable zero-load contact (without one: the stable, feasible state of largest P*)
   follows its branch towards lower P* and meets the fold before h(pi) = 0 at every pair checked, so
   the top contact never forms on a state stable under load.
"""
import mpmath as mp
import sympy as sp

from . import load
from .report import NEW
from .symbols import E, R, Delta, a, beta, inv_theta, zeta

m = sp.Symbol("m", nonnegative=True)        # M vartheta
DPS = 30
THETAS = ("0.5", "1", "5")
MS = ("0.1", "0.3", "0.4", "0.5", "0.8", "1.5")
N_WALK = 160                                # grid points per branch for the walk (then refined)


def closed_forms():
    """p = vartheta P* of (4.4) and h(pi)/Delta of (5.10) with R = Delta = beta* = 1, zeta* = 4 pi m."""
    sol = load.solution()
    units = {R: 1, Delta: 1, beta: 1, zeta: 4 * sp.pi * m}
    p = (sol["P"] / (4 * sp.pi)).subs(units)
    h = (-2 * E * sol["c0"] + sol["c1"] * (sp.asinh(1 / a) - 1 / E)).subs(units)
    return p, h


class Branches:
    """mpmath evaluation of p, dp/da, dp/dm, h(pi) at one (M, vartheta); a_crit from section 4."""

    def __init__(self, p, h, M, theta):
        self.M, self.theta = mp.mpf(M), mp.mpf(theta)
        self.args = (self.M * self.theta, 1 / self.theta)
        self.f = sp.lambdify((a, m, inv_theta), [p, sp.diff(p, a), sp.diff(p, m), h], modules="mpmath")
        self.a_crit = mp.sqrt(mp.findroot(lambda u: 2 * self.theta - mp.log1p(u) - 2 * u**2, 1))

        self.cache = {}

    def __call__(self, x):
        if x not in self.cache:
            self.cache[x] = self.f(x, *self.args)
        return self.cache[x]

    def grid(self, sub):
        """Increasing a on one branch: geometric towards a = 0, a_crit and (super-critical) a = 1e4 a_crit."""
        ac, k = self.a_crit, N_WALK // 2
        geo = lambda lo, hi: [lo * (hi / lo) ** (mp.mpf(i) / k) for i in range(k)]
        if sub:
            return [ac * t for t in geo(mp.mpf("1e-6"), mp.mpf("0.5"))] + [ac * (1 - t) for t in
                                                                            geo(mp.mpf("0.5"), mp.mpf("1e-9"))]
        return [ac * (1 + t) for t in geo(mp.mpf("1e-9"), mp.mpf(1))] + [ac * t for t in geo(mp.mpf(2), mp.mpf("1e4"))]

    def root(self, i, lo, hi):
        return mp.findroot(lambda x: self(x)[i], (lo, hi), solver="anderson")


def load_path(br):
    """(sub-critical?, a_start, fold (a, P*, h(pi)/Delta)) of the slow pull; raises if h(pi) <= 0 first."""
    starts = []
    for sub in (True, False):
        g = br.grid(sub)
        v = [br(x) for x in g]
        for (x0, v0), (x1, v1) in zip(zip(g, v), zip(g[1:], v[1:])):
            if v0[0] * v1[0] < 0:
                r = br.root(0, x0, x1)
                q = br(r)
                if (q[1] > 0 if sub else q[1] < 0) and q[3] >= 0:
                    starts.append((r, sub))
    if starts:
        a0, sub = max(starts)
    else:
        cands = [(br(x)[0], x, sub) for sub in (True, False) for x in br.grid(sub)
                 if (br(x)[1] > 0 if sub else br(x)[1] < 0) and br(x)[3] >= 0]      # (cached values)
        _, a0, sub = max(cands)
    g = [x for x in br.grid(sub) if (x < a0 if sub else x > a0)]
    g = list(reversed(g)) if sub else g            # the direction of decreasing P*
    path = [a0]
    for x in g:
        if (br(x)[1] <= 0 if sub else br(x)[1] >= 0):
            af = br.root(1, min(path[-1], x), max(path[-1], x))
            if min(br(y)[3] for y in path + [af]) <= 0:
                raise AssertionError("derive check failed: h(pi) <= 0 before the fold")
            return sub, a0, (af, br(af)[0] / br.theta, br(af)[3])
        path.append(x)
    return sub, a0, None


def derive(report):
    report.section("Confined regime: the fold and h(pi) = 0 under slow pulling (sections 6, 8.2, 8.3)")
    p, h = closed_forms()
    if sp.simplify(sp.diff(p, m, 2)) != 0:
        raise AssertionError("derive proof failed: p is not affine in m")
    rows = []
    with mp.workdps(DPS):
        for th in THETAS:
            for M in MS:
                br = Branches(p, h, M, th)
                sub, a0, fold = load_path(br)
                if fold is None:
                    raise AssertionError(f"derive check failed: no fold on the load path at M = {M}, theta = {th}")
                dpdm = br(fold[0])[2]
                if (dpdm < 0) != sub:
                    raise AssertionError("derive check failed: sign of dp/dm at the fold is not the branch's")
                rows.append((th, M, sub, fold))
    report.result("The load is affine in the adhesion at fixed contact", r"p = p_0(a) + m\,p_1(a)", NEW, "p = vartheta P* of (4.4) (derive.load), m = M vartheta; G/w = (m'/m)^2 along p(a; m'), "
                  "so dG/dP at fixed a has the sign of p1(a) = dp/dm")
    report.proof("d^2 p/dm^2 = 0 (sympy)")
    report.result("At a fold the branch decides: detachment below a_crit, growth into full contact above",
                  r"\operatorname{sign}\,\partial G/\partial P|_a = \operatorname{sign}\,p_1(a) = "
                  r"\operatorname{sign}(a - a_{crit})", NEW,
                  "G > w after a further pull at a sub-critical fold (the contact shrinks: detachment), "
                  "G < w at a super-critical one (the contact grows past h(pi) = 0: full contact)")
    report.check(f"sign of dp/dm at the fold of the load path equals the branch's, vartheta in {{{', '.join(THETAS)}}}, "
                 f"M in {{{', '.join(MS)}}}", 0, len(rows), digits=DPS)
    min_h = min(r[3][2] for r in rows)
    lines = "; ".join(f"M = {M}: fold at P* = {mp.nstr(f[1], 4)} ({'sub' if sub else 'super'}-critical)"
                      for th, M, sub, f in rows if th == "1")
    report.result("Slow pulling meets the fold before the gap at phi = pi closes", sp.Symbol(
                  r"h(\pi)|_{\mathrm{fold}} > 0"), NEW,
                  "from the stable zero-load contact (else the stable feasible state of largest P*) along the "
                  "branch towards lower P*; h(pi) (5.10) stays > 0 up to the fold (a P* minimum, found by root "
                  f"finding on dp/da) at all {len(rows)} pairs; at vartheta = 1: {lines}")
    report.check("h(pi)/Delta > 0 on the walked path and at the fold (smallest value at a fold: "
                 f"{mp.nstr(min_h, 2)})", 0, len(rows), digits=DPS)
    report.erratum("Sections 6 and 8.3, 'detachment' at a super-critical P* minimum",
                   "'for some intermediate values of the adhesion parameter (e.g. M = 0.4) fixed-load detachment "
                   "occurs at some super-critical contact angle' (section 6); 'detachment by an applied upward "
                   "load occurs at M = 0.50 (since the minimum is at P* < 0)' (section 8.3)",
                   "a super-critical P* minimum is a fold where a further pull lowers G (dG/dP > 0 at fixed a "
                   "above a_crit): the contact grows, closes the gap at phi = pi and zips round into full "
                   "contact -- no detachment under load control; only a sub-critical fold detaches the pin, "
                   "which in the hole then lands on the top",
                   "this module (p affine in m, sign of dp/dm at the folds, 30 digits) and the two-patch "
                   "analysis jkrcyl.twopatch.confined_events (tests/test_twopatch.py, tests/test_atlas.py)")
    report.erratum("Sections 8.2 and 8.3, the second contact under an upward load",
                   "'a second contact is invariably established at a large but finite value of this load' "
                   "(section 8.2); at M = 0.80 'overclosures with the confining body precedes detachment' "
                   "(section 8.3)",
                   "slow pulling meets the fold before h(pi) = 0 (checked above): the top contact forms only on "
                   "states unstable under load; at M = 0.8 (vartheta = 1) the fold comes at a compressive "
                   "P* > 0 and the contact then zips into full contact",
                   "this module (load path on (4.4), (5.10) at 30 digits) and the atlas (jkrcyl.atlas: no pair of "
                   "the default 1000 x 1000 grid closes the gap first)")
    return []
