"""The pressure solution, checked by quadrature of its governing integrals (no closed form used).

The kernel's constants (c0, c1, C) define p(x) through (2.12) (hand-typed in jkrcyl.paper);
mpmath quadrature then has to give back B and P of (2.13) and C of (2.9) as the kernel computed
them from (4.4)-(4.5), p must satisfy the Cauchy equation (2.7) at interior points (principal
value by subtraction), and its end behaviour must give the Griffith value of K* (3.3), (3.6a).
"""
import math

import mpmath as mp
import numpy as np
import pytest

import jkrcyl
from reference import paper

mp.mp.dps = 30
CASES = [  # (materials, R, Delta, w, a): sub- and super-critical, three vartheta
    (jkrcyl.Materials(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0), 1.0, 0.01, 1e-4, 0.3),
    (jkrcyl.Materials(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0), 1.0, 0.01, 1e-4, 2.5),
    (jkrcyl.Materials(G=10.0, kappa=2.0, G_I=1.0, kappa_I=1.1), 2.0, 0.05, 3e-3, 0.6),
    (jkrcyl.Materials(G=math.inf, kappa=2.0, G_I=1.0, kappa_I=1.0), 1.0, 0.02, 1e-3, 0.9),
    (jkrcyl.Materials(G=1.0, kappa=1.0, G_I=math.inf, kappa_I=1.7), 1.0, 0.01, 2e-4, 0.05),
]


def pressure_of(contact, a):
    s = contact.state(a)
    c0, c1, C = (mp.mpf(float(v)) for v in (s.c0, s.c1, s.C))
    R, beta = mp.mpf(contact.R), mp.mpf(contact.beta)
    am = mp.mpf(a)

    def p(u):
        """p at x = a sin(u), with sqrt(a^2 - x^2) = a cos(u) exactly."""
        return sum(paper.p_212(am * mp.sin(u), am, c0, c1, C, R, beta, lib=mp, S=am * mp.cos(u)))
    return s, p


def chord_quad(f, a):
    """int_{-a}^{a} f(x) dx with x = a sin(u) (removes the 1/sqrt end singularities); f takes u."""
    a = mp.mpf(a)
    return mp.quad(lambda u: f(u) * a * mp.cos(u), mp.linspace(-mp.pi / 2, mp.pi / 2, 5))


@pytest.mark.parametrize("case", range(len(CASES)))
def test_quadrature_reproduces_B_P_C(case):
    m, R, Delta, w, a = CASES[case]
    contact = jkrcyl.Contact(R=R, Delta=Delta, w=w, materials=m)
    s, p = pressure_of(contact, a)
    am = mp.mpf(a)
    for weight, expected, name in (
            (lambda x: 2 / (1 + x**2), s.B, "B (2.13)"),
            (lambda x: 2 * R * (1 - x**2) / (1 + x**2)**2, s.P, "P (2.13)"),
            (lambda x: 1, s.C, "C (2.9)")):
        value = chord_quad(lambda u: p(u) * weight(am * mp.sin(u)), a)
        size = chord_quad(lambda u: abs(p(u) * weight(am * mp.sin(u))), a)
        assert abs(value - expected) <= 1e-12 * size, name


@pytest.mark.parametrize("case", range(len(CASES)))
def test_singular_integral_equation_27(case):
    """(R beta/2 pi) PV int p(s)/(x - s) ds = -2 c0 atan(x) + c1 2x/(1 + x^2) inside the contact."""
    m, R, Delta, w, a = CASES[case]
    contact = jkrcyl.Contact(R=R, Delta=Delta, w=w, materials=m)
    s, p = pressure_of(contact, a)
    am = mp.mpf(a)
    c0, c1 = mp.mpf(float(s.c0)), mp.mpf(float(s.c1))
    for frac in ("-0.7", "0.1", "0.55"):
        x = am * mp.mpf(frac)
        ux = mp.asin(mp.mpf(frac))
        px = p(ux)
        # PV by subtraction: int (p(s) - p(x))/(x - s) ds + p(x) log((x + a)/(a - x)), s = a sin(u)
        regular = mp.quad(lambda u: (p(u) - px) / (x - am * mp.sin(u)) * am * mp.cos(u),
                          [-mp.pi / 2, ux, mp.pi / 2])
        lhs = R * contact.beta / (2 * mp.pi) * (regular + px * mp.log((x + am) / (am - x)))
        rhs = -2 * c0 * mp.atan(x) + c1 * 2 * x / (1 + x**2)
        assert abs(lhs - rhs) <= 1e-11 * (abs(2 * c0 * mp.atan(x)) + abs(c1 * 2 * x / (1 + x**2))), frac


@pytest.mark.parametrize("case", range(len(CASES)))
def test_end_limit_gives_griffith(case):
    """K* = -sqrt(4 pi R/(1 + a^2)) lim p(x) sqrt(a - x) (3.3) equals sqrt(4 w/(pi A)) (3.6a)."""
    m, R, Delta, w, a = CASES[case]
    contact = jkrcyl.Contact(R=R, Delta=Delta, w=w, materials=m)
    s, p = pressure_of(contact, a)
    am = mp.mpf(a)
    with mp.workdps(60):
        h = mp.mpf(10) ** -40
        u = mp.asin(1 - h)
        limit = p(u) * mp.sqrt(am * h)
        K = -mp.sqrt(4 * mp.pi * R / (1 + am**2)) * limit
    assert abs(K / paper.K_griffith_36a(mp.mpf(w), mp.mpf(contact.beta), lib=mp) - 1) < 1e-10


def test_pressure_kernel_vs_54():
    """Contact.pressure (stable form of (5.4)) vs the printed (5.4) at 30 digits, and 0 outside."""
    contact = jkrcyl.Contact(R=1.0, Delta=0.01, w=1e-4, materials=CASES[0][0])
    a = 0.4
    s = contact.state(a)
    eps = 2 * math.atan(a)
    phi = np.array([-0.99, -0.5, 0.0, 0.3, 0.9, 0.999]) * eps
    nb, nu = contact.pressure(a, phi, parts=True)
    for i, ph in enumerate(phi):
        b_ref, u_ref = paper.N_54(mp.mpf(ph), mp.mpf(a), mp.mpf(float(s.r0)), mp.mpf(float(s.c0)),
                                  mp.mpf(float(s.c1)), 1, mp.mpf(contact.beta), lib=mp)
        assert abs(nb[i] - b_ref) <= 1e-13 * (abs(b_ref) + abs(u_ref))
        assert abs(nu[i] - u_ref) <= 1e-13 * abs(u_ref)
    outside = contact.pressure(a, np.array([1.01 * eps, 3.0]), parts=True)
    assert np.all(outside[0] == 0) and np.all(outside[1] == 0)
