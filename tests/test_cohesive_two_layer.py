"""The zones' end layers subtracted on two arcs (jkrcyl.numerics.cohesive_two_layer): thin zones on the two-patch
branch resolved with a bounded node count, up to lambda = 1000.

Checked against what the layered solver does not use:

* the layers' potential Q at the other arc's points, at the zone ends and inside the arc: an mpmath quadrature
  (30 digits) of v_s(psi) K(phi - psi) over the arc, in theta (psi = e cos theta), split at the kernel's log
  singularity and graded into the layer (v_s from its closed form, K from its definition in
  jkrcyl.numerics.arcs); the layers' loads p, B: a Gauss-Legendre quadrature of v_s;
* the states without the layers (the unknown v itself, 8 sqrt(eps/d) nodes per arc: cohesive_two's route
  before the layers) at lambda = 20, 50;
* JKR's two-patch state at the same top arc (jkrcyl.model.two_patch at 96 nodes per arc -- its default count,
  31 at these near-touching arcs, is 7e-5 off in eps: measured 24 / 48 / 96 / 192 nodes: 2.6123272, 2.6122543,
  2.61225411033, 2.61225411033): lambda^2 (eps - eps_JKR) the same constant from lambda = 50 to 1000;
* the energy: the total potential changes by p d(delta) along the branch (Richardson on states solved alone);
* the law along the branch traced at lambda = 1000: G/w = 1 at every zone end, the gap >= 0, JKR's ends.
"""
import math

import mpmath as mp
import numpy as np
import pytest

import jkrcyl
from jkrcyl.analysis.two_patch_family import family
from jkrcyl.model import two_patch as tp
from jkrcyl.numerics import arcs
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_two as ct
from jkrcyl.numerics import cohesive_two_layer as cl2
from jkrcyl.numerics.cohesive_scales import zone_strength
from cases import two_patch_dE_ddelta

EQ = jkrcyl.equilibria
THETA, GB, M = 1.0, 1 / 2.8, 0.2                 # identical bodies, nu = 0.3
EPS_TOP, GUESS = 0.36330064433257114, 2.6123     # a state of JKR's branch at M = 0.2 (near-touching arcs)
KERNEL = arcs.Kernel(THETA, GB)


def jkr(eps_top=EPS_TOP, guess=GUESS):
    return tp.solve(EQ.problem(M, THETA, GB), eps_top=eps_top, guess=guess, n=96)


def cold(lam, layered=None, n=None):
    return ct.solve(EPS_TOP, M * THETA, zone_strength(lam, M * THETA), THETA, GB, 0.0, guess=jkr().eps, n=n,
                    layered=layered)


# --- the layers' potential and loads ----------------------------------------------------------------------------
def q_reference(phi, centre, e, c):
    """int over the arc |psi - centre| < e of K(phi - psi) v_s(psi)/s0 dpsi by mpmath (module docstring)."""
    mp.mp.dps = 30
    k0, k1 = KERNEL.k0, KERNEL.k1
    beta = mp.sqrt((mp.mpf(c) - e) * (mp.mpf(c) + e)) / e

    def K(t):
        return mp.cos(t) * 2 * mp.log(abs(2 * mp.sin(t / 2))) + k1 * mp.cos(t) + k0

    def f(th):
        psi = centre + e * mp.cos(th)
        return K(phi - psi) * e * mp.sin(th) * 2 / mp.pi * mp.atan(mp.sin(th) / beta)

    pts = {mp.mpf(0), beta / 10, beta, 10 * beta, mp.pi / 2, mp.pi - 10 * beta, mp.pi - beta, mp.pi - beta / 10,
           mp.pi}
    x = math.remainder(phi - centre, 2 * math.pi) / e            # the kernel's singularity, relative to the arc
    if abs(x) < 1:
        pts.add(mp.acos(x))
    return float(mp.quad(f, sorted(pts), maxdegree=10))


@pytest.mark.parametrize("d", [1e-3, pytest.param(1.4e-6, marks=pytest.mark.slow)])   # lambda ~ 35, 1000 at M 0.2
# (~10 s each: mpmath quadratures; the thinner layer in the slow target)
def test_layer_potential_against_quadrature(d):
    """Q of both layers at points on each arc, past each zone end, in the open gap and at the far side: 1e-13
    (measured 5e-15, 3e-15)."""
    e, et = 2.6122523, EPS_TOP
    c, c_top = e + d, et + d
    points = np.concatenate([[0.3 * e, 0.999 * e, math.pi - 0.5 * et, -math.pi + 0.99 * et], [c, e + 5 * d, 2.7,
                             math.pi - c_top, -1.0]])
    layers = cl2.Layers(e, et, KERNEL, np.concatenate([e * arcs._nodes(8), math.pi + et * arcs._nodes(8)]))
    got = layers.at(points, c, c_top)
    for phi, g in zip(points, got):
        ref = q_reference(phi, 0.0, e, c) + q_reference(phi, math.pi, et, c_top)
        assert abs(g - ref) < 1e-13, (phi, g, ref)
    # at the collocation points (the smooth-moment tables): the same values as at free angles
    pts = np.concatenate([e * arcs._nodes(8), math.pi + et * arcs._nodes(8)])
    assert np.max(np.abs(layers.rhs(c, c_top) - layers.at(pts, c, c_top))) < 1e-13


def test_layer_loads_against_quadrature():
    """p = int v_s cos, B = int v_s of both layers (the top one's cos negative): Gauss-Legendre in theta on
    panels graded into the layer, 1e-13."""
    e, et, d = 2.6122523, EPS_TOP, 1e-4
    layers = cl2.Layers(e, et, KERNEL, np.concatenate([e * arcs._nodes(8), math.pi + et * arcs._nodes(8)]))
    xg, wg = np.polynomial.legendre.leggauss(40)
    edges = np.concatenate([[0.0], np.geomspace(1e-6, math.pi / 2, 30)])
    p = b = 0.0
    for centre, a, c in ((0.0, e, e + d), (math.pi, et, et + d)):
        beta = math.sqrt((c - a) * (c + a)) / a
        for lo, hi in zip(edges[:-1], edges[1:]):           # theta in (0, pi/2], doubled (v_s is even)
            th = lo + (hi - lo) * (xg + 1) / 2
            w = (hi - lo) / 2 * wg * a * np.sin(th) * 2 / math.pi * np.arctan(np.sin(th) / beta) * 2
            p += np.sum(w * np.cos(centre + a * np.cos(th)) * 0.5 + w * np.cos(centre - a * np.cos(th)) * 0.5)
            b += np.sum(w)
    lp, lb = layers.loads(e + d, et + d)
    assert abs(lp - p) < 1e-13 and abs(lb - b) < 1e-13


# --- states: with and without the layers ----------------------------------------------------------------------
@pytest.mark.parametrize("lam", [20.0, 50.0])
def test_layered_state_is_the_unlayered_one(lam):
    """The same state solved without the layers (8 sqrt(eps/d)-type node counts: 300 at lambda = 20, 760 at 50)
    and with them at 64 nodes per arc (or the near-touching count, 71 at lambda 50): eps, P*, delta/Delta, zone
    lengths to 3e-9 (measured 2e-11 ... 1.3e-9: the zone-end gaps' rounding, ~1e-12, amplified ~1e4 by the
    equations, module docstring of cohesive_two_layer)."""
    plain = cold(lam, layered=False, n=300 if lam == 20.0 else 760)
    got = cold(lam)
    assert got.fields.fa.layers is not None and got.n >= ct.NODES_LAYER_TWO    # or the near-touching count
    for key in ("eps", "p", "delta_over_Delta", "c", "c_top", "B"):
        assert abs(getattr(got, key) - getattr(plain, key)) < 3e-9, key    # the layered solve's rounding floor


def test_jkr_limit_from_lambda_50_to_1000():
    """lambda^2 (eps - eps_JKR) at the same top arc: -1.767, -1.761, -1.78 (+-0.05: rounding, module docstring of
    cohesive_two_layer) at lambda = 50, 100, 1000 -- one constant (C/lambda^2); lambda^2 (P* - P*_JKR) 0.231, 0.231
    at 50, 100 and |P* - P*_JKR| < 1e-6 at 1000."""
    ref = jkr()
    c = {lam: lam ** 2 * np.array([cold(lam).eps - ref.eps, cold(lam).p / THETA - ref.P_star])
         for lam in (50.0, 100.0, 1000.0)}
    assert 1.6 < -c[50.0][0] < 1.9 and abs(c[100.0][0] / c[50.0][0] - 1) < 0.01
    assert abs(c[1000.0][0] / c[100.0][0] - 1) < 0.05
    assert abs(c[100.0][1] / c[50.0][1] - 1) < 0.01 and abs(c[1000.0][1]) / 1000.0 ** 2 < 1e-6


def test_beyond_lambda_1000_refused_naming_sigma0():
    with pytest.raises(ValueError, match="^sigma0 is too large for the two-arc cohesive solver: its transition"):
        cold(2000.0)
    with pytest.raises(ValueError, match="^sigma0 is too large for the two-arc"):
        family(EQ.problem(M, THETA, GB, s0=zone_strength(2000.0, M * THETA))).n


# --- the branch at lambda = 1000 --------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def branch1000():
    fam = family(EQ.problem(M, THETA, GB, s0=zone_strength(1000.0, M * THETA)))
    b, = fam.branches()
    return fam, b


@pytest.mark.slow
def test_the_law_holds_along_the_branch_at_lambda_1000(branch1000):
    """JKR's ends reached (the top arc down to 1e-4 at 'single', the bottom one at 'mirror'), G/w = h(c)/h0 = 1 at
    every zone end (the Newton's rounding floor: 1e-8 of h0 = 4.7e-4 Delta here), the gap >= 0, the mirror
    symmetry P* -> -P*, delta -> -2 - delta (not imposed), every state unstable as JKR's at M = 0.2."""
    fam, b = branch1000
    assert fam.n >= ct.NODES_LAYER_TWO and b.ends == ("single", "mirror") and len(b.eps) >= 12
    assert np.max(np.abs(b.G_bot - 1)) < 1e-4 and np.max(np.abs(b.G_top - 1)) < 1e-4
    assert b.feasible.all() and np.all(b.gap_min > 0)
    assert abs(b.P_star[0] + b.P_star[-1]) < 1e-6 and abs(b.delta_over_Delta[0] + b.delta_over_Delta[-1] + 2) < 1e-6
    assert not (b.stable_load.any() or b.stable_grip.any())


@pytest.mark.slow
def test_energy_changes_by_p_d_delta_at_lambda_200():
    """dE/d(delta) along the branch (states solved alone at the top arc x +- h, x +- 2h; Richardson) equals p to
    1e-7 at lambda = 200 (the rounding of the thin zones' states: ~4e-9 in P*), where the raw quotient is off by
    more (the check can fail)."""
    fam = family(EQ.problem(M, THETA, GB, s0=zone_strength(200.0, M * THETA)))
    x, h = 0.3, 1e-3
    s = fam.at(1, x, jkr(x, 2.6).eps, fam.n)
    p = s.P_star * THETA
    extrapolated, d1 = two_patch_dE_ddelta(fam, s, x, h)
    assert abs(extrapolated - p) < 1e-7 and abs(d1 - p) > 10 * abs(extrapolated - p)


def test_zone_ends_of_a_zone_set():
    assert cl2.zone_ends(co.zones_of(1.0, 0.5)) == (1.0, 0.5)
    assert cl2.zone_ends(co.zones_of(1.0)) == (1.0, 0.0)
    assert cl2.zone_ends(co.zones_of(2.0, 1.5)) is None
