"""Contact arcs on the circle for alpha* = 0: the displacement equation (5.2) with its log kernel, solved by
Gauss-Chebyshev collocation (used by jkrcyl.twopatch until jkrcyl.numerics.arcs provides the same pieces).

Unknown: the normalised pressure n = N R beta*/(4 pi Delta vartheta) on each arc |phi - c| < e (c = 0 or pi),
written n dphi = u(s) ds/sqrt(1 - s^2) with phi = c + e s, u smooth (the end singularities are explicit).
Equation (5.2) divided by Delta vartheta, on every arc:

    (delta/Delta) cos(phi) - (1 - cos(phi)) = -vartheta int n(psi) K(phi - psi) dpsi,
    K(t) = cos(t) log(2 - 2 cos(t)) + gb cos(t) + 1 - 1/(2 vartheta),   gb = (1/G_I)/beta*.

The log singularity is split off, log(2 - 2 cos t) = 2 log|t| + log((2 sin(t/2)/t)^2), and 2 log|x - s| is
integrated exactly against the Chebyshev interpolant of u (moments -pi T_m(x)/m inside, -pi z^m/m outside);
the rest by Gauss-Chebyshev.  Angles are carried as (arc centre, offset) so that arcs down to 1e-300 rad
keep full relative accuracy.  Spectral in the nodes per arc for separated arcs.
"""
import math

import numpy as np
from scipy.linalg import lu_factor, lu_solve

LOG2 = math.log(2.0)


def _nodes(n):
    return np.cos((2 * np.arange(1, n + 1) - 1) * np.pi / (2 * n))


def _cheb_matrix(n):
    """D with c = D @ u: Chebyshev coefficients of the interpolant through the Gauss nodes."""
    s = _nodes(n)
    T = np.cos(np.outer(np.arange(n), np.arccos(s)))
    D = (2.0 / n) * T
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
        r = np.sqrt((xo - 1) * (xo + 1))
        z = 1.0 / (np.abs(xo) + r) * np.sign(xo)            # x - sign(x) sqrt(x^2 - 1), stably
        out[~inside, 0] = math.pi * np.log((np.abs(xo) + r) / 2)
        out[~inside, 1:] = -math.pi * z[:, None] ** m / m
    return out


def _ell(t):
    """log((2 sin(t/2)/t)^2), analytic for |t| < 2 pi (series near 0)."""
    t = np.asarray(t, dtype=float)
    small = np.abs(t) < 1e-3
    ts = np.where(small, 1.0, t)
    return np.where(small, -t * t / 12 - t ** 4 / 1440, 2 * np.log(np.abs(2 * np.sin(ts / 2) / ts)))


class Arcs:
    """Collocation system for arcs [(centre, half-width), ...] at (vartheta, gb) with n nodes per arc."""

    def __init__(self, arcs, theta, gb, n):
        self.arcs = [(float(c), float(e)) for c, e in arcs if e > 0]
        self.theta, self.gb, self.n = theta, gb, n
        self.s = _nodes(n)
        self.D = _cheb_matrix(n)
        self.centres = np.repeat([c for c, _ in self.arcs], n)
        self.offsets = np.concatenate([e * self.s for _, e in self.arcs])
        self.A = self.operator(self.centres, self.offsets)
        self.cos = np.cos(self.centres) * np.cos(self.offsets)    # exact for centres 0, pi

    def operator(self, centres, offsets):
        """Matrix: node values u -> (v_r - u_r)/Delta at the angles centre + offset."""
        th, gb, n = self.theta, self.gb, self.n
        blocks = []
        for c, e in self.arcs:
            same = centres == c
            d = np.where(same, offsets, np.angle(np.exp(1j * (centres - c))) + offsets)
            t = d[:, None] - e * self.s[None, :]
            cos_t = np.cos(t)
            smooth = cos_t * (2 * math.log(e) + _ell(t)) + gb * cos_t + 1 - 1 / (2 * th)
            L = _log_moments(d / e, n) @ self.D
            blocks.append(smooth * (math.pi / n) + 2 * cos_t * L)
        return -th * np.hstack(blocks)

    def edge(self, u):
        """k at the ends of each arc: n ~ -k/sqrt(e - |phi - c|)."""
        n = self.n
        return np.array([-np.sum(self.D @ u[i * n:(i + 1) * n]) / math.sqrt(2 * e)
                         for i, (_, e) in enumerate(self.arcs)])


class Linear:
    """Both unit cases for fixed arcs: u = u0 + (delta/Delta) u1; q = [P*, B*, k_bot, k_top] likewise."""

    def __init__(self, eps, eps_top, theta, gb, n):
        self.eps, self.eps_top = eps, eps_top
        self.sys = Arcs([(0.0, eps), (math.pi, eps_top)], theta, gb, n)
        sy = self.sys
        rhs = np.column_stack([-(1 - sy.cos), sy.cos])
        lu, piv = lu_factor(sy.A)
        U = lu_solve((lu, piv), rhs)
        # sign of det(A): the fixed-arc problem is singular on curves of the (eps, eps_top) plane (a_crit for
        # one arc); the caller multiplies its Griffith residual by it to keep that residual smooth across them
        swaps = np.count_nonzero(piv != np.arange(piv.size))
        self.sign_det = float((-1) ** swaps * np.prod(np.sign(np.diag(lu))))
        self.u0, self.u1 = U[:, 0], U[:, 1]
        self.q0, self.q1 = self._q(self.u0), self._q(self.u1)

    def _q(self, u):
        w = math.pi / self.sys.n
        k = self.sys.edge(u)
        return np.array([w * np.sum(u * self.sys.cos), w * np.sum(u), k[0], k[1] if k.size > 1 else 0.0])

    def gap(self, phi, delta):
        """h(phi)/Delta (5.9) at angles phi (meaningful outside the arcs)."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        u = self.u0 + delta * self.u1
        return (1 - np.cos(phi)) - delta * np.cos(phi) + self.sys.operator(np.zeros_like(phi), phi) @ u

    def pressure(self, phi, delta):
        """n(phi) inside the arcs (Chebyshev interpolant of u over sqrt(1 - s^2)), 0 outside."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        u = self.u0 + delta * self.u1
        out = np.zeros_like(phi)
        n = self.sys.n
        for i, (c, e) in enumerate(self.sys.arcs):
            x = np.angle(np.exp(1j * (phi - c))) / e
            inside = np.abs(x) < 1
            coef = self.sys.D @ u[i * n:(i + 1) * n]
            T = np.cos(np.outer(np.arccos(x[inside]), np.arange(n)))
            out[inside] = (T @ coef) / (e * np.sqrt(1 - x[inside] ** 2))
        return out


def two_patch_linear(eps, eps_top, theta, gb, n):
    """Affine pieces of the two-arc state (eps_top = 0: the single bottom arc)."""
    return Linear(eps, eps_top, theta, gb, n)
