"""Load-control pull-off of the Maugis-Dugdale contact (jkrcyl.numerics.cohesive_pull_off, issue 19).

References: Baney and Hui's (1997) pull-off (reference/baney_hui.py: the minimum of their load over the contact
width, reproducing the printed -Pbar_c) in the half-plane limit; the JKR pull-off (the minimum of the Griffith
states of the library's single-patch solver, checked against the closed forms) for lambda -> inf; a dense scan of
the states along the branch.
"""
import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from jkrcyl.model.problem import Problem
from jkrcyl.model.single_patch import solver
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_pull_off as po
from jkrcyl.numerics import cohesive_scales as cs
from reference import baney_hui as bh

THETA, GB = 1.0, 0.5


@pytest.mark.parametrize("lam, kind", [(0.01, "touch"), (0.1, "touch"), (1.0, "fold"), (5.0, "fold")])
def test_half_plane_pull_off_is_baney_hui(lam, kind):
    """Delta/R = 0, m = 1e-6: Pbar_c = p*/m^(4/3) is Baney-Hui's to 1e-4 (measured 1e-6 at lambda = 0.01, where
    the zone is 47 contact half-widths and the curvature shows, 1e-8 above); small lambda detaches at zero contact
    width (their minimum is at abar -> 0), large lambda at a fold."""
    m = 1e-6
    r = po.pull_off_load(m, cs.zone_strength(lam, m), THETA, GB)
    assert r.kind == kind
    assert abs(r.p / m ** (4 / 3) / float(bh.pull_off(lam)) - 1) < 1e-4
    assert r.zero_load.p == pytest.approx(0.0, abs=1e-9 * m ** (4 / 3))


def _jkr_pull_off(M):
    f = lambda eps: solver(Problem(M / THETA, THETA, GB)).states([math.tan(eps / 2)]).p[0]
    return minimize_scalar(f, bracket=(0.3, 0.5, 0.7), options=dict(xtol=1e-12)).fun


@pytest.mark.slow
def test_pull_off_tends_to_jkr():
    """M = 0.2, vartheta = 1 (a sub-critical JKR fold): the pull-off approaches JKR's as lambda^-4 -- the states
    differ by O(lambda^-2) at a fixed contact, but to that order the zone only shifts the contact size (p(eps) ~
    p_JKR(eps + O(lambda^-2))), which moves a minimum's value at second order -- lambda^4 times the difference
    is steady between lambda = 25 and 50 to 5 %, and the Richardson extrapolation in lambda^-4 from 25 and 50
    is JKR's pull-off to 1e-9 (relative; measured 5e-11)."""
    M = 0.2
    ref = _jkr_pull_off(M)
    X = {lam: po.pull_off_load(M, cs.zone_strength(lam, M), THETA, GB) for lam in (12.5, 25.0, 50.0)}
    assert all(r.kind == "fold" for r in X.values())
    d = {lam: (r.p - ref) * lam ** 4 for lam, r in X.items()}
    assert abs(d[50.0] / d[25.0] - 1) < 0.05 and abs(d[25.0] / d[12.5] - 1) < 0.05
    assert abs((16 * X[50.0].p - X[25.0].p) / 15 / ref - 1) < 1e-9


def test_pull_off_is_the_branch_minimum():
    """M = 0.2, lambda = 3: the pull-off load is the minimum of p over a dense scan of eps on the branch below the
    zero-load state (800 states, each the first root: no fold in eps here), and the zero-load state has p = 0."""
    M, lam = 0.2, 3.0
    s0 = cs.zone_strength(lam, M)
    r = po.pull_off_load(M, s0, THETA, GB)
    assert r.kind == "fold" and r.zero_load.p == pytest.approx(0.0, abs=1e-12)
    scan = np.linspace(0.05, r.zero_load.eps, 800)
    p = np.array([co.cohesive_state(e, M, s0, THETA, GB).p for e in scan])
    assert p.min() >= r.p - 1e-12
    assert p.min() - r.p < 1e-6                       # the grid's own error (spacing 1e-3, curvature ~1)


def test_no_adherence_when_the_range_reaches_round():
    """h0 > 2 Delta (lambda = 0.1, M = 0.2): no pull-off, and the reason says why."""
    M = 0.2
    s0 = cs.zone_strength(0.1, M)
    assert cs.zone_range(M, s0) > 2
    r = po.pull_off_load(M, s0, THETA, GB)
    assert r.p is None and "no adherence" in r.reason


def test_no_zero_load_state_is_reported():
    """M = 0.4, lambda = 3 (strong zone traction against the clearance): p < 0 on the whole branch, which turns
    back to eps -> 0 -- no zero-load state, reported as such."""
    r = po.pull_off_load(0.4, cs.zone_strength(3.0, 0.4), THETA, GB)
    assert r.p is None and "no zero-load" in r.reason
