"""Edge laws as the extension point (jkrcyl.laws): a law of the test's own reaches every analysis through the
interface alone, the shorthand sigma0 is the Dugdale law, and what a law does not model is refused in its name.

The toy law is JKR with the edge's critical energy release rate 2w: every answer must be JKR's at 2w (an
independent Contact with w doubled), for a closed-form pair and a collocation (alpha* != 0) pair."""
import math
import warnings

import pytest

import jkrcyl


class Doubled(jkrcyl.laws.Griffith):
    """Griffith with the work of adhesion doubled: defined here, touching no library file."""

    name = "doubled JKR"

    def edge_work(self, w):
        return 2 * w


PAIRS = {"identical": jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3),
         "steel-in-aluminium": jkrcyl.Materials.from_young(E=70e9, nu=0.33, E_I=210e9, nu_I=0.3)}
R, DELTA = 1e-2, 1e-6
W = {"identical": 0.025, "steel-in-aluminium": 0.1}


def pair(name):
    m = PAIRS[name]
    return (jkrcyl.Contact(R=R, Delta=DELTA, w=W[name], materials=m, law=Doubled()),
            jkrcyl.Contact(R=R, Delta=DELTA, w=2 * W[name], materials=m))


def close(x, y, rel=1e-12):
    return x == pytest.approx(y, rel=rel, abs=1e-300)


@pytest.mark.parametrize("name", PAIRS)
def test_toy_law_pull_off_is_jkr_at_twice_w(name):
    toy, jkr = pair(name)
    for control in ("load", "grip", "grip-work"):
        a, b = toy.pull_off(control), jkr.pull_off(control)
        assert b.P is not None and b.P < 0                       # the case pulls off under every control
        assert close(a.P, b.P) and close(a.contact_width, b.contact_width) and close(a.delta, b.delta)


@pytest.mark.parametrize("name", PAIRS)
def test_toy_law_solve_is_jkr_at_twice_w(name):
    toy, jkr = pair(name)
    P = 0.5 * jkr.pull_off().P
    a = toy.solve(P=P, branches=["sub-critical", "super-critical", "sub-critical-top", "full-contact"])
    b = jkr.solve(P=P, branches=["sub-critical", "super-critical", "sub-critical-top", "full-contact"])
    assert len(a) == len(b) >= 2
    for x, y in zip(a, b):
        assert x.branch == y.branch and x.stable == y.stable and x.feasible == y.feasible
        assert close(x.eps, y.eps) and close(x.delta_work, y.delta_work) and close(x.K, y.K)
        assert close(x.energy, y.energy)


def test_toy_law_cycle_and_state_are_jkr_at_twice_w():
    toy, jkr = pair("identical")
    po = jkr.pull_off().P
    a, b = (c.cycle(P_max=-1.5 * po, P_min=1.5 * po, n=200) for c in (toy, jkr))   # both transfers
    assert [j.kind for j in a.jumps] == [j.kind for j in b.jumps] and len(a.jumps) >= 1
    assert close(a.dissipated, b.dissipated) and b.dissipated > 0
    sa, sb = toy.state([0.01, 0.3]), jkr.state([0.01, 0.3])
    for f in ("P", "K", "G_release", "delta", "h_pi"):
        assert close(getattr(sa, f)[0], getattr(sb, f)[0]) and close(getattr(sa, f)[1], getattr(sb, f)[1])
    assert close(sa.G_release[0], 2 * W["identical"], rel=1e-10)       # G = the law's edge work, (3.5)


def test_sigma0_is_shorthand_for_the_dugdale_law():
    m = PAIRS["identical"]
    a = jkrcyl.Contact(R=R, Delta=DELTA, w=0.05, materials=m, sigma0=2e5)          # lambda = 3.7
    b = jkrcyl.Contact(R=R, Delta=DELTA, w=0.05, materials=m, law=jkrcyl.laws.Dugdale(sigma0=2e5))
    assert a == b and hash(a) == hash(b) and b.sigma0 == 2e5 and a.law == jkrcyl.laws.Dugdale(2e5)
    assert a.pull_off().P == b.pull_off().P                             # bit-identical: the same problem


def test_a_law_that_does_not_model_a_family_is_refused_in_its_name():
    m = PAIRS["identical"]
    c = jkrcyl.Contact(R=R, Delta=DELTA, w=0.05, materials=m, law=jkrcyl.laws.Dugdale(sigma0=2e5))
    with pytest.raises(ValueError, match="^sigma0: .*not modelled for the Maugis-Dugdale law"):
        c.problem.require("two-patch", "JKR's landing on two patches at every jump is")
    huge = jkrcyl.Contact(R=R, Delta=DELTA, w=0.05, materials=m, law=jkrcyl.laws.Dugdale(sigma0=2e5 * 2000 / 3.7))
    with pytest.raises(ValueError, match="^sigma0 is too large for the two-arc"):   # lambda 2000 (3.7: the own branch)
        huge.confined_events()


@pytest.mark.parametrize("make, match", [
    (lambda: dict(law="JKR"), "^law must be a jkrcyl.laws.EdgeLaw"),
    (lambda: dict(law=jkrcyl.laws.Dugdale(1e6), sigma0=2e6), "^sigma0: give the law once"),
    (lambda: dict(law=jkrcyl.laws.Dugdale(-1.0)), r"^sigma0 must be in \(0, inf\]"),
    (lambda: dict(law=jkrcyl.laws.Dugdale(1e-99)), r"^sigma0 must be in \[.* Pa for this contact"),
])
def test_bad_law_arguments(make, match):
    with pytest.raises(ValueError, match=match):
        jkrcyl.Contact(R=R, Delta=DELTA, w=0.05, materials=PAIRS["identical"], **make())


def test_validity_warning_where_the_clearance_is_not_small():
    """Issue 24 item 6: a 20 um pin in a 20 mm hole answered a pull-off with a contact wider than the pin, and
    nothing said the theory assumes Delta << R."""
    m = PAIRS["identical"]
    with pytest.warns(jkrcyl.ValidityWarning, match="Delta/R = 0.999"):
        jkrcyl.Contact(R=1e-2, Delta=9.99e-3, w=0.05, materials=m)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        jkrcyl.Contact(R=1e-2, Delta=1e-4, w=0.05, materials=m)         # Delta/R = 1 %: no warning


def test_toy_law_fit_is_jkr_at_twice_w():
    """The fit through the law: loads generated by JKR at 2w (an independent Contact), fitted with the toy law, give
    w itself; its pull-off is the core's."""
    import numpy as np
    m = PAIRS["identical"]
    jkr = jkrcyl.Contact(R=R, Delta=3e-6, w=0.1, materials=m)
    width = np.linspace(7e-3, 20e-3, 12)
    P = jkr.state(np.tan(width / (4 * R))).P
    res = jkrcyl.fit.fit(P=P, width=width, R=R, Delta=3e-6, materials=m, free=("w",), law=Doubled(), w=0.03,
                         sigma_P=1.0, interval=None)
    assert res.values["w"] == pytest.approx(0.05, rel=1e-8) and isinstance(res.law, Doubled)
    assert res.contact().pull_off().P == pytest.approx(jkr.pull_off().P, rel=1e-10)
