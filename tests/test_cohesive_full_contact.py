"""Full contact under the Maugis-Dugdale law, and the walker's zip into it (through the law interface).

With no gap there is no zone: the bonded pin is JKR's full-contact state with the same w (elastic field
n = N0 + N1 cos(phi), interface energy -w over the circle).  What the law adds is its strength: the bond holds
where the tension -vartheta n stays below s0 (an opening h costs s0 h and releases the tension times h).

Checked against what the library does not use to make it:

* the end of the cohesive contact branch with its zone all round (jkrcyl.numerics.cohesive.cohesive_state at
  eps -> pi, a collocation solve with the Dugdale traction on the gap): its load tends to where the bond stops
  holding at the top, p = pi s0 - vartheta (alpha* = 0: N0 = -1/pi, (1 + P*)/pi = s0/vartheta), and its total
  potential (Gauss quadrature of the zone's opening) to the bonded pin's at the same approach;
* JKR's answers (closed forms of the single patch, the paper's full contact) at lambda = 50 and 100 for the zip
  (fold load, landing) and first contact, with the lambda trend measured;
* the energy the zip dissipates, from the states' own energies (>= 0, and JKR's to C/lambda^2).
"""
import math

import numpy as np
import pytest

import jkrcyl
from jkrcyl.model.stability import single_patch_flags
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_branch as cb

R, DELTA = 1e-2, 1e-6
IDENTICAL = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)


def contact(M, lam, materials=IDENTICAL):
    probe = jkrcyl.Contact(R, DELTA, 1.0, materials)
    return jkrcyl.Contact.with_lambda(R, DELTA, (M / probe.M) ** 2, materials, lam)


def jkr(c):
    return jkrcyl.Contact(c.R, c.Delta, c.w, c.materials)


def bond_limit(c):
    """P* above which the bond breaks at the top, alpha* = 0: vartheta (1 + P*)/pi = s0 (module docstring)."""
    return math.pi * c.problem.edge.s0 / c.theta - 1.0


# --- the bonded pin -------------------------------------------------------------------------------------------
@pytest.mark.parametrize("lam", [5.0, 50.0])
def test_round_zone_branch_ends_where_the_bond_stops_holding(lam):
    """The cohesive contact with its zone all round at eps = pi - 1e-4 (M = 0.5, identical bodies): its load is
    the bond limit pi s0 - vartheta to 1e-5 relative (the gap's width 2e-4 rad; the bonded pin at its approach
    is at that limit, feasible or not by a hair), and its
    total potential is the bonded pin's at its approach to 1e-5 of the adhesion energy 2 pi m^2."""
    c = contact(0.5, lam)
    pb = c.problem
    law = cb.Law(pb.m, pb.edge.s0, pb.theta, pb.gb, pb.alpha_ratio)
    st = law.state(math.pi - 1e-4)
    assert st.zones == "all" and abs(st.k) < 1e-9
    p_limit = math.pi * pb.edge.s0 - pb.theta
    assert abs(st.p / p_limit - 1) < 1e-5
    full = c.solve(delta=st.delta_over_Delta * DELTA, branches=["full-contact"])[0]
    assert abs(full.P_star * pb.scale / p_limit - 1) < 1e-5
    E_full = full.energy / (4 * math.pi * DELTA ** 2 / c.beta)              # the kernel scale
    assert abs(cb.potential(st) - E_full) < 1e-5 * 2 * math.pi * pb.m ** 2
    assert co.gap_check(st).feasible


@pytest.mark.parametrize("lam", [5.0, 50.0])
def test_the_bond_holds_below_the_strength_only(lam):
    """solve(branches=['full-contact']) gives JKR's bonded pin (same P, approach, energy) where the tension is
    below sigma0 (stable under every control) and an infeasible, unstable one beyond the limit (either sign of
    P: the tension peaks at the top when pushing, at the bottom when pulling)."""
    c = contact(0.5, lam)
    lim = bond_limit(c) * c.load_scale
    for P in (-0.999 * lim, -1.0, 0.0, 0.5 * lim, 0.999 * lim):
        got, ref = (x.solve(P=P, branches=["full-contact"])[0] for x in (c, jkr(c)))
        assert got.feasible and got.stable_load and got.stable_grip and got.stable_grip_work
        assert (got.P, got.delta, got.energy) == (ref.P, ref.delta, ref.energy)
    for P in (-1.001 * lim, 1.001 * lim):
        got = c.solve(P=P, branches=["full-contact"])[0]
        assert not (got.feasible or got.stable_load or got.stable_grip)
        assert jkr(c).solve(P=P, branches=["full-contact"])[0].feasible


@pytest.mark.slow                  # ~30 s: the law's two-patch branches (ConfinedEvents.branches)
def test_the_confined_classification_through_the_contact_is_jkrs():
    """M = 0.5, lambda = 50: Contact.confined_events zips into full contact as JKR's (its fold, not at a class
    boundary), the fold load within 1/lambda^2 of JKR's."""
    c = contact(0.5, 50.0)
    got, ref = c.confined_events(), jkr(c).confined_events()
    assert got.regime == ref.regime == "zip-full" and abs(got.P_fold - ref.P_fold) < 1 / 50.0 ** 2


def test_bad_load_on_full_contact():
    c = contact(0.5, 50.0)
    with pytest.raises(ValueError, match="^P"):
        c.solve(P=math.nan, branches=["full-contact"])


# --- the zip ----------------------------------------------------------------------------------------------------
@pytest.mark.slow
@pytest.mark.parametrize("lam", [50.0, 100.0])
def test_zip_under_load_lands_on_full_contact_as_jkr(lam):
    """M = 0.5, identical bodies: the pull under load ends at the super-critical fold, where a further pull grows
    the contact: the pin zips into full contact (JKR's answer, section 8.2).  The fold's P* equals JKR's to
    2e-3 (measured: 3.3e-8 at lambda = 50, 2.1e-9 at 100 -- the fold converges as lambda^-4, as the pull-off);
    the cycle jumps as JKR's, and the zip dissipates >= 0, JKR's amount to 1e-3 relative."""
    c = contact(0.5, lam)
    got, ref = c.pull_off("load"), jkr(c).pull_off("load")
    assert got.P is None and ref.P is None and "grows round into full contact" in got.reason
    assert "not modelled" not in got.reason
    assert got.state.branch == ref.state.branch == "super-critical"
    assert abs(got.state.P_star - ref.state.P_star) < 2e-3 * (50.0 / lam) ** 2
    kw = dict(control="load", P_max=0.2 * c.load_scale, P_min=-0.6 * c.load_scale, n=200)
    cy, cy_ref = c.cycle(**kw), jkr(c).cycle(**kw)
    kinds = [(j.kind, j.before.branch, j.after.branch) for j in cy.jumps]
    assert kinds == [(j.kind, j.before.branch, j.after.branch) for j in cy_ref.jumps]
    assert kinds[-1] == ("zip", "super-critical", "full-contact")
    assert cy.branch[-1] == "full-contact"
    zips = (cy.jumps[-1], cy_ref.jumps[-1])
    lost = [j.before.P * (j.after.delta - j.before.delta) - (j.after.energy - j.before.energy) for j in zips]
    assert lost[0] > 0 and abs(lost[0] / lost[1] - 1) < 1e-3


@pytest.mark.slow
@pytest.mark.parametrize("lam", [50.0, 100.0])
def test_bonded_at_first_touch_and_zip_under_grip_as_jkr(lam):
    """M = 0.8 (no zero-load contact on one patch): under load the pin is bonded at first touch (JKR's answer);
    under grip it snaps onto the super-critical branch and zips into full contact at the fold, as JKR's.  The law
    snaps in at delta = -h0 (the pin reaches the range before it touches: O(1/lambda) from JKR's delta = 0), so
    the snap-in state is compared with JKR's at its approach, and the zip's fold with JKR's fold: each within
    2e-3 in P* at lambda = 50 (measured, P*: snap-in 1.7e-7 / 1.0e-8, fold 4.3e-7 / 4.4e-8 at lambda = 50 / 100,
    i.e. ~lambda^-3.5; the fold's approach 3.2e-7 / 2.0e-8 Delta)."""
    c = contact(0.8, lam)
    got = c.pull_off("load")
    assert got.P is None and got.state.branch == "full-contact" and "zips round" in got.reason
    kw = dict(control="grip", delta_max=0.0, delta_min=-1.5 * DELTA, n=200)
    cy, cy_ref = c.cycle(**kw), jkr(c).cycle(**kw)
    assert [j.kind for j in cy.jumps] == [j.kind for j in cy_ref.jumps] == ["snap-in", "zip"]
    assert [j.after.branch for j in cy.jumps] == [j.after.branch for j in cy_ref.jumps] == \
        ["super-critical", "full-contact"]
    snap = cy.jumps[0].after
    assert snap.delta == pytest.approx(-c.h0, rel=1e-9)
    ref = [s for s in jkr(c).solve(delta=snap.delta, branches=["super-critical"]) if s.stable_grip]
    tol = 2e-3 * (50.0 / lam) ** 2
    assert len(ref) == 1 and abs(snap.P - ref[0].P) / c.load_scale < tol
    fold, fold_ref = cy.jumps[1].before, cy_ref.jumps[1].before
    assert abs(fold.P - fold_ref.P) / c.load_scale < tol and abs(fold.delta - fold_ref.delta) / DELTA < tol
    assert cy.jumps[1].after.feasible and cy.jumps[1].after.delta == fold.delta


# --- the super-critical branch's round-zone tail, into full contact -----------------------------------------
@pytest.mark.slow
def test_round_zone_tail_reaches_full_contact_at_the_bond_limit():
    """lambda = 5, M = 0.5 (identical bodies): the super-critical zone reaches round (h(pi) = h0) and the branch
    goes on with its zone all round up to eps = pi - 1e-3, where P* is the bond limit pi s0/vartheta - 1 of the
    bonded pin to 1e-5 (measured 2.5e-7); the tail's states obey the law (gap check), are stable under load there
    (the rule's flags), and their total potential (Gauss quadrature of the round zone's opening) changes by
    p d(delta) between neighbouring states (trapezoid, to 1e-3 of the change: the tail's points are far apart)."""
    c = contact(0.5, 5.0)
    sv = c.problem.edge.single_patch(c.problem)
    br = sv._super
    assert br.tail.size == 40 and br.tail[-1] > math.pi - 1.1e-3
    a = br.offset + br.t[-40:]                                      # the tail's points on the table
    s = sv.states(a)
    flags = single_patch_flags(s, c.problem.work_shift)
    assert np.all(a - br.offset > br.t_round) and np.all(np.diff(s.eps) > 0) and np.all(s.c == math.pi)
    assert abs(s.p[-1] / c.problem.scale / bond_limit(c) - 1) < 1e-5
    assert s.feasible.all() and flags["load"].all()
    law = cb.Law(c.problem.m, c.problem.edge.s0, c.theta, c.problem.gb, 0.0)
    from jkrcyl.numerics import cohesive_super as csu
    states = [csu.round_state(law, e) for e in br.tail[10:14]]
    for a, b in zip(states[:-1], states[1:]):
        dE = cb.potential(b) - cb.potential(a)
        work = 0.5 * (a.p + b.p) * (b.delta_over_Delta - a.delta_over_Delta)
        assert abs(dE - work) < 1e-3 * abs(dE) + 1e-12


@pytest.mark.slow
def test_walker_follows_the_bond_break_onto_the_tail():
    """lambda = 5, M = 0.5: under load the pin zips into full contact at the super-critical fold (as JKR's), and
    pushed past the bond limit its top opens without a jump onto the round-zone tail (no jump recorded there), up
    to the tail's largest load (a fold pushed, no larger state there), where it jumps onto the nearest stable
    state on its side, a smaller super-critical contact at the same load; the loop closes.  Under grip too.  Every
    jump dissipates >= 0: the work of the held quantity less the change of the states' own total potential (the
    tail's jump: 0.0176 J/m; asked > 0.01 J/m, a real jump -- the zip's is 0.0009 J/m)."""
    c = contact(0.5, 5.0)
    cy = c.cycle(control="load", P_max=2.0 * c.load_scale, P_min=-0.5 * c.load_scale, n=300)
    assert [j.kind for j in cy.jumps] == ["snap-in", "zip", "zip"] and cy.jumps[1].after.branch == "full-contact"
    pushed = [i for i in range(len(cy.P)) if cy.branch[i] == "full-contact"]
    assert pushed and max(cy.P[pushed]) / c.load_scale == pytest.approx(bond_limit(c), rel=1e-9)
    tail = cy.jumps[2]
    assert tail.before.branch == tail.after.branch == "super-critical" and tail.after.a < tail.before.a
    assert tail.before.P / c.load_scale > bond_limit(c) and tail.after.P == pytest.approx(tail.before.P, rel=1e-9)
    assert tail.after.stable and tail.after.feasible and cy.note == "" and cy.closed_from_leg is not None
    lost = 0.5 * (tail.before.P + tail.after.P) * (tail.after.delta - tail.before.delta) - (
        tail.after.energy - tail.before.energy)
    assert lost > 0.01                           # J/m: a real jump, the bond at the top breaking
    cg = c.cycle(control="grip", delta_max=0.0, delta_min=-1.5 * DELTA, n=300)
    assert cg.dissipated is not None and cg.dissipated > 0
    for j in cy.jumps + cg.jumps:
        lost = 0.5 * (j.before.P + j.after.P) * (j.after.delta - j.before.delta) - (j.after.energy - j.before.energy)
        assert lost >= -1e-9 * abs(j.before.energy)
