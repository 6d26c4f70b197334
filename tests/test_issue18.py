"""Issue 18: the ten silent wrong answers, each pinned by its reproducer.

References: finite-element receding limits and a_crit quoted by the issue (plane strain, independent of this
code); Contact.state on dense grids (each state solved on its own) and scipy's bounded minimiser for the pull-off;
the trapezoid rule over a cycle's path; the two-arc engine's Griffith residual for two-patch states."""
import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

import jkrcyl
from jkrcyl import equilibria as eq
from jkrcyl.analysis import landing
from jkrcyl.model import two_patch

README_PIN = dict(R=10e-3, Delta=1e-6, w=0.05)


def roller(nu_I=0.49):
    """Rubber roller (E_I 2 MPa) in a rigid cradle, R 20 mm, Delta 50 um, w 0.05 (item 1)."""
    m = jkrcyl.Materials.from_young(E=math.inf, nu=0.3, E_I=2e6, nu_I=nu_I)
    return jkrcyl.Contact(R=20e-3, Delta=50e-6, w=0.05, materials=m)


def test_1_rigid_cradle_pull_off_is_the_fold_of_P():
    c = roller()
    po = c.pull_off()
    r = minimize_scalar(lambda a: float(c.state(a).P), bounds=(0.1, 0.5), method="bounded",
                        options={"xatol": 1e-12})
    assert po.P == pytest.approx(r.fun, rel=1e-8)                   # -69.47 N/m (issue: the fold), not -23.78
    assert po.P == pytest.approx(-69.47, abs=0.01)
    cv = c.curve(n=2000)                                             # the flip of the grid slopes is gone
    assert np.count_nonzero(np.diff(cv.stable_load.astype(int))) == 1
    assert c.pull_off("grip-work").P > po.P and c.adherence("grip")


def test_2_no_equilibrium_at_the_pole_and_the_rigid_plate_limits():
    c = roller()
    for s in c.solve(P=0.0, branches=["sub-critical", "sub-critical-top"]):
        assert abs(s.P) <= 1e-10 * c.load_scale                     # was a = 2.2244 with P = 1.5e16 N/m
    assert c.a_crit == pytest.approx(2.2244, abs=1e-4)              # the pole is the receding limit
    for nu_I, fe in ((0.45, 111.79), (0.2, 87.16)):                 # finite elements, from the issue
        assert math.degrees(2 * math.atan(roller(nu_I).a_crit)) == pytest.approx(fe, abs=0.05)


def test_3_contact_a_crit_is_the_pairs_pole():
    m = jkrcyl.Materials.from_young(E=70e9, nu=0.33, E_I=210e9, nu_I=0.3)   # steel pin in aluminium
    c = jkrcyl.Contact(R=1.0, Delta=1e-2, w=1e-4, materials=m)
    assert math.degrees(2 * math.atan(c.a_crit)) == pytest.approx(81.52, abs=0.07)   # FE 81.52 +- 0.07
    cv = c.curve(n=12)
    np.testing.assert_allclose(c.state(cv.a).eps_star, cv.eps_star, rtol=1e-14)


def test_4_dissipated_energy_does_not_depend_on_the_load_range():
    pin = jkrcyl.Contact(**README_PIN, materials=jkrcyl.Materials.from_young(2.6e9, 0.3, 2.6e9, 0.3))
    small = pin.cycle(P_max=1e4, P_min=-1e4, n=100_000)
    big = pin.cycle(P_max=1e6, P_min=-1e6, n=100_000)
    assert big.dissipated == pytest.approx(small.dissipated, rel=1e-12) and big.dissipated > 0
    sel = big.leg >= big.closed_from_leg
    trap = float(np.sum(0.5 * (big.P[sel][1:] + big.P[sel][:-1]) * np.diff(big.delta[sel])))
    assert big.dissipated == pytest.approx(trap, rel=1e-6)         # 0.0079978 J/m, not -25.29


@pytest.mark.slow
def test_5_confined_events_of_a_small_steel_pin_in_aluminium():
    m = jkrcyl.Materials.from_young(E=70e9, nu=0.33, E_I=210e9, nu_I=0.3)
    c = jkrcyl.Contact(R=5e-3, Delta=2e-6, w=0.1, materials=m)
    ev = c.confined_events()                                         # was OverflowError in the clipper
    assert ev.regime == "detachment" and ev.P_fold * c.load_scale == pytest.approx(c.pull_off().P, rel=1e-9)


def test_6_the_grip_stable_loop_is_one_branch_and_solve_finds_its_states():
    bs = eq.two_patch(0.44, 1.0, gb=0.5)
    loops = [b for b in bs if b.ends == ("loop", "loop")]
    assert len(loops) == 1                                           # was two chorded pieces
    m = jkrcyl.Materials(G=1.0, kappa=1.0, G_I=1.0, kappa_I=1.0)   # vartheta = 1, gb = 1/2
    c1 = jkrcyl.Contact(R=1.0, Delta=0.01, w=1.0, materials=m)
    c = jkrcyl.Contact(R=1.0, Delta=0.01, w=(0.44 / c1.M) ** 2, materials=m)
    ref = eq.two_patch_state(0.44, 1.0, gb=0.5, eps_top=math.radians(14.0), guess=math.radians(93.0))
    assert math.degrees(ref.eps) == pytest.approx(93.07, abs=0.01) and ref.P_star == pytest.approx(-0.2296, abs=1e-4)
    got = [s for s in c.solve(P=ref.P_star * c.load_scale, branches=["two-patch"])
           if abs(s.eps - ref.eps) < 1e-6 and abs(s.eps_top - ref.eps_top) < 1e-6]
    assert len(got) == 1 and abs(two_patch.residual(c.problem, got[0].eps, got[0].eps_top)) < 1e-9


def test_7_gb_is_required_and_named():
    with pytest.raises(TypeError):
        eq.curve(0.3, 1.0)                                           # no silent incompressible default
    with pytest.raises(ValueError, match="gb"):
        eq.curve(0.3, 1.0, gb=None)
    a = np.array([0.3])
    d = [float(eq.curve(0.8, 1.0, a=a, gb=gb).delta_over_Delta[0]) for gb in (1 / 2.8, 0.5)]
    assert abs(d[0] - d[1]) > 1e-3                                   # delta depends on gb: it must be stated


def test_8_after_a_sub_critical_onset_the_pin_zips_into_full_contact():
    pb = eq.problem(0.4, 1.0, 1 / 2.8)
    (e_on, P_on, _, _), = [o for o in landing.top_onsets(pb) if math.tan(o[0] / 2) < eq.a_crit(1.0, 1 / 2.8)]
    outcome, (e, et) = two_patch.descend(pb, P_on, e_on)
    assert outcome == "full" and e + et >= math.pi - 0.02
    bs = [b for b in eq.two_patch(0.4, 1.0, gb=1 / 2.8) if abs(b.eps[0] - e_on) < 1e-3]
    assert len(bs) == 1 and bs[0].ends == ("single", "mirror")      # only the bridge leaves that onset


def test_9_no_zero_load_contact_means_bonded_everywhere():
    m = jkrcyl.Materials(G=1.0, kappa=1.8, G_I=1.0, kappa_I=1.8)    # vartheta = 1
    c1 = jkrcyl.Contact(R=1.0, Delta=0.01, w=1.0, materials=m)
    c = jkrcyl.Contact(R=1.0, Delta=0.01, w=(0.8 / c1.M) ** 2, materials=m)
    assert eq.zero_load_contact(0.8, 1.0) == []                     # (8.1) has no root (M_max = 0.645)
    po = c.pull_off()
    assert po.P is None and "zero-load" in po.reason and po.state.branch == "full-contact"
    assert c.confined_events().regime == "bonded" and math.isinf(c.confined_events().start[0])
    cy = c.cycle(P_max=c.load_scale, P_min=-c.load_scale, n=50)
    assert cy.jumps[0].after.branch == "full-contact"


def test_9_rigid_cradle_without_zero_load_contact_says_why():
    """Rubber roller (2 MPa, nu 0.45) in a rigid cradle, R 5 mm, Delta 2 um, w 0.1: M_R* = 3.98, the load of the
    single patch (Contact.state, a route apart from the walker) is negative up to the receding limit, so the pin
    zips round at first touch into full contact (a compressible pin fills the rigid hole: alpha*/beta* -1/11), which
    JKR's bond holds at any load: pull_off says so (no number), the cycle snaps into full contact at P = 0 and
    stays (the approach there: delta/Delta = -1 of the bonded pin at zero load, model.full_contact)."""
    c = jkrcyl.Contact(R=5e-3, Delta=2e-6, w=0.1,
                       materials=jkrcyl.Materials.from_young(E=math.inf, nu=0.3, E_I=2e6, nu_I=0.45))
    assert np.all(c.state(np.linspace(0.01, 0.999, 40) * c.a_crit).P < 0)
    po = c.pull_off()
    assert po.P is None and "zips round into full contact" in po.reason and "does not detach" in po.reason
    cy = c.cycle(P_max=100.0, P_min=-100.0, n=20)
    assert [(j.kind, j.after.branch) for j in cy.jumps] == [("snap-in", "full-contact")] and cy.dissipated == 0.0
    assert cy.jumps[0].after.delta == pytest.approx(-c.Delta, rel=1e-12)


def test_10_inputs():
    with pytest.raises(ValueError, match="n"):
        eq.stationary_points(0.3, 1.0, gb=0.5, n=1)
    with pytest.raises(ValueError, match="n"):
        eq.stationary_points(0.3, 1.0, gb=0.5, n=-3)
    pin = jkrcyl.Contact(**README_PIN, materials=jkrcyl.Materials.from_young(2.6e9, 0.3, 2.6e9, 0.3))
    with pytest.raises(ValueError, match="control"):
        pin.pull_off(control=["load"])
    with pytest.raises(ValueError, match="branches"):
        pin.solve(P=1.0, branches=5)
    with pytest.raises(ValueError, match="0.4999999"):
        jkrcyl.a_crit(0.4999999)
    with pytest.raises(ValueError, match="kappa"):
        jkrcyl.Materials(G=1.0, kappa=1e100, G_I=1.0, kappa_I=1.0)
    with pytest.raises(ValueError, match="delta_max"):
        pin.cycle(P_max=1.0, P_min=-1.0, delta_max=1e-6, delta_min=-1e-6)
