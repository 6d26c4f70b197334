"""Two contact arcs under the Maugis-Dugdale law: the pin touching the bottom |phi| < eps and the top
|phi - pi| < eps_top, each contact edge with a finite stress (edge coefficient k = 0), the gap between them under
the traction -s0 wherever 0 < h <= h0.

Notation of jkrcyl.numerics.cohesive (kernel scale: nu = N R beta*/(4 pi Delta), p = int nu cos(phi) dphi,
lengths over Delta, h0 = m^2/s0).  The zone set C (contacts included) is the bottom zone |phi| < c and the top
zone |phi - pi| < c_top (c > eps, c_top > eps_top), or the whole circle when the gap is everywhere within h0
('all', c + c_top >= pi).  With v = nu + s0 on the arcs (the zone traction continued over the contacts, so the
traction jumps sit at the zone ends, off the arcs), on both arcs

    -int_arcs v K(phi - psi) dpsi = (delta/Delta) cos(phi) - (1 - cos(phi)) - s0 Z_C(phi),
    h/Delta = (1 - cos(phi)) - (delta/Delta) cos(phi) - int_arcs v K + s0 Z_C(phi)             (outside),

the same equations as one arc (jkrcyl.numerics.cohesive) on the two-arc collocation of jkrcyl.numerics.arcs (one
LU per pair of arcs, the clearance, approach and zone right-hand sides).  At fixed arcs the state is affine in
delta: k_bot = 0 fixes delta, the zone ends solve h(c) = h0 and h(pi - c_top) = h0, and the remaining condition
k_top = 0 is one scalar equation F(eps, eps_top) = k_top whose zero set is the two-patch branch (as JKR's F of
jkrcyl.model.two_patch with Griffith k = M/pi replaced by the zones and k = 0).

Zones 'all' (one zone spanning the gap): Z_C is the constant Z_all = 2 pi (k0 - 1 + ar) on the circle, a
combination of the clearance and approach right-hand sides, so the fixed-arc state is JKR's adhesionless two-arc
state of the clearance (1 + s0 Z_all) Delta at the approach delta - s0 Z_all Delta (:func:`state` with c = pi;
tests: the direct solve agrees).  Its equilibria are the zeros of the adhesionless F (k = 0 at both edges), the
same for every s0: scans at M = 0.2, identical bodies (eps_top = 0.36, 1.0, 25 arcs each), found none between
the pole of the fixed-arc system and full contact, where k_top -> 0 -- the zone spanning the gap is the end of
the two-patch states at full contact, not a family of its own there.  :func:`solve` finds the states with a
zone at each edge.

Node count: the zone's traction jump sits a zone length d = c - eps off the arc: Chebyshev converges like the
Bernstein ellipse through it, n ~ NODES_PER_ZONE sqrt(eps/d) per arc (jkrcyl.numerics.cohesive_contact), with the
near-touching arcs' count of jkrcyl.numerics.two_arcs.  Where that exceeds NODES_LAYER_TWO the end layer of each
zone is subtracted in closed form (jkrcyl.numerics.cohesive_two_layer; the unknown is then v less the layers) and
NODES_LAYER_TWO nodes (or the near-touching count) resolve any lambda up to the law's LAMBDA_MAX: measured along
the whole branch at M = 0.2 (lambda = 20, 50), 64 nodes per arc are within 1e-10 in P* of 128 (48: 1e-8, 2e-7),
and a state at lambda = 50 within 3e-10 of the unlayered solve at 760 nodes.  alpha* = 0 only here (the pairs of
the JKR-limit checks).
Stability: jkrcyl.numerics.cohesive_two_stability (the energy of zone-end-held states).
"""
import math
from collections import namedtuple

import numpy as np
from scipy.linalg import lu_factor, lu_solve

from . import arcs as _arcs
from . import cohesive as _co
from . import cohesive_two_layer as _layer
from . import roots as _roots
from . import two_arcs as _two

NODES_MAX_TWO = 1000      # nodes per arc without the end layers (a dense LU of 2000 unknowns: ~1 s)
NODES_LAYER_TWO = 64      # nodes per arc with the end layers subtracted, at least (module docstring)
ZONE_SWEEPS = 40        # Newton steps at most

TwoPatchCohesive = namedtuple("TwoPatchCohesive", [
    "eps", "eps_top", "c", "c_top", "zones", "p", "delta_over_Delta", "B", "k_bot", "k_top", "m", "s0",
    "h0_over_Delta", "n", "fields"])
TwoPatchCohesive.__doc__ = """A Maugis-Dugdale state with two contact arcs (normalised; module docstring).

c, c_top: the zone ends (pi, 0 when the zone spans the gap: zones 'all'); zones: 'both' or 'all'; p, B: int nu
cos(phi), int nu; k_bot, k_top: the edge coefficients (0 in equilibrium; k_top is the residual F); n: nodes
per arc; fields: .gap(phi), .pressure(phi)."""


def nodes(eps, eps_top, d, ar=0.0, layered=False):
    """Nodes per arc for arcs eps, eps_top whose nearest zone end is d away (module docstring); layered: with the
    end layers subtracted (cohesive_two_layer), independent of d."""
    n = max(_two.nodes(eps, eps_top, NODES_LAYER_TWO if layered else _two.N_NODES, ar),
            _arcs.nodes_for(max(eps, eps_top), ar))
    if layered:
        return n
    need = _co.NODES_PER_ZONE * math.sqrt(max(eps, eps_top) / d) if d > 0 else 0.0
    n = max(n, int(need))
    if n > NODES_MAX_TWO:
        raise ValueError(f"sigma0 is too large for the two-arc cohesive solver without its end layers: its zones "
                         f"(~{d:.3g} rad) need {n} > {NODES_MAX_TWO} nodes per arc")
    return n


def needs_layers(eps, eps_top, d):
    """Whether zones d away from the arcs need more nodes than the layered count (then the layers are subtracted:
    a bounded node count for any lambda)."""
    return d > 0 and _co.NODES_PER_ZONE * math.sqrt(max(eps, eps_top) / d) > NODES_LAYER_TWO


def _wrap(phi):
    """phi wrapped to [-pi, pi], angles already there unchanged (not rounded: the gap at a thin zone's end moves
    by ~1e-12 per ulp of the angle at lambda = 1000)."""
    phi = np.asarray(phi, dtype=float)
    return np.where(np.abs(phi) <= math.pi, phi, np.angle(np.exp(1j * phi)))


class FixedArcs:
    """The two arcs with n nodes each: one LU, the clearance and approach solutions, and the zone solutions."""

    def __init__(self, eps, eps_top, kernel, n, layered=False):
        if not (0 < eps < math.pi and 0 < eps_top < math.pi and eps + eps_top < math.pi):
            raise ValueError(f"eps, eps_top must be in (0, pi) with eps + eps_top < pi, got {eps!r}, {eps_top!r}")
        self.eps, self.eps_top, self.kernel = float(eps), float(eps_top), kernel
        sy = self.sys = _arcs.Arcs([(0.0, self.eps), (math.pi, self.eps_top)], kernel, int(n))
        if sy.A.shape[0] != 2 * sy._xt.size or not np.all(np.isfinite(sy.A)):
            raise ValueError(f"eps = {eps!r}, eps_top = {eps_top!r}: the collocation system is not finite")
        self.factor()
        U = self.solve(sy._rhs)
        self.u0, self.u1 = U[:, 0], U[:, 1]
        self.points = _wrap(np.concatenate([c + e * sy._xt for c, e in zip(sy._ac, sy._ae)]))
        self.k0, self.k1 = sy.edge(self.u0), sy.edge(self.u1)
        self.layers = _layer.Layers(self.eps, self.eps_top, kernel, self.points) if layered else None

    def factor(self):
        """LU of the collocation matrix (a subclass may precondition with a neighbour's instead)."""
        self.lu = lu_factor(self.sys.A, check_finite=False)

    def solve(self, rhs):
        """A^-1 rhs."""
        return lu_solve(self.lu, rhs)

    def ends(self, zones):
        """(c, c_top) whose end layers are subtracted (cohesive_two_layer), or None."""
        return None if self.layers is None else _layer.zone_ends(zones)

    def zone_unit(self, zones):
        """The solution of a unit zone traction (s0 = 1) on the zone set: rhs -Z_C at the collocation points, plus
        the end layers' potential where they are subtracted (the solution is then w, v less the layers)."""
        rhs = -_co.zone_displacement(self.points, zones, self.kernel)
        ends = self.ends(zones)
        return self.solve(rhs if ends is None else rhs + self.layers.rhs(*ends))

    def zone_totals(self, zones):
        """(int, int cos) -> (load, width) a unit zone traction adds to p, B beyond u's moments: -(the zones') plus
        the end layers'."""
        load, width = _co.zone_load(zones)
        ends = self.ends(zones)
        lp, lb = (0.0, 0.0) if ends is None else self.layers.loads(*ends)
        return lp - load, lb - width

    def gap(self, phi, dn, u, zones, s0):
        """h/Delta at exterior angles phi."""
        phi = _wrap(np.atleast_1d(phi))
        h = (1 - np.cos(phi) - dn * np.cos(phi) + self.sys.apply(np.zeros_like(phi), phi, u)
             + s0 * _co.zone_displacement(phi, zones, self.kernel))
        ends = self.ends(zones)
        return h if ends is None else h - s0 * self.layers.at(phi, *ends)

    def at_zones(self, zones, s0):
        """(delta/Delta, u, k) at the zone set with k_bot = 0."""
        uz = self.zone_unit(zones)
        kz = self.sys.edge(uz)
        dn = -(self.k0[0] + s0 * kz[0]) / self.k1[0]
        return dn, self.u0 + dn * self.u1 + s0 * uz, self.k0 + dn * self.k1 + s0 * kz


class _Fields:
    """Gap and pressure of a solved two-arc state."""

    def __init__(self, fa, dn, u, zones, s0):
        self.fa, self.dn, self.u, self.zones, self.s0 = fa, dn, u, zones, s0

    def gap(self, phi):
        """h/Delta at angles phi (0 on the arcs)."""
        phi = _wrap(np.atleast_1d(phi))
        out = np.zeros_like(phi)
        ext = (np.abs(phi) > self.fa.eps) & (np.abs(phi) < math.pi - self.fa.eps_top)
        out[ext] = self.fa.gap(phi[ext], self.dn, self.u, self.zones, self.s0)
        return out

    def pressure(self, phi):
        """nu(phi): v - s0 on the arcs, -s0 on the zones, 0 elsewhere."""
        phi = _wrap(np.atleast_1d(phi))
        lin = self.fa.sys
        out = np.zeros_like(phi)
        for lo, hi in self.zones:
            out[(phi > lo) & (phi < hi)] = -self.s0
        U, C = lin.split(self.u)
        ends = self.fa.ends(self.zones)
        layer = 0.0 if ends is None else self.s0 * self.fa.layers.traction(phi, *ends)
        for i, (c, e) in enumerate(lin.arcs):
            x = _wrap(phi - c) / e
            inside = np.abs(x) < 1
            val = np.cos(np.outer(np.arccos(x[inside]), np.arange(lin.n))) @ (lin.D @ U[i])
            out[inside] = val / (e * np.sqrt(1 - x[inside] ** 2)) - self.s0
        return out + layer


class _Law:
    """m, s0, h0, the kernel and the fixed arcs met so far (one LU per pair of arcs and node count)."""

    def __init__(self, m, s0, kernel, layered=False):
        self.m, self.s0, self.kernel, self.h0, self.layered = m, s0, kernel, m * m / s0, bool(layered)
        self._arcs = {}

    def arcs(self, eps, eps_top, n):
        key = (eps, eps_top, n)
        if key not in self._arcs:
            if len(self._arcs) > 8:
                self._arcs.clear()
            self._arcs[key] = FixedArcs(eps, eps_top, self.kernel, n, self.layered)
        return self._arcs[key]

    def pieces(self, eps, eps_top, zones, n):
        """(fixed arcs, delta/Delta, u, k) at the zone set with k_bot = 0."""
        fa = self.arcs(eps, eps_top, n)
        return (fa,) + fa.at_zones(zones, self.s0)

    def residual(self, x, eps_top, n):
        """[k_top, h(c) - h0, h(pi - c_top) - h0] at x = (eps, log d_bot, log d_top) (None: the zones meet)."""
        eps, d = x[0], np.exp(x[1:])
        if not 0 < eps < math.pi - eps_top or d.sum() >= math.pi - eps - eps_top:
            return None
        zones = _co.zones_of(eps + d[0], eps_top + d[1])
        fa, dn, u, k = self.pieces(eps, eps_top, zones, n)
        h = fa.gap(np.array([eps + d[0], math.pi - eps_top - d[1]]), dn, u, zones, self.s0)
        return np.array([k[1], h[0] - self.h0, h[1] - self.h0])


def state(law, eps, eps_top, c, c_top, n):
    """The two-arc state with the zone ends c, c_top (c = pi: zones 'all') at k_bot = 0 (k_top reported)."""
    zones = _co.zones_of(c, c_top)
    fa, dn, u, k = law.pieces(eps, eps_top, zones, n)
    load, width = fa.zone_totals(zones)
    p = fa.sys.moments(u, np.cos) + law.s0 * load
    B = fa.sys.moments(u, np.ones_like) + law.s0 * width
    kind = "all" if zones.shape[0] == 1 else "both"
    return TwoPatchCohesive(eps, eps_top, math.pi if kind == "all" else c, 0.0 if kind == "all" else c_top, kind,
                            p, dn, B, k[0], k[1], law.m, law.s0, law.h0, n, _Fields(fa, dn, u, zones, law.s0))


def solve(eps_top, m, s0, theta, gb, ar, guess, n=None, tol=1e-11, layered=None):
    """The two-arc equilibrium with the top arc eps_top (k = 0 at both contact edges, h = h0 at both zone ends):
    Newton in (eps, log d_bot, log d_top) from eps = guess (e.g. JKR's two-patch state there, the limit
    lambda -> inf) and the Dugdale zone length (finite differences: one more LU per step for eps; the step
    halved while the residual grows).  layered: subtract the end layers (None: where the zones need more nodes
    than NODES_LAYER_TWO, :func:`needs_layers`).  ValueError naming guess if it does not converge."""
    m, s0, kernel = _co._law(m, s0, theta, gb, ar)
    eps_top = _co.finite_scalar("eps_top", eps_top, low=0.0, high=math.pi, low_open=True)
    guess = _co.finite_scalar("guess", guess, low=0.0, high=math.pi - eps_top, low_open=True)
    if m == 0.0 or ar != 0.0:
        raise ValueError(f"m must be > 0 and ar = 0 for the two-arc cohesive solver, got m = {m!r}, ar = {ar!r}")
    if guess + eps_top >= math.pi:
        raise ValueError(f"guess must be < pi - eps_top = {math.pi - eps_top!r}, got {guess!r}")
    d0 = min(_co.dugdale_zone(m, s0), 0.25 * (math.pi - guess - eps_top))
    layered = needs_layers(guess, eps_top, d0) if layered is None else bool(layered)
    if layered:
        _layer.check_lambda(m, s0)
    law = _Law(m, s0, kernel, layered)
    n = nodes(guess, eps_top, d0, ar, layered) if n is None else _co.count("n", n, 8, NODES_MAX_TWO)
    x = newton(lambda y: law.residual(y, eps_top, n), np.array([guess, math.log(d0), math.log(d0)]),
               (1e-7 * guess, 1e-6, 1e-6), np.array([max(1.0, m), max(1.0, law.h0), max(1.0, law.h0)]), tol,
               np.array([0.2 * guess, 2.0, 2.0]))
    if x is None:
        raise ValueError(f"guess: no cohesive two-patch state (zones at both edges) found near eps = {guess!r}")
    d = np.exp(x[1:])
    return state(law, x[0], eps_top, x[0] + d[0], eps_top + d[1], n)


def newton(f, x, steps, scale, tol, largest):
    """Newton on f(x) = 0 (f: a vector, None outside its domain) with a forward-difference Jacobian (steps), each
    step cut to |dx_i| <= largest_i and halved while |f/scale| grows (jkrcyl.numerics.roots.damped_newton); x
    where |f_i| < tol scale_i, else None (no convergence in ZONE_SWEEPS steps, a singular Jacobian, or the domain
    left).  A few unknowns of fixed-arc solves."""
    def jacobian(x, r):
        J = np.empty((x.size, x.size))
        for i in range(x.size):
            xi = x.copy()
            xi[i] += steps[i]
            ri = f(xi)
            if ri is None:
                return None
            J[:, i] = (ri - r) / steps[i]
        return J if np.linalg.cond(J) < 1e14 else None

    got = _roots.damped_newton(f, x, jacobian, scale, tol, largest, ZONE_SWEEPS, 12)
    return None if got is None else got[0]


def potential(st):
    """Total potential in the kernel scale (units 4 pi Delta^2/beta*), as jkrcyl.numerics.cohesive_branch.potential:
    [(1 + delta/Delta) p - B]/2 + (s0/2) int_zones h - m^2 (length of contacts and zones), by Gauss-Legendre on
    each zone (clustered at both ends)."""
    xg, wg = np.polynomial.legendre.leggauss(96)
    t = np.pi * (xg + 1) / 2
    shape, jac = (1 - np.cos(t)) / 2, np.sin(t) * np.pi / 4
    if st.zones == "all":
        pieces = [(st.eps, math.pi - st.eps_top)]
        length = 2 * math.pi
    else:
        pieces = [(st.eps, st.c), (math.pi - st.c_top, math.pi - st.eps_top)]
        length = 2 * (st.c + st.c_top)
    H = sum(2 * (b - a) * np.sum(wg * jac * st.fields.gap(a + (b - a) * shape)) for a, b in pieces)
    return 0.5 * ((1 + st.delta_over_Delta) * st.p - st.B) + 0.5 * st.s0 * H - st.m ** 2 * length
