"""Two contact patches under the Maugis-Dugdale law (jkrcyl.numerics.cohesive_two): the pin touching the bottom
and the top, k = 0 at each contact edge, the Dugdale traction where 0 < h <= h0.

Checked against what the solver does not use:

* JKR's two-patch states (jkrcyl.model.two_patch: Griffith k = M/pi at both edges, no zone), the limit
  lambda -> inf, at the same top arc: C/lambda^2 measured;
* the law everywhere on the exterior (a 2000-point grid: h >= 0, h <= h0 on the zones, h >= h0 off them), h = h0
  at the zone ends;
* the equilibrium (2.2): p = int nu cos(phi) and B = int nu by Gauss quadrature of the returned traction field;
* the energy: along the branch the total potential (elastic + Dugdale interface energy, Gauss quadrature of the
  opening over the zones) changes by p d(delta) -- central differences of states solved alone, Richardson.
"""
import math

import numpy as np
import pytest

import jkrcyl
from jkrcyl.model import two_patch as tp
from jkrcyl.numerics import cohesive_two as ct
from jkrcyl.numerics.cohesive_scales import zone_strength

THETA, GB, M = 1.0, 1 / 2.8, 0.2            # identical bodies, nu = 0.3 (gb = 1/(2 (1 + ... )) = 1/2.8)
# a two-patch state of JKR's branch with both arcs large (the branch of the confined regime at M = 0.2; the
# top arc given, JKR's bottom arc solved here as the guess and the reference)
EPS_TOP, EPS_GUESS = 0.36330064433257114, 2.6123
XG, WG = np.polynomial.legendre.leggauss(400)


def jkr_state(eps_top=EPS_TOP):
    return tp.solve(jkrcyl.equilibria.problem(M, THETA, GB), eps_top=eps_top, guess=EPS_GUESS)


def cohesive(lam, eps_top=EPS_TOP, guess=None, n=None):
    s0 = zone_strength(lam, M * THETA)
    return ct.solve(eps_top, M * THETA, s0, THETA, GB, 0.0, guess=guess or jkr_state().eps, n=n)


def quad(a, b, f):
    """int_a^b f, Gauss-Legendre clustered at both ends (cosine map)."""
    t = np.pi * (XG + 1) / 2
    x = a + (b - a) * (1 - np.cos(t)) / 2
    return float(np.sum(WG * f(x) * (b - a) * np.sin(t) / 2 * np.pi / 2))


@pytest.mark.slow
def test_jkr_limit_at_a_fixed_top_arc():
    """The bottom arc and P* at the top arc 0.3633 against JKR's two-patch state (at 96 nodes per arc: its default
    31 are 7e-5 off in eps here, which once read as 'two terms of opposite sign'): within 2e-3 in P* at lambda =
    50, both differences falling as C/lambda^2 (measured at lambda = 10, 20, 50: lambda^2 dP* = 0.237, 0.232,
    0.231, lambda^2 d eps = -1.98, -1.81, -1.77)."""
    ref = tp.solve(jkrcyl.equilibria.problem(M, THETA, GB), eps_top=EPS_TOP, guess=EPS_GUESS, n=96)
    got = {lam: cohesive(lam) for lam in (20.0, 50.0)}
    for lam, st in got.items():
        assert st.zones == "both" and abs(st.k_top) < 1e-9 and st.k_bot == pytest.approx(0.0, abs=1e-9)
    d50 = abs(got[50.0].p / THETA - ref.P_star)
    assert d50 < 2e-3 and d50 > 1e-7                       # a finite zone: not JKR's state itself
    e20, e50 = (abs(got[lam].eps - ref.eps) * lam ** 2 for lam in (20.0, 50.0))
    assert 1.0 < e20 < 3.0 and 1.0 < e50 < 3.0 and abs(e50 / e20 - 1) < 0.1      # C/lambda^2, C ~ 1.8
    p20, p50 = (abs(got[lam].p / THETA - ref.P_star) * lam ** 2 for lam in (20.0, 50.0))
    assert abs(p50 / p20 - 1) < 0.02
    assert abs(got[50.0].delta_over_Delta - ref.delta_over_Delta) < 2e-3


@pytest.mark.slow
def test_the_law_holds_on_the_gap_and_equilibrium_by_quadrature():
    """lambda = 20: h >= 0 everywhere between the patches, <= h0 on the zones, >= h0 off them, h = h0 at the zone
    ends (1e-12); p and B by quadrature of the traction field (contacts and zones) equal the state's (1e-10)."""
    st = cohesive(20.0)
    f = st.fields
    phi = np.linspace(st.eps, math.pi - st.eps_top, 2001)[1:-1]
    h = f.gap(phi)
    zone = (phi <= st.c) | (phi >= math.pi - st.c_top)
    h0 = st.h0_over_Delta
    assert h.min() > 0 and h[zone].max() <= h0 * (1 + 1e-9) and h[~zone].min() >= h0 * (1 - 1e-9)
    assert np.max(np.abs(f.gap(np.array([st.c, math.pi - st.c_top])) - h0)) < 1e-12
    pieces = [(-st.eps, st.eps), (st.eps, st.c), (-st.c, -st.eps), (math.pi - st.eps_top, math.pi + st.eps_top),
              (math.pi - st.c_top, math.pi - st.eps_top), (-math.pi + st.eps_top, -math.pi + st.c_top)]
    p = sum(quad(a, b, lambda x: f.pressure(x) * np.cos(x)) for a, b in pieces)
    B = sum(quad(a, b, f.pressure) for a, b in pieces)
    assert abs(p - st.p) < 1e-10 and abs(B - st.B) < 1e-10
    assert f.pressure(np.array([0.5 * (st.c + math.pi - st.c_top)]))[0] == 0            # the free gap


@pytest.mark.slow
def test_energy_changes_by_p_d_delta_along_the_branch():
    """lambda = 20: (E(+h) - E(-h))/(delta(+h) - delta(-h)) of states at eps_top +- h, solved alone, tends to p as
    h^2 (measured: 1.6e-6 and 1.4e-7 at h = 1e-3, 3e-4); Richardson's extrapolation of the two is p to 1e-8."""
    st = cohesive(20.0)
    rates = []
    for h in (1e-3, 3e-4):
        plus, minus = (cohesive(20.0, EPS_TOP + s * h, guess=st.eps, n=st.n) for s in (1, -1))
        rates.append((ct.potential(plus) - ct.potential(minus)) / (plus.delta_over_Delta - minus.delta_over_Delta))
    r = (1e-3 / 3e-4) ** 2
    extrapolated = (r * rates[1] - rates[0]) / (r - 1)
    assert abs(rates[0] - st.p) > 1e-7                      # the difference quotient does converge to it
    assert abs(extrapolated - st.p) < 1e-8


@pytest.mark.parametrize("kw, name", [
    (dict(eps_top=-0.1), "eps_top"), (dict(eps_top=math.nan), "eps_top"), (dict(eps_top=3.5), "eps_top"),
    (dict(guess=0.0), "guess"), (dict(guess=3.0), "guess"), (dict(guess="1"), "guess"),
    (dict(s0=0.0), "s0"), (dict(s0=math.inf), "s0"), (dict(m=math.nan), "m"), (dict(ar=0.1), "m must be > 0 and ar"),
    (dict(n=4), "n"), (dict(n=2.5), "n"), (dict(n=10 ** 6), "n"),
])
def test_bad_input_names_the_parameter(kw, name):
    args = dict(eps_top=EPS_TOP, m=M * THETA, s0=1.0, theta=THETA, gb=GB, ar=0.0, guess=EPS_GUESS)
    args.update(kw)
    with pytest.raises(ValueError, match=f"^{name}"):
        ct.solve(**args)


def test_too_thin_a_zone_is_refused_naming_sigma0():
    """Beyond the law's LAMBDA_MAX = 1e4 (the zone thinner than double precision keeps), and without the end
    layers where the zones would need more than NODES_MAX_TWO nodes per arc (lambda = 400: ~2600)."""
    with pytest.raises(ValueError, match="^sigma0 is too large for the cohesive law"):
        cohesive(2e4)
    with pytest.raises(ValueError, match="^sigma0 is too large for the two-arc cohesive solver"):
        ct.solve(EPS_TOP, M * THETA, zone_strength(400.0, M * THETA), THETA, GB, 0.0, guess=jkr_state().eps,
                 layered=False)


def test_no_state_near_the_guess_is_a_value_error():
    """A guess where no two-patch state is near (both arcs small, lambda = 20): the Newton fails and says so."""
    with pytest.raises(ValueError, match="^guess: no cohesive two-patch state"):
        ct.solve(0.05, M * THETA, zone_strength(20.0, M * THETA), THETA, GB, 0.0, guess=0.05)


@pytest.mark.parametrize("lam, eps, eps_top", [(1.0, 1.2, 0.5), (4.0, 2.0, 0.8), (20.0, 0.7, 1.9)])
def test_zone_spanning_the_gap_is_jkr_adhesionless_with_a_scaled_clearance(lam, eps, eps_top):
    """Fixed arcs with the zone all round: the uniform traction -s0 on the circle acts on the arcs as the constant
    s0 Z_all, Z_all = 2 pi (k0 - 1 + ar) (the Michell mode 0, jkrcyl.model.full_contact), a combination of the
    clearance and approach cases, so the state is JKR's fixed-arc solution (jkrcyl.numerics.arcs.Linear, its own
    right-hand sides) with the clearance 1 + s0 Z_all and the approach delta - s0 Z_all: delta from k_bot = 0,
    k_top and p agree (1e-9)."""
    s0 = zone_strength(lam, M * THETA)
    from jkrcyl.numerics import arcs
    kernel = arcs.Kernel(THETA, GB)
    n = ct.nodes(eps, eps_top, 0.0)
    st = ct.state(ct._Law(M * THETA, s0, kernel), eps, eps_top, math.pi, 0.0, n)
    assert st.zones == "all" and st.k_bot == pytest.approx(0.0, abs=1e-12)
    z = s0 * 2 * math.pi * (kernel.k0 - 1.0)
    lin = arcs.Linear(eps, eps_top, THETA, GB, n)
    q0, q1 = (1 + z) * lin.q0, lin.q1                      # n units (nu / vartheta); clearance scaled
    d_eff = -q0[2] / q1[2]
    assert abs(st.delta_over_Delta - (d_eff + z)) < 1e-9 * max(1.0, abs(d_eff))
    assert abs(st.k_top / THETA - (q0[3] + d_eff * q1[3])) < 1e-9
    assert abs(st.p / THETA - (q0[0] + d_eff * q1[0])) < 1e-9 * max(1.0, abs(st.p))


@pytest.mark.slow
def test_mirror_state_is_the_solve_with_the_arcs_swapped():
    """Upside down (phi -> phi + pi) the problem is the same: the state with the top arc set to this state's
    bottom arc has this state's top arc at the bottom, P* -> -P*, delta/Delta -> -2 - delta/Delta and the zones
    swapped (lambda = 20; a number reached two ways: the solver does not use the mirror)."""
    st = cohesive(20.0)
    mi = cohesive(20.0, eps_top=st.eps, guess=st.eps_top)
    assert abs(mi.eps - st.eps_top) < 1e-9 and abs(mi.p + st.p) < 1e-9
    assert abs(mi.delta_over_Delta + 2 + st.delta_over_Delta) < 1e-9 and abs(mi.B - st.B) < 1e-9
    assert abs(mi.c - mi.eps - (st.c_top - st.eps_top)) < 1e-9 and abs(mi.c_top - mi.eps_top - (st.c - st.eps)) < 1e-9


# --- stability: the energy of zone-end-held states ------------------------------------------------------------
def _law(lam, theta=THETA, gb=GB, M_=M):
    """The law of ct.solve's states at lambda = 20 (zones thin enough for their end layers to be subtracted)."""
    from jkrcyl.numerics import arcs
    return ct._Law(M_ * theta, zone_strength(lam, M_ * theta), arcs.Kernel(theta, gb), layered=True)


@pytest.mark.slow
@pytest.mark.parametrize("control", ["grip", "load"])
def test_held_states_energy_gradient_is_the_j_integral(control):
    """lambda = 20, zone ends held 10 % of the bottom zone past the equilibrium (k = 0 at both contacts, the
    control's quantity held): d(E - [p delta under load])/dc by central differences of the held states' total
    potential (quadrature) equals 2 s0 (h(c) - h0), Dugdale's J-integral at both ends of the bottom zone, to 1e-5
    (measured 4e-7): the gradient jkrcyl.numerics.cohesive_two_stability differentiates."""
    from jkrcyl.numerics import cohesive_two_stability as cs
    st, law = cohesive(20.0), _law(20.0)
    value = st.p if control == "load" else st.delta_over_Delta

    def held(c):
        return cs.held_state(law, c, st.c_top, control, value, (st.eps, st.eps_top), st.n)

    def energy(c):
        s = held(c)[0]
        assert abs(s.k_bot) < 1e-9 and abs(s.k_top) < 1e-9
        return ct.potential(s) - (s.p * s.delta_over_Delta if control == "load" else 0.0)

    c0, h = st.c + 0.1 * (st.c - st.eps), 1e-3 * (st.c - st.eps)
    g = held(c0)[1][0]
    assert abs(g) > 1e-5
    assert abs((energy(c0 + h) - energy(c0 - h)) / (2 * h) / (2 * law.s0 * g) - 1) < 1e-5


# a state of JKR's two-patch loop branch (vartheta = 0.6, gb = 0.1, M = 0.5; traced by jkrcyl.analysis.tracing):
# stable under grip, unstable under load (jkrcyl.model.two_patch.stability)
LOOP = dict(theta=0.6, gb=0.1, M_=0.5, eps_top=0.4838986049258979, guess=0.4286145685119062)


@pytest.mark.slow
@pytest.mark.parametrize("case", ["confined branch", "loop"])
def test_stability_flags_are_jkrs_and_the_zone_matrix_is_symmetric(case):
    """lambda = 20: the zone matrix G (h(c_i) - h0 against the zone ends at the held quantity, from held states)
    is symmetric (Maxwell: E is a potential; not imposed) to 1e-6, and its flags equal JKR's second variation at
    the limit state: M = 0.2, vartheta = 1 unstable under load and grip; the loop state stable under grip only
    (measured eigenvalues: grip 0.024, 0.116; load -0.046, 0.024)."""
    from jkrcyl.numerics import cohesive_two_stability as cs
    kw = dict(theta=THETA, gb=GB, M_=M) if case != "loop" else {k: LOOP[k] for k in ("theta", "gb", "M_")}
    pb = jkrcyl.equilibria.problem(kw["M_"], kw["theta"], kw["gb"])
    if case == "loop":
        ref = tp.solve(pb, eps_top=LOOP["eps_top"], guess=LOOP["guess"])
    else:
        ref = jkr_state()
    law = _law(20.0, **kw)
    st = ct.solve(ref.eps_top, law.m, law.s0, kw["theta"], kw["gb"], 0.0, guess=ref.eps)
    flags = tp.stability(pb, ref.eps, ref.eps_top, ref.delta_over_Delta)[:2]
    for control, expected in zip(("load", "grip"), flags):
        G = cs.zone_matrix(law, st, control)
        assert abs(G[0, 1] - G[1, 0]) < 1e-6 * np.max(np.abs(G))
        assert cs.stable(law, st, control, G) == expected
    assert flags == ((False, False) if case != "loop" else (False, True))
