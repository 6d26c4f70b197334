"""numba kernels of the Maugis-Dugdale solver (jkrcyl.numerics.cohesive): LU solves, zone displacements and
the zone-end residual h(c) - h0 with its root, all compiled (no BLAS call: small threaded BLAS calls leave
OpenBLAS workers spinning and slow the many small solves of a root search by 100x on a loaded machine).

Notation as jkrcyl.numerics.cohesive: a fixed contact |phi| < eps with the collocation matrix of
jkrcyl.numerics.arcs (unknowns u: node values, then the alpha* enrichment), the contact unknown v = nu + s0,
zones (lo, hi) rows in [-pi, pi].  A fixed contact is the tuple
fx = (lu, perm, phi_nodes, U0, U1, k_unit0, k_unit1, k_adjoint, k0, k1, ar, ac, ae, s, D, Lam, Sig, omega, gcs, gss,
      s_fine, g_fine, layered, eps, x_table, gc, gs, qmax, smooth)
(its LU, collocation angles, the clearance and approach solutions, their edge coefficients, the adjoint of the
edge coefficient, the kernel constants and the tables of jkrcyl.numerics.arcs; then whether the Dugdale end layer
of the bottom zone is subtracted (jkrcyl.numerics.cohesive_layer), the half-width, the table points phi/eps, the
Chebyshev coefficients of cos(eps s), sin(eps s), their last index and the layer's smooth-moment table).
Every array of fx is built by jkrcyl.numerics.cohesive.FixedContact, which checks their sizes against each other
before any kernel runs; arrays from a caller (angles, zones, u) are checked there too.
"""
import math

import numpy as np
from numba import njit

from ..generated import cohesive as _gc
from . import arcs_kernels as _ak
from . import cohesive_layer as _cl
from . import enrichment_kernels as _ek

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
def layer_end(fx, zones):
    """The bottom zone end c > eps whose end layer the fixed contact subtracts, or -1 (none: not layered, no zone,
    or zones 'all')."""
    if not fx[22] or zones.shape[0] == 0:
        return -1.0
    lo, hi = zones[0, 0], zones[0, 1]
    if lo == -hi and fx[23] < hi < PI:
        return hi
    return -1.0


@njit(cache=True)
def zone_rhs(fx, zones):
    """The right-hand side of a unit zone traction at the table points: -Z, plus the potential of the end layer
    v_s when it is subtracted (then the solution is w = v - v_s)."""
    phin, k0, k1, ar = fx[2], fx[8], fx[9], fx[10]
    rz = -zone_sum(phin, zones, k0, k1, ar)
    c = layer_end(fx, zones)
    if c > 0:
        rz += _cl.potential(fx[24], fx[23], c, k0, k1, ar, fx[25], fx[26], fx[27], fx[28], fx[13].size)
    return rz


@njit(cache=True)
def solve_zone(fx, zones, s0):
    """(delta/Delta, u) of the fixed contact fx with the zones: k = 0 eliminates delta (module docstring); u
    without the end layer when it is subtracted (layer_end)."""
    (lu, perm, phin, U0, U1, ku0, ku1, kadj, k0, k1, ar) = fx[:11]
    rz = zone_rhs(fx, zones)
    kz = 0.0
    for i in range(rz.size):
        kz += kadj[i] * rz[i]
    dn = -(ku0 + s0 * kz) / ku1
    uz = lu_solve(lu, perm, rz)
    return dn, U0 + dn * U1 + s0 * uz


@njit(cache=True)
def gap_rows(fx, phi):
    """Rows u -> -int_contact v K(phi - psi) dpsi at exterior angles phi (arcs.Arcs.operator, .enrichment; the
    enrichment columns within END_NEAR eps of a contact end by end_enrichment)."""
    (k0, k1, ar, ac, ae, s, D, Lam, Sig, omega, gcs, gss, sfine, gfine) = fx[8:22]
    n, m = s.size, omega.shape[0]
    rows = np.empty((phi.size, n + m))
    cen = np.zeros(phi.size)
    _ak.operator(cen, phi, ac, ae, s, D, k0, k1, ar, rows, 0)
    if m:
        _ek.enrichment(cen, phi, ac, ae, s, k0, k1, ar, False, Lam, Sig, omega, gcs, gss, sfine, gfine, rows, n)
        e = ae[0]
        for i in range(phi.size):
            x = abs(phi[i]) / e
            if 1.0 < x < 1.0 + END_NEAR:
                end_enrichment(x, e, k0, k1, ar, rows[i, n:n + m])
    return rows


END_NEAR = 0.6           # gap_rows: the enrichment columns by end_enrichment up to x = 1.6 (the engine's NEAR_ARC)
_GX, _GW = np.polynomial.legendre.leggauss(12)


@njit(cache=True)
def end_enrichment(x, e, k0, k1, ar, out):
    """out[j] = -int_0^pi K(e (x - cos theta)) g_j(cos theta) dtheta at 1 < x (a point off the contact end; the
    enrichment functions g_j of jkrcyl.numerics.arcs_enrich), by Gauss-Legendre on panels graded geometrically
    toward theta = 0 at the scale theta_s = sqrt(2 (x - 1)) of the kernel's near log singularity (the 4096-point
    fine grid of the engine loses digits there: ~1e-8 at x - 1 = 3e-6, ~1e-4 at 1e-7; tests/test_cohesive_layer.py)."""
    m = out.size
    for j in range(m):
        out[j] = 0.0
    ths = math.sqrt(2.0 * (x - 1.0))
    # panels: geometric toward 0 from min(ths/16, 1e-4) to pi/2 (g_j ~ theta^2 log(theta) at 0), and toward pi
    # from pi/2 to pi - 1e-5 (g_j ~ (pi - theta)^2 log(pi - theta) there), each with 12 Gauss-Legendre points
    a = min(ths / 16, 1e-4)
    k = 0
    while True:
        if k == 0:
            lo, hi = 0.0, a
        elif lo < PI / 2:
            lo, hi = hi, min(2 * hi, PI / 2)
        else:
            lo = hi
            hi = PI if PI - lo <= 2e-5 else PI - 0.5 * (PI - lo)
        k += 1
        for q in range(_GX.size):
            th = lo + (hi - lo) * 0.5 * (_GX[q] + 1)
            wq = (hi - lo) * 0.5 * _GW[q]
            sv = math.cos(th)
            t = e * (x - sv)
            ct, st = math.cos(t), math.sin(t)
            f = 2 * ct * math.log(abs(2 * math.sin(0.5 * t))) + k1 * ct + k0 + ar * (PI * st - t * st)
            rp, rm = 1 - sv, 1 + sv
            xp = rp * math.log(rp) if rp > 0 else 0.0
            xm = rm * math.log(rm) if rm > 0 else 0.0
            g0, g1, g2 = xp + xm, rp * xp + rm * xm, xp * xp + xm * xm
            out[0] -= wq * f * g0
            if m > 1:
                out[1] -= wq * f * g1
            if m > 2:
                out[2] -= wq * f * g2
        if hi >= PI:
            break


@njit(cache=True)
def gap(fx, phi, dn, u, zones, s0):
    """h/Delta at exterior angles phi: (1 - cos) - (delta/Delta) cos - int v K + s0 Z (v = w + v_s: u is w and
    -s0 Q(phi/eps) adds the end layer's part when it is subtracted)."""
    k0, k1, ar = fx[8], fx[9], fx[10]
    rows = gap_rows(fx, phi)
    zs = zone_sum(phi, zones, k0, k1, ar)
    out = np.empty(phi.size)
    for i in range(phi.size):
        acc = 0.0
        for j in range(u.size):
            acc += rows[i, j] * u[j]
        out[i] = 2 * math.sin(phi[i] / 2) ** 2 - dn * math.cos(phi[i]) + acc + s0 * zs[i]
    c = layer_end(fx, zones)
    if c > 0 and s0 != 0.0:
        e = fx[23]
        q = _cl.potential(phi / e, e, c, k0, k1, ar, fx[25], fx[26], fx[27], np.zeros((0, _cl.N_SMOOTH)))
        for i in range(phi.size):
            out[i] -= s0 * q[i]
    return out


@njit(cache=True)
def zone_totals(fx, zones, s0):
    """(load, width) of the zone traction -s0 with the end layer's v_s (int cos, int 1): what p and B add to
    ep.u and eb.u."""
    load = width = 0.0
    for j in range(zones.shape[0]):
        z = _gc.zone_load(hi=zones[j, 1], lo=zones[j, 0])
        load += z.load
        width += z.width
    c = layer_end(fx, zones)
    lp = lb = 0.0
    if c > 0:
        lp, lb = _cl.loads(fx[23], c, fx[25])
    return s0 * (lp - load), s0 * (lb - width)


@njit(cache=True)
def affine(fx, ek, ep, eb, c, s0, h0):
    """k, p, B and g = h(c) - h0 at the zone end c (c >= pi: zones 'all', g = NaN), each as the value at
    delta = 0 and its slope in delta/Delta (all linear in delta): one zone solve and one gap row."""
    lu, perm, U0, U1 = fx[0], fx[1], fx[3], fx[4]
    zones = zones_of(min(c, PI), 0.0)
    ua = U0 + s0 * lu_solve(lu, perm, zone_rhs(fx, zones))
    pz, bz = zone_totals(fx, zones, s0)
    out = np.empty(8)
    out[0], out[1] = np.dot(ek, ua), np.dot(ek, U1)
    out[2], out[3] = np.dot(ep, ua) + pz, np.dot(ep, U1)
    out[4], out[5] = np.dot(eb, ua) + bz, np.dot(eb, U1)
    out[6] = out[7] = math.nan
    if c < PI:
        row = gap_rows(fx, np.array([c]))[0]
        out[6] = gap(fx, np.array([c]), 0.0, ua, zones, s0)[0] - h0
        out[7] = np.dot(row, U1) - math.cos(c)
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
