"""Crack kinetics in time (jkrcyl.kinetics) against what it must reduce to: the quasi-static answers of the core
as v* -> inf, the equilibrium a held contact relaxes to, itself at half the tolerance, the collocation states
against their tables, and the high-rate power law of the half-plane limit (Barquins' cylinder, (7.3)-(7.4))."""
import math

import numpy as np
import pytest

import jkrcyl
from jkrcyl.kinetics import arc as karc
from jkrcyl.kinetics import ramps, sweep
from jkrcyl.model.problem import Problem
from jkrcyl.model.single_patch import solver

PAIRS = {"identical": (jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3), 0.05),
         "steel-in-aluminium": (jkrcyl.Materials.from_young(E=70e9, nu=0.33, E_I=210e9, nu_I=0.3), 0.1)}


def contact(name, v_star, n=0.6):
    m, w = PAIRS[name]
    return jkrcyl.Contact(R=1e-2, Delta=1e-6, w=w, materials=m, kinetics=jkrcyl.CrackKinetics(v_star, n))


@pytest.mark.parametrize("name", PAIRS)
def test_fixed_arc_states_are_linear_in_the_edge_coefficient(name):
    """X(a, k) = X0 + (k/k_eq) X1: the solver's equilibrium at 2.5 M (k = 2.5 k_eq) is the arc state at g = 2.5,
    an independent solve (closed forms at alpha* = 0, collocation otherwise)."""
    pb = contact(name, 1.0).problem
    big = Problem(2.5 * pb.M, pb.theta, pb.gb, pb.alpha_ratio, pb.edge, False)
    a = np.array([1e-4, 0.05, 0.4])
    Y, _ = karc.DirectArc(pb).table(a)
    s = solver(big).states(a)
    for field, (i0, i1) in (("p", (karc.P0, karc.P1)), ("dn", (karc.DN0, karc.DN1)), ("h", (karc.H0, karc.H1)),
                            ("B", (karc.B0, karc.B1))):
        scale = np.abs(Y[:, i0]) + np.abs(Y[:, i1])
        assert np.all(np.abs(Y[:, i0] + 2.5 * Y[:, i1] - getattr(s, field)) <= 1e-9 * scale), field


@pytest.mark.parametrize("name, tol", [("identical", 1e-13), ("steel-in-aluminium", 1e-8)])
def test_tabulated_arc_is_the_solver(name, tol):
    """The Chebyshev panels against the solver at points off their nodes (collocation: its own noise ~1e-10)."""
    pb = contact(name, 1.0).problem
    tab = karc.TabulatedArc(pb, math.log(1e-10), math.log(0.6))
    direct = karc.DirectArc(pb)
    for u in np.linspace(math.log(2e-10), math.log(0.59), 23):
        y, _ = tab.at(u)
        yd, _ = direct.at(u)
        scale = np.repeat(np.abs(yd[0::2]) + np.abs(yd[1::2]), 2)
        assert np.all(np.abs(y - yd) <= tol * scale)


@pytest.fixture(scope="module")
def quasi_static():
    return {name: {c: contact(name, 1.0).pull_off(c) for c in ("load", "grip", "grip-work")} for name in PAIRS}


@pytest.mark.parametrize("name", PAIRS)
@pytest.mark.parametrize("control", ["load", "grip", "grip-work"])
def test_quasi_static_limit(name, control, quasi_static):
    """v* = 1e12 m/s: the load at which the contact goes (load control), the held approach at separation
    (grip: the fold of the held approach) and the largest tension on the way (the fixed-load pull-off, which
    the grip path passes first) are the quasi-static values to 1e-6."""
    qs, qs_load = quasi_static[name][control], quasi_static[name]["load"]
    c = contact(name, 1e12)
    if control == "load":
        po = c.pull_off("load", rate=0.1 * abs(qs.P))           # a ramp of 10 s
        assert po.P == pytest.approx(qs.P, rel=1e-6)
        return
    po = c.pull_off(control, rate=1e-6)                          # 1 Delta per second
    assert po.kind == "separation"
    held = po.delta if control == "grip" else po.delta_work
    assert held == pytest.approx(qs.delta if control == "grip" else qs.delta_work, rel=1e-6)
    assert qs_load.state.a > qs.state.a                         # the path passes the fixed-load fold first
    assert po.P == pytest.approx(qs_load.P, rel=1e-6)


@pytest.mark.parametrize("n", [1.0, 1.5])
@pytest.mark.parametrize("control", ["load", "grip-work"])
def test_held_contact_relaxes_to_equilibrium(n, control):
    """A step of the held quantity, then held: the contact ends at the stable equilibrium the core solves for
    (exponentially for n = 1, in finite time for n > 1), G = w there."""
    c = contact("identical", 1e-3, n)
    zero = next(s for s in c.solve(P=0.0) if s.branch == "sub-critical" and s.stable)
    if control == "load":
        target = 0.5 * c.pull_off().P
        h = c.respond([0.0, 1e-3, 1e4], P=[0.0, target, target])
        eq = [s for s in c.solve(P=target) if s.branch == "sub-critical" and s.stable_load]
    else:
        target = zero.delta_work - 2e-7
        h = c.respond([0.0, 1e-3, 1e4], delta_work=[zero.delta_work, target, target])
        eq = [s for s in c.solve(delta_work=target) if s.branch == "sub-critical" and s.stable_grip_work]
    assert len(eq) == 1 and h.end == "end"
    assert h.eps[-1] == pytest.approx(eq[0].eps, rel=1e-9)
    assert h.G[-1] == pytest.approx(0.05, rel=1e-8)
    assert abs(h.eps[1] - eq[0].eps) > 1e-3 * eq[0].eps          # it did move


@pytest.mark.parametrize("control, rate", [("load", 100.0), ("grip", 1e-6), ("grip-work", 1e-6)])
def test_halving_the_tolerance(control, rate):
    c = contact("identical", 1e-3)
    a, b = (ramps.pull_off(c, control, rate, rtol=r) for r in (1e-10, 5e-11))
    assert a.kind == b.kind and a.kind
    assert a.P == pytest.approx(b.P, rel=1e-8)
    assert a.history.events[-1].t == pytest.approx(b.history.events[-1].t, rel=1e-8)


@pytest.mark.parametrize("control", ["load", "grip-work"])
def test_collocation_states_and_their_table_give_the_same_history(control):
    c = contact("steel-in-aluminium", 1e-3)
    rate = 10 * abs(c.pull_off().P) if control == "load" else 1e-6
    a, b = (ramps.pull_off(c, control, rate, route=r) for r in ("table", "direct"))
    assert a.kind == b.kind and a.kind
    assert a.P == pytest.approx(b.P, rel=1e-6)
    assert a.history.events[-1].t == pytest.approx(b.history.events[-1].t, rel=1e-6)
    t = np.linspace(0.0, 0.9 * a.history.events[-1].t, 7)                   # the same ramp, at given instants
    x = (-rate * t) if control == "load" else a.history.delta_work[0] - rate * t
    kw = {"P": x} if control == "load" else {"delta_work": x}
    ha, hb = (ramps.respond(c, t, route=r, **kw) for r in ("table", "direct"))
    rows = [np.searchsorted(h.t, t) for h in (ha, hb)]
    assert np.array_equal(ha.t[rows[0]], t) and np.array_equal(hb.t[rows[1]], t)
    assert np.allclose(ha.eps[rows[0]], hb.eps[rows[1]], rtol=1e-6, atol=0)
    assert np.allclose(ha.P[rows[0]], hb.P[rows[1]], rtol=1e-6, atol=1e-9 * np.abs(hb.P).max())


def test_half_plane_high_rate_power_law():
    """A small contact in a large hole (M ~ 8e-4, a0 ~ 0.013) is Barquins' cylinder on a half-plane (7.4):
    P = b^2/(2 A R*) (R_D/R) - sqrt(4 b w/A) at G = w, i.e. G = A (P_H(b) - P)^2/(4 b) ((3.5): K = (P_H - P)/
    sqrt(pi b)), b = R eps the contact half-width, A = beta*/(2 pi), 1/R* = 1/R_D - 1/R.

    Derivation of the high-rate law (load control, P = -r t, each edge opening at v = -db/dt with
    G = w (v/v*)^n once G >> w and |P| >> P_H):  -db/dt = v* (A r^2 t^2/(4 w b))^(1/n), so
    int_0^b0 b^(1/n) db = v* (A r^2/(4 w))^(1/n) int_0^ts t^(2/n) dt, i.e.
    ts = [(n + 2)/(n + 1) b0^((n + 1)/n) / (v* (A r^2/(4 w))^(1/n))]^(n/(n + 2)) and |P| = r ts ~ r^(n/(n + 2)),
    b0 the zero-load half-width of (7.4).  Corrections fall as r^(-n/(n + 2)) (P_H and the 1 in G = w(1 + phi)),
    removed here by one Richardson step, and as a0^2 (the half-plane limit)."""
    n, v_star, R, Delta, w = 1.0, 1e-3, 1e-2, 1e-4, 1e-3
    m = jkrcyl.Materials.from_young(E=1e9, nu=0.3, E_I=1e9, nu_I=0.3)
    c = jkrcyl.Contact(R=R, Delta=Delta, w=w, materials=m, kinetics=jkrcyl.CrackKinetics(v_star, n))
    A, RD = m.beta / (2 * math.pi), R - Delta
    b0 = (2 * A * (R * RD / Delta) * (R / RD) * math.sqrt(4 * w / A)) ** (2 / 3)

    def barquins(r):
        return -r * ((n + 2) / (n + 1) * b0 ** ((n + 1) / n) / (v_star * (A * r * r / (4 * w)) ** (1 / n))) \
            ** (n / (n + 2))

    rates = abs(c.pull_off().P) * 10.0 ** np.arange(5, 10)
    sw = sweep.rate_sweep(c, rates)
    slopes = np.diff(np.log(-sw.P)) / np.diff(np.log(rates))
    exponent = n / (n + 2)
    assert sw.exponent == exponent
    assert np.all(np.diff(slopes) < 0) and abs(slopes[-1] / exponent - 1) < 5e-3     # falling onto 1/3
    ratio = sw.P / np.array([barquins(r) for r in rates])
    f = 10.0 ** -exponent
    assert abs(ratio[-1] - 1) < 2e-3
    assert abs((ratio[-1] - f * ratio[-2]) / (1 - f) - 1) < 2e-4                     # Richardson
    assert np.all(np.abs(sw.P / sw.asymptote / ratio - 1) < 1e-3)   # the library's cylinder asymptote, too
    assert sw.P_frozen < sw.P.min()                                 # the infinite-rate ceiling is not reached
