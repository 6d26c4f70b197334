"""JKR's two-patch state at the node policy of jkrcyl.numerics.two_arcs against the same state at 200 nodes per arc
(spectral: converged to ~1e-12 there): near-touching arcs need ~sqrt(eps/g) more nodes, g = pi - eps - eps_top.
The earlier policy (8 sqrt(eps/g)) kept the residual small but left the state 7.3e-5 off in eps, 2.4e-4 in P* at
eps_top 0.3633 (g 0.166)."""
import pytest

from jkrcyl.model import two_patch
from jkrcyl.model.problem import Problem
from jkrcyl.numerics import two_arcs


@pytest.mark.parametrize("M, eps_top", [(0.2, 0.3633), (0.2, 0.1), (0.2, 0.01), (0.3, 0.3)])
def test_state_at_the_node_policy_is_converged(M, eps_top, monkeypatch):
    pb = Problem(M, 1.0, 1 / 2.8)
    got = two_patch.solve(pb, eps_top=eps_top)
    monkeypatch.setattr(two_arcs, "nodes", lambda eps, et, n, ar: 200)
    ref = two_patch.solve(pb, eps_top=eps_top, guess=got.eps)
    assert abs(got.eps - ref.eps) < 1e-10 and abs(got.P_star - ref.P_star) < 1e-10
