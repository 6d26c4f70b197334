"""The Dugdale end layer of a thin zone, in closed form (jkrcyl.numerics.cohesive subtracts it).

Notation of jkrcyl.numerics.cohesive: the contact |phi| < e, its zone |phi| < c, the contact unknown v = nu + s0
with nu dphi = u(s) ds/sqrt(1 - s^2), phi = e s = e cos(theta).  A zone end a small distance c - e past the
contact end puts a layer of that width into v (Chebyshev needs ~sqrt(e/(c - e)) nodes for it).  Its leading
part is the half-plane Maugis-Dugdale traction: with the log kernel 2 log|phi - psi| (the singular part of K)
the contact traction

    v_s(phi) = (2 s0/pi) arctan(sqrt((e^2 - phi^2)/(c^2 - e^2))) = (2 s0/pi) arctan(sin(theta)/beta),

beta = sqrt(c^2 - e^2)/e, together with -s0 on |phi| < c, displaces the contact flat (Maugis 1992; Baney and
Hui 1997; tests/test_cohesive_layer.py checks it by quadrature).  So v = v_s + w leaves w the right-hand side
-s0 Z_C + int v_s K, whose near-singular parts cancel up to the t^2 log|t| and alpha* |t| parts of K: w is
smooth (a JKR-like node count, tests/test_cohesive_layer.py) and v_s enters through the exact potential

    Q(x) = int_{-1}^{1} K(e (x - s)) u_s(s) ds/sqrt(1 - s^2),   u_s = e sin(theta) v_s(e s),

at any x = phi/e (in or off the contact).  With arctan(sin(theta)/beta) = 2 sum_{j odd} rho^j sin(j theta)/j,
rho = sqrt(1 + beta^2) - beta, u_s has the Chebyshev series (2 e s0/pi) sum_{j odd} (rho^j/j) (T_{j-1} - T_{j+1}).
K = 2 cos(t) log|x - s| + pi alpha*/beta* sign(t) sin(t) + (an analytic rest), t = e (x - s), as in
jkrcyl.numerics.arcs: cos(e s) and sin(e s) as Chebyshev series (Jacobi-Anger, arcs_enrich.trig_coefficients),
the products with u_s give the exact log and sign moments as sums sum_{j odd} (rho^j/j) zeta^|j+sigma|/|j+sigma|
(zeta = e^{i theta_x}, or z = x - sign(x) sqrt(x^2 - 1) off the contact) in closed form (atanh, log(1 - w^2),
the Legendre chi_2 through Li2, w = rho zeta), and the analytic rest by its Chebyshev moments (Gauss-Chebyshev).
Per unit s0; every function here is linear in s0.
"""
import cmath
import math

import numpy as np
from numba import njit
from scipy.special import bernoulli, factorial

from .arcs_kernels import _ell, _ell3

PI = math.pi
TWO_PI = 2 * math.pi
LOG2 = math.log(2.0)
W_DIRECT = 0.05     # |w| <= this: the moment sums term by term (a few terms); above, by parity tails
W_CLOSED = 0.85     # |w| >= this: parity tails from atanh and log(1 - w^2); between: summed far out, recurred back
N_SMOOTH = 32       # Gauss-Chebyshev points for the Chebyshev moments of the analytic rest of K (its nearest
                    # singularity, |t| = 2 pi (4 pi with the images), lies >= 2 beyond [-1, 1]: ~1e-16)
TAIL = 1e-18        # series stop once |w|^J is below this
_BERN = np.array([bernoulli(40)[n] / factorial(n + 1, exact=False) for n in range(41)])  # Li2 series
_S = np.cos((np.arange(N_SMOOTH) + 0.5) * np.pi / N_SMOOTH)
_COS_KT = np.cos(np.outer(np.arange(N_SMOOTH), (np.arange(N_SMOOTH) + 0.5) * np.pi / N_SMOOTH))


@njit(cache=True)
def beta_rho(e, c):
    """(beta, rho) of the layer of the contact e, zone end c > e."""
    beta = math.sqrt((c - e) * (c + e)) / e
    return beta, 1.0 / (math.sqrt(1.0 + beta * beta) + beta)


@njit(cache=True)
def coefficients(e, rho, n):
    """Chebyshev coefficients a_0..a_{n-1} of u_s (unit s0): a_0 = (2e/pi) rho, a_k = (2e/pi)(rho^(k+1)/(k+1)
    - rho^(k-1)/(k-1)) for even k >= 2, 0 for odd k."""
    a = np.zeros(n)
    f = 2 * e / PI
    a[0] = f * rho
    rp = rho                                  # rho^(k-1)
    for k in range(2, n, 2):
        rn = rp * rho * rho
        a[k] = f * (rn / (k + 1) - rp / (k - 1))
        rp = rn
    return a


@njit(cache=True)
def _li2_series(z):
    u = -cmath.log(1.0 - z)
    acc = _BERN[0] * u + _BERN[1] * u * u
    u2 = u * u
    p = u
    for n in range(2, 41, 2):
        p = p * u2
        acc += _BERN[n] * p
    return acc


@njit(cache=True)
def li2(z):
    """The dilogarithm for |z| <= 1 (Bernoulli series in -log(1 - z), reflected for Re z > 1/2)."""
    if z == 0:
        return 0j
    if z.real > 0.5:
        return PI * PI / 6 - cmath.log(z) * cmath.log(1.0 - z) - _li2_series(1.0 - z)
    return _li2_series(z)


@njit(cache=True)
def moment_sums(rho, zeta, S):
    """W[sigma + S] = sum_{j odd >= 1, j != -sigma} (rho^j/j) zeta^|j+sigma|/|j+sigma|, |sigma| <= S, |zeta| <= 1:
    term by term where |rho zeta| <= W_DIRECT; else each sum over j + sigma >= 1 by partial fractions,
    (1/sigma)(zeta^sigma T(j*) - rho^-sigma T(j* + sigma)), from the parity tails T(J) = sum_{J' >= J, J' = J
    mod 2} w^J'/J' (w = rho zeta: atanh(w) and -log(1 - w^2)/2 less their first terms where |w| >= W_CLOSED,
    else summed far out and recurred back, the stable direction), sigma = 0 by chi_2 (Li2), and the few
    terms with j + sigma <= -1 directly."""
    W = np.zeros(2 * S + 1, dtype=np.complex128)
    w = rho * zeta
    aw = abs(w)
    L = 2 * S + 3
    if aw <= W_DIRECT:
        L += (int(math.log(TAIL) / math.log(aw)) + 2) if aw > 0 else 2
    rj = np.empty(L + 1)                      # rho^j/j
    zm = np.empty(L + 1, dtype=np.complex128)  # zeta^m/m
    rpow = np.empty(L + 1)
    zpow = np.empty(L + 1, dtype=np.complex128)
    rpow[0], zpow[0], rj[0], zm[0] = 1.0, 1.0, 0.0, 0.0
    for k in range(1, L + 1):
        rpow[k] = rpow[k - 1] * rho
        zpow[k] = zpow[k - 1] * zeta
        rj[k] = rpow[k] / k
        zm[k] = zpow[k] / k
    if aw <= W_DIRECT:
        for s in range(-S, S + 1):
            acc = 0j
            for j in range(1, L - S, 2):
                m = abs(j + s)
                if m != 0:
                    acc += rj[j] * zm[m]
            W[s + S] = acc
        return W
    Jm = S + 3
    T = np.zeros(Jm + 2, dtype=np.complex128)       # T[J] = sum_{J' >= J, J' = J mod 2} w^J'/J'
    if aw >= W_CLOSED:
        lp, lm = cmath.log(1.0 + w), cmath.log(1.0 - w)
        T[1] = 0.5 * (lp - lm)
        T[2] = -0.5 * (lm + lp)
        for J in range(1, Jm - 1):
            T[J + 2] = T[J] - rj[J] * zpow[J]
    else:
        Jend = int(math.log(TAIL) / math.log(aw)) + Jm + 2
        w2 = w * w
        for J0 in (Jm, Jm + 1):
            acc = 0j
            wj = rpow[J0] * zpow[J0]
            for J in range(J0, Jend, 2):
                acc += wj / J
                wj = wj * w2
            T[J0] = acc
        for J in range(Jm - 1, 0, -1):
            T[J] = T[J + 2] + rj[J] * zpow[J]
    for s in range(-S, S + 1):
        if s == 0:
            W[S] = 0.5 * (li2(w) - li2(-w))           # chi_2(w) = sum_{j odd} w^j/j^2
            continue
        if s > 0:
            acc = (zpow[s] * T[1] - T[1 + s] / rpow[s]) / s
        else:
            js = 1 - s if (-s) % 2 == 0 else 2 - s
            acc = (T[js] / zpow[-s] - rpow[-s] * T[js + s]) / s
            for j in range(1, -s, 2):                 # j + s <= -1: zeta^|j+s|/|j+s|
                acc += rj[j] * zm[-s - j]
        W[s + S] = acc
    return W


@njit(cache=True)
def _combine(V, S, rho, m0, gam, q0, qmax):
    """sum_q gam_q [L(q-1) - L(q+1) + L(-q-1) - L(1-q)] over q = q0, q0 + 2, ..: the Chebyshev product of
    (cos or sin)(e s) with u_s against moments m_k, where L(sigma) = sum_{j odd} (rho^j/j) m_|j+sigma| =
    V[sigma + S] + (the j = -sigma term, rho^-sigma/-sigma m0, for odd sigma <= -1)."""
    acc = 0.0
    for q in range(q0, qmax + 1, 2):
        g = gam[q]
        if g == 0.0:
            continue
        part = 0.0
        for sg, s in ((1.0, q - 1), (-1.0, q + 1), (1.0, -q - 1), (-1.0, 1 - q)):
            val = V[s + S]
            if s <= -1 and (-s) % 2 == 1:
                val += rho ** (-s) / (-s) * m0       # -s <= S + 1: a few powers
            part += sg * val
        acc += g * part
    return acc


@njit(cache=True)
def singular_parts(y, e, rho, gc, gs, qmax, sign):
    """(I_c, I_s, J_c, J_s) at a real y: I = int log|y - s| (cos, sin)(e s) u_s(s) ds/sqrt(1 - s^2) (unit s0),
    J the same with sign(y - s) (only with sign and |y| < 1; else 0)."""
    S = qmax + 1
    inside = abs(y) <= 1.0
    if inside:
        th = math.acos(min(max(y, -1.0), 1.0))
        zeta = complex(math.cos(th), math.sin(th))
        m0 = -PI * LOG2
    else:
        ay = abs(y)
        r = math.sqrt((ay - 1) * (ay + 1))
        zeta = complex(math.copysign(1.0, y) / (ay + r), 0.0)
        m0 = PI * math.log((ay + r) / 2)
        th = 0.0
    W = moment_sums(rho, zeta, S)
    f = e / PI
    V = -PI * W.real
    Ic, Is = f * _combine(V, S, rho, m0, gc, 0, qmax), f * _combine(V, S, rho, m0, gs, 1, qmax)
    Jc = Js = 0.0
    if sign and inside and abs(y) < 1.0:
        V = -2.0 * W.imag
        s_0 = PI - 2 * th
        Jc, Js = f * _combine(V, S, rho, s_0, gc, 0, qmax), f * _combine(V, S, rho, s_0, gs, 1, qmax)
    return Ic, Is, Jc, Js


@njit(cache=True)
def smooth_moments(x, e, k0, k1, ar, out):
    """out[k] = int R_x(s) T_k(s) ds/sqrt(1 - s^2) for even k < N_SMOOTH (Gauss-Chebyshev, N_SMOOTH points; odd k
    set to 0: u_s has none), R_x the analytic rest of K(e (x - s)) (jkrcyl.numerics.arcs_kernels.operator's
    'smooth' part)."""
    images = e > 1.0
    loge = math.log(e)
    vals = np.empty(N_SMOOTH)
    for i in range(N_SMOOTH):
        t = e * (x - _S[i])
        ct, st = math.cos(t), math.sin(t)
        v = ct * (6 * loge + _ell3(t)) if images else ct * (2 * loge + _ell(t))
        v += k1 * ct + k0
        if ar != 0.0:
            v -= ar * t * st
            if abs(x) >= 1.0:
                v += ar * PI * math.copysign(1.0, x) * st
        vals[i] = v
    for k in range(0, N_SMOOTH, 2):           # u_s has even terms only
        acc = 0.0
        for i in range(N_SMOOTH):
            acc += vals[i] * _COS_KT[k, i]
        out[k] = acc * (PI / N_SMOOTH)
        if k + 1 < N_SMOOTH:
            out[k + 1] = 0.0


@njit(cache=True)
def potential_singular(x, e, rho, cx, sx, ar, gc, gs, qmax):
    """The log (and alpha* sign) part of Q at x (unit s0), cx, sx = cos, sin(e x); e > 1: the log images at
    x -+ 2 pi/e as jkrcyl.numerics.arcs_kernels.operator (its smooth part then has ell3, 6 log e)."""
    Ic, Is, Jc, Js = singular_parts(x, e, rho, gc, gs, qmax, ar != 0.0)
    out = 2 * (cx * Ic + sx * Is) + ar * PI * (sx * Jc - cx * Js)
    if e > 1.0:
        for y in (x - TWO_PI / e, x + TWO_PI / e):
            Ic, Is, _, _ = singular_parts(y, e, rho, gc, gs, qmax, False)
            out += 2 * (cx * Ic + sx * Is)
    return out


@njit(cache=True)
def smooth_table(x, e, k0, k1, ar, nsym=0):
    """The smooth moments (smooth_moments) at each x_i: rows of the fixed contact's table points (the first nsym
    symmetric, as in potential: the moments of even k, all that u_s has, are even in x)."""
    out = np.empty((x.size, N_SMOOTH))
    half = (nsym + 1) // 2
    for i in range(x.size):
        if half <= i < nsym:
            out[i] = out[nsym - 1 - i]
        else:
            smooth_moments(x[i], e, k0, k1, ar, out[i])
    return out


@njit(cache=True)
def potential(x, e, c, k0, k1, ar, gc, gs, qmax, table, nsym=0):
    """Q(x_i) = int K(e (x_i - s)) u_s(s) ds/sqrt(1 - s^2) (unit s0) at each x_i, the layer of zone end c; table:
    smooth_table(x, ...) when x are fixed points (a contact's table points), else an empty (0, N) array; nsym:
    the first nsym points are symmetric (x_i = -x_(nsym-1-i), the Gauss-Chebyshev nodes): Q is even, so their
    second half is copied."""
    _, rho = beta_rho(e, c)
    a = coefficients(e, rho, N_SMOOTH)
    b = np.empty(N_SMOOTH)
    out = np.empty(x.size)
    half = (nsym + 1) // 2
    for i in range(x.size):
        if half <= i < nsym:
            out[i] = out[nsym - 1 - i]
            continue
        if table.shape[0] == x.size:
            b[:] = table[i]
        else:
            smooth_moments(x[i], e, k0, k1, ar, b)
        acc = 0.0
        for k in range(0, N_SMOOTH, 2):
            acc += a[k] * b[k]
        out[i] = acc + potential_singular(x[i], e, rho, math.cos(e * x[i]), math.sin(e * x[i]), ar, gc, gs, qmax)
    return out


@njit(cache=True)
def loads(e, c, gc):
    """(int v_s cos(phi) dphi, int v_s dphi) (unit s0): the layer's load p and B."""
    _, rho = beta_rho(e, c)
    a = coefficients(e, rho, gc.size)
    p = PI * a[0] * gc[0]
    for k in range(2, gc.size, 2):
        p += 0.5 * PI * a[k] * gc[k]
    return p, PI * a[0]


@njit(cache=True)
def traction(phi, e, c):
    """v_s(phi)/s0 = (2/pi) arctan(sqrt((e^2 - phi^2)/(c^2 - e^2))) on the contact (0 off it)."""
    out = np.zeros(phi.size)
    den = math.sqrt((c - e) * (c + e))
    for i in range(phi.size):
        if abs(phi[i]) < e:
            out[i] = 2 / PI * math.atan(math.sqrt((e - phi[i]) * (e + phi[i])) / den)
    return out


@njit(cache=True)
def trig_coefficients(e, K):
    """gamma_c, gamma_s (K terms): Chebyshev coefficients of cos(e s), sin(e s) (Jacobi-Anger, as
    jkrcyl.numerics.arcs_enrich.trig_coefficients) with J_k(e) by Miller's backward recurrence normalised by
    J_0 + 2 sum J_2k = 1 (0 < e <= pi)."""
    top = K + 30 + int(2 * e)
    J = np.zeros(top + 2)
    J[top] = 1e-300
    norm = 0.0
    for k in range(top, 0, -1):
        J[k - 1] = 2 * k / e * J[k] - J[k + 1]
        if abs(J[k - 1]) > 1e250:                  # rescale (the recurrence grows)
            J[:] = J * 1e-250
            norm *= 1e-250
        if (k - 1) % 2 == 0 and k - 1 > 0:
            norm += 2 * J[k - 1]
    norm += J[0]
    gc, gs = np.zeros(K), np.zeros(K)
    for k in range(K):
        sgn = -1.0 if (k // 2) % 2 else 1.0
        v = J[k] / norm
        if k % 2 == 0:
            gc[k] = (1.0 if k == 0 else 2.0) * sgn * v
        else:
            gs[k] = 2.0 * sgn * v
    return gc, gs


def qmax_of(gc, gs, tol=1e-18):
    """The last Chebyshev index of cos(e s), sin(e s) above tol (relative)."""
    big = np.nonzero((np.abs(gc) > tol) | (np.abs(gs) > tol))[0]
    return int(big[-1]) if big.size else 0
