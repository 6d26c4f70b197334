"""End enrichment of the arc collocation for alpha* != 0 (used by jkrcyl.numerics.arcs).

The alpha* part of the kernel, pi alpha* sin|t|, has a kink at t = 0.  Acting on the square-root density it
feeds (1 - s)^(3/2) terms back into the log equation, whose inverse answers with (1 - s)^k log^j(1 - s) terms
in u (nu dphi = u(s) ds/sqrt(1 - s^2)): a polynomial u then converges only like n^-2 at the ends.  The
enriched unknown is u = polynomial + sum_j c_j g_j(s) with the even end functions below; the operator acts
on g_j through tables computed once per node count (Chebyshev coefficients of g_j to degree 2^16, exact
log and sign moments of T_k g_j), the smooth part of the kernel through quadrature weights for g_j w.
"""
import functools
import math

import numpy as np
from scipy.fft import dct
from scipy.special import jv
from numba import njit
from threadpoolctl import threadpool_limits

M_FINE = 2 ** 16           # Chebyshev degree of the g_j tables (aliasing error ~ M^-3 relative)
K_TRIG = 34                # Chebyshev terms of cos(e s), sin(e s) for e <= pi (J_34(pi) ~ 1e-32)
LOG2 = math.log(2.0)


def _xlogx(r):
    return np.where(r > 0, r * np.log(np.where(r > 0, r, 1.0)), 0.0)


def _g(s):
    """The enrichment functions (even in s), rows j = 0, 1, 2."""
    rp, rm = 1 - s, 1 + s
    return np.array([_xlogx(rp) + _xlogx(rm),
                     rp * _xlogx(rp) + rm * _xlogx(rm),
                     _xlogx(rp) ** 2 + _xlogx(rm) ** 2])


N_ENRICH = 3
G_END = _g(np.array([1.0]))[:, 0]          # g_j(1): enters the edge coefficient


@functools.lru_cache(maxsize=None)
def _coefficients():
    """Chebyshev coefficients of g_j to degree M_FINE (DCT-II at the first-kind points)."""
    th = (np.arange(M_FINE) + 0.5) * np.pi / M_FINE
    vals = _g(np.cos(th))
    c = dct(vals, type=2, axis=1) / M_FINE
    c[:, 0] /= 2
    return c


@njit(cache=True)
def _folded(c, k_trig, period):
    """Per (j, k): F[j, k, r] = sum over m = r (mod period) of P_jk[m]/m (m >= 1) and G[j, k, r] = the same
    of P_jk[m] (m >= 0), P_jk the Chebyshev coefficients of T_k g_j truncated at the length M of c[j]
    (T_k T_m = (T_{m+k} + T_|m-k|)/2; the three terms added in the order of the former dense tables)."""
    nj, M = c.shape
    F = np.zeros((nj, k_trig, period))
    G = np.zeros((nj, k_trig, period))
    for j in range(nj):
        for k in range(k_trig):
            r = 0
            for i in range(M):
                v = 0.0
                if i >= k:
                    v += 0.5 * c[j, i - k]
                if 1 <= i <= k:
                    v += 0.5 * c[j, k - i]
                if i + k < M:
                    v += 0.5 * c[j, i + k]
                G[j, k, r] += v
                if i > 0:
                    F[j, k, r] += v * (1.0 / i)
                r += 1
                if r == period:
                    r = 0
    return F, G


def table_points(n):
    """The points of the tables for n nodes: the Gauss-Chebyshev nodes, then the N_ENRICH end points
    cos(i pi/(2 n N_ENRICH)) (the extra collocation points of jkrcyl.numerics.arcs).  All lie on the angle
    grid theta = q pi/(2 n N_ENRICH); returned: x and the grid indices q."""
    big = 2 * n * N_ENRICH
    q = np.concatenate([N_ENRICH * (2 * np.arange(1, n + 1) - 1), np.arange(N_ENRICH)])
    x = np.concatenate([np.cos((2 * np.arange(1, n + 1) - 1) * np.pi / (2 * n)),
                        np.cos(np.arange(N_ENRICH) * np.pi / big)])
    return x, q


@functools.lru_cache(maxsize=None)
def tables(n):
    """Per node count: Lam[j][p, k] = int log|x_p - s| T_k g_j w ds, Sig[j][p, k] (sign), mu[j][m] = int T_m g_j w,
    at the points x_p of :func:`table_points`.

    With theta = arccos x the moments are -pi log 2 b_0 - pi sum_m b_m cos(m theta)/m and
    b_0 (pi - 2 theta) - 2 sum_m b_m sin(m theta)/m (b = P_jk, M_FINE terms).  The points lie on the grid
    theta_q = q pi/N (N = 2 n N_ENRICH), where cos(m theta_q) depends on m mod 2N only: the coefficients are
    folded mod 2N (O(M)) and the series summed over N + 1 terms per point, phases reduced exactly in
    integers.  arccos(x_p) differs from theta_q by the rounding of x_p (up to ~1e-13 next to s = 1): the
    first-order term in that difference (the derivatives, series of b_m without 1/m) is added, so that the
    tables are those at the stored x_p, as the dense sums over all M terms were (to ~1e-15 relative).
    """
    x, q = table_points(n)
    N = 2 * n * N_ENRICH
    th = np.arccos(np.clip(x, -1, 1))
    dth = th - q * (math.pi / N)
    ph = (np.outer(q, np.arange(N + 1)) % (2 * N)) * (math.pi / N)
    cos_ph, sin_ph = np.cos(ph), np.sin(ph)
    C = _coefficients()
    F, G = _folded(C, K_TRIG, 2 * N)
    b0 = 0.5 * C[:, :K_TRIG]                   # P_jk[0] = c_k/2 (k > 0), c_0 (k = 0)
    b0[:, 0] = C[:, 0]
    # even (cos) and odd (sin) combinations of the residues r and 2N - r, r = 0..N
    even = lambda A: np.concatenate([A[..., :1], A[..., 1:N] + A[..., 2 * N - 1:N:-1], A[..., N:N + 1]], -1)
    odd = lambda A: np.concatenate([0 * A[..., :1], A[..., 1:N] - A[..., 2 * N - 1:N:-1], 0 * A[..., :1]], -1)
    Lam, Sig, mu = [], [], []
    # one BLAS thread: threaded products here leave OpenBLAS workers spinning for ~0.1 s afterwards, which on
    # a small machine halves the speed of the many small solves that follow a fresh table
    with threadpool_limits(limits=1, user_api="blas"):
        for j in range(N_ENRICH):
            p0 = b0[j]
            L = -math.pi * (cos_ph @ even(F[j]).T) - math.pi * LOG2 * p0[None, :]
            L += dth[:, None] * (math.pi * (sin_ph @ odd(G[j]).T))
            S = -2 * (sin_ph @ odd(F[j]).T) + np.outer(math.pi - 2 * th, p0)
            S += dth[:, None] * (-2 * (cos_ph @ even(G[j]).T - p0[None, :]))
            Lam.append(L)
            Sig.append(S)
            mu.append(np.where(np.arange(n) == 0, math.pi, math.pi / 2) * C[j][:n])
    return Lam, Sig, mu


def trig_coefficients(e):
    """gamma_c, gamma_s: Chebyshev coefficients of cos(e s) and sin(e s) (Jacobi-Anger), K_TRIG terms."""
    k = np.arange(K_TRIG)
    J = jv(k, e)
    sgn = (-1.0) ** (k // 2)
    gc = np.where(k % 2 == 0, 2 * sgn * J, 0.0)
    gc[0] = J[0]
    gs = np.where(k % 2 == 1, 2 * sgn * J, 0.0)
    return gc, gs
