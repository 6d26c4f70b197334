"""The trace's end at the load cap (jkrcyl.numerics.cohesive_follow: the exit searched within the step that leaves
the domain, points backed off before it, shorter steps on lines of fixed eps past the zero load) against the plain
rule (a step that leaves is cut by 4 and regrown, no margin, no cheap: follow's defaults -- the route the trace
took before), from eps_lo (the trace's states below it, from the zone-only pin's touch, are solved alone): the
points up to the zero-load contact are the same doubles (no pull-off can move), every point is
on the branch (the residual itself), the last one lies inside the domain within 64 H_MIN of the cap as the plain
rule's does (both within 2 % of p_cap, from below), and the backed-off points shrink the last cells."""
import math

import numpy as np
import pytest

from jkrcyl.model.problem import Problem
from jkrcyl.numerics import cohesive_branch as cb
from jkrcyl.numerics import cohesive_follow as fo
from jkrcyl.numerics import cohesive_scales as scales

THETA, GB = 1.0, 1 / 2.8


def law_of(lam, M, theta=THETA):
    pb = Problem(M, theta, GB, 0.0)
    return cb.Law(pb.m, scales.zone_strength(lam, pb.m), theta, GB, 0.0)


def p_at(law, x):
    eps, d = math.exp(x[0]), math.exp(x[1])
    aff = cb.affine(law, eps, eps + d)
    return aff[1][0] - aff[1][1] * aff[0][0] / aff[0][1]


# identical bodies at the benchmark's lambda 10 and a thin zone (lambda 300, the layer subtracted), a rigid cradle
# (theta = inf: no pole of p, the cap met at a finite load) at lambda 1
@pytest.mark.parametrize("lam, M, theta", [(10.0, 0.3, THETA), (300.0, 0.3, THETA), (1.0, 0.5, math.inf)])
def test_the_exit_at_the_cap_keeps_the_pulling_part_of_the_trace(lam, M, theta):
    law = law_of(lam, M, theta)
    assert law.state(law.eps_lo).zones != "all"
    inside = lambda x: cb._inside(law, x)
    new = cb.trace(law)[0]
    new = new[new[:, 0] >= math.log(law.eps_lo)]     # the states below eps_lo: solved alone (its junction)
    start = law.state(law.eps_lo)
    plain, why = fo.follow(law, np.array([math.log(law.eps_lo), math.log(start.c - law.eps_lo)]), inside)
    assert why == ""
    p_new, p_plain = (np.array([p_at(law, x) for x in pts]) for pts in (new, plain))
    # up to the first state that pushes, the same doubles
    k = int(np.argmax(p_plain > 0))
    assert k > 0 and np.array_equal(new[:k + 1], plain[:k + 1])
    assert np.all(np.abs([fo.residual(law, x) for x in new[1:]]) <= 1e-9 * (1 + law.h0))
    # both end inside, next to the cap (64 H_MIN of arclength before the pole of p: 1.3 % of p_cap at lambda 300)
    assert all(inside(x) for x in new) and all(inside(x) for x in plain)
    assert 1 - p_new[-1] / law.p_cap <= 0.02 and 1 - p_plain[-1] / law.p_cap <= 0.02
    # where the ends differ, the last cells shrink towards the edge: the last three chords each shorter
    if not np.array_equal(new, plain):
        chords = np.hypot(*np.diff(new, axis=0).T)[-3:]
        assert np.all(np.diff(chords) < 0), chords
