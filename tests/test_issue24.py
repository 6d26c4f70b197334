"""Regression tests of the audit's reproducers (silent wrong numbers in the cohesive law's seams).

The contact of items 1-4: a rigid pin in a 1 MPa, nu = 0 hole, R 10 mm, Delta 10 um, w 2.0106e-4 J/m^2.  The
reference is JKR's answer for the same contact (the Griffith law: closed forms where alpha* = 0, the collocation
solver here, alpha*/beta* = 1/2), which the cohesive law must approach as lambda grows (the states differ by
O(lambda^-2), jkrcyl.numerics.cohesive)."""
import math
import warnings

import pytest

import jkrcyl

RIGID_PIN = jkrcyl.Materials.from_young(E=1e6, nu=0.0, E_I=math.inf, nu_I=0.3)
ARGS = dict(R=1e-2, Delta=1e-5, w=2.0106e-4, materials=RIGID_PIN)


@pytest.fixture(scope="module")
def jkr():
    return jkrcyl.Contact(**ARGS)


def test_item2_zero_load_contact_is_feasible_at_lambda_12(jkr):
    """Was None ('no stable, feasible state at first contact'): one gap sample next to the contact edge,
    -4.5e-12 m, failed a fixed 1e-9 Delta tolerance; the zero-load state has h(pi) = 1.8 Delta."""
    po = jkrcyl.Contact.with_lambda(**ARGS, lambda_=12).pull_off()
    ref = jkr.pull_off().P
    assert ref == pytest.approx(-1.2565, rel=1e-4)                # the JKR value the audit quotes
    assert po.P == pytest.approx(ref, rel=1e-3)                   # O(lambda^-2) = 7e-3 at most; measured 9e-6


def test_item3_cycle_pulls_off_at_a_pull(jkr):
    """Was a 'pull-off' at P = +0.487 N/m onto the top, 9 points and dissipated None."""
    cy = jkrcyl.Contact.with_lambda(**ARGS, lambda_=10).cycle(P_max=5, P_min=-5, n=300)
    pulls = [j for j in cy.jumps if j.kind == "pull-off"]
    assert pulls and all(j.before.P * (1 if j.before.side == "bottom" else -1) < 0 for j in pulls)
    assert pulls[0].before.P == pytest.approx(jkr.pull_off().P, rel=1e-3)
    assert cy.dissipated is not None and cy.dissipated > 0


def test_item4_solve_finds_the_state_at_a_large_push(jkr):
    """Was [] at P = 100 N/m: the traced branch stopped near 21.6 N/m (the load cap) and nobody said so."""
    c = jkrcyl.Contact.with_lambda(**ARGS, lambda_=10)
    ref, = jkr.solve(P=100.0, branches=["sub-critical"])
    got, = c.solve(P=100.0, branches=["sub-critical"])
    assert got.stable and got.feasible and ref.stable
    assert got.contact_width == pytest.approx(ref.contact_width, rel=1e-2)      # 28.7 mm; O(lambda^-2)
    with pytest.warns(jkrcyl.BranchLimitWarning, match="^P: the sub-critical branch .* traced up to P = "):
        assert c.solve(P=1e5, branches=["sub-critical"]) == []
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        jkr.solve(P=1e5, branches=["sub-critical"])               # the closed-form tables reach a_crit


def test_item7_size_arguments_are_bounded():
    """Was: two_patch(n=10**7) and `jkrcyl atlas --n-M 100000000` ran for minutes."""
    from cli_run import run                    # jkrcyl.cli.main in this process
    c = jkrcyl.Contact(R=1e-2, Delta=1e-6, w=0.05, materials=jkrcyl.Materials.from_young(2.6e9, 0.3, 2.6e9, 0.3))
    with pytest.raises(ValueError, match=r"^n must be in \[4, 100000\], got 10000000"):
        c.two_patch(n=10 ** 7)
    r = run("atlas", "--n-M", "100000000", "--out", "unused")
    assert r.returncode == 2 and r.stderr.strip().count("\n") == 0 and "n-M must be in [2, 10000]" in r.stderr


def test_item7_a_crit_has_one_meaning():
    """Seven entry points once; now jkrcyl.a_crit (= jkrcyl.equilibria.a_crit) and Contact.a_crit, the pair's
    receding contact; the cohesive solver's branch end is a_end.  Reference: the pole of the adhesionless load,
    P -> inf, solved here independently from (4.4)'s denominator 2 vartheta - log(1 + a^2) - 2 a^4 (alpha* = 0)."""
    from scipy.optimize import brentq
    from jkrcyl import equilibria
    ref = brentq(lambda a: 2 * 1.0 - math.log1p(a * a) - 2 * a ** 4, 0.1, 2.0, xtol=1e-15)
    assert jkrcyl.a_crit(1.0) == pytest.approx(ref, rel=1e-13) and equilibria.a_crit is jkrcyl.a_crit
    m = jkrcyl.Materials.from_young(70e9, 0.33, 210e9, 0.3)
    c = jkrcyl.Contact(R=1e-2, Delta=1e-6, w=0.05, materials=m)
    assert c.a_crit == jkrcyl.a_crit(m.theta, m.inv_G_I / m.beta, m.alpha_ratio)
    coh = jkrcyl.Contact(R=1e-2, Delta=1e-6, w=0.05, materials=m, sigma0=5e7)
    from jkrcyl.model.single_patch import solver
    assert solver(coh.problem).a_crit == c.a_crit
    with pytest.raises(ValueError, match="^gb must be given"):
        jkrcyl.a_crit(1.0, alpha_ratio=0.2)


def test_item4_a_cycle_past_the_traced_branch_says_so(jkr):
    """A cycle driven beyond the traced load cap stops with a note naming the table's end (it used to end with
    'no stable state to jump to')."""
    c = jkrcyl.Contact.with_lambda(**ARGS, lambda_=10)
    cy = c.cycle(P_max=1e5, P_min=-5, n=100)
    assert "table ends at P = " in cy.note and "traced up to" in cy.note and cy.dissipated is None
