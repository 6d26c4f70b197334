"""The paper's printed formulas, typed by hand: the reference derive/ and the tests compare the kernels with.

Every function takes ``lib`` (``math`` for float64, ``numpy`` for arrays, ``mpmath`` for high
precision) so that a test can evaluate the printed formula at 50 digits.  Names carry the equation number.  Where the
derivation proved the print wrong, the corrected form is used and the comment says so
(see generated/DERIVATION.md, Errata).  Symbols: vartheta -> theta, zeta* -> zeta, beta* -> beta.
"""
import math


def E(a, lib=math):
    """E = sqrt(1 + a^2) = sec(eps/2) (section 4)."""
    return lib.sqrt(1 + a * a)


def L(a, lib=math):
    """L = log(1 + a^2) (section 4), evaluated as log1p so tiny a keeps its digits."""
    return lib.log1p(a * a)


def a_crit_equation(a, theta, lib=math):
    """Denominator of (4.4): 2 vartheta - log(1 + a^2) - 2 a^4; zero at a_crit."""
    return 2 * theta - L(a, lib) - 2 * a**4


def P_44(a, Delta, beta, theta, zeta, lib=math):
    """(4.4): load per unit length P(a)."""
    return (2 * (1 + a * a) * (4 * lib.pi * Delta * theta / beta * a * a
                               - zeta * lib.sqrt(a) * (a * a - L(a, lib) + 2 * theta))
            / a_crit_equation(a, theta, lib))


def B_45a(a, Delta, R, beta, theta, zeta, lib=math):
    """(4.5a): B = int N dphi over the contact."""
    return (4 * theta / (R * beta) * (2 * lib.pi * Delta * (L(a, lib) + 2 * a**4)
                                      - zeta * beta * lib.sqrt(a) * (1 + 2 * a * a))
            / a_crit_equation(a, theta, lib))


def C_45b(a, Delta, R, beta, theta, zeta, lib=math):
    """(4.5b): C = int p dx over the contact."""
    D, Lv, Ev = a_crit_equation(a, theta, lib), L(a, lib), E(a, lib)
    delta_part = 8 * lib.pi * Delta * theta / (R * beta) * ((1 - 2 * a * a) * (Ev - 1) + 2 * a**4) / D
    adhesion = zeta * lib.sqrt(a) / R * (Ev * (2 - 2 * a**4 + 3 * Lv - 6 * theta) / D
                                         + 2 * (4 * theta - 1 - 2 * Lv + 2 * a * a * (a * a - Lv + 2 * theta)) / D)
    return delta_part - adhesion


def c0_c1_26(B, P, Delta, R, beta, theta):
    """(2.6) with R (kappa + 1)/(8 pi G) = R beta/(8 pi vartheta)."""
    return -Delta - R * beta * B / (8 * math.pi * theta), beta * P / (2 * math.pi)


def r0_212(a, c0, c1, C, R, beta, lib=math):
    """Coefficient of the unbounded term of (2.12)."""
    Ev = E(a, lib)
    return 4 * (Ev - 1) / (R * beta) * (c0 - c1 / Ev) + C / lib.pi


def p_212(x, a, c0, c1, C, R, beta, lib=math, S=None):
    """(2.12): pressure p(x) = N(phi) at x = tan(phi/2), |x| < a; returns (bounded, unbounded).

    S = sqrt(a^2 - x^2) may be passed when the caller has it without cancellation.
    """
    S = lib.sqrt(a * a - x * x) if S is None else S
    Ev = E(a, lib)
    unbounded = r0_212(a, c0, c1, C, R, beta, lib) / S
    bounded = (4 * c1 / (R * beta) * S / ((1 + x * x) * Ev)
               - 4 * c0 / (R * beta) * lib.atanh(S / Ev))
    return bounded, unbounded


def N_54(phi, a, r0, c0, c1, R, beta, lib=math):
    """(5.4): pressure in the original angle, |phi| < eps; returns (bounded, unbounded)."""
    eps = 2 * lib.atan(a)
    cp, ce = lib.cos(phi / 2), lib.cos(eps / 2)
    s = lib.sqrt(cp * cp - ce * ce)
    unbounded = r0 * cp * ce / s
    bounded = 4 * c1 / (R * beta) * cp * s - 4 * c0 / (R * beta) * lib.log((cp + s) / ce)
    return bounded, unbounded


def K_34(a, c0, c1, C, R, beta, lib=math):
    """(3.4): stress-intensity factor K*."""
    return (-lib.sqrt(4 * lib.pi * R / (1 + a * a)) * lib.sqrt(1 / (2 * a))
            * (4 * (E(a, lib) - 1) / (R * beta) * (c0 - c1 / E(a, lib)) + C / lib.pi))


def K_griffith_36a(w, beta, lib=math):
    """(3.6a): K* = sqrt(4 w/(pi A)), A = beta*/(2 pi)."""
    return lib.sqrt(4 * w / (lib.pi * beta / (2 * lib.pi)))


def P_71(a, Delta, G, kappa, beta, lib=math):
    """(7.1): adhesionless load."""
    return 8 * lib.pi * Delta * G * a * a * (1 + a * a) / (2 * G * beta - (L(a, lib) + 2 * a**4) * (1 + kappa))


def BR_over_P_72(a, lib=math):
    """(7.2): B R/P without adhesion; -> 1 as a -> 0."""
    return (L(a, lib) + 2 * a**4) / (a * a * (1 + a * a))


def P_74(a, Delta, R, beta, w, lib=math):
    """(7.4): Barquins' half-plane load with a_h = 2 a R, 1/R* = 1/R_D - 1/R, A = beta/(2 pi)."""
    A, R_D = beta / (2 * lib.pi), R - Delta
    a_h, inv_R_star = 2 * a * R, 1 / R_D - 1 / R
    return a_h**2 / (2 * A) * inv_R_star * R_D / R - lib.sqrt(4 * a_h * w / A)


def P_R_star_76(a, M_R, lib=math):
    """(7.6): rubbery cylinder in a rigid cradle, P_R* = (1 + a^2)(a^2 - 2 M_R* sqrt(a))."""
    return (1 + a * a) * (a * a - 2 * M_R * lib.sqrt(a))


def lift_off_77(a, M_R, lib=math):
    """(7.7): 4 a^(7/2) - 5 M_R* a^2 + 2 a^(3/2) - M_R* = 0 at lift-off."""
    return 4 * a**3.5 - 5 * M_R * a * a + 2 * a**1.5 - M_R


def zero_load_81(a0, M, theta, lib=math):
    """(8.1): a0^(3/2)/M - a0^2 - 2 vartheta + log(1 + a0^2) = 0 at zero load."""
    return a0**1.5 / M - a0 * a0 - 2 * theta + L(a0, lib)


def delta_58(a, Delta, R, beta, theta, G_I, zeta, lib=math):
    """(5.8) with B, P, C of (4.4)-(4.5), c0, c1 of (2.6); L_s = log sin(eps/2).

    The extracted first term reads "B R kappa+1 / 4 pi  P/2G"; it is read as
    B R (kappa + 1)/(4 pi 2G) = B R beta/(8 pi vartheta) (dimensionally the only consistent
    reading; derive/approach.py proves (5.8) with it equal to the derived approach).
    """
    B = B_45a(a, Delta, R, beta, theta, zeta, lib)
    P = P_44(a, Delta, beta, theta, zeta, lib)
    C = C_45b(a, Delta, R, beta, theta, zeta, lib)
    c0, c1 = -Delta - R * beta * B / (8 * lib.pi * theta), beta * P / (2 * lib.pi)
    eps = 2 * lib.atan(a)
    Ls = lib.log(lib.sin(eps / 2))
    return (B * R * beta / (8 * lib.pi * theta) + P / (4 * lib.pi) * (beta / 2 - 1 / G_I)
            - (5 * c0 / 4 + c0 * Ls + 19 * c1 / 16 + 17 * c1 * Ls / 8)
            - c1 / 16 * (5 + 6 * Ls) * lib.cos(2 * eps)
            + 1 / (4 * lib.pi) * (3 + 4 * Ls) * (4 * (c0 + c1) * lib.pi - beta * R * C) * lib.cos(eps / 2)**3
            - (6 * c1 * (1 + Ls) + c0 * (7 + 12 * Ls)) * lib.cos(eps) / 4)


def load_solution_t(a, Delta, R, beta, inv_theta, zeta, lib=math):
    """(4.4) and (4.5a) divided through by vartheta (as the paper does for vartheta -> inf in (7.5)),
    c0, c1 of (2.6) and r0 from the Griffith condition (3.6b): r0 = -E zeta sqrt(a)/(pi R).

    inv_theta = 1/vartheta, so the rigid cradle is inv_theta = 0.  Returns a dict P, B, c0, c1, r0.
    """
    t, Ev, Lv, sa = inv_theta, E(a, lib), L(a, lib), lib.sqrt(a)
    D = 2 - t * (Lv + 2 * a**4)
    P = 2 * Ev**2 * (4 * lib.pi * Delta * a**2 / beta - zeta * sa * (2 + t * (a**2 - Lv))) / D
    B = 4 / (R * beta) * (2 * lib.pi * Delta * (Lv + 2 * a**4) - zeta * beta * sa * (1 + 2 * a**2)) / D
    return dict(P=P, B=B, c0=-Delta - R * beta * t * B / (8 * lib.pi), c1=beta * P / (2 * lib.pi),
                r0=-Ev * zeta * sa / (lib.pi * R))
