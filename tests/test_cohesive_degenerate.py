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
from jkrcyl.numerics import roots

CRADLE = (math.inf, 0.0, 1e9, 0.3, 1.0, 3.0)


@pytest.fixture(scope="module")
def law():
    pb = cohesive_contact(*CRADLE).problem
    return cb.Law(pb.m, pb.edge.s0, pb.theta, pb.gb, pb.alpha_ratio)


def _pole(law, n):
    """eps where 1/k(U1) of a fixed contact with n nodes vanishes (Brent in [2.86, 2.87])."""
    return roots.root(lambda e: 1 / co.FixedContact(e, law.kernel, n, False).fx[6], 2.86, 2.87, xtol=1e-15)


def _affine(law, eps):
    """(p, delta/Delta) of the round-zone state by the affine route (FixedContact.solve: delta from k = 0)."""
    fc = law.fixed(eps)
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
        fc = law.fixed(e)
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
