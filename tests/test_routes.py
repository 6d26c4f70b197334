"""Issue 18: a number reached two ways must agree -- differential property tests over random material pairs.

Pairs: rigid hole or pin or neither, nu in [0, 0.5], |alpha*/beta*| <= 0.45 (so vartheta in [0.5, inf]), M in
[1e-3, 2].  The second route of each property shares no code with the library's answer:

* the fixed-arc unit cases of the two-arc engine (jkrcyl.numerics.arcs.two_patch_linear: P*, k for the Delta case
  and a unit approach, at a fixed node count) -- not the bordered single-arc solver, not the closed forms, not the
  chain rule -- give the edge coefficient k at any arc and any held P, delta or delta_work, so G/w = (pi k/M)^2
  off equilibrium: stability is the sign of a central difference of k in a at fixed X (section 8.3), the
  receding contact a_crit is the zero of 1/P at k = 0, and the direction of a fold is the sign of dk/dP at fixed
  arc;
* Contact.state on a dense grid, each state solved on its own, for the load path (pull-off is the minimum of P
  along it) -- not the library's tables, roots or walker;
* the trapezoid rule over a cycle's own path -- not the jump energies the library sums.
"""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq, minimize_scalar

import jkrcyl
from jkrcyl.numerics.arcs import two_patch_linear

R, DELTA = 1e-2, 1e-5
NODES = 48
FEW = settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                   HealthCheck.filter_too_much])
SOME = settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                     HealthCheck.filter_too_much])


# --- random pairs ----------------------------------------------------------------------------------------
poisson = st.one_of(st.just(0.0), st.floats(1e-3, 0.5))
@st.composite
def materials(draw, closed=None):
    """A plane-strain pair: closed=True draws alpha* = 0 pairs (incompressible, identical, or a rigid body
    with an incompressible partner), False alpha* != 0, None either."""
    kind = draw(st.sampled_from(["closed", "any"])) if closed is None else ("closed" if closed else "any")
    rigid = draw(st.sampled_from(["none", "hole", "pin"]))
    E = math.inf if rigid == "hole" else 10 ** draw(st.floats(6, 11))
    E_I = math.inf if rigid == "pin" else 10 ** draw(st.floats(6, 11))
    if kind == "closed":
        same = rigid == "none" and draw(st.booleans())
        nu = draw(poisson) if same else 0.5
        m = jkrcyl.Materials.from_young(E, nu, E if same else E_I, nu)
    else:
        m = jkrcyl.Materials.from_young(E, draw(poisson), E_I, draw(poisson))
        assume(not m.closed_form)
    assume(abs(m.alpha_ratio) <= 0.45)
    return m


def contact(m, M):
    """The contact of the pair with normalised adhesion M (w from M ~ sqrt(w))."""
    c1 = jkrcyl.Contact(R=R, Delta=DELTA, w=1.0, materials=m)
    return jkrcyl.Contact(R=R, Delta=DELTA, w=(M / c1.M) ** 2, materials=m)


adhesion = st.floats(-3.0, math.log10(2.0)).map(lambda u: 10 ** u)


# --- the second route: fixed-arc unit cases of the two-arc engine -----------------------------------------
def unit_cases(c, a):
    """(q0, q1, scale): [P*, B*, k_bot, k_top] of the Delta case and of a unit delta/Delta at the single arc a."""
    m = c.materials
    lin = two_patch_linear(2 * math.atan(a), 0.0, m.theta, m.inv_G_I / c.beta, NODES, m.alpha_ratio)
    return lin.q0, lin.q1, (1.0 if math.isinf(c.theta) else c.theta)


def edge_at(c, a, control, value):
    """k at the arc a with the held quantity (P*, delta/Delta or delta_work/Delta) at value."""
    q0, q1, scale = unit_cases(c, a)
    if control == "load":
        d = (value - q0[0]) / q1[0]
    elif control == "grip":
        d = value
    else:                                     # delta_work/Delta = d + (gb/2) scale P*, typed from DERIVATION.md
        cw = 0.5 * c.materials.inv_G_I / c.beta * scale
        d = (value - cw * q0[0]) / (1 + cw * q1[0])
    return q0[2] + d * q1[2]


def held(s, control):
    return {"load": s.P_star, "grip": s.delta_over_Delta, "grip-work": s.delta_work_over_Delta}[control]


# --- properties -----------------------------------------------------------------------------------------------
@FEW
@given(m=materials(closed=False), M=adhesion, frac=st.floats(0.05, 0.95))
def test_a_crit_is_the_pole_of_the_adhesionless_load(m, M, frac):
    """Contact.a_crit (the single-patch solver's pole) is the zero of 1/P at k = 0 of the unit cases."""
    c = contact(m, M)
    ac = c.a_crit
    assume(math.isfinite(ac) and ac < 50)
    inv_P = lambda a: (lambda q0, q1, _: q1[2] / (q0[0] * q1[2] - q0[2] * q1[0]))(*unit_cases(c, a))
    root = brentq(inv_P, ac * (1 - 1e-3), ac * (1 + 1e-3), xtol=1e-15, rtol=1e-14)
    assert root == pytest.approx(ac, rel=1e-9)


@pytest.mark.parametrize("closed", [True, False])
@FEW
@given(data=st.data())
def test_stability_flags_are_the_sign_of_dk_at_fixed_control(closed, data):
    """Away from turning points the flags of Contact.solve's states equal the sign of k(a + h) - k(a - h) at
    the held P, delta or delta_work (G/w = (pi k/M)^2 grows with a: stable)."""
    m = data.draw(materials(closed=closed))
    c = contact(m, data.draw(adhesion))
    control = data.draw(st.sampled_from(["load", "grip", "grip-work"]))
    cv = c.curve(n=60)
    i = data.draw(st.integers(3, 56))
    value = {"load": cv.P[i], "grip": cv.delta[i], "grip-work": cv.delta_work[i]}[control]
    kw = {"load": "P", "grip": "delta", "grip-work": "delta_work"}[control]
    for s in c.solve(**{kw: float(value)}, branches=["sub-critical", "super-critical"]):
        slope = {"load": cv.dP_star_da, "grip": cv.ddelta_da, "grip-work": cv.ddelta_work_da}[control]
        if abs(np.interp(s.a, cv.a, slope)) * s.a < 1e-3 * (abs(held(s, control)) + 1e-3):
            continue                                              # near a turning point: the flag may flip
        h = 1e-5 * s.a
        dk = edge_at(c, s.a + h, control, held(s, control)) - edge_at(c, s.a - h, control, held(s, control))
        assert s.stable == (dk > 0), (control, s)


@pytest.mark.parametrize("closed", [True, False])
@SOME
@given(data=st.data())
def test_solve_states_carry_the_request(closed, data):
    """Every state solve returns has the requested P, delta or delta_work (1e-10) and is finite; single-patch
    states are Contact.state's own (solved on its own at the returned a)."""
    m = data.draw(materials(closed=closed))
    c = contact(m, data.draw(adhesion))
    control = data.draw(st.sampled_from(["P", "delta", "delta_work"]))
    level = data.draw(st.one_of(st.just(0.0), st.floats(-2.0, -1e-6), st.floats(1e-6, 3.0)))
    target = level * (c.load_scale if control == "P" else c.Delta)
    states = c.solve(**{control: target}, branches=["sub-critical", "super-critical", "sub-critical-top",
                                                    "super-critical-top", "separated"])
    scale = c.load_scale if control == "P" else c.Delta
    for s in states:
        assert abs(getattr(s, control) - target) <= 1e-10 * max(abs(target), scale), s
        assert all(np.isfinite([s.P, s.delta, s.delta_work, s.h_pi, s.a]))
        if s.side != "none":
            st_ = c.state(s.a)
            sign = -1 if s.side == "top" else 1
            assert sign * float(st_.P) == pytest.approx(s.P, rel=1e-10, abs=1e-10 * c.load_scale)


def _dense_pull_off(c):
    """The load path on Contact.state alone: the smallest stable (sign of dk at fixed P, the unit cases),
    feasible zero-load contact, then down in P along the branch to the first minimum (refined by bounded Brent
    on Contact.state(a).P).  Returns (P_min, a_min) for a detachment, or None."""
    ac = c.a_crit
    grids = ([ac * np.geomspace(1e-7, 1 - 1e-7, 3000)] if math.isfinite(ac) else [np.geomspace(1e-7, 1e3, 3000)])
    if math.isfinite(ac):
        grids.append(ac * (1 + np.geomspace(1e-7, 1e3, 3000)))
    for a in grids:
        st_ = c.state(a)
        P, h = np.asarray(st_.P), np.asarray(st_.h_pi)
        for i in np.nonzero(np.sign(P[:-1]) * np.sign(P[1:]) < 0)[0]:
            if abs(P[i]) > 1e3 * c.load_scale or abs(P[i + 1]) > 1e3 * c.load_scale:
                continue                                       # a pole, not a zero
            a0 = brentq(lambda x: float(c.state(x).P), a[i], a[i + 1], xtol=1e-14)
            dk = edge_at(c, a0 * (1 + 1e-6), "load", 0.0) - edge_at(c, a0 * (1 - 1e-6), "load", 0.0)
            if dk <= 0 or float(c.state(a0).h_pi) < 0:
                continue                                       # unstable or infeasible
            step = -1 if P[i + 1] > P[i] else 1               # towards lower P
            j = i if step < 0 else i + 1
            while 0 < j < a.size - 1 and P[j + step] < P[j]:
                if h[j + step] < 0:
                    return None                                 # the gap closes first
                j += step
            if not 0 < j < a.size - 1:
                return None
            r = minimize_scalar(lambda x: float(c.state(x).P), bounds=(a[j - 1], a[j + 1]), method="bounded",
                                options={"xatol": 1e-13 * a[j]})
            q0, q1, _ = unit_cases(c, r.x)
            return (r.fun, r.x) if q1[2] / q1[0] < 0 else None  # pulling raises k: the contact shrinks away
    return None


@pytest.mark.parametrize("closed", [True, False])
@FEW
@given(data=st.data())
def test_pull_off_is_the_minimum_of_independent_states(closed, data):
    m = data.draw(materials(closed=closed))
    c = contact(m, data.draw(adhesion))
    po = c.pull_off()
    ref = _dense_pull_off(c)
    assert po.detached == (ref is not None), (po, ref)
    if ref is not None:
        assert po.P == pytest.approx(ref[0], rel=1e-6)


@FEW
@given(m=materials(closed=True), M=st.floats(0.02, 0.4), factor=st.floats(0.0, 3.0).map(lambda u: 10 ** u))
def test_cycle_energy_is_the_trapezoid_of_its_path(m, M, factor):
    """dissipated >= 0 and equal to the trapezoid rule over the returned (unthinned) path, for P_max from about
    the pull-off force up to 1e3 times it."""
    c = contact(m, M)
    po = c.pull_off()
    assume(po.detached)
    cy = c.cycle(P_max=-factor * po.P, P_min=2 * po.P, n=1_000_000)
    assume(cy.dissipated is not None)
    sel = cy.leg >= cy.closed_from_leg
    P, d = cy.P[sel], cy.delta[sel]
    trap = float(np.sum(0.5 * (P[1:] + P[:-1]) * np.diff(d)))
    assert cy.dissipated >= 0
    assert cy.dissipated == pytest.approx(trap, rel=1e-6)
