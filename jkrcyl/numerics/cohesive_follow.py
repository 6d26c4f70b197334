"""Continuation of the Maugis-Dugdale contact branch: the curve k = 0, h(c) = h0 in the plane
x = (log eps, log(c - eps)) (notation of jkrcyl.numerics.cohesive and jkrcyl.numerics.cohesive_branch).

Every point of the plane with a new eps costs a new collocation matrix and its LU (jkrcyl.numerics.cohesive
.FixedContact); along a line of fixed eps the zone-end residual is cheap (the LU reused).  So :func:`follow`
corrects on lines of fixed eps wherever the branch crosses them cleanly, and only near a fold in eps on lines of
fixed zone length or on the predictor's normal (one LU per iterate there), with the step control of
pseudo-arclength continuation (jkrcyl.numerics.continuation: tangent predictor, turn check) -- 3-4 times fewer
LUs than Newton on both coordinates.  Used for the branch table of the model core (cohesive_branch.trace) and
the stand-alone pull-off (cohesive_pull_off).
"""
import math
from collections import namedtuple

import numpy as np

from . import cohesive_kernels as _ck
from . import cohesive_roots as _cr

LOG_PI = math.log(math.pi)
MEMO_MAX = 20000        # residuals kept per law (each one float)
Followed = namedtuple("Followed", ["points", "reason"])
Followed.__doc__ = """The traced points (n, 2) in (log eps, log(c - eps)) and why the trace ended early ('' when it
left the domain, as it should: the caller's inside(x) said so)."""


def residual(law, x):
    """h(c) - h0 at x = (log eps, log(c - eps)) with k = 0 (delta eliminated); NaN off the plane's physical part
    (eps or eps + d not in (0, pi), a non-finite x): the correctors treat it as no point.  Kept per law by x (a
    step's fold-side check and its tangent read the same points: ~1/6 of a trace's residuals)."""
    key, memo = (float(x[0]), float(x[1])), law.residuals
    if key not in memo:
        if len(memo) > MEMO_MAX:
            memo.clear()
        memo[key] = _residual(law, x)
    return memo[key]


def _residual(law, x):
    if not (x[0] < LOG_PI and x[1] < LOG_PI):       # NaN fails too
        return math.nan
    eps, d = math.exp(x[0]), math.exp(x[1])
    if not (0.0 < eps and eps + d < math.pi):
        return math.nan
    return _ck._residual(d, (law.fixed(eps).fx, eps, law.s0, law.h0, 0.0))


TURN = 0.9              # follow: the largest turn of the branch per step, as the cosine between tangents
H_MIN = 1e-5            # follow: the smallest step in (log eps, log(c - eps)) towards the domain's edge
TURN_MIN = 1e-6         # follow: the smallest step looking for the next point where the branch turns sharply
#                         (vartheta 2.83, gb 0.694, lambda 3.87, M 0.488: 1e-5 stopped the sub-critical trace at
#                         eps 0.0141, zone 0.728 rad, where M 0.47 and 0.5 passed; 1e-6 passes it)
SECANT_STEPS = 12       # follow: secant iterations on a line of fixed zone length
FIXED_EPS_SLOPE = 0.01  # follow: correct at fixed eps where the unit tangent has |d log eps| >= this
FD_STEP = 1e-6          # follow: finite-difference step of the tangent in (log eps, log(c - eps))


def follow(law, x0, inside, h0=0.1, h_max=0.25, max_steps=1500, done=None, prev=(1.0, 0.0), margin=None,
           cheap=None):
    """The branch k = 0, h(c) = h0 through x0 = (log eps, log(c - eps)) (on it), leaving it along prev (a
    direction in x: by default towards growing eps), up to
    where it leaves the domain inside(x): a Followed (the points (n, 2) and '' -- or the reason it stopped
    before: no tangent (the residual flat or not finite), the step below TURN_MIN without a point on the branch,
    or max_steps).

    Natural-parameter continuation with a switching parameter: predict along the tangent and correct on the
    line of fixed eps (the zone end at a fixed contact, one LU) unless the branch runs almost along the zone
    length or that point is not on the same side of a fold in eps (the residual's slope in c changes sign
    across a fold); else on the line of fixed zone length (secant in log eps, one LU per iterate); else on the
    predictor's normal (secant, one LU per iterate: where neither line crosses the branch cleanly).  A step is
    taken when the corrected point lies within half a step of the predictor's line and the tangent turns less
    than acos(TURN) (else it is halved; it grows by 1.5 up to h_max), as in jkrcyl.numerics.continuation.  A
    step that leaves the domain is cut by 4 (and not grown after the next step taken) down to 64 H_MIN: the
    last point lies that close to the edge -- unless done(y) says the trace may end at that exit (a step on the
    same branch: its tangent turns less than acos(TURN)).  With margin(y) (per bound of the domain, < 0 inside
    it, smooth along the branch: for a load cap 1 - p_cap/p) the exit is searched within the step that left the
    domain instead (:func:`_exit`; 2-4 corrections where cutting by 4 and regrowing took ~20 near the cap) and
    the table's last cells are filled in as that rule left them (:func:`_backed_off`).  Where cheap(x) (say,
    no state of interest lies ahead: the trace towards a load cap), a step that finds no point on its line of
    fixed eps is halved (down to CHEAP_MIN) before the costlier correctors are tried (one LU each iterate).
    (Pseudo-arclength with Newton, jkrcyl.numerics.continuation, needs a new LU at every iterate and every
    finite difference in eps: 3-4 times the LUs.)"""
    pts = [np.asarray(x0, dtype=float)]
    t, side = _tangent(law, pts[0], np.asarray(prev, dtype=float))
    if t is None:
        return Followed(np.array(pts), _stopped("no tangent at the start", pts[0]))
    h, edge = h0, False
    for _ in range(max_steps):
        x = pts[-1]
        prefer = cheap is not None and h > CHEAP_MIN and abs(t[0]) >= CHEAP_SLOPE and cheap(x)
        y = _correct(law, x, t, side, h, only_eps=prefer)
        ok = y is not None
        if prefer and not ok:              # a shorter step on a line of fixed eps (one LU) before the others
            h = h / 2
            continue
        if ok and not inside(y):
            if h <= 64 * H_MIN or (done is not None and done(y) and _turn_ok(law, y, t)):
                return Followed(np.array(pts), "")
            exits = margin is not None and _turn_ok(law, y, t)         # the step stays on this branch
            last = _exit(law, x, t, side, h, y, inside, margin) if exits else None
            if last is not None:                 # the last point inside, within 64 H_MIN of the exit
                return Followed(np.array(pts + _backed_off(law, x, t, side, *last)), "")
            h, edge = h / 4, True
            continue
        t_new, side_new = _tangent(law, y, t) if ok else (None, None)
        if t_new is None or not t_new @ t >= TURN:
            h /= 2
            if h < TURN_MIN:
                return Followed(np.array(pts), _stopped("the step fell below TURN_MIN without a point on the branch",
                                                        x))
            continue
        pts.append(y)
        t, side, h, edge = t_new, side_new, (h if edge else min(1.5 * h, h_max)), False
    return Followed(np.array(pts), _stopped(f"{max_steps} steps taken", pts[-1]))


CHEAP_MIN = 1 / 64      # follow: where cheap(x), steps above this are halved rather than corrected off fixed eps
CHEAP_SLOPE = 0.3       # follow: ... and where the branch runs this much along eps (a unit tangent)


def _correct(law, x, t, side, h, between=None, only_eps=False):
    """The branch's point for the step h from x along t (module docstring: on the line of fixed eps, else of fixed
    zone length -- its secant started, where two branch points ``between`` bracket the predicted log(c - eps),
    at log eps interpolated between them --, else on the predictor's normal), within half a step of the
    predictor's line, or None."""
    pred = x + h * t
    near = lambda y: y is not None and abs(t[0] * (y[1] - pred[1]) - t[1] * (y[0] - pred[0])) <= 0.5 * h
    y = fixed_eps(law, pred, h) if abs(t[0]) >= FIXED_EPS_SLOPE else None
    if only_eps:
        return y if near(y) and _side(law, y) == side else None
    if not (near(y) and _side(law, y) == side):
        start = None
        if between is not None and (between[0][1] - pred[1]) * (between[1][1] - pred[1]) < 0:
            (e0, d0), (e1, d1) = between
            start = e0 + (e1 - e0) * (pred[1] - d0) / (d1 - d0)
        y = fixed_zone(law, pred, h, start)
    if not near(y):
        y = normal_line(law, pred, t, h)
    return y if near(y) else None


EXIT_TRIALS = 12        # _exit: corrections at most
EXIT_AIM = 16           # _exit: aim this many H_MIN to either side of the estimated exit


def _exit(law, x, t, side, h, y_out, inside, margin):
    """The last branch point inside the domain on the step h from x along t whose end y_out lies outside: the
    step s in (0, h) bracketed until the bracket is at most 64 H_MIN wide (the plain cut-by-4 rule's end).
    margin(y): one value per bound of the domain, each < 0 inside it; the exit is estimated as the first
    crossing of a bound, by inverse quadratic interpolation of that bound's margin through the bracket's ends
    and the end they replaced (regula falsi where that fails or an end was kept twice running: Illinois), each
    trial aimed EXIT_AIM H_MIN past the estimate towards the end that did not move last (or to within 60 H_MIN
    of the one that did: closing the bracket), so both ends close in.  Returns (x, 0, known) when the bracket
    closes on x, (the point, its step, known) -- its tangent turning less than acos(TURN) from t --, known the
    branch points found on the way as (step, point), or None: a margin not a number, margins
    disagreeing with inside, a correction failed or EXIT_TRIALS were not enough (the caller then cuts the
    step)."""
    lo, hi, q_lo, q_hi = 0.0, h, np.asarray(margin(x), float), np.asarray(margin(y_out), float)
    y_lo, y_hi, last, older = x, y_out, 0, None   # last: +1 the low end moved last, -1 the high end
    stale = 0                                     # +1: the low end kept twice running, -1: the high end
    known = [(0.0, x), (h, y_out)]                # the branch points found, by step
    for _ in range(EXIT_TRIALS):
        if np.isnan(q_lo).any() or np.isnan(q_hi).any() or not (np.all(q_lo < 0) and np.any(q_hi > 0)) or \
                np.any((q_hi > 0) & np.isneginf(q_lo)):         # a bound's margin not defined at the low end
            return None
        if hi - lo <= 64 * H_MIN:
            return (y_lo, lo, known) if y_lo is x or _turn_ok(law, y_lo, t) else None
        ql, qh = q_lo * (0.5 if stale > 0 else 1.0), q_hi * (0.5 if stale < 0 else 1.0)       # Illinois
        with np.errstate(invalid="ignore"):                              # -inf - -inf: a bound met at neither end
            f = np.where(qh > 0, ql / np.where(qh > 0, ql - qh, -1.0), 1.0)
        i = int(np.argmin(f))                       # the bound met first
        r = lo + (hi - lo) * float(f[i])
        if older is not None and not stale and math.isfinite(older[1][i]):
            r = _inverse_quadratic((older[0], older[1][i]), (lo, q_lo[i]), (hi, q_hi[i]), r)
        close = 60 * H_MIN                          # a trial this near the end that moved last closes the bracket
        s = min(r + EXIT_AIM * H_MIN, lo + close) if last > 0 and r < lo + close else \
            max(r - EXIT_AIM * H_MIN, hi - close) if last < 0 and r > hi - close else \
            r + (EXIT_AIM if last > 0 else -EXIT_AIM) * H_MIN
        keep = min(0.05 * (hi - lo), 8 * H_MIN)      # off the ends
        s = min(max(s, lo + keep), hi - keep)
        y = _correct(law, x, t, side, s, (y_lo, y_hi))
        if y is None:
            return None
        known.append((s, y))
        q, now = np.asarray(margin(y), float), (1 if inside(y) else -1)
        if (now > 0) != bool(np.all(q < 0)):
            return None
        if now > 0:
            older = (lo, q_lo)
            lo, q_lo, y_lo = s, q, y
        else:
            older = (hi, q_hi)
            hi, q_hi, y_hi = s, q, y
        stale, last = (-now if now == last else 0), now
    return None


BACK_OFF = (4, 16, 64)   # _backed_off: points this many times 64 H_MIN before the last one


def _backed_off(law, x, t, side, y_end, s_end, known):
    """The points of the step from x to its last point y_end (at the step s_end, next to the domain's edge)
    about BACK_OFF times 64 H_MIN before it, then y_end: the table's last cells shrink towards the edge as the
    plain cut-by-4 rule left them (a walk that starts from the table point nearest a state near the edge starts
    inside the table, not on its last point).  Each is the branch's point at the eps interpolated (by step)
    between the known branch points (step, point) either side of it (one LU: the zone end at a fixed contact),
    kept if its zone length lies between theirs.  [] when y_end is x."""
    if y_end is x:
        return []
    known = sorted(known, key=lambda k: k[0])
    out = []
    for k in sorted(BACK_OFF, reverse=True):
        s = s_end - k * 64 * H_MIN
        if s <= 0.5 * 64 * H_MIN:
            continue
        j = max(i for i, (sk, _) in enumerate(known) if sk <= s)
        (sa, ya), (sb, yb) = known[j], known[min(j + 1, len(known) - 1)]
        guess = ya + (yb - ya) * ((s - sa) / (sb - sa) if sb > sa else 0.0)
        lo, hi = sorted((ya[1], yb[1]))
        y = fixed_eps(law, guess, hi - lo + 1e-12)
        if y is not None and lo <= y[1] <= hi and (not out or y[0] != out[-1][0]):
            out.append(y)
    return out + [y_end]


def _stopped(why, x):
    return (f"the cohesive branch could not be followed beyond eps = {math.exp(x[0]):.6g} rad (zone length "
            f"{math.exp(x[1]):.3g} rad): {why}")


def _turn_ok(law, y, t):
    t_new = _tangent(law, y, t)[0]
    return t_new is not None and t_new @ t >= TURN


def _step_log_d(x):
    """The finite-difference step in log(c - eps): 0.1 FD_STEP, at least ~1e-9 c/(c - eps) (c = eps + d holds d
    only to ulp(c): a thin zone's d to ulp(c)/d relative)."""
    d = math.exp(x[1])
    return max(0.1 * FD_STEP, 1e-9 * (math.exp(x[0]) + d) / d)


def log_d_resolution(x):
    """How finely log(c - eps) is resolved at x: a few ulp(c)/(c - eps) (stop a secant there)."""
    d = math.exp(x[1])
    return 4e-16 * (math.exp(x[0]) + d) / d


def _side(law, x):
    """The sign of the residual's slope in c at fixed eps (no new LU): opposite on a fold's two sides."""
    e = _step_log_d(x)
    return math.copysign(1.0, residual(law, x + np.array([0.0, e])) - residual(law, x - np.array([0.0, e])))


def _tangent(law, x, prev):
    """(unit tangent of the branch at x, oriented along prev; the sign of the residual's slope in c at fixed
    eps, opposite on a fold's two sides): one LU for the slope in eps (forward difference), none in c."""
    f = lambda dx: residual(law, x + np.asarray(dx))
    e, ec = FD_STEP, _step_log_d(x)
    g = np.array([(f((e, 0.0)) - f((0.0, 0.0))) / e, (f((0.0, ec)) - f((0.0, -ec))) / (2 * ec)])
    norm = math.hypot(*g)
    if not (np.all(np.isfinite(g)) and norm > 0):     # off the plane, or a residual flat to round-off: no tangent
        return None, None
    t = np.array([-g[1], g[0]]) / norm
    return (-t if t @ prev < 0 else t), math.copysign(1.0, g[1])


def fixed_eps(law, pred, h):
    """The branch's point at the predicted eps with log(c - eps) within h of the predicted one (secant from
    it: the branch through the prediction, also next to a fold), or None."""
    if not (pred[0] < LOG_PI and pred[1] < LOG_PI):
        return None
    eps = math.exp(pred[0])
    if eps + math.exp(pred[1]) >= math.pi:
        return None
    d = _cr.zone_end_secant(law.fixed(eps).fx, eps, law.s0, law.h0, float(pred[1]), float(h), 0.0,
                            log_d_resolution(pred))
    return None if d < 0 else np.array([pred[0], math.log(d)])


def normal_line(law, pred, t, h):
    """The branch's point on the normal to t through pred within h/2 (secant; one LU per iterate), or None."""
    n = np.array([-t[1], t[0]])
    f = lambda tau: residual(law, pred + tau * n)
    a, b = 0.0, 1e-3 * h
    fa, fb = f(a), f(b)
    tol = max(1e-13 * max(1.0, np.abs(pred).max()), log_d_resolution(pred))
    for _ in range(SECANT_STEPS):
        if not (np.isfinite(fa) and np.isfinite(fb)):
            return None
        if fb == fa:                          # flat: converged at the resolution of d, else stalled
            return pred + b * n if abs(b - a) <= 4 * tol else None
        a, fa, b = b, fb, b - fb * (b - a) / (fb - fa)
        if abs(b) > 0.5 * h:
            return None
        if abs(b - a) <= tol:
            return pred + b * n
        fb = f(b)
    return None


def fixed_zone(law, pred, h, start=None):
    """The branch's point at the predicted zone length with log eps within h of the predicted one (the secant
    started at start, by default the predicted log eps), or None."""
    if not (pred[0] < LOG_PI and pred[1] < LOG_PI):
        return None
    top = math.log(math.pi - math.exp(pred[1])) - 1e-9
    f = lambda le: residual(law, np.array([le, pred[1]])) if le < top else math.nan
    a = pred[0] if start is None else start
    b = a + 1e-3 * h                                # secant in log eps (each iterate one LU)
    fa, fb = f(a), f(b)
    for _ in range(SECANT_STEPS):
        if not (np.isfinite(fa) and np.isfinite(fb)) or fb == fa:
            return None
        a, fa, b = b, fb, b - fb * (b - a) / (fb - fa)
        if abs(b - pred[0]) > h:
            return None
        if abs(b - a) <= 1e-13 * max(1.0, abs(b)):
            return np.array([b, pred[1]])
        fb = f(b)
    return None


def _inverse_quadratic(p0, p1, p2, secant):
    """The root of the inverse quadratic through three (x, f) points, or the secant's when they do not define one
    (two equal f) or it lies more than twice as far from the last point as the secant's."""
    (x0, f0), (x1, f1), (x2, f2) = p0, p1, p2
    if not (f0 != f1 and f0 != f2 and f1 != f2 and math.isfinite(f0)):
        return secant
    x = (x0 * f1 * f2 / ((f0 - f1) * (f0 - f2)) + x1 * f0 * f2 / ((f1 - f0) * (f1 - f2))
         + x2 * f0 * f1 / ((f2 - f0) * (f2 - f1)))
    return x if math.isfinite(x) and abs(x - x2) <= 2 * abs(secant - x2) else secant
