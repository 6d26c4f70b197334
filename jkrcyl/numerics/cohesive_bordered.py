"""The contact with its zone all round, solved with the approach as an unknown (a bordered system): regular where
the fixed contact's collocation operator is singular.

Notation of jkrcyl.numerics.cohesive_contact.  At a fixed contact the states are affine in the approach: u = U0 +
delta U1 + s0 Z with A U0 = clearance, A U1 = cos phi, A Z = the zone's traction, and k = 0 fixes delta =
-k(U0 + s0 Z)/k(U1).  The log-kernel operator A(eps) is singular at one contact eps_s of each kernel (a
degenerate scale of the integral equation: an eigenvalue crossing zero, independent of the node count -- a rigid
cradle with an elastic pin, vartheta = inf, gb = 1/1.4: eps_s = 2.8680471602, where k(U1) = 3.27, 12.4, 4750, -6.99
at eps = 2.80, 2.85, 2.868, 2.90 for 48, 80 and 128 nodes alike).  There U0, U1 and Z grow as 1/(eps - eps_s) along
the null vector and the state (finite: solvability fixes delta, k = 0 the null vector's amount) is their
difference: its load carries an error ~ 5e-16/(eps - eps_s) relative (5e-3 at 1e-13 from eps_s), and a central
difference of k at fixed delta across eps_s is wrong by ~ (step/distance)^2.  The round zone's state at the grip
fold of its branch lies exactly there (d delta/d eps = 0 at eps_s, measured to 1e-7 in eps), so a fold refined on
the branch landed where the load is noise (a grip pull-off 10250.8 or 10291.0 N/m).

Here the state solves M [u; delta] = [clearance + s0 Z_rhs; 0] with M = [[A, -cos phi], [k, 0]] (one LU of n + 1),
nonsingular at eps_s; and M^{-1} [0; 1] = [U1/k(U1); 1/k(U1)] gives the stability derivatives D_dn = 1/(dk/d delta)
and D_p = (dp/d delta)/(dk/d delta), both finite (and smooth) through eps_s.  The slopes along the round-zone
branch are central differences of these states' delta and p in eps (no k at fixed delta).  Only zones all round
(c = pi), without an end layer.
"""
import math

import numpy as np

from . import cohesive as _co
from . import cohesive_contact as _cc
from . import cohesive_kernels as _ck

FD_REL = 2e-4       # the step in eps of the slopes, relative (jkrcyl.numerics.cohesive_branch.FD_REL)
ROUND_KEPT = 64     # bordered systems kept per law (of), the oldest dropped first


class Bordered:
    """The bordered system of the fixed contact fc (jkrcyl.numerics.cohesive_contact.FixedContact) factorised."""

    def __init__(self, fc):
        sy, fx = fc.sys, fc.fx
        n = sy.A.shape[0]
        M = np.zeros((n + 1, n + 1))
        M[:n, :n] = sy.A
        M[:n, n] = -np.cos(fx[2])
        M[n, :n] = fc.ek
        self.lu, self.perm = _cc._factor(M)
        self.fc, self.n = fc, n
        self.clearance = -2 * np.sin(fx[2] / 2) ** 2
        unit = self._solve(np.zeros(n), 1.0)
        self.inv_k_delta = unit[n]                      # 1/(dk/d delta) at fixed contact
        self.p_per_k = float(fc.ep @ unit[:n])          # (dp/d delta)/(dk/d delta)

    def _solve(self, rhs, k):
        return _ck.lu_solve(self.lu, self.perm, np.append(rhs, k))

    def state(self, s0):
        """(delta/Delta, u) with k = 0 and the zone all round (the traction -s0 on the whole exterior)."""
        zones = _co.zones_of(math.pi)
        x = self._solve(self.clearance + s0 * _ck.zone_rhs(self.fc.fx, zones), 0.0)
        return float(x[self.n]), x[:self.n]


def applies(law, eps, c):
    """Whether the state (eps, c) is solved here: its zone all round, its contact without an end layer (the
    layered node count of thin zones: the affine route of jkrcyl.numerics.cohesive_branch then)."""
    return c >= math.pi and not law.contact(eps)[1]


def of(law, eps):
    """The bordered system at the law's contact eps, kept per law (ROUND_KEPT): its fixed contact assembled, not
    factored (FixedContact factor=False: the bordered LU alone; was a third of a round-zone state's cost)."""
    kept = law.__dict__.setdefault("_bordered", {})
    if eps not in kept:
        if len(kept) >= ROUND_KEPT:
            kept.pop(next(iter(kept)))
        kept[eps] = Bordered(_cc.FixedContact(eps, law.kernel, *law.contact(eps), factor=False))
    return kept[eps]


def round_values(law, eps):
    """(p, delta/Delta, u) of the round-zone state at the contact eps."""
    b = of(law, eps)
    delta, u = b.state(law.s0)
    p = b.fc.load_width(u, _co.zones_of(math.pi), law.s0)[0]
    return float(p), delta, u


def round_gap(law, eps, phi):
    """h/Delta of the round-zone state at the contact eps (:func:`round_values`), at the exterior angles phi."""
    _, delta, u = round_values(law, eps)
    return of(law, eps).fc.gap(np.asarray(phi, dtype=float), delta, u, _co.zones_of(math.pi), law.s0)


def round_slopes(law, eps):
    """(delta/Delta, dp/dt, d(delta/Delta)/dt, D_p, D_dn) of the round-zone branch at eps, t = log eps (as
    jkrcyl.numerics.cohesive_branch._slopes gives them): the slopes by central differences of the bordered states
    at eps (1 +- FD_REL)."""
    b = of(law, eps)
    p, delta, _ = round_values(law, eps)
    he = FD_REL * eps
    (p_hi, d_hi, _), (p_lo, d_lo, _) = round_values(law, eps + he), round_values(law, eps - he)
    return delta, eps * (p_hi - p_lo) / (2 * he), eps * (d_hi - d_lo) / (2 * he), b.p_per_k, b.inv_k_delta
