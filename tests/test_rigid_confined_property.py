"""A number reached two ways: the rigid cradle's confined regime (JKR) against a stiff finite cradle, over random
pins (hypothesis).

The rigid route normalises by pb.scale = 1 (M_R*, P_R* of (7.6)); the stiff cradle (vartheta = 1e7, the same gb and
alpha*/beta*, M = M_R*/vartheta) goes through the finite-vartheta code (M, P* = p/vartheta, 4 vartheta pi^2), checked
by quadrature in tests/test_twopatch.py.  For every two-patch branch the rigid route traces (jkrcyl.analysis.tracing),
its middle state solved again in the stiff cradle at the same top arc agrees to O(1/vartheta), with the same
stability flags; for a compressible pin (alpha* < 0) the bonded pin at any load too.  The fixed cases are in
tests/test_rigid_confined.py; this draws the pin."""
import math

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import jkrcyl
from jkrcyl.analysis import tracing
from jkrcyl.model import full_contact, two_patch
from jkrcyl.model.problem import Problem

THETA = 1e7
SOME = settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@st.composite
def rigid_cradles(draw):
    """A rigid hole round a random pin (E_I 1 MPa .. 100 GPa, nu_I in [0, 0.5]) at M_R* in [0.2, 2.5]."""
    m = jkrcyl.Materials.from_young(math.inf, 0.3, 10 ** draw(st.floats(6, 11)),
                                    draw(st.one_of(st.just(0.0), st.floats(1e-3, 0.5))))
    pb = jkrcyl.Contact(R=1e-2, Delta=1e-5, w=1.0, materials=m).problem
    return Problem(draw(st.floats(0.2, 2.5)), math.inf, pb.gb, pb.alpha_ratio)


def stiff(pb, theta=THETA):
    return Problem(pb.M / theta, theta, pb.gb, pb.alpha_ratio)


@pytest.mark.slow                       # ~15 s: a trace per example
@SOME
@given(rigid_cradles())
def test_two_patch_branches_are_the_stiff_cradles_limit(pb):
    branches = tracing.traced(pb)
    assume(branches)
    for points, _ in branches:
        eps, eps_top = points[len(points) // 2]
        got = two_patch.solve(pb, eps_top=eps_top, guess=eps)
        ref = two_patch.solve(stiff(pb), eps_top=eps_top, guess=got.eps)
        scale = 1 + abs(got.P_star)
        assert abs(got.eps - ref.eps) < 1e-5
        assert abs(got.P_star - THETA * ref.P_star) < 1e-5 * scale
        assert abs(got.delta_over_Delta - ref.delta_over_Delta) < 1e-5 * scale
        assert two_patch.stability(pb, got.eps, got.eps_top, got.delta_over_Delta) == \
            two_patch.stability(stiff(pb), ref.eps, ref.eps_top, ref.delta_over_Delta)


@SOME
@given(rigid_cradles(), st.one_of(st.just(0.0), st.floats(1e-3, 3.0), st.floats(-3.0, -1e-3)))
def test_the_bonded_pin_is_the_stiff_cradles_limit(pb, P):
    assume(pb.alpha_ratio < -1e-3)                       # an incompressible pin cannot fill a rigid hole
    got = full_contact.state(pb, P_star=P)
    off = []
    for th in (THETA, 100 * THETA):       # nu0 = 1/(2 pi alpha*/beta*) + O(1/(vartheta alpha*)): both
        ref = full_contact.state(stiff(pb, th), P_star=P / th)
        off.append(max(abs(got.N0 - th * ref.N0) / abs(got.N0),
                       abs(got.delta_over_Delta - ref.delta_over_Delta) / (1 + abs(got.delta_over_Delta))))
    assert off[1] < 1e-6 and off[1] <= off[0] / 50 + 1e-12
