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

from .._validate import real_array
from ..analysis import forward as _fw
from ..laws.kinetic import kinetics_of
from . import integrate as _int
from .arc import H0, H1, P0, P1, TabulatedArc
from .ramps import pull_off
from .run import rest_start


@dataclass(frozen=True)
class RateSweep:
    """Pull-off against rate: rates [N/m/s or m/s], P [N/m] (the largest tension; NaN without an event) and
    kind (the event: 'separation', 'top-contact' or why none) per rate; P_quasi_static [N/m] (the quasi-static
    path's largest tension: the fixed-load pull-off where the path passes it); P_frozen [N/m] the infinite-rate
    ceiling; asymptote [N/m] the high-rate power law per rate (load control; NaN otherwise) and its exponent
    n/(n + 2)."""

    control: str
    rates: np.ndarray
    P: np.ndarray
    kind: np.ndarray
    P_quasi_static: Optional[float]
    P_frozen: Optional[float]
    asymptote: np.ndarray
    exponent: float

    def table(self) -> dict:
        return {"rate": self.rates, "P": self.P, "kind": self.kind, "asymptote": self.asymptote}


def rate_sweep(contact, rates, control: str = "load", route: str = "table") -> RateSweep:
    """The pull-off (jkrcyl.kinetics.ramps.pull_off) at each rate, with the limits of the module docstring."""
    law = kinetics_of(contact.law)
    _fw.check_control(control)
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
    """The infinite-rate ceiling [N/m]: the zero-load contact frozen, pulled until h(pi) = 0 at that fixed arc
    (None where the gap at the top never closes so)."""
    arc, start = _arc_and_start(contact)
    if arc is None:
        return None
    y, _ = arc.at(math.log(start.a))
    if not y[H1] < 0:
        return None
    g = -y[H0] / y[H1]
    return float((y[P0] + g * y[P1]) * contact.load_scale / contact.problem.scale)


def high_rate_pull_off(contact, rate: float) -> Optional[float]:
    """The high-rate power law of the load-control pull-off [N/m] at ``rate`` [N/m/s] (module docstring; the
    power law phi = (v/v_ref)^n only: None for a user phi)."""
    law = kinetics_of(contact.law)
    arc, start = _arc_and_start(contact)
    if arc is None or law.phi is not None:
        return None
    n, R, v = law.n, contact.R, law.reference_speed

    def integrand(u):
        a = math.exp(u)
        return 2 * R * abs(arc.at(u)[0][P1]) ** (2 / n) / ((1 + a * a) * v) * a

    I = quad(integrand, math.log(start.a * _int.A_FLOOR), math.log(start.a), limit=200, epsrel=1e-12)[0]
    unit = contact.load_scale / contact.problem.scale               # N/m per kernel unit of load
    rho = rate / unit
    t_s = ((1 + 2 / n) * I / rho ** (2 / n)) ** (n / (n + 2))
    return -rate * t_s
