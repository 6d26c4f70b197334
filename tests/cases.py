"""Contacts several test files build the same way."""
import math

import jkrcyl


def cohesive_contact(E, nu, E_I, nu_I, h0, lam, R=1e-2, Delta=1e-5):
    """The Maugis-Dugdale contact of a material pair with range h0 (in Delta) and transition parameter lambda:
    h0/Delta = m^2/s0 with s0 = lambda m^(2/3)/4 fixes m = (h0 lambda/4)^(3/4), hence M and w (M grows as sqrt(w)).
    Two rigid bodies get an elastic pin (E_I 1 GPa): there is no elasticity at all otherwise."""
    if math.isinf(E) and math.isinf(E_I):
        E_I = 1e9
    mat = jkrcyl.Materials.from_young(E=E, nu=nu, E_I=E_I, nu_I=nu_I)
    probe = jkrcyl.Contact(R, Delta, 1.0, mat)
    m = (h0 * lam / 4) ** 0.75
    M = m if math.isinf(probe.problem.theta) else m / probe.problem.theta
    return jkrcyl.Contact.with_lambda(R, Delta, (M / probe.M) ** 2, mat, lam)


def two_patch_dE_ddelta(fam, s, x, h):
    """(Richardson's dE/d(delta), the raw central quotient) of a two-patch family at its state s, from states solved
    alone at the top arc x +- h, x +- 2h (the same node count): what a test holds against p (dE = p d(delta))."""
    E, D = {}, {}
    for k in (-2, -1, 1, 2):
        t = fam.at(1, x + k * h, s.eps, fam.n)
        E[k], D[k] = fam.potential(t), t.delta_over_Delta
    d1, d2 = (E[1] - E[-1]) / (D[1] - D[-1]), (E[2] - E[-2]) / (D[2] - D[-2])
    return (4 * d1 - d2) / 3, d1
