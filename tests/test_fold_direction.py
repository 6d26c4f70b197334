"""Which way a fold is left, two ways: the walk that reached it (jkrcyl.analysis.path.PullPath.towards: the
state goes on past the fold the way the walk went, the stable side behind it) and the solver's local rule at the
fold alone -- JKR's fixed-arc derivative (dP/dk)|_a > 0 (closed forms, jkrcyl.model.stability), the cohesive
law's branch tangent (the approach falls under a further pull).  They must agree at every ordinary fold; the
cohesive tangent is allowed to differ only where its slopes all vanish at the fold (the cusp of
tests/test_gap_stop.py, where the walk's direction decides)."""
import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import jkrcyl
from cases import cohesive_contact
from jkrcyl.analysis import path
from jkrcyl.model.single_patch import solver
from jkrcyl.units import Units

modulus = st.one_of(st.just(math.inf), st.floats(1e6, 1e12))
poisson = st.one_of(st.just(0.0), st.floats(0.01, 0.49))


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(M=st.floats(0.05, 3.0), theta=st.one_of(st.just(math.inf), st.floats(0.6, 20.0)),
       gb=st.one_of(st.just(0.0), st.floats(1e-6, 1.0)))
def test_jkr_fold_is_left_the_way_the_walk_went(M, theta, gb):
    """JKR (alpha* = 0, closed forms): where the pull from first contact ends at a fold, the fixed-arc rule says
    the contact grows exactly where the walk was making it grow (towards > 0: the super-critical zip)."""
    pb = jkrcyl.equilibria.problem(M, theta, gb)
    start, event, s, towards = path.pull_path(pb, Units.normalised(pb), "load")
    if event != "fold" or towards == 0:
        return
    assert solver(pb).grows_under_pull(s.a, "load") == (towards > 0), (s.branch, s.a, towards)


@pytest.mark.slow
@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(E=modulus, nu=poisson, E_I=modulus, nu_I=poisson, h0=st.floats(0.05, 1.0), lam=st.floats(1.0, 8.0))
def test_cohesive_fold_is_left_the_way_the_walk_went(E, nu, E_I, nu_I, h0, lam):
    """The cohesive law over random pairs (rigid bodies included): the tangent rule at the fold alone agrees with
    the walk's direction, unless the approach's slope at the fold is below 1e-3 of its value 0.05 further along
    the branch (every slope vanishing together there)."""
    c = cohesive_contact(E, nu, E_I, nu_I, h0, lam)
    pb = c.problem
    start, event, s, towards = path.pull_path(pb, c.units, "load")
    if event != "fold" or towards == 0 or s.branch == "contactless":
        return
    sv = solver(pb)
    walk_says = sv.grows_under_pull(s.a, "load", towards)
    tangent_says = sv.grows_under_pull(s.a, "load")
    if walk_says != tangent_says:
        here = abs(sv.point(s.a).ddn_dt)
        beside = max(abs(sv.point(s.a + d).ddn_dt) for d in (-0.05, 0.05))
        assert here < 1e-3 * beside, (s.a, here, beside)
