"""Load-contact size kernels (issue: foundation) against the printed formulas and against limits.

References: the hand-typed formulas of jkrcyl.paper evaluated with mpmath at 50 digits
((4.4), (4.5a), (4.5b), (2.6), (3.4)); the adhesionless (7.1), (7.2) and Barquins (7.4) limits;
a 50-digit root of the a_crit equation.
"""
import math

import mpmath as mp
import numpy as np
import pytest

import jkrcyl
from reference import paper
from jkrcyl.generated.load import LoadState, load_state, load_state_into, normalised_load, stress_intensity

mp.mp.dps = 50
A_GRID = np.geomspace(1e-6, 50, 61)
THETAS = (0.5, 0.7, 1.0, 2.0, 5.0)


def rel(x, ref):
    return abs(float((mp.mpf(x) - ref) / ref))


def away_from_crit(a, theta, distance=1e-6):
    ac = jkrcyl.a_crit(theta)
    return abs(a - ac) > 1e2 * distance * ac


def mp_state(a, Delta, R, beta, theta, zeta):
    """(4.4), (4.5a), (4.5b), (2.6) at 50 digits from the hand-typed print."""
    a, Delta, R, beta, theta, zeta = map(mp.mpf, (a, Delta, R, beta, theta, zeta))
    P = paper.P_44(a, Delta, beta, theta, zeta, lib=mp)
    B = paper.B_45a(a, Delta, R, beta, theta, zeta, lib=mp)
    C = paper.C_45b(a, Delta, R, beta, theta, zeta, lib=mp)
    c0, c1 = -Delta - R * beta * B / (8 * mp.pi * theta), beta * P / (2 * mp.pi)
    return dict(P=P, B=B, C=C, c0=c0, c1=c1, r0=paper.r0_212(a, c0, c1, C, R, beta, lib=mp))


@pytest.mark.parametrize("theta", THETAS)
@pytest.mark.parametrize("M", [0.0, 0.3, 1.0, 2.0])
def test_normalised_load_vs_44(theta, M):
    """P*(a; M, vartheta) kernel vs (4.4) times beta/(4 pi Delta vartheta): <= 1e-12 relative.

    The tolerance is relative to the larger of the two terms of the numerator (their difference
    is the physical zero-load cancellation, not a kernel error).
    """
    for a in A_GRID:
        if not away_from_crit(a, theta):
            continue
        am = mp.mpf(a)
        ref = paper.P_44(am, 1, 1, theta, 4 * mp.pi * theta * M, lib=mp) / (4 * mp.pi * theta)
        E2 = 1 + am**2
        scale = 2 * E2 * (am**2 + M * mp.sqrt(am) * (am**2 + 2 * theta)) / abs(paper.a_crit_equation(am, theta, mp))
        assert abs(normalised_load(M, a, theta) - ref) <= 1e-12 * scale, (a, theta, M)


@pytest.mark.parametrize("theta", THETAS + (math.inf,))
@pytest.mark.parametrize("part", ["clearance", "adhesion"])
def test_load_state_50_digits(theta, part):
    """Each output of load_state within 1e-13 relative of 50-digit (4.4)-(4.5), a in [1e-8, 1e4].

    The state is linear in (Delta, zeta); each part is checked alone so no cancellation between
    them hides or inflates an error.  vartheta = inf uses a 1e40 stand-in at 50 digits (terms of
    order 1/vartheta, e.g. the adhesion part of c0, are then compared with an absolute 1e-30).
    """
    Delta, zeta = (0.01, 0.0) if part == "clearance" else (0.0, 0.02)
    R, beta = 1.3, 2.1
    th_mp = mp.mpf(10) ** 40 if math.isinf(theta) else theta
    for a in np.geomspace(1e-8, 1e4, 97):
        if not math.isinf(theta) and not away_from_crit(a, theta):
            continue
        got = load_state(Delta, R, a, beta, 1 / theta, zeta)
        ref = mp_state(a, Delta, R, beta, th_mp, zeta)
        for value, name in zip(got, ("P", "B", "C", "c0", "c1", "r0")):
            if name == "r0" and zeta == 0:
                assert value == 0          # Griffith with w = 0; the print gives 0 up to 50-digit rounding
                continue
            floor = 1e-30 if math.isinf(theta) else 0.0
            assert abs(value - ref[name]) <= 1e-13 * abs(ref[name]) + floor, (name, a, theta, part)


def test_error_near_a_crit_follows_condition_number():
    """Within 1e-6 relative of a_crit P has a pole: the error grows like the condition number
    kappa_P = |a D'(a)/D(a)| times a few ulp, measured here (not a kernel defect)."""
    theta = 1.0
    ac = jkrcyl.a_crit(theta)
    for d in (1e-3, 1e-4, 1e-5, 1e-6):
        a = ac * (1 - d)
        am = mp.mpf(a)
        ref = paper.P_44(am, 1, 1, theta, 0, lib=mp)
        D = paper.a_crit_equation(am, theta, mp)
        cond = float(abs(am * (2 * am / (1 + am**2) + 8 * am**3) / D))
        assert rel(load_state(1.0, 1.0, a, 1.0, 1 / theta, 0.0)[0], ref) <= 20 * cond * 2.2e-16


def test_array_form_equals_scalar():
    a = np.geomspace(1e-4, 30, 17)
    arrays = LoadState(*(np.empty(a.size) for _ in LoadState._fields))
    load_state_into(arrays, 0.01, 1.0, a, 3.0, 1.0, 0.02)
    for i, ai in enumerate(a):
        assert tuple(col[i] for col in arrays) == load_state(0.01, 1.0, ai, 3.0, 1.0, 0.02)


def test_griffith_condition_holds_at_equilibrium():
    """K* of (3.4) from the solved constants equals sqrt(4w/(pi A)) of (3.6a), and G* = w (3.5)."""
    m = jkrcyl.Materials(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0)
    c = jkrcyl.Contact(R=1.0, Delta=0.01, w=1e-4, materials=m)
    s = c.state(np.array([0.05, 0.4, 0.8, 1.5, 4.0]))
    assert np.allclose(s.K, paper.K_griffith_36a(c.w, c.beta), rtol=1e-10, atol=0)
    assert np.allclose(s.G_release, c.w, rtol=1e-10, atol=0)
    K, G = stress_intensity(float(s.C[1]), 1.0, 0.4, c.beta, float(s.c0[1]), float(s.c1[1]))
    assert math.isclose(K, paper.K_34(0.4, s.c0[1], s.c1[1], s.C[1], 1.0, c.beta), rel_tol=1e-12)


# --- limits ------------------------------------------------------------------------------------
def test_adhesionless_71_72():
    """w = 0: P = (7.1) and B R/P = (7.2) -> 1 as a -> 0."""
    G, kappa, G_I, kappa_I = 2.0, 2.2, 1.0, 1.6
    m = jkrcyl.Materials(G=G, kappa=kappa, G_I=G_I, kappa_I=kappa_I)
    c = jkrcyl.Contact(R=1.2, Delta=0.02, w=0.0, materials=m)
    for a in (1e-5, 1e-3, 0.1, 0.5, 0.8):
        s = c.state(a)
        am = mp.mpf(a)
        assert rel(s.P, paper.P_71(am, mp.mpf("0.02"), G, kappa, m.beta, lib=mp)) < 1e-12
        assert rel(s.B * c.R / s.P, paper.BR_over_P_72(am, lib=mp)) < 1e-12
    assert abs(c.state(1e-6).B * c.R / c.state(1e-6).P - 1) < 1e-11


def test_barquins_half_plane_limit_74():
    """Small a: (4.4) -> (7.4) with relative error O(a^2) (the neglected 1 + a^2 and L, a^4 terms)."""
    m = jkrcyl.Materials(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0)
    c = jkrcyl.Contact(R=1.0, Delta=0.01, w=1e-5, materials=m)
    for a in (1e-3, 3e-3, 1e-2, 3e-2):
        P = c.state(a).P
        P_h = paper.P_74(a, c.Delta, c.R, c.beta, c.w)
        scale = abs(paper.P_74(a, c.Delta, c.R, c.beta, 0.0)) + abs(P_h - paper.P_74(a, c.Delta, c.R, c.beta, 0.0))
        assert abs(P - P_h) <= 5 * (a**2 + c.Delta / c.R) * scale, a


def test_a_crit_theta_1():
    """Section 4: a_crit(1) = 0.9135... (the paper's eps = 84.823 deg is 2 atan(0.9135) of the rounded a)."""
    ref = mp.findroot(lambda u: paper.a_crit_equation(u, 1, lib=mp), mp.mpf("0.9"))
    ac = jkrcyl.a_crit(1.0)
    assert rel(ac, ref) < 4e-16
    assert round(ac, 4) == 0.9136 and abs(ac - 0.9135) < 1e-4
    assert round(math.degrees(2 * math.atan(0.9135)), 3) == 84.823
    for theta in (0.5, 0.51, 2.0, 5.0, 100.0):
        ref = mp.findroot(lambda u: paper.a_crit_equation(u, theta, lib=mp), mp.mpf(theta) ** 0.25)
        assert rel(jkrcyl.a_crit(theta), ref) < 4e-16
    assert jkrcyl.a_crit(math.inf) == math.inf
