"""numba kernels of the arc collocation (jkrcyl.numerics.arcs): the operator and enrichment matrices.

The formulas are those of arcs.Arcs.operator / Arcs.enrichment (see there), evaluated entry by entry in
compiled loops instead of numpy temporaries; the node-count tables (nodes, Chebyshev matrix, enrichment
tables) are passed in.  Arc geometry: arrays ac (centres), ae (half-widths); points: centres, offsets.
"""
import math

import numpy as np
from numba import njit

from .arc_angles import arc_trig as _arc_trig
from .arc_angles import ell_half as _ell_half

PI = math.pi
TWO_PI = 2 * math.pi
LOG2 = math.log(2.0)
NEAR_ARC = 1.6


@njit(cache=True, inline="always")
def _sign(t):
    return 1.0 if t > 0 else (-1.0 if t < 0 else 0.0)


@njit(cache=True, inline="always")
def _ell(t):
    """log((2 sin(t/2)/t)^2) as arcs._ell: 2 log|sinc(t/(2 pi))|."""
    u = t / TWO_PI
    if u == 0.0:
        return 0.0
    y = PI * u
    return 2 * math.log(abs(math.sin(y) / y))


@njit(cache=True, inline="always")
def _ell3(t):
    return _ell(t) - 2 * math.log(abs(t - TWO_PI)) - 2 * math.log(abs(t + TWO_PI))


@njit(cache=True, inline="always")
def _wrap(y):
    """np.angle(np.exp(1j y))."""
    return math.atan2(math.sin(y), math.cos(y))


@njit(cache=True)
def _add_log_moments(x, n, out, sgn):
    """out[m] += sgn * int log|x - s| T_m(s)/sqrt(1 - s^2) ds (arcs._log_moments)."""
    if abs(x) <= 1:
        th = math.acos(min(max(x, -1.0), 1.0))
        out[0] += sgn * (-PI * LOG2)
        for m in range(1, n):
            out[m] += sgn * (-PI * math.cos(th * m) / m)
    else:
        ax = abs(x)
        r = math.sqrt((ax - 1) * (ax + 1))
        z = _sign(x) / (ax + r)
        out[0] += sgn * (PI * math.log((ax + r) / 2))
        zm = 1.0
        for m in range(1, n):
            zm *= z
            out[m] += sgn * (-PI * zm / m)


@njit(cache=True, inline="always")
def _operator_entry(smooth, t, ct, st, LDk, SDk, kink, ar, n):
    """Operator column k at a point: Gauss-Chebyshev of the smooth kernel part plus the exact log moment
    (LDk) and, on an arc with the alpha* kink, the exact sign moment (SDk); t = phi - psi_k."""
    block = 2 * ct * LDk
    if ar != 0.0:
        smooth = smooth - ar * t * st
        if kink:
            block += ar * PI * st * SDk
        else:
            smooth += ar * PI * _sign(t) * st
    return -(smooth * (PI / n) + block)


@njit(cache=True, inline="always")
def _same_arc_enrichment(smooth, Lam, Sig, gcs, gss, j, p, ia, ce, se, ar):
    """Enrichment column j at point p of its own arc: the smooth part plus the exact log and sign moments of
    the end terms (tables Lam, Sig) against the arc's trig coefficients gcs, gss (ce, se: cos, sin of the centre
    offset)."""
    lc = 0.0
    ls = 0.0
    sc = 0.0
    ss = 0.0
    for q in range(gcs.shape[1]):
        lc += Lam[j, p, q] * gcs[ia, q]
        ls += Lam[j, p, q] * gss[ia, q]
        sc += Sig[j, p, q] * gcs[ia, q]
        ss += Sig[j, p, q] * gss[ia, q]
    return smooth + 2 * (ce * lc + se * ls) + ar * PI * (se * sc - ce * ss)


@njit(cache=True)
def _sign_moments_into(x, n, out):
    """out[m] = int_{-1}^{1} sign(x - s) T_m(s)/sqrt(1 - s^2) ds (exact): pi - 2 theta, -2 sin(m theta)/m."""
    th = math.acos(min(max(x, -1.0), 1.0))
    out[0] = PI - 2 * th
    for m in range(1, n):
        out[m] = -2 * math.sin(th * m) / m


@njit(cache=True, inline="always")
def _vecmat(v, D, out, add):
    """out (+)= v @ D (rows of D in order: the sum over q ascends as in a dot product)."""
    n = D.shape[1]
    if not add:
        for k in range(n):
            out[k] = 0.0
    for q in range(D.shape[0]):
        vq = v[q]
        for k in range(n):
            out[k] += vq * D[q, k]


@njit(cache=True)
def operator(centres, offsets, ac, ae, s, D, k0, k1, ar, out, col0):
    """out[:, col0 + ia n + k] = the operator block of arc ia (arcs.Arcs.operator, negated as there)."""
    npt = centres.size
    n = s.size
    na = ac.size
    L = np.empty(n)
    L2 = np.empty(n)
    Sg = np.empty(n)
    LD = np.empty(n)
    SD = np.empty(n)
    d = np.empty(npt)
    for ia in range(na):
        c, e = ac[ia], ae[ia]
        any_same = False
        for i in range(npt):
            if centres[i] == c:
                d[i] = offsets[i]
                any_same = True
            else:
                d[i] = _wrap(centres[i] - c) + offsets[i]
        images_on = any_same and e > 1.0
        loge = math.log(e)
        images = 2 * PI / e
        for i in range(npt):
            x = d[i] / e
            for m in range(n):
                L[m] = 0.0
            _add_log_moments(x, n, L, 1.0)
            if images_on:
                for m in range(n):
                    L2[m] = 0.0
                _add_log_moments(x - images, n, L2, 1.0)
                for m in range(n):
                    L[m] = L[m] + L2[m]
                for m in range(n):
                    L2[m] = 0.0
                _add_log_moments(x + images, n, L2, 1.0)
                for m in range(n):
                    L[m] = L[m] + L2[m]
            kink = ar != 0.0 and abs(x) < 1
            if kink:
                _sign_moments_into(x, n, Sg)
            _vecmat(L, D, LD, False)
            if kink:
                _vecmat(Sg, D, SD, False)
            for k in range(n):
                t = d[i] - e * s[k]
                ct, st = math.cos(t), math.sin(t)
                if images_on:
                    smooth = ct * (6 * loge + _ell3(t)) + k1 * ct + k0
                else:
                    smooth = ct * (2 * loge + _ell(t)) + k1 * ct + k0
                out[i, col0 + ia * n + k] = _operator_entry(smooth, t, ct, st, LD[k], SD[k], kink, ar, n)


@njit(cache=True)
def image_moments(e, xt, out):
    """out[p] = the log moments of the periodic images x -+ 2 pi/e of an arc's own row p, x = (e xt[p])/e as
    assemble forms it (arcs._image_rows multiplies them by D)."""
    images = 2 * PI / e
    n = out.shape[1]
    for p in range(xt.size):
        x = (e * xt[p]) / e
        for q in range(n):
            out[p, q] = 0.0
        _add_log_moments(x - images, n, out[p], 1.0)
        _add_log_moments(x + images, n, out[p], 1.0)


@njit(cache=True)
def assemble(ac, ae, s, D, k0, k1, ar, xt, LD0, SD0, Lam, Sig, omega, gcs, gss, A, rhs, LDI):
    """The collocation matrix A of arcs.Arcs (operator columns, then enrichment columns when omega has rows)
    and the two right-hand sides of arcs.Linear, in one pass (cos t, sin t and the log factor shared).

    Rows: arc ir, table point p (centre ac[ir], offset ae[ir] xt[p]); xt = the nodes (alpha* = 0) or the
    nodes and the end points (arcs_enrich); LD0[p] = (log moments at xt[p]) @ D, SD0 (sign moments): the
    same-arc rows, whose points offset/e are the table points.  LDI[ia, p]: the same-arc rows' periodic images
    (an arc wider than 1 rad) @ D, precomputed (arcs._image_rows); an array with no rows: computed here (O(n^3))."""
    n = s.size
    na = ac.size
    m = omega.shape[0]
    npt = xt.size
    N = na * npt
    L = np.empty(n)
    Sg = np.empty(n)
    LD = np.empty(n)
    SD = np.empty(n)
    acc = np.empty(max(m, 1))
    for ir in range(na):
        for p in range(npt):
            i = ir * npt + p
            cp = math.cos(ac[ir]) * math.cos(ae[ir] * xt[p])
            rhs[i, 0] = -(1 - cp)
            rhs[i, 1] = cp
    trig = np.empty((4, n))
    for ia in range(na):
        c, e = ac[ia], ae[ia]
        loge = math.log(e)
        images = 2 * PI / e
        images_on = e > 1.0        # every arc has its own rows here
        _arc_trig(e, s, trig)
        for i in range(N):
            ir = i // npt
            p = i - ir * npt
            cen, off = ac[ir], ae[ir] * xt[p]
            same = cen == c
            d = off if same else _wrap(cen - c) + off
            x = d / e
            kink = ar != 0.0 and abs(x) < 1
            if same:
                for k in range(n):
                    LD[k] = LD0[p, k]
                    SD[k] = SD0[p, k]
                if images_on and LDI.shape[1] > p:
                    for k in range(n):
                        LD[k] += LDI[ia, p, k]
                elif images_on:
                    for q in range(n):
                        L[q] = 0.0
                    _add_log_moments(x - images, n, L, 1.0)
                    _add_log_moments(x + images, n, L, 1.0)
                    _vecmat(L, D, Sg, False)
                    for k in range(n):
                        LD[k] += Sg[k]
            else:
                for q in range(n):
                    L[q] = 0.0
                _add_log_moments(x, n, L, 1.0)
                if images_on:
                    _add_log_moments(x - images, n, L, 1.0)
                    _add_log_moments(x + images, n, L, 1.0)
                if kink:
                    _sign_moments_into(x, n, Sg)
                _vecmat(L, D, LD, False)
                if kink:
                    _vecmat(Sg, D, SD, False)
            for j in range(m):
                acc[j] = 0.0
            # t = d - e s_k: cos t, sin t and sin(t/2) by angle addition (one log per entry at most)
            cd, sd = math.cos(d), math.sin(d)
            cd2, sd2 = math.cos(0.5 * d), math.sin(0.5 * d)
            for k in range(n):
                t = d - e * s[k]
                ct = cd * trig[0, k] + sd * trig[1, k]
                st = sd * trig[0, k] - cd * trig[1, k]
                el = _ell_half(0.5 * t, sd2 * trig[2, k] - cd2 * trig[3, k])
                if images_on:
                    smooth = ct * (6 * loge + (el - 2 * math.log(abs((t - TWO_PI) * (t + TWO_PI))))) + k1 * ct + k0
                else:
                    smooth = ct * (2 * loge + el) + k1 * ct + k0
                A[i, ia * n + k] = _operator_entry(smooth, t, ct, st, LD[k], SD[k], kink, ar, n)
                if m:
                    if same:
                        r = ct * (2 * loge + el) + k1 * ct + k0 - ar * t * st
                    else:   # log(2 - 2 cos t) = log(t^2) + _ell(t), without the cancellation near t = 0, 2 pi
                        r = ct * (el + 2 * math.log(abs(t))) + k1 * ct + k0 + ar * (PI * _sign(t) * st - t * st)
                    for j in range(m):
                        acc[j] += r * omega[j, k]
            if m:
                if same:
                    ce, se = math.cos(d), math.sin(d)
                    for j in range(m):
                        A[i, na * n + ia * m + j] = -_same_arc_enrichment(acc[j], Lam, Sig, gcs, gss, j, p, ia, ce,
                                                                          se, ar)
                else:
                    for j in range(m):
                        A[i, na * n + ia * m + j] = -acc[j]
