"""numba kernels of numerics.one_arc: the bordered one-arc system assembled, solved and read in one call per
contact parameter, and the per-point slopes, for whole arrays of contact parameters (no Python per point).

Same mathematics as numerics.one_arc.OneArc (the reference the tests compare with): the collocation matrix of
numerics.arcs_kernels.assemble, bordered by the edge row; moments of cos, 1 and dx/dphi; the gap row at phi = pi.
One arc centred at phi = 0 is symmetric (the kernel and both right-hand sides are even), so the density is even:
u(s_k) = u(s_{n-1-k}) at the mirrored Gauss nodes and the enrichment functions are even already.  The kernels
therefore collocate at the table points x >= 0 only and fold the node columns k, n - 1 - k: half the rows to
assemble, an eighth of the LU, the same solution (tests: equal to the full system to rounding).
The Chebyshev coefficients of cos(e s), sin(e s) (numerics.arcs_enrich.trig_coefficients, Jacobi-Anger) come from
the power series of J_k(e), e <= pi (no scipy in numba).
"""
import math

import numpy as np
from numba import njit

from . import arcs_kernels as _ak
from . import enrichment_kernels as _ek

PI = math.pi
# the fields of one state: p, B*, d, h(pi), k, C*, p_k, d_k (numerics.one_arc.ArcState)
N_OUT = 8


@njit(cache=True)
def bessel_j(k, x):
    """J_k(x) for 0 <= x <= pi by its power series (the terms fall from m ~ x/2 on; 1e-17 relative)."""
    half = 0.5 * x
    term = 1.0
    for j in range(1, k + 1):
        term *= half / j
    total = term
    for m in range(1, 80):
        term *= -half * half / (m * (m + k))
        total += term
        if abs(term) <= 1e-17 * abs(total):
            break
    return total


@njit(cache=True)
def trig_coefficients(e, gc, gs):
    """Chebyshev coefficients of cos(e s) and sin(e s) into gc, gs (length K): numerics.arcs_enrich."""
    for k in range(gc.size):
        J = bessel_j(k, e)
        sign = -1.0 if (k // 2) % 2 == 1 else 1.0
        gc[k] = J if k == 0 else (2 * sign * J if k % 2 == 0 else 0.0)
        gs[k] = 2 * sign * J if k % 2 == 1 else 0.0


@njit(cache=True)
def bordered_state_even(e, k_target, clearance, s, D, xt, LD0, SD0, Lam, Sig, omega, gend, sf, gf, k0, k1, ar,
                        K, out):
    """One arc of half-width e on the even half (module docstring): out[:] = (p, B*, d, h(pi), k, C*, p_k, d_k)
    (numerics.one_arc.ArcState); xt, LD0, SD0, Lam, Sig restricted to the table points x >= 0
    (numerics.one_arc._half_tables), the node columns folded."""
    n = s.size
    m = omega.shape[0]
    nh = (n + 1) // 2                      # node columns k < nh (k = n - 1 - k for the middle node, n odd)
    N = nh + m
    ac, ae = np.zeros(1), np.full(1, e)
    gcs, gss = np.zeros((1, K if m else 0)), np.zeros((1, K if m else 0))
    if m:
        trig_coefficients(e, gcs[0], gss[0])
    A = np.empty((xt.size, n + m))
    rhs = np.empty((xt.size, 2))
    _ak.assemble(ac, ae, s, D, k0, k1, ar, xt, LD0, SD0, Lam, Sig, omega, gcs, gss, A, rhs, np.zeros((1, 0, n)))
    r = 1.0 / math.sqrt(2 * e)
    edge = np.empty(n + m)
    for k in range(n):
        col = 0.0
        for q in range(n):
            col += D[q, k]
        edge[k] = -col * r
    for j in range(m):
        edge[n + j] = -gend[j] * r
    mom = np.zeros((3, n + m))
    for k in range(n):
        ph = e * s[k]
        t = math.tan(0.5 * ph)
        f = (math.cos(ph), 1.0, 0.5 * (1 + t * t))
        for q in range(3):
            mom[q, k] = PI / n * f[q]
            for j in range(m):
                mom[q, n + j] += omega[j, k] * f[q]
    g = np.zeros((1, n + m))
    cen, off = np.zeros(1), np.full(1, PI)
    _ak.operator(cen, off, ac, ae, s, D, k0, k1, ar, g, 0)
    if m:
        _ek.enrichment(cen, off, ac, ae, s, k0, k1, ar, False, Lam, Sig, omega, gcs, gss, sf, gf, g, n)
    # fold: column k of the half system = columns k and n - 1 - k of the full one (the same unknown)
    B = np.zeros((N + 1, N + 1))
    rows = np.zeros((5, N))                # edge, moments (cos, 1, dx/dphi), gap at pi
    for c in range(N):
        full = c if c < nh else n + (c - nh)
        twin = n - 1 - c if c < nh and n - 1 - c != c else -1
        for i in range(xt.size):
            B[i, c] = A[i, full] + (A[i, twin] if twin >= 0 else 0.0)
        rows[0, c] = edge[full] + (edge[twin] if twin >= 0 else 0.0)
        for q in range(3):
            rows[1 + q, c] = mom[q, full] + (mom[q, twin] if twin >= 0 else 0.0)
        rows[4, c] = g[0, full] + (g[0, twin] if twin >= 0 else 0.0)
    for i in range(N):
        B[i, N] = -rhs[i, 1]
        B[N, i] = rows[0, i]
    R = np.zeros((N + 1, 2))
    for i in range(N):
        R[i, 0] = clearance * rhs[i, 0]
    R[N, 0] = k_target
    R[N, 1] = 1.0
    try:
        X = np.linalg.solve(B, R)
    except Exception:          # exactly singular: the receding-contact pole itself (p, delta -> inf)
        out[:] = np.inf
        return
    p = B_ = C = kk = gv = pk = 0.0
    for i in range(N):
        v, vk = X[i, 0], X[i, 1]
        kk += rows[0, i] * v
        p += rows[1, i] * v
        B_ += rows[2, i] * v
        C += rows[3, i] * v
        gv += rows[4, i] * v
        pk += rows[1, i] * vk
    d = X[N, 0]
    out[0], out[1], out[2], out[3] = p, B_, d, 2 * clearance + d + gv
    out[4], out[5], out[6], out[7] = kk, C, pk, X[N, 1]


@njit(cache=True)
def arc_states(a, k_target, clearance, pole, rel_step, s, D, xt, LD0, SD0, Lam, Sig, omega, gend, sf, gf, k0,
               k1, ar, K):
    """States (N_OUT columns, as bordered_state_even) and slopes dp/da, dd/da at every contact parameter a[i] (all at
    the node count of the tables given): central differences of the physical state at a +- h,
    h = rel_step min(a, |a - pole|) (numerics.one_arc.arc_states)."""
    out = np.empty((a.size, N_OUT))
    slopes = np.empty((a.size, 2))
    plus, minus = np.empty(N_OUT), np.empty(N_OUT)
    for i in range(a.size):
        ai = a[i]
        bordered_state_even(2 * math.atan(ai), k_target, clearance, s, D, xt, LD0, SD0, Lam, Sig, omega, gend,
                            sf, gf, k0, k1, ar, K, out[i])
        h = rel_step * min(ai, abs(ai - pole))
        bordered_state_even(2 * math.atan(ai + h), k_target, clearance, s, D, xt, LD0, SD0, Lam, Sig, omega, gend,
                            sf, gf, k0, k1, ar, K, plus)
        bordered_state_even(2 * math.atan(ai - h), k_target, clearance, s, D, xt, LD0, SD0, Lam, Sig, omega, gend,
                            sf, gf, k0, k1, ar, K, minus)
        slopes[i, 0] = (plus[0] - minus[0]) / (2 * h)
        slopes[i, 1] = (plus[2] - minus[2]) / (2 * h)
    return out, slopes
