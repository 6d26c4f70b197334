"""JKR's two-patch branch between two of its traced points, solved on the branch: the state where the held
quantity takes a value, and the fold (the stationary point of the held quantity), for the walker
(jkrcyl.analysis.path.walk_two_patch).

The traced points are continuation steps (up to ~0.5 in delta/Delta apart): a fold read at a point sits up to a
step short of the branch's extremum, and half-angles interpolated between two points are not an equilibrium
(Griffith holds at one end only).  Here the half-angle that varies most between the two points is held at x and
the other solved (jkrcyl.model.two_patch.solve, from the chord's guess), so every state is an equilibrium.
"""
from __future__ import annotations

import numpy as np

from ..model import two_patch as _two
from ..model.problem import Problem
from ..numerics import roots as _roots
from . import tracing as _tr

SLOPE_STEP = 1e-5       # the central difference of the held quantity along the branch, relative to the bracket


def held(pb: Problem, s, key: str) -> float:
    """The normalised held quantity key (P_star, delta_over_Delta, delta_work_over_Delta) of a TwoPatchState."""
    return (s.delta_over_Delta + pb.work_shift * pb.scale * s.P_star if key == "delta_work_over_Delta"
            else getattr(s, key))


def _top_varies_most(b, i: int, k: int) -> bool:
    return abs(float(b.eps_top[k] - b.eps_top[i])) > abs(float(b.eps[k] - b.eps[i]))


def along(pb: Problem, b, i: int, k: int):
    """(state(x), (x_i, x_k)): the branch b between its points i and k, the half-angle varying most held at x."""
    e0, e1, t0, t1 = (float(v) for v in (b.eps[i], b.eps[k], b.eps_top[i], b.eps_top[k]))
    if _top_varies_most(b, i, k):
        return (lambda x: _two.solve(pb, eps_top=x, guess=e0 + (e1 - e0) * (x - t0) / (t1 - t0))), (t0, t1)
    return (lambda x: _two.solve(pb, eps=x, guess=t0 + (t1 - t0) * (x - e0) / (e1 - e0))), (e0, e1)


def coordinate(b, i: int, k: int, j: int) -> float:
    """x of the branch's point j in the parametrisation of :func:`along` between points i and k."""
    return float(b.eps_top[j] if _top_varies_most(b, i, k) else b.eps[j])


def at_target(pb: Problem, b, i: int, k: int, key: str, target: float, span=None):
    """The state between points i and k (or over span, two x of :func:`along`'s parametrisation there) where the
    held quantity key equals target (Brent), None without one."""
    state, (x0, x1) = along(pb, b, i, k)
    x0, x1 = (x0, x1) if span is None else span
    try:
        return state(_roots.brent(lambda x, _: held(pb, state(x), key) - target, min(x0, x1), max(x0, x1)))
    except ValueError:
        return None


def fold(pb: Problem, b, i: int, k: int, key: str):
    """The fold of the held quantity key between points i and k: the root of its slope along the branch (central
    differences, bracketed by the slopes at both points; Brent): (state, x), None where the slope keeps its sign
    there."""
    state, (x0, x1) = along(pb, b, i, k)
    h = SLOPE_STEP * abs(x1 - x0)

    def slope(x, _=None):
        return (held(pb, state(x + h), key) - held(pb, state(x - h), key)) / (2 * h)
    lo, hi = sorted((x0, x1))
    lo, hi = lo + h, hi - h
    try:
        flo, fhi = slope(lo), slope(hi)
        if (flo > 0) == (fhi > 0):
            return None
        x = _roots.brent(slope, lo, hi, (), flo, fhi, xtol=1e-9 * (hi - lo))
        return state(x), x
    except ValueError:                          # no equilibrium near the chord (the secant of solve)
        return None


def fold_near(pb: Problem, eps: float, eps_top: float, key: str, sgn: int):
    """The fold (a largest sgn * key) of the traced branch of pb nearest to the arcs (eps, eps_top): the local
    extremum of the branch's points nearest to its closest point, refined (:func:`fold`); None without one."""
    b = min(_tr.branches(pb), key=lambda c: float(np.min(np.hypot(c.eps - eps, c.eps_top - eps_top))))
    i = int(np.argmin(np.hypot(b.eps - eps, b.eps_top - eps_top)))
    y = sgn * np.asarray(getattr(b, key))
    tops = [m for m in range(1, y.size - 1) if y[m] >= y[m - 1] and y[m] >= y[m + 1]]
    if not tops:
        return None
    m = min(tops, key=lambda t: abs(t - i))
    got = fold(pb, b, m - 1, m + 1, key)
    return None if got is None else got[0]
