"""The contact branch of one Maugis-Dugdale law next to, and across, the receding contact eps_crit.

Notation of jkrcyl.numerics.cohesive_branch.  At a fixed contact eps and zone end c the edge coefficient k and the
zone-end residual g = h(c) - h0 are affine in the approach, k = k0 + delta k1, g = g0 + delta g1, and k1 vanishes
on the line eps = eps_crit whatever c.  The traces eliminate delta by k = 0 (the residual g0 - k0 g1/k1), which has
a pole on that line, so they stop at eps_crit (1 -+ EPS_MARGIN).  The curve itself is the zero set of

    F(eps, c) = k1 g0 - k0 g1,

regular across the line: on it F = -k0 g1, so the curve crosses eps_crit where k0 = 0 (the approach -g0/g1 and the
load finite: a regular crossing) or where g1 = 0 (the approach and the load unbounded: the pole of JKR's (4.4)).
Where JKR's pole residue nearly vanishes the two crossings lie close together and the curve near them is a
perturbed saddle: on one side of eps_crit it folds within ~1e-4 of it (vartheta 1, lambda 50, M 0.392: the
branch from the touch folds at eps_crit (1 - 5e-4) onto a long zone; the regular crossing, whose load is finite
(P -0.465 at eps_crit), folds at eps_crit (1 - 3e-4) onto a zone vanishing at the pole, with p -> +inf, and carries
the zero-load contact).  :func:`extend` follows F = 0 (x = (log eps, log(c - eps)), F normalised by |(k1, g1)|)
from a trace's end that stops at the margin, through the line, up to the load cap P_CAP m^(4/3), the domain's
bounds, a stop line eps = eps_stop (the sub-critical table's regular crossing: it ends there) or a target point
(the other table's end there: the two tables join).
"""
import math
from collections import namedtuple

import numpy as np

from . import cohesive_branch as _cb
from . import cohesive_contact as _cc
from . import cohesive_super as _csu
from . import one_arc as _one
from . import roots as _roots

H_FIRST = 1e-5          # the first step in x (the traces stop 1e-3 from eps_crit; folds lie ~1e-4 from it)
H_MAX = 0.05            # the largest step in x
H_MIN = 1e-10           # below: the step finds no point on the curve
TURN = 0.98             # the largest turn per step (cosine between tangents)
FD_LOG = 1e-7           # finite-difference step of the tangent in x
SECANT_STEPS = 30
TOL = 1e-13             # the correctors' tolerance in x ...
NOISE = 1e-9            # ... or where the residual's rounding stops the secant this close
MAX_STEPS = 800
JOIN_TOL = 1e-6         # a target point is met when the curve passes its eps within this in log(c - eps)
WINDOW = 0.05           # followed within this of eps_crit, relative (the pole region: the rigid pair's part
                        # below it folds at eps_crit (1 - 2.3e-2)); beyond, a part not joined is not traced

Extended = namedtuple("Extended", "points reason")      # points (n, 2) after the start; reason: why it stopped


def residual(law, x):
    """F/|(k1, g1)| at x = (log eps, log(c - eps)) (module docstring); NaN off the plane's physical part."""
    eps, d = math.exp(x[0]), math.exp(x[1])
    if not (0.0 < eps < math.pi and eps + d < math.pi):
        return math.nan
    (k0, k1), _, _, (g0, g1) = _cb.affine(law, eps, eps + d)
    return (k1 * g0 - k0 * g1) / math.hypot(k1, g1)


def load(law, x):
    """p at the equilibrium x (the approach from both k = 0 and g = 0: jkrcyl.numerics.cohesive_contact.approach)."""
    eps = math.exp(x[0])
    aff = _cb.affine(law, eps, eps + math.exp(x[1]))
    return _cb._at(aff[1], _cc.approach(aff))


def _secant(f, a, b):
    """The root of f by secant from a, b to TOL, or to NOISE where f's rounding stops it (a thin zone: F's
    noise ~1e-14 over its slope in log(c - eps) ~4e-3 at lambda 200), else None (jkrcyl.numerics.roots)."""
    return _roots.secant_or_none(f, a, b, TOL, NOISE, SECANT_STEPS)


def at_eps(law, le, ld):
    """The curve's point at log eps = le, its log(c - eps) by secant from ld (one LU), or None."""
    got = _secant(lambda s: residual(law, (le, s)), ld, ld + 1e-7)
    return None if got is None else np.array([le, got])


def _at_zone(law, le, ld):
    """The curve's point at log(c - eps) = ld, its log eps by secant from le (one LU per iterate), or None."""
    got = _secant(lambda s: residual(law, (s, ld)), le, le + 1e-8)
    return None if got is None else np.array([got, ld])


def project(law, pred, chord):
    """The curve's point next to pred between two table points along chord: at pred's eps where the chord runs
    more along eps, else at its zone length."""
    y = at_eps(law, *pred) if abs(chord[0]) >= abs(chord[1]) else _at_zone(law, *pred)
    return y if y is not None and np.hypot(*(y - pred)) <= np.hypot(*chord) else None


def _tangent(law, x, prev):
    f0 = residual(law, x)
    fe = (residual(law, x + (FD_LOG, 0.0)) - f0) / FD_LOG
    fd = (residual(law, x + (0.0, FD_LOG)) - f0) / FD_LOG
    t = np.array([-fd, fe])
    n = np.hypot(*t)
    if not (np.isfinite(n) and n > 0):
        return None
    t /= n
    return t if t @ prev >= 0 else -t


def _correct(law, x, t, h):
    pred = x + h * t
    y = at_eps(law, *pred) if abs(t[0]) >= 0.5 else _at_zone(law, *pred)
    return y if y is not None and np.hypot(*(y - pred)) <= 0.5 * h else None


def _inside(law, x, eps_top):
    eps, d = math.exp(x[0]), math.exp(x[1])
    near = abs(math.log(eps / eps_crit(law))) <= WINDOW
    return near and law.eps_lo <= eps <= eps_top and eps + d < math.pi * (1 - 1e-9) and abs(load(law, x)) <= law.p_cap


def _passes(le, x, y):
    return (x[0] - le) * (y[0] - le) <= 0 and x[0] != le


def extend(law, x0, direction, eps_top, eps_stop=None, target=None):
    """The curve F = 0 from the point x0 on it, leaving along direction (in x), up to (reason) 'cap' (the next
    point's |p| beyond P_CAP m^(4/3)), 'bounds' (eps below the trace's start or above eps_top, c reaching pi),
    'stop' (the line eps = eps_stop: the last point on it), 'window' (eps leaving WINDOW of eps_crit), 'joined' (the curve passing the target point's eps
    within JOIN_TOL of it: the last point is the target), 'stalled' or 'steps'."""
    x, prev = np.asarray(x0, dtype=float), np.asarray(direction, dtype=float)
    t = _tangent(law, x, prev)
    if t is None:
        return Extended(np.zeros((0, 2)), "stalled")
    pts, h, edge = [], H_FIRST, False
    for _ in range(MAX_STEPS):
        y = _correct(law, x, t, h)
        t_new = _tangent(law, y, t) if y is not None else None
        if t_new is None or t_new @ t < TURN:
            h /= 2
            if h < H_MIN:
                return Extended(np.array(pts).reshape(-1, 2), "stalled")
            continue
        if target is not None and _passes(target[0], x, y):
            z = at_eps(law, target[0], x[1] + (y[1] - x[1]) * (target[0] - x[0]) / (y[0] - x[0]))
            if z is not None and abs(z[1] - target[1]) <= JOIN_TOL:
                return Extended(np.array(pts + [np.asarray(target, dtype=float)]), "joined")
        if eps_stop is not None and _passes(math.log(eps_stop), x, y):
            le = math.log(eps_stop)
            z = at_eps(law, le, x[1] + (y[1] - x[1]) * (le - x[0]) / (y[0] - x[0]))
            if z is not None and _inside(law, z, eps_top):
                return Extended(np.array(pts + [z]), "stop")
        if not _inside(law, y, eps_top):
            if h > 1e-3 * H_FIRST:       # close in on the bound (the last point within a fraction of a step)
                h, edge = h / 4, True
                continue
            far = abs(math.log(math.exp(y[0]) / eps_crit(law))) > WINDOW
            return Extended(_thinned(pts), "cap" if abs(load(law, y)) > law.p_cap else "window" if far else "bounds")
        pts.append(y)
        x, t, h = y, t_new, (h if edge else min(1.5 * h, H_MAX))
    return Extended(_thinned(pts), "steps")


def _thinned(pts, gap=1e-7):
    """The points without those closer than gap in x to the one kept before (closing in on a bound), the last
    point kept (replacing its too-close predecessor)."""
    out = []
    for y in pts:
        if out and np.hypot(*(y - out[-1])) < gap:
            out[-1] = y if y is pts[-1] else out[-1]
            continue
        out.append(y)
    return np.array(out).reshape(-1, 2)


def eps_crit(law):
    """The receding contact 2 atan(a_crit) (inf where there is none)."""
    return 2 * math.atan(_one.receding_contact(law.theta, law.gb, law.ar))


def _at_margin(law, x, ec):
    """Whether the trace point x is an end at the margin next to eps_crit (not at the load cap, not round)."""
    eps, d = math.exp(x[0]), math.exp(x[1])
    return (abs(math.log(eps / ec)) <= 3 * _cb.EPS_MARGIN and eps + d < math.pi - 1e-6
            and abs(load(law, x)) < 0.5 * law.p_cap)


def sub_extended(law, traced):
    """(x, n_added, crossed): the sub-critical trace (x, kind, reason, ...: jkrcyl.numerics.cohesive_branch.trace)
    with its end at the margin next to eps_crit followed on (:func:`extend`) up to the line eps = eps_crit
    (crossed: its last point lies on it, a regular crossing) or the load cap; as it was elsewhere."""
    x, kind, reason = traced[:3]
    ec = eps_crit(law)
    if kind != "zone" or reason or len(x) < 2 or not math.isfinite(ec) or not _at_margin(law, x[-1], ec):
        return x, 0, False
    ext = extend(law, x[-1], x[-1] - x[-2], _csu.EPS_TOP, eps_stop=ec)
    return np.vstack([x, ext.points]), len(ext.points), ext.reason == "stop"


def super_extended(law, traced, sub_end):
    """(x, n_before, n_after, joined, reasons): the super-critical trace (x, kind, reason[, tail, n_join]:
    jkrcyl.numerics.cohesive_super.trace) with each end at the margin next to eps_crit followed on
    (:func:`extend`; its end only where no round-zone tail follows it) through eps_crit up to the load cap or
    the sub-critical table's end sub_end on eps_crit (None where it ends elsewhere): joined -- 'start', 'end'
    or '' -- says which end of the super-critical table is that point; reasons: :func:`extend`'s at either end
    ('' where that end was not followed on)."""
    x, kind = traced[0], traced[1]
    ec = eps_crit(law)
    if kind != "zone" or len(x) < 2:
        return x, 0, 0, "", ("", "")
    joined, before, after, reasons = "", np.zeros((0, 2)), np.zeros((0, 2)), ["", ""]
    if _at_margin(law, x[0], ec):
        ext = extend(law, x[0], x[0] - x[1], _csu.EPS_TOP, target=sub_end)
        before, joined, reasons[0] = ext.points[::-1], ("start" if ext.reason == "joined" else ""), ext.reason
    if len(traced) == 3 and not traced[2] and _at_margin(law, x[-1], ec):
        ext = extend(law, x[-1], x[-1] - x[-2], _csu.EPS_TOP, target=None if joined else sub_end)
        after, joined, reasons[1] = ext.points, (joined or ("end" if ext.reason == "joined" else "")), ext.reason
    return np.vstack([before, x, after]), len(before), len(after), joined, tuple(reasons)
