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
