"""The gap h(phi) of (5.9)-(5.10): closed-form kernels of jkrcyl.generated.gap vs quadrature.

Reference values:
* "quadrature" = mpmath tanh-sinh quadrature (30 digits) of (5.2)/(5.9) and (5.3)/(5.10) with the
  pressure (5.4), psi = eps sin(u) to make the 1/sqrt contact ends smooth, and a breakpoint at
  psi = phi for the logarithm of (5.2) inside the contact.  The state (P, B, c0, c1, r0) is the
  closed form (4.4), (4.5a), (2.6) and the Griffith coefficient r0 = -E zeta sqrt(a)/(pi R) of (3.6b).
* "50-digit closed form" = the compact closed form of the derivation report evaluated by mpmath at
  50 digits at exactly the float64 inputs (accuracy of the float64 kernels).
* Figures 2, 5, 11 of the paper (vartheta = 1): which branches are dashed (infeasible).
"""
import math

import mpmath as mp
import numpy as np
import pytest

from reference import paper
from jkrcyl.generated import gap as G

# three material pairs with alpha* = 0 (h depends on beta*, vartheta only; delta on kappa_I, G_I too):
# (beta*, 1/vartheta, kappa_I, 1/G_I) with (kappa_I + 1)/(2 G_I) = beta*(1 - 1/(2 vartheta))
MATERIALS = {
    "identical": (3.0, 1.0, 2.0, 1.0),             # kappa = kappa_I = 2, G = G_I = 1
    "rubber disk in rigid cradle": (1.0, 0.0, 1.0, 1.0),   # G -> inf, kappa_I = 1 (section 7.2)
    "rigid disk in compliant hole": (1.0, 2.0, 2.0, 0.0),  # G_I -> inf, kappa = 1, vartheta = 1/2
}
R, DELTA = 1.0, 1e-3


def mp_state(a, beta, t, zeta, delta_=DELTA):
    """The load solution at mp.dps: jkrcyl.paper.load_solution_t ((4.4), (4.5a), (2.6), (3.6b))."""
    a, beta, t, zeta, d = (mp.mpf(v) for v in (a, beta, t, zeta, delta_))
    st = paper.load_solution_t(a, d, mp.mpf(R), beta, t, zeta, lib=mp)
    st.update(a=a, E=mp.sqrt(1 + a * a), eps=2 * mp.atan(a), beta=beta, Delta=d, k=4 / (R * beta))
    return st


def mp_int_N(st, f, breaks=()):
    """int_{-eps}^{eps} N(psi) f(psi) dpsi, N of (5.4), psi = eps sin(u)."""
    eps = st["eps"]
    ce = mp.cos(eps / 2)

    def g(u):
        psi = eps * mp.sin(u)
        s = mp.sqrt(mp.sin(eps * mp.sin(mp.pi / 4 - u / 2)**2) * mp.sin(eps * mp.cos(mp.pi / 4 - u / 2)**2))
        cp = mp.cos(psi / 2)
        N = st["r0"] * cp * ce / s + st["k"] * st["c1"] * cp * s - st["k"] * st["c0"] * mp.log((cp + s) / ce)
        return N * f(psi) * eps * mp.cos(u)
    return mp.quad(g, sorted({-mp.pi / 2, mp.mpf(0), mp.pi / 2} | {mp.asin(b / eps) for b in breaks}))


def mp_displacement(st, phi, kI, iG):
    """(5.2): v_r - u_r = -(R/4pi) int N [beta c log(2 - 2c) + c/G_I + (kappa_I + 1)/(2 G_I)], c = cos(phi - psi)."""
    def kern(psi):
        c = mp.cos(phi - psi)
        return st["beta"] * c * mp.log(4 * mp.sin((phi - psi) / 2)**2) + c * iG + (kI + 1) * iG / 2
    return -R / (4 * mp.pi) * mp_int_N(st, kern, [phi] if abs(phi) < st["eps"] else [])


def mp_gap(st, phi, kI, iG):
    """(5.9) with delta = (5.2) at phi = 0, i.e. (5.3)."""
    phi = mp.mpf(phi)
    delta = mp_displacement(st, mp.mpf(0), kI, iG)
    return st["Delta"] * (1 - mp.cos(phi)) - delta * mp.cos(phi) + mp_displacement(st, phi, kI, iG)


def mp_gap_pi_510(st, kI, iG):
    """(5.10) literally, with delta from (5.3) literally (both integrals by quadrature)."""
    gI = (kI + 1) * iG / 2
    # int_0^eps N g 4 dpsi = 2 int_{-eps}^{eps} N g dpsi for even g
    J = mp_int_N(st, lambda p: 2 * mp.cos(p) * mp.log(2 * abs(mp.sin(p / 2))), [0])
    J_pi = mp_int_N(st, lambda p: 2 * mp.cos(p) * mp.log(2 * mp.cos(p / 2)))
    delta = -R / (4 * mp.pi) * (gI * st["B"] + st["P"] * iG / R + st["beta"] * J)
    return 2 * st["Delta"] + delta - R / (4 * mp.pi) * (gI * st["B"] - st["P"] * iG / R - st["beta"] * J_pi)


def zeta_of(M, beta, t):
    """M = sqrt(w A R)/(sqrt(2) Delta vartheta) <=> zeta* = 4 pi Delta vartheta M / beta* (section 6)."""
    return 4 * math.pi * DELTA * M / (beta * t) if t > 0 else 4 * math.pi * DELTA * M / beta


CASES = [(name, a, M) for name in MATERIALS for a, M in ((0.05, 0.3), (0.6, 0.0), (0.6, 0.5), (2.5, 0.4))]


@pytest.mark.parametrize("name,a,M", CASES)
def test_h_pi_vs_quadrature_of_510(name, a, M):
    beta, t, kI, iG = MATERIALS[name]
    z = zeta_of(M, beta, t)
    with mp.workdps(30):
        ref = mp_gap_pi_510(mp_state(a, beta, t, z), mp.mpf(kI), mp.mpf(iG))
    got = G.gap_pi(DELTA, a, beta, t, z)
    assert abs(got - ref) <= 1e-12 * max(abs(ref), DELTA)
    assert G.gap(DELTA, a, beta, t, math.pi, z) == pytest.approx(float(ref), rel=1e-12, abs=1e-12 * DELTA)


@pytest.mark.parametrize("name,a,M", CASES[::2])
def test_h_phi_vs_quadrature_of_59(name, a, M):
    beta, t, kI, iG = MATERIALS[name]
    z = zeta_of(M, beta, t)
    eps = 2 * math.atan(a)
    with mp.workdps(30):
        st = mp_state(a, beta, t, z)
        for frac in (0.01, 0.3, 0.8):
            phi = eps + (math.pi - eps) * frac
            for p in (phi, -phi, 2 * math.pi - phi):                 # even and 2 pi periodic
                ref = mp_gap(st, mp.mpf(p), mp.mpf(kI), mp.mpf(iG))
                got = G.gap(DELTA, a, beta, t, p, z)
                assert abs(got - ref) <= 1e-12 * max(abs(ref), DELTA), (p, got, ref)


@pytest.mark.parametrize("a,M", [(0.3, 0.2), (1.5, 0.5), (0.8, 0.0)])
def test_inside_contact_identity_52(a, M):
    """(5.2) inside the contact is delta cos(phi) - Delta (1 - cos(phi)) (5.1): quadrature of (5.9) vanishes."""
    beta, t, kI, iG = MATERIALS["identical"]
    z = zeta_of(M, beta, t)
    eps = 2 * math.atan(a)
    with mp.workdps(30):
        st = mp_state(a, beta, t, z)
        for frac in (0.0, 0.4, 0.9):
            h_in = mp_gap(st, mp.mpf(eps * frac), mp.mpf(kI), mp.mpf(iG))
            assert abs(h_in) <= 1e-25 * DELTA
            assert G.gap(DELTA, a, beta, t, eps * frac, z) == 0.0


def mp_closed(a, beta, t, z, phi):
    st = mp_state(a, beta, t, z)
    E, se = st["E"], st["a"] / st["E"]
    S = abs(mp.sin(mp.mpf(phi) / 2))
    if S <= se:
        return mp.mpf(0)
    sg = mp.sqrt((S - se) * (S + se))
    return -(2 * E**2 * st["c0"] + st["c1"]) * S * sg - st["c1"] * mp.cos(mp.mpf(phi)) * mp.asinh(sg / se)


def test_float64_accuracy_sweep():
    """Kernels vs the 50-digit closed form at the same inputs, a in [1e-8, 1e4], w = 0 and w > 0.

    h(pi): relative 1e-13.  h(phi): relative 1e-13 or absolute 1e-13 Delta (where h crosses zero),
    plus the conditioning of h in phi near the contact end, where h ~ sqrt(phi - eps): a rounding of
    phi or eps by one ulp moves h by |h| ulp/(2 (phi - eps)) whatever the formula.
    """
    worst_pi = worst = 0.0
    with mp.workdps(50):
        for a in np.logspace(-8, 4, 25):
            for beta, t, z in ((3.0, 1.0, 0.0), (3.0, 1.0, 2e-3), (1.0, 0.0, 5e-3), (1.0, 2.0, 1e-4)):
                if abs(2 - t * (math.log1p(a * a) + 2 * a**4)) < 1e-6:
                    continue
                ref_pi = mp_closed(a, beta, t, z, mp.pi)
                worst_pi = max(worst_pi, float(abs(G.gap_pi(DELTA, a, beta, t, z) - ref_pi) / abs(ref_pi)))
                eps = 2 * math.atan(a)
                for frac in (1e-3, 0.05, 0.5, 0.95):
                    phi = eps + (math.pi - eps) * frac
                    ref = mp_closed(a, beta, t, z, phi)
                    err = abs(G.gap(DELTA, a, beta, t, phi, z) - ref)
                    cond = abs(ref) * (np.spacing(phi) + np.spacing(eps)) / (phi - eps)
                    worst = max(worst, float(min(err / abs(ref), err / DELTA, (err - 4 * cond) / abs(ref))))
    assert worst_pi <= 1e-13
    assert worst <= 1e-13


@pytest.mark.parametrize("M", [0.0, 0.2, 0.5, 0.8, 1.0])
def test_minimum_over_phi_is_at_pi(M):
    """Dense scan of the exterior arc: min h = min(0, h(pi)) (derivation report), as gap_min says."""
    beta, t = 3.0, 1.0
    z = zeta_of(M, beta, t)
    for a in np.concatenate([np.linspace(0.02, 0.91, 15), np.linspace(0.92, 8.0, 10)]):
        eps = 2 * math.atan(a)
        phi = eps + (math.pi - eps) * np.linspace(0.0, 1.0, 2001)[1:]**2
        h = np.empty(phi.size)
        G.gap_into(h, DELTA, np.full(phi.size, a), beta, t, phi, z)
        h_pi = G.gap_pi(DELTA, a, beta, t, z)
        h_min, phi_min = G.gap_min(DELTA, a, beta, t, z)
        assert h.min() >= min(0.0, h_pi) - 1e-13 * max(abs(h_pi), DELTA)
        assert h_min == pytest.approx(min(0.0, h_pi), rel=1e-14, abs=0.0)
        assert phi_min == (math.pi if h_pi < 0 else pytest.approx(eps))


def p_star(a, M, t=1.0):
    """P* = P beta/(4 pi Delta vartheta) of (4.4) with zeta* from M (section 6)."""
    L = math.log1p(a * a)
    return (1 + a * a) * (2 * t * a * a - 2 * M * math.sqrt(a) * (a * a - L + 2 / t)) / (2 - t * (L + 2 * a**4))


def feasible(a, M, beta=3.0, t=1.0):
    return G.gap_pi(DELTA, a, beta, t, zeta_of(M, beta, t)) >= 0.0


def test_figure_2_subcritical_dashed_branches():
    """Fig. 2 (vartheta = 1, a < a_crit): low M solid, M = 1 dashed; every dashed state has P* < 0."""
    a_crit = 0.9135727915594122           # root of 2 - log(1 + a^2) - 2 a^4 (section 4)
    sub = np.linspace(0.01, 0.995 * a_crit, 120)
    assert all(feasible(a, 0.2) for a in sub[sub < 0.99 * a_crit])
    assert all(not feasible(a, 1.0) for a in sub[sub >= 0.02])      # "dashed" at M = 1 (h(pi) -> 2 Delta as a -> 0)
    for M in (0.4, 0.6, 0.8, 1.0):
        bad = [a for a in sub if not feasible(a, M)]
        assert bad and all(p_star(a, M) < 0 for a in bad)            # overclosure only under upward load
        # once infeasible, the branch stays infeasible up to a_crit (P* -> -infinity there)
        assert all(not feasible(a, M) for a in sub if a >= bad[0])
    # the onset of overclosure moves to smaller contacts as M grows
    onset = [min(a for a in sub if not feasible(a, M)) for M in (0.4, 0.6, 0.8, 1.0)]
    assert onset == sorted(onset, reverse=True)


def test_figures_5_and_11_supercritical():
    """Fig. 5 / 11b (vartheta = 1, a > a_crit): equilibria at M = 0.3, 0.5, 0.8 with a >= 1.2 are feasible;
    Fig. 11a: at M = 0.8 the sub-critical branch overcloses (at phi = pi) before any P* minimum."""
    for M in (0.3, 0.5, 0.8):
        assert all(feasible(a, M) for a in np.linspace(1.2, 10.0, 40))
    sub = np.linspace(0.05, 0.9, 60)
    ps = np.array([p_star(a, 0.8) for a in sub])
    assert np.all(np.diff(ps) < 0)                                   # no minimum: P* keeps decreasing
    assert not feasible(0.3, 0.8) and feasible(0.02, 0.8)
    assert G.gap_min(DELTA, 0.3, 3.0, 1.0, zeta_of(0.8, 3.0, 1.0))[1] == math.pi
