"""numba kernels of numerics.arcs: what is read off a solved collocation system -- moments of the density and the
unit cases [P*, B*, k_bot, k_top] of numerics.arcs.Linear."""
import math

import numpy as np
from numba import njit

PI = math.pi


@njit(cache=True)
def moment(v, f, n, na, D, mu):
    """arcs.Arcs.moments: sum over the arcs of int u F ds/sqrt(1 - s^2), f (na n) = F at the nodes of each arc,
    v the unknown vector (node values, then the enrichment coefficients); mu (m, n): mu_j[:n]."""
    m = mu.shape[0]
    fhat = np.empty(n)
    out = 0.0
    for ia in range(na):
        a1 = 0.0
        for k in range(n):
            a1 += v[ia * n + k] * f[ia * n + k]
        out += PI / n * a1
        if m:
            for r in range(n):
                a2 = 0.0
                for k in range(n):
                    a2 += D[r, k] * f[ia * n + k]
                fhat[r] = a2
            sj = 0.0
            for j in range(m):
                a3 = 0.0
                for r in range(n):
                    a3 += mu[j, r] * fhat[r]
                sj += v[na * n + ia * m + j] * a3
            out += sj
    return out


@njit(cache=True)
def unit_q(lu, piv, U, ac, ae, s, D, mu, gend, scale):
    """(sign of det, U / scale, q) after LAPACK dgesv (lu, 1-based piv) of arcs.Linear: q[:, col] =
    [P*, B*, k_bot, k_top] of the column col of U / scale (arcs.Arcs.moments of cos and 1, arcs.Arcs.edge)."""
    n = s.size
    na = ac.size
    m = mu.shape[0]
    nc = U.shape[1]
    sgn = 1.0
    for i in range(piv.size):
        if piv[i] != i + 1:
            sgn = -sgn
        dii = lu[i, i]
        sgn *= 1.0 if dii > 0 else (-1.0 if dii < 0 else 0.0)
    Us = U / scale
    q = np.zeros((4, nc))
    fc = np.empty(na * n)
    f1 = np.ones(na * n)
    for ia in range(na):
        for k in range(n):
            fc[ia * n + k] = math.cos(ac[ia] + ae[ia] * s[k])
    for col in range(nc):
        v = np.ascontiguousarray(Us[:, col])
        q[0, col] = moment(v, fc, n, na, D, mu)
        q[1, col] = moment(v, f1, n, na, D, mu)
        for ia in range(na):
            tot = 0.0
            for r in range(n):
                for k in range(n):
                    tot += D[r, k] * v[ia * n + k]
            en = 0.0
            for j in range(m):
                en += v[na * n + ia * m + j] * gend[j]
            q[2 + ia, col] = -(tot + en) / math.sqrt(2 * ae[ia])
    return sgn, Us, q
