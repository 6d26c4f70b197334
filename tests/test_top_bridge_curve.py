"""The top bridge as a branch of the API: ``curve(regime="top-bridge")`` (jkrcyl.equilibria_bridge,
jkrcyl.model.cohesive_bridge) and its continuation past the touch without contact (two zones:
jkrcyl.numerics.cohesive_contactless).

Case: M 0.1, vartheta 10, gb 1/2.8, lambda 20 (m = 1, s0 = 5, h0 = 0.2 Delta): two junctions h(pi) = h0 on the
single patch; the first family's contact vanishes before the top closes (the touch), the second's top closes.
Checked against what the curve does not use:

* the states solved alone by other routes: with contact at the contact eps, a scan and Brent in c_top
  (jkrcyl.numerics.cohesive_zones.top_zone_states; the trace solves eps at a fixed c_top), and at a fixed c_top from
  a guess 1 % off (cohesive_top_zone.state_at); without contact a scan and Brent in c_top at the bottom zone c
  (cohesive_zones.contactless_states), 1e-10;
* the energy identity dE = p d(delta/Delta) between states (Chebyshev quadrature over states solved alone, the
  total potential with both zones' Dugdale energy: jkrcyl.numerics.cohesive_branch.potential), 1e-8;
* the mirror phi -> phi + pi (c <-> c_top, p -> -p, delta/Delta -> -2 - delta/Delta), which the trace never uses;
* the single patch at the junction (its own solver at the same contact);
* the stability from the held energy itself: its Hessian by differences of the potential (no contact), the full
  held-zone-end matrix (with contact) rather than the curve's shortcut.
"""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, example, given, settings, strategies as hst
from numpy.polynomial import chebyshev as C

import jkrcyl
from jkrcyl.cli import main as cli_main
from jkrcyl.laws.dugdale import edge_of_strength
from jkrcyl.model.problem import Problem
from jkrcyl.model.single_patch import solver
from jkrcyl.numerics import cohesive as co
from jkrcyl.numerics import cohesive_branch as cb
from jkrcyl.numerics import cohesive_contactless as cl
from jkrcyl.numerics import cohesive_top_zone as tz
from jkrcyl.numerics import cohesive_zones as cz

EQ = jkrcyl.equilibria
M, THETA, GB, LAM = 0.1, 10.0, 1 / 2.8, 20.0
S0 = EQ.zone_strength(LAM, M, THETA)


@pytest.fixture(scope="module")
def law():
    return tz.law_of(M * THETA, S0, THETA, GB)


@pytest.fixture(scope="module")
def cv():
    return EQ.curve(M, THETA, regime="top-bridge", gb=GB, s0=S0)


def rows(cv, contact):
    """Indices of the curve's states with (eps > 0) or without contact."""
    return np.flatnonzero((cv.eps > 0) == contact)


def test_three_families_one_past_the_touch_two_to_the_top_closing(cv, law):
    """Junctions at eps 0.0155 and 0.796 on the sub-critical branch and one past the receding limit (1.48) on the
    super-critical one; only the first reaches the touch."""
    fam = np.floor(cv.a).astype(int)
    assert fam.tolist() == sorted(fam.tolist()) and set(fam.tolist()) == {0, 1, 2}
    assert np.all(np.diff(cv.a) > 0) and np.allclose(cv.c_top, math.pi * (cv.a - fam), rtol=1e-12)
    assert cv.ends[0].startswith("the contact vanished (touch)")
    assert cv.ends[1].startswith("the top closes") and cv.ends[2].startswith("the top closes")
    crit = 2 * math.atan(EQ.a_crit(THETA, gb=GB))                    # the receding contact eps_crit
    assert cv.eps[fam == 1].max() < crit < cv.eps[fam == 2].min()
    assert not (cv.stable_load.any() or cv.stable_grip.any() or cv.stable_grip_work.any())
    assert cv.feasible.all() and np.all(cv.h_pi_over_Delta <= law.h0 + 1e-9)
    # each family ends where the gap at the top closes (the first after its contact vanished)
    for j in (0, 1, 2):
        assert cv.h_pi_over_Delta[fam == j][-1] == pytest.approx(0.0, abs=1e-10)
    assert np.all(cv.eps[fam == 0][rows(cv, False)[0] - np.flatnonzero(fam == 0)[0]:] == 0)
    assert np.all(cv.eps[fam >= 1] > 0)


def test_contact_states_are_those_solved_alone(cv, law):
    idx = rows(cv, True)
    for i in idx[::6]:
        alone = tz.state_at(law, cv.c_top[i], cv.eps[i] * 1.01, (cv.c[i] - cv.eps[i]) * 1.05)
        for got, want in ((alone.eps, cv.eps[i]), (alone.c, cv.c[i]), (alone.p, cv.P_star[i] * THETA),
                          (alone.delta_over_Delta, cv.delta_over_Delta[i])):
            assert got == pytest.approx(want, abs=1e-10)
    picked = [i for i in idx if 1e-5 < cv.c_top[i] < 2e-3 and cv.eps[i] > 1e-3]
    assert len(picked) >= 4
    for i in picked:
        alone = cz.top_zone_states(cv.eps[i], law.m, law.s0, THETA, GB, n=law.contact(cv.eps[i])[0])
        got = min(alone, key=lambda s: abs(s.c_top - cv.c_top[i]))
        assert got.c_top == pytest.approx(cv.c_top[i], rel=1e-10)
        assert got.c == pytest.approx(cv.c[i], abs=1e-10)
        assert got.p == pytest.approx(cv.P_star[i] * THETA, abs=1e-10)
        assert got.delta_over_Delta == pytest.approx(cv.delta_over_Delta[i], abs=1e-10)
        assert got.delta_over_Delta + GB / 2 * got.p == pytest.approx(cv.delta_work_over_Delta[i], abs=1e-10)


def test_states_without_contact_are_those_solved_alone(cv, law):
    idx = rows(cv, False)
    assert len(idx) >= 20
    for i in idx[::4]:
        alone = cz.contactless_states(cv.c[i], law.m, law.s0, THETA, GB)
        got = min(alone, key=lambda s: abs(s.c_top - cv.c_top[i]))
        assert got.c_top == pytest.approx(cv.c_top[i], rel=1e-10)
        assert got.p == pytest.approx(cv.P_star[i] * THETA, abs=1e-10)
        assert got.delta_over_Delta == pytest.approx(cv.delta_over_Delta[i], abs=1e-10)


def test_the_pin_held_by_two_zones_is_its_own_mirror(cv, law):
    """phi -> phi + pi turns a two-zone state (c, c_top) into (c_top, c) with p -> -p, delta/Delta -> -2 -
    delta/Delta: each state's mirror solves both zone-end conditions (closed form, no trace), and the family runs
    from the bottom touch (h(0) = 0) to its mirror, the top touch (measured 1e-13)."""
    idx = rows(cv, False)
    first, last = idx[0], idx[-1]
    assert cv.c[first] == pytest.approx(cv.c_top[last], rel=1e-9) and cv.c_top[first] == pytest.approx(cv.c[last],
                                                                                                        rel=1e-9)
    assert cv.P_star[first] == pytest.approx(-cv.P_star[last], abs=1e-10)
    assert cv.delta_over_Delta[first] == pytest.approx(-2 - cv.delta_over_Delta[last], abs=1e-10)
    for i in idx[::5]:
        mirror = cz.contactless_state(cv.c_top[i], law.m, law.s0, THETA, GB, c_top=cv.c[i])
        assert mirror.fields.gap(math.pi - cv.c[i])[0] == pytest.approx(law.h0, abs=1e-10)
        assert mirror.p == pytest.approx(-cv.P_star[i] * THETA, abs=1e-10)
        assert mirror.delta_over_Delta == pytest.approx(-2 - cv.delta_over_Delta[i], abs=1e-10)


def test_continuous_with_the_single_patch_at_the_junction(cv):
    """Each family's first state (c_top = 1e-9) is the single patch's at its contact (the solver's own, no top
    zone) to ~ c_top log(1/c_top) (2e-8), where that state's gap at the top is the range."""
    pb = Problem(M, THETA, GB, 0.0, edge_of_strength(S0))
    sv = solver(pb)
    for j in (0, 1, 2):
        i = np.flatnonzero(np.floor(cv.a) == j)[0]
        c, p, dn, _, h = sv.at_contact(np.array([cv.eps[i]]))
        assert abs(p[0] / THETA - cv.P_star[i]) < 1e-6 and abs(dn[0] - cv.delta_over_Delta[i]) < 1e-6
        assert abs(c[0] - cv.c[i]) < 1e-6 and h[0] == pytest.approx(sv.law.h0, abs=1e-6)


def test_slopes_are_differences_of_states_solved_alone(cv, law):
    """The curve's per-point slopes d/da (a = j + c_top/pi; with contact by implicit differentiation at a fixed
    contact, cohesive_top_zone.slopes) against central differences of states solved alone at c_top (1 +- 1e-3;
    1e-4 from c_top 1e-4) (with contact) or re-solved by the scan at c (1 +- 1e-4) (without): measured 1e-7..2e-5
    relative (the states' noise over the steps, which dominates below c_top ~ 1e-7: both routes scatter by 4e-4 at
    c_top 2e-9)."""
    for i in [i for i in rows(cv, True)[::3] if cv.c_top[i] > 1e-7]:
        h = (1e-3 if cv.c_top[i] < 1e-4 else 1e-4) * cv.c_top[i]          # noise below, truncation above
        g = [tz.state_at(law, cv.c_top[i] + s * h, cv.eps[i], cv.c[i] - cv.eps[i]) for s in (1, -1)]
        assert cv.dP_star_da[i] == pytest.approx(math.pi * (g[0].p - g[1].p) / (2 * h) / THETA, rel=1e-4)
        assert cv.ddelta_da[i] == pytest.approx(
            math.pi * (g[0].delta_over_Delta - g[1].delta_over_Delta) / (2 * h), rel=1e-4)
    for i in rows(cv, False)[1::6]:
        h = 1e-4 * cv.c[i]
        g = [min(cz.contactless_states(cv.c[i] + s * h, law.m, law.s0, THETA, GB),
                 key=lambda st: abs(st.c_top - cv.c_top[i])) for s in (1, -1)]
        da = (g[0].c_top - g[1].c_top) / math.pi
        assert cv.dP_star_da[i] == pytest.approx((g[0].p - g[1].p) / da / THETA, rel=1e-5)
        assert cv.ddelta_work_da[i] == pytest.approx((g[0].delta_work_over_Delta - g[1].delta_work_over_Delta) / da,
                                                     rel=1e-5)


def chebyshev_work(states):
    """int p d(delta/Delta) over states at the Chebyshev-Lobatto nodes of their parameter (16 nodes)."""
    n = len(states)
    x = np.cos(np.pi * np.arange(n) / (n - 1))[::-1]
    p, d = (np.array([getattr(s, k) for s in states]) for k in ("p", "delta_over_Delta"))
    work = C.chebint(C.chebmul(C.chebfit(x, p, n - 1), C.chebder(C.chebfit(x, d, n - 1))))
    return C.chebval(1, work) - C.chebval(-1, work)


def lobatto(lo, hi, n=16):
    return lo + (hi - lo) * (1 - np.cos(np.pi * np.arange(n) / (n - 1))) / 2


def test_energy_changes_by_p_d_delta_along_the_curve(cv, law):
    """Between neighbouring states of the curve (with contact: states solved alone at c_top; without: at c, c_top
    re-solved by the scan), E(b) - E(a) = int p d(delta/Delta) to 1e-8; across the touch (the last contact state to
    the first without) to the trapezoid's error."""
    contact, free = rows(cv, True), rows(cv, False)
    first, second = contact[cv.a[contact] < 1], contact[cv.a[contact] > 1]
    for i in (first[len(first) // 2], second[len(second) // 2], second[-2]):      # the last: to the closing
        sts, prev = [], None
        for ct in lobatto(cv.c_top[i], cv.c_top[i + 1]):
            e0, d0 = (cv.eps[i], cv.c[i] - cv.eps[i]) if prev is None else (prev.eps, prev.c - prev.eps)
            prev = tz.state_at(law, ct, e0, d0)
            sts.append(prev)
        dE = tz.potential(sts[-1]) - tz.potential(sts[0])
        assert abs(dE - chebyshev_work(sts)) < 1e-8
    for i in (free[0], free[len(free) // 2]):
        sts = [min(cz.contactless_states(c, law.m, law.s0, THETA, GB), key=lambda s: abs(s.c_top - cv.c_top[i]))
               for c in lobatto(cv.c[i], cv.c[i + 1])]
        assert abs(cb.potential(sts[-1]) - cb.potential(sts[0]) - chebyshev_work(sts)) < 1e-8
    k = free[0]                                        # the touch: the contact vanished between k - 1 and k
    a = tz.state_at(law, cv.c_top[k - 1], cv.eps[k - 1], cv.c[k - 1] - cv.eps[k - 1])
    b = cz.contactless_state(cv.c[k], law.m, law.s0, THETA, GB, c_top=cv.c_top[k])
    trap = 0.5 * (a.p + b.p) * (b.delta_over_Delta - a.delta_over_Delta)
    assert abs(cb.potential(b) - cb.potential(a) - trap) < 1e-8


def test_without_contact_the_held_energy_is_a_maximum_under_grip_a_saddle_under_load(cv, law):
    """The energy's own Hessian (differences of the total potential of states with held zone ends at a held
    approach) is 2 s0 G (cohesive_contactless.two_zone_matrix, from the gap at the ends: measured 1e-6 relative),
    negative definite; under load, E - p delta in (delta, c, c_top) has a negative eigenvalue."""
    i = rows(cv, False)[10]
    st = cz.contactless_state(cv.c[i], law.m, law.s0, THETA, GB, c_top=cv.c_top[i])

    def energy(x):
        dn, c, ct = x
        held = co._state(0.0, c, None, dn, None, co.zones_of(c, ct), law.m, law.s0, law.kernel, law.gb, 0, ct)
        return cb.potential(held) - st.p * dn
    x0, h = np.array([st.delta_over_Delta, st.c, st.c_top]), 1e-4 * np.array([1.0, st.c, st.c_top])
    H = np.empty((3, 3))
    for r in range(3):
        for s in range(3):
            er, es = h[r] * np.eye(3)[r], h[s] * np.eye(3)[s]
            H[r, s] = (energy(x0 + er + es) - energy(x0 + er - es) - energy(x0 - er + es) + energy(x0 - er - es)) / (
                4 * h[r] * h[s])
    G = cl.two_zone_matrix(law, st)
    assert np.allclose(H[1:, 1:] / (2 * law.s0), G, rtol=1e-5)
    assert np.all(np.linalg.eigvalsh(G) < 0) and np.linalg.eigvalsh(0.5 * (H + H.T))[0] < 0
    assert not (cv.stable_grip[i] or cv.stable_load[i] or cv.stable_grip_work[i])


def test_with_contact_every_state_a_saddle_by_the_full_held_matrix(cv, law):
    """The curve's flags come from the top entry G_22 (and the order of the controls); the full held-zone-end
    matrix under each control (cohesive_top_zone.zone_matrix) is indefinite or negative at the same states."""
    for i in rows(cv, True)[[3, 15, -2]]:
        st = tz.state_at(law, cv.c_top[i], cv.eps[i], cv.c[i] - cv.eps[i])
        for control in ("load", "grip", "grip-work"):
            G = tz.zone_matrix(law, st, control, work_shift=GB / 2)
            assert np.linalg.eigvalsh(0.5 * (G + G.T))[0] < 0


def test_the_physical_curve_is_the_normalised_one_in_units():
    """Identical nu 0.3 bodies (vartheta 1) at M 0.67, lambda 10: the bridge reaches the touch and goes on without
    contact; Contact.curve carries the normalised API's states with P = P* load_scale [N/m], delta = (delta/Delta)
    Delta [m]."""
    m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    base = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
    pin = jkrcyl.Contact.with_lambda(R=10e-3, Delta=1e-6, w=0.05 * (0.67 / base.M) ** 2, materials=m, lambda_=10.0)
    got = pin.curve(regime="top-bridge")
    ref = EQ.curve(pin.M, m.theta, regime="top-bridge", gb=m.inv_G_I / m.beta, s0=pin.problem.edge.s0)
    assert got.ends == ref.ends and got.ends[0].startswith("the contact vanished")
    assert np.any(got.eps == 0) and np.array_equal(got.c_top, ref.c_top)
    assert np.allclose(got.P, ref.P_star * pin.load_scale, rtol=1e-12, atol=0)
    assert np.allclose(got.delta, ref.delta_over_Delta * pin.Delta, rtol=1e-12, atol=0)
    assert np.allclose(got.delta_work, ref.delta_work_over_Delta * pin.Delta, rtol=1e-12, atol=0)


def test_no_bridge_is_a_value_error_naming_regime():
    m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    jkr = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
    with pytest.raises(ValueError, match=r"^regime: 'top-bridge' needs a law of finite range .*h\(pi\) = 0"):
        jkr.curve(regime="top-bridge")
    with pytest.raises(ValueError, match="^regime: no top bridge for this problem"):
        EQ.curve(1.0, 1.0, regime="top-bridge", gb=GB, s0=EQ.zone_strength(10.0, 1.0, 1.0))
    with pytest.raises(ValueError, match="^regime must be one of .*top-bridge"):
        jkr.curve(regime="top bridge")
    with pytest.raises(ValueError, match="^a: the top bridge"):
        EQ.curve(M, THETA, regime="top-bridge", gb=GB, s0=S0, a=[0.5])


def test_cli_top_bridge(capsys):
    """JKR: one line naming regime, exit 2; the cohesive law: the families' ends on comment lines, then the rows."""
    assert cli_main(["curve", "--M", "1.0", "--theta", "1", "--gb", "0.357", "--regime", "top-bridge"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "regime: 'top-bridge' needs a law of finite range" in err
    assert cli_main(["curve", "--M", str(M), "--theta", str(THETA), "--gb", str(GB), "--lambda", str(LAM),
                     "--regime", "top-bridge"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[1].startswith("# family 0: the contact vanished") and lines[2].startswith("# family 1: the top")
    ref = EQ.curve(M, THETA, regime="top-bridge", gb=GB, s0=S0)
    assert len(lines) == 2 + len(ref.ends) + len(ref.a)


# --- over material pairs -----------------------------------------------------------------------------------------
NU = hst.just(0.0) | hst.floats(0.01, 0.49)           # 0 or above the validated magnitude floor
MODULUS = hst.floats(1e8, 1e11) | hst.just(math.inf)


@pytest.mark.slow                       # ~13 s: five law problems traced (the fast suite's budget)
@settings(max_examples=2, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(E=MODULUS, nu=NU, E_I=MODULUS, nu_I=NU, m=hst.floats(0.5, 2.0), lam=hst.floats(20.0, 100.0))
@example(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3, m=0.67, lam=10.0)        # identical bodies: past the touch
@example(E=1e8, nu=0.0, E_I=math.inf, nu_I=0.0, m=1.0, lam=20.0)       # a rigid pin: past the touch, c_top 6e-4
@example(E=math.inf, nu=0.3, E_I=2.6e9, nu_I=0.3, m=1.0, lam=50.0)      # a rigid cradle: the top closes
def test_bridge_states_lie_between_the_junction_and_the_closing_all_saddles(E, nu, E_I, nu_I, m, lam):
    """Every state of curve(regime="top-bridge") is feasible with 0 <= h(pi) <= h0 (between the closing and the
    junction), c_top grows from the junction's 0 (the first state: the single patch's there, h(pi) = h0 to 1e-6),
    a family that ends by closing or touching the top ends at h(pi) = 0, and every state is unstable under every
    control; or there is no bridge (ValueError naming regime)."""
    assume(math.isfinite(E) or math.isfinite(E_I))                      # not both rigid
    mat = jkrcyl.Materials.from_young(E=E, nu=nu, E_I=E_I, nu_I=nu_I)
    theta = mat.theta if math.isfinite(mat.theta) else 1.0
    M = m / theta
    gb, ar = mat.inv_G_I / mat.beta, mat.alpha_ratio
    s0 = EQ.zone_strength(lam, M, mat.theta)
    try:
        cv = EQ.curve(M, mat.theta, regime="top-bridge", gb=gb, alpha_ratio=ar, s0=s0)
    except ValueError as exc:
        assert str(exc).startswith(("regime: no top bridge", "regime: the top bridge is not traced"))
        return
    h0 = m * m / s0 if math.isfinite(mat.theta) else M * M / s0
    assert cv.feasible.all() and np.all((cv.h_pi_over_Delta > -1e-9) & (cv.h_pi_over_Delta < h0 + 1e-9))
    assert not (cv.stable_load.any() or cv.stable_grip.any() or cv.stable_grip_work.any())
    fam = np.floor(cv.a).astype(int)
    for j, end in enumerate(cv.ends):
        h = cv.h_pi_over_Delta[fam == j]
        if h.size == 0:                               # a family whose trace stopped at once says so
            assert end.startswith("no state traced from the junction")
            continue
        assert h[0] == pytest.approx(h0, abs=1e-6) and np.all(np.diff(cv.c_top[fam == j]) > 0)
        if end.startswith(("the top closes", "the contact vanished")):
            assert h[-1] == pytest.approx(0.0, abs=1e-9)
