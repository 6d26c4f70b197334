"""Special cases of section 7 (and the half-plane comparison of section 8.1), as limits of the general
result derived in derive/special.py and emitted into generated/special.py.

* adhesionless contact (7.1), (7.2);
* Barquins / Hertz half-plane (7.3b)-(7.4), its normalised form P_h* = a^2/vartheta - 2 M sqrt(a) and
  its adherence force (minimum of P_h*): a = (vartheta M/2)^(2/3), P_h* = -(3/2)(vartheta M^4/2)^(1/3);
* rubbery cylinder in a rigid cradle, vartheta = inf (7.5)-(7.7), lift-off contact parameter;
* neat fit Delta = 0 (section 7.3): M and P* divide by Delta and are undefined, so loads are
  normalised by the adhesion instead, Q* = P sqrt(A)/sqrt(2 w R) = P/zeta*, and the gap by
  zeta* beta* (h(pi)/(zeta* beta*) is a function of a and vartheta only).
"""
import math

import numpy as np

from ._validate import contact_parameter, finite_scalar, theta as _check_theta
from .critical import a_crit as _a_crit
from .numerics import kernels, roots


def _zeta(w, R, beta):
    """zeta* = sqrt(2 w R/A), A = beta*/(2 pi) (3.6)."""
    return np.sqrt(2 * w * R / (beta / (2 * math.pi)))


# --- (7.1), (7.2) ------------------------------------------------------------------------------
def adhesionless_load(a, Delta, G, kappa, beta):
    """(7.1): P|_{w=0} = 8 pi Delta G a^2 (1 + a^2)/(2 G beta* - (L + 2a^4)(1 + kappa)) [N/m]."""
    return kernels.special("adhesionless_load", a=contact_parameter(a), Delta=Delta, beta=beta,
                           inv_theta=(1 + kappa) / (G * beta))


def adhesionless_BR_over_P(a):
    """(7.2): B R/P|_{w=0} = (log(1 + a^2) + 2 a^4)/(a^2 (1 + a^2)); -> 1 as a -> 0."""
    return kernels.special("adhesionless_BR_over_P", a=contact_parameter(a))


# --- half-plane (7.3)-(7.4) --------------------------------------------------------------------
def half_plane_load(a, Delta, R, beta, w):
    """(7.4): P_h = a_h^2 R_D/(2 A R* R) - sqrt(4 a_h w/A), a_h = 2 a R, 1/R* = 1/R_D - 1/R [N/m]."""
    return kernels.special("half_plane_load", a=contact_parameter(a), Delta=Delta, beta=beta,
                           zeta=_zeta(w, R, beta))


def half_plane_P_star(a, M, theta):
    """(7.3b) normalised as in section 6: P_h* = a^2/vartheta - 2 M sqrt(a) (the a -> 0 limit of P*)."""
    th = _check_theta(theta)
    return kernels.special("half_plane_P_star", a=contact_parameter(a), M=M,
                           inv_theta=kernels.inv_theta_of(th))


def half_plane_adherence(M, theta):
    """Minimum of P_h* (Barquins' fixed-load pull-off): (a, P_h*) = ((vartheta M/2)^(2/3), -(3/2)(vartheta M^4/2)^(1/3))."""
    M = finite_scalar("M", M, low=0.0)
    th = _check_theta(theta)
    a, P_star = kernels.special("half_plane_adherence", M=M, theta=th)
    return float(a), float(P_star)


# --- rubbery cylinder, vartheta = inf (7.5)-(7.7) -------------------------------------------------
def rubbery_load(a, Delta, beta, w, R):
    """(7.5): P = 4 pi (1 + a^2) Delta a^2/beta* - 2 (1 + a^2) sqrt(2 w a R/A), A = beta*/(2 pi) [N/m]."""
    return kernels.special("rubbery_load", a=contact_parameter(a), Delta=Delta, beta=beta,
                           zeta=_zeta(w, R, beta))


def rubbery_P_star(a, M_R):
    """(7.6): P_R* = (1 + a^2)(a^2 - 2 M_R* sqrt(a)), P_R* = P beta*/(4 pi Delta), M_R* = sqrt(w A R)/(sqrt(2) Delta)."""
    return kernels.special("rubbery_P_star", a=contact_parameter(a), M_R=M_R)


def rubbery_lift_off(M_R):
    """The lift-off contact parameter: the root of (7.7), and P_R* there: (a, P_R*).

    (7.7) is -M_R* < 0 at a = 0 and grows without bound; the first sign change found by doubling
    and Brent's method is the minimum of (7.6) (tests compare it with the general P* minimum search).
    (nan, nan) for M_R* = 0 (no adhesion: no lift-off)."""
    M_R = finite_scalar("M_R", M_R, low=0.0)
    if M_R == 0:
        return math.nan, math.nan
    f = lambda x, args: float(kernels.special("lift_off", a=x, M_R=M_R))
    lo, hi = 0.0, 1.0
    while f(hi, ()) <= 0:
        lo, hi = hi, 2 * hi
    a = roots.brent(f, lo, hi)
    return a, float(rubbery_P_star(a, M_R))


# --- neat fit, Delta = 0 (section 7.3) --------------------------------------------------------------
def neat_fit_Q(a, theta):
    """Q* = P sqrt(A)/sqrt(2 w R) = P/zeta* at Delta = 0 from (4.4):
    Q* = -2 (1 + a^2) sqrt(a) (2 vartheta + a^2 - L)/(2 vartheta - L - 2 a^4); vartheta = inf allowed."""
    th = _check_theta(theta)
    return kernels.special("neat_fit_load", a=contact_parameter(a), inv_theta=kernels.inv_theta_of(th))


def neat_fit_gap_pi(a, theta):
    """h(pi)/(zeta* beta*) at Delta = 0 (gap kernel with Delta = 0); >= 0 is the gap inequality."""
    a = contact_parameter(a).ravel()
    th = _check_theta(theta)
    return kernels.gap_pi(a, Delta=0.0, beta=1.0, inv_theta=kernels.inv_theta_of(th), zeta=1.0)


def neat_fit_curve(theta, n=400):
    """Super-critical neat-fit equilibria (a, eps, Q*, feasible): a_crit < a, eps* uniform in (0.5, 1)."""
    th = _check_theta(theta)
    if math.isinf(th):
        raise ValueError("theta: the neat fit has no equilibria for theta = inf (Q* < 0 needs a > a_crit = inf)")
    s = 0.5 + 0.5 * (np.arange(n) + 0.5) / n
    a = _a_crit(th) * np.tan(np.pi * s / 2)
    return dict(a=a, eps=2 * np.arctan(a), eps_star=s, Q_star=neat_fit_Q(a, th),
                feasible=neat_fit_gap_pi(a, th) >= 0)
