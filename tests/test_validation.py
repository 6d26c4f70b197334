"""Bad input gets a ValueError naming the parameter and the allowed range (never a wrong number)."""
import math

import numpy as np
import pytest

import jkrcyl

SAME = dict(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0)


def contact(**kw):
    args = dict(R=1.0, Delta=0.01, w=1e-4, materials=jkrcyl.Materials(**SAME))
    args.update(kw)
    return jkrcyl.Contact(**args)


@pytest.mark.parametrize("kw, pattern", [
    (dict(R=0.0), r"R must be in \(0"),
    (dict(R=-1.0), r"R must be in \(0"),
    (dict(R=math.inf), "R must be finite"),
    (dict(Delta=-0.1), r"Delta must be in \[0"),
    (dict(Delta=math.nan), "Delta must be finite"),
    (dict(w=-1e-3), r"w must be in \[0"),
    (dict(w=math.nan), "w must be finite"),
    (dict(materials="steel"), "materials must be a jkrcyl.Materials"),
])
def test_contact_inputs(kw, pattern):
    with pytest.raises(ValueError, match=pattern):
        contact(**kw)


@pytest.mark.parametrize("a", [0.0, -0.5, math.nan, math.inf, [0.1, -1.0], [0.2, math.nan]])
def test_contact_parameter(a):
    with pytest.raises(ValueError, match=r"a must be in \(0, inf\)"):
        contact().state(a)


@pytest.mark.parametrize("kw, pattern", [
    (dict(G=0.0), r"G must be in \(0"),
    (dict(G_I=-2.0), r"G_I must be in \(0"),
    (dict(G=math.nan), "G must be finite"),
    (dict(kappa=0.5), r"kappa must be in \[1"),
    (dict(G=math.inf, G_I=math.inf, kappa_I=2.0), "both inf"),
])
def test_materials(kw, pattern):
    args = dict(SAME)
    args.update(kw)
    with pytest.raises(ValueError, match=pattern):
        jkrcyl.Materials(**args)


@pytest.mark.parametrize("kw, pattern", [
    (dict(nu=0.6), r"nu must be in \(-1, 0.5\]"),
    (dict(nu_I=-1.0), r"nu_I must be in \(-1, 0.5\]"),
    (dict(E=-1.0), r"E must be in \(0"),
    (dict(E_I=math.nan), "E_I must be finite"),
])
def test_from_young(kw, pattern):
    args = dict(E=1.0, nu=0.3, E_I=1.0, nu_I=0.3)
    args.update(kw)
    with pytest.raises(ValueError, match=pattern):
        jkrcyl.Materials.from_young(**args)


def test_alpha_star_message_gives_the_value():
    m = jkrcyl.Materials(G=1.0, kappa=2.0, G_I=2.0, kappa_I=2.0)     # any alpha* is accepted (issue 10)
    c = jkrcyl.Contact(R=1.0, Delta=0.01, w=1e-4, materials=m)
    with pytest.raises(ValueError) as info:
        c.state(0.5, method="closed-form")
    assert "= 0.25 (alpha*/beta*" in str(info.value)    # (2-1)/2 - (2-1)/4
    with pytest.raises(ValueError, match="method must be"):
        c.state(0.5, method="exact")


@pytest.mark.parametrize("theta", [0.49, 0.0, -1.0, math.nan])
def test_theta_range(theta):
    with pytest.raises(ValueError, match="theta"):
        jkrcyl.a_crit(theta)


def test_neat_fit_normalisation_is_refused():
    c = contact(Delta=0.0)
    s = c.state(0.5)                       # dimensional values exist
    assert np.isfinite(s.P)
    with pytest.raises(ValueError, match="Delta = 0"):
        s.P_star
    with pytest.raises(ValueError, match="Delta = 0"):
        c.M


def test_material_parameters_of_section_2():
    """vartheta = 1/2 + G (kappa_I + 1)/(2 G_I (1 + kappa)); rigid indenter -> 1/2; rigid cradle -> inf."""
    assert jkrcyl.Materials(**SAME).theta == pytest.approx(1.0, rel=1e-15)
    assert jkrcyl.Materials(G=1.0, kappa=1.0, G_I=math.inf, kappa_I=2.0).theta == 0.5
    assert jkrcyl.Materials(G=math.inf, kappa=2.0, G_I=1.0, kappa_I=1.0).theta == math.inf
    m = jkrcyl.Materials.from_young(E=2.6, nu=0.3, E_I=2.6, nu_I=0.3)
    assert m.G == pytest.approx(1.0) and m.kappa == pytest.approx(1.8)
    c = contact()
    assert c.A == pytest.approx(c.beta / (2 * math.pi))
    assert c.M == pytest.approx(math.sqrt(c.w * c.A * c.R) / (math.sqrt(2) * c.Delta * c.theta), rel=1e-14)


def test_one_list_of_controls():
    """The controls the library checks (jkrcyl._validate.CONTROLS) are those the results know (the fields of
    jkrcyl.results.states.CONTROLS), the explorer offers and the CLI's pull-off table lists."""
    from jkrcyl import _validate
    from jkrcyl.cli import pull_off
    from jkrcyl.explore import model
    from jkrcyl.results import states
    assert set(_validate.CONTROLS) == set(states.CONTROLS) == set(model.CONTROLS) == set(pull_off.CONTROLS)
    for bad in ("Load", None, 1, "grip_work"):
        with pytest.raises(ValueError, match="^control must be one of 'load', 'grip', 'grip-work', got"):
            _validate.control(bad)
