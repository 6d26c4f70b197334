"""The Maugis-Dugdale branch at a long range, h0 >= 2 Delta: the round zone still opens by a jump (an S).

Case: vartheta 10, gb 0, lambda 3.155, M 0.246 (h0 = 4.21 Delta).  The range reaches round at the touch end (no
state pulls), and pushed, the round zone's top gap reaches h0 at eps_open = 1.8953, where the zone end leaves the
top towards smaller contacts and turns (eps 1.8719) onto the root that tends to JKR.  The scan for that jump
(jkrcyl.numerics.cohesive_branch.top_opens) was asked only for h0 < 2 Delta, so the branch was sampled in eps
across the jump: its table jumped from c = pi to c = 3.0 between neighbouring rows (P* 0.472 -> 0.349) and a load
cycle to P* 2 read the jump as a fold ('more than 20 jumps').

References: states solved alone at fixed contacts (jkrcyl.numerics.cohesive.cohesive_state, no trace), the
opening from a bisection of h(pi) = h0 over round-zone states solved alone, the jumps' held values and the sign of
the potential's drop."""
import math

import numpy as np
import pytest

from jkrcyl.analysis import cycle
from jkrcyl.analysis import landing
from jkrcyl.laws.dugdale import edge_of_strength
from jkrcyl.model.problem import Problem
from jkrcyl.model.single_patch import solver
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_scales as sc
from jkrcyl.numerics import roots
from jkrcyl.units import Units

M, THETA, GB, LAM = 0.246, 10.0, 0.0, 3.155


def _problem():
    s0 = sc.zone_strength(LAM, Problem(M, THETA, GB).m)
    return Problem(M, THETA, GB, 0.0, edge_of_strength(s0))


def _law(pb):
    return pb.m, pb.edge.s0, THETA, GB, 0.0


def _round(law, eps, n=96):
    """The state with the contact eps and its zone all round, solved alone at that contact (the fixed contact's
    linear system, n nodes: the round zone has no zone end, its field is smooth), valid or not."""
    m, s0, kernel = co._law(*law)
    fc = co.FixedContact(eps, kernel, n)
    zones = co.zones_of(math.pi)
    dn, u = fc.solve(zones, s0)
    return co._state(eps, math.pi, fc, dn, u, zones, m, s0, kernel, law[3], n)


def _opening(law):
    """eps where the round-zone state solved alone reaches h(pi) = h0 (Brent on _round)."""
    h0 = law[0] ** 2 / law[1]
    return roots.root(lambda e: _round(law, e).h_pi_over_Delta - h0, 1.85, 1.92, xtol=1e-14)


def _on_branch(sv, a, s, eps, c):
    """The branch parameter where the traced branch passes the contact eps with its zone end nearest to c."""
    cells = [i for i in range(a.size - 1) if (s.eps[i] - eps) * (s.eps[i + 1] - eps) <= 0]
    found = [roots.root(lambda x: sv._where(x)[0] - eps, a[i], a[i + 1], xtol=1e-14) for i in cells]
    return min(found, key=lambda x: abs(sv._where(x)[1] - c))


def test_the_table_is_continuous_through_the_round_zones_opening():
    """Each table interval next to the opening, refined 16 times, has steps in c and P far below the interval's
    (a jump would keep one step as large as the whole); the round part ends at the opening from the bisection
    (1e-9) and the branch's largest load there is the round-zone state's at it, solved alone."""
    pb = _problem()
    law = _law(pb)
    sv = solver(pb)
    a = sv.grid("sub-critical", sv.dense_points)
    s = sv.states(a)
    k = int(np.flatnonzero(s.c == math.pi)[-1])          # the round part's last row
    eps_open = _opening(law)
    assert s.eps[k] == pytest.approx(eps_open, rel=1e-9) and s.c[k + 1] < math.pi
    assert s.p[k] == pytest.approx(_round(law, eps_open).p, rel=1e-8)
    for i in range(k - 3, k + 8):
        fine = np.linspace(a[i], a[i + 1], 17)
        f = sv.states(fine)
        for col in ("p", "c"):
            coarse = abs(getattr(s, col)[i + 1] - getattr(s, col)[i])
            step = np.max(np.abs(np.diff(getattr(f, col))))
            assert step <= 0.3 * coarse + 1e-9, (i, col, step, coarse)


# (eps, c - eps near): a round-zone state, then at one contact the root near the top (coming back from the
# opening) and the first root (towards JKR) -- rough guesses from a sign scan; cohesive_state refines them
ALONE = [(1.6, None), (1.885, 1.248), (1.885, 1.155), (2.0, 0.85)]


def test_states_solved_alone_lie_on_the_traced_s():
    """Each state of ALONE solved at its contact lies on the table's branch (c, p, delta to 1e-9); the two at eps
    1.885 are different states (c 0.09 apart): the branch passes that contact twice."""
    pb = _problem()
    law = _law(pb)
    sv = solver(pb)
    a = sv.grid("sub-critical", sv.dense_points)
    s = sv.states(a)
    cs = []
    for eps, near in ALONE:
        alone = co.cohesive_state(eps, *law, near=near)
        pt = sv.point(_on_branch(sv, a, s, eps, alone.c if alone.zones != "all" else math.pi))
        assert abs(pt.c - alone.c) < 1e-9 and abs(pt.p - alone.p) < 1e-9 * max(1.0, abs(alone.p))
        assert abs(pt.delta - alone.delta_over_Delta) < 1e-9 * max(1.0, abs(alone.delta_over_Delta))
        cs.append(alone.c)
    assert cs[0] == math.pi and cs[1] > cs[2] + 0.05


def test_a_load_cycle_jumps_at_the_opening_and_crosses_a_crit_back():
    """Load cycle 2 .. -3 (normalised): pushed, the round zone's opening is the branch's largest load -- the
    jump there (held P) lands on the super-critical branch, stable, the potential less P delta falling
    (landing.dissipated); pulled back, the super-critical branch turns back to the receding limit with a finite
    load and crosses it onto the sub-critical one (states solved alone either side of eps_crit: their difference
    in P shrinks 10-fold with the distance; jkrcyl.numerics.cohesive_crossing traces it) and the cycle closes
    (was: 'more than 20 jumps' from the table's false fold, then a stop at the untraced crossing)."""
    pb = _problem()
    un = Units.normalised(pb)
    law = _law(pb)
    cy = cycle.cycle(pb, un, "load", 2.0, -3.0, 200, lambda P, d: d)
    assert "more than" not in cy.note
    assert all(landing.dissipated(pb, un, j.before, j.after) >= 0 for j in cy.jumps)
    jump = cy.jumps[0]
    b, t = jump.before, jump.after
    eps_open = _opening(law)
    assert b.eps == pytest.approx(eps_open, rel=1e-9)
    assert b.P_star * pb.scale == pytest.approx(_round(law, eps_open).p, rel=1e-8)
    assert t.branch == "super-critical" and t.stable and t.feasible and t.P == pytest.approx(b.P, rel=1e-9)
    assert jump.kind == "snap-in" and t.contact_width > b.contact_width      # pushed: not a 'pull-off' (was)
    assert landing.dissipated(pb, un, b, t) > 0        # the potential less the load's work falls (kernel units)
    assert cy.note == ""                                # closed: the crossing of eps_crit is traced
    eps_crit = 2 * math.atan(solver(pb).a_crit)
    gap = []
    for r in (1e-4, 1e-5):
        sides = [co.cohesive_state(eps_crit * (1 + x), *law, near=2.715 - eps_crit) for x in (-r, r)]
        assert all(abs(x.c - 2.715) < 0.01 for x in sides)
        gap.append(abs(sides[0].p - sides[1].p))
    assert gap[1] < 0.2 * gap[0]        # continuous through eps_crit (a pole or a jump would not shrink)


def test_a_grip_cycle_lands_on_the_crossing_of_a_crit():
    """Grip 0 .. 5 Delta: the round zone's opening is also the branch's largest approach; no other state of the
    single-patch tables holds that approach -- the one that does lies within 1e-3 of eps_crit (a state solved
    alone there, Brent in eps on the approach of cohesive_state, feasible), on the crossing
    (jkrcyl.numerics.cohesive_crossing): the jump lands there and the cycle closes (was: a stop, no reason)."""
    pb = _problem()
    un = Units.normalised(pb)
    law = _law(pb)
    cy = cycle.cycle(pb, un, "grip", 5.0, 0.0, 200, lambda P, d: d)
    assert all(landing.dissipated(pb, un, j.before, j.after) >= 0 for j in cy.jumps)
    assert cy.note == ""
    jump = cy.jumps[0]
    held = jump.before.delta_over_Delta
    eps_crit = 2 * math.atan(solver(pb).a_crit)
    alone = lambda e: co.cohesive_state(e, *law, near=2.715 - e)
    e = roots.root(lambda e: alone(e).delta_over_Delta - held, eps_crit * (1 - 1e-3), eps_crit * (1 + 1e-3),
                   xtol=1e-15)
    assert co.gap_check(alone(e), 120).feasible and abs(e / eps_crit - 1) < 1e-3
    assert jump.after.eps == pytest.approx(e, rel=1e-8) and jump.after.stable and jump.after.feasible
