"""The round-zone state at the degenerate contact of the collocation operator (jkrcyl.numerics.cohesive_bordered).

A rigid cradle with an elastic pin (tests/cases.py: E = inf, E_I = 1 GPa, nu_I 0.3 -> vartheta = inf, gb = 1/1.4),
lambda = 3, h0 = Delta: the super-critical branch's round-zone tail crosses eps_s = 2.86804716, where the fixed
contact's operator A is singular (its least singular value drops ~1000-fold there, whatever the node count) and
the unit solutions' edge coefficient k(U1) = dk/d(delta) has a pole.  The grip fold of the round zone (the least
approach) lies there too, so the grip pull-off, refined on the branch, read the load where the affine route
(U0 + delta U1, each ~1/(eps - eps_s)) is noise: 10250.8 or 10291.0 N/m between runs.  Checked here against what
the bordered route does not use: the singular values of A, the affine route's states away from eps_s (accurate
there) and the approach, which the affine route gets to 1e-14 even at eps_s (only u and p cancel).
"""
import math

import numpy as np
import pytest

from cases import cohesive_contact
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_bordered as bo
from jkrcyl.numerics import cohesive_branch as cb
from jkrcyl.numerics import cohesive_contact as cc
from jkrcyl.numerics import cohesive_kernels as ck
from jkrcyl.numerics import roots

CRADLE = (math.inf, 0.0, 1e9, 0.3, 1.0, 3.0)


@pytest.fixture(scope="module")
def law():
    pb = cohesive_contact(*CRADLE).problem
    return cb.Law(pb.m, pb.edge.s0, pb.theta, pb.gb, pb.alpha_ratio)


def _pole(law, n):
    """eps where 1/k(U1) of a fixed contact with n nodes vanishes (Brent in [2.86, 2.87])."""
    return roots.root(lambda e: 1 / co.FixedContact(e, law.kernel, n, False).fx[6], 2.86, 2.87, xtol=1e-15)


def _plain(law, eps):
    return co.FixedContact(eps, law.kernel, *law.contact(eps))


def _affine(law, eps):
    """(p, delta/Delta) of the round-zone state by the affine route (FixedContact.solve: delta from k = 0) of the
    plain collocation system (Law.fixed shifts it next to eps_s)."""
    fc = _plain(law, eps)
    zones = co.zones_of(math.pi)
    dn, u = fc.solve(zones, law.s0)
    return fc.load_width(u, zones, law.s0)[0], dn


def test_the_operator_is_singular_at_one_contact(law):
    """The pole of dk/d(delta) lies at the same contact for 48, 80 and 128 nodes (1e-10: the continuous
    operator's, not the discretisation's), and there the least singular value of A drops over 100-fold against
    1e-5 to either side (measured 600-fold at 48 nodes, 2000-fold at 80)."""
    es = [_pole(law, n) for n in (48, 80, 128)]
    assert max(es) - min(es) < 1e-10, es
    for n, e in zip((48, 80), es):
        sv = lambda e: np.linalg.svd(co.FixedContact(e, law.kernel, n, False).sys.A, compute_uv=False)[-1]
        assert sv(e) < 1e-2 * min(sv(e - 1e-5), sv(e + 1e-5))


def test_the_load_is_smooth_through_the_degenerate_contact(law):
    """At eps_s + k 1e-13 (k = -3 .. 3) the round-zone load (bordered) lies on the quintic through the affine
    route's loads at eps_s +- 5e-3, 1e-2, 2e-2 (accurate there: its error ~5e-16/(eps - eps_s)) to 1e-10 -- the
    smoothness bound (measured 6e-12); the affine route at those contacts misses it by more than 1e-4 (measured
    19: the noise found), while its approach is right to 1e-12 (bordered vs affine)."""
    es = _pole(law, law.contact(2.868)[0])
    xs = np.array([-2e-2, -1e-2, -5e-3, 5e-3, 1e-2, 2e-2])
    parabola = np.polyfit(xs, [_affine(law, es + x)[0] for x in xs], 5)
    worst = 0.0
    for k in range(-3, 4):
        e = es + k * 1e-13
        p, delta, _ = bo.round_values(law, e)
        assert abs(p - np.polyval(parabola, k * 1e-13)) < 1e-10 * abs(p), k
        p_aff, d_aff = _affine(law, e)
        assert abs(d_aff - delta) < 1e-12
        worst = max(worst, abs(p_aff - p) / abs(p))
    assert worst > 1e-4


def test_stability_derivatives_are_finite_through_it(law):
    """D_dn = 1/(dk/d delta) and D_p = (dp/d delta)/(dk/d delta) of the bordered system equal the affine route's
    (1/k(U1), p(U1)/k(U1)) at 1e-3 from eps_s to 1e-9, and vanish / stay finite at eps_s (|D_dn| < 1e-9)."""
    es = _pole(law, law.contact(2.868)[0])
    for e in (es - 1e-3, es + 1e-3):
        fc = _plain(law, e)
        b = bo.of(law, e)
        assert abs(b.inv_k_delta - 1 / fc.fx[6]) < 1e-9 * abs(1 / fc.fx[6])
        assert abs(b.p_per_k - (fc.ep @ fc.fx[4]) / fc.fx[6]) < 1e-9 * abs(b.p_per_k)
    b = bo.of(law, es)
    assert abs(b.inv_k_delta) < 1e-9 and math.isfinite(b.p_per_k)


def test_the_grip_pull_off_reads_the_fold_of_the_round_zone():
    """The grip pull-off of the cradle is the round zone's grip fold (the least approach over its states): at the
    minimum of the affine route's approach (Brent's, at contacts solved alone; accurate at every contact) the load
    of the affine route interpolated from 5e-3 .. 2e-2 away (a quintic through three contacts on each side):
    equal to 1e-6 relative (measured 6.7e-8: the table's central differences put the fold 6e-7 rad past the
    minimum).  It read 10291.0 N/m (noise) before."""
    c = cohesive_contact(*CRADLE)
    po = c.pull_off("grip")
    assert po.P is None and po.reason.startswith("fold at P")
    pb = c.problem
    law = cb.Law(pb.m, pb.edge.s0, pb.theta, pb.gb, pb.alpha_ratio)
    e_min, _ = roots.minimum(lambda e: _affine(law, e)[1], 2.85, 2.868, 2.89, 1e-9)
    xs = np.array([-2e-2, -1e-2, -5e-3, 5e-3, 1e-2, 2e-2])
    p_fold = np.polyval(np.polyfit(xs, [_affine(law, e_min + x)[0] for x in xs], 5), 0.0)
    p_walk = po.state.P / c.load_scale * pb.scale
    assert abs(p_walk / p_fold - 1) < 1e-6, (p_walk, p_fold)


# --- a zone end crossing eps_s: the super-critical branch at lambda = 10 --------------------------------------
SUPER = (math.inf, 0.0, 1e9, 0.3, 1.0, 10.0)
# its two arms through eps_s (pi - c there ~0.21 going up in eps, ~0.024 coming back: read off the traced branch)
ARMS = (math.pi - 0.21, math.pi - 0.024)
DISTANCES = (1e-3, -1e-3, 1e-5, 1e-7, -1e-7, 1e-9, -1e-9)


def _alone(law, eps, c_near):
    """(c, p, delta/Delta) of the zone-end state nearest c_near at the contact eps solved alone by the bordered
    system [[A, -cos], [k, 0]] (regular at eps_s; jkrcyl.numerics.cohesive_bordered.Bordered, its own fixed
    contact, the zone traction as a right-hand side) with the zone end by Brent on h(c) - h0 (41-point scan)."""
    fc = co.FixedContact(eps, law.kernel, *law.contact(eps))
    b = bo.Bordered(fc)

    def solved(c):
        zones = co.zones_of(c)
        x = b._solve(b.clearance + law.s0 * ck.zone_rhs(fc.fx, zones), 0.0)
        return x[:-1], float(x[-1]), zones

    def g(c):
        u, delta, zones = solved(c)
        return fc.gap(c, delta, u, zones, law.s0)[0] - law.h0
    grid = np.linspace(0.97 * c_near, min(1.03 * c_near, math.pi - 1e-9), 41)
    v = [g(x) for x in grid]
    lo, hi = min([(grid[i], grid[i + 1]) for i in range(40) if v[i] * v[i + 1] <= 0],
                 key=lambda br: abs(br[0] + br[1] - 2 * c_near))
    c = roots.root(g, lo, hi, xtol=1e-15)
    u, delta, zones = solved(c)
    return c, fc.load_width(u, zones, law.s0)[0], delta


def _richardson(law, eps, c, h=1e-4):
    """dp/d(delta) along the branch at the contact eps from the states solved alone at eps +- h, +- 2h
    (Richardson of two central quotients: the quotients differ by ~1e-6, the extrapolated one converged to
    ~1e-9 between h = 2e-4 and 2.5e-5)."""
    s = {k: _alone(law, eps + k * h, c) for k in (-2, -1, 1, 2)}
    q1 = (s[1][1] - s[-1][1]) / (s[1][2] - s[-1][2])
    q2 = (s[2][1] - s[-2][1]) / (s[2][2] - s[-2][2])
    return (4 * q1 - q2) / 3


@pytest.fixture(scope="module")
def super_law():
    pb = cohesive_contact(*SUPER).problem
    return cb.Law(pb.m, pb.edge.s0, pb.theta, pb.gb, pb.alpha_ratio)


def test_a_zone_end_branch_is_regular_through_eps_s(super_law):
    """The super-critical branch at lambda 10 (rigid cradle, elastic pin) crosses eps_s twice with its zone end
    short of the top.  At 1e-3 .. 1e-9 from eps_s on each arm the branch's state (its zone end at the fixed
    contact, jkrcyl.numerics.cohesive_branch.Law.fixed: the shifted system there) is the bordered one solved alone
    (c and p to 1e-10; measured <= 7e-12), and its dp/d(delta) (cohesive_branch.point: dp/dt over d(delta)/dt)
    is the Richardson quotient of states solved alone to 1e-8 (measured <= 3e-9; before, through the
    unshifted system: 1.5e-4 at 1e-3, O(1) at 1e-5, 700 at 1e-9).  The unshifted fixed contact's zone end
    misses the bordered one by more than 1e-9 at 1e-9 from eps_s (measured 1e-7 .. 5e-7): the check can fail."""
    law = super_law
    es = _pole(law, law.contact(2.868)[0])
    for arm in ARMS:
        for dist in DISTANCES:
            eps = es + dist
            c, p, _ = _alone(law, eps, arm)
            fc = law.fixed(eps)
            assert fc.shift != 0.0
            c_branch = eps + fc.zone_end_near(law.s0, law.h0, c - eps)
            pt = cb.point(law, eps, c_branch, (1.0, 0.0))
            assert abs(c_branch - c) < 1e-10 and abs(pt.p - p) < 1e-10 * max(1.0, abs(p)), (arm, dist)
            ref = _richardson(law, eps, c)
            assert abs(pt.dp_dt / pt.ddn_dt / ref - 1) < 1e-8, (arm, dist, pt.dp_dt / pt.ddn_dt, ref)
        plain = _plain(law, es + 1e-9)
        c, _, _ = _alone(law, es + 1e-9, arm)
        assert abs(es + 1e-9 + plain.zone_end_near(law.s0, law.h0, c - es - 1e-9) - c) > 1e-9


def test_the_shifted_system_has_the_same_equilibria(super_law):
    """Away from eps_s (2e-2: both systems regular) the shifted fixed contact's zone end, approach and load equal
    the plain one's to 1e-12, while its approach coefficient k(U1) is the Sherman-Morrison one, k/(1 - shift k)
    (1e-12): the same states, another affine representation."""
    law = super_law
    es = _pole(law, law.contact(2.868)[0])
    for eps in (es - 2e-2, es + 2e-2):
        n, layered = law.contact(eps)
        plain = co.FixedContact(eps, law.kernel, n, layered)
        shifted = co.FixedContact(eps, law.kernel, n, layered, shift=cc.SHIFT)
        for arm in ARMS:
            d0 = plain.zone_end_near(law.s0, law.h0, arm - eps)
            d1 = shifted.zone_end_near(law.s0, law.h0, d0)
            assert abs(d1 - d0) < 1e-12
            zones = co.zones_of(eps + d0)
            (a0, u0), (a1, u1) = plain.solve(zones, law.s0), shifted.solve(zones, law.s0)
            assert abs(a1 - a0) < 1e-12
            p0, p1 = plain.load_width(u0, zones, law.s0)[0], shifted.load_width(u1, zones, law.s0)[0]
            assert abs(p1 - p0) < 1e-12 * max(1.0, abs(p0))
        k = plain.fx[6]
        assert abs(shifted.fx[6] / (k / (1 - cc.SHIFT * k)) - 1) < 1e-12
