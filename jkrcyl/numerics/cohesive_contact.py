"""The fixed contact of the Maugis-Dugdale solver (jkrcyl.numerics.cohesive, notation there): the collocation
system of a contact |phi| < eps (jkrcyl.numerics.arcs) factored once, its unit solutions and linear functionals,
the Dugdale end layer's tables when it is subtracted (jkrcyl.numerics.cohesive_layer), and the node policy.

Every array a compiled kernel (jkrcyl.numerics.cohesive_kernels, cohesive_roots) indexes is built and
size-checked here: eps must lie in (0, pi) (a NaN once dropped the arc, leaving an empty system whose LU the
unit solutions then read past -- a segmentation fault), n in [8, NODES_MAX], the system square and finite; the
zones and unknown vectors callers pass are checked by shape.
"""
import math

import numpy as np
from scipy.linalg.lapack import dgetrf as _dgetrf
from threadpoolctl import ThreadpoolController

from . import arcs as _arcs
from . import arcs_enrich as _en
from . import cohesive_kernels as _ck
from . import cohesive_layer as _cl
from . import cohesive_roots as _cr

_BLAS = ThreadpoolController()
_UNFACTORED = (np.zeros((0, 0)), np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros(0), np.zeros(0), math.nan, math.nan)
_NO_LAYER = np.zeros(1)
_NO_TABLE = np.zeros((0, _cl.N_SMOOTH))
NODES_MIN = 24            # alpha* = 0: a contact far from its zone ends (spectral, ~1e-13)
NODES_PER_ZONE = 11       # nodes per sqrt(eps/(c - eps)): the Bernstein ellipse through the zone end (~1e-9)
NODES_MAX = 1024
NODES_ALPHA = 8           # alpha* != 0: node counts in multiples of 8 (one enrichment table per count)
NODES_MAX_ALPHA = 256
LAYER_NODES = 48          # a zone needing more nodes than this has its end layer subtracted (contact_nodes)
NODES_LAYER = 32          # nodes with the end layer subtracted (alpha* = 0: ~1e-12, tests/test_cohesive_layer.py)
NODES_LAYER_ALPHA = 64    # the same at alpha* != 0 (the enrichment's algebraic rate: ~1e-9 at |alpha*/beta*| = 0.2)
LAPACK_NODES = 96         # above: LAPACK's LU (blocked), below: the compiled one (no call overhead)
SCAN_FACTOR = 1.25        # upward scan for the first zone-end root: steps x 1.25, at most 0.05 rad
SCAN_STEP = 0.05


def _factor(A):
    """LU of the collocation matrix: compiled for small systems, LAPACK getrf on one BLAS thread above
    LAPACK_NODES (threaded BLAS calls leave workers spinning that slow the small solves that follow)."""
    if A.shape[0] <= LAPACK_NODES:
        return _ck.lu_factor(A)
    with _BLAS.limit(limits=1, user_api="blas"):
        lu, piv, _ = _dgetrf(A)
    return lu, _ck.perm_of_pivots(piv)


class FixedContact:
    """The contact |phi| < eps with n nodes: one LU, the unit solutions and the linear functionals.

    Unknown vector u of jkrcyl.numerics.arcs (node values, then the alpha* enrichment), in nu units, for v; with
    layered=True the bottom zone's end layer is subtracted (jkrcyl.numerics.cohesive_layer): u is then v less
    the layer, whose load, gap and traction the methods below add (a thin zone with a JKR-like node count).

    With shift != 0 the system factored is A - shift cos(phi) k^T (k^T u: the edge coefficient) instead of the
    collocation matrix A: it has the same solutions with k = 0 (there A u and the shifted product agree), so every
    equilibrium (the zone end's residual, the state, its load) is unchanged, while the unit solutions and the
    affine coefficients in the approach belong to the shifted system -- k' = k/(1 - shift k(U1)) at a held
    approach (Sherman-Morrison).  A is singular at one contact eps_s of a kernel (where k(U1) has a pole: see
    jkrcyl.numerics.cohesive_bordered); the shifted system is not, so the states next to eps_s are regular
    (:func:`regular` shifts where |k(U1)| >= SHIFT_K).

    factor=False: the system assembled but not factored (no LU, unit solutions or k(U0), k(U1): those entries of
    fx are empty, k NaN), for a solver that factors a system of its own (jkrcyl.numerics.cohesive_bordered): the
    gap, the loads and the zone's right-hand side read the rest.
    """

    def __init__(self, eps, kernel, n, layered=False, shift=0.0, factor=True):
        eps = float(eps)
        if not 0.0 < eps < math.pi:                   # NaN too: arcs.Arcs would drop the arc (an empty system)
            raise ValueError(f"eps must be in (0, pi), got {eps!r}")
        if not (isinstance(n, (int, np.integer)) and 8 <= n <= NODES_MAX):
            raise ValueError(f"n must be an integer in [8, {NODES_MAX}], got {n!r}")
        self.eps, self.kernel, self.layered = eps, kernel, bool(layered)
        sy = self.sys = _arcs.Arcs([(0.0, self.eps)], kernel, int(n))
        npt = sy._xt.size
        if sy.A.shape != (npt, npt) or npt != sy.n + sy.m or not np.all(np.isfinite(sy.A)):
            raise ValueError(f"eps = {eps!r}, n = {n!r}: the collocation system is not square and finite "
                             f"(shape {sy.A.shape}, {npt} points)")
        phin = self.eps * sy._xt                      # collocation angles
        nn, mm = sy.n, sy.m
        ek = np.empty(nn + mm)                        # u -> k (arcs.Arcs.edge)
        ek[:nn] = -sy.D.sum(axis=0)
        ek[nn:] = -_en.G_END[:mm]
        self.ek = ek / math.sqrt(2 * self.eps)
        self.shift = float(shift)
        if factor:
            lu, perm = _factor(sy.A - self.shift * np.outer(np.cos(phin), self.ek) if self.shift else sy.A)
            U0, U1, kadj, k_0, k_1 = _ck.unit_solutions(lu, perm, phin, self.ek)
        else:
            lu, perm, U0, U1, kadj, k_0, k_1 = _UNFACTORED
        sf, gf = _arcs._fine_grid()
        if self.layered:                              # the layer's trig coefficients and smooth-moment table
            gc, gs = (sy._gcs[0], sy._gss[0]) if mm else _cl.trig_coefficients(self.eps, _en.K_TRIG)
            qmax = _cl.qmax_of(gc, gs)
            smooth = _cl.smooth_table(sy._xt, self.eps, kernel.k0, kernel.k1, kernel.ar, sy.n)
        else:
            gc = gs = _NO_LAYER
            qmax, smooth = 0, _NO_TABLE
        gc = np.ascontiguousarray(gc, dtype=float)
        self.fx = (lu, perm, phin, U0, U1, k_0, k_1, kadj, kernel.k0, kernel.k1,
                   kernel.ar, sy._ac, sy._ae, sy.s, sy.D, sy._Lam, sy._Sig, sy._omega, sy._gcs, sy._gss, sf, gf,
                   self.layered, self.eps, np.ascontiguousarray(sy._xt, dtype=float), gc,
                   np.ascontiguousarray(gs, dtype=float), qmax, smooth)
        nodes = self.eps * sy.s                       # u -> int v cos, int v (arcs.Arcs.moments)
        self.ep = self._moment_vector(np.cos(nodes))
        self.eb = self._moment_vector(np.ones_like(nodes))

    def _moment_vector(self, f):
        sy = self.sys
        out = np.empty(sy.n + sy.m)
        out[:sy.n] = math.pi / sy.n * f
        out[sy.n:] = [sy._mu[j] @ (sy.D @ f) for j in range(sy.m)]
        return out

    def _zones(self, zones):
        zones = np.ascontiguousarray(zones, dtype=float)
        if zones.ndim != 2 or zones.shape[1] != 2:
            raise ValueError(f"zones must be an array of (lo, hi) rows, got shape {zones.shape}")
        return zones

    def _u(self, u):
        u = np.ascontiguousarray(u, dtype=float)
        if u.shape != (self.sys.n + self.sys.m,):
            raise ValueError(f"u must have {self.sys.n + self.sys.m} entries, got shape {u.shape}")
        return u

    def solve(self, zones, s0):
        """(delta/Delta, u) with k = 0 for the zone set: v for the rhs clearance + delta cos - s0 Z (u without
        the end layer when it is subtracted)."""
        return _ck.solve_zone(self.fx, self._zones(zones), float(s0))

    def zone_unit(self, zones):
        """The solution u of a unit zone traction (s0 = 1) at delta = 0 less the clearance solution."""
        lu, perm = self.fx[:2]
        return _ck.lu_solve(lu, perm, _ck.zone_rhs(self.fx, self._zones(zones)))

    def layer_end(self, zones):
        """The zone end c whose end layer is subtracted, or None."""
        c = _ck.layer_end(self.fx, self._zones(zones))
        return None if c < 0 else c

    def load_width(self, u, zones, s0):
        """(p, B) = (int nu cos(phi), int nu) of the state (u, zones, s0): contact, zones and end layer."""
        pz, bz = _ck.zone_totals(self.fx, self._zones(zones), float(s0))
        u = self._u(u)
        return self.ep @ u + pz, self.eb @ u + bz

    def gap(self, phi, dn, u, zones, s0):
        """h/Delta at exterior angles phi."""
        phi = np.ascontiguousarray(np.atleast_1d(phi), dtype=float).ravel()
        if not np.all(np.isfinite(phi)):
            raise ValueError(f"phi must be finite angles, got {phi[~np.isfinite(phi)][:3]!r}")
        return _ck.gap(self.fx, phi, float(dn), self._u(u), self._zones(zones), float(s0))

    def state(self, s0, h0, d_start, c_top=0.0):
        """(zone length or None, delta/Delta, u, h(pi)/Delta) in one compiled call (cohesive_kernels.state)."""
        d, dn, u, h_pi = _cr.state(self.fx, self.eps, float(s0), float(h0), float(d_start), SCAN_FACTOR, SCAN_STEP,
                                   float(c_top))
        return (None if d < 0 else d), dn, u, h_pi

    def zone_end_near(self, s0, h0, d_near, c_top=0.0):
        """The zone length nearest to d_near with h(c) = h0 (None: none within a factor 100)."""
        d = _cr.zone_end_near(self.fx, self.eps, float(s0), float(h0), float(d_near), float(c_top))
        return None if d < 0 else d

    def zone_end(self, s0, h0, d_start, c_top=0.0):
        """Zone length c - eps with h(c) = h0 (None: h < h0 up to pi - c_top); see cohesive_kernels.zone_end."""
        d = _cr.zone_end(self.fx, self.eps, float(s0), float(h0), float(d_start), SCAN_FACTOR, SCAN_STEP,
                         float(c_top))
        return None if d < 0 else d


SHIFT_K = 20.0          # regular: a contact with |dk/d(delta)| >= SHIFT_K is next to the singular contact eps_s
SHIFT = 2 / SHIFT_K     # ... and its system is shifted by this (|1 - SHIFT k(U1)| >= 1 there: regular)


def regular(eps, kernel, n, layered=False, shifted=None):
    """The fixed contact eps, its system shifted (FixedContact: the same equilibria) where |dk/d(delta)| >= SHIFT_K:
    next to the contact eps_s where the collocation matrix is singular (k(U1) has a pole there; it is 0.1 .. 3
    over eps = 1e-3 .. 3.09 for four kernels away from it).  There the affine route's states carried
    5e-16/(eps - eps_s) relative error and a central difference at a held approach across eps_s was wrong:
    dp/d(delta) along a branch off by 1.5e-4 at 1e-3 from eps_s, O(1) at 1e-5.  shifted(eps, shift): a cache of
    shifted contacts."""
    fc = FixedContact(eps, kernel, n, layered)
    if abs(fc.fx[6]) < SHIFT_K:
        return fc
    return shifted(eps, SHIFT) if shifted is not None else FixedContact(eps, kernel, n, layered, shift=SHIFT)


def nodes_for(eps, zone, ar=0.0):
    """Nodes for the contact |phi| < eps with its zone end at eps + zone (zone >= 0), the layer not subtracted."""
    need = NODES_PER_ZONE * math.sqrt(eps / zone) if zone > 0 else 0.0
    n = min(max(NODES_MIN, _arcs.nodes_for(eps, ar), need), NODES_MAX)
    return int(n) if ar == 0.0 else int(min(NODES_ALPHA * math.ceil(n / NODES_ALPHA), NODES_MAX_ALPHA))


def contact_nodes(eps, zone, ar=0.0):
    """(n, layered) for the contact |phi| < eps with its zone end at eps + zone: nodes_for while the zone needs
    at most LAYER_NODES, else the end layer subtracted (jkrcyl.numerics.cohesive_layer) and NODES_LAYER nodes
    (a multiple of NODES_ALPHA at alpha* != 0; at least the Griffith count of jkrcyl.numerics.arcs.nodes_for)."""
    if zone <= 0 or NODES_PER_ZONE * math.sqrt(eps / zone) <= LAYER_NODES:
        return nodes_for(eps, zone, ar), False
    n = max(NODES_LAYER if ar == 0.0 else NODES_LAYER_ALPHA, _arcs.nodes_for(eps, ar))
    return (int(n) if ar == 0.0 else int(NODES_ALPHA * math.ceil(n / NODES_ALPHA))), True


KAPPA = 1e-2            # approach: k's slope this small against g's -- next to the receding contact eps_crit


def approach(aff):
    """delta/Delta of the equilibrium k = 0, g = 0 from the affine [k, p, B, g] at a fixed contact and zone end
    (jkrcyl.numerics.cohesive_branch.affine): from k = 0 (-k0/k1), but where k's slope k1 is below KAPPA times g's,
    by least squares of both -- k1 vanishes at eps_crit, where k0 does too on a branch crossing it with a finite
    approach (then -k0/k1 is 0/0 and -g0/g1 holds)."""
    (k0, k1), g = aff[0], aff[3]
    if g is None or abs(k1) >= KAPPA * abs(g[1]):
        return -k0 / k1
    return -(k0 * k1 + g[0] * g[1]) / (k1 * k1 + g[1] * g[1])
