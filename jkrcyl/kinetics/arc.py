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
* :class:`TabulatedArc` (the default): Chebyshev series of the same states on panels of unit width in
  s ~ log a (:class:`PanelCache`: shared between windows, cached per problem), ORDER terms each.
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
PANEL = 1.0          # width of a Chebyshev panel of the tabulated route in s ~ log a
ORDER = 16           # terms per panel: the series' error ~1e-14 relative


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


class PanelCache:
    """Chebyshev series of the arc fields on the panels [i, i + 1] PANEL of one problem, each computed once.

    The grid variable s = log a - log(1 - a/a_crit) is log a for small contacts and stretches the approach to
    the pole of the load at a_crit (section 4), where the fields vary on the scale a_crit - a.  Within a panel
    the series is smooth (an integrator with a high-order error control then takes long steps); between
    panels the fields jump by the series' error."""

    def __init__(self, problem: Problem):
        self.direct = DirectArc(problem)
        self.a_crit = float(self.direct.solver.a_crit)
        self.panels = {}

    def a_of(self, s):
        """The contact parameter at the grid variable s."""
        e = np.exp(s)
        return e if math.isinf(self.a_crit) else e * self.a_crit / (self.a_crit + e)

    def s_of(self, u: float) -> float:
        """The grid variable at u = log a (inf at and beyond a_crit)."""
        x = math.exp(u) / self.a_crit
        return u - math.log1p(-x) if x < 1 else math.inf

    def window(self, i_lo: int, i_hi: int):
        """(C, CD): the series of the fields and of their d/ds on the panels i_lo..i_hi (arrays panel x field x
        term, in x = 2 (s - s_i)/PANEL - 1)."""
        need = [i for i in range(i_lo, i_hi + 1) if i not in self.panels]
        if need:
            k = np.arange(ORDER)
            x = np.cos(math.pi * (k + 0.5) / ORDER)                      # Chebyshev points of the first kind
            s = ((np.array(need)[:, None] + 0.5 * (x[None, :] + 1.0)) * PANEL).ravel()
            Y, _ = self.direct.table(self.a_of(s))
            T = np.cos(math.pi * np.outer(k, k + 0.5) / ORDER) * (2.0 / ORDER)
            T[0] *= 0.5
            for j, i in enumerate(need):
                c = Y[j * ORDER:(j + 1) * ORDER].T @ T.T                   # fields x terms
                self.panels[i] = (c, _derivative(c) * (2.0 / PANEL))
        C = np.array([self.panels[i][0] for i in range(i_lo, i_hi + 1)])
        CD = np.array([self.panels[i][1] for i in range(i_lo, i_hi + 1)])
        return np.ascontiguousarray(C), np.ascontiguousarray(CD)


def _derivative(c):
    """The Chebyshev coefficients of d/dx of the series c (rows: fields)."""
    n = c.shape[1]
    d = np.zeros_like(c)
    for j in range(n - 2, -1, -1):
        d[:, j] = (d[:, j + 2] if j + 2 < n else 0.0) + 2 * (j + 1) * c[:, j + 1]
    d[:, 0] *= 0.5
    return d


@functools.lru_cache(maxsize=16)
def panels(problem: Problem) -> PanelCache:
    return PanelCache(problem)


@njit(cache=True)
def chebyshev(s, s_first, width, C, CD):
    """The series C (and CD, their derivatives) on the panels of ``width`` from s_first, at s clamped to them:
    (y, dy/ds) by Clenshaw's recurrence."""
    n_panels, n_fields, n = C.shape
    i = int(math.floor((s - s_first) / width))
    i = min(max(i, 0), n_panels - 1)
    x = 2.0 * (s - s_first - i * width) / width - 1.0
    x = min(max(x, -1.0), 1.0)
    y, dy = np.empty(n_fields), np.empty(n_fields)
    for f in range(n_fields):
        b1, b2, d1, d2 = 0.0, 0.0, 0.0, 0.0
        for j in range(n - 1, 0, -1):
            b1, b2 = 2.0 * x * b1 - b2 + C[i, f, j], b1
            d1, d2 = 2.0 * x * d1 - d2 + CD[i, f, j], d1
        y[f] = x * b1 - b2 + C[i, f, 0]
        dy[f] = x * d1 - d2 + CD[i, f, 0]
    return y, dy


class TabulatedArc:
    """(X0, X1) and d/du from Chebyshev panels over u = log a in [u_lo, u_hi] (widened to whole panels; below
    a_crit)."""

    def __init__(self, problem: Problem, u_lo: float, u_hi: float):
        self.problem = problem
        self.cache = panels(problem)
        s_lo, s_hi = self.cache.s_of(u_lo), self.cache.s_of(u_hi)
        if not math.isfinite(s_hi):
            raise ValueError(f"a must be < a_crit = {self.cache.a_crit!r} for the tabulated arc states, got "
                             f"{math.exp(u_hi)!r}")
        i_lo, i_hi = math.floor(s_lo / PANEL), math.floor(s_hi / PANEL)
        self.C, self.CD = self.cache.window(i_lo, i_hi)
        self.s_first = i_lo * PANEL
        self.u_first = math.log(float(self.cache.a_of(i_lo * PANEL)))
        self.u_last = math.log(float(self.cache.a_of((i_hi + 1) * PANEL)))
        self.inv_a_crit = 1.0 / self.cache.a_crit

    def at(self, u):
        """(y, dy/du) at one u = log a."""
        x = math.exp(u) * self.inv_a_crit
        if x >= 1.0:
            x = 1.0 - 1e-16
        y, dy = chebyshev(u - math.log1p(-x), self.s_first, PANEL, self.C, self.CD)
        return y, dy / (1.0 - x)

    def covers(self, u) -> bool:
        return self.u_first <= u <= self.u_last
