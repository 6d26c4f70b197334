"""Issue 10 item 4: the work-conjugate approach delta_work = delta + P/(8 pi G_I) (derive/green.py).

Independent of its derivation: the displacement work-conjugate to the load of a linear elastic contact has a
positive load-approach stiffness without adhesion (the elastic energy is positive definite), while the paper's
delta (the rims' approach, load at the pin's centre) does not in Fig. 7 (rigid cradle, nu_I = 1/2).  The
relation delta_work - delta = P/(8 pi G_I) is typed here from DERIVATION.md as the reference of the fields.
"""
import math

import numpy as np
import pytest

import jkrcyl
from jkrcyl import equilibria as eq
from jkrcyl.numerics import kernels as _k

INF = math.inf


def _stiffness_signs(M, theta, gb, ar=0.0, n=400):
    cv = eq.curve(M, theta, n=n, gb=gb, alpha_ratio=ar)
    return np.sign(cv.dP_star_da * cv.ddelta_work_da), np.sign(cv.dP_star_da * cv.ddelta_da)


def test_fig7_rigid_cradle_conjugate_stiffness_is_positive():
    """Rigid cradle, incompressible pin (kappa_I = 1): gb = (1/G_I)/beta* = 1.  The paper's delta turns back
    (negative stiffness, the Fig. 7 erratum); delta_work rises with the load all the way."""
    work, paper = _stiffness_signs(0.0, INF, 1.0, n=2000)
    assert np.all(work > 0)
    assert np.any(paper < 0)


@pytest.mark.parametrize("theta, gb", [(0.5, 1.0), (1.0, 0.5), (3.0, 0.2), (INF, 0.75)])
def test_adhesionless_conjugate_stiffness_is_positive(theta, gb):
    work, _ = _stiffness_signs(0.0, theta, gb)
    assert np.all(work > 0)


def test_adhesionless_conjugate_stiffness_is_positive_for_alpha_pairs():
    for ar in (0.1167, -0.1167, 0.375):
        work, _ = _stiffness_signs(0.0, 1.0 if ar < 0 else 0.6, 0.3, ar=ar, n=60)
        assert np.all(work > 0), ar


@pytest.mark.parametrize("alpha", [False, True])
def test_fields_carry_the_shift(alpha):
    m = (jkrcyl.Materials.from_young(E=70e9, nu=0.33, E_I=210e9, nu_I=0.3) if alpha
         else jkrcyl.Materials.from_young(E=2e9, nu=0.4, E_I=2e9, nu_I=0.4))
    c = jkrcyl.Contact(R=1e-2, Delta=1e-5, w=0.05, materials=m)
    s = c.state(np.array([0.2, 0.6]))
    shift = s.P * m.inv_G_I / (8 * math.pi)
    np.testing.assert_allclose(s.delta_work, s.delta + shift, rtol=1e-14, atol=1e-14 * c.Delta)
    cv = c.curve(n=50)
    np.testing.assert_allclose(cv.delta_work, cv.delta + cv.P * m.inv_G_I / (8 * math.pi), rtol=1e-12,
                               atol=1e-12 * c.Delta)
    for e in c.solve(P=0.0, branches=["sub-critical", "super-critical"]):
        assert e.delta_work == pytest.approx(e.delta + e.P * m.inv_G_I / (8 * math.pi), rel=1e-14, abs=1e-20)


@pytest.mark.parametrize("M, theta, gb", [(0.3, 1.0, 0.5), (0.5, 1.0, 0.5), (0.2, 0.5, 1.0), (0.4, 3.0, 0.2),
                                         (0.3, INF, 1.0), (1e-9, 5.0, 0.3)])
def test_stable_grip_work_is_the_load_rule_with_delta_work(M, theta, gb):
    """The chain-rule release rate at fixed delta_work has the sign of the load rule applied to delta_work
    (dG/dp|_a < 0 below a_crit, > 0 above, proved in derive/derivatives.py; the conjugate fixed-arc compliance
    d(delta_work/Delta)/dp = d(delta/Delta)/dp + gb/2 > 0, checked here) -- over tiny to large contacts."""
    inv_t = 0.0 if math.isinf(theta) else 1 / theta
    m = M if math.isinf(theta) else M * theta
    for regime in (("sub-critical",) if math.isinf(theta) else ("sub-critical", "super-critical")):
        ac = 1.0 if math.isinf(theta) else eq.a_crit(theta, gb)    # vartheta = inf: 0 < a < 0.97 checked
        lo, hi = (1e-12, 0.97 * min(ac, 1e3)) if regime == "sub-critical" else (1.03 * ac, 1e3)
        a = np.geomspace(lo, hi, 400)
        s = _k.star_m(a, inv_theta=inv_t, m=m, gb=gb)
        assert np.all(s.ddelta_dp + gb / 2 > 0)
        assert np.all(np.sign(s.dG_dp) == (-1 if regime == "sub-critical" else 1))
        cv = eq.curve(M, theta, regime=regime, gb=gb, a=a)
        rule = (1 if regime == "sub-critical" else -1) * cv.ddelta_work_da > 0
        assert np.array_equal(cv.stable_grip_work, rule)
        assert np.all(np.isfinite(cv.dG_da_P) & np.isfinite(cv.dG_da_delta) & np.isfinite(cv.dG_da_delta_work))


def test_stable_grip_work_lies_between_grip_and_load():
    """Holding delta_work is the paper's grip through a spring of compliance 1/(8 pi G_I) >= 0: wherever an
    equilibrium is stable under the paper's fixed grip and under fixed load, it is stable under delta_work too
    (and unstable where both are unstable)."""
    for M, th in ((0.3, 1.0), (0.5, 1.0), (0.2, 0.5)):
        for regime in ("sub-critical", "super-critical"):
            cv = eq.curve(M, th, regime=regime, n=800, gb=0.5)
            both = cv.stable_grip & cv.stable_load
            neither = ~cv.stable_grip & ~cv.stable_load
            assert np.all(cv.stable_grip_work[both]) and not np.any(cv.stable_grip_work[neither])


@pytest.mark.parametrize("M, theta, gb", [(0.3, 1.0, 0.5), (0.5, 1.0, 0.5), (0.2, 0.5, 1.0), (0.6, 0.6, 1.0)])
def test_hessian_stability_of_one_arc_matches_the_release_rates(M, theta, gb):
    """jkrcyl.model.two_patch.stability (second variation of the energy with the pin's n = 1 term, finite differences of
    the collocation solution) with no top arc against Curve.stable_load / stable_grip / stable_grip_work (closed
    form, chain rule): two routes that share no code for all three controls."""
    from jkrcyl.model import two_patch
    pb = eq.problem(M, theta, gb)
    for regime in ("sub-critical", "super-critical"):
        cv = eq.curve(M, theta, regime=regime, n=40, gb=gb)
        for i in range(1, 40, 4):
            got = two_patch.stability(pb, float(cv.eps[i]), 0.0, float(cv.delta_over_Delta[i]))
            assert got == (cv.stable_load[i], cv.stable_grip[i], cv.stable_grip_work[i]), (regime, cv.a[i])
