"""numba kernels of numerics.arcs: the enrichment columns (arcs_enrich) at points off the collocation table --
the gap evaluation of numerics.arcs.Arcs.enrichment and numerics.one_arc_kernels (fine-grid quadrature near an
arc, the nodes' quadrature weights far from it)."""
import math

import numpy as np
from numba import njit

from .arc_angles import arc_trig as _arc_trig
from .arcs_kernels import NEAR_ARC, PI, _ell, _same_arc_enrichment, _sign, _wrap


@njit(cache=True, inline="always")
def _full(t, k0, k1, ar):
    ct, st = math.cos(t), math.sin(t)
    return ct * math.log(2 - 2 * ct) + k1 * ct + k0 + ar * (PI * _sign(t) * st - t * st)


@njit(cache=True)
def enrichment(centres, offsets, ac, ae, s, k0, k1, ar, table, Lam, Sig, omega, gcs, gss, sfine, gfine,
               out, col0):
    """out[:, col0 + ia m + j] = the enrichment block of arc ia (arcs.Arcs.enrichment, negated as there).

    Lam, Sig: (m, n + m, K) tables; omega: (m, n) = D^T mu_j; gcs, gss: (na, K) trig coefficients of the arcs;
    sfine, gfine: the fine grid and g_j on it (for points near an arc, table=False)."""
    npt = centres.size
    n = s.size
    na = ac.size
    m = omega.shape[0]
    nf = sfine.size
    nt = n + m
    reg = np.empty(n)
    acc = np.empty(m)
    trig = np.empty((4, nf))
    for ia in range(na):
        c, e = ac[ia], ae[ia]
        loge = math.log(e)
        # several points near this arc: cos/sin of the fine-grid angles once, then angle addition per point
        near = 0
        if not table:
            for i in range(npt):
                di = offsets[i] if centres[i] == c else _wrap(centres[i] - c) + offsets[i]
                if abs(di / e) < NEAR_ARC:
                    near += 1
        if near > 1:
            _arc_trig(e, sfine, trig)
        for i in range(npt):
            if centres[i] == c:
                di = offsets[i]
            else:
                di = _wrap(centres[i] - c) + offsets[i]
            is_row = table and (ia * nt <= i < (ia + 1) * nt)
            if is_row:
                p = i - ia * nt
                for k in range(n):
                    t = di - e * s[k]
                    ct, st = math.cos(t), math.sin(t)
                    reg[k] = ct * (2 * loge + _ell(t)) + k1 * ct + k0 - ar * t * st
                ce, se = math.cos(di), math.sin(di)
                for j in range(m):
                    a1 = 0.0
                    for k in range(n):
                        a1 += reg[k] * omega[j, k]
                    out[i, col0 + ia * m + j] = -_same_arc_enrichment(a1, Lam, Sig, gcs, gss, j, p, ia, ce, se, ar)
            elif (not table) and abs(di / e) < NEAR_ARC:
                for j in range(m):
                    acc[j] = 0.0
                cd, sd = math.cos(di), math.sin(di)
                cd2, sd2 = math.cos(0.5 * di), math.sin(0.5 * di)
                for q in range(nf):
                    t = di - e * sfine[q]
                    if near > 1:     # _full(t) with log(2 - 2 cos t) = 2 log|2 sin(t/2)|: one log
                        ct = cd * trig[0, q] + sd * trig[1, q]
                        st = sd * trig[0, q] - cd * trig[1, q]
                        s2 = sd2 * trig[2, q] - cd2 * trig[3, q]
                        f = 2 * ct * math.log(abs(2 * s2)) + k1 * ct + k0 + ar * (PI * _sign(t) * st - t * st)
                    else:
                        f = _full(t, k0, k1, ar)
                    kf = f * (PI / nf)
                    for j in range(m):
                        acc[j] += kf * gfine[j, q]
                for j in range(m):
                    out[i, col0 + ia * m + j] = -acc[j]
            else:
                for j in range(m):
                    acc[j] = 0.0
                for k in range(n):
                    f = _full(di - e * s[k], k0, k1, ar)
                    for j in range(m):
                        acc[j] += f * omega[j, k]
                for j in range(m):
                    out[i, col0 + ia * m + j] = -acc[j]
