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
zone part by the continuation of jkrcyl.numerics.cohesive_follow from c = pi - START_DC at the opening, the
tangent oriented towards a shorter zone.  Where the S is narrow (its fold within ~1e-3 of the opening in eps, the
zone end there within ~1e-2 of pi: cohesive_branch.top_opens 'narrow S-shaped branch', and an S whose fold lies
just past the scan's jump) that first step would cut across both turns, so wherever eps is single-valued in
x = pi - c next to the top (falling from the opening along c2 to the fold, rising along c1 past the opening) the
zone part there is traced by x instead (:func:`near_top`: points geometric in x from TOP_FIRST, the fold refined
and kept as a point) and the continuation starts from its last point.  The round prefix's points have c = pi
(Traced reads n_round).
"""
import math

import numpy as np

from . import cohesive_follow as _fo
from . import roots as _roots

ROUND_POINTS = 40          # round-zone points per unit of log eps (cohesive_branch.ALL_POINTS over its range)
TOP_FIRST = 1e-6          # a narrow S: its first zone point has pi - c = TOP_FIRST [rad] (eps within ~1e-13 of
                          # the opening: eps_open - eps grows as (pi - c)^2)
TOP_FACTOR = 10 ** 0.125  # ratio of successive pi - c next to the top
TOP_PAST = 1e-3           # ... up to this far past the opening in eps (relative), back on the first root
TOP_MAX = 1.0             # ... within pi - c < TOP_MAX
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
    # the zone part next to the top by pi - c where eps(pi - c) is single-valued through the fold (a narrow S, and
    # any S whose fold lies within TOP_PAST of the opening: the continuation's first step would cut across it);
    # else (a wide S, c turning along the root near the top) the continuation from c = pi - START_DC
    near, why = near_top(law, eps_open)
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


def _eps_at(law, c, guess, width):
    """The contact eps nearest to guess whose zone-end residual vanishes at the zone end c (a bracket grown from
    guess +- width by doubling, then Brent to 1e-15 relative), or None."""
    f = lambda e: _fo.residual(law, np.array([math.log(e), math.log(c - e)]))
    f0 = f(guess)
    if f0 == 0.0:
        return guess
    for w in width * 2.0 ** np.arange(24):
        for e in (guess - w, guess + w):
            fe = f(e) if 0 < e < c else math.nan
            if math.isfinite(fe) and fe * f0 <= 0:
                return _roots.root(f, *sorted((guess, e)), xtol=1e-15 * guess)
    return None


def near_top(law, eps_open):
    """The narrow S's zone part next to the top: the contact eps(x) at the zone ends c = pi - x, x geometric from
    TOP_FIRST (single-valued there: eps falls from the opening along the root near the top to the fold in eps,
    where it meets the first root, and rises along that), up to TOP_PAST past the opening in eps; the fold refined
    (the least eps, Brent's minimum in log x to 1e-12) and kept as a point.  Returns (points (n, 2) in (log eps,
    log(c - eps)), '') or (None, why)."""
    xs, es = [], []
    x, guess = TOP_FIRST, eps_open
    while x < TOP_MAX:
        steps = np.abs(np.diff(es[-3:]))
        width = max(steps.max(initial=0.0), 1e-12 * eps_open)
        if len(es) >= 2:                 # x geometric: linear (quadratic) in the index from the last two (three)
            guess = 2 * es[-1] - es[-2] + (es[-1] - 2 * es[-2] + es[-3] if len(es) >= 3 else 0.0)
        e = _eps_at(law, math.pi - x, guess, width)
        if e is not None and len(es) >= 3 and abs(e - guess) > 8 * width:     # another family's root: not this one
            e = None
        if e is None:
            return None, (f"the cohesive branch could not be followed beyond the round zone's opening at eps = "
                          f"{eps_open:.6g} rad: no contact with its zone end at pi - {x:.3g} rad near eps = "
                          f"{guess:.6g} rad")
        xs.append(x)
        es.append(e)
        if e > eps_open * (1 + TOP_PAST) and es[-2] < e:
            break
        x *= TOP_FACTOR
    else:
        return None, f"the narrow S-shaped branch does not return past its opening eps = {eps_open:.6g} rad"
    j = int(np.argmin(es))
    if not (0 < j and np.all(np.diff(es[:j + 1]) < 0) and np.all(np.diff(es[j:]) > 0)):  # one fold, else not an S
        return None, (f"the narrow S-shaped branch next to its opening eps = {eps_open:.6g} rad does not turn "
                      "back in eps once")
    if 0 < j < len(es) - 1:              # the fold in eps between the root near the top and the first root
        lx = [math.log(xs[j - 1]), math.log(xs[j]), math.log(xs[j + 1])]
        at = lambda v: _eps_at(law, math.pi - math.exp(v), es[j], abs(es[j + 1] - es[j - 1]) + 1e-12)
        v, e = _roots.minimum(lambda v: (lambda r: math.inf if r is None else r)(at(v)), *lx, 1e-12)
        k = j if v < lx[1] else j + 1
        xs.insert(k, math.exp(v))
        es.insert(k, e)
    xs, es = np.array(xs), np.array(es)
    return np.column_stack([np.log(es), np.log(math.pi - xs - es)]), ""


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
