"""The two-patch branches: the zero set of F(eps, eps_top) (jkrcyl.model.two_patch) traced by pseudo-arclength
continuation (jkrcyl.numerics.continuation) in log half-angles, started at each single-patch onset h(pi) = 0
(a_top -> 0), at its mirror (a -> 0) and at the roots of F along a few rows eps_top = const (loops) -- no plane
grid.  Cached per problem: a repeat on the same contact is free.
"""
from __future__ import annotations

import functools
import math
import warnings

import numpy as np

from .._validate import count
from ..model import two_patch as _two
from ..model.problem import Problem
from ..model.single_patch import solver
from ..notices import BranchLimitWarning
from ..numerics import continuation as _cont
from ..numerics import roots as _roots
from ..results import TwoPatchCurve
from . import branches as _br

EPS_AXIS = 1e-12        # smallest half-angle traced: a branch reaching it ends on the single-patch state
GAP_FULL = _two.GAP_FULL   # eps + eps_top >= pi - GAP_FULL: the branch has run into full contact
SCAN_TOP = (0.05, 0.3, 0.7, 1.2, 1.8, 2.5)    # eps_top rows scanned for branches not reached otherwise
SCAN_POINTS = 32
SCAN_GAP = 0.1          # rows stop this far from full contact (F keeps one sign there)
H0 = 0.05               # continuation step in log half-angles
H_MAX = 10              # longest step, in units of H0
N_RESAMPLE_MAX = 100_000   # points per resampled branch (each a two-arc solve: ~0.1 ms)
LOG_AXIS = math.log(EPS_AXIS)


@functools.lru_cache(maxsize=64)
def onset_angles(pb: Problem) -> tuple:
    """Half-angles eps where a single-patch equilibrium has h(pi) = 0 (sub- and super-critical branches);
    () without two-patch states (M = 0)."""
    if pb.M <= 0:
        return ()
    return tuple(sorted(2 * math.atan(r) for reg in solver(pb).regimes() for r, _ in _br.roots(pb, reg, "h")))


def _domain(u):
    """Inside the traced region, in log half-angles u = (log eps, log eps_top)."""
    return u[0] >= LOG_AXIS and u[1] >= LOG_AXIS and math.exp(u[0]) + math.exp(u[1]) <= math.pi - GAP_FULL


_T_MAX = math.log(math.pi - GAP_FULL - EPS_AXIS)       # largest log half-angle on a boundary


def _full_top(t):
    return math.log(max(math.pi - GAP_FULL - math.exp(t), 1e-300))


# the boundaries in log half-angles: (label, g(u) >= 0 inside, the boundary as u(t), t of a point on it)
_BOUNDARIES = (
    ("single", lambda u: u[1] - LOG_AXIS, lambda t: np.array([t, LOG_AXIS]), lambda u: u[0]),       # a_top -> 0
    ("mirror", lambda u: u[0] - LOG_AXIS, lambda t: np.array([LOG_AXIS, t]), lambda u: u[1]),       # a -> 0
    ("full", lambda u: math.pi - GAP_FULL - math.exp(min(u[0], 1.2)) - math.exp(min(u[1], 1.2)),   # arcs meet
     lambda t: np.array([t, _full_top(t)]), lambda u: u[0]),
)


def _clipper(f):
    """Exit point of the curve between u (inside) and v (outside): where it meets the first boundary crossed --
    the segment's crossing (bisection on the boundary function, no F), then a secant in the boundary's own
    parameter onto F = 0 (a handful of residuals; None when it does not settle there)."""
    def clip(u, v):
        best = None
        for label, g, at, t_of in _BOUNDARIES:
            if g(v) < 0 <= g(u):
                lo, hi = 0.0, 1.0
                for _ in range(60):
                    mid = 0.5 * (lo + hi)
                    lo, hi = (mid, hi) if g(u + mid * (v - u)) >= 0 else (lo, mid)
                if best is None or lo < best[0]:
                    best = (lo, label, at, t_of)
        if best is None:
            return None, "domain"
        s, label, at, t_of = best
        t0 = min(t_of(u + s * (v - u)), _T_MAX)
        phi = lambda t: f(at(t))
        try:
            t, ft = _roots.secant(phi, t0, t0 - 1e-4 * max(1.0, abs(t0)), LOG_AXIS, _T_MAX, tol=1e-10)
        except ValueError:
            return None, label
        return (at(t) if np.isfinite(ft) and abs(ft) < 1e-9 else None), label
    return clip


def _near(x, polylines, tol):
    """Is x within tol of one of the traced polylines (distance to their segments)?"""
    for p in polylines:
        a, b = p[:-1], p[1:]
        d = b - a
        t = np.clip(np.einsum("ij,ij->i", x - a, d) / np.maximum(np.einsum("ij,ij->i", d, d), 1e-300), 0, 1)
        if a.shape[0] and np.min(np.linalg.norm(a + t[:, None] * d - x, axis=1)) < tol:
            return True
    return False


def _crosses_row(polylines, row, lo, hi):
    """Does a traced polyline (log half-angles) cross the row u[1] = row with lo <= u[0] <= hi?"""
    for p in polylines:
        y0, y1 = p[:-1, 1] - row, p[1:, 1] - row
        for j in np.nonzero((y0 * y1 <= 0) & (y0 != y1))[0]:
            x = p[j, 0] + (p[j + 1, 0] - p[j, 0]) * y0[j] / (y0[j] - y1[j])
            if lo <= x <= hi:
                return True
    return False


def _residuals(pb, nodes):
    """F on the plane (x = half-angles) and in log half-angles, clamped so stray iterates stay evaluable."""
    lo, hi = 0.1 * EPS_AXIS, math.pi - 0.1 * GAP_FULL
    fx = lambda x: (_two.residual(pb, max(x[0], lo), max(x[1], lo), nodes) if x[0] + x[1] < hi else math.nan)
    return fx, (lambda u: fx(np.exp(np.minimum(u, 1.2))))      # exp(1.2) > pi: stray iterates give nan


def _trace(f, clip, u, t0):
    return _cont.trace(f, u, t0, _domain, clip, h0=H0, h_max=H_MAX * H0)


def _from_onsets(pb, f, clip, found):
    for e in onset_angles(pb):
        for k, label in ((0, "single"), (1, "mirror")):     # a_top -> 0 at the onset, a -> 0 at its mirror
            u0 = np.full(2, LOG_AXIS)
            u0[k] = math.log(e)
            u, ok = _cont.project(f, u0, direction=np.eye(2)[k])
            if not ok or not _domain(u) or _near(u, [p for p, _ in found], 2 * H0):
                continue
            path = _trace(f, clip, u, np.eye(2)[1 - k])
            found.append((np.vstack([u, path.points[1:]]), (label, path.boundary or path.end)))


def _from_rows(fx, f, clip, found):
    for et in SCAN_TOP:
        top = math.pi - et - SCAN_GAP
        if top <= 0.05:
            continue
        es = np.linspace(1e-3, top, SCAN_POINTS)
        for i in _roots.sign_changes([fx(np.array([e, et])) for e in es]):
            if _crosses_row([p for p, _ in found], math.log(et), math.log(es[i]), math.log(es[i + 1])):
                continue                                # a traced branch already passes through this bracket
            u, ok = _cont.project(f, np.log([0.5 * (es[i] + es[i + 1]), et]), direction=np.array([1.0, 0.0]))
            if not ok or not _domain(u) or _near(u, [p for p, _ in found], 2 * H0):
                continue
            ahead = _trace(f, clip, u, np.array([0.0, 1.0]))
            if ahead.end == "loop":
                found.append((ahead.points, ("loop", "loop")))
                continue
            back = _trace(f, clip, u, np.array([0.0, -1.0]))
            found.append((np.vstack([back.points[::-1], ahead.points[1:]]),
                          (back.boundary or back.end, ahead.boundary or ahead.end)))


@functools.lru_cache(maxsize=16)
def traced(pb: Problem, nodes: int = _two.N_NODES) -> tuple:
    """Every two-patch branch as (points (k, 2) in half-angles, ends), cached per problem."""
    _two.require_two_patch(pb)
    fx, f = _residuals(pb, nodes)
    clip = _clipper(f)
    found = []
    _from_onsets(pb, f, clip, found)
    _from_rows(fx, f, clip, found)
    return tuple((np.exp(p), ends) for p, ends in found if len(p) >= 4)


def _resample(f, points, n):
    """n points equally spaced in arclength along the traced polyline, each projected back onto F = 0."""
    seg = np.linalg.norm(np.diff(points, axis=0), axis=1)
    s = np.concatenate([[0.0], np.cumsum(seg)])
    t = np.linspace(0.0, s[-1], n)
    out = np.column_stack([np.interp(t, s, points[:, 0]), np.interp(t, s, points[:, 1])])
    for i in range(1, n - 1):                      # the ends are exact already
        j = np.searchsorted(s, t[i])
        d = points[min(j, len(points) - 1)] - points[max(j - 1, 0)]
        normal = np.array([-d[1], d[0]]) / (np.linalg.norm(d) or 1.0)
        y, ok = _cont.project(f, out[i], direction=normal)
        if ok:
            out[i] = y
    return out


def _curve(pb, points, ends, nodes):
    states = [_two.equilibrium_state(pb, e, et, nodes) for e, et in points]
    stab = np.array([_two.stability(pb, s.eps, s.eps_top, s.delta_over_Delta, nodes, lin=s._lin) for s in states])
    sv = solver(pb)
    arr = lambda k: np.array([getattr(s, k) for s in states])
    a, at = np.tan(points[:, 0] / 2), np.tan(points[:, 1] / 2)
    P, d = arr("P_star"), arr("delta_over_Delta")
    return TwoPatchCurve(M=pb.M, theta=pb.theta, gb=pb.gb, a=a, a_top=at, eps=points[:, 0], eps_top=points[:, 1],
                         eps_star=sv.eps_star(a), eps_top_star=sv.eps_star(at), P_star=P, delta_over_Delta=d,
                         delta_work_over_Delta=d + pb.work_shift * pb.scale * P, gap_min=arr("gap_min"),
                         feasible=arr("gap_min") >= -1e-9, stable_load=stab[:, 0], stable_grip=stab[:, 1],
                         stable_grip_work=stab[:, 2], G_bot=arr("G_bot"), G_top=arr("G_top"), ends=tuple(ends),
                         alpha_ratio=pb.alpha_ratio)


@functools.lru_cache(maxsize=16)
def branches(pb: Problem, n=None, nodes: int = _two.N_NODES) -> tuple:
    """Every branch of two-patch equilibria: a tuple of TwoPatchCurve (n points each, equally spaced in
    arclength in the half-angle plane; default: the continuation steps).  Cached per problem."""
    if n is not None:
        n = count("n", n, low=4, high=N_RESAMPLE_MAX)
    fx, _ = _residuals(pb, nodes)
    out = []
    for p, ends in traced(pb, nodes):
        out.append(_curve(pb, p if n is None else _resample(fx, p, n), ends, nodes))
    return tuple(out)


def states_at(pb: Problem, key: str, target: float):
    """Two-patch states where the normalised field ``key`` (P_star, delta_over_Delta, delta_work_over_Delta) equals
    target: sign changes along each traced branch, refined on the branch by Brent's method in the half-angle that
    varies most (the other from jkrcyl.model.two_patch.solve)."""
    out = []
    for b in branches(pb):
        v = np.asarray(getattr(b, key)) - target
        for i in _roots.sign_changes(v):
            e0, e1, t0, t1 = b.eps[i], b.eps[i + 1], b.eps_top[i], b.eps_top[i + 1]
            along_top = abs(t1 - t0) > abs(e1 - e0)
            lo, hi = (t0, t1) if along_top else (e0, e1)

            def state(x):
                if along_top:
                    return _two.solve(pb, eps_top=x, guess=e0 + (e1 - e0) * (x - t0) / (t1 - t0))
                return _two.solve(pb, eps=x, guess=t0 + (t1 - t0) * (x - e0) / (e1 - e0))

            def f(x, _):
                s = state(x)
                return (s.delta_over_Delta + pb.work_shift * pb.scale * s.P_star if key == "delta_work_over_Delta"
                        else getattr(s, key)) - target
            try:
                x = _roots.brent(f, min(lo, hi), max(lo, hi))
                out.append(state(x))
            except ValueError as why:        # said, not dropped silently (session 37: 22 of 26 levels were)
                warnings.warn(f"two-patch state at {key} = {target:.6g} not solved between the traced points "
                              f"({e0:.6g}, {t0:.6g}) and ({e1:.6g}, {t1:.6g}): {why}", BranchLimitWarning,
                              stacklevel=2)
    return out
