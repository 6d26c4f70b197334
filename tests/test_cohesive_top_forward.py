"""A round zone whose zone end leaves the top forward in eps (found by a fuzz run of
tests/test_cohesive_s_branch.py::test_s_branches_over_material_pairs: two rigid bodies (an elastic pin of 1 GPa,
tests/cases.py), h0 = 1.5 Delta, lambda = 1.625).  The scan of jkrcyl.numerics.cohesive_branch.top_opens calls it an
S (the first zone-end root jumps: its pair is born at a fold near eps = 1.38, c ~ 1.55, apart from the top), but
the round zone reaches the range at eps_open = 1.41079 and its zone end then leaves the top FORWARD in eps, up to
the receding limit 6e-4 past the opening (pi - c ~ 1e-2 there).  The zone-end residual with the approach eliminated
by k = 0 has a pole on the line eps = eps_crit (dk/d(delta) = 0 there) which made the branch look as if it turned
back in c; the solver refused it ("no zone end near the top").  Now traced next to the top in (eps, pi - c)
(jkrcyl.numerics.cohesive_round.near_top, a residual without the pole) and checked here against states solved at
fixed contacts (no trace), the energy identity dE = p d(delta) and the dissipation of the grip cycle's jump.
"""
import math
import sys

import numpy as np
import pytest

from cases import cohesive_contact
from jkrcyl.model.single_patch import solver
from jkrcyl.numerics import arcs
from jkrcyl.numerics import one_arc as arcs_one
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_branch as cb
from jkrcyl.numerics import roots

RIGID = (math.inf, 0.0, math.inf, 0.0, 1.5, 1.625)


@pytest.fixture(scope="module")
def forward():
    c = cohesive_contact(*RIGID)
    pb = c.problem
    law = (pb.m, pb.edge.s0, pb.theta, pb.gb, pb.alpha_ratio)
    sv = solver(pb)
    a = sv.grid("sub-critical", sv.dense_points)
    return c, law, sv, a, sv.states(a)


def _fixed(law, eps, n):
    m, s0, theta, gb, ar = law
    return co.FixedContact(eps, arcs.Kernel(theta, gb, ar), n, False)


def _opening(law, n=96):
    """eps where the round-zone state at a fixed contact of n nodes has h(pi) = h0: Brent in [1.40, 1.412] (below
    the receding contact 1.41305, where the approach at k = 0 has its pole)."""
    m, s0 = law[:2]

    def excess(eps):
        fc = _fixed(law, eps, n)
        zones = co.zones_of(math.pi)
        dn, u = fc.solve(zones, s0)
        return fc.gap(math.pi, dn, u, zones, s0)[0] - m * m / s0
    return roots.root(excess, 1.40, 1.412, xtol=1e-15)


def _zone_ends(law, eps, n, x_max=0.05):
    """(c, p) of each zone-end root with pi - c in [1e-7, x_max] at the fixed contact eps of n nodes: a sign scan
    of h(c) - h0 (the approach from k = 0) on 60 points geometric in pi - c, Brent to 1e-15."""
    m, s0 = law[:2]
    fc = _fixed(law, eps, n)

    def g(c):
        zones = co.zones_of(c)
        dn, u = fc.solve(zones, s0)
        return fc.gap(c, dn, u, zones, s0)[0] - m * m / s0
    grid = math.pi - np.geomspace(x_max, 1e-7, 60)
    v = [g(c) for c in grid]
    out = []
    for i in range(59):
        if v[i] * v[i + 1] < 0:
            c = roots.root(g, grid[i], grid[i + 1], xtol=1e-15)
            zones = co.zones_of(c)
            out.append((c, fc.load_width(fc.solve(zones, s0)[1], zones, s0)[0]))
    return out


def _on_branch(sv, a, s, eps):
    """The traced zone-end state at the contact eps (the table cell with a zone end bracketing it, Brent)."""
    cells = [i for i in range(a.size - 1) if (s.eps[i] - eps) * (s.eps[i + 1] - eps) <= 0 and s.c[i + 1] < math.pi]
    assert len(cells) == 1, cells
    i = cells[0]
    return sv.point(roots.root(lambda x: sv._where(x)[0] - eps, a[i], a[i + 1], xtol=1e-14))


def test_the_zone_end_leaves_the_top_forward(forward):
    """At fixed contacts (96 nodes, no trace): below the opening no zone end lies within 0.05 of the top; above it
    exactly one, moving away from the top as eps grows.  The traced branch: round up to the opening (to 1e-9,
    the node counts' difference), then a zone end with eps rising all the way to the receding contact eps_crit
    (one_arc.receding_contact: its last point on it to 1e-12, followed across the trace's margin there by
    jkrcyl.numerics.cohesive_crossing), no reason to stop."""
    c, law, sv, a, s = forward
    eps_open = _opening(law)
    assert _zone_ends(law, eps_open * (1 - 1e-4), 96) == []
    ends = [_zone_ends(law, eps_open * (1 + r), 96) for r in (1e-4, 3e-4, 5e-4)]
    assert [len(e) for e in ends] == [1, 1, 1]
    assert ends[0][0][0] > ends[1][0][0] > ends[2][0][0]
    assert sv.unmodelled == "" and sv._sub.reason == ""
    zone = np.nonzero(s.c < math.pi)[0]
    assert abs(s.eps[zone[0] - 1] / eps_open - 1) < 1e-9
    assert np.all(np.diff(s.eps[zone]) > 0)
    eps_crit = 2 * math.atan(arcs_one.receding_contact(*law[2:]))
    assert sv._sub.crossed and abs(s.eps[zone[-1]] / eps_crit - 1) < 1e-12


@pytest.mark.parametrize("rel", [1e-5, 1e-4, 3e-4, 5e-4])
def test_states_solved_alone_lie_on_the_forward_branch(forward, rel):
    """The zone end at the fixed contact eps_open (1 + rel), solved alone (:func:`_zone_ends`) with the law's node
    count (the trace's discretisation, no trace): c to 1e-11 (measured <= 2e-12), p to 5e-10 (measured <= 9e-11:
    the approach from k = 0 divides by dk/d(delta), only ~3e-4 here, 1e-3 from the receding contact where it
    vanishes); with 96 nodes (another discretisation) both to 1e-9 (measured ~1e-10)."""
    c, law, sv, a, s = forward
    eps = _opening(law) * (1 + rel)
    pt = _on_branch(sv, a, s, eps)
    n = cb.Law(*law).contact(eps)[0]
    for nodes, tol_c, tol_p in ((n, 1e-11, 5e-10), (96, 1e-9, 1e-9)):
        (c_alone, p_alone), = _zone_ends(law, eps, nodes)
        assert abs(c_alone - pt.c) < tol_c and abs(p_alone - pt.p) < tol_p, (nodes, c_alone - pt.c, p_alone - pt.p)


def _stencil(f, a, h):
    return (f(a - 2 * h) - 8 * f(a - h) + 8 * f(a + h) - f(a + 2 * h)) / (12 * h)


def test_energy_changes_by_p_d_delta_along_the_forward_zone_end(forward):
    """Inside table cells of the zone part (next to the opening, midway, next to the receding limit) the total
    potential (jkrcyl.numerics.cohesive_branch.potential: Clapeyron plus the Dugdale interface energy by
    quadrature) changes by p d(delta): fourth-order differences in the branch parameter, 1e-8 relative
    (measured <= 4e-9); without the zone's interface term it fails by more than 1e-2."""
    c, law, sv, a, s = forward
    m = law[0]
    zone = np.nonzero(s.c < math.pi)[0]
    for j in (zone[1], zone[zone.size // 2], zone[-1]):
        mid, h = 0.5 * (a[j - 1] + a[j]), 0.04 * (a[j] - a[j - 1])
        E = _stencil(lambda z: sv.point(z).potential, mid, h)
        work = sv.point(mid).p * _stencil(lambda z: sv.point(z).delta, mid, h)
        assert abs(E / work - 1) < 1e-8, (j, E, work)
        wrong = _stencil(lambda z: sv.point(z).potential + 2 * m ** 2 * (sv.point(z).c - sv.point(z).eps), mid, h)
        assert abs(wrong / work - 1) > 1e-2


def test_a_grip_cycle_jumps_off_the_round_zone_and_dissipates(forward):
    """Pushed under grip, the round zone's last stable state jumps at one approach (1e-9) onto a state past the
    receding limit, the potential not rising (Equilibrium.energy before and after); every jump dissipates >= 0
    (the cycle does not close: the super-critical branch has no stable state past the zip, so no loop energy)."""
    c = forward[0]
    grip = c.cycle(control="grip", delta_max=0.3 * c.Delta, delta_min=-0.6 * c.Delta, n=20)
    assert grip.jumps
    for j in grip.jumps:
        assert j.before.delta == pytest.approx(j.after.delta, rel=1e-9, abs=1e-15)
        assert j.before.energy - j.after.energy >= -1e-12 * abs(j.before.energy), j
    assert grip.jumps[0].before.eps < grip.jumps[0].after.eps


def test_the_state_at_the_receding_contact_is_listed():
    """The zone end near the top crosses the receding contact eps_crit with a finite approach and load (k at
    delta = 0 vanishes there too): solved alone at eps_crit -- the root of k1 g0 - k0 g1 (no pole,
    cohesive_round._gap_at_rest's combination) at a fixed contact of 96 nodes, the approach from g = 0 -- it has
    pi - c = 0.024, p = 0.667 (kernel scale).  The traces stop at eps_crit (1 -+ 1e-3) (p 0.7041 and 0.6374, the
    same arm); followed on without the pole (jkrcyl.numerics.cohesive_crossing) they meet there, the sub-critical
    table's end continuing as the super-critical one's: solve at that load lists the state."""
    from jkrcyl.numerics import cohesive_kernels as ck
    from jkrcyl.numerics import one_arc
    c = cohesive_contact(*RIGID)
    pb = c.problem
    law = (pb.m, pb.edge.s0, pb.theta, pb.gb, pb.alpha_ratio)
    eps = 2 * math.atan(one_arc.receding_contact(pb.theta, pb.gb, pb.alpha_ratio))
    fc = _fixed(law, eps, 96)
    aff = lambda x: ck.affine(fc.fx, fc.ek, fc.ep, fc.eb, math.pi - x, pb.edge.s0, law[0] ** 2 / pb.edge.s0)
    f = lambda x: (lambda v: v[1] * v[6] - v[0] * v[7])(aff(x))
    xs = np.geomspace(1e-4, 0.1, 60)
    fs = [f(x) for x in xs]
    i = next(j for j in range(59) if fs[j] * fs[j + 1] <= 0)
    v = aff(roots.root(f, xs[i], xs[i + 1], xtol=1e-15))
    delta = -v[6] / v[7]
    p = v[2] + delta * v[3]
    assert 0.6 < p < 0.7
    found = c.solve(P=p * c.load_scale / pb.scale)
    assert any(abs(e.eps - eps) < 1e-6 for e in found), [e.eps for e in found]
