"""Property tests of the Maugis-Dugdale states over random material pairs, rigid bodies included (issue 19):
numbers reached two ways agree -- the load by the solver's moment functional and by Gauss quadrature of the
returned pressure (2.2); the energy release at the contact edge by the J-integral sigma0 h(c) = w (the opening
read off the returned gap field); the finite stress at the contact end (k = 0); and the pressure at the end
equal to the zone traction -s0."""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

import jkrcyl
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_scales as cs

XG, WG = np.polynomial.legendre.leggauss(160)
modulus = st.one_of(st.just(math.inf), st.floats(1e6, 1e12))
poisson = st.one_of(st.just(0.0), st.floats(0.01, 0.49))


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(E=modulus, nu=poisson, E_I=modulus, nu_I=poisson, M=st.floats(0.05, 1.0), lam=st.floats(1.5, 20.0),
       eps=st.floats(0.1, 1.0))
def test_two_ways(E, nu, E_I, nu_I, M, lam, eps):
    if math.isinf(E) and math.isinf(E_I):
        E_I = 1e9                                    # two rigid bodies: no elasticity at all
    mat = jkrcyl.Materials.from_young(E=E, nu=nu, E_I=E_I, nu_I=nu_I)
    theta, gb, ar = mat.theta, mat.inv_G_I / mat.beta, mat.alpha_ratio
    m = M if math.isinf(theta) else M * theta
    s0 = cs.zone_strength(lam, m)
    s = co.cohesive_state(eps, m, s0, theta, gb, ar, n=None if ar == 0 else 48)
    scale = max(1.0, abs(s.p))
    assert abs(s.k) < 1e-9 * max(1.0, m)
    # alpha* != 0: the gap off the contact carries the engine's fine-grid quadrature of the end enrichment
    # (~1e-12 absolute, not smooth in c), against ranges h0 down to ~1e-3 here
    assert abs(s.s0 * s.fields.gap(s.c)[0] / (m * m) - 1) < (1e-11 if ar == 0 else 1e-8) or s.zones == "all"
    t = np.pi / 2 * XG
    phi, jac = eps * np.sin(t), eps * np.cos(t) * np.pi / 2
    quad = np.sum(WG * jac * s.fields.pressure(phi) * np.cos(phi))
    c = min(s.c, math.pi)
    t = np.pi * (XG + 1) / 2
    phi, jac = eps + (c - eps) * (1 - np.cos(t)) / 2, (c - eps) * np.sin(t) * np.pi / 4
    quad += 2 * np.sum(WG * jac * s.fields.pressure(phi) * np.cos(phi))
    assert abs(quad - s.p) < 1e-8 * scale
    assert abs(s.fields.pressure(eps * (1 - 1e-9))[0] + s0) < 1e-3 * s0


PAIRS = dict(E=modulus, nu=poisson, E_I=modulus, nu_I=poisson, M=st.floats(0.03, 0.6), lam=st.floats(0.3, 10.0))


@settings(max_examples=3, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(**PAIRS)
# found by a fresh seed: the walker said 'no stable, feasible state at first contact' (a gap sample next to the
# contact edge, -1.5e-9 Delta, failed a fixed 1e-9 tolerance) where the continuation found the fold
@example(E=1e6, nu=0.0, E_I=math.inf, nu_I=0.3, M=0.164, lam=9.94)
def test_pull_off_by_the_walker_and_by_continuation(E, nu, E_I, nu_I, M, lam):
    _walker_and_continuation_agree(E, nu, E_I, nu_I, M, lam)


@pytest.mark.slow                       # the same property over more pairs (~1 s each)
@settings(max_examples=33, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(**PAIRS)
def test_pull_off_by_the_walker_and_by_continuation_more_pairs(E, nu, E_I, nu_I, M, lam):
    _walker_and_continuation_agree(E, nu, E_I, nu_I, M, lam)


def _walker_and_continuation_agree(E, nu, E_I, nu_I, M, lam):
    """The load-control pull-off two ways: Contact.pull_off (the walker on the traced table) and the stand-alone
    continuation of jkrcyl.numerics.cohesive_pull_off (no table, no walker; the map's route): both give none or
    the same P to 1e-6, and a pull-off is a pull (P < 0) -- the seam where a jump of a round zone was once read
    as a fold (tests/test_cohesive_s_branch.py)."""
    from jkrcyl.numerics import cohesive_pull_off as cpo
    if math.isinf(E) and math.isinf(E_I):
        E_I = 1e9
    mat = jkrcyl.Materials.from_young(E=E, nu=nu, E_I=E_I, nu_I=nu_I)
    probe = jkrcyl.Contact(1e-2, 1e-5, 1.0, mat)
    c = jkrcyl.Contact.with_lambda(1e-2, 1e-5, (M / probe.M) ** 2, mat, lam)
    pb = c.problem
    ref = cpo.pull_off_load(pb.m, pb.edge.s0, pb.theta, pb.gb, pb.alpha_ratio)
    got = c.pull_off("load")
    assert (got.P is None) == (ref.p is None), (got, ref.reason)
    if got.P is not None:
        assert got.P < 0
        assert abs(got.P / (ref.p * c.load_scale / pb.scale) - 1) < 1e-6, (got.P, ref.p)
