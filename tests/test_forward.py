"""Issue 11 item 1: Contact.solve(P=...) / solve(delta=...) on every branch.

References: the printed load (4.4) typed by hand in jkrcyl.paper (P_44) and the rubbery (7.6); a dense
evaluation of Contact.state (the full-state kernel, not the slope kernel the solver brackets with) for the
count of states per branch; the mirror symmetry phi -> phi + pi for the top branches.
"""
import math

import numpy as np
import pytest
from cli_run import run

import jkrcyl
from jkrcyl.analysis import forward
from reference import paper

MAT = jkrcyl.Materials(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0)           # vartheta = 1, alpha* = 0
SINGLE = [b for b in forward.BRANCH_SOLVERS if b not in ("two-patch", "full-contact", "separated")]


def contact(M, theta_mat=MAT, Delta=0.01, R=1.0):
    """The Contact with normalised adhesion M (w from M = sqrt(w A R)/(sqrt(2) Delta vartheta))."""
    c0 = jkrcyl.Contact(R=R, Delta=Delta, w=1.0, materials=theta_mat)
    return jkrcyl.Contact(R=R, Delta=Delta, w=(M / c0.M) ** 2, materials=theta_mat)


def dense_crossings(c, regime, P):
    """Number of sign changes of P(a) - P on a dense grid of one branch (Contact.state, 10^5 points)."""
    ac = c.a_crit
    s = np.linspace(1e-6, 1 - 1e-6, 100000)
    a = ac * np.tan(np.pi / 2 * (s / 2 if regime == "sub-critical" else 0.5 + s / 2))
    a = np.concatenate([np.geomspace(1e-12, a[0], 2000, endpoint=False), a]) if regime == "sub-critical" else a
    v = c.state(a).P - P
    return int(np.sum(np.sign(v[:-1]) * np.sign(v[1:]) < 0))


@pytest.mark.parametrize("M", [0.05, 0.3, 0.5, 0.8])
@pytest.mark.parametrize("P_star", [-0.4, -0.1, 0.0, 0.3, 2.0])
def test_solve_load_hits_the_request(M, P_star):
    c = contact(M)
    P = P_star * c.load_scale
    states = c.solve(P=P, branches=SINGLE)
    for s in states:
        # the state's own P (full-state kernel) and the hand-typed (4.4) both equal the request
        assert abs(s.P - P) <= 1e-12 * c.load_scale
        sign = -1 if s.side == "top" else 1
        printed = paper.P_44(s.a, c.Delta, c.beta, c.theta, c.zeta) * sign
        assert printed == pytest.approx(P, rel=1e-11, abs=1e-11 * c.load_scale)
        assert s.control == "load" and s.stable == s.stable_load
        assert s.contact_width == pytest.approx(2 * c.R * 2 * math.atan(s.a), rel=1e-15)
    for regime in ("sub-critical", "super-critical"):
        found = [s for s in states if s.branch == regime]
        assert len(found) == dense_crossings(c, regime, P)
        mirrored = [s for s in states if s.branch == regime + "-top"]
        assert len(mirrored) == dense_crossings(c, regime, -P)
    assert [s.size for s in states] == sorted(s.size for s in states)


def test_stability_follows_the_slope_of_the_printed_load():
    """Fixed load: stable where dP/da > 0 sub-critically and dP/da < 0 super-critically (section 9)."""
    c = contact(0.3)
    for P_star in (-0.2, 0.0, 0.5):
        for s in c.solve(P=P_star * c.load_scale, branches=["sub-critical", "super-critical"]):
            h = 1e-6 * s.a
            slope = (paper.P_44(s.a + h, c.Delta, c.beta, c.theta, c.zeta)
                     - paper.P_44(s.a - h, c.Delta, c.beta, c.theta, c.zeta)) / (2 * h)
            assert s.stable_load == ((slope > 0) == (s.branch == "sub-critical"))


@pytest.mark.parametrize("d", [-0.08, -0.03, 0.0, 0.05, 0.5])
def test_solve_approach_hits_the_request(d):
    c = contact(0.3)
    states = c.solve(delta=d * c.Delta, branches=SINGLE + ["separated"])
    assert states, "at least one state expected"
    for s in states:
        assert s.control == "grip"
        assert abs(s.delta - d * c.Delta) <= 1e-12 * c.Delta
        if s.branch != "separated":
            st = c.state(s.a)
            ref = -2 * c.Delta - float(st.delta) if s.side == "top" else float(st.delta)
            assert ref == pytest.approx(s.delta, abs=1e-12 * c.Delta)
    sep = [s for s in states if s.branch == "separated"]
    assert len(sep) == (1 if -2 < d < 0 else 0)
    if sep:
        assert sep[0].P == 0 and sep[0].h_pi == pytest.approx((2 + d) * c.Delta) and sep[0].stable


def test_rubbery_cradle_against_76():
    m = jkrcyl.Materials(G=math.inf, kappa=2.0, G_I=1.0, kappa_I=1.0)
    c = contact(0.4, m)
    for P_star in (-0.2, 0.0, 5.0, 1e4):            # 1e4: a > 3, beyond the curve grid of jkrcyl.equilibria
        states = c.solve(P=P_star * c.load_scale, branches=["sub-critical"])
        assert states
        for s in states:
            assert paper.P_R_star_76(s.a, c.M) == pytest.approx(P_star, rel=1e-11, abs=1e-12)


def test_tiny_adhesion_zero_load_root():
    """M = 1e-9: the zero-load contact a0 ~ (2 vartheta M)^(2/3) (8.1) is found below the eps* grid."""
    c = contact(1e-9)
    states = c.solve(P=0.0, branches=["sub-critical"])
    a0 = jkrcyl.zero_load_contact(c.M, c.theta)[0]
    assert any(s.a == pytest.approx(a0, rel=1e-9) for s in states)


def test_mirror_branches():
    c = contact(0.3)
    P = -0.2 * c.load_scale
    top = [s for s in c.solve(P=P, branches=["sub-critical-top"])]
    bottom = c.solve(P=-P, branches=["sub-critical"])
    assert [s.a for s in top] == [s.a for s in bottom]
    for t, b in zip(top, bottom):
        assert t.P == -b.P and t.delta == pytest.approx(-2 * c.Delta - b.delta, abs=1e-15)
        assert t.side == "top" and t.stable_load == b.stable_load


def test_confined_branches_two_patch_and_full_contact():
    """M = 0.4, vartheta = 1 (confined): two-patch states at the request, Griffith at both ends (G = w)."""
    c = contact(0.4)
    assert forward.confined(c.problem)
    P = -1.0 * c.load_scale
    states = c.solve(P=P)
    tp = [s for s in states if s.branch == "two-patch"]
    assert tp, "the branch at M = 0.4 spans P* = -1"
    for s in tp:
        assert abs(s.P - P) <= 1e-9 * c.load_scale
        assert s.extra["G_bot"] == pytest.approx(1, abs=1e-8) and s.extra["G_top"] == pytest.approx(1, abs=1e-8)
        assert 0 < s.eps < math.pi and 0 < s.eps_top < math.pi and s.side == "both"
    full = [s for s in states if s.branch == "full-contact"]
    assert len(full) == 1 and full[0].stable and full[0].contact_width == pytest.approx(2 * math.pi * c.R)


def test_registry_and_bad_requests():
    c = contact(0.3)
    assert list(forward.BRANCH_SOLVERS)[:2] == ["sub-critical", "super-critical"]
    with pytest.raises(ValueError, match="P"):
        c.solve()
    with pytest.raises(ValueError, match="P"):
        c.solve(P=1.0, delta=1.0)
    with pytest.raises(ValueError, match="branches"):
        c.solve(P=1.0, branches=["nope"])
    with pytest.raises(ValueError, match="P"):
        c.solve(P=math.nan)
    with pytest.raises(ValueError, match="Delta"):
        jkrcyl.Contact(R=1.0, Delta=0.0, w=1e-4, materials=MAT).solve(P=1.0)


def test_alpha_nonzero_solve():
    """A rigid pin in a compressible hole (alpha* != 0): states from the collocation solver hit the request."""
    m = jkrcyl.Materials.from_young(2.6e9, 0.3, math.inf, 0.3)
    c = jkrcyl.Contact(R=0.01, Delta=1e-5, w=0.05, materials=m)
    assert not m.closed_form
    P = -300.0
    states = c.solve(P=P, branches=["sub-critical"])
    assert len(states) == 2                        # the unstable small contact and the stable one
    for s in states:
        assert abs(s.P - P) <= 1e-10 * c.load_scale
    assert [s.stable_load for s in states] == [False, True]


def test_cli_solve_physical_columns():
    r = run("solve", "--E", "2.6e9", "--nu", "0.3", "--E-I", "2.6e9", "--nu-I", "0.3", "--R", "0.01", "--Delta",
            "1e-5", "--w", "0.05", "--P", "-500", "--no-two-patch")      # jkrcyl.cli.main in this process
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    head = lines[1].split(",")
    assert "P [N/m]" in head and "delta [m]" in head and "contact_width [m]" in head
    rows = [dict(zip(head, x.split(","))) for x in lines[2:]]
    assert all(float(row["P [N/m]"]) == pytest.approx(-500, rel=1e-9) for row in rows)
    assert {row["stable"] for row in rows} <= {"true", "false"}


# --- item 4: dimensional curves, adherence points and pressure ----------------------------------------------
def test_curve_and_adherence_carry_physical_units():
    c = contact(0.3)
    cv = c.curve(n=50)
    assert np.allclose(cv.P, c.state(cv.a).P, rtol=1e-12)
    assert np.allclose(cv.delta, c.state(cv.a).delta, rtol=1e-12, atol=1e-15 * c.Delta)
    assert {"P", "delta"} <= set(cv.table())
    assert repr(cv).startswith("Curve(sub-critical") and len(repr(cv)) < 120
    (p,) = c.adherence("load")
    assert p.P == pytest.approx(float(c.state(p.a).P), rel=1e-12)
    assert p.delta == pytest.approx(float(c.state(p.a).delta), rel=1e-12)


def test_pressure_total_sign_wrap_and_arrays():
    c = contact(0.3)
    a = np.array([[0.3], [0.6]])
    phi = np.array([-0.4, 0.0, 0.2, 2.5])
    N = c.pressure(a, phi)
    nb, nu = c.pressure(a, phi, parts=True)
    assert N.shape == (2, 4) and np.array_equal(N, nb + nu)
    assert np.allclose(c.pressure(a, phi + 2 * math.pi), N, rtol=1e-12, atol=0)   # wrapped like the gap
    assert np.array_equal(c.pressure(a, -phi), c.pressure(a, phi))      # even in phi
    assert np.all(N[:, 3] == 0)                                          # outside the contact
    for i, ai in enumerate(a[:, 0]):
        assert np.array_equal(c.pressure(ai, phi), N[i])
    # sign: compressive positive, R int N cos(phi) dphi = P (4.4); phi = eps sin(t) removes the edge singularity
    for ai in (0.3, 0.6):
        eps = 2 * math.atan(ai)
        t, wts = np.polynomial.legendre.leggauss(200)
        t = 0.5 * math.pi * t
        ph = eps * np.sin(t)
        P = c.R * np.sum(0.5 * math.pi * wts * c.pressure(ai, ph) * np.cos(ph) * eps * np.cos(t))
        assert P == pytest.approx(float(c.state(ai).P), rel=1e-6)
