"""The S-shaped contact branch of a Maugis-Dugdale law whose zone reaches round at small contacts.

Notation of jkrcyl.numerics.cohesive_branch.  Where the range reaches round at the touch end (zones 'all': the
zone is the whole exterior, no zone end, k = 0 alone fixes the approach) the states with a round zone form a
family in eps that ends where its top gap reaches the range, h(pi) = h0, at eps_open.  Past it the zone end
leaves the top, c < pi.  Usually it does so towards larger contacts (c -> pi as a square root: a smooth
continuation, sampled in eps by cohesive_branch.trace).  On an S-shaped branch (cohesive_branch.top_opens) it
leaves towards smaller contacts: the zone-end root near the top (c2) runs back in eps from (eps_open, pi) to a
fold at eps_jump, where it meets the first root (c1, the root that tends to JKR), which then runs on towards
larger contacts.  Two folds in eps, at eps_open and eps_jump: the branch is

    round (eps_lo .. eps_open, c = pi)  ->  c2 (eps_open .. eps_jump, back)  ->  c1 (eps_jump .. , forward),

traced here as one polyline in x = (log eps, log(c - eps)): the round part at the constant x1 = log(pi - eps_open)
(so its arclength is log eps, the parameter of a round-zone branch, and its last point is the opening), then the
zone part next to the top by :func:`near_top` -- in the plane (eps, pi - c), by arclength, corrected along
whichever of the two the branch runs along, so that neither eps(c) nor c(eps) need be single-valued: a narrow S
(its fold within ~1e-3 of the opening in eps, where the continuation's first step from the opening would cut
across both turns), a zone end leaving the top FORWARD in eps (the scan of top_opens calls it an S where the first
root's pair is born apart from the top: a rigid pair, h0 1.5 Delta, lambda 1.625 -- its zone end runs forward up
to the receding limit), one turning back in c -- the folds in eps refined and kept as points; then the
continuation of jkrcyl.numerics.cohesive_follow from its last point (a wide S, and what near_top cannot follow:
from c = pi - START_DC at the opening, the tangent towards a shorter zone).  The round prefix's points have c = pi
(Traced reads n_round).

Next to the receding contact eps_crit the zone-end residual of cohesive_follow (the approach eliminated by k = 0)
has a pole (dk/d(delta) vanishes there at every zone end); near_top's residual is that one times dk/d(delta),
smooth there.  (A branch with its zone end near the top crosses eps_crit with a finite approach where k at
delta = 0 vanishes too -- the rigid pair above: pi - c = 0.0243, p = 0.6670 on both sides -- the sub-critical table
ends at the receding limit as usual.)
"""
import math

import numpy as np

from . import cohesive_follow as _fo
from . import cohesive_kernels as _ck
from . import roots as _roots

ROUND_POINTS = 40          # round-zone points per unit of log eps (cohesive_branch.ALL_POINTS over its range)
TOP_FIRST = 1e-6          # a narrow S: its first zone point has pi - c = TOP_FIRST [rad] (eps within ~1e-13 of
                          # the opening: eps_open - eps grows as (pi - c)^2)
TOP_FACTOR = 10 ** 0.125  # ratio of successive pi - c next to the top
TOP_STEP = math.log(TOP_FACTOR)   # ... the largest step of near_top in its plane
TOP_PAST = 1e-3           # ... within this of the opening in eps (relative): then the continuation
TOP_MAX = 1.0             # ... within pi - c < TOP_MAX
TOP_EDGE = 1e-3 * TOP_STEP   # ... the step below which a point outside the domain ends the branch there
TOP_STEPS = 400           # ... at most this many points
TOP_GROW = 1000           # ... the largest step, where the branch runs along eps: TOP_GROW steps along x
TOP_TURN = 0.9            # ... the least cosine between a step and the tangent before it
START_DC = 1e-4            # the zone part starts at c = pi - START_DC [rad] (its eps is then within ~1e-9 of the
                           # opening: pi - c grows as the square root of the distance in eps)


def opening(law, eps_jump, top_gap):
    """eps_open where the round-zone family's top gap reaches the range (top_gap(eps) = h(pi)/Delta of its state
    at the contact eps equals h0), to 1e-13 relative: above eps_jump, or below it on a narrow S (the round zone
    already at h0 there: bracketed downwards); None when it stays within the range up to eps_hi."""
    excess = lambda e: top_gap(e) - law.h0
    lo = eps_jump
    if excess(lo) >= 0:                 # a narrow S: the scan's jump is the opening itself (or just past it)
        for rel in 1e-9 * 4.0 ** np.arange(12):
            below = eps_jump * (1 - rel)
            if excess(below) < 0:
                return _roots.root(excess, below, lo, xtol=1e-15 * eps_jump)
            lo = below
        return None
    for hi in np.geomspace(eps_jump, law.eps_hi, 24)[1:]:
        if excess(hi) >= 0:
            return _roots.root(excess, lo, hi, xtol=1e-13 * hi)
        lo = hi
    return None


def trace(law, eps_jump, inside, top_gap):
    """The S-shaped branch as (x (n, 2), 'zone', reason, n_round) (module docstring); inside(x): the domain of the
    zone part (cohesive_branch.trace's); top_gap: :func:`opening`'s.  reason '' when the trace ends where the
    branch leaves its domain.  Where the round zone never opens below eps_hi the branch is the round zone alone
    (the two zone-end families born at the fold eps_jump join it only past the receding limit: not on this
    branch's table)."""
    eps_open = opening(law, eps_jump, top_gap)
    if eps_open is None:                 # the round zone stays within the range up to eps_hi: the branch is round
        eps_open = law.eps_hi            # all along (the zone-end pair born at the fold joins it past a_crit)
        x1 = math.log(math.pi - eps_open)
        eps = np.geomspace(law.eps_lo, eps_open, max(8, int(ROUND_POINTS * math.log(eps_open / law.eps_lo)) + 1))
        return np.column_stack([np.log(eps), np.full(eps.size, x1)]), "zone", "", eps.size
    x1 = math.log(math.pi - eps_open)
    n = max(8, int(ROUND_POINTS * math.log(eps_open / law.eps_lo)) + 1)
    eps = np.geomspace(law.eps_lo, eps_open, n)
    eps[-1] = eps_open
    rounded = np.column_stack([np.log(eps), np.full(n, x1)])
    # the zone part next to the top traced in (eps, pi - c) (near_top: any shape, the folds refined; the
    # continuation's first step from the opening would cut across a narrow S's turns), then the continuation;
    # where near_top finds nothing, the continuation from c = pi - START_DC towards smaller contacts (a wide S)
    near, why, ended = near_top(law, eps_open, inside)
    if ended:                            # the branch leaves its domain next to the top (the receding limit)
        return np.vstack([rounded, near]), "zone", "", n
    if not why:
        y, prev = near[-1], near[-1] - near[-2]
        rounded = np.vstack([rounded, near[:-1]])
    elif eps_open < eps_jump:            # a narrow S not traced next to the top: said so
        return rounded, "zone", why, n
    else:
        y, prev = _zone_start(law, eps_open), np.array([-1.0, 0.0])
    if y is None:
        return rounded, "zone", (f"the cohesive branch could not be followed beyond the round zone's opening at "
                                 f"eps = {eps_open:.6g} rad: no zone end near the top"), n
    got = _fo.follow(law, y, inside, prev=prev)
    return np.vstack([rounded, got.points]), "zone", got.reason, n


def _gap_at_rest(law, eps, x):
    """k1 g0 - k0 g1 at the contact eps and the zone end c = pi - x: the zone-end residual h(c) - h0 with k = 0
    (cohesive_follow.residual, the approach eliminated by k) times dk/d(delta).  Smooth where that one has a pole:
    dk/d(delta) vanishes on a line of fixed eps (the approach leaves k unchanged at that contact), crossed by the
    branch where k0 vanishes too (the state's approach there fixed by g alone)."""
    fc = law.fixed(eps)
    v = _ck.affine(fc.fx, fc.ek, fc.ep, fc.eb, math.pi - x, law.s0, law.h0)
    return v[1] * v[6] - v[0] * v[7]


def _root_near(f, guess, width, lo, hi):
    """The root of f nearest to guess within (lo, hi): a bracket grown from guess +- width by doubling, Brent to
    1e-15 relative; None without a sign change."""
    f0 = f(guess)
    if f0 == 0.0:
        return guess
    for w in width * 2.0 ** np.arange(30):
        for y in (guess - w, guess + w):
            fy = f(y) if lo < y < hi else math.nan
            if math.isfinite(fy) and fy * f0 <= 0:
                return _roots.root(f, *sorted((guess, y)), xtol=1e-15 * max(abs(guess), 1e-300))
    return None


def near_top(law, eps_open, inside=lambda y: True):
    """The zone part next to the top: the branch k = 0, h(c) = h0 from the opening (eps_open, c = pi) traced in
    s = (log(eps/eps_open)/TOP_PAST, log x), x = pi - c, by arclength: a secant predictor; corrected on the line
    of fixed x where the branch runs along x (a new contact per iterate; steps up to log(TOP_FACTOR)), else of
    fixed eps (one contact; steps up to TOP_GROW times that); a step halved where the corrected point lies farther
    than half a step from the predictor (another family's root) or turns by more than acos(TOP_TURN), grown by 1.5
    after each point -- so that neither eps(x) nor x(eps) need be single-valued: an S (eps falls from the opening
    to a fold, then rises; the continuation in (log eps, log(c - eps)) turned back at a fold 0.16 rad below the
    top), a zone end leaving the top forward in eps, one running back to the least contact, one turning back in c.
    The residual is :func:`_gap_at_rest` (no pole).  Ends where the branch rises in eps past TOP_PAST beyond the
    opening, or past a fold and along eps, or reaches x = TOP_MAX (the continuation goes on from there), or
    leaves its domain inside(y) (y = (log eps, log(c - eps)); the last point within a step of TOP_EDGE of the
    edge); each fold in eps met on the way is refined (Brent's extremum in log x to 1e-12) and kept as a point.
    Returns (points (n, 2) in (log eps, log(c - eps)), why ('' when traced), ended: the branch left its domain)."""
    to_s = lambda e, lx: np.array([math.log(e / eps_open) / TOP_PAST, lx])
    pts = []
    for lx in (math.log(TOP_FIRST), math.log(TOP_FIRST * TOP_FACTOR)):
        e = _eps_at(law, lx, pts[-1][0] if pts else eps_open, 1e-12 * eps_open)
        if e is None:
            return None, _no_zone_end(eps_open, math.exp(lx)), False
        pts.append((e, lx))
    h, ended, folded = TOP_STEP, False, False
    while len(pts) < TOP_STEPS:
        e, lx = pts[-1]
        t = to_s(*pts[-1]) - to_s(*pts[-2])
        t /= np.hypot(*t)
        along_x = abs(t[1]) >= abs(t[0])
        rising = e > pts[-2][0]
        folded = folded or (rising and len(pts) > 2 and pts[-2][0] < pts[-3][0])
        if (rising and (e > eps_open * (1 + TOP_PAST) or (folded and not along_x))) or lx > math.log(TOP_MAX):
            break                        # past the opening, or past the fold and along eps: the continuation
        h = min(h, TOP_STEP if along_x else TOP_STEP * TOP_GROW)
        pred = to_s(*pts[-1]) + h * t
        pe = eps_open * math.exp(TOP_PAST * pred[0])
        if along_x:                      # along x: eps at the predicted x
            y = _eps_at(law, pred[1], pe, max(0.25 * h * abs(t[0]) * TOP_PAST * pe, 1e-13 * eps_open))
            y = None if y is None else (y, pred[1])
        else:                            # along eps: x at the predicted contact (one LU)
            f = lambda v: _gap_at_rest(law, pe, math.exp(v))
            y = _root_near(f, pred[1], 0.25 * h * abs(t[1]) + 1e-9, -700.0, math.log(math.pi - pe))
            y = None if y is None else (pe, y)
        step = None if y is None else to_s(*y) - to_s(*pts[-1])
        if y is None or np.hypot(*(to_s(*y) - pred)) > 0.5 * h or step @ t < TOP_TURN * np.hypot(*step):
            h /= 2
            if h < TOP_STEP * 1e-4:
                return None, _no_zone_end(eps_open, math.exp(lx), e), False
            continue
        if not inside(np.array([math.log(y[0]), math.log(math.pi - math.exp(y[1]) - y[0])])):
            if h <= TOP_EDGE:            # the branch leaves its domain (the receding limit, the load cap) here
                ended = True
                break
            h /= 4
            continue
        pts.append(y)
        h *= 1.5
    else:
        return None, (f"the cohesive branch next to the round zone's opening at eps = {eps_open:.6g} rad took "
                      f"{TOP_STEPS} steps"), False
    pts = _folds_refined(law, pts)
    es, lxs = np.array([p[0] for p in pts]), np.array([p[1] for p in pts])
    return np.column_stack([np.log(es), np.log(math.pi - np.exp(lxs) - es)]), "", ended


def _no_zone_end(eps_open, x, guess=None):
    near = "" if guess is None else f" near eps = {guess:.6g} rad"
    return (f"the cohesive branch could not be followed beyond the round zone's opening at eps = {eps_open:.6g} "
            f"rad: no contact with its zone end at pi - {x:.3g} rad{near}")


def _eps_at(law, lx, guess, width):
    """The contact nearest to guess with a zone end at pi - exp(lx) (:func:`_root_near`), or None."""
    x = math.exp(lx)
    return _root_near(lambda e: _gap_at_rest(law, e, x), guess, width, 0.0, math.pi - x)


def _folds_refined(law, pts):
    """pts with each fold in eps between points traced along x (eps largest or least at an interior point, x
    monotone through it) refined: Brent's extremum of eps in log x to 1e-12, inserted as a point."""
    out = list(pts)
    for j in range(len(pts) - 2, 0, -1):
        (e0, l0), (e1, l1), (e2, l2) = pts[j - 1:j + 2]
        if (e1 - e0) * (e2 - e1) >= 0 or (l1 - l0) * (l2 - l1) <= 0:
            continue
        sign = 1.0 if e1 < e0 else -1.0
        width = abs(e2 - e0) + 1e-12 * e1
        at = lambda v: (lambda r: math.inf if r is None else sign * r)(_eps_at(law, v, e1, width))
        lo, hi = sorted((l0, l2))
        v, e = _roots.minimum(at, lo, l1, hi, 1e-12)
        k = j if (v - l1) * (l2 - l0) < 0 else j + 1
        out.insert(k, (sign * e, v))
    return out


def _zone_start(law, eps_open):
    """The zone part's first point (log eps, log(c - eps)) at c = pi - START_DC: the root in eps < eps_open of
    the zone-end residual at that c (positive at the opening, where h(pi) = h0 and the gap beside the top, with
    the traction taken off past c, exceeds it), bracketed towards smaller contacts; None without a sign change."""
    c = math.pi - START_DC
    f = lambda e: _fo.residual(law, np.array([math.log(e), math.log(c - e)]))
    hi, f_hi = eps_open, f(eps_open)
    for rel in 1e-4 * 2.0 ** np.arange(14):
        lo = eps_open * (1 - rel)
        f_lo = f(lo)
        if not (math.isfinite(f_lo) and math.isfinite(f_hi)):
            return None
        if f_lo * f_hi < 0:
            e = _roots.root(f, lo, hi, xtol=1e-14 * eps_open)
            return np.array([math.log(e), math.log(c - e)])
        hi, f_hi = lo, f_lo
    return None
