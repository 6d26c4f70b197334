"""Stability of the Maugis-Dugdale two-patch states (jkrcyl.numerics.cohesive_two, notation there): the energy of
states whose zone ends are held.

As for one patch (jkrcyl.numerics.cohesive_branch), the reduced energy E(c, c_top) -- the total potential of the
state with the zones |phi| < c and |phi - pi| < c_top, both contact edges at k = 0 and the control's quantity held
(less p delta/Delta under load) -- has the gradient dE/dc_i = 2 s0 (h(c_i) - h0) at each zone end (Dugdale's
J-integral, both ends of a zone); an equilibrium is its stationary point and is stable where E is a minimum: the
matrix G_ij = d(h(c_i) - h0)/dc_j at the held quantity (2 s0 G is the Hessian, symmetric: Maxwell) positive
definite.  :func:`held_state` gives the zone-end-held states, :func:`zone_matrix` G by central differences,
:func:`stable` the flag; tests/test_cohesive_two_patch.py checks dE/dc by differences of the held states' energy,
G's symmetry, and the flags against JKR's (jkrcyl.model.two_patch.stability) in the limit.

A traced state's flags under each control from one Jacobian (:func:`flags`, cheaper than held states): the
implicit function theorem gives G = g_c - [g_e g_d] A^-1 [k_c; q_c], A = [[k_e, k_d], [q_e, q_d]], with
q = a delta/Delta + b p the held quantity (load: (0, 1), grip: (1, 0), grip-work: (1, c_work)), e the half-angles,
d = delta/Delta; the derivatives are central differences of fixed-arc states (:func:`jacobian`: four more
systems; delta and the zone ends: back-substitutions).  tests/test_cohesive_two_patch_branch.py: G equals
:func:`zone_matrix`'s (held states solved by Newton, an independent route).
"""
import math

import numpy as np

from . import cohesive as _co
from . import cohesive_two as _two

HOLD_STEP = 1e-4          # central differences of the zone ends, relative to the zone length
ARC_STEP = 1e-6           # jacobian: central differences of the half-angles, relative
ZONE_STEP = 1e-5          # ... of the zone ends and the approach, relative to the zone length


def _held_pieces(fa, zones, s0, control, value):
    """(delta/Delta, u, k) at fixed arcs and zones with delta/Delta (grip) or p (load) held at value."""
    uz = fa.zone_unit(zones)
    if control == "grip":
        dn = value
    else:
        load = fa.zone_totals(zones)[0]
        m0, m1, mz = (fa.sys.moments(v, np.cos) for v in (fa.u0, fa.u1, uz))
        dn = (value - s0 * load - m0 - s0 * mz) / m1
    u = fa.u0 + dn * fa.u1 + s0 * uz
    return dn, u, fa.sys.edge(u)


def held_state(law, c, c_top, control, value, arcs, n, tol=1e-11):
    """The state with the zone ends c, c_top held, k = 0 at both contact edges and the control's quantity at value
    (control 'load': p; 'grip': delta/Delta), by Newton in (eps, eps_top) from arcs = (eps, eps_top): a
    TwoPatchCohesive (k_bot, k_top ~ 0) and g = (h(c) - h0, h(pi - c_top) - h0).  ValueError if it does not
    converge."""
    if control not in ("load", "grip"):
        raise ValueError(f"control must be 'load' or 'grip', got {control!r}")
    zones = _co.zones_of(c, c_top)

    def residual(x):
        if not (0 < x[0] < c and 0 < x[1] < c_top):
            return None
        return _held_pieces(law.arcs(x[0], x[1], n), zones, law.s0, control, value)[2]

    x = _two.newton(residual, np.array(arcs, dtype=float), (1e-7 * arcs[0], 1e-7 * arcs[1]),
                    np.full(2, max(1.0, law.m)), tol, np.array([0.1 * (c - arcs[0]), 0.1 * (c_top - arcs[1])]))
    if x is None:
        raise ValueError(f"arcs: no zone-end-held two-patch state near {tuple(arcs)!r}")
    fa = law.arcs(x[0], x[1], n)
    dn, u, k = _held_pieces(fa, zones, law.s0, control, value)
    load, width = fa.zone_totals(zones)
    st = _two.TwoPatchCohesive(x[0], x[1], c, c_top, "both", fa.sys.moments(u, np.cos) + law.s0 * load, dn,
                               fa.sys.moments(u, np.ones_like) + law.s0 * width, k[0], k[1], law.m, law.s0,
                               law.h0, n, _two._Fields(fa, dn, u, zones, law.s0))
    return st, st.fields.gap(np.array([c, math.pi - c_top])) - law.h0


def zone_matrix(law, st, control):
    """G_ij = d(h(c_i) - h0)/dc_j at the held quantity of control (central differences of held states, steps
    HOLD_STEP times each zone length), unsymmetrised."""
    value = st.p if control == "load" else st.delta_over_Delta
    steps = HOLD_STEP * np.array([st.c - st.eps, st.c_top - st.eps_top])
    G = np.empty((2, 2))
    for j in range(2):
        g = []
        for sgn in (1, -1):
            dc = sgn * steps[j] * np.eye(2)[j]
            g.append(held_state(law, st.c + dc[0], st.c_top + dc[1], control, value, (st.eps, st.eps_top),
                                st.n)[1])
        G[:, j] = (g[0] - g[1]) / (2 * steps[j])
    return G


def stable(law, st, control, G=None):
    """Whether the two-patch state st is stable under control ('load' or 'grip'): G's symmetric part positive
    definite (module docstring); G: :func:`zone_matrix` when already computed."""
    G = zone_matrix(law, st, control) if G is None else G
    return positive_definite(G)


def positive_definite(G):
    """Whether the symmetric part of the 2 x 2 matrix G is positive definite (both eigenvalues > 0: its first
    entry and its determinant > 0; in closed form -- LAPACK's call costs ~1 ms on a loaded machine)."""
    a, b, d = G[0, 0], 0.5 * (G[0, 1] + G[1, 0]), G[1, 1]
    return bool(a > 0 and a * d - b * b > 0)


# --- the flags of a traced state from one Jacobian ------------------------------------------------------------
def pieces(law, x, n):
    """[k_bot, k_top, g_bot, g_top, p] of the fixed-arc state at x = (eps, eps_top, c, c_top, delta/Delta)
    (g = h(c) - h0, h(pi - c_top) - h0): the functions of :func:`flags` (law: cohesive_two's, or a
    BranchLaw)."""
    eps, eps_top, c, c_top, dn = x
    fa = law.arcs(eps, eps_top, n)
    zones = _co.zones_of(c, c_top)
    u = fa.u0 + dn * fa.u1 + law.s0 * fa.zone_unit(zones)
    g = fa.gap(np.array([c, math.pi - c_top]), dn, u, zones, law.s0) - law.h0
    p = fa.sys.moments(u, np.cos) + law.s0 * fa.zone_totals(zones)[0]
    return np.concatenate([fa.sys.edge(u), g, [p]])


def jacobian(law, st):
    """d pieces/dx at the state st (5 x 5, central differences: the half-angles' take two fixed-arc systems each;
    forward differences would not do: G's first entry is a difference of larger terms, 0.6 % off at a step
    1e-6 -- measured at M = 0.2, lambda = 20 against cohesive_two_stability's held states)."""
    x = np.array([st.eps, st.eps_top, st.c, st.c_top, st.delta_over_Delta])
    zone = min(st.c - st.eps, st.c_top - st.eps_top)
    steps = np.array([ARC_STEP * st.eps, ARC_STEP * st.eps_top, ZONE_STEP * zone, ZONE_STEP * zone, 1e-3])
    J = np.empty((5, 5))
    for j in range(5):
        dx = steps[j] * np.eye(5)[j]
        J[:, j] = (pieces(law, x + dx, st.n) - pieces(law, x - dx, st.n)) / (2 * steps[j])
    return J


def implicit_zone_matrix(J, a, b):
    """G = dg/dc at k = 0 with q = a delta/Delta + b p held (module docstring), from the Jacobian J."""
    free, ends = [0, 1, 4], [2, 3]
    q = b * J[4]
    q[4] += a
    A = np.vstack([J[0:2][:, free], q[free]])
    B = np.vstack([J[0:2][:, ends], q[ends]])
    return J[2:4][:, ends] - J[2:4][:, free] @ np.linalg.solve(A, B)


def flags(J, work_shift):
    """(stable_load, stable_grip, stable_grip_work): G's symmetric part positive definite under each control
    (work_shift: c in delta_work/Delta = delta/Delta + c p)."""
    out = []
    for a, b in ((0.0, 1.0), (1.0, 0.0), (1.0, work_shift)):
        G = implicit_zone_matrix(J, a, b)
        out.append(positive_definite(G))
    return tuple(out)
