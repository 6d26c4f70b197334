"""The top bridge of the Maugis-Dugdale law: one contact |phi| < eps with its zone |phi| < c at the bottom and a
second zone |phi - pi| < c_top at the top, held by its own traction, as a 1-D family.

Notation of jkrcyl.numerics.cohesive (kernel scale: p = P beta*/(4 pi Delta), lengths over Delta, h0 = m^2/s0).
Where the single patch's gap has a local minimum at phi = pi (JKR's two-patch regime: the pin is drawn to the top
of the hole) the single-patch states end where h(pi) = h0: below, the law puts traction at the top.  There the
top-zone family starts with c_top -> 0 (:func:`junction`), and it lies on the single patch's side h(pi) > h0: in
two dimensions a zone's own traction lowers the gap at its end by ~ 4 s0 c_top log(1/c_top) (the kernel's log),
more than the flat top's curvature raises it, so a small zone closes its own end h(pi - c_top) = h0 under a
single-patch gap above h0.  Measured (M 0.1, vartheta 10, gb 1/2.8, lambda 50: junctions at eps 0.0283 and 0.728,
delta/Delta -1.728 and -1.153): each family runs away from the single patch's h(pi) = 0 with c_top growing until
the gap at the top closes, h(pi) = 0 (eps 0.0048 and 1.12, c_top 2.31e-3 = h0/(4 s0 log 2) to 1e-4, delta/Delta
-1.173 and -0.610), where the top contact forms under its zone (the law's two patches); at lambda 20 the first
reaches the touch end (eps -> 0) before the top closes.  The single patch's h(pi) at the top's closing is the
strip's h0 (1 + log(1/(2 c_top))/log 2) (0.70 Delta at lambda 50, 0.26 at 200): the family shrinks as lambda grows
like h0 log(lambda), not h0.  Each state is a
saddle (the top zone grows at a held load or approach: :func:`stable`), the barrier between the single patch and
two patches, vanishing at the junction: the single patch is a fold there.

Each state solves k = 0 at the contact edge (delta eliminated: jkrcyl.numerics.cohesive.FixedContact.solve),
h(c) = h0 (the bottom zone end at a fixed contact and c_top: cohesive_roots.zone_end_near, the LU reused) and
h(pi - c_top) = h0, a scalar root in eps (one LU per iterate); the family is traced in c_top (monotone along it in
every case met), from CT_START geometrically.  Stability as jkrcyl.numerics.cohesive_two_stability: the energy of
states whose zone ends are held (grad 2 s0 (h(c_i) - h0)), a minimum where G_ij = d(h(c_i) - h0)/dc_j at the held
quantity is positive definite.  The total potential: jkrcyl.numerics.cohesive_branch.potential (both zones).
At the top's closing the family meets the law's two-arc states (jkrcyl.numerics.cohesive_two.solve as the top arc
eps_top -> 0, as eps_top^2); where the contact vanishes first (lambda 20 above) it meets the states without
contact held by zones at the bottom and top where they touch (traced on: cohesive_contactless.two_zone_trace).

The single patch ends at the junction, h(pi) = h0, a fold of the combined branch (the bridge, a saddle, is the
barrier): a walk jumps there (jkrcyl.analysis.landing).  The families as a branch: jkrcyl.model.cohesive_bridge.
"""
import math
from collections import namedtuple

import numpy as np

from . import cohesive as _co
from . import cohesive_branch as _cb
from . import roots as _roots

CT_START = 1e-9           # the first c_top of a trace (its states within ~s0 CT_START of the junction's)
CT_RATIO = 1.35           # c_top grows by this factor per point
CT_MAX_POINTS = 400
RATIO_MIN = 1e-4          # trace: the step in c_top refined (square roots of the ratio) down to this before an end
EPS_STEP = 1e-7           # bracket search in eps: the first step relative to eps, doubled
EPS_XTOL = 1e-15          # the eps root to this relative tolerance
SUPER_TOP = 0.05          # the super-critical side: contacts up to pi - SUPER_TOP (as its single patch)
TOUCH = 1e-2              # the trace follows eps down to this times the law's eps_lo (its default first contact)
HOLD_STEP = 1e-4          # zone_matrix: central differences, relative to each zone length
SLOPE_STEP = 1e-3         # slopes: central differences relative to c_top and eps (the states' ~1e-12 noise over
SLOPE_STEP_EPS = 1e-5     # the step against its truncation, which is large in eps past the receding limit: 1e-5
                          # relative at c_top 1e-9 .. 3e-3 on both sides, measured)
HELD = ("load", "grip", "grip-work")   # the controls of held_state

TopZoneBranch = namedtuple("TopZoneBranch", ["junction", "states", "end", "onset"])
TopZoneBranch.__doc__ = """A traced top-zone family (jkrcyl.numerics.cohesive.CohesiveState each, zones 'bottom+top').

junction: the single-patch state where h(pi) = h0 (c_top = 0); states: the family in increasing c_top; end: why
the trace ended -- 'top closes' (h(pi) reaches 0: onset is that state, the top contact's onset), 'touch' (eps
below 0.1 of the law's eps_lo: the family goes on without contact, the states of
jkrcyl.numerics.cohesive_zones.contactless_states), 'receding limit' (the pole eps_crit, from either side), 'near full
contact' (a super-critical family at eps = pi - SUPER_TOP), 'zones meet' (c + c_top -> pi), 'no root'
(no eps root next to the last state: a fold in c_top) or 'points' (CT_MAX_POINTS states)."""


def law_of(m, s0, theta, gb, ar=0.0):
    """The validated law with its node policy and cached fixed contacts (jkrcyl.numerics.cohesive_branch.Law)."""
    return _cb.Law(m, s0, theta, gb, ar)


def fixed_state(law, eps, c_top, d_near):
    """The state at the contact eps with the top zone c_top (0: none) and its bottom zone end nearest to
    eps + d_near (k = 0, h(c) = h0), or None when no zone end lies within a factor 100 of d_near."""
    fc = law.fixed(eps)
    d = fc.zone_end_near(law.s0, law.h0, d_near, c_top)
    if d is None or eps + d + c_top >= math.pi:
        return None
    zones = _co.zones_of(eps + d, c_top)
    dn, u = fc.solve(zones, law.s0)
    return _co._state(eps, eps + d, fc, dn, u, zones, law.m, law.s0, law.kernel, law.gb, fc.sys.n, c_top)


def _top_gap(st):
    """h(pi - c_top) - h0 (h(pi) - h0 without top zone)."""
    return st.fields.gap(math.pi - st.c_top)[0] - st.h0_over_Delta


def _eps_root(law, c_top, eps0, d_near, step=EPS_STEP):
    """The state with the top zone c_top whose eps solves h(pi - c_top) = h0 nearest to eps0: a bracket grown
    geometrically (from the relative step ``step``, doubled) on both sides of eps0 (the family can turn back in
    eps), then Brent (to EPS_XTOL relative); None when none is found within a factor e^2."""
    memo, (lo, hi) = {}, domain(law, eps0)

    def f(eps):
        if eps not in memo:
            st = fixed_state(law, eps, c_top, d_near) if lo < eps < hi else None
            memo[eps] = (math.nan, None) if st is None else (_top_gap(st), st)
        return memo[eps][0]

    f0 = f(eps0)
    if not math.isfinite(f0):
        return None
    if f0 == 0.0:
        return memo[eps0][1]
    while step < 2.0:
        for x in (eps0 * math.exp(-step), eps0 * math.exp(step)):
            fx = f(x)
            if math.isfinite(fx) and fx * f0 <= 0:
                a, b = sorted((eps0, x))
                eps = _roots.brent(lambda y, _: f(y), a, b, (), memo[a][0], memo[b][0], EPS_XTOL * b)
                f(eps)
                return memo[eps][1]
        step *= 2
    return None


def junction(law, lo, hi, zones=None):
    """The single-patch state where h(pi) = h0 between the contacts lo and hi (h(pi) - h0 changes sign there).
    The zone end: the first root above the Dugdale estimate (as jkrcyl.numerics.cohesive.cohesive_state), or,
    with zones = (c at lo, c at hi) from a traced branch, the root nearest the branch's (log-interpolated): past a
    turn of the branch the first root is another branch's (m 1.5, vartheta 15, gb 0, lambda 20)."""
    def state(eps):
        if zones is None:
            return law.state(eps)
        t = (eps - lo) / (hi - lo)
        d = math.exp((1 - t) * math.log(zones[0] - lo) + t * math.log(zones[1] - hi))
        return fixed_state(law, eps, 0.0, d)

    def f(eps):
        st = state(eps)
        return math.nan if st is None else st.h_pi_over_Delta - law.h0
    flo, fhi = f(lo), f(hi)
    if not flo * fhi <= 0:
        raise ValueError(f"lo, hi: h(pi) - h0 must change sign between the contacts {lo:g} and {hi:g}")
    a, b, fa, fb = (lo, hi, flo, fhi) if lo < hi else (hi, lo, fhi, flo)
    return state(_roots.brent(lambda x, _: f(x), a, b, (), fa, fb, EPS_XTOL * b))


def junctions(law, points=None):
    """Every contact of the law's traced single-patch branch where h(pi) = h0 with a local minimum of the gap at
    pi (a top zone can part there): [(junction state, side)], side +1 where the single patch's h(pi) > h0 lies at
    larger eps (the top-zone family's side).  points: the branch's (eps, c) (default: cohesive_branch.trace)."""
    if points is None:
        x = _cb.trace(law)[0]
        points = np.column_stack([np.exp(x[:, 0]), np.exp(x[:, 0]) + np.exp(x[:, 1])])
    h = np.array([_cb.state_values(law, e, c)[2] if c < math.pi else math.nan for e, c in points]) - law.h0
    out = []
    for i in _roots.sign_changes(h):
        st = junction(law, points[i, 0], points[i + 1, 0], (points[i, 1], points[i + 1, 1]))
        if st.fields.gap(math.pi * (1 - 1e-3))[0] > st.h_pi_over_Delta:
            out.append((st, 1 if h[i + 1] > h[i] else -1))
    return out


def families(m, s0, theta, gb, ar=0.0, ratio=CT_RATIO):
    """Every top-zone family of the law (normalised as jkrcyl.numerics.cohesive: m, s0, vartheta, gb, ar): one
    TopZoneBranch per contact of its single patch where h(pi) = h0 with a local minimum of the gap at the top
    (:func:`junctions`, in increasing eps), traced by :func:`trace`; [] where the gap at the top never reaches the
    range.

    Examples
    --------
    >>> from jkrcyl.numerics.cohesive_scales import zone_strength
    >>> [(b.end, round(b.junction.delta_over_Delta, 4), round(b.onset.delta_over_Delta, 4))
    ...  for b in families(1.0, zone_strength(50.0, 1.0), 10.0, 1 / 2.8, ratio=3.0)]
    [('top closes', -1.7279, -1.1727), ('top closes', -1.1528, -0.61)]
    """
    law = law_of(m, s0, theta, gb, ar)
    return [trace(law, st, ratio=ratio) for st, _ in junctions(law)]


def trace(law, start, ct_start=CT_START, ratio=CT_RATIO):
    """The top-zone family from the junction state start (:func:`junction`), c_top from ct_start by the factor
    ratio per point (eps predicted from the last two, linear in log c_top), to its end (TopZoneBranch; 'top
    closes' refined to h(pi) = 0 by Brent in c_top)."""
    states, eps, d, step = [], start.eps, start.c - start.eps, ratio
    ct, end, onset = ct_start, "", None
    while len(states) < CT_MAX_POINTS:
        guess = _predict(states, ct, eps)             # its error: a fraction of the step it predicts
        st = _eps_root(law, ct, guess, d, max(EPS_STEP, 0.03 * abs(math.log(guess / eps))))
        if st is None:                                # refine the step before calling it an end
            if step - 1 > RATIO_MIN and states:
                step = math.sqrt(step)
                ct = states[-1].c_top * step
                continue
            end = _end_reason(law, eps, d, ct)
            break
        if st.h_pi_over_Delta <= 0:
            onset = _onset(law, states[-1] if states else start, st)
            end = "top closes"
            break
        states.append(st)
        eps, d, ct = st.eps, st.c - st.eps, st.c_top * step
    return TopZoneBranch(start, states, end or "points", onset)


def _predict(states, ct, eps):
    """eps at the top zone ct, extrapolated linearly in log c_top from the last two states (else eps)."""
    if len(states) < 2:
        return eps
    a, b = states[-2:]
    guess = b.eps + (b.eps - a.eps) * math.log(ct / b.c_top) / math.log(b.c_top / a.c_top)
    return guess if 0.5 * b.eps < guess < 2 * b.eps else b.eps


def domain(law, eps):
    """(lo, hi): the contacts the family through eps may reach -- the sub-critical side of the receding limit
    eps_crit (from TOUCH times the law's eps_lo to jkrcyl.numerics.cohesive_branch's eps_hi), or
    the super-critical side (from eps_crit (1 + EPS_MARGIN) to pi - SUPER_TOP): a root is never bracketed
    across the pole."""
    crit = law.eps_hi / (1 - _cb.EPS_MARGIN)           # the receding contact (or above pi - 0.05: none below)
    if eps < crit:
        return law.eps_lo * TOUCH, law.eps_hi
    return crit * (1 + _cb.EPS_MARGIN), math.pi - SUPER_TOP


def _end_reason(law, eps, d, ct):
    """Why no state follows the last one (eps, d = c - eps) at the next c_top = ct."""
    lo, hi = domain(law, eps)
    if eps < 0.1 * law.eps_lo:                     # below the single patch's own touch end: the contact vanishes
        return "touch"
    if eps > hi * (1 - 1e-3):
        return "receding limit" if hi == law.eps_hi else "near full contact"
    if eps < lo * (1 + 1e-3) and lo > law.eps_hi:
        return "receding limit"
    if eps + d + ct >= math.pi * (1 - 1e-6):
        return "zones meet"
    return "no root"


def _onset(law, before, after):
    """The state of the family between before (h(pi) > 0) and after (h(pi) <= 0) where h(pi) = 0: Brent in c_top,
    each eps root from the log-linear guess between the two (its bracket from 3 % of their distance in log eps)."""
    memo = {}
    lo = max(before.c_top, CT_START * 1e-3)         # before solves h(pi - lo) = h0 already: its h(pi) is f(lo)
    span = math.log(after.eps / before.eps)
    step = max(EPS_STEP, 0.03 * abs(span))

    def root(ct):
        guess = before.eps * math.exp(span * math.log(ct / lo) / math.log(after.c_top / lo))
        return _eps_root(law, ct, guess, before.c - before.eps, step)

    def f(ct):
        st = memo[ct] = root(ct)
        return math.nan if st is None else st.h_pi_over_Delta
    ct = _roots.brent(lambda x, _: f(x), lo, after.c_top, (), before.h_pi_over_Delta, after.h_pi_over_Delta,
                      1e-13 * after.c_top)
    return memo.get(ct) or root(ct)


def state_at(law, c_top, eps_guess, d_guess):
    """The top-zone state with the top zone c_top, solved alone: its eps the root nearest to eps_guess, the bottom
    zone end nearest to eps + d_guess (a check on the traced family)."""
    return _eps_root(law, c_top, eps_guess, d_guess)


def slopes(law, st, rel=SLOPE_STEP, rel_eps=SLOPE_STEP_EPS):
    """d(p, delta/Delta, eps)/dc_top along the family at st, by implicit differentiation of the top zone-end
    condition F(eps, c_top) = h(pi - c_top) - h0 = 0 (the bottom zone end and k = 0 solved at each): deps/dc_top =
    -F_ct/F_eps, then dX/dc_top = X_eps deps/dc_top + X_ct (X = p, delta/Delta), the partials by central differences
    (steps rel_eps times eps, rel times c_top) of states at a fixed contact -- four, where solving states alone
    costs ~40."""
    d_near, he, hc = st.c - st.eps, rel_eps * st.eps, rel * st.c_top
    at = [fixed_state(law, st.eps + he, st.c_top, d_near), fixed_state(law, st.eps - he, st.c_top, d_near),
          fixed_state(law, st.eps, st.c_top + hc, d_near), fixed_state(law, st.eps, st.c_top - hc, d_near)]
    if any(a is None for a in at):
        return math.nan, math.nan, math.nan
    part = lambda f, i, h: (f(at[i]) - f(at[i + 1])) / (2 * h)
    deps = -part(_top_gap, 2, hc) / part(_top_gap, 0, he)
    p_of, dn_of = (lambda s: s.p), (lambda s: s.delta_over_Delta)
    return (part(p_of, 0, he) * deps + part(p_of, 2, hc), part(dn_of, 0, he) * deps + part(dn_of, 2, hc), deps)


# --- energy and stability -------------------------------------------------------------------------------------
def potential(st):
    """Total potential (kernel scale): elastic energy and the Dugdale interface energy of both zones
    (jkrcyl.numerics.cohesive_branch.potential)."""
    return _cb.potential(st)


def held_state(law, c, c_top, control, value, eps_guess, work_shift=0.0):
    """The state with the zone ends c and c_top held, k = 0 at the contact edge and the control's quantity at value
    ('grip': delta/Delta, 'load': p, 'grip-work': delta_work/Delta = delta/Delta + work_shift p): a scalar root in
    eps near eps_guess (bracketed, Brent).  Returns (state, [h(c) - h0, h(pi - c_top) - h0])."""
    if control not in HELD:
        raise ValueError(f"control must be one of {', '.join(HELD)}, got {control!r}")
    zones = _co.zones_of(c, c_top)

    def pieces(eps):
        fc = law.fixed(eps)
        ua = fc.fx[3] + law.s0 * fc.zone_unit(zones)
        if control == "grip":
            dn = value
        else:                                      # p = p_a + dn q, affine in the approach
            p_a, q = fc.load_width(ua, zones, law.s0)[0], fc.ep @ fc.fx[4]
            dn = (value - p_a) / q if control == "load" else (value - work_shift * p_a) / (1 + work_shift * q)
        u = ua + dn * fc.fx[4]
        return fc, dn, u, fc.ek @ u

    k = lambda eps: pieces(eps)[3]
    lo, hi, step = eps_guess, eps_guess, 1e-6
    klo = khi = k(eps_guess)
    while klo * khi > 0 and step < 5.0:                # a bracket up to e^5 either way (a held state near the touch)
        lo, hi = eps_guess * math.exp(-step), min(eps_guess * math.exp(step), 0.5 * (eps_guess + c))
        klo, khi, step = k(lo), k(hi), step * 2
    if klo * khi > 0:
        raise ValueError(f"eps_guess: no zone-end-held state near the contact {eps_guess:g}")
    eps = _roots.brent(lambda x, _: k(x), lo, hi, (), klo, khi, EPS_XTOL * hi)
    fc, dn, u, _ = pieces(eps)
    st = _co._state(eps, c, fc, dn, u, zones, law.m, law.s0, law.kernel, law.gb, fc.sys.n, c_top)
    return st, st.fields.gap(np.array([c, math.pi - c_top])) - law.h0


def _held_value(st, control, work_shift):
    return {"grip": st.delta_over_Delta, "load": st.p, "grip-work": st.delta_over_Delta + work_shift * st.p}[control]


def zone_matrix(law, st, control, work_shift=0.0):
    """G_ij = d(h(c_i) - h0)/dc_j at the held quantity of control (central differences of zone-end-held states,
    steps HOLD_STEP times each zone length, c - eps and c_top, or the contact eps if smaller: near the touch the
    held contact moves ~ (c step)/eps and vanishes under load a step ~ eps away), unsymmetrised."""
    value = _held_value(st, control, work_shift)
    ends = np.array([st.c, st.c_top])
    steps = HOLD_STEP * np.minimum([st.c - st.eps, st.c_top], st.eps)
    G = np.empty((2, 2))
    for j in range(2):
        g = [held_state(law, *(ends + sgn * steps[j] * np.eye(2)[j]), control, value, st.eps, work_shift)[1]
             for sgn in (1, -1)]
        G[:, j] = (g[0] - g[1]) / (2 * steps[j])
    return G


def stable(law, st, control, G=None, work_shift=0.0):
    """Whether the top-zone state st is stable under control ('grip', 'load' or 'grip-work'): the held energy a
    minimum, G's symmetric part positive definite."""
    G = zone_matrix(law, st, control, work_shift) if G is None else G
    return bool(np.all(np.linalg.eigvalsh(0.5 * (G + G.T)) > 0))


def flags(law, st, work_shift=0.0):
    """{control: stable} under 'load', 'grip' and 'grip-work' (work_shift >= 0).  A stiffer control only adds a
    constraint (or a spring) to the energy's Hessian, so stable under load => under grip-work => under grip; where
    the top zone grows at a held approach (G_22 < 0 under grip: every state met) all three are False from two held
    states, else each by :func:`stable`."""
    step = HOLD_STEP * min(st.c_top, st.eps)
    g = [held_state(law, st.c, st.c_top + s * step, "grip", st.delta_over_Delta, st.eps)[1][1] for s in (1, -1)]
    if (g[0] - g[1]) / (2 * step) < 0:
        return dict.fromkeys(HELD, False)
    return {ctl: stable(law, st, ctl, work_shift=work_shift) for ctl in HELD}
