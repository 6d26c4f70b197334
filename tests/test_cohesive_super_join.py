"""The super-critical branch of the Maugis-Dugdale law where its zone reaches round: the zone states between the
continuation's end (c = pi - 1e-3) and the round-zone tail's join (c -> pi), solved at each contact
(jkrcyl.numerics.cohesive_super.join_points), so that the branch runs on to the tail without the 0.016 rad gap in
eps it had (identical bodies, lambda = 5, M = 0.5: the trace ended at eps = 2.3576, the tail starts at 2.3419).

Checked against what the library does not use to make them: states solved alone at their contact by the phase-1
solver (jkrcyl.numerics.cohesive.cohesive_state: its own node count, the zone end's root nearest a rough guess),
and the total potential (Gauss quadrature of the zone's opening) changing by p d(delta) along the joined part.
"""
import math

import numpy as np
import pytest

import jkrcyl
from jkrcyl.model.single_patch import solver
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import roots

IDENTICAL = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)


@pytest.fixture(scope="module")
def joined():
    probe = jkrcyl.Contact(1e-2, 1e-6, 1.0, IDENTICAL)
    c = jkrcyl.Contact.with_lambda(1e-2, 1e-6, (0.5 / probe.M) ** 2, IDENTICAL, 5.0)
    sv = solver(c.problem)
    br = sv._super
    n = len(br.x)
    cells = list(range(n - 1 - br.n_join, n - 1))         # the table cells from the trace's end to the join
    return c, sv, br, br.offset + br.t, cells


def test_the_branch_runs_on_to_the_tail(joined):
    """From the trace's end the joined states run back in eps (monotone) with their zone end closing on the top
    (pi - c falling from 1e-3 to below 2e-7), to within 1e-5 rad of the tail's first contact, where the load is
    the tail's to 1e-5 relative (p is largest there: the branch turns back in eps)."""
    _, sv, br, a, cells = joined
    assert br.n_join >= 10
    pts = [sv.point(a[i]) for i in cells + [cells[-1] + 1]]
    eps, top = np.array([p.eps for p in pts]), np.array([math.pi - p.c for p in pts])
    assert np.all(np.diff(eps) < 0) and np.all(np.diff(top) < 0)
    assert 5e-4 < top[0] < 2e-3 and 0 < top[-1] < 2e-7
    first = sv.point(a[len(br.x)])                        # the tail's first state: the zone all round
    assert first.c == math.pi and abs(first.eps - br.tail[0]) < 1e-12
    assert 0 < eps[-1] - first.eps < 1e-5 and abs(pts[-1].p / first.p - 1) < 1e-5


def _stencil(f, a, h):
    return (f(a - 2 * h) - 8 * f(a - h) + 8 * f(a + h) - f(a + 2 * h)) / (12 * h)


def test_energy_changes_by_p_d_delta_along_the_joined_part(joined):
    """Within each table cell of the joined part (pi - c from 1e-3 to 2e-7), the total potential (elastic energy by
    Clapeyron plus the Dugdale interface energy by Gauss quadrature of the gap: cohesive_branch.potential)
    changes by p d(delta): fourth-order differences in the branch parameter, to 1e-8 relative (measured <= 2e-9);
    without the zone's interface term (-w over the zone instead) the identity fails by more than 1e-3."""
    c, sv, _, a, cells = joined
    m2 = c.problem.m ** 2
    for i in cells[::3] + [cells[-1]]:
        x, h = 0.5 * (a[i] + a[i + 1]), (a[i + 1] - a[i]) / 10
        E = _stencil(lambda y: sv.point(y).potential, x, h)
        work = sv.point(x).p * _stencil(lambda y: sv.point(y).delta, x, h)
        assert abs(E / work - 1) < 1e-8, (i, E, work)
        wrong = _stencil(lambda y: sv.point(y).potential + 2 * m2 * (sv.point(y).c - sv.point(y).eps), x, h)
        assert abs(wrong / work - 1) > 1e-3, i


# contacts between the trace's end (2.3576) and the join (2.34186), with a rough guess of the zone length c - eps
# (pi - c read off a scan of h(c) - h0 at the fixed contact, to within a factor of 3; cohesive_state refines)
ALONE = [(2.355, 8e-4), (2.35, 5e-4), (2.345, 2e-4), (2.3425, 3e-5), (2.3419, 1e-6)]


def test_states_solved_alone_lie_on_the_joined_part(joined):
    """Each state of ALONE solved by itself (cohesive_state at its contact: its own node count, the root nearest
    the guess) is a point of the branch: where the branch passes that contact on its joined part, c, p and the
    approach agree to 1e-9 (measured ~1e-13)."""
    c, sv, _, a, cells = joined
    pb = c.problem
    law = (pb.m, pb.edge.s0, pb.theta, pb.gb, pb.alpha_ratio)
    for eps, top in ALONE:
        alone = co.cohesive_state(eps, *law, near=math.pi - top - eps)
        assert alone.zones == "bottom" and math.pi - alone.c < 1e-3
        passes = [i for i in cells if (sv._where(a[i])[0] - eps) * (sv._where(a[i + 1])[0] - eps) <= 0]
        assert len(passes) == 1, (eps, passes)
        at = roots.root(lambda y: sv._where(y)[0] - eps, a[passes[0]], a[passes[0] + 1], xtol=1e-14)
        pt = sv.point(at)
        assert abs(pt.c - alone.c) < 1e-9 and abs(pt.p - alone.p) < 1e-9, (eps, pt.c - alone.c, pt.p - alone.p)
        assert abs(pt.delta - alone.delta_over_Delta) < 1e-9
