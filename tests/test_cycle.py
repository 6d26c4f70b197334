"""Issue 11 items 2-3: pull-off along the stable path and quasi-static load cycles.

References: the minimum of P (load) or delta (grip) over a dense evaluation of Contact.state (the full-state
kernel, 2 x 10^5 points; the fold is quadratic, so the grid minimum is within ~1e-10 relative); Barquins'
half-plane limit (7.3b) for small M; an independent trapezoid integration of the loop for the energy.
"""
import math

import numpy as np
import pytest

import jkrcyl
from jkrcyl import special

MAT = jkrcyl.Materials(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0)           # vartheta = 1, alpha* = 0


def contact(M, mat=MAT, Delta=0.01, R=1.0):
    c0 = jkrcyl.Contact(R=R, Delta=Delta, w=1.0, materials=mat)
    return jkrcyl.Contact(R=R, Delta=Delta, w=(M / c0.M) ** 2, materials=mat)


def dense_sub_critical(c, n=200000):
    a = c.a_crit * np.tan(np.pi / 4 * np.linspace(1e-7, 1 - 1e-7, n)) if math.isfinite(c.a_crit) else \
        np.tan(np.pi / 2 * np.linspace(1e-7, 0.9, n))
    return a, c.state(a)


@pytest.mark.parametrize("M", [0.05, 0.2, 0.3])
def test_pull_off_load_is_the_minimum_of_a_dense_curve(M):
    c = contact(M)
    po = c.pull_off("load")
    assert po.detached and po.control == "load"
    a, st = dense_sub_critical(c)
    i = int(np.argmin(st.P))
    assert po.P == pytest.approx(st.P[i], rel=1e-9)
    assert po.contact_width == pytest.approx(2 * c.R * 2 * math.atan(a[i]), rel=1e-3)
    assert po.delta == pytest.approx(st.delta[i], rel=1e-4)        # delta is linear in a at the fold
    assert po.state.stable_load or abs(po.state.a - a[i]) < 1e-3 * a[i]     # the fold itself is marginal


@pytest.mark.parametrize("M", [0.05, 0.3])
def test_pull_off_grip_is_the_minimum_of_delta(M):
    c = contact(M)
    po = c.pull_off("grip")
    a, st = dense_sub_critical(c)
    i = int(np.argmin(st.delta))
    assert po.delta == pytest.approx(st.delta[i], rel=1e-9)
    assert po.P == pytest.approx(st.P[i], rel=1e-4)               # P is linear in a there
    assert po.P > c.pull_off("load").P          # fixed grip detaches at a smaller pull (classical JKR)


def test_pull_off_half_plane_limit():
    """Small M: the fixed-load pull-off tends to Barquins' half-plane value -(3/2)(vartheta M^4/2)^(1/3) (7.3b)."""
    c = contact(1e-4)
    P_h = special.half_plane_adherence(c.M, c.theta)[1] * c.load_scale
    assert c.pull_off("load").P == pytest.approx(P_h, rel=1e-3)


def test_pull_off_none_with_reason():
    """M = 0.5, vartheta = 1: the P* minimum is super-critical; a further pull grows the contact (jkrcyl.twopatch)."""
    po = contact(0.5).pull_off("load")
    assert po.P is None and not po and "full contact" in po.reason
    assert po.state is not None and po.state.branch == "super-critical"
    assert contact(0.0).pull_off().P is None
    with pytest.raises(ValueError, match="control"):
        contact(0.3).pull_off("force")


def test_worked_example_units():
    """E = 2.6 GPa, nu = 0.3 for both bodies, R = 10 mm, Delta = 10 um, w = 0.05 J/m^2: pull-off in N/m."""
    m = jkrcyl.Materials.from_young(2.6e9, 0.3, 2.6e9, 0.3)
    c = jkrcyl.Contact(R=0.01, Delta=1e-5, w=0.05, materials=m)
    po = c.pull_off("load")
    a, st = dense_sub_critical(c)
    assert po.P == pytest.approx(st.P.min(), rel=1e-9)
    assert -700 < po.P < -500                   # the half-plane estimate is -575 N/m (M = 0.033)
