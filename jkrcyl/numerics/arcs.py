"""Contact arcs on the circle for ANY alpha*: the displacement form of (2.1) ((5.2) plus the alpha* terms),
solved by Gauss-Chebyshev collocation on one or two arcs (bottom |phi| < eps, top |phi - pi| < eps_top).

Normalised unknown nu = N R beta*/(4 pi Delta) (so n = nu/vartheta is the n of section 6 and of
jkrcyl.model.two_patch; nu stays finite for a rigid cradle).  On every arc, with t = phi - psi,

    (delta/Delta) cos(phi) - (1 - cos(phi)) = - int nu(psi) K(phi - psi) dpsi,                  (5.2)
    K(t) = cos t log(2 - 2 cos t) + gb cos t + 1 - 1/(2 vartheta) + ar (pi sign(t) sin t - t sin t),

gb = (1/G_I)/beta*, ar = alpha*/beta* (alpha* = (kappa - 1)/(2G) - (kappa_I - 1)/(2G_I)); the alpha* part
pi sin|t| - t sin t is written pi sign(t) sin t - t sin t, valid without wrapping for |t| < 2 pi.  At ar = 0
this is (5.2) (the kernel of the closed forms, derive/approach.py).  The kernel is the sum of the Michell modes of the
hole and the disk (derive/green.py); K'' + K reproduces the csc^2 and local -pi alpha* N terms of (2.1).

Discretisation: phi = c + e s, nu dphi = u(s) ds/sqrt(1 - s^2) (square-root ends explicit, u smooth at
alpha* = 0).  The log|x - s| and sign(x - s) parts are integrated exactly against the Chebyshev interpolant
of (cos t) u and (sin t) u (product integration); the rest by Gauss-Chebyshev.  At alpha* = 0 the method is
spectral; for alpha* != 0 u carries (1 - s) log(1 - s) end terms (the kink of sin|t| at t = 0): the
sign(x - s) moments are exact, so the remaining error is the Chebyshev interpolation of u, algebraic in n
(see benchmarks/bench_solver.py for the measured table).
"""
import functools
import math

import numpy as np
from scipy import fft as _fft
from scipy.linalg.lapack import dgesv as _dgesv
from scipy.special import jv as _jv

from ..generated import green as _green
from . import arcs_enrich as _en
from . import arcs_kernels as _ak
from . import arcs_readout as _rd
from . import enrichment_kernels as _ek

LOG2 = math.log(2.0)
NEAR_ARC = 1.6     # gap points closer than this (in half-widths from the centre) use the fine grid


@functools.lru_cache(maxsize=None)
def _nodes(n):
    return np.cos((2 * np.arange(1, n + 1) - 1) * np.pi / (2 * n))


@functools.lru_cache(maxsize=None)
def _cheb_matrix(n):
    """D with c = D @ u: Chebyshev coefficients of the interpolant through the Gauss nodes."""
    s = _nodes(n)
    D = (2.0 / n) * np.cos(np.outer(np.arange(n), np.arccos(s)))
    D[0] /= 2
    return D


def _log_moments(x, n):
    """L[i, m] = int_{-1}^{1} log|x_i - s| T_m(s)/sqrt(1 - s^2) ds (exact, any real x_i)."""
    x = np.asarray(x, dtype=float)
    m = np.arange(1, n)
    out = np.empty((x.size, n))
    inside = np.abs(x) <= 1
    th = np.arccos(np.clip(x, -1, 1))
    out[:, 0] = -math.pi * LOG2
    out[:, 1:] = -math.pi * np.cos(np.outer(th, m)) / m
    if (~inside).any():
        xo = x[~inside]
        r = np.sqrt((np.abs(xo) - 1) * (np.abs(xo) + 1))
        z = np.sign(xo) / (np.abs(xo) + r)            # x - sign(x) sqrt(x^2 - 1), stably
        out[~inside, 0] = math.pi * np.log((np.abs(xo) + r) / 2)
        out[~inside, 1:] = -math.pi * z[:, None] ** m / m
    return out


IMAGE_DCT_NODES = 128
_NO_IMAGES = np.zeros((1, 0, 1))


def _image_rows(ae, xt, n):
    """(na, npt, n): per arc wider than 1 rad, the log moments of its own rows' periodic images (x -+ 2 pi/e)
    times D, by a DCT: L @ D = dct_III(L)/n (D[m, k] = (2/n) cos(m theta_k), halved at m = 0), O(n^2 log n) where
    the product row by row is O(n^3) (12 of 17 ms of a 408-node contact); zero rows for the other arcs.  Below
    IMAGE_DCT_NODES nodes, no rows (the kernel's product is cheaper than the DCT's call: equal at 128 nodes)."""
    if n < IMAGE_DCT_NODES or not np.any(ae > 1.0):
        return _NO_IMAGES
    out = np.zeros((ae.size, xt.size, n))
    for ia, e in enumerate(ae.tolist()):
        if e > 1.0:
            _ak.image_moments(e, xt, out[ia])
            out[ia] = _fft.dct(out[ia], type=3, axis=1) / n
    return out


def _sign_moments(x, n):
    """S[i, m] = int_{-1}^{1} sign(x_i - s) T_m(s)/sqrt(1 - s^2) ds (exact): pi - 2 theta, -2 sin(m theta)/m."""
    x = np.asarray(x, dtype=float)
    th = np.arccos(np.clip(x, -1, 1))
    m = np.arange(1, n)
    out = np.empty((x.size, n))
    out[:, 0] = math.pi - 2 * th
    out[:, 1:] = -2 * np.sin(np.outer(th, m)) / m
    return out


def _ell(t):
    """log((2 sin(t/2)/t)^2), analytic for |t| < 2 pi (series near 0)."""
    return 2 * np.log(np.abs(np.sinc(np.asarray(t) / (2 * math.pi))))     # sinc(x) = sin(pi x)/(pi x)


@functools.lru_cache(maxsize=None)
def _fine_grid(n_fine=4096):
    """Gauss-Chebyshev nodes and the enrichment functions on them (gap evaluation off the tables)."""
    s = _nodes(n_fine)
    return s, np.ascontiguousarray(_en._g(s)[:_en.N_ENRICH])


def _ell3(t):
    """log(4 sin^2(t/2)/(t^2 (t - 2 pi)^2 (t + 2 pi)^2)), analytic for |t| < 4 pi."""
    t = np.asarray(t, dtype=float)
    return _ell(t) - 2 * np.log(np.abs(t - 2 * math.pi)) - 2 * np.log(np.abs(t + 2 * math.pi))


_NO_TRIG = np.zeros((0, _en.K_TRIG))


class Kernel:
    """Constants of K(t): vartheta (inf allowed), gb = (1/G_I)/beta*, ar = alpha*/beta*.

    k0, k1 are the derived sums of the Michell modes (derive/green.py, generated/green.py); k1 is the one
    of the paper's delta (mean displacements of the two rims, load at the pin's centre).
    """

    def __init__(self, theta, gb, ar=0.0):
        self.theta, self.gb, self.ar = float(theta), float(gb), float(ar)
        inv_theta = 0.0 if math.isinf(self.theta) else 1.0 / self.theta
        self.k0, self.k1 = _kernel_constants(self.ar, self.gb, inv_theta)


@functools.lru_cache(maxsize=256)
def _kernel_constants(ar, gb, inv_theta):
    c = _green.kernel_constants(ar=ar, gb=gb, inv_theta=inv_theta)
    return c.k0, c.k1


@functools.lru_cache(maxsize=None)
def _tables(n, enriched):
    """Per node count: the table points xt (the nodes, and with the enrichment the end points too),
    arcs_enrich.tables and, stacked for the kernels, Lam, Sig (m, n + m, K), omega[j] = D^T mu_j (quadrature
    weights of g_j w), mu (m, n), and the same-arc rows of the log and sign moments times D, LD0 and SD0 (their
    points offset/e are the table points)."""
    D = _cheb_matrix(n)
    if not enriched:
        xt = _nodes(n)
        LD0, SD0 = _log_moments(xt, n) @ D, np.zeros((xt.size, n))
        z = np.zeros((0, 1, 1))
        return None, None, xt, None, z, z, np.zeros((0, n)), np.zeros((0, n)), LD0, SD0
    m = _en.N_ENRICH
    xt = _en.table_points(n)[0]              # the nodes, then the end points
    x_extra, x_table = xt[n:], tuple(xt)
    tab = _en.tables(n)
    Lam, Sig, mu = tab
    omega = np.ascontiguousarray([D.T @ mu[j][:n] for j in range(m)])
    LD0, SD0 = _log_moments(xt, n) @ D, _sign_moments(xt, n) @ D
    return (x_extra, x_table, xt, tab, np.ascontiguousarray(Lam), np.ascontiguousarray(Sig), omega,
            np.ascontiguousarray([mu[j][:n] for j in range(m)]), LD0, SD0)


_K = np.arange(_en.K_TRIG)
_TRIG_SIGN = (-1.0) ** (_K // 2)


_TRIG_C = np.where(_K % 2 == 0, 2 * _TRIG_SIGN, 0.0)
_TRIG_C[0] = 1.0
_TRIG_S = np.where(_K % 2 == 1, 2 * _TRIG_SIGN, 0.0)


def _trig_all(ae):
    """arcs_enrich.trig_coefficients of every half-width: (na, K) arrays gamma_c, gamma_s."""
    J = _jv(_K, ae[0])[None, :] if ae.size == 1 else _jv(_K[None, :], ae[:, None])
    return J * _TRIG_C, J * _TRIG_S


class Arcs:
    """Collocation system for arcs [(centre, half-width), ...] with n Gauss-Chebyshev nodes per arc."""

    def __init__(self, arcs, kernel, n):
        self.arcs = [(float(c), float(e)) for c, e in arcs if e > 0]
        self.kernel, self.n = kernel, n
        self.s = _nodes(n)
        self.D = _cheb_matrix(n)
        self._ac = np.array([c for c, _ in self.arcs], dtype=float)
        self._ae = np.array([e for _, e in self.arcs], dtype=float)
        # alpha* != 0: unknowns u (n per arc) then c (N_ENRICH per arc); extra collocation points at the ends
        self.m = _en.N_ENRICH if kernel.ar != 0.0 else 0
        na = len(self.arcs)
        (self.x_extra, self.x_table, self._xt, self.tab, self._Lam, self._Sig, self._omega, self._mu,
         LD0, SD0) = _tables(n, bool(self.m))
        if self.m:
            self._gcs, self._gss = _trig_all(self._ae)
        else:
            self._gcs = self._gss = _NO_TRIG
        npt = na * self._xt.size
        self.A = np.empty((npt, npt))
        self._rhs = np.empty((npt, 2))      # the right-hand sides of Linear: -(1 - cos phi), cos phi
        _ak.assemble(self._ac, self._ae, self.s, self.D, kernel.k0, kernel.k1, kernel.ar, self._xt, LD0, SD0,
                     self._Lam, self._Sig, self._omega, self._gcs, self._gss, self.A, self._rhs,
                     _image_rows(self._ae, self._xt, n))

    @property
    def centres(self):
        return np.repeat(self._ac, self.n)

    @property
    def offsets(self):
        return (self._ae[:, None] * self.s[None, :]).ravel()

    @property
    def cos(self):
        return np.cos(self.centres) * np.cos(self.offsets)    # exact for centres 0, pi

    def _operator(self, centres, offsets, out, col0):
        kn = self.kernel
        _ak.operator(centres, offsets, self._ac, self._ae, self.s, self.D, kn.k0, kn.k1, kn.ar, out, col0)

    def _enrichment(self, centres, offsets, table, out, col0):
        kn = self.kernel
        sf, gf = _fine_grid()
        _ek.enrichment(centres, offsets, self._ac, self._ae, self.s, kn.k0, kn.k1, kn.ar, table, self._Lam,
                       self._Sig, self._omega, self._gcs, self._gss, sf, gf, out, col0)

    def operator(self, centres, offsets):
        """Matrix: node values u -> -int nu K dpsi at the angles centre + offset (= gap - rigid part)."""
        centres = np.ascontiguousarray(centres, dtype=float)
        offsets = np.ascontiguousarray(offsets, dtype=float)
        out = np.empty((centres.size, len(self.arcs) * self.n))
        self._operator(centres, offsets, out, 0)
        return out

    def enrichment(self, centres, offsets, table=False):
        """Matrix: enrichment coefficients c -> -int nu K dpsi at the angles (arcs_enrich).  table=True: the
        points are the collocation points of each arc in order (same-arc rows use the exact tables)."""
        centres = np.ascontiguousarray(centres, dtype=float)
        offsets = np.ascontiguousarray(offsets, dtype=float)
        out = np.empty((centres.size, len(self.arcs) * self.m))
        self._enrichment(centres, offsets, bool(table), out, 0)
        return out

    def apply(self, centres, offsets, v):
        """-int nu K dpsi at angles outside the arcs for the unknown vector v."""
        centres = np.ascontiguousarray(centres, dtype=float)
        offsets = np.ascontiguousarray(offsets, dtype=float)
        M = np.empty((centres.size, len(self.arcs) * (self.n + self.m)))
        self._operator(centres, offsets, M, 0)
        if self.m:
            self._enrichment(centres, offsets, False, M, len(self.arcs) * self.n)
        return M @ v

    def split(self, v):
        """(node values u per arc, enrichment coefficients per arc) of an unknown vector."""
        n, m, na = self.n, self.m, len(self.arcs)
        return v[:n * na].reshape(na, n), v[n * na:].reshape(na, m)

    def edge(self, v):
        """k at the ends of each arc: nu ~ -k/sqrt(e - |phi - c|) (k > 0: tensile)."""
        U, C = self.split(v)
        return np.array([-(np.sum(self.D @ U[i]) + C[i] @ _en.G_END[:self.m]) / math.sqrt(2 * e)
                         for i, (_, e) in enumerate(self.arcs)])

    def moments(self, v, F):
        """int u(s) F(c + e s) ds/sqrt(1 - s^2) summed over the arcs, F vectorised (smooth)."""
        f = [np.asarray(F(c + e * self.s), dtype=float) for c, e in self.arcs]
        f = f[0] if len(f) == 1 and f[0].shape == self.s.shape else np.concatenate(
            [np.broadcast_to(fi, self.s.shape) for fi in f])
        return _rd.moment(np.ascontiguousarray(v, dtype=float), f, self.n, len(self.arcs), self.D, self._mu)


_G_END = np.ascontiguousarray(_en.G_END[:_en.N_ENRICH])


class Linear:
    """Both unit cases for fixed arcs, normalised by vartheta_eff (vartheta, or 1 for a rigid cradle):
    u = u0 + (delta/Delta) u1 and q = [P*, B*, k_bot, k_top] = q0 + (delta/Delta) q1, with
    P* = int n cos(phi) dphi (2.2), B* = int n dphi, n ~ -k/sqrt(distance to the end) (Griffith: k = M/pi).
    ``sign_det``: sign of det of the fixed-arc system (changes where the unit problem is singular)."""

    def __init__(self, eps, eps_top, theta, gb, n, alpha_ratio=0.0):
        self.eps, self.eps_top = eps, eps_top
        self.scale = 1.0 if math.isinf(theta) else float(theta)
        self.sys = Arcs([(0.0, eps), (math.pi, eps_top)], Kernel(theta, gb, alpha_ratio), n)
        sy = self.sys
        lu, piv, U, info = _dgesv(sy.A, sy._rhs)       # one LAPACK call: LU (for sign_det) and the solve
        # sign_det from the LU (LAPACK pivots are 1-based), U / scale and both unit cases q in one kernel
        self.sign_det, U, q = _rd.unit_q(lu, piv, U, sy._ac, sy._ae, sy.s, sy.D, sy._mu, _G_END, self.scale)
        self.u0, self.u1 = U[:, 0], U[:, 1]
        self.q0, self.q1 = q[:, 0], q[:, 1]

    def _q(self, u):
        sy = self.sys
        k = sy.edge(u)
        return np.array([sy.moments(u, np.cos), sy.moments(u, np.ones_like), k[0], k[1] if k.size > 1 else 0.0])

    def gap(self, phi, delta, clearance=1.0):
        """h(phi)/Delta (5.9) at angles phi (meaningful outside the arcs); delta = delta/Delta.
        With clearance = 0 and delta = the approach [m]: h [m] of the neat fit (and so on, linearly)."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        u = (clearance * self.u0 + delta * self.u1) * self.scale
        return clearance * (1 - np.cos(phi)) - delta * np.cos(phi) + self.sys.apply(np.zeros_like(phi), phi, u)

    def pressure(self, phi, delta, clearance=1.0):
        """n(phi) inside the arcs (Chebyshev interpolant of u over sqrt(1 - s^2)), 0 outside."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        u = clearance * self.u0 + delta * self.u1
        out = np.zeros_like(phi)
        n = self.sys.n
        U, C = self.sys.split(u)
        for i, (c, e) in enumerate(self.sys.arcs):
            x = np.angle(np.exp(1j * (phi - c))) / e
            inside = np.abs(x) < 1
            coef = self.sys.D @ U[i]
            T = np.cos(np.outer(np.arccos(x[inside]), np.arange(n)))
            val = T @ coef
            if self.sys.m:
                val = val + C[i] @ _en._g(x[inside])[:self.sys.m]
            out[inside] = val / (e * np.sqrt(1 - x[inside] ** 2))
        return out


def two_patch_linear(eps, eps_top, theta, gb, n, alpha_ratio=0.0):
    """Affine pieces of the two-arc state (eps_top = 0: the single bottom arc); see :class:`Linear`."""
    return Linear(eps, eps_top, theta, gb, n, alpha_ratio)


def nodes_for(eps, ar=0.0):
    """Nodes per arc: ~1e-12 at alpha* = 0, ~1e-11 otherwise (more as the arc closes round the circle)."""
    gap = max(math.pi - eps, 1e-12)
    n = min(max(24, 20 + 15 * math.sqrt(eps / gap)), 400)
    return int(n) if ar == 0.0 else int(min(8 * math.ceil(n / 8), 256))   # few distinct n: cached tables
