"""The Maugis-Dugdale branch across the receding contact eps_crit (jkrcyl.numerics.cohesive_crossing).

The traces eliminate the approach by k = 0, whose slope in the approach vanishes at eps_crit, and stop 1e-3 short
of it on either side; the branch is the zero set of k1 g0 - k0 g1 (k = k0 + delta k1, g = h(c) - h0 = g0 + delta
g1 at a fixed contact), regular across the line.  Two pairs where the branch crosses it with a finite load:
* a rigid pair (h0 1.5 Delta, lambda 1.625; tests/test_cohesive_top_forward.py): the zone end near the top crosses
  at pi - c = 0.024, p = 0.667 -- the sub-critical table's end, joined to the super-critical table's end;
* vartheta 1, lambda 50, M 0.392 (slow): the crossing carries the law's zero-load contact, ~3.6e-4 below
  eps_crit, on the super-critical table's part that runs back across the line and folds there.
References: states solved alone at their contact (a FixedContact built here, the root of k1 g0 - k0 g1 in c
bracketed on a grid, the approach from g = 0: no trace, no least squares), eps_crit from one_arc's closed form,
the energy identity dE = p d(delta).
"""
import math

import numpy as np
import pytest

from cases import cohesive_contact
from jkrcyl.model.single_patch import solver
from jkrcyl.numerics import arcs
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_branch as cb
from jkrcyl.numerics import cohesive_kernels as ck
from jkrcyl.numerics import one_arc
from jkrcyl.numerics import roots

RIGID = (math.inf, 0.0, math.inf, 0.0, 1.5, 1.625)


def _eps_crit(pb):
    return 2 * math.atan(one_arc.receding_contact(pb.theta, pb.gb, pb.alpha_ratio))


def _alone(pb, eps, c_near, n=None):
    """(c, p) of the equilibrium at the fixed contact eps whose zone end is next to c_near: the root of
    k1 g0 - k0 g1 in c on a FixedContact of the law's node count (or n), bracketed on a grid of +-1e-3 (c - eps)
    around c_near; the approach from g = 0."""
    law = cb.Law(pb.m, pb.edge.s0, pb.theta, pb.gb, pb.alpha_ratio)
    nodes, layered = law.contact(eps)
    fc = co.FixedContact(eps, arcs.Kernel(pb.theta, pb.gb, pb.alpha_ratio), n or nodes, layered and n is None)
    aff = lambda c: ck.affine(fc.fx, fc.ek, fc.ep, fc.eb, c, law.s0, law.h0)
    f = lambda c: (lambda v: v[1] * v[6] - v[0] * v[7])(aff(c))
    w = 1e-3 * (c_near - eps)
    grid = c_near + w * np.linspace(-1, 1, 41)
    vals = [f(c) for c in grid]
    i = min((j for j in range(40) if vals[j] * vals[j + 1] <= 0), key=lambda j: abs(grid[j] - c_near))
    c = roots.root(f, grid[i], grid[i + 1], xtol=1e-15)
    v = aff(c)
    return c, v[2] - v[6] / v[7] * v[3]


def _stencil(f, a, h):
    return (f(a - 2 * h) - 8 * f(a - h) + 8 * f(a + h) - f(a + 2 * h)) / (12 * h)


@pytest.fixture(scope="module")
def rigid():
    c = cohesive_contact(*RIGID)
    sv = solver(c.problem)
    return c, sv, sv._sub, sv._super


def test_the_sub_critical_end_on_eps_crit_continues_as_the_super_critical_end(rigid):
    """The sub-critical table ends on eps_crit (1e-12) and its end continues as the super-critical table's end
    (the same state: eps, c, p, delta to 1e-12) and back; p there = the state solved alone (1e-9; measured 1.2e-12)."""
    c, sv, sub, sup = rigid
    pb = c.problem
    assert sub.crossed and sup.joined == "end"
    a_sub, a_sup = sub.offset + sub.t[-1], sup.offset + sup.t[-1]
    assert sv.continues("sub-critical", a_sub) == ("super-critical", a_sup)
    assert sv.continues("super-critical", a_sup) == ("sub-critical", a_sub)
    assert sv.continues("sub-critical", a_sub - 1e-3) is None
    s, t = sv.point(a_sub), sv.point(a_sup)
    assert abs(s.eps / _eps_crit(pb) - 1) < 1e-12
    for k in ("eps", "c", "p", "delta"):
        assert getattr(s, k) == pytest.approx(getattr(t, k), rel=1e-12, abs=1e-12), k
    c_alone, p_alone = _alone(pb, s.eps, s.c)
    assert abs(c_alone - s.c) < 1e-10 and abs(p_alone - s.p) < 1e-9


@pytest.mark.parametrize("which", ["sub-critical", "super-critical"])
def test_states_across_the_margin_solved_alone(rigid, which):
    """Mid-cell states of the part followed past the trace's margin (the sub-critical end up to eps_crit, the
    super-critical end back down to it) equal the states solved alone at their contact (:func:`_alone`): c to
    1e-10, p to 1e-8 (the law's node count; measured <= 4.2e-12); with 96 nodes (another discretisation) to 1e-9
    (measured <= 3e-11)."""
    c, sv, sub, sup = rigid
    br = sub if which == "sub-critical" else sup
    n_after = br.cross[1]
    assert n_after >= 3
    t = br.t[len(br.x) - 1 - n_after:len(br.x)]
    for a in br.offset + 0.5 * (t[:-1] + t[1:])[[0, n_after // 2, -1]]:
        pt = sv.point(a)
        assert abs(pt.eps / _eps_crit(c.problem) - 1) < 2e-3
        for n, tol_c, tol_p in ((None, 1e-10, 1e-8), (96, 1e-9, 1e-9)):
            c_alone, p_alone = _alone(c.problem, pt.eps, pt.c, n)
            assert abs(c_alone - pt.c) < tol_c and abs(p_alone - pt.p) < tol_p, (a, n, c_alone - pt.c, p_alone - pt.p)


def test_energy_changes_by_p_d_delta_across_the_margin(rigid):
    """Inside the cells followed past the margin (sub-critical: first, last -- on eps_crit --; super-critical:
    middle) the total potential changes by p d(delta): fourth-order differences in the branch parameter, 1e-8
    relative (measured <= 1.4e-10)."""
    c, sv, sub, sup = rigid
    for br, cells in ((sub, (0, -1)), (sup, (sup.cross[1] // 2,))):
        t = br.t[len(br.x) - 1 - br.cross[1]:len(br.x)]
        for j in cells:
            lo, hi = t[:-1][j], t[1:][j]
            mid, h = br.offset + 0.5 * (lo + hi), 0.04 * (hi - lo)
            E = _stencil(lambda z: sv.point(z).potential, mid, h)
            work = sv.point(mid).p * _stencil(lambda z: sv.point(z).delta, mid, h)
            assert abs(E / work - 1) < 1e-8, (j, E, work)


def test_the_super_critical_start_runs_back_across_eps_crit_to_the_load_cap(rigid):
    """The super-critical table's start (the first root at eps_crit (1 + 1e-3)) crosses the line with a finite
    load too, folds below it and ends at the load cap P_CAP m^(4/3) (p unbounded towards the pole there): its
    first point's p within 1e-3 of the cap (measured 2e-10), its states solved alone (c 1e-10, p 1e-8; measured
    8e-13, 1.5e-10)."""
    c, sv, sub, sup = rigid
    n_before = sup.cross[0]
    assert n_before >= 3
    first = sv.point(sup.offset)
    assert abs(first.p / sv.law.p_cap - 1) < 1e-3 and first.eps < _eps_crit(c.problem)
    for a in sup.offset + 0.5 * (sup.t[:n_before] + sup.t[1:n_before + 1])[[1, n_before // 2, -1]]:
        pt = sv.point(a)
        c_alone, p_alone = _alone(c.problem, pt.eps, pt.c)
        assert abs(c_alone - pt.c) < 1e-10 and abs(p_alone - pt.p) < 1e-8, (a, c_alone - pt.c, p_alone - pt.p)


def _zero_load(M, theta, lam):
    """(a, point) of the law's zero-load state on the part of the super-critical table below eps_crit."""
    from jkrcyl.atlas import cohesive as atlas_law
    pb = atlas_law.law_problem(M, theta, lam)
    sv = solver(pb)
    a, p = sv.table_values("super-critical", "p")
    sup = sv._super
    part = a <= sup.offset + sup.t[sup.cross[0]]
    cells = [k for k in range(len(a) - 1) if part[k + 1] and p[k] * p[k + 1] <= 0]
    assert len(cells) == 1, cells
    k = cells[0]
    pt = sv.point(sv.root("p", a[k], a[k + 1], p[k], p[k + 1]))
    return pb, pt


@pytest.mark.slow
def test_the_zero_load_contact_next_to_a_crit_tends_to_jkrs():
    """vartheta 1, M 0.392 (JKR: the zero-load contact a0 just past a_crit, the closed form (4.4) solved for P = 0
    here): the law's zero-load state lies on the part of its branch that crosses eps_crit with a finite load and
    folds below it (followed by jkrcyl.numerics.cohesive_crossing; the traces stopped 1e-3 short of eps_crit and
    the first contact was 'none'); solved alone (c 1e-10, p 1e-8) and tending to JKR's as C/lambda^2:
    lambda^2 (a - a0) agrees between lambda 50 and 100 to 15 % (measured -1.30, -1.29) and is not zero."""
    from jkrcyl import equilibria as eq
    scaled = []
    for lam in (50.0, 100.0):
        pb, pt = _zero_load(0.392, 1.0, lam)
        c_alone, p_alone = _alone(pb, pt.eps, pt.c)
        assert abs(c_alone - pt.c) < 1e-10 and abs(p_alone - pt.p) < 1e-8
        a_crit = one_arc.receding_contact(pb.theta, pb.gb, pb.alpha_ratio)
        jkr_p = lambda a: eq.curve(pb.M, pb.theta, "super-critical", gb=pb.gb, a=np.array([a])).P_star[0]
        a0 = roots.root(jkr_p, a_crit * (1 + 1e-7), a_crit * 1.01, xtol=1e-14)
        scaled.append(lam ** 2 * (math.tan(pt.eps / 2) - a0))
    assert abs(scaled[0]) > 0.1 and abs(scaled[1] / scaled[0] - 1) < 0.15, scaled
