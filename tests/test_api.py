"""The public API wires the kernels as documented (shapes, broadcasting, normalisations)."""
import math

import numpy as np
import pytest

import jkrcyl
from reference import paper

MAT = jkrcyl.Materials(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0)


def test_state_shapes_follow_a():
    c = jkrcyl.Contact(R=1.0, Delta=0.01, w=1e-4, materials=MAT)
    s = c.state(np.full((2, 3), 0.4))
    assert s.P.shape == (2, 3) and s.delta.shape == (2, 3) and s.feasible.shape == (2, 3)
    scalar = c.state(0.4)
    assert np.ndim(scalar.P) == 0 and float(scalar.P) == float(s.P[1, 2])


def test_normalised_outputs():
    """P* = P beta/(4 pi Delta vartheta), eps* = 2 atan(a/a_crit)/pi (section 6)."""
    c = jkrcyl.Contact(R=2.0, Delta=0.02, w=3e-4, materials=MAT)
    s = c.state(np.array([0.2, 1.3]))
    assert np.allclose(s.P_star, s.P * c.beta / (4 * math.pi * c.Delta * c.theta), rtol=1e-15)
    assert np.allclose(s.eps_star, 2 * np.arctan(s.a / jkrcyl.a_crit(1.0)) / math.pi, rtol=1e-15)
    assert np.allclose(s.delta_over_Delta, s.delta / c.Delta, rtol=1e-15)
    assert np.allclose(s.h_pi_over_Delta, s.h_pi / c.Delta, rtol=1e-15)
    # P*(a; M, vartheta) depends on the physical inputs only through M and vartheta: (4.4)
    ref = [paper.P_44(a, 1.0, 1.0, 1.0, 4 * math.pi * c.M) / (4 * math.pi) for a in s.a]
    assert np.allclose(s.P_star, ref, rtol=1e-12)


def test_rigid_cradle_uses_section_72_normalisation():
    """vartheta = inf: P_star is P_R* = P beta/(4 pi Delta) of (7.6) and M is M_R*."""
    m = jkrcyl.Materials(G=math.inf, kappa=2.0, G_I=1.0, kappa_I=1.0)
    c = jkrcyl.Contact(R=1.0, Delta=0.01, w=1e-4, materials=m)
    a = np.array([0.05, 0.3, 1.0, 3.0])
    M_R = math.sqrt(c.w * c.A * c.R) / (math.sqrt(2) * c.Delta)
    assert c.M == pytest.approx(M_R, rel=1e-14)
    assert np.allclose(c.state(a).P_star, [paper.P_R_star_76(x, M_R) for x in a], rtol=1e-12)


def test_gap_broadcasts_and_vanishes_inside():
    c = jkrcyl.Contact(R=1.0, Delta=0.01, w=1e-4, materials=MAT)
    a = np.array([[0.2], [0.6]])
    phi = np.array([0.0, 0.1, 2.0, math.pi])
    h = c.gap(a, phi)
    assert h.shape == (2, 4)
    eps = 2 * np.arctan(a)
    assert np.all(h[np.abs(phi) < eps] == 0)
    assert np.allclose(h[:, -1], c.state(a[:, 0]).h_pi, rtol=1e-13)
    assert np.all(c.state(a[:, 0]).feasible == (c.state(a[:, 0]).h_pi >= 0))


def test_pressure_parts_sum_to_load():
    """R int N cos(phi) dphi = P by a fine midpoint rule on the bounded part plus the exact
    integral of the unbounded part (its weight int cos/s is A.11-like; here only a sanity check)."""
    c = jkrcyl.Contact(R=1.0, Delta=0.01, w=0.0, materials=MAT)     # w = 0: pressure is bounded
    a = 0.5
    eps = 2 * math.atan(a)
    n = 200000
    phi = (np.arange(n) + 0.5) / n * 2 * eps - eps
    nb, nu = c.pressure(a, phi, parts=True)
    assert np.all(nu == 0)
    P = c.R * np.sum(nb * np.cos(phi)) * (2 * eps / n)
    assert P == pytest.approx(float(c.state(a).P), rel=1e-6)


def test_long_inputs_use_the_parallel_kernel_bit_identically():
    """Contact.state switches to full_state_parallel at PARALLEL_MIN points; results do not change."""
    from jkrcyl import contact as contact_module
    c = jkrcyl.Contact(R=1.0, Delta=0.01, w=1e-4, materials=MAT)
    a = np.geomspace(1e-6, 1e3, contact_module.PARALLEL_MIN + 7)
    long = c.state(a)
    short = [c.state(a[i:i + 5000]) for i in range(0, a.size, 5000)]
    for name in ("P", "B", "C", "delta", "h_pi", "K"):
        assert np.array_equal(getattr(long, name), np.concatenate([getattr(s, name) for s in short])), name
