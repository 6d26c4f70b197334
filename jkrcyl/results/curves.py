"""Branches of equilibria and points on them: :class:`Curve` (one patch), :class:`Point`, :class:`TwoPatchCurve`."""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np


def _with_units(obj, load_scale, Delta):
    """The dimensional fields P [N/m], delta, delta_work [m] from the normalised ones."""
    return replace(obj, P=obj.P_star * load_scale, delta=obj.delta_over_Delta * Delta,
                   delta_work=obj.delta_work_over_Delta * Delta)


@dataclass(frozen=True)
class Curve:
    """One single-patch branch of equilibria (numpy arrays over the contact parameter a, increasing).

    eps [rad] = 2 atan(a); eps_star = 2 atan(a/a_crit)/pi (eps/pi where a_crit = inf); P_star (P_R* when
    vartheta = inf); delta_over_Delta (5.8); h_pi_over_Delta = h(pi)/Delta (5.10); feasible = gap inequality
    (h(pi) >= 0); stable_load, stable_grip, stable_grip_work: stable at fixed P, delta, delta_work
    (jkrcyl.model.stability); dP_star_da, ddelta_da, ddelta_work_da: slopes along the branch; dG_da_P,
    dG_da_delta, dG_da_delta_work: (1/w) dG/da at fixed P, delta, delta_work (section 8.3; NaN without adhesion,
    M = 0, where w = 0).  delta_work = delta + P/(8 pi G_I) is the work-conjugate approach (derive/green.py:
    the pin's centroid, load spread over the pin; the paper's delta is the rims' approach).  P [N/m], delta,
    delta_work [m]: set when the curve comes from a Contact.  gb = (1/G_I)/beta*, alpha_ratio = alpha*/beta*.
    Cohesive (Maugis-Dugdale) law (jkrcyl.model.cohesive): a is the branch parameter (the arclength of the
    traced branch, not tan(eps/2)), eps the contact half-angle (0 for zone-only states), c and c_top the zone
    ends [rad] (None for JKR), feasible the gap inequality and the law, dG_da_* NaN (no Griffith edge).
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
    P: np.ndarray = None
    delta: np.ndarray = None
    delta_work: np.ndarray = None
    alpha_ratio: float = 0.0
    c: np.ndarray = None
    c_top: np.ndarray = None

    COLUMNS = ("a", "eps", "eps_star", "P_star", "delta_over_Delta", "delta_work_over_Delta", "h_pi_over_Delta",
               "feasible", "stable_load", "stable_grip", "stable_grip_work")

    def with_units(self, load_scale, Delta):
        """This curve with P [N/m], delta and delta_work [m] (load_scale = P/P*, Delta [m])."""
        return _with_units(self, load_scale, Delta)

    def table(self):
        """Columns of :attr:`COLUMNS` (plus P [N/m], delta, delta_work [m] when dimensional) as a dict of arrays
        (booleans as 0/1)."""
        cols = self.COLUMNS + (("P", "delta", "delta_work") if self.P is not None else ())
        cols += tuple(k for k in ("c", "c_top") if getattr(self, k) is not None)
        return {k: np.asarray(getattr(self, k), dtype=float) for k in cols}

    def __repr__(self):
        return (f"Curve({self.regime}, M={self.M:.6g}, theta={self.theta:.6g}, {np.size(self.a)} points"
                f"{', dimensional' if self.P is not None else ''})")


@dataclass(frozen=True)
class Point:
    """A stationary point on a branch: P* minimum or maximum (control = load) or of delta/Delta (grip).

    kind: 'min' or 'max'.  outcome (control = load, from adherence): what a further pull does there --
    'detachment' (a feasible sub-critical minimum: the contact shrinks away), 'zip-full' (a feasible
    super-critical minimum: the contact grows round into full contact), for an infeasible point (h(pi) < 0:
    the gap at the top closes first) the regime of the confined analysis (jkrcyl.analysis.confined.REGIMES),
    or 'gap-closes-first' where that analysis does not apply (vartheta = inf).
    """

    control: str
    regime: str
    kind: str
    M: float
    theta: float
    a: float
    eps: float
    eps_star: float
    P_star: float
    delta_over_Delta: float
    h_pi_over_Delta: float
    feasible: bool
    delta_work_over_Delta: float = None
    P: float = None
    delta: float = None
    delta_work: float = None
    outcome: str = None
    gb: float = None
    alpha_ratio: float = 0.0

    def with_units(self, load_scale, Delta):
        return _with_units(self, load_scale, Delta)


@dataclass(frozen=True)
class TwoPatchCurve:
    """One branch of two-patch equilibria (contact at the bottom and the top at once), ordered along the curve.

    Fields as :class:`Curve` plus a_top, eps_top, eps_top_star, gap_min (min h/Delta outside both arcs), G_bot,
    G_top (G/w, = 1 on the branch) and ``ends``: how each end finishes -- 'single' (a_top -> 0: the
    single-patch state with h(pi) = 0), 'mirror' (a -> 0: the upside-down single patch), 'full'
    (eps + eps_top -> pi: runs into full contact) or 'loop' (a closed curve).  P [N/m], delta, delta_work [m]
    when made from a Contact.
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
    P: np.ndarray = None
    delta: np.ndarray = None
    delta_work: np.ndarray = None

    COLUMNS = ("a", "a_top", "eps", "eps_top", "eps_star", "eps_top_star", "P_star", "delta_over_Delta",
               "delta_work_over_Delta", "gap_min", "feasible", "stable_load", "stable_grip", "stable_grip_work")

    def with_units(self, load_scale, Delta):
        return _with_units(self, load_scale, Delta)

    def table(self, raw=False):
        """Columns of :attr:`COLUMNS` (plus P [N/m], delta, delta_work [m] when dimensional) as a dict of arrays
        (booleans as 0/1; raw=True keeps them boolean)."""
        cols = self.COLUMNS + (("P", "delta", "delta_work") if self.P is not None else ())
        return {k: np.asarray(getattr(self, k)) if raw else np.asarray(getattr(self, k), dtype=float) for k in cols}

    def __repr__(self):
        return (f"TwoPatchCurve(M={self.M:.6g}, theta={self.theta:.6g}, {np.size(self.a)} points, ends "
                f"{self.ends[0]} -> {self.ends[1]}, {int(np.sum(self.stable_load))} stable under load)")
