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
from __future__ import annotations

import math
from typing import Dict, Tuple

import numpy as np
from numpy.typing import ArrayLike

from ._validate import contact_parameter, finite_scalar, theta as _check_theta
from .critical import a_crit as _a_crit
from .model import stability as _stab
from .numerics import kernels, roots


def _inv(theta):
    """1/vartheta, 0 for the rigid cradle (the kernels' argument)."""
    return 0.0 if math.isinf(theta) else 1.0 / theta


def _zeta(w, R, beta):
    """zeta* = sqrt(2 w R/A), A = beta*/(2 pi) (3.6)."""
    return np.sqrt(2 * w * R / (beta / (2 * math.pi)))


# --- (7.1), (7.2) ------------------------------------------------------------------------------
def adhesionless_load(a: ArrayLike, Delta: float, G: float, kappa: float, beta: float) -> np.ndarray:
    """(7.1): P|_{w=0} = 8 pi Delta G a^2 (1 + a^2)/(2 G beta* - (L + 2a^4)(1 + kappa)) [N/m].

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0.
    Delta : float
        Clearance R - R_D [m].
    G, kappa : float
        Shear modulus [Pa] and Kolosov constant of the body with the hole.
    beta : float
        beta* [1/Pa] (section 2).

    Returns
    -------
    ndarray
        The load per unit length without adhesion [N/m], shaped like a.
    """
    return kernels.special("adhesionless_load", a=contact_parameter(a), Delta=Delta, beta=beta,
                           inv_theta=(1 + kappa) / (G * beta))


def adhesionless_BR_over_P(a: ArrayLike) -> np.ndarray:
    """(7.2): B R/P|_{w=0} = (log(1 + a^2) + 2 a^4)/(a^2 (1 + a^2)); -> 1 as a -> 0.

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0.

    Returns
    -------
    ndarray
        B R/P without adhesion (dimensionless), shaped like a.
    """
    return kernels.special("adhesionless_BR_over_P", a=contact_parameter(a))


# --- half-plane (7.3)-(7.4) --------------------------------------------------------------------
def half_plane_load(a: ArrayLike, Delta: float, R: float, beta: float, w: float) -> np.ndarray:
    """(7.4): P_h = a_h^2 R_D/(2 A R* R) - sqrt(4 a_h w/A), a_h = 2 a R, 1/R* = 1/R_D - 1/R [N/m].

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0 (the half-width is a_h = 2 a R).
    Delta : float
        Clearance R - R_D [m].
    R : float
        Hole radius [m].
    beta : float
        beta* [1/Pa]; A = beta*/(2 pi) of (3.5).
    w : float
        Work of adhesion [J/m^2].

    Returns
    -------
    ndarray
        Barquins' half-plane load per unit length [N/m], shaped like a.
    """
    return kernels.special("half_plane_load", a=contact_parameter(a), Delta=Delta, beta=beta,
                           zeta=_zeta(w, R, beta))


def half_plane_P_star(a: ArrayLike, M: float, theta: float) -> np.ndarray:
    """(7.3b) normalised as in section 6: P_h* = a^2/vartheta - 2 M sqrt(a) (the a -> 0 limit of P*).

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0.
    M : float
        Normalised adhesion sqrt(w A R)/(sqrt(2) Delta vartheta) (section 6).
    theta : float
        vartheta >= 1/2 (section 4); inf allowed.

    Returns
    -------
    ndarray
        P_h* (dimensionless), shaped like a.
    """
    th = _check_theta(theta)
    return kernels.special("half_plane_P_star", a=contact_parameter(a), M=M,
                           inv_theta=_inv(th))


def half_plane_adherence(M: float, theta: float) -> Tuple[float, float]:
    """Minimum of P_h* (Barquins' fixed-load pull-off), from (7.3b).

    Parameters
    ----------
    M : float
        Normalised adhesion (section 6), >= 0.
    theta : float
        vartheta >= 1/2 (section 4).

    Returns
    -------
    (float, float)
        (a, P_h*) = ((vartheta M/2)^(2/3), -(3/2)(vartheta M^4/2)^(1/3)): contact parameter and normalised load.
    """
    M = finite_scalar("M", M, low=0.0)
    th = _check_theta(theta)
    a, P_star = kernels.special("half_plane_adherence", M=M, theta=th)
    return float(a), float(P_star)


# --- rubbery cylinder, vartheta = inf (7.5)-(7.7) -------------------------------------------------
def rubbery_load(a: ArrayLike, Delta: float, beta: float, w: float, R: float) -> np.ndarray:
    """(7.5): P = 4 pi (1 + a^2) Delta a^2/beta* - 2 (1 + a^2) sqrt(2 w a R/A), A = beta*/(2 pi) [N/m].

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0.
    Delta : float
        Clearance R - R_D [m].
    beta : float
        beta* [1/Pa] (the cradle rigid: (kappa_I + 1)/(2 G_I)).
    w : float
        Work of adhesion [J/m^2].
    R : float
        Hole radius [m].

    Returns
    -------
    ndarray
        Load per unit length of a rubbery cylinder in a rigid cradle [N/m], shaped like a.
    """
    return kernels.special("rubbery_load", a=contact_parameter(a), Delta=Delta, beta=beta,
                           zeta=_zeta(w, R, beta))


def rubbery_P_star(a: ArrayLike, M_R: float) -> np.ndarray:
    """(7.6): P_R* = (1 + a^2)(a^2 - 2 M_R* sqrt(a)), P_R* = P beta*/(4 pi Delta), M_R* = sqrt(w A R)/(sqrt(2) Delta).

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0.
    M_R : float
        M_R* of (7.6) (dimensionless).

    Returns
    -------
    ndarray
        P_R* (dimensionless), shaped like a.
    """
    return kernels.special("rubbery_P_star", a=contact_parameter(a), M_R=M_R)


def rubbery_lift_off(M_R: float) -> Tuple[float, float]:
    """The lift-off contact parameter: the root of (7.7), and P_R* there: (a, P_R*).

    (7.7) is -M_R* < 0 at a = 0 and grows without bound; the first sign change found by doubling
    and Brent's method is the minimum of (7.6) (tests compare it with the general P* minimum search).

    Parameters
    ----------
    M_R : float
        M_R* of (7.6), >= 0.

    Returns
    -------
    (float, float)
        (a, P_R*) at lift-off (dimensionless); (nan, nan) for M_R* = 0 (no adhesion: no lift-off).
    """
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
def neat_fit_Q(a: ArrayLike, theta: float) -> np.ndarray:
    """Q* = P sqrt(A)/sqrt(2 w R) = P/zeta* at Delta = 0 from (4.4) (section 7.3):
    Q* = -2 (1 + a^2) sqrt(a) (2 vartheta + a^2 - L)/(2 vartheta - L - 2 a^4); vartheta = inf allowed.

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0.
    theta : float
        vartheta >= 1/2 or inf.

    Returns
    -------
    ndarray
        Q* (dimensionless), shaped like a.
    """
    th = _check_theta(theta)
    return kernels.special("neat_fit_load", a=contact_parameter(a), inv_theta=_inv(th))


def neat_fit_gap_pi(a: ArrayLike, theta: float) -> np.ndarray:
    """h(pi)/(zeta* beta*) at Delta = 0 ((5.10) with Delta = 0); >= 0 is the gap inequality.

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0.
    theta : float
        vartheta >= 1/2 or inf.

    Returns
    -------
    ndarray
        h(pi)/(zeta* beta*) (dimensionless), flattened.
    """
    a = contact_parameter(a).ravel()
    th = _check_theta(theta)
    return kernels.gap_pi(a, Delta=0.0, beta=1.0, inv_theta=_inv(th), zeta=1.0)


def neat_fit_stable(a: ArrayLike, theta: float) -> np.ndarray:
    """Fixed-load stability of neat-fit equilibria (section 8.3 at Delta = 0): the one rule of
    jkrcyl.model.stability, (dP/da)(dP/dk)|_a < 0; without clearance P is linear in the edge coefficient k, so
    (dP/dk)|_a = P/k and the flag is Q* dQ*/da < 0 (dQ*/da emitted by derive/special.py).

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0.
    theta : float
        vartheta >= 1/2 (finite).

    Returns
    -------
    ndarray of bool
    """
    th = _check_theta(theta)
    arr = contact_parameter(a)
    Q = kernels.special("neat_fit_load", a=arr, inv_theta=_inv(th))
    return _stab.stable(kernels.special("neat_fit_slope", a=arr, inv_theta=_inv(th)), Q)


def neat_fit_curve(theta: float, n: int = 400) -> Dict[str, np.ndarray]:
    """Super-critical neat-fit equilibria (Fig. 8): a_crit < a, eps* uniform in (0.5, 1).

    Parameters
    ----------
    theta : float
        vartheta >= 1/2 (finite: the neat fit has no equilibria for a rigid cradle).
    n : int
        Number of points.

    Returns
    -------
    dict of ndarray
        a, eps [rad], eps_star, Q_star (Q* of (4.4) at Delta = 0), feasible (h(pi) >= 0) and stable_load
        (:func:`neat_fit_stable`).
    """
    th = _check_theta(theta)
    if math.isinf(th):
        raise ValueError("theta: the neat fit has no equilibria for theta = inf (Q* < 0 needs a > a_crit = inf)")
    s = 0.5 + 0.5 * (np.arange(n) + 0.5) / n
    a = _a_crit(th) * np.tan(np.pi * s / 2)
    return dict(a=a, eps=2 * np.arctan(a), eps_star=s, Q_star=neat_fit_Q(a, th),
                feasible=neat_fit_gap_pi(a, th) >= 0, stable_load=neat_fit_stable(a, th))
