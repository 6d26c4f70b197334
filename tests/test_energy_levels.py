"""The levels of the total potential of every kind of state a walk lands on, joined by int p d(delta).

A jump at a held value must lower the total potential less the held quantity's work (jkrcyl.analysis.landing
keeps only such landings); that compares the energies of states of different kinds, read from different solvers.
Here each level is tied to the free pin's (no contact, no traction: E = 0 at every approach) along a path of
equilibria: the difference of two states' potentials equals int p d(delta/Delta) along the path (kernel scale,
units 4 pi Delta^2/beta*, p = vartheta P*), the integral by Chebyshev interpolation of p and delta in the path's
parameter (spectral: no slope of any solver), the potentials each state's own (Clapeyron's elastic energy from
P* and B*, the Dugdale interface energy by quadrature of the opening, -w over the contact):

* JKR: the free pin -> the single patch at its touch (a -> 0, delta -> 0) -> along the sub-critical branch; the
  super-critical branch along itself and onto full contact (eps -> pi: the difference is the adhesion of the
  closing gap, 2 m^2 (pi - eps), then nothing);
* Maugis-Dugdale (lambda 20, 50): the free pin -> the zone-only pin as it enters the range (c -> 0, delta -> -h0)
  -> along it to its touch (closed form in c) -> the contact branch from its first state (the touch itself, to
  1e-8) -> along it.

The other junctions are tested where they are built: single patch -> two patches at the onsets and two patches ->
full contact (tests/test_jump_energy.py), the law's single patch -> its top bridge -> two patches
(tests/test_cohesive_top_zone.py), the law's round-zone tail -> the bonded pin (tests/test_cohesive_full_contact.py),
and dE = p d(delta) along every traced branch of the law (its test files).
"""
import math

import numpy as np
import pytest
from numpy.polynomial import chebyshev as C

import jkrcyl
from jkrcyl.analysis import forward
from jkrcyl.laws.dugdale import edge_of_strength
from jkrcyl.model.problem import Problem
from jkrcyl.model.single_patch import solver
from jkrcyl.numerics import cohesive_branch as cb
from jkrcyl.numerics import cohesive_zones as cz
from jkrcyl.units import Units

M, THETA, GB = 0.1, 10.0, 1 / 2.8
JKR = Problem(M, THETA, GB)


def work(p_of, d_of, lo, hi, deg):
    """int p d(delta) along a path x in [lo, hi] (p_of, d_of: arrays at arrays of x), Chebyshev interpolants."""
    p = C.Chebyshev.interpolate(p_of, deg, domain=[lo, hi])
    d = C.Chebyshev.interpolate(d_of, deg, domain=[lo, hi])
    return float((p * d.deriv()).integ(lbnd=lo)(hi))


def single(pb, regime, a):
    un = Units.normalised(pb, K_edge=1.0)
    return forward.single_patch_states(pb, un, regime, np.atleast_1d(a), "grip")


def energy(pb, regime, a):
    return np.array([s.energy for s in single(pb, regime, a)])


def law_problem(lam):
    return Problem(M, THETA, GB, 0.0, edge_of_strength(jkrcyl.equilibria.zone_strength(lam, M, THETA)))


# --- JKR ---------------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("fraction", [0.3, 0.9])
def test_jkr_single_patch_starts_at_the_free_pins_level(fraction):
    """E(a) = E(a0) + int p d(delta) from a0 = 1e-10 (in log a: p ~ sqrt(a), delta ~ sqrt(a) log a are analytic
    there; two pieces, split at 0.1 a_crit), E(a0) -> 0 as the contact vanishes (the free pin's level at its touch,
    delta -> 0).  Measured: 2e-15 relative at 2 x 100 points; E(1e-8) = 6.7e-7, E(1e-10) = 8.5e-9 (~ a^(1/2) log a)."""
    sv = solver(JKR)
    a0, a1 = 1e-10, fraction * sv.a_crit                 # the pole of the load at a_crit: stop short of it
    f = lambda i: (lambda u: getattr(sv.states(np.exp(u)), ("p", "dn")[i]))
    cut = math.log(0.1 * sv.a_crit)
    along = work(f(0), f(1), math.log(a0), cut, 100) + work(f(0), f(1), cut, math.log(a1), 100)
    E0, E1 = energy(JKR, "sub-critical", [a0, a1])
    assert E1 - E0 == pytest.approx(along, rel=1e-10, abs=1e-12)
    assert abs(E0) < 1e-7 and abs(energy(JKR, "sub-critical", 1e-12)[0]) < abs(E0) / 5   # -> 0, the free pin's


def test_jkr_super_critical_branch_meets_full_contact():
    """Along the super-critical branch (1.5 a_crit -> 1e4, in log a) the potential changes by int p d(delta)
    (measured 1e-13 relative); towards eps -> pi it meets the bonded pin at the same approach (no offset): the
    difference falls with the gap g = pi - eps as m^2 g -- half the adhesion 2 m^2 g of the closing gap (Irwin at
    fixed approach: the release rate of the closing gap's edges rises linearly from 0 to w as it opens, so the
    potential of full contact lies m^2 g above less the gap's adhesion).  Measured (E - E_full)/(m^2 g) - 1:
    -3.9e-3, -3.5e-5, -3.1e-7 at a = 1e2, 1e3, 1e4."""
    sv, un = solver(JKR), Units.normalised(JKR, K_edge=1.0)
    lo, hi = 1.5 * sv.a_crit, 1e4
    f = lambda i: (lambda u: getattr(sv.states(np.exp(u)), ("p", "dn")[i]))
    E = energy(JKR, "super-critical", [lo, hi])
    assert E[1] - E[0] == pytest.approx(work(f(0), f(1), math.log(lo), math.log(hi), 120), rel=1e-10)
    rest = []
    for a in (1e2, 1e3, 1e4):
        s = single(JKR, "super-critical", a)[0]
        full = forward.full_contact_state(JKR, un, "delta_over_Delta", s.delta_over_Delta, "grip")
        gap = math.pi - s.eps
        rest.append((s.energy - full.energy) / (JKR.m ** 2 * gap) - 1)
    assert abs(rest[2]) < 1e-5 and abs(rest[2]) < abs(rest[1]) / 5 < abs(rest[0]) / 25


# --- the Maugis-Dugdale law ----------------------------------------------------------------------------------------
@pytest.mark.parametrize("lam", [pytest.param(20.0, marks=pytest.mark.slow), 50.0])     # 20: 65 s, slow
def test_the_zone_only_pin_leaves_the_free_pins_level(lam):
    """The pin entering the range (zone |phi| < c, c -> 0, delta -> -h0) has the free pin's potential 0, and
    along the zone-only branch to its touch (closed form in c: p = -2 s0 sin c, delta from h(c) = h0) the
    solver's potentials differ by int p d(delta).  Measured: 5e-10 relative at 160 points (algebraic convergence:
    1.5e-8 at 80); E(c) ~ c^2 as c -> 0."""
    pb = law_problem(lam)
    law, (c_lo, c_touch) = solver(pb).law, solver(pb)._contactless
    st = lambda c: [cz.contactless_state(x, law.m, law.s0, THETA, GB) for x in np.atleast_1d(c)]
    p_of = lambda c: np.array([s.p for s in st(c)])
    d_of = lambda c: np.array([s.delta_over_Delta for s in st(c)])
    a0 = 1e-4                                         # the solver's branch parameter: c = c_lo + a (c_touch - c_lo)
    c0 = c_lo + a0 * (c_touch - c_lo)
    E0, E1 = energy(pb, "contactless", [a0, 1.0])
    assert E1 - E0 == pytest.approx(work(p_of, d_of, c0, c_touch, 160), rel=1e-8)
    s0 = single(pb, "contactless", 1e-6)[0]
    assert s0.delta_over_Delta == pytest.approx(-pb.edge.range_over_Delta(pb.m), abs=1e-4)
    assert abs(E0) < 1e-6 * E1 and abs(s0.energy) < 2e-4 * abs(E0)   # -> 0 like c^2: the free pin's level


@pytest.mark.parametrize("lam", [20.0, 50.0])
def test_the_contact_branch_starts_at_the_zone_only_pins_touch(lam):
    """The contact branch's first state (a = 2: its trace starts at eps = 1e-6 c_touch, cohesive_zones.JUNCTION)
    is the zone-only pin's touch (a = 1), so a walk continuing from one onto the other keeps its held value: each
    compared with its state solved alone -- the touch by Brent on h(0) = 0 of the closed form
    (cohesive_zones.contactless_touch), the first contact by cohesive_state at its eps -- delta and P* agree to
    1e-8 (measured 9e-12 and 2e-12 at lambda 20, 5e-12 and 6e-13 at lambda 50; with the trace from eps_lo = 1e-3
    they were 0.0086 and 0.0016 / 0.086 and 0.0099 apart).  Along the branch (states solved alone at contacts
    from the first one, in log eps) the potentials differ by int p d(delta) (measured 1e-9 relative) up to eps =
    0.5, and the first state has the touch's potential."""
    pb = law_problem(lam)
    law, sv = solver(pb).law, solver(pb)
    at = {}

    def state(e):
        if e not in at:
            at[e] = law.state(e)
        return at[e]
    p_of = lambda u: np.array([state(math.exp(x)).p for x in u])
    d_of = lambda u: np.array([state(math.exp(x)).delta_over_Delta for x in u])
    touch = cz.contactless_touch(law.m, law.s0, THETA, GB)
    zone_only, first = single(pb, "contactless", 1.0)[0], single(pb, "sub-critical", 2.0)[0]
    alone = state(first.eps)
    assert first.eps <= 1e-6 * touch.c * (1 + 1e-12) and zone_only.extra["c"] == pytest.approx(touch.c, rel=1e-12)
    for got, ref in ((zone_only, touch), (first, alone), (first, touch)):
        assert got.delta_over_Delta == pytest.approx(ref.delta_over_Delta, abs=1e-8)
        assert got.P_star * THETA == pytest.approx(ref.p, abs=1e-8)         # p = vartheta P* (kernel scale)
    assert first.energy == pytest.approx(zone_only.energy, rel=1e-8)
    lo, mid = math.log(first.eps), math.log(law.eps_lo)
    assert cb.potential(state(law.eps_lo)) - first.energy == pytest.approx(work(p_of, d_of, lo, mid, 60), rel=1e-6)
    assert cb.potential(state(0.5)) - cb.potential(state(law.eps_lo)) == pytest.approx(
        work(p_of, d_of, mid, math.log(0.5), 60), rel=1e-9)