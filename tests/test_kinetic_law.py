"""The crack-kinetics law (jkrcyl.laws.Kinetic): its speed is the inverse of the law as written (Gent and
Schultz; Maugis and Barquins), its options (a user phi, the WLF and Arrhenius shifts) are the textbook formulas,
at rest every quasi-static answer of a contact with it is JKR's bit for bit, and bad input is refused in the name
of the parameter."""
import math

import numpy as np
import pytest

import jkrcyl
from jkrcyl.laws.kinetic import X_CLOSE, X_REST, Kinetic, arrhenius_shift, wlf_shift

PAIRS = {"identical": jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3),
         "steel-in-aluminium": jkrcyl.Materials.from_young(E=70e9, nu=0.33, E_I=210e9, nu_I=0.3)}
W = {"identical": 0.05, "steel-in-aluminium": 0.1}


def pair(name, law=None):
    return jkrcyl.Contact(R=1e-2, Delta=1e-6, w=W[name], materials=PAIRS[name], law=law)


@pytest.mark.parametrize("n", [0.1, 0.6, 1.0, 1.7, 2.0])
@pytest.mark.parametrize("v", [1e-9, 3e-7, 1e-6, 0.02, 5.0])
def test_speed_inverts_the_law(n, v):
    """G/w = 1 + (v/v*)^n opening and 1/(1 + (v/v*)^n) closing, typed here from the law's definition."""
    law = Kinetic(v_star=1e-6, n=n)
    opening, closing = 1 + (v / 1e-6) ** n, 1 / (1 + (v / 1e-6) ** n)
    if opening - 1 > 1e3 * X_REST:                 # outside the smoothing at rest (n > 1)
        assert law.speed(opening) == pytest.approx(v, rel=1e-12)
    if opening - 1 > 1e3 * X_REST and closing > X_CLOSE:   # (below X_CLOSE: continued linearly)
        assert law.speed(closing) == pytest.approx(-v, rel=1e-9)
    assert law.edge_release(v) == pytest.approx(opening, rel=1e-15)
    assert law.edge_release(-v) == pytest.approx(closing, rel=1e-15)


def test_speed_at_rest_and_its_sign():
    for n in (0.5, 1.0, 1.5):
        law = Kinetic(1e-3, n)
        assert law.speed(1.0) == 0.0
        xs = np.linspace(0.5, 1.5, 101)
        v = np.array([law.speed(x) for x in xs])
        assert np.all(np.diff(v) > 0) and np.all(np.sign(v) == np.sign(xs - 1))    # (G - w) v >= 0
        # the slope is the derivative (central difference, away from the smoothing band)
        for x in (0.7, 1.3):
            h = 1e-6
            assert law.speed_slope(x) == pytest.approx((law.speed(x + h) - law.speed(x - h)) / (2 * h), rel=1e-6)


def test_closing_edge_without_tension_is_fast_and_finite():
    law = Kinetic(1e-6, 0.6)
    assert law.speed(1e-3) < law.speed(1e-2) < 0
    assert math.isfinite(law.speed(-1.0)) and law.speed(-1.0) < law.speed(1e-5)


def test_user_phi_and_shift():
    """A user phi equal to the power law gives its speeds; the shift a_T multiplies the speed inside phi."""
    power = Kinetic(2e-6, 0.7)
    user = Kinetic(2e-6, 0.7, phi=lambda v: (v / 2e-6) ** 0.7)
    for x in (0.3, 0.9, 1.2, 4.0):
        assert user.speed(x) == pytest.approx(power.speed(x), rel=1e-10)
    shifted = Kinetic(2e-6, 0.7, shift=100.0)
    assert shifted.speed(3.0) == pytest.approx(power.speed(3.0) / 100, rel=1e-13)
    assert Kinetic(2e-6, 0.7, phi=lambda v: (v / 2e-6) ** 0.7, shift=100.0).speed(3.0) == \
        pytest.approx(shifted.speed(3.0), rel=1e-10)


def test_a_user_phi_equal_to_the_power_law_gives_its_pull_off():
    m = PAIRS["identical"]
    power = jkrcyl.Contact(R=1e-2, Delta=1e-6, w=0.05, materials=m, kinetics=Kinetic(1e-3, 0.6))
    user = jkrcyl.Contact(R=1e-2, Delta=1e-6, w=0.05, materials=m,
                          kinetics=Kinetic(1e-3, 0.6, phi=lambda v: (v / 1e-3) ** 0.6))
    a, b = power.pull_off(rate=300.0), user.pull_off(rate=300.0)
    assert a.kind == b.kind and a.P == pytest.approx(b.P, rel=1e-8)


def test_shift_factors_are_the_textbook_formulas():
    # WLF: log10 a_T = -C1 (T - Tr)/(C2 + T - Tr); universal constants 17.44, 51.6 at Tr = Tg
    assert wlf_shift(-50.0, -70.0, 17.44, 51.6) == pytest.approx(10 ** (-17.44 * 20 / 71.6), rel=1e-14)
    assert wlf_shift(25.0, 25.0) == 1.0
    # Arrhenius: a_T = exp(Ea/R (1/T - 1/Tr)), R = 8.314462618 J/(mol K) (CODATA)
    assert arrhenius_shift(300.0, 350.0, 80e3) == pytest.approx(math.exp(80e3 / 8.314462618 * (1 / 300 - 1 / 350)))
    with pytest.raises(ValueError, match="T must be"):
        wlf_shift(-200.0, 0.0)


@pytest.mark.parametrize("kw, name", [(dict(v_star=0.0, n=0.5), "v_star"), (dict(v_star=-1.0, n=0.5), "v_star"),
                                      (dict(v_star=math.nan, n=0.5), "v_star"), (dict(v_star="1", n=0.5), "v_star"),
                                      (dict(v_star=1.0, n=0.0), "n"), (dict(v_star=1.0, n=2.5), "n"),
                                      (dict(v_star=1.0, n=math.inf), "n"), (dict(v_star=1.0, n=0.5, shift=0), "shift"),
                                      (dict(v_star=1.0, n=0.5, phi=3.0), "phi"),
                                      (dict(v_star=1.0, n=0.5, phi=lambda v: -v), "phi"),
                                      (dict(v_star=1.0, n=0.5, phi=lambda v: 1 + v), "phi")])
def test_bad_law_parameters_name_themselves(kw, name):
    with pytest.raises(ValueError, match=name):
        Kinetic(**kw)


@pytest.mark.parametrize("name", PAIRS)
def test_at_rest_every_quasi_static_answer_is_jkr_bit_for_bit(name):
    kin, jkr = pair(name, jkrcyl.CrackKinetics(v_star=1e-6, n=0.6)), pair(name)
    assert kin.problem == jkr.problem and kin.M == jkr.M
    for control in ("load", "grip", "grip-work"):
        a, b = kin.pull_off(control), jkr.pull_off(control)
        assert (a.P, a.contact_width, a.delta, a.delta_work) == (b.P, b.contact_width, b.delta, b.delta_work)
    P = 0.5 * jkr.pull_off().P
    for x, y in zip(kin.solve(P=P, branches=["sub-critical", "super-critical"]),
                    jkr.solve(P=P, branches=["sub-critical", "super-critical"])):
        assert (x.eps, x.P, x.delta_work, x.energy, x.stable) == (y.eps, y.P, y.delta_work, y.energy, y.stable)
    sa, sb = kin.state([0.01, 0.3]), jkr.state([0.01, 0.3])
    assert np.array_equal(sa.P, sb.P) and np.array_equal(sa.G_release, sb.G_release)


def test_quasi_static_cycle_is_jkr_bit_for_bit():
    kin, jkr = pair("identical", jkrcyl.CrackKinetics(1e-6, 0.6)), pair("identical")
    po = jkr.pull_off().P
    a, b = (c.cycle(P_max=-1.5 * po, P_min=1.5 * po, n=200) for c in (kin, jkr))
    assert a.dissipated == b.dissipated and np.array_equal(a.P, b.P) and len(a.jumps) == len(b.jumps) >= 1


def test_kinetics_shorthand_is_the_law():
    law = jkrcyl.CrackKinetics(v_star=1e-6, n=0.6)
    a = pair("identical", law)
    b = jkrcyl.Contact(R=1e-2, Delta=1e-6, w=0.05, materials=PAIRS["identical"], kinetics=law)
    assert a == b and hash(a) == hash(b) and b.law == law and b.kinetics == law and a.kinetics == law
    assert pair("identical").kinetics is None
    assert jkrcyl.CrackKinetics(1e-6, 0.6) == jkrcyl.laws.Kinetic(1e-6, 0.6) == Kinetic(v_star=1e-6, n=0.6)


@pytest.mark.parametrize("kw, name", [(dict(kinetics=3.0), "kinetics"),
                                      (dict(kinetics=jkrcyl.CrackKinetics(1, 1), sigma0=1e6), "kinetics"),
                                      (dict(kinetics=jkrcyl.CrackKinetics(1, 1), law=jkrcyl.laws.Griffith()),
                                       "kinetics")])
def test_bad_kinetics_argument(kw, name):
    with pytest.raises(ValueError, match=name):
        jkrcyl.Contact(R=1e-2, Delta=1e-6, w=0.05, materials=PAIRS["identical"], **kw)


@pytest.mark.parametrize("rate", [0.0, -1.0, math.nan, math.inf, "fast", None])
def test_bad_rate_names_itself(rate):
    c = pair("identical", jkrcyl.CrackKinetics(1e-6, 0.6))
    with pytest.raises(ValueError, match="rate"):
        c.pull_off(rate=rate) if rate is not None else c.cycle(P_max=1.0, P_min=-1.0, rate=-2.0)


def test_rate_without_kinetics_is_refused_in_its_name():
    c = pair("identical")
    with pytest.raises(ValueError, match="rate: .*crack kinetics"):
        c.pull_off(rate=1.0)
    with pytest.raises(ValueError, match="t: .*crack kinetics"):
        c.respond([0, 1], P=[0, -1])
    with pytest.raises(ValueError, match="rate"):
        c.cycle(P_max=100.0, P_min=-100.0, rate=1.0)


@pytest.mark.parametrize("kw, name", [(dict(t=[0, 1], P=[0, -1], delta=[0, 1]), "P"), (dict(t=[0, 1]), "P"),
                                      (dict(t=[1, 0], P=[0, -1]), "t"), (dict(t=[0, 1, 2], P=[0, -1]), "t"),
                                      (dict(t=[0, math.nan], P=[0, -1]), "t"), (dict(t=["a", "b"], P=[0, 1]), "t")])
def test_bad_history_names_itself(kw, name):
    c = pair("identical", jkrcyl.CrackKinetics(1e-6, 0.6))
    with pytest.raises(ValueError, match=name):
        c.respond(**kw)


def test_a_rate_too_slow_to_resolve_is_a_value_error_naming_rate():
    """At 1e-30 N/m/s the lag G/w - 1 is below rounding from the first step: a ValueError naming rate that says
    the quasi-static answer holds (not an ArithmeticError from inside the integrator)."""
    m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    c = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m, kinetics=jkrcyl.CrackKinetics(v_star=1e-6, n=0.6))
    with pytest.raises(ValueError, match="^rate: too slow"):
        c.pull_off(rate=1e-30)


def test_a_history_beyond_the_step_budget_is_a_value_error_naming_rate(monkeypatch):
    """No integration runs for ever: past MAX_STEPS steps of a segment the answer is a ValueError naming rate
    (the budget lowered here so that an ordinary ramp meets it)."""
    from jkrcyl.kinetics import integrate
    monkeypatch.setattr(integrate, "MAX_STEPS", 10)
    m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    c = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m, kinetics=jkrcyl.CrackKinetics(v_star=1e-6, n=0.6))
    with pytest.raises(ValueError, match=r"^rate: the history at this rate needs more than 10 integrator steps"):
        c.pull_off(rate=100.0)
