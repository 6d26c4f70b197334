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
tangent oriented towards a shorter zone.  The round prefix's points have c = pi (Traced reads n_round).
"""
import math

import numpy as np

from . import cohesive_follow as _fo
from . import roots as _roots

ROUND_POINTS = 40          # round-zone points per unit of log eps (cohesive_branch.ALL_POINTS over its range)
START_DC = 1e-4            # the zone part starts at c = pi - START_DC [rad] (its eps is then within ~1e-9 of the
                           # opening: pi - c grows as the square root of the distance in eps)


def opening(law, eps_jump, top_gap):
    """eps_open > eps_jump where the round-zone family's top gap reaches the range (top_gap(eps) = h(pi)/Delta of
    its state at the contact eps equals h0), to 1e-13 relative; None when it stays within it up to eps_hi."""
    excess = lambda e: top_gap(e) - law.h0
    lo = eps_jump
    if excess(lo) >= 0:
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
    y = _zone_start(law, eps_open)
    if y is None:
        return rounded, "zone", (f"the cohesive branch could not be followed beyond the round zone's opening at "
                                 f"eps = {eps_open:.6g} rad: no zone end near the top"), n
    got = _fo.follow(law, y, inside, prev=np.array([-1.0, 0.0]))
    return np.vstack([rounded, got.points]), "zone", got.reason, n


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
