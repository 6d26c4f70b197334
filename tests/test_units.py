"""One units object (jkrcyl.units): its factors against the paper's definitions typed here, its conversions
inverse to each other, and every physical answer of a Contact equal to its normalised one times those factors
(two routes: a Curve made physical by Units and the forward solve at the same held value)."""
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import jkrcyl
from jkrcyl.units import CONTROLS, CURVE_FIELD, Units, control_of_physical

modulus = st.one_of(st.floats(5.0, 12.0).map(lambda u: 10.0 ** u), st.just(math.inf))
poisson = st.floats(0.0, 0.49)


def paper_factors(E, nu, E_I, nu_I, Delta):
    """(P/P*, p/P*) from section 2 and 4 as printed: beta* = (kappa + 1)/2G + (kappa_I + 1)/2G_I, vartheta =
    1/2 + G (kappa_I + 1)/(2 G_I (1 + kappa)), P* = P beta*/(4 pi Delta vartheta) (4 pi Delta/beta* for a rigid
    cradle, (7.6)); plane strain kappa = 3 - 4 nu, G = E/(2 (1 + nu))."""
    G, G_I = E / (2 * (1 + nu)), E_I / (2 * (1 + nu_I))
    k, k_I = 3 - 4 * nu, 3 - 4 * nu_I
    beta = (k + 1) / (2 * G) + (k_I + 1) / (2 * G_I)
    theta = math.inf if math.isinf(G) else 0.5 + G * (k_I + 1) / (2 * G_I * (1 + k))
    kernel = 1.0 if math.isinf(theta) else theta
    return 4 * math.pi * Delta * kernel / beta, kernel


@settings(max_examples=40, deadline=None)
@given(E=modulus, nu=poisson, E_I=modulus, nu_I=poisson, Delta=st.floats(1e-9, 1e-4))
def test_factors_are_the_papers(E, nu, E_I, nu_I, Delta):
    if math.isinf(E) and math.isinf(E_I):
        return                                                     # two rigid bodies: no contact to make
    c = jkrcyl.Contact(R=1e-2, Delta=Delta, w=0.05, materials=jkrcyl.Materials.from_young(E, nu, E_I, nu_I))
    load, kernel = paper_factors(E, nu, E_I, nu_I, Delta)
    u = c.units
    assert u.load_scale == pytest.approx(load, rel=1e-12) and u.kernel == pytest.approx(kernel, rel=1e-12)
    assert u.Delta == Delta and u.R == 1e-2
    for name in CONTROLS:                                          # each conversion undoes its inverse
        assert u.normalise(name, u.physical(name, 0.37)) == pytest.approx(0.37, rel=1e-15)
        assert u.to_kernel(name, u.from_kernel(name, -1.9)) == pytest.approx(-1.9, rel=1e-15)
    assert u.per_kernel("load") * kernel == pytest.approx(load, rel=1e-15)


def test_every_name_of_a_control_is_one_field():
    """The names a Control carries exist on the results and the solver's Slice, and nothing else maps to them."""
    from jkrcyl.model.patch import FIELDS
    from jkrcyl.results import Curve, Equilibrium
    eq_fields, curve_fields = set(Equilibrium.__dataclass_fields__), set(Curve.__dataclass_fields__)
    for c in CONTROLS.values():
        assert {c.physical, c.normalised, c.stable} <= eq_fields
        assert {c.physical, c.normalised, c.slope, c.stable} <= curve_fields
        assert {c.field, c.field_slope} <= set(FIELDS)
        assert control_of_physical(c.physical) is c
        assert CURVE_FIELD[c.field] == (c.normalised, c.name == "load")
    with pytest.raises(KeyError):
        control_of_physical("h_pi")


@pytest.mark.parametrize("E_I", [2.6e9, math.inf])
def test_curve_with_units_is_the_forward_solve(E_I):
    """Route 1: a branch made physical by the contact's Units (Curve.with_units); route 2: Contact.solve at each
    point's held value (the solver's own conversion of a physical target).  The same states, to 1e-9."""
    m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=E_I, nu_I=0.3)
    c = jkrcyl.Contact(R=1e-2, Delta=1e-6, w=0.05, materials=m)
    cv = c.curve(n=9)
    for i in (2, 5, 7):
        for ctl in CONTROLS.values():
            held = float(getattr(cv, ctl.physical)[i])
            got = [s for s in c.solve(**{ctl.physical: held}, branches=["sub-critical"])
                   if abs(s.a - cv.a[i]) <= 1e-6 * cv.a[i]]
            assert len(got) == 1, (ctl.name, i)
            s = got[0]
            assert s.P == pytest.approx(cv.P[i], rel=1e-9) and s.delta == pytest.approx(cv.delta[i], rel=1e-9)
            assert s.stable_load == cv.stable_load[i] and s.held(ctl.name) == pytest.approx(held, rel=1e-10)


def test_normalised_units_leave_normalised_values():
    """Units.normalised: a 'physical' answer is the normalised one (what jkrcyl.equilibria works in)."""
    pb = jkrcyl.equilibria.problem(0.3, 1.0, 1 / 2.8)
    u = Units.normalised(pb)
    assert u.physical("load", -0.25) == -0.25 and u.physical("grip", 0.5) == 0.5
    assert u.to_kernel("load", 2.0) == pytest.approx(2.0 * pb.scale)
    cv = jkrcyl.equilibria.curve(0.3, 1.0, n=5, gb=1 / 2.8).with_units(u)
    np.testing.assert_array_equal(cv.P, cv.P_star)
    np.testing.assert_array_equal(cv.delta_work, cv.delta_work_over_Delta)


def test_units_need_a_clearance():
    c = jkrcyl.Contact(R=1e-2, Delta=0.0, w=0.05, materials=jkrcyl.Materials.from_young(2.6e9, 0.3, 2.6e9, 0.3))
    with pytest.raises(ValueError, match="units"):
        c.units


@pytest.mark.parametrize("E_I", [2.6e9, math.inf])
def test_adherence_point_is_the_state_solved_at_its_approach(E_I):
    """Contact.adherence (a fold of P, built in the contact's units) against Contact.solve at the point's approach
    (a regular root there): the same state -- P, width, stability flags, energy -- to 1e-9."""
    m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=E_I, nu_I=0.3)
    c = jkrcyl.Contact(R=1e-2, Delta=1e-6, w=0.05, materials=m)
    pt, = c.adherence()
    s, = [x for x in c.solve(delta=pt.delta, branches=[pt.branch]) if abs(x.a - pt.a) <= 1e-6 * pt.a]
    assert isinstance(pt, jkrcyl.results.Equilibrium) and pt.kind == "min"
    assert s.P == pytest.approx(pt.P, rel=1e-9) and s.contact_width == pytest.approx(pt.contact_width, rel=1e-9)
    assert s.energy == pytest.approx(pt.energy, rel=1e-9)
    assert (s.stable_grip, s.stable_grip_work, s.feasible) == (pt.stable_grip, pt.stable_grip_work, pt.feasible)
    assert pt.P == pytest.approx(c.units.physical("load", pt.P_star), rel=1e-15)
