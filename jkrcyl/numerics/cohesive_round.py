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
TOP_SCALE = 0.5           # ... its plane's eps scale: log(eps/eps_open) over max(TOP_PAST, TOP_SCALE |that|)
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


def _gap_at_rest(law, eps, x, shift=None):
    """k1 g0 - k0 g1 at the contact eps and the zone end c = pi - x: the zone-end residual h(c) - h0 with k = 0
    (cohesive_follow.residual, the approach eliminated by k) times dk/d(delta).  Smooth where that one has a pole:
    dk/d(delta) vanishes on a line of fixed eps (the approach leaves k unchanged at that contact), crossed by the
    branch where k0 vanishes too (the state's approach there fixed by g alone)."""
    fc = law.fixed(eps) if shift is None else law.fixed_as(eps, shift)      # (of the system: a stencil's centre's)
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
    s = (log(eps/eps_open)/sigma, log x), x = pi - c, sigma = max(TOP_PAST, TOP_SCALE |log(eps/eps_open)|) at the
    last point (a narrow S's turn 3e-4 wide in eps resolved; a wide S's fold far from the opening not a turn
    1e-4 wide in log x), by arclength: the tangent normal to the residual's gradient (:func:`_tangent`);
    corrected on the line of fixed x where the branch runs along x (a new contact per iterate; steps up to
    log(TOP_FACTOR)), else of fixed eps (one contact; steps up to TOP_GROW TOP_PAST/sigma times that, at most
    log(TOP_FACTOR) in log x), on the other line where that one finds no point, each point on its side of a
    fold (:func:`_corrected`); a step halved where the corrected point lies farther than half a step from the
    predictor (another family's root) or turns by more than acos(TOP_TURN), grown by 1.5 after each point -- so
    that neither eps(x) nor x(eps) need be single-valued: an S (eps falls from the opening to a fold, then rises;
    the continuation in (log eps, log(c - eps)) turned back at a fold 0.16 rad below the top, and cut across one
    0.34 rad below it), a zone end leaving the top forward in eps, one running back to the least contact, one
    turning back in c.
    The residual is :func:`_gap_at_rest` (no pole).  Ends where the branch rises in eps past TOP_PAST beyond the
    opening, or past a fold and along eps, or reaches x = TOP_MAX (the continuation goes on from there), or
    leaves its domain inside(y) (y = (log eps, log(c - eps)); the last point within a step of TOP_EDGE of the
    edge); each fold in eps met on the way is refined (Brent's extremum in log x to 1e-12) and kept as a point.
    Returns (points (n, 2) in (log eps, log(c - eps)), why ('' when traced), ended: the branch left its domain)."""
    pts = []
    for lx in (math.log(TOP_FIRST), math.log(TOP_FIRST * TOP_FACTOR)):
        e = _eps_at(law, lx, pts[-1][0] if pts else eps_open, 1e-12 * eps_open)
        if e is None:
            return None, _no_zone_end(eps_open, math.exp(lx)), False
        pts.append((e, lx))
    h, ended, folded = TOP_STEP, False, False
    while len(pts) < TOP_STEPS:
        e, lx = pts[-1]
        sigma = max(TOP_PAST, TOP_SCALE * abs(math.log(e / eps_open)))
        to_s = lambda e_, lx_: np.array([math.log(e_ / eps_open) / sigma, lx_])
        t = _tangent(law, sigma, pts[-1], to_s(*pts[-1]) - to_s(*pts[-2]))
        along_x = abs(t[1]) >= abs(t[0])
        rising = e > pts[-2][0]
        folded = folded or (rising and len(pts) > 2 and pts[-2][0] < pts[-3][0])
        if (rising and (e > eps_open * (1 + TOP_PAST) or (folded and not along_x))) or lx > math.log(TOP_MAX):
            break                        # past the opening, or past the fold and along eps: the continuation
        h = min(h, TOP_STEP if along_x else min(TOP_STEP * TOP_GROW * TOP_PAST / sigma, TOP_STEP / abs(t[1])))
        pred = to_s(*pts[-1]) + h * t
        y = _corrected(law, eps_open, sigma, pred, h, t, along_x, to_s(*pts[-1]), _sides(law, *pts[-1]))
        if y is None:
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


def _corrected(law, eps_open, sigma, pred, h, t, along_x, last, sides):
    """near_top's point for the step h along t from last (both in its plane s), pred = last + h t: on the line of
    fixed x where the branch runs along x, else of fixed eps -- and on the other line where that one finds no
    point (a fold in eps met along eps: the scaled plane keeps the tangent along eps up to a fold whose turn
    is wide in x -- a rigid pair, h0 1.324 Delta, lambda 0.992: pi - c 0.34 at the fold -- so the line of fixed
    eps past the fold crosses no branch); the point within half a step of pred, turning less than
    acos(TOP_TURN) from t and on the same side of a fold as last (sides: :func:`_sides` at last; a line of fixed
    eps near a fold in eps crosses both arms -- a step along eps landed past that fold, the rigid pair above --
    and one of fixed x both arms of a fold in x), as (eps, log x), or None."""
    pe = eps_open * math.exp(sigma * pred[0])
    to_s = lambda e, lx: np.array([math.log(e / eps_open) / sigma, lx])
    for fixed_x in ((True, False) if along_x else (False, True)):
        if fixed_x:                      # eps at the predicted x
            y = _eps_at(law, pred[1], pe, max(0.25 * h * abs(t[0]) * sigma * pe, 1e-13 * eps_open))
            y = None if y is None else (y, pred[1])
        else:                            # x at the predicted contact (one LU)
            f = lambda v: _gap_at_rest(law, pe, math.exp(v))
            y = _root_near(f, pred[1], 0.25 * h * abs(t[1]) + 1e-9, -700.0, math.log(math.pi - pe))
            y = None if y is None else (pe, y)
        if y is None or _sides(law, *y)[0 if fixed_x else 1] != sides[0 if fixed_x else 1]:
            continue
        step = to_s(*y) - last
        if np.hypot(*(to_s(*y) - pred)) <= 0.5 * h and step @ t >= TOP_TURN * np.hypot(*step):
            return y
    return None


SIDE_STEP = 1e-7          # _gradient: the relative step of the differences


def _gradient(law, e, lx):
    """(d/d(log eps), d/d(log x)) of :func:`_gap_at_rest` at (e, x = exp(lx)) by central differences (kept per law:
    the tangent there and the next step's side checks read it)."""
    memo = law.__dict__.setdefault("_top_gradients", {})
    if (e, lx) not in memo:
        shift = law.fixed(e).shift
        f = lambda de, dl: _gap_at_rest(law, e * math.exp(de), math.exp(lx + dl), shift)
        memo[(e, lx)] = np.array([f(SIDE_STEP, 0.0) - f(-SIDE_STEP, 0.0),
                                  f(0.0, SIDE_STEP) - f(0.0, -SIDE_STEP)]) / (2 * SIDE_STEP)
    return memo[(e, lx)]


def _sides(law, e, lx):
    """The signs of :func:`_gradient`: the first flips across a fold in x, the second across a fold in eps."""
    return tuple(np.sign(_gradient(law, e, lx)))


def _tangent(law, sigma, point, chord):
    """The unit tangent of the branch at point = (eps, log x) in near_top's plane (eps scale sigma), normal to the
    residual's gradient, oriented along chord (the step that reached it); the chord's direction where the
    gradient is not finite or vanishes.  (The chord alone turned the wrong way at a fold in eps crossed by a step
    at fixed x: eps falls along it, rises past the fold.)"""
    g = _gradient(law, *point)
    t = np.array([-g[1], g[0] * sigma])          # normal to (dF/ds_0, dF/ds_1) = (sigma g_0, g_1)
    norm = np.hypot(*t)
    if not (np.all(np.isfinite(t)) and norm > 0):
        return chord / np.hypot(*chord)
    t /= norm
    return -t if t @ chord < 0 else t


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
