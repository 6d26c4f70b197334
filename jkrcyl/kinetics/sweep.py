"""Pull-off against rate (:func:`rate_sweep`) and its limits: the quasi-static value at low rate, the power law
at high rate (:func:`high_rate_pull_off`, load control) and the frozen contact at infinite rate
(:func:`frozen_pull_off`).

High rate, load control.  Once the tension P = -rate t is large against the adhesionless load of the contact,
g = (p - p0)/p1 ~ p/p1(a) and an opening edge moves at V = v_ref (G/w)^(1/n) = v_ref |p/p1(a)|^(2/n)
(v_ref = v*/a_T).  With da/dt = -(1 + a^2)/(2R) V the equation separates:

    I = int_0^a0 2R |p1(a)|^(2/n) / ((1 + a^2) v_ref) da = rho^(2/n) t_s^(1 + 2/n) / (1 + 2/n),

rho the rate in kernel units, so the load at which the contact is gone is

    P_s = -rate t_s,   t_s = [(1 + 2/n) I / rho^(2/n)]^(n/(n + 2)),   |P_s| ~ rate^(n/(n + 2)).

In the half-plane limit (a small contact in a large hole, Barquins' cylinder (7.3)-(7.4), p1 ~ -sqrt(a)) the
integral is elementary and gives the same exponent n/(n + 2).  The power law holds until the gap at the top
closes first: at infinite rate the zero-load contact is frozen and the pin is pulled up until h(pi) = 0 at that
fixed arc (:func:`frozen_pull_off`), the ceiling of the pull-off under every control.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional

import numpy as np
from scipy.integrate import quad

from .._validate import control as _check_control, real_array
from ..laws.kinetic import kinetics_of
from . import integrate as _int
from .arc import H0, H1, P0, P1, TabulatedArc
from .ramps import pull_off
from .run import rest_start


@dataclass(frozen=True)
class RateSweep:
    """Pull-off against rate, what :func:`rate_sweep` returns.

    Attributes
    ----------
    control : str
        The held quantity: 'load', 'grip' or 'grip-work'.
    rates : numpy.ndarray
        The rates [N/m/s under load, m/s under either approach].
    P : numpy.ndarray
        The pull-off per rate [N/m]: the largest tension before the event (NaN without one).
    kind : numpy.ndarray of str
        The event per rate: 'separation', 'top-contact', or why there is none.
    P_quasi_static : float or None
        The quasi-static path's largest tension [N/m] (the fixed-load pull-off where the path passes it).
    P_frozen : float or None
        The infinite-rate ceiling [N/m] (:func:`frozen_pull_off`).
    asymptote : numpy.ndarray
        The high-rate power law per rate [N/m] (:func:`high_rate_pull_off`; load control, NaN otherwise).
    exponent : float
        Its exponent n/(n + 2).

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m,
    ...                      kinetics=jkrcyl.CrackKinetics(v_star=1e-6, n=0.6))
    >>> sw = rate_sweep(pin, [1e-12, 1e-11], control="grip-work")    # m/s
    >>> list(sw.table()), sw.exponent == 0.6 / 2.6                  # Barquins' high-rate exponent n/(n + 2)
    (['rate', 'P', 'kind', 'asymptote'], True)
    """

    control: str
    rates: np.ndarray
    P: np.ndarray
    kind: np.ndarray
    P_quasi_static: Optional[float]
    P_frozen: Optional[float]
    asymptote: np.ndarray
    exponent: float

    def table(self) -> dict:
        """Columns rate, P, kind, asymptote (one row per rate) for CSV or JSON output."""
        return {"rate": self.rates, "P": self.P, "kind": self.kind, "asymptote": self.asymptote}


def rate_sweep(contact, rates, control: str = "load", route: str = "table") -> RateSweep:
    """The pull-off at each rate, from the zero-load contact at rest, with the limits (module docstring).

    Parameters
    ----------
    contact : jkrcyl.Contact
        A contact with crack kinetics (``kinetics=jkrcyl.CrackKinetics(...)``).
    rates : array_like
        Rates > 0: of the load [N/m/s] under ``control='load'``, of the held approach [m/s] otherwise.
    control : str, optional
        'load' (default), 'grip-work' (delta_work pulled: a testing machine) or 'grip' (the paper's delta).
    route : str, optional
        'table' (default: the fixed-arc states tabulated once per contact) or 'direct' (solved at every step).

    Returns
    -------
    RateSweep
        The pull-off and its event per rate, the quasi-static value, the power law and the ceiling.

    Raises
    ------
    ValueError
        The contact has no crack kinetics; a rate is not finite and > 0; an unknown control or route.

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m,
    ...                      kinetics=jkrcyl.CrackKinetics(v_star=1e-6, n=0.6))
    >>> sw = rate_sweep(pin, [1e-12, 1e-11], control="grip-work")    # m/s
    >>> [str(k) for k in sw.kind], [round(float(p), -1) for p in sw.P], round(sw.P_quasi_static)
    (['separation', 'separation'], [-1680.0, -2100.0], -1555)
    """
    law = kinetics_of(contact.law)
    _check_control(control)
    r = real_array("rates", rates).ravel()
    if not np.all(np.isfinite(r) & (r > 0)):
        raise ValueError(f"rates must be finite and > 0, got {r[~(np.isfinite(r) & (r > 0))][0]!r}")
    results = [pull_off(contact, control, float(x), route) for x in r]
    P = np.array([np.nan if p.P is None else p.P for p in results])
    kind = np.array([p.kind or p.reason for p in results])
    asym = np.array([np.nan if control != "load" else (high_rate_pull_off(contact, float(x)) or np.nan)
                     for x in r])
    return RateSweep(control, r, P, kind, _quasi_static(contact, control), frozen_pull_off(contact), asym,
                     law.n / (law.n + 2))


def _quasi_static(contact, control):
    """The largest tension of the quasi-static pull path: the fixed-load pull-off where the held approach passes
    it on the way to its own fold, else that fold's load."""
    own = contact.pull_off(control)
    load = contact.pull_off("load")
    if own.P is None:
        return None
    if control == "load" or load.P is None or load.state.a < own.state.a:
        return own.P
    return min(own.P, load.P)


def _arc_and_start(contact):
    start, why = rest_start(contact, "load")
    if start is None:
        return None, None
    arc = TabulatedArc(contact.problem, math.log(start.a * _int.A_FLOOR), math.log(start.a))
    return arc, start


def frozen_pull_off(contact) -> Optional[float]:
    """The infinite-rate ceiling of the pull-off: the zero-load contact frozen, pulled until h(pi) = 0 at that
    fixed arc.

    Parameters
    ----------
    contact : jkrcyl.Contact
        A contact (its law's kinetics are not used: at infinite rate the edges do not move).

    Returns
    -------
    float or None
        The load [N/m] at which the gap at the top of the hole closes; None where it never closes so (or there
        is no sub-critical zero-load contact).

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> round(frozen_pull_off(jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)))
    -4887
    """
    arc, start = _arc_and_start(contact)
    if arc is None:
        return None
    y, _ = arc.at(math.log(start.a))
    if not y[H1] < 0:
        return None
    g = -y[H0] / y[H1]
    return float(contact.units.from_kernel("load", y[P0] + g * y[P1]))


def high_rate_pull_off(contact, rate: float) -> Optional[float]:
    """The high-rate power law of the load-control pull-off, |P| ~ rate^(n/(n + 2)) (module docstring).

    Parameters
    ----------
    contact : jkrcyl.Contact
        A contact with crack kinetics, phi = (a_T v/v*)^n.
    rate : float
        The rate of the load [N/m/s].

    Returns
    -------
    float or None
        The load [N/m] at which the contact is gone on the power law; None for a user phi or without a
        sub-critical zero-load contact.

    Raises
    ------
    ValueError
        The contact has no crack kinetics.

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m,
    ...                      kinetics=jkrcyl.CrackKinetics(v_star=1e-6, n=0.6))
    >>> ratio = high_rate_pull_off(pin, 1e3) / high_rate_pull_off(pin, 1.0)
    >>> abs(ratio / 1e3 ** (0.6 / 2.6) - 1) < 1e-12                 # the exponent n/(n + 2)
    True
    """
    law = kinetics_of(contact.law)
    arc, start = _arc_and_start(contact)
    if arc is None or law.phi is not None:
        return None
    n, R, v = law.n, contact.R, law.reference_speed

    def integrand(u):
        a = math.exp(u)
        return 2 * R * abs(arc.at(u)[0][P1]) ** (2 / n) / ((1 + a * a) * v) * a

    I = quad(integrand, math.log(start.a * _int.A_FLOOR), math.log(start.a), limit=200, epsrel=1e-12)[0]
    unit = contact.units.per_kernel("load")                         # N/m per kernel unit of load
    rho = rate / unit
    t_s = ((1 + 2 / n) * I / rho ** (2 / n)) ** (n / (n + 2))
    return -rate * t_s
