"""The numerical solver of (2.1)/(5.2) for any alpha* (jkrcyl.numerics.arcs, one_arc; jkrcyl.model.collocation).

References: the closed forms (4.4)-(5.10) at alpha* = 0 (generated kernels through Contact.state with
method='closed-form'); the JKR superposition identities of a linear frictionless contact (derived below,
first checked on the closed forms); a first-order perturbation in alpha* by the reciprocal theorem
(double quadrature, no collocation of the alpha* terms); (2.2) by quadrature of the returned pressure.
"""
import math

import numpy as np
import pytest

import jkrcyl
from jkrcyl import equilibria as eq
from jkrcyl.model import stability
from jkrcyl.model.closed_form import ClosedForm
from jkrcyl.model.collocation import Collocation
from jkrcyl.numerics.one_arc import receding_contact
from jkrcyl.model.problem import Problem
from jkrcyl.numerics import arcs

INF = math.inf
# alpha* = 0 pairs for vartheta in {0.5, 1, 3, inf}: rigid pin in an incompressible hole; identical bodies;
# incompressible pair with G/G_I = 5; rigid cradle with an incompressible pin
CLOSED = {0.5: dict(G=1.0, kappa=1.0, G_I=INF, kappa_I=2.0),
          1.0: dict(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0),
          3.0: dict(G=5.0, kappa=1.0, G_I=1.0, kappa_I=1.0),
          INF: dict(G=INF, kappa=2.0, G_I=1.0, kappa_I=1.0)}
# alpha* != 0 pairs (E [Pa], nu, E_I, nu_I): steel pin in aluminium, aluminium pin in steel, steel roller in a
# polymer cradle, rigid pin in compressible plates
PAIRS = {"steel pin in aluminium": (70e9, 0.33, 210e9, 0.30),
         "aluminium pin in steel": (210e9, 0.30, 70e9, 0.33),
         "steel roller in polymer": (3e9, 0.40, 210e9, 0.30),
         "rigid pin, nu = 0.2": (210e9, 0.20, INF, 0.30)}
A_VALUES = np.geomspace(1e-3, 1e2, 11)
FIELDS = ("P", "B", "C", "c0", "c1", "r0", "K", "G_release", "delta", "h_pi")


def contact(mat, Delta=1e-2, w=1e-4):
    return jkrcyl.Contact(R=1.0, Delta=Delta, w=w, materials=mat)


def pair(name, **kw):
    return contact(jkrcyl.Materials.from_young(*PAIRS[name]), **kw)


# --- alpha* = 0: the solver against the closed forms -------------------------------------------------------
@pytest.mark.parametrize("theta", [pytest.param(th, marks=pytest.mark.slow) if th == 0.5 else th for th in CLOSED])
def test_numeric_state_matches_closed_form(theta):          # 0.5 (a rigid pin): 20 s, slow
    c = contact(jkrcyl.Materials(**CLOSED[theta]))
    ac = c.a_crit
    # away from the pole: |a/a_crit - 1| > 5%; for vartheta = inf the pole is a = inf (P ~ a^4 grows without
    # bound and the fixed-arc system degenerates), so up to the rubbery range RUBBERY_A_MAX = 3 of (7.6)
    a = A_VALUES[np.abs(A_VALUES / ac - 1) > 0.05] if math.isfinite(ac) else A_VALUES[A_VALUES <= 3.0]
    ref, num = c.state(a, method="closed-form"), c.state(a, method="numeric")
    for k in FIELDS:
        r, v = getattr(ref, k), getattr(num, k)
        assert np.all(np.isfinite(v)), k
        assert np.max(np.abs(v - r) / np.abs(r)) < 1e-10, k


def test_auto_uses_closed_form_only_where_alpha_is_zero():
    c = contact(jkrcyl.Materials(**CLOSED[1.0]))
    np.testing.assert_array_equal(c.state(A_VALUES).P, c.state(A_VALUES, method="closed-form").P)
    cp = pair("steel pin in aluminium")
    np.testing.assert_array_equal(cp.state(0.3).P, cp.state(0.3, method="numeric").P)
    with pytest.raises(ValueError, match="alpha\\*"):
        cp.state(0.3, method="closed-form")


def star(kind, a, m, theta, gb, ar=0.0):
    """The normalised single-patch states of the closed-form or the collocation solver (m = M vartheta) as a
    dict: p, dn, dw, h, their slopes dp, ddn, ddw, and the release rates gP, gd, gw = (1/w) dG/da at fixed P,
    delta, delta_work (NaN at m = 0)."""
    pb = Problem(m if math.isinf(theta) else m / theta, theta, gb, ar)
    s = (ClosedForm if kind == "closed" else Collocation)(pb).states(np.atleast_1d(a))
    r = stability.release_rates(s, pb.m, pb.work_shift)
    return dict(p=s.p, dn=s.dn, dw=s.dw, h=s.h, dp=s.dp_da, ddn=s.ddn_da, ddw=s.ddw_da, p_k=s.p_k, dn_k=s.dn_k,
                gP=r["load"], gd=r["grip"], gw=r["grip-work"])


@pytest.mark.parametrize("theta, gb, M", [(1.0, 0.5, 0.4), (3.0, 0.2, 1.0), (INF, 1.0, 0.3)])
def test_normalised_equilibria_match_closed_form(theta, gb, M):
    """p, delta/Delta, h(pi) and the fixed-arc derivatives to 1e-10; slopes (central differences in a) to 1e-7."""
    a = np.array([1e-3, 0.05, 0.3, 2.0])
    m = M if math.isinf(theta) else M * theta
    ref, num = star("closed", a, m, theta, gb), star("numeric", a, m, theta, gb)
    for k, tol in dict(p=1e-10, dn=1e-10, h=1e-10, dw=1e-10, p_k=1e-10, dn_k=1e-10, dp=1e-7, ddn=1e-7, ddw=1e-7,
                       gP=1e-7, gd=1e-7).items():
        assert np.max(np.abs(num[k] - ref[k]) / np.abs(ref[k])) < tol, k


def test_a_crit_of_the_solver_is_the_closed_form_pole():
    for th in (0.7, 1.0, 3.0):
        assert abs(receding_contact(th, 0.3, 0.0) / jkrcyl.a_crit(th) - 1) < 1e-12


# --- spectral convergence ----------------------------------------------------------------------------------
@pytest.mark.parametrize("ar", [0.0, 0.1167, -0.1167, 0.375])
@pytest.mark.parametrize("eps", [0.3, 1.5, 2.5])
def test_spectral_convergence_in_the_nodes(ar, eps):
    """Unit cases [P*, B*, k] and h(pi): errors against n = 96 fall with n down to 1e-11; a fall is required only
    while the error is above the roundoff floor (1e-14: below, the order of two ~1e-16 errors is chance)."""
    ref = arcs.two_patch_linear(eps, 0.0, 1.0, 0.4, 96, ar)
    errs = []
    for n in (8, 16, 24, 32, 48):
        lin = arcs.two_patch_linear(eps, 0.0, 1.0, 0.4, n, ar)
        e = max(np.max(np.abs(lin.q0 - ref.q0)), np.max(np.abs(lin.q1 - ref.q1)),
                abs(lin.gap(math.pi, 0.3)[0] - ref.gap(math.pi, 0.3)[0]))
        errs.append(e / max(1.0, np.max(np.abs(ref.q1))))
    assert errs[-1] < 1e-11
    falls = lambda e0, e1: e0 > e1 or max(e0, e1) < 1e-14
    assert errs[2] < 1e-7 and falls(errs[0], errs[1]) and falls(errs[1], errs[2]), errs


# --- JKR superposition identities (any linear frictionless contact) ---------------------------------------
# At fixed arc, the adhesive state = the adhesionless state (P_H, delta_H; no edge singularity) + a punch of
# the same arc pressed by delta - delta_H.  Along the adhesionless curve dP_H = S d delta_H with S the punch
# stiffness, so  P - P_H = S (delta - delta_H),  S = (dP_H/da)/(d delta_H/da).  The punch's elastic energy
# (P - P_H)^2/(2S) released as the arc l = 2 R eps shrinks gives w = -1/2 (P - P_H)^2 d(1/S)/dl.  Normalised
# (p = P beta*/(4 pi Delta), dn = delta/Delta, m = M vartheta): m^2 = -1/4 (p - p_H)^2 d(1/S)/d eps.
def _identities(star, a, m, approach="dn"):
    """approach: 'dn' (the paper's delta) or 'dw' (the work-conjugate delta_work = delta + c P, derive/green.py;
    the identities hold for both since they differ by a term linear in P, but S of the conjugate approach is a
    positive stiffness, while d delta_H/da of the paper's delta can vanish, which makes S = dp/d delta ill-conditioned)."""
    slope = "d" + approach
    H = lambda x: star(np.atleast_1d(x), 0.0)
    S = lambda x: (lambda s: s["dp"][0] / s[slope][0])(H(x))
    st, hz = star(np.array([a]), m), H(a)
    dp, dd = st["p"][0] - hz["p"][0], st[approach][0] - hz[approach][0]
    h = 1e-2 * a                                  # 4-point derivative of 1/S in eps = 2 atan(a)
    inv = [1 / S(a + k * h) for k in (-2, -1, 1, 2)]
    d_inv_da = (inv[0] - 8 * inv[1] + 8 * inv[2] - inv[3]) / (12 * h)
    d_inv_deps = d_inv_da * (1 + a * a) / 2
    return (dp - S(a) * dd) / abs(dp), (-0.25 * dp * dp * d_inv_deps) / (m * m) - 1


@pytest.mark.parametrize("approach", ["dn", "dw"])
@pytest.mark.parametrize("a", [0.05, 0.3, 0.7])
def test_superposition_identities_hold_for_the_closed_forms(a, approach):
    i1, i2 = _identities(lambda x, m: star("closed", x, m, 1.0, 0.5), a, 0.3, approach)
    assert abs(i1) < 1e-12 and abs(i2) < 1e-6


@pytest.mark.parametrize("ar", [0.1167, -0.1167, 0.1598, 0.375])
@pytest.mark.parametrize("theta, a", [(1.0, 0.05), (0.67, 0.3), (2.0, 0.7)])
def test_superposition_identities_hold_for_alpha_nonzero(ar, theta, a):
    """The solver's Griffith step (edge coefficient) against the compliance route (no edge coefficient)."""
    i1, i2 = _identities(lambda x, m: star("numeric", x, m, theta, 0.3, ar), a, 0.3, "dw")
    assert abs(i1) < 1e-9 and abs(i2) < 1e-6


# --- first-order perturbation in alpha* (reciprocal theorem) ----------------------------------------------
def test_dP_dalpha_at_zero_by_the_reciprocal_theorem():
    """d(P of the clearance case)/d(alpha*/beta*) at fixed arc and delta = 0 equals
    int int nu_delta(psi) nu_Delta(phi) K1(psi - phi), K1 = pi sin|t| - t sin t (the alpha* part of the kernel
    derived from the Michell modes, DERIVATION.md 'The kernel: sum of the modes'; the paper's delta, rims'
    reference, has no alpha* in its cos t term), with the alpha* = 0 unit solutions (validated against the
    closed forms above)."""
    eps, th, gb = 1.2, 1.0, 0.4
    lin = arcs.two_patch_linear(eps, 0.0, th, gb, 48, 0.0)
    N = 1200
    s = np.cos((2 * np.arange(1, N + 1) - 1) * np.pi / (2 * N))
    phi = eps * s
    u_D = lin.pressure(phi, 0.0) * eps * np.sqrt(1 - s * s) * th       # nu dphi = u ds/sqrt(1 - s^2)
    u_d = (lin.pressure(phi, 1.0) - lin.pressure(phi, 0.0)) * eps * np.sqrt(1 - s * s) * th
    t = phi[:, None] - phi[None, :]
    K1 = math.pi * np.sin(np.abs(t)) - t * np.sin(t)
    ref = (math.pi / N) ** 2 * u_d @ K1 @ u_D / th                     # per vartheta: P* normalisation
    h = 1e-4
    fd = (arcs.two_patch_linear(eps, 0.0, th, gb, 48, h).q0[0]
          - arcs.two_patch_linear(eps, 0.0, th, gb, 48, -h).q0[0]) / (2 * h)
    assert abs(fd / ref - 1) < 1e-4


# --- public functions with alpha* != 0 ---------------------------------------------------------------------
@pytest.mark.parametrize("name", list(PAIRS))
def test_state_fields_and_equilibrium_for_alpha_pairs(name):
    c = pair(name, Delta=1e-5, w=0.5)
    assert not c.materials.closed_form and c.materials.alpha_ratio != 0
    st = c.state([0.05, 0.3, 0.8])
    for k in FIELDS:
        assert np.all(np.isfinite(getattr(st, k))), k
    np.testing.assert_allclose(st.G_release, c.w, rtol=1e-12)       # Griffith (3.6)
    # (2.2): R int N cos(phi) dphi = P, by adaptive quadrature of the returned pressure; phi = eps - t^2 takes
    # out the edge's 1/sqrt(eps - phi), so the integrand is smooth (no roundoff warning from quad)
    from scipy.integrate import quad
    for a, P in zip(st.a, st.P):
        eps = 2 * math.atan(a)

        def f(t):
            x = eps - t * t
            return 2 * t * sum(c.pressure(a, np.array([x]), parts=True)[i][0] for i in (0, 1)) * math.cos(x)
        val = 2 * c.R * quad(f, 0, math.sqrt(eps), limit=200, epsabs=0, epsrel=1e-11)[0]
        assert abs(val - P) < 1e-7 * abs(c.load_scale)


@pytest.mark.parametrize("name", ["steel pin in aluminium", "steel roller in polymer"])
def test_gap_for_alpha_pairs(name):
    c = pair(name, Delta=1e-5, w=0.05)
    a = 0.3
    eps = 2 * math.atan(a)
    st = c.state(a)
    assert st.feasible
    assert abs(c.gap(a, math.pi) - st.h_pi) < 1e-12 * c.Delta
    phi = np.linspace(eps + 1e-3, math.pi, 200)
    assert np.all(c.gap(a, phi) > 0)
    # adhesive end: the gap opens like sqrt(phi - eps) (JKR), so it is ~1e-4 Delta at 1e-8 rad
    assert abs(c.gap(a, eps + 1e-12)) < 1e-5 * c.Delta
    assert abs(c.gap(a, eps + 1e-8)) < 1e-3 * c.Delta
    assert np.all(c.gap(a, [0.0, 0.5 * eps]) == 0)


def test_curve_solve_and_adherence_for_an_alpha_pair():
    c = pair("steel pin in aluminium", Delta=1e-5, w=0.5)
    M, th, gb = eq.from_contact(c)
    ar = c.materials.alpha_ratio
    cv = c.curve(n=40)
    st = c.state(cv.a)
    np.testing.assert_allclose(cv.P_star, st.P_star, rtol=1e-12)
    np.testing.assert_allclose(cv.delta_over_Delta, st.delta_over_Delta, rtol=1e-12)
    target = float(cv.P_star[20])
    roots = eq.solve_load(M, th, target, gb=gb, alpha_ratio=ar, n=60)
    assert any(abs(r / cv.a[20] - 1) < 1e-9 for r in roots)
    roots = eq.solve_approach(M, th, float(cv.delta_over_Delta[20]), gb=gb, alpha_ratio=ar, n=60)
    assert any(abs(r / cv.a[20] - 1) < 1e-9 for r in roots)
    (pt,) = eq.adherence(M, th, "load", gb=gb, alpha_ratio=ar, regimes=("sub-critical",))
    near = eq.curve(M, th, gb=gb, alpha_ratio=ar, a=pt.a * np.array([0.99, 1.0, 1.01]))
    assert near.P_star[1] <= near.P_star[0] and near.P_star[1] <= near.P_star[2]   # a minimum of P*


def test_cli_physical_inputs_use_the_solver(capsys):
    from jkrcyl.cli import main
    args = ["curve", "--E", "70e9", "--nu", "0.33", "--E-I", "210e9", "--nu-I", "0.3", "--R", "0.01",
            "--Delta", "1e-5", "--w", "0.5", "--n", "3"]
    assert main(args) == 0
    rows = capsys.readouterr().out.strip().splitlines()[2:]
    c = pair("steel pin in aluminium", Delta=1e-5, w=0.5)
    c = jkrcyl.Contact(R=0.01, Delta=1e-5, w=0.5, materials=c.materials)
    a = np.array([float(r.split(",")[0]) for r in rows])
    P = np.array([float(r.split(",")[3]) for r in rows])
    # The CLI prints 10 significant digits (relative rounding <= 5e-10 on a and on P*), so the solver's P* at
    # the printed a may differ from the printed P* by that rounding times (1 + |d ln P*/d ln a|).
    h = 1e-6
    slope = (c.state(a * (1 + h)).P_star - c.state(a * (1 - h)).P_star) / (2 * h)
    P_ref = c.state(a).P_star
    assert np.all(np.abs(P - P_ref) <= 6e-10 * (np.abs(P_ref) + np.abs(slope)))
    # ... a bound far tighter than the difference to the closed form as if alpha* = 0 (so the test can fail)
    as_if_0 = eq.curve(c.M, c.theta, a=a, alpha_ratio=0.0, gb=eq.incompressible_gb(c.theta)).P_star
    assert np.all(np.abs(as_if_0 - P_ref) > 1e-3 * np.abs(P_ref))


def test_alpha_ratio_range_is_validated():
    with pytest.raises(ValueError, match="alpha_ratio"):
        eq.curve(0.3, 1.0, alpha_ratio=1.5, gb=eq.incompressible_gb(1.0))


def test_two_patch_answers_for_the_pair_not_for_alpha_zero(monkeypatch):
    """Contact.two_patch/confined_events pass the pair's alpha*/beta* on (the alpha* != 0 physics itself is
    checked in tests/test_twopatch.py); the tracer is replaced by a recorder to keep this test fast."""
    from jkrcyl.analysis import confined, tracing
    c = pair("steel pin in aluminium", Delta=1e-5, w=0.5)
    seen = []
    monkeypatch.setattr(tracing, "branches", lambda pb, *a, **k: seen.append(pb.alpha_ratio) or [])
    monkeypatch.setattr(confined, "confined_events", lambda pb, *a, **k: seen.append(pb.alpha_ratio))
    c.two_patch()
    c.confined_events()
    assert seen == [c.materials.alpha_ratio] * 2 and seen[0] != 0


def test_curve_slopes_along_a_long_grid_match_closed_form():
    """The collocation solver on a 2000-point grid (slopes per point, never across grid points): 1e-5 there."""
    a = eq.curve(0.4, 1.0, n=2000, gb=0.5).a
    ref, num = star("closed", a, 0.4, 1.0, 0.5), star("numeric", a, 0.4, 1.0, 0.5)
    for k, tol in dict(p=1e-10, dn=1e-10, h=1e-10, dp=1e-5, ddn=1e-5, gP=1e-5, gd=1e-5).items():
        scale = np.abs(ref[k]) + np.median(np.abs(ref[k]))      # slopes cross zero (stationary points)
        assert np.max(np.abs(num[k] - ref[k]) / scale) < tol, k
