"""A cohesive branch whose zone reaches round at small contacts and whose first zone-end root stops short of the
top by a jump (found by the lead in session 19: the walker read the jump as a fold and returned a pull-off of
+0.00034 N/m, a positive 'detachment'; the (lambda, M) map called the point 'no adherence force').

Identical bodies (nu 0.3, vartheta = 1), M = 0.45, lambda = 1.  Independent evidence that the branch is S-shaped
there, from single states of jkrcyl.numerics.cohesive (no table, no trace): just below the jump the round-zone
state is valid with h(pi) well below h0 (so the round-zone family goes on), and a little above it two zone-end
roots coexist at one contact (the first, tending to JKR, and one ending near the top): the states turn back.
The analyses say 'not modelled' rather than a number.  A second kind of jump, a top bridge, is told apart."""
import math

import numpy as np

import jkrcyl
from jkrcyl.analysis import cohesive_map
from jkrcyl.model.problem import Problem
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_branch as cb
from jkrcyl.numerics import cohesive_scales as scales

PAIR = jkrcyl.Materials(G=1.0, kappa=1.8, G_I=1.0, kappa_I=1.8)


def s_shaped():
    probe = jkrcyl.Contact(R=1.0, Delta=0.01, w=1.0, materials=PAIR)
    return jkrcyl.Contact.with_lambda(R=1.0, Delta=0.01, w=(0.45 / probe.M) ** 2, materials=PAIR, lambda_=1.0)


def test_the_jump_is_between_two_families():
    pb = s_shaped().problem
    law = (pb.m, pb.edge.s0, pb.theta, pb.gb, pb.alpha_ratio)
    h0 = cb.Law(*law).h0
    eps, c, kind = cb.top_opens(cb.Law(*law))
    assert kind == "S-shaped branch"
    below = co.cohesive_state(eps * (1 - 1e-4), *law)
    assert below.zones == "all" and below.h_pi_over_Delta < 0.9 * h0        # far from opening at the top
    above = co.cohesive_state(eps * (1 + 1e-4), *law)
    assert above.c < math.pi - 0.3 and abs(above.c - c) < 1e-3              # the jump
    e = 1.25 * eps
    first, top = co.cohesive_state(e, *law), co.cohesive_state(e, *law, near=math.pi - e - 1e-3)
    assert top is not None and top.c > first.c + 0.05                        # two zone ends at one contact


def test_a_top_bridge_is_told_apart():
    """lambda = 0.05, M = 0.093 (gb = 1/2.8): the round zone's gap reaches h0 (h(pi) within 1e-4 of it) and the
    zone end jumps to pi - 0.021, staying there as the opening is bracketed closer (not a square root): the gap
    exceeds h0 beside the top first."""
    pb = Problem(0.09306048591020996, 1.0, 1 / 2.8)
    law = (pb.m, scales.zone_strength(0.05, pb.m), 1.0, 1 / 2.8, 0.0)
    eps, c, kind = cb.top_opens(cb.Law(*law))
    assert kind == "top bridge" and 0.01 < math.pi - c < 0.05
    assert abs(co.cohesive_state(eps * (1 - 1e-9), *law).h_pi_over_Delta / cb.Law(*law).h0 - 1) < 1e-4
    for d in (1e-6, 1e-9):
        assert math.pi - co.cohesive_state(eps * (1 + d), *law).c > 0.01


def test_analyses_say_not_modelled_instead_of_a_number():
    c = s_shaped()
    for control in ("load", "grip", "grip-work"):
        po = c.pull_off(control)
        assert po.P is None and po.reason.startswith("not modelled"), (control, po)
    cy = c.cycle(P_max=c.load_scale, P_min=-c.load_scale, n=20)
    assert cy.jumps == [] and cy.note.startswith("not modelled")
    pb = c.problem
    P, kind = cohesive_map._point(1.0, pb.M, pb.theta, pb.gb, pb.alpha_ratio)
    assert math.isnan(P) and cohesive_map.OUTCOMES[kind].startswith("not modelled")


def test_no_positive_pull_off_on_a_coarse_map():
    """Every load-control pull-off of a coarse (lambda, M) map is a pull (P* < 0) or none."""
    pm = cohesive_map.pull_off_map(np.geomspace(0.05, 2.0, 5), np.geomspace(0.05, 0.6, 5), workers=1)
    assert np.all(~np.isfinite(pm.P_star) | (pm.P_star < 0))
    assert np.any(pm.outcome == 4)
