"""The continuation of the Maugis-Dugdale contact branch (jkrcyl.numerics.cohesive_follow, issue 19 speed).

follow corrects mostly on lines of fixed eps (one LU per step); checked against the pseudo-arclength tracer of
jkrcyl.numerics.continuation (Newton on both coordinates, gradients by finite differences: an independent
route) on branches with and without a fold in eps, and every traced point against the residual itself.  The
stand-alone pull-off (jkrcyl.numerics.cohesive_pull_off) whose minimum of p lies next to a fold in eps is
checked against the walker's fold state (jkrcyl.analysis.pull_off on the model core's table).
"""
import math

import numpy as np
import pytest

import jkrcyl
from jkrcyl.analysis import pull_off as po
from jkrcyl.laws import DugdaleEdge
from jkrcyl.model.problem import Problem
from jkrcyl.model.single_patch import solver
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_branch as cb
from jkrcyl.numerics import cohesive_follow as fo
from jkrcyl.numerics import cohesive_pull_off as cpo
from jkrcyl.numerics import cohesive_scales as scales
from jkrcyl.numerics import continuation as cont
from jkrcyl.units import Units

THETA, GB = 1.0, 1 / 2.8
# (lambda, M): a branch monotone in eps (the README pin's lambda = 3 at M = 0.2), one that turns back to eps -> 0
# at a sharp fold in eps (no zero-load contact), one with the minimum of p next to a fold in eps (the map's grid
# points 75 x 82, 75 x 83 of 100 x 100 over lambda in [0.01, 10], M in [0.01, 1])
MONOTONE = (3.0, 0.2)
TURNS_BACK = (1.873817422860385, 0.4750810162102798)
MIN_AT_FOLD = (1.873817422860385, 0.4534878508128584)


def law_of(lam, M):
    pb = Problem(M, THETA, GB, 0.0)
    return cb.Law(pb.m, scales.zone_strength(lam, pb.m), THETA, GB, 0.0)


def start_and_domain(law):
    start = law.state(law.eps_lo)

    def inside(x):
        eps, d = math.exp(x[0]), math.exp(x[1])
        if not (law.eps_lo * 0.999 <= eps < law.eps_hi and eps + d < math.pi * (1 - 1e-9)):
            return False
        aff = cb.affine(law, eps, eps + d)
        return aff[1][0] - aff[1][1] * aff[0][0] / aff[0][1] < law.p_cap
    return np.array([math.log(law.eps_lo), math.log(start.c - law.eps_lo)]), inside


def pseudo_arclength(law, x0, inside, h_min=1e-5):
    return cont.trace(lambda x: fo.residual(law, x), x0, np.array([1.0, 0.0]), inside, lambda a, b: (None, "end"),
                      h0=0.1, h_max=0.25, h_min=h_min).points


@pytest.mark.parametrize("lam, M", [MONOTONE, TURNS_BACK])
def test_follow_traces_the_branch_of_the_pseudo_arclength_tracer(lam, M):
    """Every point of follow is on the branch (|h(c) - h0| <= 1e-9 (1 + h0)); its eps-range, its folds in eps and
    its end equal those of the pseudo-arclength trace (the fold's eps to 1e-3 in log eps: both sample the curve,
    the tip lies between samples; the end to 1e-2: follow stops within 64 H_MIN of the edge)."""
    _against_pseudo_arclength(law_of(lam, M))


def test_follow_goes_round_a_tight_turn_of_a_material_pair():
    """vartheta 2.83, gb 0.694 (E 17.1 GPa, nu 0.234 round E_I 3.24 GPa, nu_I 0.407), lambda 3.87, M 0.488: the
    branch turns back in eps at 0.01413 so tightly that follow stopped there with the step at 1e-5 ('the step fell
    below H_MIN', every analysis of the contact refused; M 0.47 and 0.5 passed).  As the pseudo-arclength trace
    (its smallest step 1e-7)."""
    mat = jkrcyl.Materials.from_young(E=1.71e10, nu=0.234, E_I=3.24e9, nu_I=0.407)
    w = (0.488 / jkrcyl.Contact(1e-2, 1e-5, 1.0, mat).M) ** 2
    c = jkrcyl.Contact.with_lambda(1e-2, 1e-5, w, mat, 3.87)
    _against_pseudo_arclength(solver(c.problem).law, h_min=1e-7)


def _against_pseudo_arclength(law, h_min=1e-5):
    x0, inside = start_and_domain(law)
    got, why = fo.follow(law, x0, inside)
    assert why == ""
    ref = pseudo_arclength(law, x0, inside, h_min)
    res = np.array([fo.residual(law, x) for x in got[1:]])
    assert np.all(np.abs(res) <= 1e-9 * (1 + law.h0))
    turns = lambda x: int(np.sum(np.diff(np.sign(np.diff(x[:, 0]))) != 0))
    assert turns(got) == turns(ref)
    assert got[:, 0].max() == pytest.approx(ref[:, 0].max(), abs=1e-3)
    assert np.abs(got[-1] - ref[-1]).max() <= 1e-2


def test_follow_turns_back_at_a_sharp_fold():
    """The branch at TURNS_BACK turns back to eps -> 0 (a fold whose two roots of h(c) = h0 lie within 1 % in c,
    inside one step of a bracket search): follow goes round it and ends near the start's eps."""
    law = law_of(*TURNS_BACK)
    x0, inside = start_and_domain(law)
    got, why = fo.follow(law, x0, inside)
    assert why == ""
    assert got[:, 0].max() > -1.4 and got[-1, 0] < x0[0] + 0.01


def test_stand_alone_pull_off_at_a_fold_in_eps_equals_the_walkers_fold():
    """MIN_AT_FOLD: the least p of the branch lies next to its fold in eps, where eps is no parameter; the
    stand-alone pull-off (map steps and default steps) equals the walker's fold state to 1e-8 (relative)."""
    lam, M = MIN_AT_FOLD
    pb0 = Problem(M, THETA, GB, 0.0)
    s0 = scales.zone_strength(lam, pb0.m)
    pb = Problem(M, THETA, GB, 0.0, edge=DugdaleEdge(s0))
    walker = po.pull_off(pb, Units.normalised(pb), "load")
    assert walker.state is not None and "fold" in walker.reason
    for kw in (dict(), dict(steps=(0.3, 1.2), xtol=1e-6, zero_load=False)):
        got = cpo.pull_off_load(pb.m, s0, THETA, GB, 0.0, **kw)
        assert got.kind == "fold"
        assert got.p / pb.scale == pytest.approx(walker.state.P, rel=1e-8)
