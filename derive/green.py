"""Green's functions of (2.1) and (5.2) from Michell's solution, mode by mode (issue 10, items 1 and 4).

A hole of radius R in an infinite plate (G, kappa) and a solid disk of radius R (G_I, kappa_I) carry the
same shear-free radial traction sigma_rr(R, theta) = -N(theta) (N > 0 presses the bodies apart).  For
N = cos(n theta) the radial surface displacements are v_r = V_n cos(n theta) (plate) and u_r = U_n cos(n theta)
(disk), so that the relative displacement of (5.1) is

    v_r - u_r = int N(psi) g(phi - psi) dpsi,    g(t) = (C_0 + 2 sum_{n>=1} C_n cos(n t))/(2 pi),  C_n = V_n - U_n.

Steps (each proved by sympy or checked by mpmath, recorded in DERIVATION.md):

1. Michell's table: each Airy stress function with its plane displacement (strains = Hooke's law of the
   stresses, plane strain or stress through kappa); the stresses are in equilibrium.
2. Modes n >= 2 and n = 0 (no net force): unique, C_n = R (beta* n + alpha*)/(2 (n^2 - 1)), C_0 from the
   hole under pressure and the disk under pressure.
3. Mode n = 1 carries the net force P: the plate's single-valued field grows like log r, the disk needs a
   balancing load, so V_1, U_1 depend on the points chosen as reference -- this is what the approach delta
   means.  Derived: the plate relative to the mean displacement of its rim, the disk loaded at its centre
   (point force) relative to the mean displacement of its rim, and the disk loaded over its area (uniform
   body force) relative to its centre (= its centroid, the work conjugate of that load).
4. Sum of the modes: closed-form kernel K(t) of the solver (normalised, K = -4 pi g/(R beta*)); (5.2) of the
   paper is the rim-to-rim kernel at alpha* = 0; (2.1) is (1 + d^2/dphi^2) of it (with 2 alpha* there).
5. The work-conjugate approach: delta_work = delta + P/(8 pi G_I); energy proof for the n = 1 mode.

Kernel arguments: ar = alpha*/beta*, gb = (1/G_I)/beta*, inv_theta = 1/vartheta, with
alpha* = (kappa - 1)/(2G) - (kappa_I - 1)/(2G_I) and beta* = (kappa + 1)/(2G) + (kappa_I + 1)/(2G_I).
"""
import mpmath as mp
import sympy as sp

from . import checks
from .kernel import Kernel
from .report import DIFFERS, MATCHES, NEW

r, th, R, t = sp.symbols("r theta R t", positive=True)
G, kap, G_I, kap_I = sp.symbols("G kappa G_I kappa_I", positive=True)
n = sp.Symbol("n", integer=True, positive=True)
p, b = sp.symbols("p b", positive=True)                  # traction amplitude, body force per unit area
ar, gb, inv_theta = sp.symbols("ar gb inv_theta", real=True)
P, delta = sp.symbols("P delta", real=True)
inv_G_I = sp.Symbol("inv_G_I", nonnegative=True)

BETA = (kap + 1) / (2 * G) + (kap_I + 1) / (2 * G_I)
ALPHA = (kap - 1) / (2 * G) - (kap_I - 1) / (2 * G_I)
_c, _s, _L = sp.cos(th), sp.sin(th), sp.log(r)

# Michell's solution (Barber, Elasticity, tables 8.1 and 9.1): (Airy function, 2G u_r, 2G u_theta)
MICHELL = {
    "r^(n+2) cos": (r**(n + 2) * sp.cos(n * th), (kap - n - 1) * r**(n + 1) * sp.cos(n * th),
                    (kap + n + 1) * r**(n + 1) * sp.sin(n * th)),
    "r^(2-n) cos": (r**(2 - n) * sp.cos(n * th), (kap + n - 1) * r**(1 - n) * sp.cos(n * th),
                    -(kap - n + 1) * r**(1 - n) * sp.sin(n * th)),
    "r^n cos": (r**n * sp.cos(n * th), -n * r**(n - 1) * sp.cos(n * th), n * r**(n - 1) * sp.sin(n * th)),
    "r^-n cos": (r**(-n) * sp.cos(n * th), n * r**(-n - 1) * sp.cos(n * th), n * r**(-n - 1) * sp.sin(n * th)),
    "r^2": (r**2, (kap - 1) * r, sp.S(0)),
    "log r": (sp.log(r), -1 / r, sp.S(0)),
    "r theta sin": (r * th * _s, ((kap - 1) * th * _s - _c + (kap + 1) * _L * _c) / 2,
                    ((kap - 1) * th * _c - _s - (kap + 1) * _L * _s) / 2),
    "r log r cos": (r * _L * _c, ((kap + 1) * th * _s - _c + (kap - 1) * _L * _c) / 2,
                    ((kap + 1) * th * _c - _s - (kap - 1) * _L * _s) / 2),
}


def _require(what, expr):
    if sp.simplify(expr) != 0:
        raise AssertionError(f"derive proof failed: {what}")


def stresses(phi, V=0):
    """(sigma_rr, sigma_thth, sigma_rth) of the Airy function phi (body-force potential V)."""
    return (sp.diff(phi, r) / r + sp.diff(phi, th, 2) / r**2 + V, sp.diff(phi, r, 2) + V,
            -sp.diff(sp.diff(phi, th) / r, r))


def hooke(sig, G_=G, k_=kap):
    """Strains (eps_rr, eps_thth, gamma_rth) of the stresses: plane strain kappa = 3 - 4 nu."""
    srr, stt, srt = sig
    return (((k_ + 1) * srr - (3 - k_) * stt) / (8 * G_), ((k_ + 1) * stt - (3 - k_) * srr) / (8 * G_), srt / G_)


def strains(ur, ut):
    return (sp.diff(ur, r), (ur + sp.diff(ut, th)) / r, sp.diff(ur, th) / r + sp.diff(ut, r) - ut / r)


def equilibrium(sig, body=(0, 0)):
    """Residuals of the polar equilibrium equations with body force (b_r, b_theta)."""
    srr, stt, srt = sig
    return (sp.diff(srr, r) + sp.diff(srt, th) / r + (srr - stt) / r + body[0],
            sp.diff(srt, r) + sp.diff(stt, th) / r + 2 * srt / r + body[1])


def field(coefs, nn=None, G_=G, k_=kap):
    """Airy function and displacements (u_r, u_theta) of sum coef * MICHELL[term] (mode number nn)."""
    phi = ur = ut = sp.S(0)
    for term, coef in coefs.items():
        f, fr, ft = (e if nn is None else e.subs(n, nn) for e in MICHELL[term])
        phi += coef * f
        ur += coef * fr.subs(kap, k_) / (2 * G_)
        ut += coef * ft.subs(kap, k_) / (2 * G_)
    return phi, ur, ut


def _bc_solve(coefs, unknowns, nn, trig, G_=G, k_=kap):
    """Fix the unknown coefficients by sigma_rr(R) = -trig, sigma_rth(R) = 0; return (u_r, u_theta, sigma)."""
    phi, ur, ut = field(coefs, nn, G_, k_)
    srr, _, srt = stresses(phi)
    eqs = []
    for e in (srr.subs(r, R) + trig, srt.subs(r, R)):
        e = sp.expand(sp.expand_trig(e))
        eqs += [e.subs(th, sp.Rational(1, 3)), e.subs(th, sp.Rational(2, 5))]
    sol = sp.solve(eqs, unknowns, dict=True)[0]
    phi, ur, ut = (sp.simplify(e.subs(sol)) for e in (phi, ur, ut))
    sig = stresses(phi)
    _require("traction sigma_rr(R) = -N", sp.expand_trig(sig[0].subs(r, R) + trig))
    _require("traction sigma_rtheta(R) = 0", sig[2].subs(r, R))
    return ur, ut, sig


def _rim_mean(ur, ut, radius):
    """Mean x-displacement of the material points on the circle r = radius (the translation of that ring)."""
    ux = sp.expand((ur * _c - ut * _s).subs(r, radius))
    return sp.simplify(sp.integrate(ux, (th, 0, 2 * sp.pi)) / (2 * sp.pi))


# --- 1. Michell's table -------------------------------------------------------------------------------------
def michell_table(report):
    report.result("Michell's stress functions and their displacements",
                  r"2G\,(u_r, u_\theta)\ \text{for}\ \phi \in \{r^{n+2}, r^{2-n}, r^n, r^{-n}\}\cos n\theta,"
                  r"\ r^2,\ \log r,\ r\theta\sin\theta,\ r\log r\cos\theta", NEW,
                  "Michell (1899) as tabulated by Barber (Elasticity, tables 8.1, 9.1); the paper cites "
                  "Green's functions (Sundaram and Farris 2010) without deriving them")
    for name, (phi, ur, ut) in MICHELL.items():
        sig = stresses(phi)
        for x, y in zip(strains(ur / (2 * G), ut / (2 * G)), hooke(sig)):
            _require(f"Michell {name}: strain", x - y)
        for res in equilibrium(sig):
            _require(f"Michell {name}: equilibrium", res)
    report.proof("for each of the 8 rows: the strains of (u_r, u_theta) equal Hooke's law "
                 "[(kappa+1) s_rr - (3-kappa) s_tt]/8G, ..., s_rt/G of the Airy stresses (so the stresses are "
                 "compatible and the displacement is theirs), and the stresses satisfy both polar equilibrium "
                 "equations; symbolic in n, kappa, G")


# --- 2. modes without net force -----------------------------------------------------------------------------
def modes(report):
    """(C_0, C_n for n >= 2) with the plate's and the disk's parts."""
    A, B = sp.symbols("A B")
    Vn = sp.factor(_bc_solve({"r^-n cos": A, "r^(2-n) cos": B}, [A, B], None, sp.cos(n * th))[0]
                   .subs({r: R, th: 0}))
    Un = sp.factor(_bc_solve({"r^n cos": A, "r^(n+2) cos": B}, [A, B], None, sp.cos(n * th), G_I, kap_I)[0]
                   .subs({r: R, th: 0}))
    Cn = R * (BETA * n + ALPHA) / (2 * (n**2 - 1))
    _require("C_n", Vn - Un - Cn)
    report.result("Modes n >= 2: hole, disk and the relative displacement",
                  sp.Eq(sp.Symbol("C_n"), sp.factor(R * (sp.Symbol("beta^*") * n + sp.Symbol("alpha^*"))
                                                    / (2 * (n**2 - 1)))), NEW,
                  f"plate r^(-n), r^(2-n) terms: V_n = {sp.sstr(Vn)}; disk r^n, r^(n+2) terms: U_n = {sp.sstr(Un)}")
    report.proof("traction conditions solved for the two coefficients of each body; V_n - U_n = "
                 "R (beta* n + alpha*)/(2 (n^2 - 1)) with alpha* = (kappa-1)/2G - (kappa_I-1)/2G_I")
    V0 = _bc_solve({"log r": A}, [A], 0, 1)[0].subs(r, R)
    U0 = _bc_solve({"r^2": A}, [A], 0, 1, G_I, kap_I)[0].subs(r, R)
    C0 = sp.simplify(V0 - U0)
    _require("C_0", C0 - R * (BETA / 2 - (kap_I + 1) / (4 * G_I) - ALPHA / 2))
    report.result("Mode n = 0 (uniform pressure)", sp.Eq(sp.Symbol("C_0"), C0), NEW,
                  f"hole under pressure V_0 = {sp.sstr(V0)}, disk under pressure U_0 = {sp.sstr(U0)}")
    report.proof("C_0 = R (beta*/2 - (kappa_I + 1)/(4 G_I) - alpha*/2)")
    return C0, Cn


# --- 3. the mode n = 1 and the reference of the approach ----------------------------------------------------
def mode_one(report):
    """V_1 (plate, rim mean), U_1 (disk: point force at the centre, rim mean; body force, centroid)."""
    A, T = sp.symbols("A T")
    # the plate: A/r cos + T(-(kappa-1) r log r cos + (kappa+1) r theta sin) is single-valued
    ur, ut, _ = _bc_solve({"r^-n cos": A, "r log r cos": -(kap - 1) * T, "r theta sin": (kap + 1) * T},
                          [A, T], 1, _c)
    _require("plate n = 1 single-valued", sp.diff(ur, th).subs(th, 2 * sp.pi) - sp.diff(ur, th).subs(th, 0))
    V1 = sp.simplify(ur.subs({r: R, th: 0}) - _rim_mean(ur, ut, R))
    report.result("Mode n = 1, the plate: net force pi R on the hole, relative to the rim's mean displacement",
                  sp.Eq(sp.Symbol("V_1"), V1), NEW,
                  "single-valued combination -(kappa-1) r log r cos + (kappa+1) r theta sin (the theta terms "
                  "of the displacement cancel); the field grows like (kappa R/(2G(kappa+1))) log r, so the "
                  "plate needs a reference: here the mean displacement of the rim's material points")
    report.proof(f"traction conditions and single-valuedness; v_r(R) - mean rim u_x = {sp.sstr(V1)} "
                 "(no log R: independent of the length unit)")
    # the disk loaded at its centre (Michell's point-force terms), relative to its rim
    urp, utp, _ = _bc_solve({"r^(n+2) cos": A, "r log r cos": -(kap_I - 1) * T,
                             "r theta sin": (kap_I + 1) * T}, [A, T], 1, _c, G_I, kap_I)
    U1_point = sp.factor(sp.simplify(urp.subs({r: R, th: 0}) - _rim_mean(urp, utp, R)))
    report.result("Mode n = 1, the disk loaded by a force at its centre, relative to its rim",
                  sp.Eq(sp.Symbol("U_1^{centre\\,force}"), U1_point), NEW,
                  "the balancing force P acts at r = 0 (r log r and r theta sin terms: the displacement is "
                  "log-singular there, so only a ring of material points can serve as reference)")
    report.proof(f"u_r(R) - mean rim u_x = {sp.sstr(U1_point)}")
    # the disk loaded over its area by the uniform body force b = p/R (sigma = -b x I, u ~ x^2)
    x = r * _c
    sig = (-b * x, -b * x, sp.S(0))
    for res in equilibrium(sig, body=(b * _c, -b * _s)):
        _require("body-force disk: equilibrium", res)
    uxb, uyb = -(kap_I - 1) * b * (r**2 * sp.cos(2 * th)) / (8 * G_I), -(kap_I - 1) * b * r**2 * sp.sin(2 * th) / (8 * G_I)
    urb, utb = uxb * _c + uyb * _s, -uxb * _s + uyb * _c
    for e1, e2 in zip(strains(urb, utb), hooke(sig, G_I, kap_I)):
        _require("body-force disk: strain", e1 - e2)
    _require("body-force disk: traction", sig[0].subs({r: R, b: p / R}) + p * _c)
    centroid = sp.simplify(sp.integrate(sp.integrate(sp.expand(uxb * r), (th, 0, 2 * sp.pi)), (r, 0, R)))
    _require("body-force disk: centroid = centre", centroid)
    U1_body = sp.factor(urb.subs({r: R, th: 0, b: p / R}) / p)
    report.result("Mode n = 1, the disk loaded over its area (uniform body force), relative to its centroid",
                  sp.Eq(sp.Symbol("U_1^{body}"), U1_body), NEW,
                  "sigma = -b x I with b = P/(pi R^2), u_x = -(kappa_I-1) b (x^2 - y^2)/8G_I, "
                  "u_y = -(kappa_I-1) b x y/4G_I: no singular point; the centroid (= centre) displacement is "
                  "the work conjugate of a load spread over the disk")
    report.proof("equilibrium with the body force, Hooke's law, traction sigma_rr(R) = -p cos(theta), "
                 "sigma_rtheta = 0, and zero mean displacement over the area (centroid at rest)")
    return V1, U1_point, U1_body


# --- 4. sums of the modes ----------------------------------------------------------------------------------
def series(report):
    """The two cosine series that sum the modes n >= 2 (Fourier coefficients proved, then checked)."""
    k = sp.Symbol("k", integer=True)
    s1 = -sp.Rational(1, 2) - sp.cos(t) / 4 - sp.cos(t) * sp.log(2 - 2 * sp.cos(t)) / 2     # sum n cos/(n^2-1)
    s2 = sp.Rational(1, 2) + sp.cos(t) / 4 - (sp.pi - t) * sp.sin(t) / 2                   # sum cos/(n^2-1)
    report.result("The mode sums", r"\sum_{n\ge2}\frac{n\cos nt}{n^2-1} = -\frac12 - \frac{\cos t}{4} - "
                  r"\frac{\cos t}{2}\log(2-2\cos t),\quad \sum_{n\ge2}\frac{\cos nt}{n^2-1} = \frac12 + "
                  r"\frac{\cos t}{4} - \frac{(\pi-|t|)\sin|t|}{2}", NEW,
                  "the first is (5.5) of the paper (proved in the approach section)")
    # Fourier coefficients of s2 on (0, pi) (even): symbolic integral for k >= 2 and k = 0, 1
    k2 = sp.Symbol("k2", integer=True, positive=True)         # k = k2 + 1 >= 2
    coef = 2 / sp.pi * sp.integrate(sp.expand(s2 * sp.cos((k2 + 1) * t)), (t, 0, sp.pi), conds="none")
    _require("series 2, coefficient k >= 2", sp.simplify(coef - 1 / ((k2 + 1)**2 - 1)))
    for kk in (0, 1):
        _require(f"series 2, coefficient {kk}", sp.integrate(s2 * sp.cos(kk * t), (t, 0, sp.pi)))
    report.proof("the cosine coefficients of the second sum by symbolic integration over (0, pi): "
                 "1/(k^2 - 1) for k >= 2, 0 for k = 0, 1")
    f1, f2 = checks.mp_function(s1, (t,)), checks.mp_function(s2, (t,))
    pairs = []
    with mp.workdps(checks.DPS):
        for kk in range(0, 9):
            for f, want in ((f1, lambda q: q / (q**2 - 1)), (f2, lambda q: mp.mpf(1) / (q**2 - 1))):
                got = 2 / mp.pi * mp.quad(lambda x: f(x) * mp.cos(kk * x), [0, mp.pi / 2, mp.pi])
                pairs.append((got + 1, (want(mp.mpf(kk)) if kk >= 2 else 0) + 1))
    report.check("both sums: cosine coefficients k = 0..8 by quadrature (shifted by 1)",
                 checks.assert_close("mode sums", pairs), len(pairs))
    return s1, s2


def kernel_constants(C0, C1, s1, s2):
    """K(t) = -4 pi g(t)/(R beta*) = cos t log(2 - 2 cos t) + k1 cos t + k0 + ar (pi sin|t| - t sin t):
    return (k0, k1) from C_0 and C_1 (the n >= 2 modes summed with s1, s2)."""
    g = (C0 + 2 * C1 * sp.cos(t) + 2 * (R * BETA / 2 * s1 + R * ALPHA / 2 * s2)) / (2 * sp.pi)
    K = sp.expand(-4 * sp.pi * g / (R * BETA))
    rest = sp.expand(K - sp.cos(t) * sp.log(2 - 2 * sp.cos(t))
                     - ALPHA / BETA * (sp.pi * sp.sin(t) - t * sp.sin(t)))
    k1 = sp.simplify(rest.coeff(sp.cos(t)))
    k0 = sp.simplify(rest - k1 * sp.cos(t))
    _require("kernel has no other terms", sp.diff(k0, t))
    return k0, k1


def to_normalised(expr):
    """Write a dimensionless material expression in (inv_theta, gb, ar): eliminate 1/G, kappa/G, kappa_I/G_I."""
    x, y, z = sp.symbols("x y z")          # 1/(2G beta*), kappa/(2G beta*), kappa_I/(2G_I beta*)
    beta_ = sp.Symbol("beta_", positive=True)
    sub = {G: 1 / (2 * x * beta_), kap: y / x, G_I: 1 / (gb * beta_), kap_I: 2 * z / gb}
    e = sp.simplify(expr.subs(sub))
    # beta* = 1 ; (kappa+1)/(2G beta*) = 1/(2 theta) ; alpha*/beta* = ar
    sol = sp.solve([sp.Eq(y + x + z + gb / 2, 1), sp.Eq(y + x, inv_theta / 2), sp.Eq(y - x - z + gb / 2, ar)],
                   [x, y, z], dict=True)[0]
    return sp.simplify(e.subs(sol).subs(beta_, 1))


def kernel_sum(report, C0, Cn, V1, U1_point, U1_body, s1, s2):
    C1_rim, C1_work = V1 - U1_point, V1 - U1_body
    k0, k1 = kernel_constants(C0, C1_rim, s1, s2)
    _, k1w = kernel_constants(C0, C1_work, s1, s2)
    k0n, k1n, k1wn = (to_normalised(e) for e in (k0, k1, k1w))
    _require("k0", k0n - (1 - inv_theta / 2))
    _require("k1 rim", k1n - gb)
    _require("k1 work", k1wn - gb / 2)
    report.result("The kernel: sum of the modes (normalised K = -4 pi g/(R beta*))",
                  r"K(t) = \cos t\log(2-2\cos t) + k_1\cos t + 1 - \frac{1}{2\vartheta} + "
                  r"\frac{\alpha^*}{\beta^*}(\pi\sin|t| - t\sin t),\quad k_1 = \frac{1/G_I}{\beta^*}\ "
                  r"(\delta),\quad k_1 = \frac{1/G_I}{2\beta^*}\ (\delta_{work})", NEW,
                  "g(t) = (C_0 + 2 C_1 cos t + 2 sum C_n cos nt)/2 pi with the two mode sums")
    report.proof("collecting constant and cos t terms; in (1/vartheta, (1/G_I)/beta*, alpha*/beta*): "
                 "k0 = 1 - 1/(2 vartheta); k1 = (1/G_I)/beta* for the rims' approach (disk loaded at its centre), "
                 "(1/G_I)/(2 beta*) for the centroid of a disk loaded over its area")
    # (5.2) of the paper: -(R/4pi)[beta* c log(2-2c) + c/G_I + (kappa_I + 1)/(2G_I)] at alpha* = 0
    c = sp.cos(t)
    g_paper = -R / (4 * sp.pi) * (BETA * c * sp.log(2 - 2 * c) + c / G_I + (kap_I + 1) / (2 * G_I))
    g_ours = -R * BETA / (4 * sp.pi) * (c * sp.log(2 - 2 * c) + k1 * c + k0
                                        + ALPHA / BETA * (sp.pi * sp.sin(t) - t * sp.sin(t)))
    diff = sp.simplify(sp.expand(g_ours - g_paper))
    on_line = sp.simplify(diff.subs(kap, 1 + 2 * G * (kap_I - 1) / (2 * G_I)))    # alpha* = 0
    _require("(5.2) at alpha* = 0", on_line)
    report.result("(5.2) is the rims' kernel at alpha* = 0", r"g(t)\big|_{\alpha^*=0} = -\frac{R}{4\pi}\Big["
                  r"\beta^*\cos t\log(2-2\cos t) + \frac{\cos t}{G_I} + \frac{\kappa_I+1}{2G_I}\Big]", MATCHES,
                  "our g(t) with C_1 = V_1 - U_1(centre force, rim) minus the printed kernel of (5.2)")
    report.proof("the difference vanishes identically on (kappa - 1)/G = (kappa_I - 1)/G_I; so the paper's "
                 "delta is the approach of the two rims (mean displacement of the pin's rim minus that of the "
                 "hole's rim) with the load applied at the pin's centre")
    # numerical: Fourier coefficients of the printed (5.2) kernel vs the modes, alpha* = 0 pairs
    pairs = []
    fpaper = checks.mp_function(g_paper, (t, R, G, kap, G_I, kap_I))
    with mp.workdps(checks.DPS):
        for (Gv, kv, GIv) in ((1, 2, 1), (mp.mpf(3), mp.mpf("1.4"), mp.mpf("0.7")), (1, 1, mp.mpf(5))):
            kIv = 1 + GIv * (kv - 1) / Gv                   # alpha* = 0
            vals = {R: 1, G: Gv, kap: kv, G_I: GIv, kap_I: kIv}
            for kk in range(0, 7):
                want = {0: C0, 1: C1_rim}.get(kk, Cn.subs(n, kk))
                got = mp.quad(lambda x: 2 * fpaper(x, 1, Gv, kv, GIv, kIv) * mp.cos(kk * x), [0, mp.pi / 2, mp.pi])
                want = mp.mpf(sp.N(want.subs(vals), checks.DPS))
                pairs.append((got * (1 if kk else mp.mpf(1) / 2) * 2 + 1, want + 1))
    report.check("cosine coefficients of the printed (5.2) kernel by quadrature against C_0, C_1 (rims), C_n, "
                 "n = 0..6, three alpha* = 0 pairs (shifted by 1)", checks.assert_close("(5.2) modes", pairs),
                 len(pairs))
    report.result("The solver's kernel before the derivation", r"k_1 = \frac{1/G_I}{\beta^*} - "
                  r"\frac{\alpha^*}{2\beta^*}", DIFFERS,
                  "the hand-typed kernel jkrcyl.numerics.arcs used before this derivation; the solver now takes "
                  "k0, k1, ka from kernel_constants (generated/green.py), the derived k1 above")
    report.proof("its extra -alpha*/(2 beta*) cos t shifts only the reference of delta (by alpha* P/(8 pi)); "
                 "P, B, K, the pressure and h(phi) are unchanged: C_1 never enters them")
    return k0n, k1n, k1wn, C1_rim, C1_work


def equation_21(report, C0, Cn):
    """(2.1) is (1 + d^2/dphi^2) of (5.1)-(5.2): its Fourier coefficients are (1 - n^2) C_n."""
    a2 = sp.Symbol("alpha_2")   # the coefficient printed as alpha* in (2.1)
    # (2.1) acting on N = cos(n psi), n >= 2: (R/4pi)[beta*/2 * (-4 pi n) - pi alpha_2] ; n = 0: (R/4pi)[(kappa+1)/2G 2pi - pi alpha_2]
    printed_n = R / (4 * sp.pi) * (BETA / 2 * (-4 * sp.pi * n) - sp.pi * a2)
    printed_0 = R / (4 * sp.pi) * ((kap + 1) / (2 * G) * 2 * sp.pi - sp.pi * a2)
    sol_n = sp.solve(sp.Eq(printed_n, sp.expand((1 - n**2) * Cn)), a2)
    sol_0 = sp.solve(sp.Eq(printed_0, C0), a2)
    _require("(2.1) alpha coefficient, n >= 2", sol_n[0] - 2 * ALPHA)
    _require("(2.1) alpha coefficient, n = 0", sol_0[0] - 2 * ALPHA)
    report.result("(2.1) from the modes: (1 + d^2/dphi^2) of the displacement equation",
                  r"-\Delta = \frac{R}{4\pi}\Big[\frac{\kappa+1}{2G}\mathbb{B} + (2\alpha^* + 2\beta^*)\int\cos"
                  r"(\phi-\psi)N + \frac{\beta^*}{2}\int\csc^2\frac{\phi-\psi}{2}N - 2\pi\alpha^* N(\phi)\Big]",
                  DIFFERS, "(1 - n^2) C_n against the cosine coefficients of the printed operator "
                  "(csc^2(t/2) = -4 sum n cos nt in the finite-part sense)")
    report.proof("the printed coefficient alpha* must equal 2 alpha* = (kappa-1)/G - (kappa_I-1)/G_I for the "
                 "n = 0 and n >= 2 modes; the n = 1 mode is annihilated either way")
    report.erratum("(2.1), the alpha* terms",
                   "(alpha* + 2 beta*) int cos(phi - psi) N and - pi alpha* N(phi), with alpha* unspecified "
                   "beyond 'zero when (kappa-1)/G = (kappa_I-1)/G_I'",
                   "with alpha* = (kappa-1)/(2G) - (kappa_I-1)/(2G_I) (the analogue of beta*, the library's "
                   "definition): (2 alpha* + 2 beta*) and - 2 pi alpha* N(phi); equivalently the printed form "
                   "holds with alpha* = (kappa-1)/G - (kappa_I-1)/G_I",
                   "Michell modes of the hole and the disk (derive/green.py), proved symbolically")


# --- 5. the work-conjugate approach ------------------------------------------------------------------------
def work_shift(load, inv_GI):
    """delta_work - delta = P/(8 pi G_I) (proved in :func:`work_conjugate`); used by derive.derivatives."""
    return load * inv_GI / (8 * sp.pi)


def work_conjugate(report, U1_point, U1_body):
    # energy of the n = 1 disk field loaded over its area: direct integral of sigma:eps/2 vs Clapeyron
    x = r * _c
    sig = (-b * x, -b * x, sp.S(0))
    eps = hooke(sig, G_I, kap_I)
    density = (sig[0] * eps[0] + sig[1] * eps[1] + sig[2] * eps[2]) / 2
    U = sp.simplify(sp.integrate(sp.integrate(sp.expand(density * r), (th, 0, 2 * sp.pi)), (r, 0, R)).subs(b, p / R))
    clapeyron = -sp.pi * R * p**2 * U1_body / 2          # (1/2)(traction work -int N u_r R) + (1/2) P * 0
    _require("energy of the body-force disk", U - clapeyron)
    _require("rims' bookkeeping energy", -sp.pi * R * p**2 * U1_point / 2 - sp.pi * R**2 * p**2 * (kap_I - 2) / (16 * G_I))
    report.result("Work conjugate of the load on the pin (n = 1 energy)",
                  sp.Eq(sp.Symbol("U_{disk}"), U), NEW,
                  "strain energy int sigma:eps/2 dA of the body-force field against Clapeyron's theorem "
                  "(1/2)[-int N u_r R dtheta + P u_centroid] with u_r relative to the centroid")
    report.proof("equal: the centroid displacement is the work conjugate of P spread over the pin; the energy is "
                 "positive. With the rims' reference the same bookkeeping gives (pi R^2 p^2/16 G_I)(kappa_I - 2), "
                 "negative for nu_I > 1/4: the paper's delta is the conjugate of no elastic loading there, which "
                 "is how Fig. 7 gets a negative load-approach stiffness without adhesion")
    shift = sp.simplify((U1_point - U1_body) * P / (sp.pi * R))
    _require("delta_work - delta", shift - work_shift(P, 1 / G_I))
    report.result("The work-conjugate approach", sp.Eq(sp.Symbol("delta_{work}"),
                  delta + P / (8 * sp.pi * sp.Symbol("G_I"))), NEW,
                  "the n = 1 amplitude of N is P/(pi R); delta moves the disk's reference from its rim "
                  "(centre force) to its centroid (area load); the plate's reference (its rim) is common")
    report.proof("delta_work - delta = (U_1^{centre force} - U_1^{body}) P/(pi R) = P/(8 pi G_I), any alpha*; "
                 "normalised: delta_work/Delta = delta/Delta + (gb/2) P beta*/(4 pi Delta), = delta/Delta + "
                 "(2 vartheta - 1) P*/4 when nu_I = 1/2")
    report.erratum("Section 5, (5.1)-(5.8), and Fig. 7: the approach delta",
                   "delta called the approach and drawn against P (negative slope without adhesion in Fig. 7, "
                   "rigid cradle, nu_I = 1/2)",
                   "the paper's delta is the mean displacement of the pin's rim relative to the hole's rim with "
                   "the load applied at the pin's centre; it is not the work conjugate of P. The conjugate "
                   "approach (pin centroid, load spread over the pin) is delta_work = delta + P/(8 pi G_I); "
                   "Fig. 7: delta/Delta = 0.197, -3.21, -24.1 become delta_work/Delta = 0.347, 0.793, 0.911 at "
                   "P_R* = 0.3, 8, 50",
                   "Michell modes and the n = 1 energy (derive/green.py)")


def derive(report):
    report.section("Green's functions of the hole and the disk (Michell; issue 10)")
    michell_table(report)
    C0, Cn = modes(report)
    V1, U1_point, U1_body = mode_one(report)
    s1, s2 = series(report)
    k0n, k1n, k1wn, _, _ = kernel_sum(report, C0, Cn, V1, U1_point, U1_body, s1, s2)
    equation_21(report, C0, Cn)
    work_conjugate(report, U1_point, U1_body)
    doc_k = ("Constants of the normalised kernel K(t) = cos t log(2 - 2 cos t) + k1 cos t + k0\n"
             "+ ka (pi sin|t| - t sin t) of the displacement equation (5.2) for any alpha* (derive/green.py):\n"
             "k1 for the paper's delta (rims), k1_work for the work-conjugate approach; ka = alpha*/beta*.\n"
             "Arguments: ar = alpha*/beta*, gb = (1/G_I)/beta*, inv_theta = 1/vartheta.")
    doc_w = ("Work-conjugate approach delta_work = delta + P/(8 pi G_I) [m] (derive/green.py).\n"
             "delta [m] as (5.8), P [N/m] (2.2), inv_G_I = 1/G_I [1/Pa].")
    dn, p_star = sp.symbols("delta_over_Delta p", real=True)
    Dl, bt = sp.symbols("Delta beta", positive=True)
    work_star = dn + gb * p_star / 2
    dimensional = (dn * Dl + work_shift(4 * sp.pi * Dl * p_star / bt, gb * bt)) / Dl   # P = 4 pi Delta p/beta*
    _require("normalised work-conjugate approach", sp.simplify(dimensional - work_star))
    report.proof("normalised: delta_work/Delta = delta/Delta + (gb/2) p with p = P beta*/(4 pi Delta) (= vartheta P*) "
                 "and gb = (1/G_I)/beta* (sympy: equal to the dimensional form)")
    doc_s = ("Normalised work-conjugate approach delta_work/Delta = delta/Delta + (gb/2) p (derive/green.py):\n"
             "p = P beta*/(4 pi Delta) (= vartheta P*, P_R* for vartheta = inf), gb = (1/G_I)/beta*.")
    return [Kernel("kernel_constants", (("k0", k0n), ("k1", k1n), ("k1_work", k1wn), ("ka", ar)), doc_k,
                   array_args=("ar",), extra_args=(ar, gb, inv_theta)),
            Kernel("approach_work", (("delta_work", delta + work_shift(P, inv_G_I)),), doc_w,
                   array_args=("P", "delta"), forms=("into",)),
            Kernel("approach_work_star", (("delta_work_over_Delta", work_star),), doc_s,
                   array_args=("delta_over_Delta", "p"), forms=("into",))]
