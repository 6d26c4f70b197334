"""The one root-finding toolkit of jkrcyl: bracketing on a grid, Brent's method, Newton, the secant.

Each algorithm is written once, as plain Python taking the function ``f(x, args)``; the numba form is
the same source compiled around one njit ``f`` (:func:`brent_solver`, :func:`newton_solver`), so the
library (a Python callable, e.g. one collocation solve per evaluation) and the atlas (njit loops over
millions of pairs) refine roots identically.  Closures over a jitted ``f`` are cached by numba per ``f``.
"""
import functools

import numpy as np
from numba import njit

EPS = 2.220446049250313e-16


def _make_brent(f, xtol=0.0):
    def brent(lo, hi, flo, fhi, args):
        """Root of f in [lo, hi] with f(lo) f(hi) < 0: Brent's method (inverse quadratic / secant steps
        safeguarded by bisection), then bisection of the last bracket to adjacent doubles (xtol = 0), or to xtol
        (an absolute tolerance in x, for a noisy f whose last digits a bisection cannot use)."""
        a, b, fa, fb = lo, hi, flo, fhi
        c, fc = a, fa
        d = b - a
        e = d
        for _ in range(200):
            if (fb > 0.0) == (fc > 0.0):
                c, fc = a, fa
                d = b - a
                e = d
            if abs(fc) < abs(fb):
                a, fa = b, fb
                b, fb = c, fc
                c, fc = a, fa
            tol = 2.0 * EPS * abs(b) + 1e-300 + 0.5 * xtol
            xm = 0.5 * (c - b)
            if abs(xm) <= tol or fb == 0.0:
                break
            if abs(e) >= tol and abs(fa) > abs(fb) and fc != 0.0:   # fc = 0 (an underflowed value): bisect
                s = fb / fa
                if a == c:
                    p = 2.0 * xm * s
                    q = 1.0 - s
                else:
                    q = fa / fc
                    r = fb / fc
                    p = s * (2.0 * xm * q * (q - r) - (b - a) * (r - 1.0))
                    q = (q - 1.0) * (r - 1.0) * (s - 1.0)
                if p > 0.0:
                    q = -q
                p = abs(p)
                if q != 0.0 and 2.0 * p < min(3.0 * xm * q - abs(tol * q), abs(e * q)):
                    e = d
                    d = p / q
                else:
                    d = xm
                    e = d
            else:
                d = xm
                e = d
            a, fa = b, fb
            b = b + d if abs(d) > tol else b + (tol if xm > 0.0 else -tol)
            fb = f(b, args)
        if fb == 0.0 or (fb > 0.0) == (fc > 0.0) or xtol > 0.0:
            return b
        lo, hi, flo, fhi = (b, c, fb, fc) if b < c else (c, b, fc, fb)
        for _ in range(64):
            mid = 0.5 * (lo + hi)
            if mid <= lo or mid >= hi:
                break
            fm = f(mid, args)
            if fm == 0.0:
                return mid
            if (fm > 0.0) == (flo > 0.0):
                lo, flo = mid, fm
            else:
                hi, fhi = mid, fm
        return lo if abs(flo) <= abs(fhi) else hi
    return brent


def _make_newton(f_df):
    def newton(x0, args):
        """Newton from x0 until |step| <= 1e-16 |x| (200 steps at most)."""
        x = x0
        for _ in range(200):
            fx, dfx = f_df(x, args)
            step = fx / dfx
            x -= step
            if abs(step) <= 1e-16 * abs(x):
                break
        return x
    return newton


@functools.lru_cache(maxsize=None)
def brent_solver(f):
    """njit ``solve(lo, hi, flo, fhi, args)`` for an njit ``f(x, args)``; see :func:`brent`."""
    return njit(cache=True)(_make_brent(f))


@functools.lru_cache(maxsize=None)
def newton_solver(f_df):
    """njit ``solve(x0, args)`` for an njit ``f_df(x, args) -> (f, df/dx)``."""
    return njit(cache=True)(_make_newton(f_df))


def brent(f, lo, hi, args=(), flo=None, fhi=None, xtol=0.0):
    """Root of a Python callable ``f(x, args)`` in [lo, hi] (sign change), to adjacent doubles (or to the
    absolute tolerance xtol > 0: an f with noise above rounding)."""
    flo = f(lo, args) if flo is None else flo
    fhi = f(hi, args) if fhi is None else fhi
    if flo == 0.0:
        return lo
    if fhi == 0.0:
        return hi
    if (flo > 0.0) == (fhi > 0.0):
        raise ValueError(f"brent: no sign change in [{lo!r}, {hi!r}]")
    return _make_brent(f, float(xtol))(float(lo), float(hi), float(flo), float(fhi), args)


def root(f, lo, hi, xtol=0.0):
    """Root of a one-argument callable f(x) in [lo, hi] (a sign change): :func:`brent`."""
    return brent(lambda x, _: f(x), lo, hi, (), None, None, xtol)


def minimum(f, lo, mid, hi, xtol):
    """The minimiser and minimum (x, f(x)) of f near the bracket lo < mid < hi (f(mid) below both ends; Brent's
    parabolic search, scipy), or over [lo, hi] (bounded search) where f is not below its ends at mid."""
    from scipy.optimize import minimize_scalar          # scipy.optimize loads in ~0.3 s: only where a minimum is asked
    try:
        res = minimize_scalar(f, bracket=(lo, mid, hi), method="brent", options=dict(xtol=xtol))
    except ValueError:
        res = minimize_scalar(f, bounds=(lo, hi), method="bounded", options=dict(xatol=xtol * 1e-2))
    return float(res.x), float(res.fun)


def is_pole(fx, flo, fhi):
    """A converged sign change is a pole, not a root, when |f| there exceeds |f| at both ends of the first
    bracket (|f| grew as the bracket shrank); a root leaves |f| at the rounding level."""
    return not abs(fx) <= max(abs(flo), abs(fhi))


def brent_or_pole(f, lo, hi, args=(), flo=None, fhi=None, xtol=0.0):
    """:func:`brent`, but None where the sign change is a pole of f (:func:`is_pole`)."""
    flo = f(lo, args) if flo is None else flo
    fhi = f(hi, args) if fhi is None else fhi
    try:
        x = brent(f, lo, hi, args, flo, fhi, xtol)
        return None if is_pole(f(x, args), flo, fhi) else x
    except ZeroDivisionError:                  # the bracket closed exactly on the pole
        return None


def brent_or_pole_nb(solve, f, lo, hi, flo, fhi, args):
    """The numba pair (``solve = brent_solver(f)``, ``f``) with the pole check of :func:`brent_or_pole`."""
    if flo == 0.0:
        return lo
    if fhi == 0.0:
        return hi
    try:
        x = solve(float(lo), float(hi), float(flo), float(fhi), args)
        return None if is_pole(f(x, args), flo, fhi) else float(x)
    except ZeroDivisionError:                  # the bracket closed exactly on the pole
        return None


def sign_changes(values):
    """Indices i with values[i] and values[i + 1] of opposite signs (both finite)."""
    v = np.asarray(values, dtype=float)
    ok = np.isfinite(v[:-1]) & np.isfinite(v[1:])
    return np.nonzero(ok & (np.sign(v[:-1]) * np.sign(v[1:]) < 0))[0]


def roots_on_grid(values, grid, refine):
    """Roots of f from its values on the increasing grid: every sign change refined by ``refine(lo, hi, flo,
    fhi)`` (a root, or None for a pole), exact zeros on the grid included.  Returns ``[(root, +1 or -1)]``, the
    sign that of f right of the root (+1: f rises through it), sorted."""
    v = np.asarray(values, dtype=float)
    out = []
    for i in sign_changes(v):
        r = refine(float(grid[i]), float(grid[i + 1]), float(v[i]), float(v[i + 1]))
        if r is not None:
            out.append((r, 1 if v[i + 1] > 0 else -1))
    for i in np.nonzero(v == 0)[0]:
        right = v[i + 1] if i + 1 < v.size else -v[i - 1]
        out.append((float(grid[i]), 1 if right > 0 else -1))
    return sorted(out)


def secant(f, x0, x1, lo, hi, tol=1e-13, maxit=40, noise=0.0):
    """Secant iterations for f(x) = 0 from x0, x1, kept in [lo, hi] (halving towards the previous iterate
    when a step leaves it).  Returns (x, f(x)) of the last evaluated iterate -- or, once |f| <= noise stops
    falling (f's rounding: the steps then wander far above tol), of the best one; raises ValueError without
    convergence."""
    f0, f1 = f(x0), f(x1)
    best = min((abs(f0), x0, f0), (abs(f1), x1, f1))
    for _ in range(maxit):
        if f1 == f0:
            break
        x2 = min(max(x1 - f1 * (x1 - x0) / (f1 - f0), 0.5 * (lo + x1)), 0.5 * (x1 + hi))
        x0, f0, x1 = x1, f1, x2
        if abs(x1 - x0) <= tol * abs(x1):
            return x0, f0
        f1 = f(x1)
        if abs(f1) <= noise and abs(f1) >= best[0]:
            return best[1], best[2]
        best = min(best, (abs(f1), x1, f1))
    else:
        raise ValueError(f"secant: no convergence near {x1!r}")
    return x1, f1


def secant_or_none(f, a, b, tol, noise, steps):
    """Secant iterations for f(x) = 0 from a, b, unbounded, without raising: the root where a step is below tol
    (relative to max(1, |x|)), or within noise where f's rounding stops it (equal values, or the steps run out)
    -- else None (f not finite, or no convergence)."""
    fa, fb = f(a), f(b)
    for _ in range(steps):
        if not (np.isfinite(fa) and np.isfinite(fb)):
            return None
        if fa == fb:
            return b if abs(b - a) <= noise else None
        a, fa, b = b, fb, b - fb * (b - a) / (fb - fa)
        if abs(b - a) <= tol * max(1.0, abs(b)):
            return b
        fb = f(b)
    return b if abs(b - a) <= noise else None


def damped_newton(f, x, jacobian, scale, tol, largest, max_steps, halvings, floor=None, after_step=None):
    """Newton on a small system f(x) = 0 (f: a vector, or None outside its domain) with the Jacobian
    ``jacobian(x, r)`` (None: singular or not computable), each step scaled down to |dx_i| <= largest_i and halved
    while |f/scale| does not decrease (at most ``halvings`` times).  Converged where |f_i| < tol scale_i; or, with
    floor given, where the steps stop reducing f (the line search fails, or max_steps run out) at |f_i| < floor_i:
    f's rounding floor reached above tol (the best point is returned).  ``after_step(x, dx, r, r_new, J)`` sees
    each accepted step (e.g. a secant update of a column).  Returns (x, f(x)), or None (no convergence, the domain
    left, no Jacobian)."""
    r = f(x)
    best = (x, r)

    def at_floor():
        return floor is not None and best[1] is not None and np.all(np.abs(best[1]) < floor)

    for _ in range(max_steps):
        if r is None:
            return None
        if np.all(np.abs(r) < tol * scale):
            return x, r
        J = jacobian(x, r)
        if J is None:
            return None
        dx = np.linalg.solve(J, -r)
        dx *= min(1.0, float(np.min(largest / np.maximum(np.abs(dx), 1e-300))))
        for _ in range(halvings):
            rt = f(x + dx)
            if rt is not None and np.linalg.norm(rt / scale) < np.linalg.norm(r / scale):
                break
            dx /= 2
        else:
            return best if at_floor() else None
        if after_step is not None:
            after_step(x, dx, r, rt, J)
        x, r = x + dx, rt
        if np.linalg.norm(r / scale) < np.linalg.norm(best[1] / scale):
            best = (x, r)
    if r is not None and np.all(np.abs(r) < tol * scale):
        return x, r
    return best if at_floor() else None
