"""Two contact arcs and full contact (issue 12): jkrcyl.model.two_patch, jkrcyl.analysis.tracing, confined.

References, all independent of the two-arc solve under test:
* the closed-form single patch (4.4), (5.8), (5.10) through jkrcyl.equilibria (kernels checked against
  mpmath in test_load/test_approach/test_gap) -- the a_top -> 0 and a -> 0 limits and the stability flags;
* the mirror symmetry phi -> phi + pi, which the engine does not use (the arcs sit at 0 and pi);
* finite differences of the elastic energy U* = [(1 + delta/Delta) P* - B*]/2 (pressure times rigid overlap),
  never the edge coefficients k, for the energy release rate G = w;
* scipy.integrate.quad of the pressure (2.2) and of the displacement integral (5.2) for the gap;
* the full-contact law as the limit of two arcs whose gaps close.
"""
import json
import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from jkrcyl import Contact, Materials, cli
from jkrcyl import equilibria as eq
from jkrcyl.analysis import pull_off, tracing
from jkrcyl.model import two_patch
from jkrcyl.model.problem import Problem
from jkrcyl.numerics import two_arcs
from jkrcyl.results import ConfinedEvents, TwoPatchCurve
from jkrcyl.results.paths import REGIMES

THETA = 1.0
GB = eq.incompressible_gb(THETA)


def _pb(M, theta, gb=None, alpha_ratio=0.0):
    return Problem(M, theta, eq.incompressible_gb(theta) if gb is None else gb, alpha_ratio)


class tp:
    """The calls of these tests in the normalised form (M, theta, gb, alpha_ratio; gb defaults to the
    incompressible pin the tests were written for), on jkrcyl.model.two_patch and jkrcyl.analysis."""

    N_NODES, EPS_AXIS, GAP_FULL = two_patch.N_NODES, tracing.EPS_AXIS, tracing.GAP_FULL
    REGIMES, TwoPatchCurve = REGIMES, TwoPatchCurve
    _near, _domain, _clipper = staticmethod(tracing._near), staticmethod(tracing._domain), \
        staticmethod(tracing._clipper)

    @staticmethod
    def _linear(eps, eps_top, theta, gb, n, alpha_ratio=0.0):
        return two_arcs.linear(eps, eps_top, theta, gb, alpha_ratio, n)

    @staticmethod
    def solve(M, theta, eps_top=None, eps=None, gb=None, guess=None, alpha_ratio=0.0):
        return two_patch.solve(_pb(M, theta, gb, alpha_ratio), eps_top=eps_top, eps=eps, guess=guess)

    @staticmethod
    def equilibrium_state(eps, eps_top, M, theta, gb, alpha_ratio=0.0):
        return two_patch.equilibrium_state(_pb(M, theta, gb, alpha_ratio), eps, eps_top)

    @staticmethod
    def residual(eps, eps_top, M, theta, gb, alpha_ratio=0.0):
        return two_patch.residual(_pb(M, theta, gb, alpha_ratio), eps, eps_top)

    @staticmethod
    def fixed_arcs(eps, eps_top, d, M, theta, gb, n=two_patch.N_NODES, alpha_ratio=0.0):
        return two_patch.fixed_arcs(_pb(M, theta, gb, alpha_ratio), eps, eps_top, d, n)

    @staticmethod
    def hessian(eps, eps_top, d, M, theta, gb, alpha_ratio=0.0):
        return two_patch.hessian(_pb(M, theta, gb, alpha_ratio), eps, eps_top, d)

    @staticmethod
    def full_contact(theta, P_star=None, delta_over_Delta=None, gb=None, alpha_ratio=0.0):
        return eq.full_contact(theta, P_star, delta_over_Delta, gb=eq.incompressible_gb(theta) if gb is None else gb,
                               alpha_ratio=alpha_ratio)

    @staticmethod
    def onset_angles(M, theta, gb, alpha_ratio=0.0):
        return list(tracing.onset_angles(_pb(M, theta, gb, alpha_ratio)))

    @staticmethod
    def confined_events(M, theta):
        return eq.confined_events(M, theta, gb=eq.incompressible_gb(theta))


def onset(M, theta=THETA, regime="sub-critical", bracket=(0.5, 0.91)):
    """Closed-form single patch with h(pi) = 0: (a, P*, delta/Delta) from (4.4), (5.8), (5.10)."""
    h = lambda a: float(eq.curve(M, theta, regime, a=np.array([a]), gb=eq.incompressible_gb(theta)).h_pi_over_Delta[0])
    a = brentq(h, *bracket, xtol=1e-16, rtol=1e-15)
    c = eq.curve(M, theta, regime, a=np.array([a]), gb=eq.incompressible_gb(theta))
    return a, float(c.P_star[0]), float(c.delta_over_Delta[0])


@pytest.fixture(scope="module")
def branches_04():
    return eq.two_patch(0.4, THETA, gb=eq.incompressible_gb(THETA))


# --- the engine against the closed form --------------------------------------------------------------
@pytest.mark.parametrize("theta, gb", [(1.0, 0.5), (2.0, 0.3), (0.7, 0.9)])
@pytest.mark.parametrize("a", [0.2, 0.6, 1.3])
def test_single_arc_engine_matches_closed_form(theta, gb, a):
    M = 0.35
    regime = "sub-critical" if a < eq.a_crit(theta, gb) else "super-critical"
    ref = eq.curve(M, theta, regime, a=np.array([a]), gb=gb)
    lin = tp._linear(2 * math.atan(a), 0.0, theta, gb, 32)
    d = (M / math.pi - lin.q0[2]) / lin.q1[2]        # Griffith k = M/pi
    assert d == pytest.approx(ref.delta_over_Delta[0], rel=1e-11, abs=1e-12)
    assert lin.q0[0] + d * lin.q1[0] == pytest.approx(ref.P_star[0], rel=1e-11, abs=1e-12)
    assert lin.gap(math.pi, d)[0] == pytest.approx(ref.h_pi_over_Delta[0], rel=1e-10, abs=1e-12)


# --- continuity at the two ends of a branch ----------------------------------------------------------
@pytest.mark.parametrize("M", [0.4, 0.5])
def test_top_arc_to_zero_tends_to_single_patch_with_closed_gap(M):
    a_on, P_on, d_on = onset(M)
    s = tp.solve(M, THETA, eps_top=1e-20, guess=2 * math.atan(a_on))
    assert s.G_bot == pytest.approx(1, abs=1e-9)
    assert s.a == pytest.approx(a_on, rel=1e-8)
    assert s.P_star == pytest.approx(P_on, rel=1e-8)
    assert s.delta_over_Delta == pytest.approx(d_on, rel=1e-8)


def test_bottom_arc_to_zero_tends_to_mirrored_single_patch():
    M = 0.4
    a_on, P_on, d_on = onset(M)
    s = tp.solve(M, THETA, eps=1e-20, guess=2 * math.atan(a_on))
    assert s.a_top == pytest.approx(a_on, rel=1e-8)
    assert s.P_star == pytest.approx(-P_on, rel=1e-8)
    assert s.delta_over_Delta == pytest.approx(-2 - d_on, rel=1e-8)


def test_branch_from_onset_ends_on_both_single_patches(branches_04):
    a_on, P_on, _ = onset(0.4)
    b = [b for b in branches_04 if b.ends == ("single", "mirror")]
    assert len(b) == 1
    b = b[0]
    assert b.eps[0] == pytest.approx(2 * math.atan(a_on), abs=1e-3)     # ends at a_top = EPS_AXIS
    assert b.eps_top[-1] == pytest.approx(2 * math.atan(a_on), abs=1e-3)
    assert np.max(np.abs(b.G_bot - 1)) < 1e-8 and np.max(np.abs(b.G_top - 1)) < 1e-8


# --- symmetry --------------------------------------------------------------------------------------
def test_mirror_maps_equilibria_onto_equilibria(branches_04):
    M = 0.4
    for b in branches_04:
        for i in np.linspace(1, b.a.size - 2, 5).astype(int):
            e, et = b.eps[i], b.eps_top[i]
            m = tp.equilibrium_state(et, e, M, THETA, GB)          # the swapped arcs, solved afresh
            assert abs(tp.residual(et, e, M, THETA, GB)) < 1e-9
            assert m.P_star == pytest.approx(-b.P_star[i], rel=1e-8, abs=1e-10)
            assert m.delta_over_Delta == pytest.approx(-2 - b.delta_over_Delta[i], rel=1e-8, abs=1e-10)


def test_mirror_maps_the_traced_branches_onto_themselves(branches_04):
    """The set of equilibria is mirror-symmetric: every traced point (eps, eps_top), swapped, lies on a traced
    branch (within the continuation's step), with P* -> -P* and delta -> -2 Delta - delta on the polyline."""
    pts = [np.column_stack([np.log(b.eps), np.log(b.eps_top)]) for b in branches_04]
    for b in branches_04:
        for i in range(b.a.size):
            swapped = np.array([math.log(b.eps_top[i]), math.log(b.eps[i])])
            assert tp._near(swapped, pts, 0.05), (b.ends, i)
    for b in branches_04:                   # (P*, delta) of the mirrored polyline: the same curve in the plane
        other = [c for c in branches_04 if tp._near(np.log([b.eps_top[1], b.eps[1]]), [np.column_stack(
            [np.log(c.eps), np.log(c.eps_top)])], 0.05)][0]
        mirrored = np.column_stack([-2 - b.delta_over_Delta, -b.P_star])
        assert all(tp._near(x, [np.column_stack([other.delta_over_Delta, other.P_star])], 0.05) for x in mirrored)


def test_feasible_flag_agrees_with_a_dense_gap_check_along_the_branches(branches_04):
    """h >= 0 outside both arcs, densely (2000 angles per state, uniform and at the ends) at every third traced
    point and the ends, against the flag from GAP_SAMPLES Chebyshev angles."""
    for b in branches_04:
        for i in sorted({*range(0, b.a.size, 3), b.a.size - 1}):
            s = tp.equilibrium_state(b.eps[i], b.eps_top[i], 0.4, THETA, GB)
            lo, hi = s.eps, math.pi - s.eps_top
            phi = np.concatenate([np.linspace(lo, hi, 1002)[1:-1],
                                  lo + (hi - lo) * np.geomspace(1e-9, 1e-2, 500), hi - (hi - lo) * np.geomspace(1e-9, 1e-2, 500)])
            dense = float(np.min(s.gap(phi)))
            assert (dense >= -1e-9) == bool(b.feasible[i]), (b.ends, i, dense, b.gap_min[i])


def test_branch_crosses_equal_arcs_at_zero_load_and_centred_pin(branches_04):
    b = [b for b in branches_04 if b.ends == ("single", "mirror")][0]
    i = np.nonzero(np.diff(np.sign(b.eps - b.eps_top)))[0][0]
    e = brentq(lambda x: tp.residual(x, x, 0.4, THETA, GB), min(b.eps[i], b.eps_top[i]) - 0.05,
               max(b.eps[i + 1], b.eps_top[i + 1]) + 0.05, xtol=1e-15)
    s = tp.equilibrium_state(e, e, 0.4, THETA, GB)
    assert abs(s.P_star) < 1e-10
    assert s.delta_over_Delta == pytest.approx(-1, abs=1e-10)


# --- energy ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("M, theta, gb, eps_top, guess", [(0.4, 1.0, 0.5, 0.5, 1.0), (0.3, 2.0, 0.75, 1.95, 0.8)])
def test_energy_release_at_each_patch_equals_w(M, theta, gb, eps_top, guess):
    """G = (1/2R) dU/d eps at fixed delta, i.e. G/w = (dU*/d eps)/(2 vartheta M^2), from the energy alone."""
    s = tp.solve(M, theta, eps_top=eps_top, gb=gb, guess=guess)
    d = s.delta_over_Delta
    U = lambda e, et: tp.fixed_arcs(e, et, d, M, theta, gb).energy
    h = 1e-5
    for dU in ((U(s.eps + h, s.eps_top) - U(s.eps - h, s.eps_top)) / (2 * h),
               (U(s.eps, s.eps_top + h) - U(s.eps, s.eps_top - h)) / (2 * h)):
        assert dU / (2 * theta * M * M) == pytest.approx(1, abs=1e-6)


def test_load_is_conjugate_to_approach():
    """dU*/d(delta/Delta) = P* at fixed arcs (Clapeyron, not used by the solver)."""
    e, et, d, h = 1.1, 0.6, -0.9, 1e-5
    U = lambda x: tp.fixed_arcs(e, et, x, 0.4, 1.7, 0.4).energy
    assert (U(d + h) - U(d - h)) / (2 * h) == pytest.approx(tp.fixed_arcs(e, et, d, 0.4, 1.7, 0.4).P_star,
                                                           rel=1e-8)


def test_full_contact_is_the_limit_of_closing_gaps_and_energy_consistent():
    th, gb, d = 2.0, 0.75, -0.5
    fc = tp.full_contact(th, delta_over_Delta=d, gb=gb)
    s = tp.fixed_arcs(1.6, math.pi - 1.6 - 0.01, d, 0.4, th, gb)      # two arcs, gaps of 0.01 rad
    assert s.P_star == pytest.approx(fc.P_star, rel=1e-4)
    assert s.B_star == pytest.approx(fc.B_star, rel=1e-4)
    assert s.energy == pytest.approx(fc.energy, rel=1e-4)
    h = 1e-6
    dU = (tp.full_contact(th, delta_over_Delta=d + h, gb=gb).energy
          - tp.full_contact(th, delta_over_Delta=d - h, gb=gb).energy) / (2 * h)
    assert dU == pytest.approx(fc.P_star, rel=1e-8)
    # N0 = -1/pi: entirely in tension for |P*| < 1
    assert tp.full_contact(th, P_star=0.99, gb=gb).tension_everywhere
    assert not tp.full_contact(th, P_star=1.01, gb=gb).tension_everywhere


def test_full_contact_tension_zone():
    """n = N0 + N1 cos(phi) with N0 = -1/pi (alpha* = 0), N1 = P*/pi: at P* = 2 the interface is in tension
    where cos(phi) < 1/2, i.e. |phi| > pi/3 (the top and the sides), compressed round the bottom."""
    fc = tp.full_contact(THETA, P_star=2.0, gb=GB)
    assert fc.tension_half_angle == pytest.approx(2 * math.pi / 3, rel=1e-12)   # about phi = pi
    phi = np.array([0.0, math.pi / 3 - 1e-6, math.pi / 3 + 1e-6, math.pi, -math.pi / 3 - 1e-6])
    assert fc.in_tension(phi).tolist() == [False, False, True, True, True]
    down = tp.full_contact(THETA, P_star=-2.0, gb=GB)          # pushed down: compressed at the top
    assert down.in_tension(np.array([0.0, math.pi])).tolist() == [True, False]
    assert down.tension_half_angle == pytest.approx(2 * math.pi / 3, rel=1e-12)  # about phi = 0
    assert tp.full_contact(THETA, P_star=0.5, gb=GB).tension_half_angle == math.pi


def test_a_path_running_into_full_contact_is_labelled_full():
    """The branch tracer's boundaries on a zero set known in closed form, eps - eps_top = 0.3 (a stand-in for F):
    one way it meets eps + eps_top = pi - GAP_FULL ('full'), the other way eps_top -> 0 ('single')."""
    from jkrcyl.numerics import continuation as cont
    f = lambda u: math.exp(u[0]) - math.exp(u[1]) - 0.3
    for t0, label in ((np.array([1.0, 1.0]), "full"), (np.array([-1.0, -1.0]), "single")):
        path = cont.trace(f, np.log([0.8, 0.5]), t0, tp._domain, tp._clipper(f), h0=0.05, h_max=0.5)
        assert path.boundary == label
        e, et = np.exp(path.points[-1])
        assert e - et == pytest.approx(0.3, abs=1e-9)
        if label == "full":
            assert e + et == pytest.approx(math.pi - tp.GAP_FULL, abs=1e-9)
        else:
            assert et == pytest.approx(tp.EPS_AXIS, rel=1e-6)


# --- pressure, gap, convergence ---------------------------------------------------------------------
@pytest.fixture(scope="module")
def state():
    return tp.solve(0.4, THETA, eps_top=0.5, guess=1.0)


def test_pressure_integrates_to_the_load(state):
    """(2.2): R int N cos(phi) dphi = P, by quad in phi = c + e cos(t) (removes the 1/sqrt end singularities)."""
    total = 0.0
    for c, e in ((0.0, state.eps), (math.pi, state.eps_top)):
        f = lambda t: state.pressure(c + e * math.cos(t))[0] * math.cos(c + e * math.cos(t)) * e * math.sin(t)
        total += quad(f, 1e-9, math.pi - 1e-9, limit=200, epsabs=1e-14, epsrel=1e-13)[0]
    assert total == pytest.approx(state.P_star, rel=1e-9)


def test_gap_from_direct_quadrature_of_5_2_and_nonnegative(state):
    """h(phi)/Delta from quad of (5.2) with the pressure, at exterior angles; and h >= 0 densely."""
    th, gb = THETA, GB
    K = lambda t: np.cos(t) * np.log(2 - 2 * np.cos(t)) + gb * np.cos(t) + 1 - 1 / (2 * th)
    for phi in (state.eps + 0.05, 0.5 * (state.eps + math.pi - state.eps_top), math.pi - state.eps_top - 0.05):
        disp = 0.0
        for c, e in ((0.0, state.eps), (math.pi, state.eps_top)):
            f = lambda t: (state.pressure(c + e * math.cos(t))[0] * K(phi - c - e * math.cos(t))
                           * e * math.sin(t))
            disp += quad(f, 1e-9, math.pi - 1e-9, limit=200, epsabs=1e-14, epsrel=1e-13)[0]
        d = state.delta_over_Delta
        h_ref = (1 - math.cos(phi)) - d * math.cos(phi) - th * disp
        assert state.gap(phi)[0] == pytest.approx(h_ref, rel=1e-8, abs=1e-11)
    phi = np.linspace(state.eps, math.pi - state.eps_top, 4001)[1:-1]
    assert np.all(state.gap(phi) >= 0)


def test_collocation_residual_is_small_inside_both_arcs(state):
    """Between the collocation nodes the contact condition h = 0 (5.1) still holds on both arcs."""
    for c, e in ((0.0, state.eps), (math.pi, state.eps_top)):
        phi = c + e * np.linspace(-0.999, 0.999, 301)
        assert np.max(np.abs(state.gap(phi))) < 1e-11


def test_spectral_convergence_in_the_nodes():
    errs = []
    ref = tp.fixed_arcs(1.2, 0.7, -0.8, 0.4, THETA, GB, n=64).P_star
    for n in (6, 10, 14, 18):
        errs.append(abs(tp.fixed_arcs(1.2, 0.7, -0.8, 0.4, THETA, GB, n=n).P_star - ref))
    assert errs[-1] < 1e-11
    assert all(b < a / 20 for a, b in zip(errs, errs[1:]) if a > 1e-13)


# --- stability -------------------------------------------------------------------------------------
@pytest.mark.parametrize("M, regime, a", [(0.3, "sub-critical", 0.2), (0.3, "sub-critical", 0.6),
                                          (0.3, "sub-critical", 0.05), (0.5, "super-critical", 2.5),
                                          (0.5, "super-critical", 1.0), (0.3, "super-critical", 1.6)])
def test_hessian_stability_of_a_single_arc_matches_closed_form(M, regime, a):
    """With no top arc the grip block is 1x1 and the load block (eps, delta) 2x2: compare with the signs of
    dG/da|_delta and dG/da|_P of the closed form (jkrcyl.equilibria)."""
    ref = eq.curve(M, THETA, regime, a=np.array([a]), gb=eq.incompressible_gb(THETA))
    e = 2 * math.atan(a)
    H, _, _ = tp.hessian(e, 0.0, float(ref.delta_over_Delta[0]), M, THETA, GB)
    sub = H[np.ix_([0, 2], [0, 2])]
    assert (H[0, 0] > 0) == bool(ref.stable_grip[0])
    assert bool(np.all(np.linalg.eigvalsh(sub) > 0)) == bool(ref.stable_load[0])


def test_hessian_is_symmetric(state):
    """Maxwell: d(G_bot)/d eps_top = d(G_top)/d eps at fixed delta (the solver symmetrises; check first)."""
    _, He, _ = tp.hessian(state.eps, state.eps_top, state.delta_over_Delta, 0.4, THETA, GB)
    assert He[0, 1] == pytest.approx(He[1, 0], rel=1e-6)


@pytest.mark.slow
@pytest.mark.parametrize("M", [0.3, 0.4, 0.5, 0.8])
def test_no_two_patch_state_is_stable_under_load_at_theta_1(M):
    """Finding of issue 12 (re-verified): at vartheta = 1 every two-patch equilibrium is unstable at fixed load."""
    for b in eq.two_patch(M, THETA, gb=eq.incompressible_gb(THETA)):
        assert not b.stable_load.any()


# --- API, CLI -------------------------------------------------------------------------------------
def test_contact_two_patch_and_validation():
    c = Contact(R=1.0, Delta=0.01, w=1e-4, materials=Materials(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0))
    bs = c.two_patch(n=20)
    for b in bs:
        assert b.a.size == 20 and b.a_top.size == 20
        assert set(b.table()) == set(tp.TwoPatchCurve.COLUMNS) | {"P", "delta", "delta_work"}   # dimensional
        np.testing.assert_allclose(b.P, b.P_star * c.load_scale, rtol=1e-15)
        np.testing.assert_allclose(b.delta_work, b.delta + b.P * c.materials.inv_G_I / (8 * math.pi), rtol=1e-12)
    with pytest.raises(ValueError, match="M"):
        eq.two_patch(-1, 1.0, gb=eq.incompressible_gb(1.0))
    with pytest.raises(ValueError, match="theta"):
        eq.two_patch(0.4, 0.2, gb=eq.incompressible_gb(0.2))
    with pytest.raises(ValueError, match="n"):
        eq.two_patch(0.4, 1.0, n=1, gb=eq.incompressible_gb(1.0))


def test_cli_two_patch_json(capsys):
    assert cli.main(["two-patch", "--M", "0.5", "--theta", "1", "--n", "12", "--format", "json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["M"] == 0.5 and len(out["branches"]) >= 1
    assert len(out["branches"][0]["P_star"]) == 12
    assert cli.main(["two-patch", "--M", "-1"]) == 2


# --- confined-regime events -------------------------------------------------------------------------
@pytest.mark.parametrize("M, regime, expect_growth", [(0.3, "sub-critical", False), (0.5, "super-critical", True),
                                                      (0.8, "super-critical", True)])
def test_direction_of_the_jump_at_the_fold(M, regime, expect_growth):
    """At fixed a, G/w = (M'/M)^2 along the closed-form family P*(a; M'), so a pull lowers G (the contact
    grows: zip) exactly when P* rises with M' -- the closed form's answer, against the engine's k1/P1."""
    p = [q for q in eq.stationary_points(M, THETA, "load", regime, gb=eq.incompressible_gb(THETA)) if q.kind == "min"][0]
    P = lambda m: float(eq.curve(m, THETA, regime, a=np.array([p.a]), gb=eq.incompressible_gb(THETA)).P_star[0])
    grows_closed_form = P(M * 1.001) > P(M * 0.999)
    assert grows_closed_form == expect_growth
    assert pull_off.grows_under_pull(Problem(M, THETA, GB), p.a, "load") == grows_closed_form


@pytest.mark.slow
@pytest.mark.parametrize("M, regime", [(0.3, "detachment"), (0.5, "zip-full")])
def test_confined_events(M, regime):
    ev = tp.confined_events(M, THETA)
    assert ev.regime == regime and ev.regime in tp.REGIMES
    ref = min((q for r in eq.REGIMES for q in eq.stationary_points(M, THETA, "load", r, gb=eq.incompressible_gb(THETA)) if q.kind == "min"),
              key=lambda q: abs(q.P_star - ev.P_fold))
    assert ev.P_fold == ref.P_star
    assert math.isnan(ev.P_top_contact)
    assert not ev.two_patch_stable_load


def test_zip_summary_uses_the_full_contact_law_of_the_pair():
    """Full contact is entirely in tension for |P*| < -pi N0 = 1/(1 - 2 vartheta alpha*/beta*) (N0 checked by quad
    of the kernel in test_alpha_full_contact_law): 1 at alpha* = 0, 1.25 at vartheta = 0.9, alpha*/beta* = 1/9;
    the confined analysis stores that law's answer at the fold, and the summary says it."""
    tension = lambda ar: eq.full_contact(0.9, P_star=-1.1, gb=0.37, alpha_ratio=ar).tension_everywhere
    ev = lambda ar: ConfinedEvents(0.5, 0.9, "zip-full", (0.3, 0.0), -1.1, math.nan, (), False, False, False,
                                   False, (), 0.37, ar, fold_in_tension=tension(ar))
    assert "entirely in tension" in ev(1 / 9).summary
    assert "partly compressed" in ev(0.0).summary


@pytest.mark.parametrize("M", [0.3, 0.5, 0.8])
def test_fixed_load_stability_flips_with_the_branch(M):
    """dG/dP* at fixed a is < 0 sub-critically and > 0 super-critically, so the emitted dG/da|_P kernel
    (stable_load) agrees with dP*/da > 0 on the sub-critical branch and with dP*/da < 0 on the other."""
    for regime, sign in (("sub-critical", 1), ("super-critical", -1)):
        c = eq.curve(M, THETA, regime, n=2000, gb=eq.incompressible_gb(THETA))
        assert np.array_equal(c.stable_load, sign * c.dP_star_da > 0)


# --- any alpha* (issue 12 item 1): the same checks with the alpha* kernel -----------------------------
# alpha*/beta* = 0.2 and -0.3 at vartheta = 1 (both inside (-1, 1/(2 vartheta))); references as above:
# finite differences of U* for G = w and for P*, the mirror (not used by the engine), quad of (2.2) and of
# (5.2) with the kernel K(t) of jkrcyl.numerics.arcs (typed from its docstring), the single patch of the
# same solver through jkrcyl.equilibria (a different code path: one arc, slopes along the grid).
ALPHAS = (0.2, -0.3)


def _K_alpha(t, th, gb, ar):
    """K(t) = cos t log(2 - 2 cos t) + k1 cos t + k0 + ar (pi sign(t) sin t - t sin t), |t| < 2 pi: the
    displacement form of (2.1) as defined in numerics.arcs; the constants k0, k1 (derived in derive/green.py,
    checked there) are read from the engine's Kernel, the functional form is typed here, and the checks are
    of the collocation, the quadrature of the pressure and the laws built on K -- not of the constants."""
    from jkrcyl.numerics.arcs import Kernel
    kn = Kernel(th, gb, ar)
    return (2 * np.cos(t) * np.log(np.abs(2 * np.sin(t / 2))) + kn.k1 * np.cos(t) + kn.k0
            + ar * (np.pi * np.sign(t) * np.sin(t) - t * np.sin(t)))


@pytest.fixture(scope="module", params=[(0.2, 0.5, 1.0), (-0.3, 0.01, 0.3)])
def state_alpha(request):
    """A two-patch equilibrium at M = 0.4 (alpha*/beta*, eps_top, guess of eps on its branch)."""
    ar, eps_top, guess = request.param
    return tp.solve(0.4, THETA, eps_top=eps_top, guess=guess, alpha_ratio=ar)


def test_alpha_energy_release_at_each_patch_equals_w(state_alpha):
    """G/w = (dU*/d eps_i)/(2 vartheta M^2) at fixed delta from U* alone: Griffith k = M/pi holds for any alpha*
    (the alpha* part of the kernel is bounded, so it leaves the square-root edge field alone)."""
    s, M = state_alpha, 0.4
    U = lambda e, et: tp.fixed_arcs(e, et, s.delta_over_Delta, M, THETA, GB, alpha_ratio=s.alpha_ratio).energy
    h = 1e-5
    for dU in ((U(s.eps + h, s.eps_top) - U(s.eps - h, s.eps_top)) / (2 * h),
               (U(s.eps, s.eps_top + h) - U(s.eps, s.eps_top - h)) / (2 * h)):
        assert dU / (2 * THETA * M * M) == pytest.approx(1, abs=1e-6)
    assert s.G_bot == pytest.approx(1, abs=1e-9) and s.G_top == pytest.approx(1, abs=1e-9)


@pytest.mark.parametrize("ar", ALPHAS)
def test_alpha_load_is_conjugate_to_approach(ar):
    e, et, d, h = 1.1, 0.6, -0.9, 1e-5
    U = lambda x: tp.fixed_arcs(e, et, x, 0.4, 1.7, 0.4, alpha_ratio=ar / 2).energy
    P = tp.fixed_arcs(e, et, d, 0.4, 1.7, 0.4, alpha_ratio=ar / 2).P_star
    assert (U(d + h) - U(d - h)) / (2 * h) == pytest.approx(P, rel=1e-8)


def test_alpha_mirror_maps_equilibria_onto_equilibria(state_alpha):
    s, ar = state_alpha, state_alpha.alpha_ratio
    assert abs(tp.residual(s.eps_top, s.eps, 0.4, THETA, GB, alpha_ratio=ar)) < 1e-9
    m = tp.equilibrium_state(s.eps_top, s.eps, 0.4, THETA, GB, alpha_ratio=ar)     # swapped, solved afresh
    assert m.P_star == pytest.approx(-s.P_star, rel=1e-8, abs=1e-10)
    assert m.delta_over_Delta == pytest.approx(-2 - s.delta_over_Delta, rel=1e-8, abs=1e-10)


@pytest.mark.parametrize("ar, bracket", [(0.2, (1.3, 1.6)), (-0.3, (0.02, 0.08))])
def test_alpha_equal_arcs_at_zero_load_and_centred_pin(ar, bracket):
    e = brentq(lambda x: tp.residual(x, x, 0.4, THETA, GB, alpha_ratio=ar), *bracket, xtol=1e-15)
    s = tp.equilibrium_state(e, e, 0.4, THETA, GB, alpha_ratio=ar)
    assert abs(s.P_star) < 2e-9          # the alpha* engine's P* is good to ~1e-9 (not improving with n)
    assert s.delta_over_Delta == pytest.approx(-1, abs=1e-10)


@pytest.mark.filterwarnings("ignore::scipy.integrate.IntegrationWarning")  # log end terms: quad warns, still 1e-8
def test_alpha_pressure_integrates_to_the_load(state_alpha):
    """(2.2) by quad (phi = c + e cos t removes the 1/sqrt ends; the (1 - s) log(1 - s) end terms are mild)."""
    s, total = state_alpha, 0.0
    for c, e in ((0.0, s.eps), (math.pi, s.eps_top)):
        f = lambda t: s.pressure(c + e * math.cos(t))[0] * math.cos(c + e * math.cos(t)) * e * math.sin(t)
        total += quad(f, 1e-9, math.pi - 1e-9, limit=400, epsabs=1e-14, epsrel=1e-13)[0]
    assert total == pytest.approx(s.P_star, rel=1e-8)


@pytest.mark.filterwarnings("ignore::scipy.integrate.IntegrationWarning")  # log end terms: quad warns, still 1e-8
def test_alpha_gap_from_direct_quadrature_and_nonnegative(state_alpha):
    """h/Delta from quad of (5.2) with the alpha* kernel and the solved pressure, at exterior angles (the
    engine's gap() is meant for exterior angles; inside the arcs its enrichment quadrature is only ~1e-5)."""
    s, ar = state_alpha, state_alpha.alpha_ratio
    for phi in (s.eps + 0.05, 0.5 * (s.eps + math.pi - s.eps_top), math.pi - s.eps_top - 0.05):
        disp = 0.0
        for c, e in ((0.0, s.eps), (math.pi, s.eps_top)):
            f = lambda t: (s.pressure(c + e * math.cos(t))[0] * _K_alpha(phi - c - e * math.cos(t), THETA, GB, ar)
                           * e * math.sin(t))
            disp += quad(f, 1e-9, math.pi - 1e-9, limit=400, epsabs=1e-14, epsrel=1e-13)[0]
        h_ref = (1 - math.cos(phi)) - s.delta_over_Delta * math.cos(phi) - THETA * disp
        assert s.gap(phi)[0] == pytest.approx(h_ref, rel=1e-8, abs=1e-10)
    phi = np.linspace(s.eps, math.pi - s.eps_top, 4001)[1:-1]
    assert np.all(s.gap(phi) >= 0)


@pytest.mark.filterwarnings("ignore::scipy.integrate.IntegrationWarning")
def test_alpha_collocation_residual_inside_both_arcs(state_alpha):
    """Between the collocation points the contact condition h = 0 (5.1) holds on both arcs: h/Delta from quad
    of (5.2) with the alpha* kernel and the solved pressure, split at the log/kink singularity psi = phi."""
    s, ar = state_alpha, state_alpha.alpha_ratio
    for c0, e0 in ((0.0, s.eps), (math.pi, s.eps_top)):
        for x in (-0.61, 0.93):                          # off the Gauss-Chebyshev nodes (n = 32: none there)
            phi, disp = c0 + e0 * x, 0.0
            for c, e in ((0.0, s.eps), (math.pi, s.eps_top)):
                f = lambda t: (s.pressure(c + e * math.cos(t))[0] * _K_alpha(phi - c - e * math.cos(t), THETA, GB, ar)
                               * e * math.sin(t))
                edges = [1e-9, *([math.acos(x)] if c == c0 else []), math.pi - 1e-9]
                disp += sum(quad(f, lo, hi, limit=400, epsabs=1e-14, epsrel=1e-13)[0]
                            for lo, hi in zip(edges, edges[1:]))
            h = (1 - math.cos(phi)) - s.delta_over_Delta * math.cos(phi) - THETA * disp
            assert abs(h) < 1e-8, (c0, x, h)


@pytest.mark.parametrize("ar", (0.1, -0.3))
def test_alpha_full_contact_law(ar):
    """Full contact at alpha* != 0: the Fourier integrals of K by quad, and the limit of closing gaps."""
    th, gb, d = 2.0, 0.75, -0.5
    mode0 = quad(lambda t: _K_alpha(t, th, gb, ar), -math.pi, math.pi, points=[0.0], limit=200)[0]
    mode1 = quad(lambda t: _K_alpha(t, th, gb, ar) * math.cos(t), -math.pi, math.pi, points=[0.0], limit=200)[0]
    fc = tp.full_contact(th, delta_over_Delta=d, gb=gb, alpha_ratio=ar)
    # -1 = -vartheta N0 mode0 and (delta/Delta + 1) = -vartheta N1 mode1 (nu = vartheta n on the whole circle)
    assert fc.N0 == pytest.approx(1 / (th * mode0), rel=1e-10)
    assert d + 1 == pytest.approx(-th * fc.N1 * mode1, rel=1e-10)
    s = tp.fixed_arcs(1.6, math.pi - 1.6 - 0.01, d, 0.4, th, gb, alpha_ratio=ar)    # gaps of 0.01 rad
    assert s.P_star == pytest.approx(fc.P_star, rel=1e-4)
    assert s.B_star == pytest.approx(fc.B_star, rel=1e-4)
    assert s.energy == pytest.approx(fc.energy, rel=1e-4)
    lim = -math.pi * fc.N0
    assert tp.full_contact(th, P_star=0.99 * lim, gb=gb, alpha_ratio=ar).tension_everywhere
    assert not tp.full_contact(th, P_star=1.01 * lim, gb=gb, alpha_ratio=ar).tension_everywhere


@pytest.mark.parametrize("ar", ALPHAS)
def test_alpha_top_arc_to_zero_tends_to_single_patch_with_closed_gap(ar):
    M = 0.4
    hpi = lambda a: float(eq.curve(M, THETA, "super-critical" if ar > 0 else "sub-critical", a=np.array([a]),
                                   gb=GB, alpha_ratio=ar).h_pi_over_Delta[0])
    (e_on,) = tp.onset_angles(M, THETA, GB, ar)
    a_on = math.tan(e_on / 2)
    assert abs(hpi(a_on)) < 1e-10
    s = tp.solve(M, THETA, eps_top=1e-20, guess=e_on, alpha_ratio=ar)
    ref = eq.curve(M, THETA, a=np.array([a_on]), gb=GB, alpha_ratio=ar,
                   regime="super-critical" if ar > 0 else "sub-critical")
    assert s.a == pytest.approx(a_on, rel=1e-8)
    assert s.P_star == pytest.approx(float(ref.P_star[0]), rel=1e-8)
    assert s.delta_over_Delta == pytest.approx(float(ref.delta_over_Delta[0]), rel=1e-8)
    # a -> 0: the mirrored single patch (the pin on the top side only), P* -> -P*, delta -> -2 Delta - delta
    m = tp.solve(M, THETA, eps=1e-20, guess=e_on, alpha_ratio=ar)
    assert m.a_top == pytest.approx(a_on, rel=1e-8)
    assert m.P_star == pytest.approx(-float(ref.P_star[0]), rel=1e-8)
    assert m.delta_over_Delta == pytest.approx(-2 - float(ref.delta_over_Delta[0]), rel=1e-8)


@pytest.mark.parametrize("ar, regime, a", [(0.2, "sub-critical", 0.3), (0.2, "super-critical", 2.0),
                                           (-0.3, "sub-critical", 0.6), (-0.3, "super-critical", 1.5)])
def test_alpha_hessian_stability_of_a_single_arc_matches_the_solver_curve(ar, regime, a):
    """Stability from the 2x2/3x3 Hessian of Pi* (k differences in eps) against the signs of dG/da|_delta and
    dG/da|_P that jkrcyl.equilibria gets from the single-arc solver (unit-case slopes in a)."""
    M = 0.4
    ref = eq.curve(M, THETA, regime, a=np.array([a]), gb=GB, alpha_ratio=ar)
    H, _, _ = tp.hessian(2 * math.atan(a), 0.0, float(ref.delta_over_Delta[0]), M, THETA, GB, alpha_ratio=ar)
    assert (H[0, 0] > 0) == bool(ref.stable_grip[0])
    assert bool(np.all(np.linalg.eigvalsh(H[np.ix_([0, 2], [0, 2])]) > 0)) == bool(ref.stable_load[0])


def test_alpha_ratio_validation():
    with pytest.raises(ValueError, match="alpha_ratio"):
        tp.solve(0.4, 1.0, eps_top=0.5, alpha_ratio=0.5)            # >= 1/(2 vartheta)
    with pytest.raises(ValueError, match="alpha_ratio"):
        eq.two_patch(0.4, 1.0, alpha_ratio=-1.0, gb=eq.incompressible_gb(1.0))
    with pytest.raises(ValueError, match="alpha_ratio"):
        tp.full_contact(2.0, P_star=0.0, alpha_ratio=0.3)


# physical inputs of a pair with alpha* != 0: G = 1, kappa = 2 (nu = 1/4) and G_I = 1, kappa_I = 1.4 (nu_I = 0.4)
PHYS_ALPHA = ["--E", "2.5", "--nu", "0.25", "--E-I", "2.8", "--nu-I", "0.4", "--R", "1", "--Delta", "0.01", "--w", "1e-4"]


@pytest.mark.slow
def test_cli_two_patch_and_confined_report_for_a_pair_with_alpha(capsys):
    """jkrcyl two-patch and adherence with physical inputs whose alpha* != 0 (Contact.two_patch/confined_events
    take alpha* too).  References: every CSV/JSON row is a two-arc Griffith state of the alpha* kernel (G = w
    at both ends from the fixed-arc engine, and NOT one of the alpha* = 0 kernel: alpha* was used); the fold
    P_fold is the minimum of P* over the whole super-critical range (bounded Brent at 64 nodes, where
    confined_events refines locally at its own node count) and the root of dP*/da of jkrcyl.equilibria (the
    report's own fixed-load adherence point, another algorithm); it differs from the closed-form alpha* = 0 fold."""
    mat = Materials.from_young(2.5, 0.25, 2.8, 0.4)
    c = Contact(R=1.0, Delta=0.01, w=1e-4, materials=mat)
    M, th, gb = eq.from_contact(c)
    ar = mat.alpha_ratio
    assert not mat.closed_form and ar != 0
    assert cli.main(["two-patch", *PHYS_ALPHA, "--n", "6", "--format", "json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["alpha_ratio"] == pytest.approx(ar) and out["branches"]
    off = []
    for b in out["branches"]:
        for e, et, d in zip(b["eps"], b["eps_top"], b["delta_over_Delta"]):
            if min(e, et) > 1e-6:
                s = tp.fixed_arcs(e, et, d, M, th, gb, alpha_ratio=ar)
                assert s.G_bot == pytest.approx(1, abs=1e-8) and s.G_top == pytest.approx(1, abs=1e-8)
                off.append(abs(tp.fixed_arcs(e, et, d, M, th, gb).G_bot - 1))
    assert off and max(off) > 1e-3
    assert cli.main(["adherence", *PHYS_ALPHA, "--format", "json"]) == 0
    rep = json.loads(capsys.readouterr().out)
    conf = rep["confined"]
    assert conf is not None and conf["regime"] in tp.REGIMES
    assert conf["regime"] in ("zip-full", "detachment") and conf["P_fold"] is not None
    from scipy.optimize import minimize_scalar

    def P(eps):                                   # single arc, Griffith k = M/pi, 64 nodes per arc
        lin = tp._linear(eps, 0.0, th, gb, 64, ar)
        d = (M / math.pi - lin.q0[2]) / lin.q1[2]
        return lin.q0[0] + d * lin.q1[0]
    e_c = 2 * math.atan(eq.a_crit(th, gb, ar))
    r = minimize_scalar(P, bounds=(e_c + 0.2, 2.6), method="bounded", options={"xatol": 1e-9})
    assert e_c + 0.21 < r.x < 2.59                # an interior minimum (the super-critical fold)
    assert conf["P_fold"] == pytest.approx(r.fun, rel=1e-8)
    assert conf["P_fold"] == pytest.approx(min(p["P_star"] for p in rep["load"]), rel=1e-8)
    closed = min(p.P_star for p in eq.adherence(M, th, "load", gb=gb))
    assert abs(conf["P_fold"] - closed) > 1e-3
    for e, P_on, d_on, _ in conf["onsets"]:     # h(pi) = 0 there, from the single-arc engine
        lin = tp._linear(e, 0.0, th, gb, 64, ar)
        assert abs(lin.gap(math.pi, d_on)[0]) < 1e-8
        assert P_on == pytest.approx(lin.q0[0] + d_on * lin.q1[0], rel=1e-8)


def test_adherence_outcome_replaces_overclosure():
    """Issue 12 item 4: fixed-load adherence points say what a further pull does -- the branch's fold rule
    where the point is feasible (derive/confined.py: below a_crit the contact shrinks away, above it grows into
    full contact), the confined analysis where the gap at pi closes first."""
    from dataclasses import replace
    from jkrcyl import a_crit
    for M in (0.1, 0.3, 0.5, 0.8):
        for p in eq.adherence(M, 1.0, "load", gb=eq.incompressible_gb(1.0)):
            assert p.feasible and p.outcome == ("detachment" if p.a < a_crit(1.0) else "zip-full")
    p = eq.adherence(0.3, 1.0, "load", gb=eq.incompressible_gb(1.0))[0]
    from jkrcyl.analysis import confined
    closed = confined.outcomes(Problem(0.3, 1.0, eq.incompressible_gb(1.0)), [replace(p, feasible=False)])[0]
    assert closed.outcome == tp.confined_events(0.3, 1.0).regime and closed.outcome in tp.REGIMES
    assert eq.adherence(0.3, 1.0, "grip", gb=eq.incompressible_gb(1.0))[0].outcome is None
