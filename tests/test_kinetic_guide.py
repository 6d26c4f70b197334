"""The numbers the user guide's page on rate-dependent adhesion (docs/guide/rate.md) states (a rubber roller in a
steel cradle pulled at 1, 10 and 100 mm/min), compared with what the library returns, so that the text cannot go
stale (the page's code blocks run in tests/test_docs.py); and the identity the page quotes: only the ratio of rate
to v* matters (the edge equation is invariant under t -> t/lambda, v -> lambda v, rate -> lambda rate), which the
integrator does not use."""
import pathlib

import pytest

import jkrcyl

PAGE = (pathlib.Path(__file__).resolve().parents[1] / "docs" / "guide" / "rate.md").read_text()
RUBBER_IN_STEEL = jkrcyl.Materials.from_young(E=210e9, nu=0.3, E_I=2e6, nu_I=0.49)


def roller(v_star=1e-4):
    return jkrcyl.Contact(R=20e-3, Delta=0.2e-3, w=0.05, materials=RUBBER_IN_STEEL,
                          kinetics=jkrcyl.CrackKinetics(v_star=v_star, n=0.6))


def test_the_page_states_these_numbers():
    for stated in ("about -41.6 N/m", "about -157.5, -293.1, -533.2 N/m", "3.8, 7.0 and 12.8 times", "(18 mm at rest)",
                   "about 13.03 mm and 0.0501 J/m^2", "equilibrium (13.00 mm)", "about 4.14e-5, 1.12e-4, 1.34e-5 J/m",
                   "only the ratio of rate to v* matters".capitalize()):
        assert stated in PAGE, stated


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
    # the equilibrium is a single-patch state: the two-patch branches (traced for 20 s on this alpha* != 0 pair)
    # are not searched
    eq = next(s for s in c.solve(P=-30.0, branches=["sub-critical"]) if s.branch == "sub-critical" and s.stable)
    assert round(held.contact_width[-1] * 1e3, 2) == 13.03 and round(eq.contact_width * 1e3, 2) == 13.00
    assert round(held.G[-1], 4) == 0.0501


@pytest.mark.parametrize("control, rate", [("grip-work", 1e-5), ("load", 100.0)])
def test_only_rate_over_v_star_matters(control, rate):
    a = roller(1e-4).pull_off(control, rate=rate)
    b = roller(1e-3).pull_off(control, rate=10 * rate)
    assert a.kind == b.kind and a.P == pytest.approx(b.P, rel=1e-8)
    assert a.history.events[-1].t == pytest.approx(10 * b.history.events[-1].t, rel=1e-8)


def test_cycles_at_three_frequencies_as_stated():
    """The loop's energy is the edges' dissipation over it (an independent column of the history: int (G - w)
    over the crack advance), and the page's three values."""
    c = roller()
    cycles = [c.cycle(P_max=30.0, P_min=-30.0, rate=120.0 * f) for f in (1e-4, 1e-3, 1e-1)]
    assert [cy.frequency for cy in cycles] == pytest.approx([1e-4, 1e-3, 1e-1], rel=1e-12)
    assert [float(f"{cy.dissipated:.3g}") for cy in cycles] == [4.14e-5, 1.12e-4, 1.34e-5]
    for cy in cycles:
        assert cy.edge_dissipation == pytest.approx(cy.dissipated, rel=1e-3)
