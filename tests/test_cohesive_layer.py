"""Thin cohesive zones: the Dugdale end layer subtracted in closed form (jkrcyl.numerics.cohesive_layer).

References, none of them the solver's own numbers: mpmath (30 digits) -- its polylog for Li2, its tanh-sinh
quadrature of the layer traction against the kernel K(t) = cos t log(2 - 2 cos t) + k1 cos t + k0 +
ar (pi sign(t) sin t - t sin t) typed here from the paper's form (generated/green.py docstring), of the
half-plane Maugis identity and of the enrichment columns; the plain collocation (the layer not subtracted) where
both resolve the zone (lambda <= 30); the JKR states and pull-off (the Griffith solver) as lambda grows.
"""
import math

import mpmath as mp
import numpy as np
import pytest

import jkrcyl
from jkrcyl.numerics import arcs
from jkrcyl.numerics import arcs_enrich as en
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_kernels as ck
from jkrcyl.numerics import cohesive_layer as cl
from jkrcyl.numerics import cohesive_scales as cs
from jkrcyl.model.problem import Problem
from jkrcyl.model.single_patch import solver

mp.mp.dps = 30


def jkr(eps, m, theta=1.0, gb=0.5):
    """The Griffith (JKR) state at the contact eps (the library's single-patch solver, closed forms at alpha* = 0,
    checked against the paper in tests/test_arcs.py)."""
    st = solver(Problem(m if math.isinf(theta) else m / theta, theta, gb, 0.0)).states(np.tan(np.atleast_1d(eps) / 2))
    return dict(p=st.p[0], dn=st.dn[0], h=st.h[0])


def _kernel_mp(kernel):
    ar = kernel.ar

    def K(t):
        t = mp.mpf(t)
        if t == 0:
            return mp.mpf(kernel.k1 + kernel.k0)
        return (2 * mp.cos(t) * mp.log(abs(2 * mp.sin(t / 2))) + kernel.k1 * mp.cos(t) + kernel.k0
                + ar * (mp.pi * mp.sign(t) * mp.sin(t) - t * mp.sin(t)))
    return K


def _layer_mp(e, c):
    e, c = mp.mpf(e), mp.mpf(c)
    return lambda p: 2 / mp.pi * mp.atan(mp.sqrt(max(e * e - p * p, 0) / (c * c - e * e)))


def _breaks(e, d, phi=None):
    w = min(10 * d, e / 2)
    pts = {-e, -e + w, e - w, e}
    if phi is not None and abs(phi) < e:
        pts.add(phi)
    return sorted(pts)


def test_li2_against_mpmath():
    """The dilogarithm of the layer sums (|z| <= 1, both branches of its evaluation) to 1e-15."""
    for z in (0.3 + 0.2j, -0.9 + 0.1j, 0.999 * np.exp(0.3j), 0.95, -0.999999, 0.7j, 0.6 - 0.5j, 1e-8 + 0j):
        ref = complex(mp.polylog(2, mp.mpc(z)))
        assert abs(cl.li2(complex(z)) - ref) < 1e-15 * max(1.0, abs(ref)), z


def test_maugis_traction_displaces_the_half_plane_contact_flat():
    """The identity the layer rests on: with the log kernel, v_s on |x| < a together with -1 on |x| < c moves
    every point of the contact alike (mpmath quadrature, 30 digits)."""
    a, c = mp.mpf(1), mp.mpf("1.001")
    vs = _layer_mp(a, c)
    pot = [mp.quad(lambda s: vs(s) * mp.log(abs(x - s)), [-a, -a + mp.mpf("0.01"), x, a - mp.mpf("0.01"), a])
           - mp.quad(lambda s: mp.log(abs(x - s)), [-c, x, c]) for x in map(mp.mpf, ("0", "0.4", "0.9"))]
    assert max(abs(p - pot[0]) for p in pot) < 1e-20


CASES = [  # theta, gb, ar, e, d (= c - e), points x = phi/e: on the contact, its ends, beyond, far
    (math.inf, 0.5, 0.0, 0.5, 1e-3, [0.0, 0.3, 0.99, 1.0, 1.002, 1.5, 6.0]),
    (3.0, 0.3, -0.3, 0.5, 1e-5, [0.0, -0.7, 0.99999, -1.0, 1.00002, 1.0000001, 2.5]),
    (2.0, 0.3, 0.2, 0.3, 0.5, [0.0, 0.9, 1.0, 2.0, 10.0]),
    (2.0, 0.3, 0.2, 2.0, 1e-4, [0.0, 0.9, 1.0, 1.00006, 1.5]),                # e > 1: the kernel's images
    (1.0, 1 / 2.8, 0.0, 3.0, 1e-6, [0.0, 0.999, -1.0, 1.0000004, 1.04]),      # near the receding limit
    (math.inf, 0.3, 0.0, 1e-3, 1e-9, [0.5, 1.000002, 30.0, 3000.0]),          # a tiny contact
]


@pytest.mark.parametrize("theta, gb, ar, e, d, xs", CASES)
def test_layer_potential_against_quadrature(theta, gb, ar, e, d, xs):
    """Q(x) = int v_s(psi) K(e x - psi) dpsi in closed form equals the quadrature to 1e-13 (relative to
    max(1, |Q|)), on and off the contact, for alpha* = 0 and != 0, e > 1 and a tiny contact."""
    kernel = arcs.Kernel(theta, gb, ar)
    c = e + d
    gc, gs = cl.trig_coefficients(e, en.K_TRIG)
    got = cl.potential(np.array(xs, dtype=float), e, c, kernel.k0, kernel.k1, kernel.ar, gc, gs,
                       cl.qmax_of(gc, gs), np.zeros((0, cl.N_SMOOTH)))
    K, vs = _kernel_mp(kernel), _layer_mp(e, c)
    for x, g in zip(xs, got):
        phi = mp.mpf(x) * e
        ref = mp.quad(lambda p: vs(p) * K(phi - p), _breaks(e, d, phi))
        assert abs(g - float(ref)) < 1e-13 * max(1.0, abs(float(ref))), (x, g, float(ref))


def test_layer_tables_and_loads():
    """The fixed contact's smooth-moment table gives the same Q as the per-point path (symmetric nodes mirrored);
    the layer's load and width (int v_s cos, int v_s) equal the quadrature to 1e-14; the Bessel coefficients by
    recurrence equal scipy's (arcs_enrich.trig_coefficients) to 1e-15."""
    kernel = arcs.Kernel(2.0, 0.3, 0.0)
    e, c = 0.7, 0.7 + 2e-5
    fc = co.FixedContact(e, kernel, 32, layered=True)
    x, gc, gs, qm = fc.fx[24], fc.fx[25], fc.fx[26], fc.fx[27]
    tabled = cl.potential(x, e, c, kernel.k0, kernel.k1, 0.0, gc, gs, qm, fc.fx[28], 32)
    direct = cl.potential(x, e, c, kernel.k0, kernel.k1, 0.0, gc, gs, qm, np.zeros((0, cl.N_SMOOTH)))
    assert np.abs(tabled - direct).max() < 1e-14
    vs = _layer_mp(e, c)
    p, B = cl.loads(e, c, gc)
    assert p == pytest.approx(float(mp.quad(lambda q: vs(q) * mp.cos(q), _breaks(e, c - e))), abs=1e-14)
    assert B == pytest.approx(float(mp.quad(vs, _breaks(e, c - e))), abs=1e-14)
    for ee in (1e-6, 0.1, 1.0, 3.1):
        a, b = cl.trig_coefficients(ee, en.K_TRIG), en.trig_coefficients(ee)
        assert np.abs(a[0] - b[0]).max() < 1e-15 and np.abs(a[1] - b[1]).max() < 1e-15


@pytest.mark.parametrize("dx", [1e-7, 3e-6, 1e-4, 0.3])
def test_end_enrichment_columns_against_quadrature(dx):
    """alpha* != 0: the enrichment columns of the gap just off the contact end (graded Gauss-Legendre) equal
    the quadrature to 1e-12 (the engine's 4096-point grid is off by ~1e-8 at dx = 3e-6, ~1e-4 at 1e-7)."""
    kernel = arcs.Kernel(3.0, 0.3, -0.2)
    e = 0.8
    fc = co.FixedContact(e, kernel, 48)
    n = fc.sys.n
    got = ck.gap_rows(fc.fx, np.array([e * (1 + dx)]))[0, n:]
    K = _kernel_mp(kernel)
    xl = lambda r: r * mp.log(r) if r > 0 else mp.mpf(0)
    g = [lambda s: xl(1 - s) + xl(1 + s), lambda s: (1 - s) * xl(1 - s) + (1 + s) * xl(1 + s),
         lambda s: xl(1 - s) ** 2 + xl(1 + s) ** 2]
    phi = mp.mpf(e) * (1 + mp.mpf(dx))
    for j in range(3):
        ref = -mp.quad(lambda th: K(phi - e * mp.cos(th)) * g[j](mp.cos(th)), [0, mp.mpf("1e-4"), 0.01, 0.3, mp.pi])
        assert abs(got[j] - float(ref)) < 1e-12 * max(1.0, abs(float(ref))), (j, got[j], float(ref))


PAIRS = {"identical, nu = 1/3": (1.0, 0.5, 0.0), "rigid cradle": (math.inf, 1.0, 0.0),
         "alpha* != 0": (3.0, 0.3, -0.2), "roller-like": (4e4, 0.98, -0.0196)}


@pytest.mark.parametrize("name", list(PAIRS))
@pytest.mark.parametrize("lam", [1.0, 3.0, 10.0, 30.0])
def test_layered_equals_the_plain_collocation(name, lam):
    """Where the plain collocation resolves the zone (at twice its default nodes, up to 400; 256 at alpha* != 0)
    the state with the layer subtracted (32 nodes, 64 at alpha* != 0) is the same to 1e-9 (relative to max(1,
    |X|); measured 1e-15 to 5e-11): p, delta, h(pi), the zone end, the edge coefficient (k = 0)."""
    theta, gb, ar = PAIRS[name]
    m, eps = 0.4, 0.8
    s0 = cs.zone_strength(lam, m)
    n = co.cohesive_state(eps, m, s0, theta, gb, ar, layered=False).n
    a = co.cohesive_state(eps, m, s0, theta, gb, ar, layered=False,
                          n=min(2 * n, co.NODES_MAX if ar == 0 else co.NODES_MAX_ALPHA) // 8 * 8)
    b = co.cohesive_state(eps, m, s0, theta, gb, ar, layered=True)
    assert b.zones == a.zones == "bottom" and b.n <= 64
    for k in ("p", "delta_over_Delta", "h_pi_over_Delta", "c"):
        x, y = getattr(a, k), getattr(b, k)
        assert abs(x - y) <= 1e-9 * max(1.0, abs(x)), (k, x, y)
    assert abs(b.k) < 1e-10


@pytest.mark.parametrize("ar, tol", [(0.0, 3e-10), (-0.02, 1e-9), (-0.2, 1e-8)])
@pytest.mark.parametrize("lam", [100.0, 1000.0])
def test_layered_convergence_in_the_nodes(lam, ar, tol):
    """A thin zone (c - eps ~ 3e-4 and 3e-6 eps; the plain collocation would need ~700 and ~7000 nodes) with a
    bounded node count: against 192 nodes the default (32; 64 at alpha* != 0) is within tol in p, delta, c --
    alpha* = 0: spectral, measured 1e-13 at lambda = 100 and 6e-11 at 1000 (c = eps + d holds d to ulp(c): 5e-11
    of it there); alpha* != 0: the enrichment's algebraic rate, measured 6e-11 / 4e-10 at -0.02 and 1e-9 / 2e-9 at
    -0.2 -- and 128 nodes as well."""
    m, eps = 0.4, 0.8
    s0 = cs.zone_strength(lam, m)
    ref = co.cohesive_state(eps, m, s0, 3.0, 0.3, ar, n=192, layered=True)
    err = lambda s: max(abs(s.p - ref.p), abs(s.delta_over_Delta - ref.delta_over_Delta), abs(s.c - ref.c))
    default = co.cohesive_state(eps, m, s0, 3.0, 0.3, ar)
    assert default.n == (32 if ar == 0 else 64) and err(default) < tol
    assert err(co.cohesive_state(eps, m, s0, 3.0, 0.3, ar, n=128, layered=True)) < tol


def test_jkr_limit_of_thin_zones():
    """lambda = 250, 500, 1000: the state at a fixed contact tends to JKR's as C/lambda^2 -- lambda^2 times the
    difference in p, delta, h(pi) is steady to 1e-3 (C measured: p -0.3548, delta 0.8549, h(pi) 0.6713 at
    m = 0.4, eps = 0.8, identical bodies, nu = 1/3; the next term, O(lambda^-4), is below the 1e-10 resolution of
    c = eps + d there) -- and the zone length is the Dugdale estimate m^2/(4 s0^2) to 2e-5 (measured 1.2e-5 at
    250, 7.7e-7 at 1000: O(lambda^-2) too)."""
    m, eps = 0.4, 0.8
    ref = jkr(eps, m)
    C = {}
    for lam in (250.0, 500.0, 1000.0):
        s0 = cs.zone_strength(lam, m)
        s = co.cohesive_state(eps, m, s0, 1.0, 0.5)
        assert (s.c - eps) / co.dugdale_zone(m, s0) == pytest.approx(1.0, abs=2e-5)
        C[lam] = {k: (getattr(s, a) - ref[k]) * lam ** 2 for k, a in
                  (("p", "p"), ("dn", "delta_over_Delta"), ("h", "h_pi_over_Delta"))}
    for k in ("p", "dn", "h"):
        assert C[250.0][k] == pytest.approx(C[1000.0][k], rel=1e-3), (k, C)
        assert C[500.0][k] == pytest.approx(C[1000.0][k], rel=1e-3), (k, C)


RUBBER_IN_STEEL = jkrcyl.Materials.from_young(E=210e9, nu=0.3, E_I=2e6, nu_I=0.49)


def test_rubber_roller_in_a_steel_cradle_is_jkr():
    """The thin-zone roller (R 5 mm, Delta 20 um, w 0.05, sigma0 0.5 MPa: lambda ~ 143): every answer that
    was missing (an empty solve, pull-offs None, a false minimum at -14.43 N/m) now matches the JKR contact: the
    load-control pull-off to 1e-6 (measured 9e-9; issue: JKR's -38.27 N/m within 1e-3), the grip ones to 1e-4
    (measured ~1e-6), adherence's minimum; the zero-load state and a state at eps = 0.3 differ from JKR's by
    O(lambda^-2) (measured 4.7e-5 = 0.96/lambda^2 in eps at zero load)."""
    c = jkrcyl.Contact(R=5e-3, Delta=20e-6, w=0.05, materials=RUBBER_IN_STEEL, sigma0=0.5e6)
    j = jkrcyl.Contact(R=5e-3, Delta=20e-6, w=0.05, materials=RUBBER_IN_STEEL)
    assert c.lambda_ == pytest.approx(142.83, rel=1e-4)
    po, ref = c.pull_off("load"), j.pull_off("load")
    assert ref.P == pytest.approx(-38.27, abs=0.005) and po.P == pytest.approx(ref.P, rel=1e-6)
    for ctl in ("grip", "grip-work"):
        assert c.pull_off(ctl).P == pytest.approx(j.pull_off(ctl).P, rel=1e-4)
    zero, zero_jkr = c.solve(P=0.0, branches=["sub-critical"]), j.solve(P=0.0, branches=["sub-critical"])
    assert len(zero) == len(zero_jkr) == 1 and zero[0].eps == pytest.approx(zero_jkr[0].eps, rel=3 / 143 ** 2)
    assert min(pt.P for pt in c.adherence()) == pytest.approx(ref.P, rel=1e-6)
    st, st_jkr = c.at_contact([0.3]), j.at_contact([0.3])
    assert st.c[0] > 0.3 and st.P[0] == pytest.approx(st_jkr.P[0], rel=3 / 143 ** 2)
