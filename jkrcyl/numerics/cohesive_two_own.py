"""The Maugis-Dugdale law's own two-patch branch (notation and the fixed-arc state: jkrcyl.numerics.cohesive_two),
seeded where the law's two-patch family starts and continued by its own arclength, without JKR's branch as a
scaffold (jkrcyl.numerics.cohesive_two_branch.trace follows JKR's, O(lambda^-2) away: it needs zones small against
the arcs, lambda >~ 8 at M = 0.2, and a JKR branch whose arcs exceed the zones -- at M = 0.5, lambda = 20 JKR's top
arc stays below 0.0034 against 0.0063 zones).

Seed (:func:`seed`): the law's two-patch family starts where the top bridge closes (h(pi) = 0: the top contact forms
under its zone, jkrcyl.numerics.cohesive_top_zone) -- the two-arc state with the top arc at SEED_ARC, equal to the
closing state to O(SEED_ARC^2) (tests/test_cohesive_top_zone.py; tests/test_cohesive_two_own.py: against the
bridge's closing state).  It is solved (cohesive_two_branch.solve_at, the top arc held) from the bottom arc of
JKR's branch end at that axis (JKR's single patch where h(pi) = 0; the law's closing lies O(h0 log lambda) away:
eps 2.022 against JKR's 1.909 at M = 0.2, lambda = 20) with the Dugdale zone at the bottom and the strip's closing
zone h0/(4 s0 log 2) at the top; where Newton does not reach it from there (thick zones), by continuation in
lambda from a larger one (the zone lengths scaled with the Dugdale zone's).  The mirror end the same upside down.

Continuation (:func:`trace`): in q = (log eps, log eps_top), a secant predictor of arclength h along the last two
states (the first step: the seed's small arc grows), the corrector cohesive_two_branch.solve_at with the
half-angle whose tangent component is larger held (a fold of the other is passed: the held one switches there), the
zone lengths extrapolated in log.  h grows by STEP_GROW after a success up to STEP_MAX (and to ARC_STEP_MAX rad in
either arc), halves after a failure down to STEP_MIN.  The branch ends where its smaller arc falls below END_ARC
('single': the top arc, 'mirror': the bottom arc -- the bridge's closing again, upside down or not), where the zones
meet ('zones meet': the gap between the arcs within h0 everywhere -- cohesive_two's zone all round, the end of the
two patches at full contact) or where no step is found ('unresolved').
"""
import math

import numpy as np

from . import cohesive as _co
from . import cohesive_two as _two
from . import cohesive_two_branch as _cb
from . import cohesive_two_stability as _stab
from . import roots as _roots

SEED_ARC = 0.99 * 1e-4    # the seed's small arc [rad] (the scaffold's axis ends: cohesive_two_branch.END_ARC)
STEP_FIRST = 0.5          # the first step in log of the small arc
STEP_MAX = 0.6            # the largest step in q = (log eps, log eps_top)
ARC_STEP_MAX = 0.25       # ... and in either half-angle [rad]
STEP_MIN = 1e-3
STEP_GROW = 1.5
MAX_STATES = 200
MEET = 1e-3               # zones within this [rad] of meeting (the gap within h0 everywhere): 'zones meet'
LAMBDA_RATIO = 1.25       # the seed's continuation in lambda: its first ratio (halved in log on a failure)
LAMBDA_START = 2.0 ** np.arange(1, 6)    # ... from these multiples of lambda


class NoSeed(Exception):
    """No two-patch state of the law at the axis found (neither directly nor by continuation in lambda)."""


class Folded(NoSeed):
    """The law's two-patch state at the axis, continued from a larger lambda, folds in lambda before the law's:
    the law has no two-patch state there (physical: e.g. M = 0.5, lambda = 20, tests/test_cohesive_two_own.py)."""


def _law_at(law, s0):
    """law's BranchLaw at another zone strength s0 (the same m, kernel, layers)."""
    return _cb.BranchLaw(law.m, s0, law.kernel, law.layered)


def _seed_zones(law, small):
    """The zone lengths (bottom, top) to start from at the axis of arc ``small`` (1: top, 0: bottom): the
    Dugdale zone at the large arc, the strip's closing zone h0/(4 s0 log 2) at the small one."""
    d = np.full(2, _co.dugdale_zone(law.m, law.s0))
    d[small] = law.h0 / (4 * law.s0 * math.log(2))
    return d


def seed(law, small, guess, n, d0=None, arc=SEED_ARC):
    """The two-arc state with the arc ``small`` (1: top, 0: bottom) at arc, the other from guess (e.g. JKR's
    branch end at that axis) -- directly, or by continuation in lambda (module docstring).  Raises NoSeed."""
    d0 = _seed_zones(law, small) if d0 is None else np.asarray(d0, dtype=float)
    try:
        return _cb.solve_at(law, small, arc, guess, d0, n)[0]
    except _cb.NotFound:
        pass
    lam = 4 * law.s0 / law.m ** (2 / 3)
    for k in LAMBDA_START:                              # a larger lambda (thinner zones) Newton reaches
        big = _law_at(law, law.s0 * k)
        if 4 * big.s0 / big.m ** (2 / 3) > _cb._layer.LAMBDA_MAX:
            break
        try:
            st = _cb.solve_at(big, small, arc, guess, _seed_zones(big, small), n)[0]
        except _cb.NotFound:
            continue
        return _down_in_lambda(law, st, small, big.s0, n, arc)
    raise NoSeed(f"no two-patch state of the law with its {('bottom', 'top')[small]} arc at {arc:g} near "
                 f"{guess:g} (lambda = {lam:.3g})")


def _down_in_lambda(law, st, small, s0, n, arc):
    """From the state st of the law at zone strength s0 to law's, s0 stepped down geometrically (the ratio
    halved in log on a failure); raises NoSeed where the ratio falls below 1 + 1e-3 (a fold in lambda: the
    state does not continue to law's lambda)."""
    ratio = LAMBDA_RATIO
    while s0 > law.s0:
        s = max(law.s0, s0 / ratio)
        here = _law_at(law, s) if s > law.s0 else law
        scale = _co.dugdale_zone(law.m, s) / _co.dugdale_zone(law.m, s0)
        d0 = scale * np.array([st.c - st.eps, st.c_top - st.eps_top])
        try:
            st = _cb.solve_at(here, small, arc, (st.eps, st.eps_top)[1 - small], d0, n)[0]
            s0, ratio = s, min(ratio ** 1.5, LAMBDA_RATIO)
        except _cb.NotFound:
            ratio = math.sqrt(ratio)
            if ratio < 1 + 1e-3:
                raise Folded(f"the two-patch state at the axis does not continue below lambda = "
                             f"{4 * s0 / law.m ** (2 / 3):.4g} (a fold in lambda)") from None
    return st


def _y(st):
    """The state's point y = (log eps, log eps_top, log d_bot, log d_top) (d: the zone lengths)."""
    return np.log([st.eps, st.eps_top, st.c - st.eps, st.c_top - st.eps_top])


def residual(law, y, n):
    """[k_top, h(c) - h0, h(pi - c_top) - h0] at y (k_bot = 0 fixes delta); None where the zones meet."""
    eps, eps_top, d_bot, d_top = np.exp(y)
    if not eps + eps_top + d_bot + d_top < math.pi:
        return None
    zones = _co.zones_of(eps + d_bot, eps_top + d_top)
    fa, dn, u, k = law.pieces(eps, eps_top, zones, n)
    h = fa.gap(np.array([eps + d_bot, math.pi - eps_top - d_top]), dn, u, zones, law.s0)
    return np.array([k[1], h[0] - law.h0, h[1] - law.h0])


def correct(law, y_pred, t, n, arcs=None, tol=1e-11):
    """The state on the branch where t . (y - y_pred) = 0 (Keller's pseudo-arclength corrector): Newton in y on
    [residual, t . (y - y_pred)] from y_pred.  The Jacobian's zone columns by differences at the same arcs
    (back-substitutions), its arc columns (a fixed-arc system each, refined from a neighbour's LU:
    cohesive_two_branch.BranchLaw) by forward differences at the first step -- or from arcs, a neighbour's -- and
    then secant (Broyden) updates along the iterates: one new system per step.  Returns (state, the arc columns)
    (state: cohesive_two.TwoPatchCohesive), or None."""
    scale = np.array([max(1.0, law.m), max(1.0, law.h0), max(1.0, law.h0), 1.0])
    cols = [None if arcs is None else np.array(arcs)]

    def f(y):
        r = residual(law, y, n)
        return None if r is None else np.append(r, t @ (y - y_pred))

    def jacobian(y, r):
        J = np.empty((4, 4))
        for j in (range(4) if cols[0] is None else (2, 3)):
            h = 1e-7 if j < 2 else 1e-6
            rj = f(y + h * np.eye(4)[j])
            if rj is None:
                return None
            J[:, j] = (rj - r) / h
        if cols[0] is None:
            cols[0] = J[:3, :2].copy()
        J[:3, :2], J[3] = cols[0], t
        return J if np.all(np.isfinite(J)) and np.linalg.cond(J) < 1e14 else None

    def secant(y, dy, r, rt, J):
        a = dy[:2]
        if a @ a > 0:
            cols[0] = cols[0] + np.outer(rt[:3] - r[:3] - J[:3] @ dy, a) / (a @ a)

    got = _roots.damped_newton(f, np.array(y_pred, dtype=float), jacobian, scale, tol, np.array([0.2, 0.2, 2.0, 2.0]),
                               _cb.SECANT_STEPS, 6, _cb.RESIDUAL_FLOOR * scale, secant)
    if got is None or (arcs is not None and not np.all(np.abs(got[1]) < tol * scale)):
        return None       # stopped at the floor with a neighbour's columns: the caller retries with fresh ones
    # (M 0.2, lambda 5: one state of 47 left at G/w - 1 = 9e-9 by stale secant columns, on one machine's rounding)
    eps, eps_top, d_bot, d_top = np.exp(got[0])
    return _two.state(law, eps, eps_top, eps + d_bot, eps_top + d_top, n), cols[0]


def trace(law, start, n, direction=None):
    """The branch from the state start (module docstring): (states from start on, end label).  direction: the
    tangent in y to leave along (default: the smaller arc grows, from a seed at an axis)."""
    small = int(start.eps_top < start.eps)
    t = np.eye(4)[small] if direction is None else np.asarray(direction, dtype=float)
    states, h, arcs = [start], STEP_FIRST, None
    while len(states) < MAX_STATES:
        last = states[-1]
        y0 = _y(last)
        if len(states) >= 2:
            t = y0 - _y(states[-2])
            t /= np.linalg.norm(t)
        step = min(h, ARC_STEP_MAX / max(np.max(np.abs(t[:2]) * np.exp(y0[:2])), 1e-300))
        y = y0 + step * t
        i = int(np.argmin(y[:2]))
        if y[i] < math.log(SEED_ARC) and len(states) > 1 and t[i] < 0:   # the small arc crosses the axis: on it
            step = (math.log(SEED_ARC) - y0[i]) / t[i]
            y, t_c = y0 + step * t, np.eye(4)[i]                          # ... held there
        else:
            t_c = t
        got = correct(law, y, t_c, n, arcs) if arcs is not None else None
        if got is None:                                                  # (the neighbour's columns too far)
            got = correct(law, y, t_c, n)
        st, arcs = got if got is not None else (None, None)
        if st is None or np.linalg.norm(_y(st) - y) > 2 * step + 1e-12:  # (a jump to another branch)
            if _meeting(last):
                return states, "zones meet"
            h = 0.5 * min(h, step)
            if h < STEP_MIN:
                return states, "unresolved"
            continue
        states.append(st)
        if min(st.eps, st.eps_top) <= SEED_ARC * (1 + 1e-9) and len(states) > 2:
            return states, ("mirror", "single")[int(st.eps_top < st.eps)]
        h = min(STEP_MAX, STEP_GROW * h)
    return states, "unresolved"


def _meeting(st):
    """Whether the zones of st are within MEET of meeting (the gap between the arcs within h0 nearly all round)."""
    return math.pi - st.c - st.c_top < MEET


def branches(law, points, ends, n):
    """The law's own branches from the axis ends of JKR's branch (points (k, 2) of (eps, eps_top), ends its labels):
    one :class:`cohesive_two_branch.Traced` per seed not already reached by a branch traced from another (a
    branch from the single end to the mirror is one; two loops back to their own axis are two).  [] where every
    seed folds in lambda (:class:`Folded`: physically none); NoSeed where JKR's branch has no end at an axis or a
    seed is not found."""
    points = np.asarray(points, dtype=float)
    seeds = [(1 if end == "single" else 0, points[k][0 if end == "single" else 1])
             for k, end in ((0, ends[0]), (-1, ends[1])) if end in ("single", "mirror")]
    if not seeds:
        raise NoSeed(f"JKR's branch has no end at an axis (ends {tuple(ends)!r}): no seed for the law's own")
    out = []
    for small, guess in seeds:
        try:
            sd = seed(law, small, guess, n)
        except Folded:
            continue
        if any(_same(sd, t.states[-1]) for t in out):          # reached from the other end already
            continue
        states, end = trace(law, sd, n)
        out.append(_cb.Traced(tuple(states), tuple(_stab.jacobian(law, s) for s in states),
                              (("mirror", "single")[small], end)))
    return out


def _same(a, b):
    """Whether two states at an axis are one (arcs within 1e-6 rad)."""
    return abs(a.eps - b.eps) < 1e-6 and abs(a.eps_top - b.eps_top) < 1e-6
