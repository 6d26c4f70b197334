"""The walker's landing on two patches under the Maugis-Dugdale law: the top of the hole adheres where its gap
reaches the range, h(pi) = h0 (the single patch ends there, at its junction with the top bridge, a saddle:
jkrcyl.numerics.cohesive_top_zone), and a cycle jumps there onto the law's traced two-patch branch
(jkrcyl.analysis.cohesive_two_patch) and walks along it, as JKR's lands on and walks JKR's from h(pi) = 0.

Checked against what the landing does not use:

* JKR's closed-form single patch: to first order in h0 the law's onset is JKR's (h(pi) = 0, its own root on the
  closed form) moved by h0/(dh(pi)/d delta) at fixed P-delta slope: measured at lambda = 50, 100, 200 (h0 = 0.08,
  0.04, 0.02 Delta) the remainder is -0.30 h0^2 in delta/Delta (second order), P* to 2e-5;
* the junction found on its own (jkrcyl.numerics.cohesive_top_zone.junctions: the law's trace, Brent on the
  single-patch state) -- the walker's is its table refined by the model core's root;
* the energy the jump dissipates: the work of the held quantity less the change of the states' own total
  potential, >= 0;
* the landing state solved alone (CohesiveTwoPatch.state: cold from JKR's state at its bottom arc, no branch).
"""
import math

import pytest

import jkrcyl
from jkrcyl.analysis import branches, cycle, forward, landing, tracing
from jkrcyl.analysis.two_patch_family import family
from jkrcyl.laws.dugdale import edge_of_strength
from jkrcyl.model.problem import Problem
from jkrcyl.model.single_patch import solver
from jkrcyl.numerics import cohesive_top_zone as top_zone
from jkrcyl.units import Units

EQ = jkrcyl.equilibria
M, THETA, GB = 0.1, 10.0, 1 / 2.8        # under grip the top closes before the sub-critical pull-off (JKR)


def grip_cycle(pb):
    un = Units.normalised(pb, K_edge=1.0)            # P = P*, delta = delta/Delta
    return cycle.cycle(pb, un, "grip", 0.0, -1.9, 300, lambda P, d: d)


def first_order_onset(jkr, h0, eps):
    """(delta/Delta, P*) of JKR's onset nearest eps (h(pi) = 0 on its closed form) moved along JKR's single patch
    until h(pi) = h0 to first order: delta + h0/(dh/d delta), P* + (dP*/d delta) h0/(dh/d delta), slopes by central
    differences in a (1e-6)."""
    e = min(tracing.onset_angles(jkr), key=lambda x: abs(x - eps))
    a = math.tan(e / 2)
    c = branches.values_at(jkr, solver(jkr).regime_of(a), [a * (1 - 1e-6), a, a * (1 + 1e-6)])
    dd = c.delta_over_Delta[2] - c.delta_over_Delta[0]
    step = h0 / ((c.h_pi_over_Delta[2] - c.h_pi_over_Delta[0]) / dd)
    return c.delta_over_Delta[1] + step, c.P_star[1] + (c.P_star[2] - c.P_star[0]) / dd * step


@pytest.mark.parametrize("lam", [50.0, 100.0, 200.0])
def test_the_laws_top_onset_is_jkrs_moved_by_h0(lam):
    """The junction h(pi) = h0 (jkrcyl.numerics.cohesive_top_zone.junctions) against JKR's onset moved by
    h0/(dh/d delta): second order in h0 (measured -0.30 h0^2 at each lambda; asked 1 h0^2), as the range shrinks."""
    jkr = Problem(M, THETA, GB)
    pb = Problem(M, THETA, GB, 0.0, edge_of_strength(jkrcyl.equilibria.zone_strength(lam, M, THETA)))
    h0 = pb.edge.range_over_Delta(pb.m)
    law = top_zone.law_of(pb.m, pb.edge.s0, THETA, GB)
    for j, _ in top_zone.junctions(law):
        d_on, P_on = first_order_onset(jkr, h0, j.eps)
        assert abs(j.delta_over_Delta - d_on) < h0 ** 2 and abs(j.p / pb.scale - P_on) < h0 ** 2


def dissipated(pb, j):
    """Work of the held approach less the change of total potential, kernel scale (p = vartheta P*)."""
    work = pb.scale * 0.5 * (j.before.P + j.after.P) * (j.after.delta - j.before.delta)
    return work - (j.after.energy - j.before.energy)


@pytest.mark.slow                       # ~2 min: the law's two-patch branches traced and searched at lambda 50
def test_top_closing_lands_on_the_laws_two_patch_branch_as_jkr():
    jkr = Problem(M, THETA, GB)
    lam = 50.0
    pb = Problem(M, THETA, GB, 0.0, edge_of_strength(jkrcyl.equilibria.zone_strength(lam, M, THETA)))
    ref, got = grip_cycle(jkr), grip_cycle(pb)
    kinds = [j.kind for j in ref.jumps]
    assert kinds == ["snap-in", "top-contact", "pull-off"] and [j.kind for j in got.jumps] == kinds
    top, top_ref = got.jumps[1], ref.jumps[1]
    assert top.before.branch == "sub-critical" and top.after.branch == top_ref.after.branch == "two-patch"
    h0 = pb.edge.range_over_Delta(pb.m)
    assert top.before.h_pi == pytest.approx(h0, abs=1e-9)           # the top adheres at h0 (normalised: Delta = 1)
    law = top_zone.law_of(pb.m, pb.edge.s0, THETA, GB)
    alone = min((j for j, _ in top_zone.junctions(law)), key=lambda j: abs(j.eps - top.before.eps))
    assert top.before.eps == pytest.approx(alone.eps, rel=1e-8)
    assert top.before.delta_over_Delta == pytest.approx(alone.delta_over_Delta, abs=1e-8)
    assert top.before.P_star == pytest.approx(alone.p / pb.scale, abs=1e-8)
    d_on, P_on = first_order_onset(jkr, h0, top.before.eps)                          # JKR's moved by h0
    assert abs(top.before.delta_over_Delta - d_on) < h0 ** 2 and abs(top.before.P_star - P_on) < h0 ** 2
    assert abs(top.after.P_star - top_ref.after.P_star) < h0            # measured 2.3e-3: O(h0), not C/lambda^2
    assert top.after.delta == pytest.approx(top.before.delta, abs=1e-9)          # the held approach
    assert top.after.stable_grip and top.after.feasible
    assert dissipated(pb, top) > 0 and dissipated(jkr, top_ref) > 0
    # the walk along the law's branch to its fold under grip (JKR's refined: delta/Delta -0.0700952), where the top
    # arc lets go onto the bottom patch as JKR's, the jump dissipating as JKR's (measured: fold 8e-7 in
    # delta/Delta, dissipation 0.3156 vs 0.3161, 1.7e-3)
    C = 5.0
    off, off_ref = got.jumps[2], ref.jumps[2]
    assert (off.before.branch, off.after.branch) == (off_ref.before.branch, off_ref.after.branch) == \
        ("two-patch", "sub-critical")
    assert abs(off.before.delta_over_Delta - off_ref.before.delta_over_Delta) < C / lam ** 2
    assert dissipated(pb, off) > 0 and dissipated(jkr, off_ref) > 0
    assert abs(dissipated(pb, off) / dissipated(jkr, off_ref) - 1) < 0.01
    alone = family(pb).state(eps=top.after.eps, guess=top.after.eps_top)
    assert alone.eps_top == pytest.approx(top.after.eps_top, rel=1e-9)
    assert alone.P_star == pytest.approx(top.after.P_star, abs=1e-9)     # P* ~ 0.006 here: 1e-9 of the load scale
    assert alone.delta_over_Delta == pytest.approx(top.after.delta_over_Delta, abs=1e-9)


def test_outside_the_branch_range_the_landing_is_refused_naming_sigma0():
    """At lambda = 2000 the law's two-patch branches are refused (zones too thin for the two-arc solver's
    rounding: cohesive_two_layer.check_lambda; at low lambda the law's own branch is traced,
    tests/test_cohesive_two_own.py): the refusal names sigma0 (what a cycle's note appends), and a walk whose top
    closes lands nowhere."""
    pb = Problem(M, THETA, GB, 0.0, edge_of_strength(jkrcyl.equilibria.zone_strength(2000.0, M, THETA)))
    assert landing.two_patch_refusal(pb).startswith("sigma0 is too large for the two-arc")
    assert landing.two_patch_refusal(Problem(M, THETA, GB)) == ""
    un = Units.normalised(pb, K_edge=1.0)
    s = forward.single_patch_states(pb, un, "sub-critical", [8.0], "grip")[0]
    assert landing.land(pb, un, s, "gap", "grip", s.delta, False) == (None, "top-contact")


# --- the confined classification under the law ------------------------------------------------------------------
@pytest.mark.slow                       # ~1-3 min: the law's two-patch branches at lambda 50 (ConfinedEvents.branches)
@pytest.mark.parametrize("M", [0.2, 0.5, 0.8])
def test_confined_classes_equal_jkrs_at_lambda_50(M):
    """Identical bodies (vartheta = 1): JKR's classes detachment (M 0.2), zip-full (0.5), bonded (0.8), none at a
    boundary; the law's at lambda = 50 the same, its fold load JKR's to C/lambda^2 (measured: 4e-9 and 3e-8, the
    lambda^-4 of the single patch; asked C = 1)."""
    lam = 50.0
    ref = EQ.confined_events(M, 1.0, gb=GB)
    got = EQ.confined_events(M, 1.0, gb=GB, s0=EQ.zone_strength(lam, M, 1.0))
    assert got.regime == ref.regime
    if ref.regime == "bonded":
        assert got.start[0] == math.inf
    else:
        assert abs(got.P_fold - ref.P_fold) < 1.0 / lam ** 2
    assert got.branches and all(b.G_bot.size for b in got.branches)


def test_confined_events_refused_naming_sigma0_where_the_branches_are_not_followed():
    with pytest.raises(ValueError, match="^sigma0"):                 # beyond lambda 1000 (low lambda: the own branch)
        EQ.confined_events(M, THETA, gb=GB, s0=EQ.zone_strength(2000.0, M, THETA))
    with pytest.raises(ValueError, match="^alpha_ratio"):
        EQ.confined_events(0.2, 1.0, gb=GB, alpha_ratio=0.1, s0=EQ.zone_strength(20.0, 0.2, 1.0))
