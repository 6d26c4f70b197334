"""A single patch off equilibrium: the state at a fixed arc is linear in the edge coefficient.

At a contact parameter a (eps = 2 atan a) the bottom patch whose edges carry nu ~ -k/sqrt(eps - |phi|) has every
field X (p = P beta*/(4 pi Delta), delta/Delta, delta_work/Delta, h(pi)/Delta, the bond term B of the elastic
energy) linear in k:

    X(a, k) = X0(a) + g X1(a),     g = k/k_eq,   k_eq = m/pi,   G/w = (pi k/m)^2 = g^2,

with X0 the adhesionless state (the single-patch solver at M = 0) and X1 = k_eq dX/dk|_a (the solver's
fixed-arc derivatives p_k, dn_k; dn_k + c p_k for delta_work), X0 + X1 the equilibrium.  A held P, delta or
delta_work then fixes g at every a, so G/w at both edges: the edge equation of jkrcyl.kinetics.integrate.

Two routes give (X0, X1) and their derivatives in u = log a, for any material pair:

* :class:`DirectArc`: the single-patch solver at each a (closed forms where alpha* = 0, collocation otherwise);
* :class:`TabulatedArc` (the default): the same states at the nodes of a uniform grid in u (shared between
  windows and cached per problem), interpolated by cubic Hermite polynomials with the solver's slopes (h and B:
  fourth-order differences over the nodes): error O(du^4), ~1e-10 at the grid step :data:`DU`.
"""
from __future__ import annotations

import functools
import math

import numpy as np
from numba import njit

from ..model.problem import Problem
from ..model.single_patch import solver

# the fields of an arc state, each as (adhesionless part X0, adhesive part X1)
FIELDS = ("p0", "p1", "dn0", "dn1", "dw0", "dw1", "h0", "h1", "B0", "B1")
P0, P1, DN0, DN1, DW0, DW1, H0, H1, B0, B1 = range(len(FIELDS))
HELD = {"load": (P0, P1), "grip": (DN0, DN1), "grip-work": (DW0, DW1)}
DU = 1.0 / 32        # grid step in log a of the tabulated route
_SLOPED = 6          # the first fields have the solver's own slopes; h and B take differences over the nodes


def adhesionless(problem: Problem) -> Problem:
    """The same pair and edge law without adhesion (M = 0): the X0 of every field."""
    return Problem(0.0, problem.theta, problem.gb, problem.alpha_ratio, problem.edge, False)


class DirectArc:
    """(X0, X1) and d/du at any a from the single-patch solver (two solves per point: at m and at 0)."""

    def __init__(self, problem: Problem):
        self.problem = problem
        self.solver, self.solver0 = solver(problem), solver(adhesionless(problem))
        self.k_eq = problem.edge.edge_coefficient(problem.m)
        self.work_shift = problem.work_shift

    def table(self, a):
        """(Y, D): arrays (len(a), 10) of the fields and their d/du (NaN for h and B) at the contact
        parameters a."""
        a = np.atleast_1d(np.asarray(a, dtype=float))
        s, s0 = self.solver.states(a), self.solver0.states(a)
        k, c = self.k_eq, self.work_shift
        p1, dn1 = k * s.p_k, k * s.dn_k
        Y = np.column_stack([s0.p, p1, s0.dn, dn1, s0.dw, dn1 + c * p1, s0.h, s.h - s0.h, s0.B, s.B - s0.B])
        nan = np.full(a.size, np.nan)
        D = np.column_stack([s0.dp_da, s.dp_da - s0.dp_da, s0.ddn_da, s.ddn_da - s0.ddn_da, s0.ddw_da,
                             s.ddw_da - s0.ddw_da, nan, nan, nan, nan]) * a[:, None]
        return Y, D

    def at(self, u):
        """(y, dy/du) at one u = log a (1-D arrays of the 10 fields)."""
        Y, D = self.table(np.array([math.exp(u)]))
        return Y[0], D[0]

    def covers(self, u) -> bool:
        return True


class NodeCache:
    """The arc fields at the nodes s = i DU (i an integer) of one problem, computed once each.

    The grid variable s = log a - log(1 - a/a_crit) is log a for small contacts and stretches the approach to
    the pole of the load at a_crit (section 4), where the fields vary on the scale a_crit - a."""

    def __init__(self, problem: Problem):
        self.direct = DirectArc(problem)
        self.a_crit = float(self.direct.solver.a_crit)
        self.values = {}

    def a_of(self, s):
        """The contact parameter at the grid variable s."""
        e = np.exp(s)
        return e if math.isinf(self.a_crit) else e * self.a_crit / (self.a_crit + e)

    def s_of(self, u: float) -> float:
        """The grid variable at u = log a (inf at and beyond a_crit)."""
        x = math.exp(u) / self.a_crit
        return u - math.log1p(-x) if x < 1 else math.inf

    def window(self, i_lo: int, i_hi: int):
        """(s, Y, D) over the nodes i_lo..i_hi, D = dY/ds: the solver's slopes, for h and B fourth-order
        differences over the nodes."""
        need = [i for i in range(i_lo - 2, i_hi + 3) if i not in self.values]
        if need:
            a = self.a_of(np.array(need, dtype=float) * DU)
            Y, D = self.direct.table(a)
            D *= (1.0 - a / self.a_crit)[:, None]                      # d/du -> d/ds
            for j, i in enumerate(need):
                self.values[i] = (Y[j], D[j])
        Y = np.array([self.values[i][0] for i in range(i_lo - 2, i_hi + 3)])
        D = np.array([self.values[i][1] for i in range(i_lo + 0, i_hi + 1)])
        D[:, _SLOPED:] = (Y[:-4, _SLOPED:] - 8 * Y[1:-3, _SLOPED:] + 8 * Y[3:-1, _SLOPED:]
                          - Y[4:, _SLOPED:]) / (12 * DU)
        s = np.arange(i_lo, i_hi + 1) * DU
        return s, np.ascontiguousarray(Y[2:-2]), np.ascontiguousarray(D)


@functools.lru_cache(maxsize=16)
def nodes(problem: Problem) -> NodeCache:
    return NodeCache(problem)


@njit(cache=True)
def hermite(u, u_first, du, Y, D):
    """Cubic Hermite interpolation on the uniform grid u_first + i du of values Y and slopes D (rows: nodes),
    clamped to the grid: (y, dy/du)."""
    n = Y.shape[0]
    x = (u - u_first) / du
    if x < 0.0:
        x = 0.0
    if x > n - 1.0:
        x = n - 1.0
    i = min(int(x), n - 2)
    t = x - i
    t2, t3 = t * t, t * t * t
    h00, h10, h01, h11 = 2 * t3 - 3 * t2 + 1, t3 - 2 * t2 + t, -2 * t3 + 3 * t2, t3 - t2
    d00, d10, d01, d11 = (6 * t2 - 6 * t) / du, 3 * t2 - 4 * t + 1, (-6 * t2 + 6 * t) / du, 3 * t2 - 2 * t
    y = h00 * Y[i] + h10 * du * D[i] + h01 * Y[i + 1] + h11 * du * D[i + 1]
    dy = d00 * Y[i] + d10 * D[i] + d01 * Y[i + 1] + d11 * D[i + 1]
    return y, dy


class TabulatedArc:
    """(X0, X1) and d/du interpolated over u = log a in [u_lo, u_hi] (extended to whole nodes; below a_crit)."""

    def __init__(self, problem: Problem, u_lo: float, u_hi: float):
        self.problem = problem
        self.cache = nodes(problem)
        s_lo, s_hi = self.cache.s_of(u_lo), self.cache.s_of(u_hi)
        if not math.isfinite(s_hi):
            raise ValueError(f"a must be < a_crit = {self.cache.a_crit!r} for the tabulated arc states, got "
                             f"{math.exp(u_hi)!r}")
        i_lo, i_hi = math.floor(s_lo / DU), math.ceil(s_hi / DU)
        self.s, self.Y, self.D = self.cache.window(i_lo, max(i_hi, i_lo + 1))
        self.s_first = float(self.s[0])
        self.u_first, self.u_last = (math.log(float(self.cache.a_of(x))) for x in (self.s[0], self.s[-1]))
        self.inv_a_crit = 1.0 / self.cache.a_crit

    def at(self, u):
        """(y, dy/du) at one u = log a."""
        x = math.exp(u) * self.inv_a_crit
        if x >= 1.0:
            x = 1.0 - 1e-16
        y, dy = hermite(u - math.log1p(-x), self.s_first, DU, self.Y, self.D)
        return y, dy / (1.0 - x)

    def covers(self, u) -> bool:
        return self.u_first <= u <= self.u_last
