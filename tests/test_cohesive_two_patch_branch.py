"""The Maugis-Dugdale law's two-patch branches through the API (jkrcyl.analysis.cohesive_two_patch, traced by
jkrcyl.numerics.cohesive_two_branch): equilibria.two_patch / two_patch_state with s0, Contact.two_patch and
solve(branches=['two-patch']).

Checked against what the trace does not use:

* JKR's two-patch states (jkrcyl.model.two_patch: Griffith k = M/pi at both edges, no zone; the limit
  lambda -> inf) at the same held half-angle: P* and delta/Delta within C/lambda^2, C measured at two lambdas;
* the energy: along the branch the total potential (cohesive_two.potential: elastic + Dugdale interface energy by
  quadrature of the opening) changes by p d(delta), Richardson on states solved alone at +-h, +-2h;
* a traced state solved alone, cold from JKR's state (cohesive_two.solve's route: no neighbour, no reused LU);
* the stability matrix G (the Hessian of the zone-end-held energy over 2 s0) against
  jkrcyl.numerics.cohesive_two_stability's, made of held states solved by Newton (an independent route);
* the law at every state: G/w = h(zone end)/h0 = 1 and the gap >= 0 outside the arcs.
"""
import math

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as hst

import jkrcyl
from jkrcyl.analysis.cohesive_two_patch import land_two_patch
from jkrcyl.analysis.two_patch_family import family
from jkrcyl.model import two_patch as tp
from jkrcyl.numerics import cohesive_two as ct
from jkrcyl.numerics import cohesive_two_branch as cb
from jkrcyl.numerics import cohesive_two_stability as cs
from cases import two_patch_dE_ddelta

EQ = jkrcyl.equilibria
THETA, GB = 1.0, 1 / 2.8                      # identical bodies, nu = 0.3


def s0_of(lam, M):
    return EQ.zone_strength(lam, M, THETA)


def problem(M, lam):
    return EQ.problem(M, THETA, GB, s0=s0_of(lam, M))


def jkr_at(M, e, et):
    """JKR's two-patch state with the larger of (e, et) held (tests/ reference: model.two_patch's secant on F), at
    JKR_NODES per arc: its default count is too few at large near-touching arcs (M = 0.2, eps_top 0.3633: 31
    nodes, 7e-5 off in eps; tests/test_cohesive_two_layer.py), which once passed for a faster-than-lambda^-2 P*."""
    jkr = EQ.problem(M, THETA, GB)
    return (tp.solve(jkr, eps_top=et, guess=e, n=JKR_NODES) if et < e else
            tp.solve(jkr, eps=e, guess=et, n=JKR_NODES))


JKR_NODES = 96


@pytest.fixture(scope="module")
def branch20():
    """M = 0.2, lambda = 20: the family and its one branch (single -> mirror)."""
    fam = family(problem(0.2, 20.0))
    b, = fam.branches()
    return fam, b


# --- bad input: a ValueError naming the parameter ---------------------------------------------------------------
@pytest.mark.parametrize("kw, name", [
    (dict(alpha_ratio=0.1), "^alpha_ratio"), (dict(lam=2e4), "^sigma0"), (dict(lam=2000.0), "^sigma0 is too large for the two-arc"), (dict(n=2), "^n ")])
def test_bad_input_names_the_parameter(kw, name):
    lam = kw.pop("lam", 20.0)
    args = dict(theta=THETA, n=None, alpha_ratio=0.0)
    args.update(kw)
    with pytest.raises(ValueError, match=name):
        EQ.two_patch(0.2, args["theta"], args["n"], gb=GB, alpha_ratio=args["alpha_ratio"], s0=s0_of(lam, 0.2))


def test_a_state_needs_exactly_one_half_angle():
    with pytest.raises(ValueError, match="^eps_top"):
        EQ.two_patch_state(0.2, THETA, gb=GB, eps=1.0, eps_top=0.3, s0=s0_of(20.0, 0.2))


@pytest.mark.slow
def test_at_lambda_3_the_confined_classification_follows_the_laws_own_branch():
    """confined_events follows the law's branches (tests/test_cohesive_top_landing.py): at lambda = 3 (zones not
    small: JKR's branch is no scaffold) the law's own branch (jkrcyl.numerics.cohesive_two_own, seeded at the top's
    closing) from the single patch to its mirror; solve without branches returns no two-patch state (as before),
    with branches=['two-patch'] it searches them."""
    m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    c = jkrcyl.Contact.with_lambda(R=10e-3, Delta=1e-6, w=0.05, materials=m, lambda_=3.0)
    b, = c.confined_events().branches
    # G/w = 1 to Newton's floor (cohesive_two_branch.RESIDUAL_FLOOR: measured 4e-9 at one state, 1e-11 elsewhere)
    assert b.ends == ("single", "mirror") and np.max(np.abs(b.G_top - 1)) < 1e-8 and b.feasible.all()
    assert c.problem.models("two-patch-branches") and not c.problem.models("two-patch")


# --- the traced branch ------------------------------------------------------------------------------------------
@pytest.mark.slow
def test_the_law_holds_along_the_branch(branch20):
    """G/w = h(c)/h0 = 1 at both zone ends (the Newton tolerance), the gap >= 0, the ends JKR's (the top arc down
    to 1e-4 rad at 'single', its mirror at 'mirror'), the mirror symmetry P* -> -P*, delta -> -2 - delta."""
    fam, b = branch20
    assert b.ends == ("single", "mirror") and len(b.eps) >= 12
    assert np.max(np.abs(b.G_bot - 1)) < 1e-9 and np.max(np.abs(b.G_top - 1)) < 1e-9
    assert b.feasible.all() and np.all(b.gap_min > 0)
    assert min(b.eps_top[0], b.eps[-1]) <= cb.END_ARC
    assert abs(b.P_star[0] + b.P_star[-1]) < 1e-7 and abs(b.delta_over_Delta[0] + b.delta_over_Delta[-1] + 2) < 1e-7


@pytest.mark.slow
def test_a_traced_state_solved_alone_is_the_traced_one(branch20):
    """Three interior states: two_patch_state at the traced top arc, cold from JKR's state there (no neighbour,
    no reused factorisation), equals the traced state to 1e-9."""
    fam, b = branch20
    for i in (3, len(b.eps) // 2, len(b.eps) - 4):
        s = EQ.two_patch_state(0.2, THETA, gb=GB, eps_top=float(b.eps_top[i]), guess=float(b.eps[i]),
                               s0=fam.pb.edge.s0)
        assert abs(s.eps - b.eps[i]) < 1e-9 and abs(s.P_star - b.P_star[i]) < 1e-9
        assert abs(s.delta_over_Delta - b.delta_over_Delta[i]) < 1e-9


@pytest.mark.slow
@pytest.mark.parametrize("x, h", [(0.3, 1e-3), (0.0625, 2e-4)])
def test_energy_changes_by_p_d_delta_along_the_branch(branch20, x, h):
    """dE/d(delta) along the branch by quotients of states solved alone at the top arc x +- h, x +- 2h (the same
    node count), Richardson's extrapolation: p to 1e-8 (kernel scale; measured 4e-10, 2e-11), where the raw
    quotient is 4e-6, 4e-8 off (the check can fail)."""
    fam, _ = branch20
    s = fam.at(1, x, jkr_at(0.2, 2.6, x).eps, fam.n)
    p = s.P_star * THETA
    extrapolated, d1 = two_patch_dE_ddelta(fam, s, x, h)
    assert abs(extrapolated - p) < 1e-8 and abs(d1 - p) > 10 * abs(extrapolated - p)


@pytest.mark.slow
def test_stability_matrix_is_the_held_states_one(branch20):
    """G = dg/dc at the held control (Schur complement of one Jacobian) against cohesive_two_stability.zone_matrix
    (held states by Newton, central differences): 1e-4 relative under load and grip; the flags equal, and JKR's
    (jkrcyl.model.two_patch.stability: no stable two-patch state at M = 0.2, vartheta = 1)."""
    fam, b = branch20
    assert not (b.stable_load.any() or b.stable_grip.any())
    for i in (3, len(b.eps) // 2):
        s = EQ.two_patch_state(0.2, THETA, gb=GB, eps_top=float(b.eps_top[i]), guess=float(b.eps[i]),
                               s0=fam.pb.edge.s0)
        st = s._lin
        J = cs.jacobian(fam.law, st)
        for control, (a, c) in (("load", (0.0, 1.0)), ("grip", (1.0, 0.0))):
            mine = cs.implicit_zone_matrix(J, a, c)
            held = cs.zone_matrix(ct._Law(st.m, st.s0, fam.law.kernel, layered=True), st, control)
            assert np.max(np.abs(mine - held)) < 1e-4 * np.max(np.abs(held))
            assert cs.stable(fam.law, st, control, G=held) == cs.flags(J, fam.pb.work_shift)[("load", "grip").index(
                control)]


@pytest.mark.slow
def test_solve_by_name_finds_the_branch_states(branch20):
    """solve(P*, branches=['two-patch']) named by the user (by_name): each state at the asked P*, G = w at its
    edges, one between the bracketing traced states (its top arc); the walker's search (every branch listed, not
    by name) finds no two-patch state under this law."""
    fam, b = branch20
    from jkrcyl.analysis import forward
    from jkrcyl.units import Units
    target = 0.5 * (b.P_star[3] + b.P_star[4])
    un = Units.normalised(fam.pb, K_edge=1.0)
    got = forward.solve_normalised(fam.pb, un, "load", target, ["two-patch"], by_name=True)
    assert got and all(s.branch == "two-patch" for s in got)
    walker = forward.solve_normalised(fam.pb, un, "load", target, list(forward.BRANCH_SOLVERS))
    assert all(s.branch != "two-patch" for s in walker)
    for s in got:
        assert abs(s.P_star - target) < 1e-10 and abs(s.extra["G_bot"] - 1) < 1e-9
    lo, hi = sorted(b.eps_top[3:5])
    assert any(lo <= s.eps_top <= hi for s in got)
    landed = land_two_patch(fam.pb, "load", target)                  # the walker's call: the same states
    assert sorted(s.eps_top for s, _ in landed) == pytest.approx(sorted(s.eps_top for s in got), abs=1e-12)
    assert all(f == (s.stable_load, s.stable_grip, s.stable_grip_work) for (_, f), s in
               zip(sorted(landed, key=lambda sf: sf[0].eps_top), sorted(got, key=lambda s: s.eps_top)))


# --- the JKR limit ----------------------------------------------------------------------------------------------
# (top arc, JKR's bottom arc roughly: the guess) of M = 0.3's branch with both arcs >= 0.6
TOPS = ((0.6355, 2.1418), (0.9391, 1.8419), (1.2410, 1.5403))


def _limit_errors(M, lam):
    """lambda^2 |x - x_JKR| for x = eps, P*, delta/Delta of the law's states at the top arcs TOPS (solved alone:
    equal to the traced ones, test above), JKR's at the same top arcs."""
    fam = family(problem(M, lam))
    out = []
    for et, guess in TOPS:
        r = jkr_at(M, guess, et)
        s = fam.state(eps_top=et, guess=r.eps)
        out.append([abs(s.eps - r.eps), abs(s.P_star - r.P_star), abs(s.delta_over_Delta - r.delta_over_Delta)])
    return np.max(out, axis=0) * lam ** 2


@pytest.mark.slow
def test_jkr_limit_at_lambda_50_and_100():
    """M = 0.3: the law's bottom arc, P* and delta/Delta at the same top arc equal JKR's within C/lambda^2,
    measured max over the three arcs at lambda = 50, 100: C_eps = 2.396, 2.392, C_P = 0.1009, 0.1009, C_delta =
    0.0742, 0.0741 -- second order, the same C (against JKR at 24-31 nodes per arc C_P read 0.091, 0.060)."""
    c50, c100 = _limit_errors(0.3, 50.0), _limit_errors(0.3, 100.0)
    assert np.all(c50 < [2.5, 0.12, 0.08]) and np.all(c100 < [2.5, 0.12, 0.08])
    assert np.all(np.abs(c100 / c50 - 1) < 0.01)
    assert np.all(c50 > [2.0, 0.05, 0.05])               # a finite zone: not JKR's states themselves


# --- the physical API -------------------------------------------------------------------------------------------
@pytest.mark.slow
def test_contact_two_patch_and_solve_by_name():
    """A Contact at M = 0.3, lambda = 20 (identical nu = 0.3 bodies): Contact.two_patch is the normalised branch
    in N/m (P = P* times the load scale), and Contact.solve(P, branches=['two-patch']) finds states at that P
    (P* of each equal to the asked one, G = w), and pull-off-style solves without branches find none (not
    searched)."""
    m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    probe = jkrcyl.Contact(1e-2, 1e-6, 1.0, m)
    c = jkrcyl.Contact.with_lambda(1e-2, 1e-6, (0.3 / probe.M) ** 2, m, 20.0)
    b, = c.two_patch()
    ref, = EQ.two_patch(c.M, c.materials.theta, gb=c.problem.gb, s0=c.problem.edge.s0)
    assert np.allclose(b.P, ref.P_star * c.load_scale, rtol=1e-12, atol=0)
    P = float(0.5 * (b.P[4] + b.P[5]))
    got = c.solve(P=P, branches=["two-patch"])
    assert got and all(abs(s.P / P - 1) < 1e-9 and abs(s.extra["G_top"] - 1) < 1e-9 for s in got)
    assert all(s.branch != "two-patch" for s in c.solve(P=P))


@given(hst.lists(hst.floats(-10, 10), min_size=4, max_size=4))
def test_positive_definite_in_closed_form_is_the_eigenvalues(entries):
    """The flags' 2 x 2 test (first entry and determinant of the symmetric part) against LAPACK's eigenvalues."""
    G = np.array(entries).reshape(2, 2)
    ev = np.linalg.eigvalsh(0.5 * (G + G.T))
    assume(np.min(np.abs(ev)) > 1e-9 * max(1.0, np.max(np.abs(ev))))     # off the boundary (rounding decides there)
    assert cs.positive_definite(G) == bool(np.all(ev > 0))
