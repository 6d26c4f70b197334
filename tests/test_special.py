"""Issue 5: the special cases of section 7, each against its printed formula and against the
general kernels in the corresponding limit."""
import math

import mpmath as mp
import numpy as np
import pytest

import jkrcyl
from jkrcyl import equilibria as eq
from reference import paper as pp
from jkrcyl import special

A = np.array([1e-3, 0.05, 0.3, 0.7, 0.9])


def _mp(formula, *args):
    """A printed formula of jkrcyl.paper evaluated at 50 digits."""
    with mp.workdps(50):
        return float(formula(*(mp.mpf(v) for v in args), lib=mp))


def _identical():
    return jkrcyl.Materials(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0)


def test_adhesionless_71_72():
    m = _identical()
    c = jkrcyl.Contact(R=1.5, Delta=0.01, w=0.0, materials=m)
    P = special.adhesionless_load(A, c.Delta, m.G, m.kappa, m.beta)
    # float64 evaluation of the printed (7.1) vs the same print at 50 digits
    np.testing.assert_allclose(P, [_mp(pp.P_71, x, c.Delta, m.G, m.kappa, m.beta) for x in A], rtol=1e-14)
    s = c.state(A)
    np.testing.assert_allclose(P, s.P, rtol=1e-12)
    BR = special.adhesionless_BR_over_P(A)
    np.testing.assert_allclose(BR, [_mp(pp.BR_over_P_72, x) for x in A], rtol=1e-9)
    np.testing.assert_allclose(BR, s.B * c.R / s.P, rtol=1e-11)
    assert abs(special.adhesionless_BR_over_P(1e-5) - 1) < 1e-9      # -> 1 as a -> 0


def test_half_plane_74_and_small_a_limit():
    R, Delta, w, beta = 1.5, 0.01, 2e-4, 3.0
    A_ = beta / (2 * math.pi)
    a = np.array([1e-4, 1e-3, 1e-2])
    got = special.half_plane_load(a, Delta, R, beta, w)
    np.testing.assert_allclose(got, [_mp(pp.P_74, x, Delta, R, beta, w) for x in a], rtol=1e-13)
    # (7.3c) P_h beta = 4 pi Delta a^2 - 2 beta sqrt(a) zeta, i.e. (7.4) with R_D/(R R*) = Delta/R^2
    zeta = math.sqrt(2 * w * R / A_)
    np.testing.assert_allclose(got, (4 * math.pi * Delta * a**2 - 2 * beta * np.sqrt(a) * zeta) / beta, rtol=1e-12)
    # normalised: the general P* tends to P_h* with a relative error O(a^2)
    for th in (0.5, 1.0, 3.0):
        M = 0.2
        cyl = eq.curve(M, th, "sub-critical", a=a, gb=eq.incompressible_gb(th)).P_star
        half = special.half_plane_P_star(a, M, th)
        assert np.all(np.abs(cyl / half - 1) < 5 * a**2 / th + 5 * a**1.5 * 0)


def test_half_plane_adherence_formula():
    for M, th in ((0.1, 1.0), (0.4, 0.5), (0.03, 2.0)):
        a_m, P_m = special.half_plane_adherence(M, th)
        assert abs(P_m - (-1.5) * (th * M**4 / 2) ** (1 / 3)) < 1e-15
        a = np.linspace(a_m * 0.5, a_m * 1.5, 20001)
        assert abs(special.half_plane_P_star(a, M, th).min() - P_m) < 1e-9 * abs(P_m)
        assert abs(special.half_plane_P_star(a_m, M, th) - P_m) < 1e-14
    # the cylindrical adherence tends to the half-plane one as M -> 0 (small contact)
    for th in (0.5, 1.0):
        for M in (1e-3, 1e-2):
            (p,) = eq.adherence(M, th, "load", regimes=("sub-critical",), gb=eq.incompressible_gb(th))
            a_m, P_m = special.half_plane_adherence(M, th)
            assert abs(p.P_star / P_m - 1) < 3 * a_m
            assert abs(p.a / a_m - 1) < 3 * a_m


def test_rubbery_75_76_77_and_general_kernels():
    M_R = 0.35
    a = np.array([0.01, 0.2, 0.6, 1.5, 2.5])
    P_R = special.rubbery_P_star(a, M_R)
    np.testing.assert_allclose(P_R, [_mp(pp.P_R_star_76, x, M_R) for x in a], rtol=1e-14)
    # vartheta = inf in the general kernels (inv_theta = 0)
    np.testing.assert_allclose(eq.curve(M_R, math.inf, a=a, gb=eq.incompressible_gb(math.inf)).P_star, P_R, rtol=1e-12, atol=1e-15)
    # vartheta -> inf: vartheta P* at M = M_R/vartheta tends to P_R*
    th = 1e9    # the correction is O(a^4/vartheta)
    np.testing.assert_allclose(eq.curve(M_R / th, th, a=a, gb=eq.incompressible_gb(th)).P_star * th, P_R, rtol=1e-6)
    # (7.5) in physical units vs a Contact with a rigid cradle
    m = jkrcyl.Materials(G=math.inf, kappa=2.0, G_I=1.0, kappa_I=1.0)
    c = jkrcyl.Contact(R=1.5, Delta=0.01, w=1e-4, materials=m)
    np.testing.assert_allclose(special.rubbery_load(a, c.Delta, c.beta, c.w, c.R), c.state(a).P, rtol=1e-12)
    np.testing.assert_allclose(c.state(a).P_star, special.rubbery_P_star(a, c.M), rtol=1e-12)
    # lift-off (7.7) = the minimum of P_R*: same point as the general adherence search
    for M in (0.05, 0.35, 2.0):
        a_l, P_l = special.rubbery_lift_off(M)
        # sqrt(a) dP_R*/da of (7.6), differentiated by hand, vanishes there as well
        slope = 2 * a_l * (a_l**2 - 2 * M * math.sqrt(a_l)) + (1 + a_l**2) * (2 * a_l - M / math.sqrt(a_l))
        assert abs(math.sqrt(a_l) * slope) < 1e-13 * max(1, M)
        assert abs(pp.lift_off_77(a_l, M)) < 1e-13 * max(1, M)
        (p,) = eq.adherence(M, math.inf, "load", gb=eq.incompressible_gb(math.inf))
        assert abs(p.a - a_l) < 1e-12 * a_l and abs(p.P_star - P_l) < 1e-13 * abs(P_l)
    assert math.isnan(special.rubbery_lift_off(0.0)[0])


def test_neat_fit():
    # Q* = P/zeta* from (4.4) at Delta = 0, vs a Contact with Delta = 0
    m = _identical()
    c = jkrcyl.Contact(R=1.5, Delta=0.0, w=1e-4, materials=m)
    a = np.array([0.3, 0.8, 1.2, 2.0, 5.0])
    np.testing.assert_allclose(special.neat_fit_Q(a, c.theta), c.state(a).P / c.zeta, rtol=1e-12)
    # Delta -> 0 limit of the general kernels
    c2 = jkrcyl.Contact(R=1.5, Delta=1e-12, w=1e-4, materials=m)
    np.testing.assert_allclose(c2.state(a).P / c2.zeta, special.neat_fit_Q(a, c.theta), rtol=1e-6)
    with pytest.raises(ValueError, match="Delta"):
        c.M
    # section 7.3: only super-critical equilibria satisfy the gap inequality, with P > 0
    for th in (0.5, 1.0):
        ac = jkrcyl.a_crit(th)
        sub = np.linspace(0.02, 0.98, 30) * ac
        assert (special.neat_fit_Q(sub, th) < 0).all() and (special.neat_fit_gap_pi(sub, th) < 0).all()
        cv = special.neat_fit_curve(th, 200)
        assert (cv["Q_star"] > 0).all() and cv["feasible"].all() and (cv["a"] > ac).all()
        # Q* -> inf at the critical angle (no adhesion or infinite load)
        assert special.neat_fit_Q(ac * (1 + 1e-9), th) > 1e6
