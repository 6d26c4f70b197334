"""The Maugis-Dugdale law's own two-patch branch (jkrcyl.numerics.cohesive_two_own: seeded at the top's closing, the
two-arc state with a top arc of 1e-4, and continued by its own pseudo-arclength; the route of Contact.two_patch
where JKR's branch is no scaffold: thick zones, lambda < ~8 at M = 0.2, or JKR's arcs thinner than the zones).

Checked against what the own route does not use:

* the law at every state (G/w = h(zone end)/h0 = 1, the gap >= 0) and the mirror symmetry (P* -> -P*,
  delta -> -2 - delta: the two ends are traced, not mirrored);
* states solved alone at a held top arc, from a guess off the branch (cohesive_two_branch.solve_at: no
  continuation, no neighbour);
* the energy: dE = p d(delta) along the branch (Richardson on states solved alone, tests/cases.py);
* the stability matrix against cohesive_two_stability.zone_matrix (held states by Newton);
* the scaffold route (cohesive_two_branch.trace along JKR's branch) where both work: the same states;
* JKR's states (jkrcyl.model.two_patch, no zones) as lambda grows: lambda^2 (eps - eps_JKR) a constant;
* where the law has no two-patch state (M = 0.5, lambda = 20): the axis states, continued down in lambda, fold
  (at lambda 27.6) and the branch there is two loops that shrink towards it -- () is physical, not a refusal.
"""
import math

import numpy as np
import pytest

import jkrcyl
import jkrcyl.numerics.arcs
from jkrcyl.analysis import tracing
from jkrcyl.analysis.two_patch_family import family
from jkrcyl.model import two_patch as tp
from jkrcyl.numerics import cohesive_two as ct
from jkrcyl.numerics import cohesive_two_branch as cb
from jkrcyl.numerics import cohesive_two_own as own
from jkrcyl.numerics import cohesive_two_stability as cs
from cases import two_patch_dE_ddelta

EQ = jkrcyl.equilibria
THETA, GB = 1.0, 1 / 2.8                      # identical bodies, nu = 0.3


def fam_at(M, lam):
    return family(EQ.problem(M, THETA, GB, s0=EQ.zone_strength(lam, M, THETA)))


def own_branches(fam):
    """The own route's branches (numerics states) from JKR's branch ends, at the family's node count."""
    b, = tracing.branches(fam.jkr, 12)
    with cb.one_blas_thread():
        return own.branches(fam.law, np.column_stack([b.eps, b.eps_top]), b.ends, fam.n)


@pytest.fixture(scope="module")
def lam5():
    """M = 0.2, lambda = 5 (Dugdale zone 0.055 rad: the scaffold is refused, the own route traces)."""
    fam = fam_at(0.2, 5.0)
    b, = fam.branches()
    return fam, b


def test_the_seed_is_the_top_bridges_closing_state():
    """M 0.1, vartheta 10, gb 1/2.8, lambda 50 (tests/test_cohesive_top_zone.py's case): the top bridge's two
    families close (h(pi) = 0) at eps 0.0048 and 1.12 (jkrcyl.numerics.cohesive_top_zone: one contact, a zone at
    the top, another solver); the own route's seed there (two arcs, the top one held) tends to it as the top arc
    shrinks -- delta/Delta off by 2.3e-3 / 1.6e-3 at 1e-4, 3.8e-5 / 2.7e-5 at 1e-5 (measured): the law's two-patch
    family starts at the top's closing."""
    from jkrcyl.numerics import cohesive_top_zone as tz
    m, s0 = 1.0, EQ.zone_strength(50.0, 0.1, 10.0)
    law = cb.BranchLaw(m, s0, jkrcyl.numerics.arcs.Kernel(10.0, GB), layered=True)
    onsets = [f.onset for f in tz.families(m, s0, 10.0, GB, ratio=3.0)]
    assert len(onsets) == 2
    for o in onsets:
        off = [abs(own.seed(law, 1, o.eps, 71, arc=a).delta_over_Delta - o.delta_over_Delta) for a in (1e-4, 1e-5)]
        assert off[1] < 1e-4 and off[1] < off[0] / 30


def test_at_lambda_5_the_law_holds_along_the_own_branch(lam5):
    """Ends single -> mirror (both traced to a top/bottom arc of 1e-4), G/w = 1 at every zone end, the gap >= 0,
    and the traced mirror end is the mirror of the seed: P* -> -P*, delta -> -2 - delta (to 1e-8)."""
    fam, b = lam5
    assert cb.ZONE_MAX < 0.05 < fam.law.h0 and b.ends == ("single", "mirror") and len(b.eps) > 20
    assert np.max(np.abs(b.G_bot - 1)) < 1e-9 and np.max(np.abs(b.G_top - 1)) < 1e-9 and b.feasible.all()
    assert abs(b.P_star[0] + b.P_star[-1]) < 1e-8 and abs(b.delta_over_Delta[0] + b.delta_over_Delta[-1] + 2) < 1e-8
    assert abs(b.eps[0] - b.eps_top[-1]) < 1e-8


def test_states_solved_alone_lie_on_the_own_branch(lam5):
    """Three interior states: solved alone at the traced top arc from a bottom arc 2 % off (held-arc Newton, zones
    from Dugdale's estimate): equal to the traced ones to 1e-9."""
    fam, b = lam5
    for i in (5, len(b.eps) // 2, len(b.eps) - 8):
        s = fam.at(1, float(b.eps_top[i]), 1.02 * float(b.eps[i]), fam.n)
        assert abs(s.eps - b.eps[i]) < 1e-9 and abs(s.P_star - b.P_star[i]) < 1e-9
        assert abs(s.delta_over_Delta - b.delta_over_Delta[i]) < 1e-9


@pytest.mark.parametrize("x, h", [(0.3, 1e-3), (0.02, 1e-4)])        # near these top arcs
def test_energy_changes_by_p_d_delta_along_the_own_branch(lam5, x, h):
    """dE/d(delta) by Richardson on states solved alone at the top arc x +- h, +- 2h: p to 1e-8 (kernel scale),
    where the raw quotient is 10 x further off (the check can fail)."""
    fam, b = lam5
    i = int(np.argmin(np.abs(b.eps_top[: len(b.eps) // 2] - x)))     # the branch's first pass near x: its state
    x = float(b.eps_top[i])
    s = fam.at(1, x, float(b.eps[i]), fam.n)
    extrapolated, d1 = two_patch_dE_ddelta(fam, s, x, h)
    assert abs(extrapolated - s.P_star * THETA) < 1e-8 and abs(d1 - s.P_star * THETA) > 10 * abs(
        extrapolated - s.P_star * THETA)


@pytest.mark.slow
def test_stability_matrix_is_the_held_states_one_on_the_own_branch(lam5):
    """G from one Jacobian against cohesive_two_stability.zone_matrix (held states by Newton): 1e-4 relative under
    load and grip, the flags equal (none stable: JKR's branch at M = 0.2 has none either)."""
    fam, b = lam5
    assert not (b.stable_load.any() or b.stable_grip.any())
    for i in (6, len(b.eps) // 2):
        st = fam.at(1, float(b.eps_top[i]), float(b.eps[i]), fam.n)._lin
        J = cs.jacobian(fam.law, st)
        for control, (a, c) in (("load", (0.0, 1.0)), ("grip", (1.0, 0.0))):
            held = cs.zone_matrix(ct._Law(st.m, st.s0, fam.law.kernel, layered=True), st, control)
            assert np.max(np.abs(cs.implicit_zone_matrix(J, a, c) - held)) < 1e-4 * np.max(np.abs(held))
            assert cs.stable(fam.law, st, control, G=held) == cs.flags(J, fam.pb.work_shift)[
                ("load", "grip").index(control)]


def _on_own_branch(fam, states, eps_top, eps_near):
    """The own branch's state at the top arc eps_top (the pass nearest eps_near): the own corrector on the
    hyperplane log eps_top = const from the own states' log-interpolation (no scaffold data)."""
    y = np.array([own._y(s) for s in states])
    x = math.log(eps_top)
    at = lambda i: (x - y[i, 1]) / (y[i + 1, 1] - y[i, 1])          # the chord's parameter at eps_top
    k = min((i for i in range(len(y) - 1) if (y[i, 1] - x) * (y[i + 1, 1] - x) <= 0),
            key=lambda i: abs(math.exp((1 - at(i)) * y[i, 0] + at(i) * y[i + 1, 0]) - eps_near))
    t = at(k)
    with cb.one_blas_thread():
        return own.correct(fam.law, (1 - t) * y[k] + t * y[k + 1], np.eye(4)[1], fam.n)[0]


@pytest.mark.slow
@pytest.mark.parametrize("lam", [20.0, 50.0])
def test_the_own_branch_passes_through_the_scaffolds_states(lam):
    """A number reached two ways: at M = 0.2, lambda 20 / 50 Contact.two_patch follows JKR's branch (the scaffold);
    the own branch (seeded at the top's closing, its own arclength) passes through each interior scaffold state:
    eps to 2e-9, P* (kernel scale) and delta to 5e-9 -- measured 9e-10 / 2.9e-9 at the near-touching top arc
    0.298, lambda 20, where the scaffold's state is that far from a solve to 1e-14 (Newton's tolerance there; the
    own state is 1e-13 from it), elsewhere 1e-10 or less."""
    fam = fam_at(0.2, lam)
    b, = fam.branches()
    (t,) = own_branches(fam)
    assert t.ends == ("single", "mirror")
    for i in range(2, len(b.eps) - 2):
        s = _on_own_branch(fam, t.states, float(b.eps_top[i]), float(b.eps[i]))
        assert abs(s.eps - b.eps[i]) < 2e-9 and abs(s.p / THETA - b.P_star[i]) < 5e-9
        assert abs(s.delta_over_Delta - b.delta_over_Delta[i]) < 5e-9


@pytest.mark.slow
def test_the_own_branch_tends_to_jkrs_as_lambda_squared():
    """M = 0.2, the top arc 0.3633 (near touching): lambda^2 (eps - eps_JKR) at lambda 50 / 100 on the own branch,
    JKR's state at 96 nodes per arc (model.two_patch, no zones): a constant, -1.767 / -1.761 as the scaffold's
    (measured; within 1 % of each other: second order)."""
    et, out = 0.36330064433257114, []
    ref = tp.solve(EQ.problem(0.2, THETA, GB), eps_top=et, guess=2.6123, n=96)
    for lam in (50.0, 100.0):
        fam = fam_at(0.2, lam)
        (t,) = own_branches(fam)
        out.append(lam ** 2 * (_on_own_branch(fam, t.states, et, ref.eps).eps - ref.eps))
    assert -1.8 < out[0] < -1.7 and abs(out[1] / out[0] - 1) < 0.01


@pytest.mark.slow
@pytest.mark.parametrize("M, above, below, fold, guess", [(0.5, 30.0, 20.0, "2(7|8)", 1.2366),
                                                          (0.2, 3.7, 3.0, "3.5", 1.9086)])
def test_no_two_patch_state_below_the_fold_of_the_axis_states_in_lambda(M, above, below, fold, guess):
    """M = 0.5, lambda = 20: JKR's branch has top arcs <= 0.0034, thinner than the 0.0063 zones; M = 0.2, lambda = 3:
    zones ~0.15 rad.  The law's: above (lambda 30, 3.7) two loops (single -> single and its mirror); the axis state
    continued down from larger lambda folds (Folded) at lambda 27.6 / 3.556 -- so the loops shrink to nothing there
    and two_patch() is () below (guess: JKR's single end's bottom arc): physical, not a refusal."""
    loops = own_branches(fam_at(M, above))
    assert sorted(t.ends for t in loops) == [("mirror", "mirror"), ("single", "single")]
    assert max(max(s.eps_top for s in t.states) for t in loops if t.ends[0] == "single") < 0.05
    with pytest.raises(own.Folded, match=f"below lambda = {fold}"):
        own.seed(fam_at(M, below).law, 1, guess, 64)
    assert fam_at(M, below).branches() == ()
