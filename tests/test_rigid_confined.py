"""Two patches and full contact in a rigid cradle (vartheta = inf), JKR's law.

In the kernel scale (M_R* and P_R* = p of (7.6), n = nu: jkrcyl.model.problem.Problem.scale = 1) both are the
limit of a stiff finite cradle with the same kernel constants (gb, alpha*/beta*; M = M_R*/vartheta, P* = p/vartheta),
whose states are checked elsewhere by quadrature (tests/test_twopatch.py).  Checked here against what the rigid route
does not use: the stiff cradle's states (the difference shrinks as 1/vartheta), the energy identities dU/d(delta) =
P and dU/d eps = 2 pi^2 k^2 = 2 M_R*^2 (G = w, from energy differences alone), and the paper's section 7.2: an
incompressible pin (alpha* = 0) cannot fill the rigid hole (no full contact, refused by name)."""
import math

import pytest

from jkrcyl.model import full_contact, two_patch
from jkrcyl.model.problem import Problem

STIFF = (1e5, 1e7)


def stiff(pb, theta):
    return Problem(pb.M / theta, theta, pb.gb, pb.alpha_ratio)


@pytest.mark.parametrize("gb, ar", [(0.5, -0.5), (0.3, -0.1), (0.9, -0.05)])
def test_full_contact_is_the_stiff_cradles_limit(gb, ar):
    rigid = Problem(0.7, math.inf, gb, ar)
    got = full_contact.state(rigid, P_star=-0.4)
    off = []
    for th in STIFF:
        ref = full_contact.state(stiff(rigid, th), P_star=-0.4 / th)
        off.append(max(abs(got.N0 - th * ref.N0) / abs(got.N0), abs(got.delta_over_Delta - ref.delta_over_Delta)))
    assert off[1] < 1e-6 and off[1] < off[0] / 50          # O(1/vartheta)
    assert got.N0 == pytest.approx(1 / (2 * math.pi * ar), rel=1e-12)        # mode 0: nu0 = 1/(2 pi ar)


def test_an_incompressible_pin_cannot_fill_a_rigid_hole():
    with pytest.raises(ValueError, match="^alpha_ratio: no full contact in a rigid cradle"):
        full_contact.state(Problem(0.7, math.inf, 1.0, 0.0), P_star=0.0)


# (M_R*, gb, ar, eps_top, a guess of eps): near states of jkrcyl.analysis.tracing.branches of each (the last: the
# paper's rubbery cylinder of section 7.2, an incompressible pin, M_R* 2 -- its "gap violations" are two patches)
@pytest.mark.parametrize("M, gb, ar, eps_top, guess", [(0.5, 0.5, 0.0, 0.3, None), (0.65, 0.5, -0.5, 0.0638, 1.6e-3),
                                                        (2.0, 1.0, 0.0, 1.2, 0.95)])
def test_two_patch_states_are_the_stiff_cradles_limit(M, gb, ar, eps_top, guess):
    rigid = Problem(M, math.inf, gb, ar)
    got = two_patch.solve(rigid, eps_top=eps_top, guess=guess)
    off = []
    for th in STIFF:
        ref = two_patch.solve(stiff(rigid, th), eps_top=eps_top, guess=got.eps)
        off.append(max(abs(got.eps - ref.eps), abs(got.P_star - th * ref.P_star),
                       abs(got.delta_over_Delta - ref.delta_over_Delta)))
        assert two_patch.stability(rigid, got.eps, got.eps_top, got.delta_over_Delta) == \
            two_patch.stability(stiff(rigid, th), ref.eps, ref.eps_top, ref.delta_over_Delta)
    assert off[1] < 1e-6 and off[1] < off[0] / 50


def test_energy_release_and_load_from_the_energy_alone():
    """At the rigid state: dU/d eps_i at fixed delta = 2 M_R*^2 (G = w at both edges) and dU/d(delta) = P_R*
    at fixed arcs, central differences of U = [(1 + delta/Delta) P - B]/2 (no edge coefficient used)."""
    rigid = Problem(0.5, math.inf, 0.5, 0.0)
    s = two_patch.solve(rigid, eps_top=0.3)
    U = lambda e, et, d=s.delta_over_Delta: two_patch.fixed_arcs(rigid, e, et, d).energy
    h = 1e-5
    for dU in ((U(s.eps + h, s.eps_top) - U(s.eps - h, s.eps_top)) / (2 * h),
               (U(s.eps, s.eps_top + h) - U(s.eps, s.eps_top - h)) / (2 * h)):
        assert dU / (2 * rigid.M ** 2) == pytest.approx(1, abs=1e-6)
    dUd = (U(s.eps, s.eps_top, s.delta_over_Delta + h) - U(s.eps, s.eps_top, s.delta_over_Delta - h)) / (2 * h)
    assert dUd == pytest.approx(s.P_star, rel=1e-8)
