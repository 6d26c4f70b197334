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


def _root_nearest(k, eps_guess, c, points=61):
    """The root of k(eps) = 0 nearest eps_guess: every sign change on a grid of eps_guess (1 +- 1/2) (kept
    inside the zone), refined by Brent, kept only where k vanishes (not where it grows) -- at fixed approach k
    has poles in eps (where the approach does not fix the fixed-arc problem: the paper's delta has d delta/dP = 0 at a fixed arc
    for some pairs), and a sign change through a pole is not a contact.  ValueError when there is none."""
    top = min(eps_guess * 1.5, eps_guess + 0.9 * (c - eps_guess))
    grid = np.concatenate([np.linspace(eps_guess * 0.5, eps_guess, points // 2 + 1),
                           np.linspace(eps_guess, top, points // 2 + 1)[1:]])
    ks = np.array([k(e) for e in grid])
    roots = []
    for i in np.nonzero(ks[:-1] * ks[1:] < 0)[0]:
        r = brentq(k, grid[i], grid[i + 1], xtol=1e-15, rtol=1e-15)
        if abs(k(r)) < 1e-3 * max(abs(ks[i]), abs(ks[i + 1])):     # a pole: |k| grows towards it
            roots.append(r)
    if not roots:
        raise ValueError(f"no contact with k = 0 near eps = {eps_guess!r}")
    return min(roots, key=lambda r: abs(r - eps_guess))


def energy_at_zone_end(c, law, held, value, eps_guess, n=96):
    """E(c) at the held value (load p, approach delta/Delta or delta_work/Delta): the contact eps a root of k = 0
    near eps_guess; the energy by quadrature (Clapeyron's (1/2) int nu e plus int (s0 h - m^2) over the zone and
    -m^2 over the contact, minus p delta under load, plus the pin's own field (gb/4) p^2 at fixed delta_work)."""
    m, s0, theta, gb, ar = law
    eps = _root_nearest(lambda e: _constrained(e, c, law, held, value, n)[0], eps_guess, c)
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
    """Whether E(c) is a minimum at the zone end c (second difference with step rel min(eps, c - eps): a small
    contact under a long zone moves by far more than the zone end, dc/d eps ~ (c - eps)/eps), and the second
    difference relative to the energy's scale (small: near a turning point, undecided)."""
    h = rel * min(eps, c - eps)
    E = [energy_at_zone_end(c + s * h, law, held, value, eps)[0] for s in (-1, 0, 1)]
    second = E[0] - 2 * E[1] + E[2]
    return second > 0, second / (h * h)
