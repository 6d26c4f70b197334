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


def _times_T(c, k):
    """Chebyshev coefficients of T_k g from those of g (T_k T_m = (T_{m+k} + T_|m-k|)/2), truncated."""
    out = np.zeros_like(c)
    M = c.size
    out[k:] += 0.5 * c[:M - k]
    idx = np.abs(np.arange(M) - k)
    np.add.at(out, idx, 0.5 * c)
    return out


@functools.lru_cache(maxsize=None)
def tables(n, x_key):
    """Per node count: Lam[j][p, k] = int log|x_p - s| T_k g_j w ds, Sig[j][p, k] (sign), mu[j][m] = int T_m g_j w.

    x_key: tuple of the table points x_p (the collocation points of one arc, in [-1, 1])."""
    x = np.array(x_key)
    th = np.arccos(np.clip(x, -1, 1))
    m = np.arange(1, M_FINE)
    LM = np.empty((x.size, M_FINE))
    SM = np.empty((x.size, M_FINE))
    LM[:, 0] = -math.pi * LOG2
    SM[:, 0] = math.pi - 2 * th
    LM[:, 1:] = -math.pi * np.cos(np.outer(th, m)) / m
    SM[:, 1:] = -2 * np.sin(np.outer(th, m)) / m
    C = _coefficients()
    Lam, Sig, mu = [], [], []
    # one BLAS thread: threaded products here leave OpenBLAS workers spinning for ~0.1 s afterwards, which on
    # a small machine halves the speed of the many small solves that follow a fresh table
    with threadpool_limits(limits=1, user_api="blas"):
        for j in range(N_ENRICH):
            P = np.array([_times_T(C[j], k) for k in range(K_TRIG)])       # K x M
            Lam.append(LM @ P.T)
            Sig.append(SM @ P.T)
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
