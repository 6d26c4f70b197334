"""The numbers the README's section on rate-dependent adhesion states (a rubber roller in a steel cradle pulled
at 1, 10 and 100 mm/min), compared with what the library returns, so that the text cannot go stale; and the
identity the README quotes: only the ratio of rate to v* matters (the edge equation is invariant under
t -> t/lambda, v -> lambda v, rate -> lambda rate), which the integrator does not use."""
import pytest

import jkrcyl

RUBBER_IN_STEEL = jkrcyl.Materials.from_young(E=210e9, nu=0.3, E_I=2e6, nu_I=0.49)


def roller(v_star=1e-4):
    return jkrcyl.Contact(R=20e-3, Delta=0.2e-3, w=0.05, materials=RUBBER_IN_STEEL,
                          kinetics=jkrcyl.CrackKinetics(v_star=v_star, n=0.6))


def test_roller_as_stated():
    c = roller()
    qs = c.pull_off().P
    assert round(qs, 1) == -41.6
    pulled = {mm: c.pull_off("grip-work", rate=mm * 1e-3 / 60) for mm in (1, 10, 100)}
    assert [(p.kind, round(p.P, 1)) for p in pulled.values()] == [("separation", -157.5), ("separation", -293.1),
                                                                 ("separation", -533.2)]
    assert [round(p.P / qs, 1) for p in pulled.values()] == [3.8, 7.0, 12.8]
    assert round(pulled[10].history.contact_width[0] * 1e3) == 18
    held = c.respond([0.0, 2.0, 3600.0], P=[0.0, -30.0, -30.0])
    eq = next(s for s in c.solve(P=-30.0) if s.branch == "sub-critical" and s.stable)
    assert round(held.contact_width[-1] * 1e3, 2) == 13.03 and round(eq.contact_width * 1e3, 2) == 13.00
    assert round(held.G[-1], 4) == 0.0501


@pytest.mark.parametrize("control, rate", [("grip-work", 1e-5), ("load", 100.0)])
def test_only_rate_over_v_star_matters(control, rate):
    a = roller(1e-4).pull_off(control, rate=rate)
    b = roller(1e-3).pull_off(control, rate=10 * rate)
    assert a.kind == b.kind and a.P == pytest.approx(b.P, rel=1e-8)
    assert a.history.events[-1].t == pytest.approx(10 * b.history.events[-1].t, rel=1e-8)
