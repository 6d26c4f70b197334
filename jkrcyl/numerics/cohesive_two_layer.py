"""The Dugdale end layers of both arcs of a two-arc Maugis-Dugdale state, subtracted in closed form (notation of
jkrcyl.numerics.cohesive_two; the layer of one arc: jkrcyl.numerics.cohesive_layer).

A thin zone (c - eps small against eps) puts a layer of that width into the arc's unknown v = nu + s0, which
Chebyshev resolves only with ~sqrt(eps/(c - eps)) nodes (564 per arc at lambda = 50, M = 0.2).  As for one arc
(jkrcyl.numerics.cohesive), each arc's half-plane Maugis traction v_s is subtracted: on the bottom arc
|phi| < eps with its zone |phi| < c, and on the top arc |phi - pi| < eps_top with its zone |phi - pi| < c_top,
the same function about pi (K depends on phi - psi only).  The rest w = v - v_bot - v_top solves the two-arc
system with the right-hand side of a unit zone traction -Z_C + Q_bot + Q_top at the collocation points,
Q the layer's exact potential (cohesive_layer.potential), and is smooth: a node count of JKR's arcs, whatever the
zone length.  What bounds lambda (LAMBDA_MAX) is rounding, not nodes: the zone-end gaps h(c) - h0 are sums of terms
of size ~s0 (the zone's and the layer's potentials, which cancel) and carry ~1e-12 of noise at lambda = 1000, which
the thin zones' weak hold on the arcs amplifies ~1e4 into the half-angles (measured along the branch at M = 0.2,
64 against 96 nodes per arc: P* 4e-9 at lambda = 200, 1e-7 at 1000, 3e-7 at 2000, 1e-4 at 5000; the states'
distance to JKR's is ~0.2 lambda^-2 in P* there).

Q of an arc at any angle of the circle, wrapped to x = (phi - centre)/e with |x| <= pi/e: the layer's log part in
closed form, the analytic rest of K by cohesive_layer's 32-point Chebyshev moments, whose nearest singularity
(t = 2 pi, or 4 pi when e > 1 and the log images are taken out) lies >= (pi - e)/e beyond the arc in s; so the
other arc's points and the zone ends are evaluated by the same closed form (tests/test_cohesive_two_layer.py:
against a quadrature of v_s K).  v_s vanishes like a square root at the contact end: the edge coefficient k of v
is w's, the loads p and B add the layers' (cohesive_layer.loads; the top arc's cos changes sign).  Per unit s0.
"""
import math

import numpy as np

from . import arcs_enrich as _en
from . import cohesive_layer as _cl

LAMBDA_MAX = 1e3          # the transition parameter 4 s0/m^(2/3) resolved on two arcs (module docstring)


def check_lambda(m, s0):
    """ValueError naming sigma0 where lambda = 4 s0/m^(2/3) exceeds LAMBDA_MAX (module docstring)."""
    lam = 4 * s0 / m ** (2 / 3)
    if lam > LAMBDA_MAX:
        raise ValueError(f"sigma0 is too large for the two-arc cohesive solver: its transition parameter lambda = "
                         f"{lam:.4g} must be at most {LAMBDA_MAX:g} (at most {LAMBDA_MAX / lam:.3g} times this "
                         f"sigma0; the two-patch states are JKR's there to O(lambda^-2) ~ {lam ** -2:.1g})")


MEMO = 4                  # zone ends whose right-hand side part is kept, per arc


def zone_ends(zones):
    """(c, c_top) of a zone set of cohesive.zones_of (0 where a zone is absent), or None for the zone all round
    (no zone end: no layer)."""
    c = c_top = 0.0
    for lo, hi in zones:
        if lo == -math.pi and hi == math.pi:
            return None
        if lo == -hi:
            c = hi
        elif hi == math.pi:
            c_top = math.pi - lo
    return c, c_top


class Layers:
    """The layers of the arcs (0, eps) and (pi, eps_top) at the collocation points of fixed arcs (their smooth
    moment tables computed once) and at any other angle."""

    def __init__(self, eps, eps_top, kernel, points):
        self.arcs = ((0.0, float(eps)), (math.pi, float(eps_top)))
        self.kernel = kernel
        k0, k1 = kernel.k0, kernel.k1
        self.trig, self.tables, self.x, self.memo = [], [], [], ({}, {})
        n = points.size // 2
        for centre, e in self.arcs:
            gc, gs = _cl.trig_coefficients(e, _en.K_TRIG)
            self.trig.append((gc, gs, _cl.qmax_of(gc, gs)))
            x = np.ascontiguousarray(_wrap(points - centre) / e)
            # each arc's nodes are symmetric about its centre, so are their images x about either arc's centre
            self.x.append((x[:n].copy(), x[n:].copy()))
            self.tables.append(tuple(_cl.smooth_table(xi, e, k0, k1, 0.0, n) for xi in self.x[-1]))

    def rhs(self, c, c_top):
        """Q_bot + Q_top at the collocation points (unit s0): what a unit zone traction's right-hand side adds.
        Each arc's part is kept for its last few zone ends (a Newton's differences move one zone end at a time)."""
        out = 0.0
        for i, ((centre, e), end) in enumerate(zip(self.arcs, (c, c_top))):
            if end > e:
                out = out + self._arc_rhs(i, end)
        return out

    def _arc_rhs(self, i, end):
        memo = self.memo[i]
        if end not in memo:
            if len(memo) >= MEMO:
                memo.pop(next(iter(memo)))
            e = self.arcs[i][1]
            gc, gs, q = self.trig[i]
            memo[end] = np.concatenate([_cl.potential(x, e, end, self.kernel.k0, self.kernel.k1, 0.0, gc, gs, q, t,
                                                      x.size) for x, t in zip(self.x[i], self.tables[i])])
        return memo[end]

    def at(self, phi, c, c_top):
        """Q_bot + Q_top at angles phi (any, e.g. outside the arcs: the gap subtracts s0 times it)."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        out = np.zeros(phi.shape)
        none = np.zeros((0, _cl.N_SMOOTH))
        for (centre, e), end, (gc, gs, q) in zip(self.arcs, (c, c_top), self.trig):
            if end > e:
                x = np.ascontiguousarray(_wrap(phi - centre).ravel() / e)
                out += _cl.potential(x, e, end, self.kernel.k0, self.kernel.k1, 0.0, gc, gs, q, none).reshape(
                    phi.shape)
        return out

    def loads(self, c, c_top):
        """(int v_s cos(phi) dphi, int v_s dphi) of both layers (unit s0)."""
        p = b = 0.0
        for (centre, e), end, (gc, _, _) in zip(self.arcs, (c, c_top), self.trig):
            if end > e:
                lp, lb = _cl.loads(e, end, gc)
                p, b = p + math.cos(centre) * lp, b + lb
        return p, b

    def traction(self, phi, c, c_top):
        """v_s/s0 of both layers at angles phi (0 off the arcs)."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        out = np.zeros(phi.shape)
        for (centre, e), end in zip(self.arcs, (c, c_top)):
            if end > e:
                out += _cl.traction(np.ascontiguousarray(_wrap(phi - centre).ravel()), e, end).reshape(phi.shape)
        return out


def _wrap(phi):
    """phi wrapped to [-pi, pi], angles already there unchanged (not rounded: the gap at a thin zone's end moves
    by ~1e-12 per ulp of the angle at lambda = 1000)."""
    phi = np.asarray(phi, dtype=float)
    return np.where(np.abs(phi) <= math.pi, phi, np.angle(np.exp(1j * phi)))