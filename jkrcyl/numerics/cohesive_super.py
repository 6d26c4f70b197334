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
a top gap within the range; the trace stops ROUND_MARGIN below c = pi, and the states beyond, with a zone all
round, are not on it).  Where the zone reaches round already at the
start, the branch has zones 'all' (no zone end: k = 0 alone) and is sampled in eps.

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

from . import cohesive_branch as _cb
from . import cohesive_follow as _fo
from . import one_arc as _one
from . import roots as _roots

EPS_TOP = math.pi - 0.05      # the branch is traced up to this contact half-angle (as the sub-critical one)
START_SCAN = 24               # contacts scanned past the pole for the first one below the load cap
ROUND_MARGIN = 1e-3           # the zone end stops this far below pi [rad]: it reaches round as a square root
                              # (h(c) - h0 has a double root at c = pi, h being even about the top), where the
                              # trace would need steps ~ pi - c


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
    branch leaves its domain (eps = pi - 0.05, the load cap, the zone reaching round), else why it stopped; None
    when the law has no super-critical branch (:func:`eps_range`) or no contact on it below the load cap."""
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
    return got.points, "zone", got.reason
