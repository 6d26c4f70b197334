"""Maugis-Dugdale (cohesive-zone) equilibrium states of the pin in the hole, any material pair.

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
for near-touching arcs in jkrcyl.model.two_patch).  The zone length is first estimated by the Dugdale crack value
c - eps ~ m^2/(4 s0^2) and the node count corrected once from the root.  Measured (lambda = 10, eps = 0.8,
rho = 1.263): errors 5e-5, 1e-7, 2e-9, 7e-13 at n = 24, 48, 64, 96 (benchmarks/bench_cohesive.py); the
default (11 sqrt(eps/(c - eps)), at least 24) gives ~1e-9.  Where that exceeds LAYER_NODES (a thin zone,
c - eps ~ eps/lambda^2: lambda above ~5) the zone's end layer is subtracted in closed form instead
(jkrcyl.numerics.cohesive_layer: the half-plane Maugis traction, whose potential is exact) and the rest is
smooth: 32 nodes (64 at alpha* != 0) resolve any lambda up to LAMBDA_MAX = 1e4 (~1e-10 at alpha* = 0, ~1e-9 at
|alpha*/beta*| = 0.2; tests/test_cohesive_layer.py), beyond which cohesive_state refuses naming sigma0 (c = eps + d
keeps d only to ulp(c), ~1e-8 relative at 1e4; the states are JKR's there to O(lambda^-2)).  The fixed contact,
its checks and the node policy: jkrcyl.numerics.cohesive_contact.

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

from ..generated import cohesive as _gc
from .._validate import count, finite_scalar, theta as _check_theta
from . import arcs as _arcs
from . import arcs_enrich as _en
from . import cohesive_kernels as _ck
from . import cohesive_layer as _cl
from .cohesive_contact import (FixedContact, contact_nodes, nodes_for, LAPACK_NODES, LAYER_NODES, NODES_ALPHA,  # noqa: F401
                               NODES_LAYER, NODES_LAYER_ALPHA, NODES_MAX, NODES_MAX_ALPHA, NODES_MIN, NODES_PER_ZONE)

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

LAMBDA_MAX = 1e4          # the transition parameter 4 s0/m^(2/3) supported (check_lambda)
GAP_POINTS = 96           # potential: Gauss-Legendre points of int h over a zone (the interface energy)
GAP_END_SKIP = 1e-6        # gap_check, alpha* != 0: see there
GAP_TOL_REL = 1e-6         # gap_check: a violation must exceed this times the state's gap scale (max(h0, max |h|)):
                           # next to the ends the evaluated gap carries ~1e-8 of the engine's error (alpha* != 0,
                           # 1e-6 eps past the end: it changes with the node count), the true gap there ~ d^(3/2)


def zone_displacement(phi, zones, kernel):
    """Z(phi) = int over the zones of K(phi - psi) dpsi; zones: (k, 2) array of (lo, hi) in [-pi, pi]."""
    phi = np.ascontiguousarray(np.atleast_1d(phi), dtype=float).ravel()
    zones = np.ascontiguousarray(zones, dtype=float)
    if zones.ndim != 2 or zones.shape[1] != 2:
        raise ValueError(f"zones must be an array of (lo, hi) rows, got shape {zones.shape}")
    return _ck.zone_sum(phi, zones, kernel.k0, kernel.k1, kernel.ar)


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
    its maximum on the zones (<= h0) and minimum off them (>= h0: else the law would put traction there), each up
    to GAP_TOL_REL times the state's gap scale (a tolerance that scales with the state, not with Delta).
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
    tol = GAP_TOL_REL * max(h0, float(np.max(np.abs(h))))
    zone_max = h[in_zone].max() if in_zone.any() else -math.inf
    free_min = h[~in_zone].min() if (~in_zone).any() else math.inf
    return GapCheck(h.min(), zone_max, free_min,
                    bool(h.min() >= -tol and zone_max <= h0 + tol and free_min >= h0 - tol))


_XG, _WG = np.polynomial.legendre.leggauss(GAP_POINTS)


def potential(st):
    """Total potential in the kernel scale (units 4 pi Delta^2/beta*): the elastic energy (Clapeyron) plus the
    Dugdale interface energy int (s0 h - m^2) over the zones and -m^2 over the contact:
    [(1 + delta/Delta) p - B]/2 + (s0/2) int_zones h - m^2 (length of contact and zones)."""
    eps, c = st.eps, min(st.c, math.pi)
    t = np.pi * (_XG + 1) / 2
    shape, jac = (1 - np.cos(t)) / 2, np.sin(t) * np.pi / 4
    H = 2 * (c - eps) * np.sum(_WG * jac * st.fields.gap(eps + (c - eps) * shape))
    length = 2 * c
    if st.c_top > 0:
        H += 2 * st.c_top * np.sum(_WG * jac * st.fields.gap(math.pi - st.c_top + st.c_top * shape))
        length += 2 * st.c_top
    return 0.5 * ((1 + st.delta_over_Delta) * st.p - st.B) + 0.5 * st.s0 * H - st.m ** 2 * length
