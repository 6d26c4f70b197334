"""Two routes to one state over random material pairs (rigid bodies included): where the Maugis-Dugdale law has a
pin held by its zone alone that touches the hole (the zone-only branch's end, a = 1), the contact branch starts at
that touch (its first state, a = 2: the trace from eps = 1e-6 c_touch, cohesive_zones.JUNCTION), so a walk going on
from one branch onto the other keeps its held value.  Each end against its state solved alone: the touch by Brent
on h(0) = 0 of the closed form (cohesive_zones.contactless_touch), the first contact by cohesive_state at its eps;
delta/Delta and p agree to 1e-8 (tests/test_energy_levels.py: 9e-12 / 2e-12 at lambda 20 on one pair)."""
import math

import pytest
from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st

from cases import cohesive_contact
from jkrcyl.analysis import forward
from jkrcyl.model.single_patch import solver
from jkrcyl.numerics import cohesive_zones as cz

modulus = st.one_of(st.just(math.inf), st.floats(1e6, 1e12))
poisson = st.one_of(st.just(0.0), st.floats(0.01, 0.49))


@settings(max_examples=3, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(E=modulus, nu=poisson, E_I=modulus, nu_I=poisson, h0=st.floats(0.05, 0.9), lam=st.floats(2.0, 50.0))
@example(E=1e8, nu=0.0, E_I=math.inf, nu_I=0.0, h0=0.1, lam=20.0)          # a rigid pin
@example(E=math.inf, nu=0.3, E_I=2.6e9, nu_I=0.3, h0=0.5, lam=50.0)        # a rigid cradle
def test_the_contact_branch_starts_at_the_zone_only_touch(E, nu, E_I, nu_I, h0, lam):
    c = cohesive_contact(E, nu, E_I, nu_I, h0, lam)
    pb, un = c.problem, c.units
    sv = solver(pb)
    assume(sv._contactless is not None and sv._contactless[0] == 0.0)     # a zone-only pin touching the bottom
    law = sv.law
    touch = cz.contactless_touch(law.m, law.s0, law.theta, law.gb, law.ar)
    zone_only = forward.single_patch_states(pb, un, "contactless", [1.0], "grip")[0]
    first = forward.single_patch_states(pb, un, "sub-critical", [2.0], "grip")[0]
    alone = law.state(first.eps)
    p = lambda s: s.P_star * pb.scale                                     # kernel-scale load
    for got, ref in ((zone_only, touch), (first, alone), (first, touch)):
        assert got.delta_over_Delta == pytest.approx(ref.delta_over_Delta, abs=1e-8)
        assert p(got) == pytest.approx(ref.p, abs=1e-8 * max(1.0, abs(ref.p)))
