"""Root searches of the Maugis-Dugdale zone end h(c) = h0 at a fixed contact (jkrcyl.numerics.cohesive,
notation there; the residual and the fixed-contact tuple fx of jkrcyl.numerics.cohesive_kernels): the first root
upward from an estimate, the root nearest a given zone length, the secant root of a branch through a predicted
point, and a whole state in one compiled call.
"""
import math

import numpy as np
from numba import njit

from . import roots
from .cohesive_kernels import PI, _residual, gap, solve_zone, zones_of

_brent = roots.brent_solver(_residual)


@njit(cache=True)
def zone_end(fx, eps, s0, h0, d_start, factor, step, c_top):
    """Zone length d with h(eps + d) = h0 (a top zone |phi - pi| < c_top given): the first sign change upward
    from d_start (steps x factor, at most step rad), then Brent; -1 when h < h0 up to c = pi - c_top (the zone
    reaches round, or meets the top zone).  Below d_start the zone may be unresolved by the nodes, so a root
    below is bracketed with F(0) = -h0."""
    args = (fx, eps, s0, h0, c_top)
    d_max = PI - c_top - eps
    d = min(d_start, d_max / 2)
    f = _residual(d, args)
    if f < 0:
        lo, flo = d, f
        while f < 0:
            if d >= d_max:
                return -1.0
            lo, flo = d, f
            d = min(d * factor, d + step, d_max)
            f = _residual(d, args)
        return _brent(lo, d, flo, f, args)
    hi, fhi = d, f
    for _ in range(6):
        d /= 2
        f = _residual(d, args)
        if f < 0:
            return _brent(d, hi, f, fhi, args)
        hi, fhi = d, f
    return _brent(0.0, hi, -h0, fhi, args)


@njit(cache=True)
def state(fx, eps, s0, h0, d_start, factor, step, c_top):
    """One call for a state: the zone length d (-1: the zone reaches round), delta/Delta, u and h(pi)/Delta."""
    d = zone_end(fx, eps, s0, h0, d_start, factor, step, c_top)
    zones = zones_of(PI if d < 0 else eps + d, c_top)
    dn, u = solve_zone(fx, zones, s0)
    return d, dn, u, gap(fx, np.array([PI]), dn, u, zones, s0)[0]


@njit(cache=True)
def zone_end_near(fx, eps, s0, h0, d_near, c_top):
    """The zone length nearest to d_near (in log d) with h(eps + d) = h0: brackets grown by 5 % a side around
    d_near until a sign change, then Brent; -1 if none within a factor 100 (the branch through d_near has
    turned: a fold of the zone end in eps)."""
    args = (fx, eps, s0, h0, c_top)
    d_max = PI - c_top - eps
    lo = hi = min(d_near, d_max)
    flo = fhi = _residual(lo, args)
    if flo == 0.0:
        return lo
    for _ in range(95):
        lo2, hi2 = lo / 1.05, min(hi * 1.05, d_max)
        flo2 = _residual(lo2, args)
        if flo2 * flo <= 0.0:
            return _brent(lo2, lo, flo2, flo, args)
        if hi2 > hi:
            fhi2 = _residual(hi2, args)
            if fhi2 * fhi <= 0.0:
                return _brent(hi, hi2, fhi, fhi2, args)
            hi, fhi = hi2, fhi2
        lo, flo = lo2, flo2
    return -1.0


@njit(cache=True)
def zone_end_secant(fx, eps, s0, h0, log_d, span, c_top, resolution=0.0):
    """The zone length d with h(eps + d) = h0 by the secant method in log d from log_d (and log_d + span/1000),
    within span of log_d: the root of the branch through a predicted point, also where a fold of the zone end in
    eps puts a second root close by (which a bracket search can step over); -1 when the iteration leaves that
    interval or (pi - c_top - eps), stalls, or takes more than 30 steps.  Converged once a step is below 1e-13 (relative)
    or resolution (how finely log d is resolved: c = eps + d holds d to ulp(c))."""
    args = (fx, eps, s0, h0, c_top)
    top = math.log(PI - c_top - eps)
    a, b = log_d, log_d + 1e-3 * span
    if b >= top:
        return -1.0
    fa, fb = _residual(math.exp(a), args), _residual(math.exp(b), args)
    for _ in range(30):
        if fb == 0.0:
            return math.exp(b)
        if not (math.isfinite(fa) and math.isfinite(fb)):
            return -1.0
        if fb == fa:                          # flat: converged at the resolution of d, else stalled
            return math.exp(b) if abs(b - a) <= 4 * max(resolution, 1e-13 * max(1.0, abs(b))) else -1.0
        c = b - fb * (b - a) / (fb - fa)
        if not abs(c - log_d) <= span or c >= top:
            return -1.0
        a, fa, b = b, fb, c
        if abs(b - a) <= max(1e-13 * max(1.0, abs(b)), resolution):
            return math.exp(b)
        fb = _residual(math.exp(b), args)
    return -1.0
