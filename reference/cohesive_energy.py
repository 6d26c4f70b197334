"""The second route to the stability of Maugis-Dugdale states (tests only): the energy of states whose zone end is
held off equilibrium.

For a zone |phi| < c held fixed, the minimum of the elastic energy plus the Dugdale interface energy
int (s0 h - m^2) over the zone (and -m^2 over the contact) is reached by the contact whose edge has a finite
stress (k = 0): a convex obstacle problem.  E(c) at a held load, approach or work-conjugate approach is then a
function of c alone, stationary where s0 h(c) = m^2 (the Dugdale zone end), and the equilibrium is stable when
E is a minimum there.  This module builds those constrained states from the collocation engine (a fixed contact,
its approach from k = 0 and the held quantity, the contact size a root of k = 0) and integrates their energy by
Gauss-Legendre quadrature of the returned pressure and gap -- no slope, no fixed-arc derivative, no table and no
branch of the library's cohesive solver.  Normalisation of jkrcyl.numerics.cohesive (kernel scale).
"""
import math

import numpy as np
from scipy.optimize import brentq

from jkrcyl.numerics import arcs
from jkrcyl.numerics import cohesive as co

XG, WG = np.polynomial.legendre.leggauss(200)


def _constrained(eps, c, law, held, value, n):
    """(state-like tuple) at the contact eps, zone end c: the approach from the held quantity and k = 0 is not
    imposed -- returns (k, delta, p, u, fc)."""
    m, s0, theta, gb, ar = law
    fc = co.FixedContact(eps, arcs.Kernel(theta, gb, ar), n)
    zones = co.zones_of(c)
    lu, perm, phin = fc.fx[:3]
    from jkrcyl.numerics import cohesive_kernels as ck
    uz = ck.lu_solve(lu, perm, -co.zone_displacement(phin, zones, fc.kernel))
    ua, ub = fc.fx[3] + s0 * uz, fc.fx[4]
    load = co.zone_load(zones)[0]
    p0, p1 = fc.ep @ ua - s0 * load, fc.ep @ ub
    cw = gb / 2
    if held == "load":
        delta = (value - p0) / p1
    elif held == "grip":
        delta = value
    else:                                      # delta_work = delta + (gb/2) p
        delta = (value - cw * p0) / (1 + cw * p1)
    u = ua + delta * ub
    return fc.ek @ u, delta, p0 + delta * p1, u, fc


def energy_at_zone_end(c, law, held, value, eps_guess, n=96):
    """E(c) at the held value (load p, approach delta/Delta or delta_work/Delta): the contact eps a root of k = 0
    near eps_guess; the energy by quadrature (Clapeyron's (1/2) int nu e plus int (s0 h - m^2) over the zone and
    -m^2 over the contact, minus p delta under load, plus the pin's own field (gb/4) p^2 at fixed delta_work)."""
    m, s0, theta, gb, ar = law
    k = lambda e: _constrained(e, c, law, held, value, n)[0]
    lo, hi = eps_guess * 0.97, min(eps_guess * 1.03, eps_guess + 0.5 * (c - eps_guess))
    for _ in range(60):
        if k(lo) * k(hi) < 0:
            break
        lo, hi = lo * 0.95, min(hi * 1.05, eps_guess + 0.9 * (c - eps_guess))
    eps = brentq(k, lo, hi, xtol=1e-15, rtol=1e-15)
    _, delta, p, u, fc = _constrained(eps, c, law, held, value, n)
    zones = co.zones_of(c)
    fields = co._Fields(fc, delta, u, zones, s0, fc.kernel)
    t = np.pi / 2 * XG
    phi, jac = eps * np.sin(t), eps * np.cos(t) * np.pi / 2
    total = 0.5 * np.sum(WG * jac * fields.pressure(phi) * ((1 + delta) * np.cos(phi) - 1)) - m * m * 2 * eps
    t = np.pi * (XG + 1) / 2
    phi, jac = eps + (c - eps) * (1 - np.cos(t)) / 2, (c - eps) * np.sin(t) * np.pi / 4
    h = fields.gap(phi)
    e = h - 2 * np.sin(phi / 2) ** 2 + delta * np.cos(phi)
    total += 2 * np.sum(WG * jac * (0.5 * -s0 * e - m * m + s0 * h))
    if held == "load":
        total -= p * delta
    elif held == "grip-work":
        total += gb / 4 * p * p
    return total, eps


def stable_by_energy(c, law, held, value, eps, rel=2e-3):
    """Whether E(c) is a minimum at the zone end c (second difference with step rel (c - eps)), and the second
    difference relative to the energy's scale (small: near a turning point, undecided)."""
    h = rel * (c - eps)
    E = [energy_at_zone_end(c + s * h, law, held, value, eps)[0] for s in (-1, 0, 1)]
    second = E[0] - 2 * E[1] + E[2]
    return second > 0, second / (h * h)
