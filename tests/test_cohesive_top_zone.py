"""The top bridge of the Maugis-Dugdale law (jkrcyl.numerics.cohesive_top_zone): one contact with its zone at the
bottom and a second zone at the top, between the single patch (h(pi) = h0) and the top contact's onset (h(pi) = 0).

Case: M 0.1, vartheta 10, gb 1/2.8 (m = 1) -- the pin whose top closes under grip (tests/test_cohesive_top_landing.py)
-- at lambda 50 (s0 = 12.5, h0 = 0.08 Delta).  Its single patch meets h(pi) = h0 twice; the grip path from 0 to
-1.9 Delta comes down the branch's stable part and meets the second (eps 0.728).  Checked against what the trace
does not use:

* the states solved alone at their contact by the other route, jkrcyl.numerics.cohesive_zones.top_zone_states (a
  scan and Brent in c_top at a fixed eps; the trace solves eps at a fixed c_top);
* the energy identity dE = p d(delta/Delta) along the family (Chebyshev in c_top), with the Dugdale interface
  energy of both zones (the top zone's by adaptive quadrature: without it the identity fails);
* the single-patch state where h(pi) = h0 (jkrcyl.numerics.cohesive.cohesive_state: no top zone), the limit
  c_top -> 0, and the single patch's stability rule (jkrcyl.numerics.cohesive_branch.point) at the junction;
* the half-plane Dugdale strip at the top's closing: h(pi) - h(pi - c_top) = -4 s0 c_top log 2 + O(c_top^2) (a
  uniform traction -s0 on |x| < c_top, kernel 2 log|x|: int_-c^c 2 log|x| - int_0^2c 2 log x = -4 c log 2), so
  c_top -> h0/(4 s0 log 2) where h(pi) = 0;
* Maxwell: the held-zone-end matrix G (2 s0 G the energy's Hessian) is symmetric.
"""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings, strategies as hst
from numpy.polynomial import chebyshev as C
from scipy.integrate import quad

from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_branch as cb
from jkrcyl.numerics import cohesive_top_zone as tz
from jkrcyl.numerics import cohesive_zones as cz
from jkrcyl.numerics.cohesive_scales import zone_strength

M, THETA, GB = 0.1, 10.0, 1 / 2.8
m = M * THETA


def law_at(lam):
    return tz.law_of(m, zone_strength(lam, m), THETA, GB)


@pytest.fixture(scope="module")
def law():
    return law_at(50.0)


@pytest.fixture(scope="module")
def junctions(law):
    return tz.junctions(law)


@pytest.fixture(scope="module")
def family(law, junctions):
    """The grip path's family (the second junction, side +1), coarse (c_top x 3 per point)."""
    return tz.trace(law, junctions[1][0], ratio=3.0)


def test_two_junctions_where_the_gap_at_the_top_reaches_h0(law, junctions):
    assert [side for _, side in junctions] == [-1, 1]
    for st, _ in junctions:
        assert st.h_pi_over_Delta == pytest.approx(law.h0, abs=1e-10)
        assert st.fields.gap(math.pi - 0.05)[0] > st.h_pi_over_Delta        # a local minimum at the top
        assert co.gap_check(st).feasible                                     # h(pi) = h0: the last single patch


def test_the_family_ends_where_the_top_closes_all_states_feasible(law, family):
    assert family.end == "top closes"
    assert all(co.gap_check(st).feasible for st in family.states + [family.onset])
    assert family.onset.h_pi_over_Delta == pytest.approx(0.0, abs=1e-10)
    assert all(st.zones == "bottom+top" for st in family.states)
    # the half-plane strip: c_top = h0/(4 s0 log 2) (1 + O(c_top)); measured 9.5e-5 relative
    est = law.h0 / (4 * law.s0 * math.log(2))
    assert abs(family.onset.c_top / est - 1) < family.onset.c_top


def test_states_are_those_solved_alone_at_their_contact(law, family):
    picked = [st for st in family.states if 1e-5 < st.c_top < 2e-3]
    assert len(picked) >= 3
    for st in picked:
        alone = cz.top_zone_states(st.eps, law.m, law.s0, THETA, GB, n=law.contact(st.eps)[0])
        got = min(alone, key=lambda s: abs(s.c_top - st.c_top))
        assert got.c_top == pytest.approx(st.c_top, rel=1e-10)
        assert got.c == pytest.approx(st.c, abs=1e-10)
        assert got.p == pytest.approx(st.p, abs=1e-10)
        assert got.delta_over_Delta == pytest.approx(st.delta_over_Delta, abs=1e-10)


def top_interface(st):
    """The top zone's Dugdale interface energy (s0/2) int h - m^2 (its length), adaptive quadrature."""
    H = 2 * quad(lambda x: st.fields.gap(x)[0], math.pi - st.c_top, math.pi, epsabs=1e-14, epsrel=1e-13)[0]
    return 0.5 * st.s0 * H - st.m ** 2 * 2 * st.c_top


def test_energy_changes_by_p_d_delta_with_both_zones(law, family):
    """E(b) - E(a) = int p d(delta/Delta) over c_top in [a, b] (16 Chebyshev points: p, delta analytic there;
    measured 2e-15 over a change of 0.059), and fails without the top zone's interface energy (by 1.3e-4)."""
    i = next(k for k, st in enumerate(family.states) if st.c_top > 2e-5)
    a, b = family.states[i], family.states[i + 1]
    n = 16
    x = np.cos(np.pi * np.arange(n) / (n - 1))[::-1]
    sts, prev = [], a
    for ct in a.c_top + (b.c_top - a.c_top) * (x + 1) / 2:
        prev = tz.state_at(law, ct, prev.eps, prev.c - prev.eps)
        sts.append(prev)
    p = np.array([s.p for s in sts])
    d = np.array([s.delta_over_Delta for s in sts])
    work = C.chebint(C.chebmul(C.chebfit(x, p, n - 1), C.chebder(C.chebfit(x, d, n - 1))))
    W = C.chebval(1, work) - C.chebval(-1, work)
    E = [tz.potential(s) for s in (sts[0], sts[-1])]
    assert abs(E[1] - E[0] - W) < 1e-8
    bottom_only = [e - top_interface(s) for e, s in zip(E, (sts[0], sts[-1]))]
    assert abs(bottom_only[1] - bottom_only[0] - W) > 1e-5


@pytest.mark.parametrize("which", [0, 1])
def test_continuous_with_the_single_patch_at_the_junction(law, junctions, which):
    """c_top -> 0: p, delta the single patch's where h(pi) = h0, the difference ~ c_top log(1/c_top) (measured
    1.2e-7, 1.4e-9, 1.6e-11 at c_top 1e-10, 1e-12, 1e-14)."""
    j = junctions[which][0]
    diffs = []
    for ct in (1e-10, 1e-12):
        st = tz.state_at(law, ct, j.eps, j.c - j.eps)
        diffs.append(max(abs(st.p - j.p), abs(st.delta_over_Delta - j.delta_over_Delta)))
        assert st.eps == pytest.approx(j.eps, rel=1e-6)
    assert diffs[0] < 2e-7 and diffs[1] < 1e-8
    assert diffs[0] / 200 < diffs[1] < diffs[0] / 50        # c_top log(1/c_top): 1/84 over the two decades


@pytest.mark.parametrize("which", [0, 1])
def test_bridge_is_a_saddle_and_the_junction_keeps_the_single_patchs_flag(law, junctions, which):
    """G (held zone ends) symmetric (Maxwell: measured <= 8e-7 of G_12 at c_top 1e-4, the differences' rounding);
    its bottom entry next to the junction (c_top 1e-4: G_11 within 15 % of c_top 1e-6's) has the sign
    of the single patch's own stability rule (cohesive_branch.point: the first junction unstable under both
    controls, the second stable under grip only); the top entry < 0: the top zone grows at a held quantity."""
    j = junctions[which][0]
    st = tz.state_at(law, 1e-4, j.eps, j.c - j.eps)
    pt = cb.point(law, j.eps, j.c, (1.0, 1.0))
    rule = {"grip": pt.ddn_dt * pt.D_dn < 0, "load": pt.dp_dt * pt.D_p < 0}
    assert rule == ({"grip": False, "load": False} if which == 0 else {"grip": True, "load": False})
    for control in ("grip", "load"):
        G = tz.zone_matrix(law, st, control)
        assert abs(G[0, 1] - G[1, 0]) < 1e-5 * abs(G[0, 1])
        assert (G[0, 0] > 0) == rule[control]
        assert G[1, 1] < 0 and not tz.stable(law, st, control, G)


def test_held_state_refuses_a_bad_control(law, junctions):
    j, _ = junctions[1]
    with pytest.raises(ValueError, match="^control"):
        tz.held_state(law, j.c, 1e-4, "speed", 0.0, j.eps)


@pytest.mark.slow                       # ~10 s: four traces
def test_the_family_shrinks_as_lambda_grows():
    """The grip path's family at lambda 20-200: where the top closes, c_top is the strip's h0/(4 s0 log 2) to
    O(c_top) and the single patch's gap at that contact is the strip's h0 (1 + log(1/(2 c_top))/log 2) (the
    small zone's own pull ~ 4 s0 c_top log(1/(2 c_top)) at its end), to 10 % (measured 2-5 % from lambda 20);
    the approach the family spans shrinks (measured 0.70, 0.54, 0.38, 0.24 Delta at 20, 50, 100, 200)."""
    spans = []
    for lam in (20.0, 50.0, 100.0, 200.0):
        law = law_at(lam)
        j = tz.junctions(law)[-1][0]
        br = tz.trace(law, j, ratio=2.0)
        o = br.onset
        est = law.h0 / (4 * law.s0 * math.log(2))
        assert br.end == "top closes" and abs(o.c_top / est - 1) < o.c_top
        strip = law.h0 * (1 + math.log(1 / (2 * est)) / math.log(2))
        assert law.state(o.eps).h_pi_over_Delta == pytest.approx(strip, rel=0.1)
        spans.append(o.delta_over_Delta - j.delta_over_Delta)
    assert all(s > 0 for s in spans) and spans[1] > spans[2] > spans[3]


def test_where_the_top_closes_the_laws_two_patch_states_begin(law, junctions):
    """The first junction's family (the top closes at eps 0.0048): the two-arc states of
    jkrcyl.numerics.cohesive_two.solve (two contacts, k = 0 at both edges, zones at both: another solver, cold
    from the onset's eps) tend to the onset as the top arc eps_top -> 0, as eps_top^2 (measured in delta/Delta:
    2.3e-3, 2.8e-4, 3.8e-5 at eps_top 1e-4, 3e-5, 1e-5): the top bridge is the two patches' continuation."""
    from jkrcyl.numerics import cohesive_two as two
    o = tz.trace(law, junctions[0][0], ratio=3.0).onset
    diffs = []
    for eps_top in (1e-4, 1e-5):
        s = two.solve(eps_top, law.m, law.s0, THETA, GB, 0.0, o.eps)
        diffs.append(max(abs(s.delta_over_Delta - o.delta_over_Delta), abs(s.p - o.p), abs(s.c_top - o.c_top),
                         abs(s.eps - o.eps)))
    assert diffs[1] < 1e-4 and diffs[1] < diffs[0] / 30


def contactless_touch_with_top_zone(law, c_lo, c_hi):
    """The state without contact, zones at the bottom and top (cohesive_zones.contactless_states: closed form in
    delta, the top zone end by a scan and Brent), that touches the bottom, h(0) = 0: Brent in its bottom zone c."""
    from jkrcyl.numerics import roots

    def top(c):
        return min((s for s in cz.contactless_states(c, law.m, law.s0, THETA, GB) if 0 < s.c_top < 0.1),
                   key=lambda s: s.c_top)
    return top(roots.root(lambda c: top(c).fields.gap(0.0)[0], c_lo, c_hi))


def test_at_lambda_20_the_family_reaches_the_touch_without_the_top_closing():
    """lambda 20, the first junction (eps 0.0155): the top zone grows while the contact shrinks to nothing (h(pi)
    still 0.16 Delta): the family ends at the touch, on the state without contact held by zones at the bottom
    and top that touches the bottom -- approached as eps^2 (measured: delta within 1.7e-5 at eps 3.1e-5, rate 1.84)."""
    law = law_at(20.0)
    j = tz.junctions(law)[0][0]
    br = tz.trace(law, j, ratio=2.0)
    assert br.end == "touch" and br.onset is None and br.states[-1].h_pi_over_Delta > 0.15
    ref = contactless_touch_with_top_zone(law, 0.9 * br.states[-1].c, 1.1 * br.states[-1].c)
    diff = [max(abs(s.p - ref.p), abs(s.delta_over_Delta - ref.delta_over_Delta), abs(s.c_top - ref.c_top),
                abs(s.c - ref.c)) for s in br.states[-2:]]
    assert diff[1] < 1e-4
    rate = math.log(diff[0] / diff[1]) / math.log(br.states[-2].eps / br.states[-1].eps)
    assert 1.6 < rate < 2.4, rate


# --- two routes to the law's top onset ---------------------------------------------------------------------------
ONSET_LAWS = dict(m=hst.floats(0.5, 2.0), theta=hst.floats(3.0, 20.0), gb=hst.just(0.0) | hst.floats(0.01, 0.6),
                  lam=hst.floats(20.0, 200.0))


@settings(max_examples=2, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(**ONSET_LAWS)
@example(m=1.0, theta=10.0, gb=1 / 2.8, lam=50.0)          # the grip cycle's junction (tests/test_cohesive_top_landing)
@example(m=1.5, theta=15.0, gb=0.0, lam=20.0)              # past a turn: the first zone-end root is another branch's
def test_the_walkers_top_onsets_are_the_junctions(m, theta, gb, lam):
    _onsets_are_the_junctions(m, theta, gb, lam)


@pytest.mark.slow                       # the same property over more laws (~1 s each)
@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(**ONSET_LAWS)
def test_the_walkers_top_onsets_are_the_junctions_more_laws(m, theta, gb, lam):
    _onsets_are_the_junctions(m, theta, gb, lam)


def _onsets_are_the_junctions(m, theta, gb, lam):
    """The model core's onsets where the top adheres (jkrcyl.analysis.landing.top_onsets: the roots of h(pi) = h0 on
    the law's branch table, refined by the model's root finder -- what landing.top_onset and the confined
    classification use) against :func:`cohesive_top_zone.junctions` (the numerics' trace, Brent on the state at a
    contact): every junction is an onset, eps and delta/Delta to 1e-8, P* to 1e-8.  m = M vartheta of order 1 (the
    top closes: JKR's confined regime)."""
    M = m / theta
    from jkrcyl.analysis import landing
    from jkrcyl.laws.dugdale import edge_of_strength
    from jkrcyl.model.problem import Problem
    import jkrcyl
    pb = Problem(M, theta, gb, 0.0, edge_of_strength(jkrcyl.equilibria.zone_strength(lam, M, theta)))
    law = tz.law_of(pb.m, pb.edge.s0, theta, gb)
    onsets = landing.top_onsets(pb)
    for j, _ in tz.junctions(law):
        eps, P, d, _ = min(onsets, key=lambda o: abs(o[0] - j.eps))
        assert abs(eps - j.eps) < 1e-8 * j.eps and abs(d - j.delta_over_Delta) < 1e-8
        assert abs(P - j.p / pb.scale) < 1e-8 * max(1.0, abs(P))
