"""Branches of equilibria and points on them: :class:`Curve` (one patch), :class:`Point`, :class:`TwoPatchCurve`."""
from __future__ import annotations

import math
from dataclasses import dataclass, fields as dataclass_fields, replace
from typing import Dict, Optional, Tuple

import numpy as np

from ..units import CONTROLS, Units
from .states import Equilibrium


def _with_units(obj, units: Units):
    """The dimensional fields P [N/m], delta, delta_work [m] from the normalised ones."""
    return replace(obj, **{c.physical: units.physical(c.name, getattr(obj, c.normalised)) for c in CONTROLS.values()})


@dataclass(frozen=True)
class Curve:
    """One single-patch branch of equilibria (numpy arrays over the contact parameter a, increasing).

    What :func:`jkrcyl.equilibria.curve` and :meth:`jkrcyl.Contact.curve` return.

    Attributes
    ----------
    M, theta, gb, alpha_ratio : float
        The problem (section 6; gb = (1/G_I)/beta*, alpha_ratio = alpha*/beta*).
    regime : str
        'sub-critical' or 'super-critical' (the cohesive law: 'sub-critical', 'contactless', 'top-bridge').
    a, eps, eps_star : ndarray
        a = tan(eps/2); eps [rad]; eps* = 2 atan(a/a_crit)/pi (eps/pi where a_crit = inf).  Cohesive law
        (jkrcyl.model.cohesive): a is the branch parameter (the arclength of the traced branch), eps the contact
        half-angle (0 for zone-only states).
    P_star, delta_over_Delta, delta_work_over_Delta, h_pi_over_Delta : ndarray
        P* (P_R* when vartheta = inf), delta/Delta (5.8), delta_work/Delta, h(pi)/Delta (5.10).  delta_work =
        delta + P/(8 pi G_I) is the work-conjugate approach (derive/green.py: the pin's centroid, load spread
        over the pin; the paper's delta is the rims' approach).
    feasible, stable_load, stable_grip, stable_grip_work : ndarray of bool
        The gap inequality h(pi) >= 0 (and the law's); stable at fixed P, delta, delta_work
        (jkrcyl.model.stability).
    dP_star_da, ddelta_da, ddelta_work_da : ndarray
        Slopes along the branch.
    dG_da_P, dG_da_delta, dG_da_delta_work : ndarray
        (1/w) dG/da at fixed P, delta, delta_work (section 8.3; NaN where w = 0 and for the cohesive law).
    P, delta, delta_work : ndarray or None
        [N/m], [m], [m] when the curve comes from a Contact (:meth:`with_units`).
    c, c_top : ndarray or None
        The cohesive zone ends [rad]; None for JKR.
    ends : tuple of str or None
        'top-bridge' only: how each family ends, in words (jkrcyl.model.cohesive_bridge.ENDS); its parameter is
        a = j + c_top/pi for the family j = 0, 1, ... (in increasing junction contact).

    Examples
    --------
    >>> import jkrcyl
    >>> c = jkrcyl.equilibria.curve(0.3, 1.0, n=5, gb=1 / 2.8)
    >>> c
    Curve(sub-critical, M=0.3, theta=1, 5 points)
    >>> [round(float(x), 4) for x in c.eps_star]
    [0.05, 0.15, 0.25, 0.35, 0.45]
    """

    M: float
    theta: float
    gb: float
    regime: str
    a: np.ndarray
    eps: np.ndarray
    eps_star: np.ndarray
    P_star: np.ndarray
    delta_over_Delta: np.ndarray
    h_pi_over_Delta: np.ndarray
    feasible: np.ndarray
    stable_load: np.ndarray
    stable_grip: np.ndarray
    dP_star_da: np.ndarray
    ddelta_da: np.ndarray
    dG_da_P: np.ndarray
    dG_da_delta: np.ndarray
    delta_work_over_Delta: np.ndarray
    ddelta_work_da: np.ndarray
    dG_da_delta_work: np.ndarray
    stable_grip_work: np.ndarray
    P: Optional[np.ndarray] = None
    delta: Optional[np.ndarray] = None
    delta_work: Optional[np.ndarray] = None
    alpha_ratio: float = 0.0
    c: Optional[np.ndarray] = None
    c_top: Optional[np.ndarray] = None
    ends: Optional[Tuple[str, ...]] = None

    COLUMNS = ("a", "eps", "eps_star", "P_star", "delta_over_Delta", "delta_work_over_Delta", "h_pi_over_Delta",
               "feasible", "stable_load", "stable_grip", "stable_grip_work")

    def with_units(self, units: Units) -> "Curve":
        """This curve with the dimensional fields P [N/m], delta and delta_work [m].

        Parameters
        ----------
        units : jkrcyl.Units
            The contact's scales (:attr:`jkrcyl.Contact.units`): P = P* load_scale, delta = (delta/Delta) Delta.

        Returns
        -------
        Curve

        Examples
        --------
        >>> import jkrcyl
        >>> units = jkrcyl.Units(Delta=1e-6, load_scale=1000.0)          # P = 1000 N/m P*, Delta = 1 um
        >>> c = jkrcyl.equilibria.curve(0.3, 1.0, n=5, gb=1 / 2.8).with_units(units)
        >>> bool((c.P == 1000.0 * c.P_star).all()), bool((c.delta == 1e-6 * c.delta_over_Delta).all())
        (True, True)
        """
        return _with_units(self, units)

    def table(self) -> Dict[str, np.ndarray]:
        """Columns of :attr:`COLUMNS` (plus P [N/m], delta, delta_work [m] when dimensional, c, c_top for the
        cohesive law) as a dict of float arrays (booleans as 0/1), for CSV output.

        Returns
        -------
        dict of ndarray

        Examples
        --------
        >>> import jkrcyl
        >>> t = jkrcyl.equilibria.curve(0.3, 1.0, n=5, gb=1 / 2.8).table()
        >>> list(t)[:4], t["stable_load"].tolist()
        (['a', 'eps', 'eps_star', 'P_star'], [0.0, 0.0, 0.0, 1.0, 1.0])
        """
        cols = self.COLUMNS + (("P", "delta", "delta_work") if self.P is not None else ())
        cols += tuple(k for k in ("c", "c_top") if getattr(self, k) is not None)
        return {k: np.asarray(getattr(self, k), dtype=float) for k in cols}

    def __repr__(self) -> str:
        return (f"Curve({self.regime}, M={self.M:.6g}, theta={self.theta:.6g}, {np.size(self.a)} points"
                f"{', dimensional' if self.P is not None else ''})")


@dataclass(frozen=True, repr=False)
class Point(Equilibrium):
    """A stationary point on a branch: the equilibrium where the held quantity of ``control`` (P*, delta or
    delta_work) is a minimum or maximum along the branch -- an :class:`~jkrcyl.results.Equilibrium` with what
    kind of point it is.

    What :func:`jkrcyl.equilibria.stationary_points`, :func:`jkrcyl.equilibria.adherence` (normalised: P = P*,
    delta = delta/Delta) and :meth:`jkrcyl.Contact.adherence` (SI) return.

    Attributes
    ----------
    (those of Equilibrium), and
    kind : str
        'min' or 'max'.
    outcome : str or None
        Control 'load', from adherence: what a further pull does -- 'detachment' (a feasible sub-critical
        minimum: the contact shrinks away), 'zip-full' (a feasible super-critical minimum: the contact grows round
        into full contact), for an infeasible point (h(pi) < 0: the gap at the top closes first) the regime of the
        confined analysis (jkrcyl.results.paths.REGIMES), or 'gap-closes-first' where that analysis does not apply
        (vartheta = inf).
    M, theta, gb, alpha_ratio : float
        The problem (section 6).
    eps_star, h_pi_over_Delta : float
        eps* = 2 atan(a/a_crit)/pi and h(pi)/Delta (5.10), as in :class:`Curve`.

    Examples
    --------
    >>> import jkrcyl
    >>> p = jkrcyl.equilibria.adherence(0.3, 1.0, gb=1 / 2.8)[0]
    >>> p.kind, round(p.P_star, 4), p.outcome, p.P == p.P_star, p.stable
    ('min', -0.2856, 'detachment', True, False)
    """

    kind: str = "min"
    outcome: Optional[str] = None
    M: float = math.nan
    theta: float = math.nan
    gb: Optional[float] = None
    alpha_ratio: float = 0.0
    eps_star: float = math.nan
    h_pi_over_Delta: float = math.nan

    @classmethod
    def of(cls, state: Equilibrium, **fields) -> "Point":
        """The point at an equilibrium ``state`` (the fields of Point beyond Equilibrium's as keywords)."""
        return cls(**{f.name: getattr(state, f.name) for f in dataclass_fields(Equilibrium)}, **fields)

    def __repr__(self) -> str:
        return (f"Point({self.kind} of {CONTROLS[self.control].physical} on {self.branch}, a={self.a:.6g}, "
                f"P*={self.P_star:.6g}, feasible={self.feasible}, outcome={self.outcome})")


@dataclass(frozen=True)
class TwoPatchCurve:
    """One branch of two-patch equilibria (contact at the bottom and the top at once), ordered along the curve.

    What :func:`jkrcyl.equilibria.two_patch` and :meth:`jkrcyl.Contact.two_patch` return.

    Attributes
    ----------
    M, theta, gb, alpha_ratio, a, eps, eps_star, P_star, delta_over_Delta, delta_work_over_Delta
        As :class:`Curve`.
    feasible, stable_load, stable_grip, stable_grip_work, P, delta, delta_work
        As :class:`Curve` (P, delta, delta_work when made from a Contact).
    a_top, eps_top, eps_top_star : ndarray
        The top contact, as a, eps, eps_star.
    gap_min : ndarray
        min h/Delta outside both arcs.
    G_bot, G_top : ndarray
        G/w at the bottom and top edges (1 on the branch).
    ends : tuple of str
        How each end finishes: 'single' (a_top -> 0: the single-patch state with h(pi) = 0), 'mirror' (a -> 0:
        the upside-down single patch), 'full' (eps + eps_top -> pi: into full contact) or 'loop' (a closed curve);
        under the Maugis-Dugdale law 'single'/'mirror' end at an arc of 1e-4 rad (its zone stays: a bridge), and
        'unresolved' where the states stop short (jkrcyl.analysis.cohesive_two_patch).

    Examples
    --------
    >>> import jkrcyl
    >>> b, = jkrcyl.equilibria.two_patch(0.5, 1.0, n=20, gb=1 / 2.8)
    >>> b
    TwoPatchCurve(M=0.5, theta=1, 20 points, ends single -> mirror, 0 stable under load)
    """

    M: float
    theta: float
    gb: float
    a: np.ndarray
    a_top: np.ndarray
    eps: np.ndarray
    eps_top: np.ndarray
    eps_star: np.ndarray
    eps_top_star: np.ndarray
    P_star: np.ndarray
    delta_over_Delta: np.ndarray
    delta_work_over_Delta: np.ndarray
    gap_min: np.ndarray
    feasible: np.ndarray
    stable_load: np.ndarray
    stable_grip: np.ndarray
    stable_grip_work: np.ndarray
    G_bot: np.ndarray
    G_top: np.ndarray
    ends: tuple
    alpha_ratio: float = 0.0
    P: Optional[np.ndarray] = None
    delta: Optional[np.ndarray] = None
    delta_work: Optional[np.ndarray] = None

    COLUMNS = ("a", "a_top", "eps", "eps_top", "eps_star", "eps_top_star", "P_star", "delta_over_Delta",
               "delta_work_over_Delta", "gap_min", "feasible", "stable_load", "stable_grip", "stable_grip_work")

    def with_units(self, units: Units) -> "TwoPatchCurve":
        """This branch with P [N/m], delta and delta_work [m]: :meth:`Curve.with_units`.

        Parameters
        ----------
        units : jkrcyl.Units
            The contact's scales (:attr:`jkrcyl.Contact.units`).

        Returns
        -------
        TwoPatchCurve

        Examples
        --------
        >>> import jkrcyl
        >>> b, = jkrcyl.equilibria.two_patch(0.5, 1.0, n=20, gb=1 / 2.8)
        >>> bool((b.with_units(jkrcyl.Units(Delta=1e-6, load_scale=1000.0)).P == 1000.0 * b.P_star).all())
        True
        """
        return _with_units(self, units)

    def table(self, raw: bool = False) -> Dict[str, np.ndarray]:
        """Columns of :attr:`COLUMNS` (plus P [N/m], delta, delta_work [m] when dimensional) as a dict of arrays.

        Parameters
        ----------
        raw : bool
            False: float arrays (booleans as 0/1, for CSV); True: the booleans kept.

        Returns
        -------
        dict of ndarray

        Examples
        --------
        >>> import jkrcyl
        >>> b, = jkrcyl.equilibria.two_patch(0.5, 1.0, n=20, gb=1 / 2.8)
        >>> b.table()["feasible"].dtype, b.table(raw=True)["feasible"].dtype
        (dtype('float64'), dtype('bool'))
        """
        cols = self.COLUMNS + (("P", "delta", "delta_work") if self.P is not None else ())
        return {k: np.asarray(getattr(self, k)) if raw else np.asarray(getattr(self, k), dtype=float) for k in cols}

    def __repr__(self) -> str:
        return (f"TwoPatchCurve(M={self.M:.6g}, theta={self.theta:.6g}, {np.size(self.a)} points, ends "
                f"{self.ends[0]} -> {self.ends[1]}, {int(np.sum(self.stable_load))} stable under load)")
