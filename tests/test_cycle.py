"""Issue 11 items 2-3: pull-off along the stable path and quasi-static load cycles.

References: the minimum of P (load) or delta (grip) over a dense evaluation of Contact.state (the full-state
kernel, 2 x 10^5 points; the fold is quadratic, so the grid minimum is within ~1e-10 relative); Barquins'
half-plane limit (7.3b) for small M; an independent trapezoid integration of the loop for the energy.
"""
import math

import numpy as np
import pytest

import jkrcyl
from jkrcyl import special
from jkrcyl.analysis import landing
from jkrcyl.model import full_contact
from jkrcyl.model.problem import Problem

MAT = jkrcyl.Materials(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0)           # vartheta = 1, alpha* = 0


def contact(M, mat=MAT, Delta=0.01, R=1.0):
    c0 = jkrcyl.Contact(R=R, Delta=Delta, w=1.0, materials=mat)
    return jkrcyl.Contact(R=R, Delta=Delta, w=(M / c0.M) ** 2, materials=mat)


def dense_sub_critical(c, n=200000):
    a = c.a_crit * np.tan(np.pi / 4 * np.linspace(1e-7, 1 - 1e-7, n)) if math.isfinite(c.a_crit) else \
        np.tan(np.pi / 2 * np.linspace(1e-7, 0.9, n))
    return a, c.state(a)


@pytest.mark.parametrize("M", [0.05, 0.2, 0.3])
def test_pull_off_load_is_the_minimum_of_a_dense_curve(M):
    c = contact(M)
    po = c.pull_off("load")
    assert po.detached and po.control == "load"
    a, st = dense_sub_critical(c)
    i = int(np.argmin(st.P))
    assert po.P == pytest.approx(st.P[i], rel=1e-9)
    assert po.contact_width == pytest.approx(2 * c.R * 2 * math.atan(a[i]), rel=1e-3)
    assert po.delta == pytest.approx(st.delta[i], rel=1e-4)        # delta is linear in a at the fold
    assert po.state.stable_load or abs(po.state.a - a[i]) < 1e-3 * a[i]     # the fold itself is marginal


@pytest.mark.parametrize("M", [0.05, 0.3])
def test_pull_off_grip_is_the_minimum_of_delta(M):
    c = contact(M)
    po = c.pull_off("grip")
    a, st = dense_sub_critical(c)
    i = int(np.argmin(st.delta))
    assert po.delta == pytest.approx(st.delta[i], rel=1e-9)
    assert po.P == pytest.approx(st.P[i], rel=1e-4)               # P is linear in a there
    assert po.P > c.pull_off("load").P          # fixed grip detaches at a smaller pull (classical JKR)


def test_pull_off_half_plane_limit():
    """Small M: the fixed-load pull-off tends to Barquins' half-plane value -(3/2)(vartheta M^4/2)^(1/3) (7.3b)."""
    c = contact(1e-4)
    P_h = special.half_plane_adherence(c.M, c.theta)[1] * c.load_scale
    assert c.pull_off("load").P == pytest.approx(P_h, rel=1e-3)


def test_pull_off_none_with_reason():
    """M = 0.5, vartheta = 1: the P* minimum is super-critical; a further pull grows the contact (jkrcyl.twopatch)."""
    po = contact(0.5).pull_off("load")
    assert po.P is None and not po and "full contact" in po.reason
    assert po.state is not None and po.state.branch == "super-critical"
    assert contact(0.0).pull_off().P is None
    with pytest.raises(ValueError, match="control"):
        contact(0.3).pull_off("force")


def test_worked_example_units():
    """E = 2.6 GPa, nu = 0.3 for both bodies, R = 10 mm, Delta = 10 um, w = 0.05 J/m^2: pull-off in N/m."""
    m = jkrcyl.Materials.from_young(2.6e9, 0.3, 2.6e9, 0.3)
    c = jkrcyl.Contact(R=0.01, Delta=1e-5, w=0.05, materials=m)
    po = c.pull_off("load")
    a, st = dense_sub_critical(c)
    assert po.P == pytest.approx(st.P.min(), rel=1e-9)
    assert -700 < po.P < -500                   # the half-plane estimate is -575 N/m (M = 0.033)


# --- cycles (item 3) ---------------------------------------------------------------------------------------
def _branch_points(c, a_from, a_to, n=100001, side="bottom"):
    """(P, delta) along the single patch between two contact parameters (dense Contact.state, geometric grid)."""
    a = np.geomspace(a_from, a_to, n)
    st = c.state(a)
    if side == "top":
        return -st.P, -2 * c.Delta - st.delta
    return st.P, st.delta


def _stable_root(c, P):
    """The stable sub-critical contact parameter at load P: the largest root of P(a) = P below a_crit,
    found by bisection on the printed-kernel state (independent of the solver's grid)."""
    a = c.a_crit * np.tan(np.pi / 4 * np.linspace(1e-9, 1 - 1e-9, 200001))
    v = c.state(a).P - P
    i = np.nonzero(np.sign(v[:-1]) * np.sign(v[1:]) < 0)[0][-1]
    lo, hi = a[i], a[i + 1]
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if (c.state(mid).P - P) * v[i] > 0 else (lo, mid)
    return 0.5 * (lo + hi)


def test_load_cycle_jumps_and_energy():
    c = contact(0.3)
    P_max, P_min = 0.5 * c.load_scale, -0.5 * c.load_scale
    cy = c.cycle(P_max=P_max, P_min=P_min)
    po = c.pull_off("load")
    kinds = [j.kind for j in cy.jumps]
    assert kinds == ["snap-in", "pull-off", "pull-off"]
    snap, down, up = cy.jumps
    # snap-in at zero load onto the stable root of (8.1)
    a0 = jkrcyl.zero_load_contact(c.M, c.theta)[0]
    assert snap.before.P == 0 and snap.after.a == pytest.approx(a0, rel=1e-9) and snap.after.P == pytest.approx(
        0, abs=1e-12 * c.load_scale)
    # pull-off at the fixed-load adherence force, landing on the top; the mirrored jump back at -P_po
    assert down.before.P == pytest.approx(po.P, rel=1e-12) and down.after.P == pytest.approx(po.P, rel=1e-12)
    assert down.after.side == "top" and up.after.side == "bottom"
    assert up.before.P == pytest.approx(-po.P, rel=1e-12)
    assert cy.closed_from_leg == 1
    # independent loop: dense Contact.state along bottom and top branches, trapezoid rule
    a_po, a_land = po.state.a, _stable_root(c, -po.P)
    a_max, a_min_top = _stable_root(c, P_max), _stable_root(c, -P_min)
    pieces = [_branch_points(c, a_max, a_po),                      # unload on the bottom to pull-off
              _branch_points(c, a_land, a_min_top, side="top"),    # land on the top, unload to P_min
              _branch_points(c, a_min_top, a_po, side="top"),      # reload: top contact shrinks to its pull-off
              _branch_points(c, a_land, a_max)]                    # land on the bottom, load to P_max
    P = np.concatenate([p[0] for p in pieces])
    d = np.concatenate([p[1] for p in pieces])
    area = np.sum(0.5 * (P[1:] + P[:-1]) * np.diff(d))
    assert cy.dissipated > 0
    assert cy.dissipated == pytest.approx(area, rel=1e-6)
    # the same loop in the work-conjugate approach delta + P/(8 pi G_I) (DERIVATION.md, 'The work-conjugate
    # approach'): a closed loop encloses the same area, and the cycle's own delta_work path is that shift
    dw = d + P * c.materials.inv_G_I / (8 * np.pi)
    assert np.sum(0.5 * (P[1:] + P[:-1]) * np.diff(dw)) == pytest.approx(area, rel=1e-9)
    np.testing.assert_allclose(cy.delta_work, cy.delta + cy.P * c.materials.inv_G_I / (8 * np.pi),
                               rtol=1e-14, atol=1e-14 * c.Delta)


def test_load_cycle_without_pull_off_dissipates_nothing():
    c = contact(0.3)
    po = c.pull_off("load")
    cy = c.cycle(P_max=0.5 * c.load_scale, P_min=0.5 * po.P)
    assert [j.kind for j in cy.jumps] == ["snap-in"]
    assert cy.dissipated == pytest.approx(0, abs=1e-10 * c.load_scale * c.Delta)


def test_grip_cycle_jumps_at_the_grip_pull_off():
    c = contact(0.3)
    cy = c.cycle(delta_max=0.3 * c.Delta, delta_min=-2.3 * c.Delta, control="grip")
    po = c.pull_off("grip")
    offs = [j for j in cy.jumps if j.kind == "pull-off"]
    assert offs and offs[0].before.delta == pytest.approx(po.delta, rel=1e-12)
    assert offs[0].after.branch == "separated" and offs[0].after.delta == offs[0].before.delta
    snaps = [j for j in cy.jumps if j.kind == "snap-in"]
    assert snaps[0].after.delta == pytest.approx(0, abs=1e-12 * c.Delta)      # touching at delta = 0
    assert snaps[1].before.delta == pytest.approx(-2 * c.Delta)                # and at the top, delta = -2 Delta
    sel = (cy.leg == cy.closed_from_leg) | (cy.leg == cy.closed_from_leg + 1)
    P, d = cy.P[sel], cy.delta[sel]
    assert cy.dissipated > 0
    assert cy.dissipated == pytest.approx(np.sum(0.5 * (P[1:] + P[:-1]) * np.diff(d)), rel=1e-4)


def test_cycle_bad_input():
    c = contact(0.3)
    with pytest.raises(ValueError, match="P_min"):
        c.cycle(P_max=-1.0, P_min=1.0)
    with pytest.raises(ValueError, match="P_max"):
        c.cycle(P_min=1.0)
    with pytest.raises(ValueError, match="delta_max"):
        c.cycle(P_max=1.0, P_min=-1.0, control="grip")
    with pytest.raises(ValueError, match="n"):
        c.cycle(P_max=1.0, P_min=-1.0, n=1e7)


def test_cli_cycle_plot_and_csv(tmp_path):
    import csv
    from cli_run import run                    # jkrcyl.cli.main in this process
    png, out = tmp_path / "c.png", tmp_path / "c.csv"
    r = run("cycle", "--E", "2.6e9", "--nu", "0.3", "--E-I", "2.6e9", "--nu-I", "0.3", "--R", "0.01", "--Delta",
            "1e-5", "--w", "0.05", "--P-max", "2000", "--P-min", "-2000", "--plot", png, "--csv", out)
    assert r.returncode == 0, r.stderr
    assert "pull-off" in r.stdout and "J/m" in r.stdout
    assert png.stat().st_size > 1000
    rows = list(csv.reader(open(out)))
    assert rows[1] == ["leg", "branch", "a", "P [N/m]", "delta [m]", "delta_work [m]", "stable"]
    assert {row[6] for row in rows[2:]} <= {"true", "false"}


# --- grip on the work-conjugate approach (issue 10 item 4) --------------------------------------------------
def _dense_work(c, st):
    """delta_work = delta + P/(8 pi G_I) of dense states (DERIVATION.md, 'The work-conjugate approach')."""
    return st.delta + st.P * c.materials.inv_G_I / (8 * np.pi)


@pytest.mark.parametrize("M", [0.05, 0.3])
def test_pull_off_grip_work_is_the_minimum_of_delta_work(M):
    c = contact(M)
    po = c.pull_off("grip-work")
    assert po.detached and po.control == "grip-work"
    a, st = dense_sub_critical(c)
    dw = _dense_work(c, st)
    i = int(np.argmin(dw))
    assert po.delta_work == pytest.approx(dw[i], rel=1e-9)
    assert po.P == pytest.approx(st.P[i], rel=1e-4)
    # a testing machine holding the pin is a grip through the pin's own compliance: it lets go between the
    # paper's rigid grip (delta held) and load control
    assert c.pull_off("load").P < po.P < c.pull_off("grip").P


def test_grip_work_cycle_jumps_and_energy():
    c = contact(0.3)
    cy = c.cycle(delta_max=0.3 * c.Delta, delta_min=-2.3 * c.Delta, control="grip-work")
    po = c.pull_off("grip-work")
    offs = [j for j in cy.jumps if j.kind == "pull-off"]
    assert offs and offs[0].before.delta_work == pytest.approx(po.delta_work, rel=1e-12)
    assert offs[0].after.branch == "separated" and offs[0].after.delta_work == pytest.approx(
        offs[0].before.delta_work, rel=1e-12)
    for j in cy.jumps:                                # every jump at fixed delta_work
        assert j.after.delta_work == pytest.approx(j.before.delta_work, rel=1e-9, abs=1e-12 * c.Delta)
    sel = (cy.leg == cy.closed_from_leg) | (cy.leg == cy.closed_from_leg + 1)
    P, d, dw = cy.P[sel], cy.delta[sel], cy.delta_work[sel]
    assert cy.dissipated > 0
    assert cy.dissipated == pytest.approx(np.sum(0.5 * (P[1:] + P[:-1]) * np.diff(dw)), rel=1e-4)
    assert cy.dissipated == pytest.approx(np.sum(0.5 * (P[1:] + P[:-1]) * np.diff(d)), rel=1e-4)


def test_solve_delta_work_hits_the_request():
    c = contact(0.3)
    target = -0.2 * c.Delta
    states = c.solve(delta_work=target, branches=["sub-critical", "super-critical", "separated"])
    assert states and all(s.control == "grip-work" for s in states)
    for s in states:
        assert s.delta_work == pytest.approx(target, rel=1e-12)
        assert s.delta_work == pytest.approx(s.delta + s.P * c.materials.inv_G_I / (8 * np.pi), rel=1e-12)
        assert s.stable == s.stable_grip_work
    with pytest.raises(ValueError, match="exactly one"):
        c.solve(P=0.0, delta_work=0.0)


def test_a_rigid_cradles_cycle_zips_into_full_contact():
    """A rigid cradle (vartheta = inf) round a compressible pin (nu_I 0: alpha*/beta* -1/2) at M_R* 0.65, grip 0 ..
    -1.95 Delta: the super-critical fold zips the contact round into full contact (it stopped there, 'not modelled':
    full contact needed a finite vartheta).  Reference: the bonded pin of a stiff finite cradle with the same kernel
    constants (vartheta 1e7, M = M_R*/vartheta: model.full_contact at finite vartheta, checked by quadrature in
    tests/test_twopatch.py) at the zip's approach -- its load p = vartheta P* to 1e-6; the zip dissipates."""
    m = jkrcyl.Materials.from_young(E=math.inf, nu=0.0, E_I=3.576e9, nu_I=0.0)
    c0 = jkrcyl.Contact(R=1e-2, Delta=1e-5, w=1.0, materials=m)
    c = jkrcyl.Contact(R=1e-2, Delta=1e-5, w=(0.6537 / c0.M) ** 2, materials=m)
    cy = c.cycle(delta_max=0.0, delta_min=-1.95 * c.Delta, control="grip", n=100)
    zip_, = [j for j in cy.jumps if j.kind == "zip"]
    assert zip_.before.branch == "super-critical" and zip_.after.branch == "full-contact" and cy.note == ""
    pb = c.problem
    stiff = Problem(pb.M / 1e7, 1e7, pb.gb, pb.alpha_ratio)
    ref = full_contact.state(stiff, delta_over_Delta=zip_.after.delta / c.Delta)
    assert zip_.after.P_star == pytest.approx(ref.P_star * 1e7, rel=1e-6)
    assert landing.dissipated(pb, c.units, zip_.before, zip_.after) > 0
