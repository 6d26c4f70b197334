"""Maugis-Dugdale (cohesive-zone) equilibrium states of the pin in the hole, any material pair (issue 19).

Normalised as jkrcyl.numerics.arcs: nu = N R beta*/(4 pi Delta) (N compressive positive), p = int nu cos(phi)
dphi = P beta*/(4 pi Delta) (= vartheta P*), m = M vartheta (M_R* for vartheta = inf), and the Dugdale law
nu = -s0 (s0 = sigma0 R beta*/(4 pi Delta)) wherever 0 < h <= h0, h0/Delta = m^2/s0 (w = sigma0 h0).

A state with the contact |phi| < eps has the zone set C = {|phi| < c} (contact included), or the whole circle
('all': every exterior point within the range).  The contact unknown is v = nu + s0 (the zone traction
continued over the contact), so that the traction jump sits at the zone ends, off the contact:

    -int_contact v K(phi - psi) dpsi = (delta/Delta) cos(phi) - (1 - cos(phi)) - s0 Z(phi),   |phi| < eps,
    h/Delta = (1 - cos(phi)) - (delta/Delta) cos(phi) - int_contact v K + s0 Z(phi),          outside,

Z(phi) = int_C K(phi - psi) dpsi in closed form (generated/cohesive.zone_displacement).  For fixed (eps, C) the
collocation system of jkrcyl.numerics.arcs (one LU) gives v for three right-hand sides (clearance, approach,
zone); the finite stress at the contact end (Maugis: edge coefficient k = 0) fixes delta linearly, and the zone
end solves h(c) = h0 (Brent, the LU reused: only the zone right-hand side and one gap row change).

Node count: v is analytic on the contact with singularities at the zone ends +-c (the jump of the traction),
so Chebyshev converges like rho^-n with rho the Bernstein ellipse through c/eps: n ~ sqrt(eps/(c - eps)) (as
for near-touching arcs in jkrcyl.twopatch).  The zone length is first estimated by the Dugdale crack value
c - eps ~ m^2/(4 s0^2) and the node count corrected once from the root.  Measured (lambda = 10, eps = 0.8,
rho = 1.263): errors 5e-5, 1e-7, 2e-9, 7e-13 at n = 24, 48, 64, 96 (benchmarks/bench_cohesive.py); the
default (11 sqrt(eps/(c - eps)), at least 24) gives ~1e-9.  Up to NODES_MAX = 1024 nodes (256 at alpha* != 0),
i.e. lambda up to a few hundred; beyond, cohesive_state refuses (the state is JKR's to O(lambda^-2) there).

JKR limit: at a fixed contact the states differ from the Griffith ones by C/lambda^2 (the zone length over the
contact, C = O(1): 0.77 for p at M = 0.4, eps = 0.8; 1e-4 relative is reached near lambda = 100 there); the
pull-off converges faster, as lambda^-4 (jkrcyl.numerics.cohesive_pull_off).

Several states can share a contact size: the zone end can have several roots (cohesive_state takes the first
above the Dugdale estimate, or the one near a given zone length), and the branch can turn back in eps.  Other
zone sets (no contact, a top zone): jkrcyl.numerics.cohesive_zones.
"""
import math
from collections import namedtuple

import numpy as np
from scipy.linalg.lapack import dgetrf as _dgetrf
from threadpoolctl import ThreadpoolController

from ..generated import cohesive as _gc
from .._validate import count, finite_scalar, theta as _check_theta
from . import arcs as _arcs
from . import arcs_enrich as _en
from . import cohesive_kernels as _ck
from . import cohesive_layer as _cl

_BLAS = ThreadpoolController()
_NO_LAYER = np.zeros(1)
_NO_TABLE = np.zeros((0, _cl.N_SMOOTH))
CohesiveState = namedtuple("CohesiveState", [
    "eps", "c", "c_top", "zones", "p", "delta_over_Delta", "delta_work_over_Delta", "h_pi_over_Delta", "k", "B",
    "m", "s0", "h0_over_Delta", "n", "fields"])
CohesiveState.__doc__ = """One Maugis-Dugdale state (normalised; see the module docstring).

eps: contact half-angle [rad] (0: no contact); c: zone end [rad] (pi when the zone reaches round); c_top: the top
zone |phi - pi| < c_top (0: none); zones: 'bottom' (the zone |phi| < c), 'bottom+top', 'all' (the whole exterior
within the range); p = P beta*/(4 pi Delta); delta_over_Delta (the
paper's delta), delta_work_over_Delta = delta/Delta + (gb/2) p (work conjugate of P); h_pi_over_Delta: the gap
at phi = pi; k: edge coefficient at the contact end (0: finite stress); B = int nu dphi; m, s0, h0_over_Delta:
the law; n: collocation nodes (0 without contact); fields: .gap(phi), .pressure(phi)."""

NODES_MIN = 24            # alpha* = 0: a contact far from its zone ends (spectral, ~1e-13)
NODES_PER_ZONE = 11       # nodes per sqrt(eps/(c - eps)): the Bernstein ellipse through the zone end (~1e-9)
NODES_MAX = 1024
NODES_ALPHA = 8           # alpha* != 0: node counts in multiples of 8 (one enrichment table per count)
NODES_MAX_ALPHA = 256
LAYER_NODES = 48          # a zone needing more nodes than this has its end layer subtracted (contact_nodes)
NODES_LAYER = 32          # nodes with the end layer subtracted (alpha* = 0: ~1e-12, tests/test_cohesive_layer.py)
NODES_LAYER_ALPHA = 64    # the same at alpha* != 0 (the enrichment's algebraic rate: ~1e-9 at |alpha*/beta*| = 0.2)
LAMBDA_MAX = 1e4          # the transition parameter 4 s0/m^(2/3) supported (check_lambda)
SCAN_FACTOR = 1.25        # upward scan for the first zone-end root: steps x 1.25, at most 0.05 rad
SCAN_STEP = 0.05
LAPACK_NODES = 96         # above: LAPACK's LU (blocked), below: the compiled one (no call overhead)
GAP_END_SKIP = 1e-6        # gap_check, alpha* != 0: see there


def zone_displacement(phi, zones, kernel):
    """Z(phi) = int over the zones of K(phi - psi) dpsi; zones: (k, 2) array of (lo, hi) in [-pi, pi]."""
    phi = np.ascontiguousarray(np.atleast_1d(phi), dtype=float)
    return _ck.zone_sum(phi, np.ascontiguousarray(zones, dtype=float), kernel.k0, kernel.k1, kernel.ar)


def zones_of(c, c_top=0.0):
    """The zone set as (lo, hi) rows: the bottom zone |phi| < c and the top zone |phi - pi| < c_top, or the whole
    circle when they meet (c + c_top >= pi)."""
    return _ck.zones_of(float(c), float(c_top))


def zone_load(zones):
    """int over the zones of (cos psi, 1) dpsi: a zone traction -s0 adds -s0 times these to p and B."""
    load = width = 0.0
    for lo, hi in zones:
        z = _gc.zone_load(hi=hi, lo=lo)
        load, width = load + z.load, width + z.width
    return load, width


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
    """

    def __init__(self, eps, kernel, n, layered=False):
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
        lu, perm = _factor(sy.A)
        nn, mm = sy.n, sy.m
        ek = np.empty(nn + mm)                        # u -> k (arcs.Arcs.edge)
        ek[:nn] = -sy.D.sum(axis=0)
        ek[nn:] = -_en.G_END[:mm]
        self.ek = ek / math.sqrt(2 * self.eps)
        U0, U1, kadj, k_0, k_1 = _ck.unit_solutions(lu, perm, phin, self.ek)
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
        phi = np.ascontiguousarray(np.atleast_1d(phi), dtype=float)
        return _ck.gap(self.fx, phi, float(dn), self._u(u), self._zones(zones), float(s0))

    def state(self, s0, h0, d_start, c_top=0.0):
        """(zone length or None, delta/Delta, u, h(pi)/Delta) in one compiled call (cohesive_kernels.state)."""
        d, dn, u, h_pi = _ck.state(self.fx, self.eps, float(s0), float(h0), float(d_start), SCAN_FACTOR, SCAN_STEP,
                                   float(c_top))
        return (None if d < 0 else d), dn, u, h_pi

    def zone_end_near(self, s0, h0, d_near, c_top=0.0):
        """The zone length nearest to d_near with h(c) = h0 (None: none within a factor 100)."""
        d = _ck.zone_end_near(self.fx, self.eps, float(s0), float(h0), float(d_near), float(c_top))
        return None if d < 0 else d

    def zone_end(self, s0, h0, d_start, c_top=0.0):
        """Zone length c - eps with h(c) = h0 (None: h < h0 up to pi - c_top); see cohesive_kernels.zone_end."""
        d = _ck.zone_end(self.fx, self.eps, float(s0), float(h0), float(d_start), SCAN_FACTOR, SCAN_STEP,
                         float(c_top))
        return None if d < 0 else d


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


def dugdale_zone(m, s0):
    """Zone length c - eps of a small zone: the Dugdale crack value (pi/8)(K/sigma0)^2 with the JKR edge field
    nu ~ -(m/pi)/sqrt(eps - |phi|), i.e. m^2/(4 s0^2) (the estimate that sets the node count)."""
    return m * m / (4 * s0 * s0)


class _Fields:
    """Gap and pressure of a solved state (normalised; angles in rad)."""

    def __init__(self, fc, dn, u, zones, s0, kernel):
        self.fc, self.dn, self.u, self.zones, self.s0, self.kernel = fc, dn, u, zones, s0, kernel

    def gap(self, phi):
        """h/Delta at angles phi (0 on the contact)."""
        phi = np.angle(np.exp(1j * np.atleast_1d(np.asarray(phi, dtype=float))))
        out = np.zeros_like(phi)
        eps = self.fc.eps if self.fc else 0.0
        ext = np.abs(phi) >= eps
        if self.fc:
            out[ext] = self.fc.gap(phi[ext], self.dn, self.u, self.zones, self.s0)
        else:
            x = phi[ext]
            out[ext] = (2 * np.sin(x / 2) ** 2 - self.dn * np.cos(x)
                        + self.s0 * zone_displacement(x, self.zones, self.kernel))
        return out

    def pressure(self, phi):
        """nu(phi) = N R beta*/(4 pi Delta): v - s0 on the contact, -s0 on the zones, 0 elsewhere."""
        phi = np.angle(np.exp(1j * np.atleast_1d(np.asarray(phi, dtype=float))))
        out = np.zeros_like(phi)
        for lo, hi in self.zones:
            out[(phi > lo) & (phi < hi) | (lo <= -math.pi and hi >= math.pi)] = -self.s0
        if self.fc:
            sy, e = self.fc.sys, self.fc.eps
            x = phi / e
            inside = np.abs(x) < 1
            U, C = sy.split(self.u)
            val = np.cos(np.outer(np.arccos(x[inside]), np.arange(sy.n))) @ (sy.D @ U[0])
            if sy.m:
                val = val + C[0] @ _en._g(x[inside])[:sy.m]
            out[inside] = val / (e * np.sqrt(1 - x[inside] ** 2)) - self.s0
            c = self.fc.layer_end(self.zones)
            if c is not None:
                out[inside] += self.s0 * _cl.traction(np.ascontiguousarray(phi[inside]), e, c)
        return out


# --- states ------------------------------------------------------------------------------------------------
def _state(eps, c, fc, dn, u, zones, m, s0, kernel, gb, n, c_top=0.0, h_pi=None):
    if fc is not None:
        p, B = fc.load_width(u, zones, s0)
        k = fc.ek @ u
    else:
        load, width = zone_load(zones)
        p, B, k = -s0 * load, -s0 * width, 0.0
    f = _Fields(fc, dn, u, zones, s0, kernel)
    if c + c_top >= math.pi:
        c, c_top, kind = math.pi, 0.0, "all"
    elif len(zones) == 0:
        kind = "none"
    else:
        kind = "bottom+top" if c_top > 0 else "bottom"
    h_pi = f.gap(math.pi)[0] if h_pi is None else h_pi
    return CohesiveState(eps, c, c_top, kind, p, dn, dn + gb / 2 * p, h_pi, k, B, m, s0, m * m / s0, n, f)


def _law(m, s0, theta, gb, ar):
    """Validated (m, s0, Kernel); ValueError naming sigma0 beyond the supported transition parameter."""
    m = finite_scalar("m", m, low=0.0)
    s0 = finite_scalar("s0", s0, low=0.0, low_open=True)
    theta = _check_theta(theta)
    gb = finite_scalar("gb", gb, low=0.0)
    ar = finite_scalar("ar", ar, low=-1.0, high=1.0, low_open=True)
    check_lambda(m, s0)
    return m, s0, _arcs.Kernel(theta, gb, ar)


def check_lambda(m, s0):
    """ValueError naming sigma0 and lambda when lambda = 4 s0/m^(2/3) (the transition parameter at Delta/R -> 0,
    jkrcyl.numerics.cohesive_scales) exceeds LAMBDA_MAX: there the zone is thinner than double precision keeps
    to ~1e-8 relative (c - eps ~ eps/lambda^2), and the states are JKR's to O(lambda^-2)."""
    if m > 0 and 4 * s0 > LAMBDA_MAX * m ** (2 / 3):
        lam = 4 * s0 / m ** (2 / 3)
        raise ValueError(f"sigma0 is too large for the cohesive law: its transition parameter lambda = {lam:.4g} "
                         f"must be at most {LAMBDA_MAX:g} (lambda is proportional to sigma0: at most "
                         f"{LAMBDA_MAX / lam:.3g} times this sigma0); the Maugis-Dugdale states are JKR's there to "
                         "O(lambda^-2): use the JKR law (sigma0=None)")


def cohesive_state(eps, m, s0, theta, gb, ar=0.0, n=None, near=None, layered=None):
    """The Maugis-Dugdale state with the contact |phi| < eps (normalised; module docstring).

    eps: contact half-angle in (0, pi) [rad]; m = M vartheta (M_R* for vartheta = inf; m = 0: no adhesion, the
    adhesionless state); s0 = sigma0 R beta*/(4 pi Delta) > 0 (lambda = 4 s0/m^(2/3) <= LAMBDA_MAX); theta =
    vartheta >= 1/2 (inf: rigid cradle); gb = (1/G_I)/beta*; ar = alpha*/beta*; n: nodes (default: from the zone
    length, ~1e-10: :func:`contact_nodes`); layered: subtract the zone's end layer (None: where the zone needs
    more than LAYER_NODES nodes; False with a thin zone needs n <= NODES_MAX nodes for it).  The zone is the
    bottom one |phi| < c with h(c) = h0 (the first root above the Dugdale estimate: the branch that tends to
    JKR as s0 -> inf), or the whole exterior when h <= h0 up to phi = pi (zones = 'all', c = pi; delta from
    k = 0 only).  The zone end can have several roots and the first one can turn back in eps (a fold of the
    branch): near = a zone length c - eps selects the root nearest to it (following a branch by continuity);
    None is returned when no root lies within a factor 100 of it.  Feasibility (gap >= 0, the law obeyed
    everywhere): :func:`gap_check`.
    """
    eps = finite_scalar("eps", eps, low=0.0, high=math.pi, low_open=True)
    if eps >= math.pi:
        raise ValueError(f"eps must be in (0, pi), got {eps:g}")
    m, s0, kernel = _law(m, s0, theta, gb, ar)
    nn = None if n is None else count("n", n, 8, NODES_MAX)
    if m == 0.0:                                     # no adhesion: no zone, the adhesionless (k = 0) state
        fc = FixedContact(eps, kernel, nn or nodes_for(eps, 0.0, kernel.ar))
        zones = np.zeros((0, 2))
        dn, u = fc.solve(zones, 0.0)
        return _state(eps, eps, fc, dn, u, zones, m, s0, kernel, gb, fc.sys.n)
    h0 = m * m / s0
    d_guess = dugdale_zone(m, s0) if near is None else finite_scalar("near", near, low=0.0, low_open=True)
    nn, lay = _nodes(eps, d_guess, kernel.ar, nn, layered)
    for _ in range(3):
        fc = FixedContact(eps, kernel, nn, lay)
        if near is None:
            d, dn, u, h_pi = fc.state(s0, h0, d_guess / 2)
        else:
            d = fc.zone_end_near(s0, h0, d_guess)
            if d is None:
                return None
            dn, u = fc.solve(zones_of(eps + d), s0)
            h_pi = None
        c = math.pi if d is None else eps + d
        need, lay_need = _nodes(eps, c - eps, kernel.ar, None if n is None else nn, layered)
        if need <= nn and (lay or not lay_need):
            break
        nn, lay, d_guess = need, lay or lay_need, (c - eps if near is None else near)
    return _state(eps, c, fc, dn, u, zones_of(c), m, s0, kernel, gb, nn, h_pi=h_pi)


def _nodes(eps, zone, ar, n, layered):
    """(n, layered) of cohesive_state: contact_nodes unless n or layered is given."""
    n_auto, lay = contact_nodes(eps, zone, ar)
    if layered is not None and bool(layered) != lay:
        lay = bool(layered)
        n_auto = nodes_for(eps, zone, ar) if not lay else contact_nodes(eps, 0.0, ar)[0]
        if not lay and n is None and NODES_PER_ZONE * math.sqrt(eps / zone) > 2 * NODES_MAX:
            raise ValueError(f"layered: the zone c - eps ~ {zone:.3g} rad at eps = {eps:.6g} needs more than "
                             f"{NODES_MAX} nodes without its end layer subtracted (layered=None or True)")
    return (n_auto if n is None else n), lay


GapCheck = namedtuple("GapCheck", ["min_gap", "max_zone_gap", "min_free_gap", "feasible"])


def gap_check(state, n_points=400):
    """The gap on a grid of the exterior (clustered at the contact and zone ends): its minimum (>= 0 wanted),
    its maximum on the zones (<= h0) and minimum off them (>= h0: else the law would put traction there).
    alpha* != 0: the grid starts GAP_END_SKIP eps past the contact end, where the engine's off-table evaluation
    of the end enrichment (jkrcyl.numerics.arcs, a 4096-point grid) does not resolve the log kernel (errors up
    to ~1e-6 absolute within ~1e-7 eps of the end; the true gap there is ~ distance^(3/2) >= 0)."""
    n_points = count("n_points", n_points, 8)
    eps, c, ct = state.eps, state.c, state.c_top
    start = eps * (1 + GAP_END_SKIP) if state.fields.fc is not None and state.fields.fc.sys.m else eps
    t = (1 - np.cos(np.linspace(0, math.pi, n_points))) / 2
    ends = sorted({start, min(c, math.pi), math.pi - ct, math.pi})
    grid = np.unique(np.concatenate([a + (b - a) * t for a, b in zip(ends[:-1], ends[1:]) if b > a]))
    grid = grid[grid > eps] if eps > 0 else grid
    h = state.fields.gap(grid)
    in_zone = (grid <= c) | (grid >= math.pi - ct) if ct > 0 else (grid <= c)
    h0 = state.h0_over_Delta
    tol = 1e-9 * max(1.0, h0)
    zone_max = h[in_zone].max() if in_zone.any() else -math.inf
    free_min = h[~in_zone].min() if (~in_zone).any() else math.inf
    return GapCheck(h.min(), zone_max, free_min,
                    bool(h.min() >= -tol and zone_max <= h0 + tol and free_min >= h0 - tol))
