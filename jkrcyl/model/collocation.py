"""Any material pair behind the single-patch interface: the bordered arc of numerics.one_arc at its edge
coefficient, normalised (:class:`Collocation`) and physical (:class:`CollocationPhysical`)."""
from __future__ import annotations

import math

import numpy as np

from ..numerics import one_arc as _one
from .patch import SinglePatch, Slice


class Collocation(SinglePatch):
    """Normalised single patch (Delta = 1): slopes by central differences of the physical state per point."""

    dense_points = 400             # one collocation solve per point (three with the slopes)
    noise = 1e-11                  # ~1e-12 at alpha* = 0, ~1e-11 otherwise (numerics.arcs.nodes_for)

    def __init__(self, problem):
        self.problem = problem
        self.a_max = _one.resolved_a_max(problem.alpha_ratio)

    def states(self, a) -> Slice:
        pb = self.problem
        a = np.atleast_1d(np.asarray(a, dtype=float))
        st, sl = _one.arc_states(a, pb.edge.edge_coefficient(pb.m), pb.theta, pb.gb, pb.alpha_ratio,
                                 pole=self.a_crit)
        c = pb.work_shift
        return Slice(a=a, p=st["p"], dp_da=sl["dp_da"], dn=st["d"], ddn_da=sl["dd_da"], dw=st["d"] + c * st["p"],
                     ddw_da=sl["dd_da"] + c * sl["dp_da"], h=st["h_pi"], p_k=st["p_k"], dn_k=st["d_k"], B=st["B"])

    def _one(self, field, a):
        """p, dn, dw or h at one contact parameter (one bordered solve, no slopes)."""
        pb = self.problem
        s = _one.arc_state(a, pb.edge.edge_coefficient(pb.m), pb.theta, pb.gb, pb.alpha_ratio)
        return {"p": s.p, "dn": s.d, "dw": s.d + pb.work_shift * s.p, "h": s.h_pi}[field]

    def value(self, field, a):
        if field in ("p", "dn", "dw", "h"):
            return float(self._one(field, a))
        return super().value(field, a)

    @property
    def a_crit(self) -> float:
        pb = self.problem
        return _one.receding_contact(pb.theta, pb.gb, pb.alpha_ratio)


#: the fields of CollocationPhysical.states, in the order of a row
STATE_KEYS = ("P", "B", "C", "c0", "c1", "r0", "K", "G_release", "delta", "h_pi")


class CollocationPhysical:
    """States, pressure and gap of a Contact in SI units from the bordered arc (any Delta >= 0: lengths over
    L = Delta, or over R for the neat fit)."""

    def __init__(self, contact):
        m = contact.materials
        self.c = contact
        self.L = contact.Delta if contact.Delta > 0 else contact.R
        self.clearance = contact.Delta / self.L
        self.f = 4 * math.pi * self.L / (contact.R * contact.beta)          # N = f nu
        K_w = contact.law.stress_intensity(contact)                          # (3.5)-(3.6): (pi/4) A K^2 = w
        self.k = K_w / math.sqrt(2 * math.pi * contact.R) / self.f           # edge coefficient in nu
        self.kernel = (m.theta, m.inv_G_I / contact.beta, m.alpha_ratio)

    def _arc(self, a):
        eps = 2 * math.atan(a)
        arc = _one.OneArc(eps, *self.kernel, _one.nodes(eps, self.kernel[2]))
        s, v = arc.state(self.k, self.clearance)
        return arc, s, v

    def states(self, a):
        """{field: array}: P [N/m] (2.2), B, C [Pa] (2.13), (2.9), c0 [m], c1 (2.6), r0 [Pa] (2.12), K [Pa m^1/2]
        (3.4), G_release (3.5), delta [m], h_pi [m], all from their integral definitions."""
        c, L, f = self.c, self.L, self.f
        beta, R = c.beta, c.R
        to_P, to_c0, sqrt_2piR = 4 * math.pi * L / beta, c.R * beta * c.materials.inv_theta / (8 * math.pi), \
            math.sqrt(2 * math.pi * R)
        rows = np.empty((a.size, len(STATE_KEYS)))
        for i, ai in enumerate(a.tolist()):
            s = _one.arc_state(ai, self.k, *self.kernel, self.clearance)
            P, B, kN = to_P * s.p, f * s.B, f * s.k
            K = sqrt_2piR * kN
            rows[i] = (P, B, f * s.C, -c.Delta - to_c0 * B, beta * P / (2 * math.pi),
                       -kN * math.sqrt(ai * (1 + ai * ai)), K, c.A * math.pi / 4 * K ** 2, s.d * L, s.h_pi * L)
        return dict(zip(STATE_KEYS, rows.T))

    def pressure(self, a, phi):
        """(bounded, unbounded) as for the closed form; unbounded = r0/sqrt(a^2 - x^2), x = tan(phi/2)."""
        arc, s, v = self._arc(a)
        N = self.f * arc.pressure(phi, v)
        inside = np.abs(phi) < 2 * math.atan(a)
        r0 = -self.f * s.k * math.sqrt(a * (1 + a * a))
        x = np.tan(np.where(inside, phi, 0.0) / 2)
        unb = np.where(inside, r0 / np.sqrt(np.where(inside, a * a - x * x, 1.0)), 0.0)
        return N - unb, unb

    def gap(self, a, phi):
        """h(phi) [m] (5.9) at the 1-D a and phi of equal length; 0 inside the contact."""
        out = np.zeros(a.size)
        for ai in np.unique(a):
            sel = (a == ai) & (np.abs(phi) >= 2 * math.atan(ai))
            if sel.any():
                arc, s, v = self._arc(float(ai))
                out[sel] = self.L * arc.gap(phi[sel], v, s.d, self.clearance)
        return out
