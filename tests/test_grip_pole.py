"""The paper's approach held ('grip') where the top closes next to the pole of the fixed arcs: no landing.

Helper-18's sweep found a JKR grip cycle (M 0.06, vartheta 19.68, gb 0.582, grip 0 .. -1.95 Delta) whose
top-contact landed on a patch at the top next to its pole (a = 2.082, P* -78.86 at delta/Delta -0.7472),
'dissipating' 1517 kernel units.  Checked against what the landing does not use:

* that state's potential E from the touch by int p d(delta) along its branch (Chebyshev in log a): E is right,
  -1518.69; but its elastic part U* = E + 2 m^2 eps = [(1 + delta/Delta) p - B]/2 is NEGATIVE (-1512): U* is
  Clapeyron's with the paper's delta, not the work-conjugate delta_work = delta/Delta + c p, and the strain energy,
  Clapeyron's with delta_work, U* + c p^2/2, is +3.5e5 (> 0).  Towards the pole of the load the paper's delta runs
  off opposite to p (delta/Delta ~ -1.26e-3 p), so U* ~ delta p/2 ~ -6.3e-4 p^2: the potential of a held paper's
  delta is unbounded below (holding delta is a grip of negative compliance -c), that of delta_work is not;
* the relaxation from the top's closing at the held delta (two_patch.descend) does not end on a state: it runs into
  arcs where the fixed-arc load at that delta is unbounded (G/w ~ 4e21 at its end; dP*/d delta at fixed arcs
  changes sign through infinity across it).  The old walk called that end a two-patch state, found none stable
  there and fell back on the near-pole patch: a wrong landing.  Now the walk stops there and says why;
* the same top closing under grip-work (delta_work held, a testing machine) relaxes onto a two-patch state (G = w at
  both ends: a stationary point), dissipating 2.28 > 0.
"""
import math

import numpy as np
import pytest
from numpy.polynomial import chebyshev as C

from jkrcyl.analysis import branches, cycle, forward, landing, tracing
from jkrcyl.model import two_patch as two
from jkrcyl.model.problem import Problem
from jkrcyl.model.single_patch import solver
from jkrcyl.units import Units

PB = Problem(0.06, 19.68, 0.582)
UN = Units.normalised(PB, K_edge=1.0)          # P = P*, delta = delta/Delta, energy in 4 pi Delta^2/beta*
C_WORK = PB.work_shift                         # delta_work/Delta = delta/Delta + c p (p = vartheta P*)
D_TOP = -0.7472169304854991                     # the held delta/Delta of the sweep's top closing (its walk's)


def onset():
    """JKR's top onset (h(pi) = 0, closed form) the grip cycle meets: eps 0.8536, delta/Delta -0.74739 (the walk
    meets it at its table's last feasible point, 1.7e-4 before)."""
    e = min(tracing.onset_angles(PB), key=lambda x: abs(x - 0.8536))
    return forward.single_patch_states(PB, UN, "sub-critical", [math.tan(e / 2)], "grip")[0]


def test_the_old_landing_lies_below_only_by_the_paper_deltas_negative_compliance():
    sv = solver(PB)
    top = [x for x in forward.solve_normalised(PB, UN, "grip", D_TOP, ["sub-critical-top"]) if x.P_star < -50]
    assert len(top) == 1 and top[0].stable and top[0].feasible            # the old landing: a = 2.0822
    s = forward.single_patch_states(PB, UN, "sub-critical", [top[0].a], "grip")[0]     # its mirror: the same E
    assert s.energy == pytest.approx(top[0].energy, rel=1e-12)
    ac = sv.a_crit
    touch = lambda i: (lambda u: getattr(sv.states(np.exp(u)), ("p", "dn")[i]))           # u = log a
    pole = lambda i: (lambda u: getattr(sv.states(ac - np.exp(u)), ("p", "dn")[i]))       # u = log(a_crit - a)
    along = 0.0
    for f, lo, hi in ((touch, math.log(1e-10), math.log(0.1 * ac)), (touch, math.log(0.1 * ac), math.log(0.5 * ac)),
                      (pole, math.log(0.5 * ac), math.log(ac - s.a))):
        p, d = C.Chebyshev.interpolate(f(0), 100, domain=[lo, hi]), C.Chebyshev.interpolate(f(1), 100, domain=[lo, hi])
        along += float((p * d.deriv()).integ(lbnd=lo)(hi))
    assert s.energy == pytest.approx(along, rel=1e-9)           # E from the touch (E = 0 there): -1518.69
    assert s.energy == pytest.approx(-1518.69, abs=0.01)         # the sweep's landing (its dissipation 1517)
    p = PB.scale * s.P_star
    elastic = s.energy + 2 * PB.m ** 2 * s.eps                  # U*: Clapeyron with the paper's delta
    assert elastic < -1500                                       # not a strain energy
    assert elastic + C_WORK * p ** 2 / 2 > 3e5                   # Clapeyron with delta_work: 3.5e5 > 0
    for f in (1e-4, 1e-6):       # towards the pole delta runs off opposite to p: U* ~ delta p/2 -> -inf
        near = forward.single_patch_states(PB, UN, "sub-critical", [ac * (1 - f)], "grip")[0]
        p = PB.scale * near.P_star
        u_near = near.energy + 2 * PB.m ** 2 * near.eps
        assert u_near / (near.delta_over_Delta * p / 2) == pytest.approx(1.0, abs=1000 * f)    # 1.06, 1.0006
        assert u_near < -0.5e-3 * p ** 2 and u_near + C_WORK * p ** 2 / 2 > 0.1 * p ** 2     # measured -6.3e-4 p^2


def test_the_grip_relaxation_runs_into_the_pole_of_the_fixed_arcs():
    s = onset()
    assert s.delta_over_Delta == pytest.approx(D_TOP, abs=2e-4)
    outcome, end = two.descend(PB, s.delta_over_Delta, s.eps, control="grip")
    assert outcome == "pole"
    k = (lambda L: L.q0[2:4] + s.delta_over_Delta * L.q1[2:4])(two.linear(PB, *end))
    assert np.min((math.pi * k / PB.M) ** 2) > 1e15               # G/w at its end: no equilibrium (measured 4e21)
    # across the end, along the bottom arc: dP*/d delta at fixed arcs changes sign through infinity (a pole)
    q1 = {h: two.linear(PB, end[0] + h, end[1]).q1[0] for h in (-1e-3, 1e-3, 1e-5)}     # measured +-258 at 1e-3
    assert q1[-1e-3] * q1[1e-3] < 0 and 50 < q1[1e-5] / q1[1e-3] < 200                      # ~ 1/h
    # the same closing under grip-work: a two-patch stationary point (G = w at both ends)
    dw = s.delta_work_over_Delta
    outcome, end = two.descend(PB, dw, s.eps, control="grip-work")
    assert outcome == "two-patch"
    st = two.solve(PB, eps=end[0], guess=end[1])
    assert st.eps_top == pytest.approx(end[1], abs=1e-4)


@pytest.mark.slow                       # ~20-50 s: two JKR cycles with two-patch landings
def test_the_grip_cycle_stops_there_and_grip_work_lands_on_two_patches():
    cy = cycle.cycle(PB, UN, "grip", 0.0, -1.95, 100, lambda P, d: d)
    assert [j.kind for j in cy.jumps] == ["snap-in"]
    assert "top-contact" in cy.note and landing.POLE in cy.note
    work = cycle.cycle(PB, UN, "grip-work", 0.0, -1.95, 100, lambda P, d: d)
    j = work.jumps[1]
    assert j.kind == "top-contact" and j.after.branch == "two-patch"
    assert j.before.delta_work_over_Delta == pytest.approx(onset().delta_work_over_Delta, abs=2e-4)
    assert landing.dissipated(PB, UN, j.before, j.after) == pytest.approx(2.28, abs=0.01)    # measured 2.2818
