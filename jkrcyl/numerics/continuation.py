"""Pseudo-arclength continuation of the zero set of a scalar function on the plane.

The two-patch equilibria at fixed (M, vartheta) are the curves F(eps, eps_top) = 0 of one scalar residual
in the half-angles (jkrcyl.analysis.tracing); this module follows such a curve from a point on it until it leaves a
domain or closes on itself.  Predictor: a step h along the unit tangent t (perpendicular to grad F);
corrector: Newton on [F(y) = 0, t . (y - x) = h] (Keller's pseudo-arclength).  Gradients by central
differences, so F need only be a callable.  No plane grid: cost is proportional to the curve length.
"""
import math
from dataclasses import dataclass, field

import numpy as np

FD_STEP = 1e-6


def gradient(f, x, fx=None, h=FD_STEP):
    """Gradient of f at the 2-vector x: forward differences when f(x) is given, else central."""
    g = np.empty(2)
    for i in range(2):
        e = np.zeros(2)
        e[i] = min(h, 0.1 * abs(x[i])) or h      # stay on the positive side of a half-angle
        g[i] = (f(x + e) - f(x - e)) / (2 * e[i]) if fx is None else (f(x + e) - fx) / e[i]
    return g


def _tangent(g, prev=None):
    t = np.array([-g[1], g[0]]) / math.hypot(*g)
    return -t if prev is not None and t @ prev < 0 else t


NOISE_F = 1e-10     # project: |f| below which a stalled Newton iteration is taken as f's noise floor
ACCEPT_F = 1e-8     # project: |f| accepted as on the curve when the steps do not reach tol (as always)


def project(f, x, direction=None, tol=1e-12, maxit=30):
    """Newton from x onto f = 0: along grad f, or along the unit vector ``direction`` when given.

    Returns (point, ok).  Stops when the step is below tol (relative; ok), or at f's noise floor: once some
    iterate has |f| <= NOISE_F, an iterate that does not lower the smallest |f| so far, or a step that is not
    at most half the one before, ends the iteration (rounding now drives the iterates: at large node counts
    F is noisy at ~1e-12 while the steps would need 1e-12 relative).  Then, or after maxit iterations, the
    iterate with the smallest |f| is returned, ok iff that |f| <= ACCEPT_F.
    """
    x = np.array(x, dtype=float)
    best_x, best_f = x, math.inf
    prev_size = size = math.inf
    for _ in range(maxit):
        fx = f(x)
        stalled = abs(fx) >= best_f or size > 0.5 * prev_size
        if abs(fx) < best_f:
            best_x, best_f = x, abs(fx)
        if stalled and best_f <= NOISE_F:
            return best_x, True
        g = gradient(f, x)
        den = g @ g if direction is None else g @ direction
        if not np.isfinite(den) or den == 0:
            return x, False
        d = (g if direction is None else direction) / den
        step = fx * d
        if not np.all(np.isfinite(step)):
            return x, False
        x = x - step
        prev_size, size = size, np.abs(step).max()
        if size <= tol * max(1.0, np.abs(x).max()):
            return x, True
    fx = f(x)
    if abs(fx) < best_f:
        best_x, best_f = x, abs(fx)
    return best_x, best_f <= ACCEPT_F


@dataclass
class Path:
    """A traced curve: points (k, 2), the reason it stopped at each end ('boundary', 'loop', 'steps')."""

    points: np.ndarray
    end: str
    boundary: object = None           # the boundary callable's label at the end point, if any
    info: dict = field(default_factory=dict)


def trace(f, x0, t0, inside, clip, h0=0.02, h_min=1e-7, h_max=0.08, tol=1e-11, max_steps=2000):
    """Follow f = 0 from the point x0 (on the curve) in the direction of t0.

    inside(x) -> bool: the domain; clip(x_in, x_out) -> (x_on_boundary, label): the curve's exit point
    between an inside point and an outside one (the caller knows its boundaries).  Stops on leaving the
    domain ('boundary'), on returning to x0 ('loop') or after max_steps ('steps').
    """
    x = np.asarray(x0, dtype=float)
    t = _tangent(gradient(f, x), t0)
    t0_unit = t.copy()
    pts, h, travelled = [x.copy()], h0, 0.0
    for _ in range(max_steps):
        y, ok, g_last = _correct(f, x, t, h, tol, inside)
        if not ok:
            h /= 2
            if h < h_min:
                return Path(np.array(pts), "stalled")
            continue
        if not inside(y) or g_last is None:
            yb, label = clip(x, y)
            if yb is None and h > 64 * h_min:
                h /= 4                       # a wild corrector iterate, not the curve leaving: shorter step
                continue
            if yb is not None:
                pts.append(yb)
            return Path(np.array(pts), "boundary", label)
        travelled += np.linalg.norm(y - x)
        if _closes(pts[0], t0_unit, x, y, h, travelled):
            pts.append(pts[0].copy())
            return Path(np.array(pts), "loop")
        t_new = _tangent(g_last, t)             # gradient at the last Newton iterate (|y - iterate| <= tol)
        # too sharp a turn: the step skipped part of the curve
        if t_new @ t < 0.9:
            h /= 2
            if h < h_min:
                return Path(np.array(pts), "stalled")
            continue
        x, t = y, t_new
        pts.append(x.copy())
        h = min(h * 1.5, h_max)
    return Path(np.array(pts), "steps")


def _closes(start, t_start, x, y, h, travelled):
    """The step x -> y closes a loop: after going some way round, it crosses the plane through the start point
    normal to the start tangent, forwards, within a step of the start.  (Nearness alone is not enough: a large
    step passing close by another part of the curve would cut a chord across the loop.)"""
    if travelled <= 3 * h:
        return False
    before, after = (x - start) @ t_start, (y - start) @ t_start
    return before < 0 <= after and np.linalg.norm(x - start) < 2 * h


def _correct(f, x, t, h, tol, inside, maxit=8):
    """Newton on F(y) = 0, t.(y - x) = h from the predictor x + h t (stops early once y leaves the domain:
    the caller then clips the curve at the boundary)."""
    y = x + h * t
    g = None
    for _ in range(maxit):
        if not inside(y):
            return y, True, g
        fy = f(y)
        g = gradient(f, y, fy)
        J = np.array([g, t])
        r = np.array([fy, t @ (y - x) - h])
        try:
            dy = np.linalg.solve(J, r)
        except np.linalg.LinAlgError:
            return y, False, g
        if not np.all(np.isfinite(dy)):
            return y, False, g
        y = y - dy
        if np.abs(dy).max() > 2 * h + 1e-3:
            return y, False, g
        if np.abs(dy).max() <= tol * max(1.0, np.abs(y).max()):
            return y, True, g
    return y, abs(f(y)) < 1e-9, g
