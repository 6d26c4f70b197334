"""The arc states of crack kinetics reached two ways agree over random material pairs (rigid bodies included):
the Chebyshev panels (jkrcyl.kinetics.arc.TabulatedArc, the route the integrator uses) and the single-patch
solver itself (DirectArc), values and slopes in log a; and the adhesive part X1 is k_eq times the solver's
fixed-arc derivatives, so the equilibrium is X0 + X1."""
import math

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

import jkrcyl
from jkrcyl.kinetics import arc as karc
from jkrcyl.model.single_patch import solver

moduli = st.one_of(st.just(math.inf), st.floats(1e6, 3e11))
poisson = st.floats(0.0, 0.49).map(lambda v: round(v, 4))


@settings(max_examples=12, deadline=None)
@given(E=moduli, nu=poisson, E_I=moduli, nu_I=poisson, w=st.floats(1e-3, 1.0), Delta=st.floats(1e-7, 1e-4),
       x=st.floats(0.05, 0.9))
def test_tabulated_and_direct_arc_states_agree(E, nu, E_I, nu_I, w, Delta, x):
    if math.isinf(E) and math.isinf(E_I):
        return                                                       # two rigid bodies: no contact mechanics
    m = jkrcyl.Materials.from_young(E=E, nu=nu, E_I=E_I, nu_I=nu_I)
    c = jkrcyl.Contact(R=1e-2, Delta=Delta, w=w, materials=m)
    pb = c.problem
    a_crit = solver(pb).a_crit
    a = x * (min(a_crit, 1.0) if math.isfinite(a_crit) else 1.0)
    u = math.log(a)
    tab = karc.TabulatedArc(pb, u - 0.05, u + 0.05)                  # a panel or two: a cheap window
    direct = karc.DirectArc(pb)
    y, dy = tab.at(u)
    yd, dyd = direct.at(u)
    scale = np.repeat(np.abs(yd[0::2]) + np.abs(yd[1::2]), 2)
    tol = 1e-12 if abs(m.alpha_ratio) < 1e-12 else 1e-8              # collocation: its own noise ~1e-10
    assert np.all(np.abs(y - yd) <= tol * scale)
    dscale = np.repeat(np.abs(dyd[0:6:2]) + np.abs(dyd[1:6:2]), 2)
    assert np.all(np.abs(dy[:6] - dyd[:6]) <= 1e3 * tol * dscale + 1e-300)   # slopes (collocation: differences)
    s = solver(pb).states(np.array([a]))
    for f, (i0, i1) in (("p", (karc.P0, karc.P1)), ("dn", (karc.DN0, karc.DN1)), ("dw", (karc.DW0, karc.DW1))):
        assert abs(yd[i0] + yd[i1] - getattr(s, f)[0]) <= 1e-9 * (abs(yd[i0]) + abs(yd[i1]))


QUASI_STATIC = dict(E=moduli, nu=poisson, E_I=moduli, nu_I=poisson, w=st.floats(1e-3, 1.0),
                    Delta=st.floats(1e-7, 1e-4))


@settings(max_examples=4, deadline=None)
@given(**QUASI_STATIC)
# make fuzz: LSODA stuck at its Adams stability limit (steps of 4e-10 s for ever) where the rates are rounding
# noise on the stiff path of a steel pin in a rigid hole; Radau takes over (jkrcyl.kinetics.integrate.CRAWL_STEPS)
@example(E=math.inf, nu=0.1666, E_I=284547805254.54474, nu_I=0.3892, w=0.3791404002845549,
         Delta=2.451446489831211e-05)
def test_the_quasi_static_limit_is_the_cores_pull_off(E, nu, E_I, nu_I, w, Delta):
    _quasi_static_limit(E, nu, E_I, nu_I, w, Delta)


@pytest.mark.slow                       # the same property over more pairs (~1 s each)
@settings(max_examples=12, deadline=None)
@given(**QUASI_STATIC)
def test_the_quasi_static_limit_is_the_cores_pull_off_more_pairs(E, nu, E_I, nu_I, w, Delta):
    _quasi_static_limit(E, nu, E_I, nu_I, w, Delta)


def _quasi_static_limit(E, nu, E_I, nu_I, w, Delta):
    """Two routes to one pull-off: the load ramped slowly (0.1 |P| per second) against edges that barely lag
    (v* = 1e12 m/s) reaches the largest tension the core's walker finds (Contact.pull_off, quasi-static) to 1e-6,
    and has none where the core has none -- over random pairs, rigid bodies included."""
    if math.isinf(E) and math.isinf(E_I):
        return
    m = jkrcyl.Materials.from_young(E=E, nu=nu, E_I=E_I, nu_I=nu_I)
    c = jkrcyl.Contact(R=1e-2, Delta=Delta, w=w, materials=m, kinetics=jkrcyl.CrackKinetics(v_star=1e12, n=0.6))
    qs = c.pull_off("load")
    po = c.pull_off("load", rate=0.1 * abs(qs.P if qs.P is not None else c.load_scale))
    if qs.P is None:
        assert po.P is None and po.reason
    else:
        assert po.kind in ("separation", "top-contact")
        assert po.P == pytest.approx(qs.P, rel=1e-6)
