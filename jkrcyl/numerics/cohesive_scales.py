"""Scales of the Maugis-Dugdale law in the normalisation of jkrcyl.numerics.cohesive (generated/cohesive.py):
the transition parameter lambda <-> s0, the range h0/Delta, the physical law (sigma0, w) -> (m, s0), Baney and
Hui's (1997) variables and their half-plane state (the limit Delta/R -> 0, small contacts)."""
import math
from collections import namedtuple

from .._validate import finite_scalar
from ..generated import cohesive as _gc


def _positive(name, value):
    return finite_scalar(name, value, low=0.0, low_open=True)


def transition_parameter(m, s0, Delta_over_R=0.0):
    """lambda = 4 sigma0/(pi^2 E*^2 w/R_eff)^(1/3) (Baney-Hui's, E* = 4/beta*, R_eff = R R_D/Delta) of the
    normalised m > 0 (w > 0: lambda is undefined without adhesion) and s0 > 0: 4 s0 (1 - Delta/R)^(1/3)/m^(2/3)."""
    m, s0 = _positive("m", m), _positive("s0", s0)
    dr = finite_scalar("Delta_over_R", Delta_over_R, low=0.0, high=1.0)
    if dr >= 1:
        raise ValueError(f"Delta_over_R must be in [0, 1), got {dr:g}")
    return _gc.transition_parameter(Delta_over_R=dr, m=m, s0=s0)


def zone_strength(lam, m, Delta_over_R=0.0):
    """s0 = sigma0 R beta*/(4 pi Delta) of the transition parameter lam > 0 and m > 0 (inverse of
    :func:`transition_parameter`): lam m^(2/3) (1 - Delta/R)^(-1/3)/4."""
    lam, m = _positive("lam", lam), _positive("m", m)
    dr = finite_scalar("Delta_over_R", Delta_over_R, low=0.0, high=1.0)
    if dr >= 1:
        raise ValueError(f"Delta_over_R must be in [0, 1), got {dr:g}")
    return _gc.zone_strength(Delta_over_R=dr, lam=lam, m=m)


def zone_range(m, s0):
    """h0/Delta = m^2/s0 (w = sigma0 h0)."""
    return _gc.zone_range(m=finite_scalar("m", m, low=0.0), s0=_positive("s0", s0))


DugdaleParameters = namedtuple("DugdaleParameters", ["m", "s0", "lam", "h0_over_Delta"])


def dugdale_parameters(sigma0, w, R, Delta, beta):
    """Normalised law of the physical one: sigma0 [Pa] > 0, w [J/m^2] > 0, R, Delta [m] (0 < Delta < R),
    beta = beta* [1/Pa]: m = sqrt(w beta* R/(4 pi))/Delta, s0 = sigma0 R beta*/(4 pi Delta), lambda, h0/Delta."""
    sigma0 = _positive("sigma0", sigma0)
    w = _positive("w", w)
    R, Delta, beta = _positive("R", R), _positive("Delta", Delta), _positive("beta", beta)
    if Delta >= R:
        raise ValueError(f"Delta must be < R, got Delta = {Delta:g}, R = {R:g}")
    m = math.sqrt(w * beta * R / (4 * math.pi)) / Delta
    s0 = sigma0 * R * beta / (4 * math.pi * Delta)
    return DugdaleParameters(m, s0, transition_parameter(m, s0, Delta / R), zone_range(m, s0))


def baney_hui_variables(eps, p, m, Delta_over_R=0.0):
    """(abar, Pbar) of Baney and Hui (1997) from the contact half-angle eps (a = R eps) and p = P beta*/(4 pi Delta)."""
    r = _gc.baney_hui_variables(Delta_over_R=float(Delta_over_R), eps=float(eps), m=_positive("m", m), p=float(p))
    return r.abar, r.Pbar


def half_plane_state(eps, c, s0):
    """(p, h(c)/Delta) of the half-plane limit (cylinder on a flat, Baney-Hui) with the contact |phi| < eps and the
    zone eps < |phi| < c (normalised; derive/cohesive.py): p = eps^2/4 - 2 s0 sqrt(c^2 - eps^2)."""
    r = _gc.half_plane_state(c=float(c), eps=float(eps), s0=float(s0))
    return r.p, r.opening
