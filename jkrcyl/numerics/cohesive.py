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
c - eps ~ m^2/(4 s0^2) and the node count corrected once from the root.
"""
import math
from collections import namedtuple

import numpy as np
from numba import njit
from scipy.linalg import lu_factor, lu_solve
from scipy.optimize import brentq

from ..generated import cohesive as _gc
from . import arcs as _arcs
from . import arcs_enrich as _en

CohesiveState = namedtuple("CohesiveState", [
    "eps", "c", "zones", "p", "delta_over_Delta", "delta_work_over_Delta", "h_pi_over_Delta", "k", "B",
    "m", "s0", "h0_over_Delta", "n", "solution"])
CohesiveState.__doc__ = """One Maugis-Dugdale state (normalised; see the module docstring).

eps: contact half-angle [rad] (0: no contact); c: zone end [rad] (pi when the zone reaches round);
zones: 'bottom' (the zone |phi| < c), 'all' (the whole exterior within the range), 'none'; p = P beta*/(4 pi Delta);
delta_over_Delta (the paper's delta), delta_work_over_Delta = delta/Delta + (gb/2) p (work conjugate of P);
h_pi_over_Delta: the gap at phi = pi; k: edge coefficient at the contact end (0: finite stress), B = int nu dphi;
m, s0, h0_over_Delta: the law; n: collocation nodes; solution: the fields (gap, pressure)."""

NODES_MIN = 24            # alpha* = 0: a contact far from its zone ends (spectral, ~1e-13)
NODES_PER_ZONE = 14       # nodes per sqrt(eps/(c - eps)): the Bernstein ellipse through the zone end (~1e-10)
NODES_MAX = 512
NODES_ALPHA = 8           # alpha* != 0: node counts in multiples of 8 (one enrichment table per count)
NODES_MAX_ALPHA = 256
SCAN_FACTOR = 1.25        # upward scan for the first zone-end root
SCAN_STEP = 0.05


@njit(cache=True)
def _zone_sum(phi, zones, k0, k1, ar, out):
    """out[i] = sum over the zones (lo, hi) of int_lo^hi K(phi_i - psi) dpsi (closed form)."""
    for i in range(phi.size):
        acc = 0.0
        for j in range(zones.shape[0]):
            acc += _gc.zone_displacement(ar=ar, hi=zones[j, 1], k0=k0, k1=k1, lo=zones[j, 0], phi=phi[i])
        out[i] = acc
    return out


def zone_displacement(phi, zones, kernel):
    """Z(phi) = int over the zones of K(phi - psi) dpsi; zones: (k, 2) array of (lo, hi) in [-pi, pi]."""
    phi = np.ascontiguousarray(np.atleast_1d(phi), dtype=float)
    return _zone_sum(phi, np.ascontiguousarray(zones, dtype=float), kernel.k0, kernel.k1, kernel.ar,
                     np.empty(phi.size))


def zones_of(c):
    """The zone set as (lo, hi) rows: the bottom zone |phi| < c, or the whole circle for c >= pi."""
    if c >= math.pi:
        return np.array([[-math.pi, math.pi]])
    return np.array([[-c, c]]) if c > 0 else np.zeros((0, 2))


def zone_load(zones):
    """int over the zones of (cos psi, 1) dpsi: a zone traction -s0 adds -s0 times these to p and B."""
    load = width = 0.0
    for lo, hi in zones:
        z = _gc.zone_load(hi=hi, lo=lo)
        load, width = load + z.load, width + z.width
    return load, width


class FixedContact:
    """The contact |phi| < eps with n nodes: one LU, the unit solutions and the linear functionals.

    Unknown vector u of jkrcyl.numerics.arcs (node values, then the alpha* enrichment), in nu units, for v.
    """

    def __init__(self, eps, kernel, n):
        self.eps, self.kernel = float(eps), kernel
        sy = self.sys = _arcs.Arcs([(0.0, self.eps)], kernel, n)
        self.phi = self.eps * sy._xt                  # collocation angles
        self.lu = lu_factor(sy.A, check_finite=False)
        rhs = np.column_stack([-2 * np.sin(self.phi / 2) ** 2, np.cos(self.phi)])
        self.U = lu_solve(self.lu, rhs, check_finite=False)
        nn, mm = sy.n, sy.m
        ek = np.empty(nn + mm)                        # u -> k (arcs.Arcs.edge)
        ek[:nn] = -(np.ones(nn) @ sy.D)
        ek[nn:] = -_en.G_END[:mm]
        self.ek = ek / math.sqrt(2 * self.eps)
        self.k_unit = self.ek @ self.U
        self.k_adj = lu_solve(self.lu, self.ek, trans=1, check_finite=False)   # k of a right-hand side r = k_adj.r
        nodes = self.eps * sy.s                       # u -> int v cos, int v (arcs.Arcs.moments)
        self.ep = self._moment_vector(np.cos(nodes))
        self.eb = self._moment_vector(np.ones_like(nodes))

    def _moment_vector(self, f):
        sy = self.sys
        out = np.empty(sy.n + sy.m)
        out[:sy.n] = math.pi / sy.n * f
        out[sy.n:] = [sy._mu[j] @ (sy.D @ f) for j in range(sy.m)]
        return out

    def rows(self, phi):
        """Gap rows: u -> -int_contact v K(phi - psi) dpsi at the exterior angles phi."""
        phi = np.ascontiguousarray(np.atleast_1d(phi), dtype=float)
        z = np.zeros_like(phi)
        rows = self.sys.operator(z, phi)
        if self.sys.m:
            rows = np.hstack([rows, self.sys.enrichment(z, phi)])
        return rows

    def solve(self, zones, s0):
        """(delta/Delta, u) with k = 0 for the zone set: v for the rhs clearance + delta cos - s0 Z."""
        rz = -zone_displacement(self.phi, zones, self.kernel)
        kz = self.k_adj @ rz
        dn = -(self.k_unit[0] + s0 * kz) / self.k_unit[1]
        u = self.U[:, 0] + dn * self.U[:, 1] + s0 * lu_solve(self.lu, rz, check_finite=False)
        return dn, u

    def gap(self, phi, dn, u, zones, s0):
        """h/Delta at exterior angles phi."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        return (2 * np.sin(phi / 2) ** 2 - dn * np.cos(phi) + self.rows(phi) @ u
                + s0 * zone_displacement(phi, zones, self.kernel))


def nodes_for(eps, zone, ar=0.0):
    """Nodes for the contact |phi| < eps with its zone end at eps + zone (zone >= 0)."""
    need = NODES_PER_ZONE * math.sqrt(eps / zone) if zone > 0 else 0.0
    n = min(max(NODES_MIN, _arcs.nodes_for(eps, ar), need), NODES_MAX)
    return int(n) if ar == 0.0 else int(min(NODES_ALPHA * math.ceil(n / NODES_ALPHA), NODES_MAX_ALPHA))


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
            out[(phi > lo) & (phi < hi)] = -self.s0
        if self.fc:
            sy, e = self.fc.sys, self.fc.eps
            x = phi / e
            inside = np.abs(x) < 1
            U, C = sy.split(self.u)
            val = np.cos(np.outer(np.arccos(x[inside]), np.arange(sy.n))) @ (sy.D @ U[0])
            if sy.m:
                val = val + C[0] @ _en._g(x[inside])[:sy.m]
            out[inside] = val / (e * np.sqrt(1 - x[inside] ** 2)) - self.s0
        return out


# --- states ------------------------------------------------------------------------------------------------
def _state(eps, c, fc, dn, u, zones, m, s0, kernel, gb, n):
    load, width = zone_load(zones)
    if fc is not None:
        p = fc.ep @ u - s0 * load
        B = fc.eb @ u - s0 * width
        k = fc.ek @ u
    else:
        p, B, k = -s0 * load, -s0 * width, 0.0
    f = _Fields(fc, dn, u, zones, s0, kernel)
    kind = "all" if c >= math.pi else ("bottom" if c > 0 else "none")
    return CohesiveState(eps, c, kind, p, dn, dn + gb / 2 * p, f.gap(math.pi)[0], k, B, m, s0, m * m / s0,
                         n, f)


def _zone_root(fc, s0, h0, d_start):
    """Zone length d = c - eps with h(eps + d) = h0: the first sign change of h - h0 upward from d_start
    (steps x SCAN_FACTOR, at most SCAN_STEP rad: the zone end can have several roots, the first one is the
    branch that tends to JKR as s0 -> inf), then Brent.  Returns None when h < h0 up to c = pi (the zone reaches
    round).  Below d_start the zone may be unresolved by the nodes: there F(0) = -h0 (h(eps) = 0) brackets."""
    eps = fc.eps
    d_max = math.pi - eps

    def F(d):
        zones = zones_of(eps + d)
        dn, u = fc.solve(zones, s0)
        return fc.gap(eps + d, dn, u, zones, s0)[0] - h0

    d = min(d_start, d_max / 2)
    f = F(d)
    if f < 0:
        while f < 0:
            if d >= d_max:
                return None
            lo = d
            d = min(d * SCAN_FACTOR, d + SCAN_STEP, d_max)
            f = F(d)
        hi = d
    else:
        hi, lo = d, 0.0
        for _ in range(6):
            d /= 2
            if F(d) < 0:
                lo = d
                break
            hi = d
    return brentq(lambda x: F(x) if x > 0 else -h0, lo, hi, xtol=4 * np.finfo(float).eps * eps, rtol=1e-15)


def cohesive_state(eps, m, s0, theta, gb, ar=0.0, n=None):
    """The Maugis-Dugdale state with the contact |phi| < eps (normalised; module docstring).

    eps: contact half-angle in (0, pi) [rad]; m = M vartheta (M_R* for vartheta = inf); s0 = sigma0 R beta*/(4 pi
    Delta) > 0; theta = vartheta (inf: rigid cradle); gb = (1/G_I)/beta*; ar = alpha*/beta*; n: nodes (default:
    from the zone length, ~1e-10).  The zone is the bottom one |phi| < c with h(c) = h0, or the whole exterior
    when h <= h0 there up to phi = pi (zones = 'all', c = pi; delta from k = 0 only).
    """
    kernel = _arcs.Kernel(theta, gb, ar)
    h0 = m * m / s0
    d_guess = dugdale_zone(m, s0)
    nn = n or nodes_for(eps, d_guess, ar)
    for _ in range(3):
        fc = FixedContact(eps, kernel, nn)
        d = _zone_root(fc, s0, h0, d_guess / 2)
        c = math.pi if d is None else eps + d
        need = n or nodes_for(eps, c - eps, ar)
        if need <= nn:
            break
        nn, d_guess = need, c - eps
    zones = zones_of(c)
    dn, u = fc.solve(zones, s0)
    return _state(eps, c, fc, dn, u, zones, m, s0, kernel, gb, nn)


def contactless_state(c, m, s0, theta, gb, ar=0.0):
    """The state without contact whose zone is |phi| < c (0 < c < pi, c != pi/2), closed form.

    delta/Delta from h(c) = h0 (linear: h = (1 - cos phi) - (delta/Delta) cos phi + s0 Z(phi)); p = -2 s0 sin c.
    Meaningful (feasible) while 0 <= h <= h0 on the zone and h > h0 outside (see check_gap)."""
    kernel = _arcs.Kernel(theta, gb, ar)
    zones = zones_of(c)
    h0 = m * m / s0
    dn = (2 * math.sin(c / 2) ** 2 + s0 * zone_displacement(c, zones, kernel)[0] - h0) / math.cos(c)
    return _state(0.0, c, None, dn, None, zones, m, s0, kernel, gb, 0)
