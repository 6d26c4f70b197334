"""Special cases of section 7 (and the half-plane comparison of section 8.1), as limits of the general result
derived in derive/special.py and emitted into generated/special.py: adhesionless contact (7.1), (7.2); Barquins'
half plane (7.3b)-(7.4) and its adherence force; the rubbery cylinder in a rigid cradle, vartheta = inf (7.5)-(7.7);
the neat fit Delta = 0 (section 7.3), where M and P* divide by Delta and loads are normalised by the adhesion
instead, Q* = P sqrt(A)/sqrt(2 w R) = P/zeta*, and the gap by zeta* beta* (then a function of a and vartheta only).

Raises: ValueError naming a or theta outside its range, and M, M_R where a minimum is sought; the other inputs reach
the kernels as given (:class:`jkrcyl.Contact` validates them).  Examples: the README pin (G = 1 GPa, kappa = 1.8).
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

__all__ = ["adhesionless_BR_over_P", "adhesionless_load", "half_plane_P_star", "half_plane_adherence",
           "half_plane_load", "neat_fit_Q", "neat_fit_curve", "neat_fit_gap_pi", "neat_fit_stable", "rubbery_P_star",
           "rubbery_lift_off", "rubbery_load"]


def _inv(theta):
    """1/vartheta, 0 for the rigid cradle (the kernels' argument)."""
    return 0.0 if math.isinf(theta) else 1.0 / theta


def _zeta(w, R, beta):
    """zeta* = sqrt(2 w R/A), A = beta*/(2 pi) (3.6)."""
    return np.sqrt(2 * w * R / (beta / (2 * math.pi)))


# --- (7.1), (7.2) ------------------------------------------------------------------------------
def adhesionless_load(a: ArrayLike, Delta: float, G: float, kappa: float, beta: float) -> np.ndarray:
    """(7.1): P|_{w=0} = 8 pi Delta G a^2 (1 + a^2)/(2 G beta* - (L + 2a^4)(1 + kappa)) [N/m], L = log(1 + a^2).

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0.
    Delta, G, kappa, beta : float
        Clearance R - R_D [m]; shear modulus [Pa] and Kolosov constant of the body with the hole; beta* [1/Pa].

    Returns
    -------
    ndarray
        The load per unit length without adhesion [N/m], shaped like a.

    Examples
    --------
    >>> round(float(adhesionless_load(0.5, 1e-6, 1e9, 1.8, 2.8e-9)), 6)     # = Contact(w=0).state(0.5).P
    1698.085474
    """
    return kernels.special("adhesionless_load", a=contact_parameter(a), Delta=Delta, beta=beta,
                           inv_theta=(1 + kappa) / (G * beta))


def adhesionless_BR_over_P(a: ArrayLike) -> np.ndarray:
    """(7.2): B R/P|_{w=0} = (log(1 + a^2) + 2 a^4)/(a^2 (1 + a^2)), dimensionless, shaped like a; -> 1 as a -> 0.

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0.

    Returns
    -------
    ndarray

    Examples
    --------
    >>> [round(float(x), 4) for x in adhesionless_BR_over_P([1e-3, 1.0])], round((math.log(2) + 2) / 2, 4)
    ([1.0, 1.3466], 1.3466)
    """
    return kernels.special("adhesionless_BR_over_P", a=contact_parameter(a))


# --- half-plane (7.3)-(7.4) --------------------------------------------------------------------
def half_plane_load(a: ArrayLike, Delta: float, R: float, beta: float, w: float) -> np.ndarray:
    """(7.4): Barquins' half-plane load P_h = a_h^2 R_D/(2 A R* R) - sqrt(4 a_h w/A) [N/m], a_h = 2 a R, 1/R* =
    1/R_D - 1/R, A = beta*/(2 pi) (3.5).

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0 (the half-width is a_h = 2 a R).
    Delta, R : float
        Clearance R - R_D and hole radius [m].
    beta, w : float
        beta* [1/Pa] and the work of adhesion [J/m^2].

    Returns
    -------
    ndarray
        Shaped like a: the a -> 0 limit of the cylinder's load (4.4).

    Examples
    --------
    >>> round(float(half_plane_load(1e-3, 1e-6, 10e-3, 2.8e-9, 0.05)), 3)    # the cylinder: -94.737 N/m
    -94.737
    """
    return kernels.special("half_plane_load", a=contact_parameter(a), Delta=Delta, beta=beta,
                           zeta=_zeta(w, R, beta))


def half_plane_P_star(a: ArrayLike, M: float, theta: float) -> np.ndarray:
    """(7.3b) normalised as in section 6: P_h* = a^2/vartheta - 2 M sqrt(a), the a -> 0 limit of P*.

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0.
    M, theta : float
        The adhesion sqrt(w A R)/(sqrt(2) Delta vartheta) (section 6) and vartheta >= 1/2 (section 4), or inf.

    Returns
    -------
    ndarray
        P_h*, shaped like a.

    Examples
    --------
    >>> float(half_plane_P_star(0.25, 0.3, 1.0))                 # 0.25^2 - 2 (0.3) 0.5
    -0.2375
    """
    th = _check_theta(theta)
    return kernels.special("half_plane_P_star", a=contact_parameter(a), M=M, inv_theta=_inv(th))


def half_plane_adherence(M: float, theta: float) -> Tuple[float, float]:
    """The minimum of P_h* (7.3b), Barquins' fixed-load pull-off: (a, P_h*).

    Parameters
    ----------
    M, theta : float
        The adhesion M >= 0 (section 6) and vartheta >= 1/2 (section 4).

    Returns
    -------
    (float, float)
        a = (vartheta M/2)^(2/3) and P_h* = -(3/2)(vartheta M^4/2)^(1/3).

    Examples
    --------
    >>> a, P = half_plane_adherence(0.3, 1.0)
    >>> round(a, 6), round(P, 6), round(float(half_plane_P_star(np.linspace(0.2, 0.4, 2001), 0.3, 1.0).min()), 6)
    (0.282311, -0.239098, -0.239098)
    """
    M = finite_scalar("M", M, low=0.0)
    th = _check_theta(theta)
    a, P_star = kernels.special("half_plane_adherence", M=M, theta=th)
    return float(a), float(P_star)


# --- rubbery cylinder, vartheta = inf (7.5)-(7.7) -------------------------------------------------
def rubbery_load(a: ArrayLike, Delta: float, beta: float, w: float, R: float) -> np.ndarray:
    """(7.5): P = 4 pi (1 + a^2) Delta a^2/beta* - 2 (1 + a^2) sqrt(2 w a R/A) [N/m] in a rigid cradle.

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0.
    Delta, R : float
        Clearance R - R_D and hole radius [m].
    beta, w : float
        beta* = (kappa_I + 1)/(2 G_I) [1/Pa] (the cradle rigid) and the work of adhesion [J/m^2].

    Returns
    -------
    ndarray
        Shaped like a.

    Examples
    --------
    >>> round(float(rubbery_load(0.5, 20e-6, 1e-6, 0.05, 5e-3)), 6)       # incompressible roller, G_I = 1 MPa
    -20.543366
    """
    return kernels.special("rubbery_load", a=contact_parameter(a), Delta=Delta, beta=beta, zeta=_zeta(w, R, beta))


def rubbery_P_star(a: ArrayLike, M_R: float) -> np.ndarray:
    """(7.6): P_R* = (1 + a^2)(a^2 - 2 M_R* sqrt(a)), P_R* = P beta*/(4 pi Delta), M_R* = sqrt(w A R)/(sqrt(2) Delta).

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0.
    M_R : float
        M_R* of (7.6).

    Returns
    -------
    ndarray
        P_R*, shaped like a.

    Examples
    --------
    >>> float(rubbery_P_star(1.0, 0.25))                         # (1 + 1)(1 - 0.5)
    1.0
    """
    return kernels.special("rubbery_P_star", a=contact_parameter(a), M_R=M_R)


def rubbery_lift_off(M_R: float) -> Tuple[float, float]:
    """The lift-off contact parameter, the root of (7.7), and P_R* there (the minimum of (7.6)).

    (7.7) is -M_R* < 0 at a = 0 and grows without bound; its first sign change is found by doubling and Brent's
    method (jkrcyl.numerics.roots).

    Parameters
    ----------
    M_R : float
        M_R* of (7.6), >= 0.

    Returns
    -------
    (float, float)
        (a, P_R*) at lift-off; (nan, nan) for M_R* = 0 (no adhesion: no lift-off).

    Examples
    --------
    >>> a, P = rubbery_lift_off(0.3)
    >>> round(a, 6), round(P, 6), round(float(rubbery_P_star(np.linspace(0.3, 0.36, 6001), 0.3).min()), 6)
    (0.331012, -0.261451, -0.261451)
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
    """Q* = P/zeta* at Delta = 0 from (4.4) (section 7.3): -2 (1 + a^2) sqrt(a) (2 vartheta + a^2 - L)/(2 vartheta
    - L - 2 a^4), L = log(1 + a^2).

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0.
    theta : float
        vartheta >= 1/2 or inf.

    Returns
    -------
    ndarray
        Q*, shaped like a: negative below a_crit, positive above.

    Examples
    --------
    >>> [round(float(q), 6) for q in neat_fit_Q([0.5, 1.5], 1.0)]    # = Contact(Delta=0).state(a).P/zeta*
    [-2.169081, 2.628052]
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
        Flattened (one value per contact parameter).

    Examples
    --------
    >>> [round(float(h), 6) for h in neat_fit_gap_pi(1.5, 1.0)]      # = Contact(Delta=0).state(1.5).h_pi/(zeta* beta*)
    [0.444941]
    """
    a = contact_parameter(a).ravel()
    th = _check_theta(theta)
    return kernels.gap_pi(a, Delta=0.0, beta=1.0, inv_theta=_inv(th), zeta=1.0)


def neat_fit_stable(a: ArrayLike, theta: float) -> np.ndarray:
    """Fixed-load stability of neat-fit equilibria (section 8.3 at Delta = 0): Q* dQ*/da < 0.

    The one rule of jkrcyl.model.stability, (dP/da)(dP/dk)|_a < 0: without clearance P is linear in the edge
    coefficient k, so (dP/dk)|_a = P/k (dQ*/da emitted by derive/special.py).

    Parameters
    ----------
    a : float or array_like
        Contact parameter(s) tan(eps/2) > 0.
    theta : float
        vartheta >= 1/2 (finite).

    Returns
    -------
    ndarray of bool
        Shaped like a.

    Examples
    --------
    >>> neat_fit_stable([0.5, 1.5, 3.0], 1.0).tolist()           # a_crit = 0.9136 at vartheta = 1
    [False, True, False]
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
        vartheta >= 1/2, finite (the error names theta for inf: a_crit = inf leaves no super-critical side).
    n : int
        Number of points.

    Returns
    -------
    dict of ndarray
        a, eps [rad], eps_star, Q_star (:func:`neat_fit_Q`), feasible (h(pi) >= 0) and stable_load
        (:func:`neat_fit_stable`).

    Examples
    --------
    >>> c = neat_fit_curve(1.0, n=4)
    >>> c["eps_star"].tolist(), c["stable_load"].tolist()
    ([0.5625, 0.6875, 0.8125, 0.9375], [True, True, False, False])
    """
    th = _check_theta(theta)
    if math.isinf(th):
        raise ValueError("theta: the neat fit has no super-critical side for theta = inf (a > a_crit = inf is empty)")
    s = 0.5 + 0.5 * (np.arange(n) + 0.5) / n
    a = _a_crit(th) * np.tan(np.pi * s / 2)
    return dict(a=a, eps=2 * np.arctan(a), eps_star=s, Q_star=neat_fit_Q(a, th),
                feasible=neat_fit_gap_pi(a, th) >= 0, stable_load=neat_fit_stable(a, th))
