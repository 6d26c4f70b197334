"""The (lambda, M) map's load-control pull-off (jkrcyl.analysis.cohesive_map: the stand-alone continuation of
jkrcyl.numerics.cohesive_pull_off with the map's longer steps, MAP_STEPS) against the model core's walker
(Contact.pull_off('load') on the traced table) over random material pairs, rigid bodies included, in the strip
where the range nearly reaches round (h0 between 0.9 and 2.1 Delta): round zones at first touch, S-shaped
branches, narrow or not.  Both give none or the same P* (1e-6) -- except where the walker finds the top closing
first (confined), which the map's route does not check -- and the map's 'from first contact' outcome is a
walker's none.  The map keeps its own route because the walker's pull-off costs 0.2-0.7 s a point cold (the
branch table is traced whole), ~40 times the map's budget of 60 s for 100 x 100 points on 2 cores
(benchmarks/bench_cohesive.py)."""
import math

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from cases import cohesive_contact
from jkrcyl.analysis import cohesive_map
from jkrcyl.numerics import cohesive_scales as scales

modulus = st.one_of(st.just(math.inf), st.floats(1e6, 1e12))
poisson = st.one_of(st.just(0.0), st.floats(0.01, 0.49))


@pytest.mark.slow
@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(E=modulus, nu=poisson, E_I=modulus, nu_I=poisson, h0=st.floats(0.9, 2.1), lam=st.floats(0.2, 3.0))
# the S-shaped branch of tests/test_cohesive_s_branch.py (identical bodies, nu 0.3, M = 0.45, lambda = 1)
@example(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3, h0=1.3747437098080626, lam=1.0)
# the narrow S of tests/test_cohesive_s_branch.py (M 0.70, lambda 1.47: h0 = m^2/s0, s0 = zone_strength(1.47, m))
@example(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3, h0=1.6912457176049538, lam=1.47)
# found by hypothesis: h0 just below Delta (the free range and the floating one both hold the centred pin), the
# map said 'floats' and the walker snapped in (two rigid bodies; a rigid pin in a soft cradle)
@example(E=math.inf, nu=0.01, E_I=math.inf, nu_I=0.0, h0=1.0, lam=1.822483711054704)
@example(E=math.inf, nu=0.0, E_I=1e6, nu_I=0.0, h0=1.0, lam=1.5)
@example(E=math.inf, nu=0.0, E_I=math.inf, nu_I=0.0, h0=1.0, lam=1.0)
# found by hypothesis: a shallow fold (P* -0.628642, a dip of 1e-4 below the branch beside it) lies in the cell
# before the first infeasible table point: the walker stopped at 'gap' there and the map's long steps jumped over
# it to the touch (-0.628751); both find it now (jkrcyl.analysis.path._fold_in_cell; the map confirms a touch
# with the default steps); the stand-alone route at default steps gives -0.6286423691237
@example(E=math.inf, nu=0.0, E_I=math.inf, nu_I=0.4375, h0=1.5, lam=2.0)
# found by hypothesis: the gap closes beside the contact with h(pi) = 2.7 Delta (an elastic pin, nu_I 0.45, in a
# rigid hole) at the table point past the fold; the walker stopped there ('gap') where the map finds the feasible
# fold, until the walker looked for a fold inside the cell first (jkrcyl.analysis.path._fold_in_cell): both now
# detach at P* -0.913959 (tests/test_gap_stop.py)
@example(E=math.inf, nu=0.45028557727142104, E_I=math.inf, nu_I=0.45028557727142104, h0=1.4690327046627536,
         lam=2.4731555735280266)
# a zone end leaving the top forward in eps up to the receding limit (tests/test_cohesive_top_forward.py): refused
# ("no zone end near the top") until jkrcyl.numerics.cohesive_round.near_top traced it; no pull-off either way
@example(E=math.inf, nu=0.0, E_I=math.inf, nu_I=0.0, h0=1.5, lam=1.625)
def test_map_point_is_the_walkers_pull_off(E, nu, E_I, nu_I, h0, lam):
    c = cohesive_contact(E, nu, E_I, nu_I, h0, lam)
    pb = c.problem
    # the map's lambda is the half-plane one (Delta/R -> 0): the one giving this contact's s0
    lam_map = lam * pb.edge.s0 / scales.zone_strength(lam, pb.m)
    P, kind = cohesive_map._point(lam_map, pb.M, pb.theta, pb.gb, pb.alpha_ratio)
    got = c.pull_off("load")
    # the map's route does not check the path's feasibility back from the zero-load contact: where the walker
    # finds the top closing first (confined) or the gap closing beside the contact (a second contact forming in
    # the zone), the map still gives the fold's or the touch's load
    stopped = got.reason.startswith(("confined", "no detachment on one patch"))
    assert (got.P is None) == math.isnan(P) or stopped, (got, cohesive_map.OUTCOMES[kind])
    if got.P is not None:
        assert got.P < 0 and abs(got.P / c.load_scale / P - 1) < 1e-6, (got.P / c.load_scale, P)
    if kind == 4:
        assert got.reason.startswith("no adherence force"), got.reason
