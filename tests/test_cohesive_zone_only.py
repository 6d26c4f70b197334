"""The Maugis-Dugdale pin without contact under grip at small lambda (vartheta 10, gb 0): the pin held by its
bottom zone alone, its hysteresis loops, and the pin floating in ranges that overlap (h0 > Delta).

Before: grip cycles 0 .. -0.3 .. -1.7 Delta ended 'no stable, feasible state at first contact' (lambda 0.5, M 0.03:
h0 1.61 Delta) -- the zone-only branch was taken between the approach's pole c = pi/2 and the touch, where the pin
overlaps the bottom (every state infeasible); the states are c_touch < c < pi, joining the pin floating all round
-- or 'no stable state to jump to after the snap-in' (lambda 1.3, M 0.03: h0 0.62) -- the zone-only pin on the top
was driven towards the top by the bottom's rule (it jumped into contact where it should let go).

References: the zone-only pin in closed form (jkrcyl.numerics.cohesive_zones.contactless_state: the approach from
h(c) = h0, p = -2 s0 sin c), its fold by Brent, the loop work int P d(delta) by quadrature over those states (no
energies), the floating range's closed form."""
import math

import numpy as np
import pytest

from jkrcyl.analysis import branches
from jkrcyl.analysis import cycle
from jkrcyl.analysis import forward as fw
from jkrcyl.analysis import landing
from jkrcyl.laws.dugdale import edge_of_strength
from jkrcyl.model.problem import Problem
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_branch as cb
from jkrcyl.numerics import cohesive_scales as sc
from jkrcyl.numerics import cohesive_zones as cz
from jkrcyl.numerics import roots
from jkrcyl.units import Units

THETA, GB = 10.0, 0.0


def _problem(lam, M):
    s0 = sc.zone_strength(lam, Problem(M, THETA, GB).m)
    pb = Problem(M, THETA, GB, 0.0, edge_of_strength(s0))
    return pb, Units.normalised(pb)


def _closed(pb, c):
    return cz.contactless_state(c, pb.m, pb.edge.s0, THETA, GB)


def test_a_touch_beyond_pi_half_ends_states_that_join_the_floating_pin():
    """lambda 0.5, M 0.03 (h0 1.61 Delta): the zone-only pin's touch lies beyond pi/2; its table states are all
    feasible, between the floating range's top (closed form, as c -> pi) and the touch (h(0) = 0); the floating
    pin's potential is constant over its range (dE = p d(delta), p = 0) and the zone-only pin's tends to it as
    c -> pi (1e-12)."""
    pb, un = _problem(0.5, 0.03)
    t = branches.table(pb, "contactless")
    states = fw.single_patch_states(pb, un, "contactless", t.a, "grip")
    lo, hi = cz.floating_range(pb.m, pb.edge.s0, THETA, GB)
    assert all(s.feasible for s in states) and len(states) > 30
    assert states[0].delta_over_Delta == pytest.approx(hi, abs=0.02) and states[-1].delta_over_Delta > -1e-3
    E = [cb.potential(cz.floating_state(d, pb.m, pb.edge.s0, THETA, GB)) for d in np.linspace(lo, hi, 5)]
    assert np.ptp(E) < 1e-12 * abs(E[0])
    assert cb.potential(_closed(pb, math.pi - 1e-7)) == pytest.approx(E[0], rel=1e-9)
    assert cb.potential(_closed(pb, math.pi - 1e-4)) != pytest.approx(E[0], rel=1e-9)


def _loop_work(pb, c_far, c_touch, delta_snap):
    """int |P*| d(delta/Delta) over the zone-only pin's stable states from its fold (the least approach, Brent on
    the closed form) to the approach where it snaps in, by Gauss-Legendre in c (the closed form); (work, fold)."""
    delta = lambda c: _closed(pb, c).delta_over_Delta
    lo, hi = sorted((c_far, c_touch))
    grid = np.linspace(lo + 1e-6 * (hi - lo), hi - 1e-6 * (hi - lo), 200)
    k = int(np.argmin([delta(c) for c in grid]))
    c_fold, d_fold = roots.minimum(delta, grid[k - 1], grid[k], grid[k + 1], 1e-12)
    c_snap = roots.root(lambda c: delta(c) - delta_snap, *sorted((c_fold, c_touch)), xtol=1e-14)
    x, w = np.polynomial.legendre.leggauss(60)
    c = 0.5 * (c_fold + c_snap) + 0.5 * (c_snap - c_fold) * x
    h = 1e-6
    slope = np.array([(delta(v + h) - delta(v - h)) / (2 * h) for v in c])
    P = np.array([_closed(pb, v).p / pb.scale for v in c])
    return -0.5 * (c_snap - c_fold) * np.sum(w * P * slope), d_fold


@pytest.mark.parametrize("lam, far", [(0.5, math.pi), (1.3, 0.0)])
def test_grip_cycles_close_with_the_zone_only_pins_loops(lam, far):
    """Grip 0 .. -1.7 Delta, M 0.03: the pin snaps onto its bottom zone where the free (lambda 1.3) or floating
    (lambda 0.5) range ends, lets go at the fold (the least approach of the closed form, 1e-8), and on the top the
    mirror: four jumps a loop, closed; the dissipation (the jumps' energy drops) equals twice the loop work by
    quadrature over closed-form states (1e-6)."""
    pb, un = _problem(lam, 0.03)
    cy = cycle.cycle(pb, un, "grip", 0.0, -1.7, 200, lambda P, d: d)
    assert cy.note == "" and cy.closed_from_leg == 1
    loop = [j for j in cy.jumps if j.leg in (1, 2)]
    assert [(j.kind, j.before.branch, j.after.branch) for j in loop] == [
        ("pull-off", "contactless", "separated"), ("snap-in", "separated", "contactless-top"),
        ("pull-off", "contactless-top", "separated"), ("snap-in", "separated", "contactless")]
    assert all(landing.dissipated(pb, un, j.before, j.after) > 0 for j in loop)
    snap = loop[-1].before.delta_over_Delta
    touch = cz.contactless_touch(pb.m, pb.edge.s0, THETA, GB).c
    work, d_fold = _loop_work(pb, far, touch, snap)
    assert loop[0].before.delta_over_Delta == pytest.approx(d_fold, abs=1e-8)
    assert loop[2].before.delta_over_Delta == pytest.approx(-2 - d_fold, abs=1e-8)
    assert cy.dissipated / pb.scale == pytest.approx(2 * work, rel=1e-6)


def test_a_zone_only_pin_drawn_across_the_middle_stops_saying_why():
    """lambda 0.8, M 0.03 (h0 1.004 Delta): pulled on its bottom zone towards delta = -Delta the pin's gap becomes
    nearly uniform (~Delta) and the gap at the bottom, in the middle of its zone, reaches h0 (the closed form's
    root of h(0) = h0, Brent; beyond the zone the gap stays above h0 there): the zone would part in two beside the
    bottom, not modelled.  The cycle stops with that reason at its last feasible table state, within 0.01 Delta
    of that root (was: no reason)."""
    pb, un = _problem(0.8, 0.03)
    cy = cycle.cycle(pb, un, "grip", 0.0, -1.0, 200, lambda P, d: d)
    assert cy.note.endswith(landing.ZONE_PARTS)
    h0 = pb.m ** 2 / pb.edge.s0
    c_on = roots.root(lambda c: _closed(pb, c).fields.gap(0.0)[0] - h0, 2.2, 2.5, xtol=1e-14)
    on = _closed(pb, c_on)
    assert on.fields.gap(np.linspace(c_on + 1e-3, math.pi, 200)).min() > h0
    stop = float(cy.delta[-1] / un.Delta)
    assert on.delta_over_Delta < stop < on.delta_over_Delta + 0.01


def test_a_walk_from_between_the_last_points_goes_on_at_the_touch():
    """lambda 1.2, M 0.04, grip 0 .. -0.3 Delta (h0 0.98): the pin touches at delta -0.122 Delta (closed form: the
    zone-only pin with h(0) = 0) and is pulled back onto its zone-only states, stopping between the table's last
    two points; pushed again it goes on across the touch onto the contact (was: read as a fold there -- 'no stable
    state to jump to after the snap-in').  No jump but the first snap-in: nothing dissipated (reversible)."""
    pb, un = _problem(1.2, 0.04)
    cy = cycle.cycle(pb, un, "grip", 0.0, -0.3, 200, lambda P, d: d)
    assert cy.note == "" and cy.closed_from_leg is not None and cy.dissipated == 0.0
    assert [j.kind for j in cy.jumps] == ["snap-in"]
    touch = cz.contactless_touch(pb.m, pb.edge.s0, THETA, GB).delta_over_Delta
    up = [(b, d / un.Delta) for b, d, leg in zip(cy.branch, cy.delta, cy.leg) if leg == 2]
    assert {"contactless", "sub-critical"} <= {b for b, _ in up}
    crossing = [d for (b, d), (b2, _) in zip(up, up[1:]) if b == "contactless" and b2 == "sub-critical"]
    assert len(crossing) == 1 and crossing[0] == pytest.approx(touch, abs=1e-9)
