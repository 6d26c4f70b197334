"""The super-critical contact branch of one Maugis-Dugdale law: contacts beyond the receding limit eps_crit.

Notation of jkrcyl.numerics.cohesive_branch.  At a fixed contact the edge coefficient k is affine in the approach
with a slope that vanishes at the receding contact eps_crit = 2 atan(a_crit) whatever the zone (the adhesionless
field fixes it), so the approach, and with it the load, has a pole there for any law: JKR's (4.4) splits into the
sub-critical (eps < eps_crit) and the super-critical (eps > eps_crit) branch, and so does the cohesive one.  The
super-critical branch is the same curve k = 0, h(c) = h0 (the zone end's first root above the Dugdale estimate,
the root that tends to JKR) on the other side of the pole: traced by the same continuation
(jkrcyl.numerics.cohesive_follow) in x = (log eps, log(c - eps)) from just past the pole -- eps_crit (1 +
EPS_MARGIN), or further where |p| exceeds the load cap P_CAP m^(4/3) there -- towards growing eps, up to
eps = pi - 0.05 (the limit of the sub-critical trace too), the load cap, or the zone reaching round (h(pi) = h0:
a top gap within the range; the trace stops ROUND_MARGIN below c = pi, where the branch runs back in eps with its
zone end closing on the top, solved at each contact down to pi - c = JOIN_S_MIN -- :func:`join_points` -- and
goes on with its zone all round -- :func:`round_tail`, sampled in eps towards full contact, where its load tends
to the bond limit of jkrcyl.model.full_contact.holds).  Where the zone reaches round already at the start, the branch has zones
'all' (no zone end: k = 0 alone) and is sampled in eps.  Where the branch crosses eps_crit with a finite load the
model's table goes on from an end at the margin back across it (jkrcyl.numerics.cohesive_crossing).

JKR limit (measured, identical bodies, M = 0.4 and 0.8): at a fixed contact 2.0 <= eps <= 2.7 the load differs
from JKR's (4.4) by C/lambda^2, |C| <= 5 in P* (2e-3 at lambda = 50); the limit is not uniform at either end: next
to the pole (the approach diverges, the zone of the state shrinks and the load's residue differs from JKR's: P* 149
against 188 at eps - eps_crit = 2.6e-3, lambda = 50, M = 0.8) and towards eps -> pi (the top gap nears the range:
lambda^2 dP* ~ 100 at eps = 3.09), where at lambda of order 10 the branch folds back on the second root.

A rigid cradle at alpha* = 0 (vartheta = inf) has no receding contact (a_crit = inf, section 7.2) and no
super-critical branch; nor has a pair whose eps_crit lies within 0.05 rad of pi.
"""
import math

import numpy as np

from . import cohesive as _co
from . import cohesive_bordered as _bo
from . import cohesive_branch as _cb
from . import cohesive_follow as _fo
from . import one_arc as _one
from . import roots as _roots

EPS_TOP = math.pi - 0.05      # the branch is traced up to this contact half-angle (as the sub-critical one)
START_SCAN = 24               # contacts scanned past the pole for the first one below the load cap
EPS_CLOSE = 1e-3              # the round-zone tail stops this far from full contact [rad] (nodes ~ sqrt(eps/(pi - eps)))
TAIL_POINTS = 40
JOIN_SCAN, JOIN_STEP = 40, 5e-3     # the downward scan for the tail's join below the trace's end [rad]
ROUND_MARGIN = 1e-3           # the zone end stops this far below pi [rad]: it reaches round as a square root
                              # (h(c) - h0 has a double root at c = pi, h being even about the top), where the
                              # trace would need steps ~ pi - c
JOIN_POINTS = 24              # zone states from the trace's end to the join, geometric in eps - eps_join ...
JOIN_S_MIN = 1e-7             # ... down to pi - c = JOIN_S_MIN [rad] (a state's slopes step 2e-4 (pi - c) in eps)


def eps_range(law):
    """(eps_lo, eps_hi) of the super-critical branch, or None when it has none (no receding contact, or one
    within 0.05 rad of pi)."""
    a_crit = _one.receding_contact(law.theta, law.gb, law.ar)
    if math.isinf(a_crit):
        return None
    lo = 2 * math.atan(a_crit) * (1 + _cb.EPS_MARGIN)
    return (lo, EPS_TOP) if lo < EPS_TOP * (1 - 1e-3) else None


def _load(law, eps):
    return law.state(eps).p


def start(law, lo, hi):
    """The first contact past the pole whose load is within the cap (|p| <= P_CAP m^(4/3)): lo itself, else the
    root of |p| = cap between the last contact beyond it and the first within (a scan geometric in eps - eps_crit,
    then Brent to 1e-12 in eps); None when no contact up to hi is within the cap."""
    cap = law.p_cap
    if abs(_load(law, lo)) <= cap:
        return lo
    pole = lo / (1 + _cb.EPS_MARGIN)
    grid = pole + np.geomspace(lo - pole, hi - pole, START_SCAN)
    prev = lo
    for e in grid[1:]:
        if abs(_load(law, e)) <= cap:
            return _roots.root(lambda x: abs(_load(law, x)) - cap, prev, e, xtol=1e-12)
        prev = e
    return None


def trace(law):
    """The super-critical branch as (x points (n, 2), kind, reason) -- as jkrcyl.numerics.cohesive_branch.trace:
    kind 'zone' (x = (log eps, log(c - eps))) or 'all' (x = (log eps, 0)); reason '' when the trace ends where the
    branch leaves its domain (eps = pi - 0.05, the load cap, the zone reaching round), else why it stopped -- and,
    where the zone reaches round, a fourth item: the eps of the round-zone tail (:func:`round_tail`), and a fifth:
    how many of the last points run on to the tail's join with c -> pi (:func:`join_points`); None when the law
    has no super-critical branch (:func:`eps_range`) or no contact on it below the load cap."""
    span = eps_range(law)
    if span is None:
        return None
    lo, hi = span
    eps0 = start(law, lo, hi)
    if eps0 is None:
        return None
    first = law.state(eps0)
    if first.zones == "all":
        eps = np.geomspace(eps0, hi, _cb.ALL_POINTS)
        return np.column_stack([np.log(eps), np.zeros(eps.size)]), "all", ""

    def inside(x):
        eps, d = math.exp(x[0]), math.exp(x[1])
        if not (eps0 * (1 - 1e-9) <= eps < hi and eps + d < math.pi - ROUND_MARGIN):
            return False
        aff = _cb.affine(law, eps, eps + d)
        return abs(_cb._at(aff[1], -aff[0][0] / aff[0][1])) <= law.p_cap * (1 + 1e-9)

    x0 = np.array([math.log(eps0), math.log(first.c - eps0)])
    got = _fo.follow(law, x0, inside)
    eps_end, c_end = math.exp(got.points[-1, 0]), math.exp(got.points[-1, 0]) + math.exp(got.points[-1, 1])
    if got.reason or c_end < math.pi - 2 * ROUND_MARGIN:
        return got.points, "zone", got.reason
    tail = round_tail(law, eps_end)
    join = join_points(law, got.points[-1], tail[0]) if tail.size else np.zeros((0, 2))
    return np.vstack([got.points, join]), "zone", "", tail, len(join)


def top_gap(law, eps, s_hi=4 * ROUND_MARGIN, s_lo=1e-15):
    """pi - c of the zone state at the contact eps whose zone end c lies within s_hi of pi, or None: at a fixed
    contact R(s) = h(pi - s) - h0 falls with s (the traction removed next to the top opens the gap there by ~
    s log s) to the round zone's h(pi) - h0, negative past the join, so it changes sign once in (s_lo, s_hi):
    Brent in log s (each evaluation on the contact's one LU, jkrcyl.numerics.cohesive_follow.residual)."""
    le = math.log(eps)
    r = lambda ls: _fo.residual(law, np.array([le, math.log(math.pi - math.exp(ls) - eps)]))
    lo, hi = math.log(s_lo), math.log(s_hi)
    r_lo, r_hi = r(lo), r(hi)
    if not (r_lo < 0 < r_hi):
        return None
    return math.exp(_roots.root(r, lo, hi, xtol=1e-13))


def join_points(law, x_end, eps_join):
    """The zone states between the trace's last point x_end = (log eps, log(c - eps)) (c = pi - ROUND_MARGIN)
    and the join eps_join of the round-zone tail (c -> pi): there the branch runs back in eps to eps_join while
    its zone end closes on the top, pi - c ~ (eps - eps_join)/log -- a graph pi - c (:func:`top_gap`) over eps,
    sampled at up to JOIN_POINTS contacts geometric in eps - eps_join (from x_end's, to 1e-6 of it) while
    pi - c >= JOIN_S_MIN; the
    points as x (n, 2), empty where x_end's contact lies below eps_join (no turn back: nothing to join)."""
    eps_end = math.exp(x_end[0])
    if not eps_end > eps_join:
        return np.zeros((0, 2))
    pts = []
    for f in np.geomspace(1.0, 1e-6, JOIN_POINTS + 1)[1:]:
        eps = eps_join + f * (eps_end - eps_join)
        s = top_gap(law, eps)
        if s is None or s < JOIN_S_MIN:
            break
        pts.append([math.log(eps), math.log(math.pi - s - eps)])
    return np.array(pts).reshape(-1, 2)


def round_state(law, eps):
    """The contact |phi| < eps with its zone all round (zones 'all': k = 0 alone), as a CohesiveState."""
    zones = _co.zones_of(math.pi)
    if _bo.applies(law, eps, math.pi):       # regular at the degenerate contact (jkrcyl.numerics.cohesive_bordered)
        fc, (dn, u) = _bo.of(law, eps).fc, _bo.round_values(law, eps)[1:]
    else:
        fc = law.fixed(eps)
        dn, u = fc.solve(zones, law.s0)
    return _co._state(eps, math.pi, fc, dn, u, zones, law.m, law.s0, law.kernel, law.gb, fc.sys.n)


def round_tail(law, eps_round):
    """Where the zone reaches round, the branch goes on with its zone all round.  The trace stops at
    c = pi - ROUND_MARGIN (eps_round), but c reaches pi only where the round zone's own gap at the top is h0 --
    at eps_join, below eps_round (the state with the last ROUND_MARGIN of traction removed differs from the round
    one by the log kernel's local response; identical bodies, lambda = 5, M = 0.5: eps_join = 2.3418 against
    2.3576): there the branch turns back in eps (a fold: p is largest there) and the round-zone states run from
    eps_join towards full contact, as long as they obey the law (0 <= h <= h0 on the gap:
    jkrcyl.numerics.cohesive.gap_check), up to pi - EPS_CLOSE (TAIL_POINTS, geometric in pi - eps), where the load
    tends to the bond limit (jkrcyl.model.full_contact.holds), or until the top touches (h(pi) < 0) or the gap
    leaves the range.  The eps of those states (increasing, the first eps_join; empty if the round zone at
    eps_round leaves the range).  The zone states between eps_round and eps_join: :func:`join_points`."""
    top = lambda eps: round_state(law, eps).h_pi_over_Delta - law.h0
    if not _co.gap_check(round_state(law, eps_round), 120).feasible:
        return np.zeros(0)
    lo, hi = eps_round, eps_round
    for _ in range(JOIN_SCAN):
        lo = hi - JOIN_STEP
        if top(lo) > 0:
            break
        hi = lo
    else:
        return np.zeros(0)
    join = _roots.root(top, lo, hi, xtol=1e-12) + 1e-12
    gap = (math.pi - join) * np.geomspace(1.0, EPS_CLOSE / (math.pi - join), TAIL_POINTS)
    tail = []
    for eps in math.pi - gap:
        if not _co.gap_check(round_state(law, eps), 120).feasible:
            break
        tail.append(eps)
    return np.array(tail)


def round_end(eps, tail):
    """Why a super-critical table whose zone reached round ends at eps ('' where its round-zone tail reaches
    full contact: the branch goes on as the bonded pin)."""
    if tail.size == TAIL_POINTS:
        return ""
    if tail.size == 0:
        return (f"the zone reaches round the hole at eps = {eps:.6g} rad (h(pi) = h0) and the states beyond with a "
                "zone all round leave the range (0 <= h <= h0): not traced")
    return (f"the zone all round leaves the range at eps = {eps:.6g} rad (the top closing, h(pi) < 0, or the gap "
            "exceeding h0): the states beyond are not traced")


def reaches_full(tail, a, branch):
    """Whether the branch parameter a is the end of a round-zone tail that reaches full contact (TAIL_POINTS
    states up to pi - EPS_CLOSE)."""
    return tail.size == TAIL_POINTS and a >= branch.offset + (branch.a_end - branch.offset) * (1 - 1e-9)
