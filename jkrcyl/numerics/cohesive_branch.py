"""The contact branch of one Maugis-Dugdale law as a 1-D family, and its per-point data.

Notation of jkrcyl.numerics.cohesive (kernel scale: p = P beta*/(4 pi Delta), lengths over Delta, m, s0, h0 = m^2/s0).
At a fixed contact |phi| < eps and zone end c every state is affine in the approach delta/Delta (the LU of the
contact is reused): the edge coefficient k at the contact end, the load p, B = int nu and the zone-end residual
g = h(c) - h0.  Equilibrium is k = 0 and g = 0: a curve in (eps, delta, c) that can turn back in eps and in c
(phase 1), so the branch is traced by continuation (jkrcyl.numerics.cohesive_follow) in
x = (log eps, log(c - eps)) from its touch end (eps -> 0) and parametrised by the arclength t of the traced
polyline.  A state at any t is the curve's point on the normal through the polyline (:func:`project`).
Where the range reaches round at the touch end (zones 'all': no zone end, c = pi) the branch is sampled in eps
(t = log eps).

Stability (the rule of jkrcyl.model.stability, (dX/dt)(dX/dk) < 0): the reduced energy E(c) -- the minimum of the
elastic plus interface energy over every field with the zone |phi| < c, the contact edge then at k = 0 -- has
dE/dc = 2 (s0 h(c) - m^2) (Dugdale's J-integral), so a state is stable under a held X (p, delta or delta_work)
when dg/dc at fixed X and k = 0 is > 0.  With the Jacobian M of (k, X, g) in (eps, delta, c) and M12 its (k, X)
block in (eps, delta): dg/dc = det M/det M12 (Schur complement) and, along T = grad k x grad g, dX/dT = -det M.
So the 'fixed-arc derivative' the rule reads is D_X = sigma det M12 (sigma: the orientation of t along T), linear
in X as the rule needs (delta_work = delta + c p).  Zones 'all': the problem is convex; D_X = X_delta/k_delta,
the contact edge's fixed-arc derivative.
"""
import functools
import math
from collections import namedtuple

import numpy as np

from . import cohesive as _co
from . import roots as _roots
from . import cohesive_kernels as _ck
from . import cohesive_contact as _cc
from . import cohesive_follow as _fo
from . import cohesive_zones as _cz
from . import cohesive_bordered as _bo
from . import cohesive_round as _round
from . import one_arc as _one

START = 1e-3            # the trace starts at eps = START 2 m^(2/3) (at most 1e-3; below: Law.touch)
JUNCTION_STEP = 2.0     # the spacing in log eps of the states below eps_lo (from the touch: 6 points at lambda 20)
EPS_MARGIN = 1e-3       # below the receding limit (the pair's pole)
P_CAP = 200.0           # traced up to p = P_CAP m^(4/3) (~100 pull-offs; beyond, jkrcyl.BranchLimitWarning)
FD_REL = 2e-4           # finite-difference steps: in eps at a fixed zone length, relative to eps; in c, to c - eps
ZONE_FD = 5e-4          # ... in a shifted system (next to eps_s), extrapolated from h and 2h
ALL_POINTS = 160        # eps samples of a branch whose zone reaches round at the touch end
ROUND_SCAN = 10         # contacts scanned for a zone that stops reaching round (top_opens)
ROUND_JUMP = 1e-2       # a zone end this far below pi just past the opening is a jump (a continuous one -> pi)
TOP_PROBE = 1e-2        # top_opens: the gap this fraction of the exterior below pi against h(pi) (a bridge: larger)
NARROW = 1e-6           # top_opens: a round zone within this of h0 at the jump has ended there (a narrow S)
PARTING_POINTS = 257    # top_opens: exterior angles where the round zone's gap is checked against h0

_PointData = namedtuple("_PointData", "eps c delta p B dp_dt ddn_dt D_p D_dn h_pi zones fields state")


class Point(_PointData):
    """Per-point data (kernel scale): the state, its slopes along t, the derivatives D_X the stability rule reads,
    h(pi)/Delta, zones, fields and the state itself (jkrcyl.numerics.cohesive.CohesiveState).  The total
    potential (:func:`potential`, a quadrature of the gap over the zones) and the feasibility
    (jkrcyl.numerics.cohesive.gap_check, the gap on a grid of the exterior) are computed when first read and
    kept: a branch table needs the feasibility only, a state's energy the potential."""

    @functools.cached_property
    def potential(self):
        return potential(self.state)

    @functools.cached_property
    def feasible(self):
        return _co.gap_check(self.state, 120).feasible


class Law:
    """A validated Dugdale law with its kernel, node policy and cached fixed contacts."""

    def __init__(self, m, s0, theta, gb, ar):
        self.m, self.s0, self.kernel = _co._law(m, s0, theta, gb, ar)
        self.theta, self.gb, self.ar = theta, gb, ar
        self.h0 = self.m ** 2 / self.s0
        self.d0 = _co.dugdale_zone(self.m, self.s0)
        self.eps_lo = min(START * 2 * self.m ** (2 / 3), 1e-3)
        self.eps_hi = min(math.pi - 0.05, 2 * math.atan(_one.receding_contact(theta, gb, ar)) * (1 - EPS_MARGIN))
        self.p_cap = P_CAP * self.m ** (4 / 3)
        self.fixed = functools.lru_cache(maxsize=256)(self._fixed)
        self._shifted = functools.lru_cache(maxsize=64)(
            lambda eps, shift: _co.FixedContact(eps, self.kernel, *self.contact(eps), shift=shift))
        self.residuals = {}          # the zone-end residual by (log eps, log(c - eps)): cohesive_follow.residual
        self.loads = {}              # p at k = 0 by (log eps, log(c - eps)): the trace's domain checks

    @functools.cached_property
    def touch(self):
        """(the zone-only pin's touch or None, the contact the trace starts at): cohesive_zones.law_touch."""
        return _cz.law_touch(self)

    def nodes(self, eps):
        """Nodes as a function of eps only (a smooth residual along the trace: jkrcyl.numerics.cohesive_pull_off)."""
        return self.contact(eps)[0]

    def contact(self, eps):
        """(nodes, layered) as a function of eps only, from the Dugdale zone estimate d0
        (jkrcyl.numerics.cohesive.contact_nodes): the same contact for the trace and every state on it."""
        n, layered = _co.contact_nodes(eps, self.d0, self.ar)
        return (n if layered else min(n // 8 * 8 + 8, _co.NODES_MAX)), layered

    def state(self, eps, near=None):
        """jkrcyl.numerics.cohesive.cohesive_state at eps with this law's contact (nodes, layer)."""
        n, layered = self.contact(eps)
        return _co.cohesive_state(eps, self.m, self.s0, self.theta, self.gb, self.ar, n=n, near=near,
                                  layered=layered)

    def _fixed(self, eps):
        """The fixed contact eps (its system shifted next to eps_s: jkrcyl.numerics.cohesive_contact.regular)."""
        return _cc.regular(eps, self.kernel, *self.contact(eps), shifted=self._shifted)

    def fixed_as(self, eps, shift):
        """The fixed contact eps with the shift of a difference stencil's centre (one system's coefficients)."""
        fc = self.fixed(eps)
        return fc if fc.shift == shift else self._shifted(eps, shift)


def affine(law, eps, c, shift=None):
    """[k, p, B, g] at the contact eps, zone end c (c >= pi: zones 'all'), each (value at delta = 0, d/d delta);
    g = h(c) - h0 (None for 'all'): jkrcyl.numerics.cohesive_kernels.affine; shift: the system's (Law.fixed_as)."""
    fc = law.fixed(eps) if shift is None else law.fixed_as(eps, shift)
    v = _ck.affine(fc.fx, fc.ek, fc.ep, fc.eb, float(c), law.s0, law.h0)
    return [(v[0], v[1]), (v[2], v[3]), (v[4], v[5]), (v[6], v[7]) if c < math.pi else None]


def _at(pair, delta):
    return pair[0] + delta * pair[1]


def top_opens(law, points=ROUND_SCAN):
    """For a branch whose zone reaches round at its touch end (zones 'all' at eps_lo): (eps, c, kind) where the
    first zone-end root of jkrcyl.numerics.cohesive.cohesive_state stops short of the top with a jump to c
    (pi - c > ROUND_JUMP just past eps, and as large with the opening bracketed 1e4 times closer), or None when
    the zone stays round or opens continuously (c -> pi, as a square root).  The kinds of jump:
    'S-shaped branch' -- the round zone's largest gap at the top: the round-zone states go on until h(pi) = h0,
    where a zone end comes in from pi and runs back in eps to a fold onto the first root (traced whole:
    jkrcyl.numerics.cohesive_round); 'narrow S-shaped branch' where h(pi) >= (1 - NARROW) h0 at the jump already
    (M 0.70, lambda 1.47, gb 1/2.8: two zone-end roots near the top meet ~3e-4 below the opening in eps; traced
    with pi - c as parameter, cohesive_round.near_top).  Where h has a local minimum at pi: 'top bridge' if the
    round zone's gap reaches h0 beside the top at the jump (it would part there, a zone at the top apart from the
    bottom one; none found yet), else 'second zone family': the round zone goes on (its gap below h0 at
    PARTING_POINTS angles) and the jump is to a zone family born at a fold in eps (rigid cradle round E_I 6.93
    GPa, nu_I 0, lambda 2, M 0.526: round-zone states overlapping the top up to the receding limit's pole);
    neither traced.  A scan of ``points`` contacts (geometric in eps to eps_hi), the first short one bisected."""
    c_at = lambda e: law.state(e).c
    eps = np.geomspace(law.eps_lo, law.eps_hi, points)
    if c_at(eps[0]) < math.pi:
        return None
    short = [k for k in range(1, points) if c_at(eps[k]) < math.pi]
    if not short:
        return None
    lo, hi = math.log(eps[short[0] - 1]), math.log(eps[short[0]])
    opening = []                 # pi - c just past the opening, bracketed to 1e-6 and to 1e-10 in log eps
    for tol in (1e-6, 1e-10):
        while hi - lo > tol:
            mid = 0.5 * (lo + hi)
            lo, hi = (lo, mid) if c_at(math.exp(mid)) < math.pi else (mid, hi)
        opening.append(math.pi - c_at(math.exp(hi)))
    # a continuous opening (c ~ pi - k sqrt(eps - eps_open)) shrinks 10x; a jump stays
    if opening[1] <= max(ROUND_JUMP, 0.5 * opening[0]):
        return None
    below = law.state(math.exp(lo))
    beside = below.fields.gap(math.pi - TOP_PROBE * (math.pi - below.eps))[0]
    ended = state_values(law, math.exp(hi), math.pi)[2] >= (1 - NARROW) * law.h0    # the round zone, at the jump
    kind = "narrow S-shaped branch" if ended else "S-shaped branch"
    if beside > below.h_pi_over_Delta:          # the gap's least at the top: the zone parts beside it, or goes on
        gap = _bo.round_gap(law, math.exp(hi), np.linspace(math.exp(hi), math.pi, PARTING_POINTS))
        kind = "top bridge" if gap.max() >= (1 - NARROW) * law.h0 else "second zone family"
    return math.exp(hi), math.pi - opening[1], kind


def trace(law):
    """The branch as (x points (n, 2), kind, reason): kind 'zone' (x = (log eps, log(c - eps))) or 'all'
    (x = (log eps, 0)); reason '' when the trace ends where the branch leaves its domain (the receding limit, the
    zone reaching round, p = P_CAP m^(4/3)), else why it stopped before (jkrcyl.numerics.cohesive_follow).
    An S-shaped branch, narrow or not (:func:`top_opens`), is traced whole (jkrcyl.numerics.cohesive_round): kind
    'zone' with a fourth item, the number of leading points whose zone is round (c = pi)."""
    start = law.state(law.eps_lo)
    if start.zones == "all":
        opens = opens_of(law)
        if opens is not None and opens[2] in ("S-shaped branch", "narrow S-shaped branch"):
            return _round.trace(law, opens[0], lambda x: _inside(law, x), lambda e: state_values(law, e, math.pi)[2])
        eps = np.geomspace(law.eps_lo, law.eps_hi, ALL_POINTS)
        return np.column_stack([np.log(eps), np.zeros(eps.size)]), "all", ""
    # from the zone-only pin's touch (eps0 -> 0) up to eps_lo the branch runs straight in log eps (c - c_touch ~
    # eps^2): its states solved at contacts JUNCTION_STEP apart, then traced from eps_lo
    eps0 = law.touch[1]
    pre = [[math.log(e), math.log(law.state(e).c - e)] for e in
           np.geomspace(eps0, law.eps_lo, math.ceil(math.log(law.eps_lo / eps0) / JUNCTION_STEP) + 1)[:-1]]
    x0 = np.array([math.log(law.eps_lo), math.log(start.c - law.eps_lo)])
    got = _fo.follow(law, x0, lambda x: _inside(law, x), margin=lambda x: _margin(law, x),
                     cheap=lambda x: _pushes(law, x))
    return np.concatenate([np.reshape(pre, (-1, 2)), got.points]), "zone", got.reason


def opens_of(law):
    """:func:`top_opens` of a law whose range reaches round at the touch end (else None), once per law; at any
    range (h0 >= 2 Delta: nothing pulls, but pushed the round zone jumps: vartheta 10, gb 0, lambda 3.155, M 0.246)."""
    if not hasattr(law, "_opens"):
        law._opens = top_opens(law) if law.state(law.eps_lo).zones == "all" else None
    return law._opens


def _inside(law, x):
    """The domain of the traced zone branch: eps_lo <= eps < eps_hi, c < pi, p below the load cap."""
    eps, d = math.exp(x[0]), math.exp(x[1])
    return law.touch[1] * 0.999 <= eps < law.eps_hi and eps + d < math.pi * (1 - 1e-9) and _load(law, x) < law.p_cap


def _load(law, x):
    """p at k = 0 at x = (log eps, log(c - eps)), kept per law (for _inside, _margin, _pushes)."""
    key = (float(x[0]), float(x[1]))
    if key not in law.loads:
        if len(law.loads) > _fo.MEMO_MAX:
            law.loads.clear()
        aff = affine(law, math.exp(x[0]), math.exp(x[0]) + math.exp(x[1]))
        law.loads[key] = _at(aff[1], -aff[0][0] / aff[0][1])
    return law.loads[key]


def _margin(law, x):
    """How far x lies beyond the load cap (< 0 below): 1 - p_cap/p, linear in the arclength next to the pole of
    p (the receding limit) and on through it (p < 0 past it, eps >= eps_hi: > 1); -inf where p <= 0 short of
    it; NaN outside another bound and not beyond the cap (cohesive_follow then cuts the step as before)."""
    eps, d, p = math.exp(x[0]), math.exp(x[1]), _load(law, x)
    load = 1 - law.p_cap / p if p > 0 or (p < 0 and eps >= law.eps_hi) else -math.inf
    other = not (law.touch[1] * 0.999 <= eps < law.eps_hi and eps + d < math.pi * (1 - 1e-9))
    return np.array([math.nan if other and load <= 0 else load])


def _pushes(law, x):
    """p > 0: past the zero-load contact towards the load cap, no pull-off there (cohesive_follow's cheap)."""
    return _load(law, x) > 0


def arclength(x):
    return np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(x, axis=0).T))])


def project(law, x_pred, normal, scale):
    """The curve's point near x_pred between two traced points: on the line of fixed eps where the chord runs
    more along eps (|normal_c| >= 1/2; one LU; the root by secant from the prediction), else x_pred + tau normal
    (|tau| <= 4 scale: by secant, else bracketed); else the zone end nearest to the predicted one at the predicted
    eps, or None."""
    eps = math.exp(x_pred[0])
    if abs(normal[1]) >= 0.5:
        y = _fo.fixed_eps(law, x_pred, 4 * scale)
        if y is not None:
            return y
    y = _fo.normal_line(law, x_pred, np.array([normal[1], -normal[0]]), 8 * scale)
    if y is not None:
        return y
    f = lambda tau: _fo.residual(law, x_pred + tau * normal)
    f0 = f(0.0)
    if f0 == 0.0:
        return x_pred
    for w in scale * np.array([0.05, 0.25, 1.0, 4.0]):
        for side in (1, -1):
            fs = f(side * w)
            if np.isfinite(fs) and fs * f0 < 0:
                tau = _roots.root(f, *sorted((0.0, side * w)))
                return x_pred + tau * normal
    d = law.fixed(eps).zone_end_near(law.s0, law.h0, math.exp(x_pred[1]))
    return None if d is None else np.array([x_pred[0], math.log(d)])


def load_approach(law, eps, c):
    """(p, delta/Delta) of the equilibrium (eps, c) (k = 0): :func:`state_values` without h(pi) (which costs a
    solve for the zone and the gap: a search for a held load or approach needs neither)."""
    if _bo.applies(law, eps, c):                  # the zone all round: regular at the degenerate contact
        p, delta, _ = _bo.round_values(law, eps)
        return p, delta
    aff = affine(law, eps, c)
    delta = _cc.approach(aff)
    return _at(aff[1], delta), delta


def state_values(law, eps, c):
    """(p, delta/Delta, h(pi)/Delta) of the equilibrium (eps, c) (k = 0), without slopes."""
    if _bo.applies(law, eps, c):                  # the zone all round: regular at the degenerate contact
        p, delta, u = _bo.round_values(law, eps)
        return p, delta, _bo.of(law, eps).fc.gap(math.pi, delta, u, _co.zones_of(math.pi), law.s0)[0]
    p, delta = load_approach(law, eps, c)
    fc = law.fixed(eps)
    zones = _co.zones_of(min(c, math.pi))
    u = fc.fx[3] + delta * fc.fx[4] + law.s0 * fc.zone_unit(zones)
    return p, delta, fc.gap(math.pi, delta, u, zones, law.s0)[0]


def slopes(law, eps, c, direction):
    """(dp/dt, d(delta/Delta)/dt) at an equilibrium (eps, c) as :func:`point` gives them, without the state's
    fields, feasibility and energy (the refinement of a fold)."""
    return _slopes(law, eps, c, direction)[1:3]


def _slopes(law, eps, c, direction):
    """(delta/Delta, dp/dt, d(delta/Delta)/dt, D_p, D_dn) at an equilibrium (eps, c) (:func:`point`)."""
    if _bo.applies(law, eps, c):                  # the zone all round (jkrcyl.numerics.cohesive_bordered)
        return _bo.round_slopes(law, eps)
    shift = law.fixed(eps).shift                  # the stencil's contacts in the centre's system
    aff = affine(law, eps, c)
    delta = _cc.approach(aff)
    k_d, p_d = aff[0][1], aff[1][1]
    dv = lambda i, pair, h: (_at(pair[0][i], delta) - _at(pair[1][i], delta)) / (2 * h)
    if c < math.pi:
        # d/d eps at fixed c = d/d eps at fixed zone length d = c - eps (a step on the scale of eps: the states
        # are smooth there, however thin the zone) less d/dc (a step on the scale of d, on the same LU): central
        # differences (dp/d(delta) to ~5e-7), extrapolated from h and 2h next to eps_s (~3e-9; everywhere: +13-40 %
        # LUs per cold pull-off)
        fd = ZONE_FD if shift else FD_REL
        he, hc = fd * min(eps, math.pi - c), fd * min(c - eps, math.pi - c)
        along_e = lambda h: [affine(law, eps + s * h, c + s * h, shift) for s in (1, -1)]
        along_c = lambda h: [affine(law, eps, c + s * h, shift) for s in (1, -1)]
        rich = lambda f, h: [(4 * dv(i, f(h), h) - dv(i, f(2 * h), 2 * h)) / 3 if shift else dv(i, f(h), h)
                             for i in (0, 1, 3)]
        k_c, p_c, g_c = rich(along_c, hc)
        k_e, p_e, g_e = np.array(rich(along_e, he)) - (k_c, p_c, g_c)
        g_d = aff[3][1]
        T = np.cross([k_e, k_d, k_c], [g_e, g_d, g_c])          # (d eps, d delta, d c)
        sigma = 1.0 if T[0] * direction[0] + T[2] * direction[1] >= 0 else -1.0
        D_p, D_dn = sigma * (k_e * p_d - k_d * p_e), sigma * k_e
        rate = math.hypot(T[0] / eps, (T[2] - T[0]) / (c - eps))   # dt/dT: t is arclength in x
        dp_dt, ddn_dt = sigma * (p_e * T[0] + p_d * T[1] + p_c * T[2]) / rate, sigma * T[1] / rate
    else:
        he = FD_REL * eps
        de = [affine(law, eps + s * he, c, shift) for s in (1, -1)]
        k_e, p_e = dv(0, de, he), dv(1, de, he)
        D_p, D_dn = p_d / k_d, 1.0 / k_d
        ddn_deps = -k_e / k_d                                    # t = log eps
        dp_dt, ddn_dt = eps * (p_e + p_d * ddn_deps), eps * ddn_deps
    return delta, dp_dt, ddn_dt, D_p, D_dn


def point(law, eps, c, direction):
    """The per-point data at an equilibrium (eps, c) (c = pi: zones 'all'); direction = (d eps, d c) of
    increasing t (its orientation only)."""
    delta, dp_dt, ddn_dt, D_p, D_dn = _slopes(law, eps, c, direction)
    round_zone = _bo.applies(law, eps, c)
    fc = _bo.of(law, eps).fc if round_zone else law.fixed(eps)
    zones = _co.zones_of(min(c, math.pi))
    if round_zone:
        u = _bo.round_values(law, eps)[2]
    else:
        u = fc.fx[3] + delta * fc.fx[4] + law.s0 * fc.zone_unit(zones)
    st = _co._state(eps, c, fc, delta, u, zones, law.m, law.s0, law.kernel, law.gb, fc.sys.n)
    return Point(eps, st.c, delta, st.p, st.B, dp_dt, ddn_dt, D_p, D_dn, st.h_pi_over_Delta, st.zones, st.fields,
                 st)


potential = _co.potential      # the total potential of a state (kept here: its readers name it so)
