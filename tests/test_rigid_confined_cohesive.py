"""The Maugis-Dugdale law's two patches in a rigid cradle (vartheta = inf; jkrcyl.analysis.cohesive_two_patch).

In the kernel scale (m = M_R*, p = P_R* of (7.6), s0 = sigma0 R beta*/(4 pi Delta): none of them carries vartheta)
the rigid cradle is the limit of a stiff finite cradle with the same gb, alpha*/beta*, s0 and M = M_R*/vartheta,
P* = p/vartheta, whose states tests/test_cohesive_two_patch.py checks by quadrature.  Checked here against what the
rigid route does not use: the stiff cradles' states (the difference shrinks as 1/vartheta), the energy along the
rigid branch (the total potential changes by p d(delta), central differences of states solved alone), and JKR's
rigid two-patch state as lambda grows (C/lambda^2)."""
import math

import numpy as np
import pytest

from jkrcyl.analysis.cohesive_two_patch import CohesiveTwoPatch
from jkrcyl.laws import DugdaleEdge
from jkrcyl.model import two_patch
from jkrcyl.model.problem import Problem
from jkrcyl.numerics.cohesive_scales import zone_strength
from jkrcyl.numerics.roots import sign_changes

STIFF = (1e5, 1e7)


def rigid(M, gb, lam):
    return Problem(M, math.inf, gb, 0.0, edge=DugdaleEdge(zone_strength(lam, M)))


def stiff(pb, theta):
    return Problem(pb.M / theta, theta, pb.gb, pb.alpha_ratio, edge=pb.edge)


# (M_R*, gb, lambda, eps_top): the two cases of tests/test_rigid_confined.py with alpha* = 0 (the law's two arcs need
# it): a loop branch (M_R* 0.5) and the paper's rubbery cylinder of section 7.2 (an incompressible pin, M_R* 2)
@pytest.mark.parametrize("M, gb, lam, eps_top", [(0.5, 0.5, 5.0, 0.3), (2.0, 1.0, 5.0, 1.2)])
def test_states_are_the_stiff_cradles_limit(M, gb, lam, eps_top):
    """Measured: 6.6e-6 / 6.6e-8 (M_R* 0.5) and 4.3e-5 / 4.3e-7 (M_R* 2) at vartheta 1e5 / 1e7."""
    pb = rigid(M, gb, lam)
    family = CohesiveTwoPatch(pb)
    got = family.state(eps_top=eps_top)
    assert got.G_bot == pytest.approx(1, abs=1e-9) and got.G_top == pytest.approx(1, abs=1e-9)   # h = h0 at both
    off = []
    for th in STIFF:
        near = CohesiveTwoPatch(stiff(pb, th))
        ref = near.at(1, eps_top, got.eps, family.n)     # the rigid state's nodes: only vartheta differs
        off.append(max(abs(got.eps - ref.eps), abs(got.P_star - th * ref.P_star),
                       abs(got.delta_over_Delta - ref.delta_over_Delta)))
        assert family.flags(got) == near.flags(ref)
    assert off[1] < 2e-6 and off[1] < off[0] / 50          # O(1/vartheta)


def test_energy_changes_by_p_d_delta_along_the_rigid_branch():
    """(E(+h) - E(-h))/(delta(+h) - delta(-h)) of states at eps_top +- h solved alone tends to p as h^2;
    Richardson's extrapolation of h = 1e-3, 3e-4 is p to 1e-8 (the potential: elastic + Dugdale interface
    energy, by quadrature of the opening over the zones -- no edge condition used)."""
    family = CohesiveTwoPatch(rigid(0.5, 0.5, 5.0))
    s = family.state(eps_top=0.3)
    rates = []
    for h in (1e-3, 3e-4):
        plus, minus = (family.state(eps_top=0.3 + sign * h, guess=s.eps) for sign in (1, -1))
        rates.append((family.potential(plus) - family.potential(minus))
                     / (plus.delta_over_Delta - minus.delta_over_Delta))
    r = (1e-3 / 3e-4) ** 2
    assert abs(rates[0] - s.P_star) > 1e-7                  # the quotient converges: it is not p itself
    assert abs((r * rates[1] - rates[0]) / (r - 1) - s.P_star) < 1e-8


def test_jkr_limit_in_a_rigid_cradle():
    """At a fixed top arc the law's state tends to JKR's rigid two-patch state (jkrcyl.model.two_patch, Griffith
    edges) as C/lambda^2: within 2e-3 in P_R* at lambda = 50, lambda^2 dP constant to 10 % between 20 and 50
    (measured: lambda^2 dP = 1.2213, 1.2244, 1.2253 at lambda = 10, 20, 50; dP 4.9e-4 at 50)."""
    ref = two_patch.solve(Problem(0.5, math.inf, 0.5, 0.0), eps_top=0.3, n=96)
    scaled = []
    for lam in (20.0, 50.0):
        got = CohesiveTwoPatch(rigid(0.5, 0.5, lam)).state(eps_top=0.3)
        scaled.append(lam ** 2 * abs(got.P_star - ref.P_star))
    assert scaled[1] / 50 ** 2 < 2e-3 and scaled[1] / 50 ** 2 > 1e-8     # a finite zone: not JKR's state itself
    assert abs(scaled[1] / scaled[0] - 1) < 0.1


@pytest.mark.filterwarnings("error::jkrcyl.notices.BranchLimitWarning")
def test_every_sign_change_along_the_rigid_loop_gives_its_state():
    """The law's loop branch (M_R* 0.5, lambda 20): a state at each sign change of P* and delta/Delta along it, at
    the target (two of 14 were dropped: the search started cold at a bracket's end with a top arc of 0.0091)."""
    family = CohesiveTwoPatch(rigid(0.5, 0.5, 20.0))
    b, = family.branches()
    assert b.ends == ("loop", "loop")
    for key in ("P_star", "delta_over_Delta"):
        values = np.asarray(getattr(b, key))
        for target in np.linspace(values.min(), values.max(), 5)[1:-1]:
            got = family.states_at(key, target)
            assert len(got) == len(sign_changes(values - target))
            assert all(getattr(s, key) == pytest.approx(target, abs=1e-9) for s in got)
