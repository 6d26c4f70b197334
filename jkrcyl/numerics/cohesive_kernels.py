"""numba kernels of the Maugis-Dugdale solver (jkrcyl.numerics.cohesive): LU solves, zone displacements and
the zone-end residual h(c) - h0 with its root, all compiled (no BLAS call: small threaded BLAS calls leave
OpenBLAS workers spinning and slow the many small solves of a root search by 100x on a loaded machine).

Notation as jkrcyl.numerics.cohesive: a fixed contact |phi| < eps with the collocation matrix of
jkrcyl.numerics.arcs (unknowns u: node values, then the alpha* enrichment), the contact unknown v = nu + s0,
zones (lo, hi) rows in [-pi, pi].  A fixed contact is the tuple
fx = (lu, perm, phi_nodes, U0, U1, k_unit0, k_unit1, k_adjoint, k0, k1, ar, ac, ae, s, D, Lam, Sig, omega, gcs, gss,
      s_fine, g_fine)
(its LU, collocation angles, the clearance and approach solutions, their edge coefficients, the adjoint of the
edge coefficient, the kernel constants and the tables of jkrcyl.numerics.arcs).
"""
import math

import numpy as np
from numba import njit

from ..generated import cohesive as _gc
from . import arcs_kernels as _ak
from . import enrichment_kernels as _ek
from . import roots

PI = math.pi


@njit(cache=True)
def lu_factor(A):
    """LU with partial pivoting of a copy of A: (lu, perm) with A[perm] = L U (L unit lower)."""
    n = A.shape[0]
    lu = A.copy()
    perm = np.arange(n)
    for k in range(n):
        p = k
        big = abs(lu[k, k])
        for i in range(k + 1, n):
            if abs(lu[i, k]) > big:
                big, p = abs(lu[i, k]), i
        if p != k:
            for j in range(n):
                lu[k, j], lu[p, j] = lu[p, j], lu[k, j]
            perm[k], perm[p] = perm[p], perm[k]
        piv = lu[k, k]
        if piv == 0.0:
            continue
        for i in range(k + 1, n):
            f = lu[i, k] / piv
            lu[i, k] = f
            if f != 0.0:
                for j in range(k + 1, n):
                    lu[i, j] -= f * lu[k, j]
    return lu, perm


@njit(cache=True)
def lu_solve(lu, perm, b):
    """x with A x = b."""
    n = b.size
    x = np.empty(n)
    for i in range(n):
        x[i] = b[perm[i]]
    for i in range(n):
        acc = x[i]
        for j in range(i):
            acc -= lu[i, j] * x[j]
        x[i] = acc
    for i in range(n - 1, -1, -1):
        acc = x[i]
        for j in range(i + 1, n):
            acc -= lu[i, j] * x[j]
        x[i] = acc / lu[i, i]
    return x


@njit(cache=True)
def lu_solve_transposed(lu, perm, b):
    """y with A^T y = b (the adjoint: a linear functional of the solution as a dot product with the rhs)."""
    n = b.size
    z = b.copy()
    for i in range(n):                      # U^T z = b
        acc = z[i]
        for j in range(i):
            acc -= lu[j, i] * z[j]
        z[i] = acc / lu[i, i]
    for i in range(n - 1, -1, -1):          # L^T w = z
        acc = z[i]
        for j in range(i + 1, n):
            acc -= lu[j, i] * z[j]
        z[i] = acc
    y = np.empty(n)
    for i in range(n):
        y[perm[i]] = z[i]
    return y


@njit(cache=True)
def zone_sum(phi, zones, k0, k1, ar):
    """Z(phi_i) = sum over the zones (lo, hi) of int_lo^hi K(phi_i - psi) dpsi (closed form)."""
    out = np.empty(phi.size)
    for i in range(phi.size):
        acc = 0.0
        for j in range(zones.shape[0]):
            acc += _gc.zone_displacement(ar=ar, hi=zones[j, 1], k0=k0, k1=k1, lo=zones[j, 0], phi=phi[i])
        out[i] = acc
    return out


@njit(cache=True)
def zones_of(c, c_top=0.0):
    """Rows (lo, hi): the bottom zone |phi| < c and the top zone |phi - pi| < c_top (two rows, split at pi), or the
    whole circle when they meet (c + c_top >= pi)."""
    if c + c_top >= PI:
        z = np.empty((1, 2))
        z[0, 0], z[0, 1] = -PI, PI
        return z
    rows = (1 if c > 0 else 0) + (2 if c_top > 0 else 0)
    z = np.empty((rows, 2))
    i = 0
    if c > 0:
        z[0, 0], z[0, 1] = -c, c
        i = 1
    if c_top > 0:
        z[i, 0], z[i, 1] = PI - c_top, PI
        z[i + 1, 0], z[i + 1, 1] = -PI, -PI + c_top
    return z


@njit(cache=True)
def solve_zone(fx, zones, s0):
    """(delta/Delta, u) of the fixed contact fx with the zones: k = 0 eliminates delta (module docstring)."""
    (lu, perm, phin, U0, U1, ku0, ku1, kadj, k0, k1, ar) = fx[:11]
    rz = -zone_sum(phin, zones, k0, k1, ar)
    kz = 0.0
    for i in range(rz.size):
        kz += kadj[i] * rz[i]
    dn = -(ku0 + s0 * kz) / ku1
    uz = lu_solve(lu, perm, rz)
    return dn, U0 + dn * U1 + s0 * uz


@njit(cache=True)
def gap_rows(fx, phi):
    """Rows u -> -int_contact v K(phi - psi) dpsi at exterior angles phi (arcs.Arcs.operator, .enrichment)."""
    (k0, k1, ar, ac, ae, s, D, Lam, Sig, omega, gcs, gss, sfine, gfine) = fx[8:22]
    n, m = s.size, omega.shape[0]
    rows = np.empty((phi.size, n + m))
    cen = np.zeros(phi.size)
    _ak.operator(cen, phi, ac, ae, s, D, k0, k1, ar, rows, 0)
    if m:
        _ek.enrichment(cen, phi, ac, ae, s, k0, k1, ar, False, Lam, Sig, omega, gcs, gss, sfine, gfine, rows, n)
    return rows


@njit(cache=True)
def gap(fx, phi, dn, u, zones, s0):
    """h/Delta at exterior angles phi: (1 - cos) - (delta/Delta) cos - int v K + s0 Z."""
    k0, k1, ar = fx[8], fx[9], fx[10]
    rows = gap_rows(fx, phi)
    zs = zone_sum(phi, zones, k0, k1, ar)
    out = np.empty(phi.size)
    for i in range(phi.size):
        acc = 0.0
        for j in range(u.size):
            acc += rows[i, j] * u[j]
        out[i] = 2 * math.sin(phi[i] / 2) ** 2 - dn * math.cos(phi[i]) + acc + s0 * zs[i]
    return out


@njit(cache=True)
def _residual(d, args):
    """h(eps + d) - h0 with the zone |phi| < eps + d (F(0) = -h0: h vanishes at the contact end)."""
    fx, eps, s0, h0, c_top = args
    if d <= 0.0:
        return -h0
    c = eps + d
    zones = zones_of(c, c_top)
    dn, u = solve_zone(fx, zones, s0)
    return gap(fx, np.array([c]), dn, u, zones, s0)[0] - h0


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
def perm_of_pivots(piv):
    """LAPACK getrf row interchanges (0-based: row i swapped with piv[i], in order) as a permutation."""
    perm = np.arange(piv.size)
    for i in range(piv.size):
        j = piv[i]
        perm[i], perm[j] = perm[j], perm[i]
    return perm


@njit(cache=True)
def unit_solutions(lu, perm, phin, ek):
    """The clearance and approach solutions (rhs -(1 - cos phi) = -2 sin^2(phi/2), cos phi), their edge
    coefficients and the adjoint of the edge coefficient (k of a rhs r is kadj . r)."""
    r0 = np.empty(phin.size)
    r1 = np.empty(phin.size)
    for i in range(phin.size):
        r0[i] = -2 * math.sin(phin[i] / 2) ** 2
        r1[i] = math.cos(phin[i])
    U0, U1 = lu_solve(lu, perm, r0), lu_solve(lu, perm, r1)
    return U0, U1, lu_solve_transposed(lu, perm, ek), np.dot(ek, U0), np.dot(ek, U1)


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
def zone_end_secant(fx, eps, s0, h0, log_d, span, c_top):
    """The zone length d with h(eps + d) = h0 by the secant method in log d from log_d (and log_d + span/1000),
    within span of log_d: the root of the branch through a predicted point, also where a fold of the zone end in
    eps puts a second root close by (which a bracket search can step over); -1 when the iteration leaves that
    interval or (pi - c_top - eps), stalls, or takes more than 30 steps."""
    args = (fx, eps, s0, h0, c_top)
    top = math.log(PI - c_top - eps)
    a, b = log_d, log_d + 1e-3 * span
    if b >= top:
        return -1.0
    fa, fb = _residual(math.exp(a), args), _residual(math.exp(b), args)
    for _ in range(30):
        if fb == 0.0:
            return math.exp(b)
        if fb == fa or not (math.isfinite(fa) and math.isfinite(fb)):
            return -1.0
        c = b - fb * (b - a) / (fb - fa)
        if not abs(c - log_d) <= span or c >= top:
            return -1.0
        a, fa, b = b, fb, c
        if abs(b - a) <= 1e-13 * max(1.0, abs(b)):
            return math.exp(b)
        fb = _residual(math.exp(b), args)
    return -1.0

