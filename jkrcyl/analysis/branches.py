"""Single-patch branches: curves, their dense tables, and the roots and stationary points on them (sections 6, 8).

A branch is the sub-critical (a < a_crit) or super-critical (a > a_crit) family of one bottom patch at its edge
condition, from the problem's single-patch solver (jkrcyl.model.single_patch).  Every search on a branch starts
from its dense table (cached per problem and regime: one grid uniform in eps* plus log-spaced small contacts)
and refines each sign change with the solver's own root finder, which rejects sign changes through a pole.
"""
from __future__ import annotations

import functools
import math

import numpy as np

from .._validate import A_MAX, contact_parameter
from ..model import stability as _stab
from ..model.problem import Problem
from ..model.single_patch import solver
from ..numerics import roots as _roots
from ..results import Curve
from ..units import CONTROLS, CURVE_FIELD

REGIMES = ("sub-critical", "super-critical")
ZONE_ONLY = "contactless"    # the pin held by its zone without contact: cohesive edge laws only
RUBBERY_A_MAX = 3.0      # curve(): a branch without a_crit is drawn over 0 < a < 3 (Fig. 7)
SMALL_A_POINTS = 200     # log-spaced points below the uniform grid (closed form; a tenth for collocation)


def check_regime(pb: Problem, regime: str) -> str:
    if regime not in REGIMES + (ZONE_ONLY,):
        raise ValueError(f"regime must be one of {', '.join(REGIMES + (ZONE_ONLY,))}, got {regime!r}")
    if regime not in solver(pb).regimes():
        raise ValueError(f"regime: no {regime} equilibria for this problem (its branches: "
                         f"{', '.join(solver(pb).regimes())}; super-critical needs a finite a_crit, section 7.2 -- "
                         "with a cohesive law below pi - 0.05 and a state past it below the load cap; contactless "
                         "a cohesive law)")
    return regime


def grid(pb: Problem, regime: str, n: int, small=0, a_max=None) -> np.ndarray:
    """n contact parameters over a branch, with ``small`` log-spaced ones below (the solver's grid,
    jkrcyl.model.patch.SinglePatch.grid)."""
    return solver(pb).grid(regime, n, small, a_max)


def _curve(pb: Problem, regime: str, a) -> Curve:
    sv = solver(pb)
    s = sv.states(a)
    flags = _stab.single_patch_flags(s, pb.work_shift)
    rates = sv.release_rates(s)
    k = pb.scale
    return Curve(M=pb.M, theta=pb.theta, gb=pb.gb, regime=regime, a=s.a, eps=s.contact,
                 eps_star=sv.eps_star_of(s), P_star=s.p / k, delta_over_Delta=s.dn, h_pi_over_Delta=s.h,
                 feasible=s.gap_open, stable_load=flags["load"], stable_grip=flags["grip"], dP_star_da=s.dp_da / k,
                 ddelta_da=s.ddn_da, dG_da_P=rates["load"], dG_da_delta=rates["grip"], delta_work_over_Delta=s.dw,
                 ddelta_work_da=s.ddw_da, dG_da_delta_work=rates["grip-work"], stable_grip_work=flags["grip-work"],
                 alpha_ratio=pb.alpha_ratio, c=s.c, c_top=s.c_top)


def curve(pb: Problem, regime: str = "sub-critical", n: int = 2000, a=None) -> Curve:
    """The branch ``regime``: n points uniform in eps*, or at the given contact parameters (on the branch)."""
    check_regime(pb, regime)
    if a is None:
        a = grid(pb, regime, n, a_max=RUBBERY_A_MAX if math.isinf(solver(pb).a_crit) else None)
        if a.size < 2:
            raise ValueError(f"theta: the {regime} branch lies beyond a = {A_MAX:g} (the supported domain of a) "
                             f"for theta = {pb.theta!r}")
    else:
        a = on_branch(pb, regime, a)
    return _curve(pb, regime, np.ascontiguousarray(a))


def on_branch(pb: Problem, regime: str, a):
    return solver(pb).on_branch(regime, contact_parameter(a))


@functools.lru_cache(maxsize=64)
def table(pb: Problem, regime: str) -> Curve:
    """The dense branch (the search grid of every root on it), cached per problem."""
    n = solver(pb).dense_points
    return _curve(pb, regime, grid(pb, regime, n, small=SMALL_A_POINTS * n // 4000))


def table_values(pb: Problem, regime: str, field: str):
    """(a, values) of a solver field (single_patch.FIELDS, kernel scale) on the branch's dense table grid: the
    solver's own where it has a cheaper route than the full table (SinglePatch.table_values), else the table's."""
    got = solver(pb).table_values(regime, field)
    if got is not None:
        return got
    name, scaled = CURVE_FIELD[field]
    c = table(pb, regime)
    return c.a, np.asarray(getattr(c, name)) * (pb.scale if scaled else 1.0)


def roots(pb: Problem, regime: str, field: str, target: float = 0.0, n=None):
    """[(a, sign)] where the solver field (single_patch.FIELDS, kernel scale) crosses target on the branch;
    sign: of field - target right of the root.  Sign changes through a pole are not roots.  The search grid is
    the dense table (:func:`table_values`), or n points (with the small contacts) when n is given."""
    name, scaled = CURVE_FIELD[field]
    if n is None:
        a, values = _with_folds(pb, regime, field)
    else:
        c = _curve(pb, regime, grid(pb, regime, n, small=SMALL_A_POINTS))
        a, values = c.a, np.asarray(getattr(c, name)) * (pb.scale if scaled else 1.0)
    sv = solver(pb)
    return _roots.roots_on_grid(values - target, a, lambda lo, hi, flo, fhi: sv.root(field, lo, hi, flo, fhi, target))


@functools.lru_cache(maxsize=64)
def _with_folds(pb: Problem, regime: str, field: str):
    """The table's (a, values) of a held quantity with its stationary points inserted: a target between a fold's
    value and its table neighbours' has two roots inside one table interval, no sign change on the table alone
    (the cohesive super-critical top patch at P* -0.70, 0.02 past its fold: solve found none of its two states)."""
    a, values = table_values(pb, regime, field)
    slope = {c.field: c.field_slope for c in CONTROLS.values()}.get(field)
    if slope is None:
        return a, values
    folds = [r for r, _ in roots(pb, regime, slope) if not np.any(a == r)]
    if not folds:
        return a, values
    at = np.array(folds)
    fv = np.array([solver(pb).value(field, r) for r in folds])
    order = np.argsort(np.concatenate([a, at]), kind="stable")
    return np.concatenate([a, at])[order], np.concatenate([np.asarray(values, dtype=float), fv])[order]


def values_at(pb: Problem, regime: str, a) -> Curve:
    """The branch's states at given contact parameters (validated on the branch)."""
    return curve(pb, regime, a=np.atleast_1d(np.asarray(a, dtype=float)))


def stationary_roots(pb: Problem, control: str, regime: str, n=None):
    """[(a, 'min' or 'max')] where the held quantity of ``control`` (P*, delta/Delta or delta_work/Delta) is
    stationary on a branch (the states: jkrcyl.analysis.forward.stationary_points)."""
    return [(r, "min" if sgn > 0 else "max") for r, sgn in roots(pb, regime, CONTROLS[control].field_slope, n=n)]