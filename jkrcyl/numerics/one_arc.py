"""One contact arc at its edge condition, for any alpha*: the collocation system of numerics.arcs bordered by the
edge row, so that the physical state is solved for directly.

The fixed-arc system of numerics.arcs (bottom arc |phi| < eps, unknown nu = N R beta*/(4 pi L), L a length: the
clearance Delta, or R for the neat fit) is A v = c b0 + d b1 with b0 = -(1 - cos phi), b1 = cos phi, c = Delta/L
and d = delta/L.  Eliminating d through the unit cases u0 = A^-1 b0, u1 = A^-1 b1 (as numerics.arcs.Linear does)
cancels where A is singular -- the unit cases pass a pole (det A = 0) at arcs where the physical state is smooth
(a rubber roller in a rigid cradle once got a wrong pull-off there).  Here (v, d) solve the bordered system

    [ A      -b1 ] [v]   [c b0]
    [ e_k^T   0  ] [d] = [ k  ]          (e_k: the edge coefficient k of nu ~ -k/sqrt(eps - |phi|))

which is singular only where the state itself has a pole (the receding contact a_crit, where the unit delta case
has no edge singularity).  A second right-hand side [0; 1] gives the fixed-arc derivatives with respect to the
edge coefficient, p_k = dp/dk and d_k = dd/dk at fixed arc (finite through det A = 0): the stability rules of
jkrcyl.model.stability use them.
"""
import functools
import math
from collections import namedtuple

import numpy as np
from scipy.linalg.lapack import dgesv as _dgesv

from . import arcs as _arcs
from . import arcs_enrich as _en
from . import one_arc_kernels as _ok
from . import roots as _roots

#: Per arc: load p = int nu cos, B* = int nu, d = delta/L, h_pi = h(pi)/L, k (edge coefficient, = the target),
#: C* = int nu (dx/dphi) dphi, and the fixed-arc derivatives p_k = dp/dk, d_k = dd/dk.
ArcState = namedtuple("ArcState", ["p", "B", "d", "h_pi", "k", "C", "p_k", "d_k"])

_PI1, _ZERO1 = np.array([math.pi]), np.zeros(1)
_G_END = np.ascontiguousarray(_en.G_END[:_en.N_ENRICH])


def _rows(sys):
    """Moment rows (cos, 1, dx/dphi), the edge row and the gap row at phi = pi of a one-arc Arcs system."""
    n, m = sys.n, sys.m
    e = sys.arcs[0][1]
    phi = e * sys.s
    funcs = (np.cos(phi), np.ones(n), 0.5 * (1 + np.tan(phi / 2) ** 2))
    mom = np.empty((3, n + m))
    for i, f in enumerate(funcs):
        mom[i, :n] = (math.pi / n) * f
        mom[i, n:] = sys._omega[:m] @ f if m else 0.0
    edge = np.empty(n + m)
    edge[:n] = -sys.D.sum(axis=0) / math.sqrt(2 * e)
    edge[n:] = -_G_END[:m] / math.sqrt(2 * e)
    gap = np.empty((1, n + m))
    sys._operator(_ZERO1, _PI1, gap, 0)
    if m:
        sys._enrichment(_ZERO1, _PI1, False, gap, n)
    return mom, edge, gap[0]


class OneArc:
    """The bordered system of one bottom arc of half-angle eps with n nodes (kernel of numerics.arcs)."""

    def __init__(self, eps, theta, gb, ar, n):
        self.eps = float(eps)
        self.sys = _arcs.Arcs([(0.0, self.eps)], _arcs.Kernel(theta, gb, ar), n)
        sy = self.sys
        N = sy.A.shape[0]
        self._mom, self._edge, self._gap = _rows(sy)
        B = np.empty((N + 1, N + 1))
        B[:N, :N] = sy.A
        B[:N, N] = -sy._rhs[:, 1]
        B[N, :N] = self._edge
        B[N, N] = 0.0
        self._B = B
        self._b0 = sy._rhs[:, 0]

    def solve(self, k, clearance=1.0):
        """(v, d) at edge coefficient k, and the edge-unit solution (v', d') (c = 0, k = 1)."""
        N = self._b0.size
        rhs = np.zeros((N + 1, 2))
        rhs[:N, 0] = clearance * self._b0
        rhs[N, 0] = k
        rhs[N, 1] = 1.0
        _, _, x, info = _dgesv(self._B, rhs)
        if info != 0:
            raise ZeroDivisionError("one_arc: the bordered system is singular (the receding-contact pole)")
        return x

    def state(self, k, clearance=1.0):
        """:data:`ArcState` at edge coefficient k (nu units) and clearance ratio c = Delta/L."""
        x = self.solve(k, clearance)
        v, d = x[:-1, 0], x[-1, 0]
        vk, dk = x[:-1, 1], x[-1, 1]
        p, B, C = self._mom @ v
        h = clearance * 2.0 + d + self._gap @ v          # (1 - cos pi) = 2, -d cos(pi) = +d
        return ArcState(p=p, B=B, d=d, h_pi=h, k=self._edge @ v, C=C, p_k=self._mom[0] @ vk, d_k=dk), v

    def gap(self, phi, v, d, clearance=1.0):
        """h(phi)/L (5.9) outside the arc for the solution (v, d)."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        return clearance * (1 - np.cos(phi)) - d * np.cos(phi) + self.sys.apply(np.zeros_like(phi), phi, v)

    def pressure(self, phi, v):
        """nu(phi) inside the arc (Chebyshev interpolant of u over sqrt(1 - s^2)), 0 outside."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        sy, out = self.sys, np.zeros(phi.shape)
        U, C = sy.split(v)
        x = np.angle(np.exp(1j * phi)) / self.eps
        inside = np.abs(x) < 1
        T = np.cos(np.outer(np.arccos(x[inside]), np.arange(sy.n)))
        val = T @ (sy.D @ U[0])
        if sy.m:
            val = val + C[0] @ _en._g(x[inside])[:sy.m]
        out[inside] = val / (self.eps * np.sqrt(1 - x[inside] ** 2))
        return out


def nodes(eps, ar):
    """Node count for one arc (numerics.arcs.nodes_for): ~1e-12 at alpha* = 0, ~1e-11 otherwise."""
    return _arcs.nodes_for(eps, ar)


def resolved_a_max(ar):
    """The largest contact parameter the node policy resolves: beyond it the node count is capped (the density
    varies on the scale of the gap pi - eps between the arc's ends) and the states lose digits (~1e-10 at twice
    this a).  Found on the policy itself: the first a, up a geometric ladder, whose node count is the cap."""
    cap = nodes(math.pi - 1e-12, ar)
    a = 10.0
    while nodes(2 * math.atan(a * 1.05), ar) < cap:
        a *= 1.05
    return a


@functools.lru_cache(maxsize=None)
def _half_tables(n, enriched):
    """The tables of numerics.arcs._tables restricted to the table points x >= 0 (the even half of one arc)."""
    _, _, xt, _, Lam, Sig, omega, _, LD0, SD0 = _arcs._tables(n, enriched)
    # the first (n + 1)//2 nodes (descending: x >= 0), then the end points; not xt >= 0, which drops the middle
    # node of an odd n when cos(pi/2) rounds below 0 (the kernel then read past its right-hand side)
    keep = np.concatenate([np.arange((n + 1) // 2), np.arange(n, xt.size)])
    cut = lambda T: np.ascontiguousarray(T[:, keep, :]) if T.shape[0] else T
    return (np.ascontiguousarray(xt[keep]), np.ascontiguousarray(LD0[keep]), np.ascontiguousarray(SD0[keep]),
            cut(Lam), cut(Sig), omega)


def _engine(n, theta, gb, ar):
    """The arguments of the numba kernels (numerics.one_arc_kernels) at n nodes: the half tables and the kernel
    constants."""
    xt, LD0, SD0, Lam, Sig, omega = _half_tables(n, ar != 0.0)
    sf, gf = _arcs._fine_grid()
    kernel = _arcs.Kernel(theta, gb, ar)
    return (_arcs._nodes(n), _arcs._cheb_matrix(n), xt, LD0, SD0, Lam, Sig, omega, _G_END[:omega.shape[0]], sf, gf,
            kernel.k0, kernel.k1, float(ar), _en.K_TRIG)


def arc_state(a, k, theta, gb, ar, clearance=1.0, even=True):
    """:data:`ArcState` at one contact parameter (no slopes): one call of the even kernel, or (even=False) the
    full system of :class:`OneArc` (the reference the tests compare the kernel with)."""
    eps = 2 * math.atan(a)
    n = nodes(eps, ar)
    if not even:
        return OneArc(eps, theta, gb, ar, n).state(k, clearance)[0]
    out = np.empty(_ok.N_OUT)
    _ok.bordered_state_even(eps, k, clearance, *_engine(n, theta, gb, ar), out)
    return ArcState(*out)


def arc_states(a, k, theta, gb, ar, clearance=1.0, pole=math.inf, rel_step=5e-6):
    """ArcStates at the contact parameters a (1-D) and slopes d/da of p and d, per point.

    Slopes are central differences of the PHYSICAL state (bordered solves at a +- h with the same node count):
    smooth in a where the unit cases are not (the det A poles).  The step h = rel_step min(a, |a - pole|) scales
    with the distance to the nearest singularity (a = 0, the receding-contact pole a_crit), so truncation
    ~ rel_step^2 and rounding ~ 1e-16/rel_step stay relative errors there too.  Returns (states: dict of arrays
    of ArcState fields, slopes: dict of arrays dp_da, dd_da); the points are grouped by node count, each group
    one numba call (numerics.one_arc_kernels.arc_states)."""
    a = np.atleast_1d(np.asarray(a, dtype=float))
    n_of = np.array([nodes(2 * math.atan(x), ar) for x in a.tolist()], dtype=int)
    out, sl = np.empty((a.size, _ok.N_OUT)), np.empty((a.size, 2))
    for n in np.unique(n_of):
        sel = n_of == n
        out[sel], sl[sel] = _ok.arc_states(np.ascontiguousarray(a[sel]), k, clearance, pole, rel_step,
                                           *_engine(int(n), theta, gb, ar))
    states = {f: out[:, i] for i, f in enumerate(ArcState._fields)}
    return states, {"dp_da": sl[:, 0], "dd_da": sl[:, 1]}


@functools.lru_cache(maxsize=64)
def receding_contact(theta, gb, ar, search=(0.05, 1e4)):
    """a_crit of the pair: the zero of 1/p on adhesionless states (p -> +inf below, -inf above); a sign change of
    1/p through a pole (p = 0) is not a root.  inf when none lies in the search range (beyond 1e4: a contact
    within 2e-4 rad of the full circle).  Independent of M and Delta."""
    def f(x, _):
        return 1.0 / arc_state(x, 0.0, theta, gb, ar).p
    grid = np.geomspace(*search, 60)
    vals = np.array([f(x, ()) for x in grid])
    for i in np.nonzero((vals[:-1] > 0) & (vals[1:] <= 0))[0]:
        r = _roots.brent_or_pole(f, grid[i], grid[i + 1], (), vals[i], vals[i + 1])
        if r is not None:
            return float(r)
    return math.inf
