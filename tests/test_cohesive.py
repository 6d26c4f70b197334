"""Maugis-Dugdale states of the pin in the hole (jkrcyl.numerics.cohesive, issue 19).

References, none of them the solver's own numbers: the JKR states of the Griffith solver (jkrcyl.numerics.arcs
.star, itself checked against the closed forms (4.4)-(5.10)) for lambda -> inf; Baney and Hui's (1997) equations
typed in reference/baney_hui.py for the half-plane limit; the total potential energy of the Dugdale law
(elastic energy by Clapeyron plus the interface energy, integrated here from the computed fields) whose
derivative along the states must be the load times the approach; the equilibrium (2.2) and the gap law by
quadrature / on a fine grid of the returned fields; the contactless states (closed form, no collocation) where
the contact branch ends.
"""
import math

import numpy as np
import pytest

import jkrcyl
from jkrcyl.numerics import arcs
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_scales as cs
from jkrcyl.numerics import cohesive_zones as cz
from jkrcyl.model.problem import Problem
from jkrcyl.model.single_patch import solver
from reference import baney_hui as bh

THETA, GB = 1.0, 0.5            # identical bodies, nu = 1/3 -- any alpha* = 0 pair; pairs below
XG, WG = np.polynomial.legendre.leggauss(200)


def jkr_states(eps, m, theta, gb, ar=0.0):
    """The Griffith (JKR) single patch at the contact half-angles eps (m = M vartheta): the library's single-patch
    solver (closed forms at alpha* = 0, tests/test_arcs.py checks the collocation one against them)."""
    M = m if math.isinf(theta) else m / theta
    return solver(Problem(M, theta, gb, ar)).states(np.tan(np.atleast_1d(eps) / 2))


def jkr(eps, m, theta=THETA, gb=GB, ar=0.0):
    """The Griffith (JKR) state at the same contact."""
    st = jkr_states(eps, m, theta, gb, ar)
    return dict(p=st.p[0], dn=st.dn[0], dw=st.dw[0], h=st.h[0])


def values(s):
    return dict(p=s.p, dn=s.delta_over_Delta, dw=s.delta_work_over_Delta, h=s.h_pi_over_Delta)


# --- 1. the JKR limit lambda -> inf ---------------------------------------------------------------------------
@pytest.mark.slow
@pytest.mark.parametrize("theta, gb, m, eps", [(1.0, 0.5, 0.4, 0.8), (math.inf, 1.0, 0.3, 0.5), (3.0, 0.2, 1.2, 1.2)])
def test_jkr_limit_rate_lambda_minus_two(theta, gb, m, eps):
    """The states differ from JKR's by C/lambda^2 + O(lambda^-4) (the zone length m^2/(4 s0^2) is ~lambda^-2
    relative to eps): lambda^2 times the difference agrees at lambda = 50 and 100 to 2 %, and the Richardson
    extrapolation in 1/lambda^2 from lambda = 25, 50, 100 (two levels) is the JKR state to 5e-7 (relative to the
    largest of |X|, 1; measured 1e-9 to 7e-8)."""
    ref = jkr(eps, m, theta, gb)
    st = {lam: values(co.cohesive_state(eps, m, cs.zone_strength(lam, m), theta, gb)) for lam in (25.0, 50.0, 100.0)}
    for k, r in ref.items():
        d50, d100 = (st[50.0][k] - r) * 50.0 ** 2, (st[100.0][k] - r) * 100.0 ** 2
        assert abs(d100 / d50 - 1) < 0.02, (k, d50, d100)
        r1 = [(4 * st[2 * lam][k] - st[lam][k]) / 3 for lam in (25.0, 50.0)]
        extrapolated = (16 * r1[1] - r1[0]) / 15
        assert abs(extrapolated - r) < 5e-7 * max(1.0, abs(r)), (k, extrapolated, r)


def test_jkr_limit_at_lambda_100():
    """At lambda = 100 every state quantity is within 2.5e-4 of JKR (relative): 0.77/lambda^2 for p here."""
    m, eps = 0.4, 0.8
    ref, s = jkr(eps, m), co.cohesive_state(eps, m, cs.zone_strength(100.0, m), THETA, GB)
    for k, v in values(s).items():
        assert abs(v / ref[k] - 1) < 2.5e-4, k


# --- 2. the half-plane limit (Baney and Hui 1997) -------------------------------------------------------------
@pytest.mark.parametrize("lam", [0.01, 0.1, 1.0, 10.0, 100.0])
@pytest.mark.parametrize("abar", [0.3, 1.0])
def test_half_plane_limit_is_baney_hui(lam, abar):
    """Delta/R = 1e-6 and m = 1e-6 (M tiny): the contact is a few 1e-4 rad, and load-width and the zone ratio
    agree with Baney-Hui's closure and load to 1e-4 (measured: < 3e-6, the rest O(c^2) curvature)."""
    m, DoR = 1e-6, 1e-6
    eps = 2 * abar * m ** (2 / 3) * (1 - DoR) ** (2 / 3)
    s = co.cohesive_state(eps, m, cs.zone_strength(lam, m, DoR), THETA, GB)
    assert cs.transition_parameter(m, s.s0, DoR) == pytest.approx(lam, rel=1e-14)
    ab, Pbar = cs.baney_hui_variables(eps, s.p, m, DoR)
    assert ab == pytest.approx(abar, rel=1e-14)
    assert abs(Pbar - float(bh.load(abar, lam))) < 1e-4 * max(1.0, abs(Pbar))
    assert abs(s.c / eps / float(bh.zone_ratio(abar, lam)) - 1) < 1e-4


def test_generated_half_plane_state_is_baney_hui():
    """The derived half-plane limit (generated/cohesive.half_plane_state, in the normalised variables) and the
    hand-typed Baney-Hui equations: their closure says h(c) = h0 and their load is p, to 1e-12."""
    m = 0.3
    for lam, abar in ((0.1, 0.5), (1.0, 0.8), (7.0, 1.7)):
        mr, ref = float(bh.zone_ratio(abar, lam)), float(bh.load(abar, lam))
        eps, s0 = 2 * abar * m ** (2 / 3), lam * m ** (2 / 3) / 4
        p, opening = cs.half_plane_state(eps, mr * eps, s0)
        assert opening * s0 / m ** 2 == pytest.approx(1.0, rel=1e-12)
        assert p / m ** (4 / 3) == pytest.approx(ref, rel=1e-12)


def test_reference_reproduces_printed_pull_off_and_limits():
    """The reference itself: the printed -Pbar_c (3 digits), JKR's -3/2^(4/3) = -1.19055 at large lambda
    (Barquins (7.4) in these units, derived in reference/baney_hui.py), DMT-like -sqrt(2 lambda) at small."""
    for lam, printed in bh.PRINTED_PULL_OFF.items():
        assert round(-float(bh.pull_off(lam)), 3) == printed
    assert float(bh.pull_off(2000.0)) == pytest.approx(float(bh.JKR_PULL_OFF), rel=1e-6)
    assert float(bh.pull_off(1e-5)) == pytest.approx(float(bh.dmt_pull_off(1e-5)), rel=1e-3)
    # (7.4): P = pi E* a^2/(4 R) - sqrt(2 pi E* w a) with E* = 4/beta*, at w = 1, R = 1, E* = 1: abar = a/2 (pi)^(-1/3)
    a = 0.7
    scale_a, scale_P = 2 * (1 / math.pi) ** (1 / 3), math.pi ** (1 / 3)
    barquins = math.pi * a ** 2 / 4 - math.sqrt(2 * math.pi * a)
    assert float(bh.jkr_load(a / scale_a)) * scale_P == pytest.approx(barquins, rel=1e-14)


# --- 3. energy, equilibrium and the law ---------------------------------------------------------------------
def potential(s, w_factor=1.0):
    """Total potential at fixed approach per 4 pi Delta^2/beta*: Clapeyron's (1/2) int nu e (e: the elastic part
    of the gap) plus the Dugdale interface energy int Phi(h), Phi = -m^2 + s0 min(h, h0) where h < h0 (0 beyond).
    Integrated by Gauss-Legendre from the returned fields (contact: phi = eps sin t; zones: clustered at both
    ends).  d(potential)/d(delta/Delta) = p along the states if (and only if) they are equilibria of the law."""
    eps, dn, s0, m2 = s.eps, s.delta_over_Delta, s.s0, s.m ** 2 * w_factor
    total = 0.0
    if eps > 0:
        t = np.pi / 2 * XG
        phi, jac = eps * np.sin(t), eps * np.cos(t) * np.pi / 2
        total += 0.5 * np.sum(WG * jac * s.fields.pressure(phi) * ((1 + dn) * np.cos(phi) - 1)) - m2 * 2 * eps
    t = np.pi * (XG + 1) / 2
    for lo, hi in [(eps, s.c)] + ([(math.pi - s.c_top, math.pi)] if s.c_top > 0 else []):
        phi, jac = lo + (hi - lo) * (1 - np.cos(t)) / 2, (hi - lo) * np.sin(t) * np.pi / 4
        h = s.fields.gap(phi)
        e = h - 2 * np.sin(phi / 2) ** 2 + dn * np.cos(phi)             # both sides of phi = 0: factor 2
        total += 2 * np.sum(WG * jac * (0.5 * -s0 * e - m2 + s0 * h))
    return total


def _stencil(f, states, h):
    return (f(states[-2]) - 8 * f(states[-1]) + 8 * f(states[1]) - f(states[2])) / (12 * h)


@pytest.mark.parametrize("lam, eps", [(1.0, 0.3), (3.0, 0.8), (10.0, 0.3)])
def test_energy_release_is_w(lam, eps):
    """Along the states (eps varies, the law fixed) d Pi/d eps = p d(delta/Delta)/d eps to 1e-8: the states are
    stationary points of the Dugdale energy, so the energy released at the contact edge is w.  The check fails
    for a law with 1 % more w (the zone end condition h(c) = h0 then is wrong)."""
    m = 0.4
    s0 = cs.zone_strength(lam, m)
    n = co.cohesive_state(eps, m, s0, THETA, GB).n
    h = 1e-3
    S = {k: co.cohesive_state(eps + k * h, m, s0, THETA, GB, n=n) for k in (-2, -1, 1, 2)}
    s = co.cohesive_state(eps, m, s0, THETA, GB, n=n)
    work = s.p * _stencil(lambda x: x.delta_over_Delta, S, h)
    assert abs(_stencil(potential, S, h) / work - 1) < 1e-8
    assert abs(_stencil(lambda x: potential(x, 1.01), S, h) / work - 1) > 1e-3
    # the J-integral over the zone: sigma0 times the opening at its end is w (s0 h(c) = m^2)
    assert s.s0 * s.fields.gap(s.c)[0] == pytest.approx(m * m, rel=1e-12)


@pytest.mark.parametrize("lam, eps", [(0.5, 0.2), (1.0, 0.8), (3.0, 1.5), (10.0, 2.5), (30.0, 0.4)])
def test_equilibrium_and_the_law_on_a_fine_grid(lam, eps):
    """(2.2): p = int nu cos by quadrature of the returned pressure (contact and zones); the stress at the contact
    end is finite (k = 0) and tends to -s0; the gap is >= 0 outside the contact, <= h0 on the zones and > h0
    beyond (so the traction is -s0 exactly where 0 < h <= h0), on 4000 exterior points."""
    m = 0.4
    s = co.cohesive_state(eps, m, cs.zone_strength(lam, m), THETA, GB)
    t = np.pi / 2 * XG
    phi, jac = eps * np.sin(t), eps * np.cos(t) * np.pi / 2
    quad = np.sum(WG * jac * s.fields.pressure(phi) * np.cos(phi))
    c = min(s.c, math.pi)
    t = np.pi * (XG + 1) / 2
    phi, jac = eps + (c - eps) * (1 - np.cos(t)) / 2, (c - eps) * np.sin(t) * np.pi / 4
    quad += 2 * np.sum(WG * jac * s.fields.pressure(phi) * np.cos(phi))
    assert quad == pytest.approx(s.p, abs=1e-11 * max(1.0, abs(s.p)))
    assert abs(s.k) < 1e-12 * max(1.0, s.m)
    assert s.fields.pressure(eps * (1 - 1e-10))[0] == pytest.approx(-s.s0, abs=1e-4 * s.s0)
    grid = np.linspace(eps, math.pi, 4001)[1:]
    h, nu = s.fields.gap(grid), s.fields.pressure(grid)
    h0 = s.h0_over_Delta
    assert h.min() >= -1e-12
    in_zone = (grid < s.c) | (s.zones == "all")
    assert np.all(h[in_zone] <= h0 * (1 + 1e-12)) and np.all(h[~in_zone] > h0 * (1 - 1e-12))
    assert np.all(nu[in_zone] == -s.s0) and np.all(nu[~in_zone] == 0.0)
    assert co.gap_check(s).feasible


def _nearest(states, c_top):
    return min(states, key=lambda x: abs(x.c_top - c_top))


def test_top_zone_bridges_are_equilibria():
    """States with a second zone at the top (a bridge the pin pulls to itself; m = 0.4, lambda = 2.5): the gap is
    h0 at both zone ends, and along the family (eps varies, the nearest bridge followed) d Pi/d eps =
    p d(delta/Delta)/d eps to 1e-8 -- for the contact with two zones and for the pin without contact held by
    two zones (then the bottom zone end c is the parameter)."""
    m = 0.4
    s0 = cs.zone_strength(2.5, m)
    eps, h = 0.3, 1e-3
    bridge = _nearest(cz.top_zone_states(eps, m, s0, THETA, GB), 0.116)
    assert bridge.zones == "bottom+top" and co.gap_check(bridge, 2000).feasible
    for phi in (bridge.c, math.pi - bridge.c_top):
        assert bridge.fields.gap(phi)[0] == pytest.approx(bridge.h0_over_Delta, rel=1e-11)
    S = {k: _nearest(cz.top_zone_states(eps + k * h, m, s0, THETA, GB, n=bridge.n), bridge.c_top)
         for k in (-2, -1, 1, 2)}
    work = bridge.p * _stencil(lambda x: x.delta_over_Delta, S, h)
    assert abs(_stencil(potential, S, h) / work - 1) < 1e-8
    c = 0.4
    free = _nearest(cz.contactless_states(c, m, s0, THETA, GB), 0.084)
    assert free.eps == 0 and free.zones == "bottom+top" and co.gap_check(free, 2000).feasible
    assert free.fields.gap(math.pi - free.c_top)[0] == pytest.approx(free.h0_over_Delta, rel=1e-11)
    assert free.p == pytest.approx(-2 * s0 * (math.sin(c) - math.sin(free.c_top)), rel=1e-14)
    S = {k: _nearest(cz.contactless_states(c + k * h, m, s0, THETA, GB), free.c_top) for k in (-2, -1, 1, 2)}
    work = free.p * _stencil(lambda x: x.delta_over_Delta, S, h)
    assert abs(_stencil(potential, S, h) / work - 1) < 1e-8


# --- 4. the range reaching the top: no adherence force --------------------------------------------------------
@pytest.mark.parametrize("theta, gb, ar", [(1.0, 0.5, 0.0), (math.inf, 1.0, 0.0)])
def test_range_above_2_Delta_gives_no_adherence(theta, gb, ar):
    """h0 > 2 Delta: the zone reaches round (zones 'all': a uniform traction has no resultant) unless the pin is
    pressed in so hard that h(pi) > h0; every feasible state has p >= 0; the contact branch never ends on a
    contactless state, and the free pin floats at p = 0 over a range of approaches."""
    m = 0.4
    for lam in (0.05, 0.1, 0.2):
        s0 = cs.zone_strength(lam, m)
        assert cs.zone_range(m, s0) > 2
        for eps in np.linspace(0.01, 2.8, 15):
            s = co.cohesive_state(eps, m, s0, theta, gb, ar)
            if co.gap_check(s).feasible:
                assert s.p >= 0, (lam, eps, s.p)
        assert cz.contactless_touch(m, s0, theta, gb, ar) is None
        assert cz.floating_range(m, s0, theta, gb, ar) is not None


def test_the_pin_hangs_without_contact():
    """lambda ~ 1: the contact branch at eps -> 0 ends on a contactless state that pulls (p < 0) -- the same state
    reached two ways: the collocation at eps = 1e-7 and the closed-form contactless state touching (h(0) = 0)."""
    m = 0.4
    for lam in (1.0, 3.0, 10.0):
        s0 = cs.zone_strength(lam, m)
        touch = cz.contactless_touch(m, s0, THETA, GB)
        small = co.cohesive_state(1e-7, m, s0, THETA, GB)
        assert touch is not None and touch.p < 0 and co.gap_check(touch).feasible
        assert small.c == pytest.approx(touch.c, rel=1e-5)
        assert small.p == pytest.approx(touch.p, rel=1e-5)
        assert small.delta_over_Delta == pytest.approx(touch.delta_over_Delta, rel=1e-5)


# --- 5. convergence with the number of nodes ------------------------------------------------------------------
def test_spectral_convergence_in_the_nodes():
    """At a fixed law and contact the error of the plain collocation (the end layer not subtracted) falls
    geometrically with n, at the rate of the Bernstein ellipse through the zone end (rho = c/eps +
    sqrt((c/eps)^2 - 1)); the default (here with the layer subtracted, tests/test_cohesive_layer.py) reaches 1e-8
    (measured 1e-10)."""
    m, eps = 0.4, 0.8
    s0 = cs.zone_strength(10.0, m)
    ref = co.cohesive_state(eps, m, s0, THETA, GB, n=200, layered=False)
    rho = ref.c / eps + math.sqrt((ref.c / eps) ** 2 - 1)
    errs = {}
    for n in (24, 32, 48, 64, 96):
        s = co.cohesive_state(eps, m, s0, THETA, GB, n=n, layered=False)
        errs[n] = max(abs(s.p - ref.p), abs(s.delta_over_Delta - ref.delta_over_Delta), abs(s.c - ref.c))
    assert errs[24] > errs[32] > errs[48] > errs[64] > errs[96] or errs[96] < 1e-13
    rate = (math.log(errs[24]) - math.log(errs[64])) / 40
    assert 0.5 * math.log(rho) < rate < 2.0 * math.log(rho), (rate, math.log(rho))
    default = co.cohesive_state(eps, m, s0, THETA, GB)
    assert abs(default.p - ref.p) < 1e-8 and abs(default.c - ref.c) < 1e-8


# --- 6. any material pair -------------------------------------------------------------------------------------
PAIRS = {"steel pin in aluminium": dict(E=70e9, nu=0.33, E_I=210e9, nu_I=0.3),
         "rubber roller in a rigid cradle": dict(E=math.inf, nu=0.3, E_I=2e6, nu_I=0.45),
         "rigid pin in a plate": dict(E=70e9, nu=0.33, E_I=math.inf, nu_I=0.3)}


def _normalised(name):
    mat = jkrcyl.Materials.from_young(**PAIRS[name])
    return mat.theta, mat.inv_G_I / mat.beta, mat.alpha_ratio


@pytest.mark.slow
@pytest.mark.parametrize("name", list(PAIRS))
def test_material_pairs(name):
    """alpha* != 0 and rigid bodies: k = 0, the energy identity to 1e-7, the gap law, the JKR trend
    (lambda^2 times the difference in p, delta, h(pi) steady between lambda = 12.5 and 25 to 5 %, at eps = 0.4),
    and the touch state."""
    theta, gb, ar = _normalised(name)
    m = 0.4 if math.isinf(theta) else 0.4 * theta
    eps = 0.7
    s0 = cs.zone_strength(3.0, m)
    n = co.cohesive_state(eps, m, s0, theta, gb, ar).n
    h = 2e-3
    S = {k: co.cohesive_state(eps + k * h, m, s0, theta, gb, ar, n=n) for k in (-2, -1, 1, 2)}
    s = co.cohesive_state(eps, m, s0, theta, gb, ar, n=n)
    assert abs(s.k) < 1e-10
    assert abs(_stencil(potential, S, h) / (s.p * _stencil(lambda x: x.delta_over_Delta, S, h)) - 1) < 1e-7
    assert co.gap_check(s, 2000).feasible
    ref = jkr(0.4, m, theta, gb, ar)
    st = {lam: values(co.cohesive_state(0.4, m, cs.zone_strength(lam, m), theta, gb, ar)) for lam in (12.5, 25.0)}
    for k in ("p", "dn", "h"):
        ratio = (st[25.0][k] - ref[k]) * 25.0 ** 2 / ((st[12.5][k] - ref[k]) * 12.5 ** 2)
        assert abs(ratio - 1) < 0.05, (k, ratio)
    touch, small = cz.contactless_touch(m, s0, theta, gb, ar), co.cohesive_state(1e-7, m, s0, theta, gb, ar)
    assert touch is not None and small.p == pytest.approx(touch.p, rel=1e-5)


# --- 7. scales and bad input ----------------------------------------------------------------------------------
def test_scales_round_trip_and_physical_law():
    """lambda(s0(lambda)) = lambda; the physical law: sigma0 h0 = w and lambda from its definition
    4 sigma0/(pi^2 E*^2 w/R_eff)^(1/3), E* = 4/beta*, R_eff = R R_D/Delta."""
    for lam, m, dr in ((0.01, 1e-3, 0.0), (1.0, 0.4, 1e-3), (300.0, 5.0, 0.5)):
        assert cs.transition_parameter(m, cs.zone_strength(lam, m, dr), dr) == pytest.approx(lam, rel=1e-14)
    mats = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)     # identical: vartheta = 1
    sigma0, w, R, Delta, beta = 3e6, 0.05, 0.01, 2e-6, mats.beta
    law = cs.dugdale_parameters(sigma0, w, R, Delta, beta)
    assert law.h0_over_Delta * Delta * sigma0 == pytest.approx(w, rel=1e-14)
    E, R_eff = 4 / beta, R * (R - Delta) / Delta
    assert law.lam == pytest.approx(4 * sigma0 / (math.pi ** 2 * E ** 2 * w / R_eff) ** (1 / 3), rel=1e-13)
    assert law.m == pytest.approx(jkrcyl.Contact(R, Delta, w, mats).M, rel=1e-12)        # m = M vartheta


@pytest.mark.parametrize("call, name", [
    (lambda: co.cohesive_state(0.5, 0.4, 0.0, 1.0, 0.5), "s0"),
    (lambda: co.cohesive_state(0.5, 0.4, -1.0, 1.0, 0.5), "s0"),
    (lambda: co.cohesive_state(0.5, 0.4, math.nan, 1.0, 0.5), "s0"),
    (lambda: co.cohesive_state(0.5, math.nan, 1.0, 1.0, 0.5), "m"),
    (lambda: co.cohesive_state(0.0, 0.4, 1.0, 1.0, 0.5), "eps"),
    (lambda: co.cohesive_state(math.pi, 0.4, 1.0, 1.0, 0.5), "eps"),
    (lambda: co.cohesive_state(0.5, 0.4, 1.0, 0.3, 0.5), "theta"),
    (lambda: co.cohesive_state(0.5, 0.4, 1.0, 1.0, 0.5, ar=1.5), "ar"),
    (lambda: co.cohesive_state(0.5, 0.4, 1.0, 1.0, 0.5, n=2), "n"),
    (lambda: cz.contactless_state(0.5, 0.0, 1.0, 1.0, 0.5), "m"),
    (lambda: cz.contactless_state(math.pi / 2, 0.4, 1.0, 1.0, 0.5), "c"),
    (lambda: cs.zone_strength(1.0, 0.0), "m"),
    (lambda: cs.zone_strength(math.nan, 0.4), "lam"),
    (lambda: cs.zone_strength(-1.0, 0.4), "lam"),
    (lambda: cs.transition_parameter(0.4, 0.0), "s0"),
    (lambda: cs.transition_parameter(0.4, 1.0, 1.0), "Delta_over_R"),
    (lambda: cs.dugdale_parameters(0.0, 0.05, 0.01, 1e-6, 1e-9), "sigma0"),
    (lambda: cs.dugdale_parameters(-1e6, 0.05, 0.01, 1e-6, 1e-9), "sigma0"),
    (lambda: cs.dugdale_parameters(1e6, 0.0, 0.01, 1e-6, 1e-9), "w"),
    (lambda: cs.dugdale_parameters(1e6, 0.05, 0.01, 0.02, 1e-9), "Delta"),
])
def test_bad_input_names_the_parameter(call, name):
    with pytest.raises(ValueError, match=rf"^{name}\b"):
        call()


def test_no_adhesion_is_the_adhesionless_state():
    """m = 0 (w = 0): no zone, the state is the adhesionless one (JKR with m = 0) to 1e-10."""
    for eps in (0.3, 1.0):
        s, ref = co.cohesive_state(eps, 0.0, 1.0, THETA, GB), jkr(eps, 0.0)
        assert s.c == eps
        for k, v in values(s).items():
            assert v == pytest.approx(ref[k], rel=1e-10, abs=1e-12)
